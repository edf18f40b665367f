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
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_SHEEN_MIN_ROUGHNESS: f32 = 0.07f;

@group(0) @binding(0) 
var<uniform> weft_frame: WeftFrame;
@group(0) @binding(1) 
var weft_environment: texture_cube<f32>;
@group(0) @binding(2) 
var weft_environment_sampler: sampler;
@group(0) @binding(4) 
var weft_lut_sampler: sampler;
@group(0) @binding(5) 
var weft_sheen_lut: texture_2d<f32>;
@group(2) @binding(0) 
var<uniform> weft_object: WeftObject;

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

fn weft_sheen_albedo_scaling_view_k7_(e_v: f32) -> f32 {
    return saturate((1f - (0.5499996f * saturate(e_v))));
}

fn weft_sheen_albedo_scaling_k9_(e_v_1: f32, e_l: f32) -> f32 {
    return saturate(min((1f - (0.5499996f * saturate(e_v_1))), (1f - (0.5499996f * saturate(e_l)))));
}

fn weft_sheen_albedo_k13_(n_dot_x: f32) -> f32 {
    let uv = vec2<f32>(saturate(n_dot_x), 0.36f);
    let _e8 = textureSampleLevel(weft_sheen_lut, weft_lut_sampler, uv, 0f);
    return saturate(_e8.x);
}

fn weft_d_charlie_k16_(n_dot_h: f32) -> f32 {
    let noh = saturate(n_dot_h);
    let sin2_ = max(((1f - noh) * (1f + noh)), 0f);
    return ((4.7777777f * pow(sin2_, 1.3888888f)) * 0.15915494f);
}

fn weft_sheen_l_k20_(x: f32) -> f32 {
    return (((23.09444f / (1f + (3.622809f * pow(max(x, 0f), 0.18585189f)))) + (-1.6893767f * x)) + -4.5413675f);
}

fn weft_sheen_lambda_one_exp_k19_(cos_theta: f32) -> f32 {
    let _e2 = weft_clamp_cos(cos_theta);
    let low = (_e2 < 0.5f);
    let _e8 = weft_sheen_l_k20_(select((1f - _e2), _e2, low));
    return exp(select((0.26487064f - _e8), _e8, low));
}

fn weft_v_charlie_k17_(n_dot_v: f32, n_dot_l: f32) -> f32 {
    let _e4 = weft_clamp_cos(n_dot_v);
    let _e5 = weft_clamp_cos(n_dot_l);
    let _e6 = weft_sheen_lambda_one_exp_k19_(_e4);
    let _e9 = weft_sheen_lambda_one_exp_k19_(_e5);
    let g_inv = ((1f + _e6) + _e9);
    return (1f / (((g_inv * 4f) * _e4) * _e5));
}

fn weft_sheen_charlie_k14_(n_dot_h_1: f32, n_dot_v_1: f32, n_dot_l_1: f32) -> vec3<f32> {
    let _e5 = weft_d_charlie_k16_(n_dot_h_1);
    let _e6 = weft_v_charlie_k17_(n_dot_v_1, n_dot_l_1);
    let lobe = (_e5 * _e6);
    return (vec3<f32>(0.5499996f, 0.21999988f, 0.2999997f) * (lobe * saturate(n_dot_l_1)));
}

fn weft_specular_mip_k18_() -> f32 {
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return (0.52128005f * max_mip);
}

fn weft_prefiltered_radiance_k15_(dir: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_specular_mip_k18_();
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var color: vec3<f32>;
    var sheen: vec3<f32>;
    var scaling: f32;

    let _e11 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_4 = _e11.v;
    n = _e11.n;
    let _e15 = n;
    let _e16 = weft_main_light_geometry(_e15, v_4);
    let l_dot_h = saturate(dot(_e16.l, _e16.h));
    let _e24 = n;
    let _e25 = weft_sh_irradiance(_e24);
    {
        let _e30 = weft_sheen_albedo_k13_(_e16.n_dot_v);
        let _e31 = weft_sheen_albedo_scaling_view_k7_(_e30);
        {
            let _e35 = weft_sheen_albedo_k13_(_e16.n_dot_l);
            let _e39 = weft_sheen_charlie_k14_(_e16.n_dot_h, _e16.n_dot_v, _e16.n_dot_l);
            sheen = _e39;
            let _e40 = weft_sheen_albedo_scaling_k9_(_e30, _e35);
            scaling = _e40;
        }
        let _e42 = scaling;
        let base_direct = (vec3<f32>(0.057295743f, 0.006366218f, 0.015915554f) * (_e42 * _e16.n_dot_l));
        let _e46 = sheen;
        let direct = ((_e46 + base_direct) * vec3<f32>(3f, 2.8799999f, 2.6999998f));
        let _e50 = n;
        let _e52 = weft_prefiltered_radiance_k15_(reflect(-(v_4), _e50));
        let env_sheen = ((_e52 * vec3<f32>(0.5499996f, 0.21999988f, 0.2999997f)) * _e30);
        color = ((direct + ((_e25 * vec3<f32>(0.17999989f, 0.020000065f, 0.050000187f)) * _e31)) + env_sheen);
    }
    let _e59 = color;
    let radiance = clamp(_e59, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
