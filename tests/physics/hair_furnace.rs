//! The hair material's fibre model (materials/lib/hair_bsdf.wgsl), evaluated
//! on lavapipe through wgpu from the shipped WGSL:
//!
//! - the white furnace (pbrt-v3's HairBSDF WhiteFurnace test): with σ_a = 0
//!   the fibre scatters all the light it receives, ∫ S(ω_o, ω_i) dω_i = 1
//!   (S = f |cos θ_i|), averaged over the offset h across the fibre; Monte
//!   Carlo over the sphere × h on the GPU, over a β_m × β_n × ω_o grid, with
//!   untilted (α = 0, pbrt's test) and tilted cuticle scales (α = 2°, 3°);
//!   and the fast tier's closed-form average (weft_hair_fast) in the same
//!   furnace, with a wider bar (its h averages are fitted);
//! - the WGSL against an independent f64 evaluation of pbrt-v3's model (I_0
//!   by quadrature of its integral, not its series; the cuticle tilts as
//!   pbrt-v3's HairBSDF::f applies them, to θ_o) at single offsets, and the
//!   material's h average (64 offsets) against a converged f64 one;
//! - the cuticle tilt's direction: R's peak moves by +2α in θ_i, TRT's by
//!   about -4α, on the GPU and in the f64 model;
//! - absorption only removes energy (σ_a > 0: below the furnace).
//!
//! A missing Vulkan adapter fails the test (install mesa-vulkan-drivers).

use std::f64::consts::PI;
use std::path::PathBuf;
use weft_render::Gpu;

