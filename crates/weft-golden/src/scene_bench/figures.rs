//! The figures a run produces: A/B timings and their spread, each
//! instance's and each scene's results, the files of both ways of shipping.

use crate::shading::{ImageError, quantile};
use serde_json::json;
use weft_render::FrameTimer;

use super::SceneBenchOptions;

/// A/B timing: the per-round medians of both arms, round by round.
#[derive(Clone, Debug, PartialEq)]
pub struct AbTiming {
    pub generic: Vec<f64>,
    pub specialised: Vec<f64>,
}

/// Statistics of a series of per-round figures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spread {
    pub median: f64,
    /// (p90 − p10) / median (nearest rank).
    pub spread: f64,
    pub min: f64,
    pub max: f64,
}

impl Spread {
    pub fn of(values: &[f64]) -> Spread {
        let median = quantile(values, 0.5);
        Spread {
            median,
            spread: (quantile(values, 0.9) - quantile(values, 0.1)) / median,
            min: quantile(values, 0.0),
            max: quantile(values, 1.0),
        }
    }
}

impl AbTiming {
    pub fn generic_stats(&self) -> Spread {
        Spread::of(&self.generic)
    }

    pub fn specialised_stats(&self) -> Spread {
        Spread::of(&self.specialised)
    }

    /// Specialised median over generic median.
    pub fn ratio(&self) -> f64 {
        self.specialised_stats().median / self.generic_stats().median
    }

    /// 1 − ratio, in percent (positive: the specialised draw is faster).
    pub fn saving_pct(&self) -> f64 {
        (1.0 - self.ratio()) * 100.0
    }

    /// The saving of each round, percent (specialised against the generic
    /// median of the same round, drawn just before it).
    pub fn round_savings_pct(&self) -> Vec<f64> {
        self.generic
            .iter()
            .zip(&self.specialised)
            .map(|(g, s)| (1.0 - s / g) * 100.0)
            .collect()
    }

    /// Rounds in which the specialised median was below the generic one.
    pub fn rounds_faster(&self) -> usize {
        self.generic
            .iter()
            .zip(&self.specialised)
            .filter(|(g, s)| s < g)
            .count()
    }

    pub(super) fn json(&self) -> serde_json::Value {
        let (g, s) = (self.generic_stats(), self.specialised_stats());
        json!({
            "generic_ms": round(g.median, 4),
            "specialised_ms": round(s.median, 4),
            "ratio": round(self.ratio(), 4),
            "saving_pct": round(self.saving_pct(), 2),
            "generic_spread": round(g.spread, 4),
            "specialised_spread": round(s.spread, 4),
            "rounds_specialised_faster": self.rounds_faster(),
            "round_savings_pct": self.round_savings_pct().iter().map(|x| round(*x, 2)).collect::<Vec<_>>(),
            "round_saving_median_pct": round(quantile(&self.round_savings_pct(), 0.5), 2),
            "rounds": self.generic.len(),
            "generic_round_medians_ms": self.generic.iter().map(|x| round(*x, 4)).collect::<Vec<_>>(),
            "specialised_round_medians_ms": self.specialised.iter().map(|x| round(*x, 4)).collect::<Vec<_>>(),
        })
    }
}

/// SPIR-V instruction counts: (module, fragment entry point's functions).
pub type SpirvCounts = (u32, u32);

/// One instance's figures.
#[derive(Clone, Debug, PartialEq)]
pub struct InstanceBench {
    pub name: String,
    pub material: String,
    pub tier: String,
    /// The generic library variant drawn (`alias_of` followed).
    pub generic_variant: String,
    /// The scene shader drawn.
    pub shader: String,
    pub spirv_generic: SpirvCounts,
    pub spirv_specialised: SpirvCounts,
    /// Material uniform bytes (0 when the shader reads none).
    pub uniform_generic: u32,
    pub uniform_specialised: u32,
    /// Drawn alone (same camera, options and transform).
    pub gpu: Option<AbTiming>,
    pub flip: Option<ImageError>,
}

impl InstanceBench {
    /// Fragment-instruction reduction, percent.
    pub fn spirv_reduction_pct(&self) -> f64 {
        reduction_pct(self.spirv_generic.1, self.spirv_specialised.1)
    }
}

pub(super) fn reduction_pct(generic: u32, specialised: u32) -> f64 {
    if generic == 0 {
        return 0.0;
    }
    (1.0 - f64::from(specialised) / f64::from(generic)) * 100.0
}

/// Shaders and files of one way of shipping a scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FileStats {
    /// Distinct shaders (generic: canonical library variants; scene: scene shaders).
    pub shaders: usize,
    pub shader_files: usize,
    pub shader_bytes: u64,
    /// Metadata files (generic: each material's `.meta.json`; scene: `<scene>.scene.json`).
    pub metadata_files: usize,
    pub metadata_bytes: u64,
}

impl FileStats {
    pub fn files(&self) -> usize {
        self.shader_files + self.metadata_files
    }

    pub fn bytes(&self) -> u64 {
        self.shader_bytes + self.metadata_bytes
    }

    pub(super) fn json(&self) -> serde_json::Value {
        json!({
            "shaders": self.shaders,
            "shader_files": self.shader_files,
            "shader_bytes": self.shader_bytes,
            "metadata_files": self.metadata_files,
            "metadata_bytes": self.metadata_bytes,
            "files": self.files(),
            "bytes": self.bytes(),
        })
    }
}

/// One scene's figures.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneBench {
    pub name: String,
    /// Of `generated/scenes/<scene>/<scene>.scene.json`, the files measured.
    pub inputs_hash: String,
    /// Whether a fresh `build_scene` produced exactly the files measured.
    pub current: bool,
    pub gpu: AbTiming,
    pub flip: ImageError,
    /// Per-round medians of an empty pass (the clear alone), with per-instance timing.
    pub empty_pass: Option<Vec<f64>>,
    pub instances: Vec<InstanceBench>,
    pub generic_files: FileStats,
    pub scene_files: FileStats,
    /// Build times, ms: generic materials and scene build, per run.
    pub build: AbTiming,
}

impl SceneBench {
    /// Mean over instances of the fragment-instruction reduction, percent.
    pub fn spirv_mean_reduction_pct(&self) -> f64 {
        if self.instances.is_empty() {
            return 0.0;
        }
        self.instances
            .iter()
            .map(InstanceBench::spirv_reduction_pct)
            .sum::<f64>()
            / self.instances.len() as f64
    }
}

/// The result of [`run`].
#[derive(Clone, Debug)]
pub struct SceneBenchReport {
    pub adapter: String,
    pub timer: FrameTimer,
    pub options: SceneBenchOptions,
    /// `debug` or `release`: the build times depend on it.
    pub profile: String,
    /// `LP_NUM_THREADS` (lavapipe's rasterizer threads) when set.
    pub lavapipe_threads: Option<String>,
    pub scenes: Vec<SceneBench>,
    /// Wall time of the whole run, seconds.
    pub seconds: f64,
}

pub(super) fn round(x: f64, digits: i32) -> f64 {
    let s = 10f64.powi(digits);
    (x * s).round() / s
}
