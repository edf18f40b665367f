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
    metal::float4 base_map_st;
    uint strand_along_tangent;
    char _pad3[12];
    metal::float4 jitter_map_st;
    float jitter_strength;
    float anisotropic_direction;
    float strand_noise;
    float strand_density;
    metal::float4 primary_color;
    float primary_exponent;
    float primary_intensity;
    float primary_shift;
    char _pad12[4];
    metal::float4 secondary_color;
    float secondary_exponent;
    float secondary_intensity;
    float secondary_shift;
    float roughness;
    float azimuthal_roughness;
    float scale_angle;
    float ior;
    char _pad20[4];
    metal::float4 outline_color;
    float outline_width;
    float outline_max_distance;
    char _pad23[8];
    metal::float4 fringe_shadow_color;
    float fringe_shadow_length;
    char _pad25[12];
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
struct WeftHair {
    metal::packed_float3 sigma_a;
    float eta;
    metal::float4 v;
    float s;
    char _pad4[12];
    metal::float3 sin2k;
    metal::float3 cos2k;
    metal::float3 inv_v;
    metal::float3 mp_norm;
    metal::float2 blur;
    float r_floor;
    char _pad10[4];
    metal::float4 trt;
    float trt4_;
    float inv_eta;
    char _pad13[8];
};
struct WeftHairLobes {
    metal::float3 s;
    metal::float3 albedo;
    metal::float3 back;
};
struct WeftHairAngles {
    metal::float4 theta;
    float phi;
    char _pad2[12];
};
struct HairVaryings {
    metal::float4 clip_position;
    metal::float3 world_position;
    metal::float3 world_normal;
    metal::float4 world_tangent;
    metal::float2 uv0_;
    char _pad5[8];
    metal::float4 fibre;
    metal::float4 sin2k;
    metal::float4 cos2k;
    metal::float4 mp_norm;
    metal::float4 inv_v;
    metal::float4 trt;
    metal::float4 jitter;
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
constant float WEFT_HAIR_MIN_BETA_M = 0.05;
constant float WEFT_HAIR_MIN_BETA_N = 0.05;
constant uint HAIR_REFERENCE_CELLS = 64u;
constant float HAIR_TERMINATOR = 0.25;

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
    float s_2 = (n.z >= 0.0) ? 1.0 : -1.0;
    float a_2 = -1.0 / (s_2 + n.z);
    float b = (n.x * n.y) * a_2;
    return metal::float3(1.0 + (((s_2 * n.x) * n.x) * a_2), s_2 * b, -(s_2) * n.x);
}

float weft_f_dielectric(
    float cos_i,
    float eta
) {
    float c_1 = metal::clamp(metal::abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = ((eta * eta) - 1.0) + (c_1 * c_1);
    float g = metal::sqrt(metal::max(g2_, 0.0));
    float gmc = g - c_1;
    float gpc = metal::max(g + c_1, 0.0000001);
    float b_den = metal::max((c_1 * gmc) + 1.0, 0.0000001);
    float b_num = (c_1 * gpc) - 1.0;
    float inv = 1.0 / (gpc * b_den);
    float f = metal::saturate((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv));
    return (g2_ < 0.0) ? 1.0 : f;
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
    metal::float3 n_2,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_2 * metal::dot(n_2, t_in));
    float len2_1 = metal::dot(t_proj, t_proj);
    bool ok = len2_1 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_2);
    metal::float3 t_2 = ok ? (t_proj * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : _e13;
    float s_3 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_2, t_2) * s_3;
    return metal::float3x3(t_2, b_1, n_2);
}

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

float weft_hair_sqr(
    float x
) {
    return x * x;
}

float weft_hair_safe_sqrt(
    float x_1
) {
    return metal::sqrt(metal::max(x_1, 0.0));
}

