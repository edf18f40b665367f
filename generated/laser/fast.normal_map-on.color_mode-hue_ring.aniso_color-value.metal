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
    float roughness;
    float metallic;
    float occlusion_strength;
    char _pad4[4];
    metal::float4 base_map_st;
    float normal_strength;
    float saturation;
    float brightness;
    float span;
    float view_offset;
    char _pad10[12];
    metal::float4 offset_map_st;
    uint sin_mapping;
    float color_direction;
    float film_strength;
    float film_ior;
    float thickness_min;
    float thickness_max;
    char _pad17[8];
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
struct type_12 {
    metal::float3 inner[2];
};
struct WeftFilmStack {
    float n2_;
    float cos2_;
    metal::float2 r12_;
    type_12 r23_;
    bool total_internal_reflection;
    char _pad5[15];
};
struct WeftFilmSeries {
    metal::float3 dc;
    metal::float3 first;
    metal::float3 ratio;
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant float film_sensitivity_opd_max = 16000.0;
constant uint COLOR_MODE_HUE_RING = 0u;
constant uint COLOR_MODE_CUSTOM = 1u;
constant uint ANISO_COLOR_OFF = 0u;
constant uint ANISO_COLOR_VALUE = 1u;
constant uint ANISO_COLOR_MAP = 2u;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float WEFT_FILM_PI = 3.1415927;
constant uint WEFT_FILM_SAMPLES = 101u;
constant float WEFT_FILM_LAMBDA_MIN = 380.0;
constant float WEFT_FILM_LAMBDA_MAX = 780.0;
constant float WEFT_FILM_FADE_NM = 30.0;
constant metal::float3x3 WEFT_XYZ_TO_REC709_ = metal::float3x3(metal::float3(3.2404542, -0.969266, 0.0556434), metal::float3(-1.5371385, 1.8760108, -0.2040259), metal::float3(-0.4985314, 0.041556, 1.0572252));

metal::float4 table_film_sensitivity(
    metal::float2 uv,
    metal::sampler material_clamp_sampler,
    metal::texture2d<float, metal::access::sample> film_sensitivity
) {
    metal::float2 size = metal::float2(2048.0, 2.0);
    metal::float2 st_1 = ((metal::clamp(uv, metal::float2(0.0), metal::float2(1.0)) * (size - metal::float2(1.0))) + metal::float2(0.5)) / size;
    metal::float4 _e20 = film_sensitivity.sample(material_clamp_sampler, st_1, metal::level(0.0));
    return _e20;
}

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
    float s_1 = (n_1.z >= 0.0) ? 1.0 : -1.0;
    float a = -1.0 / (s_1 + n_1.z);
    float b = (n_1.x * n_1.y) * a;
    return metal::float3(1.0 + (((s_1 * n_1.x) * n_1.x) * a), s_1 * b, -(s_1) * n_1.x);
}

float weft_d_ggx_nh(
    metal::float3 n_2,
    metal::float3 h,
    float roughness_1
) {
    float _e3 = weft_clamp_roughness(roughness_1);
    float a_1 = _e3 * _e3;
    float a2_ = a_1 * a_1;
    float noh = metal::saturate(metal::dot(n_2, h));
    metal::float3 nxh = metal::cross(n_2, h);
    float d = metal::dot(nxh, nxh) + ((noh * noh) * a2_);
    return a2_ / (WEFT_PI * metal::max(d * d, 0.000000000000000000000000000001));
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
    float roughness_2
) {
    float _e3 = weft_clamp_roughness(roughness_2);
    float a_2 = _e3 * _e3;
    float a2_1 = a_2 * a_2;
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = _e7 * metal::sqrt(((_e6 * _e6) * (1.0 - a2_1)) + a2_1);
    float ll = _e6 * metal::sqrt(((_e7 * _e7) * (1.0 - a2_1)) + a2_1);
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
    float roughness_3,
    constant WeftFrame& weft_frame
) {
    float r = metal::saturate(roughness_3);
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return (r * (1.7 - (0.7 * r))) * max_mip;
}

