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
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const uint SPHERE_MAP_OFF = 0u;
const uint SPHERE_MAP_ADD = 1u;
const uint SPHERE_MAP_MULTIPLY = 2u;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const uint TIER_LOW = 3u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_MIN_ROUGHNESS_HALF = 0.089;
const float WEFT_MIN_N_DOT_HALF = 0.001;
const float WEFT_MIN_ALPHA_HALF = 0.007921;

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_3_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
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

vec3 weft_safe_normalize_k13_(vec3 v_1) {
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * inversesqrt(max(len2_1, 1e-20))) : vec3(0.0, 0.0, 1.0));
}

vec3 weft_view_direction_k2_(vec3 world_position) {
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
    vec3 _e7 = weft_safe_normalize_k13_((_e4.xyz - world_position));
    return _e7;
}

WeftSurface weft_surface_two_sided(vec3 world_position_1, vec3 world_normal, bool front_facing_1) {
    vec3 _e3 = weft_view_direction_k2_(world_position_1);
    vec3 facing = (front_facing_1 ? world_normal : -(world_normal));
    vec3 _e6 = weft_safe_normalize(facing, _e3);
    return WeftSurface(_e3, _e6);
}

WeftLightGeometry weft_main_light_geometry(vec3 n_2, vec3 v_2) {
    vec3 _e4 = weft_safe_normalize((vec3(-0.61984503, 0.54986256, 0.55986005) + v_2), n_2);
    float _e6 = weft_clamp_cos(dot(n_2, v_2));
    return WeftLightGeometry(vec3(-0.61984503, 0.54986256, 0.55986005), _e4, _e6, clamp(dot(n_2, vec3(-0.61984503, 0.54986256, 0.55986005)), 0.0, 1.0), clamp(dot(n_2, _e4), 0.0, 1.0), clamp(dot(v_2, _e4), 0.0, 1.0));
}

vec3 weft_safe_normalize_k3_(vec3 v_3) {
    float len2_2 = dot(v_3, v_3);
    return ((len2_2 > 1e-20) ? (v_3 * inversesqrt(max(len2_2, 1e-20))) : vec3(0.0));
}

vec3 standard_sphere_map(vec3 color_in, vec3 n_3, vec3 world_position_2) {
    vec3 color = vec3(0.0);
    color = color_in;
    vec3 _e4 = color;
    return _e4;
}

float weft_v_smith_ggx_correlated_newton_k5_(float n_dot_v, float n_dot_l) {
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float gv = ((_e6 * 0.7975) + 0.20249999);
    float gl = ((_e7 * 0.7975) + 0.20249999);
    float pv = ((gv * _e6) + (0.041006245 * (1.0 - _e6)));
    float pl = ((gl * _e7) + (0.041006245 * (1.0 - _e7)));
    return (((0.5 * gv) * gl) / (((_e7 * gl) * pv) + ((_e6 * gv) * pl)));
}

vec2 weft_env_brdf_lut_k6_(float n_dot_v_1) {
    vec2 uv = vec2(clamp(n_dot_v_1, 0.0, 1.0), 0.45);
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv), 0.0);
    return _e8.xy;
}

vec3 weft_env_brdf_from_lut_k7_(vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((vec3(0.04, 0.04, 0.04) * sb.x) + vec3(sb.y));
}

vec3 weft_f_schlick_k8_(float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (vec3(0.04, 0.04, 0.04) + (vec3(0.96, 0.96, 0.96) * _e5));
}

float weft_d_ggx_k9_(float n_dot_h) {
    float noh = clamp(n_dot_h, 0.0, 1.0);
    float one_minus_noh2_ = ((1.0 - noh) * (1.0 + noh));
    float d_1 = (one_minus_noh2_ + ((noh * noh) * 0.041006245));
    return (0.041006245 / ((WEFT_PI * d_1) * d_1));
}

float weft_specular_mip_k15_() {
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.62325 * max_mip);
}

vec3 weft_prefiltered_radiance_k10_(vec3 dir) {
    float _e4 = weft_specular_mip_k15_();
    vec4 c_1 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_1.xyz, vec3(0.0));
}

void standard_alpha_test_k12_() {
    {
        return;
    }
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    bool front_facing = gl_FrontFacing;
    vec3 n = vec3(0.0);
    float visibility = 0.0;
    vec3 env_brdf = vec3(0.0);
    vec3 ambient_kd = vec3(0.0);
    vec3 direct_kd = vec3(0.0);
    vec3 specular = vec3(0.0);
    vec3 indirect_specular = vec3(0.0);
    float d = 0.0;
    WeftSurface _e13 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    vec3 v_4 = _e13.v;
    n = _e13.n;
    vec3 _e17 = n;
    WeftLightGeometry _e18 = weft_main_light_geometry(_e17, v_4);
    {
        {
            float _e27 = weft_v_smith_ggx_correlated_newton_k5_(_e18.n_dot_v, _e18.n_dot_l);
            visibility = _e27;
            vec2 _e29 = weft_env_brdf_lut_k6_(_e18.n_dot_v);
            vec3 _e30 = weft_env_brdf_from_lut_k7_(_e29);
            env_brdf = _e30;
            vec3 _e32 = env_brdf;
            ambient_kd = max((vec3(1.0) - _e32), vec3(0.0));
            vec3 _e36 = ambient_kd;
            direct_kd = _e36;
        }
    }
    {
        vec3 _e42 = weft_f_schlick_k8_(_e18.v_dot_h);
        {
            float _e45 = weft_d_ggx_k9_(_e18.n_dot_h);
            d = _e45;
        }
        float _e46 = d;
        float _e47 = visibility;
        specular = (((_e46 * _e47) * _e42) * 0.5);
        vec3 _e52 = n;
        vec3 _e54 = weft_prefiltered_radiance_k10_(reflect(-(v_4), _e52));
        vec3 _e55 = env_brdf;
        indirect_specular = ((_e54 * _e55) * 0.5);
    }
    vec3 _e59 = direct_kd;
    vec3 diffuse = (_e59 * vec3(0.101859, 0.06366192, 0.038197216));
    vec3 _e62 = specular;
    vec3 direct = (((diffuse + _e62) * vec3(3.0, 2.8799999, 2.6999998)) * _e18.n_dot_l);
    vec3 _e68 = n;
    vec3 _e69 = weft_sh_irradiance(_e68);
    vec3 _e70 = ambient_kd;
    vec3 indirect_diffuse = ((_e69 * _e70) * vec3(0.31999952, 0.19999982, 0.120000094));
    vec3 _e73 = indirect_specular;
    vec3 color_1 = ((direct + _e73) + indirect_diffuse);
    vec3 _e76 = n;
    vec3 _e78 = standard_sphere_map(color_1, _e76, in_1.world_position);
    vec3 radiance = clamp((_e78 + vec3(0.0)), vec3(0.0), vec3(65504.0));
    standard_alpha_test_k12_();
    _fs2p_location0 = vec4(radiance, 1.0);
    return;
}

