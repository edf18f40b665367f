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

struct SatinLayers {
    narrow: vec2<f32>,
    wide: vec2<f32>,
}

struct WeftMaterial {
    base_color: vec4<f32>,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const TIER_LOW: u32 = 3u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_MIN_ANISO_ALPHA: f32 = 0.001f;
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
@group(1) @binding(0) 
var<uniform> material: WeftMaterial;

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
    let s_1 = select(-1f, 1f, (n_1.z >= 0f));
    let a_1 = (-1f / (s_1 + n_1.z));
    let b = ((n_1.x * n_1.y) * a_1);
    return vec3<f32>((1f + (((s_1 * n_1.x) * n_1.x) * a_1)), (s_1 * b), (-(s_1) * n_1.x));
}

fn weft_f_schlick(f0_: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (f0_ + ((vec3(1f) - f0_) * _e5));
}

fn weft_diffuse_lambert(albedo: vec3<f32>) -> vec3<f32> {
    return (albedo * WEFT_INV_PI);
}

fn weft_env_brdf_from_lut(f0_1: vec3<f32>, scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return ((f0_1 * sb.x) + vec3(sb.y));
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

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e2 = weft_view_direction_k2_(world_position_1);
    let _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface(_e2, _e3);
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
    let s_2 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_4, t) * s_2);
    return mat3x3<f32>(t, b_1, n_4);
}

fn weft_aniso_to_frame(frame: mat3x3<f32>, x_1: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(frame[0], x_1), dot(frame[1], x_1), dot(frame[2], x_1));
}

fn weft_aniso_ggx_q(t_dot_h: f32, b_dot_h: f32, n_dot_h: f32, alpha_t: f32, alpha_b: f32) -> f32 {
    let at = max(alpha_t, WEFT_MIN_ANISO_ALPHA);
    let ab = max(alpha_b, WEFT_MIN_ANISO_ALPHA);
    let x_2 = (t_dot_h / at);
    let y = (b_dot_h / ab);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 0.000001f);
}

fn weft_d_ggx_aniso(t_dot_h_1: f32, b_dot_h_1: f32, n_dot_h_1: f32, alpha_t_1: f32, alpha_b_1: f32) -> f32 {
    let at_1 = max(alpha_t_1, WEFT_MIN_ANISO_ALPHA);
    let ab_1 = max(alpha_b_1, WEFT_MIN_ANISO_ALPHA);
    let _e9 = weft_aniso_ggx_q(t_dot_h_1, b_dot_h_1, n_dot_h_1, at_1, ab_1);
    let d = (1f / ((((WEFT_PI * at_1) * ab_1) * _e9) * _e9));
    return select(0f, d, (n_dot_h_1 > 0f));
}

fn weft_v_smith_ggx_aniso_correlated(v_4: vec3<f32>, l: vec3<f32>, alpha_t_2: f32, alpha_b_2: f32) -> f32 {
    let _e5 = weft_clamp_cos(v_4.z);
    let _e7 = weft_clamp_cos(l.z);
    let lv = (_e7 * length(vec3<f32>((alpha_t_2 * v_4.x), (alpha_b_2 * v_4.y), _e5)));
    let ll = (_e5 * length(vec3<f32>((alpha_t_2 * l.x), (alpha_b_2 * l.y), _e7)));
    return (0.5f / (lv + ll));
}

fn weft_spec_ggx_aniso(v_5: vec3<f32>, l_1: vec3<f32>, alpha_t_3: f32, alpha_b_3: f32) -> f32 {
    let _e5 = weft_safe_normalize_k4_((v_5 + l_1));
    let _e9 = weft_d_ggx_aniso(_e5.x, _e5.y, _e5.z, alpha_t_3, alpha_b_3);
    let _e10 = weft_v_smith_ggx_aniso_correlated(v_5, l_1, alpha_t_3, alpha_b_3);
    return ((_e9 * _e10) * saturate(l_1.z));
}

fn satin_lobe_reference(vf: vec3<f32>, lf: vec3<f32>, a: vec2<f32>) -> f32 {
    var s: f32;

    let _e5 = weft_spec_ggx_aniso(vf, lf, a.x, a.y);
    s = _e5;
    let _e7 = s;
    return _e7;
}

fn weft_env_brdf_lut_k10_(n_dot_v: f32) -> vec2<f32> {
    let uv = vec2<f32>(saturate(n_dot_v), 0.4f);
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv, 0f);
    return _e8.xy;
}

fn weft_env_brdf_lut_k11_(n_dot_v_1: f32) -> vec2<f32> {
    let uv_1 = vec2<f32>(saturate(n_dot_v_1), 0.8f);
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_1, 0f);
    return _e8.xy;
}

fn weft_aniso_bent_normal_k16_(frame_1: mat3x3<f32>, v_6: vec3<f32>) -> vec3<f32> {
    let n_5 = frame_1[2];
    let dir_2 = frame_1[1];
    let aniso_t = cross(dir_2, v_6);
    let aniso_n = cross(aniso_t, dir_2);
    let _e11 = weft_safe_normalize(mix(n_5, aniso_n, 0.85f), n_5);
    return _e11;
}

fn weft_specular_mip_k20_() -> f32 {
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return (0.568f * max_mip);
}

fn weft_prefiltered_radiance_k17_(dir: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_specular_mip_k20_();
    let c_3 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_3.xyz, vec3(0f));
}

