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
// <= 126, so k^2 never overflows; `one_minus_n_dot_h2` = |n x h|^2 computed
// in f32 (the cancellation near the peak is the reason for the form).
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
    let nv = max(n_dot_v, weft_half(WEFT_MIN_N_DOT_HALF));
    let alpha2 = alpha * alpha;
    let g_v = mix(nv, weft_half(1.0), alpha);
    let g_l = mix(n_dot_l, weft_half(1.0), alpha);
    let q_v = nv + alpha2 * (weft_half(1.0) - nv) / g_v;
    let q_l = n_dot_l + alpha2 * (weft_half(1.0) - n_dot_l) / g_l;
    let denominator = n_dot_l * q_v + nv * q_l;
    return weft_half(0.5) * n_dot_l / max(denominator, weft_half(1e-4));
}

// Schlick 1994: F = F0 + (1 - F0)(1 - v.h)^5.
fn weft_half_f_schlick(f0: vec3<weft_half>, v_dot_h: weft_half) -> vec3<weft_half> {
    return f0 + (vec3<weft_half>(1.0) - f0) * weft_half_pow5(weft_half(1.0) - v_dot_h);
}
