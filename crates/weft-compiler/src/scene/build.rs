//! Building a resolved scene: one folded shader per distinct instance,
//! deduplicated by emitted WGSL, plus `<scene>.scene.json`.
//!
//! Fail-closed: every instance either gets its own specialised shader or the
//! build fails with a diagnostic at the scene file's line; nothing is written
//! on error (the caller writes `SceneOutput::files` atomically).

use super::checks;
use super::fold::{Folded, fold};
use super::instance::{InstanceValues, instance_values, static_lighting_members};
use super::record::{self, BuiltInstance, Recorded, keyword_names};
use super::tiers::{AutoTierRequest, TierChooser};
use crate::compile::compose::{self, validator};
use crate::compile::digest::sha256_hex;
use crate::compile::material::{CompiledMaterial, compile_material};
use crate::compile::prelude;
use crate::compile::variant::{CompiledVariant, emit_shader, material_textures};
use codespan_reporting::diagnostic::{Diagnostic, Label};
use rayon::prelude::*;
use std::collections::BTreeMap;
use weft_front::model::Material;
use weft_front::scene::model::{InstanceMesh, ResolvedInstance, ResolvedScene, TierChoice};
use weft_front::variants::VariantKey;
use weft_front::{Diagnostics, SourceDb};
use weft_meta::scene::SceneMetadata;

/// A built scene: files relative to the output root (`<scene>/...`).
pub struct SceneOutput {
    pub name: String,
    pub files: BTreeMap<String, Vec<u8>>,
    pub metadata: SceneMetadata,
    /// Per instance: the static variant id of the generic library shader.
    pub generic_variants: Vec<String>,
    /// Warnings (e.g. a `dynamic` parameter the shader does not read).
    pub warnings: Option<(SourceDb, Diagnostics)>,
    /// The materials root the scene's materials came from (an input an
    /// output folder must lie apart from).
    pub materials_root: std::path::PathBuf,
}

#[derive(Default)]
pub struct SceneBuildOptions<'a> {
    /// Chooses `tier = "auto"` instances' tiers (None: such a scene is an error).
    pub tier_chooser: Option<&'a dyn TierChooser>,
    /// For a `.gltf` / `.glb` scene: the materials root its materials map
    /// into (None: `./materials`, else one beside an ancestor of the file;
    /// `weft_front::scene::default_gltf_materials_root`).
    pub gltf_materials: Option<&'a std::path::Path>,
}

fn instance_error(
    scene: &ResolvedScene,
    inst: &ResolvedInstance,
    code: &str,
    msg: String,
    label: &str,
) -> Diagnostic<weft_front::FileId> {
    Diagnostic::error()
        .with_code(code)
        .with_message(msg)
        .with_labels(vec![
            Label::primary(scene.manifest.file, inst.span.clone()).with_message(label.to_string()),
        ])
}

/// The tier every instance is built with; `auto` decided by the chooser.
fn decide_tiers(
    scene: &ResolvedScene,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
    chooser: Option<&dyn TierChooser>,
) -> Option<Vec<(usize, Option<weft_meta::scene::TierChoice>)>> {
    let mut libraries: BTreeMap<usize, CompiledMaterial> = BTreeMap::new();
    let mut out = Vec::new();
    for inst in &scene.instances {
        match &inst.tier {
            TierChoice::Fixed(t) => out.push((*t, None)),
            TierChoice::Auto {
                error_budget,
                screen_size,
            } => {
                let m = &scene.materials[inst.material];
                let Some(chooser) = chooser else {
                    diags.push(
                        Diagnostic::error()
                            .with_code("auto-tier")
                            .with_message(format!(
                                "instance `{}` asks for `tier = \"auto\"`, which needs tier measurements",
                                inst.name
                            ))
                            .with_labels(vec![Label::primary(
                                scene.manifest.file,
                                inst.tier_span.clone(),
                            )])
                            .with_notes(vec![
                                "build the scene with `weft build --scene` (it measures on lavapipe), or pass a tier chooser to `build_scene`".into(),
                            ]),
                    );
                    out.push((0, None));
                    continue;
                };
                if let std::collections::btree_map::Entry::Vacant(e) =
                    libraries.entry(inst.material)
                {
                    e.insert(compile_material(m, db, diags)?);
                }
                let values = instance_values(m, inst, m.tiers.default, &scene.manifest.features);
                let mut request_values = values.uniform.clone();
                request_values.extend(values.constants.clone());
                // The glTF mesh's streams, read back from its file bytes.
                let mesh_data = match &inst.mesh {
                    InstanceMesh::File(f) => Some(f.data()),
                    InstanceMesh::Builtin(_) => None,
                };
                let request = AutoTierRequest {
                    instance: &inst.name,
                    material: &libraries[&inst.material],
                    keywords: keyword_names(m, inst),
                    values: request_values,
                    mesh: inst.mesh.name(),
                    mesh_data: mesh_data.as_ref(),
                    features: scene.manifest.features,
                    error_budget: *error_budget,
                    screen_size: *screen_size,
                    gpu_family: &scene.manifest.gpu_family,
                };
                match chooser.choose(&request) {
                    Ok(decision) => match m.tiers.values.iter().position(|t| *t == decision.tier) {
                        Some(t) => out.push((t, Some(decision.record))),
                        None => {
                            diags.push(instance_error(
                                scene,
                                inst,
                                "auto-tier",
                                format!(
                                    "the tier chooser picked `{}`, which `{}` does not have",
                                    decision.tier, m.name
                                ),
                                "this instance",
                            ));
                            out.push((0, None));
                        }
                    },
                    Err(e) => {
                        diags.push(
                            Diagnostic::error()
                                .with_code("auto-tier")
                                .with_message(format!("choosing the tier of `{}`: {e}", inst.name))
                                .with_labels(vec![Label::primary(
                                    scene.manifest.file,
                                    inst.tier_span.clone(),
                                )]),
                        );
                        out.push((0, None));
                    }
                }
            }
        }
    }
    Some(out)
}

