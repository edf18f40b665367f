//! Pipelines, bind groups and draws built from a variant's metadata, and the
//! offscreen render + readback.
//!
//! Group 0 (frame) and group 2 (object) are the engine interface
//! (crates/weft-compiler/src/wgsl/engine_interface.wgsl); group 1 is the
//! material, bound by parameter name from the metadata's `bindings`.

use crate::environment::{EnvironmentMaps, Luts, SHEEN_LUT_FILE};
use crate::error::{Error, Result, io_err};
use crate::gpu::Gpu;
use crate::image::HdrImage;
use crate::material::{Material, StoredValue, TextureValue};
use crate::math;
use crate::scene::{Mesh, Scene};
use std::collections::{BTreeMap, HashMap};
use std::sync::Arc;
use weft_meta::{
    BindingKind, BlendMode, CullMode, DepthTest, ParamKind, Pass, Stage, VariantShader, VertexInput,
};
use wgpu::util::DeviceExt;

/// Colour target format of a render.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum ColorFormat {
    /// What engines use; the standard material clamps its output to the f16 maximum.
    #[default]
    Rgba16Float,
    /// Full f32, e.g. to find NaN/Inf a half-float target would hide.
    Rgba32Float,
}

impl ColorFormat {
    pub fn wgpu(self) -> wgpu::TextureFormat {
        match self {
            ColorFormat::Rgba16Float => wgpu::TextureFormat::Rgba16Float,
            ColorFormat::Rgba32Float => wgpu::TextureFormat::Rgba32Float,
        }
    }

    fn bytes_per_pixel(self) -> u32 {
        match self {
            ColorFormat::Rgba16Float => 8,
            ColorFormat::Rgba32Float => 16,
        }
    }
}

/// Which generated file a variant is drawn from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum ShaderLanguage {
    /// `<id>.wgsl`; constant-mode keywords become pipeline constants.
    #[default]
    Wgsl,
    /// `<id><c>.spv` (the file whose baked constants match the current
    /// keyword values), read by naga's SPIR-V front end (wgpu's SPIR-V path)
    /// with the clip-space y flip of weft's Vulkan-native SPIR-V undone.
    SpirV,
}

/// What is behind the object.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Background {
    /// The environment cube at this mip level (0 = sharp sky).
    Sky { mip: f32 },
    /// A flat linear colour.
    Color([f32; 4]),
}

/// Size, formats and background of one render.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RenderOptions {
    pub width: u32,
    pub height: u32,
    pub format: ColorFormat,
    pub language: ShaderLanguage,
    pub background: Background,
    /// `weft_frame.params.y` (the runtime does not scale the image by it).
    pub exposure: f32,
    /// `weft_frame.params.z`, seconds.
    pub time: f32,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            width: 256,
            height: 256,
            format: ColorFormat::Rgba16Float,
            language: ShaderLanguage::Wgsl,
            background: Background::Sky { mip: 0.0 },
            exposure: 1.0,
            time: 0.0,
        }
    }
}

const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;
const FRAME_SIZE: u64 = 336;
const OBJECT_SIZE: u64 = 128;
const SKY_UNIFORM_SIZE: u64 = 96;

struct PassPipeline {
    pass: Pass,
    pipeline: wgpu::RenderPipeline,
}

/// Pipelines and layouts of one variant for one language, format and constants.
struct VariantPipelines {
    layouts: Vec<Option<wgpu::BindGroupLayout>>,
    passes: Vec<PassPipeline>,
    vertex_inputs: Vec<VertexInput>,
}

/// A material's variant ready to draw: pipelines, bind groups, uniform buffer.
pub struct PreparedMaterial {
    variant_id: String,
    format: ColorFormat,
    pipelines: Arc<VariantPipelines>,
    bind_groups: Vec<Option<wgpu::BindGroup>>,
    uniform: Option<wgpu::Buffer>,
    uniform_layout: Option<weft_meta::UniformLayout>,
    instances: Vec<u32>,
}

impl PreparedMaterial {
    /// The canonical variant drawn.
    pub fn variant_id(&self) -> &str {
        &self.variant_id
    }

    /// The group-1 uniform buffer (`COPY_SRC`, so tests can read it back).
    pub fn uniform_buffer(&self) -> Option<&wgpu::Buffer> {
        self.uniform.as_ref()
    }

    /// Instances each pass draws, in draw (queue) order.
    pub fn instances(&self) -> &[u32] {
        &self.instances
    }

    /// Names of the passes in draw (queue) order.
    pub fn pass_names(&self) -> Vec<&str> {
        self.pipelines
            .passes
            .iter()
            .map(|p| p.pass.name.as_str())
            .collect()
    }
}

struct GpuEnvironment {
    view: wgpu::TextureView,
    mip_count: u32,
    sh: [[f32; 3]; 9],
}

/// Draws materials into offscreen targets on one [`Gpu`].
pub struct Renderer {
    gpu: Gpu,
    env: GpuEnvironment,
    lut_view: wgpu::TextureView,
    sheen_view: Option<wgpu::TextureView>,
    env_sampler: wgpu::Sampler,
    lut_sampler: wgpu::Sampler,
    repeat_sampler: wgpu::Sampler,
    clamp_sampler: wgpu::Sampler,
    frame_buffer: wgpu::Buffer,
    object_buffer: wgpu::Buffer,
    sky_buffer: wgpu::Buffer,
    sky_layout: wgpu::BindGroupLayout,
    sky_module: wgpu::ShaderModule,
    sky_pipelines: HashMap<ColorFormat, wgpu::RenderPipeline>,
    cache: HashMap<String, Arc<VariantPipelines>>,
}