metal::float3 weft_prefiltered_radiance(
    metal::float3 dir,
    float roughness_4,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip(roughness_4, weft_frame);
    metal::float4 c_1 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_1.xyz, metal::float3(0.0));
}

metal::float2 weft_env_brdf_lut(
    float n_dot_v_1,
    float roughness_5,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv_2 = metal::float2(metal::saturate(n_dot_v_1), metal::saturate(roughness_5));
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv_2, metal::level(0.0));
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
    float s_2 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_5, t) * s_2;
    return metal::float3x3(t, b_1, n_5);
}

metal::float3 weft_unpack_normal(
    metal::float3 texel,
    float strength
) {
    metal::float3 v_3 = (texel * 2.0) - metal::float3(1.0);
    return metal::float3(v_3.xy * strength, metal::max(v_3.z, 0.001));
}

metal::float3 weft_normal_from_tangent_space(
    metal::float3x3 frame,
    metal::float3 n_ts
) {
    metal::float3 _e4 = weft_safe_normalize(frame * n_ts, frame[2]);
    return _e4;
}

metal::float3 weft_mapped_normal(
    metal::float3 n_6,
    metal::float4 tangent_1,
    metal::float3 texel_1,
    float strength_1
) {
    metal::float3x3 _e4 = weft_tangent_frame(n_6, tangent_1);
    metal::float3 _e5 = weft_unpack_normal(texel_1, strength_1);
    metal::float3 _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
}

metal::float2 weft_transform_uv(
    metal::float2 uv_1,
    metal::float4 st
) {
    return (uv_1 * st.xy) + st.zw;
}

metal::float3 weft_ior_from_f0_(
    metal::float3 f0_2
) {
    metal::float3 s_3 = metal::sqrt(metal::clamp(f0_2, metal::float3(0.0), metal::float3(0.9999)));
    return (metal::float3(1.0) + s_3) / (metal::float3(1.0) - s_3);
}

float weft_film_ior(
    float film_ior,
    float thickness_nm
) {
    return metal::mix(1.0, metal::max(film_ior, 1.0), metal::smoothstep(0.0, WEFT_FILM_FADE_NM, thickness_nm));
}

metal::float2 weft_fresnel_amplitudes(
    float n_i,
    float n_t,
    float cos_i,
    float cos_t
) {
    float rs = ((n_i * cos_i) - (n_t * cos_t)) / metal::max((n_i * cos_i) + (n_t * cos_t), 0.000000000001);
    float rp = ((n_t * cos_i) - (n_i * cos_t)) / metal::max((n_t * cos_i) + (n_i * cos_t), 0.000000000001);
    return metal::float2(rs, rp);
}

type_12 weft_film_base_amplitudes(
    float n2_,
    float cos2_,
    metal::float3 n3_,
    float sin1_sq
) {
    metal::float3 cos3_ = metal::sqrt(metal::max(metal::float3(1.0) - (metal::float3(sin1_sq) / (n3_ * n3_)), metal::float3(0.0)));
    metal::float3 s_4 = (metal::float3(n2_ * cos2_) - (n3_ * cos3_)) / metal::max(metal::float3(n2_ * cos2_) + (n3_ * cos3_), metal::float3(0.000000000001));
    metal::float3 p_1 = ((n3_ * cos2_) - (metal::float3(n2_) * cos3_)) / metal::max((n3_ * cos2_) + (metal::float3(n2_) * cos3_), metal::float3(0.000000000001));
    return type_12 {{s_4, p_1}};
}

WeftFilmStack weft_film_stack(
    float cos_theta1_,
    float thickness_nm_1,
    float film_ior_1,
    metal::float3 base_f0_
) {
    float cos1_ = metal::clamp(cos_theta1_, 0.0, 1.0);
    float sin1_sq_1 = 1.0 - (cos1_ * cos1_);
    float _e10 = weft_film_ior(film_ior_1, thickness_nm_1);
    float cos2_sq = 1.0 - (sin1_sq_1 / (_e10 * _e10));
    if (cos2_sq <= 0.0) {
        return WeftFilmStack {_e10, 0.0, metal::float2(1.0), type_12 {{metal::float3(1.0), metal::float3(1.0)}}, true};
    }
    float cos2_1 = metal::sqrt(cos2_sq);
    metal::float2 _e29 = weft_fresnel_amplitudes(1.0, _e10, cos1_, cos2_1);
    metal::float3 _e30 = weft_ior_from_f0_(base_f0_);
    type_12 _e31 = weft_film_base_amplitudes(_e10, cos2_1, _e30, sin1_sq_1);
    return WeftFilmStack {_e10, cos2_1, _e29, _e31, false};
}

