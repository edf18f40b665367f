// weft half-precision BRDF terms for `low` tiers: pure functions in
// `weft_half`, which is f16 in the WGSL, SPIR-V and MSL a half-precision
// variant ships (device feature `shader-f16`) and f32 in its fallback, HLSL
// and GLSL (docs/material-format.md, "Half precision").
//
// f16 has 10 mantissa bits, a largest finite value of 65504 and a smallest
// normal one of 6.1e-5. Every function here keeps its intermediates inside
// that range for the cosines and roughness of its documented domain, so no
// Inf is ever formed (Inf * 0 would be NaN): results that can exceed 65504
// are clamped to it, as the final radiance is anyway. Lighting (radiance,
// environment, SH) stays f32: only the dimensionless BRDF terms are half.

// Smallest perceptual roughness in half precision (Filament's
// MIN_PERCEPTUAL_ROUGHNESS for mediump): alpha^2 = 6.3e-5 is still a normal
// f16 number and the GGX peak 1 / (pi alpha^2) ~ 5.1e3 stays finite. The f32
// tiers stop at 0.045, whose peak (7.8e4) would overflow.
const WEFT_MIN_ROUGHNESS_HALF: f32 = 0.089;
// Smallest cosine used in a half-precision denominator (a normal f16 number).
const WEFT_MIN_N_DOT_HALF: f32 = 1e-3;

fn weft_half_min_max(x: weft_half) -> weft_half {
    return min(x, weft_half(65504.0));
}

fn weft_half_pow5(x: weft_half) -> weft_half {
    let x2 = x * x;
    return x2 * x2 * x;
}

// GGX D in Filament's mediump form: with alpha = r^2,
// k = alpha / ((1 - n.h^2) + (n.h alpha)^2) and D = k^2 / pi. k <= 1 / alpha
// <= 126, so k^2 never overflows; `one_minus_n_dot_h2` = 1 - n.h^2 computed
// in f32 and then rounded (formed from an f16 n.h it would cancel near the
// peak, the reason for the form).
fn weft_half_d_ggx(one_minus_n_dot_h2: weft_half, n_dot_h: weft_half, alpha: weft_half) -> weft_half {
    let a = n_dot_h * alpha;
    let k = alpha / (one_minus_n_dot_h2 + a * a);
    return weft_half_min_max(k * k * weft_half(WEFT_INV_PI));
}

// Hammon's linear form of the height-correlated Smith visibility, times n.l:
// V n.l = 0.5 n.l / mix(2 n.l n.v, n.l + n.v, alpha). Folding n.l in keeps it
// finite where V alone overflows (grazing light); the denominator is floored
// at 1e-4, a normal f16 number, so a GPU that flushes f16 subnormals to zero
// never divides 0 by 0 (n.l = 0 gives 0). The floor only acts where both
// cosines are below ~1e-2, and bounds V n.l there by 5e3 n.l.
fn weft_half_v_smith_ggx_correlated_fast_nl(n_dot_v: weft_half, n_dot_l: weft_half, alpha: weft_half) -> weft_half {
    let nv = max(n_dot_v, weft_half(WEFT_MIN_N_DOT_HALF));
    let denominator = mix(weft_half(2.0) * n_dot_l * nv, n_dot_l + nv, alpha);
    return weft_half(0.5) * n_dot_l / max(denominator, weft_half(1e-4));
}

