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
struct SatinLayers {
    vec2 narrow;
    vec2 wide;
};
struct WeftMaterial {
    vec4 base_color;
};
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const uint TIER_LOW = 3u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_MIN_ANISO_ALPHA = 0.001;
const float WEFT_MIN_ROUGHNESS_HALF = 0.089;
const float WEFT_MIN_N_DOT_HALF = 0.001;
const float WEFT_MIN_ALPHA_HALF = 0.007921;

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_3_fs;

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

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
    float s_1 = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a_1 = (-1.0 / (s_1 + n_1.z));
    float b = ((n_1.x * n_1.y) * a_1);
    return vec3((1.0 + (((s_1 * n_1.x) * n_1.x) * a_1)), (s_1 * b), (-(s_1) * n_1.x));
}

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
}

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
}

vec3 weft_env_brdf_from_lut(vec3 f0_1, vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((f0_1 * sb.x) + vec3(sb.y));
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

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e2 = weft_view_direction_k2_(world_position_1);
    vec3 _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface(_e2, _e3);
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
    float s_2 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_4, t) * s_2);
    return mat3x3(t, b_1, n_4);
}

vec3 weft_aniso_to_frame(mat3x3 frame, vec3 x_1) {
    return vec3(dot(frame[0], x_1), dot(frame[1], x_1), dot(frame[2], x_1));
}

float weft_aniso_ggx_q(float t_dot_h, float b_dot_h, float n_dot_h, float alpha_t, float alpha_b) {
    float at = max(alpha_t, WEFT_MIN_ANISO_ALPHA);
    float ab = max(alpha_b, WEFT_MIN_ANISO_ALPHA);
    float x_2 = (t_dot_h / at);
    float y = (b_dot_h / ab);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 1e-6);
}

float weft_d_ggx_aniso(float t_dot_h_1, float b_dot_h_1, float n_dot_h_1, float alpha_t_1, float alpha_b_1) {
    float at_1 = max(alpha_t_1, WEFT_MIN_ANISO_ALPHA);
    float ab_1 = max(alpha_b_1, WEFT_MIN_ANISO_ALPHA);
    float _e9 = weft_aniso_ggx_q(t_dot_h_1, b_dot_h_1, n_dot_h_1, at_1, ab_1);
    float d = (1.0 / ((((WEFT_PI * at_1) * ab_1) * _e9) * _e9));
    return ((n_dot_h_1 > 0.0) ? d : 0.0);
}

float weft_v_smith_ggx_aniso_correlated(vec3 v_4, vec3 l, float alpha_t_2, float alpha_b_2) {
    float _e5 = weft_clamp_cos(v_4.z);
    float _e7 = weft_clamp_cos(l.z);
    float lv = (_e7 * length(vec3((alpha_t_2 * v_4.x), (alpha_b_2 * v_4.y), _e5)));
    float ll = (_e5 * length(vec3((alpha_t_2 * l.x), (alpha_b_2 * l.y), _e7)));
    return (0.5 / (lv + ll));
}

float weft_spec_ggx_aniso(vec3 v_5, vec3 l_1, float alpha_t_3, float alpha_b_3) {
    vec3 _e5 = weft_safe_normalize_k4_((v_5 + l_1));
    float _e9 = weft_d_ggx_aniso(_e5.x, _e5.y, _e5.z, alpha_t_3, alpha_b_3);
    float _e10 = weft_v_smith_ggx_aniso_correlated(v_5, l_1, alpha_t_3, alpha_b_3);
    return ((_e9 * _e10) * clamp(l_1.z, 0.0, 1.0));
}

float satin_lobe_reference(vec3 vf, vec3 lf, vec2 a) {
    float s = 0.0;
    float _e5 = weft_spec_ggx_aniso(vf, lf, a.x, a.y);
    s = _e5;
    float _e7 = s;
    return _e7;
}

vec2 weft_env_brdf_lut_k10_(float n_dot_v) {
    vec2 uv = vec2(clamp(n_dot_v, 0.0, 1.0), 0.4);
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv), 0.0);
    return _e8.xy;
}

vec2 weft_env_brdf_lut_k11_(float n_dot_v_1) {
    vec2 uv_1 = vec2(clamp(n_dot_v_1, 0.0, 1.0), 0.8);
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv_1), 0.0);
    return _e8.xy;
}

vec3 weft_aniso_bent_normal_k16_(mat3x3 frame_1, vec3 v_6) {
    vec3 n_5 = frame_1[2];
    vec3 dir_2 = frame_1[1];
    vec3 aniso_t = cross(dir_2, v_6);
    vec3 aniso_n = cross(aniso_t, dir_2);
    vec3 _e11 = weft_safe_normalize(mix(n_5, aniso_n, 0.85), n_5);
    return _e11;
}

float weft_specular_mip_k20_() {
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.568 * max_mip);
}

vec3 weft_prefiltered_radiance_k17_(vec3 dir) {
    float _e4 = weft_specular_mip_k20_();
    vec4 c_3 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_3.xyz, vec3(0.0));
}

vec3 satin_env_k12_(mat3x3 frame_2, vec3 v_7) {
    vec3 bent_1 = vec3(0.0);
    vec3 c_1 = vec3(0.0);
    vec3 _e4 = weft_aniso_bent_normal_k16_(frame_2, v_7);
    bent_1 = _e4;
    vec3 _e7 = bent_1;
    vec3 _e9 = weft_prefiltered_radiance_k17_(reflect(-(v_7), _e7));
    c_1 = _e9;
    vec3 _e11 = c_1;
    return _e11;
}

