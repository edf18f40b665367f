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
struct WeftSurface {
    vec3 v;
    vec3 n;
};
struct WeftLightGeometry {
    vec3 l;
    vec3 h;
    float n_dot_v;
    float n_dot_l;
    float n_dot_h;
    float v_dot_h;
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
struct WeftFilmStack {
    float n2_;
    float cos2_;
    vec2 r12_;
    vec3 r23_[2];
    bool total_internal_reflection;
};
struct WeftFilmSeries {
    vec3 dc;
    vec3 first;
    vec3 ratio;
};
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const uint COLOR_MODE_HUE_RING = 0u;
const uint COLOR_MODE_CUSTOM = 1u;
const uint ANISO_COLOR_OFF = 0u;
const uint ANISO_COLOR_VALUE = 1u;
const uint ANISO_COLOR_MAP = 2u;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_FILM_PI = 3.1415927;
const uint WEFT_FILM_SAMPLES = 101u;
const float WEFT_FILM_LAMBDA_MIN = 380.0;
const float WEFT_FILM_LAMBDA_MAX = 780.0;
const float WEFT_FILM_FADE_NM = 30.0;
const mat3x3 WEFT_XYZ_TO_REC709_ = mat3x3(vec3(3.2404542, -0.969266, 0.0556434), vec3(-1.5371385, 1.8760108, -0.2040259), vec3(-0.4985314, 0.041556, 1.0572252));
const vec4 WEFT_FILM_LOBE_WEIGHT_A = vec4(112.289, 17.9875, -22.8564, 14.636);
const vec4 WEFT_FILM_LOBE_WEIGHT_B = vec4(27.8908, 64.448, 5.9984, 99.7587);
const vec4 WEFT_FILM_LOBE_MU_A = vec4(1.64821, 2.23783, 1.51945, 1.95281);
const vec4 WEFT_FILM_LOBE_MU_B = vec4(1.87261, 1.72342, 2.31367, 2.20514);
const vec4 WEFT_FILM_LOBE_SIGMA_A = vec4(0.112563, 0.097781, 0.0710853, 0.142693);
const vec4 WEFT_FILM_LOBE_SIGMA_B = vec4(0.0790523, 0.0996288, 0.0384759, 0.109465);
const vec3 WEFT_FILM_SENSITIVITY_AT_ZERO = vec3(107.41976, 106.97481, 105.7571);

layout(std140, binding = 0) uniform WeftFrame_block_0Vertex { WeftFrame _group_0_binding_0_vs; };

layout(std140, binding = 1) uniform WeftObject_block_1Vertex { WeftObject _group_2_binding_0_vs; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec4 _p2vs_location2;
layout(location = 3) in vec2 _p2vs_location3;
layout(location = 0) smooth out vec3 _vs2fs_location0;
layout(location = 1) smooth out vec3 _vs2fs_location1;
layout(location = 2) smooth out vec4 _vs2fs_location2;
layout(location = 3) smooth out vec2 _vs2fs_location3;

float weft_pow5_(float x) {
    float x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

float weft_clamp_cos(float c) {
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_safe_normalize_k1_(vec3 v_1) {
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * inversesqrt(max(len2_1, 1e-20))) : vec3(0.0, 0.0, 1.0));
}

vec3 weft_main_light_direction() {
    vec4 _e2 = _group_0_binding_0_vs.light_direction;
    vec3 _e4 = weft_safe_normalize_k1_(_e2.xyz);
    return _e4;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_vs.light_color;
    return max(_e2.xyz, vec3(0.0));
}

vec3 weft_sh_irradiance(vec3 n_1) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_vs.sh;
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

vec3 weft_view_direction_k2_(vec3 world_position) {
    vec4 _e4 = _group_0_binding_0_vs.camera_position;
    vec3 _e7 = weft_safe_normalize_k1_((_e4.xyz - world_position));
    return _e7;
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e2 = weft_view_direction_k2_(world_position_1);
    vec3 _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface(_e2, _e3);
}

WeftLightGeometry weft_main_light_geometry(vec3 n_2, vec3 v_2) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_2), n_2);
    float _e6 = weft_clamp_cos(dot(n_2, v_2));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_2, _e2), 0.0, 1.0), clamp(dot(n_2, _e4), 0.0, 1.0), clamp(dot(v_2, _e4), 0.0, 1.0));
}

vec2 weft_fresnel_amplitudes_k3_(float n_t, float cos_i, float cos_t) {
    float rs = ((cos_i - (n_t * cos_t)) / max((cos_i + (n_t * cos_t)), 1e-12));
    float rp = (((n_t * cos_i) - cos_t) / max(((n_t * cos_i) + cos_t), 1e-12));
    return vec2(rs, rp);
}

