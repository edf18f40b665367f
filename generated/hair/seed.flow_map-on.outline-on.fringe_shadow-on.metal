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
    metal::float4 base_map_st;
    uint strand_along_tangent;
    char _pad3[12];
    metal::float4 jitter_map_st;
    float jitter_strength;
    float anisotropic_direction;
    float strand_noise;
    float strand_density;
    metal::float4 primary_color;
    float primary_exponent;
    float primary_intensity;
    float primary_shift;
    char _pad12[4];
    metal::float4 secondary_color;
    float secondary_exponent;
    float secondary_intensity;
    float secondary_shift;
    float roughness;
    float azimuthal_roughness;
    float scale_angle;
    float ior;
    char _pad20[4];
    metal::float4 outline_color;
    float outline_width;
    float outline_max_distance;
    char _pad23[8];
    metal::float4 fringe_shadow_color;
    float fringe_shadow_length;
    char _pad25[12];
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
    float s = (n.z >= 0.0) ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = (n.x * n.y) * a;
    return metal::float3(1.0 + (((s * n.x) * n.x) * a), s * b, -(s) * n.x);
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
    metal::float3 _e55 = weft_safe_normalize(normal3_ * in_4.normal, metal::float3(0.0));
    out_2.world_normal = _e55;
    metal::float3 _e62 = weft_safe_normalize(model3_ * in_4.tangent.xyz, metal::float3(0.0));
    out_2.world_tangent = metal::float4(_e62, bitangent_sign);
    out_2.uv0_ = in_4.uv0_;
    WeftVaryings _e66 = out_2;
    return _e66;
}

metal::float3x3 weft_tangent_frame(
    metal::float3 n_2,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_2 * metal::dot(n_2, t_in));
    float len2_1 = metal::dot(t_proj, t_proj);
    bool ok = len2_1 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_2);
    metal::float3 t_1 = ok ? (t_proj * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : _e13;
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_2, t_1) * s_1;
    return metal::float3x3(t_1, b_1, n_2);
}

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
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

float weft_hair_variance(
    float beta_m
) {
    float b_2 = metal::clamp(beta_m, WEFT_HAIR_MIN_BETA_M, 1.0);
    float b2_ = b_2 * b_2;
    float b4_ = b2_ * b2_;
    float b20_ = (((b4_ * b4_) * b4_) * b4_) * b4_;
    float _e18 = weft_hair_sqr(((0.726 * b_2) + (0.812 * b2_)) + (3.7 * b20_));
    return _e18;
}

float weft_hair_logistic_scale(
    float beta_n
) {
    float b_3 = metal::clamp(beta_n, WEFT_HAIR_MIN_BETA_N, 1.0);
    float b2_1 = b_3 * b_3;
    float b4_1 = b2_1 * b2_1;
    float b22_ = ((((b4_1 * b4_1) * b4_1) * b4_1) * b4_1) * b2_1;
    return 0.62665707 * (((0.265 * b_3) + (1.194 * b2_1)) + (5.372 * b22_));
}

WeftHair weft_hair_params(
    metal::float3 sigma_a,
    float eta,
    float beta_m_1,
    float beta_n_1,
    float alpha_deg
) {
    WeftHair hair = {};
    hair.sigma_a = metal::max(sigma_a, metal::float3(0.0));
    hair.eta = metal::max(eta, 1.0001);
    float _e13 = weft_hair_variance(beta_m_1);
    hair.v = metal::float4(_e13, 0.25 * _e13, 4.0 * _e13, 4.0 * _e13);
    float _e23 = weft_hair_logistic_scale(beta_n_1);
    hair.s = _e23;
    float a_1 = ((alpha_deg) * 0.017453292519943295474);
    float s0_ = metal::sin(a_1);
    float _e29 = weft_hair_safe_sqrt(1.0 - (s0_ * s0_));
    float s1_ = (2.0 * _e29) * s0_;
    float c1_ = (_e29 * _e29) - (s0_ * s0_);
    float s2_ = (2.0 * c1_) * s1_;
    float c2_ = (c1_ * c1_) - (s1_ * s1_);
    hair.sin2k = metal::float3(s0_, s1_, s2_);
    hair.cos2k = metal::float3(_e29, c1_, c2_);
    hair.inv_v = metal::float3(1.0, 4.0, 0.25) / metal::float3(_e13);
    float _e55 = hair.inv_v.x;
    float e_trt = metal::exp(-0.5 * _e55);
    float _e60 = weft_hair_sqr(e_trt * e_trt);
    metal::float3 _e63 = hair.inv_v;
    float _e67 = weft_hair_sqr(_e60 * _e60);
    hair.mp_norm = _e63 / (metal::float3(1.0) - metal::float3(_e60, _e67, e_trt));
    float _e73 = hair.s;
    float d = 0.8162094 * _e73;
    hair.blur = metal::float2(metal::sin(d), metal::cos(d));
    float _e81 = hair.s;
    float _e84 = weft_hair_sqr(0.4534 * _e81);
    hair.r_floor = _e84;
    float sh_1 = hair.s;
    hair.trt = metal::float4(-9.2609 + (sh_1 * (65.993 - (107.38 * sh_1))), 72.357 + (sh_1 * (-624.68 + (1069.8 * sh_1))), -153.75 + (sh_1 * (1704.7 - (3127.5 * sh_1))), -67.745 + (sh_1 * (-1105.8 + (2706.6 * sh_1))));
    hair.trt4_ = 239.74 - (430.94 * sh_1);
    float _e124 = hair.eta;
    hair.inv_eta = 1.0 / _e124;
    WeftHair _e127 = hair;
    return _e127;
}

