//! Building one pipeline exactly as the metadata describes it (bind group
//! layouts, vertex buffers, colour targets and blend, depth-stencil, cull)
//! on the null device, and reading the driver's statistics of each executable.

use crate::device::{NullDevice, cstr};
use crate::error::{Error, Result, vk_err};
use crate::jobs::{Job, read_spirv};
use crate::record::{PipelineStats, StageStats, StatValue, Statistic};
use crate::state;
use ash::vk;
use std::ffi::CString;

/// Vulkan objects of one compile, destroyed together on drop (also on an error half-way).
struct Objects<'d> {
    device: &'d ash::Device,
    set_layouts: Vec<vk::DescriptorSetLayout>,
    layout: vk::PipelineLayout,
    module: vk::ShaderModule,
    pipeline: vk::Pipeline,
}

impl Drop for Objects<'_> {
    fn drop(&mut self) {
        // SAFETY: every handle was created from `device` (or is null, which destroy
        // ignores) and nothing uses them: the null device never submits work.
        unsafe {
            self.device.destroy_pipeline(self.pipeline, None);
            self.device.destroy_shader_module(self.module, None);
            self.device.destroy_pipeline_layout(self.layout, None);
            for l in &self.set_layouts {
                self.device.destroy_descriptor_set_layout(*l, None);
            }
        }
    }
}

/// Compiles `job` on `dev` and returns the figures of each executable.
pub fn compile(
    dev: &NullDevice,
    family: &str,
    job: &Job,
    disassembly: bool,
) -> Result<PipelineStats> {
    let what = format!("{} pass `{}` ({})", job.source.spirv, job.pass.name, family);
    let words = read_spirv(&job.spirv_path)?;
    let mut objects = Objects {
        device: &dev.device,
        set_layouts: Vec::new(),
        layout: vk::PipelineLayout::null(),
        module: vk::ShaderModule::null(),
        pipeline: vk::Pipeline::null(),
    };
    create_layout(&mut objects, job, &what)?;
    let module_info = vk::ShaderModuleCreateInfo::default().code(&words);
    // SAFETY: `words` is a whole SPIR-V module (checked magic and size) alive across the call.
    objects.module = unsafe { dev.device.create_shader_module(&module_info, None) }
        .map_err(vk_err(format!("shader module of {what}")))?;
    objects.pipeline = create_pipeline(&objects, job, disassembly, &what)?;
    let stages = read_statistics(dev, objects.pipeline, disassembly, &what)?;
    Ok(PipelineStats {
        family: family.into(),
        source: job.source.clone(),
        pass: job.pass.name.clone(),
        stages,
    })
}

/// One descriptor set layout per group 0..=max (empty for a gap, as WebGPU's
/// implementations do), then the pipeline layout.
fn create_layout(objects: &mut Objects<'_>, job: &Job, what: &str) -> Result<()> {
    let bindings = &job.shader.bindings;
    let groups = bindings.iter().map(|b| b.group + 1).max().unwrap_or(0);
    for g in 0..groups {
        let entries: Vec<vk::DescriptorSetLayoutBinding> = bindings
            .iter()
            .filter(|b| b.group == g)
            .map(|b| {
                let dynamic = b.buffer.as_ref().is_some_and(|x| x.has_dynamic_offset);
                vk::DescriptorSetLayoutBinding::default()
                    .binding(b.binding)
                    .descriptor_type(state::descriptor_type(b.kind, dynamic))
                    .descriptor_count(1)
                    .stage_flags(state::stage_flags(&b.stages))
            })
            .collect();
        let info = vk::DescriptorSetLayoutCreateInfo::default().bindings(&entries);
        // SAFETY: `info` and `entries` live across the call.
        let l = unsafe { objects.device.create_descriptor_set_layout(&info, None) }
            .map_err(vk_err(format!("bind group layout {g} of {what}")))?;
        objects.set_layouts.push(l);
    }
    let info = vk::PipelineLayoutCreateInfo::default().set_layouts(&objects.set_layouts);
    // SAFETY: the set layouts are live.
    objects.layout = unsafe { objects.device.create_pipeline_layout(&info, None) }
        .map_err(vk_err(format!("pipeline layout of {what}")))?;
    Ok(())
}

