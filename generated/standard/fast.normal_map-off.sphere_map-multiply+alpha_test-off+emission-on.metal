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
struct WeftMaterial {
    metal::float4 base_color;
    float roughness;
    float metallic;
    float occlusion_strength;
    float normal_strength;
    float specular_strength;
    char _pad6[12];
    metal::float4 emissive;
    float emissive_strength;
    float alpha_cutoff;
    float sphere_strength;
    char _pad10[4];
    metal::float4 base_map_st;
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
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint SPHERE_MAP_OFF = 0u;
constant uint SPHERE_MAP_ADD = 1u;
constant uint SPHERE_MAP_MULTIPLY = 2u;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant uint TIER_LOW = 3u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float WEFT_MIN_ROUGHNESS_HALF = 0.089;
constant float WEFT_MIN_N_DOT_HALF = 0.001;
constant float WEFT_MIN_ALPHA_HALF = 0.007921;
constant bool ALPHA_TEST = false;
constant bool EMISSION = true;

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

float weft_clamp_roughness(
    float roughness
) {
    return metal::clamp(roughness, WEFT_MIN_ROUGHNESS, 1.0);
}

metal::float3 weft_safe_normalize(
    metal::float3 v,
    metal::float3 fallback
) {
    float len2_ = metal::dot(v, v);
    return (len2_ > 0.00000000000000000001) ? (v * metal::rsqrt(metal::max(len2_, 0.00000000000000000001))) : fallback;
}

float weft_d_ggx(
    float n_dot_h,
    float roughness_1
) {
    float _e2 = weft_clamp_roughness(roughness_1);
    float a = _e2 * _e2;
    float a2_ = a * a;
    float noh = metal::saturate(n_dot_h);
    float one_minus_noh2_ = (1.0 - noh) * (1.0 + noh);
    float d_1 = one_minus_noh2_ + ((noh * noh) * a2_);
    return a2_ / ((WEFT_PI * d_1) * d_1);
}

metal::float3 weft_f_schlick(
    metal::float3 f0_,
    float v_dot_h
) {
    float _e5 = weft_pow5_(1.0 - metal::saturate(v_dot_h));
    return f0_ + ((metal::float3(1.0) - f0_) * _e5);
}

float weft_v_smith_ggx_correlated_newton(
    float n_dot_v,
    float n_dot_l,
    float roughness_2
) {
    float _e3 = weft_clamp_roughness(roughness_2);
    float a_1 = _e3 * _e3;
    float a2_1 = a_1 * a_1;
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float gv = (_e6 * (1.0 - a_1)) + a_1;
    float gl = (_e7 * (1.0 - a_1)) + a_1;
    float pv = (gv * _e6) + (a2_1 * (1.0 - _e6));
    float pl = (gl * _e7) + (a2_1 * (1.0 - _e7));
    return ((0.5 * gv) * gl) / (((_e7 * gl) * pv) + ((_e6 * gv) * pl));
}

metal::float3 weft_diffuse_lambert(
    metal::float3 albedo
) {
    return albedo * WEFT_INV_PI;
}

metal::float3 weft_env_brdf_from_lut(
    metal::float3 f0_1,
    metal::float2 scale_bias
) {
    metal::float2 sb = metal::saturate(scale_bias);
    return (f0_1 * sb.x) + metal::float3(sb.y);
}

metal::float3 weft_main_light_direction(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_direction;
    metal::float3 _e8 = weft_safe_normalize(_e2.xyz, metal::float3(0.0, 0.0, 1.0));
    return _e8;
}

metal::float3 weft_main_light_radiance(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_color;
    return metal::max(_e2.xyz, metal::float3(0.0));
}

metal::float3 weft_view_direction(
    metal::float3 world_position,
    metal::float3 fallback_1,
    constant WeftFrame& weft_frame
) {
    metal::float4 _e4 = weft_frame.camera_position;
    metal::float3 _e7 = weft_safe_normalize(_e4.xyz - world_position, fallback_1);
    return _e7;
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

float weft_specular_mip(
    float roughness_3,
    constant WeftFrame& weft_frame
) {
    float r = metal::saturate(roughness_3);
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return (r * (1.7 - (0.7 * r))) * max_mip;
}

metal::float3 weft_prefiltered_radiance(
    metal::float3 dir,
    float roughness_4,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip(roughness_4, weft_frame);
    metal::float4 c_1 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_1.xyz, metal::float3(0.0));
}

metal::float2 weft_env_brdf_lut(
    float n_dot_v_1,
    float roughness_5,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv_2 = metal::float2(metal::saturate(n_dot_v_1), metal::saturate(roughness_5));
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv_2, metal::level(0.0));
    return _e8.xy;
}

