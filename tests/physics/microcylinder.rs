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

/// Relative tolerance of the GPU (f32) reference tier against the f64 model.
/// f32 carries 24 bits (6e-8); a lobe is ~60 dependent operations, the
/// Gaussian exp(-theta_h^2 / 2 gamma^2) amplifies an angle error by at most
/// theta_h^2 / gamma^2 (< 40 where the lobe is not negligible) and lavapipe's
/// atan2/exp/cos are accurate to a few ulp, so genuine float error stays below
/// ~1e-5. 1e-3 leaves two orders of margin while any formula error (a factor,
/// a swapped angle, a wrong Fresnel cosine) is far larger.
const REL_TOL: f64 = 1e-3;
/// Absolute floor, as a fraction of the largest value of that fabric's cases:
/// near the zero crossings of max(cos phi, 0) and max(cos psi, 0) the value is
/// a tiny difference of O(1) numbers, so its f32 rounding (~1e-7 absolute) is
/// not small relative to it.
const ABS_FLOOR: f64 = 1e-5;

/// Samples of the baked tangent curves (`samples` in microcylinder.toml and
/// MC_CURVE_SAMPLES in the WGSL).
const CURVE_SAMPLES: usize = 33;

/// The materials root holding microcylinder/ and lib/ (overridable while
/// developing in a scratch root).
fn materials_root() -> PathBuf {
    std::env::var_os("WEFT_MICROCYLINDER_ROOT")
        .map(PathBuf::from)
        .unwrap_or_else(|| repo().join("materials"))
}

// ===========================================================================
// f64 model, written from the paper (not from the WGSL)

type V3 = [f64; 3];

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
fn sub(a: V3, b: V3) -> V3 {
    add(a, scale(b, -1.0))
}
fn norm(a: V3) -> V3 {
    scale(a, 1.0 / dot(a, a).sqrt())
}
/// Rodrigues: rotate x about the unit axis k by angle a.
fn rotate(x: V3, k: V3, a: f64) -> V3 {
    add(
        add(scale(x, a.cos()), scale(cross(k, x), a.sin())),
        scale(k, dot(k, x) * (1.0 - a.cos())),
    )
}

#[derive(Clone, Copy, Debug)]
struct Thread {
    /// Linear albedo A.
    albedo: V3,
    eta: f64,
    kd: f64,
    /// Radians.
    gamma_s: f64,
    gamma_v: f64,
    /// The volume term's Fresnel transmission (the material's: `PerDirection`).
    transmission: Transmission,
}

/// Readings of the volume term's F = F_t(η, ω_i) F_t(η', ω'_r) (README,
/// "The volume term's Fresnel transmission").
#[derive(Clone, Copy, Debug, PartialEq)]
enum Transmission {
    /// (1 - F_r(cos θ_i)) (1 - F_r(cos θ_r)): in through the fibre surface
    /// facing ω_i, out through the one facing ω_r (weft's reading).
    PerDirection,
    /// (1 - F_r(cos θ_d cos(φ_d/2)))²: both at the surface reflection's
    /// effective angle (the seed, path_tracer_cloth, Ushio's port).
    SquaredEffective,
}

/// Thread geometry: u along the thread, v the other thread set, n the normal.
#[derive(Clone, Copy, Debug)]
struct Frame {
    u: V3,
    v: V3,
    n: V3,
}

// Guards shared with the WGSL (lib/microcylinder.wgsl header).
const MIN_PROJ2: f64 = 1e-8;
const MIN_COS2_THETA_D: f64 = 1e-4;
const MIN_GAMMA: f64 = 0.1 * PI / 180.0;
const MIN_Q: f64 = 1e-6;
const SIGMA_U: f64 = 20.0 * PI / 180.0;

/// Unit-area Gaussian of the paper.
fn gauss(gamma: f64, x: f64) -> f64 {
    let g = gamma.max(MIN_GAMMA);
    (-x * x / (2.0 * g * g)).exp() / (2.0 * PI * g * g).sqrt()
}

/// Unit-height Gaussian u() of the shadowing/reweighting correlation.
fn u_corr(x: f64) -> f64 {
    (-x * x / (2.0 * SIGMA_U * SIGMA_U)).exp()
}

/// Unpolarised Fresnel reflectance of a dielectric (Walter et al. 2007,
/// eq. 22), cosine floored at 1e-4 as in lib/brdf.wgsl.
fn fresnel(cos_i: f64, eta: f64) -> f64 {
    let c = cos_i.abs().clamp(1e-4, 1.0);
    let g2 = eta * eta - 1.0 + c * c;
    if g2 < 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - c) / (g + c);
    let b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    (0.5 * a * a * (1.0 + b * b)).clamp(0.0, 1.0)
}

/// Angles of one direction pair against a tilted thread.
struct Angles {
    theta_i: f64,
    theta_r: f64,
    phi_d: f64,
    cos_phi_i: f64,
    cos_phi_r: f64,
    psi_d: f64,
    cos_psi_i: f64,
    cos_psi_r: f64,
}

/// The thread tilted by `alpha` (radians; the thread rises towards +n):
/// (u', n'). Axis k = u x n, so u -> u cos + n sin, n -> n cos - u sin.
fn tilt(f: &Frame, alpha: f64) -> (V3, V3) {
    let k = norm(cross(f.u, f.n));
    (rotate(f.u, k, alpha), rotate(f.n, k, alpha))
}

/// None where an azimuth is undefined (a direction within 1e-4 rad of u' or v).
fn angles(f: &Frame, alpha: f64, wi: V3, wr: V3) -> Option<Angles> {
    let (u, n) = tilt(f, alpha);
    let si = dot(wi, u).clamp(-1.0, 1.0);
    let sr = dot(wr, u).clamp(-1.0, 1.0);
    // Projections onto the plane normal to u' (phi) and to v (psi).
    let pi = sub(wi, scale(u, si));
    let pr = sub(wr, scale(u, sr));
    let qi = sub(wi, scale(f.v, dot(wi, f.v)));
    let qr = sub(wr, scale(f.v, dot(wr, f.v)));
    if [pi, pr, qi, qr].iter().any(|p| dot(*p, *p) < MIN_PROJ2) {
        return None;
    }
    let (pi, pr, qi, qr) = (norm(pi), norm(pr), norm(qi), norm(qr));
    Some(Angles {
        theta_i: si.asin(),
        theta_r: sr.asin(),
        phi_d: dot(pi, pr).clamp(-1.0, 1.0).acos(),
        cos_phi_i: dot(n, pi),
        cos_phi_r: dot(n, pr),
        psi_d: dot(qi, qr).clamp(-1.0, 1.0).acos(),
        cos_psi_i: dot(n, qi),
        cos_psi_r: dot(n, qr),
    })
}

