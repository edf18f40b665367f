//! Reflection: what a specialised module actually contains — entry points,
//! the bindings that survived dead-branch removal, the material uniform's
//! layout as naga's layouter computes it, and vertex inputs.

use crate::backends::{HLSL_SAMPLER_INDEX_REGISTER, hlsl_options};
use crate::prelude::{MATERIAL_GROUP, MATERIAL_UNIFORM_BINDING, UNIFORM_STRUCT};
use naga::valid::ModuleInfo;
use naga::{AddressSpace, ImageClass, ImageDimension, Module, ShaderStage, TypeInner};
use weft_meta::{
    Binding, BindingKind, EntryPoint, HlslBinding, Stage, UniformLayout, UniformMember,
};

pub fn stage(s: ShaderStage) -> Stage {
    match s {
        ShaderStage::Vertex => Stage::Vertex,
        ShaderStage::Fragment => Stage::Fragment,
        _ => Stage::Compute,
    }
}

pub fn entry_points(module: &Module) -> Vec<EntryPoint> {
    module
        .entry_points
        .iter()
        .map(|ep| EntryPoint {
            name: ep.name.clone(),
            stage: stage(ep.stage),
        })
        .collect()
}

/// Every resource binding, sorted by (group, binding), with the stages that use it.
pub fn bindings(
    module: &Module,
    info: &ModuleInfo,
    texture_params: &[(String, u32)],
) -> Vec<Binding> {
    let hlsl = hlsl_options(module);
    let mut out = Vec::new();
    for (handle, var) in module.global_variables.iter() {
        let Some(rb) = &var.binding else { continue };
        let kind = match (&module.types[var.ty].inner, var.space) {
            (TypeInner::Sampler { comparison: false }, _) => BindingKind::Sampler,
            (TypeInner::Sampler { comparison: true }, _) => BindingKind::ComparisonSampler,
            (
                TypeInner::Image {
                    dim,
                    arrayed,
                    class,
                },
                _,
            ) => match (dim, arrayed, class) {
                (_, _, ImageClass::Depth { .. }) => BindingKind::DepthTexture2d,
                (ImageDimension::Cube, _, _) => BindingKind::TextureCube,
                (ImageDimension::D3, _, _) => BindingKind::Texture3d,
                (ImageDimension::D2, true, _) => BindingKind::Texture2dArray,
                _ => BindingKind::Texture2d,
            },
            (_, AddressSpace::Uniform) => BindingKind::UniformBuffer,
            _ => BindingKind::StorageBuffer,
        };
        let mut stages = Vec::new();
        for (i, ep) in module.entry_points.iter().enumerate() {
            if !info.get_entry_point(i)[handle].is_empty() && !stages.contains(&stage(ep.stage)) {
                stages.push(stage(ep.stage));
            }
        }
        let target = &hlsl.binding_map[rb];
        let hlsl_binding = match kind {
            BindingKind::Sampler | BindingKind::ComparisonSampler => HlslBinding {
                register: format!("t{HLSL_SAMPLER_INDEX_REGISTER}"),
                space: rb.group,
                sampler_index_slot: Some(rb.binding),
            },
            BindingKind::UniformBuffer => HlslBinding {
                register: format!("b{}", target.register),
                space: target.space as u32,
                sampler_index_slot: None,
            },
            _ => HlslBinding {
                register: format!("t{}", target.register),
                space: target.space as u32,
                sampler_index_slot: None,
            },
        };
        let name = var.name.clone().unwrap_or_default();
        let parameter = (rb.group == MATERIAL_GROUP)
            .then(|| {
                texture_params
                    .iter()
                    .find(|(_, b)| *b == rb.binding)
                    .map(|(p, _)| p.clone())
            })
            .flatten();
        out.push(Binding {
            group: rb.group,
            binding: rb.binding,
            name,
            kind,
            parameter,
            stages,
            hlsl: hlsl_binding,
        });
    }
    out.sort_by_key(|b| (b.group, b.binding));
    out
}

/// WGSL spelling of a type, for metadata.
pub fn type_name(module: &Module, ty: naga::Handle<naga::Type>) -> String {
    let t = &module.types[ty];
    if let Some(name) = &t.name {
        return name.clone();
    }
    scalar_or_compound(module, &t.inner)
}

fn scalar_name(s: naga::Scalar) -> String {
    match (s.kind, s.width) {
        (naga::ScalarKind::Float, 4) => "f32".into(),
        (naga::ScalarKind::Float, 2) => "f16".into(),
        (naga::ScalarKind::Sint, 4) => "i32".into(),
        (naga::ScalarKind::Uint, 4) => "u32".into(),
        (naga::ScalarKind::Bool, _) => "bool".into(),
        (k, w) => format!("{k:?}{}", w * 8).to_lowercase(),
    }
}

