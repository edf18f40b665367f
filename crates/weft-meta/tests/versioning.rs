//! The metadata versioning rule (crates/weft-meta/src/version.rs,
//! docs/engine-interface.md), tested on real files of `generated/`:
//!
//! - a later minor adds fields and objects anywhere: today's reader must read
//!   a file with an unknown field added to *every* object, and get the same
//!   value;
//! - a file written before the minor existed (no `schema_minor`) reads as `.0`;
//! - another major is rejected before anything else is read, with an error
//!   naming both versions.

use serde_json::{Map, Value, json};
use std::path::{Path, PathBuf};
use weft_meta::scene::{SCENE_SCHEMA_MINOR, SCENE_SCHEMA_VERSION, SceneMetadata};
use weft_meta::{MaterialMetadata, MetaError, SCHEMA_MINOR, SCHEMA_VERSION};

fn generated(rel: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../generated")
        .join(rel);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn first_scene() -> (PathBuf, String) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../generated/scenes");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let name = names.first().expect("a scene in generated/scenes").clone();
    let rel = format!("scenes/{name}/{name}.scene.json");
    (dir.join(&name), generated(&rel))
}

/// What a later minor might add: an object holding objects and arrays.
fn future() -> Value {
    json!({
        "note": "added by a later minor version",
        "nested": { "deeper": [1, { "k": "v", "list": [] }], "flag": true },
        "values": [0.5, null, "s"]
    })
}

/// The schema `$ref` points at, or `schema` itself.
fn resolve<'a>(schema: &'a Value, root: &'a Value) -> &'a Value {
    match schema.get("$ref").and_then(Value::as_str) {
        Some(r) => {
            let name = r.strip_prefix("#/$defs/").expect("a local $defs reference");
            resolve(&root["$defs"][name], root)
        }
        None => schema,
    }
}

/// `schema` and every branch of its `anyOf` / `oneOf` / `allOf`, resolved.
fn branches<'a>(schema: &'a Value, root: &'a Value, out: &mut Vec<&'a Value>) {
    let schema = resolve(schema, root);
    out.push(schema);
    for key in ["anyOf", "oneOf", "allOf"] {
        for b in schema
            .get(key)
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
        {
            branches(b, root, out);
        }
    }
}

/// Adds `x_future` to every JSON object that is a struct (the schema gives it
/// `properties`), recursing through struct fields, map values and arrays
/// with the schema beside the value. Maps (`additionalProperties` a schema)
/// get no key: their keys are data, not fields; nor does free-form JSON (a
/// value the schema does not type). Returns the objects changed.
fn inject(value: &mut Value, schema: &Value, root: &Value, path: &str) -> usize {
    let mut candidates = Vec::new();
    branches(schema, root, &mut candidates);
    match value {
        Value::Object(map) => {
            let is_struct = |s: &&&Value| {
                s.get("properties")
                    .and_then(Value::as_object)
                    .is_some_and(|p| map.keys().all(|k| p.contains_key(k)))
            };
            if let Some(s) = candidates.iter().find(is_struct) {
                let props = s["properties"].as_object().unwrap();
                let mut n = 0;
                for (k, v) in map.iter_mut() {
                    n += inject(v, &props[k], root, &format!("{path}.{k}"));
                }
                // `additionalProperties: false` marks the one-key object of an
                // enum value (`{"fixed": 1}`): a value, not a set of fields.
                if s.get("additionalProperties") != Some(&Value::Bool(false)) {
                    map.insert("x_future".into(), future());
                    n += 1;
                }
                n
            } else if let Some(s) = candidates
                .iter()
                .find(|s| s.get("additionalProperties").is_some_and(Value::is_object))
            {
                let inner = &s["additionalProperties"];
                (map.iter_mut())
                    .map(|(k, v)| inject(v, inner, root, &format!("{path}[{k}]")))
                    .sum()
            } else {
                // Free-form JSON (a `serde_json::Value` field): data, not fields.
                0
            }
        }
        Value::Array(items) => {
            let Some(s) = candidates.iter().find(|s| s.get("items").is_some()) else {
                return 0; // free-form JSON, as above
            };
            (items.iter_mut().enumerate())
                .map(|(i, v)| inject(v, &s["items"], root, &format!("{path}[{i}]")))
                .sum()
        }
        _ => 0,
    }
}

/// Every JSON object in `value`.
fn objects(value: &Value) -> usize {
    match value {
        Value::Object(m) => 1 + m.values().map(objects).sum::<usize>(),
        Value::Array(a) => a.iter().map(objects).sum(),
        _ => 0,
    }
}

/// `text` with an unknown field in every struct object, and how many.
fn with_future_fields(text: &str, schema: &str) -> (String, usize) {
    let schema: Value = serde_json::from_str(schema).unwrap();
    let mut value: Value = serde_json::from_str(text).unwrap();
    let n = inject(&mut value, &schema, &schema, "$");
    (serde_json::to_string_pretty(&value).unwrap(), n)
}

