//! What an engine sets in its pipeline and bind group layouts, spelled out so
//! that nothing has to be guessed: per pass the primitive, colour and depth
//! state; per binding the full layout entry (buffer, texture or sampler
//! details, and which engine data a frame/object binding carries); per
//! language the coordinate conventions of the emitted code.
//!
//! Names follow WebGPU's enums in snake_case (`one_minus_src_alpha`,
//! `clamp_to_edge`, `rgba16float`), which map one to one onto Vulkan, D3D12,
//! Metal and GL (docs/engine-interface.md has the table).

use crate::{CullMode, DepthTest, TextureDefault, UniformLayout};
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

// ---------------------------------------------------------------- passes

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum PrimitiveTopology {
    TriangleList,
}

/// Which winding is the front face.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum FrontFace {
    /// Counter-clockwise.
    Ccw,
    /// Clockwise.
    Cw,
}

/// Primitive assembly of a pass.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct PrimitiveState {
    pub topology: PrimitiveTopology,
    /// The front face in the WGSL convention (meshes wind their front faces
    /// counter-clockwise). Other languages may need the opposite setting:
    /// `languages.<lang>.front_face` is the value for drawing that language.
    pub front_face: FrontFace,
    pub cull_mode: CullMode,
}

/// What a colour output holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum ColorOutput {
    /// rgb: linear scene-referred radiance (HDR, may exceed 1), before exposure
    /// and tone mapping; a: coverage (1 for opaque passes).
    LinearRadiance,
    /// As `linear_radiance`, with rgb already multiplied by a.
    PremultipliedLinearRadiance,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum BlendFactor {
    Zero,
    One,
    Src,
    OneMinusSrc,
    SrcAlpha,
    OneMinusSrcAlpha,
    Dst,
    OneMinusDst,
    DstAlpha,
    OneMinusDstAlpha,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum BlendOperation {
    Add,
    Subtract,
    ReverseSubtract,
    Min,
    Max,
}

/// result = src × src_factor (operation) dst × dst_factor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BlendComponent {
    pub src_factor: BlendFactor,
    pub dst_factor: BlendFactor,
    pub operation: BlendOperation,
}

/// The colour (rgb) and alpha equations of a blended target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BlendState {
    pub color: BlendComponent,
    pub alpha: BlendComponent,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum ColorChannel {
    Red,
    Green,
    Blue,
    Alpha,
}

/// One colour attachment of a pass.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ColorTarget {
    /// The fragment output location.
    pub location: u32,
    /// The format the goldens and `weft-render` use. Any float format with
    /// these channels works; a unorm target clamps the HDR output to [0, 1].
    pub format: String,
    pub output: ColorOutput,
    /// False: the shader does not multiply by `weft_frame.params.y`; the
    /// engine applies exposure (and tone mapping) after the passes.
    pub exposure_applied: bool,
    /// False: the output is not tone mapped or encoded; write it to a linear
    /// target (an `*_srgb` target would encode it a second time).
    pub tone_mapped: bool,
    /// None: blending disabled (the output replaces the target).
    pub blend: Option<BlendState>,
    pub write_mask: Vec<ColorChannel>,
}

/// The depth attachment of a pass that tests or writes depth.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct DepthState {
    /// The format `weft-render` uses; any depth format works.
    pub format: String,
    pub write_enabled: bool,
    pub compare: DepthTest,
    /// Depth values: 0 near, 1 far (WGSL/SPIR-V/HLSL/MSL clip-space z in
    /// [0, w]); see `languages.glsl.depth_range` for GLSL.
    pub clear_value: f32,
}

// ---------------------------------------------------------------- bindings

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum BufferBindingType {
    Uniform,
    ReadOnlyStorage,
    Storage,
}

