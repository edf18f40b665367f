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

use crate::{MemberEncoding, ParamKind, UniformLayout, UniformMember};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::fmt;

/// A scalar type of WGSL that buffer members are built from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ScalarType {
    /// `f32`.
    F32,
    /// `f16` (device feature `shader-f16`).
    F16,
    /// `i32`.
    I32,
    /// `u32`.
    U32,
    /// `bool` (not host-shareable; never in a uniform weft writes).
    Bool,
}

impl ScalarType {
    /// The WGSL spelling.
    pub fn name(self) -> &'static str {
        match self {
            ScalarType::F32 => "f32",
            ScalarType::F16 => "f16",
            ScalarType::I32 => "i32",
            ScalarType::U32 => "u32",
            ScalarType::Bool => "bool",
        }
    }

    /// Size in bytes in a buffer (WGSL host-shareable layout).
    pub fn size(self) -> u32 {
        match self {
            ScalarType::F16 => 2,
            _ => 4,
        }
    }

    const ALL: [ScalarType; 5] = [
        ScalarType::F32,
        ScalarType::F16,
        ScalarType::I32,
        ScalarType::U32,
        ScalarType::Bool,
    ];
}

/// The WGSL type of a buffer struct member ([`UniformMember::ty`]), typed.
///
/// In JSON it is the WGSL spelling weft writes: `f32`, `vec4<f32>`,
/// `mat4x4<f32>`, `array<vec4<f32>, 9>`, `array<f32>` (runtime-sized, storage
/// buffers), `atomic<u32>`, or a struct's name.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum UniformType {
    /// A scalar: `f32`, `i32`, `u32`, `f16`.
    Scalar(ScalarType),
    /// `vecN<T>`, N in 2..=4.
    Vector { size: u8, scalar: ScalarType },
    /// `matCxR<T>` (column-major; C, R in 2..=4).
    Matrix {
        columns: u8,
        rows: u8,
        scalar: ScalarType,
    },
    /// `array<T, N>`, or `array<T>` (runtime-sized: `count` None).
    Array {
        element: Box<UniformType>,
        count: Option<u32>,
    },
    /// `atomic<T>`.
    Atomic(ScalarType),
    /// A struct, by its WGSL name.
    Struct(String),
}

impl UniformType {
    /// `f32`.
    pub const F32: UniformType = UniformType::Scalar(ScalarType::F32);
    /// `i32`.
    pub const I32: UniformType = UniformType::Scalar(ScalarType::I32);
    /// `u32`.
    pub const U32: UniformType = UniformType::Scalar(ScalarType::U32);

    /// `vecN<f32>`.
    pub const fn vec_f32(size: u8) -> UniformType {
        UniformType::Vector {
            size,
            scalar: ScalarType::F32,
        }
    }

    /// `matCxR<f32>`.
    pub const fn mat_f32(columns: u8, rows: u8) -> UniformType {
        UniformType::Matrix {
            columns,
            rows,
            scalar: ScalarType::F32,
        }
    }

    /// `array<element, count>`.
    pub fn array(element: UniformType, count: u32) -> UniformType {
        UniformType::Array {
            element: Box::new(element),
            count: Some(count),
        }
    }

    /// Size in bytes by WGSL's uniform-buffer rules (arrays: stride ×
    /// count); None for runtime-sized arrays and structs, whose size the
    /// layout states.
    pub fn size(&self) -> Option<u32> {
        match self {
            UniformType::Scalar(s) | UniformType::Atomic(s) => Some(s.size()),
            UniformType::Vector { size, scalar } => Some(u32::from(*size) * scalar.size()),
            UniformType::Matrix {
                columns, scalar, ..
            } => Some(u32::from(*columns) * self.column_stride(*scalar)),
            UniformType::Array { element, count } => Some(count.as_ref()? * element.stride()?),
            UniformType::Struct(_) => None,
        }
    }

