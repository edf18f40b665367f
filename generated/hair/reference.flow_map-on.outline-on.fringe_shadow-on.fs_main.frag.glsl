#version 450 core
struct WeftFrame {
    mat4x4 view_proj;
    mat4x4 view;
    vec4 camera_position;
    vec4 light_direction;
    vec4 light_color;
    vec4 sh[9];
    vec4 params;
    vec4 viewport;
};
struct WeftObject {
    mat4x4 model;
    mat4x4 normal_matrix;
};
struct WeftMaterial {
    vec4 base_color;
    vec4 base_map_st;
    uint strand_along_tangent;
    vec4 jitter_map_st;
    float jitter_strength;
    float anisotropic_direction;
    float strand_noise;
    float strand_density;
    vec4 primary_color;
    float primary_exponent;
    float primary_intensity;
    float primary_shift;
    vec4 secondary_color;
    float secondary_exponent;
    float secondary_intensity;
    float secondary_shift;
    float roughness;
    float azimuthal_roughness;
    float scale_angle;
    float ior;
    vec4 outline_color;
    float outline_width;
    float outline_max_distance;
    vec4 fringe_shadow_color;
    float fringe_shadow_length;
};
struct WeftOutlineVertex {
    vec3 position;
    vec3 normal;
};
struct WeftOutlineVaryings {
    vec4 clip_position;
};
struct WeftFringeShadowVertex {
    vec3 position;
};
struct WeftFringeShadowVaryings {
    vec4 clip_position;
};
struct WeftSurface {
    vec3 v;
    vec3 n;
};
struct WeftVertexInput {
    vec3 position;
    vec3 normal;
    vec4 tangent;
    vec2 uv0_;
};
struct WeftVaryings {
    vec4 clip_position;
    vec3 world_position;
    vec3 world_normal;
    vec4 world_tangent;
    vec2 uv0_;
};
struct WeftHair {
    vec3 sigma_a;
    float eta;
    vec4 v;
    float s;
    vec3 sin2k;
    vec3 cos2k;
    vec3 inv_v;
    vec3 mp_norm;
    vec2 blur;
    float r_floor;
    vec4 trt;
    float trt4_;
    float inv_eta;
};
struct WeftHairAttenuation {
    float a0_;
    vec3 a1_;
    vec3 a2_;
    vec3 a3_;
    float gamma_t;
};
struct WeftHairLobes {
    vec3 s;
    vec3 albedo;
    vec3 back;
};
struct WeftHairAngles {
    vec4 theta;
    float phi;
};
struct HairVaryings {
    vec4 clip_position;
    vec3 world_position;
    vec3 world_normal;
    vec4 world_tangent;
    vec2 uv0_;
    vec4 fibre;
    vec4 sin2k;
    vec4 cos2k;
    vec4 mp_norm;
    vec4 inv_v;
    vec4 trt;
    vec4 jitter;
};
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_HAIR_MIN_BETA_M = 0.05;
const float WEFT_HAIR_MIN_BETA_N = 0.05;
const uint HAIR_REFERENCE_CELLS = 64u;
const float HAIR_TERMINATOR = 0.25;

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 0) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 1) uniform sampler2D _group_1_binding_4_fs;

layout(binding = 2) uniform sampler2D _group_1_binding_5_fs;

layout(binding = 3) uniform sampler2D _group_1_binding_6_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 4) flat in vec4 _vs2fs_location4;
layout(location = 5) flat in vec4 _vs2fs_location5;
layout(location = 6) flat in vec4 _vs2fs_location6;
layout(location = 7) flat in vec4 _vs2fs_location7;
layout(location = 8) flat in vec4 _vs2fs_location8;
layout(location = 9) flat in vec4 _vs2fs_location9;
layout(location = 10) flat in vec4 _vs2fs_location10;
layout(location = 0) out vec4 _fs2p_location0;

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_any_perpendicular(vec3 n) {
    float s_6 = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a_1 = (-1.0 / (s_6 + n.z));
    float b = ((n.x * n.y) * a_1);
    return vec3((1.0 + (((s_6 * n.x) * n.x) * a_1)), (s_6 * b), (-(s_6) * n.x));
}

