//! The engine's uniform blocks, `weft_frame` (group 0) and `weft_object`
//! (group 2), written member by member at the offsets of the binding's
//! `buffer.layout`, into buffers of its `min_binding_size`. A member
//! weft-render does not know is a metadata error naming it.

use crate::error::{Error, Result};
use crate::gpu::Gpu;
use crate::math::{self, Mat4};
use crate::resources::GpuEnvironment;
use crate::scene::{Camera, Light};
use crate::targets::RenderOptions;

/// Camera, light and environment of one frame (`weft_frame`, and the sky).
pub(crate) struct FrameView<'a> {
    pub camera: &'a Camera,
    pub light: &'a Light,
    pub env: &'a GpuEnvironment,
}

use weft_meta::{Binding, UniformLayout, UniformMember, UniformType, UniformValue};

/// A uniform buffer and the layout its contents are written by.
#[derive(Clone)]
pub(crate) struct UniformBlock {
    pub layout: UniformLayout,
    pub buffer: wgpu::Buffer,
    /// Bytes of the buffer (`min_binding_size`, at least the layout's size).
    pub size: u64,
}

impl UniformBlock {
    /// A buffer for `binding` (a uniform buffer binding with a layout),
    /// after checking that every member of the layout is one `known`
    /// knows how to fill.
    pub fn new(
        gpu: &Gpu,
        binding: &Binding,
        known: fn(&str) -> Option<UniformType>,
    ) -> Result<UniformBlock> {
        let buf = binding.buffer.as_ref().ok_or_else(|| {
            Error::Metadata(format!(
                "binding `{}` (group {}, binding {}) has no `buffer` entry",
                binding.name, binding.group, binding.binding
            ))
        })?;
        check_members(&binding.name, &buf.layout, known)?;
        let size = buf
            .min_binding_size
            .max(u64::from(buf.layout.size))
            .next_multiple_of(wgpu::COPY_BUFFER_ALIGNMENT);
        Ok(UniformBlock {
            layout: buf.layout.clone(),
            buffer: crate::resources::uniform_buffer(gpu, &binding.name, size),
            size,
        })
    }
}

/// The WGSL type weft-render writes for each `weft_frame` member.
pub(crate) fn frame_member_type(name: &str) -> Option<UniformType> {
    Some(match name {
        "view_proj" | "view" => UniformType::mat_f32(4, 4),
        "camera_position" | "light_direction" | "light_color" | "params" | "viewport" => {
            UniformType::vec_f32(4)
        }
        "sh" => UniformType::array(UniformType::vec_f32(4), 9),
        _ => return None,
    })
}

/// The WGSL type weft-render writes for each `weft_object` member.
pub(crate) fn object_member_type(name: &str) -> Option<UniformType> {
    Some(match name {
        "model" | "normal_matrix" => UniformType::mat_f32(4, 4),
        _ => return None,
    })
}

fn check_members(
    block: &str,
    layout: &UniformLayout,
    known: fn(&str) -> Option<UniformType>,
) -> Result<()> {
    for m in &layout.members {
        let Some(ty) = known(&m.name) else {
            return Err(Error::Metadata(format!(
                "`{block}` has a member `{}` ({}) that weft-render does not know how to fill \
                 (engine interface {})",
                m.name,
                m.ty,
                weft_meta::ENGINE_INTERFACE_VERSION
            )));
        };
        if m.ty != ty {
            return Err(Error::Metadata(format!(
                "`{block}` member `{}` has type `{}`; weft-render writes `{ty}`",
                m.name, m.ty
            )));
        }
    }
    Ok(())
}

/// `values` into `m` through weft-meta's encoder (`weft_meta::uniform`).
fn write_member(bytes: &mut [u8], m: &UniformMember, values: &[f32]) -> Result<()> {
    let v = UniformValue::F32s(values.iter().map(|x| f64::from(*x)).collect());
    weft_meta::uniform::write_member(bytes, m, &v)
        .map_err(|e| Error::Metadata(format!("{e}; weft-render writes {} numbers", values.len())))
}

fn flat(m: &Mat4) -> Vec<f32> {
    m.iter().flatten().copied().collect()
}

fn vec4(v: [f32; 3], w: f32) -> Vec<f32> {
    vec![v[0], v[1], v[2], w]
}

/// `weft_frame` as the block's layout lays it out, for a viewport of
/// `size` pixels (the whole target, or one probe tile).
pub(crate) fn frame_bytes(
    block: &UniformBlock,
    view: &FrameView,
    size: (u32, u32),
    options: &RenderOptions,
) -> Result<Vec<u8>> {
    let (w, h) = (size.0.max(1) as f32, size.1.max(1) as f32);
    let aspect = w / h;
    let camera = view.camera;
    let mut bytes = vec![0u8; block.size as usize];
    for m in &block.layout.members {
        let values = match m.name.as_str() {
            "view_proj" => flat(&camera.view_proj(aspect)),
            "view" => flat(&camera.view()),
            "camera_position" => vec4(camera.eye, 1.0),
            "light_direction" => vec4(math::normalize(view.light.direction), 0.0),
            "light_color" => vec4(view.light.radiance, 0.0),
            "sh" => view.env.sh.iter().flat_map(|c| vec4(*c, 0.0)).collect(),
            "params" => vec![
                view.env.mip_count as f32,
                options.exposure,
                options.time,
                0.0,
            ],
            "viewport" => vec![w, h, 1.0 / w, 1.0 / h],
            other => {
                return Err(Error::Metadata(format!(
                    "`weft_frame` member `{other}` is not one weft-render fills"
                )));
            }
        };
        write_member(&mut bytes, m, &values)?;
    }
    Ok(bytes)
}

/// `weft_object` for `model` as the block's layout lays it out.
pub(crate) fn object_bytes(block: &UniformBlock, model: &Mat4) -> Result<Vec<u8>> {
    let mut bytes = vec![0u8; block.size as usize];
    for m in &block.layout.members {
        let values = match m.name.as_str() {
            "model" => flat(model),
            "normal_matrix" => flat(&math::normal_matrix(model)),
            other => {
                return Err(Error::Metadata(format!(
                    "`weft_object` member `{other}` is not one weft-render fills"
                )));
            }
        };
        write_member(&mut bytes, m, &values)?;
    }
    Ok(bytes)
}
