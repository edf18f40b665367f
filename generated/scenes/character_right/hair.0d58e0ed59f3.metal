// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct type_5 {
    metal::float4 inner[9];
};
struct WeftFrame {
    metal::float4x4 view_proj;
    metal::float4x4 view;
    metal::float4 camera_position;
    metal::float4 light_direction;
    metal::float4 light_color;
    type_5 sh;
    metal::float4 params;
    metal::float4 viewport;
};
struct WeftObject {
    metal::float4x4 model;
    metal::float4x4 normal_matrix;
};
struct WeftOutlineVertex {
    metal::float3 position;
    metal::float3 normal;
};
struct WeftOutlineVaryings {
    metal::float4 clip_position;
};
struct WeftFringeShadowVertex {
    metal::float3 position;
};
struct WeftFringeShadowVaryings {
    metal::float4 clip_position;
};
struct WeftSurface {
    metal::float3 v;
    metal::float3 n;
};
struct WeftVertexInput {
    metal::float3 position;
    metal::float3 normal;
    metal::float4 tangent;
    metal::float2 uv0_;
    char _pad4[8];
};
struct WeftVaryings {
    metal::float4 clip_position;
    metal::float3 world_position;
    metal::float3 world_normal;
    metal::float4 world_tangent;
    metal::float2 uv0_;
    char _pad5[8];
};
struct WeftHair {
    metal::packed_float3 sigma_a;
    float eta;
    metal::float4 v;
    float s;
    char _pad4[12];
    metal::float3 sin2k;
    metal::float3 cos2k;
    metal::float3 inv_v;
    metal::float3 mp_norm;
    metal::float2 blur;
    float r_floor;
    char _pad10[4];
    metal::float4 trt;
    float trt4_;
    float inv_eta;
    char _pad13[8];
};
struct WeftHairLobes {
    metal::float3 s;
    metal::float3 albedo;
    metal::float3 back;
};
struct HairVaryings {
    metal::float4 clip_position;
    metal::float3 world_position;
    metal::float3 world_normal;
    metal::float4 world_tangent;
    metal::float2 uv0_;
    char _pad5[8];
    metal::float4 fibre;
    metal::float4 sin2k;
    metal::float4 cos2k;
    metal::float4 mp_norm;
    metal::float4 inv_v;
    metal::float4 trt;
    metal::float4 jitter;
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float WEFT_HAIR_MIN_BETA_M = 0.05;
constant float WEFT_HAIR_MIN_BETA_N = 0.05;
constant uint HAIR_REFERENCE_CELLS = 64u;
constant float HAIR_TERMINATOR = 0.25;

metal::float3 weft_safe_normalize(
    metal::float3 v,
    metal::float3 fallback
) {
    float len2_ = metal::dot(v, v);
    return (len2_ > 0.00000000000000000001) ? (v * metal::rsqrt(metal::max(len2_, 0.00000000000000000001))) : fallback;
}

metal::float3 weft_any_perpendicular(
    metal::float3 n
) {
    float s_2 = (n.z >= 0.0) ? 1.0 : -1.0;
    float a_2 = -1.0 / (s_2 + n.z);
    float b = (n.x * n.y) * a_2;
    return metal::float3(1.0 + (((s_2 * n.x) * n.x) * a_2), s_2 * b, -(s_2) * n.x);
}

float weft_f_dielectric(
    float cos_i,
    float eta
) {
    float c = metal::clamp(metal::abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = ((eta * eta) - 1.0) + (c * c);
    float g = metal::sqrt(metal::max(g2_, 0.0));
    float gmc = g - c;
    float gpc = metal::max(g + c, 0.0000001);
    float b_den = metal::max((c * gmc) + 1.0, 0.0000001);
    float b_num = (c * gpc) - 1.0;
    float inv = 1.0 / (gpc * b_den);
    float f = metal::saturate((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv));
    return (g2_ < 0.0) ? 1.0 : f;
}

metal::float3 weft_safe_normalize_k1_(
    metal::float3 v_1
) {
    float len2_1 = metal::dot(v_1, v_1);
    return (len2_1 > 0.00000000000000000001) ? (v_1 * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : metal::float3(0.0, 0.0, 1.0);
}

metal::float3 weft_main_light_direction(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_direction;
    metal::float3 _e4 = weft_safe_normalize_k1_(_e2.xyz);
    return _e4;
}

metal::float3 weft_main_light_radiance(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_color;
    return metal::max(_e2.xyz, metal::float3(0.0));
}

metal::float3 weft_sh_irradiance(
    metal::float3 n_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 e = {};
    type_5 sh = weft_frame.sh;
    e = sh.inner[0].xyz * 0.282095;
    metal::float3 _e9 = e;
    e = _e9 + (sh.inner[1].xyz * (0.488603 * n_1.y));
    metal::float3 _e17 = e;
    e = _e17 + (sh.inner[2].xyz * (0.488603 * n_1.z));
    metal::float3 _e25 = e;
    e = _e25 + (sh.inner[3].xyz * (0.488603 * n_1.x));
    metal::float3 _e33 = e;
    e = _e33 + (sh.inner[4].xyz * ((1.092548 * n_1.x) * n_1.y));
    metal::float3 _e43 = e;
    e = _e43 + (sh.inner[5].xyz * ((1.092548 * n_1.y) * n_1.z));
    metal::float3 _e53 = e;
    e = _e53 + (sh.inner[6].xyz * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0)));
    metal::float3 _e67 = e;
    e = _e67 + (sh.inner[7].xyz * ((1.092548 * n_1.x) * n_1.z));
    metal::float3 _e77 = e;
    e = _e77 + (sh.inner[8].xyz * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y))));
    metal::float3 _e91 = e;
    return metal::max(_e91, metal::float3(0.0));
}

