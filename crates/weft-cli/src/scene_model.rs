//! `weft build --scene … --gpu-model`: what the scene's specialisation saves
//! on AMD's shader compiler (Mesa RADV/ACO on its null device: no GPU
//! needed), recorded in the scene metadata's `funnel.modelled` and printed
//! with the funnel.
//!
//! The scene's shaders and the generic variants they replace are laid out in
//! a temporary folder as a library build and a scene folder lay them out.
//! The generic variants are compiled from the scene's own materials root
//! (files of `./generated` reused only where their inputs hash matches), so
//! both sides come from the same sources. One child process per family
//! (this binary's hidden `gpu-stats-worker` command) compiles them, and the
//! loop-aware model prices every instance both ways
//! (`weft_gpu_stats::funnel`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use weft_meta::scene::{FunnelModel, SceneMetadata};

/// The hidden subcommand that serves one family's compile (`weft_gpu_stats::worker`).
pub const WORKER_SUBCOMMAND: &str = "gpu-stats-worker";

/// The saving per family in `families`, for the scene `metadata` whose
/// files (relative to its folder) are `scene_files`, built from
/// `materials_root`. Errors name what is missing (RADV: the package).
pub fn model_saving(
    metadata: &SceneMetadata,
    scene_files: &BTreeMap<String, Vec<u8>>,
    materials_root: &Path,
    families: &[String],
) -> Result<Vec<FunnelModel>, String> {
    // Before any compile: without RADV there is nothing to model with.
    weft_gpu_stats::radv_available().map_err(|e| e.to_string())?;
    let generic: BTreeSet<(String, String)> = metadata
        .built_instances()
        .map(|i| (i.material.clone(), i.variant.clone()))
        .collect();
    let materials: BTreeSet<String> = generic.iter().map(|(m, _)| m.clone()).collect();
    let staging = tempfile::Builder::new()
        .prefix("weft-gpu-model-")
        .tempdir()
        .map_err(|e| format!("creating a temporary folder: {e}"))?;
    let root = staging.path();
    stage_generic_variants(root, materials_root, &materials)?;
    let scene_dir = root.join("scenes").join(&metadata.name);
    for (rel, bytes) in scene_files {
        if is_modelled_file(rel) {
            write(&scene_dir.join(rel), bytes)?;
        }
    }
    let options = weft_gpu_stats::Options {
        generated: root.to_path_buf(),
        selection: weft_gpu_stats::Selection {
            materials: Some(materials.into_iter().collect()),
            tiers: None,
            variants: Some(generic.into_iter().collect()),
            scenes: true,
        },
        families: families.to_vec(),
        disassembly: true,
        icd_dirs: None,
        worker: weft_gpu_stats::WorkerCommand {
            program: std::env::current_exe().map_err(|e| format!("locating weft: {e}"))?,
            args: vec![WORKER_SUBCOMMAND.into()],
        },
    };
    let stats = weft_gpu_stats::collect(&options).map_err(|e| e.to_string())?;
    weft_gpu_stats::funnel::scene_saving(root, metadata, &stats).map_err(|e| e.to_string())
}

/// The used materials' library build (metadata, SPIR-V, WGSL) under `root`.
fn stage_generic_variants(
    root: &Path,
    materials_root: &Path,
    materials: &BTreeSet<String>,
) -> Result<(), String> {
    let paths: Vec<PathBuf> = weft_compiler::library::discover(materials_root)
        .map_err(|e| format!("reading {}: {e}", materials_root.display()))?
        .into_iter()
        .filter(|p| {
            p.file_stem()
                .and_then(|s| s.to_str())
                .is_some_and(|s| materials.contains(s))
        })
        .collect();
    let generated = Path::new("generated");
    let options = weft_compiler::library::BuildOptions {
        reuse_from: generated.is_dir().then(|| generated.to_path_buf()),
        ..Default::default()
    };
    let out = weft_compiler::library::build_materials(
        &paths,
        Some(materials_root),
        &options,
        &|_, _, _| {},
    )
    .map_err(|(_, diags)| {
        format!(
            "compiling the generic variants failed ({} error(s)); `weft check {}` shows them",
            diags.error_count(),
            materials_root.display()
        )
    })?;
    for m in materials {
        if !out.files.contains_key(&format!("{m}/{m}.meta.json")) {
            return Err(format!(
                "material `{m}` is not in {} (no `{m}/{m}.toml`)",
                materials_root.display()
            ));
        }
    }
    for (rel, bytes) in &out.files {
        let in_used = rel
            .split_once('/')
            .is_some_and(|(m, _)| materials.contains(m));
        if in_used && is_modelled_file(rel) {
            write(&root.join(rel), bytes)?;
        }
    }
    Ok(())
}

/// What the model reads: metadata, SPIR-V, and the WGSL its loop counts come from.
fn is_modelled_file(rel: &str) -> bool {
    rel.ends_with(".meta.json")
        || rel.ends_with(".scene.json")
        || rel.ends_with(".spv")
        || rel.ends_with(".wgsl")
}

fn write(path: &Path, bytes: &[u8]) -> Result<(), String> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    std::fs::write(path, bytes).map_err(|e| format!("{}: {e}", path.display()))
}

/// The funnel's modelled step, e.g. `modelled fragment cost −23.4 % on navi21,
/// −22.9 % on gfx1100`.
pub fn describe(modelled: &[FunnelModel]) -> String {
    let parts: Vec<String> = modelled
        .iter()
        .map(|m| {
            format!(
                "{:+.1} % on {} ({:.0} → {:.0})",
                -m.cost_saving_percent, m.family, m.generic_cost, m.specialised_cost
            )
        })
        .collect();
    format!("modelled fragment cost {}", parts.join(", "))
}
