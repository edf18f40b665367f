//! A material loaded from its metadata alone: parameter values, keyword and
//! tier selection, variant resolution and the packed uniform block.
//!
//! Nothing here knows any material's source: names, kinds, ranges, defaults,
//! uniform offsets and bindings all come from `<name>.meta.json`.

use crate::error::{Error, Result, io_err};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use weft_meta::{
    ColorInfo, GradientStop, InstanceCount, Keyframe, KeywordKind, MaterialMetadata, ParamKind,
    Parameter, Pass, TextureDefault, UniformLayout, Variant, VariantShader,
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

pub use weft_meta::bake::{
    bake_gradient, eval_curve, linear_to_srgb, sample_curve, srgb_to_linear,
};

/// A variant an id or a (tier, keywords) selection resolved to.
#[derive(Clone, Copy, Debug)]
pub struct ResolvedVariant<'a> {
    /// The variant asked for (possibly an alias).
    pub requested: &'a Variant,
    /// The variant whose files and reflection are used (`alias_of` followed).
    pub canonical: &'a Variant,
    pub shader: &'a VariantShader,
}

/// A material: its metadata plus the current parameter values and keyword/tier selection.
#[derive(Clone, Debug)]
pub struct Material {
    meta: MaterialMetadata,
    /// Folder the metadata's relative shader paths resolve against.
    dir: PathBuf,
    values: BTreeMap<String, StoredValue>,
    tiling: BTreeMap<String, [f64; 4]>,
    keywords: BTreeMap<String, String>,
    tier: String,
}

impl Material {
    /// Reads `<name>.meta.json`; shader files are resolved next to it.
    pub fn load(meta_path: impl AsRef<Path>) -> Result<Material> {
        let path = meta_path.as_ref();
        let bytes = std::fs::read(path).map_err(io_err(path))?;
        let meta: MaterialMetadata = serde_json::from_slice(&bytes).map_err(|e| {
            Error::Metadata(format!("`{}` is not weft metadata: {e}", path.display()))
        })?;
        let dir = path.parent().unwrap_or(Path::new(".")).to_path_buf();
        Material::from_metadata(meta, dir)
    }

    /// A material from already-parsed metadata; `dir` holds its shader files.
    pub fn from_metadata(meta: MaterialMetadata, dir: impl Into<PathBuf>) -> Result<Material> {
        if meta.engine_interface_version != weft_meta::ENGINE_INTERFACE_VERSION {
            return Err(Error::Metadata(format!(
                "material `{}` targets engine interface {}, this runtime implements {}",
                meta.name,
                meta.engine_interface_version,
                weft_meta::ENGINE_INTERFACE_VERSION
            )));
        }
        let mut m = Material {
            dir: dir.into(),
            values: BTreeMap::new(),
            tiling: BTreeMap::new(),
            keywords: meta
                .keywords
                .iter()
                .map(|k| (k.name.clone(), k.default.clone()))
                .collect(),
            tier: meta.tiers.default.clone(),
            meta,
        };
        m.reset()?;
        Ok(m)
    }

    /// Every parameter back to its metadata default (keywords and tier unchanged).
    pub fn reset(&mut self) -> Result<()> {
        self.values.clear();
        self.tiling.clear();
        let params = self.meta.parameters.clone();
        for p in &params {
            let stored = default_value(p)?;
            self.values.insert(p.name.clone(), stored);
            if let Some(t) = &p.texture
                && let Some(d) = t.tiling_default
            {
                self.tiling.insert(p.name.clone(), d);
            }
        }
        Ok(())
    }

    pub fn metadata(&self) -> &MaterialMetadata {
        &self.meta
    }

    pub fn name(&self) -> &str {
        &self.meta.name
    }