/// The thread scattering function f_s (paper sec. 4), reference form:
/// exact Fresnel at cos(theta_d) cos(phi_d / 2) for the surface term and,
/// for the volume term, transmission in at theta_i and out at theta_r (or
/// the other reading, `Transmission`).
fn f_s(a: &Angles, th: &Thread) -> V3 {
    let theta_h = 0.5 * (a.theta_i + a.theta_r);
    let theta_d = 0.5 * (a.theta_i - a.theta_r);
    let (ci, cr) = (a.theta_i.cos(), a.theta_r.cos());
    let half_phi = (0.5 * a.phi_d).cos();
    let f_r = fresnel(theta_d.cos() * half_phi, th.eta);
    let surface = f_r * half_phi * gauss(th.gamma_s, theta_h);
    let f_t = match th.transmission {
        Transmission::PerDirection => (1.0 - fresnel(ci, th.eta)) * (1.0 - fresnel(cr, th.eta)),
        Transmission::SquaredEffective => (1.0 - f_r) * (1.0 - f_r),
    };
    let volume = f_t * ((1.0 - th.kd) * gauss(th.gamma_v, theta_h) + th.kd) / (ci + cr);
    let cd2 = (theta_d.cos() * theta_d.cos()).max(MIN_COS2_THETA_D);
    [0, 1, 2].map(|c| (surface + volume * th.albedo[c]) / cd2)
}

/// Shadowing/masking (phi) or reweighting (psi): the correlated/uncorrelated blend.
fn corr(ci: f64, cr: f64, d: f64) -> f64 {
    let (mi, mr) = (ci.max(0.0), cr.max(0.0));
    let u = u_corr(d);
    (1.0 - u) * mi * mr + u * mi.min(mr)
}

/// One offset sample: (f_s M P cos(theta_i), P); zeros when skipped.
fn sample(f: &Frame, alpha: f64, wi: V3, wr: V3, th: &Thread) -> (V3, f64) {
    match angles(f, alpha, wi, wr) {
        None => ([0.0; 3], 0.0),
        Some(a) => {
            let m = corr(a.cos_phi_i, a.cos_phi_r, a.phi_d);
            let p = corr(a.cos_psi_i, a.cos_psi_r, a.psi_d);
            let fs = f_s(&a, th);
            let w = m * p * a.theta_i.cos();
            (fs.map(|x| x * w), p)
        }
    }
}

/// Weighted mean over (angle in radians, weight) samples.
fn mean_over(f: &Frame, wi: V3, wr: V3, th: &Thread, samples: &[(f64, f64)]) -> (V3, f64) {
    let mut s = [0.0; 3];
    let mut p = 0.0;
    let mut wsum = 0.0;
    for &(alpha, w) in samples {
        let (si, pi) = sample(f, alpha, wi, wr, th);
        s = add(s, scale(si, w));
        p += w * pi;
        wsum += w;
    }
    (scale(s, 1.0 / wsum), p / wsum)
}

/// Reference quadrature of an offset list (degrees): the piecewise-linear
/// tangent curve through equally spaced control points, each segment split
/// into ceil(|delta| / step) midpoint sub-steps (at most `max_sub`; the
/// reference tier uses 1 deg and 64).
fn list_samples(offsets_deg: &[f64], step_deg: f64, max_sub: f64) -> Vec<(f64, f64)> {
    if offsets_deg.len() == 1 {
        return vec![(offsets_deg[0].to_radians(), 1.0)];
    }
    let mut out = Vec::new();
    for seg in offsets_deg.windows(2) {
        let m = ((seg[1] - seg[0]).abs() / step_deg - 1e-3)
            .ceil()
            .clamp(1.0, max_sub);
        for j in 0..m as usize {
            let t = (j as f64 + 0.5) / m;
            out.push(((seg[0] + (seg[1] - seg[0]) * t).to_radians(), 1.0 / m));
        }
    }
    out
}

/// Reference quadrature of a baked height curve over t in [0, 1]: each
/// segment of the polyline has offset atan(slope) (the seed's mapping) and
/// weight = its arc length.
fn curve_samples(h: &[f64]) -> Vec<(f64, f64)> {
    let dt = 1.0 / (h.len() - 1) as f64;
    h.windows(2)
        .map(|s| {
            let dh = s[1] - s[0];
            ((dh / dt).atan(), (dt * dt + dh * dh).sqrt())
        })
        .collect()
}

#[derive(Clone, Debug)]
enum Profile {
    /// Offsets in degrees.
    List(Vec<f64>),
    /// Baked heights over t in [0, 1].
    Curve(Vec<f64>),
}

impl Profile {
    fn reference_samples(&self) -> Vec<(f64, f64)> {
        match self {
            Profile::List(o) => list_samples(o, 1.0, 64.0),
            Profile::Curve(h) => curve_samples(h),
        }
    }
}

#[derive(Clone, Debug)]
struct Fabric {
    name: &'static str,
    t1: Thread,
    a1: f64,
    p1: Profile,
    t2: Thread,
    a2: f64,
    p2: Profile,
    use2: bool,
}

