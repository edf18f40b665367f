//! `scenes/<name>.scene.toml` -> [`SceneManifest`]: keys, types and every
//! check that needs no material (names, the materials root, features, camera,
//! tier requests, meshes, transforms). Parameter values stay in the TOML tree
//! ([`WrittenParam`]) until `resolve` types them against their material.

use super::model::*;
use crate::diag::{Span, suggestion_listing};
use crate::parse::parse_vertex_inputs;
use crate::toml_reader::{Cx, Table, Value, expect_array, expect_string, type_error};
use codespan_reporting::diagnostic::Label;
use std::path::{Path, PathBuf};
use toml::de::{DeTable, DeValue};

pub const TOP_KEYS: &[&str] = &["scene", "camera", "light", "instances", "gltf"];
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

/// The most instances a scene may have. Instances that share a specialised
/// shader are compiled once, and the build caps the distinct shaders
/// separately (`weft_compiler::MAX_SCENE_SHADERS`), so this bounds the
/// per-instance work: resolving, checking and describing each instance
/// (1024 repeats of five objects build in about 0.2 s, docs/scaling.md).
pub const MAX_INSTANCES: usize = 1024;
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
];
/// Keys of an instance's `variant = { name = "…", replaces = "…" }`.
pub const VARIANT_KEYS: &[&str] = &["name", "replaces"];
/// Keys of a glTF mesh reference, `mesh = { gltf = "x.glb", mesh = 0, primitive = 0 }`.
pub const GLTF_MESH_KEYS: &[&str] = &["gltf", "mesh", "primitive"];

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
/// (one of [`weft_meta::scene::GPU_COST_FAMILIES`]; default RDNA2).
fn parse_gpu_family(scene: &Table, cx: &mut Cx) -> String {
    use weft_meta::scene::{DEFAULT_GPU_COST_FAMILY, GPU_COST_FAMILIES};
    let Some(family) = scene.string("gpu_family", cx) else {
        return DEFAULT_GPU_COST_FAMILY.into();
    };
    if GPU_COST_FAMILIES.contains(&family.as_str()) {
        return family;
    }
    cx.error_with_note(
        "unknown-value",
        format!("unknown `gpu_family` `{family}`"),
        scene.span_of("gpu_family"),
        "not a modelled family",
        format!(
            "`tier = \"auto\"` costs tiers with AMD's compiler for one of: {} (default `{DEFAULT_GPU_COST_FAMILY}`)",
            GPU_COST_FAMILIES.join(", ")
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

/// The instance's name (for the duplicate check) and, when it has a name
/// and a material, the instance.
type ParsedInstance<'a, 'i> = (
    Option<Spanned<String>>,
    Option<(InstanceDecl, Vec<WrittenParam<'a, 'i>>)>,
);

fn parse_instance<'a, 'i>(item: &'a Value<'i>, cx: &mut Cx) -> ParsedInstance<'a, 'i> {
    let Some(mut t) = Table::new(item, "an [[instances]] entry", cx) else {
        return (None, None);
    };
    let name = t.string("name", cx);
    if let Some(n) = &name {
        t.what = format!("instance `{n}`");
    }
    t.check_keys(INSTANCE_KEYS, cx);
    // Errors about the instance as a whole point at its name, or its first key.
    let at = t.get("name").map_or_else(
        || {
            t.entries()
                .next()
                .map_or_else(|| t.span.clone(), |(_, span, _)| span)
        },
        |v| v.span(),
    );
    match &name {
        None if t.get("name").is_none() => cx.error_with_note(
            "missing-key",
            "an [[instances]] entry has no `name`",
            at.clone(),
            "in this instance",
            "give every instance a unique lower_snake_case `name`",
        ),
        Some(n) if !is_scene_name(n) => cx.error_with_note(
            "bad-name",
            format!("instance name `{n}` is not a lower_snake_case name"),
            at.clone(),
            "names the instance in the scene metadata",
            "use lower case letters, digits and underscores, starting with a letter",
        ),
        _ => {}
    }
    let material = required_string(
        &t,
        "material",
        &at,
        "name a material folder of the materials root, e.g. `material = \"standard\"`",
        cx,
    );
    let preset = t.string("preset", cx).map(|value| Spanned {
        value,
        span: t.span_of("preset"),
    });
    let tier = parse_tier(&t, cx);
    let keywords = parse_keywords(&t, cx);
    let params = written_params(&t, cx);
    let dynamic = parse_dynamic(&t, cx);
    let mesh = parse_mesh(&t, &at, cx);
    let vertex_inputs = parse_vertex_inputs(&t, "vertex_inputs", cx).map(|value| Spanned {
        value,
        span: t.span_of("vertex_inputs"),
    });
    let transform = parse_transform(&t, cx);
    let variant = parse_variant(&t, cx);
    let overrides = parse_overrides(&t, cx);
    let Some(name) = name else {
        return (None, None);
    };
    let written_name = Spanned {
        value: name.clone(),
        span: at.clone(),
    };
    let Some(material) = material else {
        return (Some(written_name), None);
    };
    let decl = InstanceDecl {
        name,
        span: t.span.clone(),
        name_span: at,
        material,
        preset,
        tier,
        keywords,
        dynamic,
        // A missing or unknown mesh is reported; the instance is still
        // resolved (the scene fails anyway) so that one run shows everything.
        mesh: mesh.unwrap_or(Spanned {
            value: MeshSpec::Builtin(BuiltinMesh::Sphere),
            span: t.span.clone(),
        }),
        vertex_inputs,
        transform,
        variant,
        overrides,
    };
    (Some(written_name), Some((decl, params)))
}

/// `double_sided = true` and `blend = "alpha"` (any blend mode but opaque).
fn parse_overrides(t: &Table, cx: &mut Cx) -> PassOverrides {
    let double_sided = t.boolean("double_sided", cx).unwrap_or(false);
    let blend = t.string("blend", cx).and_then(|name| {
        let modes: Vec<&str> = weft_meta::BlendMode::ALL
            .iter()
            .filter(|m| **m != weft_meta::BlendMode::Opaque)
            .map(|m| m.name())
            .collect();
        let found = weft_meta::BlendMode::ALL
            .into_iter()
            .find(|m| m.name() == name && *m != weft_meta::BlendMode::Opaque);
        if found.is_none() {
            cx.error_with_note(
                "unknown-value",
                format!("`blend = \"{name}\"` is not a blend mode an instance may set"),
                t.span_of("blend"),
                "not one of the blend modes",
                suggestion_listing(&name, &modes, "blend modes"),
            );
        }
        found
    });
    PassOverrides {
        double_sided,
        blend,
    }
}

/// `tier`, with `error_budget` and `screen_size` for `auto` (and only then).
fn parse_tier(t: &Table, cx: &mut Cx) -> Spanned<TierRequest> {
    let span = t.span_of("tier");
    let tier = t.string("tier", cx);
    let budget = t.number("error_budget", cx);
    let size = t.integer("screen_size", cx);
    if tier.as_deref() != Some(AUTO_TIER) {
        for key in ["error_budget", "screen_size"] {
            if let Some(key_span) = t.key_span(key) {
                cx.error_with_note(
                    "unknown-key",
                    format!("`{key}` only applies to `tier = \"{AUTO_TIER}\"`"),
                    key_span,
                    "not used with this tier",
                    format!(
                        "write `tier = \"{AUTO_TIER}\"` to let the build choose the tier, or remove `{key}`"
                    ),
                );
            }
        }
        let value = tier.map_or(TierRequest::Default, TierRequest::Named);
        return Spanned { value, span };
    }
    let missing = |cx: &mut Cx, key: &str, note: &str| {
        cx.error_with_note(
            "missing-key",
            format!("`tier = \"{AUTO_TIER}\"` needs `{key}` in {}", t.what),
            span.clone(),
            format!("`{key}` missing"),
            note,
        );
    };
    if t.get("error_budget").is_none() {
        missing(
            cx,
            "error_budget",
            "the largest mean FLIP error against the reference tier the instance may show, in (0, 1], e.g. `error_budget = 0.05`",
        );
    }
    if t.get("screen_size").is_none() {
        missing(
            cx,
            "screen_size",
            "the instance's size on screen in pixels (16 to 4096), e.g. `screen_size = 256`",
        );
    }
    let budget = budget.filter(|b| {
        let ok = *b > 0.0 && *b <= 1.0;
        if !ok {
            cx.error_with_note(
                "out-of-range",
                format!("`error_budget` of {} must be in (0, 1]", t.what),
                t.span_of("error_budget"),
                format!("{b} is not in (0, 1]"),
                "a mean FLIP error: 0 would allow no difference at all, 1 any",
            );
        }
        ok
    });
    let size = size.filter(|s| {
        let ok = SCREEN_SIZE_RANGE.contains(s);
        if !ok {
            cx.error(
                "out-of-range",
                format!(
                    "`screen_size` of {} must be between {} and {} pixels",
                    t.what,
                    SCREEN_SIZE_RANGE.start(),
                    SCREEN_SIZE_RANGE.end()
                ),
                t.span_of("screen_size"),
                format!("{s} is outside that range"),
            );
        }
        ok
    });
    let value = match (budget, size) {
        (Some(error_budget), Some(size)) => TierRequest::Auto {
            error_budget,
            screen_size: size as u32,
        },
        // Already reported; the scene does not resolve.
        _ => TierRequest::Default,
    };
    Spanned { value, span }
}

/// `keywords = { NAME = "value" }`; `true`/`false` read as `on`/`off`, as in presets.
fn parse_keywords(t: &Table, cx: &mut Cx) -> Vec<(Spanned<String>, Spanned<String>)> {
    let Some(table) = t
        .get("keywords")
        .and_then(|v| Table::new(v, format!("`keywords` of {}", t.what), cx))
    else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for (name, name_span, v) in table.entries() {
        let value = match v.get_ref() {
            DeValue::String(s) => s.to_string(),
            DeValue::Boolean(b) => if *b { "on" } else { "off" }.to_string(),
            other => {
                type_error(
                    cx,
                    &format!("keyword `{name}` of {}", t.what),
                    "a value name (or true/false for a toggle)",
                    other,
                    v.span(),
                );
                continue;
            }
        };
        out.push((
            Spanned {
                value: name.to_string(),
                span: name_span,
            },
            Spanned {
                value,
                span: v.span(),
            },
        ));
    }
    out
}

fn written_params<'a, 'i>(t: &Table<'a, 'i>, cx: &mut Cx) -> Vec<WrittenParam<'a, 'i>> {
    t.get("params")
        .and_then(|v| Table::new(v, format!("`params` of {}", t.what), cx))
        .map(|table| {
            table
                .entries()
                .map(|(name, name_span, value)| WrittenParam {
                    name,
                    name_span,
                    value,
                })
                .collect()
        })
        .unwrap_or_default()
}

/// `dynamic`, each name once.
fn parse_dynamic(t: &Table, cx: &mut Cx) -> Vec<Spanned<String>> {
    let mut out: Vec<Spanned<String>> = Vec::new();
    for (value, span) in t.strings("dynamic", cx).unwrap_or_default() {
        if let Some(first) = out.iter().find(|d| d.value == value) {
            let first = first.span.clone();
            let d = cx.diags.error(
                "duplicate",
                format!("`{value}` is listed twice in `dynamic` of {}", t.what),
                cx.file,
                span,
                "again here",
            );
            d.labels
                .push(Label::secondary(cx.file, first).with_message("first listed here"));
            continue;
        }
        out.push(Spanned { value, span });
    }
    out
}

fn parse_mesh(t: &Table, at: &Span, cx: &mut Cx) -> Option<Spanned<MeshSpec>> {
    let names = BuiltinMesh::ALL.map(BuiltinMesh::name);
    let note = format!(
        "built-in meshes: {}; or a glTF mesh: `mesh = {{ gltf = \"x.glb\", mesh = 0, primitive = 0 }}`",
        names.join(", ")
    );
    if let Some(v) = t.get("mesh")
        && matches!(v.get_ref(), DeValue::Table(_))
    {
        let table = Table::new(v, "`mesh`", cx)?;
        table.check_keys(GLTF_MESH_KEYS, cx);
        let file = required_string(&table, "gltf", &v.span(), &note, cx)?;
        let index = |key: &str, cx: &mut Cx| -> Option<usize> {
            let n = table.integer(key, cx).unwrap_or(0);
            match usize::try_from(n) {
                Ok(n) => Some(n),
                Err(_) => {
                    cx.error(
                        "out-of-range",
                        format!("`{key}` of `mesh` must be ≥ 0"),
                        table.span_of(key),
                        "an index into the glTF file",
                    );
                    None
                }
            }
        };
        let mesh = index("mesh", cx)?;
        let primitive = index("primitive", cx)?;
        return Some(Spanned {
            value: MeshSpec::Gltf {
                file: PathBuf::from(file.value),
                mesh,
                primitive,
            },
            span: v.span(),
        });
    }
    let name = required_string(t, "mesh", at, &note, cx)?;
    match BuiltinMesh::from_name(&name.value) {
        Some(value) => Some(Spanned {
            value: MeshSpec::Builtin(value),
            span: name.span,
        }),
        None => {
            cx.error_with_note(
                "unknown-mesh",
                format!("unknown mesh `{}`", name.value),
                name.span,
                "not a built-in mesh",
                suggestion_listing(&name.value, &names, "built-in meshes"),
            );
            None
        }
    }
}

/// `variant = { name = "…", replaces = "…" }`.
fn parse_variant(t: &Table, cx: &mut Cx) -> Option<Spanned<InstanceVariant>> {
    let v = t.get("variant")?;
    let table = Table::new(v, "`variant`", cx)?;
    table.check_keys(VARIANT_KEYS, cx);
    let note = "a material variant's instance: `variant = { name = \"<variant>\", replaces = \"<instance>\" }`";
    let name = required_string(&table, "name", &v.span(), note, cx)?;
    let replaces = required_string(&table, "replaces", &v.span(), note, cx)?;
    Some(Spanned {
        value: InstanceVariant {
            name: name.value,
            replaces: replaces.value,
        },
        span: v.span(),
    })
}

/// `matrix = [16 numbers]`: object -> world, column-major.
fn parse_matrix(t: &Table, cx: &mut Cx) -> Option<[f64; 16]> {
    let span = t.span_of("matrix");
    let numbers = t.numbers("matrix", cx)?;
    if numbers.len() != 16 || !numbers.iter().all(|x| fits_f32(*x)) {
        cx.error(
            "bad-type",
            format!(
                "`matrix` of {} must be 16 finite numbers (column-major)",
                t.what
            ),
            span,
            "object -> world, columns x, y, z, translation",
        );
        return None;
    }
    Some(std::array::from_fn(|i| numbers[i]))
}

fn parse_transform(t: &Table, cx: &mut Cx) -> Transform {
    let mut transform = Transform::default();
    if t.get("matrix").is_some() {
        if let Some(key) = ["translation", "rotation", "scale"]
            .into_iter()
            .find(|k| t.get(k).is_some())
        {
            cx.error(
                "conflicting-keys",
                format!("{} has both `matrix` and `{key}`", t.what),
                t.span_of(key),
                "give either `matrix` or translation / rotation / scale",
            );
        }
        transform.matrix = parse_matrix(t, cx);
        return transform;
    }
    transform.translation = vec3(t, "translation", cx).unwrap_or(transform.translation);
    transform.rotation_degrees = vec3(t, "rotation", cx).unwrap_or(transform.rotation_degrees);
    let scale = match t.get("scale").map(|v| v.get_ref()) {
        None => None,
        Some(DeValue::Array(_)) => vec3(t, "scale", cx),
        Some(DeValue::Integer(_) | DeValue::Float(_)) => match t.number("scale", cx) {
            Some(s) if !fits_f32(s) => {
                f32_range_error("scale", t, t.span_of("scale"), cx);
                None
            }
            s => s.map(|s| [s; 3]),
        },
        Some(other) => {
            type_error(
                cx,
                &format!("`scale` of {}", t.what),
                "a number or 3 numbers [x, y, z]",
                other,
                t.span_of("scale"),
            );
            None
        }
    };
    if let Some(scale) = scale {
        if scale.iter().all(|s| *s > 0.0) {
            transform.scale = scale;
        } else {
            cx.error(
                "out-of-range",
                format!("`scale` of {} must be positive", t.what),
                t.span_of("scale"),
                "every component must be > 0",
            );
        }
    }
    transform
}

fn check_unique_names(names: &[Spanned<String>], cx: &mut Cx) {
    for (i, name) in names.iter().enumerate() {
        let Some(first) = names.iter().take(i).find(|x| x.value == name.value) else {
            continue;
        };
        let d = cx.diags.error(
            "duplicate",
            format!("two instances are named `{}`", name.value),
            cx.file,
            name.span.clone(),
            "second instance with this name",
        );
        d.labels
            .push(Label::secondary(cx.file, first.span.clone()).with_message("first one here"));
        d.notes.push(
            "instance names are unique in a scene: they name the instance in the scene metadata"
                .into(),
        );
    }
}
