//! `scenes/<name>.scene.toml` -> [`SceneManifest`]: keys, types and every
//! check that needs no material (names, the materials root, features, camera,
//! tier requests, meshes, transforms). Parameter values stay in the TOML tree
//! ([`WrittenParam`]) until `resolve` types them against their material.

mod instance;

use super::model::*;
use crate::diag::{Span, suggestion_listing};
use crate::parse::parse_vertex_inputs;
use crate::toml_reader::{
    Cx, Table, Value, expect_array, expect_numbers, expect_string, type_error,
};
use codespan_reporting::diagnostic::Label;
use instance::{check_unique_names, parse_instance};
use std::path::{Path, PathBuf};
use toml::de::{DeTable, DeValue};

pub const TOP_KEYS: &[&str] = &[
    "scene",
    "camera",
    "light",
    "static_lighting",
    "instances",
    "gltf",
];
pub const SCENE_KEYS: &[&str] = &[
    "name",
    "description",
    "materials",
    "environment",
    "sh_ambient",
    "directional_lights",
    "vertex_inputs",
    "max_shaders",
    "gpu_family",
];
pub const CAMERA_KEYS: &[&str] = &["position", "target", "fov_degrees"];
pub const LIGHT_KEYS: &[&str] = &["direction", "color"];
pub const STATIC_LIGHTING_KEYS: &[&str] = &["sh"];

pub use weft_meta::scene::MAX_INSTANCES;
pub const INSTANCE_KEYS: &[&str] = &[
    "name",
    "material",
    "preset",
    "tier",
    "error_budget",
    "screen_size",
    "keywords",
    "params",
    "dynamic",
    "mesh",
    "vertex_inputs",
    "translation",
    "rotation",
    "scale",
    "matrix",
    "variant",
    "double_sided",
    "blend",
    "sampler",
];
/// Keys of an instance's `sampler = { … }` (the state of `material_sampler`).
pub const SAMPLER_KEYS: &[&str] = &[
    "address_mode_u",
    "address_mode_v",
    "mag_filter",
    "min_filter",
    "mipmap_filter",
    "mipmaps",
];
/// Keys of an instance's `variant = { name = "…", replaces = "…" }`.
pub const VARIANT_KEYS: &[&str] = &["name", "replaces"];
/// Keys of a glTF mesh reference, `mesh = { gltf = "x.glb", mesh = 0, primitive = 0 }`.
pub const GLTF_MESH_KEYS: &[&str] = &["gltf", "mesh", "primitive", "uv_transform", "node"];

/// The materials root when `[scene]` sets no `materials`, relative to the scene file.
pub const DEFAULT_MATERIALS: &str = "../materials";
/// The `tier` value that lets the build choose the tier (the metadata's name for it).
pub use weft_meta::scene::AUTO_TIER;
/// `screen_size` limits (pixels) for `tier = "auto"`.
pub const SCREEN_SIZE_RANGE: std::ops::RangeInclusive<i64> = 16..=4096;
/// Engine interface v1 has one directional light slot.
pub const MAX_DIRECTIONAL_LIGHTS: i64 = 1;
/// A scene file's name ends with this; the scene's name is what comes before it.
pub const SCENE_SUFFIX: &str = ".scene.toml";

/// One `params` entry of an instance as written, borrowed from the TOML tree.
pub struct WrittenParam<'a, 'i> {
    pub name: &'a str,
    pub name_span: Span,
    pub value: &'a Value<'i>,
}

/// What `parse` hands `resolve`.
pub struct Parsed<'a, 'i> {
    pub manifest: SceneManifest,
    /// One list per entry of `manifest.instances`, in the same order.
    pub params: Vec<Vec<WrittenParam<'a, 'i>>>,
}

/// The TOML tree of a scene file; `None` (and a `toml-syntax` error) when it does not parse.
pub fn parse_document<'i>(text: &'i str, cx: &mut Cx) -> Option<toml::Spanned<DeTable<'i>>> {
    match DeTable::parse(text) {
        Ok(doc) => Some(doc),
        Err(e) => {
            cx.error_with_note(
                "toml-syntax",
                format!("invalid TOML: {}", e.message().trim()),
                e.span().unwrap_or(0..0),
                "here",
                "see docs/scenes.md for the file format",
            );
            None
        }
    }
}

