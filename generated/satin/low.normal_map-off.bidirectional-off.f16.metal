// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

typedef half weft_half;
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
    float roughness;
    float metallic;
    float occlusion_strength;
    char _pad4[4];
    metal::float4 base_map_st;
    float normal_strength;
    char _pad6[12];
    metal::float4 noise_map_st;
    float specular_intensity;
    char _pad8[12];
    metal::float4 specular_color;
    metal::float4 second_specular_color;
    float second_layer_width;
    float anisotropy;
    char _pad12[8];
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
    metal::float3 n_1
) {
    float s_1 = (n_1.z >= 0.0) ? 1.0 : -1.0;
    float a = -1.0 / (s_1 + n_1.z);
    float b = (n_1.x * n_1.y) * a;
    return metal::float3(1.0 + (((s_1 * n_1.x) * n_1.x) * a), s_1 * b, -(s_1) * n_1.x);
}

metal::float3 weft_f_schlick(
    metal::float3 f0_,
    float v_dot_h
) {
    float _e5 = weft_pow5_(1.0 - metal::saturate(v_dot_h));
    return f0_ + ((metal::float3(1.0) - f0_) * _e5);
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
    float roughness_1,
    constant WeftFrame& weft_frame
) {
    float r = metal::saturate(roughness_1);
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return (r * (1.7 - (0.7 * r))) * max_mip;
}

metal::float3 weft_prefiltered_radiance(
    metal::float3 dir,
    float roughness_2,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip(roughness_2, weft_frame);
    metal::float4 c_2 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_2.xyz, metal::float3(0.0));
}

metal::float2 weft_env_brdf_lut(
    float n_dot_v,
    float roughness_3,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv_1 = metal::float2(metal::saturate(n_dot_v), metal::saturate(roughness_3));
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
    float s_2 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_4, t) * s_2;
    return metal::float3x3(t, b_1, n_4);
}

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

metal::float3 weft_aniso_to_frame(
    metal::float3x3 frame,
    metal::float3 x_1
) {
    return metal::float3(metal::dot(frame[0], x_1), metal::dot(frame[1], x_1), metal::dot(frame[2], x_1));
}

metal::float2 weft_aniso_alpha_kulla(
    float roughness_4,
    float anisotropy
) {
    float _e2 = weft_clamp_roughness(roughness_4);
    float a_1 = _e2 * _e2;
    float k_1 = metal::clamp(anisotropy, -1.0, 1.0);
    return metal::max(metal::float2(a_1 * (1.0 + k_1), a_1 * (1.0 - k_1)), metal::float2(0.001));
}

metal::float3 weft_aniso_bent_normal(
    metal::float3x3 frame_1,
    metal::float3 v_2,
    float anisotropy_1,
    float roughness_5
) {
    float k_2 = metal::clamp(anisotropy_1, -1.0, 1.0);
    metal::float3 n_6 = frame_1[2];
    metal::float3 dir_1 = (k_2 >= 0.0) ? frame_1[1] : frame_1[0];
    metal::float3 aniso_t = metal::cross(dir_1, v_2);
    metal::float3 aniso_n = metal::cross(aniso_t, dir_1);
    float bend = metal::abs(k_2) * metal::saturate(5.0 * metal::saturate(roughness_5));
    metal::float3 _e22 = weft_safe_normalize(metal::mix(n_6, aniso_n, bend), n_6);
    return _e22;
}

weft_half weft_half_pow5_(
    weft_half x_2
) {
    weft_half x2_1 = x_2 * x_2;
    return (x2_1 * x2_1) * x_2;
}

metal::half3 weft_half_f_schlick(
    metal::half3 f0_2,
    weft_half v_dot_h_1
) {
    weft_half _e7 = weft_half_pow5_(1.0h - v_dot_h_1);
    return f0_2 + ((metal::half3(1.0h) - f0_2) * _e7);
}

metal::half2 weft_half_spec_ggx_aniso2_(
    metal::half3 v_3,
    metal::half3 l,
    metal::half3 h,
    metal::float2 alpha_t,
    metal::float2 alpha_b
) {
    metal::float2 at = metal::max(alpha_t, metal::float2(0.007921));
    metal::float2 ab = metal::max(alpha_b, metal::float2(0.007921));
    metal::half2 inv_at = static_cast<metal::half2>(metal::float2(1.0) / at);
    metal::half2 inv_ab = static_cast<metal::half2>(metal::float2(1.0) / ab);
    metal::half2 at_h = static_cast<metal::half2>(at);
    metal::half2 ab_h = static_cast<metal::half2>(ab);
    metal::half2 x_3 = h.x * inv_at;
    metal::half2 y = h.y * inv_ab;
    metal::half2 q = metal::max(((x_3 * x_3) + (y * y)) + metal::half2(h.z * h.z), metal::half2(0.010002136h));
    metal::half2 d = (((inv_at * inv_ab) / q) / q) * 0.31835938h;
    half nv = metal::max(v_3.z, 0.0010004044h);
    half nl = metal::saturate(l.z);
    metal::half2 vt = at_h * v_3.x;
    metal::half2 vb = ab_h * v_3.y;
    metal::half2 lt = at_h * l.x;
    metal::half2 lb = ab_h * l.y;
    metal::half2 lv = nl * metal::sqrt(((vt * vt) + (vb * vb)) + metal::half2(nv * nv));
    metal::half2 ll = nv * metal::sqrt(((lt * lt) + (lb * lb)) + metal::half2(nl * nl));
    metal::half2 v_n_dot_l = metal::half2(0.5h * nl) / metal::max(lv + ll, metal::half2(0.000100016594h));
    return (h.z > 0.0h) ? metal::min(d * v_n_dot_l, metal::half2(65504.0h)) : metal::half2(0.0h);
}

