//! The binding details an engine needs beyond what naga's reflection says:
//! the sampler objects weft's code expects, the texture formats of the data,
//! which engine data each group-0/group-2 binding carries (with the baked
//! LUT files' layout), what each frame/object uniform member holds, and the
//! coordinate conventions of every emitted language.
//!
//! This is the one place that describes `wgsl/engine_interface.wgsl` and the
//! prelude's group-1 samplers to engines; `reflect.rs` attaches it to the
//! bindings a variant keeps.

use crate::compile::prelude::{
    MATERIAL_CLAMP_SAMPLER_BINDING, MATERIAL_GROUP, MATERIAL_SAMPLER_BINDING,
};
use naga::Module;
use naga::back::hlsl;
use std::collections::BTreeMap;
use weft_meta::{
    AddressMode, ClipSpaceY, ConstantKeywords, DepthRange, EngineResource, FilterMode, FrontFace,
    LanguageConventions, ResourceFile, SamplerBinding, SamplerBindingType,
};

use weft_meta::engine::{self as ids, ENGINE_BINDINGS};
pub use weft_meta::engine::{FRAME_GROUP, OBJECT_GROUP};

pub const ENGINE_INTERFACE: &str = include_str!("wgsl/engine_interface.wgsl");

/// The frame uniform's variable in `engine_interface.wgsl` (group 0,
/// binding 0), whose light and SH members a scene with static lighting folds.
pub const FRAME_VAR: &str = "weft_frame";

/// The engine-feature overrides of `engine_interface.wgsl` and the values a
/// library (scene-independent) variant is built with: everything provided.
/// Scene builds fix them to what the scene provides (`scene::features`).
pub const FEATURE_ENVIRONMENT: &str = "WEFT_ENVIRONMENT";
pub const FEATURE_SH_AMBIENT: &str = "WEFT_SH_AMBIENT";
pub const FEATURE_DIRECTIONAL_LIGHTS: &str = "WEFT_DIRECTIONAL_LIGHTS";
pub const FEATURE_DEFAULTS: [(&str, naga::Literal); 3] = [
    (FEATURE_ENVIRONMENT, naga::Literal::Bool(true)),
    (FEATURE_SH_AMBIENT, naga::Literal::Bool(true)),
    (FEATURE_DIRECTIONAL_LIGHTS, naga::Literal::U32(1)),
];

/// Size and sample count of the baked split-sum LUT.
pub const SPLIT_SUM_LUT_SIZE: u32 = 64;

pub const SPLIT_SUM_LUT_SAMPLES: u32 = 1024;

/// Size and sample count are in the name, so a reused file is never a stale bake.
pub const SPLIT_SUM_LUT_PATH: &str = "luts/split_sum_ggx_64x64_1024spp.rg16f";

/// Size and quadrature of the baked Charlie sheen albedo table (bake/sheen.rs):
/// `SHEEN_LUT_SIZE`^2 texels, `THETA_STEPS * PHI_STEPS` = 8192 points each.
pub const SHEEN_LUT_SIZE: u32 = 32;

pub const SHEEN_LUT_PATH: &str = "luts/charlie_albedo_32x32_8192spp.r16f";

const _: () = assert!(
    SHEEN_LUT_SIZE == 32 && crate::bake::sheen::THETA_STEPS * crate::bake::sheen::PHI_STEPS == 8192,
    "SHEEN_LUT_PATH must name the table's size and quadrature"
);

/// HLSL: samplers live in naga's sampler heap (`nagaSamplerHeap`) at this space…
pub const HLSL_SAMPLER_HEAP_SPACE: u8 = 8;
pub const HLSL_COMPARISON_SAMPLER_HEAP_SPACE: u8 = 9;
/// …and each group's sampler-index buffer is `t<this>` in the group's space.
pub const HLSL_SAMPLER_INDEX_REGISTER: u32 = 64;