vec3 weft_film_lobe_orders_k7_(float phase, vec3 k1_, vec3 k2_, vec3 k3_, vec3 k4_) {
    float c1_ = cos((phase * 1.64821));
    float sg = (phase * 0.112563);
    float g1_ = exp(((-0.5 * sg) * sg));
    float c2_ = (((2.0 * c1_) * c1_) - 1.0);
    float c3_ = (((2.0 * c1_) * c2_) - c1_);
    float c4_ = (((2.0 * c2_) * c2_) - 1.0);
    float g2_ = ((g1_ * g1_) * (g1_ * g1_));
    float g3_ = ((g2_ * g2_) * g1_);
    float g4_ = ((g2_ * g2_) * (g2_ * g2_));
    return ((((k1_ * (c1_ * g1_)) + (k2_ * (c2_ * g2_))) + (k3_ * (c3_ * g3_))) + (k4_ * (c4_ * g4_)));
}

vec3 weft_film_lobe_orders_k8_(float phase_1, vec3 k1_1, vec3 k2_1, vec3 k3_1, vec3 k4_1) {
    float c1_1 = cos((phase_1 * 2.23783));
    float sg_1 = (phase_1 * 0.097781);
    float g1_1 = exp(((-0.5 * sg_1) * sg_1));
    float c2_1 = (((2.0 * c1_1) * c1_1) - 1.0);
    float c3_1 = (((2.0 * c1_1) * c2_1) - c1_1);
    float c4_1 = (((2.0 * c2_1) * c2_1) - 1.0);
    float g2_1 = ((g1_1 * g1_1) * (g1_1 * g1_1));
    float g3_1 = ((g2_1 * g2_1) * g1_1);
    float g4_1 = ((g2_1 * g2_1) * (g2_1 * g2_1));
    return ((((k1_1 * (c1_1 * g1_1)) + (k2_1 * (c2_1 * g2_1))) + (k3_1 * (c3_1 * g3_1))) + (k4_1 * (c4_1 * g4_1)));
}

vec3 weft_film_lobe_orders_k9_(float phase_2, vec3 k1_2, vec3 k2_2, vec3 k3_2, vec3 k4_2) {
    float c1_2 = cos((phase_2 * 1.51945));
    float sg_2 = (phase_2 * 0.0710853);
    float g1_2 = exp(((-0.5 * sg_2) * sg_2));
    float c2_2 = (((2.0 * c1_2) * c1_2) - 1.0);
    float c3_2 = (((2.0 * c1_2) * c2_2) - c1_2);
    float c4_2 = (((2.0 * c2_2) * c2_2) - 1.0);
    float g2_2 = ((g1_2 * g1_2) * (g1_2 * g1_2));
    float g3_2 = ((g2_2 * g2_2) * g1_2);
    float g4_2 = ((g2_2 * g2_2) * (g2_2 * g2_2));
    return ((((k1_2 * (c1_2 * g1_2)) + (k2_2 * (c2_2 * g2_2))) + (k3_2 * (c3_2 * g3_2))) + (k4_2 * (c4_2 * g4_2)));
}

vec3 weft_film_lobe_orders_k10_(float phase_3, vec3 k1_3, vec3 k2_3, vec3 k3_3, vec3 k4_3) {
    float c1_3 = cos((phase_3 * 1.95281));
    float sg_3 = (phase_3 * 0.142693);
    float g1_3 = exp(((-0.5 * sg_3) * sg_3));
    float c2_3 = (((2.0 * c1_3) * c1_3) - 1.0);
    float c3_3 = (((2.0 * c1_3) * c2_3) - c1_3);
    float c4_3 = (((2.0 * c2_3) * c2_3) - 1.0);
    float g2_3 = ((g1_3 * g1_3) * (g1_3 * g1_3));
    float g3_3 = ((g2_3 * g2_3) * g1_3);
    float g4_3 = ((g2_3 * g2_3) * (g2_3 * g2_3));
    return ((((k1_3 * (c1_3 * g1_3)) + (k2_3 * (c2_3 * g2_3))) + (k3_3 * (c3_3 * g3_3))) + (k4_3 * (c4_3 * g4_3)));
}

