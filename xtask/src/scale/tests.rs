//! Determinism, the WGSL rewrite, and every base yielding a material that
//! compiles.

use super::wgsl::{strip_attributes, wrap_fragment};
use super::*;

fn shipped() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../materials")
}

#[test]
fn attributes_are_stripped_and_the_entry_wrapped() {
    assert_eq!(
        strip_attributes("@builtin(front_facing) ff: bool"),
        "ff: bool"
    );
    let src = "@fragment\nfn fs(in: WeftVaryings, @builtin(front_facing) ff: bool) -> @location(0) vec4<f32> {\n    return vec4<f32>(1.0);\n}\n";
    let out = wrap_fragment(src, "fs", "").unwrap();
    assert!(
        out.starts_with("fn weft_syn_base_fs(in: WeftVaryings, ff: bool) -> vec4<f32> {"),
        "{out}"
    );
    assert!(out.contains("var c = weft_syn_base_fs(in, ff);"), "{out}");
    assert!(out.contains(
        "@fragment\nfn fs(in: WeftVaryings, @builtin(front_facing) ff: bool) -> @location(0) vec4<f32> {"
    ));
}

/// One synthetic material per shipped base compiles without warnings,
/// with the variant count the generator promised; generation is
/// deterministic.
#[test]
fn every_base_yields_a_compiling_material() {
    let tmp = tempfile::tempdir().unwrap();
    let dest = tmp.path().join("materials");
    let bases = load_bases(&shipped()).unwrap();
    let lib = generate(&shipped(), &dest, bases.len(), 48, DEFAULT_SEED).unwrap();
    let again = tmp.path().join("again");
    generate(&shipped(), &again, bases.len(), 48, DEFAULT_SEED).unwrap();
    for name in weft_compiler::output::list_files(&dest).unwrap() {
        assert_eq!(
            std::fs::read(dest.join(&name)).unwrap(),
            std::fs::read(again.join(&name)).unwrap(),
            "{name} differs between two runs"
        );
    }
    let out = match weft_compiler::build_library(&dest, &Default::default(), &|_, _, _| {}) {
        Ok(out) => out,
        Err((db, diags)) => {
            let mut s = codespan_reporting::term::termcolor::Buffer::no_color();
            diags.emit(&db, &mut s);
            panic!("{}", String::from_utf8_lossy(s.as_slice()));
        }
    };
    if let Some((db, diags)) = &out.warnings {
        let mut s = codespan_reporting::term::termcolor::Buffer::no_color();
        diags.emit(db, &mut s);
        panic!("warnings: {}", String::from_utf8_lossy(s.as_slice()));
    }
    assert_eq!(out.materials.len(), bases.len());
    assert_eq!(out.variant_count, lib.variants);
    // Each material lands within a factor sqrt(3) of the target (the
    // keywords multiply the base's count by a 2^a 3^b).
    let target = 48.0 * bases.len() as f64;
    let ratio = lib.variants as f64 / target;
    assert!(
        (0.577..=1.733).contains(&ratio),
        "{} variants for a target of {target}",
        lib.variants
    );
}
