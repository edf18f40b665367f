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
    metal::float4 base_map_st;
    float smoothness;
    float metallic;
    uint diffuse_uses_aniso_normal;
    float anisotropy;
    metal::float4 aniso_normal_map_st;
    float aniso_normal_strength;
    float tangent_shift;
    float aniso_gloss;
    float aniso_spec;
    float aniso_mask;
    float flow_strength;
    char _pad13[8];
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
struct SilkLobe {
    float value;
    char _pad1[4];
    metal::float2 alpha;
    float ibl_roughness;
    char _pad3[4];
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint ANISO_MODEL_WARD = 0u;
constant uint ANISO_MODEL_HAIR_SHIFTED = 1u;
constant uint ANISO_MODEL_GGX = 2u;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant uint TIER_LOW = 3u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float WEFT_MIN_ANISO_ALPHA = 0.001;
constant float SILK_MIN_ALPHA = 0.001;
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
    metal::float3 n
) {
    float s = (n.z >= 0.0) ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = (n.x * n.y) * a;
    return metal::float3(1.0 + (((s * n.x) * n.x) * a), s * b, -(s) * n.x);
}

float weft_d_ggx_nh(
    metal::float3 n_1,
    metal::float3 h,
    float roughness_1
) {
    float _e3 = weft_clamp_roughness(roughness_1);
    float a_1 = _e3 * _e3;
    float a2_ = a_1 * a_1;
    float noh = metal::saturate(metal::dot(n_1, h));
    metal::float3 nxh = metal::cross(n_1, h);
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
    metal::float3 n_2,
    constant WeftFrame& weft_frame
) {
    metal::float3 e = {};
    type_4 sh = weft_frame.sh;
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
    metal::float2 uv_1 = metal::float2(metal::saturate(n_dot_v_1), metal::saturate(roughness_5));
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv_1, metal::level(0.0));
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
    metal::float3 n_3,
    metal::float3 v_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_1, n_3);
    float _e6 = weft_clamp_cos(metal::dot(n_3, v_1));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_3, _e2)), metal::saturate(metal::dot(n_3, _e4)), metal::saturate(metal::dot(v_1, _e4))};
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
    metal::float3 v_4 = (texel * 2.0) - metal::float3(1.0);
    return metal::float3(v_4.xy * strength, metal::max(v_4.z, 0.001));
}

metal::float3 weft_normal_from_tangent_space(
    metal::float3x3 frame,
    metal::float3 n_ts
) {
    metal::float3 _e4 = weft_safe_normalize(frame * n_ts, frame[2]);
    return _e4;
}

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

metal::float3 weft_aniso_to_frame(
    metal::float3x3 frame_1,
    metal::float3 x_1
) {
    return metal::float3(metal::dot(frame_1[0], x_1), metal::dot(frame_1[1], x_1), metal::dot(frame_1[2], x_1));
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
    float d_1 = 1.0 / ((((WEFT_PI * at_1) * ab_1) * _e9) * _e9);
    return (n_dot_h_1 > 0.0) ? d_1 : 0.0;
}

float weft_v_smith_ggx_aniso_correlated(
    metal::float3 v_2,
    metal::float3 l,
    float alpha_t_2,
    float alpha_b_2
) {
    float _e5 = weft_clamp_cos(v_2.z);
    float _e7 = weft_clamp_cos(l.z);
    float lv_1 = _e7 * metal::length(metal::float3(alpha_t_2 * v_2.x, alpha_b_2 * v_2.y, _e5));
    float ll_1 = _e5 * metal::length(metal::float3(alpha_t_2 * l.x, alpha_b_2 * l.y, _e7));
    return 0.5 / (lv_1 + ll_1);
}

metal::float3 weft_aniso_bent_normal(
    metal::float3x3 frame_2,
    metal::float3 v_3,
    float anisotropy,
    float roughness_6
) {
    float k = metal::clamp(anisotropy, -1.0, 1.0);
    metal::float3 n_5 = frame_2[2];
    metal::float3 dir_1 = (k >= 0.0) ? frame_2[1] : frame_2[0];
    metal::float3 aniso_t = metal::cross(dir_1, v_3);
    metal::float3 aniso_n = metal::cross(aniso_t, dir_1);
    float bend = metal::abs(k) * metal::saturate(5.0 * metal::saturate(roughness_6));
    metal::float3 _e22 = weft_safe_normalize(metal::mix(n_5, aniso_n, bend), n_5);
    return _e22;
}

