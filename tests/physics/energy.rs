//! White-furnace energy checks through the actual shader code, on lavapipe.
//!
//! 1. `lobes_conserve_energy` — a compute pass composed from the material
//!    library itself (materials/lib/brdf.wgsl, anisotropic.wgsl, sheen.wgsl,
//!    silk_brdf.wgsl, with the engine interface's WEFT_PI) integrates the
//!    directional albedo `E(v) = ∫ f(v, l) (n·l) dl` of each lobe over the
//!    hemisphere for a grid of N·V and roughness, Fresnel / colour = 1. The
//!    estimator is deterministic (Hammersley) one-sample MIS, balance
//!    heuristic, between cosine sampling and sampling the (anisotropic) GGX
//!    NDF of the lobe's own widths (its pdf computed in the kernel from the
//!    half vector's components, independently of the library's D): 2 x 65536
//!    samples per cell, in chunks of 4096 per invocation (Kahan-summed in
//!    f32, chunks added in f64; llvmpipe stops any loop nest after 65535
//!    iterations, so one invocation cannot take a whole cell). A reference
//!    lobe fails when `E > 1 + 4 standard errors + 2e-4` (the standard error
//!    from the pair means, conservative for a quasi-random sequence; 2e-4
//!    covers f32 rounding of the weights). Excesses that are understood and
//!    reported but not yet fixed may be listed in `KNOWN_EXCESSES` (printed,
//!    not failed); the list is empty: both found so far are fixed. Fast
//!    lobes are reported as their deviation from their reference lobe. The
//!    estimator is checked on Lambert (E = 1 within 1e-3) and the GGX
//!    reference lobe against the toolchain's split-sum LUT (an independent
//!    f64 CPU integration, 1024 samples per texel, read bilinearly: within
//!    0.015 inside its texel centres; the largest difference is at grazing
//!    N.V where the albedo is most curved).
//!
//! 2. `standard_white_furnace` — the standard material drawn by the runtime
//!    under a uniform white environment (radiance 1: every prefiltered mip is
//!    1 and the SH of a constant is exactly Y00 = 1/0.282095, so
//!    `weft_sh_irradiance` = 1) with the main light off, through the
//!    stability probe's tiles (N·V exact per tile). The output radiance is
//!    then the directional albedo of the whole shading model (specular IBL +
//!    diffuse ambient) for base colour white, metallic 1 (F0 = 1) and
//!    metallic 0 (dielectric). Reference must be <= 1 + 1e-3: the split-sum
//!    LUT is stored as two f16 values (rounding <= 2.4e-4 each near 1,
//!    bilinear interpolation of values that are each <= 1 by construction)
//!    and the environment is f16 (1.0 exactly); the fast tier's deviation is
//!    printed.
//!
//! `cargo test -p weft-tests --test physics energy:: -- --nocapture` prints the tables
//! quoted in docs/energy.md.

use weft_render::probe::{GeometricCase, Probe};
use weft_render::{CubeLevel, EnvironmentMaps, Gpu, Luts, Material, Renderer};
use weft_tests::repo;

const NV: [f32; 8] = [1.0, 0.9, 0.7, 0.5, 0.3, 0.15, 0.05, 0.01];
const ROUGHNESS: [f32; 8] = [0.0, 0.1, 0.2, 0.3, 0.5, 0.7, 0.85, 1.0];
/// Hammersley points per strategy (a power of two), CHUNK per invocation.
const SAMPLES_PER_STRATEGY: u32 = 65536;
const CHUNK: u32 = 4096;

