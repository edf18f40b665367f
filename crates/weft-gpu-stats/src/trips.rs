//! Constant trip counts of the loops a specialised WGSL entry point runs,
//! read with naga. ACO's code keeps a loop's bound only sometimes (an
//! immediate compare) and never its start or step, so the counts come from
//! the source: every call is followed (as if inlined, which is what the
//! driver does) with its integer arguments evaluated, and each `loop`
//! whose exit is `if counter <op> bound {} else { break; }` (naga's form of
//! WGSL `for`/`while`) with a constant start, bound and step gets a count.

use naga::{BinaryOperator, Block, Expression, Function, Handle, Literal, Module, Statement};
use std::collections::HashMap;

/// One loop of the entry point, in program order with calls inlined.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SourceLoop {
    /// Loops around it (0: outermost).
    pub depth: usize,
    /// Iterations per execution of the loop, when start, bound and step are constant.
    pub trips: Option<u64>,
    /// The bound the counter is compared against, when constant.
    pub bound: Option<i64>,
}

/// Calls deeper than this are not followed (WGSL forbids recursion; this bounds the walk).
const MAX_CALL_DEPTH: usize = 32;

/// The loops `entry` runs, or `None` when the text does not parse or has no such entry point.
pub fn source_loops(wgsl: &str, entry: &str) -> Option<Vec<SourceLoop>> {
    let module = naga::front::wgsl::parse_str(wgsl).ok()?;
    let ep = module.entry_points.iter().find(|e| e.name == entry)?;
    let mut walker = Walker {
        module: &module,
        out: Vec::new(),
    };
    walker.block(&ep.function, &ep.function.body, &[], 0, 0);
    Some(walker.out)
}

struct Walker<'m> {
    module: &'m Module,
    out: Vec<SourceLoop>,
}

/// Integer arguments of the function being walked (`None`: not constant here).
type Args = [Option<i64>];

impl Walker<'_> {
    fn block(&mut self, f: &Function, block: &Block, args: &Args, depth: usize, calls: usize) {
        // Constant stores seen so far in this block: a counter's start when it is not the init.
        let mut stores: HashMap<Handle<Expression>, Option<i64>> = HashMap::new();
        for stmt in block.iter() {
            match stmt {
                Statement::Block(b) => self.block(f, b, args, depth, calls),
                Statement::If { accept, reject, .. } => {
                    self.block(f, accept, args, depth, calls);
                    self.block(f, reject, args, depth, calls);
                }
                Statement::Switch { cases, .. } => {
                    for c in cases {
                        self.block(f, &c.body, args, depth, calls);
                    }
                }
                Statement::Loop {
                    body, continuing, ..
                } => {
                    let (trips, bound) =
                        loop_trips(self.module, f, body, continuing, args, &stores);
                    self.out.push(SourceLoop {
                        depth,
                        trips,
                        bound,
                    });
                    self.block(f, body, args, depth + 1, calls);
                    self.block(f, continuing, args, depth + 1, calls);
                }
                Statement::Call {
                    function,
                    arguments,
                    ..
                } if calls < MAX_CALL_DEPTH => {
                    let callee = &self.module.functions[*function];
                    let values: Vec<Option<i64>> = arguments
                        .iter()
                        .map(|a| eval(self.module, f, *a, args))
                        .collect();
                    self.block(callee, &callee.body, &values, depth, calls + 1);
                }
                Statement::Store { pointer, value } => {
                    stores.insert(*pointer, eval(self.module, f, *value, args));
                }
                _ => {}
            }
        }
    }
}

/// (trips, bound) of a loop whose body starts with `if counter <op> bound {} else { break; }`.
fn loop_trips(
    module: &Module,
    f: &Function,
    body: &Block,
    continuing: &Block,
    args: &Args,
    stores: &HashMap<Handle<Expression>, Option<i64>>,
) -> (Option<u64>, Option<i64>) {
    let Some((op, counter, bound_expr)) = exit_condition(f, body) else {
        return (None, None);
    };
    let bound = eval(module, f, bound_expr, args);
    let start = match stores.get(&counter) {
        Some(v) => *v,
        None => match f.expressions[counter] {
            Expression::LocalVariable(lv) => f.local_variables[lv]
                .init
                .and_then(|init| eval(module, f, init, args)),
            _ => None,
        },
    };
    let step = counter_step(module, f, continuing, counter, args);
    let trips = match (start, bound, step) {
        (Some(s), Some(b), Some(d)) => count(op, s, b, d),
        _ => None,
    };
    (trips, bound)
}

/// Iterations of `for (i = s; i <op> b; i += d)`.
fn count(op: BinaryOperator, s: i64, b: i64, d: i64) -> Option<u64> {
    let span = match (op, d > 0) {
        (BinaryOperator::Less, true) => b - s,
        (BinaryOperator::LessEqual, true) => b - s + 1,
        (BinaryOperator::Greater, false) => s - b,
        (BinaryOperator::GreaterEqual, false) => s - b + 1,
        (BinaryOperator::NotEqual, _) if (b - s) % d == 0 => {
            return u64::try_from((b - s) / d).ok();
        }
        _ => return None,
    };
    let d = d.unsigned_abs();
    Some(u64::try_from(span.max(0)).ok()?.div_ceil(d))
}

