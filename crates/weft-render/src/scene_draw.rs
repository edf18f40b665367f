//! Whole scenes drawn from `<scene>.scene.json` and the files it lists:
//! every instance with its specialised shader, values, textures, passes,
//! built-in mesh and transform, in one render pass over one depth buffer.
//!
//! Data flows one way: metadata -> per-instance resources ([`PreparedScene`],
//! built once; no pipeline is created while drawing) -> draws in
//! [`scene_draw_order`]. The same scene can instead be drawn with the
//! generic library variants ([`SceneShaders::Library`], `scene_library.rs`):
//! only where an instance's shader, uniform bytes and textures come from
//! differs; pipelines, bind groups, meshes, transforms, lighting and the
//! draw itself are shared.

use crate::bindings::{BoundShader, ObjectResources};
use crate::draw::DrawCall;
use crate::engine_uniforms::FrameView;
use crate::error::{Error, Result, io_err};
use crate::image::HdrImage;
use crate::material::{constant_default, constant_value, instance_count_of};
use crate::math::{self, Mat4};
use crate::pipelines::{ShaderInput, spirv_file_for};
use crate::renderer::{
    Background, ColorFormat, RenderOptions, Renderer, ShaderLanguage, check_format,
};
use crate::resources::{GpuEnvironment, GpuMesh, TextureSource, material_texture_views};
use crate::scene::{Camera, Light, Scene, SceneKind};
use crate::scene_library::Library;
use crate::uniform::pack_uniform_values;
use crate::values::TextureValue;
use std::borrow::Cow;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use weft_meta::scene::{SCENE_SCHEMA_VERSION, SceneFeatures, SceneInstance, SceneMetadata};
use weft_meta::{Binding, InstanceCount, Pass};

/// A scene's metadata and the folder its shader files are relative to.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneFile {
    /// The `.scene.json` (named in errors).
    pub path: PathBuf,
    pub dir: PathBuf,
    pub metadata: SceneMetadata,
    /// What group 0 provides; from `metadata.features` unless changed.
    pub lighting: SceneLighting,
}

impl SceneFile {
    /// Reads `<out>/<scene>/<scene>.scene.json`.
    pub fn load(path: impl AsRef<Path>) -> Result<SceneFile> {
        let path = path.as_ref();
        let bytes = weft_meta::files::read_regular(path, weft_meta::files::MAX_TEXT_BYTES)
            .map_err(io_err(path))?;
        let metadata: SceneMetadata = serde_json::from_slice(&bytes).map_err(|e| {
            Error::Metadata(format!(
                "`{}` is not weft scene metadata: {e}",
                path.display()
            ))
        })?;
        SceneFile::from_metadata(metadata, path)
    }

    /// Scene metadata already parsed; `path` is where it lives (its folder
    /// holds the shader files).
    pub fn from_metadata(metadata: SceneMetadata, path: impl AsRef<Path>) -> Result<SceneFile> {
        let path = path.as_ref().to_path_buf();
        let versions = [
            (
                "scene schema",
                metadata.schema_version,
                SCENE_SCHEMA_VERSION,
            ),
            (
                "engine interface",
                metadata.engine_interface_version,
                weft_meta::ENGINE_INTERFACE_VERSION,
            ),
        ];
        for (what, got, ours) in versions {
            if got != ours {
                return Err(scene_error(
                    &path,
                    None,
                    Error::Metadata(format!(
                        "scene `{}` has {what} version {got}, this runtime reads {ours}",
                        metadata.name
                    )),
                ));
            }
        }
        Ok(SceneFile {
            dir: path.parent().unwrap_or(Path::new(".")).to_path_buf(),
            lighting: SceneLighting::from_metadata(&metadata),
            path,
            metadata,
        })
    }
}

/// What group 0 gives a scene's shaders. A feature that is off is bound
/// but black/zero: the specialised shaders do not read it, and a generic
/// shader drawn for comparison must see the same lighting.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneLighting {
    /// The prefiltered environment cube (else a black cube).
    pub environment: bool,
    /// The SH irradiance (else zero).
    pub sh_ambient: bool,
    /// The main light (radiance zero when the scene has no directional light).
    pub light: Light,
    /// SH coefficients the scene's shaders hold as constants (the metadata's
    /// `static_lighting.sh`): uploaded in place of the sky's own, so that a
    /// generic shader drawn for comparison sees what the folded ones do.
    pub static_sh: Option<[[f32; 3]; 9]>,
}

