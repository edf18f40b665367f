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

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const SPHERE_MAP_OFF: u32 = 0u;
const SPHERE_MAP_ADD: u32 = 1u;
const SPHERE_MAP_MULTIPLY: u32 = 2u;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const TIER_LOW: u32 = 3u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_MIN_ROUGHNESS_HALF: f32 = 0.089f;
const WEFT_MIN_N_DOT_HALF: f32 = 0.001f;
const WEFT_MIN_ALPHA_HALF: f32 = 0.007921f;

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

fn weft_safe_normalize_k13_(v_1: vec3<f32>) -> vec3<f32> {
    let len2_1 = dot(v_1, v_1);
    return select(vec3<f32>(0f, 0f, 1f), (v_1 * inverseSqrt(max(len2_1, 0.00000000000000000001f))), (len2_1 > 0.00000000000000000001f));
}

fn weft_view_direction_k2_(world_position: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_frame.camera_position;
    let _e7 = weft_safe_normalize_k13_((_e4.xyz - world_position));
    return _e7;
}

fn weft_surface_two_sided(world_position_1: vec3<f32>, world_normal: vec3<f32>, front_facing_1: bool) -> WeftSurface {
    let _e3 = weft_view_direction_k2_(world_position_1);
    let facing = select(-(world_normal), world_normal, front_facing_1);
    let _e6 = weft_safe_normalize(facing, _e3);
    return WeftSurface(_e3, _e6);
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

fn standard_sphere_map(color_in: vec3<f32>, n_3: vec3<f32>, world_position_2: vec3<f32>) -> vec3<f32> {
    var color: vec3<f32>;

    color = color_in;
    let _e4 = color;
    return _e4;
}

fn weft_v_smith_ggx_correlated_newton_k5_(n_dot_v: f32, n_dot_l: f32) -> f32 {
    let _e6 = weft_clamp_cos(n_dot_v);
    let _e7 = weft_clamp_cos(n_dot_l);
    let gv = ((_e6 * 0.7975f) + 0.20249999f);
    let gl = ((_e7 * 0.7975f) + 0.20249999f);
    let pv = ((gv * _e6) + (0.041006245f * (1f - _e6)));
    let pl = ((gl * _e7) + (0.041006245f * (1f - _e7)));
    return (((0.5f * gv) * gl) / (((_e7 * gl) * pv) + ((_e6 * gv) * pl)));
}

fn weft_env_brdf_lut_k6_(n_dot_v_1: f32) -> vec2<f32> {
    let uv = vec2<f32>(saturate(n_dot_v_1), 0.45f);
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv, 0f);
    return _e8.xy;
}

fn weft_env_brdf_from_lut_k7_(scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return ((vec3<f32>(0.04f, 0.04f, 0.04f) * sb.x) + vec3(sb.y));
}

fn weft_f_schlick_k8_(v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (vec3<f32>(0.04f, 0.04f, 0.04f) + (vec3<f32>(0.96f, 0.96f, 0.96f) * _e5));
}

fn weft_d_ggx_k9_(n_dot_h: f32) -> f32 {
    let noh = saturate(n_dot_h);
    let one_minus_noh2_ = ((1f - noh) * (1f + noh));
    let d_1 = (one_minus_noh2_ + ((noh * noh) * 0.041006245f));
    return (0.041006245f / ((WEFT_PI * d_1) * d_1));
}

fn weft_specular_mip_k15_() -> f32 {
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return (0.62325f * max_mip);
}

fn weft_prefiltered_radiance_k10_(dir: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_specular_mip_k15_();
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
}

fn standard_alpha_test_k12_() {
    {
        return;
    }
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var visibility: f32;
    var env_brdf: vec3<f32>;
    var ambient_kd: vec3<f32>;
    var direct_kd: vec3<f32>;
    var specular: vec3<f32> = vec3(0f);
    var indirect_specular: vec3<f32> = vec3(0f);
    var d: f32;

    let _e13 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    let v_4 = _e13.v;
    n = _e13.n;
    let _e17 = n;
    let _e18 = weft_main_light_geometry(_e17, v_4);
    {
        {
            let _e27 = weft_v_smith_ggx_correlated_newton_k5_(_e18.n_dot_v, _e18.n_dot_l);
            visibility = _e27;
            let _e29 = weft_env_brdf_lut_k6_(_e18.n_dot_v);
            let _e30 = weft_env_brdf_from_lut_k7_(_e29);
            env_brdf = _e30;
            let _e32 = env_brdf;
            ambient_kd = max((vec3(1f) - _e32), vec3(0f));
            let _e36 = ambient_kd;
            direct_kd = _e36;
        }
    }
    {
        let _e42 = weft_f_schlick_k8_(_e18.v_dot_h);
        {
            let _e45 = weft_d_ggx_k9_(_e18.n_dot_h);
            d = _e45;
        }
        let _e46 = d;
        let _e47 = visibility;
        specular = (((_e46 * _e47) * _e42) * 0.5f);
        let _e52 = n;
        let _e54 = weft_prefiltered_radiance_k10_(reflect(-(v_4), _e52));
        let _e55 = env_brdf;
        indirect_specular = ((_e54 * _e55) * 0.5f);
    }
    let _e59 = direct_kd;
    let diffuse = (_e59 * vec3<f32>(0.101859f, 0.06366192f, 0.038197216f));
    let _e62 = specular;
    let direct = (((diffuse + _e62) * vec3<f32>(3f, 2.8799999f, 2.6999998f)) * _e18.n_dot_l);
    let _e68 = n;
    let _e69 = weft_sh_irradiance(_e68);
    let _e70 = ambient_kd;
    let indirect_diffuse = ((_e69 * _e70) * vec3<f32>(0.31999952f, 0.19999982f, 0.120000094f));
    let _e73 = indirect_specular;
    let color_1 = ((direct + _e73) + indirect_diffuse);
    let _e76 = n;
    let _e78 = standard_sphere_map(color_1, _e76, in_1.world_position);
    let radiance = clamp((_e78 + vec3(0f)), vec3(0f), vec3(65504f));
    standard_alpha_test_k12_();
    return vec4<f32>(radiance, 1f);
}
