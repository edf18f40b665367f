//! Uniform members and the one encoder from parameter values to uniform bytes.
//!
//! This is the bridge between the compiler and every runtime (as Filament's
//! `filabridge` is between `matc` and its engine):
//!
//! - [`UniformType`]: a member's WGSL type, typed. It serialises to the same
//!   string the metadata has always written (`vec4<f32>`,
//!   `array<vec4<f32>, 9>`, …), so readers never parse type strings.
//! - [`ParamKind::uniform_type`] and [`ParamKind::encoding`]: each
//!   parameter kind's member type and upload encoding, stated once (the
//!   compiler's prelude declares the struct from them, reflection records
//!   them, the runtime checks against them).
//! - [`MemberEncoding::value`]: a parameter's value (as edited) to the value
//!   its member holds ([`UniformValue`]: colours linearised, booleans 0/1).
//! - [`encode`], [`write_member`] and [`pack`]: a [`UniformValue`] to the
//!   member's little-endian bytes, at the layout's offsets.
//!
//! The compiler's scene folding folds the constants these bytes hold
//! (bit for bit what the runtime uploads) and writes [`UniformValue::to_json`]
//! into scene metadata; weft-render packs a material's uniform block and a
//! scene instance's `uniform_values` with the same functions.

use crate::{MemberEncoding, ParamKind};
use std::fmt;

mod encode;
mod json;
#[cfg(test)]
mod tests;
mod types;

pub use encode::{encode, pack, write_member};
pub use json::{json_number, json_numbers, json_rows};
pub use types::{ScalarType, TypeParseError, UniformType};

/// What a texture's tiling member (`texture.tiling_member`) holds while
/// unset: tiling (1, 1), offset (0, 0).
pub const TILING_OFFSET_DEFAULT: [f64; 4] = [1.0, 1.0, 0.0, 0.0];

/// The uniform member type of a texture's tiling and offset
/// ([`MemberEncoding::TilingOffset`]).
pub const TILING_OFFSET_TYPE: UniformType = UniformType::vec_f32(4);

impl ParamKind {
    /// The WGSL type of the parameter's uniform member: `float` `f32`,
    /// `int` `i32`, `bool` `u32`, `vecN` `vecN<f32>`, `color` `vec4<f32>`,
    /// `curve` `array<vec4<f32>, ceil(samples / 4)>` (the samples packed 4
    /// per element). None for the kinds bound as textures.
    pub fn uniform_type(self, curve_samples: u32) -> Option<UniformType> {
        Some(match self {
            ParamKind::Float => UniformType::F32,
            ParamKind::Int => UniformType::I32,
            ParamKind::Bool => UniformType::U32,
            ParamKind::Vec2 => UniformType::vec_f32(2),
            ParamKind::Vec3 => UniformType::vec_f32(3),
            ParamKind::Vec4 | ParamKind::Color => UniformType::vec_f32(4),
            ParamKind::Curve => {
                UniformType::array(UniformType::vec_f32(4), curve_samples.div_ceil(4))
            }
            ParamKind::Texture2d | ParamKind::Cube | ParamKind::Gradient => return None,
        })
    }

    /// How the parameter's value becomes its member's bytes (None for the
    /// kinds bound as textures; a texture's tiling member is
    /// [`MemberEncoding::TilingOffset`]).
    pub fn encoding(self) -> Option<MemberEncoding> {
        Some(match self {
            ParamKind::Float => MemberEncoding::F32,
            ParamKind::Int => MemberEncoding::I32,
            ParamKind::Bool => MemberEncoding::BoolU32,
            ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 => MemberEncoding::Vector,
            ParamKind::Color => MemberEncoding::Color,
            ParamKind::Curve => MemberEncoding::Curve,
            ParamKind::Texture2d | ParamKind::Cube | ParamKind::Gradient => return None,
        })
    }
}

