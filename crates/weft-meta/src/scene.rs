//! Scene metadata: `<scene>.scene.json`, what an engine reads to draw a scene
//! built by `weft build --scene`.
//!
//! A scene build compiles one shader per distinct specialised instance
//! (instances that specialise to the same module share it). Each instance
//! names its shader, the values folded into it, the `dynamic` parameters it
//! still reads from its (shrunk) material uniform, the textures to bind, its
//! passes, mesh and transform. Nothing here needs the material metadata.

pub use crate::names::{AUTO_TIER, BUILTIN_MESHES};
use crate::{Pass, TextureDefault, VariantShader};
#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Major version of the scene metadata layout: a reader rejects any other
/// (the rule of [`crate::version`]).
pub const SCENE_SCHEMA_VERSION: u32 = 3;

/// Minor version of the scene metadata layout (additions a reader of the same
/// major may ignore). 1: the first that states its minor (files without
/// `schema_minor` are 3.0). 2: `tier_choice.gpu_family` and each candidate's
/// `gpu` figures (automatic tiers costed by the GPU model). 3: `light` is
/// always written, with its `color`: the light weft draws the scene with,
/// [`DEFAULT_LIGHT_DIRECTION`] and [`DEFAULT_LIGHT_COLOR`] where the manifest
/// gives none; `conventions` (as in material metadata 4.2); and `meshes`,
/// the files of the built-in meshes the instances draw. 4: `meshes` entries
/// of meshes the scene folder carries (from glTF) with `file` and `radius`
/// in place of `path`; an instance's `transform.model` may be any affine
/// matrix (translation, rotation and scale are then read back from it).
/// 5: `funnel`. 6: `funnel.modelled`, the GPU model's cost of the
/// instances against their generic variants (`weft build --scene …
/// --gpu-model`). 7: `static_lighting`, the lighting a scene folds into
/// its shaders.
pub const SCENE_SCHEMA_MINOR: u32 = 7;

/// The most instances a scene may have (a written manifest's and a glTF
/// file's alike, `EXT_mesh_gpu_instancing` copies included). Instances that
/// share a specialised shader are compiled once, and the build caps the
/// distinct shaders separately (`weft_compiler::MAX_SCENE_SHADERS`), so this
/// bounds the per-instance work: resolving, checking and describing each
/// instance (1024 repeats of five objects build in about 0.2 s,
/// docs/scaling.md).
pub const MAX_INSTANCES: usize = 1024;

/// The main light's direction (from the surface towards the light, world
/// space; length ≈ 1, normalise it) when a scene manifest has no `[light]`:
/// what weft's renderer draws with, and since scene schema 3.3 what the
/// scene metadata's `light.direction` says.
pub const DEFAULT_LIGHT_DIRECTION: [f64; 3] = [-0.62, 0.55, 0.56];

/// The main light's linear radiance when a scene's `[light]` gives no
/// `color` (or there is no `[light]`): written into `light.color` since
/// scene schema 3.3.
pub const DEFAULT_LIGHT_COLOR: [f64; 3] = [3.2, 3.05, 2.8];

/// The GPU families whose modelled cost (`generated/reports/gpu-model.json`,
/// AMD's compiler on Mesa RADV's null device) `tier = "auto"` can use: a
/// scene picks one with `[scene] gpu_family`.
pub const GPU_COST_FAMILIES: &[&str] = &["navi21", "gfx1100"];
/// The family used when a scene names none (RDNA2).
pub const DEFAULT_GPU_COST_FAMILY: &str = "navi21";

/// Families Mesa's RADV has named differently across releases: weft's name
/// (the oldest spelling, the one reports and scene metadata use) and every
/// `RADV_FORCE_FAMILY` spelling, oldest first. Mesa 22.3 (Debian 12) calls
/// RDNA3's first chip `gfx1100`; later releases call it `navi31`.
pub const GPU_FAMILY_SPELLINGS: &[(&str, &[&str])] = &[("gfx1100", &["gfx1100", "navi31"])];

/// weft's name of the family some Mesa calls `family` (`navi31` is
/// `gfx1100`); every other name is weft's as it is.
pub fn weft_gpu_family(family: &str) -> &str {
    GPU_FAMILY_SPELLINGS
        .iter()
        .find(|(_, all)| all.contains(&family))
        .map_or(family, |(weft, _)| weft)
}

