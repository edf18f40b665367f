//! Builds the GPU model's compact form ([`weft_meta::gpu_model`],
//! `generated/reports/gpu-model.json`) from figures captured with their
//! disassembly: per family each material × tier (its default keyword values,
//! f32 files), each canonical library variant and each scene shader beside
//! the generic variant it specialises, fragment stage.

use crate::error::Result;
use crate::loop_report;
use crate::pairing::{GenericVariants, material_pipeline, read_meta};
use crate::record::{FamilyStats, PipelineStats};
use crate::report::{INSTRUCTIONS, VGPRS, WAVES};
use std::collections::BTreeMap;
use std::path::Path;
pub use weft_meta::gpu_model::{
    FILE_NAME, FamilySummary, FragmentCost, ModelSummary, SceneShaderCost, TierCost, VariantCost,
};

/// Builds the summary from figures captured with their disassembly.
pub fn summarize(
    generated: &Path,
    families: &[FamilyStats],
    command: &str,
) -> Result<ModelSummary> {
    let mut out = Vec::new();
    for f in families {
        let models = crate::report::tier_models(generated, f)?;
        let base = models
            .iter()
            .find(|m| m.material == "standard" && m.tier == "fast")
            .map(|m| m.executed_cost)
            .filter(|c| *c > 0.0);
        let entries = fragment_entries(generated, f)?;
        let pipeline = |material: &str, variant: &str, pass: &str| {
            material_pipeline(f, material, variant, pass)
        };
        let cost_of = |p: &PipelineStats| cost_of(generated, &entries, p);
        let mut tiers = Vec::new();
        for m in &models {
            let meta = read_meta(generated, &m.material)?;
            let passes = meta
                .resolve_variant(&m.variant)
                .map(|v| v.passes.clone())
                .unwrap_or_default();
            let costs: Option<Vec<FragmentCost>> = passes
                .iter()
                .map(|pass| pipeline(&m.material, &m.variant, pass).and_then(cost_of))
                .collect();
            let Some(fragment) = costs.and_then(|c| combine(&c)) else {
                continue;
            };
            tiers.push(TierCost {
                material: m.material.clone(),
                tier: m.tier.clone(),
                variant: m.variant.clone(),
                executed_ratio: base.map_or(0.0, |b| round(fragment.executed_cost / b)),
                fragment,
            });
        }
        let mut variants = Vec::new();
        let mut materials: Vec<&str> = f
            .pipelines
            .iter()
            .filter(|p| p.source.kind == "material")
            .map(|p| p.source.material.as_str())
            .collect();
        materials.sort();
        materials.dedup();
        for material in materials {
            let meta = read_meta(generated, material)?;
            for v in meta.variants.iter().filter(|v| v.alias_of.is_none()) {
                let costs: Option<Vec<FragmentCost>> = v
                    .passes
                    .iter()
                    .map(|pass| pipeline(material, &v.id, pass).and_then(cost_of))
                    .collect();
                let Some(fragment) = costs.and_then(|c| combine(&c)) else {
                    continue;
                };
                variants.push(VariantCost {
                    material: material.into(),
                    variant: v.id.clone(),
                    tier: v.tier.clone(),
                    executed_ratio: base.map_or(0.0, |b| round(fragment.executed_cost / b)),
                    fragment,
                });
            }
        }
        let scene_shaders = scene_costs(generated, f, &entries)?;
        out.push(FamilySummary {
            family: f.family.clone(),
            device_name: f.device_name.clone(),
            driver_info: f.driver_info.clone(),
            tiers,
            variants,
            scene_shaders,
        });
    }
    Ok(ModelSummary {
        command: command.into(),
        families: out,
    })
}

/// Each scene shader × pass of a family's figures beside the generic
/// variant it specialises (fragment stage; the generic variant's loops run
/// as many times as the scene shader's show). The generic variant is the one
/// its id resolves to: a variant identical to another is an alias with no
/// files of its own (`alias_of`). A pair whose generic variant was not
/// compiled is left out.
pub fn scene_shader_costs(generated: &Path, f: &FamilyStats) -> Result<Vec<SceneShaderCost>> {
    scene_costs(generated, f, &fragment_entries(generated, f)?)
}

fn scene_costs(
    generated: &Path,
    f: &FamilyStats,
    entries: &BTreeMap<(String, String), String>,
) -> Result<Vec<SceneShaderCost>> {
    let mut generics = GenericVariants::new(generated);
    // The generic variant drawing a scene instance: its loops as many
    // times as the instance's shader shows (model::model_at).
    let generic_at = |g: &PipelineStats, scene: &PipelineStats| -> Option<FragmentCost> {
        let entry = entries.get(&(g.source.material.clone(), g.pass.clone()))?;
        let instance = loop_report::source_loops(generated, scene, entry);
        fragment_cost(generated, g, entry, instance.as_deref())
    };
    let mut scene_shaders = Vec::new();
    for p in f.pipelines.iter().filter(|p| p.source.kind == "scene") {
        let s = &p.source;
        let generic = generics.generic_of(f, p)?.and_then(|g| generic_at(g, p));
        let (Some(specialised), Some(generic)) = (cost_of(generated, entries, p), generic) else {
            continue;
        };
        scene_shaders.push(SceneShaderCost {
            scene: s.scene.clone().unwrap_or_default(),
            shader: s.shader.clone().unwrap_or_default(),
            material: s.material.clone(),
            variant: s.variant.clone(),
            pass: p.pass.clone(),
            specialised,
            generic,
        });
    }
    Ok(scene_shaders)
}

/// A pipeline's fragment figures at its own loop counts.
fn cost_of(
    generated: &Path,
    entries: &BTreeMap<(String, String), String>,
    p: &PipelineStats,
) -> Option<FragmentCost> {
    let entry = entries.get(&(p.source.material.clone(), p.pass.clone()))?;
    fragment_cost(generated, p, entry, None)
}

/// A pipeline's fragment figures; None without the stage or its disassembly.
fn fragment_cost(
    generated: &Path,
    p: &PipelineStats,
    entry: &str,
    instance: Option<&[crate::trips::SourceLoop]>,
) -> Option<FragmentCost> {
    let stage = p.stage("fragment")?;
    let model = loop_report::fragment_model_at(generated, p, entry, instance)?;
    let get = |name| stage.get(name).map_or(0, |v| v as u64);
    Some(FragmentCost {
        instructions: get(INSTRUCTIONS),
        vgprs: get(VGPRS),
        waves: get(WAVES),
        static_cost: model.static_cost,
        executed_cost: model.executed_cost,
        unknown_loops: model.unknown_loops() as u64,
    })
}

/// Several passes as one ([`FragmentCost::combined`]).
fn combine(costs: &[FragmentCost]) -> Option<FragmentCost> {
    FragmentCost::combined(costs.iter().copied())
}

fn round(x: f64) -> f64 {
    (x * 1000.0).round() / 1000.0
}

/// (material, pass) → the pass's fragment entry point, for every material
/// the family's pipelines draw.
fn fragment_entries(
    generated: &Path,
    f: &FamilyStats,
) -> Result<BTreeMap<(String, String), String>> {
    let mut materials: Vec<&str> = f
        .pipelines
        .iter()
        .map(|p| p.source.material.as_str())
        .collect();
    materials.sort();
    materials.dedup();
    let mut out = BTreeMap::new();
    for m in materials {
        for pass in read_meta(generated, m)?.passes {
            out.insert((m.to_string(), pass.name), pass.fragment_entry);
        }
    }
    Ok(out)
}
