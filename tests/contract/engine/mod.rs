//! A second, independent consumer of weft's output: an "engine" that binds
//! and draws every pass of a library variant or a scene shader from the
//! metadata alone, as docs/engine-interface.md describes it.
//!
//! It links what an engine links — `weft_meta` (the metadata types),
//! `serde_json` and raw `wgpu` (Vulkan) — and nothing from `weft-render`,
//! `weft-compiler` or `weft-front`. Shader files are handed to wgpu as they
//! are (WGSL text, or SPIR-V words through wgpu's passthrough path); nothing
//! is read out of them. Everything the contract leaves to the engine (its
//! meshes, camera, light and environment) comes in as plain arrays
//! ([`data`]), so the test harness may take them from anywhere.
//!
//! Shared by `tests/contract/independent_engine.rs` and `tests/contract/conventions.rs` with
//! `#[path = "support/engine/mod.rs"] mod engine;`.

#![allow(dead_code)]

pub mod data;
pub mod device;
pub mod draw;
pub mod formats;
pub mod library;
pub mod pipeline;
pub mod uniforms;

// Each test file uses some of these.
#[allow(unused_imports)]
pub use data::{Environment, FrameInputs, Image, Mesh};
pub use device::Engine;
#[allow(unused_imports)]
pub use draw::{DrawItem, World};
#[allow(unused_imports)]
pub use library::{Library, ShaderRef};
pub use pipeline::Language;