float weft_f_dielectric(float cos_i, float eta) {
    float c_1 = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c_1 * c_1));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c_1);
    float gpc = max((g + c_1), 1e-7);
    float b_den = max(((c_1 * gmc) + 1.0), 1e-7);
    float b_num = ((c_1 * gpc) - 1.0);
    float inv = (1.0 / (gpc * b_den));
    float f = clamp(((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)), 0.0, 1.0);
    return ((g2_ < 0.0) ? 1.0 : f);
}

vec3 weft_main_light_direction() {
    vec4 _e2 = _group_0_binding_0_fs.light_direction;
    vec3 _e8 = weft_safe_normalize(_e2.xyz, vec3(0.0, 0.0, 1.0));
    return _e8;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_fs.light_color;
    return max(_e2.xyz, vec3(0.0));
}

vec3 weft_view_direction(vec3 world_position, vec3 fallback_1) {
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
    vec3 _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
}

vec3 weft_sh_irradiance(vec3 n_1) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_fs.sh;
    e = (sh[0].xyz * 0.282095);
    vec3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_1.y)));
    vec3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_1.z)));
    vec3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_1.x)));
    vec3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_1.x) * n_1.y)));
    vec3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_1.y) * n_1.z)));
    vec3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0))));
    vec3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_1.x) * n_1.z)));
    vec3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    vec3 _e91 = e;
    return max(_e91, vec3(0.0));
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e6 = weft_view_direction(world_position_1, vec3(0.0, 0.0, 1.0));
    vec3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

mat3x3 weft_tangent_frame(vec3 n_2, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_2);
    vec3 t_1 = (ok ? (t_proj * inversesqrt(max(len2_1, 1e-20))) : _e13);
    float s_7 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_2, t_1) * s_7);
    return mat3x3(t_1, b_1, n_2);
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

float weft_hair_sqr(float x) {
    return (x * x);
}

float weft_hair_safe_sqrt(float x_1) {
    return sqrt(max(x_1, 0.0));
}

float weft_hair_variance(float beta_m) {
    float b_2 = clamp(beta_m, WEFT_HAIR_MIN_BETA_M, 1.0);
    float b2_ = (b_2 * b_2);
    float b4_ = (b2_ * b2_);
    float b20_ = ((((b4_ * b4_) * b4_) * b4_) * b4_);
    float _e18 = weft_hair_sqr((((0.726 * b_2) + (0.812 * b2_)) + (3.7 * b20_)));
    return _e18;
}

float weft_hair_logistic_scale(float beta_n) {
    float b_3 = clamp(beta_n, WEFT_HAIR_MIN_BETA_N, 1.0);
    float b2_1 = (b_3 * b_3);
    float b4_1 = (b2_1 * b2_1);
    float b22_ = (((((b4_1 * b4_1) * b4_1) * b4_1) * b4_1) * b2_1);
    return (0.62665707 * (((0.265 * b_3) + (1.194 * b2_1)) + (5.372 * b22_)));
}

vec3 weft_hair_sigma_a_scaled(vec3 c, float scale_1) {
    vec3 l = (log(clamp(c, vec3(0.0001), vec3(1.0))) * scale_1);
    return (l * l);
}

float weft_hair_sigma_a_scale(float beta_n_1) {
    float b_4 = clamp(beta_n_1, WEFT_HAIR_MIN_BETA_N, 1.0);
    float d = (((((5.969 - (0.215 * b_4)) + ((2.532 * b_4) * b_4)) - (10.73 * pow(b_4, 3.0))) + (5.574 * pow(b_4, 4.0))) + (0.245 * pow(b_4, 5.0)));
    return (1.0 / d);
}

