// @include "lib/brdf.wgsl"
// @include "lib/half.wgsl"
//
// Microcylinder woven-cloth BSDF: Sadeghi, Bisker, De Deken, Jensen 2013,
// "A Practical Microcylinder Appearance Model for Cloth Rendering",
// ACM TOG 32(2):14 (seed 000; research notes sec. 1).
//
// PURE functions: every input is an argument; nothing here reads `material`,
// `weft_frame` or any binding, so tests/physics/microcylinder/ evaluates exactly
// these functions in a compute shader and compares them with an f64 model.
// Needs WEFT_PI (engine interface) and weft_f_dielectric / weft_pow5 (brdf.wgsl).
//
// ---------------------------------------------------------------- model
// A thread set j runs along u (before its tangent offset), the other thread
// set along v, n is the surface normal. A tangent offset alpha tilts the
// thread about v (the thread rises towards +n for alpha > 0):
//   u' = u cos(alpha) + n sin(alpha),  n' = n cos(alpha) - u sin(alpha).
// For a direction w: sin(theta) = w.u' (theta in [-pi/2, pi/2]); phi is the
// azimuth of w projected onto the plane normal to u' (measured from n');
// psi is the azimuth of w projected onto the plane normal to v (the u'-n'
// plane). theta_h = (theta_i + theta_r)/2, theta_d = (theta_i - theta_r)/2,
// phi_d, psi_d the angles between the two projections.
//   g(gamma, x) = exp(-x^2 / (2 gamma^2)) / sqrt(2 pi gamma^2)
//   f_s   = [F_r cos(phi_d/2) g(gamma_s, theta_h)
//            + F ((1 - k_d) g(gamma_v, theta_h) + k_d) A / (cos theta_i + cos theta_r)]
//           / cos^2(theta_d)
//   F_r   = Fresnel reflectance at cos theta_i' = cos(theta_d) cos(phi_d/2)
//   M     = (1 - u(phi_d)) M_i M_r + u(phi_d) min(M_i, M_r),  M_x = max(cos phi_x, 0)
//   P     = the same with psi,  u(x) = exp(-x^2 / (2 (20 deg)^2))
// Per thread set, over its tangent-offset distribution (weights w_t):
//   S_j = sum_t w_t f_s M P cos(theta_i),   P_j = sum_t w_t P    (sum w_t = 1)
// and the cloth (paper eq. for L_r = a1 L_r,1 + a2 L_r,2 with the
// visibility normalisation Q used by the public implementations):
//   L_r = L_i * (a1 S_1 + a2 S_2) / Q,   Q = a1 P_1 + a2 P_2 + (1 - a1 - a2)(n.w_i)
// i.e. mc_combine returns the BRDF times n.w_i. Q depends on both directions
// through P, but its gap term only on w_i: the model is NOT reciprocal
// (measured in tests/physics/microcylinder/, documented in the material README).
//
// Tiers:
//   reference: angles with atan2 (well conditioned near +-pi/2 and 0),
//     exact dielectric Fresnel (Walter et al. 2007) for F_r and for the
//     transmission in and out, F = (1 - F_r(cos theta_i))(1 - F_r(cos theta_r)),
//     the tangent curve integrated densely (every baked curve segment
//     weighted by its arc length; offset lists linearly interpolated with
//     midpoint sub-steps <= 1 deg, at most 64 per segment: relative error
//     < 3e-3 against a 0.02 deg quadrature for Table II, measured in the test).
//   fast: the same offset distribution and the same lobe (M, P, Q, the
//     surface and volume terms), integrated with a few nodes per range of
//     offsets instead of one lobe per degree (microcylinder_nodes.wgsl,
//     "fast tier"): each range clipped to the offsets where M P > 0 (an
//     interval, in closed form); offset lists by the 3-node rule
//     (microcylinder_nodes.wgsl, as low),
//     curves by one range in t and two nodes (Gauss-Legendre, or the
//     2-point Gauss-Jacobi rule for the weight (t - t0)^2 (t1 - t)^2 where
//     both ends of the range are support bounds, where M P vanishes
//     quadratically); the surface Gaussian in theta_h averaged exactly
//     (erf) over each node's cell, the volume Gaussian (twice as wide)
//     sampled at the nodes. Node factors: exact dielectric F_r (one
//     division), Schlick's transmission in and out, theta_h from one
//     polynomial asin, u() from a series in cos (no acos). Cost 3.87x /
//     3.83x standard fast (navi21 / gfx1100 model) against 6.84x / 6.76x
//     for the 3-node tier it replaces (README "fast").
//   low: the 3-node rule (microcylinder_nodes.wgsl) with each node's
//     factors in half precision (mc_low_node; unchanged by the fast tier's
//     rewrite).
//
// Guards (the same constants are used by the f64 model in the test):
//   - a sample whose w_i or w_r lies within 0.0057 deg of u' (or of v for
//     psi) has no defined azimuth: it is skipped (contributes to neither S nor
//     P), as path_tracer_cloth does with try_normalize;
//   - cos^2(theta_d) is floored at 1e-4 (theta_d within 0.57 deg of 90 deg
//     only happens for w_i, w_r running opposite ways along the fibre);
//   - gamma floored at 0.1 deg; Q <= 1e-6 gives 0; w_i or w_r at or below the
//     horizon of n gives 0 (the cloth is opaque; no transmission modelled).

