//! What an engine sets in its pipeline and bind group layouts, spelled out so
//! that nothing has to be guessed: per pass the primitive, colour and depth
//! state; per binding the full layout entry (buffer, texture or sampler
//! details, and which engine data a frame/object binding carries); per
//! language the coordinate conventions of the emitted code.
//!
//! Names follow WebGPU's enums in snake_case (`one_minus_src_alpha`,
//! `clamp_to_edge`, `rgba16float`), which map one to one onto Vulkan, D3D12,
//! Metal and GL (docs/engine-interface.md has the table).

use crate::{CullMode, DepthTest, StencilOperation, TextureDefault, UniformLayout};
#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

// ---------------------------------------------------------------- passes

/// How vertices form primitives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum PrimitiveTopology {
    /// Independent triangles: vertices (or indices) 3i, 3i + 1, 3i + 2 form triangle i.
    TriangleList,
}

/// Which winding is the front face.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum FrontFace {
    /// Counter-clockwise.
    Ccw,
    /// Clockwise.
    Cw,
}

/// Primitive assembly of a pass.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct PrimitiveState {
    /// How the pass's vertices form primitives.
    pub topology: PrimitiveTopology,
    /// The front face in the WGSL convention (meshes wind their front faces
    /// counter-clockwise). Other languages may need the opposite setting:
    /// `languages.<lang>.front_face` is the value for drawing that language.
    pub front_face: FrontFace,
    /// Faces culled, front and back judged by `front_face`.
    pub cull_mode: CullMode,
}

/// What a colour output holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum ColorOutput {
    /// rgb: linear scene-referred radiance (HDR, may exceed 1), before exposure
    /// and tone mapping; a: coverage (1 for opaque passes).
    LinearRadiance,
    /// As `linear_radiance`, with rgb already multiplied by a.
    PremultipliedLinearRadiance,
}

/// What a blend term is multiplied by (WebGPU `GPUBlendFactor`): src is the fragment output,
/// dst the target's current value.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum BlendFactor {
    /// 0.
    Zero,
    /// 1.
    One,
    /// The source: its rgb in the colour equation, its alpha in the alpha equation.
    Src,
    /// 1 − the source (rgb in the colour equation, alpha in the alpha equation).
    OneMinusSrc,
    /// The source's alpha.
    SrcAlpha,
    /// 1 − the source's alpha.
    OneMinusSrcAlpha,
    /// The target: its rgb in the colour equation, its alpha in the alpha equation.
    Dst,
    /// 1 − the target (rgb in the colour equation, alpha in the alpha equation).
    OneMinusDst,
    /// The target's alpha.
    DstAlpha,
    /// 1 − the target's alpha.
    OneMinusDstAlpha,
}

/// How the two weighted terms combine (WebGPU `GPUBlendOperation`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum BlendOperation {
    /// src × src_factor + dst × dst_factor.
    Add,
    /// src × src_factor − dst × dst_factor.
    Subtract,
    /// dst × dst_factor − src × src_factor.
    ReverseSubtract,
    /// min(src, dst): the factors are not applied (WebGPU requires them to be `one`).
    Min,
    /// max(src, dst): the factors are not applied (WebGPU requires them to be `one`).
    Max,
}

/// result = src × src_factor (operation) dst × dst_factor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct BlendComponent {
    /// Factor the fragment output is multiplied by.
    pub src_factor: BlendFactor,
    /// Factor the target's current value is multiplied by.
    pub dst_factor: BlendFactor,
    /// How the two products combine.
    pub operation: BlendOperation,
}

/// The colour (rgb) and alpha equations of a blended target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct BlendState {
    /// Equation of the rgb channels.
    pub color: BlendComponent,
    /// Equation of the alpha channel.
    pub alpha: BlendComponent,
}

/// A channel of a colour target's write mask.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum ColorChannel {
    /// The red channel.
    Red,
    /// The green channel.
    Green,
    /// The blue channel.
    Blue,
    /// The alpha channel.
    Alpha,
}

/// One colour attachment of a pass.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct ColorTarget {
    /// The fragment output location.
    pub location: u32,
    /// The format the goldens and `weft-render` use. Any float format with
    /// these channels works; a unorm target clamps the HDR output to [0, 1].
    pub format: String,
    /// What the fragment output holds.
    pub output: ColorOutput,
    /// False: the shader does not multiply by `weft_frame.params.y`; the
    /// engine applies exposure (and tone mapping) after the passes.
    pub exposure_applied: bool,
    /// False: the output is not tone mapped or encoded; write it to a linear
    /// target (an `*_srgb` target would encode it a second time).
    pub tone_mapped: bool,
    /// None: blending disabled (the output replaces the target).
    pub blend: Option<BlendState>,
    /// The channels the pass writes; the others keep the target's value.
    pub write_mask: Vec<ColorChannel>,
}

