//! What a scene build records: each built instance's entry (its shader,
//! textures, tables, uniform values, passes) with the files it carries, and
//! at the end the scene metadata — material variants apart, meshes, the
//! inputs hash, the funnel — as `<scene>.scene.json` among the files.

use super::instance::{InstanceValues, scene_transform};
use crate::compile::metadata;
use crate::compile::variant::CompiledVariant;
use sha2::{Digest, Sha256};
use std::collections::BTreeMap;
use weft_front::SourceDb;
use weft_front::model::{Material, ParamValue};
use weft_front::scene::model::{InstanceMesh, ResolvedInstance, ResolvedScene};
use weft_front::variants::VariantKey;
use weft_meta::scene::{
    SCENE_SCHEMA_VERSION, SceneCamera, SceneFeatures, SceneInstance, SceneMetadata, SceneShader,
    SceneTexture, TierChoice,
};
use weft_meta::{ENGINE_INTERFACE_VERSION, ParamKind, VariantShader};

/// The scene as built so far: files (relative to the output root), unique
/// shaders, one entry per instance and the generic variant each would draw.
#[derive(Default)]
pub(super) struct Recorded {
    pub files: BTreeMap<String, Vec<u8>>,
    pub shaders: Vec<SceneShader>,
    pub instances: Vec<SceneInstance>,
    pub generic_variants: Vec<String>,
}

/// One instance that passed its checks, with what it was built from.
pub(super) struct BuiltInstance<'a> {
    pub material: &'a Material,
    pub instance: &'a ResolvedInstance,
    pub tier: usize,
    pub choice: Option<TierChoice>,
    pub values: InstanceValues,
    pub static_key: VariantKey,
    pub variant: String,
}

impl Recorded {
    /// Records one instance. Identical specialised instances share one
    /// shader: the first takes the compiled files, the others find it by id.
    pub(super) fn add(
        &mut self,
        scene_name: &str,
        built: BuiltInstance,
        compiled: &mut CompiledVariant,
    ) {
        let BuiltInstance {
            material: m,
            instance: inst,
            tier,
            choice,
            values,
            static_key,
            variant,
        } = built;
        let id = compiled.id.clone();
        if !self.shaders.iter().any(|s| s.id == id) {
            for (name, bytes) in std::mem::take(&mut compiled.files) {
                self.files.insert(format!("{scene_name}/{name}"), bytes);
            }
            self.shaders.push(SceneShader {
                id: id.clone(),
                material: m.name.clone(),
                variant: variant.clone(),
                shader: compiled.shader.clone(),
            });
        }
        let shader = self
            .shaders
            .iter()
            .find(|s| s.id == id)
            .expect("just added")
            .shader
            .clone();
        carry_tables(&mut self.files, scene_name, m, &shader);
        let uniform_values = uniform_values(&shader, &values);
        let textures = textures(&mut self.files, scene_name, m, inst, &shader);
        self.instances.push(SceneInstance {
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
        self.generic_variants.push(variant);
    }
}

/// The scene folder carries the baked tables its shader binds
/// (`resource.file`, a material's `[tables]`), at the path named.
fn carry_tables(
    files: &mut BTreeMap<String, Vec<u8>>,
    scene_name: &str,
    m: &Material,
    shader: &VariantShader,
) {
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
                format!("{scene_name}/{path}"),
                crate::compile::tables::bake(t).to_vec(),
            );
        }
    }
}

/// The instance's values of the uniform members its shader still has.
fn uniform_values(
    shader: &VariantShader,
    values: &InstanceValues,
) -> BTreeMap<String, serde_json::Value> {
    shader
        .material_uniform
        .as_ref()
        .map(|layout| {
            layout
                .members
                .iter()
                .filter_map(|mem| Some((mem.name.clone(), values.uniform.get(&mem.name)?.clone())))
                .collect()
        })
        .unwrap_or_default()
}

/// Each texture binding of the shader: a gradient's baked ramp, a scene
/// image (carried once per distinct image), or the material's texture with
/// its image carried when the instance leaves it unset.
fn textures(
    files: &mut BTreeMap<String, Vec<u8>>,
    scene_name: &str,
    m: &Material,
    inst: &ResolvedInstance,
    shader: &VariantShader,
) -> BTreeMap<String, SceneTexture> {
    shader
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
                    let image = &inst.images[&pi];
                    let file = crate::compile::texture_files::scene_image_file(image, p.srgb);
                    files.insert(
                        format!("{scene_name}/{}", file.path),
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
                    // Left unset, a texture with an image binds it (it is
                    // never folded, `instance::values`).
                    file: if inst.set.get(pi).copied().unwrap_or(true) {
                        None
                    } else {
                        // The scene folder carries the image at the path
                        // the metadata names (self-contained: docs/scenes.md
                        // "The scene metadata").
                        let file = crate::compile::texture_files::resource_file(m, p);
                        if let (Some(f), Some(image)) = (&file, &p.file) {
                            files.insert(
                                format!("{scene_name}/{}", f.path),
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
        .collect()
}

/// The scene metadata and output from everything recorded. Material
/// variants' stand-ins go apart, keyed by what they replace; the glTF
/// meshes' bytes move out of the instances into the files.
pub(super) fn assemble(
    mut scene: ResolvedScene,
    db: &SourceDb,
    recorded: Recorded,
) -> super::SceneOutput {
    let Recorded {
        mut files,
        shaders,
        instances,
        generic_variants,
    } = recorded;
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
    let features = manifest.features;
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
        light: Some(manifest.light_used()),
        static_lighting: manifest.static_lighting.clone(),
        shaders,
        instances,
        languages: crate::compile::engine_binding::languages(),
        conventions: Some(weft_meta::Conventions::current()),
        meshes,
        variants,
        limits: scene_limits(&scene),
        funnel: Some(funnel),
    };
    files.insert(
        format!("{0}/{0}.scene.json", manifest.name),
        metadata_json(&metadata),
    );
    super::SceneOutput {
        name: manifest.name.clone(),
        files,
        metadata,
        generic_variants,
        warnings: None,
        materials_root: manifest.materials_root.clone(),
    }
}

/// `<scene>.scene.json`'s bytes: pretty JSON and a final newline (also what
/// `weft build --scene --gpu-model` writes again once the funnel's cost is in).
pub fn metadata_json(metadata: &SceneMetadata) -> Vec<u8> {
    let mut json = serde_json::to_string_pretty(metadata).expect("scene metadata serialises");
    json.push('\n');
    json.into_bytes()
}

pub(super) fn keyword_names(m: &Material, inst: &ResolvedInstance) -> BTreeMap<String, String> {
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
    h.update(crate::compile::engine_binding::ENGINE_INTERFACE);
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
        modelled: Vec::new(),
    }
}

/// A material pass with an instance's render-state overrides (glTF's
/// `doubleSided` and `alphaMode: BLEND`, docs/scenes.md): back-face culling
/// off, an opaque pass blended without depth writes in the transparent queue.
fn overridden(
    p: &weft_front::model::Pass,
    o: weft_front::scene::model::InstanceOverrides,
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
