//! Reading the hand-written editor schemas (`schemas/*.schema.json`) in the
//! tests that keep them in sync with the parsers' key lists. Shared by the
//! test binaries through `weft_tests::schema`.

use std::path::Path;

pub fn load(path: impl AsRef<Path>) -> serde_json::Value {
    let path = path.as_ref();
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Resolves `{"$ref": "#/definitions/x"}`.
pub fn resolve<'a>(
    schema: &'a serde_json::Value,
    v: &'a serde_json::Value,
) -> &'a serde_json::Value {
    match v.get("$ref").and_then(|r| r.as_str()) {
        Some(r) => {
            let pointer = r.strip_prefix('#').expect("local $ref");
            resolve(
                schema,
                schema
                    .pointer(pointer)
                    .unwrap_or_else(|| panic!("dangling {r}")),
            )
        }
        None => v,
    }
}

/// The property names of a closed object schema, sorted.
pub fn property_names(
    schema: &serde_json::Value,
    v: &serde_json::Value,
    what: &str,
) -> Vec<String> {
    let v = resolve(schema, v);
    assert_eq!(
        v.get("additionalProperties"),
        Some(&serde_json::Value::Bool(false)),
        "{what}: additionalProperties must be false"
    );
    let mut names: Vec<String> = v
        .get("properties")
        .and_then(|p| p.as_object())
        .unwrap_or_else(|| panic!("{what}: no properties"))
        .keys()
        .cloned()
        .collect();
    names.sort();
    names
}

pub fn sorted(keys: &[&str]) -> Vec<String> {
    let mut v: Vec<String> = keys.iter().map(|s| s.to_string()).collect();
    v.sort();
    v
}

/// The strings of an `enum` array.
pub fn enum_values(v: &serde_json::Value, what: &str) -> Vec<String> {
    v.get("enum")
        .and_then(|e| e.as_array())
        .unwrap_or_else(|| panic!("{what}: no enum"))
        .iter()
        .map(|v| v.as_str().expect("string").to_string())
        .collect()
}

/// The file's first line is a `#:schema <path>` directive naming an existing file.
pub fn assert_schema_directive(path: impl AsRef<Path>) {
    let path = path.as_ref();
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let first = text.lines().next().unwrap_or_default();
    assert!(
        first.starts_with("#:schema "),
        "{}: first line is not a #:schema directive",
        path.display()
    );
    let target = path
        .parent()
        .expect("dir")
        .join(first.trim_start_matches("#:schema ").trim());
    assert!(
        target.is_file(),
        "{}: schema directive points at {}",
        path.display(),
        target.display()
    );
}
