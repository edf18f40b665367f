//! Building a whole materials folder: discovery, per-material compilation
//! (variants in parallel), aliasing, metadata assembly and library-level files
//! (baked LUTs, the metadata JSON Schema).
//!
//! Output is a map of relative path -> bytes; `output.rs` writes or checks it.
//! Results are collected in a fixed order, so bytes do not depend on thread count.

use crate::cache::UnitCache;
use crate::compose::{self, ENGINE_INTERFACE};
use crate::variant::{self, CompiledVariant, sha256_hex};
use crate::{bake, metadata, prelude};
use codespan_reporting::diagnostic::{Diagnostic, Label};
use rayon::prelude::*;
use sha2::{Digest, Sha256};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use weft_front::model::Material;
use weft_front::{Diagnostics, SourceDb, variants};
use weft_meta::{ENGINE_INTERFACE_VERSION, MaterialMetadata, SCHEMA_VERSION, Variant};

/// Size and sample count of the baked split-sum LUT.
pub const SPLIT_SUM_LUT_SIZE: u32 = 64;
pub const SPLIT_SUM_LUT_SAMPLES: u32 = 1024;
/// Size and sample count are in the name, so a reused file is never a stale bake.
pub const SPLIT_SUM_LUT_PATH: &str = "luts/split_sum_ggx_64x64_1024spp.rg16f";
/// Size and quadrature of the baked Charlie sheen albedo table (bake/sheen.rs):
/// `SHEEN_LUT_SIZE`^2 texels, `THETA_STEPS * PHI_STEPS` = 8192 points each.
pub const SHEEN_LUT_SIZE: u32 = 32;
pub const SHEEN_LUT_PATH: &str = "luts/charlie_albedo_32x32_8192spp.r16f";
const _: () = assert!(
    SHEEN_LUT_SIZE == 32 && bake::sheen::THETA_STEPS * bake::sheen::PHI_STEPS == 8192,
    "SHEEN_LUT_PATH must name the table's size and quadrature"
);

/// A material's metadata and its files (paths relative to its folder).
pub type CompiledMaterial = (MaterialMetadata, Vec<(String, Vec<u8>)>);

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
    /// loaded and checked); see [`crate::shard`].
    pub shard: Option<crate::shard::Shard>,
    /// A shared cache of compile units (material × variant); see [`crate::cache`].
    pub cache_dir: Option<PathBuf>,
    /// How far units read from the cache are trusted: a secret key they
    /// must be signed with, and the share of them compiled again and
    /// compared; see [`crate::cache`] ("Trust").
    pub cache_trust: crate::cache::CacheTrust,
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
    pub kept: Option<crate::unchanged::KeptFiles>,
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

