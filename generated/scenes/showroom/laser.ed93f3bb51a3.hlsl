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

struct WeftFilmStack {
    float n2_;
    float cos2_;
    float2 r12_;
    float3 r23_[2];
    int _pad4_0;
    bool total_internal_reflection;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct WeftFilmSeries {
    float3 dc;
    int _pad1_0;
    float3 first;
    int _pad2_0;
    float3 ratio;
    int _end_pad_0;
};

typedef float4 ret_Constructarray9_float4_[9];
ret_Constructarray9_float4_ Constructarray9_float4_(float4 arg0, float4 arg1, float4 arg2, float4 arg3, float4 arg4, float4 arg5, float4 arg6, float4 arg7, float4 arg8) {
    float4 ret[9] = { arg0, arg1, arg2, arg3, arg4, arg5, arg6, arg7, arg8 };
    return ret;
}

typedef float3 ret_Constructarray2_float3_[2];
ret_Constructarray2_float3_ Constructarray2_float3_(float3 arg0, float3 arg1) {
    float3 ret[2] = { arg0, arg1 };
    return ret;
}

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const float film_sensitivity_opd_max = 16000.0;
static const uint COLOR_MODE_HUE_RING = 0u;
static const uint COLOR_MODE_CUSTOM = 1u;
static const uint ANISO_COLOR_OFF = 0u;
static const uint ANISO_COLOR_VALUE = 1u;
static const uint ANISO_COLOR_MAP = 2u;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SEED = 2u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float WEFT_FILM_PI = 3.1415927;
static const uint WEFT_FILM_SAMPLES = 101u;
static const float WEFT_FILM_LAMBDA_MIN = 380.0;
static const float WEFT_FILM_LAMBDA_MAX = 780.0;
static const float WEFT_FILM_FADE_NM = 30.0;
static const float3x3 WEFT_XYZ_TO_REC709_ = float3x3(float3(3.2404542, -0.969266, 0.0556434), float3(-1.5371385, 1.8760108, -0.2040259), float3(-0.4985314, 0.041556, 1.0572252));

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
#define material_clamp_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[2]])
Texture2D<float4> film_sensitivity : register(t9, space1);

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

float4 table_film_sensitivity(float2 uv)
{
    float2 st = (((clamp(uv, (0.0).xx, (1.0).xx) * float2(2047.0, 1.0)) + (0.5).xx) / float2(2048.0, 2.0));
    float4 _e13 = film_sensitivity.SampleLevel(material_clamp_sampler, st, 0.0);
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

float3 weft_safe_normalize_k11_(float3 v_1)
{
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * rsqrt(max(len2_1, 1e-20))) : float3(0.0, 0.0, 1.0));
}

float3 weft_view_direction_k2_(float3 world_position)
{
    float4 _e4 = weft_frame.camera_position;
    const float3 _e7 = weft_safe_normalize_k11_((_e4.xyz - world_position));
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

float2 weft_fresnel_amplitudes_k4_(float n_t, float cos_i, float cos_t)
{
    float rs = ((cos_i - (n_t * cos_t)) / max((cos_i + (n_t * cos_t)), 1e-12));
    float rp = (((n_t * cos_i) - cos_t) / max(((n_t * cos_i) + cos_t), 1e-12));
    return float2(rs, rp);
}

float3 weft_film_sensitivity(float opd_nm)
{
    const float4 _e5 = table_film_sensitivity(float2((opd_nm / film_sensitivity_opd_max), 0.0));
    return _e5.xyz;
}

float3 weft_film_orders(float opd_nm_1, WeftFilmSeries s, WeftFilmSeries p)
{
    float3 k1_ = ((s.first * s.ratio) + (p.first * p.ratio));
    float3 k2_ = (((s.first * s.ratio) * s.ratio) + ((p.first * p.ratio) * p.ratio));
    float3 k3_ = ((((s.first * s.ratio) * s.ratio) * s.ratio) + (((p.first * p.ratio) * p.ratio) * p.ratio));
    float3 k4_ = (((s.first * (s.ratio * s.ratio)) * (s.ratio * s.ratio)) + ((p.first * (p.ratio * p.ratio)) * (p.ratio * p.ratio)));
    const float3 _e55 = weft_film_sensitivity(opd_nm_1);
    const float3 _e59 = weft_film_sensitivity((2.0 * opd_nm_1));
    const float3 _e64 = weft_film_sensitivity((3.0 * opd_nm_1));
    const float3 _e69 = weft_film_sensitivity((4.0 * opd_nm_1));
    float3 sum = ((((k1_ * _e55) + (k2_ * _e59)) + (k3_ * _e64)) + (k4_ * _e69));
    return (2.0 * sum);
}

WeftFilmSeries ConstructWeftFilmSeries(float3 arg0, float3 arg1, float3 arg2) {
    WeftFilmSeries ret = (WeftFilmSeries)0;
    ret.dc = arg0;
    ret.first = arg1;
    ret.ratio = arg2;
    return ret;
}

WeftFilmSeries weft_film_series(float r12_, float3 r23_)
{
    float big_r12_ = (r12_ * r12_);
    float t121_ = (1.0 - big_r12_);
    float3 big_r23_ = (r23_ * r23_);
    float3 big_r123_ = min((big_r12_ * big_r23_), (0.9999).xxx);
    float3 rs_1 = (((t121_ * t121_) * big_r23_) / ((1.0).xxx - big_r123_));
    float3 ratio = clamp((-(r12_) * r23_), (-0.99995).xxx, (0.99995).xxx);
    const WeftFilmSeries weftfilmseries = ConstructWeftFilmSeries(((big_r12_).xxx + rs_1), (rs_1 - (t121_).xxx), ratio);
    return weftfilmseries;
}

float2 weft_env_brdf_lut_k6_(float n_dot_v)
{
    float2 uv_1 = float2(saturate(n_dot_v), 0.2);
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv_1, 0.0);
    return _e8.xy;
}

