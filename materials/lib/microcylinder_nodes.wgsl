// @include "lib/microcylinder.wgsl"
//
// The microcylinder BSDF's approximation tiers (lib/microcylinder.wgsl holds
// the model, the reference tier and the cloth combination): the node rule
// that integrates a thread set's tangent offsets with a few nodes per range,
// then `low` (its factors in half precision) and `fast` (fewer, cheaper
// nodes). PURE functions, as the model's file: tests/physics/microcylinder/
// composes both files.

// ---------------------------------------------------------------- node rule
// The 3-node rule (low's rule for lists and curves; the fast tier's rule for
// offset lists, with its own node factors, "fast tier" below). It integrates
// the same tangent-offset distribution as the reference with three nodes per
// range of offsets instead of one lobe per degree:
//   1. Support: every term of S and P carries M and P, which vanish unless
//      n'.w_i > 0 and n'.w_r > 0. With w = (x, y, z) along (u, v, n) and
//      s = tan(alpha), n'.w = cos(alpha) (z - x s): each direction bounds the
//      slope s from one side, so the offsets that contribute form one
//      interval (s_lo, s_hi). Each range is clipped to it first: the
//      integrand then has no kinks (max(cos, 0)) inside the range and falls
//      smoothly to 0 at a clipped end. Without this, rim light (w_i, w_r on
//      opposite sides, a support of 10-30 deg inside a 50-110 deg segment)
//      needs many nodes.
//   2. A 3-point Gauss-Legendre rule on the clipped range for the slowly
//      varying factors (Fresnel, cos(phi_d/2), M, P, cos(theta),
//      1/cos^2(theta_d), 1/(cos theta_i + cos theta_r)): mc_low_node,
//      mc_fast_node.
//   3. The narrow Gaussians in theta_h are not sampled but averaged over
//      each node's cell of the rule (cell widths 5/18, 8/18, 5/18), theta_h
//      linear across a cell: mean g = (cdf(x_b/gamma) - cdf(x_a/gamma)) /
//      (x_b - x_a) (erf by Abramowitz & Stegun 7.1.26, sharing the pdf's
//      exp). theta_h at the cell edges is interpolated linearly from the
//      nodes. This is what sampling at control points gets wrong: a 2.5-12
//      deg lobe swept by a 50 deg range of tilts is a band of width ~50 deg
//      in theta_h, not a few spikes.
// Offset lists: each segment is one range (uniform offsets from one control
// point to the next), two halves when it spans more than 60 deg (velvet's
// -55..55); a flat segment or single control point is the point lobe by the
// same code (all nodes on one offset, zero-width cells). Curves: one range in
// t over the whole profile, the slope taken as linear in t on each half
// through its values at t = 0, 1/2, 1 (exact for a quadratic profile such as
// the default), nodes weighted by arc length sqrt(1 + s^2).
// The code is straight-line (no early return; the list path has one loop
// over its pieces): llvmpipe runs both sides of every branch and a loop
// around the nodes costs as much again as the nodes (measured: the same
// curve code inside a one-iteration loop went from 1.6x to 3.1x standard
// fast).

// Per thread set: the components of w_i and w_r in the thread frame before
// the offset (x along u, y along v, z along n), psi (offset-independent),
// the support and the constants of the thread.
struct McFastPre {
    wi: vec3<f32>,
    wr: vec3<f32>,
    // 1 / |projection onto the u-n plane| of w_i, w_r (psi's azimuth).
    inv_ri: f32,
    inv_rr: f32,
    // Correlation weight u(psi_d); 1/0 whether psi is defined.
    u_psi: f32,
    ok: f32,
    inv_gamma_s: f32,
    inv_gamma_v: f32,
    // Offsets with a non-zero integrand: tan(alpha) in (s_lo, s_hi).
    s_lo: f32,
    s_hi: f32,
    eta: f32,
}

// The slowly varying factors at one offset.
struct McFastNode {
    // theta_h.
    x: f32,
    // F_r cos(phi_d/2) M P cos(theta_i) / cos^2(theta_d): multiplies
    // g(gamma_s, theta_h).
    s: f32,
    // F_t M P cos(theta_i) / ((cos theta_i + cos theta_r) cos^2(theta_d)):
    // multiplies A ((1 - k_d) g(gamma_v, theta_h) + k_d).
    v: f32,
    // The reweighting P.
    p: f32,
}

// 1 / sqrt(2 pi).
const MC_INV_SQRT_TWO_PI: f32 = 0.398942280401;
// Below this cell width (in units of gamma) the mean of the Gaussian over a
// cell is the mean of its edge values (relative error < 1e-3 there) instead
// of the cdf difference, which cancels.
const MC_FAST_MIN_DT: f32 = 0.1;
// Three-point Gauss-Legendre rule on [0, 1]: nodes 1/2 -+ sqrt(15)/10,
// weights 5/18, 8/18, 5/18; cell edges 0, 5/18, 13/18, 1.
const MC_GL3_T: f32 = 0.112701665379;
const MC_GL3_W0: f32 = 0.277777777778;
const MC_GL3_W1: f32 = 0.444444444444;
// theta_h at the cell edges, linear through the nodes: edge 0 and 5/18 from
// nodes 0 and 1, 13/18 and 1 from nodes 1 and 2 (fractions of the node step).
const MC_GL3_E0: f32 = -0.290994448736;
const MC_GL3_E1: f32 = 0.426217847263;

// Standard normal at each t: (pdf, cdf - 1/2). cdf by Abramowitz & Stegun
// 7.1.26 (|error of erf| < 1.5e-7), sharing the exponential with the pdf.
fn mc_normal4(t: vec4<f32>) -> array<vec4<f32>, 2> {
    let e = exp(-0.5 * t * t);
    let z = abs(t) * 0.707106781187;
    let k = 1.0 / (1.0 + 0.3275911 * z);
    let poly = k * (0.254829592 + k * (-0.284496736 + k * (1.421413741 + k * (-1.453152027 + k * 1.061405429))));
    // Upper tail 1 - cdf(|t|) = erfc(z) / 2.
    let half = 0.5 - 0.5 * poly * e;
    return array<vec4<f32>, 2>(e * MC_INV_SQRT_TWO_PI, select(-half, half, t >= vec4<f32>(0.0)));
}

