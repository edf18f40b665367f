//! `[gltf]` in a scene manifest: a glTF file's nodes, camera and light
//! with weft's choices layered on its materials.
//!
//! ```toml
//! [gltf]
//! file = "gltf/showroom.glb"
//! [gltf.materials.Cushion]          # a glTF material's name, or "#3" by index
//! tier = "auto"
//! error_budget = 0.05
//! params = { smoothness = 0.2 }
//! dynamic = ["base_color"]
//! ```
//!
//! The glTF's `[[instances]]` (and its `[camera]` / `[light]` where the
//! manifest has none) are appended to the manifest's own text, so every
//! span of what the user wrote stays where it was and the composed text
//! goes through the ordinary parse and resolve.

use crate::gltf::materials::MaterialMapping;
use crate::gltf::scene::{Overrides, scene_manifest};
use crate::gltf::{GltfFile, Warnings};
use crate::toml_reader::{Cx, Table, Value};
use std::path::Path;
use toml::de::DeTable;

pub const GLTF_KEYS: &[&str] = &["file", "materials"];
/// `[gltf.materials.<name>]`: the same keys as a glTF material's `extras.weft`.
pub const GLTF_MATERIAL_KEYS: &[&str] = crate::gltf::materials::WEFT_KEYS;

/// The source text of a value, as written (kept verbatim into the
/// generated instance, so it is checked against the material as written).
fn written<'t>(text: &'t str, v: &Value) -> &'t str {
    text.get(v.span()).unwrap_or("")
}

/// An inline table's entries as (key, value text).
fn entries(t: &Table, key: &str, text: &str, cx: &mut Cx) -> Vec<(String, String)> {
    let Some(v) = t.get(key) else {
        return Vec::new();
    };
    let Some(inner) = Table::new(v, format!("`{key}`"), cx) else {
        return Vec::new();
    };
    inner
        .entries()
        .map(|(k, _, v)| (k.to_string(), written(text, v).to_string()))
        .collect()
}

fn overrides(gltf: &Table, text: &str, cx: &mut Cx) -> Overrides {
    let mut out = Overrides::new();
    let Some(v) = gltf.get("materials") else {
        return out;
    };
    let Some(materials) = Table::new(v, "[gltf.materials]", cx) else {
        return out;
    };
    for (name, _, v) in materials.entries() {
        let Some(t) = Table::new(v, format!("[gltf.materials.{name}]"), cx) else {
            continue;
        };
        t.check_keys(GLTF_MATERIAL_KEYS, cx);
        let mapping = MaterialMapping {
            gltf_name: name.to_string(),
            material: t.string("material", cx).unwrap_or_default(),
            preset: t.string("preset", cx),
            tier: t.string("tier", cx),
            error_budget: t.number("error_budget", cx),
            screen_size: t
                .integer("screen_size", cx)
                .and_then(|n| u32::try_from(n).ok()),
            keywords: entries(&t, "keywords", text, cx),
            params: entries(&t, "params", text, cx),
            dynamic: t
                .strings("dynamic", cx)
                .unwrap_or_default()
                .into_iter()
                .map(|(s, _)| s)
                .collect(),
            losses: Vec::new(),
            double_sided: false,
            blend: false,
            sampler: None,
            uv_transform: None,
            rule: "[gltf.materials]",
        };
        out.insert(name.to_string(), mapping);
    }
    out
}

/// The manifest's text with the `[gltf]` file's scene appended, or `None`
/// (and a diagnostic) when the table or the file is wrong. Warnings about
/// what the glTF mapping drops go to `warnings`.
pub fn compose(
    doc: &DeTable,
    text: &str,
    manifest_path: &Path,
    cx: &mut Cx,
    warnings: &mut Warnings,
) -> Option<(String, super::model::GltfSource, std::sync::Arc<GltfFile>)> {
    let top = Table {
        map: doc,
        span: 0..0,
        what: "the scene file".into(),
    };
    let v = top.get("gltf")?;
    let gltf = Table::new(v, "[gltf]", cx)?;
    gltf.check_keys(GLTF_KEYS, cx);
    let Some(file) = gltf.string("file", cx) else {
        cx.error_with_note(
            "missing-key",
            "[gltf] has no `file`",
            gltf.span.clone(),
            "in this table",
            "name the glTF file, relative to this manifest: `file = \"gltf/showroom.glb\"`",
        );
        return None;
    };
    let dir = manifest_path.parent().unwrap_or(Path::new("."));
    let overrides = overrides(&gltf, text, cx);
    let result = GltfFile::open(&dir.join(&file), warnings).and_then(|opened| {
        let scene = scene_manifest(&opened, "gltf", dir, None, &overrides, warnings)?;
        Ok((scene, std::sync::Arc::new(opened)))
    });
    let (scene, opened) = match result {
        Ok(s) => s,
        Err(e) => {
            cx.error_with_note(
                "gltf",
                e.to_string(),
                gltf.span_of("file"),
                "the glTF file",
                e.hint,
            );
            return None;
        }
    };
    for m in &scene.mappings {
        for loss in &m.losses {
            warnings.push(format!(
                "{}: material `{}` → {}: drops {loss}",
                crate::gltf::shown(&dir.join(&file)),
                m.gltf_name,
                m.material
            ));
        }
    }
    let mut out = text.to_string();
    out.push_str(&format!(
        "\n\n# ---- appended by weft from [gltf] file `{file}` (docs/gltf.md) ----\n"
    ));
    if top.get("camera").is_none() {
        out.push_str(&scene.camera);
        out.push('\n');
    }
    if top.get("light").is_none() && !scene.light.is_empty() {
        out.push_str(&scene.light);
        out.push('\n');
    }
    out.push_str(&scene.instances);
    let source = super::model::GltfSource {
        file: file.clone(),
        materials: scene.materials_in_file,
        materials_used: scene.materials_used,
    };
    Some((out, source, opened))
}