// Curve profiles: the material's tangent curves are baked into this many
// samples over t in [0, 1] (`samples = 33` in microcylinder.toml).
const MC_CURVE_SAMPLES: u32 = 33u;
const MC_CURVE_SEGMENTS: u32 = 32u;
// Offset lists hold at most 8 control points (two vec4).
const MC_MAX_OFFSETS: i32 = 8;
// Reference tier: largest sub-step along an offset-list segment (degrees) and
// the most sub-steps per segment.
const MC_REF_STEP_DEG: f32 = 1.0;
const MC_REF_MAX_SUBDIV: f32 = 64.0;
// 1 / (2 sigma^2) of the correlation Gaussian u(), sigma = 20 deg (the seed's
// 4.082 corresponds to sigma = 20.05 deg).
const MC_U_INV_TWO_SIGMA2: f32 = 4.10351863;
// sqrt(2 pi).
const MC_SQRT_TWO_PI: f32 = 2.50662827463;
const MC_DEG: f32 = 0.0174532925199433;
const MC_MIN_GAMMA: f32 = 0.00174532925199433;
// Squared length of a projected unit direction below which its azimuth is
// undefined (|sin| of the angle to the axis < 1e-4).
const MC_MIN_PROJ2: f32 = 1e-8;
const MC_MIN_COS2_THETA_D: f32 = 1e-4;
const MC_MIN_Q: f32 = 1e-6;

// Optical parameters of one thread set. Angles in radians.
struct McThread {
    albedo: vec3<f32>,
    eta: f32,
    // Isotropic fraction k_d of the volume lobe.
    kd: f32,
    gamma_s: f32,
    gamma_v: f32,
}

// Geometry of one thread set: u along the thread (before the offset), v the
// other thread set (the tilt axis), n the surface normal. Orthonormal.
struct McFrame {
    u: vec3<f32>,
    v: vec3<f32>,
    n: vec3<f32>,
}

// The psi projections do not depend on the tangent offset (the tilt is about
// v): computed once per thread set.
struct McPsi {
    // Unit projections of w_i, w_r onto the plane normal to v.
    pi: vec3<f32>,
    pr: vec3<f32>,
    // Correlation weight u(psi_d).
    u: f32,
    // 1 when both projections are defined, else 0 (every sample skipped).
    ok: f32,
}

// ---------------------------------------------------------------- helpers

// Unit-area Gaussian g(gamma, x); gamma floored at 0.1 deg (peak <= 229).
fn mc_gauss(gamma: f32, x: f32) -> f32 {
    let g = max(gamma, MC_MIN_GAMMA);
    return exp(-x * x / (2.0 * g * g)) / (MC_SQRT_TWO_PI * g);
}

// Correlated/uncorrelated blend of the masking (or reweighting) terms.
fn mc_correlate(ci: f32, cr: f32, u: f32) -> f32 {
    let mi = max(ci, 0.0);
    let mr = max(cr, 0.0);
    return (1.0 - u) * mi * mr + u * min(mi, mr);
}

// acos without transcendentals (Abramowitz & Stegun 4.4.45 form, as in Cg's
// reference acos): |error| < 6.8e-5 rad on [-1, 1]; input clamped.
fn mc_acos_fast(x: f32) -> f32 {
    let ax = min(abs(x), 1.0);
    let r = sqrt(1.0 - ax) * (1.5707288 + ax * (-0.2121144 + ax * (0.0742610 - 0.0187293 * ax)));
    return select(r, WEFT_PI - r, x < 0.0);
}

