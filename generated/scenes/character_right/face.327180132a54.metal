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
struct FaceLight {
    float f_dot_l;
    bool from_right;
    char _pad2[3];
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant metal::float3 skin_lut_shape = metal::float3(4.0, 10.0, 20.0);
constant float skin_lut_ring = 3.1415927;
constant uint TIER_STYLISED = 0u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;

metal::float4 table_skin_lut(
    metal::float2 uv,
    metal::sampler material_clamp_sampler,
    metal::texture2d<float, metal::access::sample> skin_lut
) {
    metal::float2 st = ((metal::clamp(uv, metal::float2(0.0), metal::float2(1.0)) * metal::float2(63.0, 63.0)) + metal::float2(0.5)) / metal::float2(64.0, 64.0);
    metal::float4 _e13 = skin_lut.sample(material_clamp_sampler, st, metal::level(0.0));
    return _e13;
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

metal::float3 weft_safe_normalize_k1_(
    metal::float3 v_1
) {
    float len2_1 = metal::dot(v_1, v_1);
    return (len2_1 > 0.00000000000000000001) ? (v_1 * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : metal::float3(0.0, 0.0, 1.0);
}

metal::float3 weft_main_light_direction(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_direction;
    metal::float3 _e4 = weft_safe_normalize_k1_(_e2.xyz);
    return _e4;
}

metal::float3 weft_main_light_radiance(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_color;
    return metal::max(_e2.xyz, metal::float3(0.0));
}

metal::float3 weft_sh_irradiance(
    metal::float3 n,
    constant WeftFrame& weft_frame
) {
    metal::float3 e = {};
    type_5 sh = weft_frame.sh;
    e = sh.inner[0].xyz * 0.282095;
    metal::float3 _e9 = e;
    e = _e9 + (sh.inner[1].xyz * (0.488603 * n.y));
    metal::float3 _e17 = e;
    e = _e17 + (sh.inner[2].xyz * (0.488603 * n.z));
    metal::float3 _e25 = e;
    e = _e25 + (sh.inner[3].xyz * (0.488603 * n.x));
    metal::float3 _e33 = e;
    e = _e33 + (sh.inner[4].xyz * ((1.092548 * n.x) * n.y));
    metal::float3 _e43 = e;
    e = _e43 + (sh.inner[5].xyz * ((1.092548 * n.y) * n.z));
    metal::float3 _e53 = e;
    e = _e53 + (sh.inner[6].xyz * (0.315392 * (((3.0 * n.z) * n.z) - 1.0)));
    metal::float3 _e67 = e;
    e = _e67 + (sh.inner[7].xyz * ((1.092548 * n.x) * n.z));
    metal::float3 _e77 = e;
    e = _e77 + (sh.inner[8].xyz * (0.546274 * ((n.x * n.x) - (n.y * n.y))));
    metal::float3 _e91 = e;
    return metal::max(_e91, metal::float3(0.0));
}

metal::float3 weft_view_direction_k2_(
    metal::float3 world_position,
    constant WeftFrame& weft_frame
) {
    metal::float4 _e4 = weft_frame.camera_position;
    metal::float3 _e7 = weft_safe_normalize_k1_(_e4.xyz - world_position);
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
    metal::float3 n_1,
    metal::float3 v_2,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_2, n_1);
    float _e6 = weft_clamp_cos(metal::dot(n_1, v_2));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_1, _e2)), metal::saturate(metal::dot(n_1, _e4)), metal::saturate(metal::dot(v_2, _e4))};
}

metal::float3 weft_safe_normalize_k3_(
    metal::float3 v_3
) {
    float len2_2 = metal::dot(v_3, v_3);
    return (len2_2 > 0.00000000000000000001) ? (v_3 * metal::rsqrt(metal::max(len2_2, 0.00000000000000000001))) : metal::float3(0.0);
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
    metal::float3 _e53 = weft_safe_normalize_k3_(normal3_ * in_3.normal);
    out_1.world_normal = _e53;
    metal::float3 _e58 = weft_safe_normalize_k3_(model3_ * in_3.tangent.xyz);
    out_1.world_tangent = metal::float4(_e58, bitangent_sign);
    out_1.uv0_ = in_3.uv0_;
    WeftVaryings _e62 = out_1;
    return _e62;
}

