// @include "lib/brdf.wgsl"
//
// weft sheen / fabric library: pure functions, no bindings (the baked albedo
// table is read by lib/sheen_lighting.wgsl). Used by velvet; meant for shell
// fur and any other fibre-covered surface.
//
// Two families:
//   * The seed 003 fabric model (a port of a Unity BRDF1 extension): FabricD,
//     an un-normalised "inverted" distribution used in place of GGX, and the
//     fabric scatter rim. Empirical; for `fast` tiers.
//   * The "Charlie" sheen microfacet BRDF (Conty Estevez & Kulla 2017,
//     "Production Friendly Microfacet Sheen BRDF", SIGGRAPH course), with the
//     Smith visibility of the same paper as written in KHR_materials_sheen,
//     and the albedo-scaling layering (same sources). For `reference` tiers.
//
// Conventions: n_dot_x = dot(n, x); `sheen_roughness` r is the Charlie
// parameter used directly (KHR: alphaG = sheenRoughness), not squared. Every
// function returns finite, non-negative values for any input, including
// grazing (0) and back-facing (negative) cosines and r = 0.

// Smallest sheen roughness: 1/r <= 14.3 keeps sin^(1/r) and (2 + 1/r) well
// inside f32 and matches the baked table (crates/weft-compiler/src/bake/
// sheen.rs SHEEN_MIN_ROUGHNESS; one public sheen shader uses the same 0.07).
const WEFT_SHEEN_MIN_ROUGHNESS: f32 = 0.07;

// ---------------------------------------------------------------- seed 003

// FabricD (seed 003, after The Order: 1886's inverted Gaussian):
// 0.96 (1 - n.h)^2 + 0.057, used in place of GGX's D. Not normalised:
// integral of D (n.h) dh = 2 pi (0.96/12 + 0.057/2) = 0.68. In [0.057, 1.017].
fn weft_fabric_d(n_dot_h: f32) -> f32 {
    let x = 1.0 - saturate(n_dot_h);
    return 0.96 * x * x + 0.057;
}

// FabricScatterFresnelLerp (seed 003): lerp(pow4(1 - n.v), 0.4 (1 - n.v), scale).
// scale is clamped to [0, 1] (the seed's lerp would extrapolate and turn
// negative outside it); result in [0, 1].
fn weft_fabric_scatter_fresnel_lerp(n_dot_v: f32, scale: f32) -> f32 {
    let x = 1.0 - saturate(n_dot_v);
    return mix(weft_pow4(x), 0.4 * x, saturate(scale));
}

// The seed's fabric scatter term, added to the output as is (the seed does
// not multiply it by the light colour): scatter colour x wrap (n.l 0.5 + 0.5,
// n.l saturated as in Unity's BRDF1) x the Fresnel lerp above.
fn weft_fabric_scatter(scatter_color: vec3<f32>, n_dot_l: f32, n_dot_v: f32, scale: f32) -> vec3<f32> {
    let wrap = saturate(n_dot_l) * 0.5 + 0.5;
    return max(scatter_color, vec3<f32>(0.0)) * (wrap * weft_fabric_scatter_fresnel_lerp(n_dot_v, scale));
}

// ---------------------------------------------------------------- Charlie

fn weft_sheen_clamp_roughness(sheen_roughness: f32) -> f32 {
    return clamp(sheen_roughness, WEFT_SHEEN_MIN_ROUGHNESS, 1.0);
}

// Charlie distribution: D(h) = (2 + 1/r) sin(theta_h)^(1/r) / (2 pi).
// sin^2 = (1 - n.h)(1 + n.h) >= 0 (no cancellation near n.h = 1); pow of a
// value in [0, 1] with a positive exponent is in [0, 1]. Peak (2 + 1/r) / 2pi
// <= 2.6. Normalised: integral of D (n.h) dh = 1.
fn weft_d_charlie(n_dot_h: f32, sheen_roughness: f32) -> f32 {
    let r = weft_sheen_clamp_roughness(sheen_roughness);
    let inv_r = 1.0 / r;
    let noh = saturate(n_dot_h);
    let sin2 = max((1.0 - noh) * (1.0 + noh), 0.0);
    return (2.0 + inv_r) * pow(sin2, 0.5 * inv_r) * (0.5 * WEFT_INV_PI);
}

// Exponent L(x) of the fitted Charlie Lambda (Conty Estevez & Kulla 2017;
// constants as in KHR_materials_sheen): a / (1 + b x^c) + d x + e with the
// coefficients interpolated over (1 - r)^2. x in [0, 1]: x^c with c > 0 is
// 0 at x = 0 (x floored at 0 so pow never sees a negative base).
fn weft_sheen_l(x: f32, r: f32) -> f32 {
    let t = (1.0 - r) * (1.0 - r);
    let a = mix(21.5473, 25.3245, t);
    let b = mix(3.82987, 3.32435, t);
    let c = mix(0.19823, 0.16801, t);
    let d = mix(-1.97760, -1.27393, t);
    let e = mix(-4.32054, -4.85967, t);
    return a / (1.0 + b * pow(max(x, 0.0), c)) + d * x + e;
}

