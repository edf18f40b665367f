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
    int _pad6_0;
    float3 inv_v;
    int _pad7_0;
    float3 mp_norm;
    int _pad8_0;
    float2 blur;
    float r_floor;
    int _pad10_0;
    float4 trt;
    float trt4_;
    float inv_eta;
    int _end_pad_0;
    int _end_pad_1;
};

struct WeftHairLobes {
    float3 s;
    int _pad1_0;
    float3 albedo;
    int _pad2_0;
    float3 back;
    int _end_pad_0;
};

struct HairVaryings {
    float4 clip_position : SV_Position;
    float3 world_position : LOC0;
    float3 world_normal : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    nointerpolation float4 fibre : LOC4;
    nointerpolation float4 sin2k : LOC5;
    nointerpolation float4 cos2k : LOC6;
    nointerpolation float4 mp_norm : LOC7;
    nointerpolation float4 inv_v : LOC8;
    nointerpolation float4 trt : LOC9;
    nointerpolation float4 jitter : LOC10;
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

struct VertexOutput_vs_hair {
    float3 world_position_2 : LOC0;
    float3 world_normal_1 : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_2 : LOC3;
    nointerpolation float4 fibre : LOC4;
    nointerpolation float4 sin2k : LOC5;
    nointerpolation float4 cos2k : LOC6;
    nointerpolation float4 mp_norm : LOC7;
    nointerpolation float4 inv_v : LOC8;
    nointerpolation float4 trt : LOC9;
    nointerpolation float4 jitter : LOC10;
    float4 clip_position_2 : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_3 : LOC0;
    float3 world_normal_2 : LOC1;
    float4 world_tangent_1 : LOC2;
    float2 uv0_3 : LOC3;
    nointerpolation float4 fibre_1 : LOC4;
    nointerpolation float4 sin2k_1 : LOC5;
    nointerpolation float4 cos2k_1 : LOC6;
    nointerpolation float4 mp_norm_1 : LOC7;
    nointerpolation float4 inv_v_1 : LOC8;
    nointerpolation float4 trt_1 : LOC9;
    nointerpolation float4 jitter_1 : LOC10;
    float4 clip_position_3 : SV_Position;
};

float3 weft_safe_normalize(float3 v, float3 fallback)
{
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * rsqrt(max(len2_, 1e-20))) : fallback);
}

float3 weft_any_perpendicular(float3 n)
{
    float s_2 = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a_2 = (-1.0 / (s_2 + n.z));
    float b = ((n.x * n.y) * a_2);
    return float3((1.0 + (((s_2 * n.x) * n.x) * a_2)), (s_2 * b), (-(s_2) * n.x));
}

float weft_f_dielectric(float cos_i, float eta)
{
    float c = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c * c));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c);
    float gpc = max((g + c), 1e-7);
    float b_den = max(((c * gmc) + 1.0), 1e-7);
    float b_num = ((c * gpc) - 1.0);
    float inv = (1.0 / (gpc * b_den));
    float f = saturate(((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)));
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

float3 weft_safe_normalize_k3_(float3 v_2)
{
    float len2_2 = dot(v_2, v_2);
    return ((len2_2 > 1e-20) ? (v_2 * rsqrt(max(len2_2, 1e-20))) : (0.0).xxx);
}

WeftVaryings weft_forward_vertex(WeftVertexInput in_4)
{
    WeftVaryings out_2 = (WeftVaryings)0;

    float4x4 model = weft_object.model;
    float3x3 model3_ = float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    float4x4 nm = weft_object.normal_matrix;
    float3x3 normal3_ = float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    float4 world = mul(float4(in_4.position, 1.0), model);
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_4.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    float4x4 _e43 = weft_frame.view_proj;
    out_2.clip_position = mul(float4(world.xyz, 1.0), _e43);
    out_2.world_position = world.xyz;
    const float3 _e53 = weft_safe_normalize_k3_(mul(in_4.normal, normal3_));
    out_2.world_normal = _e53;
    const float3 _e58 = weft_safe_normalize_k3_(mul(in_4.tangent.xyz, model3_));
    out_2.world_tangent = float4(_e58, bitangent_sign);
    out_2.uv0_ = in_4.uv0_;
    WeftVaryings _e62 = out_2;
    const WeftVaryings weftvaryings = _e62;
    return weftvaryings;
}

float3x3 weft_tangent_frame(float3 n_2, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_3 = dot(t_proj, t_proj);
    bool ok = (len2_3 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_2);
    float3 t_1 = (ok ? (t_proj * rsqrt(max(len2_3, 1e-20))) : _e13);
    float s_3 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_2, t_1) * s_3);
    return float3x3(t_1, b_1, n_2);
}

