//! Parameter values: what [`crate::Material::set`] takes ([`Value`]), how
//! it is checked against the parameter's kind and range and normalised for
//! upload ([`StoredValue`]), and the metadata defaults.

use crate::error::{Error, Result};
use weft_meta::{ColorInfo, GradientStop, Keyframe, ParamKind, Parameter, TextureDefault};

pub use weft_meta::bake::{
    bake_gradient, eval_curve, linear_to_srgb, sample_curve, srgb_to_linear,
};

/// A value for [`Material::set`].
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Float(f64),
    Int(i64),
    Bool(bool),
    /// vec2/vec3/vec4 components; for a colour, 3 or 4 components *as
    /// edited*: sRGB-encoded unless the colour is `hdr` (then linear).
    Vector(Vec<f64>),
    /// A colour already in linear space, written to the uniform as is.
    LinearColor([f64; 4]),
    Curve(CurveValue),
    /// Gradient stops (sRGB-encoded colours as edited), baked like the toolchain does.
    Gradient(Vec<GradientStop>),
    Texture(TextureValue),
}

/// A curve: keyframes (sampled like the toolchain bakes them) or the baked samples themselves.
#[derive(Clone, Debug, PartialEq)]
pub enum CurveValue {
    Keyframes(Vec<Keyframe>),
    /// Exactly `CurveInfo::samples` values.
    Samples(Vec<f64>),
}

/// A texture, cube or gradient ramp.
#[derive(Clone, Debug, PartialEq)]
pub enum TextureValue {
    /// One of the built-in 1x1 textures (cube: a 1x1 cube of that texel).
    Builtin(TextureDefault),
    /// RGBA8 texels as stored (sRGB-encoded when the parameter is `srgb`,
    /// always for gradients), row-major, `width * height * 4` bytes.
    Rgba8 {
        width: u32,
        height: u32,
        data: Vec<u8>,
    },
    /// A cube map in linear RGBA (stored as `Rgba16Float`): faces +X, -X, +Y,
    /// -Y, +Z, -Z, each `size * size` texels row-major.
    CubeRgbaF32 { size: u32, data: Vec<[f32; 4]> },
}

impl From<f64> for Value {
    fn from(v: f64) -> Self {
        Value::Float(v)
    }
}
impl From<f32> for Value {
    fn from(v: f32) -> Self {
        Value::Float(f64::from(v))
    }
}
impl From<i64> for Value {
    fn from(v: i64) -> Self {
        Value::Int(v)
    }
}
impl From<i32> for Value {
    fn from(v: i32) -> Self {
        Value::Int(i64::from(v))
    }
}
impl From<bool> for Value {
    fn from(v: bool) -> Self {
        Value::Bool(v)
    }
}
impl<const N: usize> From<[f64; N]> for Value {
    fn from(v: [f64; N]) -> Self {
        Value::Vector(v.to_vec())
    }
}
impl From<Vec<f64>> for Value {
    fn from(v: Vec<f64>) -> Self {
        Value::Vector(v)
    }
}
impl From<TextureDefault> for Value {
    fn from(v: TextureDefault) -> Self {
        Value::Texture(TextureValue::Builtin(v))
    }
}
impl From<TextureValue> for Value {
    fn from(v: TextureValue) -> Self {
        Value::Texture(v)
    }
}
impl From<CurveValue> for Value {
    fn from(v: CurveValue) -> Self {
        Value::Curve(v)
    }
}

