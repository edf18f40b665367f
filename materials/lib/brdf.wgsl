// weft BRDF library: pure functions, no bindings.
//
// Conventions: `roughness` is perceptual roughness r in [0, 1]; alpha = r^2.
// n_dot_x = dot(n, x). Every function returns finite, non-negative values for
// any input in its documented domain, including grazing (0), back-facing
// (negative) cosines and r = 0. Uses WEFT_PI / WEFT_INV_PI from the engine
// interface, which the toolchain composes ahead of every material.

// Smallest perceptual roughness used inside D and V: alpha^2 = 4.1e-6 stays a
// normal fp32 number and D peaks at 1 / (pi alpha^2) ~ 7.8e4
// (Frostbite / Filament MIN_PERCEPTUAL_ROUGHNESS for fp32).
const WEFT_MIN_ROUGHNESS: f32 = 0.045;
// Smallest cosine used where a cosine is divided by (Filament MIN_N_DOT_V).
const WEFT_MIN_N_DOT: f32 = 1e-4;
// Largest finite fp16 value: radiance clamped to it stays finite in an
// Rgba16Float target.
const WEFT_MAX_HALF: f32 = 65504.0;
// Dielectric F0 of the metallic/roughness workflow (IOR 1.5).
const WEFT_DIELECTRIC_F0: f32 = 0.04;

// ---------------------------------------------------------------- helpers

fn weft_pow4(x: f32) -> f32 {
    let x2 = x * x;
    return x2 * x2;
}

fn weft_pow5(x: f32) -> f32 {
    let x2 = x * x;
    return x2 * x2 * x;
}

fn weft_max3(v: vec3<f32>) -> f32 {
    return max(v.x, max(v.y, v.z));
}

// Cosine clamped away from 0 for use in a denominator (back-facing -> 1e-4).
fn weft_clamp_cos(c: f32) -> f32 {
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

// Perceptual roughness clamped to [0.045, 1] for the D and V terms.
fn weft_clamp_roughness(roughness: f32) -> f32 {
    return clamp(roughness, WEFT_MIN_ROUGHNESS, 1.0);
}

// normalize(v), or `fallback` (assumed unit) when v is (nearly) zero-length.
// Branch-free (keeps callers' control flow trivially uniform); the max() keeps
// the unused arm finite too, so no Inf/NaN is ever computed.
fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2 = dot(v, v);
    return select(fallback, v * inverseSqrt(max(len2, 1e-20)), len2 > 1e-20);
}

// A unit vector perpendicular to the unit vector n, branch-free and without
// singularities (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
fn weft_any_perpendicular(n: vec3<f32>) -> vec3<f32> {
    let s = select(-1.0, 1.0, n.z >= 0.0);
    let a = -1.0 / (s + n.z);
    let b = n.x * n.y * a;
    return vec3<f32>(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
}

fn weft_luminance(c: vec3<f32>) -> f32 {
    // Rec. 709 / sRGB primaries.
    return dot(c, vec3<f32>(0.2126, 0.7152, 0.0722));
}

// IEC 61966-2-1 sRGB transfer functions (per channel, inputs clamped to >= 0).
fn weft_srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    let x = max(c, vec3<f32>(0.0));
    let lo = x / 12.92;
    let hi = pow((x + 0.055) / 1.055, vec3<f32>(2.4));
    return select(hi, lo, x <= vec3<f32>(0.04045));
}

fn weft_linear_to_srgb(c: vec3<f32>) -> vec3<f32> {
    let x = max(c, vec3<f32>(0.0));
    let lo = x * 12.92;
    let hi = 1.055 * pow(x, vec3<f32>(1.0 / 2.4)) - 0.055;
    return select(hi, lo, x <= vec3<f32>(0.0031308));
}

// ---------------------------------------------------------------- D

// GGX / Trowbridge-Reitz NDF (Walter et al. 2007; seed 004 sec. 2.1):
// D = alpha^2 / (pi ((n.h)^2 (alpha^2 - 1) + 1)^2), alpha = r^2.
// The denominator is rewritten as (1 - NoH^2) + NoH^2 alpha^2 with
// 1 - NoH^2 = (1 - NoH)(1 + NoH): 1 - NoH is exact near 1 (Sterbenz), so no
// cancellation where the lobe peaks; the sum is >= alpha^2 > 0.
fn weft_d_ggx(n_dot_h: f32, roughness: f32) -> f32 {
    let r = weft_clamp_roughness(roughness);
    let a = r * r;
    let a2 = a * a;
    let noh = saturate(n_dot_h);
    let one_minus_noh2 = (1.0 - noh) * (1.0 + noh);
    let d = one_minus_noh2 + noh * noh * a2;
    return a2 / (WEFT_PI * d * d);
}

