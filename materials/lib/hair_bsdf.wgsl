// @include "lib/brdf.wgsl"
//
// weft hair BSDF library: pure functions, no bindings. The energy-conserving
// hair scattering model of d'Eon et al. 2011 (longitudinal M_p) with the
// azimuthal N_p, attenuation A_p and parameterisation of Chiang et al. 2016
// as pbrt-v3's HairBSDF writes it (Pharr, Jakob & Humphreys, PBR 3rd ed.,
// sec. 9.9 "Hair"): lobes p = 0 (R), 1 (TT), 2 (TRT) and a residual p = 3
// for every longer internal path.
//
// Angles (Marschner et al. 2003): θ is measured from the normal plane of the
// fibre (sin θ = w·t for the unit strand tangent t), φ around the fibre, h
// in [-1, 1] the offset across it (γ_o = asin h). Every function returns the
// cosine-weighted form S = Σ_p M_p A_p N_p (pbrt's f · |cos θ_i|), so that
// ∫ S dω_i is the fraction of light the fibre scatters (1 with σ_a = 0) and
// a directional light of radiance E gives L_o = S E.

// Longitudinal variances and azimuthal scale from the user's roughnesses,
// the scale tilts (sin, cos of 2^k α), the IOR and the absorption: what a
// pixel evaluates once and every lobe reads. All but σ_a depend on the
// material's uniforms alone (hair.wgsl computes them per vertex).
struct WeftHair {
    sigma_a: vec3<f32>,
    eta: f32,
    // v_p of lobes R, TT, TRT, residual.
    v: vec4<f32>,
    // Logistic scale s of N_p.
    s: f32,
    // sin / cos of α, 2α, 4α.
    sin2k: vec3<f32>,
    cos2k: vec3<f32>,
    // The fast tier's (weft_hair_fast): 1/v_p and M_p's normalisation
    // 1/(v_p (1 - e^(-2/v_p))) of R, TT, TRT; sin, cos of the TT blur's
    // half-step δ/2; R's floor (σ/4)²; log s_TRT²'s coefficients in a
    // (powers 0-3, then 4 in trt4); 1/η.
    inv_v: vec3<f32>,
    mp_norm: vec3<f32>,
    blur: vec2<f32>,
    r_floor: f32,
    trt: vec4<f32>,
    trt4: f32,
    inv_eta: f32,
}

// Smallest longitudinal roughness: v_TT = v / 4 stays above 2e-4, where the
// log-space M_p is still accurate in f32 (its exponents stay below ~1e4).
const WEFT_HAIR_MIN_BETA_M: f32 = 0.05;
// Smallest azimuthal roughness: the logistic scale s >= 4e-3.
const WEFT_HAIR_MIN_BETA_N: f32 = 0.05;

fn weft_hair_sqr(x: f32) -> f32 {
    return x * x;
}

fn weft_hair_safe_sqrt(x: f32) -> f32 {
    return sqrt(max(x, 0.0));
}

fn weft_hair_safe_asin(x: f32) -> f32 {
    return asin(clamp(x, -1.0, 1.0));
}

// Chiang et al. 2016, eq. 7: the longitudinal variance v = (0.726 β_m +
// 0.812 β_m² + 3.7 β_m^20)² fitted so that β_m is perceptually linear.
fn weft_hair_variance(beta_m: f32) -> f32 {
    let b = clamp(beta_m, WEFT_HAIR_MIN_BETA_M, 1.0);
    let b2 = b * b;
    let b4 = b2 * b2;
    let b20 = b4 * b4 * b4 * b4 * b4;
    return weft_hair_sqr(0.726 * b + 0.812 * b2 + 3.7 * b20);
}

// Chiang et al. 2016, eq. 8: the logistic scale s = √(π/8) (0.265 β_n +
// 1.194 β_n² + 5.372 β_n^22).
fn weft_hair_logistic_scale(beta_n: f32) -> f32 {
    let b = clamp(beta_n, WEFT_HAIR_MIN_BETA_N, 1.0);
    let b2 = b * b;
    let b4 = b2 * b2;
    let b22 = b4 * b4 * b4 * b4 * b4 * b2;
    return 0.626657069 * (0.265 * b + 1.194 * b2 + 5.372 * b22);
}

// Chiang et al. 2016, eq. 9: absorption σ_a (per unit diameter) that gives
// multiply-scattered hair of colour c (linear, each channel in (0, 1]) at
// azimuthal roughness β_n. c is floored at 1e-4 (log 0).
fn weft_hair_sigma_a_from_color(c: vec3<f32>, beta_n: f32) -> vec3<f32> {
    return weft_hair_sigma_a_scaled(c, weft_hair_sigma_a_scale(beta_n));
}

