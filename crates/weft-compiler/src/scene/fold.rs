//! Folding a scene instance's constants into its shader (naga IR).
//!
//! The generic variant reads every parameter from the material uniform. For a
//! scene instance most parameters are constants of the scene, so:
//! 1. loads of folded uniform members (and of components and elements of
//!    them) become module constants — the material uniform's, and with
//!    `[static_lighting]` the frame uniform's light and SH; samples of
//!    textures left at a built-in default become the constant texel the
//!    sample would return;
//! 2. every override (tier, every keyword, the engine features) becomes a
//!    literal;
//! 3. round after round until nothing changes (`fold_to_fixed_point`):
//!    every expression whose operands are now constant is evaluated
//!    (`evaluate.rs`), identities with a constant operand are applied
//!    (`identities.rs`: `select` on a constant, `x * 1`, `clamp(x, c, c)`,
//!    …), `if`s on constant conditions keep only the taken branch, locals
//!    holding a constant are read as it and loops that now run once or never
//!    become their body or nothing (`locals.rs`, `loops.rs`), calls of pure
//!    helpers that return a constant become it, and calls with constant
//!    arguments call a clone of the helper bound to them (`call_sites.rs`),
//!    which the next round folds in turn;
//! 4. calls to side-effect-free helpers whose result nothing uses go
//!    (`dead_calls.rs`), and compaction drops what only dead code used:
//!    textures, LUTs, helper functions;
//! 5. the material uniform shrinks to the members still read (the `dynamic`
//!    parameters, curves), re-laid out by WGSL's rules; with none left, the
//!    binding disappears.
//!
//! Every step keeps the shader's value bit for bit where the GPU follows
//! IEEE arithmetic (no `x * 0 -> 0`, no `x + 0.0 -> x`; `identities.rs`), and
//! the output is deterministic (clones are named and ordered by where they
//! are first needed). What pays on the GPU, where the driver inlines every
//! call and folds literals itself, is what it cannot do after inlining: a
//! loop it will not unroll resolved (microcylinder's one-offset threads) and
//! a degenerate `clamp` folded (docs/performance.md, "Scene specialisation").

use super::call_sites::{fold_constant_returns, specialise_calls};
use super::dead_calls::remove_dead_calls;
use super::evaluate::{anonymous_constant, evaluate_constants, filter_emits};
use super::identities::simplify_identities;
use super::locals::forward_locals;
use crate::compile::engine_binding::FRAME_VAR;
use crate::compile::specialise::prune_function;
use naga::{
    AddressSpace, Constant, Expression, Handle, Literal, Module, Span, StructMember, Type,
    TypeInner,
};
use std::collections::{BTreeMap, BTreeSet, HashMap};

/// A scalar or vector constant, as the uniform would have held it.
#[derive(Clone, Debug, PartialEq)]
pub enum ConstValue {
    F32(Vec<f32>),
    I32(i32),
    U32(u32),
}

/// What to fold into one instance's shader.
#[derive(Clone, Debug, Default)]
pub struct FoldRequest {
    /// Every override's value (tier, keywords, engine features).
    pub overrides: BTreeMap<String, Literal>,
    /// Uniform member -> the value to fold in its place.
    pub members: BTreeMap<String, ConstValue>,
    /// Texture global -> the constant texel sampling it returns.
    pub textures: BTreeMap<String, [f32; 4]>,
    /// The material uniform variable's name.
    pub uniform_var: String,
    /// Frame-uniform (`weft_frame`, group 0) member -> the value to fold in
    /// its place: a scene with `[static_lighting]` fixes the light and the SH
    /// (docs/scenes.md). The frame uniform keeps its layout (engines bind
    /// group 0 whole); only its reads become constants.
    pub frame_members: BTreeMap<String, ConstValue>,
    /// Entry points of the passes the instance draws; the module's others
    /// (passes it does not draw, a library's unused `vs_main`) are dropped.
    /// `None` keeps every entry point (a module folded on its own).
    pub keep_entry_points: Option<Vec<String>>,
}

