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
//!
//! # Trust
//!
//! A shared cache is a trust boundary: whoever can write it decides the
//! bytes of every build that reads it. The checks above catch damage (a
//! blob that does not hash to the SHA-256 its unit records, a unit for
//! another variant, file names that would leave the material's folder),
//! but a writer who replaces a blob *and* its unit consistently is not
//! damage. Two defences, in [`CacheTrust`]:
//!
//! - **A key** (`WEFT_CACHE_KEY`): every unit stored carries an
//!   HMAC-SHA256 of its contents under the key, and a unit read must carry
//!   a valid one, or it is refused (counted, compiled and stored again).
//!   Then only holders of the key can put bytes into a build: the cache
//!   needs to be trusted for availability, not for content.
//! - **Verification** (`--cache-verify PERCENT`): that share of the hits,
//!   chosen by their keys (the same units on every machine; 100 for all),
//!   is compiled again and compared byte for byte with the unit; any
//!   difference fails the build, naming the unit.
//!
//! Without either, the cache must be trusted like the compiler itself.

use crate::compile::digest::sha256_hex;
use crate::compile::variant::CompiledVariant;
use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use std::io::{self, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use weft_meta::VariantShader;

/// Identifies the compiler code (see build.rs).
pub const TOOLCHAIN_ID: &str = env!("WEFT_TOOLCHAIN_ID");

/// How far units read from a shared cache are trusted (module docs, "Trust").
#[derive(Clone, Debug, Default)]
pub struct CacheTrust {
    /// Units must carry an HMAC-SHA256 under this key (`WEFT_CACHE_KEY`).
    pub key: Option<Vec<u8>>,
    /// Share of hits, 0 to 100, compiled again and compared.
    pub verify_percent: u8,
}

/// An open cache folder, with this build's hit and miss counts.
#[derive(Debug)]
pub struct UnitCache {
    root: PathBuf,
    trust: CacheTrust,
    hits: AtomicUsize,
    misses: AtomicUsize,
    rejected: AtomicUsize,
    verified: AtomicUsize,
}

#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct StoredUnit {
    id: String,
    /// File name and SHA-256, in the order compilation produced them.
    files: Vec<(String, String)>,
    shader: VariantShader,
    /// HMAC-SHA256 (hex) of the unit without this field, under the cache
    /// key, when the writer had one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    mac: Option<String>,
}

/// The largest unit or blob file read from a cache.
const MAX_CACHE_FILE_BYTES: u64 = weft_meta::files::MAX_BINARY_BYTES;