fn create_pipeline(
    objects: &Objects<'_>,
    job: &Job,
    disassembly: bool,
    what: &str,
) -> Result<vk::Pipeline> {
    let pass = &job.pass;
    let vs_name = entry_name(&pass.vertex_entry)?;
    let fs_name = entry_name(&pass.fragment_entry)?;
    let stages = [
        vk::PipelineShaderStageCreateInfo::default()
            .stage(vk::ShaderStageFlags::VERTEX)
            .module(objects.module)
            .name(&vs_name),
        vk::PipelineShaderStageCreateInfo::default()
            .stage(vk::ShaderStageFlags::FRAGMENT)
            .module(objects.module)
            .name(&fs_name),
    ];
    // One vertex buffer per input, slot = position in the list (as weft-render binds them).
    let mut vbufs = Vec::new();
    let mut attrs = Vec::new();
    for (slot, vi) in job.shader.vertex_inputs.iter().enumerate() {
        let (format, size) = state::vertex_format(&vi.format)?;
        vbufs.push(vk::VertexInputBindingDescription {
            binding: slot as u32,
            stride: size,
            input_rate: vk::VertexInputRate::VERTEX,
        });
        attrs.push(vk::VertexInputAttributeDescription {
            location: vi.location,
            binding: slot as u32,
            format,
            offset: 0,
        });
    }
    let vertex_input = vk::PipelineVertexInputStateCreateInfo::default()
        .vertex_binding_descriptions(&vbufs)
        .vertex_attribute_descriptions(&attrs);
    let assembly = vk::PipelineInputAssemblyStateCreateInfo::default()
        .topology(vk::PrimitiveTopology::TRIANGLE_LIST);
    let viewport = vk::PipelineViewportStateCreateInfo::default()
        .viewport_count(1)
        .scissor_count(1);
    let raster = vk::PipelineRasterizationStateCreateInfo::default()
        .polygon_mode(vk::PolygonMode::FILL)
        .cull_mode(state::cull_mode(pass.primitive.cull_mode))
        .front_face(state::front_face(pass.primitive.front_face))
        .line_width(1.0);
    let multisample = vk::PipelineMultisampleStateCreateInfo::default()
        .rasterization_samples(vk::SampleCountFlags::TYPE_1);
    let ds = &pass.depth_stencil;
    let ds_format = state::depth_stencil_format(&ds.format)?;
    let stencil_on = state::has_stencil(ds_format);
    let depth_stencil = vk::PipelineDepthStencilStateCreateInfo::default()
        .depth_test_enable(true)
        .depth_write_enable(ds.depth_write_enabled)
        .depth_compare_op(state::compare_op(ds.depth_compare))
        .stencil_test_enable(stencil_on && stencil_used(ds))
        .front(state::stencil_face(
            &ds.stencil_front,
            ds.stencil_read_mask,
            ds.stencil_write_mask,
        ))
        .back(state::stencil_face(
            &ds.stencil_back,
            ds.stencil_read_mask,
            ds.stencil_write_mask,
        ));
    let (formats, blends) = color_targets(pass)?;
    let blend = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blends);
    // What WebGPU sets while drawing rather than in the pipeline.
    let dynamic_states = [
        vk::DynamicState::VIEWPORT,
        vk::DynamicState::SCISSOR,
        vk::DynamicState::BLEND_CONSTANTS,
        vk::DynamicState::STENCIL_REFERENCE,
    ];
    let dynamic = vk::PipelineDynamicStateCreateInfo::default().dynamic_states(&dynamic_states);
    let mut rendering = vk::PipelineRenderingCreateInfo::default()
        .color_attachment_formats(&formats)
        .depth_attachment_format(ds_format)
        .stencil_attachment_format(if stencil_on {
            ds_format
        } else {
            vk::Format::UNDEFINED
        });
    let mut flags = vk::PipelineCreateFlags::CAPTURE_STATISTICS_KHR;
    if disassembly {
        flags |= vk::PipelineCreateFlags::CAPTURE_INTERNAL_REPRESENTATIONS_KHR;
    }
    let info = vk::GraphicsPipelineCreateInfo::default()
        .flags(flags)
        .stages(&stages)
        .vertex_input_state(&vertex_input)
        .input_assembly_state(&assembly)
        .viewport_state(&viewport)
        .rasterization_state(&raster)
        .multisample_state(&multisample)
        .depth_stencil_state(&depth_stencil)
        .color_blend_state(&blend)
        .dynamic_state(&dynamic)
        .layout(objects.layout)
        .push_next(&mut rendering);
    // SAFETY: every struct `info` points to lives until the call returns; the layout
    // and module are live.
    let made = unsafe {
        objects
            .device
            .create_graphics_pipelines(vk::PipelineCache::null(), &[info], None)
    };
    match made {
        Ok(p) => Ok(p[0]),
        Err((_, result)) => Err(Error::Vulkan {
            what: format!("compiling {what}"),
            result,
        }),
    }
}

