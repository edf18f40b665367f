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
struct WeftSurface {
    metal::float3 v;
    metal::float3 n;
};
struct WeftLightGeometry {
    metal::float3 l;
    metal::packed_float3 h;
    float n_dot_v;
    float n_dot_l;
    float n_dot_h;
    float v_dot_h;
    char _pad6[4];
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
struct type_12 {
    metal::float3 inner[2];
};
struct WeftFilmStack {
    float n2_;
    float cos2_;
    metal::float2 r12_;
    type_12 r23_;
    bool total_internal_reflection;
    char _pad5[15];
};
struct WeftFilmSeries {
    metal::float3 dc;
    metal::float3 first;
    metal::float3 ratio;
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant float film_sensitivity_opd_max = 16000.0;
constant uint COLOR_MODE_HUE_RING = 0u;
constant uint COLOR_MODE_CUSTOM = 1u;
constant uint ANISO_COLOR_OFF = 0u;
constant uint ANISO_COLOR_VALUE = 1u;
constant uint ANISO_COLOR_MAP = 2u;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float WEFT_FILM_PI = 3.1415927;
constant uint WEFT_FILM_SAMPLES = 101u;
constant float WEFT_FILM_LAMBDA_MIN = 380.0;
constant float WEFT_FILM_LAMBDA_MAX = 780.0;
constant float WEFT_FILM_FADE_NM = 30.0;
constant metal::float3x3 WEFT_XYZ_TO_REC709_ = metal::float3x3(metal::float3(3.2404542, -0.969266, 0.0556434), metal::float3(-1.5371385, 1.8760108, -0.2040259), metal::float3(-0.4985314, 0.041556, 1.0572252));

metal::float4 table_film_sensitivity(
    metal::float2 uv,
    metal::sampler material_clamp_sampler,
    metal::texture2d<float, metal::access::sample> film_sensitivity
) {
    metal::float2 st = ((metal::clamp(uv, metal::float2(0.0), metal::float2(1.0)) * metal::float2(2047.0, 1.0)) + metal::float2(0.5)) / metal::float2(2048.0, 2.0);
    metal::float4 _e13 = film_sensitivity.sample(material_clamp_sampler, st, metal::level(0.0));
    return _e13;
}

float weft_pow5_(
    float x
) {
    float x2_ = x * x;
    return (x2_ * x2_) * x;
}

float weft_clamp_cos(
    float c
) {
    return metal::clamp(c, WEFT_MIN_N_DOT, 1.0);
}

metal::float3 weft_safe_normalize(
    metal::float3 v,
    metal::float3 fallback
) {
    float len2_ = metal::dot(v, v);
    return (len2_ > 0.00000000000000000001) ? (v * metal::rsqrt(metal::max(len2_, 0.00000000000000000001))) : fallback;
}

metal::float3 weft_sh_irradiance(
    metal::float3 n_1
) {
    metal::float3 e = {};
    e = metal::float3(0.27778354, 0.32136026, 0.4497644);
    e = metal::float3(0.27778354, 0.32136026, 0.4497644) + (metal::float3(0.2192843, 0.34164187, 0.663193) * (0.488603 * n_1.y));
    metal::float3 _e11 = e;
    e = _e11 + (metal::float3(0.1352113, 0.12394369, 0.10366199) * (0.488603 * n_1.z));
    metal::float3 _e18 = e;
    e = _e18 + (metal::float3(-0.14969625, -0.13722156, -0.11476713) * (0.488603 * n_1.x));
    metal::float3 _e25 = e;
    e = _e25 + (metal::float3(-0.064625785, -0.059240304, -0.049546435) * ((1.092548 * n_1.x) * n_1.y));
    metal::float3 _e34 = e;
    e = _e34 + (metal::float3(0.05837178, 0.053507466, 0.044751696) * ((1.092548 * n_1.y) * n_1.z));
    metal::float3 _e43 = e;
    e = _e43 + (metal::float3(0.025110306, 0.023586905, 0.01273896) * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0)));
    metal::float3 _e56 = e;
    e = _e56 + (metal::float3(-0.06322707, -0.057958152, -0.04847409) * ((1.092548 * n_1.x) * n_1.z));
    metal::float3 _e65 = e;
    e = _e65 + (metal::float3(0.056382716, 0.05266991, 0.031947177) * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y))));
    metal::float3 _e78 = e;
    return metal::max(_e78, metal::float3(0.0));
}

