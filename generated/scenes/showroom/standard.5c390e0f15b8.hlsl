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
static const uint SPHERE_MAP_OFF = 0u;
static const uint SPHERE_MAP_ADD = 1u;
static const uint SPHERE_MAP_MULTIPLY = 2u;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SEED = 2u;
static const uint TIER_LOW = 3u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float WEFT_MIN_ROUGHNESS_HALF = 0.089;
static const float WEFT_MIN_N_DOT_HALF = 0.001;
static const float WEFT_MIN_ALPHA_HALF = 0.007921;

cbuffer weft_frame : register(b0) { WeftFrame weft_frame; }
TextureCube<float4> weft_environment : register(t1);
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup0SamplerIndexArray : register(t64, space0);
#define weft_environment_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[2]])
Texture2D<float4> weft_brdf_lut : register(t3);
#define weft_lut_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[4]])
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }

struct VertexOutput_vs_main {
    float3 world_position_3 : LOC0;
    float3 world_normal_1 : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    float4 clip_position : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_4 : LOC0;
    float3 world_normal_2 : LOC1;
    float4 world_tangent_1 : LOC2;
    float2 uv0_1 : LOC3;
    float4 clip_position_1 : SV_Position;
    bool front_facing_2 : SV_IsFrontFace;
};

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

float3 weft_safe_normalize_k13_(float3 v_1)
{
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * rsqrt(max(len2_1, 1e-20))) : float3(0.0, 0.0, 1.0));
}

float3 weft_view_direction_k2_(float3 world_position)
{
    float4 _e4 = weft_frame.camera_position;
    const float3 _e7 = weft_safe_normalize_k13_((_e4.xyz - world_position));
    return _e7;
}

WeftSurface ConstructWeftSurface(float3 arg0, float3 arg1) {
    WeftSurface ret = (WeftSurface)0;
    ret.v = arg0;
    ret.n = arg1;
    return ret;
}

WeftSurface weft_surface_two_sided(float3 world_position_1, float3 world_normal, bool front_facing_1)
{
    const float3 _e3 = weft_view_direction_k2_(world_position_1);
    float3 facing = (front_facing_1 ? world_normal : -(world_normal));
    const float3 _e6 = weft_safe_normalize(facing, _e3);
    const WeftSurface weftsurface = ConstructWeftSurface(_e3, _e6);
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
    const float3 _e4 = weft_safe_normalize((float3(-0.61984503, 0.54986256, 0.55986005) + v_2), n_2);
    const float _e6 = weft_clamp_cos(dot(n_2, v_2));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(float3(-0.61984503, 0.54986256, 0.55986005), _e4, _e6, saturate(dot(n_2, float3(-0.61984503, 0.54986256, 0.55986005))), saturate(dot(n_2, _e4)), saturate(dot(v_2, _e4)));
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

float3 standard_sphere_map(float3 color_in, float3 n_3, float3 world_position_2)
{
    float3 color = (float3)0;

    color = color_in;
    float3 _e4 = color;
    return _e4;
}

float weft_v_smith_ggx_correlated_newton_k5_(float n_dot_v, float n_dot_l)
{
    const float _e6 = weft_clamp_cos(n_dot_v);
    const float _e7 = weft_clamp_cos(n_dot_l);
    float gv = ((_e6 * 0.7975) + 0.20249999);
    float gl = ((_e7 * 0.7975) + 0.20249999);
    float pv = ((gv * _e6) + (0.041006245 * (1.0 - _e6)));
    float pl = ((gl * _e7) + (0.041006245 * (1.0 - _e7)));
    return (((0.5 * gv) * gl) / (((_e7 * gl) * pv) + ((_e6 * gv) * pl)));
}

float2 weft_env_brdf_lut_k6_(float n_dot_v_1)
{
    float2 uv = float2(saturate(n_dot_v_1), 0.45);
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv, 0.0);
    return _e8.xy;
}

