//! The bad-material corpus (`tests/diagnostics/materials/bad/`): every file
//! fails with the diagnostic its name says, rendered exactly as the CLI shows
//! it (snapshots in `tests/snapshots/`). Also: the corpus' `ok` material and
//! the documentation example build, and the editor schema for material files
//! lists exactly the keys the parser accepts.
//!
//! Cargo runs integration tests with the package folder (`tests/`) as the
//! working directory, so file names in diagnostics are relative and stable.

use docs::doc_block;
use schema::{assert_schema_directive, enum_values, property_names, resolve, sorted};
use std::path::{Path, PathBuf};
use weft_compiler::{BuildOptions, build_materials};
use weft_front::{Diagnostics, SourceDb};
use weft_tests::{docs, schema};

/// Every corpus file and the error codes it must produce (at least these;
/// no other codes are allowed).
const EXPECTED: &[(&str, &[&str])] = &[
    ("bad_condition", &["bad-condition"]),
    ("bad_name", &["bad-name"]),
    (
        "bad_preset",
        &["unknown-key", "out-of-range", "unknown-value", "wrong-type"],
    ),
    ("constant_combinations", &["variant-space"]),
    ("default_out_of_range", &["default-out-of-range"]),
    ("default_when_bad_texture", &["unknown-value"]),
    ("default_when_bool_param", &["bad-condition"]),
    ("default_when_constant_keyword", &["bad-condition"]),
    ("default_when_on_float", &["unknown-key"]),
    ("default_when_unknown_key", &["unknown-key"]),
    ("default_when_unknown_value", &["unknown-value"]),
    ("duplicate_names", &["duplicate"]),
    ("exclude_constant_keyword", &["bad-condition"]),
    ("exclude_removes_all", &["no-variants"]),
    ("float_beyond_f32_range", &["type-range"]),
    ("half_spelled_directly", &["wgsl-parse"]),
    ("include_cycle", &["include-cycle"]),
    ("include_outside_root", &["include-outside-root"]),
    ("instances_not_int", &["unknown-param"]),
    ("int_beyond_i32_range", &["type-range"]),
    ("limits_below_default", &["unknown-key", "out-of-range"]),
    ("min_above_max", &["min-above-max"]),
    ("missing_entry_point", &["missing-entry-point"]),
    ("missing_include", &["missing-include"]),
    ("missing_require", &["missing-require"]),
    ("missing_source", &["missing-source"]),
    ("missing_tier", &["missing-tier"]),
    ("pass_all_conditional", &["pass-condition"]),
    ("pass_file_errors", &["unknown-key", "default-out-of-range"]),
    ("pass_include_extra_key", &["pass-include"]),
    ("pass_include_missing", &["missing-include"]),
    ("pass_when_bool_param", &["bad-condition"]),
    ("pass_when_unknown_keyword", &["unknown-keyword"]),
    (
        "several_errors",
        &[
            "unknown-key",
            "wrong-type",
            "default-out-of-range",
            "unknown-keyword",
            "unknown-value",
        ],
    ),
    ("source_outside_root", &["source-outside-root"]),
    ("stage_mismatch", &["stage-mismatch"]),
    ("stage_mismatch_args", &["stage-mismatch", "stage-mismatch"]),
    ("stencil_bad_op", &["unknown-value"]),
    ("stencil_out_of_range", &["out-of-range", "unknown-key"]),
    ("table_budget", &["too-large"]),
    (
        "table_errors",
        &[
            "unknown-value",
            "out-of-range",
            "missing-key",
            "unknown-key",
            "duplicate",
        ],
    ),
    (
        "texture_file_misplaced",
        &["unknown-key", "conflicting-keys", "wrong-type"],
    ),
    ("texture_file_missing", &["missing-texture-file"]),
    ("texture_file_outside_root", &["texture-file-outside-root"]),
    ("texture_file_undecodable", &["bad-texture-file"]),
    ("tier_relations", &["tier-relation"]),
    ("toml_syntax", &["toml-syntax"]),
    ("too_many_textures", &["gpu-limit"]),
    ("too_many_varyings", &["gpu-limit"]),
    ("trailing_digit_name", &["bad-name"]),
    ("uniform_too_large", &["gpu-limit"]),
    ("unknown_enum_value", &["unknown-value"]),
    ("unknown_group", &["unknown-group"]),
    ("unknown_key", &["unknown-key"]),
    ("unknown_key_top_level", &["unknown-key"]),
    ("unknown_keyword_filter", &["unknown-keyword"]),
    ("unknown_keyword_show_if", &["unknown-keyword"]),
    ("unknown_param_type", &["unknown-value"]),
    ("unknown_show_if_value", &["unknown-value"]),
    ("unknown_texture_default", &["unknown-value"]),
    ("unordered_keyframes", &["unordered-keys"]),
    ("variant_budget", &["variant-budget"]),
    ("variant_space_too_large", &["variant-space"]),
    ("wgsl_error_in_include", &["wgsl-parse"]),
    ("wgsl_expression_too_deep", &["wgsl-nesting"]),
    ("wgsl_nested_too_deep", &["wgsl-parse"]),
    ("wgsl_parse_error", &["wgsl-parse"]),
    ("wgsl_reserved_name", &["wgsl-parse"]),
    ("wgsl_validation_error", &["wgsl-validation"]),
    ("wrong_type", &["wrong-type"]),
];

