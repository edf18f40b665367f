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
struct WeftMaterial {
    metal::float4 base_color;
    float metallic;
    float smoothness;
    char _pad3[8];
    metal::float4 base_map_st;
    float normal_strength;
    float occlusion_strength;
    char _pad6[8];
    metal::float4 scatter_color;
    float scatter_scale;
    char _pad8[12];
    metal::float4 outline_color;
    float outline_width;
    float outline_max_distance;
    char _pad11[8];
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

float weft_max3_(
    metal::float3 v
) {
    return metal::max(v.x, metal::max(v.y, v.z));
}

float weft_clamp_cos(
    float c
) {
    return metal::clamp(c, WEFT_MIN_N_DOT, 1.0);
}

metal::float3 weft_safe_normalize(
    metal::float3 v_1,
    metal::float3 fallback
) {
    float len2_ = metal::dot(v_1, v_1);
    return (len2_ > 0.00000000000000000001) ? (v_1 * metal::rsqrt(metal::max(len2_, 0.00000000000000000001))) : fallback;
}

metal::float3 weft_diffuse_lambert(
    metal::float3 albedo
) {
    return albedo * WEFT_INV_PI;
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
    metal::float3 n_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 e = {};
    type_4 sh = weft_frame.sh;
    e = sh.inner[0].xyz * 0.282095;
    metal::float3 _e9 = e;
    e = _e9 + (sh.inner[1].xyz * (0.488603 * n_1.y));
    metal::float3 _e17 = e;
    e = _e17 + (sh.inner[2].xyz * (0.488603 * n_1.z));
    metal::float3 _e25 = e;
    e = _e25 + (sh.inner[3].xyz * (0.488603 * n_1.x));
    metal::float3 _e33 = e;
    e = _e33 + (sh.inner[4].xyz * ((1.092548 * n_1.x) * n_1.y));
    metal::float3 _e43 = e;
    e = _e43 + (sh.inner[5].xyz * ((1.092548 * n_1.y) * n_1.z));
    metal::float3 _e53 = e;
    e = _e53 + (sh.inner[6].xyz * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0)));
    metal::float3 _e67 = e;
    e = _e67 + (sh.inner[7].xyz * ((1.092548 * n_1.x) * n_1.z));
    metal::float3 _e77 = e;
    e = _e77 + (sh.inner[8].xyz * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y))));
    metal::float3 _e91 = e;
    return metal::max(_e91, metal::float3(0.0));
}

float weft_specular_mip(
    float roughness,
    constant WeftFrame& weft_frame
) {
    float r_2 = metal::saturate(roughness);
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return (r_2 * (1.7 - (0.7 * r_2))) * max_mip;
}

metal::float3 weft_prefiltered_radiance(
    metal::float3 dir,
    float roughness_1,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip(roughness_1, weft_frame);
    metal::float4 c_1 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_1.xyz, metal::float3(0.0));
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
    metal::float3 n_2,
    metal::float3 v_2,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_2, n_2);
    float _e6 = weft_clamp_cos(metal::dot(n_2, v_2));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_2, _e2)), metal::saturate(metal::dot(n_2, _e4)), metal::saturate(metal::dot(v_2, _e4))};
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

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

float weft_sheen_clamp_roughness(
    float sheen_roughness
) {
    return metal::clamp(sheen_roughness, WEFT_SHEEN_MIN_ROUGHNESS, 1.0);
}

float weft_d_charlie(
    float n_dot_h,
    float sheen_roughness_1
) {
    float _e2 = weft_sheen_clamp_roughness(sheen_roughness_1);
    float inv_r = 1.0 / _e2;
    float noh = metal::saturate(n_dot_h);
    float sin2_ = metal::max((1.0 - noh) * (1.0 + noh), 0.0);
    return ((2.0 + inv_r) * metal::pow(sin2_, 0.5 * inv_r)) * 0.15915494;
}

float weft_sheen_l(
    float x,
    float r
) {
    float t = (1.0 - r) * (1.0 - r);
    float a = metal::mix(21.5473, 25.3245, t);
    float b = metal::mix(3.82987, 3.32435, t);
    float c_2 = metal::mix(0.19823, 0.16801, t);
    float d = metal::mix(-1.9776, -1.27393, t);
    float e_1 = metal::mix(-4.32054, -4.85967, t);
    return ((a / (1.0 + (b * metal::pow(metal::max(x, 0.0), c_2)))) + (d * x)) + e_1;
}

float weft_sheen_lambda_one_exp(
    float cos_theta,
    float r_1
) {
    float _e2 = weft_clamp_cos(cos_theta);
    bool low = _e2 < 0.5;
    float _e8 = weft_sheen_l(low ? _e2 : (1.0 - _e2), r_1);
    float _e10 = weft_sheen_l(0.5, r_1);
    return metal::exp(low ? _e8 : ((2.0 * _e10) - _e8));
}