float weft_film_ior_k19_()
{
    return lerp(1.0, 1.8, smoothstep(0.0, WEFT_FILM_FADE_NM, 420.0));
}

float weft_v_smith_ggx_correlated_k8_(float n_dot_v_1, float n_dot_l)
{
    const float _e6 = weft_clamp_cos(n_dot_v_1);
    const float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * 0.9984) + 0.0016000002)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * 0.9984) + 0.0016000002)));
    return (0.5 / (lv + ll));
}

float weft_d_ggx_nh_k9_(float3 n_3, float3 h)
{
    float noh = saturate(dot(n_3, h));
    float3 nxh = cross(n_3, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * 0.0016000002));
    return (0.0016000002 / (WEFT_PI * max((d * d), 1e-30)));
}

float weft_specular_mip_k14_()
{
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.312 * max_mip);
}

float3 weft_prefiltered_radiance_k10_(float3 dir)
{
    const float _e4 = weft_specular_mip_k14_();
    float4 c_1 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, (0.0).xxx);
}

float3 weft_f_schlick_k15_(float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (float3(0.8999996, 0.8999996, 0.8999996) + (float3(0.10000038, 0.10000038, 0.10000038) * _e5));
}

float3 weft_env_brdf_from_lut_k16_(float2 scale_bias)
{
    float2 sb = saturate(scale_bias);
    return ((float3(0.8999996, 0.8999996, 0.8999996) * sb.x) + (sb.y).xxx);
}

typedef float3 ret_weft_film_base_amplitudes_k22_[2];
ret_weft_film_base_amplitudes_k22_ weft_film_base_amplitudes_k22_(float n2_, float cos2_, float sin1_sq)
{
    float3 cos3_ = sqrt(max(((1.0).xxx - ((sin1_sq).xxx / float3(1441.9869, 1441.9869, 1441.9869))), (0.0).xxx));
    float3 s_1 = ((((n2_ * cos2_)).xxx - (float3(37.973503, 37.973503, 37.973503) * cos3_)) / max((((n2_ * cos2_)).xxx + (float3(37.973503, 37.973503, 37.973503) * cos3_)), (1e-12).xxx));
    float3 p_1 = (((float3(37.973503, 37.973503, 37.973503) * cos2_) - ((n2_).xxx * cos3_)) / max(((float3(37.973503, 37.973503, 37.973503) * cos2_) + ((n2_).xxx * cos3_)), (1e-12).xxx));
    return Constructarray2_float3_(s_1, p_1);
}

WeftFilmStack ConstructWeftFilmStack(float arg0, float arg1, float2 arg2, float3 arg3[2], bool arg4) {
    WeftFilmStack ret = (WeftFilmStack)0;
    ret.n2_ = arg0;
    ret.cos2_ = arg1;
    ret.r12_ = arg2;
    ret.r23_ = arg3;
    ret.total_internal_reflection = arg4;
    return ret;
}