/// Everything an engine needs to draw one scene built by `weft build --scene`: the content of
/// `<scene>.scene.json`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SceneMetadata {
    /// Major version of the scene metadata layout (`weft_meta::scene::SCENE_SCHEMA_VERSION`,
    /// currently 3): a reader rejects a major it does not know.
    pub schema_version: u32,
    /// Minor version of the scene metadata layout (`weft_meta::scene::SCENE_SCHEMA_MINOR`,
    /// currently 3): a reader of the same major ignores fields it does not know. Absent (0) in
    /// files written before the minor existed.
    #[serde(default)]
    pub schema_minor: u32,
    /// Version of the engine interface the shaders were composed with
    /// (`weft_meta::ENGINE_INTERFACE_VERSION`, currently 2).
    pub engine_interface_version: u32,
    /// Scene name: the manifest's file name before `.scene.toml`.
    pub name: String,
    /// What the scene shows; absent when the manifest says nothing.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub description: Option<String>,
    /// Hash of every input (scene file, materials, toolchain version).
    pub inputs_hash: String,
    /// Engine features the scene provides; shaders were specialised for exactly these.
    pub features: SceneFeatures,
    /// Camera for previews and tests.
    pub camera: SceneCamera,
    /// The main light weft draws the scene with: the manifest's `[light]`,
    /// else weft's default light (`weft_meta::scene::DEFAULT_LIGHT_DIRECTION`
    /// and `DEFAULT_LIGHT_COLOR`). Always written since schema 3.3 (absent in
    /// older files: read it as that default light). With
    /// `features.directional_lights` 0 no shader reads it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub light: Option<SceneLight>,
    /// Lighting folded into every shader of the scene (the manifest's
    /// `[static_lighting]`, scene schema 3.7). Present, the shaders read
    /// neither `weft_frame.light_direction` nor `light_color` (they hold
    /// `light`) nor, with `sh`, `weft_frame.sh`: set the frame to these
    /// values (a generic variant drawn beside them still reads it); changing
    /// them at run time changes nothing in this scene. Absent: the engine
    /// lights the scene at run time.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub static_lighting: Option<StaticLighting>,
    /// Unique specialised shaders, in first-use order.
    pub shaders: Vec<SceneShader>,
    /// Instances in manifest order (draw them by pass queue, then this order).
    pub instances: Vec<SceneInstance>,
    /// Per emitted language: the coordinate conventions to draw its files
    /// with (as in the material metadata).
    pub languages: std::collections::BTreeMap<String, crate::LanguageConventions>,
    /// WebGPU device limits above the defaults that the scene's materials declare
    /// (for each limit, the highest): request at least these when creating the device.
    /// Absent when every shader fits WebGPU's default limits.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub limits: Option<crate::DeviceLimits>,
    /// What an engine does as weft's renderer does beyond bindings and
    /// pipeline states (as in the material metadata). Written since schema
    /// 3.3; absent in older files (read it as
    /// `weft_meta::Conventions::current()`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub conventions: Option<crate::Conventions>,
    /// The built-in meshes the instances draw (`instances[].mesh`), by
    /// name: the file with the exact vertex data weft draws. Written since
    /// schema 3.3; absent (empty) in older files.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub meshes: BTreeMap<String, SceneMesh>,
    /// Material variants (glTF `KHR_materials_variants`; schema 3.4): per
    /// variant name, the instances drawn in place of others while it is
    /// shown — keyed by the name of the instance each replaces (in
    /// `instances`). Their shaders are in `shaders`. Absent when none.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub variants: BTreeMap<String, BTreeMap<String, SceneInstance>>,
    /// What the scene needs, step by step (schema 3.5): from the glTF's
    /// materials to the unique shaders the folder carries. Absent in older files.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub funnel: Option<SceneFunnel>,
}

/// A mesh's file (`weft_meta::mesh`): exactly one of `path` (a built-in
/// mesh, in the library) and `file` (a mesh the scene carries, from glTF).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SceneMesh {
    /// A built-in mesh: relative to the library root (two folders above
    /// the scene metadata), `meshes/<name>.mesh`, written by `cargo xtask
    /// regenerate`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub path: Option<String>,
    /// A mesh read from a glTF file (schema 3.4): relative to the scene
    /// folder (the folder holding `<scene>.scene.json`), `meshes/<name>.mesh`,
    /// written by the scene build.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<String>,
    /// The largest distance of a vertex from the mesh's origin, in object
    /// space (for near/far planes and culling). Written for meshes in the
    /// scene folder (schema 3.4); every built-in mesh lies within √2.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<f64>,
    /// The file's layout: `weft_mesh_v1` (`weft_meta::mesh::MESH_FORMAT`:
    /// a 24-byte header, the six vertex streams of the engine interface in
    /// location order, u32 indices; all little-endian; docs/engine-interface.md).
    pub format: String,
}

