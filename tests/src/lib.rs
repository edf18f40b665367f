//! The one support library of weft's integration tests. The tests are four
//! binaries by area (`contract/`, `inputs/`, `physics/`, `rendering/`, each a
//! `main.rs` with one module per concern, and `stability/` alone); what more than one of them needs
//! lives here, written once: where the workspace is, tree copies, and the
//! readers of docs, schemas and shader lists. The crates' own
//! integration tests use it too (as a dev-dependency). GPU set-up and image
//! comparison are not here: they are `weft_render::Gpu` and `weft_golden`'s
//! FLIP and PNG helpers, which the product's benches use as well.

pub mod docs;
pub mod schema;
pub mod shaders;
pub mod thin_film;

use std::path::{Path, PathBuf};

/// The workspace root (the folder holding `materials/`, `generated/`, `tests/`).
pub fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("tests/ sits in the workspace root")
        .to_path_buf()
}

/// Copies the tree `from` into `to` (created), files and folders; panics with
/// the path on any error, as a test should. Symbolic links are copied as the
/// files they point to.
pub fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap_or_else(|e| panic!("create {}: {e}", to.display()));
    let entries =
        std::fs::read_dir(from).unwrap_or_else(|e| panic!("read {}: {e}", from.display()));
    for entry in entries {
        let path = entry
            .unwrap_or_else(|e| panic!("read {}: {e}", from.display()))
            .path();
        let target = to.join(path.file_name().expect("a directory entry has a name"));
        if path.is_dir() {
            copy_dir(&path, &target);
        } else {
            std::fs::copy(&path, &target)
                .unwrap_or_else(|e| panic!("copy {} to {}: {e}", path.display(), target.display()));
        }
    }
}

/// One GPU-using test at a time within a test binary: the `physics` and
/// `rendering` tests that create a wgpu device (themselves or through a
/// helper, a renderer, a preview or the inspector's page) call this first;
/// tests that only build, bake or integrate on the CPU do not, and run
/// beside them. (`stability`'s sweeps, each on one thread, run side by
/// side.)
/// With the tests of many modules in one process, Mesa 22.3's lavapipe
/// corrupted its heap while the stability sweep ran beside other modules'
/// devices ("free(): corrupted unsorted chunks", CI, 2026-11-27; the sweep
/// was then leaking gigabytes of JIT-compiled shaders, see
/// docs/performance.md "Fresh clone"); separate binaries never ran them side
/// by side. lavapipe spreads each draw over every core, so running them one
/// by one costs little wall time.
pub fn gpu_serial() -> std::sync::MutexGuard<'static, ()> {
    static LOCK: std::sync::Mutex<()> = std::sync::Mutex::new(());
    // A test that panicked holding it leaves nothing to repair.
    LOCK.lock().unwrap_or_else(|e| e.into_inner())
}