float weft_v_charlie(
    float n_dot_v,
    float n_dot_l,
    float sheen_roughness_2
) {
    float _e3 = weft_sheen_clamp_roughness(sheen_roughness_2);
    float _e4 = weft_clamp_cos(n_dot_v);
    float _e5 = weft_clamp_cos(n_dot_l);
    float _e6 = weft_sheen_lambda_one_exp(_e4, _e3);
    float _e9 = weft_sheen_lambda_one_exp(_e5, _e3);
    float g_inv = (1.0 + _e6) + _e9;
    return 1.0 / (((g_inv * 4.0) * _e4) * _e5);
}

metal::float3 weft_sheen_charlie(
    metal::float3 sheen_color,
    float n_dot_h_1,
    float n_dot_v_1,
    float n_dot_l_1,
    float sheen_roughness_3
) {
    float _e5 = weft_d_charlie(n_dot_h_1, sheen_roughness_3);
    float _e6 = weft_v_charlie(n_dot_v_1, n_dot_l_1, sheen_roughness_3);
    float lobe = _e5 * _e6;
    return metal::max(sheen_color, metal::float3(0.0)) * (lobe * metal::saturate(n_dot_l_1));
}

float weft_sheen_albedo_scaling_view(
    metal::float3 sheen_color_1,
    float e_v
) {
    float _e2 = weft_max3_(sheen_color_1);
    return metal::saturate(1.0 - (metal::saturate(_e2) * metal::saturate(e_v)));
}

float weft_sheen_albedo(
    float n_dot_x,
    float sheen_roughness_4,
    metal::sampler weft_lut_sampler,
    metal::texture2d<float, metal::access::sample> weft_sheen_lut
) {
    float _e3 = weft_sheen_clamp_roughness(sheen_roughness_4);
    metal::float2 uv_1 = metal::float2(metal::saturate(n_dot_x), _e3);
    metal::float4 _e8 = weft_sheen_lut.sample(weft_lut_sampler, uv_1, metal::level(0.0));
    return metal::saturate(_e8.x);
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
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> occlusion_map [[texture(3)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    metal::float3 color = {};
    metal::float3 sheen = {};
    float scaling = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    metal::float4 _e8 = material.base_color;
    metal::float4 _e11 = base_map.sample(material_sampler, _e5);
    metal::float4 base_rgba = _e8 * _e11;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float alpha = metal::saturate(base_rgba.w);
    float _e19 = material.metallic;
    float metallic = metal::saturate(_e19);
    float _e23 = material.smoothness;
    float smoothness = metal::saturate(_e23);
    float roughness_2 = 1.0 - smoothness;
    metal::float4 _e29 = occlusion_map.sample(material_sampler, _e5);
    float occlusion = _e29.x;
    float _e33 = material.occlusion_strength;
    float ao = metal::saturate(metal::mix(1.0, occlusion, _e33));
    WeftSurface _e39 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_3 = _e39.v;
    n = _e39.n;
    metal::float3 _e43 = n;
    WeftLightGeometry _e44 = weft_main_light_geometry(_e43, v_3, weft_frame);
    float l_dot_h = metal::saturate(metal::dot(_e44.l, _e44.h));
    metal::float3 f0_ = metal::mix(metal::float3(0.04), base, metallic);
    metal::float3 diffuse_albedo = base * (1.0 - metallic);
    metal::float3 _e55 = weft_main_light_radiance(weft_frame);
    metal::float3 _e56 = n;
    metal::float3 _e57 = weft_sh_irradiance(_e56, weft_frame);
    metal::float3 ambient = _e57 * ao;
    {
        metal::float4 _e62 = material.scatter_color;
        metal::float3 sheen_color_2 = metal::saturate(f0_ + metal::max(_e62.xyz, metal::float3(0.0)));
        float _e69 = weft_sheen_clamp_roughness(roughness_2);
        float _e71 = weft_sheen_albedo(_e44.n_dot_v, _e69, weft_lut_sampler, weft_sheen_lut);
        float _e72 = weft_sheen_albedo_scaling_view(sheen_color_2, _e71);
        {
            metal::float3 _e78 = weft_sheen_charlie(sheen_color_2, _e44.n_dot_h, _e44.n_dot_v, _e44.n_dot_l, _e69);
            sheen = _e78;
            scaling = _e72;
        }
        metal::float3 _e79 = weft_diffuse_lambert(diffuse_albedo);
        float _e80 = scaling;
        metal::float3 base_direct = _e79 * (_e80 * _e44.n_dot_l);
        metal::float3 _e84 = sheen;
        metal::float3 direct = (_e84 + base_direct) * _e55;
        metal::float3 _e88 = n;
        metal::float3 _e90 = weft_prefiltered_radiance(metal::reflect(-(v_3), _e88), _e69, weft_frame, weft_environment, weft_environment_sampler);
        metal::float3 env_sheen = (_e90 * sheen_color_2) * (_e71 * ao);
        color = (direct + ((ambient * diffuse_albedo) * _e72)) + env_sheen;
    }
    metal::float3 _e98 = color;
    metal::float3 radiance = metal::clamp(_e98, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
