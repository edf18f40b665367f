struct WeftFrame {
    row_major float4x4 view_proj;
    row_major float4x4 view;
    float4 camera_position;
    float4 light_direction;
    float4 light_color;
    float4 sh[9];
    float4 params;
    float4 viewport;
};

struct WeftObject {
    row_major float4x4 model;
    row_major float4x4 normal_matrix;
};

struct WeftMaterial {
    float4 base_color;
    float4 base_map_st;
    float face_soft_shadow;
    float curvature_factor;
    float dark_bound;
    float bright_bound;
    float roughness;
    float specular;
    float lobe_weight;
    int _pad9_0;
    float4 outline_color;
    float outline_width;
    float outline_max_distance;
    int _end_pad_0;
    int _end_pad_1;
};

struct WeftOutlineVertex {
    float3 position : LOC0;
    float3 normal : LOC1;
};

struct WeftOutlineVaryings {
    float4 clip_position : SV_Position;
};

struct WeftSurface {
    float3 v;
    int _pad1_0;
    float3 n;
    int _end_pad_0;
};

struct WeftLightGeometry {
    float3 l;
    int _pad1_0;
    float3 h;
    float n_dot_v;
    float n_dot_l;
    float n_dot_h;
    float v_dot_h;
    int _end_pad_0;
};

struct WeftVertexInput {
    float3 position : LOC0;
    float3 normal : LOC1;
    float4 tangent : LOC2;
    float2 uv0_ : LOC3;
};

struct WeftVaryings {
    float4 clip_position : SV_Position;
    float3 world_position : LOC0;
    float3 world_normal : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
};

struct FaceLight {
    float f_dot_l;
    bool from_right;
};

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const float3 skin_lut_shape = float3(4.0, 10.0, 20.0);
static const float skin_lut_ring = 3.1415927;
static const uint TIER_STYLISED = 0u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;

cbuffer weft_frame : register(b0) { WeftFrame weft_frame; }
TextureCube<float4> weft_environment : register(t1);
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup0SamplerIndexArray : register(t64, space0);
#define weft_environment_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[2]])
Texture2D<float4> weft_brdf_lut : register(t3);
#define weft_lut_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[4]])
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }
cbuffer material : register(b0, space1) { WeftMaterial material; }
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
#define material_clamp_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[2]])
Texture2D<float4> base_map : register(t3, space1);
Texture2D<float4> face_sdf_map : register(t4, space1);
Texture2D<float4> shadow_mask_map : register(t5, space1);
Texture2D<float4> specular_mask : register(t6, space1);
Texture2D<float4> skin_lut : register(t7, space1);

struct VertexOutput_vs_outline {
    float4 clip_position : SV_Position;
};

struct VertexOutput_vs_main {
    float3 world_position_2 : LOC0;
    float3 world_normal_1 : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    float4 clip_position_1 : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_3 : LOC0;
    float3 world_normal_2 : LOC1;
    float4 world_tangent_1 : LOC2;
    float2 uv0_1 : LOC3;
    float4 clip_position_2 : SV_Position;
};

float4 table_skin_lut(float2 uv)
{
    float2 size = float2(64.0, 64.0);
    float2 st_1 = (((clamp(uv, (0.0).xx, (1.0).xx) * (size - (1.0).xx)) + (0.5).xx) / size);
    float4 _e20 = skin_lut.SampleLevel(material_clamp_sampler, st_1, 0.0);
    return _e20;
}

float weft_clamp_cos(float c)
{
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

float3 weft_safe_normalize(float3 v, float3 fallback)
{
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * rsqrt(max(len2_, 1e-20))) : fallback);
}

float3 weft_diffuse_lambert(float3 albedo)
{
    return (albedo * WEFT_INV_PI);
}

float3 weft_env_brdf_from_lut(float3 f0_, float2 scale_bias)
{
    float2 sb = saturate(scale_bias);
    return ((f0_ * sb.x) + (sb.y).xxx);
}

float3 weft_main_light_direction()
{
    float4 _e2 = weft_frame.light_direction;
    const float3 _e8 = weft_safe_normalize(_e2.xyz, float3(0.0, 0.0, 1.0));
    return _e8;
}

