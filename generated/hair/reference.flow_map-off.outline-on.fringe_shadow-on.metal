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
struct WeftFringeShadowVertex {
    metal::float3 position;
};
struct WeftFringeShadowVaryings {
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
struct WeftHairAttenuation {
    float a0_;
    char _pad1[12];
    metal::float3 a1_;
    metal::float3 a2_;
    metal::packed_float3 a3_;
    float gamma_t;
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
    float s_6 = (n.z >= 0.0) ? 1.0 : -1.0;
    float a_1 = -1.0 / (s_6 + n.z);
    float b = (n.x * n.y) * a_1;
    return metal::float3(1.0 + (((s_6 * n.x) * n.x) * a_1), s_6 * b, -(s_6) * n.x);
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
    WeftVertexInput in_4,
    constant WeftFrame& weft_frame,
    constant WeftObject& weft_object
) {
    WeftVaryings out_2 = {};
    metal::float4x4 model = weft_object.model;
    metal::float3x3 model3_ = metal::float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    metal::float4x4 nm = weft_object.normal_matrix;
    metal::float3x3 normal3_ = metal::float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    metal::float4 world = model * metal::float4(in_4.position, 1.0);
    float mirror = (metal::determinant(model3_) < 0.0) ? -1.0 : 1.0;
    float bitangent_sign = ((in_4.tangent.w < 0.0) ? -1.0 : 1.0) * mirror;
    metal::float4x4 _e43 = weft_frame.view_proj;
    out_2.clip_position = _e43 * metal::float4(world.xyz, 1.0);
    out_2.world_position = world.xyz;
    metal::float3 _e55 = weft_safe_normalize(normal3_ * in_4.normal, metal::float3(0.0));
    out_2.world_normal = _e55;
    metal::float3 _e62 = weft_safe_normalize(model3_ * in_4.tangent.xyz, metal::float3(0.0));
    out_2.world_tangent = metal::float4(_e62, bitangent_sign);
    out_2.uv0_ = in_4.uv0_;
    WeftVaryings _e66 = out_2;
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
    metal::float3 t_1 = ok ? (t_proj * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : _e13;
    float s_7 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_2, t_1) * s_7;
    return metal::float3x3(t_1, b_1, n_2);
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
    float a_2 = ((alpha_deg) * 0.017453292519943295474);
    float s0_ = metal::sin(a_2);
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

float weft_hair_i0_(
    float x_2
) {
    float term = 1.0;
    float sum = 1.0;
    int i = 1;
    float q = (0.25 * x_2) * x_2;
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            int _e22 = i;
            i = as_type<int>(as_type<uint>(_e22) + as_type<uint>(1));
        }
        loop_init = false;
        int _e10 = i;
        if (_e10 < 16) {
        } else {
            break;
        }
        {
            int _e13 = i;
            float k_1 = static_cast<float>(_e13);
            float _e15 = term;
            term = _e15 * (q / (k_1 * k_1));
            float _e19 = sum;
            float _e20 = term;
            sum = _e19 + _e20;
        }
    }
    float _e25 = sum;
    return _e25;
}

float weft_hair_log_i0_(
    float x_3
) {
    if (x_3 > 12.0) {
        float r = 1.0 / x_3;
        return (x_3 - (0.5 * metal::log(6.2831855 * x_3))) + metal::log(1.0 + (r * (0.125 + (0.0703125 * r))));
    }
    float _e20 = weft_hair_i0_(x_3);
    return metal::log(_e20);
}

float weft_hair_mp(
    float cos_i_1,
    float cos_o,
    float sin_i,
    float sin_o,
    float v_1
) {
    float a_3 = (cos_i_1 * cos_o) / v_1;
    float b_5 = (sin_i * sin_o) / v_1;
    if (v_1 <= 0.1) {
        float _e11 = weft_hair_log_i0_(a_3);
        return metal::exp((((_e11 - b_5) - (1.0 / v_1)) + 0.6931472) + metal::log(1.0 / (2.0 * v_1)));
    }
    float _e27 = weft_hair_i0_(a_3);
    return (metal::exp(-(b_5)) * _e27) / ((metal::sinh(1.0 / v_1) * 2.0) * v_1);
}

