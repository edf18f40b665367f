//! Resolution rules of scene manifests, on a small material written to a
//! temporary materials root: default < preset < instance values, keyword
//! values for every keyword, tiers, `dynamic`, exclusions, and no panic on
//! damaged files.

use super::load_scene;
use super::model::*;
use crate::diag::{Diagnostics, SourceDb};
use crate::model::{ParamValue, VertexAttribute};
use std::path::{Path, PathBuf};
use weft_meta::TextureDefault;

const MATERIAL: &str = r#"
[material]
name = "m"
source = "m.wgsl"

[params.a]
type = "float"
default = 0.1
range = [0.0, 1.0]

[params.b]
type = "float"
default = 0.2
range = [0.0, 1.0]

[params.c]
type = "float"
default = 0.3
range = [0.0, 1.0]

[params.n]
type = "int"
default = 1
range = [0, 8]

[params.col]
type = "color"
default = [1.0, 1.0, 1.0]

[params.tex]
type = "texture2d"
default = "white"

[keywords.TOGGLE]
type = "toggle"
default = true

[keywords.CHOICE]
type = "enum"
values = ["x", "y", "z"]
default = "y"

[keywords.PIPE]
type = "enum"
values = ["p", "q"]
default = "q"
mode = "constant"

[[tier]]
name = "fast"

[[tier]]
name = "reference"

[variants]
exclude = ["tier == reference && CHOICE == z", "TOGGLE == off && CHOICE == x"]

[presets.warm]
values = { a = 0.5, b = 0.6, n = 3, col = [0.1, 0.2, 0.3], CHOICE = "x", PIPE = "p", tier = "reference" }
"#;

/// A materials root with material `m`, and `scenes/t.scene.toml` holding `scene`.
fn write_fixture(scene: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().expect("temp dir");
    let m = dir.path().join("materials/m");
    std::fs::create_dir_all(&m).expect("material dir");
    std::fs::write(m.join("m.toml"), MATERIAL).expect("m.toml");
    std::fs::write(m.join("m.wgsl"), "// not compiled by the front end\n").expect("m.wgsl");
    std::fs::create_dir_all(dir.path().join("scenes")).expect("scenes dir");
    let path = dir.path().join("scenes/t.scene.toml");
    std::fs::write(&path, scene).expect("scene");
    (dir, path)
}

fn scene_text(instances: &str) -> String {
    format!(
        "[scene]\nname = \"t\"\nvertex_inputs = [\"position\", \"normal\", \"uv0\"]\n\n{instances}"
    )
}

fn load(path: &Path) -> Result<ResolvedScene, String> {
    let (mut db, mut diags) = (SourceDb::new(), Diagnostics::new());
    load_scene(path, &mut db, &mut diags).ok_or_else(|| diags.render_plain(&db))
}

fn resolve_ok(instances: &str) -> ResolvedScene {
    let (_dir, path) = write_fixture(&scene_text(instances));
    load(&path).unwrap_or_else(|e| panic!("scene failed:\n{e}"))
}

fn codes(instances: &str) -> Vec<String> {
    let (_dir, path) = write_fixture(&scene_text(instances));
    let (mut db, mut diags) = (SourceDb::new(), Diagnostics::new());
    assert!(load_scene(&path, &mut db, &mut diags).is_none());
    diags.iter().filter_map(|d| d.code.clone()).collect()
}

fn value<'s>(scene: &'s ResolvedScene, inst: usize, param: &str) -> &'s ParamValue {
    let i = &scene.instances[inst];
    let m = &scene.materials[i.material];
    let p = m
        .params
        .iter()
        .position(|p| p.name == param)
        .expect("param");
    &i.values[p]
}

fn keyword(scene: &ResolvedScene, inst: usize, name: &str) -> String {
    let i = &scene.instances[inst];
    let m = &scene.materials[i.material];
    let k = m
        .keywords
        .iter()
        .position(|k| k.name == name)
        .expect("keyword");
    m.keywords[k].values[i.keywords[k]].clone()
}