// The part of eq. 9 that depends on β_n alone: 1 / its polynomial.
fn weft_hair_sigma_a_scale(beta_n: f32) -> f32 {
    let b = clamp(beta_n, WEFT_HAIR_MIN_BETA_N, 1.0);
    let d = 5.969 - 0.215 * b + 2.532 * b * b - 10.73 * pow(b, 3.0) + 5.574 * pow(b, 4.0) + 0.245 * pow(b, 5.0);
    return 1.0 / d;
}

// σ_a = (ln c · scale)², scale = weft_hair_sigma_a_scale(β_n).
fn weft_hair_sigma_a_scaled(c: vec3<f32>, scale: f32) -> vec3<f32> {
    let l = log(clamp(c, vec3<f32>(1e-4), vec3<f32>(1.0))) * scale;
    return l * l;
}

// Per-pixel constants of the model. alpha_deg: cuticle scale tilt α in
// degrees (θ_o tilted by -2α for R, α for TT, 4α for TRT: pbrt-v3's tilts,
// weft_hair_longitudinal).
fn weft_hair_params(sigma_a: vec3<f32>, eta: f32, beta_m: f32, beta_n: f32, alpha_deg: f32) -> WeftHair {
    var hair: WeftHair;
    hair.sigma_a = max(sigma_a, vec3<f32>(0.0));
    hair.eta = max(eta, 1.0001);
    let v = weft_hair_variance(beta_m);
    hair.v = vec4<f32>(v, 0.25 * v, 4.0 * v, 4.0 * v);
    hair.s = weft_hair_logistic_scale(beta_n);
    let a = radians(alpha_deg);
    let s0 = sin(a);
    let c0 = weft_hair_safe_sqrt(1.0 - s0 * s0);
    let s1 = 2.0 * c0 * s0;
    let c1 = c0 * c0 - s0 * s0;
    let s2 = 2.0 * c1 * s1;
    let c2 = c1 * c1 - s1 * s1;
    hair.sin2k = vec3<f32>(s0, s1, s2);
    hair.cos2k = vec3<f32>(c0, c1, c2);
    // The fast tier's (weft_hair_fast, where each is explained).
    hair.inv_v = vec3<f32>(1.0, 4.0, 0.25) / v;
    // e^(-2/v_R) = (e^(-2/v_TRT))^4, e^(-2/v_TT) = (e^(-2/v_R))^4: one exp.
    let e_trt = exp(-0.5 * hair.inv_v.x);
    let e_r = weft_hair_sqr(e_trt * e_trt);
    hair.mp_norm = hair.inv_v / (vec3<f32>(1.0) - vec3<f32>(e_r, weft_hair_sqr(e_r * e_r), e_trt));
    let d = 0.45 * WEFT_PI * 0.577350 * hair.s;
    hair.blur = vec2<f32>(sin(d), cos(d));
    hair.r_floor = weft_hair_sqr(0.4534 * hair.s);
    let sh = hair.s;
    hair.trt = vec4<f32>(-9.2609 + sh * (65.993 - 107.38 * sh), 72.357 + sh * (-624.68 + 1069.8 * sh),
                         -153.75 + sh * (1704.7 - 3127.5 * sh), -67.745 + sh * (-1105.8 + 2706.6 * sh));
    hair.trt4 = 239.74 - 430.94 * sh;
    hair.inv_eta = 1.0 / hair.eta;
    return hair;
}

// ---------------------------------------------------------------- M_p

// Modified Bessel function I_0 by its power series Σ (x²/4)^i / (i!)², 16
// terms, each from the previous one (no factorial overflow): relative error
// below 1e-6 for x <= 12, the range the linear-space M_p uses.
fn weft_hair_i0(x: f32) -> f32 {
    let q = 0.25 * x * x;
    var term = 1.0;
    var sum = 1.0;
    for (var i = 1; i < 16; i += 1) {
        let k = f32(i);
        term *= q / (k * k);
        sum += term;
    }
    return sum;
}

