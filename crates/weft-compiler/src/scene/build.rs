//! Building a resolved scene: one folded shader per distinct instance,
//! deduplicated by emitted WGSL, plus `<scene>.scene.json`.
//!
//! Fail-closed: every instance either gets its own specialised shader or the
//! build fails with a diagnostic at the scene file's line; nothing is written
//! on error (the caller writes `SceneOutput::files` atomically).

use super::fold::{Folded, fold};
use super::instance::{InstanceValues, instance_values, scene_transform};
use super::tiers::{AutoTierRequest, TierChooser};
use crate::compile::compose::{self, validator};
use crate::compile::material::{CompiledMaterial, compile_material};
use crate::compile::variant::{CompiledVariant, emit_shader, material_textures, sha256_hex};
use crate::compile::{metadata, prelude};
use codespan_reporting::diagnostic::{Diagnostic, Label};
use rayon::prelude::*;
use sha2::{Digest, Sha256};
use std::collections::BTreeMap;
use weft_front::model::{Material, ParamValue};
use weft_front::scene::model::{InstanceMesh, ResolvedInstance, ResolvedScene, TierChoice};
use weft_front::variants::VariantKey;
use weft_front::{Diagnostics, SourceDb};
use weft_meta::scene::{
    SCENE_SCHEMA_VERSION, SceneCamera, SceneFeatures, SceneInstance, SceneLight, SceneMetadata,
    SceneShader, SceneTexture,
};
use weft_meta::{ENGINE_INTERFACE_VERSION, ParamKind};

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

fn keyword_names(m: &Material, inst: &ResolvedInstance) -> BTreeMap<String, String> {
    m.keywords
        .iter()
        .zip(&inst.keywords)
        .map(|(k, &v)| (k.name.clone(), k.values[v].clone()))
        .collect()
}

/// Hash of everything the scene's output depends on but its glTF meshes
/// (hashed on top by the caller, from the files it carries): the manifest,
/// the materials, the toolchain and every image an instance binds.
fn scene_inputs_hash(scene: &ResolvedScene, db: &SourceDb) -> String {
    let mut h = Sha256::new();
    h.update(env!("CARGO_PKG_VERSION"));
    h.update(compose::ENGINE_INTERFACE);
    h.update(db.text(scene.manifest.file));
    for m in &scene.materials {
        h.update(crate::compile::material::inputs_hash(m, db));
    }
    for inst in &scene.instances {
        for (param, image) in &inst.images {
            h.update(param.to_le_bytes());
            h.update(&image.image.sha256);
        }
    }
    h.finalize().iter().map(|b| format!("{b:02x}")).collect()
}

/// The meshes the instances draw, by name: a built-in mesh's file in the
/// library (`path`), a glTF primitive's in the scene folder (`file`).
fn scene_meshes(
    scene: &ResolvedScene,
) -> std::collections::BTreeMap<String, weft_meta::scene::SceneMesh> {
    scene
        .instances
        .iter()
        .map(|i| {
            let name = i.mesh.name().to_string();
            let (path, file, radius) = match &i.mesh {
                InstanceMesh::Builtin(_) => (Some(weft_meta::mesh::mesh_path(&name)), None, None),
                InstanceMesh::File(m) => (
                    None,
                    Some(weft_meta::mesh::mesh_path(&name)),
                    Some(m.radius),
                ),
            };
            let mesh = weft_meta::scene::SceneMesh {
                path,
                file,
                radius,
                format: weft_meta::mesh::MESH_FORMAT.into(),
            };
            (name, mesh)
        })
        .collect()
}

/// The glTF meshes the scene carries: `meshes/<name>.mesh` (in the scene
/// folder) → the file's bytes, each once.
///
/// Moved out of the instances (which are spent: their meshes become the
/// built-in placeholder), so that the build never holds a mesh twice.
fn file_meshes(instances: &mut [ResolvedInstance]) -> BTreeMap<String, Vec<u8>> {
    let mut by_name: BTreeMap<String, Vec<std::sync::Arc<weft_front::gltf::FileMesh>>> =
        BTreeMap::new();
    for inst in instances.iter_mut() {
        if matches!(inst.mesh, InstanceMesh::File(_))
            && let InstanceMesh::File(m) = std::mem::replace(
                &mut inst.mesh,
                InstanceMesh::Builtin(weft_front::scene::model::BuiltinMesh::Sphere),
            )
        {
            by_name.entry(m.name.clone()).or_default().push(m);
        }
    }
    by_name
        .into_iter()
        .map(|(name, mut refs)| {
            let last = refs.pop().expect("at least one");
            drop(refs);
            // The last holder moves the bytes; one still shared elsewhere
            // (a caller's own clone) is copied.
            let bytes =
                std::sync::Arc::try_unwrap(last).map_or_else(|m| m.bytes.clone(), |m| m.bytes);
            (weft_meta::mesh::mesh_path(&name), bytes)
        })
        .collect()
}

