//! What weft-render's test modules share: `ok`, and materials roots built
//! once per binary from their TOML (so the tests do
//! not depend on generated/ being current).

use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use weft_render::Result;
use weft_tests::repo;

pub fn ok<T>(r: Result<T>) -> T {
    r.unwrap_or_else(|e| panic!("{e}"))
}

/// Builds each `(root, name)` (a materials folder relative to the
/// repository, and its output folder name) into `<target tmp>/<dir>/<name>`
/// on the first call; later calls return the same folder.
pub fn built(cell: &'static OnceLock<PathBuf>, dir: &str, roots: &[(&str, &str)]) -> &'static Path {
    cell.get_or_init(|| {
        let out = Path::new(env!("CARGO_TARGET_TMPDIR")).join(dir);
        for (root, name) in roots {
            let built = weft_compiler::build_library(
                &repo().join(root),
                &weft_compiler::BuildOptions::default(),
                &|_, _, _| {},
            )
            .unwrap_or_else(|_| panic!("{root} does not build"));
            weft_compiler::output::write_atomically(&out.join(name), &built.files, &[])
                .expect("write the build");
        }
        out
    })
}

/// `<built>/<root>/<material>/<material>.meta.json`.
pub fn meta_path(built: &Path, root: &str, material: &str) -> PathBuf {
    built
        .join(root)
        .join(material)
        .join(format!("{material}.meta.json"))
}
