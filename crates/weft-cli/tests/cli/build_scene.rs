//! `weft build --scene` as a user runs it: a scene that only the compiler can
//! reject (its front end accepts it) exits 1 with the diagnostic and writes nothing.

use std::process::Command;
use weft_tests::repo;

#[test]
fn build_scene_writes_nothing_when_the_compiler_rejects_the_scene() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_weft"))
        .current_dir(repo())
        .args([
            "build",
            "--color",
            "never",
            "--scene",
            "tests/diagnostics/scenes/bad/shader_budget.scene.toml",
            "-o",
        ])
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("error[shader-budget]"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!out.exists(), "no output folder on error");
    // Nothing half-written beside it either.
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn build_scene_replaces_only_its_own_folder() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir_all(out.join("other_scene")).unwrap();
    std::fs::write(out.join("other_scene/keep.txt"), "kept").unwrap();
    std::fs::create_dir_all(out.join("swatch_book")).unwrap();
    std::fs::write(out.join("swatch_book/stale.wgsl"), "old").unwrap();
    let build = || {
        Command::new(env!("CARGO_BIN_EXE_weft"))
            .current_dir(repo())
            .args(["build", "--scene", "scenes/swatch_book.scene.toml", "-o"])
            .arg(&out)
            .output()
            .unwrap()
    };
    // Not marked as weft's output: refused, left as it was.
    let o = build();
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        std::fs::read_to_string(out.join("swatch_book/stale.wgsl")).unwrap(),
        "old"
    );
    // An earlier build's folder (marked) is replaced.
    std::fs::write(out.join("swatch_book/.weft-output"), "").unwrap();
    let o = build();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    assert_eq!(
        std::fs::read_to_string(out.join("other_scene/keep.txt")).unwrap(),
        "kept"
    );
    assert!(
        !out.join("swatch_book/stale.wgsl").exists(),
        "the scene folder is replaced whole"
    );
    // Byte-identical to the committed build.
    let built = std::fs::read(out.join("swatch_book/swatch_book.scene.json")).unwrap();
    let committed =
        std::fs::read(repo().join("generated/scenes/swatch_book/swatch_book.scene.json")).unwrap();
    assert_eq!(built, committed);
}
