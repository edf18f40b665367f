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
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
#define material_clamp_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[2]])
Texture2D<float4> face_sdf_map : register(t4, space1);
Texture2D<float4> shadow_mask_map : register(t5, space1);
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
    float2 st = (((clamp(uv, (0.0).xx, (1.0).xx) * float2(63.0, 63.0)) + (0.5).xx) / float2(64.0, 64.0));
    float4 _e13 = skin_lut.SampleLevel(material_clamp_sampler, st, 0.0);
    return _e13;
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

float3 weft_safe_normalize_k1_(float3 v_1)
{
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * rsqrt(max(len2_1, 1e-20))) : float3(0.0, 0.0, 1.0));
}

float3 weft_main_light_direction()
{
    float4 _e2 = weft_frame.light_direction;
    const float3 _e4 = weft_safe_normalize_k1_(_e2.xyz);
    return _e4;
}

float3 weft_main_light_radiance()
{
    float4 _e2 = weft_frame.light_color;
    return max(_e2.xyz, (0.0).xxx);
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

float3 weft_view_direction_k2_(float3 world_position)
{
    float4 _e4 = weft_frame.camera_position;
    const float3 _e7 = weft_safe_normalize_k1_((_e4.xyz - world_position));
    return _e7;
}

WeftSurface ConstructWeftSurface(float3 arg0, float3 arg1) {
    WeftSurface ret = (WeftSurface)0;
    ret.v = arg0;
    ret.n = arg1;
    return ret;
}

WeftSurface weft_surface(float3 world_position_1, float3 world_normal)
{
    const float3 _e2 = weft_view_direction_k2_(world_position_1);
    const float3 _e3 = weft_safe_normalize(world_normal, _e2);
    const WeftSurface weftsurface = ConstructWeftSurface(_e2, _e3);
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

WeftLightGeometry weft_main_light_geometry(float3 n_1, float3 v_2)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_2), n_1);
    const float _e6 = weft_clamp_cos(dot(n_1, v_2));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_1, _e2)), saturate(dot(n_1, _e4)), saturate(dot(v_2, _e4)));
    return weftlightgeometry;
}

float3 weft_safe_normalize_k3_(float3 v_3)
{
    float len2_2 = dot(v_3, v_3);
    return ((len2_2 > 1e-20) ? (v_3 * rsqrt(max(len2_2, 1e-20))) : (0.0).xxx);
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
    const float3 _e53 = weft_safe_normalize_k3_(mul(in_3.normal, normal3_));
    out_1.world_normal = _e53;
    const float3 _e58 = weft_safe_normalize_k3_(mul(in_3.tangent.xyz, model3_));
    out_1.world_tangent = float4(_e58, bitangent_sign);
    out_1.uv0_ = in_3.uv0_;
    WeftVaryings _e62 = out_1;
    const WeftVaryings weftvaryings = _e62;
    return weftvaryings;
}

float3 weft_safe_normalize_k4_(float3 v_4)
{
    float len2_3 = dot(v_4, v_4);
    return ((len2_3 > 1e-20) ? (v_4 * rsqrt(max(len2_3, 1e-20))) : float3(1.0, 0.0, 0.0));
}

FaceLight face_light(float3 l)
{
    FaceLight out_2 = (FaceLight)0;

    float4x4 model_1 = weft_object.model;
    const float3 _e6 = weft_safe_normalize_k1_(model_1[2].xyz);
    const float3 _e9 = weft_safe_normalize_k4_(model_1[0].xyz);
    const float3 _e14 = weft_safe_normalize(float3(l.x, 0.0, l.z), _e6);
    out_2.f_dot_l = ((dot(_e6, _e14) * -0.5) + 0.5);
    out_2.from_right = (dot(_e9, _e14) >= 0.0);
    FaceLight _e26 = out_2;
    const FaceLight facelight = _e26;
    return facelight;
}

float2 weft_transform_uv_k5_(float2 uv_1)
{
    return (uv_1 + float2(0.0, 0.0));
}

float face_sdf_shadow_k6_(float2 uv_2, FaceLight light)
{
    float4 _e5 = face_sdf_map.Sample(material_sampler, uv_2);
    float sdf_l = _e5.x;
    float4 _e14 = face_sdf_map.Sample(material_sampler, float2((1.0 - uv_2.x), uv_2.y));
    float sdf_r = _e14.x;
    float sdf = (light.from_right ? sdf_r : sdf_l);
    return smoothstep(-0.05, 0.05, (sdf - light.f_dot_l));
}

