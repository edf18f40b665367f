// @include "lib/brdf.wgsl"
//
// weft anisotropic specular library: pure functions, no bindings (usable from
// any material and any stage). Shared by gauze, satin and silk.
//
// Conventions
//   * Tangent frame (T, B, N): orthonormal, e.g. from weft_tangent_frame()
//     (lib/forward.wgsl); columns of a mat3x3 in that order.
//   * A vector x in that frame is (T.x, B.x, N.x); weft_aniso_to_frame()
//     computes it. "t_dot_h" etc. below are such components.
//   * roughness r is perceptual, alpha = r^2 (as lib/brdf.wgsl);
//     anisotropy k in [-1, 1]; alpha_t / alpha_b (a_t, a_b) are the GGX
//     widths along T and B: k > 0 makes the surface rougher along T than
//     along B (a_t > a_b), k < 0 the opposite, k = 0 is isotropic.
//   * Every function returns finite, non-negative values for any input in
//     its documented domain, including grazing (0) and back-facing (negative)
//     cosines, k = +-1 and r = 0. Unit vectors are assumed where stated; the
//     guards keep even non-unit inputs finite.
//
// References
//   Burley 2012, "Physically-Based Shading at Disney" (anisotropic GGX, the
//     aspect mapping); Heitz 2014, "Understanding the Masking-Shadowing
//     Function in Microfacet-Based BRDFs", JCGT 3(2) (anisotropic Lambda,
//     height-correlated G2); Kulla & Conty 2017, "Revisiting Physically Based
//     Shading at Imageworks" (the linear mapping, also Filament's);
//     Filament "Physically Based Rendering in Filament", sec. Anisotropic
//     (visibility form, fp32 note, bent reflection vector for IBL).

// Smallest axis width. At k = +-1 the linear mapping gives a_b = 0 (a
// delta lobe): clamp (research/shading-models.md sec. 3; Filament uses the
// same 0.001 floor). With the 0.045 perceptual floor of lib/brdf.wgsl
// (alpha >= 2.0e-3) the linear mapping gives a_t a_b >= 3.0e-6 (at k ~ 0.5,
// where a_b reaches the floor), so 1 / (pi a_t a_b) <= 1.1e5.
const WEFT_MIN_ANISO_ALPHA: f32 = 0.001;

// ---------------------------------------------------------------- frames

// Components (T.x, B.x, N.x) of x in the frame (columns T, B, N).
fn weft_aniso_to_frame(frame: mat3x3<f32>, x: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(frame[0], x), dot(frame[1], x), dot(frame[2], x));
}

// Rotate the tangent and bitangent of an orthonormal frame (columns T, B, N)
// about N by `angle` radians (counter-clockwise seen from +N, i.e. from T
// towards B). N is unchanged; the result is orthonormal if the input is.
// Used to turn a highlight (seed 001 sec. 4.2.6: weft threads rotate the
// warp highlight) or to apply a flow/direction map.
fn weft_rotate_tangent_frame(frame: mat3x3<f32>, angle: f32) -> mat3x3<f32> {
    return weft_rotate_tangent_frame_cs(frame, cos(angle), sin(angle));
}

// The same with a precomputed (cos, sin); (c, s) need not be normalised: a
// zero pair keeps the frame (fallback), others are normalised first.
fn weft_rotate_tangent_frame_cs(frame: mat3x3<f32>, c: f32, s: f32) -> mat3x3<f32> {
    let len2 = c * c + s * s;
    let inv = inverseSqrt(max(len2, 1e-20));
    let cc = select(1.0, c * inv, len2 > 1e-20);
    let ss = select(0.0, s * inv, len2 > 1e-20);
    let t = frame[0] * cc + frame[1] * ss;
    let b = frame[1] * cc - frame[0] * ss;
    return mat3x3<f32>(t, b, frame[2]);
}

// ---------------------------------------------------------------- roughness mappings

// Kulla & Conty 2017 / Filament (also seed 001 sec. 4.2.2 and 7.2.1:
// ax = r^2 (1 + k), ay = r^2 (1 - k)). Returns (a_t, a_b). Roughness is
// clamped with weft_clamp_roughness (>= 0.045), k to [-1, 1], each width to
// >= 0.001. a_t can reach 2 at r = 1, k = 1 (allowed: D and V stay finite).
// The sum a_t + a_b = 2 r^2 is independent of k (the seed's "L1
// normalisation").
fn weft_aniso_alpha_kulla(roughness: f32, anisotropy: f32) -> vec2<f32> {
    let r = weft_clamp_roughness(roughness);
    let a = r * r;
    let k = clamp(anisotropy, -1.0, 1.0);
    return max(vec2<f32>(a * (1.0 + k), a * (1.0 - k)), vec2<f32>(WEFT_MIN_ANISO_ALPHA));
}

