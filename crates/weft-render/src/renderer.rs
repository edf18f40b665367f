//! The [`Renderer`] and the material path: a [`Material`]'s current variant
//! prepared (pipelines, bind groups, uniform) and drawn on a built-in scene.
//!
//! Group 0 (frame) and group 2 (object) are the engine interface
//! (crates/weft-compiler/src/compile/wgsl/engine_interface.wgsl); group 1 is the
//! material, bound by parameter name from the metadata's `bindings`. The
//! jobs live in their own modules: `pipelines.rs` (layouts and pipelines from
//! metadata, `meta_wgpu.rs` the state conversions), `resources.rs`
//! (textures, buffers), `bindings.rs` (bind groups, samplers, LUTs),
//! `engine_uniforms.rs` (`weft_frame`, `weft_object`), `draw.rs` (render
//! pass, readback), `tiles.rs` (probe tiles) and `scene_draw.rs` (whole scenes).

mod bind_groups;
mod frames;
mod pipeline_cache;

use crate::bindings::{BoundShader, ObjectResources};
use crate::draw::{DrawCall, sky_uniform_buffer};
use crate::engine_uniforms::FrameView;
use crate::engine_uniforms::{UniformBlock, object_bytes};
use crate::environment::EnvironmentMaps;
use crate::error::{Error, Result};
use crate::gpu::Gpu;
use crate::image::HdrImage;
use crate::luts::Luts;
use crate::material::Material;
use crate::math::{self, Mat4};
use crate::pipelines::{ShaderInput, VariantPipelines, kind_layout_entry, spirv_file_for};
use crate::resources::{
    GpuEnvironment, GpuMesh, TextureSource, black_environment, material_texture_views,
    upload_environment,
};
use crate::scene::Scene;
use crate::values::{StoredValue, TextureValue};
use std::borrow::Cow;
use std::collections::HashMap;
use std::sync::Arc;
use weft_meta::{Binding, BindingKind, ParamKind, Pass};

// Probe tiles are drawn by `tiles.rs`; `Tile` stays reachable here too.
pub use crate::probe::Tile;
pub use crate::targets::{Background, ColorFormat, RenderOptions, ShaderLanguage};

/// A material's variant ready to draw: pipelines, bind groups, uniform buffer.
pub struct PreparedMaterial {
    variant_id: String,
    pub(crate) format: ColorFormat,
    pub(crate) bound: BoundShader,
    uniform_layout: Option<weft_meta::UniformLayout>,
    pub(crate) instances: Vec<u32>,
}

impl PreparedMaterial {
    /// The canonical variant drawn.
    pub fn variant_id(&self) -> &str {
        &self.variant_id
    }

    /// The group-1 uniform buffer (`COPY_SRC`, so tests can read it back).
    pub fn uniform_buffer(&self) -> Option<&wgpu::Buffer> {
        self.bound.uniform.as_ref()
    }

    /// Instances each pass draws, in draw (queue) order.
    pub fn instances(&self) -> &[u32] {
        &self.instances
    }

    /// Names of the passes in draw (queue) order.
    pub fn pass_names(&self) -> Vec<&str> {
        self.bound
            .pipelines
            .passes
            .iter()
            .map(|p| p.pass.name.as_str())
            .collect()
    }

    pub(crate) fn check_format(&self, options: &RenderOptions) -> Result<()> {
        check_format("material", self.format, options)
    }
}

/// Pipelines are built for one colour format: a render must ask for it.
pub(crate) fn check_format(
    what: &str,
    prepared: ColorFormat,
    options: &RenderOptions,
) -> Result<()> {
    if prepared != options.format {
        return Err(Error::Gpu(format!(
            "{what} prepared for {prepared:?}, render asks for {:?}",
            options.format
        )));
    }
    Ok(())
}

