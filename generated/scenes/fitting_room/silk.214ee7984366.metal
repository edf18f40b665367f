// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

typedef float weft_half;
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
struct SilkLobe {
    float value;
    char _pad1[4];
    metal::float2 alpha;
    float ibl_roughness;
    char _pad3[4];
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint ANISO_MODEL_WARD = 0u;
constant uint ANISO_MODEL_HAIR_SHIFTED = 1u;
constant uint ANISO_MODEL_GGX = 2u;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant uint TIER_LOW = 3u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float WEFT_MIN_ANISO_ALPHA = 0.001;
constant float SILK_MIN_ALPHA = 0.001;
constant float WEFT_MIN_ROUGHNESS_HALF = 0.089;
constant float WEFT_MIN_N_DOT_HALF = 0.001;
constant float WEFT_MIN_ALPHA_HALF = 0.007921;

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

metal::float3 weft_any_perpendicular(
    metal::float3 n
) {
    float s = (n.z >= 0.0) ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = (n.x * n.y) * a;
    return metal::float3(1.0 + (((s * n.x) * n.x) * a), s * b, -(s) * n.x);
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

float weft_specular_mip(
    float roughness,
    constant WeftFrame& weft_frame
) {
    float r = metal::saturate(roughness);
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return (r * (1.7 - (0.7 * r))) * max_mip;
}

metal::float3 weft_prefiltered_radiance(
    metal::float3 dir,
    float roughness_1,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip(roughness_1, weft_frame);
    metal::float4 c_1 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_1.xyz, metal::float3(0.0));
}

metal::float2 weft_env_brdf_lut(
    float n_dot_v,
    float roughness_2,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv = metal::float2(metal::saturate(n_dot_v), metal::saturate(roughness_2));
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv, metal::level(0.0));
    return _e8.xy;
}

metal::float3 weft_safe_normalize_k8_(
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
    metal::float3 _e7 = weft_safe_normalize_k8_(_e4.xyz - world_position);
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

metal::float3x3 weft_tangent_frame(
    metal::float3 n_3,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_3 * metal::dot(n_3, t_in));
    float len2_3 = metal::dot(t_proj, t_proj);
    bool ok = len2_3 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_3);
    metal::float3 t = ok ? (t_proj * metal::rsqrt(metal::max(len2_3, 0.00000000000000000001))) : _e13;
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_3, t) * s_1;
    return metal::float3x3(t, b_1, n_3);
}

metal::float3 weft_aniso_to_frame(
    metal::float3x3 frame,
    metal::float3 x
) {
    return metal::float3(metal::dot(frame[0], x), metal::dot(frame[1], x), metal::dot(frame[2], x));
}

metal::float3 weft_aniso_bent_normal(
    metal::float3x3 frame_1,
    metal::float3 v_4,
    float anisotropy,
    float roughness_3
) {
    float k = metal::clamp(anisotropy, -1.0, 1.0);
    metal::float3 n_4 = frame_1[2];
    metal::float3 dir_1 = (k >= 0.0) ? frame_1[1] : frame_1[0];
    metal::float3 aniso_t = metal::cross(dir_1, v_4);
    metal::float3 aniso_n = metal::cross(aniso_t, dir_1);
    float bend = metal::abs(k) * metal::saturate(5.0 * metal::saturate(roughness_3));
    metal::float3 _e22 = weft_safe_normalize(metal::mix(n_4, aniso_n, bend), n_4);
    return _e22;
}

float silk_lobe_anisotropy(
    metal::float2 alpha
) {
    float at = metal::max(alpha.x, SILK_MIN_ALPHA);
    float ab = metal::max(alpha.y, SILK_MIN_ALPHA);
    return (at - ab) / (at + ab);
}

weft_half weft_half_pow5_(
    weft_half x_1
) {
    weft_half x2_ = x_1 * x_1;
    return (x2_ * x2_) * x_1;
}

metal::float3 weft_half_f_schlick_k10_(
    weft_half v_dot_h
) {
    weft_half _e5 = weft_half_pow5_(1.0 - v_dot_h);
    return metal::float3(0.14609632, 0.10047833, 0.11062463) + (metal::float3(0.85390365, 0.89952165, 0.8893754) * _e5);
}

