//! Where a draw's resources meet a shader's reflected bindings: bind groups
//! built from the metadata alone. Each binding's `sampler` entry is the
//! sampler created for it (one per distinct description), a group-0/2
//! binding's `resource` says which engine data it carries (`frame`,
//! `object`, `environment`, the LUTs by their `file`), and group 1 is the
//! material (its uniform buffer and textures).

use crate::engine_uniforms::UniformBlock;
use crate::error::{Error, Result};
use crate::math::Mat4;
use crate::pipelines::VariantPipelines;
use crate::resources::GpuEnvironment;
use std::collections::BTreeMap;
use std::sync::Arc;
use weft_meta::{Binding, EngineResource, ResourceFile};
use wgpu::util::DeviceExt;

/// What one shader's draws bind: its pipelines, bind groups, the material
/// uniform buffer behind group 1 and the engine's frame and object blocks
/// (also what the material path's [`crate::PreparedMaterial`] holds).
pub(crate) struct BoundShader {
    pub pipelines: Arc<VariantPipelines>,
    pub bind_groups: Vec<Option<wgpu::BindGroup>>,
    pub uniform: Option<wgpu::Buffer>,
    /// `weft_frame` (shared by every shader with the same layout; written
    /// once a frame by [`Renderer::draw_frames`]).
    pub frame: Option<UniformBlock>,
    /// This shader's own `weft_object`.
    pub object: Option<UniformBlock>,
}

/// The per-object inputs of [`Renderer::bind_shader`] (wgpu handles are
/// reference-counted: these are shared, not copied).
pub(crate) struct ObjectResources {
    /// The packed material uniform (`None` when the shader has no layout).
    pub uniform_bytes: Option<Vec<u8>>,
    /// Group-1 texture views by binding number.
    pub textures: BTreeMap<u32, wgpu::TextureView>,
    /// What `weft_object` starts with (the material path rewrites it per draw).
    pub model: Mat4,
    /// Group 0's cube.
    pub env: GpuEnvironment,
}

/// The engine data a binding carries, if it is a group-0/2 binding.
pub(crate) fn engine_resource(b: &Binding) -> Option<&EngineResource> {
    b.resource.as_ref()
}

pub(crate) fn lut_file<'b>(b: &'b Binding, r: &'b EngineResource) -> Result<&'b ResourceFile> {
    r.file.as_ref().ok_or_else(|| {
        Error::Metadata(format!(
            "binding `{}` carries LUT `{}` but names no `file`",
            b.name, r.id
        ))
    })
}

/// A LUT as its metadata describes it: `width` x `height` texels of `format`.
pub(crate) fn lut_texture(
    gpu: &crate::gpu::Gpu,
    label: &str,
    file: &ResourceFile,
    format: wgpu::TextureFormat,
    bytes: &[u8],
) -> wgpu::TextureView {
    gpu.device
        .create_texture_with_data(
            &gpu.queue,
            &wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d {
                    width: file.width,
                    height: file.height,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage: wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[],
            },
            wgpu::util::TextureDataOrder::LayerMajor,
            bytes,
        )
        .create_view(&Default::default())
}