/// The engine features a scene provides. Engine interface v1: group 0 is
/// always bound in full; a feature that is off is never read by the scene's shaders.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SceneFeatures {
    /// Prefiltered environment cube (specular image-based lighting).
    pub environment: bool,
    /// L2 spherical-harmonic ambient (diffuse image-based lighting).
    pub sh_ambient: bool,
    /// Directional lights (0 or 1 in engine interface v1).
    pub directional_lights: u32,
}

/// The lighting a scene's shaders hold as constants (`[static_lighting]`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct StaticLighting {
    /// The SH ambient's nine RGB coefficients folded in (`weft_frame.sh[i].xyz`,
    /// docs/engine-interface.md "SH"); absent when the scene has no SH ambient.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sh: Option<[[f64; 3]; 9]>,
}

/// The camera for previews and tests: perspective, +y up.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SceneCamera {
    /// Eye position in world space.
    pub position: [f64; 3],
    /// The world-space point looked at.
    pub target: [f64; 3],
    /// Vertical field of view in degrees, in (0, 180).
    pub fov_degrees: f64,
}

/// The main directional light: `weft_frame.light_direction` (normalised)
/// and `weft_frame.light_color`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SceneLight {
    /// From the surface towards the light, world space (normalise it).
    pub direction: [f64; 3],
    /// Linear radiance (`weft_frame.light_color`). Always written since
    /// schema 3.3; absent in older files: read it as
    /// `weft_meta::scene::DEFAULT_LIGHT_COLOR`, (3.2, 3.05, 2.8).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub color: Option<[f64; 3]>,
}

impl SceneLight {
    /// A light with the defaults filled in: [`DEFAULT_LIGHT_DIRECTION`]
    /// without a direction, [`DEFAULT_LIGHT_COLOR`] without a colour. What
    /// the compiler writes (`color` always set) and what a reader of a file
    /// older than 3.3 uses.
    pub fn with_defaults(direction: Option<[f64; 3]>, color: Option<[f64; 3]>) -> SceneLight {
        SceneLight {
            direction: direction.unwrap_or(DEFAULT_LIGHT_DIRECTION),
            color: Some(color.unwrap_or(DEFAULT_LIGHT_COLOR)),
        }
    }
}

impl SceneMetadata {
    /// Every instance built: those drawn (`instances`), then every material
    /// variant's stand-ins (`variants`, by variant then replaced name).
    pub fn built_instances(&self) -> impl Iterator<Item = &SceneInstance> {
        self.instances
            .iter()
            .chain(self.variants.values().flat_map(|v| v.values()))
    }

    /// The scene as drawn while material variant `name` is shown: each
    /// instance the variant replaces swapped, in place, for its stand-in
    /// (`variants`). An unknown name is an error listing the variants.
    pub fn showing_variant(&self, name: &str) -> Result<SceneMetadata, String> {
        let Some(stand_ins) = self.variants.get(name) else {
            let known: Vec<&str> = self.variants.keys().map(String::as_str).collect();
            return Err(if known.is_empty() {
                format!(
                    "scene `{}` has no material variants (glTF KHR_materials_variants)",
                    self.name
                )
            } else {
                format!(
                    "scene `{}` has no material variant `{name}`; its variants: {}",
                    self.name,
                    known.join(", ")
                )
            });
        };
        let mut out = self.clone();
        for inst in &mut out.instances {
            if let Some(stand_in) = stand_ins.get(&inst.name) {
                *inst = stand_in.clone();
            }
        }
        Ok(out)
    }

    /// The light the scene is drawn with: `light`, completed with the
    /// defaults where a file older than schema 3.3 left them out.
    pub fn light_used(&self) -> SceneLight {
        match &self.light {
            Some(l) => SceneLight::with_defaults(Some(l.direction), l.color),
            None => SceneLight::with_defaults(None, None),
        }
    }
}

