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

float weft_clamp_roughness(
    float roughness
) {
    return metal::clamp(roughness, WEFT_MIN_ROUGHNESS, 1.0);
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
    float s_1 = (n_1.z >= 0.0) ? 1.0 : -1.0;
    float a_1 = -1.0 / (s_1 + n_1.z);
    float b = (n_1.x * n_1.y) * a_1;
    return metal::float3(1.0 + (((s_1 * n_1.x) * n_1.x) * a_1), s_1 * b, -(s_1) * n_1.x);
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
    metal::float3 v_2,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_2, n_3);
    float _e6 = weft_clamp_cos(metal::dot(n_3, v_2));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_3, _e2)), metal::saturate(metal::dot(n_3, _e4)), metal::saturate(metal::dot(v_2, _e4))};
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
    float a_2 = _e2 * _e2;
    float k_1 = metal::clamp(anisotropy, -1.0, 1.0);
    return metal::max(metal::float2(a_2 * (1.0 + k_1), a_2 * (1.0 - k_1)), metal::float2(0.001));
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
    float d = 1.0 / ((((WEFT_PI * at_1) * ab_1) * _e9) * _e9);
    return (n_dot_h_1 > 0.0) ? d : 0.0;
}

float weft_v_smith_ggx_aniso_correlated(
    metal::float3 v_3,
    metal::float3 l,
    float alpha_t_2,
    float alpha_b_2
) {
    float _e5 = weft_clamp_cos(v_3.z);
    float _e7 = weft_clamp_cos(l.z);
    float lv = _e7 * metal::length(metal::float3(alpha_t_2 * v_3.x, alpha_b_2 * v_3.y, _e5));
    float ll = _e5 * metal::length(metal::float3(alpha_t_2 * l.x, alpha_b_2 * l.y, _e7));
    return 0.5 / (lv + ll);
}

float weft_spec_ggx_aniso(
    metal::float3 v_4,
    metal::float3 l_1,
    float alpha_t_3,
    float alpha_b_3
) {
    metal::float3 _e9 = weft_safe_normalize(v_4 + l_1, metal::float3(0.0, 0.0, 1.0));
    float _e13 = weft_d_ggx_aniso(_e9.x, _e9.y, _e9.z, alpha_t_3, alpha_b_3);
    float _e14 = weft_v_smith_ggx_aniso_correlated(v_4, l_1, alpha_t_3, alpha_b_3);
    return (_e13 * _e14) * metal::saturate(l_1.z);
}

metal::float3 weft_aniso_bent_normal(
    metal::float3x3 frame_1,
    metal::float3 v_5,
    float anisotropy_1,
    float roughness_5
) {
    float k_2 = metal::clamp(anisotropy_1, -1.0, 1.0);
    metal::float3 n_5 = frame_1[2];
    metal::float3 dir_1 = (k_2 >= 0.0) ? frame_1[1] : frame_1[0];
    metal::float3 aniso_t = metal::cross(dir_1, v_5);
    metal::float3 aniso_n = metal::cross(aniso_t, dir_1);
    float bend = metal::abs(k_2) * metal::saturate(5.0 * metal::saturate(roughness_5));
    metal::float3 _e22 = weft_safe_normalize(metal::mix(n_5, aniso_n, bend), n_5);
    return _e22;
}

float satin_lobe_reference(
    metal::float3 vf,
    metal::float3 lf,
    metal::float2 a
) {
    float s = {};
    float _e5 = weft_spec_ggx_aniso(vf, lf, a.x, a.y);
    s = _e5;
    float _e7 = s;
    return _e7;
}