// Mean of g(gamma, x) over the three cells whose edges are x_e (x linear in
// each cell).
fn mc_cell_means(xe: vec4<f32>, inv_gamma: f32) -> vec3<f32> {
    let t = xe * inv_gamma;
    let nd = mc_normal4(t);
    let dt = t.yzw - t.xyz;
    let wide = abs(dt) >= vec3<f32>(MC_FAST_MIN_DT);
    let exact = (nd[1].yzw - nd[1].xyz) / select(vec3<f32>(1.0), dt, wide);
    let trap = 0.5 * (nd[0].xyz + nd[0].yzw);
    return max(select(trap, exact, wide), vec3<f32>(0.0)) * inv_gamma;
}

// The support in slope space: with s = tan(alpha) (alpha in (-pi/2, pi/2)),
// n'.w = cos(alpha) (z - x s) > 0 <=> x s < z, so each direction bounds s
// from above (x > 0) or below (x < 0). MC_FAST_BIG stands for no bound.
const MC_FAST_BIG: f32 = 1e6;
fn mc_fast_pre(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, th: McThread) -> McFastPre {
    let li = vec3<f32>(dot(wi, fr.u), dot(wi, fr.v), dot(wi, fr.n));
    let lr = vec3<f32>(dot(wr, fr.u), dot(wr, fr.v), dot(wr, fr.n));
    let ri2 = li.x * li.x + li.z * li.z;
    let rr2 = lr.x * lr.x + lr.z * lr.z;
    let ok = min(ri2, rr2) >= MC_MIN_PROJ2;
    let inv_ri = inverseSqrt(max(ri2, MC_MIN_PROJ2));
    let inv_rr = inverseSqrt(max(rr2, MC_MIN_PROJ2));
    let cos_psi_d = (li.x * lr.x + li.z * lr.z) * inv_ri * inv_rr;
    let psi_d = mc_acos_fast(cos_psi_d);
    let u_psi = exp(-psi_d * psi_d * MC_U_INV_TWO_SIGMA2);
    // z / x with |x| floored: a tiny |x| gives a bound beyond MC_FAST_BIG.
    let bi = li.z / select(max(li.x, 1e-12), min(li.x, -1e-12), li.x < 0.0);
    let br = lr.z / select(max(lr.x, 1e-12), min(lr.x, -1e-12), lr.x < 0.0);
    let s_lo = max(select(-MC_FAST_BIG, bi, li.x < 0.0), select(-MC_FAST_BIG, br, lr.x < 0.0));
    let s_hi = min(select(MC_FAST_BIG, bi, li.x > 0.0), select(MC_FAST_BIG, br, lr.x > 0.0));
    return McFastPre(li, lr, inv_ri, inv_rr, u_psi, select(0.0, 1.0, ok),
                     1.0 / max(th.gamma_s, MC_MIN_GAMMA), 1.0 / max(th.gamma_v, MC_MIN_GAMMA),
                     clamp(s_lo, -MC_FAST_BIG, MC_FAST_BIG), clamp(s_hi, -MC_FAST_BIG, MC_FAST_BIG), th.eta);
}

// The rule on one range, given its three nodes and their weights r (the
// Gauss-Legendre weight times the range's width times any density):
// (sum r S rgb, sum r P).
fn mc_fast_gl3(q: McFastPre, th: McThread, n0: McFastNode, n1: McFastNode, n2: McFastNode, r: vec3<f32>) -> vec4<f32> {
    let xe = vec4<f32>(n0.x + MC_GL3_E0 * (n1.x - n0.x), n0.x + MC_GL3_E1 * (n1.x - n0.x),
                       n2.x - MC_GL3_E1 * (n2.x - n1.x), n2.x - MC_GL3_E0 * (n2.x - n1.x));
    let gs = mc_cell_means(xe, q.inv_gamma_s);
    let gv = mc_cell_means(xe, q.inv_gamma_v);
    let s = r * vec3<f32>(n0.s, n1.s, n2.s);
    let v = r * vec3<f32>(n0.v, n1.v, n2.v);
    let surface = dot(gs, s);
    let volume = (1.0 - th.kd) * dot(gv, v) + th.kd * (v.x + v.y + v.z);
    return vec4<f32>(vec3<f32>(surface) + volume * th.albedo, dot(r, vec3<f32>(n0.p, n1.p, n2.p)));
}

// Curve, one half of the profile (t from ta to ta + 1/2, slope linear from
// sa to sb): the sub-interval of t whose slope lies in the support
// (s_lo, s_hi), as (t0, t1); empty as (2, -1).
fn mc_fast_half_clip(q: McFastPre, sa: f32, sb: f32, ta: f32) -> vec2<f32> {
    let ds = sb - sa;
    let flat = abs(ds) < MC_FAST_MIN_DSLOPE;
    let inv = 1.0 / select(ds, 1.0, flat);
    let u0 = (q.s_lo - sa) * inv;
    let u1 = (q.s_hi - sa) * inv;
    let uf = select(vec2<f32>(1.0, 0.0), vec2<f32>(0.0, 1.0), sa > q.s_lo && sa < q.s_hi);
    let u = select(vec2<f32>(max(min(u0, u1), 0.0), min(max(u0, u1), 1.0)), uf, flat);
    return select(vec2<f32>(2.0, -1.0), ta + 0.5 * u, u.x < u.y);
}

// Slope of the profile at t (linear on each half through s0, s1, s2).
fn mc_fast_slope(s0: f32, s1: f32, s2: f32, t: f32) -> f32 {
    return select(s1 + (s2 - s1) * (2.0 * t - 1.0), s0 + (s1 - s0) * (2.0 * t), t < 0.5);
}

// int sqrt(1 + s^2) ds = (s sqrt(1 + s^2) + asinh(s)) / 2.
fn mc_arc_primitive(s: f32) -> f32 {
    let h = sqrt(1.0 + s * s);
    return 0.5 * (s * h + sign(s) * log(abs(s) + h));
}

