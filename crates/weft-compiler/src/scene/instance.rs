//! From a resolved instance to what folding needs and what the engine uploads:
//! which uniform members and textures are scene constants (and their values,
//! exactly as the runtime would have uploaded them), and which stay data.

use super::fold::{ConstValue, FoldRequest};
use crate::compose::{FEATURE_DIRECTIONAL_LIGHTS, FEATURE_ENVIRONMENT, FEATURE_SH_AMBIENT};
use crate::prelude::{TIER_OVERRIDE, UNIFORM_VAR, uniform_members};
use naga::Literal;
use serde_json::{Value, json};
use std::collections::BTreeMap;
use weft_front::model::{Material, Param, ParamValue};
use weft_front::samples;
use weft_front::scene::model::{ResolvedInstance, SceneFeatures};
use weft_front::variants::VariantKey;
use weft_meta::{KeywordKind, ParamKind};

/// The default texture transform (Unity's `_ST`: scale xy, offset zw).
const DEFAULT_ST: [f64; 4] = [1.0, 1.0, 0.0, 0.0];

/// The value a uniform member holds for this instance, as uploaded
/// (colours linear, curves baked), or None for non-uniform parameters.
fn member_value(p: &Param, v: &ParamValue) -> Option<(ConstValue, Value)> {
    Some(match (p.kind, v) {
        (ParamKind::Float, ParamValue::Float(x)) => (ConstValue::F32(vec![*x as f32]), json!(x)),
        (ParamKind::Int, ParamValue::Int(i)) => {
            let i = i32::try_from(*i).ok()?;
            (ConstValue::I32(i), json!(i))
        }
        (ParamKind::Bool, ParamValue::Bool(b)) => {
            (ConstValue::U32(u32::from(*b)), json!(u32::from(*b)))
        }
        (ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4, ParamValue::Vector(xs)) => (
            ConstValue::F32(xs.iter().map(|x| *x as f32).collect()),
            json!(xs),
        ),
        (ParamKind::Color, ParamValue::Vector(xs)) => {
            let c: Vec<f64> = (0..4)
                .map(|i| {
                    let x = xs.get(i).copied().unwrap_or(1.0);
                    if i < 3 && !p.hdr {
                        samples::srgb_to_linear(x)
                    } else {
                        x
                    }
                })
                .collect();
            (
                ConstValue::F32(c.iter().map(|x| *x as f32).collect()),
                json!(c),
            )
        }
        (ParamKind::Curve, ParamValue::Curve(keys)) => {
            let s = samples::sample_curve(keys, p.samples);
            (ConstValue::F32(Vec::new()), json!(s))
        }
        _ => return None,
    })
}

/// What one instance folds and what it still uploads.
pub struct InstanceValues {
    pub fold: FoldRequest,
    /// Folded parameter -> its value (as uploaded).
    pub constants: BTreeMap<String, Value>,
    /// Every uniform member -> its value (as uploaded); the shader's layout
    /// says which of them the engine still writes.
    pub uniform: BTreeMap<String, Value>,
}