fn library(name: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../materials/lib")
        .join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn gpu() -> Gpu {
    Gpu::new().unwrap_or_else(|e| panic!("the hair tests need a Vulkan adapter: {e}"))
}

/// Three kernels over the shipped library (with lib/brdf.wgsl, which it
/// includes, and the engine interface's π constants):
/// - `hair_points`: per point four vec4 in, (ω_o, γ_o), (ω_i, offsets),
///   (σ_a, η), (β_m, β_n, α°, φ), strand along +x (pbrt's frame); two vec4
///   out, S and the albedo, at the offset h = sin γ_o and azimuth φ (both
///   from f64 here, offsets = 0) or averaged over `offsets` cells as the
///   material does;
/// - `hair_furnace`: per thread three vec4 in, (ω_o, seed), (β_m, β_n, α°,
///   η), (samples, -, -, -); out (Σ x, Σ x², -, -) of x = 4π S_h(ω_o, ω_i)
///   for ω_i uniform on the sphere and h uniform in [-1, 1], σ_a = 0;
/// - `hair_longitudinal`: the four lobes' M_p at given angles.
const KERNEL: &str = r#"
@group(0) @binding(0) var<storage, read> hair_in: array<vec4<f32>>;
@group(0) @binding(1) var<storage, read_write> hair_out: array<vec4<f32>>;

fn test_lobes_at(hair: WeftHair, o: vec3<f32>, i: vec3<f32>, phi: f32, gamma_o: f32) -> WeftHairLobes {
    let sin_o = clamp(o.x, -1.0, 1.0);
    let cos_o = sqrt(max(1.0 - sin_o * sin_o, 0.0));
    let sin_i = clamp(i.x, -1.0, 1.0);
    let cos_i = sqrt(max(1.0 - sin_i * sin_i, 0.0));
    let mp = weft_hair_longitudinal(hair, sin_o, cos_o, sin_i, cos_i);
    return weft_hair_at_gamma(hair, sin_o, cos_o, phi, gamma_o, mp);
}

@compute @workgroup_size(64)
fn hair_points(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    if k >= arrayLength(&hair_out) / 2u {
        return;
    }
    let a = hair_in[4u * k];
    let b = hair_in[4u * k + 1u];
    let c = hair_in[4u * k + 2u];
    let d = hair_in[4u * k + 3u];
    let hair = weft_hair_params(c.xyz, c.w, d.x, d.y, d.z);
    let offsets = u32(b.w);
    var lobes: WeftHairLobes;
    if offsets == 0u {
        lobes = test_lobes_at(hair, a.xyz, b.xyz, d.w, a.w);
    } else {
        lobes = weft_hair_mean(hair, weft_hair_angles(vec3<f32>(1.0, 0.0, 0.0), a.xyz, b.xyz), offsets);
    }
    hair_out[2u * k] = vec4<f32>(lobes.s, 0.0);
    hair_out[2u * k + 1u] = vec4<f32>(lobes.albedo, 0.0);
}

// Per point two vec4 in, (sin θ_o, cos θ_o, sin θ_i, cos θ_i), (β_m, α°,
// -, -); out the four lobes' M_p.
@compute @workgroup_size(64)
fn hair_longitudinal(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    if k >= arrayLength(&hair_out) {
        return;
    }
    let a = hair_in[2u * k];
    let b = hair_in[2u * k + 1u];
    let hair = weft_hair_params(vec3<f32>(0.0), 1.55, b.x, 0.3, b.y);
    hair_out[k] = weft_hair_longitudinal(hair, a.x, a.y, a.z, a.w);
}

// PCG (Jarzynski & Olano 2020): 32-bit state to a uniform in [0, 1).
fn test_pcg(state: ptr<function, u32>) -> f32 {
    *state = *state * 747796405u + 2891336453u;
    let s = *state;
    let word = ((s >> ((s >> 28u) + 4u)) ^ s) * 277803737u;
    return f32(((word >> 22u) ^ word) >> 8u) * (1.0 / 16777216.0);
}

// A direction uniform on the sphere.
fn test_sphere(state: ptr<function, u32>) -> vec3<f32> {
    let z = 1.0 - 2.0 * test_pcg(state);
    let r = sqrt(max(1.0 - z * z, 0.0));
    let phi = 2.0 * WEFT_PI * test_pcg(state);
    return vec3<f32>(z, r * cos(phi), r * sin(phi));
}

@compute @workgroup_size(64)
fn hair_furnace(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    if k >= arrayLength(&hair_out) {
        return;
    }
    let a = hair_in[3u * k];
    let b = hair_in[3u * k + 1u];
    let samples = u32(hair_in[3u * k + 2u].x);
    let hair = weft_hair_params(vec3<f32>(0.0), b.w, b.x, b.y, b.z);
    var state = bitcast<u32>(a.w);
    var sum = 0.0;
    var sum2 = 0.0;
    for (var j = 0u; j < samples; j += 1u) {
        let i = test_sphere(&state);
        let gamma_o = asin(-1.0 + 2.0 * test_pcg(&state));
        let x = 4.0 * WEFT_PI * test_lobes_at(hair, a.xyz, i, atan2(i.z, i.y) - atan2(a.z, a.y), gamma_o).s.x;
        sum += x;
        sum2 += x * x;
    }
    hair_out[k] = vec4<f32>(sum, sum2, 0.0, 0.0);
}

// The fast tier's closed-form fibre average (weft_hair_fast), strand along
// +x: the same sampling of ω_i, no h (fast averages over it itself).
@compute @workgroup_size(64)
fn hair_furnace_fast(@builtin(global_invocation_id) id: vec3<u32>) {
    let k = id.x;
    if k >= arrayLength(&hair_out) {
        return;
    }
    let a = hair_in[3u * k];
    let b = hair_in[3u * k + 1u];
    let samples = u32(hair_in[3u * k + 2u].x);
    let hair = weft_hair_params(vec3<f32>(0.0), b.w, b.x, b.y, b.z);
    var state = bitcast<u32>(a.w);
    var sum = 0.0;
    var sum2 = 0.0;
    for (var j = 0u; j < samples; j += 1u) {
        let i = test_sphere(&state);
        let x = 4.0 * WEFT_PI * weft_hair_fast(hair, vec3<f32>(1.0, 0.0, 0.0), a.xyz, i).s.x;
        sum += x;
        sum2 += x * x;
    }
    hair_out[k] = vec4<f32>(sum, sum2, 0.0, 0.0);
}
"#;

fn source() -> String {
    format!(
        "const WEFT_PI: f32 = 3.14159265358979;\nconst WEFT_INV_PI: f32 = 0.318309886183791;\n{}\n{}\n{KERNEL}",
        library("brdf.wgsl"),
        library("hair_bsdf.wgsl")
    )
}

fn floats(bytes: &[u8]) -> Vec<f32> {
    bytes
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect()
}

fn push(buf: &mut Vec<u8>, values: &[f32]) {
    for v in values {
        buf.extend_from_slice(&v.to_le_bytes());
    }
}

/// The model's parameters, as the material passes them.
#[derive(Clone, Copy, Debug)]
struct Fibre {
    sigma_a: [f64; 3],
    eta: f64,
    beta_m: f64,
    beta_n: f64,
    alpha_deg: f64,
}

/// One evaluation: ω_o, ω_i (unit, strand along +x), the offset h, or the
/// material's h average over `offsets` offsets (then h is unused).
#[derive(Clone, Copy, Debug)]
struct Point {
    o: [f64; 3],
    i: [f64; 3],
    h: f64,
    offsets: u32,
    fibre: Fibre,
}

/// (S, albedo) per point from the shipped WGSL.
fn gpu_points(gpu: &Gpu, points: &[Point]) -> Vec<([f32; 3], [f32; 3])> {
    let mut input = Vec::new();
    for p in points {
        let f = p.fibre;
        let o = p.o.map(|x| x as f32);
        let i = p.i.map(|x| x as f32);
        // γ_o and φ from f64: Vulkan's asin/atan2 (4096 ulp) would move
        // them by ~5e-4 rad, a visible change where N_p is steep.
        let phi = p.i[2].atan2(p.i[1]) - p.o[2].atan2(p.o[1]);
        push(&mut input, &[o[0], o[1], o[2], p.h.asin() as f32]);
        push(&mut input, &[i[0], i[1], i[2], p.offsets as f32]);
        let s = f.sigma_a.map(|x| x as f32);
        push(&mut input, &[s[0], s[1], s[2], f.eta as f32]);
        push(
            &mut input,
            &[
                f.beta_m as f32,
                f.beta_n as f32,
                f.alpha_deg as f32,
                phi as f32,
            ],
        );
    }
    let out = gpu
        .run_compute(
            &source(),
            "hair_points",
            &input,
            (points.len() * 32) as u64,
            (points.len() as u32).div_ceil(64),
        )
        .expect("the hair kernel runs");
    floats(&out)
        .chunks_exact(8)
        .map(|c| ([c[0], c[1], c[2]], [c[4], c[5], c[6]]))
        .collect()
}

// ---------------------------------------------------------------- f64 model
// Written from the papers' formulas (d'Eon et al. 2011 eq. 7, Chiang et al.
// 2016 eqs. 7–11, Marschner et al. 2003 for η' and γ_t), not from the WGSL:
// I_0 by Simpson quadrature of (1/π) ∫_0^π e^{x cos t} dt, scaled by e^{-x}
// so that M_p is formed in log space at every roughness.

/// log I_0(x) = x + log((1/π) ∫_0^π e^{x (cos t - 1)} dt).
fn log_i0(x: f64) -> f64 {
    let n = 4096;
    let step = PI / n as f64;
    let mut sum = 0.0;
    for k in 0..=n {
        let t = k as f64 * step;
        let w = if k == 0 || k == n {
            1.0
        } else if k % 2 == 1 {
            4.0
        } else {
            2.0
        };
        sum += w * (x * (t.cos() - 1.0)).exp();
    }
    x + (sum * step / 3.0 / PI).ln()
}

/// M_p = exp(-sin θ_i sin θ_o / v) I_0(cos θ_i cos θ_o / v) / (2 v sinh(1/v)),
/// with log(2 v sinh(1/v)) = log v + 1/v + log(1 - e^{-2/v}).
fn mp(cos_i: f64, cos_o: f64, sin_i: f64, sin_o: f64, v: f64) -> f64 {
    let log_norm = v.ln() + 1.0 / v + (-(-2.0 / v).exp()).ln_1p();
    (log_i0(cos_i * cos_o / v) - sin_i * sin_o / v - log_norm).exp()
}

fn fresnel(cos_i: f64, eta: f64) -> f64 {
    let sin_t2 = (1.0 - cos_i * cos_i) / (eta * eta);
    if sin_t2 >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin_t2).sqrt();
    let rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    let rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    0.5 * (rs * rs + rp * rp)
}

