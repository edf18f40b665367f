//! The hair's flow map (seed 004 §7, `_TangentMap`): the strand direction
//! in tangent space for the bust's hair cards (u across the card, v from
//! root to tip; the mesh's strand is the bitangent, +v). `hair.wgsl` decodes
//! rgb × 2 − 1 and uses its xy (x along the tangent, y along the
//! bitangent), so each texel holds (sin w, cos w, 0) for a small angle w
//! off the card's strand: gentle waves along the strand, their phase
//! drifting across the card, growing from the root, and strands that gather
//! towards the card's middle at the tip (clumping). B = ½ (no component
//! along the normal; the jitter supplies the tilt). Linear, not sRGB.

use super::math::{cos, sin};
use super::{Channels, Texture, quantise, smoothstep};
use std::f64::consts::PI;

pub const WIDTH: usize = 64;
pub const HEIGHT: usize = 256;

/// The angle off the strand (radians, towards +u) at card uv.
pub fn angle(u: f64, v: f64) -> f64 {
    let grow = smoothstep(0.0, 0.2, v);
    let wave =
        0.16 * sin(2.0 * PI * (2.0 * v + 0.35 * u)) + 0.06 * sin(2.0 * PI * (5.0 * v - 0.6 * u));
    let clump = -0.5 * (u - 0.5) * v * v;
    grow * wave + clump
}

/// The unit tangent-space direction (x along u, y along v) at card uv.
pub fn direction(u: f64, v: f64) -> [f64; 2] {
    let w = angle(u, v);
    [sin(w), cos(w)]
}

pub fn texture() -> Texture {
    let mut data = Vec::with_capacity(WIDTH * HEIGHT * 3);
    for j in 0..HEIGHT {
        for i in 0..WIDTH {
            let (u, v) = (
                (i as f64 + 0.5) / WIDTH as f64,
                (j as f64 + 0.5) / HEIGHT as f64,
            );
            let [x, y] = direction(u, v);
            data.extend([quantise(0.5 + 0.5 * x), quantise(0.5 + 0.5 * y), 128]);
        }
    }
    Texture {
        path: "materials/hair/textures/flow.png",
        width: WIDTH as u32,
        height: HEIGHT as u32,
        channels: Channels::Rgb,
        srgb: false,
        data,
    }
}