/// One specialised shader.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SceneShader {
    /// `<material>.<first 12 hex digits of the WGSL's SHA-256>` (taken over
    /// the WGSL and the instance's `sampler` state when it sets one); also
    /// the file stem.
    pub id: String,
    /// Name of the material the shader was built from.
    pub material: String,
    /// The library variant this shader specialises (tier and keywords).
    pub variant: String,
    /// Files, entry points, bindings, the shrunk material uniform, vertex inputs.
    pub shader: VariantShader,
}

/// One drawable instance.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SceneInstance {
    /// Instance name, unique in the scene.
    pub name: String,
    /// Name of the instance's material.
    pub material: String,
    /// The material preset the instance's values start from; absent when none.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preset: Option<String>,
    /// The tier built (after [`AUTO_TIER`] was decided).
    #[cfg_attr(feature = "schema", schemars(description = crate::names::tier_built_description()))]
    pub tier: String,
    /// Every keyword's value (static and constant mode).
    pub keywords: BTreeMap<String, String>,
    /// The library variant id with the same tier and static keywords (the
    /// generic shader this instance specialises).
    pub variant: String,
    /// Id of the entry of [`SceneMetadata::shaders`] to draw with.
    pub shader: String,
    /// Parameter values folded into the shader as literals (as uploaded:
    /// colours linear), by parameter name; a texture's folded tiling by its
    /// uniform member's name (`<texture>_st`: scale xy, offset zw). Curves
    /// and gradients are never folded: they stay in the uniform / ramp
    /// texture and are listed in `uniform_values`.
    pub constants: BTreeMap<String, serde_json::Value>,
    /// Parameters the engine may still change at run time, in manifest order.
    pub dynamic: Vec<String>,
    /// Initial bytes of the material uniform by member: what to upload at
    /// the shader's `material_uniform` offsets (colours linear; curves as
    /// their baked samples; booleans as 0/1).
    pub uniform_values: BTreeMap<String, serde_json::Value>,
    /// Material textures still bound, by binding name.
    pub textures: BTreeMap<String, SceneTexture>,
    /// Passes with their render state, in the material's order.
    pub passes: Vec<Pass>,
    /// The built-in mesh to draw: one of [`BUILTIN_MESHES`].
    #[cfg_attr(feature = "schema", schemars(description = crate::names::mesh_description()))]
    pub mesh: String,
    /// Placement in world space (`transform.model` is the matrix to use).
    pub transform: SceneTransform,
    /// How `tier = "auto"` ([`AUTO_TIER`]) was decided; absent for a tier named in the manifest.
    #[cfg_attr(feature = "schema", schemars(description = crate::names::tier_choice_description()))]
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tier_choice: Option<TierChoice>,
}

/// The build's funnel: how much of the source the scene keeps. Generic
/// variants against unique shaders is what specialisation saves in count;
/// `modelled` what it saves in GPU cost, when the build was asked to model
/// it (`weft build --scene … --gpu-model`; per instance in
/// `generated/reports/scenes.md` for the shipped scenes).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SceneFunnel {
    /// The glTF file the instances came from (as the manifest names it);
    /// absent for a scene written by hand.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gltf_file: Option<String>,
    /// Materials in the glTF file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gltf_materials: Option<usize>,
    /// glTF materials the scene's nodes draw with (material variants included).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gltf_materials_used: Option<usize>,
    /// Instances, material variants' stand-ins included.
    pub instances: usize,
    /// Distinct library variants the instances would draw with unspecialised.
    pub generic_variants: usize,
    /// Unique specialised shaders the scene folder carries.
    pub shaders: usize,
    /// Bytes of the shader files (every language) the scene folder carries.
    pub shader_bytes: u64,
    /// Per GPU family, the instances' fragment cost with their specialised
    /// shaders against their generic variants, from AMD's shader compiler
    /// on Mesa RADV's null device (docs/performance.md); empty unless the
    /// build was asked (`--gpu-model`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub modelled: Vec<FunnelModel>,
}

/// What specialising saves on one GPU family, summed over the scene's
/// instances (material variants' stand-ins included; each instance counts
/// once, whatever its size on screen) and the passes each draws, fragment
/// stage.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct FunnelModel {
    /// weft's name of the family (`navi21`: RDNA2, `gfx1100`: RDNA3, which
    /// Mesa after 22.3 calls `navi31`).
    pub family: String,
    /// The compiler that produced the figures (RADV's driver string, e.g.
    /// `Mesa 22.3.6`): figures move with it.
    pub driver: String,
    /// Loop-aware executed cost (docs/performance.md) with the generic variants.
    pub generic_cost: f64,
    /// The same with the scene's specialised shaders.
    pub specialised_cost: f64,
    /// Static instructions with the generic variants.
    pub generic_instructions: u64,
    /// Static instructions with the specialised shaders.
    pub specialised_instructions: u64,
    /// 100 × (1 − specialised / generic) of the executed cost, rounded to 0.1.
    pub cost_saving_percent: f64,
}

