//! "Nothing to guess" as a tested property of the metadata contract: every
//! property of the published JSON Schemas (`generated/metadata.schema.json`,
//! `generated/scene-metadata.schema.json`) says what it means, every type
//! says what it is, and every enum value is documented.
//!
//! The descriptions are the `///` doc comments of `weft_meta`'s types, which
//! schemars copies into the schema. A failure lists every gap; fix it with a
//! doc comment on the field or variant and `cargo xtask regenerate`.

use serde_json::{Map, Value};
use weft_tests::{docs, repo};

/// A committed schema file, checked to be what `weft_meta` generates now.
fn load(name: &str, current: &str) -> Value {
    let path = repo().join("generated").join(name);
    let text = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| panic!("{}: {e} (run `cargo xtask regenerate`)", path.display()));
    assert!(
        text == current,
        "generated/{name} is stale: run `cargo xtask regenerate`"
    );
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("generated/{name}: {e}"))
}

fn has_description(schema: &Value) -> bool {
    schema
        .get("description")
        .and_then(Value::as_str)
        .is_some_and(|d| !d.trim().is_empty())
}

/// What one schema leaves to guess.
struct Report {
    /// `Type.property` (or `Type[variant].property`) and what is missing.
    gaps: Vec<String>,
    /// Properties and enum values looked at (so an empty walk cannot pass).
    checked: usize,
}

struct Checker<'a> {
    defs: &'a Map<String, Value>,
    report: Report,
}

impl Checker<'_> {
    /// The definition a `$ref` names (`#/$defs/X` or `#/definitions/X`).
    fn target(&self, schema: &Value) -> Option<&Value> {
        let r = schema.get("$ref")?.as_str()?;
        let name = r
            .strip_prefix("#/$defs/")
            .or_else(|| r.strip_prefix("#/definitions/"))?;
        self.defs.get(name)
    }

    /// A property is described by its own description, or, when it is a
    /// plain `$ref`, by the description of the definition it names.
    fn described(&self, property: &Value) -> bool {
        has_description(property) || self.target(property).is_some_and(has_description)
    }

    fn gap(&mut self, what: String) {
        self.report.gaps.push(what);
    }

    /// Checks the properties and enum alternatives of `schema` and of every
    /// schema nested in it. `tagged` is set inside a documented alternative of
    /// an externally tagged enum, whose single property (the variant's name)
    /// the alternative's description covers.
    fn walk(&mut self, path: &str, schema: &Value, tagged: bool) {
        if let Some(properties) = schema.get("properties").and_then(Value::as_object) {
            let single = properties.len() == 1;
            for (name, property) in properties {
                self.report.checked += 1;
                if !(self.described(property) || (tagged && single)) {
                    self.gap(format!("{path}.{name}: no description"));
                }
                self.walk(&format!("{path}.{name}"), property, false);
            }
        }
        // Enums: schemars writes a documented unit or tagged variant as one
        // `oneOf` alternative carrying the variant's doc comment; an
        // undocumented one has none (or, if no variant of the enum is
        // documented, the enum becomes a bare `enum` array, see `check`).
        if let Some(alternatives) = schema.get("oneOf").and_then(Value::as_array) {
            for alternative in alternatives {
                let variant = variant_name(alternative);
                self.report.checked += 1;
                let documented = has_description(alternative);
                if !documented {
                    self.gap(format!("{path}: variant `{variant}` has no description"));
                }
                self.walk(&format!("{path}[{variant}]"), alternative, documented);
            }
        }
        for key in ["anyOf", "allOf"] {
            for alternative in schema
                .get(key)
                .and_then(Value::as_array)
                .into_iter()
                .flatten()
            {
                self.walk(path, alternative, false);
            }
        }
        for key in ["items", "additionalProperties"] {
            if let Some(inner) = schema.get(key).filter(|v| v.is_object()) {
                self.walk(&format!("{path}[]"), inner, false);
            }
        }
        if let Some(items) = schema.get("prefixItems").and_then(Value::as_array) {
            for inner in items {
                self.walk(&format!("{path}[]"), inner, false);
            }
        }
    }
}

fn variant_name(alternative: &Value) -> String {
    if let Some(c) = alternative.get("const") {
        return c.as_str().map_or_else(|| c.to_string(), str::to_string);
    }
    if let Some(values) = alternative.get("enum").and_then(Value::as_array) {
        return values
            .iter()
            .map(|v| v.as_str().map_or_else(|| v.to_string(), str::to_string))
            .collect::<Vec<_>>()
            .join("|");
    }
    alternative
        .get("properties")
        .and_then(Value::as_object)
        .and_then(|p| p.keys().next().cloned())
        .unwrap_or_else(|| "?".into())
}