fn corpus() -> PathBuf {
    Path::new("diagnostics/materials").to_path_buf()
}

fn build(path: &Path) -> Result<weft_compiler::BuildOutput, (SourceDb, Diagnostics)> {
    let root = weft_front::find_root(path);
    assert!(
        root.ends_with("diagnostics/materials") || root.ends_with("example"),
        "root {}",
        root.display()
    );
    build_materials(
        &[path.to_path_buf()],
        None,
        &BuildOptions::default(),
        &|_, _, _| {},
    )
}

fn codes(diags: &Diagnostics) -> Vec<String> {
    diags.iter().filter_map(|d| d.code.clone()).collect()
}

#[test]
fn every_bad_material_has_an_expectation() {
    let mut found: Vec<String> = std::fs::read_dir(corpus().join("bad"))
        .expect("corpus folder")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| p.file_stem().expect("stem").to_string_lossy().into_owned())
        .collect();
    found.sort();
    let expected: Vec<String> = EXPECTED.iter().map(|(n, _)| n.to_string()).collect();
    assert_eq!(found, expected, "bad/*.toml and EXPECTED differ");
}

#[test]
fn bad_materials_report_their_diagnostic() {
    for (name, want) in EXPECTED {
        let path = corpus().join("bad").join(format!("{name}.toml"));
        let Err((db, diags)) = build(&path) else {
            panic!("{name}: built without errors");
        };
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
        let cwd = std::env::current_dir().expect("cwd");
        let workspace = cwd.parent().expect("workspace");
        assert!(
            !rendered.contains(&*workspace.to_string_lossy()),
            "{name}: an absolute path leaks into the diagnostics:\n{rendered}"
        );
        insta::assert_snapshot!(*name, rendered);
    }
}

#[test]
fn several_errors_are_reported_in_one_run() {
    let Err((_, diags)) = build(&corpus().join("bad/several_errors.toml")) else {
        panic!("several_errors built");
    };
    assert!(
        diags.error_count() >= 3,
        "only {} errors",
        diags.error_count()
    );
}

#[test]
fn wgsl_errors_point_into_the_users_files() {
    for (name, file) in [
        ("wgsl_parse_error", "bad/wgsl_parse_error.wgsl"),
        ("wgsl_validation_error", "bad/wgsl_validation_error.wgsl"),
        ("wgsl_error_in_include", "lib/broken.wgsl"),
        ("wgsl_reserved_name", "bad/wgsl_reserved_name.toml"),
        ("wgsl_nested_too_deep", "bad/wgsl_nested_too_deep.wgsl"),
        (
            "wgsl_expression_too_deep",
            "bad/wgsl_expression_too_deep.wgsl",
        ),
        ("stage_mismatch", "bad/stage_mismatch.toml"),
    ] {
        let Err((db, diags)) = build(&corpus().join(format!("bad/{name}.toml"))) else {
            panic!("{name} built");
        };
        let d = diags.iter().next().expect("a diagnostic");
        let primary = d.labels.first().expect("a label");
        let shown = db.name(primary.file_id);
        assert!(
            shown.ends_with(file),
            "{name}: primary label in `{shown}`, expected `{file}`"
        );
    }
}

