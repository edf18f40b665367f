// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

typedef float weft_half;
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
    metal::float4 c_1 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_1.xyz, metal::float3(0.0));
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
    metal::float3 n_3,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_3 * metal::dot(n_3, t_in));
    float len2_1 = metal::dot(t_proj, t_proj);
    bool ok = len2_1 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_3);
    metal::float3 t = ok ? (t_proj * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : _e13;
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_3, t) * s_1;
    return metal::float3x3(t, b_1, n_3);
}

metal::float3 weft_unpack_normal(
    metal::float3 texel,
    float strength
) {
    metal::float3 v_5 = (texel * 2.0) - metal::float3(1.0);
    return metal::float3(v_5.xy * strength, metal::max(v_5.z, 0.001));
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
    metal::float3 x
) {
    return metal::float3(metal::dot(frame_1[0], x), metal::dot(frame_1[1], x), metal::dot(frame_1[2], x));
}

metal::float2 weft_aniso_alpha_burley(
    float roughness_4,
    float anisotropy
) {
    float _e2 = weft_clamp_roughness(roughness_4);
    float a_1 = _e2 * _e2;
    float k = metal::clamp(anisotropy, -1.0, 1.0);
    float aspect = metal::sqrt(1.0 - (0.9 * metal::abs(k)));
    float wide = a_1 / aspect;
    float narrow = a_1 * aspect;
    metal::float2 ab = (k >= 0.0) ? metal::float2(wide, narrow) : metal::float2(narrow, wide);
    return metal::max(ab, metal::float2(0.001));
}

metal::float3 weft_aniso_bent_normal(
    metal::float3x3 frame_2,
    metal::float3 v_2,
    float anisotropy_1,
    float roughness_5
) {
    float k_1 = metal::clamp(anisotropy_1, -1.0, 1.0);
    metal::float3 n_4 = frame_2[2];
    metal::float3 dir_1 = (k_1 >= 0.0) ? frame_2[1] : frame_2[0];
    metal::float3 aniso_t = metal::cross(dir_1, v_2);
    metal::float3 aniso_n = metal::cross(aniso_t, dir_1);
    float bend = metal::abs(k_1) * metal::saturate(5.0 * metal::saturate(roughness_5));
    metal::float3 _e22 = weft_safe_normalize(metal::mix(n_4, aniso_n, bend), n_4);
    return _e22;
}

float silk_lobe_anisotropy(
    metal::float2 alpha
) {
    float at = metal::max(alpha.x, SILK_MIN_ALPHA);
    float ab_1 = metal::max(alpha.y, SILK_MIN_ALPHA);
    return (at - ab_1) / (at + ab_1);
}

weft_half weft_half_min_max(
    weft_half x_1
) {
    return metal::min(x_1, 65504.0);
}

weft_half weft_half_pow5_(
    weft_half x_2
) {
    weft_half x2_ = x_2 * x_2;
    return (x2_ * x2_) * x_2;
}

metal::float3 weft_half_f_schlick(
    metal::float3 f0_,
    weft_half v_dot_h
) {
    weft_half _e7 = weft_half_pow5_(1.0 - v_dot_h);
    return f0_ + ((metal::float3(1.0) - f0_) * _e7);
}

weft_half weft_half_spec_ggx_aniso(
    metal::float3 v_3,
    metal::float3 l,
    metal::float3 h,
    metal::float2 alpha_1
) {
    metal::float2 a_2 = metal::max(alpha_1, metal::float2(0.007921));
    metal::float2 inv_a = static_cast<metal::float2>(metal::float2(1.0) / a_2);
    metal::float2 ah = static_cast<metal::float2>(a_2);
    float x_3 = h.x * inv_a.x;
    float y = h.y * inv_a.y;
    float q = metal::max(((x_3 * x_3) + (y * y)) + (h.z * h.z), 0.01);
    float d = (((inv_a.x * inv_a.y) / q) / q) * 0.31830987;
    float nv = metal::max(v_3.z, 0.001);
    float nl = metal::saturate(l.z);
    float lv = nl * metal::length(metal::float3(ah.x * v_3.x, ah.y * v_3.y, nv));
    float ll = nv * metal::length(metal::float3(ah.x * l.x, ah.y * l.y, nl));
    float v_n_dot_l = (0.5 * nl) / metal::max(lv + ll, 0.0001);
    weft_half _e65 = weft_half_min_max(d * v_n_dot_l);
    return (h.z > 0.0) ? _e65 : 0.0;
}

