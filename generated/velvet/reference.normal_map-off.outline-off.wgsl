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
    metallic: f32,
    smoothness: f32,
    base_map_st: vec4<f32>,
    normal_strength: f32,
    occlusion_strength: f32,
    scatter_color: vec4<f32>,
    scatter_scale: f32,
    outline_color: vec4<f32>,
    outline_width: f32,
    outline_max_distance: f32,
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
@group(1) @binding(0) 
var<uniform> material: WeftMaterial;
@group(1) @binding(1) 
var material_sampler: sampler;
@group(1) @binding(3) 
var base_map: texture_2d<f32>;
@group(1) @binding(5) 
var occlusion_map: texture_2d<f32>;

fn weft_max3_(v: vec3<f32>) -> f32 {
    return max(v.x, max(v.y, v.z));
}

fn weft_clamp_cos(c: f32) -> f32 {
    return clamp(c, WEFT_MIN_N_DOT, 1f);
}

fn weft_safe_normalize(v_1: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v_1, v_1);
    return select(fallback, (v_1 * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_diffuse_lambert(albedo: vec3<f32>) -> vec3<f32> {
    return (albedo * WEFT_INV_PI);
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

fn weft_specular_mip(roughness: f32) -> f32 {
    let r_2 = saturate(roughness);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r_2 * (1.7f - (0.7f * r_2))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_1: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_1);
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

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn weft_sheen_clamp_roughness(sheen_roughness: f32) -> f32 {
    return clamp(sheen_roughness, WEFT_SHEEN_MIN_ROUGHNESS, 1f);
}

fn weft_d_charlie(n_dot_h: f32, sheen_roughness_1: f32) -> f32 {
    let _e2 = weft_sheen_clamp_roughness(sheen_roughness_1);
    let inv_r = (1f / _e2);
    let noh = saturate(n_dot_h);
    let sin2_ = max(((1f - noh) * (1f + noh)), 0f);
    return (((2f + inv_r) * pow(sin2_, (0.5f * inv_r))) * 0.15915494f);
}

fn weft_sheen_l(x: f32, r: f32) -> f32 {
    let t = ((1f - r) * (1f - r));
    let a = mix(21.5473f, 25.3245f, t);
    let b = mix(3.82987f, 3.32435f, t);
    let c_2 = mix(0.19823f, 0.16801f, t);
    let d = mix(-1.9776f, -1.27393f, t);
    let e_1 = mix(-4.32054f, -4.85967f, t);
    return (((a / (1f + (b * pow(max(x, 0f), c_2)))) + (d * x)) + e_1);
}

fn weft_sheen_lambda_one_exp(cos_theta: f32, r_1: f32) -> f32 {
    let _e2 = weft_clamp_cos(cos_theta);
    let low = (_e2 < 0.5f);
    let _e8 = weft_sheen_l(select((1f - _e2), _e2, low), r_1);
    let _e10 = weft_sheen_l(0.5f, r_1);
    return exp(select(((2f * _e10) - _e8), _e8, low));
}

fn weft_v_charlie(n_dot_v: f32, n_dot_l: f32, sheen_roughness_2: f32) -> f32 {
    let _e3 = weft_sheen_clamp_roughness(sheen_roughness_2);
    let _e4 = weft_clamp_cos(n_dot_v);
    let _e5 = weft_clamp_cos(n_dot_l);
    let _e6 = weft_sheen_lambda_one_exp(_e4, _e3);
    let _e9 = weft_sheen_lambda_one_exp(_e5, _e3);
    let g_inv = ((1f + _e6) + _e9);
    return (1f / (((g_inv * 4f) * _e4) * _e5));
}

fn weft_sheen_charlie(sheen_color: vec3<f32>, n_dot_h_1: f32, n_dot_v_1: f32, n_dot_l_1: f32, sheen_roughness_3: f32) -> vec3<f32> {
    let _e5 = weft_d_charlie(n_dot_h_1, sheen_roughness_3);
    let _e6 = weft_v_charlie(n_dot_v_1, n_dot_l_1, sheen_roughness_3);
    let lobe = (_e5 * _e6);
    return (max(sheen_color, vec3(0f)) * (lobe * saturate(n_dot_l_1)));
}

fn weft_sheen_albedo_scaling(sheen_color_1: vec3<f32>, e_v: f32, e_l: f32) -> f32 {
    let _e3 = weft_max3_(sheen_color_1);
    let c_3 = saturate(_e3);
    return saturate(min((1f - (c_3 * saturate(e_v))), (1f - (c_3 * saturate(e_l)))));
}

fn weft_sheen_albedo_scaling_view(sheen_color_2: vec3<f32>, e_v_1: f32) -> f32 {
    let _e2 = weft_max3_(sheen_color_2);
    return saturate((1f - (saturate(_e2) * saturate(e_v_1))));
}

fn weft_sheen_albedo(n_dot_x: f32, sheen_roughness_4: f32) -> f32 {
    let _e3 = weft_sheen_clamp_roughness(sheen_roughness_4);
    let uv_1 = vec2<f32>(saturate(n_dot_x), _e3);
    let _e8 = textureSampleLevel(weft_sheen_lut, weft_lut_sampler, uv_1, 0f);
    return saturate(_e8.x);
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

    let _e4 = material.base_map_st;
    let _e5 = weft_transform_uv(in_1.uv0_, _e4);
    let _e8 = material.base_color;
    let _e11 = textureSample(base_map, material_sampler, _e5);
    let base_rgba = (_e8 * _e11);
    let base = saturate(base_rgba.xyz);
    let alpha = saturate(base_rgba.w);
    let _e19 = material.metallic;
    let metallic = saturate(_e19);
    let _e23 = material.smoothness;
    let smoothness = saturate(_e23);
    let roughness_2 = (1f - smoothness);
    let _e29 = textureSample(occlusion_map, material_sampler, _e5);
    let occlusion = _e29.x;
    let _e33 = material.occlusion_strength;
    let ao = saturate(mix(1f, occlusion, _e33));
    let _e39 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_3 = _e39.v;
    n = _e39.n;
    let _e43 = n;
    let _e44 = weft_main_light_geometry(_e43, v_3);
    let l_dot_h = saturate(dot(_e44.l, _e44.h));
    let f0_ = mix(vec3(0.04f), base, metallic);
    let diffuse_albedo = (base * (1f - metallic));
    let _e55 = weft_main_light_radiance();
    let _e56 = n;
    let _e57 = weft_sh_irradiance(_e56);
    let ambient = (_e57 * ao);
    {
        let _e62 = material.scatter_color;
        let sheen_color_3 = saturate((f0_ + max(_e62.xyz, vec3(0f))));
        let _e69 = weft_sheen_clamp_roughness(roughness_2);
        let _e71 = weft_sheen_albedo(_e44.n_dot_v, _e69);
        let _e72 = weft_sheen_albedo_scaling_view(sheen_color_3, _e71);
        {
            let _e76 = weft_sheen_albedo(_e44.n_dot_l, _e69);
            let _e80 = weft_sheen_charlie(sheen_color_3, _e44.n_dot_h, _e44.n_dot_v, _e44.n_dot_l, _e69);
            sheen = _e80;
            let _e81 = weft_sheen_albedo_scaling(sheen_color_3, _e71, _e76);
            scaling = _e81;
        }
        let _e82 = weft_diffuse_lambert(diffuse_albedo);
        let _e83 = scaling;
        let base_direct = (_e82 * (_e83 * _e44.n_dot_l));
        let _e87 = sheen;
        let direct = ((_e87 + base_direct) * _e55);
        let _e91 = n;
        let _e93 = weft_prefiltered_radiance(reflect(-(v_3), _e91), _e69);
        let env_sheen = ((_e93 * sheen_color_3) * (_e71 * ao));
        color = ((direct + ((ambient * diffuse_albedo) * _e72)) + env_sheen);
    }
    let _e101 = color;
    let radiance = clamp(_e101, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