// Arc length of a half (t over 1/2) whose slope runs linearly from sa to sb.
fn mc_fast_half_length(sa: f32, sb: f32) -> f32 {
    let ds = sb - sa;
    let sm = 0.5 * (sa + sb);
    return select(0.5 * (mc_arc_primitive(sb) - mc_arc_primitive(sa)) / ds, 0.5 * sqrt(1.0 + sm * sm), abs(ds) < MC_FAST_MIN_DSLOPE);
}

// ---------------------------------------------------------------- low
// The 3-node rule of the section "node rule" (the same ranges, support
// clipping, 3 nodes and erf-exact cell means of both Gaussians; fast's rule
// before its rewrite) with the slowly varying factors at each node in
// half precision (weft_half: f16 where the device has shader-f16, else the
// f32 fallback): mc_low_node. theta_h, the support and the Gaussians' cell
// means stay f32: the Gaussians are as narrow as 2.5 deg, and their cdf
// differences cancel. (Two nodes per range instead of three were measured
// at worst FLIP 0.085 over the error grid: README.)

// mc_fast_node with the factors in half precision: the tilted cosines and
// theta_h in f32, then the masking and reweighting blends, cos(phi_d / 2),
// cos^2(theta_d) and the three exact Fresnel terms in weft_half. Bounds:
// every factor is in [0, 1] but 1 / cos^2(theta_d) <= 1e4 (floored at 1e-4,
// a normal f16 number) and cos(theta_i) / (cos(theta_i) + cos(theta_r))
// <= 1, so s and v are <= 1e4.
fn mc_low_node(q: McFastPre, ca: f32, sa: f32) -> McFastNode {
    let si = clamp(q.wi.x * ca + q.wi.z * sa, -1.0, 1.0);
    let sr = clamp(q.wr.x * ca + q.wr.z * sa, -1.0, 1.0);
    let ni = q.wi.z * ca - q.wi.x * sa;
    let nr = q.wr.z * ca - q.wr.x * sa;
    let ci2 = q.wi.y * q.wi.y + ni * ni;
    let cr2 = q.wr.y * q.wr.y + nr * nr;
    let ok = min(ci2, cr2) >= MC_MIN_PROJ2 && q.ok != 0.0;
    let inv_ci = inverseSqrt(max(ci2, MC_MIN_PROJ2));
    let inv_cr = inverseSqrt(max(cr2, MC_MIN_PROJ2));
    let ci_f = ci2 * inv_ci;
    let cr_f = cr2 * inv_cr;
    let cos_phi_d = clamp((q.wi.y * q.wr.y + ni * nr) * inv_ci * inv_cr, -1.0, 1.0);
    let phi_d = mc_acos_fast(cos_phi_d);
    let u_phi = exp(-phi_d * phi_d * MC_U_INV_TWO_SIGMA2);
    let x = 0.5 * (mc_asin_fast(si) + mc_asin_fast(sr));
    // Half from here: cosines and blends in [-1, 1].
    let ci = weft_half(ci_f);
    let cr = weft_half(cr_f);
    let eta = weft_half(q.eta);
    let cos_half_phi = sqrt(weft_half(0.5) + weft_half(0.5) * weft_half(cos_phi_d));
    // The masking M (lane 0) and the reweighting P (lane 1) blend alike,
    // and the two transmissions are one Fresnel at two cosines: each pair
    // shares a vec2<weft_half>, which AMD's compiler packs (README,
    // "`low` — the node rule in half precision").
    let at_i = max(vec2<weft_half>(vec2<f32>(ni * inv_ci, ni * q.inv_ri)), vec2<weft_half>(0.0));
    let at_r = max(vec2<weft_half>(vec2<f32>(nr * inv_cr, nr * q.inv_rr)), vec2<weft_half>(0.0));
    let blend = vec2<weft_half>(vec2<f32>(u_phi, q.u_psi));
    let mask = (vec2<weft_half>(1.0) - blend) * at_i * at_r + blend * min(at_i, at_r);
    let m = mask.x;
    let p = mask.y;
    let cd2 = max(weft_half(0.5) + weft_half(0.5) * weft_half(ci_f * cr_f + si * sr), weft_half(MC_MIN_COS2_THETA_D));
    let f_r = weft_half_f_dielectric(sqrt(cd2) * cos_half_phi, eta);
    let f_in_out = weft_half_f_dielectric2(vec2<weft_half>(ci, cr), eta);
    let f_t = (weft_half(1.0) - f_in_out.x) * (weft_half(1.0) - f_in_out.y);
    let mp = m * p / cd2;
    let s = f_r * cos_half_phi * mp * ci;
    let v = f_t * mp * (ci / max(ci + cr, weft_half(2e-4)));
    return McFastNode(x, select(0.0, f32(s), ok), select(0.0, f32(v), ok), select(0.0, f32(p), ok));
}

// mc_fast_segment with mc_low_node.
fn mc_low_segment(q: McFastPre, th: McThread, a0: f32, a1: f32, lo_s: f32, hi_s: f32) -> vec4<f32> {
    let span = abs(a1 - a0);
    let flat = span < MC_FAST_MIN_SPAN;
    let lo = clamp(lo_s, min(a0, a1), max(a0, a1));
    let hi = clamp(hi_s, lo, max(a0, a1));
    let w = hi - lo;
    let al = vec3<f32>(lo + MC_GL3_T * w, lo + 0.5 * w, hi - MC_GL3_T * w);
    let ca = cos(al);
    let sa = sin(al);
    let n0 = mc_low_node(q, ca.x, sa.x);
    let n1 = mc_low_node(q, ca.y, sa.y);
    let n2 = mc_low_node(q, ca.z, sa.z);
    let r = vec3<f32>(MC_GL3_W0, MC_GL3_W1, MC_GL3_W0) * select(w / max(span, MC_FAST_MIN_SPAN), 1.0, flat);
    return mc_fast_gl3(q, th, n0, n1, n2, r);
}

