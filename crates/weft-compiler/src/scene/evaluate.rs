//! Constant evaluation inside function bodies: every expression whose
//! operands are all constant is replaced by its value, computed by naga's own
//! constant evaluator in the module's global arena (so WGSL's rules and
//! errors apply). naga's `process_overrides` does the same on overrides but
//! can emit an expression twice when evaluation reuses an operand, and its
//! WGSL front end treats `let` bindings as run-time values, so weft drives
//! the evaluator itself, expression by expression.

use crate::compile::specialise::map_child_blocks;
use naga::{Constant, Expression, Handle, Module, Range, Span, Statement, Type};
use std::collections::HashMap;

/// A module constant holding a global expression; the writers name or inline it.
pub(super) fn anonymous_constant(
    module: &mut Module,
    ty: Handle<Type>,
    init: Handle<Expression>,
) -> Handle<Constant> {
    module.constants.append(
        Constant {
            name: None,
            ty,
            init,
        },
        Span::UNDEFINED,
    )
}

/// Whether a function expression is a value known at compile time, in the
/// form evaluation leaves one (a literal, a module constant, a zero value).
pub(super) fn is_constant(e: &Expression) -> bool {
    matches!(
        e,
        Expression::Literal(_) | Expression::Constant(_) | Expression::ZeroValue(_)
    )
}

/// A canonical spelling of a constant function expression's value (bit
/// patterns for floats, so `0.0` and `-0.0` differ): equal keys, equal values.
/// `None` for anything else.
pub(super) fn const_key(module: &Module, e: &Expression) -> Option<String> {
    match e {
        Expression::Literal(l) => Some(literal_key(l)),
        Expression::Constant(c) => global_key(module, module.constants[*c].init),
        Expression::ZeroValue(ty) => Some(format!("z{}", ty.index())),
        _ => None,
    }
}

fn literal_key(l: &naga::Literal) -> String {
    match *l {
        naga::Literal::F32(x) => format!("f{:08x}", x.to_bits()),
        naga::Literal::F64(x) => format!("d{:016x}", x.to_bits()),
        naga::Literal::F16(x) => format!("h{:04x}", x.to_bits()),
        other => format!("{other:?}"),
    }
}

fn global_key(module: &Module, h: Handle<Expression>) -> Option<String> {
    Some(match &module.global_expressions[h] {
        Expression::Literal(l) => literal_key(l),
        Expression::Constant(c) => return global_key(module, module.constants[*c].init),
        Expression::ZeroValue(ty) => format!("z{}", ty.index()),
        Expression::Splat { size, value } => {
            format!("s{}({})", *size as u8, global_key(module, *value)?)
        }
        Expression::Compose { ty, components } => {
            let parts = components
                .iter()
                .map(|c| global_key(module, *c))
                .collect::<Option<Vec<_>>>()?;
            format!("c{}({})", ty.index(), parts.join(","))
        }
        _ => return None,
    })
}

/// Replaces every function expression whose operands are all constant by its
/// value, evaluated by naga's constant evaluator in the module's global
/// arena (so WGSL's rules and errors apply; an expression it cannot or may
/// not evaluate, e.g. a division by zero, is left to run time).
pub(super) fn evaluate_constants(module: &mut Module, info: &naga::valid::ModuleInfo) {
    let mut tracker = naga::proc::ExpressionKindTracker::from_arena(&module.global_expressions);
    let mut layouter = naga::proc::Layouter::default();
    let mut fns = std::mem::take(&mut module.functions);
    for (h, f) in fns.iter_mut() {
        evaluate_function(module, f, &info[h], &mut tracker, &mut layouter);
    }
    module.functions = fns;
    let mut eps = std::mem::take(&mut module.entry_points);
    for (i, ep) in eps.iter_mut().enumerate() {
        evaluate_function(
            module,
            &mut ep.function,
            info.get_entry_point(i),
            &mut tracker,
            &mut layouter,
        );
    }
    module.entry_points = eps;
}

/// The operands of a side-effect-free expression the evaluator understands.
fn pure_operands(e: &Expression) -> Option<Vec<Handle<Expression>>> {
    Some(match e {
        Expression::Binary { left, right, .. } => vec![*left, *right],
        Expression::Unary { expr, .. } | Expression::As { expr, .. } => vec![*expr],
        Expression::Splat { value, .. } => vec![*value],
        Expression::Swizzle { vector, .. } => vec![*vector],
        Expression::AccessIndex { base, .. } => vec![*base],
        Expression::Access { base, index } => vec![*base, *index],
        Expression::Compose { components, .. } => components.clone(),
        Expression::Select {
            condition,
            accept,
            reject,
        } => vec![*condition, *accept, *reject],
        Expression::Relational { argument, .. } => vec![*argument],
        Expression::Math {
            arg,
            arg1,
            arg2,
            arg3,
            ..
        } => std::iter::once(*arg)
            .chain(arg1.iter().chain(arg2).chain(arg3).copied())
            .collect(),
        _ => return None,
    })
}

