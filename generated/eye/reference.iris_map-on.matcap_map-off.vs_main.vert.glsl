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
struct WeftMaterial {
    float iris_radius;
    float pupil_size;
    vec4 iris_color;
    vec4 iris_inner_color;
    float limbus_width;
    vec4 sclera_color;
    float cornea_height;
    float cornea_ior;
    float cornea_smoothness;
    float specular_strength;
    float backlight_dimming;
    float parallax_height;
    float matcap_intensity;
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

layout(std140, binding = 2) uniform WeftObject_block_1Vertex { WeftObject _group_2_binding_0_vs; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec4 _p2vs_location2;
layout(location = 3) in vec2 _p2vs_location3;
layout(location = 0) smooth out vec3 _vs2fs_location0;
layout(location = 1) smooth out vec3 _vs2fs_location1;
layout(location = 2) smooth out vec4 _vs2fs_location2;
layout(location = 3) smooth out vec2 _vs2fs_location3;

float weft_clamp_cos(float c) {
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

float weft_clamp_roughness(float roughness) {
    return clamp(roughness, WEFT_MIN_ROUGHNESS, 1.0);
}

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

float weft_d_ggx_nh(vec3 n, vec3 h, float roughness_1) {
    float _e3 = weft_clamp_roughness(roughness_1);
    float a = (_e3 * _e3);
    float a2_ = (a * a);
    float noh = clamp(dot(n, h), 0.0, 1.0);
    vec3 nxh = cross(n, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d * d), 1e-30)));
}

float weft_f_dielectric(float cos_i, float eta) {
    float c_2 = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c_2 * c_2));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c_2);
    float gpc = max((g + c_2), 1e-7);
    float b_den = max(((c_2 * gmc) + 1.0), 1e-7);
    float b_num = ((c_2 * gpc) - 1.0);
    float inv = (1.0 / (gpc * b_den));
    float f = clamp(((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)), 0.0, 1.0);
    return ((g2_ < 0.0) ? 1.0 : f);
}

float weft_f0_from_ior(float ior) {
    float q_1 = ((ior - 1.0) / max((ior + 1.0), 0.0001));
    return (q_1 * q_1);
}

float weft_v_smith_ggx_correlated(float n_dot_v, float n_dot_l, float roughness_2) {
    float _e3 = weft_clamp_roughness(roughness_2);
    float a_1 = (_e3 * _e3);
    float a2_1 = (a_1 * a_1);
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * (1.0 - a2_1)) + a2_1)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * (1.0 - a2_1)) + a2_1)));
    return (0.5 / (lv + ll));
}

vec3 weft_env_brdf_from_lut(vec3 f0_, vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((f0_ * sb.x) + vec3(sb.y));
}

vec3 weft_main_light_direction() {
    vec4 _e2 = _group_0_binding_0_vs.light_direction;
    vec3 _e8 = weft_safe_normalize(_e2.xyz, vec3(0.0, 0.0, 1.0));
    return _e8;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_vs.light_color;
    return max(_e2.xyz, vec3(0.0));
}

vec3 weft_view_direction(vec3 world_position, vec3 fallback_1) {
    vec4 _e4 = _group_0_binding_0_vs.camera_position;
    vec3 _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
}

vec3 weft_sh_irradiance(vec3 n_1) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_vs.sh;
    e = (sh[0].xyz * 0.282095);
    vec3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_1.y)));
    vec3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_1.z)));
    vec3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_1.x)));
    vec3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_1.x) * n_1.y)));
    vec3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_1.y) * n_1.z)));
    vec3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0))));
    vec3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_1.x) * n_1.z)));
    vec3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    vec3 _e91 = e;
    return max(_e91, vec3(0.0));
}

float weft_specular_mip(float roughness_3) {
    float r = clamp(roughness_3, 0.0, 1.0);
    float _e5 = _group_0_binding_0_vs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e6 = weft_view_direction(world_position_1, vec3(0.0, 0.0, 1.0));
    vec3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
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
    vec3 _e55 = weft_safe_normalize((normal3_1 * in_2.normal), vec3(0.0));
    out_.world_normal = _e55;
    vec3 _e62 = weft_safe_normalize((model3_ * in_2.tangent.xyz), vec3(0.0));
    out_.world_tangent = vec4(_e62, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out_;
    return _e66;
}

EyeCornea eye_cornea(float iris_radius, float height) {
    float r_1 = clamp(iris_radius, 0.05, 0.95);
    float h_2 = max(height, 0.01);
    float z_iris_1 = sqrt((1.0 - (r_1 * r_1)));
    float radius = (((r_1 * r_1) + (h_2 * h_2)) / (2.0 * h_2));
    return EyeCornea(z_iris_1, ((z_iris_1 + h_2) - radius), radius);
}

vec2 eye_to_iris_plane(vec3 start, vec3 t, float z_iris) {
    float down = max(-(t.z), 0.0001);
    return (start.xy + (t.xy * ((start.z - z_iris) / down)));
}

EyeLookup eye_refracted(vec3 p, vec3 v_1, EyeCornea c_1, float ior_1) {
    bool local = false;
    bool local_1 = false;
    vec3 centre = vec3(0.0, 0.0, c_1.centre_z);
    vec3 o = (p - centre);
    float b = dot(o, v_1);
    float disc = ((b * b) - (dot(o, o) - (c_1.radius * c_1.radius)));
    float s_1 = (-(b) + sqrt(max(disc, 0.0)));
    vec3 hit = (p + (s_1 * v_1));
    if (!((p.z <= 0.0))) {
        local = (disc <= 0.0);
    } else {
        local = true;
    }
    bool _e33 = local;
    if (!(_e33)) {
        local_1 = (hit.z < c_1.z_iris);
    } else {
        local_1 = true;
    }
    bool _e41 = local_1;
    if (_e41) {
        return EyeLookup(p.xy, p, 0.0);
    }
    vec3 n_3 = ((hit - centre) / vec3(c_1.radius));
    vec3 t_1 = refract(-(v_1), n_3, (1.0 / max(ior_1, 1.0)));
    vec2 _e56 = eye_to_iris_plane(hit, t_1, c_1.z_iris);
    return EyeLookup(_e56, n_3, 1.0);
}

vec2 eye_uv_from_xy(vec2 xy) {
    return vec2((0.5 + (0.5 * xy.x)), (0.5 - (0.5 * xy.y)));
}

float eye_fresnel(float cos_i_1, float ior_2) {
    {
        float _e2 = weft_f_dielectric(cos_i_1, ior_2);
        return _e2;
    }
}

float eye_ggx(vec3 s, vec3 h_1, float s_dot_v, float s_dot_l, float roughness_6) {
    {
        float _e5 = weft_d_ggx_nh(s, h_1, roughness_6);
        float _e6 = weft_v_smith_ggx_correlated(s_dot_v, s_dot_l, roughness_6);
        return (_e5 * _e6);
    }
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

