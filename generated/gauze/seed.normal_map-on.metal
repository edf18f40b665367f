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
    float roughness;
    char _pad2[12];
    metal::float4 base_map_st;
    metal::float4 normal_map_st;
    float normal_strength;
    float thread_density;
    float thread_transmittance;
    float mesh_gap;
    float anisotropy;
    float anisotropic_intensity;
    char _pad10[8];
    metal::float4 scatter_color;
    float scatter_intensity;
    float pattern_threshold;
    float pattern_rotation;
    float sampling_density;
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
constant float WEFT_MIN_ANISO_ALPHA = 0.001;
constant float GAUZE_LN_MAX_TRANSMITTANCE = 6.9077554;

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
    float a = -1.0 / (s_1 + n_1.z);
    float b = (n_1.x * n_1.y) * a;
    return metal::float3(1.0 + (((s_1 * n_1.x) * n_1.x) * a), s_1 * b, -(s_1) * n_1.x);
}

metal::float3 weft_f_schlick_roughness(
    metal::float3 f0_,
    float n_dot_v,
    float roughness_1
) {
    float _e6 = weft_pow5_(1.0 - metal::saturate(n_dot_v));
    metal::float3 f90_ = metal::max(metal::float3(1.0 - metal::saturate(roughness_1)), f0_);
    return f0_ + ((f90_ - f0_) * _e6);
}

float weft_v_schlick_ggx(
    float n_dot_v_1,
    float n_dot_l,
    float roughness_2
) {
    float _e3 = weft_clamp_roughness(roughness_2);
    float a_1 = _e3 * _e3;
    float k = ((a_1 + 1.0) * (a_1 + 1.0)) * 0.125;
    float gv = (metal::saturate(n_dot_v_1) * (1.0 - k)) + k;
    float gl = (metal::saturate(n_dot_l) * (1.0 - k)) + k;
    return 0.25 / (gv * gl);
}

metal::float3 weft_diffuse_lambert(
    metal::float3 albedo
) {
    return albedo * WEFT_INV_PI;
}

metal::float3 weft_env_brdf_approx(
    metal::float3 f0_1,
    float n_dot_v_2,
    float roughness_3
) {
    float r = metal::saturate(roughness_3);
    float surface_reduction = 1.0 / ((r * r) + 1.0);
    float _e9 = weft_max3_(f0_1);
    float grazing = metal::saturate(_e9 + (1.0 - r));
    float _e17 = weft_pow4_(1.0 - metal::saturate(n_dot_v_2));
    return metal::mix(f0_1, metal::float3(grazing), _e17) * surface_reduction;
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
    float roughness_4,
    constant WeftFrame& weft_frame
) {
    float r_1 = metal::saturate(roughness_4);
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return (r_1 * (1.7 - (0.7 * r_1))) * max_mip;
}

metal::float3 weft_prefiltered_radiance(
    metal::float3 dir,
    float roughness_5,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip(roughness_5, weft_frame);
    metal::float4 c_2 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_2.xyz, metal::float3(0.0));
}

