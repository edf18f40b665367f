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
struct SilkLobe {
    float value;
    vec2 alpha;
    float ibl_roughness;
};
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const uint ANISO_MODEL_WARD = 0u;
const uint ANISO_MODEL_HAIR_SHIFTED = 1u;
const uint ANISO_MODEL_GGX = 2u;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const uint TIER_LOW = 3u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_MIN_ANISO_ALPHA = 0.001;
const float SILK_MIN_ALPHA = 0.001;
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

vec3 weft_any_perpendicular(vec3 n) {
    float s = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n.z));
    float b = ((n.x * n.y) * a);
    return vec3((1.0 + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
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

float weft_specular_mip(float roughness) {
    float r = clamp(roughness, 0.0, 1.0);
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

vec3 weft_prefiltered_radiance(vec3 dir, float roughness_1) {
    float _e4 = weft_specular_mip(roughness_1);
    vec4 c_1 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_1.xyz, vec3(0.0));
}

vec2 weft_env_brdf_lut(float n_dot_v, float roughness_2) {
    vec2 uv = vec2(clamp(n_dot_v, 0.0, 1.0), clamp(roughness_2, 0.0, 1.0));
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv), 0.0);
    return _e8.xy;
}

vec3 weft_safe_normalize_k10_(vec3 v_1) {
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * inversesqrt(max(len2_1, 1e-20))) : vec3(0.0, 0.0, 1.0));
}

vec3 weft_view_direction_k2_(vec3 world_position) {
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
    vec3 _e7 = weft_safe_normalize_k10_((_e4.xyz - world_position));
    return _e7;
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e2 = weft_view_direction_k2_(world_position_1);
    vec3 _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface(_e2, _e3);
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

mat3x3 weft_tangent_frame(vec3 n_3, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_3 * dot(n_3, t_in)));
    float len2_3 = dot(t_proj, t_proj);
    bool ok = (len2_3 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_3);
    vec3 t = (ok ? (t_proj * inversesqrt(max(len2_3, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_3, t) * s_1);
    return mat3x3(t, b_1, n_3);
}

vec3 weft_aniso_to_frame(mat3x3 frame, vec3 x_1) {
    return vec3(dot(frame[0], x_1), dot(frame[1], x_1), dot(frame[2], x_1));
}

vec3 weft_aniso_bent_normal(mat3x3 frame_1, vec3 v_4, float anisotropy, float roughness_3) {
    float k = clamp(anisotropy, -1.0, 1.0);
    vec3 n_4 = frame_1[2];
    vec3 dir_1 = ((k >= 0.0) ? frame_1[1] : frame_1[0]);
    vec3 aniso_t = cross(dir_1, v_4);
    vec3 aniso_n = cross(aniso_t, dir_1);
    float bend = (abs(k) * clamp((5.0 * clamp(roughness_3, 0.0, 1.0)), 0.0, 1.0));
    vec3 _e22 = weft_safe_normalize(mix(n_4, aniso_n, bend), n_4);
    return _e22;
}

float silk_lobe_anisotropy(vec2 alpha) {
    float at = max(alpha.x, SILK_MIN_ALPHA);
    float ab = max(alpha.y, SILK_MIN_ALPHA);
    return ((at - ab) / (at + ab));
}

vec3 weft_f_schlick_k7_(float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (vec3(0.04, 0.04, 0.04) + (vec3(0.96, 0.96, 0.96) * _e5));
}

vec3 weft_env_brdf_from_lut_k9_(vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((vec3(0.04, 0.04, 0.04) * sb.x) + vec3(sb.y));
}

vec3 weft_normal_from_tangent_space_k12_(mat3x3 frame_2) {
    vec3 _e4 = weft_safe_normalize((frame_2 * vec3(vec2(0.003921628, 0.003921628), 1.0)), frame_2[2]);
    return _e4;
}

float weft_v_smith_ggx_aniso_correlated_k13_(vec3 v_5, vec3 l) {
    float _e5 = weft_clamp_cos(v_5.z);
    float _e7 = weft_clamp_cos(l.z);
    float lv = (_e7 * length(vec3((0.23174134 * v_5.x), (0.06475432 * v_5.y), _e5)));
    float ll = (_e5 * length(vec3((0.23174134 * l.x), (0.06475432 * l.y), _e7)));
    return (0.5 / (lv + ll));
}

float weft_aniso_ggx_q_k15_(float t_dot_h, float b_dot_h, float n_dot_h) {
    float x_2 = (t_dot_h / 0.23174134);
    float y = (b_dot_h / 0.06475432);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 1e-6);
}

