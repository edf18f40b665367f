//! Material TOML -> [`Material`], checking each table's keys, types and local
//! rules (default inside range, min <= max, known enum values) as it goes.
//! Cross-references (show-if targets, groups, presets, budget) are checked
//! afterwards in `check.rs`.
//!
//! This module holds the format's key lists, [`parse_material`] (the file and
//! its `[material]`, `[groups]` and `[variants]` tables) and the helpers the
//! table readers share; each kind of table has its own submodule.

mod keywords;
mod limits;
mod params;
mod pass_files;
mod passes;
mod presets;
mod tables;

use crate::check::Sites;
use crate::condition::parse_condition_text;
use crate::diag::{FileId, Span};
use crate::model::*;
use crate::toml_reader::{Cx, Table, Value, expect_array, expect_string};
use std::path::Path;
use toml::de::{DeTable, DeValue};

pub const TOP_KEYS: &[&str] = &[
    "material", "groups", "params", "keywords", "tier", "variants", "presets", "pass", "limits",
    "tables",
];
/// Keys of a `[tables.<name>]` entry: the common ones (`recipe`, `size`) first,
/// then every recipe's own.
pub const TABLE_KEYS: &[&str] = &["recipe", "size", "shape", "ring", "opd_max"];
pub const MATERIAL_KEYS: &[&str] = &[
    "name",
    "label",
    "label_zh",
    "description",
    "description_zh",
    "source",
    "includes",
    "requires",
    "stylised",
];
pub const GROUP_KEYS: &[&str] = &["label", "label_zh"];
pub const PARAM_KEYS: &[&str] = &[
    "type",
    "default",
    "file",
    "range",
    "soft_range",
    "step",
    "power",
    "label",
    "label_zh",
    "tooltip",
    "tooltip_zh",
    "group",
    "order",
    "show_if",
    "default_when",
    "hdr",
    "srgb",
    "tiling",
    "samples",
    "width",
];
pub const KEYWORD_KEYS: &[&str] = &[
    "type",
    "values",
    "default",
    "mode",
    "label",
    "label_zh",
    "tooltip",
    "tooltip_zh",
    "group",
    "show_if",
];
/// Keys of one entry of a texture parameter's `default_when` array.
pub const DEFAULT_WHEN_KEYS: &[&str] = &["if", "default"];
pub const TIER_KEYS: &[&str] = &[
    "name",
    "description",
    "description_zh",
    "default",
    "approximates",
    "look",
];
pub const VARIANTS_KEYS: &[&str] = &["max_variants", "exclude"];
pub const PRESET_KEYS: &[&str] = &["label", "label_zh", "values"];
pub const PASS_KEYS: &[&str] = &[
    "name",
    "vertex",
    "fragment",
    "blend",
    "cull",
    "depth_write",
    "depth_test",
    "queue",
    "instances",
    "when",
    "stencil",
    "include",
];
/// Top-level tables of a shared pass file (`lib/<name>.pass.toml`).
pub const PASS_FILE_TOP_KEYS: &[&str] = &["pass", "groups", "params", "keywords"];
/// Keys of a shared pass file's `[pass]`: a `[[pass]]`'s, with the WGSL
/// `source` it brings instead of `include`.
pub const PASS_FILE_PASS_KEYS: &[&str] = &[
    "name",
    "vertex",
    "fragment",
    "blend",
    "cull",
    "depth_write",
    "depth_test",
    "queue",
    "instances",
    "when",
    "stencil",
    "source",
];
/// Keys of a pass's `stencil` table (docs/material-format.md, "Stencil").
pub const STENCIL_KEYS: &[&str] = &[
    "reference",
    "compare",
    "pass_op",
    "fail_op",
    "depth_fail_op",
    "read_mask",
    "write_mask",
];
/// Keys of `[limits]`: WebGPU's limits in snake_case (`weft_meta::limits::LIMITS`).
pub const LIMITS_KEYS: &[&str] = &[
    "max_bind_groups",
    "max_bindings_per_bind_group",
    "max_uniform_buffer_binding_size",
    "max_uniform_buffers_per_shader_stage",
    "max_sampled_textures_per_shader_stage",
    "max_samplers_per_shader_stage",
    "max_vertex_attributes",
    "max_inter_stage_shader_variables",
];
pub use crate::values::{KEYFRAME_KEYS, STOP_KEYS};
pub use tables::{RECIPES, RINGS};

