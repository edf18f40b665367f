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
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant metal::float3 skin_lut_shape = metal::float3(4.0, 10.0, 20.0);
constant float skin_lut_ring = 3.1415927;
constant metal::float3 seed_lut_shape = metal::float3(4.0, 10.0, 20.0);
constant float seed_lut_ring = 1.5707964;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
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
    metal::float3 n_2,
    metal::float3 v_2,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_2, n_2);
    float _e6 = weft_clamp_cos(metal::dot(n_2, v_2));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_2, _e2)), metal::saturate(metal::dot(n_2, _e4)), metal::saturate(metal::dot(v_2, _e4))};
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

metal::float2 weft_transform_uv_k4_(
    metal::float2 uv_1
) {
    return uv_1 + metal::float2(0.0, 0.0);
}

metal::float2 weft_env_brdf_lut_k5_(
    float n_dot_v,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv_2 = metal::float2(metal::saturate(n_dot_v), 0.5);
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv_2, metal::level(0.0));
    return _e8.xy;
}

metal::float3 weft_env_brdf_from_lut_k6_(
    metal::float2 scale_bias
) {
    metal::float2 sb = metal::saturate(scale_bias);
    return (metal::float3(0.028) * sb.x) + metal::float3(sb.y);
}

float weft_d_ggx_nh_k10_(
    metal::float3 n_3,
    metal::float3 h
) {
    float noh = metal::saturate(metal::dot(n_3, h));
    metal::float3 nxh = metal::cross(n_3, h);
    float d = metal::dot(nxh, nxh) + ((noh * noh) * 0.01977539);
    return 0.01977539 / (WEFT_PI * metal::max(d * d, 0.000000000000000000000000000001));
}

float weft_v_smith_ggx_correlated_k11_(
    float n_dot_v_1,
    float n_dot_l
) {
    float _e6 = weft_clamp_cos(n_dot_v_1);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = _e7 * metal::sqrt(((_e6 * _e6) * 0.9802246) + 0.01977539);
    float ll = _e6 * metal::sqrt(((_e7 * _e7) * 0.9802246) + 0.01977539);
    return 0.5 / (lv + ll);
}

float weft_d_ggx_nh_k12_(
    metal::float3 n_4,
    metal::float3 h_1
) {
    float noh_1 = metal::saturate(metal::dot(n_4, h_1));
    metal::float3 nxh_1 = metal::cross(n_4, h_1);
    float d_1 = metal::dot(nxh_1, nxh_1) + ((noh_1 * noh_1) * 0.17850621);
    return 0.17850621 / (WEFT_PI * metal::max(d_1 * d_1, 0.000000000000000000000000000001));
}

float weft_v_smith_ggx_correlated_k13_(
    float n_dot_v_2,
    float n_dot_l_1
) {
    float _e6 = weft_clamp_cos(n_dot_v_2);
    float _e7 = weft_clamp_cos(n_dot_l_1);
    float lv_1 = _e7 * metal::sqrt(((_e6 * _e6) * 0.8214938) + 0.17850621);
    float ll_1 = _e6 * metal::sqrt(((_e7 * _e7) * 0.8214938) + 0.17850621);
    return 0.5 / (lv_1 + ll_1);
}

metal::float3 weft_f_schlick_k14_(
    float v_dot_h
) {
    float _e5 = weft_pow5_(1.0 - metal::saturate(v_dot_h));
    return metal::float3(0.028) + (metal::float3(0.972, 0.972, 0.972) * _e5);
}

float skin_dual_ggx_k7_(
    metal::float3 n_5,
    metal::float3 h_2,
    float n_dot_v_3,
    float n_dot_l_2,
    float v_dot_h_1
) {
    float _e10 = weft_d_ggx_nh_k10_(n_5, h_2);
    float _e11 = weft_v_smith_ggx_correlated_k11_(n_dot_v_3, n_dot_l_2);
    float lobe0_ = _e10 * _e11;
    float _e13 = weft_d_ggx_nh_k12_(n_5, h_2);
    float _e14 = weft_v_smith_ggx_correlated_k13_(n_dot_v_3, n_dot_l_2);
    float lobe1_ = _e13 * _e14;
    metal::float3 _e16 = weft_f_schlick_k14_(v_dot_h_1);
    float f = _e16.x;
    return metal::mix(lobe0_, lobe1_, 0.15) * f;
}