metal::float3 weft_safe_normalize_k4_(
    metal::float3 v_4
) {
    float len2_3 = metal::dot(v_4, v_4);
    return (len2_3 > 0.00000000000000000001) ? (v_4 * metal::rsqrt(metal::max(len2_3, 0.00000000000000000001))) : metal::float3(1.0, 0.0, 0.0);
}

FaceLight face_light(
    metal::float3 l,
    constant WeftObject& weft_object
) {
    FaceLight out_2 = {};
    metal::float4x4 model_1 = weft_object.model;
    metal::float3 _e6 = weft_safe_normalize_k1_(model_1[2].xyz);
    metal::float3 _e9 = weft_safe_normalize_k4_(model_1[0].xyz);
    metal::float3 _e14 = weft_safe_normalize(metal::float3(l.x, 0.0, l.z), _e6);
    out_2.f_dot_l = (metal::dot(_e6, _e14) * -0.5) + 0.5;
    out_2.from_right = metal::dot(_e9, _e14) >= 0.0;
    FaceLight _e26 = out_2;
    return _e26;
}

metal::float2 weft_transform_uv_k5_(
    metal::float2 uv_1
) {
    return uv_1 + metal::float2(0.0, 0.0);
}

float face_sdf_shadow_k6_(
    metal::float2 uv_2,
    FaceLight light,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> face_sdf_map
) {
    metal::float4 _e5 = face_sdf_map.sample(material_sampler, uv_2);
    float sdf_l = _e5.x;
    metal::float4 _e14 = face_sdf_map.sample(material_sampler, metal::float2(1.0 - uv_2.x, uv_2.y));
    float sdf_r = _e14.x;
    float sdf = light.from_right ? sdf_r : sdf_l;
    return metal::smoothstep(-0.05, 0.05, sdf - light.f_dot_l);
}

float skin_seed_specular_k7_(
    metal::float3 n_2,
    metal::float3 l_1,
    metal::float3 h
) {
    float n_dot_h = metal::saturate(metal::dot(n_2, h));
    float l_dot_h = metal::saturate(metal::dot(l_1, h));
    float d = ((n_dot_h * n_dot_h) * -0.8704) + 1.00001;
    float nl = metal::saturate(metal::dot(n_2, l_1));
    float s_ao = metal::mix(0.100112915, 1.0, metal::saturate(-0.3 + (nl * nl)));
    float denom = ((d * d) * metal::max(0.1, l_dot_h * l_dot_h)) * 3.44;
    float ggx = 0.1296 / denom;
    float second = (0.2592 / denom) * 0.15;
    return (((ggx / 2.0) + second) * s_ao) / WEFT_PI;
}

metal::float2 weft_env_brdf_lut_k9_(
    float n_dot_v,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv_3 = metal::float2(metal::saturate(n_dot_v), 0.6);
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv_3, metal::level(0.0));
    return _e8.xy;
}

metal::float3 weft_env_brdf_from_lut_k10_(
    metal::float2 scale_bias
) {
    metal::float2 sb = metal::saturate(scale_bias);
    return (metal::float3(0.028) * sb.x) + metal::float3(sb.y);
}

float weft_specular_mip_k12_(
    constant WeftFrame& weft_frame
) {
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return 0.768 * max_mip;
}

metal::float3 weft_prefiltered_radiance_k11_(
    metal::float3 dir,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip_k12_(weft_frame);
    metal::float4 c_1 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_1.xyz, metal::float3(0.0));
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
, constant WeftObject& weft_object [[buffer(1)]]
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
    float distance = metal::min(clip.w, 10.0);
    metal::float4 _e74 = weft_frame.viewport;
    metal::float2 offset = (((direction * 1.5) * 2.0) * _e74.zw) * distance;
    out.clip_position = metal::float4(clip.xy + offset, clip.zw);
    WeftOutlineVaryings _e84 = out;
    const auto _tmp = _e84;
    return vs_outlineOutput { _tmp.clip_position };
}