metal::float3 weft_view_direction_k2_(
    metal::float3 world_position,
    constant WeftFrame& weft_frame
) {
    metal::float4 _e4 = weft_frame.camera_position;
    metal::float3 _e7 = weft_safe_normalize_k1_(_e4.xyz - world_position);
    return _e7;
}

WeftSurface weft_surface(
    metal::float3 world_position_1,
    metal::float3 world_normal,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_view_direction_k2_(world_position_1, weft_frame);
    metal::float3 _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface {_e2, _e3};
}

metal::float3 weft_safe_normalize_k3_(
    metal::float3 v_2
) {
    float len2_2 = metal::dot(v_2, v_2);
    return (len2_2 > 0.00000000000000000001) ? (v_2 * metal::rsqrt(metal::max(len2_2, 0.00000000000000000001))) : metal::float3(0.0);
}

WeftVaryings weft_forward_vertex(
    WeftVertexInput in_4,
    constant WeftFrame& weft_frame,
    constant WeftObject& weft_object
) {
    WeftVaryings out_2 = {};
    metal::float4x4 model = weft_object.model;
    metal::float3x3 model3_ = metal::float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    metal::float4x4 nm = weft_object.normal_matrix;
    metal::float3x3 normal3_ = metal::float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    metal::float4 world = model * metal::float4(in_4.position, 1.0);
    float mirror = (metal::determinant(model3_) < 0.0) ? -1.0 : 1.0;
    float bitangent_sign = ((in_4.tangent.w < 0.0) ? -1.0 : 1.0) * mirror;
    metal::float4x4 _e43 = weft_frame.view_proj;
    out_2.clip_position = _e43 * metal::float4(world.xyz, 1.0);
    out_2.world_position = world.xyz;
    metal::float3 _e53 = weft_safe_normalize_k3_(normal3_ * in_4.normal);
    out_2.world_normal = _e53;
    metal::float3 _e58 = weft_safe_normalize_k3_(model3_ * in_4.tangent.xyz);
    out_2.world_tangent = metal::float4(_e58, bitangent_sign);
    out_2.uv0_ = in_4.uv0_;
    WeftVaryings _e62 = out_2;
    return _e62;
}