// log I_0(x): the series below 12, above it the asymptotic expansion
// x - ½ log(2πx) + log(1 + 1/(8x) + 9/(128x²)) (relative error of I_0 below
// 5e-5 at x = 12, less beyond). pbrt-v3's LogI0 adds 1/(16x) instead of
// log(1 + 1/(8x)) (the term inside the ½): 0.5 % low at x = 12, found by
// tests/physics/hair_furnace.rs's f64 comparison.
fn weft_hair_log_i0(x: f32) -> f32 {
    if x > 12.0 {
        let r = 1.0 / x;
        return x - 0.5 * log(2.0 * WEFT_PI * x) + log(1.0 + r * (0.125 + 0.0703125 * r));
    }
    return log(weft_hair_i0(x));
}

// d'Eon et al. 2011, eq. 7: M_p = csch(1/v) / (2v) · exp(-sin θ_i sin θ_o / v)
// · I_0(cos θ_i cos θ_o / v), normalised so ∫ M_p cos θ_i dθ_i = 1. For
// v <= 0.1 sinh(1/v) and I_0 overflow f32 (1/v = 5000 at β_m = 0.05's TT):
// the log-space form of d'Eon et al. sec. 4.2, with
// log(csch(1/v)) = -1/v + log 2 + log(1 / (1 - e^(-2/v))) ~ -1/v + log 2.
fn weft_hair_mp(cos_i: f32, cos_o: f32, sin_i: f32, sin_o: f32, v: f32) -> f32 {
    let a = cos_i * cos_o / v;
    let b = sin_i * sin_o / v;
    if v <= 0.1 {
        return exp(weft_hair_log_i0(a) - b - 1.0 / v + 0.6931472 + log(1.0 / (2.0 * v)));
    }
    return exp(-b) * weft_hair_i0(a) / (sinh(1.0 / v) * 2.0 * v);
}

// The four lobes' M_p for one pair of directions, with the cuticle tilts
// applied to θ_o as pbrt-v3 does since its commit c65c588 ("Correct
// importance sampling as per d'Eon paper", 2019) and pbrt-v4: θ_o' = θ_o - 2α
// (R), θ_o + α (TT), θ_o + 4α (TRT), |cos θ_o'|; the residual is untilted.
// M_p(θ_i, θ_o') peaks near θ_i = -θ_o', so R's peak moves to
// θ_i ≈ -θ_o + 2α and TRT's to -θ_o - 4α (sin θ = ω·t, t from root to
// tip). Earlier pbrt-v3 (and weft before issue 28) tilted θ_i by +2α, -α,
// -4α instead, which mirrors every shift; since ∫ M_p cos θ_i dθ_i = 1 at
// any θ_o', tilting θ_o also keeps the white furnace at 1 for α ≠ 0.
fn weft_hair_longitudinal(hair: WeftHair, sin_o: f32, cos_o: f32, sin_i: f32, cos_i: f32) -> vec4<f32> {
    let sin_r = sin_o * hair.cos2k.y - cos_o * hair.sin2k.y;
    let cos_r = abs(cos_o * hair.cos2k.y + sin_o * hair.sin2k.y);
    let sin_tt = sin_o * hair.cos2k.x + cos_o * hair.sin2k.x;
    let cos_tt = abs(cos_o * hair.cos2k.x - sin_o * hair.sin2k.x);
    let sin_trt = sin_o * hair.cos2k.z + cos_o * hair.sin2k.z;
    let cos_trt = abs(cos_o * hair.cos2k.z - sin_o * hair.sin2k.z);
    return vec4<f32>(
        weft_hair_mp(cos_i, cos_r, sin_i, sin_r, hair.v.x),
        weft_hair_mp(cos_i, cos_tt, sin_i, sin_tt, hair.v.y),
        weft_hair_mp(cos_i, cos_trt, sin_i, sin_trt, hair.v.z),
        weft_hair_mp(cos_i, cos_o, sin_i, sin_o, hair.v.w),
    );
}

// ---------------------------------------------------------------- N_p, A_p

// The logistic distribution of scale s, symmetric in x.
fn weft_hair_logistic(x: f32, s: f32) -> f32 {
    let e = exp(-abs(x) / s);
    return e / (s * weft_hair_sqr(1.0 + e));
}

// The logistic normalised over [-π, π] (Chiang et al. 2016, eq. 11).
fn weft_hair_trimmed_logistic(x: f32, s: f32) -> f32 {
    // CDF(π) - CDF(-π) = 1 - 2 CDF(-π) = (1 - e^(-π/s)) / (1 + e^(-π/s)).
    let e = exp(-WEFT_PI / s);
    return weft_hair_logistic(x, s) * (1.0 + e) / (1.0 - e);
}

