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
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float WEFT_MIN_ANISO_ALPHA = 0.001;
constant float GAUZE_LN_MAX_TRANSMITTANCE = 6.9077554;

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
    float s = (n_1.z >= 0.0) ? 1.0 : -1.0;
    float a = -1.0 / (s + n_1.z);
    float b = (n_1.x * n_1.y) * a;
    return metal::float3(1.0 + (((s * n_1.x) * n_1.x) * a), s * b, -(s) * n_1.x);
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

WeftSurface weft_surface_two_sided(
    metal::float3 world_position_1,
    metal::float3 world_normal,
    bool front_facing_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e3 = weft_view_direction_k2_(world_position_1, weft_frame);
    metal::float3 facing = front_facing_1 ? world_normal : -(world_normal);
    metal::float3 _e6 = weft_safe_normalize(facing, _e3);
    return WeftSurface {_e3, _e6};
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
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_4, t) * s_1;
    return metal::float3x3(t, b_1, n_4);
}

metal::float3 weft_aniso_to_frame(
    metal::float3x3 frame,
    metal::float3 x_1
) {
    return metal::float3(metal::dot(frame[0], x_1), metal::dot(frame[1], x_1), metal::dot(frame[2], x_1));
}

metal::float3x3 weft_rotate_tangent_frame_cs_k15_(
    metal::float3x3 frame_1
) {
    metal::float3 t_1 = (frame_1[0] * -0.00000004371139) + frame_1[1];
    metal::float3 b_2 = (frame_1[1] * -0.00000004371139) - frame_1[0];
    return metal::float3x3(t_1, b_2, frame_1[2]);
}

metal::float3x3 weft_rotate_tangent_frame_k7_(
    metal::float3x3 frame_2
) {
    metal::float3x3 _e2 = weft_rotate_tangent_frame_cs_k15_(frame_2);
    return _e2;
}

metal::float3 weft_f_schlick_k9_(
    float v_dot_h
) {
    float _e5 = weft_pow5_(1.0 - metal::saturate(v_dot_h));
    return metal::float3(0.04) + (metal::float3(0.96, 0.96, 0.96) * _e5);
}

metal::float2 weft_env_brdf_lut_k10_(
    float n_dot_v,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv = metal::float2(metal::saturate(n_dot_v), 0.45);
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv, metal::level(0.0));
    return _e8.xy;
}

metal::float3 weft_env_brdf_from_lut_k11_(
    metal::float2 scale_bias
) {
    metal::float2 sb = metal::saturate(scale_bias);
    return (metal::float3(0.04) * sb.x) + metal::float3(sb.y);
}

metal::float3 weft_aniso_bent_normal_k13_(
    metal::float3x3 frame_3,
    metal::float3 v_4
) {
    metal::float3 n_5 = frame_3[2];
    metal::float3 dir_1 = frame_3[1];
    metal::float3 aniso_t = metal::cross(dir_1, v_4);
    metal::float3 aniso_n = metal::cross(aniso_t, dir_1);
    metal::float3 _e11 = weft_safe_normalize(metal::mix(n_5, aniso_n, 0.8), n_5);
    return _e11;
}

float weft_specular_mip_k17_(
    constant WeftFrame& weft_frame
) {
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return 0.62325 * max_mip;
}

metal::float3 weft_prefiltered_radiance_k14_(
    metal::float3 dir,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip_k17_(weft_frame);
    metal::float4 c_1 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_1.xyz, metal::float3(0.0));
}

