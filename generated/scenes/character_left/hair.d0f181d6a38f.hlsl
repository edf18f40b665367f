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

struct WeftFringeShadowVertex {
    float3 position : LOC0;
};

struct WeftFringeShadowVaryings {
    float4 clip_position : SV_Position;
};

struct WeftSurface {
    float3 v;
    int _pad1_0;
    float3 n;
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

struct WeftHair {
    float3 sigma_a;
    float eta;
    float4 v;
    float s;
    int _pad4_0;
    int _pad4_1;
    int _pad4_2;
    float3 sin2k;
    int _pad5_0;
    float3 cos2k;
    int _end_pad_0;
};

struct WeftHairAttenuation {
    float a0_;
    int _pad1_0;
    int _pad1_1;
    int _pad1_2;
    float3 a1_;
    int _pad2_0;
    float3 a2_;
    int _pad3_0;
    float3 a3_;
    float gamma_t;
};

struct WeftHairLobes {
    float3 s;
    int _pad1_0;
    float3 albedo;
    int _pad2_0;
    float3 back;
    int _end_pad_0;
};

struct WeftHairAngles {
    float4 theta;
    float phi;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SEED = 2u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float WEFT_HAIR_MIN_BETA_M = 0.05;
static const float WEFT_HAIR_MIN_BETA_N = 0.05;
static const uint HAIR_REFERENCE_CELLS = 64u;
static const uint HAIR_FAST_CELLS = 12u;
static const float HAIR_TERMINATOR = 0.25;

cbuffer weft_frame : register(b0) { WeftFrame weft_frame; }
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
Texture2D<float4> jitter_map : register(t5, space1);

struct VertexOutput_vs_outline {
    float4 clip_position : SV_Position;
};

struct VertexOutput_vs_fringe_shadow {
    float4 clip_position_1 : SV_Position;
};

struct VertexOutput_vs_main {
    float3 world_position_2 : LOC0;
    float3 world_normal_1 : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_2 : LOC3;
    float4 clip_position_2 : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_3 : LOC0;
    float3 world_normal_2 : LOC1;
    float4 world_tangent_1 : LOC2;
    float2 uv0_3 : LOC3;
    float4 clip_position_3 : SV_Position;
};

float3 weft_safe_normalize(float3 v, float3 fallback)
{
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * rsqrt(max(len2_, 1e-20))) : fallback);
}

float3 weft_any_perpendicular(float3 n)
{
    float s_8 = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a_1 = (-1.0 / (s_8 + n.z));
    float b = ((n.x * n.y) * a_1);
    return float3((1.0 + (((s_8 * n.x) * n.x) * a_1)), (s_8 * b), (-(s_8) * n.x));
}

float weft_f_dielectric(float cos_i, float eta)
{
    float c = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c * c));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c);
    float gpc = max((g + c), 1e-7);
    float a_2 = (gmc / gpc);
    float b_1 = (((c * gpc) - 1.0) / max(((c * gmc) + 1.0), 1e-7));
    float f = saturate((((0.5 * a_2) * a_2) * (1.0 + (b_1 * b_1))));
    return ((g2_ < 0.0) ? 1.0 : f);
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

float3x3 weft_tangent_frame(float3 n_2, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_2 = dot(t_proj, t_proj);
    bool ok = (len2_2 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_2);
    float3 t_1 = (ok ? (t_proj * rsqrt(max(len2_2, 1e-20))) : _e13);
    float s_9 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_2 = (cross(n_2, t_1) * s_9);
    return float3x3(t_1, b_2, n_2);
}

float weft_hair_sqr(float x)
{
    return (x * x);
}

float weft_hair_safe_sqrt(float x_1)
{
    return sqrt(max(x_1, 0.0));
}

float weft_hair_i0_(float x_2)
{
    float term = 1.0;
    float sum = 1.0;
    int i = int(1);

    float q = ((0.25 * x_2) * x_2);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            int _e22 = i;
            i = asint(asuint(_e22) + asuint(int(1)));
        }
        loop_init = false;
        int _e10 = i;
        if ((_e10 < int(16))) {
        } else {
            break;
        }
        {
            int _e13 = i;
            float k_1 = float(_e13);
            float _e15 = term;
            term = (_e15 * (q / (k_1 * k_1)));
            float _e19 = sum;
            float _e20 = term;
            sum = (_e19 + _e20);
        }
    }
    float _e25 = sum;
    return _e25;
}

