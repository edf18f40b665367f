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

struct WeftMaterial {
    float4 scatter_color;
};

typedef float4 ret_Constructarray9_float4_[9];
ret_Constructarray9_float4_ Constructarray9_float4_(float4 arg0, float4 arg1, float4 arg2, float4 arg3, float4 arg4, float4 arg5, float4 arg6, float4 arg7, float4 arg8) {
    float4 ret[9] = { arg0, arg1, arg2, arg3, arg4, arg5, arg6, arg7, arg8 };
    return ret;
}

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SEED = 2u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float WEFT_SHEEN_MIN_ROUGHNESS = 0.07;

cbuffer weft_frame : register(b0) { WeftFrame weft_frame; }
TextureCube<float4> weft_environment : register(t1);
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup0SamplerIndexArray : register(t64, space0);
#define weft_environment_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[2]])
#define weft_lut_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[4]])
Texture2D<float4> weft_sheen_lut : register(t5);
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }
cbuffer material : register(b0, space1) { WeftMaterial material; }

struct VertexOutput_vs_main {
    float3 world_position_2 : LOC0;
    float3 world_normal_1 : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    float4 clip_position : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_3 : LOC0;
    float3 world_normal_2 : LOC1;
    float4 world_tangent_1 : LOC2;
    float2 uv0_1 : LOC3;
    float4 clip_position_1 : SV_Position;
};

float weft_max3_(float3 v)
{
    return max(v.x, max(v.y, v.z));
}

