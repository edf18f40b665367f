//! The scene manifest model: what `scenes/<name>.scene.toml` asks for.
//!
//! Two stages, data flowing one way:
//! - [`SceneManifest`] is the file as written (parsed and locally checked by
//!   `scene::parse`), spans kept for every value a later check may reject
//!   (parameter values are typed by `resolve` straight from the TOML tree);
//! - [`ResolvedScene`] is the manifest checked against the materials it names
//!   (`scene::resolve`): every instance has one static variant, a full set of
//!   parameter values and its `dynamic` list. The compiler only ever sees this.

use crate::diag::{FileId, Span};
use crate::model::{ParamValue, VertexAttribute};
use std::path::PathBuf;

/// Built-in meshes the runtime and the tests can draw an instance on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum BuiltinMesh {
    Sphere,
    Cloth,
    Swatch,
    /// The character bust (head, eyes, hair cards, shoulders) as one mesh.
    Bust,
    /// The bust's parts, one mesh each, so every part can have its own
    /// material (a face on the head, eyes, hair on the cards).
    BustHead,
    BustEyes,
    BustHair,
    BustShoulders,
}

impl BuiltinMesh {
    pub const ALL: [BuiltinMesh; 8] = [
        BuiltinMesh::Sphere,
        BuiltinMesh::Cloth,
        BuiltinMesh::Swatch,
        BuiltinMesh::Bust,
        BuiltinMesh::BustHead,
        BuiltinMesh::BustEyes,
        BuiltinMesh::BustHair,
        BuiltinMesh::BustShoulders,
    ];
    pub fn name(self) -> &'static str {
        match self {
            BuiltinMesh::Sphere => "sphere",
            BuiltinMesh::Cloth => "cloth",
            BuiltinMesh::Swatch => "swatch",
            BuiltinMesh::Bust => "bust",
            BuiltinMesh::BustHead => "bust.head",
            BuiltinMesh::BustEyes => "bust.eyes",
            BuiltinMesh::BustHair => "bust.hair",
            BuiltinMesh::BustShoulders => "bust.shoulders",
        }
    }
    pub fn from_name(s: &str) -> Option<BuiltinMesh> {
        Self::ALL.into_iter().find(|m| m.name() == s)
    }
}

/// An instance's mesh as written: a built-in mesh's name, or a mesh
/// primitive of a glTF file (`mesh = { gltf = "x.glb", mesh = 0, primitive = 0 }`,
/// the path relative to the manifest's folder).
#[derive(Clone, Debug, PartialEq)]
pub enum MeshSpec {
    Builtin(BuiltinMesh),
    Gltf {
        file: PathBuf,
        mesh: usize,
        primitive: usize,
        /// `uv_transform = [a, b, c, d, e, f]`: TEXCOORD_0 taken to
        /// (a u + b v + c, d u + e v + f) when the mesh is read — glTF's
        /// KHR_texture_transform with a rotation, baked (docs/gltf.md).
        uv_transform: Option<[f64; 6]>,
        /// `node = N`: the glTF node that draws the primitive, whose morph
        /// weights and skin pose it as the file shows it (docs/gltf.md,
        /// "Posed meshes"); without it, the mesh's own default state.
        node: Option<usize>,
    },
}

/// An instance's mesh once resolved: built in, or read from a glTF file
/// (the scene build writes it into the scene folder).
#[derive(Clone, Debug)]
pub enum InstanceMesh {
    Builtin(BuiltinMesh),
    File(std::sync::Arc<crate::gltf::FileMesh>),
}

impl InstanceMesh {
    /// The name the scene metadata's `instances[].mesh` and `meshes` use.
    pub fn name(&self) -> &str {
        match self {
            InstanceMesh::Builtin(m) => m.name(),
            InstanceMesh::File(f) => &f.name,
        }
    }
}

/// What the scene's renderer provides to every material (engine features).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SceneFeatures {
    /// The prefiltered environment cube (specular image-based lighting).
    pub environment: bool,
    /// L2 spherical-harmonic ambient (diffuse image-based lighting).
    pub sh_ambient: bool,
    /// Directional lights; engine interface v1 has one slot, so 0 or 1.
    pub directional_lights: u32,
}

impl Default for SceneFeatures {
    fn default() -> Self {
        SceneFeatures {
            environment: true,
            sh_ambient: true,
            directional_lights: 1,
        }
    }
}

/// `[light]`: the main directional light previews and tests draw with.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneLight {
    /// From the surface towards the light (any length but zero).
    pub direction: [f64; 3],
    /// Linear radiance; `None`: the renderer's default.
    pub color: Option<[f64; 3]>,
}

/// `[static_lighting]`: the scene's lighting is fixed, so the build folds
/// it into every shader — the main light (`[light]`, or weft's default) and,
/// with SH ambient, these coefficients (docs/scenes.md). The metadata's type:
/// the manifest's table is what the metadata states.
pub use weft_meta::scene::StaticLighting;

