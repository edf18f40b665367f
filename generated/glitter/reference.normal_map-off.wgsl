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

struct GlintSlopeRand {
    gate_rand: vec4<f32>,
    gaussian: vec4<f32>,
    lerp: vec2<f32>,
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

struct GlintGrids {
    g0_: GlintGrid,
    g1_: GlintGrid,
    g2_: GlintGrid,
    g3_: GlintGrid,
}

struct GlintTetra {
    p0_: vec3<f32>,
    p1_: vec3<f32>,
    p2_: vec3<f32>,
    p3_: vec3<f32>,
    w: vec4<f32>,
    center: bool,
    bin0_: f32,
    bin_h: f32,
    bin1_: f32,
    lod0_: f32,
    ratio0_: f32,
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
    let r_1 = saturate(roughness_4);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r_1 * (1.7f - (0.7f * r_1))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_5: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_5);
    let c_3 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_3.xyz, vec3(0f));
}

fn weft_env_brdf_lut(n_dot_v_1: f32, roughness_6: f32) -> vec2<f32> {
    let uv_6 = vec2<f32>(saturate(n_dot_v_1), saturate(roughness_6));
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_6, 0f);
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

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn glint_pcg4d(v_in: vec4<u32>) -> vec4<u32> {
    var v_2: vec4<u32>;

    v_2 = ((v_in * 1664525u) + vec4(1013904223u));
    let _e8 = v_2.x;
    let _e10 = v_2.y;
    let _e12 = v_2.w;
    v_2.x = (_e8 + (_e10 * _e12));
    let _e16 = v_2.y;
    let _e18 = v_2.z;
    let _e20 = v_2.x;
    v_2.y = (_e16 + (_e18 * _e20));
    let _e24 = v_2.z;
    let _e26 = v_2.x;
    let _e28 = v_2.y;
    v_2.z = (_e24 + (_e26 * _e28));
    let _e32 = v_2.w;
    let _e34 = v_2.y;
    let _e36 = v_2.z;
    v_2.w = (_e32 + (_e34 * _e36));
    let _e39 = v_2;
    let _e40 = v_2;
    v_2 = (_e39 ^ (_e40 >> vec4(16u)));
    let _e46 = v_2.x;
    let _e48 = v_2.y;
    let _e50 = v_2.w;
    v_2.x = (_e46 + (_e48 * _e50));
    let _e54 = v_2.y;
    let _e56 = v_2.z;
    let _e58 = v_2.x;
    v_2.y = (_e54 + (_e56 * _e58));
    let _e62 = v_2.z;
    let _e64 = v_2.x;
    let _e66 = v_2.y;
    v_2.z = (_e62 + (_e64 * _e66));
    let _e70 = v_2.w;
    let _e72 = v_2.y;
    let _e74 = v_2.z;
    v_2.w = (_e70 + (_e72 * _e74));
    let _e77 = v_2;
    return _e77;
}

fn glint_pcg3d(v_in_1: vec3<u32>) -> vec3<u32> {
    var v_3: vec3<u32>;

    v_3 = ((v_in_1 * 1664525u) + vec3(1013904223u));
    let _e8 = v_3.x;
    let _e10 = v_3.y;
    let _e12 = v_3.z;
    v_3.x = (_e8 + (_e10 * _e12));
    let _e16 = v_3.y;
    let _e18 = v_3.z;
    let _e20 = v_3.x;
    v_3.y = (_e16 + (_e18 * _e20));
    let _e24 = v_3.z;
    let _e26 = v_3.x;
    let _e28 = v_3.y;
    v_3.z = (_e24 + (_e26 * _e28));
    let _e31 = v_3;
    let _e32 = v_3;
    v_3 = (_e31 ^ (_e32 >> vec3(16u)));
    let _e38 = v_3.x;
    let _e40 = v_3.y;
    let _e42 = v_3.z;
    v_3.x = (_e38 + (_e40 * _e42));
    let _e46 = v_3.y;
    let _e48 = v_3.z;
    let _e50 = v_3.x;
    v_3.y = (_e46 + (_e48 * _e50));
    let _e54 = v_3.z;
    let _e56 = v_3.x;
    let _e58 = v_3.y;
    v_3.z = (_e54 + (_e56 * _e58));
    let _e61 = v_3;
    return _e61;
}

