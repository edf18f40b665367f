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

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 0) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 1) uniform sampler2D _group_1_binding_4_fs;

layout(binding = 2) uniform sampler2D _group_1_binding_5_fs;

layout(binding = 3) uniform sampler2D _group_1_binding_6_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 4) flat in vec4 _vs2fs_location4;
layout(location = 5) flat in vec4 _vs2fs_location5;
layout(location = 6) flat in vec4 _vs2fs_location6;
layout(location = 7) flat in vec4 _vs2fs_location7;
layout(location = 8) flat in vec4 _vs2fs_location8;
layout(location = 9) flat in vec4 _vs2fs_location9;
layout(location = 10) flat in vec4 _vs2fs_location10;
layout(location = 0) out vec4 _fs2p_location0;

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
    vec4 _e2 = _group_0_binding_0_fs.light_direction;
    vec3 _e8 = weft_safe_normalize(_e2.xyz, vec3(0.0, 0.0, 1.0));
    return _e8;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_fs.light_color;
    return max(_e2.xyz, vec3(0.0));
}

vec3 weft_view_direction(vec3 world_position, vec3 fallback_1) {
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
    vec3 _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
}

vec3 weft_sh_irradiance(vec3 n_1) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_fs.sh;
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
    uint _e10 = _group_1_binding_0_fs.strand_along_tangent;
    ts = ((_e10 != 0u) ? vec2(1.0, 0.0) : vec2(0.0, 1.0));
    {
        vec4 _e17 = texture(_group_1_binding_4_fs, vec2(uv0_));
        vec2 f = ((_e17.xy * 2.0) - vec2(1.0));
        float len2_2 = dot(f, f);
        vec2 _e25 = ts;
        ts = ((len2_2 > 0.0001) ? (f * inversesqrt(max(len2_2, 1e-12))) : _e25);
    }
    float _e35 = ts.x;
    float _e39 = ts.y;
    vec3 _e43 = weft_safe_normalize(((frame[0] * _e35) + (frame[1] * _e39)), frame[1]);
    return _e43;
}

float hair_hash(uint x_2) {
    uint state = ((x_2 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (float(((word >> 22u) ^ word)) * 2.3283064e-10);
}

float hair_value_noise(float x_3, float p) {
    float cell = floor(x_3);
    float f_1 = (x_3 - cell);
    float c0_ = (cell - (p * floor((cell / p))));
    float c1_1 = (((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0));
    float _e16 = hair_hash(uint(c0_));
    float _e18 = hair_hash(uint(c1_1));
    return (mix(_e16, _e18, ((f_1 * f_1) * (3.0 - (2.0 * f_1)))) - 0.5);
}

float hair_jitter(vec2 uv0_1, vec2 rotation, float noise_period) {
    vec4 _e5 = texture(_group_1_binding_6_fs, vec2(uv0_1));
    float mask = step(0.8, _e5.x);
    float c = rotation.x;
    float s_2 = rotation.y;
    vec2 rotated = vec2(((c * uv0_1.x) + (s_2 * uv0_1.y)), ((-(s_2) * uv0_1.x) + (c * uv0_1.y)));
    vec4 _e28 = _group_1_binding_0_fs.jitter_map_st;
    vec2 _e29 = weft_transform_uv(((mask > 0.5) ? rotated : uv0_1), _e28);
    vec4 _e32 = texture(_group_1_binding_5_fs, vec2(_e29));
    float j = _e32.x;
    uint _e38 = _group_1_binding_0_fs.strand_along_tangent;
    float across = ((_e38 != 0u) ? _e29.y : _e29.x);
    float _e44 = _group_1_binding_0_fs.strand_density;
    float _e46 = hair_value_noise((across * _e44), noise_period);
    float _e49 = _group_1_binding_0_fs.jitter_strength;
    float _e53 = _group_1_binding_0_fs.strand_noise;
    return ((_e49 * j) + (_e53 * _e46));
}

float hair_kajiya_kay(vec3 t, vec3 h_1, float exponent) {
    float t_dot_h = clamp(dot(t, h_1), -1.0, 1.0);
    float sin_th = sqrt(max((1.0 - (t_dot_h * t_dot_h)), 0.0));
    float dir_atten = smoothstep(-1.0, 0.0, t_dot_h);
    return (dir_atten * pow(sin_th, max(exponent, 1.0)));
}

void main() {
    HairVaryings in_2 = HairVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3, _vs2fs_location4, _vs2fs_location5, _vs2fs_location6, _vs2fs_location7, _vs2fs_location8, _vs2fs_location9, _vs2fs_location10);
    vec3 color = vec3(0.0);
    WeftHairLobes lobes = WeftHairLobes(vec3(0.0), vec3(0.0), vec3(0.0));
    vec4 _e4 = _group_1_binding_0_fs.base_map_st;
    vec2 _e5 = weft_transform_uv(in_2.uv0_, _e4);
    vec4 _e8 = _group_1_binding_0_fs.base_color;
    vec4 _e11 = texture(_group_1_binding_3_fs, vec2(_e5));
    vec4 base_rgba = (_e8 * _e11);
    vec3 base = clamp(base_rgba.xyz, vec3(0.0), vec3(1.0));
    float alpha = clamp(base_rgba.w, 0.0, 1.0);
    WeftSurface _e19 = weft_surface(in_2.world_position, in_2.world_normal);
    vec3 v_1 = _e19.v;
    vec3 n_3 = _e19.n;
    mat3x3 _e23 = weft_tangent_frame(n_3, in_2.world_tangent);
    vec3 _e25 = hair_strand(_e23, in_2.uv0_);
    float _e31 = hair_jitter(in_2.uv0_, in_2.jitter.xy, in_2.jitter.w);
    vec3 _e32 = weft_main_light_direction();
    vec3 _e33 = weft_main_light_radiance();
    vec3 _e34 = weft_sh_irradiance(n_3);
    float n_dot_l = dot(n_3, _e32);
    {
        vec3 _e38 = weft_safe_normalize((_e32 + v_1), n_3);
        float _e41 = _group_1_binding_0_fs.primary_shift;
        vec3 _e45 = weft_safe_normalize((_e25 + ((_e41 + _e31) * n_3)), _e25);
        float _e48 = _group_1_binding_0_fs.secondary_shift;
        vec3 _e52 = weft_safe_normalize((_e25 + ((_e48 + _e31) * n_3)), _e25);
        vec4 _e55 = _group_1_binding_0_fs.primary_color;
        float _e59 = _group_1_binding_0_fs.primary_intensity;
        float _e62 = _group_1_binding_0_fs.primary_exponent;
        float _e63 = hair_kajiya_kay(_e45, _e38, _e62);
        vec3 primary = (_e55.xyz * (_e59 * _e63));
        vec4 _e68 = _group_1_binding_0_fs.secondary_color;
        float _e72 = _group_1_binding_0_fs.secondary_intensity;
        float _e75 = _group_1_binding_0_fs.secondary_exponent;
        float _e76 = hair_kajiya_kay(_e52, _e38, _e75);
        vec3 secondary = (_e68.xyz * (_e72 * _e76));
        vec3 direct = (((((base + primary) + secondary) * WEFT_INV_PI) * _e33) * clamp(n_dot_l, 0.0, 1.0));
        color = (direct + (_e34 * base));
    }
    vec3 _e88 = color;
    vec3 radiance = clamp(_e88, vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, alpha);
    return;
}

