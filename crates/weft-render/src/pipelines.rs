//! Shader modules, bind group layouts, vertex layouts and render pipelines
//! built from a `VariantShader` (a library variant's or a scene shader's)
//! and the pipeline state its passes state (`primitive`, `color_targets`,
//! `depth`; converted in `meta_wgpu.rs`). Nothing here knows where the
//! shader's values come from.

use crate::error::{Error, Result, io_err};
use crate::gpu::Gpu;
use crate::meta_wgpu::{
    binding_layout_entry, color_target_state, depth_stencil_state, primitive_state,
};
use crate::targets::{ColorFormat, DEPTH_FORMAT, ShaderLanguage};
use std::collections::BTreeMap;
use std::path::Path;
use weft_meta::{BindingKind, Pass, VariantShader, VertexInput};

/// Which shader to build pipelines from, and how.
pub(crate) struct ShaderInput<'a> {
    /// The variant id or scene shader id (labels, error messages).
    pub label: &'a str,
    /// Folder the shader's file paths are relative to.
    pub dir: &'a Path,
    pub shader: &'a VariantShader,
    /// Draw a half-precision shader's f32 files even when the device has `shader-f16`.
    pub f32_fallback: bool,
    /// `RenderOptions::uniforms_as_storage` (WGSL only).
    pub uniforms_as_storage: bool,
    /// `Some`: this SPIR-V file (relative to `dir`); `None`: the WGSL file.
    pub spirv_file: Option<String>,
    /// Values of the WGSL `override`s.
    pub constants: Vec<(String, f64)>,
    /// Identifies the module's contents for the pipeline cache (the
    /// language, format, constants and passes are added to it).
    pub cache_id: String,
}

impl ShaderInput<'_> {
    pub fn language(&self) -> ShaderLanguage {
        match self.spirv_file {
            Some(_) => ShaderLanguage::SpirV,
            None => ShaderLanguage::Wgsl,
        }
    }
}

pub(crate) struct PassPipeline {
    pub pass: Pass,
    pub pipeline: wgpu::RenderPipeline,
}

/// Pipelines (one per pass, in the order given) and layouts of one shader
/// for one language, format and set of constants.
pub(crate) struct VariantPipelines {
    pub layouts: Vec<Option<wgpu::BindGroupLayout>>,
    pub passes: Vec<PassPipeline>,
    pub vertex_inputs: Vec<VertexInput>,
}

/// Whether to draw the shader's half-precision files (`f16_files`): when it
/// has them, the device has `shader-f16` and the f32 files were not asked for.
fn draws_f16(gpu: &Gpu, input: &ShaderInput) -> bool {
    !input.shader.f16_files.is_empty() && !input.f32_fallback && gpu.has_shader_f16()
}

/// The shader source of `input`: the WGSL text, or the SPIR-V module read
/// through naga with weft's Vulkan y flip undone; from the half-precision
/// files when [`draws_f16`].
fn shader_source(gpu: &Gpu, input: &ShaderInput) -> Result<wgpu::ShaderSource<'static>> {
    let f16 = draws_f16(gpu, input);
    let files = |lang: &str| {
        let listed = match f16 {
            true => input.shader.f16_files.get(lang),
            false => input.shader.files.get(lang),
        };
        listed.ok_or_else(|| {
            Error::Metadata(format!(
                "variant `{}` lists no {}{lang} file",
                input.label,
                if f16 { "f16 " } else { "" }
            ))
        })
    };
    let spirv_file = match (&input.spirv_file, f16) {
        (Some(rel), true) => {
            // The f16 file with the same baked constants.
            let constants = input
                .shader
                .files
                .get("spirv")
                .and_then(|l| l.iter().find(|f| &f.path == rel))
                .map(|f| &f.constants);
            let f = files("spirv")?
                .iter()
                .find(|f| Some(&f.constants) == constants)
                .ok_or_else(|| {
                    Error::Metadata(format!(
                        "variant `{}`: no f16 file for `{rel}`",
                        input.label
                    ))
                })?;
            Some(f.path.clone())
        }
        (other, _) => other.clone(),
    };
    Ok(match &spirv_file {
        None => {
            let rel = &files("wgsl")?
                .first()
                .ok_or_else(|| {
                    Error::Metadata(format!("variant `{}` lists no WGSL file", input.label))
                })?
                .path;
            let path = input.dir.join(rel);
            let mut text =
                weft_meta::files::read_regular_string(&path, weft_meta::files::MAX_TEXT_BYTES)
                    .map_err(io_err(&path))?;
            if input.uniforms_as_storage {
                text = text.replace("var<uniform>", "var<storage, read>");
            }
            wgpu::ShaderSource::Wgsl(text.into())
        }
        Some(rel) => {
            let path = input.dir.join(rel);
            let bytes = weft_meta::files::read_regular(&path, weft_meta::files::MAX_BINARY_BYTES)
                .map_err(io_err(&path))?;
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
            let module = wgpu::naga::front::spv::parse_u8_slice(&bytes, &options).map_err(|e| {
                Error::Gpu(format!("{}: SPIR-V does not parse: {e}", path.display()))
            })?;
            wgpu::ShaderSource::Naga(std::borrow::Cow::Owned(module))
        }
    })
}

