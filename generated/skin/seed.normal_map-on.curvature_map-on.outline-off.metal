// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct type_4 {
    metal::float4 inner[9];
};
struct WeftFrame {
    metal::float4x4 view_proj;
    metal::float4x4 view;
    metal::float4 camera_position;
    metal::float4 light_direction;
    metal::float4 light_color;
    type_4 sh;
    metal::float4 params;
    metal::float4 viewport;
};
struct WeftObject {
    metal::float4x4 model;
    metal::float4x4 normal_matrix;
};
struct WeftMaterial {
    metal::float4 base_color;
    metal::float4 base_map_st;
    float normal_strength;
    float roughness;
    float specular;
    float curvature_factor;
    float dark_bound;
    float bright_bound;
    float lobe_weight;
    char _pad9[4];
    metal::float4 outline_color;
    float outline_width;
    float outline_max_distance;
    char _pad12[8];
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
constant metal::float3 skin_lut_shape = metal::float3(4.0, 10.0, 20.0);
constant float skin_lut_ring = 3.1415927;
constant metal::float3 seed_lut_shape = metal::float3(4.0, 10.0, 20.0);
constant float seed_lut_ring = 1.5707964;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_SEED = 2u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;

metal::float4 table_seed_lut(
    metal::float2 uv,
    metal::sampler material_clamp_sampler,
    metal::texture2d<float, metal::access::sample> seed_lut
) {
    metal::float2 size = metal::float2(64.0, 64.0);
    metal::float2 st_1 = ((metal::clamp(uv, metal::float2(0.0), metal::float2(1.0)) * (size - metal::float2(1.0))) + metal::float2(0.5)) / size;
    metal::float4 _e20 = seed_lut.sample(material_clamp_sampler, st_1, metal::level(0.0));
    return _e20;
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

metal::float3 weft_any_perpendicular(
    metal::float3 n_1
) {
    float s = (n_1.z >= 0.0) ? 1.0 : -1.0;
    float a = -1.0 / (s + n_1.z);
    float b = (n_1.x * n_1.y) * a;
    return metal::float3(1.0 + (((s * n_1.x) * n_1.x) * a), s * b, -(s) * n_1.x);
}

metal::float3 weft_diffuse_lambert(
    metal::float3 albedo
) {
    return albedo * WEFT_INV_PI;
}

metal::float3 weft_env_brdf_from_lut(
    metal::float3 f0_,
    metal::float2 scale_bias
) {
    metal::float2 sb = metal::saturate(scale_bias);
    return (f0_ * sb.x) + metal::float3(sb.y);
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
    metal::float3 n_2,
    constant WeftFrame& weft_frame
) {
    metal::float3 e = {};
    type_4 sh = weft_frame.sh;
    e = sh.inner[0].xyz * 0.282095;
    metal::float3 _e9 = e;
    e = _e9 + (sh.inner[1].xyz * (0.488603 * n_2.y));
    metal::float3 _e17 = e;
    e = _e17 + (sh.inner[2].xyz * (0.488603 * n_2.z));
    metal::float3 _e25 = e;
    e = _e25 + (sh.inner[3].xyz * (0.488603 * n_2.x));
    metal::float3 _e33 = e;
    e = _e33 + (sh.inner[4].xyz * ((1.092548 * n_2.x) * n_2.y));
    metal::float3 _e43 = e;
    e = _e43 + (sh.inner[5].xyz * ((1.092548 * n_2.y) * n_2.z));
    metal::float3 _e53 = e;
    e = _e53 + (sh.inner[6].xyz * (0.315392 * (((3.0 * n_2.z) * n_2.z) - 1.0)));
    metal::float3 _e67 = e;
    e = _e67 + (sh.inner[7].xyz * ((1.092548 * n_2.x) * n_2.z));
    metal::float3 _e77 = e;
    e = _e77 + (sh.inner[8].xyz * (0.546274 * ((n_2.x * n_2.x) - (n_2.y * n_2.y))));
    metal::float3 _e91 = e;
    return metal::max(_e91, metal::float3(0.0));
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
    metal::float2 uv_2 = metal::float2(metal::saturate(n_dot_v), metal::saturate(roughness_2));
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv_2, metal::level(0.0));
    return _e8.xy;
}

WeftSurface weft_surface(
    metal::float3 world_position_1,
    metal::float3 world_normal,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e6 = weft_view_direction(world_position_1, metal::float3(0.0, 0.0, 1.0), weft_frame);
    metal::float3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface {_e6, _e7};
}

WeftLightGeometry weft_main_light_geometry(
    metal::float3 n_3,
    metal::float3 v_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_1, n_3);
    float _e6 = weft_clamp_cos(metal::dot(n_3, v_1));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_3, _e2)), metal::saturate(metal::dot(n_3, _e4)), metal::saturate(metal::dot(v_1, _e4))};
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