float weft_clamp_cos(float c)
{
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

float3 weft_safe_normalize(float3 v_1, float3 fallback)
{
    float len2_ = dot(v_1, v_1);
    return ((len2_ > 1e-20) ? (v_1 * rsqrt(max(len2_, 1e-20))) : fallback);
}

float3 weft_sh_irradiance(float3 n_1)
{
    float3 e = (float3)0;

    e = float3(0.27778354, 0.32136026, 0.4497644);
    e = (float3(0.27778354, 0.32136026, 0.4497644) + (float3(0.2192843, 0.34164187, 0.663193) * (0.488603 * n_1.y)));
    float3 _e11 = e;
    e = (_e11 + (float3(0.1352113, 0.12394369, 0.10366199) * (0.488603 * n_1.z)));
    float3 _e18 = e;
    e = (_e18 + (float3(-0.14969625, -0.13722156, -0.11476713) * (0.488603 * n_1.x)));
    float3 _e25 = e;
    e = (_e25 + (float3(-0.064625785, -0.059240304, -0.049546435) * ((1.092548 * n_1.x) * n_1.y)));
    float3 _e34 = e;
    e = (_e34 + (float3(0.05837178, 0.053507466, 0.044751696) * ((1.092548 * n_1.y) * n_1.z)));
    float3 _e43 = e;
    e = (_e43 + (float3(0.025110306, 0.023586905, 0.01273896) * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0))));
    float3 _e56 = e;
    e = (_e56 + (float3(-0.06322707, -0.057958152, -0.04847409) * ((1.092548 * n_1.x) * n_1.z)));
    float3 _e65 = e;
    e = (_e65 + (float3(0.056382716, 0.05266991, 0.031947177) * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    float3 _e78 = e;
    return max(_e78, (0.0).xxx);
}

float3 weft_safe_normalize_k8_(float3 v_2)
{
    float len2_1 = dot(v_2, v_2);
    return ((len2_1 > 1e-20) ? (v_2 * rsqrt(max(len2_1, 1e-20))) : float3(0.0, 0.0, 1.0));
}

float3 weft_view_direction_k2_(float3 world_position)
{
    float4 _e4 = weft_frame.camera_position;
    const float3 _e7 = weft_safe_normalize_k8_((_e4.xyz - world_position));
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

WeftLightGeometry weft_main_light_geometry(float3 n_2, float3 v_3)
{
    const float3 _e4 = weft_safe_normalize((float3(-0.61984503, 0.54986256, 0.55986005) + v_3), n_2);
    const float _e6 = weft_clamp_cos(dot(n_2, v_3));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(float3(-0.61984503, 0.54986256, 0.55986005), _e4, _e6, saturate(dot(n_2, float3(-0.61984503, 0.54986256, 0.55986005))), saturate(dot(n_2, _e4)), saturate(dot(v_3, _e4)));
    return weftlightgeometry;
}

float3 weft_safe_normalize_k3_(float3 v_4)
{
    float len2_2 = dot(v_4, v_4);
    return ((len2_2 > 1e-20) ? (v_4 * rsqrt(max(len2_2, 1e-20))) : (0.0).xxx);
}

WeftVaryings weft_forward_vertex(WeftVertexInput in_2)
{
    WeftVaryings out_ = (WeftVaryings)0;

    float4x4 model = weft_object.model;
    float3x3 model3_ = float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    float4x4 nm = weft_object.normal_matrix;
    float3x3 normal3_ = float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    float4 world = mul(float4(in_2.position, 1.0), model);
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    float4x4 _e43 = weft_frame.view_proj;
    out_.clip_position = mul(float4(world.xyz, 1.0), _e43);
    out_.world_position = world.xyz;
    const float3 _e53 = weft_safe_normalize_k3_(mul(in_2.normal, normal3_));
    out_.world_normal = _e53;
    const float3 _e58 = weft_safe_normalize_k3_(mul(in_2.tangent.xyz, model3_));
    out_.world_tangent = float4(_e58, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e62 = out_;
    const WeftVaryings weftvaryings = _e62;
    return weftvaryings;
}

float weft_sheen_albedo_scaling_view(float3 sheen_color, float e_v)
{
    const float _e2 = weft_max3_(sheen_color);
    return saturate((1.0 - (saturate(_e2) * saturate(e_v))));
}

float weft_sheen_albedo_k9_(float n_dot_x)
{
    float2 uv = float2(saturate(n_dot_x), 0.1225);
    float4 _e8 = weft_sheen_lut.SampleLevel(weft_lut_sampler, uv, 0.0);
    return saturate(_e8.x);
}

float weft_d_charlie_k12_(float n_dot_h)
{
    float noh = saturate(n_dot_h);
    float sin2_ = max(((1.0 - noh) * (1.0 + noh)), 0.0);
    return ((10.163265 * pow(sin2_, 4.0816326)) * 0.15915494);
}

float weft_sheen_l_k16_(float x)
{
    return (((24.455767 / (1.0 + (3.4406166 * pow(max(x, 0.0), 0.1749604)))) + (-1.4357697 * x)) + -4.7356734);
}

float weft_sheen_lambda_one_exp_k15_(float cos_theta)
{
    const float _e2 = weft_clamp_cos(cos_theta);
    bool low = (_e2 < 0.5);
    const float _e8 = weft_sheen_l_k16_((low ? _e2 : (1.0 - _e2)));
    return exp((low ? _e8 : (1.1767559 - _e8)));
}

float weft_v_charlie_k13_(float n_dot_v, float n_dot_l)
{
    const float _e4 = weft_clamp_cos(n_dot_v);
    const float _e5 = weft_clamp_cos(n_dot_l);
    const float _e6 = weft_sheen_lambda_one_exp_k15_(_e4);
    const float _e9 = weft_sheen_lambda_one_exp_k15_(_e5);
    float g_inv = ((1.0 + _e6) + _e9);
    return (1.0 / (((g_inv * 4.0) * _e4) * _e5));
}

float3 weft_sheen_charlie_k10_(float3 sheen_color_1, float n_dot_h_1, float n_dot_v_1, float n_dot_l_1)
{
    const float _e5 = weft_d_charlie_k12_(n_dot_h_1);
    const float _e6 = weft_v_charlie_k13_(n_dot_v_1, n_dot_l_1);
    float lobe = (_e5 * _e6);
    return (max(sheen_color_1, (0.0).xxx) * (lobe * saturate(n_dot_l_1)));
}

float weft_specular_mip_k14_()
{
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.19774564 * max_mip);
}

float3 weft_prefiltered_radiance_k11_(float3 dir)
{
    const float _e4 = weft_specular_mip_k14_();
    float4 c_1 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, (0.0).xxx);
}

VertexOutput_vs_main vs_main(WeftVertexInput in_)
{
    const WeftVaryings _e1 = weft_forward_vertex(in_);
    const WeftVaryings weftvaryings_1 = _e1;
    const VertexOutput_vs_main weftvaryings_1_ = { weftvaryings_1.world_position, weftvaryings_1.world_normal, weftvaryings_1.world_tangent, weftvaryings_1.uv0_, weftvaryings_1.clip_position };
    return weftvaryings_1_;
}

float4 fs_main(FragmentInput_fs_main fragmentinput_fs_main) : SV_Target0
{
    WeftVaryings in_1 = { fragmentinput_fs_main.clip_position_1, fragmentinput_fs_main.world_position_3, fragmentinput_fs_main.world_normal_2, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_1 };
    float3 n = (float3)0;
    float3 color = (float3)0;
    float3 sheen = (float3)0;
    float scaling = (float)0;

    const WeftSurface _e11 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_5 = _e11.v;
    n = _e11.n;
    float3 _e15 = n;
    const WeftLightGeometry _e16 = weft_main_light_geometry(_e15, v_5);
    float l_dot_h = saturate(dot(_e16.l, _e16.h));
    float3 _e24 = n;
    const float3 _e25 = weft_sh_irradiance(_e24);
    {
        float4 _e29 = material.scatter_color;
        float3 sheen_color_2 = saturate((float3(0.04, 0.04, 0.04) + max(_e29.xyz, (0.0).xxx)));
        const float _e37 = weft_sheen_albedo_k9_(_e16.n_dot_v);
        const float _e38 = weft_sheen_albedo_scaling_view(sheen_color_2, _e37);
        {
            const float3 _e44 = weft_sheen_charlie_k10_(sheen_color_2, _e16.n_dot_h, _e16.n_dot_v, _e16.n_dot_l);
            sheen = _e44;
            scaling = _e38;
        }
        float _e46 = scaling;
        float3 base_direct = (float3(0.015915554, 0.038197216, 0.095493145) * (_e46 * _e16.n_dot_l));
        float3 _e50 = sheen;
        float3 direct = ((_e50 + base_direct) * float3(3.0, 2.8799999, 2.6999998));
        float3 _e54 = n;
        const float3 _e56 = weft_prefiltered_radiance_k11_(reflect(-(v_5), _e54));
        float3 env_sheen = ((_e56 * sheen_color_2) * _e37);
        color = ((direct + ((_e25 * float3(0.050000187, 0.120000094, 0.30000058)) * _e38)) + env_sheen);
    }
    float3 _e63 = color;
    float3 radiance = clamp(_e63, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