/// A scene or instance name: lower case letters, digits and underscores, starting with a letter.
pub fn is_scene_name(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some('a'..='z'))
        && chars.all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
}

/// The scene name a file's name implies: `fitting_room.scene.toml` -> `fitting_room`.
pub fn file_scene_name(path: &Path) -> String {
    let file = path
        .file_name()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    match file.strip_suffix(SCENE_SUFFIX) {
        Some(stem) => stem.to_string(),
        None => path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default(),
    }
}

/// `gpu_family`: the GPU family whose modelled cost `tier = "auto"` uses
/// (one of [`weft_meta::scene::GPU_COST_FAMILIES`]; default RDNA2). A name
/// another Mesa release gives the family (`navi31`) is read as weft's
/// (`gfx1100`), so the scene's metadata is the same whichever a user wrote.
fn parse_gpu_family(scene: &Table, cx: &mut Cx) -> String {
    use weft_meta::scene::{
        DEFAULT_GPU_COST_FAMILY, GPU_COST_FAMILIES, GPU_FAMILY_SPELLINGS, weft_gpu_family,
    };
    let Some(family) = scene.string("gpu_family", cx) else {
        return DEFAULT_GPU_COST_FAMILY.into();
    };
    let weft_name = weft_gpu_family(&family);
    if GPU_COST_FAMILIES.contains(&weft_name) {
        return weft_name.to_owned();
    }
    let other_spellings: Vec<String> = GPU_FAMILY_SPELLINGS
        .iter()
        .map(|(weft, all)| format!("`{weft}` is also {}", all[1..].join(", ")))
        .collect();
    cx.error_with_note(
        "unknown-value",
        format!("unknown `gpu_family` `{family}`"),
        scene.span_of("gpu_family"),
        "not a modelled family",
        format!(
            "`tier = \"auto\"` costs tiers with AMD's compiler for one of: {} (default \
             `{DEFAULT_GPU_COST_FAMILY}`: RDNA2; `gfx1100`: RDNA3; later Mesa's names: {})",
            GPU_COST_FAMILIES.join(", "),
            other_spellings.join("; ")
        ),
    );
    DEFAULT_GPU_COST_FAMILY.into()
}

