//! The closed lists of names the metadata documents, stated once.
//!
//! The front end accepts exactly these (scene meshes, vertex inputs, the
//! `auto` tier), the compiler writes exactly these (engine resource ids),
//! and the published JSON Schemas describe the fields that hold them with
//! text generated from the lists here, so a name added to the code cannot be
//! missing from the schema. The tests of `tests/` (metadata_contract,
//! diagnostics, scene_diagnostics) hold the parsers, the editor schemas
//! (`schemas/*.schema.json`) and the docs to the same lists.
//!
//! The enums of the metadata (`BlendMode`, `CullMode`, `DepthTest`,
//! `StencilOperation`, `KeywordKind`, `KeywordMode`, `ParamKind`,
//! `TextureDefault`) carry their own lists: `ALL` and `name()`, spelled as
//! serde writes them.

/// The built-in meshes a scene instance is drawn on (`[[instances]] mesh`,
/// `SceneInstance::mesh`), in the order docs and schemas list them: the
/// preview meshes, then the character bust whole and its parts (one mesh
/// each, sharing the bust's frame).
pub const BUILTIN_MESHES: [&str; 8] = [
    "sphere",
    "cloth",
    "swatch",
    "bust",
    "bust.head",
    "bust.eyes",
    "bust.hair",
    "bust.shoulders",
];

/// The `tier` value of a scene instance that lets the build choose the tier
/// (`TierChoice` records how).
pub const AUTO_TIER: &str = "auto";

/// The vertex inputs of the engine interface, by shader location (the index):
/// name and WebGPU vertex format.
pub const VERTEX_INPUTS: [(&str, &str); 6] = [
    ("position", "float32x3"),
    ("normal", "float32x3"),
    ("tangent", "float32x4"),
    ("uv0", "float32x2"),
    ("uv1", "float32x2"),
    ("color", "float32x4"),
];

/// The `resource.id`s of the engine interface's group-0 and group-2
/// bindings, by (group, binding) ([`crate::engine::ENGINE_BINDINGS`]). A
/// material's baked table (`[tables]`, group 1) has the id
/// `<material>.<table>` instead.
pub const ENGINE_RESOURCE_IDS: [&str; 7] = crate::engine::ENGINE_RESOURCE_IDS;

/// "`a`, `b` or `c`": a list of names as the schema descriptions write it.
#[cfg(feature = "schema")]
pub(crate) fn one_of(names: &[&str]) -> String {
    let quoted: Vec<String> = names.iter().map(|n| format!("`{n}`")).collect();
    match quoted.split_last() {
        None => String::new(),
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} or {last}", rest.join(", ")),
    }
}

// Schema descriptions generated from the lists above (schemars copies them
// into `generated/*.schema.json` in place of the fields' doc comments).

#[cfg(feature = "schema")]
pub(crate) fn mesh_description() -> String {
    format!(
        "The built-in mesh to draw (docs/scenes.md): {}.",
        one_of(&BUILTIN_MESHES)
    )
}

#[cfg(feature = "schema")]
pub(crate) fn measured_mesh_description() -> String {
    format!(
        "The built-in mesh the figures were measured on: {}.",
        one_of(&BUILTIN_MESHES)
    )
}

#[cfg(feature = "schema")]
pub(crate) fn tier_built_description() -> String {
    format!("The tier built (after `{AUTO_TIER}` was decided).")
}

#[cfg(feature = "schema")]
pub(crate) fn tier_choice_description() -> String {
    format!("How `tier = \"{AUTO_TIER}\"` was decided; absent for a tier named in the manifest.")
}

#[cfg(feature = "schema")]
pub(crate) fn vertex_input_name_description() -> String {
    let names: Vec<&str> = VERTEX_INPUTS.iter().map(|(n, _)| *n).collect();
    format!("The input's name: {}.", one_of(&names))
}

#[cfg(feature = "schema")]
pub(crate) fn vertex_input_location_description() -> String {
    let locations: Vec<String> = VERTEX_INPUTS
        .iter()
        .enumerate()
        .map(|(i, (n, _))| format!("{n} {i}"))
        .collect();
    format!(
        "Shader location (`@location`), fixed by the engine interface: {}.",
        locations.join(", ")
    )
}

#[cfg(feature = "schema")]
pub(crate) fn engine_resource_id_description() -> String {
    format!(
        "Stable name: {} for the engine interface's bindings (groups 0 and 2), or \
         `<material>.<table>` for a material's baked table (`[tables]`, group 1).",
        one_of(&ENGINE_RESOURCE_IDS)
    )
}

#[cfg(all(test, feature = "schema"))]
mod tests {
    use super::*;
    use crate::*;
    use schemars::JsonSchema;
    use serde::Serialize;

    /// `name()` is serde's spelling of every value, and `ALL` holds every
    /// variant the schema lists, once.
    fn check<T: Serialize + JsonSchema + Copy>(all: &[T], name: fn(T) -> &'static str) {
        let mut names: Vec<&str> = all.iter().map(|v| name(*v)).collect();
        for v in all {
            assert_eq!(serde_json::to_value(v).unwrap(), name(*v));
        }
        let schema = serde_json::to_value(schemars::schema_for!(T)).unwrap();
        let mut variants: Vec<String> = schema["oneOf"]
            .as_array()
            .expect("every variant is documented: schemars writes a oneOf")
            .iter()
            .map(|alt| {
                alt.get("const")
                    .or_else(|| alt["enum"].get(0))
                    .and_then(|v| v.as_str())
                    .expect("a unit variant")
                    .to_string()
            })
            .collect();
        variants.sort();
        names.sort();
        assert_eq!(names, variants, "{}", std::any::type_name::<T>());
    }

    #[test]
    fn value_names_are_serdes_and_complete() {
        check(&BlendMode::ALL, BlendMode::name);
        check(&CullMode::ALL, CullMode::name);
        check(&DepthTest::ALL, DepthTest::name);
        check(&StencilOperation::ALL, StencilOperation::name);
        check(&KeywordKind::ALL, KeywordKind::name);
        check(&KeywordMode::ALL, KeywordMode::name);
        check(&ParamKind::ALL, ParamKind::name);
        check(&TextureDefault::ALL, TextureDefault::name);
        check(&FilterMode::ALL, FilterMode::name);
        check(&AddressMode::ALL, AddressMode::name);
    }

    #[test]
    fn generated_descriptions_list_every_name() {
        for m in BUILTIN_MESHES {
            assert!(mesh_description().contains(&format!("`{m}`")));
            assert!(measured_mesh_description().contains(&format!("`{m}`")));
        }
        for id in ENGINE_RESOURCE_IDS {
            assert!(engine_resource_id_description().contains(&format!("`{id}`")));
        }
        for (i, (name, _)) in VERTEX_INPUTS.iter().enumerate() {
            assert!(vertex_input_name_description().contains(&format!("`{name}`")));
            assert!(vertex_input_location_description().contains(&format!("{name} {i}")));
        }
    }

    #[test]
    fn lists_read_as_prose() {
        assert_eq!(one_of(&[]), "");
        assert_eq!(one_of(&["a"]), "`a`");
        assert_eq!(one_of(&["a", "b"]), "`a` or `b`");
        assert_eq!(one_of(&["a", "b", "c"]), "`a`, `b` or `c`");
    }
}