/// The format of the prefiltered environment cube `weft-render` binds.
pub const ENVIRONMENT_FORMAT: &str = "rgba16float";

/// The sampler object a sampler binding expects: every weft sampler filters
/// linearly (trilinear where there are mips); they differ in addressing.
pub fn sampler(group: u32, binding: u32, comparison: bool) -> SamplerBinding {
    let repeat = group == MATERIAL_GROUP && binding == MATERIAL_SAMPLER_BINDING;
    let address = if repeat {
        AddressMode::Repeat
    } else {
        AddressMode::ClampToEdge
    };
    SamplerBinding {
        binding_type: if comparison {
            SamplerBindingType::Comparison
        } else {
            SamplerBindingType::Filtering
        },
        mag_filter: FilterMode::Linear,
        min_filter: FilterMode::Linear,
        mipmap_filter: FilterMode::Linear,
        address_mode_u: address,
        address_mode_v: address,
        address_mode_w: address,
        lod_min_clamp: 0.0,
        lod_max_clamp: 32.0,
        anisotropy_clamp: 1,
        compare: None,
    }
}

/// Material samplers are in the prelude; keep the two constants in view here.
const _: () = assert!(MATERIAL_SAMPLER_BINDING == 1 && MATERIAL_CLAMP_SAMPLER_BINDING == 2);

fn resource(id: &str, description: &str, file: Option<ResourceFile>) -> EngineResource {
    EngineResource {
        id: id.into(),
        description: description.into(),
        file,
    }
}

/// Which engine data a group-0 or group-2 binding carries, by the WGSL name.
pub fn engine_resource(name: &str) -> Option<EngineResource> {
    Some(match name {
        "weft_frame" => resource(
            ids::FRAME,
            "Per-frame constants: camera, main light, SH ambient, environment mip count, \
             exposure and time (the members' descriptions say what to write). Update once a frame.",
            None,
        ),
        "weft_object" => resource(
            ids::OBJECT,
            "Per-object transforms (the members' descriptions say what to write).",
            None,
        ),
        "weft_environment" => resource(
            ids::ENVIRONMENT,
            "The engine's environment as a GGX-prefiltered radiance cube (linear HDR, any \
             filterable float format; weft-render uses rgba16float), standard cube face order \
             (+x, −x, +y, −y, +z, −z) with WebGPU/Vulkan face orientation. Mip m holds radiance \
             prefiltered at perceptual roughness r with r (1.7 − 0.7 r) (mip_count − 1) = m; \
             mip_count goes in weft_frame.params.x.",
            None,
        ),
        "weft_environment_sampler" => resource(
            ids::ENVIRONMENT_SAMPLER,
            "Trilinear, clamp to edge (the sampler entry states it in full).",
            None,
        ),
        "weft_brdf_lut" => resource(
            ids::SPLIT_SUM_LUT,
            "Split-sum environment BRDF (scale, bias) for GGX with Smith height-correlated \
             visibility: specular = prefiltered × (F0 × scale + bias). Bind the file's texels.",
            Some(ResourceFile {
                path: SPLIT_SUM_LUT_PATH.into(),
                format: "rg16float".into(),
                width: SPLIT_SUM_LUT_SIZE,
                height: SPLIT_SUM_LUT_SIZE,
                layout: "width × height texels, rows in order (row 0 first), texels in a row \
                         left to right; each texel two little-endian IEEE half floats (r, g); \
                         no header, no padding"
                    .into(),
                u: "N·V, 0 at the left edge, 1 at the right; sampled at texel centres".into(),
                v: "perceptual roughness, 0 at row 0, 1 at the last row; sampled at texel centres"
                    .into(),
                channels: "r: scale, g: bias".into(),
                sha256: None,
                mip_chain: None,
            }),
        ),
        "weft_lut_sampler" => resource(
            ids::LUT_SAMPLER,
            "Bilinear, clamp to edge (the sampler entry states it in full).",
            None,
        ),
        "weft_sheen_lut" => resource(
            ids::SHEEN_ALBEDO_LUT,
            "Directional albedo E of the Charlie sheen BRDF with sheen colour 1 (velvet's energy \
             compensation). Bind the file's texels.",
            Some(ResourceFile {
                path: SHEEN_LUT_PATH.into(),
                format: "r16float".into(),
                width: SHEEN_LUT_SIZE,
                height: SHEEN_LUT_SIZE,
                layout: "width × height texels, rows in order (row 0 first), texels in a row \
                         left to right; each texel one little-endian IEEE half float; no \
                         header, no padding"
                    .into(),
                u: "N·V, 0 at the left edge, 1 at the right; sampled at texel centres".into(),
                v: "Charlie sheen roughness (clamped to ≥ 0.07 by the shader), 0 at row 0, 1 at \
                    the last row; sampled at texel centres"
                    .into(),
                channels: "r: E".into(),
                sha256: None,
                mip_chain: None,
            }),
        ),
        _ => return None,
    })
}

