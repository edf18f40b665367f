//! Splitting a library build over machines: `weft build --shard k/n`
//! compiles only the materials of shard `k` (of `n`, counted from 1) into its
//! own folder, and `weft merge` joins the shards' folders into exactly the
//! folder one unsharded build writes, byte for byte.
//!
//! That holds because a material's files depend only on its own inputs (its
//! TOML, WGSL sources and includes, and the toolchain: what its
//! `inputs_hash` covers), and the library-wide files (LUTs, schemas) are the
//! same in every build. A material's shard is the first 8 bytes of
//! SHA-256(name), big-endian, modulo `n`, plus one: the same on every
//! machine and in every run, and adding or removing a material moves no
//! other. Every shard still loads and checks every material, so each reports
//! the same diagnostics.
//!
//! Each shard's folder also holds [`SHARD_MARKER`] (`k/n`), which [`merge`]
//! checks (every shard of `1..=n` exactly once) and drops.

use sha2::{Digest, Sha256};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// File in a shard's output folder naming the shard (`k/n` and a newline).
pub const SHARD_MARKER: &str = ".weft-shard";

/// Shard `index` of `count`, both counted from 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
}

impl std::str::FromStr for Shard {
    type Err = String;

    /// `k/n` with 1 <= k <= n.
    fn from_str(s: &str) -> Result<Shard, String> {
        let bad = || format!("`{s}` is not a shard: write k/n with 1 <= k <= n, e.g. 2/4");
        let (k, n) = s.trim().split_once('/').ok_or_else(bad)?;
        let (index, count): (usize, usize) = (
            k.trim().parse().map_err(|_| bad())?,
            n.trim().parse().map_err(|_| bad())?,
        );
        if index == 0 || index > count {
            return Err(bad());
        }
        Ok(Shard { index, count })
    }
}

impl std::fmt::Display for Shard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl Shard {
    /// The shard (from 1) that material `name` belongs to among `count`.
    pub fn of(name: &str, count: usize) -> usize {
        let digest = Sha256::digest(name.as_bytes());
        let head = u64::from_be_bytes(digest[..8].try_into().expect("8 bytes"));
        (head % count.max(1) as u64) as usize + 1
    }

    pub fn contains(&self, name: &str) -> bool {
        Shard::of(name, self.count) == self.index
    }

    /// The contents of [`SHARD_MARKER`].
    pub fn marker(&self) -> Vec<u8> {
        format!("{self}\n").into_bytes()
    }
}

/// The files of the shards' output folders `dirs`, joined: one of each
/// shard `1..=n` (told by its [`SHARD_MARKER`], which is left out), files
/// present in several (the library-wide ones) identical in all. Returns
/// where each file is (relative path -> the file in one shard's folder), so
/// that the merged folder can link rather than copy them; only files present
/// in several shards are read.
pub fn merge(dirs: &[PathBuf]) -> Result<BTreeMap<String, PathBuf>, String> {
    let mut files: BTreeMap<String, PathBuf> = BTreeMap::new();
    let mut seen: BTreeMap<usize, &Path> = BTreeMap::new();
    let mut count = None;
    for dir in dirs {
        let marker = dir.join(SHARD_MARKER);
        let text = std::fs::read_to_string(&marker).map_err(|e| {
            format!(
                "`{}` is not a shard's output folder (no readable {SHARD_MARKER}: {e}); build it with `weft build --shard k/n`",
                dir.display()
            )
        })?;
        let shard: Shard = text
            .parse()
            .map_err(|e| format!("{}: {e}", marker.display()))?;
        if *count.get_or_insert(shard.count) != shard.count {
            return Err(format!(
                "`{}` is shard {shard}, but an earlier folder is of {} shards",
                dir.display(),
                count.unwrap_or_default()
            ));
        }
        if let Some(other) = seen.insert(shard.index, dir) {
            return Err(format!(
                "`{}` and `{}` are both shard {shard}",
                other.display(),
                dir.display()
            ));
        }
        let list = crate::output::list_files(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        for rel in list {
            if rel == SHARD_MARKER {
                continue;
            }
            let path = dir.join(&rel);
            match files.get(&rel) {
                Some(other) => {
                    let read =
                        |p: &Path| std::fs::read(p).map_err(|e| format!("{}: {e}", p.display()));
                    if read(other)? != read(&path)? {
                        return Err(format!(
                            "`{rel}` differs between `{}` and `{}` (shards of different sources or toolchains?)",
                            other.display(),
                            path.display()
                        ));
                    }
                }
                None => {
                    files.insert(rel, path);
                }
            }
        }
    }
    let count = count.ok_or("no shard folders given")?;
    let missing: Vec<String> = (1..=count)
        .filter(|k| !seen.contains_key(k))
        .map(|k| format!("{k}/{count}"))
        .collect();
    if !missing.is_empty() {
        return Err(format!("missing shard(s) {}", missing.join(", ")));
    }
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_partitions() {
        assert_eq!("2/4".parse::<Shard>(), Ok(Shard { index: 2, count: 4 }));
        for bad in ["0/4", "5/4", "1", "a/b", "1/0"] {
            assert!(bad.parse::<Shard>().is_err(), "{bad}");
        }
        // Every name is in exactly one shard.
        for name in ["standard", "silk", "velvet", "gauze_0003_syn"] {
            let owners: Vec<usize> = (1..=3)
                .filter(|&k| Shard { index: k, count: 3 }.contains(name))
                .collect();
            assert_eq!(owners.len(), 1, "{name}");
        }
        // Fixed: the partition is part of the interface (CI configurations).
        assert_eq!(Shard::of("standard", 1), 1);
    }
}
