//! Reflection: what a specialised module actually contains — entry points,
//! the bindings that survived dead-branch removal, the material uniform's
//! layout as naga's layouter computes it, and vertex inputs.

use crate::compile::engine_binding;
use crate::compile::engine_binding::{HLSL_SAMPLER_INDEX_REGISTER, hlsl_options};
use crate::compile::prelude::{MATERIAL_GROUP, MATERIAL_UNIFORM_BINDING, UNIFORM_STRUCT};
use naga::valid::ModuleInfo;
use naga::{AddressSpace, ImageClass, ImageDimension, Module, ShaderStage, TypeInner};
use weft_meta::{
    Binding, BindingKind, BufferBinding, BufferBindingType, EntryPoint, HlslBinding,
    MemberEncoding, Stage, TextureBinding, TextureDefault, TextureSampleType, TextureViewDimension,
    UniformLayout, UniformMember, UniformType, uniform::ScalarType,
};

/// A group-1 texture binding of the variant: the parameter it carries, the
/// format its data comes in and the built-in default the variant binds.
pub struct MaterialTexture {
    /// The parameter, or for a baked table (`table`) its name.
    pub param: String,
    /// Set for a baked table: what the binding carries (no parameter).
    pub table: Option<weft_meta::EngineResource>,
    pub binding: u32,
    pub format: String,
    /// None for gradient ramps (their default is the baked ramp).
    pub default: Option<TextureDefault>,
    /// The parameter's image (`file`), bound while it is unset.
    pub file: Option<weft_meta::ResourceFile>,
}

/// What the material's uniform members hold: member name -> (parameter, encoding).
pub type MemberParams = std::collections::BTreeMap<String, (String, MemberEncoding)>;

/// The encoding of each generated uniform member of `m`.
pub fn member_params(m: &weft_front::Material) -> MemberParams {
    crate::compile::prelude::uniform_members(m)
        .into_iter()
        .filter_map(|mem| {
            let p = m.param(&mem.param)?;
            let encoding = if mem.name != p.name {
                MemberEncoding::TilingOffset
            } else {
                p.kind.encoding()?
            };
            Some((mem.name, (mem.param, encoding)))
        })
        .collect()
}

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

/// Every resource binding, sorted by (group, binding), with the stages that
/// use it and its layout entry in full.
pub fn bindings(
    module: &Module,
    info: &ModuleInfo,
    textures: &[MaterialTexture],
    members: &MemberParams,
) -> Vec<Binding> {
    let hlsl = hlsl_options(module);
    let msl = engine_binding::msl_slots(module);
    let mut out = Vec::new();
    for (handle, var) in module.global_variables.iter() {
        let Some(rb) = &var.binding else { continue };
        let inner = &module.types[var.ty].inner;
        let kind = binding_kind(inner, var.space);
        let stages = binding_stages(module, info, handle);
        let hlsl_binding = hlsl_binding(kind, rb, &hlsl.binding_map[rb]);
        let name = var.name.clone().unwrap_or_default();
        let material_texture = (rb.group == MATERIAL_GROUP)
            .then(|| textures.iter().find(|t| t.binding == rb.binding))
            .flatten();
        let buffer = buffer_binding(module, var, rb, members);
        let texture = texture_binding(inner, material_texture, &name);
        let sampler = match inner {
            TypeInner::Sampler { comparison } => {
                Some(engine_binding::sampler(rb.group, rb.binding, *comparison))
            }
            _ => None,
        };
        let table = material_texture.and_then(|t| t.table.clone());
        let resource = (rb.group != MATERIAL_GROUP)
            .then(|| engine_binding::engine_resource(&name))
            .flatten()
            .or(table.clone());
        out.push(Binding {
            group: rb.group,
            binding: rb.binding,
            parameter: material_texture
                .filter(|t| t.table.is_none())
                .map(|t| t.param.clone()),
            name,
            kind,
            stages,
            hlsl: hlsl_binding,
            msl: msl.get(rb).copied(),
            buffer,
            texture,
            sampler,
            resource,
        });
    }
    out.sort_by_key(|b| (b.group, b.binding));
    out
}

