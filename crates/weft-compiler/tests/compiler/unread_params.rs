//! A parameter no variant reads is a warning at its declaration (`weft check`);
//! the build still succeeds.

use std::path::Path;
use weft_compiler::{BuildOptions, build_materials};

#[test]
fn a_parameter_no_variant_reads_is_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/diagnostics/materials");
    std::fs::create_dir_all(root.join("lib")).unwrap();
    std::fs::copy(corpus.join("lib/common.wgsl"), root.join("lib/common.wgsl")).unwrap();
    std::fs::create_dir_all(root.join("ok")).unwrap();
    std::fs::copy(corpus.join("ok/ok.wgsl"), root.join("ok/ok.wgsl")).unwrap();
    let toml = std::fs::read_to_string(corpus.join("ok/ok.toml")).unwrap()
        + "\n[params.unused_gloss]\ntype = \"float\"\ndefault = 0.5\nrange = [0.0, 1.0]\n";
    std::fs::write(root.join("ok/ok.toml"), toml).unwrap();

    let out = build_materials(
        &[root.join("ok/ok.toml")],
        Some(root),
        &BuildOptions::default(),
        &|_, _, _| {},
    )
    .unwrap_or_else(|(db, d)| panic!("{}", d.render_plain(&db)));
    let (db, warnings) = out.warnings.expect("a warning");
    let text = warnings.render_plain(&db);
    assert!(text.contains("warning[unread-param]"), "{text}");
    assert!(
        text.contains("`unused_gloss` is read by no variant"),
        "{text}"
    );
    assert!(!text.contains("`tint`"), "tint is read: {text}");
    // Every variant lists what it reads.
    for v in &out.materials[0].variants {
        if let Some(s) = &v.shader {
            assert_eq!(s.reads, ["tint"]);
        }
    }
}

/// A `constant` keyword no code reads leaves no override to set: the other
/// languages' files are still emitted, one per value.
#[test]
fn a_constant_keyword_no_code_reads_still_builds() {
    let dir = tempfile::tempdir().unwrap();
    let root = dir.path();
    let corpus = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/diagnostics/materials");
    std::fs::create_dir_all(root.join("lib")).unwrap();
    std::fs::copy(corpus.join("lib/common.wgsl"), root.join("lib/common.wgsl")).unwrap();
    std::fs::create_dir_all(root.join("ok")).unwrap();
    std::fs::copy(corpus.join("ok/ok.wgsl"), root.join("ok/ok.wgsl")).unwrap();
    let toml = std::fs::read_to_string(corpus.join("ok/ok.toml")).unwrap()
        + "\n[keywords.UNUSED_OPT]\ntype = \"toggle\"\nmode = \"constant\"\n";
    std::fs::write(root.join("ok/ok.toml"), toml).unwrap();
    let out = build_materials(
        &[root.join("ok/ok.toml")],
        Some(root),
        &BuildOptions::default(),
        &|_, _, _| {},
    )
    .unwrap_or_else(|(db, d)| panic!("{}", d.render_plain(&db)));
    let spirv = out
        .files
        .keys()
        .filter(|f| f.ends_with(".spv") && f.contains("+unused_opt-"))
        .count();
    assert!(spirv >= 2, "one SPIR-V file per value: {spirv}");
}
