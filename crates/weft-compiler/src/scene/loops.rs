//! Loops that run exactly once, or never, once the scene's constants are in.
//!
//! A loop whose trip count a scene fixes at one (e.g. the microcylinder's
//! loop over offset-list segments for a thread with one offset) is still a
//! loop for the driver: Mesa's NIR unrolls a loop only when its body's cost
//! times its trip count is small, so this one (hundreds of instructions once
//! its helpers are inlined) keeps its induction variables, its run-time
//! indexing and everything downstream of them. Replaced by its body, the loop's counters become constants
//! (`locals.rs`) and what depended on them folds.
//!
//! The shapes handled are the two naga's WGSL front end produces for `for`,
//! `while` and `loop`: a body starting with `if c {} else { break; }` (or
//! `if c { break; }`) after only `Emit`s, or a `break if` in `continuing`;
//! nothing else in the body or `continuing` may `break` or `continue` this
//! loop. The first iteration is interpreted with the constants known before
//! the loop (a small evaluator over scalar literals); when the guard breaks
//! at once the loop never runs, and when after one iteration (body then
//! continuing) the `break if` holds or the guard breaks, it runs once.

use super::local_vars::{State, root_local, stored_locals};
use naga::{
    BinaryOperator, Block, Expression, Handle, Literal, LocalVariable, Module, Statement,
    TypeInner, UnaryOperator,
};
use std::collections::{BTreeSet, HashMap};

/// A loop's trip count, when it is 0 or 1.
pub(super) enum Trip {
    Never,
    Once,
}

/// The trip count of `loop { body } continuing { continuing } break if
/// break_if` entered with the locals in `state`, when it is 0 or 1.
pub(super) fn single_trip(
    module: &Module,
    exprs: &naga::Arena<Expression>,
    body: &Block,
    continuing: &Block,
    break_if: Option<Handle<Expression>>,
    state: &State,
) -> Option<Trip> {
    let mut run = Interpreter {
        module,
        exprs,
        vals: HashMap::new(),
        locals: state
            .iter()
            .filter_map(|(v, e)| Some((*v, constant_literal(module, e)?)))
            .collect(),
    };
    let (g, guard) = guard(body);
    let head = &body[..g];
    let rest: Vec<&Statement> = body.iter().skip(g + usize::from(guard.is_some())).collect();
    if rest.iter().any(|s| exits(s)) || continuing.iter().any(exits) {
        return None;
    }
    // First iteration.
    run.statements(head.iter())?;
    if let Some((condition, break_when)) = guard {
        if run.bool(condition)? == break_when {
            return Some(Trip::Never);
        }
    } else {
        break_if?; // an unguarded loop without `break if` never stops here
    }
    run.statements(rest.into_iter())?;
    run.statements(continuing.iter())?;
    if let Some(b) = break_if
        && run.bool(b) == Some(true)
    {
        return Some(Trip::Once);
    }
    // Second iteration's head: fresh values, the locals as the first left them.
    let (condition, break_when) = guard?;
    run.vals.clear();
    run.statements(head.iter())?;
    (run.bool(condition)? == break_when).then_some(Trip::Once)
}

/// The body of a loop that runs once, then its continuing, without the guard.
pub(super) fn unrolled(body: Block, continuing: Block) -> Block {
    let (g, guard) = guard(&body);
    let mut out = Block::with_capacity(body.len() + continuing.len());
    for (i, (stmt, span)) in body.span_into_iter().enumerate() {
        if i == g && guard.is_some() {
            continue;
        }
        out.push(stmt, span);
    }
    for (stmt, span) in continuing.span_into_iter() {
        out.push(stmt, span);
    }
    out
}

/// The index of the first statement that is not an `Emit`, and the loop
/// guard there if it is one: (condition, the value of it that breaks).
fn guard(body: &Block) -> (usize, Option<(Handle<Expression>, bool)>) {
    let g = body
        .iter()
        .position(|s| !matches!(s, Statement::Emit(_)))
        .unwrap_or(body.len());
    let is_break = |b: &Block| b.len() == 1 && matches!(b.first(), Some(Statement::Break));
    let guard = match body.get(g) {
        Some(Statement::If {
            condition,
            accept,
            reject,
        }) => {
            if accept.is_empty() && is_break(reject) {
                Some((*condition, false))
            } else if is_break(accept) && reject.is_empty() {
                Some((*condition, true))
            } else {
                None
            }
        }
        _ => None,
    };
    (g, guard)
}