impl SceneLighting {
    /// The features' lighting with weft's default light (`weft_meta::scene`'s
    /// `DEFAULT_LIGHT_*`), radiance zero without a directional light.
    pub fn from_features(features: &SceneFeatures) -> SceneLighting {
        let mut light = Light::default();
        if features.directional_lights == 0 {
            light.radiance = [0.0; 3];
        }
        SceneLighting {
            environment: features.environment,
            sh_ambient: features.sh_ambient,
            light,
            static_sh: None,
        }
    }

    /// The features' lighting with the light the metadata states
    /// (`light`: always written since scene schema 3.3; the defaults fill
    /// in what an older file left out).
    pub fn from_metadata(meta: &SceneMetadata) -> SceneLighting {
        let mut lighting = SceneLighting::from_features(&meta.features);
        lighting.static_sh = meta
            .static_lighting
            .as_ref()
            .and_then(|s| s.sh)
            .map(|sh| sh.map(|rgb| rgb.map(|c| c as f32)));
        let l = meta.light_used();
        lighting.light.direction = l.direction.map(|c| c as f32);
        if let (Some(c), true) = (l.color, meta.features.directional_lights > 0) {
            lighting.light.radiance = c.map(|c| c as f32);
        }
        lighting
    }
}

/// Which shaders draw a scene.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneShaders {
    /// The scene's specialised shaders: what an engine ships.
    Specialised,
    /// The generic library variants of this `generated/` folder
    /// (`<material>/<material>.meta.json`), each instance's values set as
    /// parameters: for comparisons and benchmarks.
    Library(PathBuf),
}

/// One (instance, pass) draw of a scene: indices into
/// `SceneMetadata::instances` and that instance's `passes`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct DrawRef {
    pub instance: usize,
    pub pass: usize,
}

/// The order a scene's passes are drawn in: by queue, then instance order,
/// then the material's pass order (a stable sort).
pub fn scene_draw_order(instances: &[SceneInstance]) -> Vec<DrawRef> {
    let mut order: Vec<(i64, DrawRef)> = instances
        .iter()
        .enumerate()
        .flat_map(|(i, inst)| {
            inst.passes.iter().enumerate().map(move |(p, pass)| {
                (
                    pass.render_state.queue,
                    DrawRef {
                        instance: i,
                        pass: p,
                    },
                )
            })
        })
        .collect();
    order.sort_by_key(|(queue, _)| *queue);
    order.into_iter().map(|(_, d)| d).collect()
}

/// Where an instance's mesh comes from: a built-in generator, or a file in
/// the scene folder (`meshes[name].file`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum MeshSource {
    Builtin(SceneKind),
    File(String),
}

fn mesh_source(meta: &SceneMetadata, name: &str) -> Result<MeshSource> {
    if let Some(file) = meta.meshes.get(name).and_then(|m| m.file.clone()) {
        return Ok(MeshSource::File(file));
    }
    SceneKind::from_name(name)
        .map(MeshSource::Builtin)
        .ok_or_else(|| Error::UnknownName {
            what: "mesh",
            name: name.to_string(),
            valid: SceneKind::ALL.map(|k| k.name().to_string()).to_vec(),
        })
}

/// The radius around its origin that an instance's mesh fits in: the
/// metadata's `radius` for a mesh the scene carries, √2 for a built-in one.
fn mesh_radius(meta: &SceneMetadata, name: &str) -> f32 {
    meta.meshes
        .get(name)
        .and_then(|m| m.radius)
        .map_or(std::f32::consts::SQRT_2, |r| r as f32)
}

/// An instance's `weft_object.model` (its `transform.model`, column-major).
pub fn instance_model(instance: &SceneInstance) -> Mat4 {
    let m = &instance.transform.model;
    std::array::from_fn(|c| std::array::from_fn(|r| m[4 * c + r]))
}