// The same D from the vectors (Filament's form): 1 - (n.h)^2 = |n x h|^2.
// Near the peak 1 - n.h ~ alpha^2 / 2 (2e-6 at the roughness floor) is below
// the f32 rounding of n.h itself, so weft_d_ggx(n.h) over-estimates the peak
// (the lobe's albedo reached 1.02, docs/energy.md); the cross product keeps
// it. Prefer this form wherever n and h are at hand.
fn weft_d_ggx_nh(n: vec3<f32>, h: vec3<f32>, roughness: f32) -> f32 {
    let r = weft_clamp_roughness(roughness);
    let a = r * r;
    let a2 = a * a;
    let noh = saturate(dot(n, h));
    let nxh = cross(n, h);
    let d = dot(nxh, nxh) + noh * noh * a2;
    return a2 / (WEFT_PI * max(d * d, 1e-30));
}

// ---------------------------------------------------------------- F

// Schlick 1994: F = F0 + (1 - F0)(1 - v.h)^5 (seed 004 sec. 2.1).
fn weft_f_schlick(f0: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let fc = weft_pow5(1.0 - saturate(v_dot_h));
    return f0 + (vec3<f32>(1.0) - f0) * fc;
}

// Schlick with an explicit grazing reflectance f90.
fn weft_f_schlick_f90(f0: vec3<f32>, f90: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let fc = weft_pow5(1.0 - saturate(v_dot_h));
    return f0 + (f90 - f0) * fc;
}

// Roughness-aware Schlick for ambient light (Lagarde 2011, the seed's
// Indir_Fresnel_Schlick): F0 + (max(1 - r, F0) - F0)(1 - n.v)^5.
fn weft_f_schlick_roughness(f0: vec3<f32>, n_dot_v: f32, roughness: f32) -> vec3<f32> {
    let fc = weft_pow5(1.0 - saturate(n_dot_v));
    let f90 = max(vec3<f32>(1.0 - saturate(roughness)), f0);
    return f0 + (f90 - f0) * fc;
}

// Exact unpolarised Fresnel reflectance of a dielectric interface
// (Walter et al. 2007, eq. 22). cos_i = |i.m|, eta = n_transmitted / n_incident.
// g^2 < 0 is total internal reflection (F = 1). At eta = 1, cos_i = 0 the
// formula is 0/0: c is floored at 1e-4 and g + c at 1e-7.
// F = a² (1 + b²) / 2 with a = (g - c) / (g + c), b = (c (g + c) - 1) /
// (c (g - c) + 1), over one common denominator: one division instead of two
// (each a reciprocal on the GPU; both floors keep it >= 1e-14, its square
// within f32).
fn weft_f_dielectric(cos_i: f32, eta: f32) -> f32 {
    let c = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    let g2 = eta * eta - 1.0 + c * c;
    let g = sqrt(max(g2, 0.0));
    let gmc = g - c;
    let gpc = max(g + c, 1e-7);
    // c (g - c) + 1 >= 0 for c <= 1, eta >= 0; floored for eta -> 0.
    let b_den = max(c * gmc + 1.0, 1e-7);
    let b_num = c * gpc - 1.0;
    let inv = 1.0 / (gpc * b_den);
    let f = saturate(0.5 * gmc * gmc * (b_den * b_den + b_num * b_num) * (inv * inv));
    return select(f, 1.0, g2 < 0.0);
}

// Normal-incidence reflectance of a dielectric of relative IOR `ior`.
fn weft_f0_from_ior(ior: f32) -> f32 {
    let q = (ior - 1.0) / max(ior + 1.0, 1e-4);
    return q * q;
}

// ---------------------------------------------------------------- G / V

// Schlick-GGX geometry term in the seed's form (seed 004 sec. 2.1):
// k = (alpha + 1)^2 / 8, G = G1(n.v) G1(n.l), G1(c) = c / (c (1 - k) + k).
fn weft_g_schlick_ggx(n_dot_v: f32, n_dot_l: f32, roughness: f32) -> f32 {
    let r = weft_clamp_roughness(roughness);
    let a = r * r;
    let k = (a + 1.0) * (a + 1.0) * 0.125;
    let nv = saturate(n_dot_v);
    let nl = saturate(n_dot_l);
    return (nv / (nv * (1.0 - k) + k)) * (nl / (nl * (1.0 - k) + k));
}

// The same term as a visibility V = G / (4 n.v n.l), with n.v n.l cancelled
// analytically: V = 1 / (4 (n.v (1 - k) + k)(n.l (1 - k) + k)). Since
// k >= 0.125, V <= 16 and nothing is divided by a cosine.
fn weft_v_schlick_ggx(n_dot_v: f32, n_dot_l: f32, roughness: f32) -> f32 {
    let r = weft_clamp_roughness(roughness);
    let a = r * r;
    let k = (a + 1.0) * (a + 1.0) * 0.125;
    let gv = saturate(n_dot_v) * (1.0 - k) + k;
    let gl = saturate(n_dot_l) * (1.0 - k) + k;
    return 0.25 / (gv * gl);
}