float3 weft_main_light_radiance()
{
    float4 _e2 = weft_frame.light_color;
    return max(_e2.xyz, (0.0).xxx);
}

float3 weft_view_direction(float3 world_position, float3 fallback_1)
{
    float4 _e4 = weft_frame.camera_position;
    const float3 _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
}

float3 weft_sh_irradiance(float3 n)
{
    float3 e = (float3)0;

    float4 sh[9] = weft_frame.sh;
    e = (sh[0].xyz * 0.282095);
    float3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n.y)));
    float3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n.z)));
    float3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n.x)));
    float3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n.x) * n.y)));
    float3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n.y) * n.z)));
    float3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n.z) * n.z) - 1.0))));
    float3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n.x) * n.z)));
    float3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n.x * n.x) - (n.y * n.y)))));
    float3 _e91 = e;
    return max(_e91, (0.0).xxx);
}

float weft_specular_mip(float roughness)
{
    float r = saturate(roughness);
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

float3 weft_prefiltered_radiance(float3 dir, float roughness_1)
{
    const float _e4 = weft_specular_mip(roughness_1);
    float4 c_1 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, (0.0).xxx);
}

float2 weft_env_brdf_lut(float n_dot_v, float roughness_2)
{
    float2 uv_3 = float2(saturate(n_dot_v), saturate(roughness_2));
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv_3, 0.0);
    return _e8.xy;
}

WeftSurface ConstructWeftSurface(float3 arg0, float3 arg1) {
    WeftSurface ret = (WeftSurface)0;
    ret.v = arg0;
    ret.n = arg1;
    return ret;
}

WeftSurface weft_surface(float3 world_position_1, float3 world_normal)
{
    const float3 _e6 = weft_view_direction(world_position_1, float3(0.0, 0.0, 1.0));
    const float3 _e7 = weft_safe_normalize(world_normal, _e6);
    const WeftSurface weftsurface = ConstructWeftSurface(_e6, _e7);
    return weftsurface;
}

WeftLightGeometry ConstructWeftLightGeometry(float3 arg0, float3 arg1, float arg2, float arg3, float arg4, float arg5) {
    WeftLightGeometry ret = (WeftLightGeometry)0;
    ret.l = arg0;
    ret.h = arg1;
    ret.n_dot_v = arg2;
    ret.n_dot_l = arg3;
    ret.n_dot_h = arg4;
    ret.v_dot_h = arg5;
    return ret;
}

WeftLightGeometry weft_main_light_geometry(float3 n_1, float3 v_1)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_1), n_1);
    const float _e6 = weft_clamp_cos(dot(n_1, v_1));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_1, _e2)), saturate(dot(n_1, _e4)), saturate(dot(v_1, _e4)));
    return weftlightgeometry;
}

WeftVaryings weft_forward_vertex(WeftVertexInput in_3)
{
    WeftVaryings out_1 = (WeftVaryings)0;

    float4x4 model = weft_object.model;
    float3x3 model3_ = float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    float4x4 nm = weft_object.normal_matrix;
    float3x3 normal3_ = float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    float4 world = mul(float4(in_3.position, 1.0), model);
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_3.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    float4x4 _e43 = weft_frame.view_proj;
    out_1.clip_position = mul(float4(world.xyz, 1.0), _e43);
    out_1.world_position = world.xyz;
    const float3 _e55 = weft_safe_normalize(mul(in_3.normal, normal3_), (0.0).xxx);
    out_1.world_normal = _e55;
    const float3 _e62 = weft_safe_normalize(mul(in_3.tangent.xyz, model3_), (0.0).xxx);
    out_1.world_tangent = float4(_e62, bitangent_sign);
    out_1.uv0_ = in_3.uv0_;
    WeftVaryings _e66 = out_1;
    const WeftVaryings weftvaryings = _e66;
    return weftvaryings;
}

float2 weft_transform_uv(float2 uv_1, float4 st)
{
    return ((uv_1 * st.xy) + st.zw);
}