metal::float3x3 weft_tangent_frame(
    metal::float3 n_2,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_2 * metal::dot(n_2, t_in));
    float len2_3 = metal::dot(t_proj, t_proj);
    bool ok = len2_3 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_2);
    metal::float3 t_1 = ok ? (t_proj * metal::rsqrt(metal::max(len2_3, 0.00000000000000000001))) : _e13;
    float s_3 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_2, t_1) * s_3;
    return metal::float3x3(t_1, b_1, n_2);
}

float weft_hair_sqr(
    float x
) {
    return x * x;
}

float weft_hair_safe_sqrt(
    float x_1
) {
    return metal::sqrt(metal::max(x_1, 0.0));
}

float weft_hair_logistic(
    float x_2,
    float s
) {
    float e_1 = metal::exp(-(metal::abs(x_2)) / s);
    float _e8 = weft_hair_sqr(1.0 + e_1);
    return e_1 / (s * _e8);
}

float weft_hair_trimmed_logistic(
    float x_3,
    float s_1
) {
    float e_2 = metal::exp(-3.1415927 / s_1);
    float _e5 = weft_hair_logistic(x_3, s_1);
    return (_e5 * (1.0 + e_2)) / (1.0 - e_2);
}

metal::float3 weft_hair_fast_tt_density(
    float sin_half,
    float a
) {
    float rho2_ = (1.0 - ((2.0 * a) * sin_half)) + (a * a);
    float inv_rho = metal::rsqrt(metal::max(rho2_, 0.00000001));
    float cos_go = metal::max(sin_half - a, 0.0) * inv_rho;
    float cos_gt = (1.0 - (a * sin_half)) * inv_rho;
    return metal::float3(cos_go, cos_gt, ((0.25 * cos_go) * cos_gt) * inv_rho);
}

metal::float3 weft_hair_fast_tt(
    float sin_plus,
    float sin_minus,
    float a_1,
    float cos_o,
    float eta_1,
    metal::float3 sigma_a,
    float chord
) {
    metal::float3 _e7 = weft_hair_fast_tt_density(sin_plus, a_1);
    metal::float3 _e8 = weft_hair_fast_tt_density(sin_minus, a_1);
    float _e11 = weft_f_dielectric(cos_o * _e7.x, eta_1);
    float _e19 = weft_hair_sqr(1.0 - _e11);
    return metal::exp(-(sigma_a) * (chord * _e7.y)) * ((_e19 * 0.5) * (_e7.z + _e8.z));
}

