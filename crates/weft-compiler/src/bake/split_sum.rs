//! Split-sum environment BRDF LUT (Karis 2013, "Real Shading in Unreal Engine 4").
//!
//! The specular image-based-lighting integral is split into prefiltered radiance
//! times the directional albedo of the BRDF, which for Schlick's Fresnel is
//! `F0 * scale + bias` with
//!
//! ```text
//! scale = E[(1 - Fc) G2 (v.h) / ((n.h)(n.v))],  bias = E[Fc G2 (v.h) / ((n.h)(n.v))],
//! Fc = (1 - v.h)^5,
//! ```
//!
//! the expectation taken over GGX-distributed half vectors h (alpha = r^2,
//! r = perceptual roughness). `G2` is the height-correlated Smith masking-shadowing
//! function (Heitz 2014), matching the shader's `reference` tier
//! (`weft_v_smith_ggx_correlated`). Samples follow a Hammersley sequence, so the
//! table is deterministic; sums are accumulated in f64.
//!
//! Layout: row-major, `size * size` texels; row = roughness index, column = N.V
//! index; texel `(i, j)` holds the value at the texel centre
//! `N.V = (i + 0.5) / size`, `r = (j + 0.5) / size`, so a linear sampler at
//! `(N.V, r)` interpolates the table correctly.

/// Bakes the LUT: `size * size` (scale, bias) pairs, each estimated from
/// `samples` GGX importance samples. Both arguments must be non-zero.
pub fn split_sum_lut(size: u32, samples: u32) -> Vec<[f32; 2]> {
    assert!(size > 0, "split-sum LUT size must be non-zero");
    assert!(samples > 0, "split-sum LUT sample count must be non-zero");
    // Texels are independent; rayon's indexed collect keeps row-major order,
    // so the result does not depend on the thread count.
    use rayon::prelude::*;
    (0..size * size)
        .into_par_iter()
        .map(|i| {
            let (row, col) = (i / size, i % size);
            let roughness = (f64::from(row) + 0.5) / f64::from(size);
            let n_dot_v = (f64::from(col) + 0.5) / f64::from(size);
            let (scale, bias) = integrate(n_dot_v, roughness, samples);
            clamp_albedo(scale, bias)
        })
        .collect()
}

/// Keeps a Monte Carlo estimate inside the physical bounds: scale and bias are
/// non-negative and their sum (the albedo at F0 = 1) is at most 1. Near the
/// mirror limit the finite Hammersley estimate overshoots 1 by ~1e-6.
fn clamp_albedo(scale: f64, bias: f64) -> [f32; 2] {
    let (s, b) = (scale.max(0.0), bias.max(0.0));
    let sum = s + b;
    let k = if sum > 1.0 { 1.0 / sum } else { 1.0 };
    [(s * k) as f32, (b * k) as f32]
}

/// Encodes (scale, bias) pairs as little-endian IEEE half floats, the texel
/// layout of an `Rg16Float` texture (4 bytes per texel).
pub fn encode_rg16f(data: &[[f32; 2]]) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(data.len() * 4);
    for &[a, b] in data {
        bytes.extend_from_slice(&half::f16::from_f32(a).to_le_bytes());
        bytes.extend_from_slice(&half::f16::from_f32(b).to_le_bytes());
    }
    bytes
}

/// Van der Corput radical inverse in base 2 (second Hammersley coordinate).
fn radical_inverse(i: u32) -> f64 {
    f64::from(i.reverse_bits()) * (1.0 / 4_294_967_296.0)
}

/// Height-correlated Smith G2 for isotropic GGX (Heitz 2014, eq. 99):
/// `G2 = 1 / (1 + Lambda(v) + Lambda(l))`, written as
/// `2 n.v n.l / (n.l sqrt(n.v^2 (1 - a^2) + a^2) + n.v sqrt(n.l^2 (1 - a^2) + a^2))`.
fn g2_smith_correlated(n_dot_v: f64, n_dot_l: f64, alpha: f64) -> f64 {
    let a2 = alpha * alpha;
    let lv = n_dot_l * (n_dot_v * n_dot_v * (1.0 - a2) + a2).sqrt();
    let ll = n_dot_v * (n_dot_l * n_dot_l * (1.0 - a2) + a2).sqrt();
    2.0 * n_dot_v * n_dot_l / (lv + ll)
}