float weft_hair_sqr(float x)
{
    return (x * x);
}

float weft_hair_safe_sqrt(float x_1)
{
    return sqrt(max(x_1, 0.0));
}

float weft_hair_logistic(float x_2, float s)
{
    float e_1 = exp((-(abs(x_2)) / s));
    const float _e8 = weft_hair_sqr((1.0 + e_1));
    return (e_1 / (s * _e8));
}

float weft_hair_trimmed_logistic(float x_3, float s_1)
{
    float e_2 = exp((-3.1415927 / s_1));
    const float _e5 = weft_hair_logistic(x_3, s_1);
    return ((_e5 * (1.0 + e_2)) / (1.0 - e_2));
}

float3 weft_hair_fast_tt_density(float sin_half, float a)
{
    float rho2_ = ((1.0 - ((2.0 * a) * sin_half)) + (a * a));
    float inv_rho = rsqrt(max(rho2_, 1e-8));
    float cos_go = (max((sin_half - a), 0.0) * inv_rho);
    float cos_gt = ((1.0 - (a * sin_half)) * inv_rho);
    return float3(cos_go, cos_gt, (((0.25 * cos_go) * cos_gt) * inv_rho));
}

float3 weft_hair_fast_tt(float sin_plus, float sin_minus, float a_1, float cos_o, float eta_1, float3 sigma_a, float chord)
{
    const float3 _e7 = weft_hair_fast_tt_density(sin_plus, a_1);
    const float3 _e8 = weft_hair_fast_tt_density(sin_minus, a_1);
    const float _e11 = weft_f_dielectric((cos_o * _e7.x), eta_1);
    const float _e19 = weft_hair_sqr((1.0 - _e11));
    return (exp((-(sigma_a) * (chord * _e7.y))) * ((_e19 * 0.5) * (_e7.z + _e8.z)));
}

