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
struct WeftMaterial {
    vec4 scatter_color;
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

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_5_fs;

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

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

vec3 weft_sh_irradiance(vec3 n_1) {
    vec3 e = vec3(0.0);
    e = vec3(0.27778354, 0.32136026, 0.4497644);
    e = (vec3(0.27778354, 0.32136026, 0.4497644) + (vec3(0.2192843, 0.34164187, 0.663193) * (0.488603 * n_1.y)));
    vec3 _e11 = e;
    e = (_e11 + (vec3(0.1352113, 0.12394369, 0.10366199) * (0.488603 * n_1.z)));
    vec3 _e18 = e;
    e = (_e18 + (vec3(-0.14969625, -0.13722156, -0.11476713) * (0.488603 * n_1.x)));
    vec3 _e25 = e;
    e = (_e25 + (vec3(-0.064625785, -0.059240304, -0.049546435) * ((1.092548 * n_1.x) * n_1.y)));
    vec3 _e34 = e;
    e = (_e34 + (vec3(0.05837178, 0.053507466, 0.044751696) * ((1.092548 * n_1.y) * n_1.z)));
    vec3 _e43 = e;
    e = (_e43 + (vec3(0.025110306, 0.023586905, 0.01273896) * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0))));
    vec3 _e56 = e;
    e = (_e56 + (vec3(-0.06322707, -0.057958152, -0.04847409) * ((1.092548 * n_1.x) * n_1.z)));
    vec3 _e65 = e;
    e = (_e65 + (vec3(0.056382716, 0.05266991, 0.031947177) * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    vec3 _e78 = e;
    return max(_e78, vec3(0.0));
}

vec3 weft_safe_normalize_k8_(vec3 v_2) {
    float len2_1 = dot(v_2, v_2);
    return ((len2_1 > 1e-20) ? (v_2 * inversesqrt(max(len2_1, 1e-20))) : vec3(0.0, 0.0, 1.0));
}

vec3 weft_view_direction_k2_(vec3 world_position) {
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
    vec3 _e7 = weft_safe_normalize_k8_((_e4.xyz - world_position));
    return _e7;
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e2 = weft_view_direction_k2_(world_position_1);
    vec3 _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface(_e2, _e3);
}

WeftLightGeometry weft_main_light_geometry(vec3 n_2, vec3 v_3) {
    vec3 _e4 = weft_safe_normalize((vec3(-0.61984503, 0.54986256, 0.55986005) + v_3), n_2);
    float _e6 = weft_clamp_cos(dot(n_2, v_3));
    return WeftLightGeometry(vec3(-0.61984503, 0.54986256, 0.55986005), _e4, _e6, clamp(dot(n_2, vec3(-0.61984503, 0.54986256, 0.55986005)), 0.0, 1.0), clamp(dot(n_2, _e4), 0.0, 1.0), clamp(dot(v_3, _e4), 0.0, 1.0));
}

vec3 weft_safe_normalize_k3_(vec3 v_4) {
    float len2_2 = dot(v_4, v_4);
    return ((len2_2 > 1e-20) ? (v_4 * inversesqrt(max(len2_2, 1e-20))) : vec3(0.0));
}

float weft_sheen_albedo_scaling_view(vec3 sheen_color, float e_v) {
    float _e2 = weft_max3_(sheen_color);
    return clamp((1.0 - (clamp(_e2, 0.0, 1.0) * clamp(e_v, 0.0, 1.0))), 0.0, 1.0);
}

float weft_sheen_albedo_k9_(float n_dot_x) {
    vec2 uv = vec2(clamp(n_dot_x, 0.0, 1.0), 0.1225);
    vec4 _e8 = textureLod(_group_0_binding_5_fs, vec2(uv), 0.0);
    return clamp(_e8.x, 0.0, 1.0);
}

float weft_d_charlie_k12_(float n_dot_h) {
    float noh = clamp(n_dot_h, 0.0, 1.0);
    float sin2_ = max(((1.0 - noh) * (1.0 + noh)), 0.0);
    return ((10.163265 * pow(sin2_, 4.0816326)) * 0.15915494);
}

float weft_sheen_l_k16_(float x) {
    return (((24.455767 / (1.0 + (3.4406166 * pow(max(x, 0.0), 0.1749604)))) + (-1.4357697 * x)) + -4.7356734);
}

float weft_sheen_lambda_one_exp_k15_(float cos_theta) {
    float _e2 = weft_clamp_cos(cos_theta);
    bool low = (_e2 < 0.5);
    float _e8 = weft_sheen_l_k16_((low ? _e2 : (1.0 - _e2)));
    return exp((low ? _e8 : (1.1767559 - _e8)));
}

float weft_v_charlie_k13_(float n_dot_v, float n_dot_l) {
    float _e4 = weft_clamp_cos(n_dot_v);
    float _e5 = weft_clamp_cos(n_dot_l);
    float _e6 = weft_sheen_lambda_one_exp_k15_(_e4);
    float _e9 = weft_sheen_lambda_one_exp_k15_(_e5);
    float g_inv = ((1.0 + _e6) + _e9);
    return (1.0 / (((g_inv * 4.0) * _e4) * _e5));
}

vec3 weft_sheen_charlie_k10_(vec3 sheen_color_1, float n_dot_h_1, float n_dot_v_1, float n_dot_l_1) {
    float _e5 = weft_d_charlie_k12_(n_dot_h_1);
    float _e6 = weft_v_charlie_k13_(n_dot_v_1, n_dot_l_1);
    float lobe = (_e5 * _e6);
    return (max(sheen_color_1, vec3(0.0)) * (lobe * clamp(n_dot_l_1, 0.0, 1.0)));
}

float weft_specular_mip_k14_() {
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.19774564 * max_mip);
}

