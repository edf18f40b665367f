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

struct SilkLobe {
    value: f32,
    alpha: vec2<f32>,
    ibl_roughness: f32,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const ANISO_MODEL_WARD: u32 = 0u;
const ANISO_MODEL_HAIR_SHIFTED: u32 = 1u;
const ANISO_MODEL_GGX: u32 = 2u;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const TIER_LOW: u32 = 3u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_MIN_ANISO_ALPHA: f32 = 0.001f;
const SILK_MIN_ALPHA: f32 = 0.001f;
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

fn weft_any_perpendicular(n: vec3<f32>) -> vec3<f32> {
    let s = select(-1f, 1f, (n.z >= 0f));
    let a = (-1f / (s + n.z));
    let b = ((n.x * n.y) * a);
    return vec3<f32>((1f + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
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

fn weft_specular_mip(roughness: f32) -> f32 {
    let r = saturate(roughness);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r * (1.7f - (0.7f * r))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_1: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_1);
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
}

fn weft_env_brdf_lut(n_dot_v: f32, roughness_2: f32) -> vec2<f32> {
    let uv = vec2<f32>(saturate(n_dot_v), saturate(roughness_2));
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv, 0f);
    return _e8.xy;
}

fn weft_safe_normalize_k10_(v_1: vec3<f32>) -> vec3<f32> {
    let len2_1 = dot(v_1, v_1);
    return select(vec3<f32>(0f, 0f, 1f), (v_1 * inverseSqrt(max(len2_1, 0.00000000000000000001f))), (len2_1 > 0.00000000000000000001f));
}

fn weft_view_direction_k2_(world_position: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_frame.camera_position;
    let _e7 = weft_safe_normalize_k10_((_e4.xyz - world_position));
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

fn weft_tangent_frame(n_3: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_3 * dot(n_3, t_in)));
    let len2_3 = dot(t_proj, t_proj);
    let ok = (len2_3 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_3);
    let t = select(_e13, (t_proj * inverseSqrt(max(len2_3, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_3, t) * s_1);
    return mat3x3<f32>(t, b_1, n_3);
}

fn weft_aniso_to_frame(frame: mat3x3<f32>, x_1: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(frame[0], x_1), dot(frame[1], x_1), dot(frame[2], x_1));
}

fn weft_aniso_bent_normal(frame_1: mat3x3<f32>, v_4: vec3<f32>, anisotropy: f32, roughness_3: f32) -> vec3<f32> {
    let k = clamp(anisotropy, -1f, 1f);
    let n_4 = frame_1[2];
    let dir_1 = select(frame_1[0], frame_1[1], (k >= 0f));
    let aniso_t = cross(dir_1, v_4);
    let aniso_n = cross(aniso_t, dir_1);
    let bend = (abs(k) * saturate((5f * saturate(roughness_3))));
    let _e22 = weft_safe_normalize(mix(n_4, aniso_n, bend), n_4);
    return _e22;
}

fn silk_lobe_anisotropy(alpha: vec2<f32>) -> f32 {
    let at = max(alpha.x, SILK_MIN_ALPHA);
    let ab = max(alpha.y, SILK_MIN_ALPHA);
    return ((at - ab) / (at + ab));
}

fn weft_f_schlick_k7_(v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (vec3<f32>(0.04f, 0.04f, 0.04f) + (vec3<f32>(0.96f, 0.96f, 0.96f) * _e5));
}

fn weft_env_brdf_from_lut_k9_(scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return ((vec3<f32>(0.04f, 0.04f, 0.04f) * sb.x) + vec3(sb.y));
}

fn weft_normal_from_tangent_space_k12_(frame_2: mat3x3<f32>) -> vec3<f32> {
    let _e4 = weft_safe_normalize((frame_2 * vec3<f32>(vec2<f32>(0.003921628f, 0.003921628f), 1f)), frame_2[2]);
    return _e4;
}

fn weft_v_smith_ggx_aniso_correlated_k13_(v_5: vec3<f32>, l: vec3<f32>) -> f32 {
    let _e5 = weft_clamp_cos(v_5.z);
    let _e7 = weft_clamp_cos(l.z);
    let lv = (_e7 * length(vec3<f32>((0.23174134f * v_5.x), (0.06475432f * v_5.y), _e5)));
    let ll = (_e5 * length(vec3<f32>((0.23174134f * l.x), (0.06475432f * l.y), _e7)));
    return (0.5f / (lv + ll));
}

fn weft_aniso_ggx_q_k15_(t_dot_h: f32, b_dot_h: f32, n_dot_h: f32) -> f32 {
    let x_2 = (t_dot_h / 0.23174134f);
    let y = (b_dot_h / 0.06475432f);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 0.000001f);
}

fn weft_d_ggx_aniso_k14_(t_dot_h_1: f32, b_dot_h_1: f32, n_dot_h_1: f32) -> f32 {
    let _e7 = weft_aniso_ggx_q_k15_(t_dot_h_1, b_dot_h_1, n_dot_h_1);
    let d = (1f / ((0.047143534f * _e7) * _e7));
    return select(0f, d, (n_dot_h_1 > 0f));
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var fibre: vec3<f32>;
    var lobe: SilkLobe;
    var vis: f32;
    var env_brdf: vec3<f32>;
    var ambient_kd: vec3<f32>;
    var reflect_n: vec3<f32>;

    let _e11 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_6 = _e11.v;
    let n_geo = _e11.n;
    let _e15 = weft_tangent_frame(n_geo, in_1.world_tangent);
    let _e17 = weft_normal_from_tangent_space_k12_(_e15);
    fibre = _e15[0];
    let _e20 = fibre;
    let _e24 = weft_tangent_frame(_e17, vec4<f32>(_e20, in_1.world_tangent.w));
    let _e25 = weft_main_light_geometry(_e17, v_6);
    let _e26 = weft_aniso_to_frame(_e24, v_6);
    let _e28 = weft_aniso_to_frame(_e24, _e25.l);
    let _e30 = weft_aniso_to_frame(_e24, _e25.h);
    {
        {
            lobe.alpha = vec2<f32>(0.23174134f, 0.06475432f);
            lobe.ibl_roughness = 0.35000002f;
            {
                {
                    let _e37 = weft_v_smith_ggx_aniso_correlated_k13_(_e26, _e28);
                    vis = _e37;
                }
                let _e42 = weft_d_ggx_aniso_k14_(_e30.x, _e30.y, _e30.z);
                let _e43 = vis;
                lobe.value = ((_e42 * _e43) * _e25.n_dot_l);
            }
        }
    }
    let n_dot_l_diffuse = saturate(dot(n_geo, _e25.l));
    let _e52 = weft_f_schlick_k7_(_e25.v_dot_h);
    let diffuse = (((vec3(1f) - _e52) * vec3<f32>(0.222817f, 0.14323957f, 0.031830948f)) * n_dot_l_diffuse);
    let _e59 = lobe.value;
    let direct = ((diffuse + (_e52 * _e59)) * vec3<f32>(3f, 2.8799999f, 2.6999998f));
    reflect_n = _e17;
    {
        let _e68 = lobe.ibl_roughness;
        let _e69 = weft_env_brdf_lut(_e25.n_dot_v, _e68);
        let _e70 = weft_env_brdf_from_lut_k9_(_e69);
        env_brdf = _e70;
        let _e72 = env_brdf;
        ambient_kd = max((vec3(1f) - _e72), vec3(0f));
        let _e77 = lobe.alpha;
        let _e78 = silk_lobe_anisotropy(_e77);
        let _e80 = lobe.ibl_roughness;
        let _e81 = weft_aniso_bent_normal(_e24, v_6, _e78, _e80);
        reflect_n = _e81;
    }
    let _e83 = reflect_n;
    let _e86 = lobe.ibl_roughness;
    let _e87 = weft_prefiltered_radiance(reflect(-(v_6), _e83), _e86);
    let _e88 = env_brdf;
    let _e90 = weft_sh_irradiance(n_geo);
    let _e91 = ambient_kd;
    let indirect = ((_e87 * _e88) + ((_e90 * _e91) * vec3<f32>(0.7000003f, 0.4500004f, 0.099999875f)));
    let radiance = clamp((direct + indirect), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
