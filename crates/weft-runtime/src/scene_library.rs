//! A scene instance as the generic library variant would draw it: the
//! material's metadata from `generated/`, its variant and keywords, and the
//! instance's values (as uploaded) set as parameters. Used to compare a
//! scene's specialised shaders against the library and to measure the gain.

use crate::error::{Error, Result};
use crate::material::Material;
use crate::uniform::{json_number as number, json_numbers as numbers, json_samples};
use crate::values::{CurveValue, TextureValue, Value};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use weft_meta::scene::SceneInstance;
use weft_meta::{ParamKind, Parameter, TextureDefault};

/// The materials of one `generated/` folder, each loaded once.
pub struct Library {
    generated: PathBuf,
    materials: HashMap<String, Material>,
}

impl Library {
    pub fn new(generated: &Path) -> Library {
        Library {
            generated: generated.to_path_buf(),
            materials: HashMap::new(),
        }
    }

    /// The instance's material configured as the instance; the scene's own
    /// images (`textures/…`, docs/scenes.md "Images") read from `scene_dir`.
    pub fn instance_material(
        &mut self,
        inst: &SceneInstance,
        scene_dir: &Path,
    ) -> Result<Material> {
        let name = &inst.material;
        let mut material = match self.materials.get(name) {
            Some(m) => m.clone(),
            None => {
                let path = self.generated.join(name).join(format!("{name}.meta.json"));
                let m = Material::load(&path)?;
                self.materials.insert(name.clone(), m.clone());
                m
            }
        };
        configure_instance_material(&mut material, inst)?;
        for t in inst.textures.values() {
            let Some(file) = &t.file else { continue };
            // The material's own image is bound by the variant already.
            let shipped = material
                .metadata()
                .parameters
                .iter()
                .find(|p| p.name == t.parameter)
                .and_then(|p| p.texture.as_ref()?.file.as_ref())
                .is_some_and(|f| f.path == file.path);
            if !shipped {
                let roots = crate::texture_files::scene_roots(scene_dir);
                let value = crate::texture_files::read(&roots, file)?;
                material.set_as_uploaded(&t.parameter, Value::Texture(value))?;
            }
        }
        Ok(material)
    }
}

/// Sets `material` (the instance's material, freshly loaded) up as the scene
/// instance: its library variant (`alias_of` followed), every keyword, the
/// folded `constants`, the `uniform_values` by member (tiling members
/// included) and the bound `textures`. Values are taken as uploaded:
/// colours linear, curves as baked samples, booleans as 0/1.
pub fn configure_instance_material(material: &mut Material, inst: &SceneInstance) -> Result<()> {
    material.select_variant(&inst.variant)?;
    for (k, v) in &inst.keywords {
        material.set_keyword(k, v)?;
    }
    let wanted = material.variant_by_id(&inst.variant)?.canonical.id.clone();
    let current = material.current_variant()?.canonical.id.clone();
    if current != wanted || material.tier() != inst.tier {
        return Err(Error::Metadata(format!(
            "variant `{}` (tier `{}`) and keywords {:?} select `{current}` (tier `{}`) in material `{}`",
            inst.variant,
            inst.tier,
            inst.keywords,
            material.tier(),
            material.name()
        )));
    }
    for (name, v) in &inst.constants {
        if material
            .metadata()
            .parameters
            .iter()
            .any(|p| p.name == *name)
        {
            let p = material.parameter(name)?.clone();
            material.set_as_uploaded(name, uploaded_value(&p, v)?)?;
        } else {
            // A folded texture tiling (`<texture>_st`), by its member name.
            set_member(material, name, v)?;
        }
    }
    for (member, v) in &inst.uniform_values {
        set_member(material, member, v)?;
    }
    for (binding, t) in &inst.textures {
        // Left at its image: unset, so the variant's binding binds the file.
        if t.file.is_some() {
            continue;
        }
        let value = match (&t.builtin, &t.ramp_rgba8) {
            (Some(d), None) => TextureValue::Builtin(*d),
            (None, Some(ramp)) if !ramp.is_empty() && ramp.len().is_multiple_of(4) => {
                TextureValue::Rgba8 {
                    width: (ramp.len() / 4) as u32,
                    height: 1,
                    data: ramp.clone(),
                }
            }
            _ => {
                return Err(Error::Metadata(format!(
                    "texture `{binding}` (parameter `{}`) must give a built-in texture or an RGBA8 ramp",
                    t.parameter
                )));
            }
        };
        material.set_as_uploaded(&t.parameter, Value::Texture(value))?;
    }
    Ok(())
}

