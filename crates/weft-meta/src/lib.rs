//! Inspector metadata: the JSON an engine's material panel and binding code read.
//!
//! This crate is what an engine links. It depends on serde (and schemars, to
//! publish the JSON Schema) only — never on naga — so a runtime can read
//! `generated/<material>/<material>.meta.json` without pulling in a compiler.
//!
//! Versioning: [`SCHEMA_VERSION`] changes whenever a field is removed or its
//! meaning changes; adding optional fields does not bump it.

pub mod bake;
pub mod pipeline;
pub mod scene;

pub use pipeline::*;

use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Version of the metadata layout written into every file.
pub const SCHEMA_VERSION: u32 = 2;

/// Version of the engine interface (group 0 frame, group 2 object, vertex inputs).
pub const ENGINE_INTERFACE_VERSION: u32 = 1;

/// Everything an engine needs to show, bind and draw one material.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MaterialMetadata {
    pub schema_version: u32,
    pub engine_interface_version: u32,
    /// Material name (the folder name under `generated/`).
    pub name: String,
    pub label: Text,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<Text>,
    /// Hash of every input (TOML, WGSL sources, toolchain version): unchanged inputs skip the rebuild.
    pub inputs_hash: String,
    /// Inspector groups, in display order.
    pub groups: Vec<Group>,
    /// Parameters in declaration order (display order is `group` then `order`).
    pub parameters: Vec<Parameter>,
    pub keywords: Vec<Keyword>,
    pub tiers: Tiers,
    pub presets: Vec<Preset>,
    pub passes: Vec<Pass>,
    /// Vertex inputs the material requires, with the engine interface's locations.
    pub vertex_inputs: Vec<VertexInput>,
    /// Every variant of the static keyword/tier space, canonical ones first-seen.
    pub variants: Vec<Variant>,
    /// Per emitted language (`wgsl`, `spirv`, `hlsl`, `msl`, `glsl`): the
    /// coordinate conventions to draw its files with.
    pub languages: BTreeMap<String, LanguageConventions>,
    /// Measured cost and error per tier. Never written by the compiler (its
    /// output is deterministic); attached at load time from
    /// `<generated>/reports/<name>.measurements.json` by [`MaterialMetadata::attach_measurements`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub measurements: Option<Measurements>,
}

/// Shading cost and accuracy of a material's tiers, measured by
/// `cargo xtask bench shading` / `weft bench` on one adapter. This is the
/// content of `generated/reports/<name>.measurements.json`; timings vary by machine.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
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
    pub width: u32,
    pub height: u32,
    /// Built-in scene (`sphere`, `cloth`, `swatch`).
    pub scene: String,
    /// Keywords and parameters: the material's defaults unless stated here.
    pub setup: String,
    /// One entry per tier, in the material's tier order.
    pub tiers: Vec<TierMeasurement>,
}

/// One tier of [`Measurements`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TierMeasurement {
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
}

/// User-facing text in English with an optional Chinese translation.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Text {
    pub en: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub zh: Option<String>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Group {
    pub name: String,
    pub label: Text,
}

/// The value kinds a parameter can have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum ParamKind {
    Float,
    Int,
    Bool,
    Vec2,
    Vec3,
    Vec4,
    Color,
    Texture2d,
    Cube,
    Curve,
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
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Parameter {
    pub name: String,
    pub kind: ParamKind,
    pub label: Text,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tooltip: Option<Text>,
    pub group: String,
    pub order: i64,
    /// Default value as the inspector shows it: a number, bool, array of
    /// numbers (vectors; colours in sRGB-encoded space unless `hdr`), or a
    /// texture default name.
    pub default: serde_json::Value,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub range: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub soft_range: Option<[f64; 2]>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub step: Option<f64>,
    /// Power-slider exponent: slider position p maps to value min + (max-min) p^power.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub power: Option<f64>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub show_if: Option<Condition>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<ColorInfo>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub texture: Option<TextureInfo>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub curve: Option<CurveInfo>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gradient: Option<GradientInfo>,
    /// Where the value lives in the material uniform (numeric kinds, curves, texture tiling).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub uniform_member: Option<String>,
    /// The binding (group 1) of a texture, cube or gradient ramp.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub binding: Option<u32>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ColorInfo {
    /// HDR colours may exceed 1 and are edited in linear space.
    pub hdr: bool,
    /// The default converted to the linear value written into the uniform.
    pub linear_default: [f64; 4],
}

