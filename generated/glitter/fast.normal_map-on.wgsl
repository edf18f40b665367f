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
    flake_color: vec4<f32>,
    flake_intensity: f32,
    flake_density: f32,
    flake_size: f32,
    flake_roughness: f32,
    twinkle: f32,
    density_variation: f32,
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

struct GlintGrid {
    uv: vec2<f32>,
    seed: u32,
    cell_area: f32,
    weight: f32,
}

struct GlintParams {
    log_density: f32,
    micro_roughness: f32,
    density_randomization: f32,
}

struct GlintSimplex {
    id: vec2<i32>,
    si: i32,
    bary: vec3<f32>,
}

struct GlintEllipse {
    major_dir: vec2<f32>,
    major: f32,
    minor: f32,
}

struct GlintFootprintCell {
    theta_lerp: f32,
    ratio_lerp: f32,
    lod_lerp: f32,
    center: bool,
    bin0_: f32,
    bin_h: f32,
    bin1_: f32,
    lod0_: f32,
    ratio0_: f32,
}

struct GlintTetraFast {
    codes: u32,
    w: vec4<f32>,
    bin0_: f32,
    bin_h: f32,
    bin1_: f32,
    lod0_: f32,
    ratio0_: f32,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SMOOTH: u32 = 2u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const GLINT_TAU: f32 = 6.2831855f;
const GLINT_HALF_PI: f32 = 1.5707964f;
const GLINT_TABLE_SIZE: f32 = 64f;
const GLINT_MIN_LOD: f32 = -20f;
const GLINT_MAX_LOD: f32 = 20f;
const GLINT_MAX_RATIO: f32 = 16f;
const GLINT_TET_A_UP: u32 = 36292u;
const GLINT_TET_A_DOWN: u32 = 36165u;
const GLINT_TET_A_LOW: u32 = 34112u;
const GLINT_TET_B_UP: u32 = 23168u;
const GLINT_TET_B_DOWN: u32 = 42242u;
const GLINT_TET_B_HIGH: u32 = 44421u;
const GLINT_TET_C_UP: u32 = 44517u;
const GLINT_TET_C_DOWN: u32 = 58790u;
const GLINT_TET_C_LOW: u32 = 42338u;
const GLINT_TET_CENTER_UP: u32 = 60596u;
const GLINT_TET_CENTER_DOWN: u32 = 18110u;
const GLINT_TET_CENTER_LOW: u32 = 46659u;

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
@group(1) @binding(1) 
var material_sampler: sampler;
@group(1) @binding(3) 
var base_map: texture_2d<f32>;
@group(1) @binding(4) 
var normal_map: texture_2d<f32>;
@group(1) @binding(5) 
var occlusion_map: texture_2d<f32>;

fn weft_pow5_(x: f32) -> f32 {
    let x2_ = (x * x);
    return ((x2_ * x2_) * x);
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
    let a_1 = (-1f / (s + n_1.z));
    let b_1 = ((n_1.x * n_1.y) * a_1);
    return vec3<f32>((1f + (((s * n_1.x) * n_1.x) * a_1)), (s * b_1), (-(s) * n_1.x));
}

fn weft_d_ggx(n_dot_h: f32, roughness_1: f32) -> f32 {
    let _e2 = weft_clamp_roughness(roughness_1);
    let a_2 = (_e2 * _e2);
    let a2_ = (a_2 * a_2);
    let noh = saturate(n_dot_h);
    let one_minus_noh2_ = ((1f - noh) * (1f + noh));
    let d_2 = (one_minus_noh2_ + ((noh * noh) * a2_));
    return (a2_ / ((WEFT_PI * d_2) * d_2));
}

fn weft_d_ggx_nh(n_2: vec3<f32>, h: vec3<f32>, roughness_2: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_2);
    let a_3 = (_e3 * _e3);
    let a2_1 = (a_3 * a_3);
    let noh_1 = saturate(dot(n_2, h));
    let nxh = cross(n_2, h);
    let d_3 = (dot(nxh, nxh) + ((noh_1 * noh_1) * a2_1));
    return (a2_1 / (WEFT_PI * max((d_3 * d_3), 0.000000000000000000000000000001f)));
}