float weft_hair_variance(
    float beta_m
) {
    float b_2 = metal::clamp(beta_m, WEFT_HAIR_MIN_BETA_M, 1.0);
    float b2_ = b_2 * b_2;
    float b4_ = b2_ * b2_;
    float b20_ = (((b4_ * b4_) * b4_) * b4_) * b4_;
    float _e18 = weft_hair_sqr(((0.726 * b_2) + (0.812 * b2_)) + (3.7 * b20_));
    return _e18;
}

float weft_hair_logistic_scale(
    float beta_n
) {
    float b_3 = metal::clamp(beta_n, WEFT_HAIR_MIN_BETA_N, 1.0);
    float b2_1 = b_3 * b_3;
    float b4_1 = b2_1 * b2_1;
    float b22_ = ((((b4_1 * b4_1) * b4_1) * b4_1) * b4_1) * b2_1;
    return 0.62665707 * (((0.265 * b_3) + (1.194 * b2_1)) + (5.372 * b22_));
}

metal::float3 weft_hair_sigma_a_scaled(
    metal::float3 c,
    float scale_1
) {
    metal::float3 l = metal::log(metal::clamp(c, metal::float3(0.0001), metal::float3(1.0))) * scale_1;
    return l * l;
}

float weft_hair_sigma_a_scale(
    float beta_n_1
) {
    float b_4 = metal::clamp(beta_n_1, WEFT_HAIR_MIN_BETA_N, 1.0);
    float d = ((((5.969 - (0.215 * b_4)) + ((2.532 * b_4) * b_4)) - (10.73 * metal::pow(b_4, 3.0))) + (5.574 * metal::pow(b_4, 4.0))) + (0.245 * metal::pow(b_4, 5.0));
    return 1.0 / d;
}

WeftHair weft_hair_params(
    metal::float3 sigma_a,
    float eta_1,
    float beta_m_1,
    float beta_n_2,
    float alpha_deg
) {
    WeftHair hair = {};
    hair.sigma_a = metal::max(sigma_a, metal::float3(0.0));
    hair.eta = metal::max(eta_1, 1.0001);
    float _e13 = weft_hair_variance(beta_m_1);
    hair.v = metal::float4(_e13, 0.25 * _e13, 4.0 * _e13, 4.0 * _e13);
    float _e23 = weft_hair_logistic_scale(beta_n_2);
    hair.s = _e23;
    float a_3 = ((alpha_deg) * 0.017453292519943295474);
    float s0_ = metal::sin(a_3);
    float _e29 = weft_hair_safe_sqrt(1.0 - (s0_ * s0_));
    float s1_ = (2.0 * _e29) * s0_;
    float c1_ = (_e29 * _e29) - (s0_ * s0_);
    float s2_ = (2.0 * c1_) * s1_;
    float c2_ = (c1_ * c1_) - (s1_ * s1_);
    hair.sin2k = metal::float3(s0_, s1_, s2_);
    hair.cos2k = metal::float3(_e29, c1_, c2_);
    hair.inv_v = metal::float3(1.0, 4.0, 0.25) / metal::float3(_e13);
    float _e55 = hair.inv_v.x;
    float e_trt = metal::exp(-0.5 * _e55);
    float _e60 = weft_hair_sqr(e_trt * e_trt);
    metal::float3 _e63 = hair.inv_v;
    float _e67 = weft_hair_sqr(_e60 * _e60);
    hair.mp_norm = _e63 / (metal::float3(1.0) - metal::float3(_e60, _e67, e_trt));
    float _e73 = hair.s;
    float d_1 = 0.8162094 * _e73;
    hair.blur = metal::float2(metal::sin(d_1), metal::cos(d_1));
    float _e81 = hair.s;
    float _e84 = weft_hair_sqr(0.4534 * _e81);
    hair.r_floor = _e84;
    float sh_1 = hair.s;
    hair.trt = metal::float4(-9.2609 + (sh_1 * (65.993 - (107.38 * sh_1))), 72.357 + (sh_1 * (-624.68 + (1069.8 * sh_1))), -153.75 + (sh_1 * (1704.7 - (3127.5 * sh_1))), -67.745 + (sh_1 * (-1105.8 + (2706.6 * sh_1))));
    hair.trt4_ = 239.74 - (430.94 * sh_1);
    float _e124 = hair.eta;
    hair.inv_eta = 1.0 / _e124;
    WeftHair _e127 = hair;
    return _e127;
}