    /// Folder holding the shader files.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    pub fn parameter(&self, name: &str) -> Result<&Parameter> {
        self.meta
            .parameters
            .iter()
            .find(|p| p.name == name)
            .ok_or_else(|| Error::UnknownParameter {
                name: name.to_string(),
                valid: self
                    .meta
                    .parameters
                    .iter()
                    .map(|p| p.name.clone())
                    .collect(),
            })
    }

    /// The current (normalised) value of a parameter.
    pub fn get(&self, name: &str) -> Option<&StoredValue> {
        self.values.get(name)
    }

    /// Sets a parameter by name, checking its type and range.
    pub fn set(&mut self, name: &str, value: impl Into<Value>) -> Result<()> {
        let value = value.into();
        let p = self.parameter(name)?.clone();
        let stored = normalise(&p, value)?;
        self.values.insert(p.name.clone(), stored);
        Ok(())
    }

    /// Sets a parameter from command-line text (see [`Value::parse`]).
    pub fn set_from_str(&mut self, name: &str, text: &str) -> Result<()> {
        let p = self.parameter(name)?.clone();
        let v = Value::parse(&p, text)?;
        self.set(name, v)
    }

    /// Tiling (xy) and offset (zw) of a texture parameter that has them.
    pub fn set_tiling(&mut self, name: &str, st: [f64; 4]) -> Result<()> {
        let p = self.parameter(name)?;
        if p.texture
            .as_ref()
            .and_then(|t| t.tiling_member.as_ref())
            .is_none()
        {
            return Err(Error::InvalidValue {
                name: name.into(),
                message: "this parameter has no tiling/offset".into(),
            });
        }
        self.tiling.insert(name.to_string(), st);
        Ok(())
    }

    /// Selects a keyword value (toggles: `on`/`off`, also `true`/`false`).
    pub fn set_keyword(&mut self, name: &str, value: &str) -> Result<()> {
        let k = self
            .meta
            .keywords
            .iter()
            .find(|k| k.name == name || k.name.eq_ignore_ascii_case(name))
            .ok_or_else(|| Error::UnknownName {
                what: "keyword",
                name: name.into(),
                valid: self.meta.keywords.iter().map(|k| k.name.clone()).collect(),
            })?;
        let value = match (k.kind, value) {
            (KeywordKind::Toggle, "true" | "1") => "on",
            (KeywordKind::Toggle, "false" | "0") => "off",
            _ => value,
        };
        let v = k
            .values
            .iter()
            .find(|v| v.eq_ignore_ascii_case(value))
            .ok_or_else(|| Error::UnknownName {
                what: "keyword value",
                name: format!("{}={value}", k.name),
                valid: k.values.clone(),
            })?;
        self.keywords.insert(k.name.clone(), v.clone());
        Ok(())
    }

    pub fn keyword(&self, name: &str) -> Option<&str> {
        self.keywords.get(name).map(String::as_str)
    }

    pub fn keywords(&self) -> &BTreeMap<String, String> {
        &self.keywords
    }

    pub fn set_tier(&mut self, tier: &str) -> Result<()> {
        let t = self
            .meta
            .tiers
            .values
            .iter()
            .find(|t| t.eq_ignore_ascii_case(tier))
            .ok_or_else(|| Error::UnknownName {
                what: "tier",
                name: tier.into(),
                valid: self.meta.tiers.values.clone(),
            })?;
        self.tier = t.clone();
        Ok(())
    }

    pub fn tier(&self) -> &str {
        &self.tier
    }

    /// Selects a variant by id (aliases allowed): sets the tier and the static keywords.
    pub fn select_variant(&mut self, id: &str) -> Result<()> {
        let v = self.variant_entry(id)?.clone();
        self.tier = v.tier.clone();
        for (k, val) in &v.keywords {
            self.keywords.insert(k.clone(), val.clone());
        }
        Ok(())
    }

    /// Applies a preset: parameter values, keyword values and `tier`.
    pub fn apply_preset(&mut self, name: &str) -> Result<()> {
        let preset = self
            .meta
            .presets
            .iter()
            .find(|p| p.name == name)
            .ok_or_else(|| Error::UnknownName {
                what: "preset",
                name: name.into(),
                valid: self.meta.presets.iter().map(|p| p.name.clone()).collect(),
            })?
            .clone();
        for (key, v) in &preset.values {
            if key == "tier" {
                let t = v.as_str().ok_or_else(|| Error::InvalidValue {
                    name: "tier".into(),
                    message: format!("expected a tier name, got {v}"),
                })?;
                self.set_tier(t)?;
            } else if self.meta.keywords.iter().any(|k| &k.name == key) {
                let s = match v {
                    serde_json::Value::Bool(b) => if *b { "on" } else { "off" }.to_string(),
                    serde_json::Value::String(s) => s.clone(),
                    other => other.to_string(),
                };
                self.set_keyword(key, &s)?;
            } else {
                let p = self.parameter(key)?.clone();
                let value = Value::from_json(&p, v)?;
                self.set(key, value)?;
            }
        }
        Ok(())
    }

    fn variant_entry(&self, id: &str) -> Result<&Variant> {
        self.meta
            .variants
            .iter()
            .find(|v| v.id == id)
            .ok_or_else(|| Error::UnknownName {
                what: "variant",
                name: id.into(),
                valid: self.meta.variants.iter().map(|v| v.id.clone()).collect(),
            })
    }

    /// Resolves a variant id (following `alias_of`).
    pub fn variant_by_id(&self, id: &str) -> Result<ResolvedVariant<'_>> {
        let requested = self.variant_entry(id)?;
        let canonical = match &requested.alias_of {
            Some(target) => self.variant_entry(target)?,
            None => requested,
        };
        let shader = canonical.shader.as_ref().ok_or_else(|| {
            Error::Metadata(format!(
                "variant `{}` has neither files nor alias_of",
                canonical.id
            ))
        })?;
        Ok(ResolvedVariant {
            requested,
            canonical,
            shader,
        })
    }

    /// The variant for a tier and keyword values (static keywords choose the
    /// variant; constant-mode keywords are pipeline constants and ignored here).
    pub fn variant_for(
        &self,
        tier: &str,
        keywords: &BTreeMap<String, String>,
    ) -> Result<ResolvedVariant<'_>> {
        let found = self.meta.variants.iter().find(|v| {
            v.tier == tier
                && v.keywords
                    .iter()
                    .all(|(k, val)| keywords.get(k).is_some_and(|x| x == val))
        });
        match found {
            Some(v) => self.variant_by_id(&v.id),
            None => Err(Error::UnknownName {
                what: "variant (tier and keyword combination)",
                name: std::iter::once(format!("tier={tier}"))
                    .chain(keywords.iter().map(|(k, v)| format!("{k}={v}")))
                    .collect::<Vec<_>>()
                    .join(" "),
                valid: self.meta.variants.iter().map(|v| v.id.clone()).collect(),
            }),
        }
    }

    /// The variant of the current tier and keyword selection.
    pub fn current_variant(&self) -> Result<ResolvedVariant<'_>> {
        self.variant_for(&self.tier, &self.keywords)
    }

    /// Values for the variant's WGSL `override`s (constant-mode keywords):
    /// toggles 0/1, enums the value's index.
    pub fn pipeline_constants(&self, shader: &VariantShader) -> Result<Vec<(String, f64)>> {
        let mut out = Vec::new();
        for c in &shader.pipeline_constants {
            let value = match self.meta.keywords.iter().find(|k| k.name == c.name) {
                Some(k) => {
                    let v = self.keywords.get(&k.name).unwrap_or(&k.default);
                    let idx = k.values.iter().position(|x| x == v).ok_or_else(|| {
                        Error::Metadata(format!("keyword `{}` has no value `{v}`", k.name))
                    })?;
                    idx as f64
                }
                None => match c.default.as_str() {
                    "true" => 1.0,
                    "false" => 0.0,
                    s => s.trim_end_matches('u').parse::<f64>().map_err(|_| {
                        Error::Metadata(format!(
                            "pipeline constant `{}` has no keyword and an unreadable default `{s}`",
                            c.name
                        ))
                    })?,
                },
            };
            out.push((c.name.clone(), value));
        }
        Ok(out)
    }

    /// Instances a pass draws (a fixed count or an int parameter's value, at least 0).
    pub fn instance_count(&self, pass: &Pass) -> Result<u32> {
        match &pass.instances {
            InstanceCount::Fixed(n) => Ok(*n),
            InstanceCount::Parameter(p) => match self.values.get(p) {
                Some(StoredValue::Numbers(v)) if !v.is_empty() => {
                    Ok(v[0].round().clamp(0.0, f64::from(u32::MAX)) as u32)
                }
                _ => Err(Error::Metadata(format!(
                    "pass `{}` takes its instance count from `{p}`, which is not an int parameter",
                    pass.name
                ))),
            },
        }
    }

    /// The material uniform block packed at the offsets of `layout`.
    pub fn uniform_bytes(&self, layout: &UniformLayout) -> Result<Vec<u8>> {
        let mut bytes = vec![0u8; layout.size as usize];
        let member = |name: &str| layout.members.iter().find(|m| m.name == name);
        for p in &self.meta.parameters {
            if let Some(t) = &p.texture
                && let Some(tm) = &t.tiling_member
                && let Some(m) = member(tm)
            {
                let st = self
                    .tiling
                    .get(&p.name)
                    .copied()
                    .unwrap_or([1.0, 1.0, 0.0, 0.0]);
                expect_ty(p, &m.ty, "vec4<f32>")?;
                write_f32s(&mut bytes, m.offset, &st);
            }
            let Some(mname) = &p.uniform_member else {
                continue;
            };
            let Some(m) = member(mname) else {
                continue; // not read by this variant's layout
            };
            let value = self
                .values
                .get(&p.name)
                .ok_or_else(|| Error::Metadata(format!("parameter `{}` has no value", p.name)))?;
            match (p.kind, value) {
                (ParamKind::Float, StoredValue::Numbers(v)) => {
                    expect_ty(p, &m.ty, "f32")?;
                    write_f32s(&mut bytes, m.offset, &v[..1]);
                }
                (ParamKind::Int, StoredValue::Numbers(v)) => {
                    expect_ty(p, &m.ty, "i32")?;
                    let i = v[0].round() as i32;
                    put(&mut bytes, m.offset, &i.to_le_bytes());
                }
                (ParamKind::Bool, StoredValue::Numbers(v)) => {
                    expect_ty(p, &m.ty, "u32")?;
                    let u = u32::from(v[0] != 0.0);
                    put(&mut bytes, m.offset, &u.to_le_bytes());
                }
                (ParamKind::Vec2, StoredValue::Numbers(v)) => {
                    expect_ty(p, &m.ty, "vec2<f32>")?;
                    write_f32s(&mut bytes, m.offset, v);
                }
                (ParamKind::Vec3, StoredValue::Numbers(v)) => {
                    expect_ty(p, &m.ty, "vec3<f32>")?;
                    write_f32s(&mut bytes, m.offset, v);
                }
                (ParamKind::Vec4 | ParamKind::Color, StoredValue::Numbers(v)) => {
                    expect_ty(p, &m.ty, "vec4<f32>")?;
                    write_f32s(&mut bytes, m.offset, v);
                }
                (ParamKind::Curve, StoredValue::Curve(samples)) => {
                    let n = samples.len().div_ceil(4);
                    expect_ty(p, &m.ty, &format!("array<vec4<f32>, {n}>"))?;
                    // Packed 4 per vec4, sample i at [i / 4][i % 4]; the tail stays 0.
                    write_f32s(&mut bytes, m.offset, samples);
                }
                _ => {
                    return Err(Error::Metadata(format!(
                        "parameter `{}` ({}) has uniform member `{mname}` of type `{}`",
                        p.name,
                        p.kind.name(),
                        m.ty
                    )));
                }
            }
        }
        Ok(bytes)
    }
}

