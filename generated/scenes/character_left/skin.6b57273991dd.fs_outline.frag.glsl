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
struct WeftOutlineVertex {
    vec3 position;
    vec3 normal;
};
struct WeftOutlineVaryings {
    vec4 clip_position;
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
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const vec3 skin_lut_shape = vec3(4.0, 10.0, 20.0);
const float skin_lut_ring = 3.1415927;
const vec3 seed_lut_shape = vec3(4.0, 10.0, 20.0);
const float seed_lut_ring = 1.5707964;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;

layout(location = 0) out vec4 _fs2p_location0;

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

vec3 weft_safe_normalize_k3_(vec3 v_3) {
    float len2_2 = dot(v_3, v_3);
    return ((len2_2 > 1e-20) ? (v_3 * inversesqrt(max(len2_2, 1e-20))) : vec3(0.0));
}

vec2 weft_transform_uv_k4_(vec2 uv_1) {
    return (uv_1 + vec2(0.0, 0.0));
}

vec3 weft_env_brdf_from_lut_k6_(vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((vec3(0.028) * sb.x) + vec3(sb.y));
}

float weft_d_ggx_nh_k10_(vec3 n_3, vec3 h) {
    float noh = clamp(dot(n_3, h), 0.0, 1.0);
    vec3 nxh = cross(n_3, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * 0.01977539));
    return (0.01977539 / (WEFT_PI * max((d * d), 1e-30)));
}

float weft_v_smith_ggx_correlated_k11_(float n_dot_v_1, float n_dot_l) {
    float _e6 = weft_clamp_cos(n_dot_v_1);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * 0.9802246) + 0.01977539)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * 0.9802246) + 0.01977539)));
    return (0.5 / (lv + ll));
}

float weft_d_ggx_nh_k12_(vec3 n_4, vec3 h_1) {
    float noh_1 = clamp(dot(n_4, h_1), 0.0, 1.0);
    vec3 nxh_1 = cross(n_4, h_1);
    float d_1 = (dot(nxh_1, nxh_1) + ((noh_1 * noh_1) * 0.17850621));
    return (0.17850621 / (WEFT_PI * max((d_1 * d_1), 1e-30)));
}

float weft_v_smith_ggx_correlated_k13_(float n_dot_v_2, float n_dot_l_1) {
    float _e6 = weft_clamp_cos(n_dot_v_2);
    float _e7 = weft_clamp_cos(n_dot_l_1);
    float lv_1 = (_e7 * sqrt((((_e6 * _e6) * 0.8214938) + 0.17850621)));
    float ll_1 = (_e6 * sqrt((((_e7 * _e7) * 0.8214938) + 0.17850621)));
    return (0.5 / (lv_1 + ll_1));
}

vec3 weft_f_schlick_k14_(float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (vec3(0.028) + (vec3(0.972, 0.972, 0.972) * _e5));
}

float skin_dual_ggx_k7_(vec3 n_5, vec3 h_2, float n_dot_v_3, float n_dot_l_2, float v_dot_h_1) {
    float _e10 = weft_d_ggx_nh_k10_(n_5, h_2);
    float _e11 = weft_v_smith_ggx_correlated_k11_(n_dot_v_3, n_dot_l_2);
    float lobe0_ = (_e10 * _e11);
    float _e13 = weft_d_ggx_nh_k12_(n_5, h_2);
    float _e14 = weft_v_smith_ggx_correlated_k13_(n_dot_v_3, n_dot_l_2);
    float lobe1_ = (_e13 * _e14);
    vec3 _e16 = weft_f_schlick_k14_(v_dot_h_1);
    float f = _e16.x;
    return (mix(lobe0_, lobe1_, 0.15) * f);
}

void main() {
    _fs2p_location0 = vec4(vec3(0.0, 0.0, 0.0), 1.0);
    return;
}

