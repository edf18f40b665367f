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

mod binding;
mod keyword;
#[cfg(feature = "measurements")]
mod measurements;
mod parameter;
mod pass;
mod variant;

pub use binding::{
    Binding, BindingKind, HlslBinding, MemberEncoding, UniformLayout, UniformMember,
};
pub use conventions::Conventions;
pub use keyword::{Condition, ConditionOp, Keyword, KeywordKind, KeywordMode, Preset, Tiers};
pub use limits::DeviceLimits;
#[cfg(feature = "measurements")]
pub use measurements::{F32FilesCost, Measurements, TierMeasurement};
pub use names::{BUILTIN_MESHES, ENGINE_RESOURCE_IDS, VERTEX_INPUTS};
pub use parameter::{
    ColorInfo, ConditionalTextureDefault, CurveEncoding, CurveInfo, GradientEncoding, GradientInfo,
    GradientStop, Keyframe, ParamKind, Parameter, TextureDefault, TextureInfo,
};
pub use pass::{
    BlendMode, CullMode, DepthTest, InstanceCount, Pass, RenderState, StencilOperation,
    StencilRenderState, VertexInput,
};
pub use pipeline::*;
pub use uniform::{UniformType, UniformValue};
pub use variant::{EntryPoint, PipelineConstant, ShaderFile, Stage, Variant, VariantShader};
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
