struct WeftFrame {
    view_proj: mat4x4<f32>,
    view: mat4x4<f32>,
    camera_position: vec4<f32>,
    light_direction: vec4<f32>,
    light_color: vec4<f32>,
    sh: array<vec4<f32>, 9>,
    params: vec4<f32>,
    viewport: vec4<f32>,
}

struct WeftObject {
    model: mat4x4<f32>,
    normal_matrix: mat4x4<f32>,
}

struct WeftOutlineVertex {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
}

struct WeftOutlineVaryings {
    @builtin(position) clip_position: vec4<f32>,
}

struct WeftFringeShadowVertex {
    @location(0) position: vec3<f32>,
}

struct WeftFringeShadowVaryings {
    @builtin(position) clip_position: vec4<f32>,
}

struct WeftSurface {
    v: vec3<f32>,
    n: vec3<f32>,
}

struct WeftVertexInput {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) tangent: vec4<f32>,
    @location(3) uv0_: vec2<f32>,
}

struct WeftVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) world_tangent: vec4<f32>,
    @location(3) uv0_: vec2<f32>,
}

struct WeftHair {
    sigma_a: vec3<f32>,
    eta: f32,
    v: vec4<f32>,
    s: f32,
    sin2k: vec3<f32>,
    cos2k: vec3<f32>,
}

struct WeftHairAttenuation {
    a0_: f32,
    a1_: vec3<f32>,
    a2_: vec3<f32>,
    a3_: vec3<f32>,
    gamma_t: f32,
}

struct WeftHairLobes {
    s: vec3<f32>,
    albedo: vec3<f32>,
    back: vec3<f32>,
}

struct WeftHairAngles {
    theta: vec4<f32>,
    phi: f32,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_HAIR_MIN_BETA_M: f32 = 0.05f;
const WEFT_HAIR_MIN_BETA_N: f32 = 0.05f;
const HAIR_REFERENCE_CELLS: u32 = 64u;
const HAIR_FAST_CELLS: u32 = 12u;
const HAIR_TERMINATOR: f32 = 0.25f;

@group(0) @binding(0) 
var<uniform> weft_frame: WeftFrame;
@group(2) @binding(0) 
var<uniform> weft_object: WeftObject;
@group(1) @binding(1) 
var material_sampler: sampler;
@group(1) @binding(5) 
var jitter_map: texture_2d<f32>;

fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v, v);
    return select(fallback, (v * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_any_perpendicular(n: vec3<f32>) -> vec3<f32> {
    let s_8 = select(-1f, 1f, (n.z >= 0f));
    let a_1 = (-1f / (s_8 + n.z));
    let b = ((n.x * n.y) * a_1);
    return vec3<f32>((1f + (((s_8 * n.x) * n.x) * a_1)), (s_8 * b), (-(s_8) * n.x));
}

fn weft_f_dielectric(cos_i: f32, eta: f32) -> f32 {
    let c = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1f);
    let g2_ = (((eta * eta) - 1f) + (c * c));
    let g = sqrt(max(g2_, 0f));
    let gmc = (g - c);
    let gpc = max((g + c), 0.0000001f);
    let a_2 = (gmc / gpc);
    let b_1 = (((c * gpc) - 1f) / max(((c * gmc) + 1f), 0.0000001f));
    let f = saturate((((0.5f * a_2) * a_2) * (1f + (b_1 * b_1))));
    return select(f, 1f, (g2_ < 0f));
}

fn weft_safe_normalize_k1_(v_1: vec3<f32>) -> vec3<f32> {
    let len2_1 = dot(v_1, v_1);
    return select(vec3<f32>(0f, 0f, 1f), (v_1 * inverseSqrt(max(len2_1, 0.00000000000000000001f))), (len2_1 > 0.00000000000000000001f));
}

fn weft_main_light_direction() -> vec3<f32> {
    let _e2 = weft_frame.light_direction;
    let _e4 = weft_safe_normalize_k1_(_e2.xyz);
    return _e4;
}

fn weft_main_light_radiance() -> vec3<f32> {
    let _e2 = weft_frame.light_color;
    return max(_e2.xyz, vec3(0f));
}

fn weft_sh_irradiance(n_1: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    let sh = weft_frame.sh;
    e = (sh[0].xyz * 0.282095f);
    let _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603f * n_1.y)));
    let _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603f * n_1.z)));
    let _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603f * n_1.x)));
    let _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548f * n_1.x) * n_1.y)));
    let _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548f * n_1.y) * n_1.z)));
    let _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392f * (((3f * n_1.z) * n_1.z) - 1f))));
    let _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548f * n_1.x) * n_1.z)));
    let _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274f * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    let _e91 = e;
    return max(_e91, vec3(0f));
}

