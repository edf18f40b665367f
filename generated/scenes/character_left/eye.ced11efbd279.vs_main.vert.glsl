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
struct EyeCornea {
    float z_iris;
    float centre_z;
    float radius;
};
struct EyeLookup {
    vec2 iris;
    vec3 normal;
    float through_cornea;
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

vec3 weft_safe_normalize_k1_(vec3 v_1) {
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * inversesqrt(max(len2_1, 1e-20))) : vec3(0.0, 0.0, 1.0));
}

vec3 weft_main_light_direction() {
    vec4 _e2 = _group_0_binding_0_vs.light_direction;
    vec3 _e4 = weft_safe_normalize_k1_(_e2.xyz);
    return _e4;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_vs.light_color;
    return max(_e2.xyz, vec3(0.0));
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

vec3 weft_view_direction_k2_(vec3 world_position) {
    vec4 _e4 = _group_0_binding_0_vs.camera_position;
    vec3 _e7 = weft_safe_normalize_k1_((_e4.xyz - world_position));
    return _e7;
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e2 = weft_view_direction_k2_(world_position_1);
    vec3 _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface(_e2, _e3);
}

vec3 weft_safe_normalize_k3_(vec3 v_2) {
    float len2_2 = dot(v_2, v_2);
    return ((len2_2 > 1e-20) ? (v_2 * inversesqrt(max(len2_2, 1e-20))) : vec3(0.0));
}

WeftVaryings weft_forward_vertex(WeftVertexInput in_2) {
    WeftVaryings out_ = WeftVaryings(vec4(0.0), vec3(0.0), vec3(0.0), vec4(0.0), vec2(0.0));
    mat4x4 model = _group_2_binding_0_vs.model;
    mat3x3 model3_ = mat3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    mat4x4 nm = _group_2_binding_0_vs.normal_matrix;
    mat3x3 normal3_1 = mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    vec4 world = (model * vec4(in_2.position, 1.0));
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    mat4x4 _e43 = _group_0_binding_0_vs.view_proj;
    out_.clip_position = (_e43 * vec4(world.xyz, 1.0));
    out_.world_position = world.xyz;
    vec3 _e53 = weft_safe_normalize_k3_((normal3_1 * in_2.normal));
    out_.world_normal = _e53;
    vec3 _e58 = weft_safe_normalize_k3_((model3_ * in_2.tangent.xyz));
    out_.world_tangent = vec4(_e58, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e62 = out_;
    return _e62;
}

vec3 eye_procedural_iris(float rho, float a) {
    vec3 c_1 = vec3(0.0);
    float t = clamp(((rho - 0.38) / 0.62), 0.0, 1.0);
    c_1 = mix(vec3(0.34239164, 0.147319, 0.021980947), vec3(0.10653923, 0.033104766, 0.008540382), smoothstep(0.05, 0.5, t));
    float fibres = ((0.82 + (0.1 * sin(((a * 23.0) + (6.0 * t))))) + (0.08 * sin((((a * 41.0) - (9.0 * t)) + 1.3))));
    vec3 _e35 = c_1;
    c_1 = (_e35 * fibres);
    vec3 _e38 = c_1;
    c_1 = (_e38 * (1.0 - (0.8 * smoothstep(0.88, 1.0, rho))));
    vec3 _e48 = c_1;
    return mix(vec3(0.01), _e48, smoothstep(0.35999998, 0.4, rho));
}

vec3 eye_albedo(vec2 q, bool front) {
    vec3 iris = vec3(0.0);
    float rho_2 = (length(q) / 0.5);
    {
        vec2 qa = ((dot(q, q) > 1e-12) ? q : vec2(1.0, 0.0));
        vec3 _e14 = eye_procedural_iris(rho_2, atan(qa.y, qa.x));
        iris = _e14;
    }
    float to_sclera = (front ? smoothstep(0.985, 1.015, rho_2) : 1.0);
    vec3 _e21 = iris;
    return clamp(mix(_e21, vec3(0.71056646, 0.67385954, 0.6382832), to_sclera), vec3(0.0), vec3(1.0));
}

vec3 weft_f_schlick_k20_(float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (vec3(0.025042804) + (vec3(0.97495717, 0.97495717, 0.97495717) * _e5));
}

float eye_fresnel_k8_(float cos_i) {
    vec3 _e2 = weft_f_schlick_k20_(cos_i);
    return _e2.x;
}

float weft_d_ggx_k14_(float n_dot_h) {
    float noh = clamp(n_dot_h, 0.0, 1.0);
    float one_minus_noh2_ = ((1.0 - noh) * (1.0 + noh));
    float d = (one_minus_noh2_ + ((noh * noh) * 1.2960001e-5));
    return (1.2960001e-5 / ((WEFT_PI * d) * d));
}

float weft_v_smith_ggx_correlated_newton_k15_(float n_dot_v, float n_dot_l) {
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float gv = ((_e6 * 0.9964) + 0.0036000002);
    float gl = ((_e7 * 0.9964) + 0.0036000002);
    float pv = ((gv * _e6) + (1.2960001e-5 * (1.0 - _e6)));
    float pl = ((gl * _e7) + (1.2960001e-5 * (1.0 - _e7)));
    return (((0.5 * gv) * gl) / (((_e7 * gl) * pv) + ((_e6 * gv) * pl)));
}

float eye_ggx_k9_(vec3 s, vec3 h, float s_dot_v, float s_dot_l) {
    float _e7 = weft_d_ggx_k14_(clamp(dot(s, h), 0.0, 1.0));
    float _e8 = weft_v_smith_ggx_correlated_newton_k15_(s_dot_v, s_dot_l);
    return (_e7 * _e8);
}

float weft_specular_mip_k16_() {
    float _e5 = _group_0_binding_0_vs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.09948 * max_mip);
}

vec3 weft_env_brdf_from_lut_k19_(vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((vec3(0.025042804) * sb.x) + vec3(sb.y));
}

float eye_cornea_height_k17_(float rho_1) {
    float z = (0.5380625 + sqrt(max((0.35755965 - (rho_1 * rho_1)), 0.0)));
    return max((z - 0.8660254), 0.0);
}

vec3 eye_cornea_normal_k18_(vec2 xy) {
    float z_1 = sqrt(max((0.35755965 - dot(xy, xy)), 0.0));
    return (vec3(xy, z_1) / vec3(0.5979629));
}

EyeLookup eye_parallax_k13_(vec3 p, vec3 v_4) {
    bool local_1 = false;
    float rho_3 = length(p.xy);
    if (!((p.z <= 0.0))) {
        local_1 = (rho_3 >= 0.5);
    } else {
        local_1 = true;
    }
    bool _e15 = local_1;
    if (_e15) {
        return EyeLookup(p.xy, p, 0.0);
    }
    float _e21 = eye_cornea_height_k17_(rho_3);
    float d_1 = ((0.8660254 + _e21) - p.z);
    vec2 e_raw = (p.xy + (d_1 * v_4.xy));
    vec2 e_1 = (e_raw * min(1.0, (0.5 / max(length(e_raw), 1e-6))));
    float _e37 = eye_cornea_height_k17_(length(e_1));
    vec3 _e38 = eye_cornea_normal_k18_(e_1);
    vec2 iris_1 = (e_1 - (_e37 * ((v_4.xy * 0.7267442) + (_e38.xy * 0.27325583))));
    return EyeLookup(iris_1, _e38, 1.0);
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

