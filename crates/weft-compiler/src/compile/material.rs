//! One material through every compile stage: prelude, compose, parse and
//! validate once, every variant in parallel (specialise, validate, backends,
//! reflect), the interface and limit checks, aliasing, then the metadata.
//! Returns the material's files relative to its own folder; writes nothing.
//! Where compiled variants are kept between builds is the caller's
//! ([`VariantStore`]; the build's shared cache implements it).

use crate::compile::compose;
use crate::compile::engine_binding::ENGINE_INTERFACE;
pub use crate::compile::engine_binding::{
    SHEEN_LUT_PATH, SHEEN_LUT_SIZE, SPLIT_SUM_LUT_PATH, SPLIT_SUM_LUT_SAMPLES, SPLIT_SUM_LUT_SIZE,
};
use crate::compile::variant::{self, CompiledVariant};
use crate::compile::{metadata, prelude};
use codespan_reporting::diagnostic::{Diagnostic, Label};
use rayon::prelude::*;
use sha2::{Digest, Sha256};
use weft_front::model::Material;
use weft_front::{Diagnostics, SourceDb, variants};
use weft_meta::{ENGINE_INTERFACE_VERSION, MaterialMetadata, SCHEMA_VERSION, Variant};

/// Where compiled variants are kept between builds, keyed by the material's
/// [`inputs_hash`] and the variant id. The compile stages never touch disk;
/// `build::cache::UnitCache` implements this for the shared cache.
pub trait VariantStore: Sync {
    /// The stored variant, if there is one, and whether it must be compiled
    /// again and compared before it is trusted.
    fn fetch(&self, inputs_hash: &str, variant_id: &str) -> Option<(CompiledVariant, bool)>;
    /// A stored variant against the same variant compiled now: an error
    /// saying what is wrong with the store if they differ.
    fn verify(
        &self,
        inputs_hash: &str,
        stored: &CompiledVariant,
        fresh: &CompiledVariant,
    ) -> Result<(), String>;
    /// Keeps a variant just compiled. Best effort: a store that cannot be
    /// written only costs the next build time.
    fn keep(&self, inputs_hash: &str, compiled: &CompiledVariant);
}

/// A material's metadata and its files (paths relative to its folder).
pub type CompiledMaterial = (MaterialMetadata, Vec<(String, Vec<u8>)>);

