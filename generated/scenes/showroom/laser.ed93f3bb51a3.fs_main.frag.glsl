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
struct WeftFilmStack {
    float n2_;
    float cos2_;
    vec2 r12_;
    vec3 r23_[2];
    bool total_internal_reflection;
};
struct WeftFilmSeries {
    vec3 dc;
    vec3 first;
    vec3 ratio;
};
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const float film_sensitivity_opd_max = 16000.0;
const uint COLOR_MODE_HUE_RING = 0u;
const uint COLOR_MODE_CUSTOM = 1u;
const uint ANISO_COLOR_OFF = 0u;
const uint ANISO_COLOR_VALUE = 1u;
const uint ANISO_COLOR_MAP = 2u;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_FILM_PI = 3.1415927;
const uint WEFT_FILM_SAMPLES = 101u;
const float WEFT_FILM_LAMBDA_MIN = 380.0;
const float WEFT_FILM_LAMBDA_MAX = 780.0;
const float WEFT_FILM_FADE_NM = 30.0;
const mat3x3 WEFT_XYZ_TO_REC709_ = mat3x3(vec3(3.2404542, -0.969266, 0.0556434), vec3(-1.5371385, 1.8760108, -0.2040259), vec3(-0.4985314, 0.041556, 1.0572252));

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_3_fs;

layout(binding = 2) uniform sampler2D _group_1_binding_9_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

vec4 table_film_sensitivity(vec2 uv) {
    vec2 st = (((clamp(uv, vec2(0.0), vec2(1.0)) * vec2(2047.0, 1.0)) + vec2(0.5)) / vec2(2048.0, 2.0));
    vec4 _e13 = textureLod(_group_1_binding_9_fs, vec2(st), 0.0);
    return _e13;
}

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

vec3 weft_safe_normalize_k11_(vec3 v_1) {
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * inversesqrt(max(len2_1, 1e-20))) : vec3(0.0, 0.0, 1.0));
}

vec3 weft_view_direction_k2_(vec3 world_position) {
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
    vec3 _e7 = weft_safe_normalize_k11_((_e4.xyz - world_position));
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

vec2 weft_fresnel_amplitudes_k4_(float n_t, float cos_i, float cos_t) {
    float rs = ((cos_i - (n_t * cos_t)) / max((cos_i + (n_t * cos_t)), 1e-12));
    float rp = (((n_t * cos_i) - cos_t) / max(((n_t * cos_i) + cos_t), 1e-12));
    return vec2(rs, rp);
}

vec3 weft_film_sensitivity(float opd_nm) {
    vec4 _e5 = table_film_sensitivity(vec2((opd_nm / film_sensitivity_opd_max), 0.0));
    return _e5.xyz;
}

vec3 weft_film_orders(float opd_nm_1, WeftFilmSeries s, WeftFilmSeries p) {
    vec3 k1_ = ((s.first * s.ratio) + (p.first * p.ratio));
    vec3 k2_ = (((s.first * s.ratio) * s.ratio) + ((p.first * p.ratio) * p.ratio));
    vec3 k3_ = ((((s.first * s.ratio) * s.ratio) * s.ratio) + (((p.first * p.ratio) * p.ratio) * p.ratio));
    vec3 k4_ = (((s.first * (s.ratio * s.ratio)) * (s.ratio * s.ratio)) + ((p.first * (p.ratio * p.ratio)) * (p.ratio * p.ratio)));
    vec3 _e55 = weft_film_sensitivity(opd_nm_1);
    vec3 _e59 = weft_film_sensitivity((2.0 * opd_nm_1));
    vec3 _e64 = weft_film_sensitivity((3.0 * opd_nm_1));
    vec3 _e69 = weft_film_sensitivity((4.0 * opd_nm_1));
    vec3 sum = ((((k1_ * _e55) + (k2_ * _e59)) + (k3_ * _e64)) + (k4_ * _e69));
    return (2.0 * sum);
}

WeftFilmSeries weft_film_series(float r12_, vec3 r23_) {
    float big_r12_ = (r12_ * r12_);
    float t121_ = (1.0 - big_r12_);
    vec3 big_r23_ = (r23_ * r23_);
    vec3 big_r123_ = min((big_r12_ * big_r23_), vec3(0.9999));
    vec3 rs_1 = (((t121_ * t121_) * big_r23_) / (vec3(1.0) - big_r123_));
    vec3 ratio = clamp((-(r12_) * r23_), vec3(-0.99995), vec3(0.99995));
    return WeftFilmSeries((vec3(big_r12_) + rs_1), (rs_1 - vec3(t121_)), ratio);
}

vec2 weft_env_brdf_lut_k6_(float n_dot_v) {
    vec2 uv_1 = vec2(clamp(n_dot_v, 0.0, 1.0), 0.2);
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv_1), 0.0);
    return _e8.xy;
}

