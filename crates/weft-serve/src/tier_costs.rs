//! What the page's tier panel shows beside each tier, attached to the
//! material's served metadata: the measured cost and error
//! (`<name>.measurements.json`, a rasteriser's timings: lavapipe unless
//! measured elsewhere) and, apart, the GPU model's cost per AMD family
//! (`gpu-model.json`: AMD's shader compiler on Mesa RADV's null device,
//! docs/performance.md). Both come from the reports folder (regular files
//! only, bounded); neither is mixed into the other.

use serde_json::{Value, json};
use std::path::Path;
use weft_meta::files::{MAX_TEXT_BYTES, read_regular};
use weft_meta::gpu_model::{ModelSummary, generated_inputs_hash};
use weft_meta::{MaterialMetadata, Measurements};

/// The reports a build's snapshot attaches, read once per build.
pub struct TierCosts {
    reports: std::path::PathBuf,
    model: Option<ModelSummary>,
}

impl TierCosts {
    /// Reads `<reports>/gpu-model.json` if it is there (no model columns otherwise).
    pub fn load(reports: &Path) -> TierCosts {
        TierCosts {
            reports: reports.to_path_buf(),
            model: ModelSummary::load(reports).ok(),
        }
    }

    /// The metadata as served: `measurements` attached from the material's
    /// report, and `gpu_model` (not a metadata field: the page's own) when
    /// the model has the material.
    pub fn served_json(&self, metadata: &mut MaterialMetadata) -> Vec<u8> {
        let report = self
            .reports
            .join(format!("{}.measurements.json", metadata.name));
        if let Ok(bytes) = read_regular(&report, MAX_TEXT_BYTES)
            && let Ok(m) = serde_json::from_slice::<Measurements>(&bytes)
        {
            metadata.measurements = Some(m);
        }
        let mut value = serde_json::to_value(&*metadata).unwrap_or(Value::Null);
        if let (Some(model), Value::Object(map)) = (self.gpu_model(&metadata.name), &mut value) {
            map.insert("gpu_model".into(), model);
        }
        serde_json::to_vec(&value).unwrap_or_default()
    }

    /// `{inputs_hash, families: [{family, device, driver, tiers: [{tier,
    /// executed_ratio, vgprs, waves}]}]}` for `material`; `inputs_hash` is
    /// that of the generated metadata the model costed
    /// (`<reports>/../<material>/<material>.meta.json`), so the page can say
    /// when the material has changed since.
    fn gpu_model(&self, material: &str) -> Option<Value> {
        let model = self.model.as_ref()?;
        let families: Vec<Value> = model
            .families
            .iter()
            .map(|f| {
                let tiers: Vec<Value> = f
                    .tiers
                    .iter()
                    .filter(|t| t.material == material)
                    .map(|t| {
                        json!({
                            "tier": t.tier,
                            "executed_ratio": t.executed_ratio,
                            "vgprs": t.fragment.vgprs,
                            "waves": t.fragment.waves,
                        })
                    })
                    .collect();
                json!({
                    "family": f.family,
                    "device": f.device_name,
                    "driver": f.driver_info,
                    "tiers": tiers,
                })
            })
            .filter(|f| f["tiers"].as_array().is_some_and(|t| !t.is_empty()))
            .collect();
        if families.is_empty() {
            return None;
        }
        let inputs_hash = generated_inputs_hash(&self.reports.join(".."), material);
        Some(json!({ "inputs_hash": inputs_hash, "families": families }))
    }
}