fn weft_f_schlick(f0_: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (f0_ + ((vec3(1f) - f0_) * _e5));
}

fn weft_v_smith_ggx_correlated(n_dot_v: f32, n_dot_l: f32, roughness_3: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_3);
    let a_4 = (_e3 * _e3);
    let a2_2 = (a_4 * a_4);
    let _e6 = weft_clamp_cos(n_dot_v);
    let _e7 = weft_clamp_cos(n_dot_l);
    let lv = (_e7 * sqrt((((_e6 * _e6) * (1f - a2_2)) + a2_2)));
    let ll = (_e6 * sqrt((((_e7 * _e7) * (1f - a2_2)) + a2_2)));
    return (0.5f / (lv + ll));
}

fn weft_diffuse_lambert(albedo: vec3<f32>) -> vec3<f32> {
    return (albedo * WEFT_INV_PI);
}

fn weft_env_brdf_from_lut(f0_1: vec3<f32>, scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return ((f0_1 * sb.x) + vec3(sb.y));
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

fn weft_sh_irradiance(n_3: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    let sh = weft_frame.sh;
    e = (sh[0].xyz * 0.282095f);
    let _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603f * n_3.y)));
    let _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603f * n_3.z)));
    let _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603f * n_3.x)));
    let _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548f * n_3.x) * n_3.y)));
    let _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548f * n_3.y) * n_3.z)));
    let _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392f * (((3f * n_3.z) * n_3.z) - 1f))));
    let _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548f * n_3.x) * n_3.z)));
    let _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274f * ((n_3.x * n_3.x) - (n_3.y * n_3.y)))));
    let _e91 = e;
    return max(_e91, vec3(0f));
}

fn weft_specular_mip(roughness_4: f32) -> f32 {
    let r = saturate(roughness_4);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r * (1.7f - (0.7f * r))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_5: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_5);
    let c_4 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_4.xyz, vec3(0f));
}

fn weft_env_brdf_lut(n_dot_v_1: f32, roughness_6: f32) -> vec2<f32> {
    let uv_5 = vec2<f32>(saturate(n_dot_v_1), saturate(roughness_6));
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_5, 0f);
    return _e8.xy;
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_main_light_geometry(n_4: vec3<f32>, v_1: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_1), n_4);
    let _e6 = weft_clamp_cos(dot(n_4, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_4, _e2)), saturate(dot(n_4, _e4)), saturate(dot(v_1, _e4)));
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

fn weft_tangent_frame(n_5: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_5 * dot(n_5, t_in)));
    let len2_1 = dot(t_proj, t_proj);
    let ok = (len2_1 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_5);
    let t = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_2 = (cross(n_5, t) * s_1);
    return mat3x3<f32>(t, b_2, n_5);
}

fn weft_unpack_normal(texel: vec3<f32>, strength: f32) -> vec3<f32> {
    let v_3 = ((texel * 2f) - vec3(1f));
    return vec3<f32>((v_3.xy * strength), max(v_3.z, 0.001f));
}

fn weft_normal_from_tangent_space(frame: mat3x3<f32>, n_ts: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_safe_normalize((frame * n_ts), frame[2]);
    return _e4;
}