/// The scene's camera: its position, target and vertical field of view,
/// +Y up, near 0.1 and a far plane past every instance.
pub fn scene_camera(meta: &SceneMetadata) -> Camera {
    let c = &meta.camera;
    let eye = c.position.map(|x| x as f32);
    // Each instance's mesh fits in a sphere of its radius (√2 for the
    // built-in meshes) around its origin, scaled by the model's columns.
    let reach = meta
        .instances
        .iter()
        .map(|i| {
            let m = &i.transform.model;
            let t = [m[12], m[13], m[14]];
            let s = (0..3)
                .map(|c| math::length([m[4 * c], m[4 * c + 1], m[4 * c + 2]]))
                .fold(0.0f32, f32::max);
            math::length(math::sub(t, eye)) + 1.07 * mesh_radius(meta, &i.mesh) * s
        })
        .fold(0.0f32, f32::max);
    Camera {
        eye,
        target: c.target.map(|x| x as f32),
        up: [0.0, 1.0, 0.0],
        fov_y_degrees: c.fov_degrees as f32,
        near: 0.1,
        far: (2.0 * reach).max(100.0),
    }
}

/// One instance ready to draw.
struct PreparedInstance {
    name: String,
    bound: BoundShader,
    mesh: Arc<GpuMesh>,
    /// Instances per pass of `SceneInstance::passes`.
    instances: Vec<u32>,
    pass_names: Vec<String>,
}

/// A scene ready to draw: per instance pipelines, bind groups, uniform,
/// object buffer and mesh, and the draw order.
pub struct PreparedScene {
    name: String,
    format: ColorFormat,
    camera: Camera,
    light: Light,
    env: GpuEnvironment,
    instances: Vec<PreparedInstance>,
    order: Vec<DrawRef>,
}

impl PreparedScene {
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The draws in order: (instance, pass, instance count).
    pub fn draws(&self) -> Vec<(&str, &str, u32)> {
        self.order
            .iter()
            .map(|d| {
                let i = &self.instances[d.instance];
                (
                    i.name.as_str(),
                    i.pass_names[d.pass].as_str(),
                    i.instances[d.pass],
                )
            })
            .collect()
    }

    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    /// The material uniform buffer of instance `index` (`COPY_SRC`), if it has one.
    pub fn uniform_buffer(&self, index: usize) -> Option<&wgpu::Buffer> {
        self.instances.get(index)?.bound.uniform.as_ref()
    }
}

fn scene_error(path: &Path, instance: Option<&str>, e: Error) -> Error {
    Error::Scene {
        file: path.to_path_buf(),
        instance: instance.map(str::to_string),
        source: Box::new(e),
    }
}

impl Renderer {
    /// Builds everything `scene` draws with: pipelines (cached across
    /// instances sharing a shader), bind groups, uniforms, object buffers,
    /// meshes, and the sky pipeline. Errors name the scene file and the instance.
    pub fn prepare_scene(
        &mut self,
        scene: &SceneFile,
        shaders: &SceneShaders,
        options: &RenderOptions,
    ) -> Result<PreparedScene> {
        let meta = &scene.metadata;
        let fail = |instance: Option<&str>, e| scene_error(&scene.path, instance, e);
        self.ensure_sky_pipeline(options.format)
            .map_err(|e| fail(None, e))?;
        let lighting = &scene.lighting;
        let cube = if lighting.environment {
            &self.env
        } else {
            &self.black_env
        };
        let env = GpuEnvironment {
            view: cube.view.clone(),
            mip_count: cube.mip_count,
            sh: if lighting.sh_ambient {
                lighting.static_sh.unwrap_or(self.env.sh)
            } else {
                [[0.0; 3]; 9]
            },
        };
        let mut library = match shaders {
            SceneShaders::Specialised => None,
            SceneShaders::Library(generated) => Some(Library::new(generated)),
        };
        let mut meshes: HashMap<(MeshSource, String), Arc<GpuMesh>> = HashMap::new();
        let mut instances = Vec::with_capacity(meta.instances.len());
        for inst in &meta.instances {
            let prepared = self
                .prepare_instance(scene, inst, library.as_mut(), &env, &mut meshes, options)
                .map_err(|e| fail(Some(&inst.name), e))?;
            instances.push(prepared);
        }
        Ok(PreparedScene {
            name: meta.name.clone(),
            format: options.format,
            camera: scene_camera(meta),
            light: lighting.light,
            env,
            instances,
            order: scene_draw_order(&meta.instances),
        })
    }