float weft_hair_log_i0_(float x_3)
{
    if ((x_3 > 12.0)) {
        float r = (1.0 / x_3);
        return ((x_3 - (0.5 * log((6.2831855 * x_3)))) + log((1.0 + (r * (0.125 + (0.0703125 * r))))));
    }
    const float _e20 = weft_hair_i0_(x_3);
    return log(_e20);
}

float weft_hair_mp(float cos_i_1, float cos_o, float sin_i, float sin_o, float v_2)
{
    float a_3 = ((cos_i_1 * cos_o) / v_2);
    float b_3 = ((sin_i * sin_o) / v_2);
    if ((v_2 <= 0.1)) {
        const float _e11 = weft_hair_log_i0_(a_3);
        return exp(((((_e11 - b_3) - (1.0 / v_2)) + 0.6931472) + log((1.0 / (2.0 * v_2)))));
    }
    const float _e27 = weft_hair_i0_(a_3);
    return ((exp(-(b_3)) * _e27) / ((sinh((1.0 / v_2)) * 2.0) * v_2));
}

float4 weft_hair_longitudinal(WeftHair hair, float sin_o_1, float cos_o_1, float sin_i_1, float cos_i_2)
{
    float sin_r = ((sin_o_1 * hair.cos2k.y) - (cos_o_1 * hair.sin2k.y));
    float cos_r = abs(((cos_o_1 * hair.cos2k.y) + (sin_o_1 * hair.sin2k.y)));
    float sin_tt = ((sin_o_1 * hair.cos2k.x) + (cos_o_1 * hair.sin2k.x));
    float cos_tt = abs(((cos_o_1 * hair.cos2k.x) - (sin_o_1 * hair.sin2k.x)));
    float sin_trt = ((sin_o_1 * hair.cos2k.z) + (cos_o_1 * hair.sin2k.z));
    float cos_trt = abs(((cos_o_1 * hair.cos2k.z) - (sin_o_1 * hair.sin2k.z)));
    const float _e52 = weft_hair_mp(cos_i_2, cos_r, sin_i_1, sin_r, hair.v.x);
    const float _e55 = weft_hair_mp(cos_i_2, cos_tt, sin_i_1, sin_tt, hair.v.y);
    const float _e58 = weft_hair_mp(cos_i_2, cos_trt, sin_i_1, sin_trt, hair.v.z);
    const float _e61 = weft_hair_mp(cos_i_2, cos_o_1, sin_i_1, sin_o_1, hair.v.w);
    return float4(_e52, _e55, _e58, _e61);
}

float weft_hair_logistic(float x_4, float s)
{
    float e_1 = exp((-(abs(x_4)) / s));
    const float _e8 = weft_hair_sqr((1.0 + e_1));
    return (e_1 / (s * _e8));
}

float weft_hair_trimmed_logistic(float x_5, float s_1)
{
    float e_2 = exp((-3.1415927 / s_1));
    const float _e5 = weft_hair_logistic(x_5, s_1);
    return ((_e5 * (1.0 + e_2)) / (1.0 - e_2));
}

float weft_hair_etap(WeftHair hair_1, float sin_o_2, float cos_o_2)
{
    return (sqrt(((hair_1.eta * hair_1.eta) - (sin_o_2 * sin_o_2))) / max(cos_o_2, 0.0001));
}