fn weft_mapped_normal(n_6: vec3<f32>, tangent_1: vec4<f32>, texel_1: vec3<f32>, strength_1: f32) -> vec3<f32> {
    let _e4 = weft_tangent_frame(n_6, tangent_1);
    let _e5 = weft_unpack_normal(texel_1, strength_1);
    let _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
}

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn glint_pcg3d(v_in: vec3<u32>) -> vec3<u32> {
    var v_2: vec3<u32>;

    v_2 = ((v_in * 1664525u) + vec3(1013904223u));
    let _e8 = v_2.x;
    let _e10 = v_2.y;
    let _e12 = v_2.z;
    v_2.x = (_e8 + (_e10 * _e12));
    let _e16 = v_2.y;
    let _e18 = v_2.z;
    let _e20 = v_2.x;
    v_2.y = (_e16 + (_e18 * _e20));
    let _e24 = v_2.z;
    let _e26 = v_2.x;
    let _e28 = v_2.y;
    v_2.z = (_e24 + (_e26 * _e28));
    let _e31 = v_2;
    let _e32 = v_2;
    v_2 = (_e31 ^ (_e32 >> vec3(16u)));
    let _e38 = v_2.x;
    let _e40 = v_2.y;
    let _e42 = v_2.z;
    v_2.x = (_e38 + (_e40 * _e42));
    let _e46 = v_2.y;
    let _e48 = v_2.z;
    let _e50 = v_2.x;
    v_2.y = (_e46 + (_e48 * _e50));
    let _e54 = v_2.z;
    let _e56 = v_2.x;
    let _e58 = v_2.y;
    v_2.z = (_e54 + (_e56 * _e58));
    let _e61 = v_2;
    return _e61;
}

fn glint_hash13_(p_in: vec3<f32>) -> f32 {
    var p3_: vec3<f32>;

    p3_ = fract((p_in * 0.1031f));
    let _e5 = p3_;
    let _e6 = p3_;
    let _e7 = p3_;
    p3_ = (_e5 + vec3(dot(_e6, (_e7.yzx + vec3(33.33f)))));
    let _e16 = p3_.x;
    let _e18 = p3_.y;
    let _e21 = p3_.z;
    return fract(((_e16 + _e18) * _e21));
}

fn glint_simplex(uv_1: vec2<f32>) -> GlintSimplex {
    let skewed = vec2<f32>((uv_1.x - (0.57735026f * uv_1.y)), (1.1547005f * uv_1.y));
    let base = floor(skewed);
    let f = (skewed - base);
    let fz = ((1f - f.x) - f.y);
    let s_2 = select(0f, 1f, (fz < 0f));
    let s2_ = ((2f * s_2) - 1f);
    return GlintSimplex(vec2<i32>(base), i32(s_2), vec3<f32>((-(fz) * s2_), (s_2 - (f.y * s2_)), (s_2 - (f.x * s2_))));
}

fn glint_ellipse(duv_dx: vec2<f32>, duv_dy: vec2<f32>) -> GlintEllipse {
    var out_1: GlintEllipse;

    let a_5 = ((duv_dx.x * duv_dx.x) + (duv_dy.x * duv_dy.x));
    let b_3 = ((duv_dx.x * duv_dx.y) + (duv_dy.x * duv_dy.y));
    let d_4 = ((duv_dx.y * duv_dx.y) + (duv_dy.y * duv_dy.y));
    let half_trace = (0.5f * (a_5 + d_4));
    let disc = sqrt(max((((0.25f * (a_5 - d_4)) * (a_5 - d_4)) + (b_3 * b_3)), 0f));
    let l1_ = (half_trace + disc);
    let l2_ = max((half_trace - disc), 0f);
    let e_a = vec2<f32>(b_3, (l1_ - a_5));
    let e_b = vec2<f32>((l1_ - d_4), b_3);
    let e_5 = select(e_b, e_a, (dot(e_a, e_a) > dot(e_b, e_b)));
    let e_len2_ = dot(e_5, e_5);
    out_1.major_dir = select(vec2<f32>(1f, 0f), (e_5 * inverseSqrt(max(e_len2_, 0.0000000000000000000000000000000000001f))), (e_len2_ > 0.0000000000000000000000000000000000001f));
    out_1.major = max(sqrt(l1_), 0.000000000001f);
    let _e68 = out_1.major;
    out_1.minor = max(sqrt(l2_), (_e68 / 64f));
    let _e72 = out_1;
    return _e72;
}

fn glint_rotate(uv_2: vec2<f32>, angle: f32) -> vec2<f32> {
    let c_5 = cos(angle);
    let s_3 = sin(angle);
    return vec2<f32>(((c_5 * uv_2.x) + (s_3 * uv_2.y)), ((c_5 * uv_2.y) - (s_3 * uv_2.x)));
}

