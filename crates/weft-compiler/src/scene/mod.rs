//! Scene builds: compile exactly the shaders a scene manifest needs, each
//! specialised for its instance.
//!
//! `weft_front::scene` resolves the manifest against its materials (every
//! diagnostic about what a scene asks is raised there); [`build`] folds each
//! instance ([`fold`], values from [`instance`]), checks what only the
//! specialised shader can tell (vertex inputs, the shader budget) and
//! assembles `<scene>.scene.json`; [`tiers`] is the interface for `auto` tiers.

pub mod build;
pub mod fold;
pub mod instance;
pub mod tiers;

pub use build::{SceneBuildOptions, SceneOutput, build_resolved_scene};
pub use tiers::{AutoTierDecision, AutoTierRequest, TierChooser};

use std::path::Path;
use weft_front::{Diagnostics, SourceDb};

/// Builds the scene manifest at `scene_toml`: the `build.rs` entry point next
/// to [`crate::build_library`]. Returns every file (relative to the output
/// root, under `<scene>/`) or every diagnostic; writes nothing.
pub fn build_scene(
    scene_toml: &Path,
    options: &SceneBuildOptions,
) -> Result<SceneOutput, (SourceDb, Diagnostics)> {
    let mut db = SourceDb::new();
    let mut diags = Diagnostics::new();
    let Some(scene) = weft_front::scene::load_scene(scene_toml, &mut db, &mut diags) else {
        return Err((db, diags));
    };
    match build_resolved_scene(&scene, &mut db, &mut diags, options) {
        Some(out) if !diags.has_errors() => Ok(out),
        _ => Err((db, diags)),
    }
}