    /// Alignment in bytes (WGSL rules; vec3 aligns to 16).
    fn align(&self) -> Option<u32> {
        match self {
            UniformType::Scalar(s) | UniformType::Atomic(s) => Some(s.size()),
            UniformType::Vector { size, scalar } => {
                Some(if *size == 2 { 2 } else { 4 } * scalar.size())
            }
            UniformType::Matrix { rows, scalar, .. } => UniformType::Vector {
                size: *rows,
                scalar: *scalar,
            }
            .align(),
            UniformType::Array { element, .. } => element.align(),
            UniformType::Struct(_) => None,
        }
    }

    fn column_stride(&self, scalar: ScalarType) -> u32 {
        match self {
            UniformType::Matrix { rows, .. } => {
                let column = UniformType::Vector {
                    size: *rows,
                    scalar,
                };
                column.align().unwrap_or(16)
            }
            _ => 0,
        }
    }

    /// The stride of this type as an array element in a uniform buffer:
    /// its size rounded up to its alignment, then to 16.
    fn stride(&self) -> Option<u32> {
        let (size, align) = (self.size()?, self.align()?);
        Some(size.next_multiple_of(align).next_multiple_of(16))
    }

    /// Number of scalars the type holds (arrays: elements × scalars each).
    fn scalars(&self) -> Option<(u32, ScalarType)> {
        match self {
            UniformType::Scalar(s) => Some((1, *s)),
            UniformType::Vector { size, scalar } => Some((u32::from(*size), *scalar)),
            UniformType::Matrix {
                columns,
                rows,
                scalar,
            } => Some((u32::from(*columns) * u32::from(*rows), *scalar)),
            _ => None,
        }
    }
}

impl fmt::Display for UniformType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            UniformType::Scalar(s) => f.write_str(s.name()),
            UniformType::Vector { size, scalar } => write!(f, "vec{size}<{}>", scalar.name()),
            UniformType::Matrix {
                columns,
                rows,
                scalar,
            } => write!(f, "mat{columns}x{rows}<{}>", scalar.name()),
            UniformType::Array {
                element,
                count: Some(n),
            } => write!(f, "array<{element}, {n}>"),
            UniformType::Array {
                element,
                count: None,
            } => write!(f, "array<{element}>"),
            UniformType::Atomic(s) => write!(f, "atomic<{}>", s.name()),
            UniformType::Struct(name) => f.write_str(name),
        }
    }
}

/// A type string that is not one [`UniformType`] writes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TypeParseError(pub String);

impl fmt::Display for TypeParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "`{}` is not a WGSL buffer member type weft writes",
            self.0
        )
    }
}

impl std::error::Error for TypeParseError {}

impl std::str::FromStr for UniformType {
    type Err = TypeParseError;

    /// Exactly the spellings [`fmt::Display`] writes (what metadata holds).
    fn from_str(s: &str) -> Result<UniformType, TypeParseError> {
        parse_type(s).ok_or_else(|| TypeParseError(s.to_string()))
    }
}

fn parse_scalar(s: &str) -> Option<ScalarType> {
    ScalarType::ALL.into_iter().find(|t| t.name() == s)
}

fn dim(c: char) -> Option<u8> {
    c.to_digit(10)
        .map(|d| d as u8)
        .filter(|d| (2..=4).contains(d))
}

fn parse_type(s: &str) -> Option<UniformType> {
    if let Some(scalar) = parse_scalar(s) {
        return Some(UniformType::Scalar(scalar));
    }
    if let Some(rest) = s.strip_prefix("array<").and_then(|r| r.strip_suffix('>')) {
        // The element may itself hold `, ` (nested arrays): split at the last.
        return Some(match rest.rsplit_once(", ") {
            Some((element, n)) if n.bytes().all(|b| b.is_ascii_digit()) && !n.is_empty() => {
                UniformType::Array {
                    element: Box::new(parse_type(element)?),
                    count: Some(n.parse().ok()?),
                }
            }
            _ => UniformType::Array {
                element: Box::new(parse_type(rest)?),
                count: None,
            },
        });
    }
    if let Some(rest) = s.strip_prefix("atomic<").and_then(|r| r.strip_suffix('>')) {
        return Some(UniformType::Atomic(parse_scalar(rest)?));
    }
    if let Some(rest) = s.strip_prefix("vec") {
        let mut chars = rest.chars();
        let size = dim(chars.next()?)?;
        let scalar = parse_scalar(chars.as_str().strip_prefix('<')?.strip_suffix('>')?)?;
        return Some(UniformType::Vector { size, scalar });
    }
    if let Some(rest) = s.strip_prefix("mat") {
        let mut chars = rest.chars();
        let columns = dim(chars.next()?)?;
        (chars.next()? == 'x').then_some(())?;
        let rows = dim(chars.next()?)?;
        let scalar = parse_scalar(chars.as_str().strip_prefix('<')?.strip_suffix('>')?)?;
        return Some(UniformType::Matrix {
            columns,
            rows,
            scalar,
        });
    }
    let ident = !s.is_empty()
        && !s.starts_with(|c: char| c.is_ascii_digit())
        && s.chars().all(|c| c.is_alphanumeric() || c == '_');
    ident.then(|| UniformType::Struct(s.to_string()))
}