pub(crate) fn build_pipelines(
    gpu: &Gpu,
    input: &ShaderInput,
    passes: &[Pass],
    format: ColorFormat,
) -> Result<VariantPipelines> {
    let device = &gpu.device;
    let (shader, label) = (input.shader, input.label);
    let source = shader_source(gpu, input)?;
    let module = gpu.checked(&format!("shader module of `{label}`"), || {
        device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(label),
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
                .map(|b| {
                    let entry = binding_layout_entry(b)?;
                    Ok(
                        match input.uniforms_as_storage && input.spirv_file.is_none() {
                            true => uniform_as_storage(entry),
                            false => entry,
                        },
                    )
                })
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
        label: Some(label),
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

    let constant_refs: Vec<(&str, f64)> = input
        .constants
        .iter()
        .map(|(k, v)| (k.as_str(), *v))
        .collect();
    let mut out = Vec::new();
    for pass in passes {
        let primitive = primitive_state(pass);
        let depth_stencil = depth_stencil_state(pass)?;
        let target = color_target_state(pass, format)?;
        let pipeline = gpu.checked(
            &format!("pipeline of pass `{}` of `{label}`", pass.name),
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
                    primitive,
                    depth_stencil: Some(depth_stencil),
                    multisample: Default::default(),
                    fragment: Some(wgpu::FragmentState {
                        module: &module,
                        entry_point: Some(&pass.fragment_entry),
                        compilation_options: wgpu::PipelineCompilationOptions {
                            constants: &constant_refs,
                            ..Default::default()
                        },
                        targets: &[Some(target)],
                    }),
                    multiview_mask: None,
                    cache: None,
                })
            },
        )?;
        out.push(PassPipeline {
            pass: pass.clone(),
            pipeline,
        });
    }
    Ok(VariantPipelines {
        layouts,
        passes: out,
        vertex_inputs: shader.vertex_inputs.clone(),
    })
}

pub(crate) fn build_sky_pipeline(
    gpu: &Gpu,
    sky_layout: &wgpu::BindGroupLayout,
    sky_module: &wgpu::ShaderModule,
    format: ColorFormat,
) -> Result<wgpu::RenderPipeline> {
    let device = &gpu.device;
    gpu.checked("sky pipeline", || {
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("weft sky"),
            bind_group_layouts: &[Some(sky_layout)],
            immediate_size: 0,
        });
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("weft sky"),
            layout: Some(&layout),
            vertex: wgpu::VertexState {
                module: sky_module,
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
                module: sky_module,
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

/// The SPIR-V file whose baked constants equal `keywords`' values.
pub(crate) fn spirv_file_for(
    shader: &VariantShader,
    id: &str,
    keywords: &BTreeMap<String, String>,
) -> Result<String> {
    let files = shader
        .files
        .get("spirv")
        .ok_or_else(|| Error::Metadata(format!("variant `{id}` lists no SPIR-V file")))?;
    files
        .iter()
        .find(|f| f.constants.iter().all(|(k, v)| keywords.get(k) == Some(v)))
        .map(|f| f.path.clone())
        .ok_or_else(|| {
            Error::Metadata(format!(
                "variant `{id}` has no SPIR-V file for keywords {keywords:?}"
            ))
        })
}

/// A uniform-buffer layout entry as a read-only storage buffer
/// (`RenderOptions::uniforms_as_storage`); other entries unchanged.
fn uniform_as_storage(mut entry: wgpu::BindGroupLayoutEntry) -> wgpu::BindGroupLayoutEntry {
    if let wgpu::BindingType::Buffer {
        ty: ty @ wgpu::BufferBindingType::Uniform,
        ..
    } = &mut entry.ty
    {
        *ty = wgpu::BufferBindingType::Storage { read_only: true };
    }
    entry
}

/// A layout entry from a binding kind alone: only for weft-render's own
/// sky pipeline (variants' entries come from their metadata:
/// `meta_wgpu::binding_layout_entry`).
pub(crate) fn kind_layout_entry(
    binding: u32,
    visibility: wgpu::ShaderStages,
    kind: BindingKind,
) -> Result<wgpu::BindGroupLayoutEntry> {
    let ty = match kind {
        BindingKind::UniformBuffer => wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        BindingKind::Sampler => wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
        BindingKind::TextureCube => wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: true },
            view_dimension: wgpu::TextureViewDimension::Cube,
            multisampled: false,
        },
        other => {
            return Err(Error::Metadata(format!(
                "the sky pipeline does not bind a {other:?}"
            )));
        }
    };
    Ok(wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty,
        count: None,
    })
}

/// WebGPU vertex format names (the float formats the engine interface uses).
pub(crate) fn vertex_format(name: &str) -> Result<wgpu::VertexFormat> {
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