float weft_hair_logistic(
    float x_2,
    float s
) {
    float e_1 = metal::exp(-(metal::abs(x_2)) / s);
    float _e8 = weft_hair_sqr(1.0 + e_1);
    return e_1 / (s * _e8);
}

float weft_hair_trimmed_logistic(
    float x_3,
    float s_1
) {
    float e_2 = metal::exp(-3.1415927 / s_1);
    float _e5 = weft_hair_logistic(x_3, s_1);
    return (_e5 * (1.0 + e_2)) / (1.0 - e_2);
}

WeftHairAngles weft_hair_angles(
    metal::float3 t,
    metal::float3 o,
    metal::float3 i
) {
    WeftHairAngles out_2 = {};
    float sin_o = metal::clamp(metal::dot(o, t), -1.0, 1.0);
    float sin_i = metal::clamp(metal::dot(i, t), -1.0, 1.0);
    float _e16 = weft_hair_safe_sqrt(1.0 - (sin_o * sin_o));
    float _e20 = weft_hair_safe_sqrt(1.0 - (sin_i * sin_i));
    out_2.theta = metal::float4(sin_o, _e16, sin_i, _e20);
    metal::float3 o_perp = o - (sin_o * t);
    metal::float3 i_perp = i - (sin_i * t);
    float len2_2 = metal::dot(o_perp, o_perp) * metal::dot(i_perp, i_perp);
    float cos_phi = (len2_2 > 0.000000000001) ? (metal::dot(o_perp, i_perp) * metal::rsqrt(metal::max(len2_2, 0.000000000000000000000000000001))) : 1.0;
    out_2.phi = metal::acos(metal::clamp(cos_phi, -1.0, 1.0));
    WeftHairAngles _e43 = out_2;
    return _e43;
}

metal::float3 weft_hair_fast_tt_density(
    float sin_half,
    float a
) {
    float rho2_ = (1.0 - ((2.0 * a) * sin_half)) + (a * a);
    float inv_rho = metal::rsqrt(metal::max(rho2_, 0.00000001));
    float cos_go = metal::max(sin_half - a, 0.0) * inv_rho;
    float cos_gt = (1.0 - (a * sin_half)) * inv_rho;
    return metal::float3(cos_go, cos_gt, ((0.25 * cos_go) * cos_gt) * inv_rho);
}

metal::float3 weft_hair_fast_tt(
    float sin_plus,
    float sin_minus,
    float a_1,
    float cos_o,
    float eta_2,
    metal::float3 sigma_a_1,
    float chord
) {
    metal::float3 _e7 = weft_hair_fast_tt_density(sin_plus, a_1);
    metal::float3 _e8 = weft_hair_fast_tt_density(sin_minus, a_1);
    float _e11 = weft_f_dielectric(cos_o * _e7.x, eta_2);
    float _e19 = weft_hair_sqr(1.0 - _e11);
    return metal::exp(-(sigma_a_1) * (chord * _e7.y)) * ((_e19 * 0.5) * (_e7.z + _e8.z));
}