WeftHairLobes weft_hair_fast(
    WeftHair hair,
    metal::float3 t,
    metal::float3 o,
    metal::float3 i
) {
    WeftHairLobes out_3 = {};
    float sin_o = metal::clamp(metal::dot(o, t), -1.0, 1.0);
    float sin_i = metal::clamp(metal::dot(i, t), -1.0, 1.0);
    float _e15 = weft_hair_safe_sqrt(1.0 - (sin_o * sin_o));
    float _e19 = weft_hair_safe_sqrt(1.0 - (sin_i * sin_i));
    metal::float3 o_perp = o - (sin_o * t);
    metal::float3 i_perp = i - (sin_i * t);
    float len2_4 = metal::dot(o_perp, o_perp) * metal::dot(i_perp, i_perp);
    float cos_phi = metal::clamp((len2_4 > 0.000000000001) ? (metal::dot(o_perp, i_perp) * metal::rsqrt(metal::max(len2_4, 0.000000000000000000000000000001))) : 1.0, -1.0, 1.0);
    float cos_half = metal::sqrt(0.5 + (0.5 * cos_phi));
    float sin_half_1 = metal::sqrt(0.5 - (0.5 * cos_phi));
    metal::float3 so = metal::float3((sin_o * hair.cos2k.y) - (_e15 * hair.sin2k.y), (sin_o * hair.cos2k.x) + (_e15 * hair.sin2k.x), (sin_o * hair.cos2k.z) + (_e15 * hair.sin2k.z));
    metal::float3 co = metal::abs(metal::float3((_e15 * hair.cos2k.y) + (sin_o * hair.sin2k.y), (_e15 * hair.cos2k.x) - (sin_o * hair.sin2k.x), (_e15 * hair.cos2k.z) - (sin_o * hair.sin2k.z)));
    metal::float3 inv_v = hair.inv_v;
    metal::float3 norm = hair.mp_norm;
    metal::float3 x_6 = (_e19 * co) * inv_v;
    metal::float3 u = metal::float3(1.0) / (metal::float3(1.0) + (0.7 * x_6));
    metal::float3 bessel = (metal::float3(1.0) + ((u * (metal::float3(1.0) - u)) * (metal::float3(0.181903) + (u * (metal::float3(-0.401835) + (u * 3.1851)))))) * metal::rsqrt(metal::float3(1.0) + (6.2831855 * x_6));
    metal::float3 mp = (metal::exp(metal::min((((_e19 * co) - (sin_i * so)) - metal::float3(1.0)) * inv_v, metal::float3(0.0))) * bessel) * norm;
    float sin_t = sin_o * hair.inv_eta;
    float chord_1 = 2.0 * metal::rsqrt(metal::max(1.0 - (sin_t * sin_t), 0.00000001));
    float a_3 = _e15 * metal::rsqrt(metal::max((hair.eta * hair.eta) - (sin_o * sin_o), 0.00000001));
    float sd = hair.blur.x;
    float cd = hair.blur.y;
    float c_r = metal::sqrt(metal::min((0.5 + (0.5 * cos_phi)) + hair.r_floor, 1.0));
    float _e170 = weft_f_dielectric(_e15 * c_r, hair.eta);
    float r = (0.25 * c_r) * _e170;
    metal::float3 _e180 = weft_hair_fast_tt((sin_half_1 * cd) + (cos_half * sd), (sin_half_1 * cd) - (cos_half * sd), a_3, _e15, hair.eta, hair.sigma_a, chord_1);
    float h_f = 0.6243 + (0.1898 * _e15);
    float _e188 = weft_hair_safe_sqrt(1.0 - (h_f * h_f));
    float _e191 = weft_f_dielectric(_e15 * _e188, hair.eta);
    float h2_ = 0.4824 + (0.2778 * _e15);
    float _e199 = weft_hair_safe_sqrt(1.0 - (h2_ * h2_));
    float _e202 = weft_f_dielectric(_e15 * _e199, hair.eta);
    float _e210 = weft_hair_safe_sqrt(1.0 - (((h2_ * h2_) * a_3) * a_3));
    metal::float3 t2_ = metal::exp(-(hair.sigma_a) * (chord_1 * _e210));
    float _e216 = weft_hair_sqr(1.0 - _e202);
    metal::float3 a2_ = ((_e216 * _e202) * t2_) * t2_;
    metal::float3 ft = _e191 * t2_;
    metal::float3 a3_ = (a2_ * ft) / (metal::float3(1.0) - ft);
    float s2_fit = hair.trt.x + (a_3 * (hair.trt.y + (a_3 * (hair.trt.z + (a_3 * (hair.trt.w + (a_3 * hair.trt4_)))))));
    float s_trt = metal::sqrt(metal::max(metal::exp(metal::clamp(s2_fit, -9.0, 2.5)), hair.s * hair.s));
    float _e252 = weft_hair_trimmed_logistic(metal::acos(cos_phi), s_trt);
    out_3.s = (metal::float3(mp.x * r) + (mp.y * _e180)) + (mp.z * ((a2_ * _e252) + (a3_ * 0.15915494)));
    out_3.back = metal::float3(_e191) + a2_;
    float _e274 = weft_hair_sqr(1.0 - _e202);
    out_3.albedo = ((metal::float3(_e191) + (_e274 * t2_)) + a2_) + a3_;
    WeftHairLobes _e280 = out_3;
    return _e280;
}