/// Draws materials and scenes into offscreen targets on one [`Gpu`].
pub struct Renderer {
    pub(crate) gpu: Gpu,
    pub(crate) env: GpuEnvironment,
    /// Group 0's environment where a scene provides none (black, SH zero).
    pub(crate) black_env: GpuEnvironment,
    /// The tables LUT bindings are filled from (by their `resource.file`).
    pub(crate) luts: Luts,
    /// LUT textures by `resource.file.path`.
    pub(crate) lut_views: HashMap<String, wgpu::TextureView>,
    /// Samplers by description (`meta_wgpu::sampler_key`).
    pub(crate) samplers: HashMap<String, wgpu::Sampler>,
    /// `weft_frame` buffers, one per distinct layout; all written each frame.
    pub(crate) frame_blocks: Vec<UniformBlock>,
    /// The sky's own sampler (trilinear, clamp): the sky is weft-render's
    /// pipeline, not a weft variant.
    pub(crate) sky_sampler: wgpu::Sampler,
    pub(crate) sky_buffer: wgpu::Buffer,
    pub(crate) sky_layout: wgpu::BindGroupLayout,
    pub(crate) sky_module: wgpu::ShaderModule,
    pub(crate) sky_pipelines: HashMap<ColorFormat, wgpu::RenderPipeline>,
    pub(crate) cache: HashMap<String, Arc<VariantPipelines>>,
    pub(crate) pipelines_created: u64,
}

