//! [`UniformType`]: a buffer member's WGSL type, typed, with its size,
//! alignment and stride by WGSL's uniform-buffer rules, and the exact
//! spellings it reads and writes (`vec4<f32>`, `array<vec4<f32>, 9>`, …).

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
    pub(super) fn align(&self) -> Option<u32> {
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

    pub(super) fn column_stride(&self, scalar: ScalarType) -> u32 {
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
    pub(super) fn stride(&self) -> Option<u32> {
        let (size, align) = (self.size()?, self.align()?);
        Some(size.next_multiple_of(align).next_multiple_of(16))
    }

    /// Number of scalars the type holds (arrays: elements × scalars each).
    pub(super) fn scalars(&self) -> Option<(u32, ScalarType)> {
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
