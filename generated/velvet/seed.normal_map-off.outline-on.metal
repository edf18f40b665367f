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

float weft_pow4_(
    float x
) {
    float x2_ = x * x;
    return x2_ * x2_;
}

float weft_pow5_(
    float x_1
) {
    float x2_1 = x_1 * x_1;
    return (x2_1 * x2_1) * x_1;
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

metal::float3 weft_f_schlick(
    metal::float3 f0_,
    float v_dot_h
) {
    float _e5 = weft_pow5_(1.0 - metal::saturate(v_dot_h));
    return f0_ + ((metal::float3(1.0) - f0_) * _e5);
}

float weft_v_schlick_ggx(
    float n_dot_v,
    float n_dot_l,
    float roughness_1
) {
    float _e3 = weft_clamp_roughness(roughness_1);
    float a = _e3 * _e3;
    float k = ((a + 1.0) * (a + 1.0)) * 0.125;
    float gv = (metal::saturate(n_dot_v) * (1.0 - k)) + k;
    float gl = (metal::saturate(n_dot_l) * (1.0 - k)) + k;
    return 0.25 / (gv * gl);
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
    type_5 sh = weft_frame.sh;
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
    metal::float3 v_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_1, n_2);
    float _e6 = weft_clamp_cos(metal::dot(n_2, v_1));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_2, _e2)), metal::saturate(metal::dot(n_2, _e4)), metal::saturate(metal::dot(v_1, _e4))};
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

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

float weft_fabric_d(
    float n_dot_h
) {
    float x_2 = 1.0 - metal::saturate(n_dot_h);
    return ((0.96 * x_2) * x_2) + 0.057;
}

float weft_fabric_scatter_fresnel_lerp(
    float n_dot_v_1,
    float scale
) {
    float x_3 = 1.0 - metal::saturate(n_dot_v_1);
    float _e5 = weft_pow4_(x_3);
    return metal::mix(_e5, 0.4 * x_3, metal::saturate(scale));
}

metal::float3 weft_fabric_scatter(
    metal::float3 scatter_color,
    float n_dot_l_1,
    float n_dot_v_2,
    float scale_1
) {
    float wrap = (metal::saturate(n_dot_l_1) * 0.5) + 0.5;
    float _e12 = weft_fabric_scatter_fresnel_lerp(n_dot_v_2, scale_1);
    return metal::max(scatter_color, metal::float3(0.0)) * (wrap * _e12);
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
  vs_mainInput varyings_2 [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
) {
    const WeftVertexInput in_1 = { varyings_2.position, varyings_2.normal, varyings_2.tangent, varyings_2.uv0_ };
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
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(0)]]
, metal::texture2d<float, metal::access::sample> occlusion_map [[texture(1)]]
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
    metal::float3 v_2 = _e39.v;
    n = _e39.n;
    metal::float3 _e43 = n;
    WeftLightGeometry _e44 = weft_main_light_geometry(_e43, v_2, weft_frame);
    float l_dot_h = metal::saturate(metal::dot(_e44.l, _e44.h));
    metal::float3 f0_1 = metal::mix(metal::float3(0.04), base, metallic);
    metal::float3 diffuse_albedo = base * (1.0 - metallic);
    metal::float3 _e55 = weft_main_light_radiance(weft_frame);
    metal::float3 _e56 = n;
    metal::float3 _e57 = weft_sh_irradiance(_e56, weft_frame);
    metal::float3 ambient = _e57 * ao;
    {
        float _e62 = weft_v_schlick_ggx(_e44.n_dot_v, _e44.n_dot_l, roughness_2);
        metal::float3 _e63 = weft_f_schlick(f0_1, l_dot_h);
        float _e65 = weft_fabric_d(_e44.n_dot_h);
        metal::float3 specular = (_e65 * _e62) * _e63;
        metal::float3 _e68 = weft_diffuse_lambert(diffuse_albedo);
        metal::float3 direct = ((_e68 + specular) * _e55) * _e44.n_dot_l;
        metal::float4 _e75 = material.scatter_color;
        float _e81 = material.scatter_scale;
        metal::float3 _e82 = weft_fabric_scatter(_e75.xyz, _e44.n_dot_l, _e44.n_dot_v, _e81);
        color = (direct + (ambient * diffuse_albedo)) + _e82;
    }
    metal::float3 _e86 = color;
    metal::float3 radiance = metal::clamp(_e86, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