metal::float3x3 weft_tangent_frame(
    metal::float3 n_4,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_4 * metal::dot(n_4, t_in));
    float len2_1 = metal::dot(t_proj, t_proj);
    bool ok = len2_1 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_4);
    metal::float3 t = ok ? (t_proj * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : _e13;
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_4, t) * s_1;
    return metal::float3x3(t, b_1, n_4);
}

metal::float3 weft_unpack_normal(
    metal::float3 texel,
    float strength
) {
    metal::float3 v_2 = (texel * 2.0) - metal::float3(1.0);
    return metal::float3(v_2.xy * strength, metal::max(v_2.z, 0.001));
}

metal::float3 weft_normal_from_tangent_space(
    metal::float3x3 frame,
    metal::float3 n_ts
) {
    metal::float3 _e4 = weft_safe_normalize(frame * n_ts, frame[2]);
    return _e4;
}

metal::float3 weft_mapped_normal(
    metal::float3 n_5,
    metal::float4 tangent_1,
    metal::float3 texel_1,
    float strength_1
) {
    metal::float3x3 _e4 = weft_tangent_frame(n_5, tangent_1);
    metal::float3 _e5 = weft_unpack_normal(texel_1, strength_1);
    metal::float3 _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
}

metal::float2 weft_transform_uv(
    metal::float2 uv_1,
    metal::float4 st
) {
    return (uv_1 * st.xy) + st.zw;
}

float skin_seed_specular(
    metal::float3 n_6,
    metal::float3 l,
    metal::float3 h,
    float roughness_3,
    float mask,
    float lobe_weight
) {
    float n_dot_h = metal::saturate(metal::dot(n_6, h));
    float l_dot_h = metal::saturate(metal::dot(l, h));
    float r2_ = roughness_3 * roughness_3;
    float normalization = (roughness_3 * 4.0) + 2.0;
    float d = ((n_dot_h * n_dot_h) * (r2_ - 1.0)) + 1.00001;
    float nl = metal::saturate(metal::dot(n_6, l));
    float s_ao = metal::mix(0.100112915, 1.0, metal::saturate(-0.3 + (nl * nl)));
    float denom = ((d * d) * metal::max(0.1, l_dot_h * l_dot_h)) * normalization;
    float ggx = r2_ / denom;
    float second = (((2.0 * r2_) / denom) * lobe_weight) * mask;
    return (((ggx / 2.0) + second) * s_ao) / WEFT_PI;
}