// mc_thread_list_fast with mc_low_segment (the same pieces).
fn mc_thread_list_low(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, th: McThread, offsets_a: vec4<f32>, offsets_b: vec4<f32>, count: i32) -> vec4<f32> {
    let n = clamp(count, 1, MC_MAX_OFFSETS);
    let q = mc_fast_pre(fr, wi, wr, th);
    let lo_s = atan(q.s_lo);
    let hi_s = atan(q.s_hi);
    let segments = max(n - 1, 1);
    let pieces = mc_list_piece_count(offsets_a, offsets_b, n);
    var acc = vec4<f32>(0.0);
    var k = 0;
    var h = 0;
    for (var i = 0; i < pieces; i++) {
        let piece = mc_list_piece(offsets_a, offsets_b, n, k, h);
        acc += mc_low_segment(q, th, piece.x, piece.y, lo_s, hi_s) * piece.z;
        let next = mc_list_next(offsets_a, offsets_b, n, k, h);
        k = next.x;
        h = next.y;
    }
    return acc / f32(segments);
}

// mc_thread_curve_fast with mc_low_node.
fn mc_thread_curve_low(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, th: McThread, heights: array<vec4<f32>, 9>) -> vec4<f32> {
    let q = mc_fast_pre(fr, wi, wr, th);
    let n = f32(MC_CURVE_SEGMENTS);
    let s0 = n * (-1.5 * heights[0].x + 2.0 * heights[0].y - 0.5 * heights[0].z);
    let s1 = 0.5 * n * (heights[4].y - heights[3].w);
    let s2 = n * (1.5 * heights[8].x - 2.0 * heights[7].w + 0.5 * heights[7].z);
    let h0 = mc_fast_half_clip(q, s0, s1, 0.0);
    let h1 = mc_fast_half_clip(q, s1, s2, 0.5);
    let t0 = min(h0.x, h1.x);
    let t1 = max(max(h0.y, h1.y), t0);
    let w = t1 - t0;
    let t = vec3<f32>(t0 + MC_GL3_T * w, t0 + 0.5 * w, t1 - MC_GL3_T * w);
    let sl = vec3<f32>(mc_fast_slope(s0, s1, s2, t.x), mc_fast_slope(s0, s1, s2, t.y), mc_fast_slope(s0, s1, s2, t.z));
    let inv_len = inverseSqrt(1.0 + sl * sl);
    let n0 = mc_low_node(q, inv_len.x, sl.x * inv_len.x);
    let n1 = mc_low_node(q, inv_len.y, sl.y * inv_len.y);
    let n2 = mc_low_node(q, inv_len.z, sl.z * inv_len.z);
    let r = vec3<f32>(MC_GL3_W0, MC_GL3_W1, MC_GL3_W0) * w / inv_len;
    let total = mc_fast_half_length(s0, s1) + mc_fast_half_length(s1, s2);
    return mc_fast_gl3(q, th, n0, n1, n2, r) / max(total, 1e-6);
}

// ---------------------------------------------------------------- fast tier
// The fast tier integrates the reference's offset distribution with the
// support-clipped node rule of the section above, with fewer and cheaper
// nodes where the loop-aware AMD model (README "fast") showed the cost:
//   - node factors (mc_fast_node): F_r exact (Walter et al. 2007, the same
//     reflectance as weft_f_dielectric in a one-division form); the
//     transmissions in and out by Schlick, (1 - F0)(1 - (1 - cos)^5) each
//     (relative error of 1 - F < 6 % for cos >= 0.2 and eta 1.345-1.54, up
//     to 21 % at grazing; measured: exact -> Schlick moved the worst FLIP by
//     0.0003; Schlick for F_r as well costs 0.15, README); theta_h =
//     asin((sin theta_i + sin theta_r) / (2 cos theta_d)), one polynomial
//     asin instead of two, with cos theta_d and 1 / cos^2(theta_d) from one
//     inverseSqrt; u(phi_d) and u(psi_d) from the cosine by the series
//     phi^2 = 4 (h + h^2/3 + ...), h = (1 - cos phi)/2 = sin^2(phi/2) (no
//     acos; |error of u| < 8.4e-4); the correlation blend as
//     M_i M_r + u (min - M_i M_r) (mc_fast_correlate);
//   - the volume Gaussian g(gamma_v) (twice gamma_s in every Table II row)
//     sampled at the nodes (the plain Gauss rule); only the narrow surface
//     Gaussian is averaged over each node's cell (erf);
//   - offset lists: the 3-node rule on each segment (halved beyond 60 deg);
//   - curves: one range in t (the hull of the halves' support intervals) and
//     two nodes. Where the range ends at a curve end (t = 0 or 1) the
//     2-point Gauss-Legendre rule (nodes 1/2 -+ sqrt(3)/6, weights 1/2);
//     where both ends are support bounds, the 2-point Gauss-Jacobi rule for
//     the weight (t - t0)^2 (t1 - t)^2 (nodes 1/2 -+ 1/(2 sqrt(7)), weights
//     98/270 of the width each): a support bound is a zero of n'.w_i or
//     n'.w_r, a factor of both M and P, so the integrand vanishes
//     quadratically there (Gauss-Legendre's pair integrates t^2 (1 - t)^2
//     17 % low; this pair integrates it times any cubic exactly; rim light
//     is this case). The surface Gaussian is averaged over the cells
//     [0, 1/2] and [1/2, 1] of the range (theta_h linear through the nodes,
//     both cells of equal width in theta_h: one division); the profile's
//     arc length by 2-point Gauss-Legendre on each half (exact for a
//     straight slope, < 1e-5 relative for the default arch).
// What depends on a thread set's uniforms alone (its widths, eta, the
// curve's slopes and arc length) is McFastConst: microcylinder.wgsl computes
// it once per vertex and passes it flat (RDNA has no scalar float ALU, so in
// the fragment stage it is per-pixel work; README, "Per-vertex constants").
// mc_thread_list_fast / mc_thread_curve_fast keep their signatures and
// compute it themselves (tests/physics/microcylinder/ calls them); the
// material calls the `_with` forms.

