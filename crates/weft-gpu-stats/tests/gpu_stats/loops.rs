//! The loop-aware model on RADV's null device (navi21 only, four materials:
//! a few seconds). Needs `mesa-vulkan-drivers`, like tests/gpu_stats/radv.rs.

use std::path::PathBuf;
use weft_gpu_stats::loop_report::TierModel;
use weft_gpu_stats::{FamilyStats, Options, Selection, WorkerCommand};

fn generated() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../generated"))
}

fn compile() -> Vec<FamilyStats> {
    let options = Options {
        generated: generated(),
        selection: Selection {
            materials: Some(
                ["hair", "laser", "microcylinder", "standard"]
                    .map(String::from)
                    .to_vec(),
            ),
            tiers: Some(["fast", "reference"].map(String::from).to_vec()),
            variants: None,
            scenes: false,
        },
        families: vec!["navi21".into()],
        disassembly: true,
        icd_dirs: None,
        worker: WorkerCommand {
            program: env!("CARGO_BIN_EXE_weft-gpu-stats").into(),
            args: vec![],
        },
    };
    weft_gpu_stats::collect(&options).unwrap_or_else(|e| panic!("{e}"))
}

fn tier<'a>(models: &'a [TierModel], material: &str, tier: &str) -> &'a TierModel {
    models
        .iter()
        .find(|m| m.material == material && m.tier == tier)
        .unwrap_or_else(|| panic!("no {material} {tier}"))
}

#[test]
fn reference_tiers_cost_more_than_fast_once_loops_count() {
    let stats = compile();
    let models = weft_gpu_stats::report::tier_models(&generated(), &stats[0]).unwrap();
    for m in &models {
        assert_eq!(
            m.unknown, 0,
            "{} {}: loop without a trip count",
            m.material, m.tier
        );
    }
    // A loop-free tier executes each block once; a loop adds its body's
    // repeats (every loop here runs at least twice).
    for m in &models {
        if m.loops == 0 {
            assert_eq!(m.executed_cost, m.static_cost, "{m:?}");
        } else {
            assert!(m.executed_cost > m.static_cost, "{m:?}");
        }
    }
    for material in ["hair", "laser", "microcylinder"] {
        let (fast, reference) = (
            tier(&models, material, "fast"),
            tier(&models, material, "reference"),
        );
        // Static figures count each reference's loops once (laser's and
        // microcylinder's static costs are within 6 % of fast's); executed,
        // its trip counts multiply them ...
        assert!(reference.loops >= 1, "{material}: {reference:?}");
        assert!(
            reference.executed_cost > 4.0 * reference.static_cost,
            "{material}: {reference:?}"
        );
        // ... executed, it is the dearer one, as llvmpipe measures.
        assert!(
            reference.executed_cost > 3.0 * fast.executed_cost,
            "{material}: {reference:?} {fast:?}"
        );
    }
    // Deterministic: the same records give the same figures.
    let again = weft_gpu_stats::report::tier_models(&generated(), &stats[0]).unwrap();
    assert_eq!(models, again);
}
