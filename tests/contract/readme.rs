//! The README's `build.rs` example is `docs/example/build.rs`, which
//! weft-compiler's doc tests compile (`readme_build_rs_example`): the two
//! must stay one text.

use weft_tests::{docs, repo};

#[test]
fn readme_build_rs_example_is_the_compiled_file() {
    let readme = docs::load(repo().join("README.md"));
    let example = docs::load(repo().join("docs/example/build.rs"));
    assert_eq!(
        docs::doc_block(&readme, "build-rs"),
        example,
        "README.md's build.rs block differs from docs/example/build.rs"
    );
}
