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

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_3_fs;

layout(std140, binding = 1) uniform WeftObject_block_1Fragment { WeftObject _group_2_binding_0_fs; };

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

vec3 weft_safe_normalize_k1_(vec3 v_1) {
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * inversesqrt(max(len2_1, 1e-20))) : vec3(0.0, 0.0, 1.0));
}

vec3 weft_main_light_direction() {
    vec4 _e2 = _group_0_binding_0_fs.light_direction;
    vec3 _e4 = weft_safe_normalize_k1_(_e2.xyz);
    return _e4;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_fs.light_color;
    return max(_e2.xyz, vec3(0.0));
}

vec3 weft_sh_irradiance(vec3 n) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_fs.sh;
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
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
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
    mat4x4 model = _group_2_binding_0_fs.model;
    mat3x3 model3_ = mat3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    mat4x4 nm = _group_2_binding_0_fs.normal_matrix;
    mat3x3 normal3_1 = mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    vec4 world = (model * vec4(in_2.position, 1.0));
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    mat4x4 _e43 = _group_0_binding_0_fs.view_proj;
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
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.09948 * max_mip);
}

vec3 weft_prefiltered_radiance_k11_(vec3 dir) {
    float _e4 = weft_specular_mip_k16_();
    vec4 c_2 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_2.xyz, vec3(0.0));
}

vec2 weft_env_brdf_lut_k12_(float n_dot_v_1) {
    vec2 uv = vec2(clamp(n_dot_v_1, 0.0, 1.0), 0.060000002);
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv), 0.0);
    return _e8.xy;
}

vec3 weft_env_brdf_from_lut_k19_(vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((vec3(0.025042804) * sb.x) + vec3(sb.y));
}

vec3 eye_physical_k7_(EyeLookup look_1, vec3 n_1, vec3 v_3, vec3 l, mat3x3 normal3_, vec3 light) {
    bool local = false;
    if (!((look_1.through_cornea > 0.0))) {
        local = (look_1.normal.z > 0.0);
    } else {
        local = true;
    }
    bool _e19 = local;
    vec3 _e20 = eye_albedo(look_1.iris, _e19);
    vec3 _e24 = weft_safe_normalize((normal3_ * look_1.normal), n_1);
    float _e26 = weft_clamp_cos(dot(_e24, v_3));
    float s_dot_l_1 = clamp(dot(_e24, l), 0.0, 1.0);
    vec3 _e30 = weft_safe_normalize((l + v_3), _e24);
    float _e32 = eye_fresnel_k8_(dot(v_3, _e30));
    float _e33 = eye_ggx_k9_(_e24, _e30, _e26, s_dot_l_1);
    float direct_spec = ((_e33 * _e32) * s_dot_l_1);
    vec3 _e39 = weft_prefiltered_radiance_k11_(reflect(-(v_3), _e24));
    vec2 _e40 = weft_env_brdf_lut_k12_(_e26);
    vec3 _e41 = weft_env_brdf_from_lut_k19_(_e40);
    vec3 env = (_e39 * _e41);
    vec3 specular = ((light * direct_spec) + env);
    bool on_iris = (look_1.through_cornea > 0.0);
    vec3 _e50 = weft_safe_normalize((normal3_ * vec3(0.0, 0.0, 1.0)), n_1);
    vec3 l_in = refract(-(l), _e24, 0.7267442);
    float iris_cos = ((s_dot_l_1 > 0.0) ? clamp(dot(_e50, -(l_in)), 0.0, 1.0) : 0.0);
    float _e61 = eye_fresnel_k8_(_e26);
    float t_v = (1.0 - _e61);
    float _e64 = eye_fresnel_k8_(s_dot_l_1);
    float t_l = (1.0 - _e64);
    vec3 diffuse_n = (on_iris ? _e50 : n_1);
    float diffuse_cos = (on_iris ? (iris_cos * t_l) : clamp(dot(n_1, l), 0.0, 1.0));
    float transmission = (on_iris ? t_v : 1.0);
    vec3 _e78 = weft_sh_irradiance(diffuse_n);
    vec3 diffuse = ((_e20 * transmission) * ((light * (WEFT_INV_PI * diffuse_cos)) + _e78));
    return (diffuse + specular);
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
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 color = vec3(0.0);
    EyeLookup look = EyeLookup(vec2(0.0), vec3(0.0), 0.0);
    mat4x4 model_1 = _group_2_binding_0_fs.model;
    mat3x3 model3_1 = mat3x3(model_1[0].xyz, model_1[1].xyz, model_1[2].xyz);
    mat4x4 nm_1 = _group_2_binding_0_fs.normal_matrix;
    mat3x3 normal3_2 = mat3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    WeftSurface _e23 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_5 = _e23.v;
    vec3 n_2 = _e23.n;
    vec3 _e26 = weft_main_light_direction();
    vec3 _e29 = weft_safe_normalize_k1_((transpose(model3_1) * n_2));
    vec3 _e32 = weft_safe_normalize_k1_((transpose(normal3_2) * v_5));
    vec3 _e35 = weft_safe_normalize((model3_1 * vec3(0.0, 0.0, 1.0)), n_2);
    float dimming = (1.0 - (0.5 * clamp(-(dot(_e35, _e26)), 0.0, 1.0)));
    vec3 _e43 = weft_main_light_radiance();
    {
        {
            EyeLookup _e48 = eye_parallax_k13_(_e29, _e32);
            look = _e48;
        }
        EyeLookup _e49 = look;
        vec3 _e50 = eye_physical_k7_(_e49, n_2, v_5, _e26, normal3_2, _e43);
        color = _e50;
    }
    vec3 _e51 = color;
    vec3 radiance = clamp((_e51 * dimming), vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, 1.0);
    return;
}

