//! Algebraic identities with a constant operand, exact in IEEE arithmetic.
//!
//! Evaluation (`evaluate.rs`) needs every operand constant; a folded
//! parameter often meets a run-time value instead: `x * brightness` with
//! brightness 1, `select(a, b, USE_X)` with the keyword known, `clamp(x, lo,
//! hi)` with lo = hi. What is rewritten, and only when the result has the
//! expression's type (a scalar `x * vec3(1.0)` stays):
//!
//! - `select(a, b, c)` with `c` constant (all components alike) -> `a` or `b`;
//!   `select(a, a, c)` -> `a`;
//! - `x * 1`, `1 * x`, `x / 1` -> `x` (exact, NaN and infinities included);
//! - `x - 0.0` and `x + -0.0` -> `x` (exact, -0.0 included), integer `x ± 0`;
//!   **not** `x + 0.0` (-0.0 + 0.0 is +0.0) and **not** `x * 0` (NaN x 0 and
//!   inf x 0 are NaN);
//! - `min(x, x)`, `max(x, x)` -> `x`;
//! - `clamp(x, c, c)` -> `c` (WGSL's clamp is min(max(x, c), c): c for every
//!   x, NaN included where the GPU's max returns the non-NaN operand, as
//!   IEEE's maxNum and every shading language's max do). This one pays on the
//!   GPU: Mesa's NIR does not fold it, and a degenerate range (a
//!   microcylinder segment of zero width) otherwise keeps three identical
//!   quadrature nodes apart.
//!
//! The GPU compiler applies the others itself; they are here so that every
//! language's output is the simplified one. An expression rewritten to
//! another is redirected: every use points at the operand instead.

use super::evaluate::{const_key, filter_emits, is_constant};
use naga::{
    BinaryOperator, Block, Expression, Function, Handle, Literal, MathFunction, Module,
    SampleLevel, Statement,
};
use std::collections::HashMap;

/// Applies the identities in every function and entry point; returns how many.
pub(super) fn simplify_identities(module: &mut Module, info: &naga::valid::ModuleInfo) -> usize {
    let mut changed = 0;
    let mut fns = std::mem::take(&mut module.functions);
    for (h, f) in fns.iter_mut() {
        changed += simplify_function(module, f, &info[h]);
    }
    module.functions = fns;
    let mut eps = std::mem::take(&mut module.entry_points);
    for (i, ep) in eps.iter_mut().enumerate() {
        changed += simplify_function(module, &mut ep.function, info.get_entry_point(i));
    }
    module.entry_points = eps;
    changed
}

enum Rewrite {
    /// Every use of the expression uses this one instead.
    Alias(Handle<Expression>),
    /// The expression becomes this constant.
    Constant(Expression),
}

fn simplify_function(module: &Module, f: &mut Function, info: &naga::valid::FunctionInfo) -> usize {
    if !block_supported(&f.body) || f.expressions.iter().any(|(_, e)| !expression_supported(e)) {
        return 0;
    }
    let same_type = |a: Handle<Expression>, b: Handle<Expression>| {
        info[a].ty.inner_with(&module.types) == info[b].ty.inner_with(&module.types)
    };
    let mut alias: HashMap<Handle<Expression>, Handle<Expression>> = HashMap::new();
    let mut constants = 0;
    let handles: Vec<Handle<Expression>> = f.expressions.iter().map(|(h, _)| h).collect();
    for h in handles {
        operands_mut(&mut f.expressions[h], &mut |o| {
            if let Some(a) = alias.get(o) {
                *o = *a;
            }
        });
        let rewrite = rewrite(module, &f.expressions, h, &same_type);
        match rewrite {
            Some(Rewrite::Alias(a)) => {
                alias.insert(h, a);
            }
            Some(Rewrite::Constant(c)) => {
                f.expressions[h] = c;
                constants += 1;
            }
            None => {}
        }
    }
    if alias.is_empty() && constants == 0 {
        return 0;
    }
    let body = std::mem::take(&mut f.body);
    let body = redirect_block(body, &alias);
    f.body = filter_emits(body, &f.expressions);
    // A name moves to the expression that now carries the value (a `let`
    // bound to `x * 1.0` names `x`), unless that one has a name or is a constant.
    let mut moved: Vec<_> = alias.iter().collect();
    moved.sort();
    for (h, a) in moved {
        if let Some(name) = f.named_expressions.shift_remove(h)
            && !f.named_expressions.contains_key(a)
            && !f.expressions[*a].needs_pre_emit()
        {
            f.named_expressions.insert(*a, name);
        }
    }
    alias.len() + constants
}