/// The cloth: L_r / L_i = (a1 S1 + a2 S2) / Q,
/// Q = a1 P1 + a2 P2 + (1 - a1 - a2)(n.wi); zero below either horizon.
#[allow(clippy::too_many_arguments)]
fn cloth_with(
    fab: &Fabric,
    n: V3,
    t: V3,
    b: V3,
    wi: V3,
    wr: V3,
    s1: &[(f64, f64)],
    s2: &[(f64, f64)],
) -> V3 {
    let (ndi, ndr) = (dot(n, wi), dot(n, wr));
    let warp = Frame { u: t, v: b, n };
    let weft = Frame { u: b, v: t, n };
    let (a1, a2) = (fab.a1, if fab.use2 { fab.a2 } else { 0.0 });
    let (r1, q1) = mean_over(&warp, wi, wr, &fab.t1, s1);
    let (r2, q2) = if fab.use2 {
        mean_over(&weft, wi, wr, &fab.t2, s2)
    } else {
        ([0.0; 3], 0.0)
    };
    let q = a1 * q1 + a2 * q2 + (1.0 - a1 - a2).max(0.0) * ndi.max(0.0);
    if ndi <= 0.0 || ndr <= 0.0 || q <= MIN_Q {
        return [0.0; 3];
    }
    [0, 1, 2].map(|c| (a1 * r1[c] + a2 * r2[c]).max(0.0) / q)
}

fn cloth_reference(fab: &Fabric, n: V3, t: V3, b: V3, wi: V3, wr: V3) -> V3 {
    cloth_with(
        fab,
        n,
        t,
        b,
        wi,
        wr,
        &fab.p1.reference_samples(),
        &fab.p2.reference_samples(),
    )
}

// ===========================================================================
// Table II (as transcribed in path_tracer_cloth src/main.rs; research notes
// sec. 1): eta, A (linear), k_d, gamma_s / gamma_v (deg), a, offsets (deg).

fn thread(eta: f64, color: V3, s: f64, kd: f64, gs: f64, gv: f64) -> Thread {
    Thread {
        albedo: color.map(|c| c * s),
        eta,
        kd,
        gamma_s: gs.to_radians(),
        gamma_v: gv.to_radians(),
        transmission: Transmission::PerDirection,
    }
}

fn table_ii() -> Vec<(&'static str, Fabric)> {
    let linen = thread(1.46, [0.2, 0.8, 1.0], 0.3, 0.3, 12.0, 24.0);
    let satin1 = thread(1.539, [1.0, 0.37, 0.3], 0.035, 0.1, 2.5, 5.0);
    let satin2 = thread(1.539, [1.0, 0.37, 0.3], 0.02, 0.7, 30.0, 60.0);
    let velvet = thread(1.46, [0.05, 0.02, 0.0], 0.3, 0.1, 6.0, 12.0);
    let l = |v: &[f64]| Profile::List(v.to_vec());
    let fab = |name, t1, a1, p1, t2, a2, p2| Fabric {
        name,
        t1,
        a1,
        p1,
        t2,
        a2,
        p2,
        use2: true,
    };
    vec![
        (
            "linen_plain",
            fab(
                "linen plain",
                linen,
                0.33,
                l(&[-25.0, 25.0]),
                linen,
                0.33,
                l(&[-25.0, 25.0]),
            ),
        ),
        (
            "silk_crepe_de_chine",
            fab(
                "silk crepe de chine",
                thread(1.345, [1.0, 0.95, 0.05], 0.12, 0.2, 5.0, 10.0),
                0.75,
                l(&[-35.0, -35.0, 35.0, 35.0]),
                thread(1.345, [1.0, 0.95, 0.05], 0.16, 0.3, 18.0, 32.0),
                0.25,
                l(&[0.0]),
            ),
        ),
        (
            "satin_charmeuse",
            fab(
                "satin charmeuse",
                satin1,
                0.9,
                l(&[-32.0, -32.0, -18.0, 0.0, 0.0, 18.0, 32.0, 32.0]),
                satin2,
                0.1,
                l(&[0.0]),
            ),
        ),
        (
            "satin_charmeuse_back",
            fab(
                "satin charmeuse back",
                satin1,
                0.67,
                l(&[-30.0, -30.0, 30.0, 30.0, -5.0, -5.0, 5.0, 5.0]),
                satin2,
                0.33,
                l(&[0.0]),
            ),
        ),
        (
            "silk_shot",
            fab(
                "silk shot",
                thread(1.345, [0.1, 1.0, 0.4], 0.2, 0.1, 4.0, 8.0),
                0.86,
                l(&[-25.0, -25.0, 25.0, 25.0]),
                thread(1.345, [1.0, 0.0, 0.1], 0.6, 0.1, 5.0, 10.0),
                0.14,
                l(&[0.0]),
            ),
        ),
        (
            "velvet",
            fab(
                "velvet",
                velvet,
                0.5,
                l(&[-90.0, -50.0]),
                velvet,
                0.5,
                l(&[-90.0, -55.0, 55.0, 90.0]),
            ),
        ),
    ]
}

// ===========================================================================
// The material file: presets against Table II, the default curves

fn load_material() -> weft_front::Material {
    let root = materials_root();
    let path = root.join("microcylinder/microcylinder.toml");
    let mut db = weft_front::SourceDb::new();
    let mut diags = weft_front::Diagnostics::new();
    match weft_front::load_material(&path, &root, &mut db, &mut diags) {
        Some(m) => m,
        None => panic!(
            "{} does not load:\n{}",
            path.display(),
            diags.render_plain(&db)
        ),
    }
}

fn preset_number(values: &[(String, PresetValue)], key: &str) -> f64 {
    match values.iter().find(|(k, _)| k == key) {
        Some((_, PresetValue::Param(ParamValue::Float(x)))) => *x,
        other => panic!("preset value {key}: {other:?}"),
    }
}

fn preset_vector(values: &[(String, PresetValue)], key: &str) -> Vec<f64> {
    match values.iter().find(|(k, _)| k == key) {
        Some((_, PresetValue::Param(ParamValue::Vector(v)))) => v.clone(),
        other => panic!("preset value {key}: {other:?}"),
    }
}

fn preset_keyword(values: &[(String, PresetValue)], key: &str) -> String {
    match values.iter().find(|(k, _)| k == key) {
        Some((_, PresetValue::Keyword(v))) => v.clone(),
        other => panic!("preset value {key}: {other:?}"),
    }
}

