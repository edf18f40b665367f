//! Bind group layouts, pipeline layouts and render pipelines from a
//! shader's `bindings[]`, `vertex_inputs` and its passes' `primitive`,
//! `color_targets` and `depth_stencil`, for the WGSL file or (through wgpu's
//! passthrough path) the SPIR-V file.

use super::device::Engine;
use super::formats;
use super::library::ShaderRef;
use std::num::NonZeroU64;
use weft_meta::{BufferBindingType, FrontFace, LanguageConventions, Pass, VariantShader};

/// Which emitted file to draw and how to orient it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Language {
    /// The WGSL file, `constant`-mode keywords as pipeline constants
    /// (`default_value`, bools as 0/1).
    Wgsl,
    /// The SPIR-V file whose baked `constants` are the keywords' defaults,
    /// given to the Vulkan driver untouched. wgpu maps WebGPU's y-up clip
    /// space to Vulkan with a negative viewport height, so y is flipped a
    /// second time; `undo_layer_flip` draws with the front face and row
    /// order that follow from `languages.spirv` and that flip. Without it the
    /// passes keep their WGSL front face and only the rows are reversed
    /// (the wrong way, for the negative test).
    SpirvPassthrough { undo_layer_flip: bool },
}

/// The front face and row order to draw one language with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orientation {
    /// Whether the pass's WGSL front face is to be inverted.
    pub invert_front_face: bool,
    /// Whether row 0 of the target is the bottom of the picture.
    pub bottom_row_first: bool,
}

fn conventions<'a>(
    languages: Option<&'a std::collections::BTreeMap<String, LanguageConventions>>,
    lang: &str,
) -> Result<&'a LanguageConventions, String> {
    languages
        .and_then(|l| l.get(lang))
        .ok_or_else(|| format!("the metadata states no `languages.{lang}` conventions"))
}

impl Language {
    pub fn orientation(
        self,
        languages: Option<&std::collections::BTreeMap<String, LanguageConventions>>,
    ) -> Result<Orientation, String> {
        match self {
            // WebGPU is the convention the metadata is stated in.
            Language::Wgsl => Ok(Orientation {
                invert_front_face: false,
                bottom_row_first: false,
            }),
            Language::SpirvPassthrough { undo_layer_flip } => {
                let wgsl = conventions(languages, "wgsl")?;
                let spirv = conventions(languages, "spirv")?;
                // Native Vulkan (positive viewport height) wants
                // `spirv.front_face` and gives `spirv.top_row_first`; the
                // layer's y flip mirrors the picture vertically, which
                // reverses both the winding and the rows.
                let native_inverts = spirv.front_face != wgsl.front_face;
                Ok(if undo_layer_flip {
                    Orientation {
                        invert_front_face: !native_inverts,
                        bottom_row_first: spirv.top_row_first,
                    }
                } else {
                    Orientation {
                        invert_front_face: false,
                        bottom_row_first: true,
                    }
                })
            }
        }
    }
}

pub struct PassPipeline {
    pub pass: Pass,
    pub pipeline: wgpu::RenderPipeline,
}

/// Layouts and one pipeline per pass (in `passes` order) of one shader.
pub struct Pipelines {
    /// Groups 0..=max; a group with no bindings gets an empty layout.
    pub layouts: Vec<wgpu::BindGroupLayout>,
    pub passes: Vec<PassPipeline>,
    pub orientation: Orientation,
    /// The colour target's format (the same for every pass).
    pub color_format: wgpu::TextureFormat,
    /// (group, binding) of placeholder sampler entries (SPIR-V only, see
    /// [`build`]): bind any sampler there.
    pub placeholders: Vec<(u32, u32)>,
}

fn layout_entry(b: &weft_meta::Binding) -> Result<wgpu::BindGroupLayoutEntry, String> {
    let ty = match (&b.buffer, &b.texture, &b.sampler) {
        (Some(buf), None, None) => wgpu::BindingType::Buffer {
            ty: match buf.ty {
                BufferBindingType::Uniform => wgpu::BufferBindingType::Uniform,
                BufferBindingType::ReadOnlyStorage => {
                    wgpu::BufferBindingType::Storage { read_only: true }
                }
                BufferBindingType::Storage => wgpu::BufferBindingType::Storage { read_only: false },
            },
            has_dynamic_offset: buf.has_dynamic_offset,
            min_binding_size: NonZeroU64::new(buf.min_binding_size),
        },
        (None, Some(t), None) => wgpu::BindingType::Texture {
            sample_type: formats::sample_type(t.sample_type),
            view_dimension: formats::view_dimension(t.view_dimension),
            multisampled: t.multisampled,
        },
        (None, None, Some(s)) => {
            wgpu::BindingType::Sampler(formats::sampler_binding_type(s.binding_type))
        }
        _ => {
            return Err(format!(
                "binding `{}` (group {}, binding {}) must have exactly one of \
                 `buffer`, `texture` and `sampler`",
                b.name, b.group, b.binding
            ));
        }
    };
    Ok(wgpu::BindGroupLayoutEntry {
        binding: b.binding,
        visibility: formats::stages(&b.stages),
        ty,
        count: None,
    })
}