/// The raised limits of the scene's materials, each at its highest.
fn scene_limits(scene: &ResolvedScene) -> Option<weft_meta::DeviceLimits> {
    let mut limits = weft_meta::DeviceLimits::default();
    for m in &scene.materials {
        limits.raise_to(&m.limits);
    }
    (!limits.is_default()).then_some(limits)
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
        "{}|{tier}|{:?}|{:?}",
        inst.material, inst.keywords, values.fold
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
    // placeholder stem and rename.
    let wgsl = crate::compile::backends::emit_wgsl(&module, &info)?;
    let id = format!("{}.{}", m.name, &sha256_hex(wgsl.as_bytes())[..12]);
    let keywords = keyword_names(m, inst);
    let textures = material_textures(m, prelude, &m.tiers.values[tier], |k| {
        keywords.get(k).map(String::as_str)
    });
    let compiled = emit_shader(
        m,
        (&module, &info),
        fallback.as_ref().map(|(f, i)| (f, i)),
        id,
        prelude,
        &textures,
        &[Vec::new()],
    )?;
    Ok(compiled)
}

/// Builds a resolved scene. Diagnostics point into the scene file.
pub fn build_resolved_scene(
    mut scene: ResolvedScene,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
    options: &SceneBuildOptions,
) -> Option<SceneOutput> {
    let before = diags.error_count();
    let manifest = &scene.manifest;
    let tiers = decide_tiers(&scene, db, diags, options.tier_chooser)?;
    if diags.error_count() > before {
        return None;
    }

    // Each material composed, parsed and validated once.
    let mut modules = Vec::new();
    for m in &scene.materials {
        let prelude = prelude::generate(m);
        let composed = compose::compose(m, &prelude, db);
        let (module, _) = compose::parse_and_validate(&composed, m, diags)?;
        let fallback =
            crate::compile::half::fallback_module(m, &prelude, db, diags)?.map(|(_, f)| f);
        modules.push((prelude, module, composed, fallback));
    }
    let engine = compose::engine_interface_file(db);

    let features = manifest.features;
    let values: Vec<InstanceValues> = scene
        .instances
        .iter()
        .zip(&tiers)
        .map(|(inst, (tier, _))| {
            instance_values(&scene.materials[inst.material], inst, *tier, &features)
        })
        .collect();
    // Instances with the same specialisation share one compile: `unique`
    // holds the first instance of each, `spec[k]` instance k's index into it.
    let mut first: std::collections::HashMap<String, usize> = std::collections::HashMap::new();
    let mut unique: Vec<usize> = Vec::new();
    let mut spec: Vec<usize> = Vec::with_capacity(scene.instances.len());
    for (k, (inst, (tier, _))) in scene.instances.iter().zip(&tiers).enumerate() {
        let key = specialisation_key(inst, *tier, &values[k]);
        let next = unique.len();
        let u = *first.entry(key).or_insert(next);
        if u == next {
            unique.push(k);
        }
        spec.push(u);
    }
    if unique.len() > MAX_SCENE_SHADERS {
        let over = &scene.instances[unique[MAX_SCENE_SHADERS]];
        diags.push(
            Diagnostic::error()
                .with_code("too-many-shaders")
                .with_message(format!(
                    "the scene needs {} distinct specialised shaders; at most {MAX_SCENE_SHADERS} are built",
                    unique.len()
                ))
                .with_labels(vec![
                    Label::primary(manifest.file, over.span.clone()).with_message(format!(
                        "instance `{}` needs shader number {}",
                        over.name,
                        MAX_SCENE_SHADERS + 1
                    )),
                ])
                .with_notes(vec![
                    "instances share a shader when they have the same material, tier, keywords and constant values: make the differing parameters `dynamic`, or split the scene".into(),
                ]),
        );
        return None;
    }
    let mut results: Vec<Result<CompiledVariant, String>> = unique
        .par_iter()
        .map(|&k| {
            let inst = &scene.instances[k];
            let m = &scene.materials[inst.material];
            let (prelude, module, _, fallback) = &modules[inst.material];
            build_instance(
                m,
                (module, fallback.as_ref()),
                prelude,
                inst,
                tiers[k].0,
                &values[k],
            )
        })
        .collect();

    let mut files = BTreeMap::new();
    let mut shaders: Vec<SceneShader> = Vec::new();
    let mut instances = Vec::new();
    let mut generic_variants = Vec::new();
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
        let shader = &compiled.shader;

        // The mesh must feed every input the specialised shader reads.
        let missing: Vec<&str> = shader
            .vertex_inputs
            .iter()
            .filter(|vi| !inst.vertex_inputs.iter().any(|a| a.name() == vi.name))
            .map(|vi| vi.name.as_str())
            .collect();
        if !missing.is_empty() {
            diags.push(
                Diagnostic::error()
                    .with_code("missing-vertex-input")
                    .with_message(format!(
                        "instance `{}`: its shader ({} `{variant}`) reads vertex input{} {} that the mesh does not have",
                        inst.name,
                        m.name,
                        if missing.len() > 1 { "s" } else { "" },
                        missing.iter().map(|s| format!("`{s}`")).collect::<Vec<_>>().join(", ")
                    ))
                    .with_labels(vec![
                        Label::primary(manifest.file, inst.vertex_inputs_span.clone())
                            .with_message("the mesh's vertex inputs"),
                        Label::secondary(manifest.file, inst.span.clone())
                            .with_message("this instance"),
                    ])
                    .with_notes(vec![format!(
                        "add {} to `vertex_inputs`, or choose keyword values whose variant does not read {}",
                        missing.join(", "),
                        if missing.len() > 1 { "them" } else { "it" }
                    )]),
            );
            continue;
        }

        // The shader fits WebGPU's limits (or the material's `[limits]`).
        let mark = diags.len();
        let (_, module, composed, _) = &modules[inst.material];
        let fits = crate::compile::limits::check_variants(
            m,
            &[format!("the shader of instance `{}`", inst.name)],
            composed,
            module,
            engine,
            std::slice::from_ref(&static_key),
            std::slice::from_ref(&*compiled),
            diags,
        );
        if !fits {
            for d in diags.since_mut(mark) {
                d.labels.push(
                    Label::secondary(manifest.file, inst.span.clone())
                        .with_message(format!("instance `{}`", inst.name)),
                );
            }
            continue;
        }

        // A `dynamic` parameter the shader does not read does nothing at run time.
        for (k, &pi) in inst.dynamic.iter().enumerate() {
            let name = &m.params[pi].name;
            if shader.reads.contains(name) {
                continue;
            }
            let span = inst
                .dynamic_spans
                .get(k)
                .cloned()
                .unwrap_or(inst.span.clone());
            diags.push(
                Diagnostic::warning()
                    .with_code("unread-dynamic")
                    .with_message(format!(
                        "instance `{}`: dynamic parameter `{name}` is not read by its shader ({} `{variant}`)",
                        inst.name, m.name
                    ))
                    .with_labels(vec![Label::primary(manifest.file, span)
                        .with_message("changing this at run time changes nothing")])
                    .with_notes(vec![format!(
                        "`{name}` only matters with other keyword values or tiers; remove it from `dynamic`"
                    )]),
            );
        }

        // Identical specialised instances share one shader.
        let id = compiled.id.clone();
        if !shaders.iter().any(|s| s.id == id) {
            // The first instance of a shader takes its files (instances that
            // share its specialisation find the shader by id below).
            for (name, bytes) in std::mem::take(&mut compiled.files) {
                files.insert(format!("{}/{name}", manifest.name), bytes);
            }
            shaders.push(SceneShader {
                id: id.clone(),
                material: m.name.clone(),
                variant: variant.clone(),
                shader: compiled.shader.clone(),
            });
        }
        let shader = &shaders
            .iter()
            .find(|s| s.id == id)
            .expect("just added")
            .shader;
        // The scene folder carries the baked tables its shader binds
        // (`resource.file`, a material's `[tables]`), at the path named.
        for t in &m.tables {
            let path = crate::compile::tables::resource(m, t).file.map(|f| f.path);
            let bound = shader.bindings.iter().any(|b| {
                b.resource
                    .as_ref()
                    .and_then(|r| r.file.as_ref())
                    .map(|f| &f.path)
                    == path.as_ref()
            });
            if let (true, Some(path)) = (bound, path) {
                files.insert(
                    format!("{}/{path}", manifest.name),
                    crate::compile::tables::bake(t).to_vec(),
                );
            }
        }
        let uniform_values = shader
            .material_uniform
            .as_ref()
            .map(|layout| {
                layout
                    .members
                    .iter()
                    .filter_map(|mem| {
                        Some((mem.name.clone(), values.uniform.get(&mem.name)?.clone()))
                    })
                    .collect()
            })
            .unwrap_or_default();
        let textures = shader
            .bindings
            .iter()
            .filter_map(|b| {
                let pname = b.parameter.as_ref()?;
                let pi = m.params.iter().position(|p| p.name == *pname)?;
                let p = &m.params[pi];
                let texture = match (&p.kind, &inst.values[pi]) {
                    (ParamKind::Gradient, ParamValue::Gradient(stops)) => SceneTexture {
                        parameter: pname.clone(),
                        builtin: None,
                        file: None,
                        ramp_rgba8: Some(weft_front::samples::bake_gradient(stops, p.samples)),
                        srgb: true,
                    },
                    (_, ParamValue::Texture(t)) if inst.images.contains_key(&pi) => {
                        // The scene's image: carried once per distinct image.
                        let image = &inst.images[&pi];
                        let file = crate::compile::texture_files::scene_image_file(image, p.srgb);
                        files.insert(
                            format!("{}/{}", manifest.name, file.path),
                            image.image.rgba8.clone(),
                        );
                        SceneTexture {
                            parameter: pname.clone(),
                            builtin: Some(*t),
                            file: Some(file),
                            ramp_rgba8: None,
                            srgb: p.srgb,
                        }
                    }
                    (_, ParamValue::Texture(t)) => SceneTexture {
                        parameter: pname.clone(),
                        builtin: Some(*t),
                        // Left unset, a texture with an image binds it (it
                        // is never folded, `instance::values`).
                        file: if inst.set.get(pi).copied().unwrap_or(true) {
                            None
                        } else {
                            // The scene folder carries the image at the
                            // path the metadata names (self-contained:
                            // docs/scenes.md "The scene metadata").
                            let file = crate::compile::texture_files::resource_file(m, p);
                            if let (Some(f), Some(image)) = (&file, &p.file) {
                                files.insert(
                                    format!("{}/{}", manifest.name, f.path),
                                    image.image.rgba8.clone(),
                                );
                            }
                            file
                        },
                        ramp_rgba8: None,
                        srgb: p.srgb,
                    },
                    _ => return None,
                };
                Some((b.name.clone(), texture))
            })
            .collect();
        instances.push(SceneInstance {
            name: inst.name.clone(),
            material: m.name.clone(),
            preset: inst.preset.clone(),
            tier: m.tiers.values[tier].clone(),
            keywords: keyword_names(m, inst),
            variant: variant.clone(),
            shader: id,
            constants: values.constants,
            dynamic: inst
                .dynamic
                .iter()
                .map(|&i| m.params[i].name.clone())
                .collect(),
            uniform_values,
            textures,
            passes: m
                .passes
                .iter()
                .filter(|p| static_key.matches(m, &p.when))
                .map(|p| metadata::pass(&overridden(p, inst.overrides)))
                .collect(),
            mesh: inst.mesh.name().into(),
            transform: scene_transform(&inst.transform),
            tier_choice: choice,
        });
        generic_variants.push(variant);
    }

    if let Some(budget) = &manifest.max_shaders
        && shaders.len() > budget.value
    {
        diags.push(
            Diagnostic::error()
                .with_code("shader-budget")
                .with_message(format!(
                    "the scene needs {} distinct shaders; `max_shaders` allows {}",
                    shaders.len(),
                    budget.value
                ))
                .with_labels(vec![Label::primary(manifest.file, budget.span.clone())])
                .with_notes(vec![
                    "raise `max_shaders`, or make instances share a shader: same material, tier, keywords and constant values (or make the differing parameters `dynamic`)".into(),
                ]),
        );
    }
    if diags.error_count() > before {
        return None;
    }

    // Material variants' stand-ins go apart, keyed by what they replace.
    let mut variants: BTreeMap<String, BTreeMap<String, SceneInstance>> = BTreeMap::new();
    let mut drawn = Vec::with_capacity(instances.len());
    for (inst, built) in scene.instances.iter().zip(instances) {
        match &inst.variant {
            Some(v) => {
                variants
                    .entry(v.name.clone())
                    .or_default()
                    .insert(v.replaces.clone(), built);
            }
            None => drawn.push(built),
        }
    }
    let instances = drawn;
    let meshes = scene_meshes(&scene);
    let inputs_hash = scene_inputs_hash(&scene, db);
    // The meshes' bytes moved out of the instances into the output.
    let mesh_files = file_meshes(&mut scene.instances);
    let manifest = &scene.manifest;
    let inputs_hash = {
        let mut h = Sha256::new();
        h.update(inputs_hash);
        for (name, bytes) in &mesh_files {
            h.update(name);
            h.update(bytes);
        }
        h.finalize()
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect::<String>()
    };
    for (path, bytes) in mesh_files {
        files.insert(format!("{}/{path}", manifest.name), bytes);
    }
    let funnel = funnel(manifest, &shaders, &generic_variants, &files);
    let metadata = SceneMetadata {
        schema_version: SCENE_SCHEMA_VERSION,
        schema_minor: weft_meta::scene::SCENE_SCHEMA_MINOR,
        engine_interface_version: ENGINE_INTERFACE_VERSION,
        name: manifest.name.clone(),
        description: manifest.description.clone(),
        inputs_hash,
        features: SceneFeatures {
            environment: features.environment,
            sh_ambient: features.sh_ambient,
            directional_lights: features.directional_lights,
        },
        camera: SceneCamera {
            position: manifest.camera.position,
            target: manifest.camera.target,
            fov_degrees: manifest.camera.fov_degrees,
        },
        // Always written (schema 3.3): the light weft draws with, defaults
        // included, so an engine never has to know them.
        light: Some(SceneLight::with_defaults(
            manifest.light.as_ref().map(|l| l.direction),
            manifest.light.as_ref().and_then(|l| l.color),
        )),
        shaders,
        instances,
        languages: crate::compile::engine_binding::languages(),
        conventions: Some(weft_meta::Conventions::current()),
        meshes,
        variants,
        limits: scene_limits(&scene),
        funnel: Some(funnel),
    };
    let mut json = serde_json::to_string_pretty(&metadata).expect("scene metadata serialises");
    json.push('\n');
    files.insert(
        format!("{0}/{0}.scene.json", manifest.name),
        json.into_bytes(),
    );
    Some(SceneOutput {
        name: manifest.name.clone(),
        files,
        metadata,
        generic_variants,
        warnings: None,
        materials_root: manifest.materials_root.clone(),
    })
}