/// Checks one thread set of a preset against Table II; returns the preset's
/// own thread (linear albedo from its sRGB colour) and profile.
fn check_preset_thread(
    name: &str,
    values: &[(String, PresetValue)],
    j: u32,
    want: &Thread,
    want_a: f64,
    want_p: &Profile,
) -> (Thread, f64, Profile) {
    let k = |s: &str| format!("thread{j}_{s}");
    let srgb = preset_vector(values, &k("color"));
    let albedo = [0, 1, 2].map(|c| weft_front::samples::srgb_to_linear(srgb[c]));
    for c in 0..3 {
        assert!(
            (albedo[c] - want.albedo[c]).abs() <= 5e-5,
            "{name}: thread{j}_color decodes to {albedo:?}, Table II says {:?}",
            want.albedo
        );
    }
    let th = Thread {
        albedo,
        eta: preset_number(values, &k("ior")),
        kd: preset_number(values, &k("isotropy")),
        gamma_s: preset_number(values, &k("gamma_s")).to_radians(),
        gamma_v: preset_number(values, &k("gamma_v")).to_radians(),
        transmission: Transmission::PerDirection,
    };
    let a = preset_number(values, &k("coverage"));
    for (got, exp, what) in [
        (th.eta, want.eta, "ior"),
        (th.kd, want.kd, "isotropy"),
        (th.gamma_s, want.gamma_s, "gamma_s"),
        (th.gamma_v, want.gamma_v, "gamma_v"),
        (a, want_a, "coverage"),
    ] {
        assert!(
            (got - exp).abs() < 1e-12,
            "{name}: thread{j}_{what} = {got}, Table II says {exp}"
        );
    }
    let count = preset_number(values, &k("offset_count")) as usize;
    let mut all = preset_vector(values, &k("offsets_a"));
    all.extend(preset_vector(values, &k("offsets_b")));
    let offsets = all[..count].to_vec();
    match want_p {
        Profile::List(w) => assert_eq!(&offsets, w, "{name}: offsets of thread set {j}"),
        Profile::Curve(_) => unreachable!(),
    }
    (th, a, Profile::List(offsets))
}

/// The fabrics as the shipped presets define them (after checking them
/// against Table II).
fn preset_fabrics(m: &weft_front::Material) -> Vec<Fabric> {
    table_ii()
        .into_iter()
        .map(|(key, want)| {
            let p = m
                .presets
                .iter()
                .find(|p| p.name == key)
                .unwrap_or_else(|| panic!("preset `{key}` missing"));
            assert_eq!(
                preset_keyword(&p.values, "TANGENT_OFFSETS"),
                "list",
                "{key}"
            );
            assert_eq!(preset_keyword(&p.values, "USE_SECOND_PARA"), "on", "{key}");
            let (t1, a1, p1) = check_preset_thread(key, &p.values, 1, &want.t1, want.a1, &want.p1);
            let (t2, a2, p2) = check_preset_thread(key, &p.values, 2, &want.t2, want.a2, &want.p2);
            Fabric {
                name: want.name,
                t1,
                a1,
                p1,
                t2,
                a2,
                p2,
                use2: true,
            }
        })
        .collect()
}

/// The default keyframes of a curve parameter, baked as the toolchain bakes
/// them (then rounded to f32, which is what the uniform holds).
fn default_curve(m: &weft_front::Material, name: &str) -> Vec<f64> {
    let p = m.params.iter().find(|p| p.name == name).unwrap();
    assert_eq!(p.samples as usize, CURVE_SAMPLES, "{name}: samples");
    match &p.default {
        ParamValue::Curve(keys) => {
            let span = weft_front::samples::curve_time_range(keys);
            assert_eq!(
                span,
                [0.0, 1.0],
                "{name}: the shader assumes key times 0..1"
            );
            bake(keys)
        }
        other => panic!("{name}: {other:?}"),
    }
}

fn bake(keys: &[Keyframe]) -> Vec<f64> {
    weft_front::samples::sample_curve(keys, CURVE_SAMPLES as u32)
        .into_iter()
        .map(|x| x as f32 as f64)
        .collect()
}

fn default_fabric(m: &weft_front::Material) -> Fabric {
    let num = |n: &str| match &m.params.iter().find(|p| p.name == n).unwrap().default {
        ParamValue::Float(x) => *x,
        ParamValue::Int(x) => *x as f64,
        ParamValue::Vector(v) => v[0],
        other => panic!("{n}: {other:?}"),
    };
    let color = |n: &str| match &m.params.iter().find(|p| p.name == n).unwrap().default {
        ParamValue::Vector(v) => [0, 1, 2].map(|c| weft_front::samples::srgb_to_linear(v[c])),
        other => panic!("{n}: {other:?}"),
    };
    let th = |j: u32| Thread {
        albedo: color(&format!("thread{j}_color")),
        eta: num(&format!("thread{j}_ior")),
        kd: num(&format!("thread{j}_isotropy")),
        gamma_s: num(&format!("thread{j}_gamma_s")).to_radians(),
        gamma_v: num(&format!("thread{j}_gamma_v")).to_radians(),
        transmission: Transmission::PerDirection,
    };
    Fabric {
        name: "default (linen, curves)",
        t1: th(1),
        a1: num("thread1_coverage"),
        p1: Profile::Curve(default_curve(m, "thread1_curve")),
        t2: th(2),
        a2: num("thread2_coverage"),
        p2: Profile::Curve(default_curve(m, "thread2_curve")),
        use2: true,
    }
}

/// A steeper, asymmetric profile (slopes up to 1.5, i.e. offsets up to 56 deg).
fn bumpy_curve() -> Vec<f64> {
    let k = |time, value, slope| Keyframe {
        time,
        value,
        in_slope: slope,
        out_slope: slope,
    };
    bake(&[
        k(0.0, 0.0, 1.5),
        k(0.4, 0.25, 0.0),
        k(0.7, 0.1, -1.0),
        k(1.0, 0.0, 0.2),
    ])
}

// ===========================================================================
// Directions

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        // xorshift64*
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_F491_4F6C_DD1D) >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// A direction in the local frame with cos(polar) in [cmin, cmax].
fn local_dir(rng: &mut Rng, cmin: f64, cmax: f64) -> V3 {
    let c = cmin + (cmax - cmin) * rng.next();
    let s = (1.0 - c * c).sqrt();
    let phi = 2.0 * PI * rng.next();
    [s * phi.cos(), s * phi.sin(), c]
}

