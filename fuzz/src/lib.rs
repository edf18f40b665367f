//! The bodies of weft's fuzz targets, shared by the libFuzzer binaries in
//! `fuzz_targets/` and by the test suite's smoke run (`tests/inputs/fuzz_smoke.rs`
//! includes this file with `#[path]`). Each takes arbitrary bytes and must
//! return, whatever they are: every problem in the input is a diagnostic,
//! never a panic, an abort or a hang. Diagnostics are rendered too, as the
//! CLI would show them, so a span that points outside its file is caught.
//!
//! Inputs (docs/fuzzing.md):
//! - [`material_front`]: a material TOML file (bytes read as UTF-8, lossily).
//! - [`material_compile`]: a material TOML file, then WGSL files, each after
//!   a line `%%% <path>` (path relative to the materials root; the TOML is
//!   `m/m.toml`, so `%%% m/m.wgsl` is its default source). The shipped
//!   `materials/lib/*.wgsl` and shared pass files `*.pass.toml` are there
//!   too unless the input replaces one.
//! - [`scene`]: a scene manifest, read as if it were
//!   `tests/diagnostics/scenes/bad/fuzz.scene.toml` (so `materials =
//!   "../../../../materials"` names the shipped materials, as the bad-scene
//!   corpus does).

use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use weft_front::toml_reader::Cx;
use weft_front::{Diagnostics, SourceDb};

/// Root of the in-memory materials. Not a real folder: nothing is read from it.
pub const MEMORY_ROOT: &str = "/weft-fuzz/materials";
/// Where the fuzzed material TOML sits under [`MEMORY_ROOT`].
pub const TOML_PATH: &str = "m/m.toml";
/// Marks the start of a WGSL file in a [`material_compile`] input: a line
/// that starts with `%%% ` (the rest of the line is the file's path).
pub const FILE_MARK: &str = "\n%%% ";
/// At most this many WGSL files are taken from one input.
pub const MAX_FILES: usize = 8;
/// Variants compiled per [`material_compile`] input, spread over the variant list.
pub const MAX_VARIANTS: usize = 3;

/// The workspace root (this file's package is `fuzz/` or `tests/`, one level down).
pub fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("package folder has a parent")
        .to_path_buf()
}

/// The shipped `materials/lib/*.wgsl` and `*.pass.toml` (shared passes), as
/// (`lib/<file>`, text), read once.
pub fn shipped_lib() -> &'static [(String, String)] {
    static LIB: OnceLock<Vec<(String, String)>> = OnceLock::new();
    LIB.get_or_init(|| {
        let dir = repo().join("materials/lib");
        let mut files: Vec<(String, String)> = std::fs::read_dir(&dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .map(|e| e.expect("lib entry").path())
            .filter(|p| {
                let name = p.file_name().unwrap_or_default().to_string_lossy();
                name.ends_with(".wgsl") || name.ends_with(".pass.toml")
            })
            .map(|p| {
                let name = p.file_name().expect("name").to_string_lossy();
                let text = std::fs::read_to_string(&p).expect("lib file");
                (format!("lib/{name}"), text)
            })
            .collect();
        files.sort();
        files
    })
}

/// Target (a): the material TOML front end. Parse, resolve includes (in
/// memory, where no WGSL file exists: every source is missing), check.
pub fn material_front(data: &[u8]) -> String {
    let text = String::from_utf8_lossy(data);
    let mut db = SourceDb::new();
    let mut diags = Diagnostics::new();
    let _ = weft_front::load_material_in_memory(
        TOML_PATH,
        &text,
        &[],
        Path::new(MEMORY_ROOT),
        &mut db,
        &mut diags,
    );
    diags.render_plain(&db)
}

/// Splits a [`material_compile`] input into the TOML text and its WGSL files.
pub fn split_files(text: &str) -> (&str, Vec<(String, String)>) {
    let mut parts = text.split(FILE_MARK);
    let toml = parts.next().unwrap_or_default();
    let files = parts
        .take(MAX_FILES)
        .map(|part| {
            let (path, body) = part.split_once('\n').unwrap_or((part, ""));
            (path.trim().to_string(), body.to_string())
        })
        .collect();
    (toml, files)
}

