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
};
struct WeftHairAttenuation {
    float a0_;
    vec3 a1_;
    vec3 a2_;
    vec3 a3_;
    float gamma_t;
};
struct WeftHairLobes {
    vec3 s;
    vec3 albedo;
    vec3 back;
};
struct WeftHairAngles {
    vec4 theta;
    float phi;
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
const uint HAIR_FAST_CELLS = 12u;
const float HAIR_TERMINATOR = 0.25;

layout(std140, binding = 0) uniform WeftFrame_block_0Vertex { WeftFrame _group_0_binding_0_vs; };

layout(std140, binding = 1) uniform WeftObject_block_1Vertex { WeftObject _group_2_binding_0_vs; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_any_perpendicular(vec3 n) {
    float s_8 = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a_1 = (-1.0 / (s_8 + n.z));
    float b = ((n.x * n.y) * a_1);
    return vec3((1.0 + (((s_8 * n.x) * n.x) * a_1)), (s_8 * b), (-(s_8) * n.x));
}

float weft_f_dielectric(float cos_i, float eta) {
    float c = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c * c));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c);
    float gpc = max((g + c), 1e-7);
    float a_2 = (gmc / gpc);
    float b_1 = (((c * gpc) - 1.0) / max(((c * gmc) + 1.0), 1e-7));
    float f = clamp((((0.5 * a_2) * a_2) * (1.0 + (b_1 * b_1))), 0.0, 1.0);
    return ((g2_ < 0.0) ? 1.0 : f);
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

mat3x3 weft_tangent_frame(vec3 n_2, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_2 = dot(t_proj, t_proj);
    bool ok = (len2_2 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_2);
    vec3 t_1 = (ok ? (t_proj * inversesqrt(max(len2_2, 1e-20))) : _e13);
    float s_9 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_2 = (cross(n_2, t_1) * s_9);
    return mat3x3(t_1, b_2, n_2);
}

float weft_hair_sqr(float x) {
    return (x * x);
}

float weft_hair_safe_sqrt(float x_1) {
    return sqrt(max(x_1, 0.0));
}

float weft_hair_i0_(float x_2) {
    float term = 1.0;
    float sum = 1.0;
    int i = 1;
    float q = ((0.25 * x_2) * x_2);
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e22 = i;
            i = (_e22 + 1);
        }
        loop_init = false;
        int _e10 = i;
        if ((_e10 < 16)) {
        } else {
            break;
        }
        {
            int _e13 = i;
            float k_1 = float(_e13);
            float _e15 = term;
            term = (_e15 * (q / (k_1 * k_1)));
            float _e19 = sum;
            float _e20 = term;
            sum = (_e19 + _e20);
        }
    }
    float _e25 = sum;
    return _e25;
}

float weft_hair_log_i0_(float x_3) {
    if ((x_3 > 12.0)) {
        float r = (1.0 / x_3);
        return ((x_3 - (0.5 * log((6.2831855 * x_3)))) + log((1.0 + (r * (0.125 + (0.0703125 * r))))));
    }
    float _e20 = weft_hair_i0_(x_3);
    return log(_e20);
}

float weft_hair_mp(float cos_i_1, float cos_o, float sin_i, float sin_o, float v_2) {
    float a_3 = ((cos_i_1 * cos_o) / v_2);
    float b_3 = ((sin_i * sin_o) / v_2);
    if ((v_2 <= 0.1)) {
        float _e11 = weft_hair_log_i0_(a_3);
        return exp(((((_e11 - b_3) - (1.0 / v_2)) + 0.6931472) + log((1.0 / (2.0 * v_2)))));
    }
    float _e27 = weft_hair_i0_(a_3);
    return ((exp(-(b_3)) * _e27) / ((sinh((1.0 / v_2)) * 2.0) * v_2));
}