/// Every gap in one schema: the root and every definition must describe
/// themselves, their properties and their enum values.
fn check(schema: &Value) -> Report {
    let empty = Map::new();
    let defs = schema
        .get("$defs")
        .or_else(|| schema.get("definitions"))
        .and_then(Value::as_object)
        .unwrap_or(&empty);
    let mut c = Checker {
        defs,
        report: Report {
            gaps: Vec::new(),
            checked: 0,
        },
    };
    let root = schema
        .get("title")
        .and_then(Value::as_str)
        .unwrap_or("root")
        .to_string();
    if !has_description(schema) {
        c.gap(format!("{root}: the type has no description"));
    }
    c.walk(&root, schema, false);
    for (name, def) in defs {
        if !has_description(def) {
            c.gap(format!("{name}: the type has no description"));
        }
        if let Some(values) = def.get("enum").and_then(Value::as_array) {
            // No variant has a doc comment: schemars emits the bare values.
            c.report.checked += values.len();
            c.gap(format!(
                "{name}: values {} have no descriptions (document every variant)",
                Value::Array(values.clone())
            ));
        }
        c.walk(name, def, false);
    }
    c.report
}

#[test]
fn every_schema_property_and_enum_value_is_described() {
    let schemas = [
        ("metadata.schema.json", weft_meta::metadata_json_schema()),
        (
            "scene-metadata.schema.json",
            weft_meta::scene::scene_metadata_json_schema(),
        ),
    ];
    let mut failures = Vec::new();
    for (name, current) in &schemas {
        let report = check(&load(name, current));
        assert!(
            report.checked > 100,
            "generated/{name}: only {} properties and values found: has the schema layout changed?",
            report.checked
        );
        failures.extend(report.gaps.iter().map(|g| format!("generated/{name}: {g}")));
    }
    assert!(
        failures.is_empty(),
        "{} gaps in the metadata contract; add a `///` doc comment to each field, variant or \
         type in crates/weft-meta/src/ and run `cargo xtask regenerate`:\n  {}",
        failures.len(),
        failures.join("\n  ")
    );
}

/// The checker itself finds each kind of gap (so the test above cannot pass
/// by looking at nothing).
#[test]
fn undescribed_properties_and_values_are_reported() {
    let schema: Value = serde_json::from_str(
        r##"{
            "title": "Root",
            "description": "root",
            "properties": {
                "plain": { "type": "integer" },
                "described": { "type": "integer", "description": "ok" },
                "via_ref": { "$ref": "#/$defs/Described" },
                "via_bare_ref": { "$ref": "#/$defs/Bare" },
                "optional_ref": { "anyOf": [{ "$ref": "#/$defs/Described" }, { "type": "null" }] }
            },
            "$defs": {
                "Described": { "description": "a type", "type": "object", "properties": {} },
                "Bare": { "type": "object", "properties": { "inner": { "type": "string" } } },
                "Plain": { "description": "an enum", "type": "string", "enum": ["a", "b"] },
                "Mixed": {
                    "description": "an enum",
                    "oneOf": [
                        { "type": "string", "enum": ["x"] },
                        { "type": "string", "const": "y", "description": "y" },
                        { "description": "tagged", "type": "object",
                          "properties": { "z": { "type": "integer" } } },
                        { "type": "object", "properties": { "w": { "type": "integer" } } }
                    ]
                }
            }
        }"##,
    )
    .unwrap();
    let mut gaps = check(&schema).gaps;
    gaps.sort();
    assert_eq!(
        gaps,
        [
            "Bare.inner: no description",
            "Bare: the type has no description",
            "Mixed: variant `w` has no description",
            "Mixed: variant `x` has no description",
            "Mixed[w].w: no description",
            "Plain: values [\"a\",\"b\"] have no descriptions (document every variant)",
            "Root.optional_ref: no description",
            "Root.plain: no description",
            "Root.via_bare_ref: no description",
        ]
    );
}

// ------------------------------------------------- names the code owns

use docs::backticked;
use std::collections::{BTreeMap, BTreeSet};
use weft_meta::MaterialMetadata;

fn generated_materials() -> Vec<MaterialMetadata> {
    let metas = weft_golden::materials(&repo().join("generated")).expect("generated/");
    assert!(
        metas.len() > 10,
        "only {} materials in generated/",
        metas.len()
    );
    metas.into_iter().map(|(_, m)| m).collect()
}

