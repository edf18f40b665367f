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

struct WeftOutlineVertex {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
}

struct WeftOutlineVaryings {
    @builtin(position) clip_position: vec4<f32>,
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
@group(1) @binding(4) 
var normal_map: texture_2d<f32>;
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

fn weft_any_perpendicular(n_1: vec3<f32>) -> vec3<f32> {
    let s = select(-1f, 1f, (n_1.z >= 0f));
    let a = (-1f / (s + n_1.z));
    let b = ((n_1.x * n_1.y) * a);
    return vec3<f32>((1f + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
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

fn weft_sh_irradiance(n_2: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    let sh = weft_frame.sh;
    e = (sh[0].xyz * 0.282095f);
    let _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603f * n_2.y)));
    let _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603f * n_2.z)));
    let _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603f * n_2.x)));
    let _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548f * n_2.x) * n_2.y)));
    let _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548f * n_2.y) * n_2.z)));
    let _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392f * (((3f * n_2.z) * n_2.z) - 1f))));
    let _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548f * n_2.x) * n_2.z)));
    let _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274f * ((n_2.x * n_2.x) - (n_2.y * n_2.y)))));
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

fn weft_main_light_geometry(n_3: vec3<f32>, v_2: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_2), n_3);
    let _e6 = weft_clamp_cos(dot(n_3, v_2));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_3, _e2)), saturate(dot(n_3, _e4)), saturate(dot(v_2, _e4)));
}

fn weft_forward_vertex(in_3: WeftVertexInput) -> WeftVaryings {
    var out_1: WeftVaryings;

    let model = weft_object.model;
    let model3_ = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm = weft_object.normal_matrix;
    let normal3_ = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = (model * vec4<f32>(in_3.position, 1f));
    let mirror = select(1f, -1f, (determinant(model3_) < 0f));
    let bitangent_sign = (select(1f, -1f, (in_3.tangent.w < 0f)) * mirror);
    let _e43 = weft_frame.view_proj;
    out_1.clip_position = (_e43 * vec4<f32>(world.xyz, 1f));
    out_1.world_position = world.xyz;
    let _e55 = weft_safe_normalize((normal3_ * in_3.normal), vec3(0f));
    out_1.world_normal = _e55;
    let _e62 = weft_safe_normalize((model3_ * in_3.tangent.xyz), vec3(0f));
    out_1.world_tangent = vec4<f32>(_e62, bitangent_sign);
    out_1.uv0_ = in_3.uv0_;
    let _e66 = out_1;
    return _e66;
}

fn weft_tangent_frame(n_4: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_4 * dot(n_4, t_in)));
    let len2_1 = dot(t_proj, t_proj);
    let ok = (len2_1 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_4);
    let t = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_4, t) * s_1);
    return mat3x3<f32>(t, b_1, n_4);
}

fn weft_unpack_normal(texel: vec3<f32>, strength: f32) -> vec3<f32> {
    let v_3 = ((texel * 2f) - vec3(1f));
    return vec3<f32>((v_3.xy * strength), max(v_3.z, 0.001f));
}

fn weft_normal_from_tangent_space(frame: mat3x3<f32>, n_ts: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_safe_normalize((frame * n_ts), frame[2]);
    return _e4;
}

