//! The GPU model's compact, committed form: `generated/reports/gpu-model.json`
//! (written by `cargo xtask bench gpu-model --write`, built by
//! `weft_gpu_stats::summary`). Per family — AMD's shader compiler on Mesa
//! RADV's null device — each material × tier, each library variant and each
//! scene shader beside its generic variant, fragment stage. What uses GPU
//! cost without compiling reads it through these types (the `tier = "auto"`
//! chooser, the real-GPU bench, the docs' tables), so it needs no RADV.

use serde::{Deserialize, Serialize};
use std::path::Path;

/// The file name under `generated/reports/`.
pub const FILE_NAME: &str = "gpu-model.json";

/// The whole summary.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ModelSummary {
    /// The command that wrote it.
    pub command: String,
    /// One entry per family, in the order compiled.
    pub families: Vec<FamilySummary>,
}

/// One family's figures.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FamilySummary {
    /// weft's name of the family (`navi21`, `gfx1100`; RADV's `RADV_FORCE_FAMILY` value, or
    /// what older Mesa called it).
    pub family: String,
    /// The Vulkan device name the driver reported.
    pub device_name: String,
    /// The driver's version string.
    pub driver_info: String,
    /// Each material × tier, materials by name, tiers in the material's order.
    pub tiers: Vec<TierCost>,
    /// Every canonical library variant (f32 files), materials by name,
    /// variants in metadata order: what `tier = "auto"` costs a tier by
    /// (the variant an instance's keywords select).
    pub variants: Vec<VariantCost>,
    /// Each scene shader × pass, in the order compiled.
    pub scene_shaders: Vec<SceneShaderCost>,
}

/// A library variant's fragment stages (its passes together).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VariantCost {
    pub material: String,
    pub variant: String,
    pub tier: String,
    pub fragment: FragmentCost,
    /// `executed_cost` divided by `standard` `fast`'s.
    pub executed_ratio: f64,
}

/// The fragment figures a pipeline (or a tier's passes together) gives.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct FragmentCost {
    /// ACO's instruction count (summed over passes).
    pub instructions: u64,
    /// Vector registers per lane (the most of any pass).
    pub vgprs: u64,
    /// Waves per SIMD (the fewest of any pass).
    pub waves: u64,
    /// Loop-aware model: Σ block cost, each block once.
    pub static_cost: f64,
    /// Loop-aware model: Σ block cost × executions (the figure to compare).
    pub executed_cost: f64,
    /// Loops counted once for want of a trip count.
    pub unknown_loops: u64,
}

/// A material × tier.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TierCost {
    pub material: String,
    pub tier: String,
    /// The variant of the default keyword values.
    pub variant: String,
    /// The fragment stages of the variant's passes together.
    pub fragment: FragmentCost,
    /// `executed_cost` divided by `standard` `fast`'s.
    pub executed_ratio: f64,
}

/// A scene shader beside its generic variant.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SceneShaderCost {
    pub scene: String,
    /// `<material>.<hash>`.
    pub shader: String,
    pub material: String,
    /// The library variant it specialises.
    pub variant: String,
    pub pass: String,
    pub specialised: FragmentCost,
    pub generic: FragmentCost,
}

impl FragmentCost {
    /// Several passes' fragment stages as one: instructions, costs and
    /// unknown loops add; registers take the worst pass (most VGPRs, fewest
    /// waves). None for no passes.
    pub fn combined(costs: impl IntoIterator<Item = FragmentCost>) -> Option<FragmentCost> {
        costs.into_iter().reduce(|a, c| FragmentCost {
            instructions: a.instructions + c.instructions,
            vgprs: a.vgprs.max(c.vgprs),
            waves: a.waves.min(c.waves),
            static_cost: a.static_cost + c.static_cost,
            executed_cost: a.executed_cost + c.executed_cost,
            unknown_loops: a.unknown_loops + c.unknown_loops,
        })
    }
}

impl ModelSummary {
    /// Reads `<reports>/gpu-model.json` (`reports`: e.g. `generated/reports`).
    pub fn load(reports: &Path) -> Result<ModelSummary, String> {
        let path = reports.join(FILE_NAME);
        let bytes = crate::files::read_regular(&path, crate::files::MAX_TEXT_BYTES).map_err(|e| {
            format!(
                "cannot read the GPU model {}: {e} (write it with `cargo xtask bench gpu-model --write`)",
                path.display()
            )
        })?;
        serde_json::from_slice(&bytes).map_err(|e| format!("{}: {e}", path.display()))
    }

    /// Pretty JSON with a final newline (the committed form).
    pub fn to_json(&self) -> String {
        let mut s = serde_json::to_string_pretty(self).expect("plain data serialises");
        s.push('\n');
        s
    }

    /// The family named `family`.
    pub fn family(&self, family: &str) -> Option<&FamilySummary> {
        self.families.iter().find(|f| f.family == family)
    }
}

impl FamilySummary {
    /// The figures of `material`'s variant `variant` (its canonical id: an
    /// alias's target).
    pub fn variant(&self, material: &str, variant: &str) -> Option<&VariantCost> {
        self.variants
            .iter()
            .find(|v| v.material == material && v.variant == variant)
    }

    /// The figures of `material` `tier`.
    pub fn tier(&self, material: &str, tier: &str) -> Option<&TierCost> {
        self.tiers
            .iter()
            .find(|t| t.material == material && t.tier == tier)
    }
}

/// The `inputs_hash` of `<generated>/<material>/<material>.meta.json`: which
/// version of the material the committed reports beside it (the model, a
/// GPU bench) describe, for telling figures of an earlier version apart.
/// None when the file is absent or unreadable (regular files only, bounded).
pub fn generated_inputs_hash(generated: &Path, material: &str) -> Option<String> {
    let path = generated
        .join(material)
        .join(format!("{material}.meta.json"));
    let bytes = crate::files::read_regular(&path, crate::files::MAX_TEXT_BYTES).ok()?;
    let json: serde_json::Value = serde_json::from_slice(&bytes).ok()?;
    Some(json.get("inputs_hash")?.as_str()?.to_string())
}
