//! [`UniformValue`]s as scene metadata states them (`uniform_values`,
//! `constants`): to and from JSON numbers and arrays.

use super::{EncodeError, ScalarType, UniformType, UniformValue};

impl UniformValue {
    /// The value as scene metadata states it (`uniform_values`,
    /// `constants`): a number, or an array of numbers (f64 as edited, so
    /// the JSON keeps what the f32 rounds from).
    pub fn to_json(&self) -> serde_json::Value {
        match self {
            UniformValue::F32(x) => serde_json::json!(x),
            UniformValue::I32(i) => serde_json::json!(i),
            UniformValue::U32(u) => serde_json::json!(u),
            UniformValue::F32s(xs) => serde_json::json!(xs),
        }
    }

    /// A value as scene metadata states it, for a member of type `ty`: `f32`,
    /// `i32`, `u32` take a number (booleans as 0/1 or `true`/`false`),
    /// `vecN<f32>` and matrices an array of their numbers, `array<vec4<f32>,
    /// N>` the samples packed 4 per vec4 (a flat array whose last vec4 may be
    /// partly filled, or N arrays of 4).
    pub fn from_json(ty: &UniformType, v: &serde_json::Value) -> Result<UniformValue, EncodeError> {
        let expected = |what: &str| EncodeError(format!("expected {what} for {ty}, got {v}"));
        Ok(match ty {
            UniformType::Scalar(ScalarType::F32) => {
                UniformValue::F32(json_number(v).ok_or_else(|| expected("a number"))?)
            }
            UniformType::Scalar(ScalarType::I32) => UniformValue::I32(
                integer(v, f64::from(i32::MIN), f64::from(i32::MAX))
                    .ok_or_else(|| expected("an i32"))? as i32,
            ),
            UniformType::Scalar(ScalarType::U32) => UniformValue::U32(
                integer(v, 0.0, f64::from(u32::MAX)).ok_or_else(|| expected("a u32 (or a bool)"))?
                    as u32,
            ),
            UniformType::Array {
                element,
                count: Some(count),
            } if element.scalars().is_some() => {
                let (per, _) = element.scalars().unwrap_or((4, ScalarType::F32));
                UniformValue::F32s(json_rows(v, per as usize).ok_or_else(|| {
                    expected(&format!(
                        "at most {} numbers (or {count} arrays of {per})",
                        count * per
                    ))
                })?)
            }
            UniformType::Vector { .. } | UniformType::Matrix { .. } => {
                UniformValue::F32s(json_numbers(v).ok_or_else(|| expected("an array of numbers"))?)
            }
            _ => return Err(EncodeError(format!("a member of type {ty} takes no value"))),
        })
    }
}

/// A finite number, or a bool as 0/1 (JSON values as uploaded).
pub fn json_number(v: &serde_json::Value) -> Option<f64> {
    match v {
        serde_json::Value::Bool(b) => Some(f64::from(u8::from(*b))),
        _ => v.as_f64().filter(|x| x.is_finite()),
    }
}

fn integer(v: &serde_json::Value, lo: f64, hi: f64) -> Option<f64> {
    json_number(v).filter(|x| x.fract() == 0.0 && (lo..=hi).contains(x))
}

/// An array of [`json_number`]s.
pub fn json_numbers(v: &serde_json::Value) -> Option<Vec<f64>> {
    v.as_array()?.iter().map(json_number).collect()
}

/// Numbers written flat or as rows of `per` numbers, flattened.
pub fn json_rows(v: &serde_json::Value, per: usize) -> Option<Vec<f64>> {
    let arr = v.as_array()?;
    if !arr.is_empty() && arr.iter().all(serde_json::Value::is_array) {
        let mut out = Vec::with_capacity(per * arr.len());
        for row in arr {
            out.extend(json_numbers(row).filter(|x| x.len() == per)?);
        }
        Some(out)
    } else {
        json_numbers(v)
    }
}
