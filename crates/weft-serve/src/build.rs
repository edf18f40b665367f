//! The in-memory build: the materials folder compiled with
//! `weft_compiler::build_library` (nothing written to the materials' output
//! folder), its metadata and files held as one immutable [`Snapshot`].
//!
//! Rebuilds reuse the unchanged materials of the last good build: its files
//! are kept in a private cache folder that the next build reads as its
//! `reuse_from` (the same no-change path `weft build` takes), so an edit
//! recompiles only the material it touched, and the LUTs are baked once.

use crate::ServeOptions;
use crate::tier_costs::TierCosts;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;
use std::sync::{Arc, Mutex};
use weft_compiler::{BuildOptions, BuildOutput};
use weft_meta::MaterialMetadata;

/// One material of a good build.
pub struct MaterialEntry {
    pub metadata: MaterialMetadata,
    /// The metadata as served (measurements and the GPU model's tier costs
    /// attached when the reports have them: `tier_costs`).
    pub json: Vec<u8>,
}

/// A good build: every material's metadata and every generated file
/// (`<material>/<file>`, `luts/…`), as `weft build` would write them.
pub struct Snapshot {
    pub materials: Vec<MaterialEntry>,
    pub files: BTreeMap<String, Vec<u8>>,
    disassembly: Mutex<HashMap<String, Arc<Vec<u8>>>>,
}

impl Snapshot {
    pub fn material(&self, name: &str) -> Option<&MaterialEntry> {
        self.materials.iter().find(|m| m.metadata.name == name)
    }

    /// The SPIR-V file `path` disassembled (rspirv's text form), cached.
    pub fn disassembly(&self, path: &str) -> Option<Arc<Vec<u8>>> {
        if let Some(hit) = self.disassembly.lock().ok()?.get(path) {
            return Some(hit.clone());
        }
        let bytes = self.files.get(path)?;
        let text = disassemble(bytes);
        let text = Arc::new(text.into_bytes());
        if let Ok(mut cache) = self.disassembly.lock() {
            cache.insert(path.to_string(), text.clone());
        }
        Some(text)
    }
}

fn disassemble(bytes: &[u8]) -> String {
    use rspirv::binary::Disassemble;
    match rspirv::dr::load_bytes(bytes) {
        Ok(module) => module.disassemble(),
        Err(e) => format!("; this SPIR-V file does not parse: {e}\n"),
    }
}

/// What the page is told about the build it looks at.
#[derive(Clone)]
pub struct BuildStatus {
    /// Counts build attempts; the page refetches when it changes.
    pub generation: u64,
    /// The last good build (kept when a later build fails).
    pub snapshot: Option<Arc<Snapshot>>,
    /// Diagnostics of the latest build, exactly as `weft build` prints them
    /// (without colour); None when it succeeded.
    pub error: Option<String>,
    /// Warnings of the last good build, as printed.
    pub warnings: Option<String>,
    /// Wall time of the latest build.
    pub build_ms: u64,
}

/// Builds the materials folder; keeps the last good build's files for reuse.
pub(crate) struct Builder {
    options: ServeOptions,
    /// The last good build's files (`reuse_from` of the next build).
    cache: Option<tempfile::TempDir>,
}

impl Builder {
    pub fn new(options: ServeOptions) -> Builder {
        Builder {
            options,
            cache: tempfile::Builder::new()
                .prefix("weft-serve-")
                .tempdir()
                .ok(),
        }
    }

    /// One build; `previous` supplies the generation and the last good build.
    pub fn build(&mut self, previous: Option<&BuildStatus>) -> BuildStatus {
        let started = std::time::Instant::now();
        let generation = previous.map_or(1, |p| p.generation + 1);
        let cache_dir = self.cache.as_ref().map(|c| c.path().join("out"));
        let result = compile(&self.options.materials, cache_dir.as_deref());
        let build_ms = started.elapsed().as_millis() as u64;
        match result {
            Ok(out) => {
                if let Some(dir) = &cache_dir {
                    // Only a speed-up: a failure just means a full rebuild next time.
                    let _ = weft_compiler::output::write_atomically(dir, &out.files, &[]);
                }
                let warnings = out
                    .warnings
                    .as_ref()
                    .map(|(db, diags)| diags.render_plain(db));
                let snapshot = snapshot(out, &self.options.reports_dir());
                BuildStatus {
                    generation,
                    snapshot: Some(Arc::new(snapshot)),
                    error: None,
                    warnings,
                    build_ms,
                }
            }
            Err(error) => BuildStatus {
                generation,
                snapshot: previous.and_then(|p| p.snapshot.clone()),
                error: Some(error),
                warnings: previous.and_then(|p| p.warnings.clone()),
                build_ms,
            },
        }
    }
}

/// A single build with no cache (`--export`).
pub(crate) fn build_once(options: &ServeOptions) -> BuildStatus {
    let mut builder = Builder {
        options: options.clone(),
        cache: None,
    };
    builder.build(None)
}

/// Compiles the folder; on error, the diagnostics as `weft build` prints
/// them. A panic in the compiler becomes an error too: the server stays up.
fn compile(dir: &Path, reuse: Option<&Path>) -> Result<BuildOutput, String> {
    let options = BuildOptions {
        reuse_from: reuse.filter(|d| d.exists()).map(Path::to_path_buf),
        ..BuildOptions::default()
    };
    let run = || {
        match weft_compiler::library::discover(dir) {
            Ok(found) if found.is_empty() => {
                return Err(format!(
                    "error[no-material]: no material in `{}`\n  = a materials folder holds one folder per material, `<name>/<name>.toml` (and `lib/` for shared WGSL)\n",
                    dir.display()
                ));
            }
            _ => {}
        }
        weft_compiler::build_library(dir, &options, &|_, _, _| {}).map_err(|(db, diags)| {
            let n = diags.error_count();
            format!(
                "{}error: {n} error{} found; nothing was written\n",
                diags.render_plain(&db),
                if n == 1 { "" } else { "s" }
            )
        })
    };
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(run)) {
        Ok(r) => r,
        Err(panic) => {
            let what = panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_else(|| "unknown panic".into());
            Err(format!(
                "error: the compiler panicked: {what}\n  = this is a bug in weft; the last good build stays visible\n"
            ))
        }
    }
}

fn snapshot(out: BuildOutput, reports: &Path) -> Snapshot {
    let costs = TierCosts::load(reports);
    let mut materials: Vec<MaterialEntry> = out
        .materials
        .into_iter()
        .map(|mut metadata| {
            let json = costs.served_json(&mut metadata);
            MaterialEntry { metadata, json }
        })
        .collect();
    materials.sort_by(|a, b| a.metadata.name.cmp(&b.metadata.name));
    Snapshot {
        materials,
        files: out.files,
        disassembly: Mutex::new(HashMap::new()),
    }
}
