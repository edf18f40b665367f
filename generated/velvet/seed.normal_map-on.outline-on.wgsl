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

fn weft_pow4_(x: f32) -> f32 {
    let x2_ = (x * x);
    return (x2_ * x2_);
}

fn weft_pow5_(x_1: f32) -> f32 {
    let x2_1 = (x_1 * x_1);
    return ((x2_1 * x2_1) * x_1);
}

fn weft_clamp_cos(c: f32) -> f32 {
    return clamp(c, WEFT_MIN_N_DOT, 1f);
}

fn weft_clamp_roughness(roughness: f32) -> f32 {
    return clamp(roughness, WEFT_MIN_ROUGHNESS, 1f);
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

fn weft_f_schlick(f0_: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (f0_ + ((vec3(1f) - f0_) * _e5));
}

fn weft_v_schlick_ggx(n_dot_v: f32, n_dot_l: f32, roughness_1: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_1);
    let a_1 = (_e3 * _e3);
    let k = (((a_1 + 1f) * (a_1 + 1f)) * 0.125f);
    let gv = ((saturate(n_dot_v) * (1f - k)) + k);
    let gl = ((saturate(n_dot_l) * (1f - k)) + k);
    return (0.25f / (gv * gl));
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

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_main_light_geometry(n_3: vec3<f32>, v_1: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_1), n_3);
    let _e6 = weft_clamp_cos(dot(n_3, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_3, _e2)), saturate(dot(n_3, _e4)), saturate(dot(v_1, _e4)));
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
    let v_2 = ((texel * 2f) - vec3(1f));
    return vec3<f32>((v_2.xy * strength), max(v_2.z, 0.001f));
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

fn weft_fabric_d(n_dot_h: f32) -> f32 {
    let x_2 = (1f - saturate(n_dot_h));
    return (((0.96f * x_2) * x_2) + 0.057f);
}

fn weft_fabric_scatter_fresnel_lerp(n_dot_v_1: f32, scale: f32) -> f32 {
    let x_3 = (1f - saturate(n_dot_v_1));
    let _e5 = weft_pow4_(x_3);
    return mix(_e5, (0.4f * x_3), saturate(scale));
}

fn weft_fabric_scatter(scatter_color: vec3<f32>, n_dot_l_1: f32, n_dot_v_2: f32, scale_1: f32) -> vec3<f32> {
    let wrap = ((saturate(n_dot_l_1) * 0.5f) + 0.5f);
    let _e12 = weft_fabric_scatter_fresnel_lerp(n_dot_v_2, scale_1);
    return (max(scatter_color, vec3(0f)) * (wrap * _e12));
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
    let v_3 = _e39.v;
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
    let _e54 = weft_main_light_geometry(_e53, v_3);
    let l_dot_h = saturate(dot(_e54.l, _e54.h));
    let f0_1 = mix(vec3(0.04f), base, metallic);
    let diffuse_albedo = (base * (1f - metallic));
    let _e65 = weft_main_light_radiance();
    let _e66 = n;
    let _e67 = weft_sh_irradiance(_e66);
    let ambient = (_e67 * ao);
    {
        let _e72 = weft_v_schlick_ggx(_e54.n_dot_v, _e54.n_dot_l, roughness_2);
        let _e73 = weft_f_schlick(f0_1, l_dot_h);
        let _e75 = weft_fabric_d(_e54.n_dot_h);
        let specular = ((_e75 * _e72) * _e73);
        let _e78 = weft_diffuse_lambert(diffuse_albedo);
        let direct = (((_e78 + specular) * _e65) * _e54.n_dot_l);
        let _e85 = material.scatter_color;
        let _e91 = material.scatter_scale;
        let _e92 = weft_fabric_scatter(_e85.xyz, _e54.n_dot_l, _e54.n_dot_v, _e91);
        color = ((direct + (ambient * diffuse_albedo)) + _e92);
    }
    let _e96 = color;
    let radiance = clamp(_e96, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