metal::float4 weft_hair_longitudinal(
    WeftHair hair_1,
    float sin_o_1,
    float cos_o_1,
    float sin_i_1,
    float cos_i_2
) {
    float sin_r = (sin_o_1 * hair_1.cos2k.y) - (cos_o_1 * hair_1.sin2k.y);
    float cos_r = metal::abs((cos_o_1 * hair_1.cos2k.y) + (sin_o_1 * hair_1.sin2k.y));
    float sin_tt = (sin_o_1 * hair_1.cos2k.x) + (cos_o_1 * hair_1.sin2k.x);
    float cos_tt = metal::abs((cos_o_1 * hair_1.cos2k.x) - (sin_o_1 * hair_1.sin2k.x));
    float sin_trt = (sin_o_1 * hair_1.cos2k.z) + (cos_o_1 * hair_1.sin2k.z);
    float cos_trt = metal::abs((cos_o_1 * hair_1.cos2k.z) - (sin_o_1 * hair_1.sin2k.z));
    float _e52 = weft_hair_mp(cos_i_2, cos_r, sin_i_1, sin_r, hair_1.v.x);
    float _e55 = weft_hair_mp(cos_i_2, cos_tt, sin_i_1, sin_tt, hair_1.v.y);
    float _e58 = weft_hair_mp(cos_i_2, cos_trt, sin_i_1, sin_trt, hair_1.v.z);
    float _e61 = weft_hair_mp(cos_i_2, cos_o_1, sin_i_1, sin_o_1, hair_1.v.w);
    return metal::float4(_e52, _e55, _e58, _e61);
}

float weft_hair_logistic(
    float x_4,
    float s
) {
    float e_1 = metal::exp(-(metal::abs(x_4)) / s);
    float _e8 = weft_hair_sqr(1.0 + e_1);
    return e_1 / (s * _e8);
}

float weft_hair_trimmed_logistic(
    float x_5,
    float s_1
) {
    float e_2 = metal::exp(-3.1415927 / s_1);
    float _e5 = weft_hair_logistic(x_5, s_1);
    return (_e5 * (1.0 + e_2)) / (1.0 - e_2);
}

float weft_hair_etap(
    WeftHair hair_2,
    float sin_o_2,
    float cos_o_2
) {
    return metal::sqrt((hair_2.eta * hair_2.eta) - (sin_o_2 * sin_o_2)) / metal::max(cos_o_2, 0.0001);
}

WeftHairAttenuation weft_hair_attenuation(
    WeftHair hair_3,
    float sin_o_3,
    float cos_o_3,
    float h_1
) {
    WeftHairAttenuation a = {};
    float sin_t = sin_o_3 / hair_3.eta;
    float _e9 = weft_hair_safe_sqrt(1.0 - (sin_t * sin_t));
    float _e10 = weft_hair_etap(hair_3, sin_o_3, cos_o_3);
    float sin_gamma_t = metal::clamp(h_1 / _e10, -1.0, 1.0);
    float _e18 = weft_hair_safe_sqrt(1.0 - (sin_gamma_t * sin_gamma_t));
    metal::float3 t_2 = metal::exp(-(hair_3.sigma_a) * ((2.0 * _e18) / metal::max(_e9, 0.0001)));
    float _e31 = weft_hair_safe_sqrt(1.0 - (h_1 * h_1));
    float _e34 = weft_f_dielectric(cos_o_3 * _e31, hair_3.eta);
    a.a0_ = _e34;
    a.a1_ = ((1.0 - _e34) * (1.0 - _e34)) * t_2;
    metal::float3 _e46 = a.a1_;
    a.a2_ = (_e46 * t_2) * _e34;
    metal::float3 _e51 = a.a2_;
    a.a3_ = ((_e51 * t_2) * _e34) / (metal::float3(1.0) - (t_2 * _e34));
    a.gamma_t = metal::asin(sin_gamma_t);
    WeftHairAttenuation _e61 = a;
    return _e61;
}

