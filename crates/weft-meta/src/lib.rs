//! Inspector metadata: the JSON an engine's material panel and binding code read.
//!
//! This crate is what an engine links. It depends on serde and serde_json
//! only — never on naga — so a runtime can read
//! `generated/<material>/<material>.meta.json` without pulling in a compiler.
//! It is the bridge between compiler and runtime ([`uniform`]: member types
//! and the one encoder from parameter values to uniform bytes; [`engine`]:
//! the engine interface's groups, bindings and resource ids).
//!
//! Features (off by default, so an engine compiles neither):
//! `schema` derives `schemars::JsonSchema` and publishes the JSON Schemas
//! (`metadata_json_schema`, `scene::scene_metadata_json_schema`); it
//! implies `measurements`, the bench figures (`Measurements`,
//! `MaterialMetadata::measurements`, `gpu_model`).
//!
//! Versioning ([`version`]): a file states `schema_version` (the major) and
//! `schema_minor`. Adding optional fields or objects bumps the minor, and
//! readers ignore fields they do not know; anything else bumps the major, and
//! [`MaterialMetadata::from_json`] rejects a major it does not know with an
//! error naming both versions.

/// `ALL` (every value, in the order docs and editor schemas list them) and
/// `name()` (the value as serde spells it: a unit test holds the two to
/// serde and to the generated schema) for a unit enum of the metadata, so
/// parsers and tests take the accepted names from the type itself.
macro_rules! value_names {
    ($ty:ident { $($variant:ident => $name:literal),+ $(,)? }) => {
        impl $ty {
            /// Every value, in the order docs and editor schemas list them.
            pub const ALL: [$ty; [$($name),+].len()] = [$($ty::$variant),+];

            /// The value's name in TOML and JSON.
            pub fn name(self) -> &'static str {
                match self {
                    $($ty::$variant => $name),+
                }
            }
        }
    };
}

pub mod bake;
pub mod conventions;
pub mod engine;
pub mod files;
#[cfg(feature = "measurements")]
pub mod gpu_model;
pub mod limits;
pub mod mesh;
pub mod names;
pub mod pipeline;
pub mod scene;
pub mod uniform;
pub mod version;

pub use conventions::Conventions;
pub use limits::DeviceLimits;
pub use names::{BUILTIN_MESHES, ENGINE_RESOURCE_IDS, VERTEX_INPUTS};
pub use pipeline::*;
pub use uniform::{UniformType, UniformValue};
pub use version::MetaError;

#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Major version of the metadata layout written into every file: a reader
/// rejects any other (see [`version`]).
pub const SCHEMA_VERSION: u32 = 4;

/// Minor version of the metadata layout: additions a reader of the same major
/// may ignore. 1: the first layout that states its minor (files without
/// `schema_minor` are 4.0). 2: `conventions` ([`Conventions`]: the built-in
/// textures' exact texels).
pub const SCHEMA_MINOR: u32 = 2;

/// Version of the engine interface (group 0 frame, group 2 object, vertex inputs).
pub const ENGINE_INTERFACE_VERSION: u32 = 2;

/// Everything an engine needs to show, bind and draw one material.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct MaterialMetadata {
    /// Major version of the metadata layout (`weft_meta::SCHEMA_VERSION`, currently 4). It
    /// changes when a field is removed or changes meaning: a reader rejects a major it does not
    /// know (`MaterialMetadata::from_json` does).
    pub schema_version: u32,
    /// Minor version of the metadata layout (`weft_meta::SCHEMA_MINOR`, currently 2). It changes
    /// when optional fields or objects are added: a reader of the same major ignores what it does
    /// not know. Absent (0) in files written before the minor existed.
    #[serde(default)]
    pub schema_minor: u32,
    /// Version of the engine interface the shaders were composed with
    /// (`weft_meta::ENGINE_INTERFACE_VERSION`, currently 2): the group-0 frame and group-2
    /// object bindings and the fixed vertex locations (docs/engine-interface.md).
    pub engine_interface_version: u32,
    /// Material name (the folder name under `generated/`).
    pub name: String,
    /// Display name of the material (`[material].label`; the name when not given).
    pub label: Text,
    /// One-paragraph description for the inspector; absent when the material has none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<Text>,
    /// Hash of every input (TOML, WGSL sources, toolchain version): unchanged inputs skip the rebuild.
    pub inputs_hash: String,
    /// Inspector groups, in display order.
    pub groups: Vec<Group>,
    /// Parameters in declaration order (display order is `group` then `order`).
    pub parameters: Vec<Parameter>,
    /// Keywords (compile-time switches), in declaration order.
    pub keywords: Vec<Keyword>,
    /// Quality tiers: their names, the default and the reference.
    pub tiers: Tiers,
    /// Named sets of parameter, keyword and tier values, in declaration order.
    pub presets: Vec<Preset>,
    /// Every pass of the material, in declaration order, each with its entry points and full
    /// pipeline state. A variant draws the ones its `passes` names (a pass with a `when`
    /// condition exists only in the variants where it holds), by `render_state.queue`, then
    /// this order.
    pub passes: Vec<Pass>,
    /// Vertex inputs the material requires, with the engine interface's locations.
    pub vertex_inputs: Vec<VertexInput>,
    /// WebGPU device limits above the defaults that the material declares (its
    /// `[limits]` table) and its variants may need: request at least these when creating
    /// the device. Absent when every variant fits WebGPU's default limits.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limits: Option<DeviceLimits>,
    /// Every variant of the static keyword/tier space, canonical ones first-seen.
    pub variants: Vec<Variant>,
    /// Per emitted language (`wgsl`, `spirv`, `hlsl`, `msl`, `glsl`): the
    /// coordinate conventions to draw its files with.
    pub languages: BTreeMap<String, LanguageConventions>,
    /// What an engine does as weft's renderer does beyond bindings and
    /// pipeline states: the built-in textures' exact texels
    /// (docs/engine-interface.md). Written since schema 4.2; absent in older
    /// files (read it as `weft_meta::Conventions::current()`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub conventions: Option<Conventions>,
    /// Measured cost and error per tier. Never written by the compiler (its
    /// output is deterministic); attached at load time from
    /// `<generated>/reports/<name>.measurements.json` by [`MaterialMetadata::attach_measurements`].
    // Only with the crate feature `measurements` (a reader without it
    // ignores the field).
    #[cfg(feature = "measurements")]
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub measurements: Option<Measurements>,
}