metal::float3 silk_low_k7_(
    metal::float3x3 frame_2,
    metal::float3 n_spec,
    metal::float3 n_diff,
    metal::float3 v_5,
    float n_dot_v_1,
    float v_dot_h_1,
    float n_dot_l_diffuse,
    SilkLobe lobe_1,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float3 _e13 = weft_half_f_schlick_k10_(static_cast<float>(v_dot_h_1));
    metal::float3 kd = (metal::float3(1.0) - _e13) * (static_cast<float>(n_dot_l_diffuse) * 0.31830987);
    metal::float3 direct = ((metal::float3(0.45638528, 0.27391332, 0.3144985) * static_cast<metal::float3>(kd)) + (static_cast<metal::float3>(_e13) * lobe_1.value)) * metal::float3(3.2, 3.05, 2.8);
    metal::float2 _e28 = weft_env_brdf_lut(n_dot_v_1, lobe_1.ibl_roughness, weft_brdf_lut, weft_lut_sampler);
    metal::float2 lut = metal::saturate(_e28);
    metal::float3 env_brdf_1 = (metal::float3(0.14609632, 0.10047833, 0.11062463) * static_cast<float>(lut.x)) + metal::float3(static_cast<float>(lut.y));
    metal::float3 ambient_kd_1 = metal::max(metal::float3(1.0) - env_brdf_1, metal::float3(0.0));
    float _e42 = silk_lobe_anisotropy(lobe_1.alpha);
    metal::float3 _e44 = weft_aniso_bent_normal(frame_2, v_5, _e42, lobe_1.ibl_roughness);
    metal::float3 _e48 = weft_prefiltered_radiance(metal::reflect(-(v_5), _e44), lobe_1.ibl_roughness, weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 _e51 = weft_sh_irradiance(n_diff);
    metal::float3 indirect = (_e48 * static_cast<metal::float3>(env_brdf_1)) + ((_e51 * static_cast<metal::float3>(ambient_kd_1)) * metal::float3(0.45638528, 0.27391332, 0.3144985));
    return metal::clamp(direct + indirect, metal::float3(0.0), metal::float3(65504.0));
}

metal::float3 weft_normal_from_tangent_space_k11_(
    metal::float3x3 frame_3
) {
    metal::float3 _e4 = weft_safe_normalize(frame_3 * metal::float3(metal::float2(0.002352977, 0.002352977), 1.0), frame_3[2]);
    return _e4;
}

float silk_ward_bounded_k13_(
    metal::float3 v_6,
    metal::float3 l
) {
    bool local = {};
    metal::float3 hv = v_6 + l;
    float hn = metal::max(hv.z, 0.0001);
    float hn2_ = hn * hn;
    float x_2 = hv.x / 0.20215853;
    float y = hv.y / 0.047507256;
    float f = (metal::dot(hv, hv) / ((0.030171847 * hn2_) * hn2_)) * metal::exp(-(((x_2 * x_2) + (y * y))) / hn2_);
    if (v_6.z > 0.0) {
        local = l.z > 0.0;
    } else {
        local = false;
    }
    bool _e35 = local;
    return _e35 ? f : 0.0;
}

struct vs_mainInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float4 tangent_1 [[attribute(2)]];
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
    const WeftVertexInput in = { varyings.position, varyings.normal, varyings.tangent_1, varyings.uv0_ };
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
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 fibre = {};
    SilkLobe lobe = {};
    float vis = {};
    metal::float3 env_brdf = {};
    metal::float3 ambient_kd = {};
    metal::float3 reflect_n = {};
    WeftSurface _e11 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_7 = _e11.v;
    metal::float3 n_geo = _e11.n;
    metal::float3x3 _e15 = weft_tangent_frame(n_geo, in_1.world_tangent);
    metal::float3 _e17 = weft_normal_from_tangent_space_k11_(_e15);
    fibre = _e15[0];
    metal::float3 _e20 = fibre;
    metal::float3x3 _e24 = weft_tangent_frame(_e17, metal::float4(_e20, in_1.world_tangent.w));
    WeftLightGeometry _e25 = weft_main_light_geometry(_e17, v_7);
    metal::float3 _e26 = weft_aniso_to_frame(_e24, v_7);
    metal::float3 _e28 = weft_aniso_to_frame(_e24, _e25.l);
    {
        lobe.alpha = metal::float2(0.20215853, 0.047507256);
        lobe.ibl_roughness = 0.3130495;
        {
            float _e36 = silk_ward_bounded_k13_(_e26, _e28);
            lobe.value = _e36 * _e25.n_dot_l;
        }
    }
    float n_dot_l_diffuse_1 = metal::saturate(metal::dot(n_geo, _e25.l));
    {
        SilkLobe _e45 = lobe;
        metal::float3 _e46 = silk_low_k7_(_e24, _e17, n_geo, v_7, _e25.n_dot_v, _e25.v_dot_h, n_dot_l_diffuse_1, _e45, weft_frame, weft_environment, weft_environment_sampler, weft_brdf_lut, weft_lut_sampler);
        return fs_mainOutput { metal::float4(_e46, 1.0) };
    }
}