/// Reads a file of the shader (path relative to its metadata's folder).
fn read(dir: &std::path::Path, rel: &str) -> Result<Vec<u8>, String> {
    let path = dir.join(rel);
    std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))
}

/// The SPIR-V file whose `constants` are the default value of every
/// `constant`-mode keyword (`pipeline_constants[].default`).
pub fn default_spirv_file(shader: &VariantShader) -> Result<&weft_meta::ShaderFile, String> {
    let files = shader
        .files
        .get("spirv")
        .ok_or("the shader lists no SPIR-V file")?;
    let matching: Vec<_> = files
        .iter()
        .filter(|f| {
            f.constants.len() == shader.pipeline_constants.len()
                && f.constants.iter().all(|(k, v)| {
                    shader
                        .pipeline_constants
                        .iter()
                        .any(|c| &c.name == k && &c.default == v)
                })
        })
        .collect();
    match matching.as_slice() {
        [one] => Ok(one),
        other => Err(format!(
            "{} SPIR-V files have the default constants (want exactly one)",
            other.len()
        )),
    }
}

fn pipeline_constants(shader: &VariantShader) -> Result<Vec<(String, f64)>, String> {
    shader
        .pipeline_constants
        .iter()
        .map(|c| {
            let v = match &c.default_value {
                serde_json::Value::Bool(b) => f64::from(u8::from(*b)),
                serde_json::Value::Number(n) => n.as_f64().unwrap(),
                other => {
                    return Err(format!(
                        "pipeline constant `{}`: default_value `{other}`",
                        c.name
                    ));
                }
            };
            Ok((c.name.clone(), v))
        })
        .collect()
}

fn shader_module(
    engine: &Engine,
    s: &ShaderRef,
    language: Language,
) -> Result<wgpu::ShaderModule, String> {
    let shader = s.shader;
    match language {
        Language::Wgsl => {
            let file = shader
                .files
                .get("wgsl")
                .and_then(|f| f.first())
                .ok_or("the shader lists no WGSL file")?;
            let text = String::from_utf8(read(&s.dir, &file.path)?)
                .map_err(|e| format!("{}: {e}", file.path))?;
            engine.checked(&format!("WGSL module of {}", s.label), || {
                engine
                    .device
                    .create_shader_module(wgpu::ShaderModuleDescriptor {
                        label: Some(&s.label),
                        source: wgpu::ShaderSource::Wgsl(text.into()),
                    })
            })
        }
        Language::SpirvPassthrough { .. } => {
            let file = default_spirv_file(shader)?;
            let bytes = read(&s.dir, &file.path)?;
            if bytes.len() % 4 != 0 || bytes.len() < 20 {
                return Err(format!("{}: not a SPIR-V module", file.path));
            }
            let words: Vec<u32> = bytes
                .chunks_exact(4)
                .map(|w| u32::from_le_bytes([w[0], w[1], w[2], w[3]]))
                .collect();
            if words[0] != 0x0723_0203 {
                return Err(format!("{}: no SPIR-V magic number", file.path));
            }
            let entry_points: Vec<wgpu::PassthroughShaderEntryPoint> = shader
                .entry_points
                .iter()
                .map(|e| wgpu::PassthroughShaderEntryPoint {
                    name: e.name.clone().into(),
                    workgroup_size: (0, 0, 0),
                })
                .collect();
            engine.checked(&format!("SPIR-V module of {}", s.label), || unsafe {
                engine.device.create_shader_module_passthrough(
                    wgpu::ShaderModuleDescriptorPassthrough {
                        label: Some(&s.label),
                        entry_points: entry_points.into(),
                        spirv: Some(words.into()),
                        ..Default::default()
                    },
                )
            })
        }
    }
}

