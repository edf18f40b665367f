//! weft compiler: a checked material -> validated shader variants in every
//! language, plus inspector metadata.
//!
//! Two halves, data flowing one way: [`compile`] holds the stages (nothing
//! there writes a file), [`scene`] the scene specialisation built on them,
//! [`bake`] the baked tables, and [`build`] the plumbing that runs the
//! stages over folders, caches, shards and writes outputs.
//!
//! Pipeline (one way): [`prelude`] (uniforms/bindings/keywords from the TOML)
//! -> [`compose`] (one WGSL module + source map) -> naga parse + validate once
//! -> per variant [`specialise`] (bake keywords and tier, drop dead branches,
//! compact) -> validate -> [`backends`] -> [`reflect`] (metadata from the
//! specialised module itself). [`library`] runs that over a materials folder
//! and [`output`] writes the result atomically. This is also the API for
//! `build.rs` scripts: see [`library::build_library`].

pub mod bake;
pub mod build;
pub mod compile;
pub mod scene;

// The stage and plumbing modules at the crate root too: these paths are the
// public API `build.rs` scripts, weft-render and the CLI use
// (`weft_compiler::output::write_atomically`, `weft_compiler::backends`, …).
pub use build::{
    cache, folder_build, in_memory, library, output, ownership, shard, staging, stamp, unchanged,
};
pub use compile::{
    backends, compose, digest, engine_binding, half, hlsl_samplers, hlsl_select, limits, metadata,
    nesting, prelude, reflect, source_map, specialise, stage_io, tables, texture_files, variant,
};

pub use in_memory::{InMemoryBuild, compile_in_memory};
pub use library::{
    BuildOptions, BuildOutput, build_library, build_materials, build_materials_streaming,
    compile_material,
};
pub use scene::{MAX_SCENE_SHADERS, SceneBuildOptions, SceneOutput, build_scene};

/// The README's `build.rs` example (`docs/example/build.rs`; a test keeps
/// the README's copy equal to it), compiled by `cargo test` as a doc test so
/// the API it shows cannot drift from the one `build.rs` users call.
#[doc = concat!("```no_run\n", include_str!("../../../docs/example/build.rs"), "```")]
mod readme_build_rs_example {}

/// The stages never reach the plumbing: no file under `compile/`, `scene/`
/// or `bake/` names `crate::build` or one of its modules (re-exported at the
/// root, so `crate::output` would hide the dependency).
#[cfg(test)]
#[test]
fn compile_stages_do_not_depend_on_build_plumbing() {
    let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let forbidden: Vec<String> = ["build", "cache", "folder_build", "in_memory", "library"]
        .iter()
        .chain(&[
            "output",
            "ownership",
            "shard",
            "staging",
            "stamp",
            "unchanged",
        ])
        .map(|m| format!("crate::{m}"))
        .collect();
    let mut offences = Vec::new();
    for half in ["compile", "scene", "bake"] {
        let mut stack = vec![src.join(half)];
        while let Some(dir) = stack.pop() {
            for entry in std::fs::read_dir(&dir).expect("read src folder") {
                let path = entry.expect("entry").path();
                if path.is_dir() {
                    stack.push(path);
                    continue;
                }
                if path.extension().is_none_or(|e| e != "rs") {
                    continue;
                }
                let text = std::fs::read_to_string(&path).expect("read source");
                for (n, line) in text.lines().enumerate() {
                    if line.trim_start().starts_with("//") {
                        continue;
                    }
                    let reaches = forbidden.iter().any(|f| {
                        line.match_indices(f.as_str()).any(|(i, _)| {
                            !line[i + f.len()..]
                                .starts_with(|c: char| c.is_alphanumeric() || c == '_')
                        })
                    });
                    if reaches {
                        offences.push(format!("{}:{}: {}", path.display(), n + 1, line.trim()));
                    }
                }
            }
        }
    }
    assert!(
        offences.is_empty(),
        "stages reach the build plumbing:\n{}",
        offences.join("\n")
    );
}