fn glint_grid_seed(lod: f32, theta: f32, ratio: f32) -> u32 {
    let t_1 = (theta - (GLINT_TAU * trunc((theta / GLINT_TAU))));
    let _e10 = glint_hash13_(vec3<f32>(lod, t_1, ratio));
    return u32(min((_e10 * 4294967300f), 4294967000f));
}

fn glint_make_grid(uv_3: vec2<f32>, lod_1: f32, theta_1: f32, ratio_1: f32, weight: f32) -> GlintGrid {
    var g: GlintGrid;

    let _e7 = glint_rotate(uv_3, theta_1);
    g.uv = ((_e7 * exp2(-(lod_1))) / vec2<f32>(1f, ratio_1));
    let _e15 = glint_grid_seed(lod_1, theta_1, ratio_1);
    g.seed = _e15;
    g.cell_area = (ratio_1 * exp2((2f * lod_1)));
    g.weight = weight;
    let _e22 = g;
    return _e22;
}

fn glint_tetra_weights(p: vec3<f32>, a: vec3<f32>, b: vec3<f32>, c_1: vec3<f32>, d: vec3<f32>) -> vec4<f32> {
    let c1_ = (a - d);
    let c2_ = (b - d);
    let c3_ = (c_1 - d);
    let q = (p - d);
    let det = dot(c1_, cross(c2_, c3_));
    let inv = (1f / det);
    let w1_ = (dot(q, cross(c2_, c3_)) * inv);
    let w2_ = (dot(c1_, cross(q, c3_)) * inv);
    let w3_ = (dot(c1_, cross(c2_, q)) * inv);
    return vec4<f32>(w1_, w2_, w3_, (((1f - w1_) - w2_) - w3_));
}

fn glint_lod(e_1: GlintEllipse, screen_scale: f32) -> f32 {
    return clamp(log2(((e_1.minor * screen_scale) * 0.5f)), GLINT_MIN_LOD, GLINT_MAX_LOD);
}

fn glint_footprint_cell(e_2: GlintEllipse, screen_scale_1: f32) -> GlintFootprintCell {
    var out_2: GlintFootprintCell;

    let ratio_e = min((e_2.major / (e_2.minor + (0.00000001f * e_2.major))), GLINT_MAX_RATIO);
    let _e11 = glint_lod(e_2, screen_scale_1);
    let lod0_ = floor(_e11);
    let lod_lerp = (_e11 - lod0_);
    let ratio0_ = max(exp2(floor(log2(max(ratio_e, 1f)))), 1f);
    let ratio1_ = (ratio0_ * 2f);
    let ratio_lerp = saturate(((ratio_e - ratio0_) / (ratio1_ - ratio0_)));
    let q_1 = (0.7853982f / max(ratio0_, 2f));
    let per_pi = (4f * max(ratio0_, 2f));
    let theta_2 = atan2(-(e_2.major_dir.x), e_2.major_dir.y);
    let theta_q = (theta_2 / q_1);
    let h0_ = floor(theta_q);
    let theta_lerp = saturate((theta_q - h0_));
    let i0_ = (h0_ - (per_pi * floor((h0_ / per_pi))));
    let i1_ = ((i0_ + 1f) - (per_pi * floor(((i0_ + 1f) / per_pi))));
    let theta_bin0_ = (i0_ * q_1);
    let theta_bin_h = ((i0_ + 0.5f) * q_1);
    let theta_bin1_ = (i1_ * q_1);
    out_2.theta_lerp = theta_lerp;
    out_2.ratio_lerp = ratio_lerp;
    out_2.lod_lerp = lod_lerp;
    out_2.center = (ratio0_ == 1f);
    out_2.bin0_ = theta_bin0_;
    out_2.bin_h = theta_bin_h;
    out_2.bin1_ = theta_bin1_;
    out_2.lod0_ = lod0_;
    out_2.ratio0_ = ratio0_;
    let _e74 = out_2;
    return _e74;
}