impl Renderer {
    pub fn new(gpu: Gpu, env: &EnvironmentMaps, luts: &Luts) -> Result<Renderer> {
        let lut = &luts.brdf;
        let device = &gpu.device;
        let linear = |label, mode| {
            device.create_sampler(&wgpu::SamplerDescriptor {
                label: Some(label),
                address_mode_u: mode,
                address_mode_v: mode,
                address_mode_w: mode,
                mag_filter: wgpu::FilterMode::Linear,
                min_filter: wgpu::FilterMode::Linear,
                mipmap_filter: wgpu::MipmapFilterMode::Linear,
                ..Default::default()
            })
        };
        let env_sampler = linear("weft_environment_sampler", wgpu::AddressMode::ClampToEdge);
        let lut_sampler = linear("weft_lut_sampler", wgpu::AddressMode::ClampToEdge);
        let repeat_sampler = linear("material_sampler", wgpu::AddressMode::Repeat);
        let clamp_sampler = linear("material_clamp_sampler", wgpu::AddressMode::ClampToEdge);
        let uniform = |label, size| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            })
        };
        let frame_buffer = uniform("weft_frame", FRAME_SIZE);
        let object_buffer = uniform("weft_object", OBJECT_SIZE);
        let sky_buffer = uniform("weft sky", SKY_UNIFORM_SIZE);
        let lut_texture = device.create_texture_with_data(
            &gpu.queue,
            &wgpu::TextureDescriptor {
                label: Some("weft_brdf_lut"),
                size: wgpu::Extent3d {
                    width: lut.size,
                    height: lut.size,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::Rg16Float,
                usage: wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            },
            wgpu::util::TextureDataOrder::LayerMajor,
            &lut.bytes,
        );
        let lut_view = lut_texture.create_view(&Default::default());
        let sheen_view = luts.sheen.as_ref().map(|sheen| {
            device
                .create_texture_with_data(
                    &gpu.queue,
                    &wgpu::TextureDescriptor {
                        label: Some("weft_sheen_lut"),
                        size: wgpu::Extent3d {
                            width: sheen.size,
                            height: sheen.size,
                            depth_or_array_layers: 1,
                        },
                        mip_level_count: 1,
                        sample_count: 1,
                        dimension: wgpu::TextureDimension::D2,
                        format: wgpu::TextureFormat::R16Float,
                        usage: wgpu::TextureUsages::TEXTURE_BINDING,
                        view_formats: &[],
                    },
                    wgpu::util::TextureDataOrder::LayerMajor,
                    &sheen.bytes,
                )
                .create_view(&Default::default())
        });
        let sky_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("weft sky"),
            entries: &[
                layout_entry(0, wgpu::ShaderStages::FRAGMENT, BindingKind::UniformBuffer)?,
                layout_entry(1, wgpu::ShaderStages::FRAGMENT, BindingKind::TextureCube)?,
                layout_entry(2, wgpu::ShaderStages::FRAGMENT, BindingKind::Sampler)?,
            ],
        });
        let sky_module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("weft sky"),
            source: wgpu::ShaderSource::Wgsl(include_str!("sky.wgsl").into()),
        });
        let env = upload_environment(&gpu, env);
        gpu.take_uncaptured("renderer setup")?;
        Ok(Renderer {
            gpu,
            env,
            lut_view,
            sheen_view,
            env_sampler,
            lut_sampler,
            repeat_sampler,
            clamp_sampler,
            frame_buffer,
            object_buffer,
            sky_buffer,
            sky_layout,
            sky_module,
            sky_pipelines: HashMap::new(),
            cache: HashMap::new(),
        })
    }

    pub fn gpu(&self) -> &Gpu {
        &self.gpu
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
        let resolved = material.current_variant()?;
        let shader = resolved.shader;
        let variant_id = resolved.canonical.id.clone();
        let constants = match options.language {
            ShaderLanguage::Wgsl => material.pipeline_constants(shader)?,
            ShaderLanguage::SpirV => Vec::new(),
        };
        let spirv_file = match options.language {
            ShaderLanguage::Wgsl => None,
            ShaderLanguage::SpirV => Some(spirv_file_for(material, shader, &variant_id)?),
        };
        let key = format!(
            "{}|{}|{}|{:?}|{:?}|{:?}|{:?}",
            material.name(),
            material.metadata().inputs_hash,
            variant_id,
            options.language,
            options.format,
            constants,
            spirv_file
        );
        let pipelines = match self.cache.get(&key) {
            Some(p) => p.clone(),
            None => {
                let p = Arc::new(self.build_pipelines(
                    material,
                    shader,
                    &variant_id,
                    options,
                    &constants,
                    spirv_file.as_deref(),
                )?);
                self.cache.insert(key, p.clone());
                p
            }
        };
        let gpu = &self.gpu;
        let uniform_layout = shader.material_uniform.clone();
        let uniform = match &uniform_layout {
            Some(layout) => {
                let bytes = material.uniform_bytes(layout)?;
                Some(
                    gpu.device
                        .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                            label: Some("material"),
                            contents: &bytes,
                            usage: wgpu::BufferUsages::UNIFORM
                                | wgpu::BufferUsages::COPY_DST
                                | wgpu::BufferUsages::COPY_SRC,
                        }),
                )
            }
            None => None,
        };
        let bind_groups = gpu.checked("binding material resources", || {
            self.bind_groups(material, shader, &pipelines, uniform.as_ref())
        })??;
        let instances = pipelines
            .passes
            .iter()
            .map(|p| material.instance_count(&p.pass))
            .collect::<Result<Vec<_>>>()?;
        Ok(PreparedMaterial {
            variant_id,
            format: options.format,
            pipelines,
            bind_groups,
            uniform,
            uniform_layout,
            instances,
        })
    }

    /// Rewrites the uniform block and instance counts from `material`
    /// (same variant; textures are rebound only by [`Renderer::prepare`]).
    pub fn update(&self, prepared: &mut PreparedMaterial, material: &Material) -> Result<()> {
        if let (Some(buf), Some(layout)) = (&prepared.uniform, &prepared.uniform_layout) {
            let bytes = material.uniform_bytes(layout)?;
            self.gpu.queue.write_buffer(buf, 0, &bytes);
        }
        prepared.instances = prepared
            .pipelines
            .passes
            .iter()
            .map(|p| material.instance_count(&p.pass))
            .collect::<Result<Vec<_>>>()?;
        Ok(())
    }

    /// Reads the prepared material's uniform buffer back from the GPU.
    pub fn read_uniform(&self, prepared: &PreparedMaterial) -> Result<Option<Vec<u8>>> {
        match &prepared.uniform {
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

    /// Draws `frames` frames into the same targets, one submit each, and
    /// reads the last one back. With `timed`, every frame is waited for and
    /// its submit-to-completion CPU time (ms) returned; `timestamps` receives
    /// pass timestamp writes at 2i and 2i+1 (see timing.rs).
    pub(crate) fn draw_repeated(
        &mut self,
        prepared: &PreparedMaterial,
        scene: &Scene,
        options: &RenderOptions,
        frames: u32,
        timed: bool,
        timestamps: Option<&wgpu::QuerySet>,
    ) -> Result<(HdrImage, Vec<f64>)> {
        if prepared.format != options.format {
            return Err(Error::Gpu(format!(
                "material prepared for {:?}, render asks for {:?}",
                prepared.format, options.format
            )));
        }
        let (w, h) = (options.width.max(1), options.height.max(1));
        let aspect = w as f32 / h as f32;
        self.write_frame(scene, aspect, options);
        if matches!(options.background, Background::Sky { .. })
            && !self.sky_pipelines.contains_key(&options.format)
        {
            let p = self.build_sky_pipeline(options.format)?;
            self.sky_pipelines.insert(options.format, p);
        }
        let mesh = &scene.mesh;
        let vertex_count = mesh.vertex_count();
        if let Some(bad) = mesh.indices.iter().find(|&&i| i as usize >= vertex_count) {
            return Err(Error::InvalidValue {
                name: "mesh".into(),
                message: format!("index {bad} is out of range ({vertex_count} vertices)"),
            });
        }
        let draw_mesh = !mesh.indices.is_empty();
        let gpu = &self.gpu;
        let device = &gpu.device;
        let vertex_buffers = prepared
            .pipelines
            .vertex_inputs
            .iter()
            .map(|vi| {
                let mut bytes = vertex_stream(&scene.mesh, vi)?;
                if bytes.is_empty() {
                    bytes = vec![0; 16];
                }
                Ok(
                    device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                        label: Some(&vi.name),
                        contents: &bytes,
                        usage: wgpu::BufferUsages::VERTEX,
                    }),
                )
            })
            .collect::<Result<Vec<_>>>()?;
        let index_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("indices"),
            contents: if draw_mesh {
                bytemuck::cast_slice(&scene.mesh.indices)
            } else {
                &[0; 4]
            },
            usage: wgpu::BufferUsages::INDEX,
        });
        let size = wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        };
        let color = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("weft colour"),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: options.format.wgpu(),
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let depth = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("weft depth"),
            size,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: DEPTH_FORMAT,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            view_formats: &[],
        });
        let color_view = color.create_view(&Default::default());
        let depth_view = depth.create_view(&Default::default());
        let sky_bind_group = match options.background {
            Background::Sky { .. } => Some(device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("weft sky"),
                layout: &self.sky_layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: self.sky_buffer.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::TextureView(&self.env.view),
                    },
                    wgpu::BindGroupEntry {
                        binding: 2,
                        resource: wgpu::BindingResource::Sampler(&self.env_sampler),
                    },
                ],
            })),
            Background::Color(_) => None,
        };
        let clear = clear_color(options.background);
        let (staging, row) = readback_buffer(device, w, h, options.format, "weft colour readback");
        let frames = frames.max(1);
        let mut cpu_ms = Vec::new();
        for frame in 0..frames {
            let last = frame + 1 == frames;
            let commands = gpu.checked("drawing", || {
                let mut enc = device.create_command_encoder(&Default::default());
                {
                    let mut rp = enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                        label: Some("weft render"),
                        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                            view: &color_view,
                            depth_slice: None,
                            resolve_target: None,
                            ops: wgpu::Operations {
                                load: wgpu::LoadOp::Clear(clear),
                                store: wgpu::StoreOp::Store,
                            },
                        })],
                        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                            view: &depth_view,
                            depth_ops: Some(wgpu::Operations {
                                load: wgpu::LoadOp::Clear(1.0),
                                store: wgpu::StoreOp::Discard,
                            }),
                            stencil_ops: None,
                        }),
                        timestamp_writes: timestamps.map(|q| wgpu::RenderPassTimestampWrites {
                            query_set: q,
                            beginning_of_pass_write_index: Some(2 * frame),
                            end_of_pass_write_index: Some(2 * frame + 1),
                        }),
                        occlusion_query_set: None,
                        multiview_mask: None,
                    });
                    if let (Some(bg), Some(p)) =
                        (&sky_bind_group, self.sky_pipelines.get(&options.format))
                    {
                        rp.set_pipeline(p);
                        rp.set_bind_group(0, bg, &[]);
                        rp.draw(0..3, 0..1);
                    }
                    if draw_mesh {
                        for (i, b) in vertex_buffers.iter().enumerate() {
                            rp.set_vertex_buffer(i as u32, b.slice(..));
                        }
                        rp.set_index_buffer(index_buffer.slice(..), wgpu::IndexFormat::Uint32);
                        for (g, bg) in prepared.bind_groups.iter().enumerate() {
                            if let Some(bg) = bg {
                                rp.set_bind_group(g as u32, bg, &[]);
                            }
                        }
                        let n = scene.mesh.indices.len() as u32;
                        let passes = prepared.pipelines.passes.iter().zip(&prepared.instances);
                        for (pp, &instances) in passes {
                            if instances == 0 {
                                continue;
                            }
                            rp.set_pipeline(&pp.pipeline);
                            rp.draw_indexed(0..n, 0, 0..instances);
                        }
                    }
                }
                if last {
                    enc.copy_texture_to_buffer(
                        wgpu::TexelCopyTextureInfo {
                            texture: &color,
                            mip_level: 0,
                            origin: wgpu::Origin3d::ZERO,
                            aspect: wgpu::TextureAspect::All,
                        },
                        wgpu::TexelCopyBufferInfo {
                            buffer: &staging,
                            layout: wgpu::TexelCopyBufferLayout {
                                offset: 0,
                                bytes_per_row: Some(row),
                                rows_per_image: Some(h),
                            },
                        },
                        size,
                    );
                }
                enc.finish()
            })?;
            let started = std::time::Instant::now();
            gpu.queue.submit([commands]);
            if timed {
                gpu.wait()?;
                cpu_ms.push(started.elapsed().as_secs_f64() * 1e3);
            }
        }
        gpu.take_uncaptured("drawing")?;
        let bytes = gpu.map_read(&staging)?;
        let pixels = decode_rows(&bytes, w, h, row, options.format);
        let image = HdrImage {
            width: w,
            height: h,
            pixels,
        };
        Ok((image, cpu_ms))
    }

    /// The `weft_frame` and `weft_object` uniform contents (as f32s) of a scene.
    fn frame_and_object(
        &self,
        scene: &Scene,
        aspect: f32,
        options: &RenderOptions,
    ) -> (Vec<f32>, Vec<f32>) {
        let view = scene.camera.view();
        let view_proj = scene.camera.view_proj(aspect);
        let light_dir = math::normalize(scene.light.direction);
        let mut f: Vec<f32> = Vec::with_capacity((FRAME_SIZE / 4) as usize);
        f.extend(view_proj.iter().flatten());
        f.extend(view.iter().flatten());
        f.extend(scene.camera.eye);
        f.push(1.0);
        f.extend(light_dir);
        f.push(0.0);
        f.extend(scene.light.radiance);
        f.push(0.0);
        for c in &self.env.sh {
            f.extend(c);
            f.push(0.0);
        }
        f.extend([
            self.env.mip_count as f32,
            options.exposure,
            options.time,
            0.0,
        ]);
        debug_assert_eq!(f.len() * 4, FRAME_SIZE as usize);
        let mut o: Vec<f32> = Vec::with_capacity((OBJECT_SIZE / 4) as usize);
        o.extend(scene.model.iter().flatten());
        o.extend(math::normal_matrix(&scene.model).iter().flatten());
        (f, o)
    }

    fn write_frame(&self, scene: &Scene, aspect: f32, options: &RenderOptions) {
        let (f, o) = self.frame_and_object(scene, aspect, options);
        self.gpu
            .queue
            .write_buffer(&self.frame_buffer, 0, bytemuck::cast_slice(&f));
        self.gpu
            .queue
            .write_buffer(&self.object_buffer, 0, bytemuck::cast_slice(&o));

        let view_proj = scene.camera.view_proj(aspect);
        let inv = math::inverse(&view_proj).unwrap_or(math::IDENTITY);
        let mip = match options.background {
            Background::Sky { mip } => mip,
            Background::Color(_) => 0.0,
        };
        let mut s: Vec<f32> = Vec::with_capacity((SKY_UNIFORM_SIZE / 4) as usize);
        s.extend(inv.iter().flatten());
        s.extend(scene.camera.eye);
        s.push(1.0);
        s.extend([mip, 0.0, 0.0, 0.0]);
        self.gpu
            .queue
            .write_buffer(&self.sky_buffer, 0, bytemuck::cast_slice(&s));
    }

    fn build_sky_pipeline(&self, format: ColorFormat) -> Result<wgpu::RenderPipeline> {
        let device = &self.gpu.device;
        self.gpu.checked("sky pipeline", || {
            let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some("weft sky"),
                bind_group_layouts: &[Some(&self.sky_layout)],
                immediate_size: 0,
            });
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some("weft sky"),
                layout: Some(&layout),
                vertex: wgpu::VertexState {
                    module: &self.sky_module,
                    entry_point: Some("vs_sky"),
                    compilation_options: Default::default(),
                    buffers: &[],
                },
                primitive: wgpu::PrimitiveState::default(),
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: DEPTH_FORMAT,
                    depth_write_enabled: Some(false),
                    depth_compare: Some(wgpu::CompareFunction::Always),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: Default::default(),
                fragment: Some(wgpu::FragmentState {
                    module: &self.sky_module,
                    entry_point: Some("fs_sky"),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format: format.wgpu(),
                        blend: None,
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                multiview_mask: None,
                cache: None,
            })
        })
    }

    fn build_pipelines(
        &self,
        material: &Material,
        shader: &VariantShader,
        variant_id: &str,
        options: &RenderOptions,
        constants: &[(String, f64)],
        spirv_file: Option<&str>,
    ) -> Result<VariantPipelines> {
        let gpu = &self.gpu;
        let device = &gpu.device;
        let source = match spirv_file {
            None => {
                let rel = &shader
                    .files
                    .get("wgsl")
                    .and_then(|f| f.first())
                    .ok_or_else(|| {
                        Error::Metadata(format!("variant `{variant_id}` lists no WGSL file"))
                    })?
                    .path;
                let path = material.dir().join(rel);
                let text = std::fs::read_to_string(&path).map_err(io_err(&path))?;
                wgpu::ShaderSource::Wgsl(text.into())
            }
            Some(rel) => {
                let path = material.dir().join(rel);
                let bytes = std::fs::read(&path).map_err(io_err(&path))?;
                if bytes.len() % 4 != 0 || bytes.len() < 20 {
                    return Err(Error::Metadata(format!(
                        "{} is not a SPIR-V module",
                        path.display()
                    )));
                }
                // weft's SPIR-V is Vulkan-native: the compiler negates the
                // clip-space y (naga's ADJUST_COORDINATE_SPACE), while wgpu
                // expects y up (its own SPIR-V path parses with
                // `adjust_coordinate_space: false`). naga's SPIR-V front end
                // with the adjustment on undoes exactly that negation, so the
                // module rasterises like the WGSL file.
                let options = wgpu::naga::front::spv::Options {
                    adjust_coordinate_space: true,
                    strict_capabilities: true,
                    block_ctx_dump_prefix: None,
                };
                let module =
                    wgpu::naga::front::spv::parse_u8_slice(&bytes, &options).map_err(|e| {
                        Error::Gpu(format!("{}: SPIR-V does not parse: {e}", path.display()))
                    })?;
                wgpu::ShaderSource::Naga(std::borrow::Cow::Owned(module))
            }
        };
        let module = gpu.checked(&format!("shader module of `{variant_id}`"), || {
            device.create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some(variant_id),
                source,
            })
        })?;

        // Bind group layouts from the reflected bindings.
        let max_group = shader.bindings.iter().map(|b| b.group).max();
        let mut layouts: Vec<Option<wgpu::BindGroupLayout>> = Vec::new();
        if let Some(max_group) = max_group {
            for g in 0..=max_group {
                let entries = shader
                    .bindings
                    .iter()
                    .filter(|b| b.group == g)
                    .map(|b| layout_entry(b.binding, stages(&b.stages), b.kind))
                    .collect::<Result<Vec<_>>>()?;
                let layout = gpu.checked("bind group layout", || {
                    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                        label: Some(&format!("group {g}")),
                        entries: &entries,
                    })
                })?;
                layouts.push(Some(layout));
            }
        }
        let layout_refs: Vec<Option<&wgpu::BindGroupLayout>> =
            layouts.iter().map(Option::as_ref).collect();
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(variant_id),
            bind_group_layouts: &layout_refs,
            immediate_size: 0,
        });

        // One vertex buffer per input, at slot = position in the list.
        let attributes = shader
            .vertex_inputs
            .iter()
            .map(|vi| {
                Ok([wgpu::VertexAttribute {
                    format: vertex_format(&vi.format)?,
                    offset: 0,
                    shader_location: vi.location,
                }])
            })
            .collect::<Result<Vec<_>>>()?;
        let buffers: Vec<Option<wgpu::VertexBufferLayout>> = attributes
            .iter()
            .map(|a| {
                Some(wgpu::VertexBufferLayout {
                    array_stride: a[0].format.size(),
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: a,
                })
            })
            .collect();

        let constant_refs: Vec<(&str, f64)> =
            constants.iter().map(|(k, v)| (k.as_str(), *v)).collect();
        let mut order: Vec<&Pass> = material.metadata().passes.iter().collect();
        order.sort_by_key(|p| p.render_state.queue);
        let mut passes = Vec::new();
        for pass in order {
            let rs = &pass.render_state;
            let pipeline = gpu.checked(
                &format!("pipeline of pass `{}` of `{variant_id}`", pass.name),
                || {
                    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                        label: Some(&pass.name),
                        layout: Some(&pipeline_layout),
                        vertex: wgpu::VertexState {
                            module: &module,
                            entry_point: Some(&pass.vertex_entry),
                            compilation_options: wgpu::PipelineCompilationOptions {
                                constants: &constant_refs,
                                ..Default::default()
                            },
                            buffers: &buffers,
                        },
                        primitive: wgpu::PrimitiveState {
                            topology: wgpu::PrimitiveTopology::TriangleList,
                            front_face: wgpu::FrontFace::Ccw,
                            cull_mode: match rs.cull {
                                CullMode::None => None,
                                CullMode::Front => Some(wgpu::Face::Front),
                                CullMode::Back => Some(wgpu::Face::Back),
                            },
                            ..Default::default()
                        },
                        depth_stencil: Some(wgpu::DepthStencilState {
                            format: DEPTH_FORMAT,
                            depth_write_enabled: Some(rs.depth_write),
                            depth_compare: Some(compare(rs.depth_test)),
                            stencil: Default::default(),
                            bias: Default::default(),
                        }),
                        multisample: Default::default(),
                        fragment: Some(wgpu::FragmentState {
                            module: &module,
                            entry_point: Some(&pass.fragment_entry),
                            compilation_options: wgpu::PipelineCompilationOptions {
                                constants: &constant_refs,
                                ..Default::default()
                            },
                            targets: &[Some(wgpu::ColorTargetState {
                                format: options.format.wgpu(),
                                blend: blend(rs.blend),
                                write_mask: wgpu::ColorWrites::ALL,
                            })],
                        }),
                        multiview_mask: None,
                        cache: None,
                    })
                },
            )?;
            passes.push(PassPipeline {
                pass: pass.clone(),
                pipeline,
            });
        }
        Ok(VariantPipelines {
            layouts,
            passes,
            vertex_inputs: shader.vertex_inputs.clone(),
        })
    }

    fn bind_groups(
        &self,
        material: &Material,
        shader: &VariantShader,
        pipelines: &VariantPipelines,
        uniform: Option<&wgpu::Buffer>,
    ) -> Result<Vec<Option<wgpu::BindGroup>>> {
        let gpu = &self.gpu;
        // Material textures first: the entries borrow their views.
        let mut views: BTreeMap<(u32, u32), wgpu::TextureView> = BTreeMap::new();
        for b in &shader.bindings {
            if b.group != 1 || !is_texture(b.kind) {
                continue;
            }
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
            let srgb = param.texture.as_ref().is_some_and(|t| t.srgb);
            let tex = match (b.kind, param.kind, value) {
                (BindingKind::Texture2d, ParamKind::Texture2d, StoredValue::Texture(t)) => {
                    texture_2d(gpu, pname, t, srgb)?
                }
                (BindingKind::Texture2d, ParamKind::Gradient, StoredValue::Gradient(bytes)) => {
                    let width = (bytes.len() / 4) as u32;
                    rgba8_texture(gpu, pname, width, 1, 1, bytes, true)
                }
                (BindingKind::TextureCube, ParamKind::Cube, StoredValue::Texture(t)) => {
                    cube_texture(gpu, pname, t, srgb)?
                }
                _ => {
                    return Err(Error::Metadata(format!(
                        "binding `{}` ({:?}) cannot carry {} parameter `{pname}`",
                        b.name,
                        b.kind,
                        param.kind.name()
                    )));
                }
            };
            let dim = match b.kind {
                BindingKind::TextureCube => wgpu::TextureViewDimension::Cube,
                _ => wgpu::TextureViewDimension::D2,
            };
            views.insert(
                (b.group, b.binding),
                tex.create_view(&wgpu::TextureViewDescriptor {
                    dimension: Some(dim),
                    ..Default::default()
                }),
            );
        }
        let mut groups = Vec::new();
        for (g, layout) in pipelines.layouts.iter().enumerate() {
            let g = g as u32;
            let Some(layout) = layout else {
                groups.push(None);
                continue;
            };
            let mut entries = Vec::new();
            for b in shader.bindings.iter().filter(|b| b.group == g) {
                let mismatch = || {
                    Error::Metadata(format!(
                        "binding `{}` (group {g}, binding {}, {:?}) is not part of engine interface {}",
                        b.name,
                        b.binding,
                        b.kind,
                        weft_meta::ENGINE_INTERFACE_VERSION
                    ))
                };
                let resource = match (g, b.binding, b.kind) {
                    (0, 0, BindingKind::UniformBuffer) => self.frame_buffer.as_entire_binding(),
                    (0, 1, BindingKind::TextureCube) => {
                        wgpu::BindingResource::TextureView(&self.env.view)
                    }
                    (0, 2, BindingKind::Sampler) => {
                        wgpu::BindingResource::Sampler(&self.env_sampler)
                    }
                    (0, 3, BindingKind::Texture2d) => {
                        wgpu::BindingResource::TextureView(&self.lut_view)
                    }
                    (0, 4, BindingKind::Sampler) => {
                        wgpu::BindingResource::Sampler(&self.lut_sampler)
                    }
                    (0, 5, BindingKind::Texture2d) => wgpu::BindingResource::TextureView(
                        self.sheen_view.as_ref().ok_or_else(|| {
                            Error::Metadata(format!(
                                "the variant binds `{}` but no sheen LUT was loaded \
                                     (expected `{SHEEN_LUT_FILE}` in the generated folder)",
                                b.name
                            ))
                        })?,
                    ),
                    (1, 0, BindingKind::UniformBuffer) => uniform
                        .ok_or_else(|| {
                            Error::Metadata(
                                "the variant binds `material` but has no material_uniform layout"
                                    .into(),
                            )
                        })?
                        .as_entire_binding(),
                    (1, 1, BindingKind::Sampler) => {
                        wgpu::BindingResource::Sampler(&self.repeat_sampler)
                    }
                    (1, 2, BindingKind::Sampler) => {
                        wgpu::BindingResource::Sampler(&self.clamp_sampler)
                    }
                    (1, _, k) if is_texture(k) => wgpu::BindingResource::TextureView(
                        views.get(&(g, b.binding)).ok_or_else(mismatch)?,
                    ),
                    (2, 0, BindingKind::UniformBuffer) => self.object_buffer.as_entire_binding(),
                    _ => return Err(mismatch()),
                };
                entries.push(wgpu::BindGroupEntry {
                    binding: b.binding,
                    resource,
                });
            }
            groups.push(Some(gpu.device.create_bind_group(
                &wgpu::BindGroupDescriptor {
                    label: Some(&format!("group {g}")),
                    layout,
                    entries: &entries,
                },
            )));
        }
        Ok(groups)
    }
}

