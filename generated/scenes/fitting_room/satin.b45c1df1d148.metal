// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct type_4 {
    metal::float4 inner[9];
};
struct WeftFrame {
    metal::float4x4 view_proj;
    metal::float4x4 view;
    metal::float4 camera_position;
    metal::float4 light_direction;
    metal::float4 light_color;
    type_4 sh;
    metal::float4 params;
    metal::float4 viewport;
};
struct WeftObject {
    metal::float4x4 model;
    metal::float4x4 normal_matrix;
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
struct SatinLayers {
    metal::float2 narrow;
    metal::float2 wide;
};
struct WeftMaterial {
    metal::float4 base_color;
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant uint TIER_LOW = 3u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float WEFT_MIN_ANISO_ALPHA = 0.001;
constant float WEFT_MIN_ROUGHNESS_HALF = 0.089;
constant float WEFT_MIN_N_DOT_HALF = 0.001;
constant float WEFT_MIN_ALPHA_HALF = 0.007921;

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
    float a_1 = -1.0 / (s_1 + n_1.z);
    float b = (n_1.x * n_1.y) * a_1;
    return metal::float3(1.0 + (((s_1 * n_1.x) * n_1.x) * a_1), s_1 * b, -(s_1) * n_1.x);
}

metal::float3 weft_f_schlick(
    metal::float3 f0_,
    float v_dot_h
) {
    float _e5 = weft_pow5_(1.0 - metal::saturate(v_dot_h));
    return f0_ + ((metal::float3(1.0) - f0_) * _e5);
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

metal::float3 weft_sh_irradiance(
    metal::float3 n_2
) {
    metal::float3 e = {};
    e = metal::float3(0.27778354, 0.32136026, 0.4497644);
    e = metal::float3(0.27778354, 0.32136026, 0.4497644) + (metal::float3(0.2192843, 0.34164187, 0.663193) * (0.488603 * n_2.y));
    metal::float3 _e11 = e;
    e = _e11 + (metal::float3(0.1352113, 0.12394369, 0.10366199) * (0.488603 * n_2.z));
    metal::float3 _e18 = e;
    e = _e18 + (metal::float3(-0.14969625, -0.13722156, -0.11476713) * (0.488603 * n_2.x));
    metal::float3 _e25 = e;
    e = _e25 + (metal::float3(-0.064625785, -0.059240304, -0.049546435) * ((1.092548 * n_2.x) * n_2.y));
    metal::float3 _e34 = e;
    e = _e34 + (metal::float3(0.05837178, 0.053507466, 0.044751696) * ((1.092548 * n_2.y) * n_2.z));
    metal::float3 _e43 = e;
    e = _e43 + (metal::float3(0.025110306, 0.023586905, 0.01273896) * (0.315392 * (((3.0 * n_2.z) * n_2.z) - 1.0)));
    metal::float3 _e56 = e;
    e = _e56 + (metal::float3(-0.06322707, -0.057958152, -0.04847409) * ((1.092548 * n_2.x) * n_2.z));
    metal::float3 _e65 = e;
    e = _e65 + (metal::float3(0.056382716, 0.05266991, 0.031947177) * (0.546274 * ((n_2.x * n_2.x) - (n_2.y * n_2.y))));
    metal::float3 _e78 = e;
    return metal::max(_e78, metal::float3(0.0));
}

metal::float3 weft_safe_normalize_k4_(
    metal::float3 v_1
) {
    float len2_1 = metal::dot(v_1, v_1);
    return (len2_1 > 0.00000000000000000001) ? (v_1 * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : metal::float3(0.0, 0.0, 1.0);
}

metal::float3 weft_view_direction_k2_(
    metal::float3 world_position,
    constant WeftFrame& weft_frame
) {
    metal::float4 _e4 = weft_frame.camera_position;
    metal::float3 _e7 = weft_safe_normalize_k4_(_e4.xyz - world_position);
    return _e7;
}

WeftSurface weft_surface(
    metal::float3 world_position_1,
    metal::float3 world_normal,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_view_direction_k2_(world_position_1, weft_frame);
    metal::float3 _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface {_e2, _e3};
}

WeftLightGeometry weft_main_light_geometry(
    metal::float3 n_3,
    metal::float3 v_2
) {
    metal::float3 _e4 = weft_safe_normalize(metal::float3(-0.61984503, 0.54986256, 0.55986005) + v_2, n_3);
    float _e6 = weft_clamp_cos(metal::dot(n_3, v_2));
    return WeftLightGeometry {metal::float3(-0.61984503, 0.54986256, 0.55986005), _e4, _e6, metal::saturate(metal::dot(n_3, metal::float3(-0.61984503, 0.54986256, 0.55986005))), metal::saturate(metal::dot(n_3, _e4)), metal::saturate(metal::dot(v_2, _e4))};
}

metal::float3 weft_safe_normalize_k3_(
    metal::float3 v_3
) {
    float len2_2 = metal::dot(v_3, v_3);
    return (len2_2 > 0.00000000000000000001) ? (v_3 * metal::rsqrt(metal::max(len2_2, 0.00000000000000000001))) : metal::float3(0.0);
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
    metal::float3 _e53 = weft_safe_normalize_k3_(normal3_ * in_2.normal);
    out.world_normal = _e53;
    metal::float3 _e58 = weft_safe_normalize_k3_(model3_ * in_2.tangent.xyz);
    out.world_tangent = metal::float4(_e58, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    WeftVaryings _e62 = out;
    return _e62;
}

metal::float3x3 weft_tangent_frame(
    metal::float3 n_4,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_4 * metal::dot(n_4, t_in));
    float len2_3 = metal::dot(t_proj, t_proj);
    bool ok = len2_3 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_4);
    metal::float3 t = ok ? (t_proj * metal::rsqrt(metal::max(len2_3, 0.00000000000000000001))) : _e13;
    float s_2 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_4, t) * s_2;
    return metal::float3x3(t, b_1, n_4);
}

metal::float3 weft_aniso_to_frame(
    metal::float3x3 frame,
    metal::float3 x_1
) {
    return metal::float3(metal::dot(frame[0], x_1), metal::dot(frame[1], x_1), metal::dot(frame[2], x_1));
}

float weft_aniso_ggx_q(
    float t_dot_h,
    float b_dot_h,
    float n_dot_h,
    float alpha_t,
    float alpha_b
) {
    float at = metal::max(alpha_t, WEFT_MIN_ANISO_ALPHA);
    float ab = metal::max(alpha_b, WEFT_MIN_ANISO_ALPHA);
    float x_2 = t_dot_h / at;
    float y = b_dot_h / ab;
    return metal::max(((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h), 0.000001);
}

float weft_d_ggx_aniso(
    float t_dot_h_1,
    float b_dot_h_1,
    float n_dot_h_1,
    float alpha_t_1,
    float alpha_b_1
) {
    float at_1 = metal::max(alpha_t_1, WEFT_MIN_ANISO_ALPHA);
    float ab_1 = metal::max(alpha_b_1, WEFT_MIN_ANISO_ALPHA);
    float _e9 = weft_aniso_ggx_q(t_dot_h_1, b_dot_h_1, n_dot_h_1, at_1, ab_1);
    float d = 1.0 / ((((WEFT_PI * at_1) * ab_1) * _e9) * _e9);
    return (n_dot_h_1 > 0.0) ? d : 0.0;
}

float weft_v_smith_ggx_aniso_correlated(
    metal::float3 v_4,
    metal::float3 l,
    float alpha_t_2,
    float alpha_b_2
) {
    float _e5 = weft_clamp_cos(v_4.z);
    float _e7 = weft_clamp_cos(l.z);
    float lv = _e7 * metal::length(metal::float3(alpha_t_2 * v_4.x, alpha_b_2 * v_4.y, _e5));
    float ll = _e5 * metal::length(metal::float3(alpha_t_2 * l.x, alpha_b_2 * l.y, _e7));
    return 0.5 / (lv + ll);
}

float weft_spec_ggx_aniso(
    metal::float3 v_5,
    metal::float3 l_1,
    float alpha_t_3,
    float alpha_b_3
) {
    metal::float3 _e5 = weft_safe_normalize_k4_(v_5 + l_1);
    float _e9 = weft_d_ggx_aniso(_e5.x, _e5.y, _e5.z, alpha_t_3, alpha_b_3);
    float _e10 = weft_v_smith_ggx_aniso_correlated(v_5, l_1, alpha_t_3, alpha_b_3);
    return (_e9 * _e10) * metal::saturate(l_1.z);
}

float satin_lobe_reference(
    metal::float3 vf,
    metal::float3 lf,
    metal::float2 a
) {
    float s = {};
    float _e5 = weft_spec_ggx_aniso(vf, lf, a.x, a.y);
    s = _e5;
    float _e7 = s;
    return _e7;
}

metal::float2 weft_env_brdf_lut_k10_(
    float n_dot_v,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv = metal::float2(metal::saturate(n_dot_v), 0.4);
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv, metal::level(0.0));
    return _e8.xy;
}

metal::float2 weft_env_brdf_lut_k11_(
    float n_dot_v_1,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv_1 = metal::float2(metal::saturate(n_dot_v_1), 0.8);
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv_1, metal::level(0.0));
    return _e8.xy;
}

