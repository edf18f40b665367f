//! Parameter values as written in TOML, typed against the parameter's kind:
//! a material's `default`, a preset's curve or gradient, a scene instance's
//! `params`. One implementation for every place a value is written, so the
//! rules (components, ranges, built-in textures, keyframes, stops) cannot drift.

use crate::diag::Span;
use crate::gpu_numbers::{self, GpuType};
use crate::model::{Loc, ParamValue};
use crate::toml_reader::{Cx, Table, Value, expect_array, expect_number, expect_string};
use codespan_reporting::diagnostic::Label;
use weft_meta::{GradientStop, Keyframe, ParamKind, TextureDefault};

pub const KEYFRAME_KEYS: &[&str] = &["time", "value", "in_slope", "out_slope"];
pub const STOP_KEYS: &[&str] = &["position", "color"];

/// How a number outside its parameter's `range` is reported.
#[derive(Clone, Debug)]
pub struct RangeReport {
    pub code: &'static str,
    pub message: String,
    /// Where the range is declared (a secondary label), when there is one to show.
    pub declared: Option<Loc>,
    pub note: Option<String>,
}

impl RangeReport {
    /// A material's default (or preset curve) outside the range it declares.
    pub fn default_of(what: &str, declared: Loc) -> Self {
        RangeReport {
            code: "default-out-of-range",
            message: format!("default of {what} is outside its range"),
            declared: Some(declared),
            note: Some("change the default or widen `range`".into()),
        }
    }
}

/// Where a value is written, for its messages.
#[derive(Clone, Debug)]
pub struct Site {
    /// The subject of type errors, e.g. "`default` of parameter `roughness`".
    pub what: String,
    /// What an unknown texture name is called: "unknown {texture} `name`".
    pub texture: &'static str,
    pub range: RangeReport,
}

/// How a value of a `kind` parameter is written (the hint of a wrong-type error).
pub fn how_to_write(kind: ParamKind) -> &'static str {
    match kind {
        ParamKind::Float => "write a number",
        ParamKind::Int => "write a whole number",
        ParamKind::Bool => "write true or false",
        ParamKind::Vec2 => "write 2 numbers: [x, y]",
        ParamKind::Vec3 => "write 3 numbers: [x, y, z]",
        ParamKind::Vec4 => "write 4 numbers: [x, y, z, w]",
        ParamKind::Color => "write 3 or 4 numbers: [r, g, b] or [r, g, b, a]",
        ParamKind::Texture2d | ParamKind::Cube => {
            "write a built-in texture: \"white\", \"black\", \"gray\" or \"normal\""
        }
        ParamKind::Curve => {
            "write an array of keyframes: [{ time = 0.0, value = 0.0 }, { time = 1.0, value = 1.0 }]"
        }
        ParamKind::Gradient => {
            "write an array of stops: [{ position = 0.0, color = [r, g, b] }, { position = 1.0, color = [r, g, b] }]"
        }
    }
}

/// The value a parameter has when its declaration gives no `default`.
pub fn builtin_default(kind: ParamKind, range: Option<[f64; 2]>) -> ParamValue {
    match kind {
        ParamKind::Float => ParamValue::Float(range.map_or(0.0, |r| r[0].max(0.0).min(r[1]))),
        ParamKind::Int => ParamValue::Int(range.map_or(0, |r| r[0].max(0.0).min(r[1]) as i64)),
        ParamKind::Bool => ParamValue::Bool(false),
        ParamKind::Vec2 => ParamValue::Vector(vec![0.0; 2]),
        ParamKind::Vec3 => ParamValue::Vector(vec![0.0; 3]),
        ParamKind::Vec4 => ParamValue::Vector(vec![0.0; 4]),
        ParamKind::Color => ParamValue::Vector(vec![1.0; 4]),
        ParamKind::Texture2d | ParamKind::Cube => ParamValue::Texture(TextureDefault::White),
        ParamKind::Curve => ParamValue::Curve(vec![
            Keyframe {
                time: 0.0,
                value: 0.0,
                in_slope: 0.0,
                out_slope: 0.0,
            },
            Keyframe {
                time: 1.0,
                value: 0.0,
                in_slope: 0.0,
                out_slope: 0.0,
            },
        ]),
        ParamKind::Gradient => ParamValue::Gradient(vec![
            GradientStop {
                position: 0.0,
                color: [0.0, 0.0, 0.0, 1.0],
            },
            GradientStop {
                position: 1.0,
                color: [1.0, 1.0, 1.0, 1.0],
            },
        ]),
    }
}