impl Value {
    fn type_name(&self) -> &'static str {
        match self {
            Value::Float(_) => "a float",
            Value::Int(_) => "an int",
            Value::Bool(_) => "a bool",
            Value::Vector(_) => "a vector",
            Value::LinearColor(_) => "a linear colour",
            Value::Curve(_) => "a curve",
            Value::Gradient(_) => "a gradient",
            Value::Texture(_) => "a texture",
        }
    }

    /// A value written as in the metadata (`Parameter::default`, preset values).
    pub fn from_json(param: &Parameter, v: &serde_json::Value) -> Result<Value> {
        let bad = |what: &str| Error::InvalidValue {
            name: param.name.clone(),
            message: format!(
                "expected {what} for a {} parameter, got {v}",
                param.kind.name()
            ),
        };
        Ok(match param.kind {
            ParamKind::Float => Value::Float(v.as_f64().ok_or_else(|| bad("a number"))?),
            ParamKind::Int => Value::Float(v.as_f64().ok_or_else(|| bad("a number"))?),
            ParamKind::Bool => Value::Bool(v.as_bool().ok_or_else(|| bad("true or false"))?),
            ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 | ParamKind::Color => {
                let arr = v.as_array().ok_or_else(|| bad("an array of numbers"))?;
                let nums: Option<Vec<f64>> = arr.iter().map(serde_json::Value::as_f64).collect();
                Value::Vector(nums.ok_or_else(|| bad("an array of numbers"))?)
            }
            ParamKind::Texture2d | ParamKind::Cube => {
                let s = v.as_str().ok_or_else(|| bad("a built-in texture name"))?;
                Value::Texture(TextureValue::Builtin(builtin_texture(&param.name, s)?))
            }
            ParamKind::Curve => {
                let keys: Vec<Keyframe> =
                    serde_json::from_value(v.clone()).map_err(|_| bad("keyframes"))?;
                Value::Curve(CurveValue::Keyframes(keys))
            }
            ParamKind::Gradient => {
                let stops: Vec<GradientStop> =
                    serde_json::from_value(v.clone()).map_err(|_| bad("gradient stops"))?;
                Value::Gradient(stops)
            }
        })
    }

    /// Parses command-line text for a parameter: numbers, `true`/`false`,
    /// comma-separated vectors and colours (as edited), built-in texture
    /// names, comma-separated curve samples.
    pub fn parse(param: &Parameter, text: &str) -> Result<Value> {
        let bad = |what: &str| Error::InvalidValue {
            name: param.name.clone(),
            message: format!(
                "expected {what} for a {} parameter, got `{text}`",
                param.kind.name()
            ),
        };
        let numbers = || -> Result<Vec<f64>> {
            text.split(',')
                .map(|s| {
                    s.trim()
                        .parse::<f64>()
                        .map_err(|_| bad("comma-separated numbers"))
                })
                .collect()
        };
        Ok(match param.kind {
            ParamKind::Float => Value::Float(text.trim().parse().map_err(|_| bad("a number"))?),
            ParamKind::Int => Value::Int(text.trim().parse().map_err(|_| bad("an integer"))?),
            ParamKind::Bool => match text.trim() {
                "true" | "on" | "1" => Value::Bool(true),
                "false" | "off" | "0" => Value::Bool(false),
                _ => return Err(bad("true or false")),
            },
            ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 | ParamKind::Color => {
                Value::Vector(numbers()?)
            }
            ParamKind::Texture2d | ParamKind::Cube => Value::Texture(TextureValue::Builtin(
                builtin_texture(&param.name, text.trim())?,
            )),
            ParamKind::Curve => Value::Curve(CurveValue::Samples(numbers()?)),
            ParamKind::Gradient => {
                return Err(bad(
                    "(nothing: gradients cannot be set from text; use the API)",
                ));
            }
        })
    }
}

fn builtin_texture(param: &str, s: &str) -> Result<TextureDefault> {
    TextureDefault::ALL
        .into_iter()
        .find(|t| t.name() == s)
        .ok_or_else(|| Error::InvalidValue {
            name: param.to_string(),
            message: format!(
                "unknown built-in texture `{s}`; valid: {}",
                TextureDefault::ALL.map(|t| t.name()).join(", ")
            ),
        })
}

/// A parameter's current value, normalised for upload.
#[derive(Clone, Debug, PartialEq)]
pub enum StoredValue {
    /// Uniform-ready numbers: 1 for float/int/bool (0 or 1), N for vecN, 4
    /// for colours (linear).
    Numbers(Vec<f64>),
    /// Curve samples (`CurveInfo::samples` of them).
    Curve(Vec<f64>),
    /// Texture or cube.
    Texture(TextureValue),
    /// Gradient ramp: sRGB8 RGBA texels, width = len / 4.
    Gradient(Vec<u8>),
}

pub fn default_value(p: &Parameter) -> Result<StoredValue> {
    match p.kind {
        ParamKind::Color => {
            if let Some(ColorInfo { linear_default, .. }) = &p.color {
                return Ok(StoredValue::Numbers(linear_default.to_vec()));
            }
        }
        ParamKind::Curve => {
            if let Some(c) = &p.curve {
                return Ok(StoredValue::Curve(c.baked_default.clone()));
            }
        }
        ParamKind::Gradient => {
            if let Some(g) = &p.gradient {
                return Ok(StoredValue::Gradient(g.baked_default.clone()));
            }
        }
        ParamKind::Texture2d | ParamKind::Cube => {
            if let Some(t) = &p.texture {
                return Ok(StoredValue::Texture(TextureValue::Builtin(t.default)));
            }
        }
        _ => {}
    }
    let v = Value::from_json(p, &p.default)?;
    normalise(p, v, Ranges::Check)
}