impl Serialize for UniformType {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

impl<'de> Deserialize<'de> for UniformType {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<UniformType, D::Error> {
        let s = String::deserialize(deserializer)?;
        s.parse().map_err(serde::de::Error::custom)
    }
}

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
    fn describe(&self) -> String {
        match self {
            UniformValue::F32(x) => format!("the f32 {x}"),
            UniformValue::I32(i) => format!("the i32 {i}"),
            UniformValue::U32(u) => format!("the u32 {u}"),
            UniformValue::F32s(xs) => format!("{} f32 numbers", xs.len()),
        }
    }

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

#[cfg(test)]
mod tests {
    use super::*;

    /// Little-endian f32 bytes, written out by hand from the IEEE bits.
    fn f(bits: u32) -> [u8; 4] {
        bits.to_le_bytes()
    }

    fn member(name: &str, ty: UniformType, offset: u32, size: u32) -> UniformMember {
        UniformMember {
            name: name.into(),
            ty,
            offset,
            size,
            align: 4,
            parameter: None,
            encoding: None,
            description: None,
        }
    }

    /// Every parameter kind with a uniform member, through the kind's own
    /// type and encoding, against bytes written by hand.
    #[test]
    fn every_kind_encodes_to_hand_written_bytes() {
        let cases: Vec<(ParamKind, u32, ParamValue, Vec<u8>)> = vec![
            // 1.5 = 0x3FC00000.
            (
                ParamKind::Float,
                0,
                ParamValue::Float(1.5),
                vec![0x00, 0x00, 0xC0, 0x3F],
            ),
            // -2 as i32: two's complement.
            (
                ParamKind::Int,
                0,
                ParamValue::Int(-2),
                vec![0xFE, 0xFF, 0xFF, 0xFF],
            ),
            (
                ParamKind::Bool,
                0,
                ParamValue::Bool(true),
                vec![0x01, 0x00, 0x00, 0x00],
            ),
            (
                ParamKind::Bool,
                0,
                ParamValue::Bool(false),
                vec![0x00, 0x00, 0x00, 0x00],
            ),
            // 1.0 = 0x3F800000, 2.0 = 0x40000000.
            (
                ParamKind::Vec2,
                0,
                ParamValue::Vector(vec![1.0, 2.0]),
                [f(0x3F80_0000), f(0x4000_0000)].concat(),
            ),
            // vec3: 12 bytes (the 16-byte alignment is the layout's business).
            (
                ParamKind::Vec3,
                0,
                ParamValue::Vector(vec![0.5, -1.0, 0.0]),
                [f(0x3F00_0000), f(0xBF80_0000), f(0)].concat(),
            ),
            (
                ParamKind::Vec4,
                0,
                ParamValue::Vector(vec![0.25, 4.0, -0.5, 8.0]),
                [
                    f(0x3E80_0000),
                    f(0x4080_0000),
                    f(0xBF00_0000),
                    f(0x4100_0000),
                ]
                .concat(),
            ),
            // sRGB 1.0 and 0.0 are linear 1.0 and 0.0; alpha 0.5 as is; sRGB
            // 0.5 is linear 0.21404114 = f32 0x3E5B2D9A (rounded;
            // Python: struct.pack("<f", ((0.5 + 0.055) / 1.055) ** 2.4)).
            (
                ParamKind::Color,
                0,
                ParamValue::Color {
                    edited: vec![1.0, 0.0, 0.5, 0.5],
                    hdr: false,
                },
                [f(0x3F80_0000), f(0), f(0x3E5B_2D9A), f(0x3F00_0000)].concat(),
            ),
            // HDR colours are linear as edited; three components: alpha 1.
            (
                ParamKind::Color,
                0,
                ParamValue::Color {
                    edited: vec![2.0, 0.5, 0.0],
                    hdr: true,
                },
                [f(0x4000_0000), f(0x3F00_0000), f(0), f(0x3F80_0000)].concat(),
            ),
            (
                ParamKind::Color,
                0,
                ParamValue::LinearColor([0.25, 0.5, 1.0, 1.0]),
                [
                    f(0x3E80_0000),
                    f(0x3F00_0000),
                    f(0x3F80_0000),
                    f(0x3F80_0000),
                ]
                .concat(),
            ),
            // 5 samples: array<vec4<f32>, 2>, sample i at [i / 4][i % 4], the tail 0.
            (
                ParamKind::Curve,
                5,
                ParamValue::Curve(vec![0.0, 0.25, 0.5, 0.75, 1.0]),
                [
                    f(0),
                    f(0x3E80_0000),
                    f(0x3F00_0000),
                    f(0x3F40_0000),
                    f(0x3F80_0000),
                    f(0),
                    f(0),
                    f(0),
                ]
                .concat(),
            ),
        ];
        for (kind, samples, value, expected) in cases {
            let ty = kind.uniform_type(samples).expect("a uniform kind");
            let encoding = kind.encoding().expect("a uniform kind");
            let v = encoding.value(&value).expect("fits the kind");
            let bytes = encode(&ty, &v).expect("encodes");
            assert_eq!(bytes, expected, "{kind:?} {value:?}");
            assert_eq!(Some(bytes.len() as u32), ty.size(), "{kind:?}");
        }
        // A texture's tiling member.
        let v = MemberEncoding::TilingOffset
            .value(&ParamValue::TilingOffset(TILING_OFFSET_DEFAULT))
            .unwrap();
        assert_eq!(
            encode(&TILING_OFFSET_TYPE, &v).unwrap(),
            [f(0x3F80_0000), f(0x3F80_0000), f(0), f(0)].concat()
        );
        // The kinds bound as textures have no member.
        for kind in [ParamKind::Texture2d, ParamKind::Cube, ParamKind::Gradient] {
            assert_eq!(kind.uniform_type(4), None);
            assert_eq!(kind.encoding(), None);
        }
    }

