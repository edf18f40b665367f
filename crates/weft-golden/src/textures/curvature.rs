//! The skin's curvature map (seed 004 §3.1: the pre-integrated table's
//! v = 1/r, precomputed instead of the per-pixel |fwidth(N)| / |fwidth(P)|)
//! for the bust head's uvs: the mean curvature of the head's actual surface
//! (`head`: the ellipsoid narrowing to the jaw; the mesh has no nose or
//! ears, so the jaw and chin are where it peaks), R = H / SCALE.
//!
//! The head is symmetric in x and in z, so its curvature repeats with
//! period 1 in u: the map covers u ∈ [0, 1] and repeat addressing gives the
//! back half (u outside [0, 1]) its own, correct, values.

use super::head;
use super::{Channels, Texture, quantise};

pub const SIZE: usize = 256;
/// Curvature (1/units of the bust, whose head is about 1 tall) stored as 1:
/// `skin.wgsl` reads v = saturate(curvature_factor × R), so R × SCALE is the
/// 1/r the screen-space estimate gives, and the map reads like the estimate
/// with curvature_factor = SCALE × the estimate's (the default 0.6 → 1.2).
pub const SCALE: f64 = 2.0;

/// Mean curvature (1/units) at head uv.
pub fn mean_curvature(u: f64, v: f64) -> f64 {
    let (theta, phi) = head::angles(u, v);
    let (k1, k2) = head::principal_curvatures(theta, phi);
    0.5 * (k1 + k2)
}

pub fn texture() -> Texture {
    let mut data = Vec::with_capacity(SIZE * SIZE);
    for j in 0..SIZE {
        for i in 0..SIZE {
            let (u, v) = (
                (i as f64 + 0.5) / SIZE as f64,
                (j as f64 + 0.5) / SIZE as f64,
            );
            data.push(quantise(mean_curvature(u, v) / SCALE));
        }
    }
    Texture {
        path: "materials/skin/textures/curvature.png",
        width: SIZE as u32,
        height: SIZE as u32,
        channels: Channels::Grey,
        srgb: false,
        data,
    }
}