/// The trimmed logistic around Φ_p, on the circle.
fn np(phi: f64, p: f64, s: f64, gamma_o: f64, gamma_t: f64) -> f64 {
    let mut d = phi - (2.0 * p * gamma_t - 2.0 * gamma_o + p * PI);
    while d > PI {
        d -= 2.0 * PI;
    }
    while d < -PI {
        d += 2.0 * PI;
    }
    let logistic = |x: f64| {
        let e = (-x.abs() / s).exp();
        e / (s * (1.0 + e) * (1.0 + e))
    };
    let cdf = |x: f64| 1.0 / (1.0 + (-x / s).exp());
    logistic(d) / (cdf(PI) - cdf(-PI))
}

/// The four lobes' M_p at (θ_o, θ_i) with pbrt-v3's cuticle tilts, as its
/// HairBSDF::f writes them since commit c65c588 (2019, "Correct importance
/// sampling as per d'Eon paper"; pbrt-v4 the same): θ_o' = θ_o - 2α for R,
/// θ_o + α for TT, θ_o + 4α for TRT, |cos θ_o'|, the residual untilted.
fn longitudinal_f64(f: &Fibre, theta_o: f64, theta_i: f64) -> [f64; 4] {
    let bm = f.beta_m;
    let v = (0.726 * bm + 0.812 * bm * bm + 3.7 * bm.powi(20)).powi(2);
    let vs = [v, v / 4.0, 4.0 * v, 4.0 * v];
    let a = f.alpha_deg.to_radians();
    let tilts = [-2.0 * a, a, 4.0 * a, 0.0];
    let (sin_i, cos_i) = theta_i.sin_cos();
    std::array::from_fn(|p| {
        let t = theta_o + tilts[p];
        mp(cos_i, t.cos().abs(), sin_i, t.sin(), vs[p])
    })
}

