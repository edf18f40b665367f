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
    float metallic;
    float smoothness;
    vec4 base_map_st;
    float normal_strength;
    float occlusion_strength;
    vec4 scatter_color;
    float scatter_scale;
    vec4 outline_color;
    float outline_width;
    float outline_max_distance;
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
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_SHEEN_MIN_ROUGHNESS = 0.07;

layout(std140, binding = 1) uniform WeftMaterial_block_0Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(location = 0) out vec4 _fs2p_location0;

float weft_pow4_(float x) {
    float x2_ = (x * x);
    return (x2_ * x2_);
}

float weft_pow5_(float x_1) {
    float x2_1 = (x_1 * x_1);
    return ((x2_1 * x2_1) * x_1);
}

float weft_clamp_cos(float c) {
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

float weft_clamp_roughness(float roughness) {
    return clamp(roughness, WEFT_MIN_ROUGHNESS, 1.0);
}

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
}

float weft_v_schlick_ggx(float n_dot_v, float n_dot_l, float roughness_1) {
    float _e3 = weft_clamp_roughness(roughness_1);
    float a = (_e3 * _e3);
    float k = (((a + 1.0) * (a + 1.0)) * 0.125);
    float gv = ((clamp(n_dot_v, 0.0, 1.0) * (1.0 - k)) + k);
    float gl = ((clamp(n_dot_l, 0.0, 1.0) * (1.0 - k)) + k);
    return (0.25 / (gv * gl));
}

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

float weft_fabric_d(float n_dot_h) {
    float x_2 = (1.0 - clamp(n_dot_h, 0.0, 1.0));
    return (((0.96 * x_2) * x_2) + 0.057);
}

float weft_fabric_scatter_fresnel_lerp(float n_dot_v_1, float scale) {
    float x_3 = (1.0 - clamp(n_dot_v_1, 0.0, 1.0));
    float _e5 = weft_pow4_(x_3);
    return mix(_e5, (0.4 * x_3), clamp(scale, 0.0, 1.0));
}

vec3 weft_fabric_scatter(vec3 scatter_color, float n_dot_l_1, float n_dot_v_2, float scale_1) {
    float wrap = ((clamp(n_dot_l_1, 0.0, 1.0) * 0.5) + 0.5);
    float _e12 = weft_fabric_scatter_fresnel_lerp(n_dot_v_2, scale_1);
    return (max(scatter_color, vec3(0.0)) * (wrap * _e12));
}

void main() {
    vec4 _e2 = _group_1_binding_0_fs.outline_color;
    _fs2p_location0 = vec4(max(_e2.xyz, vec3(0.0)), 1.0);
    return;
}

