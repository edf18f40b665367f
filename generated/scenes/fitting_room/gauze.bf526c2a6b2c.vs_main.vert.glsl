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
    vec4 _e4 = _group_0_binding_0_vs.camera_position;
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
    float _e5 = _group_0_binding_0_vs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.62325 * max_mip);
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

