//! Directional albedo of the "Charlie" sheen BRDF (Conty Estevez & Kulla 2017,
//! "Production Friendly Microfacet Sheen BRDF"), for albedo scaling of the
//! layer under a sheen (KHR_materials_sheen, "Albedo-scaling technique"):
//!
//! ```text
//! E(v) = integral over l of f_sheen(v, l) (n.l) dl,   sheen colour = 1,
//! f_sheen = D(h) G2(v, l) / (4 (n.v)(n.l)),
//! D(h)    = (2 + 1/r) sin(theta_h)^(1/r) / (2 pi)                (Charlie),
//! G2      = 1 / (1 + Lambda(n.v) + Lambda(n.l))                  (height-correlated Smith),
//! Lambda(c) = exp(L(c)) for c < 0.5, exp(2 L(0.5) - L(1 - c)) otherwise,
//! L(x)    = a / (1 + b x^c) + d x + e,  (a..e) = mix(P0, P1, (1 - r)^2)
//! ```
//!
//! with the paper's fitted Lambda as written in the KHR_materials_sheen spec
//! (`P0 = (21.5473, 3.82987, 0.19823, -1.97760, -4.32054)`,
//! `P1 = (25.3245, 3.32435, 0.16801, -1.27393, -4.85967)`), and `r` the sheen
//! roughness used directly as the distribution's parameter (KHR: `alphaG =
//! sheenRoughness`). The shader's `lib/sheen.wgsl` uses the same terms, so
//! `1 - max3(sheenColor) E` keeps the sheen plus the scaled base at most 1.
//!
//! **Quadrature** (deterministic, no random numbers): over half vectors,
//! `E = integral of D(h) G2 (v.h) / (n.v) dh` (the Jacobian `dl = 4 (v.h) dh`
//! cancels the 4 of the BRDF), midpoint rule on a fixed `theta_h x phi_h`
//! grid in f64 (`phi_h` over `[0, pi]`, doubled by the symmetry of the
//! integrand about the plane of n and v), accumulated per texel and then
//! quantised to f16.
//!
//! **Layout** (`luts/charlie_albedo_<size>x<size>_<points>spp.r16f`): one
//! little-endian IEEE half per texel (an `R16Float` texture), row-major,
//! `size * size` texels; row = sheen roughness index, column = N.V index;
//! texel `(i, j)` holds E at the texel centre `N.V = (i + 0.5) / size`,
//! `r = max((j + 0.5) / size, SHEEN_MIN_ROUGHNESS)`, so a linear sampler at
//! `(u, v) = (N.V, r)` interpolates the table (rows below the clamp hold the
//! clamped value, matching the shader, which clamps r the same way).
//! `<points>` is the number of quadrature points per texel.

use std::f64::consts::PI;

/// Smallest sheen roughness the shader and the table use: 1/r stays <= 14.3,
/// so sin^(1/r) and the (2 + 1/r) factor are well inside f32 (one public sheen
/// shader clamps to the same 0.07).
pub const SHEEN_MIN_ROUGHNESS: f64 = 0.07;

/// Quadrature grid per texel: theta_h steps x phi_h steps (over [0, pi]).
pub const THETA_STEPS: u32 = 128;
pub const PHI_STEPS: u32 = 64;

/// Bakes the table: `size * size` albedos (row = roughness, column = N.V),
/// each from a `theta_steps x phi_steps` midpoint quadrature.
pub fn charlie_albedo_lut(size: u32, theta_steps: u32, phi_steps: u32) -> Vec<f32> {
    assert!(size > 0, "sheen albedo table size must be non-zero");
    assert!(
        theta_steps > 0 && phi_steps > 0,
        "sheen quadrature needs at least one point"
    );
    use rayon::prelude::*;
    // Texels are independent; the indexed collect keeps row-major order, so
    // the bytes do not depend on the thread count.
    (0..size * size)
        .into_par_iter()
        .map(|i| {
            let (row, col) = (i / size, i % size);
            let r = ((f64::from(row) + 0.5) / f64::from(size)).max(SHEEN_MIN_ROUGHNESS);
            let n_dot_v = (f64::from(col) + 0.5) / f64::from(size);
            // The exact albedo is in [0, 1]; clamp the quadrature's rounding.
            albedo(n_dot_v, r, theta_steps, phi_steps).clamp(0.0, 1.0) as f32
        })
        .collect()
}

/// Encodes albedos as little-endian IEEE half floats, the texel layout of an
/// `R16Float` texture (2 bytes per texel).
pub fn encode_r16f(data: &[f32]) -> Vec<u8> {
    data.iter()
        .flat_map(|&x| half::f16::from_f32(x).to_le_bytes())
        .collect()
}