/// Reads the manifest from the TOML tree. `None` without a `[scene]` table;
/// otherwise every problem found is in `cx.diags` and the manifest holds the
/// instances that have a name and a material (the others cannot be resolved).
pub fn parse_manifest<'a, 'i>(
    doc: &'a DeTable<'i>,
    path: &Path,
    cx: &mut Cx,
) -> Option<Parsed<'a, 'i>> {
    let top = Table {
        map: doc,
        span: 0..0,
        what: "the scene file".into(),
    };
    top.check_keys(TOP_KEYS, cx);
    let Some(scene_v) = top.get("scene") else {
        cx.error_with_note(
            "missing-key",
            "missing [scene] table",
            0..0,
            "the file starts here",
            "add a [scene] table with at least `name` and `vertex_inputs` (docs/scenes.md)",
        );
        return None;
    };
    let scene = Table::new(scene_v, "[scene]", cx)?;
    scene.check_keys(SCENE_KEYS, cx);

    let stem = file_scene_name(path);
    let name = match scene.get("name") {
        None => {
            cx.error_with_note(
                "missing-key",
                "[scene] has no `name`",
                scene.span.clone(),
                "in this table",
                format!("add `name = \"{stem}\"` (the file name before `{SCENE_SUFFIX}`)"),
            );
            stem
        }
        Some(v) => {
            let name = expect_string(v, "`name` of [scene]", cx).unwrap_or_else(|| stem.clone());
            check_scene_name(&name, &stem, v.span(), cx);
            name
        }
    };

    let dir = path.parent().unwrap_or(Path::new("."));
    let materials_root = materials_root(&scene, dir, cx);
    let features = parse_features(&scene, cx);
    let vertex_inputs = match parse_vertex_inputs(&scene, "vertex_inputs", cx) {
        Some(list) => list,
        None => {
            if scene.get("vertex_inputs").is_none() {
                cx.error_with_note(
                    "missing-key",
                    "[scene] has no `vertex_inputs`",
                    scene.span.clone(),
                    "in this table",
                    "list what every instance's mesh provides, e.g. `vertex_inputs = [\"position\", \"normal\", \"tangent\", \"uv0\"]`",
                );
            }
            Vec::new()
        }
    };
    let max_shaders = scene.integer("max_shaders", cx).and_then(|n| {
        let span = scene.span_of("max_shaders");
        match usize::try_from(n) {
            Ok(n) if n >= 1 => Some(Spanned { value: n, span }),
            _ => {
                cx.error(
                    "out-of-range",
                    "`max_shaders` must be at least 1",
                    span,
                    format!("{n} is below 1"),
                );
                None
            }
        }
    });
    let gpu_family = parse_gpu_family(&scene, cx);
    let camera = top
        .get("camera")
        .and_then(|v| Table::new(v, "[camera]", cx))
        .map(|t| parse_camera(&t, cx))
        .unwrap_or_default();
    let light = top
        .get("light")
        .and_then(|v| Table::new(v, "[light]", cx))
        .and_then(|t| parse_light(&t, cx));
    let static_lighting = top
        .get("static_lighting")
        .and_then(|v| Table::new(v, "[static_lighting]", cx))
        .and_then(|t| parse_static_lighting(&t, &features, cx));

    let mut manifest = SceneManifest {
        name,
        description: scene.string("description", cx),
        file: cx.file,
        path: path.to_path_buf(),
        materials_root,
        features,
        scene_span: scene.span.clone(),
        vertex_inputs: Spanned {
            value: vertex_inputs,
            span: scene.span_of("vertex_inputs"),
        },
        camera,
        light,
        static_lighting,
        max_shaders,
        gpu_family,
        instances: Vec::new(),
        gltf: None,
    };
    let mut params = Vec::new();
    let items = match top.get("instances") {
        Some(v) => expect_array(v, "`instances`", cx).map(|items| (items, v.span())),
        None => Some((&[][..], scene.span.clone())),
    };
    if let Some((items, span)) = items {
        if items.len() > MAX_INSTANCES {
            cx.error_with_note(
                "too-many-instances",
                format!(
                    "the scene has {} instances; at most {MAX_INSTANCES} are built",
                    items.len()
                ),
                span,
                "too many",
                "each instance gets its own specialised shader: split the scene, or draw \
                 repeats of one object with the engine's instancing",
            );
            return None;
        }
        if items.is_empty() {
            cx.error_with_note(
                "empty-scene",
                "the scene has no instances",
                span,
                "nothing to draw",
                "add an [[instances]] table per object, with at least `name`, `material` and `mesh`",
            );
        }
        let mut names = Vec::new();
        for item in items {
            let (name, instance) = parse_instance(item, cx);
            names.extend(name);
            if let Some((decl, written)) = instance {
                manifest.instances.push(decl);
                params.push(written);
            }
        }
        check_unique_names(&names, cx);
    }
    Some(Parsed { manifest, params })
}

fn check_scene_name(name: &str, stem: &str, span: Span, cx: &mut Cx) {
    if !is_scene_name(name) {
        cx.error_with_note(
            "bad-name",
            format!("scene name `{name}` is not a lower_snake_case name"),
            span,
            "names the build's output files",
            "use lower case letters, digits and underscores, starting with a letter",
        );
    } else if name != stem {
        cx.error_with_note(
            "bad-name",
            format!("scene name `{name}` does not match the file name `{stem}{SCENE_SUFFIX}`"),
            span,
            format!("expected `{stem}`"),
            format!("rename the file to `{name}{SCENE_SUFFIX}`, or write `name = \"{stem}\"`"),
        );
    }
}