fn glint_normal_fast(h_1: u32) -> f32 {
    let x_2 = fma(f32(h_1), 0.0000000004656613f, -1f);
    let x2_1 = (x_2 * x_2);
    return (x_2 * (1.2225f + (x2_1 * (0.75468f + (x2_1 * (-1.263127f + (x2_1 * 1.568366f)))))));
}

fn glint_corner_hits(ax: u32, ay: u32, gate_a: f32, gate_b: f32, deviation: f32, mean1_: f32) -> f32 {
    var x_1: u32;
    var y: u32;
    var z: u32;
    var w: u32;

    x_1 = (ax + (ay * 1860535849u));
    let _e10 = x_1;
    y = (ay + (_e10 * 220351156u));
    let _e16 = x_1;
    let _e17 = y;
    z = (220351156u + (_e16 * _e17));
    let _e22 = y;
    let _e23 = z;
    w = (1860535849u + (_e22 * _e23));
    let _e27 = x_1;
    let _e28 = x_1;
    x_1 = (_e27 ^ (_e28 >> 16u));
    let _e32 = y;
    let _e33 = y;
    y = (_e32 ^ (_e33 >> 16u));
    let _e37 = z;
    let _e38 = z;
    z = (_e37 ^ (_e38 >> 16u));
    let _e42 = w;
    let _e43 = w;
    w = (_e42 ^ (_e43 >> 16u));
    let _e47 = x_1;
    let _e48 = y;
    let _e49 = w;
    x_1 = (_e47 + (_e48 * _e49));
    let _e52 = y;
    let _e53 = z;
    let _e54 = x_1;
    y = (_e52 + (_e53 * _e54));
    let _e57 = x_1;
    let gate = saturate(fma(f32(_e57), gate_a, gate_b));
    let _e61 = y;
    let _e62 = glint_normal_fast(_e61);
    let count = max(floor(fma(_e62, deviation, mean1_)), 1f);
    return (gate * count);
}

fn glint_cell_fast(params: GlintParams, grid: GlintGrid, c_2: vec2<i32>, s_slope: vec2<f32>, p_1: f32, log2_q: f32) -> f32 {
    let _e16 = glint_pcg3d(vec3<u32>((bitcast<u32>(c_2.x) + 2147483648u), (bitcast<u32>(c_2.y) + 2147483648u), grid.seed));
    let _e18 = glint_normal_fast(_e16.x);
    let log_density = clamp(((_e18 * params.density_randomization) + params.log_density), 0f, 50f);
    let count_1 = max(0.00000001f, (grid.cell_area * exp(log_density)));
    let blended = (count_1 * grid.weight);
    let miss = exp2((blended * log2_q));
    let one_hit = (1f - miss);
    let others = max((blended - 1f), 0f);
    let mean1_1 = ((others * p_1) + 1f);
    let deviation_1 = sqrt((others * (p_1 * (1f - p_1))));
    let width = max(((0.1f * saturate((one_hit * 10f))) * saturate((miss * 10f))), 0.000000000000000000000000000001f);
    let inv_1 = (0.5f / width);
    let gate_a_1 = (inv_1 * -0.00000000023283064f);
    let gate_b_1 = fma(one_hit, inv_1, 0.5f);
    let s_4 = fma(vec2<f32>((_e16.yz >> vec2(8u))), vec2(0.0000038146973f), s_slope);
    let cell = floor(s_4);
    let l = (s_4 - cell);
    let ci = vec2<u32>(cell);
    let t0_ = (ci & vec2(63u));
    let t1_ = ((ci + vec2(1u)) & vec2(63u));
    let ax_1 = ((vec2<u32>(t0_.x, t1_.x) * 1664525u) + vec2(1013904223u));
    let ay_1 = ((vec2<u32>(t0_.y, t1_.y) * 1664525u) + vec2(1013904223u));
    let _e104 = glint_corner_hits(ax_1.x, ay_1.x, gate_a_1, gate_b_1, deviation_1, mean1_1);
    let _e107 = glint_corner_hits(ax_1.x, ay_1.y, gate_a_1, gate_b_1, deviation_1, mean1_1);
    let _e110 = glint_corner_hits(ax_1.y, ay_1.x, gate_a_1, gate_b_1, deviation_1, mean1_1);
    let _e113 = glint_corner_hits(ax_1.y, ay_1.y, gate_a_1, gate_b_1, deviation_1, mean1_1);
    let x0_ = mix(_e104, _e110, l.x);
    let x1_ = mix(_e107, _e113, l.x);
    return (mix(x0_, x1_, l.y) / count_1);
}