WeftHair weft_hair_params(vec3 sigma_a, float eta_1, float beta_m_1, float beta_n_2, float alpha_deg) {
    WeftHair hair = WeftHair(vec3(0.0), 0.0, vec4(0.0), 0.0, vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec2(0.0), 0.0, vec4(0.0), 0.0, 0.0);
    hair.sigma_a = max(sigma_a, vec3(0.0));
    hair.eta = max(eta_1, 1.0001);
    float _e13 = weft_hair_variance(beta_m_1);
    hair.v = vec4(_e13, (0.25 * _e13), (4.0 * _e13), (4.0 * _e13));
    float _e23 = weft_hair_logistic_scale(beta_n_2);
    hair.s = _e23;
    float a_2 = radians(alpha_deg);
    float s0_ = sin(a_2);
    float _e29 = weft_hair_safe_sqrt((1.0 - (s0_ * s0_)));
    float s1_ = ((2.0 * _e29) * s0_);
    float c1_ = ((_e29 * _e29) - (s0_ * s0_));
    float s2_ = ((2.0 * c1_) * s1_);
    float c2_ = ((c1_ * c1_) - (s1_ * s1_));
    hair.sin2k = vec3(s0_, s1_, s2_);
    hair.cos2k = vec3(_e29, c1_, c2_);
    hair.inv_v = (vec3(1.0, 4.0, 0.25) / vec3(_e13));
    float _e55 = hair.inv_v.x;
    float e_trt = exp((-0.5 * _e55));
    float _e60 = weft_hair_sqr((e_trt * e_trt));
    vec3 _e63 = hair.inv_v;
    float _e67 = weft_hair_sqr((_e60 * _e60));
    hair.mp_norm = (_e63 / (vec3(1.0) - vec3(_e60, _e67, e_trt)));
    float _e73 = hair.s;
    float d_1 = (0.8162094 * _e73);
    hair.blur = vec2(sin(d_1), cos(d_1));
    float _e81 = hair.s;
    float _e84 = weft_hair_sqr((0.4534 * _e81));
    hair.r_floor = _e84;
    float sh_1 = hair.s;
    hair.trt = vec4((-9.2609 + (sh_1 * (65.993 - (107.38 * sh_1)))), (72.357 + (sh_1 * (-624.68 + (1069.8 * sh_1)))), (-153.75 + (sh_1 * (1704.7 - (3127.5 * sh_1)))), (-67.745 + (sh_1 * (-1105.8 + (2706.6 * sh_1)))));
    hair.trt4_ = (239.74 - (430.94 * sh_1));
    float _e124 = hair.eta;
    hair.inv_eta = (1.0 / _e124);
    WeftHair _e127 = hair;
    return _e127;
}

float weft_hair_i0_(float x_2) {
    float term = 1.0;
    float sum = 1.0;
    int i = 1;
    float q = ((0.25 * x_2) * x_2);
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e22 = i;
            i = (_e22 + 1);
        }
        loop_init = false;
        int _e10 = i;
        if ((_e10 < 16)) {
        } else {
            break;
        }
        {
            int _e13 = i;
            float k_1 = float(_e13);
            float _e15 = term;
            term = (_e15 * (q / (k_1 * k_1)));
            float _e19 = sum;
            float _e20 = term;
            sum = (_e19 + _e20);
        }
    }
    float _e25 = sum;
    return _e25;
}

float weft_hair_log_i0_(float x_3) {
    if ((x_3 > 12.0)) {
        float r = (1.0 / x_3);
        return ((x_3 - (0.5 * log((6.2831855 * x_3)))) + log((1.0 + (r * (0.125 + (0.0703125 * r))))));
    }
    float _e20 = weft_hair_i0_(x_3);
    return log(_e20);
}

float weft_hair_mp(float cos_i_1, float cos_o, float sin_i, float sin_o, float v_1) {
    float a_3 = ((cos_i_1 * cos_o) / v_1);
    float b_5 = ((sin_i * sin_o) / v_1);
    if ((v_1 <= 0.1)) {
        float _e11 = weft_hair_log_i0_(a_3);
        return exp(((((_e11 - b_5) - (1.0 / v_1)) + 0.6931472) + log((1.0 / (2.0 * v_1)))));
    }
    float _e27 = weft_hair_i0_(a_3);
    return ((exp(-(b_5)) * _e27) / ((sinh((1.0 / v_1)) * 2.0) * v_1));
}

