//! Compiling one variant: specialise, validate, emit every language, reflect.

use crate::compile::backends::{self, stage_suffix};
use crate::compile::compose::validator;
use crate::compile::digest::sha256_hex;
use crate::compile::engine_binding::FEATURE_DEFAULTS;
use crate::compile::prelude::{Prelude, TIER_OVERRIDE};
use crate::compile::reflect;
use crate::compile::specialise::{Bindings, specialise};
use naga::Literal;
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

fn keyword_literal(kind: KeywordKind, value: usize) -> Literal {
    match kind {
        KeywordKind::Toggle => Literal::Bool(value == 1),
        KeywordKind::Enum => Literal::U32(value as u32),
    }
}

/// All combinations of the `constant`-mode keywords' values (one empty
/// combination if none), the keywords' defaults first: a variant's first
/// file set is the one its defaults select (the GPU model costs that one).
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
                let values = std::iter::once(kw.default)
                    .chain((0..kw.values.len()).filter(move |&v| v != kw.default));
                values.map(move |v| {
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
    fallback: Option<&naga::Module>,
    key: &VariantKey,
    prelude: &Prelude,
) -> Result<CompiledVariant, String> {
    let id = key.id(m);
    let mut values = Bindings {
        keep_entry_points: Some(m.kept_entry_points(key)),
        ..Bindings::default()
    };
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
    let validate = |module: &naga::Module, what: &str| {
        validator().validate(module).map_err(|e| {
            format!(
                "variant `{id}`{what} fails validation after specialisation: {}",
                e.as_inner()
            )
        })
    };
    let specialised = specialise(module, &values);
    let info = validate(&specialised, "")?;
    // Half-precision code: the same variant of the f32 composition (crate::compile::half).
    let specialised_fallback = match fallback {
        Some(f) if crate::compile::half::uses_f16(&specialised) => {
            let f = specialise(f, &values);
            let finfo = validate(&f, " (its f32 fallback)")?;
            Some((f, finfo))
        }
        _ => None,
    };
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
        (&specialised, &info),
        specialised_fallback.as_ref().map(|(f, i)| (f, i)),
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
                table: None,
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
                file: crate::compile::texture_files::resource_file(m, p),
            })
        })
        .chain(prelude.table_bindings.iter().filter_map(|(name, binding)| {
            let t = m.tables.iter().find(|t| &t.name == name)?;
            Some(reflect::MaterialTexture {
                table: Some(crate::compile::tables::resource(m, t)),
                param: name.clone(),
                binding: *binding,
                format: crate::compile::tables::TABLE_FORMAT.into(),
                default: None,
                file: None,
            })
        }))
        .collect()
}