fn rewrite(
    module: &Module,
    exprs: &naga::Arena<Expression>,
    h: Handle<Expression>,
    same_type: &dyn Fn(Handle<Expression>, Handle<Expression>) -> bool,
) -> Option<Rewrite> {
    let alias_if = |x: Handle<Expression>| same_type(x, h).then_some(Rewrite::Alias(x));
    let value = |x: Handle<Expression>| components(module, &exprs[x]);
    match exprs[h] {
        Expression::Select {
            condition,
            accept,
            reject,
        } => {
            if accept == reject {
                return Some(Rewrite::Alias(accept));
            }
            let c = value(condition)?;
            if c.iter().all(|l| *l == Literal::Bool(true)) {
                Some(Rewrite::Alias(accept))
            } else if c.iter().all(|l| *l == Literal::Bool(false)) {
                Some(Rewrite::Alias(reject))
            } else {
                None
            }
        }
        Expression::Binary { op, left, right } => {
            let is = |x: Handle<Expression>, test: fn(&Literal) -> bool| {
                value(x).is_some_and(|c| !c.is_empty() && c.iter().all(test))
            };
            match op {
                BinaryOperator::Multiply if is(right, is_one) => alias_if(left),
                BinaryOperator::Multiply if is(left, is_one) => alias_if(right),
                BinaryOperator::Divide if is(right, is_one) => alias_if(left),
                BinaryOperator::Subtract if is(right, is_plus_zero) => alias_if(left),
                BinaryOperator::Add if is(right, is_neutral_in_add) => alias_if(left),
                BinaryOperator::Add if is(left, is_neutral_in_add) => alias_if(right),
                _ => None,
            }
        }
        Expression::Math {
            fun: MathFunction::Min | MathFunction::Max,
            arg,
            arg1: Some(b),
            ..
        } if arg == b => Some(Rewrite::Alias(arg)),
        Expression::Math {
            fun: MathFunction::Clamp,
            arg1: Some(lo),
            arg2: Some(hi),
            ..
        } => {
            let (l, r) = (&exprs[lo], &exprs[hi]);
            let equal = is_constant(l)
                && const_key(module, l).is_some_and(|k| const_key(module, r) == Some(k));
            equal.then(|| Rewrite::Constant(l.clone()))
        }
        _ => None,
    }
}

fn is_one(l: &Literal) -> bool {
    match *l {
        Literal::F32(x) => x == 1.0,
        Literal::F16(x) => x == half::f16::ONE,
        Literal::I32(x) => x == 1,
        Literal::U32(x) => x == 1,
        _ => false,
    }
}

fn is_plus_zero(l: &Literal) -> bool {
    match *l {
        Literal::F32(x) => x.to_bits() == 0,
        Literal::F16(x) => x.to_bits() == 0,
        Literal::I32(x) => x == 0,
        Literal::U32(x) => x == 0,
        _ => false,
    }
}

/// -0.0, or an integer 0: `x + that` is `x` for every `x`.
fn is_neutral_in_add(l: &Literal) -> bool {
    match *l {
        Literal::F32(x) => x.to_bits() == 0x8000_0000,
        Literal::F16(x) => x.to_bits() == 0x8000,
        Literal::I32(x) => x == 0,
        Literal::U32(x) => x == 0,
        _ => false,
    }
}