/// Hash of everything a material's output depends on.
pub fn inputs_hash(m: &Material, db: &SourceDb) -> String {
    let mut h = Sha256::new();
    h.update(env!("CARGO_PKG_VERSION"));
    h.update(ENGINE_INTERFACE);
    h.update(db.text(m.file));
    for s in m.sources.iter().chain(&m.pass_files) {
        h.update(&s.rel_path);
        h.update([0]);
        h.update(db.text(s.file));
    }
    // Texture files: a changed PNG rebuilds the material.
    for p in &m.params {
        if let Some(f) = &p.file {
            h.update(&f.path);
            h.update([0]);
            h.update(&f.image.sha256);
            h.update(
                [f.image.width, f.image.height]
                    .map(u32::to_le_bytes)
                    .concat(),
            );
        }
    }
    h.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

/// Compiles one loaded material: every variant, in parallel, then metadata.
/// Returns the material's files relative to its own folder.
pub fn compile_material(
    m: &Material,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<CompiledMaterial> {
    compile_material_with(m, db, diags, None)
}

/// As [`compile_material`], taking each variant (compile unit) from `store`
/// when it is there and keeping those it compiles.
pub fn compile_material_with(
    m: &Material,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
    store: Option<&dyn VariantStore>,
) -> Option<CompiledMaterial> {
    let inputs = inputs_hash(m, db);
    let prelude = prelude::generate(m);
    let composed = compose::compose(m, &prelude, db);
    let (module, _info) = compose::parse_and_validate(&composed, m, diags)?;
    if !check_interface(m, &module, diags) {
        return None;
    }
    let fallback = crate::compile::half::fallback_module(m, &prelude, db, diags)?;
    let fallback = fallback.as_ref().map(|(_, f)| f);
    let keys = variants::variants(m);
    let results: Vec<Result<CompiledVariant, String>> = keys
        .par_iter()
        .map(|k| {
            let Some(store) = store else {
                return variant::compile_variant(m, &module, fallback, k, &prelude);
            };
            let id = k.id(m);
            if let Some((stored, verify)) = store.fetch(&inputs, &id) {
                if !verify {
                    return Ok(stored);
                }
                let fresh = variant::compile_variant(m, &module, fallback, k, &prelude)?;
                store.verify(&inputs, &stored, &fresh)?;
                return Ok(fresh);
            }
            let v = variant::compile_variant(m, &module, fallback, k, &prelude)?;
            store.keep(&inputs, &v);
            Ok(v)
        })
        .collect();
    let mut compiled = Vec::new();
    for r in results {
        match r {
            Ok(v) => compiled.push(v),
            Err(msg) => diags.push(
                Diagnostic::error()
                    .with_code("variant")
                    .with_message(msg)
                    .with_labels(vec![
                        Label::primary(m.decl.file, m.decl.span.clone())
                            .with_message("in this material"),
                    ]),
            ),
        }
    }
    if compiled.len() != keys.len() {
        return None;
    }
    let engine = compose::engine_interface_file(db);
    let shown: Vec<String> = compiled
        .iter()
        .map(|v| format!("variant `{}`", v.id))
        .collect();
    if !crate::compile::limits::check_variants(
        m, &shown, &composed, &module, engine, &keys, &compiled, diags,
    ) {
        return None;
    }
    warn_unread_parameters(m, &compiled, diags);
    let aliases = variant::find_aliases(&compiled);
    // Baked tables and texture files first: files of the material whatever
    // its variants read.
    let mut files: Vec<(String, Vec<u8>)> = m
        .tables
        .iter()
        .map(|t| {
            (
                crate::compile::tables::file_name(t),
                crate::compile::tables::bake(t).to_vec(),
            )
        })
        .chain(crate::compile::texture_files::files(m))
        .collect();
    let mut variants_meta = Vec::new();
    for ((key, v), alias) in keys.iter().zip(compiled).zip(aliases) {
        let keywords = key
            .keywords
            .iter()
            .map(|&(k, val)| {
                (
                    m.keywords[k].name.clone(),
                    m.keywords[k].values[val].clone(),
                )
            })
            .collect();
        let passes: Vec<String> = m.passes_of(key).map(|p| p.name.clone()).collect();
        // An alias shares its target's files, so it must also draw the same
        // passes (two pass lists over the same entry points stay apart).
        let same_passes = |j: usize| m.passes_of(&keys[j]).map(|p| &p.name).eq(passes.iter());
        let (alias_of, shader) = match alias.filter(|&j| same_passes(j)) {
            Some(j) => (Some(keys[j].id(m)), None),
            None => {
                files.extend(v.files);
                (None, Some(v.shader))
            }
        };
        variants_meta.push(Variant {
            id: v.id,
            tier: m.tiers.values[key.tier].clone(),
            keywords,
            passes,
            alias_of,
            shader,
        });
    }
    let meta = MaterialMetadata {
        schema_version: SCHEMA_VERSION,
        schema_minor: weft_meta::SCHEMA_MINOR,
        engine_interface_version: ENGINE_INTERFACE_VERSION,
        name: m.name.clone(),
        label: weft_meta::Text {
            en: m.label.clone(),
            zh: m.label_zh.clone(),
        },
        description: m.description.as_ref().map(|d| weft_meta::Text {
            en: d.clone(),
            zh: m.description_zh.clone(),
        }),
        inputs_hash: inputs,
        groups: metadata::groups(m),
        parameters: metadata::parameters(m, &prelude),
        keywords: metadata::keywords(m),
        tiers: metadata::tiers(m),
        presets: metadata::presets(m),
        passes: metadata::passes(m),
        vertex_inputs: metadata::vertex_inputs(m),
        limits: (!m.limits.is_default()).then(|| m.limits.clone()),
        variants: variants_meta,
        languages: crate::compile::engine_binding::languages(),
        conventions: Some(weft_meta::Conventions::current()),
        // Measured by `weft bench`, attached at load time from reports/, never built in.
        measurements: None,
    };
    Some((meta, files))
}

/// A parameter that no variant reads does nothing: say so at its declaration.
fn warn_unread_parameters(m: &Material, compiled: &[CompiledVariant], diags: &mut Diagnostics) {
    for p in &m.params {
        if compiled.iter().any(|v| v.shader.reads.contains(&p.name)) {
            continue;
        }
        diags.push(
            Diagnostic::warning()
                .with_code("unread-param")
                .with_message(format!(
                    "parameter `{}` is read by no variant of `{}`",
                    p.name, m.name
                ))
                .with_labels(vec![
                    Label::primary(p.decl.file, p.decl.span.clone())
                        .with_message("changing this value changes nothing"),
                ])
                .with_notes(vec![
                    "use it in the shading code, or remove it from the material".into(),
                ]),
        );
    }
}

/// Passes name entry points that exist with the right stage; vertex stages
/// read only the inputs the material `requires`.
pub(crate) fn check_interface(
    m: &Material,
    module: &naga::Module,
    diags: &mut Diagnostics,
) -> bool {
    let before = diags.error_count();
    for pass in &m.passes {
        let wanted = [
            (
                &pass.vertex,
                naga::ShaderStage::Vertex,
                "vertex",
                &pass.vertex_span,
            ),
            (
                &pass.fragment,
                naga::ShaderStage::Fragment,
                "fragment",
                &pass.fragment_span,
            ),
        ];
        for (name, stage, stage_name, span) in wanted {
            if module
                .entry_points
                .iter()
                .any(|ep| &ep.name == name && ep.stage == stage)
            {
                continue;
            }
            let candidates: Vec<&str> = module
                .entry_points
                .iter()
                .filter(|ep| ep.stage == stage)
                .map(|ep| ep.name.as_str())
                .collect();
            let mut notes = Vec::new();
            if let Some(s) = weft_front::diag::did_you_mean(name, candidates.iter().copied()) {
                notes.push(format!("did you mean `{s}`?"));
            }
            notes.push(if candidates.is_empty() {
                format!("the WGSL defines no @{stage_name} entry point")
            } else {
                format!(
                    "@{stage_name} entry points in the WGSL: {}",
                    candidates.join(", ")
                )
            });
            diags.push(
                Diagnostic::error()
                    .with_code("missing-entry-point")
                    .with_message(format!("pass `{}` names {stage_name} entry point `{name}`, which the WGSL does not define", pass.name))
                    .with_labels(vec![Label::primary(pass.decl.file, span.clone()).with_message(format!("no @{stage_name} fn `{name}`"))])
                    .with_notes(notes),
            );
        }
    }
    let locations = crate::compile::reflect::vertex_locations(module);
    for loc in locations {
        if !m.requires.iter().any(|a| a.location() == loc) {
            let name = weft_front::model::VertexAttribute::ALL
                .iter()
                .find(|a| a.location() == loc)
                .map_or(format!("location {loc}"), |a| a.name().to_string());
            diags.push(
                Diagnostic::error()
                    .with_code("missing-require")
                    .with_message(format!("the vertex stage reads `{name}` (@location({loc})) but the material does not require it"))
                    .with_labels(vec![Label::primary(m.file, m.requires_span.clone()).with_message(format!("`{name}` missing here"))])
                    .with_notes(vec![format!("add \"{name}\" to `requires` in [material]")]),
            );
        }
    }
    diags.error_count() == before
}
