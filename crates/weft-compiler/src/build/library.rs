//! Building a whole materials folder: discovery, per-material compilation
//! (variants in parallel), aliasing, metadata assembly and library-level files
//! (baked LUTs, the metadata JSON Schema).
//!
//! Output is a map of relative path -> bytes; `output.rs` writes or checks it.
//! Results are collected in a fixed order, so bytes do not depend on thread count.

use crate::build::cache::UnitCache;
// The per-material compile and its constants, kept at their old paths for
// `build.rs` users (`weft_compiler::library::compile_material`).
use crate::bake;
use crate::compile::digest::sha256_hex;
pub use crate::compile::material::{
    CompiledMaterial, SHEEN_LUT_PATH, SHEEN_LUT_SIZE, SPLIT_SUM_LUT_PATH, SPLIT_SUM_LUT_SAMPLES,
    SPLIT_SUM_LUT_SIZE, compile_material, inputs_hash,
};
use crate::compile::material::{VariantStore, compile_material_with};
use codespan_reporting::diagnostic::{Diagnostic, Label};
use sha2::{Digest, Sha256};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use weft_front::model::Material;
use weft_front::{Diagnostics, SourceDb};
use weft_meta::MaterialMetadata;

#[derive(Clone, Debug, Default)]
pub struct BuildOptions {
    /// Worker threads (None: rayon's default).
    pub jobs: Option<usize>,
    /// Reuse a material's files from this output folder when its inputs are unchanged.
    pub reuse_from: Option<PathBuf>,
    /// With `reuse_from`: leave an unchanged material's files where they are,
    /// unread (listed in [`BuildOutput::kept`], not in `files`); see
    /// [`BuildOutput::up_to_date`] and [`BuildOutput::load_kept`].
    pub keep_unchanged: bool,
    /// Compile only the materials of this shard (every material is still
    /// loaded and checked); see [`crate::build::shard`].
    pub shard: Option<crate::build::shard::Shard>,
    /// A shared cache of compile units (material × variant); see [`crate::build::cache`].
    pub cache_dir: Option<PathBuf>,
    /// How far units read from the cache are trusted: a secret key they
    /// must be signed with, and the share of them compiled again and
    /// compared; see [`crate::build::cache`] ("Trust").
    pub cache_trust: crate::build::cache::CacheTrust,
    /// For a streaming build whose sink writes the files: do not keep each
    /// material's metadata in [`BuildOutput::materials`] as well (it is in
    /// the `.meta.json` handed over); only [`BuildOutput::dropped_metadata`]
    /// counts them. Keeps memory to one material's worth.
    pub drop_metadata: bool,
}

/// Everything a build produced: files relative to the output folder.
#[derive(Default)]
pub struct BuildOutput {
    pub files: BTreeMap<String, Vec<u8>>,
    /// Metadata of every material, except those `kept` on disk (and all,
    /// with [`BuildOptions::drop_metadata`]).
    pub materials: Vec<MaterialMetadata>,
    /// Materials compiled whose metadata was not kept ([`BuildOptions::drop_metadata`]).
    pub dropped_metadata: usize,
    /// Materials whose files were reused unchanged.
    pub reused: Vec<String>,
    /// With `keep_unchanged`: the files of reused materials, left in
    /// `reuse_from` (not in `files`).
    pub kept: Option<crate::build::unchanged::KeptFiles>,
    pub variant_count: usize,
    /// With `cache_dir`: compile units served from the cache, and compiled
    /// (then stored).
    pub cache_hits: usize,
    pub cache_misses: usize,
    /// Units found but refused: not signed with the cache key (then compiled).
    pub cache_rejected: usize,
    /// Hits compiled again and found byte-identical (`CacheTrust::verify_percent`).
    pub cache_verified: usize,
    /// Warnings (e.g. parameters no variant reads), with the files they point into.
    pub warnings: Option<(SourceDb, Diagnostics)>,
    /// A hash of every loaded material's name and inputs hash and of the
    /// toolchain, shard or not: equal exactly when two builds had the same
    /// inputs (a shard records it so `weft merge` can check its shards).
    pub library_inputs: String,
}