/// Every stage mismatch labels the fragment input's own declaration in the
/// user's WGSL (a struct, or a bare argument, at its line), not only the TOML.
#[test]
fn stage_mismatches_point_at_the_wgsl_declarations() {
    for (name, wgsl, lines) in [
        ("stage_mismatch", "bad/stage_mismatch.wgsl", &[3, 3, 3][..]),
        (
            "stage_mismatch_args",
            "bad/stage_mismatch_args.wgsl",
            &[5, 6],
        ),
    ] {
        let Err((db, diags)) = build(&corpus().join(format!("bad/{name}.toml"))) else {
            panic!("{name} built");
        };
        let found: Vec<usize> = diags
            .iter()
            .filter_map(|d| {
                let l = d
                    .labels
                    .iter()
                    .find(|l| db.name(l.file_id).ends_with(wgsl))?;
                Some(db.text(l.file_id)[..l.range.start].matches('\n').count() + 1)
            })
            .collect();
        assert_eq!(found, lines, "{name}: lines of the labels in `{wgsl}`");
    }
}

#[test]
fn ok_material_builds() {
    match build(&corpus().join("ok/ok.toml")) {
        Ok(out) => assert_eq!(out.variant_count, 2),
        Err((db, diags)) => panic!("ok.toml failed:\n{}", diags.render_plain(&db)),
    }
}

// ------------------------------------------------------------ documentation

const EXAMPLE: &str = "../docs/example/velvet_swatch/velvet_swatch.toml";
const SMALL_EXAMPLE: &str = "../docs/example/tinted/tinted.toml";

/// The complete example in docs/ builds, so the documentation cannot rot.
#[test]
fn documentation_example_builds() {
    let out = weft_compiler::build_library(
        Path::new("../docs/example"),
        &BuildOptions::default(),
        &|_, _, _| {},
    )
    .unwrap_or_else(|(db, diags)| panic!("docs/example failed:\n{}", diags.render_plain(&db)));
    let names: Vec<&str> = out.materials.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(names, ["tinted", "velvet_swatch"]);
    let velvet = &out.materials[1];

    for kind in weft_meta::ParamKind::ALL {
        assert!(
            velvet.parameters.iter().any(|p| p.kind == kind),
            "the example uses no {} parameter",
            kind.name()
        );
    }
}

fn prelude_text(path: &str) -> String {
    let path = Path::new(path);
    let root = weft_front::find_root(path);
    let (mut db, mut diags) = (SourceDb::new(), Diagnostics::new());
    let m = weft_front::load_material(path, &root, &mut db, &mut diags)
        .unwrap_or_else(|| panic!("{}:\n{}", path.display(), diags.render_plain(&db)));
    let p = weft_compiler::prelude::generate(&m);
    p.lines.iter().map(|(l, _)| format!("{l}\n")).collect()
}

/// The prelude shown in docs/material-format.md is the one the toolchain generates.
#[test]
fn documented_prelude_is_current() {
    let doc =
        std::fs::read_to_string("../docs/material-format.md").expect("docs/material-format.md");
    let prelude = prelude_text(SMALL_EXAMPLE);
    assert!(
        doc_block(&doc, "tinted-prelude") == prelude,
        "docs/material-format.md shows a stale prelude for tinted.toml; the current one is:\n{prelude}"
    );
    let toml = std::fs::read_to_string(SMALL_EXAMPLE).expect("tinted.toml");
    assert!(
        doc_block(&doc, "tinted-toml") == toml,
        "docs/material-format.md shows a stale tinted.toml"
    );
    // The curve and gradient accessors shown are what velvet_swatch generates.
    let velvet = prelude_text(EXAMPLE);
    for line in doc_block(&doc, "velvet-accessors").lines() {
        assert!(
            velvet.lines().any(|l| l == line),
            "not in velvet_swatch's prelude: {line}\ncurrent prelude:\n{velvet}"
        );
    }
}

// ------------------------------------------------------------ editor schema

fn schema() -> serde_json::Value {
    schema::load("../schemas/material.schema.json")
}

fn defs_stencil(s: &serde_json::Value) -> serde_json::Value {
    s["definitions"]["stencil"].clone()
}