impl Renderer {
    pub fn new(gpu: Gpu, env: &EnvironmentMaps, luts: &Luts) -> Result<Renderer> {
        let device = &gpu.device;
        let sky_sampler = device.create_sampler(&wgpu::SamplerDescriptor {
            label: Some("weft sky"),
            mag_filter: wgpu::FilterMode::Linear,
            min_filter: wgpu::FilterMode::Linear,
            mipmap_filter: wgpu::MipmapFilterMode::Linear,
            ..Default::default()
        });
        const FRAGMENT: wgpu::ShaderStages = wgpu::ShaderStages::FRAGMENT;
        let sky_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("weft sky"),
            entries: &[
                kind_layout_entry(0, FRAGMENT, BindingKind::UniformBuffer)?,
                kind_layout_entry(1, FRAGMENT, BindingKind::TextureCube)?,
                kind_layout_entry(2, FRAGMENT, BindingKind::Sampler)?,
            ],
        });
        let sky_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("weft sky"),
            source: wgpu::ShaderSource::Wgsl(include_str!("sky.wgsl").into()),
        });
        let renderer = Renderer {
            env: upload_environment(&gpu, env),
            black_env: black_environment(&gpu),
            luts: luts.clone(),
            lut_views: HashMap::new(),
            samplers: HashMap::new(),
            frame_blocks: Vec::new(),
            sky_sampler,
            sky_buffer: sky_uniform_buffer(&gpu),
            sky_layout,
            sky_module,
            sky_pipelines: HashMap::new(),
            cache: HashMap::new(),
            pipelines_created: 0,
            gpu,
        };
        renderer.gpu.take_uncaptured("renderer setup")?;
        Ok(renderer)
    }

    pub fn gpu(&self) -> &Gpu {
        &self.gpu
    }

    /// Render pipelines this renderer has created so far (material and
    /// scene passes, and the sky). Cached pipelines are reused, so drawing
    /// something already prepared leaves it unchanged.
    pub fn pipelines_created(&self) -> u64 {
        self.pipelines_created
    }

    /// Drops the cached material pipelines (prepared materials keep theirs
    /// alive until they are dropped). A long run over many materials — the
    /// stability sweep — calls it between materials: on lavapipe every
    /// pipeline holds its JIT-compiled code, and keeping all of a library's
    /// pipelines grew one process past 20 GiB.
    pub fn release_pipelines(&mut self) {
        self.cache.clear();
    }

    /// Replaces the environment (prepared materials keep the old one).
    pub fn set_environment(&mut self, env: &EnvironmentMaps) -> Result<()> {
        self.env = upload_environment(&self.gpu, env);
        self.gpu.take_uncaptured("environment upload")
    }

    /// Builds (or reuses) the pipelines of the material's current variant and
    /// its bind groups, and uploads the parameter values.
    pub fn prepare(
        &mut self,
        material: &Material,
        options: &RenderOptions,
    ) -> Result<PreparedMaterial> {
        let (bound, variant_id) = self.bind_material(
            material,
            &material_passes(material)?,
            options,
            math::IDENTITY,
            self.env.clone(),
        )?;
        let uniform_layout = material.current_variant()?.shader.material_uniform.clone();
        let instances = bound
            .pipelines
            .passes
            .iter()
            .map(|p| material.instance_count(&p.pass))
            .collect::<Result<Vec<_>>>()?;
        Ok(PreparedMaterial {
            variant_id,
            format: options.format,
            bound,
            uniform_layout,
            instances,
        })
    }

    /// The material's current variant bound for `passes`: what
    /// [`Renderer::prepare`] and the library draw of a scene instance share.
    /// Returns the canonical variant id too.
    pub(crate) fn bind_material(
        &mut self,
        material: &Material,
        passes: &[Pass],
        options: &RenderOptions,
        model: Mat4,
        env: GpuEnvironment,
    ) -> Result<(BoundShader, String)> {
        let resolved = material.current_variant()?;
        let shader = resolved.shader;
        let variant_id = resolved.canonical.id.clone();
        let input = ShaderInput {
            label: &variant_id,
            dir: material.dir(),
            shader,
            f32_fallback: options.f32_fallback,
            uniforms_as_storage: options.uniforms_as_storage,
            spirv_file: match options.language {
                ShaderLanguage::Wgsl => None,
                ShaderLanguage::SpirV => {
                    Some(spirv_file_for(shader, &variant_id, material.keywords())?)
                }
            },
            constants: match options.language {
                ShaderLanguage::Wgsl => material.pipeline_constants(shader)?,
                ShaderLanguage::SpirV => Vec::new(),
            },
            cache_id: format!(
                "material|{}|{}|{}",
                material.name(),
                material.metadata().inputs_hash,
                variant_id
            ),
        };
        let textures = self.gpu.checked("material textures", || {
            material_texture_views(&self.gpu, shader, |b| material_texture(material, b))
        })??;
        let uniform_bytes = shader
            .material_uniform
            .as_ref()
            .map(|layout| material.uniform_bytes(layout))
            .transpose()?;
        let resources = ObjectResources {
            uniform_bytes,
            textures,
            model,
            env,
        };
        let bound = self.bind_shader(&input, passes, options.format, resources)?;
        Ok((bound, variant_id))
    }

    /// Rewrites the uniform block and instance counts from `material`
    /// (same variant; textures are rebound only by [`Renderer::prepare`]).
    pub fn update(&self, prepared: &mut PreparedMaterial, material: &Material) -> Result<()> {
        if let (Some(buf), Some(layout)) = (&prepared.bound.uniform, &prepared.uniform_layout) {
            let bytes = material.uniform_bytes(layout)?;
            self.gpu.queue.write_buffer(buf, 0, &bytes);
        }
        prepared.instances = prepared
            .bound
            .pipelines
            .passes
            .iter()
            .map(|p| material.instance_count(&p.pass))
            .collect::<Result<Vec<_>>>()?;
        Ok(())
    }

    /// Reads the prepared material's uniform buffer back from the GPU.
    pub fn read_uniform(&self, prepared: &PreparedMaterial) -> Result<Option<Vec<u8>>> {
        match &prepared.bound.uniform {
            Some(b) => Ok(Some(self.gpu.read_buffer(b)?)),
            None => Ok(None),
        }
    }

    /// Prepares and draws in one call.
    pub fn render(
        &mut self,
        material: &Material,
        scene: &Scene,
        options: &RenderOptions,
    ) -> Result<HdrImage> {
        let prepared = self.prepare(material, options)?;
        self.render_prepared(&prepared, scene, options)
    }

    /// Draws a prepared material over the background and reads the linear image back.
    pub fn render_prepared(
        &mut self,
        prepared: &PreparedMaterial,
        scene: &Scene,
        options: &RenderOptions,
    ) -> Result<HdrImage> {
        Ok(self
            .draw_repeated(prepared, scene, options, 1, false, None)?
            .0)
    }

    /// [`Renderer::draw_frames`] of a prepared material on `scene`: every
    /// pass in queue order with its instance count.
    pub(crate) fn draw_repeated(
        &mut self,
        prepared: &PreparedMaterial,
        scene: &Scene,
        options: &RenderOptions,
        frames: u32,
        timed: bool,
        timestamps: Option<&wgpu::QuerySet>,
    ) -> Result<(HdrImage, Vec<f64>)> {
        prepared.check_format(options)?;
        if matches!(options.background, crate::Background::Sky { .. }) {
            self.ensure_sky_pipeline(options.format)?;
        }
        if let Some(object) = &prepared.bound.object {
            let bytes = object_bytes(object, &scene.model)?;
            self.gpu.queue.write_buffer(&object.buffer, 0, &bytes);
        }
        let pipelines = &prepared.bound.pipelines;
        let mesh = GpuMesh::upload(&self.gpu, &scene.mesh, &pipelines.vertex_inputs)?;
        let draws: Vec<DrawCall> = pipelines
            .passes
            .iter()
            .zip(&prepared.instances)
            .map(|(pp, &instances)| DrawCall {
                pipeline: &pp.pipeline,
                bind_groups: &prepared.bound.bind_groups,
                mesh: &mesh,
                instances,
                stencil_reference: pp.pass.depth_stencil.stencil_reference,
            })
            .collect();
        let view = FrameView {
            camera: &scene.camera,
            light: &scene.light,
            env: &self.env,
        };
        self.draw_frames(&view, &draws, options, frames, timed, timestamps)
    }
}