vec3 weft_film_lobe_orders_k11_(float phase_4, vec3 k1_4, vec3 k2_4, vec3 k3_4, vec3 k4_4) {
    float c1_4 = cos((phase_4 * 1.87261));
    float sg_4 = (phase_4 * 0.0790523);
    float g1_4 = exp(((-0.5 * sg_4) * sg_4));
    float c2_4 = (((2.0 * c1_4) * c1_4) - 1.0);
    float c3_4 = (((2.0 * c1_4) * c2_4) - c1_4);
    float c4_4 = (((2.0 * c2_4) * c2_4) - 1.0);
    float g2_4 = ((g1_4 * g1_4) * (g1_4 * g1_4));
    float g3_4 = ((g2_4 * g2_4) * g1_4);
    float g4_4 = ((g2_4 * g2_4) * (g2_4 * g2_4));
    return ((((k1_4 * (c1_4 * g1_4)) + (k2_4 * (c2_4 * g2_4))) + (k3_4 * (c3_4 * g3_4))) + (k4_4 * (c4_4 * g4_4)));
}

vec3 weft_film_lobe_orders_k12_(float phase_5, vec3 k1_5, vec3 k2_5, vec3 k3_5, vec3 k4_5) {
    float c1_5 = cos((phase_5 * 1.72342));
    float sg_5 = (phase_5 * 0.0996288);
    float g1_5 = exp(((-0.5 * sg_5) * sg_5));
    float c2_5 = (((2.0 * c1_5) * c1_5) - 1.0);
    float c3_5 = (((2.0 * c1_5) * c2_5) - c1_5);
    float c4_5 = (((2.0 * c2_5) * c2_5) - 1.0);
    float g2_5 = ((g1_5 * g1_5) * (g1_5 * g1_5));
    float g3_5 = ((g2_5 * g2_5) * g1_5);
    float g4_5 = ((g2_5 * g2_5) * (g2_5 * g2_5));
    return ((((k1_5 * (c1_5 * g1_5)) + (k2_5 * (c2_5 * g2_5))) + (k3_5 * (c3_5 * g3_5))) + (k4_5 * (c4_5 * g4_5)));
}

vec3 weft_film_lobe_orders_k13_(float phase_6, vec3 k1_6, vec3 k2_6, vec3 k3_6, vec3 k4_6) {
    float c1_6 = cos((phase_6 * 2.31367));
    float sg_6 = (phase_6 * 0.0384759);
    float g1_6 = exp(((-0.5 * sg_6) * sg_6));
    float c2_6 = (((2.0 * c1_6) * c1_6) - 1.0);
    float c3_6 = (((2.0 * c1_6) * c2_6) - c1_6);
    float c4_6 = (((2.0 * c2_6) * c2_6) - 1.0);
    float g2_6 = ((g1_6 * g1_6) * (g1_6 * g1_6));
    float g3_6 = ((g2_6 * g2_6) * g1_6);
    float g4_6 = ((g2_6 * g2_6) * (g2_6 * g2_6));
    return ((((k1_6 * (c1_6 * g1_6)) + (k2_6 * (c2_6 * g2_6))) + (k3_6 * (c3_6 * g3_6))) + (k4_6 * (c4_6 * g4_6)));
}

vec3 weft_film_lobe_orders_k14_(float phase_7, vec3 k1_7, vec3 k2_7, vec3 k3_7, vec3 k4_7) {
    float c1_7 = cos((phase_7 * 2.20514));
    float sg_7 = (phase_7 * 0.109465);
    float g1_7 = exp(((-0.5 * sg_7) * sg_7));
    float c2_7 = (((2.0 * c1_7) * c1_7) - 1.0);
    float c3_7 = (((2.0 * c1_7) * c2_7) - c1_7);
    float c4_7 = (((2.0 * c2_7) * c2_7) - 1.0);
    float g2_7 = ((g1_7 * g1_7) * (g1_7 * g1_7));
    float g3_7 = ((g2_7 * g2_7) * g1_7);
    float g4_7 = ((g2_7 * g2_7) * (g2_7 * g2_7));
    return ((((k1_7 * (c1_7 * g1_7)) + (k2_7 * (c2_7 * g2_7))) + (k3_7 * (c3_7 * g3_7))) + (k4_7 * (c4_7 * g4_7)));
}