/// (S, albedo) at one offset h, ω in pbrt's frame (x along the strand).
fn lobes_f64(f: &Fibre, o: [f64; 3], i: [f64; 3], h: f64) -> ([f64; 3], [f64; 3]) {
    let (sin_o, sin_i) = (o[0], i[0]);
    let cos_o = (1.0 - sin_o * sin_o).sqrt();
    let phi = i[2].atan2(i[1]) - o[2].atan2(o[1]);
    let bn = f.beta_n;
    let s = (PI / 8.0).sqrt() * (0.265 * bn + 1.194 * bn * bn + 5.372 * bn.powi(22));
    let m = longitudinal_f64(f, sin_o.asin(), sin_i.asin());
    let gamma_o = h.asin();
    let sin_t = sin_o / f.eta;
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    let etap = (f.eta * f.eta - sin_o * sin_o).sqrt() / cos_o;
    let gamma_t = (h / etap).asin();
    let fr = fresnel(cos_o * (1.0 - h * h).sqrt(), f.eta);
    let (mut s_out, mut albedo) = ([0.0; 3], [0.0; 3]);
    for c in 0..3 {
        let t = (-f.sigma_a[c] * 2.0 * gamma_t.cos() / cos_t).exp();
        let a0 = fr;
        let a1 = (1.0 - fr) * (1.0 - fr) * t;
        let a2 = a1 * t * fr;
        let a3 = a2 * t * fr / (1.0 - t * fr);
        s_out[c] = m[0] * a0 * np(phi, 0.0, s, gamma_o, gamma_t)
            + m[1] * a1 * np(phi, 1.0, s, gamma_o, gamma_t)
            + m[2] * a2 * np(phi, 2.0, s, gamma_o, gamma_t)
            + m[3] * a3 / (2.0 * PI);
        albedo[c] = a0 + a1 + a2 + a3;
    }
    (s_out, albedo)
}

/// The average over h uniform in [-1, 1]: Simpson in h = sin γ, 2048
/// intervals (the converged value the material's 32 offsets approximate).
fn mean_f64(f: &Fibre, o: [f64; 3], i: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let n = 2048;
    let (mut s, mut albedo) = ([0.0; 3], [0.0; 3]);
    for k in 0..=n {
        let gamma = -PI / 2.0 + PI * k as f64 / n as f64;
        let w = if k == 0 || k == n {
            1.0
        } else if k % 2 == 1 {
            4.0
        } else {
            2.0
        } * gamma.cos()
            * (PI / n as f64)
            / 3.0
            / 2.0;
        let (sh, ah) = lobes_f64(f, o, i, gamma.sin());
        for c in 0..3 {
            s[c] += w * sh[c];
            albedo[c] += w * ah[c];
        }
    }
    (s, albedo)
}

fn unit(theta_deg: f64, phi_deg: f64) -> [f64; 3] {
    let (t, p) = (theta_deg.to_radians(), phi_deg.to_radians());
    [t.sin(), t.cos() * p.cos(), t.cos() * p.sin()]
}

const BROWN: Fibre = Fibre {
    sigma_a: [0.42, 0.9, 1.6],
    eta: 1.55,
    beta_m: 0.3,
    beta_n: 0.3,
    alpha_deg: 2.0,
};

// ---------------------------------------------------------------- tests

