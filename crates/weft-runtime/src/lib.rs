//! The CPU half of weft's runtime: what drawing a material or a scene needs
//! before a GPU is involved, read from the metadata alone. weft-render (the
//! wgpu half) draws with it; the inspector server (weft-serve), which bakes
//! the same sky and previews on the CPU and in the browser, links only this.
//!
//! - [`material`]: a material loaded from `<name>.meta.json`: variant
//!   selection, parameter [`values`], presets, keywords; [`uniform`] packs
//!   its uniform bytes by the metadata's layout; [`texture_files`] reads the
//!   texture files it lists; [`scene_library`] sets a scene instance's values
//!   on a library material (the comparison path of folding).
//! - [`environment`]: the procedural sky, its GGX-prefiltered cube and SH;
//!   [`luts`]: the engine LUTs a build writes.
//! - [`scene`]: built-in scenes (cameras, lights, meshes; [`bust`] the
//!   character bust); [`image`]: linear HDR images, tone mapping, PNG;
//!   [`math`]: the small vector maths they share; [`error`]: one error type.
//!
//! Invariant: no wgpu, no naga — `cargo tree -p weft-runtime -e normal`
//! shows neither.

pub mod bust;
pub mod environment;
pub mod error;
pub mod image;
pub mod luts;
pub mod material;
pub mod math;
pub mod mesh;
pub mod scene;
pub mod scene_library;
pub mod texture_files;
pub mod uniform;
pub mod values;

pub use bust::{
    BustPart, EYE_CENTRES, EYE_RADIUS, HAIR_END, HEAD_CENTRE, HEAD_JAW, HEAD_RADII, bust_parts,
    whole_bust,
};
pub use environment::{
    CubeLevel, EnvironmentMaps, MipRoughness, SkyParams, cube_direction, cube_face_uv, project_sh,
    sh_basis, texel_solid_angle,
};
pub use error::{Error, NO_ADAPTER_HINT, Result};
pub use image::{HdrImage, MAX_TEXTURE_SIZE, Tonemap, decode_png, encode_png, encode_srgb};
pub use luts::{BrdfLut, Luts, SHEEN_LUT_FILE, SPLIT_SUM_LUT_FILE, SheenLut};
pub use material::{Material, ResolvedVariant};
pub use scene::{Camera, Light, Mesh, Scene, SceneKind, lit};
pub use scene_library::configure_instance_material;
pub use uniform::pack_uniform_values;
pub use values::{
    CurveValue, StoredValue, TextureValue, Value, bake_gradient, eval_curve, linear_to_srgb,
    sample_curve, srgb_to_linear,
};
pub use weft_meta;
