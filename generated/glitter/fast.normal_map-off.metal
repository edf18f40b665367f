// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct type_5 {
    metal::float4 inner[9];
};
struct WeftFrame {
    metal::float4x4 view_proj;
    metal::float4x4 view;
    metal::float4 camera_position;
    metal::float4 light_direction;
    metal::float4 light_color;
    type_5 sh;
    metal::float4 params;
    metal::float4 viewport;
};
struct WeftObject {
    metal::float4x4 model;
    metal::float4x4 normal_matrix;
};
struct WeftMaterial {
    metal::float4 base_color;
    float metallic;
    float smoothness;
    char _pad3[8];
    metal::float4 base_map_st;
    float normal_strength;
    float occlusion_strength;
    char _pad6[8];
    metal::float4 flake_color;
    float flake_intensity;
    float flake_density;
    float flake_size;
    float flake_roughness;
    float twinkle;
    float density_variation;
    char _pad13[8];
};
struct WeftSurface {
    metal::float3 v;
    metal::float3 n;
};
struct WeftLightGeometry {
    metal::float3 l;
    metal::packed_float3 h;
    float n_dot_v;
    float n_dot_l;
    float n_dot_h;
    float v_dot_h;
    char _pad6[4];
};
struct WeftVertexInput {
    metal::float3 position;
    metal::float3 normal;
    metal::float4 tangent;
    metal::float2 uv0_;
    char _pad4[8];
};
struct WeftVaryings {
    metal::float4 clip_position;
    metal::float3 world_position;
    metal::float3 world_normal;
    metal::float4 world_tangent;
    metal::float2 uv0_;
    char _pad5[8];
};
struct GlintGrid {
    metal::float2 uv;
    uint seed;
    float cell_area;
    float weight;
    char _pad4[4];
};
struct GlintParams {
    float log_density;
    float micro_roughness;
    float density_randomization;
};
struct GlintSimplex {
    metal::int2 id;
    int si;
    char _pad2[4];
    metal::float3 bary;
};
struct GlintEllipse {
    metal::float2 major_dir;
    float major;
    float minor;
};
struct GlintFootprintCell {
    float theta_lerp;
    float ratio_lerp;
    float lod_lerp;
    bool center;
    char _pad4[3];
    float bin0_;
    float bin_h;
    float bin1_;
    float lod0_;
    float ratio0_;
};
struct GlintTetraFast {
    uint codes;
    char _pad1[12];
    metal::float4 w;
    float bin0_;
    float bin_h;
    float bin1_;
    float lod0_;
    float ratio0_;
    char _pad7[12];
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SMOOTH = 2u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float GLINT_TAU = 6.2831855;
constant float GLINT_HALF_PI = 1.5707964;
constant float GLINT_TABLE_SIZE = 64.0;
constant float GLINT_MIN_LOD = -20.0;
constant float GLINT_MAX_LOD = 20.0;
constant float GLINT_MAX_RATIO = 16.0;
constant uint GLINT_TET_A_UP = 36292u;
constant uint GLINT_TET_A_DOWN = 36165u;
constant uint GLINT_TET_A_LOW = 34112u;
constant uint GLINT_TET_B_UP = 23168u;
constant uint GLINT_TET_B_DOWN = 42242u;
constant uint GLINT_TET_B_HIGH = 44421u;
constant uint GLINT_TET_C_UP = 44517u;
constant uint GLINT_TET_C_DOWN = 58790u;
constant uint GLINT_TET_C_LOW = 42338u;
constant uint GLINT_TET_CENTER_UP = 60596u;
constant uint GLINT_TET_CENTER_DOWN = 18110u;
constant uint GLINT_TET_CENTER_LOW = 46659u;

float weft_pow5_(
    float x
) {
    float x2_ = x * x;
    return (x2_ * x2_) * x;
}

float weft_clamp_cos(
    float c
) {
    return metal::clamp(c, WEFT_MIN_N_DOT, 1.0);
}

float weft_clamp_roughness(
    float roughness
) {
    return metal::clamp(roughness, WEFT_MIN_ROUGHNESS, 1.0);
}

metal::float3 weft_safe_normalize(
    metal::float3 v,
    metal::float3 fallback
) {
    float len2_ = metal::dot(v, v);
    return (len2_ > 0.00000000000000000001) ? (v * metal::rsqrt(metal::max(len2_, 0.00000000000000000001))) : fallback;
}

metal::float3 weft_any_perpendicular(
    metal::float3 n_1
) {
    float s = (n_1.z >= 0.0) ? 1.0 : -1.0;
    float a_1 = -1.0 / (s + n_1.z);
    float b_1 = (n_1.x * n_1.y) * a_1;
    return metal::float3(1.0 + (((s * n_1.x) * n_1.x) * a_1), s * b_1, -(s) * n_1.x);
}

float weft_d_ggx(
    float n_dot_h,
    float roughness_1
) {
    float _e2 = weft_clamp_roughness(roughness_1);
    float a_2 = _e2 * _e2;
    float a2_ = a_2 * a_2;
    float noh = metal::saturate(n_dot_h);
    float one_minus_noh2_ = (1.0 - noh) * (1.0 + noh);
    float d_2 = one_minus_noh2_ + ((noh * noh) * a2_);
    return a2_ / ((WEFT_PI * d_2) * d_2);
}

float weft_d_ggx_nh(
    metal::float3 n_2,
    metal::float3 h,
    float roughness_2
) {
    float _e3 = weft_clamp_roughness(roughness_2);
    float a_3 = _e3 * _e3;
    float a2_1 = a_3 * a_3;
    float noh_1 = metal::saturate(metal::dot(n_2, h));
    metal::float3 nxh = metal::cross(n_2, h);
    float d_3 = metal::dot(nxh, nxh) + ((noh_1 * noh_1) * a2_1);
    return a2_1 / (WEFT_PI * metal::max(d_3 * d_3, 0.000000000000000000000000000001));
}

metal::float3 weft_f_schlick(
    metal::float3 f0_,
    float v_dot_h
) {
    float _e5 = weft_pow5_(1.0 - metal::saturate(v_dot_h));
    return f0_ + ((metal::float3(1.0) - f0_) * _e5);
}

float weft_v_smith_ggx_correlated(
    float n_dot_v,
    float n_dot_l,
    float roughness_3
) {
    float _e3 = weft_clamp_roughness(roughness_3);
    float a_4 = _e3 * _e3;
    float a2_2 = a_4 * a_4;
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = _e7 * metal::sqrt(((_e6 * _e6) * (1.0 - a2_2)) + a2_2);
    float ll = _e6 * metal::sqrt(((_e7 * _e7) * (1.0 - a2_2)) + a2_2);
    return 0.5 / (lv + ll);
}

metal::float3 weft_diffuse_lambert(
    metal::float3 albedo
) {
    return albedo * WEFT_INV_PI;
}

metal::float3 weft_env_brdf_from_lut(
    metal::float3 f0_1,
    metal::float2 scale_bias
) {
    metal::float2 sb = metal::saturate(scale_bias);
    return (f0_1 * sb.x) + metal::float3(sb.y);
}

metal::float3 weft_main_light_direction(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_direction;
    metal::float3 _e8 = weft_safe_normalize(_e2.xyz, metal::float3(0.0, 0.0, 1.0));
    return _e8;
}

metal::float3 weft_main_light_radiance(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_color;
    return metal::max(_e2.xyz, metal::float3(0.0));
}

metal::float3 weft_view_direction(
    metal::float3 world_position,
    metal::float3 fallback_1,
    constant WeftFrame& weft_frame
) {
    metal::float4 _e4 = weft_frame.camera_position;
    metal::float3 _e7 = weft_safe_normalize(_e4.xyz - world_position, fallback_1);
    return _e7;
}

metal::float3 weft_sh_irradiance(
    metal::float3 n_3,
    constant WeftFrame& weft_frame
) {
    metal::float3 e = {};
    type_5 sh = weft_frame.sh;
    e = sh.inner[0].xyz * 0.282095;
    metal::float3 _e9 = e;
    e = _e9 + (sh.inner[1].xyz * (0.488603 * n_3.y));
    metal::float3 _e17 = e;
    e = _e17 + (sh.inner[2].xyz * (0.488603 * n_3.z));
    metal::float3 _e25 = e;
    e = _e25 + (sh.inner[3].xyz * (0.488603 * n_3.x));
    metal::float3 _e33 = e;
    e = _e33 + (sh.inner[4].xyz * ((1.092548 * n_3.x) * n_3.y));
    metal::float3 _e43 = e;
    e = _e43 + (sh.inner[5].xyz * ((1.092548 * n_3.y) * n_3.z));
    metal::float3 _e53 = e;
    e = _e53 + (sh.inner[6].xyz * (0.315392 * (((3.0 * n_3.z) * n_3.z) - 1.0)));
    metal::float3 _e67 = e;
    e = _e67 + (sh.inner[7].xyz * ((1.092548 * n_3.x) * n_3.z));
    metal::float3 _e77 = e;
    e = _e77 + (sh.inner[8].xyz * (0.546274 * ((n_3.x * n_3.x) - (n_3.y * n_3.y))));
    metal::float3 _e91 = e;
    return metal::max(_e91, metal::float3(0.0));
}

float weft_specular_mip(
    float roughness_4,
    constant WeftFrame& weft_frame
) {
    float r = metal::saturate(roughness_4);
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return (r * (1.7 - (0.7 * r))) * max_mip;
}

metal::float3 weft_prefiltered_radiance(
    metal::float3 dir,
    float roughness_5,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip(roughness_5, weft_frame);
    metal::float4 c_4 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_4.xyz, metal::float3(0.0));
}