/// Target (b): includes, prelude, composition, naga parse + validate, the
/// pass interface, and per variant specialisation, validation, every
/// backend and reflection (`weft_compiler::compile_in_memory`, at most
/// [`MAX_VARIANTS`] variants).
pub fn material_compile(data: &[u8]) -> String {
    let text = String::from_utf8_lossy(data);
    let (toml, mut files) = split_files(&text);
    for (path, body) in shipped_lib() {
        if !files.iter().any(|(p, _)| p == path) {
            files.push((path.clone(), body.clone()));
        }
    }
    let mut db = SourceDb::new();
    let mut diags = Diagnostics::new();
    let _ = weft_compiler::compile_in_memory(
        TOML_PATH,
        toml,
        &files,
        Path::new(MEMORY_ROOT),
        MAX_VARIANTS,
        &mut db,
        &mut diags,
    );
    diags.render_plain(&db)
}

/// The path a fuzzed scene is read as.
pub fn scene_path() -> &'static Path {
    static PATH: OnceLock<PathBuf> = OnceLock::new();
    PATH.get_or_init(|| repo().join("tests/diagnostics/scenes/bad/fuzz.scene.toml"))
}

/// Target (c): scene manifests. Parse, then resolve every instance against
/// the materials it names (loaded from disk: the shipped materials, the
/// scene corpus' and the documentation example's).
pub fn scene(data: &[u8]) -> String {
    let text = String::from_utf8_lossy(data).into_owned();
    let path = scene_path();
    let mut db = SourceDb::new();
    let mut diags = Diagnostics::new();
    let file = db.add(path, "fuzz.scene.toml".into(), text.clone());
    'resolve: {
        let mut cx = Cx {
            file,
            diags: &mut diags,
        };
        let Some(doc) = weft_front::scene::parse::parse_document(&text, &mut cx) else {
            break 'resolve;
        };
        let Some(parsed) = weft_front::scene::parse::parse_manifest(doc.get_ref(), path, &mut cx)
        else {
            break 'resolve;
        };
        let _ = weft_front::scene::resolve::resolve(parsed, &mut db, &mut diags);
    }
    diags.render_plain(&db)
}

/// Target (d): glTF files (`.gltf` JSON or `.glb`, in memory: only
/// embedded buffers). Open and check, map nodes, camera, lights and
/// materials into a scene manifest, then read every mesh primitive.
pub fn gltf(data: &[u8]) -> String {
    use weft_front::gltf::{GltfFile, meshes, scene};
    let path = Path::new("fuzz.glb");
    let mut warnings = Vec::new();
    let mut out = String::new();
    match GltfFile::from_bytes(path, None, data.to_vec(), &mut warnings) {
        Err(e) => out.push_str(&format!("{e}\n{}\n", e.hint)),
        Ok(file) => {
            match scene::scene_manifest(
                &file,
                "fuzz",
                Path::new("."),
                None,
                &Default::default(),
                &mut warnings,
            ) {
                Ok(s) => out.push_str(&s.manifest()),
                Err(e) => out.push_str(&format!("{e}\n")),
            }
            // Every texture's image decoded as a scene would bind it.
            for t in 0..file.document.textures().count().min(16) {
                if let Err(e) = weft_front::scene::images::gltf_texture(&file, t) {
                    out.push_str(&format!("{e}\n"));
                }
            }
            for (m, mesh) in file.document.meshes().enumerate().take(16) {
                for p in 0..mesh.primitives().count().min(16) {
                    if let Err(e) = meshes::read_primitive(&file, m, p, None) {
                        out.push_str(&format!("{e}\n"));
                    }
                }
            }
            // And as each node that draws a mesh poses it (skin, weights).
            for node in file.document.nodes().take(16) {
                let Some(mesh) = node.mesh() else { continue };
                for p in 0..mesh.primitives().count().min(16) {
                    if let Err(e) =
                        meshes::read_primitive(&file, mesh.index(), p, Some(node.index()))
                    {
                        out.push_str(&format!("{e}\n"));
                    }
                }
            }
        }
    }
    for w in warnings {
        out.push_str(&w);
        out.push('\n');
    }
    out
}
