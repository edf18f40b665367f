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
struct WeftMaterial {
    metal::float4 base_color;
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint SPHERE_MAP_OFF = 0u;
constant uint SPHERE_MAP_ADD = 1u;
constant uint SPHERE_MAP_MULTIPLY = 2u;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant uint TIER_LOW = 3u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
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
    metal::float3 n_1
) {
    metal::float3 e = {};
    e = metal::float3(0.27778354, 0.32136026, 0.4497644);
    e = metal::float3(0.27778354, 0.32136026, 0.4497644) + (metal::float3(0.2192843, 0.34164187, 0.663193) * (0.488603 * n_1.y));
    metal::float3 _e11 = e;
    e = _e11 + (metal::float3(0.1352113, 0.12394369, 0.10366199) * (0.488603 * n_1.z));
    metal::float3 _e18 = e;
    e = _e18 + (metal::float3(-0.14969625, -0.13722156, -0.11476713) * (0.488603 * n_1.x));
    metal::float3 _e25 = e;
    e = _e25 + (metal::float3(-0.064625785, -0.059240304, -0.049546435) * ((1.092548 * n_1.x) * n_1.y));
    metal::float3 _e34 = e;
    e = _e34 + (metal::float3(0.05837178, 0.053507466, 0.044751696) * ((1.092548 * n_1.y) * n_1.z));
    metal::float3 _e43 = e;
    e = _e43 + (metal::float3(0.025110306, 0.023586905, 0.01273896) * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0)));
    metal::float3 _e56 = e;
    e = _e56 + (metal::float3(-0.06322707, -0.057958152, -0.04847409) * ((1.092548 * n_1.x) * n_1.z));
    metal::float3 _e65 = e;
    e = _e65 + (metal::float3(0.056382716, 0.05266991, 0.031947177) * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y))));
    metal::float3 _e78 = e;
    return metal::max(_e78, metal::float3(0.0));
}

metal::float3 weft_safe_normalize_k9_(
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
    metal::float3 _e7 = weft_safe_normalize_k9_(_e4.xyz - world_position);
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
    metal::float3 n_2,
    metal::float3 v_2
) {
    metal::float3 _e4 = weft_safe_normalize(metal::float3(-0.61984503, 0.54986256, 0.55986005) + v_2, n_2);
    float _e6 = weft_clamp_cos(metal::dot(n_2, v_2));
    return WeftLightGeometry {metal::float3(-0.61984503, 0.54986256, 0.55986005), _e4, _e6, metal::saturate(metal::dot(n_2, metal::float3(-0.61984503, 0.54986256, 0.55986005))), metal::saturate(metal::dot(n_2, _e4)), metal::saturate(metal::dot(v_2, _e4))};
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

metal::float3 standard_sphere_map(
    metal::float3 color_in,
    metal::float3 n_3,
    metal::float3 world_position_2
) {
    metal::float3 color = {};
    color = color_in;
    metal::float3 _e4 = color;
    return _e4;
}

void standard_alpha_test(
    float alpha
) {
    {
        return;
    }
}

float weft_v_smith_ggx_correlated_newton_k5_(
    float n_dot_v,
    float n_dot_l
) {
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float gv = (_e6 * 0.6975) + 0.3025;
    float gl = (_e7 * 0.6975) + 0.3025;
    float pv = (gv * _e6) + (0.09150626 * (1.0 - _e6));
    float pl = (gl * _e7) + (0.09150626 * (1.0 - _e7));
    return ((0.5 * gv) * gl) / (((_e7 * gl) * pv) + ((_e6 * gv) * pl));
}

metal::float2 weft_env_brdf_lut_k6_(
    float n_dot_v_1,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv = metal::float2(metal::saturate(n_dot_v_1), 0.55);
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv, metal::level(0.0));
    return _e8.xy;
}

float weft_d_ggx_k7_(
    float n_dot_h
) {
    float noh = metal::saturate(n_dot_h);
    float one_minus_noh2_ = (1.0 - noh) * (1.0 + noh);
    float d_1 = one_minus_noh2_ + ((noh * noh) * 0.09150626);
    return 0.09150626 / ((WEFT_PI * d_1) * d_1);
}