/// The folded module and what folding left in the uniform.
pub struct Folded {
    pub module: Module,
    /// Members asked to be folded that the code reads in a way that cannot
    /// be folded (a dynamic index): they stay in the uniform with their value.
    pub kept_in_uniform: BTreeSet<String>,
}

/// A uniform variable some of whose members fold to constants.
struct FoldedUniform {
    var: Handle<naga::GlobalVariable>,
    members: Vec<StructMember>,
    /// Member index -> its value.
    folded: BTreeMap<u32, ConstValue>,
}

/// The uniform `var_name` and the members of `values` it can fold; and the
/// names of those it cannot (read through a path `fold` cannot see: a
/// dynamic index, the whole struct), which stay in the uniform.
fn folded_uniform(
    module: &Module,
    var_name: &str,
    values: &BTreeMap<String, ConstValue>,
) -> (Option<FoldedUniform>, BTreeSet<String>) {
    let Some(var) = module.global_variables.iter().find_map(|(h, g)| {
        (g.space == AddressSpace::Uniform && g.name.as_deref() == Some(var_name)).then_some(h)
    }) else {
        return (None, BTreeSet::new());
    };
    let members: Vec<StructMember> = match &module.types[module.global_variables[var].ty].inner {
        TypeInner::Struct { members, .. } => members.clone(),
        _ => Vec::new(),
    };
    let mut unfoldable = BTreeSet::new();
    for f in functions(module) {
        unfoldable.extend(unfoldable_members(f, var));
    }
    let mut folded = BTreeMap::new();
    let mut kept = BTreeSet::new();
    for (name, v) in values {
        let Some(i) = members.iter().position(|m| m.name.as_deref() == Some(name)) else {
            continue;
        };
        if unfoldable.contains(&(i as u32)) {
            kept.insert(name.clone());
        } else {
            folded.insert(i as u32, v.clone());
        }
    }
    let uniform = FoldedUniform {
        var,
        members,
        folded,
    };
    (Some(uniform), kept)
}

pub fn fold(module: &Module, request: &FoldRequest) -> Result<Folded, String> {
    let mut module = module.clone();
    let (material, kept_in_uniform) =
        folded_uniform(&module, &request.uniform_var, &request.members);
    let (frame, _) = folded_uniform(&module, FRAME_VAR, &request.frame_members);
    let uniforms: Vec<FoldedUniform> = material.into_iter().chain(frame).collect();

    let textures: HashMap<Handle<naga::GlobalVariable>, [f32; 4]> = module
        .global_variables
        .iter()
        .filter_map(|(h, g)| Some((h, *request.textures.get(g.name.as_deref()?)?)))
        .collect();

    // 1. Loads and samples -> constants.
    let mut constants = ConstantPool::default();
    let mut fns = std::mem::take(&mut module.functions);
    for (_, f) in fns.iter_mut() {
        replace_reads(&mut module, f, &uniforms, &textures, &mut constants)?;
    }
    module.functions = fns;
    let mut eps = std::mem::take(&mut module.entry_points);
    for ep in eps.iter_mut() {
        replace_reads(
            &mut module,
            &mut ep.function,
            &uniforms,
            &textures,
            &mut constants,
        )?;
    }
    module.entry_points = eps;

    // 2. Overrides -> literals, and the constant `if`s that alone decide pruned.
    let bindings = crate::compile::specialise::Bindings {
        values: request
            .overrides
            .iter()
            .map(|(k, v)| (k.clone(), *v))
            .collect(),
        keep_entry_points: request.keep_entry_points.clone(),
    };
    let module = crate::compile::specialise::specialise(&module, &bindings);

    // 3. Constant evaluation through the function bodies and into helpers,
    // to a fixed point.
    let mut module = module;
    fold_to_fixed_point(&mut module)?;

    // 4. Dead pure calls, and what only dead code used.
    naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
    remove_dead_calls(&mut module);

    // 5. The uniform keeps only the members still read.
    shrink_uniform(&mut module, &request.uniform_var)?;
    naga::compact::compact(&mut module, naga::compact::KeepUnused::No);
    crate::compile::half::declare_f16(&mut module);
    Ok(Folded {
        module,
        kept_in_uniform,
    })
}