/// The scalar components of a constant function expression (one for a
/// scalar), when it is a constant built from literals.
fn components(module: &Module, e: &Expression) -> Option<Vec<Literal>> {
    let mut out = Vec::new();
    match e {
        Expression::Literal(l) => out.push(*l),
        Expression::Constant(c) => global(module, module.constants[*c].init, &mut out)?,
        Expression::ZeroValue(ty) => zeros(module, *ty, &mut out)?,
        _ => return None,
    }
    Some(out)
}

fn global(module: &Module, h: Handle<Expression>, out: &mut Vec<Literal>) -> Option<()> {
    match &module.global_expressions[h] {
        Expression::Literal(l) => out.push(*l),
        Expression::Constant(c) => global(module, module.constants[*c].init, out)?,
        Expression::Splat { size, value } => {
            let mut one = Vec::new();
            global(module, *value, &mut one)?;
            for _ in 0..*size as u8 {
                out.extend(one.iter().copied());
            }
        }
        Expression::Compose { components, .. } => {
            for c in components {
                global(module, *c, out)?;
            }
        }
        Expression::ZeroValue(ty) => zeros(module, *ty, out)?,
        _ => return None,
    }
    Some(())
}

fn zeros(module: &Module, ty: naga::Handle<naga::Type>, out: &mut Vec<Literal>) -> Option<()> {
    match module.types[ty].inner {
        naga::TypeInner::Scalar(s) => out.push(Literal::zero(s)?),
        naga::TypeInner::Vector { size, scalar } => {
            out.extend(std::iter::repeat_n(Literal::zero(scalar)?, size as usize))
        }
        _ => return None,
    }
    Some(())
}

/// Whether every statement is one whose expression operands `redirect_block` rewrites.
fn block_supported(block: &Block) -> bool {
    block.iter().all(|s| match s {
        Statement::Emit(_)
        | Statement::Break
        | Statement::Continue
        | Statement::Kill
        | Statement::Return { .. }
        | Statement::Store { .. }
        | Statement::ImageStore { .. }
        | Statement::Call { .. }
        | Statement::ControlBarrier(_)
        | Statement::MemoryBarrier(_) => true,
        Statement::Block(b) => block_supported(b),
        Statement::If { accept, reject, .. } => block_supported(accept) && block_supported(reject),
        Statement::Loop {
            body, continuing, ..
        } => block_supported(body) && block_supported(continuing),
        Statement::Switch { cases, .. } => cases.iter().all(|c| block_supported(&c.body)),
        _ => false,
    })
}

fn expression_supported(e: &Expression) -> bool {
    !matches!(
        e,
        Expression::RayQueryVertexPositions { .. }
            | Expression::RayQueryGetIntersection { .. }
            | Expression::CooperativeLoad { .. }
            | Expression::CooperativeMultiplyAdd { .. }
    )
}