/// The funnel: the glTF's materials, the instances, the distinct generic
/// variants they would draw with and the unique shaders that replace them.
fn funnel(
    manifest: &weft_front::scene::model::SceneManifest,
    shaders: &[SceneShader],
    generic_variants: &[String],
    files: &BTreeMap<String, Vec<u8>>,
) -> weft_meta::scene::SceneFunnel {
    let gltf = manifest.gltf.as_ref();
    let distinct: std::collections::BTreeSet<&String> = generic_variants.iter().collect();
    let shader_bytes = shaders
        .iter()
        .flat_map(|s| s.shader.files.values().flatten())
        .filter_map(|f| files.get(&format!("{}/{}", manifest.name, f.path)))
        .map(|b| b.len() as u64)
        .sum();
    weft_meta::scene::SceneFunnel {
        gltf_file: gltf.map(|g| g.file.clone()),
        gltf_materials: gltf.map(|g| g.materials),
        gltf_materials_used: gltf.map(|g| g.materials_used),
        instances: generic_variants.len(),
        generic_variants: distinct.len(),
        shaders: shaders.len(),
        shader_bytes,
    }
}

/// A material pass with an instance's render-state overrides (glTF's
/// `doubleSided` and `alphaMode: BLEND`, docs/scenes.md): back-face culling
/// off, an opaque pass blended without depth writes in the transparent queue.
fn overridden(
    p: &weft_front::model::Pass,
    o: weft_front::scene::model::PassOverrides,
) -> weft_front::model::Pass {
    let mut p = p.clone();
    if o.double_sided && p.cull == weft_meta::CullMode::Back {
        p.cull = weft_meta::CullMode::None;
    }
    if let Some(blend) = o.blend
        && p.blend == weft_meta::BlendMode::Opaque
    {
        p.blend = blend;
        p.depth_write = false;
        p.queue = p.queue.max(3000);
    }
    p
}