#[cfg(feature = "measurements")]
/// Shading cost and accuracy of a material's tiers, measured by
/// `cargo xtask bench shading` / `weft bench` on one adapter. This is the
/// content of `generated/reports/<name>.measurements.json`; timings vary by machine.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Measurements {
    /// The material measured.
    pub material: String,
    /// The metadata's `inputs_hash` when measured: a different current hash
    /// means the figures belong to an earlier version of the material.
    pub inputs_hash: String,
    /// The adapter the figures were measured on (name, driver, backend, type).
    pub adapter: String,
    /// `gpu-timestamp` (timestamp queries around the render pass) or
    /// `cpu-wall` (submit to completion on the CPU: the adapter has no timestamp queries).
    pub timer: String,
    /// Width of the render target the figures were measured at, in pixels.
    pub width: u32,
    /// Height of the render target the figures were measured at, in pixels.
    pub height: u32,
    /// The built-in mesh the figures were measured on (one of [`BUILTIN_MESHES`]).
    #[cfg_attr(feature = "schema", schemars(description = names::measured_mesh_description()))]
    pub scene: String,
    /// Keywords and parameters: the material's defaults unless stated here.
    pub setup: String,
    /// One entry per tier, in the material's tier order.
    pub tiers: Vec<TierMeasurement>,
}

#[cfg(feature = "measurements")]
/// One tier of [`Measurements`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct TierMeasurement {
    /// The tier measured (one of the material's `tiers.values`).
    pub tier: String,
    /// The canonical variant drawn.
    pub variant: String,
    /// Timed frames (after warm-up; fewer than asked for when the tier's
    /// frames would exceed the per-tier time budget).
    pub frames: u32,
    /// Median GPU time of the frame's render pass (clear + the material's draws), ms.
    pub gpu_ms: f64,
    /// Fastest frame, ms (least disturbed by other work on a shared machine).
    pub gpu_ms_min: f64,
    /// (90th − 10th percentile) / median of the frame times: run-to-run noise.
    pub gpu_ms_spread: f64,
    /// `gpu_ms` over that of `standard`'s `fast` tier (default keywords) in
    /// the same run; absent when `standard` was not measured.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ratio_to_standard_fast: Option<f64>,
    /// Instructions in the variant's SPIR-V module (static cost).
    pub spirv_instructions: u32,
    /// Of those, the instructions of the functions the fragment entry point reaches.
    pub spirv_fragment_instructions: u32,
    /// FLIP against the reference tier's image (ACES tone-mapped, sRGB8), mean over object pixels.
    pub flip_mean: f64,
    /// 99th percentile of the per-pixel FLIP over object pixels.
    pub flip_p99: f64,
    /// sqrt(Σ(a−b)² / Σb²) over the RGB of object pixels of the linear HDR images, b the reference.
    pub rel_rmse: f64,
    /// What the tier is: `reference`, `approximation` (its error is an
    /// approximation error) or `look` (a different model: its difference is
    /// not an error).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kind: Option<String>,
    /// The error grid (every preset and the defaults × sphere and cloth ×
    /// three light directions, one a grazing rim light), FLIP mean against
    /// the reference per cell: the worst cell. Absent for the reference.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flip_worst: Option<f64>,
    /// The mean over the error grid's cells.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flip_grid_mean: Option<f64>,
    /// The worst cell, as `preset/scene/light`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flip_worst_cell: Option<String>,
    /// Cells of the error grid this tier was measured in.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grid_cells: Option<u32>,
    /// A half-precision variant drawn from its f16 files (the figures
    /// above) is timed from its portable f32 files too, in the same run:
    /// what an engine without `shader-f16` pays. Absent for other variants
    /// and on adapters without `shader-f16`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub f32_files: Option<F32FilesCost>,
}

#[cfg(feature = "measurements")]
/// The cost of a half-precision variant's f32 files ([`TierMeasurement::f32_files`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct F32FilesCost {
    /// Median GPU time of the frame's render pass, ms.
    pub gpu_ms: f64,
    /// `gpu_ms` over that of `standard`'s `fast` tier in the same run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ratio_to_standard_fast: Option<f64>,
}

/// User-facing text in English with an optional Chinese translation.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Text {
    /// English text (always present).
    pub en: String,
    /// Chinese translation; absent when none was given (show `en`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub zh: Option<String>,
}

/// An inspector section.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Group {
    /// Section id (lower_snake_case) that `parameters[].group` and `keywords[].group` name.
    pub name: String,
    /// Section title.
    pub label: Text,
}