    fn prepare_instance(
        &mut self,
        scene: &SceneFile,
        inst: &SceneInstance,
        library: Option<&mut Library>,
        env: &GpuEnvironment,
        meshes: &mut HashMap<(MeshSource, String), Arc<GpuMesh>>,
        options: &RenderOptions,
    ) -> Result<PreparedInstance> {
        let mesh_source = mesh_source(&scene.metadata, &inst.mesh)?;
        let model = instance_model(inst);
        let (bound, instances) = match library {
            None => {
                let bound = self.bind_scene_shader(scene, inst, env, model, options)?;
                let counts = inst
                    .passes
                    .iter()
                    .map(|p| scene_instance_count(inst, p))
                    .collect::<Result<Vec<_>>>()?;
                (bound, counts)
            }
            Some(lib) => {
                let material = lib.instance_material(inst, &scene.dir)?;
                let (bound, _) =
                    self.bind_material(&material, &inst.passes, options, model, env.clone())?;
                let counts = inst
                    .passes
                    .iter()
                    .map(|p| material.instance_count(p))
                    .collect::<Result<Vec<_>>>()?;
                (bound, counts)
            }
        };
        let inputs = &bound.pipelines.vertex_inputs;
        let key = (
            mesh_source.clone(),
            format!(
                "{:?}",
                inputs
                    .iter()
                    .map(|v| (&v.name, &v.format))
                    .collect::<Vec<_>>()
            ),
        );
        let mesh = match meshes.get(&key) {
            Some(m) => m.clone(),
            None => {
                let mesh = match &mesh_source {
                    MeshSource::Builtin(kind) => Scene::new(*kind).mesh,
                    MeshSource::File(file) => crate::mesh_files::read_scene_mesh(&scene.dir, file)?,
                };
                let m = Arc::new(GpuMesh::upload(&self.gpu, &mesh, inputs)?);
                meshes.insert(key, m.clone());
                m
            }
        };
        Ok(PreparedInstance {
            name: inst.name.clone(),
            bound,
            mesh,
            instances,
            pass_names: inst.passes.iter().map(|p| p.name.clone()).collect(),
        })
    }

    /// The instance's specialised shader bound with its uniform values and textures.
    fn bind_scene_shader(
        &mut self,
        scene: &SceneFile,
        inst: &SceneInstance,
        env: &GpuEnvironment,
        model: Mat4,
        options: &RenderOptions,
    ) -> Result<BoundShader> {
        let meta = &scene.metadata;
        let entry = meta
            .shaders
            .iter()
            .find(|s| s.id == inst.shader)
            .ok_or_else(|| {
                Error::Metadata(format!(
                    "names shader `{}`, which the scene does not list (shaders: {})",
                    inst.shader,
                    meta.shaders
                        .iter()
                        .map(|s| s.id.as_str())
                        .collect::<Vec<_>>()
                        .join(", ")
                ))
            })?;
        let shader = &entry.shader;
        let input = ShaderInput {
            label: &entry.id,
            dir: &scene.dir,
            shader,
            f32_fallback: options.f32_fallback,
            uniforms_as_storage: options.uniforms_as_storage,
            spirv_file: match options.language {
                ShaderLanguage::Wgsl => None,
                ShaderLanguage::SpirV => Some(spirv_file_for(shader, &entry.id, &inst.keywords)?),
            },
            // A scene shader folds its keywords; an `override` left in it
            // takes the instance's value of its keyword (the index in the
            // constant's `values`), else its `default_value`.
            constants: match options.language {
                ShaderLanguage::Wgsl => shader
                    .pipeline_constants
                    .iter()
                    .map(|c| {
                        let v = match inst.keywords.get(&c.name) {
                            Some(value) => constant_value(c, value)?,
                            None => constant_default(c)?,
                        };
                        Ok((c.name.clone(), v))
                    })
                    .collect::<Result<Vec<_>>>()?,
                ShaderLanguage::SpirV => Vec::new(),
            },
            cache_id: format!(
                "scene|{}|{}|{}",
                scene.dir.display(),
                meta.inputs_hash,
                entry.id
            ),
        };
        let uniform_bytes = shader
            .material_uniform
            .as_ref()
            .map(|layout| pack_uniform_values(layout, &inst.uniform_values))
            .transpose()?;
        let textures = self.gpu.checked("scene textures", || {
            material_texture_views(&self.gpu, shader, |b| scene_texture(inst, b, &scene.dir))
        })??;
        let resources = ObjectResources {
            uniform_bytes,
            textures,
            model,
            env: env.clone(),
        };
        self.bind_shader(&input, &inst.passes, options.format, resources)
    }