float weft_specular_mip_k15_(
    constant WeftFrame& weft_frame
) {
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return 0.675 * max_mip;
}

metal::float3 weft_prefiltered_radiance_k9_(
    metal::float3 dir,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip_k15_(weft_frame);
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
, metal::sampler material_sampler [[sampler(2)]]
, metal::sampler material_clamp_sampler [[sampler(3)]]
, metal::texture2d<float, metal::access::sample> curvature_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> skin_lut [[texture(3)]]
) {
    const WeftVaryings in_2 = { clip_position, varyings_3.world_position_2, varyings_3.world_normal_1, varyings_3.world_tangent, varyings_3.uv0_ };
    float curvature = {};
    metal::float3 n = {};
    metal::float3 falloff = {};
    float specular = {};
    metal::float3 kd = {};
    metal::float2 _e2 = weft_transform_uv_k4_(in_2.uv0_);
    WeftSurface _e11 = weft_surface(in_2.world_position, in_2.world_normal, weft_frame);
    metal::float3 v_4 = _e11.v;
    metal::float3 n_geom = _e11.n;
    metal::float3 _e14 = metal::fwidth(n_geom);
    float dn = metal::length(_e14);
    metal::float3 _e17 = metal::fwidth(in_2.world_position);
    float dp = metal::length(_e17);
    float estimated = (dp > 0.000000000001) ? (dn / dp) : 0.0;
    metal::float4 _e26 = curvature_map.sample(material_sampler, _e2);
    float mapped = _e26.x;
    curvature = metal::saturate(0.6 * estimated);
    n = n_geom;
    metal::float3 _e33 = n;
    WeftLightGeometry _e34 = weft_main_light_geometry(_e33, v_4, weft_frame);
    metal::float3 _e35 = n;
    float u = metal::clamp((metal::dot(_e35, _e34.l) * 0.5) + 0.5, 0.0, 1.0);
    {
        {
            float _e46 = curvature;
            metal::float4 _e48 = table_skin_lut(metal::float2(u, _e46), material_clamp_sampler, skin_lut);
            falloff = _e48.xyz;
        }
    }
    metal::float3 _e50 = falloff;
    falloff = metal::max(_e50, metal::float3(0.0));
    metal::float2 _e54 = weft_env_brdf_lut_k5_(_e34.n_dot_v, weft_brdf_lut, weft_lut_sampler);
    metal::float3 _e55 = weft_env_brdf_from_lut_k6_(_e54);
    {
        metal::float3 _e58 = n;
        float _e63 = skin_dual_ggx_k7_(_e58, _e34.h, _e34.n_dot_v, _e34.n_dot_l, _e34.v_dot_h);
        specular = _e63 * _e34.n_dot_l;
        kd = metal::max(metal::float3(1.0) - _e55, metal::float3(0.0));
    }
    metal::float3 _e70 = weft_main_light_radiance(weft_frame);
    metal::float3 _e71 = kd;
    metal::float3 _e74 = falloff;
    float _e76 = specular;
    metal::float3 direct = (((_e71 * metal::float3(0.22029306, 0.10898664, 0.074173205)) * _e74) + metal::float3(_e76)) * _e70;
    metal::float3 _e80 = n;
    metal::float3 _e81 = weft_sh_irradiance(_e80, weft_frame);
    metal::float3 _e82 = kd;
    metal::float3 indirect_diffuse = (_e81 * _e82) * metal::float3(0.6920711, 0.34239164, 0.233022);
    metal::float3 _e86 = n;
    metal::float3 _e88 = weft_prefiltered_radiance_k9_(metal::reflect(-(v_4), _e86), weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 indirect_specular = _e88 * _e55;
    metal::float3 color = (direct + indirect_diffuse) + indirect_specular;
    metal::float3 radiance = metal::clamp(color, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