/// Default budget when a material sets no `max_variants`.
pub const DEFAULT_MAX_VARIANTS: usize = 64;

/// Parses a material file. `None` when the TOML itself does not parse or a
/// required part is missing; every problem found is in `cx.diags`.
/// `pass_files` are the shared pass files its `[[pass]] include`s name, read
/// beforehand ([`pass_include_entries`]): (path as written, file, text).
pub fn parse_material(
    text: &str,
    path: &Path,
    root: &Path,
    pass_files: &[(String, FileId, String)],
    cx: &mut Cx,
) -> Option<Material> {
    let doc = match DeTable::parse(text) {
        Ok(doc) => doc,
        Err(e) => {
            let span = e.span().unwrap_or(0..0);
            cx.error_with_note(
                "toml-syntax",
                format!("invalid TOML: {}", e.message().trim()),
                span,
                "here",
                "see docs/material-format.md for the file format",
            );
            return None;
        }
    };
    let top = Table {
        map: doc.get_ref(),
        span: 0..0,
        what: "the material file".into(),
    };
    top.check_keys(TOP_KEYS, cx);

    let mut material = new_material(&top, path, root, cx)?;

    let mut sites = Sites::default();
    parse_declarations(&top, &mut material, &mut sites, cx);
    sites.material_declares_groups = !material.groups.is_empty();
    // Shared passes bring their own groups, parameters and keywords: read
    // them before the presets, which may set them.
    let included = pass_files::parse_included(&top, pass_files, &mut material, &mut sites, cx);

    keywords::parse_tiers(&top, &mut material, cx);
    limits::parse_limits(&top, &mut material, cx);
    tables::parse_tables(&top, &mut material, cx);

    parse_variants(&top, &mut material, cx);
    parse_presets(&top, &mut material, &mut sites, cx);
    parse_passes(&top, &included, &mut material, &mut sites, cx);

    // Cross-references, while the spans of what the file wrote are at hand.
    // The WGSL source is resolved afterwards by `includes.rs`.
    crate::check::check_references(&mut material, &sites, cx.diags);
    Some(material)
}

/// The material from its `[material]` table (name, labels, vertex inputs,
/// `stylised`), every list still empty; `None` when the table is missing
/// or is not a table.
fn new_material(top: &Table, path: &Path, root: &Path, cx: &mut Cx) -> Option<Material> {
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let Some(mat_v) = top.get("material") else {
        cx.error_with_note(
            "missing-key",
            "missing [material] table",
            0..0,
            "the file starts here",
            "add a [material] table with at least `source = \"<file>.wgsl\"`",
        );
        return None;
    };
    let mat = Table::new(mat_v, "[material]", cx)?;
    mat.check_keys(MATERIAL_KEYS, cx);
    let name = mat.string("name", cx).unwrap_or(stem);
    if !is_snake_ident(&name) {
        cx.error_with_note(
            "bad-name",
            format!("material name `{name}` is not a lower-case identifier"),
            mat.span_of("name"),
            "used as a folder name and in WGSL",
            "use lower_snake_case letters, digits and underscores",
        );
    }
    let label = mat.string("label", cx).unwrap_or_else(|| name.clone());
    let decl = Loc {
        file: cx.file,
        span: mat.key_span("name").unwrap_or_else(|| mat.span.clone()),
    };

    let requires = parse_vertex_inputs(&mat, "requires", cx).unwrap_or_else(|| {
        vec![
            VertexAttribute::Position,
            VertexAttribute::Normal,
            VertexAttribute::Uv0,
        ]
    });

    Some(Material {
        label,
        label_zh: mat.string("label_zh", cx),
        description: mat.string("description", cx),
        description_zh: mat.string("description_zh", cx),
        file: cx.file,
        path: path.to_path_buf(),
        root: root.to_path_buf(),
        sources: Vec::new(),
        requires,
        requires_span: mat.span_of("requires"),
        groups: Vec::new(),
        params: Vec::new(),
        keywords: Vec::new(),
        tiers: Tiers {
            values: Vec::new(),
            default: 0,
            reference: 0,
            descriptions: Vec::new(),
            approximates: Vec::new(),
            looks: Vec::new(),
        },
        stylised: mat.boolean("stylised", cx) == Some(true),
        max_variants: DEFAULT_MAX_VARIANTS,
        max_variants_span: None,
        exclude: Vec::new(),
        exclude_spans: Vec::new(),
        presets: Vec::new(),
        passes: Vec::new(),
        pass_files: Vec::new(),
        pass_sources: Vec::new(),
        tables: Vec::new(),
        limits: weft_meta::DeviceLimits::default(),
        limit_spans: Vec::new(),
        decl,
        name,
    })
}

