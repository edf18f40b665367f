//! Material TOML -> [`Material`], checking each table's keys, types and local
//! rules (default inside range, min <= max, known enum values) as it goes.
//! Cross-references (show-if targets, groups, presets, budget) are checked
//! afterwards in `check.rs`.

use crate::check::Sites;
use crate::condition::parse_condition_text;
use crate::diag::Span;
use crate::model::*;
use crate::toml_reader::{
    Cx, Table, Value, expect_array, expect_number, expect_string, type_error,
};
use crate::values;
use std::path::Path;
use toml::de::{DeTable, DeValue};
use weft_meta::{
    BlendMode, CullMode, DepthTest, KeywordKind, KeywordMode, ParamKind, TextureDefault,
};

pub const TOP_KEYS: &[&str] = &[
    "material", "groups", "params", "keywords", "tier", "variants", "presets", "pass",
];
pub const MATERIAL_KEYS: &[&str] = &[
    "name",
    "label",
    "label_zh",
    "description",
    "description_zh",
    "source",
    "includes",
    "requires",
];
pub const GROUP_KEYS: &[&str] = &["label", "label_zh"];
pub const PARAM_KEYS: &[&str] = &[
    "type",
    "default",
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
pub const TIER_KEYS: &[&str] = &["name", "description", "description_zh", "default"];
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
];
pub use crate::values::{KEYFRAME_KEYS, STOP_KEYS};

/// Default budget when a material sets no `max_variants`.
pub const DEFAULT_MAX_VARIANTS: usize = 64;

/// Parses a material file. `None` when the TOML itself does not parse or a
/// required part is missing; every problem found is in `cx.diags`.
pub fn parse_material(text: &str, path: &Path, root: &Path, cx: &mut Cx) -> Option<Material> {
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

    let mut material = Material {
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
        },
        max_variants: DEFAULT_MAX_VARIANTS,
        max_variants_span: None,
        exclude: Vec::new(),
        exclude_spans: Vec::new(),
        presets: Vec::new(),
        passes: Vec::new(),
        decl,
        name,
    };

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

    let mut sites = Sites::default();
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
            if let Some(param) = parse_param(pname, pspan, pv, cx) {
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
            if let Some(kw) = parse_keyword(kname, kspan, kv, cx) {
                material.keywords.push(kw);
            }
        }
    }

    parse_tiers(&top, &mut material, cx);

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
            if let Some(preset) = parse_preset(name, span, pv, &material.params, cx) {
                material.presets.push(preset);
            }
        }
    }

    match top.get("pass") {
        Some(v) => {
            if let Some(items) = expect_array(v, "`pass`", cx) {
                for item in items {
                    if let Some(pass) = parse_pass(item, cx) {
                        material.passes.push(pass);
                        sites.instances.push(value_span(item, "instances"));
                    }
                }
            }
        }
        None => material
            .passes
            .push(default_pass(cx.file, material.decl.span.clone())),
    }

    // Cross-references, while the spans of what the file wrote are at hand.
    // The WGSL source is resolved afterwards by `includes.rs`.
    crate::check::check_references(&mut material, &sites, cx.diags);
    Some(material)
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

/// The `source` and `includes` entries of [material], with spans, for `includes.rs`.
/// A string value and where it is written.
pub type NamedSpan = (String, Span);

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
    let text = expect_string(v, "`show_if`", cx)?;
    match parse_condition_text(&text) {
        Ok(mut c) if c.len() == 1 => c.pop(),
        Ok(_) => {
            bad_condition(cx, "show_if takes one condition", v.span());
            None
        }
        Err(msg) => {
            bad_condition(cx, &msg, v.span());
            None
        }
    }
}