vec4 weft_hair_longitudinal(WeftHair hair_1, float sin_o_1, float cos_o_1, float sin_i_1, float cos_i_2) {
    float sin_r = ((sin_o_1 * hair_1.cos2k.y) - (cos_o_1 * hair_1.sin2k.y));
    float cos_r = abs(((cos_o_1 * hair_1.cos2k.y) + (sin_o_1 * hair_1.sin2k.y)));
    float sin_tt = ((sin_o_1 * hair_1.cos2k.x) + (cos_o_1 * hair_1.sin2k.x));
    float cos_tt = abs(((cos_o_1 * hair_1.cos2k.x) - (sin_o_1 * hair_1.sin2k.x)));
    float sin_trt = ((sin_o_1 * hair_1.cos2k.z) + (cos_o_1 * hair_1.sin2k.z));
    float cos_trt = abs(((cos_o_1 * hair_1.cos2k.z) - (sin_o_1 * hair_1.sin2k.z)));
    float _e52 = weft_hair_mp(cos_i_2, cos_r, sin_i_1, sin_r, hair_1.v.x);
    float _e55 = weft_hair_mp(cos_i_2, cos_tt, sin_i_1, sin_tt, hair_1.v.y);
    float _e58 = weft_hair_mp(cos_i_2, cos_trt, sin_i_1, sin_trt, hair_1.v.z);
    float _e61 = weft_hair_mp(cos_i_2, cos_o_1, sin_i_1, sin_o_1, hair_1.v.w);
    return vec4(_e52, _e55, _e58, _e61);
}

float weft_hair_logistic(float x_4, float s) {
    float e_1 = exp((-(abs(x_4)) / s));
    float _e8 = weft_hair_sqr((1.0 + e_1));
    return (e_1 / (s * _e8));
}

float weft_hair_trimmed_logistic(float x_5, float s_1) {
    float e_2 = exp((-3.1415927 / s_1));
    float _e5 = weft_hair_logistic(x_5, s_1);
    return ((_e5 * (1.0 + e_2)) / (1.0 - e_2));
}

float weft_hair_etap(WeftHair hair_2, float sin_o_2, float cos_o_2) {
    return (sqrt(((hair_2.eta * hair_2.eta) - (sin_o_2 * sin_o_2))) / max(cos_o_2, 0.0001));
}

WeftHairAttenuation weft_hair_attenuation(WeftHair hair_3, float sin_o_3, float cos_o_3, float h_1) {
    WeftHairAttenuation a = WeftHairAttenuation(0.0, vec3(0.0), vec3(0.0), vec3(0.0), 0.0);
    float sin_t = (sin_o_3 / hair_3.eta);
    float _e9 = weft_hair_safe_sqrt((1.0 - (sin_t * sin_t)));
    float _e10 = weft_hair_etap(hair_3, sin_o_3, cos_o_3);
    float sin_gamma_t = clamp((h_1 / _e10), -1.0, 1.0);
    float _e18 = weft_hair_safe_sqrt((1.0 - (sin_gamma_t * sin_gamma_t)));
    vec3 t_2 = exp((-(hair_3.sigma_a) * ((2.0 * _e18) / max(_e9, 0.0001))));
    float _e31 = weft_hair_safe_sqrt((1.0 - (h_1 * h_1)));
    float _e34 = weft_f_dielectric((cos_o_3 * _e31), hair_3.eta);
    a.a0_ = _e34;
    a.a1_ = (((1.0 - _e34) * (1.0 - _e34)) * t_2);
    vec3 _e46 = a.a1_;
    a.a2_ = ((_e46 * t_2) * _e34);
    vec3 _e51 = a.a2_;
    a.a3_ = (((_e51 * t_2) * _e34) / (vec3(1.0) - (t_2 * _e34)));
    a.gamma_t = asin(sin_gamma_t);
    WeftHairAttenuation _e61 = a;
    return _e61;
}

WeftHairAngles weft_hair_angles(vec3 t, vec3 o, vec3 i_1) {
    WeftHairAngles out_3 = WeftHairAngles(vec4(0.0), 0.0);
    float sin_o_4 = clamp(dot(o, t), -1.0, 1.0);
    float sin_i_2 = clamp(dot(i_1, t), -1.0, 1.0);
    float _e16 = weft_hair_safe_sqrt((1.0 - (sin_o_4 * sin_o_4)));
    float _e20 = weft_hair_safe_sqrt((1.0 - (sin_i_2 * sin_i_2)));
    out_3.theta = vec4(sin_o_4, _e16, sin_i_2, _e20);
    vec3 o_perp = (o - (sin_o_4 * t));
    vec3 i_perp = (i_1 - (sin_i_2 * t));
    float len2_2 = (dot(o_perp, o_perp) * dot(i_perp, i_perp));
    float cos_phi = ((len2_2 > 1e-12) ? (dot(o_perp, i_perp) * inversesqrt(max(len2_2, 1e-30))) : 1.0);
    out_3.phi = acos(clamp(cos_phi, -1.0, 1.0));
    WeftHairAngles _e43 = out_3;
    return _e43;
}