fn satin_env_k12_(frame_2: mat3x3<f32>, v_7: vec3<f32>) -> vec3<f32> {
    var bent_1: vec3<f32>;
    var c_1: vec3<f32>;

    let _e4 = weft_aniso_bent_normal_k16_(frame_2, v_7);
    bent_1 = _e4;
    let _e7 = bent_1;
    let _e9 = weft_prefiltered_radiance_k17_(reflect(-(v_7), _e7));
    c_1 = _e9;
    let _e11 = c_1;
    return _e11;
}

fn weft_aniso_bent_normal_k18_(frame_3: mat3x3<f32>, v_8: vec3<f32>) -> vec3<f32> {
    let n_6 = frame_3[2];
    let dir_3 = frame_3[1];
    let aniso_t_1 = cross(dir_3, v_8);
    let aniso_n_1 = cross(aniso_t_1, dir_3);
    let _e11 = weft_safe_normalize(mix(n_6, aniso_n_1, 0.85f), n_6);
    return _e11;
}

fn weft_specular_mip_k21_() -> f32 {
    let _e5 = weft_frame.params.x;
    let max_mip_1 = max((_e5 - 1f), 0f);
    return (0.9120001f * max_mip_1);
}

fn weft_prefiltered_radiance_k19_(dir_1: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_specular_mip_k21_();
    let c_4 = textureSampleLevel(weft_environment, weft_environment_sampler, dir_1, _e4);
    return max(c_4.xyz, vec3(0f));
}

fn satin_env_k13_(frame_4: mat3x3<f32>, v_9: vec3<f32>) -> vec3<f32> {
    var bent_2: vec3<f32>;
    var c_2: vec3<f32>;

    let _e4 = weft_aniso_bent_normal_k18_(frame_4, v_9);
    bent_2 = _e4;
    let _e7 = bent_2;
    let _e9 = weft_prefiltered_radiance_k19_(reflect(-(v_9), _e7));
    c_2 = _e9;
    let _e11 = c_2;
    return _e11;
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var layers: SatinLayers;
    var specular: vec3<f32>;
    var diffuse_kd: vec3<f32>;
    var indirect_specular: vec3<f32>;
    var ambient_kd: vec3<f32>;
    var bent: vec3<f32>;

    let base_rgba = material.base_color;
    let base = saturate(base_rgba.xyz);
    let alpha = saturate(base_rgba.w);
    let _e18 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_10 = _e18.v;
    n = _e18.n;
    let _e22 = n;
    let _e24 = weft_tangent_frame(_e22, in_1.world_tangent);
    let _e25 = n;
    let _e26 = weft_main_light_geometry(_e25, v_10);
    layers.narrow = vec2<f32>(0.29600003f, 0.023999998f);
    layers.wide = vec2<f32>(1.1840001f, 0.09599999f);
    let f0_2 = mix(vec3(0.04f), base, 0f);
    let _e38 = weft_f_schlick(f0_2, _e26.v_dot_h);
    {
        let _e48 = weft_aniso_to_frame(_e24, v_10);
        let _e50 = weft_aniso_to_frame(_e24, _e26.l);
        let _e52 = layers.narrow;
        let _e53 = satin_lobe_reference(_e48, _e50, _e52);
        let _e55 = layers.wide;
        let _e56 = satin_lobe_reference(_e48, _e50, _e55);
        specular = ((((vec3<f32>(0.7584107f, 0.6081799f, 0.62124574f) * _e53) + (vec3<f32>(0.24158928f, 0.13334814f, 0.14008713f) * _e56)) * _e38) * vec3<f32>(3.2f, 3.05f, 2.8f));
        let _e65 = weft_f_schlick(f0_2, _e26.n_dot_v);
        diffuse_kd = max((vec3(1f) - (vec3<f32>(1f, 0.74152803f, 0.76133287f) * _e65)), vec3(0f));
        let _e71 = weft_env_brdf_lut_k10_(_e26.n_dot_v);
        let _e72 = weft_env_brdf_from_lut(f0_2, _e71);
        let e1_ = (_e72 * vec3<f32>(0.7584107f, 0.6081799f, 0.62124574f));
        let _e75 = weft_env_brdf_lut_k11_(_e26.n_dot_v);
        let _e76 = weft_env_brdf_from_lut(f0_2, _e75);
        let e2_ = (_e76 * vec3<f32>(0.24158928f, 0.13334814f, 0.14008713f));
        {
            let _e78 = satin_env_k12_(_e24, v_10);
            let _e80 = satin_env_k13_(_e24, v_10);
            indirect_specular = ((_e78 * e1_) + (_e80 * e2_));
        }
        ambient_kd = max(((vec3(1f) - e1_) - e2_), vec3(0f));
    }
    let _e88 = diffuse_kd;
    let _e89 = weft_diffuse_lambert(base);
    let _e94 = specular;
    let direct = ((((_e88 * _e89) * vec3<f32>(3.2f, 3.05f, 2.8f)) * _e26.n_dot_l) + _e94);
    let _e96 = indirect_specular;
    let _e97 = n;
    let _e98 = weft_sh_irradiance(_e97);
    let _e99 = ambient_kd;
    let indirect = (_e96 + ((_e98 * _e99) * base));
    let radiance = clamp((direct + indirect), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