/// Material TOML files in a materials folder: `<dir>/<name>/*.toml`, sorted.
pub fn discover(materials_dir: &Path) -> std::io::Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(materials_dir)? {
        let dir = entry?.path();
        if !dir.is_dir() || dir.file_name().is_some_and(|n| n == "lib") {
            continue;
        }
        for f in std::fs::read_dir(&dir)? {
            let f = f?.path();
            if f.extension().is_some_and(|e| e == "toml") {
                out.push(f);
            }
        }
    }
    out.sort();
    Ok(out)
}

/// Reads a previous build's files for a material if its inputs are unchanged.
fn reuse(out_dir: &Path, m: &Material, hash: &str) -> Option<CompiledMaterial> {
    let dir = out_dir.join(&m.name);
    let meta_bytes = std::fs::read(dir.join(format!("{}.meta.json", m.name))).ok()?;
    let meta: MaterialMetadata = serde_json::from_slice(&meta_bytes).ok()?;
    if meta.inputs_hash != hash {
        return None;
    }
    let mut files = Vec::new();
    for v in &meta.variants {
        for f in v.shader.iter().flat_map(|s| s.all_files()) {
            let bytes = std::fs::read(dir.join(&f.path)).ok()?;
            if sha256_hex(&bytes) != f.sha256 {
                return None;
            }
            files.push((f.path.clone(), bytes));
        }
    }
    // Baked tables are no variant's files; they follow from the TOML.
    for t in &m.tables {
        files.push((
            crate::compile::tables::file_name(t),
            crate::compile::tables::bake(t).to_vec(),
        ));
    }
    files.extend(crate::compile::texture_files::files(m));
    Some((meta, files))
}

/// Compiles every material under `materials_dir` (see [`build_materials`]).
pub fn build_library(
    materials_dir: &Path,
    options: &BuildOptions,
    progress: &(dyn Fn(usize, usize, &str) + Sync),
) -> Result<BuildOutput, (SourceDb, Diagnostics)> {
    match discover(materials_dir) {
        Ok(paths) => build_materials(&paths, Some(materials_dir), options, progress),
        Err(e) => {
            let mut diags = Diagnostics::new();
            diags.push(Diagnostic::error().with_code("io").with_message(format!(
                "cannot read materials folder `{}`: {e}",
                materials_dir.display()
            )));
            Err((SourceDb::new(), diags))
        }
    }
}

/// Compiles the given material files. `root` is the materials root includes
/// resolve against (None: found per file, see [`weft_front::find_root`]).
///
/// On any error, returns the diagnostics (with the files they point into);
/// nothing is written by this function.
pub fn build_materials(
    paths: &[PathBuf],
    root: Option<&Path>,
    options: &BuildOptions,
    progress: &(dyn Fn(usize, usize, &str) + Sync),
) -> Result<BuildOutput, (SourceDb, Diagnostics)> {
    let mut files = BTreeMap::new();
    let mut out = build_materials_streaming(paths, root, options, progress, &mut |rel, bytes| {
        files.insert(rel, bytes);
        Ok(())
    })?;
    out.files = files;
    Ok(out)
}

