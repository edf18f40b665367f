//! Vector `select` for HLSL: the module transform that keeps naga's HLSL
//! writer from writing a ternary with a vector condition.
//!
//! naga writes every `Expression::Select` as `(c ? a : b)`. With a vector
//! `c` that is a per-component select in HLSL 2018 and earlier (FXC, DXC
//! `-HV 2016`), but HLSL 2021 — DXC's default — made `?:` short-circuiting and
//! rejects a non-scalar condition ("use 'select'"), and Slang deprecates it.
//! The `select` intrinsic exists only in HLSL 2021, so the portable form is a
//! per-component scalar ternary. This module rewrites every vector-condition
//! `Select` into a call of a small helper function (one per vector type) whose
//! body composes N scalar selects: `float3(c.x ? a.x : b.x, …)`.
//!
//! Why a call rather than inlining the scalar selects: an expression may only
//! refer to earlier handles, so inlining would renumber every expression of
//! the function; a call needs only the `Select` turned into a `CallResult`, its
//! `Emit` range split around the new `Call`, and the function handles shifted
//! (the helpers go first: a function may only call earlier ones).

use naga::valid::ModuleInfo;
use naga::{
    Arena, Block, Expression, Function, FunctionArgument, FunctionResult, Handle, Module, Scalar,
    Span, Statement, Type, TypeInner, VectorSize,
};
use std::collections::{BTreeMap, BTreeSet};

/// The vector-condition `Select` expressions of one function: what the HLSL
/// writer would turn into a vector ternary.
fn vector_selects(
    module: &Module,
    fun: &Function,
    info: &naga::valid::FunctionInfo,
) -> BTreeMap<Handle<Expression>, (VectorSize, Scalar)> {
    let mut found = BTreeMap::new();
    for (h, e) in fun.expressions.iter() {
        if let Expression::Select {
            condition, accept, ..
        } = *e
        {
            let cond = info[condition].ty.inner_with(&module.types);
            if let TypeInner::Vector { .. } = cond {
                match *info[accept].ty.inner_with(&module.types) {
                    TypeInner::Vector { size, scalar } => {
                        found.insert(h, (size, scalar));
                    }
                    // A vector condition always selects vectors (naga validates
                    // that); keep the count honest if it ever does not.
                    _ => {
                        found.insert(h, (VectorSize::Quad, Scalar::BOOL));
                    }
                }
            }
        }
    }
    found
}

/// How many `Select` expressions with a vector condition `module` has, in all
/// functions and entry points. Zero is what [`split_vector_selects`] leaves.
pub fn count_vector_selects(module: &Module, info: &ModuleInfo) -> usize {
    let functions = module
        .functions
        .iter()
        .map(|(h, f)| vector_selects(module, f, &info[h]).len());
    let entries = module
        .entry_points
        .iter()
        .enumerate()
        .map(|(i, ep)| vector_selects(module, &ep.function, info.get_entry_point(i)).len());
    functions.chain(entries).sum()
}

/// `module` with every vector-condition `Select` replaced by a call of a
/// per-component helper; `None` when it has none (the common case: no copy,
/// no re-validation).
pub fn split_vector_selects(module: &Module, info: &ModuleInfo) -> Option<Module> {
    let per_function: Vec<_> = module
        .functions
        .iter()
        .map(|(h, f)| vector_selects(module, f, &info[h]))
        .collect();
    let per_entry: Vec<_> = module
        .entry_points
        .iter()
        .enumerate()
        .map(|(i, ep)| vector_selects(module, &ep.function, info.get_entry_point(i)))
        .collect();
    let kinds: BTreeSet<(VectorSize, Scalar)> = per_function
        .iter()
        .chain(&per_entry)
        .flat_map(|m| m.values().copied())
        .collect();
    if kinds.is_empty() {
        return None;
    }
    let mut out = module.clone();
    // Helpers first, in a fixed order (deterministic output).
    let mut functions = Arena::new();
    let mut helper = BTreeMap::new();
    for &(size, scalar) in &kinds {
        let f = helper_function(&mut out, size, scalar);
        helper.insert((size, scalar), functions.append(f, Span::UNDEFINED));
    }
    // A function only calls earlier ones, so each callee is already in `moved`
    // when its caller is rewritten.
    let mut moved: Vec<Handle<Function>> = Vec::new();
    let mut old = std::mem::take(&mut out.functions);
    for ((_, mut f, span), selects) in old.drain().zip(&per_function) {
        rewrite_function(&mut f, selects, &helper, &|h| moved[h.index()]);
        moved.push(functions.append(f, span));
    }
    out.functions = functions;
    for (ep, selects) in out.entry_points.iter_mut().zip(&per_entry) {
        rewrite_function(&mut ep.function, selects, &helper, &|h| moved[h.index()]);
    }
    Some(out)
}