metal::float3 weft_film_sensitivity(
    float opd_nm,
    metal::sampler material_clamp_sampler,
    metal::texture2d<float, metal::access::sample> film_sensitivity
) {
    metal::float4 _e5 = table_film_sensitivity(metal::float2(opd_nm / film_sensitivity_opd_max, 0.0), material_clamp_sampler, film_sensitivity);
    return _e5.xyz;
}

metal::float3 weft_film_orders(
    float opd_nm_1,
    WeftFilmSeries s,
    WeftFilmSeries p,
    metal::sampler material_clamp_sampler,
    metal::texture2d<float, metal::access::sample> film_sensitivity
) {
    metal::float3 k1_ = (s.first * s.ratio) + (p.first * p.ratio);
    metal::float3 k2_ = ((s.first * s.ratio) * s.ratio) + ((p.first * p.ratio) * p.ratio);
    metal::float3 k3_ = (((s.first * s.ratio) * s.ratio) * s.ratio) + (((p.first * p.ratio) * p.ratio) * p.ratio);
    metal::float3 k4_ = ((s.first * (s.ratio * s.ratio)) * (s.ratio * s.ratio)) + ((p.first * (p.ratio * p.ratio)) * (p.ratio * p.ratio));
    metal::float3 _e55 = weft_film_sensitivity(opd_nm_1, material_clamp_sampler, film_sensitivity);
    metal::float3 _e59 = weft_film_sensitivity(2.0 * opd_nm_1, material_clamp_sampler, film_sensitivity);
    metal::float3 _e64 = weft_film_sensitivity(3.0 * opd_nm_1, material_clamp_sampler, film_sensitivity);
    metal::float3 _e69 = weft_film_sensitivity(4.0 * opd_nm_1, material_clamp_sampler, film_sensitivity);
    metal::float3 sum = (((k1_ * _e55) + (k2_ * _e59)) + (k3_ * _e64)) + (k4_ * _e69);
    return 2.0 * sum;
}

WeftFilmSeries weft_film_series(
    float r12_,
    metal::float3 r23_
) {
    float big_r12_ = r12_ * r12_;
    float t121_ = 1.0 - big_r12_;
    metal::float3 big_r23_ = r23_ * r23_;
    metal::float3 big_r123_ = metal::min(big_r12_ * big_r23_, metal::float3(0.9999));
    metal::float3 rs_1 = ((t121_ * t121_) * big_r23_) / (metal::float3(1.0) - big_r123_);
    metal::float3 ratio = metal::clamp(-(r12_) * r23_, metal::float3(-0.99995), metal::float3(0.99995));
    return WeftFilmSeries {metal::float3(big_r12_) + rs_1, rs_1 - metal::float3(t121_), ratio};
}

metal::float3 weft_film_fourier_layers(
    float cos_theta1_1,
    float d1_,
    float d2_,
    float film_ior_2,
    metal::float3 base_f0_1,
    metal::sampler material_clamp_sampler,
    metal::texture2d<float, metal::access::sample> film_sensitivity
) {
    float d_mean = 0.5 * (metal::max(d1_, 0.0) + metal::max(d2_, 0.0));
    WeftFilmStack _e12 = weft_film_stack(cos_theta1_1, d_mean, film_ior_2, base_f0_1);
    if (_e12.total_internal_reflection) {
        return metal::float3(1.0);
    }
    WeftFilmSeries _e20 = weft_film_series(_e12.r12_.x, _e12.r23_.inner[0]);
    WeftFilmSeries _e25 = weft_film_series(_e12.r12_.y, _e12.r23_.inner[1]);
    float path = (2.0 * _e12.n2_) * _e12.cos2_;
    metal::float3 _e37 = weft_film_orders(path * metal::max(d1_, 0.0), _e20, _e25, material_clamp_sampler, film_sensitivity);
    metal::float3 r1_ = (_e20.dc + _e25.dc) + _e37;
    metal::float3 _e45 = weft_film_orders(path * metal::max(d2_, 0.0), _e20, _e25, material_clamp_sampler, film_sensitivity);
    metal::float3 r2_ = (_e20.dc + _e25.dc) + _e45;
    return metal::clamp(0.25 * (r1_ + r2_), metal::float3(0.0), metal::float3(1.0));
}