fn glint_unit3_(v_4: vec3<u32>) -> vec3<f32> {
    return ((vec3<f32>((v_4 >> vec3(8u))) + vec3(0.5f)) * 0.000000059604645f);
}

fn glint_unit4_(v_5: vec4<u32>) -> vec4<f32> {
    return ((vec4<f32>((v_5 >> vec4(8u))) + vec4(0.5f)) * 0.000000059604645f);
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

fn glint_erfinv(x_1: f32) -> f32 {
    var w: f32;
    var p: f32;

    w = -(log(max(((1f - x_1) * (1f + x_1)), 0.000000000000000000000000000001f)));
    let _e12 = w;
    if (_e12 < 5f) {
        let _e15 = w;
        w = (_e15 - 2.5f);
        p = 0.000000028102264f;
        let _e19 = p;
        let _e20 = w;
        p = (0.00000034327394f + (_e19 * _e20));
        let _e24 = p;
        let _e25 = w;
        p = (-0.0000035233877f + (_e24 * _e25));
        let _e29 = p;
        let _e30 = w;
        p = (-0.0000043915065f + (_e29 * _e30));
        let _e34 = p;
        let _e35 = w;
        p = (0.00021858087f + (_e34 * _e35));
        let _e39 = p;
        let _e40 = w;
        p = (-0.001253725f + (_e39 * _e40));
        let _e44 = p;
        let _e45 = w;
        p = (-0.0041776816f + (_e44 * _e45));
        let _e49 = p;
        let _e50 = w;
        p = (0.24664073f + (_e49 * _e50));
        let _e54 = p;
        let _e55 = w;
        p = (1.5014094f + (_e54 * _e55));
    } else {
        let _e59 = w;
        w = (sqrt(_e59) - 3f);
        p = -0.00020021426f;
        let _e64 = p;
        let _e65 = w;
        p = (0.00010095056f + (_e64 * _e65));
        let _e69 = p;
        let _e70 = w;
        p = (0.0013493432f + (_e69 * _e70));
        let _e74 = p;
        let _e75 = w;
        p = (-0.0036734284f + (_e74 * _e75));
        let _e79 = p;
        let _e80 = w;
        p = (0.0057395077f + (_e79 * _e80));
        let _e84 = p;
        let _e85 = w;
        p = (-0.0076224613f + (_e84 * _e85));
        let _e89 = p;
        let _e90 = w;
        p = (0.0094388705f + (_e89 * _e90));
        let _e94 = p;
        let _e95 = w;
        p = (1.001674f + (_e94 * _e95));
        let _e99 = p;
        let _e100 = w;
        p = (2.8329768f + (_e99 * _e100));
    }
    let _e104 = p;
    return (_e104 * x_1);
}

fn glint_erfinv_poly(x_in: f32) -> f32 {
    let x_3 = clamp(x_in, -0.95f, 0.95f);
    let x2_1 = (x_3 * x_3);
    return (x_3 * (0.864441f + (x2_1 * (0.533641f + (x2_1 * (-0.893165f + (x2_1 * 1.108999f)))))));
}

fn glint_erfinv_by(x_2: f32, poly: bool) -> f32 {
    if poly {
        let _e2 = glint_erfinv_poly(x_2);
        return _e2;
    }
    let _e3 = glint_erfinv(x_2);
    return _e3;
}

fn glint_gaussian3_(u: vec3<f32>, poly_normals: bool) -> vec3<f32> {
    let _e7 = glint_erfinv_by(((2f * u.x) - 1f), poly_normals);
    let _e13 = glint_erfinv_by(((2f * u.y) - 1f), poly_normals);
    let _e19 = glint_erfinv_by(((2f * u.z) - 1f), poly_normals);
    return (1.4142135f * vec3<f32>(_e7, _e13, _e19));
}

fn glint_corner(c_1: vec2<f32>, poly_normals_1: bool) -> vec2<f32> {
    let texel = vec2<u32>((c_1 - (GLINT_TABLE_SIZE * floor((c_1 / vec2(64f))))));
    let _e13 = glint_pcg4d(vec4<u32>(texel, 6777961u, 1953785202u));
    let _e14 = glint_unit4_(_e13);
    let _e21 = glint_erfinv_by(((2f * _e14.y) - 1f), poly_normals_1);
    return vec2<f32>(_e14.x, (1.4142135f * _e21));
}

fn glint_slope_rand(micro_roughness: f32, slope: vec2<f32>, offset: vec2<f32>, poly_normals_2: bool) -> GlintSlopeRand {
    var out_1: GlintSlopeRand;

    let s_2 = ((abs(slope) / vec2(micro_roughness)) + (offset * GLINT_TABLE_SIZE));
    let cell = floor(s_2);
    let _e11 = glint_corner(cell, poly_normals_2);
    let _e16 = glint_corner((cell + vec2<f32>(0f, 1f)), poly_normals_2);
    let _e21 = glint_corner((cell + vec2<f32>(1f, 0f)), poly_normals_2);
    let _e26 = glint_corner((cell + vec2<f32>(1f, 1f)), poly_normals_2);
    out_1.gate_rand = vec4<f32>(_e11.x, _e16.x, _e21.x, _e26.x);
    out_1.gaussian = vec4<f32>(_e11.y, _e16.y, _e21.y, _e26.y);
    out_1.lerp = (s_2 - cell);
    let _e42 = out_1;
    return _e42;
}

fn glint_cell_hits(r: GlintSlopeRand, one_hit: f32, smooth_width: f32, mean: f32, deviation: f32, count: f32) -> f32 {
    var gate: vec4<f32>;

    if (smooth_width > 0.0000001f) {
        gate = saturate(((r.gate_rand - vec4((one_hit + smooth_width))) / vec4((-2f * smooth_width))));
    } else {
        gate = select(vec4(0f), vec4(1f), (r.gate_rand < vec4(one_hit)));
    }
    let gauss = clamp(floor(((r.gaussian * deviation) + vec4(mean))), vec4(0f), vec4(count));
    let _e35 = gate;
    let hits = (_e35 * (vec4(1f) + gauss));
    let x0_ = mix(hits.x, hits.z, r.lerp.x);
    let x1_ = mix(hits.y, hits.w, r.lerp.x);
    return mix(x0_, x1_, r.lerp.y);
}

fn glint_simplex(uv_1: vec2<f32>) -> GlintSimplex {
    let skewed = vec2<f32>((uv_1.x - (0.57735026f * uv_1.y)), (1.1547005f * uv_1.y));
    let base = floor(skewed);
    let f = (skewed - base);
    let fz = ((1f - f.x) - f.y);
    let s_3 = select(0f, 1f, (fz < 0f));
    let s2_ = ((2f * s_3) - 1f);
    return GlintSimplex(vec2<i32>(base), i32(s_3), vec3<f32>((-(fz) * s2_), (s_3 - (f.y * s2_)), (s_3 - (f.x * s2_))));
}

fn glint_sample_grid(params: GlintParams, grid: GlintGrid, slope_1: vec2<f32>, target_ndf: f32, poly_normals_3: bool) -> f32 {
    let _e6 = glint_simplex(grid.uv);
    let id = _e6.id;
    let si = _e6.si;
    let c0_ = (id + vec2<i32>(si, si));
    let c1_ = (id + vec2<i32>(si, (1i - si)));
    let c2_ = (id + vec2<i32>((1i - si), si));
    let bary = _e6.bary;
    let _e29 = glint_pcg3d(vec3<u32>((bitcast<u32>(c0_.x) + 2147483648u), (bitcast<u32>(c0_.y) + 2147483648u), grid.seed));
    let _e30 = glint_unit3_(_e29);
    let _e39 = glint_pcg3d(vec3<u32>((bitcast<u32>(c1_.x) + 2147483648u), (bitcast<u32>(c1_.y) + 2147483648u), grid.seed));
    let _e40 = glint_unit3_(_e39);
    let _e49 = glint_pcg3d(vec3<u32>((bitcast<u32>(c2_.x) + 2147483648u), (bitcast<u32>(c2_.y) + 2147483648u), grid.seed));
    let _e50 = glint_unit3_(_e49);
    let _e53 = glint_slope_rand(params.micro_roughness, slope_1, _e30.yz, poly_normals_3);
    let _e56 = glint_slope_rand(params.micro_roughness, slope_1, _e40.yz, poly_normals_3);
    let _e59 = glint_slope_rand(params.micro_roughness, slope_1, _e50.yz, poly_normals_3);
    let _e64 = glint_gaussian3_(vec3<f32>(_e30.x, _e40.x, _e50.x), poly_normals_3);
    let log_density = clamp(((_e64 * params.density_randomization) + vec3(params.log_density)), vec3(0f), vec3(50f));
    let count_1 = max(vec3(0.00000001f), (grid.cell_area * exp(log_density)));
    let blended = (count_1 * grid.weight);
    let p_4 = (params.micro_roughness * target_ndf);
    let one_hit_1 = (vec3(1f) - pow(vec3((1f - p_4)), blended));
    let others = max((blended - vec3(1f)), vec3(0f));
    let mean_1 = (others * p_4);
    let deviation_1 = sqrt((others * (p_4 * (1f - p_4))));
    let smooth_width_1 = ((0.1f * saturate((one_hit_1 * 10f))) * saturate(((vec3(1f) - one_hit_1) * 10f)));
    let _e121 = glint_cell_hits(_e53, one_hit_1.x, smooth_width_1.x, mean_1.x, deviation_1.x, blended.x);
    let _e127 = glint_cell_hits(_e56, one_hit_1.y, smooth_width_1.y, mean_1.y, deviation_1.y, blended.y);
    let _e133 = glint_cell_hits(_e59, one_hit_1.z, smooth_width_1.z, mean_1.z, deviation_1.z, blended.z);
    return dot((vec3<f32>(_e121, _e127, _e133) / count_1), bary);
}

fn glint_ellipse(duv_dx: vec2<f32>, duv_dy: vec2<f32>) -> GlintEllipse {
    var out_2: GlintEllipse;

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
    out_2.major_dir = select(vec2<f32>(1f, 0f), (e_5 * inverseSqrt(max(e_len2_, 0.0000000000000000000000000000000000001f))), (e_len2_ > 0.0000000000000000000000000000000000001f));
    out_2.major = max(sqrt(l1_), 0.000000000001f);
    let _e68 = out_2.major;
    out_2.minor = max(sqrt(l2_), (_e68 / 64f));
    let _e72 = out_2;
    return _e72;
}

fn glint_rotate(uv_2: vec2<f32>, angle: f32) -> vec2<f32> {
    let c_4 = cos(angle);
    let s_4 = sin(angle);
    return vec2<f32>(((c_4 * uv_2.x) + (s_4 * uv_2.y)), ((c_4 * uv_2.y) - (s_4 * uv_2.x)));
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

fn glint_tetra_weights(p_1: vec3<f32>, a: vec3<f32>, b: vec3<f32>, c_2: vec3<f32>, d: vec3<f32>) -> vec4<f32> {
    let c1_1 = (a - d);
    let c2_1 = (b - d);
    let c3_ = (c_2 - d);
    let q = (p_1 - d);
    let det = dot(c1_1, cross(c2_1, c3_));
    let inv = (1f / det);
    let w1_ = (dot(q, cross(c2_1, c3_)) * inv);
    let w2_ = (dot(c1_1, cross(q, c3_)) * inv);
    let w3_ = (dot(c1_1, cross(c2_1, q)) * inv);
    return vec4<f32>(w1_, w2_, w3_, (((1f - w1_) - w2_) - w3_));
}

fn glint_lod(e_1: GlintEllipse, screen_scale: f32) -> f32 {
    return clamp(log2(((e_1.minor * screen_scale) * 0.5f)), GLINT_MIN_LOD, GLINT_MAX_LOD);
}

fn glint_footprint_cell(e_2: GlintEllipse, screen_scale_1: f32) -> GlintFootprintCell {
    var out_3: GlintFootprintCell;

    let ratio_e = min((e_2.major / (e_2.minor + (0.00000001f * e_2.major))), GLINT_MAX_RATIO);
    let _e11 = glint_lod(e_2, screen_scale_1);
    let lod0_1 = floor(_e11);
    let lod_lerp = (_e11 - lod0_1);
    let ratio0_1 = max(exp2(floor(log2(max(ratio_e, 1f)))), 1f);
    let ratio1_ = (ratio0_1 * 2f);
    let ratio_lerp = saturate(((ratio_e - ratio0_1) / (ratio1_ - ratio0_1)));
    let q_1 = (0.7853982f / max(ratio0_1, 2f));
    let per_pi = (4f * max(ratio0_1, 2f));
    let theta_3 = atan2(-(e_2.major_dir.x), e_2.major_dir.y);
    let theta_q = (theta_3 / q_1);
    let h0_ = floor(theta_q);
    let theta_lerp_1 = saturate((theta_q - h0_));
    let i0_ = (h0_ - (per_pi * floor((h0_ / per_pi))));
    let i1_ = ((i0_ + 1f) - (per_pi * floor(((i0_ + 1f) / per_pi))));
    let theta_bin0_ = (i0_ * q_1);
    let theta_bin_h = ((i0_ + 0.5f) * q_1);
    let theta_bin1_ = (i1_ * q_1);
    out_3.theta_lerp = theta_lerp_1;
    out_3.ratio_lerp = ratio_lerp;
    out_3.lod_lerp = lod_lerp;
    out_3.center = (ratio0_1 == 1f);
    out_3.bin0_ = theta_bin0_;
    out_3.bin_h = theta_bin_h;
    out_3.bin1_ = theta_bin1_;
    out_3.lod0_ = lod0_1;
    out_3.ratio0_ = ratio0_1;
    let _e74 = out_3;
    return _e74;
}

fn glint_tetra(e_3: GlintEllipse, screen_scale_2: f32) -> GlintTetra {
    var theta_lerp: f32;
    var p0_: vec3<f32>;
    var p1_: vec3<f32>;
    var p2_: vec3<f32>;
    var p3_1: vec3<f32>;
    var local_1: bool;
    var out_4: GlintTetra;

    let _e2 = glint_footprint_cell(e_3, screen_scale_2);
    theta_lerp = _e2.theta_lerp;
    let ratio_lerp_1 = _e2.ratio_lerp;
    let lod_lerp_1 = _e2.lod_lerp;
    let center_1 = _e2.center;
    if center_1 {
        let a_6 = vec3<f32>(0f, 1f, 0f);
        let b_4 = vec3<f32>(0f, 0f, 0f);
        let c_5 = vec3<f32>(1f, 1f, 0f);
        let d_5 = vec3<f32>(0f, 1f, 1f);
        let ee = vec3<f32>(0f, 0f, 1f);
        let f_1 = vec3<f32>(1f, 1f, 1f);
        if (lod_lerp_1 > (1f - ratio_lerp_1)) {
            let _e45 = theta_lerp;
            if (((lod_lerp_1 - (1f - ratio_lerp_1)) / max(ratio_lerp_1, 0.00000001f)) > _e45) {
                p0_ = a_6;
                p1_ = ee;
                p2_ = d_5;
                p3_1 = f_1;
            } else {
                p0_ = f_1;
                p1_ = ee;
                p2_ = c_5;
                p3_1 = a_6;
            }
        } else {
            p0_ = b_4;
            p1_ = a_6;
            p2_ = c_5;
            p3_1 = ee;
        }
        let _e47 = theta_lerp;
        theta_lerp = (_e47 * ratio_lerp_1);
    } else {
        let a_7 = vec3<f32>(0f, 1f, 0f);
        let b_5 = vec3<f32>(0f, 0f, 0f);
        let c_6 = vec3<f32>(0.5f, 1f, 0f);
        let d_6 = vec3<f32>(1f, 0f, 0f);
        let ee_1 = vec3<f32>(1f, 1f, 0f);
        let f_2 = vec3<f32>(0f, 1f, 1f);
        let g_1 = vec3<f32>(0f, 0f, 1f);
        let h_1 = vec3<f32>(0.5f, 1f, 1f);
        let i = vec3<f32>(1f, 0f, 1f);
        let j = vec3<f32>(1f, 1f, 1f);
        let _e89 = theta_lerp;
        if (_e89 < 0.5f) {
            let _e94 = theta_lerp;
            local_1 = ((_e94 * 2f) < ratio_lerp_1);
        } else {
            local_1 = false;
        }
        let _e99 = local_1;
        if _e99 {
            if (lod_lerp_1 > (1f - ratio_lerp_1)) {
                let _e109 = theta_lerp;
                if (((lod_lerp_1 - (1f - ratio_lerp_1)) / max(ratio_lerp_1, 0.00000001f)) > ((_e109 * 2f) / max(ratio_lerp_1, 0.00000001f))) {
                    p0_ = a_7;
                    p1_ = f_2;
                    p2_ = h_1;
                    p3_1 = g_1;
                } else {
                    p0_ = c_6;
                    p1_ = a_7;
                    p2_ = h_1;
                    p3_1 = g_1;
                }
            } else {
                p0_ = b_5;
                p1_ = a_7;
                p2_ = c_6;
                p3_1 = g_1;
            }
        } else {
            let _e116 = theta_lerp;
            if ((1f - ((_e116 - 0.5f) * 2f)) > ratio_lerp_1) {
                if (lod_lerp_1 < (1f - ratio_lerp_1)) {
                    let half_width = (0.5f * (1f - ratio_lerp_1));
                    let _e136 = theta_lerp;
                    if ((lod_lerp_1 / max((1f - ratio_lerp_1), 0.00000001f)) > ((_e136 - (0.5f - half_width)) / max((2f * half_width), 0.00000001f))) {
                        p0_ = b_5;
                        p1_ = g_1;
                        p2_ = i;
                        p3_1 = c_6;
                    } else {
                        p0_ = d_6;
                        p1_ = b_5;
                        p2_ = c_6;
                        p3_1 = i;
                    }
                } else {
                    p0_ = c_6;
                    p1_ = g_1;
                    p2_ = h_1;
                    p3_1 = i;
                }
            } else {
                if (lod_lerp_1 > (1f - ratio_lerp_1)) {
                    let _e155 = theta_lerp;
                    if (((lod_lerp_1 - (1f - ratio_lerp_1)) / max(ratio_lerp_1, 0.00000001f)) > ((((_e155 - 0.5f) * 2f) - (1f - ratio_lerp_1)) / max(ratio_lerp_1, 0.00000001f))) {
                        p0_ = c_6;
                        p1_ = j;
                        p2_ = h_1;
                        p3_1 = i;
                    } else {
                        p0_ = ee_1;
                        p1_ = i;
                        p2_ = c_6;
                        p3_1 = j;
                    }
                } else {
                    p0_ = d_6;
                    p1_ = ee_1;
                    p2_ = c_6;
                    p3_1 = i;
                }
            }
        }
    }
    let _e169 = p0_;
    out_4.p0_ = _e169;
    let _e171 = p1_;
    out_4.p1_ = _e171;
    let _e173 = p2_;
    out_4.p2_ = _e173;
    let _e175 = p3_1;
    out_4.p3_ = _e175;
    let _e177 = theta_lerp;
    let _e179 = p0_;
    let _e180 = p1_;
    let _e181 = p2_;
    let _e182 = p3_1;
    let _e183 = glint_tetra_weights(vec3<f32>(_e177, ratio_lerp_1, lod_lerp_1), _e179, _e180, _e181, _e182);
    out_4.w = _e183;
    out_4.center = center_1;
    out_4.bin0_ = _e2.bin0_;
    out_4.bin_h = _e2.bin_h;
    out_4.bin1_ = _e2.bin1_;
    out_4.lod0_ = _e2.lod0_;
    out_4.ratio0_ = _e2.ratio0_;
    let _e195 = out_4;
    return _e195;
}

fn glint_vertex_grid(uv_4: vec2<f32>, p_2: vec3<f32>, weight_1: f32, center: bool, bin0_: f32, bin_h: f32, bin1_: f32, lod0_: f32, ratio0_: f32) -> GlintGrid {
    var theta_2: f32;
    var local_2: bool;

    let rot_index = (p_2.x * 2f);
    theta_2 = select(select(bin1_, bin_h, (rot_index < 1.5f)), bin0_, (rot_index < 0.5f));
    if center {
        local_2 = (p_2.y == 0f);
    } else {
        local_2 = false;
    }
    let _e25 = local_2;
    if _e25 {
        theta_2 = 0f;
    }
    let ratio_2 = select(ratio0_, (ratio0_ * 2f), (p_2.y > 0.5f));
    let lod_2 = (lod0_ + p_2.z);
    let _e35 = theta_2;
    let _e36 = glint_make_grid(uv_4, lod_2, _e35, ratio_2, weight_1);
    return _e36;
}

fn glint_grids(uv_5: vec2<f32>, e_4: GlintEllipse, screen_scale_3: f32) -> GlintGrids {
    var out_5: GlintGrids;

    let _e3 = glint_tetra(e_4, screen_scale_3);
    let _e15 = glint_vertex_grid(uv_5, _e3.p0_, _e3.w.x, _e3.center, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g0_ = _e15;
    let _e26 = glint_vertex_grid(uv_5, _e3.p1_, _e3.w.y, _e3.center, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g1_ = _e26;
    let _e37 = glint_vertex_grid(uv_5, _e3.p2_, _e3.w.z, _e3.center, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g2_ = _e37;
    let _e48 = glint_vertex_grid(uv_5, _e3.p3_, _e3.w.w, _e3.center, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g3_ = _e48;
    let _e49 = out_5;
    return _e49;
}

fn glint_ndf(params_1: GlintParams, grids: GlintGrids, slope_2: vec2<f32>, d_1: f32, d_max: f32, poly_normals_4: bool) -> f32 {
    let target_ndf_1 = (d_1 / d_max);
    let _e8 = glint_sample_grid(params_1, grids.g0_, slope_2, target_ndf_1, poly_normals_4);
    let _e10 = glint_sample_grid(params_1, grids.g1_, slope_2, target_ndf_1, poly_normals_4);
    let _e13 = glint_sample_grid(params_1, grids.g2_, slope_2, target_ndf_1, poly_normals_4);
    let _e16 = glint_sample_grid(params_1, grids.g3_, slope_2, target_ndf_1, poly_normals_4);
    let sum = (((_e8 + _e10) + _e13) + _e16);
    return (min((sum / params_1.micro_roughness), 20f) * d_max);
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
    let v_6 = _e41.v;
    n = _e41.n;
    let _e45 = n;
    let _e47 = weft_tangent_frame(_e45, in_1.world_tangent);
    let _e48 = n;
    let _e49 = weft_main_light_geometry(_e48, v_6);
    let _e50 = weft_main_light_radiance();
    let f0_2 = mix(vec3(0.04f), base_1, metallic);
    let diffuse_albedo = (base_1 * (1f - metallic));
    let _e59 = weft_v_smith_ggx_correlated(_e49.n_dot_v, _e49.n_dot_l, roughness_7);
    let _e61 = weft_env_brdf_lut(_e49.n_dot_v, roughness_7);
    let _e62 = weft_env_brdf_from_lut(f0_2, _e61);
    let kd = max((vec3(1f) - _e62), vec3(0f));
    let _e69 = n;
    let _e71 = weft_d_ggx_nh(_e69, _e49.h, roughness_7);
    let _e74 = weft_f_schlick(f0_2, _e49.v_dot_h);
    let specular = ((_e71 * _e59) * _e74);
    let _e76 = weft_diffuse_lambert(diffuse_albedo);
    let direct = ((((kd * _e76) + specular) * _e50) * _e49.n_dot_l);
    let _e83 = n;
    let _e85 = weft_prefiltered_radiance(reflect(-(v_6), _e83), roughness_7);
    let _e88 = n;
    let _e89 = weft_sh_irradiance(_e88);
    let indirect = (((_e85 * _e62) * ao) + (((_e89 * ao) * kd) * diffuse_albedo));
    color = (direct + indirect);
    let _e98 = material.flake_intensity;
    let intensity = max(_e98, 0f);
    if (intensity > 0f) {
        local = (_e49.n_dot_l > 0f);
    } else {
        local = false;
    }
    let _e109 = local;
    if _e109 {
        let _e112 = material.flake_roughness;
        let r_f = clamp(_e112, 0.05f, 1f);
        let _e116 = n;
        let _e118 = weft_d_ggx_nh(_e116, _e49.h, r_f);
        let _e120 = weft_d_ggx(1f, r_f);
        let _e123 = material.flake_color;
        let flake_f0_ = saturate(_e123.xyz);
        let _e128 = weft_v_smith_ggx_correlated(_e49.n_dot_v, _e49.n_dot_l, r_f);
        {
            {
                let slope_3 = vec2<f32>(dot(_e47[0], _e49.h), dot(_e47[1], _e49.h));
                let _e137 = glitter_params();
                let _e138 = glint_ellipse(duv_dx_1, duv_dy_1);
                let _e141 = material.flake_size;
                let screen_scale_4 = clamp(_e141, 1f, 8f);
                let _e145 = glint_grids(_e5, _e138, screen_scale_4);
                let _e147 = glint_ndf(_e137, _e145, slope_3, _e118, _e120, false);
                d_flakes = _e147;
            }
            let _e148 = color;
            let _e149 = d_flakes;
            let _e153 = weft_f_schlick(flake_f0_, _e49.v_dot_h);
            color = (_e148 + (((((intensity * _e149) * _e128) * _e153) * _e50) * _e49.n_dot_l));
        }
    }
    let _e159 = color;
    let radiance = clamp(_e159, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