float weft_film_ior_k19_() {
    return mix(1.0, 1.8, smoothstep(0.0, WEFT_FILM_FADE_NM, 420.0));
}

float weft_v_smith_ggx_correlated_k8_(float n_dot_v_1, float n_dot_l) {
    float _e6 = weft_clamp_cos(n_dot_v_1);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * 0.9984) + 0.0016000002)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * 0.9984) + 0.0016000002)));
    return (0.5 / (lv + ll));
}

float weft_d_ggx_nh_k9_(vec3 n_3, vec3 h) {
    float noh = clamp(dot(n_3, h), 0.0, 1.0);
    vec3 nxh = cross(n_3, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * 0.0016000002));
    return (0.0016000002 / (WEFT_PI * max((d * d), 1e-30)));
}

float weft_specular_mip_k14_() {
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.312 * max_mip);
}

vec3 weft_prefiltered_radiance_k10_(vec3 dir) {
    float _e4 = weft_specular_mip_k14_();
    vec4 c_1 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_1.xyz, vec3(0.0));
}

vec3 weft_f_schlick_k15_(float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (vec3(0.8999996, 0.8999996, 0.8999996) + (vec3(0.10000038, 0.10000038, 0.10000038) * _e5));
}

vec3 weft_env_brdf_from_lut_k16_(vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((vec3(0.8999996, 0.8999996, 0.8999996) * sb.x) + vec3(sb.y));
}

vec3[2] weft_film_base_amplitudes_k22_(float n2_, float cos2_, float sin1_sq) {
    vec3 cos3_ = sqrt(max((vec3(1.0) - (vec3(sin1_sq) / vec3(1441.9869, 1441.9869, 1441.9869))), vec3(0.0)));
    vec3 s_1 = ((vec3((n2_ * cos2_)) - (vec3(37.973503, 37.973503, 37.973503) * cos3_)) / max((vec3((n2_ * cos2_)) + (vec3(37.973503, 37.973503, 37.973503) * cos3_)), vec3(1e-12)));
    vec3 p_1 = (((vec3(37.973503, 37.973503, 37.973503) * cos2_) - (vec3(n2_) * cos3_)) / max(((vec3(37.973503, 37.973503, 37.973503) * cos2_) + (vec3(n2_) * cos3_)), vec3(1e-12)));
    return vec3[2](s_1, p_1);
}

WeftFilmStack weft_film_stack_k20_(float cos_theta1_) {
    float cos1_ = clamp(cos_theta1_, 0.0, 1.0);
    float sin1_sq_1 = (1.0 - (cos1_ * cos1_));
    float _e10 = weft_film_ior_k19_();
    float cos2_sq = (1.0 - (sin1_sq_1 / (_e10 * _e10)));
    if ((cos2_sq <= 0.0)) {
        return WeftFilmStack(_e10, 0.0, vec2(1.0), vec3[2](vec3(1.0), vec3(1.0)), true);
    }
    float cos2_1 = sqrt(cos2_sq);
    vec2 _e23 = weft_fresnel_amplitudes_k4_(_e10, cos1_, cos2_1);
    vec3 _e24[2] = weft_film_base_amplitudes_k22_(_e10, cos2_1, sin1_sq_1);
    return WeftFilmStack(_e10, cos2_1, _e23, _e24, false);
}