WeftFilmStack weft_film_stack_k20_(float cos_theta1_)
{
    float cos1_ = clamp(cos_theta1_, 0.0, 1.0);
    float sin1_sq_1 = (1.0 - (cos1_ * cos1_));
    const float _e10 = weft_film_ior_k19_();
    float cos2_sq = (1.0 - (sin1_sq_1 / (_e10 * _e10)));
    if ((cos2_sq <= 0.0)) {
        const WeftFilmStack weftfilmstack = ConstructWeftFilmStack(_e10, 0.0, (1.0).xx, Constructarray2_float3_((1.0).xxx, (1.0).xxx), true);
        return weftfilmstack;
    }
    float cos2_1 = sqrt(cos2_sq);
    const float2 _e23 = weft_fresnel_amplitudes_k4_(_e10, cos1_, cos2_1);
    const float3 _e24[2] = weft_film_base_amplitudes_k22_(_e10, cos2_1, sin1_sq_1);
    const WeftFilmStack weftfilmstack_1 = ConstructWeftFilmStack(_e10, cos2_1, _e23, _e24, false);
    return weftfilmstack_1;
}

float3 weft_film_fourier_layers_k17_(float cos_theta1_1)
{
    const WeftFilmStack _e6 = weft_film_stack_k20_(cos_theta1_1);
    if (_e6.total_internal_reflection) {
        return (1.0).xxx;
    }
    const WeftFilmSeries _e13 = weft_film_series(_e6.r12_.x, _e6.r23_[0]);
    const WeftFilmSeries _e18 = weft_film_series(_e6.r12_.y, _e6.r23_[1]);
    float path = ((2.0 * _e6.n2_) * _e6.cos2_);
    const float3 _e29 = weft_film_orders((path * 420.0), _e13, _e18);
    float3 r1_ = ((_e13.dc + _e18.dc) + _e29);
    const float3 _e36 = weft_film_orders((path * 420.0), _e13, _e18);
    float3 r2_ = ((_e13.dc + _e18.dc) + _e36);
    return clamp((0.25 * (r1_ + r2_)), (0.0).xxx, (1.0).xxx);
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
    float film_cos = (float)0;
    float2 direction_ts = float2(1.0, 0.0);
    float3 surface_base = (float3)0;
    float3 f_light = (float3)0;
    float3 e_spec = (float3)0;
    float light_cos = (float)0;
    float3 film_view = (float3)0;
    float3 film_light = (float3)0;

    const WeftSurface _e11 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_4 = _e11.v;
    float3 geometric_n = _e11.n;
    n = geometric_n;
    float3 _e15 = n;
    const WeftLightGeometry _e16 = weft_main_light_geometry(_e15, v_4);
    film_cos = _e16.n_dot_v;
    const float2 _e23 = weft_env_brdf_lut_k6_(_e16.n_dot_v);
    const float3 _e25 = weft_f_schlick_k15_(_e16.v_dot_h);
    f_light = _e25;
    const float3 _e27 = weft_env_brdf_from_lut_k16_(_e23);
    e_spec = _e27;
    {
        light_cos = _e16.v_dot_h;
        {
            float _e36 = film_cos;
            const float3 _e37 = weft_film_fourier_layers_k17_(_e36);
            film_view = _e37;
            float _e38 = light_cos;
            const float3 _e39 = weft_film_fourier_layers_k17_(_e38);
            film_light = _e39;
        }
        float3 _e40 = f_light;
        float3 _e41 = film_light;
        f_light = lerp(_e40, _e41, 1.0);
        float3 _e43 = e_spec;
        float3 _e44 = film_view;
        e_spec = lerp(_e43, (_e44 * (_e23.x + _e23.y)), 1.0);
    }
    float3 _e51 = e_spec;
    float3 kd = max(((1.0).xxx - _e51), (0.0).xxx);
    const float _e57 = weft_v_smith_ggx_correlated_k8_(_e16.n_dot_v, _e16.n_dot_l);
    float3 _e58 = n;
    const float _e60 = weft_d_ggx_nh_k9_(_e58, _e16.h);
    float3 _e62 = f_light;
    float3 specular = ((_e60 * _e57) * _e62);
    float3 diffuse = (kd * float3(0.0, 0.0, 0.0));
    float3 direct = (((diffuse + specular) * float3(3.0, 2.8799999, 2.6999998)) * _e16.n_dot_l);
    float3 _e72 = n;
    const float3 _e74 = weft_prefiltered_radiance_k10_(reflect(-(v_4), _e72));
    float3 _e75 = e_spec;
    float3 indirect_specular = (_e74 * _e75);
    float3 _e77 = n;
    const float3 _e78 = weft_sh_irradiance(_e77);
    float3 indirect_diffuse = ((_e78 * kd) * float3(0.0, 0.0, 0.0));
    float3 color = ((direct + indirect_specular) + indirect_diffuse);
    return float4(clamp(color, (0.0).xxx, (65504.0).xxx), 1.0);
}
