//! The face material (`materials/face`, seed 004 §4): the SDF threshold
//! shadow, drawn on the bust's head through `weft-render`.
//!
//! - a texel is lit exactly while the light's horizontal angle keeps
//!   FdotL = 0.5 − 0.5 forward·L_h below its threshold, and the result is the
//!   skin table read at u = that shadow: the picture equals the one with the
//!   table's u pinned to 1 (lit) or 0 (dark) by the dark/bright bounds;
//! - the shadow mask multiplies it (a black mask darkens a lit face);
//! - the map is read mirrored for a light from the right: the bust lit from
//!   the right is the mirror image of the bust lit from the left, with a map
//!   that is not symmetric.

use std::path::{Path, PathBuf};
use weft_render::{
    Background, BustPart, ColorFormat, EnvironmentMaps, Gpu, HdrImage, Luts, Material,
    PreviewOptions, RenderOptions, Renderer, Scene, TextureValue,
};

const SIZE: u32 = 128;

fn generated() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated")
}

struct Setup {
    renderer: Renderer,
}

/// A `w`×`h` grey map with the value `f(u)` at each texel centre.
fn grey_map(w: u32, h: u32, f: impl Fn(f64) -> f64) -> TextureValue {
    let mut data = Vec::with_capacity((w * h * 4) as usize);
    for _ in 0..h {
        for x in 0..w {
            let g = (f((f64::from(x) + 0.5) / f64::from(w)).clamp(0.0, 1.0) * 255.0).round() as u8;
            data.extend_from_slice(&[g, g, g, 255]);
        }
    }
    TextureValue::Rgba8 {
        width: w,
        height: h,
        data,
    }
}

/// A light in the horizontal plane's direction at `cos_forward` = forward·L_h
/// (FdotL = 0.5 − 0.5 cos), on the −X side (`side` = −1) or +X, raised a little.
fn light(cos_forward: f32, side: f32) -> [f32; 3] {
    let sin = (1.0 - cos_forward * cos_forward).max(0.0).sqrt();
    [side * sin, 0.35, cos_forward]
}

impl Setup {
    fn new() -> Setup {
        let luts = Luts::load_dir(generated()).expect("generated/ LUTs");
        let gpu = Gpu::new().unwrap_or_else(|e| {
            panic!("face tests need a Vulkan adapter (apt-get install mesa-vulkan-drivers): {e}")
        });
        let env = EnvironmentMaps::sky(&PreviewOptions::default().sky_params());
        Setup {
            renderer: Renderer::new(gpu, &env, &luts).expect("renderer"),
        }
    }

    fn render(
        &mut self,
        sdf: TextureValue,
        light_dir: [f32; 3],
        values: &[(&str, &str)],
    ) -> HdrImage {
        self.render_with(sdf, light_dir, values, None)
    }

    fn render_with(
        &mut self,
        sdf: TextureValue,
        light_dir: [f32; 3],
        values: &[(&str, &str)],
        mask: Option<TextureValue>,
    ) -> HdrImage {
        let mut m = Material::load(generated().join("face/face.meta.json")).unwrap();
        m.set("face_sdf_map", sdf).unwrap();
        // White unless a test asks: the shipped mask fades the hairline and
        // the neck, which these pictures are not about.
        let mask = mask.unwrap_or(TextureValue::Builtin(weft_meta::TextureDefault::White));
        m.set("shadow_mask_map", mask).unwrap();
        for (name, value) in values {
            m.set_from_str(name, value).unwrap();
        }
        let mut scene = Scene::bust_part(BustPart::Head);
        let len = light_dir.iter().map(|c| c * c).sum::<f32>().sqrt();
        scene.light.direction = light_dir.map(|c| c / len);
        let options = RenderOptions {
            width: SIZE,
            height: SIZE,
            format: ColorFormat::Rgba32Float,
            background: Background::Color([0.0, 0.0, 0.0, 1.0]),
            ..RenderOptions::default()
        };
        self.renderer.render(&m, &scene, &options).expect("render")
    }
}

/// Largest channel difference over the picture, and the mean.
fn difference(a: &HdrImage, b: &HdrImage) -> (f32, f32) {
    let mut worst = 0.0f32;
    let mut sum = 0.0f64;
    for (p, q) in a.pixels.iter().zip(&b.pixels) {
        for c in 0..3 {
            let d = (p[c] - q[c]).abs();
            worst = worst.max(d);
            sum += f64::from(d);
        }
    }
    (worst, (sum / (a.pixels.len() * 3) as f64) as f32)
}