// N_p: the trimmed logistic around the exit azimuth Φ_p = 2pγ_t - 2γ_o + pπ,
// the difference wrapped into [-π, π].
fn weft_hair_np(phi: f32, p: f32, s: f32, gamma_o: f32, gamma_t: f32) -> f32 {
    let d = phi - (2.0 * p * gamma_t - 2.0 * gamma_o + p * WEFT_PI);
    let wrapped = d - 2.0 * WEFT_PI * round(d / (2.0 * WEFT_PI));
    return weft_hair_trimmed_logistic(wrapped, s);
}

// The attenuations at one offset h: A_0 = F, A_1 = (1-F)² T, A_2 = A_1 F T,
// A_3 = A_2 F T / (1 - F T) (every longer path), with F the dielectric
// Fresnel at cos θ_o cos γ_o and T = exp(-σ_a 2 cos γ_t / cos θ_t) the
// transmittance of one chord; Σ A_p = 1 with σ_a = 0. Also γ_t, from
// Bravais' modified IOR η' of the projected problem (Marschner et al. 2003).
struct WeftHairAttenuation {
    a0: f32,
    a1: vec3<f32>,
    a2: vec3<f32>,
    a3: vec3<f32>,
    gamma_t: f32,
}

fn weft_hair_etap(hair: WeftHair, sin_o: f32, cos_o: f32) -> f32 {
    return sqrt(hair.eta * hair.eta - sin_o * sin_o) / max(cos_o, 1e-4);
}

fn weft_hair_attenuation(hair: WeftHair, sin_o: f32, cos_o: f32, h: f32) -> WeftHairAttenuation {
    let sin_t = sin_o / hair.eta;
    let cos_t = weft_hair_safe_sqrt(1.0 - sin_t * sin_t);
    let sin_gamma_t = clamp(h / weft_hair_etap(hair, sin_o, cos_o), -1.0, 1.0);
    let cos_gamma_t = weft_hair_safe_sqrt(1.0 - sin_gamma_t * sin_gamma_t);
    let t = exp(-hair.sigma_a * (2.0 * cos_gamma_t / max(cos_t, 1e-4)));
    let f = weft_f_dielectric(cos_o * weft_hair_safe_sqrt(1.0 - h * h), hair.eta);
    var a: WeftHairAttenuation;
    a.a0 = f;
    a.a1 = (1.0 - f) * (1.0 - f) * t;
    a.a2 = a.a1 * t * f;
    a.a3 = a.a2 * t * f / (vec3<f32>(1.0) - t * f);
    a.gamma_t = asin(sin_gamma_t);
    return a;
}

// The lobes at one offset h: S_h = Σ_{p<3} M_p A_p N_p + M_3 A_3 / (2π),
// and the albedo Σ_p A_p (= ∫ S_h dω_i, since each M_p N_p integrates to 1).
// phi: φ_i - φ_o (signed: at one h, S is not even in φ); the offset is given
// as γ_o = asin h, so a caller that has the angle need not pass it through
// asin (Vulkan allows asin and atan 4096 ulp: ~5e-4 rad near 1.1).
struct WeftHairLobes {
    s: vec3<f32>,
    albedo: vec3<f32>,
    // The share scattered back towards the viewer's side by R and TRT,
    // ⟨A_0 + A_2⟩ (the part of the albedo a front-lit fibre shows).
    back: vec3<f32>,
}

fn weft_hair_at_gamma(hair: WeftHair, sin_o: f32, cos_o: f32, phi: f32, gamma_o: f32, mp: vec4<f32>) -> WeftHairLobes {
    let h = sin(gamma_o);
    let a = weft_hair_attenuation(hair, sin_o, cos_o, h);
    var out: WeftHairLobes;
    out.s = mp.x * a.a0 * weft_hair_np(phi, 0.0, hair.s, gamma_o, a.gamma_t)
        + mp.y * a.a1 * weft_hair_np(phi, 1.0, hair.s, gamma_o, a.gamma_t)
        + mp.z * a.a2 * weft_hair_np(phi, 2.0, hair.s, gamma_o, a.gamma_t)
        + mp.w * a.a3 * (0.5 * WEFT_INV_PI);
    out.albedo = a.a0 + a.a1 + a.a2 + vec3<f32>(a.a3);
    out.back = a.a0 + a.a2;
    return out;
}

// The fibre's angles from unit world vectors: the strand tangent t, the
// direction towards the viewer (o) and towards the light (i).
// x: sin θ_o, y: cos θ_o, z: sin θ_i, w: cos θ_i; phi: φ_i - φ_o in [0, π]
// (the h-averaged S is even in φ). A direction along the fibre has no
// azimuth: φ = 0 is used (S does not depend on it there).
struct WeftHairAngles {
    theta: vec4<f32>,
    phi: f32,
}