    #[test]
    fn values_that_do_not_fit_are_errors() {
        assert!(
            MemberEncoding::I32
                .value(&ParamValue::Int(1 << 40))
                .is_err()
        );
        assert!(MemberEncoding::F32.value(&ParamValue::Bool(true)).is_err());
        assert!(encode(&UniformType::F32, &UniformValue::I32(1)).is_err());
        assert!(encode(&UniformType::vec_f32(3), &UniformValue::F32s(vec![1.0; 4])).is_err());
        let curve = ParamKind::Curve.uniform_type(8).unwrap();
        assert!(encode(&curve, &UniformValue::F32s(vec![0.0; 4])).is_err());
        assert!(encode(&curve, &UniformValue::F32s(vec![0.0; 9])).is_err());
    }

    #[test]
    fn matrices_pad_their_columns() {
        let m3: Vec<f64> = (1..=9).map(f64::from).collect();
        let bytes = encode(&UniformType::mat_f32(3, 3), &UniformValue::F32s(m3)).unwrap();
        assert_eq!(bytes.len(), 48);
        assert_eq!(&bytes[12..16], &[0; 4]);
        assert_eq!(&bytes[16..20], &4f32.to_le_bytes());
        let m4: Vec<f64> = (0..16).map(f64::from).collect();
        let bytes = encode(&UniformType::mat_f32(4, 4), &UniformValue::F32s(m4)).unwrap();
        assert_eq!(&bytes[60..64], &15f32.to_le_bytes());
    }