/// The depth-stencil format of every pass of every material (WebGPU `depth24plus-stencil8`,
/// core in every API): a scene draws all its materials' passes into one attachment, so they
/// must agree. docs/engine-interface.md maps it per API.
pub const DEPTH_STENCIL_FORMAT: &str = "depth24plus_stencil8";

/// The stencil test and operations of one face (WebGPU `GPUStencilFaceState`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct StencilFaceState {
    /// Passes when `(stencil_reference & stencil_read_mask) compare (stored & stencil_read_mask)`.
    pub compare: DepthTest,
    /// Operation when the stencil test fails.
    pub fail_op: StencilOperation,
    /// Operation when the stencil test passes and the depth test fails.
    pub depth_fail_op: StencilOperation,
    /// Operation when both tests pass.
    pub pass_op: StencilOperation,
}

/// The depth-stencil attachment of a pass (WebGPU `GPUDepthStencilState`, plus the clear values
/// and the stencil reference the engine sets while drawing the pass). A pass that neither
/// tests nor writes depth has `depth_compare: always` and no depth write; one without stencil
/// has `always`/`keep` faces and write mask 0.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct DepthStencilState {
    /// `depth24plus_stencil8` ([`DEPTH_STENCIL_FORMAT`]) for every pass.
    pub format: String,
    /// Write the fragment's depth into the attachment.
    pub depth_write_enabled: bool,
    /// Depth test: a fragment passes when its depth compares so with the stored depth.
    pub depth_compare: DepthTest,
    /// Depth values: 0 near, 1 far (WGSL/SPIR-V/HLSL/MSL clip-space z in
    /// [0, w]); see `languages.glsl.depth_range` for GLSL.
    pub depth_clear_value: f32,
    /// Stencil state of front faces (as `primitive.front_face` judges them).
    pub stencil_front: StencilFaceState,
    /// Stencil state of back faces (weft sets the same as the front).
    pub stencil_back: StencilFaceState,
    /// Bits of the stored value and the reference the test reads.
    pub stencil_read_mask: u32,
    /// Bits the stencil operations may change (0: the pass writes no stencil).
    pub stencil_write_mask: u32,
    /// The reference to set before drawing the pass (WebGPU `setStencilReference`, Vulkan
    /// `vkCmdSetStencilReference`, D3D12 `OMSetStencilRef`, Metal
    /// `setStencilReferenceValue`, GL `glStencilFunc`'s `ref`).
    pub stencil_reference: u32,
    /// The value the attachment is cleared to at the start of the frame.
    pub stencil_clear_value: u32,
}

// ---------------------------------------------------------------- bindings

/// A buffer layout entry's type (WebGPU `GPUBufferBindingType`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum BufferBindingType {
    /// Uniform buffer (`var<uniform>`).
    Uniform,
    /// Read-only storage buffer (`var<storage, read>`).
    ReadOnlyStorage,
    /// Read-write storage buffer (`var<storage, read_write>`).
    Storage,
}

/// A buffer binding's layout entry and the buffer's contents.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct BufferBinding {
    /// Buffer type of the layout entry.
    #[serde(rename = "type")]
    pub ty: BufferBindingType,
    /// Whether the layout entry takes a dynamic offset (WebGPU `hasDynamicOffset`); false for
    /// every weft binding.
    pub has_dynamic_offset: bool,
    /// Bytes: the struct's size (std140-compatible layout; WGSL uniform rules).
    pub min_binding_size: u64,
    /// Member names, types, offsets and sizes.
    pub layout: UniformLayout,
}

/// A texture layout entry's sample type (WebGPU `GPUTextureSampleType`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum TextureSampleType {
    /// Filterable float (bind with a filtering sampler).
    Float,
    /// Float that is not filtered (bind with a non-filtering sampler).
    UnfilterableFloat,
    /// Depth texture.
    Depth,
    /// Signed-integer texels.
    Sint,
    /// Unsigned-integer texels.
    Uint,
}

/// A texture layout entry's view dimension (WebGPU `GPUTextureViewDimension`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum TextureViewDimension {
    /// 1-D texture.
    #[serde(rename = "1d")]
    D1,
    /// 2-D texture.
    #[serde(rename = "2d")]
    D2,
    /// Array of 2-D layers.
    #[serde(rename = "2d_array")]
    D2Array,
    /// Cube map: six square 2-D faces.
    Cube,
    /// Array of cube maps.
    CubeArray,
    /// 3-D texture.
    #[serde(rename = "3d")]
    D3,
}

