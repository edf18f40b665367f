// Thin-film interference (iridescence): the reflectance of the stack
// outside (air, IOR 1) | film (IOR n2, thickness d) | base, as linear RGB.
// Used by materials/laser; measured by tests/physics/laser_film.rs and the laser
// film report (weft-golden's film module evaluates these functions on the GPU).
//
// Two evaluations of the same physics:
//   weft_film_spectral - the reference: exact Airy summation of the
//     multiple reflections, per polarisation (s, p) with exact dielectric
//     Fresnel amplitudes, at WEFT_FILM_SAMPLES wavelengths over 380-780 nm,
//     integrated against the CIE 1931 colour matching functions (Wyman,
//     Sloan & Shirley 2013 multi-lobe fit) and taken to linear sRGB,
//     normalised so that a flat spectrum maps to that grey.
//   weft_film_fourier - the fast form: Belcour & Barla 2017's Fourier
//     evaluation of the Airy series (exact amplitudes per polarisation,
//     orders 1-4), each term's spectral integral read from a table baked
//     from the reference's CMFs (weft_film_sensitivity, below).
// Both take the base as an RGB F0 (the metallic workflow's f0) and turn it
// into a real IOR, as KHR_materials_iridescence does (a metal's complex IOR
// is not modelled). Thickness in nanometres.
//
// Guards (research notes sec. 4): the base IOR from F0 diverges at F0 = 1
// (F0 clamped to 0.9999); the film IOR is blended to the outside IOR over
// the first WEFT_FILM_FADE_NM so that d = 0 is the bare base with no edge
// (the Fourier form's truncation is not continuous there; the reference
// gets the same blend so both evaluate one model); total internal
// reflection in the film returns full reflectance; the Fourier form's
// out-of-gamut negatives are clamped to 0.

const WEFT_FILM_PI: f32 = 3.14159265358979;
// Wavelength samples of the reference (4 nm steps over 380-780 nm): the
// phase step 4 pi n d cos / lambda^2 x 4 nm stays under 0.7 rad for the
// thickest film the laser material accepts (IOR 2, 1000 nm); against 201
// samples the colours differ by at most 0.02 CIELAB Delta E 2000
// (tests/physics/laser_film.rs).
const WEFT_FILM_SAMPLES: u32 = 101u;
const WEFT_FILM_LAMBDA_MIN: f32 = 380.0;
const WEFT_FILM_LAMBDA_MAX: f32 = 780.0;
const WEFT_FILM_FADE_NM: f32 = 30.0;

// CIE XYZ (D65 white) to linear Rec. 709 / sRGB primaries.
const WEFT_XYZ_TO_REC709: mat3x3<f32> = mat3x3<f32>(
    vec3<f32>(3.2404542, -0.9692660, 0.0556434),
    vec3<f32>(-1.5371385, 1.8760108, -0.2040259),
    vec3<f32>(-0.4985314, 0.0415560, 1.0572252),
);

// IOR of a dielectric with normal-incidence reflectance f0 (against IOR 1).
fn weft_ior_from_f0(f0: vec3<f32>) -> vec3<f32> {
    let s = sqrt(clamp(f0, vec3<f32>(0.0), vec3<f32>(0.9999)));
    return (vec3<f32>(1.0) + s) / (vec3<f32>(1.0) - s);
}

// The film's IOR faded to the outside's (1) for the thinnest films.
fn weft_film_ior(film_ior: f32, thickness_nm: f32) -> f32 {
    return mix(1.0, max(film_ior, 1.0), smoothstep(0.0, WEFT_FILM_FADE_NM, thickness_nm));
}

// ---------------------------------------------------------------- reference

// One lobe of the Wyman-Sloan-Shirley fit: a Gaussian with different
// widths left and right of its centre.
fn weft_cmf_lobe(lambda: f32, mu: f32, sigma_left: f32, sigma_right: f32) -> f32 {
    let t = (lambda - mu) / select(sigma_right, sigma_left, lambda < mu);
    return exp(-0.5 * t * t);
}

