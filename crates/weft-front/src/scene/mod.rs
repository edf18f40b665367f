//! Scene manifests (`scenes/<name>.scene.toml`): parse, then resolve every
//! instance against the materials it names. Everything a scene asks that a
//! material cannot give is a diagnostic at the scene file's line; the
//! compiler only ever receives a [`model::ResolvedScene`].
//!
//! Pipeline: [`parse`] (TOML -> [`SceneManifest`], local checks) ->
//! [`resolve`] (materials loaded from the materials root, values typed,
//! keywords, tier and variant checked). The format: docs/scenes.md.

pub mod model;
pub mod parse;
pub mod resolve;

pub use model::{ResolvedInstance, ResolvedScene, SceneManifest};
pub use parse::{CAMERA_KEYS, INSTANCE_KEYS, LIGHT_KEYS, SCENE_KEYS, TOP_KEYS};

use crate::diag::{Diagnostics, SourceDb};
use crate::toml_reader::Cx;
use std::path::Path;

/// Parses and resolves a scene manifest; loads (and checks) each material it names from the materials root.
pub fn load_scene(
    path: &Path,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<ResolvedScene> {
    let (abs, file, text) = crate::read_source(path, db, diags)?;
    let before = diags.error_count();
    let doc = parse::parse_document(&text, &mut Cx { file, diags })?;
    let parsed = parse::parse_manifest(doc.get_ref(), &abs, &mut Cx { file, diags })?;
    let scene = resolve::resolve(parsed, db, diags);
    (diags.error_count() == before).then_some(scene)
}

#[cfg(test)]
mod tests;