fn scalar_or_compound(module: &Module, inner: &TypeInner) -> String {
    match inner {
        TypeInner::Scalar(s) => scalar_name(*s),
        TypeInner::Vector { size, scalar } => {
            format!("vec{}<{}>", *size as u8, scalar_name(*scalar))
        }
        TypeInner::Matrix {
            columns,
            rows,
            scalar,
        } => format!(
            "mat{}x{}<{}>",
            *columns as u8,
            *rows as u8,
            scalar_name(*scalar)
        ),
        TypeInner::Array { base, size, .. } => match size {
            naga::ArraySize::Constant(n) => format!("array<{}, {n}>", type_name(module, *base)),
            _ => format!("array<{}>", type_name(module, *base)),
        },
        other => format!("{other:?}"),
    }
}

/// Layout of the group-1 uniform block, if the variant still has it.
pub fn material_uniform(module: &Module) -> Option<UniformLayout> {
    let var = module.global_variables.iter().find(|(_, v)| {
        v.binding
            .as_ref()
            .is_some_and(|b| b.group == MATERIAL_GROUP && b.binding == MATERIAL_UNIFORM_BINDING)
    })?;
    struct_layout(module, var.1.ty)
}

/// Layout of any struct type, by naga's layouter.
pub fn struct_layout(module: &Module, ty: naga::Handle<naga::Type>) -> Option<UniformLayout> {
    let TypeInner::Struct { members, span } = &module.types[ty].inner else {
        return None;
    };
    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).ok()?;
    Some(UniformLayout {
        struct_name: module.types[ty]
            .name
            .clone()
            .unwrap_or_else(|| UNIFORM_STRUCT.into()),
        size: *span,
        align: layouter[ty].alignment.round_up(1),
        members: members
            .iter()
            .map(|m| UniformMember {
                name: m.name.clone().unwrap_or_default(),
                ty: type_name(module, m.ty),
                offset: m.offset,
                size: layouter[m.ty].size,
                align: layouter[m.ty].alignment.round_up(1),
            })
            .collect(),
    })
}

/// Shader locations the vertex entry points read.
pub fn vertex_locations(module: &Module) -> Vec<u32> {
    let mut out = Vec::new();
    for ep in module
        .entry_points
        .iter()
        .filter(|e| e.stage == ShaderStage::Vertex)
    {
        for arg in &ep.function.arguments {
            let mut push = |b: &Option<naga::Binding>| {
                if let Some(naga::Binding::Location { location, .. }) = b
                    && !out.contains(location)
                {
                    out.push(*location);
                }
            };
            push(&arg.binding);
            if let TypeInner::Struct { members, .. } = &module.types[arg.ty].inner {
                for m in members {
                    push(&m.binding);
                }
            }
        }
    }
    out.sort();
    out
}

/// Parameters the module still reads, in declaration order: uniform members
/// reached from any function (a texture's `_st` member counts for the
/// texture) and material textures still bound.
pub fn reads(
    m: &weft_front::Material,
    module: &Module,
    prelude: &crate::prelude::Prelude,
) -> Vec<String> {
    let uniform = module.global_variables.iter().find_map(|(h, v)| {
        v.binding
            .as_ref()
            .is_some_and(|b| b.group == MATERIAL_GROUP && b.binding == MATERIAL_UNIFORM_BINDING)
            .then_some(h)
    });
    let mut member_names = std::collections::BTreeSet::new();
    if let Some(u) = uniform
        && let TypeInner::Struct { members, .. } =
            &module.types[module.global_variables[u].ty].inner
    {
        let functions = module
            .functions
            .iter()
            .map(|(_, f)| f)
            .chain(module.entry_points.iter().map(|ep| &ep.function));
        for f in functions {
            for (_, e) in f.expressions.iter() {
                if let naga::Expression::AccessIndex { base, index } = *e
                    && matches!(f.expressions[base], naga::Expression::GlobalVariable(g) if g == u)
                    && let Some(name) = members.get(index as usize).and_then(|m| m.name.clone())
                {
                    member_names.insert(name);
                }
            }
        }
    }
    let bound: std::collections::BTreeSet<u32> = module
        .global_variables
        .iter()
        .filter_map(|(_, v)| v.binding.as_ref())
        .filter(|b| b.group == MATERIAL_GROUP)
        .map(|b| b.binding)
        .collect();
    let members = crate::prelude::uniform_members(m);
    m.params
        .iter()
        .filter(|p| {
            members
                .iter()
                .any(|mem| mem.param == p.name && member_names.contains(&mem.name))
                || prelude
                    .texture_bindings
                    .iter()
                    .any(|(name, b)| *name == p.name && bound.contains(b))
        })
        .map(|p| p.name.clone())
        .collect()
}