/// A parameter's value from its JSON as uploaded by a scene build.
fn uploaded_value(p: &Parameter, v: &serde_json::Value) -> Result<Value> {
    let bad = |what: &str| Error::InvalidValue {
        name: p.name.clone(),
        message: format!(
            "expected {what} for a {} parameter (as uploaded), got {v}",
            p.kind.name()
        ),
    };
    Ok(match p.kind {
        ParamKind::Float => Value::Float(number(v).ok_or_else(|| bad("a number"))?),
        ParamKind::Int => {
            let x = number(v)
                .filter(|x| x.fract() == 0.0)
                .ok_or_else(|| bad("an integer"))?;
            Value::Int(x as i64)
        }
        ParamKind::Bool => Value::Bool(number(v).ok_or_else(|| bad("0, 1 or a bool"))? != 0.0),
        ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 => {
            Value::Vector(numbers(v).ok_or_else(|| bad("an array of numbers"))?)
        }
        ParamKind::Color => match numbers(v).as_deref() {
            Some(&[r, g, b]) => Value::LinearColor([r, g, b, 1.0]),
            Some(&[r, g, b, a]) => Value::LinearColor([r, g, b, a]),
            _ => return Err(bad("3 or 4 linear components")),
        },
        ParamKind::Curve => {
            let n = p.curve.as_ref().map_or(0, |c| c.samples as usize);
            let flat = json_samples(v).ok_or_else(|| bad("curve samples"))?;
            // Packed 4 per vec4: the tail of the last vec4 is padding.
            if flat.len() < n || flat.len().div_ceil(4) != n.div_ceil(4) {
                return Err(bad(&format!("{n} curve samples")));
            }
            Value::Curve(CurveValue::Samples(flat[..n].to_vec()))
        }
        ParamKind::Gradient => {
            let bytes: Option<Vec<u8>> = v.as_array().and_then(|a| {
                a.iter()
                    .map(|x| x.as_u64().and_then(|b| u8::try_from(b).ok()))
                    .collect()
            });
            match bytes {
                Some(data) if !data.is_empty() && data.len().is_multiple_of(4) => {
                    Value::Texture(TextureValue::Rgba8 {
                        width: (data.len() / 4) as u32,
                        height: 1,
                        data,
                    })
                }
                _ => return Err(bad("RGBA8 ramp bytes")),
            }
        }
        ParamKind::Texture2d | ParamKind::Cube => {
            let srgb = p.texture.as_ref().is_some_and(|t| t.srgb);
            Value::Texture(TextureValue::Builtin(
                builtin_texture(v, srgb).ok_or_else(|| bad("a built-in texture"))?,
            ))
        }
    })
}

/// A built-in texture by name, or by the value sampling it returns (how a
/// scene build folds a texture left at its default).
fn builtin_texture(v: &serde_json::Value, srgb: bool) -> Option<TextureDefault> {
    if let Some(s) = v.as_str() {
        return TextureDefault::ALL.into_iter().find(|t| t.name() == s);
    }
    let n = numbers(v)?;
    TextureDefault::ALL.into_iter().find(|t| {
        let s = t.sampled(srgb);
        n.len() == 4
            && n.iter()
                .zip(s)
                .all(|(a, b)| (a - f64::from(b)).abs() < 1e-6)
    })
}

/// One uniform member's value as uploaded: a parameter's member, or a
/// texture's tiling (`<texture>_st`).
fn set_member(material: &mut Material, member: &str, v: &serde_json::Value) -> Result<()> {
    let params = &material.metadata().parameters;
    if let Some(p) = params
        .iter()
        .find(|p| p.uniform_member.as_deref() == Some(member))
    {
        let p = p.clone();
        material.set_as_uploaded(&p.name, uploaded_value(&p, v)?)?;
    } else if let Some(p) = params
        .iter()
        .find(|p| p.texture.as_ref().and_then(|t| t.tiling_member.as_deref()) == Some(member))
    {
        let name = p.name.clone();
        let st = numbers(v)
            .and_then(|n| <[f64; 4]>::try_from(n).ok())
            .ok_or_else(|| Error::InvalidValue {
                name: member.to_string(),
                message: format!("expected 4 numbers (tiling xy, offset zw), got {v}"),
            })?;
        material.set_tiling(&name, st)?;
    } else {
        return Err(Error::Metadata(format!(
            "uniform member `{member}` belongs to no parameter of material `{}`",
            material.name()
        )));
    }
    Ok(())
}