    #[test]
    fn pack_writes_at_the_layout_offsets() {
        let layout = UniformLayout {
            struct_name: "WeftMaterial".into(),
            size: 32,
            align: 16,
            members: vec![
                member("tint", UniformType::vec_f32(3), 0, 12),
                member("roughness", UniformType::F32, 12, 4),
                member("layers", UniformType::I32, 16, 4),
            ],
        };
        let bytes = pack::<EncodeError>(&layout, |m| {
            Ok(Some(match m.name.as_str() {
                "tint" => UniformValue::F32s(vec![1.0, 0.0, 0.0]),
                "roughness" => UniformValue::F32(0.5),
                _ => UniformValue::I32(3),
            }))
        })
        .unwrap();
        let mut expected = vec![0u8; 32];
        expected[0..4].copy_from_slice(&f(0x3F80_0000));
        expected[12..16].copy_from_slice(&f(0x3F00_0000));
        expected[16..20].copy_from_slice(&[3, 0, 0, 0]);
        assert_eq!(bytes, expected);
        let short = UniformLayout { size: 8, ..layout };
        let e = pack::<EncodeError>(&short, |m| {
            Ok((m.name == "tint").then(|| UniformValue::F32s(vec![0.0; 3])))
        })
        .unwrap_err();
        assert!(e.0.contains("overruns"), "{e}");
    }

    #[test]
    fn types_serialise_to_the_wgsl_spelling() {
        for s in [
            "f32",
            "i32",
            "u32",
            "f16",
            "vec2<f32>",
            "vec3<f32>",
            "vec4<f32>",
            "vec4<f16>",
            "mat4x4<f32>",
            "mat3x2<f32>",
            "array<vec4<f32>, 9>",
            "array<array<f32, 4>, 2>",
            "array<f32>",
            "atomic<u32>",
            "WeftFrame",
        ] {
            let t: UniformType = s.parse().unwrap();
            assert_eq!(t.to_string(), s);
            let json = serde_json::to_string(&t).unwrap();
            assert_eq!(json, format!("\"{s}\""));
            assert_eq!(serde_json::from_str::<UniformType>(&json).unwrap(), t);
        }
        for bad in [
            "vec5<f32>",
            "array<vec4<f32>,9>",
            "vec4f",
            "mat4<f32>",
            "",
            "a b",
        ] {
            assert!(bad.parse::<UniformType>().is_err(), "{bad}");
        }
        assert_eq!(
            ParamKind::Curve.uniform_type(33).unwrap().to_string(),
            "array<vec4<f32>, 9>"
        );
        assert_eq!(UniformType::vec_f32(3).size(), Some(12));
        assert_eq!(UniformType::mat_f32(4, 4).size(), Some(64));
        assert_eq!(
            UniformType::array(UniformType::vec_f32(4), 9).size(),
            Some(144)
        );
    }

    #[test]
    fn json_values_are_read_by_the_member_type() {
        use serde_json::json;
        let curve = ParamKind::Curve.uniform_type(6).unwrap();
        assert_eq!(
            UniformValue::from_json(&curve, &json!([[1, 2, 3, 4], [5, 6, 0, 0]])).unwrap(),
            UniformValue::F32s(vec![1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 0.0, 0.0])
        );
        assert_eq!(
            UniformValue::from_json(&UniformType::U32, &json!(true)).unwrap(),
            UniformValue::U32(1)
        );
        assert!(UniformValue::from_json(&UniformType::I32, &json!(1.5)).is_err());
        for v in [
            UniformValue::F32(0.1),
            UniformValue::I32(-3),
            UniformValue::U32(1),
            UniformValue::F32s(vec![0.1, 0.2]),
        ] {
            let ty = match v {
                UniformValue::F32(_) => UniformType::F32,
                UniformValue::I32(_) => UniformType::I32,
                UniformValue::U32(_) => UniformType::U32,
                UniformValue::F32s(_) => UniformType::vec_f32(2),
            };
            assert_eq!(UniformValue::from_json(&ty, &v.to_json()).unwrap(), v);
        }
    }
}