// Offset-list pieces (shared with low): segments beyond MC_FAST_SPLIT_DEG
// are integrated as two halves.
const MC_FAST_MIN_SPAN: f32 = 1e-4;
const MC_FAST_MIN_DSLOPE: f32 = 1e-4;
const MC_FAST_SPLIT_DEG: f32 = 60.0;
fn mc_fast_pieces(offsets_a: vec4<f32>, offsets_b: vec4<f32>, k: i32) -> i32 {
    let span = abs(mc_offset_at(offsets_a, offsets_b, k + 1) - mc_offset_at(offsets_a, offsets_b, k));
    return select(1, 2, span > MC_FAST_SPLIT_DEG);
}

// The pieces of an offset list of n points (fast and low walk the same
// ones): each of the n - 1 segments is one piece, or two halves beyond
// MC_FAST_SPLIT_DEG; a single point is one flat piece.
fn mc_list_piece_count(offsets_a: vec4<f32>, offsets_b: vec4<f32>, n: i32) -> i32 {
    let spans = abs(vec4<f32>(offsets_a.yzw, offsets_b.x) - offsets_a);
    let spans_b = abs(offsets_b.yzw - offsets_b.xyz);
    let live = vec4<i32>(0, 1, 2, 3) < vec4<i32>(n - 1);
    let live_b = vec3<i32>(4, 5, 6) < vec3<i32>(n - 1);
    let per = select(vec4<i32>(0), select(vec4<i32>(1), vec4<i32>(2), spans > vec4<f32>(MC_FAST_SPLIT_DEG)), live);
    let per_b = select(vec3<i32>(0), select(vec3<i32>(1), vec3<i32>(2), spans_b > vec3<f32>(MC_FAST_SPLIT_DEG)), live_b);
    return max(per.x + per.y + per.z + per.w + per_b.x + per_b.y + per_b.z, 1);
}

// Piece h of segment k: its ends in radians and its share 1/m of the
// segment (x, y, z).
fn mc_list_piece(offsets_a: vec4<f32>, offsets_b: vec4<f32>, n: i32, k: i32, h: i32) -> vec3<f32> {
    let d0 = mc_offset_at(offsets_a, offsets_b, k) * MC_DEG;
    let d1 = select(d0, mc_offset_at(offsets_a, offsets_b, k + 1) * MC_DEG, n > 1);
    let fm = f32(select(1, mc_fast_pieces(offsets_a, offsets_b, k), n > 1));
    return vec3<f32>(mix(d0, d1, f32(h) / fm), mix(d0, d1, f32(h + 1) / fm), 1.0 / fm);
}

// The next (segment, piece) after piece h of segment k.
fn mc_list_next(offsets_a: vec4<f32>, offsets_b: vec4<f32>, n: i32, k: i32, h: i32) -> vec2<i32> {
    let m = select(1, mc_fast_pieces(offsets_a, offsets_b, k), n > 1);
    let next = h + 1;
    return select(vec2<i32>(k, next), vec2<i32>(k + 1, 0), next >= m);
}

// Per thread set, as McFastPre, with eta^2 and Schlick's 1 - F0 instead of eta.
struct McFastSet {
    wi: vec3<f32>,
    wr: vec3<f32>,
    inv_ri: f32,
    inv_rr: f32,
    u_psi: f32,
    ok: f32,
    inv_gamma_s: f32,
    inv_gamma_v: f32,
    s_lo: f32,
    s_hi: f32,
    eta2: f32,
    // (1 - F0)^2: Schlick's transmission in and out at normal incidence.
    t02: f32,
}

// u(x) = exp(-x^2 / (2 (20 deg)^2)) of the angle x whose cosine is c:
// x^2 = 4 asin^2(sqrt(h)), h = (1 - c)/2 = sin^2(x/2), by its series
// h + h^2/3 + 8h^3/45 + ... to h^2 (|error of u| < 8.4e-4, largest near
// 49 deg; u < 1e-5 beyond 90 deg where the truncation grows).
fn mc_u_of_cos(c: f32) -> f32 {
    let h = 0.5 - 0.5 * clamp(c, -1.0, 1.0);
    let x2 = h * (1.0 + 0.333333333333 * h);
    return exp(-4.0 * MC_U_INV_TWO_SIGMA2 * x2);
}

// mc_correlate rearranged: M_i M_r + u (min(M_i, M_r) - M_i M_r).
fn mc_fast_correlate(ci: f32, cr: f32, u: f32) -> f32 {
    let mi = max(ci, 0.0);
    let mr = max(cr, 0.0);
    let prod = mi * mr;
    return prod + u * (min(mi, mr) - prod);
}

// asin(x) = sign(x) (pi/2 - acos(|x|)), acos as mc_acos_fast (|error| < 6.8e-5 rad).
fn mc_fast_asin(x: f32) -> f32 {
    let ax = min(abs(x), 1.0);
    let r = 0.5 * WEFT_PI - sqrt(1.0 - ax) * (1.5707288 + ax * (-0.2121144 + ax * (0.0742610 - 0.0187293 * ax)));
    return select(r, -r, x < 0.0);
}

// Exact unpolarised dielectric reflectance for eta^2 >= 1 (the value of
// weft_f_dielectric): Rs = ((g - c)/(g + c))^2, Rp = ((eta^2 c - g)/(eta^2 c
// + g))^2, g = sqrt(eta^2 - 1 + c^2), over one common denominator.
fn mc_fresnel_exact(c_in: f32, eta2: f32) -> f32 {
    let c = clamp(c_in, WEFT_MIN_N_DOT, 1.0);
    let g = sqrt(max(eta2 - 1.0 + c * c, 0.0));
    let ec = eta2 * c;
    let a = (g - c) * (ec + g);
    let b = (ec - g) * (g + c);
    // d >= 4 c^2 >= 4e-8 (g >= c, eta^2 >= 1).
    let d = (g + c) * (ec + g);
    return saturate(0.5 * (a * a + b * b) / (d * d));
}