/// Whether a statement can leave the loop it sits in (not a nested one) by
/// `break` or `continue` (a `break` inside a `switch` leaves the switch).
fn exits(stmt: &Statement) -> bool {
    fn any(b: &Block, in_switch: bool) -> bool {
        b.iter().any(|s| walk(s, in_switch))
    }
    fn walk(s: &Statement, in_switch: bool) -> bool {
        match s {
            Statement::Break => !in_switch,
            Statement::Continue => true,
            Statement::Block(b) => any(b, in_switch),
            Statement::If { accept, reject, .. } => {
                any(accept, in_switch) || any(reject, in_switch)
            }
            Statement::Switch { cases, .. } => cases.iter().any(|c| any(&c.body, true)),
            _ => false,
        }
    }
    walk(stmt, false)
}

/// A scalar literal a constant function expression holds, if it is one.
fn constant_literal(module: &Module, e: &Expression) -> Option<Literal> {
    match e {
        Expression::Literal(l) => Some(*l),
        Expression::Constant(c) => global_literal(module, module.constants[*c].init),
        Expression::ZeroValue(ty) => match module.types[*ty].inner {
            TypeInner::Scalar(s) => Literal::zero(s),
            _ => None,
        },
        _ => None,
    }
}

fn global_literal(module: &Module, h: Handle<Expression>) -> Option<Literal> {
    match &module.global_expressions[h] {
        Expression::Literal(l) => Some(*l),
        Expression::Constant(c) => global_literal(module, module.constants[*c].init),
        e @ Expression::ZeroValue(_) => constant_literal(module, e),
        _ => None,
    }
}

/// One iteration's scalar values: expressions as they are emitted, locals as stored.
struct Interpreter<'a> {
    module: &'a Module,
    exprs: &'a naga::Arena<Expression>,
    vals: HashMap<Handle<Expression>, Literal>,
    locals: HashMap<Handle<LocalVariable>, Literal>,
}

