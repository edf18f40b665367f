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

struct WeftMaterial {
    base_color: vec4<f32>,
    base_map_st: vec4<f32>,
    smoothness: f32,
    metallic: f32,
    diffuse_uses_aniso_normal: u32,
    anisotropy: f32,
    aniso_normal_map_st: vec4<f32>,
    aniso_normal_strength: f32,
    tangent_shift: f32,
    aniso_gloss: f32,
    aniso_spec: f32,
    aniso_mask: f32,
    flow_strength: f32,
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
@group(2) @binding(0) 
var<uniform> weft_object: WeftObject;
@group(1) @binding(0) 
var<uniform> material: WeftMaterial;
@group(1) @binding(1) 
var material_sampler: sampler;
@group(1) @binding(3) 
var base_map: texture_2d<f32>;
@group(1) @binding(4) 
var aniso_normal_map: texture_2d<f32>;

fn weft_pow4_(x: f32) -> f32 {
    let x2_ = (x * x);
    return (x2_ * x2_);
}

fn weft_pow5_(x_1: f32) -> f32 {
    let x2_1 = (x_1 * x_1);
    return ((x2_1 * x2_1) * x_1);
}

fn weft_max3_(v: vec3<f32>) -> f32 {
    return max(v.x, max(v.y, v.z));
}

fn weft_clamp_cos(c: f32) -> f32 {
    return clamp(c, WEFT_MIN_N_DOT, 1f);
}

fn weft_clamp_roughness(roughness: f32) -> f32 {
    return clamp(roughness, WEFT_MIN_ROUGHNESS, 1f);
}

fn weft_safe_normalize(v_1: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v_1, v_1);
    return select(fallback, (v_1 * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_any_perpendicular(n: vec3<f32>) -> vec3<f32> {
    let s = select(-1f, 1f, (n.z >= 0f));
    let a = (-1f / (s + n.z));
    let b = ((n.x * n.y) * a);
    return vec3<f32>((1f + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
}

fn weft_d_ggx(n_dot_h: f32, roughness_1: f32) -> f32 {
    let _e2 = weft_clamp_roughness(roughness_1);
    let a_1 = (_e2 * _e2);
    let a2_ = (a_1 * a_1);
    let noh = saturate(n_dot_h);
    let one_minus_noh2_ = ((1f - noh) * (1f + noh));
    let d = (one_minus_noh2_ + ((noh * noh) * a2_));
    return (a2_ / ((WEFT_PI * d) * d));
}

fn weft_f_schlick(f0_: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (f0_ + ((vec3(1f) - f0_) * _e5));
}

fn weft_f_schlick_roughness(f0_1: vec3<f32>, n_dot_v: f32, roughness_2: f32) -> vec3<f32> {
    let _e6 = weft_pow5_((1f - saturate(n_dot_v)));
    let f90_ = max(vec3((1f - saturate(roughness_2))), f0_1);
    return (f0_1 + ((f90_ - f0_1) * _e6));
}

fn weft_v_schlick_ggx(n_dot_v_1: f32, n_dot_l: f32, roughness_3: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_3);
    let a_2 = (_e3 * _e3);
    let k = (((a_2 + 1f) * (a_2 + 1f)) * 0.125f);
    let gv = ((saturate(n_dot_v_1) * (1f - k)) + k);
    let gl = ((saturate(n_dot_l) * (1f - k)) + k);
    return (0.25f / (gv * gl));
}

fn weft_diffuse_lambert(albedo: vec3<f32>) -> vec3<f32> {
    return (albedo * WEFT_INV_PI);
}

fn weft_env_brdf_approx(f0_2: vec3<f32>, n_dot_v_2: f32, roughness_4: f32) -> vec3<f32> {
    let r = saturate(roughness_4);
    let surface_reduction = (1f / ((r * r) + 1f));
    let _e9 = weft_max3_(f0_2);
    let grazing = saturate((_e9 + (1f - r)));
    let _e17 = weft_pow4_((1f - saturate(n_dot_v_2)));
    return (mix(f0_2, vec3(grazing), _e17) * surface_reduction);
}

fn weft_main_light_direction() -> vec3<f32> {
    let _e2 = weft_frame.light_direction;
    let _e8 = weft_safe_normalize(_e2.xyz, vec3<f32>(0f, 0f, 1f));
    return _e8;
}

fn weft_main_light_radiance() -> vec3<f32> {
    let _e2 = weft_frame.light_color;
    return max(_e2.xyz, vec3(0f));
}

fn weft_view_direction(world_position: vec3<f32>, fallback_1: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_frame.camera_position;
    let _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
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

fn weft_specular_mip(roughness_5: f32) -> f32 {
    let r_1 = saturate(roughness_5);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r_1 * (1.7f - (0.7f * r_1))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_6: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_6);
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_main_light_geometry(n_2: vec3<f32>, v_2: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_2), n_2);
    let _e6 = weft_clamp_cos(dot(n_2, v_2));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_2, _e2)), saturate(dot(n_2, _e4)), saturate(dot(v_2, _e4)));
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
    let _e55 = weft_safe_normalize((normal3_ * in_2.normal), vec3(0f));
    out.world_normal = _e55;
    let _e62 = weft_safe_normalize((model3_ * in_2.tangent.xyz), vec3(0f));
    out.world_tangent = vec4<f32>(_e62, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    let _e66 = out;
    return _e66;
}

fn weft_tangent_frame(n_3: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_3 * dot(n_3, t_in)));
    let len2_1 = dot(t_proj, t_proj);
    let ok = (len2_1 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_3);
    let t_1 = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_3, t_1) * s_1);
    return mat3x3<f32>(t_1, b_1, n_3);
}

