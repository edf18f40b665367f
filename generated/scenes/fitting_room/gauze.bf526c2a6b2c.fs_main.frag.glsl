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
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_MIN_ANISO_ALPHA = 0.001;
const float GAUZE_LN_MAX_TRANSMITTANCE = 6.9077554;

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

vec3 weft_any_perpendicular(vec3 n_1) {
    float s = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return vec3((1.0 + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
}

vec3 weft_sh_irradiance(vec3 n_2) {
    vec3 e = vec3(0.0);
    e = vec3(0.27778354, 0.32136026, 0.4497644);
    e = (vec3(0.27778354, 0.32136026, 0.4497644) + (vec3(0.2192843, 0.34164187, 0.663193) * (0.488603 * n_2.y)));
    vec3 _e11 = e;
    e = (_e11 + (vec3(0.1352113, 0.12394369, 0.10366199) * (0.488603 * n_2.z)));
    vec3 _e18 = e;
    e = (_e18 + (vec3(-0.14969625, -0.13722156, -0.11476713) * (0.488603 * n_2.x)));
    vec3 _e25 = e;
    e = (_e25 + (vec3(-0.064625785, -0.059240304, -0.049546435) * ((1.092548 * n_2.x) * n_2.y)));
    vec3 _e34 = e;
    e = (_e34 + (vec3(0.05837178, 0.053507466, 0.044751696) * ((1.092548 * n_2.y) * n_2.z)));
    vec3 _e43 = e;
    e = (_e43 + (vec3(0.025110306, 0.023586905, 0.01273896) * (0.315392 * (((3.0 * n_2.z) * n_2.z) - 1.0))));
    vec3 _e56 = e;
    e = (_e56 + (vec3(-0.06322707, -0.057958152, -0.04847409) * ((1.092548 * n_2.x) * n_2.z)));
    vec3 _e65 = e;
    e = (_e65 + (vec3(0.056382716, 0.05266991, 0.031947177) * (0.546274 * ((n_2.x * n_2.x) - (n_2.y * n_2.y)))));
    vec3 _e78 = e;
    return max(_e78, vec3(0.0));
}

vec3 weft_safe_normalize_k4_(vec3 v_1) {
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * inversesqrt(max(len2_1, 1e-20))) : vec3(0.0, 0.0, 1.0));
}

vec3 weft_view_direction_k2_(vec3 world_position) {
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
    vec3 _e7 = weft_safe_normalize_k4_((_e4.xyz - world_position));
    return _e7;
}

WeftSurface weft_surface_two_sided(vec3 world_position_1, vec3 world_normal, bool front_facing_1) {
    vec3 _e3 = weft_view_direction_k2_(world_position_1);
    vec3 facing = (front_facing_1 ? world_normal : -(world_normal));
    vec3 _e6 = weft_safe_normalize(facing, _e3);
    return WeftSurface(_e3, _e6);
}

WeftLightGeometry weft_main_light_geometry(vec3 n_3, vec3 v_2) {
    vec3 _e4 = weft_safe_normalize((vec3(-0.61984503, 0.54986256, 0.55986005) + v_2), n_3);
    float _e6 = weft_clamp_cos(dot(n_3, v_2));
    return WeftLightGeometry(vec3(-0.61984503, 0.54986256, 0.55986005), _e4, _e6, clamp(dot(n_3, vec3(-0.61984503, 0.54986256, 0.55986005)), 0.0, 1.0), clamp(dot(n_3, _e4), 0.0, 1.0), clamp(dot(v_2, _e4), 0.0, 1.0));
}

vec3 weft_safe_normalize_k3_(vec3 v_3) {
    float len2_2 = dot(v_3, v_3);
    return ((len2_2 > 1e-20) ? (v_3 * inversesqrt(max(len2_2, 1e-20))) : vec3(0.0));
}

