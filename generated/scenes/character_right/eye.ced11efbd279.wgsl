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

struct EyeCornea {
    z_iris: f32,
    centre_z: f32,
    radius: f32,
}

struct EyeLookup {
    iris: vec2<f32>,
    normal: vec3<f32>,
    through_cornea: f32,
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

fn weft_sh_irradiance(n: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    let sh = weft_frame.sh;
    e = (sh[0].xyz * 0.282095f);
    let _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603f * n.y)));
    let _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603f * n.z)));
    let _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603f * n.x)));
    let _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548f * n.x) * n.y)));
    let _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548f * n.y) * n.z)));
    let _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392f * (((3f * n.z) * n.z) - 1f))));
    let _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548f * n.x) * n.z)));
    let _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274f * ((n.x * n.x) - (n.y * n.y)))));
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

fn weft_safe_normalize_k3_(v_2: vec3<f32>) -> vec3<f32> {
    let len2_2 = dot(v_2, v_2);
    return select(vec3(0f), (v_2 * inverseSqrt(max(len2_2, 0.00000000000000000001f))), (len2_2 > 0.00000000000000000001f));
}

fn weft_forward_vertex(in_2: WeftVertexInput) -> WeftVaryings {
    var out: WeftVaryings;

    let model = weft_object.model;
    let model3_ = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm = weft_object.normal_matrix;
    let normal3_1 = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = (model * vec4<f32>(in_2.position, 1f));
    let mirror = select(1f, -1f, (determinant(model3_) < 0f));
    let bitangent_sign = (select(1f, -1f, (in_2.tangent.w < 0f)) * mirror);
    let _e43 = weft_frame.view_proj;
    out.clip_position = (_e43 * vec4<f32>(world.xyz, 1f));
    out.world_position = world.xyz;
    let _e53 = weft_safe_normalize_k3_((normal3_1 * in_2.normal));
    out.world_normal = _e53;
    let _e58 = weft_safe_normalize_k3_((model3_ * in_2.tangent.xyz));
    out.world_tangent = vec4<f32>(_e58, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    let _e62 = out;
    return _e62;
}

fn eye_procedural_iris(rho: f32, a: f32) -> vec3<f32> {
    var c_1: vec3<f32>;

    let t = saturate(((rho - 0.38f) / 0.62f));
    c_1 = mix(vec3<f32>(0.34239164f, 0.147319f, 0.021980947f), vec3<f32>(0.10653923f, 0.033104766f, 0.008540382f), smoothstep(0.05f, 0.5f, t));
    let fibres = ((0.82f + (0.1f * sin(((a * 23f) + (6f * t))))) + (0.08f * sin((((a * 41f) - (9f * t)) + 1.3f))));
    let _e35 = c_1;
    c_1 = (_e35 * fibres);
    let _e38 = c_1;
    c_1 = (_e38 * (1f - (0.8f * smoothstep(0.88f, 1f, rho))));
    let _e48 = c_1;
    return mix(vec3(0.01f), _e48, smoothstep(0.35999998f, 0.4f, rho));
}

fn eye_albedo(q: vec2<f32>, front: bool) -> vec3<f32> {
    var iris: vec3<f32>;

    let rho_2 = (length(q) / 0.5f);
    {
        let qa = select(vec2<f32>(1f, 0f), q, (dot(q, q) > 0.000000000001f));
        let _e14 = eye_procedural_iris(rho_2, atan2(qa.y, qa.x));
        iris = _e14;
    }
    let to_sclera = select(1f, smoothstep(0.985f, 1.015f, rho_2), front);
    let _e21 = iris;
    return saturate(mix(_e21, vec3<f32>(0.71056646f, 0.67385954f, 0.6382832f), to_sclera));
}

fn weft_f_schlick_k20_(v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (vec3(0.025042804f) + (vec3<f32>(0.97495717f, 0.97495717f, 0.97495717f) * _e5));
}

fn eye_fresnel_k8_(cos_i: f32) -> f32 {
    let _e2 = weft_f_schlick_k20_(cos_i);
    return _e2.x;
}

fn weft_d_ggx_k14_(n_dot_h: f32) -> f32 {
    let noh = saturate(n_dot_h);
    let one_minus_noh2_ = ((1f - noh) * (1f + noh));
    let d = (one_minus_noh2_ + ((noh * noh) * 0.000012960001f));
    return (0.000012960001f / ((WEFT_PI * d) * d));
}

fn weft_v_smith_ggx_correlated_newton_k15_(n_dot_v: f32, n_dot_l: f32) -> f32 {
    let _e6 = weft_clamp_cos(n_dot_v);
    let _e7 = weft_clamp_cos(n_dot_l);
    let gv = ((_e6 * 0.9964f) + 0.0036000002f);
    let gl = ((_e7 * 0.9964f) + 0.0036000002f);
    let pv = ((gv * _e6) + (0.000012960001f * (1f - _e6)));
    let pl = ((gl * _e7) + (0.000012960001f * (1f - _e7)));
    return (((0.5f * gv) * gl) / (((_e7 * gl) * pv) + ((_e6 * gv) * pl)));
}

fn eye_ggx_k9_(s: vec3<f32>, h: vec3<f32>, s_dot_v: f32, s_dot_l: f32) -> f32 {
    let _e7 = weft_d_ggx_k14_(saturate(dot(s, h)));
    let _e8 = weft_v_smith_ggx_correlated_newton_k15_(s_dot_v, s_dot_l);
    return (_e7 * _e8);
}

fn weft_specular_mip_k16_() -> f32 {
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return (0.09948f * max_mip);
}

fn weft_prefiltered_radiance_k11_(dir: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_specular_mip_k16_();
    let c_2 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_2.xyz, vec3(0f));
}