/// `[variants]`: the budget (`max_variants`) and the `exclude` conditions.
fn parse_variants(top: &Table, material: &mut Material, cx: &mut Cx) {
    if let Some(v) = top
        .get("variants")
        .and_then(|v| Table::new(v, "[variants]", cx))
    {
        v.check_keys(VARIANTS_KEYS, cx);
        if let Some(n) = v.integer("max_variants", cx) {
            if n < 1 {
                cx.error(
                    "out-of-range",
                    "`max_variants` must be at least 1",
                    v.span_of("max_variants"),
                    "here",
                );
            } else {
                material.max_variants = n as usize;
                material.max_variants_span = Some(v.span_of("max_variants"));
            }
        }
        if let Some(list) = v.strings("exclude", cx) {
            for (text, span) in list {
                match parse_condition_text(&text) {
                    Ok(conds) => {
                        material.exclude.push(conds);
                        material.exclude_spans.push(span);
                    }
                    Err(msg) => bad_condition(cx, &msg, span),
                }
            }
        }
    }
}

/// `[presets]`, with the spans of each preset's values for the checks.
fn parse_presets(top: &Table, material: &mut Material, sites: &mut Sites, cx: &mut Cx) {
    if let Some(p) = top
        .get("presets")
        .and_then(|v| Table::new(v, "[presets]", cx))
    {
        for (name, span, pv) in p.entries() {
            if let Some(DeValue::Table(values)) = value_of(pv, "values").map(|v| v.get_ref()) {
                for (key, value) in values.iter() {
                    sites.preset_values.insert(
                        (name.to_string(), key.get_ref().to_string()),
                        (key.span(), value.span()),
                    );
                }
            }
            if let Some(preset) = presets::parse_preset(name, span, pv, &material.params, cx) {
                material.presets.push(preset);
            }
        }
    }
}

/// `[[pass]]`: each entry parsed, or the shared pass it includes (already
/// read into `included`); no `[[pass]]` at all: the default pass.
fn parse_passes(
    top: &Table,
    included: &pass_files::IncludedPasses,
    material: &mut Material,
    sites: &mut Sites,
    cx: &mut Cx,
) {
    match top.get("pass") {
        Some(v) => {
            if let Some(items) = expect_array(v, "`pass`", cx) {
                for (i, item) in items.iter().enumerate() {
                    if let Some((pass, instances)) = included.get(&i) {
                        material.passes.push(pass.clone());
                        sites.instances.push(instances.clone());
                    } else if value_of(item, "include").is_some() {
                        // A shared pass that could not be read: reported already.
                    } else if let Some(pass) = passes::parse_pass(item, PASS_KEYS, "a [[pass]]", cx)
                    {
                        material.passes.push(pass);
                        sites.instances.push(value_span(item, "instances"));
                    }
                }
            }
        }
        None => material
            .passes
            .push(passes::default_pass(cx.file, material.decl.span.clone())),
    }
}