#[test]
fn values_resolve_default_then_preset_then_instance() {
    let s = resolve_ok(
        r#"
[[instances]]
name = "plain"
material = "m"
mesh = "sphere"

[[instances]]
name = "preset_only"
material = "m"
preset = "warm"
mesh = "sphere"

[[instances]]
name = "both"
material = "m"
preset = "warm"
params = { b = 0.9, n = 7, tex = "black" }
mesh = "sphere"
"#,
    );
    // Defaults; a three-component colour default gets alpha 1.
    assert_eq!(value(&s, 0, "a"), &ParamValue::Float(0.1));
    assert_eq!(value(&s, 0, "b"), &ParamValue::Float(0.2));
    assert_eq!(value(&s, 0, "n"), &ParamValue::Int(1));
    assert_eq!(
        value(&s, 0, "col"),
        &ParamValue::Vector(vec![1.0, 1.0, 1.0, 1.0])
    );
    // The preset over the defaults, in the parameters' own representation.
    assert_eq!(value(&s, 1, "a"), &ParamValue::Float(0.5));
    assert_eq!(value(&s, 1, "b"), &ParamValue::Float(0.6));
    assert_eq!(value(&s, 1, "c"), &ParamValue::Float(0.3));
    assert_eq!(value(&s, 1, "n"), &ParamValue::Int(3));
    assert_eq!(
        value(&s, 1, "col"),
        &ParamValue::Vector(vec![0.1, 0.2, 0.3, 1.0])
    );
    // The instance over the preset.
    assert_eq!(value(&s, 2, "a"), &ParamValue::Float(0.5));
    assert_eq!(value(&s, 2, "b"), &ParamValue::Float(0.9));
    assert_eq!(value(&s, 2, "n"), &ParamValue::Int(7));
    assert_eq!(
        value(&s, 2, "tex"),
        &ParamValue::Texture(TextureDefault::Black)
    );
    // One value per parameter, in declaration order.
    for i in &s.instances {
        assert_eq!(i.values.len(), s.materials[i.material].params.len());
    }
}

#[test]
fn keywords_resolve_default_then_preset_then_instance() {
    let s = resolve_ok(
        r#"
[[instances]]
name = "plain"
material = "m"
mesh = "sphere"

[[instances]]
name = "preset_only"
material = "m"
preset = "warm"
mesh = "sphere"

[[instances]]
name = "both"
material = "m"
preset = "warm"
keywords = { CHOICE = "y", PIPE = "q", TOGGLE = false }
tier = "fast"
mesh = "sphere"
"#,
    );
    let kw = |i, n| keyword(&s, i, n);
    // Defaults, static and constant mode alike.
    assert_eq!(
        (kw(0, "TOGGLE"), kw(0, "CHOICE"), kw(0, "PIPE")),
        ("on".into(), "y".into(), "q".into())
    );
    assert_eq!(
        (kw(1, "TOGGLE"), kw(1, "CHOICE"), kw(1, "PIPE")),
        ("on".into(), "x".into(), "p".into())
    );
    // `false` reads as `off`, as in presets.
    assert_eq!(
        (kw(2, "TOGGLE"), kw(2, "CHOICE"), kw(2, "PIPE")),
        ("off".into(), "y".into(), "q".into())
    );
}

#[test]
fn every_keyword_gets_a_value() {
    let s = resolve_ok(
        r#"
[[instances]]
name = "plain"
material = "m"
keywords = { CHOICE = "z" }
mesh = "cloth"
"#,
    );
    let i = &s.instances[0];
    let m = &s.materials[i.material];
    assert_eq!(i.keywords.len(), m.keywords.len());
    assert!(
        m.keywords
            .iter()
            .any(|k| k.mode == weft_meta::KeywordMode::Constant)
    );
    for (k, v) in m.keywords.iter().zip(&i.keywords) {
        assert!(*v < k.values.len(), "{}: value {v} out of range", k.name);
    }
}