fn set(text: &str, edit: impl FnOnce(&mut Map<String, Value>)) -> String {
    let mut value: Value = serde_json::from_str(text).unwrap();
    edit(value.as_object_mut().unwrap());
    value.to_string()
}

#[test]
fn material_metadata_with_unknown_fields_everywhere_reads_the_same() {
    let text = generated("standard/standard.meta.json");
    let today = MaterialMetadata::from_json(&text).unwrap();
    let (future, n) = with_future_fields(&text, &generated("metadata.schema.json"));
    // Every struct object got a field (maps are the rest, and hold objects).
    let original: Value = serde_json::from_str(&text).unwrap();
    assert!(n > 1000 && n < objects(&original), "{n} objects changed");
    assert!(future.matches("\"x_future\"").count() == n);
    let read = MaterialMetadata::from_json(&future).unwrap_or_else(|e| panic!("{e}"));
    assert!(read == today, "unknown fields changed what was read");
}

#[test]
fn scene_metadata_with_unknown_fields_everywhere_reads_the_same() {
    let (dir, text) = first_scene();
    let today = SceneMetadata::from_json(&text).unwrap();
    let (future, n) = with_future_fields(&text, &generated("scene-metadata.schema.json"));
    assert!(n > 20, "{}: only {n} objects changed", dir.display());
    let read = SceneMetadata::from_json(&future).unwrap_or_else(|e| panic!("{e}"));
    assert!(read == today, "unknown fields changed what was read");
}

#[test]
fn a_file_without_a_minor_is_minor_zero_and_the_minor_is_written() {
    let text = generated("standard/standard.meta.json");
    let meta = MaterialMetadata::from_json(&text).unwrap();
    assert_eq!(
        (meta.schema_version, meta.schema_minor),
        (SCHEMA_VERSION, SCHEMA_MINOR)
    );
    let old = set(&text, |m| {
        m.remove("schema_minor");
    });
    assert_eq!(MaterialMetadata::from_json(&old).unwrap().schema_minor, 0);
    let (_, scene) = first_scene();
    let s = SceneMetadata::from_json(&scene).unwrap();
    assert_eq!(
        (s.schema_version, s.schema_minor),
        (SCENE_SCHEMA_VERSION, SCENE_SCHEMA_MINOR)
    );
}

#[test]
fn another_major_is_rejected_naming_both_versions() {
    let text = generated("standard/standard.meta.json");
    // A newer major whose layout also changed: the version is what is reported.
    let newer = set(&text, |m| {
        m.insert("schema_version".into(), json!(SCHEMA_VERSION + 1));
        m.insert("schema_minor".into(), json!(2));
        m.insert("variants".into(), json!("changed in the next major"));
    });
    let e = MaterialMetadata::from_json(&newer).unwrap_err();
    assert!(matches!(e, MetaError::Version { .. }), "{e:?}");
    let msg = e.to_string();
    let file = format!("{}.2", SCHEMA_VERSION + 1);
    let reader = format!("{SCHEMA_VERSION}.{SCHEMA_MINOR}");
    assert!(msg.contains(&file) && msg.contains(&reader), "{msg}");
    assert!(msg.contains("newer") && msg.contains("upgrade"), "{msg}");
    // A newer minor of the same major reads.
    let minor = set(&text, |m| {
        m.insert("schema_minor".into(), json!(SCHEMA_MINOR + 5));
    });
    assert_eq!(
        MaterialMetadata::from_json(&minor).unwrap().schema_minor,
        SCHEMA_MINOR + 5
    );
    // An older major.
    let older = set(&text, |m| {
        m.insert("schema_version".into(), json!(SCHEMA_VERSION - 1));
        m.remove("schema_minor");
    });
    let msg = MaterialMetadata::from_json(&older).unwrap_err().to_string();
    assert!(
        msg.contains(&format!("{}.0", SCHEMA_VERSION - 1)) && msg.contains(&reader),
        "{msg}"
    );
    assert!(msg.contains("older"), "{msg}");

    let (_, scene) = first_scene();
    let newer = set(&scene, |m| {
        m.insert("schema_version".into(), json!(SCENE_SCHEMA_VERSION + 1));
    });
    let msg = SceneMetadata::from_json(&newer).unwrap_err().to_string();
    let file = format!("{}.{SCENE_SCHEMA_MINOR}", SCENE_SCHEMA_VERSION + 1);
    let reader = format!("{SCENE_SCHEMA_VERSION}.{SCENE_SCHEMA_MINOR}");
    assert!(
        msg.contains("scene metadata") && msg.contains(&file) && msg.contains(&reader),
        "{msg}"
    );
    // Not metadata at all: a JSON error, not a version one.
    let e = MaterialMetadata::from_json("{}").unwrap_err();
    assert!(
        matches!(e, MetaError::Json { .. }) && e.to_string().contains("schema_version"),
        "{e}"
    );
}