/// Charlie distribution D(h) for cos(theta_h) = `n_dot_h`, roughness `r`.
pub fn d_charlie(n_dot_h: f64, r: f64) -> f64 {
    let inv_r = 1.0 / r;
    let sin2 = ((1.0 - n_dot_h) * (1.0 + n_dot_h)).max(0.0);
    (2.0 + inv_r) * sin2.powf(0.5 * inv_r) / (2.0 * PI)
}

/// The fitted exponent L(x) of the Charlie Smith Lambda.
fn charlie_l(x: f64, r: f64) -> f64 {
    let t = (1.0 - r) * (1.0 - r);
    let mix = |a: f64, b: f64| a + (b - a) * t;
    let a = mix(21.5473, 25.3245);
    let b = mix(3.82987, 3.32435);
    let c = mix(0.19823, 0.16801);
    let d = mix(-1.97760, -1.27393);
    let e = mix(-4.32054, -4.85967);
    a / (1.0 + b * x.max(0.0).powf(c)) + d * x + e
}

/// Smith Lambda of the Charlie distribution for a direction with cosine `cos`.
pub fn lambda_charlie(cos: f64, r: f64) -> f64 {
    let c = cos.abs();
    if c < 0.5 {
        charlie_l(c, r).exp()
    } else {
        (2.0 * charlie_l(0.5, r) - charlie_l(1.0 - c, r)).exp()
    }
}

/// Directional albedo at one (N.V, r). n = +z, v in the xz-plane.
pub fn albedo(n_dot_v: f64, r: f64, theta_steps: u32, phi_steps: u32) -> f64 {
    let v = [(1.0 - n_dot_v * n_dot_v).max(0.0).sqrt(), 0.0, n_dot_v];
    let lambda_v = lambda_charlie(n_dot_v, r);
    let d_theta = 0.5 * PI / f64::from(theta_steps);
    let d_phi = PI / f64::from(phi_steps);
    let mut sum = 0.0f64;
    for i in 0..theta_steps {
        let theta = (f64::from(i) + 0.5) * d_theta;
        let (sin_t, cos_t) = theta.sin_cos();
        let d = d_charlie(cos_t, r);
        let mut ring = 0.0f64;
        for j in 0..phi_steps {
            let phi = (f64::from(j) + 0.5) * d_phi;
            let (sin_p, cos_p) = phi.sin_cos();
            let h = [sin_t * cos_p, sin_t * sin_p, cos_t];
            let v_dot_h = v[0] * h[0] + v[2] * h[2];
            let n_dot_l = 2.0 * v_dot_h * h[2] - v[2];
            if v_dot_h > 0.0 && n_dot_l > 0.0 {
                let g2 = 1.0 / (1.0 + lambda_v + lambda_charlie(n_dot_l, r));
                ring += g2 * v_dot_h;
            }
        }
        sum += d * ring * sin_t;
    }
    // x2: phi over [0, pi] only (the integrand is even in phi).
    2.0 * sum * d_theta * d_phi / n_dot_v
}

#[cfg(test)]
mod tests {
    use super::*;

    const SIZE: u32 = 32;

    fn at(lut: &[f32], row: u32, col: u32) -> f32 {
        lut[(row * SIZE + col) as usize]
    }

    /// Independent check: the same albedo by midpoint quadrature over light
    /// directions (E = integral of D G2 / (4 n.v) dl), no half-vector change.
    fn brute_force_over_l(n_dot_v: f64, r: f64, n: usize) -> f64 {
        let v = [(1.0 - n_dot_v * n_dot_v).sqrt(), 0.0, n_dot_v];
        let (dt, dp) = (0.5 * PI / n as f64, 2.0 * PI / n as f64);
        let lambda_v = lambda_charlie(n_dot_v, r);
        let mut sum = 0.0;
        for i in 0..n {
            let theta = (i as f64 + 0.5) * dt;
            let (st, ct) = theta.sin_cos();
            for j in 0..n {
                let phi = (j as f64 + 0.5) * dp;
                let l = [st * phi.cos(), st * phi.sin(), ct];
                let hv = [v[0] + l[0], v[1] + l[1], v[2] + l[2]];
                let len = (hv[0] * hv[0] + hv[1] * hv[1] + hv[2] * hv[2]).sqrt();
                let g2 = 1.0 / (1.0 + lambda_v + lambda_charlie(ct, r));
                sum += d_charlie(hv[2] / len, r) * g2 / (4.0 * n_dot_v) * st * dt * dp;
            }
        }
        sum
    }

    #[test]
    fn charlie_distribution_is_normalised() {
        // integral of D(h) (n.h) dh = 1 for every r (the (2 + 1/r)/(2 pi) factor).
        for r in [SHEEN_MIN_ROUGHNESS, 0.2, 0.5, 1.0] {
            let n = 4096;
            let dt = 0.5 * PI / f64::from(n);
            let s: f64 = (0..n)
                .map(|i| {
                    let t = (f64::from(i) + 0.5) * dt;
                    d_charlie(t.cos(), r) * t.cos() * t.sin() * dt * 2.0 * PI
                })
                .sum();
            assert!((s - 1.0).abs() < 1e-4, "r {r}: integral {s}");
        }
    }

