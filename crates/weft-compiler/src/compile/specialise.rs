//! Per-variant specialisation of the validated module.
//!
//! naga's `process_overrides` replaces *every* override and keeps the
//! now-constant `if`s, so weft does its own pass:
//! 1. each static keyword's and the tier's `override` becomes a literal;
//! 2. `if`s whose condition folds to a constant keep only the taken branch;
//! 3. the replaced overrides lose their names so `compact` can drop them, and
//!    compaction removes everything the dead branches used (textures too);
//! 4. the module is validated again.
//!
//! Keywords in `constant` mode are left as overrides (WGSL pipeline constants).

use naga::{BinaryOperator, Block, Expression, Handle, Literal, Module, Statement, UnaryOperator};
use std::collections::{HashMap, HashSet};

/// Values to bake into a variant: override name -> value.
#[derive(Clone, Debug, Default)]
pub struct Bindings {
    pub values: HashMap<String, Literal>,
    /// The entry points to keep (those the variant's passes name): every
    /// other - a pass the variant does not have, a library's entry point no
    /// pass uses - goes, with the code only it reaches. `None` keeps all.
    pub keep_entry_points: Option<Vec<String>>,
}

/// Returns the specialised module; validation is the caller's.
pub fn specialise(module: &Module, values: &Bindings) -> Module {
    let mut module = module.clone();
    let replace: HashMap<Handle<naga::Override>, Literal> = module
        .overrides
        .iter()
        .filter_map(|(h, o)| {
            let name = o.name.as_deref()?;
            values.values.get(name).map(|lit| (h, *lit))
        })
        .collect();

    for (_, expr) in module.global_expressions.iter_mut() {
        if let Expression::Override(h) = *expr
            && let Some(lit) = replace.get(&h)
        {
            *expr = Expression::Literal(*lit);
        }
    }
    let mut functions = std::mem::take(&mut module.functions);
    for (_, f) in functions.iter_mut() {
        specialise_function(&module, f, &replace);
    }
    module.functions = functions;
    let mut entry_points = std::mem::take(&mut module.entry_points);
    if let Some(keep) = &values.keep_entry_points {
        entry_points.retain(|ep| keep.contains(&ep.name));
    }
    for ep in entry_points.iter_mut() {
        specialise_function(&module, &mut ep.function, &replace);
    }
    module.entry_points = entry_points;

    // Anonymous, unreferenced overrides are dropped by compaction.
    for (h, o) in module.overrides.iter_mut() {
        if replace.contains_key(&h) {
            o.name = None;
            o.id = None;
        }
    }
    naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
    crate::compile::half::declare_f16(&mut module);
    module
}

fn specialise_function(
    module: &Module,
    f: &mut naga::Function,
    replace: &HashMap<Handle<naga::Override>, Literal>,
) {
    for (_, expr) in f.expressions.iter_mut() {
        if let Expression::Override(h) = *expr
            && let Some(lit) = replace.get(&h)
        {
            *expr = Expression::Literal(*lit);
        }
    }
    prune_function(module, f);
}

/// Replaces constant `if`s by their taken branch and drops the names of
/// expressions only dead code evaluated. Also used by scene folding.
pub(crate) fn prune_function(module: &Module, f: &mut naga::Function) {
    let body = std::mem::take(&mut f.body);
    f.body = prune_block(module, &f.expressions, body);
    // Names of expressions that only dead code evaluated would keep them (and
    // e.g. calls to functions compaction removes) alive: drop those names.
    let mut live = HashSet::new();
    collect_evaluated(&f.body, &mut live);
    let exprs = &f.expressions;
    f.named_expressions
        .retain(|h, _| live.contains(h) || exprs[*h].needs_pre_emit());
}

/// Expressions a block evaluates: emitted ranges and statement results.
fn collect_evaluated(block: &Block, live: &mut HashSet<Handle<Expression>>) {
    for stmt in block.iter() {
        match stmt {
            Statement::Emit(range) => live.extend(range.clone()),
            Statement::Call {
                result: Some(r), ..
            }
            | Statement::Atomic {
                result: Some(r), ..
            }
            | Statement::WorkGroupUniformLoad { result: r, .. }
            | Statement::SubgroupBallot { result: r, .. }
            | Statement::SubgroupGather { result: r, .. }
            | Statement::SubgroupCollectiveOperation { result: r, .. } => {
                live.insert(*r);
            }
            Statement::Block(b) => collect_evaluated(b, live),
            Statement::If { accept, reject, .. } => {
                collect_evaluated(accept, live);
                collect_evaluated(reject, live);
            }
            Statement::Loop {
                body, continuing, ..
            } => {
                collect_evaluated(body, live);
                collect_evaluated(continuing, live);
            }
            Statement::Switch { cases, .. } => {
                cases.iter().for_each(|c| collect_evaluated(&c.body, live))
            }
            _ => {}
        }
    }
}