fn weft_view_direction_k2_(world_position: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_frame.camera_position;
    let _e7 = weft_safe_normalize_k1_((_e4.xyz - world_position));
    return _e7;
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e2 = weft_view_direction_k2_(world_position_1);
    let _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface(_e2, _e3);
}

fn weft_tangent_frame(n_2: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    let len2_2 = dot(t_proj, t_proj);
    let ok = (len2_2 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_2);
    let t_1 = select(_e13, (t_proj * inverseSqrt(max(len2_2, 0.00000000000000000001f))), ok);
    let s_9 = select(1f, -1f, (tangent.w < 0f));
    let b_2 = (cross(n_2, t_1) * s_9);
    return mat3x3<f32>(t_1, b_2, n_2);
}

fn weft_hair_sqr(x: f32) -> f32 {
    return (x * x);
}

fn weft_hair_safe_sqrt(x_1: f32) -> f32 {
    return sqrt(max(x_1, 0f));
}

fn weft_hair_i0_(x_2: f32) -> f32 {
    var term: f32 = 1f;
    var sum: f32 = 1f;
    var i: i32 = 1i;

    let q = ((0.25f * x_2) * x_2);
    loop {
        let _e10 = i;
        if (_e10 < 16i) {
        } else {
            break;
        }
        {
            let _e13 = i;
            let k_1 = f32(_e13);
            let _e15 = term;
            term = (_e15 * (q / (k_1 * k_1)));
            let _e19 = sum;
            let _e20 = term;
            sum = (_e19 + _e20);
        }
        continuing {
            let _e22 = i;
            i = (_e22 + 1i);
        }
    }
    let _e25 = sum;
    return _e25;
}

fn weft_hair_log_i0_(x_3: f32) -> f32 {
    if (x_3 > 12f) {
        let r = (1f / x_3);
        return ((x_3 - (0.5f * log((6.2831855f * x_3)))) + log((1f + (r * (0.125f + (0.0703125f * r))))));
    }
    let _e20 = weft_hair_i0_(x_3);
    return log(_e20);
}

fn weft_hair_mp(cos_i_1: f32, cos_o: f32, sin_i: f32, sin_o: f32, v_2: f32) -> f32 {
    let a_3 = ((cos_i_1 * cos_o) / v_2);
    let b_3 = ((sin_i * sin_o) / v_2);
    if (v_2 <= 0.1f) {
        let _e11 = weft_hair_log_i0_(a_3);
        return exp(((((_e11 - b_3) - (1f / v_2)) + 0.6931472f) + log((1f / (2f * v_2)))));
    }
    let _e27 = weft_hair_i0_(a_3);
    return ((exp(-(b_3)) * _e27) / ((sinh((1f / v_2)) * 2f) * v_2));
}

fn weft_hair_longitudinal(hair: WeftHair, sin_o_1: f32, cos_o_1: f32, sin_i_1: f32, cos_i_2: f32) -> vec4<f32> {
    let sin_r = ((sin_o_1 * hair.cos2k.y) - (cos_o_1 * hair.sin2k.y));
    let cos_r = abs(((cos_o_1 * hair.cos2k.y) + (sin_o_1 * hair.sin2k.y)));
    let sin_tt = ((sin_o_1 * hair.cos2k.x) + (cos_o_1 * hair.sin2k.x));
    let cos_tt = abs(((cos_o_1 * hair.cos2k.x) - (sin_o_1 * hair.sin2k.x)));
    let sin_trt = ((sin_o_1 * hair.cos2k.z) + (cos_o_1 * hair.sin2k.z));
    let cos_trt = abs(((cos_o_1 * hair.cos2k.z) - (sin_o_1 * hair.sin2k.z)));
    let _e52 = weft_hair_mp(cos_i_2, cos_r, sin_i_1, sin_r, hair.v.x);
    let _e55 = weft_hair_mp(cos_i_2, cos_tt, sin_i_1, sin_tt, hair.v.y);
    let _e58 = weft_hair_mp(cos_i_2, cos_trt, sin_i_1, sin_trt, hair.v.z);
    let _e61 = weft_hair_mp(cos_i_2, cos_o_1, sin_i_1, sin_o_1, hair.v.w);
    return vec4<f32>(_e52, _e55, _e58, _e61);
}