/// The materials root, canonical when it exists; a missing folder is reported.
fn materials_root(scene: &Table, dir: &Path, cx: &mut Cx) -> PathBuf {
    let written = scene.string("materials", cx);
    let rel = written.as_deref().unwrap_or(DEFAULT_MATERIALS);
    let root = dir.join(rel);
    match root.canonicalize() {
        Ok(abs) if abs.is_dir() => abs,
        _ => {
            let (span, label, note) = match written {
                Some(_) => (
                    scene.span_of("materials"),
                    "no such folder (relative to this scene file)".to_string(),
                    "materials are looked up as `<root>/<name>/<name>.toml`".to_string(),
                ),
                None => (
                    scene.span.clone(),
                    format!("no `materials`, so the root is `{DEFAULT_MATERIALS}`"),
                    "set `materials = \"<folder>\"` (relative to this file) under [scene]"
                        .to_string(),
                ),
            };
            cx.error_with_note(
                "missing-root",
                format!("the materials root `{rel}` does not exist"),
                span,
                label,
                note,
            );
            root
        }
    }
}

fn parse_features(scene: &Table, cx: &mut Cx) -> SceneFeatures {
    let mut features = SceneFeatures::default();
    features.environment = scene
        .boolean("environment", cx)
        .unwrap_or(features.environment);
    features.sh_ambient = scene
        .boolean("sh_ambient", cx)
        .unwrap_or(features.sh_ambient);
    if let Some(n) = scene.integer("directional_lights", cx) {
        let span = scene.span_of("directional_lights");
        if n < 0 {
            cx.error(
                "out-of-range",
                "`directional_lights` cannot be negative",
                span,
                format!("{n} lights"),
            );
        } else if n > MAX_DIRECTIONAL_LIGHTS {
            cx.error_with_note(
                "unsupported-feature",
                format!("{n} directional lights: engine interface v1 has one light slot"),
                span,
                format!("at most {MAX_DIRECTIONAL_LIGHTS}"),
                "write 0 (no direct light) or 1; more lights need a new engine interface version (docs/engine-interface.md)",
            );
        } else {
            features.directional_lights = n as u32;
        }
    }
    features
}

/// `[x, y, z]` under `key`; `None` when absent or malformed (reported).
fn vec3(t: &Table, key: &str, cx: &mut Cx) -> Option<[f64; 3]> {
    let span = t.get(key)?.span();
    let nums = t.numbers(key, cx)?;
    match <[f64; 3]>::try_from(nums) {
        Ok(v) if !v.iter().all(|x| fits_f32(*x)) => {
            f32_range_error(key, t, span, cx);
            None
        }
        Ok(v) => Some(v),
        Err(nums) => {
            cx.error(
                "wrong-type",
                format!("`{key}` of {} must be 3 numbers [x, y, z]", t.what),
                span,
                format!("{} numbers here", nums.len()),
            );
            None
        }
    }
}

/// Whether `x` is finite and stays finite as the f32 the GPU receives.
fn fits_f32(x: f64) -> bool {
    x.is_finite() && x.abs() <= f64::from(f32::MAX)
}

fn f32_range_error(key: &str, t: &Table, span: Span, cx: &mut Cx) {
    cx.error(
        "type-range",
        format!(
            "`{key}` of {} must be finite numbers within ±3.4e38 (they become 32-bit floats)",
            t.what
        ),
        span,
        "out of f32 range",
    );
}

fn parse_camera(t: &Table, cx: &mut Cx) -> Camera {
    t.check_keys(CAMERA_KEYS, cx);
    let mut camera = Camera::default();
    camera.position = vec3(t, "position", cx).unwrap_or(camera.position);
    camera.target = vec3(t, "target", cx).unwrap_or(camera.target);
    if let Some(fov) = t.number("fov_degrees", cx) {
        if fov > 0.0 && fov < 180.0 {
            camera.fov_degrees = fov;
        } else {
            cx.error(
                "out-of-range",
                "`fov_degrees` of [camera] must be between 0 and 180 (exclusive)",
                t.span_of("fov_degrees"),
                format!("{fov} is not in (0, 180)"),
            );
        }
    }
    camera
}