/// A texture binding's layout entry and what to put in it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct TextureBinding {
    /// Sample type of the layout entry.
    pub sample_type: TextureSampleType,
    /// View dimension of the layout entry and of the view to bind.
    pub view_dimension: TextureViewDimension,
    /// Whether the texture is multisampled (WebGPU `multisampled`).
    pub multisampled: bool,
    /// The format of the data weft provides or `weft-render` uses (e.g.
    /// `rgba8unorm_srgb` for a colour map: sampling must return linear values).
    pub format: String,
    /// Material textures: the built-in 1×1 texture this variant binds while
    /// the parameter is unset (keyword-dependent defaults already resolved).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub default: Option<TextureDefault>,
    /// Material textures whose parameter ships an image (`file` in the
    /// material's TOML): bind this file's texels while the parameter is
    /// unset (`default` is then only the fallback of an engine that cannot
    /// load files). The same file for every variant.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<ResourceFile>,
}

/// A sampler layout entry's type (WebGPU `GPUSamplerBindingType`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum SamplerBindingType {
    /// May filter linearly; pairs with filterable float textures.
    Filtering,
    /// Nearest filtering only; pairs with unfilterable textures.
    NonFiltering,
    /// Depth-comparison sampler (`sampler_comparison`).
    Comparison,
}

/// How neighbouring texels (or mip levels) are combined.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum FilterMode {
    /// The nearest texel (mip level).
    Nearest,
    /// Linear interpolation between the neighbouring texels (mip levels).
    Linear,
}

value_names!(FilterMode {
    Nearest => "nearest",
    Linear => "linear",
});

/// What sampling outside [0, 1] reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum AddressMode {
    /// Coordinates are clamped: the edge texels extend outward.
    ClampToEdge,
    /// The texture tiles (the coordinate's fractional part is used).
    Repeat,
    /// The texture tiles, every other tile mirrored.
    MirrorRepeat,
}

value_names!(AddressMode {
    ClampToEdge => "clamp_to_edge",
    Repeat => "repeat",
    MirrorRepeat => "mirror_repeat",
});

/// A sampler binding's layout entry and the sampler object to create for it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SamplerBinding {
    /// Sampler type of the layout entry.
    pub binding_type: SamplerBindingType,
    /// Filter when the texture is magnified (a texel covers more than a pixel).
    pub mag_filter: FilterMode,
    /// Filter when the texture is minified.
    pub min_filter: FilterMode,
    /// Filter between mip levels.
    pub mipmap_filter: FilterMode,
    /// Addressing of u, the horizontal coordinate.
    pub address_mode_u: AddressMode,
    /// Addressing of v, the vertical coordinate.
    pub address_mode_v: AddressMode,
    /// Addressing of w, the third coordinate (3-D textures).
    pub address_mode_w: AddressMode,
    /// Lowest level of detail (mip level) sampled; 0 is the full-resolution level.
    pub lod_min_clamp: f32,
    /// Highest level of detail (mip level) sampled; 32 leaves every mip level reachable.
    pub lod_max_clamp: f32,
    /// 1: no anisotropic filtering (the goldens are made without it).
    pub anisotropy_clamp: u16,
    /// Comparison samplers only.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub compare: Option<DepthTest>,
}

/// The data a binding carries that is not a material parameter: engine data (groups 0 and
/// 2) or a material's baked table (`[tables]`, group 1).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct EngineResource {
    /// Stable name: one of [`crate::ENGINE_RESOURCE_IDS`] for the engine interface's bindings
    /// (groups 0 and 2), or `<material>.<table>` for a material's baked table (group 1).
    #[cfg_attr(feature = "schema", schemars(description = crate::names::engine_resource_id_description()))]
    pub id: String,
    /// What the data is and how to fill it.
    pub description: String,
    /// Set when weft ships the data: bind exactly this file's texels.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<ResourceFile>,
}

/// A data file weft writes for an engine to bind: a lookup table, a
/// material's baked table (`[tables]`) or a texture parameter's image
/// (`file`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct ResourceFile {
    /// Relative to the library root (the folder holding
    /// `metadata.schema.json` and `luts/`): material metadata lives one folder
    /// below it, scene metadata two (`scenes/<scene>/`).
    pub path: String,
    /// Texture format of the texels (`rg16float`, `r16float`, `rgba16float`;
    /// `rgba8unorm` or `rgba8unorm_srgb` for a texture parameter's image).
    pub format: String,
    /// Width in texels (along u).
    pub width: u32,
    /// Height in texels: the number of rows (along v).
    pub height: u32,
    /// Byte layout: texel order, endianness.
    pub layout: String,
    /// What the texture coordinates mean.
    pub u: String,
    /// What the v coordinate (rows) means.
    pub v: String,
    /// What the channels hold.
    pub channels: String,
    /// SHA-256 of the file's bytes, hex: set for the files that lie beside
    /// a material's variants (baked tables, texture parameters' images).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sha256: Option<String>,
    /// Texture parameters' images (since schema 4.2): the file holds level 0
    /// only, and the engine builds this mip chain before binding it. Absent
    /// for LUTs and baked tables, which are bound with one level.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mip_chain: Option<MipChain>,
}