/// What to write into a member of `WeftFrame` or `WeftObject`.
pub fn member_description(struct_name: &str, member: &str) -> Option<&'static str> {
    Some(match (struct_name, member) {
        ("WeftFrame", "view_proj") => {
            "World → clip (projection × view), column-major, for WebGPU clip space (y up, z in \
             [0, w]); the same matrix serves every language (each file adjusts its own clip space)"
        }
        ("WeftFrame", "view") => "World → view (rotation and translation), column-major",
        ("WeftFrame", "camera_position") => "xyz: camera position in world space; w: unused",
        ("WeftFrame", "light_direction") => {
            "xyz: unit vector from the surface towards the main directional light; w: unused"
        }
        ("WeftFrame", "light_color") => "rgb: the main light's linear radiance; a: unused",
        ("WeftFrame", "sh") => {
            "L2 spherical-harmonic irradiance, rgb in xyz (w unused): Σ c_i Y_i(n) = E(n)/π, \
             orthonormal real basis in the order Y00, Y1−1 (y), Y10 (z), Y11 (x), Y2−2 (xy), \
             Y2−1 (yz), Y20 (3z²−1), Y21 (xz), Y22 (x²−y²)"
        }
        ("WeftFrame", "params") => {
            "x: mip count of weft_environment; y: exposure (informational: shaders do not apply \
             it, the engine does after the passes); z: time in seconds; w: unused"
        }
        ("WeftFrame", "viewport") => {
            "xy: width and height of the colour target in pixels; zw: their reciprocals \
             (engine interface 2; pixel-sized effects such as outlines read it)"
        }
        ("WeftObject", "model") => "Object → world, column-major",
        ("WeftObject", "normal_matrix") => {
            "Inverse transpose of the model's upper 3×3, in the upper 3×3 of a column-major \
             mat4 (the rest identity)"
        }
        _ => return None,
    })
}