vec4 weft_hair_longitudinal(WeftHair hair, float sin_o_1, float cos_o_1, float sin_i_1, float cos_i_2) {
    float sin_r = ((sin_o_1 * hair.cos2k.y) - (cos_o_1 * hair.sin2k.y));
    float cos_r = abs(((cos_o_1 * hair.cos2k.y) + (sin_o_1 * hair.sin2k.y)));
    float sin_tt = ((sin_o_1 * hair.cos2k.x) + (cos_o_1 * hair.sin2k.x));
    float cos_tt = abs(((cos_o_1 * hair.cos2k.x) - (sin_o_1 * hair.sin2k.x)));
    float sin_trt = ((sin_o_1 * hair.cos2k.z) + (cos_o_1 * hair.sin2k.z));
    float cos_trt = abs(((cos_o_1 * hair.cos2k.z) - (sin_o_1 * hair.sin2k.z)));
    float _e52 = weft_hair_mp(cos_i_2, cos_r, sin_i_1, sin_r, hair.v.x);
    float _e55 = weft_hair_mp(cos_i_2, cos_tt, sin_i_1, sin_tt, hair.v.y);
    float _e58 = weft_hair_mp(cos_i_2, cos_trt, sin_i_1, sin_trt, hair.v.z);
    float _e61 = weft_hair_mp(cos_i_2, cos_o_1, sin_i_1, sin_o_1, hair.v.w);
    return vec4(_e52, _e55, _e58, _e61);
}

float weft_hair_logistic(float x_4, float s) {
    float e_1 = exp((-(abs(x_4)) / s));
    float _e8 = weft_hair_sqr((1.0 + e_1));
    return (e_1 / (s * _e8));
}

float weft_hair_trimmed_logistic(float x_5, float s_1) {
    float e_2 = exp((-3.1415927 / s_1));
    float _e5 = weft_hair_logistic(x_5, s_1);
    return ((_e5 * (1.0 + e_2)) / (1.0 - e_2));
}

float weft_hair_etap(WeftHair hair_1, float sin_o_2, float cos_o_2) {
    return (sqrt(((hair_1.eta * hair_1.eta) - (sin_o_2 * sin_o_2))) / max(cos_o_2, 0.0001));
}

WeftHairAttenuation weft_hair_attenuation(WeftHair hair_2, float sin_o_3, float cos_o_3, float h) {
    WeftHairAttenuation a = WeftHairAttenuation(0.0, vec3(0.0), vec3(0.0), vec3(0.0), 0.0);
    float sin_t = (sin_o_3 / hair_2.eta);
    float _e9 = weft_hair_safe_sqrt((1.0 - (sin_t * sin_t)));
    float _e10 = weft_hair_etap(hair_2, sin_o_3, cos_o_3);
    float sin_gamma_t = clamp((h / _e10), -1.0, 1.0);
    float _e18 = weft_hair_safe_sqrt((1.0 - (sin_gamma_t * sin_gamma_t)));
    vec3 t_2 = exp((-(hair_2.sigma_a) * ((2.0 * _e18) / max(_e9, 0.0001))));
    float _e31 = weft_hair_safe_sqrt((1.0 - (h * h)));
    float _e34 = weft_f_dielectric((cos_o_3 * _e31), hair_2.eta);
    a.a0_ = _e34;
    a.a1_ = (((1.0 - _e34) * (1.0 - _e34)) * t_2);
    vec3 _e46 = a.a1_;
    a.a2_ = ((_e46 * t_2) * _e34);
    vec3 _e51 = a.a2_;
    a.a3_ = (((_e51 * t_2) * _e34) / (vec3(1.0) - (t_2 * _e34)));
    a.gamma_t = asin(sin_gamma_t);
    WeftHairAttenuation _e60 = a;
    return _e60;
}

WeftHairAngles weft_hair_angles(vec3 t, vec3 o, vec3 i_1) {
    WeftHairAngles out_3 = WeftHairAngles(vec4(0.0), 0.0);
    float sin_o_4 = clamp(dot(o, t), -1.0, 1.0);
    float sin_i_2 = clamp(dot(i_1, t), -1.0, 1.0);
    float _e16 = weft_hair_safe_sqrt((1.0 - (sin_o_4 * sin_o_4)));
    float _e20 = weft_hair_safe_sqrt((1.0 - (sin_i_2 * sin_i_2)));
    out_3.theta = vec4(sin_o_4, _e16, sin_i_2, _e20);
    vec3 o_perp = (o - (sin_o_4 * t));
    vec3 i_perp = (i_1 - (sin_i_2 * t));
    float len2_3 = (dot(o_perp, o_perp) * dot(i_perp, i_perp));
    float cos_phi = ((len2_3 > 1e-12) ? (dot(o_perp, i_perp) * inversesqrt(max(len2_3, 1e-30))) : 1.0);
    out_3.phi = acos(clamp(cos_phi, -1.0, 1.0));
    WeftHairAngles _e43 = out_3;
    return _e43;
}

float weft_hair_logistic_cdf(float x_6, float s_2) {
    return (1.0 / (1.0 + exp((-(x_6) / s_2))));
}