fn parse_light(t: &Table, cx: &mut Cx) -> Option<SceneLight> {
    t.check_keys(LIGHT_KEYS, cx);
    let color = light_color(t, cx);
    let Some(direction) = vec3(t, "direction", cx) else {
        if t.get("direction").is_none() {
            cx.error_with_note(
                "missing-key",
                "[light] needs a `direction`",
                t.span.clone(),
                "no `direction` here",
                "e.g. direction = [-1.0, 0.5, 0.6] (from the surface towards the light)",
            );
        }
        return None;
    };
    if direction.iter().any(|c| !c.is_finite()) || direction.iter().all(|c| c.abs() < 1e-6) {
        cx.error_with_note(
            "out-of-range",
            "`direction` of [light] must be finite and not zero",
            t.span_of("direction"),
            "no direction",
            "it points from the surface towards the light, e.g. [-1.0, 0.5, 0.6]",
        );
        return None;
    }
    Some(SceneLight {
        direction,
        color: color?,
    })
}

/// `[static_lighting]`: `sh` (nine `[r, g, b]`) exactly when the scene has
/// SH ambient, each coefficient a finite f32.
fn parse_static_lighting(
    t: &Table,
    features: &SceneFeatures,
    cx: &mut Cx,
) -> Option<StaticLighting> {
    t.check_keys(STATIC_LIGHTING_KEYS, cx);
    let Some(value) = t.get("sh") else {
        if features.sh_ambient {
            cx.error_with_note(
                "missing-key",
                "[static_lighting] needs the SH ambient's coefficients, `sh`",
                t.span.clone(),
                "no `sh` here",
                "give the nine [r, g, b] coefficients of your ambient probe \
                 (docs/engine-interface.md, \"SH\"), or set `sh_ambient = false` in [scene]",
            );
            return None;
        }
        return Some(StaticLighting { sh: None });
    };
    let span = value.span();
    if !features.sh_ambient {
        cx.error_with_note(
            "unused-key",
            "`sh` of [static_lighting] is given, but the scene has no SH ambient",
            span,
            "never read",
            "remove `sh`, or set `sh_ambient = true` in [scene]",
        );
        return None;
    }
    let rows = expect_array(value, "`sh` of [static_lighting]", cx)?;
    if rows.len() != 9 {
        cx.error_with_note(
            "wrong-type",
            "`sh` of [static_lighting] must be 9 coefficients [r, g, b]",
            span,
            format!("{} here", rows.len()),
            "L2 SH has nine: Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22 (docs/engine-interface.md)",
        );
        return None;
    }
    let mut sh = [[0.0; 3]; 9];
    for (i, row) in rows.iter().enumerate() {
        let what = format!("`sh[{i}]` of [static_lighting]");
        let nums = expect_numbers(row, &what, cx)?;
        let rgb = <[f64; 3]>::try_from(nums.as_slice()).ok();
        match rgb {
            Some(rgb) if rgb.iter().all(|x| fits_f32(*x)) => sh[i] = rgb,
            _ => {
                cx.error(
                    "wrong-type",
                    format!("{what} must be 3 finite numbers [r, g, b] within the f32 range"),
                    row.span(),
                    "not an RGB coefficient",
                );
                return None;
            }
        }
    }
    Some(StaticLighting { sh: Some(sh) })
}

/// `color` of `[light]`: `Some(None)` when absent, `None` when wrong.
fn light_color(t: &Table, cx: &mut Cx) -> Option<Option<[f64; 3]>> {
    if t.get("color").is_none() {
        return Some(None);
    }
    let c = vec3(t, "color", cx)?;
    if c.iter().any(|x| *x < 0.0 || !x.is_finite()) {
        cx.error(
            "out-of-range",
            "`color` of [light] must be finite and not negative",
            t.span_of("color"),
            "not a radiance",
        );
        return None;
    }
    Some(Some(c))
}

/// A required string key; reports it missing at `at`.
fn required_string(
    t: &Table,
    key: &str,
    at: &Span,
    note: &str,
    cx: &mut Cx,
) -> Option<Spanned<String>> {
    match t.get(key) {
        None => {
            cx.error_with_note(
                "missing-key",
                format!("{} has no `{key}`", t.what),
                at.clone(),
                format!("`{key}` missing in this instance"),
                note,
            );
            None
        }
        Some(v) => expect_string(v, &format!("`{key}` of {}", t.what), cx).map(|value| Spanned {
            value,
            span: v.span(),
        }),
    }
}