/// The loop's exit test: (operator, counter pointer, bound expression).
fn exit_condition(
    f: &Function,
    body: &Block,
) -> Option<(BinaryOperator, Handle<Expression>, Handle<Expression>)> {
    let stmt = body.iter().find(|s| !matches!(s, Statement::Emit(_)))?;
    let Statement::If {
        condition,
        accept,
        reject,
    } = stmt
    else {
        return None;
    };
    let breaks = |b: &Block| matches!(b.iter().next(), Some(Statement::Break)) && b.len() == 1;
    if !(accept.is_empty() && breaks(reject)) {
        return None;
    }
    let Expression::Binary { op, left, right } = f.expressions[*condition] else {
        return None;
    };
    let Expression::Load { pointer } = f.expressions[left] else {
        return None;
    };
    Some((op, pointer, right))
}

/// `d` of the continuing block's `counter = counter + d` (or `- d`).
fn counter_step(
    module: &Module,
    f: &Function,
    continuing: &Block,
    counter: Handle<Expression>,
    args: &Args,
) -> Option<i64> {
    continuing.iter().find_map(|s| match s {
        Statement::Store { pointer, value } if *pointer == counter => {
            let Expression::Binary { op, left, right } = f.expressions[*value] else {
                return None;
            };
            let is_counter =
                matches!(f.expressions[left], Expression::Load { pointer } if pointer == counter);
            let d = eval(module, f, right, args)?;
            match op {
                BinaryOperator::Add if is_counter => Some(d),
                BinaryOperator::Subtract if is_counter => Some(-d),
                _ => None,
            }
        }
        _ => None,
    })
}

/// An integer expression's value where it is constant given the arguments.
fn eval(module: &Module, f: &Function, h: Handle<Expression>, args: &Args) -> Option<i64> {
    eval_in(module, &f.expressions, h, args, 0)
}

fn eval_in(
    module: &Module,
    arena: &naga::Arena<Expression>,
    h: Handle<Expression>,
    args: &Args,
    depth: usize,
) -> Option<i64> {
    if depth > 64 {
        return None;
    }
    let rec = |e| eval_in(module, arena, e, args, depth + 1);
    match &arena[h] {
        Expression::Literal(l) => literal(*l),
        Expression::Constant(c) => {
            let init = module.constants[*c].init;
            eval_in(module, &module.global_expressions, init, &[], depth + 1)
        }
        Expression::FunctionArgument(i) => args.get(*i as usize).copied().flatten(),
        Expression::As { expr, .. } => rec(*expr),
        Expression::Math { fun, arg, arg1, .. } => {
            let (a, b) = (rec(*arg)?, rec((*arg1)?)?);
            match fun {
                naga::MathFunction::Max => Some(a.max(b)),
                naga::MathFunction::Min => Some(a.min(b)),
                _ => None,
            }
        }
        Expression::Binary { op, left, right } => {
            let (a, b) = (rec(*left)?, rec(*right)?);
            match op {
                BinaryOperator::Add => a.checked_add(b),
                BinaryOperator::Subtract => a.checked_sub(b),
                BinaryOperator::Multiply => a.checked_mul(b),
                BinaryOperator::Divide => a.checked_div(b),
                _ => None,
            }
        }
        _ => None,
    }
}

fn literal(l: Literal) -> Option<i64> {
    match l {
        Literal::U32(v) => Some(v.into()),
        Literal::I32(v) => Some(v.into()),
        Literal::U16(v) => Some(v.into()),
        Literal::I16(v) => Some(v.into()),
        Literal::I64(v) | Literal::AbstractInt(v) => Some(v),
        Literal::U64(v) => i64::try_from(v).ok(),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bound_passed_through_a_call_is_followed() {
        let src = "
            const N: u32 = 12u;
            fn mean(count: u32) -> f32 {
                var s = 0.0;
                let cells = max(count, 1u);
                for (var k = 0u; k < cells; k += 1u) { s += 1.0; }
                for (var j = 1i; j <= 16i; j += 2i) { s += 1.0; }
                return s;
            }
            @fragment fn fs() -> @location(0) vec4<f32> {
                var t = 0.0;
                for (var i = 0u; i < 3u; i++) { t += mean(N); }
                return vec4(t);
            }";
        let loops = source_loops(src, "fs").unwrap();
        let got: Vec<_> = loops.iter().map(|l| (l.depth, l.trips, l.bound)).collect();
        assert_eq!(
            got,
            vec![
                (0, Some(3), Some(3)),
                (1, Some(12), Some(12)),
                (1, Some(8), Some(16))
            ]
        );
    }
}