/// The `[groups]`, `[params]` and `[keywords]` of a material file or of a
/// shared pass file (`cx.file`), appended to `material`.
fn parse_declarations(top: &Table, material: &mut Material, sites: &mut Sites, cx: &mut Cx) {
    if let Some(g) = top
        .get("groups")
        .and_then(|v| Table::new(v, "[groups]", cx))
    {
        for (gname, gspan, gv) in g.entries() {
            let Some(t) = Table::new(gv, format!("group `{gname}`"), cx) else {
                continue;
            };
            t.check_keys(GROUP_KEYS, cx);
            let _ = gspan;
            material.groups.push(Group {
                name: gname.to_string(),
                label: t.string("label", cx).unwrap_or_else(|| gname.to_string()),
                label_zh: t.string("label_zh", cx),
            });
        }
    }

    if let Some(p) = top
        .get("params")
        .and_then(|v| Table::new(v, "[params]", cx))
    {
        for (pname, pspan, pv) in p.entries() {
            if let Some(span) = value_span(pv, "show_if") {
                sites.param_show_if.insert(pname.to_string(), span);
            }
            if let Some(span) = value_span(pv, "group") {
                sites.param_group.insert(pname.to_string(), span);
            }
            if let Some(param) = params::parse_param(pname, pspan, pv, sites, cx) {
                material.params.push(param);
            }
        }
    }

    if let Some(k) = top
        .get("keywords")
        .and_then(|v| Table::new(v, "[keywords]", cx))
    {
        for (kname, kspan, kv) in k.entries() {
            if let Some(span) = value_span(kv, "show_if") {
                sites.keyword_show_if.insert(kname.to_string(), span);
            }
            if let Some(span) = value_span(kv, "group") {
                sites.keyword_group.insert(kname.to_string(), span);
            }
            if let Some(kw) = keywords::parse_keyword(kname, kspan, kv, cx) {
                material.keywords.push(kw);
            }
        }
    }
}

/// `key` of a TOML table value, if it is a table that has it.
fn value_of<'a, 'i>(table: &'a Value<'i>, key: &str) -> Option<&'a Value<'i>> {
    match table.get_ref() {
        DeValue::Table(t) => t.get(key),
        _ => None,
    }
}

fn value_span(table: &Value, key: &str) -> Option<Span> {
    value_of(table, key).map(|v| v.span())
}

/// A string value and where it is written.
pub type NamedSpan = (String, Span);

/// The `source` and `includes` entries of `[material]`, with spans, for `includes.rs`.
pub fn source_entries(text: &str) -> (Option<NamedSpan>, Vec<NamedSpan>) {
    let Ok(doc) = DeTable::parse(text) else {
        return (None, Vec::new());
    };
    let Some(DeValue::Table(mat)) = doc.get_ref().get("material").map(|v| v.get_ref()) else {
        return (None, Vec::new());
    };
    let source = mat.get("source").and_then(|v| match v.get_ref() {
        DeValue::String(s) => Some((s.to_string(), v.span())),
        _ => None,
    });
    let includes = match mat.get("includes").map(|v| v.get_ref()) {
        Some(DeValue::Array(items)) => items
            .iter()
            .filter_map(|v| match v.get_ref() {
                DeValue::String(s) => Some((s.to_string(), v.span())),
                _ => None,
            })
            .collect(),
        _ => Vec::new(),
    };
    (source, includes)
}

