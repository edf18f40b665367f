//! Writing a build's files: atomically, removing stale files, or checking
//! that a folder already holds exactly those bytes.
//!
//! Everything is written into a temporary folder beside the target, then
//! swapped in by rename, so a failed or interrupted build never leaves a
//! partial `generated/`. Paths listed in `preserve` (e.g. measured reports,
//! which only `regenerate --reports` rewrites) are carried over untouched.

use std::collections::BTreeMap;
use std::io;
use std::path::{Path, PathBuf};

/// What differs between a build and a folder on disk.
#[derive(Debug, Default, PartialEq)]
pub struct Staleness {
    pub changed: Vec<String>,
    pub missing: Vec<String>,
    /// Files on disk the build would remove.
    pub extra: Vec<String>,
}

impl Staleness {
    pub fn is_clean(&self) -> bool {
        self.changed.is_empty() && self.missing.is_empty() && self.extra.is_empty()
    }
}

fn is_preserved(rel: &str, preserve: &[&str]) -> bool {
    preserve
        .iter()
        .any(|p| rel == *p || rel.starts_with(&format!("{p}/")))
}

/// Every file under `dir`, relative, with `/` separators, sorted.
pub fn list_files(dir: &Path) -> io::Result<Vec<String>> {
    let mut out = Vec::new();
    if !dir.exists() {
        return Ok(out);
    }
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d)? {
            let p = e?.path();
            if p.is_dir() {
                stack.push(p);
            } else {
                let rel = p
                    .strip_prefix(dir)
                    .expect("under dir")
                    .to_string_lossy()
                    .replace('\\', "/");
                out.push(rel);
            }
        }
    }
    out.sort();
    Ok(out)
}

/// Compares `files` with `dir` (ignoring preserved paths).
pub fn check(
    dir: &Path,
    files: &BTreeMap<String, Vec<u8>>,
    preserve: &[&str],
) -> io::Result<Staleness> {
    let mut s = Staleness::default();
    for (rel, bytes) in files {
        match std::fs::read(dir.join(rel)) {
            Ok(disk) if disk == *bytes => {}
            Ok(_) => s.changed.push(rel.clone()),
            Err(_) => s.missing.push(rel.clone()),
        }
    }
    for rel in list_files(dir)? {
        if !files.contains_key(&rel) && !is_preserved(&rel, preserve) {
            s.extra.push(rel);
        }
    }
    Ok(s)
}

/// Replaces `dir` with exactly `files` (plus preserved paths from the old `dir`).
pub fn write_atomically(
    dir: &Path,
    files: &BTreeMap<String, Vec<u8>>,
    preserve: &[&str],
) -> io::Result<()> {
    let parent = dir
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    std::fs::create_dir_all(parent)?;
    let name = dir
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "out".into());
    let tmp = tempfile::Builder::new()
        .prefix(&format!(".{name}.tmp-"))
        .tempdir_in(parent)?;
    for (rel, bytes) in files {
        let path = tmp.path().join(rel);
        if let Some(p) = path.parent() {
            std::fs::create_dir_all(p)?;
        }
        std::fs::write(&path, bytes)?;
    }
    if dir.exists() {
        for rel in list_files(dir)? {
            if is_preserved(&rel, preserve) && !files.contains_key(&rel) {
                let to = tmp.path().join(&rel);
                if let Some(p) = to.parent() {
                    std::fs::create_dir_all(p)?;
                }
                std::fs::copy(dir.join(&rel), to)?;
            }
        }
    }
    let new_dir: PathBuf = tmp.keep();
    if dir.exists() {
        let old = tempfile::Builder::new()
            .prefix(&format!(".{name}.old-"))
            .tempdir_in(parent)?
            .keep();
        std::fs::remove_dir(&old)?;
        std::fs::rename(dir, &old)?;
        if let Err(e) = std::fs::rename(&new_dir, dir) {
            // Put the old tree back rather than leave nothing.
            let _ = std::fs::rename(&old, dir);
            let _ = std::fs::remove_dir_all(&new_dir);
            return Err(e);
        }
        std::fs::remove_dir_all(&old)?;
    } else {
        std::fs::rename(&new_dir, dir)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_checks_and_preserves() {
        let root = tempfile::tempdir().unwrap();
        let dir = root.path().join("generated");
        let mut files = BTreeMap::new();
        files.insert("a/x.txt".to_string(), b"one".to_vec());
        write_atomically(&dir, &files, &["reports"]).unwrap();
        std::fs::create_dir_all(dir.join("reports")).unwrap();
        std::fs::write(dir.join("reports/r.md"), "kept").unwrap();
        std::fs::write(dir.join("a/stale.txt"), "old").unwrap();
        let s = check(&dir, &files, &["reports"]).unwrap();
        assert_eq!(s.extra, vec!["a/stale.txt".to_string()]);
        files.insert("b.txt".into(), b"two".to_vec());
        write_atomically(&dir, &files, &["reports"]).unwrap();
        assert!(check(&dir, &files, &["reports"]).unwrap().is_clean());
        assert_eq!(
            std::fs::read_to_string(dir.join("reports/r.md")).unwrap(),
            "kept"
        );
        assert!(!dir.join("a/stale.txt").exists());
        // No temporary folders left behind.
        let leftovers: Vec<_> = std::fs::read_dir(root.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(leftovers.len(), 1);
    }
}
