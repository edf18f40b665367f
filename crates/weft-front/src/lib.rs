//! weft front end: reads a material's TOML and WGSL sources into a checked
//! [`Material`], reporting every problem it finds as a codespan diagnostic.
//!
//! Pipeline: [`parse`] (TOML -> model, local checks) -> [`includes`] (WGSL
//! sources, in dependency order; [`texture_files`] the PNGs texture
//! parameters ship) -> [`check`] (cross-references, budget).

pub mod check;
pub mod condition;
pub mod diag;
pub mod gltf;
pub mod gpu_numbers;
pub mod includes;
pub mod model;
pub mod parse;
pub mod scene;
pub mod texture_files;
pub mod toml_reader;
pub mod values;
pub mod variant_space;
pub mod variants;

pub use diag::{Diagnostics, FileId, SourceDb, Span};
pub use model::Material;
/// Curve, gradient and colour baking (shared with engines through weft-meta).
pub use weft_meta::bake as samples;

use includes::{Origin, Resolver};
use std::path::{Path, PathBuf};
use toml_reader::Cx;

/// The materials root for a TOML file: the nearest ancestor directory that has
/// a `lib/` folder, else the file's own directory.
pub fn find_root(toml_path: &Path) -> PathBuf {
    let abs = toml_path
        .canonicalize()
        .unwrap_or_else(|_| toml_path.to_path_buf());
    let mut dir = abs.parent();
    while let Some(d) = dir {
        if d.join("lib").is_dir() {
            return d.to_path_buf();
        }
        dir = d.parent();
    }
    abs.parent().map(Path::to_path_buf).unwrap_or_default()
}

/// Reads a TOML file into `db` (canonical path; named relative to the working
/// directory); an unreadable file is an `io` error.
pub(crate) fn read_source(
    path: &Path,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<(PathBuf, FileId, String)> {
    let abs = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
    match weft_meta::files::read_regular_string(&abs, weft_meta::files::MAX_TEXT_BYTES) {
        Ok(text) => {
            let file = db.add(&abs, includes::display_path(&abs), text.clone());
            Some((abs, file, text))
        }
        Err(e) => {
            diags.push(
                codespan_reporting::diagnostic::Diagnostic::error()
                    .with_code("io")
                    .with_message(format!("cannot read `{}`: {e}", path.display())),
            );
            None
        }
    }
}

/// Loads and checks one material. On error, `None` and the reasons in `diags`.
pub fn load_material(
    path: &Path,
    root: &Path,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<Material> {
    let (abs, file, text) = read_source(path, db, diags)?;
    load_loaded(&abs, file, &text, root, false, db, diags)
}

/// Loads and checks one material held in memory, reading nothing from disk
/// (for fuzzing and tools that keep sources in memory). `toml_path` and the
/// paths in `files` (WGSL text by path) are relative to `root`, as in
/// `"silk/silk.toml"` and `"lib/brdf.wgsl"`; a source or include not in
/// `files` is missing. Diagnostics name the files by those relative paths.
pub fn load_material_in_memory(
    toml_path: &str,
    toml_text: &str,
    files: &[(String, String)],
    root: &Path,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<Material> {
    let add = |db: &mut SourceDb, rel: &str, text: &str| {
        db.add(
            &includes::normalize(&root.join(rel)),
            rel.to_string(),
            text.to_string(),
        )
    };
    for (rel, text) in files {
        add(db, rel, text);
    }
    let abs = includes::normalize(&root.join(toml_path));
    let file = add(db, toml_path, toml_text);
    load_loaded(&abs, file, toml_text, root, true, db, diags)
}

/// Parses an already-read material TOML, resolves its WGSL sources (from
/// `db` alone when `in_memory`) and checks the result.
fn load_loaded(
    abs: &Path,
    file: FileId,
    text: &str,
    root: &Path,
    in_memory: bool,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<Material> {
    let before = diags.error_count();
    if !in_memory && !includes::material_inside_root(abs, root, file, diags) {
        return None;
    }
    // Shared pass files first: the parser merges their declarations.
    let pass_files: Vec<(String, FileId, String)> = {
        let mut resolver = if in_memory {
            Resolver::in_memory(db, diags, root)
        } else {
            Resolver::new(db, diags, root)
        };
        let mut read = Vec::new();
        for (rel, span) in parse::pass_include_entries(text) {
            if let Some(id) = resolver.read(&rel, Origin { file, span }) {
                read.push((rel, id));
            }
        }
        read.into_iter()
            .map(|(rel, id)| {
                let text = db.text(id).to_string();
                (rel, id, text)
            })
            .collect()
    };
    let mut material = {
        let mut cx = Cx { file, diags };
        parse::parse_material(text, abs, root, &pass_files, &mut cx)?
    };

    // WGSL sources: the material's own file last, its includes first.
    let (source, extra) = parse::source_entries(text);
    let (source_rel, source_span) = source.unwrap_or_else(|| {
        let stem = abs
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        (format!("{stem}.wgsl"), material.decl.span.clone())
    });
    let mut resolver = if in_memory {
        Resolver::in_memory(db, diags, root)
    } else {
        Resolver::new(db, diags, root)
    };
    for (inc, span) in extra {
        resolver.include(&inc, Origin { file, span });
    }
    for (inc, loc) in &material.pass_sources {
        resolver.include(
            inc,
            Origin {
                file: loc.file,
                span: loc.span.clone(),
            },
        );
    }
    let dir = abs.parent().unwrap_or(Path::new("."));
    resolver.source(
        &source_rel,
        &dir.join(&source_rel),
        Origin {
            file,
            span: source_span,
        },
    );
    texture_files::load(&mut material, &mut resolver, in_memory);
    material.sources = resolver.finish();

    check::check(&mut material, diags);
    (diags.error_count() == before).then_some(material)
}