/// Rounds of step 3 at most; each round's work is what the previous round
/// made constant, one call level deeper. Today's materials settle in at most
/// 8 (microcylinder: a loop inside a helper inside a helper); past the bound
/// the module is still valid, only less folded.
const MAX_ROUNDS: usize = 16;

/// Step 3, round after round until nothing changes: evaluate constant
/// expressions (`evaluate.rs`), apply identities (`identities.rs`), prune
/// constant `if`s, forward constant locals and resolve loops that run once
/// (`locals.rs`, `loops.rs`), fold calls that return a constant and
/// specialise calls with constant arguments (`call_sites.rs`).
fn fold_to_fixed_point(module: &mut Module) -> Result<(), String> {
    let mut memo = super::call_sites::Memo::new();
    for round in 0..=MAX_ROUNDS {
        let info = crate::compile::compose::validator()
            .validate(module)
            .map_err(|e| {
                let when = if round == 0 {
                    "after folding uniform reads"
                } else {
                    "after specialising helpers"
                };
                format!("{when}: {}", error_chain(e.as_inner()))
            })?;
        evaluate_constants(module, &info);
        let mut changed = simplify_identities(module, &info);
        prune_all(module);
        if round == MAX_ROUNDS {
            break;
        }
        changed += forward_locals(module);
        changed += fold_constant_returns(module);
        changed += specialise_calls(module, &mut memo);
        if changed == 0 {
            break;
        }
        // Calls in removed loops and pruned branches leave results no
        // statement computes: unname them and compact before validating again.
        prune_all(module);
        naga::compact::compact(module, naga::compact::KeepUnused::No);
    }
    Ok(())
}

/// `prune_function` on every function and entry point.
fn prune_all(module: &mut Module) {
    let mut fns = std::mem::take(&mut module.functions);
    for (_, f) in fns.iter_mut() {
        prune_function(module, f);
    }
    module.functions = fns;
    let mut eps = std::mem::take(&mut module.entry_points);
    for ep in eps.iter_mut() {
        prune_function(module, &mut ep.function);
    }
    module.entry_points = eps;
}

fn functions(module: &Module) -> impl Iterator<Item = &naga::Function> {
    module
        .functions
        .iter()
        .map(|(_, f)| f)
        .chain(module.entry_points.iter().map(|ep| &ep.function))
}

/// The chain of constant member/component indices from `h` up to the
/// uniform global, outermost first; None when `h` is not such a chain.
fn access_path(
    exprs: &naga::Arena<Expression>,
    uniform: Handle<naga::GlobalVariable>,
    mut h: Handle<Expression>,
) -> Option<Vec<u32>> {
    let mut path = Vec::new();
    loop {
        match exprs[h] {
            Expression::AccessIndex { base, index } => {
                path.push(index);
                h = base;
            }
            Expression::GlobalVariable(g) if g == uniform => {
                path.reverse();
                return Some(path);
            }
            _ => return None,
        }
    }
}

/// Members reached through anything other than constant indices.
fn unfoldable_members(f: &naga::Function, uniform: Handle<naga::GlobalVariable>) -> BTreeSet<u32> {
    let mut out = BTreeSet::new();
    for (_, e) in f.expressions.iter() {
        match *e {
            // `material.m[i]` with a run-time `i`: member m is data.
            Expression::Access { base, .. } => {
                if let Some(p) = access_path(&f.expressions, uniform, base)
                    && let Some(&m) = p.first()
                {
                    out.insert(m);
                }
            }
            // The whole struct loaded (or passed as a pointer): keep everything.
            Expression::Load { pointer } => {
                if matches!(f.expressions[pointer], Expression::GlobalVariable(g) if g == uniform) {
                    out.insert(u32::MAX);
                }
            }
            _ => {}
        }
    }
    if out.contains(&u32::MAX) {
        out.extend(0..1024);
    }
    out
}

/// Module constants created for folded values, one per (member, component path).
#[derive(Default)]
struct ConstantPool {
    by_path: HashMap<(Handle<naga::GlobalVariable>, Vec<u32>), Handle<Constant>>,
    texels: HashMap<[u32; 4], Handle<Constant>>,
}