fn mirrored(img: &HdrImage) -> HdrImage {
    let (w, h) = (img.width as usize, img.height as usize);
    let mut pixels = img.pixels.clone();
    for y in 0..h {
        for x in 0..w {
            pixels[y * w + x] = img.pixels[y * w + (w - 1 - x)];
        }
    }
    HdrImage {
        width: img.width,
        height: img.height,
        pixels,
    }
}

#[test]
fn a_texel_is_lit_while_the_light_stays_inside_its_threshold() {
    let _gpu = weft_tests::gpu_serial();
    let mut s = Setup::new();
    // Threshold 0.4 everywhere (102/255), a hard edge.
    let flat = || grey_map(4, 4, |_| 0.4);
    let hard = ("face_soft_shadow", "0.001");
    // FdotL 0.3 (cos 0.4): inside the threshold, lit.
    let lit_light = light(0.4, -1.0);
    let lit = s.render(flat(), lit_light, &[hard]);
    let pinned_lit = s.render(flat(), lit_light, &[hard, ("dark_bound", "1")]);
    // FdotL 0.5 (the light at the side): beyond it, dark.
    let dark_light = light(0.0, -1.0);
    let dark = s.render(flat(), dark_light, &[hard]);
    let pinned_dark = s.render(flat(), dark_light, &[hard, ("bright_bound", "0")]);
    let (worst_lit, _) = difference(&lit, &pinned_lit);
    let (worst_dark, _) = difference(&dark, &pinned_dark);
    println!("lit vs u = 1: {worst_lit:.2e}; dark vs u = 0: {worst_dark:.2e}");
    assert!(
        worst_lit < 1e-4,
        "inside the threshold the face reads u = 1: {worst_lit}"
    );
    assert!(
        worst_dark < 1e-4,
        "beyond the threshold the face reads u = 0: {worst_dark}"
    );
    // And the two differ: the shadow is there at all.
    let (_, mean) = difference(&lit, &pinned_dark);
    assert!(mean > 0.02, "lit and shadowed faces differ (mean {mean})");
}

#[test]
fn the_shadow_mask_multiplies_the_sdf_result() {
    let _gpu = weft_tests::gpu_serial();
    let mut s = Setup::new();
    let flat = || grey_map(4, 4, |_| 1.0);
    let l = light(0.6, -1.0);
    let black = grey_map(4, 4, |_| 0.0);
    let masked = s.render_with(flat(), l, &[], Some(black));
    let pinned_dark = s.render(flat(), l, &[("bright_bound", "0")]);
    let (worst, _) = difference(&masked, &pinned_dark);
    assert!(
        worst < 1e-4,
        "a black shadow mask shadows the face: {worst}"
    );
}

#[test]
fn the_map_is_read_mirrored_for_a_light_from_the_right() {
    let _gpu = weft_tests::gpu_serial();
    let mut s = Setup::new();
    // Not symmetric: high thresholds (lit long) towards u = 0, the −X side.
    let ramp = || grey_map(64, 4, |u| 1.05 - u);
    // What the shadow adds over the face in full shadow (u pinned to 0):
    // the sky, the ambient and the specular are not mirror-symmetric (the
    // sky's sun stays where it is) and cancel out here.
    let mut shadow_term = |side: f32| {
        let l = light(0.3, side);
        let shaded = s.render(ramp(), l, &[]);
        let dark = s.render(ramp(), l, &[("bright_bound", "0")]);
        HdrImage {
            width: shaded.width,
            height: shaded.height,
            pixels: shaded
                .pixels
                .iter()
                .zip(&dark.pixels)
                .map(|(a, b)| [a[0] - b[0], a[1] - b[1], a[2] - b[2], 1.0])
                .collect(),
        }
    };
    let from_left = shadow_term(-1.0);
    let from_right = shadow_term(1.0);
    let (_, mirror_mean) = difference(&mirrored(&from_left), &from_right);
    let (_, plain_mean) = difference(&from_left, &from_right);
    println!("right vs mirrored left: mean {mirror_mean:.4}; right vs left: {plain_mean:.4}");
    assert!(
        plain_mean > 0.02,
        "the two sides are lit differently ({plain_mean})"
    );
    assert!(
        mirror_mean < plain_mean / 10.0,
        "lit from the right is the mirror image of lit from the left: {mirror_mean} vs {plain_mean}"
    );
}
