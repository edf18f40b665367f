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

layout(std140, binding = 0) uniform WeftFrame_block_0Vertex { WeftFrame _group_0_binding_0_vs; };

layout(std140, binding = 1) uniform WeftObject_block_1Vertex { WeftObject _group_2_binding_0_vs; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec4 _p2vs_location2;
layout(location = 3) in vec2 _p2vs_location3;
layout(location = 0) smooth out vec3 _vs2fs_location0;
layout(location = 1) smooth out vec3 _vs2fs_location1;
layout(location = 2) smooth out vec4 _vs2fs_location2;
layout(location = 3) smooth out vec2 _vs2fs_location3;

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
    vec4 _e4 = _group_0_binding_0_vs.camera_position;
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

WeftVaryings weft_forward_vertex(WeftVertexInput in_2) {
    WeftVaryings out_ = WeftVaryings(vec4(0.0), vec3(0.0), vec3(0.0), vec4(0.0), vec2(0.0));
    mat4x4 model = _group_2_binding_0_vs.model;
    mat3x3 model3_ = mat3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    mat4x4 nm = _group_2_binding_0_vs.normal_matrix;
    mat3x3 normal3_ = mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    vec4 world = (model * vec4(in_2.position, 1.0));
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    mat4x4 _e43 = _group_0_binding_0_vs.view_proj;
    out_.clip_position = (_e43 * vec4(world.xyz, 1.0));
    out_.world_position = world.xyz;
    vec3 _e53 = weft_safe_normalize_k3_((normal3_ * in_2.normal));
    out_.world_normal = _e53;
    vec3 _e58 = weft_safe_normalize_k3_((model3_ * in_2.tangent.xyz));
    out_.world_tangent = vec4(_e58, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e62 = out_;
    return _e62;
}

vec2 weft_fresnel_amplitudes_k4_(float n_t, float cos_i, float cos_t) {
    float rs = ((cos_i - (n_t * cos_t)) / max((cos_i + (n_t * cos_t)), 1e-12));
    float rp = (((n_t * cos_i) - cos_t) / max(((n_t * cos_i) + cos_t), 1e-12));
    return vec2(rs, rp);
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
    float _e5 = _group_0_binding_0_vs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.312 * max_mip);
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

void main() {
    WeftVertexInput in_ = WeftVertexInput(_p2vs_location0, _p2vs_location1, _p2vs_location2, _p2vs_location3);
    WeftVaryings _e1 = weft_forward_vertex(in_);
    gl_Position = _e1.clip_position;
    _vs2fs_location0 = _e1.world_position;
    _vs2fs_location1 = _e1.world_normal;
    _vs2fs_location2 = _e1.world_tangent;
    _vs2fs_location3 = _e1.uv0_;
    gl_Position.yz = vec2(-gl_Position.y, gl_Position.z * 2.0 - gl_Position.w);
    return;
}

