//! The bad-scene corpus (`tests/diagnostics/scenes/bad/`): every file fails
//! with the diagnostics its EXPECTED entry lists, rendered exactly as the CLI
//! shows them (snapshots in `tests/snapshots/scene_diagnostics__*.snap`).
//! The corpus goes through the compiler's `build_scene`, which runs the front
//! end first: one path covers what the front end diagnoses and what only the
//! compiler can (a vertex input the specialised shader reads, the shader
//! budget), and a failed build returns no files.
//! Also: the corpus' `ok` scene and the shipped scenes resolve, and the editor
//! schema for scene files lists exactly the keys the parser accepts.
//!
//! The corpus names the shipped materials (`materials/`) and the documentation
//! example (`docs/example/`), so these tests run from the workspace root
//! rather than cargo's `tests/`: every file in a diagnostic, scene or
//! material, is then shown with a stable relative path.

use schema::{assert_schema_directive, enum_values, property_names, resolve, sorted};
use std::path::{Path, PathBuf};
use weft_front::scene::{self, ResolvedScene};
use weft_front::{Diagnostics, SourceDb};
use weft_tests::{copy_dir, docs, repo, schema};

/// Every corpus file and the diagnostic codes it must produce (at least
/// these; no other codes are allowed).
const EXPECTED: &[(&str, &[&str])] = &[
    ("auto_without_budget", &["missing-key"]),
    ("bad_camera", &["out-of-range"]),
    ("bad_instance_name", &["bad-name"]),
    ("bad_light", &["out-of-range"]),
    ("bad_name", &["bad-name"]),
    ("bad_sampler", &["unknown-key", "unknown-value"]),
    ("bad_scale", &["out-of-range"]),
    (
        "broken_material",
        &["default-out-of-range", "material-error"],
    ),
    ("budget_out_of_range", &["out-of-range"]),
    ("budget_without_auto", &["unknown-key"]),
    ("color_components", &["wrong-type"]),
    ("directional_lights", &["unsupported-feature"]),
    ("duplicate_instance", &["duplicate"]),
    ("dynamic_duplicate", &["duplicate"]),
    ("dynamic_unknown", &["unknown-param"]),
    ("empty_scene", &["empty-scene"]),
    ("excluded_variant", &["excluded-variant"]),
    ("excluded_variant_preset", &["excluded-variant"]),
    ("gpu_limit", &["gpu-limit"]),
    ("light_without_direction", &["missing-key"]),
    ("material_outside_root", &["material-outside-root"]),
    ("missing_mesh", &["missing-key"]),
    ("missing_root", &["missing-root"]),
    ("missing_scene_table", &["missing-key"]),
    ("missing_vertex_input", &["missing-vertex-input"]),
    ("missing_vertex_inputs", &["missing-key"]),
    ("name_mismatch", &["bad-name"]),
    ("out_of_range", &["out-of-range"]),
    ("param_wrong_type", &["wrong-type"]),
    (
        "several_errors",
        &[
            "unsupported-feature",
            "wrong-type",
            "unknown-key",
            "unknown-mesh",
            "duplicate",
            "unknown-preset",
            "unknown-value",
            "out-of-range",
            "unknown-param",
            "unknown-tier",
        ],
    ),
    (
        "several_instances",
        &[
            "duplicate",
            "unknown-value",
            "out-of-range",
            "wrong-type",
            "unknown-param",
            "unknown-keyword",
        ],
    ),
    ("shader_budget", &["shader-budget"]),
    ("static_lighting_sh_shape", &["wrong-type"]),
    ("static_lighting_unused_sh", &["unused-key"]),
    ("static_lighting_without_sh", &["missing-key"]),
    ("toml_syntax", &["toml-syntax"]),
    ("unknown_key_camera", &["unknown-key"]),
    ("unknown_key_instance", &["unknown-key"]),
    ("unknown_key_scene", &["unknown-key"]),
    ("unknown_key_top_level", &["unknown-key"]),
    ("unknown_keyword", &["unknown-keyword"]),
    ("unknown_keyword_value", &["unknown-value"]),
    ("unknown_material", &["unknown-material"]),
    ("unknown_mesh", &["unknown-mesh"]),
    ("unknown_param", &["unknown-param"]),
    ("unknown_preset", &["unknown-preset"]),
    ("unknown_texture", &["unknown-value"]),
    ("unknown_tier", &["unknown-tier"]),
    ("unknown_vertex_input", &["unknown-value"]),
    ("wrong_type", &["wrong-type"]),
];

