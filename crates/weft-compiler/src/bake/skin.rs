//! Pre-integrated skin diffuse (Penner & Borshukov 2011, "Pre-Integrated Skin
//! Shading", GPU Pro 2) over the Burley normalised diffusion profile
//! (Christensen & Burley 2015), the table of seed 004 §3.1:
//!
//! ```text
//! D(θ, r) = ∫ sat(cos(θ + x)) w(x) dx / ∫ w(x) dx,   x ∈ [−X, X]
//! w(x)    = d R(d) ∝ e^(−s d) + e^(−s d / 3),        d = 2 r |sin(x / 2)|
//! ```
//!
//! per RGB channel with its own shape s, X = π (Penner: the whole ring) or
//! π/2 (the seed's integral). Burley's R(d) = A s (e^(−s d) + e^(−s d/3)) /
//! (8 π d) is singular at d = 0; weighting by d R(d) (the radial density
//! of the profile, as Unreal integrates it) removes the singularity, and
//! the constant factors cancel in the ratio.
//!
//! **Table**: u = N·L · 0.5 + 0.5 = (cos θ + 1) / 2 and v = curvature 1/r, both
//! in [0, 1] at texel centres (column i: u = i / (W − 1); row j: v = j /
//! (H − 1)); v = 0 is the flat limit sat(cos θ). RGBA16Float texels, A = 1.
//!
//! **Quadrature** (deterministic, f64): the integrand is even in x about
//! the ring point, so x runs over [0, X] with both sat(cos(θ ± x)); the
//! kernel narrows as s r grows, so x = X g(t) with g(t) = (e^(a t) − 1) /
//! (e^a − 1), a = ln(1 + X s_max r) (a cluster of points within the kernel
//! of the sharpest channel), midpoint rule in t. The reference tier of
//! `materials/skin` evaluates the same integral per pixel with the same
//! warp and fewer points.

use std::f64::consts::PI;

/// Points of the bake's quadrature per texel.
pub const SKIN_BAKE_POINTS: u32 = 4096;

/// The warp's exponent `a` for half-range `x_max`, sharpest shape `s_max`,
/// radius `r`: points cluster where the kernel is.
pub fn warp_exponent(x_max: f64, s_max: f64, r: f64) -> f64 {
    (x_max * s_max * r).ln_1p().min(40.0)
}

/// The quadrature of one curvature: every point's offset x and per-channel
/// weight, and the weights' sum. None of it depends on θ, so a table row
/// computes it once and `ring_integral` reuses it for every column (the
/// transcendental calls per texel drop from eleven per point to none).
struct Kernel {
    /// (cos x, sin x, weight per channel) per point.
    points: Vec<(f64, f64, [f64; 3])>,
    /// Σ 2 w per channel: the normalisation (both sides of the ring).
    den: [f64; 3],
}

/// The kernel of curvature `curvature` (> 0) for shapes `shape`, half-range
/// `x_max`, with `points` points.
fn kernel(curvature: f64, shape: [f64; 3], x_max: f64, points: u32) -> Kernel {
    let r = 1.0 / curvature;
    let s_max = shape.iter().copied().fold(0.0, f64::max);
    let a = warp_exponent(x_max, s_max, r);
    let mut den = [0.0; 3];
    let points = (0..points)
        .map(|k| {
            let t = (f64::from(k) + 0.5) / f64::from(points);
            // x = X g(t), dx = X g'(t) dt (g(t) = t when a is ~0).
            let (g, dg) = if a < 1e-6 {
                (t, 1.0)
            } else {
                let e = a.exp_m1();
                ((a * t).exp_m1() / e, a * (a * t).exp() / e)
            };
            let x = x_max * g;
            let jac = x_max * dg;
            let d = 2.0 * r * (0.5 * x).sin().abs();
            let w: [f64; 3] = std::array::from_fn(|c| {
                let s = shape[c];
                ((-s * d).exp() + (-s * d / 3.0).exp()) * jac
            });
            for c in 0..3 {
                den[c] += 2.0 * w[c];
            }
            (x.cos(), x.sin(), w)
        })
        .collect();
    Kernel { points, den }
}