fn glint_sample_grid_fast(params_1: GlintParams, grid_1: GlintGrid, s_slope_1: vec2<f32>, p_2: f32, log2_q_1: f32) -> f32 {
    var sum: f32 = 0f;
    var k: i32 = 0i;

    let _e6 = glint_simplex(grid_1.uv);
    let id = _e6.id;
    let si = _e6.si;
    let bary = _e6.bary;
    loop {
        let _e14 = k;
        if (_e14 < 3i) {
        } else {
            break;
        }
        {
            let _e19 = k;
            let _e25 = k;
            let c_6 = (id + vec2<i32>(select(si, (1i - si), (_e19 == 2i)), select(si, (1i - si), (_e25 == 1i))));
            let _e33 = k;
            let _e38 = k;
            let b_4 = select(select(bary.z, bary.y, (_e33 == 1i)), bary.x, (_e38 == 0i));
            let _e42 = sum;
            let _e43 = glint_cell_fast(params_1, grid_1, c_6, s_slope_1, p_2, log2_q_1);
            sum = (_e42 + (b_4 * _e43));
        }
        continuing {
            let _e47 = k;
            k = (_e47 + 1i);
        }
    }
    let _e49 = sum;
    return _e49;
}

fn glint_vertex_of_code(c_3: u32) -> vec3<f32> {
    let rot = (c_3 & 3u);
    return vec3<f32>(select((f32(rot) * 0.5f), 0f, (rot == 3u)), f32(((c_3 >> 2u) & 1u)), f32((c_3 >> 3u)));
}

fn glint_tetra_fast(e_3: GlintEllipse, screen_scale_2: f32) -> GlintTetraFast {
    var local_1: bool;
    var out_3: GlintTetraFast;

    let _e2 = glint_footprint_cell(e_3, screen_scale_2);
    let t_2 = _e2.theta_lerp;
    let r_1 = _e2.ratio_lerp;
    let l_1 = _e2.lod_lerp;
    let upper = (l_1 > (1f - r_1));
    let upper_left = ((l_1 - (1f - r_1)) / max(r_1, 0.00000001f));
    let half_width = (0.5f * (1f - r_1));
    let center_codes = select(GLINT_TET_CENTER_LOW, select(GLINT_TET_CENTER_DOWN, GLINT_TET_CENTER_UP, (upper_left > t_2)), upper);
    let a_codes = select(GLINT_TET_A_LOW, select(GLINT_TET_A_DOWN, GLINT_TET_A_UP, (upper_left > ((t_2 * 2f) / max(r_1, 0.00000001f)))), upper);
    let b_codes = select(GLINT_TET_B_HIGH, select(GLINT_TET_B_DOWN, GLINT_TET_B_UP, ((l_1 / max((1f - r_1), 0.00000001f)) > ((t_2 - (0.5f - half_width)) / max((2f * half_width), 0.00000001f)))), (l_1 < (1f - r_1)));
    let c_codes = select(GLINT_TET_C_LOW, select(GLINT_TET_C_DOWN, GLINT_TET_C_UP, (upper_left > ((((t_2 - 0.5f) * 2f) - (1f - r_1)) / max(r_1, 0.00000001f)))), upper);
    if (t_2 < 0.5f) {
        local_1 = ((t_2 * 2f) < r_1);
    } else {
        local_1 = false;
    }
    let prism_a = local_1;
    let prism_b = ((1f - ((t_2 - 0.5f) * 2f)) > r_1);
    let codes = select(select(select(c_codes, b_codes, prism_b), a_codes, prism_a), center_codes, _e2.center);
    let point = vec3<f32>(select(t_2, (t_2 * r_1), _e2.center), r_1, l_1);
    out_3.codes = codes;
    let _e103 = glint_vertex_of_code((codes & 15u));
    let _e108 = glint_vertex_of_code(((codes >> 4u) & 15u));
    let _e113 = glint_vertex_of_code(((codes >> 8u) & 15u));
    let _e116 = glint_vertex_of_code((codes >> 12u));
    let _e117 = glint_tetra_weights(point, _e103, _e108, _e113, _e116);
    out_3.w = _e117;
    out_3.bin0_ = _e2.bin0_;
    out_3.bin_h = _e2.bin_h;
    out_3.bin1_ = _e2.bin1_;
    out_3.lod0_ = _e2.lod0_;
    out_3.ratio0_ = _e2.ratio0_;
    let _e128 = out_3;
    return _e128;
}

