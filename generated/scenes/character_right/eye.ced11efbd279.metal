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
struct EyeCornea {
    float z_iris;
    float centre_z;
    float radius;
};
struct EyeLookup {
    metal::float2 iris;
    char _pad1[8];
    metal::packed_float3 normal;
    float through_cornea;
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
    metal::float3 n,
    constant WeftFrame& weft_frame
) {
    metal::float3 e = {};
    type_5 sh = weft_frame.sh;
    e = sh.inner[0].xyz * 0.282095;
    metal::float3 _e9 = e;
    e = _e9 + (sh.inner[1].xyz * (0.488603 * n.y));
    metal::float3 _e17 = e;
    e = _e17 + (sh.inner[2].xyz * (0.488603 * n.z));
    metal::float3 _e25 = e;
    e = _e25 + (sh.inner[3].xyz * (0.488603 * n.x));
    metal::float3 _e33 = e;
    e = _e33 + (sh.inner[4].xyz * ((1.092548 * n.x) * n.y));
    metal::float3 _e43 = e;
    e = _e43 + (sh.inner[5].xyz * ((1.092548 * n.y) * n.z));
    metal::float3 _e53 = e;
    e = _e53 + (sh.inner[6].xyz * (0.315392 * (((3.0 * n.z) * n.z) - 1.0)));
    metal::float3 _e67 = e;
    e = _e67 + (sh.inner[7].xyz * ((1.092548 * n.x) * n.z));
    metal::float3 _e77 = e;
    e = _e77 + (sh.inner[8].xyz * (0.546274 * ((n.x * n.x) - (n.y * n.y))));
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
    WeftVertexInput in_2,
    constant WeftFrame& weft_frame,
    constant WeftObject& weft_object
) {
    WeftVaryings out = {};
    metal::float4x4 model = weft_object.model;
    metal::float3x3 model3_ = metal::float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    metal::float4x4 nm = weft_object.normal_matrix;
    metal::float3x3 normal3_1 = metal::float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    metal::float4 world = model * metal::float4(in_2.position, 1.0);
    float mirror = (metal::determinant(model3_) < 0.0) ? -1.0 : 1.0;
    float bitangent_sign = ((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror;
    metal::float4x4 _e43 = weft_frame.view_proj;
    out.clip_position = _e43 * metal::float4(world.xyz, 1.0);
    out.world_position = world.xyz;
    metal::float3 _e53 = weft_safe_normalize_k3_(normal3_1 * in_2.normal);
    out.world_normal = _e53;
    metal::float3 _e58 = weft_safe_normalize_k3_(model3_ * in_2.tangent.xyz);
    out.world_tangent = metal::float4(_e58, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    WeftVaryings _e62 = out;
    return _e62;
}

metal::float3 eye_procedural_iris(
    float rho,
    float a
) {
    metal::float3 c_1 = {};
    float t = metal::saturate((rho - 0.38) / 0.62);
    c_1 = metal::mix(metal::float3(0.34239164, 0.147319, 0.021980947), metal::float3(0.10653923, 0.033104766, 0.008540382), metal::smoothstep(0.05, 0.5, t));
    float fibres = (0.82 + (0.1 * metal::sin((a * 23.0) + (6.0 * t)))) + (0.08 * metal::sin(((a * 41.0) - (9.0 * t)) + 1.3));
    metal::float3 _e35 = c_1;
    c_1 = _e35 * fibres;
    metal::float3 _e38 = c_1;
    c_1 = _e38 * (1.0 - (0.8 * metal::smoothstep(0.88, 1.0, rho)));
    metal::float3 _e48 = c_1;
    return metal::mix(metal::float3(0.01), _e48, metal::smoothstep(0.35999998, 0.4, rho));
}

metal::float3 eye_albedo(
    metal::float2 q,
    bool front
) {
    metal::float3 iris = {};
    float rho_2 = metal::length(q) / 0.5;
    {
        metal::float2 qa = (metal::dot(q, q) > 0.000000000001) ? q : metal::float2(1.0, 0.0);
        metal::float3 _e14 = eye_procedural_iris(rho_2, metal::atan2(qa.y, qa.x));
        iris = _e14;
    }
    float to_sclera = front ? metal::smoothstep(0.985, 1.015, rho_2) : 1.0;
    metal::float3 _e21 = iris;
    return metal::saturate(metal::mix(_e21, metal::float3(0.71056646, 0.67385954, 0.6382832), to_sclera));
}

metal::float3 weft_f_schlick_k20_(
    float v_dot_h
) {
    float _e5 = weft_pow5_(1.0 - metal::saturate(v_dot_h));
    return metal::float3(0.025042804) + (metal::float3(0.97495717, 0.97495717, 0.97495717) * _e5);
}

float eye_fresnel_k8_(
    float cos_i
) {
    metal::float3 _e2 = weft_f_schlick_k20_(cos_i);
    return _e2.x;
}

float weft_d_ggx_k14_(
    float n_dot_h
) {
    float noh = metal::saturate(n_dot_h);
    float one_minus_noh2_ = (1.0 - noh) * (1.0 + noh);
    float d = one_minus_noh2_ + ((noh * noh) * 0.000012960001);
    return 0.000012960001 / ((WEFT_PI * d) * d);
}

float weft_v_smith_ggx_correlated_newton_k15_(
    float n_dot_v,
    float n_dot_l
) {
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float gv = (_e6 * 0.9964) + 0.0036000002;
    float gl = (_e7 * 0.9964) + 0.0036000002;
    float pv = (gv * _e6) + (0.000012960001 * (1.0 - _e6));
    float pl = (gl * _e7) + (0.000012960001 * (1.0 - _e7));
    return ((0.5 * gv) * gl) / (((_e7 * gl) * pv) + ((_e6 * gv) * pl));
}

float eye_ggx_k9_(
    metal::float3 s,
    metal::float3 h,
    float s_dot_v,
    float s_dot_l
) {
    float _e7 = weft_d_ggx_k14_(metal::saturate(metal::dot(s, h)));
    float _e8 = weft_v_smith_ggx_correlated_newton_k15_(s_dot_v, s_dot_l);
    return _e7 * _e8;
}

float weft_specular_mip_k16_(
    constant WeftFrame& weft_frame
) {
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return 0.09948 * max_mip;
}

metal::float3 weft_prefiltered_radiance_k11_(
    metal::float3 dir,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip_k16_(weft_frame);
    metal::float4 c_2 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_2.xyz, metal::float3(0.0));
}

metal::float2 weft_env_brdf_lut_k12_(
    float n_dot_v_1,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv = metal::float2(metal::saturate(n_dot_v_1), 0.060000002);
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv, metal::level(0.0));
    return _e8.xy;
}

metal::float3 weft_env_brdf_from_lut_k19_(
    metal::float2 scale_bias
) {
    metal::float2 sb = metal::saturate(scale_bias);
    return (metal::float3(0.025042804) * sb.x) + metal::float3(sb.y);
}

metal::float3 eye_physical_k7_(
    EyeLookup look_1,
    metal::float3 n_1,
    metal::float3 v_3,
    metal::float3 l,
    metal::float3x3 normal3_,
    metal::float3 light,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    bool local = {};
    if (!((look_1.through_cornea > 0.0))) {
        local = look_1.normal[2] > 0.0;
    } else {
        local = true;
    }
    bool _e19 = local;
    metal::float3 _e20 = eye_albedo(look_1.iris, _e19);
    metal::float3 _e24 = weft_safe_normalize(normal3_ * metal::float3(look_1.normal), n_1);
    float _e26 = weft_clamp_cos(metal::dot(_e24, v_3));
    float s_dot_l_1 = metal::saturate(metal::dot(_e24, l));
    metal::float3 _e30 = weft_safe_normalize(l + v_3, _e24);
    float _e32 = eye_fresnel_k8_(metal::dot(v_3, _e30));
    float _e33 = eye_ggx_k9_(_e24, _e30, _e26, s_dot_l_1);
    float direct_spec = (_e33 * _e32) * s_dot_l_1;
    metal::float3 _e39 = weft_prefiltered_radiance_k11_(metal::reflect(-(v_3), _e24), weft_frame, weft_environment, weft_environment_sampler);
    metal::float2 _e40 = weft_env_brdf_lut_k12_(_e26, weft_brdf_lut, weft_lut_sampler);
    metal::float3 _e41 = weft_env_brdf_from_lut_k19_(_e40);
    metal::float3 env = _e39 * _e41;
    metal::float3 specular = (light * direct_spec) + env;
    bool on_iris = look_1.through_cornea > 0.0;
    metal::float3 _e50 = weft_safe_normalize(normal3_ * metal::float3(0.0, 0.0, 1.0), n_1);
    metal::float3 l_in = metal::refract(-(l), _e24, 0.7267442);
    float iris_cos = (s_dot_l_1 > 0.0) ? metal::saturate(metal::dot(_e50, -(l_in))) : 0.0;
    float _e61 = eye_fresnel_k8_(_e26);
    float t_v = 1.0 - _e61;
    float _e64 = eye_fresnel_k8_(s_dot_l_1);
    float t_l = 1.0 - _e64;
    metal::float3 diffuse_n = on_iris ? _e50 : n_1;
    float diffuse_cos = on_iris ? (iris_cos * t_l) : metal::saturate(metal::dot(n_1, l));
    float transmission = on_iris ? t_v : 1.0;
    metal::float3 _e78 = weft_sh_irradiance(diffuse_n, weft_frame);
    metal::float3 diffuse = (_e20 * transmission) * ((light * (WEFT_INV_PI * diffuse_cos)) + _e78);
    return diffuse + specular;
}

float eye_cornea_height_k17_(
    float rho_1
) {
    float z = 0.5380625 + metal::sqrt(metal::max(0.35755965 - (rho_1 * rho_1), 0.0));
    return metal::max(z - 0.8660254, 0.0);
}

metal::float3 eye_cornea_normal_k18_(
    metal::float2 xy
) {
    float z_1 = metal::sqrt(metal::max(0.35755965 - metal::dot(xy, xy), 0.0));
    return metal::float3(xy, z_1) / metal::float3(0.5979629);
}

EyeLookup eye_parallax_k13_(
    metal::float3 p,
    metal::float3 v_4
) {
    bool local_1 = {};
    float rho_3 = metal::length(p.xy);
    if (!((p.z <= 0.0))) {
        local_1 = rho_3 >= 0.5;
    } else {
        local_1 = true;
    }
    bool _e15 = local_1;
    if (_e15) {
        return EyeLookup {p.xy, {}, p, 0.0};
    }
    float _e21 = eye_cornea_height_k17_(rho_3);
    float d_1 = (0.8660254 + _e21) - p.z;
    metal::float2 e_raw = p.xy + (d_1 * v_4.xy);
    metal::float2 e_1 = e_raw * metal::min(1.0, 0.5 / metal::max(metal::length(e_raw), 0.000001));
    float _e37 = eye_cornea_height_k17_(metal::length(e_1));
    metal::float3 _e38 = eye_cornea_normal_k18_(e_1);
    metal::float2 iris_1 = e_1 - (_e37 * ((v_4.xy * 0.7267442) + (_e38.xy * 0.27325583)));
    return EyeLookup {iris_1, {}, _e38, 1.0};
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
, constant WeftObject& weft_object [[buffer(1)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 color = {};
    EyeLookup look = {};
    metal::float4x4 model_1 = weft_object.model;
    metal::float3x3 model3_1 = metal::float3x3(model_1[0].xyz, model_1[1].xyz, model_1[2].xyz);
    metal::float4x4 nm_1 = weft_object.normal_matrix;
    metal::float3x3 normal3_2 = metal::float3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    WeftSurface _e23 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_5 = _e23.v;
    metal::float3 n_2 = _e23.n;
    metal::float3 _e26 = weft_main_light_direction(weft_frame);
    metal::float3 _e29 = weft_safe_normalize_k1_(metal::transpose(model3_1) * n_2);
    metal::float3 _e32 = weft_safe_normalize_k1_(metal::transpose(normal3_2) * v_5);
    metal::float3 _e35 = weft_safe_normalize(model3_1 * metal::float3(0.0, 0.0, 1.0), n_2);
    float dimming = 1.0 - (0.5 * metal::saturate(-(metal::dot(_e35, _e26))));
    metal::float3 _e43 = weft_main_light_radiance(weft_frame);
    {
        {
            EyeLookup _e48 = eye_parallax_k13_(_e29, _e32);
            look = _e48;
        }
        EyeLookup _e49 = look;
        metal::float3 _e50 = eye_physical_k7_(_e49, n_2, v_5, _e26, normal3_2, _e43, weft_frame, weft_environment, weft_environment_sampler, weft_brdf_lut, weft_lut_sampler);
        color = _e50;
    }
    metal::float3 _e51 = color;
    metal::float3 radiance = metal::clamp(_e51 * dimming, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