/// Relative agreement of S, GPU against f64, with γ_o and φ given (above).
/// Measured worst 3.1e-3: lavapipe's f32 asin (γ_t) and sin, which Vulkan
/// lets err by 4096 ulp and 2^-11, against N_p's slope 1/s; the WGSL's
/// formulas evaluated in numpy f32 agree with this f64 model to 1e-6. With
/// γ_o and φ through the GPU's asin/atan2 the worst was 1.8 % (β_n 0.15).
/// A formula error moves S by far more: pbrt's LogI0 term 1/(16x) by 0.5 %
/// at β_m 0.3, dropping log 2 from M_p by 50 %.
const S_TOLERANCE: f64 = 5e-3;

#[test]
fn wgsl_matches_an_independent_f64_evaluation() {
    let _gpu = weft_tests::gpu_serial();
    let gpu = gpu();
    let fibres = [
        BROWN,
        Fibre {
            sigma_a: [0.0; 3],
            eta: 1.55,
            beta_m: 0.1,
            beta_n: 0.6,
            alpha_deg: 3.0,
        },
        Fibre {
            sigma_a: [4.0, 6.0, 8.0],
            eta: 1.3,
            beta_m: 0.7,
            beta_n: 0.15,
            alpha_deg: 0.0,
        },
    ];
    // Near the R and TRT peaks (θ_i ≈ -θ_o) and elsewhere, forward and back.
    let pairs = [
        ((20.0, 10.0), (-22.0, 100.0)),
        ((0.0, 0.0), (4.0, 180.0)),
        ((45.0, 30.0), (-40.0, 60.0)),
        ((-60.0, 0.0), (55.0, 170.0)),
        ((10.0, 90.0), (30.0, -45.0)),
        ((75.0, 0.0), (-80.0, 150.0)),
    ];
    let mut points = Vec::new();
    for fibre in fibres {
        for ((to, po), (ti, pi)) in pairs {
            for h in [-0.9, -0.3, 0.0, 0.5, 0.95] {
                points.push(Point {
                    o: unit(to, po),
                    i: unit(ti, pi),
                    h,
                    offsets: 0,
                    fibre,
                });
            }
        }
    }
    let got = gpu_points(&gpu, &points);
    let mut worst = 0.0f64;
    for (p, (s, albedo)) in points.iter().zip(&got) {
        // The f64 model at the f32 inputs the GPU got (S is steep in φ).
        let f32_in = |v: [f64; 3]| v.map(|x| f64::from(x as f32));
        let h = f64::from(p.h as f32);
        let (want_s, want_albedo) = lobes_f64(&p.fibre, f32_in(p.o), f32_in(p.i), h);
        for c in 0..3 {
            let err = (f64::from(s[c]) - want_s[c]).abs() / (want_s[c].abs() + 1e-3);
            worst = worst.max(err);
            assert!(
                err < S_TOLERANCE,
                "{p:?} channel {c}: S GPU {} f64 {}",
                s[c],
                want_s[c]
            );
            assert!(
                (f64::from(albedo[c]) - want_albedo[c]).abs() < 1e-4,
                "{p:?} channel {c}: albedo GPU {} f64 {}",
                albedo[c],
                want_albedo[c]
            );
        }
    }
    eprintln!(
        "{} points: worst relative error of S {worst:.2e}",
        points.len()
    );
}

/// The material's h average with 64 offsets (its reference) against the
/// converged average (measured worst 0.6 %; 32 offsets: 3.4 % at β_n 0.15).
#[test]
fn the_reference_average_over_the_fibre_width_converges() {
    let _gpu = weft_tests::gpu_serial();
    let gpu = gpu();
    let mut points = Vec::new();
    for beta_n in [0.15, 0.3, 0.6] {
        let fibre = Fibre { beta_n, ..BROWN };
        for ((to, po), (ti, pi)) in [
            ((20.0, 0.0), (-22.0, 30.0)),
            ((20.0, 0.0), (-15.0, 120.0)),
            ((20.0, 0.0), (-25.0, 175.0)),
            ((-40.0, 0.0), (35.0, 90.0)),
            ((5.0, 0.0), (5.0, 150.0)),
        ] {
            points.push(Point {
                o: unit(to, po),
                i: unit(ti, pi),
                h: 0.0,
                offsets: 64,
                fibre,
            });
        }
    }
    let got = gpu_points(&gpu, &points);
    let mut worst = 0.0f64;
    for (p, (s, albedo)) in points.iter().zip(&got) {
        let (want_s, want_albedo) = mean_f64(&p.fibre, p.o, p.i);
        for c in 0..3 {
            let err = (f64::from(s[c]) - want_s[c]).abs() / want_s[c].max(1e-2);
            worst = worst.max(err);
            assert!(
                err < 0.03,
                "{p:?} channel {c}: 32 offsets {} converged {}",
                s[c],
                want_s[c]
            );
            assert!((f64::from(albedo[c]) - want_albedo[c]).abs() < 2e-3);
        }
    }
    eprintln!("64 offsets against 2048: worst relative error {worst:.4}");
}