// CIE 1931 2-degree colour matching functions (Wyman, Sloan, Shirley 2013,
// "Simple Analytic Approximations to the CIE XYZ Color Matching Functions",
// JCGT 2(2), multi-lobe fit; within 1 % of the tabulated CMFs' integral).
fn weft_cie_xyz(lambda: f32) -> vec3<f32> {
    let x = 1.056 * weft_cmf_lobe(lambda, 599.8, 37.9, 31.0)
        + 0.362 * weft_cmf_lobe(lambda, 442.0, 16.0, 26.7)
        - 0.065 * weft_cmf_lobe(lambda, 501.1, 20.4, 26.2);
    let y = 0.821 * weft_cmf_lobe(lambda, 568.8, 46.9, 40.5)
        + 0.286 * weft_cmf_lobe(lambda, 530.9, 16.3, 31.1);
    let z = 1.217 * weft_cmf_lobe(lambda, 437.0, 11.8, 36.0)
        + 0.681 * weft_cmf_lobe(lambda, 459.0, 26.0, 13.8);
    return vec3<f32>(x, y, z);
}

// Signed Fresnel amplitude coefficients (s, p) of the interface from IOR
// n_i to n_t at cosines cos_i, cos_t (Hecht's convention; the same formula
// for both interfaces keeps the signs consistent).
fn weft_fresnel_amplitudes(n_i: f32, n_t: f32, cos_i: f32, cos_t: f32) -> vec2<f32> {
    let rs = (n_i * cos_i - n_t * cos_t) / max(n_i * cos_i + n_t * cos_t, 1e-12);
    let rp = (n_t * cos_i - n_i * cos_t) / max(n_t * cos_i + n_i * cos_t, 1e-12);
    return vec2<f32>(rs, rp);
}

// Airy reflectance of a non-absorbing film for real amplitudes r12, r23
// (per base channel) and round-trip phase delta:
// |r12 + r23 e^{i delta}|^2 / |1 + r12 r23 e^{i delta}|^2.
fn weft_airy(r12: f32, r23: vec3<f32>, cos_delta: f32) -> vec3<f32> {
    let cross_term = 2.0 * r12 * r23 * cos_delta;
    let numerator = vec3<f32>(r12 * r12) + r23 * r23 + cross_term;
    let denominator = vec3<f32>(1.0) + r12 * r12 * r23 * r23 + cross_term;
    // denominator >= (1 - |r12 r23|)^2 > 0 for |r| < 1.
    return numerator / max(denominator, vec3<f32>(1e-12));
}

// Signed amplitudes (s, p) of the film | base interface for each base
// channel's IOR n3.
fn weft_film_base_amplitudes(n2: f32, cos2: f32, n3: vec3<f32>, sin1_sq: f32) -> array<vec3<f32>, 2> {
    let cos3 = sqrt(max(vec3<f32>(1.0) - vec3<f32>(sin1_sq) / (n3 * n3), vec3<f32>(0.0)));
    let s = (vec3<f32>(n2 * cos2) - n3 * cos3) / max(vec3<f32>(n2 * cos2) + n3 * cos3, vec3<f32>(1e-12));
    let p = (n3 * cos2 - vec3<f32>(n2) * cos3) / max(n3 * cos2 + vec3<f32>(n2) * cos3, vec3<f32>(1e-12));
    return array<vec3<f32>, 2>(s, p);
}

// The stack at one angle, shared by both evaluations: the film's IOR (faded
// in over the first nanometres), the cosine inside the film, and the signed
// amplitudes (s, p) of both interfaces (per base channel at the second).
struct WeftFilmStack {
    n2: f32,
    cos2: f32,
    r12: vec2<f32>,
    r23: array<vec3<f32>, 2>,
    total_internal_reflection: bool,
}

fn weft_film_stack(cos_theta1: f32, thickness_nm: f32, film_ior: f32, base_f0: vec3<f32>) -> WeftFilmStack {
    let cos1 = clamp(cos_theta1, 0.0, 1.0);
    let sin1_sq = 1.0 - cos1 * cos1;
    let n2 = weft_film_ior(film_ior, thickness_nm);
    let cos2_sq = 1.0 - sin1_sq / (n2 * n2);
    if cos2_sq <= 0.0 {
        return WeftFilmStack(n2, 0.0, vec2<f32>(1.0), array<vec3<f32>, 2>(vec3<f32>(1.0), vec3<f32>(1.0)), true);
    }
    let cos2 = sqrt(cos2_sq);
    return WeftFilmStack(
        n2,
        cos2,
        weft_fresnel_amplitudes(1.0, n2, cos1, cos2),
        weft_film_base_amplitudes(n2, cos2, weft_ior_from_f0(base_f0), sin1_sq),
        false,
    );
}