fn scalar_literal(v: &ConstValue, component: usize) -> Option<Literal> {
    match v {
        ConstValue::F32(c) => c.get(component).map(|x| Literal::F32(*x)),
        ConstValue::I32(i) if component == 0 => Some(Literal::I32(*i)),
        ConstValue::U32(u) if component == 0 => Some(Literal::U32(*u)),
        _ => None,
    }
}

/// How many scalars a value of type `ty` holds (scalars, vectors and
/// fixed-size arrays of them: what a uniform member folds as).
fn scalar_count(module: &Module, ty: Handle<Type>) -> Result<usize, String> {
    match &module.types[ty].inner {
        TypeInner::Scalar(_) => Ok(1),
        TypeInner::Vector { size, .. } => Ok(*size as usize),
        TypeInner::Array {
            base,
            size: naga::ArraySize::Constant(n),
            ..
        } => Ok(n.get() as usize * scalar_count(module, *base)?),
        inner => Err(format!("cannot fold a uniform member of type {inner:?}")),
    }
}

/// The type reached from `ty` through the constant indices `path`, and the
/// position of its first scalar in the member's flattened value.
fn reached(
    module: &mut Module,
    ty: Handle<Type>,
    path: &[u32],
) -> Result<(Handle<Type>, usize), String> {
    let mut ty = ty;
    let mut first = 0;
    for &i in path {
        match module.types[ty].inner.clone() {
            TypeInner::Vector { scalar, .. } => {
                first += i as usize;
                ty = module.types.insert(
                    Type {
                        name: None,
                        inner: TypeInner::Scalar(scalar),
                    },
                    Span::UNDEFINED,
                );
            }
            TypeInner::Array { base, .. } => {
                first += i as usize * scalar_count(module, base)?;
                ty = base;
            }
            inner => {
                return Err(format!(
                    "cannot index into a uniform member of type {inner:?}"
                ));
            }
        }
    }
    Ok((ty, first))
}

/// A global expression of type `ty` holding the scalars of `v` from `first` on.
fn const_expr(
    module: &mut Module,
    ty: Handle<Type>,
    v: &ConstValue,
    first: usize,
) -> Result<Handle<Expression>, String> {
    let components = match module.types[ty].inner.clone() {
        TypeInner::Scalar(_) => {
            let l = scalar_literal(v, first)
                .ok_or_else(|| format!("value {v:?} has no component {first}"))?;
            return Ok(module
                .global_expressions
                .append(Expression::Literal(l), Span::UNDEFINED));
        }
        TypeInner::Vector { size, scalar } => {
            let scalar_ty = module.types.insert(
                Type {
                    name: None,
                    inner: TypeInner::Scalar(scalar),
                },
                Span::UNDEFINED,
            );
            (0..size as usize)
                .map(|c| const_expr(module, scalar_ty, v, first + c))
                .collect::<Result<Vec<_>, _>>()?
        }
        TypeInner::Array {
            base,
            size: naga::ArraySize::Constant(n),
            ..
        } => {
            let step = scalar_count(module, base)?;
            (0..n.get() as usize)
                .map(|i| const_expr(module, base, v, first + i * step))
                .collect::<Result<Vec<_>, _>>()?
        }
        inner => return Err(format!("cannot fold a uniform member of type {inner:?}")),
    };
    Ok(module
        .global_expressions
        .append(Expression::Compose { ty, components }, Span::UNDEFINED))
}