/// The value kinds a parameter can have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum ParamKind {
    /// A number: uniform member `f32` (encoding `f32`).
    Float,
    /// An integer: uniform member `i32` (encoding `i32`).
    Int,
    /// A run-time switch: uniform member `u32`, 0 or 1 (encoding `bool_u32`).
    Bool,
    /// Two numbers: uniform member `vec2<f32>` (encoding `vector`).
    Vec2,
    /// Three numbers: uniform member `vec3<f32>` (encoding `vector`; 12 bytes at 16-byte
    /// alignment).
    Vec3,
    /// Four numbers: uniform member `vec4<f32>` (encoding `vector`).
    Vec4,
    /// An RGBA colour edited in sRGB (linear when `color.hdr`): uniform member `vec4<f32>`
    /// (encoding `color`).
    Color,
    /// A 2-D texture (`texture_2d<f32>`) at its own group-1 `binding`; no uniform member unless
    /// tiled (`texture.tiling_member`).
    Texture2d,
    /// A cube texture (`texture_cube<f32>`) at its own group-1 `binding`.
    Cube,
    /// A keyframed curve baked into uniform samples (encoding `curve`; see `curve`).
    Curve,
    /// A colour ramp baked into a `width` × 1 `rgba8unorm_srgb` texture at its own group-1
    /// `binding` (see `gradient`).
    Gradient,
}

impl ParamKind {
    pub const ALL: [ParamKind; 11] = [
        ParamKind::Float,
        ParamKind::Int,
        ParamKind::Bool,
        ParamKind::Vec2,
        ParamKind::Vec3,
        ParamKind::Vec4,
        ParamKind::Color,
        ParamKind::Texture2d,
        ParamKind::Cube,
        ParamKind::Curve,
        ParamKind::Gradient,
    ];

    pub fn name(self) -> &'static str {
        match self {
            ParamKind::Float => "float",
            ParamKind::Int => "int",
            ParamKind::Bool => "bool",
            ParamKind::Vec2 => "vec2",
            ParamKind::Vec3 => "vec3",
            ParamKind::Vec4 => "vec4",
            ParamKind::Color => "color",
            ParamKind::Texture2d => "texture2d",
            ParamKind::Cube => "cube",
            ParamKind::Curve => "curve",
            ParamKind::Gradient => "gradient",
        }
    }

    /// Number of scalar components of a numeric parameter (None for resources).
    pub fn components(self) -> Option<usize> {
        match self {
            ParamKind::Float | ParamKind::Int | ParamKind::Bool => Some(1),
            ParamKind::Vec2 => Some(2),
            ParamKind::Vec3 => Some(3),
            ParamKind::Vec4 | ParamKind::Color => Some(4),
            _ => None,
        }
    }
}

/// One inspector parameter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Parameter {
    /// Parameter name (lower_snake_case): the key in presets and scene values, and the uniform
    /// member's name for uniform-backed kinds.
    pub name: String,
    /// Value kind: decides how the value is stored and which of `color`, `texture`, `curve` and
    /// `gradient` is present.
    pub kind: ParamKind,
    /// Display name.
    pub label: Text,
    /// Hover help; absent when none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tooltip: Option<Text>,
    /// The `groups[].name` of the section the parameter is shown in.
    pub group: String,
    /// Sort key within the group, ascending (default 0).
    pub order: i64,
    /// Default value as the inspector shows it: a number, bool, array of
    /// numbers (vectors; colours in sRGB-encoded space unless `hdr`), or a
    /// texture default name.
    pub default: serde_json::Value,
    /// Hard limits [min, max], inclusive: values outside are invalid and the inspector clamps
    /// to them. Per component for vectors and colours, keyframe values for curves. Non-HDR
    /// colours get [0, 1]; absent: unbounded.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub range: Option<[f64; 2]>,
    /// The slider's span [min, max], inside `range`; values outside it (but inside `range`) may
    /// still be typed in. Absent: the slider spans `range`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub soft_range: Option<[f64; 2]>,
    /// Slider increment (> 0); absent: the inspector chooses.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub step: Option<f64>,
    /// Power-slider exponent: slider position p maps to value min + (max-min) p^power.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub power: Option<f64>,
    /// Show the parameter only while this condition holds; absent: always shown.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub show_if: Option<Condition>,
    /// Present for `color` parameters: the HDR flag and the linear default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<ColorInfo>,
    /// Present for `texture2d` and `cube` parameters: defaults, sRGB flag and tiling.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub texture: Option<TextureInfo>,
    /// Present for `curve` parameters: keyframes and how they are baked into the uniform.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub curve: Option<CurveInfo>,
    /// Present for `gradient` parameters: stops and how they are baked into the ramp texture.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gradient: Option<GradientInfo>,
    /// Where the value lives in the material uniform (numeric kinds, curves, texture tiling).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub uniform_member: Option<String>,
    /// The binding (group 1) of a texture, cube or gradient ramp.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub binding: Option<u32>,
}

/// Colour details of a `color` parameter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct ColorInfo {
    /// HDR colours may exceed 1 and are edited in linear space.
    pub hdr: bool,
    /// The default converted to the linear value written into the uniform.
    pub linear_default: [f64; 4],
}

/// Built-in 1x1 textures an engine binds when a texture parameter is unset.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum TextureDefault {
    /// (1,1,1,1)
    White,
    /// (0,0,0,1)
    Black,
    /// (0.5,0.5,0.5,1) in the texture's own encoding: bytes (128, 128, 128, 255).
    Gray,
    /// Flat tangent-space normal (0.5,0.5,1,1): bytes (128, 128, 255, 255).
    Normal,
}