float hair_noise_period(
    float density
) {
    return metal::max(metal::rint(density), 1.0);
}

metal::float3 hair_strand(
    metal::float3x3 frame,
    metal::float2 uv0_,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> flow_map
) {
    metal::float2 ts = {};
    uint _e10 = material.strand_along_tangent;
    ts = (_e10 != 0u) ? metal::float2(1.0, 0.0) : metal::float2(0.0, 1.0);
    {
        metal::float4 _e17 = flow_map.sample(material_sampler, uv0_);
        metal::float2 f = (_e17.xy * 2.0) - metal::float2(1.0);
        float len2_2 = metal::dot(f, f);
        metal::float2 _e25 = ts;
        ts = (len2_2 > 0.0001) ? (f * metal::rsqrt(metal::max(len2_2, 0.000000000001))) : _e25;
    }
    float _e35 = ts.x;
    float _e39 = ts.y;
    metal::float3 _e43 = weft_safe_normalize((frame[0] * _e35) + (frame[1] * _e39), frame[1]);
    return _e43;
}

float hair_hash(
    uint x_2
) {
    uint state = (x_2 * 747796405u) + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return static_cast<float>((word >> 22u) ^ word) * 0.00000000023283064;
}

uint naga_f2u32(float value) {
    return static_cast<uint>(metal::clamp(value, 0.0, 4294967000.0));
}

