//! What one scene's specialisation saves on each GPU family: every instance
//! (material variants' stand-ins included) priced with its specialised shader
//! and with the generic variant it replaces, each pass it draws, fragment
//! stage, summed — the scene metadata's `funnel.modelled`, which
//! `weft build --scene … --gpu-model` records and prints.

use crate::error::{Error, Result};
use crate::record::FamilyStats;
use crate::summary::scene_shader_costs;
use std::path::Path;
use weft_meta::scene::{FunnelModel, SceneMetadata};

/// The saving per family, from figures compiled (with their disassembly) for
/// the scene's shaders and its generic variants, both laid out under
/// `generated` as a library build and `scenes/<scene>/` lay them out. An
/// instance pass without figures is an error: the saving covers the whole
/// scene or is not stated.
pub fn scene_saving(
    generated: &Path,
    scene: &SceneMetadata,
    families: &[FamilyStats],
) -> Result<Vec<FunnelModel>> {
    let mut out = Vec::new();
    for f in families {
        let costs = scene_shader_costs(generated, f)?;
        let mut sums = (0.0, 0.0, 0u64, 0u64);
        for inst in scene.built_instances() {
            for pass in &inst.passes {
                let c = costs
                    .iter()
                    .find(|c| {
                        c.scene == scene.name && c.shader == inst.shader && c.pass == pass.name
                    })
                    .ok_or_else(|| {
                        Error::Input(format!(
                            "{}: no figures for instance `{}` (shader `{}`, pass `{}`) against \
                             its generic variant `{}`",
                            f.family, inst.name, inst.shader, pass.name, inst.variant
                        ))
                    })?;
                sums.0 += c.generic.executed_cost;
                sums.1 += c.specialised.executed_cost;
                sums.2 += c.generic.instructions;
                sums.3 += c.specialised.instructions;
            }
        }
        let (generic_cost, specialised_cost, generic_instructions, specialised_instructions) = sums;
        let saving = if generic_cost > 0.0 {
            100.0 * (1.0 - specialised_cost / generic_cost)
        } else {
            0.0
        };
        out.push(FunnelModel {
            family: f.family.clone(),
            driver: f.driver_info.clone(),
            generic_cost: round1(generic_cost),
            specialised_cost: round1(specialised_cost),
            generic_instructions,
            specialised_instructions,
            cost_saving_percent: round1(saving),
        });
    }
    Ok(out)
}

/// Figures to 0.1: the model's sums are exact, their last bits are not
/// worth recording.
fn round1(x: f64) -> f64 {
    (x * 10.0).round() / 10.0
}
