//! From a resolved instance to what folding needs and what the engine uploads:
//! which uniform members and textures are scene constants (and their values,
//! exactly as the runtime would have uploaded them), and which stay data.

use super::fold::{ConstValue, FoldRequest};
use crate::compile::engine_binding::{
    FEATURE_DIRECTIONAL_LIGHTS, FEATURE_ENVIRONMENT, FEATURE_SH_AMBIENT,
};
use crate::compile::prelude::{TIER_OVERRIDE, UNIFORM_VAR, uniform_members};
use naga::Literal;
use serde_json::{Value, json};
use std::collections::BTreeMap;
use weft_front::model::{Material, Param, ParamValue};
use weft_front::samples;
use weft_front::scene::model::{ResolvedInstance, SceneFeatures, SceneManifest};
use weft_front::variants::VariantKey;
use weft_meta::uniform::{
    self, ParamValue as Upload, ScalarType, TILING_OFFSET_DEFAULT, TILING_OFFSET_TYPE,
};
use weft_meta::{KeywordKind, MemberEncoding, ParamKind, UniformType};

/// The value a uniform member holds for this instance, as uploaded (the
/// JSON of `uniform_values`), and the constant folding puts in its place:
/// both through weft-meta's encoder (`weft_meta::uniform`), the constant
/// read back from the very bytes the runtime would upload. None for
/// parameters without a uniform member.
fn member_value(p: &Param, v: &ParamValue) -> Option<(ConstValue, Value)> {
    let upload = match (p.kind, v) {
        (ParamKind::Float, ParamValue::Float(x)) => Upload::Float(*x),
        (ParamKind::Int, ParamValue::Int(i)) => Upload::Int(*i),
        (ParamKind::Bool, ParamValue::Bool(b)) => Upload::Bool(*b),
        (ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4, ParamValue::Vector(xs)) => {
            Upload::Vector(xs.clone())
        }
        (ParamKind::Color, ParamValue::Vector(xs)) => Upload::Color {
            edited: xs.clone(),
            hdr: p.hdr,
        },
        (ParamKind::Curve, ParamValue::Curve(keys)) => {
            Upload::Curve(samples::sample_curve(keys, p.samples))
        }
        _ => return None,
    };
    let ty = p.kind.uniform_type(p.samples)?;
    encoded(&ty, p.kind.encoding()?, &upload)
}

/// `upload` encoded as a member of type `ty`: the folded constant (from the
/// bytes) and the value as scene metadata states it.
fn encoded(
    ty: &UniformType,
    encoding: MemberEncoding,
    upload: &Upload,
) -> Option<(ConstValue, Value)> {
    let value = encoding.value(upload).ok()?;
    let bytes = uniform::encode(ty, &value).ok()?;
    let mut words = bytes.chunks_exact(4).map(|w| [w[0], w[1], w[2], w[3]]);
    let constant = match ty {
        UniformType::Scalar(ScalarType::I32) => ConstValue::I32(i32::from_le_bytes(words.next()?)),
        UniformType::Scalar(ScalarType::U32) => ConstValue::U32(u32::from_le_bytes(words.next()?)),
        _ => ConstValue::F32(words.map(f32::from_le_bytes).collect()),
    };
    Some((constant, value.to_json()))
}

/// The frame-uniform members a scene with `[static_lighting]` folds into
/// every shader, as `weft-render` uploads them (`engine_uniforms.rs`): the
/// light's direction normalised in f32 and its radiance (`light`, defaults
/// filled in, as the scene metadata states it), and the SH coefficients
/// (`sh[i].xyz`, w = 0). Empty without `[static_lighting]`.
pub fn static_lighting_members(manifest: &SceneManifest) -> BTreeMap<String, ConstValue> {
    let mut out = BTreeMap::new();
    let Some(fixed) = &manifest.static_lighting else {
        return out;
    };
    let light = manifest.light_used();
    let d = light.direction.map(|c| c as f32);
    let length = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let unit = d.map(|c| c * (1.0 / length));
    out.insert(
        "light_direction".into(),
        ConstValue::F32(vec![unit[0], unit[1], unit[2], 0.0]),
    );
    if manifest.features.directional_lights > 0 {
        let c = light.color.unwrap_or(weft_meta::scene::DEFAULT_LIGHT_COLOR);
        out.insert(
            "light_color".into(),
            ConstValue::F32(vec![c[0] as f32, c[1] as f32, c[2] as f32, 0.0]),
        );
    }
    if let Some(sh) = &fixed.sh {
        let flat = sh
            .iter()
            .flat_map(|rgb| [rgb[0] as f32, rgb[1] as f32, rgb[2] as f32, 0.0])
            .collect();
        out.insert("sh".into(), ConstValue::F32(flat));
    }
    out
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
        keep_entry_points: Some(m.kept_entry_points(&VariantKey::of_values(
            m,
            tier,
            &inst.keywords,
        ))),
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
            && let Some((c, json)) = encoded(
                &TILING_OFFSET_TYPE,
                MemberEncoding::TilingOffset,
                // An image's scale and offset (`KHR_texture_transform`), else none.
                &Upload::TilingOffset(
                    inst.images
                        .get(&i)
                        .map_or(TILING_OFFSET_DEFAULT, |img| img.tiling),
                ),
            )
        {
            uniform.insert(st.name.clone(), json.clone());
            if !dynamic {
                fold.members.insert(st.name.clone(), c);
                // Recorded by member name: the tiling is no parameter.
                constants.insert(st.name.clone(), json);
            }
        }
        let set = inst.set.get(i).copied().unwrap_or(true);
        // A texture with an image (the scene's, or unset with its `file`)
        // stays bound to it: an image is no constant.
        if let (ParamKind::Texture2d | ParamKind::Cube, ParamValue::Texture(t)) = (p.kind, v)
            && !dynamic
            && !inst.images.contains_key(&i)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// The folded constant is what the encoder's bytes hold (the f32 the
    /// runtime uploads), the JSON the value as uploaded before rounding.
    #[test]
    fn folded_constants_are_the_encoders_bytes() {
        let (c, json) = encoded(
            &UniformType::vec_f32(4),
            MemberEncoding::Color,
            &Upload::Color {
                edited: vec![0.5, 0.0, 1.0, 0.25],
                hdr: false,
            },
        )
        .unwrap();
        // sRGB 0.5 is linear 0.21404114048223255, f32 bits 0x3E5B2D9A.
        assert_eq!(
            c,
            ConstValue::F32(vec![f32::from_bits(0x3E5B_2D9A), 0.0, 1.0, 0.25])
        );
        assert_eq!(json, json!([0.21404114048223255, 0.0, 1.0, 0.25]));
        let (c, json) = encoded(
            &UniformType::U32,
            MemberEncoding::BoolU32,
            &Upload::Bool(true),
        )
        .unwrap();
        assert_eq!((c, json), (ConstValue::U32(1), json!(1)));
        let (c, json) = encoded(&UniformType::I32, MemberEncoding::I32, &Upload::Int(-3)).unwrap();
        assert_eq!((c, json), (ConstValue::I32(-3), json!(-3)));
        // A value of the wrong kind folds nothing.
        assert!(encoded(&UniformType::F32, MemberEncoding::F32, &Upload::Bool(true)).is_none());
    }
}
