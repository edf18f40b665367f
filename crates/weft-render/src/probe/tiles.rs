//! Many small independent renders of one prepared material in one target
//! (the stability probe's tiles: `Renderer::render_tiles`).

use crate::draw::{RenderTargets, clear_color};
use crate::engine_uniforms::FrameView;
use crate::engine_uniforms::{frame_bytes, object_bytes};
use crate::error::{Error, Result};
use crate::image::HdrImage;
use crate::renderer::{PreparedMaterial, RenderOptions, Renderer};
use crate::resources::vertex_stream;
use crate::scene::Scene;
use wgpu::util::DeviceExt;

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
        prepared.check_format(options)?;
        let (w, h) = (options.width.max(1), options.height.max(1));
        let gpu = &self.gpu;
        let device = &gpu.device;
        let pipelines = &prepared.bound.pipelines;
        let (frame, object) = (&prepared.bound.frame, &prepared.bound.object);
        // Per tile: the frame block, then the object block, at 256-byte
        // aligned offsets (copies need 4).
        let frame_size = frame.as_ref().map_or(0, |b| b.size);
        let object_size = object.as_ref().map_or(0, |b| b.size);
        let stride = (frame_size + object_size).next_multiple_of(256).max(256);
        // One vertex stream per input and one index buffer for all tiles;
        // each tile draws its index range with its own base vertex.
        let mut streams: Vec<Vec<u8>> = vec![Vec::new(); pipelines.vertex_inputs.len()];
        let mut indices: Vec<u32> = Vec::new();
        let mut ranges = Vec::with_capacity(tiles.len());
        let mut uniforms: Vec<u8> = Vec::with_capacity(tiles.len() * stride as usize);
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
            for (stream, vi) in streams.iter_mut().zip(&pipelines.vertex_inputs) {
                stream.extend(vertex_stream(mesh, vi)?);
            }
            let first = indices.len() as u32;
            indices.extend(&mesh.indices);
            ranges.push((first..indices.len() as u32, base_vertex as i32));
            base_vertex += count;
            let view = FrameView {
                camera: &tile.scene.camera,
                light: &tile.scene.light,
                env: &self.env,
            };
            let start = uniforms.len();
            if let Some(block) = frame {
                uniforms.extend(frame_bytes(block, &view, (tw, th), options)?);
            }
            if let Some(block) = object {
                uniforms.extend(object_bytes(block, &tile.scene.model)?);
            }
            uniforms.resize(start + stride as usize, 0);
        }
        let vertex_buffers: Vec<wgpu::Buffer> = streams
            .iter()
            .zip(&pipelines.vertex_inputs)
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
        let targets = RenderTargets::new(device, w, h, options.format, "weft tiles");
        let clear = clear_color(options.background);
        gpu.checked("drawing tiles", || {
            let mut enc = device.create_command_encoder(&Default::default());
            drop(targets.pass(&mut enc, "weft tile", wgpu::LoadOp::Clear(clear), None));
            for (i, (tile, (range, base))) in tiles.iter().zip(&ranges).enumerate() {
                let off = i as u64 * stride;
                if let Some(block) = frame {
                    enc.copy_buffer_to_buffer(&uniform_records, off, &block.buffer, 0, block.size);
                }
                if let Some(block) = object {
                    let at = off + frame_size;
                    enc.copy_buffer_to_buffer(&uniform_records, at, &block.buffer, 0, block.size);
                }
                let mut rp = targets.pass(&mut enc, "weft tile", wgpu::LoadOp::Load, None);
                let [x, y, tw, th] = tile.viewport;
                rp.set_viewport(x as f32, y as f32, tw as f32, th as f32, 0.0, 1.0);
                rp.set_scissor_rect(x, y, tw, th);
                for (k, b) in vertex_buffers.iter().enumerate() {
                    rp.set_vertex_buffer(k as u32, b.slice(..));
                }
                rp.set_index_buffer(index_buffer.slice(..), wgpu::IndexFormat::Uint32);
                for (g, bg) in prepared.bound.bind_groups.iter().enumerate() {
                    if let Some(bg) = bg {
                        rp.set_bind_group(g as u32, bg, &[]);
                    }
                }
                if range.is_empty() {
                    continue;
                }
                for (pp, &instances) in pipelines.passes.iter().zip(&prepared.instances) {
                    if instances > 0 {
                        rp.set_pipeline(&pp.pipeline);
                        rp.set_stencil_reference(pp.pass.depth_stencil.stencil_reference);
                        rp.draw_indexed(range.clone(), *base, 0..instances);
                    }
                }
            }
            targets.copy_out(&mut enc);
            gpu.queue.submit([enc.finish()]);
        })?;
        targets.read(gpu)
    }
}