WeftHairAttenuation weft_hair_attenuation(WeftHair hair_2, float sin_o_3, float cos_o_3, float h)
{
    WeftHairAttenuation a = (WeftHairAttenuation)0;

    float sin_t = (sin_o_3 / hair_2.eta);
    const float _e9 = weft_hair_safe_sqrt((1.0 - (sin_t * sin_t)));
    const float _e10 = weft_hair_etap(hair_2, sin_o_3, cos_o_3);
    float sin_gamma_t = clamp((h / _e10), -1.0, 1.0);
    const float _e18 = weft_hair_safe_sqrt((1.0 - (sin_gamma_t * sin_gamma_t)));
    float3 t_2 = exp((-(hair_2.sigma_a) * ((2.0 * _e18) / max(_e9, 0.0001))));
    const float _e31 = weft_hair_safe_sqrt((1.0 - (h * h)));
    const float _e34 = weft_f_dielectric((cos_o_3 * _e31), hair_2.eta);
    a.a0_ = _e34;
    a.a1_ = (((1.0 - _e34) * (1.0 - _e34)) * t_2);
    float3 _e46 = a.a1_;
    a.a2_ = ((_e46 * t_2) * _e34);
    float3 _e51 = a.a2_;
    a.a3_ = (((_e51 * t_2) * _e34) / ((1.0).xxx - (t_2 * _e34)));
    a.gamma_t = asin(sin_gamma_t);
    WeftHairAttenuation _e60 = a;
    const WeftHairAttenuation wefthairattenuation = _e60;
    return wefthairattenuation;
}

WeftHairAngles weft_hair_angles(float3 t, float3 o, float3 i_1)
{
    WeftHairAngles out_3 = (WeftHairAngles)0;

    float sin_o_4 = clamp(dot(o, t), -1.0, 1.0);
    float sin_i_2 = clamp(dot(i_1, t), -1.0, 1.0);
    const float _e16 = weft_hair_safe_sqrt((1.0 - (sin_o_4 * sin_o_4)));
    const float _e20 = weft_hair_safe_sqrt((1.0 - (sin_i_2 * sin_i_2)));
    out_3.theta = float4(sin_o_4, _e16, sin_i_2, _e20);
    float3 o_perp = (o - (sin_o_4 * t));
    float3 i_perp = (i_1 - (sin_i_2 * t));
    float len2_3 = (dot(o_perp, o_perp) * dot(i_perp, i_perp));
    float cos_phi = ((len2_3 > 1e-12) ? (dot(o_perp, i_perp) * rsqrt(max(len2_3, 1e-30))) : 1.0);
    out_3.phi = acos(clamp(cos_phi, -1.0, 1.0));
    WeftHairAngles _e43 = out_3;
    const WeftHairAngles wefthairangles = _e43;
    return wefthairangles;
}

float weft_hair_logistic_cdf(float x_6, float s_2)
{
    return (1.0 / (1.0 + exp((-(x_6) / s_2))));
}

float weft_hair_logistic_cdf_k3_(float s_3)
{
    return (1.0 / (1.0 + exp((3.1415927 / s_3))));
}

float weft_hair_logistic_cdf_k4_(float s_4)
{
    return (1.0 / (1.0 + exp((-3.1415927 / s_4))));
}

float weft_hair_trimmed_integral(float lo, float hi, float s_5)
{
    float sum_1 = (float)0;

    const float _e3 = weft_hair_logistic_cdf_k3_(s_5);
    const float _e4 = weft_hair_logistic_cdf_k4_(s_5);
    float a_4 = clamp(lo, -3.1415927, WEFT_PI);
    float b_4 = clamp(hi, -3.1415927, WEFT_PI);
    const float _e11 = weft_hair_logistic_cdf(b_4, s_5);
    const float _e12 = weft_hair_logistic_cdf(a_4, s_5);
    sum_1 = (_e11 - _e12);
    if ((hi > WEFT_PI)) {
        float _e17 = sum_1;
        const float _e22 = weft_hair_logistic_cdf(min((hi - 6.2831855), WEFT_PI), s_5);
        sum_1 = (_e17 + (_e22 - _e3));
    }
    if ((lo < -3.1415927)) {
        float _e27 = sum_1;
        const float _e32 = weft_hair_logistic_cdf(max((lo + 6.2831855), -3.1415927), s_5);
        sum_1 = (_e27 + (_e4 - _e32));
    }
    float _e35 = sum_1;
    return (_e35 / (_e4 - _e3));
}