// The reference: spectral Airy reflectance, unpolarised light, as linear
// RGB. Each RGB channel of the result is the film over a base of that
// channel's IOR (the convention of KHR_materials_iridescence and of the fast
// form), so a zero-thickness film returns the base's own Fresnel colour.
fn weft_film_spectral(cos_theta1: f32, thickness_nm: f32, film_ior: f32, base_f0: vec3<f32>) -> vec3<f32> {
    let stack = weft_film_stack(cos_theta1, thickness_nm, film_ior, base_f0);
    if stack.total_internal_reflection {
        return vec3<f32>(1.0);
    }
    let n2 = stack.n2;
    let cos2 = stack.cos2;
    let r12 = stack.r12;
    let r23 = stack.r23;
    let d = max(thickness_nm, 0.0);
    let lambda_step = (WEFT_FILM_LAMBDA_MAX - WEFT_FILM_LAMBDA_MIN) / f32(WEFT_FILM_SAMPLES - 1u);
    // XYZ of the reflected light, one accumulator per base channel.
    var xyz_r = vec3<f32>(0.0);
    var xyz_g = vec3<f32>(0.0);
    var xyz_b = vec3<f32>(0.0);
    var white = vec3<f32>(0.0);
    for (var i = 0u; i < WEFT_FILM_SAMPLES; i++) {
        let lambda = WEFT_FILM_LAMBDA_MIN + lambda_step * f32(i);
        // Trapezoid weights: half at both ends.
        let w = select(1.0, 0.5, i == 0u || i == WEFT_FILM_SAMPLES - 1u);
        let cos_delta = cos(4.0 * WEFT_FILM_PI * n2 * d * cos2 / lambda);
        let r = 0.5 * (weft_airy(r12.x, r23[0], cos_delta) + weft_airy(r12.y, r23[1], cos_delta));
        let cmf = weft_cie_xyz(lambda) * w;
        xyz_r += r.r * cmf;
        xyz_g += r.g * cmf;
        xyz_b += r.b * cmf;
        white += cmf;
    }
    // Normalised per channel so that r = 1 at every wavelength is white and
    // a flat spectrum keeps its value; out-of-gamut negatives clamped.
    let rgb_white = WEFT_XYZ_TO_REC709 * white;
    let rgb = vec3<f32>(
        (WEFT_XYZ_TO_REC709 * xyz_r).r,
        (WEFT_XYZ_TO_REC709 * xyz_g).g,
        (WEFT_XYZ_TO_REC709 * xyz_b).b,
    );
    return clamp(rgb / rgb_white, vec3<f32>(0.0), vec3<f32>(1.0));
}

// ---------------------------------------------------------------- fast

// The Airy series' oscillating part, orders 1 to 4 (the fifth adds under
// 0.5 CIELAB units except on gold at grazing angles):
// sum over m of 2 (C_s,m + C_p,m) S(m opd), where
//   S(x) = integral of CMF(lambda) cos(2 pi x / lambda) over 380-780 nm,
// in linear Rec. 709 over its value at x = 0 (so that, as in the reference,
// a flat spectrum is grey), is the same function of the path difference for
// every film: weft bakes it from the reference's own CMFs into a table
// (`[tables]` recipe `thin_film_sensitivity`, weft_compiler::bake::film),
// and the file that includes this one provides
//   fn weft_film_sensitivity(opd_nm: f32) -> vec3<f32>
// reading it (materials/laser: its `film_sensitivity` table). Four fetches
// replace Belcour & Barla's closed-form Gaussian transforms (eight fitted
// lobes here before: 5.57x standard fast on the AMD model (navi21), now
// 3.05x).
fn weft_film_orders(opd_nm: f32, s: WeftFilmSeries, p: WeftFilmSeries) -> vec3<f32> {
    // C_m = first ratio^m per polarisation, per base channel.
    let k1 = s.first * s.ratio + p.first * p.ratio;
    let k2 = s.first * s.ratio * s.ratio + p.first * p.ratio * p.ratio;
    let k3 = s.first * s.ratio * s.ratio * s.ratio + p.first * p.ratio * p.ratio * p.ratio;
    let k4 = s.first * (s.ratio * s.ratio) * (s.ratio * s.ratio) + p.first * (p.ratio * p.ratio) * (p.ratio * p.ratio);
    let sum = k1 * weft_film_sensitivity(opd_nm)
        + k2 * weft_film_sensitivity(2.0 * opd_nm)
        + k3 * weft_film_sensitivity(3.0 * opd_nm)
        + k4 * weft_film_sensitivity(4.0 * opd_nm);
    return 2.0 * sum;
}

