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

layout(std140, binding = 1) uniform WeftObject_block_1Vertex { WeftObject _group_2_binding_0_vs; };

layout(location = 0) in vec3 _p2vs_location0;

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_any_perpendicular(vec3 n) {
    float s_2 = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a_2 = (-1.0 / (s_2 + n.z));
    float b = ((n.x * n.y) * a_2);
    return vec3((1.0 + (((s_2 * n.x) * n.x) * a_2)), (s_2 * b), (-(s_2) * n.x));
}

float weft_f_dielectric(float cos_i, float eta) {
    float c = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c * c));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c);
    float gpc = max((g + c), 1e-7);
    float b_den = max(((c * gmc) + 1.0), 1e-7);
    float b_num = ((c * gpc) - 1.0);
    float inv = (1.0 / (gpc * b_den));
    float f = clamp(((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)), 0.0, 1.0);
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

vec3 weft_safe_normalize_k3_(vec3 v_2) {
    float len2_2 = dot(v_2, v_2);
    return ((len2_2 > 1e-20) ? (v_2 * inversesqrt(max(len2_2, 1e-20))) : vec3(0.0));
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
    vec3 _e53 = weft_safe_normalize_k3_((normal3_ * in_4.normal));
    out_2.world_normal = _e53;
    vec3 _e58 = weft_safe_normalize_k3_((model3_ * in_4.tangent.xyz));
    out_2.world_tangent = vec4(_e58, bitangent_sign);
    out_2.uv0_ = in_4.uv0_;
    WeftVaryings _e62 = out_2;
    return _e62;
}

mat3x3 weft_tangent_frame(vec3 n_2, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_3 = dot(t_proj, t_proj);
    bool ok = (len2_3 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_2);
    vec3 t_1 = (ok ? (t_proj * inversesqrt(max(len2_3, 1e-20))) : _e13);
    float s_3 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_2, t_1) * s_3);
    return mat3x3(t_1, b_1, n_2);
}

float weft_hair_sqr(float x) {
    return (x * x);
}

float weft_hair_safe_sqrt(float x_1) {
    return sqrt(max(x_1, 0.0));
}

float weft_hair_logistic(float x_2, float s) {
    float e_1 = exp((-(abs(x_2)) / s));
    float _e8 = weft_hair_sqr((1.0 + e_1));
    return (e_1 / (s * _e8));
}

float weft_hair_trimmed_logistic(float x_3, float s_1) {
    float e_2 = exp((-3.1415927 / s_1));
    float _e5 = weft_hair_logistic(x_3, s_1);
    return ((_e5 * (1.0 + e_2)) / (1.0 - e_2));
}

vec3 weft_hair_fast_tt_density(float sin_half, float a) {
    float rho2_ = ((1.0 - ((2.0 * a) * sin_half)) + (a * a));
    float inv_rho = inversesqrt(max(rho2_, 1e-8));
    float cos_go = (max((sin_half - a), 0.0) * inv_rho);
    float cos_gt = ((1.0 - (a * sin_half)) * inv_rho);
    return vec3(cos_go, cos_gt, (((0.25 * cos_go) * cos_gt) * inv_rho));
}

vec3 weft_hair_fast_tt(float sin_plus, float sin_minus, float a_1, float cos_o, float eta_1, vec3 sigma_a, float chord) {
    vec3 _e7 = weft_hair_fast_tt_density(sin_plus, a_1);
    vec3 _e8 = weft_hair_fast_tt_density(sin_minus, a_1);
    float _e11 = weft_f_dielectric((cos_o * _e7.x), eta_1);
    float _e19 = weft_hair_sqr((1.0 - _e11));
    return (exp((-(sigma_a) * (chord * _e7.y))) * ((_e19 * 0.5) * (_e7.z + _e8.z)));
}