/// A parameter's value as the encoder takes it (the kinds with a uniform
/// member). Numbers are f64 as edited; the encoder rounds them to the
/// member's type.
#[derive(Clone, Debug, PartialEq)]
pub enum ParamValue {
    Float(f64),
    Int(i64),
    Bool(bool),
    /// `vec2`/`vec3`/`vec4` components.
    Vector(Vec<f64>),
    /// A colour as edited: RGB sRGB-encoded unless `hdr` (then linear),
    /// alpha as is (1 when only RGB is given).
    Color {
        edited: Vec<f64>,
        hdr: bool,
    },
    /// A colour already in linear space (alpha as is).
    LinearColor([f64; 4]),
    /// A curve's baked samples (`curve.samples` of them).
    Curve(Vec<f64>),
    /// A texture's tiling (xy) and offset (zw).
    TilingOffset([f64; 4]),
}

/// A value that does not fit the member it is written to.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct EncodeError(pub String);

impl fmt::Display for EncodeError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for EncodeError {}

/// The value a uniform member holds, as uploaded: what [`encode`] writes
/// and scene metadata's `uniform_values` state.
#[derive(Clone, Debug, PartialEq)]
pub enum UniformValue {
    /// An `f32` member.
    F32(f64),
    /// An `i32` member.
    I32(i32),
    /// A `u32` member (booleans 0 or 1).
    U32(u32),
    /// The f32 components of a `vecN<f32>`, `matCxR<f32>` (column-major) or
    /// `array<vec4<f32>, N>` member, in order; an array's last element may be
    /// partly given (the rest is 0).
    F32s(Vec<f64>),
}

impl MemberEncoding {
    /// The value a member with this encoding holds for `value`: the rule of
    /// each parameter kind, stated once.
    pub fn value(self, value: &ParamValue) -> Result<UniformValue, EncodeError> {
        let wrong = || {
            EncodeError(format!(
                "a {value:?} does not go into a member encoded `{}`",
                self.name()
            ))
        };
        Ok(match (self, value) {
            (MemberEncoding::F32, ParamValue::Float(x)) => UniformValue::F32(*x),
            (MemberEncoding::I32, ParamValue::Int(i)) => UniformValue::I32(
                i32::try_from(*i).map_err(|_| EncodeError(format!("{i} does not fit an i32")))?,
            ),
            (MemberEncoding::BoolU32, ParamValue::Bool(b)) => UniformValue::U32(u32::from(*b)),
            (MemberEncoding::Vector, ParamValue::Vector(xs)) => UniformValue::F32s(xs.clone()),
            (MemberEncoding::Color, ParamValue::Color { edited, hdr }) => {
                UniformValue::F32s(color_as_uploaded(edited, *hdr).to_vec())
            }
            (MemberEncoding::Color, ParamValue::LinearColor(c)) => UniformValue::F32s(c.to_vec()),
            (MemberEncoding::Curve, ParamValue::Curve(samples)) => {
                UniformValue::F32s(samples.clone())
            }
            (MemberEncoding::TilingOffset, ParamValue::TilingOffset(st)) => {
                UniformValue::F32s(st.to_vec())
            }
            _ => return Err(wrong()),
        })
    }

    /// The encoding's name in JSON.
    pub fn name(self) -> &'static str {
        match self {
            MemberEncoding::F32 => "f32",
            MemberEncoding::I32 => "i32",
            MemberEncoding::BoolU32 => "bool_u32",
            MemberEncoding::Vector => "vector",
            MemberEncoding::Color => "color",
            MemberEncoding::Curve => "curve",
            MemberEncoding::TilingOffset => "tiling_offset",
        }
    }
}

/// A colour as uploaded: RGB from the sRGB-encoded value to linear (unless
/// `hdr`: edited linear, written as is), alpha as is (1 when absent).
pub fn color_as_uploaded(edited: &[f64], hdr: bool) -> [f64; 4] {
    std::array::from_fn(|i| {
        let x = edited.get(i).copied().unwrap_or(1.0);
        if i < 3 && !hdr {
            crate::bake::srgb_to_linear(x)
        } else {
            x
        }
    })
}
