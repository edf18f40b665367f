//! `weft build --shard k/n` and `weft merge`: the shards of the shipped
//! library, merged, are byte-identical to one unsharded build.

use std::path::Path;
use std::process::{Command, Output};
use weft_tests::repo;

fn weft(args: &[&str]) -> Output {
    let o = Command::new(env!("CARGO_BIN_EXE_weft"))
        .current_dir(repo())
        .args(args)
        .output()
        .unwrap();
    assert!(
        o.status.success(),
        "weft {args:?}: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    o
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
fn merged_shards_equal_the_unsharded_build() {
    let tmp = tempfile::tempdir().unwrap();
    let path = |name: &str| tmp.path().join(name).to_str().unwrap().to_string();
    let full = weft(&["build", "materials", "-o", &path("full")]);
    // "built N material(s), …": every shipped material.
    let shipped: usize = String::from_utf8_lossy(&full.stdout)
        .split_whitespace()
        .nth(1)
        .and_then(|m| m.parse().ok())
        .expect("the build reports its material count");
    // Two shard counts: every material lands in exactly one shard of each.
    for n in [2, 3] {
        let mut shards = Vec::new();
        let mut materials = 0;
        for k in 1..=n {
            let out = path(&format!("shard-{k}-of-{n}"));
            let shard = format!("{k}/{n}");
            let o = weft(&["build", "materials", "--shard", &shard, "-o", &out]);
            let line = String::from_utf8_lossy(&o.stdout).into_owned();
            materials += line
                .split_whitespace()
                .nth(1)
                .and_then(|m| m.parse::<usize>().ok())
                .unwrap_or_else(|| panic!("{line}"));
            let marker = std::fs::read_to_string(tmp.path().join(&out).join(".weft-shard"));
            // The shard, and the whole library's inputs it was built from.
            let marker = marker.unwrap();
            assert!(marker.starts_with(&format!("{shard}\ninputs ")), "{marker}");
            shards.push(out);
        }
        assert_eq!(
            materials, shipped,
            "each shipped material in one shard of {n}"
        );
        let merged = path(&format!("merged-{n}"));
        let mut args = vec!["merge"];
        args.extend(shards.iter().map(String::as_str));
        args.extend(["-o", &merged]);
        weft(&args);
        assert!(
            tree(Path::new(&merged)) == tree(Path::new(&path("full"))),
            "merging {n} shards differs from the unsharded build"
        );
        // A missing shard is refused, and nothing is written.
        let o = Command::new(env!("CARGO_BIN_EXE_weft"))
            .current_dir(repo())
            .args(["merge", &shards[0], "-o", &path("partial")])
            .output()
            .unwrap();
        assert_eq!(o.status.code(), Some(1));
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains("missing shard(s)"), "{err}");
        assert!(!tmp.path().join("partial").exists());
    }
}