metal::float3 satin_env(
    metal::float3x3 frame_2,
    metal::float3 v_4,
    float k,
    float roughness_6,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    metal::float3 bent_1 = {};
    metal::float3 c_1 = {};
    metal::float3 _e4 = weft_aniso_bent_normal(frame_2, v_4, k, roughness_6);
    bent_1 = _e4;
    metal::float3 _e7 = bent_1;
    metal::float3 _e9 = weft_prefiltered_radiance(metal::reflect(-(v_4), _e7), roughness_6, weft_frame, weft_environment, weft_environment_sampler);
    c_1 = _e9;
    metal::float3 _e11 = c_1;
    return _e11;
}

metal::half2 satin_lobes_low(
    metal::half3 vf,
    metal::half3 lf,
    metal::half3 hf,
    metal::float2 a1_,
    metal::float2 a2_
) {
    metal::half2 s = {};
    metal::float2 at_1 = metal::float2(a1_.x, a2_.x);
    metal::float2 ab_1 = metal::float2(a1_.y, a2_.y);
    metal::half2 _e11 = weft_half_spec_ggx_aniso2_(vf, lf, hf, at_1, ab_1);
    s = _e11;
    metal::half2 _e13 = s;
    return _e13;
}

metal::float3 satin_low(
    metal::float3x3 frame_3,
    metal::float3 n_5,
    metal::float3 v_5,
    WeftLightGeometry lit,
    metal::float3 f0_in,
    metal::float3 diffuse_albedo,
    float roughness_7,
    float roughness2_,
    float anisotropy_2,
    metal::float3 c1_in,
    metal::float3 c2_in,
    float noise,
    float ao,
    metal::float3 light,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    float n_dot_v_1 = lit.n_dot_v;
    half n_dot_l = static_cast<half>(lit.n_dot_l);
    half v_dot_h_2 = static_cast<half>(lit.v_dot_h);
    metal::half3 f0_3 = static_cast<metal::half3>(f0_in);
    metal::half3 c1_ = static_cast<metal::half3>(c1_in);
    metal::half3 c2_ = static_cast<metal::half3>(c2_in);
    metal::half3 t1_ = metal::mix(c1_, metal::half3(metal::max(c1_.x, metal::max(c1_.y, c1_.z))), 0.5h);
    metal::half3 t2_ = metal::mix(c2_, metal::half3(metal::max(c2_.x, metal::max(c2_.y, c2_.z))), 0.5h);
    metal::half3 t_1 = t1_ + t2_;
    half norm = 1.0h / metal::max(1.0h, metal::max(t_1.x, metal::max(t_1.y, t_1.z)));
    metal::half3 w1_ = t1_ * norm;
    metal::half3 w2_ = t2_ * norm;
    float r_low = metal::max(roughness_7, WEFT_MIN_ROUGHNESS_HALF);
    float r2_low = metal::max(roughness2_, WEFT_MIN_ROUGHNESS_HALF);
    metal::float3 _e54 = weft_aniso_to_frame(frame_3, v_5);
    metal::half3 vf_1 = static_cast<metal::half3>(_e54);
    metal::float3 _e57 = weft_aniso_to_frame(frame_3, lit.l);
    metal::half3 lf_1 = static_cast<metal::half3>(_e57);
    metal::float3 _e60 = weft_aniso_to_frame(frame_3, lit.h);
    metal::half3 hf_1 = static_cast<metal::half3>(_e60);
    metal::float2 _e62 = weft_aniso_alpha_kulla(r_low, anisotropy_2);
    metal::float2 _e63 = weft_aniso_alpha_kulla(r2_low, anisotropy_2);
    metal::half2 _e64 = satin_lobes_low(vf_1, lf_1, hf_1, _e62, _e63);
    half lobe1_ = _e64.x;
    half lobe2_ = _e64.y;
    metal::half3 _e67 = weft_half_f_schlick(f0_3, v_dot_h_2);
    metal::float3 specular_1 = ((static_cast<metal::float3>(w1_ * _e67) * static_cast<float>(lobe1_)) + (static_cast<metal::float3>(w2_ * _e67) * static_cast<float>(lobe2_))) * (noise * light);
    metal::half3 _e83 = weft_half_f_schlick(f0_3, static_cast<half>(n_dot_v_1));
    metal::half3 diffuse_kd_1 = metal::max(metal::half3(1.0h) - ((w1_ + w2_) * _e83), metal::half3(0.0h));
    metal::float2 _e89 = weft_env_brdf_lut(n_dot_v_1, roughness_7, weft_brdf_lut, weft_lut_sampler);
    metal::float3 _e90 = weft_env_brdf_from_lut(f0_in, _e89);
    metal::half3 e1_ = static_cast<metal::half3>(_e90) * w1_;
    metal::float2 _e93 = weft_env_brdf_lut(n_dot_v_1, roughness2_, weft_brdf_lut, weft_lut_sampler);
    metal::float3 _e94 = weft_env_brdf_from_lut(f0_in, _e93);
    metal::half3 e2_ = static_cast<metal::half3>(_e94) * w2_;
    float r_env = (metal::max(e1_.x, metal::max(e1_.y, e1_.z)) >= metal::max(e2_.x, metal::max(e2_.y, e2_.z))) ? roughness_7 : roughness2_;
    metal::float3 _e109 = satin_env(frame_3, v_5, anisotropy_2, r_env, weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 indirect_specular_1 = (_e109 * static_cast<metal::float3>(e1_ + e2_)) * noise;
    metal::half3 ambient_kd_1 = metal::max((metal::half3(1.0h) - e1_) - e2_, metal::half3(0.0h));
    metal::float3 direct = ((diffuse_albedo * static_cast<metal::float3>(diffuse_kd_1 * (n_dot_l * 0.31835938h))) * light) + specular_1;
    metal::float3 _e129 = weft_sh_irradiance(n_5, weft_frame);
    metal::float3 indirect = (indirect_specular_1 * ao) + (((_e129 * ao) * static_cast<metal::float3>(ambient_kd_1)) * diffuse_albedo);
    return direct + indirect;
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
, metal::texture2d<float, metal::access::sample> rmo_map [[texture(3)]]
, metal::texture2d<float, metal::access::sample> noise_map [[texture(4)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    SatinLayers layers = {};
    metal::float3 specular = {};
    metal::float3 diffuse_kd = {};
    metal::float3 indirect_specular = {};
    metal::float3 ambient_kd = {};
    metal::float3 bent = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    metal::float4 _e8 = material.base_color;
    metal::float4 _e11 = base_map.sample(material_sampler, _e5);
    metal::float4 base_rgba = _e8 * _e11;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float alpha = metal::saturate(base_rgba.w);
    metal::float4 _e19 = rmo_map.sample(material_sampler, _e5);
    metal::float3 rmo = _e19.xyz;
    float _e23 = material.roughness;
    float roughness_8 = metal::saturate(_e23 * rmo.x);
    float _e29 = material.metallic;
    float metallic = metal::saturate(_e29 * rmo.y);
    float _e36 = material.occlusion_strength;
    float ao_1 = metal::saturate(metal::mix(1.0, rmo.z, _e36));
    float _e42 = material.anisotropy;
    float anisotropy_3 = metal::clamp(_e42, -1.0, 1.0);
    float _e48 = material.second_layer_width;
    float width = metal::clamp(_e48, 1.0, 4.0);
    float roughness2_1 = metal::min(roughness_8 * width, 1.0);
    metal::float4 _e58 = material.noise_map_st;
    metal::float2 _e59 = weft_transform_uv(in_1.uv0_, _e58);
    metal::float4 _e62 = noise_map.sample(material_sampler, _e59);
    float noise_1 = 0.5 + (0.5 * metal::saturate(_e62.x));
    WeftSurface _e71 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_6 = _e71.v;
    n = _e71.n;
    metal::float3 _e75 = n;
    metal::float3x3 _e77 = weft_tangent_frame(_e75, in_1.world_tangent);
    metal::float3 _e78 = n;
    WeftLightGeometry _e79 = weft_main_light_geometry(_e78, v_6, weft_frame);
    metal::float3 _e80 = weft_main_light_radiance(weft_frame);
    metal::float2 _e83 = weft_aniso_alpha_kulla(roughness_8, anisotropy_3);
    layers.narrow = _e83;
    metal::float2 _e85 = weft_aniso_alpha_kulla(roughness2_1, anisotropy_3);
    layers.wide = _e85;
    metal::float3 f0_4 = metal::mix(metal::float3(0.04), base, metallic);
    metal::float3 diffuse_albedo_1 = base * (1.0 - metallic);
    metal::float4 _e94 = material.specular_color;
    metal::float3 c1_1 = metal::saturate(_e94.xyz);
    metal::float4 _e99 = material.second_specular_color;
    metal::float3 c2_1 = metal::saturate(_e99.xyz);
    metal::float3 _e103 = weft_f_schlick(f0_4, _e79.v_dot_h);
    {
        metal::float3 _e104 = n;
        metal::float3 _e105 = satin_low(_e77, _e104, v_6, _e79, f0_4, diffuse_albedo_1, roughness_8, roughness2_1, anisotropy_3, c1_1, c2_1, noise_1, ao_1, _e80, weft_frame, weft_environment, weft_environment_sampler, weft_brdf_lut, weft_lut_sampler);
        return fs_mainOutput { metal::float4(metal::clamp(_e105, metal::float3(0.0), metal::float3(65504.0)), alpha) };
    }
}