float skin_seed_specular_k7_(float3 n_2, float3 l_1, float3 h)
{
    float n_dot_h = saturate(dot(n_2, h));
    float l_dot_h = saturate(dot(l_1, h));
    float d = (((n_dot_h * n_dot_h) * -0.8704) + 1.00001);
    float nl = saturate(dot(n_2, l_1));
    float s_ao = lerp(0.100112915, 1.0, saturate((-0.3 + (nl * nl))));
    float denom = (((d * d) * max(0.1, (l_dot_h * l_dot_h))) * 3.44);
    float ggx = (0.1296 / denom);
    float second = ((0.2592 / denom) * 0.15);
    return ((((ggx / 2.0) + second) * s_ao) / WEFT_PI);
}

float2 weft_env_brdf_lut_k9_(float n_dot_v)
{
    float2 uv_3 = float2(saturate(n_dot_v), 0.6);
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv_3, 0.0);
    return _e8.xy;
}

float3 weft_env_brdf_from_lut_k10_(float2 scale_bias)
{
    float2 sb = saturate(scale_bias);
    return (((0.028).xxx * sb.x) + (sb.y).xxx);
}

float weft_specular_mip_k12_()
{
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.768 * max_mip);
}

float3 weft_prefiltered_radiance_k11_(float3 dir)
{
    const float _e4 = weft_specular_mip_k12_();
    float4 c_1 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, (0.0).xxx);
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
    float2 size = _e29.xy;
    float4x4 _e33 = weft_frame.view_proj;
    float2 screen_normal = (mul(float4(normal, 0.0), _e33).xy * size);
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
    float distance_ = min(clip_.w, 10.0);
    float4 _e74 = weft_frame.viewport;
    float2 offset = ((((direction * 1.5) * 2.0) * _e74.zw) * distance_);
    out_.clip_position = float4((clip_.xy + offset), clip_.zw);
    WeftOutlineVaryings _e84 = out_;
    const WeftOutlineVaryings weftoutlinevaryings = _e84;
    const VertexOutput_vs_outline weftoutlinevaryings_1 = { weftoutlinevaryings.clip_position };
    return weftoutlinevaryings_1;
}

float4 fs_outline() : SV_Target0
{
    return float4(float3(0.0, 0.0, 0.0), 1.0);
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

    const float2 _e2 = weft_transform_uv_k5_(in_2.uv0_);
    float4 _e11 = shadow_mask_map.Sample(material_sampler, _e2);
    float shadow_mask = saturate(_e11.x);
    const WeftSurface _e16 = weft_surface(in_2.world_position, in_2.world_normal);
    float3 v_5 = _e16.v;
    float3 n_3 = _e16.n;
    float3 _e19 = fwidth(n_3);
    float dn = length(_e19);
    float3 _e22 = fwidth(in_2.world_position);
    float dp = length(_e22);
    float estimated = ((dp > 1e-12) ? (dn / dp) : 0.0);
    float curvature = clamp((0.6 * estimated), 0.01, 0.99);
    const WeftLightGeometry _e34 = weft_main_light_geometry(n_3, v_5);
    const FaceLight _e36 = face_light(_e34.l);
    const float _e37 = face_sdf_shadow_k6_(_e2, _e36);
    bias = (_e37 * shadow_mask);
    float _e40 = bias;
    bias = clamp(_e40, 0.0, 1.0);
    float _e44 = bias;
    const float4 _e46 = table_skin_lut(float2(_e44, curvature));
    float3 falloff = max(_e46.xyz, (0.0).xxx);
    const float _e52 = skin_seed_specular_k7_(n_3, _e34.l, _e34.h);
    float specular = ((_e52 * 0.028) * _e34.n_dot_l);
    const float3 _e57 = weft_main_light_radiance();
    float3 direct = (((float3(0.2560481, 0.15688866, 0.1216312) * falloff) + (specular).xxx) * _e57);
    const float2 _e64 = weft_env_brdf_lut_k9_(_e34.n_dot_v);
    const float3 _e65 = weft_env_brdf_from_lut_k10_(_e64);
    const float3 _e66 = weft_sh_irradiance(n_3);
    float3 indirect_diffuse = ((_e66 * (0.972).xxx) * float3(0.82757086, 0.5070785, 0.39312312));
    const float3 _e71 = weft_prefiltered_radiance_k11_(reflect(-(v_5), n_3));
    float3 indirect_specular = (_e71 * _e65);
    float3 color = ((direct + indirect_diffuse) + indirect_specular);
    float3 radiance = clamp(color, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
