//! The microcylinder cloth BSDF (materials/lib/microcylinder.wgsl) against an
//! independent f64 implementation of Sadeghi, Bisker, De Deken, Jensen 2013,
//! "A Practical Microcylinder Appearance Model for Cloth Rendering" (ACM TOG
//! 32(2):14), evaluated on lavapipe through wgpu.
//!
//! - The material's presets are checked against this file's copy of the
//!   paper's Table II.
//! - A compute shader composed of lib/brdf.wgsl + lib/microcylinder.wgsl + a
//!   small entry point evaluates the reference tier (and the fast tier, for a
//!   report) for every Table II fabric and two tangent curves at a few hundred
//!   direction pairs each; the reference tier must agree with the f64 model to
//!   [`REL_TOL`] relative, with an absolute floor of [`ABS_FLOOR`] times the
//!   fabric's peak value (see their comments for why).
//! - The reciprocity error of the published model (with its Q normalisation)
//!   is measured in f64 and printed; the unnormalised f_s must be reciprocal.
//! - Normalisations: the Gaussians integrate to 1; the curve and list paths
//!   agree for a flat curve; the reference tier's offset quadrature converges.
//!
//! A missing Vulkan adapter fails the test (install mesa-vulkan-drivers).

use std::f64::consts::PI;
use std::path::PathBuf;
use weft_front::model::{ParamValue, PresetValue};
use weft_meta::Keyframe;
use weft_tests::repo;

mod f64_checks;
mod gpu;
mod material;
mod model;

use gpu::*;
use material::*;
use model::*;

/// Relative tolerance of the GPU (f32) reference tier against the f64 model.
/// f32 carries 24 bits (6e-8); a lobe is ~60 dependent operations, the
/// Gaussian exp(-theta_h^2 / 2 gamma^2) amplifies an angle error by at most
/// theta_h^2 / gamma^2 (< 40 where the lobe is not negligible) and lavapipe's
/// atan2/exp/cos are accurate to a few ulp, so genuine float error stays below
/// ~1e-5. 1e-3 leaves two orders of margin while any formula error (a factor,
/// a swapped angle, a wrong Fresnel cosine) is far larger.
pub(super) const REL_TOL: f64 = 1e-3;
/// Absolute floor, as a fraction of the largest value of that fabric's cases:
/// near the zero crossings of max(cos phi, 0) and max(cos psi, 0) the value is
/// a tiny difference of O(1) numbers, so its f32 rounding (~1e-7 absolute) is
/// not small relative to it.
pub(super) const ABS_FLOOR: f64 = 1e-5;

/// Samples of the baked tangent curves (`samples` in microcylinder.toml and
/// MC_CURVE_SAMPLES in the WGSL).
pub(super) const CURVE_SAMPLES: usize = 33;

/// The materials root holding microcylinder/ and lib/ (overridable while
/// developing in a scratch root).
pub(super) fn materials_root() -> PathBuf {
    std::env::var_os("WEFT_MICROCYLINDER_ROOT")
        .map(PathBuf::from)
        .unwrap_or_else(|| repo().join("materials"))
}

// ===========================================================================
// Tests

#[test]
fn gpu_reference_tier_matches_f64_model() {
    let _gpu = weft_tests::gpu_serial();
    let m = load_material();
    let mut fabrics = preset_fabrics(&m);
    let default = default_fabric(&m);
    let mut one_thread = default.clone();
    one_thread.name = "default, second set off";
    one_thread.use2 = false;
    let mut bumpy = default.clone();
    bumpy.name = "bumpy curve, satin threads";
    bumpy.t1 = fabrics[2].t1;
    bumpy.t2 = fabrics[2].t2;
    bumpy.p1 = Profile::Curve(bumpy_curve());
    fabrics.push(default);
    fabrics.push(one_thread);
    fabrics.push(bumpy);
    let fabrics: Vec<Fabric> = fabrics.iter().map(as_f32).collect();

    let mut cases = Vec::new();
    for (fi, _) in fabrics.iter().enumerate() {
        for (k, (t, b, n)) in frames().into_iter().enumerate() {
            let (t, b, n) = (round_f32(t), round_f32(b), round_f32(n));
            for (wi, wr) in direction_pairs(0x9E37_79B9 + 31 * fi as u64 + k as u64, t, b, n) {
                cases.push(Case {
                    fabric: fi,
                    n,
                    t,
                    b,
                    wi,
                    wr,
                });
            }
        }
    }
    let data: Vec<[f32; 4]> = cases
        .iter()
        .flat_map(|c| pack_case(&fabrics[c.fabric], c))
        .collect();
    let results = run_gpu(&compose_shader(), &data, cases.len());

    let expected: Vec<V3> = cases
        .iter()
        .map(|c| cloth_reference(&fabrics[c.fabric], c.n, c.t, c.b, c.wi, c.wr))
        .collect();

    println!(
        "\n{:<28} {:>5} {:>10} {:>12} {:>12} {:>12} {:>12}",
        "fabric", "cases", "peak", "max rel err", "max abs/pk", "fast: p95", "fast: max"
    );
    let mut worst_rel = 0.0f64;
    let mut failures = Vec::new();
    for (fi, fab) in fabrics.iter().enumerate() {
        let idx: Vec<usize> = (0..cases.len())
            .filter(|&i| cases[i].fabric == fi)
            .collect();
        let peak = idx.iter().flat_map(|&i| expected[i]).fold(0.0f64, f64::max);
        assert!(peak > 0.0, "{}: every case is zero", fab.name);
        let floor = ABS_FLOOR * peak;
        let (mut max_rel, mut max_abs) = (0.0f64, 0.0f64);
        let mut fast_err = Vec::new();
        for &i in &idx {
            let gpu = results[2 * i];
            let fast = results[2 * i + 1];
            for c in 0..3 {
                let (g, e, f) = (gpu[c] as f64, expected[i][c], fast[c] as f64);
                assert!(
                    g.is_finite() && g >= 0.0,
                    "{}: reference tier gave {g}",
                    fab.name
                );
                assert!(
                    f.is_finite() && f >= 0.0,
                    "{}: fast tier gave {f}",
                    fab.name
                );
                let err = (g - e).abs();
                max_abs = max_abs.max(err / peak);
                if e.abs() > floor {
                    max_rel = max_rel.max(err / e.abs());
                }
                if err > REL_TOL * e.abs() + floor {
                    failures.push(format!(
                        "{}: case {i} channel {c}: gpu {g:e}, f64 {e:e} (wi {:?}, wr {:?})",
                        fab.name, cases[i].wi, cases[i].wr
                    ));
                }
                if e > 1e-3 * peak {
                    fast_err.push((f - e).abs() / e);
                }
            }
        }
        fast_err.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let p95 = fast_err
            .get(fast_err.len() * 95 / 100)
            .copied()
            .unwrap_or(0.0);
        let fmax = fast_err.last().copied().unwrap_or(0.0);
        worst_rel = worst_rel.max(max_rel);
        println!(
            "{:<28} {:>5} {:>10.4e} {:>12.3e} {:>12.3e} {:>12.3e} {:>12.3e}",
            fab.name,
            idx.len(),
            peak,
            max_rel,
            max_abs,
            p95,
            fmax
        );
    }
    println!(
        "GPU reference tier vs f64: worst relative error {worst_rel:.3e} (tolerance {REL_TOL:e} + {ABS_FLOOR:e} x peak).\n\
         fast columns: |fast - reference| / reference over values above 1e-3 x peak (a report, not a check)."
    );
    assert!(
        failures.is_empty(),
        "{} mismatches:\n{}",
        failures.len(),
        failures[..failures.len().min(20)].join("\n")
    );
}

