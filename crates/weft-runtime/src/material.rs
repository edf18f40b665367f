//! A material loaded from its metadata alone: parameter values, keyword and
//! tier selection, variant resolution and the packed uniform block.
//!
//! Nothing here knows any material's source: names, kinds, ranges, defaults,
//! uniform offsets and bindings all come from `<name>.meta.json`. The values
//! themselves (kinds, ranges, normalisation) live in `values.rs`.

use crate::TextureValue;
use crate::error::{Error, Result, io_err};
use weft_meta::uniform::{
    ParamValue as Upload, TILING_OFFSET_DEFAULT, TILING_OFFSET_TYPE, write_member,
};
// The value types are part of this module's API (`crate::material::Value`, ...).
pub use crate::values::{CurveValue, StoredValue, Value};
use crate::values::{Ranges, default_value, normalise};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use weft_meta::{
    InstanceCount, KeywordKind, MaterialMetadata, MemberEncoding, ParamKind, Parameter, Pass,
    PipelineConstant, UniformLayout, UniformMember, UniformType, Variant, VariantShader,
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
    /// Texture and cube parameters given a value since the last reset;
    /// the others bind their variant's default (`bindings[].texture.default`).
    set_textures: BTreeSet<String>,
    /// Texture parameters' images (`texture.file`), by parameter: what an
    /// unset one binds where its variant's binding names the file.
    images: BTreeMap<String, TextureValue>,
    tiling: BTreeMap<String, [f64; 4]>,
    keywords: BTreeMap<String, String>,
    tier: String,
}

impl Material {
    /// Reads `<name>.meta.json`; shader files are resolved next to it.
    pub fn load(meta_path: impl AsRef<Path>) -> Result<Material> {
        let path = meta_path.as_ref();
        let bytes = weft_meta::files::read_regular(path, weft_meta::files::MAX_TEXT_BYTES)
            .map_err(io_err(path))?;
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
        let dir: PathBuf = dir.into();
        let roots = crate::texture_files::material_roots(&dir);
        let images = meta
            .parameters
            .iter()
            .filter_map(|p| Some((p, p.texture.as_ref()?.file.as_ref()?)))
            .map(|(p, f)| Ok((p.name.clone(), crate::texture_files::read(&roots, f)?)))
            .collect::<Result<_>>()?;
        let mut m = Material {
            dir,
            values: BTreeMap::new(),
            set_textures: BTreeSet::new(),
            images,
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
        self.set_textures.clear();
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
        let stored = normalise(&p, value, Ranges::Check)?;
        self.store(&p, stored);
        Ok(())
    }

    fn store(&mut self, p: &Parameter, stored: StoredValue) {
        if matches!(p.kind, ParamKind::Texture2d | ParamKind::Cube) {
            self.set_textures.insert(p.name.clone());
        }
        self.values.insert(p.name.clone(), stored);
    }

    /// Whether a texture or cube parameter was given a value since the
    /// last reset. An unset one binds the built-in texture its variant's
    /// binding names (`texture.default`: the keyword-dependent default
    /// resolved), which [`Material::get`]'s declared default may not be.
    pub fn texture_is_set(&self, name: &str) -> bool {
        self.set_textures.contains(name)
    }

    /// The image a texture parameter ships (`texture.file`, read when the
    /// material was loaded), if it has one.
    pub fn texture_image(&self, name: &str) -> Option<&TextureValue> {
        self.images.get(name)
    }

    /// Sets a parameter to a value as a scene build uploaded it (colours
    /// linear, curves as samples): type-checked but not range-checked.
    pub fn set_as_uploaded(&mut self, name: &str, value: Value) -> Result<()> {
        let p = self.parameter(name)?.clone();
        let stored = normalise(&p, value, Ranges::Skip)?;
        self.store(&p, stored);
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
    /// the current keyword value's index in the constant's `values` (value
    /// i is the constant i; toggles off = 0, on = 1); a constant no keyword
    /// sets takes its `default_value`.
    pub fn pipeline_constants(&self, shader: &VariantShader) -> Result<Vec<(String, f64)>> {
        shader
            .pipeline_constants
            .iter()
            .map(|c| {
                let value = match self.keywords.get(&c.name) {
                    Some(v) => constant_value(c, v)?,
                    None => constant_default(c)?,
                };
                Ok((c.name.clone(), value))
            })
            .collect()
    }

    /// Instances a pass draws (a fixed count or an int parameter's value, at least 0).
    pub fn instance_count(&self, pass: &Pass) -> Result<u32> {
        match &pass.instances {
            InstanceCount::Fixed(n) => Ok(*n),
            InstanceCount::Parameter(p) => match self.values.get(p) {
                Some(StoredValue::Numbers(v)) if !v.is_empty() => Ok(instance_count_of(v[0])),
                _ => Err(Error::Metadata(format!(
                    "pass `{}` takes its instance count from `{p}`, which is not an int parameter",
                    pass.name
                ))),
            },
        }
    }

    /// The material uniform block packed at the offsets of `layout`: each
    /// parameter's value through weft-meta's encoder (its kind's member
    /// type and encoding, `weft_meta::uniform`).
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
                    .unwrap_or(TILING_OFFSET_DEFAULT);
                expect_ty(p, m, &TILING_OFFSET_TYPE)?;
                let v = MemberEncoding::TilingOffset.value(&Upload::TilingOffset(st))?;
                write_member(&mut bytes, m, &v)?;
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
            let mismatch = || {
                Error::Metadata(format!(
                    "parameter `{}` ({}) has uniform member `{mname}` of type `{}`",
                    p.name,
                    p.kind.name(),
                    m.ty
                ))
            };
            let (upload, samples) = match (p.kind, value) {
                (ParamKind::Float, StoredValue::Numbers(v)) => (Upload::Float(v[0]), 0),
                (ParamKind::Int, StoredValue::Numbers(v)) => (Upload::Int(v[0].round() as i64), 0),
                (ParamKind::Bool, StoredValue::Numbers(v)) => (Upload::Bool(v[0] != 0.0), 0),
                (ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4, StoredValue::Numbers(v)) => {
                    (Upload::Vector(v.clone()), 0)
                }
                // Stored linear (`values::normalise`).
                (ParamKind::Color, StoredValue::Numbers(v)) => (
                    Upload::LinearColor(v.as_slice().try_into().map_err(|_| mismatch())?),
                    0,
                ),
                (ParamKind::Curve, StoredValue::Curve(samples)) => {
                    (Upload::Curve(samples.clone()), samples.len() as u32)
                }
                _ => return Err(mismatch()),
            };
            let (Some(ty), Some(encoding)) = (p.kind.uniform_type(samples), p.kind.encoding())
            else {
                return Err(mismatch());
            };
            expect_ty(p, m, &ty)?;
            write_member(&mut bytes, m, &encoding.value(&upload)?)?;
        }
        Ok(bytes)
    }
}