/// One draw of [`Renderer::render_tiles`]: a mesh drawn with its own frame
/// uniforms (camera, light) and object uniforms (model matrix) into its own
/// rectangle of the target.
#[derive(Clone, Debug, PartialEq)]
pub struct Tile {
    /// Mesh, model matrix, camera and light of this draw. The projection's
    /// aspect is the viewport's.
    pub scene: Scene,
    /// x, y, width, height in pixels; must lie inside the target. Drawing is
    /// confined to it (viewport and scissor).
    pub viewport: [u32; 4],
}

/// Bytes between the per-tile uniform records of [`Renderer::render_tiles`].
const TILE_UNIFORM_STRIDE: u64 = 512;

impl Renderer {
    /// Draws a prepared material once per tile into one target and reads the
    /// whole target back: each tile gets its own `weft_frame` and
    /// `weft_object` contents (copied into the frame and object buffers
    /// between render passes) and its own viewport, so one target holds many
    /// small, independent renders (the stability probe, `probe.rs`). Every
    /// pass of the material is drawn per tile with its instance count; the
    /// depth buffer is cleared per tile. The background is
    /// `options.background` when it is a colour, black for `Sky` (no sky is drawn).
    pub fn render_tiles(
        &mut self,
        prepared: &PreparedMaterial,
        tiles: &[Tile],
        options: &RenderOptions,
    ) -> Result<HdrImage> {
        if prepared.format != options.format {
            return Err(Error::Gpu(format!(
                "material prepared for {:?}, render asks for {:?}",
                prepared.format, options.format
            )));
        }
        let (w, h) = (options.width.max(1), options.height.max(1));
        let gpu = &self.gpu;
        let device = &gpu.device;
        // One vertex stream per input and one index buffer for all tiles;
        // each tile draws its index range with its own base vertex.
        let mut streams: Vec<Vec<u8>> = vec![Vec::new(); prepared.pipelines.vertex_inputs.len()];
        let mut indices: Vec<u32> = Vec::new();
        let mut ranges = Vec::with_capacity(tiles.len());
        let mut uniforms: Vec<u8> = Vec::with_capacity(tiles.len() * TILE_UNIFORM_STRIDE as usize);
        let mut base_vertex = 0usize;
        for (i, tile) in tiles.iter().enumerate() {
            let [x, y, tw, th] = tile.viewport;
            if tw == 0 || th == 0 || x + tw > w || y + th > h {
                return Err(Error::InvalidValue {
                    name: format!("tile {i}"),
                    message: format!("viewport {:?} is outside the {w}x{h} target", tile.viewport),
                });
            }
            let mesh = &tile.scene.mesh;
            let count = mesh.vertex_count();
            if let Some(bad) = mesh.indices.iter().find(|&&k| k as usize >= count) {
                return Err(Error::InvalidValue {
                    name: format!("tile {i}"),
                    message: format!("index {bad} is out of range ({count} vertices)"),
                });
            }
            for (stream, vi) in streams.iter_mut().zip(&prepared.pipelines.vertex_inputs) {
                stream.extend(vertex_stream(mesh, vi)?);
            }
            let first = indices.len() as u32;
            indices.extend(&mesh.indices);
            ranges.push((first..indices.len() as u32, base_vertex as i32));
            base_vertex += count;
            let (f, o) = self.frame_and_object(&tile.scene, tw as f32 / th as f32, options);
            let start = uniforms.len();
            uniforms.extend_from_slice(bytemuck::cast_slice(&f));
            uniforms.extend_from_slice(bytemuck::cast_slice(&o));
            uniforms.resize(start + TILE_UNIFORM_STRIDE as usize, 0);
        }
        let vertex_buffers: Vec<wgpu::Buffer> = streams
            .iter()
            .zip(&prepared.pipelines.vertex_inputs)
            .map(|(bytes, vi)| {
                let contents: &[u8] = if bytes.is_empty() { &[0; 16] } else { bytes };
                device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some(&vi.name),
                    contents,
                    usage: wgpu::BufferUsages::VERTEX,
                })
            })
            .collect();
        let index_buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("tile indices"),
            contents: if indices.is_empty() {
                &[0; 4]
            } else {
                bytemuck::cast_slice(&indices)
            },
            usage: wgpu::BufferUsages::INDEX,
        });
        let uniform_records = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("tile uniforms"),
            contents: if uniforms.is_empty() {
                &[0; 4]
            } else {
                &uniforms
            },
            usage: wgpu::BufferUsages::COPY_SRC,
        });
        let size = wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        };
        let target = |label, format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let color = target(
            "weft tiles colour",
            options.format.wgpu(),
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        );
        let depth = target(
            "weft tiles depth",
            DEPTH_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        let color_view = color.create_view(&Default::default());
        let depth_view = depth.create_view(&Default::default());
        let clear = clear_color(options.background);
        let (staging, row) = readback_buffer(device, w, h, options.format, "weft tiles readback");
        let pass = |enc: &mut wgpu::CommandEncoder, load| {
            enc.begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("weft tile"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: &color_view,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load,
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                    view: &depth_view,
                    depth_ops: Some(wgpu::Operations {
                        load: wgpu::LoadOp::Clear(1.0),
                        store: wgpu::StoreOp::Discard,
                    }),
                    stencil_ops: None,
                }),
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            })
            .forget_lifetime()
        };
        gpu.checked("drawing tiles", || {
            let mut enc = device.create_command_encoder(&Default::default());
            drop(pass(&mut enc, wgpu::LoadOp::Clear(clear)));
            for (i, (tile, (range, base))) in tiles.iter().zip(&ranges).enumerate() {
                let off = i as u64 * TILE_UNIFORM_STRIDE;
                enc.copy_buffer_to_buffer(&uniform_records, off, &self.frame_buffer, 0, FRAME_SIZE);
                enc.copy_buffer_to_buffer(
                    &uniform_records,
                    off + FRAME_SIZE,
                    &self.object_buffer,
                    0,
                    OBJECT_SIZE,
                );
                let mut rp = pass(&mut enc, wgpu::LoadOp::Load);
                let [x, y, tw, th] = tile.viewport;
                rp.set_viewport(x as f32, y as f32, tw as f32, th as f32, 0.0, 1.0);
                rp.set_scissor_rect(x, y, tw, th);
                for (k, b) in vertex_buffers.iter().enumerate() {
                    rp.set_vertex_buffer(k as u32, b.slice(..));
                }
                rp.set_index_buffer(index_buffer.slice(..), wgpu::IndexFormat::Uint32);
                for (g, bg) in prepared.bind_groups.iter().enumerate() {
                    if let Some(bg) = bg {
                        rp.set_bind_group(g as u32, bg, &[]);
                    }
                }
                if range.is_empty() {
                    continue;
                }
                let passes = prepared.pipelines.passes.iter().zip(&prepared.instances);
                for (pp, &instances) in passes {
                    if instances > 0 {
                        rp.set_pipeline(&pp.pipeline);
                        rp.draw_indexed(range.clone(), *base, 0..instances);
                    }
                }
            }
            enc.copy_texture_to_buffer(
                wgpu::TexelCopyTextureInfo {
                    texture: &color,
                    mip_level: 0,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                wgpu::TexelCopyBufferInfo {
                    buffer: &staging,
                    layout: wgpu::TexelCopyBufferLayout {
                        offset: 0,
                        bytes_per_row: Some(row),
                        rows_per_image: Some(h),
                    },
                },
                size,
            );
            gpu.queue.submit([enc.finish()]);
        })?;
        let bytes = gpu.map_read(&staging)?;
        let pixels = decode_rows(&bytes, w, h, row, options.format);
        Ok(HdrImage {
            width: w,
            height: h,
            pixels,
        })
    }
}