/// Built-in 1x1 textures an engine binds when a texture parameter is unset.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum TextureDefault {
    /// (1,1,1,1)
    White,
    /// (0,0,0,1)
    Black,
    /// (0.5,0.5,0.5,1) in the texture's own encoding.
    Gray,
    /// Flat tangent-space normal (0.5,0.5,1,1).
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
    /// The RGBA8 bytes of the built-in 1x1 texture.
    pub fn rgba8(self) -> [u8; 4] {
        self.texel().map(|c| (c * 255.0).round() as u8)
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
    /// The texel value as stored (before any sRGB decode).
    pub fn texel(self) -> [f32; 4] {
        match self {
            TextureDefault::White => [1.0, 1.0, 1.0, 1.0],
            TextureDefault::Black => [0.0, 0.0, 0.0, 1.0],
            TextureDefault::Gray => [0.5, 0.5, 0.5, 1.0],
            TextureDefault::Normal => [0.5, 0.5, 1.0, 1.0],
        }
    }
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
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
    /// Uniform member (vec4: xy tiling, zw offset) when the texture has tiling/offset.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tiling_member: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tiling_default: Option<[f64; 4]>,
}

/// `default` replaces the texture default in variants where `condition` holds.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ConditionalTextureDefault {
    /// On a static keyword or `tier`.
    pub condition: Condition,
    pub default: TextureDefault,
}

/// A curve keyframe: cubic Hermite between keys, slopes per unit time.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Keyframe {
    pub time: f64,
    pub value: f64,
    pub in_slope: f64,
    pub out_slope: f64,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CurveInfo {
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
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum CurveEncoding {
    /// Named and versioned: a different packing gets a new name.
    F32x4PackedV1,
}

#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GradientStop {
    pub position: f64,
    /// sRGB-encoded colour as edited.
    pub color: [f64; 4],
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GradientInfo {
    pub stops: Vec<GradientStop>,
    /// Width in texels of the 1-D ramp (a `width` x 1 Rgba8UnormSrgb texture).
    pub width: u32,
    /// How the ramp's texels are made from the stops.
    pub encoding: GradientEncoding,
    /// The default ramp, sRGB8 RGBA texels, `width` * 4 bytes as numbers.
    pub baked_default: Vec<u8>,
}

/// The texel encoding of a gradient ramp.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum GradientEncoding {
    /// Texel i samples the stops at t = i / (width − 1), interpolating the
    /// sRGB-encoded colours linearly between neighbouring stops (constant
    /// outside the first and last), rounded to 8 bits; bound as
    /// `rgba8unorm_srgb`, width × 1, sampled at texel centres with the
    /// clamp sampler. `weft_meta::bake` is the reference implementation.
    Rgba8SrgbRampV1,
}