// Burley 2012 (Disney): aspect = sqrt(1 - 0.9 |k|), a_t = a / aspect,
// a_b = a * aspect for k >= 0; for k < 0 the two are swapped (Disney defines
// k in [0, 1] only; the swap makes the sign flip the direction as in the
// linear mapping). The product a_t a_b = a^2 is independent of k (the peak
// of the normalised D does not change), the aspect ratio is at most
// 1 / 0.1 = 10. aspect >= sqrt(0.1), so nothing is divided by zero.
fn weft_aniso_alpha_burley(roughness: f32, anisotropy: f32) -> vec2<f32> {
    let r = weft_clamp_roughness(roughness);
    let a = r * r;
    let k = clamp(anisotropy, -1.0, 1.0);
    let aspect = sqrt(1.0 - 0.9 * abs(k));
    let wide = a / aspect;
    let narrow = a * aspect;
    let ab = select(vec2<f32>(narrow, wide), vec2<f32>(wide, narrow), k >= 0.0);
    return max(ab, vec2<f32>(WEFT_MIN_ANISO_ALPHA));
}

// ---------------------------------------------------------------- D

// The GGX denominator term q = (T.h / a_t)^2 + (B.h / a_b)^2 + (N.h)^2.
// For a unit h, q >= 1 / max(a_t, a_b, 1)^2 >= 1/4 (a_t <= 2), so
// 1 / q^2 <= 16; the floor only matters for a non-unit (e.g. zero) h. Written
// as a sum of squares (Burley's form) rather than Walter's
// (N.h)^2 (a^2 - 1) + 1, so there is no cancellation near the peak.
// Computed in fp32 (the a^-4 scale would overflow fp16: Filament's note).
fn weft_aniso_ggx_q(t_dot_h: f32, b_dot_h: f32, n_dot_h: f32, alpha_t: f32, alpha_b: f32) -> f32 {
    let at = max(alpha_t, WEFT_MIN_ANISO_ALPHA);
    let ab = max(alpha_b, WEFT_MIN_ANISO_ALPHA);
    let x = t_dot_h / at;
    let y = b_dot_h / ab;
    return max(x * x + y * y + n_dot_h * n_dot_h, 1e-6);
}

// Normalised anisotropic GGX NDF (Burley 2012, eq. (13) of the Disney notes;
// Heitz 2014 eq. 85):
//   D(h) = chi+(N.h) / (pi a_t a_b q^2),   Integral D(h) (N.h) dh = 1.
// h must be unit (e.g. weft_safe_normalize(l + v, n)). Zero for h below the
// surface. Peak 1 / (pi a_t a_b): <= 1.1e5 for widths from the mappings below,
// <= 3.2e5 for any widths >= 0.001 (see WEFT_MIN_ANISO_ALPHA).
fn weft_d_ggx_aniso(t_dot_h: f32, b_dot_h: f32, n_dot_h: f32, alpha_t: f32, alpha_b: f32) -> f32 {
    let at = max(alpha_t, WEFT_MIN_ANISO_ALPHA);
    let ab = max(alpha_b, WEFT_MIN_ANISO_ALPHA);
    let q = weft_aniso_ggx_q(t_dot_h, b_dot_h, n_dot_h, at, ab);
    let d = 1.0 / (WEFT_PI * at * ab * q * q);
    return select(0.0, d, n_dot_h > 0.0);
}

// The anisotropic GGX in the form printed in seed 001 (sec. 4.2.2):
//   GGXAniso = 1 / (pi q^2)
// i.e. WITHOUT the 1 / (a_t a_b) normalisation: its peak is 1/pi for every
// roughness and anisotropy, so it does not integrate to 1 and a narrower lobe
// is not brighter; the seed compensates with its intensity sliders (0-20,
// 0-30). Bounded by 16/pi for unit h. For fast tiers that reproduce the seed.
fn weft_d_ggx_aniso_unnormalized(t_dot_h: f32, b_dot_h: f32, n_dot_h: f32, alpha_t: f32, alpha_b: f32) -> f32 {
    let q = weft_aniso_ggx_q(t_dot_h, b_dot_h, n_dot_h, alpha_t, alpha_b);
    let d = 1.0 / (WEFT_PI * q * q);
    return select(0.0, d, n_dot_h > 0.0);
}

// ---------------------------------------------------------------- G / V