fn weft_hair_logistic(x_4: f32, s: f32) -> f32 {
    let e_1 = exp((-(abs(x_4)) / s));
    let _e8 = weft_hair_sqr((1f + e_1));
    return (e_1 / (s * _e8));
}

fn weft_hair_trimmed_logistic(x_5: f32, s_1: f32) -> f32 {
    let e_2 = exp((-3.1415927f / s_1));
    let _e5 = weft_hair_logistic(x_5, s_1);
    return ((_e5 * (1f + e_2)) / (1f - e_2));
}

fn weft_hair_etap(hair_1: WeftHair, sin_o_2: f32, cos_o_2: f32) -> f32 {
    return (sqrt(((hair_1.eta * hair_1.eta) - (sin_o_2 * sin_o_2))) / max(cos_o_2, 0.0001f));
}

fn weft_hair_attenuation(hair_2: WeftHair, sin_o_3: f32, cos_o_3: f32, h: f32) -> WeftHairAttenuation {
    var a: WeftHairAttenuation;

    let sin_t = (sin_o_3 / hair_2.eta);
    let _e9 = weft_hair_safe_sqrt((1f - (sin_t * sin_t)));
    let _e10 = weft_hair_etap(hair_2, sin_o_3, cos_o_3);
    let sin_gamma_t = clamp((h / _e10), -1f, 1f);
    let _e18 = weft_hair_safe_sqrt((1f - (sin_gamma_t * sin_gamma_t)));
    let t_2 = exp((-(hair_2.sigma_a) * ((2f * _e18) / max(_e9, 0.0001f))));
    let _e31 = weft_hair_safe_sqrt((1f - (h * h)));
    let _e34 = weft_f_dielectric((cos_o_3 * _e31), hair_2.eta);
    a.a0_ = _e34;
    a.a1_ = (((1f - _e34) * (1f - _e34)) * t_2);
    let _e46 = a.a1_;
    a.a2_ = ((_e46 * t_2) * _e34);
    let _e51 = a.a2_;
    a.a3_ = (((_e51 * t_2) * _e34) / (vec3(1f) - (t_2 * _e34)));
    a.gamma_t = asin(sin_gamma_t);
    let _e60 = a;
    return _e60;
}

fn weft_hair_angles(t: vec3<f32>, o: vec3<f32>, i_1: vec3<f32>) -> WeftHairAngles {
    var out_3: WeftHairAngles;

    let sin_o_4 = clamp(dot(o, t), -1f, 1f);
    let sin_i_2 = clamp(dot(i_1, t), -1f, 1f);
    let _e16 = weft_hair_safe_sqrt((1f - (sin_o_4 * sin_o_4)));
    let _e20 = weft_hair_safe_sqrt((1f - (sin_i_2 * sin_i_2)));
    out_3.theta = vec4<f32>(sin_o_4, _e16, sin_i_2, _e20);
    let o_perp = (o - (sin_o_4 * t));
    let i_perp = (i_1 - (sin_i_2 * t));
    let len2_3 = (dot(o_perp, o_perp) * dot(i_perp, i_perp));
    let cos_phi = select(1f, (dot(o_perp, i_perp) * inverseSqrt(max(len2_3, 0.000000000000000000000000000001f))), (len2_3 > 0.000000000001f));
    out_3.phi = acos(clamp(cos_phi, -1f, 1f));
    let _e43 = out_3;
    return _e43;
}

fn weft_hair_logistic_cdf(x_6: f32, s_2: f32) -> f32 {
    return (1f / (1f + exp((-(x_6) / s_2))));
}

fn weft_hair_logistic_cdf_k3_(s_3: f32) -> f32 {
    return (1f / (1f + exp((3.1415927f / s_3))));
}

fn weft_hair_logistic_cdf_k4_(s_4: f32) -> f32 {
    return (1f / (1f + exp((-3.1415927f / s_4))));
}

fn weft_hair_trimmed_integral(lo: f32, hi: f32, s_5: f32) -> f32 {
    var sum_1: f32;

    let _e3 = weft_hair_logistic_cdf_k3_(s_5);
    let _e4 = weft_hair_logistic_cdf_k4_(s_5);
    let a_4 = clamp(lo, -3.1415927f, WEFT_PI);
    let b_4 = clamp(hi, -3.1415927f, WEFT_PI);
    let _e11 = weft_hair_logistic_cdf(b_4, s_5);
    let _e12 = weft_hair_logistic_cdf(a_4, s_5);
    sum_1 = (_e11 - _e12);
    if (hi > WEFT_PI) {
        let _e17 = sum_1;
        let _e22 = weft_hair_logistic_cdf(min((hi - 6.2831855f), WEFT_PI), s_5);
        sum_1 = (_e17 + (_e22 - _e3));
    }
    if (lo < -3.1415927f) {
        let _e27 = sum_1;
        let _e32 = weft_hair_logistic_cdf(max((lo + 6.2831855f), -3.1415927f), s_5);
        sum_1 = (_e27 + (_e4 - _e32));
    }
    let _e35 = sum_1;
    return (_e35 / (_e4 - _e3));
}

