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

metal::float3 weft_safe_normalize(
    metal::float3 v,
    metal::float3 fallback
) {
    float len2_ = metal::dot(v, v);
    return (len2_ > 0.00000000000000000001) ? (v * metal::rsqrt(metal::max(len2_, 0.00000000000000000001))) : fallback;
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

metal::float2 eye_seed_uv(
    metal::float2 uv,
    metal::float3 v_1,
    float height
) {
    return uv + (height * metal::float2(v_1.x, -(v_1.y)));
}

metal::float2 eye_uv_from_xy(
    metal::float2 xy
) {
    return metal::float2(0.5 + (0.5 * xy.x), 0.5 - (0.5 * xy.y));
}

metal::float2 eye_xy_from_uv(
    metal::float2 uv_1
) {
    return metal::float2((2.0 * uv_1.x) - 1.0, 1.0 - (2.0 * uv_1.y));
}

metal::float3 eye_procedural_iris(
    float rho,
    float a,
    constant WeftMaterial& material
) {
    metal::float3 c = {};
    float _e4 = material.pupil_size;
    float pupil = metal::clamp(_e4, 0.0, 0.95);
    float t = metal::saturate((rho - pupil) / (1.0 - pupil));
    metal::float4 _e15 = material.iris_inner_color;
    metal::float4 _e19 = material.iris_color;
    c = metal::mix(_e15.xyz, _e19.xyz, metal::smoothstep(0.05, 0.5, t));
    float fibres = (0.82 + (0.1 * metal::sin((a * 23.0) + (6.0 * t)))) + (0.08 * metal::sin(((a * 41.0) - (9.0 * t)) + 1.3));
    metal::float3 _e47 = c;
    c = _e47 * fibres;
    float _e51 = material.limbus_width;
    float w = metal::saturate(_e51);
    metal::float3 _e53 = c;
    c = _e53 * (1.0 - (0.8 * metal::smoothstep(1.0 - w, 1.0, rho)));
    metal::float3 _e65 = c;
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
    float r = metal::clamp(_e4, 0.05, 0.95);
    float rho_1 = metal::length(q) / r;
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

metal::float3 eye_procedural_matcap(
    metal::float2 uv_2
) {
    float key = 1.0 - metal::smoothstep(0.03, 0.08, metal::length(uv_2 - metal::float2(0.36, 0.3)));
    float bounce = 1.0 - metal::smoothstep(0.02, 0.09, metal::length(uv_2 - metal::float2(0.66, 0.72)));
    return metal::float3(key + (0.25 * bounce));
}

metal::float3 eye_seed(
    metal::float3 p,
    metal::float3 v_eye,
    metal::float3 n_1,
    metal::float3 world_position_2,
    metal::float3 light,
    constant WeftFrame& weft_frame,
    constant WeftMaterial& material,
    metal::sampler material_sampler,
    metal::texture2d<float, metal::access::sample> sclera_map
) {
    metal::float3 matcap = {};
    metal::float2 _e6 = eye_uv_from_xy(p.xy);
    float _e9 = material.parallax_height;
    metal::float2 _e10 = eye_seed_uv(_e6, v_eye, _e9);
    metal::float2 _e11 = eye_xy_from_uv(_e10);
    metal::float3 _e15 = eye_albedo(_e11, p.z > 0.0, material, material_sampler, sclera_map);
    metal::float4x4 view = weft_frame.view;
    metal::float3x3 view3_ = metal::float3x3(view[0].xyz, view[1].xyz, view[2].xyz);
    metal::float3 _e31 = weft_safe_normalize(view3_ * n_1, metal::float3(0.0, 0.0, 1.0));
    metal::float3 _e40 = weft_safe_normalize((view * metal::float4(world_position_2, 1.0)).xyz, metal::float3(0.0, 0.0, -1.0));
    metal::float3 vxn = metal::cross(_e40, _e31);
    metal::float2 matcap_uv = metal::float2(0.5 - (0.5 * vxn.y), 0.5 - (0.5 * vxn.x));
    {
        metal::float3 _e54 = eye_procedural_matcap(matcap_uv);
        matcap = _e54;
    }
    metal::float3 _e55 = matcap;
    float _e58 = material.matcap_intensity;
    metal::float3 base = _e15 + (_e55 * metal::max(_e58, 0.0));
    metal::float3 _e65 = weft_sh_irradiance(n_1, weft_frame);
    return base * ((light * WEFT_INV_PI) + _e65);
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
    metal::float3 world_position_3 [[user(loc0), center_perspective]];
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
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> sclera_map [[texture(0)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_3, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float3 color = {};
    EyeLookup look = {};
    metal::float4x4 model_1 = weft_object.model;
    metal::float3x3 model3_1 = metal::float3x3(model_1[0].xyz, model_1[1].xyz, model_1[2].xyz);
    metal::float4x4 nm_1 = weft_object.normal_matrix;
    metal::float3x3 normal3_1 = metal::float3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    WeftSurface _e23 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_2 = _e23.v;
    metal::float3 n_2 = _e23.n;
    metal::float3 _e26 = weft_main_light_direction(weft_frame);
    metal::float3 _e33 = weft_safe_normalize(metal::transpose(model3_1) * n_2, metal::float3(0.0, 0.0, 1.0));
    metal::float3 _e40 = weft_safe_normalize(metal::transpose(normal3_1) * v_2, metal::float3(0.0, 0.0, 1.0));
    metal::float3 _e46 = weft_safe_normalize(model3_1 * metal::float3(0.0, 0.0, 1.0), n_2);
    float _e49 = material.backlight_dimming;
    float dimming = 1.0 - (metal::saturate(_e49) * metal::saturate(-(metal::dot(_e46, _e26))));
    metal::float3 _e57 = weft_main_light_radiance(weft_frame);
    {
        metal::float3 _e60 = eye_seed(_e33, _e40, n_2, in_1.world_position, _e57, weft_frame, material, material_sampler, sclera_map);
        color = _e60;
    }
    metal::float3 _e61 = color;
    metal::float3 radiance = metal::clamp(_e61 * dimming, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