fn weft_mapped_normal(n_5: vec3<f32>, tangent_1: vec4<f32>, texel_1: vec3<f32>, strength_1: f32) -> vec3<f32> {
    let _e4 = weft_tangent_frame(n_5, tangent_1);
    let _e5 = weft_unpack_normal(texel_1, strength_1);
    let _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
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
    let t_1 = ((1f - r) * (1f - r));
    let a_1 = mix(21.5473f, 25.3245f, t_1);
    let b_2 = mix(3.82987f, 3.32435f, t_1);
    let c_2 = mix(0.19823f, 0.16801f, t_1);
    let d = mix(-1.9776f, -1.27393f, t_1);
    let e_1 = mix(-4.32054f, -4.85967f, t_1);
    return (((a_1 / (1f + (b_2 * pow(max(x, 0f), c_2)))) + (d * x)) + e_1);
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

fn weft_sheen_albedo_scaling_view(sheen_color_1: vec3<f32>, e_v: f32) -> f32 {
    let _e2 = weft_max3_(sheen_color_1);
    return saturate((1f - (saturate(_e2) * saturate(e_v))));
}

fn weft_sheen_albedo(n_dot_x: f32, sheen_roughness_4: f32) -> f32 {
    let _e3 = weft_sheen_clamp_roughness(sheen_roughness_4);
    let uv_1 = vec2<f32>(saturate(n_dot_x), _e3);
    let _e8 = textureSampleLevel(weft_sheen_lut, weft_lut_sampler, uv_1, 0f);
    return saturate(_e8.x);
}

@vertex 
fn vs_outline(in: WeftOutlineVertex) -> WeftOutlineVaryings {
    var local: bool;
    var local_1: bool;
    var out: WeftOutlineVaryings;

    let _e3 = weft_object.model;
    let world_1 = (_e3 * vec4<f32>(in.position, 1f));
    let nm_1 = weft_object.normal_matrix;
    let normal = (mat3x3<f32>(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz) * in.normal);
    let _e22 = weft_frame.view_proj;
    let clip = (_e22 * vec4<f32>(world_1.xyz, 1f));
    let _e29 = weft_frame.viewport;
    let size = _e29.xy;
    let _e33 = weft_frame.view_proj;
    let screen_normal = ((_e33 * vec4<f32>(normal, 0f)).xy * size);
    let len = length(screen_normal);
    if (len > 0.000001f) {
        let _e47 = weft_frame.viewport.x;
        local = (_e47 > 0f);
    } else {
        local = false;
    }
    let _e51 = local;
    if _e51 {
        local_1 = (clip.w > 0f);
    } else {
        local_1 = false;
    }
    let usable = local_1;
    let direction = select(vec2(0f), (screen_normal / vec2(max(len, 0.000001f))), usable);
    let _e68 = material.outline_width;
    let width_px = max(_e68, 0f);
    let _e74 = material.outline_max_distance;
    let distance_ = min(clip.w, max(_e74, 0f));
    let _e83 = weft_frame.viewport;
    let offset = ((((direction * width_px) * 2f) * _e83.zw) * distance_);
    out.clip_position = vec4<f32>((clip.xy + offset), clip.zw);
    let _e93 = out;
    return _e93;
}

@fragment 
fn fs_outline() -> @location(0) vec4<f32> {
    let _e2 = material.outline_color;
    return vec4<f32>(max(_e2.xyz, vec3(0f)), 1f);
}

@vertex 
fn vs_main(in_1: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in_1);
    return _e1;
}

@fragment 
fn fs_main(in_2: WeftVaryings) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var color: vec3<f32>;
    var sheen: vec3<f32>;
    var scaling: f32;

    let _e4 = material.base_map_st;
    let _e5 = weft_transform_uv(in_2.uv0_, _e4);
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
    let _e39 = weft_surface(in_2.world_position, in_2.world_normal);
    let v_4 = _e39.v;
    n = _e39.n;
    {
        let _e45 = textureSample(normal_map, material_sampler, _e5);
        let texel_2 = _e45.xyz;
        let _e47 = n;
        let _e51 = material.normal_strength;
        let _e52 = weft_mapped_normal(_e47, in_2.world_tangent, texel_2, _e51);
        n = _e52;
    }
    let _e53 = n;
    let _e54 = weft_main_light_geometry(_e53, v_4);
    let l_dot_h = saturate(dot(_e54.l, _e54.h));
    let f0_ = mix(vec3(0.04f), base, metallic);
    let diffuse_albedo = (base * (1f - metallic));
    let _e65 = weft_main_light_radiance();
    let _e66 = n;
    let _e67 = weft_sh_irradiance(_e66);
    let ambient = (_e67 * ao);
    {
        let _e72 = material.scatter_color;
        let sheen_color_2 = saturate((f0_ + max(_e72.xyz, vec3(0f))));
        let _e79 = weft_sheen_clamp_roughness(roughness_2);
        let _e81 = weft_sheen_albedo(_e54.n_dot_v, _e79);
        let _e82 = weft_sheen_albedo_scaling_view(sheen_color_2, _e81);
        {
            let _e88 = weft_sheen_charlie(sheen_color_2, _e54.n_dot_h, _e54.n_dot_v, _e54.n_dot_l, _e79);
            sheen = _e88;
            scaling = _e82;
        }
        let _e89 = weft_diffuse_lambert(diffuse_albedo);
        let _e90 = scaling;
        let base_direct = (_e89 * (_e90 * _e54.n_dot_l));
        let _e94 = sheen;
        let direct = ((_e94 + base_direct) * _e65);
        let _e98 = n;
        let _e100 = weft_prefiltered_radiance(reflect(-(v_4), _e98), _e79);
        let env_sheen = ((_e100 * sheen_color_2) * (_e81 * ao));
        color = ((direct + ((ambient * diffuse_albedo) * _e82)) + env_sheen);
    }
    let _e108 = color;
    let radiance = clamp(_e108, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
