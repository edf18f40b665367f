//! A shared cache of compile units, like Unreal's shared derived-data cache:
//! one folder (`weft build --cache-dir`, or `BuildOptions::cache_dir`) that
//! any number of checkouts, machines and concurrent builds read and fill.
//!
//! A compile unit is one variant of one material: specialisation, validation
//! and every backend, the bulk of a build's work. Its output depends only on
//! the material's inputs (what its `inputs_hash` covers: its TOML, WGSL
//! sources and includes, the engine interface), the variant (tier and
//! keyword values, its id) and the code that compiles it
//! (`WEFT_TOOLCHAIN_ID`, a hash of the compiler's sources and naga's
//! release; see build.rs). The SHA-256 of those is the unit's key.
//!
//! Layout under `<dir>/v1/`:
//! - `units/<kk>/<key>.json`: the unit — its variant id, its files as
//!   (name, SHA-256) and its reflection ([`weft_meta::VariantShader`]);
//! - `blobs/<ss>/<sha256>`: file contents, by their SHA-256, shared between
//!   units with identical files.
//!
//! Every file is written under a temporary name and renamed into place, the
//! unit last, so a reader sees a unit only once its blobs are there, and two
//! writers of one unit write the same bytes. A unit whose file is missing or
//! does not hash to its name (disk trouble, a half-copied cache) is a miss
//! and is compiled again. Material-level checks (GPU limits, unread
//! parameters, aliases) still run on every build, so a cached unit gives the
//! same diagnostics and bytes as a compiled one. Nothing is ever evicted:
//! delete the folder, or files by age, whenever you like (docs/scaling.md).

use crate::variant::{CompiledVariant, sha256_hex};
use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use weft_meta::VariantShader;

/// Identifies the compiler code (see build.rs).
pub const TOOLCHAIN_ID: &str = env!("WEFT_TOOLCHAIN_ID");

/// An open cache folder, with this build's hit and miss counts.
#[derive(Debug)]
pub struct UnitCache {
    root: PathBuf,
    hits: AtomicUsize,
    misses: AtomicUsize,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct StoredUnit {
    id: String,
    /// File name and SHA-256, in the order compilation produced them.
    files: Vec<(String, String)>,
    shader: VariantShader,
}

impl UnitCache {
    /// Opens (creating) the cache folder `dir`.
    pub fn open(dir: &Path) -> io::Result<UnitCache> {
        let root = dir.join("v1");
        for sub in ["units", "blobs"] {
            let d = root.join(sub);
            std::fs::create_dir_all(&d).map_err(|e| {
                io::Error::new(e.kind(), format!("cannot create `{}`: {e}", d.display()))
            })?;
        }
        Ok(UnitCache {
            root,
            hits: AtomicUsize::new(0),
            misses: AtomicUsize::new(0),
        })
    }

    /// The key of variant `variant_id` of a material with `inputs_hash`.
    pub fn unit_key(inputs_hash: &str, variant_id: &str) -> String {
        let mut h = Sha256::new();
        for part in [TOOLCHAIN_ID, inputs_hash, variant_id] {
            h.update(part.as_bytes());
            h.update([0]);
        }
        h.finalize().iter().map(|b| format!("{b:02x}")).collect()
    }

    /// Units served from the cache so far.
    pub fn hits(&self) -> usize {
        self.hits.load(Ordering::Relaxed)
    }

    /// Units looked up and not found (compiled, then stored).
    pub fn misses(&self) -> usize {
        self.misses.load(Ordering::Relaxed)
    }

    /// The unit `key` (of variant `variant_id`), if it is in the cache whole
    /// and well formed.
    pub fn load(&self, key: &str, variant_id: &str) -> Option<CompiledVariant> {
        let found = self.read_unit(key).filter(|v| is_sound(v, variant_id));
        let counter = if found.is_some() {
            &self.hits
        } else {
            &self.misses
        };
        counter.fetch_add(1, Ordering::Relaxed);
        found
    }

    fn read_unit(&self, key: &str) -> Option<CompiledVariant> {
        let bytes = std::fs::read(self.unit_path(key)).ok()?;
        let unit: StoredUnit = serde_json::from_slice(&bytes).ok()?;
        let wgsl_name = format!("{}.wgsl", unit.id);
        let mut files = Vec::with_capacity(unit.files.len());
        let mut wgsl = None;
        for (name, sha) in unit.files {
            let blob = std::fs::read(self.blob_path(&sha)?).ok()?;
            if sha256_hex(&blob) != sha {
                return None;
            }
            if name == wgsl_name {
                wgsl = Some(String::from_utf8(blob.clone()).ok()?);
            }
            files.push((name, blob));
        }
        Some(CompiledVariant {
            id: unit.id,
            files,
            shader: unit.shader,
            wgsl: wgsl?,
        })
    }

    /// Stores a compiled unit under `key` (blobs first, the unit last).
    pub fn store(&self, key: &str, v: &CompiledVariant) -> io::Result<()> {
        let mut files = Vec::with_capacity(v.files.len());
        for (name, bytes) in &v.files {
            let sha = sha256_hex(bytes);
            let path = self.blob_path(&sha).expect("a SHA-256 in hex");
            if !path.exists() {
                write_atomically(&path, bytes)?;
            }
            files.push((name.clone(), sha));
        }
        let unit = StoredUnit {
            id: v.id.clone(),
            files,
            shader: v.shader.clone(),
        };
        let json = serde_json::to_vec(&unit).expect("a unit serialises");
        write_atomically(&self.unit_path(key), &json)
    }

    fn unit_path(&self, key: &str) -> PathBuf {
        self.root
            .join("units")
            .join(&key[..2.min(key.len())])
            .join(format!("{key}.json"))
    }

    /// None for a name that is not a SHA-256 in hex (a tampered unit).
    fn blob_path(&self, sha: &str) -> Option<PathBuf> {
        (sha.len() == 64 && sha.bytes().all(|b| b.is_ascii_hexdigit()))
            .then(|| self.root.join("blobs").join(&sha[..2]).join(sha))
    }
}

/// A unit read from a shared folder is trusted no further than this: it is
/// the variant asked for, and its files are plain names of that variant
/// (`<variant id>…`, no path separators), so a damaged or hostile cache can
/// never make a build write outside the material's folder.
fn is_sound(v: &CompiledVariant, variant_id: &str) -> bool {
    v.id == variant_id
        && !v.files.is_empty()
        && v.files.iter().all(|(name, _)| {
            name.starts_with(variant_id)
                && !name.contains(['/', '\\', '\0'])
                && !name.contains("..")
        })
}

/// Writes `path` under a temporary name beside it, then renames it into place.
fn write_atomically(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let parent = path.parent().expect("inside the cache");
    let at =
        |e: io::Error| io::Error::new(e.kind(), format!("cannot write `{}`: {e}", path.display()));
    std::fs::create_dir_all(parent).map_err(at)?;
    let mut tmp = tempfile::Builder::new()
        .prefix(".tmp-")
        .tempfile_in(parent)
        .map_err(at)?;
    tmp.write_all(bytes).map_err(at)?;
    tmp.persist(path).map_err(|e| at(e.error))?;
    Ok(())
}
