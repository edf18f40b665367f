//! The loop-aware section of the report: each material × tier's modelled
//! (executed) fragment cost beside its static cost, as × standard fast, the
//! llvmpipe ratio committed in `generated/reports/<material>.measurements.json`,
//! and Spearman's rank correlation between the two.

use crate::model::{self, StageModel};
use crate::record::PipelineStats;
use crate::trips;
use std::collections::BTreeMap;
use std::path::Path;
use weft_meta::gpu_model::generated_inputs_hash;

/// A tier's figures: summed over the variant's passes (f32 files).
#[derive(Clone, Debug, PartialEq)]
pub struct TierModel {
    /// Material.
    pub material: String,
    /// Tier.
    pub tier: String,
    /// The variant (its default keyword values).
    pub variant: String,
    /// Σ static cost of the fragment stages.
    pub static_cost: f64,
    /// Σ executed cost of the fragment stages.
    pub executed_cost: f64,
    /// ACO loops found / of which without a trip count.
    pub loops: usize,
    /// Loops counted once for want of a trip count.
    pub unknown: usize,
}

/// Models the fragment stage of `p` (its disassembly must have been captured);
/// `entry` is the pass's fragment entry point in the specialised WGSL next to the SPIR-V.
pub fn fragment_model(generated: &Path, p: &PipelineStats, entry: &str) -> Option<StageModel> {
    fragment_model_at(generated, p, entry, None)
}

/// [`fragment_model`] with the loops of a scene instance's specialised
/// shader giving the trip counts `p`'s own source lacks ([`model::model_at`]).
pub fn fragment_model_at(
    generated: &Path,
    p: &PipelineStats,
    entry: &str,
    instance: Option<&[trips::SourceLoop]>,
) -> Option<StageModel> {
    let text = p.stage("fragment")?.disassembly.as_deref()?;
    let source = source_loops(generated, p, entry);
    Some(model::model_at(text, source.as_deref(), instance))
}

/// The loops of `entry` in the WGSL next to `p`'s SPIR-V.
pub fn source_loops(
    generated: &Path,
    p: &PipelineStats,
    entry: &str,
) -> Option<Vec<trips::SourceLoop>> {
    let wgsl_path = generated.join(p.source.spirv.strip_suffix(".spv")?.to_string() + ".wgsl");
    std::fs::read_to_string(wgsl_path)
        .ok()
        .and_then(|w| trips::source_loops(&w, entry))
}

/// A tier's time ÷ `standard` `fast`'s in one bench run, as drawn: a
/// half-precision tier is drawn from its f16 files where the adapter has
/// `shader-f16`, and then its portable f32 files are timed too. The model's
/// tier rows cost the f32 files, so they pair with [`TierRatio::f32_files`]
/// (like with like); its f16 rows with [`TierRatio::f16_files`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TierRatio {
    /// The ratio as the bench drew the tier.
    pub drawn: f64,
    /// The f32 files' ratio, where the tier was drawn from f16 files.
    pub f32_files: Option<f64>,
}

impl TierRatio {
    /// The ratio of the tier's f32 files.
    pub fn f32_files(&self) -> f64 {
        self.f32_files.unwrap_or(self.drawn)
    }

    /// The ratio of the tier's f16 files, where the bench drew them.
    pub fn f16_files(&self) -> Option<f64> {
        self.f32_files.map(|_| self.drawn)
    }
}

/// llvmpipe's ratios of (material, tier) from the committed measurements
/// (`ratio_to_standard_fast`, and `f32_files` for a half-precision tier).
pub fn llvmpipe_ratio(generated: &Path, material: &str, tier: &str) -> Option<TierRatio> {
    let path = generated
        .join("reports")
        .join(format!("{material}.measurements.json"));
    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(path).ok()?).ok()?;
    let t = json
        .get("tiers")?
        .as_array()?
        .iter()
        .find(|t| t.get("tier").and_then(|v| v.as_str()) == Some(tier))?;
    Some(TierRatio {
        drawn: t.get("ratio_to_standard_fast")?.as_f64()?,
        f32_files: t
            .get("f32_files")
            .and_then(|f| f.get("ratio_to_standard_fast")?.as_f64()),
    })
}

/// A real GPU's tier ratios, from a committed `cargo xtask bench gpu` report.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuTimings {
    /// The report's file name (`gpu-<adapter>.json`).
    pub file: String,
    /// The adapter as the report describes it.
    pub adapter: String,
    /// The tiers timed.
    pub tiers: Vec<GpuTier>,
    /// The model families the run paired its timings with, and ρ of each
    /// against them as the run computed it: the model of the library it
    /// timed (`spearman_model`).
    pub recorded_rho: Vec<(String, Option<f64>)>,
}