#[test]
fn tiers_resolve_instance_then_preset_then_default() {
    let s = resolve_ok(
        r#"
[[instances]]
name = "plain"
material = "m"
mesh = "sphere"

[[instances]]
name = "preset_tier"
material = "m"
preset = "warm"
mesh = "sphere"

[[instances]]
name = "written"
material = "m"
preset = "warm"
tier = "fast"
mesh = "sphere"

[[instances]]
name = "auto"
material = "m"
tier = "auto"
error_budget = 0.05
screen_size = 256
mesh = "sphere"
"#,
    );
    let tiers: Vec<&TierChoice> = s.instances.iter().map(|i| &i.tier).collect();
    assert_eq!(
        tiers,
        [
            &TierChoice::Fixed(0),
            &TierChoice::Fixed(1),
            &TierChoice::Fixed(0),
            &TierChoice::Auto {
                error_budget: 0.05,
                screen_size: 256
            },
        ]
    );
}

#[test]
fn dynamic_mesh_transform_and_vertex_inputs() {
    let s = resolve_ok(
        r#"
[[instances]]
name = "one"
material = "m"
dynamic = ["col", "a"]
mesh = "swatch"
vertex_inputs = ["uv0", "position"]
translation = [1.0, 2.0, 3.0]
rotation = [0.0, 90.0, 0.0]
scale = 2.0

[[instances]]
name = "two"
material = "m"
mesh = "cloth"
scale = [1.0, 2.0, 3.0]
"#,
    );
    let (one, two) = (&s.instances[0], &s.instances[1]);
    assert_eq!(one.dynamic, [4, 0]);
    assert_eq!(one.dynamic_spans.len(), 2);
    assert_eq!(one.mesh.name(), BuiltinMesh::Swatch.name());
    assert_eq!(
        one.vertex_inputs,
        [VertexAttribute::Position, VertexAttribute::Uv0]
    );
    assert_eq!(one.transform.translation, [1.0, 2.0, 3.0]);
    assert_eq!(one.transform.rotation_degrees, [0.0, 90.0, 0.0]);
    assert_eq!(one.transform.scale, [2.0; 3]);
    assert_eq!(
        two.vertex_inputs,
        [
            VertexAttribute::Position,
            VertexAttribute::Normal,
            VertexAttribute::Uv0
        ]
    );
    assert_eq!(two.transform.scale, [1.0, 2.0, 3.0]);
    assert_eq!(s.materials.len(), 1, "a material is loaded once");
    assert_eq!(s.manifest.features, SceneFeatures::default());
    assert_eq!(s.manifest.camera, Camera::default());
}

#[test]
fn excluded_combinations_are_errors() {
    // reference && CHOICE == z is excluded.
    let got = codes(
        r#"
[[instances]]
name = "one"
material = "m"
tier = "reference"
keywords = { CHOICE = "z" }
mesh = "sphere"
"#,
    );
    assert_eq!(got, ["excluded-variant"]);
    // With `auto`, one tier left is enough...
    resolve_ok(
        r#"
[[instances]]
name = "one"
material = "m"
tier = "auto"
error_budget = 0.1
screen_size = 64
keywords = { CHOICE = "z" }
mesh = "sphere"
"#,
    );
    // ...but TOGGLE == off && CHOICE == x removes every tier.
    let got = codes(
        r#"
[[instances]]
name = "one"
material = "m"
tier = "auto"
error_budget = 0.1
screen_size = 64
keywords = { CHOICE = "x", TOGGLE = "off" }
mesh = "sphere"
"#,
    );
    assert_eq!(got, ["excluded-variant"]);
}

#[test]
fn instance_problems_have_codes() {
    let got = codes(
        r#"
[[instances]]
name = "one"
material = "m"
preset = "cold"
keywords = { CHOICE = "w", NOPE = "on" }
params = { a = 2.0, zz = 1.0, n = 1.5 }
dynamic = ["a", "a", "q"]
tier = "medium"
mesh = "cube"
"#,
    );
    for code in [
        "unknown-preset",
        "unknown-value",
        "unknown-keyword",
        "out-of-range",
        "unknown-param",
        "wrong-type",
        "duplicate",
        "unknown-tier",
        "unknown-mesh",
    ] {
        assert!(got.iter().any(|c| c == code), "no `{code}` in {got:?}");
    }
}