impl UnitCache {
    /// Opens (creating) the cache folder `dir`.
    pub fn open(dir: &Path, trust: CacheTrust) -> io::Result<UnitCache> {
        let root = dir.join("v1");
        for sub in ["units", "blobs"] {
            let d = root.join(sub);
            std::fs::create_dir_all(&d).map_err(|e| {
                io::Error::new(e.kind(), format!("cannot create `{}`: {e}", d.display()))
            })?;
        }
        Ok(UnitCache {
            root,
            trust,
            hits: AtomicUsize::new(0),
            misses: AtomicUsize::new(0),
            rejected: AtomicUsize::new(0),
            verified: AtomicUsize::new(0),
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

    /// Units found but refused for a missing or wrong signature.
    pub fn rejected(&self) -> usize {
        self.rejected.load(Ordering::Relaxed)
    }

    /// Hits compiled again and found identical.
    pub fn verified(&self) -> usize {
        self.verified.load(Ordering::Relaxed)
    }

    /// Whether the hit `key` is one to compile again and compare: the
    /// first byte of the key against the share asked for, so the choice is
    /// the same on every machine.
    pub fn should_verify(&self, key: &str) -> bool {
        let percent = u32::from(self.trust.verify_percent.min(100));
        let byte = u32::from_str_radix(key.get(..2).unwrap_or("ff"), 16).unwrap_or(255);
        percent == 100 || byte * 100 < percent * 256
    }

    /// Compares a unit served from the cache with the same unit compiled
    /// now: an error naming the unit if they differ.
    pub fn check_unit(
        &self,
        key: &str,
        cached: &CompiledVariant,
        fresh: &CompiledVariant,
    ) -> Result<(), String> {
        if cached.files == fresh.files && cached.shader == fresh.shader {
            self.verified.fetch_add(1, Ordering::Relaxed);
            return Ok(());
        }
        Err(format!(
            "the shared cache's unit `{}` (variant `{}`) holds bytes this compiler does not \
             produce: the cache at `{}` was damaged or tampered with. Delete the folder (or \
             that unit), and protect a shared cache with WEFT_CACHE_KEY (docs/scaling.md)",
            self.unit_path(key).display(),
            fresh.id,
            self.root.parent().unwrap_or(&self.root).display()
        ))
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
        let bytes =
            weft_meta::files::read_regular(&self.unit_path(key), MAX_CACHE_FILE_BYTES).ok()?;
        let mut unit: StoredUnit = serde_json::from_slice(&bytes).ok()?;
        if let Some(secret) = &self.trust.key {
            let mac = unit.mac.take();
            if mac.as_deref() != Some(unit_mac(secret, &unit).as_str()) {
                self.rejected.fetch_add(1, Ordering::Relaxed);
                return None;
            }
        }
        let wgsl_name = format!("{}.wgsl", unit.id);
        let mut files = Vec::with_capacity(unit.files.len());
        let mut wgsl = None;
        for (name, sha) in unit.files {
            let blob = weft_meta::files::read_regular(&self.blob_path(&sha)?, MAX_CACHE_FILE_BYTES)
                .ok()?;
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
        let mut unit = StoredUnit {
            id: v.id.clone(),
            files,
            shader: v.shader.clone(),
            mac: None,
        };
        unit.mac = self.trust.key.as_ref().map(|k| unit_mac(k, &unit));
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

/// The HMAC-SHA256 (RFC 2104), in hex, of `unit`'s JSON without its `mac`.
fn unit_mac(key: &[u8], unit: &StoredUnit) -> String {
    let unsigned = StoredUnit {
        id: unit.id.clone(),
        files: unit.files.clone(),
        shader: unit.shader.clone(),
        mac: None,
    };
    let message = serde_json::to_vec(&unsigned).expect("a unit serialises");
    hmac_sha256(key, &message)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// HMAC-SHA256 as RFC 2104 defines it (block size 64 bytes).
fn hmac_sha256(key: &[u8], message: &[u8]) -> [u8; 32] {
    let mut block = [0u8; 64];
    if key.len() > 64 {
        block[..32].copy_from_slice(&Sha256::digest(key));
    } else {
        block[..key.len()].copy_from_slice(key);
    }
    let pad = |byte: u8| block.map(|b| b ^ byte);
    let inner = Sha256::new()
        .chain_update(pad(0x36))
        .chain_update(message)
        .finalize();
    Sha256::new()
        .chain_update(pad(0x5c))
        .chain_update(inner)
        .finalize()
        .into()
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

/// The compile stages take and keep variants through this (see
/// [`crate::compile::material::VariantStore`]); keys are [`UnitCache::unit_key`].
impl crate::compile::material::VariantStore for UnitCache {
    fn fetch(&self, inputs_hash: &str, variant_id: &str) -> Option<(CompiledVariant, bool)> {
        let key = Self::unit_key(inputs_hash, variant_id);
        let stored = self.load(&key, variant_id)?;
        Some((stored, self.should_verify(&key)))
    }

    fn verify(
        &self,
        inputs_hash: &str,
        stored: &CompiledVariant,
        fresh: &CompiledVariant,
    ) -> Result<(), String> {
        self.check_unit(&Self::unit_key(inputs_hash, &fresh.id), stored, fresh)
    }

    fn keep(&self, inputs_hash: &str, compiled: &CompiledVariant) {
        // A cache that cannot be written only costs the next build time.
        let _ = self.store(&Self::unit_key(inputs_hash, &compiled.id), compiled);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn hex(bytes: &[u8]) -> String {
        bytes.iter().map(|b| format!("{b:02x}")).collect()
    }

    #[test]
    fn hmac_matches_rfc_4231() {
        // Test cases 2 and 6 (a key longer than the block).
        assert_eq!(
            hex(&hmac_sha256(b"Jefe", b"what do ya want for nothing?")),
            "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843"
        );
        assert_eq!(
            hex(&hmac_sha256(
                &[0xaa; 131],
                b"Test Using Larger Than Block-Size Key - Hash Key First"
            )),
            "60e431591ee0b67f0d8a26aacbf5b77f8e0bc6213728c5140546040f0ee37f54"
        );
    }

    /// A real variant's reflection, from the shipped library.
    fn shader() -> VariantShader {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../generated/standard/standard.meta.json");
        let meta: serde_json::Value =
            serde_json::from_slice(&std::fs::read(path).unwrap()).unwrap();
        serde_json::from_value(meta["variants"][0]["shader"].clone()).unwrap()
    }

    fn unit(bytes: &[u8]) -> CompiledVariant {
        CompiledVariant {
            id: "fast".into(),
            files: vec![("fast.wgsl".into(), bytes.to_vec())],
            shader: shader(),
            wgsl: String::from_utf8(bytes.to_vec()).unwrap(),
        }
    }

    /// Replaces the unit's blob and its recorded SHA-256 consistently, as a
    /// hostile writer of a shared cache can.
    fn forge(cache: &UnitCache, key: &str, bytes: &[u8]) {
        let path = cache.unit_path(key);
        let mut stored: StoredUnit =
            serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
        let sha = sha256_hex(bytes);
        write_atomically(&cache.blob_path(&sha).unwrap(), bytes).unwrap();
        stored.files[0].1 = sha;
        std::fs::write(&path, serde_json::to_vec(&stored).unwrap()).unwrap();
    }

    #[test]
    fn a_consistently_forged_unit_is_refused_with_a_key() {
        let dir = tempfile::tempdir().unwrap();
        let trust = CacheTrust {
            key: Some(b"secret".to_vec()),
            verify_percent: 0,
        };
        let cache = UnitCache::open(dir.path(), trust).unwrap();
        let key = UnitCache::unit_key("inputs", "fast");
        cache.store(&key, &unit(b"real")).unwrap();
        assert_eq!(cache.load(&key, "fast").unwrap().wgsl, "real");
        forge(&cache, &key, b"evil");
        assert!(cache.load(&key, "fast").is_none());
        assert_eq!(cache.rejected(), 1);
        // Without a key the same forgery is served: what verification is for.
        let open = UnitCache::open(dir.path(), CacheTrust::default()).unwrap();
        let served = open.load(&key, "fast").unwrap();
        assert_eq!(served.wgsl, "evil");
        let e = open.check_unit(&key, &served, &unit(b"real")).unwrap_err();
        assert!(e.contains("tampered"), "{e}");
        open.check_unit(&key, &unit(b"real"), &unit(b"real"))
            .unwrap();
    }

    #[test]
    fn verification_share_is_chosen_by_key() {
        let dir = tempfile::tempdir().unwrap();
        let with = |verify_percent| {
            let trust = CacheTrust {
                key: None,
                verify_percent,
            };
            UnitCache::open(dir.path(), trust).unwrap()
        };
        let keys: Vec<String> = (0..400)
            .map(|i| UnitCache::unit_key("x", &i.to_string()))
            .collect();
        let share = |c: &UnitCache| keys.iter().filter(|k| c.should_verify(k)).count();
        assert_eq!(share(&with(0)), 0);
        assert_eq!(share(&with(100)), 400);
        let quarter = share(&with(25));
        assert!((60..140).contains(&quarter), "{quarter}");
    }
}