vec3 weft_film_fourier_layers_k17_(float cos_theta1_1) {
    WeftFilmStack _e6 = weft_film_stack_k20_(cos_theta1_1);
    if (_e6.total_internal_reflection) {
        return vec3(1.0);
    }
    WeftFilmSeries _e13 = weft_film_series(_e6.r12_.x, _e6.r23_[0]);
    WeftFilmSeries _e18 = weft_film_series(_e6.r12_.y, _e6.r23_[1]);
    float path = ((2.0 * _e6.n2_) * _e6.cos2_);
    vec3 _e29 = weft_film_orders((path * 420.0), _e13, _e18);
    vec3 r1_ = ((_e13.dc + _e18.dc) + _e29);
    vec3 _e36 = weft_film_orders((path * 420.0), _e13, _e18);
    vec3 r2_ = ((_e13.dc + _e18.dc) + _e36);
    return clamp((0.25 * (r1_ + r2_)), vec3(0.0), vec3(1.0));
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 n = vec3(0.0);
    float film_cos = 0.0;
    vec2 direction_ts = vec2(1.0, 0.0);
    vec3 surface_base = vec3(0.0);
    vec3 f_light = vec3(0.0);
    vec3 e_spec = vec3(0.0);
    float light_cos = 0.0;
    vec3 film_view = vec3(0.0);
    vec3 film_light = vec3(0.0);
    WeftSurface _e11 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_4 = _e11.v;
    vec3 geometric_n = _e11.n;
    n = geometric_n;
    vec3 _e15 = n;
    WeftLightGeometry _e16 = weft_main_light_geometry(_e15, v_4);
    film_cos = _e16.n_dot_v;
    vec2 _e23 = weft_env_brdf_lut_k6_(_e16.n_dot_v);
    vec3 _e25 = weft_f_schlick_k15_(_e16.v_dot_h);
    f_light = _e25;
    vec3 _e27 = weft_env_brdf_from_lut_k16_(_e23);
    e_spec = _e27;
    {
        light_cos = _e16.v_dot_h;
        {
            float _e36 = film_cos;
            vec3 _e37 = weft_film_fourier_layers_k17_(_e36);
            film_view = _e37;
            float _e38 = light_cos;
            vec3 _e39 = weft_film_fourier_layers_k17_(_e38);
            film_light = _e39;
        }
        vec3 _e40 = f_light;
        vec3 _e41 = film_light;
        f_light = mix(_e40, _e41, 1.0);
        vec3 _e43 = e_spec;
        vec3 _e44 = film_view;
        e_spec = mix(_e43, (_e44 * (_e23.x + _e23.y)), 1.0);
    }
    vec3 _e51 = e_spec;
    vec3 kd = max((vec3(1.0) - _e51), vec3(0.0));
    float _e57 = weft_v_smith_ggx_correlated_k8_(_e16.n_dot_v, _e16.n_dot_l);
    vec3 _e58 = n;
    float _e60 = weft_d_ggx_nh_k9_(_e58, _e16.h);
    vec3 _e62 = f_light;
    vec3 specular = ((_e60 * _e57) * _e62);
    vec3 diffuse = (kd * vec3(0.0, 0.0, 0.0));
    vec3 direct = (((diffuse + specular) * vec3(3.0, 2.8799999, 2.6999998)) * _e16.n_dot_l);
    vec3 _e72 = n;
    vec3 _e74 = weft_prefiltered_radiance_k10_(reflect(-(v_4), _e72));
    vec3 _e75 = e_spec;
    vec3 indirect_specular = (_e74 * _e75);
    vec3 _e77 = n;
    vec3 _e78 = weft_sh_irradiance(_e77);
    vec3 indirect_diffuse = ((_e78 * kd) * vec3(0.0, 0.0, 0.0));
    vec3 color = ((direct + indirect_specular) + indirect_diffuse);
    _fs2p_location0 = vec4(clamp(color, vec3(0.0), vec3(65504.0)), 1.0);
    return;
}