// Height-correlated Smith visibility for GGX (Heitz 2014, "Understanding the
// Masking-Shadowing Function", eq. 99; Filament V_SmithGGXCorrelated):
// V = G2 / (4 n.v n.l) = 0.5 / (n.l sqrt(n.v^2 (1 - a^2) + a^2)
//                             + n.v sqrt(n.l^2 (1 - a^2) + a^2)).
// Cosines are floored at 1e-4 so the denominator is >= 2e-4 * alpha > 0.
fn weft_v_smith_ggx_correlated(n_dot_v: f32, n_dot_l: f32, roughness: f32) -> f32 {
    let r = weft_clamp_roughness(roughness);
    let a = r * r;
    let a2 = a * a;
    let nv = weft_clamp_cos(n_dot_v);
    let nl = weft_clamp_cos(n_dot_l);
    let lv = nl * sqrt(nv * nv * (1.0 - a2) + a2);
    let ll = nv * sqrt(nl * nl * (1.0 - a2) + a2);
    return 0.5 / (lv + ll);
}

// Hammon 2017 ("PBR Diffuse Lighting for GGX+Smith Microsurfaces", GDC)
// approximation of the height-correlated Smith visibility above: each
// sqrt(x^2 (1 - a^2) + a^2) replaced by x (1 - a) + a, which gives
// V = 0.5 / mix(2 n.l n.v, n.l + n.v, a) (no square root). Exact at a = 0
// and a = 1; cosines floored at 1e-4 as above, so the denominator is
// >= 2e-4 * a > 0.
fn weft_v_smith_ggx_correlated_fast(n_dot_v: f32, n_dot_l: f32, roughness: f32) -> f32 {
    let r = weft_clamp_roughness(roughness);
    let a = r * r;
    let nv = weft_clamp_cos(n_dot_v);
    let nl = weft_clamp_cos(n_dot_l);
    return 0.5 / mix(2.0 * nl * nv, nl + nv, a);
}

// The height-correlated Smith visibility without square roots, to within 6 %
// (Hammon's form above is up to 29 % low where a cosine is near alpha, i.e.
// at grazing light or view). Each root f(x) = sqrt(x^2 (1 - a^2) + a^2) gets
// one Newton step from Hammon's chord g(x) = x (1 - a) + a, which lies above
// the convex f: f ~ (g + f^2 / g) / 2, whose relative error
// (g - f)^2 / (2 g f) is <= 0.061 (worst at x = a, a -> 0) and 0 at x = 0, 1
// and at a = 1. Putting the two Newton quotients over one denominator keeps a
// single division, as Hammon's, and g^2 + f^2 = 2 (g x + a^2 (1 - x)) = 2 P:
//   V = 0.5 g_v g_l / (n.l g_l P_v + n.v g_v P_l).
// Never above the exact V (the Newton value is >= f), >= 0.94 of it (checked
// on a 2001^2 grid of cosines for r = 0.045 ... 1). Cosines floored at 1e-4 as
// above: g >= a >= 2e-3 and P = (1 - a) x (x + a) + a^2 >= a^2, so the
// denominator is >= 1e-4 a^3 >= 8e-13.
fn weft_v_smith_ggx_correlated_newton(n_dot_v: f32, n_dot_l: f32, roughness: f32) -> f32 {
    let r = weft_clamp_roughness(roughness);
    let a = r * r;
    let a2 = a * a;
    let nv = weft_clamp_cos(n_dot_v);
    let nl = weft_clamp_cos(n_dot_l);
    let gv = nv * (1.0 - a) + a;
    let gl = nl * (1.0 - a) + a;
    let pv = gv * nv + a2 * (1.0 - nv);
    let pl = gl * nl + a2 * (1.0 - nl);
    return 0.5 * gv * gl / (nl * gl * pv + nv * gv * pl);
}

// ---------------------------------------------------------------- diffuse

// Lambert: f = albedo / pi (MATERIALS.md: the seed's missing 1/pi is not used).
fn weft_diffuse_lambert(albedo: vec3<f32>) -> vec3<f32> {
    return albedo * WEFT_INV_PI;
}

// ---------------------------------------------------------------- env BRDF

// Analytic split-sum environment BRDF of seed 004 sec. 2.3 (Unity's
// BRDF1_Unity_PBS fit, linear colour space):
// lerp(F0, saturate(reflectivity + smoothness), (1 - n.v)^4) / (r^2 + 1),
// reflectivity = max3(F0), smoothness = 1 - r (r perceptual, as in the seed).
// Multiplies the prefiltered radiance. Result in [0, 1].
fn weft_env_brdf_approx(f0: vec3<f32>, n_dot_v: f32, roughness: f32) -> vec3<f32> {
    let r = saturate(roughness);
    let surface_reduction = 1.0 / (r * r + 1.0);
    let grazing = saturate(weft_max3(f0) + (1.0 - r));
    let fre = weft_pow4(1.0 - saturate(n_dot_v));
    return mix(f0, vec3<f32>(grazing), fre) * surface_reduction;
}

// Split-sum environment BRDF from the baked LUT (Karis 2013): F0 * scale + bias.
fn weft_env_brdf_from_lut(f0: vec3<f32>, scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return f0 * sb.x + vec3<f32>(sb.y);
}
