//! The spectral sensitivity of thin-film interference, the table a film's
//! fast form reads (recipe `thin_film_sensitivity`; materials/laser).
//!
//! The Airy reflectance of a film is a Fourier series in the round-trip phase
//! δ = 2π x / λ, x the optical path difference 2 n₂ d cos θ₂ (Belcour & Barla
//! 2017, "A Practical Extension to Microfacet Theory for the Modeling of
//! Varying Iridescence", SIGGRAPH): R(λ) = C₀ + Σₘ 2 Cₘ cos(m δ). Its colour is
//! linear in the terms, so each order needs only
//!
//! ```text
//! S(x) = ∫ CMF(λ) cos(2π x / λ) dλ,   λ ∈ [380, 780] nm
//! ```
//!
//! at x = m · OPD, a function of the path difference alone. weft bakes it
//! from the CMFs the reference integrates (CIE 1931 2°, Wyman, Sloan &
//! Shirley 2013's multi-lobe fit: lib/thin_film.wgsl's `weft_cie_xyz`),
//! in linear Rec. 709 and divided per channel by its value at x = 0, so
//! that a flat spectrum stays grey as in the reference.
//!
//! **Table**: u = x / `opd_max` at texel centres (column i: x = i / (W − 1) ·
//! opd_max), every row the same; RGBA16Float, rgb the sensitivity (signed),
//! a = 1. **Quadrature**: the trapezoid rule at 0.25 nm (1601 wavelengths):
//! at x = 16 µm the phase turns 0.17 rad per step, and halving the step
//! moves no texel by more than 1e-5.

use std::f64::consts::PI;

/// Wavelengths of the integral (nm): the reference's range.
pub const LAMBDA_MIN_NM: f64 = 380.0;
pub const LAMBDA_MAX_NM: f64 = 780.0;
/// Trapezoid steps over the range (0.25 nm each).
pub const STEPS: u32 = 1600;

/// CIE XYZ (D65 white) to linear Rec. 709, rows R, G, B (the matrix of
/// lib/thin_film.wgsl's `WEFT_XYZ_TO_REC709`).
const XYZ_TO_REC709: [[f64; 3]; 3] = [
    [3.2404542, -1.5371385, -0.4985314],
    [-0.9692660, 1.8760108, 0.0415560],
    [0.0556434, -0.2040259, 1.0572252],
];

/// One lobe of the Wyman–Sloan–Shirley fit: a Gaussian with different widths
/// left and right of its centre.
fn lobe(lambda: f64, mu: f64, sigma_left: f64, sigma_right: f64) -> f64 {
    let t = (lambda - mu) / if lambda < mu { sigma_left } else { sigma_right };
    (-0.5 * t * t).exp()
}

/// CIE 1931 2° colour matching functions, Wyman, Sloan & Shirley 2013
/// ("Simple Analytic Approximations to the CIE XYZ Color Matching
/// Functions", JCGT 2(2)), multi-lobe fit.
pub fn cie_xyz(lambda: f64) -> [f64; 3] {
    [
        1.056 * lobe(lambda, 599.8, 37.9, 31.0) + 0.362 * lobe(lambda, 442.0, 16.0, 26.7)
            - 0.065 * lobe(lambda, 501.1, 20.4, 26.2),
        0.821 * lobe(lambda, 568.8, 46.9, 40.5) + 0.286 * lobe(lambda, 530.9, 16.3, 31.1),
        1.217 * lobe(lambda, 437.0, 11.8, 36.0) + 0.681 * lobe(lambda, 459.0, 26.0, 13.8),
    ]
}

/// The integrand's fixed part: each wavelength with its CMF times its
/// trapezoid weight, over `steps` steps.
fn weighted_cmfs(steps: u32) -> Vec<(f64, [f64; 3])> {
    let step = (LAMBDA_MAX_NM - LAMBDA_MIN_NM) / f64::from(steps);
    (0..=steps)
        .map(|i| {
            let lambda = LAMBDA_MIN_NM + step * f64::from(i);
            let w = if i == 0 || i == steps { 0.5 } else { 1.0 } * step;
            (lambda, cie_xyz(lambda).map(|c| c * w))
        })
        .collect()
}

