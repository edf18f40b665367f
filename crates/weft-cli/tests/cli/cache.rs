//! `weft build --cache-dir`: two checkouts of the library (copies at
//! different paths) share one cache; the second compiles nothing and writes
//! the same bytes, and a shard of a third checkout is served from it too.

use std::path::Path;
use std::process::Command;
use weft_tests::repo;

fn copy(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let p = e.unwrap().path();
        let t = to.join(p.file_name().unwrap());
        if p.is_dir() {
            copy(&p, &t);
        } else {
            std::fs::copy(&p, &t).unwrap();
        }
    }
}

/// Builds `checkout/materials` into `checkout/generated`; returns
/// (units from the cache, units compiled).
fn build(checkout: &Path, cache: &Path, extra: &[&str]) -> (usize, usize) {
    let o = Command::new(env!("CARGO_BIN_EXE_weft"))
        .current_dir(checkout)
        .args(["build", "materials", "-o", "generated", "--cache-dir"])
        .arg(cache)
        .args(extra)
        .env_remove("WEFT_CACHE_DIR")
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let line = stdout
        .lines()
        .find(|l| l.starts_with("compile units: "))
        .unwrap_or_else(|| panic!("{stdout}"));
    let nums: Vec<usize> = line
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|w| w.parse().ok())
        .collect();
    (nums[0], nums[1])
}

fn tree(dir: &Path) -> Vec<(String, Vec<u8>)> {
    weft_compiler::output::list_files(dir)
        .unwrap()
        .into_iter()
        .map(|f| {
            let bytes = std::fs::read(dir.join(&f)).unwrap();
            (f, bytes)
        })
        .collect()
}

#[test]
fn checkouts_share_one_cache() {
    let tmp = tempfile::tempdir().unwrap();
    let cache = tmp.path().join("cache");
    let (a, b, c) = (
        tmp.path().join("a"),
        tmp.path().join("elsewhere/b"),
        tmp.path().join("c"),
    );
    for checkout in [&a, &b, &c] {
        copy(&repo().join("materials"), &checkout.join("materials"));
    }
    let (hits, compiled) = build(&a, &cache, &[]);
    assert_eq!(hits, 0);
    assert!(compiled >= 48, "{compiled} units");
    assert_eq!(build(&b, &cache, &[]), (compiled, 0));
    assert_eq!(tree(&a.join("generated")), tree(&b.join("generated")));
    // A shard of another checkout: its units come from the cache too.
    let (shard_hits, shard_compiled) = build(&c, &cache, &["--shard", "2/2"]);
    assert_eq!(shard_compiled, 0);
    assert!(shard_hits > 0 && shard_hits < compiled);

    // An edited material misses (its inputs changed); the others hit.
    let satin = b.join("materials/satin/satin.toml");
    let text = std::fs::read_to_string(&satin).unwrap();
    std::fs::write(&satin, text.replacen("default = 0.45", "default = 0.5", 1)).unwrap();
    let (hits, missed) = build(&b, &cache, &["--force"]);
    assert!(
        missed > 0 && hits > 0 && hits + missed == compiled,
        "{hits} + {missed}"
    );
}
