//! The whole project built the one way `cargo xtask regenerate` and the tests
//! build it: the library under `<root>/materials`, then every scene manifest
//! under `<root>/scenes` (their files under `scenes/<scene>/`), `auto` tiers
//! measured on the local Vulkan adapter with the bench reports of
//! `<root>/generated/reports`.

use codespan_reporting::diagnostic::Diagnostic;
use std::path::Path;
use weft_auto::LavapipeTierChooser;
use weft_compiler::{BuildOptions, BuildOutput, SceneBuildOptions, build_library};
use weft_front::{Diagnostics, SourceDb};

/// Builds `<root>/materials` and every `<root>/scenes/*.scene.toml`; the
/// scene files (`scenes/<scene>/…`) are merged into the library's files.
/// `options.jobs` also sizes the rayon pool the scenes are built on. Scene
/// warnings are dropped (the library's are kept in `warnings`). Writes nothing.
pub fn build_project(
    root: &Path,
    options: &BuildOptions,
) -> Result<BuildOutput, (SourceDb, Diagnostics)> {
    let mut out = build_library(&root.join("materials"), options, &|_, _, _| {})?;
    let chooser = LavapipeTierChooser::new(None)
        .map(|c| c.with_reports_dir(root.join("generated/reports")))
        .map_err(error)?;
    let scene_options = SceneBuildOptions {
        tier_chooser: Some(&chooser),
        ..Default::default()
    };
    let scenes = root.join("scenes");
    let build = || weft_compiler::scene::build_scene_folder(&scenes, &scene_options);
    let (files, _) = match options.jobs {
        None => build()?,
        Some(jobs) => rayon::ThreadPoolBuilder::new()
            .num_threads(jobs)
            .build()
            .map_err(|e| error(format!("cannot start {jobs} worker threads: {e}")))?
            .install(build)?,
    };
    out.files.extend(files);
    // The built-in meshes the scenes name (`meshes/<name>.mesh`), beside
    // the LUTs in the library root.
    let meshes = weft_render::builtin_mesh_files()
        .map_err(|e| error(format!("cannot write the built-in meshes: {e}")))?;
    out.files.extend(meshes);
    Ok(out)
}

fn error(message: String) -> (SourceDb, Diagnostics) {
    let mut diags = Diagnostics::new();
    diags.push(Diagnostic::error().with_message(message));
    (SourceDb::new(), diags)
}