WeftHairLobes weft_hair_fast(
    WeftHair hair_1,
    metal::float3 t_1,
    metal::float3 o_1,
    metal::float3 i_1
) {
    WeftHairLobes out_3 = {};
    float sin_o_1 = metal::clamp(metal::dot(o_1, t_1), -1.0, 1.0);
    float sin_i_1 = metal::clamp(metal::dot(i_1, t_1), -1.0, 1.0);
    float _e15 = weft_hair_safe_sqrt(1.0 - (sin_o_1 * sin_o_1));
    float _e19 = weft_hair_safe_sqrt(1.0 - (sin_i_1 * sin_i_1));
    metal::float3 o_perp_1 = o_1 - (sin_o_1 * t_1);
    metal::float3 i_perp_1 = i_1 - (sin_i_1 * t_1);
    float len2_3 = metal::dot(o_perp_1, o_perp_1) * metal::dot(i_perp_1, i_perp_1);
    float cos_phi_1 = metal::clamp((len2_3 > 0.000000000001) ? (metal::dot(o_perp_1, i_perp_1) * metal::rsqrt(metal::max(len2_3, 0.000000000000000000000000000001))) : 1.0, -1.0, 1.0);
    float cos_half = metal::sqrt(0.5 + (0.5 * cos_phi_1));
    float sin_half_1 = metal::sqrt(0.5 - (0.5 * cos_phi_1));
    metal::float3 so = metal::float3((sin_o_1 * hair_1.cos2k.y) - (_e15 * hair_1.sin2k.y), (sin_o_1 * hair_1.cos2k.x) + (_e15 * hair_1.sin2k.x), (sin_o_1 * hair_1.cos2k.z) + (_e15 * hair_1.sin2k.z));
    metal::float3 co = metal::abs(metal::float3((_e15 * hair_1.cos2k.y) + (sin_o_1 * hair_1.sin2k.y), (_e15 * hair_1.cos2k.x) - (sin_o_1 * hair_1.sin2k.x), (_e15 * hair_1.cos2k.z) - (sin_o_1 * hair_1.sin2k.z)));
    metal::float3 inv_v = hair_1.inv_v;
    metal::float3 norm = hair_1.mp_norm;
    metal::float3 x_6 = (_e19 * co) * inv_v;
    metal::float3 u = metal::float3(1.0) / (metal::float3(1.0) + (0.7 * x_6));
    metal::float3 bessel = (metal::float3(1.0) + ((u * (metal::float3(1.0) - u)) * (metal::float3(0.181903) + (u * (metal::float3(-0.401835) + (u * 3.1851)))))) * metal::rsqrt(metal::float3(1.0) + (6.2831855 * x_6));
    metal::float3 mp = (metal::exp(metal::min((((_e19 * co) - (sin_i_1 * so)) - metal::float3(1.0)) * inv_v, metal::float3(0.0))) * bessel) * norm;
    float sin_t = sin_o_1 * hair_1.inv_eta;
    float chord_1 = 2.0 * metal::rsqrt(metal::max(1.0 - (sin_t * sin_t), 0.00000001));
    float a_4 = _e15 * metal::rsqrt(metal::max((hair_1.eta * hair_1.eta) - (sin_o_1 * sin_o_1), 0.00000001));
    float sd = hair_1.blur.x;
    float cd = hair_1.blur.y;
    float c_r = metal::sqrt(metal::min((0.5 + (0.5 * cos_phi_1)) + hair_1.r_floor, 1.0));
    float _e179 = weft_f_dielectric(_e15 * c_r, hair_1.eta);
    float r = (0.25 * c_r) * _e179;
    metal::float3 _e189 = weft_hair_fast_tt((sin_half_1 * cd) + (cos_half * sd), (sin_half_1 * cd) - (cos_half * sd), a_4, _e15, hair_1.eta, hair_1.sigma_a, chord_1);
    float h_f = 0.6243 + (0.1898 * _e15);
    float _e197 = weft_hair_safe_sqrt(1.0 - (h_f * h_f));
    float _e200 = weft_f_dielectric(_e15 * _e197, hair_1.eta);
    float h2_ = 0.4824 + (0.2778 * _e15);
    float _e208 = weft_hair_safe_sqrt(1.0 - (h2_ * h2_));
    float _e211 = weft_f_dielectric(_e15 * _e208, hair_1.eta);
    float _e219 = weft_hair_safe_sqrt(1.0 - (((h2_ * h2_) * a_4) * a_4));
    metal::float3 t2_ = metal::exp(-(hair_1.sigma_a) * (chord_1 * _e219));
    float _e225 = weft_hair_sqr(1.0 - _e211);
    metal::float3 a2_ = ((_e225 * _e211) * t2_) * t2_;
    metal::float3 ft = _e200 * t2_;
    metal::float3 a3_ = (a2_ * ft) / (metal::float3(1.0) - ft);
    float s2_fit = hair_1.trt.x + (a_4 * (hair_1.trt.y + (a_4 * (hair_1.trt.z + (a_4 * (hair_1.trt.w + (a_4 * hair_1.trt4_)))))));
    float s_trt = metal::sqrt(metal::max(metal::exp(metal::clamp(s2_fit, -9.0, 2.5)), hair_1.s * hair_1.s));
    float _e262 = weft_hair_trimmed_logistic(metal::acos(cos_phi_1), s_trt);
    out_3.s = (metal::float3(mp.x * r) + (mp.y * _e189)) + (mp.z * ((a2_ * _e262) + (a3_ * 0.15915494)));
    out_3.back = metal::float3(_e200) + a2_;
    float _e284 = weft_hair_sqr(1.0 - _e211);
    out_3.albedo = ((metal::float3(_e200) + (_e284 * t2_)) + a2_) + a3_;
    WeftHairLobes _e290 = out_3;
    return _e290;
}

