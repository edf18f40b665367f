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

struct SilkLobe {
    float value;
    int _pad1_0;
    float2 alpha;
    float ibl_roughness;
    int _end_pad_0;
};

typedef float4 ret_Constructarray9_float4_[9];
ret_Constructarray9_float4_ Constructarray9_float4_(float4 arg0, float4 arg1, float4 arg2, float4 arg3, float4 arg4, float4 arg5, float4 arg6, float4 arg7, float4 arg8) {
    float4 ret[9] = { arg0, arg1, arg2, arg3, arg4, arg5, arg6, arg7, arg8 };
    return ret;
}

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const uint ANISO_MODEL_WARD = 0u;
static const uint ANISO_MODEL_HAIR_SHIFTED = 1u;
static const uint ANISO_MODEL_GGX = 2u;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SEED = 2u;
static const uint TIER_LOW = 3u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float WEFT_MIN_ANISO_ALPHA = 0.001;
static const float SILK_MIN_ALPHA = 0.001;
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

float3 weft_any_perpendicular(float3 n)
{
    float s = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n.z));
    float b = ((n.x * n.y) * a);
    return float3((1.0 + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
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
    float2 uv = float2(saturate(n_dot_v), saturate(roughness_2));
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv, 0.0);
    return _e8.xy;
}

float3 weft_safe_normalize_k10_(float3 v_1)
{
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * rsqrt(max(len2_1, 1e-20))) : float3(0.0, 0.0, 1.0));
}

float3 weft_view_direction_k2_(float3 world_position)
{
    float4 _e4 = weft_frame.camera_position;
    const float3 _e7 = weft_safe_normalize_k10_((_e4.xyz - world_position));
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

float3x3 weft_tangent_frame(float3 n_3, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_3 * dot(n_3, t_in)));
    float len2_3 = dot(t_proj, t_proj);
    bool ok = (len2_3 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_3);
    float3 t = (ok ? (t_proj * rsqrt(max(len2_3, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_3, t) * s_1);
    return float3x3(t, b_1, n_3);
}

float3 weft_aniso_to_frame(float3x3 frame, float3 x_1)
{
    return float3(dot(frame[0], x_1), dot(frame[1], x_1), dot(frame[2], x_1));
}

float3 weft_aniso_bent_normal(float3x3 frame_1, float3 v_4, float anisotropy, float roughness_3)
{
    float k = clamp(anisotropy, -1.0, 1.0);
    float3 n_4 = frame_1[2];
    float3 dir_1 = ((k >= 0.0) ? frame_1[1] : frame_1[0]);
    float3 aniso_t = cross(dir_1, v_4);
    float3 aniso_n = cross(aniso_t, dir_1);
    float bend = (abs(k) * saturate((5.0 * saturate(roughness_3))));
    const float3 _e22 = weft_safe_normalize(lerp(n_4, aniso_n, bend), n_4);
    return _e22;
}

float silk_lobe_anisotropy(float2 alpha)
{
    float at = max(alpha.x, SILK_MIN_ALPHA);
    float ab = max(alpha.y, SILK_MIN_ALPHA);
    return ((at - ab) / (at + ab));
}

float3 weft_f_schlick_k7_(float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (float3(0.04, 0.04, 0.04) + (float3(0.96, 0.96, 0.96) * _e5));
}

float3 weft_env_brdf_from_lut_k9_(float2 scale_bias)
{
    float2 sb = saturate(scale_bias);
    return ((float3(0.04, 0.04, 0.04) * sb.x) + (sb.y).xxx);
}

float3 weft_normal_from_tangent_space_k12_(float3x3 frame_2)
{
    const float3 _e4 = weft_safe_normalize(mul(float3(float2(0.003921628, 0.003921628), 1.0), frame_2), frame_2[2]);
    return _e4;
}

float weft_v_smith_ggx_aniso_correlated_k13_(float3 v_5, float3 l)
{
    const float _e5 = weft_clamp_cos(v_5.z);
    const float _e7 = weft_clamp_cos(l.z);
    float lv = (_e7 * length(float3((0.23174134 * v_5.x), (0.06475432 * v_5.y), _e5)));
    float ll = (_e5 * length(float3((0.23174134 * l.x), (0.06475432 * l.y), _e7)));
    return (0.5 / (lv + ll));
}

float weft_aniso_ggx_q_k15_(float t_dot_h, float b_dot_h, float n_dot_h)
{
    float x_2 = (t_dot_h / 0.23174134);
    float y = (b_dot_h / 0.06475432);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 1e-6);
}