impl TextureDefault {
    pub const ALL: [TextureDefault; 4] = [
        TextureDefault::White,
        TextureDefault::Black,
        TextureDefault::Gray,
        TextureDefault::Normal,
    ];
    pub fn name(self) -> &'static str {
        match self {
            TextureDefault::White => "white",
            TextureDefault::Black => "black",
            TextureDefault::Gray => "gray",
            TextureDefault::Normal => "normal",
        }
    }
    /// The RGBA8 bytes of the built-in 1x1 texture: what weft's renderer
    /// uploads and metadata states (`conventions.builtin_textures`). 0.5 is
    /// 128 (0.5 × 255 = 127.5, rounded half away from zero).
    pub const fn rgba8(self) -> [u8; 4] {
        match self {
            TextureDefault::White => [255, 255, 255, 255],
            TextureDefault::Black => [0, 0, 0, 255],
            TextureDefault::Gray => [128, 128, 128, 255],
            TextureDefault::Normal => [128, 128, 255, 255],
        }
    }
    /// What sampling the built-in texture returns: its RGBA8 bytes decoded,
    /// through the sRGB curve (RGB only) when the texture is sRGB. Scene
    /// builds fold a texture left at its default to this constant.
    pub fn sampled(self, srgb: bool) -> [f32; 4] {
        let b = self.rgba8();
        std::array::from_fn(|i| {
            let unorm = f64::from(b[i]) / 255.0;
            if srgb && i < 3 {
                bake::srgb_to_linear(unorm) as f32
            } else {
                unorm as f32
            }
        })
    }
    /// The texel value as stored (before any sRGB decode): the
    /// [`TextureDefault::rgba8`] bytes / 255 (`gray` is 128/255, not 0.5).
    pub fn texel(self) -> [f32; 4] {
        self.rgba8().map(|b| f32::from(b) / 255.0)
    }
}

/// Details of a `texture2d` or `cube` parameter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct TextureInfo {
    /// The built-in texture bound while the parameter is unset, unless an
    /// entry of `default_when` holds for the variant.
    pub default: TextureDefault,
    /// Keyword-dependent defaults, tried in order; each variant's binding
    /// states the resolved one (`bindings[].texture.default`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub default_when: Vec<ConditionalTextureDefault>,
    /// Colour data: bind an `*Srgb` format so sampling returns linear values.
    pub srgb: bool,
    /// `texture2d` parameters that ship an image (`file` in the material's
    /// TOML): the texels weft wrote beside the variants. An engine binds this
    /// file while the parameter is unset; `default` is what it binds where it
    /// cannot load the file. Absent for parameters without one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<ResourceFile>,
    /// Uniform member (vec4: xy tiling, zw offset) when the texture has tiling/offset.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tiling_member: Option<String>,
    /// Default of `tiling_member`, [tiling x, tiling y, offset x, offset y] = [1, 1, 0, 0];
    /// present exactly when `tiling_member` is.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tiling_default: Option<[f64; 4]>,
}

/// `default` replaces the texture default in variants where `condition` holds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct ConditionalTextureDefault {
    /// On a static keyword or `tier`.
    pub condition: Condition,
    /// The built-in texture bound in variants where `condition` holds.
    pub default: TextureDefault,
}

/// A curve keyframe: cubic Hermite between keys, slopes per unit time.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Keyframe {
    /// Position on the curve's axis; strictly increasing along `keyframes`.
    pub time: f64,
    /// Curve value at `time` (inside the parameter's `range`, when it has one).
    pub value: f64,
    /// Slope (value per unit time) entering the key, from the previous key.
    pub in_slope: f64,
    /// Slope (value per unit time) leaving the key, towards the next key.
    pub out_slope: f64,
}

/// How a `curve` parameter is edited and baked into the material uniform.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct CurveInfo {
    /// The default curve's keys, times strictly increasing; the curve is constant before the
    /// first and after the last (`weft_meta::bake::eval_curve` evaluates it).
    pub keyframes: Vec<Keyframe>,
    /// Number of samples the toolchain bakes into the uniform array.
    pub samples: u32,
    /// The default curve sampled at `time_min + i (time_max - time_min)/(samples-1)`.
    pub baked_default: Vec<f64>,
    /// [time_min, time_max]: the span the shader maps its argument onto.
    /// Fixed at build time: a re-baked curve must be sampled over this span.
    pub time_range: [f64; 2],
    /// How the samples are laid out in the uniform member.
    pub encoding: CurveEncoding,
}

/// The uniform encoding of a curve: `samples` f32 values packed four per
/// `vec4<f32>` (sample i in element i / 4, component i % 4), the last
/// element's unused components zero. The shader interpolates linearly
/// between neighbouring samples and clamps outside `time_range`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum CurveEncoding {
    /// Named and versioned: a different packing gets a new name.
    F32x4PackedV1,
}

/// One stop of a gradient.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct GradientStop {
    /// Where the stop sits, in [0, 1]; positions never decrease along `stops`.
    pub position: f64,
    /// sRGB-encoded colour as edited.
    pub color: [f64; 4],
}

/// How a `gradient` parameter is edited and baked into its ramp texture.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct GradientInfo {
    /// The default gradient's stops, positions non-decreasing; the colour is constant before
    /// the first and after the last.
    pub stops: Vec<GradientStop>,
    /// Width in texels of the 1-D ramp (a `width` x 1 Rgba8UnormSrgb texture).
    pub width: u32,
    /// How the ramp's texels are made from the stops.
    pub encoding: GradientEncoding,
    /// The default ramp, sRGB8 RGBA texels, `width` * 4 bytes as numbers.
    pub baked_default: Vec<u8>,
}