float weft_hair_logistic_cdf(float x_6, float s_2) {
    return (1.0 / (1.0 + exp((-(x_6) / s_2))));
}

float weft_hair_trimmed_integral(float lo, float hi, float s_3) {
    float sum_1 = 0.0;
    float _e4 = weft_hair_logistic_cdf(-3.1415927, s_3);
    float _e6 = weft_hair_logistic_cdf(WEFT_PI, s_3);
    float a_4 = clamp(lo, -3.1415927, WEFT_PI);
    float b_6 = clamp(hi, -3.1415927, WEFT_PI);
    float _e13 = weft_hair_logistic_cdf(b_6, s_3);
    float _e14 = weft_hair_logistic_cdf(a_4, s_3);
    sum_1 = (_e13 - _e14);
    if ((hi > WEFT_PI)) {
        float _e19 = sum_1;
        float _e24 = weft_hair_logistic_cdf(min((hi - 6.2831855), WEFT_PI), s_3);
        sum_1 = (_e19 + (_e24 - _e4));
    }
    if ((lo < -3.1415927)) {
        float _e29 = sum_1;
        float _e34 = weft_hair_logistic_cdf(max((lo + 6.2831855), -3.1415927), s_3);
        sum_1 = (_e29 + (_e6 - _e34));
    }
    float _e37 = sum_1;
    return (_e37 / (_e6 - _e4));
}

float weft_hair_np_cell(float d0_, float d1_, float s_4) {
    float mid = (0.5 * (d0_ + d1_));
    float m = (mid - (6.2831855 * roundEven((mid / 6.2831855))));
    float half_ = min((0.5 * abs((d1_ - d0_))), WEFT_PI);
    if ((half_ < 0.0001)) {
        float _e20 = weft_hair_trimmed_logistic(m, s_4);
        return _e20;
    }
    float _e23 = weft_hair_trimmed_integral((m - half_), (m + half_), s_4);
    return (_e23 / (2.0 * half_));
}