// The fast form: Belcour & Barla's Fourier evaluation of the Airy series.
// The amplitudes are the exact signed Fresnel ones per polarisation (s, p),
// as in their paper (the KHR sample code's Schlick amplitudes do not vanish
// for an index-matched film and are far off at grazing angles); a base
// channel's phase (0 or pi for real amplitudes) is the sign of r21 r23, so
// one spectral sensitivity per order serves every channel and both
// polarisations; orders 1 to 4 of the series (weft_film_orders).
fn weft_film_fourier(cos_theta1: f32, thickness_nm: f32, film_ior: f32, base_f0: vec3<f32>) -> vec3<f32> {
    // One layer is two equal ones: the measured function (tests/physics/
    // laser_film.rs, `cargo xtask bench film`) is the laser's fast code.
    return weft_film_fourier_layers(cos_theta1, thickness_nm, thickness_nm, film_ior, base_f0);
}

// Two film layers of thicknesses d1 and d2 over one base, averaged (the
// laser material's offset map): one stack - its angles and amplitudes - for
// both, at the mean thickness's IOR fade (the layers' own fades differ only
// where one is under WEFT_FILM_FADE_NM), and each layer's own path
// difference.
fn weft_film_fourier_layers(cos_theta1: f32, d1: f32, d2: f32, film_ior: f32, base_f0: vec3<f32>) -> vec3<f32> {
    let d_mean = 0.5 * (max(d1, 0.0) + max(d2, 0.0));
    let stack = weft_film_stack(cos_theta1, d_mean, film_ior, base_f0);
    if stack.total_internal_reflection {
        return vec3<f32>(1.0);
    }
    let s = weft_film_series(stack.r12.x, stack.r23[0]);
    let p = weft_film_series(stack.r12.y, stack.r23[1]);
    let path = 2.0 * stack.n2 * stack.cos2;
    let r1 = s.dc + p.dc + weft_film_orders(path * max(d1, 0.0), s, p);
    let r2 = s.dc + p.dc + weft_film_orders(path * max(d2, 0.0), s, p);
    return clamp(0.25 * (r1 + r2), vec3<f32>(0.0), vec3<f32>(1.0));
}

// The Fourier series of one polarisation's Airy reflectance:
// I = C0 + sum over m of 2 C_m S(m OPD), C0 = R12 + Rs,
// C_m = (Rs - T121) (sign r123)^m, Rs = T121^2 R23 / (1 - R123), with sign
// the phase of r21 r23 = -r12 r23 (0 or pi for real amplitudes).
struct WeftFilmSeries {
    dc: vec3<f32>,
    // C_m / (sign r123)^m: the order-0 factor of the oscillating terms.
    first: vec3<f32>,
    ratio: vec3<f32>,
}

fn weft_film_series(r12: f32, r23: vec3<f32>) -> WeftFilmSeries {
    let big_r12 = r12 * r12;
    let t121 = 1.0 - big_r12;
    let big_r23 = r23 * r23;
    let big_r123 = min(big_r12 * big_r23, vec3<f32>(0.9999));
    let rs = t121 * t121 * big_r23 / (vec3<f32>(1.0) - big_r123);
    // sqrt(R123) with the sign of r21 r23 = -r12 r23 is -r12 r23 itself
    // (clamped as R123 is): no square root.
    let ratio = clamp(-r12 * r23, vec3<f32>(-0.99995), vec3<f32>(0.99995));
    return WeftFilmSeries(vec3<f32>(big_r12) + rs, rs - vec3<f32>(t121), ratio);
}
