//! Scene builds: compile exactly the shaders a scene manifest needs, each
//! specialised for its instance.
//!
//! `weft_front::scene` resolves the manifest against its materials (every
//! diagnostic about what a scene asks is raised there); [`build`] folds each
//! instance ([`fold`], values from [`instance`]), checks what only the
//! specialised shader can tell (vertex inputs, the shader budget) and
//! assembles `<scene>.scene.json`; [`tiers`] is the interface for `auto` tiers.

pub mod build;
mod call_sites;
mod checks;
mod dead_calls;
mod evaluate;
pub mod fold;
mod identities;
pub mod instance;
mod local_vars;
mod locals;
mod loops;
mod record;
pub mod tiers;

pub use build::{MAX_SCENE_SHADERS, SceneBuildOptions, SceneOutput, build_resolved_scene};
pub use record::metadata_json;
pub use tiers::{AutoTierDecision, AutoTierRequest, TierChooser};

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use weft_front::{Diagnostics, SourceDb};

/// Where a library build puts the scene metadata's JSON Schema.
pub const SCENE_METADATA_SCHEMA_PATH: &str = "scene-metadata.schema.json";
/// Where a project build (`cargo xtask regenerate`) puts built scenes, under the output root.
pub const SCENES_OUTPUT_DIR: &str = "scenes";

/// Scene manifests in a folder: `<dir>/*.scene.toml`, sorted.
pub fn discover_scenes(dir: &Path) -> std::io::Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir)? {
        let p = entry?.path();
        if p.is_file() && p.to_string_lossy().ends_with(".scene.toml") {
            out.push(p);
        }
    }
    out.sort();
    Ok(out)
}

/// Every built scene's files under `scenes/<scene>/`, and the scenes themselves.
pub type SceneFolderOutput = (BTreeMap<String, Vec<u8>>, Vec<SceneOutput>);

/// Builds every scene manifest in `dir` and returns their files under
/// `scenes/<scene>/`, ready to merge into a library build's files. Stops at
/// the first scene with errors.
pub fn build_scene_folder(
    dir: &Path,
    options: &SceneBuildOptions,
) -> Result<SceneFolderOutput, (SourceDb, Diagnostics)> {
    let paths = discover_scenes(dir).map_err(|e| {
        let mut diags = Diagnostics::new();
        diags.push(
            codespan_reporting::diagnostic::Diagnostic::error()
                .with_code("io")
                .with_message(format!(
                    "cannot read scenes folder `{}`: {e}",
                    dir.display()
                )),
        );
        (SourceDb::new(), diags)
    })?;
    let mut files = BTreeMap::new();
    let mut outputs = Vec::new();
    for p in paths {
        let out = build_scene(&p, options)?;
        for (name, bytes) in &out.files {
            files.insert(format!("{SCENES_OUTPUT_DIR}/{name}"), bytes.clone());
        }
        outputs.push(out);
    }
    Ok((files, outputs))
}

/// Builds the scene manifest at `scene_toml`: the `build.rs` entry point next
/// to [`crate::build_library`]. Returns every file (relative to the output
/// root, under `<scene>/`) or every diagnostic; writes nothing.
pub fn build_scene(
    scene_toml: &Path,
    options: &SceneBuildOptions,
) -> Result<SceneOutput, (SourceDb, Diagnostics)> {
    let mut db = SourceDb::new();
    let mut diags = Diagnostics::new();
    let loaded = if weft_front::gltf::is_gltf_path(scene_toml) {
        weft_front::scene::load_gltf_scene(scene_toml, options.gltf_materials, &mut db, &mut diags)
    } else {
        weft_front::scene::load_scene(scene_toml, &mut db, &mut diags)
    };
    let Some(scene) = loaded else {
        return Err((db, diags));
    };
    // On compiler threads (naga's writers need deep stacks, see `nesting`),
    // as many as the caller's pool has.
    let built = crate::compile::nesting::compiler_pool(Some(rayon::current_num_threads()))
        .install(|| build_resolved_scene(scene, &mut db, &mut diags, options));
    match built {
        Some(mut out) if !diags.has_errors() => {
            if !diags.is_empty() {
                out.warnings = Some((db, diags));
            }
            Ok(out)
        }
        _ => Err((db, diags)),
    }
}