/// A texture to bind for a material texture binding.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SceneTexture {
    /// The material parameter (`texture2d`, `cube` or `gradient`) this texture carries.
    pub parameter: String,
    /// A built-in 1x1 texture (the parameter's default, read at run time
    /// because the parameter is `dynamic`; with `file`, what an engine that
    /// cannot load the file binds instead).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub builtin: Option<TextureDefault>,
    /// An image to bind: the instance's own (a scene image, docs/scenes.md
    /// "Images": `textures/<hash>.rgba8`) or, for a texture parameter left
    /// unset, the image its material ships (`file` in the material's TOML:
    /// `<material>/<parameter>.rgba8`). Read `path` relative to the scene
    /// folder first (a scene folder holds every file it binds); a material's
    /// image is also at the same path under the library root, two folders
    /// above the scene metadata in a project build.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub file: Option<crate::ResourceFile>,
    /// For gradients: the baked ramp, RGBA8 sRGB-encoded, row-major (`width` x 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ramp_rgba8: Option<Vec<u8>>,
    /// sRGB-encoded texels (sample through an sRGB view).
    pub srgb: bool,
}

/// An instance's placement in world space: `model` = translation × rotation (Z · Y · X) ×
/// scale.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct SceneTransform {
    /// World-space position of the object's origin (x, y, z).
    pub translation: [f64; 3],
    /// Degrees, applied X then Y then Z.
    pub rotation_degrees: [f64; 3],
    /// Scale along the object's x, y and z axes (each > 0), applied before rotation.
    pub scale: [f64; 3],
    /// Object -> world, column-major (the engine interface's `weft_object.model`).
    pub model: [f32; 16],
}

/// The record of an automatic tier choice.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct TierChoice {
    /// The largest mean FLIP against the reference tier the choice may accept, in (0, 1].
    pub error_budget: f64,
    /// The instance's size on screen in pixels: the tiers were rendered at `screen_size` ×
    /// `screen_size` for the choice.
    pub screen_size: u32,
    /// Where the costs came from: the GPU model (`gpu-model.json`, with the
    /// family and driver) or the `--tier-costs` file.
    pub cost_source: String,
    /// The GPU family the costs model (`[scene] gpu_family`); absent when the
    /// costs came from a `--tier-costs` file.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gpu_family: Option<String>,
    /// Every candidate tier with its figures, cheapest first.
    pub candidates: Vec<TierCandidate>,
}

/// One tier considered by an automatic choice.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct TierCandidate {
    /// The tier's name.
    pub tier: String,
    /// Cost: the GPU model's executed cost of the variant the instance's
    /// keywords select, divided by `standard` `fast`'s, or the `--tier-costs`
    /// figure (any unit; only ratios within a material matter).
    pub cost: f64,
    /// The GPU model's figures for that variant (fragment stages of its
    /// passes together); absent with `--tier-costs`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gpu: Option<TierGpuFigures>,
    /// FLIP mean against the reference tier at the instance's values, mesh and screen size.
    pub flip_mean: f64,
    /// Whether `flip_mean` ≤ `error_budget` (the reference tier always is); the first candidate
    /// within budget is chosen.
    pub within_budget: bool,
}

/// A candidate tier's figures from AMD's shader compiler (the GPU model).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct TierGpuFigures {
    /// ISA instructions (each counted once), summed over the passes.
    pub instructions: u64,
    /// Vector registers per lane (the most of any pass).
    pub vgprs: u64,
    /// Waves per SIMD the registers allow (the fewest of any pass).
    pub waves: u64,
    /// Modelled executed cost: ISA blocks weighted and multiplied by the trip
    /// counts of the loops around them (docs/performance.md).
    pub executed_cost: f64,
}

#[cfg(feature = "schema")]
/// The JSON Schema of [`SceneMetadata`], pretty-printed.
pub fn scene_metadata_json_schema() -> String {
    let schema = schemars::schema_for!(SceneMetadata);
    let mut s = serde_json::to_string_pretty(&schema).expect("schema serialises");
    s.push('\n');
    s
}