fn to_world(t: V3, b: V3, n: V3, d: V3) -> V3 {
    add(add(scale(t, d[0]), scale(b, d[1])), scale(n, d[2]))
}

fn round_f32(v: V3) -> V3 {
    v.map(|x| x as f32 as f64)
}

/// Two frames: axis-aligned, and a tilted one (tests nothing assumes n = z).
fn frames() -> Vec<(V3, V3, V3)> {
    let n = norm([0.3, -0.5, 0.81]);
    let t = norm(sub([1.0, 0.2, 0.0], scale(n, dot([1.0, 0.2, 0.0], n))));
    let b = cross(n, t);
    vec![
        ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]),
        (t, b, n),
    ]
}

/// Direction pairs (world, rounded to f32): random pairs and near-mirror pairs.
fn direction_pairs(seed: u64, t: V3, b: V3, n: V3) -> Vec<(V3, V3)> {
    let mut rng = Rng(seed);
    let mut out = Vec::new();
    for k in 0..96 {
        let wi = local_dir(&mut rng, 0.03, 0.995);
        let wr = if k % 3 == 0 {
            // Near the mirror direction, where the surface lobes peak.
            let m = [-wi[0], -wi[1], wi[2]];
            norm(add(m, scale(local_dir(&mut rng, -1.0, 1.0), 0.15)))
        } else {
            local_dir(&mut rng, 0.03, 0.995)
        };
        if wr[2] < 0.03 {
            continue;
        }
        out.push((
            round_f32(to_world(t, b, n, wi)),
            round_f32(to_world(t, b, n, wr)),
        ));
    }
    out
}

// ===========================================================================
// GPU

/// One case = 32 vec4 (layout of `Case` in the shader below).
const CASE_VEC4S: usize = 32;

const ENTRY: &str = r#"
struct Case {
    wi: vec4<f32>, wr: vec4<f32>, t: vec4<f32>, b: vec4<f32>, n: vec4<f32>,
    // rgb = linear albedo, w = eta
    albedo1: vec4<f32>,
    // k_d, gamma_s, gamma_v (radians), coverage
    p1: vec4<f32>,
    albedo2: vec4<f32>,
    p2: vec4<f32>,
    off1a: vec4<f32>, off1b: vec4<f32>, off2a: vec4<f32>, off2b: vec4<f32>,
    // x: 1 = offset list, 0 = curve; y, z: offset counts; w: 1 = second thread set
    mode: vec4<f32>,
    curve1: array<vec4<f32>, 9>,
    curve2: array<vec4<f32>, 9>,
}
@group(0) @binding(0) var<storage, read> cases: array<Case>;
// Two per case: reference tier, fast tier.
@group(0) @binding(1) var<storage, read_write> results: array<vec4<f32>>;

@compute @workgroup_size(64)
fn main(@builtin(global_invocation_id) gid: vec3<u32>) {
    let i = gid.x;
    if i >= arrayLength(&cases) {
        return;
    }
    let c = cases[i];
    let wi = c.wi.xyz;
    let wr = c.wr.xyz;
    let warp = McFrame(c.t.xyz, c.b.xyz, c.n.xyz);
    let weft = McFrame(c.b.xyz, c.t.xyz, c.n.xyz);
    let th1 = McThread(c.albedo1.xyz, c.albedo1.w, c.p1.x, c.p1.y, c.p1.z);
    let th2 = McThread(c.albedo2.xyz, c.albedo2.w, c.p2.x, c.p2.y, c.p2.z);
    let use2 = c.mode.w > 0.5;
    let a2 = select(0.0, c.p2.w, use2);
    var r1 = vec4<f32>(0.0);
    var r2 = vec4<f32>(0.0);
    var f1 = vec4<f32>(0.0);
    var f2 = vec4<f32>(0.0);
    if c.mode.x > 0.5 {
        let n1 = i32(c.mode.y);
        let n2 = i32(c.mode.z);
        r1 = mc_thread_list_reference(warp, wi, wr, th1, c.off1a, c.off1b, n1);
        f1 = mc_thread_list_fast(warp, wi, wr, th1, c.off1a, c.off1b, n1);
        if use2 {
            r2 = mc_thread_list_reference(weft, wi, wr, th2, c.off2a, c.off2b, n2);
            f2 = mc_thread_list_fast(weft, wi, wr, th2, c.off2a, c.off2b, n2);
        }
    } else {
        r1 = mc_thread_curve_reference(warp, wi, wr, th1, c.curve1);
        f1 = mc_thread_curve_fast(warp, wi, wr, th1, c.curve1);
        if use2 {
            r2 = mc_thread_curve_reference(weft, wi, wr, th2, c.curve2);
            f2 = mc_thread_curve_fast(weft, wi, wr, th2, c.curve2);
        }
    }
    let ndi = dot(c.n.xyz, wi);
    let ndr = dot(c.n.xyz, wr);
    results[2u * i] = vec4<f32>(mc_combine(r1, r2, c.p1.w, a2, ndi, ndr), 0.0);
    results[2u * i + 1u] = vec4<f32>(mc_combine(f1, f2, c.p1.w, a2, ndi, ndr), 0.0);
}
"#;

/// The compute module: the engine-interface constants the library uses, then
/// lib/brdf.wgsl, lib/half.wgsl (with `weft_half` = f32), lib/microcylinder.wgsl
/// and the entry point.
fn compose_shader() -> String {
    let root = materials_root();
    let read = |p: &str| {
        std::fs::read_to_string(root.join(p))
            .unwrap_or_else(|e| panic!("{}: {e}", root.join(p).display()))
    };
    let lib = read("lib/microcylinder.wgsl");
    assert!(
        lib.contains(&format!("const MC_CURVE_SAMPLES: u32 = {CURVE_SAMPLES}u;")),
        "MC_CURVE_SAMPLES in lib/microcylinder.wgsl must be {CURVE_SAMPLES}"
    );
    // The library must stay pure: no material uniform, frame or binding
    // (comments aside).
    let code: String = lib
        .lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n");
    for forbidden in [
        "material.",
        "weft_frame",
        "@group",
        "@binding",
        "textureSample",
    ] {
        assert!(
            !code.contains(forbidden),
            "lib/microcylinder.wgsl uses `{forbidden}`"
        );
    }
    // The low tier's code in the library computes in `weft_half`
    // (lib/half.wgsl): composed here in f32, as a material's f32 fallback.
    format!(
        "const WEFT_PI: f32 = 3.14159265358979;\nconst WEFT_INV_PI: f32 = 0.318309886183791;\nalias weft_half = f32;\n{}\n{}\n{}\n{}",
        read("lib/brdf.wgsl"),
        read("lib/half.wgsl"),
        lib,
        ENTRY
    )
}