float weft_hair_np_cell(float d0_, float d1_, float s_6)
{
    float mid = (0.5 * (d0_ + d1_));
    float m = (mid - (6.2831855 * round((mid / 6.2831855))));
    float half_ = min((0.5 * abs((d1_ - d0_))), WEFT_PI);
    if ((half_ < 0.0001)) {
        const float _e20 = weft_hair_trimmed_logistic(m, s_6);
        return _e20;
    }
    const float _e23 = weft_hair_trimmed_integral((m - half_), (m + half_), s_6);
    return (_e23 / (2.0 * half_));
}

float3 hair_strand(float3x3 frame, float2 uv0_)
{
    float2 ts = (float2)0;

    ts = float2(0.0, 1.0);
    float _e6 = ts.x;
    float _e10 = ts.y;
    const float3 _e14 = weft_safe_normalize(((frame[0] * _e6) + (frame[1] * _e10)), frame[1]);
    return _e14;
}

float hair_hash(uint x_7)
{
    uint state = ((x_7 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (float(((word >> 22u) ^ word)) * 2.3283064e-10);
}

float2 weft_transform_uv_k5_(float2 uv)
{
    return (uv + float2(0.0, 0.0));
}

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

float hair_value_noise_k6_(float x_8)
{
    float cell = floor(x_8);
    float f_1 = (x_8 - cell);
    float c0_ = (cell - (128.0 * floor((cell / 128.0))));
    float c1_ = (((c0_ + 1.0) >= 128.0) ? 0.0 : (c0_ + 1.0));
    const float _e17 = hair_hash(naga_f2u32(c0_));
    const float _e19 = hair_hash(naga_f2u32(c1_));
    return (lerp(_e17, _e19, ((f_1 * f_1) * (3.0 - (2.0 * f_1)))) - 0.5);
}

float hair_jitter(float2 uv0_1)
{
    float2 rotated = float2(((-4.371139e-8 * uv0_1.x) + uv0_1.y), ((-1.0 * uv0_1.x) + (-4.371139e-8 * uv0_1.y)));
    const float2 _e16 = weft_transform_uv_k5_(uv0_1);
    float4 _e19 = jitter_map.Sample(material_sampler, _e16);
    float j = _e19.x;
    float across = _e16.x;
    const float _e25 = hair_value_noise_k6_((across * 128.0));
    return (j + (0.2 * _e25));
}

float3 weft_safe_normalize_k7_(float3 v_3)
{
    float len2_4 = dot(v_3, v_3);
    return ((len2_4 > 1e-20) ? (v_3 * rsqrt(max(len2_4, 1e-20))) : (0.0).xxx);
}

WeftHairLobes weft_hair_mean_k10_(WeftHair hair_3, WeftHairAngles angles)
{
    float3 s_7 = (0.0).xxx;
    float3 albedo = (0.0).xxx;
    float3 back = (0.0).xxx;
    float weights = 0.0;
    float g0_ = -1.5707964;
    float3 d0_1 = (float3)0;
    uint k = 0u;
    WeftHairLobes out_4 = (WeftHairLobes)0;

    float4 th = angles.theta;
    const float4 _e8 = weft_hair_longitudinal(hair_3, th.x, th.y, th.z, th.w);
    const float _e11 = weft_hair_etap(hair_3, th.x, th.y);
    d0_1 = ((angles.phi).xxx - (((float3(0.0, 2.0, 4.0) * asin(clamp((-1.0 / _e11), -1.0, 1.0))) - (-3.1415927).xxx) + float3(0.0, 3.1415927, 6.2831855)));
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e130 = k;
            k = (_e130 + 1u);
        }
        loop_init_1 = false;
        uint _e42 = k;
        if ((_e42 < 12u)) {
        } else {
            break;
        }
        {
            float _e44 = g0_;
            float g1_ = (_e44 + 0.2617994);
            float gamma_t1_ = asin(clamp((sin(g1_) / _e11), -1.0, 1.0));
            float3 d1_1 = ((angles.phi).xxx - (((float3(0.0, 2.0, 4.0) * gamma_t1_) - ((2.0 * g1_)).xxx) + float3(0.0, 3.1415927, 6.2831855)));
            float _e63 = g0_;
            float gm = (_e63 + 0.1308997);
            float w = cos(gm);
            const WeftHairAttenuation _e70 = weft_hair_attenuation(hair_3, th.x, th.y, sin(gm));
            float _e75 = d0_1.x;
            const float _e78 = weft_hair_np_cell(_e75, d1_1.x, hair_3.s);
            float _e84 = d0_1.y;
            const float _e87 = weft_hair_np_cell(_e84, d1_1.y, hair_3.s);
            float _e95 = d0_1.z;
            const float _e98 = weft_hair_np_cell(_e95, d1_1.z, hair_3.s);
            float3 lobes_1 = ((((((_e8.x * _e70.a0_) * _e78)).xxx + ((_e8.y * _e70.a1_) * _e87)) + ((_e8.z * _e70.a2_) * _e98)) + ((_e8.w * _e70.a3_) * 0.15915494));
            float3 _e107 = s_7;
            s_7 = (_e107 + (w * lobes_1));
            float3 _e110 = albedo;
            albedo = (_e110 + (w * ((((_e70.a0_).xxx + _e70.a1_) + _e70.a2_) + _e70.a3_)));
            float3 _e121 = back;
            back = (_e121 + (w * ((_e70.a0_).xxx + _e70.a2_)));
            float _e128 = weights;
            weights = (_e128 + w);
            g0_ = g1_;
            d0_1 = d1_1;
        }
    }
    float3 _e135 = s_7;
    float _e136 = weights;
    out_4.s = (_e135 / (_e136).xxx);
    float3 _e140 = albedo;
    float _e141 = weights;
    out_4.albedo = (_e140 / (_e141).xxx);
    float3 _e145 = back;
    float _e146 = weights;
    out_4.back = (_e145 / (_e146).xxx);
    WeftHairLobes _e149 = out_4;
    const WeftHairLobes wefthairlobes = _e149;
    return wefthairlobes;
}