WeftHairLobes weft_hair_fast(WeftHair hair, float3 t, float3 o, float3 i)
{
    WeftHairLobes out_3 = (WeftHairLobes)0;

    float sin_o = clamp(dot(o, t), -1.0, 1.0);
    float sin_i = clamp(dot(i, t), -1.0, 1.0);
    const float _e15 = weft_hair_safe_sqrt((1.0 - (sin_o * sin_o)));
    const float _e19 = weft_hair_safe_sqrt((1.0 - (sin_i * sin_i)));
    float3 o_perp = (o - (sin_o * t));
    float3 i_perp = (i - (sin_i * t));
    float len2_4 = (dot(o_perp, o_perp) * dot(i_perp, i_perp));
    float cos_phi = clamp(((len2_4 > 1e-12) ? (dot(o_perp, i_perp) * rsqrt(max(len2_4, 1e-30))) : 1.0), -1.0, 1.0);
    float cos_half = sqrt((0.5 + (0.5 * cos_phi)));
    float sin_half_1 = sqrt((0.5 - (0.5 * cos_phi)));
    float3 so = float3(((sin_o * hair.cos2k.y) - (_e15 * hair.sin2k.y)), ((sin_o * hair.cos2k.x) + (_e15 * hair.sin2k.x)), ((sin_o * hair.cos2k.z) + (_e15 * hair.sin2k.z)));
    float3 co = abs(float3(((_e15 * hair.cos2k.y) + (sin_o * hair.sin2k.y)), ((_e15 * hair.cos2k.x) - (sin_o * hair.sin2k.x)), ((_e15 * hair.cos2k.z) - (sin_o * hair.sin2k.z))));
    float3 inv_v_2 = hair.inv_v;
    float3 norm = hair.mp_norm;
    float3 x_6 = ((_e19 * co) * inv_v_2);
    float3 u = ((1.0).xxx / ((1.0).xxx + (0.7 * x_6)));
    float3 bessel = (((1.0).xxx + ((u * ((1.0).xxx - u)) * ((0.181903).xxx + (u * ((-0.401835).xxx + (u * 3.1851)))))) * rsqrt(((1.0).xxx + (6.2831855 * x_6))));
    float3 mp = ((exp(min(((((_e19 * co) - (sin_i * so)) - (1.0).xxx) * inv_v_2), (0.0).xxx)) * bessel) * norm);
    float sin_t = (sin_o * hair.inv_eta);
    float chord_1 = (2.0 * rsqrt(max((1.0 - (sin_t * sin_t)), 1e-8)));
    float a_3 = (_e15 * rsqrt(max(((hair.eta * hair.eta) - (sin_o * sin_o)), 1e-8)));
    float sd = hair.blur.x;
    float cd = hair.blur.y;
    float c_r = sqrt(min(((0.5 + (0.5 * cos_phi)) + hair.r_floor), 1.0));
    const float _e170 = weft_f_dielectric((_e15 * c_r), hair.eta);
    float r = ((0.25 * c_r) * _e170);
    const float3 _e180 = weft_hair_fast_tt(((sin_half_1 * cd) + (cos_half * sd)), ((sin_half_1 * cd) - (cos_half * sd)), a_3, _e15, hair.eta, hair.sigma_a, chord_1);
    float h_f = (0.6243 + (0.1898 * _e15));
    const float _e188 = weft_hair_safe_sqrt((1.0 - (h_f * h_f)));
    const float _e191 = weft_f_dielectric((_e15 * _e188), hair.eta);
    float h2_ = (0.4824 + (0.2778 * _e15));
    const float _e199 = weft_hair_safe_sqrt((1.0 - (h2_ * h2_)));
    const float _e202 = weft_f_dielectric((_e15 * _e199), hair.eta);
    const float _e210 = weft_hair_safe_sqrt((1.0 - (((h2_ * h2_) * a_3) * a_3)));
    float3 t2_ = exp((-(hair.sigma_a) * (chord_1 * _e210)));
    const float _e216 = weft_hair_sqr((1.0 - _e202));
    float3 a2_ = (((_e216 * _e202) * t2_) * t2_);
    float3 ft = (_e191 * t2_);
    float3 a3_ = ((a2_ * ft) / ((1.0).xxx - ft));
    float s2_fit = (hair.trt.x + (a_3 * (hair.trt.y + (a_3 * (hair.trt.z + (a_3 * (hair.trt.w + (a_3 * hair.trt4_))))))));
    float s_trt = sqrt(max(exp(clamp(s2_fit, -9.0, 2.5)), (hair.s * hair.s)));
    const float _e252 = weft_hair_trimmed_logistic(acos(cos_phi), s_trt);
    out_3.s = ((((mp.x * r)).xxx + (mp.y * _e180)) + (mp.z * ((a2_ * _e252) + (a3_ * 0.15915494))));
    out_3.back = ((_e191).xxx + a2_);
    const float _e274 = weft_hair_sqr((1.0 - _e202));
    out_3.albedo = ((((_e191).xxx + (_e274 * t2_)) + a2_) + a3_);
    WeftHairLobes _e280 = out_3;
    const WeftHairLobes wefthairlobes = _e280;
    return wefthairlobes;
}

WeftHair ConstructWeftHair(float3 arg0, float arg1, float4 arg2, float arg3, float3 arg4, float3 arg5, float3 arg6, float3 arg7, float2 arg8, float arg9, float4 arg10, float arg11, float arg12) {
    WeftHair ret = (WeftHair)0;
    ret.sigma_a = arg0;
    ret.eta = arg1;
    ret.v = arg2;
    ret.s = arg3;
    ret.sin2k = arg4;
    ret.cos2k = arg5;
    ret.inv_v = arg6;
    ret.mp_norm = arg7;
    ret.blur = arg8;
    ret.r_floor = arg9;
    ret.trt = arg10;
    ret.trt4_ = arg11;
    ret.inv_eta = arg12;
    return ret;
}