fn weft_unpack_normal(texel: vec3<f32>, strength: f32) -> vec3<f32> {
    let v_3 = ((texel * 2f) - vec3(1f));
    return vec3<f32>((v_3.xy * strength), max(v_3.z, 0.001f));
}

fn weft_normal_from_tangent_space(frame: mat3x3<f32>, n_ts: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_safe_normalize((frame * n_ts), frame[2]);
    return _e4;
}

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn weft_aniso_to_frame(frame_1: mat3x3<f32>, x_2: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(frame_1[0], x_2), dot(frame_1[1], x_2), dot(frame_1[2], x_2));
}

fn silk_jitter_tangent(t: vec3<f32>, n_4: vec3<f32>, shift: f32) -> vec3<f32> {
    let _e5 = weft_safe_normalize((t + (shift * n_4)), t);
    return _e5;
}

fn silk_hair_mx_seed(smoothness: f32, gloss: f32) -> f32 {
    let p = (1f - saturate((smoothness * gloss)));
    let rx = (p * p);
    let rx_safe = select(rx, 0.0001f, (rx == 0f));
    return (rx_safe * rx_safe);
}

fn silk_hair_d_seed(x_axis: vec3<f32>, n_5: vec3<f32>, h: vec3<f32>, mx: f32) -> f32 {
    let m = max(mx, 0.00000001f);
    let y_axis = cross(n_5, x_axis);
    let xh = dot(x_axis, h);
    let yh = dot(y_axis, h);
    let nh = saturate(dot(n_5, h));
    let d_1 = max(((((xh * xh) / (m * m)) + (yh * yh)) + (nh * nh)), 0.0001f);
    return (1f / (((WEFT_PI * m) * d_1) * d_1));
}

