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
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float WEFT_SHEEN_MIN_ROUGHNESS = 0.07;

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

metal::float3 weft_safe_normalize_k12_(
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
    metal::float3 _e7 = weft_safe_normalize_k12_(_e4.xyz - world_position);
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
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_4, t) * s_1;
    return metal::float3x3(t, b_1, n_4);
}

metal::float3 weft_normal_from_tangent_space_k18_(
    metal::float3x3 frame
) {
    metal::float3 _e4 = weft_safe_normalize(frame * metal::float3(metal::float2(0.003921628, 0.003921628), 1.0), frame[2]);
    return _e4;
}

metal::float3 weft_mapped_normal_k6_(
    metal::float3 n_5,
    metal::float4 tangent_1
) {
    metal::float3x3 _e4 = weft_tangent_frame(n_5, tangent_1);
    metal::float3 _e5 = weft_normal_from_tangent_space_k18_(_e4);
    return _e5;
}

float weft_sheen_albedo_scaling_view_k8_(
    float e_v
) {
    return metal::saturate(1.0 - (0.46167183 * metal::saturate(e_v)));
}

float weft_sheen_albedo_scaling_k10_(
    float e_v_1,
    float e_l
) {
    return metal::saturate(metal::min(1.0 - (0.46167183 * metal::saturate(e_v_1)), 1.0 - (0.46167183 * metal::saturate(e_l))));
}

float weft_sheen_albedo_k15_(
    float n_dot_x,
    metal::sampler weft_lut_sampler,
    metal::texture2d<float, metal::access::sample> weft_sheen_lut
) {
    metal::float2 uv = metal::float2(metal::saturate(n_dot_x), 0.39999998);
    metal::float4 _e8 = weft_sheen_lut.sample(weft_lut_sampler, uv, metal::level(0.0));
    return metal::saturate(_e8.x);
}

float weft_d_charlie_k19_(
    float n_dot_h
) {
    float noh = metal::saturate(n_dot_h);
    float sin2_ = metal::max((1.0 - noh) * (1.0 + noh), 0.0);
    return (4.5 * metal::pow(sin2_, 1.2500001)) * 0.15915494;
}

float weft_sheen_l_k23_(
    float x
) {
    return ((22.907091 / (1.0 + (3.647883 * metal::pow(metal::max(x, 0.0), 0.1873508)))) + (-1.7242787 * x)) + -4.514627;
}

float weft_sheen_lambda_one_exp_k22_(
    float cos_theta
) {
    float _e2 = weft_clamp_cos(cos_theta);
    bool low = _e2 < 0.5;
    float _e8 = weft_sheen_l_k23_(low ? _e2 : (1.0 - _e2));
    return metal::exp(low ? _e8 : (0.1451807 - _e8));
}

float weft_v_charlie_k20_(
    float n_dot_v,
    float n_dot_l
) {
    float _e4 = weft_clamp_cos(n_dot_v);
    float _e5 = weft_clamp_cos(n_dot_l);
    float _e6 = weft_sheen_lambda_one_exp_k22_(_e4);
    float _e9 = weft_sheen_lambda_one_exp_k22_(_e5);
    float g_inv = (1.0 + _e6) + _e9;
    return 1.0 / (((g_inv * 4.0) * _e4) * _e5);
}

metal::float3 weft_sheen_charlie_k16_(
    float n_dot_h_1,
    float n_dot_v_1,
    float n_dot_l_1
) {
    float _e5 = weft_d_charlie_k19_(n_dot_h_1);
    float _e6 = weft_v_charlie_k20_(n_dot_v_1, n_dot_l_1);
    float lobe = _e5 * _e6;
    return metal::float3(0.46167183, 0.07633493, 0.16470811) * (lobe * metal::saturate(n_dot_l_1));
}

float weft_specular_mip_k21_(
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
    float _e4 = weft_specular_mip_k21_(weft_frame);
    metal::float4 c_1 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_1.xyz, metal::float3(0.0));
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
, constant WeftObject& weft_object [[buffer(1)]]
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
, metal::sampler weft_lut_sampler [[sampler(1)]]
, metal::texture2d<float, metal::access::sample> weft_sheen_lut [[texture(1)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    metal::float3 color = {};
    metal::float3 sheen = {};
    float scaling = {};
    WeftSurface _e11 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_4 = _e11.v;
    n = _e11.n;
    {
        metal::float3 _e16 = n;
        metal::float3 _e18 = weft_mapped_normal_k6_(_e16, in_1.world_tangent);
        n = _e18;
    }
    metal::float3 _e19 = n;
    WeftLightGeometry _e20 = weft_main_light_geometry(_e19, v_4);
    float l_dot_h = metal::saturate(metal::dot(_e20.l, _e20.h));
    metal::float3 _e28 = n;
    metal::float3 _e29 = weft_sh_irradiance(_e28);
    {
        float _e34 = weft_sheen_albedo_k15_(_e20.n_dot_v, weft_lut_sampler, weft_sheen_lut);
        float _e35 = weft_sheen_albedo_scaling_view_k8_(_e34);
        {
            float _e39 = weft_sheen_albedo_k15_(_e20.n_dot_l, weft_lut_sampler, weft_sheen_lut);
            metal::float3 _e43 = weft_sheen_charlie_k16_(_e20.n_dot_h, _e20.n_dot_v, _e20.n_dot_l);
            sheen = _e43;
            float _e44 = weft_sheen_albedo_scaling_k10_(_e34, _e39);
            scaling = _e44;
        }
        float _e46 = scaling;
        metal::float3 base_direct = metal::float3(0.0, 0.0, 0.0) * (_e46 * _e20.n_dot_l);
        metal::float3 _e50 = sheen;
        metal::float3 direct = (_e50 + base_direct) * metal::float3(3.2, 3.05, 2.8);
        metal::float3 _e54 = n;
        metal::float3 _e56 = weft_prefiltered_radiance_k17_(metal::reflect(-(v_4), _e54), weft_frame, weft_environment, weft_environment_sampler);
        metal::float3 env_sheen = (_e56 * metal::float3(0.46167183, 0.07633493, 0.16470811)) * _e34;
        color = (direct + ((_e29 * metal::float3(0.0, 0.0, 0.0)) * _e35)) + env_sheen;
    }
    metal::float3 _e63 = color;
    metal::float3 radiance = metal::clamp(_e63, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
