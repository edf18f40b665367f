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
//! Each shard's folder also holds [`SHARD_MARKER`] (`k/n` and a hash of the
//! whole library's inputs), which [`merge`] checks (every shard of `1..=n`
//! exactly once, all from the same inputs) and drops. Merge takes only
//! regular files that a build writes: never a symbolic link's target.

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
        if count > MAX_SHARDS {
            return Err(format!("`{s}`: at most {MAX_SHARDS} shards"));
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

    /// The contents of [`SHARD_MARKER`]: the shard, and the inputs of the
    /// whole library ([`crate::BuildOutput::library_inputs`]).
    pub fn marker(&self, library_inputs: &str) -> Vec<u8> {
        format!("{self}\ninputs {library_inputs}\n").into_bytes()
    }
}

/// The most shards a build may be split into: far above any build farm,
/// and small enough that every count weft derives from it stays cheap.
pub const MAX_SHARDS: usize = 4096;

/// A shard folder's [`SHARD_MARKER`]: which shard, and the inputs of the
/// whole library it was built from ([`crate::BuildOutput::library_inputs`]).
struct ShardMarker {
    shard: Shard,
    inputs: String,
}

fn read_marker(dir: &Path) -> Result<ShardMarker, String> {
    let marker = dir.join(SHARD_MARKER);
    let text = weft_meta::files::read_regular_string(&marker, 4096).map_err(|e| {
        format!(
            "`{}` is not a shard's output folder (no readable {SHARD_MARKER}: {e}); build it with `weft build --shard k/n`",
            dir.display()
        )
    })?;
    let mut lines = text.lines();
    let shard: Shard = lines
        .next()
        .unwrap_or_default()
        .parse()
        .map_err(|e| format!("{}: {e}", marker.display()))?;
    let inputs = lines
        .next()
        .and_then(|l| l.strip_prefix("inputs "))
        .ok_or_else(|| {
            format!(
                "{}: no `inputs` line (built by an older weft?); rebuild the shard",
                marker.display()
            )
        })?;
    Ok(ShardMarker {
        shard,
        inputs: inputs.to_string(),
    })
}

/// The files of the shards' output folders `dirs`, joined: one of each
/// shard `1..=n` (told by its [`SHARD_MARKER`], which is left out), all
/// built from the same inputs (the markers' `inputs` agree). Only regular
/// files are taken (a symbolic link or special file is an error, so nothing
/// outside the shard folders is ever read), and only files a build writes:
/// a file in a material's folder must be listed by that material's
/// metadata and be in one shard only; any other file (the library-wide
/// LUTs and schemas) must be in every shard, identical. Returns where each
/// file is (relative path -> the file in one shard's folder), so that the
/// merged folder can link rather than copy them; only files present in
/// several shards are read.
pub fn merge(dirs: &[PathBuf]) -> Result<BTreeMap<String, PathBuf>, String> {
    let mut files: BTreeMap<String, PathBuf> = BTreeMap::new();
    let mut seen: BTreeMap<usize, &Path> = BTreeMap::new();
    let mut first: Option<(ShardMarker, &Path)> = None;
    // Library-wide files: how many shards hold each.
    let mut shared: BTreeMap<String, usize> = BTreeMap::new();
    for dir in dirs {
        let marker = read_marker(dir)?;
        let shard = marker.shard;
        if let Some((f, f_dir)) = &first {
            if f.shard.count != shard.count {
                return Err(format!(
                    "`{}` is shard {shard}, but `{}` is of {} shards",
                    dir.display(),
                    f_dir.display(),
                    f.shard.count
                ));
            }
            if f.inputs != marker.inputs {
                return Err(format!(
                    "`{}` and `{}` were built from different inputs (materials, sources or \
                     toolchain differ); build every shard from the same checkout",
                    f_dir.display(),
                    dir.display()
                ));
            }
        }
        if let Some(other) = seen.insert(shard.index, dir) {
            return Err(format!(
                "`{}` and `{}` are both shard {shard}",
                other.display(),
                dir.display()
            ));
        }
        for ShardFile { rel, library_wide } in shard_files(dir)? {
            let path = dir.join(&rel);
            if let Some(other) = files.get(&rel) {
                if !library_wide {
                    return Err(format!(
                        "`{rel}` is in both `{}` and `{}`, but a material belongs to one shard",
                        other.display(),
                        path.display()
                    ));
                }
                if read(other)? != read(&path)? {
                    return Err(format!(
                        "`{rel}` differs between `{}` and `{}` (shards of different sources or toolchains?)",
                        other.display(),
                        path.display()
                    ));
                }
            } else {
                files.insert(rel.clone(), path);
            }
            if library_wide {
                *shared.entry(rel).or_default() += 1;
            }
        }
        first.get_or_insert((marker, dir));
    }
    let count = first
        .map(|(m, _)| m.shard.count)
        .ok_or("no shard folders given")?;
    let missing: Vec<String> = (1..=count)
        .filter(|k| !seen.contains_key(k))
        .take(10)
        .map(|k| format!("{k}/{count}"))
        .collect();
    if !missing.is_empty() {
        let more = count - seen.len() - missing.len();
        let more = if more > 0 {
            format!(" and {more} more")
        } else {
            String::new()
        };
        return Err(format!("missing shard(s) {}{more}", missing.join(", ")));
    }
    if let Some((rel, n)) = shared.iter().find(|(_, n)| **n != dirs.len()) {
        return Err(format!(
            "the library-wide file `{rel}` is in {n} of {} shard folders; every shard writes it",
            dirs.len()
        ));
    }
    Ok(files)
}