float hair_noise_period(
    float density
) {
    return metal::max(metal::rint(density), 1.0);
}

WeftHair hair_from_varyings(
    HairVaryings in_4,
    metal::float3 sigma_a_2
) {
    float v_1 = in_4.fibre.z;
    return WeftHair {metal::max(sigma_a_2, metal::float3(0.0)), in_4.fibre.x, metal::float4(v_1, 0.25 * v_1, 4.0 * v_1, 4.0 * v_1), in_4.fibre.y, {}, in_4.sin2k.xyz, in_4.cos2k.xyz, in_4.inv_v.xyz, in_4.mp_norm.xyz, metal::float2(in_4.cos2k.w, in_4.mp_norm.w), in_4.sin2k.w, {}, metal::float4(in_4.inv_v.w, in_4.trt.xyz), in_4.trt.w, in_4.jitter.z};
}

metal::float3 hair_strand(
    metal::float3x3 frame,
    metal::float2 uv0_,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> flow_map
) {
    metal::float2 ts = {};
    uint _e10 = material.strand_along_tangent;
    ts = (_e10 != 0u) ? metal::float2(1.0, 0.0) : metal::float2(0.0, 1.0);
    {
        metal::float4 _e17 = flow_map.sample(material_sampler, uv0_);
        metal::float2 f_1 = (_e17.xy * 2.0) - metal::float2(1.0);
        float len2_4 = metal::dot(f_1, f_1);
        metal::float2 _e25 = ts;
        ts = (len2_4 > 0.0001) ? (f_1 * metal::rsqrt(metal::max(len2_4, 0.000000000001))) : _e25;
    }
    float _e35 = ts.x;
    float _e39 = ts.y;
    metal::float3 _e43 = weft_safe_normalize((frame[0] * _e35) + (frame[1] * _e39), frame[1]);
    return _e43;
}

float hair_hash(
    uint x_4
) {
    uint state = (x_4 * 747796405u) + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return static_cast<float>((word >> 22u) ^ word) * 0.00000000023283064;
}

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