/// Builds the layouts and every pass's pipeline of `s`.
pub fn build(engine: &Engine, s: &ShaderRef, language: Language) -> Result<Pipelines, String> {
    let shader = s.shader;
    let device = &engine.device;
    let orientation = language.orientation(s.languages)?;
    let module = shader_module(engine, s, language)?;

    let max_group = shader.bindings.iter().map(|b| b.group).max();
    let mut layouts = Vec::new();
    let mut placeholders = Vec::new();
    for g in 0..max_group.map_or(0, |m| m + 1) {
        let mut entries = shader
            .bindings
            .iter()
            .filter(|b| b.group == g)
            .map(layout_entry)
            .collect::<Result<Vec<_>, _>>()?;
        if let Language::SpirvPassthrough { .. } = language {
            // wgpu's Vulkan backend numbers each set's descriptors 0, 1, …
            // in binding order and rewrites the bindings of the SPIR-V it
            // generates itself to match; a passthrough module is not
            // rewritten. For its `binding = N` to reach the WGSL binding N,
            // every number below the group's largest is given an entry: the
            // gaps get placeholder samplers the shader never reads.
            let max = entries.iter().map(|e| e.binding).max().unwrap_or(0);
            for n in 0..max {
                if !entries.iter().any(|e| e.binding == n) {
                    entries.push(wgpu::BindGroupLayoutEntry {
                        binding: n,
                        visibility: wgpu::ShaderStages::FRAGMENT,
                        ty: wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
                        count: None,
                    });
                    placeholders.push((g, n));
                }
            }
        }
        layouts.push(
            engine.checked(&format!("group {g} layout of {}", s.label), || {
                device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                    label: Some(&format!("{} group {g}", s.label)),
                    entries: &entries,
                })
            })?,
        );
    }
    let layout_refs: Vec<Option<&wgpu::BindGroupLayout>> = layouts.iter().map(Some).collect();
    let pipeline_layout = engine.checked(&format!("pipeline layout of {}", s.label), || {
        device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(&s.label),
            bind_group_layouts: &layout_refs,
            immediate_size: 0,
        })
    })?;

    // One vertex buffer per input, slot = index in `vertex_inputs`.
    let attributes = shader
        .vertex_inputs
        .iter()
        .map(|vi| {
            Ok([wgpu::VertexAttribute {
                format: formats::vertex_format(&vi.format)?,
                offset: 0,
                shader_location: vi.location,
            }])
        })
        .collect::<Result<Vec<_>, String>>()?;
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

    let constants = match language {
        Language::Wgsl => pipeline_constants(shader)?,
        Language::SpirvPassthrough { .. } => Vec::new(),
    };
    let constant_refs: Vec<(&str, f64)> = constants.iter().map(|(k, v)| (k.as_str(), *v)).collect();
    let options = wgpu::PipelineCompilationOptions {
        constants: &constant_refs,
        ..Default::default()
    };

    let mut passes = Vec::new();
    let mut color_format = None;
    for pass in s.passes {
        for ep in [&pass.vertex_entry, &pass.fragment_entry] {
            if !shader.entry_points.iter().any(|e| &e.name == ep) {
                return Err(format!("pass `{}`: no entry point `{ep}`", pass.name));
            }
        }
        let weft_meta::PrimitiveTopology::TriangleList = pass.primitive.topology;
        let front = match (pass.primitive.front_face, orientation.invert_front_face) {
            (f, false) => f,
            (FrontFace::Ccw, true) => FrontFace::Cw,
            (FrontFace::Cw, true) => FrontFace::Ccw,
        };
        let mut targets: Vec<Option<wgpu::ColorTargetState>> = Vec::new();
        let [t] = pass.color_targets.as_slice() else {
            return Err(format!("pass `{}`: one colour target expected", pass.name));
        };
        let format = formats::texture_format(&t.format)?;
        if *color_format.get_or_insert(format) != format {
            return Err("passes draw into different colour formats".into());
        }
        {
            let at = t.location as usize;
            if targets.len() <= at {
                targets.resize(at + 1, None);
            }
            targets[at] = Some(wgpu::ColorTargetState {
                format,
                blend: t.blend.as_ref().map(formats::blend),
                write_mask: formats::write_mask(&t.write_mask),
            });
        }
        let depth_stencil = Some(formats::depth_stencil(&pass.depth_stencil)?);
        let pipeline = engine.checked(
            &format!("pipeline of pass `{}` of {}", pass.name, s.label),
            || {
                device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                    label: Some(&pass.name),
                    layout: Some(&pipeline_layout),
                    vertex: wgpu::VertexState {
                        module: &module,
                        entry_point: Some(&pass.vertex_entry),
                        compilation_options: options.clone(),
                        buffers: &buffers,
                    },
                    primitive: wgpu::PrimitiveState {
                        topology: wgpu::PrimitiveTopology::TriangleList,
                        front_face: formats::front_face(front),
                        cull_mode: formats::cull(pass.primitive.cull_mode),
                        ..Default::default()
                    },
                    depth_stencil,
                    multisample: Default::default(),
                    fragment: Some(wgpu::FragmentState {
                        module: &module,
                        entry_point: Some(&pass.fragment_entry),
                        compilation_options: options.clone(),
                        targets: &targets,
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
    Ok(Pipelines {
        layouts,
        passes,
        orientation,
        color_format: color_format.ok_or("no pass")?,
        placeholders,
    })
}