WeftHairAngles weft_hair_angles(
    metal::float3 t,
    metal::float3 o,
    metal::float3 i_1
) {
    WeftHairAngles out_3 = {};
    float sin_o_4 = metal::clamp(metal::dot(o, t), -1.0, 1.0);
    float sin_i_2 = metal::clamp(metal::dot(i_1, t), -1.0, 1.0);
    float _e16 = weft_hair_safe_sqrt(1.0 - (sin_o_4 * sin_o_4));
    float _e20 = weft_hair_safe_sqrt(1.0 - (sin_i_2 * sin_i_2));
    out_3.theta = metal::float4(sin_o_4, _e16, sin_i_2, _e20);
    metal::float3 o_perp = o - (sin_o_4 * t);
    metal::float3 i_perp = i_1 - (sin_i_2 * t);
    float len2_2 = metal::dot(o_perp, o_perp) * metal::dot(i_perp, i_perp);
    float cos_phi = (len2_2 > 0.000000000001) ? (metal::dot(o_perp, i_perp) * metal::rsqrt(metal::max(len2_2, 0.000000000000000000000000000001))) : 1.0;
    out_3.phi = metal::acos(metal::clamp(cos_phi, -1.0, 1.0));
    WeftHairAngles _e43 = out_3;
    return _e43;
}

float weft_hair_logistic_cdf(
    float x_6,
    float s_2
) {
    return 1.0 / (1.0 + metal::exp(-(x_6) / s_2));
}

float weft_hair_trimmed_integral(
    float lo,
    float hi,
    float s_3
) {
    float sum_1 = {};
    float _e4 = weft_hair_logistic_cdf(-3.1415927, s_3);
    float _e6 = weft_hair_logistic_cdf(WEFT_PI, s_3);
    float a_4 = metal::clamp(lo, -3.1415927, WEFT_PI);
    float b_6 = metal::clamp(hi, -3.1415927, WEFT_PI);
    float _e13 = weft_hair_logistic_cdf(b_6, s_3);
    float _e14 = weft_hair_logistic_cdf(a_4, s_3);
    sum_1 = _e13 - _e14;
    if (hi > WEFT_PI) {
        float _e19 = sum_1;
        float _e24 = weft_hair_logistic_cdf(metal::min(hi - 6.2831855, WEFT_PI), s_3);
        sum_1 = _e19 + (_e24 - _e4);
    }
    if (lo < -3.1415927) {
        float _e29 = sum_1;
        float _e34 = weft_hair_logistic_cdf(metal::max(lo + 6.2831855, -3.1415927), s_3);
        sum_1 = _e29 + (_e6 - _e34);
    }
    float _e37 = sum_1;
    return _e37 / (_e6 - _e4);
}

float weft_hair_np_cell(
    float d0_,
    float d1_,
    float s_4
) {
    float mid = 0.5 * (d0_ + d1_);
    float m = mid - (6.2831855 * metal::rint(mid / 6.2831855));
    float half_ = metal::min(0.5 * metal::abs(d1_ - d0_), WEFT_PI);
    if (half_ < 0.0001) {
        float _e20 = weft_hair_trimmed_logistic(m, s_4);
        return _e20;
    }
    float _e23 = weft_hair_trimmed_integral(m - half_, m + half_, s_4);
    return _e23 / (2.0 * half_);
}