// Schlick's transmission 1 - F without the (1 - F0) factor: 1 - (1 - c)^5.
fn mc_schlick_t(c: f32) -> f32 {
    let x = 1.0 - saturate(c);
    let x2 = x * x;
    return 1.0 - x2 * x2 * x;
}

// A thread set's values that depend on its uniforms alone.
struct McFastConst {
    // 1/gamma_s, 1/gamma_v (gamma floored at MC_MIN_GAMMA), eta^2, (1 - F0)^2.
    shape: vec4<f32>,
    // A curve: its slopes at t = 0, 1/2, 1 and 1 / its arc length.
    curve: vec4<f32>,
    // A curve: 1 / the slope step of each half (mc_fast_clip_step).
    steps: vec2<f32>,
}

fn mc_fast_shape(th: McThread) -> vec4<f32> {
    let f0 = weft_f0_from_ior(th.eta);
    return vec4<f32>(1.0 / max(th.gamma_s, MC_MIN_GAMMA), 1.0 / max(th.gamma_v, MC_MIN_GAMMA),
                     th.eta * th.eta, (1.0 - f0) * (1.0 - f0));
}

// The curve's slopes at t = 0, 1/2, 1 (one-sided and central differences of
// its 33 heights, as the low tier), its arc length (mc_fast_half_len on each
// half) and each half's inverse slope step.
fn mc_fast_const(th: McThread, heights: array<vec4<f32>, 9>) -> McFastConst {
    let n = f32(MC_CURVE_SEGMENTS);
    let s0 = n * (-1.5 * heights[0].x + 2.0 * heights[0].y - 0.5 * heights[0].z);
    let s1 = 0.5 * n * (heights[4].y - heights[3].w);
    let s2 = n * (1.5 * heights[8].x - 2.0 * heights[7].w + 0.5 * heights[7].z);
    let total = mc_fast_half_len(s0, s1) + mc_fast_half_len(s1, s2);
    return McFastConst(mc_fast_shape(th), vec4<f32>(s0, s1, s2, 1.0 / max(total, 1e-6)),
                       vec2<f32>(mc_fast_clip_step(s0, s1), mc_fast_clip_step(s1, s2)));
}

// As mc_fast_pre: frame components, psi, the support in slope space; `shape`
// as McFastConst's.
fn mc_fast_setup(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, shape: vec4<f32>) -> McFastSet {
    let li = vec3<f32>(dot(wi, fr.u), dot(wi, fr.v), dot(wi, fr.n));
    let lr = vec3<f32>(dot(wr, fr.u), dot(wr, fr.v), dot(wr, fr.n));
    let ri2 = li.x * li.x + li.z * li.z;
    let rr2 = lr.x * lr.x + lr.z * lr.z;
    let ok = min(ri2, rr2) >= MC_MIN_PROJ2;
    let inv_ri = inverseSqrt(max(ri2, MC_MIN_PROJ2));
    let inv_rr = inverseSqrt(max(rr2, MC_MIN_PROJ2));
    let u_psi = mc_u_of_cos((li.x * lr.x + li.z * lr.z) * inv_ri * inv_rr);
    let bi = li.z / select(max(li.x, 1e-12), min(li.x, -1e-12), li.x < 0.0);
    let br = lr.z / select(max(lr.x, 1e-12), min(lr.x, -1e-12), lr.x < 0.0);
    let s_lo = max(select(-MC_FAST_BIG, bi, li.x < 0.0), select(-MC_FAST_BIG, br, lr.x < 0.0));
    let s_hi = min(select(MC_FAST_BIG, bi, li.x > 0.0), select(MC_FAST_BIG, br, lr.x > 0.0));
    return McFastSet(li, lr, inv_ri, inv_rr, u_psi, select(0.0, 1.0, ok), shape.x, shape.y,
                     clamp(s_lo, -MC_FAST_BIG, MC_FAST_BIG), clamp(s_hi, -MC_FAST_BIG, MC_FAST_BIG),
                     shape.z, shape.w);
}

// The factors at the offset with (cos, sin) = (ca, sa), as mc_low_node in
// f32 with the cheaper forms listed above. sin(theta_i) + sin(theta_r) =
// 2 sin(theta_h) cos(theta_d). Skipped (zero) as the reference skips a sample.
fn mc_fast_node(q: McFastSet, ca: f32, sa: f32) -> McFastNode {
    let si = q.wi.x * ca + q.wi.z * sa;
    let sr = q.wr.x * ca + q.wr.z * sa;
    let ni = q.wi.z * ca - q.wi.x * sa;
    let nr = q.wr.z * ca - q.wr.x * sa;
    let ci2 = q.wi.y * q.wi.y + ni * ni;
    let cr2 = q.wr.y * q.wr.y + nr * nr;
    let ok = min(ci2, cr2) >= MC_MIN_PROJ2 && q.ok != 0.0;
    let inv_ci = inverseSqrt(max(ci2, MC_MIN_PROJ2));
    let inv_cr = inverseSqrt(max(cr2, MC_MIN_PROJ2));
    let ci = ci2 * inv_ci;
    let cr = cr2 * inv_cr;
    let cos_phi_d = (q.wi.y * q.wr.y + ni * nr) * inv_ci * inv_cr;
    let cos_half_phi = sqrt(saturate(0.5 + 0.5 * cos_phi_d));
    let m = mc_fast_correlate(ni * inv_ci, nr * inv_cr, mc_u_of_cos(cos_phi_d));
    let p = mc_fast_correlate(ni * q.inv_ri, nr * q.inv_rr, q.u_psi);
    let cd2 = max(0.5 + 0.5 * (ci * cr + si * sr), MC_MIN_COS2_THETA_D);
    let inv_cd = inverseSqrt(cd2);
    let x = mc_fast_asin(clamp(0.5 * (si + sr) * inv_cd, -1.0, 1.0));
    let f_r = mc_fresnel_exact(cd2 * inv_cd * cos_half_phi, q.eta2);
    let f_t = q.t02 * mc_schlick_t(ci) * mc_schlick_t(cr);
    let base = select(0.0, m * p * ci * inv_cd * inv_cd, ok);
    return McFastNode(x, f_r * cos_half_phi * base, f_t * base / max(ci + cr, 2e-4), select(0.0, p, ok));
}

