//! Numerical-stability probe: evaluates a material's fragment stage for many
//! exact geometric configurations (N, T, V, L) in one small render, and
//! sweeps every variant and a parameter grid derived from the metadata
//! (`weft stability`, `tests/stability/main.rs`).
//!
//! # The probe scene
//!
//! Each [`GeometricCase`] is one tile of [`Probe::cell`]² pixels, drawn by
//! [`Renderer::render_tiles`] with its own frame uniforms:
//!
//! - the geometry is a 2 × 2 quad through the world origin, perpendicular to
//!   the case's view direction V and wound counter-clockwise towards it, so it
//!   is always front-facing and rasterised;
//! - the *vertex attributes* carry the case's normal and tangent (constant
//!   over the quad), so the shading normal is whatever the case asks,
//!   including back-facing, zero-length or non-orthogonal frames;
//! - the camera sits at `V * 1e6` looking at the origin, with a field of view
//!   that the quad over-fills: the shader's `camera_position - world_position`
//!   is V to within |p| / 1e6 <= 1.5e-6 rad;
//! - the main light direction is the case's L exactly.
//!
//! Outputs are read from an `Rgba32Float` target (nothing is hidden by f16
//! rounding) and every channel of every pixel is classified by [`classify`].
//! A half-precision variant (metadata `f16_files`) is drawn from its f16
//! files and from its f32 files, and the two are compared by
//! [`classify_half`]: an f16 overflow the shader's final clamp would hide,
//! and an underflow to 0 where the f32 value is visible.

mod cases;
mod classify;
mod grid;
mod sweep;
mod tiles;

pub use tiles::Tile;

#[cfg(test)]
mod tests;

pub use cases::{GeometricCase, geometric_cases};
pub use classify::{BadKind, MAX_HALF, VISIBLE, classify, classify_half};
pub use grid::{Setting, parameter_settings, variant_reads};
pub use sweep::{
    Failure, MaterialSweep, SweepReport, draw_sweeps_on_the_calling_thread, failures_by_case,
    generated_materials, sweep_material, sweep_renderer,
};

use crate::error::Result;
use crate::image::HdrImage;
use crate::math::Vec3;
use crate::renderer::{Background, ColorFormat, RenderOptions, Renderer, ShaderLanguage};
use cases::case_scene;

/// The probe scene: one tile per geometric case.
pub struct Probe {
    pub cases: Vec<GeometricCase>,
    /// Tile size in pixels (square).
    pub cell: u32,
    pub columns: u32,
    tiles: Vec<Tile>,
}

impl Probe {
    /// Tiles of `cell` x `cell` pixels, `columns` per row.
    pub fn new(cases: Vec<GeometricCase>, light_radiance: Vec3, cell: u32, columns: u32) -> Probe {
        let cell = cell.max(1);
        let columns = columns.max(1);
        let tiles = cases
            .iter()
            .enumerate()
            .map(|(i, c)| {
                let i = i as u32;
                Tile {
                    scene: case_scene(c, light_radiance),
                    viewport: [(i % columns) * cell, (i / columns) * cell, cell, cell],
                }
            })
            .collect();
        Probe {
            cases,
            cell,
            columns,
            tiles,
        }
    }

    /// [`geometric_cases`] lit by a light of radiance `light_radiance`, 2 x 2 pixels per case.
    pub fn stability(light_radiance: Vec3) -> Probe {
        Probe::new(geometric_cases(), light_radiance, 2, 16)
    }

    pub fn width(&self) -> u32 {
        self.columns.min(self.cases.len().max(1) as u32) * self.cell
    }

    pub fn height(&self) -> u32 {
        (self.cases.len().max(1) as u32).div_ceil(self.columns) * self.cell
    }

    /// Options for preparing and rendering: the probe's size, `Rgba32Float`,
    /// WGSL, a transparent black background.
    pub fn render_options(&self) -> RenderOptions {
        RenderOptions {
            width: self.width(),
            height: self.height(),
            format: ColorFormat::Rgba32Float,
            language: ShaderLanguage::Wgsl,
            background: Background::Color([0.0; 4]),
            // Bounded memory on lavapipe (see the field's doc).
            uniforms_as_storage: true,
            ..RenderOptions::default()
        }
    }

    /// Renders the prepared material (prepared with [`Probe::render_options`])
    /// at every case; returns each case's pixels.
    pub fn evaluate(
        &self,
        renderer: &mut Renderer,
        prepared: &crate::renderer::PreparedMaterial,
    ) -> Result<Vec<Vec<[f32; 4]>>> {
        let image = renderer.render_tiles(prepared, &self.tiles, &self.render_options())?;
        Ok(self.split(&image))
    }

    /// The pixels of each case's tile.
    pub fn split(&self, image: &HdrImage) -> Vec<Vec<[f32; 4]>> {
        self.tiles
            .iter()
            .map(|t| {
                let [x0, y0, w, h] = t.viewport;
                let mut px = Vec::with_capacity((w * h) as usize);
                for y in y0..y0 + h {
                    for x in x0..x0 + w {
                        px.push(image.pixels[(y * image.width + x) as usize]);
                    }
                }
                px
            })
            .collect()
    }
}