/// The most distinct specialised shaders one scene may need: each is folded,
/// validated, written for every backend and written out (six files), about
/// 4 ms of CPU and as much again of file writing apiece on the project's
/// 2-core machine, so this bounds a scene's build at a few seconds
/// (docs/scaling.md, "Scene limits"). Instances that share a shader (the same
/// material, tier, keywords and folded values) count once.
pub const MAX_SCENE_SHADERS: usize = 256;

/// What decides an instance's specialised shader: its material, tier,
/// keywords and everything folded into it. Instances with equal keys get the
/// same shader, so it is compiled once (the emitted WGSL's hash still merges
/// different keys that fold to the same code).
fn specialisation_key(inst: &ResolvedInstance, tier: usize, values: &InstanceValues) -> String {
    format!(
        "{}|{tier}|{:?}|{:?}|{:?}",
        inst.material, inst.keywords, values.fold, inst.overrides.sampler
    )
}

/// One distinct specialisation folded, validated and emitted.
fn build_instance(
    m: &Material,
    (module, fallback): (&naga::Module, Option<&naga::Module>),
    prelude: &prelude::Prelude,
    inst: &ResolvedInstance,
    tier: usize,
    values: &InstanceValues,
) -> Result<CompiledVariant, String> {
    // A literal WGSL cannot spell (inf, NaN) would make every backend's output
    // invalid; ranges normally stop such values in the front end.
    for (name, v) in &values.fold.members {
        if let super::fold::ConstValue::F32(xs) = v
            && xs.iter().any(|x| !x.is_finite())
        {
            return Err(format!("the value of `{name}` does not fit a 32-bit float"));
        }
    }
    let Folded { module, .. } = fold(module, &values.fold)?;
    let validate = |module: &naga::Module, what: &str| {
        validator()
            .validate(module)
            .map_err(|e| format!("the folded shader{what} fails validation: {}", e.as_inner()))
    };
    let info = validate(&module, "")?;
    // Half-precision code: the same fold of the f32 composition (crate::compile::half).
    let fallback = match fallback {
        Some(f) if crate::compile::half::uses_f16(&module) => {
            let Folded { module: f, .. } = fold(f, &values.fold)?;
            let finfo = validate(&f, " (its f32 fallback)")?;
            Some((f, finfo))
        }
        _ => None,
    };
    // The id is the content hash, known only after emitting: emit under a
    // placeholder stem and rename. A sampler override is part of what the
    // shader entry describes (its binding's state), so it is hashed too:
    // instances that fold to one WGSL but sample differently get two entries.
    let wgsl = crate::compile::backends::emit_wgsl(&module, &info)?;
    let hash = match &inst.overrides.sampler {
        None => sha256_hex(wgsl.as_bytes()),
        Some(s) => sha256_hex(format!("{wgsl}\0sampler {s:?}").as_bytes()),
    };
    let id = format!("{}.{}", m.name, &hash[..12]);
    let keywords = keyword_names(m, inst);
    let textures = material_textures(m, prelude, &m.tiers.values[tier], |k| {
        keywords.get(k).map(String::as_str)
    });
    let mut compiled = emit_shader(
        m,
        (&module, &info),
        fallback.as_ref().map(|(f, i)| (f, i)),
        id,
        prelude,
        &textures,
        &[Vec::new()],
    )?;
    // The instance's sampler state where the shader reads its maps (a shader
    // that folded every map away has no such binding left to set).
    if let Some(over) = &inst.overrides.sampler {
        for b in compiled
            .shader
            .bindings
            .iter_mut()
            .filter(|b| checks::is_material_sampler(b))
        {
            if let Some(s) = &mut b.sampler {
                over.apply(s);
            }
        }
    }
    Ok(compiled)
}