/// The texel encoding of a gradient ramp.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum GradientEncoding {
    /// Texel i holds the gradient at x = (i + 0.5) / width (texel centres):
    /// the stops' colours decoded from sRGB to linear, interpolated linearly
    /// between neighbouring stops (alpha linearly too; constant outside the
    /// first and last stop), then sRGB-encoded and rounded to 8 bits. Bound
    /// as `rgba8unorm_srgb`, width × 1, and sampled with the clamp sampler.
    /// `weft_meta::bake::bake_gradient` is the reference implementation.
    Rgba8SrgbRampV1,
}

/// A show-if condition on a keyword or a bool parameter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Condition {
    /// A keyword, `tier`, or a bool parameter.
    pub subject: String,
    /// The comparison of the subject's current value with `value`.
    pub op: ConditionOp,
    /// Keyword value, tier name, or "on"/"off" for toggles and bool parameters.
    pub value: String,
}

/// How a condition compares its subject's current value with `value`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum ConditionOp {
    /// Holds when the subject's value is `value`.
    Equal,
    /// Holds when the subject's value is not `value`.
    NotEqual,
}

/// The values a keyword has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum KeywordKind {
    /// Unity's Toggle: values "off", "on".
    Toggle,
    /// Unity's KeywordEnum.
    Enum,
}

value_names!(KeywordKind {
    Toggle => "toggle",
    Enum => "enum",
});

/// How a keyword's values become compiled code.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum KeywordMode {
    /// One compiled variant per value.
    Static,
    /// Kept as a WGSL `override` (a pipeline constant) in the WGSL output; the
    /// other languages, which naga cannot give specialisation constants, get
    /// one file per value.
    Constant,
}

value_names!(KeywordMode {
    Static => "static",
    Constant => "constant",
});

/// A keyword: a compile-time switch shown in the inspector.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Keyword {
    /// The WGSL `override` name (UPPER_SNAKE).
    pub name: String,
    /// Toggle (values `off`, `on`) or enum (values as listed).
    pub kind: KeywordKind,
    /// `static`: a variant per value; `constant`: one variant, the value set as a pipeline
    /// constant (WGSL) or by choosing a file (other languages).
    pub mode: KeywordMode,
    /// Values in order; the WGSL constant `<NAME>_<VALUE>` equals the index.
    pub values: Vec<String>,
    /// The value (one of `values`) the inspector starts from.
    pub default: String,
    /// Display name.
    pub label: Text,
    /// Hover help; absent when none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tooltip: Option<Text>,
    /// The `groups[].name` of the section the keyword is shown in.
    pub group: String,
    /// Show the keyword only while this condition holds; absent: always shown.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub show_if: Option<Condition>,
}

/// The material's quality tiers: the same material at different cost, each tier its own
/// variant.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Tiers {
    /// Tier names; the WGSL constant `TIER_<NAME>` equals the index.
    pub values: Vec<String>,
    /// The tier (one of `values`) the inspector starts from.
    pub default: String,
    /// The most accurate tier every other tier is measured against.
    pub reference: String,
    /// Per tier: what it changes, for people choosing one.
    pub descriptions: BTreeMap<String, Text>,
    /// Per tier that approximates another: the tier it approximates (its
    /// error is measured against that one; `reference` unless the material
    /// says otherwise). The reference and the looks are not listed.
    #[serde(default)]
    pub approximates: BTreeMap<String, String>,
    /// Tiers that are a different model, not an approximation (e.g. `seed`:
    /// a source document's formula kept for its look). Their difference from
    /// the reference is reported apart, never as an error, and automatic
    /// tier choice never picks them.
    #[serde(default)]
    pub looks: Vec<String>,
    /// The material declares itself stylised (no physical ground truth,
    /// `[material] stylised = true`). With a single tier, that tier is
    /// `reference` here and nothing is measured against it.
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub stylised: bool,
}

/// A named set of values for the inspector.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Preset {
    /// Preset id (lower_snake_case), as scene manifests name it.
    pub name: String,
    /// Display name.
    pub label: Text,
    /// Values by name: parameters (as in `Parameter::default`), keywords (a
    /// value name) and `tier` (a tier name).
    pub values: BTreeMap<String, serde_json::Value>,
}

/// How a pass's output is combined with the colour target; `color_targets[].blend` spells out
/// the colour and alpha equations.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum BlendMode {
    /// No blending: the output replaces the target.
    Opaque,
    /// src * a + dst * (1 - a)
    Alpha,
    /// src + dst * (1 - a)
    Premultiplied,
    /// src * a + dst
    Additive,
    /// src * dst
    Multiply,
}

value_names!(BlendMode {
    Opaque => "opaque",
    Alpha => "alpha",
    Premultiplied => "premultiplied",
    Additive => "additive",
    Multiply => "multiply",
});

/// Which faces are culled; which face is front is `primitive.front_face` (counter-clockwise in
/// WGSL).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum CullMode {
    /// Cull nothing: both faces are drawn.
    None,
    /// Cull front faces.
    Front,
    /// Cull back faces.
    Back,
}

value_names!(CullMode {
    None => "none",
    Front => "front",
    Back => "back",
});

/// A comparison function (WebGPU `GPUCompareFunction`): the incoming value (a fragment's depth,
/// or a comparison sampler's reference) against the stored one. Depth 0 is near, 1 far.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum DepthTest {
    /// Always passes.
    Always,
    /// Never passes.
    Never,
    /// Passes when incoming < stored.
    Less,
    /// Passes when incoming ≤ stored.
    LessEqual,
    /// Passes when incoming = stored.
    Equal,
    /// Passes when incoming > stored.
    Greater,
    /// Passes when incoming ≥ stored.
    GreaterEqual,
    /// Passes when incoming ≠ stored.
    NotEqual,
}

