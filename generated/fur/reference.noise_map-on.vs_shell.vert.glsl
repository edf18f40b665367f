#version 450 core
#extension GL_ARB_shader_draw_parameters : require
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
    float metallic;
    float smoothness;
    vec4 spot_color;
    vec4 noise_map_st;
    vec2 strand_density;
    float fur_length;
    float height_scale;
    float fur_occlusion;
    float cutoff_start;
    float cutoff_end;
    float edge_fade;
    uint tapered_tips;
    int shell_count;
    vec3 force_direction;
    float force_strength;
    float force_map_scale;
    vec4 sheen_color;
    float scatter_scale;
    vec4 strand_color;
    float strand_strength;
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
struct FurInput {
    vec3 position;
    vec3 normal;
    vec2 uv0_;
};
struct FurVaryings {
    vec4 clip_position;
    vec3 world_position;
    vec3 world_normal;
    vec3 strand;
    vec2 uv0_;
    float offset;
    vec4 light_diffuse;
    vec4 light_ambient;
    vec4 light_sheen;
    vec4 light_strand;
    float light_n_dot_v;
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
const float FUR_SEED_SHELLS = 20.0;

layout(std140, binding = 0) uniform WeftFrame_block_0Vertex { WeftFrame _group_0_binding_0_vs; };

layout(std140, binding = 2) uniform WeftObject_block_1Vertex { WeftObject _group_2_binding_0_vs; };

layout(std140, binding = 1) uniform WeftMaterial_block_2Vertex { WeftMaterial _group_1_binding_0_vs; };

layout(binding = 5) uniform sampler2D _group_1_binding_6_vs;

layout(binding = 6) uniform sampler2D _group_1_binding_7_vs;

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 3) in vec2 _p2vs_location3;
layout(location = 0) smooth out vec3 _vs2fs_location0;
layout(location = 1) smooth out vec3 _vs2fs_location1;
layout(location = 2) smooth out vec3 _vs2fs_location2;
layout(location = 3) smooth out vec2 _vs2fs_location3;
layout(location = 4) smooth out float _vs2fs_location4;
layout(location = 5) smooth out vec4 _vs2fs_location5;
layout(location = 6) smooth out vec4 _vs2fs_location6;
layout(location = 7) smooth out vec4 _vs2fs_location7;
layout(location = 8) smooth out vec4 _vs2fs_location8;
layout(location = 9) smooth out float _vs2fs_location9;

float weft_pow5_(float x) {
    float x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

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

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
}

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
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

float weft_sheen_l(float x_1, float r) {
    float t_1 = ((1.0 - r) * (1.0 - r));
    float a = mix(21.5473, 25.3245, t_1);
    float b = mix(3.82987, 3.32435, t_1);
    float c_1 = mix(0.19823, 0.16801, t_1);
    float d = mix(-1.9776, -1.27393, t_1);
    float e_1 = mix(-4.32054, -4.85967, t_1);
    return (((a / (1.0 + (b * pow(max(x_1, 0.0), c_1)))) + (d * x_1)) + e_1);
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

float weft_sheen_albedo_scaling(vec3 sheen_color_1, float e_v, float e_l) {
    float _e3 = weft_max3_(sheen_color_1);
    float c_2 = clamp(_e3, 0.0, 1.0);
    return clamp(min((1.0 - (c_2 * clamp(e_v, 0.0, 1.0))), (1.0 - (c_2 * clamp(e_l, 0.0, 1.0)))), 0.0, 1.0);
}

float weft_sheen_albedo_scaling_view(vec3 sheen_color_2, float e_v_1) {
    float _e2 = weft_max3_(sheen_color_2);
    return clamp((1.0 - (clamp(_e2, 0.0, 1.0) * clamp(e_v_1, 0.0, 1.0))), 0.0, 1.0);
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

vec3 weft_sh_irradiance(vec3 n) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_vs.sh;
    e = (sh[0].xyz * 0.282095);
    vec3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n.y)));
    vec3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n.z)));
    vec3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n.x)));
    vec3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n.x) * n.y)));
    vec3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n.y) * n.z)));
    vec3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n.z) * n.z) - 1.0))));
    vec3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n.x) * n.z)));
    vec3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n.x * n.x) - (n.y * n.y)))));
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

WeftLightGeometry weft_main_light_geometry(vec3 n_1, vec3 v_2) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_2), n_1);
    float _e6 = weft_clamp_cos(dot(n_1, v_2));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_1, _e2), 0.0, 1.0), clamp(dot(n_1, _e4), 0.0, 1.0), clamp(dot(v_2, _e4), 0.0, 1.0));
}

vec2 fur_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

