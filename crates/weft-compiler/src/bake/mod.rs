//! Lookup tables the toolchain computes at build time (pure Rust, deterministic),
//! written under `generated/luts/` and bound through the engine interface.

pub mod film;
pub mod sheen;
pub mod skin;
pub mod split_sum;