/// One tier of a [`GpuTimings`].
#[derive(Clone, Debug, PartialEq)]
pub struct GpuTier {
    /// Material.
    pub material: String,
    /// Tier.
    pub tier: String,
    /// GPU ms ÷ `standard` `fast`.
    pub ratio: TierRatio,
    /// The material's `inputs_hash` when timed; absent in reports written
    /// before 2026-11-29, which cannot tell which files they timed.
    pub inputs_hash: Option<String>,
}

impl GpuTimings {
    /// The ratios of the tiers timed on their material's current files, by
    /// (material, tier): the report recorded the `inputs_hash` the material's
    /// metadata has now (`generated/<material>/<material>.meta.json`, read
    /// once per material). A timing of an earlier version of a tier does not
    /// rank today's.
    pub fn current_ratios(&self, generated: &Path) -> BTreeMap<(String, String), TierRatio> {
        let mut hashes: BTreeMap<&str, Option<String>> = BTreeMap::new();
        self.tiers
            .iter()
            .filter(|t| {
                let now = hashes
                    .entry(&t.material)
                    .or_insert_with(|| generated_inputs_hash(generated, &t.material));
                t.inputs_hash.is_some() && t.inputs_hash == *now
            })
            .map(|t| ((t.material.clone(), t.tier.clone()), t.ratio))
            .collect()
    }

    /// The run's own ρ against `family`'s model (of the library it timed).
    pub fn recorded_rho(&self, family: &str) -> Option<f64> {
        self.recorded_rho
            .iter()
            .find(|(f, _)| f == family)
            .and_then(|r| r.1)
    }
}

/// Every committed real-GPU report under `generated/reports/` (`gpu-*.json`
/// but the model's own `gpu-model.json`), by file name.
pub fn committed_gpu_timings(generated: &Path) -> Vec<GpuTimings> {
    let dir = generated.join("reports");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        return Vec::new();
    };
    let mut files: Vec<String> = entries
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| {
            n.starts_with("gpu-") && n.ends_with(".json") && n != weft_meta::gpu_model::FILE_NAME
        })
        .collect();
    files.sort();
    files
        .into_iter()
        .filter_map(|file| {
            let json: serde_json::Value =
                serde_json::from_slice(&std::fs::read(dir.join(&file)).ok()?).ok()?;
            parse_gpu_timings(file, &json)
        })
        .collect()
}

/// A `cargo xtask bench gpu` JSON report's tiers and recorded ρ.
pub fn parse_gpu_timings(file: String, json: &serde_json::Value) -> Option<GpuTimings> {
    let str_of = |v: &serde_json::Value, key: &str| Some(v.get(key)?.as_str()?.to_string());
    let tiers = json
        .get("tiers")?
        .as_array()?
        .iter()
        .filter_map(|t| {
            Some(GpuTier {
                material: str_of(t, "material")?,
                tier: str_of(t, "tier")?,
                ratio: TierRatio {
                    drawn: t.get("gpu_ratio")?.as_f64()?,
                    f32_files: t.get("f32_files_ratio").and_then(|v| v.as_f64()),
                },
                inputs_hash: str_of(t, "inputs_hash"),
            })
        })
        .collect();
    let families = json.get("families").and_then(|f| f.as_array());
    let rhos = json.get("spearman_model").and_then(|r| r.as_array());
    let recorded_rho = match (families, rhos) {
        (Some(f), Some(r)) => f
            .iter()
            .zip(r)
            .filter_map(|(f, r)| Some((f.as_str()?.to_string(), r.as_f64())))
            .collect(),
        _ => Vec::new(),
    };
    Some(GpuTimings {
        adapter: str_of(json, "adapter")?,
        file,
        tiers,
        recorded_rho,
    })
}

/// Spearman's ρ (Pearson correlation of the ranks, ties given their mean rank).
pub fn spearman(pairs: &[(f64, f64)]) -> Option<f64> {
    if pairs.len() < 3 {
        return None;
    }
    let xs = ranks(&pairs.iter().map(|p| p.0).collect::<Vec<_>>());
    let ys = ranks(&pairs.iter().map(|p| p.1).collect::<Vec<_>>());
    let n = xs.len() as f64;
    let (mx, my) = (xs.iter().sum::<f64>() / n, ys.iter().sum::<f64>() / n);
    let cov: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let vx: f64 = xs.iter().map(|x| (x - mx).powi(2)).sum();
    let vy: f64 = ys.iter().map(|y| (y - my).powi(2)).sum();
    (vx > 0.0 && vy > 0.0).then(|| cov / (vx * vy).sqrt())
}