fn weft_hair_np_cell(d0_: f32, d1_: f32, s_6: f32) -> f32 {
    let mid = (0.5f * (d0_ + d1_));
    let m = (mid - (6.2831855f * round((mid / 6.2831855f))));
    let half = min((0.5f * abs((d1_ - d0_))), WEFT_PI);
    if (half < 0.0001f) {
        let _e20 = weft_hair_trimmed_logistic(m, s_6);
        return _e20;
    }
    let _e23 = weft_hair_trimmed_integral((m - half), (m + half), s_6);
    return (_e23 / (2f * half));
}

fn hair_strand(frame: mat3x3<f32>, uv0_: vec2<f32>) -> vec3<f32> {
    var ts: vec2<f32>;

    ts = vec2<f32>(0f, 1f);
    let _e6 = ts.x;
    let _e10 = ts.y;
    let _e14 = weft_safe_normalize(((frame[0] * _e6) + (frame[1] * _e10)), frame[1]);
    return _e14;
}

fn hair_hash(x_7: u32) -> f32 {
    let state = ((x_7 * 747796405u) + 2891336453u);
    let word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (f32(((word >> 22u) ^ word)) * 0.00000000023283064f);
}

fn weft_transform_uv_k5_(uv: vec2<f32>) -> vec2<f32> {
    return (uv + vec2<f32>(0f, 0f));
}

fn hair_value_noise_k6_(x_8: f32) -> f32 {
    let cell = floor(x_8);
    let f_1 = (x_8 - cell);
    let c0_ = (cell - (128f * floor((cell / 128f))));
    let c1_ = select((c0_ + 1f), 0f, ((c0_ + 1f) >= 128f));
    let _e17 = hair_hash(u32(c0_));
    let _e19 = hair_hash(u32(c1_));
    return (mix(_e17, _e19, ((f_1 * f_1) * (3f - (2f * f_1)))) - 0.5f);
}

fn hair_jitter(uv0_1: vec2<f32>) -> f32 {
    let rotated = vec2<f32>(((-0.00000004371139f * uv0_1.x) + uv0_1.y), ((-1f * uv0_1.x) + (-0.00000004371139f * uv0_1.y)));
    let _e16 = weft_transform_uv_k5_(uv0_1);
    let _e19 = textureSample(jitter_map, material_sampler, _e16);
    let j = _e19.x;
    let across = _e16.x;
    let _e25 = hair_value_noise_k6_((across * 128f));
    return (j + (0.2f * _e25));
}

fn weft_safe_normalize_k7_(v_3: vec3<f32>) -> vec3<f32> {
    let len2_4 = dot(v_3, v_3);
    return select(vec3(0f), (v_3 * inverseSqrt(max(len2_4, 0.00000000000000000001f))), (len2_4 > 0.00000000000000000001f));
}