// The height-correlated Smith visibility as `fast` computes it in f32
// (lib/brdf.wgsl, weft_v_smith_ggx_correlated_newton: Hammon's chord
// g = mix(x, 1, alpha) refined by one Newton step, P = g x + alpha^2 (1 - x)),
// times n.l, in a form whose intermediates stay in f16's range: dividing
// V = 0.5 g_v g_l / (n.l g_l P_v + n.v g_v P_l) through by g_v g_l gives
// V n.l = 0.5 n.l / (n.l q_v + n.v q_l) with q = P / g in [x, x + alpha]
// (g >= alpha >= 7.9e-3, a normal f16 number), so no product of three small
// factors (alpha^3 would be an f16 subnormal) is ever formed. The
// denominator is ~alpha (n.l + n.v) near zero, as Hammon's: floored at 1e-4
// for the same reason.
fn weft_half_v_smith_ggx_correlated_newton_nl(n_dot_v: weft_half, n_dot_l: weft_half, alpha: weft_half) -> weft_half {
    // The view (lane 0) and light (lane 1) terms alike, in one vec2 so that
    // a compiler packing f16 pairs (AMD's `v_pk_*`) does both at once.
    let x = vec2<weft_half>(max(n_dot_v, weft_half(WEFT_MIN_N_DOT_HALF)), n_dot_l);
    let alpha2 = alpha * alpha;
    let g = mix(x, vec2<weft_half>(1.0), alpha);
    // One reciprocal for both 1/g (a reciprocal costs four multiplies on
    // AMD's compiler): g_v g_l >= alpha (alpha + 1e-3 (1 - alpha)) >= 7e-5 at
    // the 0.089 roughness floor, a normal f16 number, and 1/(g_v g_l) <= 1.5e4.
    let inv_gg = weft_half(1.0) / (g.x * g.y);
    // (q_v, q_l): q_v = x_v + alpha^2 (1 - x_v) / g_v, and so for l.
    let q = x + alpha2 * (vec2<weft_half>(1.0) - x) * (g.yx * inv_gg);
    let denominator = x.y * q.x + x.x * q.y;
    return weft_half(0.5) * n_dot_l / max(denominator, weft_half(1e-4));
}

// Schlick 1994: F = F0 + (1 - F0)(1 - v.h)^5.
fn weft_half_f_schlick(f0: vec3<weft_half>, v_dot_h: weft_half) -> vec3<weft_half> {
    return f0 + (vec3<weft_half>(1.0) - f0) * weft_half_pow5(weft_half(1.0) - v_dot_h);
}

// ---------------------------------------------------------------- anisotropic GGX
// Smallest anisotropic GGX width in half precision: the square of
// WEFT_MIN_ROUGHNESS_HALF. The widths enter only through their reciprocals
// (<= 126.2, formed in f32), so a_t a_b (>= 6.3e-5, barely a normal f16
// number) is never formed; the peak 1 / (pi a_t a_b) <= 5.1e3.
const WEFT_MIN_ALPHA_HALF: f32 = 0.007921;

// Normalised anisotropic GGX D times the height-correlated anisotropic Smith
// visibility times n.l (lib/anisotropic.wgsl's weft_spec_ggx_aniso) in half
// precision. v, l, h: frame components (T, B, N) of the unit view, light and
// half vectors; alpha: (a_t, a_b), floored at WEFT_MIN_ALPHA_HALF here.
// Bounds for unit h: x = T.h / a_t and y = B.h / a_b give x^2 + y^2 <= 1.6e4,
// q = x^2 + y^2 + (N.h)^2 >= 1/4 (floored at 1e-2 for a degenerate h),
// D pi = (1 / (a_t a_b)) / q^2 <= 1.6e4, formed as ((1/a_t)(1/a_b) / q) / q,
// each step <= 1.6e4. V n.l = 0.5 n.l / (n.l |(a_t v_t, a_b v_b, n.v)| +
// n.v |(a_t l_t, a_b l_b, n.l)|), n.v floored at 1e-3 and the denominator
// at 1e-4 (as weft_half_v_smith_ggx_correlated_fast_nl). D V n.l is clamped
// to 65504.
fn weft_half_spec_ggx_aniso(v: vec3<weft_half>, l: vec3<weft_half>, h: vec3<weft_half>, alpha: vec2<f32>) -> weft_half {
    let a = max(alpha, vec2<f32>(WEFT_MIN_ALPHA_HALF));
    let inv_a = vec2<weft_half>(vec2<f32>(1.0) / a);
    let ah = vec2<weft_half>(a);
    let x = h.x * inv_a.x;
    let y = h.y * inv_a.y;
    let q = max(x * x + y * y + h.z * h.z, weft_half(1e-2));
    let d = inv_a.x * inv_a.y / q / q * weft_half(WEFT_INV_PI);
    let nv = max(v.z, weft_half(WEFT_MIN_N_DOT_HALF));
    let nl = saturate(l.z);
    let lv = nl * length(vec3<weft_half>(ah.x * v.x, ah.y * v.y, nv));
    let ll = nv * length(vec3<weft_half>(ah.x * l.x, ah.y * l.y, nl));
    let v_n_dot_l = weft_half(0.5) * nl / max(lv + ll, weft_half(1e-4));
    return select(weft_half(0.0), weft_half_min_max(d * v_n_dot_l), h.z > weft_half(0.0));
}

