//! `tier = "auto"` for scene instances: the [`chooser`] the scene build
//! calls (through weft-compiler's `TierChooser`) from `weft build --scene`,
//! `weft preview --scene-file` and `cargo xtask regenerate`, and the
//! [`image_error`] it ranks tiers by — the same FLIP-over-object-pixels
//! measure the benches and the scene tests use (weft-golden re-exports it).
//!
//! A product feature, so it lives apart from the test and bench crate
//! weft-golden: the `weft` binary links this for `auto` tiers.

pub mod chooser;
pub mod image_error;

pub use chooser::{LavapipeTierChooser, describe_choice};
pub use image_error::{ImageError, TONEMAP, flip_map, image_error, quantile, to_ldr};