fn weft_hair_mean_k10_(hair_3: WeftHair, angles: WeftHairAngles) -> WeftHairLobes {
    var s_7: vec3<f32> = vec3(0f);
    var albedo: vec3<f32> = vec3(0f);
    var back: vec3<f32> = vec3(0f);
    var weights: f32 = 0f;
    var g0_: f32 = -1.5707964f;
    var d0_1: vec3<f32>;
    var k: u32 = 0u;
    var out_4: WeftHairLobes;

    let th = angles.theta;
    let _e8 = weft_hair_longitudinal(hair_3, th.x, th.y, th.z, th.w);
    let _e11 = weft_hair_etap(hair_3, th.x, th.y);
    d0_1 = (vec3(angles.phi) - (((vec3<f32>(0f, 2f, 4f) * asin(clamp((-1f / _e11), -1f, 1f))) - vec3(-3.1415927f)) + vec3<f32>(0f, 3.1415927f, 6.2831855f)));
    loop {
        let _e42 = k;
        if (_e42 < 12u) {
        } else {
            break;
        }
        {
            let _e44 = g0_;
            let g1_ = (_e44 + 0.2617994f);
            let gamma_t1_ = asin(clamp((sin(g1_) / _e11), -1f, 1f));
            let d1_1 = (vec3(angles.phi) - (((vec3<f32>(0f, 2f, 4f) * gamma_t1_) - vec3((2f * g1_))) + vec3<f32>(0f, 3.1415927f, 6.2831855f)));
            let _e63 = g0_;
            let gm = (_e63 + 0.1308997f);
            let w = cos(gm);
            let _e70 = weft_hair_attenuation(hair_3, th.x, th.y, sin(gm));
            let _e75 = d0_1.x;
            let _e78 = weft_hair_np_cell(_e75, d1_1.x, hair_3.s);
            let _e84 = d0_1.y;
            let _e87 = weft_hair_np_cell(_e84, d1_1.y, hair_3.s);
            let _e95 = d0_1.z;
            let _e98 = weft_hair_np_cell(_e95, d1_1.z, hair_3.s);
            let lobes_1 = (((vec3(((_e8.x * _e70.a0_) * _e78)) + ((_e8.y * _e70.a1_) * _e87)) + ((_e8.z * _e70.a2_) * _e98)) + ((_e8.w * _e70.a3_) * 0.15915494f));
            let _e107 = s_7;
            s_7 = (_e107 + (w * lobes_1));
            let _e110 = albedo;
            albedo = (_e110 + (w * (((vec3(_e70.a0_) + _e70.a1_) + _e70.a2_) + _e70.a3_)));
            let _e121 = back;
            back = (_e121 + (w * (vec3(_e70.a0_) + _e70.a2_)));
            let _e128 = weights;
            weights = (_e128 + w);
            g0_ = g1_;
            d0_1 = d1_1;
        }
        continuing {
            let _e130 = k;
            k = (_e130 + 1u);
        }
    }
    let _e135 = s_7;
    let _e136 = weights;
    out_4.s = (_e135 / vec3(_e136));
    let _e140 = albedo;
    let _e141 = weights;
    out_4.albedo = (_e140 / vec3(_e141));
    let _e145 = back;
    let _e146 = weights;
    out_4.back = (_e145 / vec3(_e146));
    let _e149 = out_4;
    return _e149;
}

fn weft_hair_params_k14_() -> WeftHair {
    var hair_4: WeftHair;

    hair_4.sigma_a = vec3<f32>(0.19707139f, 0.44586682f, 0.7557883f);
    hair_4.eta = 1.55f;
    hair_4.v = vec4<f32>(0.03157018f, 0.007892545f, 0.12628073f, 0.12628073f);
    hair_4.s = 0.11715981f;
    hair_4.sin2k = vec3<f32>(0.034899496f, 0.06975647f, 0.1391731f);
    hair_4.cos2k = vec3<f32>(0.99939084f, 0.9975641f, 0.9902682f);
    let _e26 = hair_4;
    return _e26;
}

@vertex 
fn vs_outline(in: WeftOutlineVertex) -> WeftOutlineVaryings {
    var local: bool;
    var local_1: bool;
    var out: WeftOutlineVaryings;

    let _e3 = weft_object.model;
    let world = (_e3 * vec4<f32>(in.position, 1f));
    let nm = weft_object.normal_matrix;
    let normal = (mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz) * in.normal);
    let _e22 = weft_frame.view_proj;
    let clip = (_e22 * vec4<f32>(world.xyz, 1f));
    let _e29 = weft_frame.viewport;
    let size = _e29.xy;
    let _e33 = weft_frame.view_proj;
    let screen_normal = ((_e33 * vec4<f32>(normal, 0f)).xy * size);
    let len = length(screen_normal);
    if (len > 0.000001f) {
        let _e47 = weft_frame.viewport.x;
        local = (_e47 > 0f);
    } else {
        local = false;
    }
    let _e51 = local;
    if _e51 {
        local_1 = (clip.w > 0f);
    } else {
        local_1 = false;
    }
    let usable = local_1;
    let direction = select(vec2(0f), (screen_normal / vec2(max(len, 0.000001f))), usable);
    let distance_ = min(clip.w, 10f);
    let _e74 = weft_frame.viewport;
    let offset = ((((direction * 1.5f) * 2f) * _e74.zw) * distance_);
    out.clip_position = vec4<f32>((clip.xy + offset), clip.zw);
    let _e84 = out;
    return _e84;
}

@fragment 
fn fs_outline() -> @location(0) vec4<f32> {
    return vec4<f32>(vec3<f32>(0f, 0f, 0f), 1f);
}

