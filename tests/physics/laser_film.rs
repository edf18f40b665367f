//! The laser material's thin film (materials/lib/thin_film.wgsl), evaluated
//! on lavapipe through wgpu:
//!
//! - the spectral reference against an independent f64 implementation
//!   (complex Airy amplitude summed per polarisation, the same CMF fit,
//!   the same wavelengths): formula errors (a phase, a sign, a polarisation,
//!   the normalisation) move colours by whole ΔE units, f32 rounding by
//!   hundredths;
//! - the reference converges in wavelength (101 vs 201 samples, below one
//!   just-noticeable difference everywhere on the chart);
//! - the fast Fourier form's error against it over thickness × cos θ
//!   (the figures generated/reports/laser-film.md reports);
//! - the guards: zero thickness is the bare base, F0 = 1 and grazing stay
//!   finite, a film of IOR 1 is no film.
//!
//! A missing Vulkan adapter fails the test (install mesa-vulkan-drivers).

use std::path::PathBuf;
use weft_golden::film::{self, CASES, FilmCase};
use weft_render::Gpu;

/// The library's film code and the laser's baked sensitivity table.
fn film_code() -> film::FilmCode {
    let materials = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../materials");
    film::FilmCode::load(&materials).unwrap_or_else(|e| panic!("{e}"))
}

fn gpu() -> Gpu {
    Gpu::new().unwrap_or_else(|e| panic!("the film tests need a Vulkan adapter: {e}"))
}

// ---------------------------------------------------------------- f64 model

// The independent models live in `weft_tests::thin_film` (shared with the
// glTF iridescence check).
use weft_tests::thin_film::{
    cie_xyz_wyman as cie_xyz, film_spectral as film_f64, fresnel_dielectric as fresnel_f64,
    xyz_to_rec709,
};

fn f64x3(v: [f32; 3]) -> [f64; 3] {
    v.map(f64::from)
}

// ---------------------------------------------------------------- tests

#[test]
fn cmf_fit_has_an_equal_energy_white() {
    // CIE 1931's CMFs integrate to the same value for X, Y and Z (the
    // equal-energy white is x = y = 1/3); the fit must keep that within 1 %,
    // or every film colour would carry a cast.
    let mut sum = [0.0; 3];
    for i in 0..=400 {
        let c = cie_xyz(380.0 + i as f64);
        for k in 0..3 {
            sum[k] += c[k];
        }
    }
    for (k, name) in [(0, "X"), (2, "Z")] {
        let ratio = sum[k] / sum[1];
        assert!(
            (ratio - 1.0).abs() < 0.01,
            "{name}/Y of the CMF fit = {ratio}"
        );
    }
}

#[test]
fn spectral_reference_matches_an_independent_f64_airy() {
    let _gpu = weft_tests::gpu_serial();
    let gpu = gpu();
    let code = film_code();
    let points: Vec<(f32, f32)> = [0.05f32, 0.3, 0.6, 0.9, 1.0]
        .iter()
        .flat_map(|&c| [0.0f32, 15.0, 120.0, 333.0, 450.0, 777.0, 1000.0].map(move |d| (c, d)))
        .collect();
    for case in CASES {
        let (gpu_reference, _) = film::evaluate_points(&gpu, &code, case, &points).unwrap();
        for (&(c, d), got) in points.iter().zip(&gpu_reference) {
            let want = film_f64(
                f64::from(c),
                f64::from(d),
                f64::from(case.film_ior),
                f64x3(case.base_f0),
            );
            let want32 = want.map(|x| x as f32);
            let de = film::delta_e2000(film::lab(*got), film::lab(want32));
            let abs = (0..3)
                .map(|k| (f64::from(got[k]) - want[k]).abs())
                .fold(0.0, f64::max);
            assert!(
                de < 0.05 && abs < 1e-3,
                "{}: cos {c}, d {d} nm: GPU {got:?}, f64 {want:?} (ΔE2000 {de:.4})",
                case.name
            );
        }
    }
}