/// Monte Carlo estimate of (scale, bias) at one (N.V, perceptual roughness).
/// n = +z, v in the xz-plane.
fn integrate(n_dot_v: f64, roughness: f64, samples: u32) -> (f64, f64) {
    let alpha = roughness * roughness;
    let a2 = alpha * alpha;
    let v = [(1.0 - n_dot_v * n_dot_v).max(0.0).sqrt(), 0.0, n_dot_v];
    let inv_count = 1.0 / f64::from(samples);
    let (mut scale, mut bias) = (0.0f64, 0.0f64);
    for i in 0..samples {
        // GGX importance sampling of h (Karis 2013, ImportanceSampleGGX):
        // phi = 2 pi u1, cos(theta) = sqrt((1 - u2) / (1 + (a^2 - 1) u2)).
        let u1 = f64::from(i) * inv_count;
        let u2 = radical_inverse(i);
        let phi = std::f64::consts::TAU * u1;
        let cos_theta = ((1.0 - u2) / (1.0 + (a2 - 1.0) * u2)).max(0.0).sqrt();
        let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
        let h = [sin_theta * phi.cos(), sin_theta * phi.sin(), cos_theta];
        let v_dot_h = v[0] * h[0] + v[1] * h[1] + v[2] * h[2];
        // l = reflect(-v, h); only n.l is needed.
        let n_dot_l = 2.0 * v_dot_h * h[2] - v[2];
        if n_dot_l > 0.0 && v_dot_h > 0.0 && cos_theta > 0.0 {
            let g = g2_smith_correlated(n_dot_v, n_dot_l, alpha);
            // pdf(l) = D (n.h) / (4 v.h), so f cos / pdf = F G (v.h) / ((n.h)(n.v)).
            let g_vis = g * v_dot_h / (cos_theta * n_dot_v);
            let fc = (1.0 - v_dot_h).powi(5);
            scale += (1.0 - fc) * g_vis;
            bias += fc * g_vis;
        }
    }
    (scale * inv_count, bias * inv_count)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SIZE: u32 = 32;
    const SAMPLES: u32 = 1024;

    fn at(lut: &[[f32; 2]], size: u32, roughness_idx: u32, nov_idx: u32) -> [f32; 2] {
        lut[(roughness_idx * size + nov_idx) as usize]
    }

    #[test]
    fn values_are_finite_in_range_and_energy_bounded() {
        let lut = split_sum_lut(SIZE, SAMPLES);
        assert_eq!(lut.len(), (SIZE * SIZE) as usize);
        for (k, &[s, b]) in lut.iter().enumerate() {
            assert!(
                s.is_finite() && b.is_finite(),
                "texel {k}: non-finite ({s}, {b})"
            );
            assert!(
                (0.0..=1.0).contains(&s),
                "texel {k}: scale {s} outside [0, 1]"
            );
            assert!(
                (0.0..=1.0).contains(&b),
                "texel {k}: bias {b} outside [0, 1]"
            );
            // scale + bias is the directional albedo at F0 = 1: at most 1.
            assert!(
                s + b <= 1.0 + 2e-3,
                "texel {k}: scale + bias = {} > 1",
                s + b
            );
        }
    }

    #[test]
    fn smooth_surface_at_normal_incidence_reflects_f0() {
        // r ~ 0, N.V ~ 1: a mirror at normal incidence, F = F0 exactly.
        let lut = split_sum_lut(SIZE, SAMPLES);
        let [s, b] = at(&lut, SIZE, 0, SIZE - 1);
        assert!((s - 1.0).abs() < 0.01, "scale {s}");
        assert!(b.abs() < 0.01, "bias {b}");
    }

    #[test]
    fn rough_surface_loses_single_scattering_energy() {
        // r ~ 1 (alpha ~ 1), N.V ~ 1: GGX with alpha = 1 has D = 1/pi, so the
        // albedo is the mean of G2 / (4 pi) over the hemisphere (<= 0.5): about
        // 0.33 here (brute-force quadrature: 0.3258). Multiple scattering, which
        // a single-scattering BRDF drops, is the missing energy.
        let lut = split_sum_lut(SIZE, SAMPLES);
        let [s, b] = at(&lut, SIZE, SIZE - 1, SIZE - 1);
        let e = s + b;
        assert!((e - 0.3258).abs() < 0.01, "albedo {e}");
        // Bias grows toward grazing for smooth surfaces (Fresnel).
        let [_, b_graze] = at(&lut, SIZE, 0, 0);
        let [_, b_normal] = at(&lut, SIZE, 0, SIZE - 1);
        assert!(
            b_graze > b_normal + 0.3,
            "bias grazing {b_graze} vs normal {b_normal}"
        );
    }

    #[test]
    fn albedo_decreases_with_roughness_at_normal_incidence() {
        let lut = split_sum_lut(SIZE, SAMPLES);
        let mut prev = f32::INFINITY;
        for row in 0..SIZE {
            let [s, b] = at(&lut, SIZE, row, SIZE - 1);
            assert!(s + b <= prev + 1e-3, "row {row}: {} after {prev}", s + b);
            prev = s + b;
        }
    }

    /// Independent check: the albedo at F0 = 1 by brute-force midpoint
    /// quadrature over the light hemisphere (no importance sampling):
    /// E = integral of D(h) V(v, l) (n.l) dl, V = G2 / (4 n.v n.l).
    fn brute_force_albedo(n_dot_v: f64, alpha: f64) -> f64 {
        let a2 = alpha * alpha;
        let v = [(1.0 - n_dot_v * n_dot_v).sqrt(), 0.0, n_dot_v];
        let (nt, np) = (256usize, 256usize);
        let (dt, dp) = (
            std::f64::consts::FRAC_PI_2 / nt as f64,
            std::f64::consts::TAU / np as f64,
        );
        let mut sum = 0.0;
        for i in 0..nt {
            let theta = (i as f64 + 0.5) * dt;
            let (st, ct) = theta.sin_cos();
            for j in 0..np {
                let phi = (j as f64 + 0.5) * dp;
                let l = [st * phi.cos(), st * phi.sin(), ct];
                let hv = [v[0] + l[0], v[1] + l[1], v[2] + l[2]];
                let len = (hv[0] * hv[0] + hv[1] * hv[1] + hv[2] * hv[2]).sqrt();
                let n_dot_h = hv[2] / len;
                let dd = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0;
                let d = a2 / (std::f64::consts::PI * dd * dd);
                let g = g2_smith_correlated(n_dot_v, ct, alpha);
                sum += d * g / (4.0 * n_dot_v) * st * dt * dp;
            }
        }
        sum
    }

    #[test]
    fn matches_brute_force_quadrature() {
        let size = 16;
        let lut = split_sum_lut(size, SAMPLES);
        // Rough enough for the midpoint grid to resolve the lobe.
        for (row, col) in [(15, 15), (12, 3), (9, 8), (7, 12), (15, 0), (10, 1)] {
            let r = (f64::from(row) + 0.5) / f64::from(size);
            let nov = (f64::from(col) + 0.5) / f64::from(size);
            let reference = brute_force_albedo(nov, r * r);
            let [s, b] = at(&lut, size, row, col);
            let e = f64::from(s + b);
            assert!(
                (e - reference).abs() < 0.01,
                "r {r} nov {nov}: LUT albedo {e}, quadrature {reference}"
            );
        }
    }

    #[test]
    fn bake_is_deterministic() {
        let a = encode_rg16f(&split_sum_lut(16, 256));
        let b = encode_rg16f(&split_sum_lut(16, 256));
        assert_eq!(a, b);
        let fa: Vec<u32> = split_sum_lut(8, 64)
            .iter()
            .flat_map(|p| [p[0].to_bits(), p[1].to_bits()])
            .collect();
        let fb: Vec<u32> = split_sum_lut(8, 64)
            .iter()
            .flat_map(|p| [p[0].to_bits(), p[1].to_bits()])
            .collect();
        assert_eq!(fa, fb);
    }

    #[test]
    fn rg16f_encoding_is_little_endian_half_pairs() {
        let bytes = encode_rg16f(&[[1.0, 0.5], [0.0, -2.0]]);
        // f16: 1.0 = 0x3C00, 0.5 = 0x3800, 0.0 = 0x0000, -2.0 = 0xC000.
        assert_eq!(bytes, vec![0x00, 0x3C, 0x00, 0x38, 0x00, 0x00, 0x00, 0xC0]);
    }
}
