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

float weft_clamp_cos(float c)
{
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

float3 weft_safe_normalize(float3 v, float3 fallback)
{
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * rsqrt(max(len2_, 1e-20))) : fallback);
}

float3 weft_any_perpendicular(float3 n_1)
{
    float s = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return float3((1.0 + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
}

float3 weft_sh_irradiance(float3 n_2)
{
    float3 e = (float3)0;

    e = float3(0.27778354, 0.32136026, 0.4497644);
    e = (float3(0.27778354, 0.32136026, 0.4497644) + (float3(0.2192843, 0.34164187, 0.663193) * (0.488603 * n_2.y)));
    float3 _e11 = e;
    e = (_e11 + (float3(0.1352113, 0.12394369, 0.10366199) * (0.488603 * n_2.z)));
    float3 _e18 = e;
    e = (_e18 + (float3(-0.14969625, -0.13722156, -0.11476713) * (0.488603 * n_2.x)));
    float3 _e25 = e;
    e = (_e25 + (float3(-0.064625785, -0.059240304, -0.049546435) * ((1.092548 * n_2.x) * n_2.y)));
    float3 _e34 = e;
    e = (_e34 + (float3(0.05837178, 0.053507466, 0.044751696) * ((1.092548 * n_2.y) * n_2.z)));
    float3 _e43 = e;
    e = (_e43 + (float3(0.025110306, 0.023586905, 0.01273896) * (0.315392 * (((3.0 * n_2.z) * n_2.z) - 1.0))));
    float3 _e56 = e;
    e = (_e56 + (float3(-0.06322707, -0.057958152, -0.04847409) * ((1.092548 * n_2.x) * n_2.z)));
    float3 _e65 = e;
    e = (_e65 + (float3(0.056382716, 0.05266991, 0.031947177) * (0.546274 * ((n_2.x * n_2.x) - (n_2.y * n_2.y)))));
    float3 _e78 = e;
    return max(_e78, (0.0).xxx);
}

float3 weft_safe_normalize_k12_(float3 v_1)
{
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * rsqrt(max(len2_1, 1e-20))) : float3(0.0, 0.0, 1.0));
}