WeftSurface weft_surface_two_sided(
    metal::float3 world_position_1,
    metal::float3 world_normal,
    bool front_facing_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e7 = weft_view_direction(world_position_1, metal::float3(0.0, 0.0, 1.0), weft_frame);
    metal::float3 facing = front_facing_1 ? world_normal : -(world_normal);
    metal::float3 _e10 = weft_safe_normalize(facing, _e7);
    return WeftSurface {_e7, _e10};
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

metal::float3 weft_aniso_to_frame(
    metal::float3x3 frame_1,
    metal::float3 x_2
) {
    return metal::float3(metal::dot(frame_1[0], x_2), metal::dot(frame_1[1], x_2), metal::dot(frame_1[2], x_2));
}

metal::float3x3 weft_rotate_tangent_frame_cs(
    metal::float3x3 frame_2,
    float c_1,
    float s
) {
    float len2_2 = (c_1 * c_1) + (s * s);
    float inv = metal::rsqrt(metal::max(len2_2, 0.00000000000000000001));
    float cc = (len2_2 > 0.00000000000000000001) ? (c_1 * inv) : 1.0;
    float ss = (len2_2 > 0.00000000000000000001) ? (s * inv) : 0.0;
    metal::float3 t_1 = (frame_2[0] * cc) + (frame_2[1] * ss);
    metal::float3 b_2 = (frame_2[1] * cc) - (frame_2[0] * ss);
    return metal::float3x3(t_1, b_2, frame_2[2]);
}

metal::float3x3 weft_rotate_tangent_frame(
    metal::float3x3 frame_3,
    float angle
) {
    metal::float3x3 _e4 = weft_rotate_tangent_frame_cs(frame_3, metal::cos(angle), metal::sin(angle));
    return _e4;
}

metal::float2 weft_aniso_alpha_kulla(
    float roughness_6,
    float anisotropy
) {
    float _e2 = weft_clamp_roughness(roughness_6);
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
    float x_3 = t_dot_h / at;
    float y = b_dot_h / ab;
    return metal::max(((x_3 * x_3) + (y * y)) + (n_dot_h * n_dot_h), 0.000001);
}

float weft_d_ggx_aniso_unnormalized(
    float t_dot_h_1,
    float b_dot_h_1,
    float n_dot_h_1,
    float alpha_t_1,
    float alpha_b_1
) {
    float _e5 = weft_aniso_ggx_q(t_dot_h_1, b_dot_h_1, n_dot_h_1, alpha_t_1, alpha_b_1);
    float d = 1.0 / ((WEFT_PI * _e5) * _e5);
    return (n_dot_h_1 > 0.0) ? d : 0.0;
}

metal::float3 weft_aniso_bent_normal(
    metal::float3x3 frame_4,
    metal::float3 v_3,
    float anisotropy_1,
    float roughness_7
) {
    float k_2 = metal::clamp(anisotropy_1, -1.0, 1.0);
    metal::float3 n_6 = frame_4[2];
    metal::float3 dir_1 = (k_2 >= 0.0) ? frame_4[1] : frame_4[0];
    metal::float3 aniso_t = metal::cross(dir_1, v_3);
    metal::float3 aniso_n = metal::cross(aniso_t, dir_1);
    float bend = metal::abs(k_2) * metal::saturate(5.0 * metal::saturate(roughness_7));
    metal::float3 _e22 = weft_safe_normalize(metal::mix(n_6, aniso_n, bend), n_6);
    return _e22;
}

float gauze_grid_coverage(
    metal::float2 cell,
    metal::float2 w,
    float gap
) {
    float g = metal::clamp(gap, 0.0, 1.0);
    metal::float2 d_1 = metal::abs(metal::fract(cell) - metal::float2(0.5));
    metal::float2 ww = metal::max(w, metal::float2(0.0001));
    metal::float2 ramp = metal::saturate(((metal::float2(0.5 * g) - d_1) / ww) + metal::float2(0.5));
    metal::float2 open = metal::mix(ramp, metal::float2(g), metal::saturate((ww * 2.0) - metal::float2(1.0)));
    float open_xy = (g > 0.0) ? (open.x * open.y) : 0.0;
    return 1.0 - open_xy;
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
  vs_mainInput varyings [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
) {
    const WeftVertexInput in = { varyings.position, varyings.normal, varyings.tangent_2, varyings.uv0_ };
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
, bool front_facing [[front_facing]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, metal::texturecube<float, metal::access::sample> weft_environment [[texture(0)]]
, metal::sampler weft_environment_sampler [[sampler(0)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(1)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(1)]]
, metal::texture2d<float, metal::access::sample> normal_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> mesh_map [[texture(3)]]
, metal::texture2d<float, metal::access::sample> noise_map [[texture(4)]]
, metal::texture2d<float, metal::access::sample> pattern_map [[texture(5)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    metal::float3 spec_direct = {};
    metal::float3 env_brdf = {};
    metal::float3 diffuse_kd = {};
    metal::float3 ambient_kd = {};
    float lobe = {};
    metal::float4 _e5 = material.base_map_st;
    metal::float2 _e6 = weft_transform_uv(in_1.uv0_, _e5);
    metal::float4 _e9 = material.base_color;
    metal::float4 _e12 = base_map.sample(material_sampler, _e6);
    metal::float4 base_rgba = _e9 * _e12;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float base_alpha = metal::saturate(base_rgba.w);
    float _e20 = material.roughness;
    float roughness_8 = metal::saturate(_e20);
    float _e24 = material.anisotropy;
    float anisotropy_2 = metal::clamp(_e24, -1.0, 1.0);
    float _e31 = material.sampling_density;
    metal::float2 uv_s = in_1.uv0_ * _e31;
    metal::float4 _e35 = mesh_map.sample(material_sampler, uv_s);
    float mesh_tex = metal::saturate(_e35.x);
    metal::float4 _e40 = noise_map.sample(material_sampler, uv_s);
    float noise = metal::saturate(_e40.x);
    metal::float4 _e45 = pattern_map.sample(material_sampler, uv_s);
    float pattern = _e45.x;
    metal::float2 grid_w = metal::fwidth(uv_s);
    float pattern_w = metal::fwidth(pattern);
    float _e51 = material.mesh_gap;
    float _e52 = gauze_grid_coverage(uv_s, grid_w, _e51);
    float mesh = mesh_tex * _e52;
    WeftSurface _e56 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing, weft_frame);
    metal::float3 v_5 = _e56.v;
    metal::float3 n_geom = _e56.n;
    n = n_geom;
    {
        metal::float4 _e63 = material.normal_map_st;
        metal::float2 _e64 = weft_transform_uv(in_1.uv0_, _e63);
        metal::float4 _e67 = normal_map.sample(material_sampler, _e64);
        metal::float3 texel_2 = _e67.xyz;
        float _e72 = material.normal_strength;
        metal::float3 _e73 = weft_mapped_normal(n_geom, in_1.world_tangent, texel_2, _e72);
        n = _e73;
    }
    metal::float3 _e74 = n;
    metal::float3x3 _e76 = weft_tangent_frame(_e74, in_1.world_tangent);
    float cos_v = metal::min(metal::abs(metal::dot(n_geom, v_5)), 1.0);
    float sin_v = metal::sqrt(metal::max(1.0 - (cos_v * cos_v), 0.0));
    float _e89 = material.thread_density;
    float density = metal::clamp(_e89, 0.0, 200.0);
    float s_3 = metal::pow(metal::max(sin_v, 0.00000001), density);
    float _e98 = material.thread_transmittance;
    float transmittance = metal::clamp(_e98, 1.0, 1000.0);
    float thread_opacity = metal::saturate(1.0 - (metal::log(transmittance) / GAUZE_LN_MAX_TRANSMITTANCE));
    float alpha = metal::saturate((1.0 - ((1.0 - s_3) * (1.0 - (mesh * thread_opacity)))) * base_alpha);
    float coverage = metal::saturate((1.0 - ((1.0 - s_3) * (1.0 - mesh))) * base_alpha);
    float _e129 = material.pattern_rotation;
    float rot = ((_e129) * 0.017453292519943295474);
    metal::float3x3 _e131 = weft_rotate_tangent_frame(_e76, rot);
    float _e134 = material.pattern_threshold;
    float above_hard = (pattern > _e134) ? 1.0 : 0.0;
    float _e141 = material.pattern_threshold;
    float above_aa = metal::saturate(((pattern - _e141) / metal::max(pattern_w, 0.0001)) + 0.5);
    metal::float3 _e149 = n;
    WeftLightGeometry _e150 = weft_main_light_geometry(_e149, v_5, weft_frame);
    metal::float2 _e151 = weft_aniso_alpha_kulla(roughness_8, anisotropy_2);
    metal::float3 _e152 = weft_main_light_radiance(weft_frame);
    metal::float4 _e155 = material.scatter_color;
    metal::float3 scatter = metal::max(_e155.xyz, metal::float3(0.0));
    metal::float3 tint = metal::saturate(scatter);
    metal::float3 f0_2 = metal::float3(0.04);
    {
        metal::float3x3 _e168 = weft_rotate_tangent_frame(_e76, rot * above_hard);
        metal::float3 _e170 = weft_aniso_to_frame(_e168, _e150.h);
        float _e176 = weft_d_ggx_aniso_unnormalized(_e170.x, _e170.y, _e170.z, _e151.x, _e151.y);
        float _e179 = weft_v_schlick_ggx(_e150.n_dot_v, _e150.n_dot_l, roughness_8);
        float _e182 = material.anisotropic_intensity;
        float _e187 = material.scatter_intensity;
        float gain = metal::max(_e182, 0.0) * metal::max(_e187, 0.0);
        spec_direct = (((((_e176 * _e179) * _e150.n_dot_l) * gain) * noise) * scatter) * _e152;
        diffuse_kd = metal::float3(1.0);
        metal::float3 _e201 = weft_env_brdf_approx(f0_2, _e150.n_dot_v, roughness_8);
        env_brdf = _e201;
        metal::float3 _e205 = weft_f_schlick_roughness(f0_2, _e150.n_dot_v, roughness_8);
        ambient_kd = metal::float3(1.0) - _e205;
    }
    metal::float3 _e207 = diffuse_kd;
    metal::float3 _e208 = weft_diffuse_lambert(base);
    metal::float3 diffuse_direct = ((_e207 * _e208) * _e152) * _e150.n_dot_l;
    metal::float3 _e213 = n;
    metal::float3 _e214 = weft_sh_irradiance(_e213, weft_frame);
    metal::float3 _e215 = ambient_kd;
    metal::float3 diffuse_indirect = (_e214 * _e215) * base;
    metal::float3 _e218 = weft_aniso_bent_normal(_e76, v_5, anisotropy_2, roughness_8);
    metal::float3 _e221 = weft_prefiltered_radiance(metal::reflect(-(v_5), _e218), roughness_8, weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 _e222 = env_brdf;
    metal::float3 spec_indirect = (_e221 * _e222) * noise;
    metal::float3 _e227 = spec_direct;
    metal::float3 color = (alpha * (diffuse_direct + diffuse_indirect)) + (coverage * (_e227 + spec_indirect));
    metal::float3 radiance = metal::clamp(color, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