/// For each table, the schema's property names are the parser's key list.
#[test]
fn schema_matches_parser_keys() {
    use weft_front::parse::*;
    let s = schema();
    let top = &s;
    let prop = |parent: &serde_json::Value, key: &str| -> serde_json::Value {
        resolve(&s, parent)
            .get("properties")
            .and_then(|p| p.get(key))
            .unwrap_or_else(|| panic!("no property {key}"))
            .clone()
    };
    // Map-like tables: their values are the schema under additionalProperties / items.
    let map_values = |v: &serde_json::Value| -> serde_json::Value {
        resolve(&s, v)
            .get("additionalProperties")
            .cloned()
            .expect("map of tables")
    };
    let items = |v: &serde_json::Value| -> serde_json::Value {
        resolve(&s, v)
            .get("items")
            .cloned()
            .expect("array of tables")
    };

    assert_eq!(property_names(&s, top, "top level"), sorted(TOP_KEYS));
    assert_eq!(
        property_names(&s, &prop(top, "material"), "[material]"),
        sorted(MATERIAL_KEYS)
    );
    assert_eq!(
        property_names(&s, &map_values(&prop(top, "groups")), "[groups.*]"),
        sorted(GROUP_KEYS)
    );
    let param = map_values(&prop(top, "params"));
    assert_eq!(property_names(&s, &param, "[params.*]"), sorted(PARAM_KEYS));
    assert_eq!(
        property_names(&s, &map_values(&prop(top, "keywords")), "[keywords.*]"),
        sorted(KEYWORD_KEYS)
    );
    assert_eq!(
        property_names(&s, &items(&prop(top, "tier")), "[[tier]]"),
        sorted(TIER_KEYS)
    );
    assert_eq!(
        property_names(&s, &prop(top, "variants"), "[variants]"),
        sorted(VARIANTS_KEYS)
    );
    assert_eq!(
        property_names(&s, &map_values(&prop(top, "presets")), "[presets.*]"),
        sorted(PRESET_KEYS)
    );
    assert_eq!(
        property_names(&s, &items(&prop(top, "pass")), "[[pass]]"),
        sorted(PASS_KEYS)
    );
    assert_eq!(
        property_names(&s, &defs_stencil(&s), "[[pass]] stencil"),
        sorted(STENCIL_KEYS)
    );
    assert_eq!(
        property_names(&s, &prop(top, "limits"), "[limits]"),
        sorted(LIMITS_KEYS)
    );
    assert_eq!(
        property_names(&s, &map_values(&prop(top, "tables")), "[tables.*]"),
        sorted(TABLE_KEYS)
    );
    let defs = s.get("definitions").expect("definitions");
    assert_eq!(
        property_names(&s, &defs["keyframe"], "curve keyframe"),
        sorted(KEYFRAME_KEYS)
    );
    assert_eq!(
        property_names(&s, &defs["gradient_stop"], "gradient stop"),
        sorted(STOP_KEYS)
    );
    assert_eq!(
        property_names(&s, &defs["default_when_entry"], "default_when entry"),
        sorted(DEFAULT_WHEN_KEYS)
    );

    // Enumerated values match the model's.
    let kinds: Vec<String> = weft_meta::ParamKind::ALL
        .iter()
        .map(|k| k.name().to_string())
        .collect();
    assert_eq!(
        enum_values(resolve(&s, &prop(&param, "type")), "type"),
        kinds
    );
    let builtin: Vec<String> = weft_meta::TextureDefault::ALL
        .iter()
        .map(|d| d.name().to_string())
        .collect();
    assert_eq!(
        enum_values(&defs["texture_default"], "texture_default"),
        builtin
    );
    let attrs: Vec<String> = weft_front::model::VertexAttribute::ALL
        .iter()
        .map(|a| a.name().to_string())
        .collect();
    assert_eq!(
        enum_values(
            &resolve(&s, &prop(&prop(top, "material"), "requires"))["items"],
            "requires"
        ),
        attrs
    );
}