fn replace_reads(
    module: &mut Module,
    f: &mut naga::Function,
    uniforms: &[FoldedUniform],
    textures: &HashMap<Handle<naga::GlobalVariable>, [f32; 4]>,
    pool: &mut ConstantPool,
) -> Result<(), String> {
    let handles: Vec<Handle<Expression>> = f.expressions.iter().map(|(h, _)| h).collect();
    for h in handles {
        let replacement = match f.expressions[h] {
            Expression::Load { pointer } => {
                let Some((u, path)) = uniforms
                    .iter()
                    .find_map(|u| Some((u, access_path(&f.expressions, u.var, pointer)?)))
                else {
                    continue;
                };
                let Some((&member, rest)) = path.split_first() else {
                    continue;
                };
                let Some(value) = u.folded.get(&member) else {
                    continue;
                };
                let key = (u.var, path.clone());
                if let Some(&c) = pool.by_path.get(&key) {
                    Expression::Constant(c)
                } else {
                    let (ty, first) = reached(module, u.members[member as usize].ty, rest)?;
                    let init = const_expr(module, ty, value, first)?;
                    let c = anonymous_constant(module, ty, init);
                    pool.by_path.insert(key, c);
                    Expression::Constant(c)
                }
            }
            // (A gather returns one channel of four texels: not the texel; leave it.)
            Expression::ImageSample {
                image,
                depth_ref: None,
                gather: None,
                ..
            } => {
                let Expression::GlobalVariable(g) = f.expressions[image] else {
                    continue;
                };
                let Some(texel) = textures.get(&g) else {
                    continue;
                };
                let key = texel.map(f32::to_bits);
                let c = match pool.texels.get(&key) {
                    Some(&c) => c,
                    None => {
                        let ty = module.types.insert(
                            Type {
                                name: None,
                                inner: TypeInner::Vector {
                                    size: naga::VectorSize::Quad,
                                    scalar: naga::Scalar::F32,
                                },
                            },
                            Span::UNDEFINED,
                        );
                        let init = const_expr(module, ty, &ConstValue::F32(texel.to_vec()), 0)?;
                        let c = anonymous_constant(module, ty, init);
                        pool.texels.insert(key, c);
                        c
                    }
                };
                Expression::Constant(c)
            }
            _ => continue,
        };
        f.expressions[h] = replacement;
    }
    let body = std::mem::take(&mut f.body);
    f.body = filter_emits(body, &f.expressions);
    Ok(())
}

/// Rebuilds the material uniform struct with only the members some function
/// still reaches, laid out by WGSL's rules, and renumbers the accesses.
fn shrink_uniform(module: &mut Module, uniform_var: &str) -> Result<(), String> {
    let Some(u) = module.global_variables.iter().find_map(|(h, g)| {
        (g.space == AddressSpace::Uniform && g.name.as_deref() == Some(uniform_var)).then_some(h)
    }) else {
        return Ok(());
    };
    let ty = module.global_variables[u].ty;
    let (name, members) = match &module.types[ty] {
        Type {
            name,
            inner: TypeInner::Struct { members, .. },
        } => (name.clone(), members.clone()),
        _ => return Ok(()),
    };
    let mut used = BTreeSet::new();
    for f in functions(module) {
        for (_, e) in f.expressions.iter() {
            match *e {
                Expression::AccessIndex { base, index } if matches!(f.expressions[base], Expression::GlobalVariable(g) if g == u) =>
                {
                    used.insert(index);
                }
                Expression::Load { pointer } if matches!(f.expressions[pointer], Expression::GlobalVariable(g) if g == u) =>
                {
                    return Ok(()); // the whole struct is read: keep its layout
                }
                _ => {}
            }
        }
    }
    if used.len() == members.len() {
        return Ok(());
    }
    let mut layouter = naga::proc::Layouter::default();
    layouter
        .update(module.to_ctx())
        .map_err(|e| format!("laying out the material uniform: {e}"))?;
    let mut new_members = Vec::new();
    let mut remap = HashMap::new();
    let mut offset = 0u32;
    let mut align = 16u32;
    for (new_i, &old_i) in used.iter().enumerate() {
        let m = &members[old_i as usize];
        let layout = layouter[m.ty];
        let a = layout.alignment.round_up(1);
        offset = offset.div_ceil(a) * a;
        new_members.push(StructMember {
            name: m.name.clone(),
            ty: m.ty,
            binding: None,
            offset,
        });
        offset += layout.size;
        align = align.max(a);
        remap.insert(old_i, new_i as u32);
    }
    let span = offset.div_ceil(align).max(1) * align;
    let new_ty = module.types.insert(
        Type {
            name,
            inner: TypeInner::Struct {
                members: new_members,
                span,
            },
        },
        Span::UNDEFINED,
    );
    module.global_variables[u].ty = new_ty;
    let renumber = |f: &mut naga::Function| {
        let handles: Vec<_> = f.expressions.iter().map(|(h, _)| h).collect();
        for h in handles {
            if let Expression::AccessIndex { base, index } = f.expressions[h]
                && matches!(f.expressions[base], Expression::GlobalVariable(g) if g == u)
            {
                f.expressions[h] = Expression::AccessIndex {
                    base,
                    index: remap[&index],
                };
            }
        }
    };
    for (_, f) in module.functions.iter_mut() {
        renumber(f);
    }
    for ep in module.entry_points.iter_mut() {
        renumber(&mut ep.function);
    }
    Ok(())
}