vec3 weft_film_orders(float opd_nm, WeftFilmSeries s, WeftFilmSeries p) {
    vec3 sum = vec3(0.0);
    float phase_8 = ((6.2831855 * opd_nm) * 0.001);
    vec3 k1_8 = ((s.first * s.ratio) + (p.first * p.ratio));
    vec3 k2_8 = (((s.first * s.ratio) * s.ratio) + ((p.first * p.ratio) * p.ratio));
    vec3 k3_8 = ((((s.first * s.ratio) * s.ratio) * s.ratio) + (((p.first * p.ratio) * p.ratio) * p.ratio));
    vec3 k4_8 = (((s.first * (s.ratio * s.ratio)) * (s.ratio * s.ratio)) + ((p.first * (p.ratio * p.ratio)) * (p.ratio * p.ratio)));
    vec3 _e65 = weft_film_lobe_orders_k7_(phase_8, k1_8, k2_8, k3_8, k4_8);
    sum = (vec3(2.7790883, -1.0780041, 0.0651115) * _e65);
    vec3 _e68 = sum;
    vec3 _e70 = weft_film_lobe_orders_k8_(phase_8, k1_8, k2_8, k3_8, k4_8);
    sum = (_e68 + (vec3(0.4451803, -0.17268476, 0.010430167) * _e70));
    vec3 _e73 = sum;
    vec3 _e75 = weft_film_lobe_orders_k9_(phase_8, k1_8, k2_8, k3_8, k4_8);
    sum = (_e73 + (vec3(-0.56568277, 0.2194275, -0.013253431) * _e75));
    vec3 _e78 = sum;
    vec3 _e80 = weft_film_lobe_orders_k10_(phase_8, k1_8, k2_8, k3_8, k4_8);
    sum = (_e78 + (vec3(-0.17182827, 0.27195558, -0.031118203) * _e80));
    vec3 _e83 = sum;
    vec3 _e85 = weft_film_lobe_orders_k11_(phase_8, k1_8, k2_8, k3_8, k4_8);
    sum = (_e83 + (vec3(-0.32744113, 0.5182467, -0.059299782) * _e85));
    vec3 _e88 = sum;
    vec3 _e90 = weft_film_lobe_orders_k12_(phase_8, k1_8, k2_8, k3_8, k4_8);
    sum = (_e88 + (vec3(-0.7566267, 1.1975262, -0.13702555) * _e90));
    vec3 _e93 = sum;
    vec3 _e95 = weft_film_lobe_orders_k13_(phase_8, k1_8, k2_8, k3_8, k4_8);
    sum = (_e93 + (vec3(-0.022839531, 0.0024689338, 0.06608605) * _e95));
    vec3 _e98 = sum;
    vec3 _e100 = weft_film_lobe_orders_k14_(phase_8, k1_8, k2_8, k3_8, k4_8);
    sum = (_e98 + (vec3(-0.3798416, 0.041060552, 1.0990694) * _e100));
    vec3 _e103 = sum;
    return (2.0 * _e103);
}

WeftFilmSeries weft_film_series(float r12_, vec3 r23_) {
    float big_r12_ = (r12_ * r12_);
    float t121_ = (1.0 - big_r12_);
    vec3 big_r23_ = (r23_ * r23_);
    vec3 big_r123_ = min((big_r12_ * big_r23_), vec3(0.9999));
    vec3 rs_1 = (((t121_ * t121_) * big_r23_) / (vec3(1.0) - big_r123_));
    vec3 ratio = clamp((-(r12_) * r23_), vec3(-0.99995), vec3(0.99995));
    return WeftFilmSeries((vec3(big_r12_) + rs_1), (rs_1 - vec3(t121_)), ratio);
}

vec3 weft_safe_normalize_k15_(vec3 v_3) {
    float len2_2 = dot(v_3, v_3);
    return ((len2_2 > 1e-20) ? (v_3 * inversesqrt(max(len2_2, 1e-20))) : vec3(0.0));
}

float weft_film_ior_k29_() {
    return mix(1.0, 1.8, smoothstep(0.0, WEFT_FILM_FADE_NM, 420.0));
}

float weft_v_smith_ggx_correlated_k19_(float n_dot_v_1, float n_dot_l) {
    float _e6 = weft_clamp_cos(n_dot_v_1);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * 0.9984) + 0.0016000002)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * 0.9984) + 0.0016000002)));
    return (0.5 / (lv + ll));
}

float weft_d_ggx_nh_k20_(vec3 n_3, vec3 h) {
    float noh = clamp(dot(n_3, h), 0.0, 1.0);
    vec3 nxh = cross(n_3, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * 0.0016000002));
    return (0.0016000002 / (WEFT_PI * max((d * d), 1e-30)));
}

float weft_specular_mip_k24_() {
    float _e5 = _group_0_binding_0_vs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.312 * max_mip);
}

vec3 weft_f_schlick_k25_(float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (vec3(0.8999996, 0.8999996, 0.8999996) + (vec3(0.10000038, 0.10000038, 0.10000038) * _e5));
}