float laser_cos_in_plane(
    metal::float3 n_7,
    metal::float3 v_2,
    metal::float3 direction
) {
    metal::float3 p_2 = metal::cross(direction, n_7);
    float p_len = metal::length(p_2);
    if (p_len < 0.0001) {
        float _e8 = weft_clamp_cos(metal::dot(n_7, v_2));
        return _e8;
    }
    metal::float3 p_unit = p_2 / metal::float3(p_len);
    metal::float3 v_in_plane = v_2 - (metal::dot(v_2, p_unit) * p_unit);
    float len = metal::length(v_in_plane);
    float _e19 = weft_clamp_cos(metal::dot(n_7, v_in_plane) / metal::max(len, 0.0001));
    return _e19;
}

struct vs_mainInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float4 tangent_2 [[attribute(2)]];
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
    const WeftVertexInput in = { varyings.position, varyings.normal, varyings.tangent_2, varyings.uv0_ };
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
, metal::sampler material_clamp_sampler [[sampler(3)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> normal_map [[texture(3)]]
, metal::texture2d<float, metal::access::sample> rmo_map [[texture(4)]]
, metal::texture2d<float, metal::access::sample> offset_map [[texture(5)]]
, metal::texture2d<float, metal::access::sample> film_sensitivity [[texture(6)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    float film_cos = {};
    metal::float2 direction_ts = metal::float2(1.0, 0.0);
    metal::float3 surface_base = {};
    metal::float3 f_light = {};
    metal::float3 e_spec = {};
    float light_cos = {};
    metal::float3 film_view = {};
    metal::float3 film_light = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    metal::float4 _e8 = material.base_color;
    metal::float4 _e11 = base_map.sample(material_sampler, _e5);
    metal::float4 base_rgba = _e8 * _e11;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float alpha = metal::saturate(base_rgba.w);
    metal::float4 _e19 = rmo_map.sample(material_sampler, _e5);
    metal::float3 rmo = _e19.xyz;
    float _e23 = material.roughness;
    float roughness_6 = metal::saturate(_e23 * rmo.x);
    float _e29 = material.metallic;
    float metallic = metal::saturate(_e29 * rmo.y);
    float _e36 = material.occlusion_strength;
    float ao = metal::saturate(metal::mix(1.0, rmo.z, _e36));
    metal::float4 _e45 = material.offset_map_st;
    metal::float2 _e46 = weft_transform_uv(in_1.uv0_, _e45);
    metal::float4 _e47 = offset_map.sample(material_sampler, _e46);
    metal::float2 offsets = metal::saturate(_e47.xy);
    WeftSurface _e52 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_4 = _e52.v;
    metal::float3 geometric_n = _e52.n;
    n = geometric_n;
    {
        metal::float4 _e58 = normal_map.sample(material_sampler, _e5);
        metal::float3 texel_2 = _e58.xyz;
        float _e63 = material.normal_strength;
        metal::float3 _e64 = weft_mapped_normal(geometric_n, in_1.world_tangent, texel_2, _e63);
        n = _e64;
    }
    metal::float3 _e65 = n;
    WeftLightGeometry _e66 = weft_main_light_geometry(_e65, v_4, weft_frame);
    film_cos = _e66.n_dot_v;
    {
        metal::float3x3 _e70 = weft_tangent_frame(geometric_n, in_1.world_tangent);
        {
            float _e77 = material.color_direction;
            float angle = ((_e77) * 0.017453292519943295474);
            direction_ts = metal::float2(metal::cos(angle), metal::sin(angle));
        }
        float _e84 = direction_ts.x;
        float _e88 = direction_ts.y;
        metal::float3 direction_1 = (_e70[0] * _e84) + (_e70[1] * _e88);
        metal::float3 _e91 = n;
        float _e92 = laser_cos_in_plane(_e91, v_4, direction_1);
        film_cos = _e92;
    }
    surface_base = base;
    metal::float3 _e96 = surface_base;
    metal::float3 f0_3 = metal::mix(metal::float3(0.04), _e96, metallic);
    metal::float3 _e98 = surface_base;
    metal::float3 diffuse_albedo = _e98 * (1.0 - metallic);
    metal::float2 _e103 = weft_env_brdf_lut(_e66.n_dot_v, roughness_6, weft_brdf_lut, weft_lut_sampler);
    metal::float3 _e105 = weft_f_schlick(f0_3, _e66.v_dot_h);
    f_light = _e105;
    metal::float3 _e107 = weft_env_brdf_from_lut(f0_3, _e103);
    e_spec = _e107;
    {
        float _e111 = material.thickness_min;
        float _e114 = material.thickness_max;
        float d1_1 = metal::mix(_e111, _e114, offsets.x);
        float _e119 = material.thickness_min;
        float _e122 = material.thickness_max;
        float d2_1 = metal::mix(_e119, _e122, offsets.y);
        float _e127 = material.film_strength;
        float strength_2 = metal::saturate(_e127);
        light_cos = _e66.v_dot_h;
        {
            float _e131 = film_cos;
            light_cos = _e131;
        }
        {
            float _e134 = film_cos;
            float _e137 = material.film_ior;
            metal::float3 _e138 = weft_film_fourier_layers(_e134, d1_1, d2_1, _e137, f0_3, material_clamp_sampler, film_sensitivity);
            film_view = _e138;
            float _e139 = light_cos;
            float _e142 = material.film_ior;
            metal::float3 _e143 = weft_film_fourier_layers(_e139, d1_1, d2_1, _e142, f0_3, material_clamp_sampler, film_sensitivity);
            film_light = _e143;
        }
        metal::float3 _e144 = f_light;
        metal::float3 _e145 = film_light;
        f_light = metal::mix(_e144, _e145, strength_2);
        metal::float3 _e147 = e_spec;
        metal::float3 _e148 = film_view;
        e_spec = metal::mix(_e147, _e148 * (_e103.x + _e103.y), strength_2);
    }
    metal::float3 _e156 = e_spec;
    metal::float3 kd = metal::max(metal::float3(1.0) - _e156, metal::float3(0.0));
    float _e163 = weft_v_smith_ggx_correlated(_e66.n_dot_v, _e66.n_dot_l, roughness_6);
    metal::float3 _e164 = n;
    float _e166 = weft_d_ggx_nh(_e164, _e66.h, roughness_6);
    metal::float3 _e168 = f_light;
    metal::float3 specular = (_e166 * _e163) * _e168;
    metal::float3 _e170 = weft_diffuse_lambert(diffuse_albedo);
    metal::float3 diffuse = kd * _e170;
    metal::float3 _e173 = weft_main_light_radiance(weft_frame);
    metal::float3 direct = ((diffuse + specular) * _e173) * _e66.n_dot_l;
    metal::float3 _e178 = n;
    metal::float3 _e180 = weft_prefiltered_radiance(metal::reflect(-(v_4), _e178), roughness_6, weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 _e181 = e_spec;
    metal::float3 indirect_specular = (_e180 * _e181) * ao;
    metal::float3 _e184 = n;
    metal::float3 _e185 = weft_sh_irradiance(_e184, weft_frame);
    metal::float3 indirect_diffuse = ((_e185 * ao) * kd) * diffuse_albedo;
    metal::float3 color = (direct + indirect_specular) + indirect_diffuse;
    return fs_mainOutput { metal::float4(metal::clamp(color, metal::float3(0.0), metal::float3(65504.0)), alpha) };
}
