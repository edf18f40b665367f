//! weft render runtime: draws generated material variants and built scenes
//! through wgpu from their metadata alone (`<name>.meta.json` or
//! `<scene>.scene.json` plus the files it lists).
//!
//! ```no_run
//! use weft_render::*;
//! let mut material = Material::load("generated/standard/standard.meta.json")?;
//! material.apply_preset("gold")?;
//! material.set("roughness", 0.3)?;
//! let luts = Luts::for_metadata("generated/standard/standard.meta.json")?;
//! let mut renderer = Renderer::new(Gpu::new()?, &EnvironmentMaps::sky(&SkyParams::default()), &luts)?;
//! let image = renderer.render(&material, &Scene::sphere(), &RenderOptions::default())?;
//! image.save_png("sphere.png", Tonemap::Aces, 1.0)?;
//! # Ok::<(), weft_render::Error>(())
//! ```
//!
//! A built scene (`weft build --scene`) is drawn from its `.scene.json`
//! alone, every instance with its specialised shader; the same scene drawn
//! with the library's generic variants ([`SceneShaders::Library`]) is the
//! comparison:
//!
//! ```no_run
//! use weft_render::*;
//! let scene = SceneFile::load("generated/scenes/fitting_room/fitting_room.scene.json")?;
//! let luts = Luts::for_scene(&scene.path)?;
//! let mut renderer = Renderer::new(Gpu::new()?, &EnvironmentMaps::sky(&SkyParams::default()), &luts)?;
//! let options = RenderOptions::default();
//! let prepared = renderer.prepare_scene(&scene, &SceneShaders::Specialised, &options)?;
//! let image = renderer.render_scene(&prepared, &options)?; // builds no pipeline
//! # Ok::<(), weft_render::Error>(())
//! ```
//!
//! Conventions: world +Y up, right-handed, counter-clockwise front faces,
//! WebGPU clip space. The environment cube's mip m holds GGX-prefiltered
//! radiance for the roughness that `weft_specular_mip` (lighting.wgsl) maps
//! to m (see [`MipRoughness`]). Output is linear HDR ([`HdrImage`]); tone
//! mapping happens on the CPU.

mod bindings;
use weft_runtime::bust;
mod draw;
mod engine_uniforms;
use weft_runtime::environment;
use weft_runtime::error;
mod gpu;
use weft_runtime::image;
use weft_runtime::luts;
use weft_runtime::material;
pub use weft_runtime::math;
pub use weft_runtime::mesh;
mod mesh_files;
mod meta_wgpu;
mod pipelines;
mod preview;
pub mod probe;
mod renderer;
mod resources;
use weft_runtime::scene;
mod scene_draw;
mod targets;
use weft_runtime::scene_library;
use weft_runtime::texture_files;
mod timing;
use weft_runtime::uniform;
use weft_runtime::values;

pub use bust::{
    BustPart, EYE_CENTRES, EYE_RADIUS, HAIR_END, HEAD_CENTRE, HEAD_JAW, HEAD_RADII, bust_parts,
};
pub use environment::{
    CubeLevel, EnvironmentMaps, MipRoughness, SkyParams, cube_direction, cube_face_uv, project_sh,
    sh_basis, texel_solid_angle,
};
pub use error::{Error, NO_ADAPTER_HINT, Result};
pub use gpu::{ADAPTER_VARIABLE, AdapterChoice, Gpu};
pub use image::{HdrImage, MAX_TEXTURE_SIZE, Tonemap, decode_png, encode_png, encode_srgb};
pub use luts::{BrdfLut, Luts, SHEEN_LUT_FILE, SPLIT_SUM_LUT_FILE, SheenLut};
pub use material::{Material, ResolvedVariant};
pub use mesh_files::{builtin_mesh_files, mesh_data};
pub use preview::{MaterialOptions, PreviewOptions, render_preview, render_scene_preview};
pub use renderer::{
    Background, ColorFormat, PreparedMaterial, RenderOptions, Renderer, ShaderLanguage, Tile,
};
pub use resources::object_uniform;
pub use scene::{Camera, Light, Mesh, Scene, SceneKind};
pub use scene_draw::{
    DrawRef, PreparedScene, SceneFile, SceneLighting, SceneShaders, instance_model, scene_camera,
    scene_draw_order, scene_instance_count,
};
pub use scene_library::configure_instance_material;
pub use timing::{FrameTimer, FrameTimes, TimingOptions};
pub use uniform::pack_uniform_values;
pub use values::{
    CurveValue, StoredValue, TextureValue, Value, bake_gradient, eval_curve, linear_to_srgb,
    sample_curve, srgb_to_linear,
};
pub use weft_meta;
pub use weft_runtime;
pub use wgpu;