fn weft_hair_angles(t: vec3<f32>, o: vec3<f32>, i: vec3<f32>) -> WeftHairAngles {
    var out: WeftHairAngles;
    let sin_o = clamp(dot(o, t), -1.0, 1.0);
    let sin_i = clamp(dot(i, t), -1.0, 1.0);
    out.theta = vec4<f32>(sin_o, weft_hair_safe_sqrt(1.0 - sin_o * sin_o), sin_i, weft_hair_safe_sqrt(1.0 - sin_i * sin_i));
    let o_perp = o - sin_o * t;
    let i_perp = i - sin_i * t;
    let len2 = dot(o_perp, o_perp) * dot(i_perp, i_perp);
    let cos_phi = select(1.0, dot(o_perp, i_perp) * inverseSqrt(max(len2, 1e-30)), len2 > 1e-12);
    out.phi = acos(clamp(cos_phi, -1.0, 1.0));
    return out;
}

// The logistic's CDF, and the trimmed logistic integrated over [lo, hi]
// (0 <= hi - lo <= 2π, lo in [-2π, π]) as a function on the circle: the
// parts beyond ±π wrap to the other end.
fn weft_hair_logistic_cdf(x: f32, s: f32) -> f32 {
    return 1.0 / (1.0 + exp(-x / s));
}

fn weft_hair_trimmed_integral(lo: f32, hi: f32, s: f32) -> f32 {
    let c_lo = weft_hair_logistic_cdf(-WEFT_PI, s);
    let c_hi = weft_hair_logistic_cdf(WEFT_PI, s);
    let a = clamp(lo, -WEFT_PI, WEFT_PI);
    let b = clamp(hi, -WEFT_PI, WEFT_PI);
    var sum = weft_hair_logistic_cdf(b, s) - weft_hair_logistic_cdf(a, s);
    if hi > WEFT_PI {
        sum += weft_hair_logistic_cdf(min(hi - 2.0 * WEFT_PI, WEFT_PI), s) - c_lo;
    }
    if lo < -WEFT_PI {
        sum += c_hi - weft_hair_logistic_cdf(max(lo + 2.0 * WEFT_PI, -WEFT_PI), s);
    }
    return sum / (c_hi - c_lo);
}

// The mean of N_p over a cell of γ_o whose ends give φ - Φ_p = d0 and d1:
// Φ_p is taken linear across the cell (exact for R, Φ_0 = -2γ_o), so the
// logistic is integrated exactly instead of sampled at the midpoint, which
// would alias once a cell moves Φ_p by more than the lobe's width.
fn weft_hair_np_cell(d0: f32, d1: f32, s: f32) -> f32 {
    let mid = 0.5 * (d0 + d1);
    let m = mid - 2.0 * WEFT_PI * round(mid / (2.0 * WEFT_PI));
    let half = min(0.5 * abs(d1 - d0), WEFT_PI);
    if half < 1e-4 {
        return weft_hair_trimmed_logistic(m, s);
    }
    return weft_hair_trimmed_integral(m - half, m + half, s) / (2.0 * half);
}

