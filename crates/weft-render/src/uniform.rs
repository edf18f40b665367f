//! Writing a material uniform block: the byte helpers the material path
//! (values by parameter, `Material::uniform_bytes`) and the scene path
//! (values by member, as JSON: [`pack_uniform_values`]) share.

use crate::error::{Error, Result};
use std::collections::BTreeMap;
use weft_meta::{UniformLayout, UniformMember};

/// Copies `data` to `offset`; an error (never a panic) when it does not fit.
pub(crate) fn put(bytes: &mut [u8], offset: u32, data: &[u8]) -> Result<()> {
    let o = offset as usize;
    let end = o.checked_add(data.len()).filter(|&e| e <= bytes.len());
    match end {
        Some(end) => {
            bytes[o..end].copy_from_slice(data);
            Ok(())
        }
        None => Err(Error::Metadata(format!(
            "a {}-byte write at offset {offset} overruns the {}-byte uniform block",
            data.len(),
            bytes.len()
        ))),
    }
}

/// Writes `v` as consecutive little-endian f32s from `offset`.
pub(crate) fn write_f32s(bytes: &mut [u8], offset: u32, v: &[f64]) -> Result<()> {
    let data: Vec<u8> = v.iter().flat_map(|x| (*x as f32).to_le_bytes()).collect();
    put(bytes, offset, &data)
}

/// A member's WGSL type, as far as uniform packing cares.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum MemberType {
    F32,
    I32,
    U32,
    /// `vecN<f32>`.
    Vec(usize),
    /// `array<vec4<f32>, N>` (curve samples, 4 per element).
    Vec4Array(usize),
}

fn member_type(ty: &str) -> Option<MemberType> {
    let t: String = ty.chars().filter(|c| !c.is_whitespace()).collect();
    Some(match t.as_str() {
        "f32" => MemberType::F32,
        "i32" => MemberType::I32,
        "u32" => MemberType::U32,
        "vec2<f32>" | "vec2f" => MemberType::Vec(2),
        "vec3<f32>" | "vec3f" => MemberType::Vec(3),
        "vec4<f32>" | "vec4f" => MemberType::Vec(4),
        _ => {
            let n = t
                .strip_prefix("array<vec4<f32>,")
                .or_else(|| t.strip_prefix("array<vec4f,"))?
                .strip_suffix('>')?
                .parse::<usize>()
                .ok()?;
            MemberType::Vec4Array(n)
        }
    })
}

/// The material uniform of a scene instance: every member of `layout`
/// written from `values` (member name -> value as uploaded, see
/// `SceneInstance::uniform_values`) by the member's WGSL type: `f32`, `i32`,
/// `u32` take a number (booleans as 0/1 or `true`/`false`), `vecN<f32>` an
/// array of N numbers, `array<vec4<f32>, N>` the samples packed 4 per vec4
/// (a flat array of at most 4N numbers whose last vec4 is partly filled, or N
/// arrays of 4). Values for members the layout does not have are ignored:
/// the shader no longer reads them.
pub fn pack_uniform_values(
    layout: &UniformLayout,
    values: &BTreeMap<String, serde_json::Value>,
) -> Result<Vec<u8>> {
    let mut bytes = vec![0u8; layout.size as usize];
    for m in &layout.members {
        let v = values.get(&m.name).ok_or_else(|| {
            Error::Metadata(format!(
                "uniform member `{}` ({}) has no value in `uniform_values`",
                m.name, m.ty
            ))
        })?;
        write_member(&mut bytes, m, v)?;
    }
    Ok(bytes)
}

fn write_member(bytes: &mut [u8], m: &UniformMember, v: &serde_json::Value) -> Result<()> {
    let bad = |message: String| Error::InvalidValue {
        name: m.name.clone(),
        message,
    };
    let ty = member_type(&m.ty)
        .ok_or_else(|| bad(format!("uniform member type `{}` is not supported", m.ty)))?;
    let data: Vec<u8> = match ty {
        MemberType::F32 => (json_number(v).ok_or_else(|| bad(expected("a number", v)))? as f32)
            .to_le_bytes()
            .to_vec(),
        MemberType::I32 => {
            let x = integer(v, f64::from(i32::MIN), f64::from(i32::MAX))
                .ok_or_else(|| bad(expected("an i32", v)))?;
            (x as i32).to_le_bytes().to_vec()
        }
        MemberType::U32 => {
            let x = integer(v, 0.0, f64::from(u32::MAX))
                .ok_or_else(|| bad(expected("a u32 (or a bool)", v)))?;
            (x as u32).to_le_bytes().to_vec()
        }
        MemberType::Vec(n) => {
            let nums = json_numbers(v).filter(|x| x.len() == n).ok_or_else(|| {
                bad(expected(
                    &format!("an array of {n} numbers for {}", m.ty),
                    v,
                ))
            })?;
            nums.iter()
                .flat_map(|x| (*x as f32).to_le_bytes())
                .collect()
        }
        MemberType::Vec4Array(n) => {
            let samples = packed_samples(v, n).ok_or_else(|| {
                bad(expected(
                    &format!(
                        "at most {} numbers (or {n} arrays of 4) for {}",
                        4 * n,
                        m.ty
                    ),
                    v,
                ))
            })?;
            samples
                .iter()
                .flat_map(|x| (*x as f32).to_le_bytes())
                .collect()
        }
    };
    if data.len() > m.size as usize {
        return Err(bad(format!(
            "{} bytes of data for a {}-byte member of type `{}`",
            data.len(),
            m.size,
            m.ty
        )));
    }
    put(bytes, m.offset, &data).map_err(|e| bad(e.to_string()))
}

fn expected(what: &str, got: &serde_json::Value) -> String {
    format!("expected {what}, got {got}")
}

/// A finite number, or a bool as 0/1 (JSON values as uploaded).
pub(crate) fn json_number(v: &serde_json::Value) -> Option<f64> {
    match v {
        serde_json::Value::Bool(b) => Some(f64::from(u8::from(*b))),
        _ => v.as_f64().filter(|x| x.is_finite()),
    }
}

fn integer(v: &serde_json::Value, lo: f64, hi: f64) -> Option<f64> {
    json_number(v).filter(|x| x.fract() == 0.0 && (lo..=hi).contains(x))
}

/// An array of [`json_number`]s.
pub(crate) fn json_numbers(v: &serde_json::Value) -> Option<Vec<f64>> {
    v.as_array()?.iter().map(json_number).collect()
}

/// Samples packed 4 per vec4, written flat or as rows of 4 numbers.
pub(crate) fn json_samples(v: &serde_json::Value) -> Option<Vec<f64>> {
    let arr = v.as_array()?;
    if !arr.is_empty() && arr.iter().all(serde_json::Value::is_array) {
        let mut out = Vec::with_capacity(4 * arr.len());
        for row in arr {
            out.extend(json_numbers(row).filter(|x| x.len() == 4)?);
        }
        Some(out)
    } else {
        json_numbers(v)
    }
}

/// Curve samples for an `array<vec4<f32>, n>`, padded to 4n (only the last
/// vec4 may be partly filled).
fn packed_samples(v: &serde_json::Value, n: usize) -> Option<Vec<f64>> {
    let mut flat = json_samples(v)?;
    if flat.len().div_ceil(4) != n {
        return None;
    }
    flat.resize(4 * n, 0.0);
    Some(flat)
}