/// The SPIR-V file whose baked constants equal the material's keyword values.
/// What a render pass clears the colour target to (the sky is drawn over black).
fn clear_color(background: Background) -> wgpu::Color {
    match background {
        Background::Color(c) => wgpu::Color {
            r: f64::from(c[0]),
            g: f64::from(c[1]),
            b: f64::from(c[2]),
            a: f64::from(c[3]),
        },
        Background::Sky { .. } => wgpu::Color::BLACK,
    }
}

/// A mappable buffer for a `w` x `h` colour readback and its padded row pitch.
fn readback_buffer(
    device: &wgpu::Device,
    w: u32,
    h: u32,
    format: ColorFormat,
    label: &str,
) -> (wgpu::Buffer, u32) {
    let row = (w * format.bytes_per_pixel()).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
        * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
    let staging = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size: u64::from(row) * u64::from(h),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    (staging, row)
}

/// Linear RGBA pixels from a padded readback of an Rgba16Float/Rgba32Float target.
fn decode_rows(bytes: &[u8], w: u32, h: u32, row: u32, format: ColorFormat) -> Vec<[f32; 4]> {
    let bpp = format.bytes_per_pixel();
    let mut pixels = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        let line = &bytes[(y * row) as usize..(y * row + w * bpp) as usize];
        match format {
            ColorFormat::Rgba16Float => pixels.extend(line.chunks_exact(8).map(|px| {
                [0, 2, 4, 6].map(|i| half::f16::from_le_bytes([px[i], px[i + 1]]).to_f32())
            })),
            ColorFormat::Rgba32Float => pixels.extend(line.chunks_exact(16).map(|px| {
                [0, 4, 8, 12].map(|i| f32::from_le_bytes([px[i], px[i + 1], px[i + 2], px[i + 3]]))
            })),
        }
    }
    pixels
}