float skin_seed_specular(float3 n_2, float3 l, float3 h, float roughness_3, float mask, float lobe_weight)
{
    float n_dot_h = saturate(dot(n_2, h));
    float l_dot_h = saturate(dot(l, h));
    float r2_ = (roughness_3 * roughness_3);
    float normalization = ((roughness_3 * 4.0) + 2.0);
    float d = (((n_dot_h * n_dot_h) * (r2_ - 1.0)) + 1.00001);
    float nl = saturate(dot(n_2, l));
    float s_ao = lerp(0.100112915, 1.0, saturate((-0.3 + (nl * nl))));
    float denom = (((d * d) * max(0.1, (l_dot_h * l_dot_h))) * normalization);
    float ggx = (r2_ / denom);
    float second = ((((2.0 * r2_) / denom) * lobe_weight) * mask);
    return ((((ggx / 2.0) + second) * s_ao) / WEFT_PI);
}

FaceLight face_light(float3 l_1)
{
    FaceLight out_2 = (FaceLight)0;

    float4x4 model_1 = weft_object.model;
    const float3 _e10 = weft_safe_normalize(model_1[2].xyz, float3(0.0, 0.0, 1.0));
    const float3 _e17 = weft_safe_normalize(model_1[0].xyz, float3(1.0, 0.0, 0.0));
    const float3 _e22 = weft_safe_normalize(float3(l_1.x, 0.0, l_1.z), _e10);
    out_2.f_dot_l = ((dot(_e10, _e22) * -0.5) + 0.5);
    out_2.from_right = (dot(_e17, _e22) >= 0.0);
    FaceLight _e34 = out_2;
    const FaceLight facelight = _e34;
    return facelight;
}

float face_sdf_shadow(float2 uv_2, FaceLight light, float soft)
{
    float4 _e5 = face_sdf_map.Sample(material_sampler, uv_2);
    float sdf_l = _e5.x;
    float4 _e14 = face_sdf_map.Sample(material_sampler, float2((1.0 - uv_2.x), uv_2.y));
    float sdf_r = _e14.x;
    float sdf = (light.from_right ? sdf_r : sdf_l);
    float w = max(soft, 0.0001);
    return smoothstep(-(w), w, (sdf - light.f_dot_l));
}

VertexOutput_vs_outline vs_outline(WeftOutlineVertex in_)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;
    WeftOutlineVaryings out_ = (WeftOutlineVaryings)0;

    float4x4 _e3 = weft_object.model;
    float4 world_1 = mul(float4(in_.position, 1.0), _e3);
    float4x4 nm_1 = weft_object.normal_matrix;
    float3 normal = mul(in_.normal, float3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz));
    float4x4 _e22 = weft_frame.view_proj;
    float4 clip_ = mul(float4(world_1.xyz, 1.0), _e22);
    float4 _e29 = weft_frame.viewport;
    float2 size_1 = _e29.xy;
    float4x4 _e33 = weft_frame.view_proj;
    float2 screen_normal = (mul(float4(normal, 0.0), _e33).xy * size_1);
    float len = length(screen_normal);
    if ((len > 1e-6)) {
        float _e47 = weft_frame.viewport.x;
        local = (_e47 > 0.0);
    } else {
        local = false;
    }
    bool _e51 = local;
    if (_e51) {
        local_1 = (clip_.w > 0.0);
    } else {
        local_1 = false;
    }
    bool usable = local_1;
    float2 direction = (usable ? (screen_normal / (max(len, 1e-6)).xx) : (0.0).xx);
    float _e68 = material.outline_width;
    float width_px = max(_e68, 0.0);
    float _e74 = material.outline_max_distance;
    float distance_ = min(clip_.w, max(_e74, 0.0));
    float4 _e83 = weft_frame.viewport;
    float2 offset = ((((direction * width_px) * 2.0) * _e83.zw) * distance_);
    out_.clip_position = float4((clip_.xy + offset), clip_.zw);
    WeftOutlineVaryings _e93 = out_;
    const WeftOutlineVaryings weftoutlinevaryings = _e93;
    const VertexOutput_vs_outline weftoutlinevaryings_1 = { weftoutlinevaryings.clip_position };
    return weftoutlinevaryings_1;
}

float4 fs_outline() : SV_Target0
{
    float4 _e2 = material.outline_color;
    return float4(max(_e2.xyz, (0.0).xxx), 1.0);
}

