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
    metallic: f32,
    smoothness: f32,
    spot_color: vec4<f32>,
    noise_map_st: vec4<f32>,
    strand_density: vec2<f32>,
    fur_length: f32,
    height_scale: f32,
    fur_occlusion: f32,
    cutoff_start: f32,
    cutoff_end: f32,
    edge_fade: f32,
    tapered_tips: u32,
    shell_count: i32,
    force_direction: vec3<f32>,
    force_strength: f32,
    force_map_scale: f32,
    sheen_color: vec4<f32>,
    scatter_scale: f32,
    strand_color: vec4<f32>,
    strand_strength: f32,
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

struct FurInput {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(3) uv0_: vec2<f32>,
}

struct FurVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) strand: vec3<f32>,
    @location(3) uv0_: vec2<f32>,
    @location(4) offset: f32,
    @location(5) light_diffuse: vec4<f32>,
    @location(6) light_ambient: vec4<f32>,
    @location(7) light_sheen: vec4<f32>,
    @location(8) light_strand: vec4<f32>,
    @location(9) light_n_dot_v: f32,
}

struct FurLight {
    diffuse: vec4<f32>,
    ambient: vec4<f32>,
    sheen: vec4<f32>,
    strand: vec4<f32>,
    n_dot_v: f32,
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
const FUR_SEED_SHELLS: f32 = 20f;

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
var spot_map: texture_2d<f32>;
@group(1) @binding(5) 
var noise_map: texture_2d<f32>;
@group(1) @binding(6) 
var height_map: texture_2d<f32>;
@group(1) @binding(7) 
var force_map: texture_2d<f32>;

fn weft_pow5_(x: f32) -> f32 {
    let x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

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

fn weft_sheen_l(x_1: f32, r: f32) -> f32 {
    let t = ((1f - r) * (1f - r));
    let a = mix(21.5473f, 25.3245f, t);
    let b = mix(3.82987f, 3.32435f, t);
    let c_1 = mix(0.19823f, 0.16801f, t);
    let d = mix(-1.9776f, -1.27393f, t);
    let e_1 = mix(-4.32054f, -4.85967f, t);
    return (((a / (1f + (b * pow(max(x_1, 0f), c_1)))) + (d * x_1)) + e_1);
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
    let c_2 = saturate(_e3);
    return saturate(min((1f - (c_2 * saturate(e_v))), (1f - (c_2 * saturate(e_l)))));
}

fn weft_sheen_albedo_scaling_view(sheen_color_2: vec3<f32>, e_v_1: f32) -> f32 {
    let _e2 = weft_max3_(sheen_color_2);
    return saturate((1f - (saturate(_e2) * saturate(e_v_1))));
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

fn weft_specular_mip(roughness: f32) -> f32 {
    let r_2 = saturate(roughness);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r_2 * (1.7f - (0.7f * r_2))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_1: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_1);
    let c_3 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_3.xyz, vec3(0f));
}

fn weft_sheen_albedo(n_dot_x: f32, sheen_roughness_4: f32) -> f32 {
    let _e3 = weft_sheen_clamp_roughness(sheen_roughness_4);
    let uv_1 = vec2<f32>(saturate(n_dot_x), _e3);
    let _e8 = textureSampleLevel(weft_sheen_lut, weft_lut_sampler, uv_1, 0f);
    return saturate(_e8.x);
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_main_light_geometry(n_1: vec3<f32>, v_2: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_2), n_1);
    let _e6 = weft_clamp_cos(dot(n_1, v_2));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_1, _e2)), saturate(dot(n_1, _e4)), saturate(dot(v_2, _e4)));
}

fn fur_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn fur_strand_exponent(smoothness: f32) -> f32 {
    return exp2((1f + (9f * saturate(smoothness))));
}

fn fur_strand_norm(p: f32) -> f32 {
    return sqrt(((((2f * p) + 1f) * 0.25f) * WEFT_INV_PI));
}