WeftHair hair_from_varyings(
    HairVaryings in_5,
    metal::float3 sigma_a_1
) {
    float v_3 = in_5.fibre.z;
    return WeftHair {metal::max(sigma_a_1, metal::float3(0.0)), in_5.fibre.x, metal::float4(v_3, 0.25 * v_3, 4.0 * v_3, 4.0 * v_3), in_5.fibre.y, {}, in_5.sin2k.xyz, in_5.cos2k.xyz, in_5.inv_v.xyz, in_5.mp_norm.xyz, metal::float2(in_5.cos2k.w, in_5.mp_norm.w), in_5.sin2k.w, {}, metal::float4(in_5.inv_v.w, in_5.trt.xyz), in_5.trt.w, in_5.jitter.z};
}

metal::float3 hair_strand(
    metal::float3x3 frame,
    metal::float2 uv0_
) {
    metal::float2 ts = {};
    ts = metal::float2(0.0, 1.0);
    float _e6 = ts.x;
    float _e10 = ts.y;
    metal::float3 _e14 = weft_safe_normalize((frame[0] * _e6) + (frame[1] * _e10), frame[1]);
    return _e14;
}

float hair_hash(
    uint x_4
) {
    uint state = (x_4 * 747796405u) + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return static_cast<float>((word >> 22u) ^ word) * 0.00000000023283064;
}

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