fn spirv_file_for(material: &Material, shader: &VariantShader, id: &str) -> Result<String> {
    let files = shader
        .files
        .get("spirv")
        .ok_or_else(|| Error::Metadata(format!("variant `{id}` lists no SPIR-V file")))?;
    files
        .iter()
        .find(|f| {
            f.constants
                .iter()
                .all(|(k, v)| material.keyword(k).is_some_and(|x| x == v))
        })
        .map(|f| f.path.clone())
        .ok_or_else(|| {
            Error::Metadata(format!(
                "variant `{id}` has no SPIR-V file for keywords {:?}",
                material.keywords()
            ))
        })
}

fn upload_environment(gpu: &Gpu, env: &EnvironmentMaps) -> GpuEnvironment {
    let size = env.mips[0].size;
    let mip_count = env.mip_count();
    // Layer-major: face 0 mips 0..n, face 1 mips 0..n, ...
    let mut data: Vec<u8> = Vec::new();
    for face in 0..6u32 {
        for level in &env.mips {
            let n = (level.size * level.size) as usize;
            let start = face as usize * n;
            for t in &level.data[start..start + n] {
                for c in [t[0], t[1], t[2], 1.0] {
                    data.extend_from_slice(&half::f16::from_f32(c).to_le_bytes());
                }
            }
        }
    }
    let texture = gpu.device.create_texture_with_data(
        &gpu.queue,
        &wgpu::TextureDescriptor {
            label: Some("weft_environment"),
            size: wgpu::Extent3d {
                width: size,
                height: size,
                depth_or_array_layers: 6,
            },
            mip_level_count: mip_count,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: wgpu::TextureFormat::Rgba16Float,
            usage: wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        &data,
    );
    let view = texture.create_view(&wgpu::TextureViewDescriptor {
        dimension: Some(wgpu::TextureViewDimension::Cube),
        ..Default::default()
    });
    GpuEnvironment {
        view,
        mip_count,
        sh: env.sh,
    }
}

fn is_texture(k: BindingKind) -> bool {
    matches!(
        k,
        BindingKind::Texture2d
            | BindingKind::TextureCube
            | BindingKind::Texture2dArray
            | BindingKind::Texture3d
            | BindingKind::DepthTexture2d
    )
}

fn stages(s: &[Stage]) -> wgpu::ShaderStages {
    let mut out = wgpu::ShaderStages::NONE;
    for st in s {
        out |= match st {
            Stage::Vertex => wgpu::ShaderStages::VERTEX,
            Stage::Fragment => wgpu::ShaderStages::FRAGMENT,
            Stage::Compute => wgpu::ShaderStages::COMPUTE,
        };
    }
    out
}

fn layout_entry(
    binding: u32,
    visibility: wgpu::ShaderStages,
    kind: BindingKind,
) -> Result<wgpu::BindGroupLayoutEntry> {
    let tex = |view_dimension, sample_type| wgpu::BindingType::Texture {
        sample_type,
        view_dimension,
        multisampled: false,
    };
    let float = wgpu::TextureSampleType::Float { filterable: true };
    let ty = match kind {
        BindingKind::UniformBuffer => wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        BindingKind::StorageBuffer => wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only: true },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        BindingKind::Sampler => wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
        BindingKind::ComparisonSampler => {
            wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Comparison)
        }
        BindingKind::Texture2d => tex(wgpu::TextureViewDimension::D2, float),
        BindingKind::TextureCube => tex(wgpu::TextureViewDimension::Cube, float),
        BindingKind::Texture2dArray => tex(wgpu::TextureViewDimension::D2Array, float),
        BindingKind::Texture3d => tex(wgpu::TextureViewDimension::D3, float),
        BindingKind::DepthTexture2d => tex(
            wgpu::TextureViewDimension::D2,
            wgpu::TextureSampleType::Depth,
        ),
    };
    Ok(wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty,
        count: None,
    })
}