value_names!(DepthTest {
    Always => "always",
    Never => "never",
    Less => "less",
    LessEqual => "less_equal",
    Equal => "equal",
    NotEqual => "not_equal",
    Greater => "greater",
    GreaterEqual => "greater_equal",
});

/// What a stencil test does to the stored value (WebGPU `GPUStencilOperation`); only the bits
/// of the write mask change.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum StencilOperation {
    /// Keep the stored value.
    Keep,
    /// Set it to 0.
    Zero,
    /// Set it to the reference (`stencil_reference`).
    Replace,
    /// Invert its bits.
    Invert,
    /// Add 1, staying at 255.
    IncrementClamp,
    /// Subtract 1, staying at 0.
    DecrementClamp,
    /// Add 1, 255 wrapping to 0.
    IncrementWrap,
    /// Subtract 1, 0 wrapping to 255.
    DecrementWrap,
}

value_names!(StencilOperation {
    Keep => "keep",
    Zero => "zero",
    Replace => "replace",
    Invert => "invert",
    IncrementClamp => "increment_clamp",
    DecrementClamp => "decrement_clamp",
    IncrementWrap => "increment_wrap",
    DecrementWrap => "decrement_wrap",
});

/// A pass's stencil test and writes as the material author wrote them (`[[pass]] stencil`),
/// the same for front and back faces. The test passes when
/// `(reference & read_mask) compare (stored & read_mask)`; the operation chosen by the
/// outcome changes the bits of `write_mask`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct StencilRenderState {
    /// The reference value, 0..=255.
    pub reference: u32,
    /// Comparison of the masked reference with the masked stored value.
    pub compare: DepthTest,
    /// Operation when the stencil and depth tests pass.
    pub pass_op: StencilOperation,
    /// Operation when the stencil test fails.
    pub fail_op: StencilOperation,
    /// Operation when the stencil test passes and the depth test fails.
    pub depth_fail_op: StencilOperation,
    /// Bits read by the test, 0..=255.
    pub read_mask: u32,
    /// Bits the operations may change, 0..=255.
    pub write_mask: u32,
}

/// A pass's render state as the material author wrote it (`[[pass]]`); `primitive`,
/// `color_targets` and `depth_stencil` are the pipeline state it implies.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct RenderState {
    /// Blend mode of the colour output.
    pub blend: BlendMode,
    /// Faces culled.
    pub cull: CullMode,
    /// Whether the pass writes depth (as `depth_stencil.depth_write_enabled`).
    pub depth_write: bool,
    /// Depth comparison (as `depth_stencil.depth_compare`).
    pub depth_test: DepthTest,
    /// Draw order (Unity-style: 2000 geometry, 3000 transparent). A scene draws every pass of
    /// every instance by queue, then instance order.
    pub queue: i64,
    /// The stencil test and writes (as `depth_stencil.stencil_*`); absent: the pass neither
    /// tests nor writes the stencil.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stencil: Option<StencilRenderState>,
}

/// How many instances a pass draws.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum InstanceCount {
    /// A fixed number of instances, 1..=4096.
    Fixed(u32),
    /// The value of an int parameter (e.g. a shell count).
    Parameter(String),
}

/// One draw of the mesh: entry points, instance count and pipeline state.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Pass {
    /// Pass name, distinct within the material.
    pub name: String,
    /// Name of the vertex entry point (listed in every variant's `entry_points`).
    pub vertex_entry: String,
    /// Name of the fragment entry point (listed in every variant's `entry_points`).
    pub fragment_entry: String,
    /// The state as the material author wrote it.
    pub render_state: RenderState,
    /// How many instances to draw (the shader reads `@builtin(instance_index)`).
    pub instances: InstanceCount,
    /// The static keyword (or tier) values the pass exists in, all of which must hold
    /// (`[[pass]] when`, e.g. an outline pass switched on by `OUTLINE`); empty: every
    /// variant. Informational: each variant lists its passes (`Variant::passes`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub when: Vec<Condition>,
    /// The pipeline state that follows from it, in full.
    pub primitive: PrimitiveState,
    /// Colour attachments in fragment-output location order.
    pub color_targets: Vec<ColorTarget>,
    /// The depth-stencil attachment's state, present for every pass: every pass of every
    /// material draws into one `depth24plus_stencil8` attachment.
    pub depth_stencil: DepthStencilState,
}

/// A vertex attribute the mesh provides.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct VertexInput {
    /// The input's name: one of [`VERTEX_INPUTS`].
    #[cfg_attr(feature = "schema", schemars(description = names::vertex_input_name_description()))]
    pub name: String,
    /// Shader location (`@location`), fixed by the engine interface: the input's index in
    /// [`VERTEX_INPUTS`].
    #[cfg_attr(feature = "schema", schemars(description = names::vertex_input_location_description()))]
    pub location: u32,
    /// WebGPU vertex format name, e.g. `float32x3`.
    pub format: String,
}

/// One point of the static keyword x tier space.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Variant {
    /// Stable id, also the file stem: `<tier>.<keyword>-<value>...` (lower case).
    pub id: String,
    /// The variant's tier (one of `tiers.values`).
    pub tier: String,
    /// Static keyword values.
    pub keywords: BTreeMap<String, String>,
    /// Names of the passes (`MaterialMetadata::passes`) this variant draws, in declaration
    /// order: the passes whose `when` holds here. The shader has the entry points of these
    /// passes only.
    pub passes: Vec<String>,
    /// Set when the specialised module is identical to an earlier variant's:
    /// use that variant's files and reflection.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alias_of: Option<String>,
    /// Files and reflection; absent for an alias (`alias_of`), which uses its target's.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shader: Option<VariantShader>,
}

