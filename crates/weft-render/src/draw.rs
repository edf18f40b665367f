//! Recording draws into the offscreen HDR target and reading it back: the
//! frame uniforms, the sky, the render pass, the colour readback. Materials
//! and scenes both come here as a list of [`DrawCall`]s.

use crate::error::Result;
use crate::gpu::Gpu;
use crate::image::HdrImage;
use crate::resources::GpuMesh;
use crate::targets::{Background, ColorFormat, DEPTH_FORMAT};

pub(crate) const SKY_UNIFORM_SIZE: u64 = 96;

pub(crate) fn sky_uniform_buffer(gpu: &Gpu) -> wgpu::Buffer {
    crate::resources::uniform_buffer(gpu, "weft sky", SKY_UNIFORM_SIZE)
}

/// One pass of one object: a pipeline with its bind groups, mesh and
/// instance count.
pub(crate) struct DrawCall<'a> {
    pub pipeline: &'a wgpu::RenderPipeline,
    pub bind_groups: &'a [Option<wgpu::BindGroup>],
    pub mesh: &'a GpuMesh,
    pub instances: u32,
    /// The pass's `depth_stencil.stencil_reference`, set before its draw.
    pub stencil_reference: u32,
}

/// Records `draws` in order, setting bind groups and buffers only when
/// they change. Draws with no instances or no indices are skipped.
pub(crate) fn record_draws(rp: &mut wgpu::RenderPass, draws: &[DrawCall]) {
    let mut bound_groups: Option<*const [Option<wgpu::BindGroup>]> = None;
    let mut bound_mesh: Option<*const GpuMesh> = None;
    for d in draws {
        if d.instances == 0 || d.mesh.index_count == 0 {
            continue;
        }
        let mesh: *const GpuMesh = d.mesh;
        if bound_mesh != Some(mesh) {
            for (i, b) in d.mesh.vertex_buffers.iter().enumerate() {
                rp.set_vertex_buffer(i as u32, b.slice(..));
            }
            rp.set_index_buffer(d.mesh.index_buffer.slice(..), wgpu::IndexFormat::Uint32);
            bound_mesh = Some(mesh);
        }
        let groups: *const [Option<wgpu::BindGroup>] = d.bind_groups;
        if bound_groups != Some(groups) {
            for (g, bg) in d.bind_groups.iter().enumerate() {
                if let Some(bg) = bg {
                    rp.set_bind_group(g as u32, bg, &[]);
                }
            }
            bound_groups = Some(groups);
        }
        rp.set_pipeline(d.pipeline);
        rp.set_stencil_reference(d.stencil_reference);
        rp.draw_indexed(0..d.mesh.index_count, 0, 0..d.instances);
    }
}

/// What a render pass clears the colour target to (the sky is drawn over black).
pub(crate) fn clear_color(background: Background) -> wgpu::Color {
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

/// A colour and a depth target of one size, and the buffer the colour is
/// read back through.
pub(crate) struct RenderTargets {
    pub width: u32,
    pub height: u32,
    format: ColorFormat,
    color: wgpu::Texture,
    pub color_view: wgpu::TextureView,
    pub depth_view: wgpu::TextureView,
    staging: wgpu::Buffer,
    row: u32,
}

impl RenderTargets {
    pub fn new(device: &wgpu::Device, w: u32, h: u32, format: ColorFormat, label: &str) -> Self {
        let size = wgpu::Extent3d {
            width: w,
            height: h,
            depth_or_array_layers: 1,
        };
        let target = |label: String, format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(&label),
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
            format!("{label} colour"),
            format.wgpu(),
            wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        );
        let depth = target(
            format!("{label} depth"),
            DEPTH_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        let row = (w * format.bytes_per_pixel()).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
            * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let staging = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(&format!("{label} readback")),
            size: u64::from(row) * u64::from(h),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        RenderTargets {
            width: w,
            height: h,
            format,
            color_view: color.create_view(&Default::default()),
            depth_view: depth.create_view(&Default::default()),
            color,
            staging,
            row,
        }
    }

    /// A render pass over both targets: colour `load`, depth cleared to 1,
    /// stencil to 0 (the metadata's clear values).
    pub fn pass<'e>(
        &self,
        enc: &'e mut wgpu::CommandEncoder,
        label: &str,
        load: wgpu::LoadOp<wgpu::Color>,
        timestamp_writes: Option<wgpu::RenderPassTimestampWrites>,
    ) -> wgpu::RenderPass<'e> {
        enc.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some(label),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: &self.color_view,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load,
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &self.depth_view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Discard,
                }),
                stencil_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(0),
                    store: wgpu::StoreOp::Discard,
                }),
            }),
            timestamp_writes,
            occlusion_query_set: None,
            multiview_mask: None,
        })
    }

    /// Copies the colour target into the readback buffer.
    pub fn copy_out(&self, enc: &mut wgpu::CommandEncoder) {
        enc.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &self.color,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &self.staging,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(self.row),
                    rows_per_image: Some(self.height),
                },
            },
            wgpu::Extent3d {
                width: self.width,
                height: self.height,
                depth_or_array_layers: 1,
            },
        );
    }

    /// Maps the readback buffer (after [`RenderTargets::copy_out`] was submitted).
    pub fn read(&self, gpu: &Gpu) -> Result<HdrImage> {
        let bytes = gpu.map_read(&self.staging)?;
        Ok(HdrImage {
            width: self.width,
            height: self.height,
            pixels: decode_rows(&bytes, self.width, self.height, self.row, self.format),
        })
    }
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
