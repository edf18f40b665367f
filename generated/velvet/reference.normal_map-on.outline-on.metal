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
    metal::float4 scatter_color;
    float scatter_scale;
    char _pad8[12];
    metal::float4 outline_color;
    float outline_width;
    float outline_max_distance;
    char _pad11[8];
};
struct WeftOutlineVertex {
    metal::float3 position;
    metal::float3 normal;
};
struct WeftOutlineVaryings {
    metal::float4 clip_position;
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

metal::float3 weft_any_perpendicular(
    metal::float3 n_1
) {
    float s = (n_1.z >= 0.0) ? 1.0 : -1.0;
    float a = -1.0 / (s + n_1.z);
    float b = (n_1.x * n_1.y) * a;
    return metal::float3(1.0 + (((s * n_1.x) * n_1.x) * a), s * b, -(s) * n_1.x);
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
    metal::float3 n_2,
    constant WeftFrame& weft_frame
) {
    metal::float3 e = {};
    type_5 sh = weft_frame.sh;
    e = sh.inner[0].xyz * 0.282095;
    metal::float3 _e9 = e;
    e = _e9 + (sh.inner[1].xyz * (0.488603 * n_2.y));
    metal::float3 _e17 = e;
    e = _e17 + (sh.inner[2].xyz * (0.488603 * n_2.z));
    metal::float3 _e25 = e;
    e = _e25 + (sh.inner[3].xyz * (0.488603 * n_2.x));
    metal::float3 _e33 = e;
    e = _e33 + (sh.inner[4].xyz * ((1.092548 * n_2.x) * n_2.y));
    metal::float3 _e43 = e;
    e = _e43 + (sh.inner[5].xyz * ((1.092548 * n_2.y) * n_2.z));
    metal::float3 _e53 = e;
    e = _e53 + (sh.inner[6].xyz * (0.315392 * (((3.0 * n_2.z) * n_2.z) - 1.0)));
    metal::float3 _e67 = e;
    e = _e67 + (sh.inner[7].xyz * ((1.092548 * n_2.x) * n_2.z));
    metal::float3 _e77 = e;
    e = _e77 + (sh.inner[8].xyz * (0.546274 * ((n_2.x * n_2.x) - (n_2.y * n_2.y))));
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
    metal::float3 n_3,
    metal::float3 v_2,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_2, n_3);
    float _e6 = weft_clamp_cos(metal::dot(n_3, v_2));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_3, _e2)), metal::saturate(metal::dot(n_3, _e4)), metal::saturate(metal::dot(v_2, _e4))};
}

WeftVaryings weft_forward_vertex(
    WeftVertexInput in_3,
    constant WeftFrame& weft_frame,
    constant WeftObject& weft_object
) {
    WeftVaryings out_1 = {};
    metal::float4x4 model = weft_object.model;
    metal::float3x3 model3_ = metal::float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    metal::float4x4 nm = weft_object.normal_matrix;
    metal::float3x3 normal3_ = metal::float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    metal::float4 world = model * metal::float4(in_3.position, 1.0);
    float mirror = (metal::determinant(model3_) < 0.0) ? -1.0 : 1.0;
    float bitangent_sign = ((in_3.tangent.w < 0.0) ? -1.0 : 1.0) * mirror;
    metal::float4x4 _e43 = weft_frame.view_proj;
    out_1.clip_position = _e43 * metal::float4(world.xyz, 1.0);
    out_1.world_position = world.xyz;
    metal::float3 _e55 = weft_safe_normalize(normal3_ * in_3.normal, metal::float3(0.0));
    out_1.world_normal = _e55;
    metal::float3 _e62 = weft_safe_normalize(model3_ * in_3.tangent.xyz, metal::float3(0.0));
    out_1.world_tangent = metal::float4(_e62, bitangent_sign);
    out_1.uv0_ = in_3.uv0_;
    WeftVaryings _e66 = out_1;
    return _e66;
}