metal::float2 weft_env_brdf_lut(
    float n_dot_v_1,
    float roughness_6,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv_5 = metal::float2(metal::saturate(n_dot_v_1), metal::saturate(roughness_6));
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv_5, metal::level(0.0));
    return _e8.xy;
}

WeftSurface weft_surface(
    metal::float3 world_position_1,
    metal::float3 world_normal,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e6 = weft_view_direction(world_position_1, metal::float3(0.0, 0.0, 1.0), weft_frame);
    metal::float3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface {_e6, _e7};
}

WeftLightGeometry weft_main_light_geometry(
    metal::float3 n_4,
    metal::float3 v_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_1, n_4);
    float _e6 = weft_clamp_cos(metal::dot(n_4, v_1));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_4, _e2)), metal::saturate(metal::dot(n_4, _e4)), metal::saturate(metal::dot(v_1, _e4))};
}

WeftVaryings weft_forward_vertex(
    WeftVertexInput in_2,
    constant WeftFrame& weft_frame,
    constant WeftObject& weft_object
) {
    WeftVaryings out = {};
    metal::float4x4 model = weft_object.model;
    metal::float3x3 model3_ = metal::float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    metal::float4x4 nm = weft_object.normal_matrix;
    metal::float3x3 normal3_ = metal::float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    metal::float4 world = model * metal::float4(in_2.position, 1.0);
    float mirror = (metal::determinant(model3_) < 0.0) ? -1.0 : 1.0;
    float bitangent_sign = ((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror;
    metal::float4x4 _e43 = weft_frame.view_proj;
    out.clip_position = _e43 * metal::float4(world.xyz, 1.0);
    out.world_position = world.xyz;
    metal::float3 _e55 = weft_safe_normalize(normal3_ * in_2.normal, metal::float3(0.0));
    out.world_normal = _e55;
    metal::float3 _e62 = weft_safe_normalize(model3_ * in_2.tangent.xyz, metal::float3(0.0));
    out.world_tangent = metal::float4(_e62, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out;
    return _e66;
}

metal::float3x3 weft_tangent_frame(
    metal::float3 n_5,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_5 * metal::dot(n_5, t_in));
    float len2_1 = metal::dot(t_proj, t_proj);
    bool ok = len2_1 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_5);
    metal::float3 t = ok ? (t_proj * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : _e13;
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_2 = metal::cross(n_5, t) * s_1;
    return metal::float3x3(t, b_2, n_5);
}

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

metal::uint3 glint_pcg3d(
    metal::uint3 v_in
) {
    metal::uint3 v_2 = {};
    v_2 = (v_in * 1664525u) + metal::uint3(1013904223u);
    uint _e8 = v_2.x;
    uint _e10 = v_2.y;
    uint _e12 = v_2.z;
    v_2.x = _e8 + (_e10 * _e12);
    uint _e16 = v_2.y;
    uint _e18 = v_2.z;
    uint _e20 = v_2.x;
    v_2.y = _e16 + (_e18 * _e20);
    uint _e24 = v_2.z;
    uint _e26 = v_2.x;
    uint _e28 = v_2.y;
    v_2.z = _e24 + (_e26 * _e28);
    metal::uint3 _e31 = v_2;
    metal::uint3 _e32 = v_2;
    v_2 = _e31 ^ (_e32 >> metal::uint3(16u));
    uint _e38 = v_2.x;
    uint _e40 = v_2.y;
    uint _e42 = v_2.z;
    v_2.x = _e38 + (_e40 * _e42);
    uint _e46 = v_2.y;
    uint _e48 = v_2.z;
    uint _e50 = v_2.x;
    v_2.y = _e46 + (_e48 * _e50);
    uint _e54 = v_2.z;
    uint _e56 = v_2.x;
    uint _e58 = v_2.y;
    v_2.z = _e54 + (_e56 * _e58);
    metal::uint3 _e61 = v_2;
    return _e61;
}

float glint_hash13_(
    metal::float3 p_in
) {
    metal::float3 p3_ = {};
    p3_ = metal::fract(p_in * 0.1031);
    metal::float3 _e5 = p3_;
    metal::float3 _e6 = p3_;
    metal::float3 _e7 = p3_;
    p3_ = _e5 + metal::float3(metal::dot(_e6, _e7.yzx + metal::float3(33.33)));
    float _e16 = p3_.x;
    float _e18 = p3_.y;
    float _e21 = p3_.z;
    return metal::fract((_e16 + _e18) * _e21);
}

metal::int2 naga_f2i32(metal::float2 value) {
    return static_cast<metal::int2>(metal::clamp(value, -2147483600.0, 2147483500.0));
}

int naga_f2i32(float value) {
    return static_cast<int>(metal::clamp(value, -2147483600.0, 2147483500.0));
}

GlintSimplex glint_simplex(
    metal::float2 uv_1
) {
    metal::float2 skewed = metal::float2(uv_1.x - (0.57735026 * uv_1.y), 1.1547005 * uv_1.y);
    metal::float2 base = metal::floor(skewed);
    metal::float2 f = skewed - base;
    float fz = (1.0 - f.x) - f.y;
    float s_2 = (fz < 0.0) ? 1.0 : 0.0;
    float s2_ = (2.0 * s_2) - 1.0;
    return GlintSimplex {naga_f2i32(base), naga_f2i32(s_2), {}, metal::float3(-(fz) * s2_, s_2 - (f.y * s2_), s_2 - (f.x * s2_))};
}

GlintEllipse glint_ellipse(
    metal::float2 duv_dx,
    metal::float2 duv_dy
) {
    GlintEllipse out_1 = {};
    float a_5 = (duv_dx.x * duv_dx.x) + (duv_dy.x * duv_dy.x);
    float b_3 = (duv_dx.x * duv_dx.y) + (duv_dy.x * duv_dy.y);
    float d_4 = (duv_dx.y * duv_dx.y) + (duv_dy.y * duv_dy.y);
    float half_trace = 0.5 * (a_5 + d_4);
    float disc = metal::sqrt(metal::max(((0.25 * (a_5 - d_4)) * (a_5 - d_4)) + (b_3 * b_3), 0.0));
    float l1_ = half_trace + disc;
    float l2_ = metal::max(half_trace - disc, 0.0);
    metal::float2 e_a = metal::float2(b_3, l1_ - a_5);
    metal::float2 e_b = metal::float2(l1_ - d_4, b_3);
    metal::float2 e_5 = (metal::dot(e_a, e_a) > metal::dot(e_b, e_b)) ? e_a : e_b;
    float e_len2_ = metal::dot(e_5, e_5);
    out_1.major_dir = (e_len2_ > 0.0000000000000000000000000000000000001) ? (e_5 * metal::rsqrt(metal::max(e_len2_, 0.0000000000000000000000000000000000001))) : metal::float2(1.0, 0.0);
    out_1.major = metal::max(metal::sqrt(l1_), 0.000000000001);
    float _e68 = out_1.major;
    out_1.minor = metal::max(metal::sqrt(l2_), _e68 / 64.0);
    GlintEllipse _e72 = out_1;
    return _e72;
}

metal::float2 glint_rotate(
    metal::float2 uv_2,
    float angle
) {
    float c_5 = metal::cos(angle);
    float s_3 = metal::sin(angle);
    return metal::float2((c_5 * uv_2.x) + (s_3 * uv_2.y), (c_5 * uv_2.y) - (s_3 * uv_2.x));
}

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

uint glint_grid_seed(
    float lod,
    float theta,
    float ratio
) {
    float t_1 = theta - (GLINT_TAU * metal::trunc(theta / GLINT_TAU));
    float _e10 = glint_hash13_(metal::float3(lod, t_1, ratio));
    return naga_f2u32(metal::min(_e10 * 4294967300.0, 4294967000.0));
}

GlintGrid glint_make_grid(
    metal::float2 uv_3,
    float lod_1,
    float theta_1,
    float ratio_1,
    float weight
) {
    GlintGrid g = {};
    metal::float2 _e7 = glint_rotate(uv_3, theta_1);
    g.uv = (_e7 * metal::exp2(-(lod_1))) / metal::float2(1.0, ratio_1);
    uint _e15 = glint_grid_seed(lod_1, theta_1, ratio_1);
    g.seed = _e15;
    g.cell_area = ratio_1 * metal::exp2(2.0 * lod_1);
    g.weight = weight;
    GlintGrid _e22 = g;
    return _e22;
}

metal::float4 glint_tetra_weights(
    metal::float3 p,
    metal::float3 a,
    metal::float3 b,
    metal::float3 c_1,
    metal::float3 d
) {
    metal::float3 c1_ = a - d;
    metal::float3 c2_ = b - d;
    metal::float3 c3_ = c_1 - d;
    metal::float3 q = p - d;
    float det = metal::dot(c1_, metal::cross(c2_, c3_));
    float inv = 1.0 / det;
    float w1_ = metal::dot(q, metal::cross(c2_, c3_)) * inv;
    float w2_ = metal::dot(c1_, metal::cross(q, c3_)) * inv;
    float w3_ = metal::dot(c1_, metal::cross(c2_, q)) * inv;
    return metal::float4(w1_, w2_, w3_, ((1.0 - w1_) - w2_) - w3_);
}

float glint_lod(
    GlintEllipse e_1,
    float screen_scale
) {
    return metal::clamp(metal::log2((e_1.minor * screen_scale) * 0.5), GLINT_MIN_LOD, GLINT_MAX_LOD);
}

GlintFootprintCell glint_footprint_cell(
    GlintEllipse e_2,
    float screen_scale_1
) {
    GlintFootprintCell out_2 = {};
    float ratio_e = metal::min(e_2.major / (e_2.minor + (0.00000001 * e_2.major)), GLINT_MAX_RATIO);
    float _e11 = glint_lod(e_2, screen_scale_1);
    float lod0_ = metal::floor(_e11);
    float lod_lerp = _e11 - lod0_;
    float ratio0_ = metal::max(metal::exp2(metal::floor(metal::log2(metal::max(ratio_e, 1.0)))), 1.0);
    float ratio1_ = ratio0_ * 2.0;
    float ratio_lerp = metal::saturate((ratio_e - ratio0_) / (ratio1_ - ratio0_));
    float q_1 = 0.7853982 / metal::max(ratio0_, 2.0);
    float per_pi = 4.0 * metal::max(ratio0_, 2.0);
    float theta_2 = metal::atan2(-(e_2.major_dir.x), e_2.major_dir.y);
    float theta_q = theta_2 / q_1;
    float h0_ = metal::floor(theta_q);
    float theta_lerp = metal::saturate(theta_q - h0_);
    float i0_ = h0_ - (per_pi * metal::floor(h0_ / per_pi));
    float i1_ = (i0_ + 1.0) - (per_pi * metal::floor((i0_ + 1.0) / per_pi));
    float theta_bin0_ = i0_ * q_1;
    float theta_bin_h = (i0_ + 0.5) * q_1;
    float theta_bin1_ = i1_ * q_1;
    out_2.theta_lerp = theta_lerp;
    out_2.ratio_lerp = ratio_lerp;
    out_2.lod_lerp = lod_lerp;
    out_2.center = ratio0_ == 1.0;
    out_2.bin0_ = theta_bin0_;
    out_2.bin_h = theta_bin_h;
    out_2.bin1_ = theta_bin1_;
    out_2.lod0_ = lod0_;
    out_2.ratio0_ = ratio0_;
    GlintFootprintCell _e74 = out_2;
    return _e74;
}

float glint_normal_fast(
    uint h_1
) {
    float x_2 = metal::fma(static_cast<float>(h_1), 0.0000000004656613, -1.0);
    float x2_1 = x_2 * x_2;
    return x_2 * (1.2225 + (x2_1 * (0.75468 + (x2_1 * (-1.263127 + (x2_1 * 1.568366))))));
}

float glint_corner_hits(
    uint ax,
    uint ay,
    float gate_a,
    float gate_b,
    float deviation,
    float mean1_
) {
    uint x_1 = {};
    uint y = {};
    uint z = {};
    uint w = {};
    x_1 = ax + (ay * 1860535849u);
    uint _e10 = x_1;
    y = ay + (_e10 * 220351156u);
    uint _e16 = x_1;
    uint _e17 = y;
    z = 220351156u + (_e16 * _e17);
    uint _e22 = y;
    uint _e23 = z;
    w = 1860535849u + (_e22 * _e23);
    uint _e27 = x_1;
    uint _e28 = x_1;
    x_1 = _e27 ^ (_e28 >> 16u);
    uint _e32 = y;
    uint _e33 = y;
    y = _e32 ^ (_e33 >> 16u);
    uint _e37 = z;
    uint _e38 = z;
    z = _e37 ^ (_e38 >> 16u);
    uint _e42 = w;
    uint _e43 = w;
    w = _e42 ^ (_e43 >> 16u);
    uint _e47 = x_1;
    uint _e48 = y;
    uint _e49 = w;
    x_1 = _e47 + (_e48 * _e49);
    uint _e52 = y;
    uint _e53 = z;
    uint _e54 = x_1;
    y = _e52 + (_e53 * _e54);
    uint _e57 = x_1;
    float gate = metal::saturate(metal::fma(static_cast<float>(_e57), gate_a, gate_b));
    uint _e61 = y;
    float _e62 = glint_normal_fast(_e61);
    float count = metal::max(metal::floor(metal::fma(_e62, deviation, mean1_)), 1.0);
    return gate * count;
}

metal::uint2 naga_f2u32(metal::float2 value) {
    return static_cast<metal::uint2>(metal::clamp(value, 0.0, 4294967000.0));
}

float glint_cell_fast(
    GlintParams params,
    GlintGrid grid,
    metal::int2 c_2,
    metal::float2 s_slope,
    float p_1,
    float log2_q
) {
    metal::uint3 _e16 = glint_pcg3d(metal::uint3(as_type<uint>(c_2.x) + 2147483648u, as_type<uint>(c_2.y) + 2147483648u, grid.seed));
    float _e18 = glint_normal_fast(_e16.x);
    float log_density = metal::clamp((_e18 * params.density_randomization) + params.log_density, 0.0, 50.0);
    float count_1 = metal::max(0.00000001, grid.cell_area * metal::exp(log_density));
    float blended = count_1 * grid.weight;
    float miss = metal::exp2(blended * log2_q);
    float one_hit = 1.0 - miss;
    float others = metal::max(blended - 1.0, 0.0);
    float mean1_1 = (others * p_1) + 1.0;
    float deviation_1 = metal::sqrt(others * (p_1 * (1.0 - p_1)));
    float width = metal::max((0.1 * metal::saturate(one_hit * 10.0)) * metal::saturate(miss * 10.0), 0.000000000000000000000000000001);
    float inv_1 = 0.5 / width;
    float gate_a_1 = inv_1 * -0.00000000023283064;
    float gate_b_1 = metal::fma(one_hit, inv_1, 0.5);
    metal::float2 s_4 = metal::fma(static_cast<metal::float2>(_e16.yz >> metal::uint2(8u)), metal::float2(0.0000038146973), s_slope);
    metal::float2 cell = metal::floor(s_4);
    metal::float2 l = s_4 - cell;
    metal::uint2 ci = naga_f2u32(cell);
    metal::uint2 t0_ = ci & metal::uint2(63u);
    metal::uint2 t1_ = (ci + metal::uint2(1u)) & metal::uint2(63u);
    metal::uint2 ax_1 = (metal::uint2(t0_.x, t1_.x) * 1664525u) + metal::uint2(1013904223u);
    metal::uint2 ay_1 = (metal::uint2(t0_.y, t1_.y) * 1664525u) + metal::uint2(1013904223u);
    float _e104 = glint_corner_hits(ax_1.x, ay_1.x, gate_a_1, gate_b_1, deviation_1, mean1_1);
    float _e107 = glint_corner_hits(ax_1.x, ay_1.y, gate_a_1, gate_b_1, deviation_1, mean1_1);
    float _e110 = glint_corner_hits(ax_1.y, ay_1.x, gate_a_1, gate_b_1, deviation_1, mean1_1);
    float _e113 = glint_corner_hits(ax_1.y, ay_1.y, gate_a_1, gate_b_1, deviation_1, mean1_1);
    float x0_ = metal::mix(_e104, _e110, l.x);
    float x1_ = metal::mix(_e107, _e113, l.x);
    return metal::mix(x0_, x1_, l.y) / count_1;
}

float glint_sample_grid_fast(
    GlintParams params_1,
    GlintGrid grid_1,
    metal::float2 s_slope_1,
    float p_2,
    float log2_q_1
) {
    float sum = 0.0;
    int k = 0;
    GlintSimplex _e6 = glint_simplex(grid_1.uv);
    metal::int2 id = _e6.id;
    int si = _e6.si;
    metal::float3 bary = _e6.bary;
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            int _e47 = k;
            k = as_type<int>(as_type<uint>(_e47) + as_type<uint>(1));
        }
        loop_init = false;
        int _e14 = k;
        if (_e14 < 3) {
        } else {
            break;
        }
        {
            int _e19 = k;
            int _e25 = k;
            metal::int2 c_6 = as_type<metal::int2>(as_type<metal::uint2>(id) + as_type<metal::uint2>(metal::int2((_e19 == 2) ? as_type<int>(as_type<uint>(1) - as_type<uint>(si)) : si, (_e25 == 1) ? as_type<int>(as_type<uint>(1) - as_type<uint>(si)) : si)));
            int _e33 = k;
            int _e38 = k;
            float b_4 = (_e38 == 0) ? _e6.bary.x : ((_e33 == 1) ? _e6.bary.y : _e6.bary.z);
            float _e42 = sum;
            float _e43 = glint_cell_fast(params_1, grid_1, c_6, s_slope_1, p_2, log2_q_1);
            sum = _e42 + (b_4 * _e43);
        }
    }
    float _e49 = sum;
    return _e49;
}