VertexOutput_vs_main vs_main(WeftVertexInput in_1)
{
    const WeftVaryings _e1 = weft_forward_vertex(in_1);
    const WeftVaryings weftvaryings_1 = _e1;
    const VertexOutput_vs_main weftvaryings_1_ = { weftvaryings_1.world_position, weftvaryings_1.world_normal, weftvaryings_1.world_tangent, weftvaryings_1.uv0_, weftvaryings_1.clip_position };
    return weftvaryings_1_;
}

float4 fs_main(FragmentInput_fs_main fragmentinput_fs_main) : SV_Target0
{
    WeftVaryings in_2 = { fragmentinput_fs_main.clip_position_2, fragmentinput_fs_main.world_position_3, fragmentinput_fs_main.world_normal_2, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_1 };
    float bias = (float)0;

    float4 _e4 = material.base_map_st;
    const float2 _e5 = weft_transform_uv(in_2.uv0_, _e4);
    float4 _e8 = material.base_color;
    float4 _e11 = base_map.Sample(material_sampler, _e5);
    float4 base_rgba = (_e8 * _e11);
    float3 albedo_1 = saturate(base_rgba.xyz);
    float alpha = saturate(base_rgba.w);
    float _e19 = material.roughness;
    float roughness_4 = clamp(_e19, 0.05, 1.0);
    float _e25 = material.specular;
    float f0_1 = clamp(_e25, 0.0, 1.0);
    float4 _e31 = specular_mask.Sample(material_sampler, _e5);
    float mask_1 = saturate(_e31.x);
    float4 _e36 = shadow_mask_map.Sample(material_sampler, _e5);
    float shadow_mask = saturate(_e36.x);
    const WeftSurface _e41 = weft_surface(in_2.world_position, in_2.world_normal);
    float3 v_2 = _e41.v;
    float3 n_3 = _e41.n;
    float3 _e44 = fwidth(n_3);
    float dn = length(_e44);
    float3 _e47 = fwidth(in_2.world_position);
    float dp = length(_e47);
    float estimated = ((dp > 1e-12) ? (dn / dp) : 0.0);
    float _e56 = material.curvature_factor;
    float curvature = clamp((max(_e56, 0.0) * estimated), 0.01, 0.99);
    const WeftLightGeometry _e63 = weft_main_light_geometry(n_3, v_2);
    const FaceLight _e65 = face_light(_e63.l);
    float _e68 = material.face_soft_shadow;
    const float _e69 = face_sdf_shadow(_e5, _e65, _e68);
    bias = (_e69 * shadow_mask);
    float _e72 = bias;
    float _e75 = material.dark_bound;
    float _e78 = material.bright_bound;
    bias = clamp(_e72, _e75, _e78);
    float _e80 = bias;
    const float4 _e82 = table_skin_lut(float2(_e80, curvature));
    float3 falloff = max(_e82.xyz, (0.0).xxx);
    float _e92 = material.lobe_weight;
    const float _e93 = skin_seed_specular(n_3, _e63.l, _e63.h, (roughness_4 * roughness_4), mask_1, _e92);
    float specular = ((_e93 * f0_1) * _e63.n_dot_l);
    float3 kd = ((1.0 - f0_1)).xxx;
    const float3 _e100 = weft_main_light_radiance();
    const float3 _e101 = weft_diffuse_lambert(albedo_1);
    float3 direct = ((((kd * _e101) * falloff) + (specular).xxx) * _e100);
    const float2 _e109 = weft_env_brdf_lut(_e63.n_dot_v, roughness_4);
    const float3 _e110 = weft_env_brdf_from_lut((f0_1).xxx, _e109);
    const float3 _e111 = weft_sh_irradiance(n_3);
    float3 indirect_diffuse = ((_e111 * kd) * albedo_1);
    const float3 _e116 = weft_prefiltered_radiance(reflect(-(v_2), n_3), roughness_4);
    float3 indirect_specular = ((_e116 * _e110) * mask_1);
    float3 color = ((direct + indirect_diffuse) + indirect_specular);
    float3 radiance = clamp(color, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