/// The description of `property` of the definition `def` (None: the root).
fn description<'a>(schema: &'a Value, def: Option<&str>, property: &str) -> &'a str {
    let owner = match def {
        Some(d) => &schema["$defs"][d],
        None => schema,
    };
    owner["properties"][property]["description"]
        .as_str()
        .unwrap_or_else(|| panic!("{def:?}.{property}: no description"))
}

/// Every closed list of names a metadata field holds is described, in both
/// published schemas, with exactly the names the code accepts (the scene
/// parser, the renderer) or writes (the compiler, as `generated/` shows):
/// meshes, the `auto` tier, vertex inputs, engine resource ids, languages,
/// toggle values.
#[test]
fn listed_names_are_what_the_code_accepts_and_writes() {
    let material = load("metadata.schema.json", &weft_meta::metadata_json_schema());
    let scene = load(
        "scene-metadata.schema.json",
        &weft_meta::scene::scene_metadata_json_schema(),
    );
    let metas = generated_materials();

    // Meshes: what a scene's `mesh` accepts and what the renderer draws
    // (and the shading benchmark measures on).
    let parser: Vec<String> = weft_front::scene::model::BuiltinMesh::ALL
        .iter()
        .map(|m| m.name().to_string())
        .collect();
    let renderer: Vec<String> = weft_render::SceneKind::ALL
        .iter()
        .map(|k| k.name().to_string())
        .collect();
    assert_eq!(
        parser, renderer,
        "the scene parser's meshes against the renderer's"
    );
    assert_eq!(
        backticked(description(&scene, Some("SceneInstance"), "mesh")),
        parser,
        "scene-metadata.schema.json: SceneInstance.mesh"
    );
    assert_eq!(
        backticked(description(&material, Some("Measurements"), "scene")),
        renderer,
        "metadata.schema.json: Measurements.scene"
    );

    // The tier that lets a scene build choose.
    let auto = weft_front::scene::parse::AUTO_TIER;
    for property in ["tier", "tier_choice"] {
        let d = description(&scene, Some("SceneInstance"), property);
        assert!(
            d.contains(&format!("`{auto}`")) || d.contains(&format!("= \"{auto}\"`")),
            "SceneInstance.{property} does not name `{auto}`: {d}"
        );
    }

    // Vertex inputs: the front end's names and locations.
    let attrs = weft_front::model::VertexAttribute::ALL;
    let names: Vec<String> = attrs.iter().map(|a| a.name().to_string()).collect();
    for (file, schema) in [("metadata", &material), ("scene-metadata", &scene)] {
        assert_eq!(
            backticked(description(schema, Some("VertexInput"), "name")),
            names,
            "{file}.schema.json: VertexInput.name"
        );
        let d = description(schema, Some("VertexInput"), "location");
        for a in attrs {
            assert!(
                d.contains(&format!("{} {},", a.name(), a.location()))
                    || d.ends_with(&format!("{} {}.", a.name(), a.location())),
                "{file}.schema.json: VertexInput.location does not say {} {}: {d}",
                a.name(),
                a.location()
            );
        }
    }

    // Engine resource ids: every one the compiler writes, by (group, binding);
    // baked tables are `<material>.<table>`.
    let mut engine: BTreeMap<(u32, u32), String> = BTreeMap::new();
    for meta in &metas {
        for v in &meta.variants {
            for b in v.shader.iter().flat_map(|s| &s.bindings) {
                let Some(r) = &b.resource else { continue };
                if b.group == 1 {
                    assert_eq!(r.id, format!("{}.{}", meta.name, b.name), "{}", v.id);
                } else if let Some(other) = engine.insert((b.group, b.binding), r.id.clone()) {
                    assert_eq!(other, r.id, "{} {}/{}", meta.name, b.group, b.binding);
                }
            }
        }
    }
    let written: Vec<String> = engine.into_values().collect();
    assert_eq!(
        written,
        weft_meta::ENGINE_RESOURCE_IDS,
        "the resource ids generated/ holds against weft_meta::ENGINE_RESOURCE_IDS"
    );
    for (file, schema) in [("metadata", &material), ("scene-metadata", &scene)] {
        let listed: Vec<String> = backticked(description(schema, Some("EngineResource"), "id"))
            .into_iter()
            .filter(|t| t != "<material>.<table>" && t != "[tables]")
            .collect();
        assert_eq!(listed, written, "{file}.schema.json: EngineResource.id");
    }

    // Languages: what the compiler emits.
    let emitted: BTreeSet<String> = weft_compiler::engine_binding::languages()
        .into_keys()
        .collect();
    for meta in &metas {
        let keys: BTreeSet<String> = meta.languages.keys().cloned().collect();
        assert_eq!(keys, emitted, "{}: languages", meta.name);
    }
    let listed: BTreeSet<String> = backticked(description(&material, None, "languages"))
        .into_iter()
        .collect();
    assert_eq!(listed, emitted, "metadata.schema.json: languages");

    // Toggle values: what every toggle keyword has.
    let toggle: Vec<String> = backticked(description(&material, Some("Keyword"), "kind"));
    let mut toggles = 0;
    for meta in &metas {
        for k in &meta.keywords {
            if k.kind == weft_meta::KeywordKind::Toggle {
                assert_eq!(k.values, toggle, "{}: keyword {}", meta.name, k.name);
                toggles += 1;
            }
        }
    }
    assert!(toggles > 5, "only {toggles} toggle keywords");
}