float weft_hair_logistic_cdf_k3_(float s_3) {
    return (1.0 / (1.0 + exp((3.1415927 / s_3))));
}

float weft_hair_logistic_cdf_k4_(float s_4) {
    return (1.0 / (1.0 + exp((-3.1415927 / s_4))));
}

float weft_hair_trimmed_integral(float lo, float hi, float s_5) {
    float sum_1 = 0.0;
    float _e3 = weft_hair_logistic_cdf_k3_(s_5);
    float _e4 = weft_hair_logistic_cdf_k4_(s_5);
    float a_4 = clamp(lo, -3.1415927, WEFT_PI);
    float b_4 = clamp(hi, -3.1415927, WEFT_PI);
    float _e11 = weft_hair_logistic_cdf(b_4, s_5);
    float _e12 = weft_hair_logistic_cdf(a_4, s_5);
    sum_1 = (_e11 - _e12);
    if ((hi > WEFT_PI)) {
        float _e17 = sum_1;
        float _e22 = weft_hair_logistic_cdf(min((hi - 6.2831855), WEFT_PI), s_5);
        sum_1 = (_e17 + (_e22 - _e3));
    }
    if ((lo < -3.1415927)) {
        float _e27 = sum_1;
        float _e32 = weft_hair_logistic_cdf(max((lo + 6.2831855), -3.1415927), s_5);
        sum_1 = (_e27 + (_e4 - _e32));
    }
    float _e35 = sum_1;
    return (_e35 / (_e4 - _e3));
}

float weft_hair_np_cell(float d0_, float d1_, float s_6) {
    float mid = (0.5 * (d0_ + d1_));
    float m = (mid - (6.2831855 * roundEven((mid / 6.2831855))));
    float half_ = min((0.5 * abs((d1_ - d0_))), WEFT_PI);
    if ((half_ < 0.0001)) {
        float _e20 = weft_hair_trimmed_logistic(m, s_6);
        return _e20;
    }
    float _e23 = weft_hair_trimmed_integral((m - half_), (m + half_), s_6);
    return (_e23 / (2.0 * half_));
}

vec3 hair_strand(mat3x3 frame, vec2 uv0_) {
    vec2 ts = vec2(0.0);
    ts = vec2(0.0, 1.0);
    float _e6 = ts.x;
    float _e10 = ts.y;
    vec3 _e14 = weft_safe_normalize(((frame[0] * _e6) + (frame[1] * _e10)), frame[1]);
    return _e14;
}