// asin(x) = pi/2 - acos(x) on [-1, 1].
fn mc_asin_fast(x: f32) -> f32 {
    return 0.5 * WEFT_PI - mc_acos_fast(x);
}

// ---------------------------------------------------------------- psi

fn mc_psi_reference(v: vec3<f32>, wi: vec3<f32>, wr: vec3<f32>) -> McPsi {
    let pi = wi - v * dot(wi, v);
    let pr = wr - v * dot(wr, v);
    let li2 = dot(pi, pi);
    let lr2 = dot(pr, pr);
    let ok = min(li2, lr2) >= MC_MIN_PROJ2;
    // max() keeps the unused arm finite when a projection vanishes.
    let hi = pi * inverseSqrt(max(li2, MC_MIN_PROJ2));
    let hr = pr * inverseSqrt(max(lr2, MC_MIN_PROJ2));
    // psi_d = atan2(|hi x hr|, hi.hr): accurate at 0 and pi, unlike acos.
    let psi_d = atan2(length(cross(hi, hr)), dot(hi, hr));
    let u = exp(-psi_d * psi_d * MC_U_INV_TWO_SIGMA2);
    return McPsi(hi, hr, u, select(0.0, 1.0, ok));
}

// ---------------------------------------------------------------- lobes

// One tangent-offset sample, reference form. (ca, sa) = (cos, sin) of the
// offset. Returns (f_s M P cos(theta_i), P); zero for a skipped sample.
fn mc_lobe_reference(fr: McFrame, psi: McPsi, wi: vec3<f32>, wr: vec3<f32>, ca: f32, sa: f32, th: McThread) -> vec4<f32> {
    let u = fr.u * ca + fr.n * sa;
    let np = fr.n * ca - fr.u * sa;
    let si = clamp(dot(wi, u), -1.0, 1.0);
    let sr = clamp(dot(wr, u), -1.0, 1.0);
    let pi = wi - u * si;
    let pr = wr - u * sr;
    let ci2 = dot(pi, pi);
    let cr2 = dot(pr, pr);
    if min(ci2, cr2) < MC_MIN_PROJ2 || psi.ok == 0.0 {
        return vec4<f32>(0.0);
    }
    // cos(theta) is the projection's length: exact even where 1 - si^2 cancels.
    let ci = sqrt(ci2);
    let cr = sqrt(cr2);
    let hi = pi / ci;
    let hr = pr / cr;
    let theta_i = atan2(si, ci);
    let theta_r = atan2(sr, cr);
    let theta_h = 0.5 * (theta_i + theta_r);
    let theta_d = 0.5 * (theta_i - theta_r);
    let phi_d = atan2(length(cross(hi, hr)), dot(hi, hr));
    let cos_half_phi = cos(0.5 * phi_d);

    // Shadowing/masking (phi) and reweighting (psi), both against n'.
    let u_phi = exp(-phi_d * phi_d * MC_U_INV_TWO_SIGMA2);
    let m = mc_correlate(dot(np, hi), dot(np, hr), u_phi);
    let p = mc_correlate(dot(np, psi.pi), dot(np, psi.pr), psi.u);

    let cd = cos(theta_d);
    let cd2 = max(cd * cd, MC_MIN_COS2_THETA_D);
    // Surface reflection at the effective angle (weft_f_dielectric floors the
    // cosine at 1e-4 and guards eta = 1).
    let f_r = weft_f_dielectric(cd * cos_half_phi, th.eta);
    let surface = f_r * cos_half_phi * mc_gauss(th.gamma_s, theta_h);
    // Volume: transmitted in at cos(theta_i), out at cos(theta_r) (the fibre
    // surface facing each direction); ci + cr >= 2e-4.
    let f_t = (1.0 - weft_f_dielectric(ci, th.eta)) * (1.0 - weft_f_dielectric(cr, th.eta));
    let volume = f_t * ((1.0 - th.kd) * mc_gauss(th.gamma_v, theta_h) + th.kd) / (ci + cr);
    let fs = (vec3<f32>(surface) + volume * th.albedo) / cd2;
    return vec4<f32>(fs * (m * p * ci), p);
}

// ---------------------------------------------------------------- thread sets
// Each returns the offset-weighted means (S_j, P_j) of a thread set.

// Sample i of a baked curve (four samples per vec4). Arrays are indexed as
// values (no function-local array variables: glslang's HLSL front end
// rejects the zero initialiser naga writes for them).
fn mc_curve_at(h: array<vec4<f32>, 9>, i: u32) -> f32 {
    return h[i / 4u][i % 4u];
}

