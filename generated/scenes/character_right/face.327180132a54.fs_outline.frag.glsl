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
struct FaceLight {
    float f_dot_l;
    bool from_right;
};
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const vec3 skin_lut_shape = vec3(4.0, 10.0, 20.0);
const float skin_lut_ring = 3.1415927;
const uint TIER_STYLISED = 0u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;

layout(location = 0) out vec4 _fs2p_location0;

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

vec3 weft_safe_normalize_k4_(vec3 v_4) {
    float len2_3 = dot(v_4, v_4);
    return ((len2_3 > 1e-20) ? (v_4 * inversesqrt(max(len2_3, 1e-20))) : vec3(1.0, 0.0, 0.0));
}

vec2 weft_transform_uv_k5_(vec2 uv_1) {
    return (uv_1 + vec2(0.0, 0.0));
}

float skin_seed_specular_k7_(vec3 n_2, vec3 l_1, vec3 h) {
    float n_dot_h = clamp(dot(n_2, h), 0.0, 1.0);
    float l_dot_h = clamp(dot(l_1, h), 0.0, 1.0);
    float d = (((n_dot_h * n_dot_h) * -0.8704) + 1.00001);
    float nl = clamp(dot(n_2, l_1), 0.0, 1.0);
    float s_ao = mix(0.100112915, 1.0, clamp((-0.3 + (nl * nl)), 0.0, 1.0));
    float denom = (((d * d) * max(0.1, (l_dot_h * l_dot_h))) * 3.44);
    float ggx = (0.1296 / denom);
    float second = ((0.2592 / denom) * 0.15);
    return ((((ggx / 2.0) + second) * s_ao) / WEFT_PI);
}

vec3 weft_env_brdf_from_lut_k10_(vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((vec3(0.028) * sb.x) + vec3(sb.y));
}

void main() {
    _fs2p_location0 = vec4(vec3(0.0, 0.0, 0.0), 1.0);
    return;
}