/// What a global holds, from its type and address space.
fn binding_kind(inner: &TypeInner, space: AddressSpace) -> BindingKind {
    match (inner, space) {
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
    }
}

/// The stages whose entry points use the global, in entry point order.
fn binding_stages(
    module: &Module,
    info: &ModuleInfo,
    handle: naga::Handle<naga::GlobalVariable>,
) -> Vec<Stage> {
    let mut stages = Vec::new();
    for (i, ep) in module.entry_points.iter().enumerate() {
        if !info.get_entry_point(i)[handle].is_empty() && !stages.contains(&stage(ep.stage)) {
            stages.push(stage(ep.stage));
        }
    }
    stages
}

/// Where the binding lives in the HLSL output: samplers by their slot in the
/// group's sampler-index buffer, the rest at naga's register.
fn hlsl_binding(
    kind: BindingKind,
    rb: &naga::ResourceBinding,
    target: &naga::back::hlsl::BindTarget,
) -> HlslBinding {
    match kind {
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
    }
}

/// A uniform or storage buffer's layout entry and struct layout (material
/// members with their parameters, engine members with what to write).
fn buffer_binding(
    module: &Module,
    var: &naga::GlobalVariable,
    rb: &naga::ResourceBinding,
    members: &MemberParams,
) -> Option<BufferBinding> {
    match var.space {
        AddressSpace::Uniform | AddressSpace::Storage { .. } => {
            let layout = if rb.group == MATERIAL_GROUP {
                struct_layout(module, var.ty, |member| {
                    members
                        .get(member)
                        .map(|(p, e)| (Some(p.clone()), Some(*e), None))
                })
            } else {
                struct_layout(module, var.ty, |member| {
                    let s = module.types[var.ty].name.as_deref().unwrap_or_default();
                    engine_binding::member_description(s, member)
                        .map(|d| (None, None, Some(d.to_string())))
                })
            };
            layout.map(|layout| BufferBinding {
                ty: match var.space {
                    AddressSpace::Uniform => BufferBindingType::Uniform,
                    AddressSpace::Storage { access }
                        if !access.contains(naga::StorageAccess::STORE) =>
                    {
                        BufferBindingType::ReadOnlyStorage
                    }
                    _ => BufferBindingType::Storage,
                },
                has_dynamic_offset: false,
                min_binding_size: u64::from(layout.size),
                layout,
            })
        }
        _ => None,
    }
}

/// A texture's layout entry, its format (the material texture's, or the
/// engine resource's) and the material texture's default and file.
fn texture_binding(
    inner: &TypeInner,
    material_texture: Option<&MaterialTexture>,
    name: &str,
) -> Option<TextureBinding> {
    match inner {
        TypeInner::Image {
            dim,
            arrayed,
            class,
        } => Some(TextureBinding {
            sample_type: match class {
                ImageClass::Depth { .. } => TextureSampleType::Depth,
                ImageClass::Sampled {
                    kind: naga::ScalarKind::Sint,
                    ..
                } => TextureSampleType::Sint,
                ImageClass::Sampled {
                    kind: naga::ScalarKind::Uint,
                    ..
                } => TextureSampleType::Uint,
                _ => TextureSampleType::Float,
            },
            view_dimension: match (dim, arrayed) {
                (ImageDimension::D1, _) => TextureViewDimension::D1,
                (ImageDimension::D2, false) => TextureViewDimension::D2,
                (ImageDimension::D2, true) => TextureViewDimension::D2Array,
                (ImageDimension::Cube, false) => TextureViewDimension::Cube,
                (ImageDimension::Cube, true) => TextureViewDimension::CubeArray,
                (ImageDimension::D3, _) => TextureViewDimension::D3,
            },
            multisampled: matches!(
                class,
                ImageClass::Sampled { multi: true, .. } | ImageClass::Depth { multi: true }
            ),
            format: match (material_texture, name) {
                (Some(t), _) => t.format.clone(),
                (None, "weft_environment") => engine_binding::ENVIRONMENT_FORMAT.into(),
                (None, n) => engine_binding::engine_resource(n)
                    .and_then(|r| r.file)
                    .map(|f| f.format)
                    .unwrap_or_default(),
            },
            default: material_texture.and_then(|t| t.default),
            file: material_texture.and_then(|t| t.file.clone()),
        }),
        _ => None,
    }
}