float hair_value_noise(
    float x_5,
    float p
) {
    float cell = metal::floor(x_5);
    float f_1 = x_5 - cell;
    float c0_ = cell - (p * metal::floor(cell / p));
    float c1_ = ((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0);
    float _e16 = hair_hash(naga_f2u32(c0_));
    float _e18 = hair_hash(naga_f2u32(c1_));
    return metal::mix(_e16, _e18, (f_1 * f_1) * (3.0 - (2.0 * f_1))) - 0.5;
}

metal::float2 weft_transform_uv_k4_(
    metal::float2 uv
) {
    return uv + metal::float2(0.0, 0.0);
}

float hair_jitter(
    metal::float2 uv0_1,
    metal::float2 rotation,
    float noise_period,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> jitter_map
) {
    float c_1 = rotation.x;
    float s_4 = rotation.y;
    metal::float2 rotated = metal::float2((c_1 * uv0_1.x) + (s_4 * uv0_1.y), (-(s_4) * uv0_1.x) + (c_1 * uv0_1.y));
    metal::float2 _e18 = weft_transform_uv_k4_(uv0_1);
    metal::float4 _e21 = jitter_map.sample(material_sampler, _e18);
    float j = _e21.x;
    float across = _e18.x;
    float _e26 = hair_value_noise(across * 128.0, noise_period);
    return j + (0.2 * _e26);
}

WeftHair weft_hair_params_k5_(
) {
    WeftHair hair_1 = {};
    hair_1.sigma_a = metal::float3(0.0, 0.0, 0.0);
    hair_1.eta = 1.55;
    hair_1.v = metal::float4(0.03157018, 0.007892545, 0.12628073, 0.12628073);
    hair_1.s = 0.11715981;
    hair_1.sin2k = metal::float3(0.034899496, 0.06975647, 0.1391731);
    hair_1.cos2k = metal::float3(0.99939084, 0.9975641, 0.9902682);
    hair_1.inv_v = metal::float3(31.675459, 126.701836, 7.9188647);
    float _e30 = hair_1.inv_v.x;
    float e_trt = metal::exp(-0.5 * _e30);
    float _e35 = weft_hair_sqr(e_trt * e_trt);
    metal::float3 _e38 = hair_1.inv_v;
    float _e41 = weft_hair_sqr(_e35 * _e35);
    hair_1.mp_norm = _e38 / (metal::float3(1.0) - metal::float3(_e35, _e41, e_trt));
    float _e47 = hair_1.s;
    float d = 0.8162094 * _e47;
    hair_1.blur = metal::float2(metal::sin(d), metal::cos(d));
    float _e55 = hair_1.s;
    float _e58 = weft_hair_sqr(0.4534 * _e55);
    hair_1.r_floor = _e58;
    float sh_1 = hair_1.s;
    hair_1.trt = metal::float4(-9.2609 + (sh_1 * (65.993 - (107.38 * sh_1))), 72.357 + (sh_1 * (-624.68 + (1069.8 * sh_1))), -153.75 + (sh_1 * (1704.7 - (3127.5 * sh_1))), -67.745 + (sh_1 * (-1105.8 + (2706.6 * sh_1))));
    hair_1.trt4_ = 239.74 - (430.94 * sh_1);
    float _e98 = hair_1.eta;
    hair_1.inv_eta = 1.0 / _e98;
    WeftHair _e101 = hair_1;
    return _e101;
}

metal::float3 weft_hair_sigma_a_scaled_k8_(
    float scale_1
) {
    metal::float3 l = metal::float3(-2.6140277, -3.9318867, -5.1191573) * scale_1;
    return l * l;
}

struct vs_outlineInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
};
struct vs_outlineOutput {
    metal::float4 clip_position [[position]];
};
vertex vs_outlineOutput vs_outline(
  vs_outlineInput varyings [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(1)]]
) {
    const WeftOutlineVertex in = { varyings.position, varyings.normal };
    bool local = {};
    bool local_1 = {};
    WeftOutlineVaryings out = {};
    metal::float4x4 _e3 = weft_object.model;
    metal::float4 world_1 = _e3 * metal::float4(in.position, 1.0);
    metal::float4x4 nm_1 = weft_object.normal_matrix;
    metal::float3 normal = metal::float3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz) * in.normal;
    metal::float4x4 _e22 = weft_frame.view_proj;
    metal::float4 clip = _e22 * metal::float4(world_1.xyz, 1.0);
    metal::float4 _e29 = weft_frame.viewport;
    metal::float2 size = _e29.xy;
    metal::float4x4 _e33 = weft_frame.view_proj;
    metal::float2 screen_normal = (_e33 * metal::float4(normal, 0.0)).xy * size;
    float len = metal::length(screen_normal);
    if (len > 0.000001) {
        float _e47 = weft_frame.viewport.x;
        local = _e47 > 0.0;
    } else {
        local = false;
    }
    bool _e51 = local;
    if (_e51) {
        local_1 = clip.w > 0.0;
    } else {
        local_1 = false;
    }
    bool usable = local_1;
    metal::float2 direction = usable ? (screen_normal / metal::float2(metal::max(len, 0.000001))) : metal::float2(0.0);
    float distance = metal::min(clip.w, 10.0);
    metal::float4 _e74 = weft_frame.viewport;
    metal::float2 offset = (((direction * 1.5) * 2.0) * _e74.zw) * distance;
    out.clip_position = metal::float4(clip.xy + offset, clip.zw);
    WeftOutlineVaryings _e84 = out;
    const auto _tmp = _e84;
    return vs_outlineOutput { _tmp.clip_position };
}


struct fs_outlineOutput {
    metal::float4 member_1 [[color(0)]];
};
fragment fs_outlineOutput fs_outline(
) {
    return fs_outlineOutput { metal::float4(metal::float3(0.0, 0.0, 0.0), 1.0) };
}