/// As [`build_materials`], but hands every file to `sink` (path relative to
/// the output folder, bytes) as soon as its material is compiled instead of
/// collecting them in [`BuildOutput::files`], which stays empty: a sink that
/// writes them to disk holds one material's files at a time, not the
/// library's. Files come material by material, in `paths` order, then the
/// library-wide files (LUTs, schemas). On any error the build stops and the
/// files already handed over belong to a failed build (discard them); an
/// error from `sink` is reported as an `io` diagnostic.
pub fn build_materials_streaming(
    paths: &[PathBuf],
    root: Option<&Path>,
    options: &BuildOptions,
    progress: &(dyn Fn(usize, usize, &str) + Sync),
    sink: &mut dyn FnMut(String, Vec<u8>) -> std::io::Result<()>,
) -> Result<BuildOutput, (SourceDb, Diagnostics)> {
    let mut db = SourceDb::new();
    let mut diags = Diagnostics::new();
    let pool = crate::compile::nesting::compiler_pool(options.jobs);
    let mut out = BuildOutput::default();
    let mut previous = crate::build::unchanged::Previous::read(paths, options, &pool);
    let Ok(cache) = open_cache(options, &mut diags) else {
        return Err((db, diags));
    };
    let mut names = std::collections::HashSet::new();
    let mut library_inputs = Sha256::new();
    library_inputs.update(crate::build::cache::TOOLCHAIN_ID);
    library_inputs.update([0]);
    for (i, path) in paths.iter().enumerate() {
        let root = root.map_or_else(|| weft_front::find_root(path), Path::to_path_buf);
        let Some(m) = weft_front::load_material(path, &root, &mut db, &mut diags) else {
            continue;
        };
        if !names.insert(m.name.clone()) {
            diags.push(
                Diagnostic::error()
                    .with_code("duplicate")
                    .with_message(format!("two materials are named `{}`", m.name))
                    .with_labels(vec![
                        Label::primary(m.decl.file, m.decl.span.clone())
                            .with_message("second material with this name"),
                    ]),
            );
            continue;
        }
        let hash = inputs_hash(&m, &db);
        library_inputs.update(format!("{}\t{hash}\n", m.name));
        if options.shard.is_some_and(|s| !s.contains(&m.name)) {
            continue;
        }
        progress(i, paths.len(), &m.name);
        if let Some(dir) = options
            .reuse_from
            .as_deref()
            .filter(|_| options.keep_unchanged)
            && let Some(k) = previous.keep(dir, &m.name, &hash)
        {
            record_kept(&mut out, dir, &m.name, k);
            continue;
        }
        let reused = options
            .reuse_from
            .as_deref()
            .and_then(|dir| reuse(dir, &m, &hash));
        let result = match reused {
            Some(r) => {
                out.reused.push(m.name.clone());
                Some(r)
            }
            None => pool.install(|| {
                compile_material_with(
                    &m,
                    &mut db,
                    &mut diags,
                    cache.as_ref().map(|c| c as &dyn VariantStore),
                )
            }),
        };
        // Nothing more is handed over once the build has failed.
        if let Some((meta, files)) = result.filter(|_| !diags.has_errors())
            && !hand_over(&m.name, meta, files, options, &mut out, sink, &mut diags)
        {
            return Err((db, diags));
        }
    }
    out.library_inputs = library_inputs
        .finalize()
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    if let Some(c) = &cache {
        out.cache_hits = c.hits();
        out.cache_misses = c.misses();
        out.cache_rejected = c.rejected();
        out.cache_verified = c.verified();
    }
    if diags.has_errors() {
        return Err((db, diags));
    }
    progress(paths.len(), paths.len(), "");
    let mut library = BTreeMap::new();
    add_library_files(&mut library, options.reuse_from.as_deref());
    for (rel, bytes) in library {
        if !put(sink, rel, bytes, &mut diags) {
            return Err((db, diags));
        }
    }
    if !diags.is_empty() {
        out.warnings = Some((db, diags));
    }
    Ok(out)
}

/// The shared cache of compile units, when `--cache-dir` names one; a
/// folder that cannot be used is an `io` diagnostic (`Err`).
fn open_cache(options: &BuildOptions, diags: &mut Diagnostics) -> Result<Option<UnitCache>, ()> {
    match options
        .cache_dir
        .as_deref()
        .map(|dir| UnitCache::open(dir, options.cache_trust.clone()))
    {
        None => Ok(None),
        Some(Ok(c)) => Ok(Some(c)),
        Some(Err(e)) => {
            diags.push(
                Diagnostic::error()
                    .with_code("io")
                    .with_message(format!("cannot use the cache folder: {e}"))
                    .with_notes(vec![
                        "give --cache-dir a folder this user can create and write".into(),
                    ]),
            );
            Err(())
        }
    }
}