fn expect_ty(p: &Parameter, actual: &str, expected: &str) -> Result<()> {
    if actual.replace(' ', "") == expected.replace(' ', "") {
        Ok(())
    } else {
        Err(Error::Metadata(format!(
            "uniform member of `{}` ({}) has type `{actual}`, expected `{expected}`",
            p.name,
            p.kind.name()
        )))
    }
}

fn put(bytes: &mut [u8], offset: u32, data: &[u8]) {
    let o = offset as usize;
    bytes[o..o + data.len()].copy_from_slice(data);
}

fn write_f32s(bytes: &mut [u8], offset: u32, v: &[f64]) {
    for (i, x) in v.iter().enumerate() {
        put(bytes, offset + 4 * i as u32, &(*x as f32).to_le_bytes());
    }
}

fn default_value(p: &Parameter) -> Result<StoredValue> {
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
    normalise(p, v)
}

fn check_range(p: &Parameter, values: &[f64]) -> Result<()> {
    for v in values {
        if !v.is_finite() {
            return Err(Error::InvalidValue {
                name: p.name.clone(),
                message: format!("{v} is not a finite number"),
            });
        }
        if let Some([lo, hi]) = p.range
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

fn normalise(p: &Parameter, value: Value) -> Result<StoredValue> {
    let wrong = |v: &Value| Error::InvalidValue {
        name: p.name.clone(),
        message: format!("is a {} parameter; got {}", p.kind.name(), v.type_name()),
    };
    match p.kind {
        ParamKind::Float => {
            let x = match value {
                Value::Float(x) => x,
                Value::Int(i) => i as f64,
                ref v => return Err(wrong(v)),
            };
            check_range(p, &[x])?;
            Ok(StoredValue::Numbers(vec![x]))
        }
        ParamKind::Int => {
            let x = match value {
                Value::Int(i) => i as f64,
                Value::Float(x) if x.fract() == 0.0 => x,
                Value::Float(x) => {
                    return Err(Error::InvalidValue {
                        name: p.name.clone(),
                        message: format!("is an int parameter; got {x}"),
                    });
                }
                ref v => return Err(wrong(v)),
            };
            if x < f64::from(i32::MIN) || x > f64::from(i32::MAX) {
                return Err(Error::InvalidValue {
                    name: p.name.clone(),
                    message: format!("{x} does not fit an i32"),
                });
            }
            check_range(p, &[x])?;
            Ok(StoredValue::Numbers(vec![x]))
        }
        ParamKind::Bool => match value {
            Value::Bool(b) => Ok(StoredValue::Numbers(vec![f64::from(u8::from(b))])),
            Value::Int(i @ (0 | 1)) => Ok(StoredValue::Numbers(vec![i as f64])),
            ref v => Err(wrong(v)),
        },
        ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 => {
            let n = p.kind.components().unwrap_or(4);
            let v = match value {
                Value::Vector(v) => v,
                ref v => return Err(wrong(v)),
            };
            if v.len() != n {
                return Err(Error::InvalidValue {
                    name: p.name.clone(),
                    message: format!("expected {n} components, got {}", v.len()),
                });
            }
            check_range(p, &v)?;
            Ok(StoredValue::Numbers(v))
        }
        ParamKind::Color => {
            let hdr = p.color.as_ref().is_some_and(|c| c.hdr);
            match value {
                Value::Vector(v) => {
                    if v.len() != 3 && v.len() != 4 {
                        return Err(Error::InvalidValue {
                            name: p.name.clone(),
                            message: format!("expected 3 or 4 components, got {}", v.len()),
                        });
                    }
                    check_range(p, &v)?;
                    let mut c = [v[0], v[1], v[2], v.get(3).copied().unwrap_or(1.0)];
                    if !hdr {
                        for x in &mut c[..3] {
                            *x = srgb_to_linear(*x);
                        }
                    }
                    Ok(StoredValue::Numbers(c.to_vec()))
                }
                Value::LinearColor(c) => {
                    let check: Vec<f64> = if hdr {
                        c.to_vec()
                    } else {
                        c.iter().map(|x| linear_to_srgb(*x)).collect()
                    };
                    check_range(p, &check)?;
                    Ok(StoredValue::Numbers(c.to_vec()))
                }
                ref v => Err(wrong(v)),
            }
        }
        ParamKind::Curve => {
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
                    check_range(p, &keys.iter().map(|k| k.value).collect::<Vec<_>>())?;
                    sample_curve(&keys, info.samples)
                }
                Value::Curve(CurveValue::Samples(s)) | Value::Vector(s) => {
                    if s.len() != info.samples as usize {
                        return Err(Error::InvalidValue {
                            name: p.name.clone(),
                            message: format!(
                                "expected {} curve samples, got {}",
                                info.samples,
                                s.len()
                            ),
                        });
                    }
                    check_range(p, &s)?;
                    s
                }
                ref v => return Err(wrong(v)),
            };
            Ok(StoredValue::Curve(samples))
        }
        ParamKind::Gradient => {
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
                ref v => Err(wrong(v)),
            }
        }
        ParamKind::Texture2d => match value {
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
            ref v => Err(wrong(v)),
        },
        ParamKind::Cube => match value {
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
            ref v => Err(wrong(v)),
        },
    }
}
