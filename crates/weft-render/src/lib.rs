//! weft render runtime: draws generated material variants through wgpu from
//! their metadata alone (`<name>.meta.json` plus the files it lists).
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
//! Conventions: world +Y up, right-handed, counter-clockwise front faces,
//! WebGPU clip space. The environment cube's mip m holds GGX-prefiltered
//! radiance for the roughness that `weft_specular_mip` (lighting.wgsl) maps
//! to m (see [`MipRoughness`]). Output is linear HDR ([`HdrImage`]); tone
//! mapping happens on the CPU.

mod environment;
mod error;
mod gpu;
mod image;
mod material;
pub mod math;
mod preview;
pub mod probe;
mod renderer;
mod scene;
mod timing;

pub use environment::{
    BrdfLut, CubeLevel, EnvironmentMaps, Luts, MipRoughness, SHEEN_LUT_FILE, SPLIT_SUM_LUT_FILE,
    SheenLut, SkyParams, cube_direction, cube_face_uv, project_sh, sh_basis, texel_solid_angle,
};
pub use error::{Error, NO_ADAPTER_HINT, Result};
pub use gpu::Gpu;
pub use image::{HdrImage, Tonemap, encode_png, encode_srgb};
pub use material::{
    CurveValue, Material, ResolvedVariant, StoredValue, TextureValue, Value, bake_gradient,
    eval_curve, linear_to_srgb, sample_curve, srgb_to_linear,
};
pub use preview::{MaterialOptions, PreviewOptions, render_preview};
pub use renderer::{
    Background, ColorFormat, PreparedMaterial, RenderOptions, Renderer, ShaderLanguage, Tile,
};
pub use scene::{Camera, Light, Mesh, Scene, SceneKind};
pub use timing::{FrameTimer, FrameTimes, TimingOptions};
pub use weft_meta;
pub use wgpu;