/// Whether [`normalise`] checks declared ranges (finiteness is always checked).
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Ranges {
    Check,
    /// Values as uploaded by a scene build: already checked against the
    /// ranges as edited; their linear round trip may sit an ulp outside.
    Skip,
}

fn check_range(p: &Parameter, values: &[f64], ranges: Ranges) -> Result<()> {
    for v in values {
        if !v.is_finite() {
            return Err(Error::InvalidValue {
                name: p.name.clone(),
                message: format!("{v} is not a finite number"),
            });
        }
        if let Some([lo, hi]) = p.range
            && ranges == Ranges::Check
            && (*v < lo || *v > hi)
        {
            return Err(Error::InvalidValue {
                name: p.name.clone(),
                message: format!("{v} is outside the range [{lo}, {hi}]"),
            });
        }
    }
    Ok(())
}

pub fn normalise(p: &Parameter, value: Value, ranges: Ranges) -> Result<StoredValue> {
    match p.kind {
        ParamKind::Float => {
            let x = match value {
                Value::Float(x) => x,
                Value::Int(i) => i as f64,
                ref v => return Err(wrong(p, v)),
            };
            check_range(p, &[x], ranges)?;
            Ok(StoredValue::Numbers(vec![x]))
        }
        ParamKind::Int => normalise_int(p, value, ranges),
        ParamKind::Bool => match value {
            Value::Bool(b) => Ok(StoredValue::Numbers(vec![f64::from(u8::from(b))])),
            Value::Int(i @ (0 | 1)) => Ok(StoredValue::Numbers(vec![i as f64])),
            ref v => Err(wrong(p, v)),
        },
        ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 => normalise_vector(p, value, ranges),
        ParamKind::Color => normalise_color(p, value, ranges),
        ParamKind::Curve => normalise_curve(p, value, ranges),
        ParamKind::Gradient => normalise_gradient(p, value),
        ParamKind::Texture2d => normalise_texture2d(p, value),
        ParamKind::Cube => normalise_cube(p, value),
    }
}

/// The error for a value of the wrong kind.
fn wrong(p: &Parameter, v: &Value) -> Error {
    Error::InvalidValue {
        name: p.name.clone(),
        message: format!("is a {} parameter; got {}", p.kind.name(), v.type_name()),
    }
}

/// An `int`: a whole number that fits an i32.
fn normalise_int(p: &Parameter, value: Value, ranges: Ranges) -> Result<StoredValue> {
    let x = match value {
        Value::Int(i) => i as f64,
        Value::Float(x) if x.fract() == 0.0 => x,
        Value::Float(x) => {
            return Err(Error::InvalidValue {
                name: p.name.clone(),
                message: format!("is an int parameter; got {x}"),
            });
        }
        ref v => return Err(wrong(p, v)),
    };
    if x < f64::from(i32::MIN) || x > f64::from(i32::MAX) {
        return Err(Error::InvalidValue {
            name: p.name.clone(),
            message: format!("{x} does not fit an i32"),
        });
    }
    check_range(p, &[x], ranges)?;
    Ok(StoredValue::Numbers(vec![x]))
}

/// A `vecN`'s N components.
fn normalise_vector(p: &Parameter, value: Value, ranges: Ranges) -> Result<StoredValue> {
    let n = p.kind.components().unwrap_or(4);
    let v = match value {
        Value::Vector(v) => v,
        ref v => return Err(wrong(p, v)),
    };
    if v.len() != n {
        return Err(Error::InvalidValue {
            name: p.name.clone(),
            message: format!("expected {n} components, got {}", v.len()),
        });
    }
    check_range(p, &v, ranges)?;
    Ok(StoredValue::Numbers(v))
}

/// A colour as uploaded (linear), from sRGB-encoded or linear components.
fn normalise_color(p: &Parameter, value: Value, ranges: Ranges) -> Result<StoredValue> {
    let hdr = p.color.as_ref().is_some_and(|c| c.hdr);
    match value {
        Value::Vector(v) => {
            if v.len() != 3 && v.len() != 4 {
                return Err(Error::InvalidValue {
                    name: p.name.clone(),
                    message: format!("expected 3 or 4 components, got {}", v.len()),
                });
            }
            check_range(p, &v, ranges)?;
            // The colour rule of the encoder (weft_meta::uniform).
            let c = weft_meta::uniform::color_as_uploaded(&v, hdr);
            Ok(StoredValue::Numbers(c.to_vec()))
        }
        Value::LinearColor(c) => {
            let check: Vec<f64> = if hdr {
                c.to_vec()
            } else {
                c.iter().map(|x| linear_to_srgb(*x)).collect()
            };
            check_range(p, &check, ranges)?;
            Ok(StoredValue::Numbers(c.to_vec()))
        }
        ref v => Err(wrong(p, v)),
    }
}