fn corpus() -> PathBuf {
    PathBuf::from("diagnostics/scenes")
}

fn load(path: &Path) -> Result<ResolvedScene, (SourceDb, Diagnostics)> {
    let (mut db, mut diags) = (SourceDb::new(), Diagnostics::new());
    match scene::load_scene(path, &mut db, &mut diags) {
        Some(s) if diags.is_empty() => Ok(s),
        _ => Err((db, diags)),
    }
}

/// The scene built by the compiler (front end, then folding and the build's
/// own checks), as `weft build --scene` builds it: its diagnostics, or the
/// files it would write (on error there are none to write).
fn build(path: &Path) -> Result<weft_compiler::SceneOutput, (SourceDb, Diagnostics)> {
    weft_compiler::build_scene(path, &weft_compiler::SceneBuildOptions::default())
}

fn codes(diags: &Diagnostics) -> Vec<String> {
    diags.iter().filter_map(|d| d.code.clone()).collect()
}

#[test]
fn every_bad_scene_has_an_expectation() {
    let mut found: Vec<String> = std::fs::read_dir(corpus().join("bad"))
        .expect("corpus folder")
        .map(|e| e.expect("entry").path())
        .filter_map(|p| {
            let name = p.file_name()?.to_str()?.to_string();
            name.strip_suffix(".scene.toml").map(str::to_string)
        })
        .collect();
    found.sort();
    let expected: Vec<String> = EXPECTED.iter().map(|(n, _)| n.to_string()).collect();
    assert_eq!(found, expected, "bad/*.scene.toml and EXPECTED differ");
}

#[test]
fn bad_scenes_report_their_diagnostics() {
    for (name, want) in EXPECTED {
        let path = corpus().join("bad").join(format!("{name}.scene.toml"));
        let Err((db, diags)) = build(&path) else {
            panic!("{name}: built without errors");
        };
        assert!(diags.has_errors(), "{name}: no error");
        let got = codes(&diags);
        for code in *want {
            assert!(
                got.iter().any(|c| c == code),
                "{name}: no `{code}` among {got:?}"
            );
        }
        for code in &got {
            assert!(
                want.contains(&code.as_str()),
                "{name}: unexpected `{code}` among {got:?}"
            );
        }
        assert!(
            diags.iter().all(|d| !d.labels.is_empty()),
            "{name}: a diagnostic points nowhere"
        );
        let rendered = diags.render_plain(&db);
        let root = std::env::current_dir().expect("cwd");
        assert!(
            !rendered.contains(&*root.to_string_lossy()),
            "{name}: an absolute path leaks into the diagnostics:\n{rendered}"
        );
        // The materials sit outside the working directory (tests/), so their
        // paths show whole; the snapshot holds them relative to the workspace.
        let workspace = repo().canonicalize().expect("workspace root");
        let rendered = rendered.replace(&format!("{}/", workspace.display()), "");
        // Even a broken material's errors come with a note at the scene's line.
        let scene_file = format!("diagnostics/scenes/bad/{name}.scene.toml");
        assert!(
            diags
                .iter()
                .any(|d| d.labels.iter().any(|l| db.name(l.file_id) == scene_file)),
            "{name}: no diagnostic points into the scene file"
        );
        insta::assert_snapshot!(*name, rendered);
    }
}

#[test]
fn several_errors_are_reported_in_one_run() {
    for name in ["several_errors", "several_instances"] {
        let Err((_, diags)) = load(&corpus().join(format!("bad/{name}.scene.toml"))) else {
            panic!("{name} resolved");
        };
        assert!(
            diags.error_count() >= 6,
            "{name}: only {} errors",
            diags.error_count()
        );
    }
}

#[test]
fn ok_scene_resolves() {
    let s = load(&corpus().join("ok/ok.scene.toml"))
        .unwrap_or_else(|(db, diags)| panic!("ok.scene.toml failed:\n{}", diags.render_plain(&db)));
    let names: Vec<&str> = s.instances.iter().map(|i| i.name.as_str()).collect();
    assert_eq!(names, ["dress", "lining", "ball"]);
    let materials: Vec<&str> = s.materials.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(materials, ["satin", "microcylinder", "standard"]);
}

/// `scenes/*.scene.toml`, sorted.
fn shipped_scenes() -> Vec<PathBuf> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(repo().join("scenes"))
        .expect("scenes/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.to_string_lossy().ends_with(".scene.toml"))
        .collect();
    paths.sort();
    assert!(!paths.is_empty(), "no scenes/*.scene.toml");
    paths
}