fn bad_condition(cx: &mut Cx, msg: &str, span: Span) {
    cx.error_with_note(
        "bad-condition",
        format!("cannot read condition: {msg}"),
        span,
        "here",
        "write `KEYWORD`, `!KEYWORD`, `KEYWORD == value`, `tier == fast` or a bool parameter, joined with &&",
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

fn parse_kind(t: &Table, cx: &mut Cx) -> Option<ParamKind> {
    let Some(v) = t.get("type") else {
        cx.error_with_note(
            "missing-key",
            format!("{} has no `type`", t.what),
            t.span.clone(),
            "declared here",
            format!(
                "add `type = \"...\"`, one of: {}",
                ParamKind::ALL.map(|k| k.name()).join(", ")
            ),
        );
        return None;
    };
    let name = expect_string(v, &format!("`type` of {}", t.what), cx)?;
    match ParamKind::ALL.iter().find(|k| k.name() == name) {
        Some(k) => Some(*k),
        None => {
            let names = ParamKind::ALL.map(|k| k.name());
            let hint = crate::diag::did_you_mean(&name, names.iter().copied()).map_or_else(
                || format!("expected one of: {}", names.join(", ")),
                |s| format!("did you mean `{s}`?"),
            );
            cx.error_with_note(
                "unknown-value",
                format!("unknown parameter type `{name}`"),
                v.span(),
                "unknown type",
                hint,
            );
            None
        }
    }
}

fn parse_param(name: &str, name_span: Span, v: &Value, cx: &mut Cx) -> Option<Param> {
    let t = Table::new(v, format!("parameter `{name}`"), cx)?;
    t.check_keys(PARAM_KEYS, cx);
    if !is_snake_ident(name) {
        cx.error_with_note(
            "bad-name",
            format!("parameter name `{name}` is not a lower-case identifier"),
            name_span.clone(),
            "becomes a WGSL struct member",
            "use lower_snake_case that does not end in a digit (naga's writers rename such names)",
        );
    }
    let kind = parse_kind(&t, cx)?;

    // Keys that only make sense for some kinds.
    let only_for: &[(&str, &[ParamKind])] = &[
        ("hdr", &[ParamKind::Color]),
        ("srgb", &[ParamKind::Texture2d, ParamKind::Cube]),
        ("tiling", &[ParamKind::Texture2d]),
        ("samples", &[ParamKind::Curve]),
        ("width", &[ParamKind::Gradient]),
        ("power", &[ParamKind::Float]),
    ];
    for (key, kinds) in only_for {
        if t.get(key).is_some() && !kinds.contains(&kind) {
            cx.error_with_note(
                "unknown-key",
                format!("`{key}` does not apply to a {} parameter", kind.name()),
                t.key_span(key).unwrap_or(t.span.clone()),
                "not used for this type",
                format!(
                    "`{key}` is for: {}",
                    kinds
                        .iter()
                        .map(|k| k.name())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            );
        }
    }

    let hdr = t.boolean("hdr", cx).unwrap_or(false);
    let numeric = kind.components().is_some() && kind != ParamKind::Bool;
    let mut range = t.range("range", cx);
    if range.is_some() && !numeric && kind != ParamKind::Curve {
        cx.error(
            "unknown-key",
            format!("`range` does not apply to a {} parameter", kind.name()),
            t.key_span("range").unwrap_or(t.span.clone()),
            "not used for this type",
        );
        range = None;
    }
    if kind == ParamKind::Color && range.is_none() && !hdr {
        range = Some([0.0, 1.0]);
    }
    let soft_range = t.range("soft_range", cx);
    if let (Some(soft), Some(hard)) = (soft_range, range)
        && (soft[0] < hard[0] || soft[1] > hard[1])
    {
        cx.error(
            "out-of-range",
            format!(
                "`soft_range` of parameter `{name}` is outside its `range` [{}, {}]",
                hard[0], hard[1]
            ),
            t.span_of("soft_range"),
            "must lie inside range",
        );
    }
    let step = t.number("step", cx);
    if let Some(s) = step
        && s <= 0.0
    {
        cx.error(
            "out-of-range",
            "`step` must be positive",
            t.span_of("step"),
            "here",
        );
    }
    let power = t.number("power", cx);
    if let Some(p) = power
        && p <= 0.0
    {
        cx.error(
            "out-of-range",
            "`power` must be positive",
            t.span_of("power"),
            "here",
        );
    }
    let samples = match kind {
        ParamKind::Curve => t.integer("samples", cx).unwrap_or(16),
        ParamKind::Gradient => t.integer("width", cx).unwrap_or(256),
        _ => 0,
    };
    if matches!(kind, ParamKind::Curve | ParamKind::Gradient) && !(2..=4096).contains(&samples) {
        let key = if kind == ParamKind::Curve {
            "samples"
        } else {
            "width"
        };
        cx.error(
            "out-of-range",
            format!("`{key}` must be between 2 and 4096"),
            t.span_of(key),
            "here",
        );
    }

    let default = parse_default(&t, kind, range, cx)?;
    let show_if = parse_show_if(&t, cx);

    Some(Param {
        name: name.to_string(),
        kind,
        label: t.string("label", cx).unwrap_or_else(|| humanize(name)),
        label_zh: t.string("label_zh", cx),
        tooltip: t.string("tooltip", cx),
        tooltip_zh: t.string("tooltip_zh", cx),
        group: t.string("group", cx).unwrap_or_else(|| "main".into()),
        order: t.integer("order", cx).unwrap_or(0),
        default,
        range,
        soft_range,
        step,
        power,
        show_if,
        hdr,
        srgb: t.boolean("srgb", cx).unwrap_or(false),
        tiling: t.boolean("tiling", cx).unwrap_or(false),
        samples: samples.clamp(2, 4096) as u32,
        decl: Loc {
            file: cx.file,
            span: name_span,
        },
    })
}

/// "base_color" -> "Base color".
pub fn humanize(name: &str) -> String {
    let s = name.replace('_', " ");
    let mut c = s.chars();
    match c.next() {
        Some(f) => f.to_uppercase().chain(c).collect(),
        None => s,
    }
}

/// The `default` of a parameter table, or the kind's built-in default.
fn parse_default(
    t: &Table,
    kind: ParamKind,
    range: Option<[f64; 2]>,
    cx: &mut Cx,
) -> Option<ParamValue> {
    let Some(v) = t.get("default") else {
        // Sensible defaults so a material renders without any value set.
        return Some(values::builtin_default(kind, range));
    };
    let site = values::Site {
        what: format!("`default` of {}", t.what),
        texture: "texture default",
        range: values::RangeReport::default_of(
            &t.what,
            Loc {
                file: cx.file,
                span: t.span_of("range"),
            },
        ),
    };
    values::parse_value(v, kind, range, &site, cx)
}

fn parse_keyword(name: &str, name_span: Span, v: &Value, cx: &mut Cx) -> Option<Keyword> {
    let t = Table::new(v, format!("keyword `{name}`"), cx)?;
    t.check_keys(KEYWORD_KEYS, cx);
    if !is_upper_ident(name) || name == "WEFT_TIER" || name.starts_with("TIER_") {
        cx.error_with_note(
            "bad-name",
            format!("keyword name `{name}` is not an UPPER_SNAKE identifier (or is reserved)"),
            name_span.clone(),
            "becomes a WGSL override",
            "use UPPER_SNAKE_CASE not ending in a digit; WEFT_TIER and TIER_* are reserved for tiers",
        );
    }
    let kind_name = t.string("type", cx).unwrap_or_else(|| "toggle".into());
    let kind = match kind_name.as_str() {
        "toggle" => KeywordKind::Toggle,
        "enum" => KeywordKind::Enum,
        other => {
            let hint = crate::diag::did_you_mean(other, ["toggle", "enum"])
                .map_or("use `toggle` or `enum`".to_string(), |s| {
                    format!("did you mean `{s}`?")
                });
            cx.error_with_note(
                "unknown-value",
                format!("unknown keyword type `{other}`"),
                t.span_of("type"),
                "unknown",
                hint,
            );
            return None;
        }
    };
    let mode = match t.string("mode", cx).as_deref() {
        None | Some("static") => KeywordMode::Static,
        Some("constant") => KeywordMode::Constant,
        Some(other) => {
            cx.error_with_note(
                "unknown-value",
                format!("unknown keyword mode `{other}`"),
                t.span_of("mode"),
                "unknown",
                "use `static` (a variant per value) or `constant` (a pipeline constant)",
            );
            return None;
        }
    };
    let values: Vec<String> = match kind {
        KeywordKind::Toggle => {
            if t.get("values").is_some() {
                cx.error(
                    "unknown-key",
                    "a toggle keyword has the fixed values off/on",
                    t.key_span("values").unwrap_or(t.span.clone()),
                    "remove `values`, or use type = \"enum\"",
                );
            }
            vec!["off".into(), "on".into()]
        }
        KeywordKind::Enum => {
            let Some(list) = t.strings("values", cx) else {
                cx.error(
                    "missing-key",
                    format!("enum keyword `{name}` needs `values`"),
                    name_span.clone(),
                    "declared here",
                );
                return None;
            };
            let mut out: Vec<String> = Vec::new();
            for (value, span) in list {
                if !is_snake_ident(&value) {
                    cx.error(
                        "bad-name",
                        format!("keyword value `{value}` is not a lower-case identifier"),
                        span,
                        "becomes a WGSL constant suffix",
                    );
                } else if out.contains(&value) {
                    cx.error(
                        "duplicate",
                        format!("keyword value `{value}` is listed twice"),
                        span,
                        "again here",
                    );
                } else {
                    out.push(value);
                }
            }
            if out.len() < 2 {
                cx.error(
                    "wrong-type",
                    format!("enum keyword `{name}` needs at least two values"),
                    t.span_of("values"),
                    "here",
                );
                return None;
            }
            out
        }
    };
    let default = match t.get("default") {
        None => 0,
        Some(dv) => {
            let value = match (kind, dv.get_ref()) {
                (KeywordKind::Toggle, DeValue::Boolean(b)) => {
                    if *b { "on" } else { "off" }.to_string()
                }
                (_, DeValue::String(s)) => s.to_string(),
                (_, other) => {
                    type_error(
                        cx,
                        &format!("`default` of keyword `{name}`"),
                        "a value name (or true/false for a toggle)",
                        other,
                        dv.span(),
                    );
                    return None;
                }
            };
            match values.iter().position(|v| *v == value) {
                Some(i) => i,
                None => {
                    let hint = match crate::diag::did_you_mean(
                        &value,
                        values.iter().map(String::as_str),
                    ) {
                        Some(s) => format!(
                            "did you mean `{s}`? values of `{name}`: {}",
                            values.join(", ")
                        ),
                        None => format!("values of `{name}`: {}", values.join(", ")),
                    };
                    cx.error_with_note(
                        "unknown-value",
                        format!("`{value}` is not a value of keyword `{name}`"),
                        dv.span(),
                        "unknown value",
                        hint,
                    );
                    0
                }
            }
        }
    };
    let show_if = parse_show_if(&t, cx);
    Some(Keyword {
        name: name.to_string(),
        kind,
        mode,
        values,
        default,
        label: t
            .string("label", cx)
            .unwrap_or_else(|| humanize(&name.to_lowercase())),
        label_zh: t.string("label_zh", cx),
        tooltip: t.string("tooltip", cx),
        tooltip_zh: t.string("tooltip_zh", cx),
        group: t.string("group", cx).unwrap_or_else(|| "main".into()),
        show_if,
        decl: Loc {
            file: cx.file,
            span: name_span,
        },
    })
}

fn parse_tiers(top: &Table, material: &mut Material, cx: &mut Cx) {
    let Some(v) = top.get("tier") else {
        cx.error_with_note(
            "missing-key",
            "no quality tiers declared",
            material.decl.span.clone(),
            "material declared here",
            "add [[tier]] tables named `fast` and `reference` (the reference is what other tiers are measured against)",
        );
        return;
    };
    let Some(items) = expect_array(v, "`tier`", cx) else {
        return;
    };
    let mut default = None;
    for item in items {
        let Some(t) = Table::new(item, "a [[tier]]", cx) else {
            continue;
        };
        t.check_keys(TIER_KEYS, cx);
        let Some(name) = t.string("name", cx) else {
            cx.error(
                "missing-key",
                "a [[tier]] needs a `name`",
                item.span(),
                "here",
            );
            continue;
        };
        if !is_snake_ident(&name) {
            cx.error(
                "bad-name",
                format!("tier name `{name}` is not a lower-case identifier"),
                t.span_of("name"),
                "becomes TIER_<NAME> in WGSL",
            );
            continue;
        }
        if material.tiers.values.contains(&name) {
            cx.error(
                "duplicate",
                format!("tier `{name}` is declared twice"),
                t.span_of("name"),
                "again here",
            );
            continue;
        }
        if t.boolean("default", cx) == Some(true) {
            if default.is_some() {
                cx.error(
                    "duplicate",
                    "more than one tier is marked `default = true`",
                    t.span_of("default"),
                    "second default",
                );
            }
            default = Some(material.tiers.values.len());
        }
        material.tiers.descriptions.push((
            name.clone(),
            t.string("description", cx).unwrap_or_default(),
            t.string("description_zh", cx),
        ));
        material.tiers.values.push(name);
    }
    for required in ["fast", "reference"] {
        if !material.tiers.values.iter().any(|t| t == required) {
            cx.error_with_note(
                "missing-tier",
                format!("the `{required}` tier is missing"),
                v.span(),
                "tiers declared here",
                "every material has at least `fast` and `reference` tiers",
            );
        }
    }
    material.tiers.reference = material
        .tiers
        .values
        .iter()
        .position(|t| t == "reference")
        .unwrap_or(0);
    material.tiers.default = default
        .or_else(|| material.tiers.values.iter().position(|t| t == "fast"))
        .unwrap_or(0);
}

fn parse_preset(
    name: &str,
    span: Span,
    v: &Value,
    params: &[Param],
    cx: &mut Cx,
) -> Option<Preset> {
    let t = Table::new(v, format!("preset `{name}`"), cx)?;
    t.check_keys(PRESET_KEYS, cx);
    let mut values = Vec::new();
    if let Some(vals) = t
        .get("values")
        .and_then(|v| Table::new(v, format!("values of preset `{name}`"), cx))
    {
        for (key, _kspan, val) in vals.entries() {
            let pv = match val.get_ref() {
                DeValue::String(s) if is_upper_ident(key) || key == "tier" => {
                    PresetValue::Keyword(s.to_string())
                }
                DeValue::Boolean(b) if is_upper_ident(key) => {
                    PresetValue::Keyword(if *b { "on" } else { "off" }.into())
                }
                DeValue::Boolean(b) => PresetValue::Param(ParamValue::Bool(*b)),
                DeValue::Integer(_) | DeValue::Float(_) => {
                    PresetValue::Param(ParamValue::Float(expect_number(val, "a preset value", cx)?))
                }
                DeValue::String(s) => {
                    let builtin = TextureDefault::ALL
                        .iter()
                        .copied()
                        .find(|d| d.name() == s.as_ref());
                    let texture = params.iter().any(|p| {
                        p.name == key && matches!(p.kind, ParamKind::Texture2d | ParamKind::Cube)
                    });
                    if builtin.is_none() && texture {
                        let names = TextureDefault::ALL.map(|d| d.name());
                        let hint = crate::diag::did_you_mean(s, names.iter().copied()).map_or_else(
                            || format!("use one of: {}", names.join(", ")),
                            |x| format!("did you mean `{x}`?"),
                        );
                        cx.error_with_note(
                            "unknown-value",
                            format!("preset `{name}`: unknown texture `{s}` for `{key}`"),
                            val.span(),
                            "not a built-in texture",
                            hint,
                        );
                        continue;
                    }
                    // A string for a non-texture parameter is reported by the reference checks.
                    PresetValue::Param(ParamValue::Texture(
                        builtin.unwrap_or(TextureDefault::White),
                    ))
                }
                DeValue::Array(_) => {
                    let what = format!("preset value `{key}`");
                    match params.iter().find(|p| p.name == key) {
                        Some(p) if p.kind == ParamKind::Curve => {
                            let report = values::RangeReport::default_of(&what, p.decl.clone());
                            PresetValue::Param(ParamValue::Curve(values::parse_keyframes(
                                val, &what, p.range, &report, cx,
                            )?))
                        }
                        Some(p) if p.kind == ParamKind::Gradient => PresetValue::Param(
                            ParamValue::Gradient(values::parse_stops(val, &what, cx)?),
                        ),
                        _ => PresetValue::Param(ParamValue::Vector(
                            crate::toml_reader::expect_numbers(val, &what, cx)?,
                        )),
                    }
                }
                other => {
                    type_error(
                        cx,
                        &format!("preset value `{key}`"),
                        "a number, bool, string or array",
                        other,
                        val.span(),
                    );
                    continue;
                }
            };
            values.push((key.to_string(), pv));
        }
    }
    Some(Preset {
        name: name.to_string(),
        label: t.string("label", cx).unwrap_or_else(|| humanize(name)),
        label_zh: t.string("label_zh", cx),
        values,
        decl: Loc {
            file: cx.file,
            span,
        },
    })
}

fn default_pass(file: usize, span: Span) -> Pass {
    Pass {
        name: "forward".into(),
        vertex: "vs_main".into(),
        fragment: "fs_main".into(),
        blend: BlendMode::Opaque,
        cull: CullMode::Back,
        depth_write: true,
        depth_test: DepthTest::LessEqual,
        queue: 2000,
        instances: Instances::Fixed(1),
        vertex_span: span.clone(),
        fragment_span: span.clone(),
        decl: Loc { file, span },
    }
}

fn pick<T: Copy>(t: &Table, key: &str, options: &[(&str, T)], cx: &mut Cx) -> Option<T> {
    let s = t.string(key, cx)?;
    match options.iter().find(|(n, _)| *n == s) {
        Some((_, v)) => Some(*v),
        None => {
            let names: Vec<&str> = options.iter().map(|(n, _)| *n).collect();
            let hint = crate::diag::did_you_mean(&s, names.iter().copied()).map_or_else(
                || format!("expected one of: {}", names.join(", ")),
                |x| format!("did you mean `{x}`?"),
            );
            cx.error_with_note(
                "unknown-value",
                format!("unknown `{key}` value `{s}` in {}", t.what),
                t.span_of(key),
                "unknown",
                hint,
            );
            None
        }
    }
}

fn parse_pass(v: &Value, cx: &mut Cx) -> Option<Pass> {
    let t = Table::new(v, "a [[pass]]", cx)?;
    t.check_keys(PASS_KEYS, cx);
    let mut pass = default_pass(cx.file, v.span());
    pass.name = t.string("name", cx).unwrap_or(pass.name);
    pass.vertex = t.string("vertex", cx).unwrap_or(pass.vertex);
    pass.fragment = t.string("fragment", cx).unwrap_or(pass.fragment);
    pass.vertex_span = t.span_of("vertex");
    pass.fragment_span = t.span_of("fragment");
    use BlendMode as B;
    if let Some(b) = pick(
        &t,
        "blend",
        &[
            ("opaque", B::Opaque),
            ("alpha", B::Alpha),
            ("premultiplied", B::Premultiplied),
            ("additive", B::Additive),
            ("multiply", B::Multiply),
        ],
        cx,
    ) {
        pass.blend = b;
        if b != B::Opaque {
            pass.depth_write = false;
            pass.queue = 3000;
        }
    }
    if let Some(c) = pick(
        &t,
        "cull",
        &[
            ("none", CullMode::None),
            ("front", CullMode::Front),
            ("back", CullMode::Back),
        ],
        cx,
    ) {
        pass.cull = c;
    }
    use DepthTest as D;
    if let Some(d) = pick(
        &t,
        "depth_test",
        &[
            ("always", D::Always),
            ("never", D::Never),
            ("less", D::Less),
            ("less_equal", D::LessEqual),
            ("equal", D::Equal),
            ("greater", D::Greater),
            ("greater_equal", D::GreaterEqual),
        ],
        cx,
    ) {
        pass.depth_test = d;
    }
    pass.depth_write = t.boolean("depth_write", cx).unwrap_or(pass.depth_write);
    pass.queue = t.integer("queue", cx).unwrap_or(pass.queue);
    if let Some(iv) = t.get("instances") {
        match iv.get_ref() {
            DeValue::Integer(_) => {
                let n = crate::toml_reader::expect_integer(iv, "`instances`", cx)?;
                if !(1..=4096).contains(&n) {
                    cx.error(
                        "out-of-range",
                        "`instances` must be between 1 and 4096",
                        iv.span(),
                        "here",
                    );
                }
                pass.instances = Instances::Fixed(n.clamp(1, 4096) as u32);
            }
            DeValue::String(s) => pass.instances = Instances::Param(s.to_string()),
            other => type_error(
                cx,
                "`instances`",
                "a count or an int parameter's name",
                other,
                iv.span(),
            ),
        }
    }
    Some(pass)
}