fn glint_hits_fast(params_2: GlintParams, uv_4: vec2<f32>, e_4: GlintEllipse, screen_scale_3: f32, slope: vec2<f32>, d_1: f32, d_max: f32) -> f32 {
    var sum_1: f32 = 0f;
    var i: u32 = 0u;

    let _e7 = glint_tetra_fast(e_4, screen_scale_3);
    let codes_1 = _e7.codes;
    let p_4 = (params_2.micro_roughness * (d_1 / d_max));
    let log2_q_2 = log2((1f - p_4));
    let s_slope_2 = ((abs(slope) / vec2(params_2.micro_roughness)) + vec2(0.0000019073486f));
    loop {
        let _e26 = i;
        if (_e26 < 4u) {
        } else {
            break;
        }
        {
            let _e30 = i;
            let c_7 = ((codes_1 >> (4u * _e30)) & 15u);
            let rot_1 = (c_7 & 3u);
            let theta_3 = select(select(select(0f, _e7.bin1_, (rot_1 == 2u)), _e7.bin_h, (rot_1 == 1u)), _e7.bin0_, (rot_1 == 0u));
            let ratio_2 = select(_e7.ratio0_, (_e7.ratio0_ * 2f), ((c_7 & 4u) != 0u));
            let lod_2 = (_e7.lod0_ + f32((c_7 >> 3u)));
            let _e76 = i;
            let _e82 = i;
            let _e88 = i;
            let w_1 = select(select(select((((1f - _e7.w.x) - _e7.w.y) - _e7.w.z), _e7.w.z, (_e76 == 2u)), _e7.w.y, (_e82 == 1u)), _e7.w.x, (_e88 == 0u));
            let _e92 = sum_1;
            let _e93 = glint_make_grid(uv_4, lod_2, theta_3, ratio_2, w_1);
            let _e94 = glint_sample_grid_fast(params_2, _e93, s_slope_2, p_4, log2_q_2);
            sum_1 = (_e92 + _e94);
        }
        continuing {
            let _e97 = i;
            i = (_e97 + 1u);
        }
    }
    let _e99 = sum_1;
    return _e99;
}