WeftHairLobes weft_hair_fast(WeftHair hair, vec3 t, vec3 o, vec3 i) {
    WeftHairLobes out_3 = WeftHairLobes(vec3(0.0), vec3(0.0), vec3(0.0));
    float sin_o = clamp(dot(o, t), -1.0, 1.0);
    float sin_i = clamp(dot(i, t), -1.0, 1.0);
    float _e15 = weft_hair_safe_sqrt((1.0 - (sin_o * sin_o)));
    float _e19 = weft_hair_safe_sqrt((1.0 - (sin_i * sin_i)));
    vec3 o_perp = (o - (sin_o * t));
    vec3 i_perp = (i - (sin_i * t));
    float len2_4 = (dot(o_perp, o_perp) * dot(i_perp, i_perp));
    float cos_phi = clamp(((len2_4 > 1e-12) ? (dot(o_perp, i_perp) * inversesqrt(max(len2_4, 1e-30))) : 1.0), -1.0, 1.0);
    float cos_half = sqrt((0.5 + (0.5 * cos_phi)));
    float sin_half_1 = sqrt((0.5 - (0.5 * cos_phi)));
    vec3 so = vec3(((sin_o * hair.cos2k.y) - (_e15 * hair.sin2k.y)), ((sin_o * hair.cos2k.x) + (_e15 * hair.sin2k.x)), ((sin_o * hair.cos2k.z) + (_e15 * hair.sin2k.z)));
    vec3 co = abs(vec3(((_e15 * hair.cos2k.y) + (sin_o * hair.sin2k.y)), ((_e15 * hair.cos2k.x) - (sin_o * hair.sin2k.x)), ((_e15 * hair.cos2k.z) - (sin_o * hair.sin2k.z))));
    vec3 inv_v = hair.inv_v;
    vec3 norm = hair.mp_norm;
    vec3 x_6 = ((_e19 * co) * inv_v);
    vec3 u = (vec3(1.0) / (vec3(1.0) + (0.7 * x_6)));
    vec3 bessel = ((vec3(1.0) + ((u * (vec3(1.0) - u)) * (vec3(0.181903) + (u * (vec3(-0.401835) + (u * 3.1851)))))) * inversesqrt((vec3(1.0) + (6.2831855 * x_6))));
    vec3 mp = ((exp(min(((((_e19 * co) - (sin_i * so)) - vec3(1.0)) * inv_v), vec3(0.0))) * bessel) * norm);
    float sin_t = (sin_o * hair.inv_eta);
    float chord_1 = (2.0 * inversesqrt(max((1.0 - (sin_t * sin_t)), 1e-8)));
    float a_3 = (_e15 * inversesqrt(max(((hair.eta * hair.eta) - (sin_o * sin_o)), 1e-8)));
    float sd = hair.blur.x;
    float cd = hair.blur.y;
    float c_r = sqrt(min(((0.5 + (0.5 * cos_phi)) + hair.r_floor), 1.0));
    float _e170 = weft_f_dielectric((_e15 * c_r), hair.eta);
    float r = ((0.25 * c_r) * _e170);
    vec3 _e180 = weft_hair_fast_tt(((sin_half_1 * cd) + (cos_half * sd)), ((sin_half_1 * cd) - (cos_half * sd)), a_3, _e15, hair.eta, hair.sigma_a, chord_1);
    float h_f = (0.6243 + (0.1898 * _e15));
    float _e188 = weft_hair_safe_sqrt((1.0 - (h_f * h_f)));
    float _e191 = weft_f_dielectric((_e15 * _e188), hair.eta);
    float h2_ = (0.4824 + (0.2778 * _e15));
    float _e199 = weft_hair_safe_sqrt((1.0 - (h2_ * h2_)));
    float _e202 = weft_f_dielectric((_e15 * _e199), hair.eta);
    float _e210 = weft_hair_safe_sqrt((1.0 - (((h2_ * h2_) * a_3) * a_3)));
    vec3 t2_ = exp((-(hair.sigma_a) * (chord_1 * _e210)));
    float _e216 = weft_hair_sqr((1.0 - _e202));
    vec3 a2_ = (((_e216 * _e202) * t2_) * t2_);
    vec3 ft = (_e191 * t2_);
    vec3 a3_ = ((a2_ * ft) / (vec3(1.0) - ft));
    float s2_fit = (hair.trt.x + (a_3 * (hair.trt.y + (a_3 * (hair.trt.z + (a_3 * (hair.trt.w + (a_3 * hair.trt4_))))))));
    float s_trt = sqrt(max(exp(clamp(s2_fit, -9.0, 2.5)), (hair.s * hair.s)));
    float _e252 = weft_hair_trimmed_logistic(acos(cos_phi), s_trt);
    out_3.s = ((vec3((mp.x * r)) + (mp.y * _e180)) + (mp.z * ((a2_ * _e252) + (a3_ * 0.15915494))));
    out_3.back = (vec3(_e191) + a2_);
    float _e274 = weft_hair_sqr((1.0 - _e202));
    out_3.albedo = (((vec3(_e191) + (_e274 * t2_)) + a2_) + a3_);
    WeftHairLobes _e280 = out_3;
    return _e280;
}

WeftHair hair_from_varyings(HairVaryings in_5, vec3 sigma_a_1) {
    float v_3 = in_5.fibre.z;
    return WeftHair(max(sigma_a_1, vec3(0.0)), in_5.fibre.x, vec4(v_3, (0.25 * v_3), (4.0 * v_3), (4.0 * v_3)), in_5.fibre.y, in_5.sin2k.xyz, in_5.cos2k.xyz, in_5.inv_v.xyz, in_5.mp_norm.xyz, vec2(in_5.cos2k.w, in_5.mp_norm.w), in_5.sin2k.w, vec4(in_5.inv_v.w, in_5.trt.xyz), in_5.trt.w, in_5.jitter.z);
}

vec3 hair_strand(mat3x3 frame, vec2 uv0_) {
    vec2 ts = vec2(0.0);
    ts = vec2(0.0, 1.0);
    float _e6 = ts.x;
    float _e10 = ts.y;
    vec3 _e14 = weft_safe_normalize(((frame[0] * _e6) + (frame[1] * _e10)), frame[1]);
    return _e14;
}