float fur_strand_exponent(float smoothness) {
    return exp2((1.0 + (9.0 * clamp(smoothness, 0.0, 1.0))));
}

float fur_strand_norm(float p) {
    return sqrt(((((2.0 * p) + 1.0) * 0.25) * WEFT_INV_PI));
}

FurVaryings fur_vertex(FurInput in_4, float offset) {
    FurVaryings out_ = FurVaryings(vec4(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec2(0.0), 0.0, vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0), 0.0);
    mat4x4 model = _group_2_binding_0_vs.model;
    mat4x4 nm = _group_2_binding_0_vs.normal_matrix;
    mat3x3 normal3_ = mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    vec3 world = (model * vec4(in_4.position, 1.0)).xyz;
    vec3 _e24 = weft_safe_normalize((normal3_ * in_4.normal), vec3(0.0));
    vec4 _e28 = _group_1_binding_0_vs.base_map_st;
    vec2 _e29 = fur_transform_uv(in_4.uv0_, _e28);
    vec4 _e33 = textureLod(_group_1_binding_7_vs, vec2(_e29), 0.0);
    vec3 force_texel = _e33.xyz;
    vec3 _e37 = _group_1_binding_0_vs.force_direction;
    float _e45 = _group_1_binding_0_vs.force_map_scale;
    vec3 force = (_e37 + (((force_texel * 2.0) - vec3(1.0)) * _e45));
    float _e50 = _group_1_binding_0_vs.force_strength;
    float s = clamp(_e50, 0.0, 1.0);
    vec3 target_dir = ((_e24 * (1.0 - s)) + (force * s));
    vec4 _e60 = textureLod(_group_1_binding_6_vs, vec2(_e29), 0.0);
    float height = _e60.x;
    float _e64 = _group_1_binding_0_vs.height_scale;
    float hs = clamp(_e64, 0.0, 1.0);
    float _e68 = _group_1_binding_0_vs.fur_length;
    float len = (max(_e68, 0.0) * max((1.0 + (hs * (clamp(height, 0.0, 1.0) - 1.0))), 0.0));
    vec3 dir_1 = mix(_e24, target_dir, offset);
    vec3 p_1 = (world + (dir_1 * (len * offset)));
    mat4x4 _e88 = _group_0_binding_0_vs.view_proj;
    out_.clip_position = (_e88 * vec4(p_1, 1.0));
    out_.world_position = p_1;
    out_.world_normal = _e24;
    out_.strand = (_e24 + ((2.0 * offset) * (target_dir - _e24)));
    out_.uv0_ = in_4.uv0_;
    out_.offset = offset;
    FurVaryings _e103 = out_;
    return _e103;
}

vec2 fur_kajiya_kay_cone(vec3 t, vec3 l, vec3 v_3) {
    float t_dot_l = clamp(dot(t, l), -1.0, 1.0);
    float t_dot_v = clamp(dot(t, v_3), -1.0, 1.0);
    float sin_l = sqrt(max((1.0 - (t_dot_l * t_dot_l)), 0.0));
    float sin_v = sqrt(max((1.0 - (t_dot_v * t_dot_v)), 0.0));
    return vec2(max(((sin_l * sin_v) - (t_dot_l * t_dot_v)), 0.0), sin_l);
}

float fur_fade_n_dot_v(FurVaryings in_6) {
    WeftSurface _e3 = weft_surface(in_6.world_position, in_6.world_normal);
    return clamp(dot(_e3.n, _e3.v), 0.0, 1.0);
}

void main() {
    FurInput in_1 = FurInput(_p2vs_location0, _p2vs_location1, _p2vs_location3);
    uint instance = (uint(gl_InstanceID) + uint(gl_BaseInstanceARB));
    int _e4 = _group_1_binding_0_vs.shell_count;
    float count = float(max(_e4, 1));
    FurVaryings _e12 = fur_vertex(in_1, ((float(instance) + 0.5) / count));
    gl_Position = _e12.clip_position;
    _vs2fs_location0 = _e12.world_position;
    _vs2fs_location1 = _e12.world_normal;
    _vs2fs_location2 = _e12.strand;
    _vs2fs_location3 = _e12.uv0_;
    _vs2fs_location4 = _e12.offset;
    _vs2fs_location5 = _e12.light_diffuse;
    _vs2fs_location6 = _e12.light_ambient;
    _vs2fs_location7 = _e12.light_sheen;
    _vs2fs_location8 = _e12.light_strand;
    _vs2fs_location9 = _e12.light_n_dot_v;
    gl_Position.yz = vec2(-gl_Position.y, gl_Position.z * 2.0 - gl_Position.w);
    return;
}