struct Case {
    fabric: usize,
    n: V3,
    t: V3,
    b: V3,
    wi: V3,
    wr: V3,
}

fn pack_case(fab: &Fabric, c: &Case) -> [[f32; 4]; CASE_VEC4S] {
    let mut v = [[0.0f32; 4]; CASE_VEC4S];
    let v3 = |a: V3, w: f64| [a[0] as f32, a[1] as f32, a[2] as f32, w as f32];
    v[0] = v3(c.wi, 0.0);
    v[1] = v3(c.wr, 0.0);
    v[2] = v3(c.t, 0.0);
    v[3] = v3(c.b, 0.0);
    v[4] = v3(c.n, 0.0);
    v[5] = v3(fab.t1.albedo, fab.t1.eta);
    v[6] = [
        fab.t1.kd as f32,
        fab.t1.gamma_s as f32,
        fab.t1.gamma_v as f32,
        fab.a1 as f32,
    ];
    v[7] = v3(fab.t2.albedo, fab.t2.eta);
    v[8] = [
        fab.t2.kd as f32,
        fab.t2.gamma_s as f32,
        fab.t2.gamma_v as f32,
        fab.a2 as f32,
    ];
    let mut mode = [0.0f32, 0.0, 0.0, if fab.use2 { 1.0 } else { 0.0 }];
    for (j, p) in [&fab.p1, &fab.p2].into_iter().enumerate() {
        match p {
            Profile::List(o) => {
                mode[0] = 1.0;
                mode[1 + j] = o.len() as f32;
                for (k, x) in o.iter().enumerate() {
                    v[9 + 2 * j + k / 4][k % 4] = *x as f32;
                }
            }
            Profile::Curve(h) => {
                for (k, x) in h.iter().enumerate() {
                    v[14 + 9 * j + k / 4][k % 4] = *x as f32;
                }
            }
        }
    }
    v[13] = mode;
    v
}

/// The fabric as the GPU sees it (every input rounded to f32), so that the
/// comparison measures arithmetic only.
fn as_f32(f: &Fabric) -> Fabric {
    let r = |x: f64| x as f32 as f64;
    let th = |t: &Thread| Thread {
        albedo: t.albedo.map(r),
        eta: r(t.eta),
        kd: r(t.kd),
        gamma_s: r(t.gamma_s),
        gamma_v: r(t.gamma_v),
        transmission: t.transmission,
    };
    let p = |p: &Profile| match p {
        Profile::List(o) => Profile::List(o.iter().map(|x| r(*x)).collect()),
        Profile::Curve(h) => Profile::Curve(h.iter().map(|x| r(*x)).collect()),
    };
    Fabric {
        name: f.name,
        t1: th(&f.t1),
        a1: r(f.a1),
        p1: p(&f.p1),
        t2: th(&f.t2),
        a2: r(f.a2),
        p2: p(&f.p2),
        use2: f.use2,
    }
}

