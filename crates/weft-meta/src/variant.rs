//! Variants: the points of the keyword × tier space, their emitted files,
//! entry points and pipeline constants.

use crate::{Binding, GlslReflection, UniformLayout, VertexInput};
#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

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