/// A buffer binding's layout entry and the buffer's contents.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BufferBinding {
    #[serde(rename = "type")]
    pub ty: BufferBindingType,
    pub has_dynamic_offset: bool,
    /// Bytes: the struct's size (std140-compatible layout; WGSL uniform rules).
    pub min_binding_size: u64,
    /// Member names, types, offsets and sizes.
    pub layout: UniformLayout,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum TextureSampleType {
    /// Filterable float (bind with a filtering sampler).
    Float,
    UnfilterableFloat,
    Depth,
    Sint,
    Uint,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum TextureViewDimension {
    #[serde(rename = "1d")]
    D1,
    #[serde(rename = "2d")]
    D2,
    #[serde(rename = "2d_array")]
    D2Array,
    Cube,
    CubeArray,
    #[serde(rename = "3d")]
    D3,
}

/// A texture binding's layout entry and what to put in it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TextureBinding {
    pub sample_type: TextureSampleType,
    pub view_dimension: TextureViewDimension,
    pub multisampled: bool,
    /// The format of the data weft provides or `weft-render` uses (e.g.
    /// `rgba8unorm_srgb` for a colour map: sampling must return linear values).
    pub format: String,
    /// Material textures: the built-in 1×1 texture this variant binds while
    /// the parameter is unset (keyword-dependent defaults already resolved).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub default: Option<TextureDefault>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum SamplerBindingType {
    Filtering,
    NonFiltering,
    Comparison,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum FilterMode {
    Nearest,
    Linear,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum AddressMode {
    ClampToEdge,
    Repeat,
    MirrorRepeat,
}

/// A sampler binding's layout entry and the sampler object to create for it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct SamplerBinding {
    pub binding_type: SamplerBindingType,
    pub mag_filter: FilterMode,
    pub min_filter: FilterMode,
    pub mipmap_filter: FilterMode,
    pub address_mode_u: AddressMode,
    pub address_mode_v: AddressMode,
    pub address_mode_w: AddressMode,
    pub lod_min_clamp: f32,
    pub lod_max_clamp: f32,
    /// 1: no anisotropic filtering (the goldens are made without it).
    pub anisotropy_clamp: u16,
    /// Comparison samplers only.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compare: Option<DepthTest>,
}

/// Engine data a group-0 or group-2 binding carries.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct EngineResource {
    /// Stable name: `frame`, `object`, `environment`, `split_sum_lut`, `sheen_albedo_lut`.
    pub id: String,
    /// What the data is and how to fill it.
    pub description: String,
    /// Set when weft ships the data: bind exactly this file's texels.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<ResourceFile>,
}

/// A toolchain-baked data file (a lookup table).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ResourceFile {
    /// Relative to the metadata file.
    pub path: String,
    /// Texture format of the texels (`rg16float`, `r16float`).
    pub format: String,
    pub width: u32,
    pub height: u32,
    /// Byte layout: texel order, endianness.
    pub layout: String,
    /// What the texture coordinates mean.
    pub u: String,
    pub v: String,
    /// What the channels hold.
    pub channels: String,
}

// ---------------------------------------------------------------- GLSL

/// A (group, binding) pair of the WGSL interface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct BindingRef {
    pub group: u32,
    pub binding: u32,
}

/// A GLSL uniform block and its binding point (`layout(std140, binding = N)`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GlslUniformBlock {
    /// The block name (`glGetUniformBlockIndex`).
    pub block: String,
    /// The WGSL binding it stands for.
    pub source: BindingRef,
    /// The uniform-buffer binding point written in the file.
    pub binding: u32,
}

/// A GLSL combined image-sampler uniform and its texture unit
/// (`layout(binding = N) uniform sampler2D …`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GlslSampler {
    /// The uniform's name in the file.
    pub name: String,
    /// The WGSL texture binding it samples.
    pub texture: BindingRef,
    /// The WGSL sampler binding whose state (filter, address modes) the
    /// texture unit needs.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampler: Option<BindingRef>,
    /// The texture unit written in the file.
    pub unit: u32,
}

/// How a GL engine binds one GLSL file. Binding points and units are the
/// same in every stage's file of one variant, so one program can link them.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GlslReflection {
    pub uniform_blocks: Vec<GlslUniformBlock>,
    pub samplers: Vec<GlslSampler>,
}

// ---------------------------------------------------------------- MSL

/// The argument table a Metal resource lives in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum MslSlotKind {
    /// `[[buffer(n)]]`: set with `setVertexBuffer`/`setFragmentBuffer`.
    Buffer,
    /// `[[texture(n)]]`.
    Texture,
    /// `[[sampler(n)]]`.
    Sampler,
}

/// Where a binding lives in the MSL output; the same index in every stage.
/// Indices are dense per table in (group, binding) order, so vertex buffers
/// are free from index 16 up (`languages.msl.notes`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MslBinding {
    pub kind: MslSlotKind,
    pub index: u32,
}

// ---------------------------------------------------------------- languages

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum ClipSpaceY {
    /// +y is the top of the picture (WebGPU, D3D, Metal).
    Up,
    /// +y is the bottom: the vertex stage negates y (naga's coordinate
    /// adjustment), as native Vulkan and weft's GL convention expect.
    Down,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum DepthRange {
    /// Clip-space z in [0, w].
    ZeroToOne,
    /// Clip-space z in [−w, w] (GL's default `glClipControl`).
    MinusOneToOne,
}

/// How `constant`-mode keywords are chosen in one language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum ConstantKeywords {
    /// Pipeline-overridable constants (`pipeline_constants`).
    PipelineConstants,
    /// One file per combination of values (`files[].constants`).
    FilePerValue,
}

/// The conventions of one emitted language: how to draw its files so that
/// the picture matches the WGSL drawn through WebGPU.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct LanguageConventions {
    pub clip_space_y: ClipSpaceY,
    pub depth_range: DepthRange,
    /// The front face to set in this API's pipeline (native viewport, no
    /// y flip of its own) for a pass's `cull_mode` to keep the faces meant.
    pub front_face: FrontFace,
    /// Row 0 of the colour target holds the top of the picture when drawn
    /// with this API's native conventions.
    pub top_row_first: bool,
    pub constant_keywords: ConstantKeywords,
    /// The target API and anything else an engine must know.
    pub notes: String,
}
