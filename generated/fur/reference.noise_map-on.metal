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
    float metallic;
    float smoothness;
    char _pad4[8];
    metal::float4 spot_color;
    metal::float4 noise_map_st;
    metal::float2 strand_density;
    float fur_length;
    float height_scale;
    float fur_occlusion;
    float cutoff_start;
    float cutoff_end;
    float edge_fade;
    uint tapered_tips;
    int shell_count;
    char _pad15[8];
    metal::packed_float3 force_direction;
    float force_strength;
    float force_map_scale;
    char _pad18[12];
    metal::float4 sheen_color;
    float scatter_scale;
    char _pad20[12];
    metal::float4 strand_color;
    float strand_strength;
    char _pad22[12];
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
struct FurInput {
    metal::float3 position;
    metal::float3 normal;
    metal::float2 uv0_;
    char _pad3[8];
};
struct FurVaryings {
    metal::float4 clip_position;
    metal::float3 world_position;
    metal::float3 world_normal;
    metal::float3 strand;
    metal::float2 uv0_;
    float offset;
    char _pad6[4];
    metal::float4 light_diffuse;
    metal::float4 light_ambient;
    metal::float4 light_sheen;
    metal::float4 light_strand;
    float light_n_dot_v;
    char _pad11[12];
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
constant float WEFT_SHEEN_MIN_ROUGHNESS = 0.07;
constant float FUR_SEED_SHELLS = 20.0;

float weft_pow5_(
    float x
) {
    float x2_ = x * x;
    return (x2_ * x2_) * x;
}

float weft_max3_(
    metal::float3 v
) {
    return metal::max(v.x, metal::max(v.y, v.z));
}

float weft_clamp_cos(
    float c
) {
    return metal::clamp(c, WEFT_MIN_N_DOT, 1.0);
}

metal::float3 weft_safe_normalize(
    metal::float3 v_1,
    metal::float3 fallback
) {
    float len2_ = metal::dot(v_1, v_1);
    return (len2_ > 0.00000000000000000001) ? (v_1 * metal::rsqrt(metal::max(len2_, 0.00000000000000000001))) : fallback;
}

metal::float3 weft_f_schlick(
    metal::float3 f0_,
    float v_dot_h
) {
    float _e5 = weft_pow5_(1.0 - metal::saturate(v_dot_h));
    return f0_ + ((metal::float3(1.0) - f0_) * _e5);
}

metal::float3 weft_diffuse_lambert(
    metal::float3 albedo
) {
    return albedo * WEFT_INV_PI;
}

float weft_sheen_clamp_roughness(
    float sheen_roughness
) {
    return metal::clamp(sheen_roughness, WEFT_SHEEN_MIN_ROUGHNESS, 1.0);
}

float weft_d_charlie(
    float n_dot_h,
    float sheen_roughness_1
) {
    float _e2 = weft_sheen_clamp_roughness(sheen_roughness_1);
    float inv_r = 1.0 / _e2;
    float noh = metal::saturate(n_dot_h);
    float sin2_ = metal::max((1.0 - noh) * (1.0 + noh), 0.0);
    return ((2.0 + inv_r) * metal::pow(sin2_, 0.5 * inv_r)) * 0.15915494;
}

float weft_sheen_l(
    float x_1,
    float r
) {
    float t_1 = (1.0 - r) * (1.0 - r);
    float a = metal::mix(21.5473, 25.3245, t_1);
    float b = metal::mix(3.82987, 3.32435, t_1);
    float c_1 = metal::mix(0.19823, 0.16801, t_1);
    float d = metal::mix(-1.9776, -1.27393, t_1);
    float e_1 = metal::mix(-4.32054, -4.85967, t_1);
    return ((a / (1.0 + (b * metal::pow(metal::max(x_1, 0.0), c_1)))) + (d * x_1)) + e_1;
}

float weft_sheen_lambda_one_exp(
    float cos_theta,
    float r_1
) {
    float _e2 = weft_clamp_cos(cos_theta);
    bool low = _e2 < 0.5;
    float _e8 = weft_sheen_l(low ? _e2 : (1.0 - _e2), r_1);
    float _e10 = weft_sheen_l(0.5, r_1);
    return metal::exp(low ? _e8 : ((2.0 * _e10) - _e8));
}

float weft_v_charlie(
    float n_dot_v,
    float n_dot_l,
    float sheen_roughness_2
) {
    float _e3 = weft_sheen_clamp_roughness(sheen_roughness_2);
    float _e4 = weft_clamp_cos(n_dot_v);
    float _e5 = weft_clamp_cos(n_dot_l);
    float _e6 = weft_sheen_lambda_one_exp(_e4, _e3);
    float _e9 = weft_sheen_lambda_one_exp(_e5, _e3);
    float g_inv = (1.0 + _e6) + _e9;
    return 1.0 / (((g_inv * 4.0) * _e4) * _e5);
}

metal::float3 weft_sheen_charlie(
    metal::float3 sheen_color,
    float n_dot_h_1,
    float n_dot_v_1,
    float n_dot_l_1,
    float sheen_roughness_3
) {
    float _e5 = weft_d_charlie(n_dot_h_1, sheen_roughness_3);
    float _e6 = weft_v_charlie(n_dot_v_1, n_dot_l_1, sheen_roughness_3);
    float lobe = _e5 * _e6;
    return metal::max(sheen_color, metal::float3(0.0)) * (lobe * metal::saturate(n_dot_l_1));
}

float weft_sheen_albedo_scaling(
    metal::float3 sheen_color_1,
    float e_v,
    float e_l
) {
    float _e3 = weft_max3_(sheen_color_1);
    float c_2 = metal::saturate(_e3);
    return metal::saturate(metal::min(1.0 - (c_2 * metal::saturate(e_v)), 1.0 - (c_2 * metal::saturate(e_l))));
}

float weft_sheen_albedo_scaling_view(
    metal::float3 sheen_color_2,
    float e_v_1
) {
    float _e2 = weft_max3_(sheen_color_2);
    return metal::saturate(1.0 - (metal::saturate(_e2) * metal::saturate(e_v_1)));
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
    metal::float3 n,
    constant WeftFrame& weft_frame
) {
    metal::float3 e = {};
    type_4 sh = weft_frame.sh;
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

float weft_specular_mip(
    float roughness,
    constant WeftFrame& weft_frame
) {
    float r_2 = metal::saturate(roughness);
    float _e5 = weft_frame.params.x;
    float max_mip = metal::max(_e5 - 1.0, 0.0);
    return (r_2 * (1.7 - (0.7 * r_2))) * max_mip;
}

metal::float3 weft_prefiltered_radiance(
    metal::float3 dir,
    float roughness_1,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler
) {
    float _e4 = weft_specular_mip(roughness_1, weft_frame);
    metal::float4 c_3 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_3.xyz, metal::float3(0.0));
}

float weft_sheen_albedo(
    float n_dot_x,
    float sheen_roughness_4,
    metal::sampler weft_lut_sampler,
    metal::texture2d<float, metal::access::sample> weft_sheen_lut
) {
    float _e3 = weft_sheen_clamp_roughness(sheen_roughness_4);
    metal::float2 uv_1 = metal::float2(metal::saturate(n_dot_x), _e3);
    metal::float4 _e8 = weft_sheen_lut.sample(weft_lut_sampler, uv_1, metal::level(0.0));
    return metal::saturate(_e8.x);
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
    metal::float3 n_1,
    metal::float3 v_2,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_main_light_direction(weft_frame);
    metal::float3 _e4 = weft_safe_normalize(_e2 + v_2, n_1);
    float _e6 = weft_clamp_cos(metal::dot(n_1, v_2));
    return WeftLightGeometry {_e2, _e4, _e6, metal::saturate(metal::dot(n_1, _e2)), metal::saturate(metal::dot(n_1, _e4)), metal::saturate(metal::dot(v_2, _e4))};
}

metal::float2 fur_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

float fur_strand_exponent(
    float smoothness
) {
    return metal::exp2(1.0 + (9.0 * metal::saturate(smoothness)));
}

float fur_strand_norm(
    float p
) {
    return metal::sqrt((((2.0 * p) + 1.0) * 0.25) * WEFT_INV_PI);
}

FurVaryings fur_vertex(
    FurInput in_4,
    float offset,
    constant WeftFrame& weft_frame,
    constant WeftObject& weft_object,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> height_map,
    metal::texture2d<float, metal::access::sample> force_map
) {
    FurVaryings out = {};
    metal::float4x4 model = weft_object.model;
    metal::float4x4 nm = weft_object.normal_matrix;
    metal::float3x3 normal3_ = metal::float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    metal::float3 world = (model * metal::float4(in_4.position, 1.0)).xyz;
    metal::float3 _e24 = weft_safe_normalize(normal3_ * in_4.normal, metal::float3(0.0));
    metal::float4 _e28 = material.base_map_st;
    metal::float2 _e29 = fur_transform_uv(in_4.uv0_, _e28);
    metal::float4 _e33 = force_map.sample(material_sampler, _e29, metal::level(0.0));
    metal::float3 force_texel = _e33.xyz;
    metal::float3 _e37 = material.force_direction;
    float _e45 = material.force_map_scale;
    metal::float3 force = _e37 + (((force_texel * 2.0) - metal::float3(1.0)) * _e45);
    float _e50 = material.force_strength;
    float s = metal::saturate(_e50);
    metal::float3 target_dir = (_e24 * (1.0 - s)) + (force * s);
    metal::float4 _e60 = height_map.sample(material_sampler, _e29, metal::level(0.0));
    float height = _e60.x;
    float _e64 = material.height_scale;
    float hs = metal::saturate(_e64);
    float _e68 = material.fur_length;
    float len = metal::max(_e68, 0.0) * metal::max(1.0 + (hs * (metal::saturate(height) - 1.0)), 0.0);
    metal::float3 dir_1 = metal::mix(_e24, target_dir, offset);
    metal::float3 p_1 = world + (dir_1 * (len * offset));
    metal::float4x4 _e88 = weft_frame.view_proj;
    out.clip_position = _e88 * metal::float4(p_1, 1.0);
    out.world_position = p_1;
    out.world_normal = _e24;
    out.strand = _e24 + ((2.0 * offset) * (target_dir - _e24));
    out.uv0_ = in_4.uv0_;
    out.offset = offset;
    FurVaryings _e103 = out;
    return _e103;
}

float fur_noise(
    metal::float2 uv0_,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> noise_map
) {
    metal::float4 _e3 = material.noise_map_st;
    metal::float2 _e4 = fur_transform_uv(uv0_, _e3);
    {
        metal::float4 _e7 = noise_map.sample(material_sampler, _e4);
        return metal::saturate(_e7.x);
    }
}

metal::float2 fur_kajiya_kay_cone(
    metal::float3 t,
    metal::float3 l,
    metal::float3 v_3
) {
    float t_dot_l = metal::clamp(metal::dot(t, l), -1.0, 1.0);
    float t_dot_v = metal::clamp(metal::dot(t, v_3), -1.0, 1.0);
    float sin_l = metal::sqrt(metal::max(1.0 - (t_dot_l * t_dot_l), 0.0));
    float sin_v = metal::sqrt(metal::max(1.0 - (t_dot_v * t_dot_v), 0.0));
    return metal::float2(metal::max((sin_l * sin_v) - (t_dot_l * t_dot_v), 0.0), sin_l);
}

metal::float4 fur_shade(
    FurVaryings in_5,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler,
    metal::sampler weft_lut_sampler,
    metal::texture2d<float, metal::access::sample> weft_sheen_lut,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> base_map,
    metal::texture2d<float, metal::access::sample> spot_map
) {
    metal::float3 color = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = fur_transform_uv(in_5.uv0_, _e4);
    metal::float4 _e8 = material.base_color;
    metal::float4 _e11 = base_map.sample(material_sampler, _e5);
    metal::float4 base_rgba = _e8 * _e11;
    metal::float4 _e15 = spot_map.sample(material_sampler, _e5);
    float spot = metal::saturate(_e15.x);
    metal::float4 _e22 = material.spot_color;
    metal::float3 base = metal::mix(metal::saturate(base_rgba.xyz), metal::saturate(_e22.xyz), spot);
    float alpha = metal::saturate(base_rgba.w);
    {
        float _e31 = material.metallic;
        float metallic = metal::saturate(_e31);
        float _e35 = material.smoothness;
        float smoothness_1 = metal::saturate(_e35);
        float roughness_2 = 1.0 - smoothness_1;
        WeftSurface _e41 = weft_surface(in_5.world_position, in_5.world_normal, weft_frame);
        metal::float3 v_4 = _e41.v;
        metal::float3 n_2 = _e41.n;
        metal::float3 _e45 = weft_safe_normalize(in_5.strand, n_2);
        WeftLightGeometry _e46 = weft_main_light_geometry(n_2, v_4, weft_frame);
        float l_dot_h = metal::saturate(metal::dot(_e46.l, _e46.h));
        metal::float3 f0_1 = metal::mix(metal::float3(0.04), base, metallic);
        metal::float3 diffuse_albedo = base * (1.0 - metallic);
        metal::float3 _e57 = weft_main_light_radiance(weft_frame);
        metal::float3 _e58 = weft_sh_irradiance(n_2, weft_frame);
        {
            metal::float4 _e61 = material.sheen_color;
            metal::float3 sheen_color_3 = metal::saturate(f0_1 + metal::max(_e61.xyz, metal::float3(0.0)));
            float _e68 = weft_sheen_clamp_roughness(roughness_2);
            float _e70 = weft_sheen_albedo(_e46.n_dot_v, _e68, weft_lut_sampler, weft_sheen_lut);
            float _e72 = weft_sheen_albedo(_e46.n_dot_l, _e68, weft_lut_sampler, weft_sheen_lut);
            float _e73 = weft_sheen_albedo_scaling_view(sheen_color_3, _e70);
            float _e74 = weft_sheen_albedo_scaling(sheen_color_3, _e70, _e72);
            metal::float3 _e78 = weft_sheen_charlie(sheen_color_3, _e46.n_dot_h, _e46.n_dot_v, _e46.n_dot_l, _e68);
            float _e79 = fur_strand_exponent(smoothness_1);
            metal::float2 _e81 = fur_kajiya_kay_cone(_e45, _e46.l, v_4);
            float strand = metal::pow(_e81.x, _e79) * _e81.y;
            metal::float3 _e86 = weft_f_schlick(f0_1, l_dot_h);
            metal::float4 _e89 = material.strand_color;
            metal::float3 strand_color = metal::max(_e89.xyz, metal::float3(0.0)) * _e86;
            float _e97 = material.strand_strength;
            float _e100 = fur_strand_norm(_e79);
            metal::float3 strand_lobe = strand_color * (((metal::max(_e97, 0.0) * _e100) * strand) * _e46.n_dot_l);
            metal::float3 _e106 = weft_diffuse_lambert(diffuse_albedo);
            metal::float3 base_direct = _e106 * (_e74 * _e46.n_dot_l);
            metal::float3 direct = ((_e78 + base_direct) + strand_lobe) * _e57;
            metal::float3 _e115 = weft_prefiltered_radiance(metal::reflect(-(v_4), n_2), _e68, weft_frame, weft_environment, weft_environment_sampler);
            metal::float3 env_sheen = (_e115 * sheen_color_3) * _e70;
            color = (direct + ((_e58 * diffuse_albedo) * _e73)) + env_sheen;
        }
    }
    float _e124 = material.fur_occlusion;
    float occlusion = 1.0 - (metal::saturate(_e124) * (1.0 - in_5.offset));
    metal::float3 _e132 = color;
    metal::float3 radiance = metal::clamp(_e132 * occlusion, metal::float3(0.0), metal::float3(65504.0));
    return metal::float4(radiance, alpha);
}

float fur_fade_n_dot_v(
    FurVaryings in_6,
    constant WeftFrame& weft_frame
) {
    WeftSurface _e3 = weft_surface(in_6.world_position, in_6.world_normal, weft_frame);
    return metal::saturate(metal::dot(_e3.n, _e3.v));
}

metal::float4 fur_shell(
    FurVaryings in_7,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler,
    metal::sampler weft_lut_sampler,
    metal::texture2d<float, metal::access::sample> weft_sheen_lut,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> base_map,
    metal::texture2d<float, metal::access::sample> spot_map,
    metal::texture2d<float, metal::access::sample> noise_map
) {
    float _e2 = fur_noise(in_7.uv0_, material, material_sampler, noise_map);
    float o = metal::saturate(in_7.offset);
    uint _e8 = material.tapered_tips;
    float shape = (_e8 != 0u) ? (o * o) : o;
    float _e14 = material.cutoff_start;
    float _e18 = material.cutoff_end;
    float threshold = metal::mix(metal::saturate(_e14), metal::saturate(_e18), shape);
    float _e21 = metal::fwidth(_e2);
    float width = metal::max(_e21, 0.001);
    float coverage = metal::saturate(((_e2 - threshold) / width) + 0.5) * metal::step(0.000001, _e2);
    metal::float4 _e32 = fur_shade(in_7, weft_frame, weft_environment, weft_environment_sampler, weft_lut_sampler, weft_sheen_lut, material, material_sampler, base_map, spot_map);
    float _e35 = material.edge_fade;
    float _e37 = fur_fade_n_dot_v(in_7, weft_frame);
    float fade = 1.0 - (metal::saturate(_e35) * (1.0 - _e37));
    float a_1 = metal::saturate(((coverage * (1.0 - o)) * fade) * _e32.w);
    int _e53 = material.shell_count;
    float slab = FUR_SEED_SHELLS / static_cast<float>(metal::max(_e53, 1));
    float keep = 1.0 - a_1;
    float alpha_1 = 1.0 - ((keep <= 0.0) ? 0.0 : metal::pow(keep, slab));
    return metal::float4(_e32.xyz, alpha_1);
}

struct vs_skinInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float2 uv0_1 [[attribute(3)]];
};
struct vs_skinOutput {
    metal::float4 clip_position [[position]];
    metal::float3 world_position [[user(loc0), center_perspective]];
    metal::float3 world_normal [[user(loc1), center_perspective]];
    metal::float3 strand [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
    float offset [[user(loc4), center_perspective]];
    metal::float4 light_diffuse [[user(loc5), center_perspective]];
    metal::float4 light_ambient [[user(loc6), center_perspective]];
    metal::float4 light_sheen [[user(loc7), center_perspective]];
    metal::float4 light_strand [[user(loc8), center_perspective]];
    float light_n_dot_v [[user(loc9), center_perspective]];
};
vertex vs_skinOutput vs_skin(
  vs_skinInput varyings [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::texture2d<float, metal::access::sample> height_map [[texture(5)]]
, metal::texture2d<float, metal::access::sample> force_map [[texture(6)]]
) {
    const FurInput in = { varyings.position, varyings.normal, varyings.uv0_1 };
    FurVaryings _e2 = fur_vertex(in, 0.0, weft_frame, weft_object, material, material_sampler, height_map, force_map);
    const auto _tmp = _e2;
    return vs_skinOutput { _tmp.clip_position, _tmp.world_position, _tmp.world_normal, _tmp.strand, _tmp.uv0_, _tmp.offset, _tmp.light_diffuse, _tmp.light_ambient, _tmp.light_sheen, _tmp.light_strand, _tmp.light_n_dot_v };
}


struct vs_shellInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float2 uv0_1 [[attribute(3)]];
};
struct vs_shellOutput {
    metal::float4 clip_position [[position]];
    metal::float3 world_position [[user(loc0), center_perspective]];
    metal::float3 world_normal [[user(loc1), center_perspective]];
    metal::float3 strand [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
    float offset [[user(loc4), center_perspective]];
    metal::float4 light_diffuse [[user(loc5), center_perspective]];
    metal::float4 light_ambient [[user(loc6), center_perspective]];
    metal::float4 light_sheen [[user(loc7), center_perspective]];
    metal::float4 light_strand [[user(loc8), center_perspective]];
    float light_n_dot_v [[user(loc9), center_perspective]];
};
vertex vs_shellOutput vs_shell(
  vs_shellInput varyings_1 [[stage_in]]
, uint instance [[instance_id]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::texture2d<float, metal::access::sample> height_map [[texture(5)]]
, metal::texture2d<float, metal::access::sample> force_map [[texture(6)]]
) {
    const FurInput in_1 = { varyings_1.position, varyings_1.normal, varyings_1.uv0_1 };
    int _e4 = material.shell_count;
    float count = static_cast<float>(metal::max(_e4, 1));
    FurVaryings _e12 = fur_vertex(in_1, (static_cast<float>(instance) + 0.5) / count, weft_frame, weft_object, material, material_sampler, height_map, force_map);
    const auto _tmp_1 = _e12;
    return vs_shellOutput { _tmp_1.clip_position, _tmp_1.world_position, _tmp_1.world_normal, _tmp_1.strand, _tmp_1.uv0_, _tmp_1.offset, _tmp_1.light_diffuse, _tmp_1.light_ambient, _tmp_1.light_sheen, _tmp_1.light_strand, _tmp_1.light_n_dot_v };
}


struct fs_skinInput {
    metal::float3 world_position_2 [[user(loc0), center_perspective]];
    metal::float3 world_normal_1 [[user(loc1), center_perspective]];
    metal::float3 strand [[user(loc2), center_perspective]];
    metal::float2 uv0_1 [[user(loc3), center_perspective]];
    float offset_1 [[user(loc4), center_perspective]];
    metal::float4 light_diffuse [[user(loc5), center_perspective]];
    metal::float4 light_ambient [[user(loc6), center_perspective]];
    metal::float4 light_sheen [[user(loc7), center_perspective]];
    metal::float4 light_strand [[user(loc8), center_perspective]];
    float light_n_dot_v [[user(loc9), center_perspective]];
};
struct fs_skinOutput {
    metal::float4 member_2 [[color(0)]];
};
fragment fs_skinOutput fs_skin(
  fs_skinInput varyings_2 [[stage_in]]
, metal::float4 clip_position [[position]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, metal::texturecube<float, metal::access::sample> weft_environment [[texture(0)]]
, metal::sampler weft_environment_sampler [[sampler(0)]]
, metal::sampler weft_lut_sampler [[sampler(1)]]
, metal::texture2d<float, metal::access::sample> weft_sheen_lut [[texture(1)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> spot_map [[texture(3)]]
) {
    const FurVaryings in_2 = { clip_position, varyings_2.world_position_2, varyings_2.world_normal_1, varyings_2.strand, varyings_2.uv0_1, varyings_2.offset_1, {}, varyings_2.light_diffuse, varyings_2.light_ambient, varyings_2.light_sheen, varyings_2.light_strand, varyings_2.light_n_dot_v };
    metal::float4 _e1 = fur_shade(in_2, weft_frame, weft_environment, weft_environment_sampler, weft_lut_sampler, weft_sheen_lut, material, material_sampler, base_map, spot_map);
    return fs_skinOutput { metal::float4(_e1.xyz, 1.0) };
}


struct fs_shellInput {
    metal::float3 world_position_2 [[user(loc0), center_perspective]];
    metal::float3 world_normal_1 [[user(loc1), center_perspective]];
    metal::float3 strand [[user(loc2), center_perspective]];
    metal::float2 uv0_1 [[user(loc3), center_perspective]];
    float offset_1 [[user(loc4), center_perspective]];
    metal::float4 light_diffuse [[user(loc5), center_perspective]];
    metal::float4 light_ambient [[user(loc6), center_perspective]];
    metal::float4 light_sheen [[user(loc7), center_perspective]];
    metal::float4 light_strand [[user(loc8), center_perspective]];
    float light_n_dot_v [[user(loc9), center_perspective]];
};
struct fs_shellOutput {
    metal::float4 member_3 [[color(0)]];
};
fragment fs_shellOutput fs_shell(
  fs_shellInput varyings_3 [[stage_in]]
, metal::float4 clip_position_1 [[position]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, metal::texturecube<float, metal::access::sample> weft_environment [[texture(0)]]
, metal::sampler weft_environment_sampler [[sampler(0)]]
, metal::sampler weft_lut_sampler [[sampler(1)]]
, metal::texture2d<float, metal::access::sample> weft_sheen_lut [[texture(1)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> spot_map [[texture(3)]]
, metal::texture2d<float, metal::access::sample> noise_map [[texture(4)]]
) {
    const FurVaryings in_3 = { clip_position_1, varyings_3.world_position_2, varyings_3.world_normal_1, varyings_3.strand, varyings_3.uv0_1, varyings_3.offset_1, {}, varyings_3.light_diffuse, varyings_3.light_ambient, varyings_3.light_sheen, varyings_3.light_strand, varyings_3.light_n_dot_v };
    metal::float4 _e1 = fur_shell(in_3, weft_frame, weft_environment, weft_environment_sampler, weft_lut_sampler, weft_sheen_lut, material, material_sampler, base_map, spot_map, noise_map);
    return fs_shellOutput { _e1 };
}
