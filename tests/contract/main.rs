//! The output contract: what engines, compilers and browsers that load weft's
//! output must accept. The committed `generated/` tree is current and
//! deterministic, every HLSL entry point compiles in Slang, DXC and FXC, every
//! WGSL module in Chromium's WebGPU, and a second engine written from the
//! metadata alone (`engine/`, driven by `harness`) draws what weft draws.

mod build_outputs;
mod conventions;
mod engine;
mod half_precision;
mod harness;
mod hlsl;
mod hlsl_compilers;
mod hlsl_d3d;
mod independent_engine;
mod metadata_contract;
mod readme;
mod texture_files;
mod tint;