metal::float3 weft_safe_normalize_k11_(
    metal::float3 v_1
) {
    float len2_1 = metal::dot(v_1, v_1);
    return (len2_1 > 0.00000000000000000001) ? (v_1 * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : metal::float3(0.0, 0.0, 1.0);
}

metal::float3 weft_view_direction_k2_(
    metal::float3 world_position,
    constant WeftFrame& weft_frame
) {
    metal::float4 _e4 = weft_frame.camera_position;
    metal::float3 _e7 = weft_safe_normalize_k11_(_e4.xyz - world_position);
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

WeftLightGeometry weft_main_light_geometry(
    metal::float3 n_2,
    metal::float3 v_2
) {
    metal::float3 _e4 = weft_safe_normalize(metal::float3(-0.61984503, 0.54986256, 0.55986005) + v_2, n_2);
    float _e6 = weft_clamp_cos(metal::dot(n_2, v_2));
    return WeftLightGeometry {metal::float3(-0.61984503, 0.54986256, 0.55986005), _e4, _e6, metal::saturate(metal::dot(n_2, metal::float3(-0.61984503, 0.54986256, 0.55986005))), metal::saturate(metal::dot(n_2, _e4)), metal::saturate(metal::dot(v_2, _e4))};
}

metal::float3 weft_safe_normalize_k3_(
    metal::float3 v_3
) {
    float len2_2 = metal::dot(v_3, v_3);
    return (len2_2 > 0.00000000000000000001) ? (v_3 * metal::rsqrt(metal::max(len2_2, 0.00000000000000000001))) : metal::float3(0.0);
}

WeftVaryings weft_forward_vertex(
    WeftVertexInput in_2,
    constant WeftFrame& weft_frame,
    constant WeftObject& weft_object
) {
    WeftVaryings out = {};
    metal::float4x4 model = weft_object.model;
    metal::float3x3 model3_ = metal::float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    metal::float4x4 nm = weft_object.normal_matrix;
    metal::float3x3 normal3_ = metal::float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    metal::float4 world = model * metal::float4(in_2.position, 1.0);
    float mirror = (metal::determinant(model3_) < 0.0) ? -1.0 : 1.0;
    float bitangent_sign = ((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror;
    metal::float4x4 _e43 = weft_frame.view_proj;
    out.clip_position = _e43 * metal::float4(world.xyz, 1.0);
    out.world_position = world.xyz;
    metal::float3 _e53 = weft_safe_normalize_k3_(normal3_ * in_2.normal);
    out.world_normal = _e53;
    metal::float3 _e58 = weft_safe_normalize_k3_(model3_ * in_2.tangent.xyz);
    out.world_tangent = metal::float4(_e58, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    WeftVaryings _e62 = out;
    return _e62;
}

metal::float2 weft_fresnel_amplitudes_k4_(
    float n_t,
    float cos_i,
    float cos_t
) {
    float rs = (cos_i - (n_t * cos_t)) / metal::max(cos_i + (n_t * cos_t), 0.000000000001);
    float rp = ((n_t * cos_i) - cos_t) / metal::max((n_t * cos_i) + cos_t, 0.000000000001);
    return metal::float2(rs, rp);
}

metal::float3 weft_film_sensitivity(
    float opd_nm,
    metal::sampler material_clamp_sampler,
    metal::texture2d<float, metal::access::sample> film_sensitivity
) {
    metal::float4 _e5 = table_film_sensitivity(metal::float2(opd_nm / film_sensitivity_opd_max, 0.0), material_clamp_sampler, film_sensitivity);
    return _e5.xyz;
}

metal::float3 weft_film_orders(
    float opd_nm_1,
    WeftFilmSeries s,
    WeftFilmSeries p,
    metal::sampler material_clamp_sampler,
    metal::texture2d<float, metal::access::sample> film_sensitivity
) {
    metal::float3 k1_ = (s.first * s.ratio) + (p.first * p.ratio);
    metal::float3 k2_ = ((s.first * s.ratio) * s.ratio) + ((p.first * p.ratio) * p.ratio);
    metal::float3 k3_ = (((s.first * s.ratio) * s.ratio) * s.ratio) + (((p.first * p.ratio) * p.ratio) * p.ratio);
    metal::float3 k4_ = ((s.first * (s.ratio * s.ratio)) * (s.ratio * s.ratio)) + ((p.first * (p.ratio * p.ratio)) * (p.ratio * p.ratio));
    metal::float3 _e55 = weft_film_sensitivity(opd_nm_1, material_clamp_sampler, film_sensitivity);
    metal::float3 _e59 = weft_film_sensitivity(2.0 * opd_nm_1, material_clamp_sampler, film_sensitivity);
    metal::float3 _e64 = weft_film_sensitivity(3.0 * opd_nm_1, material_clamp_sampler, film_sensitivity);
    metal::float3 _e69 = weft_film_sensitivity(4.0 * opd_nm_1, material_clamp_sampler, film_sensitivity);
    metal::float3 sum = (((k1_ * _e55) + (k2_ * _e59)) + (k3_ * _e64)) + (k4_ * _e69);
    return 2.0 * sum;
}

WeftFilmSeries weft_film_series(
    float r12_,
    metal::float3 r23_
) {
    float big_r12_ = r12_ * r12_;
    float t121_ = 1.0 - big_r12_;
    metal::float3 big_r23_ = r23_ * r23_;
    metal::float3 big_r123_ = metal::min(big_r12_ * big_r23_, metal::float3(0.9999));
    metal::float3 rs_1 = ((t121_ * t121_) * big_r23_) / (metal::float3(1.0) - big_r123_);
    metal::float3 ratio = metal::clamp(-(r12_) * r23_, metal::float3(-0.99995), metal::float3(0.99995));
    return WeftFilmSeries {metal::float3(big_r12_) + rs_1, rs_1 - metal::float3(t121_), ratio};
}

metal::float2 weft_env_brdf_lut_k6_(
    float n_dot_v,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv_1 = metal::float2(metal::saturate(n_dot_v), 0.2);
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv_1, metal::level(0.0));
    return _e8.xy;
}

float weft_film_ior_k19_(
) {
    return metal::mix(1.0, 1.8, metal::smoothstep(0.0, WEFT_FILM_FADE_NM, 420.0));
}

float weft_v_smith_ggx_correlated_k8_(
    float n_dot_v_1,
    float n_dot_l
) {
    float _e6 = weft_clamp_cos(n_dot_v_1);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = _e7 * metal::sqrt(((_e6 * _e6) * 0.9984) + 0.0016000002);
    float ll = _e6 * metal::sqrt(((_e7 * _e7) * 0.9984) + 0.0016000002);
    return 0.5 / (lv + ll);
}

float weft_d_ggx_nh_k9_(
    metal::float3 n_3,
    metal::float3 h
) {
    float noh = metal::saturate(metal::dot(n_3, h));
    metal::float3 nxh = metal::cross(n_3, h);
    float d = metal::dot(nxh, nxh) + ((noh * noh) * 0.0016000002);
    return 0.0016000002 / (WEFT_PI * metal::max(d * d, 0.000000000000000000000000000001));
}

float weft_specular_mip_k14_(
    constant WeftFrame& weft_frame
) {
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return 0.312 * max_mip;
}

metal::float3 weft_prefiltered_radiance_k10_(
    metal::float3 dir,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip_k14_(weft_frame);
    metal::float4 c_1 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_1.xyz, metal::float3(0.0));
}

metal::float3 weft_f_schlick_k15_(
    float v_dot_h
) {
    float _e5 = weft_pow5_(1.0 - metal::saturate(v_dot_h));
    return metal::float3(0.8999996, 0.8999996, 0.8999996) + (metal::float3(0.10000038, 0.10000038, 0.10000038) * _e5);
}

metal::float3 weft_env_brdf_from_lut_k16_(
    metal::float2 scale_bias
) {
    metal::float2 sb = metal::saturate(scale_bias);
    return (metal::float3(0.8999996, 0.8999996, 0.8999996) * sb.x) + metal::float3(sb.y);
}

type_12 weft_film_base_amplitudes_k22_(
    float n2_,
    float cos2_,
    float sin1_sq
) {
    metal::float3 cos3_ = metal::sqrt(metal::max(metal::float3(1.0) - (metal::float3(sin1_sq) / metal::float3(1441.9869, 1441.9869, 1441.9869)), metal::float3(0.0)));
    metal::float3 s_1 = (metal::float3(n2_ * cos2_) - (metal::float3(37.973503, 37.973503, 37.973503) * cos3_)) / metal::max(metal::float3(n2_ * cos2_) + (metal::float3(37.973503, 37.973503, 37.973503) * cos3_), metal::float3(0.000000000001));
    metal::float3 p_1 = ((metal::float3(37.973503, 37.973503, 37.973503) * cos2_) - (metal::float3(n2_) * cos3_)) / metal::max((metal::float3(37.973503, 37.973503, 37.973503) * cos2_) + (metal::float3(n2_) * cos3_), metal::float3(0.000000000001));
    return type_12 {{s_1, p_1}};
}

WeftFilmStack weft_film_stack_k20_(
    float cos_theta1_
) {
    float cos1_ = metal::clamp(cos_theta1_, 0.0, 1.0);
    float sin1_sq_1 = 1.0 - (cos1_ * cos1_);
    float _e10 = weft_film_ior_k19_();
    float cos2_sq = 1.0 - (sin1_sq_1 / (_e10 * _e10));
    if (cos2_sq <= 0.0) {
        return WeftFilmStack {_e10, 0.0, metal::float2(1.0), type_12 {{metal::float3(1.0), metal::float3(1.0)}}, true};
    }
    float cos2_1 = metal::sqrt(cos2_sq);
    metal::float2 _e23 = weft_fresnel_amplitudes_k4_(_e10, cos1_, cos2_1);
    type_12 _e24 = weft_film_base_amplitudes_k22_(_e10, cos2_1, sin1_sq_1);
    return WeftFilmStack {_e10, cos2_1, _e23, _e24, false};
}

metal::float3 weft_film_fourier_layers_k17_(
    float cos_theta1_1,
    metal::sampler material_clamp_sampler,
    metal::texture2d<float, metal::access::sample> film_sensitivity
) {
    WeftFilmStack _e6 = weft_film_stack_k20_(cos_theta1_1);
    if (_e6.total_internal_reflection) {
        return metal::float3(1.0);
    }
    WeftFilmSeries _e13 = weft_film_series(_e6.r12_.x, _e6.r23_.inner[0]);
    WeftFilmSeries _e18 = weft_film_series(_e6.r12_.y, _e6.r23_.inner[1]);
    float path = (2.0 * _e6.n2_) * _e6.cos2_;
    metal::float3 _e29 = weft_film_orders(path * 420.0, _e13, _e18, material_clamp_sampler, film_sensitivity);
    metal::float3 r1_ = (_e13.dc + _e18.dc) + _e29;
    metal::float3 _e36 = weft_film_orders(path * 420.0, _e13, _e18, material_clamp_sampler, film_sensitivity);
    metal::float3 r2_ = (_e13.dc + _e18.dc) + _e36;
    return metal::clamp(0.25 * (r1_ + r2_), metal::float3(0.0), metal::float3(1.0));
}

struct vs_mainInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float4 tangent [[attribute(2)]];
    metal::float2 uv0_ [[attribute(3)]];
};
struct vs_mainOutput {
    metal::float4 clip_position [[position]];
    metal::float3 world_position [[user(loc0), center_perspective]];
    metal::float3 world_normal [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
};
vertex vs_mainOutput vs_main(
  vs_mainInput varyings [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(1)]]
) {
    const WeftVertexInput in = { varyings.position, varyings.normal, varyings.tangent, varyings.uv0_ };
    WeftVaryings _e1 = weft_forward_vertex(in, weft_frame, weft_object);
    const auto _tmp = _e1;
    return vs_mainOutput { _tmp.clip_position, _tmp.world_position, _tmp.world_normal, _tmp.world_tangent, _tmp.uv0_ };
}


struct fs_mainInput {
    metal::float3 world_position_2 [[user(loc0), center_perspective]];
    metal::float3 world_normal_1 [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
};
struct fs_mainOutput {
    metal::float4 member_1 [[color(0)]];
};
fragment fs_mainOutput fs_main(
  fs_mainInput varyings_1 [[stage_in]]
, metal::float4 clip_position [[position]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, metal::texturecube<float, metal::access::sample> weft_environment [[texture(0)]]
, metal::sampler weft_environment_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> weft_brdf_lut [[texture(1)]]
, metal::sampler weft_lut_sampler [[sampler(1)]]
, metal::sampler material_clamp_sampler [[sampler(2)]]
, metal::texture2d<float, metal::access::sample> film_sensitivity [[texture(2)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    float film_cos = {};
    metal::float2 direction_ts = metal::float2(1.0, 0.0);
    metal::float3 surface_base = {};
    metal::float3 f_light = {};
    metal::float3 e_spec = {};
    float light_cos = {};
    metal::float3 film_view = {};
    metal::float3 film_light = {};
    WeftSurface _e11 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_4 = _e11.v;
    metal::float3 geometric_n = _e11.n;
    n = geometric_n;
    metal::float3 _e15 = n;
    WeftLightGeometry _e16 = weft_main_light_geometry(_e15, v_4);
    film_cos = _e16.n_dot_v;
    metal::float2 _e23 = weft_env_brdf_lut_k6_(_e16.n_dot_v, weft_brdf_lut, weft_lut_sampler);
    metal::float3 _e25 = weft_f_schlick_k15_(_e16.v_dot_h);
    f_light = _e25;
    metal::float3 _e27 = weft_env_brdf_from_lut_k16_(_e23);
    e_spec = _e27;
    {
        light_cos = _e16.v_dot_h;
        {
            float _e36 = film_cos;
            metal::float3 _e37 = weft_film_fourier_layers_k17_(_e36, material_clamp_sampler, film_sensitivity);
            film_view = _e37;
            float _e38 = light_cos;
            metal::float3 _e39 = weft_film_fourier_layers_k17_(_e38, material_clamp_sampler, film_sensitivity);
            film_light = _e39;
        }
        metal::float3 _e40 = f_light;
        metal::float3 _e41 = film_light;
        f_light = metal::mix(_e40, _e41, 1.0);
        metal::float3 _e43 = e_spec;
        metal::float3 _e44 = film_view;
        e_spec = metal::mix(_e43, _e44 * (_e23.x + _e23.y), 1.0);
    }
    metal::float3 _e51 = e_spec;
    metal::float3 kd = metal::max(metal::float3(1.0) - _e51, metal::float3(0.0));
    float _e57 = weft_v_smith_ggx_correlated_k8_(_e16.n_dot_v, _e16.n_dot_l);
    metal::float3 _e58 = n;
    float _e60 = weft_d_ggx_nh_k9_(_e58, _e16.h);
    metal::float3 _e62 = f_light;
    metal::float3 specular = (_e60 * _e57) * _e62;
    metal::float3 diffuse = kd * metal::float3(0.0, 0.0, 0.0);
    metal::float3 direct = ((diffuse + specular) * metal::float3(3.0, 2.8799999, 2.6999998)) * _e16.n_dot_l;
    metal::float3 _e72 = n;
    metal::float3 _e74 = weft_prefiltered_radiance_k10_(metal::reflect(-(v_4), _e72), weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 _e75 = e_spec;
    metal::float3 indirect_specular = _e74 * _e75;
    metal::float3 _e77 = n;
    metal::float3 _e78 = weft_sh_irradiance(_e77);
    metal::float3 indirect_diffuse = (_e78 * kd) * metal::float3(0.0, 0.0, 0.0);
    metal::float3 color = (direct + indirect_specular) + indirect_diffuse;
    return fs_mainOutput { metal::float4(metal::clamp(color, metal::float3(0.0), metal::float3(65504.0)), 1.0) };
}