float3 weft_env_brdf_from_lut_k7_(float2 scale_bias)
{
    float2 sb = saturate(scale_bias);
    return ((float3(0.04, 0.04, 0.04) * sb.x) + (sb.y).xxx);
}

float3 weft_f_schlick_k8_(float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (float3(0.04, 0.04, 0.04) + (float3(0.96, 0.96, 0.96) * _e5));
}

float weft_d_ggx_k9_(float n_dot_h)
{
    float noh = saturate(n_dot_h);
    float one_minus_noh2_ = ((1.0 - noh) * (1.0 + noh));
    float d_1 = (one_minus_noh2_ + ((noh * noh) * 0.041006245));
    return (0.041006245 / ((WEFT_PI * d_1) * d_1));
}

float weft_specular_mip_k15_()
{
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.62325 * max_mip);
}

float3 weft_prefiltered_radiance_k10_(float3 dir)
{
    const float _e4 = weft_specular_mip_k15_();
    float4 c_1 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, (0.0).xxx);
}

void standard_alpha_test_k12_()
{
    {
        return;
    }
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
    WeftVaryings in_1 = { fragmentinput_fs_main.clip_position_1, fragmentinput_fs_main.world_position_4, fragmentinput_fs_main.world_normal_2, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_1 };
    bool front_facing = fragmentinput_fs_main.front_facing_2;
    float3 n = (float3)0;
    float visibility = (float)0;
    float3 env_brdf = (float3)0;
    float3 ambient_kd = (float3)0;
    float3 direct_kd = (float3)0;
    float3 specular = (0.0).xxx;
    float3 indirect_specular = (0.0).xxx;
    float d = (float)0;

    const WeftSurface _e13 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    float3 v_4 = _e13.v;
    n = _e13.n;
    float3 _e17 = n;
    const WeftLightGeometry _e18 = weft_main_light_geometry(_e17, v_4);
    {
        {
            const float _e27 = weft_v_smith_ggx_correlated_newton_k5_(_e18.n_dot_v, _e18.n_dot_l);
            visibility = _e27;
            const float2 _e29 = weft_env_brdf_lut_k6_(_e18.n_dot_v);
            const float3 _e30 = weft_env_brdf_from_lut_k7_(_e29);
            env_brdf = _e30;
            float3 _e32 = env_brdf;
            ambient_kd = max(((1.0).xxx - _e32), (0.0).xxx);
            float3 _e36 = ambient_kd;
            direct_kd = _e36;
        }
    }
    {
        const float3 _e42 = weft_f_schlick_k8_(_e18.v_dot_h);
        {
            const float _e45 = weft_d_ggx_k9_(_e18.n_dot_h);
            d = _e45;
        }
        float _e46 = d;
        float _e47 = visibility;
        specular = (((_e46 * _e47) * _e42) * 0.5);
        float3 _e52 = n;
        const float3 _e54 = weft_prefiltered_radiance_k10_(reflect(-(v_4), _e52));
        float3 _e55 = env_brdf;
        indirect_specular = ((_e54 * _e55) * 0.5);
    }
    float3 _e59 = direct_kd;
    float3 diffuse = (_e59 * float3(0.101859, 0.06366192, 0.038197216));
    float3 _e62 = specular;
    float3 direct = (((diffuse + _e62) * float3(3.0, 2.8799999, 2.6999998)) * _e18.n_dot_l);
    float3 _e68 = n;
    const float3 _e69 = weft_sh_irradiance(_e68);
    float3 _e70 = ambient_kd;
    float3 indirect_diffuse = ((_e69 * _e70) * float3(0.31999952, 0.19999982, 0.120000094));
    float3 _e73 = indirect_specular;
    float3 color_1 = ((direct + _e73) + indirect_diffuse);
    float3 _e76 = n;
    const float3 _e78 = standard_sphere_map(color_1, _e76, in_1.world_position);
    float3 radiance = clamp((_e78 + (0.0).xxx), (0.0).xxx, (65504.0).xxx);
    standard_alpha_test_k12_();
    return float4(radiance, 1.0);
}