fn silk_ibl_roughness(alpha: vec2<f32>) -> f32 {
    return saturate(sqrt(sqrt(max((alpha.x * alpha.y), 0f))));
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

    let _e4 = material.base_map_st;
    let _e5 = weft_transform_uv(in_1.uv0_, _e4);
    let _e8 = material.base_color;
    let _e11 = textureSample(base_map, material_sampler, _e5);
    let base_rgba = (_e8 * _e11);
    let base = saturate(base_rgba.xyz);
    let alpha_out = saturate(base_rgba.w);
    let _e19 = material.smoothness;
    let smoothness_1 = saturate(_e19);
    let roughness_7 = (1f - smoothness_1);
    let _e25 = material.metallic;
    let metallic = saturate(_e25);
    let f0_3 = mix(vec3(0.04f), base, metallic);
    let diffuse_albedo = (base * (1f - metallic));
    let _e35 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_4 = _e35.v;
    let n_geo = _e35.n;
    let _e39 = weft_tangent_frame(n_geo, in_1.world_tangent);
    let _e43 = material.aniso_normal_map_st;
    let _e44 = weft_transform_uv(in_1.uv0_, _e43);
    let _e47 = textureSample(aniso_normal_map, material_sampler, _e44);
    let texel_1 = _e47.xyz;
    let _e51 = material.aniso_normal_strength;
    let _e52 = weft_unpack_normal(texel_1, _e51);
    let _e53 = weft_normal_from_tangent_space(_e39, _e52);
    fibre = _e39[0];
    let _e56 = fibre;
    let _e60 = weft_tangent_frame(_e53, vec4<f32>(_e56, in_1.world_tangent.w));
    let _e63 = material.diffuse_uses_aniso_normal;
    let n_diff = select(n_geo, _e53, (_e63 != 0u));
    let _e67 = weft_main_light_geometry(_e53, v_4);
    let _e68 = weft_aniso_to_frame(_e60, v_4);
    let _e70 = weft_aniso_to_frame(_e60, _e67.l);
    let _e72 = weft_aniso_to_frame(_e60, _e67.h);
    let k_1 = material.anisotropy;
    {
        {
            let _e79 = material.aniso_gloss;
            let _e80 = silk_hair_mx_seed(smoothness_1, _e79);
            let _e83 = material.aniso_mask;
            let mask = saturate(_e83);
            let _e87 = material.aniso_spec;
            let spec_scale = mix(max(_e87, 0f), 1f, mask);
            let a_hair = vec2<f32>(max(_e80, SILK_MIN_ALPHA), 1f);
            let _e96 = weft_clamp_roughness(roughness_7);
            let _e97 = weft_clamp_roughness(roughness_7);
            let a_iso = (_e96 * _e97);
            lobe.alpha = mix(a_hair, vec2(a_iso), mask);
            let _e103 = silk_ibl_roughness(a_hair);
            lobe.ibl_roughness = mix(_e103, roughness_7, mask);
            {
                let _e109 = material.tangent_shift;
                let _e110 = silk_jitter_tangent(_e60[0], _e60[2], _e109);
                let _e113 = silk_hair_d_seed(_e110, _e60[2], _e67.h, _e80);
                let _e115 = weft_d_ggx(_e67.n_dot_h, roughness_7);
                let d_2 = (mix(_e113, _e115, mask) * spec_scale);
                let _e121 = weft_v_schlick_ggx(_e67.n_dot_v, _e67.n_dot_l, roughness_7);
                lobe.value = ((d_2 * _e121) * _e67.n_dot_l);
            }
        }
    }
    let _e125 = weft_main_light_radiance();
    let n_dot_l_diffuse = saturate(dot(n_diff, _e67.l));
    let _e130 = weft_f_schlick(f0_3, _e67.v_dot_h);
    let _e134 = weft_diffuse_lambert(diffuse_albedo);
    let diffuse = (((vec3(1f) - _e130) * _e134) * n_dot_l_diffuse);
    let _e138 = lobe.value;
    let direct = ((diffuse + (_e130 * _e138)) * _e125);
    reflect_n = _e53;
    {
        let _e147 = lobe.ibl_roughness;
        let _e148 = weft_env_brdf_approx(f0_3, _e67.n_dot_v, _e147);
        env_brdf = _e148;
        let _e153 = lobe.ibl_roughness;
        let _e154 = weft_f_schlick_roughness(f0_3, _e67.n_dot_v, _e153);
        ambient_kd = (vec3(1f) - _e154);
    }
    let _e157 = reflect_n;
    let _e160 = lobe.ibl_roughness;
    let _e161 = weft_prefiltered_radiance(reflect(-(v_4), _e157), _e160);
    let _e162 = env_brdf;
    let _e164 = weft_sh_irradiance(n_diff);
    let _e165 = ambient_kd;
    let indirect = ((_e161 * _e162) + ((_e164 * _e165) * diffuse_albedo));
    let radiance = clamp((direct + indirect), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha_out);
}
