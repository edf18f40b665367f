//! A material's passes: the render state as authored (blend, cull, depth,
//! stencil, queue), instance counts, and the vertex inputs a mesh provides.

#[cfg(feature = "schema")]
use crate::names;
use crate::{ColorTarget, Condition, DepthStencilState, PrimitiveState};
#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

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
    /// The input's name: one of [`VERTEX_INPUTS`](crate::VERTEX_INPUTS).
    #[cfg_attr(feature = "schema", schemars(description = names::vertex_input_name_description()))]
    pub name: String,
    /// Shader location (`@location`), fixed by the engine interface: the input's index in
    /// [`VERTEX_INPUTS`](crate::VERTEX_INPUTS).
    #[cfg_attr(feature = "schema", schemars(description = names::vertex_input_location_description()))]
    pub location: u32,
    /// WebGPU vertex format name, e.g. `float32x3`.
    pub format: String,
}