/// Replaces every constant `if` in a block (recursively) by its taken branch.
fn prune_block(module: &Module, exprs: &naga::Arena<Expression>, block: Block) -> Block {
    let mut out = Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        let stmt = match stmt {
            Statement::If {
                condition,
                accept,
                reject,
            } => match eval(module, exprs, condition) {
                Some(Value::Bool(taken)) => {
                    let chosen = prune_block(module, exprs, if taken { accept } else { reject });
                    if chosen.is_empty() {
                        continue; // e.g. a feature test whose early return is gone
                    }
                    Statement::Block(chosen)
                }
                _ => map_child_blocks(
                    Statement::If {
                        condition,
                        accept,
                        reject,
                    },
                    &mut |b| prune_block(module, exprs, b),
                ),
            },
            other => map_child_blocks(other, &mut |b| prune_block(module, exprs, b)),
        };
        let ends = diverges(&stmt);
        out.push(stmt, span);
        // Code after a `return` (e.g. of a feature test that became
        // `if true { return ...; }`) is dead; it would keep its bindings alive.
        if ends {
            break;
        }
    }
    out
}

/// Rebuilds a statement with `f` applied to each block it holds (a block,
/// both branches of an `if`, a loop's body and continuing, every case).
pub(crate) fn map_child_blocks(stmt: Statement, f: &mut dyn FnMut(Block) -> Block) -> Statement {
    match stmt {
        Statement::Block(b) => Statement::Block(f(b)),
        Statement::If {
            condition,
            accept,
            reject,
        } => Statement::If {
            condition,
            accept: f(accept),
            reject: f(reject),
        },
        Statement::Loop {
            body,
            continuing,
            break_if,
        } => Statement::Loop {
            body: f(body),
            continuing: f(continuing),
            break_if,
        },
        Statement::Switch { selector, cases } => Statement::Switch {
            selector,
            cases: cases
                .into_iter()
                .map(|mut c| {
                    c.body = f(c.body);
                    c
                })
                .collect(),
        },
        other => other,
    }
}

/// Whether control never continues past `stmt`.
fn diverges(stmt: &Statement) -> bool {
    match stmt {
        Statement::Return { .. } | Statement::Kill | Statement::Break | Statement::Continue => true,
        Statement::Block(b) => b.last().is_some_and(diverges),
        Statement::If { accept, reject, .. } => {
            accept.last().is_some_and(diverges) && reject.last().is_some_and(diverges)
        }
        _ => false,
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Value {
    Bool(bool),
    U32(u32),
    I32(i32),
}

fn literal(l: &Literal) -> Option<Value> {
    match *l {
        Literal::Bool(b) => Some(Value::Bool(b)),
        Literal::U32(u) => Some(Value::U32(u)),
        Literal::I32(i) => Some(Value::I32(i)),
        Literal::AbstractInt(i) => i32::try_from(i).ok().map(Value::I32),
        _ => None,
    }
}

fn eval_global(module: &Module, h: Handle<Expression>) -> Option<Value> {
    match &module.global_expressions[h] {
        Expression::Literal(l) => literal(l),
        Expression::Constant(c) => eval_global(module, module.constants[*c].init),
        _ => None,
    }
}

/// Folds the small expression language keyword conditions use.
fn eval(module: &Module, exprs: &naga::Arena<Expression>, h: Handle<Expression>) -> Option<Value> {
    match &exprs[h] {
        Expression::Literal(l) => literal(l),
        Expression::Constant(c) => eval_global(module, module.constants[*c].init),
        Expression::Unary {
            op: UnaryOperator::LogicalNot,
            expr,
        } => match eval(module, exprs, *expr)? {
            Value::Bool(b) => Some(Value::Bool(!b)),
            _ => None,
        },
        Expression::Binary { op, left, right } => {
            let l = eval(module, exprs, *left);
            let r = eval(module, exprs, *right);
            // Short-circuit forms fold with one side known.
            match (op, l, r) {
                (BinaryOperator::LogicalAnd, Some(Value::Bool(false)), _)
                | (BinaryOperator::LogicalAnd, _, Some(Value::Bool(false))) => {
                    return Some(Value::Bool(false));
                }
                (BinaryOperator::LogicalOr, Some(Value::Bool(true)), _)
                | (BinaryOperator::LogicalOr, _, Some(Value::Bool(true))) => {
                    return Some(Value::Bool(true));
                }
                _ => {}
            }
            let (l, r) = (l?, r?);
            let cmp = |ord: std::cmp::Ordering| -> Option<bool> {
                use std::cmp::Ordering::*;
                Some(match op {
                    BinaryOperator::Equal => ord == Equal,
                    BinaryOperator::NotEqual => ord != Equal,
                    BinaryOperator::Less => ord == Less,
                    BinaryOperator::LessEqual => ord != Greater,
                    BinaryOperator::Greater => ord == Greater,
                    BinaryOperator::GreaterEqual => ord != Less,
                    _ => return None,
                })
            };
            match (l, r) {
                (Value::Bool(a), Value::Bool(b)) => match op {
                    BinaryOperator::LogicalAnd | BinaryOperator::And => Some(Value::Bool(a && b)),
                    BinaryOperator::LogicalOr | BinaryOperator::InclusiveOr => {
                        Some(Value::Bool(a || b))
                    }
                    BinaryOperator::Equal => Some(Value::Bool(a == b)),
                    BinaryOperator::NotEqual => Some(Value::Bool(a != b)),
                    _ => None,
                },
                (Value::U32(a), Value::U32(b)) => cmp(a.cmp(&b)).map(Value::Bool),
                (Value::I32(a), Value::I32(b)) => cmp(a.cmp(&b)).map(Value::Bool),
                _ => None,
            }
        }
        _ => None,
    }
}