/// A show-if condition on a keyword or a bool parameter.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Condition {
    /// A keyword, `tier`, or a bool parameter.
    pub subject: String,
    pub op: ConditionOp,
    /// Keyword value, tier name, or "on"/"off" for toggles and bool parameters.
    pub value: String,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum ConditionOp {
    Equal,
    NotEqual,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum KeywordKind {
    /// Unity's Toggle: values "off", "on".
    Toggle,
    /// Unity's KeywordEnum.
    Enum,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum KeywordMode {
    /// One compiled variant per value.
    Static,
    /// Kept as a WGSL `override` (a pipeline constant) in the WGSL output; the
    /// other languages, which naga cannot give specialisation constants, get
    /// one file per value.
    Constant,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Keyword {
    /// The WGSL `override` name (UPPER_SNAKE).
    pub name: String,
    pub kind: KeywordKind,
    pub mode: KeywordMode,
    /// Values in order; the WGSL constant `<NAME>_<VALUE>` equals the index.
    pub values: Vec<String>,
    pub default: String,
    pub label: Text,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tooltip: Option<Text>,
    pub group: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub show_if: Option<Condition>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Tiers {
    /// Tier names; the WGSL constant `TIER_<NAME>` equals the index.
    pub values: Vec<String>,
    pub default: String,
    /// The most accurate tier every other tier is measured against.
    pub reference: String,
    /// Per tier: what it changes, for people choosing one.
    pub descriptions: BTreeMap<String, Text>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Preset {
    pub name: String,
    pub label: Text,
    /// Parameter values (as in `Parameter::default`) and keyword values.
    pub values: BTreeMap<String, serde_json::Value>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum BlendMode {
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

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum CullMode {
    None,
    Front,
    Back,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum DepthTest {
    Always,
    Never,
    Less,
    LessEqual,
    Equal,
    Greater,
    GreaterEqual,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RenderState {
    pub blend: BlendMode,
    pub cull: CullMode,
    pub depth_write: bool,
    pub depth_test: DepthTest,
    /// Draw order (Unity-style: 2000 geometry, 3000 transparent).
    pub queue: i64,
}

/// How many instances a pass draws.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum InstanceCount {
    Fixed(u32),
    /// The value of an int parameter (e.g. a shell count).
    Parameter(String),
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Pass {
    pub name: String,
    pub vertex_entry: String,
    pub fragment_entry: String,
    /// The state as the material author wrote it.
    pub render_state: RenderState,
    pub instances: InstanceCount,
    /// The pipeline state that follows from it, in full.
    pub primitive: PrimitiveState,
    /// Colour attachments in fragment-output location order.
    pub color_targets: Vec<ColorTarget>,
    /// None when the pass neither tests nor writes depth (no depth
    /// attachment needed).
    pub depth: Option<DepthState>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct VertexInput {
    /// position, normal, tangent, uv0, uv1 or color.
    pub name: String,
    pub location: u32,
    /// WebGPU vertex format name, e.g. `float32x3`.
    pub format: String,
}

/// One point of the static keyword x tier space.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Variant {
    /// Stable id, also the file stem: `<tier>.<keyword>-<value>...` (lower case).
    pub id: String,
    pub tier: String,
    /// Static keyword values.
    pub keywords: BTreeMap<String, String>,
    /// Set when the specialised module is identical to an earlier variant's:
    /// use that variant's files and reflection.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub alias_of: Option<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shader: Option<VariantShader>,
}

/// Files and reflection of a canonical (non-alias) variant.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct VariantShader {
    /// Language -> files (paths relative to the metadata file).
    pub files: BTreeMap<String, Vec<ShaderFile>>,
    pub entry_points: Vec<EntryPoint>,
    /// WGSL `override`s left in the WGSL output (keywords in `constant` mode).
    pub pipeline_constants: Vec<PipelineConstant>,
    pub bindings: Vec<Binding>,
    /// The group 1 uniform block, when the variant still reads it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub material_uniform: Option<UniformLayout>,
    pub vertex_inputs: Vec<VertexInput>,
    /// Parameters the specialised module still reads (uniform members and
    /// textures), in declaration order: an inspector hides the others.
    #[serde(default)]
    pub reads: Vec<String>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ShaderFile {
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

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Stage {
    Vertex,
    Fragment,
    Compute,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EntryPoint {
    pub name: String,
    pub stage: Stage,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
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

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum BindingKind {
    UniformBuffer,
    StorageBuffer,
    Sampler,
    ComparisonSampler,
    Texture2d,
    TextureCube,
    Texture2dArray,
    Texture3d,
    DepthTexture2d,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Binding {
    pub group: u32,
    pub binding: u32,
    /// The WGSL global's name.
    pub name: String,
    pub kind: BindingKind,
    /// The parameter this binding carries, for material textures.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub parameter: Option<String>,
    pub stages: Vec<Stage>,
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
    /// Groups 0 and 2: which engine data the binding carries.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub resource: Option<EngineResource>,
}

/// Where a binding lives in the HLSL output (see docs/hlsl-registers.md).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct HlslBinding {
    /// `b3`, `t2`, … For samplers: the sampler-index buffer's register.
    pub register: String,
    pub space: u32,
    /// Samplers only: the slot of the group's sampler-index buffer that holds
    /// this sampler's index into `nagaSamplerHeap`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampler_index_slot: Option<u32>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct UniformLayout {
    pub struct_name: String,
    pub size: u32,
    pub align: u32,
    pub members: Vec<UniformMember>,
}

#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct UniformMember {
    pub name: String,
    /// WGSL type, e.g. `vec4<f32>`, `array<vec4<f32>, 4>`. Matrices are
    /// column-major; `vec3` members occupy 12 bytes at a 16-byte alignment.
    pub ty: String,
    pub offset: u32,
    pub size: u32,
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
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
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

/// The JSON Schema of [`MaterialMetadata`], pretty-printed.
pub fn metadata_json_schema() -> String {
    let schema = schemars::schema_for!(MaterialMetadata);
    let mut s = serde_json::to_string_pretty(&schema).expect("schema serialises");
    s.push('\n');
    s
}
