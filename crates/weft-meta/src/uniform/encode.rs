//! The one encoder: a [`UniformValue`] to a member's little-endian bytes
//! ([`encode`]), written at its offset ([`write_member`]) or a whole block
//! packed at the layout's offsets ([`pack`]).

use super::{EncodeError, ScalarType, UniformType, UniformValue};
use crate::{UniformLayout, UniformMember};

/// `value` as the little-endian bytes of a member of type `ty`: exactly
/// `ty.size()` bytes (vec3: 12; matrices with their column padding; arrays
/// with their stride, a partly given last element zero-filled).
pub fn encode(ty: &UniformType, value: &UniformValue) -> Result<Vec<u8>, EncodeError> {
    let mismatch = || EncodeError(format!("{} does not hold {}", ty, value.describe()));
    match (ty, value) {
        (UniformType::Scalar(ScalarType::F32), UniformValue::F32(x)) => {
            Ok((*x as f32).to_le_bytes().to_vec())
        }
        (UniformType::Scalar(ScalarType::I32), UniformValue::I32(i)) => {
            Ok(i.to_le_bytes().to_vec())
        }
        (UniformType::Scalar(ScalarType::U32), UniformValue::U32(u)) => {
            Ok(u.to_le_bytes().to_vec())
        }
        (
            UniformType::Vector {
                scalar: ScalarType::F32,
                ..
            }
            | UniformType::Matrix {
                scalar: ScalarType::F32,
                ..
            },
            UniformValue::F32s(xs),
        ) => {
            let (n, _) = ty.scalars().ok_or_else(mismatch)?;
            if xs.len() != n as usize {
                return Err(EncodeError(format!(
                    "{ty} holds {n} numbers, got {}",
                    xs.len()
                )));
            }
            let mut out = vec![0u8; ty.size().ok_or_else(mismatch)? as usize];
            let rows = match ty {
                UniformType::Matrix { rows, .. } => usize::from(*rows),
                _ => n as usize,
            };
            let stride = ty.column_stride(ScalarType::F32).max(4 * rows as u32) as usize;
            for (i, x) in xs.iter().enumerate() {
                let at = (i / rows) * stride + (i % rows) * 4;
                out[at..at + 4].copy_from_slice(&(*x as f32).to_le_bytes());
            }
            Ok(out)
        }
        (
            UniformType::Array {
                element,
                count: Some(count),
            },
            UniformValue::F32s(xs),
        ) => {
            let (per, scalar) = element.scalars().ok_or_else(mismatch)?;
            if scalar != ScalarType::F32 {
                return Err(mismatch());
            }
            if xs.len().div_ceil(per as usize) != *count as usize {
                return Err(EncodeError(format!(
                    "{ty} holds at most {} numbers (or {count} arrays of {per}; only the last \
                     element partly given), got {}",
                    count * per,
                    xs.len()
                )));
            }
            let stride = element.stride().ok_or_else(mismatch)? as usize;
            let mut out = vec![0u8; stride * *count as usize];
            for (i, chunk) in xs.chunks(per as usize).enumerate() {
                let mut full = chunk.to_vec();
                full.resize(per as usize, 0.0);
                let bytes = encode(element, &UniformValue::F32s(full))?;
                out[i * stride..i * stride + bytes.len()].copy_from_slice(&bytes);
            }
            Ok(out)
        }
        _ => Err(mismatch()),
    }
}

/// Writes `value` into `bytes` at `member`'s offset, checked against its
/// type and size; the error names the member.
pub fn write_member(
    bytes: &mut [u8],
    member: &UniformMember,
    value: &UniformValue,
) -> Result<(), EncodeError> {
    let named = |e: EncodeError| EncodeError(format!("uniform member `{}`: {e}", member.name));
    let data = encode(&member.ty, value).map_err(named)?;
    if data.len() > member.size as usize {
        return Err(named(EncodeError(format!(
            "{} bytes of data for a {}-byte member of type `{}`",
            data.len(),
            member.size,
            member.ty
        ))));
    }
    let o = member.offset as usize;
    match o.checked_add(data.len()).filter(|&e| e <= bytes.len()) {
        Some(end) => {
            bytes[o..end].copy_from_slice(&data);
            Ok(())
        }
        None => Err(named(EncodeError(format!(
            "a {}-byte write at offset {} overruns the {}-byte uniform block",
            data.len(),
            member.offset,
            bytes.len()
        )))),
    }
}

/// A uniform block of `layout.size` bytes with every member `value_of`
/// gives a value written at its offset (a member it gives None stays 0).
pub fn pack<E: From<EncodeError>>(
    layout: &UniformLayout,
    mut value_of: impl FnMut(&UniformMember) -> Result<Option<UniformValue>, E>,
) -> Result<Vec<u8>, E> {
    let mut bytes = vec![0u8; layout.size as usize];
    for m in &layout.members {
        if let Some(v) = value_of(m)? {
            write_member(&mut bytes, m, &v)?;
        }
    }
    Ok(bytes)
}

impl UniformValue {
    pub(super) fn describe(&self) -> String {
        match self {
            UniformValue::F32(x) => format!("the f32 {x}"),
            UniformValue::I32(i) => format!("the i32 {i}"),
            UniformValue::U32(u) => format!("the u32 {u}"),
            UniformValue::F32s(xs) => format!("{} f32 numbers", xs.len()),
        }
    }
}