fn compare(d: DepthTest) -> wgpu::CompareFunction {
    match d {
        DepthTest::Always => wgpu::CompareFunction::Always,
        DepthTest::Never => wgpu::CompareFunction::Never,
        DepthTest::Less => wgpu::CompareFunction::Less,
        DepthTest::LessEqual => wgpu::CompareFunction::LessEqual,
        DepthTest::Equal => wgpu::CompareFunction::Equal,
        DepthTest::Greater => wgpu::CompareFunction::Greater,
        DepthTest::GreaterEqual => wgpu::CompareFunction::GreaterEqual,
    }
}

fn blend(b: BlendMode) -> Option<wgpu::BlendState> {
    use wgpu::{BlendComponent as C, BlendFactor as F, BlendOperation as O};
    let comp = |src, dst| C {
        src_factor: src,
        dst_factor: dst,
        operation: O::Add,
    };
    let keep_dst_alpha = comp(F::Zero, F::One);
    match b {
        BlendMode::Opaque => None,
        BlendMode::Alpha => Some(wgpu::BlendState {
            color: comp(F::SrcAlpha, F::OneMinusSrcAlpha),
            alpha: comp(F::One, F::OneMinusSrcAlpha),
        }),
        BlendMode::Premultiplied => Some(wgpu::BlendState {
            color: comp(F::One, F::OneMinusSrcAlpha),
            alpha: comp(F::One, F::OneMinusSrcAlpha),
        }),
        BlendMode::Additive => Some(wgpu::BlendState {
            color: comp(F::SrcAlpha, F::One),
            alpha: keep_dst_alpha,
        }),
        BlendMode::Multiply => Some(wgpu::BlendState {
            color: comp(F::Dst, F::Zero),
            alpha: keep_dst_alpha,
        }),
    }
}

