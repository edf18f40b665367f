//! Scene manifests (`scenes/<name>.scene.toml`): parse, then resolve every
//! instance against the materials it names. Everything a scene asks that a
//! material cannot give is a diagnostic at the scene file's line; the
//! compiler only ever receives a [`model::ResolvedScene`].
//!
//! Pipeline: [`parse`] (TOML -> [`SceneManifest`], local checks) ->
//! [`resolve`] (materials loaded from the materials root, values typed,
//! keywords, tier and variant checked). The format: docs/scenes.md.

pub mod gltf_layer;
pub mod images;
pub mod model;
pub mod parse;
pub mod resolve;

pub use model::{ResolvedInstance, ResolvedScene, SceneManifest};
pub use parse::{CAMERA_KEYS, INSTANCE_KEYS, LIGHT_KEYS, SCENE_KEYS, TOP_KEYS};

use crate::diag::{Diagnostics, SourceDb};
use crate::toml_reader::Cx;
use codespan_reporting::diagnostic::Diagnostic;
use model::GltfSource;
use std::path::{Path, PathBuf};

/// Parses and resolves a scene manifest; loads (and checks) each material it
/// names from the materials root. A `.gltf` / `.glb` file is a scene too
/// ([`load_gltf_scene`] with the default materials root).
pub fn load_scene(
    path: &Path,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<ResolvedScene> {
    if crate::gltf::is_gltf_path(path) {
        return load_gltf_scene(path, None, db, diags);
    }
    let (abs, file, text) = crate::read_source(path, db, diags)?;
    let before = diags.error_count();
    let doc = parse::parse_document(&text, &mut Cx { file, diags })?;
    if doc.get_ref().contains_key("gltf") {
        // The glTF's instances appended to the text as written: the
        // composed text is a new source whose prefix is the file's own.
        let mut warnings = Vec::new();
        let composed = gltf_layer::compose(
            doc.get_ref(),
            &text,
            &abs,
            &mut Cx { file, diags },
            &mut warnings,
        );
        for w in warnings {
            diags.push(Diagnostic::warning().with_code("gltf").with_message(w));
        }
        let (composed, source, opened) = composed?;
        let display = db.name(file).to_string();
        let file = db.add(&abs, display, composed.clone());
        let doc = parse::parse_document(&composed, &mut Cx { file, diags })?;
        let mut parsed = parse::parse_manifest(doc.get_ref(), &abs, &mut Cx { file, diags })?;
        parsed.manifest.gltf = Some(source);
        let cache = crate::gltf::GltfCache::with_file(opened);
        let scene = resolve::resolve_with(parsed, cache, db, diags);
        return (diags.error_count() == before).then_some(scene);
    }
    let parsed = parse::parse_manifest(doc.get_ref(), &abs, &mut Cx { file, diags })?;
    let scene = resolve::resolve(parsed, db, diags);
    (diags.error_count() == before).then_some(scene)
}

#[cfg(test)]
mod tests;

/// The materials root a glTF scene's materials come from when none is
/// given: `./materials`, else the nearest `materials/` beside an ancestor
/// of the glTF file (a folder holding `lib/`).
pub fn default_gltf_materials_root(gltf: &Path) -> Option<PathBuf> {
    let is_root = |d: &Path| d.join("lib").is_dir();
    let cwd = PathBuf::from("materials");
    if is_root(&cwd) {
        return cwd.canonicalize().ok();
    }
    let abs = gltf.canonicalize().ok()?;
    abs.ancestors()
        .skip(1)
        .map(|a| a.join("materials"))
        .find(|m| is_root(m))
}

/// A glTF file as a scene: its manifest generated (`gltf::scene`), then
/// parsed and resolved like a written one. Problems with the file are
/// errors naming its JSON pointer.
pub fn load_gltf_scene(
    path: &Path,
    materials_root: Option<&Path>,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<ResolvedScene> {
    let manifest = match gltf_manifest(path, materials_root) {
        Ok(m) => m,
        Err(e) => {
            diags.push(gltf_diagnostic(&e));
            return None;
        }
    };
    let (text, warnings, virtual_path, source, opened) = manifest;
    for w in warnings {
        diags.push(Diagnostic::warning().with_code("gltf").with_message(w));
    }
    let display = format!("{} (as a weft scene)", crate::includes::display_path(path));
    let file = db.add(&virtual_path, display, text.clone());
    let before = diags.error_count();
    let doc = parse::parse_document(&text, &mut Cx { file, diags })?;
    let mut parsed = parse::parse_manifest(doc.get_ref(), &virtual_path, &mut Cx { file, diags })?;
    parsed.manifest.gltf = Some(source);
    let cache = crate::gltf::GltfCache::with_file(opened);
    let scene = resolve::resolve_with(parsed, cache, db, diags);
    (diags.error_count() == before).then_some(scene)
}

/// What [`gltf_manifest`] gives: the text, warnings, the manifest's path,
/// the funnel's first steps and the opened file.
pub type GltfManifest = (
    String,
    Vec<String>,
    PathBuf,
    GltfSource,
    std::sync::Arc<crate::gltf::GltfFile>,
);

/// The generated manifest text, its warnings, the manifest's path
/// (`<gltf folder>/<name>.scene.toml`: never written, it names the scene)
/// the funnel's first steps and the opened file (for the resolver).
pub fn gltf_manifest(
    path: &Path,
    materials_root: Option<&Path>,
) -> Result<GltfManifest, crate::gltf::GltfError> {
    let mut warnings = Vec::new();
    let file = std::sync::Arc::new(crate::gltf::GltfFile::open(path, &mut warnings)?);
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let name = crate::gltf::scene::snake_name(&stem, "gltf_scene");
    let root = materials_root
        .map(Path::to_path_buf)
        .or_else(|| default_gltf_materials_root(path));
    let dir = file.dir.clone();
    let scene = crate::gltf::scene::scene_manifest(
        &file,
        &name,
        &dir,
        root.as_deref(),
        &Default::default(),
        &mut warnings,
    )?;
    for m in &scene.mappings {
        for loss in &m.losses {
            warnings.push(format!(
                "{}: material `{}` → {}: drops {loss}",
                crate::gltf::shown(path),
                m.gltf_name,
                m.material
            ));
        }
    }
    let source = GltfSource {
        file: path
            .file_name()
            .map_or(String::new(), |f| f.to_string_lossy().into_owned()),
        materials: scene.materials_in_file,
        materials_used: scene.materials_used,
    };
    Ok((
        scene.manifest(),
        warnings,
        dir.join(format!("{name}{}", parse::SCENE_SUFFIX)),
        source,
        file,
    ))
}

/// A glTF problem as a diagnostic: the file and JSON pointer in the
/// message, the hint as a note.
pub fn gltf_diagnostic(e: &crate::gltf::GltfError) -> Diagnostic<crate::FileId> {
    Diagnostic::error()
        .with_code("gltf")
        .with_message(e.to_string())
        .with_notes(vec![e.hint.clone()])
}
