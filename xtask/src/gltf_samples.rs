//! `cargo xtask gltf-samples [--check]`: the committed glTF test content
//! (`scenes/gltf/`, `tests/gltf/`) from `weft_golden::gltf_samples`.

use std::path::Path;
use std::process::ExitCode;

pub(crate) fn gltf_samples(root: &Path, check: bool) -> ExitCode {
    let files = weft_golden::gltf_samples::committed_files();
    let stale: Vec<&String> = files
        .iter()
        .filter(|(path, bytes)| std::fs::read(root.join(path)).ok().as_ref() != Some(*bytes))
        .map(|(path, _)| path)
        .collect();
    if stale.is_empty() {
        println!("glTF samples are current ({} files)", files.len());
        return ExitCode::SUCCESS;
    }
    if check {
        for path in stale {
            eprintln!("stale: {path}");
        }
        eprintln!("run `cargo xtask gltf-samples` and commit the files");
        return ExitCode::FAILURE;
    }
    for path in stale {
        let target = root.join(path);
        let written = target
            .parent()
            .map_or(Ok(()), std::fs::create_dir_all)
            .and_then(|()| std::fs::write(&target, &files[path]));
        if let Err(e) = written {
            eprintln!("cannot write {}: {e}", target.display());
            return ExitCode::FAILURE;
        }
        println!("wrote {path}");
    }
    ExitCode::SUCCESS
}