pub fn instance_values(
    m: &Material,
    inst: &ResolvedInstance,
    tier: usize,
    features: &SceneFeatures,
) -> InstanceValues {
    let mut fold = FoldRequest {
        uniform_var: UNIFORM_VAR.into(),
        drop_entry_points: m.dropped_entry_points(&VariantKey::of_values(m, tier, &inst.keywords)),
        ..Default::default()
    };
    fold.overrides
        .insert(TIER_OVERRIDE.into(), Literal::U32(tier as u32));
    for (kw, &v) in m.keywords.iter().zip(&inst.keywords) {
        let x = match kw.kind {
            KeywordKind::Toggle => Literal::Bool(v == 1),
            KeywordKind::Enum => Literal::U32(v as u32),
        };
        fold.overrides.insert(kw.name.clone(), x);
    }
    fold.overrides.insert(
        FEATURE_ENVIRONMENT.into(),
        Literal::Bool(features.environment),
    );
    fold.overrides.insert(
        FEATURE_SH_AMBIENT.into(),
        Literal::Bool(features.sh_ambient),
    );
    fold.overrides.insert(
        FEATURE_DIRECTIONAL_LIGHTS.into(),
        Literal::U32(features.directional_lights),
    );

    let is_dynamic = |i: usize| inst.dynamic.contains(&i);
    let members = uniform_members(m);
    let mut constants = BTreeMap::new();
    let mut uniform = BTreeMap::new();
    for (i, (p, v)) in m.params.iter().zip(&inst.values).enumerate() {
        let dynamic = is_dynamic(i);
        if let Some((c, json)) = member_value(p, v) {
            uniform.insert(p.name.clone(), json.clone());
            // Curves are read with a run-time index: they stay data.
            if !dynamic && p.kind != ParamKind::Curve {
                fold.members.insert(p.name.clone(), c);
                constants.insert(p.name.clone(), json);
            }
        }
        if let Some(st) = members
            .iter()
            .find(|mem| mem.param == p.name && mem.name != p.name)
        {
            uniform.insert(st.name.clone(), json!(DEFAULT_ST));
            if !dynamic {
                fold.members.insert(
                    st.name.clone(),
                    ConstValue::F32(DEFAULT_ST.iter().map(|x| *x as f32).collect()),
                );
            }
        }
        let set = inst.set.get(i).copied().unwrap_or(true);
        // An unset texture with an image (`file`) stays bound to it: an
        // image is no constant.
        if let (ParamKind::Texture2d | ParamKind::Cube, ParamValue::Texture(t)) = (p.kind, v)
            && !dynamic
            && (set || p.file.is_none())
        {
            // An unset texture starts from its keyword-dependent default.
            let t = if set {
                *t
            } else {
                p.texture_default_where(|subject| {
                    if subject == "tier" {
                        m.tiers.values.get(tier).map(String::as_str)
                    } else {
                        m.keywords
                            .iter()
                            .zip(&inst.keywords)
                            .find(|(k, _)| k.name == subject)
                            .map(|(k, &v)| k.values[v].as_str())
                    }
                })
                .unwrap_or(*t)
            };
            fold.textures.insert(p.name.clone(), t.sampled(p.srgb));
            constants.insert(p.name.clone(), json!(t.name()));
        }
    }
    InstanceValues {
        fold,
        constants,
        uniform,
    }
}

/// The metadata's transform: the model matrix, and translation, rotation
/// and scale as written — or, for a `matrix`, read back from it
/// (translation exact; scale the columns' lengths; rotation the Euler
/// angles of the normalised columns, exact when the matrix has no shear).
pub fn scene_transform(
    t: &weft_front::scene::model::Transform,
) -> weft_meta::scene::SceneTransform {
    let model = model_matrix(t);
    match &t.matrix {
        None => weft_meta::scene::SceneTransform {
            translation: t.translation,
            rotation_degrees: t.rotation_degrees,
            scale: t.scale,
            model,
        },
        Some(m) => {
            let column = |c: usize| [m[4 * c], m[4 * c + 1], m[4 * c + 2]];
            let length = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
            let scale = [0, 1, 2].map(|c| length(column(c)));
            let unit =
                |c: usize| column(c).map(|x| if scale[c] > 0.0 { x / scale[c] } else { 0.0 });
            let (x, y, z) = (unit(0), unit(1), unit(2));
            // R = Rz Ry Rx: R[2][0] = -sin(ry), R[2][1] = cos(ry) sin(rx), …
            let ry = (-x[2]).clamp(-1.0, 1.0).asin();
            let (rx, rz) = if ry.cos().abs() > 1e-9 {
                (y[2].atan2(z[2]), x[1].atan2(x[0]))
            } else {
                ((-z[1]).atan2(y[1]), 0.0)
            };
            let round = |a: f64| (a.to_degrees() * 1e6).round() / 1e6;
            weft_meta::scene::SceneTransform {
                translation: [m[12], m[13], m[14]],
                rotation_degrees: [round(rx), round(ry), round(rz)],
                scale: scale.map(|s| (s * 1e9).round() / 1e9),
                model,
            }
        }
    }
}

/// Object -> world, column-major: translate * rotate(Z * Y * X) * scale,
/// or the instance's `matrix`.
pub fn model_matrix(t: &weft_front::scene::model::Transform) -> [f32; 16] {
    if let Some(m) = &t.matrix {
        return m.map(|x| x as f32);
    }
    let [rx, ry, rz] = t.rotation_degrees.map(f64::to_radians);
    let (sx, cx) = rx.sin_cos();
    let (sy, cy) = ry.sin_cos();
    let (sz, cz) = rz.sin_cos();
    // Rows of R = Rz * Ry * Rx.
    let r = [
        [cz * cy, cz * sy * sx - sz * cx, cz * sy * cx + sz * sx],
        [sz * cy, sz * sy * sx + cz * cx, sz * sy * cx - cz * sx],
        [-sy, cy * sx, cy * cx],
    ];
    let mut m = [0f32; 16];
    for col in 0..3 {
        for row in 0..3 {
            m[col * 4 + row] = (r[row][col] * t.scale[col]) as f32;
        }
    }
    m[12] = t.translation[0] as f32;
    m[13] = t.translation[1] as f32;
    m[14] = t.translation[2] as f32;
    m[15] = 1.0;
    m
}
