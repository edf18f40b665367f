//! The f64 model of Sadeghi et al. 2013, written from the paper (not from
//! the WGSL), and the paper's Table II.

use super::*;

pub(super) type V3 = [f64; 3];

pub(super) fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub(super) fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
pub(super) fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
pub(super) fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
pub(super) fn sub(a: V3, b: V3) -> V3 {
    add(a, scale(b, -1.0))
}
pub(super) fn norm(a: V3) -> V3 {
    scale(a, 1.0 / dot(a, a).sqrt())
}
/// Rodrigues: rotate x about the unit axis k by angle a.
pub(super) fn rotate(x: V3, k: V3, a: f64) -> V3 {
    add(
        add(scale(x, a.cos()), scale(cross(k, x), a.sin())),
        scale(k, dot(k, x) * (1.0 - a.cos())),
    )
}

#[derive(Clone, Copy, Debug)]
pub(super) struct Thread {
    /// Linear albedo A.
    pub(super) albedo: V3,
    pub(super) eta: f64,
    pub(super) kd: f64,
    /// Radians.
    pub(super) gamma_s: f64,
    pub(super) gamma_v: f64,
    /// The volume term's Fresnel transmission (the material's: `PerDirection`).
    pub(super) transmission: Transmission,
}

/// Readings of the volume term's F = F_t(η, ω_i) F_t(η', ω'_r) (README,
/// "The volume term's Fresnel transmission").
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Transmission {
    /// (1 - F_r(cos θ_i)) (1 - F_r(cos θ_r)): in through the fibre surface
    /// facing ω_i, out through the one facing ω_r (weft's reading).
    PerDirection,
    /// (1 - F_r(cos θ_d cos(φ_d/2)))²: both at the surface reflection's
    /// effective angle (the seed, path_tracer_cloth, Ushio's port).
    SquaredEffective,
}

/// Thread geometry: u along the thread, v the other thread set, n the normal.
#[derive(Clone, Copy, Debug)]
pub(super) struct Frame {
    pub(super) u: V3,
    pub(super) v: V3,
    pub(super) n: V3,
}

// Guards shared with the WGSL (lib/microcylinder.wgsl header).
pub(super) const MIN_PROJ2: f64 = 1e-8;
pub(super) const MIN_COS2_THETA_D: f64 = 1e-4;
pub(super) const MIN_GAMMA: f64 = 0.1 * PI / 180.0;
pub(super) const MIN_Q: f64 = 1e-6;
pub(super) const SIGMA_U: f64 = 20.0 * PI / 180.0;

/// Unit-area Gaussian of the paper.
pub(super) fn gauss(gamma: f64, x: f64) -> f64 {
    let g = gamma.max(MIN_GAMMA);
    (-x * x / (2.0 * g * g)).exp() / (2.0 * PI * g * g).sqrt()
}

/// Unit-height Gaussian u() of the shadowing/reweighting correlation.
pub(super) fn u_corr(x: f64) -> f64 {
    (-x * x / (2.0 * SIGMA_U * SIGMA_U)).exp()
}

/// Unpolarised Fresnel reflectance of a dielectric (Walter et al. 2007,
/// eq. 22), cosine floored at 1e-4 as in lib/brdf.wgsl.
pub(super) fn fresnel(cos_i: f64, eta: f64) -> f64 {
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
pub(super) struct Angles {
    pub(super) theta_i: f64,
    pub(super) theta_r: f64,
    pub(super) phi_d: f64,
    pub(super) cos_phi_i: f64,
    pub(super) cos_phi_r: f64,
    pub(super) psi_d: f64,
    pub(super) cos_psi_i: f64,
    pub(super) cos_psi_r: f64,
}

/// The thread tilted by `alpha` (radians; the thread rises towards +n):
/// (u', n'). Axis k = u x n, so u -> u cos + n sin, n -> n cos - u sin.
pub(super) fn tilt(f: &Frame, alpha: f64) -> (V3, V3) {
    let k = norm(cross(f.u, f.n));
    (rotate(f.u, k, alpha), rotate(f.n, k, alpha))
}

/// None where an azimuth is undefined (a direction within 1e-4 rad of u' or v).
pub(super) fn angles(f: &Frame, alpha: f64, wi: V3, wr: V3) -> Option<Angles> {
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
pub(super) fn f_s(a: &Angles, th: &Thread) -> V3 {
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
pub(super) fn corr(ci: f64, cr: f64, d: f64) -> f64 {
    let (mi, mr) = (ci.max(0.0), cr.max(0.0));
    let u = u_corr(d);
    (1.0 - u) * mi * mr + u * mi.min(mr)
}

/// One offset sample: (f_s M P cos(theta_i), P); zeros when skipped.
pub(super) fn sample(f: &Frame, alpha: f64, wi: V3, wr: V3, th: &Thread) -> (V3, f64) {
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
pub(super) fn mean_over(
    f: &Frame,
    wi: V3,
    wr: V3,
    th: &Thread,
    samples: &[(f64, f64)],
) -> (V3, f64) {
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
pub(super) fn list_samples(offsets_deg: &[f64], step_deg: f64, max_sub: f64) -> Vec<(f64, f64)> {
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
pub(super) fn curve_samples(h: &[f64]) -> Vec<(f64, f64)> {
    let dt = 1.0 / (h.len() - 1) as f64;
    h.windows(2)
        .map(|s| {
            let dh = s[1] - s[0];
            ((dh / dt).atan(), (dt * dt + dh * dh).sqrt())
        })
        .collect()
}

#[derive(Clone, Debug)]
pub(super) enum Profile {
    /// Offsets in degrees.
    List(Vec<f64>),
    /// Baked heights over t in [0, 1].
    Curve(Vec<f64>),
}

impl Profile {
    pub(super) fn reference_samples(&self) -> Vec<(f64, f64)> {
        match self {
            Profile::List(o) => list_samples(o, 1.0, 64.0),
            Profile::Curve(h) => curve_samples(h),
        }
    }
}

#[derive(Clone, Debug)]
pub(super) struct Fabric {
    pub(super) name: &'static str,
    pub(super) t1: Thread,
    pub(super) a1: f64,
    pub(super) p1: Profile,
    pub(super) t2: Thread,
    pub(super) a2: f64,
    pub(super) p2: Profile,
    pub(super) use2: bool,
}

/// The cloth: L_r / L_i = (a1 S1 + a2 S2) / Q,
/// Q = a1 P1 + a2 P2 + (1 - a1 - a2)(n.wi); zero below either horizon.
#[allow(clippy::too_many_arguments)]
pub(super) fn cloth_with(
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

pub(super) fn cloth_reference(fab: &Fabric, n: V3, t: V3, b: V3, wi: V3, wr: V3) -> V3 {
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

pub(super) fn thread(eta: f64, color: V3, s: f64, kd: f64, gs: f64, gv: f64) -> Thread {
    Thread {
        albedo: color.map(|c| c * s),
        eta,
        kd,
        gamma_s: gs.to_radians(),
        gamma_v: gv.to_radians(),
        transmission: Transmission::PerDirection,
    }
}

pub(super) fn table_ii() -> Vec<(&'static str, Fabric)> {
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