/// What a lobe is checked for.
#[derive(Clone, Copy, PartialEq)]
enum Role {
    /// A reference-tier lobe: E <= 1 + tol is asserted.
    Reference,
    /// A fast-tier lobe: its deviation from this reference lobe is reported.
    Fast(&'static str),
    /// Printed only.
    Diagnostic,
}

/// (name, kernel id, role)
const LOBES: [(&str, u32, Role); 11] = [
    (
        "GGX D*V_smith_correlated (standard reference spec, F=1)",
        0,
        Role::Reference,
    ),
    (
        "GGX D*V_schlick_ggx (standard fast spec, F=1)",
        1,
        Role::Fast("GGX D*V_smith_correlated (standard reference spec, F=1)"),
    ),
    (
        "standard direct, white dielectric: (1-E(n.v))/pi + D*V_corr*F, F0=0.04",
        2,
        Role::Reference,
    ),
    (
        "standard direct fast, white dielectric: (1-F)/pi + D*V_schlick*F",
        3,
        Role::Fast("standard direct, white dielectric: (1-E(n.v))/pi + D*V_corr*F, F0=0.04"),
    ),
    (
        "aniso GGX D*V_corr, Kulla k=0.5 (silk/satin/gauze reference)",
        4,
        Role::Reference,
    ),
    ("aniso GGX D*V_corr, Kulla k=0.9", 5, Role::Reference),
    (
        "Charlie sheen D*V, colour 1 (velvet reference)",
        6,
        Role::Reference,
    ),
    (
        "bounded-albedo Ward, Kulla widths k=0.5 (silk reference)",
        7,
        Role::Reference,
    ),
    (
        "seed Ward 1992, same widths (silk fast)",
        8,
        Role::Fast("bounded-albedo Ward, Kulla widths k=0.5 (silk reference)"),
    ),
    ("Lambert, albedo 1", 9, Role::Reference),
    (
        "diagnostic: GGX with D from |n x h|^2 (kernel-side) * V_smith_correlated",
        10,
        Role::Diagnostic,
    ),
];

/// Reference-lobe excesses found by this test and reported (docs/energy.md),
/// not yet fixed in the library: (lobe, cells affected, why). They are
/// printed by `lobes_conserve_energy` instead of failing it.
/// (lobe name, whether a (N.V, r) cell is affected, why).
type KnownExcess = (&'static str, fn(f32, f32) -> bool, &'static str);

// Both excesses this test first found are fixed: GGX D from |n x h|^2
// (`weft_d_ggx_nh`) and the reference direct diffuse weighted by 1 - E(n.v).
const KNOWN_EXCESSES: [KnownExcess; 0] = [];

const KERNEL: &str = r#"
struct Cell { lobe: u32, n_dot_v: f32, roughness: f32, first: u32, e_spec: f32 }
@group(0) @binding(0) var<storage, read> cells: array<Cell>;
@group(0) @binding(1) var<storage, read_write> results: array<vec4<f32>>;

const SAMPLES: u32 = SAMPLES_PER_STRATEGY_U;
// E(n.v) of the specular lobe for the current cell (standard reference direct).
var<private> furnace_e_spec: f32;
const CHUNK: u32 = CHUNK_U;

fn furnace_radical_inverse(i: u32) -> f32 {
    return f32(reverseBits(i)) * 2.3283064365386963e-10;
}

// Sampling widths of the lobe (a_t, a_b).
fn furnace_alpha(lobe: u32, r: f32) -> vec2<f32> {
    if lobe == 4u || lobe == 7u || lobe == 8u { return weft_aniso_alpha_kulla(r, 0.5); }
    if lobe == 5u { return weft_aniso_alpha_kulla(r, 0.9); }
    let a = max(r, 0.045) * max(r, 0.045);
    return vec2<f32>(a, a);
}

// pdf of l when h is drawn from the anisotropic GGX NDF (D(h) (n.h)) and l = reflect(-v, h).
fn furnace_pdf_ggx(v: vec3<f32>, l: vec3<f32>, ax: f32, ay: f32) -> f32 {
    let h = normalize(v + l);
    if h.z <= 0.0 { return 0.0; }
    let x = h.x / ax;
    let y = h.y / ay;
    let q = x * x + y * y + h.z * h.z;
    let pdf_h = h.z / (3.14159265358979 * ax * ay * q * q);
    return pdf_h / max(4.0 * abs(dot(v, h)), 1e-12);
}

// f(v, l) (n.l) of one lobe; n = +z, T = +x, B = +y, v and l unit.
fn furnace_lobe(lobe: u32, v: vec3<f32>, l: vec3<f32>, r: f32) -> f32 {
    let n_dot_v = v.z;
    let n_dot_l = l.z;
    let h = weft_safe_normalize(v + l, vec3<f32>(0.0, 0.0, 1.0));
    let n_dot_h = h.z;
    let v_dot_h = saturate(dot(v, h));
    let nl = saturate(n_dot_l);
    switch lobe {
        case 0u: { return weft_d_ggx_nh(vec3<f32>(0.0, 0.0, 1.0), h, r) * weft_v_smith_ggx_correlated(n_dot_v, n_dot_l, r) * nl; }
        case 1u: { return weft_d_ggx_nh(vec3<f32>(0.0, 0.0, 1.0), h, r) * weft_v_schlick_ggx(n_dot_v, n_dot_l, r) * nl; }
        case 2u, 3u: {
            let f = weft_f_schlick(vec3<f32>(WEFT_DIELECTRIC_F0), v_dot_h).x;
            var vis = weft_v_smith_ggx_correlated(n_dot_v, n_dot_l, r);
            // As standard.wgsl: reference weights diffuse by 1 - E(n.v) (the
            // split-sum LUT's E for F0 = 0.04, passed per cell), fast by 1 - F(v.h).
            var kd = 1.0 - furnace_e_spec;
            if lobe == 3u {
                vis = weft_v_schlick_ggx(n_dot_v, n_dot_l, r);
                kd = 1.0 - f;
            }
            let diffuse = kd * weft_diffuse_lambert(vec3<f32>(1.0)).x;
            return (diffuse + weft_d_ggx_nh(vec3<f32>(0.0, 0.0, 1.0), h, r) * vis * f) * nl;
        }
        case 4u, 5u: {
            let a = furnace_alpha(lobe, r);
            return weft_spec_ggx_aniso(v, l, a.x, a.y);
        }
        case 6u: { return weft_sheen_charlie(vec3<f32>(1.0), n_dot_h, n_dot_v, n_dot_l, r).x; }
        case 7u: { return silk_ward_bounded(v, l, furnace_alpha(lobe, r)) * nl; }
        case 8u: { return silk_ward_seed(h, n_dot_l, n_dot_v, furnace_alpha(lobe, r)) * nl; }
        case 9u: { return weft_diffuse_lambert(vec3<f32>(1.0)).x * nl; }
        default: {
            let rc = weft_clamp_roughness(r);
            let a2 = rc * rc * rc * rc;
            let d = h.x * h.x + h.y * h.y + h.z * h.z * a2;
            return a2 / (WEFT_PI * d * d) * weft_v_smith_ggx_correlated(n_dot_v, n_dot_l, r) * nl;
        }
    }
}

// One invocation = one chunk of CHUNK Hammersley indices m of one cell;
// each m gives a pair (one cosine sample, one GGX-NDF sample). Writes
// (sum of pair means, sum of their squares, max weight). A single loop of
// CHUNK iterations: llvmpipe stops any loop nest after 65535 iterations.
@compute @workgroup_size(64)
fn furnace(@builtin(global_invocation_id) gid: vec3<u32>) {
    let idx = gid.x;
    if idx >= arrayLength(&cells) { return; }
    let cell = cells[idx];
    furnace_e_spec = cell.e_spec;
    let nv = cell.n_dot_v;
    let v = vec3<f32>(sqrt(max(1.0 - nv * nv, 0.0)), 0.0, nv);
    let a = furnace_alpha(cell.lobe, cell.roughness);
    // Kahan-compensated sums.
    var s = 0.0;
    var c = 0.0;
    var s2 = 0.0;
    var wmax = 0.0;
    for (var m = cell.first; m < cell.first + CHUNK; m++) {
        let u1 = (f32(m) + 0.5) / f32(SAMPLES);
        let phi = 6.283185307179586 * furnace_radical_inverse(m);
        let sr = sqrt(u1);
        let l_cos = vec3<f32>(sr * cos(phi), sr * sin(phi), sqrt(max(1.0 - u1, 0.0)));
        let slope = sqrt(u1 / (1.0 - u1));
        let h = normalize(vec3<f32>(-slope * a.x * cos(phi), -slope * a.y * sin(phi), 1.0));
        let l_ggx = 2.0 * dot(v, h) * h - v;
        let w0 = furnace_weight(cell.lobe, v, l_cos, cell.roughness, a);
        let w1 = furnace_weight(cell.lobe, v, l_ggx, cell.roughness, a);
        let pair = 0.5 * (w0 + w1);
        let y = pair - c;
        let t = s + y;
        c = (t - s) - y;
        s = t;
        s2 += pair * pair;
        wmax = max(wmax, max(w0, w1));
    }
    results[idx] = vec4<f32>(s, s2, wmax, 0.0);
}

// f (n.l) / pdf of the 50/50 mixture for one sample direction (0 below the horizon).
fn furnace_weight(lobe: u32, v: vec3<f32>, l_in: vec3<f32>, r: f32, a: vec2<f32>) -> f32 {
    if l_in.z <= 0.0 { return 0.0; }
    let l = normalize(l_in);
    let pdf = 0.5 * l.z * 0.318309886183791 + 0.5 * furnace_pdf_ggx(v, l, a.x, a.y);
    return furnace_lobe(lobe, v, l, r) / pdf;
}
"#;

/// The engine interface's WEFT_ constants, then the library files, then the kernel.
fn furnace_source() -> String {
    let root = repo();
    let interface = std::fs::read_to_string(
        root.join("crates/weft-compiler/src/compile/wgsl/engine_interface.wgsl"),
    )
    .unwrap();
    let mut src: String = interface
        .lines()
        .filter(|l| l.starts_with("const WEFT_"))
        .map(|l| format!("{l}\n"))
        .collect();
    for lib in ["brdf", "anisotropic", "sheen", "silk_brdf"] {
        let path = root.join(format!("materials/lib/{lib}.wgsl"));
        src +=
            &std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        src.push('\n');
    }
    src + &KERNEL
        .replace(
            "SAMPLES_PER_STRATEGY_U",
            &format!("{SAMPLES_PER_STRATEGY}u"),
        )
        .replace("CHUNK_U", &format!("{CHUNK}u"))
}

/// E = F0 scale + bias from the toolchain's split-sum LUT, bilinear at texel
/// centres as the shader's linear sampler reads it.
fn split_sum_e(n_dot_v: f32, roughness: f32, f0: f32) -> f32 {
    use weft_compiler::library::{SPLIT_SUM_LUT_SAMPLES, SPLIT_SUM_LUT_SIZE};
    static LUT: std::sync::OnceLock<Vec<[f32; 2]>> = std::sync::OnceLock::new();
    let lut = LUT.get_or_init(|| {
        weft_compiler::bake::split_sum::split_sum_lut(SPLIT_SUM_LUT_SIZE, SPLIT_SUM_LUT_SAMPLES)
    });
    let n = SPLIT_SUM_LUT_SIZE as f32;
    let at = |c: i32, r: i32| {
        let (c, r) = (
            c.clamp(0, n as i32 - 1) as usize,
            r.clamp(0, n as i32 - 1) as usize,
        );
        let [s, b] = lut[r * SPLIT_SUM_LUT_SIZE as usize + c];
        f0 * s + b
    };
    let (x, y) = (n_dot_v * n - 0.5, roughness * n - 0.5);
    let (x0, y0) = (x.floor(), y.floor());
    let (fx, fy) = (x - x0, y - y0);
    let (x0, y0) = (x0 as i32, y0 as i32);
    let top = at(x0, y0) * (1.0 - fx) + at(x0 + 1, y0) * fx;
    let bottom = at(x0, y0 + 1) * (1.0 - fx) + at(x0 + 1, y0 + 1) * fx;
    top * (1.0 - fy) + bottom * fy
}

/// [mean, standard error, max weight] per (lobe, n.v, roughness), in LOBES x NV x ROUGHNESS order.
fn integrate_on_gpu(gpu: &Gpu) -> Vec<[f32; 3]> {
    let mut cells: Vec<u32> = Vec::new();
    let chunks = SAMPLES_PER_STRATEGY / CHUNK;
    for (_, id, _) in LOBES {
        for nv in NV {
            for r in ROUGHNESS {
                let e = split_sum_e(nv, r, 0.04);
                for k in 0..chunks {
                    cells.extend([id, nv.to_bits(), r.to_bits(), k * CHUNK, e.to_bits()]);
                }
            }
        }
    }
    let n = cells.len() / 5;
    let bytes = gpu
        .run_compute(
            &furnace_source(),
            "furnace",
            bytemuck::cast_slice(&cells),
            (n * 16) as u64,
            (n as u32).div_ceil(64),
        )
        .unwrap_or_else(|e| panic!("the furnace kernel does not run with the library: {e}"));
    let v: &[f32] = bytemuck::cast_slice(&bytes);
    // Chunks -> cells, in f64.
    let n = f64::from(SAMPLES_PER_STRATEGY);
    v.chunks_exact(4 * chunks as usize)
        .map(|cell| {
            let (mut s, mut s2, mut wmax) = (0.0f64, 0.0f64, 0.0f32);
            for c in cell.chunks_exact(4) {
                s += f64::from(c[0]);
                s2 += f64::from(c[1]);
                wmax = wmax.max(c[2]);
            }
            let mean = s / n;
            let variance = (s2 / n - mean * mean).max(0.0);
            [mean as f32, (variance / n).sqrt() as f32, wmax]
        })
        .collect()
}

fn at(results: &[[f32; 3]], lobe: usize, i_nv: usize, i_r: usize) -> [f32; 3] {
    results[(lobe * NV.len() + i_nv) * ROUGHNESS.len() + i_r]
}

fn header(title: &str) {
    println!("\n{title}");
    print!("| N.V \\ r |");
    for r in ROUGHNESS {
        print!(" {r} |");
    }
    println!();
    println!("|---|{}", "---|".repeat(ROUGHNESS.len()));
}

/// The LUT's scale + bias (albedo at F0 = 1) at (n.v, r), bilinear between texel centres.
fn lut_albedo(luts: &Luts, nv: f32, r: f32) -> f32 {
    let lut = &luts.brdf;
    let n = lut.size as f32;
    let coord = |x: f32| {
        let t = (x * n - 0.5).clamp(0.0, n - 1.0);
        let i = (t.floor() as u32).min(lut.size - 2);
        (i, t - i as f32)
    };
    let (c, fc) = coord(nv);
    let (rr, fr) = coord(r);
    let e = |c: u32, r: u32| {
        let t = lut.texel(c, r);
        t[0] + t[1]
    };
    let top = e(c, rr) * (1.0 - fc) + e(c + 1, rr) * fc;
    let bottom = e(c, rr + 1) * (1.0 - fc) + e(c + 1, rr + 1) * fc;
    top * (1.0 - fr) + bottom * fr
}

/// Integrates every lobe, prints the tables and returns the reference-lobe
/// excesses: (known, unknown).
fn furnace_lobes() -> (Vec<String>, Vec<String>) {
    let gpu = Gpu::new().unwrap_or_else(|e| panic!("the energy check needs a Vulkan adapter: {e}"));
    let started = std::time::Instant::now();
    let results = integrate_on_gpu(&gpu);
    println!(
        "white furnace of the library lobes on {} ({} cells x 2 x {} samples) in {:.1}s",
        gpu.describe(),
        results.len(),
        SAMPLES_PER_STRATEGY,
        started.elapsed().as_secs_f64()
    );
    let (mut known, mut unknown) = (Vec::new(), Vec::new());
    let mut summary = Vec::new();
    for (li, (name, _, role)) in LOBES.iter().enumerate() {
        let reference = *role == Role::Reference;
        header(&format!(
            "E(N.V, r) of {name}{}",
            if reference { " [reference: <= 1]" } else { "" }
        ));
        let (mut max, mut max_at) = (f32::MIN, (0.0, 0.0));
        let (mut dev_max, mut dev_sum, mut dev_at) = (0.0f32, 0.0f32, (0.0, 0.0));
        let mut max_se = 0.0f32;
        for (i, nv) in NV.iter().enumerate() {
            print!("| {nv} |");
            for (j, r) in ROUGHNESS.iter().enumerate() {
                let [e, se, _] = at(&results, li, i, j);
                print!(" {e:.4} |");
                max_se = max_se.max(se);
                if e > max {
                    (max, max_at) = (e, (*nv, *r));
                }
                if reference && e > 1.0 + 4.0 * se + 2e-4 {
                    let line = format!("{name}: E = {e:.5} (± {se:.1e}) at N.V = {nv}, r = {r}");
                    let is_known = KNOWN_EXCESSES
                        .iter()
                        .any(|(lobe, cells, _)| lobe == name && cells(*nv, *r));
                    if is_known { &mut known } else { &mut unknown }.push(line);
                }
                if let Role::Fast(refname) = role {
                    let ri = LOBES.iter().position(|l| l.0 == *refname).unwrap();
                    let d = e - at(&results, ri, i, j)[0];
                    dev_sum += d.abs();
                    if d.abs() > dev_max.abs() {
                        (dev_max, dev_at) = (d, (*nv, *r));
                    }
                }
            }
            println!();
        }
        let mut line = format!(
            "{name}: max E {max:.4} at (N.V {}, r {}), max standard error {max_se:.1e}",
            max_at.0, max_at.1
        );
        if matches!(role, Role::Fast(_)) {
            line += &format!(
                "; fast - reference: max {dev_max:+.4} at (N.V {}, r {}), mean |dev| {:.4}",
                dev_at.0,
                dev_at.1,
                dev_sum / (NV.len() * ROUGHNESS.len()) as f32
            );
        }
        summary.push(line);
    }
    // Cross-check: the GPU integral of the reference GGX lobe against the
    // split-sum LUT (f64 CPU Hammersley bake, f16 storage).
    let luts = Luts::load_dir(repo().join("generated")).unwrap();
    let (mut lut_dev, mut lut_at) = (0.0f32, (0.0, 0.0));
    for (i, nv) in NV.iter().enumerate() {
        for (j, r) in ROUGHNESS.iter().enumerate() {
            // Inside the LUT's texel centres (it clamps beyond 0.5/64 of the edges).
            if (0.1..0.9).contains(r) && (0.05..0.95).contains(nv) {
                let d = at(&results, 0, i, j)[0] - lut_albedo(&luts, *nv, *r);
                if d.abs() > lut_dev {
                    (lut_dev, lut_at) = (d.abs(), (*nv, *r));
                }
            }
        }
    }
    println!("\nsummary:");
    for l in &summary {
        println!("- {l}");
    }
    println!(
        "- GGX reference lobe vs the split-sum LUT (scale + bias, bilinear), r in [0.1, 0.9), N.V in [0.05, 0.95): max |diff| {lut_dev:.4} at (N.V {}, r {})",
        lut_at.0, lut_at.1
    );
    assert!(
        lut_dev < 0.015,
        "the GPU integral disagrees with the split-sum LUT by {lut_dev}"
    );
    // The Lambert lobe integrates to exactly 1: a check of the estimator itself.
    let lambert = LOBES.iter().position(|l| l.1 == 9).unwrap();
    for i in 0..NV.len() {
        for j in 0..ROUGHNESS.len() {
            let e = at(&results, lambert, i, j)[0];
            assert!((e - 1.0).abs() < 1e-3, "Lambert: E = {e} at {i},{j}");
        }
    }
    (known, unknown)
}

#[test]
fn lobes_conserve_energy() {
    let _gpu = weft_tests::gpu_serial();
    let (known, unknown) = furnace_lobes();
    if !known.is_empty() {
        println!(
            "\nknown excesses ({}), reported in docs/energy.md:",
            known.len()
        );
        for (lobe, _, why) in KNOWN_EXCESSES {
            println!("- {lobe}: {why}");
        }
        for k in &known {
            println!("  {k}");
        }
    }
    assert!(
        unknown.is_empty(),
        "reference lobes reflect more than they receive:\n{}",
        unknown.join("\n")
    );
}

/// A uniform environment of radiance 1: every mip of every face 1, SH = Y00 only.
fn white_environment() -> EnvironmentMaps {
    let mips: Vec<CubeLevel> = [16u32, 8, 4, 2, 1]
        .iter()
        .map(|&size| CubeLevel {
            size,
            data: vec![[1.0; 3]; (size * size * 6) as usize],
        })
        .collect();
    let count = mips.len();
    let mut sh = [[0.0f32; 3]; 9];
    // Projection of L = 1 on Y00 is 4 pi 0.282095; the cosine convolution
    // divided by pi keeps band 0 (A_0 / pi = 1): c0 = 4 pi * 0.282095 = 1 / 0.282095.
    sh[0] = [(1.0 / 0.282095f64) as f32; 3];
    EnvironmentMaps {
        mips,
        mip_roughness: (0..count).map(|m| m as f64 / (count - 1) as f64).collect(),
        sh,
    }
}

#[test]
fn standard_white_furnace() {
    let _gpu = weft_tests::gpu_serial();
    let generated = repo().join("generated");
    let luts = Luts::load_dir(&generated).unwrap();
    let gpu = Gpu::new().unwrap_or_else(|e| panic!("the energy check needs a Vulkan adapter: {e}"));
    let mut renderer = Renderer::new(gpu, &white_environment(), &luts).unwrap();
    // One tile per N.V; N = +Z, V in the xz-plane, the light off.
    let cases: Vec<GeometricCase> = NV
        .iter()
        .map(|&nv| GeometricCase {
            name: format!("N.V={nv}"),
            normal: [0.0, 0.0, 1.0],
            tangent: [1.0, 0.0, 0.0, 1.0],
            view: [(1.0 - nv * nv).max(0.0).sqrt(), 0.0, nv],
            light: [0.0, 0.0, 1.0],
        })
        .collect();
    let probe = Probe::new(cases, [0.0; 3], 2, NV.len() as u32);
    let mut material = Material::load(generated.join("standard/standard.meta.json")).unwrap();
    let mut failures = Vec::new();
    let mut table = |tier: &str, metallic: f64| -> Vec<Vec<f32>> {
        material.reset().unwrap();
        material.set_tier(tier).unwrap();
        material.set("base_color", [1.0, 1.0, 1.0, 1.0]).unwrap();
        material.set("metallic", metallic).unwrap();
        let mut out = vec![vec![0.0f32; ROUGHNESS.len()]; NV.len()];
        for (j, r) in ROUGHNESS.iter().enumerate() {
            material.set("roughness", f64::from(*r)).unwrap();
            let prepared = renderer
                .prepare(&material, &probe.render_options())
                .unwrap();
            let tiles = probe.evaluate(&mut renderer, &prepared).unwrap();
            for (i, px) in tiles.iter().enumerate() {
                // Grey in, grey out: every pixel's channels agree. Pixels of
                // one tile agree within rounding, except where the fast
                // tier's nearest-texel table steps from one texel to the
                // next inside the tile (n.v varies a little across it): the
                // table's value is the tile's mean then.
                for p in px {
                    for c in &p[..3] {
                        assert!((c - p[0]).abs() < 1e-5, "{tier}: channels differ: {p:?}");
                    }
                }
                let mean = px.iter().map(|p| p[0]).sum::<f32>() / px.len() as f32;
                let spread = px.iter().map(|p| (p[0] - mean).abs()).fold(0.0, f32::max);
                assert!(
                    spread < if tier == "reference" { 1e-5 } else { 5e-3 },
                    "{tier}: pixels of one tile differ by {spread}"
                );
                out[i][j] = mean;
            }
        }
        out
    };
    let mut tables = Vec::new();
    for (label, metallic) in [("metal (F0 = 1)", 1.0), ("dielectric (F0 = 0.04)", 0.0)] {
        let reference = table("reference", metallic);
        let fast = table("fast", metallic);
        tables.push((label, reference, fast));
    }
    for (label, reference, fast) in &tables {
        for (tier, t) in [("reference", reference), ("fast", fast)] {
            header(&format!(
                "standard {tier}, white {label}: reflected radiance under a uniform white sky"
            ));
            for (i, nv) in NV.iter().enumerate() {
                print!("| {nv} |");
                for e in &t[i] {
                    print!(" {e:.4} |");
                }
                println!();
            }
        }
        let mut max_ref = 0.0f32;
        let (mut dev_max, mut dev_sum, mut dev_at) = (0.0f32, 0.0f32, (0.0, 0.0));
        for (i, nv) in NV.iter().enumerate() {
            for (j, r) in ROUGHNESS.iter().enumerate() {
                let e = reference[i][j];
                max_ref = max_ref.max(e);
                if e > 1.0 + 1e-3 {
                    failures.push(format!("reference {label}: {e} at N.V = {nv}, r = {r}"));
                }
                let d = fast[i][j] - e;
                dev_sum += d.abs();
                if d.abs() > dev_max.abs() {
                    (dev_max, dev_at) = (d, (*nv, *r));
                }
            }
        }
        println!(
            "\nstandard, white {label}: reference max {max_ref:.4}; fast - reference: max {dev_max:+.4} at (N.V {}, r {}), mean |dev| {:.4}",
            dev_at.0,
            dev_at.1,
            dev_sum / (NV.len() * ROUGHNESS.len()) as f32
        );
    }
    assert!(
        failures.is_empty(),
        "the standard reference tier reflects more than it receives:\n{}",
        failures.join("\n")
    );
}

/// The standard reference's direct diffuse is Lambert × (1 − E(n·v)) (weft's
/// choice for energy conservation; Filament weights only its indirect
/// diffuse: materials/standard/README.md). Prints the weight against
/// Lambert at F0 = 0.04 from the split-sum table as the shader reads it
/// (the README's table) and checks that the weight stays in [0, 1] (the
/// table's E ≤ 1) and is 1 − F0 at normal view.
#[test]
fn standard_direct_diffuse_weight_against_lambert() {
    let columns = [0.045f32, 0.1, 0.3, 0.5, 1.0];
    println!("n.v \\ r | {columns:?}");
    for nv in [1.0f32, 0.5, 0.2, 0.1, 0.05, 0.01] {
        let row: Vec<String> = columns
            .iter()
            .map(|&r| format!("{:.3}", 1.0 - split_sum_e(nv, r, 0.04)))
            .collect();
        println!("{nv} | {}", row.join(" | "));
    }
    let (mut lowest, mut at) = (1.0f32, (0.0f32, 0.0f32));
    for j in 0..=100 {
        let r = (j as f32 / 100.0).max(0.045);
        for i in 1..=200 {
            let nv = i as f32 / 200.0;
            let weight = 1.0 - split_sum_e(nv, r, 0.04);
            assert!((0.0..=1.0).contains(&weight), "(n.v {nv}, r {r}): {weight}");
            if weight < lowest {
                (lowest, at) = (weight, (nv, r));
            }
        }
    }
    println!("lowest weight {lowest:.3} at (n.v, r) = {at:?}");
    let normal = 1.0 - split_sum_e(1.0, 0.045, 0.04);
    assert!((normal - 0.96).abs() < 2e-3, "normal view: {normal}");
}