impl Interpreter<'_> {
    fn value(&self, h: Handle<Expression>) -> Option<Literal> {
        self.vals
            .get(&h)
            .copied()
            .or_else(|| constant_literal(self.module, &self.exprs[h]))
    }

    fn bool(&self, h: Handle<Expression>) -> Option<bool> {
        match self.value(h)? {
            Literal::Bool(b) => Some(b),
            _ => None,
        }
    }

    /// Runs straight-line statements; `None` where the walk cannot follow
    /// (a `return`, `discard`, `break` or `continue` reached).
    fn statements<'s>(&mut self, stmts: impl Iterator<Item = &'s Statement>) -> Option<()> {
        for stmt in stmts {
            self.statement(stmt)?;
        }
        Some(())
    }

    fn statement(&mut self, stmt: &Statement) -> Option<()> {
        match stmt {
            Statement::Emit(range) => {
                for h in range.clone() {
                    match self.evaluate(h) {
                        Some(v) => self.vals.insert(h, v),
                        None => self.vals.remove(&h),
                    };
                }
            }
            Statement::Store { pointer, value } => match self.exprs[*pointer] {
                Expression::LocalVariable(v) => match self.value(*value) {
                    Some(l) => {
                        self.locals.insert(v, l);
                    }
                    None => {
                        self.locals.remove(&v);
                    }
                },
                _ => {
                    if let Some(v) = root_local(self.exprs, *pointer) {
                        self.locals.remove(&v);
                    }
                }
            },
            Statement::Call { arguments, .. } => {
                for a in arguments {
                    if let Some(v) = root_local(self.exprs, *a) {
                        self.locals.remove(&v);
                    }
                }
            }
            Statement::Block(b) => self.statements(b.iter())?,
            Statement::If {
                condition,
                accept,
                reject,
            } => match self.bool(*condition) {
                Some(taken) => self.statements(if taken { accept } else { reject }.iter())?,
                None => {
                    let forget = |me: &mut Self, b: &Block| {
                        let mut stored = BTreeSet::new();
                        stored_locals(me.exprs, b, &mut stored);
                        stored.iter().for_each(|v| {
                            me.locals.remove(v);
                        });
                    };
                    forget(self, accept);
                    forget(self, reject);
                }
            },
            Statement::Loop {
                body, continuing, ..
            } => {
                let mut stored = BTreeSet::new();
                stored_locals(self.exprs, body, &mut stored);
                stored_locals(self.exprs, continuing, &mut stored);
                stored.iter().for_each(|v| {
                    self.locals.remove(v);
                });
            }
            Statement::Switch { cases, .. } => {
                let mut stored = BTreeSet::new();
                for c in cases {
                    stored_locals(self.exprs, &c.body, &mut stored);
                }
                stored.iter().for_each(|v| {
                    self.locals.remove(v);
                });
            }
            Statement::Return { .. } | Statement::Kill | Statement::Break | Statement::Continue => {
                return None;
            }
            _ => {}
        }
        Some(())
    }

    fn evaluate(&self, h: Handle<Expression>) -> Option<Literal> {
        match self.exprs[h] {
            Expression::Load { pointer } => match self.exprs[pointer] {
                Expression::LocalVariable(v) => self.locals.get(&v).copied(),
                _ => None,
            },
            Expression::Binary { op, left, right } => {
                binary(op, self.value(left)?, self.value(right)?)
            }
            Expression::Unary { op, expr } => unary(op, self.value(expr)?),
            Expression::Select {
                condition,
                accept,
                reject,
            } => match self.value(condition)? {
                Literal::Bool(true) => self.value(accept),
                Literal::Bool(false) => self.value(reject),
                _ => None,
            },
            Expression::As {
                expr,
                kind,
                convert: Some(4),
            } => convert(self.value(expr)?, kind),
            ref e => constant_literal(self.module, e),
        }
    }
}

fn unary(op: UnaryOperator, v: Literal) -> Option<Literal> {
    Some(match (op, v) {
        (UnaryOperator::Negate, Literal::I32(a)) => Literal::I32(a.wrapping_neg()),
        (UnaryOperator::Negate, Literal::F32(a)) => Literal::F32(-a),
        (UnaryOperator::LogicalNot, Literal::Bool(a)) => Literal::Bool(!a),
        (UnaryOperator::BitwiseNot, Literal::I32(a)) => Literal::I32(!a),
        (UnaryOperator::BitwiseNot, Literal::U32(a)) => Literal::U32(!a),
        _ => return None,
    })
}

fn convert(v: Literal, kind: naga::ScalarKind) -> Option<Literal> {
    use naga::ScalarKind as K;
    Some(match (v, kind) {
        (Literal::I32(a), K::Uint) => Literal::U32(a as u32),
        (Literal::U32(a), K::Sint) => Literal::I32(a as i32),
        (Literal::I32(a), K::Float) => Literal::F32(a as f32),
        (Literal::U32(a), K::Float) => Literal::F32(a as f32),
        _ => return None,
    })
}