// Offset k (0..7) of a list held in two vec4.
fn mc_offset_at(a: vec4<f32>, b: vec4<f32>, k: i32) -> f32 {
    return select(a, b, k >= 4)[k & 3];
}

// Reference, tangent curve: the baked height profile h(t), t in [0, 1], is a
// polyline of 32 segments; segment k has the constant tangent (dt, dh)/len,
// i.e. offset atan(dh/dt) (the seed's atan of the slope), and weight len (its
// arc length). The sum is the exact integral along that polyline. len >= dt.
fn mc_thread_curve_reference(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, th: McThread, heights: array<vec4<f32>, 9>) -> vec4<f32> {
    let psi = mc_psi_reference(fr.v, wi, wr);
    let dt = 1.0 / f32(MC_CURVE_SEGMENTS);
    var acc = vec4<f32>(0.0);
    var wsum = 0.0;
    for (var k = 0u; k < MC_CURVE_SEGMENTS; k++) {
        let dh = mc_curve_at(heights, k + 1u) - mc_curve_at(heights, k);
        let len = sqrt(dt * dt + dh * dh);
        acc += len * mc_lobe_reference(fr, psi, wi, wr, dt / len, dh / len, th);
        wsum += len;
    }
    return acc / wsum;
}

// Reference, offset list (degrees, `count` in 1..8 control points, equally
// spaced along the thread): the piecewise-linear tangent curve through them,
// each segment integrated with the midpoint rule in ceil(|delta| / 1 deg)
// sub-steps (at most 64; 1 for a flat segment), segments weighted equally
// (equal length). One control point: that offset alone.
fn mc_thread_list_reference(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, th: McThread, offsets_a: vec4<f32>, offsets_b: vec4<f32>, count: i32) -> vec4<f32> {
    let n = clamp(count, 1, MC_MAX_OFFSETS);
    let psi = mc_psi_reference(fr.v, wi, wr);
    if n == 1 {
        let a = offsets_a.x * MC_DEG;
        return mc_lobe_reference(fr, psi, wi, wr, cos(a), sin(a), th);
    }
    var acc = vec4<f32>(0.0);
    for (var k = 0; k < n - 1; k++) {
        let a0 = mc_offset_at(offsets_a, offsets_b, k);
        let a1 = mc_offset_at(offsets_a, offsets_b, k + 1);
        // The 1e-3 keeps the sub-step count stable when |delta| / step is an
        // integer up to rounding (f32 here, f64 in the test).
        let m = clamp(ceil(abs(a1 - a0) / MC_REF_STEP_DEG - 1e-3), 1.0, MC_REF_MAX_SUBDIV);
        let mi = i32(m);
        var seg = vec4<f32>(0.0);
        for (var j = 0; j < mi; j++) {
            let a = mix(a0, a1, (f32(j) + 0.5) / m) * MC_DEG;
            seg += mc_lobe_reference(fr, psi, wi, wr, cos(a), sin(a), th);
        }
        acc += seg / m;
    }
    return acc / f32(n - 1);
}

// ---------------------------------------------------------------- cloth

// Combines two thread sets (a = coverage ratios, a2 = 0 for one set) into
// L_r / L_i for a light from w_i: (a1 S_1 + a2 S_2) / Q, Q = a1 P_1 + a2 P_2
// + max(1 - a1 - a2, 0)(n.w_i). Zero when w_i or w_r is at or below the
// horizon (n_dot_wi, n_dot_wr <= 0) or Q <= 1e-6 (then S ~ 0 too, since
// every term of S carries its P).
fn mc_combine(t1: vec4<f32>, t2: vec4<f32>, a1: f32, a2: f32, n_dot_wi: f32, n_dot_wr: f32) -> vec3<f32> {
    let c1 = saturate(a1);
    let c2 = saturate(a2);
    let gap = max(1.0 - c1 - c2, 0.0);
    let q = c1 * t1.w + c2 * t2.w + gap * max(n_dot_wi, 0.0);
    let s = max(c1 * t1.xyz + c2 * t2.xyz, vec3<f32>(0.0));
    let lit = n_dot_wi > 0.0 && n_dot_wr > 0.0 && q > MC_MIN_Q;
    return select(vec3<f32>(0.0), s / max(q, MC_MIN_Q), lit);
}