/// The scenes in `scenes/` resolve without a diagnostic — but for the
/// warnings a glTF file's mapping gives (what it drops, docs/gltf.md), which
/// the showroom's file provokes on purpose.
#[test]
fn shipped_scenes_resolve() {
    for path in shipped_scenes() {
        let (mut db, mut diags) = (SourceDb::new(), Diagnostics::new());
        let resolved = scene::load_scene(&path, &mut db, &mut diags);
        let unexpected = diags.iter().any(|d| {
            d.severity != codespan_reporting::diagnostic::Severity::Warning
                || d.code.as_deref() != Some("gltf")
        });
        if resolved.is_none() || unexpected {
            panic!("{}:\n{}", path.display(), diags.render_plain(&db));
        }
    }
}

/// The example in docs/scenes.md resolves, as `scenes/showroom.scene.toml`
/// beside a copy of `materials/`, so the documentation cannot rot.
#[test]
fn documentation_example_resolves() {
    let doc = std::fs::read_to_string(repo().join("docs/scenes.md")).expect("docs/scenes.md");
    let example = docs::doc_block(&doc, "scene-example");
    let dir = tempfile::tempdir().expect("temp dir");
    copy_dir(&repo().join("materials"), &dir.path().join("materials"));
    std::fs::create_dir(dir.path().join("scenes")).expect("scenes folder");
    let path = dir.path().join("scenes/showroom.scene.toml");
    std::fs::write(&path, example).expect("write the example");
    let s = load(&path).unwrap_or_else(|(db, diags)| {
        panic!(
            "the example in docs/scenes.md:\n{}",
            diags.render_plain(&db)
        )
    });
    let tiers: Vec<bool> = s
        .instances
        .iter()
        .map(|i| matches!(i.tier, scene::model::TierChoice::Auto { .. }))
        .collect();
    assert_eq!(tiers, [false, true, false]);
}

// ------------------------------------------------------------ editor schema

/// For each table, the schema's property names are the parser's key list;
/// enumerations are the model's.
#[test]
fn schema_matches_parser_keys() {
    let s = schema::load(repo().join("schemas/scene.schema.json"));
    let prop = |parent: &serde_json::Value, key: &str| -> serde_json::Value {
        resolve(&s, parent)
            .get("properties")
            .and_then(|p| p.get(key))
            .unwrap_or_else(|| panic!("no property {key}"))
            .clone()
    };
    let instance = resolve(&s, &prop(&s, "instances"))
        .get("items")
        .cloned()
        .expect("array of tables");

    assert_eq!(property_names(&s, &s, "top level"), sorted(scene::TOP_KEYS));
    assert_eq!(
        property_names(&s, &prop(&s, "scene"), "[scene]"),
        sorted(scene::SCENE_KEYS)
    );
    assert_eq!(
        property_names(&s, &prop(&s, "camera"), "[camera]"),
        sorted(scene::CAMERA_KEYS)
    );
    assert_eq!(
        property_names(&s, &prop(&s, "light"), "[light]"),
        sorted(scene::LIGHT_KEYS)
    );
    assert_eq!(
        property_names(&s, &instance, "[[instances]]"),
        sorted(scene::INSTANCE_KEYS)
    );
    assert_eq!(
        property_names(&s, &prop(&s, "gltf"), "[gltf]"),
        sorted(scene::gltf_layer::GLTF_KEYS)
    );
    let gltf = prop(&s, "gltf");
    let gltf_material = &resolve(&s, &gltf)["properties"]["materials"]["additionalProperties"];
    assert_eq!(
        property_names(&s, gltf_material, "[gltf.materials.<name>]"),
        sorted(scene::gltf_layer::GLTF_MATERIAL_KEYS)
    );
    assert_eq!(
        property_names(
            &s,
            &resolve(&s, &prop(&instance, "mesh"))["anyOf"][1],
            "mesh = { … }"
        ),
        sorted(scene::parse::GLTF_MESH_KEYS)
    );
    assert_eq!(
        property_names(
            &s,
            &resolve(&s, &prop(&instance, "params"))["additionalProperties"]["anyOf"][1],
            "params.<texture> = { … }"
        ),
        sorted(scene::images::IMAGE_KEYS)
    );

    let meshes: Vec<String> = scene::model::BuiltinMesh::ALL
        .iter()
        .map(|m| m.name().to_string())
        .collect();
    assert_eq!(
        enum_values(resolve(&s, &prop(&instance, "mesh")["anyOf"][0]), "mesh"),
        meshes
    );
    let attrs: Vec<String> = weft_front::model::VertexAttribute::ALL
        .iter()
        .map(|a| a.name().to_string())
        .collect();
    for (parent, what) in [(prop(&s, "scene"), "[scene]"), (instance, "[[instances]]")] {
        assert_eq!(
            enum_values(
                &resolve(&s, &prop(&parent, "vertex_inputs"))["items"],
                "vertex_inputs"
            ),
            attrs,
            "{what}"
        );
    }
}

