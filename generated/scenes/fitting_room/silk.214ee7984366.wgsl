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

fn weft_safe_normalize_k8_(v_1: vec3<f32>) -> vec3<f32> {
    let len2_1 = dot(v_1, v_1);
    return select(vec3<f32>(0f, 0f, 1f), (v_1 * inverseSqrt(max(len2_1, 0.00000000000000000001f))), (len2_1 > 0.00000000000000000001f));
}

fn weft_view_direction_k2_(world_position: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_frame.camera_position;
    let _e7 = weft_safe_normalize_k8_((_e4.xyz - world_position));
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

fn weft_aniso_to_frame(frame: mat3x3<f32>, x: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(frame[0], x), dot(frame[1], x), dot(frame[2], x));
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

fn weft_half_pow5_(x_1: f32) -> f32 {
    let x2_ = (x_1 * x_1);
    return ((x2_ * x2_) * x_1);
}

fn weft_half_f_schlick_k10_(v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_half_pow5_((1f - v_dot_h));
    return (vec3<f32>(0.14609632f, 0.10047833f, 0.11062463f) + (vec3<f32>(0.85390365f, 0.89952165f, 0.8893754f) * _e5));
}

fn silk_low_k7_(frame_2: mat3x3<f32>, n_spec: vec3<f32>, n_diff: vec3<f32>, v_5: vec3<f32>, n_dot_v_1: f32, v_dot_h_1: f32, n_dot_l_diffuse: f32, lobe_1: SilkLobe) -> vec3<f32> {
    let _e13 = weft_half_f_schlick_k10_(f32(v_dot_h_1));
    let kd = ((vec3(1f) - _e13) * (f32(n_dot_l_diffuse) * 0.31830987f));
    let direct = (((vec3<f32>(0.45638528f, 0.27391332f, 0.3144985f) * vec3<f32>(kd)) + (vec3<f32>(_e13) * lobe_1.value)) * vec3<f32>(3.2f, 3.05f, 2.8f));
    let _e28 = weft_env_brdf_lut(n_dot_v_1, lobe_1.ibl_roughness);
    let lut = saturate(_e28);
    let env_brdf_1 = ((vec3<f32>(0.14609632f, 0.10047833f, 0.11062463f) * f32(lut.x)) + vec3(f32(lut.y)));
    let ambient_kd_1 = max((vec3(1f) - env_brdf_1), vec3(0f));
    let _e42 = silk_lobe_anisotropy(lobe_1.alpha);
    let _e44 = weft_aniso_bent_normal(frame_2, v_5, _e42, lobe_1.ibl_roughness);
    let _e48 = weft_prefiltered_radiance(reflect(-(v_5), _e44), lobe_1.ibl_roughness);
    let _e51 = weft_sh_irradiance(n_diff);
    let indirect = ((_e48 * vec3<f32>(env_brdf_1)) + ((_e51 * vec3<f32>(ambient_kd_1)) * vec3<f32>(0.45638528f, 0.27391332f, 0.3144985f)));
    return clamp((direct + indirect), vec3(0f), vec3(65504f));
}

fn weft_normal_from_tangent_space_k11_(frame_3: mat3x3<f32>) -> vec3<f32> {
    let _e4 = weft_safe_normalize((frame_3 * vec3<f32>(vec2<f32>(0.002352977f, 0.002352977f), 1f)), frame_3[2]);
    return _e4;
}

fn silk_ward_bounded_k13_(v_6: vec3<f32>, l: vec3<f32>) -> f32 {
    var local: bool;

    let hv = (v_6 + l);
    let hn = max(hv.z, 0.0001f);
    let hn2_ = (hn * hn);
    let x_2 = (hv.x / 0.20215853f);
    let y = (hv.y / 0.047507256f);
    let f = ((dot(hv, hv) / ((0.030171847f * hn2_) * hn2_)) * exp((-(((x_2 * x_2) + (y * y))) / hn2_)));
    if (v_6.z > 0f) {
        local = (l.z > 0f);
    } else {
        local = false;
    }
    let _e35 = local;
    return select(0f, f, _e35);
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
    let v_7 = _e11.v;
    let n_geo = _e11.n;
    let _e15 = weft_tangent_frame(n_geo, in_1.world_tangent);
    let _e17 = weft_normal_from_tangent_space_k11_(_e15);
    fibre = _e15[0];
    let _e20 = fibre;
    let _e24 = weft_tangent_frame(_e17, vec4<f32>(_e20, in_1.world_tangent.w));
    let _e25 = weft_main_light_geometry(_e17, v_7);
    let _e26 = weft_aniso_to_frame(_e24, v_7);
    let _e28 = weft_aniso_to_frame(_e24, _e25.l);
    {
        lobe.alpha = vec2<f32>(0.20215853f, 0.047507256f);
        lobe.ibl_roughness = 0.3130495f;
        {
            let _e36 = silk_ward_bounded_k13_(_e26, _e28);
            lobe.value = (_e36 * _e25.n_dot_l);
        }
    }
    let n_dot_l_diffuse_1 = saturate(dot(n_geo, _e25.l));
    {
        let _e45 = lobe;
        let _e46 = silk_low_k7_(_e24, _e17, n_geo, v_7, _e25.n_dot_v, _e25.v_dot_h, n_dot_l_diffuse_1, _e45);
        return vec4<f32>(_e46, 1f);
    }
}
