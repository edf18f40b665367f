//! Backends: one validated, specialised module -> WGSL, SPIR-V, HLSL, GLSL, MSL.
//!
//! Options are fixed here (never naga's build-profile-dependent defaults) so
//! bytes are identical in debug and release builds and on every machine.
//! The HLSL register mapping (`engine_binding::hlsl_options`) is documented
//! in docs/hlsl-registers.md.

use crate::compile::engine_binding::hlsl_options;
use naga::back::{glsl, hlsl, msl, spv, wgsl};
use naga::valid::ModuleInfo;
use naga::{Module, ShaderStage};

pub fn emit_wgsl(module: &Module, info: &ModuleInfo) -> Result<String, String> {
    wgsl::write_string(module, info, wgsl::WriterFlags::empty())
        .map_err(|e| format!("WGSL backend: {e}"))
}

/// Every language but WGSL needs the overrides resolved (naga has no SPIR-V
/// specialisation constants): the callers pass a module without overrides.
pub fn emit_spirv(module: &Module, info: &ModuleInfo) -> Result<Vec<u8>, String> {
    let options = spv::Options {
        lang_version: (1, 0),
        flags: spv::WriterFlags::ADJUST_COORDINATE_SPACE
            | spv::WriterFlags::LABEL_VARYINGS
            | spv::WriterFlags::CLAMP_FRAG_DEPTH,
        // No `StorageInputOutput16`: Vulkan's storageInputOutput16 is not
        // part of wgpu's shader-f16 and many desktop GPUs lack it. weft's
        // stage interfaces are f32; naga converts any f16 one.
        use_storage_input_output_16: false,
        ..spv::Options::default()
    };
    let words =
        spv::write_vec(module, info, &options, None).map_err(|e| format!("SPIR-V backend: {e}"))?;
    Ok(words.iter().flat_map(|w| w.to_le_bytes()).collect())
}

/// HLSL that DXC (HLSL 2021 and 2016), FXC SM 5.1 and Slang all accept:
/// vector selects become per-component helpers before naga writes the
/// module ([`crate::compile::hlsl_select`]), sampler-heap aliases become macros after
/// ([`crate::compile::hlsl_samplers`]). docs/engine-interface.md lists the compilers.
pub fn emit_hlsl(module: &Module, info: &ModuleInfo) -> Result<String, String> {
    let split = crate::compile::hlsl_select::split_vector_selects(module, info)
        .map(|m| {
            let info = crate::compile::compose::validator()
                .validate(&m)
                .map_err(|e| format!("HLSL: per-component selects do not validate: {e:?}"))?;
            Ok::<_, String>((m, info))
        })
        .transpose()?;
    let (module, info) = split.as_ref().map_or((module, info), |(m, i)| (m, i));
    // The structural check, on every variant of every build: naga writes a
    // vector-condition select as `c ? a : b`, which HLSL 2021 rejects.
    let left = crate::compile::hlsl_select::count_vector_selects(module, info);
    if left > 0 {
        return Err(format!(
            "HLSL: {left} vector-condition select(s) would be written as a ternary, \
             which DXC's default HLSL 2021 rejects"
        ));
    }
    let options = hlsl_options(module);
    let pipeline = hlsl::PipelineOptions { entry_point: None };
    let mut out = String::new();
    let mut w = hlsl::Writer::new(&mut out, &options, &pipeline);
    w.write(module, info, None)
        .map_err(|e| format!("HLSL backend: {e}"))?;
    crate::compile::hlsl_samplers::sampler_heap_macros(&out)
}