struct fs_outlineOutput {
    metal::float4 member_1 [[color(0)]];
};
fragment fs_outlineOutput fs_outline(
) {
    return fs_outlineOutput { metal::float4(metal::float3(0.0, 0.0, 0.0), 1.0) };
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
, constant WeftObject& weft_object [[buffer(1)]]
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
, metal::texturecube<float, metal::access::sample> weft_environment [[texture(0)]]
, metal::sampler weft_environment_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> weft_brdf_lut [[texture(1)]]
, metal::sampler weft_lut_sampler [[sampler(1)]]
, constant WeftObject& weft_object [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::sampler material_clamp_sampler [[sampler(3)]]
, metal::texture2d<float, metal::access::sample> face_sdf_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> shadow_mask_map [[texture(3)]]
, metal::texture2d<float, metal::access::sample> skin_lut [[texture(4)]]
) {
    const WeftVaryings in_2 = { clip_position, varyings_3.world_position_2, varyings_3.world_normal_1, varyings_3.world_tangent, varyings_3.uv0_ };
    float bias = {};
    metal::float2 _e2 = weft_transform_uv_k5_(in_2.uv0_);
    metal::float4 _e11 = shadow_mask_map.sample(material_sampler, _e2);
    float shadow_mask = metal::saturate(_e11.x);
    WeftSurface _e16 = weft_surface(in_2.world_position, in_2.world_normal, weft_frame);
    metal::float3 v_5 = _e16.v;
    metal::float3 n_3 = _e16.n;
    metal::float3 _e19 = metal::fwidth(n_3);
    float dn = metal::length(_e19);
    metal::float3 _e22 = metal::fwidth(in_2.world_position);
    float dp = metal::length(_e22);
    float estimated = (dp > 0.000000000001) ? (dn / dp) : 0.0;
    float curvature = metal::clamp(0.6 * estimated, 0.01, 0.99);
    WeftLightGeometry _e34 = weft_main_light_geometry(n_3, v_5, weft_frame);
    FaceLight _e36 = face_light(_e34.l, weft_object);
    float _e37 = face_sdf_shadow_k6_(_e2, _e36, material_sampler, face_sdf_map);
    bias = _e37 * shadow_mask;
    float _e40 = bias;
    bias = metal::clamp(_e40, 0.0, 1.0);
    float _e44 = bias;
    metal::float4 _e46 = table_skin_lut(metal::float2(_e44, curvature), material_clamp_sampler, skin_lut);
    metal::float3 falloff = metal::max(_e46.xyz, metal::float3(0.0));
    float _e52 = skin_seed_specular_k7_(n_3, _e34.l, _e34.h);
    float specular = (_e52 * 0.028) * _e34.n_dot_l;
    metal::float3 _e57 = weft_main_light_radiance(weft_frame);
    metal::float3 direct = ((metal::float3(0.2560481, 0.15688866, 0.1216312) * falloff) + metal::float3(specular)) * _e57;
    metal::float2 _e64 = weft_env_brdf_lut_k9_(_e34.n_dot_v, weft_brdf_lut, weft_lut_sampler);
    metal::float3 _e65 = weft_env_brdf_from_lut_k10_(_e64);
    metal::float3 _e66 = weft_sh_irradiance(n_3, weft_frame);
    metal::float3 indirect_diffuse = (_e66 * metal::float3(0.972)) * metal::float3(0.82757086, 0.5070785, 0.39312312);
    metal::float3 _e71 = weft_prefiltered_radiance_k11_(metal::reflect(-(v_5), n_3), weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 indirect_specular = _e71 * _e65;
    metal::float3 color = (direct + indirect_diffuse) + indirect_specular;
    metal::float3 radiance = metal::clamp(color, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