WeftHairLobes weft_hair_mean(
    WeftHair hair_4,
    WeftHairAngles angles,
    uint count
) {
    metal::float3 s_5 = metal::float3(0.0);
    metal::float3 albedo = metal::float3(0.0);
    metal::float3 back = metal::float3(0.0);
    float weights = 0.0;
    float g0_ = -1.5707964;
    metal::float3 d0_1 = {};
    uint k = 0u;
    WeftHairLobes out_4 = {};
    metal::float4 th = angles.theta;
    metal::float4 _e8 = weft_hair_longitudinal(hair_4, angles.theta.x, angles.theta.y, angles.theta.z, angles.theta.w);
    float _e11 = weft_hair_etap(hair_4, angles.theta.x, angles.theta.y);
    uint cells = metal::max(count, 1u);
    float step = WEFT_PI / static_cast<float>(cells);
    float _e35 = g0_;
    float _e43 = g0_;
    d0_1 = metal::float3(angles.phi) - (((metal::float3(0.0, 2.0, 4.0) * metal::asin(metal::clamp(metal::sin(_e35) / _e11, -1.0, 1.0))) - metal::float3(2.0 * _e43)) + metal::float3(0.0, 3.1415927, 6.2831855));
    uint2 loop_bound_1 = uint2(4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (metal::all(loop_bound_1 == uint2(0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e153 = k;
            k = _e153 + 1u;
        }
        loop_init_1 = false;
        uint _e58 = k;
        if (_e58 < cells) {
        } else {
            break;
        }
        {
            float _e60 = g0_;
            float g1_ = _e60 + step;
            float gamma_t1_ = metal::asin(metal::clamp(metal::sin(g1_) / _e11, -1.0, 1.0));
            metal::float3 d1_1 = metal::float3(angles.phi) - (((metal::float3(0.0, 2.0, 4.0) * gamma_t1_) - metal::float3(2.0 * g1_)) + metal::float3(0.0, 3.1415927, 6.2831855));
            float _e85 = g0_;
            float gm = _e85 + (0.5 * step);
            float w = metal::cos(gm);
            WeftHairAttenuation _e93 = weft_hair_attenuation(hair_4, angles.theta.x, angles.theta.y, metal::sin(gm));
            float _e98 = d0_1.x;
            float _e101 = weft_hair_np_cell(_e98, d1_1.x, hair_4.s);
            float _e107 = d0_1.y;
            float _e110 = weft_hair_np_cell(_e107, d1_1.y, hair_4.s);
            float _e118 = d0_1.z;
            float _e121 = weft_hair_np_cell(_e118, d1_1.z, hair_4.s);
            metal::float3 lobes_1 = ((metal::float3((_e8.x * _e93.a0_) * _e101) + ((_e8.y * _e93.a1_) * _e110)) + ((_e8.z * _e93.a2_) * _e121)) + ((_e8.w * _e93.a3_) * 0.15915494);
            metal::float3 _e130 = s_5;
            s_5 = _e130 + (w * lobes_1);
            metal::float3 _e133 = albedo;
            albedo = _e133 + (w * (((metal::float3(_e93.a0_) + _e93.a1_) + _e93.a2_) + _e93.a3_));
            metal::float3 _e144 = back;
            back = _e144 + (w * (metal::float3(_e93.a0_) + _e93.a2_));
            float _e151 = weights;
            weights = _e151 + w;
            g0_ = g1_;
            d0_1 = d1_1;
        }
    }
    metal::float3 _e158 = s_5;
    float _e159 = weights;
    out_4.s = _e158 / metal::float3(_e159);
    metal::float3 _e163 = albedo;
    float _e164 = weights;
    out_4.albedo = _e163 / metal::float3(_e164);
    metal::float3 _e168 = back;
    float _e169 = weights;
    out_4.back = _e168 / metal::float3(_e169);
    WeftHairLobes _e172 = out_4;
    return _e172;
}

float hair_noise_period(
    float density
) {
    return metal::max(metal::rint(density), 1.0);
}

WeftHair hair_from_varyings(
    HairVaryings in_5,
    metal::float3 sigma_a_1
) {
    float v_2 = in_5.fibre.z;
    return WeftHair {metal::max(sigma_a_1, metal::float3(0.0)), in_5.fibre.x, metal::float4(v_2, 0.25 * v_2, 4.0 * v_2, 4.0 * v_2), in_5.fibre.y, {}, in_5.sin2k.xyz, in_5.cos2k.xyz, in_5.inv_v.xyz, in_5.mp_norm.xyz, metal::float2(in_5.cos2k.w, in_5.mp_norm.w), in_5.sin2k.w, {}, metal::float4(in_5.inv_v.w, in_5.trt.xyz), in_5.trt.w, in_5.jitter.z};
}

metal::float3 hair_strand(
    metal::float3x3 frame,
    metal::float2 uv0_,
    constant WeftMaterial& material
) {
    metal::float2 ts = {};
    uint _e10 = material.strand_along_tangent;
    ts = (_e10 != 0u) ? metal::float2(1.0, 0.0) : metal::float2(0.0, 1.0);
    float _e17 = ts.x;
    float _e21 = ts.y;
    metal::float3 _e25 = weft_safe_normalize((frame[0] * _e17) + (frame[1] * _e21), frame[1]);
    return _e25;
}

float hair_hash(
    uint x_7
) {
    uint state = (x_7 * 747796405u) + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return static_cast<float>((word >> 22u) ^ word) * 0.00000000023283064;
}

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

float hair_value_noise(
    float x_8,
    float p
) {
    float cell = metal::floor(x_8);
    float f_1 = x_8 - cell;
    float c0_ = cell - (p * metal::floor(cell / p));
    float c1_1 = ((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0);
    float _e16 = hair_hash(naga_f2u32(c0_));
    float _e18 = hair_hash(naga_f2u32(c1_1));
    return metal::mix(_e16, _e18, (f_1 * f_1) * (3.0 - (2.0 * f_1))) - 0.5;
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
    float s_8 = rotation.y;
    metal::float2 rotated = metal::float2((c_2 * uv0_1.x) + (s_8 * uv0_1.y), (-(s_8) * uv0_1.x) + (c_2 * uv0_1.y));
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


struct vs_fringe_shadowInput {
    metal::float3 position [[attribute(0)]];
};
struct vs_fringe_shadowOutput {
    metal::float4 clip_position [[position]];
};
vertex vs_fringe_shadowOutput vs_fringe_shadow(
  vs_fringe_shadowInput varyings_2 [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
) {
    const WeftFringeShadowVertex in_1 = { varyings_2.position };
    bool local_2 = {};
    WeftFringeShadowVaryings out_1 = {};
    metal::float4x4 _e3 = weft_object.model;
    metal::float3 world_2 = (_e3 * metal::float4(in_1.position, 1.0)).xyz;
    metal::float4x4 _e11 = weft_frame.view_proj;
    metal::float4 clip_1 = _e11 * metal::float4(world_2, 1.0);
    metal::float4 _e17 = weft_frame.light_direction;
    metal::float3 l_1 = _e17.xyz;
    float l_len = metal::length(l_1);
    metal::float3 travel = (l_len > 0.000001) ? (-(l_1) / metal::float3(metal::max(l_len, 0.000001))) : metal::float3(0.0);
    float _e32 = material.fringe_shadow_length;
    float length_world = metal::max(_e32, 0.0);
    metal::float4x4 _e37 = weft_frame.view_proj;
    metal::float4 pushed = _e37 * metal::float4(world_2 + (travel * length_world), 1.0);
    if (clip_1.w > 0.000001) {
        local_2 = pushed.w > 0.000001;
    } else {
        local_2 = false;
    }
    bool usable_1 = local_2;
    metal::float2 offset_ndc = usable_1 ? ((pushed.xy / metal::float2(metal::max(pushed.w, 0.000001))) - (clip_1.xy / metal::float2(metal::max(clip_1.w, 0.000001)))) : metal::float2(0.0);
    out_1.clip_position = metal::float4(clip_1.xy + (offset_ndc * clip_1.w), clip_1.zw);
    WeftFringeShadowVaryings _e77 = out_1;
    const auto _tmp_1 = _e77;
    return vs_fringe_shadowOutput { _tmp_1.clip_position };
}


struct fs_fringe_shadowOutput {
    metal::float4 member_3 [[color(0)]];
};
fragment fs_fringe_shadowOutput fs_fringe_shadow(
  constant WeftMaterial& material [[buffer(1)]]
) {
    metal::float4 _e2 = material.fringe_shadow_color;
    return fs_fringe_shadowOutput { metal::float4(metal::max(_e2.xyz, metal::float3(0.0)), 1.0) };
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
  vs_hairInput varyings_4 [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
) {
    const WeftVertexInput in_2 = { varyings_4.position, varyings_4.normal, varyings_4.tangent_1, varyings_4.uv0_2 };
    WeftHair h = {};
    float scale = 0.0;
    WeftVaryings _e1 = weft_forward_vertex(in_2, weft_frame, weft_object);
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
    const auto _tmp_2 = HairVaryings {_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, {}, metal::float4(_e34, _e36, _e39, _e40), metal::float4(_e43, _e45), metal::float4(_e48, _e51), metal::float4(_e54, _e57), metal::float4(_e60, _e63), metal::float4(_e66.yzw, _e69), metal::float4(metal::cos(a_5), metal::sin(a_5), _e74, _e78)};
    return vs_hairOutput { _tmp_2.clip_position, _tmp_2.world_position, _tmp_2.world_normal, _tmp_2.world_tangent, _tmp_2.uv0_, _tmp_2.fibre, _tmp_2.sin2k, _tmp_2.cos2k, _tmp_2.mp_norm, _tmp_2.inv_v, _tmp_2.trt, _tmp_2.jitter };
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
    metal::float4 member_5 [[color(0)]];
};
fragment fs_mainOutput fs_main(
  fs_mainInput varyings_5 [[stage_in]]
, metal::float4 clip_position [[position]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(0)]]
, metal::texture2d<float, metal::access::sample> jitter_map [[texture(1)]]
, metal::texture2d<float, metal::access::sample> uv_rotate_mask [[texture(2)]]
) {
    const HairVaryings in_3 = { clip_position, varyings_5.world_position_2, varyings_5.world_normal_1, varyings_5.world_tangent, varyings_5.uv0_2, {}, varyings_5.fibre, varyings_5.sin2k, varyings_5.cos2k, varyings_5.mp_norm, varyings_5.inv_v, varyings_5.trt, varyings_5.jitter };
    metal::float3 color = {};
    WeftHairLobes lobes = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = weft_transform_uv(in_3.uv0_, _e4);
    metal::float4 _e8 = material.base_color;
    metal::float4 _e11 = base_map.sample(material_sampler, _e5);
    metal::float4 base_rgba = _e8 * _e11;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float alpha = metal::saturate(base_rgba.w);
    WeftSurface _e19 = weft_surface(in_3.world_position, in_3.world_normal, weft_frame);
    metal::float3 v_3 = _e19.v;
    metal::float3 n_3 = _e19.n;
    metal::float3x3 _e23 = weft_tangent_frame(n_3, in_3.world_tangent);
    metal::float3 _e25 = hair_strand(_e23, in_3.uv0_, material);
    float _e31 = hair_jitter(in_3.uv0_, in_3.jitter.xy, in_3.jitter.w, material, material_sampler, jitter_map, uv_rotate_mask);
    metal::float3 _e32 = weft_main_light_direction(weft_frame);
    metal::float3 _e33 = weft_main_light_radiance(weft_frame);
    metal::float3 _e34 = weft_sh_irradiance(n_3, weft_frame);
    float n_dot_l = metal::dot(n_3, _e32);
    {
        metal::float3 _e39 = weft_safe_normalize(_e25 + (_e31 * n_3), _e25);
        metal::float3 _e42 = weft_hair_sigma_a_scaled(base, in_3.fibre.w);
        WeftHair _e43 = hair_from_varyings(in_3, _e42);
        WeftHairAngles _e44 = weft_hair_angles(_e39, v_3, _e32);
        {
            WeftHairLobes _e47 = weft_hair_mean(_e43, _e44, HAIR_REFERENCE_CELLS);
            lobes = _e47;
        }
        float body = metal::smoothstep(-0.25, HAIR_TERMINATOR, n_dot_l);
        metal::float3 _e54 = lobes.back;
        metal::float3 multiple = base * (metal::float3(1.0) - _e54);
        metal::float3 _e58 = lobes.s;
        metal::float3 direct = (_e58 * body) + (multiple * (WEFT_INV_PI * metal::saturate(n_dot_l)));
        metal::float3 _e67 = lobes.back;
        color = (direct * _e33) + (_e34 * (multiple + _e67));
    }
    metal::float3 _e71 = color;
    metal::float3 radiance = metal::clamp(_e71, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