WeftHair weft_hair_params_k14_()
{
    WeftHair hair_4 = (WeftHair)0;

    hair_4.sigma_a = float3(0.19707139, 0.44586682, 0.7557883);
    hair_4.eta = 1.55;
    hair_4.v = float4(0.03157018, 0.007892545, 0.12628073, 0.12628073);
    hair_4.s = 0.11715981;
    hair_4.sin2k = float3(0.034899496, 0.06975647, 0.1391731);
    hair_4.cos2k = float3(0.99939084, 0.9975641, 0.9902682);
    WeftHair _e26 = hair_4;
    const WeftHair wefthair = _e26;
    return wefthair;
}

VertexOutput_vs_outline vs_outline(WeftOutlineVertex in_)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;
    WeftOutlineVaryings out_ = (WeftOutlineVaryings)0;

    float4x4 _e3 = weft_object.model;
    float4 world = mul(float4(in_.position, 1.0), _e3);
    float4x4 nm = weft_object.normal_matrix;
    float3 normal = mul(in_.normal, float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz));
    float4x4 _e22 = weft_frame.view_proj;
    float4 clip_ = mul(float4(world.xyz, 1.0), _e22);
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

VertexOutput_vs_fringe_shadow vs_fringe_shadow(WeftFringeShadowVertex in_1)
{
    bool local_2 = (bool)0;
    WeftFringeShadowVaryings out_1 = (WeftFringeShadowVaryings)0;

    float4x4 _e3 = weft_object.model;
    float3 world_1 = mul(float4(in_1.position, 1.0), _e3).xyz;
    float4x4 _e11 = weft_frame.view_proj;
    float4 clip_1 = mul(float4(world_1, 1.0), _e11);
    float4 _e17 = weft_frame.light_direction;
    float3 l = _e17.xyz;
    float l_len = length(l);
    float3 travel = ((l_len > 1e-6) ? (-(l) / (max(l_len, 1e-6)).xxx) : (0.0).xxx);
    float4x4 _e32 = weft_frame.view_proj;
    float4 pushed = mul(float4((world_1 + (travel * 0.16)), 1.0), _e32);
    if ((clip_1.w > 1e-6)) {
        local_2 = (pushed.w > 1e-6);
    } else {
        local_2 = false;
    }
    bool usable_1 = local_2;
    float2 offset_ndc = (usable_1 ? ((pushed.xy / (max(pushed.w, 1e-6)).xx) - (clip_1.xy / (max(clip_1.w, 1e-6)).xx)) : (0.0).xx);
    out_1.clip_position = float4((clip_1.xy + (offset_ndc * clip_1.w)), clip_1.zw);
    WeftFringeShadowVaryings _e71 = out_1;
    const WeftFringeShadowVaryings weftfringeshadowvaryings = _e71;
    const VertexOutput_vs_fringe_shadow weftfringeshadowvaryings_1 = { weftfringeshadowvaryings.clip_position };
    return weftfringeshadowvaryings_1;
}