// Two lobes of weft_half_spec_ggx_aniso at once, one per lane (lane i has
// widths (alpha_t[i], alpha_b[i])), the same values and bounds: written as
// vec2<weft_half> so that a compiler packing f16 pairs (AMD's `v_pk_*`) does
// both lobes' multiply-adds in one instruction each.
fn weft_half_spec_ggx_aniso2(v: vec3<weft_half>, l: vec3<weft_half>, h: vec3<weft_half>, alpha_t: vec2<f32>, alpha_b: vec2<f32>) -> vec2<weft_half> {
    let at = max(alpha_t, vec2<f32>(WEFT_MIN_ALPHA_HALF));
    let ab = max(alpha_b, vec2<f32>(WEFT_MIN_ALPHA_HALF));
    let inv_at = vec2<weft_half>(vec2<f32>(1.0) / at);
    let inv_ab = vec2<weft_half>(vec2<f32>(1.0) / ab);
    let at_h = vec2<weft_half>(at);
    let ab_h = vec2<weft_half>(ab);
    let x = h.x * inv_at;
    let y = h.y * inv_ab;
    let q = max(x * x + y * y + vec2<weft_half>(h.z * h.z), vec2<weft_half>(1e-2));
    let d = inv_at * inv_ab / q / q * weft_half(WEFT_INV_PI);
    let nv = max(v.z, weft_half(WEFT_MIN_N_DOT_HALF));
    let nl = saturate(l.z);
    let vt = at_h * v.x;
    let vb = ab_h * v.y;
    let lt = at_h * l.x;
    let lb = ab_h * l.y;
    let lv = nl * sqrt(vt * vt + vb * vb + vec2<weft_half>(nv * nv));
    let ll = nv * sqrt(lt * lt + lb * lb + vec2<weft_half>(nl * nl));
    let v_n_dot_l = weft_half(0.5) * nl / max(lv + ll, vec2<weft_half>(1e-4));
    return select(vec2<weft_half>(0.0), min(d * v_n_dot_l, vec2<weft_half>(65504.0)), h.z > weft_half(0.0));
}

// ---------------------------------------------------------------- Fresnel
// Exact unpolarised Fresnel reflectance of a dielectric (lib/brdf.wgsl's
// weft_f_dielectric) in half precision, for eta in [1, 4] (the caller
// clamps it): g^2 = eta^2 - 1 + c^2 <= 16, c floored at 1e-3, a and b
// bounded by 1 in magnitude, the denominators at least 1 for eta >= 1
// (floored at 1e-3 for safety). In [0, 1].
fn weft_half_f_dielectric(cos_i: weft_half, eta: weft_half) -> weft_half {
    let c = clamp(abs(cos_i), weft_half(WEFT_MIN_N_DOT_HALF), weft_half(1.0));
    let g2 = eta * eta - weft_half(1.0) + c * c;
    let g = sqrt(max(g2, weft_half(0.0)));
    let gmc = g - c;
    let gpc = max(g + c, weft_half(1e-3));
    let a = gmc / gpc;
    let b = (c * gpc - weft_half(1.0)) / max(c * gmc + weft_half(1.0), weft_half(1e-3));
    let f = saturate(weft_half(0.5) * a * a * (weft_half(1.0) + b * b));
    return select(f, weft_half(1.0), g2 < weft_half(0.0));
}

// weft_half_f_dielectric at two cosines at once, one per lane (the same
// values and bounds), so that a compiler packing f16 pairs (AMD's `v_pk_*`)
// evaluates both in one instruction each.
fn weft_half_f_dielectric2(cos_i: vec2<weft_half>, eta: weft_half) -> vec2<weft_half> {
    let c = clamp(abs(cos_i), vec2<weft_half>(weft_half(WEFT_MIN_N_DOT_HALF)), vec2<weft_half>(1.0));
    let g2 = vec2<weft_half>(eta * eta - weft_half(1.0)) + c * c;
    let g = sqrt(max(g2, vec2<weft_half>(0.0)));
    let gmc = g - c;
    let gpc = max(g + c, vec2<weft_half>(1e-3));
    let a = gmc / gpc;
    let b = (c * gpc - vec2<weft_half>(1.0)) / max(c * gmc + vec2<weft_half>(1.0), vec2<weft_half>(1e-3));
    let f = saturate(weft_half(0.5) * a * a * (vec2<weft_half>(1.0) + b * b));
    return select(f, vec2<weft_half>(1.0), g2 < vec2<weft_half>(0.0));
}