metal::float3 weft_aniso_bent_normal_k16_(
    metal::float3x3 frame_1,
    metal::float3 v_6
) {
    metal::float3 n_5 = frame_1[2];
    metal::float3 dir_2 = frame_1[1];
    metal::float3 aniso_t = metal::cross(dir_2, v_6);
    metal::float3 aniso_n = metal::cross(aniso_t, dir_2);
    metal::float3 _e11 = weft_safe_normalize(metal::mix(n_5, aniso_n, 0.85), n_5);
    return _e11;
}

float weft_specular_mip_k20_(
    constant WeftFrame& weft_frame
) {
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return 0.568 * max_mip;
}

metal::float3 weft_prefiltered_radiance_k17_(
    metal::float3 dir,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip_k20_(weft_frame);
    metal::float4 c_3 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_3.xyz, metal::float3(0.0));
}

metal::float3 satin_env_k12_(
    metal::float3x3 frame_2,
    metal::float3 v_7,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    metal::float3 bent_1 = {};
    metal::float3 c_1 = {};
    metal::float3 _e4 = weft_aniso_bent_normal_k16_(frame_2, v_7);
    bent_1 = _e4;
    metal::float3 _e7 = bent_1;
    metal::float3 _e9 = weft_prefiltered_radiance_k17_(metal::reflect(-(v_7), _e7), weft_frame, weft_environment, weft_environment_sampler);
    c_1 = _e9;
    metal::float3 _e11 = c_1;
    return _e11;
}

