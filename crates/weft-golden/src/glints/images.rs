//! Helpers of the checks: render options, a redrawn flake pattern, sums
//! over an image, the sub-pixel pan, the far view and the box filter.

use super::REDRAWN_TILING;
use weft_render::{Background, ColorFormat, HdrImage, Material, RenderOptions, Scene, math};

pub(super) fn options(size: u32) -> RenderOptions {
    RenderOptions {
        width: size,
        height: size,
        format: ColorFormat::Rgba32Float,
        background: Background::Color([0.0; 4]),
        ..RenderOptions::default()
    }
}

/// The material with every grid cell moved (same statistics, other flakes).
pub(super) fn redrawn(m: &Material) -> Result<Material, String> {
    let mut other = m.clone();
    other
        .set_tiling("base_map", REDRAWN_TILING)
        .map_err(|e| format!("uv offset: {e}"))?;
    Ok(other)
}

/// Sum of r + g + b over the image (linear radiance).
pub(super) fn energy(img: &HdrImage) -> f64 {
    img.pixels
        .iter()
        .map(|p| f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2]))
        .sum()
}

/// Mean of r + g + b over the pixels the object covers (non-zero alpha or
/// colour; the background is cleared to zero).
pub(super) fn object_mean(img: &HdrImage) -> f64 {
    let covered: Vec<&[f32; 4]> = img.pixels.iter().filter(|p| **p != [0.0; 4]).collect();
    covered
        .iter()
        .map(|p| f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2]))
        .sum::<f64>()
        / covered.len().max(1) as f64
}

/// `scene` with the camera moved along its right axis by `pixels` pixels of
/// a `size`-pixel image, measured at the target's distance (eye and target
/// translate together: a pure sub-pixel pan of the static scene).
pub(super) fn shift_camera(scene: &Scene, pixels: f32, size: u32) -> Scene {
    let mut s = scene.clone();
    let c = s.camera;
    let forward = math::sub(c.target, c.eye);
    let distance = math::length(forward);
    let right = math::normalize(math::cross(forward, c.up));
    let pixel = 2.0 * distance * (c.fov_y_degrees.to_radians() * 0.5).tan() / size as f32;
    let d = math::scale(right, pixels * pixel);
    s.camera.eye = math::add(c.eye, d);
    s.camera.target = math::add(c.target, d);
    s
}

/// `scene` seen from `factor` times as far (same target and field of view).
pub(super) fn far(scene: &Scene, factor: f32) -> Scene {
    let mut s = scene.clone();
    let c = s.camera;
    s.camera.eye = math::add(c.target, math::scale(math::sub(c.eye, c.target), factor));
    s
}

/// Box filter of `k` x `k` pixel blocks (linear radiance).
pub(super) fn downsample(img: &HdrImage, k: u32) -> HdrImage {
    let (w, h) = (img.width / k, img.height / k);
    let mut pixels = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            let mut acc = [0.0f64; 4];
            for j in 0..k {
                for i in 0..k {
                    let p = img.pixel(x * k + i, y * k + j);
                    for c in 0..4 {
                        acc[c] += f64::from(p[c]);
                    }
                }
            }
            let n = f64::from(k * k);
            pixels.push(acc.map(|a| (a / n) as f32));
        }
    }
    HdrImage {
        width: w,
        height: h,
        pixels,
    }
}