mat3x3 weft_tangent_frame(vec3 n_4, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_4 * dot(n_4, t_in)));
    float len2_3 = dot(t_proj, t_proj);
    bool ok = (len2_3 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_4);
    vec3 t = (ok ? (t_proj * inversesqrt(max(len2_3, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_4, t) * s_1);
    return mat3x3(t, b_1, n_4);
}

vec3 weft_aniso_to_frame(mat3x3 frame, vec3 x_1) {
    return vec3(dot(frame[0], x_1), dot(frame[1], x_1), dot(frame[2], x_1));
}

mat3x3 weft_rotate_tangent_frame_cs_k15_(mat3x3 frame_1) {
    vec3 t_1 = ((frame_1[0] * -4.371139e-8) + frame_1[1]);
    vec3 b_2 = ((frame_1[1] * -4.371139e-8) - frame_1[0]);
    return mat3x3(t_1, b_2, frame_1[2]);
}

mat3x3 weft_rotate_tangent_frame_k7_(mat3x3 frame_2) {
    mat3x3 _e2 = weft_rotate_tangent_frame_cs_k15_(frame_2);
    return _e2;
}

vec3 weft_f_schlick_k9_(float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (vec3(0.04) + (vec3(0.96, 0.96, 0.96) * _e5));
}

vec2 weft_env_brdf_lut_k10_(float n_dot_v) {
    vec2 uv = vec2(clamp(n_dot_v, 0.0, 1.0), 0.45);
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv), 0.0);
    return _e8.xy;
}

vec3 weft_env_brdf_from_lut_k11_(vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((vec3(0.04) * sb.x) + vec3(sb.y));
}

vec3 weft_aniso_bent_normal_k13_(mat3x3 frame_3, vec3 v_4) {
    vec3 n_5 = frame_3[2];
    vec3 dir_1 = frame_3[1];
    vec3 aniso_t = cross(dir_1, v_4);
    vec3 aniso_n = cross(aniso_t, dir_1);
    vec3 _e11 = weft_safe_normalize(mix(n_5, aniso_n, 0.8), n_5);
    return _e11;
}

float weft_specular_mip_k17_() {
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.62325 * max_mip);
}

vec3 weft_prefiltered_radiance_k14_(vec3 dir) {
    float _e4 = weft_specular_mip_k17_();
    vec4 c_1 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_1.xyz, vec3(0.0));
}

float weft_aniso_ggx_q_k21_(float t_dot_h, float b_dot_h, float n_dot_h) {
    float x_2 = (t_dot_h / 0.36449996);
    float y = (b_dot_h / 0.040499996);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 1e-6);
}

float weft_d_ggx_aniso_k19_(float t_dot_h_1, float b_dot_h_1, float n_dot_h_1) {
    float _e7 = weft_aniso_ggx_q_k21_(t_dot_h_1, b_dot_h_1, n_dot_h_1);
    float d = (1.0 / ((0.046376966 * _e7) * _e7));
    return ((n_dot_h_1 > 0.0) ? d : 0.0);
}

float weft_v_smith_ggx_aniso_correlated_k20_(vec3 v_5, vec3 l) {
    float _e5 = weft_clamp_cos(v_5.z);
    float _e7 = weft_clamp_cos(l.z);
    float lv = (_e7 * length(vec3((0.36449996 * v_5.x), (0.040499996 * v_5.y), _e5)));
    float ll = (_e5 * length(vec3((0.36449996 * l.x), (0.040499996 * l.y), _e7)));
    return (0.5 / (lv + ll));
}

