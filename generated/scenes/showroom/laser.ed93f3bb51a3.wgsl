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

struct WeftSurface {
    v: vec3<f32>,
    n: vec3<f32>,
}

struct WeftLightGeometry {
    l: vec3<f32>,
    h: vec3<f32>,
    n_dot_v: f32,
    n_dot_l: f32,
    n_dot_h: f32,
    v_dot_h: f32,
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

struct WeftFilmStack {
    n2_: f32,
    cos2_: f32,
    r12_: vec2<f32>,
    r23_: array<vec3<f32>, 2>,
    total_internal_reflection: bool,
}

struct WeftFilmSeries {
    dc: vec3<f32>,
    first: vec3<f32>,
    ratio: vec3<f32>,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const film_sensitivity_opd_max: f32 = 16000f;
const COLOR_MODE_HUE_RING: u32 = 0u;
const COLOR_MODE_CUSTOM: u32 = 1u;
const ANISO_COLOR_OFF: u32 = 0u;
const ANISO_COLOR_VALUE: u32 = 1u;
const ANISO_COLOR_MAP: u32 = 2u;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_FILM_PI: f32 = 3.1415927f;
const WEFT_FILM_SAMPLES: u32 = 101u;
const WEFT_FILM_LAMBDA_MIN: f32 = 380f;
const WEFT_FILM_LAMBDA_MAX: f32 = 780f;
const WEFT_FILM_FADE_NM: f32 = 30f;
const WEFT_XYZ_TO_REC709_: mat3x3<f32> = mat3x3<f32>(vec3<f32>(3.2404542f, -0.969266f, 0.0556434f), vec3<f32>(-1.5371385f, 1.8760108f, -0.2040259f), vec3<f32>(-0.4985314f, 0.041556f, 1.0572252f));

@group(0) @binding(0) 
var<uniform> weft_frame: WeftFrame;
@group(0) @binding(1) 
var weft_environment: texture_cube<f32>;
@group(0) @binding(2) 
var weft_environment_sampler: sampler;
@group(0) @binding(3) 
var weft_brdf_lut: texture_2d<f32>;
@group(0) @binding(4) 
var weft_lut_sampler: sampler;
@group(2) @binding(0) 
var<uniform> weft_object: WeftObject;
@group(1) @binding(2) 
var material_clamp_sampler: sampler;
@group(1) @binding(9) 
var film_sensitivity: texture_2d<f32>;

fn table_film_sensitivity(uv: vec2<f32>) -> vec4<f32> {
    let st = (((clamp(uv, vec2(0f), vec2(1f)) * vec2<f32>(2047f, 1f)) + vec2(0.5f)) / vec2<f32>(2048f, 2f));
    let _e13 = textureSampleLevel(film_sensitivity, material_clamp_sampler, st, 0f);
    return _e13;
}

fn weft_pow5_(x: f32) -> f32 {
    let x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

fn weft_clamp_cos(c: f32) -> f32 {
    return clamp(c, WEFT_MIN_N_DOT, 1f);
}

fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v, v);
    return select(fallback, (v * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_sh_irradiance(n_1: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    e = vec3<f32>(0.27778354f, 0.32136026f, 0.4497644f);
    e = (vec3<f32>(0.27778354f, 0.32136026f, 0.4497644f) + (vec3<f32>(0.2192843f, 0.34164187f, 0.663193f) * (0.488603f * n_1.y)));
    let _e11 = e;
    e = (_e11 + (vec3<f32>(0.1352113f, 0.12394369f, 0.10366199f) * (0.488603f * n_1.z)));
    let _e18 = e;
    e = (_e18 + (vec3<f32>(-0.14969625f, -0.13722156f, -0.11476713f) * (0.488603f * n_1.x)));
    let _e25 = e;
    e = (_e25 + (vec3<f32>(-0.064625785f, -0.059240304f, -0.049546435f) * ((1.092548f * n_1.x) * n_1.y)));
    let _e34 = e;
    e = (_e34 + (vec3<f32>(0.05837178f, 0.053507466f, 0.044751696f) * ((1.092548f * n_1.y) * n_1.z)));
    let _e43 = e;
    e = (_e43 + (vec3<f32>(0.025110306f, 0.023586905f, 0.01273896f) * (0.315392f * (((3f * n_1.z) * n_1.z) - 1f))));
    let _e56 = e;
    e = (_e56 + (vec3<f32>(-0.06322707f, -0.057958152f, -0.04847409f) * ((1.092548f * n_1.x) * n_1.z)));
    let _e65 = e;
    e = (_e65 + (vec3<f32>(0.056382716f, 0.05266991f, 0.031947177f) * (0.546274f * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    let _e78 = e;
    return max(_e78, vec3(0f));
}

fn weft_safe_normalize_k11_(v_1: vec3<f32>) -> vec3<f32> {
    let len2_1 = dot(v_1, v_1);
    return select(vec3<f32>(0f, 0f, 1f), (v_1 * inverseSqrt(max(len2_1, 0.00000000000000000001f))), (len2_1 > 0.00000000000000000001f));
}

fn weft_view_direction_k2_(world_position: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_frame.camera_position;
    let _e7 = weft_safe_normalize_k11_((_e4.xyz - world_position));
    return _e7;
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e2 = weft_view_direction_k2_(world_position_1);
    let _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface(_e2, _e3);
}

fn weft_main_light_geometry(n_2: vec3<f32>, v_2: vec3<f32>) -> WeftLightGeometry {
    let _e4 = weft_safe_normalize((vec3<f32>(-0.61984503f, 0.54986256f, 0.55986005f) + v_2), n_2);
    let _e6 = weft_clamp_cos(dot(n_2, v_2));
    return WeftLightGeometry(vec3<f32>(-0.61984503f, 0.54986256f, 0.55986005f), _e4, _e6, saturate(dot(n_2, vec3<f32>(-0.61984503f, 0.54986256f, 0.55986005f))), saturate(dot(n_2, _e4)), saturate(dot(v_2, _e4)));
}

fn weft_safe_normalize_k3_(v_3: vec3<f32>) -> vec3<f32> {
    let len2_2 = dot(v_3, v_3);
    return select(vec3(0f), (v_3 * inverseSqrt(max(len2_2, 0.00000000000000000001f))), (len2_2 > 0.00000000000000000001f));
}

fn weft_forward_vertex(in_2: WeftVertexInput) -> WeftVaryings {
    var out: WeftVaryings;

    let model = weft_object.model;
    let model3_ = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm = weft_object.normal_matrix;
    let normal3_ = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = (model * vec4<f32>(in_2.position, 1f));
    let mirror = select(1f, -1f, (determinant(model3_) < 0f));
    let bitangent_sign = (select(1f, -1f, (in_2.tangent.w < 0f)) * mirror);
    let _e43 = weft_frame.view_proj;
    out.clip_position = (_e43 * vec4<f32>(world.xyz, 1f));
    out.world_position = world.xyz;
    let _e53 = weft_safe_normalize_k3_((normal3_ * in_2.normal));
    out.world_normal = _e53;
    let _e58 = weft_safe_normalize_k3_((model3_ * in_2.tangent.xyz));
    out.world_tangent = vec4<f32>(_e58, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    let _e62 = out;
    return _e62;
}

fn weft_fresnel_amplitudes_k4_(n_t: f32, cos_i: f32, cos_t: f32) -> vec2<f32> {
    let rs = ((cos_i - (n_t * cos_t)) / max((cos_i + (n_t * cos_t)), 0.000000000001f));
    let rp = (((n_t * cos_i) - cos_t) / max(((n_t * cos_i) + cos_t), 0.000000000001f));
    return vec2<f32>(rs, rp);
}

fn weft_film_sensitivity(opd_nm: f32) -> vec3<f32> {
    let _e5 = table_film_sensitivity(vec2<f32>((opd_nm / film_sensitivity_opd_max), 0f));
    return _e5.xyz;
}

fn weft_film_orders(opd_nm_1: f32, s: WeftFilmSeries, p: WeftFilmSeries) -> vec3<f32> {
    let k1_ = ((s.first * s.ratio) + (p.first * p.ratio));
    let k2_ = (((s.first * s.ratio) * s.ratio) + ((p.first * p.ratio) * p.ratio));
    let k3_ = ((((s.first * s.ratio) * s.ratio) * s.ratio) + (((p.first * p.ratio) * p.ratio) * p.ratio));
    let k4_ = (((s.first * (s.ratio * s.ratio)) * (s.ratio * s.ratio)) + ((p.first * (p.ratio * p.ratio)) * (p.ratio * p.ratio)));
    let _e55 = weft_film_sensitivity(opd_nm_1);
    let _e59 = weft_film_sensitivity((2f * opd_nm_1));
    let _e64 = weft_film_sensitivity((3f * opd_nm_1));
    let _e69 = weft_film_sensitivity((4f * opd_nm_1));
    let sum = ((((k1_ * _e55) + (k2_ * _e59)) + (k3_ * _e64)) + (k4_ * _e69));
    return (2f * sum);
}

fn weft_film_series(r12_: f32, r23_: vec3<f32>) -> WeftFilmSeries {
    let big_r12_ = (r12_ * r12_);
    let t121_ = (1f - big_r12_);
    let big_r23_ = (r23_ * r23_);
    let big_r123_ = min((big_r12_ * big_r23_), vec3(0.9999f));
    let rs_1 = (((t121_ * t121_) * big_r23_) / (vec3(1f) - big_r123_));
    let ratio = clamp((-(r12_) * r23_), vec3(-0.99995f), vec3(0.99995f));
    return WeftFilmSeries((vec3(big_r12_) + rs_1), (rs_1 - vec3(t121_)), ratio);
}

fn weft_env_brdf_lut_k6_(n_dot_v: f32) -> vec2<f32> {
    let uv_1 = vec2<f32>(saturate(n_dot_v), 0.2f);
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_1, 0f);
    return _e8.xy;
}

fn weft_film_ior_k19_() -> f32 {
    return mix(1f, 1.8f, smoothstep(0f, WEFT_FILM_FADE_NM, 420f));
}

fn weft_v_smith_ggx_correlated_k8_(n_dot_v_1: f32, n_dot_l: f32) -> f32 {
    let _e6 = weft_clamp_cos(n_dot_v_1);
    let _e7 = weft_clamp_cos(n_dot_l);
    let lv = (_e7 * sqrt((((_e6 * _e6) * 0.9984f) + 0.0016000002f)));
    let ll = (_e6 * sqrt((((_e7 * _e7) * 0.9984f) + 0.0016000002f)));
    return (0.5f / (lv + ll));
}

fn weft_d_ggx_nh_k9_(n_3: vec3<f32>, h: vec3<f32>) -> f32 {
    let noh = saturate(dot(n_3, h));
    let nxh = cross(n_3, h);
    let d = (dot(nxh, nxh) + ((noh * noh) * 0.0016000002f));
    return (0.0016000002f / (WEFT_PI * max((d * d), 0.000000000000000000000000000001f)));
}

fn weft_specular_mip_k14_() -> f32 {
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return (0.312f * max_mip);
}

fn weft_prefiltered_radiance_k10_(dir: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_specular_mip_k14_();
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
}

fn weft_f_schlick_k15_(v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (vec3<f32>(0.8999996f, 0.8999996f, 0.8999996f) + (vec3<f32>(0.10000038f, 0.10000038f, 0.10000038f) * _e5));
}

fn weft_env_brdf_from_lut_k16_(scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return ((vec3<f32>(0.8999996f, 0.8999996f, 0.8999996f) * sb.x) + vec3(sb.y));
}

fn weft_film_base_amplitudes_k22_(n2_: f32, cos2_: f32, sin1_sq: f32) -> array<vec3<f32>, 2> {
    let cos3_ = sqrt(max((vec3(1f) - (vec3(sin1_sq) / vec3<f32>(1441.9869f, 1441.9869f, 1441.9869f))), vec3(0f)));
    let s_1 = ((vec3((n2_ * cos2_)) - (vec3<f32>(37.973503f, 37.973503f, 37.973503f) * cos3_)) / max((vec3((n2_ * cos2_)) + (vec3<f32>(37.973503f, 37.973503f, 37.973503f) * cos3_)), vec3(0.000000000001f)));
    let p_1 = (((vec3<f32>(37.973503f, 37.973503f, 37.973503f) * cos2_) - (vec3(n2_) * cos3_)) / max(((vec3<f32>(37.973503f, 37.973503f, 37.973503f) * cos2_) + (vec3(n2_) * cos3_)), vec3(0.000000000001f)));
    return array<vec3<f32>, 2>(s_1, p_1);
}

fn weft_film_stack_k20_(cos_theta1_: f32) -> WeftFilmStack {
    let cos1_ = clamp(cos_theta1_, 0f, 1f);
    let sin1_sq_1 = (1f - (cos1_ * cos1_));
    let _e10 = weft_film_ior_k19_();
    let cos2_sq = (1f - (sin1_sq_1 / (_e10 * _e10)));
    if (cos2_sq <= 0f) {
        return WeftFilmStack(_e10, 0f, vec2(1f), array<vec3<f32>, 2>(vec3(1f), vec3(1f)), true);
    }
    let cos2_1 = sqrt(cos2_sq);
    let _e23 = weft_fresnel_amplitudes_k4_(_e10, cos1_, cos2_1);
    let _e24 = weft_film_base_amplitudes_k22_(_e10, cos2_1, sin1_sq_1);
    return WeftFilmStack(_e10, cos2_1, _e23, _e24, false);
}

fn weft_film_fourier_layers_k17_(cos_theta1_1: f32) -> vec3<f32> {
    let _e6 = weft_film_stack_k20_(cos_theta1_1);
    if _e6.total_internal_reflection {
        return vec3(1f);
    }
    let _e13 = weft_film_series(_e6.r12_.x, _e6.r23_[0]);
    let _e18 = weft_film_series(_e6.r12_.y, _e6.r23_[1]);
    let path = ((2f * _e6.n2_) * _e6.cos2_);
    let _e29 = weft_film_orders((path * 420f), _e13, _e18);
    let r1_ = ((_e13.dc + _e18.dc) + _e29);
    let _e36 = weft_film_orders((path * 420f), _e13, _e18);
    let r2_ = ((_e13.dc + _e18.dc) + _e36);
    return clamp((0.25f * (r1_ + r2_)), vec3(0f), vec3(1f));
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var film_cos: f32;
    var direction_ts: vec2<f32> = vec2<f32>(1f, 0f);
    var surface_base: vec3<f32>;
    var f_light: vec3<f32>;
    var e_spec: vec3<f32>;
    var light_cos: f32;
    var film_view: vec3<f32>;
    var film_light: vec3<f32>;

    let _e11 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_4 = _e11.v;
    let geometric_n = _e11.n;
    n = geometric_n;
    let _e15 = n;
    let _e16 = weft_main_light_geometry(_e15, v_4);
    film_cos = _e16.n_dot_v;
    let _e23 = weft_env_brdf_lut_k6_(_e16.n_dot_v);
    let _e25 = weft_f_schlick_k15_(_e16.v_dot_h);
    f_light = _e25;
    let _e27 = weft_env_brdf_from_lut_k16_(_e23);
    e_spec = _e27;
    {
        light_cos = _e16.v_dot_h;
        {
            let _e36 = film_cos;
            let _e37 = weft_film_fourier_layers_k17_(_e36);
            film_view = _e37;
            let _e38 = light_cos;
            let _e39 = weft_film_fourier_layers_k17_(_e38);
            film_light = _e39;
        }
        let _e40 = f_light;
        let _e41 = film_light;
        f_light = mix(_e40, _e41, 1f);
        let _e43 = e_spec;
        let _e44 = film_view;
        e_spec = mix(_e43, (_e44 * (_e23.x + _e23.y)), 1f);
    }
    let _e51 = e_spec;
    let kd = max((vec3(1f) - _e51), vec3(0f));
    let _e57 = weft_v_smith_ggx_correlated_k8_(_e16.n_dot_v, _e16.n_dot_l);
    let _e58 = n;
    let _e60 = weft_d_ggx_nh_k9_(_e58, _e16.h);
    let _e62 = f_light;
    let specular = ((_e60 * _e57) * _e62);
    let diffuse = (kd * vec3<f32>(0f, 0f, 0f));
    let direct = (((diffuse + specular) * vec3<f32>(3f, 2.8799999f, 2.6999998f)) * _e16.n_dot_l);
    let _e72 = n;
    let _e74 = weft_prefiltered_radiance_k10_(reflect(-(v_4), _e72));
    let _e75 = e_spec;
    let indirect_specular = (_e74 * _e75);
    let _e77 = n;
    let _e78 = weft_sh_irradiance(_e77);
    let indirect_diffuse = ((_e78 * kd) * vec3<f32>(0f, 0f, 0f));
    let color = ((direct + indirect_specular) + indirect_diffuse);
    return vec4<f32>(clamp(color, vec3(0f), vec3(65504f)), 1f);
}
