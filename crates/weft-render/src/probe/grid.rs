//! The parameter grid: each parameter a variant reads at the ends and
//! middle of its domain, and the all-min and all-max corners.

use crate::material::{CurveValue, Value};
use weft_meta::{
    GradientStop, InstanceCount, MaterialMetadata, ParamKind, Parameter, TextureDefault,
    VariantShader,
};

/// One point of the parameter grid: values set on top of the defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct Setting {
    /// e.g. `defaults`, `roughness=0 (min)`, `all-max`.
    pub label: String,
    pub values: Vec<(String, Value)>,
}

/// Which end of a parameter's domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum End {
    Min,
    Mid,
    Max,
}

fn numeric_domain(p: &Parameter) -> (f64, f64) {
    if let Some([lo, hi]) = p.range {
        return (lo, hi);
    }
    if let Some([lo, hi]) = p.soft_range {
        return (lo, hi);
    }
    match p.kind {
        ParamKind::Color => (0.0, 1.0),
        _ => {
            // Unbounded: from min(0, default) to max(1, 2 default).
            let d = p
                .default
                .as_f64()
                .or_else(|| p.default.as_array().and_then(|a| a.first()?.as_f64()))
                .unwrap_or(0.0);
            (d.min(0.0), (2.0 * d).max(1.0))
        }
    }
}

fn fmt_num(x: f64) -> String {
    let s = format!("{x}");
    if s.len() > 10 { format!("{x:.4}") } else { s }
}

/// The value of `p` at one end of its domain, with its label; None when the
/// kind has no such value (e.g. the middle of a texture).
fn param_value(p: &Parameter, end: End) -> Option<(Value, String)> {
    let (lo, hi) = numeric_domain(p);
    let x = match end {
        End::Min => lo,
        End::Max => hi,
        End::Mid => 0.5 * (lo + hi),
    };
    let tag = match end {
        End::Min => "min",
        End::Mid => "mid",
        End::Max => "max",
    };
    match p.kind {
        ParamKind::Float => Some((Value::Float(x), fmt_num(x))),
        ParamKind::Int => {
            let i = match end {
                End::Mid => x.round(),
                End::Min => x.ceil(),
                End::Max => x.floor(),
            };
            Some((Value::Int(i as i64), format!("{i}")))
        }
        ParamKind::Bool => match end {
            End::Min => Some((Value::Bool(false), "false".into())),
            End::Max => Some((Value::Bool(true), "true".into())),
            End::Mid => None,
        },
        ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 => {
            let n = p.kind.components().unwrap_or(4);
            Some((Value::Vector(vec![x; n]), format!("all {}", fmt_num(x))))
        }
        ParamKind::Color => {
            if end == End::Mid {
                return None;
            }
            // rgb at the end of the range, alpha 0 or 1 (clamped into the range).
            let a: f64 = if end == End::Min { 0.0 } else { 1.0 };
            let a = a.clamp(lo, hi);
            Some((
                Value::Vector(vec![x, x, x, a]),
                format!("[{0}, {0}, {0}, {1}]", fmt_num(x), fmt_num(a)),
            ))
        }
        ParamKind::Curve => {
            let n = p.curve.as_ref()?.samples as usize;
            let samples: Vec<f64> = match end {
                End::Min => vec![lo; n],
                End::Max => vec![hi; n],
                // The steepest curve: samples alternate between the ends.
                End::Mid => (0..n).map(|i| if i % 2 == 0 { lo } else { hi }).collect(),
            };
            let label = match end {
                End::Mid => format!("zigzag {}/{}", fmt_num(lo), fmt_num(hi)),
                _ => format!("flat {}", fmt_num(x)),
            };
            Some((Value::Curve(CurveValue::Samples(samples)), label))
        }
        ParamKind::Gradient => {
            let c = match end {
                End::Min => 0.0,
                End::Max => 1.0,
                End::Mid => return None,
            };
            let stop = |position| GradientStop {
                position,
                color: [c, c, c, c],
            };
            Some((
                Value::Gradient(vec![stop(0.0), stop(1.0)]),
                format!("flat [{c}, {c}, {c}, {c}]"),
            ))
        }
        ParamKind::Texture2d | ParamKind::Cube => {
            let t = match end {
                End::Min => TextureDefault::Black,
                End::Max => TextureDefault::White,
                End::Mid => TextureDefault::Normal,
            };
            if p.kind == ParamKind::Cube && end == End::Mid {
                return None;
            }
            Some((Value::from(t), t.name().to_string()))
        }
    }
    .map(|(v, label)| (v, format!("{label} ({tag})")))
}

/// Whether the variant reads the parameter: its uniform member or tiling
/// member is in the variant's uniform layout, a binding carries it, or a
/// pass takes its instance count from it.
pub fn variant_reads(meta: &MaterialMetadata, shader: &VariantShader, p: &Parameter) -> bool {
    let member = |m: &String| {
        shader
            .material_uniform
            .as_ref()
            .is_some_and(|u| u.members.iter().any(|x| &x.name == m))
    };
    p.uniform_member.as_ref().is_some_and(member)
        || p.texture
            .as_ref()
            .and_then(|t| t.tiling_member.as_ref())
            .is_some_and(member)
        || shader
            .bindings
            .iter()
            .any(|b| b.parameter.as_deref() == Some(p.name.as_str()))
        || meta
            .passes
            .iter()
            .any(|pass| matches!(&pass.instances, InstanceCount::Parameter(n) if *n == p.name))
}

/// The parameter grid of one variant: the defaults; each parameter the
/// variant reads at its min, mid and max (colours at 0 and 1, bools false and
/// true, textures black / white / flat normal, curves flat at their range's
/// ends and zigzag, gradients black and white) with every other parameter
/// at its default; and the corners all-min and all-max (every parameter).
pub fn parameter_settings(meta: &MaterialMetadata, shader: &VariantShader) -> Vec<Setting> {
    let mut out = vec![Setting {
        label: "defaults".into(),
        values: Vec::new(),
    }];
    for p in &meta.parameters {
        if !variant_reads(meta, shader, p) {
            continue;
        }
        for end in [End::Min, End::Mid, End::Max] {
            if let Some((v, label)) = param_value(p, end) {
                out.push(Setting {
                    label: format!("{}={label}", p.name),
                    values: vec![(p.name.clone(), v)],
                });
            }
        }
    }
    for (end, label) in [(End::Min, "all-min"), (End::Max, "all-max")] {
        out.push(Setting {
            label: label.into(),
            values: meta
                .parameters
                .iter()
                .filter_map(|p| Some((p.name.clone(), param_value(p, end)?.0)))
                .collect(),
        });
    }
    out
}