// The Gaussian g(gamma_v, theta_h) at three or two nodes (the plain rule).
fn mc_fast_volume3(x: vec3<f32>, inv_gamma: f32) -> vec3<f32> {
    let t = x * inv_gamma;
    return exp(-0.5 * t * t) * (MC_INV_SQRT_TWO_PI * inv_gamma);
}
fn mc_fast_volume2(x: vec2<f32>, inv_gamma: f32) -> vec2<f32> {
    let t = x * inv_gamma;
    return exp(-0.5 * t * t) * (MC_INV_SQRT_TWO_PI * inv_gamma);
}

// The 3-node rule on one range (as mc_fast_gl3): the surface Gaussian
// averaged over the cells (mc_cell_means), the volume Gaussian at the nodes.
fn mc_fast_rule3(q: McFastSet, th: McThread, n0: McFastNode, n1: McFastNode, n2: McFastNode, r: vec3<f32>) -> vec4<f32> {
    let xe = vec4<f32>(n0.x + MC_GL3_E0 * (n1.x - n0.x), n0.x + MC_GL3_E1 * (n1.x - n0.x),
                       n2.x - MC_GL3_E1 * (n2.x - n1.x), n2.x - MC_GL3_E0 * (n2.x - n1.x));
    let gs = mc_cell_means(xe, q.inv_gamma_s);
    let gv = mc_fast_volume3(vec3<f32>(n0.x, n1.x, n2.x), q.inv_gamma_v);
    let s = r * vec3<f32>(n0.s, n1.s, n2.s);
    let v = r * vec3<f32>(n0.v, n1.v, n2.v);
    let surface = dot(gs, s);
    let volume = (1.0 - th.kd) * dot(gv, v) + th.kd * (v.x + v.y + v.z);
    return vec4<f32>(vec3<f32>(surface) + volume * th.albedo, dot(r, vec3<f32>(n0.p, n1.p, n2.p)));
}

// Offset list piece (as mc_low_segment): uniform offsets in [a0, a1],
// clipped to the support, 3 nodes; a flat piece is the point lobe.
fn mc_fast_segment(q: McFastSet, th: McThread, a0: f32, a1: f32, lo_s: f32, hi_s: f32) -> vec4<f32> {
    let span = abs(a1 - a0);
    let flat = span < MC_FAST_MIN_SPAN;
    let lo = clamp(lo_s, min(a0, a1), max(a0, a1));
    let hi = clamp(hi_s, lo, max(a0, a1));
    let w = hi - lo;
    let al = vec3<f32>(lo + MC_GL3_T * w, lo + 0.5 * w, hi - MC_GL3_T * w);
    let ca = cos(al);
    let sa = sin(al);
    let n0 = mc_fast_node(q, ca.x, sa.x);
    let n1 = mc_fast_node(q, ca.y, sa.y);
    let n2 = mc_fast_node(q, ca.z, sa.z);
    let r = vec3<f32>(MC_GL3_W0, MC_GL3_W1, MC_GL3_W0) * select(w / max(span, MC_FAST_MIN_SPAN), 1.0, flat);
    return mc_fast_rule3(q, th, n0, n1, n2, r);
}

// Fast, offset list: the same pieces as the reference's polyline (each
// segment one piece, two halves beyond MC_FAST_SPLIT_DEG), segments weighted
// equally; one loop over the pieces, no branches.
fn mc_thread_list_fast(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, th: McThread, offsets_a: vec4<f32>, offsets_b: vec4<f32>, count: i32) -> vec4<f32> {
    return mc_thread_list_fast_with(fr, wi, wr, th, mc_fast_shape(th), offsets_a, offsets_b, count);
}

fn mc_thread_list_fast_with(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, th: McThread, shape: vec4<f32>, offsets_a: vec4<f32>, offsets_b: vec4<f32>, count: i32) -> vec4<f32> {
    let n = clamp(count, 1, MC_MAX_OFFSETS);
    let q = mc_fast_setup(fr, wi, wr, shape);
    let lo_s = atan(q.s_lo);
    let hi_s = atan(q.s_hi);
    // A single control point: one flat piece on it.
    let segments = max(n - 1, 1);
    let pieces = mc_list_piece_count(offsets_a, offsets_b, n);
    var acc = vec4<f32>(0.0);
    var k = 0;
    var h = 0;
    for (var i = 0; i < pieces; i++) {
        let piece = mc_list_piece(offsets_a, offsets_b, n, k, h);
        acc += mc_fast_segment(q, th, piece.x, piece.y, lo_s, hi_s) * piece.z;
        let next = mc_list_next(offsets_a, offsets_b, n, k, h);
        k = next.x;
        h = next.y;
    }
    return acc / f32(segments);
}

// Curve, one half (as mc_fast_half_clip): the t in [ta, ta + 1/2] whose
// slope (linear from sa to sb) lies in (s_lo, s_hi), as (t0, t1); empty as
// (2, -1). `inv` = mc_fast_clip_step(sa, sb).
fn mc_fast_clip(s_lo: f32, s_hi: f32, sa: f32, inv: f32, ta: f32) -> vec2<f32> {
    let u0 = (s_lo - sa) * inv;
    let u1 = (s_hi - sa) * inv;
    let u = saturate(vec2<f32>(min(u0, u1), max(u0, u1)));
    return select(vec2<f32>(2.0, -1.0), ta + 0.5 * u, u.x < u.y);
}

// 1 / the slope step sb - sa of a half. A flat half (|sb - sa| <
// MC_FAST_MIN_DSLOPE) is taken with that slope step, so that its interval is
// all or nothing.
fn mc_fast_clip_step(sa: f32, sb: f32) -> f32 {
    let ds = sb - sa;
    return 1.0 / select(ds, select(-MC_FAST_MIN_DSLOPE, MC_FAST_MIN_DSLOPE, ds >= 0.0), abs(ds) < MC_FAST_MIN_DSLOPE);
}