fn evaluate_function(
    module: &mut Module,
    f: &mut naga::Function,
    info: &naga::valid::FunctionInfo,
    tracker: &mut naga::proc::ExpressionKindTracker,
    layouter: &mut naga::proc::Layouter,
) {
    // Function expression -> the global expression holding its value.
    let mut known: HashMap<Handle<Expression>, Handle<Expression>> = HashMap::new();
    let handles: Vec<Handle<Expression>> = f.expressions.iter().map(|(h, _)| h).collect();
    for h in handles {
        let expr = f.expressions[h].clone();
        let global = match &expr {
            Expression::Constant(c) => Some(module.constants[*c].init),
            Expression::Literal(_) | Expression::ZeroValue(_) => {
                naga::proc::ConstantEvaluator::for_wgsl_module(module, tracker, layouter, false)
                    .try_eval_and_append(expr.clone(), Span::UNDEFINED)
                    .ok()
            }
            // The derivative of a constant is zero.
            Expression::Derivative { expr: inner, .. } if known.contains_key(inner) => {
                let ty = type_handle(module, info, h);
                naga::proc::ConstantEvaluator::for_wgsl_module(module, tracker, layouter, false)
                    .try_eval_and_append(Expression::ZeroValue(ty), Span::UNDEFINED)
                    .ok()
            }
            e => pure_operands(e).and_then(|ops| {
                let mapped: HashMap<Handle<Expression>, Handle<Expression>> = ops
                    .iter()
                    .map(|op| known.get(op).map(|g| (*op, *g)))
                    .collect::<Option<_>>()?;
                let mut g = expr.clone();
                remap_operands(&mut g, &mapped);
                let mut evaluator = naga::proc::ConstantEvaluator::for_wgsl_module(
                    module, tracker, layouter, false,
                );
                match g {
                    // naga's evaluator has no `mix`: a + (b - a) t, which it has.
                    Expression::Math {
                        fun: naga::MathFunction::Mix,
                        arg: a,
                        arg1: Some(b),
                        arg2: Some(t),
                        ..
                    } => {
                        let mut bin = |op, left, right| {
                            evaluator
                                .try_eval_and_append(
                                    Expression::Binary { op, left, right },
                                    Span::UNDEFINED,
                                )
                                .ok()
                        };
                        let d = bin(naga::BinaryOperator::Subtract, b, a)?;
                        let p = bin(naga::BinaryOperator::Multiply, d, t)?;
                        bin(naga::BinaryOperator::Add, a, p)
                    }
                    g => evaluator.try_eval_and_append(g, Span::UNDEFINED).ok(),
                }
            }),
        };
        let Some(g) = global else { continue };
        known.insert(h, g);
        if f.expressions[h].needs_pre_emit() {
            continue;
        }
        f.expressions[h] = match module.global_expressions[g] {
            Expression::Literal(l) => Expression::Literal(l),
            _ => {
                let ty = type_handle(module, info, h);
                Expression::Constant(anonymous_constant(module, ty, g))
            }
        };
    }
    let body = std::mem::take(&mut f.body);
    f.body = filter_emits(body, &f.expressions);
}

/// The type of a function expression, as a handle.
fn type_handle(
    module: &mut Module,
    info: &naga::valid::FunctionInfo,
    h: Handle<Expression>,
) -> Handle<Type> {
    match &info[h].ty {
        naga::proc::TypeResolution::Handle(t) => *t,
        naga::proc::TypeResolution::Value(inner) => module.types.insert(
            Type {
                name: None,
                inner: inner.clone(),
            },
            Span::UNDEFINED,
        ),
    }
}

fn remap_operands(e: &mut Expression, map: &HashMap<Handle<Expression>, Handle<Expression>>) {
    let m = |h: &mut Handle<Expression>| {
        if let Some(g) = map.get(h) {
            *h = *g;
        }
    };
    match e {
        Expression::Binary { left, right, .. } => {
            m(left);
            m(right);
        }
        Expression::Unary { expr, .. } | Expression::As { expr, .. } => m(expr),
        Expression::Splat { value, .. } => m(value),
        Expression::Swizzle { vector, .. } => m(vector),
        Expression::AccessIndex { base, .. } => m(base),
        Expression::Access { base, index } => {
            m(base);
            m(index);
        }
        Expression::Compose { components, .. } => components.iter_mut().for_each(m),
        Expression::Select {
            condition,
            accept,
            reject,
        } => {
            m(condition);
            m(accept);
            m(reject);
        }
        Expression::Relational { argument, .. } => m(argument),
        Expression::Math {
            arg,
            arg1,
            arg2,
            arg3,
            ..
        } => {
            m(arg);
            arg1.iter_mut()
                .chain(arg2.iter_mut())
                .chain(arg3.iter_mut())
                .for_each(m);
        }
        _ => {}
    }
}

/// `Emit` ranges may not cover pre-emitted expressions (constants): split them.
pub(super) fn filter_emits(block: naga::Block, exprs: &naga::Arena<Expression>) -> naga::Block {
    let mut out = naga::Block::with_capacity(block.len());
    for (stmt, span) in block.span_into_iter() {
        let stmt = match stmt {
            Statement::Emit(range) => {
                let mut run: Option<(Handle<Expression>, Handle<Expression>)> = None;
                for h in range {
                    if exprs[h].needs_pre_emit() {
                        if let Some((a, b)) = run.take() {
                            out.push(Statement::Emit(Range::new_from_bounds(a, b)), span);
                        }
                    } else {
                        run = Some(match run {
                            Some((a, _)) => (a, h),
                            None => (h, h),
                        });
                    }
                }
                match run {
                    Some((a, b)) => Statement::Emit(Range::new_from_bounds(a, b)),
                    None => continue,
                }
            }
            other => map_child_blocks(other, &mut |b| filter_emits(b, exprs)),
        };
        out.push(stmt, span);
    }
    out
}