float hair_hash(uint x_7) {
    uint state = ((x_7 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (float(((word >> 22u) ^ word)) * 2.3283064e-10);
}

vec2 weft_transform_uv_k5_(vec2 uv) {
    return (uv + vec2(0.0, 0.0));
}

float hair_value_noise_k6_(float x_8) {
    float cell = floor(x_8);
    float f_1 = (x_8 - cell);
    float c0_ = (cell - (128.0 * floor((cell / 128.0))));
    float c1_ = (((c0_ + 1.0) >= 128.0) ? 0.0 : (c0_ + 1.0));
    float _e17 = hair_hash(uint(c0_));
    float _e19 = hair_hash(uint(c1_));
    return (mix(_e17, _e19, ((f_1 * f_1) * (3.0 - (2.0 * f_1)))) - 0.5);
}

vec3 weft_safe_normalize_k7_(vec3 v_3) {
    float len2_4 = dot(v_3, v_3);
    return ((len2_4 > 1e-20) ? (v_3 * inversesqrt(max(len2_4, 1e-20))) : vec3(0.0));
}

WeftHairLobes weft_hair_mean_k10_(WeftHair hair_3, WeftHairAngles angles) {
    vec3 s_7 = vec3(0.0);
    vec3 albedo = vec3(0.0);
    vec3 back = vec3(0.0);
    float weights = 0.0;
    float g0_ = -1.5707964;
    vec3 d0_1 = vec3(0.0);
    uint k = 0u;
    WeftHairLobes out_4 = WeftHairLobes(vec3(0.0), vec3(0.0), vec3(0.0));
    vec4 th = angles.theta;
    vec4 _e8 = weft_hair_longitudinal(hair_3, th.x, th.y, th.z, th.w);
    float _e11 = weft_hair_etap(hair_3, th.x, th.y);
    d0_1 = (vec3(angles.phi) - (((vec3(0.0, 2.0, 4.0) * asin(clamp((-1.0 / _e11), -1.0, 1.0))) - vec3(-3.1415927)) + vec3(0.0, 3.1415927, 6.2831855)));
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e130 = k;
            k = (_e130 + 1u);
        }
        loop_init_1 = false;
        uint _e42 = k;
        if ((_e42 < 12u)) {
        } else {
            break;
        }
        {
            float _e44 = g0_;
            float g1_ = (_e44 + 0.2617994);
            float gamma_t1_ = asin(clamp((sin(g1_) / _e11), -1.0, 1.0));
            vec3 d1_1 = (vec3(angles.phi) - (((vec3(0.0, 2.0, 4.0) * gamma_t1_) - vec3((2.0 * g1_))) + vec3(0.0, 3.1415927, 6.2831855)));
            float _e63 = g0_;
            float gm = (_e63 + 0.1308997);
            float w = cos(gm);
            WeftHairAttenuation _e70 = weft_hair_attenuation(hair_3, th.x, th.y, sin(gm));
            float _e75 = d0_1.x;
            float _e78 = weft_hair_np_cell(_e75, d1_1.x, hair_3.s);
            float _e84 = d0_1.y;
            float _e87 = weft_hair_np_cell(_e84, d1_1.y, hair_3.s);
            float _e95 = d0_1.z;
            float _e98 = weft_hair_np_cell(_e95, d1_1.z, hair_3.s);
            vec3 lobes_1 = (((vec3(((_e8.x * _e70.a0_) * _e78)) + ((_e8.y * _e70.a1_) * _e87)) + ((_e8.z * _e70.a2_) * _e98)) + ((_e8.w * _e70.a3_) * 0.15915494));
            vec3 _e107 = s_7;
            s_7 = (_e107 + (w * lobes_1));
            vec3 _e110 = albedo;
            albedo = (_e110 + (w * (((vec3(_e70.a0_) + _e70.a1_) + _e70.a2_) + _e70.a3_)));
            vec3 _e121 = back;
            back = (_e121 + (w * (vec3(_e70.a0_) + _e70.a2_)));
            float _e128 = weights;
            weights = (_e128 + w);
            g0_ = g1_;
            d0_1 = d1_1;
        }
    }
    vec3 _e135 = s_7;
    float _e136 = weights;
    out_4.s = (_e135 / vec3(_e136));
    vec3 _e140 = albedo;
    float _e141 = weights;
    out_4.albedo = (_e140 / vec3(_e141));
    vec3 _e145 = back;
    float _e146 = weights;
    out_4.back = (_e145 / vec3(_e146));
    WeftHairLobes _e149 = out_4;
    return _e149;
}

WeftHair weft_hair_params_k14_() {
    WeftHair hair_4 = WeftHair(vec3(0.0), 0.0, vec4(0.0), 0.0, vec3(0.0), vec3(0.0));
    hair_4.sigma_a = vec3(0.19707139, 0.44586682, 0.7557883);
    hair_4.eta = 1.55;
    hair_4.v = vec4(0.03157018, 0.007892545, 0.12628073, 0.12628073);
    hair_4.s = 0.11715981;
    hair_4.sin2k = vec3(0.034899496, 0.06975647, 0.1391731);
    hair_4.cos2k = vec3(0.99939084, 0.9975641, 0.9902682);
    WeftHair _e26 = hair_4;
    return _e26;
}

void main() {
    WeftOutlineVertex in_ = WeftOutlineVertex(_p2vs_location0, _p2vs_location1);
    bool local = false;
    bool local_1 = false;
    WeftOutlineVaryings out_ = WeftOutlineVaryings(vec4(0.0));
    mat4x4 _e3 = _group_2_binding_0_vs.model;
    vec4 world = (_e3 * vec4(in_.position, 1.0));
    mat4x4 nm = _group_2_binding_0_vs.normal_matrix;
    vec3 normal = (mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz) * in_.normal);
    mat4x4 _e22 = _group_0_binding_0_vs.view_proj;
    vec4 clip = (_e22 * vec4(world.xyz, 1.0));
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
    float distance_ = min(clip.w, 10.0);
    vec4 _e74 = _group_0_binding_0_vs.viewport;
    vec2 offset = ((((direction * 1.5) * 2.0) * _e74.zw) * distance_);
    out_.clip_position = vec4((clip.xy + offset), clip.zw);
    WeftOutlineVaryings _e84 = out_;
    gl_Position = _e84.clip_position;
    gl_Position.yz = vec2(-gl_Position.y, gl_Position.z * 2.0 - gl_Position.w);
    return;
}