/// `fn(c: vecN<bool>, a: vecN<T>, b: vecN<T>) -> vecN<T>`: `vecN(c[i] ? a[i] : b[i], …)`.
fn helper_function(module: &mut Module, size: VectorSize, scalar: Scalar) -> Function {
    let mut ty = |scalar| {
        module.types.insert(
            Type {
                name: None,
                inner: TypeInner::Vector { size, scalar },
            },
            Span::UNDEFINED,
        )
    };
    let (cond_ty, value_ty) = (ty(Scalar::BOOL), ty(scalar));
    let arg = |name: &str, ty| FunctionArgument {
        name: Some(name.to_string()),
        ty,
        binding: None,
    };
    let mut f = Function {
        // Names no shader uses (naga makes every name unique in the module,
        // so a short one would rename the shader's own `c`, `a`, `b`), none
        // ending in a digit (naga would append `_`).
        name: Some(format!("weft_select{}_{}", size as u8, scalar_name(scalar))),
        arguments: vec![
            arg("weft_sel_c", cond_ty),
            arg("weft_sel_a", value_ty),
            arg("weft_sel_b", value_ty),
        ],
        result: Some(FunctionResult {
            ty: value_ty,
            binding: None,
        }),
        ..Function::default()
    };
    let e = &mut f.expressions;
    let args: Vec<_> = (0..3)
        .map(|i| e.append(Expression::FunctionArgument(i), Span::UNDEFINED))
        .collect();
    let first = e.len();
    let components = (0..size as u32)
        .map(|index| {
            let mut at = |base| e.append(Expression::AccessIndex { base, index }, Span::UNDEFINED);
            let (condition, accept, reject) = (at(args[0]), at(args[1]), at(args[2]));
            let select = Expression::Select {
                condition,
                accept,
                reject,
            };
            e.append(select, Span::UNDEFINED)
        })
        .collect();
    let compose = e.append(
        Expression::Compose {
            ty: value_ty,
            components,
        },
        Span::UNDEFINED,
    );
    let emitted = naga::Range::from_index_range(first as u32..e.len() as u32, e);
    f.body.push(Statement::Emit(emitted), Span::UNDEFINED);
    f.body.push(
        Statement::Return {
            value: Some(compose),
        },
        Span::UNDEFINED,
    );
    f
}

fn scalar_name(scalar: Scalar) -> String {
    let kind = match scalar.kind {
        naga::ScalarKind::Float => "f",
        naga::ScalarKind::Sint => "i",
        naga::ScalarKind::Uint => "u",
        naga::ScalarKind::Bool => "b",
        _ => "x",
    };
    format!("{kind}{}bit", 8 * scalar.width)
}

/// Turns each listed `Select` into a call of its helper and shifts the calls
/// of the module's other functions past the helpers.
fn rewrite_function(
    f: &mut Function,
    selects: &BTreeMap<Handle<Expression>, (VectorSize, Scalar)>,
    helper: &BTreeMap<(VectorSize, Scalar), Handle<Function>>,
    shift: &dyn Fn(Handle<Function>) -> Handle<Function>,
) {
    let mut calls = BTreeMap::new();
    for (h, e) in f.expressions.iter_mut() {
        if let Expression::CallResult(callee) = e {
            *callee = shift(*callee);
        }
        if let (Some(kind), Expression::Select { .. }) = (selects.get(&h), &*e) {
            let Expression::Select {
                condition,
                accept,
                reject,
            } = std::mem::replace(e, Expression::CallResult(helper[kind]))
            else {
                unreachable!("matched a Select above")
            };
            calls.insert(h, (helper[kind], vec![condition, accept, reject]));
        }
    }
    let body = std::mem::take(&mut f.body);
    f.body = rewrite_block(body, &calls, &f.expressions, shift);
}

type Calls = BTreeMap<Handle<Expression>, (Handle<Function>, Vec<Handle<Expression>>)>;

