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

fn weft_f_schlick(f0_: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (f0_ + ((vec3(1f) - f0_) * _e5));
}

fn weft_v_schlick_ggx(n_dot_v: f32, n_dot_l: f32, roughness_1: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_1);
    let a = (_e3 * _e3);
    let k = (((a + 1f) * (a + 1f)) * 0.125f);
    let gv = ((saturate(n_dot_v) * (1f - k)) + k);
    let gl = ((saturate(n_dot_l) * (1f - k)) + k);
    return (0.25f / (gv * gl));
}

fn weft_diffuse_lambert(albedo: vec3<f32>) -> vec3<f32> {
    return (albedo * WEFT_INV_PI);
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

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_main_light_geometry(n_1: vec3<f32>, v_1: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_1), n_1);
    let _e6 = weft_clamp_cos(dot(n_1, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_1, _e2)), saturate(dot(n_1, _e4)), saturate(dot(v_1, _e4)));
}

fn fur_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn fur_vertex(in_4: FurInput, offset: f32) -> FurVaryings {
    var out: FurVaryings;

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
    let dir = mix(_e24, target_dir, offset);
    let p = (world + (dir * (len * offset)));
    let _e88 = weft_frame.view_proj;
    out.clip_position = (_e88 * vec4<f32>(p, 1f));
    out.world_position = p;
    out.world_normal = _e24;
    out.strand = (_e24 + ((2f * offset) * (target_dir - _e24)));
    out.uv0_ = in_4.uv0_;
    out.offset = offset;
    let _e103 = out;
    return _e103;
}

fn fur_noise(uv0_: vec2<f32>) -> f32 {
    let _e3 = material.noise_map_st;
    let _e4 = fur_transform_uv(uv0_, _e3);
    {
        let _e7 = textureSample(noise_map, material_sampler, _e4);
        return saturate(_e7.x);
    }
}

fn fur_shade(in_5: FurVaryings) -> vec4<f32> {
    var color: vec3<f32>;

    let _e4 = material.base_map_st;
    let _e5 = fur_transform_uv(in_5.uv0_, _e4);
    let _e8 = material.base_color;
    let _e11 = textureSample(base_map, material_sampler, _e5);
    let base_rgba = (_e8 * _e11);
    let _e15 = textureSample(spot_map, material_sampler, _e5);
    let spot = saturate(_e15.x);
    let _e22 = material.spot_color;
    let base = mix(saturate(base_rgba.xyz), saturate(_e22.xyz), spot);
    let alpha = saturate(base_rgba.w);
    {
        let _e31 = material.metallic;
        let metallic = saturate(_e31);
        let _e35 = material.smoothness;
        let smoothness = saturate(_e35);
        let roughness_2 = (1f - smoothness);
        let _e41 = weft_surface(in_5.world_position, in_5.world_normal);
        let v_2 = _e41.v;
        let n_2 = _e41.n;
        let _e45 = weft_safe_normalize(in_5.strand, n_2);
        let _e46 = weft_main_light_geometry(n_2, v_2);
        let l_dot_h = saturate(dot(_e46.l, _e46.h));
        let f0_1 = mix(vec3(0.04f), base, metallic);
        let diffuse_albedo = (base * (1f - metallic));
        let _e57 = weft_main_light_radiance();
        let _e58 = weft_sh_irradiance(n_2);
        {
            let _e61 = weft_v_schlick_ggx(_e46.n_dot_v, _e46.n_dot_l, roughness_2);
            let _e62 = weft_f_schlick(f0_1, l_dot_h);
            let _e64 = weft_fabric_d(_e46.n_dot_h);
            let specular = ((_e64 * _e61) * _e62);
            let _e67 = weft_diffuse_lambert(diffuse_albedo);
            let _e70 = material.sheen_color;
            let _e76 = material.scatter_scale;
            let _e77 = weft_fabric_scatter(_e70.xyz, _e46.n_dot_l, _e46.n_dot_v, _e76);
            color = (((((_e67 + specular) * _e57) * _e46.n_dot_l) + (_e58 * diffuse_albedo)) + _e77);
        }
    }
    let _e87 = material.fur_occlusion;
    let occlusion = (1f - (saturate(_e87) * (1f - in_5.offset)));
    let _e95 = color;
    let radiance = clamp((_e95 * occlusion), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}

fn fur_fade_n_dot_v(in_6: FurVaryings) -> f32 {
    let _e3 = weft_surface(in_6.world_position, in_6.world_normal);
    return saturate(dot(_e3.n, _e3.v));
}

fn fur_shell(in_7: FurVaryings) -> vec4<f32> {
    let _e2 = fur_noise(in_7.uv0_);
    let o = saturate(in_7.offset);
    let _e8 = material.tapered_tips;
    let shape = select(o, (o * o), (_e8 != 0u));
    let _e14 = material.cutoff_start;
    let _e18 = material.cutoff_end;
    let threshold = mix(saturate(_e14), saturate(_e18), shape);
    let _e21 = fwidth(_e2);
    let width = max(_e21, 0.001f);
    let coverage = (saturate((((_e2 - threshold) / width) + 0.5f)) * step(0.000001f, _e2));
    let _e32 = fur_shade(in_7);
    let _e35 = material.edge_fade;
    let _e37 = fur_fade_n_dot_v(in_7);
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