struct vs_fringe_shadowInput {
    metal::float3 position [[attribute(0)]];
};
struct vs_fringe_shadowOutput {
    metal::float4 clip_position [[position]];
};
vertex vs_fringe_shadowOutput vs_fringe_shadow(
  vs_fringe_shadowInput varyings_2 [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(1)]]
) {
    const WeftFringeShadowVertex in_1 = { varyings_2.position };
    bool local_2 = {};
    WeftFringeShadowVaryings out_1 = {};
    metal::float4x4 _e3 = weft_object.model;
    metal::float3 world_2 = (_e3 * metal::float4(in_1.position, 1.0)).xyz;
    metal::float4x4 _e11 = weft_frame.view_proj;
    metal::float4 clip_1 = _e11 * metal::float4(world_2, 1.0);
    metal::float4 _e17 = weft_frame.light_direction;
    metal::float3 l_1 = _e17.xyz;
    float l_len = metal::length(l_1);
    metal::float3 travel = (l_len > 0.000001) ? (-(l_1) / metal::float3(metal::max(l_len, 0.000001))) : metal::float3(0.0);
    metal::float4x4 _e32 = weft_frame.view_proj;
    metal::float4 pushed = _e32 * metal::float4(world_2 + (travel * 0.16), 1.0);
    if (clip_1.w > 0.000001) {
        local_2 = pushed.w > 0.000001;
    } else {
        local_2 = false;
    }
    bool usable_1 = local_2;
    metal::float2 offset_ndc = usable_1 ? ((pushed.xy / metal::float2(metal::max(pushed.w, 0.000001))) - (clip_1.xy / metal::float2(metal::max(clip_1.w, 0.000001)))) : metal::float2(0.0);
    out_1.clip_position = metal::float4(clip_1.xy + (offset_ndc * clip_1.w), clip_1.zw);
    WeftFringeShadowVaryings _e71 = out_1;
    const auto _tmp_1 = _e71;
    return vs_fringe_shadowOutput { _tmp_1.clip_position };
}


struct fs_fringe_shadowOutput {
    metal::float4 member_3 [[color(0)]];
};
fragment fs_fringe_shadowOutput fs_fringe_shadow(
) {
    return fs_fringe_shadowOutput { metal::float4(metal::float3(0.5704816, 0.34239164, 0.34239164), 1.0) };
}


struct vs_hairInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float4 tangent_1 [[attribute(2)]];
    metal::float2 uv0_2 [[attribute(3)]];
};
struct vs_hairOutput {
    metal::float4 clip_position [[position]];
    metal::float3 world_position [[user(loc0), center_perspective]];
    metal::float3 world_normal [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
    metal::float4 fibre [[user(loc4), flat]];
    metal::float4 sin2k [[user(loc5), flat]];
    metal::float4 cos2k [[user(loc6), flat]];
    metal::float4 mp_norm [[user(loc7), flat]];
    metal::float4 inv_v [[user(loc8), flat]];
    metal::float4 trt [[user(loc9), flat]];
    metal::float4 jitter [[user(loc10), flat]];
};
vertex vs_hairOutput vs_hair(
  vs_hairInput varyings_4 [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(1)]]
) {
    const WeftVertexInput in_2 = { varyings_4.position, varyings_4.normal, varyings_4.tangent_1, varyings_4.uv0_2 };
    WeftHair h = {};
    float scale = 0.0;
    WeftVaryings _e1 = weft_forward_vertex(in_2, weft_frame, weft_object);
    WeftHair _e2 = weft_hair_params_k5_();
    h = _e2;
    float _e12 = h.eta;
    float _e14 = h.s;
    float _e17 = h.v.x;
    metal::float3 _e21 = h.sin2k;
    float _e23 = h.r_floor;
    metal::float3 _e26 = h.cos2k;
    float _e29 = h.blur.x;
    metal::float3 _e32 = h.mp_norm;
    float _e35 = h.blur.y;
    metal::float3 _e38 = h.inv_v;
    float _e41 = h.trt.x;
    metal::float4 _e44 = h.trt;
    float _e47 = h.trt4_;
    float _e52 = h.inv_eta;
    const auto _tmp_2 = HairVaryings {_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, {}, metal::float4(_e12, _e14, _e17, 0.16982499), metal::float4(_e21, _e23), metal::float4(_e26, _e29), metal::float4(_e32, _e35), metal::float4(_e38, _e41), metal::float4(_e44.yzw, _e47), metal::float4(-0.00000004371139, 1.0, _e52, 128.0)};
    return vs_hairOutput { _tmp_2.clip_position, _tmp_2.world_position, _tmp_2.world_normal, _tmp_2.world_tangent, _tmp_2.uv0_, _tmp_2.fibre, _tmp_2.sin2k, _tmp_2.cos2k, _tmp_2.mp_norm, _tmp_2.inv_v, _tmp_2.trt, _tmp_2.jitter };
}