/// Applies `f` to every expression operand of `e` (for the supported kinds).
fn operands_mut(e: &mut Expression, f: &mut dyn FnMut(&mut Handle<Expression>)) {
    match e {
        Expression::Compose { components, .. } => components.iter_mut().for_each(f),
        Expression::Access { base, index } => {
            f(base);
            f(index);
        }
        Expression::AccessIndex { base, .. } => f(base),
        Expression::Splat { value, .. } => f(value),
        Expression::Swizzle { vector, .. } => f(vector),
        Expression::Load { pointer } => f(pointer),
        Expression::ImageSample {
            image,
            sampler,
            coordinate,
            array_index,
            offset,
            level,
            depth_ref,
            ..
        } => {
            f(image);
            f(sampler);
            f(coordinate);
            array_index.iter_mut().for_each(&mut *f);
            offset.iter_mut().for_each(&mut *f);
            match level {
                SampleLevel::Exact(x) | SampleLevel::Bias(x) => f(x),
                SampleLevel::Gradient { x, y } => {
                    f(x);
                    f(y);
                }
                SampleLevel::Auto | SampleLevel::Zero => {}
            }
            depth_ref.iter_mut().for_each(f);
        }
        Expression::ImageLoad {
            image,
            coordinate,
            array_index,
            sample,
            level,
        } => {
            f(image);
            f(coordinate);
            array_index.iter_mut().for_each(&mut *f);
            sample.iter_mut().for_each(&mut *f);
            level.iter_mut().for_each(f);
        }
        Expression::ImageQuery { image, query } => {
            f(image);
            if let naga::ImageQuery::Size { level: Some(l) } = query {
                f(l);
            }
        }
        Expression::Unary { expr, .. }
        | Expression::Derivative { expr, .. }
        | Expression::As { expr, .. } => f(expr),
        Expression::Binary { left, right, .. } => {
            f(left);
            f(right);
        }
        Expression::Select {
            condition,
            accept,
            reject,
        } => {
            f(condition);
            f(accept);
            f(reject);
        }
        Expression::Relational { argument, .. } => f(argument),
        Expression::Math {
            arg,
            arg1,
            arg2,
            arg3,
            ..
        } => {
            f(arg);
            arg1.iter_mut().for_each(&mut *f);
            arg2.iter_mut().for_each(&mut *f);
            arg3.iter_mut().for_each(f);
        }
        Expression::ArrayLength(x) => f(x),
        _ => {}
    }
}

fn redirect_block(block: Block, alias: &HashMap<Handle<Expression>, Handle<Expression>>) -> Block {
    let r = |h: &mut Handle<Expression>| {
        if let Some(a) = alias.get(h) {
            *h = *a;
        }
    };
    let mut out = Block::with_capacity(block.len());
    for (mut stmt, span) in block.span_into_iter() {
        match &mut stmt {
            Statement::If { condition, .. } => r(condition),
            Statement::Switch { selector, .. } => r(selector),
            Statement::Loop { break_if, .. } => break_if.iter_mut().for_each(r),
            Statement::Return { value } => value.iter_mut().for_each(r),
            Statement::Store { pointer, value } => {
                r(pointer);
                r(value);
            }
            Statement::ImageStore {
                image,
                coordinate,
                array_index,
                value,
            } => {
                r(image);
                r(coordinate);
                array_index.iter_mut().for_each(r);
                r(value);
            }
            Statement::Call { arguments, .. } => arguments.iter_mut().for_each(r),
            _ => {}
        }
        let stmt =
            crate::compile::specialise::map_child_blocks(stmt, &mut |b| redirect_block(b, alias));
        out.push(stmt, span);
    }
    out
}

#[cfg(test)]
mod tests {
    use crate::scene::fold::test_support::folded;

    #[test]
    fn only_exact_identities_are_applied() {
        let wgsl = folded(
            "
@fragment fn fs(@location(0) v: vec3<f32>, @location(1) s: f32) -> @location(0) vec4<f32> {
    let a = v * 1.0;
    let b = select(v, a, true);
    let c = clamp(s, 0.25, 0.25);
    let d = s + 0.0;
    let e = s * 0.0;
    let g = (s - 0.0) / 1.0;
    let h = s * vec3<f32>(1.0);
    return vec4<f32>(b + h, c + d + e + g);
}",
        );
        for gone in ["* 1f", "/ 1f", "- 0f", "select", "clamp"] {
            assert!(!wgsl.contains(gone), "`{gone}` left in:\n{wgsl}");
        }
        // x + 0.0 is +0.0 for x = -0.0, x * 0.0 is NaN for infinite x; a
        // scalar times vec3(1.0) is a vector.
        for kept in ["(s + 0f)", "(s * 0f)", "(s * vec3(1f))", "0.25f"] {
            assert!(wgsl.contains(kept), "`{kept}` missing from:\n{wgsl}");
        }
    }
}