fn fur_vertex_light(p_1: vec3<f32>, normal: vec3<f32>, strand: vec3<f32>) -> FurLight {
    var out: FurLight;

    let _e5 = material.smoothness;
    let smoothness_1 = saturate(_e5);
    let _e7 = weft_surface(p_1, normal);
    let v_3 = _e7.v;
    let n_2 = _e7.n;
    let _e10 = weft_safe_normalize(strand, n_2);
    let _e11 = weft_main_light_geometry(n_2, v_3);
    let _e12 = weft_main_light_radiance();
    let _e15 = weft_sheen_clamp_roughness((1f - smoothness_1));
    let _e17 = weft_sheen_albedo(_e11.n_dot_v, _e15);
    let _e19 = weft_sheen_albedo(_e11.n_dot_l, _e15);
    let _e25 = weft_sheen_charlie(vec3(1f), _e11.n_dot_h, _e11.n_dot_v, _e11.n_dot_l, _e15);
    let _e29 = weft_prefiltered_radiance(reflect(-(v_3), n_2), _e15);
    let sheen = ((_e25 * _e12) + (_e29 * _e17));
    let _e32 = fur_strand_exponent(smoothness_1);
    let t_dot_l = clamp(dot(_e10, _e11.l), -1f, 1f);
    let sin_l = sqrt(max((1f - (t_dot_l * t_dot_l)), 0f));
    let cone_angle = ((acos(t_dot_l) + acos(clamp(dot(_e10, v_3), -1f, 1f))) - WEFT_PI);
    let _e55 = material.strand_strength;
    let _e58 = fur_strand_norm(_e32);
    let lobe_1 = (((max(_e55, 0f) * _e58) * sin_l) * _e11.n_dot_l);
    out.diffuse = vec4<f32>((_e12 * (WEFT_INV_PI * _e11.n_dot_l)), _e17);
    let _e71 = weft_sh_irradiance(n_2);
    out.ambient = vec4<f32>(_e71, _e19);
    let _e80 = weft_pow5_((1f - saturate(dot(_e11.l, _e11.h))));
    out.sheen = vec4<f32>(sheen, _e80);
    out.strand = vec4<f32>((_e12 * lobe_1), cone_angle);
    out.n_dot_v = saturate(dot(n_2, v_3));
    let _e88 = out;
    return _e88;
}

fn fur_vertex(in_4: FurInput, offset: f32) -> FurVaryings {
    var out_1: FurVaryings;

    let model = weft_object.model;
    let nm = weft_object.normal_matrix;
    let normal3_ = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = (model * vec4<f32>(in_4.position, 1f)).xyz;
    let _e24 = weft_safe_normalize((normal3_ * in_4.normal), vec3(0f));
    let _e28 = material.base_map_st;
    let _e29 = fur_transform_uv(in_4.uv0_, _e28);
    let _e33 = textureSampleLevel(force_map, material_sampler, _e29, 0f);
    let force_texel = _e33.xyz;
    let _e37 = material.force_direction;
    let _e45 = material.force_map_scale;
    let force = (_e37 + (((force_texel * 2f) - vec3(1f)) * _e45));
    let _e50 = material.force_strength;
    let s = saturate(_e50);
    let target_dir = ((_e24 * (1f - s)) + (force * s));
    let _e60 = textureSampleLevel(height_map, material_sampler, _e29, 0f);
    let height = _e60.x;
    let _e64 = material.height_scale;
    let hs = saturate(_e64);
    let _e68 = material.fur_length;
    let len = (max(_e68, 0f) * max((1f + (hs * (saturate(height) - 1f))), 0f));
    let dir_1 = mix(_e24, target_dir, offset);
    let p_2 = (world + (dir_1 * (len * offset)));
    let _e88 = weft_frame.view_proj;
    out_1.clip_position = (_e88 * vec4<f32>(p_2, 1f));
    out_1.world_position = p_2;
    out_1.world_normal = _e24;
    out_1.strand = (_e24 + ((2f * offset) * (target_dir - _e24)));
    out_1.uv0_ = in_4.uv0_;
    out_1.offset = offset;
    {
        let _e104 = out_1.strand;
        let _e105 = fur_vertex_light(p_2, _e24, _e104);
        out_1.light_diffuse = _e105.diffuse;
        out_1.light_ambient = _e105.ambient;
        out_1.light_sheen = _e105.sheen;
        out_1.light_strand = _e105.strand;
        out_1.light_n_dot_v = _e105.n_dot_v;
    }
    let _e116 = out_1;
    return _e116;
}

fn fur_noise(uv0_: vec2<f32>) -> f32 {
    let _e3 = material.noise_map_st;
    let _e4 = fur_transform_uv(uv0_, _e3);
    {
        let _e7 = textureSample(noise_map, material_sampler, _e4);
        return saturate(_e7.x);
    }
}