float4 fs_fringe_shadow() : SV_Target0
{
    return float4(float3(0.5704816, 0.34239164, 0.34239164), 1.0);
}

VertexOutput_vs_main vs_main(WeftVertexInput in_2)
{
    WeftVaryings out_2 = (WeftVaryings)0;

    float4x4 model = weft_object.model;
    float3x3 model3_ = float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    float4x4 nm_1 = weft_object.normal_matrix;
    float3x3 normal3_ = float3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    float4 world_2 = mul(float4(in_2.position, 1.0), model);
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    float4x4 _e43 = weft_frame.view_proj;
    out_2.clip_position = mul(float4(world_2.xyz, 1.0), _e43);
    out_2.world_position = world_2.xyz;
    const float3 _e53 = weft_safe_normalize_k7_(mul(in_2.normal, normal3_));
    out_2.world_normal = _e53;
    const float3 _e58 = weft_safe_normalize_k7_(mul(in_2.tangent.xyz, model3_));
    out_2.world_tangent = float4(_e58, bitangent_sign);
    out_2.uv0_ = in_2.uv0_;
    WeftVaryings _e62 = out_2;
    const WeftVaryings weftvaryings = _e62;
    const VertexOutput_vs_main weftvaryings_1 = { weftvaryings.world_position, weftvaryings.world_normal, weftvaryings.world_tangent, weftvaryings.uv0_, weftvaryings.clip_position };
    return weftvaryings_1;
}

float4 fs_main(FragmentInput_fs_main fragmentinput_fs_main) : SV_Target0
{
    WeftVaryings in_3 = { fragmentinput_fs_main.clip_position_3, fragmentinput_fs_main.world_position_3, fragmentinput_fs_main.world_normal_2, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_3 };
    float3 color = (float3)0;
    WeftHairLobes lobes = (WeftHairLobes)0;

    const WeftSurface _e6 = weft_surface(in_3.world_position, in_3.world_normal);
    float3 v_4 = _e6.v;
    float3 n_3 = _e6.n;
    const float3x3 _e10 = weft_tangent_frame(n_3, in_3.world_tangent);
    const float3 _e12 = hair_strand(_e10, in_3.uv0_);
    const float _e14 = hair_jitter(in_3.uv0_);
    const float3 _e15 = weft_main_light_direction();
    const float3 _e16 = weft_main_light_radiance();
    const float3 _e17 = weft_sh_irradiance(n_3);
    float n_dot_l = dot(n_3, _e15);
    {
        const float3 _e22 = weft_safe_normalize((_e12 + (_e14 * n_3)), _e12);
        const WeftHair _e24 = weft_hair_params_k14_();
        const WeftHairAngles _e25 = weft_hair_angles(_e22, v_4, _e15);
        {
            const WeftHairLobes _e27 = weft_hair_mean_k10_(_e24, _e25);
            lobes = _e27;
        }
        float body = smoothstep(-0.25, HAIR_TERMINATOR, n_dot_l);
        float3 _e33 = lobes.back;
        float3 multiple = (float3(0.073238954, 0.019606648, 0.0059810597) * ((1.0).xxx - _e33));
        float3 _e37 = lobes.s;
        float3 direct = ((_e37 * body) + (multiple * (WEFT_INV_PI * saturate(n_dot_l))));
        float3 _e46 = lobes.back;
        color = ((direct * _e16) + (_e17 * (multiple + _e46)));
    }
    float3 _e50 = color;
    float3 radiance = clamp(_e50, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