metal::float3 glint_vertex_of_code(
    uint c_3
) {
    uint rot = c_3 & 3u;
    return metal::float3((rot == 3u) ? 0.0 : (static_cast<float>(rot) * 0.5), static_cast<float>((c_3 >> 2u) & 1u), static_cast<float>(c_3 >> 3u));
}

GlintTetraFast glint_tetra_fast(
    GlintEllipse e_3,
    float screen_scale_2
) {
    bool local_1 = {};
    GlintTetraFast out_3 = {};
    GlintFootprintCell _e2 = glint_footprint_cell(e_3, screen_scale_2);
    float t_2 = _e2.theta_lerp;
    float r_1 = _e2.ratio_lerp;
    float l_1 = _e2.lod_lerp;
    bool upper = l_1 > (1.0 - r_1);
    float upper_left = (l_1 - (1.0 - r_1)) / metal::max(r_1, 0.00000001);
    float half_width = 0.5 * (1.0 - r_1);
    uint center_codes = upper ? ((upper_left > t_2) ? GLINT_TET_CENTER_UP : GLINT_TET_CENTER_DOWN) : GLINT_TET_CENTER_LOW;
    uint a_codes = upper ? ((upper_left > ((t_2 * 2.0) / metal::max(r_1, 0.00000001))) ? GLINT_TET_A_UP : GLINT_TET_A_DOWN) : GLINT_TET_A_LOW;
    uint b_codes = (l_1 < (1.0 - r_1)) ? (((l_1 / metal::max(1.0 - r_1, 0.00000001)) > ((t_2 - (0.5 - half_width)) / metal::max(2.0 * half_width, 0.00000001))) ? GLINT_TET_B_UP : GLINT_TET_B_DOWN) : GLINT_TET_B_HIGH;
    uint c_codes = upper ? ((upper_left > ((((t_2 - 0.5) * 2.0) - (1.0 - r_1)) / metal::max(r_1, 0.00000001))) ? GLINT_TET_C_UP : GLINT_TET_C_DOWN) : GLINT_TET_C_LOW;
    if (t_2 < 0.5) {
        local_1 = (t_2 * 2.0) < r_1;
    } else {
        local_1 = false;
    }
    bool prism_a = local_1;
    bool prism_b = (1.0 - ((t_2 - 0.5) * 2.0)) > r_1;
    uint codes = _e2.center ? center_codes : (prism_a ? a_codes : (prism_b ? b_codes : c_codes));
    metal::float3 point = metal::float3(_e2.center ? (t_2 * r_1) : t_2, r_1, l_1);
    out_3.codes = codes;
    metal::float3 _e103 = glint_vertex_of_code(codes & 15u);
    metal::float3 _e108 = glint_vertex_of_code((codes >> 4u) & 15u);
    metal::float3 _e113 = glint_vertex_of_code((codes >> 8u) & 15u);
    metal::float3 _e116 = glint_vertex_of_code(codes >> 12u);
    metal::float4 _e117 = glint_tetra_weights(point, _e103, _e108, _e113, _e116);
    out_3.w = _e117;
    out_3.bin0_ = _e2.bin0_;
    out_3.bin_h = _e2.bin_h;
    out_3.bin1_ = _e2.bin1_;
    out_3.lod0_ = _e2.lod0_;
    out_3.ratio0_ = _e2.ratio0_;
    GlintTetraFast _e128 = out_3;
    return _e128;
}