fn run_gpu(shader: &str, data: &[[f32; 4]], n_cases: usize) -> Vec<[f32; 4]> {
    let gpu = weft_render::Gpu::new().unwrap_or_else(|e| panic!("{e}"));
    eprintln!("adapter: {}", gpu.describe());
    let bytes = gpu
        .run_compute(
            shader,
            "main",
            bytemuck::cast_slice(data),
            (n_cases * 2 * 16) as u64,
            n_cases.div_ceil(64) as u32,
        )
        .unwrap_or_else(|e| panic!("wgpu: {e}"));
    bytemuck::cast_slice::<u8, [f32; 4]>(&bytes).to_vec()
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

#[test]
fn reciprocity_of_the_published_model() {
    // f(wi, wr) = L_r / (L_i n.wi) = (a1 S1 + a2 S2) / (Q n.wi). f_s, M and P
    // are symmetric in (wi, wr); S carries cos(theta_i) and Q's gap term
    // (1 - a1 - a2) n.wi depends on wi only, so the published form is not.
    let m = load_material();
    let fabrics = preset_fabrics(&m);
    let (t, b, n) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    println!(
        "\n{:<24} {:>12} {:>14} {:>14} {:>14} {:>14}",
        "fabric", "f_s M P", "f median", "f p95", "f max", "f no-gap max"
    );
    let mut rng = Rng(12345);
    let mut all_max = 0.0f64;
    for fab in &fabrics {
        let s1 = fab.p1.reference_samples();
        let s2 = fab.p2.reference_samples();
        let mut sym_lobe = 0.0f64;
        let mut rel = Vec::new();
        let mut rel_nogap = Vec::new();
        let mut rel_l = Vec::new();
        let mut nogap = fab.clone();
        // Same model with Q's gap term removed (a1 + a2 rescaled to 1).
        let s = fab.a1 + fab.a2;
        nogap.a1 /= s;
        nogap.a2 /= s;
        for _ in 0..400 {
            let wi = local_dir(&mut rng, 0.05, 0.99);
            let wr = local_dir(&mut rng, 0.05, 0.99);
            // The per-sample thread function f_s M P (no cos(theta_i), no Q).
            for (frame, th, samples) in [
                (Frame { u: t, v: b, n }, &fab.t1, &s1),
                (Frame { u: b, v: t, n }, &fab.t2, &s2),
            ] {
                for &(alpha, _) in samples.iter() {
                    if let (Some(a), Some(r)) =
                        (angles(&frame, alpha, wi, wr), angles(&frame, alpha, wr, wi))
                    {
                        let fa = f_s(&a, th);
                        let fr = f_s(&r, th);
                        let ma = corr(a.cos_phi_i, a.cos_phi_r, a.phi_d)
                            * corr(a.cos_psi_i, a.cos_psi_r, a.psi_d);
                        let mr = corr(r.cos_phi_i, r.cos_phi_r, r.phi_d)
                            * corr(r.cos_psi_i, r.cos_psi_r, r.psi_d);
                        for c in 0..3 {
                            let (x, y) = (fa[c] * ma, fr[c] * mr);
                            if x.max(y) > 0.0 {
                                sym_lobe = sym_lobe.max((x - y).abs() / x.max(y));
                            }
                        }
                    }
                }
            }
            let brdf = |f: &Fabric, i: V3, r: V3| {
                let l = cloth_with(f, n, t, b, i, r, &s1, &s2);
                l.map(|x| x / dot(n, i))
            };
            let (fir, fri) = (brdf(fab, wi, wr), brdf(fab, wr, wi));
            let (gir, gri) = (brdf(&nogap, wi, wr), brdf(&nogap, wr, wi));
            let (lir, lri) = (
                cloth_with(fab, n, t, b, wi, wr, &s1, &s2),
                cloth_with(fab, n, t, b, wr, wi, &s1, &s2),
            );
            for c in 0..3 {
                if lir[c].max(lri[c]) > 1e-6 {
                    rel_l.push((lir[c] - lri[c]).abs() / lir[c].max(lri[c]));
                }
            }
            for c in 0..3 {
                if fir[c].max(fri[c]) > 1e-6 {
                    rel.push((fir[c] - fri[c]).abs() / fir[c].max(fri[c]));
                }
                if gir[c].max(gri[c]) > 1e-6 {
                    rel_nogap.push((gir[c] - gri[c]).abs() / gir[c].max(gri[c]));
                }
            }
        }
        rel.sort_by(|a, b| a.partial_cmp(b).unwrap());
        rel_nogap.sort_by(|a, b| a.partial_cmp(b).unwrap());
        let med = rel[rel.len() / 2];
        let p95 = rel[rel.len() * 95 / 100];
        let max = *rel.last().unwrap();
        let ng = *rel_nogap.last().unwrap();
        all_max = all_max.max(max);
        println!(
            "{:<24} {:>12.2e} {:>14.4} {:>14.4} {:>14.4} {:>14.4}",
            fab.name, sym_lobe, med, p95, max, ng
        );
        println!(
            "{:<24} {:>12} {:>14.4} (median of L_r/L_i = f n.wi, i.e. without the 1/n.wi)",
            "",
            "",
            {
                let mut v = rel_l.clone();
                v.sort_by(|a, b| a.partial_cmp(b).unwrap());
                v[v.len() / 2]
            }
        );
        assert!(
            sym_lobe < 1e-12,
            "{}: f_s M P is not symmetric ({sym_lobe:e})",
            fab.name
        );
        assert!(
            max > 1e-3,
            "{}: the Q-normalised model measured reciprocal ({max:e})?",
            fab.name
        );
    }
    println!(
        "relative reciprocity error |f(wi,wr) - f(wr,wi)| / max: columns over 400 random pairs x 3 channels \
         (cos polar in [0.05, 0.99]); worst {all_max:.3}"
    );
}

#[test]
fn normalisations_and_quadrature() {
    // The surface and volume Gaussians have unit area over the real line.
    for deg in [0.5, 2.5, 12.0, 30.0, 60.0] {
        let g = f64::to_radians(deg);
        let n = 20000;
        let (lo, hi) = (-12.0 * g, 12.0 * g);
        let h = (hi - lo) / n as f64;
        let area: f64 = (0..n)
            .map(|k| gauss(g, lo + (k as f64 + 0.5) * h) * h)
            .sum();
        assert!((area - 1.0).abs() < 1e-9, "gamma {deg} deg: area {area}");
        // theta_h only spans [-pi/2, pi/2]: the mass the model actually sees.
        let m = 20000;
        let hh = PI / m as f64;
        let inside: f64 = (0..m)
            .map(|k| gauss(g, -PI / 2.0 + (k as f64 + 0.5) * hh) * hh)
            .sum();
        println!(
            "gamma {deg:>5} deg: area over R {area:.12}, over theta_h in [-90, 90] deg {inside:.6}"
        );
    }

    // A flat curve is the single offset 0: both quadratures reduce to it.
    let m = load_material();
    let fabs = preset_fabrics(&m);
    let (t, b, n) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let mut flat = fabs[0].clone();
    flat.p1 = Profile::Curve(vec![0.0; CURVE_SAMPLES]);
    flat.p2 = Profile::Curve(vec![0.3; CURVE_SAMPLES]);
    let mut single = fabs[0].clone();
    single.p1 = Profile::List(vec![0.0]);
    single.p2 = Profile::List(vec![0.0]);
    let mut rng = Rng(777);
    for _ in 0..200 {
        let wi = local_dir(&mut rng, 0.05, 0.99);
        let wr = local_dir(&mut rng, 0.05, 0.99);
        let a = cloth_reference(&flat, n, t, b, wi, wr);
        let c = cloth_reference(&single, n, t, b, wi, wr);
        for k in 0..3 {
            assert!(
                (a[k] - c[k]).abs() <= 1e-12 * a[k].abs().max(1e-12),
                "flat curve {a:?} vs offset 0 {c:?}"
            );
        }
    }

    // The reference tier's offset quadrature (<= 1 deg sub-steps, at most 64
    // per segment) against a 0.02 deg one: relative error over values above
    // 1e-3 x peak, and absolute error over the peak.
    println!(
        "\n{:<24} {:>14} {:>14}",
        "fabric", "rel. error", "error / peak"
    );
    for fab in &fabs {
        let coarse = (fab.p1.reference_samples(), fab.p2.reference_samples());
        let fine = |p: &Profile| match p {
            Profile::List(o) => list_samples(o, 0.02, 1e9),
            Profile::Curve(_) => unreachable!(),
        };
        let dense = (fine(&fab.p1), fine(&fab.p2));
        let mut rng = Rng(4242);
        let (mut worst, mut peak, mut worst_pk) = (0.0f64, 0.0f64, 0.0f64);
        let mut vals = Vec::new();
        for _ in 0..150 {
            let wi = local_dir(&mut rng, 0.05, 0.99);
            let wr = local_dir(&mut rng, 0.05, 0.99);
            let a = cloth_with(fab, n, t, b, wi, wr, &coarse.0, &coarse.1);
            let d = cloth_with(fab, n, t, b, wi, wr, &dense.0, &dense.1);
            for k in 0..3 {
                peak = peak.max(d[k]);
                vals.push((a[k], d[k]));
            }
        }
        for (a, d) in vals {
            worst_pk = worst_pk.max((a - d).abs() / peak);
            if d > 1e-3 * peak {
                worst = worst.max((a - d).abs() / d);
            }
        }
        println!("{:<24} {:>14.3e} {:>14.3e}", fab.name, worst, worst_pk);
        assert!(
            worst < 5e-3 && worst_pk < 2e-3,
            "{}: reference quadrature error {worst} ({worst_pk} of peak)",
            fab.name
        );
    }
}

#[test]
fn ambient_factor_report() {
    // fs_main's ambient is E(n)/pi x sum_j a_j (A_j + F_avg(eta_j)) / (a1 + a2),
    // F_avg = f0 + (1 - f0)/21 (mean of Schlick). The model's
    // own response to uniform unit radiance is R(wr) = integral of L_r/L_i
    // over the hemisphere; printed for comparison (no assertion beyond
    // finiteness: the ambient term is a documented approximation).
    let m = load_material();
    let (t, b, n) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    println!(
        "\n{:<24} {:>8} {:>30} {:>30}",
        "fabric", "view", "R(wr) (rgb)", "ambient factor used (rgb)"
    );
    for fab in preset_fabrics(&m) {
        let s1 = fab.p1.reference_samples();
        let s2 = fab.p2.reference_samples();
        let favg = |eta: f64| {
            let f0 = ((eta - 1.0) / (eta + 1.0)).powi(2);
            f0 + (1.0 - f0) / 21.0
        };
        let abar = [0, 1, 2].map(|c| {
            (fab.a1 * (fab.t1.albedo[c] + favg(fab.t1.eta))
                + fab.a2 * (fab.t2.albedo[c] + favg(fab.t2.eta)))
                / (fab.a1 + fab.a2)
        });
        for view_deg in [0.0f64, 60.0] {
            let wr = [
                view_deg.to_radians().sin(),
                0.0,
                view_deg.to_radians().cos(),
            ];
            let (nu, np) = (48, 96);
            let mut r = [0.0; 3];
            for i in 0..nu {
                let c = (i as f64 + 0.5) / nu as f64;
                let s = (1.0 - c * c).sqrt();
                for j in 0..np {
                    let phi = 2.0 * PI * (j as f64 + 0.5) / np as f64;
                    let wi = [s * phi.cos(), s * phi.sin(), c];
                    let l = cloth_with(&fab, n, t, b, wi, wr, &s1, &s2);
                    let dw = (1.0 / nu as f64) * (2.0 * PI / np as f64);
                    r = add(r, scale(l, dw));
                }
            }
            assert!(r.iter().all(|x| x.is_finite() && *x >= 0.0));
            println!(
                "{:<24} {:>6} d {:>30} {:>30}",
                fab.name,
                view_deg,
                format!("({:.4}, {:.4}, {:.4})", r[0], r[1], r[2]),
                format!("({:.4}, {:.4}, {:.4})", abar[0], abar[1], abar[2])
            );
        }
    }
}

/// The volume term's two readings of F = F_t(η, ω_i) F_t(η', ω'_r) on the
/// shipped Table II presets (f64, the reference quadrature): the relative
/// difference of L_r/L_i between weft's per-direction transmission and the
/// squared transmission at the effective angle, over the GPU test's
/// direction pairs and frames, for values above 1e-3 of the fabric's peak.
/// Printed for the README; the test fails unless every preset tells the two
/// apart by more than the GPU test's tolerance (ten times `REL_TOL`), so
/// `gpu_reference_tier_matches_f64_model` catches a tier written with the
/// other reading.
#[test]
fn volume_fresnel_readings_on_table_ii() {
    let m = load_material();
    for fab in preset_fabrics(&m) {
        let mut other = fab.clone();
        other.t1.transmission = Transmission::SquaredEffective;
        other.t2.transmission = Transmission::SquaredEffective;
        let mut pairs = Vec::new();
        for (k, (t, b, n)) in frames().into_iter().enumerate() {
            for (wi, wr) in direction_pairs(0x5EED + k as u64, t, b, n) {
                let ours = cloth_reference(&fab, n, t, b, wi, wr);
                let theirs = cloth_reference(&other, n, t, b, wi, wr);
                pairs.push((ours, theirs, dot(n, wi).min(dot(n, wr))));
            }
        }
        let peak = pairs
            .iter()
            .flat_map(|(o, _, _)| o.iter().copied())
            .fold(0.0f64, f64::max);
        let mut rel: Vec<(f64, f64)> = pairs
            .iter()
            .flat_map(|(o, t, grazing)| {
                (0..3)
                    .filter(|&c| o[c] > 1e-3 * peak)
                    .map(move |c| ((t[c] - o[c]).abs() / o[c], *grazing))
            })
            .collect();
        rel.sort_by(|a, b| a.0.total_cmp(&b.0));
        let at = |q: f64| rel[((rel.len() - 1) as f64 * q) as usize].0;
        let (worst, grazing) = *rel.last().expect("values above the floor");
        eprintln!(
            "{}: {} values, |squared effective − per direction| / per direction: median {:.4}, p95 {:.4}, max {:.4} (min(n·ω_i, n·ω_r) {:.3} there)",
            fab.name,
            rel.len(),
            at(0.5),
            at(0.95),
            worst,
            grazing
        );
        assert!(
            worst > 10.0 * REL_TOL,
            "{}: the two readings differ by at most {worst:.2e}",
            fab.name
        );
    }
}