fn fur_shade_fast(in_5: FurVaryings, base: vec3<f32>) -> vec3<f32> {
    let _e4 = material.metallic;
    let metallic = saturate(_e4);
    let f0_ = mix(vec3(0.04f), base, metallic);
    let diffuse_albedo = (base * (1f - metallic));
    let _e14 = material.sheen_color;
    let sheen_color_3 = saturate((f0_ + max(_e14.xyz, vec3(0f))));
    let _e25 = weft_sheen_albedo_scaling(sheen_color_3, in_5.light_diffuse.w, in_5.light_ambient.w);
    let _e28 = weft_sheen_albedo_scaling_view(sheen_color_3, in_5.light_diffuse.w);
    let fresnel = (f0_ + ((vec3(1f) - f0_) * in_5.light_sheen.w));
    let _e38 = material.strand_color;
    let strand_color = (max(_e38.xyz, vec3(0f)) * fresnel);
    let _e51 = material.smoothness;
    let _e52 = fur_strand_exponent(_e51);
    let cone_p = pow(max(cos(in_5.light_strand.w), 0f), _e52);
    return (((diffuse_albedo * ((in_5.light_diffuse.xyz * _e25) + (in_5.light_ambient.xyz * _e28))) + (sheen_color_3 * in_5.light_sheen.xyz)) + (strand_color * (in_5.light_strand.xyz * cone_p)));
}

fn fur_shade(in_6: FurVaryings) -> vec4<f32> {
    var color: vec3<f32>;

    let _e4 = material.base_map_st;
    let _e5 = fur_transform_uv(in_6.uv0_, _e4);
    let _e8 = material.base_color;
    let _e11 = textureSample(base_map, material_sampler, _e5);
    let base_rgba = (_e8 * _e11);
    let _e15 = textureSample(spot_map, material_sampler, _e5);
    let spot = saturate(_e15.x);
    let _e22 = material.spot_color;
    let base_1 = mix(saturate(base_rgba.xyz), saturate(_e22.xyz), spot);
    let alpha = saturate(base_rgba.w);
    {
        let _e29 = fur_shade_fast(in_6, base_1);
        color = _e29;
    }
    let _e32 = material.fur_occlusion;
    let occlusion = (1f - (saturate(_e32) * (1f - in_6.offset)));
    let _e40 = color;
    let radiance = clamp((_e40 * occlusion), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}

fn fur_fade_n_dot_v(in_7: FurVaryings) -> f32 {
    {
        return in_7.light_n_dot_v;
    }
}

fn fur_shell(in_8: FurVaryings) -> vec4<f32> {
    let _e2 = fur_noise(in_8.uv0_);
    let o = saturate(in_8.offset);
    let _e8 = material.tapered_tips;
    let shape = select(o, (o * o), (_e8 != 0u));
    let _e14 = material.cutoff_start;
    let _e18 = material.cutoff_end;
    let threshold = mix(saturate(_e14), saturate(_e18), shape);
    let _e21 = fwidth(_e2);
    let width = max(_e21, 0.001f);
    let coverage = (saturate((((_e2 - threshold) / width) + 0.5f)) * step(0.000001f, _e2));
    let _e32 = fur_shade(in_8);
    let _e35 = material.edge_fade;
    let _e37 = fur_fade_n_dot_v(in_8);
    let fade = (1f - (saturate(_e35) * (1f - _e37)));
    let a_1 = saturate((((coverage * (1f - o)) * fade) * _e32.w));
    let _e53 = material.shell_count;
    let slab = (FUR_SEED_SHELLS / f32(max(_e53, 1i)));
    let keep = (1f - a_1);
    let alpha_1 = (1f - select(pow(keep, slab), 0f, (keep <= 0f)));
    return vec4<f32>(_e32.xyz, alpha_1);
}

@vertex 
fn vs_skin(in: FurInput) -> FurVaryings {
    let _e2 = fur_vertex(in, 0f);
    return _e2;
}

@vertex 
fn vs_shell(in_1: FurInput, @builtin(instance_index) instance: u32) -> FurVaryings {
    let _e4 = material.shell_count;
    let count = f32(max(_e4, 1i));
    let _e12 = fur_vertex(in_1, ((f32(instance) + 0.5f) / count));
    return _e12;
}

@fragment 
fn fs_skin(in_2: FurVaryings) -> @location(0) vec4<f32> {
    let _e1 = fur_shade(in_2);
    return vec4<f32>(_e1.xyz, 1f);
}

@fragment 
fn fs_shell(in_3: FurVaryings) -> @location(0) vec4<f32> {
    let _e1 = fur_shell(in_3);
    return _e1;
}