fn glitter_params() -> GlintParams {
    var p_3: GlintParams;

    let _e4 = material.flake_density;
    p_3.log_density = (4f + (28f * saturate(_e4)));
    let _e13 = material.twinkle;
    p_3.micro_roughness = exp2(mix(-4.321928f, -8.965784f, saturate(_e13)));
    let _e22 = material.density_variation;
    p_3.density_randomization = clamp(_e22, 0f, 4f);
    let _e26 = p_3;
    return _e26;
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
    var local: bool;
    var d_flakes: f32;

    let _e4 = material.base_map_st;
    let _e5 = weft_transform_uv(in_1.uv0_, _e4);
    let duv_dx_1 = dpdx(_e5);
    let duv_dy_1 = dpdy(_e5);
    let _e10 = material.base_color;
    let _e13 = textureSample(base_map, material_sampler, _e5);
    let base_rgba = (_e10 * _e13);
    let base_1 = saturate(base_rgba.xyz);
    let alpha = saturate(base_rgba.w);
    let _e21 = material.metallic;
    let metallic = saturate(_e21);
    let _e25 = material.smoothness;
    let roughness_7 = (1f - saturate(_e25));
    let _e31 = textureSample(occlusion_map, material_sampler, _e5);
    let occlusion = _e31.x;
    let _e35 = material.occlusion_strength;
    let ao = saturate(mix(1f, occlusion, _e35));
    let _e41 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_4 = _e41.v;
    n = _e41.n;
    {
        let _e47 = textureSample(normal_map, material_sampler, _e5);
        let texel_2 = _e47.xyz;
        let _e49 = n;
        let _e53 = material.normal_strength;
        let _e54 = weft_mapped_normal(_e49, in_1.world_tangent, texel_2, _e53);
        n = _e54;
    }
    let _e55 = n;
    let _e57 = weft_tangent_frame(_e55, in_1.world_tangent);
    let _e58 = n;
    let _e59 = weft_main_light_geometry(_e58, v_4);
    let _e60 = weft_main_light_radiance();
    let f0_2 = mix(vec3(0.04f), base_1, metallic);
    let diffuse_albedo = (base_1 * (1f - metallic));
    let _e69 = weft_v_smith_ggx_correlated(_e59.n_dot_v, _e59.n_dot_l, roughness_7);
    let _e71 = weft_env_brdf_lut(_e59.n_dot_v, roughness_7);
    let _e72 = weft_env_brdf_from_lut(f0_2, _e71);
    let kd = max((vec3(1f) - _e72), vec3(0f));
    let _e79 = n;
    let _e81 = weft_d_ggx_nh(_e79, _e59.h, roughness_7);
    let _e84 = weft_f_schlick(f0_2, _e59.v_dot_h);
    let specular = ((_e81 * _e69) * _e84);
    let _e86 = weft_diffuse_lambert(diffuse_albedo);
    let direct = ((((kd * _e86) + specular) * _e60) * _e59.n_dot_l);
    let _e93 = n;
    let _e95 = weft_prefiltered_radiance(reflect(-(v_4), _e93), roughness_7);
    let _e98 = n;
    let _e99 = weft_sh_irradiance(_e98);
    let indirect = (((_e95 * _e72) * ao) + (((_e99 * ao) * kd) * diffuse_albedo));
    color = (direct + indirect);
    let _e108 = material.flake_intensity;
    let intensity = max(_e108, 0f);
    if (intensity > 0f) {
        local = (_e59.n_dot_l > 0f);
    } else {
        local = false;
    }
    let _e119 = local;
    if _e119 {
        let _e122 = material.flake_roughness;
        let r_f = clamp(_e122, 0.05f, 1f);
        let _e126 = n;
        let _e128 = weft_d_ggx_nh(_e126, _e59.h, r_f);
        let _e130 = weft_d_ggx(1f, r_f);
        let _e133 = material.flake_color;
        let flake_f0_ = saturate(_e133.xyz);
        let _e138 = weft_v_smith_ggx_correlated(_e59.n_dot_v, _e59.n_dot_l, r_f);
        {
            let _e139 = glitter_params();
            let _e142 = weft_f_schlick(flake_f0_, _e59.v_dot_h);
            let lobe = (((((intensity * _e138) * _e142) * _e60) * _e59.n_dot_l) * (_e130 / _e139.micro_roughness));
            let slope_1 = vec2<f32>(dot(_e57[0], _e59.h), dot(_e57[1], _e59.h));
            let _e157 = glint_ellipse(duv_dx_1, duv_dy_1);
            let _e160 = material.flake_size;
            let screen_scale_4 = clamp(_e160, 1f, 8f);
            let _e164 = glint_hits_fast(_e139, _e5, _e157, screen_scale_4, slope_1, _e128, _e130);
            let _e165 = color;
            color = (_e165 + (min(_e164, (20f * _e139.micro_roughness)) * lobe));
        }
    }
    let _e172 = color;
    let radiance = clamp(_e172, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