vec3 weft_env_brdf_from_lut_k26_(vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((vec3(0.8999996, 0.8999996, 0.8999996) * sb.x) + vec3(sb.y));
}

vec3[2] weft_film_base_amplitudes_k32_(float n2_, float cos2_, float sin1_sq) {
    vec3 cos3_ = sqrt(max((vec3(1.0) - (vec3(sin1_sq) / vec3(1441.9869, 1441.9869, 1441.9869))), vec3(0.0)));
    vec3 s_1 = ((vec3((n2_ * cos2_)) - (vec3(37.973503, 37.973503, 37.973503) * cos3_)) / max((vec3((n2_ * cos2_)) + (vec3(37.973503, 37.973503, 37.973503) * cos3_)), vec3(1e-12)));
    vec3 p_1 = (((vec3(37.973503, 37.973503, 37.973503) * cos2_) - (vec3(n2_) * cos3_)) / max(((vec3(37.973503, 37.973503, 37.973503) * cos2_) + (vec3(n2_) * cos3_)), vec3(1e-12)));
    return vec3[2](s_1, p_1);
}

WeftFilmStack weft_film_stack_k30_(float cos_theta1_) {
    float cos1_ = clamp(cos_theta1_, 0.0, 1.0);
    float sin1_sq_1 = (1.0 - (cos1_ * cos1_));
    float _e10 = weft_film_ior_k29_();
    float cos2_sq = (1.0 - (sin1_sq_1 / (_e10 * _e10)));
    if ((cos2_sq <= 0.0)) {
        return WeftFilmStack(_e10, 0.0, vec2(1.0), vec3[2](vec3(1.0), vec3(1.0)), true);
    }
    float cos2_1 = sqrt(cos2_sq);
    vec2 _e23 = weft_fresnel_amplitudes_k3_(_e10, cos1_, cos2_1);
    vec3 _e24[2] = weft_film_base_amplitudes_k32_(_e10, cos2_1, sin1_sq_1);
    return WeftFilmStack(_e10, cos2_1, _e23, _e24, false);
}

vec3 weft_film_fourier_layers_k27_(float cos_theta1_1) {
    WeftFilmStack _e6 = weft_film_stack_k30_(cos_theta1_1);
    if (_e6.total_internal_reflection) {
        return vec3(1.0);
    }
    WeftFilmSeries _e13 = weft_film_series(_e6.r12_.x, _e6.r23_[0]);
    WeftFilmSeries _e18 = weft_film_series(_e6.r12_.y, _e6.r23_[1]);
    float path = ((2.0 * _e6.n2_) * _e6.cos2_);
    vec3 _e29 = weft_film_orders((path * 420.0), _e13, _e18);
    vec3 r1_ = ((_e13.dc + _e18.dc) + _e29);
    vec3 _e36 = weft_film_orders((path * 420.0), _e13, _e18);
    vec3 r2_ = ((_e13.dc + _e18.dc) + _e36);
    return clamp((0.25 * (r1_ + r2_)), vec3(0.0), vec3(1.0));
}

void main() {
    WeftVertexInput in_ = WeftVertexInput(_p2vs_location0, _p2vs_location1, _p2vs_location2, _p2vs_location3);
    WeftVaryings out_ = WeftVaryings(vec4(0.0), vec3(0.0), vec3(0.0), vec4(0.0), vec2(0.0));
    mat4x4 model = _group_2_binding_0_vs.model;
    mat3x3 model3_ = mat3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    mat4x4 nm = _group_2_binding_0_vs.normal_matrix;
    mat3x3 normal3_ = mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    vec4 world = (model * vec4(in_.position, 1.0));
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    mat4x4 _e43 = _group_0_binding_0_vs.view_proj;
    out_.clip_position = (_e43 * vec4(world.xyz, 1.0));
    out_.world_position = world.xyz;
    vec3 _e53 = weft_safe_normalize_k15_((normal3_ * in_.normal));
    out_.world_normal = _e53;
    vec3 _e58 = weft_safe_normalize_k15_((model3_ * in_.tangent.xyz));
    out_.world_tangent = vec4(_e58, bitangent_sign);
    out_.uv0_ = in_.uv0_;
    WeftVaryings _e62 = out_;
    gl_Position = _e62.clip_position;
    _vs2fs_location0 = _e62.world_position;
    _vs2fs_location1 = _e62.world_normal;
    _vs2fs_location2 = _e62.world_tangent;
    _vs2fs_location3 = _e62.uv0_;
    gl_Position.yz = vec2(-gl_Position.y, gl_Position.z * 2.0 - gl_Position.w);
    return;
}