// Arc length of a half (t over 1/2, slope linear from sa to sb) by 2-point
// Gauss-Legendre.
fn mc_fast_half_len(sa: f32, sb: f32) -> f32 {
    let s = vec2<f32>(mix(sa, sb, MC_GL2_T), mix(sa, sb, 1.0 - MC_GL2_T));
    let l = sqrt(1.0 + s * s);
    return 0.25 * (l.x + l.y);
}

// Two-node rules on [0, 1]: Gauss-Legendre (node offset from the ends, weight)
// and Gauss-Jacobi for the weight t^2 (1 - t)^2 (nodes 1/2 -+ 1/(2 sqrt 7):
// (1/60) / (3/14)^2 = 98/270 of the width each).
const MC_GL2_T: f32 = 0.211324865405;
const MC_GJ2_T: f32 = 0.311017764983;
// tn / (1 - 2 tn) of each: (sqrt 3 - 1) / 2 and (sqrt 7 - 1) / 2.
const MC_GL2_E: f32 = 0.366025403784;
const MC_GJ2_E: f32 = 0.822875655532;
const MC_GJ2_W: f32 = 0.362962962963;

// Standard normal at each t: (pdf, cdf - 1/2), as mc_normal4.
fn mc_normal3(t: vec3<f32>) -> array<vec3<f32>, 2> {
    let e = exp(-0.5 * t * t);
    let z = abs(t) * 0.707106781187;
    let k = 1.0 / (1.0 + 0.3275911 * z);
    let poly = k * (0.254829592 + k * (-0.284496736 + k * (1.421413741 + k * (-1.453152027 + k * 1.061405429))));
    let half = 0.5 - 0.5 * poly * e;
    return array<vec3<f32>, 2>(e * MC_INV_SQRT_TWO_PI, select(-half, half, t >= vec3<f32>(0.0)));
}

// The 2-node rule on one range: nodes at tn and 1 - tn of it (tn of the
// Gauss-Jacobi pair if `jacobi`, else of Gauss-Legendre's), weights r;
// theta_h linear through the nodes gives the cell edges at 0, 1/2, 1
// (e = tn / (1 - 2 tn) node steps beyond the nodes, a constant of each rule:
// no division); the surface Gaussian
// averaged over each cell (mean of the edge pdfs below 0.1 gamma, as
// mc_cell_means), the volume Gaussian at the nodes.
fn mc_fast_rule2(q: McFastSet, th: McThread, n0: McFastNode, n1: McFastNode, r: vec2<f32>, jacobi: bool) -> vec4<f32> {
    let e = select(MC_GL2_E, MC_GJ2_E, jacobi);
    let d = n1.x - n0.x;
    let xe = vec3<f32>(n0.x - e * d, 0.5 * (n0.x + n1.x), n1.x + e * d);
    // Both cells span the same width in theta_h.
    let dx = select(0.5 + MC_GL2_E, 0.5 + MC_GJ2_E, jacobi) * d;
    let nd = mc_normal3(xe * q.inv_gamma_s);
    let wide = abs(dx) * q.inv_gamma_s >= MC_FAST_MIN_DT;
    let exact = (nd[1].yz - nd[1].xy) / select(1.0, dx, wide);
    let trap = 0.5 * q.inv_gamma_s * (nd[0].xy + nd[0].yz);
    let gs = max(select(trap, exact, wide), vec2<f32>(0.0));
    let gv = mc_fast_volume2(vec2<f32>(n0.x, n1.x), q.inv_gamma_v);
    let s = r * vec2<f32>(n0.s, n1.s);
    let v = r * vec2<f32>(n0.v, n1.v);
    let surface = dot(gs, s);
    let volume = (1.0 - th.kd) * dot(gv, v) + th.kd * (v.x + v.y);
    return vec4<f32>(vec3<f32>(surface) + volume * th.albedo, dot(r, vec2<f32>(n0.p, n1.p)));
}

// Fast, tangent curve: the profile's slope at t = 0, 1/2, 1 (as the low
// tier), linear in t on each half; one range in t over the hull of the two
// halves' support intervals; two nodes (Gauss-Jacobi where both ends of the
// range are support bounds, else Gauss-Legendre), each weighted by its arc
// length sqrt(1 + s^2), offset atan(s); divided by the profile's arc length.
fn mc_thread_curve_fast(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, th: McThread, heights: array<vec4<f32>, 9>) -> vec4<f32> {
    return mc_thread_curve_fast_with(fr, wi, wr, th, mc_fast_const(th, heights));
}

fn mc_thread_curve_fast_with(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, th: McThread, k: McFastConst) -> vec4<f32> {
    let q = mc_fast_setup(fr, wi, wr, k.shape);
    let s0 = k.curve.x;
    let s1 = k.curve.y;
    let s2 = k.curve.z;
    let h0 = mc_fast_clip(q.s_lo, q.s_hi, s0, k.steps.x, 0.0);
    let h1 = mc_fast_clip(q.s_lo, q.s_hi, s1, k.steps.y, 0.5);
    let t0 = min(h0.x, h1.x);
    let t1 = max(max(h0.y, h1.y), t0);
    let w = t1 - t0;
    // Both ends support bounds (not the profile's ends): Gauss-Jacobi.
    let bump = t0 > 1e-4 && t1 < 1.0 - 1e-4;
    let tn = select(MC_GL2_T, MC_GJ2_T, bump);
    let t = vec2<f32>(t0 + tn * w, t1 - tn * w);
    let sl = vec2<f32>(mc_fast_slope(s0, s1, s2, t.x), mc_fast_slope(s0, s1, s2, t.y));
    let l2 = 1.0 + sl * sl;
    let inv_len = inverseSqrt(l2);
    let n0 = mc_fast_node(q, inv_len.x, sl.x * inv_len.x);
    let n1 = mc_fast_node(q, inv_len.y, sl.y * inv_len.y);
    let r = select(0.5, MC_GJ2_W, bump) * w * (l2 * inv_len);
    return mc_fast_rule2(q, th, n0, n1, r, bump) * k.curve.w;
}
