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
    float face_soft_shadow;
    float curvature_factor;
    float dark_bound;
    float bright_bound;
    float roughness;
    float specular;
    float lobe_weight;
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

layout(std140, binding = 1) uniform WeftMaterial_block_0Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(location = 0) out vec4 _fs2p_location0;

float weft_clamp_cos(float c) {
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
}

vec3 weft_env_brdf_from_lut(vec3 f0_, vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((f0_ * sb.x) + vec3(sb.y));
}

vec2 weft_transform_uv(vec2 uv_1, vec4 st) {
    return ((uv_1 * st.xy) + st.zw);
}

float skin_seed_specular(vec3 n_2, vec3 l, vec3 h, float roughness_3, float mask, float lobe_weight) {
    float n_dot_h = clamp(dot(n_2, h), 0.0, 1.0);
    float l_dot_h = clamp(dot(l, h), 0.0, 1.0);
    float r2_ = (roughness_3 * roughness_3);
    float normalization = ((roughness_3 * 4.0) + 2.0);
    float d = (((n_dot_h * n_dot_h) * (r2_ - 1.0)) + 1.00001);
    float nl = clamp(dot(n_2, l), 0.0, 1.0);
    float s_ao = mix(0.100112915, 1.0, clamp((-0.3 + (nl * nl)), 0.0, 1.0));
    float denom = (((d * d) * max(0.1, (l_dot_h * l_dot_h))) * normalization);
    float ggx = (r2_ / denom);
    float second = ((((2.0 * r2_) / denom) * lobe_weight) * mask);
    return ((((ggx / 2.0) + second) * s_ao) / WEFT_PI);
}

void main() {
    vec4 _e2 = _group_1_binding_0_fs.outline_color;
    _fs2p_location0 = vec4(max(_e2.xyz, vec3(0.0)), 1.0);
    return;
}