float weft_specular_mip_k11_(
    constant WeftFrame& weft_frame
) {
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return 0.72325003 * max_mip;
}

metal::float3 weft_prefiltered_radiance_k8_(
    metal::float3 dir,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip_k11_(weft_frame);
    metal::float4 c_1 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_1.xyz, metal::float3(0.0));
}

struct vs_mainInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float4 tangent [[attribute(2)]];
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
    const WeftVertexInput in = { varyings.position, varyings.normal, varyings.tangent, varyings.uv0_ };
    WeftVaryings _e1 = weft_forward_vertex(in, weft_frame, weft_object);
    const auto _tmp = _e1;
    return vs_mainOutput { _tmp.clip_position, _tmp.world_position, _tmp.world_normal, _tmp.world_tangent, _tmp.uv0_ };
}


struct fs_mainInput {
    metal::float3 world_position_3 [[user(loc0), center_perspective]];
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
, constant WeftMaterial& material [[buffer(1)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_3, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    float visibility = {};
    metal::float3 env_brdf = {};
    metal::float3 ambient_kd = {};
    metal::float3 direct_kd = {};
    metal::float3 specular = metal::float3(0.0);
    metal::float3 indirect_specular = metal::float3(0.0);
    float d = {};
    metal::float4 base_rgba = material.base_color;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float alpha_1 = metal::saturate(base_rgba.w);
    WeftSurface _e17 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing, weft_frame);
    metal::float3 v_4 = _e17.v;
    n = _e17.n;
    metal::float3 _e21 = n;
    WeftLightGeometry _e22 = weft_main_light_geometry(_e21, v_4);
    metal::float3 f0_2 = metal::mix(metal::float3(0.04), base, 0.0);
    {
        {
            float _e31 = weft_v_smith_ggx_correlated_newton_k5_(_e22.n_dot_v, _e22.n_dot_l);
            visibility = _e31;
            metal::float2 _e33 = weft_env_brdf_lut_k6_(_e22.n_dot_v, weft_brdf_lut, weft_lut_sampler);
            metal::float3 _e34 = weft_env_brdf_from_lut(f0_2, _e33);
            env_brdf = _e34;
            metal::float3 _e36 = env_brdf;
            ambient_kd = metal::max(metal::float3(1.0) - _e36, metal::float3(0.0));
            metal::float3 _e40 = ambient_kd;
            direct_kd = _e40;
        }
    }
    {
        metal::float3 _e46 = weft_f_schlick(f0_2, _e22.v_dot_h);
        {
            float _e49 = weft_d_ggx_k7_(_e22.n_dot_h);
            d = _e49;
        }
        float _e50 = d;
        float _e51 = visibility;
        specular = ((_e50 * _e51) * _e46) * 0.5;
        metal::float3 _e56 = n;
        metal::float3 _e58 = weft_prefiltered_radiance_k8_(metal::reflect(-(v_4), _e56), weft_frame, weft_environment, weft_environment_sampler);
        metal::float3 _e59 = env_brdf;
        indirect_specular = (_e58 * _e59) * 0.5;
    }
    metal::float3 _e63 = direct_kd;
    metal::float3 _e64 = weft_diffuse_lambert(base);
    metal::float3 diffuse = _e63 * _e64;
    metal::float3 _e66 = specular;
    metal::float3 direct = ((diffuse + _e66) * metal::float3(3.2, 3.05, 2.8)) * _e22.n_dot_l;
    metal::float3 _e72 = n;
    metal::float3 _e73 = weft_sh_irradiance(_e72);
    metal::float3 _e74 = ambient_kd;
    metal::float3 indirect_diffuse = (_e73 * _e74) * base;
    metal::float3 _e77 = indirect_specular;
    metal::float3 color_1 = (direct + _e77) + indirect_diffuse;
    metal::float3 _e80 = n;
    metal::float3 _e82 = standard_sphere_map(color_1, _e80, in_1.world_position);
    metal::float3 radiance = metal::clamp(_e82 + metal::float3(0.0), metal::float3(0.0), metal::float3(65504.0));
    standard_alpha_test(alpha_1);
    return fs_mainOutput { metal::float4(radiance, alpha_1) };
}
