//! A variant's resource bindings (kind, stages, HLSL registers) and the
//! layouts of its uniform blocks, member by member.

use crate::{
    BufferBinding, EngineResource, MslBinding, SamplerBinding, Stage, TextureBinding, UniformType,
};
#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

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