/// WebGPU vertex format names (the float formats the engine interface uses).
fn vertex_format(name: &str) -> Result<wgpu::VertexFormat> {
    Ok(match name {
        "float32" => wgpu::VertexFormat::Float32,
        "float32x2" => wgpu::VertexFormat::Float32x2,
        "float32x3" => wgpu::VertexFormat::Float32x3,
        "float32x4" => wgpu::VertexFormat::Float32x4,
        other => {
            return Err(Error::Metadata(format!(
                "vertex format `{other}` is not supported (float32, float32x2/3/4)"
            )));
        }
    })
}

/// The mesh stream of a vertex input, as tightly packed f32s of its format.
fn vertex_stream(mesh: &Mesh, vi: &VertexInput) -> Result<Vec<u8>> {
    let n = vertex_format(&vi.format)?.size() as usize / 4;
    let count = mesh.vertex_count();
    let get = |i: usize| -> [f32; 4] {
        match vi.name.as_str() {
            "position" => {
                let p = mesh.positions[i];
                [p[0], p[1], p[2], 1.0]
            }
            "normal" => {
                let p = mesh.normals.get(i).copied().unwrap_or([0.0, 0.0, 1.0]);
                [p[0], p[1], p[2], 0.0]
            }
            "tangent" => mesh
                .tangents
                .get(i)
                .copied()
                .unwrap_or([1.0, 0.0, 0.0, 1.0]),
            "uv0" => {
                let p = mesh.uv0.get(i).copied().unwrap_or([0.0, 0.0]);
                [p[0], p[1], 0.0, 1.0]
            }
            "uv1" => {
                let p = mesh
                    .uv1
                    .get(i)
                    .or_else(|| mesh.uv0.get(i))
                    .copied()
                    .unwrap_or([0.0, 0.0]);
                [p[0], p[1], 0.0, 1.0]
            }
            "color" => mesh.colors.get(i).copied().unwrap_or([1.0; 4]),
            _ => [0.0; 4],
        }
    };
    if !matches!(
        vi.name.as_str(),
        "position" | "normal" | "tangent" | "uv0" | "uv1" | "color"
    ) {
        return Err(Error::Metadata(format!(
            "vertex input `{}` is not part of the engine interface",
            vi.name
        )));
    }
    let mut out = Vec::with_capacity(count * n * 4);
    for i in 0..count {
        let v = get(i);
        for c in &v[..n] {
            out.extend_from_slice(&c.to_le_bytes());
        }
    }
    Ok(out)
}