metal::float3 weft_sphere_map_direction(
    metal::float3 world_normal,
    metal::float3 world_position_1,
    constant WeftFrame& weft_frame
) {
    metal::float4x4 view = weft_frame.view;
    metal::float3x3 view3_ = metal::float3x3(view[0].xyz, view[1].xyz, view[2].xyz);
    metal::float3 _e17 = weft_safe_normalize(view3_ * world_normal, metal::float3(0.0, 0.0, 1.0));
    metal::float3 p_vs = (view * metal::float4(world_position_1, 1.0)).xyz;
    metal::float3 _e26 = weft_safe_normalize(p_vs, metal::float3(0.0, 0.0, -1.0));
    return metal::reflect(_e26, _e17);
}

WeftSurface weft_surface_two_sided(
    metal::float3 world_position_2,
    metal::float3 world_normal_1,
    bool front_facing_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e7 = weft_view_direction(world_position_2, metal::float3(0.0, 0.0, 1.0), weft_frame);
    metal::float3 facing = front_facing_1 ? world_normal_1 : -(world_normal_1);
    metal::float3 _e10 = weft_safe_normalize(facing, _e7);
    return WeftSurface {_e7, _e10};
}

WeftLightGeometry weft_main_light_geometry(
    metal::float3 n_2,
    metal::float3 v_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_1, n_2);
    float _e6 = weft_clamp_cos(metal::dot(n_2, v_1));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_2, _e2)), metal::saturate(metal::dot(n_2, _e4)), metal::saturate(metal::dot(v_1, _e4))};
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
    metal::float3 _e55 = weft_safe_normalize(normal3_ * in_2.normal, metal::float3(0.0));
    out.world_normal = _e55;
    metal::float3 _e62 = weft_safe_normalize(model3_ * in_2.tangent.xyz, metal::float3(0.0));
    out.world_tangent = metal::float4(_e62, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out;
    return _e66;
}

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

metal::float3 standard_emission(
    metal::float2 uv_1,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> emissive_map
) {
    if (EMISSION) {
        float _e4 = material.emissive_strength;
        float strength = metal::max(_e4, 0.0);
        metal::float4 _e9 = material.emissive;
        metal::float3 emissive = metal::max(_e9.xyz, metal::float3(0.0));
        metal::float4 _e17 = emissive_map.sample(material_sampler, uv_1);
        return (emissive * strength) * _e17.xyz;
    }
    return metal::float3(0.0);
}

metal::float3 standard_sphere_map(
    metal::float3 color_in,
    metal::float3 n_3,
    metal::float3 world_position_3,
    constant WeftFrame& weft_frame,
    constant WeftMaterial& material,
    metal::sampler material_clamp_sampler,
    metal::texturecube<float, metal::access::sample> sphere_map
) {
    metal::float3 color = {};
    color = color_in;
    {
        metal::float3 _e4 = weft_sphere_map_direction(n_3, world_position_3, weft_frame);
        metal::float4 _e7 = sphere_map.sample(material_clamp_sampler, _e4);
        metal::float3 sph = metal::max(_e7.xyz, metal::float3(0.0));
        metal::float3 _e12 = color;
        float _e17 = material.sphere_strength;
        color = _e12 * metal::max(metal::mix(metal::float3(1.0), sph, _e17), metal::float3(0.0));
    }
    metal::float3 _e23 = color;
    return _e23;
}

void standard_alpha_test(
    float alpha,
    constant WeftMaterial& material
) {
    if (ALPHA_TEST) {
        float _e4 = material.alpha_cutoff;
        if (alpha < _e4) {
            metal::discard_fragment();
        } else {
            return;
        }
    } else {
        return;
    }
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
, constant WeftObject& weft_object [[buffer(2)]]
) {
    const WeftVertexInput in = { varyings.position, varyings.normal, varyings.tangent, varyings.uv0_ };
    WeftVaryings _e1 = weft_forward_vertex(in, weft_frame, weft_object);
    const auto _tmp = _e1;
    return vs_mainOutput { _tmp.clip_position, _tmp.world_position, _tmp.world_normal, _tmp.world_tangent, _tmp.uv0_ };
}


