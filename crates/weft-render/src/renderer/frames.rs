//! Drawing frames: the frame uniforms written, the sky and every draw call
//! recorded into one pass per frame (`draw.rs` has the pieces).

use super::Renderer;
use crate::draw::{DrawCall, RenderTargets, SKY_UNIFORM_SIZE, clear_color, record_draws};
use crate::engine_uniforms::{FrameView, frame_bytes};
use crate::error::Result;
use crate::image::HdrImage;
use crate::math;
use crate::targets::{Background, RenderOptions};

impl Renderer {
    /// Draws `frames` frames of `draws` over the background into the same
    /// targets, one submit each, and reads the last one back. With `timed`,
    /// every frame is waited for and its submit-to-completion CPU time (ms)
    /// returned; `timestamps` receives pass timestamp writes at 2i and 2i+1
    /// (see timing.rs). The sky pipeline must exist for a sky background
    /// ([`Renderer::ensure_sky_pipeline`]): nothing is built here.
    pub(crate) fn draw_frames(
        &self,
        view: &FrameView,
        draws: &[DrawCall],
        options: &RenderOptions,
        frames: u32,
        timed: bool,
        timestamps: Option<&wgpu::QuerySet>,
    ) -> Result<(HdrImage, Vec<f64>)> {
        let (w, h) = (options.width.max(1), options.height.max(1));
        self.write_frame(view, (w, h), options)?;
        let gpu = &self.gpu;
        let device = &gpu.device;
        let targets = RenderTargets::new(device, w, h, options.format, "weft");
        let sky = match options.background {
            Background::Sky { .. } => Some(self.sky_bind_group(&view.env.view)),
            Background::Color(_) => None,
        };
        let clear = clear_color(options.background);
        let frames = frames.max(1);
        let mut cpu_ms = Vec::new();
        for frame in 0..frames {
            let last = frame + 1 == frames;
            let commands = gpu.checked("drawing", || {
                let mut enc = device.create_command_encoder(&Default::default());
                {
                    let writes = timestamps.map(|q| wgpu::RenderPassTimestampWrites {
                        query_set: q,
                        beginning_of_pass_write_index: Some(2 * frame),
                        end_of_pass_write_index: Some(2 * frame + 1),
                    });
                    let mut rp =
                        targets.pass(&mut enc, "weft render", wgpu::LoadOp::Clear(clear), writes);
                    if let (Some(bg), Some(p)) = (&sky, self.sky_pipelines.get(&options.format)) {
                        rp.set_pipeline(p);
                        rp.set_bind_group(0, bg, &[]);
                        rp.draw(0..3, 0..1);
                    }
                    record_draws(&mut rp, draws);
                }
                if last {
                    targets.copy_out(&mut enc);
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
        Ok((targets.read(gpu)?, cpu_ms))
    }

    /// Writes `weft_frame` (every layout's buffer) and the sky's uniform
    /// for one frame.
    fn write_frame(
        &self,
        view: &FrameView,
        size: (u32, u32),
        options: &RenderOptions,
    ) -> Result<()> {
        let aspect = size.0 as f32 / size.1 as f32;
        for block in &self.frame_blocks {
            let bytes = frame_bytes(block, view, size, options)?;
            self.gpu.queue.write_buffer(&block.buffer, 0, &bytes);
        }
        let view_proj = view.camera.view_proj(aspect);
        let inv = math::inverse(&view_proj).unwrap_or(math::IDENTITY);
        let mip = match options.background {
            Background::Sky { mip } => mip,
            Background::Color(_) => 0.0,
        };
        let mut s: Vec<f32> = Vec::with_capacity((SKY_UNIFORM_SIZE / 4) as usize);
        s.extend(inv.iter().flatten());
        s.extend(view.camera.eye);
        s.push(1.0);
        s.extend([mip, 0.0, 0.0, 0.0]);
        self.gpu
            .queue
            .write_buffer(&self.sky_buffer, 0, bytemuck::cast_slice(&s));
        Ok(())
    }

    fn sky_bind_group(&self, env: &wgpu::TextureView) -> wgpu::BindGroup {
        self.gpu
            .device
            .create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("weft sky"),
                layout: &self.sky_layout,
                entries: &[
                    wgpu::BindGroupEntry {
                        binding: 0,
                        resource: self.sky_buffer.as_entire_binding(),
                    },
                    wgpu::BindGroupEntry {
                        binding: 1,
                        resource: wgpu::BindingResource::TextureView(env),
                    },
                    wgpu::BindGroupEntry {
                        binding: 2,
                        resource: wgpu::BindingResource::Sampler(&self.sky_sampler),
                    },
                ],
            })
    }
}