/// Whether the pass tests or writes the stencil at all (else the test stays off,
/// as WebGPU implementations do for `always`/`keep` with no writes).
fn stencil_used(ds: &weft_meta::pipeline::DepthStencilState) -> bool {
    use weft_meta::{DepthTest, StencilOperation as Op};
    let face_used = |f: &weft_meta::pipeline::StencilFaceState| {
        f.compare != DepthTest::Always
            || [f.fail_op, f.depth_fail_op, f.pass_op]
                .iter()
                .any(|o| *o != Op::Keep)
    };
    face_used(&ds.stencil_front) || face_used(&ds.stencil_back)
}

/// Attachment formats and blend states by location (a gap is an unused attachment).
fn color_targets(
    pass: &weft_meta::Pass,
) -> Result<(Vec<vk::Format>, Vec<vk::PipelineColorBlendAttachmentState>)> {
    let count = pass
        .color_targets
        .iter()
        .map(|t| t.location + 1)
        .max()
        .unwrap_or(0) as usize;
    let mut formats = vec![vk::Format::UNDEFINED; count];
    let mut blends = vec![vk::PipelineColorBlendAttachmentState::default(); count];
    for t in &pass.color_targets {
        let i = t.location as usize;
        formats[i] = state::color_format(&t.format)?;
        let mut b = vk::PipelineColorBlendAttachmentState::default()
            .color_write_mask(state::write_mask(&t.write_mask));
        if let Some(s) = &t.blend {
            b = b
                .blend_enable(true)
                .src_color_blend_factor(state::blend_factor(s.color.src_factor))
                .dst_color_blend_factor(state::blend_factor(s.color.dst_factor))
                .color_blend_op(state::blend_op(s.color.operation))
                .src_alpha_blend_factor(state::blend_factor(s.alpha.src_factor))
                .dst_alpha_blend_factor(state::blend_factor(s.alpha.dst_factor))
                .alpha_blend_op(state::blend_op(s.alpha.operation));
        }
        blends[i] = b;
    }
    Ok((formats, blends))
}

fn entry_name(name: &str) -> Result<CString> {
    CString::new(name).map_err(|_| Error::Input(format!("entry point `{name}` holds a NUL")))
}

/// Every executable's statistics (and disassembly when captured).
fn read_statistics(
    dev: &NullDevice,
    pipeline: vk::Pipeline,
    disassembly: bool,
    what: &str,
) -> Result<Vec<StageStats>> {
    let info = vk::PipelineInfoKHR::default().pipeline(pipeline);
    // SAFETY: `pipeline` was created with CAPTURE_STATISTICS on a device with the extension.
    let executables = unsafe { dev.executables.get_pipeline_executable_properties(&info) }
        .map_err(vk_err(format!("executables of {what}")))?;
    let mut out = Vec::new();
    for (i, e) in executables.iter().enumerate() {
        let exe = vk::PipelineExecutableInfoKHR::default()
            .pipeline(pipeline)
            .executable_index(i as u32);
        // SAFETY: as above; `i` is below the executable count.
        let stats = unsafe { dev.executables.get_pipeline_executable_statistics(&exe) }
            .map_err(vk_err(format!("statistics of {what}")))?;
        let statistics = stats
            .iter()
            .map(|s| Statistic {
                name: cstr(&s.name),
                value: stat_value(s),
            })
            .collect();
        let disassembly = if disassembly {
            assembly_text(dev, &exe, what)?
        } else {
            None
        };
        out.push(StageStats {
            stage: stage_name(e.stages),
            executable: cstr(&e.name),
            subgroup_size: e.subgroup_size,
            statistics,
            disassembly,
        });
    }
    Ok(out)
}