    #[test]
    fn values_are_finite_and_in_unit_interval() {
        let lut = charlie_albedo_lut(SIZE, THETA_STEPS, PHI_STEPS);
        assert_eq!(lut.len(), (SIZE * SIZE) as usize);
        for (k, &e) in lut.iter().enumerate() {
            assert!(e.is_finite(), "texel {k}: {e}");
            assert!((0.0..=1.0).contains(&e), "texel {k}: {e} outside [0, 1]");
        }
        // The fibre lobe reflects most at grazing view: E rises as N.V falls.
        for row in [4, 16, SIZE - 1] {
            assert!(at(&lut, row, 0) > at(&lut, row, SIZE - 1), "row {row}");
        }
    }

    #[test]
    fn known_points_match_light_space_quadrature() {
        // A second, independent quadrature (over l rather than h, finer).
        let lut = charlie_albedo_lut(SIZE, THETA_STEPS, PHI_STEPS);
        for (row, col) in [
            (31, 31),
            (31, 0),
            (15, 15),
            (8, 3),
            (2, 28),
            (0, 16),
            (20, 1),
        ] {
            let r = ((f64::from(row) + 0.5) / f64::from(SIZE)).max(SHEEN_MIN_ROUGHNESS);
            let nov = (f64::from(col) + 0.5) / f64::from(SIZE);
            let reference = brute_force_over_l(nov, r, 512);
            let e = f64::from(at(&lut, row, col));
            assert!(
                (e - reference).abs() < 2e-3,
                "r {r} nov {nov}: table {e}, light-space quadrature {reference}"
            );
        }
    }

    #[test]
    fn known_values() {
        // Converged values of E (the 256x128, 512x256 and 1024x512 grids agree
        // to < 1e-5); the table's 128x64 grid is within 5e-4 of them (about
        // one f16 step at 0.9), the light-space quadrature within 2e-3.
        for (nov, r, expected) in [
            (1.0, 1.0, 0.163_76),  // broad fibres, normal view: little sheen
            (0.02, 1.0, 0.915_11), // grazing: the fibre lobe dominates
            (0.5, 0.5, 0.281_22),
            (0.1, SHEEN_MIN_ROUGHNESS, 0.545_76),
            (1.0, SHEEN_MIN_ROUGHNESS, 0.000_257),
        ] {
            let e = albedo(nov, r, THETA_STEPS, PHI_STEPS);
            assert!(
                (e - expected).abs() < 5e-4,
                "E({nov}, {r}) = {e}, expected {expected}"
            );
        }
    }

    #[test]
    fn layered_white_furnace_is_bounded() {
        // Sheen colour 1 over a white Lambert base scaled by
        // min(1 - E(n.v), 1 - E(n.l)): E_sheen(v) + integral of
        // scaling / pi (n.l) dl <= E(v) + 1 - E(v) = 1 (the reason for albedo
        // scaling). Checked numerically, and that little energy is lost.
        let n = 64;
        let e_l: Vec<(f64, f64)> = (0..n)
            .map(|i| {
                let theta = (f64::from(i) + 0.5) * 0.5 * PI / f64::from(n);
                (theta, albedo(theta.cos(), 0.5, 64, 32))
            })
            .collect();
        for nov in [0.05, 0.3, 0.7, 1.0] {
            let e_v = albedo(nov, 0.5, 64, 32);
            let d_theta = 0.5 * PI / f64::from(n);
            let base: f64 = e_l
                .iter()
                .map(|&(t, e)| 2.0 * (1.0 - e_v).min(1.0 - e) * t.cos() * t.sin() * d_theta)
                .sum();
            let total = e_v + base;
            eprintln!("layered furnace n.v {nov}: E_sheen {e_v:.4}, total {total:.4}");
            assert!(total <= 1.0 + 1e-3, "n.v {nov}: {total}");
            assert!(total > 0.75, "n.v {nov}: {total}");
        }
    }

    #[test]
    fn bake_is_bit_identical_across_runs() {
        let a = encode_r16f(&charlie_albedo_lut(16, 64, 32));
        let b = encode_r16f(&charlie_albedo_lut(16, 64, 32));
        assert_eq!(a, b);
        assert_eq!(a.len(), 16 * 16 * 2);
    }

    #[test]
    fn r16f_encoding_is_little_endian_half() {
        // f16: 1.0 = 0x3C00, 0.5 = 0x3800.
        assert_eq!(encode_r16f(&[1.0, 0.5]), vec![0x00, 0x3C, 0x00, 0x38]);
    }
}