/// The passes of the material's current variant (`Variant::passes`) in draw
/// order: by queue, stable.
fn material_passes(material: &Material) -> Result<Vec<Pass>> {
    let variant = material.current_variant()?.requested;
    let mut passes: Vec<Pass> = material
        .metadata()
        .variant_passes(variant)
        .cloned()
        .collect();
    passes.sort_by_key(|p| p.render_state.queue);
    Ok(passes)
}

/// What a group-1 texture binding of the material's variant samples: the
/// value of the parameter it carries; a texture left unset binds the
/// built-in texture its binding names (`texture.default`, resolved for the
/// variant's keywords), not the parameter's declared default, or the image
/// the binding names (`texture.file`).
fn material_texture<'m>(material: &'m Material, b: &Binding) -> Result<TextureSource<'m>> {
    let pname = b.parameter.as_ref().ok_or_else(|| {
        Error::Metadata(format!(
            "material texture binding `{}` names no parameter",
            b.name
        ))
    })?;
    let param = material.parameter(pname)?;
    let value = material
        .get(pname)
        .ok_or_else(|| Error::Metadata(format!("parameter `{pname}` has no value")))?;
    let binding_default = b.texture.as_ref().and_then(|t| t.default);
    // An unset texture whose binding names an image binds it.
    let image = b
        .texture
        .as_ref()
        .and_then(|t| t.file.as_ref())
        .and_then(|_| material.texture_image(pname));
    let texture = |t: &'m TextureValue| match (image, binding_default) {
        _ if material.texture_is_set(pname) => Cow::Borrowed(t),
        (Some(image), _) => Cow::Borrowed(image),
        (None, Some(d)) => Cow::Owned(TextureValue::Builtin(d)),
        (None, None) => Cow::Borrowed(t),
    };
    Ok(match (param.kind, value) {
        (ParamKind::Texture2d, StoredValue::Texture(t)) => TextureSource::Texture2d(texture(t)),
        (ParamKind::Gradient, StoredValue::Gradient(bytes)) => TextureSource::Ramp(bytes),
        (ParamKind::Cube, StoredValue::Texture(t)) => TextureSource::Cube(texture(t)),
        _ => {
            return Err(Error::Metadata(format!(
                "binding `{}` ({:?}) cannot carry {} parameter `{pname}`",
                b.name,
                b.kind,
                param.kind.name()
            )));
        }
    })
}