/// An int parameter's value as an instance count (rounded, at least 0).
pub fn instance_count_of(x: f64) -> u32 {
    x.round().clamp(0.0, f64::from(u32::MAX)) as u32
}

/// The constant for keyword value `value`: its index in `c.values`.
pub fn constant_value(c: &PipelineConstant, value: &str) -> Result<f64> {
    c.values
        .iter()
        .position(|x| x == value)
        .map(|i| i as f64)
        .ok_or_else(|| {
            Error::Metadata(format!(
                "pipeline constant `{}` has no value `{value}` (values: {})",
                c.name,
                c.values.join(", ")
            ))
        })
}

/// A pipeline constant's `default_value` as the number WebGPU takes
/// (bools 0/1): what a constant no keyword sets is drawn with.
pub fn constant_default(c: &PipelineConstant) -> Result<f64> {
    match &c.default_value {
        serde_json::Value::Bool(b) => Ok(f64::from(u8::from(*b))),
        serde_json::Value::Number(n) => n.as_f64().ok_or_else(|| {
            Error::Metadata(format!(
                "pipeline constant `{}` has an unreadable default_value {n}",
                c.name
            ))
        }),
        other => Err(Error::Metadata(format!(
            "pipeline constant `{}` has default_value {other}; expected a bool or a number",
            c.name
        ))),
    }
}

fn expect_ty(p: &Parameter, m: &UniformMember, expected: &UniformType) -> Result<()> {
    if m.ty == *expected {
        Ok(())
    } else {
        Err(Error::Metadata(format!(
            "uniform member of `{}` ({}) has type `{}`, expected `{expected}`",
            p.name,
            p.kind.name(),
            m.ty
        )))
    }
}