/// WGSL spelling of a type, for diagnostics.
pub fn type_name(module: &Module, ty: naga::Handle<naga::Type>) -> String {
    match member_type(module, ty) {
        Some(t) => t.to_string(),
        None => format!("{:?}", module.types[ty].inner),
    }
}

/// A buffer member's type, for metadata (None for what no buffer member
/// can be: images, samplers, pointers, unnamed structs, 64-bit scalars).
pub fn member_type(module: &Module, ty: naga::Handle<naga::Type>) -> Option<UniformType> {
    let t = &module.types[ty];
    if let Some(name) = &t.name {
        return Some(UniformType::Struct(name.clone()));
    }
    Some(match &t.inner {
        TypeInner::Scalar(s) => UniformType::Scalar(scalar_type(*s)?),
        TypeInner::Vector { size, scalar } => UniformType::Vector {
            size: *size as u8,
            scalar: scalar_type(*scalar)?,
        },
        TypeInner::Matrix {
            columns,
            rows,
            scalar,
        } => UniformType::Matrix {
            columns: *columns as u8,
            rows: *rows as u8,
            scalar: scalar_type(*scalar)?,
        },
        TypeInner::Array { base, size, .. } => UniformType::Array {
            element: Box::new(member_type(module, *base)?),
            count: match size {
                naga::ArraySize::Constant(n) => Some(n.get()),
                _ => None,
            },
        },
        TypeInner::Atomic(s) => UniformType::Atomic(scalar_type(*s)?),
        _ => return None,
    })
}

fn scalar_type(s: naga::Scalar) -> Option<ScalarType> {
    Some(match (s.kind, s.width) {
        (naga::ScalarKind::Float, 4) => ScalarType::F32,
        (naga::ScalarKind::Float, 2) => ScalarType::F16,
        (naga::ScalarKind::Sint, 4) => ScalarType::I32,
        (naga::ScalarKind::Uint, 4) => ScalarType::U32,
        (naga::ScalarKind::Bool, _) => ScalarType::Bool,
        _ => return None,
    })
}

/// Layout of the group-1 uniform block, if the variant still has it.
pub fn material_uniform(module: &Module, members: &MemberParams) -> Option<UniformLayout> {
    let var = module.global_variables.iter().find(|(_, v)| {
        v.binding
            .as_ref()
            .is_some_and(|b| b.group == MATERIAL_GROUP && b.binding == MATERIAL_UNIFORM_BINDING)
    })?;
    struct_layout(module, var.1.ty, |member| {
        members
            .get(member)
            .map(|(p, e)| (Some(p.clone()), Some(*e), None))
    })
}

/// What a member holds: (parameter, encoding, description).
type MemberNotes = (Option<String>, Option<MemberEncoding>, Option<String>);

/// Layout of any struct type, by naga's layouter; `notes` annotates members by name.
pub fn struct_layout(
    module: &Module,
    ty: naga::Handle<naga::Type>,
    notes: impl Fn(&str) -> Option<MemberNotes>,
) -> Option<UniformLayout> {
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
            .map(|m| {
                let name = m.name.clone().unwrap_or_default();
                let (parameter, encoding, description) = notes(&name).unwrap_or_default();
                UniformMember {
                    // Every type a WGSL struct member can have is one
                    // (`member_type`); a struct without a name cannot be
                    // declared in WGSL.
                    ty: member_type(module, m.ty)
                        .unwrap_or_else(|| UniformType::Struct(type_name(module, m.ty))),
                    offset: m.offset,
                    size: layouter[m.ty].size,
                    align: layouter[m.ty].alignment.round_up(1),
                    parameter,
                    encoding,
                    description,
                    name,
                }
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
    prelude: &crate::compile::prelude::Prelude,
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
    let members = crate::compile::prelude::uniform_members(m);
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
