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
const WEFT_MIN_ANISO_ALPHA: f32 = 0.001f;
const GAUZE_LN_MAX_TRANSMITTANCE: f32 = 6.9077554f;

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

fn weft_any_perpendicular(n_1: vec3<f32>) -> vec3<f32> {
    let s = select(-1f, 1f, (n_1.z >= 0f));
    let a = (-1f / (s + n_1.z));
    let b = ((n_1.x * n_1.y) * a);
    return vec3<f32>((1f + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
}

fn weft_sh_irradiance(n_2: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    e = vec3<f32>(0.27778354f, 0.32136026f, 0.4497644f);
    e = (vec3<f32>(0.27778354f, 0.32136026f, 0.4497644f) + (vec3<f32>(0.2192843f, 0.34164187f, 0.663193f) * (0.488603f * n_2.y)));
    let _e11 = e;
    e = (_e11 + (vec3<f32>(0.1352113f, 0.12394369f, 0.10366199f) * (0.488603f * n_2.z)));
    let _e18 = e;
    e = (_e18 + (vec3<f32>(-0.14969625f, -0.13722156f, -0.11476713f) * (0.488603f * n_2.x)));
    let _e25 = e;
    e = (_e25 + (vec3<f32>(-0.064625785f, -0.059240304f, -0.049546435f) * ((1.092548f * n_2.x) * n_2.y)));
    let _e34 = e;
    e = (_e34 + (vec3<f32>(0.05837178f, 0.053507466f, 0.044751696f) * ((1.092548f * n_2.y) * n_2.z)));
    let _e43 = e;
    e = (_e43 + (vec3<f32>(0.025110306f, 0.023586905f, 0.01273896f) * (0.315392f * (((3f * n_2.z) * n_2.z) - 1f))));
    let _e56 = e;
    e = (_e56 + (vec3<f32>(-0.06322707f, -0.057958152f, -0.04847409f) * ((1.092548f * n_2.x) * n_2.z)));
    let _e65 = e;
    e = (_e65 + (vec3<f32>(0.056382716f, 0.05266991f, 0.031947177f) * (0.546274f * ((n_2.x * n_2.x) - (n_2.y * n_2.y)))));
    let _e78 = e;
    return max(_e78, vec3(0f));
}

fn weft_safe_normalize_k4_(v_1: vec3<f32>) -> vec3<f32> {
    let len2_1 = dot(v_1, v_1);
    return select(vec3<f32>(0f, 0f, 1f), (v_1 * inverseSqrt(max(len2_1, 0.00000000000000000001f))), (len2_1 > 0.00000000000000000001f));
}

fn weft_view_direction_k2_(world_position: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_frame.camera_position;
    let _e7 = weft_safe_normalize_k4_((_e4.xyz - world_position));
    return _e7;
}

fn weft_surface_two_sided(world_position_1: vec3<f32>, world_normal: vec3<f32>, front_facing_1: bool) -> WeftSurface {
    let _e3 = weft_view_direction_k2_(world_position_1);
    let facing = select(-(world_normal), world_normal, front_facing_1);
    let _e6 = weft_safe_normalize(facing, _e3);
    return WeftSurface(_e3, _e6);
}

fn weft_main_light_geometry(n_3: vec3<f32>, v_2: vec3<f32>) -> WeftLightGeometry {
    let _e4 = weft_safe_normalize((vec3<f32>(-0.61984503f, 0.54986256f, 0.55986005f) + v_2), n_3);
    let _e6 = weft_clamp_cos(dot(n_3, v_2));
    return WeftLightGeometry(vec3<f32>(-0.61984503f, 0.54986256f, 0.55986005f), _e4, _e6, saturate(dot(n_3, vec3<f32>(-0.61984503f, 0.54986256f, 0.55986005f))), saturate(dot(n_3, _e4)), saturate(dot(v_2, _e4)));
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

fn weft_tangent_frame(n_4: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_4 * dot(n_4, t_in)));
    let len2_3 = dot(t_proj, t_proj);
    let ok = (len2_3 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_4);
    let t = select(_e13, (t_proj * inverseSqrt(max(len2_3, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_4, t) * s_1);
    return mat3x3<f32>(t, b_1, n_4);
}

fn weft_aniso_to_frame(frame: mat3x3<f32>, x_1: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(frame[0], x_1), dot(frame[1], x_1), dot(frame[2], x_1));
}

fn weft_rotate_tangent_frame_cs_k15_(frame_1: mat3x3<f32>) -> mat3x3<f32> {
    let t_1 = ((frame_1[0] * -0.00000004371139f) + frame_1[1]);
    let b_2 = ((frame_1[1] * -0.00000004371139f) - frame_1[0]);
    return mat3x3<f32>(t_1, b_2, frame_1[2]);
}

fn weft_rotate_tangent_frame_k7_(frame_2: mat3x3<f32>) -> mat3x3<f32> {
    let _e2 = weft_rotate_tangent_frame_cs_k15_(frame_2);
    return _e2;
}

fn weft_f_schlick_k9_(v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (vec3(0.04f) + (vec3<f32>(0.96f, 0.96f, 0.96f) * _e5));
}

fn weft_env_brdf_lut_k10_(n_dot_v: f32) -> vec2<f32> {
    let uv = vec2<f32>(saturate(n_dot_v), 0.45f);
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv, 0f);
    return _e8.xy;
}

fn weft_env_brdf_from_lut_k11_(scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return ((vec3(0.04f) * sb.x) + vec3(sb.y));
}

fn weft_aniso_bent_normal_k13_(frame_3: mat3x3<f32>, v_4: vec3<f32>) -> vec3<f32> {
    let n_5 = frame_3[2];
    let dir_1 = frame_3[1];
    let aniso_t = cross(dir_1, v_4);
    let aniso_n = cross(aniso_t, dir_1);
    let _e11 = weft_safe_normalize(mix(n_5, aniso_n, 0.8f), n_5);
    return _e11;
}

fn weft_specular_mip_k17_() -> f32 {
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return (0.62325f * max_mip);
}

fn weft_prefiltered_radiance_k14_(dir: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_specular_mip_k17_();
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
}

fn weft_aniso_ggx_q_k21_(t_dot_h: f32, b_dot_h: f32, n_dot_h: f32) -> f32 {
    let x_2 = (t_dot_h / 0.36449996f);
    let y = (b_dot_h / 0.040499996f);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 0.000001f);
}

