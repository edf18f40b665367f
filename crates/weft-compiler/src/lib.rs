//! weft compiler: a checked material -> validated shader variants in every
//! language, plus inspector metadata.
//!
//! Pipeline (one way): [`prelude`] (uniforms/bindings/keywords from the TOML)
//! -> [`compose`] (one WGSL module + source map) -> naga parse + validate once
//! -> per variant [`specialise`] (bake keywords and tier, drop dead branches,
//! compact) -> validate -> [`backends`] -> [`reflect`] (metadata from the
//! specialised module itself). [`library`] runs that over a materials folder
//! and [`output`] writes the result atomically. This is also the API for
//! `build.rs` scripts: see [`library::build_library`].

pub mod backends;
pub mod bake;
pub mod cache;
pub mod compose;
pub mod engine_binding;
pub mod folder_build;
pub mod half;
pub mod hlsl_samplers;
pub mod hlsl_select;
pub mod in_memory;
pub mod library;
pub mod limits;
pub mod metadata;
pub mod nesting;
pub mod output;
pub mod ownership;
pub mod prelude;
pub mod reflect;
pub mod scene;
pub mod shard;
pub mod specialise;
pub mod stage_io;
pub mod staging;
pub mod stamp;
pub mod tables;
pub mod texture_files;
pub mod unchanged;
pub mod variant;

pub use in_memory::{InMemoryBuild, compile_in_memory};
pub use library::{
    BuildOptions, BuildOutput, build_library, build_materials, build_materials_streaming,
    compile_material,
};
pub use scene::{MAX_SCENE_SHADERS, SceneBuildOptions, SceneOutput, build_scene};
