//! `cargo xtask bless`: rewrite tests/goldens/ from fresh renders (a golden the new render matches keeps its bytes).

use crate::render_sets::render_cases;
use crate::render_sets::render_scenes;
use std::path::Path;
use std::process::ExitCode;
use weft_compiler::output;

pub(crate) fn bless(root: &Path, force: bool) -> ExitCode {
    let goldens = root.join("tests/goldens");
    let mut files = std::collections::BTreeMap::new();
    // (kept, largest FLIP mean among them)
    let mut kept = (0usize, 0.0f32);
    // A golden the new render matches within the tests' threshold keeps its
    // bytes (re-blessing on another machine does not churn every PNG).
    let mut add = |rel: String, (w, h): (u32, u32), ldr: &[u8]| {
        let old = goldens.join(&rel);
        if !force
            && let Ok((ow, oh, rgba)) = weft_golden::read_png(&old)
            && (ow, oh) == (w, h)
            && let mean = weft_golden::flip(&rgba, ldr, w, h).mean
            && mean <= weft_golden::FLIP_MEAN_THRESHOLD
            && let Ok(bytes) = std::fs::read(&old)
        {
            kept = (kept.0 + 1, kept.1.max(mean));
            files.insert(rel, bytes);
            return;
        }
        files.insert(rel, weft_render::encode_png(w, h, ldr).expect("encode PNG"));
    };
    let size = weft_golden::GOLDEN_SIZE;
    let result = render_cases(root, size, |case, _, ldr| {
        let rel = weft_golden::golden_path(Path::new(""), case);
        add(rel.to_string_lossy().replace('\\', "/"), (size, size), &ldr);
    })
    .and_then(|adapter| {
        let size = weft_golden::scenes::SCENE_GOLDEN_SIZE;
        for (name, _, ldr) in render_scenes(root, size)? {
            let rel = weft_golden::scenes::scene_golden_path(Path::new(""), &name);
            add(rel.to_string_lossy().replace('\\', "/"), size, &ldr);
        }
        Ok(adapter)
    });
    match result.and_then(|adapter| {
        output::write_atomically(&goldens, &files, &[]).map_err(|e| e.to_string())?;
        Ok(adapter)
    }) {
        Ok(adapter) => {
            println!(
                "blessed {} goldens in tests/goldens/ on {adapter}",
                files.len()
            );
            if kept.0 > 0 {
                println!(
                    "kept {} of them unchanged: their new renders match within FLIP mean {} (largest {:.5}); `--force` rewrites them",
                    kept.0,
                    weft_golden::FLIP_MEAN_THRESHOLD,
                    kept.1
                );
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