/// docs/engine-interface.md's tables of the engine interface are what the
/// metadata says: group 0 (binding, name, `resource.id`), group 2, the
/// vertex input locations and the blend modes.
#[test]
fn engine_interface_doc_is_the_metadata() {
    use docs::{cells, section};
    let doc = docs::load(repo().join("docs/engine-interface.md"));
    let metas = generated_materials();
    let mut bound: BTreeSet<(u32, u32, String, String)> = BTreeSet::new();
    for meta in &metas {
        for v in &meta.variants {
            for b in v.shader.iter().flat_map(|s| &s.bindings) {
                if let (Some(r), 0 | 2) = (&b.resource, b.group) {
                    bound.insert((b.group, b.binding, b.name.clone(), r.id.clone()));
                }
            }
        }
    }
    let group0: Vec<(u32, u32, String, String)> = section(&doc, "## Group 0")
        .into_iter()
        .filter(|l| l.starts_with("| ") && l[2..].starts_with(|c: char| c.is_ascii_digit()))
        .map(|l| {
            let c = cells(l);
            let code = |i: usize| backticked(&c[i]).first().cloned().unwrap_or_default();
            (0, c[0].parse().expect("binding number"), code(1), code(2))
        })
        .collect();
    let expected: Vec<_> = bound.iter().filter(|b| b.0 == 0).cloned().collect();
    assert_eq!(
        group0, expected,
        "docs/engine-interface.md: the group 0 table"
    );
    let group2 = backticked(&section(&doc, "## Group 2").join("\n"));
    for (_, _, name, id) in bound.iter().filter(|b| b.0 == 2) {
        assert!(
            group2.contains(name) && group2.contains(id),
            "docs/engine-interface.md, group 2: `{name}` (`{id}`) is missing"
        );
    }
    let inputs = section(&doc, "## Vertex inputs").join(" ");
    let inputs = inputs.split_whitespace().collect::<Vec<_>>().join(" ");
    for (i, (name, _)) in weft_meta::VERTEX_INPUTS.iter().enumerate() {
        assert!(
            inputs.contains(&format!("{name} {i} ")) || inputs.contains(&format!("{name} {i},")),
            "docs/engine-interface.md, vertex inputs: no `{name} {i}`"
        );
    }
    let blends: Vec<String> = section(&doc, "## Passes: what the output means")
        .into_iter()
        .skip_while(|l| !l.starts_with("| `render_state.blend`"))
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| backticked(l)[0].clone())
        .collect();
    let modes: Vec<String> = weft_meta::BlendMode::ALL
        .iter()
        .map(|b| b.name().to_string())
        .collect();
    assert_eq!(blends, modes, "docs/engine-interface.md: the blend table");
}

/// Every material's README has a bindings table (`<!-- weft:bindings:… -->`,
/// written by `cargo xtask regenerate` from the metadata) and it is the one
/// its committed metadata gives: what a README says each tier binds is
/// what `generated/<m>/<m>.meta.json` binds.
#[test]
fn readme_bindings_tables_are_the_metadatas() {
    use weft_golden::{bindings, shading::replace_marked};
    let mut stale = Vec::new();
    for meta in generated_materials() {
        let readme = repo().join("materials").join(&meta.name).join("README.md");
        let text = std::fs::read_to_string(&readme)
            .unwrap_or_else(|e| panic!("{}: {e}", readme.display()));
        let table = bindings::readme_table(&meta);
        let expected = replace_marked(&text, bindings::MARKER, &table).unwrap_or_else(|| {
            panic!(
                "{}: no <!-- weft:bindings:begin --> … <!-- weft:bindings:end --> markers",
                readme.display()
            )
        });
        if expected != text {
            stale.push(format!(
                "materials/{}/README.md; the metadata's table is:\n{table}",
                meta.name
            ));
        }
    }
    assert!(
        stale.is_empty(),
        "bindings tables that are not the metadata's (run `cargo xtask regenerate`):\n{}",
        stale.join("\n")
    );
}