fn rewrite_block(
    block: Block,
    calls: &Calls,
    expressions: &Arena<Expression>,
    shift: &dyn Fn(Handle<Function>) -> Handle<Function>,
) -> Block {
    let mut out = Block::with_capacity(block.len());
    let sub = |b: Block| rewrite_block(b, calls, expressions, shift);
    for (statement, span) in block.span_into_iter() {
        let statement = match statement {
            Statement::Emit(range) => {
                split_emit(range, calls, expressions, &mut out, span);
                continue;
            }
            Statement::Call {
                function,
                arguments,
                result,
            } => Statement::Call {
                function: shift(function),
                arguments,
                result,
            },
            Statement::Block(b) => Statement::Block(sub(b)),
            Statement::If {
                condition,
                accept,
                reject,
            } => Statement::If {
                condition,
                accept: sub(accept),
                reject: sub(reject),
            },
            Statement::Switch { selector, cases } => Statement::Switch {
                selector,
                cases: cases
                    .into_iter()
                    .map(|c| naga::SwitchCase {
                        body: sub(c.body),
                        ..c
                    })
                    .collect(),
            },
            Statement::Loop {
                body,
                continuing,
                break_if,
            } => Statement::Loop {
                body: sub(body),
                continuing: sub(continuing),
                break_if,
            },
            other => other,
        };
        out.push(statement, span);
    }
    out
}

/// `Emit(a..b)` holding rewritten selects: `Emit(a..s)`, `Call(s)`, `Emit(s+1..b)`.
/// A call result must not be emitted; the call sits where the select was
/// evaluated, so its arguments are in scope and later expressions see it.
fn split_emit(
    range: naga::Range<Expression>,
    calls: &Calls,
    expressions: &Arena<Expression>,
    out: &mut Block,
    span: Span,
) {
    let indices = range.index_range();
    let flush = |start: u32, end: u32, out: &mut Block| {
        if start < end {
            let r = naga::Range::from_index_range(start..end, expressions);
            out.push(Statement::Emit(r), span);
        }
    };
    let mut start = indices.start;
    for h in range {
        if let Some((function, arguments)) = calls.get(&h) {
            let i = h.index() as u32;
            flush(start, i, out);
            out.push(
                Statement::Call {
                    function: *function,
                    arguments: arguments.clone(),
                    result: Some(h),
                },
                span,
            );
            start = i + 1;
        }
    }
    flush(start, indices.end, out);
}

#[cfg(test)]
mod tests {
    use super::*;

    const WGSL: &str = "
fn pick(v: vec3<f32>, m: vec2<i32>) -> vec3<f32> {
    let i = select(vec2<i32>(1, 2), m, m > vec2<i32>(0));
    return select(vec3<f32>(0.0), v, v > vec3<f32>(0.5)) + f32(i.x + i.y);
}
@fragment
fn fs(@location(0) v: vec3<f32>) -> @location(0) vec4<f32> {
    let a = pick(v, vec2<i32>(v.xy));
    let b = select(vec4<f32>(a, 1.0), vec4<f32>(v, 0.0), vec4<bool>((v.x < 0.2), true, false, (v.z > 0.0)));
    let s = select(1.0, 2.0, v.x > 0.5);
    return b * s;
}
";

    fn parse(src: &str) -> (Module, ModuleInfo) {
        let m = naga::front::wgsl::parse_str(src).unwrap();
        let info = crate::compile::compose::validator().validate(&m).unwrap();
        (m, info)
    }

    #[test]
    fn vector_selects_become_helper_calls_that_validate() {
        let (m, info) = parse(WGSL);
        assert_eq!(count_vector_selects(&m, &info), 3);
        let split = split_vector_selects(&m, &info).expect("vector selects to split");
        let info = crate::compile::compose::validator()
            .validate(&split)
            .unwrap_or_else(|e| panic!("{e:?}"));
        assert_eq!(count_vector_selects(&split, &info), 0);
        // One helper per vector type (vec2<i32>, vec3<f32>, vec4<f32>), ahead of `pick`.
        let names: Vec<_> = split
            .functions
            .iter()
            .map(|(_, f)| f.name.clone().unwrap())
            .collect();
        assert_eq!(
            names,
            [
                "weft_select2_i32bit",
                "weft_select3_f32bit",
                "weft_select4_f32bit",
                "pick"
            ]
        );
        // The scalar select is left alone; the HLSL has only scalar ternaries.
        let hlsl = crate::compile::backends::emit_hlsl(
            &m,
            &crate::compile::compose::validator().validate(&m).unwrap(),
        )
        .unwrap();
        assert!(
            hlsl.contains("(weft_sel_c.x ? weft_sel_a.x : weft_sel_b.x)"),
            "{hlsl}"
        );
    }

    #[test]
    fn a_module_without_vector_selects_is_not_copied() {
        let (m, info) =
            parse("@fragment fn fs() -> @location(0) f32 { return select(1.0, 2.0, true); }");
        assert!(split_vector_selects(&m, &info).is_none());
    }
}