fn stat_value(s: &vk::PipelineExecutableStatisticKHR<'_>) -> StatValue {
    // SAFETY: the driver sets `format` to say which member of the union it wrote.
    unsafe {
        match s.format {
            vk::PipelineExecutableStatisticFormatKHR::BOOL32 => StatValue::Bool(s.value.b32 != 0),
            vk::PipelineExecutableStatisticFormatKHR::INT64 => StatValue::Int(s.value.i64),
            vk::PipelineExecutableStatisticFormatKHR::FLOAT64 => StatValue::Float(s.value.f64),
            _ => StatValue::Uint(s.value.u64),
        }
    }
}

fn stage_name(stages: vk::ShaderStageFlags) -> String {
    let mut parts = Vec::new();
    for (flag, name) in [
        (vk::ShaderStageFlags::VERTEX, "vertex"),
        (vk::ShaderStageFlags::GEOMETRY, "geometry"),
        (vk::ShaderStageFlags::FRAGMENT, "fragment"),
        (vk::ShaderStageFlags::COMPUTE, "compute"),
    ] {
        if stages.contains(flag) {
            parts.push(name);
        }
    }
    if parts.is_empty() {
        format!("{stages:?}")
    } else {
        parts.join("+")
    }
}

/// The text of the executable's last internal representation (RADV: the ISA
/// `Assembly`), read with the two-call idiom (ash's helper reads no text).
fn assembly_text(
    dev: &NullDevice,
    exe: &vk::PipelineExecutableInfoKHR<'_>,
    what: &str,
) -> Result<Option<String>> {
    let f = dev
        .executables
        .fp()
        .get_pipeline_executable_internal_representations_khr;
    let handle = dev.device.handle();
    let mut count = 0u32;
    // SAFETY: querying the count with a null array is the documented first call.
    unsafe { f(handle, exe, &mut count, std::ptr::null_mut()) }
        .result()
        .map_err(vk_err(format!("internal representations of {what}")))?;
    let mut reps = vec![vk::PipelineExecutableInternalRepresentationKHR::default(); count as usize];
    // SAFETY: `reps` holds `count` structs with null data: the driver fills in the sizes.
    unsafe { f(handle, exe, &mut count, reps.as_mut_ptr()) }
        .result()
        .map_err(vk_err(format!("internal representations of {what}")))?;
    let mut buffers: Vec<Vec<u8>> = reps.iter().map(|r| vec![0u8; r.data_size]).collect();
    for (r, b) in reps.iter_mut().zip(buffers.iter_mut()) {
        r.p_data = b.as_mut_ptr().cast();
    }
    // SAFETY: each `p_data` points at `data_size` writable bytes that outlive the call.
    unsafe { f(handle, exe, &mut count, reps.as_mut_ptr()) }
        .result()
        .map_err(vk_err(format!("internal representations of {what}")))?;
    let pick = reps
        .iter()
        .zip(&buffers)
        .rev()
        .find(|(r, _)| cstr(&r.name).eq_ignore_ascii_case("assembly"))
        .or_else(|| reps.iter().zip(&buffers).next_back());
    Ok(pick.map(|(r, b)| {
        let text = if r.is_text == vk::TRUE {
            b.as_slice()
        } else {
            &[][..]
        };
        let end = text.iter().position(|c| *c == 0).unwrap_or(text.len());
        String::from_utf8_lossy(&text[..end]).into_owned()
    }))
}
