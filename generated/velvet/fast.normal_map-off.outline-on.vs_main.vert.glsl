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

layout(std140, binding = 0) uniform WeftFrame_block_0Vertex { WeftFrame _group_0_binding_0_vs; };

layout(std140, binding = 2) uniform WeftObject_block_1Vertex { WeftObject _group_2_binding_0_vs; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec4 _p2vs_location2;
layout(location = 3) in vec2 _p2vs_location3;
layout(location = 0) smooth out vec3 _vs2fs_location0;
layout(location = 1) smooth out vec3 _vs2fs_location1;
layout(location = 2) smooth out vec4 _vs2fs_location2;
layout(location = 3) smooth out vec2 _vs2fs_location3;

float weft_max3_(vec3 v) {
    return max(v.x, max(v.y, v.z));
}

float weft_clamp_cos(float c) {
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

vec3 weft_safe_normalize(vec3 v_1, vec3 fallback) {
    float len2_ = dot(v_1, v_1);
    return ((len2_ > 1e-20) ? (v_1 * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
}

vec3 weft_main_light_direction() {
    vec4 _e2 = _group_0_binding_0_vs.light_direction;
    vec3 _e8 = weft_safe_normalize(_e2.xyz, vec3(0.0, 0.0, 1.0));
    return _e8;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_vs.light_color;
    return max(_e2.xyz, vec3(0.0));
}

vec3 weft_view_direction(vec3 world_position, vec3 fallback_1) {
    vec4 _e4 = _group_0_binding_0_vs.camera_position;
    vec3 _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
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

float weft_specular_mip(float roughness) {
    float r_2 = clamp(roughness, 0.0, 1.0);
    float _e5 = _group_0_binding_0_vs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r_2 * (1.7 - (0.7 * r_2))) * max_mip);
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e6 = weft_view_direction(world_position_1, vec3(0.0, 0.0, 1.0));
    vec3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

WeftLightGeometry weft_main_light_geometry(vec3 n_2, vec3 v_2) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_2), n_2);
    float _e6 = weft_clamp_cos(dot(n_2, v_2));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_2, _e2), 0.0, 1.0), clamp(dot(n_2, _e4), 0.0, 1.0), clamp(dot(v_2, _e4), 0.0, 1.0));
}

WeftVaryings weft_forward_vertex(WeftVertexInput in_3) {
    WeftVaryings out_1 = WeftVaryings(vec4(0.0), vec3(0.0), vec3(0.0), vec4(0.0), vec2(0.0));
    mat4x4 model = _group_2_binding_0_vs.model;
    mat3x3 model3_ = mat3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    mat4x4 nm = _group_2_binding_0_vs.normal_matrix;
    mat3x3 normal3_ = mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    vec4 world = (model * vec4(in_3.position, 1.0));
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_3.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    mat4x4 _e43 = _group_0_binding_0_vs.view_proj;
    out_1.clip_position = (_e43 * vec4(world.xyz, 1.0));
    out_1.world_position = world.xyz;
    vec3 _e55 = weft_safe_normalize((normal3_ * in_3.normal), vec3(0.0));
    out_1.world_normal = _e55;
    vec3 _e62 = weft_safe_normalize((model3_ * in_3.tangent.xyz), vec3(0.0));
    out_1.world_tangent = vec4(_e62, bitangent_sign);
    out_1.uv0_ = in_3.uv0_;
    WeftVaryings _e66 = out_1;
    return _e66;
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

float weft_sheen_clamp_roughness(float sheen_roughness) {
    return clamp(sheen_roughness, WEFT_SHEEN_MIN_ROUGHNESS, 1.0);
}

float weft_d_charlie(float n_dot_h, float sheen_roughness_1) {
    float _e2 = weft_sheen_clamp_roughness(sheen_roughness_1);
    float inv_r = (1.0 / _e2);
    float noh = clamp(n_dot_h, 0.0, 1.0);
    float sin2_ = max(((1.0 - noh) * (1.0 + noh)), 0.0);
    return (((2.0 + inv_r) * pow(sin2_, (0.5 * inv_r))) * 0.15915494);
}

float weft_sheen_l(float x, float r) {
    float t = ((1.0 - r) * (1.0 - r));
    float a = mix(21.5473, 25.3245, t);
    float b = mix(3.82987, 3.32435, t);
    float c_1 = mix(0.19823, 0.16801, t);
    float d = mix(-1.9776, -1.27393, t);
    float e_1 = mix(-4.32054, -4.85967, t);
    return (((a / (1.0 + (b * pow(max(x, 0.0), c_1)))) + (d * x)) + e_1);
}

float weft_sheen_lambda_one_exp(float cos_theta, float r_1) {
    float _e2 = weft_clamp_cos(cos_theta);
    bool low = (_e2 < 0.5);
    float _e8 = weft_sheen_l((low ? _e2 : (1.0 - _e2)), r_1);
    float _e10 = weft_sheen_l(0.5, r_1);
    return exp((low ? _e8 : ((2.0 * _e10) - _e8)));
}

float weft_v_charlie(float n_dot_v, float n_dot_l, float sheen_roughness_2) {
    float _e3 = weft_sheen_clamp_roughness(sheen_roughness_2);
    float _e4 = weft_clamp_cos(n_dot_v);
    float _e5 = weft_clamp_cos(n_dot_l);
    float _e6 = weft_sheen_lambda_one_exp(_e4, _e3);
    float _e9 = weft_sheen_lambda_one_exp(_e5, _e3);
    float g_inv = ((1.0 + _e6) + _e9);
    return (1.0 / (((g_inv * 4.0) * _e4) * _e5));
}

vec3 weft_sheen_charlie(vec3 sheen_color, float n_dot_h_1, float n_dot_v_1, float n_dot_l_1, float sheen_roughness_3) {
    float _e5 = weft_d_charlie(n_dot_h_1, sheen_roughness_3);
    float _e6 = weft_v_charlie(n_dot_v_1, n_dot_l_1, sheen_roughness_3);
    float lobe = (_e5 * _e6);
    return (max(sheen_color, vec3(0.0)) * (lobe * clamp(n_dot_l_1, 0.0, 1.0)));
}

float weft_sheen_albedo_scaling_view(vec3 sheen_color_1, float e_v) {
    float _e2 = weft_max3_(sheen_color_1);
    return clamp((1.0 - (clamp(_e2, 0.0, 1.0) * clamp(e_v, 0.0, 1.0))), 0.0, 1.0);
}

void main() {
    WeftVertexInput in_1 = WeftVertexInput(_p2vs_location0, _p2vs_location1, _p2vs_location2, _p2vs_location3);
    WeftVaryings _e1 = weft_forward_vertex(in_1);
    gl_Position = _e1.clip_position;
    _vs2fs_location0 = _e1.world_position;
    _vs2fs_location1 = _e1.world_normal;
    _vs2fs_location2 = _e1.world_tangent;
    _vs2fs_location3 = _e1.uv0_;
    gl_Position.yz = vec2(-gl_Position.y, gl_Position.z * 2.0 - gl_Position.w);
    return;
}