fn binary(op: BinaryOperator, a: Literal, b: Literal) -> Option<Literal> {
    use BinaryOperator as B;
    let ord = |o: std::cmp::Ordering| -> Option<Literal> {
        use std::cmp::Ordering::*;
        Some(Literal::Bool(match op {
            B::Equal => o == Equal,
            B::NotEqual => o != Equal,
            B::Less => o == Less,
            B::LessEqual => o != Greater,
            B::Greater => o == Greater,
            B::GreaterEqual => o != Less,
            _ => return None,
        }))
    };
    match (a, b) {
        (Literal::I32(x), Literal::I32(y)) => match op {
            B::Add => Some(Literal::I32(x.wrapping_add(y))),
            B::Subtract => Some(Literal::I32(x.wrapping_sub(y))),
            B::Multiply => Some(Literal::I32(x.wrapping_mul(y))),
            B::And => Some(Literal::I32(x & y)),
            B::InclusiveOr => Some(Literal::I32(x | y)),
            B::ExclusiveOr => Some(Literal::I32(x ^ y)),
            _ => ord(x.cmp(&y)),
        },
        (Literal::U32(x), Literal::U32(y)) => match op {
            B::Add => Some(Literal::U32(x.wrapping_add(y))),
            B::Subtract => Some(Literal::U32(x.wrapping_sub(y))),
            B::Multiply => Some(Literal::U32(x.wrapping_mul(y))),
            B::And => Some(Literal::U32(x & y)),
            B::InclusiveOr => Some(Literal::U32(x | y)),
            B::ExclusiveOr => Some(Literal::U32(x ^ y)),
            _ => ord(x.cmp(&y)),
        },
        (Literal::F32(x), Literal::F32(y)) => match op {
            B::Add => Some(Literal::F32(x + y)),
            B::Subtract => Some(Literal::F32(x - y)),
            B::Multiply => Some(Literal::F32(x * y)),
            _ => ord(x.partial_cmp(&y)?),
        },
        (Literal::Bool(x), Literal::Bool(y)) => Some(Literal::Bool(match op {
            B::LogicalAnd | B::And => x && y,
            B::LogicalOr | B::InclusiveOr => x || y,
            B::Equal => x == y,
            B::NotEqual => x != y,
            _ => return None,
        })),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use crate::scene::fold::test_support::folded;

    fn summed(n: i32) -> String {
        folded(&format!(
            "
fn term(i: i32, x: f32) -> f32 {{ return x * f32(i + 1); }}
fn sum(x: f32, n: i32) -> f32 {{
    var acc = 0.0;
    for (var i = 0; i < n; i++) {{ acc += term(i, x); }}
    return acc;
}}
@fragment fn fs(@location(0) v: f32) -> @location(0) vec4<f32> {{
    return vec4<f32>(sum(v, {n}), 0.0, 0.0, 1.0);
}}"
        ))
    }

    #[test]
    fn a_loop_that_runs_once_becomes_its_body() {
        let wgsl = summed(1);
        assert!(!wgsl.contains("loop"), "{wgsl}");
        // The counter is 0 inside: term(0, x) = x * f32(1) = x.
        assert!(
            wgsl.contains("(x: f32) -> f32 {\n    return x;\n}"),
            "{wgsl}"
        );
    }

    #[test]
    fn a_loop_that_never_runs_disappears() {
        let wgsl = summed(0);
        assert!(!wgsl.contains("loop"), "{wgsl}");
        assert!(!wgsl.contains("sum"), "{wgsl}");
    }

    #[test]
    fn a_loop_that_runs_twice_stays() {
        let wgsl = summed(2);
        assert!(wgsl.contains("loop"), "{wgsl}");
    }

    #[test]
    fn a_break_if_loop_that_runs_once_becomes_its_body() {
        let wgsl = folded(
            "
@fragment fn fs(@location(0) v: f32) -> @location(0) vec4<f32> {
    var acc = v;
    var i = 0;
    loop {
        acc = acc * 2.0;
        continuing { i += 1; break if i >= 1; }
    }
    return vec4<f32>(acc, 0.0, 0.0, 1.0);
}",
        );
        assert!(!wgsl.contains("loop"), "{wgsl}");
    }

    #[test]
    fn a_counter_a_run_time_branch_may_change_keeps_its_loop() {
        let wgsl = folded(
            "
@fragment fn fs(@location(0) v: f32) -> @location(0) vec4<f32> {
    var acc = 0.0;
    for (var i = 0; i < 1; i++) {
        if v > 0.5 { i = -5; }
        acc += v;
    }
    return vec4<f32>(acc, 0.0, 0.0, 1.0);
}",
        );
        assert!(wgsl.contains("loop"), "{wgsl}");
    }

    #[test]
    fn a_loop_with_an_inner_break_stays() {
        let wgsl = folded(
            "
@fragment fn fs(@location(0) v: f32) -> @location(0) vec4<f32> {
    var acc = 0.0;
    for (var i = 0; i < 1; i++) {
        if v > 0.5 { break; }
        acc += v;
    }
    return vec4<f32>(acc, 0.0, 0.0, 1.0);
}",
        );
        assert!(wgsl.contains("loop"), "{wgsl}");
    }
}
