//! Compiling one variant: specialise, validate, emit every language, reflect.

use crate::backends::{self, stage_suffix};
use crate::compose::FEATURE_DEFAULTS;
use crate::compose::validator;
use crate::prelude::{Prelude, TIER_OVERRIDE};
use crate::reflect;
use crate::specialise::{Bindings, specialise};
use naga::Literal;
use sha2::{Digest, Sha256};
use std::collections::{BTreeMap, HashMap};
use weft_front::model::Material;
use weft_front::variants::VariantKey;
use weft_meta::{KeywordKind, KeywordMode, PipelineConstant, ShaderFile, VariantShader};

/// A compiled variant: its files (name -> bytes) and reflection.
pub struct CompiledVariant {
    pub id: String,
    pub files: Vec<(String, Vec<u8>)>,
    pub shader: VariantShader,
    /// The WGSL text, used to detect identical variants.
    pub wgsl: String,
}

pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

fn keyword_literal(kind: KeywordKind, value: usize) -> Literal {
    match kind {
        KeywordKind::Toggle => Literal::Bool(value == 1),
        KeywordKind::Enum => Literal::U32(value as u32),
    }
}

/// All combinations of the `constant`-mode keywords' values (one empty combination if none).
pub fn constant_combinations(m: &Material) -> Vec<Vec<(usize, usize)>> {
    let mut combos = vec![Vec::new()];
    for (k, kw) in m
        .keywords
        .iter()
        .enumerate()
        .filter(|(_, k)| k.mode == KeywordMode::Constant)
    {
        combos = combos
            .into_iter()
            .flat_map(|c| {
                (0..kw.values.len()).map(move |v| {
                    let mut c2 = c.clone();
                    c2.push((k, v));
                    c2
                })
            })
            .collect();
    }
    combos
}

pub fn compile_variant(
    m: &Material,
    module: &naga::Module,
    key: &VariantKey,
    prelude: &Prelude,
) -> Result<CompiledVariant, String> {
    let id = key.id(m);
    let mut values = Bindings::default();
    values
        .values
        .insert(TIER_OVERRIDE.into(), Literal::U32(key.tier as u32));
    for &(k, v) in &key.keywords {
        let kw = &m.keywords[k];
        values
            .values
            .insert(kw.name.clone(), keyword_literal(kw.kind, v));
    }
    for (name, value) in FEATURE_DEFAULTS {
        values.values.insert(name.into(), value);
    }
    let specialised = specialise(module, &values);
    let info = validator().validate(&specialised).map_err(|e| {
        format!(
            "variant `{id}` fails validation after specialisation: {}",
            e.as_inner()
        )
    })?;
    let keyword_values: BTreeMap<&str, &str> = key
        .keywords
        .iter()
        .map(|&(k, v)| {
            (
                m.keywords[k].name.as_str(),
                m.keywords[k].values[v].as_str(),
            )
        })
        .collect();
    let textures = material_textures(m, prelude, m.tiers.values[key.tier].as_str(), |k| {
        keyword_values.get(k).copied()
    });
    emit_shader(
        m,
        &specialised,
        &info,
        id,
        prelude,
        &textures,
        &constant_combinations(m),
    )
}

/// The group-1 textures of `m` for one variant (its tier and the values of
/// its static keywords): formats, and defaults with `default_when` resolved.
pub fn material_textures<'a>(
    m: &Material,
    prelude: &Prelude,
    tier: &str,
    keyword: impl Fn(&str) -> Option<&'a str>,
) -> Vec<reflect::MaterialTexture> {
    prelude
        .texture_bindings
        .iter()
        .filter_map(|(name, binding)| {
            let p = m.param(name)?;
            let format = if p.srgb || p.kind == weft_meta::ParamKind::Gradient {
                "rgba8unorm_srgb"
            } else {
                "rgba8unorm"
            };
            Some(reflect::MaterialTexture {
                param: name.clone(),
                binding: *binding,
                format: format.into(),
                // None for gradients: their default is the baked ramp.
                default: p.texture_default_where(|subject| {
                    if subject == "tier" {
                        Some(tier)
                    } else {
                        keyword(subject)
                    }
                }),
            })
        })
        .collect()
}