// Smith Lambda of the Charlie distribution. The cosine is clamped to
// [1e-4, 1]: L <= a + e ~ 20.5, so Lambda <= e^20.5 ~ 8e8 (finite in f32; far
// above the fp16 maximum, so keep this in f32: research notes sec. 2).
fn weft_sheen_lambda(cos_theta: f32, r: f32) -> f32 {
    let c = weft_clamp_cos(cos_theta);
    let lo = exp(weft_sheen_l(c, r));
    let hi = exp(2.0 * weft_sheen_l(0.5, r) - weft_sheen_l(1.0 - c, r));
    return select(hi, lo, c < 0.5);
}

// The same Lambda with one exp and two evaluations of L instead of two exps
// and three: the branch is chosen on the cosine first, then only its
// exponent is formed (L(c) below 1/2, 2 L(1/2) - L(1 - c) above), the same
// value as weft_sheen_lambda (which computes both sides and selects; a GPU
// or llvmpipe evaluates both). f32: Lambda reaches ~8e8.
fn weft_sheen_lambda_one_exp(cos_theta: f32, r: f32) -> f32 {
    let c = weft_clamp_cos(cos_theta);
    let low = c < 0.5;
    let lx = weft_sheen_l(select(1.0 - c, c, low), r);
    return exp(select(2.0 * weft_sheen_l(0.5, r) - lx, lx, low));
}

// Charlie visibility V = G2 / (4 n.v n.l), G2 = 1 / (1 + Lambda(v) + Lambda(l))
// (height-correlated form). Cosines floored at 1e-4, so the denominator is
// >= 4e-8 and V is finite: 0.25 at n.v = n.l = 1, at most ~1.5e3 at
// n.v = n.l = 1e-4, where D V n.l is still < 0.65 (numeric sweep over
// r in {0.07, 0.3, 1}). Multiply by the saturated n.l outside.
fn weft_v_charlie(n_dot_v: f32, n_dot_l: f32, sheen_roughness: f32) -> f32 {
    let r = weft_sheen_clamp_roughness(sheen_roughness);
    let nv = weft_clamp_cos(n_dot_v);
    let nl = weft_clamp_cos(n_dot_l);
    let g_inv = 1.0 + weft_sheen_lambda_one_exp(nv, r) + weft_sheen_lambda_one_exp(nl, r);
    return 1.0 / (g_inv * 4.0 * nv * nl);
}

// Neubelt & Pettineo 2013 (Ashikhmin) cloth visibility, 1 / (4 (n.l + n.v -
// n.l n.v)): cheaper, not used by velvet (the KHR spec notes it is not energy
// conserving with albedo scaling). Floored like Filament's PREVENT_DIV0.
fn weft_v_neubelt(n_dot_v: f32, n_dot_l: f32) -> f32 {
    let nv = saturate(n_dot_v);
    let nl = saturate(n_dot_l);
    return 1.0 / max(4.0 * (nl + nv - nl * nv), 1.532e-5 * 4.0);
}

// The Charlie sheen lobe times n.l (Fresnel omitted, as in KHR and Filament):
// sheen_color * D * V * n.l. Zero below the horizon.
fn weft_sheen_charlie(sheen_color: vec3<f32>, n_dot_h: f32, n_dot_v: f32, n_dot_l: f32, sheen_roughness: f32) -> vec3<f32> {
    let lobe = weft_d_charlie(n_dot_h, sheen_roughness) * weft_v_charlie(n_dot_v, n_dot_l, sheen_roughness);
    return max(sheen_color, vec3<f32>(0.0)) * (lobe * saturate(n_dot_l));
}

// Albedo scaling of the layer under the sheen (Conty Estevez & Kulla 2017;
// KHR_materials_sheen): min(1 - max3(C) E(n.v), 1 - max3(C) E(n.l)), the
// reciprocal form; e_v, e_l from the baked albedo table. In [0, 1].
fn weft_sheen_albedo_scaling(sheen_color: vec3<f32>, e_v: f32, e_l: f32) -> f32 {
    let c = saturate(weft_max3(sheen_color));
    return saturate(min(1.0 - c * saturate(e_v), 1.0 - c * saturate(e_l)));
}

// The cheap, view-only form 1 - max3(C) E(n.v), for light that has no single
// direction (ambient / environment). In [0, 1].
fn weft_sheen_albedo_scaling_view(sheen_color: vec3<f32>, e_v: f32) -> f32 {
    return saturate(1.0 - saturate(weft_max3(sheen_color)) * saturate(e_v));
}