#[derive(Clone, Debug, PartialEq)]
pub struct Camera {
    pub position: [f64; 3],
    pub target: [f64; 3],
    pub fov_degrees: f64,
}

impl Default for Camera {
    fn default() -> Self {
        Camera {
            position: [0.0, 0.0, 3.0],
            target: [0.0, 0.0, 0.0],
            fov_degrees: 35.0,
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct Transform {
    pub translation: [f64; 3],
    /// Euler angles in degrees, applied X, then Y, then Z (R = Rz * Ry * Rx).
    pub rotation_degrees: [f64; 3],
    pub scale: [f64; 3],
    /// `matrix`: object -> world, column-major, in place of translation,
    /// rotation and scale (what a glTF node's world transform gives).
    pub matrix: Option<[f64; 16]>,
}

impl Default for Transform {
    fn default() -> Self {
        Transform {
            translation: [0.0; 3],
            rotation_degrees: [0.0; 3],
            scale: [1.0; 3],
            matrix: None,
        }
    }
}

/// A value with the span it was written at.
#[derive(Clone, Debug, PartialEq)]
pub struct Spanned<T> {
    pub value: T,
    pub span: Span,
}

/// The tier an instance asks for.
#[derive(Clone, Debug, PartialEq)]
pub enum TierRequest {
    /// The material's default tier (no `tier` key).
    Default,
    Named(String),
    /// `tier = "auto"`: the cheapest tier whose FLIP mean against the
    /// reference tier stays within `error_budget` at `screen_size` pixels.
    Auto {
        error_budget: f64,
        screen_size: u32,
    },
}

/// One `[[instances]]` entry as written.
#[derive(Clone, Debug)]
pub struct InstanceDecl {
    pub name: String,
    /// The whole `[[instances]]` table.
    pub span: Span,
    pub name_span: Span,
    pub material: Spanned<String>,
    pub preset: Option<Spanned<String>>,
    pub tier: Spanned<TierRequest>,
    /// keyword name -> value name (`true`/`false` read as `on`/`off`), in file order.
    pub keywords: Vec<(Spanned<String>, Spanned<String>)>,
    /// The `params` values are not kept here: `scene::resolve` types them
    /// against the material from the TOML tree (`scene::parse::WrittenParam`)
    /// and the result is [`ResolvedInstance::values`].
    pub dynamic: Vec<Spanned<String>>,
    pub mesh: Spanned<MeshSpec>,
    /// The mesh's vertex inputs when they differ from the scene's.
    pub vertex_inputs: Option<Spanned<Vec<VertexAttribute>>>,
    pub transform: Transform,
    /// `variant = { name, replaces }`: drawn in place of instance
    /// `replaces` when the scene shows material variant `name` (glTF
    /// `KHR_materials_variants`), not drawn otherwise.
    pub variant: Option<Spanned<InstanceVariant>>,
    /// The instance's render-state overrides (glTF `doubleSided`, `alphaMode`).
    pub overrides: InstanceOverrides,
}

/// What an instance changes in its material's render state (docs/scenes.md,
/// `double_sided`, `blend` and `sampler`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct InstanceOverrides {
    /// Passes that cull back faces draw both sides (the material shades a
    /// back face with its flipped normal).
    pub double_sided: bool,
    /// Opaque passes blend so, without depth writes, in the transparent
    /// queue (3000) when they were below it.
    pub blend: Option<weft_meta::BlendMode>,
    /// The state of the sampler the material reads its maps through.
    pub sampler: Option<SamplerOverride>,
}

/// `sampler = { … }`: the sampler a material reads its maps through
/// (`material_sampler`, trilinear and repeating) set otherwise for one
/// instance — glTF's samplers (docs/gltf.md, "Textures"). Fields left out
/// keep the material's.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SamplerOverride {
    pub address_mode_u: Option<weft_meta::AddressMode>,
    pub address_mode_v: Option<weft_meta::AddressMode>,
    pub mag_filter: Option<weft_meta::FilterMode>,
    pub min_filter: Option<weft_meta::FilterMode>,
    pub mipmap_filter: Option<weft_meta::FilterMode>,
    /// `false`: only the full-resolution level is read (`lod_max_clamp` 0;
    /// glTF's minFilter NEAREST or LINEAR).
    pub mipmaps: Option<bool>,
}

impl SamplerOverride {
    /// `sampler` with the fields this override sets.
    pub fn apply(&self, sampler: &mut weft_meta::SamplerBinding) {
        fn set<T: Copy>(field: &mut T, value: Option<T>) {
            if let Some(v) = value {
                *field = v;
            }
        }
        set(&mut sampler.address_mode_u, self.address_mode_u);
        set(&mut sampler.address_mode_v, self.address_mode_v);
        set(&mut sampler.mag_filter, self.mag_filter);
        set(&mut sampler.min_filter, self.min_filter);
        set(&mut sampler.mipmap_filter, self.mipmap_filter);
        if self.mipmaps == Some(false) {
            sampler.lod_min_clamp = 0.0;
            sampler.lod_max_clamp = 0.0;
        }
    }
}

/// A material variant's stand-in for another instance.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InstanceVariant {
    /// The variant's name (as the glTF names it).
    pub name: String,
    /// The instance this one replaces while the variant is shown.
    pub replaces: String,
}