/// Emits a specialised, validated module in every language (one set of
/// non-WGSL files per combination of `constant`-mode keyword values) and
/// reflects its metadata. Files are named `<id>[+keyword-value...].<ext>`.
pub fn emit_shader(
    m: &Material,
    specialised: &naga::Module,
    info: &naga::valid::ModuleInfo,
    id: String,
    prelude: &Prelude,
    textures: &[reflect::MaterialTexture],
    combos: &[Vec<(usize, usize)>],
) -> Result<CompiledVariant, String> {
    let wgsl = backends::emit_wgsl(specialised, info)?;

    let mut files: Vec<(String, Vec<u8>)> = vec![(format!("{id}.wgsl"), wgsl.clone().into_bytes())];
    let mut by_lang: BTreeMap<String, Vec<ShaderFile>> = BTreeMap::new();
    by_lang.entry("wgsl".into()).or_default().push(ShaderFile {
        path: format!("{id}.wgsl"),
        sha256: sha256_hex(wgsl.as_bytes()),
        entry_point: None,
        constants: BTreeMap::new(),
        glsl: None,
    });

    // Other languages cannot keep overrides: one set of files per constant-keyword combination.
    for combo in combos {
        let mut suffix = String::new();
        let mut constants = BTreeMap::new();
        let mut pc = naga::back::PipelineConstants::default();
        for &(k, v) in combo {
            let kw = &m.keywords[k];
            suffix.push_str(&format!("+{}-{}", kw.name.to_lowercase(), kw.values[v]));
            constants.insert(kw.name.clone(), kw.values[v].clone());
            // A keyword the module no longer reads has no override left to set.
            let read = specialised
                .overrides
                .iter()
                .any(|(_, o)| o.name.as_deref() == Some(kw.name.as_str()));
            if !read {
                continue;
            }
            pc.insert(
                kw.name.clone(),
                if kw.kind == KeywordKind::Toggle {
                    (v == 1) as u8 as f64
                } else {
                    v as f64
                },
            );
        }
        let (resolved, _) =
            naga::back::pipeline_constants::process_overrides(specialised, info, None, &pc)
                .map_err(|e| format!("variant `{id}`: resolving pipeline constants: {e}"))?;
        let mut resolved = resolved.into_owned();
        for (_, o) in resolved.overrides.iter_mut() {
            o.name = None;
            o.id = None;
        }
        naga::compact::compact(&mut resolved, naga::compact::KeepUnused::No);
        let rinfo = validator()
            .validate(&resolved)
            .map_err(|e| format!("variant `{id}{suffix}` fails validation: {}", e.as_inner()))?;
        let backends::OtherLanguages {
            spirv,
            hlsl,
            msl,
            glsl,
        } = backends::emit_others(&resolved, &rinfo)
            .map_err(|e| format!("variant `{id}{suffix}`: {e}"))?;
        let stem = format!("{id}{suffix}");
        let mut add = |lang: &str,
                       name: String,
                       bytes: Vec<u8>,
                       entry: Option<String>,
                       glsl: Option<weft_meta::GlslReflection>| {
            by_lang.entry(lang.into()).or_default().push(ShaderFile {
                path: name.clone(),
                sha256: sha256_hex(&bytes),
                entry_point: entry,
                constants: constants.clone(),
                glsl,
            });
            files.push((name, bytes));
        };
        add("spirv", format!("{stem}.spv"), spirv, None, None);
        add(
            "hlsl",
            format!("{stem}.hlsl"),
            hlsl.into_bytes(),
            None,
            None,
        );
        add("msl", format!("{stem}.metal"), msl.into_bytes(), None, None);
        for (entry, stage, src, table) in glsl {
            add(
                "glsl",
                format!("{stem}.{entry}.{}.glsl", stage_suffix(stage)),
                src.into_bytes(),
                Some(entry),
                Some(table),
            );
        }
    }

    let pipeline_constants = specialised
        .overrides
        .iter()
        .filter_map(|(_, o)| {
            let name = o.name.clone()?;
            let kw = m.keyword(&name)?;
            let toggle = kw.kind == KeywordKind::Toggle;
            Some(PipelineConstant {
                ty: if toggle { "bool".into() } else { "u32".into() },
                values: kw.values.clone(),
                default: kw.values[kw.default].clone(),
                default_value: if toggle {
                    serde_json::json!(kw.default == 1)
                } else {
                    serde_json::json!(kw.default)
                },
                name,
            })
        })
        .collect();

    let members = reflect::member_params(m);
    let locations = reflect::vertex_locations(specialised);
    let vertex_inputs = m
        .requires
        .iter()
        .filter(|a| locations.contains(&a.location()))
        .map(|a| weft_meta::VertexInput {
            name: a.name().into(),
            location: a.location(),
            format: a.format().into(),
        })
        .collect();

    let shader = VariantShader {
        files: by_lang,
        entry_points: reflect::entry_points(specialised),
        pipeline_constants,
        bindings: reflect::bindings(specialised, info, textures, &members),
        material_uniform: reflect::material_uniform(specialised, &members),
        vertex_inputs,
        reads: reflect::reads(m, specialised, prelude),
    };
    Ok(CompiledVariant {
        id,
        files,
        shader,
        wgsl,
    })
}

/// Maps each variant to the first earlier variant with identical WGSL.
pub fn find_aliases(variants: &[CompiledVariant]) -> Vec<Option<usize>> {
    let mut first: HashMap<&str, usize> = HashMap::new();
    variants
        .iter()
        .enumerate()
        .map(|(i, v)| match first.get(v.wgsl.as_str()) {
            Some(&j) => Some(j),
            None => {
                first.insert(&v.wgsl, i);
                None
            }
        })
        .collect()
}