WeftHairLobes weft_hair_mean(WeftHair hair_4, WeftHairAngles angles, uint count) {
    vec3 s_5 = vec3(0.0);
    vec3 albedo = vec3(0.0);
    vec3 back = vec3(0.0);
    float weights = 0.0;
    float g0_ = -1.5707964;
    vec3 d0_1 = vec3(0.0);
    uint k = 0u;
    WeftHairLobes out_4 = WeftHairLobes(vec3(0.0), vec3(0.0), vec3(0.0));
    vec4 th = angles.theta;
    vec4 _e8 = weft_hair_longitudinal(hair_4, th.x, th.y, th.z, th.w);
    float _e11 = weft_hair_etap(hair_4, th.x, th.y);
    uint cells = max(count, 1u);
    float step_ = (WEFT_PI / float(cells));
    float _e35 = g0_;
    float _e43 = g0_;
    d0_1 = (vec3(angles.phi) - (((vec3(0.0, 2.0, 4.0) * asin(clamp((sin(_e35) / _e11), -1.0, 1.0))) - vec3((2.0 * _e43))) + vec3(0.0, 3.1415927, 6.2831855)));
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e153 = k;
            k = (_e153 + 1u);
        }
        loop_init_1 = false;
        uint _e58 = k;
        if ((_e58 < cells)) {
        } else {
            break;
        }
        {
            float _e60 = g0_;
            float g1_ = (_e60 + step_);
            float gamma_t1_ = asin(clamp((sin(g1_) / _e11), -1.0, 1.0));
            vec3 d1_1 = (vec3(angles.phi) - (((vec3(0.0, 2.0, 4.0) * gamma_t1_) - vec3((2.0 * g1_))) + vec3(0.0, 3.1415927, 6.2831855)));
            float _e85 = g0_;
            float gm = (_e85 + (0.5 * step_));
            float w = cos(gm);
            WeftHairAttenuation _e93 = weft_hair_attenuation(hair_4, th.x, th.y, sin(gm));
            float _e98 = d0_1.x;
            float _e101 = weft_hair_np_cell(_e98, d1_1.x, hair_4.s);
            float _e107 = d0_1.y;
            float _e110 = weft_hair_np_cell(_e107, d1_1.y, hair_4.s);
            float _e118 = d0_1.z;
            float _e121 = weft_hair_np_cell(_e118, d1_1.z, hair_4.s);
            vec3 lobes_1 = (((vec3(((_e8.x * _e93.a0_) * _e101)) + ((_e8.y * _e93.a1_) * _e110)) + ((_e8.z * _e93.a2_) * _e121)) + ((_e8.w * _e93.a3_) * 0.15915494));
            vec3 _e130 = s_5;
            s_5 = (_e130 + (w * lobes_1));
            vec3 _e133 = albedo;
            albedo = (_e133 + (w * (((vec3(_e93.a0_) + _e93.a1_) + _e93.a2_) + _e93.a3_)));
            vec3 _e144 = back;
            back = (_e144 + (w * (vec3(_e93.a0_) + _e93.a2_)));
            float _e151 = weights;
            weights = (_e151 + w);
            g0_ = g1_;
            d0_1 = d1_1;
        }
    }
    vec3 _e158 = s_5;
    float _e159 = weights;
    out_4.s = (_e158 / vec3(_e159));
    vec3 _e163 = albedo;
    float _e164 = weights;
    out_4.albedo = (_e163 / vec3(_e164));
    vec3 _e168 = back;
    float _e169 = weights;
    out_4.back = (_e168 / vec3(_e169));
    WeftHairLobes _e172 = out_4;
    return _e172;
}

float hair_noise_period(float density) {
    return max(roundEven(density), 1.0);
}

WeftHair hair_from_varyings(HairVaryings in_5, vec3 sigma_a_1) {
    float v_2 = in_5.fibre.z;
    return WeftHair(max(sigma_a_1, vec3(0.0)), in_5.fibre.x, vec4(v_2, (0.25 * v_2), (4.0 * v_2), (4.0 * v_2)), in_5.fibre.y, in_5.sin2k.xyz, in_5.cos2k.xyz, in_5.inv_v.xyz, in_5.mp_norm.xyz, vec2(in_5.cos2k.w, in_5.mp_norm.w), in_5.sin2k.w, vec4(in_5.inv_v.w, in_5.trt.xyz), in_5.trt.w, in_5.jitter.z);
}

vec3 hair_strand(mat3x3 frame, vec2 uv0_) {
    vec2 ts = vec2(0.0);
    uint _e10 = _group_1_binding_0_fs.strand_along_tangent;
    ts = ((_e10 != 0u) ? vec2(1.0, 0.0) : vec2(0.0, 1.0));
    {
        vec4 _e17 = texture(_group_1_binding_4_fs, vec2(uv0_));
        vec2 f_1 = ((_e17.xy * 2.0) - vec2(1.0));
        float len2_3 = dot(f_1, f_1);
        vec2 _e25 = ts;
        ts = ((len2_3 > 0.0001) ? (f_1 * inversesqrt(max(len2_3, 1e-12))) : _e25);
    }
    float _e35 = ts.x;
    float _e39 = ts.y;
    vec3 _e43 = weft_safe_normalize(((frame[0] * _e35) + (frame[1] * _e39)), frame[1]);
    return _e43;
}

