//! The bench figures attached to a material's metadata at load time
//! (`generated/reports/<name>.measurements.json`; feature `measurements`).

#[cfg(feature = "schema")]
use crate::names;
#[cfg(feature = "schema")]
use schemars::JsonSchema;
use serde::{Deserialize, Serialize};

/// Shading cost and accuracy of a material's tiers, measured by
/// `cargo xtask bench shading` / `weft bench` on one adapter. This is the
/// content of `generated/reports/<name>.measurements.json`; timings vary by machine.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct Measurements {
    /// The material measured.
    pub material: String,
    /// The metadata's `inputs_hash` when measured: a different current hash
    /// means the figures belong to an earlier version of the material.
    pub inputs_hash: String,
    /// The adapter the figures were measured on (name, driver, backend, type).
    pub adapter: String,
    /// `gpu-timestamp` (timestamp queries around the render pass) or
    /// `cpu-wall` (submit to completion on the CPU: the adapter has no timestamp queries).
    pub timer: String,
    /// Width of the render target the figures were measured at, in pixels.
    pub width: u32,
    /// Height of the render target the figures were measured at, in pixels.
    pub height: u32,
    /// The built-in mesh the figures were measured on (one of [`BUILTIN_MESHES`](crate::BUILTIN_MESHES)).
    #[cfg_attr(feature = "schema", schemars(description = names::measured_mesh_description()))]
    pub scene: String,
    /// Keywords and parameters: the material's defaults unless stated here.
    pub setup: String,
    /// One entry per tier, in the material's tier order.
    pub tiers: Vec<TierMeasurement>,
}

/// One tier of [`Measurements`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct TierMeasurement {
    /// The tier measured (one of the material's `tiers.values`).
    pub tier: String,
    /// The canonical variant drawn.
    pub variant: String,
    /// Timed frames (after warm-up; fewer than asked for when the tier's
    /// frames would exceed the per-tier time budget).
    pub frames: u32,
    /// Median GPU time of the frame's render pass (clear + the material's draws), ms.
    pub gpu_ms: f64,
    /// Fastest frame, ms (least disturbed by other work on a shared machine).
    pub gpu_ms_min: f64,
    /// (90th − 10th percentile) / median of the frame times: run-to-run noise.
    pub gpu_ms_spread: f64,
    /// `gpu_ms` over that of `standard`'s `fast` tier (default keywords) in
    /// the same run; absent when `standard` was not measured.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ratio_to_standard_fast: Option<f64>,
    /// Instructions in the variant's SPIR-V module (static cost).
    pub spirv_instructions: u32,
    /// Of those, the instructions of the functions the fragment entry point reaches.
    pub spirv_fragment_instructions: u32,
    /// FLIP against the reference tier's image (ACES tone-mapped, sRGB8), mean over object pixels.
    pub flip_mean: f64,
    /// 99th percentile of the per-pixel FLIP over object pixels.
    pub flip_p99: f64,
    /// sqrt(Σ(a−b)² / Σb²) over the RGB of object pixels of the linear HDR images, b the reference.
    pub rel_rmse: f64,
    /// What the tier is: `reference`, `approximation` (its error is an
    /// approximation error) or `look` (a different model: its difference is
    /// not an error).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub kind: Option<String>,
    /// The error grid (every preset and the defaults × sphere and cloth ×
    /// three light directions, one a grazing rim light), FLIP mean against
    /// the reference per cell: the worst cell. Absent for the reference.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flip_worst: Option<f64>,
    /// The mean over the error grid's cells.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flip_grid_mean: Option<f64>,
    /// The worst cell, as `preset/scene/light`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub flip_worst_cell: Option<String>,
    /// Cells of the error grid this tier was measured in.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub grid_cells: Option<u32>,
    /// A half-precision variant drawn from its f16 files (the figures
    /// above) is timed from its portable f32 files too, in the same run:
    /// what an engine without `shader-f16` pays. Absent for other variants
    /// and on adapters without `shader-f16`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub f32_files: Option<F32FilesCost>,
}

/// The cost of a half-precision variant's f32 files ([`TierMeasurement::f32_files`]).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "schema", derive(JsonSchema))]
pub struct F32FilesCost {
    /// Median GPU time of the frame's render pass, ms.
    pub gpu_ms: f64,
    /// `gpu_ms` over that of `standard`'s `fast` tier in the same run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ratio_to_standard_fast: Option<f64>,
}
