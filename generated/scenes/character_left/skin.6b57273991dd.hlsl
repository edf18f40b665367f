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

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const float3 skin_lut_shape = float3(4.0, 10.0, 20.0);
static const float skin_lut_ring = 3.1415927;
static const float3 seed_lut_shape = float3(4.0, 10.0, 20.0);
static const float seed_lut_ring = 1.5707964;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SEED = 2u;
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
Texture2D<float4> curvature_map : register(t5, space1);
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

float weft_pow5_(float x)
{
    float x2_ = (x * x);
    return ((x2_ * x2_) * x);
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

float3 weft_sh_irradiance(float3 n_1)
{
    float3 e = (float3)0;

    float4 sh[9] = weft_frame.sh;
    e = (sh[0].xyz * 0.282095);
    float3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_1.y)));
    float3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_1.z)));
    float3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_1.x)));
    float3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_1.x) * n_1.y)));
    float3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_1.y) * n_1.z)));
    float3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0))));
    float3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_1.x) * n_1.z)));
    float3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
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

WeftLightGeometry weft_main_light_geometry(float3 n_2, float3 v_2)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_2), n_2);
    const float _e6 = weft_clamp_cos(dot(n_2, v_2));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_2, _e2)), saturate(dot(n_2, _e4)), saturate(dot(v_2, _e4)));
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

float2 weft_transform_uv_k4_(float2 uv_1)
{
    return (uv_1 + float2(0.0, 0.0));
}

float2 weft_env_brdf_lut_k5_(float n_dot_v)
{
    float2 uv_2 = float2(saturate(n_dot_v), 0.5);
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv_2, 0.0);
    return _e8.xy;
}

float3 weft_env_brdf_from_lut_k6_(float2 scale_bias)
{
    float2 sb = saturate(scale_bias);
    return (((0.028).xxx * sb.x) + (sb.y).xxx);
}

float weft_d_ggx_nh_k10_(float3 n_3, float3 h)
{
    float noh = saturate(dot(n_3, h));
    float3 nxh = cross(n_3, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * 0.01977539));
    return (0.01977539 / (WEFT_PI * max((d * d), 1e-30)));
}

float weft_v_smith_ggx_correlated_k11_(float n_dot_v_1, float n_dot_l)
{
    const float _e6 = weft_clamp_cos(n_dot_v_1);
    const float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * 0.9802246) + 0.01977539)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * 0.9802246) + 0.01977539)));
    return (0.5 / (lv + ll));
}

float weft_d_ggx_nh_k12_(float3 n_4, float3 h_1)
{
    float noh_1 = saturate(dot(n_4, h_1));
    float3 nxh_1 = cross(n_4, h_1);
    float d_1 = (dot(nxh_1, nxh_1) + ((noh_1 * noh_1) * 0.17850621));
    return (0.17850621 / (WEFT_PI * max((d_1 * d_1), 1e-30)));
}

float weft_v_smith_ggx_correlated_k13_(float n_dot_v_2, float n_dot_l_1)
{
    const float _e6 = weft_clamp_cos(n_dot_v_2);
    const float _e7 = weft_clamp_cos(n_dot_l_1);
    float lv_1 = (_e7 * sqrt((((_e6 * _e6) * 0.8214938) + 0.17850621)));
    float ll_1 = (_e6 * sqrt((((_e7 * _e7) * 0.8214938) + 0.17850621)));
    return (0.5 / (lv_1 + ll_1));
}

float3 weft_f_schlick_k14_(float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return ((0.028).xxx + (float3(0.972, 0.972, 0.972) * _e5));
}

float skin_dual_ggx_k7_(float3 n_5, float3 h_2, float n_dot_v_3, float n_dot_l_2, float v_dot_h_1)
{
    const float _e10 = weft_d_ggx_nh_k10_(n_5, h_2);
    const float _e11 = weft_v_smith_ggx_correlated_k11_(n_dot_v_3, n_dot_l_2);
    float lobe0_ = (_e10 * _e11);
    const float _e13 = weft_d_ggx_nh_k12_(n_5, h_2);
    const float _e14 = weft_v_smith_ggx_correlated_k13_(n_dot_v_3, n_dot_l_2);
    float lobe1_ = (_e13 * _e14);
    const float3 _e16 = weft_f_schlick_k14_(v_dot_h_1);
    float f = _e16.x;
    return (lerp(lobe0_, lobe1_, 0.15) * f);
}

float weft_specular_mip_k15_()
{
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.675 * max_mip);
}

float3 weft_prefiltered_radiance_k9_(float3 dir)
{
    const float _e4 = weft_specular_mip_k15_();
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
    float curvature = (float)0;
    float3 n = (float3)0;
    float3 falloff = (float3)0;
    float specular = (float)0;
    float3 kd = (float3)0;

    const float2 _e2 = weft_transform_uv_k4_(in_2.uv0_);
    const WeftSurface _e11 = weft_surface(in_2.world_position, in_2.world_normal);
    float3 v_4 = _e11.v;
    float3 n_geom = _e11.n;
    float3 _e14 = fwidth(n_geom);
    float dn = length(_e14);
    float3 _e17 = fwidth(in_2.world_position);
    float dp = length(_e17);
    float estimated = ((dp > 1e-12) ? (dn / dp) : 0.0);
    float4 _e26 = curvature_map.Sample(material_sampler, _e2);
    float mapped = _e26.x;
    curvature = saturate((0.6 * estimated));
    n = n_geom;
    float3 _e33 = n;
    const WeftLightGeometry _e34 = weft_main_light_geometry(_e33, v_4);
    float3 _e35 = n;
    float u = clamp(((dot(_e35, _e34.l) * 0.5) + 0.5), 0.0, 1.0);
    {
        {
            float _e46 = curvature;
            const float4 _e48 = table_skin_lut(float2(u, _e46));
            falloff = _e48.xyz;
        }
    }
    float3 _e50 = falloff;
    falloff = max(_e50, (0.0).xxx);
    const float2 _e54 = weft_env_brdf_lut_k5_(_e34.n_dot_v);
    const float3 _e55 = weft_env_brdf_from_lut_k6_(_e54);
    {
        float3 _e58 = n;
        const float _e63 = skin_dual_ggx_k7_(_e58, _e34.h, _e34.n_dot_v, _e34.n_dot_l, _e34.v_dot_h);
        specular = (_e63 * _e34.n_dot_l);
        kd = max(((1.0).xxx - _e55), (0.0).xxx);
    }
    const float3 _e70 = weft_main_light_radiance();
    float3 _e71 = kd;
    float3 _e74 = falloff;
    float _e76 = specular;
    float3 direct = ((((_e71 * float3(0.22029306, 0.10898664, 0.074173205)) * _e74) + (_e76).xxx) * _e70);
    float3 _e80 = n;
    const float3 _e81 = weft_sh_irradiance(_e80);
    float3 _e82 = kd;
    float3 indirect_diffuse = ((_e81 * _e82) * float3(0.6920711, 0.34239164, 0.233022));
    float3 _e86 = n;
    const float3 _e88 = weft_prefiltered_radiance_k9_(reflect(-(v_4), _e86));
    float3 indirect_specular = (_e88 * _e55);
    float3 color = ((direct + indirect_diffuse) + indirect_specular);
    float3 radiance = clamp(color, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