float weft_d_ggx_aniso_k14_(float t_dot_h_1, float b_dot_h_1, float n_dot_h_1)
{
    const float _e7 = weft_aniso_ggx_q_k15_(t_dot_h_1, b_dot_h_1, n_dot_h_1);
    float d = (1.0 / ((0.047143534 * _e7) * _e7));
    return ((n_dot_h_1 > 0.0) ? d : 0.0);
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
    float3 fibre = (float3)0;
    SilkLobe lobe = (SilkLobe)0;
    float vis = (float)0;
    float3 env_brdf = (float3)0;
    float3 ambient_kd = (float3)0;
    float3 reflect_n = (float3)0;

    const WeftSurface _e11 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_6 = _e11.v;
    float3 n_geo = _e11.n;
    const float3x3 _e15 = weft_tangent_frame(n_geo, in_1.world_tangent);
    const float3 _e17 = weft_normal_from_tangent_space_k12_(_e15);
    fibre = _e15[0];
    float3 _e20 = fibre;
    const float3x3 _e24 = weft_tangent_frame(_e17, float4(_e20, in_1.world_tangent.w));
    const WeftLightGeometry _e25 = weft_main_light_geometry(_e17, v_6);
    const float3 _e26 = weft_aniso_to_frame(_e24, v_6);
    const float3 _e28 = weft_aniso_to_frame(_e24, _e25.l);
    const float3 _e30 = weft_aniso_to_frame(_e24, _e25.h);
    {
        {
            lobe.alpha = float2(0.23174134, 0.06475432);
            lobe.ibl_roughness = 0.35000002;
            {
                {
                    const float _e37 = weft_v_smith_ggx_aniso_correlated_k13_(_e26, _e28);
                    vis = _e37;
                }
                const float _e42 = weft_d_ggx_aniso_k14_(_e30.x, _e30.y, _e30.z);
                float _e43 = vis;
                lobe.value = ((_e42 * _e43) * _e25.n_dot_l);
            }
        }
    }
    float n_dot_l_diffuse = saturate(dot(n_geo, _e25.l));
    const float3 _e52 = weft_f_schlick_k7_(_e25.v_dot_h);
    float3 diffuse = ((((1.0).xxx - _e52) * float3(0.222817, 0.14323957, 0.031830948)) * n_dot_l_diffuse);
    float _e59 = lobe.value;
    float3 direct = ((diffuse + (_e52 * _e59)) * float3(3.0, 2.8799999, 2.6999998));
    reflect_n = _e17;
    {
        float _e68 = lobe.ibl_roughness;
        const float2 _e69 = weft_env_brdf_lut(_e25.n_dot_v, _e68);
        const float3 _e70 = weft_env_brdf_from_lut_k9_(_e69);
        env_brdf = _e70;
        float3 _e72 = env_brdf;
        ambient_kd = max(((1.0).xxx - _e72), (0.0).xxx);
        float2 _e77 = lobe.alpha;
        const float _e78 = silk_lobe_anisotropy(_e77);
        float _e80 = lobe.ibl_roughness;
        const float3 _e81 = weft_aniso_bent_normal(_e24, v_6, _e78, _e80);
        reflect_n = _e81;
    }
    float3 _e83 = reflect_n;
    float _e86 = lobe.ibl_roughness;
    const float3 _e87 = weft_prefiltered_radiance(reflect(-(v_6), _e83), _e86);
    float3 _e88 = env_brdf;
    const float3 _e90 = weft_sh_irradiance(n_geo);
    float3 _e91 = ambient_kd;
    float3 indirect = ((_e87 * _e88) + ((_e90 * _e91) * float3(0.7000003, 0.4500004, 0.099999875)));
    float3 radiance = clamp((direct + indirect), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