float hair_hash(uint x_7) {
    uint state = ((x_7 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (float(((word >> 22u) ^ word)) * 2.3283064e-10);
}

float hair_value_noise(float x_8, float p) {
    float cell = floor(x_8);
    float f_2 = (x_8 - cell);
    float c0_ = (cell - (p * floor((cell / p))));
    float c1_1 = (((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0));
    float _e16 = hair_hash(uint(c0_));
    float _e18 = hair_hash(uint(c1_1));
    return (mix(_e16, _e18, ((f_2 * f_2) * (3.0 - (2.0 * f_2)))) - 0.5);
}

float hair_jitter(vec2 uv0_1, vec2 rotation, float noise_period) {
    vec4 _e5 = texture(_group_1_binding_6_fs, vec2(uv0_1));
    float mask = step(0.8, _e5.x);
    float c_2 = rotation.x;
    float s_8 = rotation.y;
    vec2 rotated = vec2(((c_2 * uv0_1.x) + (s_8 * uv0_1.y)), ((-(s_8) * uv0_1.x) + (c_2 * uv0_1.y)));
    vec4 _e28 = _group_1_binding_0_fs.jitter_map_st;
    vec2 _e29 = weft_transform_uv(((mask > 0.5) ? rotated : uv0_1), _e28);
    vec4 _e32 = texture(_group_1_binding_5_fs, vec2(_e29));
    float j = _e32.x;
    uint _e38 = _group_1_binding_0_fs.strand_along_tangent;
    float across = ((_e38 != 0u) ? _e29.y : _e29.x);
    float _e44 = _group_1_binding_0_fs.strand_density;
    float _e46 = hair_value_noise((across * _e44), noise_period);
    float _e49 = _group_1_binding_0_fs.jitter_strength;
    float _e53 = _group_1_binding_0_fs.strand_noise;
    return ((_e49 * j) + (_e53 * _e46));
}

void main() {
    HairVaryings in_3 = HairVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3, _vs2fs_location4, _vs2fs_location5, _vs2fs_location6, _vs2fs_location7, _vs2fs_location8, _vs2fs_location9, _vs2fs_location10);
    vec3 color = vec3(0.0);
    WeftHairLobes lobes = WeftHairLobes(vec3(0.0), vec3(0.0), vec3(0.0));
    vec4 _e4 = _group_1_binding_0_fs.base_map_st;
    vec2 _e5 = weft_transform_uv(in_3.uv0_, _e4);
    vec4 _e8 = _group_1_binding_0_fs.base_color;
    vec4 _e11 = texture(_group_1_binding_3_fs, vec2(_e5));
    vec4 base_rgba = (_e8 * _e11);
    vec3 base = clamp(base_rgba.xyz, vec3(0.0), vec3(1.0));
    float alpha = clamp(base_rgba.w, 0.0, 1.0);
    WeftSurface _e19 = weft_surface(in_3.world_position, in_3.world_normal);
    vec3 v_3 = _e19.v;
    vec3 n_3 = _e19.n;
    mat3x3 _e23 = weft_tangent_frame(n_3, in_3.world_tangent);
    vec3 _e25 = hair_strand(_e23, in_3.uv0_);
    float _e31 = hair_jitter(in_3.uv0_, in_3.jitter.xy, in_3.jitter.w);
    vec3 _e32 = weft_main_light_direction();
    vec3 _e33 = weft_main_light_radiance();
    vec3 _e34 = weft_sh_irradiance(n_3);
    float n_dot_l = dot(n_3, _e32);
    {
        vec3 _e39 = weft_safe_normalize((_e25 + (_e31 * n_3)), _e25);
        vec3 _e42 = weft_hair_sigma_a_scaled(base, in_3.fibre.w);
        WeftHair _e43 = hair_from_varyings(in_3, _e42);
        WeftHairAngles _e44 = weft_hair_angles(_e39, v_3, _e32);
        {
            WeftHairLobes _e47 = weft_hair_mean(_e43, _e44, HAIR_REFERENCE_CELLS);
            lobes = _e47;
        }
        float body = smoothstep(-0.25, HAIR_TERMINATOR, n_dot_l);
        vec3 _e54 = lobes.back;
        vec3 multiple = (base * (vec3(1.0) - _e54));
        vec3 _e58 = lobes.s;
        vec3 direct = ((_e58 * body) + (multiple * (WEFT_INV_PI * clamp(n_dot_l, 0.0, 1.0))));
        vec3 _e67 = lobes.back;
        color = ((direct * _e33) + (_e34 * (multiple + _e67)));
    }
    vec3 _e71 = color;
    vec3 radiance = clamp(_e71, vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, alpha);
    return;
}