@vertex 
fn vs_fringe_shadow(in_1: WeftFringeShadowVertex) -> WeftFringeShadowVaryings {
    var local_2: bool;
    var out_1: WeftFringeShadowVaryings;

    let _e3 = weft_object.model;
    let world_1 = (_e3 * vec4<f32>(in_1.position, 1f)).xyz;
    let _e11 = weft_frame.view_proj;
    let clip_1 = (_e11 * vec4<f32>(world_1, 1f));
    let _e17 = weft_frame.light_direction;
    let l = _e17.xyz;
    let l_len = length(l);
    let travel = select(vec3(0f), (-(l) / vec3(max(l_len, 0.000001f))), (l_len > 0.000001f));
    let _e32 = weft_frame.view_proj;
    let pushed = (_e32 * vec4<f32>((world_1 + (travel * 0.16f)), 1f));
    if (clip_1.w > 0.000001f) {
        local_2 = (pushed.w > 0.000001f);
    } else {
        local_2 = false;
    }
    let usable_1 = local_2;
    let offset_ndc = select(vec2(0f), ((pushed.xy / vec2(max(pushed.w, 0.000001f))) - (clip_1.xy / vec2(max(clip_1.w, 0.000001f)))), usable_1);
    out_1.clip_position = vec4<f32>((clip_1.xy + (offset_ndc * clip_1.w)), clip_1.zw);
    let _e71 = out_1;
    return _e71;
}

@fragment 
fn fs_fringe_shadow() -> @location(0) vec4<f32> {
    return vec4<f32>(vec3<f32>(0.5704816f, 0.34239164f, 0.34239164f), 1f);
}

@vertex 
fn vs_main(in_2: WeftVertexInput) -> WeftVaryings {
    var out_2: WeftVaryings;

    let model = weft_object.model;
    let model3_ = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm_1 = weft_object.normal_matrix;
    let normal3_ = mat3x3<f32>(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    let world_2 = (model * vec4<f32>(in_2.position, 1f));
    let mirror = select(1f, -1f, (determinant(model3_) < 0f));
    let bitangent_sign = (select(1f, -1f, (in_2.tangent.w < 0f)) * mirror);
    let _e43 = weft_frame.view_proj;
    out_2.clip_position = (_e43 * vec4<f32>(world_2.xyz, 1f));
    out_2.world_position = world_2.xyz;
    let _e53 = weft_safe_normalize_k7_((normal3_ * in_2.normal));
    out_2.world_normal = _e53;
    let _e58 = weft_safe_normalize_k7_((model3_ * in_2.tangent.xyz));
    out_2.world_tangent = vec4<f32>(_e58, bitangent_sign);
    out_2.uv0_ = in_2.uv0_;
    let _e62 = out_2;
    return _e62;
}

@fragment 
fn fs_main(in_3: WeftVaryings) -> @location(0) vec4<f32> {
    var color: vec3<f32>;
    var lobes: WeftHairLobes;

    let _e6 = weft_surface(in_3.world_position, in_3.world_normal);
    let v_4 = _e6.v;
    let n_3 = _e6.n;
    let _e10 = weft_tangent_frame(n_3, in_3.world_tangent);
    let _e12 = hair_strand(_e10, in_3.uv0_);
    let _e14 = hair_jitter(in_3.uv0_);
    let _e15 = weft_main_light_direction();
    let _e16 = weft_main_light_radiance();
    let _e17 = weft_sh_irradiance(n_3);
    let n_dot_l = dot(n_3, _e15);
    {
        let _e22 = weft_safe_normalize((_e12 + (_e14 * n_3)), _e12);
        let _e24 = weft_hair_params_k14_();
        let _e25 = weft_hair_angles(_e22, v_4, _e15);
        {
            let _e27 = weft_hair_mean_k10_(_e24, _e25);
            lobes = _e27;
        }
        let body = smoothstep(-0.25f, HAIR_TERMINATOR, n_dot_l);
        let _e33 = lobes.back;
        let multiple = (vec3<f32>(0.073238954f, 0.019606648f, 0.0059810597f) * (vec3(1f) - _e33));
        let _e37 = lobes.s;
        let direct = ((_e37 * body) + (multiple * (WEFT_INV_PI * saturate(n_dot_l))));
        let _e46 = lobes.back;
        color = ((direct * _e16) + (_e17 * (multiple + _e46)));
    }
    let _e50 = color;
    let radiance = clamp(_e50, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