/// The `include` of every `[[pass]]` that has one, with its span, for
/// `lib.rs` to read before parsing.
pub fn pass_include_entries(text: &str) -> Vec<NamedSpan> {
    let Ok(doc) = DeTable::parse(text) else {
        return Vec::new();
    };
    let Some(DeValue::Array(items)) = doc.get_ref().get("pass").map(|v| v.get_ref()) else {
        return Vec::new();
    };
    items
        .iter()
        .filter_map(
            |item| match value_of(item, "include").map(|v| (v.get_ref(), v.span())) {
                Some((DeValue::String(s), span)) => Some((s.to_string(), span)),
                _ => None,
            },
        )
        .collect()
}

/// A lower_snake identifier that survives naga's writers unchanged: they
/// append `_` to names ending in a digit (`color_1` -> `color_1_`), which
/// would make the metadata disagree with the emitted code.
pub fn is_snake_ident(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some('a'..='z'))
        && chars.all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
        && !s.ends_with(|c: char| c.is_ascii_digit())
}

/// An UPPER_SNAKE identifier, with the same trailing-digit rule.
pub fn is_upper_ident(s: &str) -> bool {
    let mut chars = s.chars();
    matches!(chars.next(), Some('A'..='Z'))
        && chars.all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_')
        && !s.ends_with(|c: char| c.is_ascii_digit())
}

/// A table's `show_if`: exactly one condition.
fn parse_show_if(t: &Table, cx: &mut Cx) -> Option<weft_meta::Condition> {
    let v = t.get("show_if")?;
    parse_one_condition(v, "show_if", CONDITION_FORMS, cx)
}

/// What [`bad_condition`] suggests writing.
const CONDITION_FORMS: &str = "write `KEYWORD`, `!KEYWORD`, `KEYWORD == value`, `tier == fast` or a bool parameter, joined with &&";

/// A string holding exactly one condition (`show_if`, a `default_when`
/// entry's `if`); `key` names it in messages, `forms` is the hint on errors.
fn parse_one_condition(
    v: &Value,
    key: &str,
    forms: &str,
    cx: &mut Cx,
) -> Option<weft_meta::Condition> {
    let text = expect_string(v, &format!("`{key}`"), cx)?;
    match parse_condition_text(&text) {
        Ok(mut c) if c.len() == 1 => c.pop(),
        Ok(_) => {
            bad_condition_with(cx, &format!("{key} takes one condition"), v.span(), forms);
            None
        }
        Err(msg) => {
            bad_condition_with(cx, &msg, v.span(), forms);
            None
        }
    }
}

fn bad_condition(cx: &mut Cx, msg: &str, span: Span) {
    bad_condition_with(cx, msg, span, CONDITION_FORMS);
}

fn bad_condition_with(cx: &mut Cx, msg: &str, span: Span, forms: &str) {
    cx.error_with_note(
        "bad-condition",
        format!("cannot read condition: {msg}"),
        span,
        "here",
        forms,
    );
}

/// A list of vertex input names (`requires`, a scene's `vertex_inputs`):
/// sorted, duplicates and unknown names reported. `None` when `key` is absent.
pub fn parse_vertex_inputs(t: &Table, key: &str, cx: &mut Cx) -> Option<Vec<VertexAttribute>> {
    let list = t.strings(key, cx)?;
    let mut out = Vec::new();
    for (name, span) in list {
        match VertexAttribute::ALL.iter().find(|a| a.name() == name) {
            Some(a) if !out.contains(a) => out.push(*a),
            Some(_) => cx.error(
                "duplicate",
                format!("`{name}` is listed twice"),
                span,
                "again here",
            ),
            None => {
                let names: Vec<&str> = VertexAttribute::ALL.iter().map(|a| a.name()).collect();
                let hint = crate::diag::did_you_mean(&name, names.iter().copied()).map_or_else(
                    || format!("expected one of: {}", names.join(", ")),
                    |s| format!("did you mean `{s}`?"),
                );
                cx.error_with_note(
                    "unknown-value",
                    format!("unknown vertex input `{name}`"),
                    span,
                    "not a vertex input",
                    hint,
                );
            }
        }
    }
    out.sort();
    Some(out)
}