fn rgba8_texture(
    gpu: &Gpu,
    label: &str,
    width: u32,
    height: u32,
    layers: u32,
    data: &[u8],
    srgb: bool,
) -> wgpu::Texture {
    gpu.device.create_texture_with_data(
        &gpu.queue,
        &wgpu::TextureDescriptor {
            label: Some(label),
            size: wgpu::Extent3d {
                width,
                height,
                depth_or_array_layers: layers,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: if srgb {
                wgpu::TextureFormat::Rgba8UnormSrgb
            } else {
                wgpu::TextureFormat::Rgba8Unorm
            },
            usage: wgpu::TextureUsages::TEXTURE_BINDING,
            view_formats: &[],
        },
        wgpu::util::TextureDataOrder::LayerMajor,
        data,
    )
}

fn texel_bytes(t: weft_meta::TextureDefault) -> [u8; 4] {
    t.texel().map(|c| (c * 255.0).round() as u8)
}

fn texture_2d(gpu: &Gpu, label: &str, t: &TextureValue, srgb: bool) -> Result<wgpu::Texture> {
    Ok(match t {
        TextureValue::Builtin(d) => rgba8_texture(gpu, label, 1, 1, 1, &texel_bytes(*d), srgb),
        TextureValue::Rgba8 {
            width,
            height,
            data,
        } => rgba8_texture(gpu, label, *width, *height, 1, data, srgb),
        TextureValue::CubeRgbaF32 { .. } => {
            return Err(Error::InvalidValue {
                name: label.into(),
                message: "a cube cannot be bound to a 2D texture".into(),
            });
        }
    })
}

fn cube_texture(gpu: &Gpu, label: &str, t: &TextureValue, srgb: bool) -> Result<wgpu::Texture> {
    Ok(match t {
        TextureValue::Builtin(d) => {
            let face = texel_bytes(*d);
            let data: Vec<u8> = (0..6).flat_map(|_| face).collect();
            rgba8_texture(gpu, label, 1, 1, 6, &data, srgb)
        }
        TextureValue::CubeRgbaF32 { size, data } => {
            let bytes: Vec<u8> = data
                .iter()
                .flatten()
                .flat_map(|c| half::f16::from_f32(*c).to_le_bytes())
                .collect();
            gpu.device.create_texture_with_data(
                &gpu.queue,
                &wgpu::TextureDescriptor {
                    label: Some(label),
                    size: wgpu::Extent3d {
                        width: *size,
                        height: *size,
                        depth_or_array_layers: 6,
                    },
                    mip_level_count: 1,
                    sample_count: 1,
                    dimension: wgpu::TextureDimension::D2,
                    format: wgpu::TextureFormat::Rgba16Float,
                    usage: wgpu::TextureUsages::TEXTURE_BINDING,
                    view_formats: &[],
                },
                wgpu::util::TextureDataOrder::LayerMajor,
                &bytes,
            )
        }
        TextureValue::Rgba8 { .. } => {
            return Err(Error::InvalidValue {
                name: label.into(),
                message: "a 2D texture cannot be bound to a cube".into(),
            });
        }
    })
}