/// Files and reflection of a canonical (non-alias) variant.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct VariantShader {
    /// Language -> files (paths relative to the metadata file).
    pub files: BTreeMap<String, Vec<ShaderFile>>,
    /// The same variant computing in half precision, for devices with the
    /// WebGPU feature `shader-f16` (Vulkan `shaderFloat16`; Metal always):
    /// `wgsl`, `spirv` and `msl` files `<stem>.f16.*`, with the same entry
    /// points, bindings and uniform layout as `files`. Present only for
    /// variants whose code computes in `weft_half`; `files` then holds the
    /// same code in f32, which runs everywhere (HLSL SM 5.1 and GLSL have no
    /// 16-bit float, so they have no f16 files).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub f16_files: BTreeMap<String, Vec<ShaderFile>>,
    /// Every entry point of the module, with its stage.
    pub entry_points: Vec<EntryPoint>,
    /// WGSL `override`s left in the WGSL output (keywords in `constant` mode).
    pub pipeline_constants: Vec<PipelineConstant>,
    /// The resource bindings the variant still uses, sorted by (group, binding), each with its
    /// layout entry in full.
    pub bindings: Vec<Binding>,
    /// The group 1 uniform block, when the variant still reads it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material_uniform: Option<UniformLayout>,
    /// The vertex inputs the variant's vertex stage reads: a subset of the material's
    /// `vertex_inputs`.
    pub vertex_inputs: Vec<VertexInput>,
    /// Parameters the specialised module still reads (uniform members and
    /// textures), in declaration order: an inspector hides the others.
    #[serde(default)]
    pub reads: Vec<String>,
}

impl VariantShader {
    /// Every file the variant lists: `files`, then `f16_files`.
    pub fn all_files(&self) -> impl Iterator<Item = &ShaderFile> {
        self.files
            .values()
            .flatten()
            .chain(self.f16_files.values().flatten())
    }
}

/// One emitted shader file.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct ShaderFile {
    /// File name, relative to the folder of the metadata file.
    pub path: String,
    /// SHA-256 of the file's bytes, hex.
    pub sha256: String,
    /// Entry point the file holds when the language needs one file per stage (GLSL).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub entry_point: Option<String>,
    /// Values of `constant`-mode keywords baked into this file (non-WGSL languages).
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub constants: BTreeMap<String, String>,
    /// GLSL files: the uniform-block binding points and texture units.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub glsl: Option<GlslReflection>,
}

/// A shader stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    /// The vertex stage.
    Vertex,
    /// The fragment stage.
    Fragment,
    /// The compute stage.
    Compute,
}

/// An entry point of a shader module.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct EntryPoint {
    /// The entry point's function name.
    pub name: String,
    /// The stage it runs in.
    pub stage: Stage,
}

/// A WGSL `override` left in the WGSL output: a `constant`-mode keyword, set when the engine
/// creates the pipeline.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct PipelineConstant {
    /// The WGSL `override` (a keyword's name).
    pub name: String,
    /// `bool` (toggles) or `u32` (enums).
    pub ty: String,
    /// The keyword's values in order: value i is the constant `i` (toggles:
    /// off = false = 0, on = true = 1).
    pub values: Vec<String>,
    /// The keyword's default value, as a name.
    pub default: String,
    /// The default as the constant: `false`/`true` or the value's index.
    /// APIs that take pipeline constants as numbers (WebGPU) pass 0/1 for bools.
    pub default_value: serde_json::Value,
}

/// What a binding holds: the WGSL type of its global.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum BindingKind {
    /// A uniform buffer, `var<uniform>` (details in `buffer`).
    UniformBuffer,
    /// A storage buffer, `var<storage>` (details in `buffer`).
    StorageBuffer,
    /// A `sampler` (details in `sampler`).
    Sampler,
    /// A `sampler_comparison` (details in `sampler`).
    ComparisonSampler,
    /// A sampled 2-D texture, `texture_2d<T>` (details in `texture`).
    Texture2d,
    /// A sampled cube texture, `texture_cube<T>` (details in `texture`).
    TextureCube,
    /// A sampled 2-D array texture, `texture_2d_array<T>` (details in `texture`).
    Texture2dArray,
    /// A sampled 3-D texture, `texture_3d<T>` (details in `texture`).
    Texture3d,
    /// A depth texture, `texture_depth_*` (details in `texture`).
    DepthTexture2d,
}

/// One resource binding of a variant, with its layout entry in full.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Binding {
    /// The WGSL `@group` (Vulkan descriptor set; HLSL register space): 0 frame, 1 material, 2
    /// object.
    pub group: u32,
    /// The WGSL `@binding` within the group (the Vulkan binding number); the HLSL, MSL and
    /// GLSL slots are given separately (`hlsl`, `msl`, `files.glsl[].glsl`).
    pub binding: u32,
    /// The WGSL global's name.
    pub name: String,
    /// What the binding holds; says which of `buffer`, `texture` and `sampler` is present.
    pub kind: BindingKind,
    /// The parameter this binding carries, for material textures.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub parameter: Option<String>,
    /// The stages that use the binding: the layout entry's visibility.
    pub stages: Vec<Stage>,
    /// Where the binding lives in the HLSL output.
    pub hlsl: HlslBinding,
    /// Where the binding lives in the MSL output.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub msl: Option<MslBinding>,
    /// Buffer bindings: the layout entry and the struct's layout.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub buffer: Option<BufferBinding>,
    /// Texture bindings: the layout entry, the format and the default.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub texture: Option<TextureBinding>,
    /// Sampler bindings: the layout entry and the sampler to create.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampler: Option<SamplerBinding>,
    /// Groups 0 and 2: which engine data the binding carries; group 1: the baked table
    /// (`[tables]`) it carries. Absent for material parameters, the material uniform and the
    /// material samplers.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub resource: Option<EngineResource>,
}