/// Damaged files (every prefix of a valid scene, and bytes replaced by
/// characters that matter to TOML) produce diagnostics, never a panic.
#[test]
fn damaged_scenes_do_not_panic() {
    let text = scene_text(
        r#"
[camera]
position = [0.0, 0.3, 3.2]
fov_degrees = 35.0

[[instances]]
name = "one"
material = "m"
preset = "warm"
tier = "auto"
error_budget = 0.05
screen_size = 256
keywords = { CHOICE = "z", TOGGLE = false }
params = { a = 0.5, col = [0.1, 0.2, 0.3], n = 2, tex = "gray" }
dynamic = ["a"]
mesh = "cloth"
scale = [1.0, 2.0, 3.0]
"#,
    );
    let (_dir, path) = write_fixture(&text);
    load(&path).expect("the undamaged scene resolves");
    let mut damaged: Vec<String> = (0..text.len())
        .filter(|i| text.is_char_boundary(*i))
        .map(|i| text[..i].to_string())
        .collect();
    for (i, c) in text.char_indices() {
        if c.is_ascii_alphanumeric() || c == '"' || c == ']' {
            for r in ["\"", "[", "]", "-", "9e999", "{", "", "0"] {
                damaged.push(format!("{}{r}{}", &text[..i], &text[i + c.len_utf8()..]));
            }
        }
    }
    for d in damaged {
        std::fs::write(&path, &d).expect("write");
        let _ = load(&path);
    }
}

/// What one file can make a build do is bounded: the instance count, and
/// numbers that would overflow the f32 the GPU receives.
#[test]
fn limits_bound_instances_and_f32_numbers() {
    let one = "[[instances]]\nname = \"i{}\"\nmaterial = \"m\"\nmesh = \"sphere\"\n";
    let many: String = (0..=super::parse::MAX_INSTANCES)
        .map(|i| one.replace("{}", &i.to_string()))
        .collect();
    assert_eq!(codes(&many), ["too-many-instances"]);
    let at_limit: String = (0..super::parse::MAX_INSTANCES)
        .map(|i| one.replace("{}", &i.to_string()))
        .collect();
    assert_eq!(
        resolve_ok(&at_limit).instances.len(),
        super::parse::MAX_INSTANCES
    );
    let base = one.replace("{}", "0");
    for bad in [
        "translation = [1e39, 0, 0]",
        "scale = 1e39",
        "scale = [1, 1e300, 1]",
        "rotation = [0, 0, -4e38]",
    ] {
        assert_eq!(codes(&format!("{base}{bad}\n")), ["type-range"], "{bad}");
    }
    let light = format!("[light]\ndirection = [0, 0, 1]\ncolor = [1e39, 1, 1]\n\n{base}");
    assert_eq!(codes(&light), ["type-range"]);
    let camera = format!("[camera]\nposition = [0, 0, 1e40]\n\n{base}");
    assert_eq!(codes(&camera), ["type-range"]);
}

#[test]
fn gpu_family_defaults_to_rdna2_and_must_be_modelled() {
    let instance = "[[instances]]\nname = \"a\"\nmaterial = \"m\"\nmesh = \"sphere\"\n";
    assert_eq!(resolve_ok(instance).manifest.gpu_family, "navi21");
    let with = |family: &str| {
        format!(
            "[scene]\nname = \"t\"\nvertex_inputs = [\"position\", \"normal\", \"uv0\"]\ngpu_family = \"{family}\"\n\n{instance}"
        )
    };
    let (_dir, path) = write_fixture(&with("gfx1100"));
    assert_eq!(load(&path).unwrap().manifest.gpu_family, "gfx1100");
    // Later Mesa's name for RDNA3 is read as weft's.
    let (_dir, path) = write_fixture(&with("navi31"));
    assert_eq!(load(&path).unwrap().manifest.gpu_family, "gfx1100");
    let (_dir, path) = write_fixture(&with("navi24"));
    let e = load(&path).expect_err("not a modelled family");
    assert!(e.contains("unknown `gpu_family` `navi24`"), "{e}");
    assert!(e.contains("navi21, gfx1100"), "{e}");
    assert!(e.contains("`gfx1100` is also navi31"), "{e}");
    assert!(e.contains("t.scene.toml:4:14"), "{e}");
}
