//! The TEST side of the independent-engine tests — not part of the
//! consumer in `mod.rs` (which never imports `weft-render`). It takes the
//! engine-side data an engine owns anyway (meshes, camera, light, the
//! environment cube and its SH) from `weft-render` as plain arrays, draws
//! `weft-render`'s reference pictures, and measures pictures.
//!
//! Included on its own by the test files with
//! `#[path = "support/engine/harness.rs"] mod harness;` next to
//! `#[path = "support/engine/mod.rs"] mod engine;`.

#![allow(dead_code)]

use crate::engine::data::luminance;
use crate::engine::{Environment, FrameInputs, Image, Mesh};
use std::path::{Path, PathBuf};
use weft_render::{
    Background, ColorFormat, EnvironmentMaps, HdrImage, Luts, Material, PreviewOptions,
    RenderOptions, Renderer, Scene, ShaderLanguage,
};

/// Size of every picture (square).
pub const SIZE: u32 = 128;

/// Clear colour of every picture: transparent black, so that alpha is the
/// object's coverage ("alpha is coverage", docs/engine-interface.md).
pub const CLEAR: [f64; 4] = [0.0, 0.0, 0.0, 0.0];

pub fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

pub fn generated() -> PathBuf {
    repo().join("generated")
}

/// The sky every picture is lit by: weft-render's procedural sky with the
/// sun where the default light is, as the goldens use.
pub fn sky() -> EnvironmentMaps {
    EnvironmentMaps::sky(&PreviewOptions::default().sky_params())
}

/// The environment as the engine takes it: the cube's mips and the SH.
pub fn environment(env: &EnvironmentMaps) -> Environment {
    Environment {
        size: env.mips[0].size,
        mips: env
            .mips
            .iter()
            .map(|m| m.data.iter().map(|c| [c[0], c[1], c[2], 1.0]).collect())
            .collect(),
        sh: env.sh,
    }
}

pub fn mesh(m: &weft_render::Mesh) -> Mesh {
    Mesh {
        positions: m.positions.clone(),
        normals: m.normals.clone(),
        tangents: m.tangents.clone(),
        uv0: m.uv0.clone(),
        uv1: m.uv1.clone(),
        colors: m.colors.clone(),
        indices: m.indices.clone(),
    }
}

/// Camera and light of `camera`/`light` for the square `SIZE` picture.
pub fn frame(camera: &weft_render::Camera, light: &weft_render::Light) -> FrameInputs {
    FrameInputs {
        view_proj: camera.view_proj(1.0),
        view: camera.view(),
        camera_position: camera.eye,
        light_direction: light.direction,
        light_color: light.radiance,
        exposure: 1.0,
        time: 0.0,
        viewport: [SIZE as f32; 2],
    }
}

/// The scene every material variant is drawn on: weft-render's unit
/// sphere (closed, so back-face culling matters).
pub fn material_scene() -> Scene {
    Scene::sphere()
}

pub fn options() -> RenderOptions {
    RenderOptions {
        width: SIZE,
        height: SIZE,
        format: ColorFormat::Rgba16Float,
        language: ShaderLanguage::Wgsl,
        background: Background::Color(CLEAR.map(|c| c as f32)),
        exposure: 1.0,
        time: 0.0,
        // The consumer draws each variant's portable `files` (what every
        // engine may do); the f16 files are compared with them in
        // tests/contract/half_precision.rs.
        f32_fallback: true,
        uniforms_as_storage: false,
    }
}

pub fn image(h: &HdrImage) -> Image {
    Image {
        width: h.width,
        height: h.height,
        pixels: h.pixels.clone(),
    }
}

/// weft-render drawing the reference pictures.
pub struct Reference {
    pub renderer: Renderer,
}

impl Reference {
    pub fn new(env: &EnvironmentMaps) -> Reference {
        let gpu = weft_render::Gpu::new()
            .unwrap_or_else(|e| panic!("the reference renderer needs a Vulkan adapter: {e}"));
        let luts = Luts::load_dir(generated()).unwrap();
        Reference {
            renderer: Renderer::new(gpu, env, &luts).unwrap(),
        }
    }

    /// A library variant with its default parameter values.
    pub fn variant(&mut self, meta_path: &Path, variant: &str, scene: &Scene) -> Image {
        let mut material = Material::load(meta_path).unwrap();
        material.select_variant(variant).unwrap();
        image(&self.renderer.render(&material, scene, &options()).unwrap())
    }
}

/// FLIP between the two pictures, both tone-mapped by [`Image::to_srgb8`].
pub fn flip(reference: &Image, test: &Image) -> weft_golden::FlipResult {
    weft_golden::flip(
        &reference.to_srgb8(),
        &test.to_srgb8(),
        reference.width,
        reference.height,
    )
}

/// What a picture shows: covered pixels (alpha > [`COVERED_ALPHA`]) and
/// their mean linear luminance.
#[derive(Clone, Copy, Debug)]
pub struct Stats {
    pub coverage: f64,
    pub mean_luminance: f64,
    pub non_finite: usize,
    /// Pixels with a channel at or above the f16 maximum (65504): where the
    /// materials' output clamp (`min(x, 65504)`) puts an Inf or a NaN.
    pub at_f16_max: usize,
    /// The largest finite channel value.
    pub max_channel: f32,
}

/// The largest finite f16.
pub const F16_MAX: f32 = 65504.0;

/// Alpha above which a pixel counts as showing the object.
pub const COVERED_ALPHA: f32 = 0.02;

pub fn stats(image: &Image) -> Stats {
    let covered: Vec<&[f32; 4]> = image
        .pixels
        .iter()
        .filter(|p| p[3] > COVERED_ALPHA)
        .collect();
    let sum: f64 = covered
        .iter()
        .map(|p| f64::from(luminance(**p)))
        .filter(|l| l.is_finite())
        .sum();
    Stats {
        coverage: covered.len() as f64 / image.pixels.len() as f64,
        mean_luminance: if covered.is_empty() {
            0.0
        } else {
            sum / covered.len() as f64
        },
        non_finite: image.non_finite_count(),
        at_f16_max: image
            .pixels
            .iter()
            .filter(|p| p.iter().any(|c| c.abs() >= F16_MAX))
            .count(),
        max_channel: image
            .pixels
            .iter()
            .flatten()
            .filter(|c| c.is_finite())
            .fold(0.0f32, |a, c| a.max(c.abs())),
    }
}

/// The largest difference of any channel of any pixel (linear values).
pub fn max_abs_difference(a: &Image, b: &Image) -> f32 {
    a.pixels
        .iter()
        .zip(&b.pixels)
        .flat_map(|(p, q)| (0..4).map(move |i| (p[i] - q[i]).abs()))
        .fold(
            0.0f32,
            |m, d| if d.is_nan() { f32::INFINITY } else { m.max(d) },
        )
}

/// The test fixtures (`tests/fixtures/materials`: a `constant`-mode
/// keyword, a curve, a gradient, aliases) built into a temporary library.
/// Returns the folder (keep the `TempDir` alive) and the library root.
pub fn fixture_library() -> (tempfile::TempDir, PathBuf) {
    let tmp = tempfile::tempdir().unwrap();
    let out = weft_compiler::build_library(
        &repo().join("tests/fixtures/materials"),
        &Default::default(),
        &|_, _, _| {},
    )
    .unwrap_or_else(|(db, d)| panic!("fixtures do not build:\n{}", d.render_plain(&db)));
    let root = tmp.path().join("generated");
    weft_compiler::output::write_atomically(&root, &out.files, &[]).unwrap();
    (tmp, root)
}