metal::float3x3 weft_tangent_frame(
    metal::float3 n_4,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_4 * metal::dot(n_4, t_in));
    float len2_1 = metal::dot(t_proj, t_proj);
    bool ok = len2_1 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_4);
    metal::float3 t = ok ? (t_proj * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : _e13;
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_4, t) * s_1;
    return metal::float3x3(t, b_1, n_4);
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
    metal::float3 n_5,
    metal::float4 tangent_1,
    metal::float3 texel_1,
    float strength_1
) {
    metal::float3x3 _e4 = weft_tangent_frame(n_5, tangent_1);
    metal::float3 _e5 = weft_unpack_normal(texel_1, strength_1);
    metal::float3 _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
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
    float t_1 = (1.0 - r) * (1.0 - r);
    float a_1 = metal::mix(21.5473, 25.3245, t_1);
    float b_2 = metal::mix(3.82987, 3.32435, t_1);
    float c_2 = metal::mix(0.19823, 0.16801, t_1);
    float d = metal::mix(-1.9776, -1.27393, t_1);
    float e_1 = metal::mix(-4.32054, -4.85967, t_1);
    return ((a_1 / (1.0 + (b_2 * metal::pow(metal::max(x, 0.0), c_2)))) + (d * x)) + e_1;
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

float weft_sheen_albedo_scaling(
    metal::float3 sheen_color_1,
    float e_v,
    float e_l
) {
    float _e3 = weft_max3_(sheen_color_1);
    float c_3 = metal::saturate(_e3);
    return metal::saturate(metal::min(1.0 - (c_3 * metal::saturate(e_v)), 1.0 - (c_3 * metal::saturate(e_l))));
}

float weft_sheen_albedo_scaling_view(
    metal::float3 sheen_color_2,
    float e_v_1
) {
    float _e2 = weft_max3_(sheen_color_2);
    return metal::saturate(1.0 - (metal::saturate(_e2) * metal::saturate(e_v_1)));
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

struct vs_outlineInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
};
struct vs_outlineOutput {
    metal::float4 clip_position [[position]];
};
vertex vs_outlineOutput vs_outline(
  vs_outlineInput varyings [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
) {
    const WeftOutlineVertex in = { varyings.position, varyings.normal };
    bool local = {};
    bool local_1 = {};
    WeftOutlineVaryings out = {};
    metal::float4x4 _e3 = weft_object.model;
    metal::float4 world_1 = _e3 * metal::float4(in.position, 1.0);
    metal::float4x4 nm_1 = weft_object.normal_matrix;
    metal::float3 normal = metal::float3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz) * in.normal;
    metal::float4x4 _e22 = weft_frame.view_proj;
    metal::float4 clip = _e22 * metal::float4(world_1.xyz, 1.0);
    metal::float4 _e29 = weft_frame.viewport;
    metal::float2 size = _e29.xy;
    metal::float4x4 _e33 = weft_frame.view_proj;
    metal::float2 screen_normal = (_e33 * metal::float4(normal, 0.0)).xy * size;
    float len = metal::length(screen_normal);
    if (len > 0.000001) {
        float _e47 = weft_frame.viewport.x;
        local = _e47 > 0.0;
    } else {
        local = false;
    }
    bool _e51 = local;
    if (_e51) {
        local_1 = clip.w > 0.0;
    } else {
        local_1 = false;
    }
    bool usable = local_1;
    metal::float2 direction = usable ? (screen_normal / metal::float2(metal::max(len, 0.000001))) : metal::float2(0.0);
    float _e68 = material.outline_width;
    float width_px = metal::max(_e68, 0.0);
    float _e74 = material.outline_max_distance;
    float distance = metal::min(clip.w, metal::max(_e74, 0.0));
    metal::float4 _e83 = weft_frame.viewport;
    metal::float2 offset = (((direction * width_px) * 2.0) * _e83.zw) * distance;
    out.clip_position = metal::float4(clip.xy + offset, clip.zw);
    WeftOutlineVaryings _e93 = out;
    const auto _tmp = _e93;
    return vs_outlineOutput { _tmp.clip_position };
}


struct fs_outlineOutput {
    metal::float4 member_1 [[color(0)]];
};
fragment fs_outlineOutput fs_outline(
  constant WeftMaterial& material [[buffer(1)]]
) {
    metal::float4 _e2 = material.outline_color;
    return fs_outlineOutput { metal::float4(metal::max(_e2.xyz, metal::float3(0.0)), 1.0) };
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
  vs_mainInput varyings_2 [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
) {
    const WeftVertexInput in_1 = { varyings_2.position, varyings_2.normal, varyings_2.tangent_2, varyings_2.uv0_ };
    WeftVaryings _e1 = weft_forward_vertex(in_1, weft_frame, weft_object);
    const auto _tmp_1 = _e1;
    return vs_mainOutput { _tmp_1.clip_position, _tmp_1.world_position, _tmp_1.world_normal, _tmp_1.world_tangent, _tmp_1.uv0_ };
}


struct fs_mainInput {
    metal::float3 world_position_2 [[user(loc0), center_perspective]];
    metal::float3 world_normal_1 [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
};
struct fs_mainOutput {
    metal::float4 member_3 [[color(0)]];
};
fragment fs_mainOutput fs_main(
  fs_mainInput varyings_3 [[stage_in]]
, metal::float4 clip_position [[position]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, metal::texturecube<float, metal::access::sample> weft_environment [[texture(0)]]
, metal::sampler weft_environment_sampler [[sampler(0)]]
, metal::sampler weft_lut_sampler [[sampler(1)]]
, metal::texture2d<float, metal::access::sample> weft_sheen_lut [[texture(1)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> normal_map [[texture(3)]]
, metal::texture2d<float, metal::access::sample> occlusion_map [[texture(4)]]
) {
    const WeftVaryings in_2 = { clip_position, varyings_3.world_position_2, varyings_3.world_normal_1, varyings_3.world_tangent, varyings_3.uv0_ };
    metal::float3 n = {};
    metal::float3 color = {};
    metal::float3 sheen = {};
    float scaling = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = weft_transform_uv(in_2.uv0_, _e4);
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
    WeftSurface _e39 = weft_surface(in_2.world_position, in_2.world_normal, weft_frame);
    metal::float3 v_4 = _e39.v;
    n = _e39.n;
    {
        metal::float4 _e45 = normal_map.sample(material_sampler, _e5);
        metal::float3 texel_2 = _e45.xyz;
        metal::float3 _e47 = n;
        float _e51 = material.normal_strength;
        metal::float3 _e52 = weft_mapped_normal(_e47, in_2.world_tangent, texel_2, _e51);
        n = _e52;
    }
    metal::float3 _e53 = n;
    WeftLightGeometry _e54 = weft_main_light_geometry(_e53, v_4, weft_frame);
    float l_dot_h = metal::saturate(metal::dot(_e54.l, _e54.h));
    metal::float3 f0_ = metal::mix(metal::float3(0.04), base, metallic);
    metal::float3 diffuse_albedo = base * (1.0 - metallic);
    metal::float3 _e65 = weft_main_light_radiance(weft_frame);
    metal::float3 _e66 = n;
    metal::float3 _e67 = weft_sh_irradiance(_e66, weft_frame);
    metal::float3 ambient = _e67 * ao;
    {
        metal::float4 _e72 = material.scatter_color;
        metal::float3 sheen_color_3 = metal::saturate(f0_ + metal::max(_e72.xyz, metal::float3(0.0)));
        float _e79 = weft_sheen_clamp_roughness(roughness_2);
        float _e81 = weft_sheen_albedo(_e54.n_dot_v, _e79, weft_lut_sampler, weft_sheen_lut);
        float _e82 = weft_sheen_albedo_scaling_view(sheen_color_3, _e81);
        {
            float _e86 = weft_sheen_albedo(_e54.n_dot_l, _e79, weft_lut_sampler, weft_sheen_lut);
            metal::float3 _e90 = weft_sheen_charlie(sheen_color_3, _e54.n_dot_h, _e54.n_dot_v, _e54.n_dot_l, _e79);
            sheen = _e90;
            float _e91 = weft_sheen_albedo_scaling(sheen_color_3, _e81, _e86);
            scaling = _e91;
        }
        metal::float3 _e92 = weft_diffuse_lambert(diffuse_albedo);
        float _e93 = scaling;
        metal::float3 base_direct = _e92 * (_e93 * _e54.n_dot_l);
        metal::float3 _e97 = sheen;
        metal::float3 direct = (_e97 + base_direct) * _e65;
        metal::float3 _e101 = n;
        metal::float3 _e103 = weft_prefiltered_radiance(metal::reflect(-(v_4), _e101), _e79, weft_frame, weft_environment, weft_environment_sampler);
        metal::float3 env_sheen = (_e103 * sheen_color_3) * (_e81 * ao);
        color = (direct + ((ambient * diffuse_albedo) * _e82)) + env_sheen;
    }
    metal::float3 _e111 = color;
    metal::float3 radiance = metal::clamp(_e111, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