// The far-field fibre seen across its width: S and the albedo averaged over
// h uniform in [-1, 1] (a pixel covers many fibres at every offset), written
// over γ_o = asin h (dh = cos γ_o dγ_o) and split into `count` equal cells.
// Per cell: the smooth factors (A_p, cos γ_o) at its midpoint, N_p
// integrated over the cell (weft_hair_np_cell); weights cos γ_o normalised
// by their sum, so a constant in h is kept exactly (the albedo is 1 with
// σ_a = 0 at any count).
fn weft_hair_mean(hair: WeftHair, angles: WeftHairAngles, count: u32) -> WeftHairLobes {
    let th = angles.theta;
    let mp = weft_hair_longitudinal(hair, th.x, th.y, th.z, th.w);
    let etap = weft_hair_etap(hair, th.x, th.y);
    let cells = max(count, 1u);
    let step = WEFT_PI / f32(cells);
    var s = vec3<f32>(0.0);
    var albedo = vec3<f32>(0.0);
    var back = vec3<f32>(0.0);
    var weights = 0.0;
    // φ - Φ_p at the cell's lower end, carried from the previous cell.
    var g0 = -0.5 * WEFT_PI;
    var d0 = angles.phi - (2.0 * vec3<f32>(0.0, 1.0, 2.0) * asin(clamp(sin(g0) / etap, -1.0, 1.0)) - 2.0 * g0 + vec3<f32>(0.0, 1.0, 2.0) * WEFT_PI);
    for (var k = 0u; k < cells; k += 1u) {
        let g1 = g0 + step;
        let gamma_t1 = asin(clamp(sin(g1) / etap, -1.0, 1.0));
        let d1 = angles.phi - (2.0 * vec3<f32>(0.0, 1.0, 2.0) * gamma_t1 - 2.0 * g1 + vec3<f32>(0.0, 1.0, 2.0) * WEFT_PI);
        let gm = g0 + 0.5 * step;
        let w = cos(gm);
        let a = weft_hair_attenuation(hair, th.x, th.y, sin(gm));
        let lobes = mp.x * a.a0 * weft_hair_np_cell(d0.x, d1.x, hair.s)
            + mp.y * a.a1 * weft_hair_np_cell(d0.y, d1.y, hair.s)
            + mp.z * a.a2 * weft_hair_np_cell(d0.z, d1.z, hair.s)
            + mp.w * a.a3 * (0.5 * WEFT_INV_PI);
        s += w * lobes;
        albedo += w * (a.a0 + a.a1 + a.a2 + a.a3);
        back += w * (a.a0 + a.a2);
        weights += w;
        g0 = g1;
        d0 = d1;
    }
    var out: WeftHairLobes;
    out.s = s / weights;
    out.albedo = albedo / weights;
    out.back = back / weights;
    return out;
}

// ---------------------------------------------------------------- fast

// The fast tier: the same model (S = Σ_p M_p ⟨A_p N_p⟩_h + M_3 ⟨A_3⟩ / 2π,
// averaged over the fibre's width h) with the average over h in closed
// form instead of weft_hair_mean's cells, after Karis 2016 ("Physically
// Based Hair Shading in Unreal", SIGGRAPH course): each lobe at the offset h
// where its exit azimuth Φ_p(h) meets φ, weighted by the smooth-limit
// density |dh/dΦ_p| / 2 (Marschner et al. 2003), then spread by the
// logistic of scale s. Unlike Karis's fits (one η, no β_n), every term
// follows η, β_m, β_n, α and σ_a. Measured against the reference in
// materials/hair/README.md ("fast").

// The TT offset for one azimuth, given sin(φ/2) and a = 1/η'. Φ_1 = 2γ_t -
// 2γ_o + π = φ with sin γ_t = a sin γ_o solves in closed form: tan γ_o =
// cos(φ/2) / (sin(φ/2) - a). With ρ² = 1 - 2a sin(φ/2) + a²: cos γ_o =
// (sin(φ/2) - a)/ρ, cos γ_t = (1 - a sin(φ/2))/ρ, and the density
// |dh/dΦ_1| / 2 = ½ / |2a/cos γ_t - 2/cos γ_o| = cos γ_o cos γ_t / (4ρ)
// (cos γ_t - a cos γ_o = ρ). Returns (cos γ_o, cos γ_t, density); no TT
// path reaches sin(φ/2) <= a (|φ| below 2 asin(a)): density 0.
fn weft_hair_fast_tt_density(sin_half: f32, a: f32) -> vec3<f32> {
    let rho2 = 1.0 - 2.0 * a * sin_half + a * a;
    let inv_rho = inverseSqrt(max(rho2, 1e-8));
    let cos_go = max(sin_half - a, 0.0) * inv_rho;
    let cos_gt = (1.0 - a * sin_half) * inv_rho;
    return vec3<f32>(cos_go, cos_gt, 0.25 * cos_go * cos_gt * inv_rho);
}

// ⟨A_1 N_1⟩_h: the density at φ + δ and φ - δ (given sin((φ ± δ)/2)),
// averaged: the logistic's blur, which takes 5-18 % off the smooth limit's
// peak at φ = π and fills the edge at 2 asin(a); A_1 = (1 - F)² T at the
// first point only (φ + δ folds back about π, so it lies inside the lobe
// whenever the other does): F at cos θ_o cos γ_o, T = exp(-σ_a 2 cos γ_t /
// cos θ_t) (chord = 2 / cos θ_t), as weft_hair_attenuation.
fn weft_hair_fast_tt(sin_plus: f32, sin_minus: f32, a: f32, cos_o: f32, eta: f32, sigma_a: vec3<f32>, chord: f32) -> vec3<f32> {
    let p = weft_hair_fast_tt_density(sin_plus, a);
    let m = weft_hair_fast_tt_density(sin_minus, a);
    let f_tt = weft_f_dielectric(cos_o * p.x, eta);
    return exp(-sigma_a * (chord * p.y)) * (weft_hair_sqr(1.0 - f_tt) * 0.5 * (p.z + m.z));
}

