//! The eye's matcap (seed 004 §5, `_EyeMatCap`): a lit-sphere image added to
//! the eye's albedo, sampled by `eye.wgsl` at uv = (½ − ½ (V×N).y,
//! ½ − ½ (V×N).x) in view space, which for a view straight ahead is
//! (½ + ½ n.x, ½ − ½ n.y): the image's right is the view's right, its top is
//! up. Black adds nothing, so the sphere is black but for a small bright key
//! catch-light up and to the left, a soft dim secondary low on the right and
//! a faint cool sky on the upper half, all fading out to a dark rim.
//!
//! Painted in display values (sRGB-encoded, as an artist paints a matcap;
//! the parameter is declared `srgb`).

use super::{Channels, Texture, quantise, smoothstep};

pub const SIZE: usize = 128;

/// The display-referred colour at matcap uv.
pub fn color(u: f64, v: f64) -> [f64; 3] {
    let (nx, ny) = (2.0 * u - 1.0, 1.0 - 2.0 * v);
    let r = (nx * nx + ny * ny).sqrt();
    if r >= 1.0 {
        return [0.0; 3];
    }
    // Dark rim: everything fades out over the sphere's outer fifth.
    let rim = 1.0 - smoothstep(0.78, 0.98, r);
    // Key: a small, slightly tall oval with a crisp edge (the window).
    let (kx, ky) = ((nx + 0.28) / 0.085, (ny - 0.40) / 0.11);
    let key = 1.0 - smoothstep(0.7, 1.0, (kx * kx + ky * ky).sqrt());
    // Secondary: a broad, soft, dimmer glow opposite (a bounce), faintly cool.
    let (sx, sy) = ((nx - 0.32) / 0.3, (ny + 0.44) / 0.22);
    let s = 1.0 - smoothstep(0.0, 1.0, (sx * sx + sy * sy).sqrt());
    let secondary = 0.32 * s * s;
    // Sky: the upper half reflects a little cool light.
    let sky = 0.07 * smoothstep(-0.1, 0.9, ny);
    let tint = [0.85, 0.92, 1.0];
    let mut c = [0.0; 3];
    for (k, t) in c.iter_mut().zip(tint) {
        *k = rim * (key + (secondary + sky) * t).min(1.0);
    }
    c
}

pub fn texture() -> Texture {
    let mut data = Vec::with_capacity(SIZE * SIZE * 3);
    for j in 0..SIZE {
        for i in 0..SIZE {
            let (u, v) = (
                (i as f64 + 0.5) / SIZE as f64,
                (j as f64 + 0.5) / SIZE as f64,
            );
            data.extend(color(u, v).map(quantise));
        }
    }
    Texture {
        path: "materials/eye/textures/matcap.png",
        width: SIZE as u32,
        height: SIZE as u32,
        channels: Channels::Rgb,
        srgb: true,
        data,
    }
}