metal::float3 satin_env(
    metal::float3x3 frame_2,
    metal::float3 v_6,
    float k,
    float roughness_6,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    metal::float3 bent_1 = {};
    metal::float3 c_1 = {};
    metal::float3 _e4 = weft_aniso_bent_normal(frame_2, v_6, k, roughness_6);
    bent_1 = _e4;
    metal::float3 _e7 = bent_1;
    metal::float3 _e9 = weft_prefiltered_radiance(metal::reflect(-(v_6), _e7), roughness_6, weft_frame, weft_environment, weft_environment_sampler);
    c_1 = _e9;
    metal::float3 _e11 = c_1;
    return _e11;
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
    float roughness_7 = metal::saturate(_e23 * rmo.x);
    float _e29 = material.metallic;
    float metallic = metal::saturate(_e29 * rmo.y);
    float _e36 = material.occlusion_strength;
    float ao = metal::saturate(metal::mix(1.0, rmo.z, _e36));
    float _e42 = material.anisotropy;
    float anisotropy_2 = metal::clamp(_e42, -1.0, 1.0);
    float _e48 = material.second_layer_width;
    float width = metal::clamp(_e48, 1.0, 4.0);
    float roughness2_ = metal::min(roughness_7 * width, 1.0);
    metal::float4 _e58 = material.noise_map_st;
    metal::float2 _e59 = weft_transform_uv(in_1.uv0_, _e58);
    metal::float4 _e62 = noise_map.sample(material_sampler, _e59);
    float noise = 0.5 + (0.5 * metal::saturate(_e62.x));
    WeftSurface _e71 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_7 = _e71.v;
    n = _e71.n;
    metal::float3 _e75 = n;
    metal::float3x3 _e77 = weft_tangent_frame(_e75, in_1.world_tangent);
    metal::float3 _e78 = n;
    WeftLightGeometry _e79 = weft_main_light_geometry(_e78, v_7, weft_frame);
    metal::float3 _e80 = weft_main_light_radiance(weft_frame);
    metal::float2 _e83 = weft_aniso_alpha_kulla(roughness_7, anisotropy_2);
    layers.narrow = _e83;
    metal::float2 _e85 = weft_aniso_alpha_kulla(roughness2_, anisotropy_2);
    layers.wide = _e85;
    metal::float3 f0_2 = metal::mix(metal::float3(0.04), base, metallic);
    metal::float3 diffuse_albedo = base * (1.0 - metallic);
    metal::float4 _e94 = material.specular_color;
    metal::float3 c1_ = metal::saturate(_e94.xyz);
    metal::float4 _e99 = material.second_specular_color;
    metal::float3 c2_ = metal::saturate(_e99.xyz);
    metal::float3 _e103 = weft_f_schlick(f0_2, _e79.v_dot_h);
    {
        float _e108 = weft_max3_(c1_);
        metal::float3 t1_ = metal::mix(c1_, metal::float3(_e108), 0.5);
        float _e112 = weft_max3_(c2_);
        metal::float3 t2_ = metal::mix(c2_, metal::float3(_e112), 0.5);
        float _e117 = weft_max3_(t1_ + t2_);
        float norm = 1.0 / metal::max(1.0, _e117);
        metal::float3 w1_ = t1_ * norm;
        metal::float3 w2_ = t2_ * norm;
        metal::float3 _e124 = weft_aniso_to_frame(_e77, v_7);
        metal::float3 _e126 = weft_aniso_to_frame(_e77, _e79.l);
        metal::float2 _e128 = layers.narrow;
        float _e129 = satin_lobe_reference(_e124, _e126, _e128);
        metal::float2 _e131 = layers.wide;
        float _e132 = satin_lobe_reference(_e124, _e126, _e131);
        specular = ((((w1_ * _e129) + (w2_ * _e132)) * _e103) * noise) * _e80;
        metal::float3 _e143 = weft_f_schlick(f0_2, _e79.n_dot_v);
        diffuse_kd = metal::max(metal::float3(1.0) - ((w1_ + w2_) * _e143), metal::float3(0.0));
        metal::float2 _e150 = weft_env_brdf_lut(_e79.n_dot_v, roughness_7, weft_brdf_lut, weft_lut_sampler);
        metal::float3 _e151 = weft_env_brdf_from_lut(f0_2, _e150);
        metal::float3 e1_ = _e151 * w1_;
        metal::float2 _e154 = weft_env_brdf_lut(_e79.n_dot_v, roughness2_, weft_brdf_lut, weft_lut_sampler);
        metal::float3 _e155 = weft_env_brdf_from_lut(f0_2, _e154);
        metal::float3 e2_ = _e155 * w2_;
        {
            metal::float3 _e157 = satin_env(_e77, v_7, anisotropy_2, roughness_7, weft_frame, weft_environment, weft_environment_sampler);
            metal::float3 _e159 = satin_env(_e77, v_7, anisotropy_2, roughness2_, weft_frame, weft_environment, weft_environment_sampler);
            indirect_specular = ((_e157 * e1_) + (_e159 * e2_)) * noise;
        }
        ambient_kd = metal::max((metal::float3(1.0) - e1_) - e2_, metal::float3(0.0));
    }
    metal::float3 _e170 = diffuse_kd;
    metal::float3 _e171 = weft_diffuse_lambert(diffuse_albedo);
    metal::float3 _e176 = specular;
    metal::float3 direct = (((_e170 * _e171) * _e80) * _e79.n_dot_l) + _e176;
    metal::float3 _e178 = indirect_specular;
    metal::float3 _e180 = n;
    metal::float3 _e181 = weft_sh_irradiance(_e180, weft_frame);
    metal::float3 _e183 = ambient_kd;
    metal::float3 indirect = (_e178 * ao) + (((_e181 * ao) * _e183) * diffuse_albedo);
    metal::float3 radiance = metal::clamp(direct + indirect, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