/// A preset value in the parameter's own representation: presets keep
/// numbers as floats and colours as written, a resolved value does not.
pub fn conform(kind: ParamKind, value: &ParamValue) -> ParamValue {
    match (kind, value) {
        (ParamKind::Int, ParamValue::Float(x)) => ParamValue::Int(*x as i64),
        (ParamKind::Color, ParamValue::Vector(xs)) if xs.len() == 3 => {
            ParamValue::Vector(xs.iter().copied().chain([1.0]).collect())
        }
        _ => value.clone(),
    }
}

fn out_of_range(cx: &mut Cx, report: &RangeReport, value: f64, range: [f64; 2], span: Span) {
    let d = cx.diags.error(
        report.code,
        report.message.clone(),
        cx.file,
        span,
        format!("{value} is not in [{}, {}]", range[0], range[1]),
    );
    if let Some(at) = &report.declared {
        d.labels
            .push(Label::secondary(at.file, at.span.clone()).with_message("range declared here"));
    }
    if let Some(note) = &report.note {
        d.notes.push(note.clone());
    }
}

/// Reads `v` as a value of a `kind` parameter, checking components, the
/// range (per component; keyframe values for curves) and built-in texture names.
pub fn parse_value(
    v: &Value,
    kind: ParamKind,
    range: Option<[f64; 2]>,
    site: &Site,
    cx: &mut Cx,
) -> Option<ParamValue> {
    let what = site.what.as_str();
    let check = |cx: &mut Cx, x: f64, span: Span| {
        if let Some(r) = range
            && (x < r[0] || x > r[1])
        {
            out_of_range(cx, &site.range, x, r, span);
        }
    };
    match kind {
        ParamKind::Float => {
            let x = expect_number(v, what, cx)?;
            if gpu_numbers::check(cx, GpuType::F32, x, v.span(), what) {
                check(cx, x, v.span());
            }
            Some(ParamValue::Float(x))
        }
        ParamKind::Int => {
            let x = crate::toml_reader::expect_integer(v, what, cx)?;
            if gpu_numbers::check(cx, GpuType::I32, x as f64, v.span(), what) {
                check(cx, x as f64, v.span());
            }
            Some(ParamValue::Int(x))
        }
        ParamKind::Bool => crate::toml_reader::expect_bool(v, what, cx).map(ParamValue::Bool),
        ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 | ParamKind::Color => {
            let items = expect_array(v, what, cx)?;
            let n = kind.components().unwrap_or(4);
            let ok_len = if kind == ParamKind::Color {
                items.len() == 3 || items.len() == 4
            } else {
                items.len() == n
            };
            if !ok_len {
                cx.error(
                    "wrong-type",
                    format!(
                        "{what} must have {} components",
                        if kind == ParamKind::Color {
                            "3 or 4".to_string()
                        } else {
                            n.to_string()
                        }
                    ),
                    v.span(),
                    format!("{} components here", items.len()),
                );
                return None;
            }
            let mut out = Vec::new();
            for item in items {
                let x = expect_number(item, what, cx)?;
                if gpu_numbers::check(cx, GpuType::F32, x, item.span(), what) {
                    check(cx, x, item.span());
                }
                out.push(x);
            }
            if kind == ParamKind::Color && out.len() == 3 {
                out.push(1.0);
            }
            Some(ParamValue::Vector(out))
        }
        ParamKind::Texture2d | ParamKind::Cube => {
            let name = expect_string(v, what, cx)?;
            match TextureDefault::ALL.iter().find(|d| d.name() == name) {
                Some(d) => Some(ParamValue::Texture(*d)),
                None => {
                    let names = TextureDefault::ALL.map(|d| d.name());
                    let hint = crate::diag::did_you_mean(&name, names.iter().copied()).map_or_else(
                        || format!("use one of: {}", names.join(", ")),
                        |x| {
                            format!(
                                "did you mean `{x}`? (built-in textures: {})",
                                names.join(", ")
                            )
                        },
                    );
                    cx.error_with_note(
                        "unknown-value",
                        format!("unknown {} `{name}`", site.texture),
                        v.span(),
                        "not a built-in texture",
                        hint,
                    );
                    None
                }
            }
        }
        ParamKind::Curve => parse_keyframes(v, what, range, &site.range, cx).map(ParamValue::Curve),
        ParamKind::Gradient => parse_stops(v, what, cx).map(ParamValue::Gradient),
    }
}