    /// Draws a prepared scene over the background and reads the linear image back.
    pub fn render_scene(
        &mut self,
        prepared: &PreparedScene,
        options: &RenderOptions,
    ) -> Result<HdrImage> {
        Ok(self.draw_scene(prepared, options, 1, false, None)?.0)
    }

    /// [`Renderer::draw_frames`] of a prepared scene (also timing.rs).
    pub(crate) fn draw_scene(
        &self,
        prepared: &PreparedScene,
        options: &RenderOptions,
        frames: u32,
        timed: bool,
        timestamps: Option<&wgpu::QuerySet>,
    ) -> Result<(HdrImage, Vec<f64>)> {
        check_format("scene", prepared.format, options)?;
        let draws: Vec<DrawCall> = prepared
            .order
            .iter()
            .map(|d| {
                let i = &prepared.instances[d.instance];
                DrawCall {
                    pipeline: &i.bound.pipelines.passes[d.pass].pipeline,
                    bind_groups: &i.bound.bind_groups,
                    mesh: &i.mesh,
                    instances: i.instances[d.pass],
                    stencil_reference: i.bound.pipelines.passes[d.pass]
                        .pass
                        .depth_stencil
                        .stencil_reference,
                }
            })
            .collect();
        let view = FrameView {
            camera: &prepared.camera,
            light: &prepared.light,
            env: &prepared.env,
        };
        if matches!(options.background, Background::Sky { .. })
            && !self.sky_pipelines.contains_key(&options.format)
        {
            return Err(Error::Gpu("the sky pipeline was not prepared".into()));
        }
        self.draw_frames(&view, &draws, options, frames, timed, timestamps)
    }
}

/// A pass's instance count: fixed, or the value of the int parameter named,
/// folded (`constants`) or still uploaded (`uniform_values`).
pub fn scene_instance_count(inst: &SceneInstance, pass: &Pass) -> Result<u32> {
    match &pass.instances {
        InstanceCount::Fixed(n) => Ok(*n),
        InstanceCount::Parameter(p) => {
            let v = inst.constants.get(p).or_else(|| inst.uniform_values.get(p));
            match v.and_then(serde_json::Value::as_f64) {
                Some(x) if x.is_finite() => Ok(instance_count_of(x)),
                _ => Err(Error::Metadata(format!(
                    "pass `{}` takes its instance count from `{p}`, which has no numeric value \
                     in the instance's constants or uniform_values",
                    pass.name
                ))),
            }
        }
    }
}

/// What a group-1 texture binding of a scene shader samples: the
/// instance's `textures` entry for the binding (a texture left at its
/// default is listed with the built-in texture the build resolved for the
/// instance's keywords; one left at its image with the image's `file`). The
/// binding's `texture.format` says whether its
/// texels are sRGB (`material_texture_views`).
fn scene_texture<'a>(
    inst: &'a SceneInstance,
    b: &Binding,
    scene_dir: &Path,
) -> Result<TextureSource<'a>> {
    let t = inst.textures.get(&b.name).ok_or_else(|| {
        Error::Metadata(format!(
            "the shader binds texture `{}` (group 1, binding {}) but the instance's `textures` \
             has no entry for it (entries: {})",
            b.name,
            b.binding,
            inst.textures.keys().cloned().collect::<Vec<_>>().join(", ")
        ))
    })?;
    let cube = b
        .texture
        .as_ref()
        .is_some_and(|t| t.view_dimension == weft_meta::TextureViewDimension::Cube);
    // A texture left at the image it ships (`file`) binds the file.
    if let Some(f) = &t.file {
        let roots = crate::texture_files::scene_roots(scene_dir);
        return Ok(TextureSource::Texture2d(Cow::Owned(
            crate::texture_files::read(&roots, f)?,
        )));
    }
    match (&t.builtin, &t.ramp_rgba8) {
        (Some(d), None) if cube => Ok(TextureSource::Cube(Cow::Owned(TextureValue::Builtin(*d)))),
        (Some(d), None) => Ok(TextureSource::Texture2d(Cow::Owned(TextureValue::Builtin(
            *d,
        )))),
        (None, Some(ramp)) => Ok(TextureSource::Ramp(ramp)),
        (Some(_), Some(_)) | (None, None) => Err(Error::Metadata(format!(
            "texture `{}` (parameter `{}`) must give exactly one of `builtin` and `ramp_rgba8`",
            b.name, t.parameter
        ))),
    }
}