/// A curve's baked samples, from keyframes or the samples themselves.
fn normalise_curve(p: &Parameter, value: Value, ranges: Ranges) -> Result<StoredValue> {
    let info = p.curve.as_ref().ok_or_else(|| {
        Error::Metadata(format!("curve parameter `{}` has no curve info", p.name))
    })?;
    let samples = match value {
        Value::Curve(CurveValue::Keyframes(keys)) => {
            if keys.is_empty() {
                return Err(Error::InvalidValue {
                    name: p.name.clone(),
                    message: "a curve needs at least one keyframe".into(),
                });
            }
            if keys.windows(2).any(|w| w[1].time <= w[0].time) {
                return Err(Error::InvalidValue {
                    name: p.name.clone(),
                    message: "keyframe times must increase".into(),
                });
            }
            check_range(p, &keys.iter().map(|k| k.value).collect::<Vec<_>>(), ranges)?;
            sample_curve(&keys, info.samples)
        }
        Value::Curve(CurveValue::Samples(s)) | Value::Vector(s) => {
            if s.len() != info.samples as usize {
                return Err(Error::InvalidValue {
                    name: p.name.clone(),
                    message: format!("expected {} curve samples, got {}", info.samples, s.len()),
                });
            }
            check_range(p, &s, ranges)?;
            s
        }
        ref v => return Err(wrong(p, v)),
    };
    Ok(StoredValue::Curve(samples))
}

/// A gradient's ramp texels, baked from stops or given.
fn normalise_gradient(p: &Parameter, value: Value) -> Result<StoredValue> {
    let width = p.gradient.as_ref().map_or(64, |g| g.width);
    match value {
        Value::Gradient(stops) => {
            if stops.is_empty() {
                return Err(Error::InvalidValue {
                    name: p.name.clone(),
                    message: "a gradient needs at least one stop".into(),
                });
            }
            Ok(StoredValue::Gradient(bake_gradient(&stops, width)))
        }
        Value::Texture(TextureValue::Rgba8 {
            width: w,
            height: 1,
            data,
        }) if data.len() == w as usize * 4 && w > 0 => Ok(StoredValue::Gradient(data)),
        ref v => Err(wrong(p, v)),
    }
}

/// A texture: a built-in one, or RGBA8 texels of the right size.
fn normalise_texture2d(p: &Parameter, value: Value) -> Result<StoredValue> {
    match value {
        Value::Texture(t @ TextureValue::Builtin(_)) => Ok(StoredValue::Texture(t)),
        Value::Texture(t @ TextureValue::Rgba8 { .. }) => {
            if let TextureValue::Rgba8 {
                width,
                height,
                data,
            } = &t
                && (*width == 0 || *height == 0 || data.len() != (width * height * 4) as usize)
            {
                return Err(Error::InvalidValue {
                    name: p.name.clone(),
                    message: format!(
                        "{width}x{height} RGBA8 needs {} bytes, got {}",
                        width * height * 4,
                        data.len()
                    ),
                });
            }
            Ok(StoredValue::Texture(t))
        }
        ref v => Err(wrong(p, v)),
    }
}

/// A cube: a built-in one, or RGBA f32 texels of the right size.
fn normalise_cube(p: &Parameter, value: Value) -> Result<StoredValue> {
    match value {
        Value::Texture(t @ TextureValue::Builtin(_)) => Ok(StoredValue::Texture(t)),
        Value::Texture(t @ TextureValue::CubeRgbaF32 { .. }) => {
            if let TextureValue::CubeRgbaF32 { size, data } = &t
                && (*size == 0 || data.len() != (size * size * 6) as usize)
            {
                return Err(Error::InvalidValue {
                    name: p.name.clone(),
                    message: format!(
                        "a {size}x{size} cube needs {} texels, got {}",
                        size * size * 6,
                        data.len()
                    ),
                });
            }
            Ok(StoredValue::Texture(t))
        }
        ref v => Err(wrong(p, v)),
    }
}