vec3 weft_prefiltered_radiance_k11_(vec3 dir) {
    float _e4 = weft_specular_mip_k14_();
    vec4 c_1 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_1.xyz, vec3(0.0));
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 n = vec3(0.0);
    vec3 color = vec3(0.0);
    vec3 sheen = vec3(0.0);
    float scaling = 0.0;
    WeftSurface _e11 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_5 = _e11.v;
    n = _e11.n;
    vec3 _e15 = n;
    WeftLightGeometry _e16 = weft_main_light_geometry(_e15, v_5);
    float l_dot_h = clamp(dot(_e16.l, _e16.h), 0.0, 1.0);
    vec3 _e24 = n;
    vec3 _e25 = weft_sh_irradiance(_e24);
    {
        vec4 _e29 = _group_1_binding_0_fs.scatter_color;
        vec3 sheen_color_2 = clamp((vec3(0.04, 0.04, 0.04) + max(_e29.xyz, vec3(0.0))), vec3(0.0), vec3(1.0));
        float _e37 = weft_sheen_albedo_k9_(_e16.n_dot_v);
        float _e38 = weft_sheen_albedo_scaling_view(sheen_color_2, _e37);
        {
            vec3 _e44 = weft_sheen_charlie_k10_(sheen_color_2, _e16.n_dot_h, _e16.n_dot_v, _e16.n_dot_l);
            sheen = _e44;
            scaling = _e38;
        }
        float _e46 = scaling;
        vec3 base_direct = (vec3(0.015915554, 0.038197216, 0.095493145) * (_e46 * _e16.n_dot_l));
        vec3 _e50 = sheen;
        vec3 direct = ((_e50 + base_direct) * vec3(3.0, 2.8799999, 2.6999998));
        vec3 _e54 = n;
        vec3 _e56 = weft_prefiltered_radiance_k11_(reflect(-(v_5), _e54));
        vec3 env_sheen = ((_e56 * sheen_color_2) * _e37);
        color = ((direct + ((_e25 * vec3(0.050000187, 0.120000094, 0.30000058)) * _e38)) + env_sheen);
    }
    vec3 _e63 = color;
    vec3 radiance = clamp(_e63, vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, 1.0);
    return;
}