/// Every closed list of values a material file takes, as the parser reads it
/// (the metadata enums' `ALL`, the front end's lists), is exactly what the
/// editor schema enumerates and what docs/material-format.md lists, and the
/// metadata's vertex inputs are the front end's.
#[test]
fn schema_and_docs_list_the_parsers_values() {
    use docs::{backticked, backticked_set, row, section, set};
    use weft_meta::{
        BlendMode, CullMode, DepthTest, KeywordKind, KeywordMode, ParamKind, StencilOperation,
        TextureDefault,
    };
    let names = |v: &[&str]| -> Vec<String> { v.iter().map(|n| n.to_string()).collect() };
    let s = schema();
    let defs = &s["definitions"];
    let schema_enum = |def: &str, key: Option<&str>| -> Vec<String> {
        let v = &defs[def];
        let v = match key {
            Some(k) => resolve(&s, &v["properties"][k]),
            None => v,
        };
        enum_values(v, &format!("{def}.{}", key.unwrap_or("")))
    };
    let blend = BlendMode::ALL.map(BlendMode::name);
    let cull = CullMode::ALL.map(CullMode::name);
    let compare = DepthTest::ALL.map(DepthTest::name);
    let ops = StencilOperation::ALL.map(StencilOperation::name);
    let kinds = KeywordKind::ALL.map(KeywordKind::name);
    let modes = KeywordMode::ALL.map(KeywordMode::name);
    let recipes: Vec<&str> = weft_front::parse::RECIPES
        .iter()
        .map(|(n, _, _)| *n)
        .collect();
    let rings: Vec<&str> = weft_front::parse::RINGS.iter().map(|(n, _)| *n).collect();

    // The editor schema, in the parser's order.
    for (def, key, expected) in [
        ("pass", Some("blend"), &blend[..]),
        ("pass", Some("cull"), &cull[..]),
        ("pass", Some("depth_test"), &compare[..]),
        ("stencil", Some("compare"), &compare[..]),
        ("stencil_op", None, &ops[..]),
        ("keyword", Some("type"), &kinds[..]),
        ("keyword", Some("mode"), &modes[..]),
        ("table", Some("recipe"), &recipes[..]),
        ("table", Some("ring"), &rings[..]),
    ] {
        assert_eq!(
            schema_enum(def, key),
            names(expected),
            "schemas/material.schema.json: {def}.{}",
            key.unwrap_or("")
        );
    }
    for op in ["pass_op", "fail_op", "depth_fail_op"] {
        assert_eq!(
            defs["stencil"]["properties"][op]["$ref"], "#/definitions/stencil_op",
            "stencil.{op}"
        );
    }

    // docs/material-format.md: the tables' value columns and lists.
    let doc = docs::load("../docs/material-format.md");
    let column = |heading: &str, key: &str, col: usize| -> Vec<String> {
        backticked(&row(&doc, heading, key)[col])
    };
    let params = ParamKind::ALL.map(ParamKind::name);
    for (heading, key, col, expected) in [
        ("## `[params]`", "type", 3, &params[..]),
        ("## `[keywords]`", "type", 1, &kinds[..]),
        ("## `[keywords]`", "mode", 1, &modes[..]),
        ("## `[[pass]]`", "blend", 1, &blend[..]),
        ("## `[[pass]]`", "cull", 1, &cull[..]),
        ("## `[[pass]]`", "depth_test", 1, &compare[..]),
    ] {
        assert_eq!(
            column(heading, key, col),
            names(expected),
            "docs/material-format.md, {heading}: the `{key}` row"
        );
    }
    let textures = TextureDefault::ALL.map(TextureDefault::name);
    let first_cells: Vec<String> = section(&doc, "### Textures: ")
        .into_iter()
        .take_while(|l| !l.starts_with("A `texture2d`"))
        .filter(|l| l.starts_with("| `"))
        .map(|l| backticked(l)[0].clone())
        .collect();
    assert_eq!(first_cells, names(&textures), "the built-in texture table");
    let meaning = row(&doc, "#### `default_when`", "default")[2].clone();
    let (_, list) = meaning
        .split_once(": ")
        .expect("`default`: the list after a colon");
    assert_eq!(
        backticked_set(list),
        set(textures),
        "default_when's `default` row"
    );
    let stencil = section(&doc, "### Stencil").join(
        "
",
    );
    let listed = backticked_set(&stencil);
    for name in ops {
        assert!(
            listed.contains(name),
            "docs/material-format.md, ### Stencil: `{name}` is not mentioned"
        );
    }
    // Each recipe has its row (`row` panics naming a missing one); the
    // skin row lists its rings.
    for name in &recipes {
        row(&doc, "## `[tables]`", name);
    }
    let skin = row(&doc, "## `[tables]`", "preintegrated_skin").join(" | ");
    for name in &rings {
        assert!(
            backticked_set(&skin).contains(*name),
            "docs/material-format.md, `[tables]`: `{name}` is not listed"
        );
    }

    // The vertex inputs a material `requires` are the metadata's, by location.
    let attrs: Vec<(&str, u32, &str)> = weft_front::model::VertexAttribute::ALL
        .iter()
        .map(|a| (a.name(), a.location(), a.format()))
        .collect();
    let meta: Vec<(&str, u32, &str)> = weft_meta::VERTEX_INPUTS
        .iter()
        .enumerate()
        .map(|(i, (n, f))| (*n, i as u32, *f))
        .collect();
    assert_eq!(
        attrs, meta,
        "weft_front's vertex attributes against weft_meta::VERTEX_INPUTS"
    );
}

/// Every material file in the repository parses with the schema directive on its first line.
#[test]
fn schema_directive_is_accepted() {
    for path in [
        "../materials/standard/standard.toml",
        EXAMPLE,
        "diagnostics/materials/ok/ok.toml",
    ] {
        assert_schema_directive(path);
    }
}