/// The glTF file a scene's instances come from (a bare `.gltf`/`.glb`, or
/// a manifest's `[gltf]`): the first steps of the build's funnel.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GltfSource {
    /// The file as the manifest names it (relative to the manifest's folder).
    pub file: String,
    /// Materials in the file.
    pub materials: usize,
    /// Materials the scene's nodes draw with (material variants included).
    pub materials_used: usize,
}

/// `scenes/<name>.scene.toml` as written.
#[derive(Clone, Debug)]
pub struct SceneManifest {
    pub name: String,
    pub description: Option<String>,
    pub file: FileId,
    pub path: PathBuf,
    /// The materials root the instances' materials are looked up in.
    pub materials_root: PathBuf,
    pub features: SceneFeatures,
    /// Span of the `[scene]` table (features are reported there).
    pub scene_span: Span,
    pub vertex_inputs: Spanned<Vec<VertexAttribute>>,
    pub camera: Camera,
    /// The main light for previews and tests (`[light]`); the renderer's
    /// default light when absent.
    pub light: Option<SceneLight>,
    /// `[static_lighting]`: the light and SH folded into the shaders.
    pub static_lighting: Option<StaticLighting>,
    /// Fails the build when the scene needs more unique shaders.
    pub max_shaders: Option<Spanned<usize>>,
    /// The GPU family `tier = "auto"` costs tiers for (`[scene] gpu_family`).
    pub gpu_family: String,
    pub instances: Vec<InstanceDecl>,
    /// Where the instances came from when a glTF file made them.
    pub gltf: Option<GltfSource>,
}

impl SceneManifest {
    /// The main light the scene is drawn with: `[light]`, weft's default
    /// light (`weft_meta::scene`) filling in what it leaves out — what the
    /// scene metadata's `light` states and `[static_lighting]` folds.
    pub fn light_used(&self) -> weft_meta::scene::SceneLight {
        weft_meta::scene::SceneLight::with_defaults(
            self.light.as_ref().map(|l| l.direction),
            self.light.as_ref().and_then(|l| l.color),
        )
    }
}

/// How an instance's tier was chosen.
#[derive(Clone, Debug, PartialEq)]
pub enum TierChoice {
    /// Written (or the material's default).
    Fixed(usize),
    /// `auto`: chosen by the build from measurements.
    Auto { error_budget: f64, screen_size: u32 },
}

/// One instance checked against its material.
#[derive(Clone, Debug)]
pub struct ResolvedInstance {
    pub name: String,
    /// Index into [`ResolvedScene::materials`].
    pub material: usize,
    pub preset: Option<String>,
    pub tier: TierChoice,
    /// Value index of every keyword of the material (static and constant mode), in declaration order.
    pub keywords: Vec<usize>,
    /// Every parameter of the material, in declaration order: default, then
    /// preset, then the instance's own value.
    pub values: Vec<ParamValue>,
    /// Per parameter: whether the preset or the instance wrote its value.
    /// An unset texture takes its keyword-dependent default
    /// (`Param::texture_default_where`) once the tier is chosen.
    pub set: Vec<bool>,
    /// Parameters the engine still sets at run time (indices into the material's params).
    pub dynamic: Vec<usize>,
    pub dynamic_spans: Vec<Span>,
    /// `texture2d` parameters set to an image (`scene::images`), by
    /// parameter index: bound to the image, never folded.
    pub images: std::collections::BTreeMap<usize, super::images::SceneImage>,
    pub mesh: InstanceMesh,
    pub vertex_inputs: Vec<VertexAttribute>,
    /// Where the mesh's inputs are declared (scene or instance), for the compiler's check.
    pub vertex_inputs_span: Span,
    pub transform: Transform,
    /// Drawn only in place of another instance, for a material variant.
    pub variant: Option<InstanceVariant>,
    /// Render-state overrides of the material's passes.
    pub overrides: InstanceOverrides,
    /// The `[[instances]]` table, for diagnostics the compiler raises.
    pub span: Span,
    pub tier_span: Span,
}

/// A scene whose every instance resolves to a variant its material can build.
#[derive(Clone, Debug)]
pub struct ResolvedScene {
    pub manifest: SceneManifest,
    pub materials: Vec<crate::model::Material>,
    pub instances: Vec<ResolvedInstance>,
}
