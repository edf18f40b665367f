//! `[params.<name>]` tables -> [`Param`]: the type, the keys that apply to it,
//! ranges, slider settings and the default value.

use super::{DEFAULT_WHEN_KEYS, PARAM_KEYS, is_snake_ident, parse_show_if};
use crate::check::Sites;
use crate::diag::Span;
use crate::gpu_numbers::{self, GpuType};
use crate::model::humanize;
use crate::model::*;
use crate::toml_reader::{Cx, Table, Value, expect_array, expect_string};
use crate::values;
use weft_meta::{Condition, ParamKind, TextureDefault};

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

/// One `[params.<name>]` table. The spans of its `default_when` conditions go
/// to `sites`, for the cross-reference checks.
pub(super) fn parse_param(
    name: &str,
    name_span: Span,
    v: &Value,
    sites: &mut Sites,
    cx: &mut Cx,
) -> Option<Param> {
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

    check_kind_keys(&t, kind, cx);

    let hdr = t.boolean("hdr", cx).unwrap_or(false);
    let (range, soft_range) = parse_ranges(&t, name, kind, hdr, cx);
    let (step, power) = parse_slider(&t, cx);
    let samples = parse_samples(&t, kind, cx);

    let default = parse_default(&t, kind, range, cx)?;
    let show_if = parse_show_if(&t, cx);
    let default_when = match kind {
        ParamKind::Texture2d | ParamKind::Cube => {
            let (entries, spans) = parse_default_when(&t, kind, cx);
            if !spans.is_empty() {
                sites.param_default_when.insert(name.to_string(), spans);
            }
            entries
        }
        // Reported above as a key that does not apply.
        _ => Vec::new(),
    };
    let file = parse_file(&t, kind, cx);

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
        default_when,
        file,
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

/// Keys that only make sense for some kinds, reported on any other.
fn check_kind_keys(t: &Table, kind: ParamKind, cx: &mut Cx) {
    let only_for: &[(&str, &[ParamKind])] = &[
        ("hdr", &[ParamKind::Color]),
        ("srgb", &[ParamKind::Texture2d, ParamKind::Cube]),
        ("tiling", &[ParamKind::Texture2d]),
        ("samples", &[ParamKind::Curve]),
        ("width", &[ParamKind::Gradient]),
        ("power", &[ParamKind::Float]),
        ("default_when", &[ParamKind::Texture2d, ParamKind::Cube]),
        ("file", &[ParamKind::Texture2d]),
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
}

/// `range` (colours without `hdr`: [0, 1] when not given) and
/// `soft_range`, each dropped when it does not apply or does not fit the
/// GPU type; a soft range outside the range is an error.
fn parse_ranges(
    t: &Table,
    name: &str,
    kind: ParamKind,
    hdr: bool,
    cx: &mut Cx,
) -> (Option<[f64; 2]>, Option<[f64; 2]>) {
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
    let number_type = if kind == ParamKind::Int {
        GpuType::I32
    } else {
        GpuType::F32
    };
    let fits = |key: &str, cx: &mut Cx| fits_as(t, number_type, key, cx);
    if range.is_some() && !fits("range", cx) {
        range = None;
    }
    if kind == ParamKind::Color && range.is_none() && !hdr {
        range = Some([0.0, 1.0]);
    }
    let mut soft_range = t.range("soft_range", cx);
    if soft_range.is_some() && !fits("soft_range", cx) {
        soft_range = None;
    }
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
    (range, soft_range)
}

/// Whether `key`, if given, fits `ty` (reported where it does not).
fn fits_as(t: &Table, ty: GpuType, key: &str, cx: &mut Cx) -> bool {
    t.get(key)
        .is_none_or(|v| gpu_numbers::check_value(cx, ty, v, &format!("`{key}` of {}", t.what)))
}

/// The slider's `step` and `power`, each positive.
fn parse_slider(t: &Table, cx: &mut Cx) -> (Option<f64>, Option<f64>) {
    let step = t
        .number("step", cx)
        .filter(|_| fits_as(t, GpuType::F32, "step", cx));
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
    let power = t
        .number("power", cx)
        .filter(|_| fits_as(t, GpuType::F32, "power", cx));
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
    (step, power)
}

/// A curve's `samples` (16 when not given) or a gradient's `width` (256),
/// reported outside 2..=4096; 0 for other kinds.
fn parse_samples(t: &Table, kind: ParamKind, cx: &mut Cx) -> i64 {
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
    samples
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

/// A `texture2d` parameter's `file`: the path as written (read and decoded
/// once the materials root is known, `crate::texture_files`). Not with
/// `default_when`: a file is one image for every variant, and which of the
/// two would win where an entry holds is nothing a reader could guess.
fn parse_file(t: &Table, kind: ParamKind, cx: &mut Cx) -> Option<TextureFile> {
    let written = t.string("file", cx)?;
    if kind != ParamKind::Texture2d {
        // Reported as a key that does not apply.
        return None;
    }
    let loc = Loc {
        file: cx.file,
        span: t.span_of("file"),
    };
    if written.is_empty() {
        cx.error_with_note(
            "wrong-type",
            "`file` is empty",
            loc.span,
            "here",
            "name a PNG relative to the materials root, e.g. `file = \"face/textures/face_sdf.png\"`",
        );
        return None;
    }
    if let Some(span) = t.key_span("default_when") {
        let d = cx.diags.error(
            "conflicting-keys",
            format!("{} has both `file` and `default_when`", t.what),
            cx.file,
            span,
            "keyword-dependent defaults here",
        );
        d.labels.push(
            codespan_reporting::diagnostic::Label::secondary(loc.file, loc.span)
                .with_message("file default here"),
        );
        d.notes.push(
            "a file default is one image for every variant: drop `default_when`, or drop `file` and bind the image from the engine"
                .into(),
        );
        return None;
    }
    Some(TextureFile {
        path: written,
        loc,
        image: Default::default(),
    })
}

/// What a `default_when` condition may say (the hint on a condition that does
/// not parse).
const DEFAULT_WHEN_FORMS: &str = "write one condition on a static keyword or the tier: `KEYWORD`, `!KEYWORD`, `KEYWORD == value`, `KEYWORD != value` or `tier == name`";

/// A texture parameter's `default_when`: `[{ if = "<condition>", default =
/// "<texture>" }, ...]`, in order, with the span of each kept entry's `if`.
/// Entries with an error are reported and left out. Whether the condition
/// names a static keyword or `tier`, and one of its values, is checked in
/// `check.rs`.
fn parse_default_when(
    t: &Table,
    kind: ParamKind,
    cx: &mut Cx,
) -> (Vec<(Condition, TextureDefault)>, Vec<Span>) {
    let mut entries = Vec::new();
    let mut spans = Vec::new();
    let Some(v) = t.get("default_when") else {
        return (entries, spans);
    };
    let what = format!("`default_when` of {}", t.what);
    let Some(items) = expect_array(v, &what, cx) else {
        return (entries, spans);
    };
    for item in items {
        let Some(e) = Table::new(item, format!("an entry of {what}"), cx) else {
            continue;
        };
        e.check_keys(DEFAULT_WHEN_KEYS, cx);
        let example = "write `{ if = \"KEYWORD == value\", default = \"white\" }`";
        let condition = match e.get("if") {
            Some(cv) => {
                super::parse_one_condition(cv, "if", DEFAULT_WHEN_FORMS, cx).map(|c| (c, cv.span()))
            }
            None => {
                cx.error_with_note(
                    "missing-key",
                    format!("{} has no `if`", e.what),
                    e.span.clone(),
                    "this entry",
                    example,
                );
                None
            }
        };
        let default = match e.get("default") {
            Some(dv) => {
                let site = values::Site {
                    what: format!("`default` of {}", e.what),
                    texture: "texture default",
                    range: values::RangeReport::default_of(
                        &t.what,
                        Loc {
                            file: cx.file,
                            span: e.span.clone(),
                        },
                    ),
                };
                match values::parse_value(dv, kind, None, &site, cx) {
                    Some(ParamValue::Texture(d)) => Some(d),
                    _ => None,
                }
            }
            None => {
                cx.error_with_note(
                    "missing-key",
                    format!("{} has no `default`", e.what),
                    e.span.clone(),
                    "this entry",
                    example,
                );
                None
            }
        };
        if let (Some((c, span)), Some(d)) = (condition, default) {
            entries.push((c, d));
            spans.push(span);
        }
    }
    (entries, spans)
}

#[cfg(test)]
mod tests {
    use crate::diag::{Diagnostics, SourceDb};
    use crate::toml_reader::Cx;
    use std::path::Path;

    const KEYWORDS: &str = r#"
[keywords.SPHERE_MAP]
type = "enum"
values = ["off", "add", "multiply"]

[keywords.WEAVE]
type = "enum"
values = ["plain", "twill"]
mode = "constant"

[[tier]]
name = "fast"

[[tier]]
name = "reference"
"#;

    /// The codes of the errors a material with `param` (a `[params.x]`
    /// table's body) gets, and the text each primary label points at.
    fn errors(param: &str) -> Vec<(String, String)> {
        let text = format!(
            "[material]\nname = \"m\"\n\n[params.x]\n{param}\n\n[params.flag]\ntype = \"bool\"\n{KEYWORDS}"
        );
        let mut db = SourceDb::new();
        let mut diags = Diagnostics::new();
        let file = db.add(Path::new("m.toml"), "m.toml".into(), text.clone());
        let m = crate::parse::parse_material(
            &text,
            Path::new("m.toml"),
            Path::new("."),
            &[],
            &mut Cx {
                file,
                diags: &mut diags,
            },
        );
        let out: Vec<(String, String)> = diags
            .iter()
            .map(|d| {
                let l = &d.labels[0];
                (d.code.clone().unwrap(), text[l.range.clone()].to_string())
            })
            .collect();
        if out.is_empty() {
            let m = m.expect("parses");
            assert!(!m.params[0].default_when.is_empty());
        }
        out
    }

    fn pair(code: &str, at: &str) -> (String, String) {
        (code.to_string(), at.to_string())
    }

    #[test]
    fn valid_entries() {
        assert_eq!(
            errors(
                r#"type = "texture2d"
default_when = [{ if = "SPHERE_MAP != off", default = "gray" }, { if = "tier == fast", default = "normal" }]"#
            ),
            []
        );
    }

    #[test]
    fn condition_must_name_a_static_keyword_or_tier() {
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = [{ if = "WEAVE == twill", default = "white" }]"#
            ),
            [pair("bad-condition", "\"WEAVE == twill\"")]
        );
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = [{ if = "flag", default = "white" }]"#
            ),
            [pair("bad-condition", "\"flag\"")]
        );
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = [{ if = "SPHERE_MAPS == add", default = "white" }]"#
            ),
            [pair("unknown-keyword", "\"SPHERE_MAPS == add\"")]
        );
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = [{ if = "tier == fast", default = "white" }, { if = "SPHERE_MAP == multiplly", default = "white" }]"#
            ),
            [pair("unknown-value", "\"SPHERE_MAP == multiplly\"")]
        );
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = [{ if = "tier == slow", default = "white" }]"#
            ),
            [pair("unknown-value", "\"tier == slow\"")]
        );
        // One condition, as in show_if.
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = [{ if = "SPHERE_MAP == add && tier == fast", default = "white" }]"#
            ),
            [pair(
                "bad-condition",
                "\"SPHERE_MAP == add && tier == fast\""
            )]
        );
    }

    #[test]
    fn entries_are_checked() {
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = [{ if = "SPHERE_MAP == add", default = "grey" }]"#
            ),
            [pair("unknown-value", "\"grey\"")]
        );
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = [{ if = "SPHERE_MAP == add", default = "white", then = 1 }]"#
            ),
            [pair("unknown-key", "then")]
        );
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = [{ default = "white" }]"#
            ),
            [pair("missing-key", "{ default = \"white\" }")]
        );
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = [{ if = "tier == fast" }]"#
            ),
            [pair("missing-key", "{ if = \"tier == fast\" }")]
        );
        assert_eq!(
            errors(
                r#"type = "cube"
default_when = { if = "tier == fast", default = "white" }"#
            )[0]
            .0,
            "wrong-type"
        );
    }

    #[test]
    fn only_for_textures() {
        assert_eq!(
            errors(
                r#"type = "float"
default_when = [{ if = "tier == fast", default = "white" }]"#
            ),
            [pair("unknown-key", "default_when")]
        );
    }
}