fn ranks(v: &[f64]) -> Vec<f64> {
    let mut order: Vec<usize> = (0..v.len()).collect();
    order.sort_by(|&a, &b| v[a].total_cmp(&v[b]));
    let mut out = vec![0.0; v.len()];
    let mut i = 0;
    while i < order.len() {
        let mut j = i;
        while j + 1 < order.len() && v[order[j + 1]] == v[order[i]] {
            j += 1;
        }
        let mean = (i + j) as f64 / 2.0 + 1.0;
        for &k in &order[i..=j] {
            out[k] = mean;
        }
        i = j + 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spearman_of_known_orders() {
        let same = [(1.0, 10.0), (2.0, 20.0), (3.0, 25.0), (4.0, 100.0)];
        assert_eq!(spearman(&same), Some(1.0));
        let reversed = [(1.0, 4.0), (2.0, 3.0), (3.0, 2.0), (4.0, 1.0)];
        assert_eq!(spearman(&reversed), Some(-1.0));
        // Ties take their mean rank: x ranks 1.5, 1.5, 3; y ranks 1, 2, 3.
        let tied = spearman(&[(1.0, 1.0), (1.0, 2.0), (2.0, 3.0)]).unwrap();
        assert!((tied - 0.866_025).abs() < 1e-5, "{tied}");
    }

    /// A half-precision tier's timing pairs with the model by files: its f32
    /// files' ratio with the f32 model, the drawn (f16) ratio with the f16
    /// one; a tier drawn in f32 only has no f16 timing.
    #[test]
    fn tier_ratios_pair_like_with_like() {
        let half = TierRatio {
            drawn: 1.69,
            f32_files: Some(1.01),
        };
        assert_eq!(half.f32_files(), 1.01);
        assert_eq!(half.f16_files(), Some(1.69));
        let plain = TierRatio {
            drawn: 1.2,
            f32_files: None,
        };
        assert_eq!(plain.f32_files(), 1.2);
        assert_eq!(plain.f16_files(), None);
    }

    #[test]
    fn llvmpipe_ratio_reads_the_f32_files_of_a_half_precision_tier() {
        let root = std::env::temp_dir().join(format!("weft-tier-ratio-{}", std::process::id()));
        let reports = root.join("reports");
        std::fs::create_dir_all(&reports).unwrap();
        std::fs::write(
            reports.join("m.measurements.json"),
            r#"{"tiers": [
                {"tier": "fast", "ratio_to_standard_fast": 1.5},
                {"tier": "low", "ratio_to_standard_fast": 2.5, "f32_files": {"ratio_to_standard_fast": 1.4}}
            ]}"#,
        )
        .unwrap();
        let fast = llvmpipe_ratio(&root, "m", "fast").unwrap();
        let low = llvmpipe_ratio(&root, "m", "low").unwrap();
        std::fs::remove_dir_all(&root).unwrap();
        assert_eq!((fast.f32_files(), fast.f16_files()), (1.5, None));
        assert_eq!((low.f32_files(), low.f16_files()), (1.4, Some(2.5)));
    }

    /// A GPU timing ranks a tier's cost only when it timed the material's
    /// current files: same `inputs_hash`; another hash, or none (reports
    /// before 2026-11-29), leaves the tier out. The run's own ρ per family
    /// is kept for the report.
    #[test]
    fn gpu_timings_pair_only_with_the_files_they_timed() {
        let root = std::env::temp_dir().join(format!("weft-gpu-timings-{}", std::process::id()));
        for (m, hash) in [("a", "h1"), ("b", "h2-new"), ("c", "h3")] {
            std::fs::create_dir_all(root.join(m)).unwrap();
            std::fs::write(
                root.join(m).join(format!("{m}.meta.json")),
                format!(r#"{{"inputs_hash": "{hash}"}}"#),
            )
            .unwrap();
        }
        let json: serde_json::Value = serde_json::from_str(
            r#"{"adapter": "GPU", "families": ["navi21", "gfx1100"], "spearman_model": [0.9, null],
                "tiers": [
                {"material": "a", "tier": "fast", "gpu_ratio": 2.0, "inputs_hash": "h1"},
                {"material": "b", "tier": "fast", "gpu_ratio": 3.0, "inputs_hash": "h2-old"},
                {"material": "c", "tier": "fast", "gpu_ratio": 4.0}
            ]}"#,
        )
        .unwrap();
        let g = parse_gpu_timings("gpu-gpu.json".into(), &json).unwrap();
        let current = g.current_ratios(&root);
        std::fs::remove_dir_all(&root).unwrap();
        let key = |m: &str| (m.to_string(), "fast".to_string());
        assert_eq!(current.get(&key("a")).map(|r| r.f32_files()), Some(2.0));
        assert_eq!(current.len(), 1, "{current:?}");
        assert_eq!(g.recorded_rho("navi21"), Some(0.9));
        assert_eq!(g.recorded_rho("gfx1100"), None);
    }
}