#[test]
fn gpu_extremes_are_finite_and_non_negative() {
    let _gpu = weft_tests::gpu_serial();
    // Degenerate geometry the stability sweep will throw at the material:
    // directions along the threads, L = V, L = -V at grazing, the normal,
    // the horizon, below it, and extreme parameters.
    let m = load_material();
    let mut fabrics = preset_fabrics(&m);
    let mut extreme = fabrics[0].clone();
    extreme.t1 = Thread {
        albedo: [1.0; 3],
        eta: 1.0,
        kd: 0.0,
        gamma_s: 0.5f64.to_radians(),
        gamma_v: 0.5f64.to_radians(),
        transmission: Transmission::PerDirection,
    };
    extreme.t2 = Thread {
        albedo: [1.0; 3],
        eta: 2.5,
        kd: 1.0,
        gamma_s: 90f64.to_radians(),
        gamma_v: 90f64.to_radians(),
        transmission: Transmission::PerDirection,
    };
    extreme.a1 = 1.0;
    extreme.a2 = 1.0;
    extreme.p1 = Profile::List(vec![90.0, -90.0, 90.0, -90.0, 0.0, 90.0, -90.0, 90.0]);
    let mut zero = fabrics[0].clone();
    zero.a1 = 0.0;
    zero.a2 = 0.0;
    let mut steep = fabrics[0].clone();
    let k = |time, value, slope| Keyframe {
        time,
        value,
        in_slope: slope,
        out_slope: slope,
    };
    steep.p1 = Profile::Curve(bake(&[
        k(0.0, -1.0, 60.0),
        k(0.5, 1.0, -60.0),
        k(1.0, -1.0, 0.0),
    ]));
    fabrics.extend([extreme, zero, steep]);
    let (t, b, n) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let g = 1e-4f64;
    let dirs: Vec<V3> = vec![
        n,
        t,
        scale(t, -1.0),
        b,
        norm([1.0, 0.0, g]),
        norm([-1.0, 0.0, g]),
        norm([0.0, 1.0, g]),
        norm([0.0, -1.0, 1e-7]),
        norm([1.0, 1.0, 0.0]),
        norm([0.3, 0.2, -0.5]),
        norm([0.6, 0.0, 0.8]),
        norm([-0.6, 0.0, 0.8]),
        norm([0.0, 0.6, 0.8]),
    ];
    let mut cases = Vec::new();
    for fi in 0..fabrics.len() {
        for &wi in &dirs {
            for &wr in &dirs {
                cases.push(Case {
                    fabric: fi,
                    n,
                    t,
                    b,
                    wi: round_f32(wi),
                    wr: round_f32(wr),
                });
            }
        }
        // Zero-length and non-orthogonal frames are handled by
        // weft_tangent_frame before the BSDF; the BSDF itself gets a frame.
    }
    let data: Vec<[f32; 4]> = cases
        .iter()
        .flat_map(|c| pack_case(&fabrics[c.fabric], c))
        .collect();
    let results = run_gpu(&compose_shader(), &data, cases.len());
    let mut max_seen = 0.0f32;
    for (i, c) in cases.iter().enumerate() {
        for tier in 0..2 {
            for &x in &results[2 * i + tier][..3] {
                assert!(
                    x.is_finite() && x >= 0.0,
                    "{} tier {tier}: {x} at wi {:?} wr {:?}",
                    fabrics[c.fabric].name,
                    c.wi,
                    c.wr
                );
                max_seen = max_seen.max(x);
            }
        }
    }
    println!(
        "extremes: {} cases, all finite and >= 0; largest L_r/L_i {max_seen:e} (fs_main clamps at 65504)",
        cases.len()
    );
}
