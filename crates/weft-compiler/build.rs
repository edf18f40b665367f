//! `WEFT_TOOLCHAIN_ID`: a hash of the code that decides what a compile unit
//! produces (this crate's, weft-front's and weft-meta's sources, and the
//! naga release in the workspace's Cargo.lock), so that a shared cache of
//! compiled units (`src/cache.rs`) never serves the output of other code
//! under the same version number. Built from sources, not from the binary,
//! so every checkout of one commit gets the same id.

use sha2::{Digest, Sha256};
use std::path::{Path, PathBuf};

fn files_under(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            files_under(&p, out);
        } else {
            out.push(p);
        }
    }
}

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let crates = manifest.parent().expect("crates/").to_path_buf();
    let mut h = Sha256::new();
    h.update(std::env::var("CARGO_PKG_VERSION").unwrap_or_default());
    for krate in ["weft-compiler", "weft-front", "weft-meta"] {
        let src = crates.join(krate).join("src");
        println!("cargo:rerun-if-changed={}", src.display());
        let mut files = Vec::new();
        files_under(&src, &mut files);
        let mut rel: Vec<(String, PathBuf)> = files
            .into_iter()
            .map(|p| {
                let r = p.strip_prefix(&crates).unwrap_or(&p);
                (r.to_string_lossy().replace('\\', "/"), p)
            })
            .collect();
        rel.sort();
        for (name, path) in rel {
            h.update(name.as_bytes());
            h.update([0]);
            // Line endings as checked out must not change the id.
            let text = std::fs::read(&path).unwrap_or_default();
            let text: Vec<u8> = text.into_iter().filter(|&b| b != b'\r').collect();
            h.update((text.len() as u64).to_le_bytes());
            h.update(&text);
        }
    }
    // The naga release (its entry in the workspace's lock file).
    let lock = crates.parent().map(|w| w.join("Cargo.lock"));
    if let Some(lock) = lock.filter(|l| l.exists()) {
        println!("cargo:rerun-if-changed={}", lock.display());
        let text = std::fs::read_to_string(&lock).unwrap_or_default();
        for block in text.split("[[package]]") {
            if block.contains("name = \"naga\"") {
                h.update(block.trim().as_bytes());
            }
        }
    }
    let id: String = h.finalize().iter().map(|b| format!("{b:02x}")).collect();
    println!("cargo:rustc-env=WEFT_TOOLCHAIN_ID={id}");
}
