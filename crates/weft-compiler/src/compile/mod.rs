//! The compile stages, in pipeline order: nothing here writes a file or
//! reads a cache. A checked material goes in, validated shader variants and
//! metadata come out (`material.rs` runs the stages over one material).
//!
//! [`prelude`] (uniforms, bindings, keywords from the TOML) → [`compose`] (one
//! WGSL module + source map; [`nesting`] bounds its depth) → naga parse +
//! validate once → per variant ([`variant`]) [`specialise`] (bake keywords
//! and tier, drop dead branches, compact; [`half`] for `low` tiers) →
//! validate → [`backends`] (WGSL, SPIR-V, HLSL with [`hlsl_samplers`] and
//! [`hlsl_select`], GLSL, MSL) → [`reflect`] (bindings and layouts from the
//! specialised module; [`stage_io`], [`engine_binding`]) → [`limits`] →
//! [`metadata`]. [`tables`] and [`texture_files`] give the material's data
//! files.
//!
//! Invariant: no module here names `crate::build` (the plumbing depends on
//! the stages, never the reverse; a unit test in `lib.rs` holds it).

pub mod backends;
pub mod compose;
pub mod digest;
pub mod engine_binding;
pub mod half;
pub mod hlsl_samplers;
pub mod hlsl_select;
pub mod limits;
pub mod material;
pub mod metadata;
pub mod nesting;
pub mod prelude;
pub mod reflect;
pub mod source_map;
pub mod specialise;
pub mod stage_io;
pub mod tables;
pub mod texture_files;
pub mod variant;