struct fs_mainInput {
    metal::float3 world_position_4 [[user(loc0), center_perspective]];
    metal::float3 world_normal_2 [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
};
struct fs_mainOutput {
    metal::float4 member_1 [[color(0)]];
};
fragment fs_mainOutput fs_main(
  fs_mainInput varyings_1 [[stage_in]]
, metal::float4 clip_position [[position]]
, bool front_facing [[front_facing]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, metal::texturecube<float, metal::access::sample> weft_environment [[texture(0)]]
, metal::sampler weft_environment_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> weft_brdf_lut [[texture(1)]]
, metal::sampler weft_lut_sampler [[sampler(1)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::sampler material_clamp_sampler [[sampler(3)]]
, metal::texture2d<float, metal::access::sample> emissive_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(3)]]
, metal::texture2d<float, metal::access::sample> rmo_map [[texture(4)]]
, metal::texturecube<float, metal::access::sample> sphere_map [[texture(5)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_4, varyings_1.world_normal_2, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 n = {};
    float visibility = {};
    metal::float3 env_brdf = {};
    metal::float3 ambient_kd = {};
    metal::float3 direct_kd = {};
    metal::float3 specular = metal::float3(0.0);
    metal::float3 indirect_specular = metal::float3(0.0);
    float d = {};
    metal::float4 _e5 = material.base_map_st;
    metal::float2 _e6 = weft_transform_uv(in_1.uv0_, _e5);
    metal::float4 _e9 = material.base_color;
    metal::float4 _e12 = base_map.sample(material_sampler, _e6);
    metal::float4 base_rgba = _e9 * _e12;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float alpha_1 = metal::saturate(base_rgba.w);
    metal::float4 _e20 = rmo_map.sample(material_sampler, _e6);
    metal::float3 rmo = _e20.xyz;
    metal::float3 _e22 = standard_emission(_e6, material, material_sampler, emissive_map);
    float _e25 = material.roughness;
    float roughness_6 = metal::saturate(_e25 * rmo.x);
    float _e31 = material.metallic;
    float metallic = metal::saturate(_e31 * rmo.y);
    float _e38 = material.occlusion_strength;
    float ao = metal::saturate(metal::mix(1.0, rmo.z, _e38));
    float _e44 = material.specular_strength;
    float specular_strength = metal::max(_e44, 0.0);
    WeftSurface _e49 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing, weft_frame);
    metal::float3 v_2 = _e49.v;
    n = _e49.n;
    metal::float3 _e53 = n;
    WeftLightGeometry _e54 = weft_main_light_geometry(_e53, v_2, weft_frame);
    metal::float3 f0_2 = metal::mix(metal::float3(0.04), base, metallic);
    metal::float3 diffuse_albedo = base * (1.0 - metallic);
    {
        {
            float _e67 = weft_v_smith_ggx_correlated_newton(_e54.n_dot_v, _e54.n_dot_l, roughness_6);
            visibility = _e67;
            metal::float2 _e69 = weft_env_brdf_lut(_e54.n_dot_v, roughness_6, weft_brdf_lut, weft_lut_sampler);
            metal::float3 _e70 = weft_env_brdf_from_lut(f0_2, _e69);
            env_brdf = _e70;
            metal::float3 _e73 = env_brdf;
            ambient_kd = metal::max(metal::float3(1.0) - _e73, metal::float3(0.0));
            metal::float3 _e78 = ambient_kd;
            direct_kd = _e78;
        }
    }
    if (specular_strength > 0.0) {
        metal::float3 _e88 = weft_f_schlick(f0_2, _e54.v_dot_h);
        {
            float _e91 = weft_d_ggx(_e54.n_dot_h, roughness_6);
            d = _e91;
        }
        float _e92 = d;
        float _e93 = visibility;
        specular = ((_e92 * _e93) * _e88) * specular_strength;
        metal::float3 _e98 = n;
        metal::float3 _e100 = weft_prefiltered_radiance(metal::reflect(-(v_2), _e98), roughness_6, weft_frame, weft_environment, weft_environment_sampler);
        metal::float3 _e101 = env_brdf;
        indirect_specular = (_e100 * _e101) * (ao * specular_strength);
    }
    metal::float3 _e105 = direct_kd;
    metal::float3 _e106 = weft_diffuse_lambert(diffuse_albedo);
    metal::float3 diffuse = _e105 * _e106;
    metal::float3 _e108 = specular;
    metal::float3 _e110 = weft_main_light_radiance(weft_frame);
    metal::float3 direct = ((diffuse + _e108) * _e110) * _e54.n_dot_l;
    metal::float3 _e114 = n;
    metal::float3 _e115 = weft_sh_irradiance(_e114, weft_frame);
    metal::float3 _e117 = ambient_kd;
    metal::float3 indirect_diffuse = ((_e115 * ao) * _e117) * diffuse_albedo;
    metal::float3 _e120 = indirect_specular;
    metal::float3 color_1 = (direct + _e120) + indirect_diffuse;
    metal::float3 _e123 = n;
    metal::float3 _e125 = standard_sphere_map(color_1, _e123, in_1.world_position, weft_frame, material, material_clamp_sampler, sphere_map);
    metal::float3 radiance = metal::clamp(_e125 + _e22, metal::float3(0.0), metal::float3(65504.0));
    standard_alpha_test(alpha_1, material);
    return fs_mainOutput { metal::float4(radiance, alpha_1) };
}
