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
    vec4 base_color;
    vec4 base_map_st;
    float normal_strength;
    float roughness;
    float specular;
    float curvature_factor;
    float dark_bound;
    float bright_bound;
    float lobe_weight;
    vec4 outline_color;
    float outline_width;
    float outline_max_distance;
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
const vec3 skin_lut_shape = vec3(4.0, 10.0, 20.0);
const float skin_lut_ring = 3.1415927;
const vec3 seed_lut_shape = vec3(4.0, 10.0, 20.0);
const float seed_lut_ring = 1.5707964;
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

float weft_pow5_(float x) {
    float x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

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

float weft_d_ggx_nh(vec3 n_1, vec3 h, float roughness_1) {
    float _e3 = weft_clamp_roughness(roughness_1);
    float a = (_e3 * _e3);
    float a2_ = (a * a);
    float noh = clamp(dot(n_1, h), 0.0, 1.0);
    vec3 nxh = cross(n_1, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d * d), 1e-30)));
}

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
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

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
}

vec3 weft_env_brdf_from_lut(vec3 f0_1, vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((f0_1 * sb.x) + vec3(sb.y));
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

vec3 weft_sh_irradiance(vec3 n_2) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_vs.sh;
    e = (sh[0].xyz * 0.282095);
    vec3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_2.y)));
    vec3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_2.z)));
    vec3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_2.x)));
    vec3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_2.x) * n_2.y)));
    vec3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_2.y) * n_2.z)));
    vec3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_2.z) * n_2.z) - 1.0))));
    vec3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_2.x) * n_2.z)));
    vec3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_2.x * n_2.x) - (n_2.y * n_2.y)))));
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

WeftLightGeometry weft_main_light_geometry(vec3 n_3, vec3 v_1) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_1), n_3);
    float _e6 = weft_clamp_cos(dot(n_3, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_3, _e2), 0.0, 1.0), clamp(dot(n_3, _e4), 0.0, 1.0), clamp(dot(v_1, _e4), 0.0, 1.0));
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
    vec3 _e55 = weft_safe_normalize((normal3_ * in_2.normal), vec3(0.0));
    out_.world_normal = _e55;
    vec3 _e62 = weft_safe_normalize((model3_ * in_2.tangent.xyz), vec3(0.0));
    out_.world_tangent = vec4(_e62, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out_;
    return _e66;
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

vec3 skin_preintegrated(float cos_theta, float curvature_1, vec3 shape, float x_max) {
    vec3 num = vec3(0.0);
    vec3 den = vec3(0.0);
    uint k = 0u;
    float g = 0.0;
    float dg = 0.0;
    float flat_ = max(cos_theta, 0.0);
    if ((curvature_1 <= 0.0)) {
        return vec3(flat_);
    }
    float r_1 = (1.0 / curvature_1);
    float theta = acos(clamp(cos_theta, -1.0, 1.0));
    float s_max = max(shape.x, max(shape.y, shape.z));
    float a_2 = min(log((1.0 + ((x_max * s_max) * r_1))), 40.0);
    float e_1 = (exp(a_2) - 1.0);
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            uint _e100 = k;
            k = (_e100 + 1u);
        }
        loop_init = false;
        uint _e38 = k;
        if ((_e38 < 64u)) {
        } else {
            break;
        }
        {
            uint _e41 = k;
            float t = ((float(_e41) + 0.5) / 64.0);
            g = t;
            dg = 1.0;
            if ((a_2 >= 0.0001)) {
                g = ((exp((a_2 * t)) - 1.0) / e_1);
                dg = ((a_2 * exp((a_2 * t))) / e_1);
            }
            float _e61 = g;
            float x_1 = (x_max * _e61);
            float _e63 = dg;
            float jac = (x_max * _e63);
            float d_1 = ((2.0 * r_1) * abs(sin((0.5 * x_1))));
            float light = (max(cos((theta + x_1)), 0.0) + max(cos((theta - x_1)), 0.0));
            vec3 w_1 = ((exp((-(shape) * d_1)) + exp(((-(shape) * d_1) / vec3(3.0)))) * jac);
            vec3 _e92 = num;
            num = (_e92 + (light * w_1));
            vec3 _e95 = den;
            den = (_e95 + (2.0 * w_1));
        }
    }
    vec3 _e103 = num;
    vec3 _e104 = den;
    vec3 _e109 = den;
    return mix(vec3(flat_), (_e103 / max(_e104, vec3(1e-30))), greaterThan(_e109, vec3(0.0)));
}

float skin_dual_ggx(vec3 n_4, vec3 h_1, float n_dot_v_2, float n_dot_l_1, float v_dot_h_1, float roughness_6, float w, float f0_2) {
    float r0_ = clamp((roughness_6 * 0.75), 0.0, 1.0);
    float r1_ = clamp((roughness_6 * 1.3), 0.0, 1.0);
    float _e18 = weft_d_ggx_nh(n_4, h_1, r0_);
    float _e19 = weft_v_smith_ggx_correlated(n_dot_v_2, n_dot_l_1, r0_);
    float lobe0_ = (_e18 * _e19);
    float _e21 = weft_d_ggx_nh(n_4, h_1, r1_);
    float _e22 = weft_v_smith_ggx_correlated(n_dot_v_2, n_dot_l_1, r1_);
    float lobe1_ = (_e21 * _e22);
    vec3 _e25 = weft_f_schlick(vec3(f0_2), v_dot_h_1);
    float f = _e25.x;
    return (mix(lobe0_, lobe1_, clamp(w, 0.0, 1.0)) * f);
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