float glint_hits_fast(
    GlintParams params_2,
    metal::float2 uv_4,
    GlintEllipse e_4,
    float screen_scale_3,
    metal::float2 slope,
    float d_1,
    float d_max
) {
    float sum_1 = 0.0;
    uint i = 0u;
    GlintTetraFast _e7 = glint_tetra_fast(e_4, screen_scale_3);
    uint codes_1 = _e7.codes;
    float p_4 = params_2.micro_roughness * (d_1 / d_max);
    float log2_q_2 = metal::log2(1.0 - p_4);
    metal::float2 s_slope_2 = (metal::abs(slope) / metal::float2(params_2.micro_roughness)) + metal::float2(0.0000019073486);
    uint2 loop_bound_1 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e97 = i;
            i = _e97 + 1u;
        }
        loop_init_1 = false;
        uint _e26 = i;
        if (_e26 < 4u) {
        } else {
            break;
        }
        {
            uint _e30 = i;
            uint c_7 = (codes_1 >> (4u * _e30)) & 15u;
            uint rot_1 = c_7 & 3u;
            float theta_3 = (rot_1 == 0u) ? _e7.bin0_ : ((rot_1 == 1u) ? _e7.bin_h : ((rot_1 == 2u) ? _e7.bin1_ : 0.0));
            float ratio_2 = ((c_7 & 4u) != 0u) ? (_e7.ratio0_ * 2.0) : _e7.ratio0_;
            float lod_2 = _e7.lod0_ + static_cast<float>(c_7 >> 3u);
            uint _e76 = i;
            uint _e82 = i;
            uint _e88 = i;
            float w_1 = (_e88 == 0u) ? _e7.w.x : ((_e82 == 1u) ? _e7.w.y : ((_e76 == 2u) ? _e7.w.z : (((1.0 - _e7.w.x) - _e7.w.y) - _e7.w.z)));
            float _e92 = sum_1;
            GlintGrid _e93 = glint_make_grid(uv_4, lod_2, theta_3, ratio_2, w_1);
            float _e94 = glint_sample_grid_fast(params_2, _e93, s_slope_2, p_4, log2_q_2);
            sum_1 = _e92 + _e94;
        }
    }
    float _e99 = sum_1;
    return _e99;
}