float hair_value_noise(
    float x_5,
    float p
) {
    float cell = metal::floor(x_5);
    float f_2 = x_5 - cell;
    float c0_ = cell - (p * metal::floor(cell / p));
    float c1_1 = ((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0);
    float _e16 = hair_hash(naga_f2u32(c0_));
    float _e18 = hair_hash(naga_f2u32(c1_1));
    return metal::mix(_e16, _e18, (f_2 * f_2) * (3.0 - (2.0 * f_2))) - 0.5;
}

float hair_jitter(
    metal::float2 uv0_1,
    metal::float2 rotation,
    float noise_period,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> jitter_map,
    metal::texture2d<float, metal::access::sample> uv_rotate_mask
) {
    metal::float4 _e5 = uv_rotate_mask.sample(material_sampler, uv0_1);
    float mask = metal::step(0.8, _e5.x);
    float c_2 = rotation.x;
    float s_4 = rotation.y;
    metal::float2 rotated = metal::float2((c_2 * uv0_1.x) + (s_4 * uv0_1.y), (-(s_4) * uv0_1.x) + (c_2 * uv0_1.y));
    metal::float4 _e28 = material.jitter_map_st;
    metal::float2 _e29 = weft_transform_uv((mask > 0.5) ? rotated : uv0_1, _e28);
    metal::float4 _e32 = jitter_map.sample(material_sampler, _e29);
    float j = _e32.x;
    uint _e38 = material.strand_along_tangent;
    float across = (_e38 != 0u) ? _e29.y : _e29.x;
    float _e44 = material.strand_density;
    float _e46 = hair_value_noise(across * _e44, noise_period);
    float _e49 = material.jitter_strength;
    float _e53 = material.strand_noise;
    return (_e49 * j) + (_e53 * _e46);
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


struct vs_hairInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float4 tangent_1 [[attribute(2)]];
    metal::float2 uv0_2 [[attribute(3)]];
};
struct vs_hairOutput {
    metal::float4 clip_position [[position]];
    metal::float3 world_position [[user(loc0), center_perspective]];
    metal::float3 world_normal [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
    metal::float4 fibre [[user(loc4), flat]];
    metal::float4 sin2k [[user(loc5), flat]];
    metal::float4 cos2k [[user(loc6), flat]];
    metal::float4 mp_norm [[user(loc7), flat]];
    metal::float4 inv_v [[user(loc8), flat]];
    metal::float4 trt [[user(loc9), flat]];
    metal::float4 jitter [[user(loc10), flat]];
};
vertex vs_hairOutput vs_hair(
  vs_hairInput varyings_2 [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
) {
    const WeftVertexInput in_1 = { varyings_2.position, varyings_2.normal, varyings_2.tangent_1, varyings_2.uv0_2 };
    WeftHair h = {};
    float scale = 0.0;
    WeftVaryings _e1 = weft_forward_vertex(in_1, weft_frame, weft_object);
    float _e6 = material.ior;
    float _e9 = material.roughness;
    float _e12 = material.azimuthal_roughness;
    float _e15 = material.scale_angle;
    WeftHair _e16 = weft_hair_params(metal::float3(0.0), _e6, _e9, _e12, _e15);
    h = _e16;
    {
        float _e22 = material.azimuthal_roughness;
        float _e23 = weft_hair_sigma_a_scale(_e22);
        scale = _e23;
    }
    float _e26 = material.anisotropic_direction;
    float a_5 = ((_e26) * 0.017453292519943295474);
    float _e34 = h.eta;
    float _e36 = h.s;
    float _e39 = h.v.x;
    float _e40 = scale;
    metal::float3 _e43 = h.sin2k;
    float _e45 = h.r_floor;
    metal::float3 _e48 = h.cos2k;
    float _e51 = h.blur.x;
    metal::float3 _e54 = h.mp_norm;
    float _e57 = h.blur.y;
    metal::float3 _e60 = h.inv_v;
    float _e63 = h.trt.x;
    metal::float4 _e66 = h.trt;
    float _e69 = h.trt4_;
    float _e74 = h.inv_eta;
    float _e77 = material.strand_density;
    float _e78 = hair_noise_period(_e77);
    const auto _tmp_1 = HairVaryings {_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, {}, metal::float4(_e34, _e36, _e39, _e40), metal::float4(_e43, _e45), metal::float4(_e48, _e51), metal::float4(_e54, _e57), metal::float4(_e60, _e63), metal::float4(_e66.yzw, _e69), metal::float4(metal::cos(a_5), metal::sin(a_5), _e74, _e78)};
    return vs_hairOutput { _tmp_1.clip_position, _tmp_1.world_position, _tmp_1.world_normal, _tmp_1.world_tangent, _tmp_1.uv0_, _tmp_1.fibre, _tmp_1.sin2k, _tmp_1.cos2k, _tmp_1.mp_norm, _tmp_1.inv_v, _tmp_1.trt, _tmp_1.jitter };
}


struct fs_mainInput {
    metal::float3 world_position_2 [[user(loc0), center_perspective]];
    metal::float3 world_normal_1 [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_2 [[user(loc3), center_perspective]];
    metal::float4 fibre [[user(loc4), flat]];
    metal::float4 sin2k [[user(loc5), flat]];
    metal::float4 cos2k [[user(loc6), flat]];
    metal::float4 mp_norm [[user(loc7), flat]];
    metal::float4 inv_v [[user(loc8), flat]];
    metal::float4 trt [[user(loc9), flat]];
    metal::float4 jitter [[user(loc10), flat]];
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
, metal::texture2d<float, metal::access::sample> flow_map [[texture(1)]]
, metal::texture2d<float, metal::access::sample> jitter_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> uv_rotate_mask [[texture(3)]]
) {
    const HairVaryings in_2 = { clip_position, varyings_3.world_position_2, varyings_3.world_normal_1, varyings_3.world_tangent, varyings_3.uv0_2, {}, varyings_3.fibre, varyings_3.sin2k, varyings_3.cos2k, varyings_3.mp_norm, varyings_3.inv_v, varyings_3.trt, varyings_3.jitter };
    metal::float3 color = {};
    WeftHairLobes lobes = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = weft_transform_uv(in_2.uv0_, _e4);
    metal::float4 _e8 = material.base_color;
    metal::float4 _e11 = base_map.sample(material_sampler, _e5);
    metal::float4 base_rgba = _e8 * _e11;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float alpha = metal::saturate(base_rgba.w);
    WeftSurface _e19 = weft_surface(in_2.world_position, in_2.world_normal, weft_frame);
    metal::float3 v_2 = _e19.v;
    metal::float3 n_3 = _e19.n;
    metal::float3x3 _e23 = weft_tangent_frame(n_3, in_2.world_tangent);
    metal::float3 _e25 = hair_strand(_e23, in_2.uv0_, material, material_sampler, flow_map);
    float _e31 = hair_jitter(in_2.uv0_, in_2.jitter.xy, in_2.jitter.w, material, material_sampler, jitter_map, uv_rotate_mask);
    metal::float3 _e32 = weft_main_light_direction(weft_frame);
    metal::float3 _e33 = weft_main_light_radiance(weft_frame);
    metal::float3 _e34 = weft_sh_irradiance(n_3, weft_frame);
    float n_dot_l = metal::dot(n_3, _e32);
    {
        metal::float3 _e39 = weft_safe_normalize(_e25 + (_e31 * n_3), _e25);
        metal::float3 _e42 = weft_hair_sigma_a_scaled(base, in_2.fibre.w);
        WeftHair _e43 = hair_from_varyings(in_2, _e42);
        WeftHairAngles _e44 = weft_hair_angles(_e39, v_2, _e32);
        {
            WeftHairLobes _e46 = weft_hair_fast(_e43, _e39, v_2, _e32);
            lobes = _e46;
        }
        float body = metal::smoothstep(-0.25, HAIR_TERMINATOR, n_dot_l);
        metal::float3 _e53 = lobes.back;
        metal::float3 multiple = base * (metal::float3(1.0) - _e53);
        metal::float3 _e57 = lobes.s;
        metal::float3 direct = (_e57 * body) + (multiple * (WEFT_INV_PI * metal::saturate(n_dot_l)));
        metal::float3 _e66 = lobes.back;
        color = (direct * _e33) + (_e34 * (multiple + _e66));
    }
    metal::float3 _e70 = color;
    metal::float3 radiance = metal::clamp(_e70, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