/// D(θ) per channel for cos θ = `cos_theta` under `kernel`; `flat` (the
/// clamped cosine) where a channel's weights vanish.
fn ring_integral(cos_theta: f64, kernel: &Kernel) -> [f64; 3] {
    let flat = cos_theta.max(0.0);
    let cos = cos_theta.clamp(-1.0, 1.0);
    let sin = (1.0 - cos * cos).sqrt();
    let mut num = [0.0; 3];
    for &(cos_x, sin_x, w) in &kernel.points {
        // cos(θ ± x), by the angle-sum identities.
        let (a, b) = (cos * cos_x, sin * sin_x);
        let light = (a - b).max(0.0) + (a + b).max(0.0);
        for c in 0..3 {
            num[c] += light * w[c];
        }
    }
    let den = kernel.den;
    std::array::from_fn(|c| if den[c] > 0.0 { num[c] / den[c] } else { flat })
}

/// D(θ, r) per channel for cos θ = `cos_theta`, curvature `curvature` (1/r;
/// 0 = flat), shapes `shape`, half-range `x_max`, with `points` points.
pub fn preintegrated(
    cos_theta: f64,
    curvature: f64,
    shape: [f64; 3],
    x_max: f64,
    points: u32,
) -> [f64; 3] {
    if curvature <= 0.0 {
        return [cos_theta.max(0.0); 3];
    }
    ring_integral(cos_theta, &kernel(curvature, shape, x_max, points))
}

/// The table, `size[0]` × `size[1]` texels, row 0 first, as RGBA16Float
/// little-endian bytes (A = 1).
pub fn preintegrated_table(size: [u32; 2], shape: [f64; 3], half_ring: bool) -> Vec<u8> {
    let x_max = if half_ring { PI / 2.0 } else { PI };
    let [w, h] = size;
    let mut out = Vec::with_capacity((w * h * 8) as usize);
    for j in 0..h {
        let v = f64::from(j) / f64::from(h - 1);
        let row = (v > 0.0).then(|| kernel(v, shape, x_max, SKIN_BAKE_POINTS));
        for i in 0..w {
            let u = f64::from(i) / f64::from(w - 1);
            let cos_theta = 2.0 * u - 1.0;
            let d = match &row {
                Some(kernel) => ring_integral(cos_theta, kernel),
                None => [cos_theta.max(0.0); 3],
            };
            for x in [d[0], d[1], d[2], 1.0] {
                out.extend(half::f16::from_f64(x).to_le_bytes());
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_and_wide_limits() {
        // Flat skin: plain clamped cosine.
        let d = preintegrated(0.5, 0.0, [1.0, 2.0, 3.0], PI, 512);
        assert_eq!(d, [0.5; 3]);
        // A tight kernel (large s r) is nearly the clamped cosine too.
        let d = preintegrated(0.5, 1e-3, [1.0, 2.0, 3.0], PI, 4096);
        assert!(d.iter().all(|x| (x - 0.5).abs() < 2e-3), "{d:?}");
        // A wide kernel wraps light past the terminator, red (small s) most.
        let d = preintegrated(-0.1, 1.0, [0.5, 2.0, 4.0], PI, 4096);
        assert!(d[0] > d[1] && d[1] > d[2] && d[2] > 0.0, "{d:?}");
    }

    #[test]
    fn deterministic_bytes() {
        let a = preintegrated_table([8, 4], [1.0, 2.0, 3.0], false);
        assert_eq!(a, preintegrated_table([8, 4], [1.0, 2.0, 3.0], false));
        assert_eq!(a.len(), 8 * 4 * 8);
    }

    #[test]
    fn the_table_is_the_pointwise_integral() {
        // The table reuses one kernel per row; each texel must equal the
        // integral evaluated on its own.
        let (shape, size) = ([1.0, 2.0, 3.0], [5, 3]);
        let table = preintegrated_table(size, shape, true);
        let mut expected = Vec::new();
        for j in 0..size[1] {
            for i in 0..size[0] {
                let u = f64::from(i) / f64::from(size[0] - 1);
                let v = f64::from(j) / f64::from(size[1] - 1);
                let d = preintegrated(2.0 * u - 1.0, v, shape, PI / 2.0, SKIN_BAKE_POINTS);
                for x in [d[0], d[1], d[2], 1.0] {
                    expected.extend(half::f16::from_f64(x).to_le_bytes());
                }
            }
        }
        assert_eq!(table, expected);
    }
}