/// Builds a resolved scene. Diagnostics point into the scene file.
///
/// Stages: `auto` tiers decided; each material composed and validated once;
/// each instance's values, grouped into distinct specialisations, each folded
/// and emitted in parallel; every instance checked ([`super::checks`]) and
/// recorded ([`super::record`]); the metadata assembled.
pub fn build_resolved_scene(
    scene: ResolvedScene,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
    options: &SceneBuildOptions,
) -> Option<SceneOutput> {
    let before = diags.error_count();
    let tiers = decide_tiers(&scene, db, diags, options.tier_chooser)?;
    if diags.error_count() > before {
        return None;
    }
    let modules = material_modules(&scene, db, diags)?;
    let engine = compose::engine_interface_file(db);
    let features = scene.manifest.features;
    let static_lighting = static_lighting_members(&scene.manifest);
    let values: Vec<InstanceValues> = scene
        .instances
        .iter()
        .zip(&tiers)
        .map(|(inst, (tier, _))| {
            let mut v = instance_values(&scene.materials[inst.material], inst, *tier, &features);
            v.fold.frame_members = static_lighting.clone();
            v
        })
        .collect();
    let (unique, spec) = specialisations(&scene, &tiers, &values);
    if !checks::within_shader_limit(&scene, &unique, diags) {
        return None;
    }
    let mut results: Vec<Result<CompiledVariant, String>> = unique
        .par_iter()
        .map(|&k| {
            let inst = &scene.instances[k];
            let m = &scene.materials[inst.material];
            let module = &modules[inst.material];
            build_instance(
                m,
                (&module.module, module.fallback.as_ref()),
                &module.prelude,
                inst,
                tiers[k].0,
                &values[k],
            )
        })
        .collect();

    let manifest = &scene.manifest;
    let mut recorded = Recorded::default();
    for (k, ((inst, (tier, choice)), values)) in
        scene.instances.iter().zip(tiers).zip(values).enumerate()
    {
        let m = &scene.materials[inst.material];
        let compiled = match &mut results[spec[k]] {
            Ok(c) => c,
            Err(e) => {
                diags.push(instance_error(
                    &scene,
                    inst,
                    "scene-fold",
                    format!("specialising instance `{}` ({}): {e}", inst.name, m.name),
                    "this instance",
                ));
                continue;
            }
        };
        let static_key = VariantKey::of_values(m, tier, &inst.keywords);
        let variant = static_key.id(m);
        let module = &modules[inst.material];
        let limits = checks::LimitInputs {
            composed: &module.composed,
            module: &module.module,
            engine,
        };
        if !checks::mesh_feeds_shader(manifest, inst, m, &variant, &compiled.shader, diags)
            || !checks::shader_fits_limits(manifest, inst, m, &static_key, compiled, limits, diags)
        {
            continue;
        }
        checks::warn_unread_dynamic(manifest, inst, m, &variant, &compiled.shader, diags);
        checks::warn_unused_sampler(manifest, inst, &compiled.shader, diags);
        let built = BuiltInstance {
            material: m,
            instance: inst,
            tier,
            choice,
            values,
            static_key,
            variant,
        };
        recorded.add(&manifest.name, built, compiled);
    }
    checks::within_shader_budget(manifest, recorded.shaders.len(), diags);
    if diags.error_count() > before {
        return None;
    }
    Some(record::assemble(scene, db, recorded))
}

/// A material composed, parsed and validated once for all its instances.
struct MaterialModule {
    prelude: prelude::Prelude,
    module: naga::Module,
    composed: crate::compile::source_map::Composed,
    /// The f32 module of a material with half-precision tiers.
    fallback: Option<naga::Module>,
}

fn material_modules(
    scene: &ResolvedScene,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<Vec<MaterialModule>> {
    let mut modules = Vec::new();
    for m in &scene.materials {
        let prelude = prelude::generate(m);
        let composed = compose::compose(m, &prelude, db);
        let (module, _) = compose::parse_and_validate(&composed, m, diags)?;
        let fallback =
            crate::compile::half::fallback_module(m, &prelude, db, diags)?.map(|(_, f)| f);
        modules.push(MaterialModule {
            prelude,
            module,
            composed,
            fallback,
        });
    }
    Some(modules)
}

/// Instances with the same specialisation share one compile: `unique` holds
/// the first instance of each, `spec[k]` instance k's index into it.
fn specialisations(
    scene: &ResolvedScene,
    tiers: &[(usize, Option<weft_meta::scene::TierChoice>)],
    values: &[InstanceValues],
) -> (Vec<usize>, Vec<usize>) {
    let mut first: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    let mut unique: Vec<usize> = Vec::new();
    let mut spec: Vec<usize> = Vec::with_capacity(scene.instances.len());
    for (k, (inst, (tier, _))) in scene.instances.iter().zip(tiers).enumerate() {
        let key = specialisation_key(inst, *tier, &values[k]);
        let next = unique.len();
        let u = *first.entry(key).or_insert(next);
        if u == next {
            unique.push(k);
        }
        spec.push(u);
    }
    (unique, spec)
}