/// The built-in meshes and the `auto` tier: the front end's parser, the
/// renderer, the metadata (`weft_meta`, whose lists the scene metadata
/// schema's descriptions are generated from), the editor schema and
/// docs/scenes.md name the same ones, in the same order.
#[test]
fn meshes_and_auto_tier_are_one_list() {
    use docs::{backticked, row};
    let meta: Vec<String> = weft_meta::BUILTIN_MESHES
        .iter()
        .map(|m| m.to_string())
        .collect();
    let parser: Vec<String> = scene::model::BuiltinMesh::ALL
        .iter()
        .map(|m| m.name().to_string())
        .collect();
    let renderer: Vec<String> = weft_render::SceneKind::ALL
        .iter()
        .map(|k| k.name().to_string())
        .collect();
    assert_eq!(
        parser, meta,
        "weft_front's BuiltinMesh against weft_meta::BUILTIN_MESHES"
    );
    assert_eq!(
        renderer, meta,
        "weft_render's SceneKind against weft_meta::BUILTIN_MESHES"
    );

    let s = schema::load(repo().join("schemas/scene.schema.json"));
    let instance = &s["definitions"]["instance"];
    assert_eq!(
        enum_values(
            resolve(&s, &instance["properties"]["mesh"]["anyOf"][0]),
            "mesh"
        ),
        meta,
        "schemas/scene.schema.json: mesh"
    );
    assert_eq!(
        instance["allOf"][0]["if"]["properties"]["tier"]["const"],
        scene::parse::AUTO_TIER,
        "schemas/scene.schema.json: the `auto` tier"
    );

    let doc = docs::load(repo().join("docs/scenes.md"));
    let mesh = row(&doc, "### `[[instances]]`", "mesh");
    assert_eq!(backticked(&mesh[3]), meta, "docs/scenes.md: the `mesh` row");
    for key in ["tier", "error_budget", "screen_size"] {
        let r = row(&doc, "### `[[instances]]`", key).join(" | ");
        assert!(
            backticked(&r).iter().any(|t| t == scene::parse::AUTO_TIER),
            "docs/scenes.md: the `{key}` row does not name `\"{}\"`",
            scene::parse::AUTO_TIER
        );
    }
    let inputs: Vec<String> = weft_meta::VERTEX_INPUTS
        .iter()
        .map(|(n, _)| n.to_string())
        .collect();
    assert_eq!(
        backticked(&row(&doc, "### `[scene]`", "vertex_inputs")[3]),
        inputs,
        "docs/scenes.md: `[scene]` vertex_inputs"
    );
}

/// Every scene file in the repository names the schema on its first line.
#[test]
fn schema_directive_is_accepted() {
    let mut paths = shipped_scenes();
    paths.push(corpus().join("ok/ok.scene.toml"));
    for path in paths {
        assert_schema_directive(&path);
    }
}

/// `[scene] gpu_family`: the editor schema offers exactly the families the
/// parser accepts (the GPU model's), with the same default.
#[test]
fn gpu_family_schema_is_the_modelled_families() {
    let s = schema::load(repo().join("schemas/scene.schema.json"));
    let family = &s["definitions"]["scene"]["properties"]["gpu_family"];
    let listed: Vec<&str> = family["enum"]
        .as_array()
        .expect("gpu_family has an enum")
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert_eq!(listed, weft_meta::scene::GPU_COST_FAMILIES);
    assert_eq!(
        family["default"].as_str(),
        Some(weft_meta::scene::DEFAULT_GPU_COST_FAMILY)
    );
    let docs = std::fs::read_to_string(repo().join("docs/scenes.md")).unwrap();
    let row = docs
        .lines()
        .find(|l| l.starts_with("| `gpu_family` |"))
        .expect("docs/scenes.md documents gpu_family");
    for f in weft_meta::scene::GPU_COST_FAMILIES {
        assert!(row.contains(&format!("`{f}`")), "{row}");
    }
}