/// Where a binding lives in the HLSL output (see docs/hlsl-registers.md).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct HlslBinding {
    /// `b3`, `t2`, … For samplers: the sampler-index buffer's register.
    pub register: String,
    /// Register space (`space<N>`): the binding's WGSL group.
    pub space: u32,
    /// Samplers only: the slot of the group's sampler-index buffer that holds
    /// this sampler's index into `nagaSamplerHeap`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampler_index_slot: Option<u32>,
}

/// A buffer struct's layout by WGSL's uniform-buffer rules (naga's layouter;
/// std140-compatible).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct UniformLayout {
    /// The WGSL struct's name (`WeftFrame`, `WeftMaterial`, `WeftObject`).
    pub struct_name: String,
    /// Size of the struct in bytes, trailing padding included: the least buffer size to bind.
    pub size: u32,
    /// Alignment of the struct in bytes.
    pub align: u32,
    /// The struct's members in declaration order (offsets increasing).
    pub members: Vec<UniformMember>,
}

/// One member of a buffer struct.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct UniformMember {
    /// The member's name in the WGSL struct.
    pub name: String,
    /// WGSL type, e.g. `vec4<f32>`, `array<vec4<f32>, 4>`. Matrices are
    /// column-major; `vec3` members occupy 12 bytes at a 16-byte alignment.
    #[cfg_attr(feature = "schema", schemars(with = "String"))]
    pub ty: UniformType,
    /// Byte offset from the start of the buffer.
    pub offset: u32,
    /// Size in bytes (arrays: element stride × count).
    pub size: u32,
    /// Alignment in bytes (WGSL uniform rules).
    pub align: u32,
    /// Material members: the parameter whose value the member holds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub parameter: Option<String>,
    /// Material members: how the parameter's value becomes these bytes.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub encoding: Option<MemberEncoding>,
    /// Engine members (frame, object): what to write.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
}

/// How a parameter's value is written into its uniform member.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum MemberEncoding {
    /// `float`: the value as f32.
    F32,
    /// `int`: the value as i32.
    I32,
    /// `bool`: u32 0 (false) or 1 (true).
    BoolU32,
    /// `vec2`/`vec3`/`vec4`: the components as f32.
    Vector,
    /// `color`: four f32, RGB converted from the sRGB-encoded value to
    /// linear (`color.hdr` false) or written as is (HDR colours are edited
    /// linear); alpha as is.
    Color,
    /// `curve`: the baked samples, see `curve.encoding`.
    Curve,
    /// A texture's tiling and offset (`texture.tiling_member`): xy tiling, zw offset.
    TilingOffset,
}

impl MaterialMetadata {
    /// The passes `variant` draws (its `passes`), in declaration order.
    pub fn variant_passes<'a>(&'a self, variant: &'a Variant) -> impl Iterator<Item = &'a Pass> {
        self.passes
            .iter()
            .filter(|p| variant.passes.contains(&p.name))
    }

    #[cfg(feature = "measurements")]
    /// Where measurements of the material whose metadata is at `meta_path`
    /// (`<generated>/<name>/<name>.meta.json`) live: `<generated>/reports/<name>.measurements.json`.
    pub fn measurements_path(meta_path: &std::path::Path, name: &str) -> std::path::PathBuf {
        let generated = meta_path
            .parent()
            .and_then(|d| d.parent())
            .unwrap_or(std::path::Path::new("."));
        generated
            .join("reports")
            .join(format!("{name}.measurements.json"))
    }

    #[cfg(feature = "measurements")]
    /// Reads [`Measurements`] from [`MaterialMetadata::measurements_path`] into
    /// `measurements`. Ok(false) when there is no report; an error when there
    /// is one that does not parse.
    pub fn attach_measurements(&mut self, meta_path: &std::path::Path) -> Result<bool, String> {
        let path = Self::measurements_path(meta_path, &self.name);
        let bytes = match std::fs::read(&path) {
            Ok(b) => b,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(false),
            Err(e) => return Err(format!("{}: {e}", path.display())),
        };
        let m: Measurements =
            serde_json::from_slice(&bytes).map_err(|e| format!("{}: {e}", path.display()))?;
        self.measurements = Some(m);
        Ok(true)
    }

    /// The variant an id or alias resolves to, following `alias_of`.
    pub fn resolve_variant(&self, id: &str) -> Option<&Variant> {
        let v = self.variants.iter().find(|v| v.id == id)?;
        match &v.alias_of {
            Some(target) => self.variants.iter().find(|c| &c.id == target),
            None => Some(v),
        }
    }
}

#[cfg(feature = "schema")]
/// The JSON Schema of [`MaterialMetadata`], pretty-printed.
pub fn metadata_json_schema() -> String {
    let schema = schemars::schema_for!(MaterialMetadata);
    let mut s = serde_json::to_string_pretty(&schema).expect("schema serialises");
    s.push('\n');
    s
}