float silk_hair_mx_seed(
    float smoothness,
    float gloss
) {
    float p = 1.0 - metal::saturate(smoothness * gloss);
    float rx = p * p;
    float rx_safe = (rx == 0.0) ? 0.0001 : rx;
    return rx_safe * rx_safe;
}

metal::float3x3 silk_tilt_frame(
    metal::float3x3 frame_3,
    float shift
) {
    float s_2 = metal::clamp(shift, -1.0, 1.0);
    metal::float3 _e10 = weft_safe_normalize(frame_3[0] + (s_2 * frame_3[2]), frame_3[0]);
    metal::float3 _e16 = weft_safe_normalize(frame_3[2] - (s_2 * frame_3[0]), frame_3[2]);
    return metal::float3x3(_e10, frame_3[1], _e16);
}

float silk_lobe_anisotropy(
    metal::float2 alpha
) {
    float at_2 = metal::max(alpha.x, SILK_MIN_ALPHA);
    float ab_2 = metal::max(alpha.y, SILK_MIN_ALPHA);
    return (at_2 - ab_2) / (at_2 + ab_2);
}

float silk_ibl_roughness(
    metal::float2 alpha_1
) {
    return metal::saturate(metal::sqrt(metal::sqrt(metal::max(alpha_1.x * alpha_1.y, 0.0))));
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
, metal::sampler material_sampler [[sampler(2)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> aniso_normal_map [[texture(3)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 fibre = {};
    SilkLobe lobe = {};
    float vis = {};
    metal::float3 env_brdf = {};
    metal::float3 ambient_kd = {};
    metal::float3 reflect_n = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    metal::float4 _e8 = material.base_color;
    metal::float4 _e11 = base_map.sample(material_sampler, _e5);
    metal::float4 base_rgba = _e8 * _e11;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float alpha_out = metal::saturate(base_rgba.w);
    float _e19 = material.smoothness;
    float smoothness_1 = metal::saturate(_e19);
    float roughness_7 = 1.0 - smoothness_1;
    float _e25 = material.metallic;
    float metallic = metal::saturate(_e25);
    metal::float3 f0_2 = metal::mix(metal::float3(0.04), base, metallic);
    metal::float3 diffuse_albedo = base * (1.0 - metallic);
    WeftSurface _e35 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_5 = _e35.v;
    metal::float3 n_geo = _e35.n;
    metal::float3x3 _e39 = weft_tangent_frame(n_geo, in_1.world_tangent);
    metal::float4 _e43 = material.aniso_normal_map_st;
    metal::float2 _e44 = weft_transform_uv(in_1.uv0_, _e43);
    metal::float4 _e47 = aniso_normal_map.sample(material_sampler, _e44);
    metal::float3 texel_1 = _e47.xyz;
    float _e51 = material.aniso_normal_strength;
    metal::float3 _e52 = weft_unpack_normal(texel_1, _e51);
    metal::float3 _e53 = weft_normal_from_tangent_space(_e39, _e52);
    fibre = _e39[0];
    metal::float3 _e56 = fibre;
    metal::float3x3 _e60 = weft_tangent_frame(_e53, metal::float4(_e56, in_1.world_tangent.w));
    uint _e63 = material.diffuse_uses_aniso_normal;
    metal::float3 n_diff = (_e63 != 0u) ? _e53 : n_geo;
    WeftLightGeometry _e67 = weft_main_light_geometry(_e53, v_5, weft_frame);
    metal::float3 _e68 = weft_aniso_to_frame(_e60, v_5);
    metal::float3 _e70 = weft_aniso_to_frame(_e60, _e67.l);
    metal::float3 _e72 = weft_aniso_to_frame(_e60, _e67.h);
    float k_1 = material.anisotropy;
    {
        {
            float _e79 = material.aniso_gloss;
            float _e80 = silk_hair_mx_seed(smoothness_1, _e79);
            float _e83 = material.aniso_mask;
            float mask = metal::saturate(_e83);
            float _e87 = material.aniso_spec;
            float spec_scale = metal::mix(metal::max(_e87, 0.0), 1.0, mask);
            metal::float2 a_hair = metal::float2(metal::max(_e80, SILK_MIN_ALPHA), 1.0);
            float _e96 = weft_clamp_roughness(roughness_7);
            float _e97 = weft_clamp_roughness(roughness_7);
            float a_iso = _e96 * _e97;
            lobe.alpha = metal::mix(a_hair, metal::float2(a_iso), mask);
            float _e103 = silk_ibl_roughness(a_hair);
            lobe.ibl_roughness = metal::mix(_e103, roughness_7, mask);
            {
                {
                    float _e107 = material.tangent_shift;
                    metal::float3x3 _e108 = silk_tilt_frame(_e60, _e107);
                    metal::float3 _e109 = weft_aniso_to_frame(_e108, v_5);
                    metal::float3 _e111 = weft_aniso_to_frame(_e108, _e67.l);
                    metal::float3 _e113 = weft_aniso_to_frame(_e108, _e67.h);
                    float _e119 = weft_d_ggx_aniso(_e113.x, _e113.y, _e113.z, a_hair.x, a_hair.y);
                    float _e122 = weft_v_smith_ggx_aniso_correlated(_e109, _e111, a_hair.x, a_hair.y);
                    float aniso = (_e119 * _e122) * metal::saturate(_e111.z);
                    float _e128 = weft_d_ggx_nh(_e53, _e67.h, roughness_7);
                    float _e131 = weft_v_smith_ggx_correlated(_e67.n_dot_v, _e67.n_dot_l, roughness_7);
                    float iso = (_e128 * _e131) * _e67.n_dot_l;
                    lobe.value = metal::mix(aniso, iso, mask) * spec_scale;
                }
            }
        }
    }
    metal::float3 _e138 = weft_main_light_radiance(weft_frame);
    float n_dot_l_diffuse = metal::saturate(metal::dot(n_diff, _e67.l));
    metal::float3 _e143 = weft_f_schlick(f0_2, _e67.v_dot_h);
    metal::float3 _e147 = weft_diffuse_lambert(diffuse_albedo);
    metal::float3 diffuse = ((metal::float3(1.0) - _e143) * _e147) * n_dot_l_diffuse;
    float _e151 = lobe.value;
    metal::float3 direct = (diffuse + (_e143 * _e151)) * _e138;
    reflect_n = _e53;
    {
        float _e160 = lobe.ibl_roughness;
        metal::float2 _e161 = weft_env_brdf_lut(_e67.n_dot_v, _e160, weft_brdf_lut, weft_lut_sampler);
        metal::float3 _e162 = weft_env_brdf_from_lut(f0_2, _e161);
        env_brdf = _e162;
        metal::float3 _e165 = env_brdf;
        ambient_kd = metal::max(metal::float3(1.0) - _e165, metal::float3(0.0));
        metal::float2 _e171 = lobe.alpha;
        float _e172 = silk_lobe_anisotropy(_e171);
        float _e174 = lobe.ibl_roughness;
        metal::float3 _e175 = weft_aniso_bent_normal(_e60, v_5, _e172, _e174);
        reflect_n = _e175;
    }
    metal::float3 _e177 = reflect_n;
    float _e180 = lobe.ibl_roughness;
    metal::float3 _e181 = weft_prefiltered_radiance(metal::reflect(-(v_5), _e177), _e180, weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 _e182 = env_brdf;
    metal::float3 _e184 = weft_sh_irradiance(n_diff, weft_frame);
    metal::float3 _e185 = ambient_kd;
    metal::float3 indirect = (_e181 * _e182) + ((_e184 * _e185) * diffuse_albedo);
    metal::float3 radiance = metal::clamp(direct + indirect, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha_out) };
}
