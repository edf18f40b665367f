//! Writing a material uniform block: the scene path (values by member, as
//! JSON: [`pack_uniform_values`]) beside the material path
//! (`Material::uniform_bytes`), both through weft-meta's one encoder
//! (`weft_meta::uniform`: member types, each parameter kind's rule, bytes at
//! the layout's offsets).

use crate::error::{Error, Result};
use std::collections::BTreeMap;
use weft_meta::uniform::{EncodeError, UniformValue, write_member};
use weft_meta::{UniformLayout, UniformMember};

pub use weft_meta::uniform::{json_number, json_numbers};

/// A metadata error from the encoder (a layout that does not fit its block,
/// a member of the wrong type).
impl From<EncodeError> for Error {
    fn from(e: EncodeError) -> Error {
        Error::Metadata(e.0)
    }
}

/// The material uniform of a scene instance: every member of `layout`
/// written from `values` (member name -> value as uploaded, see
/// `SceneInstance::uniform_values`), read by the member's type
/// (`weft_meta::UniformValue::from_json`: `f32`, `i32`, `u32` take a number,
/// booleans as 0/1 or `true`/`false`; `vecN<f32>` an array of N numbers;
/// `array<vec4<f32>, N>` the samples packed 4 per vec4, flat or as N arrays
/// of 4) and encoded at its offset. Values for members the layout does not
/// have are ignored: the shader no longer reads them.
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
        let value = UniformValue::from_json(&m.ty, v).map_err(|e| bad(m, e))?;
        write_member(&mut bytes, m, &value).map_err(|e| bad(m, e))?;
    }
    Ok(bytes)
}

fn bad(m: &UniformMember, e: EncodeError) -> Error {
    Error::InvalidValue {
        name: m.name.clone(),
        message: e.0,
    }
}

/// Samples packed 4 per vec4, written flat or as rows of 4 numbers.
pub fn json_samples(v: &serde_json::Value) -> Option<Vec<f64>> {
    weft_meta::uniform::json_rows(v, 4)
}