/// One white-furnace case: (β_m, β_n, α in degrees, ω_o).
type FurnaceCase = (f64, f64, f64, [f64; 3]);

/// ∫ S dω_i per case on the GPU, 2^23 samples each (ω_i uniform on the
/// sphere, h uniform): returns (mean, Monte Carlo standard error) per case.
fn furnace(gpu: &Gpu, entry: &str, cases: &[FurnaceCase]) -> Vec<(f64, f64)> {
    const THREADS: usize = 256;
    const SAMPLES: u32 = 32768;
    let mut input = Vec::new();
    for (c, (beta_m, beta_n, alpha, o)) in cases.iter().enumerate() {
        for t in 0..THREADS {
            let seed = ((c * THREADS + t) as u32).wrapping_mul(2_654_435_761) ^ 0x9e37_79b9;
            let o = o.map(|x| x as f32);
            push(&mut input, &[o[0], o[1], o[2], f32::from_bits(seed)]);
            push(
                &mut input,
                &[*beta_m as f32, *beta_n as f32, *alpha as f32, 1.55],
            );
            push(&mut input, &[SAMPLES as f32, 0.0, 0.0, 0.0]);
        }
    }
    let threads = cases.len() * THREADS;
    let out = gpu
        .run_compute(
            &source(),
            entry,
            &input,
            (threads * 16) as u64,
            (threads as u32).div_ceil(64),
        )
        .expect("the furnace kernel runs");
    let sums = floats(&out);
    let n = (THREADS as f64) * f64::from(SAMPLES);
    (0..cases.len())
        .map(|c| {
            let (mut sum, mut sum2) = (0.0f64, 0.0f64);
            for t in 0..THREADS {
                sum += f64::from(sums[4 * (c * THREADS + t)]);
                sum2 += f64::from(sums[4 * (c * THREADS + t) + 1]);
            }
            let mean = sum / n;
            (mean, ((sum2 / n - mean * mean) / n).sqrt())
        })
        .collect()
}

/// pbrt-v3's bar for the furnace: ∫ S dω_i within [0.95, 1.05].
const PBRT_FURNACE: std::ops::RangeInclusive<f64> = 0.95..=1.05;

