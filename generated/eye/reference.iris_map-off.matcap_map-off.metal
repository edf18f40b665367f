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
    float iris_radius;
    float pupil_size;
    char _pad2[8];
    metal::float4 iris_color;
    metal::float4 iris_inner_color;
    float limbus_width;
    char _pad5[12];
    metal::float4 sclera_color;
    float cornea_height;
    float cornea_ior;
    float cornea_smoothness;
    float specular_strength;
    float backlight_dimming;
    float parallax_height;
    float matcap_intensity;
    char _pad13[4];
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

float weft_d_ggx_nh(
    metal::float3 n,
    metal::float3 h,
    float roughness_1
) {
    float _e3 = weft_clamp_roughness(roughness_1);
    float a_1 = _e3 * _e3;
    float a2_ = a_1 * a_1;
    float noh = metal::saturate(metal::dot(n, h));
    metal::float3 nxh = metal::cross(n, h);
    float d = metal::dot(nxh, nxh) + ((noh * noh) * a2_);
    return a2_ / (WEFT_PI * metal::max(d * d, 0.000000000000000000000000000001));
}

float weft_f_dielectric(
    float cos_i,
    float eta
) {
    float c_3 = metal::clamp(metal::abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = ((eta * eta) - 1.0) + (c_3 * c_3);
    float g = metal::sqrt(metal::max(g2_, 0.0));
    float gmc = g - c_3;
    float gpc = metal::max(g + c_3, 0.0000001);
    float b_den = metal::max((c_3 * gmc) + 1.0, 0.0000001);
    float b_num = (c_3 * gpc) - 1.0;
    float inv = 1.0 / (gpc * b_den);
    float f = metal::saturate((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv));
    return (g2_ < 0.0) ? 1.0 : f;
}

float weft_f0_from_ior(
    float ior
) {
    float q_1 = (ior - 1.0) / metal::max(ior + 1.0, 0.0001);
    return q_1 * q_1;
}

float weft_v_smith_ggx_correlated(
    float n_dot_v,
    float n_dot_l,
    float roughness_2
) {
    float _e3 = weft_clamp_roughness(roughness_2);
    float a_2 = _e3 * _e3;
    float a2_1 = a_2 * a_2;
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = _e7 * metal::sqrt(((_e6 * _e6) * (1.0 - a2_1)) + a2_1);
    float ll = _e6 * metal::sqrt(((_e7 * _e7) * (1.0 - a2_1)) + a2_1);
    return 0.5 / (lv + ll);
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
    metal::float4 c_4 = weft_environment.sample(weft_environment_sampler, dir, metal::level(_e4));
    return metal::max(c_4.xyz, metal::float3(0.0));
}

metal::float2 weft_env_brdf_lut(
    float n_dot_v_1,
    float roughness_5,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler
) {
    metal::float2 uv = metal::float2(metal::saturate(n_dot_v_1), metal::saturate(roughness_5));
    metal::float4 _e8 = weft_brdf_lut.sample(weft_lut_sampler, uv, metal::level(0.0));
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
    metal::float3 _e55 = weft_safe_normalize(normal3_1 * in_2.normal, metal::float3(0.0));
    out.world_normal = _e55;
    metal::float3 _e62 = weft_safe_normalize(model3_ * in_2.tangent.xyz, metal::float3(0.0));
    out.world_tangent = metal::float4(_e62, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out;
    return _e66;
}

EyeCornea eye_cornea(
    float iris_radius,
    float height
) {
    float r_1 = metal::clamp(iris_radius, 0.05, 0.95);
    float h_2 = metal::max(height, 0.01);
    float z_iris_1 = metal::sqrt(1.0 - (r_1 * r_1));
    float radius = ((r_1 * r_1) + (h_2 * h_2)) / (2.0 * h_2);
    return EyeCornea {z_iris_1, (z_iris_1 + h_2) - radius, radius};
}

metal::float2 eye_to_iris_plane(
    metal::float3 start,
    metal::float3 t,
    float z_iris
) {
    float down = metal::max(-(t.z), 0.0001);
    return start.xy + (t.xy * ((start.z - z_iris) / down));
}

EyeLookup eye_refracted(
    metal::float3 p,
    metal::float3 v_1,
    EyeCornea c_1,
    float ior_1
) {
    bool local = {};
    bool local_1 = {};
    metal::float3 centre = metal::float3(0.0, 0.0, c_1.centre_z);
    metal::float3 o = p - centre;
    float b = metal::dot(o, v_1);
    float disc = (b * b) - (metal::dot(o, o) - (c_1.radius * c_1.radius));
    float s_1 = -(b) + metal::sqrt(metal::max(disc, 0.0));
    metal::float3 hit = p + (s_1 * v_1);
    if (!((p.z <= 0.0))) {
        local = disc <= 0.0;
    } else {
        local = true;
    }
    bool _e33 = local;
    if (!(_e33)) {
        local_1 = hit.z < c_1.z_iris;
    } else {
        local_1 = true;
    }
    bool _e41 = local_1;
    if (_e41) {
        return EyeLookup {p.xy, {}, p, 0.0};
    }
    metal::float3 n_3 = (hit - centre) / metal::float3(c_1.radius);
    metal::float3 t_1 = metal::refract(-(v_1), n_3, 1.0 / metal::max(ior_1, 1.0));
    metal::float2 _e56 = eye_to_iris_plane(hit, t_1, c_1.z_iris);
    return EyeLookup {_e56, {}, n_3, 1.0};
}

metal::float2 eye_uv_from_xy(
    metal::float2 xy
) {
    return metal::float2(0.5 + (0.5 * xy.x), 0.5 - (0.5 * xy.y));
}

metal::float3 eye_procedural_iris(
    float rho,
    float a,
    constant WeftMaterial& material
) {
    metal::float3 c_2 = {};
    float _e4 = material.pupil_size;
    float pupil = metal::clamp(_e4, 0.0, 0.95);
    float t_2 = metal::saturate((rho - pupil) / (1.0 - pupil));
    metal::float4 _e15 = material.iris_inner_color;
    metal::float4 _e19 = material.iris_color;
    c_2 = metal::mix(_e15.xyz, _e19.xyz, metal::smoothstep(0.05, 0.5, t_2));
    float fibres = (0.82 + (0.1 * metal::sin((a * 23.0) + (6.0 * t_2)))) + (0.08 * metal::sin(((a * 41.0) - (9.0 * t_2)) + 1.3));
    metal::float3 _e47 = c_2;
    c_2 = _e47 * fibres;
    float _e51 = material.limbus_width;
    float w = metal::saturate(_e51);
    metal::float3 _e53 = c_2;
    c_2 = _e53 * (1.0 - (0.8 * metal::smoothstep(1.0 - w, 1.0, rho)));
    metal::float3 _e65 = c_2;
    return metal::mix(metal::float3(0.01), _e65, metal::smoothstep(pupil - 0.02, pupil + 0.02, rho));
}

metal::float3 eye_albedo(
    metal::float2 q,
    bool front,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> sclera_map
) {
    metal::float3 iris = {};
    float _e4 = material.iris_radius;
    float r_2 = metal::clamp(_e4, 0.05, 0.95);
    float rho_1 = metal::length(q) / r_2;
    {
        metal::float2 qa = (metal::dot(q, q) > 0.000000000001) ? q : metal::float2(1.0, 0.0);
        metal::float3 _e21 = eye_procedural_iris(rho_1, metal::atan2(qa.y, qa.x), material);
        iris = _e21;
    }
    metal::float4 _e24 = material.sclera_color;
    metal::float2 _e28 = eye_uv_from_xy(q);
    metal::float4 _e29 = sclera_map.sample(material_sampler, _e28);
    metal::float3 sclera = _e24.xyz * _e29.xyz;
    float to_sclera = front ? metal::smoothstep(0.985, 1.015, rho_1) : 1.0;
    metal::float3 _e37 = iris;
    return metal::saturate(metal::mix(_e37, sclera, to_sclera));
}

float eye_fresnel(
    float cos_i_1,
    float ior_2
) {
    {
        float _e2 = weft_f_dielectric(cos_i_1, ior_2);
        return _e2;
    }
}

float eye_ggx(
    metal::float3 s,
    metal::float3 h_1,
    float s_dot_v,
    float s_dot_l,
    float roughness_6
) {
    {
        float _e5 = weft_d_ggx_nh(s, h_1, roughness_6);
        float _e6 = weft_v_smith_ggx_correlated(s_dot_v, s_dot_l, roughness_6);
        return _e5 * _e6;
    }
}

metal::float3 eye_physical(
    EyeLookup look_1,
    metal::float3 n_2,
    metal::float3 v_2,
    metal::float3 l,
    metal::float3x3 normal3_,
    float ior_3,
    metal::float3 light,
    constant WeftFrame& weft_frame,
    metal::texturecube<float, metal::access::sample> weft_environment,
    metal::sampler weft_environment_sampler,
    metal::texture2d<float, metal::access::sample> weft_brdf_lut,
    metal::sampler weft_lut_sampler,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> sclera_map
) {
    bool local_2 = {};
    if (!((look_1.through_cornea > 0.0))) {
        local_2 = look_1.normal[2] > 0.0;
    } else {
        local_2 = true;
    }
    bool _e19 = local_2;
    metal::float3 _e20 = eye_albedo(look_1.iris, _e19, material, material_sampler, sclera_map);
    float _e23 = material.cornea_smoothness;
    float _e27 = weft_clamp_roughness(1.0 - metal::saturate(_e23));
    metal::float3 _e30 = weft_safe_normalize(normal3_ * metal::float3(look_1.normal), n_2);
    float _e32 = weft_clamp_cos(metal::dot(_e30, v_2));
    float s_dot_l_1 = metal::saturate(metal::dot(_e30, l));
    metal::float3 _e36 = weft_safe_normalize(l + v_2, _e30);
    float _e38 = eye_fresnel(metal::dot(v_2, _e36), ior_3);
    float _e39 = eye_ggx(_e30, _e36, _e32, s_dot_l_1, _e27);
    float direct_spec = (_e39 * _e38) * s_dot_l_1;
    float _e42 = weft_f0_from_ior(ior_3);
    metal::float3 f0_1 = metal::float3(_e42);
    metal::float3 _e46 = weft_prefiltered_radiance(metal::reflect(-(v_2), _e30), _e27, weft_frame, weft_environment, weft_environment_sampler);
    metal::float2 _e47 = weft_env_brdf_lut(_e32, _e27, weft_brdf_lut, weft_lut_sampler);
    metal::float3 _e48 = weft_env_brdf_from_lut(f0_1, _e47);
    metal::float3 env = _e46 * _e48;
    float _e54 = material.specular_strength;
    metal::float3 specular = ((light * direct_spec) + env) * metal::max(_e54, 0.0);
    bool on_iris = look_1.through_cornea > 0.0;
    metal::float3 _e66 = weft_safe_normalize(normal3_ * metal::float3(0.0, 0.0, 1.0), n_2);
    metal::float3 l_in = metal::refract(-(l), _e30, 1.0 / ior_3);
    float iris_cos = (s_dot_l_1 > 0.0) ? metal::saturate(metal::dot(_e66, -(l_in))) : 0.0;
    float _e78 = eye_fresnel(_e32, ior_3);
    float t_v = 1.0 - _e78;
    float _e81 = eye_fresnel(s_dot_l_1, ior_3);
    float t_l = 1.0 - _e81;
    metal::float3 diffuse_n = on_iris ? _e66 : n_2;
    float diffuse_cos = on_iris ? (iris_cos * t_l) : metal::saturate(metal::dot(n_2, l));
    float transmission = on_iris ? t_v : 1.0;
    metal::float3 _e95 = weft_sh_irradiance(diffuse_n, weft_frame);
    metal::float3 diffuse = (_e20 * transmission) * ((light * (WEFT_INV_PI * diffuse_cos)) + _e95);
    return diffuse + specular;
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
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(2)]]
, metal::texture2d<float, metal::access::sample> sclera_map [[texture(2)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 color = {};
    EyeLookup look = {};
    metal::float4x4 model_1 = weft_object.model;
    metal::float3x3 model3_1 = metal::float3x3(model_1[0].xyz, model_1[1].xyz, model_1[2].xyz);
    metal::float4x4 nm_1 = weft_object.normal_matrix;
    metal::float3x3 normal3_2 = metal::float3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    WeftSurface _e23 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_3 = _e23.v;
    metal::float3 n_4 = _e23.n;
    metal::float3 _e26 = weft_main_light_direction(weft_frame);
    metal::float3 _e33 = weft_safe_normalize(metal::transpose(model3_1) * n_4, metal::float3(0.0, 0.0, 1.0));
    metal::float3 _e40 = weft_safe_normalize(metal::transpose(normal3_2) * v_3, metal::float3(0.0, 0.0, 1.0));
    metal::float3 _e46 = weft_safe_normalize(model3_1 * metal::float3(0.0, 0.0, 1.0), n_4);
    float _e49 = material.backlight_dimming;
    float dimming = 1.0 - (metal::saturate(_e49) * metal::saturate(-(metal::dot(_e46, _e26))));
    metal::float3 _e57 = weft_main_light_radiance(weft_frame);
    {
        float _e61 = material.iris_radius;
        float _e64 = material.cornea_height;
        EyeCornea _e65 = eye_cornea(_e61, _e64);
        float _e68 = material.cornea_ior;
        float ior_4 = metal::max(_e68, 1.0);
        {
            EyeLookup _e72 = eye_refracted(_e33, _e40, _e65, ior_4);
            look = _e72;
        }
        EyeLookup _e73 = look;
        metal::float3 _e74 = eye_physical(_e73, n_4, v_3, _e26, normal3_2, ior_4, _e57, weft_frame, weft_environment, weft_environment_sampler, weft_brdf_lut, weft_lut_sampler, material, material_sampler, sclera_map);
        color = _e74;
    }
    metal::float3 _e75 = color;
    metal::float3 radiance = metal::clamp(_e75 * dimming, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
