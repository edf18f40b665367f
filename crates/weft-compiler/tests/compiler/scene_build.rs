//! Scene builds of the shipped scenes: exactly one shader per distinct
//! instance, byte-deterministic, and only what each instance reads.

use std::path::{Path, PathBuf};
use weft_compiler::{MAX_SCENE_SHADERS, SceneBuildOptions, build_scene};

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

fn temp_scene(body: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let materials = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../materials")
        .canonicalize()
        .unwrap();
    let text = format!(
        "[scene]\nname = \"probe\"\nmaterials = {:?}\nvertex_inputs = [\"position\", \"normal\", \"tangent\", \"uv0\"]\n\n{body}",
        materials.to_string_lossy()
    );
    let path = dir.path().join("probe.scene.toml");
    std::fs::write(&path, text).unwrap();
    (dir, path)
}

#[test]
fn a_dynamic_parameter_the_shader_does_not_read_is_a_warning() {
    // normal_strength is only read with NORMAL_MAP on.
    let (_dir, path) = temp_scene(
        "[[instances]]\nname = \"ball\"\nmaterial = \"standard\"\nmesh = \"sphere\"\nkeywords = { NORMAL_MAP = \"off\" }\ndynamic = [\"normal_strength\", \"roughness\"]\n",
    );
    let out = build_scene(&path, &SceneBuildOptions::default())
        .unwrap_or_else(|(db, d)| panic!("{}", d.render_plain(&db)));
    let (db, warnings) = out.warnings.expect("a warning");
    let text = warnings.render_plain(&db);
    assert!(text.contains("warning[unread-dynamic]"), "{text}");
    assert!(text.contains("`normal_strength`"), "{text}");
    assert!(!text.contains("`roughness` is not read"), "{text}");
    let inst = &out.metadata.instances[0];
    assert_eq!(inst.dynamic, ["normal_strength", "roughness"]);
    assert_eq!(
        inst.uniform_values.keys().collect::<Vec<_>>(),
        ["roughness"]
    );
}

#[test]
fn identical_instances_share_one_shader_and_differing_constants_do_not() {
    let (_dir, path) = temp_scene(
        "[[instances]]\nname = \"a\"\nmaterial = \"standard\"\nmesh = \"sphere\"\nparams = { roughness = 0.3 }\n\n\
         [[instances]]\nname = \"b\"\nmaterial = \"standard\"\nmesh = \"cloth\"\nparams = { roughness = 0.3 }\ntranslation = [1.0, 0.0, 0.0]\n\n\
         [[instances]]\nname = \"c\"\nmaterial = \"standard\"\nmesh = \"sphere\"\nparams = { roughness = 0.7 }\n",
    );
    let out = build_scene(&path, &SceneBuildOptions::default())
        .unwrap_or_else(|(db, d)| panic!("{}", d.render_plain(&db)));
    let ids: Vec<_> = out
        .metadata
        .instances
        .iter()
        .map(|i| i.shader.as_str())
        .collect();
    assert_eq!(ids[0], ids[1]);
    assert_ne!(ids[0], ids[2]);
    assert_eq!(out.metadata.shaders.len(), 2);
}

#[test]
fn auto_tier_without_a_chooser_fails_at_the_tier_line() {
    let (_dir, path) = temp_scene(
        "[[instances]]\nname = \"a\"\nmaterial = \"silk\"\nmesh = \"cloth\"\ntier = \"auto\"\nerror_budget = 0.05\nscreen_size = 128\n",
    );
    let Err((db, diags)) = build_scene(&path, &SceneBuildOptions::default()) else {
        panic!("an auto tier cannot be decided without measurements");
    };
    let text = diags.render_plain(&db);
    assert!(
        text.contains("error[auto-tier]") && text.contains("probe.scene.toml:10"),
        "{text}"
    );
}

fn standard_instances(n: usize, roughness: impl Fn(usize) -> f64) -> String {
    (0..n)
        .map(|i| {
            format!(
                "[[instances]]\nname = \"i{i}\"\nmaterial = \"standard\"\nmesh = \"sphere\"\n\
                 params = {{ roughness = {} }}\ntranslation = [{i}.0, 0.0, 0.0]\n\n",
                roughness(i)
            )
        })
        .collect()
}

#[test]
fn the_shader_cap_counts_distinct_specialisations_not_instances() {
    // One more distinct specialisation than the cap: refused before anything
    // is compiled, at the first instance beyond it.
    let (_dir, path) = temp_scene(&standard_instances(MAX_SCENE_SHADERS + 1, |i| {
        0.1 + 0.5 * i as f64 / MAX_SCENE_SHADERS as f64
    }));
    let Err((db, diags)) = build_scene(&path, &SceneBuildOptions::default()) else {
        panic!("{} distinct shaders must be refused", MAX_SCENE_SHADERS + 1);
    };
    let text = diags.render_plain(&db);
    assert!(
        text.contains("error[too-many-shaders]")
            && text.contains(&format!("needs {} distinct", MAX_SCENE_SHADERS + 1))
            && text.contains(&format!("instance `i{MAX_SCENE_SHADERS}`")),
        "{text}"
    );
    // More instances than the cap, all of one specialisation: one shader,
    // compiled once.
    let (_dir, path) = temp_scene(&standard_instances(MAX_SCENE_SHADERS + 44, |_| 0.3));
    let out = build_scene(&path, &SceneBuildOptions::default())
        .unwrap_or_else(|(db, d)| panic!("{}", d.render_plain(&db)));
    assert_eq!(out.metadata.instances.len(), MAX_SCENE_SHADERS + 44);
    assert_eq!(out.metadata.shaders.len(), 1);
}