/// Curve keyframes (`[{ time, value, in_slope, out_slope }, …]`), their
/// values checked against `range`.
pub fn parse_keyframes(
    v: &Value,
    what: &str,
    range: Option<[f64; 2]>,
    report: &RangeReport,
    cx: &mut Cx,
) -> Option<Vec<Keyframe>> {
    let items = expect_array(v, what, cx)?;
    let mut keys = Vec::new();
    for item in items {
        let k = Table::new(item, "a curve keyframe", cx)?;
        k.check_keys(KEYFRAME_KEYS, cx);
        let (Some(time), Some(value)) = (k.number("time", cx), k.number("value", cx)) else {
            cx.error(
                "missing-key",
                "a keyframe needs `time` and `value`",
                item.span(),
                "here",
            );
            return None;
        };
        let mut fits = true;
        for key in KEYFRAME_KEYS {
            if let Some(kv) = k.get(key) {
                fits &= gpu_numbers::check_value(
                    cx,
                    GpuType::F32,
                    kv,
                    &format!("`{key}` of a keyframe of {what}"),
                );
            }
        }
        if let Some(r) = range
            && fits
            && (value < r[0] || value > r[1])
        {
            out_of_range(cx, report, value, r, k.span_of("value"));
        }
        if let Some(prev) = keys.last().map(|k: &Keyframe| k.time)
            && time <= prev
        {
            cx.error(
                "unordered-keys",
                "curve keyframes must have increasing `time`",
                k.span_of("time"),
                format!("{time} is not after {prev}"),
            );
        }
        keys.push(Keyframe {
            time,
            value,
            in_slope: k.number("in_slope", cx).unwrap_or(0.0),
            out_slope: k.number("out_slope", cx).unwrap_or(0.0),
        });
    }
    if keys.is_empty() {
        cx.error(
            "wrong-type",
            "a curve needs at least one keyframe",
            v.span(),
            "empty",
        );
        return None;
    }
    if !curve_fits_f32(&keys) {
        cx.error_with_note(
            "type-range",
            format!("{what} does not fit in an f32 once baked"),
            v.span(),
            "this curve's time span or baked samples exceed f32's range",
            format!(
                "the curve is baked into f32 samples over t, and its time span is an f32 too (an f32: {}); bring the keys' times, values or slopes closer together",
                GpuType::F32.range_text()
            ),
        );
    }
    Some(keys)
}

/// The baked form of a curve fits f32: its time span (the prelude divides
/// by it) and its values at the most samples a curve may have.
fn curve_fits_f32(keys: &[Keyframe]) -> bool {
    let [t0, t1] = weft_meta::bake::curve_time_range(keys);
    let fits = |x: f64| GpuType::F32.fits(x);
    // Keys that do not fit are reported one by one, not again here.
    if keys
        .iter()
        .any(|k| !(fits(k.time) && fits(k.value) && fits(k.in_slope) && fits(k.out_slope)))
    {
        return true;
    }
    // Keys out of order are reported as such; the curve is not baked.
    if keys.windows(2).any(|w| w[1].time <= w[0].time) {
        return true;
    }
    fits(t1 - t0)
        && weft_meta::bake::sample_curve(keys, 4096)
            .into_iter()
            .all(fits)
}

/// Gradient stops (`[{ position, color }, …]`).
pub fn parse_stops(v: &Value, what: &str, cx: &mut Cx) -> Option<Vec<GradientStop>> {
    let items = expect_array(v, what, cx)?;
    let mut stops = Vec::new();
    for item in items {
        let s = Table::new(item, "a gradient stop", cx)?;
        s.check_keys(STOP_KEYS, cx);
        let (Some(position), Some(color)) = (s.number("position", cx), s.numbers("color", cx))
        else {
            cx.error(
                "missing-key",
                "a gradient stop needs `position` and `color`",
                item.span(),
                "here",
            );
            return None;
        };
        if !(0.0..=1.0).contains(&position) {
            cx.error(
                "out-of-range",
                "gradient stop `position` must be in [0, 1]",
                s.span_of("position"),
                "here",
            );
        }
        if color.len() != 3 && color.len() != 4 || color.iter().any(|c| !(0.0..=1.0).contains(c)) {
            cx.error(
                "wrong-type",
                "gradient stop `color` must be 3 or 4 numbers in [0, 1]",
                s.span_of("color"),
                "here",
            );
            return None;
        }
        if let Some(prev) = stops.last().map(|s: &GradientStop| s.position)
            && position < prev
        {
            cx.error(
                "unordered-keys",
                "gradient stops must have non-decreasing `position`",
                s.span_of("position"),
                "out of order",
            );
        }
        stops.push(GradientStop {
            position,
            color: [
                color[0],
                color[1],
                color[2],
                color.get(3).copied().unwrap_or(1.0),
            ],
        });
    }
    if stops.is_empty() {
        cx.error(
            "wrong-type",
            "a gradient needs at least one stop",
            v.span(),
            "empty",
        );
        return None;
    }
    Some(stops)
}
