//! Frame timing: GPU time of a material's render pass from timestamp
//! queries, or CPU wall time when the adapter has none.
//!
//! Each timed frame is one render pass (clear + the material's draws, plus
//! the sky when the background is the sky) submitted on its own and waited
//! for, into the same targets; the last frame is read back, so the image the
//! timings belong to comes with them.

use crate::error::{Error, Result};
use crate::image::HdrImage;
use crate::renderer::{PreparedMaterial, RenderOptions, Renderer};
use crate::scene::Scene;
use crate::scene_draw::PreparedScene;

/// What measured the frame times.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FrameTimer {
    /// Timestamp queries written at the beginning and end of the render pass
    /// (`Features::TIMESTAMP_QUERY`), scaled by `Queue::get_timestamp_period`.
    GpuTimestamp,
    /// CPU wall time from submit to completion (`Device::poll` wait): used
    /// when the adapter lacks timestamp queries, or when asked for.
    CpuWall,
}

impl FrameTimer {
    pub fn name(self) -> &'static str {
        match self {
            FrameTimer::GpuTimestamp => "gpu-timestamp",
            FrameTimer::CpuWall => "cpu-wall",
        }
    }
}

/// How many frames [`Renderer::time_frames`] draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TimingOptions {
    /// Untimed frames drawn first (pipeline and cache warm-up).
    pub warmup: u32,
    /// Timed frames.
    pub frames: u32,
    /// Measure CPU wall time even when timestamp queries are available.
    pub force_cpu_timer: bool,
}

impl Default for TimingOptions {
    fn default() -> Self {
        TimingOptions {
            warmup: 5,
            frames: 50,
            force_cpu_timer: false,
        }
    }
}

/// Per-frame times of [`Renderer::time_frames`] and the last frame's image.
#[derive(Clone, Debug)]
pub struct FrameTimes {
    pub timer: FrameTimer,
    /// Milliseconds per timed frame, in draw order.
    pub ms: Vec<f64>,
    pub image: HdrImage,
}

impl FrameTimes {
    /// The q-quantile (0..=1, nearest rank) of the frame times.
    pub fn quantile(&self, q: f64) -> f64 {
        quantile(&self.ms, q)
    }

    pub fn median(&self) -> f64 {
        self.quantile(0.5)
    }
}

/// The q-quantile (nearest rank) of `values`; NaN when empty.
fn quantile(values: &[f64], q: f64) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    let i = (q.clamp(0.0, 1.0) * (v.len() - 1) as f64).round() as usize;
    v[i]
}

/// wgpu's limit on queries in one query set.
const MAX_QUERIES: u32 = wgpu::QUERY_SET_MAX_QUERIES;

impl Renderer {
    /// Whether [`Renderer::time_frames`] can use timestamp queries here.
    pub fn has_timestamp_queries(&self) -> bool {
        self.gpu()
            .device
            .features()
            .contains(wgpu::Features::TIMESTAMP_QUERY)
    }

    /// Draws `timing.warmup + timing.frames` frames of a prepared material
    /// and returns the timed frames' durations and the last image.
    pub fn time_frames(
        &mut self,
        prepared: &PreparedMaterial,
        scene: &Scene,
        options: &RenderOptions,
        timing: &TimingOptions,
    ) -> Result<FrameTimes> {
        self.time_draws(timing, |r, frames, timestamps| {
            r.draw_repeated(prepared, scene, options, frames, true, timestamps)
        })
    }

    /// [`Renderer::time_frames`] for a prepared scene: every frame draws all
    /// of its instances.
    pub fn time_scene_frames(
        &mut self,
        prepared: &PreparedScene,
        options: &RenderOptions,
        timing: &TimingOptions,
    ) -> Result<FrameTimes> {
        self.time_draws(timing, |r, frames, timestamps| {
            r.draw_scene(prepared, options, frames, true, timestamps)
        })
    }

    /// Times `draw(renderer, frames, timestamps)`, which draws that many
    /// timed frames (waiting for each; CPU times returned) and writes pass
    /// timestamps at 2i and 2i+1 when given a query set.
    fn time_draws(
        &mut self,
        timing: &TimingOptions,
        mut draw: impl FnMut(
            &mut Renderer,
            u32,
            Option<&wgpu::QuerySet>,
        ) -> Result<(HdrImage, Vec<f64>)>,
    ) -> Result<FrameTimes> {
        let total = timing.warmup + timing.frames.max(1);
        if 2 * total > MAX_QUERIES {
            return Err(Error::InvalidValue {
                name: "frames".into(),
                message: format!("at most {} frames per call", MAX_QUERIES / 2),
            });
        }
        if timing.force_cpu_timer || !self.has_timestamp_queries() {
            let (image, ms) = draw(self, total, None)?;
            let ms = ms[ms.len() - timing.frames.max(1) as usize..].to_vec();
            return Ok(FrameTimes {
                timer: FrameTimer::CpuWall,
                ms,
                image,
            });
        }
        let count = 2 * total;
        let device = &self.gpu().device;
        let query_set = device.create_query_set(&wgpu::QuerySetDescriptor {
            label: Some("weft frame timestamps"),
            ty: wgpu::QueryType::Timestamp,
            count,
        });
        let size = u64::from(count) * 8;
        let resolve = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("weft timestamp resolve"),
            size,
            usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let (image, _) = draw(self, total, Some(&query_set))?;
        let gpu = self.gpu();
        let mut enc = gpu.device.create_command_encoder(&Default::default());
        enc.resolve_query_set(&query_set, 0..count, &resolve, 0);
        gpu.queue.submit([enc.finish()]);
        let bytes = gpu.read_buffer(&resolve)?;
        let period_ns = f64::from(gpu.queue.get_timestamp_period());
        let ticks: Vec<u64> = bytes
            .chunks_exact(8)
            .map(|b| u64::from_le_bytes(b.try_into().expect("8 bytes")))
            .collect();
        let frames = (count / 2) as usize;
        let ms: Vec<f64> = (frames - timing.frames.max(1) as usize..frames)
            .map(|i| ticks[2 * i + 1].wrapping_sub(ticks[2 * i]) as f64 * period_ns * 1e-6)
            .collect();
        if ms.iter().any(|t| !(0.0..1e6).contains(t)) {
            return Err(Error::Gpu(format!(
                "timestamp queries returned unusable values ({:?}…)",
                &ms[..ms.len().min(4)]
            )));
        }
        Ok(FrameTimes {
            timer: FrameTimer::GpuTimestamp,
            ms,
            image,
        })
    }
}