fn read(p: &Path) -> Result<Vec<u8>, String> {
    weft_meta::files::read_regular(p, weft_meta::files::MAX_BINARY_BYTES)
        .map_err(|e| format!("{}: {e}", p.display()))
}

/// A file of a shard folder: its path, and whether every shard writes it
/// (LUTs, schemas) rather than one material's shard.
struct ShardFile {
    rel: String,
    library_wide: bool,
}

/// The files of one shard folder a merge takes (relative paths, sorted):
/// see [`merge`]. Refuses anything that is not a regular file or a folder,
/// and files of a material's folder its metadata does not list.
fn shard_files(dir: &Path) -> Result<Vec<ShardFile>, String> {
    let mut out = Vec::new();
    let entries = std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut names: Vec<_> = entries
        .map(|e| e.map(|e| e.file_name()))
        .collect::<Result<_, _>>()
        .map_err(|e| format!("{}: {e}", dir.display()))?;
    names.sort();
    for name in names {
        let name = name
            .to_str()
            .ok_or_else(|| format!("{}: a file name that is not UTF-8", dir.display()))?
            .to_string();
        if name == SHARD_MARKER || name == crate::build::ownership::OUTPUT_MARKER {
            continue;
        }
        let path = dir.join(&name);
        let kind = std::fs::symlink_metadata(&path)
            .map_err(|e| format!("{}: {e}", path.display()))?
            .file_type();
        if kind.is_file() {
            out.push(ShardFile {
                rel: name,
                library_wide: true,
            });
        } else if kind.is_dir() {
            folder_files(dir, &name, &mut out)?;
        } else {
            return Err(not_regular(&path));
        }
    }
    Ok(out)
}

/// The files of the top-level folder `name` of a shard: a material's (as
/// its metadata lists them, each checked to be a regular file) or the
/// library-wide LUT folder (every regular file in it).
fn folder_files(dir: &Path, name: &str, out: &mut Vec<ShardFile>) -> Result<(), String> {
    let folder = dir.join(name);
    if let Some((_, listed)) = crate::build::unchanged::material_files(dir, name) {
        let listed: std::collections::BTreeSet<String> =
            listed.into_iter().map(|(rel, _)| rel).collect();
        for rel in crate::build::output::list_files(&folder)
            .map_err(|e| format!("{}: {e}", folder.display()))?
        {
            let path = folder.join(&rel);
            if !std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
                return Err(not_regular(&path));
            }
            if !listed.contains(&rel) {
                return Err(format!(
                    "`{}` is not a file material `{name}`'s metadata lists; a shard folder holds only what `weft build` wrote",
                    path.display()
                ));
            }
            out.push(ShardFile {
                rel: format!("{name}/{rel}"),
                library_wide: false,
            });
        }
        return Ok(());
    }
    if name != "luts" {
        return Err(format!(
            "`{}` is neither a material's folder (no `{name}.meta.json`) nor the LUT folder; a shard folder holds only what `weft build` wrote",
            folder.display()
        ));
    }
    for rel in crate::build::output::list_files(&folder)
        .map_err(|e| format!("{}: {e}", folder.display()))?
    {
        let path = folder.join(&rel);
        if !std::fs::symlink_metadata(&path).is_ok_and(|m| m.is_file()) {
            return Err(not_regular(&path));
        }
        out.push(ShardFile {
            rel: format!("{name}/{rel}"),
            library_wide: true,
        });
    }
    Ok(())
}

fn not_regular(path: &Path) -> String {
    format!(
        "`{}` is not a regular file (a symbolic link or special file); a shard folder holds only the files `weft build` wrote",
        path.display()
    )
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