struct fs_mainInput {
    metal::float3 world_position_2 [[user(loc0), center_perspective]];
    metal::float3 world_normal_1 [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_2 [[user(loc3), center_perspective]];
    metal::float4 fibre [[user(loc4), flat]];
    metal::float4 sin2k [[user(loc5), flat]];
    metal::float4 cos2k [[user(loc6), flat]];
    metal::float4 mp_norm [[user(loc7), flat]];
    metal::float4 inv_v [[user(loc8), flat]];
    metal::float4 trt [[user(loc9), flat]];
    metal::float4 jitter [[user(loc10), flat]];
};
struct fs_mainOutput {
    metal::float4 member_5 [[color(0)]];
};
fragment fs_mainOutput fs_main(
  fs_mainInput varyings_5 [[stage_in]]
, metal::float4 clip_position [[position]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, metal::sampler material_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> jitter_map [[texture(0)]]
) {
    const HairVaryings in_3 = { clip_position, varyings_5.world_position_2, varyings_5.world_normal_1, varyings_5.world_tangent, varyings_5.uv0_2, {}, varyings_5.fibre, varyings_5.sin2k, varyings_5.cos2k, varyings_5.mp_norm, varyings_5.inv_v, varyings_5.trt, varyings_5.jitter };
    metal::float3 color = {};
    WeftHairLobes lobes = {};
    WeftSurface _e6 = weft_surface(in_3.world_position, in_3.world_normal, weft_frame);
    metal::float3 v_4 = _e6.v;
    metal::float3 n_3 = _e6.n;
    metal::float3x3 _e10 = weft_tangent_frame(n_3, in_3.world_tangent);
    metal::float3 _e12 = hair_strand(_e10, in_3.uv0_);
    float _e18 = hair_jitter(in_3.uv0_, in_3.jitter.xy, in_3.jitter.w, material_sampler, jitter_map);
    metal::float3 _e19 = weft_main_light_direction(weft_frame);
    metal::float3 _e20 = weft_main_light_radiance(weft_frame);
    metal::float3 _e21 = weft_sh_irradiance(n_3, weft_frame);
    float n_dot_l = metal::dot(n_3, _e19);
    {
        metal::float3 _e26 = weft_safe_normalize(_e12 + (_e18 * n_3), _e12);
        metal::float3 _e29 = weft_hair_sigma_a_scaled_k8_(in_3.fibre.w);
        WeftHair _e30 = hair_from_varyings(in_3, _e29);
        {
            WeftHairLobes _e32 = weft_hair_fast(_e30, _e26, v_4, _e19);
            lobes = _e32;
        }
        float body = metal::smoothstep(-0.25, HAIR_TERMINATOR, n_dot_l);
        metal::float3 _e38 = lobes.back;
        metal::float3 multiple = metal::float3(0.073238954, 0.019606648, 0.0059810597) * (metal::float3(1.0) - _e38);
        metal::float3 _e42 = lobes.s;
        metal::float3 direct = (_e42 * body) + (multiple * (WEFT_INV_PI * metal::saturate(n_dot_l)));
        metal::float3 _e51 = lobes.back;
        color = (direct * _e20) + (_e21 * (multiple + _e51));
    }
    metal::float3 _e55 = color;
    metal::float3 radiance = metal::clamp(_e55, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