float hair_value_noise(
    float x_3,
    float p
) {
    float cell = metal::floor(x_3);
    float f_1 = x_3 - cell;
    float c0_ = cell - (p * metal::floor(cell / p));
    float c1_1 = ((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0);
    float _e16 = hair_hash(naga_f2u32(c0_));
    float _e18 = hair_hash(naga_f2u32(c1_1));
    return metal::mix(_e16, _e18, (f_1 * f_1) * (3.0 - (2.0 * f_1))) - 0.5;
}

float hair_jitter(
    metal::float2 uv0_1,
    metal::float2 rotation,
    float noise_period,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> jitter_map,
    metal::texture2d<float, metal::access::sample> uv_rotate_mask
) {
    metal::float4 _e5 = uv_rotate_mask.sample(material_sampler, uv0_1);
    float mask = metal::step(0.8, _e5.x);
    float c = rotation.x;
    float s_2 = rotation.y;
    metal::float2 rotated = metal::float2((c * uv0_1.x) + (s_2 * uv0_1.y), (-(s_2) * uv0_1.x) + (c * uv0_1.y));
    metal::float4 _e28 = material.jitter_map_st;
    metal::float2 _e29 = weft_transform_uv((mask > 0.5) ? rotated : uv0_1, _e28);
    metal::float4 _e32 = jitter_map.sample(material_sampler, _e29);
    float j = _e32.x;
    uint _e38 = material.strand_along_tangent;
    float across = (_e38 != 0u) ? _e29.y : _e29.x;
    float _e44 = material.strand_density;
    float _e46 = hair_value_noise(across * _e44, noise_period);
    float _e49 = material.jitter_strength;
    float _e53 = material.strand_noise;
    return (_e49 * j) + (_e53 * _e46);
}

float hair_kajiya_kay(
    metal::float3 t,
    metal::float3 h_1,
    float exponent
) {
    float t_dot_h = metal::clamp(metal::dot(t, h_1), -1.0, 1.0);
    float sin_th = metal::sqrt(metal::max(1.0 - (t_dot_h * t_dot_h), 0.0));
    float dir_atten = metal::smoothstep(-1.0, 0.0, t_dot_h);
    return dir_atten * metal::pow(sin_th, metal::max(exponent, 1.0));
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
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
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
    float _e68 = material.outline_width;
    float width_px = metal::max(_e68, 0.0);
    float _e74 = material.outline_max_distance;
    float distance = metal::min(clip.w, metal::max(_e74, 0.0));
    metal::float4 _e83 = weft_frame.viewport;
    metal::float2 offset = (((direction * width_px) * 2.0) * _e83.zw) * distance;
    out.clip_position = metal::float4(clip.xy + offset, clip.zw);
    WeftOutlineVaryings _e93 = out;
    const auto _tmp = _e93;
    return vs_outlineOutput { _tmp.clip_position };
}


struct fs_outlineOutput {
    metal::float4 member_1 [[color(0)]];
};
fragment fs_outlineOutput fs_outline(
  constant WeftMaterial& material [[buffer(1)]]
) {
    metal::float4 _e2 = material.outline_color;
    return fs_outlineOutput { metal::float4(metal::max(_e2.xyz, metal::float3(0.0)), 1.0) };
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
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
) {
    const WeftFringeShadowVertex in_1 = { varyings_2.position };
    bool local_2 = {};
    WeftFringeShadowVaryings out_1 = {};
    metal::float4x4 _e3 = weft_object.model;
    metal::float3 world_2 = (_e3 * metal::float4(in_1.position, 1.0)).xyz;
    metal::float4x4 _e11 = weft_frame.view_proj;
    metal::float4 clip_1 = _e11 * metal::float4(world_2, 1.0);
    metal::float4 _e17 = weft_frame.light_direction;
    metal::float3 l = _e17.xyz;
    float l_len = metal::length(l);
    metal::float3 travel = (l_len > 0.000001) ? (-(l) / metal::float3(metal::max(l_len, 0.000001))) : metal::float3(0.0);
    float _e32 = material.fringe_shadow_length;
    float length_world = metal::max(_e32, 0.0);
    metal::float4x4 _e37 = weft_frame.view_proj;
    metal::float4 pushed = _e37 * metal::float4(world_2 + (travel * length_world), 1.0);
    if (clip_1.w > 0.000001) {
        local_2 = pushed.w > 0.000001;
    } else {
        local_2 = false;
    }
    bool usable_1 = local_2;
    metal::float2 offset_ndc = usable_1 ? ((pushed.xy / metal::float2(metal::max(pushed.w, 0.000001))) - (clip_1.xy / metal::float2(metal::max(clip_1.w, 0.000001)))) : metal::float2(0.0);
    out_1.clip_position = metal::float4(clip_1.xy + (offset_ndc * clip_1.w), clip_1.zw);
    WeftFringeShadowVaryings _e77 = out_1;
    const auto _tmp_1 = _e77;
    return vs_fringe_shadowOutput { _tmp_1.clip_position };
}


struct fs_fringe_shadowOutput {
    metal::float4 member_3 [[color(0)]];
};
fragment fs_fringe_shadowOutput fs_fringe_shadow(
  constant WeftMaterial& material [[buffer(1)]]
) {
    metal::float4 _e2 = material.fringe_shadow_color;
    return fs_fringe_shadowOutput { metal::float4(metal::max(_e2.xyz, metal::float3(0.0)), 1.0) };
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
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
) {
    const WeftVertexInput in_2 = { varyings_4.position, varyings_4.normal, varyings_4.tangent_1, varyings_4.uv0_2 };
    WeftHair h = {};
    float scale = 0.0;
    WeftVaryings _e1 = weft_forward_vertex(in_2, weft_frame, weft_object);
    float _e6 = material.ior;
    float _e9 = material.roughness;
    float _e12 = material.azimuthal_roughness;
    float _e15 = material.scale_angle;
    WeftHair _e16 = weft_hair_params(metal::float3(0.0), _e6, _e9, _e12, _e15);
    h = _e16;
    {
        h = WeftHair {};
    }
    float _e23 = material.anisotropic_direction;
    float a_2 = ((_e23) * 0.017453292519943295474);
    float _e31 = h.eta;
    float _e33 = h.s;
    float _e36 = h.v.x;
    float _e37 = scale;
    metal::float3 _e40 = h.sin2k;
    float _e42 = h.r_floor;
    metal::float3 _e45 = h.cos2k;
    float _e48 = h.blur.x;
    metal::float3 _e51 = h.mp_norm;
    float _e54 = h.blur.y;
    metal::float3 _e57 = h.inv_v;
    float _e60 = h.trt.x;
    metal::float4 _e63 = h.trt;
    float _e66 = h.trt4_;
    float _e71 = h.inv_eta;
    float _e74 = material.strand_density;
    float _e75 = hair_noise_period(_e74);
    const auto _tmp_2 = HairVaryings {_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, {}, metal::float4(_e31, _e33, _e36, _e37), metal::float4(_e40, _e42), metal::float4(_e45, _e48), metal::float4(_e51, _e54), metal::float4(_e57, _e60), metal::float4(_e63.yzw, _e66), metal::float4(metal::cos(a_2), metal::sin(a_2), _e71, _e75)};
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
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> base_map [[texture(0)]]
, metal::texture2d<float, metal::access::sample> flow_map [[texture(1)]]
, metal::texture2d<float, metal::access::sample> jitter_map [[texture(2)]]
, metal::texture2d<float, metal::access::sample> uv_rotate_mask [[texture(3)]]
) {
    const HairVaryings in_3 = { clip_position, varyings_5.world_position_2, varyings_5.world_normal_1, varyings_5.world_tangent, varyings_5.uv0_2, {}, varyings_5.fibre, varyings_5.sin2k, varyings_5.cos2k, varyings_5.mp_norm, varyings_5.inv_v, varyings_5.trt, varyings_5.jitter };
    metal::float3 color = {};
    WeftHairLobes lobes = {};
    metal::float4 _e4 = material.base_map_st;
    metal::float2 _e5 = weft_transform_uv(in_3.uv0_, _e4);
    metal::float4 _e8 = material.base_color;
    metal::float4 _e11 = base_map.sample(material_sampler, _e5);
    metal::float4 base_rgba = _e8 * _e11;
    metal::float3 base = metal::saturate(base_rgba.xyz);
    float alpha = metal::saturate(base_rgba.w);
    WeftSurface _e19 = weft_surface(in_3.world_position, in_3.world_normal, weft_frame);
    metal::float3 v_1 = _e19.v;
    metal::float3 n_3 = _e19.n;
    metal::float3x3 _e23 = weft_tangent_frame(n_3, in_3.world_tangent);
    metal::float3 _e25 = hair_strand(_e23, in_3.uv0_, material, material_sampler, flow_map);
    float _e31 = hair_jitter(in_3.uv0_, in_3.jitter.xy, in_3.jitter.w, material, material_sampler, jitter_map, uv_rotate_mask);
    metal::float3 _e32 = weft_main_light_direction(weft_frame);
    metal::float3 _e33 = weft_main_light_radiance(weft_frame);
    metal::float3 _e34 = weft_sh_irradiance(n_3, weft_frame);
    float n_dot_l = metal::dot(n_3, _e32);
    {
        metal::float3 _e38 = weft_safe_normalize(_e32 + v_1, n_3);
        float _e41 = material.primary_shift;
        metal::float3 _e45 = weft_safe_normalize(_e25 + ((_e41 + _e31) * n_3), _e25);
        float _e48 = material.secondary_shift;
        metal::float3 _e52 = weft_safe_normalize(_e25 + ((_e48 + _e31) * n_3), _e25);
        metal::float4 _e55 = material.primary_color;
        float _e59 = material.primary_intensity;
        float _e62 = material.primary_exponent;
        float _e63 = hair_kajiya_kay(_e45, _e38, _e62);
        metal::float3 primary = _e55.xyz * (_e59 * _e63);
        metal::float4 _e68 = material.secondary_color;
        float _e72 = material.secondary_intensity;
        float _e75 = material.secondary_exponent;
        float _e76 = hair_kajiya_kay(_e52, _e38, _e75);
        metal::float3 secondary = _e68.xyz * (_e72 * _e76);
        metal::float3 direct = ((((base + primary) + secondary) * WEFT_INV_PI) * _e33) * metal::saturate(n_dot_l);
        color = direct + (_e34 * base);
    }
    metal::float3 _e88 = color;
    metal::float3 radiance = metal::clamp(_e88, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, alpha) };
}