fn weft_d_ggx_aniso_k19_(t_dot_h_1: f32, b_dot_h_1: f32, n_dot_h_1: f32) -> f32 {
    let _e7 = weft_aniso_ggx_q_k21_(t_dot_h_1, b_dot_h_1, n_dot_h_1);
    let d = (1f / ((0.046376966f * _e7) * _e7));
    return select(0f, d, (n_dot_h_1 > 0f));
}

fn weft_v_smith_ggx_aniso_correlated_k20_(v_5: vec3<f32>, l: vec3<f32>) -> f32 {
    let _e5 = weft_clamp_cos(v_5.z);
    let _e7 = weft_clamp_cos(l.z);
    let lv = (_e7 * length(vec3<f32>((0.36449996f * v_5.x), (0.040499996f * v_5.y), _e5)));
    let ll = (_e5 * length(vec3<f32>((0.36449996f * l.x), (0.040499996f * l.y), _e7)));
    return (0.5f / (lv + ll));
}

fn weft_spec_ggx_aniso_k18_(v_6: vec3<f32>, l_1: vec3<f32>) -> f32 {
    let _e5 = weft_safe_normalize_k4_((v_6 + l_1));
    let _e9 = weft_d_ggx_aniso_k19_(_e5.x, _e5.y, _e5.z);
    let _e10 = weft_v_smith_ggx_aniso_correlated_k20_(v_6, l_1);
    return ((_e9 * _e10) * saturate(l_1.z));
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var spec_direct: vec3<f32>;
    var env_brdf: vec3<f32>;
    var diffuse_kd: vec3<f32>;
    var ambient_kd: vec3<f32>;
    var lobe: f32;

    let uv_s = (in_1.uv0_ * 60f);
    let grid_w = fwidth(uv_s);
    let _e18 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    let v_7 = _e18.v;
    let n_geom = _e18.n;
    n = n_geom;
    let _e22 = n;
    let _e24 = weft_tangent_frame(_e22, in_1.world_tangent);
    let cos_v = min(abs(dot(n_geom, v_7)), 1f);
    let sin_v = sqrt(max((1f - (cos_v * cos_v)), 0f));
    let s_2 = pow(max(sin_v, 0.00000001f), 3f);
    let alpha = saturate((1f - ((1f - s_2) * 0.6930604f)));
    let coverage = saturate((1f - ((1f - s_2) * 0f)));
    let _e56 = weft_rotate_tangent_frame_k7_(_e24);
    let _e59 = n;
    let _e60 = weft_main_light_geometry(_e59, v_7);
    {
        {
            let _e71 = weft_aniso_to_frame(_e24, v_7);
            let _e73 = weft_aniso_to_frame(_e24, _e60.l);
            let _e74 = weft_aniso_to_frame(_e56, v_7);
            let _e76 = weft_aniso_to_frame(_e56, _e60.l);
            let _e77 = weft_spec_ggx_aniso_k18_(_e71, _e73);
            let _e78 = weft_spec_ggx_aniso_k18_(_e74, _e76);
            lobe = mix(_e77, _e78, 0f);
        }
        let _e81 = weft_f_schlick_k9_(_e60.v_dot_h);
        let _e82 = lobe;
        spec_direct = (((_e82 * _e81) * vec3<f32>(1f, 0.8900054f, 0.93310684f)) * vec3<f32>(3.2f, 3.05f, 2.8f));
        let _e88 = weft_f_schlick_k9_(_e60.n_dot_v);
        diffuse_kd = (vec3(1f) - (vec3<f32>(1f, 0.8900054f, 0.93310684f) * _e88));
        let _e92 = weft_env_brdf_lut_k10_(_e60.n_dot_v);
        let _e93 = weft_env_brdf_from_lut_k11_(_e92);
        env_brdf = (_e93 * vec3<f32>(1f, 0.8900054f, 0.93310684f));
        let _e96 = env_brdf;
        ambient_kd = max((vec3(1f) - _e96), vec3(0f));
    }
    let _e100 = diffuse_kd;
    let diffuse_direct = (((_e100 * vec3<f32>(0.26995486f, 0.22618032f, 0.23822759f)) * vec3<f32>(3.2f, 3.05f, 2.8f)) * _e60.n_dot_l);
    let _e106 = n;
    let _e107 = weft_sh_irradiance(_e106);
    let _e108 = ambient_kd;
    let diffuse_indirect = ((_e107 * _e108) * vec3<f32>(0.84808826f, 0.71056646f, 0.7484141f));
    let _e111 = weft_aniso_bent_normal_k13_(_e24, v_7);
    let _e114 = weft_prefiltered_radiance_k14_(reflect(-(v_7), _e111));
    let _e115 = env_brdf;
    let spec_indirect = (_e114 * _e115);
    let _e119 = spec_direct;
    let color = ((alpha * (diffuse_direct + diffuse_indirect)) + (coverage * (_e119 + spec_indirect)));
    let radiance = clamp(color, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