float weft_aniso_ggx_q_k21_(
    float t_dot_h,
    float b_dot_h,
    float n_dot_h
) {
    float x_2 = t_dot_h / 0.36449996;
    float y = b_dot_h / 0.040499996;
    return metal::max(((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h), 0.000001);
}

float weft_d_ggx_aniso_k19_(
    float t_dot_h_1,
    float b_dot_h_1,
    float n_dot_h_1
) {
    float _e7 = weft_aniso_ggx_q_k21_(t_dot_h_1, b_dot_h_1, n_dot_h_1);
    float d = 1.0 / ((0.046376966 * _e7) * _e7);
    return (n_dot_h_1 > 0.0) ? d : 0.0;
}

float weft_v_smith_ggx_aniso_correlated_k20_(
    metal::float3 v_5,
    metal::float3 l
) {
    float _e5 = weft_clamp_cos(v_5.z);
    float _e7 = weft_clamp_cos(l.z);
    float lv = _e7 * metal::length(metal::float3(0.36449996 * v_5.x, 0.040499996 * v_5.y, _e5));
    float ll = _e5 * metal::length(metal::float3(0.36449996 * l.x, 0.040499996 * l.y, _e7));
    return 0.5 / (lv + ll);
}

float weft_spec_ggx_aniso_k18_(
    metal::float3 v_6,
    metal::float3 l_1
) {
    metal::float3 _e5 = weft_safe_normalize_k4_(v_6 + l_1);
    float _e9 = weft_d_ggx_aniso_k19_(_e5.x, _e5.y, _e5.z);
    float _e10 = weft_v_smith_ggx_aniso_correlated_k20_(v_6, l_1);
    return (_e9 * _e10) * metal::saturate(l_1.z);
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
, constant WeftObject& weft_object [[buffer(1)]]
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
, bool front_facing [[front_facing]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, metal::texturecube<float, metal::access::sample> weft_environment [[texture(0)]]
, metal::sampler weft_environment_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> weft_brdf_lut [[texture(1)]]
, metal::sampler weft_lut_sampler [[sampler(1)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    metal::float3 spec_direct = {};
    metal::float3 env_brdf = {};
    metal::float3 diffuse_kd = {};
    metal::float3 ambient_kd = {};
    float lobe = {};
    metal::float2 uv_s = in_1.uv0_ * 60.0;
    metal::float2 grid_w = metal::fwidth(uv_s);
    WeftSurface _e18 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing, weft_frame);
    metal::float3 v_7 = _e18.v;
    metal::float3 n_geom = _e18.n;
    n = n_geom;
    metal::float3 _e22 = n;
    metal::float3x3 _e24 = weft_tangent_frame(_e22, in_1.world_tangent);
    float cos_v = metal::min(metal::abs(metal::dot(n_geom, v_7)), 1.0);
    float sin_v = metal::sqrt(metal::max(1.0 - (cos_v * cos_v), 0.0));
    float s_2 = metal::pow(metal::max(sin_v, 0.00000001), 3.0);
    float alpha = metal::saturate(1.0 - ((1.0 - s_2) * 0.6930604));
    float coverage = metal::saturate(1.0 - ((1.0 - s_2) * 0.0));
    metal::float3x3 _e56 = weft_rotate_tangent_frame_k7_(_e24);
    metal::float3 _e59 = n;
    WeftLightGeometry _e60 = weft_main_light_geometry(_e59, v_7);
    {
        {
            metal::float3 _e71 = weft_aniso_to_frame(_e24, v_7);
            metal::float3 _e73 = weft_aniso_to_frame(_e24, _e60.l);
            metal::float3 _e74 = weft_aniso_to_frame(_e56, v_7);
            metal::float3 _e76 = weft_aniso_to_frame(_e56, _e60.l);
            float _e77 = weft_spec_ggx_aniso_k18_(_e71, _e73);
            float _e78 = weft_spec_ggx_aniso_k18_(_e74, _e76);
            lobe = metal::mix(_e77, _e78, 0.0);
        }
        metal::float3 _e81 = weft_f_schlick_k9_(_e60.v_dot_h);
        float _e82 = lobe;
        spec_direct = ((_e82 * _e81) * metal::float3(1.0, 0.8900054, 0.93310684)) * metal::float3(3.2, 3.05, 2.8);
        metal::float3 _e88 = weft_f_schlick_k9_(_e60.n_dot_v);
        diffuse_kd = metal::float3(1.0) - (metal::float3(1.0, 0.8900054, 0.93310684) * _e88);
        metal::float2 _e92 = weft_env_brdf_lut_k10_(_e60.n_dot_v, weft_brdf_lut, weft_lut_sampler);
        metal::float3 _e93 = weft_env_brdf_from_lut_k11_(_e92);
        env_brdf = _e93 * metal::float3(1.0, 0.8900054, 0.93310684);
        metal::float3 _e96 = env_brdf;
        ambient_kd = metal::max(metal::float3(1.0) - _e96, metal::float3(0.0));
    }
    metal::float3 _e100 = diffuse_kd;
    metal::float3 diffuse_direct = ((_e100 * metal::float3(0.26995486, 0.22618032, 0.23822759)) * metal::float3(3.2, 3.05, 2.8)) * _e60.n_dot_l;
    metal::float3 _e106 = n;
    metal::float3 _e107 = weft_sh_irradiance(_e106);
    metal::float3 _e108 = ambient_kd;
    metal::float3 diffuse_indirect = (_e107 * _e108) * metal::float3(0.84808826, 0.71056646, 0.7484141);
    metal::float3 _e111 = weft_aniso_bent_normal_k13_(_e24, v_7);
    metal::float3 _e114 = weft_prefiltered_radiance_k14_(metal::reflect(-(v_7), _e111), weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 _e115 = env_brdf;
    metal::float3 spec_indirect = _e114 * _e115;
    metal::float3 _e119 = spec_direct;
    metal::float3 color = (alpha * (diffuse_direct + diffuse_indirect)) + (coverage * (_e119 + spec_indirect));
    metal::float3 radiance = metal::clamp(color, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