metal::float3 silk_low(
    metal::float3x3 frame_3,
    metal::float3 n_spec,
    metal::float3 n_diff,
    metal::float3 v_4,
    float n_dot_v_1,
    float v_dot_h_1,
    float n_dot_l_diffuse,
    metal::float3 f0_in,
    metal::float3 diffuse_albedo,
    SilkLobe lobe_1,
    metal::float3 light,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float3 f0_1 = static_cast<metal::float3>(f0_in);
    metal::float3 _e13 = weft_half_f_schlick(f0_1, static_cast<float>(v_dot_h_1));
    metal::float3 kd = (metal::float3(1.0) - _e13) * (static_cast<float>(n_dot_l_diffuse) * 0.31830987);
    metal::float3 direct = ((diffuse_albedo * static_cast<metal::float3>(kd)) + (static_cast<metal::float3>(_e13) * lobe_1.value)) * light;
    metal::float2 _e29 = weft_env_brdf_lut(n_dot_v_1, lobe_1.ibl_roughness, weft_brdf_lut, weft_lut_sampler);
    metal::float2 lut = metal::saturate(_e29);
    metal::float3 env_brdf_1 = (f0_1 * static_cast<float>(lut.x)) + metal::float3(static_cast<float>(lut.y));
    metal::float3 ambient_kd_1 = metal::max(metal::float3(1.0) - env_brdf_1, metal::float3(0.0));
    float _e45 = silk_lobe_anisotropy(lobe_1.alpha);
    metal::float3 _e47 = weft_aniso_bent_normal(frame_3, v_4, _e45, lobe_1.ibl_roughness);
    metal::float3 _e51 = weft_prefiltered_radiance(metal::reflect(-(v_4), _e47), lobe_1.ibl_roughness, weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 _e54 = weft_sh_irradiance(n_diff, weft_frame);
    metal::float3 indirect = (_e51 * static_cast<metal::float3>(env_brdf_1)) + ((_e54 * static_cast<metal::float3>(ambient_kd_1)) * diffuse_albedo);
    return metal::clamp(direct + indirect, metal::float3(0.0), metal::float3(65504.0));
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
, metal::texture2d<float, metal::access::sample> flow_map [[texture(4)]]
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
    float smoothness = metal::saturate(_e19);
    float roughness_6 = 1.0 - smoothness;
    float _e25 = material.metallic;
    float metallic = metal::saturate(_e25);
    metal::float3 f0_2 = metal::mix(metal::float3(0.04), base, metallic);
    metal::float3 diffuse_albedo_1 = base * (1.0 - metallic);
    WeftSurface _e35 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_6 = _e35.v;
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
    {
        metal::float4 _e58 = flow_map.sample(material_sampler, _e5);
        metal::float2 flow = (_e58.xy * 2.0) - metal::float2(1.0);
        metal::float3 dir_2 = (_e39[0] * flow.x) + (_e39[1] * flow.y);
        float _e75 = material.flow_strength;
        metal::float3 _e79 = weft_safe_normalize(metal::mix(_e39[0], dir_2, metal::saturate(_e75)), _e39[0]);
        fibre = _e79;
    }
    metal::float3 _e80 = fibre;
    metal::float3x3 _e84 = weft_tangent_frame(_e53, metal::float4(_e80, in_1.world_tangent.w));
    uint _e87 = material.diffuse_uses_aniso_normal;
    metal::float3 n_diff_1 = (_e87 != 0u) ? _e53 : n_geo;
    WeftLightGeometry _e91 = weft_main_light_geometry(_e53, v_6, weft_frame);
    metal::float3 _e92 = weft_aniso_to_frame(_e84, v_6);
    metal::float3 _e94 = weft_aniso_to_frame(_e84, _e91.l);
    metal::float3 _e96 = weft_aniso_to_frame(_e84, _e91.h);
    float k_2 = material.anisotropy;
    {
        {
            metal::float2 _e101 = weft_aniso_alpha_burley(roughness_6, k_2);
            lobe.alpha = _e101;
            lobe.ibl_roughness = roughness_6;
            {
                metal::float2 _e106 = weft_aniso_alpha_burley(metal::max(roughness_6, WEFT_MIN_ROUGHNESS_HALF), k_2);
                weft_half _e111 = weft_half_spec_ggx_aniso(static_cast<metal::float3>(_e92), static_cast<metal::float3>(_e94), static_cast<metal::float3>(_e96), _e106);
                lobe.value = static_cast<float>(_e111);
            }
        }
    }
    metal::float3 _e113 = weft_main_light_radiance(weft_frame);
    float n_dot_l_diffuse_1 = metal::saturate(metal::dot(n_diff_1, _e91.l));
    {
        SilkLobe _e119 = lobe;
        metal::float3 _e120 = silk_low(_e84, _e53, n_diff_1, v_6, _e91.n_dot_v, _e91.v_dot_h, n_dot_l_diffuse_1, f0_2, diffuse_albedo_1, _e119, _e113, weft_frame, weft_environment, weft_environment_sampler, weft_brdf_lut, weft_lut_sampler);
        return fs_mainOutput { metal::float4(_e120, alpha_out) };
    }
}
