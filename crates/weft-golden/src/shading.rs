//! The shading benchmark: for every material × tier, in one run on one
//! adapter, the GPU time of a frame (timestamp queries; CPU wall time when
//! the adapter has none), its ratio to `standard`'s `fast` tier, the SPIR-V
//! instruction count of the variant and its error against the material's
//! reference tier (FLIP on the ACES tone-mapped image, relative RMSE on the
//! linear HDR image, both over object pixels).
//!
//! Shared by `cargo xtask bench shading`, `cargo xtask regenerate --reports`
//! and `weft bench`. Reports go to `generated/reports/`: `shading.md`, and per
//! material `<name>.measurements.json` ([`weft_meta::Measurements`], which
//! inspectors attach to the metadata) and `<name>.pareto.svg`.

mod measure;
mod report;
mod spirv;
#[cfg(test)]
mod tests;

// The error measure is the `auto` chooser's (weft-auto), written once.
pub use measure::run;
pub(crate) use report::cost_cell;
pub use report::{
    describe, floor_line, markdown_report, markdown_table, replace_marked, write_reports,
};
pub use spirv::spirv_instruction_counts;
pub use weft_auto::image_error::{ImageError, flip_map, image_error, quantile};

use std::path::{Path, PathBuf};
use weft_meta::Measurements;
use weft_render::{FrameTimer, SceneKind};

/// The cost every tier is compared with: `standard`'s `fast` tier.
pub const BASELINE_MATERIAL: &str = "standard";
pub const BASELINE_TIER: &str = "fast";

/// What the benchmark draws and how long it times.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadingOptions {
    /// Square image size in pixels.
    pub size: u32,
    pub scene: SceneKind,
    /// Untimed frames per tier before the first timed one.
    pub warmup: u32,
    /// Timed frames per tier (the median is reported).
    pub frames: u32,
    /// The timed frames are taken in this many rounds over all tiers, so
    /// that a change in machine load affects every tier alike.
    pub rounds: u32,
    /// Time with the CPU even when the adapter has timestamp queries.
    pub force_cpu_timer: bool,
    /// A tier whose `frames` would take longer than this (estimated from a
    /// probe frame) gets fewer, but at least `rounds` and at least 5.
    pub max_seconds_per_tier: f64,
    /// Materials to measure (empty: every material under the generated folder).
    pub materials: Vec<String>,
    /// Each tier's error over presets × scenes × lights
    /// ([`crate::error_grid`]); None measures only at the defaults.
    pub grid: Option<crate::error_grid::GridOptions>,
    /// Also time the cost floor, an unlit fill ([`crate::floor`]) built
    /// against this materials folder's `lib/`.
    pub floor: Option<PathBuf>,
}

impl Default for ShadingOptions {
    fn default() -> Self {
        ShadingOptions {
            size: 512,
            scene: SceneKind::Sphere,
            warmup: 5,
            frames: 50,
            rounds: 10,
            force_cpu_timer: false,
            max_seconds_per_tier: 20.0,
            materials: Vec::new(),
            grid: Some(crate::error_grid::GridOptions::default()),
            floor: None,
        }
    }
}

/// The result of [`run`].
#[derive(Clone, Debug)]
pub struct ShadingReport {
    pub adapter: String,
    pub timer: FrameTimer,
    pub options: ShadingOptions,
    /// One entry per measured material, sorted by name.
    pub materials: Vec<Measurements>,
    /// Wall time of the whole run, seconds.
    pub seconds: f64,
    /// Median frame time of the unlit fill ([`ShadingOptions::floor`]), ms.
    pub floor_ms: Option<f64>,
}

/// What every report says about the setup.
const SETUP: &str = "the material's default keyword and parameter values; no background (cleared to transparent black, so the pass holds the clear and the material's draws); Rgba16Float target; WGSL variants; errors over object pixels (those the material drew)";