/// The mip chain an engine builds for a texture file
/// (`weft_meta::bake::rgba8_mip_chain` builds it exactly).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct MipChain {
    /// Levels to create the texture with, level 0 being the file:
    /// floor(log2(max(width, height))) + 1, down to 1×1.
    pub levels: u32,
    /// How level n + 1 is made from level n: `box_2x2`, the mean of the 2×2
    /// texels (2x + i, 2y + j) clamped to level n's size (sides halve,
    /// rounded down, never below 1; an odd side's last row or column is
    /// left out).
    pub filter: String,
    /// Whether RGB is averaged in linear light: decoded from sRGB, averaged,
    /// encoded and rounded to the nearest byte (true for `rgba8unorm_srgb`).
    /// Otherwise, and always for alpha, bytes are averaged and rounded half
    /// up: (a + b + c + d + 2) / 4.
    pub linear_light: bool,
}

/// [`MipChain::filter`]'s one value.
pub const MIP_FILTER_BOX: &str = "box_2x2";

impl MipChain {
    /// The chain of a `width` × `height` texture file, sRGB or not.
    pub fn for_texture(width: u32, height: u32, srgb: bool) -> MipChain {
        MipChain {
            levels: crate::bake::mip_level_count(width, height),
            filter: MIP_FILTER_BOX.into(),
            linear_light: srgb,
        }
    }
}

// ---------------------------------------------------------------- GLSL

/// A (group, binding) pair of the WGSL interface.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct BindingRef {
    /// The WGSL `@group`.
    pub group: u32,
    /// The WGSL `@binding` within the group.
    pub binding: u32,
}

/// A GLSL uniform block and its binding point (`layout(std140, binding = N)`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
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
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct GlslSampler {
    /// The uniform's name in the file.
    pub name: String,
    /// The WGSL texture binding it samples.
    pub texture: BindingRef,
    /// The WGSL sampler binding whose state (filter, address modes) the
    /// texture unit needs. Absent when the file reads the texture only with
    /// `texelFetch`/`textureSize` (WGSL `textureLoad`), where no sampler
    /// state applies: bind the texture to the unit, with any sampler.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sampler: Option<BindingRef>,
    /// The texture unit written in the file.
    pub unit: u32,
}

/// How a GL engine binds one GLSL file. Binding points and units are the
/// same in every stage's file of one variant, so one program can link them.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct GlslReflection {
    /// Each uniform block of the file with its binding point.
    pub uniform_blocks: Vec<GlslUniformBlock>,
    /// Each combined image-sampler uniform of the file with its texture unit.
    pub samplers: Vec<GlslSampler>,
}

// ---------------------------------------------------------------- MSL

/// The argument table a Metal resource lives in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
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
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct MslBinding {
    /// The argument table the resource lives in.
    pub kind: MslSlotKind,
    /// Index in that table (`[[buffer(n)]]`, `[[texture(n)]]` or `[[sampler(n)]]`), the same in
    /// every stage.
    pub index: u32,
}

// ---------------------------------------------------------------- languages

/// Which way clip-space +y points in a language's vertex output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum ClipSpaceY {
    /// +y is the top of the picture (WebGPU, D3D, Metal).
    Up,
    /// +y is the bottom: the vertex stage negates y (naga's coordinate
    /// adjustment), as native Vulkan and weft's GL convention expect.
    Down,
}

/// The clip-space depth range of a language's vertex output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum DepthRange {
    /// Clip-space z in [0, w].
    ZeroToOne,
    /// Clip-space z in [−w, w] (GL's default `glClipControl`).
    MinusOneToOne,
}

/// How `constant`-mode keywords are chosen in one language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum ConstantKeywords {
    /// Pipeline-overridable constants (`pipeline_constants`).
    PipelineConstants,
    /// One file per combination of values (`files[].constants`).
    FilePerValue,
}

/// The conventions of one emitted language: how to draw its files so that
/// the picture matches the WGSL drawn through WebGPU.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct LanguageConventions {
    /// Direction of clip-space +y in this language's vertex output.
    pub clip_space_y: ClipSpaceY,
    /// Clip-space z range of this language's vertex output.
    pub depth_range: DepthRange,
    /// The front face to set in this API's pipeline (native viewport, no
    /// y flip of its own) for a pass's `cull_mode` to keep the faces meant.
    pub front_face: FrontFace,
    /// Row 0 of the colour target holds the top of the picture when drawn
    /// with this API's native conventions.
    pub top_row_first: bool,
    /// How `constant`-mode keywords are chosen in this language.
    pub constant_keywords: ConstantKeywords,
    /// The target API and anything else an engine must know.
    pub notes: String,
}
