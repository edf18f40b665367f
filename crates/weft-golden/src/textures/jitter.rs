//! The hair's jitter map (seed 004 §7, `_JitterMap`): a stretched noise,
//! many thin streaks across u and long along v, whose red channel
//! `hair.wgsl` adds to the strand tangent along the normal
//! (t + strength × R × n, R ∈ [0, 1] as stored). Tileable in both
//! directions (periodic lattice noise), so the material's jitter tiling can
//! repeat it. Linear grey.
//!
//! Values span about [0.07, 0.51] (mean ≈ 0.3, standard deviation ≈ 0.08):
//! strand-to-strand tilts of up to ±0.2, and a mean shift that
//! `primary_shift` ≈ −0.3 takes back out if the highlight should stay where
//! it is without the map.

use super::{Channels, Texture, quantise};

pub const SIZE: usize = 256;

/// A hash of a lattice point to [0, 1) (PCG, Jarzynski & Olano 2020).
fn hash(x: u32, y: u32, octave: u32) -> f64 {
    let mut s = x
        .wrapping_mul(0x9e37_79b9)
        .wrapping_add(y.wrapping_mul(0x85eb_ca6b))
        .wrapping_add(octave.wrapping_mul(0xc2b2_ae35));
    s = s.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
    let w = ((s >> ((s >> 28) + 4)) ^ s).wrapping_mul(277_803_737);
    let h = (w >> 22) ^ w;
    f64::from(h) / 4_294_967_296.0
}

/// Periodic value noise in [0, 1): `cells` lattice cells over the unit
/// square per axis, smoothly (Hermite) interpolated.
fn value_noise(u: f64, v: f64, cells: (u32, u32), octave: u32) -> f64 {
    let (x, y) = (u * f64::from(cells.0), v * f64::from(cells.1));
    let (x0, y0) = (x.floor(), y.floor());
    let (fx, fy) = (x - x0, y - y0);
    let (sx, sy) = (fx * fx * (3.0 - 2.0 * fx), fy * fy * (3.0 - 2.0 * fy));
    let wrap = |c: f64, n: u32| (c as i64).rem_euclid(i64::from(n)) as u32;
    let (ix0, iy0) = (wrap(x0, cells.0), wrap(y0, cells.1));
    let (ix1, iy1) = ((ix0 + 1) % cells.0, (iy0 + 1) % cells.1);
    let a = hash(ix0, iy0, octave) + (hash(ix1, iy0, octave) - hash(ix0, iy0, octave)) * sx;
    let b = hash(ix0, iy1, octave) + (hash(ix1, iy1, octave) - hash(ix0, iy1, octave)) * sx;
    a + (b - a) * sy
}

/// The stored value at uv (both in [0, 1), periodic).
pub fn value(u: f64, v: f64) -> f64 {
    // Streaks: 64 and 128 cells across, 3 and 6 along.
    let n = 0.65 * value_noise(u, v, (64, 3), 0) + 0.35 * value_noise(u, v, (128, 6), 1);
    0.05 + 0.5 * n
}

pub fn texture() -> Texture {
    let mut data = Vec::with_capacity(SIZE * SIZE);
    for j in 0..SIZE {
        for i in 0..SIZE {
            let (u, v) = (
                (i as f64 + 0.5) / SIZE as f64,
                (j as f64 + 0.5) / SIZE as f64,
            );
            data.push(quantise(value(u, v)));
        }
    }
    Texture {
        path: "materials/hair/textures/jitter.png",
        width: SIZE as u32,
        height: SIZE as u32,
        channels: Channels::Grey,
        srgb: false,
        data,
    }
}