// The fast tier's lobes for the strand tangent t and the unit directions
// towards the viewer (o) and the light (i); the fields mean what
// weft_hair_mean's do (s: the cosine-weighted S; back: ⟨A_0 + A_2⟩).
fn weft_hair_fast(hair: WeftHair, t: vec3<f32>, o: vec3<f32>, i: vec3<f32>) -> WeftHairLobes {
    // Angles as weft_hair_angles, φ through its cosine and half angles
    // (no acos on this path but N_TRT's).
    let sin_o = clamp(dot(o, t), -1.0, 1.0);
    let sin_i = clamp(dot(i, t), -1.0, 1.0);
    let cos_o = weft_hair_safe_sqrt(1.0 - sin_o * sin_o);
    let cos_i = weft_hair_safe_sqrt(1.0 - sin_i * sin_i);
    let o_perp = o - sin_o * t;
    let i_perp = i - sin_i * t;
    let len2 = dot(o_perp, o_perp) * dot(i_perp, i_perp);
    let cos_phi = clamp(select(1.0, dot(o_perp, i_perp) * inverseSqrt(max(len2, 1e-30)), len2 > 1e-12), -1.0, 1.0);
    let cos_half = sqrt(0.5 + 0.5 * cos_phi);
    let sin_half = sqrt(0.5 - 0.5 * cos_phi);

    // M_p of R, TT, TRT (the residual takes TRT's: the same variance 4v,
    // tilted by 4α instead of 0; it is 1-4 % of S). d'Eon et al. 2011 eq. 7
    // rewritten without overflow: csch(1/v)/(2v) e^(-b) I_0(x) =
    // exp((cos(θ_i + θ_o') - 1)/v) · e^(-x) I_0(x) / (v (1 - e^(-2/v))),
    // x = cos θ_i cos θ_o' / v, b = sin θ_i sin θ_o' / v - exact but for
    // e^(-x) I_0(x) ≈ (1 + u(1-u)(0.1819 - 0.4018u + 3.1851u²)) / √(1 + 2πx),
    // u = 1/(1 + 0.7x): relative error < 0.3 % for every x >= 0 (least
    // squares against numpy's i0; the series / asymptotic split of the
    // reference, weft_hair_log_i0, is not needed). Tilts of θ_o as
    // weft_hair_longitudinal (issue 28): R -2α, TT +α, TRT +4α.
    let so = vec3<f32>(
        sin_o * hair.cos2k.y - cos_o * hair.sin2k.y,
        sin_o * hair.cos2k.x + cos_o * hair.sin2k.x,
        sin_o * hair.cos2k.z + cos_o * hair.sin2k.z);
    let co = abs(vec3<f32>(
        cos_o * hair.cos2k.y + sin_o * hair.sin2k.y,
        cos_o * hair.cos2k.x - sin_o * hair.sin2k.x,
        cos_o * hair.cos2k.z - sin_o * hair.sin2k.z));
    // 1/v_p and the normalisation 1/(v_p (1 - e^(-2/v_p))): hair.inv_v,
    // hair.mp_norm (weft_hair_params).
    let inv_v = hair.inv_v;
    let norm = hair.mp_norm;
    let x = cos_i * co * inv_v;
    let u = 1.0 / (1.0 + 0.7 * x);
    let bessel = (1.0 + u * (1.0 - u) * (0.181903 + u * (-0.401835 + u * 3.1851))) * inverseSqrt(1.0 + 2.0 * WEFT_PI * x);
    let mp = exp(min((cos_i * co - sin_i * so - 1.0) * inv_v, vec3<f32>(0.0))) * bessel * norm;

    // chord = 2 / cos θ_t (as weft_hair_attenuation), cos θ_t floored at 1e-4.
    let sin_t = sin_o * hair.inv_eta;
    let chord = 2.0 * inverseSqrt(max(1.0 - sin_t * sin_t, 1e-8));
    // a = 1/η' = cos θ_o / √(η² - sin² θ_o) (Bravais).
    let a = cos_o * inverseSqrt(max(hair.eta * hair.eta - sin_o * sin_o, 1e-8));
    // The logistic's standard deviation is πs/√3; the blur's half-step in
    // φ/2 is δ/2 = 0.45 πs/√3 (0.45 fitted: the two-point mean of TT's
    // smooth limit within 2-4 % of the 3000-offset average at β_n 0.3-0.4):
    // (sin, cos) of it in hair.blur.
    let sd = hair.blur.x;
    let cd = hair.blur.y;

    // R: Φ_0 = -2γ_o meets φ at γ_o = -φ/2 only, so ⟨N_R⟩_h = |dh/dφ| / 2 =
    // cos(φ/2) / 4 and A_R = F(cos θ_o cos(φ/2)) (Karis 2016's N_R and A_R).
    // The logistic rounds the kink at φ = π where cos(φ/2) -> 0 and F -> 1:
    // cos(φ/2) -> √(cos²(φ/2) + (σ/4)²), σ = πs/√3 (σ/4 = 0.4534 s, fitted:
    // the value at φ = π within 7 % of the reference's at β_n 0.3-0.4).
    let c_r = sqrt(min(0.5 + 0.5 * cos_phi + hair.r_floor, 1.0));
    let r = 0.25 * c_r * weft_f_dielectric(cos_o * c_r, hair.eta);

    // TT: sin((φ ± δ)/2) by the angle sum.
    let tt_lobe = weft_hair_fast_tt(sin_half * cd + cos_half * sd, sin_half * cd - cos_half * sd, a, cos_o, hair.eta, hair.sigma_a, chord);

    // ⟨A_0⟩ (F) and ⟨A_2⟩ = ⟨(1 - F)² F T²⟩ each at one offset, h_F = 0.624 +
    // 0.190 cos θ_o and h_2 = 0.482 + 0.278 cos θ_o (fitted to 3000-offset
    // averages over η 1.4-1.7, σ_a 0-1, θ_o 0-76°: ⟨A_0⟩ within 2.8 %,
    // ⟨A_0 + A_2⟩ within 3 %, ⟨A_2⟩ -8 %/+11 %; Karis takes h = √3/2 for
    // TRT); the residual A_3 = A_2 F T / (1 - F T) from them (a few % of S).
    let h_f = 0.6243 + 0.1898 * cos_o;
    let mean_f = weft_f_dielectric(cos_o * weft_hair_safe_sqrt(1.0 - h_f * h_f), hair.eta);
    let h2 = 0.4824 + 0.2778 * cos_o;
    let f2 = weft_f_dielectric(cos_o * weft_hair_safe_sqrt(1.0 - h2 * h2), hair.eta);
    let t2 = exp(-hair.sigma_a * (chord * weft_hair_safe_sqrt(1.0 - h2 * h2 * a * a)));
    let a2 = weft_hair_sqr(1.0 - f2) * f2 * t2 * t2;
    let ft = mean_f * t2;
    let a3 = a2 * ft / (vec3<f32>(1.0) - ft);

    // N_TRT: Φ_2 = 4γ_t - 2γ_o + 2π has caustics near ±20° (η' 1.55) that
    // merge at η' ~ 1.7 and give way to a broad lobe beyond; with the
    // logistic on top, a trimmed logistic about φ = 0 whose scale s_TRT has
    // the reference's peak: log s_TRT² fitted over a = 1/η' and s (least
    // squares, 192 cases: η 1.45-1.65, θ_o 0-76°, β_n 0.2-0.6; s_TRT within
    // 8.5 % at the grid's β_n; Karis's fixed exp(17 cos φ - 16.78) is this
    // lobe for one η and β_n). Never narrower than the logistic itself. The
    // fit, -9.2609 + 72.357a - 153.75a² - 67.745a³ + 239.74a⁴ + s (65.993 -
    // 624.68a + 1704.7a² - 1105.8a³ - 430.94a⁴) + s² (-107.38 + 1069.8a -
    // 3127.5a² + 2706.6a³), as a polynomial in a (hair.trt, hair.trt4).
    let s2_fit = hair.trt.x + a * (hair.trt.y + a * (hair.trt.z + a * (hair.trt.w + a * hair.trt4)));
    let s_trt = sqrt(max(exp(clamp(s2_fit, -9.0, 2.5)), hair.s * hair.s));
    let n_trt = weft_hair_trimmed_logistic(acos(cos_phi), s_trt);

    var out: WeftHairLobes;
    out.s = mp.x * r + mp.y * tt_lobe + mp.z * (a2 * n_trt + a3 * (0.5 * WEFT_INV_PI));
    out.back = mean_f + a2;
    // Σ ⟨A_p⟩ with ⟨A_1⟩ at h_2 (not used by hair.wgsl).
    out.albedo = mean_f + weft_hair_sqr(1.0 - f2) * t2 + a2 + a3;
    return out;
}