GlintParams glitter_params(
    constant WeftMaterial& material
) {
    GlintParams p_3 = {};
    float _e4 = material.flake_density;
    p_3.log_density = 4.0 + (28.0 * metal::saturate(_e4));
    float _e13 = material.twinkle;
    p_3.micro_roughness = metal::exp2(metal::mix(-4.321928, -8.965784, metal::saturate(_e13)));
    float _e22 = material.density_variation;
    p_3.density_randomization = metal::clamp(_e22, 0.0, 4.0);
    GlintParams _e26 = p_3;
    return _e26;
}

struct vs_mainInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float4 tangent_1 [[attribute(2)]];
    metal::float2 uv0_ [[attribute(3)]];
};
struct vs_mainOutput {
    metal::float4 clip_position [[position]];
    metal::float3 world_position [[user(loc0), center_perspective]];
    metal::float3 world_normal [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
};
vertex vs_mainOutput vs_main(
  vs_mainInput varyings [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
) {
    const WeftVertexInput in = { varyings.position, varyings.normal, varyings.tangent_1, varyings.uv0_ };
    WeftVaryings _e1 = weft_forward_vertex(in, weft_frame, weft_object);
    const auto _tmp = _e1;
    return vs_mainOutput { _tmp.clip_position, _tmp.world_position, _tmp.world_normal, _tmp.world_tangent, _tmp.uv0_ };
}


struct fs_mainInput {
    metal::float3 world_position_2 [[user(loc0), center_perspective]];
    metal::float3 world_normal_1 [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
};
struct fs_mainOutput {
    metal::float4 member_1 [[color(0)]];
};
fragment fs_mainOutput fs_main(
  fs_mainInput varyings_1 [[stage_in]]
, metal::float4 clip_position [[position]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, metal::texturecube<float, metal::access::sample> weft_environment [[texture(0)]]
, metal::sampler weft_environment_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> weft_brdf_lut [[texture(1)]]
, metal::sampler weft_lut_sampler [[sampler(1)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> occlusion_map [[texture(3)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    metal::float3 color = {};
    bool local = {};
    float d_flakes = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    metal::float2 duv_dx_1 = metal::dfdx(_e5);
    metal::float2 duv_dy_1 = metal::dfdy(_e5);
    metal::float4 _e10 = material.base_color;
    metal::float4 _e13 = base_map.sample(material_sampler, _e5);
    metal::float4 base_rgba = _e10 * _e13;
    metal::float3 base_1 = metal::saturate(base_rgba.xyz);
    float alpha = metal::saturate(base_rgba.w);
    float _e21 = material.metallic;
    float metallic = metal::saturate(_e21);
    float _e25 = material.smoothness;
    float roughness_7 = 1.0 - metal::saturate(_e25);
    metal::float4 _e31 = occlusion_map.sample(material_sampler, _e5);
    float occlusion = _e31.x;
    float _e35 = material.occlusion_strength;
    float ao = metal::saturate(metal::mix(1.0, occlusion, _e35));
    WeftSurface _e41 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_3 = _e41.v;
    n = _e41.n;
    metal::float3 _e45 = n;
    metal::float3x3 _e47 = weft_tangent_frame(_e45, in_1.world_tangent);
    metal::float3 _e48 = n;
    WeftLightGeometry _e49 = weft_main_light_geometry(_e48, v_3, weft_frame);
    metal::float3 _e50 = weft_main_light_radiance(weft_frame);
    metal::float3 f0_2 = metal::mix(metal::float3(0.04), base_1, metallic);
    metal::float3 diffuse_albedo = base_1 * (1.0 - metallic);
    float _e59 = weft_v_smith_ggx_correlated(_e49.n_dot_v, _e49.n_dot_l, roughness_7);
    metal::float2 _e61 = weft_env_brdf_lut(_e49.n_dot_v, roughness_7, weft_brdf_lut, weft_lut_sampler);
    metal::float3 _e62 = weft_env_brdf_from_lut(f0_2, _e61);
    metal::float3 kd = metal::max(metal::float3(1.0) - _e62, metal::float3(0.0));
    metal::float3 _e69 = n;
    float _e71 = weft_d_ggx_nh(_e69, _e49.h, roughness_7);
    metal::float3 _e74 = weft_f_schlick(f0_2, _e49.v_dot_h);
    metal::float3 specular = (_e71 * _e59) * _e74;
    metal::float3 _e76 = weft_diffuse_lambert(diffuse_albedo);
    metal::float3 direct = (((kd * _e76) + specular) * _e50) * _e49.n_dot_l;
    metal::float3 _e83 = n;
    metal::float3 _e85 = weft_prefiltered_radiance(metal::reflect(-(v_3), _e83), roughness_7, weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 _e88 = n;
    metal::float3 _e89 = weft_sh_irradiance(_e88, weft_frame);
    metal::float3 indirect = ((_e85 * _e62) * ao) + (((_e89 * ao) * kd) * diffuse_albedo);
    color = direct + indirect;
    float _e98 = material.flake_intensity;
    float intensity = metal::max(_e98, 0.0);
    if (intensity > 0.0) {
        local = _e49.n_dot_l > 0.0;
    } else {
        local = false;
    }
    bool _e109 = local;
    if (_e109) {
        float _e112 = material.flake_roughness;
        float r_f = metal::clamp(_e112, 0.05, 1.0);
        metal::float3 _e116 = n;
        float _e118 = weft_d_ggx_nh(_e116, _e49.h, r_f);
        float _e120 = weft_d_ggx(1.0, r_f);
        metal::float4 _e123 = material.flake_color;
        metal::float3 flake_f0_ = metal::saturate(_e123.xyz);
        float _e128 = weft_v_smith_ggx_correlated(_e49.n_dot_v, _e49.n_dot_l, r_f);
        {
            GlintParams _e129 = glitter_params(material);
            metal::float3 _e132 = weft_f_schlick(flake_f0_, _e49.v_dot_h);
            metal::float3 lobe = ((((intensity * _e128) * _e132) * _e50) * _e49.n_dot_l) * (_e120 / _e129.micro_roughness);
            metal::float2 slope_1 = metal::float2(metal::dot(_e47[0], _e49.h), metal::dot(_e47[1], _e49.h));
            GlintEllipse _e147 = glint_ellipse(duv_dx_1, duv_dy_1);
            float _e150 = material.flake_size;
            float screen_scale_4 = metal::clamp(_e150, 1.0, 8.0);
            float _e154 = glint_hits_fast(_e129, _e5, _e147, screen_scale_4, slope_1, _e118, _e120);
            metal::float3 _e155 = color;
            color = _e155 + (metal::min(_e154, 20.0 * _e129.micro_roughness) * lobe);
        }
    }
    metal::float3 _e162 = color;
    metal::float3 radiance = metal::clamp(_e162, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
