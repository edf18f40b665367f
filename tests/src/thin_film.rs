//! Thin-film interference in f64, written from the papers and the glTF
//! extension's text, never from weft's WGSL: the reference models the film
//! tests hold `materials/lib/thin_film.wgsl` to (tests/physics/laser_film.rs)
//! and the glTF iridescence check draws against
//! (tests/rendering/gltf_iridescence.rs).
//!
//! The stack is air (IOR 1) | film (IOR η₂, thickness d) | base; the base is
//! given, as KHR_materials_iridescence gives it, by its normal-incidence
//! reflectance F0 per RGB channel and taken as the real IOR
//! (1 + √F0)/(1 − √F0). Results are linear Rec. 709 reflectances.

use std::f64::consts::PI;

type V3 = [f64; 3];

/// CIE XYZ (D65) to linear Rec. 709.
pub fn xyz_to_rec709(xyz: V3) -> V3 {
    [
        3.2404542 * xyz[0] - 1.5371385 * xyz[1] - 0.4985314 * xyz[2],
        -0.9692660 * xyz[0] + 1.8760108 * xyz[1] + 0.0415560 * xyz[2],
        0.0556434 * xyz[0] - 0.2040259 * xyz[1] + 1.0572252 * xyz[2],
    ]
}

/// The CIE 1931 colour matching functions in Wyman, Sloan & Shirley's
/// multi-lobe analytic fit (JCGT 2(2), 2013), `lambda` in nm.
pub fn cie_xyz_wyman(lambda: f64) -> V3 {
    let g = |mu: f64, s1: f64, s2: f64| {
        let t = (lambda - mu) / if lambda < mu { s1 } else { s2 };
        (-0.5 * t * t).exp()
    };
    [
        1.056 * g(599.8, 37.9, 31.0) + 0.362 * g(442.0, 16.0, 26.7) - 0.065 * g(501.1, 20.4, 26.2),
        0.821 * g(568.8, 46.9, 40.5) + 0.286 * g(530.9, 16.3, 31.1),
        1.217 * g(437.0, 11.8, 36.0) + 0.681 * g(459.0, 26.0, 13.8),
    ]
}

/// The Fourier transform of Belcour & Barla's (2017) Gaussian fit of the
/// CIE 1931 XYZ sensitivities in wavenumber, at optical path difference
/// `opd_nm` with phase `shift`: ∫ s(k) cos(2π k·OPD + shift) dk, with Y of a
/// flat spectrum 1 (the constants of the authors' published code: three
/// Gaussians and a fourth for X's blue lobe).
pub fn sensitivity_belcour_barla(opd_nm: f64, shift: f64) -> V3 {
    let phase = 2.0 * PI * opd_nm * 1e-9;
    let gauss = |val: f64, pos: f64, var: f64| {
        val * (2.0 * PI * var).sqrt() * (pos * phase + shift).cos() * (-phase * phase * var).exp()
    };
    [
        gauss(5.4856e-13, 1.6810e6, 4.3278e9) + gauss(9.7470e-14, 2.2399e6, 4.5282e9),
        gauss(4.4201e-13, 1.7953e6, 9.3046e9),
        gauss(5.2481e-13, 2.2084e6, 6.6121e9),
    ]
    .map(|x| x / 1.0685e-7)
}

/// The IOR of a dielectric of normal-incidence reflectance `f0` against air,
/// F0 clamped below 1 where it diverges.
pub fn ior_from_f0(f0: f64) -> f64 {
    let s = f0.clamp(0.0, 0.9999).sqrt();
    (1.0 + s) / (1.0 - s)
}