float weft_spec_ggx_aniso_k18_(vec3 v_6, vec3 l_1) {
    vec3 _e5 = weft_safe_normalize_k4_((v_6 + l_1));
    float _e9 = weft_d_ggx_aniso_k19_(_e5.x, _e5.y, _e5.z);
    float _e10 = weft_v_smith_ggx_aniso_correlated_k20_(v_6, l_1);
    return ((_e9 * _e10) * clamp(l_1.z, 0.0, 1.0));
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    bool front_facing = gl_FrontFacing;
    vec3 n = vec3(0.0);
    vec3 spec_direct = vec3(0.0);
    vec3 env_brdf = vec3(0.0);
    vec3 diffuse_kd = vec3(0.0);
    vec3 ambient_kd = vec3(0.0);
    float lobe = 0.0;
    vec2 uv_s = (in_1.uv0_ * 60.0);
    vec2 grid_w = fwidth(uv_s);
    WeftSurface _e18 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    vec3 v_7 = _e18.v;
    vec3 n_geom = _e18.n;
    n = n_geom;
    vec3 _e22 = n;
    mat3x3 _e24 = weft_tangent_frame(_e22, in_1.world_tangent);
    float cos_v = min(abs(dot(n_geom, v_7)), 1.0);
    float sin_v = sqrt(max((1.0 - (cos_v * cos_v)), 0.0));
    float s_2 = pow(max(sin_v, 1e-8), 3.0);
    float alpha = clamp((1.0 - ((1.0 - s_2) * 0.6930604)), 0.0, 1.0);
    float coverage = clamp((1.0 - ((1.0 - s_2) * 0.0)), 0.0, 1.0);
    mat3x3 _e56 = weft_rotate_tangent_frame_k7_(_e24);
    vec3 _e59 = n;
    WeftLightGeometry _e60 = weft_main_light_geometry(_e59, v_7);
    {
        {
            vec3 _e71 = weft_aniso_to_frame(_e24, v_7);
            vec3 _e73 = weft_aniso_to_frame(_e24, _e60.l);
            vec3 _e74 = weft_aniso_to_frame(_e56, v_7);
            vec3 _e76 = weft_aniso_to_frame(_e56, _e60.l);
            float _e77 = weft_spec_ggx_aniso_k18_(_e71, _e73);
            float _e78 = weft_spec_ggx_aniso_k18_(_e74, _e76);
            lobe = mix(_e77, _e78, 0.0);
        }
        vec3 _e81 = weft_f_schlick_k9_(_e60.v_dot_h);
        float _e82 = lobe;
        spec_direct = (((_e82 * _e81) * vec3(1.0, 0.8900054, 0.93310684)) * vec3(3.2, 3.05, 2.8));
        vec3 _e88 = weft_f_schlick_k9_(_e60.n_dot_v);
        diffuse_kd = (vec3(1.0) - (vec3(1.0, 0.8900054, 0.93310684) * _e88));
        vec2 _e92 = weft_env_brdf_lut_k10_(_e60.n_dot_v);
        vec3 _e93 = weft_env_brdf_from_lut_k11_(_e92);
        env_brdf = (_e93 * vec3(1.0, 0.8900054, 0.93310684));
        vec3 _e96 = env_brdf;
        ambient_kd = max((vec3(1.0) - _e96), vec3(0.0));
    }
    vec3 _e100 = diffuse_kd;
    vec3 diffuse_direct = (((_e100 * vec3(0.26995486, 0.22618032, 0.23822759)) * vec3(3.2, 3.05, 2.8)) * _e60.n_dot_l);
    vec3 _e106 = n;
    vec3 _e107 = weft_sh_irradiance(_e106);
    vec3 _e108 = ambient_kd;
    vec3 diffuse_indirect = ((_e107 * _e108) * vec3(0.84808826, 0.71056646, 0.7484141));
    vec3 _e111 = weft_aniso_bent_normal_k13_(_e24, v_7);
    vec3 _e114 = weft_prefiltered_radiance_k14_(reflect(-(v_7), _e111));
    vec3 _e115 = env_brdf;
    vec3 spec_indirect = (_e114 * _e115);
    vec3 _e119 = spec_direct;
    vec3 color = ((alpha * (diffuse_direct + diffuse_indirect)) + (coverage * (_e119 + spec_indirect)));
    vec3 radiance = clamp(color, vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, alpha);
    return;
}