/// The fast form's bar over the whole chart, per stack: ΔE2000 mean at most
/// 0.1 and 95th percentile at most 0.4 (one ΔE2000 is about one
/// just-noticeable difference), chart FLIP at most 0.01. Measured with the
/// baked sensitivity table: means 0.005 to 0.074, p95 0.013 to 0.30, FLIP
/// 0.0013 to 0.0046 (generated/reports/laser-film.md); what is left is the
/// series cut after its fourth order, on metal bases near grazing. The
/// closed-form Gaussian fit it replaced measured means of 0.14 to 0.31,
/// Belcour & Barla's own four Gaussians 0.5 to 1.8 (their CMFs are not the
/// reference's), the KHR sample code's form 3.2 to 8.5.
const FAST_MEAN_DELTA_E: f64 = 0.1;
const FAST_P95_DELTA_E: f64 = 0.4;
const FAST_CHART_FLIP: f32 = 0.01;

#[test]
fn reference_converges_and_fast_stays_within_its_bar() {
    let _gpu = weft_tests::gpu_serial();
    let gpu = gpu();
    let code = film_code();
    for case in CASES {
        let m = film::measure(&gpu, &code, case).unwrap();
        eprintln!(
            "{}: fast ΔE2000 mean {:.3} p95 {:.3} max {:.3} at ({} nm, {:.2}); FLIP {:.4}; convergence max {:.4}",
            case.name,
            m.fast.mean,
            m.fast.p95,
            m.fast.max,
            m.fast.worst_thickness_nm,
            m.fast.worst_cos,
            m.flip_mean,
            m.convergence.max
        );
        // One ΔE2000 is about one just-noticeable difference.
        assert!(
            m.convergence.max < 1.0,
            "{}: 101 wavelengths differ from 201 by ΔE2000 {:.3} at ({} nm, cos {:.2})",
            case.name,
            m.convergence.max,
            m.convergence.worst_thickness_nm,
            m.convergence.worst_cos
        );
        assert!(
            m.fast.mean <= FAST_MEAN_DELTA_E
                && m.fast.p95 <= FAST_P95_DELTA_E
                && m.flip_mean <= FAST_CHART_FLIP,
            "{}: fast ΔE2000 mean {:.3} (bar {FAST_MEAN_DELTA_E}), p95 {:.3} (bar {FAST_P95_DELTA_E}), chart FLIP {:.4} (bar {FAST_CHART_FLIP})",
            case.name,
            m.fast.mean,
            m.fast.p95,
            m.flip_mean
        );
    }
}

#[test]
fn zero_thickness_is_the_bare_base() {
    let _gpu = weft_tests::gpu_serial();
    let gpu = gpu();
    let code = film_code();
    let dielectric = FilmCase {
        name: "bare",
        label: "bare",
        film_ior: 1.8,
        base_f0: [0.04; 3],
    };
    let cosines = [0.02f32, 0.2, 0.5, 0.8, 1.0];
    let points: Vec<(f32, f32)> = cosines.iter().map(|&c| (c, 0.0)).collect();
    let (reference, fast) = film::evaluate_points(&gpu, &code, &dielectric, &points).unwrap();
    for ((&c, r), f) in cosines.iter().zip(&reference).zip(&fast) {
        let exact = fresnel_f64(f64::from(c), 1.5) as f32;
        for k in 0..3 {
            assert!(
                (r[k] - exact).abs() < 2e-3,
                "reference at cos {c}: {r:?}, bare Fresnel {exact}"
            );
            assert!(
                (f[k] - exact).abs() < 2e-3,
                "fast at cos {c}: {f:?}, bare Fresnel {exact}"
            );
        }
    }
}

