//! Finding RADV's ICD manifest (`radeon_icd.<arch>.json`) in the folders the
//! Vulkan loader searches, so that a missing driver is reported by name
//! before any Vulkan call.

use crate::error::{Error, Result};
use std::path::{Path, PathBuf};

/// The folders the Vulkan loader searches for ICD manifests on Linux, in its
/// order: `$XDG_CONFIG_HOME` (or `~/.config`), `$XDG_CONFIG_DIRS` (or
/// `/etc/xdg`), `/etc`, `$XDG_DATA_HOME` (or `~/.local/share`), `$XDG_DATA_DIRS`
/// (or `/usr/local/share:/usr/share`), each followed by `vulkan/icd.d`.
pub fn standard_icd_dirs() -> Vec<PathBuf> {
    let var = |k: &str| std::env::var_os(k).filter(|v| !v.is_empty());
    let home = var("HOME").map(PathBuf::from);
    let mut roots: Vec<PathBuf> = Vec::new();
    match var("XDG_CONFIG_HOME") {
        Some(v) => roots.push(v.into()),
        None => roots.extend(home.as_ref().map(|h| h.join(".config"))),
    }
    let config_dirs = var("XDG_CONFIG_DIRS").unwrap_or_else(|| "/etc/xdg".into());
    roots.extend(std::env::split_paths(&config_dirs));
    roots.push("/etc".into());
    match var("XDG_DATA_HOME") {
        Some(v) => roots.push(v.into()),
        None => roots.extend(home.as_ref().map(|h| h.join(".local/share"))),
    }
    let data_dirs = var("XDG_DATA_DIRS").unwrap_or_else(|| "/usr/local/share:/usr/share".into());
    roots.extend(std::env::split_paths(&data_dirs));
    roots.into_iter().map(|r| r.join("vulkan/icd.d")).collect()
}

/// The first RADV manifest in `dirs`: `radeon_icd.<this arch>.json`, else any
/// `radeon_icd*.json`. [`Error::RadvMissing`] names the package when there is none.
pub fn find_radv_icd(dirs: &[PathBuf]) -> Result<PathBuf> {
    let preferred = format!("radeon_icd.{}.json", std::env::consts::ARCH);
    for dir in dirs {
        let exact = dir.join(&preferred);
        if exact.is_file() {
            return Ok(exact);
        }
        if let Some(any) = any_radeon_manifest(dir) {
            return Ok(any);
        }
    }
    Err(Error::RadvMissing {
        searched: dirs.to_vec(),
    })
}

fn any_radeon_manifest(dir: &Path) -> Option<PathBuf> {
    let mut names: Vec<PathBuf> = std::fs::read_dir(dir)
        .ok()?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.file_name()
                .and_then(|n| n.to_str())
                .is_some_and(|n| n.starts_with("radeon_icd") && n.ends_with(".json"))
        })
        .collect();
    names.sort();
    names.into_iter().next()
}
