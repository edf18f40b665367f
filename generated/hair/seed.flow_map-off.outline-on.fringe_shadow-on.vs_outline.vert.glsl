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
    uint strand_along_tangent;
    vec4 jitter_map_st;
    float jitter_strength;
    float anisotropic_direction;
    float strand_noise;
    float strand_density;
    vec4 primary_color;
    float primary_exponent;
    float primary_intensity;
    float primary_shift;
    vec4 secondary_color;
    float secondary_exponent;
    float secondary_intensity;
    float secondary_shift;
    float roughness;
    float azimuthal_roughness;
    float scale_angle;
    float ior;
    vec4 outline_color;
    float outline_width;
    float outline_max_distance;
    vec4 fringe_shadow_color;
    float fringe_shadow_length;
};
struct WeftOutlineVertex {
    vec3 position;
    vec3 normal;
};
struct WeftOutlineVaryings {
    vec4 clip_position;
};
struct WeftFringeShadowVertex {
    vec3 position;
};
struct WeftFringeShadowVaryings {
    vec4 clip_position;
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
struct WeftHair {
    vec3 sigma_a;
    float eta;
    vec4 v;
    float s;
    vec3 sin2k;
    vec3 cos2k;
    vec3 inv_v;
    vec3 mp_norm;
    vec2 blur;
    float r_floor;
    vec4 trt;
    float trt4_;
    float inv_eta;
};
struct WeftHairLobes {
    vec3 s;
    vec3 albedo;
    vec3 back;
};
struct HairVaryings {
    vec4 clip_position;
    vec3 world_position;
    vec3 world_normal;
    vec4 world_tangent;
    vec2 uv0_;
    vec4 fibre;
    vec4 sin2k;
    vec4 cos2k;
    vec4 mp_norm;
    vec4 inv_v;
    vec4 trt;
    vec4 jitter;
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
const float WEFT_HAIR_MIN_BETA_M = 0.05;
const float WEFT_HAIR_MIN_BETA_N = 0.05;
const uint HAIR_REFERENCE_CELLS = 64u;
const float HAIR_TERMINATOR = 0.25;

layout(std140, binding = 0) uniform WeftFrame_block_0Vertex { WeftFrame _group_0_binding_0_vs; };

layout(std140, binding = 2) uniform WeftObject_block_1Vertex { WeftObject _group_2_binding_0_vs; };

layout(std140, binding = 1) uniform WeftMaterial_block_2Vertex { WeftMaterial _group_1_binding_0_vs; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;

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

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e6 = weft_view_direction(world_position_1, vec3(0.0, 0.0, 1.0));
    vec3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

WeftVaryings weft_forward_vertex(WeftVertexInput in_4) {
    WeftVaryings out_2 = WeftVaryings(vec4(0.0), vec3(0.0), vec3(0.0), vec4(0.0), vec2(0.0));
    mat4x4 model = _group_2_binding_0_vs.model;
    mat3x3 model3_ = mat3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    mat4x4 nm = _group_2_binding_0_vs.normal_matrix;
    mat3x3 normal3_ = mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    vec4 world = (model * vec4(in_4.position, 1.0));
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_4.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    mat4x4 _e43 = _group_0_binding_0_vs.view_proj;
    out_2.clip_position = (_e43 * vec4(world.xyz, 1.0));
    out_2.world_position = world.xyz;
    vec3 _e55 = weft_safe_normalize((normal3_ * in_4.normal), vec3(0.0));
    out_2.world_normal = _e55;
    vec3 _e62 = weft_safe_normalize((model3_ * in_4.tangent.xyz), vec3(0.0));
    out_2.world_tangent = vec4(_e62, bitangent_sign);
    out_2.uv0_ = in_4.uv0_;
    WeftVaryings _e66 = out_2;
    return _e66;
}

mat3x3 weft_tangent_frame(vec3 n_2, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_2);
    vec3 t_1 = (ok ? (t_proj * inversesqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_2, t_1) * s_1);
    return mat3x3(t_1, b_1, n_2);
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

float weft_hair_sqr(float x) {
    return (x * x);
}

float weft_hair_safe_sqrt(float x_1) {
    return sqrt(max(x_1, 0.0));
}

float weft_hair_variance(float beta_m) {
    float b_2 = clamp(beta_m, WEFT_HAIR_MIN_BETA_M, 1.0);
    float b2_ = (b_2 * b_2);
    float b4_ = (b2_ * b2_);
    float b20_ = ((((b4_ * b4_) * b4_) * b4_) * b4_);
    float _e18 = weft_hair_sqr((((0.726 * b_2) + (0.812 * b2_)) + (3.7 * b20_)));
    return _e18;
}

float weft_hair_logistic_scale(float beta_n) {
    float b_3 = clamp(beta_n, WEFT_HAIR_MIN_BETA_N, 1.0);
    float b2_1 = (b_3 * b_3);
    float b4_1 = (b2_1 * b2_1);
    float b22_ = (((((b4_1 * b4_1) * b4_1) * b4_1) * b4_1) * b2_1);
    return (0.62665707 * (((0.265 * b_3) + (1.194 * b2_1)) + (5.372 * b22_)));
}

WeftHair weft_hair_params(vec3 sigma_a, float eta, float beta_m_1, float beta_n_1, float alpha_deg) {
    WeftHair hair = WeftHair(vec3(0.0), 0.0, vec4(0.0), 0.0, vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec2(0.0), 0.0, vec4(0.0), 0.0, 0.0);
    hair.sigma_a = max(sigma_a, vec3(0.0));
    hair.eta = max(eta, 1.0001);
    float _e13 = weft_hair_variance(beta_m_1);
    hair.v = vec4(_e13, (0.25 * _e13), (4.0 * _e13), (4.0 * _e13));
    float _e23 = weft_hair_logistic_scale(beta_n_1);
    hair.s = _e23;
    float a_1 = radians(alpha_deg);
    float s0_ = sin(a_1);
    float _e29 = weft_hair_safe_sqrt((1.0 - (s0_ * s0_)));
    float s1_ = ((2.0 * _e29) * s0_);
    float c1_ = ((_e29 * _e29) - (s0_ * s0_));
    float s2_ = ((2.0 * c1_) * s1_);
    float c2_ = ((c1_ * c1_) - (s1_ * s1_));
    hair.sin2k = vec3(s0_, s1_, s2_);
    hair.cos2k = vec3(_e29, c1_, c2_);
    hair.inv_v = (vec3(1.0, 4.0, 0.25) / vec3(_e13));
    float _e55 = hair.inv_v.x;
    float e_trt = exp((-0.5 * _e55));
    float _e60 = weft_hair_sqr((e_trt * e_trt));
    vec3 _e63 = hair.inv_v;
    float _e67 = weft_hair_sqr((_e60 * _e60));
    hair.mp_norm = (_e63 / (vec3(1.0) - vec3(_e60, _e67, e_trt)));
    float _e73 = hair.s;
    float d = (0.8162094 * _e73);
    hair.blur = vec2(sin(d), cos(d));
    float _e81 = hair.s;
    float _e84 = weft_hair_sqr((0.4534 * _e81));
    hair.r_floor = _e84;
    float sh_1 = hair.s;
    hair.trt = vec4((-9.2609 + (sh_1 * (65.993 - (107.38 * sh_1)))), (72.357 + (sh_1 * (-624.68 + (1069.8 * sh_1)))), (-153.75 + (sh_1 * (1704.7 - (3127.5 * sh_1)))), (-67.745 + (sh_1 * (-1105.8 + (2706.6 * sh_1)))));
    hair.trt4_ = (239.74 - (430.94 * sh_1));
    float _e124 = hair.eta;
    hair.inv_eta = (1.0 / _e124);
    WeftHair _e127 = hair;
    return _e127;
}

float hair_noise_period(float density) {
    return max(roundEven(density), 1.0);
}

vec3 hair_strand(mat3x3 frame, vec2 uv0_) {
    vec2 ts = vec2(0.0);
    uint _e10 = _group_1_binding_0_vs.strand_along_tangent;
    ts = ((_e10 != 0u) ? vec2(1.0, 0.0) : vec2(0.0, 1.0));
    float _e17 = ts.x;
    float _e21 = ts.y;
    vec3 _e25 = weft_safe_normalize(((frame[0] * _e17) + (frame[1] * _e21)), frame[1]);
    return _e25;
}

float hair_hash(uint x_2) {
    uint state = ((x_2 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (float(((word >> 22u) ^ word)) * 2.3283064e-10);
}

float hair_value_noise(float x_3, float p) {
    float cell = floor(x_3);
    float f = (x_3 - cell);
    float c0_ = (cell - (p * floor((cell / p))));
    float c1_1 = (((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0));
    float _e16 = hair_hash(uint(c0_));
    float _e18 = hair_hash(uint(c1_1));
    return (mix(_e16, _e18, ((f * f) * (3.0 - (2.0 * f)))) - 0.5);
}

float hair_kajiya_kay(vec3 t, vec3 h_1, float exponent) {
    float t_dot_h = clamp(dot(t, h_1), -1.0, 1.0);
    float sin_th = sqrt(max((1.0 - (t_dot_h * t_dot_h)), 0.0));
    float dir_atten = smoothstep(-1.0, 0.0, t_dot_h);
    return (dir_atten * pow(sin_th, max(exponent, 1.0)));
}

void main() {
    WeftOutlineVertex in_ = WeftOutlineVertex(_p2vs_location0, _p2vs_location1);
    bool local = false;
    bool local_1 = false;
    WeftOutlineVaryings out_ = WeftOutlineVaryings(vec4(0.0));
    mat4x4 _e3 = _group_2_binding_0_vs.model;
    vec4 world_1 = (_e3 * vec4(in_.position, 1.0));
    mat4x4 nm_1 = _group_2_binding_0_vs.normal_matrix;
    vec3 normal = (mat3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz) * in_.normal);
    mat4x4 _e22 = _group_0_binding_0_vs.view_proj;
    vec4 clip = (_e22 * vec4(world_1.xyz, 1.0));
    vec4 _e29 = _group_0_binding_0_vs.viewport;
    vec2 size = _e29.xy;
    mat4x4 _e33 = _group_0_binding_0_vs.view_proj;
    vec2 screen_normal = ((_e33 * vec4(normal, 0.0)).xy * size);
    float len = length(screen_normal);
    if ((len > 1e-6)) {
        float _e47 = _group_0_binding_0_vs.viewport.x;
        local = (_e47 > 0.0);
    } else {
        local = false;
    }
    bool _e51 = local;
    if (_e51) {
        local_1 = (clip.w > 0.0);
    } else {
        local_1 = false;
    }
    bool usable = local_1;
    vec2 direction = (usable ? (screen_normal / vec2(max(len, 1e-6))) : vec2(0.0));
    float _e68 = _group_1_binding_0_vs.outline_width;
    float width_px = max(_e68, 0.0);
    float _e74 = _group_1_binding_0_vs.outline_max_distance;
    float distance_ = min(clip.w, max(_e74, 0.0));
    vec4 _e83 = _group_0_binding_0_vs.viewport;
    vec2 offset = ((((direction * width_px) * 2.0) * _e83.zw) * distance_);
    out_.clip_position = vec4((clip.xy + offset), clip.zw);
    WeftOutlineVaryings _e93 = out_;
    gl_Position = _e93.clip_position;
    gl_Position.yz = vec2(-gl_Position.y, gl_Position.z * 2.0 - gl_Position.w);
    return;
}