pub fn emit_msl(module: &Module, info: &ModuleInfo) -> Result<String, String> {
    // Explicit argument slots (engine_binding::msl_slots); a resource
    // without one is an error rather than naga's unbindable placeholder.
    let slots = crate::compile::engine_binding::msl_slots(module);
    let resources: msl::BindingMap = slots
        .iter()
        .map(|(rb, slot)| {
            let index = slot.index as u8;
            let target = match slot.kind {
                weft_meta::MslSlotKind::Buffer => msl::BindTarget {
                    buffer: Some(index),
                    ..Default::default()
                },
                weft_meta::MslSlotKind::Texture => msl::BindTarget {
                    texture: Some(index),
                    ..Default::default()
                },
                weft_meta::MslSlotKind::Sampler => msl::BindTarget {
                    sampler: Some(msl::BindSamplerTarget::Resource(index)),
                    ..Default::default()
                },
            };
            (*rb, target)
        })
        .collect();
    let per_entry_point_map = module
        .entry_points
        .iter()
        .map(|ep| {
            (
                ep.name.clone(),
                msl::EntryPointResources {
                    resources: resources.clone(),
                    ..Default::default()
                },
            )
        })
        .collect();
    let options = msl::Options {
        lang_version: (2, 1),
        per_entry_point_map,
        fake_missing_bindings: false,
        ..msl::Options::default()
    };
    let pipeline = msl::PipelineOptions::default();
    msl::write_string(module, info, &options, &pipeline)
        .map(|(s, _)| s)
        .map_err(|e| format!("MSL backend: {e}"))
}

/// One entry point as GLSL 4.50 with explicit binding points
/// (`engine_binding::glsl_binding_points`), and the table that maps them
/// back to the WGSL bindings.
pub fn emit_glsl(
    module: &Module,
    info: &ModuleInfo,
    entry: &str,
    stage: ShaderStage,
) -> Result<(String, weft_meta::GlslReflection), String> {
    let points = crate::compile::engine_binding::glsl_binding_points(module);
    let options = glsl::Options {
        version: glsl::Version::Desktop(450),
        // DRAW_PARAMETERS: `@builtin(instance_index)` (instanced passes such
        // as fur shells) becomes gl_InstanceID + gl_BaseInstanceARB
        // (GL_ARB_shader_draw_parameters, core in GL 4.6) instead of a
        // loose `uniform uint naga_vs_first_instance` that has no binding
        // point, no table entry and that glslang rejects. Shaders without
        // instance_index are unchanged.
        writer_flags: glsl::WriterFlags::ADJUST_COORDINATE_SPACE
            | glsl::WriterFlags::DRAW_PARAMETERS,
        binding_map: points.iter().map(|(rb, b)| (*rb, *b)).collect(),
        ..glsl::Options::default()
    };
    let pipeline = glsl::PipelineOptions {
        shader_stage: stage,
        entry_point: entry.to_string(),
        multiview: None,
    };
    let mut out = String::new();
    let mut w = glsl::Writer::new(
        &mut out,
        module,
        info,
        &options,
        &pipeline,
        naga::proc::BoundsCheckPolicies::default(),
    )
    .map_err(|e| format!("GLSL backend ({entry}): {e}"))?;
    let reflection = w
        .write()
        .map_err(|e| format!("GLSL backend ({entry}): {e}"))?;
    let binding_of = |h: naga::Handle<naga::GlobalVariable>| {
        module.global_variables[h]
            .binding
            .map(|rb| weft_meta::BindingRef {
                group: rb.group,
                binding: rb.binding,
            })
    };
    let mut table = weft_meta::GlslReflection::default();
    for (handle, block) in &reflection.uniforms {
        let rb = module.global_variables[*handle]
            .binding
            .ok_or_else(|| format!("GLSL backend ({entry}): uniform `{block}` has no binding"))?;
        table.uniform_blocks.push(weft_meta::GlslUniformBlock {
            block: block.clone(),
            source: weft_meta::BindingRef {
                group: rb.group,
                binding: rb.binding,
            },
            binding: u32::from(points[&rb]),
        });
    }
    for (name, mapping) in &reflection.texture_mapping {
        let rb = module.global_variables[mapping.texture]
            .binding
            .ok_or_else(|| format!("GLSL backend ({entry}): texture `{name}` has no binding"))?;
        table.samplers.push(weft_meta::GlslSampler {
            name: name.clone(),
            texture: weft_meta::BindingRef {
                group: rb.group,
                binding: rb.binding,
            },
            sampler: mapping.sampler.and_then(binding_of),
            unit: u32::from(points[&rb]),
        });
    }
    // naga's reflection maps are hash maps: sort for deterministic metadata.
    table.uniform_blocks.sort_by_key(|b| b.binding);
    table.samplers.sort_by_key(|s| s.unit);
    Ok((out, table))
}

pub fn stage_suffix(stage: ShaderStage) -> &'static str {
    match stage {
        ShaderStage::Vertex => "vert",
        ShaderStage::Fragment => "frag",
        ShaderStage::Compute => "comp",
        _ => "other",
    }
}