#[test]
fn extremes_stay_finite_and_in_range() {
    let _gpu = weft_tests::gpu_serial();
    let gpu = gpu();
    let code = film_code();
    let stacks = [
        // F0 = 1: the IOR from F0 diverges without the clamp.
        FilmCase {
            name: "mirror",
            label: "",
            film_ior: 1.8,
            base_f0: [1.0; 3],
        },
        // Film IOR 1 (no film), and below the range (clamped to 1).
        FilmCase {
            name: "no film",
            label: "",
            film_ior: 1.0,
            base_f0: [0.04; 3],
        },
        FilmCase {
            name: "below 1",
            label: "",
            film_ior: 0.5,
            base_f0: [0.04; 3],
        },
        FilmCase {
            name: "black",
            label: "",
            film_ior: 2.0,
            base_f0: [0.0; 3],
        },
    ];
    let points: Vec<(f32, f32)> = [0.0f32, 1e-6, 0.5, 1.0, 1.5, -0.5]
        .iter()
        .flat_map(|&c| [0.0f32, 1e-3, 30.0, 1000.0, 5000.0, -10.0].map(move |d| (c, d)))
        .collect();
    for stack in &stacks {
        let (reference, fast) = film::evaluate_points(&gpu, &code, stack, &points).unwrap();
        for ((p, r), f) in points.iter().zip(&reference).zip(&fast) {
            for v in r.iter().chain(f) {
                assert!(
                    v.is_finite() && (0.0..=1.0).contains(v),
                    "{}: {p:?}: reference {r:?}, fast {f:?}",
                    stack.name
                );
            }
        }
        if stack.film_ior <= 1.0 {
            // No film: the bare base's Fresnel at every thickness.
            for (&(c, _), r) in points.iter().zip(&reference) {
                let c = c.clamp(0.0, 1.0);
                let exact = fresnel_f64(f64::from(c).max(1e-9), 1.5) as f32;
                assert!(
                    (r[1] - exact).abs() < 2e-3,
                    "{}: cos {c}: {r:?} vs {exact}",
                    stack.name
                );
            }
        }
    }
}

#[test]
fn sensitivity_table_matches_an_independent_cmf_integral() {
    // The laser's baked table (weft_compiler::bake::film, read back as the
    // f16 texels it ships) against S(x) = integral of CMF(lambda)
    // cos(2 pi x / lambda) over 380-780 nm integrated here by Simpson's
    // rule at 0.1 nm with the support library's CMFs and matrix, in linear
    // Rec. 709 over its value at 0. Bar: 2e-3, four f16 steps at 1; the two
    // integrals agree to ~1e-6, so this measures the table's storage.
    let code = film_code();
    let width = code.sensitivity.len();
    assert!(width >= 1024, "{width} texels");
    let n = 4000;
    let h = 400.0 / n as f64;
    let integral = |x: f64| {
        let mut s = [0.0; 3];
        for i in 0..=n {
            let lambda = 380.0 + h * i as f64;
            let w = if i == 0 || i == n {
                1.0
            } else if i % 2 == 1 {
                4.0
            } else {
                2.0
            } * h
                / 3.0;
            let c = cie_xyz(lambda);
            let phase = (2.0 * std::f64::consts::PI * x / lambda).cos();
            for k in 0..3 {
                s[k] += w * c[k] * phase;
            }
        }
        xyz_to_rec709(s)
    };
    let at_zero = integral(0.0);
    let mut worst = 0.0f64;
    for i in (0..width).step_by(7).chain([width - 1]) {
        let x = f64::from(code.opd_max_nm) * i as f64 / (width - 1) as f64;
        let want = integral(x);
        for c in 0..3 {
            let d = (f64::from(code.sensitivity[i][c]) - want[c] / at_zero[c]).abs();
            worst = worst.max(d);
            assert!(
                d < 2e-3,
                "texel {i} (x = {x:.0} nm), channel {c}: table {} vs {}",
                code.sensitivity[i][c],
                want[c] / at_zero[c]
            );
        }
    }
    println!("sensitivity table: worst |table - integral| {worst:.2e}");
    // Past the table's end the fast form clamps to the last texel: it must
    // have decayed to nothing.
    assert!(
        code.sensitivity[width - 1].iter().all(|v| v.abs() < 1e-3),
        "{:?}",
        code.sensitivity[width - 1]
    );
}