/// The conventions of every emitted language (backends.rs sets the options
/// these follow from; tests/contract/conventions.rs draws them).
pub fn languages() -> BTreeMap<String, LanguageConventions> {
    let entry = |y, depth, front_face, constants, notes: &str| LanguageConventions {
        clip_space_y: y,
        depth_range: depth,
        front_face,
        top_row_first: true,
        constant_keywords: constants,
        notes: notes.into(),
    };
    use ClipSpaceY::{Down, Up};
    use ConstantKeywords::{FilePerValue, PipelineConstants};
    use DepthRange::{MinusOneToOne, ZeroToOne};
    BTreeMap::from([
        (
            "wgsl".into(),
            entry(
                Up,
                ZeroToOne,
                FrontFace::Ccw,
                PipelineConstants,
                "WebGPU (wgpu, Dawn, browsers). Bind as the bindings say; `constant`-mode keywords \
                 are the pipeline constants.",
            ),
        ),
        (
            "spirv".into(),
            entry(
                Down,
                ZeroToOne,
                FrontFace::Ccw,
                FilePerValue,
                "Vulkan 1.0, SPIR-V 1.0: descriptor set = group, binding = binding. The vertex \
                 stage negates clip-space y, so with a positive viewport height the picture \
                 is upright and counter-clockwise faces are front faces, as in WGSL. Through a \
                 layer that itself maps WebGPU's y-up clip space to Vulkan with a negative \
                 viewport height (wgpu's passthrough shaders), y is flipped twice: set front \
                 face clockwise and read the rows bottom to top.",
            ),
        ),
        (
            "hlsl".into(),
            entry(
                Up,
                ZeroToOne,
                FrontFace::Ccw,
                FilePerValue,
                "Shader model 5.1 (D3D12): registers and spaces as `bindings[].hlsl` says \
                 (docs/hlsl-registers.md); samplers through naga's sampler heap. Set \
                 FrontCounterClockwise = TRUE.",
            ),
        ),
        (
            "msl".into(),
            entry(
                Up,
                ZeroToOne,
                FrontFace::Ccw,
                FilePerValue,
                "Metal Shading Language 2.1. Each binding's `msl` gives its argument table \
                 and index (the same in both stages); resource buffers take the lowest \
                 buffer indices, so put vertex buffers at index 16 and above \
                 (MTLVertexDescriptor; attributes at the vertex input locations). Set \
                 MTLWindingCounterClockwise.",
            ),
        ),
        (
            "glsl".into(),
            entry(
                Down,
                MinusOneToOne,
                FrontFace::Cw,
                FilePerValue,
                "GLSL 4.50 core, one file per stage. The vertex stage writes \
                 gl_Position.yz = (−y, 2z − w): with GL's default clip control the picture's \
                 top lands in row 0 of the target (as in every other language) and, because y \
                 is mirrored in GL's y-up window coordinates, glFrontFace(GL_CW) keeps the \
                 faces WGSL calls front. Uniform blocks and combined samplers carry \
                 `layout(binding = N)`; `files.glsl[].glsl` maps each to its WGSL binding.",
            ),
        ),
    ])
}

/// The GL binding points of one variant: uniform blocks and textures are
/// numbered densely, each in (group, binding) order, so they fit GL ES 3.1's
/// minimum limits. The same numbering serves every stage's file.
pub fn glsl_binding_points(module: &naga::Module) -> BTreeMap<naga::ResourceBinding, u8> {
    let mut blocks = Vec::new();
    let mut textures = Vec::new();
    for (_, var) in module.global_variables.iter() {
        let Some(rb) = var.binding else { continue };
        match (&module.types[var.ty].inner, var.space) {
            (naga::TypeInner::Image { .. }, _) => textures.push(rb),
            (_, naga::AddressSpace::Uniform | naga::AddressSpace::Storage { .. }) => {
                blocks.push(rb)
            }
            _ => {}
        }
    }
    let key = |rb: &naga::ResourceBinding| (rb.group, rb.binding);
    blocks.sort_by_key(key);
    textures.sort_by_key(key);
    let mut map = BTreeMap::new();
    for list in [blocks, textures] {
        for (i, rb) in list.into_iter().enumerate() {
            map.insert(rb, i as u8);
        }
    }
    map
}

/// The Metal argument slots of one variant: buffers, textures and samplers
/// numbered densely, each table in (group, binding) order, the same in every
/// stage (limits: 31 buffers, 128 textures, 16 samplers per stage).
pub fn msl_slots(module: &naga::Module) -> BTreeMap<naga::ResourceBinding, weft_meta::MslBinding> {
    use weft_meta::MslSlotKind;
    let mut by_kind: BTreeMap<u8, Vec<naga::ResourceBinding>> = BTreeMap::new();
    for (_, var) in module.global_variables.iter() {
        let Some(rb) = var.binding else { continue };
        let kind = match &module.types[var.ty].inner {
            naga::TypeInner::Image { .. } => 1,
            naga::TypeInner::Sampler { .. } => 2,
            _ => 0,
        };
        by_kind.entry(kind).or_default().push(rb);
    }
    let mut map = BTreeMap::new();
    for (kind, mut list) in by_kind {
        list.sort_by_key(|rb| (rb.group, rb.binding));
        for (i, rb) in list.into_iter().enumerate() {
            let kind = match kind {
                0 => MslSlotKind::Buffer,
                1 => MslSlotKind::Texture,
                _ => MslSlotKind::Sampler,
            };
            map.insert(
                rb,
                weft_meta::MslBinding {
                    kind,
                    index: i as u32,
                },
            );
        }
    }
    map
}