metal::float3 weft_aniso_bent_normal_k18_(
    metal::float3x3 frame_3,
    metal::float3 v_8
) {
    metal::float3 n_6 = frame_3[2];
    metal::float3 dir_3 = frame_3[1];
    metal::float3 aniso_t_1 = metal::cross(dir_3, v_8);
    metal::float3 aniso_n_1 = metal::cross(aniso_t_1, dir_3);
    metal::float3 _e11 = weft_safe_normalize(metal::mix(n_6, aniso_n_1, 0.85), n_6);
    return _e11;
}

float weft_specular_mip_k21_(
    constant WeftFrame& weft_frame
) {
    float _e5 = weft_frame.params.x;
    float max_mip_1 = metal::max(_e5 - 1.0, 0.0);
    return 0.9120001 * max_mip_1;
}

metal::float3 weft_prefiltered_radiance_k19_(
    metal::float3 dir_1,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip_k21_(weft_frame);
    metal::float4 c_4 = weft_environment.sample(weft_environment_sampler, dir_1, metal::level(_e4));
    return metal::max(c_4.xyz, metal::float3(0.0));
}

metal::float3 satin_env_k13_(
    metal::float3x3 frame_4,
    metal::float3 v_9,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    metal::float3 bent_2 = {};
    metal::float3 c_2 = {};
    metal::float3 _e4 = weft_aniso_bent_normal_k18_(frame_4, v_9);
    bent_2 = _e4;
    metal::float3 _e7 = bent_2;
    metal::float3 _e9 = weft_prefiltered_radiance_k19_(metal::reflect(-(v_9), _e7), weft_frame, weft_environment, weft_environment_sampler);
    c_2 = _e9;
    metal::float3 _e11 = c_2;
    return _e11;
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
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    SatinLayers layers = {};
    metal::float3 specular = {};
    metal::float3 diffuse_kd = {};
    metal::float3 indirect_specular = {};
    metal::float3 ambient_kd = {};
    metal::float3 bent = {};
    metal::float4 base_rgba = material.base_color;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float alpha = metal::saturate(base_rgba.w);
    WeftSurface _e18 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_10 = _e18.v;
    n = _e18.n;
    metal::float3 _e22 = n;
    metal::float3x3 _e24 = weft_tangent_frame(_e22, in_1.world_tangent);
    metal::float3 _e25 = n;
    WeftLightGeometry _e26 = weft_main_light_geometry(_e25, v_10);
    layers.narrow = metal::float2(0.29600003, 0.023999998);
    layers.wide = metal::float2(1.1840001, 0.09599999);
    metal::float3 f0_2 = metal::mix(metal::float3(0.04), base, 0.0);
    metal::float3 _e38 = weft_f_schlick(f0_2, _e26.v_dot_h);
    {
        metal::float3 _e48 = weft_aniso_to_frame(_e24, v_10);
        metal::float3 _e50 = weft_aniso_to_frame(_e24, _e26.l);
        metal::float2 _e52 = layers.narrow;
        float _e53 = satin_lobe_reference(_e48, _e50, _e52);
        metal::float2 _e55 = layers.wide;
        float _e56 = satin_lobe_reference(_e48, _e50, _e55);
        specular = (((metal::float3(0.7584107, 0.6081799, 0.62124574) * _e53) + (metal::float3(0.24158928, 0.13334814, 0.14008713) * _e56)) * _e38) * metal::float3(3.2, 3.05, 2.8);
        metal::float3 _e65 = weft_f_schlick(f0_2, _e26.n_dot_v);
        diffuse_kd = metal::max(metal::float3(1.0) - (metal::float3(1.0, 0.74152803, 0.76133287) * _e65), metal::float3(0.0));
        metal::float2 _e71 = weft_env_brdf_lut_k10_(_e26.n_dot_v, weft_brdf_lut, weft_lut_sampler);
        metal::float3 _e72 = weft_env_brdf_from_lut(f0_2, _e71);
        metal::float3 e1_ = _e72 * metal::float3(0.7584107, 0.6081799, 0.62124574);
        metal::float2 _e75 = weft_env_brdf_lut_k11_(_e26.n_dot_v, weft_brdf_lut, weft_lut_sampler);
        metal::float3 _e76 = weft_env_brdf_from_lut(f0_2, _e75);
        metal::float3 e2_ = _e76 * metal::float3(0.24158928, 0.13334814, 0.14008713);
        {
            metal::float3 _e78 = satin_env_k12_(_e24, v_10, weft_frame, weft_environment, weft_environment_sampler);
            metal::float3 _e80 = satin_env_k13_(_e24, v_10, weft_frame, weft_environment, weft_environment_sampler);
            indirect_specular = (_e78 * e1_) + (_e80 * e2_);
        }
        ambient_kd = metal::max((metal::float3(1.0) - e1_) - e2_, metal::float3(0.0));
    }
    metal::float3 _e88 = diffuse_kd;
    metal::float3 _e89 = weft_diffuse_lambert(base);
    metal::float3 _e94 = specular;
    metal::float3 direct = (((_e88 * _e89) * metal::float3(3.2, 3.05, 2.8)) * _e26.n_dot_l) + _e94;
    metal::float3 _e96 = indirect_specular;
    metal::float3 _e97 = n;
    metal::float3 _e98 = weft_sh_irradiance(_e97);
    metal::float3 _e99 = ambient_kd;
    metal::float3 indirect = _e96 + ((_e98 * _e99) * base);
    metal::float3 radiance = metal::clamp(direct + indirect, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