float3 weft_view_direction_k2_(float3 world_position)
{
    float4 _e4 = weft_frame.camera_position;
    const float3 _e7 = weft_safe_normalize_k12_((_e4.xyz - world_position));
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

WeftLightGeometry weft_main_light_geometry(float3 n_3, float3 v_2)
{
    const float3 _e4 = weft_safe_normalize((float3(-0.61984503, 0.54986256, 0.55986005) + v_2), n_3);
    const float _e6 = weft_clamp_cos(dot(n_3, v_2));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(float3(-0.61984503, 0.54986256, 0.55986005), _e4, _e6, saturate(dot(n_3, float3(-0.61984503, 0.54986256, 0.55986005))), saturate(dot(n_3, _e4)), saturate(dot(v_2, _e4)));
    return weftlightgeometry;
}

float3 weft_safe_normalize_k3_(float3 v_3)
{
    float len2_2 = dot(v_3, v_3);
    return ((len2_2 > 1e-20) ? (v_3 * rsqrt(max(len2_2, 1e-20))) : (0.0).xxx);
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

float3x3 weft_tangent_frame(float3 n_4, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_4 * dot(n_4, t_in)));
    float len2_3 = dot(t_proj, t_proj);
    bool ok = (len2_3 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_4);
    float3 t = (ok ? (t_proj * rsqrt(max(len2_3, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_4, t) * s_1);
    return float3x3(t, b_1, n_4);
}

float3 weft_normal_from_tangent_space_k18_(float3x3 frame)
{
    const float3 _e4 = weft_safe_normalize(mul(float3(float2(0.003921628, 0.003921628), 1.0), frame), frame[2]);
    return _e4;
}

float3 weft_mapped_normal_k6_(float3 n_5, float4 tangent_1)
{
    const float3x3 _e4 = weft_tangent_frame(n_5, tangent_1);
    const float3 _e5 = weft_normal_from_tangent_space_k18_(_e4);
    return _e5;
}

float weft_sheen_albedo_scaling_view_k8_(float e_v)
{
    return saturate((1.0 - (0.46167183 * saturate(e_v))));
}

float weft_sheen_albedo_scaling_k10_(float e_v_1, float e_l)
{
    return saturate(min((1.0 - (0.46167183 * saturate(e_v_1))), (1.0 - (0.46167183 * saturate(e_l)))));
}

float weft_sheen_albedo_k15_(float n_dot_x)
{
    float2 uv = float2(saturate(n_dot_x), 0.39999998);
    float4 _e8 = weft_sheen_lut.SampleLevel(weft_lut_sampler, uv, 0.0);
    return saturate(_e8.x);
}

float weft_d_charlie_k19_(float n_dot_h)
{
    float noh = saturate(n_dot_h);
    float sin2_ = max(((1.0 - noh) * (1.0 + noh)), 0.0);
    return ((4.5 * pow(sin2_, 1.2500001)) * 0.15915494);
}

float weft_sheen_l_k23_(float x)
{
    return (((22.907091 / (1.0 + (3.647883 * pow(max(x, 0.0), 0.1873508)))) + (-1.7242787 * x)) + -4.514627);
}

float weft_sheen_lambda_one_exp_k22_(float cos_theta)
{
    const float _e2 = weft_clamp_cos(cos_theta);
    bool low = (_e2 < 0.5);
    const float _e8 = weft_sheen_l_k23_((low ? _e2 : (1.0 - _e2)));
    return exp((low ? _e8 : (0.1451807 - _e8)));
}

float weft_v_charlie_k20_(float n_dot_v, float n_dot_l)
{
    const float _e4 = weft_clamp_cos(n_dot_v);
    const float _e5 = weft_clamp_cos(n_dot_l);
    const float _e6 = weft_sheen_lambda_one_exp_k22_(_e4);
    const float _e9 = weft_sheen_lambda_one_exp_k22_(_e5);
    float g_inv = ((1.0 + _e6) + _e9);
    return (1.0 / (((g_inv * 4.0) * _e4) * _e5));
}

float3 weft_sheen_charlie_k16_(float n_dot_h_1, float n_dot_v_1, float n_dot_l_1)
{
    const float _e5 = weft_d_charlie_k19_(n_dot_h_1);
    const float _e6 = weft_v_charlie_k20_(n_dot_v_1, n_dot_l_1);
    float lobe = (_e5 * _e6);
    return (float3(0.46167183, 0.07633493, 0.16470811) * (lobe * saturate(n_dot_l_1)));
}

float weft_specular_mip_k21_()
{
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.568 * max_mip);
}

float3 weft_prefiltered_radiance_k17_(float3 dir)
{
    const float _e4 = weft_specular_mip_k21_();
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
    float3 v_4 = _e11.v;
    n = _e11.n;
    {
        float3 _e16 = n;
        const float3 _e18 = weft_mapped_normal_k6_(_e16, in_1.world_tangent);
        n = _e18;
    }
    float3 _e19 = n;
    const WeftLightGeometry _e20 = weft_main_light_geometry(_e19, v_4);
    float l_dot_h = saturate(dot(_e20.l, _e20.h));
    float3 _e28 = n;
    const float3 _e29 = weft_sh_irradiance(_e28);
    {
        const float _e34 = weft_sheen_albedo_k15_(_e20.n_dot_v);
        const float _e35 = weft_sheen_albedo_scaling_view_k8_(_e34);
        {
            const float _e39 = weft_sheen_albedo_k15_(_e20.n_dot_l);
            const float3 _e43 = weft_sheen_charlie_k16_(_e20.n_dot_h, _e20.n_dot_v, _e20.n_dot_l);
            sheen = _e43;
            const float _e44 = weft_sheen_albedo_scaling_k10_(_e34, _e39);
            scaling = _e44;
        }
        float _e46 = scaling;
        float3 base_direct = (float3(0.0, 0.0, 0.0) * (_e46 * _e20.n_dot_l));
        float3 _e50 = sheen;
        float3 direct = ((_e50 + base_direct) * float3(3.2, 3.05, 2.8));
        float3 _e54 = n;
        const float3 _e56 = weft_prefiltered_radiance_k17_(reflect(-(v_4), _e54));
        float3 env_sheen = ((_e56 * float3(0.46167183, 0.07633493, 0.16470811)) * _e34);
        color = ((direct + ((_e29 * float3(0.0, 0.0, 0.0)) * _e35)) + env_sheen);
    }
    float3 _e63 = color;
    float3 radiance = clamp(_e63, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
