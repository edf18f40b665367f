//! `[presets.<name>]` tables -> [`Preset`]: named sets of parameter, keyword
//! and tier values, read against the parameters declared before them.

use super::{PRESET_KEYS, is_upper_ident};
use crate::diag::Span;
use crate::gpu_numbers::{self, GpuType};
use crate::model::humanize;
use crate::model::*;
use crate::toml_reader::{Cx, Table, Value, expect_number, type_error};
use crate::values;
use toml::de::DeValue;
use weft_meta::{ParamKind, TextureDefault};

pub(super) fn parse_preset(
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
            // Numbers must fit the parameter's GPU type (curves: per keyframe, below).
            let number_type = params
                .iter()
                .find(|p| p.name == key)
                .and_then(|p| match p.kind {
                    ParamKind::Int => Some(GpuType::I32),
                    ParamKind::Float
                    | ParamKind::Vec2
                    | ParamKind::Vec3
                    | ParamKind::Vec4
                    | ParamKind::Color => Some(GpuType::F32),
                    _ => None,
                });
            if let Some(ty) = number_type
                && !gpu_numbers::check_value(
                    cx,
                    ty,
                    val,
                    &format!("preset `{name}`'s value for `{key}`"),
                )
            {
                continue;
            }
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