vec3 weft_aniso_bent_normal_k18_(mat3x3 frame_3, vec3 v_8) {
    vec3 n_6 = frame_3[2];
    vec3 dir_3 = frame_3[1];
    vec3 aniso_t_1 = cross(dir_3, v_8);
    vec3 aniso_n_1 = cross(aniso_t_1, dir_3);
    vec3 _e11 = weft_safe_normalize(mix(n_6, aniso_n_1, 0.85), n_6);
    return _e11;
}

float weft_specular_mip_k21_() {
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip_1 = max((_e5 - 1.0), 0.0);
    return (0.9120001 * max_mip_1);
}

vec3 weft_prefiltered_radiance_k19_(vec3 dir_1) {
    float _e4 = weft_specular_mip_k21_();
    vec4 c_4 = textureLod(_group_0_binding_1_fs, vec3(dir_1), _e4);
    return max(c_4.xyz, vec3(0.0));
}

vec3 satin_env_k13_(mat3x3 frame_4, vec3 v_9) {
    vec3 bent_2 = vec3(0.0);
    vec3 c_2 = vec3(0.0);
    vec3 _e4 = weft_aniso_bent_normal_k18_(frame_4, v_9);
    bent_2 = _e4;
    vec3 _e7 = bent_2;
    vec3 _e9 = weft_prefiltered_radiance_k19_(reflect(-(v_9), _e7));
    c_2 = _e9;
    vec3 _e11 = c_2;
    return _e11;
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 n = vec3(0.0);
    SatinLayers layers = SatinLayers(vec2(0.0), vec2(0.0));
    vec3 specular = vec3(0.0);
    vec3 diffuse_kd = vec3(0.0);
    vec3 indirect_specular = vec3(0.0);
    vec3 ambient_kd = vec3(0.0);
    vec3 bent = vec3(0.0);
    vec4 base_rgba = _group_1_binding_0_fs.base_color;
    vec3 base = clamp(base_rgba.xyz, vec3(0.0), vec3(1.0));
    float alpha = clamp(base_rgba.w, 0.0, 1.0);
    WeftSurface _e18 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_10 = _e18.v;
    n = _e18.n;
    vec3 _e22 = n;
    mat3x3 _e24 = weft_tangent_frame(_e22, in_1.world_tangent);
    vec3 _e25 = n;
    WeftLightGeometry _e26 = weft_main_light_geometry(_e25, v_10);
    layers.narrow = vec2(0.29600003, 0.023999998);
    layers.wide = vec2(1.1840001, 0.09599999);
    vec3 f0_2 = mix(vec3(0.04), base, 0.0);
    vec3 _e38 = weft_f_schlick(f0_2, _e26.v_dot_h);
    {
        vec3 _e48 = weft_aniso_to_frame(_e24, v_10);
        vec3 _e50 = weft_aniso_to_frame(_e24, _e26.l);
        vec2 _e52 = layers.narrow;
        float _e53 = satin_lobe_reference(_e48, _e50, _e52);
        vec2 _e55 = layers.wide;
        float _e56 = satin_lobe_reference(_e48, _e50, _e55);
        specular = ((((vec3(0.7584107, 0.6081799, 0.62124574) * _e53) + (vec3(0.24158928, 0.13334814, 0.14008713) * _e56)) * _e38) * vec3(3.2, 3.05, 2.8));
        vec3 _e65 = weft_f_schlick(f0_2, _e26.n_dot_v);
        diffuse_kd = max((vec3(1.0) - (vec3(1.0, 0.74152803, 0.76133287) * _e65)), vec3(0.0));
        vec2 _e71 = weft_env_brdf_lut_k10_(_e26.n_dot_v);
        vec3 _e72 = weft_env_brdf_from_lut(f0_2, _e71);
        vec3 e1_ = (_e72 * vec3(0.7584107, 0.6081799, 0.62124574));
        vec2 _e75 = weft_env_brdf_lut_k11_(_e26.n_dot_v);
        vec3 _e76 = weft_env_brdf_from_lut(f0_2, _e75);
        vec3 e2_ = (_e76 * vec3(0.24158928, 0.13334814, 0.14008713));
        {
            vec3 _e78 = satin_env_k12_(_e24, v_10);
            vec3 _e80 = satin_env_k13_(_e24, v_10);
            indirect_specular = ((_e78 * e1_) + (_e80 * e2_));
        }
        ambient_kd = max(((vec3(1.0) - e1_) - e2_), vec3(0.0));
    }
    vec3 _e88 = diffuse_kd;
    vec3 _e89 = weft_diffuse_lambert(base);
    vec3 _e94 = specular;
    vec3 direct = ((((_e88 * _e89) * vec3(3.2, 3.05, 2.8)) * _e26.n_dot_l) + _e94);
    vec3 _e96 = indirect_specular;
    vec3 _e97 = n;
    vec3 _e98 = weft_sh_irradiance(_e97);
    vec3 _e99 = ambient_kd;
    vec3 indirect = (_e96 + ((_e98 * _e99) * base));
    vec3 radiance = clamp((direct + indirect), vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, alpha);
    return;
}

