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
    float normal_strength;
    float roughness;
    float specular;
    float curvature_factor;
    float dark_bound;
    float bright_bound;
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

layout(std140, binding = 1) uniform WeftMaterial_block_0Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(location = 0) out vec4 _fs2p_location0;

float weft_clamp_cos(float c) {
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_any_perpendicular(vec3 n_1) {
    float s = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return vec3((1.0 + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
}

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
}

vec3 weft_env_brdf_from_lut(vec3 f0_, vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((f0_ * sb.x) + vec3(sb.y));
}

mat3x3 weft_tangent_frame(vec3 n_4, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_4 * dot(n_4, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_4);
    vec3 t = (ok ? (t_proj * inversesqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_4, t) * s_1);
    return mat3x3(t, b_1, n_4);
}

vec3 weft_unpack_normal(vec3 texel, float strength) {
    vec3 v_2 = ((texel * 2.0) - vec3(1.0));
    return vec3((v_2.xy * strength), max(v_2.z, 0.001));
}

vec3 weft_normal_from_tangent_space(mat3x3 frame, vec3 n_ts) {
    vec3 _e4 = weft_safe_normalize((frame * n_ts), frame[2]);
    return _e4;
}

vec3 weft_mapped_normal(vec3 n_5, vec4 tangent_1, vec3 texel_1, float strength_1) {
    mat3x3 _e4 = weft_tangent_frame(n_5, tangent_1);
    vec3 _e5 = weft_unpack_normal(texel_1, strength_1);
    vec3 _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
}

vec2 weft_transform_uv(vec2 uv_1, vec4 st) {
    return ((uv_1 * st.xy) + st.zw);
}

float skin_seed_specular(vec3 n_6, vec3 l, vec3 h, float roughness_3, float mask, float lobe_weight) {
    float n_dot_h = clamp(dot(n_6, h), 0.0, 1.0);
    float l_dot_h = clamp(dot(l, h), 0.0, 1.0);
    float r2_ = (roughness_3 * roughness_3);
    float normalization = ((roughness_3 * 4.0) + 2.0);
    float d = (((n_dot_h * n_dot_h) * (r2_ - 1.0)) + 1.00001);
    float nl = clamp(dot(n_6, l), 0.0, 1.0);
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