/// Emits a specialised, validated module in every language (one set of
/// non-WGSL files per combination of `constant`-mode keyword values) and
/// reflects its metadata. Files are named `<id>[+keyword-value...].<ext>`.
///
/// A module that keeps f16 values needs `portable`, the same variant with
/// `weft_half` = f32 (crate::compile::half): every language's files are written from
/// it, so they run on any device, and the f16 module adds `<stem>.f16.*`
/// WGSL, SPIR-V and MSL files (`f16_files`) for devices with `shader-f16`.
pub fn emit_shader(
    m: &Material,
    (specialised, info): (&naga::Module, &naga::valid::ModuleInfo),
    portable: Option<(&naga::Module, &naga::valid::ModuleInfo)>,
    id: String,
    prelude: &Prelude,
    textures: &[reflect::MaterialTexture],
    combos: &[Vec<(usize, usize)>],
) -> Result<CompiledVariant, String> {
    // (main module, its f16 original when the main one is the f32 fallback)
    let (main, half) = match (crate::compile::half::uses_f16(specialised), portable) {
        (false, _) => ((specialised, info), None),
        (true, Some(p)) => (p, Some((specialised, info))),
        (true, None) => {
            return Err(format!(
                "variant `{id}` computes in f16 but has no f32 fallback (write half-precision code with `weft_half`)"
            ));
        }
    };
    let mut out = Emitted::default();
    let wgsl = backends::emit_wgsl(main.0, main.1)?;
    out.add(LanguageFile {
        lang: "wgsl",
        name: format!("{id}.wgsl"),
        bytes: wgsl.clone().into_bytes(),
        ..Default::default()
    });
    if let Some((h, hinfo)) = half {
        let text = backends::emit_wgsl(h, hinfo)?;
        out.add_f16(LanguageFile {
            lang: "wgsl",
            name: format!("{id}.f16.wgsl"),
            bytes: text.into_bytes(),
            ..Default::default()
        });
    }

    // Other languages cannot keep overrides: one set of files per constant-keyword combination.
    for combo in combos {
        let mut suffix = String::new();
        let mut constants = BTreeMap::new();
        for &(k, v) in combo {
            let kw = &m.keywords[k];
            suffix.push_str(&format!("+{}-{}", kw.name.to_lowercase(), kw.values[v]));
            constants.insert(kw.name.clone(), kw.values[v].clone());
        }
        let stem = format!("{id}{suffix}");
        let err = |e: String| format!("variant `{stem}`: {e}");
        let file = |lang: &'static str, name: String, bytes: Vec<u8>| LanguageFile {
            lang,
            name,
            bytes,
            constants: constants.clone(),
            ..Default::default()
        };
        let (resolved, rinfo) = resolve_constants(m, main.0, main.1, combo).map_err(err)?;
        let spirv = backends::emit_spirv(&resolved, &rinfo).map_err(err)?;
        out.add(file("spirv", format!("{stem}.spv"), spirv));
        let hlsl = backends::emit_hlsl(&resolved, &rinfo).map_err(err)?;
        out.add(file("hlsl", format!("{stem}.hlsl"), hlsl.into_bytes()));
        let msl = backends::emit_msl(&resolved, &rinfo).map_err(err)?;
        out.add(file("msl", format!("{stem}.metal"), msl.into_bytes()));
        for ep in &resolved.entry_points {
            let (src, table) =
                backends::emit_glsl(&resolved, &rinfo, &ep.name, ep.stage).map_err(err)?;
            out.add(LanguageFile {
                entry_point: Some(ep.name.clone()),
                glsl: Some(table),
                ..file(
                    "glsl",
                    format!("{stem}.{}.{}.glsl", ep.name, stage_suffix(ep.stage)),
                    src.into_bytes(),
                )
            });
        }
        // Half precision: the languages that can carry f16 (naga's GLSL
        // writer cannot; HLSL SM 5.1 has no 16-bit float).
        if let Some((h, hinfo)) = half {
            let (resolved, rinfo) = resolve_constants(m, h, hinfo, combo).map_err(err)?;
            let spirv = backends::emit_spirv(&resolved, &rinfo).map_err(err)?;
            out.add_f16(file("spirv", format!("{stem}.f16.spv"), spirv));
            let msl = backends::emit_msl(&resolved, &rinfo).map_err(err)?;
            out.add_f16(file("msl", format!("{stem}.f16.metal"), msl.into_bytes()));
        }
    }
    let Emitted {
        files,
        by_lang,
        f16_by_lang,
    } = out;
    let specialised = main.0;
    let info = main.1;

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
        f16_files: f16_by_lang,
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

/// One emitted file before it is listed in the metadata.
#[derive(Default)]
struct LanguageFile {
    lang: &'static str,
    name: String,
    bytes: Vec<u8>,
    entry_point: Option<String>,
    constants: BTreeMap<String, String>,
    glsl: Option<weft_meta::GlslReflection>,
}

/// The files of a variant and their metadata listings (main and f16).
#[derive(Default)]
struct Emitted {
    files: Vec<(String, Vec<u8>)>,
    by_lang: BTreeMap<String, Vec<ShaderFile>>,
    f16_by_lang: BTreeMap<String, Vec<ShaderFile>>,
}

impl Emitted {
    fn listing(f: &LanguageFile) -> ShaderFile {
        ShaderFile {
            path: f.name.clone(),
            sha256: sha256_hex(&f.bytes),
            entry_point: f.entry_point.clone(),
            constants: f.constants.clone(),
            glsl: f.glsl.clone(),
        }
    }

    fn add(&mut self, f: LanguageFile) {
        let listing = Self::listing(&f);
        self.by_lang.entry(f.lang.into()).or_default().push(listing);
        self.files.push((f.name, f.bytes));
    }

    fn add_f16(&mut self, f: LanguageFile) {
        let listing = Self::listing(&f);
        self.f16_by_lang
            .entry(f.lang.into())
            .or_default()
            .push(listing);
        self.files.push((f.name, f.bytes));
    }
}

/// `module` with the `constant`-mode keywords of `combo` resolved (naga has
/// no SPIR-V specialisation constants), anonymised, compacted and validated.
fn resolve_constants(
    m: &Material,
    module: &naga::Module,
    info: &naga::valid::ModuleInfo,
    combo: &[(usize, usize)],
) -> Result<(naga::Module, naga::valid::ModuleInfo), String> {
    let mut pc = naga::back::PipelineConstants::default();
    for &(k, v) in combo {
        let kw = &m.keywords[k];
        // A keyword the module no longer reads has no override left to set.
        let read = module
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
    let (resolved, _) = naga::back::pipeline_constants::process_overrides(module, info, None, &pc)
        .map_err(|e| format!("resolving pipeline constants: {e}"))?;
    let mut resolved = resolved.into_owned();
    for (_, o) in resolved.overrides.iter_mut() {
        o.name = None;
        o.id = None;
    }
    naga::compact::compact(&mut resolved, naga::compact::KeepUnused::No);
    crate::compile::half::declare_f16(&mut resolved);
    let rinfo = validator()
        .validate(&resolved)
        .map_err(|e| format!("fails validation: {}", e.as_inner()))?;
    Ok((resolved, rinfo))
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