pub fn smoothstep(a: f64, b: f64, x: f64) -> f64 {
    let t = ((x - a) / (b - a)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// The film's IOR, faded to air's over the first 30 nm so that a vanishing
/// film is the bare base (Belcour & Barla's code does the same).
pub fn faded_film_ior(film_ior: f64, d_nm: f64) -> f64 {
    1.0 + (film_ior.max(1.0) - 1.0) * smoothstep(0.0, 30.0, d_nm)
}

/// Fresnel amplitude of one interface for s (`p = false`) or p light, one
/// sign convention for every interface (the Airy sum needs them consistent).
pub fn amplitude(n_i: f64, n_t: f64, cos_i: f64, cos_t: f64, p: bool) -> f64 {
    if p {
        (n_t * cos_i - n_i * cos_t) / (n_t * cos_i + n_i * cos_t)
    } else {
        (n_i * cos_i - n_t * cos_t) / (n_i * cos_i + n_t * cos_t)
    }
}

/// Unpolarised exact Fresnel reflectance of a bare dielectric of IOR `n`.
pub fn fresnel_dielectric(cos1: f64, n: f64) -> f64 {
    let cos_t = (1.0 - (1.0 - cos1 * cos1) / (n * n)).sqrt();
    let (s, p) = (
        amplitude(1.0, n, cos1, cos_t, false),
        amplitude(1.0, n, cos1, cos_t, true),
    );
    0.5 * (s * s + p * p)
}

/// The Airy reflectance of one polarisation at phase δ, from the complex
/// amplitude (r₁₂ + r₂₃e^{iδ}) / (1 + r₁₂r₂₃e^{iδ}).
pub fn airy(r12: f64, r23: f64, delta: f64) -> f64 {
    let (c, s) = (delta.cos(), delta.sin());
    let (num_re, num_im) = (r12 + r23 * c, r23 * s);
    let (den_re, den_im) = (1.0 + r12 * r23 * c, r12 * r23 * s);
    (num_re * num_re + num_im * num_im) / (den_re * den_re + den_im * den_im)
}

/// The cosines in the film and in the base for a ray at `cos1` in air.
fn refracted(cos1: f64, n: f64) -> f64 {
    (1.0 - (1.0 - cos1 * cos1) / (n * n)).sqrt()
}

/// The spectral film: the Airy reflectance averaged over s and p at 101
/// wavelengths (380–780 nm), integrated (trapezoid) against Wyman's CMF fit,
/// taken to Rec. 709 and divided per channel by a flat spectrum's, so that
/// reflectance 1 is white. Channel c is the film over channel c's base.
pub fn film_spectral(cos1: f64, d_nm: f64, film_ior: f64, base_f0: V3) -> V3 {
    let n2 = faded_film_ior(film_ior, d_nm);
    let cos2 = refracted(cos1, n2);
    std::array::from_fn(|c| {
        let n3 = ior_from_f0(base_f0[c]);
        let cos3 = refracted(cos1, n3);
        let r12 = [false, true].map(|p| amplitude(1.0, n2, cos1, cos2, p));
        let r23 = [false, true].map(|p| amplitude(n2, n3, cos2, cos3, p));
        let (mut xyz, mut white) = ([0.0; 3], [0.0; 3]);
        for i in 0..101 {
            let lambda = 380.0 + 4.0 * i as f64;
            let w = if i == 0 || i == 100 { 0.5 } else { 1.0 };
            let delta = 4.0 * PI * n2 * d_nm.max(0.0) * cos2 / lambda;
            let r = 0.5 * (airy(r12[0], r23[0], delta) + airy(r12[1], r23[1], delta));
            let cmf = cie_xyz_wyman(lambda);
            for k in 0..3 {
                xyz[k] += w * r * cmf[k];
                white[k] += w * cmf[k];
            }
        }
        (xyz_to_rec709(xyz)[c] / xyz_to_rec709(white)[c]).clamp(0.0, 1.0)
    })
}

/// The Airy series of one polarisation (Belcour & Barla 2017, §4):
/// R = C₀ + Σₘ 2 Cₘ cos(m(δ + φ)), C₀ = R₁₂ + Rₛ, Cₘ = (Rₛ − T₁₂₁) √(R₁₂R₂₃)ᵐ,
/// Rₛ = T₁₂₁² R₂₃ / (1 − R₁₂R₂₃), φ the phase of r₂₁r₂₃ (0 or π with real
/// amplitudes, r₂₁ = −r₁₂).
pub struct AirySeries {
    pub c0: f64,
    /// C₁.
    pub first: f64,
    /// Cₘ₊₁ / Cₘ.
    pub ratio: f64,
    pub phi: f64,
}

impl AirySeries {
    pub fn new(r12: f64, r23: f64) -> AirySeries {
        let (r12_sq, r23_sq) = (r12 * r12, r23 * r23);
        let t121 = 1.0 - r12_sq;
        let rs = t121 * t121 * r23_sq / (1.0 - r12_sq * r23_sq);
        let ratio = (r12_sq * r23_sq).sqrt();
        AirySeries {
            c0: r12_sq + rs,
            first: (rs - t121) * ratio,
            ratio,
            phi: if -r12 * r23 < 0.0 { PI } else { 0.0 },
        }
    }
}

/// Belcour & Barla's film as the paper states it: per polarisation the
/// Airy series with exact amplitudes, each order integrated against their
/// Gaussian sensitivity fit, taken to Rec. 709 and divided per channel by
/// the fit's white (a flat reflectance stays grey); s and p averaged.
/// Summed to order 8, where it has converged to 1e-6.
pub fn film_belcour_barla(cos1: f64, d_nm: f64, film_ior: f64, base_f0: V3) -> V3 {
    let n2 = faded_film_ior(film_ior, d_nm);
    let cos2 = refracted(cos1, n2);
    let opd = 2.0 * n2 * d_nm * cos2;
    let white = xyz_to_rec709(sensitivity_belcour_barla(0.0, 0.0));
    std::array::from_fn(|c| {
        let n3 = ior_from_f0(base_f0[c]);
        let cos3 = refracted(cos1, n3);
        let mut sum = 0.0;
        for p in [false, true] {
            let s = AirySeries::new(
                amplitude(1.0, n2, cos1, cos2, p),
                amplitude(n2, n3, cos2, cos3, p),
            );
            let (mut r, mut cm) = (s.c0, s.first);
            for m in 1..=8 {
                let m = m as f64;
                let sm = xyz_to_rec709(sensitivity_belcour_barla(m * opd, m * s.phi))[c] / white[c];
                r += 2.0 * cm * sm;
                cm *= s.ratio;
            }
            sum += 0.5 * r;
        }
        sum.max(0.0)
    })
}

/// The film of KHR_materials_iridescence's implementation notes (the
/// Khronos sample renderer's `evalIridescence`): Schlick reflectances at
/// both interfaces, phases 0 or π from the IOR order, orders 1 and 2, the
/// sensitivity in Rec. 709 without a per-channel white. The phase is taken
/// per base channel (the notes pass the three channels' phases as one
/// vector into the XYZ evaluation; the two agree whenever the base lies on
/// one side of the film's IOR).
pub fn film_gltf_notes(cos1: f64, d_nm: f64, film_ior: f64, base_f0: V3) -> V3 {
    let schlick = |r0: f64, c: f64| r0 + (1.0 - r0) * (1.0 - c).powi(5);
    let n2 = film_ior;
    let cos2 = refracted(cos1, n2);
    let r12 = schlick(((n2 - 1.0) / (n2 + 1.0)).powi(2), cos1);
    let t121 = 1.0 - r12;
    let phi21 = if n2 < 1.0 { 0.0 } else { PI };
    let opd = 2.0 * n2 * d_nm * cos2;
    std::array::from_fn(|c| {
        let base_ior = ior_from_f0(base_f0[c]);
        let r23 = schlick(((base_ior - n2) / (base_ior + n2)).powi(2), cos2);
        let phi = phi21 + if base_ior < n2 { PI } else { 0.0 };
        let r123 = (r12 * r23).clamp(1e-5, 0.9999);
        let rs = t121 * t121 * r23 / (1.0 - r123);
        let (mut i, mut cm) = (r12 + rs, rs - t121);
        for m in 1..=2 {
            let m = m as f64;
            cm *= r123.sqrt();
            i += cm * 2.0 * xyz_to_rec709(sensitivity_belcour_barla(m * opd, m * phi))[c];
        }
        i.max(0.0)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At one wavelength, summed far enough, the series is the Airy
    /// reflectance for every sign of the two amplitudes (a wrong φ or Cₘ
    /// shows at once).
    #[test]
    fn the_airy_series_sums_to_the_airy_reflectance() {
        for (r12, r23) in [(-0.2, -0.3), (-0.2, 0.3), (0.45, -0.1), (0.6, 0.7)] {
            let s = AirySeries::new(r12, r23);
            for k in 0..32 {
                let delta = k as f64 * 0.37;
                let (mut r, mut cm) = (s.c0, s.first);
                for m in 1..=200 {
                    r += 2.0 * cm * (m as f64 * (delta + s.phi)).cos();
                    cm *= s.ratio;
                }
                let want = airy(r12, r23, delta);
                assert!(
                    (r - want).abs() < 1e-9,
                    "r12 {r12}, r23 {r23}, δ {delta}: series {r}, Airy {want}"
                );
            }
        }
    }

    /// A film of zero thickness is the bare base in every model.
    #[test]
    fn a_vanishing_film_is_the_bare_base() {
        for cos1 in [1.0, 0.7, 0.3] {
            let bare = fresnel_dielectric(cos1, 1.5);
            for f in [film_spectral, film_belcour_barla] {
                let got = f(cos1, 0.0, 1.8, [0.04; 3]);
                for c in got {
                    assert!((c - bare).abs() < 1e-6, "cos {cos1}: {c} vs bare {bare}");
                }
            }
        }
    }
}