/// A material whose files stay in `dir` unread (the no-change fast path).
fn record_kept(out: &mut BuildOutput, dir: &Path, name: &str, k: crate::build::unchanged::Kept) {
    let kept = out
        .kept
        .get_or_insert_with(|| crate::build::unchanged::KeptFiles {
            dir: dir.to_path_buf(),
            ..Default::default()
        });
    for (file, sha) in k.files {
        kept.files.insert(format!("{name}/{file}"), sha);
    }
    kept.materials.push(name.to_string());
    out.reused.push(name.to_string());
    out.variant_count += k.variants;
}

/// Hands a compiled material's files and then its metadata to `sink`;
/// false when the sink failed (reported in `diags`).
fn hand_over(
    name: &str,
    meta: MaterialMetadata,
    files: Vec<(String, Vec<u8>)>,
    options: &BuildOptions,
    out: &mut BuildOutput,
    sink: &mut dyn FnMut(String, Vec<u8>) -> std::io::Result<()>,
    diags: &mut Diagnostics,
) -> bool {
    out.variant_count += meta.variants.len();
    for (file, bytes) in files {
        if !put(sink, format!("{name}/{file}"), bytes, diags) {
            return false;
        }
    }
    let mut json = serde_json::to_string_pretty(&meta).expect("metadata serialises");
    json.push('\n');
    let rel = format!("{0}/{0}.meta.json", name);
    if !put(sink, rel, json.into_bytes(), diags) {
        return false;
    }
    if options.drop_metadata {
        out.dropped_metadata += 1;
    } else {
        out.materials.push(meta);
    }
    true
}

/// One file to `sink`; false when it failed (an `io` diagnostic).
fn put(
    sink: &mut dyn FnMut(String, Vec<u8>) -> std::io::Result<()>,
    rel: String,
    bytes: Vec<u8>,
    diags: &mut Diagnostics,
) -> bool {
    let message = format!("cannot write `{rel}`");
    match sink(rel, bytes) {
        Ok(()) => true,
        Err(e) => {
            diags.push(
                Diagnostic::error()
                    .with_code("io")
                    .with_message(format!("{message}: {e}")),
            );
            false
        }
    }
}

/// Files shared by every material: baked LUTs and the metadata schema.
/// With `reuse_from`, a LUT already baked there (same size and sample count,
/// same toolchain version) is reused instead of baked again.
pub fn add_library_files(files: &mut BTreeMap<String, Vec<u8>>, reuse_from: Option<&Path>) {
    let expected_len = (SPLIT_SUM_LUT_SIZE * SPLIT_SUM_LUT_SIZE * 4) as usize;
    let reused = reuse_from
        .and_then(|dir| std::fs::read(dir.join(SPLIT_SUM_LUT_PATH)).ok())
        .filter(|b| b.len() == expected_len);
    let lut = reused.unwrap_or_else(|| {
        let lut = bake::split_sum::split_sum_lut(SPLIT_SUM_LUT_SIZE, SPLIT_SUM_LUT_SAMPLES);
        bake::split_sum::encode_rg16f(&lut)
    });
    files.insert(SPLIT_SUM_LUT_PATH.into(), lut);
    let sheen_len = (SHEEN_LUT_SIZE * SHEEN_LUT_SIZE * 2) as usize;
    let sheen = reuse_from
        .and_then(|dir| std::fs::read(dir.join(SHEEN_LUT_PATH)).ok())
        .filter(|b| b.len() == sheen_len)
        .unwrap_or_else(|| {
            let (t, p) = (bake::sheen::THETA_STEPS, bake::sheen::PHI_STEPS);
            bake::sheen::encode_r16f(&bake::sheen::charlie_albedo_lut(SHEEN_LUT_SIZE, t, p))
        });
    files.insert(SHEEN_LUT_PATH.into(), sheen);
    files.insert(
        "metadata.schema.json".into(),
        weft_meta::metadata_json_schema().into_bytes(),
    );
    files.insert(
        crate::scene::SCENE_METADATA_SCHEMA_PATH.into(),
        weft_meta::scene::scene_metadata_json_schema().into_bytes(),
    );
}