/// Every case's mean (kernel `entry`) within `bar` and its standard error
/// below 0.01; prints the range.
fn assert_furnace(
    label: &str,
    entry: &str,
    bar: std::ops::RangeInclusive<f64>,
    cases: &[FurnaceCase],
) {
    let results = furnace(&gpu(), entry, cases);
    let (mut lowest, mut highest, mut worst_error) = (f64::MAX, f64::MIN, 0.0f64);
    let mut failures = Vec::new();
    for ((beta_m, beta_n, alpha, o), (mean, error)) in cases.iter().zip(&results) {
        lowest = lowest.min(*mean);
        highest = highest.max(*mean);
        worst_error = worst_error.max(*error);
        if !bar.contains(mean) || *error > 0.01 {
            failures.push(format!(
                "β_m {beta_m}, β_n {beta_n}, α {alpha}°, ω_o {o:.3?}: ∫ S dω_i = {mean:.4} ± {error:.4}"
            ));
        }
    }
    eprintln!(
        "white furnace {label}, {} cases × 2^23 samples: {lowest:.4} to {highest:.4}, standard error at most {worst_error:.4}",
        cases.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// pbrt-v3's WhiteFurnace (α = 0, as pbrt's test): β_m, β_n ∈ {0.1, 0.3,
/// 0.5, 0.7, 0.9}, ω_o at three inclinations.
#[test]
fn white_furnace() {
    let _gpu = weft_tests::gpu_serial();
    let cases = furnace_cases(&[0.0], &[0.1, 0.3, 0.5, 0.7, 0.9]);
    assert_furnace("α = 0", "hair_furnace", PBRT_FURNACE, &cases);
}

/// The furnace with tilted scales (α = 2°, 3°). Tilting θ_o, as pbrt-v3
/// does, keeps ∫ M_p cos θ_i dθ_i = 1, so the fibre still scatters all the
/// light; tilting θ_i instead (weft before issue 28) gave 0.944 at the
/// grazing ω_o with β_m 0.1.
#[test]
fn white_furnace_with_tilted_scales() {
    let _gpu = weft_tests::gpu_serial();
    let cases = furnace_cases(&[2.0, 3.0], &[0.1, 0.5, 0.9]);
    assert_furnace("α = 2°, 3°", "hair_furnace", PBRT_FURNACE, &cases);
}

/// The fast tier's closed-form fibre average (weft_hair_fast) in the same
/// furnace, untilted and tilted. Its h averages are fitted, not integrated
/// (materials/hair/README.md), so its bar is wider than pbrt's: an f64 port
/// of it gave 0.981 to 1.081 over the α = 0 grid of `white_furnace` (highest
/// at the grazing ω_o) and 0.978 to 1.071 at α = 2°.
#[test]
fn white_furnace_of_the_fast_tier() {
    let _gpu = weft_tests::gpu_serial();
    let cases = furnace_cases(&[0.0, 2.0], &[0.1, 0.5, 0.9]);
    assert_furnace("fast, α = 0°, 2°", "hair_furnace_fast", 0.95..=1.10, &cases);
}

/// Every α × β_m × β_n, each at three ω_o: θ_o = 0°, 35° and -70° (near
/// grazing), at three azimuths.
fn furnace_cases(alphas: &[f64], betas: &[f64]) -> Vec<FurnaceCase> {
    let outgoing = [unit(0.0, 0.0), unit(35.0, 60.0), unit(-70.0, 200.0)];
    let mut cases = Vec::new();
    for &alpha in alphas {
        for &beta_m in betas {
            for &beta_n in betas {
                for o in outgoing {
                    cases.push((beta_m, beta_n, alpha, o));
                }
            }
        }
    }
    cases
}

/// The GPU's M_p of lobes R and TRT (weft_hair_longitudinal) over θ_i in
/// 0.05° steps at one θ_o: the θ_i (degrees) of each lobe's maximum.
fn gpu_longitudinal_peaks(gpu: &Gpu, beta_m: f64, alpha: f64, theta_o: f64) -> [f64; 2] {
    let grid: Vec<f64> = (-1400..=1400).map(|k| f64::from(k) * 0.05).collect();
    let (sin_o, cos_o) = theta_o.to_radians().sin_cos();
    let mut input = Vec::new();
    for theta_i in &grid {
        let (sin_i, cos_i) = theta_i.to_radians().sin_cos();
        push(
            &mut input,
            &[sin_o as f32, cos_o as f32, sin_i as f32, cos_i as f32],
        );
        push(&mut input, &[beta_m as f32, alpha as f32, 0.0, 0.0]);
    }
    let out = gpu
        .run_compute(
            &source(),
            "hair_longitudinal",
            &input,
            (grid.len() * 16) as u64,
            (grid.len() as u32).div_ceil(64),
        )
        .expect("the longitudinal kernel runs");
    let m = floats(&out);
    [0, 2].map(|lobe| {
        let best = (0..grid.len())
            .max_by(|&a, &b| m[4 * a + lobe].total_cmp(&m[4 * b + lobe]))
            .expect("a grid");
        grid[best]
    })
}

/// The f64 pbrt-v3 model's maximum of lobe p's M_p over θ_i (degrees), by
/// golden-section search (M_p is unimodal in θ_i).
fn f64_longitudinal_peak(fibre: &Fibre, theta_o: f64, lobe: usize) -> f64 {
    let value = |t: f64| longitudinal_f64(fibre, theta_o.to_radians(), t.to_radians())[lobe];
    let (mut a, mut b) = (-70.0f64, 70.0f64);
    let r = (5f64.sqrt() - 1.0) / 2.0;
    while b - a > 1e-3 {
        let (c, d) = (b - r * (b - a), a + r * (b - a));
        if value(c) > value(d) {
            b = d;
        } else {
            a = c;
        }
    }
    0.5 * (a + b)
}

/// The cuticle tilt moves the R highlight by +2α in θ_i at a fixed θ_o (its
/// peak from ≈ -θ_o to ≈ -θ_o + 2α; sin θ = ω·t with t from root to tip)
/// and TRT by about -4α, as pbrt-v3's model does: on a strand lit and seen
/// from the front, R then sits where the strand still rises towards the
/// viewer, nearer the root, and TRT nearer the tip. Before issue 28 weft
/// tilted θ_i, which moved R by -2α and TRT by +4α. Checked on the GPU
/// against the f64 pbrt-v3 model (peaks within 0.15°) and against the
/// expected shift (R within ±0.5α of 2α; TRT, whose lobe is 2× wider and
/// bends the shift, within ±1.5α of -4α: the model gives -4.4α at β_m 0.2).
#[test]
fn cuticle_tilt_moves_r_and_trt_highlights_as_pbrt() {
    let _gpu = weft_tests::gpu_serial();
    let gpu = gpu();
    let alpha = 3.0;
    let beta_m = 0.2;
    let base = Fibre {
        beta_m,
        alpha_deg: 0.0,
        ..BROWN
    };
    let tilted = Fibre {
        alpha_deg: alpha,
        ..base
    };
    for theta_o in [20.0, -30.0] {
        let flat = gpu_longitudinal_peaks(&gpu, beta_m, 0.0, theta_o);
        let shifted = gpu_longitudinal_peaks(&gpu, beta_m, alpha, theta_o);
        for (k, lobe) in [0usize, 2].into_iter().enumerate() {
            for (fibre, got) in [(&base, flat[k]), (&tilted, shifted[k])] {
                let want = f64_longitudinal_peak(fibre, theta_o, lobe);
                assert!(
                    (got - want).abs() < 0.15,
                    "θ_o {theta_o}°, lobe {lobe}, α {}°: GPU peak at θ_i {got}°, pbrt-v3 f64 {want:.3}°",
                    fibre.alpha_deg
                );
            }
        }
        let (r_shift, trt_shift) = (shifted[0] - flat[0], shifted[1] - flat[1]);
        eprintln!(
            "θ_o {theta_o}°, α {alpha}°: R peak {}° → {}° ({r_shift:+.2}°), TRT peak {}° → {}° ({trt_shift:+.2}°)",
            flat[0], shifted[0], flat[1], shifted[1]
        );
        assert!(
            (r_shift - 2.0 * alpha).abs() <= 0.5 * alpha,
            "θ_o {theta_o}°: R moved by {r_shift:+.2}° in θ_i, expected ≈ +2α = {:+}°",
            2.0 * alpha
        );
        assert!(
            (trt_shift + 4.0 * alpha).abs() <= 1.5 * alpha,
            "θ_o {theta_o}°: TRT moved by {trt_shift:+.2}° in θ_i, expected ≈ -4α = {:+}°",
            -4.0 * alpha
        );
    }
}

/// Absorption only removes energy: the h-averaged albedo is 1 at σ_a = 0,
/// decreasing in σ_a, and above the R lobe's share (the h-averaged Fresnel
/// A_0, f64), which absorption cannot remove.
#[test]
fn absorption_removes_energy() {
    let _gpu = weft_tests::gpu_serial();
    let gpu = gpu();
    let o = unit(25.0, 0.0);
    let i = unit(-25.0, 90.0);
    let points: Vec<Point> = [0.0, 0.5, 2.0, 8.0]
        .iter()
        .map(|&s| Point {
            o,
            i,
            h: 0.0,
            offsets: 64,
            fibre: Fibre {
                sigma_a: [s; 3],
                ..BROWN
            },
        })
        .collect();
    let got = gpu_points(&gpu, &points);
    let albedos: Vec<f32> = got.iter().map(|(_, a)| a[0]).collect();
    assert!((albedos[0] - 1.0).abs() < 1e-4, "σ_a = 0: {albedos:?}");
    assert!(
        albedos.windows(2).all(|w| w[1] < w[0]),
        "not decreasing: {albedos:?}"
    );
    let n = 4096;
    let fresnel_mean = (0..n)
        .map(|k| {
            let h = -1.0 + (2.0 * k as f64 + 1.0) / n as f64;
            fresnel(o[1].hypot(o[2]) * (1.0 - h * h).sqrt(), BROWN.eta)
        })
        .sum::<f64>()
        / n as f64;
    for a in &albedos {
        assert!(
            f64::from(*a) > fresnel_mean - 1e-3,
            "{albedos:?} below the R lobe's {fresnel_mean}"
        );
    }
    // σ_a = 8 leaves little but R: TT and TRT are below e^-8 of their light
    // at normal chords.
    assert!(
        f64::from(albedos[3]) < fresnel_mean + 0.03,
        "σ_a = 8: {albedos:?}, R alone {fresnel_mean}"
    );
}