/// Every group-0 and group-2 binding name (`weft_meta::engine::ENGINE_BINDINGS`)
/// has a description (checked by a test).
pub const ENGINE_BINDING_NAMES: [&str; ENGINE_BINDINGS.len()] = {
    let mut names = [""; ENGINE_BINDINGS.len()];
    let mut i = 0;
    while i < names.len() {
        names[i] = ENGINE_BINDINGS[i].name;
        i += 1;
    }
    names
};

/// (group, binding) -> register `binding` in space `group`.
pub fn hlsl_options(module: &Module) -> hlsl::Options {
    let mut options = hlsl::Options {
        shader_model: hlsl::ShaderModel::V5_1,
        fake_missing_bindings: false,
        ..hlsl::Options::default()
    };
    options.sampler_heap_target = hlsl::SamplerHeapBindTargets {
        standard_samplers: bind_target(HLSL_SAMPLER_HEAP_SPACE, 0),
        comparison_samplers: bind_target(HLSL_COMPARISON_SAMPLER_HEAP_SPACE, 0),
    };
    for (_, var) in module.global_variables.iter() {
        if let Some(rb) = &var.binding {
            options
                .binding_map
                .insert(*rb, bind_target(rb.group as u8, rb.binding));
            options.sampler_buffer_binding_map.insert(
                hlsl::SamplerIndexBufferKey { group: rb.group },
                bind_target(rb.group as u8, HLSL_SAMPLER_INDEX_REGISTER),
            );
        }
    }
    options
}

fn bind_target(space: u8, register: u32) -> hlsl::BindTarget {
    hlsl::BindTarget {
        space,
        register,
        binding_array_size: None,
        dynamic_storage_buffer_offsets_index: None,
        restrict_indexing: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_engine_binding_is_described() {
        for b in ENGINE_BINDINGS {
            let r = engine_resource(b.name).expect(b.name);
            assert_eq!(r.id, b.id, "{}", b.name);
        }
        // The WGSL declares exactly weft_meta's (group, binding, name) table.
        let src = ENGINE_INTERFACE;
        let declared = src
            .lines()
            .filter(|l| l.starts_with("@group("))
            .map(|l| {
                let number = |key: &str| -> u32 {
                    let rest = &l[l.find(key).expect(key) + key.len()..];
                    rest[..rest.find(')').unwrap()].parse().unwrap()
                };
                let rest = l.split("var").nth(1).unwrap();
                let rest = rest.trim_start_matches(|c| c != ' ').trim();
                let name = rest.split(':').next().unwrap().trim().to_string();
                (number("@group("), number("@binding("), name)
            })
            .collect::<Vec<_>>();
        let expected: Vec<(u32, u32, String)> = ENGINE_BINDINGS
            .iter()
            .map(|b| (b.group, b.binding, b.name.to_string()))
            .collect();
        assert_eq!(declared, expected);
    }

    #[test]
    fn every_engine_member_is_described() {
        for m in [
            "view_proj",
            "view",
            "camera_position",
            "light_direction",
            "light_color",
            "sh",
            "params",
            "viewport",
        ] {
            assert!(member_description("WeftFrame", m).is_some(), "{m}");
        }
        for m in ["model", "normal_matrix"] {
            assert!(member_description("WeftObject", m).is_some(), "{m}");
        }
    }
}