WeftHair hair_from_varyings(HairVaryings in_5, float3 sigma_a_1)
{
    float v_3 = in_5.fibre.z;
    const WeftHair wefthair = ConstructWeftHair(max(sigma_a_1, (0.0).xxx), in_5.fibre.x, float4(v_3, (0.25 * v_3), (4.0 * v_3), (4.0 * v_3)), in_5.fibre.y, in_5.sin2k.xyz, in_5.cos2k.xyz, in_5.inv_v.xyz, in_5.mp_norm.xyz, float2(in_5.cos2k.w, in_5.mp_norm.w), in_5.sin2k.w, float4(in_5.inv_v.w, in_5.trt.xyz), in_5.trt.w, in_5.jitter.z);
    return wefthair;
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

float hair_hash(uint x_4)
{
    uint state = ((x_4 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (float(((word >> 22u) ^ word)) * 2.3283064e-10);
}

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

float hair_value_noise(float x_5, float p)
{
    float cell = floor(x_5);
    float f_1 = (x_5 - cell);
    float c0_ = (cell - (p * floor((cell / p))));
    float c1_ = (((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0));
    const float _e16 = hair_hash(naga_f2u32(c0_));
    const float _e18 = hair_hash(naga_f2u32(c1_));
    return (lerp(_e16, _e18, ((f_1 * f_1) * (3.0 - (2.0 * f_1)))) - 0.5);
}

float2 weft_transform_uv_k4_(float2 uv)
{
    return (uv + float2(0.0, 0.0));
}

float hair_jitter(float2 uv0_1, float2 rotation, float noise_period)
{
    float c_1 = rotation.x;
    float s_4 = rotation.y;
    float2 rotated = float2(((c_1 * uv0_1.x) + (s_4 * uv0_1.y)), ((-(s_4) * uv0_1.x) + (c_1 * uv0_1.y)));
    const float2 _e18 = weft_transform_uv_k4_(uv0_1);
    float4 _e21 = jitter_map.Sample(material_sampler, _e18);
    float j = _e21.x;
    float across = _e18.x;
    const float _e26 = hair_value_noise((across * 128.0), noise_period);
    return (j + (0.2 * _e26));
}

WeftHair weft_hair_params_k5_()
{
    WeftHair hair_1 = (WeftHair)0;

    hair_1.sigma_a = float3(0.0, 0.0, 0.0);
    hair_1.eta = 1.55;
    hair_1.v = float4(0.03157018, 0.007892545, 0.12628073, 0.12628073);
    hair_1.s = 0.11715981;
    hair_1.sin2k = float3(0.034899496, 0.06975647, 0.1391731);
    hair_1.cos2k = float3(0.99939084, 0.9975641, 0.9902682);
    hair_1.inv_v = float3(31.675459, 126.701836, 7.9188647);
    float _e30 = hair_1.inv_v.x;
    float e_trt = exp((-0.5 * _e30));
    const float _e35 = weft_hair_sqr((e_trt * e_trt));
    float3 _e38 = hair_1.inv_v;
    const float _e41 = weft_hair_sqr((_e35 * _e35));
    hair_1.mp_norm = (_e38 / ((1.0).xxx - float3(_e35, _e41, e_trt)));
    float _e47 = hair_1.s;
    float d = (0.8162094 * _e47);
    hair_1.blur = float2(sin(d), cos(d));
    float _e55 = hair_1.s;
    const float _e58 = weft_hair_sqr((0.4534 * _e55));
    hair_1.r_floor = _e58;
    float sh_1 = hair_1.s;
    hair_1.trt = float4((-9.2609 + (sh_1 * (65.993 - (107.38 * sh_1)))), (72.357 + (sh_1 * (-624.68 + (1069.8 * sh_1)))), (-153.75 + (sh_1 * (1704.7 - (3127.5 * sh_1)))), (-67.745 + (sh_1 * (-1105.8 + (2706.6 * sh_1)))));
    hair_1.trt4_ = (239.74 - (430.94 * sh_1));
    float _e98 = hair_1.eta;
    hair_1.inv_eta = (1.0 / _e98);
    WeftHair _e101 = hair_1;
    const WeftHair wefthair_1 = _e101;
    return wefthair_1;
}

float3 weft_hair_sigma_a_scaled_k8_(float scale_1)
{
    float3 l = (float3(-2.6140277, -3.9318867, -5.1191573) * scale_1);
    return (l * l);
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

VertexOutput_vs_fringe_shadow vs_fringe_shadow(WeftFringeShadowVertex in_1)
{
    bool local_2 = (bool)0;
    WeftFringeShadowVaryings out_1 = (WeftFringeShadowVaryings)0;

    float4x4 _e3 = weft_object.model;
    float3 world_2 = mul(float4(in_1.position, 1.0), _e3).xyz;
    float4x4 _e11 = weft_frame.view_proj;
    float4 clip_1 = mul(float4(world_2, 1.0), _e11);
    float4 _e17 = weft_frame.light_direction;
    float3 l_1 = _e17.xyz;
    float l_len = length(l_1);
    float3 travel = ((l_len > 1e-6) ? (-(l_1) / (max(l_len, 1e-6)).xxx) : (0.0).xxx);
    float4x4 _e32 = weft_frame.view_proj;
    float4 pushed = mul(float4((world_2 + (travel * 0.16)), 1.0), _e32);
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

HairVaryings ConstructHairVaryings(float4 arg0, float3 arg1, float3 arg2, float4 arg3, float2 arg4, float4 arg5, float4 arg6, float4 arg7, float4 arg8, float4 arg9, float4 arg10, float4 arg11) {
    HairVaryings ret = (HairVaryings)0;
    ret.clip_position = arg0;
    ret.world_position = arg1;
    ret.world_normal = arg2;
    ret.world_tangent = arg3;
    ret.uv0_ = arg4;
    ret.fibre = arg5;
    ret.sin2k = arg6;
    ret.cos2k = arg7;
    ret.mp_norm = arg8;
    ret.inv_v = arg9;
    ret.trt = arg10;
    ret.jitter = arg11;
    return ret;
}

VertexOutput_vs_hair vs_hair(WeftVertexInput in_2)
{
    WeftHair h = (WeftHair)0;
    float scale = 0.0;

    const WeftVaryings _e1 = weft_forward_vertex(in_2);
    const WeftHair _e2 = weft_hair_params_k5_();
    h = _e2;
    {
    }
    float _e12 = h.eta;
    float _e14 = h.s;
    float _e17 = h.v.x;
    float3 _e21 = h.sin2k;
    float _e23 = h.r_floor;
    float3 _e26 = h.cos2k;
    float _e29 = h.blur.x;
    float3 _e32 = h.mp_norm;
    float _e35 = h.blur.y;
    float3 _e38 = h.inv_v;
    float _e41 = h.trt.x;
    float4 _e44 = h.trt;
    float _e47 = h.trt4_;
    float _e52 = h.inv_eta;
    const HairVaryings hairvaryings = ConstructHairVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, float4(_e12, _e14, _e17, 0.16982499), float4(_e21, _e23), float4(_e26, _e29), float4(_e32, _e35), float4(_e38, _e41), float4(_e44.yzw, _e47), float4(-4.371139e-8, 1.0, _e52, 128.0));
    const VertexOutput_vs_hair hairvaryings_1 = { hairvaryings.world_position, hairvaryings.world_normal, hairvaryings.world_tangent, hairvaryings.uv0_, hairvaryings.fibre, hairvaryings.sin2k, hairvaryings.cos2k, hairvaryings.mp_norm, hairvaryings.inv_v, hairvaryings.trt, hairvaryings.jitter, hairvaryings.clip_position };
    return hairvaryings_1;
}

float4 fs_main(FragmentInput_fs_main fragmentinput_fs_main) : SV_Target0
{
    HairVaryings in_3 = { fragmentinput_fs_main.clip_position_3, fragmentinput_fs_main.world_position_3, fragmentinput_fs_main.world_normal_2, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_3, fragmentinput_fs_main.fibre_1, fragmentinput_fs_main.sin2k_1, fragmentinput_fs_main.cos2k_1, fragmentinput_fs_main.mp_norm_1, fragmentinput_fs_main.inv_v_1, fragmentinput_fs_main.trt_1, fragmentinput_fs_main.jitter_1 };
    float3 color = (float3)0;
    WeftHairLobes lobes = (WeftHairLobes)0;

    const WeftSurface _e6 = weft_surface(in_3.world_position, in_3.world_normal);
    float3 v_4 = _e6.v;
    float3 n_3 = _e6.n;
    const float3x3 _e10 = weft_tangent_frame(n_3, in_3.world_tangent);
    const float3 _e12 = hair_strand(_e10, in_3.uv0_);
    const float _e18 = hair_jitter(in_3.uv0_, in_3.jitter.xy, in_3.jitter.w);
    const float3 _e19 = weft_main_light_direction();
    const float3 _e20 = weft_main_light_radiance();
    const float3 _e21 = weft_sh_irradiance(n_3);
    float n_dot_l = dot(n_3, _e19);
    {
        const float3 _e26 = weft_safe_normalize((_e12 + (_e18 * n_3)), _e12);
        const float3 _e29 = weft_hair_sigma_a_scaled_k8_(in_3.fibre.w);
        const WeftHair _e30 = hair_from_varyings(in_3, _e29);
        {
            const WeftHairLobes _e32 = weft_hair_fast(_e30, _e26, v_4, _e19);
            lobes = _e32;
        }
        float body = smoothstep(-0.25, HAIR_TERMINATOR, n_dot_l);
        float3 _e38 = lobes.back;
        float3 multiple = (float3(0.073238954, 0.019606648, 0.0059810597) * ((1.0).xxx - _e38));
        float3 _e42 = lobes.s;
        float3 direct = ((_e42 * body) + (multiple * (WEFT_INV_PI * saturate(n_dot_l))));
        float3 _e51 = lobes.back;
        color = ((direct * _e20) + (_e21 * (multiple + _e51)));
    }
    float3 _e55 = color;
    float3 radiance = clamp(_e55, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