float hair_hash(uint x_4) {
    uint state = ((x_4 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (float(((word >> 22u) ^ word)) * 2.3283064e-10);
}

float hair_value_noise(float x_5, float p) {
    float cell = floor(x_5);
    float f_1 = (x_5 - cell);
    float c0_ = (cell - (p * floor((cell / p))));
    float c1_ = (((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0));
    float _e16 = hair_hash(uint(c0_));
    float _e18 = hair_hash(uint(c1_));
    return (mix(_e16, _e18, ((f_1 * f_1) * (3.0 - (2.0 * f_1)))) - 0.5);
}

vec2 weft_transform_uv_k4_(vec2 uv) {
    return (uv + vec2(0.0, 0.0));
}

WeftHair weft_hair_params_k5_() {
    WeftHair hair_1 = WeftHair(vec3(0.0), 0.0, vec4(0.0), 0.0, vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec2(0.0), 0.0, vec4(0.0), 0.0, 0.0);
    hair_1.sigma_a = vec3(0.0, 0.0, 0.0);
    hair_1.eta = 1.55;
    hair_1.v = vec4(0.03157018, 0.007892545, 0.12628073, 0.12628073);
    hair_1.s = 0.11715981;
    hair_1.sin2k = vec3(0.034899496, 0.06975647, 0.1391731);
    hair_1.cos2k = vec3(0.99939084, 0.9975641, 0.9902682);
    hair_1.inv_v = vec3(31.675459, 126.701836, 7.9188647);
    float _e30 = hair_1.inv_v.x;
    float e_trt = exp((-0.5 * _e30));
    float _e35 = weft_hair_sqr((e_trt * e_trt));
    vec3 _e38 = hair_1.inv_v;
    float _e41 = weft_hair_sqr((_e35 * _e35));
    hair_1.mp_norm = (_e38 / (vec3(1.0) - vec3(_e35, _e41, e_trt)));
    float _e47 = hair_1.s;
    float d = (0.8162094 * _e47);
    hair_1.blur = vec2(sin(d), cos(d));
    float _e55 = hair_1.s;
    float _e58 = weft_hair_sqr((0.4534 * _e55));
    hair_1.r_floor = _e58;
    float sh_1 = hair_1.s;
    hair_1.trt = vec4((-9.2609 + (sh_1 * (65.993 - (107.38 * sh_1)))), (72.357 + (sh_1 * (-624.68 + (1069.8 * sh_1)))), (-153.75 + (sh_1 * (1704.7 - (3127.5 * sh_1)))), (-67.745 + (sh_1 * (-1105.8 + (2706.6 * sh_1)))));
    hair_1.trt4_ = (239.74 - (430.94 * sh_1));
    float _e98 = hair_1.eta;
    hair_1.inv_eta = (1.0 / _e98);
    WeftHair _e101 = hair_1;
    return _e101;
}

vec3 weft_hair_sigma_a_scaled_k8_(float scale_1) {
    vec3 l = (vec3(-2.6140277, -3.9318867, -5.1191573) * scale_1);
    return (l * l);
}

void main() {
    WeftFringeShadowVertex in_1 = WeftFringeShadowVertex(_p2vs_location0);
    bool local_2 = false;
    WeftFringeShadowVaryings out_1 = WeftFringeShadowVaryings(vec4(0.0));
    mat4x4 _e3 = _group_2_binding_0_vs.model;
    vec3 world_1 = (_e3 * vec4(in_1.position, 1.0)).xyz;
    mat4x4 _e11 = _group_0_binding_0_vs.view_proj;
    vec4 clip = (_e11 * vec4(world_1, 1.0));
    vec4 _e17 = _group_0_binding_0_vs.light_direction;
    vec3 l_1 = _e17.xyz;
    float l_len = length(l_1);
    vec3 travel = ((l_len > 1e-6) ? (-(l_1) / vec3(max(l_len, 1e-6))) : vec3(0.0));
    mat4x4 _e32 = _group_0_binding_0_vs.view_proj;
    vec4 pushed = (_e32 * vec4((world_1 + (travel * 0.16)), 1.0));
    if ((clip.w > 1e-6)) {
        local_2 = (pushed.w > 1e-6);
    } else {
        local_2 = false;
    }
    bool usable = local_2;
    vec2 offset_ndc = (usable ? ((pushed.xy / vec2(max(pushed.w, 1e-6))) - (clip.xy / vec2(max(clip.w, 1e-6)))) : vec2(0.0));
    out_1.clip_position = vec4((clip.xy + (offset_ndc * clip.w)), clip.zw);
    WeftFringeShadowVaryings _e71 = out_1;
    gl_Position = _e71.clip_position;
    gl_Position.yz = vec2(-gl_Position.y, gl_Position.z * 2.0 - gl_Position.w);
    return;
}