float weft_d_ggx_aniso_k14_(float t_dot_h_1, float b_dot_h_1, float n_dot_h_1) {
    float _e7 = weft_aniso_ggx_q_k15_(t_dot_h_1, b_dot_h_1, n_dot_h_1);
    float d = (1.0 / ((0.047143534 * _e7) * _e7));
    return ((n_dot_h_1 > 0.0) ? d : 0.0);
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 fibre = vec3(0.0);
    SilkLobe lobe = SilkLobe(0.0, vec2(0.0), 0.0);
    float vis = 0.0;
    vec3 env_brdf = vec3(0.0);
    vec3 ambient_kd = vec3(0.0);
    vec3 reflect_n = vec3(0.0);
    WeftSurface _e11 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_6 = _e11.v;
    vec3 n_geo = _e11.n;
    mat3x3 _e15 = weft_tangent_frame(n_geo, in_1.world_tangent);
    vec3 _e17 = weft_normal_from_tangent_space_k12_(_e15);
    fibre = _e15[0];
    vec3 _e20 = fibre;
    mat3x3 _e24 = weft_tangent_frame(_e17, vec4(_e20, in_1.world_tangent.w));
    WeftLightGeometry _e25 = weft_main_light_geometry(_e17, v_6);
    vec3 _e26 = weft_aniso_to_frame(_e24, v_6);
    vec3 _e28 = weft_aniso_to_frame(_e24, _e25.l);
    vec3 _e30 = weft_aniso_to_frame(_e24, _e25.h);
    {
        {
            lobe.alpha = vec2(0.23174134, 0.06475432);
            lobe.ibl_roughness = 0.35000002;
            {
                {
                    float _e37 = weft_v_smith_ggx_aniso_correlated_k13_(_e26, _e28);
                    vis = _e37;
                }
                float _e42 = weft_d_ggx_aniso_k14_(_e30.x, _e30.y, _e30.z);
                float _e43 = vis;
                lobe.value = ((_e42 * _e43) * _e25.n_dot_l);
            }
        }
    }
    float n_dot_l_diffuse = clamp(dot(n_geo, _e25.l), 0.0, 1.0);
    vec3 _e52 = weft_f_schlick_k7_(_e25.v_dot_h);
    vec3 diffuse = (((vec3(1.0) - _e52) * vec3(0.222817, 0.14323957, 0.031830948)) * n_dot_l_diffuse);
    float _e59 = lobe.value;
    vec3 direct = ((diffuse + (_e52 * _e59)) * vec3(3.0, 2.8799999, 2.6999998));
    reflect_n = _e17;
    {
        float _e68 = lobe.ibl_roughness;
        vec2 _e69 = weft_env_brdf_lut(_e25.n_dot_v, _e68);
        vec3 _e70 = weft_env_brdf_from_lut_k9_(_e69);
        env_brdf = _e70;
        vec3 _e72 = env_brdf;
        ambient_kd = max((vec3(1.0) - _e72), vec3(0.0));
        vec2 _e77 = lobe.alpha;
        float _e78 = silk_lobe_anisotropy(_e77);
        float _e80 = lobe.ibl_roughness;
        vec3 _e81 = weft_aniso_bent_normal(_e24, v_6, _e78, _e80);
        reflect_n = _e81;
    }
    vec3 _e83 = reflect_n;
    float _e86 = lobe.ibl_roughness;
    vec3 _e87 = weft_prefiltered_radiance(reflect(-(v_6), _e83), _e86);
    vec3 _e88 = env_brdf;
    vec3 _e90 = weft_sh_irradiance(n_geo);
    vec3 _e91 = ambient_kd;
    vec3 indirect = ((_e87 * _e88) + ((_e90 * _e91) * vec3(0.7000003, 0.4500004, 0.099999875)));
    vec3 radiance = clamp((direct + indirect), vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, 1.0);
    return;
}