/// S(x) in XYZ for a path difference `opd_nm`.
fn sensitivity_xyz(cmfs: &[(f64, [f64; 3])], opd_nm: f64) -> [f64; 3] {
    let mut s = [0.0; 3];
    for (lambda, w) in cmfs {
        let c = (2.0 * PI * opd_nm / lambda).cos();
        for k in 0..3 {
            s[k] += w[k] * c;
        }
    }
    s
}

fn to_rec709(xyz: [f64; 3]) -> [f64; 3] {
    XYZ_TO_REC709.map(|row| row[0] * xyz[0] + row[1] * xyz[1] + row[2] * xyz[2])
}

/// The normalised sensitivity (linear Rec. 709, 1 at x = 0) at each path
/// difference in `opd_nm`.
pub fn sensitivity(opd_nm: &[f64]) -> Vec<[f64; 3]> {
    let cmfs = weighted_cmfs(STEPS);
    let at_zero = to_rec709(sensitivity_xyz(&cmfs, 0.0));
    opd_nm
        .iter()
        .map(|&x| {
            let rgb = to_rec709(sensitivity_xyz(&cmfs, x));
            [0, 1, 2].map(|c| rgb[c] / at_zero[c])
        })
        .collect()
}

/// The table's texels (RGBA16Float, row 0 first): `size` = [W, H], column i
/// at x = i / (W − 1) · `opd_max_nm`, every row the same.
pub fn sensitivity_table(size: [u32; 2], opd_max_nm: f64) -> Vec<u8> {
    let [w, h] = size;
    let xs: Vec<f64> = (0..w)
        .map(|i| f64::from(i) / f64::from(w - 1) * opd_max_nm)
        .collect();
    let row: Vec<u8> = sensitivity(&xs)
        .into_iter()
        .flat_map(|[r, g, b]| [r, g, b, 1.0])
        .flat_map(|x| half::f16::from_f64(x).to_le_bytes())
        .collect();
    row.repeat(h as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_at_zero_and_decayed_at_the_laser_tables_end() {
        let s = sensitivity(&[0.0, 16_000.0]);
        assert!(s[0].iter().all(|c| (c - 1.0).abs() < 1e-12), "{:?}", s[0]);
        // The CMFs' narrowest lobe (z, 11.8 nm at 437 nm) has decayed by
        // 16 µm: the table's clamped end adds nothing.
        assert!(s[1].iter().all(|c| c.abs() < 1e-3), "{:?}", s[1]);
    }

    #[test]
    fn the_step_is_converged() {
        // Halving the step moves no value by more than 1e-5 up to 16 µm.
        let xs: Vec<f64> = (0..=64).map(|i| f64::from(i) * 250.0).collect();
        let coarse = sensitivity(&xs);
        let cmfs_fine = weighted_cmfs(2 * STEPS);
        let zero = to_rec709(sensitivity_xyz(&cmfs_fine, 0.0));
        for (x, c) in xs.iter().zip(&coarse) {
            let f = to_rec709(sensitivity_xyz(&cmfs_fine, *x));
            for k in 0..3 {
                assert!(
                    (f[k] / zero[k] - c[k]).abs() < 1e-5,
                    "x {x}: {c:?} vs {f:?}"
                );
            }
        }
    }

    #[test]
    fn deterministic_bytes_and_layout() {
        let a = sensitivity_table([64, 2], 16_000.0);
        assert_eq!(a, sensitivity_table([64, 2], 16_000.0));
        assert_eq!(a.len(), 64 * 2 * 8);
        // Both rows equal; texel 0 is (1, 1, 1, 1).
        assert_eq!(a[..64 * 8], a[64 * 8..]);
        assert!(
            a[..8]
                .chunks(2)
                .all(|b| half::f16::from_le_bytes([b[0], b[1]]) == half::f16::ONE)
        );
    }
}