/// An error and its sources, innermost last (naga nests "entry point invalid" around the cause).
fn error_chain(e: &dyn std::error::Error) -> String {
    let mut out = e.to_string();
    let mut source = e.source();
    while let Some(s) = source {
        out.push_str(": ");
        out.push_str(&s.to_string());
        source = s.source();
    }
    out
}

#[cfg(test)]
pub(super) mod test_support {
    /// `src` (WGSL without a material uniform) folded with nothing to fold
    /// but what the code itself makes constant, emitted as WGSL.
    pub fn folded(src: &str) -> String {
        let module = naga::front::wgsl::parse_str(src).expect("parses");
        let request = super::FoldRequest::default();
        let first = super::fold(&module, &request).expect("folds").module;
        let info = crate::compile::compose::validator()
            .validate(&first)
            .expect("the folded module validates");
        let wgsl = crate::compile::backends::emit_wgsl(&first, &info).expect("emits");
        // Folding is deterministic: a second fold emits the same bytes.
        let second = super::fold(&module, &request).expect("folds").module;
        let info = crate::compile::compose::validator()
            .validate(&second)
            .unwrap();
        assert_eq!(
            crate::compile::backends::emit_wgsl(&second, &info).unwrap(),
            wgsl
        );
        wgsl
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Static lighting: the frame uniform's vector and array-of-vector
    /// members fold (a whole array loaded, one element, one component),
    /// members not asked for stay reads, and the frame keeps its layout.
    #[test]
    fn frame_members_fold_and_the_frame_keeps_its_layout() {
        let src = "
            struct Frame { view: vec4<f32>, light_direction: vec4<f32>, sh: array<vec4<f32>, 2> }
            @group(0) @binding(0) var<uniform> weft_frame: Frame;
            @fragment fn fs_main() -> @location(0) vec4<f32> {
                let sh = weft_frame.sh;
                let a = sh[0].xyz + weft_frame.sh[1].xyz * weft_frame.sh[1].w;
                return vec4<f32>(a * weft_frame.light_direction.y, weft_frame.view.x);
            }";
        let module = naga::front::wgsl::parse_str(src).unwrap();
        let request = FoldRequest {
            frame_members: BTreeMap::from([
                (
                    "light_direction".into(),
                    ConstValue::F32(vec![0.0, 0.5, 0.0, 0.0]),
                ),
                (
                    "sh".into(),
                    ConstValue::F32(vec![1.0, 2.0, 3.0, 0.0, 4.0, 5.0, 6.0, 0.25]),
                ),
            ]),
            ..Default::default()
        };
        let folded = fold(&module, &request).unwrap().module;
        let info = crate::compile::compose::validator()
            .validate(&folded)
            .unwrap();
        let wgsl = crate::compile::backends::emit_wgsl(&folded, &info).unwrap();
        assert!(!wgsl.contains("weft_frame.sh"), "{wgsl}");
        assert!(!wgsl.contains("weft_frame.light_direction"), "{wgsl}");
        assert!(wgsl.contains("weft_frame.view"), "{wgsl}");
        // (1, 2, 3) + (4, 5, 6) × 0.25, times 0.5, all evaluated at build time.
        assert!(wgsl.contains("vec3<f32>(1f, 1.625f, 2.25f)"), "{wgsl}");
        let frame = folded
            .global_variables
            .iter()
            .find(|(_, g)| g.name.as_deref() == Some(FRAME_VAR))
            .map(|(_, g)| &folded.types[g.ty].inner);
        assert!(
            matches!(frame, Some(TypeInner::Struct { members, span: 64 }) if members.len() == 3),
            "{frame:?}"
        );
    }
}
