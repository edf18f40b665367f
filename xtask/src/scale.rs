//! Synthetic material libraries for `cargo xtask bench scale`.
//!
//! Each synthetic material is a copy of a shipped one (`materials/<base>/`,
//! taken round-robin in name order) under a new name, `<base>_<i:04>_syn`
//! (names may not end in a digit), with
//!
//! - its float parameters' defaults moved inside their ranges and
//! - static keywords added (toggles and three-value enums from a fixed pool,
//!   [`FEATURES`](features::FEATURES)), each with its own parameters and shading code (rim light,
//!   distance fog, detail map, glints, colour grading, wrap diffuse, tone
//!   shoulder), gated in the WGSL with plain `if`s.
//!
//! The keywords go into a new `@fragment` entry point that calls the shipped
//! one (renamed `weft_syn_base_<entry>`, its attributes dropped) and then
//! applies them, so the shipped shading code compiles unchanged in every
//! variant. Enough keywords are added to bring a material close to a target
//! variant count (48 by default: 4 × 12, 8 × 6, 12 × 4 for the shipped
//! bases). Everything is derived from a fixed seed: the same arguments write
//! the same bytes.

mod features;
mod material;
#[cfg(test)]
mod tests;
mod wgsl;

use material::{load_bases, synthesise};

use std::path::{Path, PathBuf};

/// Default seed of `bench scale`.
pub const DEFAULT_SEED: u64 = 0x5eed_0013;

/// SplitMix64: small, deterministic, good enough to pick and jitter.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi), rounded to 3 decimals (stable, short literals).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        ((lo + (hi - lo) * self.unit()) * 1000.0).round() / 1000.0
    }
}

/// A generated library.
pub struct Library {
    /// The materials folder (with `lib/`).
    pub dir: PathBuf,
    /// Variants the front end will enumerate (tiers × static keyword values).
    pub variants: usize,
}

/// Writes `count` synthetic materials derived from `shipped` (a materials
/// folder) into `dest` (replaced), with `shipped/lib` and the shipped
/// materials' `textures/` folders copied beside them.
pub fn generate(
    shipped: &Path,
    dest: &Path,
    count: usize,
    per_material: usize,
    seed: u64,
) -> Result<Library, String> {
    let bases = load_bases(shipped)?;
    if bases.is_empty() {
        return Err(format!("no materials under {}", shipped.display()));
    }
    if dest.exists() {
        std::fs::remove_dir_all(dest).map_err(|e| format!("{}: {e}", dest.display()))?;
    }
    copy_dir(&shipped.join("lib"), &dest.join("lib"))?;
    // The shipped texture files (`file = "<base>/textures/x.png"`): a copy
    // keeps naming its base's path under the materials root.
    for entry in std::fs::read_dir(shipped).map_err(|e| format!("{}: {e}", shipped.display()))? {
        let base = entry.map_err(|e| e.to_string())?.path();
        let textures = base.join("textures");
        if textures.is_dir() {
            let name = base.file_name().expect("a folder entry has a name");
            copy_dir(&textures, &dest.join(name).join("textures"))?;
        }
    }
    let mut variants = 0;
    for i in 0..count {
        let s = synthesise(&bases[i % bases.len()], i, per_material, seed)?;
        let dir = dest.join(&s.name);
        std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
        std::fs::write(dir.join(format!("{}.toml", s.name)), &s.toml)
            .and_then(|()| std::fs::write(dir.join(&s.wgsl_name), &s.wgsl))
            .map_err(|e| format!("{}: {e}", dir.display()))?;
        variants += s.variants;
    }
    Ok(Library {
        dir: dest.to_path_buf(),
        variants,
    })
}

pub fn copy_dir(from: &Path, to: &Path) -> Result<(), String> {
    std::fs::create_dir_all(to).map_err(|e| format!("{}: {e}", to.display()))?;
    let mut entries: Vec<_> = std::fs::read_dir(from)
        .map_err(|e| format!("{}: {e}", from.display()))?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .collect();
    entries.sort();
    for p in entries {
        let target = to.join(p.file_name().expect("entry name"));
        if p.is_dir() {
            copy_dir(&p, &target)?;
        } else {
            std::fs::copy(&p, &target).map_err(|e| format!("{}: {e}", p.display()))?;
        }
    }
    Ok(())
}
