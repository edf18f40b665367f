//! Scene builds of the shipped scenes: exactly one shader per distinct
//! instance, byte-deterministic, and only what each instance reads.

use std::path::{Path, PathBuf};
use weft_compiler::{SceneBuildOptions, build_scene};

fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../../scenes/{name}.scene.toml"))
}

#[test]
fn swatch_book_builds_one_shader_per_preset() {
    let out = build_scene(&scene("swatch_book"), &SceneBuildOptions::default())
        .unwrap_or_else(|(db, d)| panic!("{}", d.render_plain(&db)));
    assert_eq!(out.metadata.instances.len(), 6);
    assert_eq!(
        out.metadata.shaders.len(),
        6,
        "each preset folds differently"
    );
    for inst in &out.metadata.instances {
        let shader = out
            .metadata
            .shaders
            .iter()
            .find(|s| s.id == inst.shader)
            .expect("shader");
        // No dynamic parameters: only curves (read with a run-time index) may stay.
        if let Some(u) = &shader.shader.material_uniform {
            assert!(
                u.members.iter().all(|m| m.name.ends_with("_curve")),
                "{:?}",
                u.members
            );
        }
        assert!(inst.dynamic.is_empty());
    }
    let again = build_scene(&scene("swatch_book"), &SceneBuildOptions::default())
        .ok()
        .unwrap();
    assert_eq!(out.files, again.files, "scene builds are deterministic");
}

#[test]
#[ignore]
fn dump_swatch_book() {
    let out = build_scene(&scene("swatch_book"), &SceneBuildOptions::default())
        .ok()
        .unwrap();
    weft_compiler::output::write_atomically(Path::new("/tmp/scene_out"), &out.files, &[]).unwrap();
}

#[test]
#[ignore]
fn dump_scene_from_env() {
    let p = std::env::var("WEFT_SCENE").unwrap();
    let out = build_scene(Path::new(&p), &SceneBuildOptions::default())
        .unwrap_or_else(|(db, d)| panic!("{}", d.render_plain(&db)));
    weft_compiler::output::write_atomically(Path::new("/tmp/scene_out"), &out.files, &[]).unwrap();
}