struct vs_mainInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float4 tangent_2 [[attribute(2)]];
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
    const WeftVertexInput in = { varyings.position, varyings.normal, varyings.tangent_2, varyings.uv0_ };
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
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::sampler material_clamp_sampler [[sampler(3)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> normal_map [[texture(3)]]
, metal::texture2d<float, metal::access::sample> curvature_map [[texture(4)]]
, metal::texture2d<float, metal::access::sample> specular_mask [[texture(5)]]
, metal::texture2d<float, metal::access::sample> seed_lut [[texture(6)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    float curvature = {};
    metal::float3 n = {};
    metal::float3 falloff = {};
    float specular = {};
    metal::float3 kd = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    metal::float4 _e8 = material.base_color;
    metal::float4 _e11 = base_map.sample(material_sampler, _e5);
    metal::float4 base_rgba = _e8 * _e11;
    metal::float3 albedo_1 = metal::saturate(base_rgba.xyz);
    float alpha = metal::saturate(base_rgba.w);
    float _e19 = material.roughness;
    float roughness_4 = metal::clamp(_e19, 0.05, 1.0);
    float _e25 = material.specular;
    float f0_1 = metal::clamp(_e25, 0.0, 1.0);
    metal::float4 _e31 = specular_mask.sample(material_sampler, _e5);
    float mask_1 = metal::saturate(_e31.x);
    WeftSurface _e36 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_3 = _e36.v;
    metal::float3 n_geom = _e36.n;
    metal::float3 _e39 = metal::fwidth(n_geom);
    float dn = metal::length(_e39);
    metal::float3 _e42 = metal::fwidth(in_1.world_position);
    float dp = metal::length(_e42);
    float estimated = (dp > 0.000000000001) ? (dn / dp) : 0.0;
    metal::float4 _e51 = curvature_map.sample(material_sampler, _e5);
    float mapped = _e51.x;
    float _e55 = material.curvature_factor;
    float factor = metal::max(_e55, 0.0);
    curvature = metal::saturate(factor * estimated);
    {
        curvature = metal::saturate(factor * mapped);
    }
    n = n_geom;
    {
        metal::float4 _e66 = normal_map.sample(material_sampler, _e5);
        metal::float3 texel_2 = _e66.xyz;
        metal::float3 _e68 = n;
        float _e72 = material.normal_strength;
        metal::float3 _e73 = weft_mapped_normal(_e68, in_1.world_tangent, texel_2, _e72);
        n = _e73;
    }
    metal::float3 _e74 = n;
    WeftLightGeometry _e75 = weft_main_light_geometry(_e74, v_3, weft_frame);
    metal::float3 _e76 = n;
    float _e85 = material.dark_bound;
    float _e88 = material.bright_bound;
    float u = metal::clamp((metal::dot(_e76, _e75.l) * 0.5) + 0.5, _e85, _e88);
    {
        {
            float _e91 = curvature;
            metal::float4 _e93 = table_seed_lut(metal::float2(u, _e91), material_clamp_sampler, seed_lut);
            falloff = _e93.xyz;
        }
    }
    metal::float3 _e95 = falloff;
    falloff = metal::max(_e95, metal::float3(0.0));
    metal::float2 _e101 = weft_env_brdf_lut(_e75.n_dot_v, roughness_4, weft_brdf_lut, weft_lut_sampler);
    metal::float3 _e102 = weft_env_brdf_from_lut(metal::float3(f0_1), _e101);
    {
        float linear_roughness = roughness_4 * roughness_4;
        metal::float3 _e106 = n;
        float _e111 = material.lobe_weight;
        float _e112 = skin_seed_specular(_e106, _e75.l, _e75.h, linear_roughness, mask_1, _e111);
        specular = (_e112 * f0_1) * _e75.n_dot_l;
        kd = metal::float3(1.0 - f0_1);
    }
    metal::float3 _e119 = weft_main_light_radiance(weft_frame);
    metal::float3 _e120 = kd;
    metal::float3 _e121 = weft_diffuse_lambert(albedo_1);
    metal::float3 _e123 = falloff;
    float _e125 = specular;
    metal::float3 direct = (((_e120 * _e121) * _e123) + metal::float3(_e125)) * _e119;
    metal::float3 _e129 = n;
    metal::float3 _e130 = weft_sh_irradiance(_e129, weft_frame);
    metal::float3 _e131 = kd;
    metal::float3 indirect_diffuse = (_e130 * _e131) * albedo_1;
    metal::float3 _e135 = n;
    metal::float3 _e137 = weft_prefiltered_radiance(metal::reflect(-(v_3), _e135), roughness_4, weft_frame, weft_environment, weft_environment_sampler);
    metal::float3 indirect_specular = (_e137 * _e102) * mask_1;
    metal::float3 color = (direct + indirect_diffuse) + indirect_specular;
    metal::float3 radiance = metal::clamp(color, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