// Smith Lambda for anisotropic GGX (Heitz 2014, eq. 86 with the projected
// roughness): Lambda(w) = (-1 + sqrt(1 + (a_t^2 w_t^2 + a_b^2 w_b^2) / w_n^2)) / 2,
// w = (T.w, B.w, N.w). w_n is floored at 1e-4 (grazing directions get a
// large but finite Lambda). Rewritten as (|(a_t w_t, a_b w_b, w_n)| / w_n - 1) / 2,
// which needs no square of a small ratio. Non-negative.
fn weft_lambda_ggx_aniso(w: vec3<f32>, alpha_t: f32, alpha_b: f32) -> f32 {
    let wn = weft_clamp_cos(w.z);
    let s = length(vec3<f32>(alpha_t * w.x, alpha_b * w.y, wn));
    return max(0.5 * (s / wn - 1.0), 0.0);
}

// Smith G1 = 1 / (1 + Lambda) (masking of one direction), in [0, 1].
fn weft_g1_ggx_aniso(w: vec3<f32>, alpha_t: f32, alpha_b: f32) -> f32 {
    return 1.0 / (1.0 + weft_lambda_ggx_aniso(w, alpha_t, alpha_b));
}

// Height-correlated anisotropic Smith visibility (Heitz 2014 eq. 99 with the
// anisotropic Lambda; Filament V_SmithGGXCorrelated_Anisotropic):
//   G2 = 1 / (1 + Lambda(v) + Lambda(l)),   V = G2 / (4 N.v N.l)
//      = 0.5 / (N.l |(a_t T.v, a_b B.v, N.v)| + N.v |(a_t T.l, a_b B.l, N.l)|).
// v and l are frame components (weft_aniso_to_frame). Cosines are floored at
// 1e-4, so the denominator is >= 2e-8 and V is finite; multiply by N.l
// (saturated, may be 0) outside.
fn weft_v_smith_ggx_aniso_correlated(v: vec3<f32>, l: vec3<f32>, alpha_t: f32, alpha_b: f32) -> f32 {
    let nv = weft_clamp_cos(v.z);
    let nl = weft_clamp_cos(l.z);
    let lv = nl * length(vec3<f32>(alpha_t * v.x, alpha_b * v.y, nv));
    let ll = nv * length(vec3<f32>(alpha_t * l.x, alpha_b * l.y, nl));
    return 0.5 / (lv + ll);
}

// ---------------------------------------------------------------- a full lobe

// Single-scattering anisotropic microfacet specular without Fresnel:
//   f(v, l) N.l = D(h) V(v, l) N.l,  h = normalize(v + l),
// v, l given as frame components (unit). With Fresnel <= 1 multiplied in,
// its directional albedo is <= 1 (Heitz 2014 weak white furnace: exactly 1
// for F = 1 without the shadowing loss, less with it). Returns the value
// already multiplied by the clamped N.l, so it is 0 below the horizon.
fn weft_spec_ggx_aniso(v: vec3<f32>, l: vec3<f32>, alpha_t: f32, alpha_b: f32) -> f32 {
    let h = weft_safe_normalize(v + l, vec3<f32>(0.0, 0.0, 1.0));
    let d = weft_d_ggx_aniso(h.x, h.y, h.z, alpha_t, alpha_b);
    let vis = weft_v_smith_ggx_aniso_correlated(v, l, alpha_t, alpha_b);
    return d * vis * saturate(l.z);
}

// ---------------------------------------------------------------- IBL

// Bent normal for sampling a prefiltered (isotropic) environment with an
// anisotropic lobe (Filament, "Anisotropic specular BRDF / IBL", after
// McAuley's "bent reflection vector"): the normal is bent towards the
// direction of the smoother axis seen from v, by |k| scaled down for very
// smooth surfaces. Use reflect(-v, bent) as the lookup direction. frame =
// (T, B, N), v unit. Falls back to N when the construction degenerates
// (v parallel to the anisotropy direction).
fn weft_aniso_bent_normal(frame: mat3x3<f32>, v: vec3<f32>, anisotropy: f32, roughness: f32) -> vec3<f32> {
    let k = clamp(anisotropy, -1.0, 1.0);
    let n = frame[2];
    // k >= 0: rougher along T, so the highlight stretches along T and the
    // reflection is bent in the plane containing B (Filament's choice).
    let dir = select(frame[0], frame[1], k >= 0.0);
    let aniso_t = cross(dir, v);
    let aniso_n = cross(aniso_t, dir);
    let bend = abs(k) * saturate(5.0 * saturate(roughness));
    return weft_safe_normalize(mix(n, aniso_n, bend), n);
}