fn weft_env_brdf_lut_k12_(n_dot_v_1: f32) -> vec2<f32> {
    let uv = vec2<f32>(saturate(n_dot_v_1), 0.060000002f);
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv, 0f);
    return _e8.xy;
}

fn weft_env_brdf_from_lut_k19_(scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return ((vec3(0.025042804f) * sb.x) + vec3(sb.y));
}

fn eye_physical_k7_(look_1: EyeLookup, n_1: vec3<f32>, v_3: vec3<f32>, l: vec3<f32>, normal3_: mat3x3<f32>, light: vec3<f32>) -> vec3<f32> {
    var local: bool;

    if !((look_1.through_cornea > 0f)) {
        local = (look_1.normal.z > 0f);
    } else {
        local = true;
    }
    let _e19 = local;
    let _e20 = eye_albedo(look_1.iris, _e19);
    let _e24 = weft_safe_normalize((normal3_ * look_1.normal), n_1);
    let _e26 = weft_clamp_cos(dot(_e24, v_3));
    let s_dot_l_1 = saturate(dot(_e24, l));
    let _e30 = weft_safe_normalize((l + v_3), _e24);
    let _e32 = eye_fresnel_k8_(dot(v_3, _e30));
    let _e33 = eye_ggx_k9_(_e24, _e30, _e26, s_dot_l_1);
    let direct_spec = ((_e33 * _e32) * s_dot_l_1);
    let _e39 = weft_prefiltered_radiance_k11_(reflect(-(v_3), _e24));
    let _e40 = weft_env_brdf_lut_k12_(_e26);
    let _e41 = weft_env_brdf_from_lut_k19_(_e40);
    let env = (_e39 * _e41);
    let specular = ((light * direct_spec) + env);
    let on_iris = (look_1.through_cornea > 0f);
    let _e50 = weft_safe_normalize((normal3_ * vec3<f32>(0f, 0f, 1f)), n_1);
    let l_in = refract(-(l), _e24, 0.7267442f);
    let iris_cos = select(0f, saturate(dot(_e50, -(l_in))), (s_dot_l_1 > 0f));
    let _e61 = eye_fresnel_k8_(_e26);
    let t_v = (1f - _e61);
    let _e64 = eye_fresnel_k8_(s_dot_l_1);
    let t_l = (1f - _e64);
    let diffuse_n = select(n_1, _e50, on_iris);
    let diffuse_cos = select(saturate(dot(n_1, l)), (iris_cos * t_l), on_iris);
    let transmission = select(1f, t_v, on_iris);
    let _e78 = weft_sh_irradiance(diffuse_n);
    let diffuse = ((_e20 * transmission) * ((light * (WEFT_INV_PI * diffuse_cos)) + _e78));
    return (diffuse + specular);
}

fn eye_cornea_height_k17_(rho_1: f32) -> f32 {
    let z = (0.5380625f + sqrt(max((0.35755965f - (rho_1 * rho_1)), 0f)));
    return max((z - 0.8660254f), 0f);
}

fn eye_cornea_normal_k18_(xy: vec2<f32>) -> vec3<f32> {
    let z_1 = sqrt(max((0.35755965f - dot(xy, xy)), 0f));
    return (vec3<f32>(xy, z_1) / vec3(0.5979629f));
}

fn eye_parallax_k13_(p: vec3<f32>, v_4: vec3<f32>) -> EyeLookup {
    var local_1: bool;

    let rho_3 = length(p.xy);
    if !((p.z <= 0f)) {
        local_1 = (rho_3 >= 0.5f);
    } else {
        local_1 = true;
    }
    let _e15 = local_1;
    if _e15 {
        return EyeLookup(p.xy, p, 0f);
    }
    let _e21 = eye_cornea_height_k17_(rho_3);
    let d_1 = ((0.8660254f + _e21) - p.z);
    let e_raw = (p.xy + (d_1 * v_4.xy));
    let e_1 = (e_raw * min(1f, (0.5f / max(length(e_raw), 0.000001f))));
    let _e37 = eye_cornea_height_k17_(length(e_1));
    let _e38 = eye_cornea_normal_k18_(e_1);
    let iris_1 = (e_1 - (_e37 * ((v_4.xy * 0.7267442f) + (_e38.xy * 0.27325583f))));
    return EyeLookup(iris_1, _e38, 1f);
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var color: vec3<f32>;
    var look: EyeLookup;

    let model_1 = weft_object.model;
    let model3_1 = mat3x3<f32>(model_1[0].xyz, model_1[1].xyz, model_1[2].xyz);
    let nm_1 = weft_object.normal_matrix;
    let normal3_2 = mat3x3<f32>(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    let _e23 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_5 = _e23.v;
    let n_2 = _e23.n;
    let _e26 = weft_main_light_direction();
    let _e29 = weft_safe_normalize_k1_((transpose(model3_1) * n_2));
    let _e32 = weft_safe_normalize_k1_((transpose(normal3_2) * v_5));
    let _e35 = weft_safe_normalize((model3_1 * vec3<f32>(0f, 0f, 1f)), n_2);
    let dimming = (1f - (0.5f * saturate(-(dot(_e35, _e26)))));
    let _e43 = weft_main_light_radiance();
    {
        {
            let _e48 = eye_parallax_k13_(_e29, _e32);
            look = _e48;
        }
        let _e49 = look;
        let _e50 = eye_physical_k7_(_e49, n_2, v_5, _e26, normal3_2, _e43);
        color = _e50;
    }
    let _e51 = color;
    let radiance = clamp((_e51 * dimming), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