/// Hash of everything a material's output depends on.
pub fn inputs_hash(m: &Material, db: &SourceDb) -> String {
    let mut h = Sha256::new();
    h.update(env!("CARGO_PKG_VERSION"));
    h.update(ENGINE_INTERFACE);
    h.update(db.text(m.file));
    for s in m.sources.iter().chain(&m.pass_files) {
        h.update(&s.rel_path);
        h.update([0]);
        h.update(db.text(s.file));
    }
    // Texture files: a changed PNG rebuilds the material.
    for p in &m.params {
        if let Some(f) = &p.file {
            h.update(&f.path);
            h.update([0]);
            h.update(&f.image.sha256);
            h.update(
                [f.image.width, f.image.height]
                    .map(u32::to_le_bytes)
                    .concat(),
            );
        }
    }
    h.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

/// Compiles one loaded material: every variant, in parallel, then metadata.
/// Returns the material's files relative to its own folder.
pub fn compile_material(
    m: &Material,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<CompiledMaterial> {
    compile_material_cached(m, db, diags, None)
}

/// As [`compile_material`], taking each variant (compile unit) from `cache`
/// when it is there and storing those it compiles (see [`crate::cache`]).
pub fn compile_material_cached(
    m: &Material,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
    cache: Option<&UnitCache>,
) -> Option<CompiledMaterial> {
    let inputs = inputs_hash(m, db);
    let prelude = prelude::generate(m);
    let composed = compose::compose(m, &prelude, db);
    let (module, _info) = compose::parse_and_validate(&composed, m, diags)?;
    if !check_interface(m, &module, diags) {
        return None;
    }
    let fallback = crate::half::fallback_module(m, &prelude, db, diags)?;
    let fallback = fallback.as_ref().map(|(_, f)| f);
    let keys = variants::variants(m);
    let results: Vec<Result<CompiledVariant, String>> = keys
        .par_iter()
        .map(|k| {
            let Some(cache) = cache else {
                return variant::compile_variant(m, &module, fallback, k, &prelude);
            };
            let id = k.id(m);
            let key = UnitCache::unit_key(&inputs, &id);
            if let Some(v) = cache.load(&key, &id) {
                if !cache.should_verify(&key) {
                    return Ok(v);
                }
                let fresh = variant::compile_variant(m, &module, fallback, k, &prelude)?;
                cache.check_unit(&key, &v, &fresh)?;
                return Ok(fresh);
            }
            let v = variant::compile_variant(m, &module, fallback, k, &prelude)?;
            // A cache that cannot be written only costs the next build time.
            let _ = cache.store(&key, &v);
            Ok(v)
        })
        .collect();
    let mut compiled = Vec::new();
    for r in results {
        match r {
            Ok(v) => compiled.push(v),
            Err(msg) => diags.push(
                Diagnostic::error()
                    .with_code("variant")
                    .with_message(msg)
                    .with_labels(vec![
                        Label::primary(m.decl.file, m.decl.span.clone())
                            .with_message("in this material"),
                    ]),
            ),
        }
    }
    if compiled.len() != keys.len() {
        return None;
    }
    let engine = compose::engine_interface_file(db);
    let shown: Vec<String> = compiled
        .iter()
        .map(|v| format!("variant `{}`", v.id))
        .collect();
    if !crate::limits::check_variants(
        m, &shown, &composed, &module, engine, &keys, &compiled, diags,
    ) {
        return None;
    }
    warn_unread_parameters(m, &compiled, diags);
    let aliases = variant::find_aliases(&compiled);
    // Baked tables and texture files first: files of the material whatever
    // its variants read.
    let mut files: Vec<(String, Vec<u8>)> = m
        .tables
        .iter()
        .map(|t| (crate::tables::file_name(t), crate::tables::bake(t).to_vec()))
        .chain(crate::texture_files::files(m))
        .collect();
    let mut variants_meta = Vec::new();
    for ((key, v), alias) in keys.iter().zip(compiled).zip(aliases) {
        let keywords = key
            .keywords
            .iter()
            .map(|&(k, val)| {
                (
                    m.keywords[k].name.clone(),
                    m.keywords[k].values[val].clone(),
                )
            })
            .collect();
        let passes: Vec<String> = m.passes_of(key).map(|p| p.name.clone()).collect();
        // An alias shares its target's files, so it must also draw the same
        // passes (two pass lists over the same entry points stay apart).
        let same_passes = |j: usize| m.passes_of(&keys[j]).map(|p| &p.name).eq(passes.iter());
        let (alias_of, shader) = match alias.filter(|&j| same_passes(j)) {
            Some(j) => (Some(keys[j].id(m)), None),
            None => {
                files.extend(v.files);
                (None, Some(v.shader))
            }
        };
        variants_meta.push(Variant {
            id: v.id,
            tier: m.tiers.values[key.tier].clone(),
            keywords,
            passes,
            alias_of,
            shader,
        });
    }
    let meta = MaterialMetadata {
        schema_version: SCHEMA_VERSION,
        schema_minor: weft_meta::SCHEMA_MINOR,
        engine_interface_version: ENGINE_INTERFACE_VERSION,
        name: m.name.clone(),
        label: weft_meta::Text {
            en: m.label.clone(),
            zh: m.label_zh.clone(),
        },
        description: m.description.as_ref().map(|d| weft_meta::Text {
            en: d.clone(),
            zh: m.description_zh.clone(),
        }),
        inputs_hash: inputs,
        groups: metadata::groups(m),
        parameters: metadata::parameters(m, &prelude),
        keywords: metadata::keywords(m),
        tiers: metadata::tiers(m),
        presets: metadata::presets(m),
        passes: metadata::passes(m),
        vertex_inputs: metadata::vertex_inputs(m),
        limits: (!m.limits.is_default()).then(|| m.limits.clone()),
        variants: variants_meta,
        languages: crate::engine_binding::languages(),
        conventions: Some(weft_meta::Conventions::current()),
        // Measured by `weft bench`, attached at load time from reports/, never built in.
        measurements: None,
    };
    Some((meta, files))
}

/// A parameter that no variant reads does nothing: say so at its declaration.
fn warn_unread_parameters(m: &Material, compiled: &[CompiledVariant], diags: &mut Diagnostics) {
    for p in &m.params {
        if compiled.iter().any(|v| v.shader.reads.contains(&p.name)) {
            continue;
        }
        diags.push(
            Diagnostic::warning()
                .with_code("unread-param")
                .with_message(format!(
                    "parameter `{}` is read by no variant of `{}`",
                    p.name, m.name
                ))
                .with_labels(vec![
                    Label::primary(p.decl.file, p.decl.span.clone())
                        .with_message("changing this value changes nothing"),
                ])
                .with_notes(vec![
                    "use it in the shading code, or remove it from the material".into(),
                ]),
        );
    }
}

/// Passes name entry points that exist with the right stage; vertex stages
/// read only the inputs the material `requires`.
pub(crate) fn check_interface(
    m: &Material,
    module: &naga::Module,
    diags: &mut Diagnostics,
) -> bool {
    let before = diags.error_count();
    for pass in &m.passes {
        let wanted = [
            (
                &pass.vertex,
                naga::ShaderStage::Vertex,
                "vertex",
                &pass.vertex_span,
            ),
            (
                &pass.fragment,
                naga::ShaderStage::Fragment,
                "fragment",
                &pass.fragment_span,
            ),
        ];
        for (name, stage, stage_name, span) in wanted {
            if module
                .entry_points
                .iter()
                .any(|ep| &ep.name == name && ep.stage == stage)
            {
                continue;
            }
            let candidates: Vec<&str> = module
                .entry_points
                .iter()
                .filter(|ep| ep.stage == stage)
                .map(|ep| ep.name.as_str())
                .collect();
            let mut notes = Vec::new();
            if let Some(s) = weft_front::diag::did_you_mean(name, candidates.iter().copied()) {
                notes.push(format!("did you mean `{s}`?"));
            }
            notes.push(if candidates.is_empty() {
                format!("the WGSL defines no @{stage_name} entry point")
            } else {
                format!(
                    "@{stage_name} entry points in the WGSL: {}",
                    candidates.join(", ")
                )
            });
            diags.push(
                Diagnostic::error()
                    .with_code("missing-entry-point")
                    .with_message(format!("pass `{}` names {stage_name} entry point `{name}`, which the WGSL does not define", pass.name))
                    .with_labels(vec![Label::primary(pass.decl.file, span.clone()).with_message(format!("no @{stage_name} fn `{name}`"))])
                    .with_notes(notes),
            );
        }
    }
    let locations = crate::reflect::vertex_locations(module);
    for loc in locations {
        if !m.requires.iter().any(|a| a.location() == loc) {
            let name = weft_front::model::VertexAttribute::ALL
                .iter()
                .find(|a| a.location() == loc)
                .map_or(format!("location {loc}"), |a| a.name().to_string());
            diags.push(
                Diagnostic::error()
                    .with_code("missing-require")
                    .with_message(format!("the vertex stage reads `{name}` (@location({loc})) but the material does not require it"))
                    .with_labels(vec![Label::primary(m.file, m.requires_span.clone()).with_message(format!("`{name}` missing here"))])
                    .with_notes(vec![format!("add \"{name}\" to `requires` in [material]")]),
            );
        }
    }
    diags.error_count() == before
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
        files.push((crate::tables::file_name(t), crate::tables::bake(t).to_vec()));
    }
    files.extend(crate::texture_files::files(m));
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
    let pool = crate::nesting::compiler_pool(options.jobs);
    let mut out = BuildOutput::default();
    let mut previous = crate::unchanged::Previous::read(paths, options, &pool);
    let Ok(cache) = open_cache(options, &mut diags) else {
        return Err((db, diags));
    };
    let mut names = std::collections::HashSet::new();
    let mut library_inputs = Sha256::new();
    library_inputs.update(crate::cache::TOOLCHAIN_ID);
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
            None => {
                pool.install(|| compile_material_cached(&m, &mut db, &mut diags, cache.as_ref()))
            }
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
fn record_kept(out: &mut BuildOutput, dir: &Path, name: &str, k: crate::unchanged::Kept) {
    let kept = out.kept.get_or_insert_with(|| crate::unchanged::KeptFiles {
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
