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
    uint strand_along_tangent;
    int _pad3_0;
    int _pad3_1;
    int _pad3_2;
    float4 jitter_map_st;
    float jitter_strength;
    float anisotropic_direction;
    float strand_noise;
    float strand_density;
    float4 primary_color;
    float primary_exponent;
    float primary_intensity;
    float primary_shift;
    int _pad12_0;
    float4 secondary_color;
    float secondary_exponent;
    float secondary_intensity;
    float secondary_shift;
    float roughness;
    float azimuthal_roughness;
    float scale_angle;
    float ior;
    int _pad20_0;
    float4 outline_color;
    float outline_width;
    float outline_max_distance;
    int _pad23_0;
    int _pad23_1;
    float4 fringe_shadow_color;
    float fringe_shadow_length;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
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

struct WeftHairAngles {
    float4 theta;
    float phi;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
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
cbuffer material : register(b0, space1) { WeftMaterial material; }
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
Texture2D<float4> base_map : register(t3, space1);
Texture2D<float4> jitter_map : register(t5, space1);
Texture2D<float4> uv_rotate_mask : register(t6, space1);

struct VertexOutput_vs_outline {
    float4 clip_position : SV_Position;
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
    float4 clip_position_1 : SV_Position;
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
    float4 clip_position_2 : SV_Position;
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
    float c_1 = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c_1 * c_1));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c_1);
    float gpc = max((g + c_1), 1e-7);
    float b_den = max(((c_1 * gmc) + 1.0), 1e-7);
    float b_num = ((c_1 * gpc) - 1.0);
    float inv = (1.0 / (gpc * b_den));
    float f = saturate(((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)));
    return ((g2_ < 0.0) ? 1.0 : f);
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

float3x3 weft_tangent_frame(float3 n_2, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_2);
    float3 t_2 = (ok ? (t_proj * rsqrt(max(len2_1, 1e-20))) : _e13);
    float s_3 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_2, t_2) * s_3);
    return float3x3(t_2, b_1, n_2);
}

float2 weft_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

float weft_hair_sqr(float x)
{
    return (x * x);
}

float weft_hair_safe_sqrt(float x_1)
{
    return sqrt(max(x_1, 0.0));
}

float weft_hair_variance(float beta_m)
{
    float b_2 = clamp(beta_m, WEFT_HAIR_MIN_BETA_M, 1.0);
    float b2_ = (b_2 * b_2);
    float b4_ = (b2_ * b2_);
    float b20_ = ((((b4_ * b4_) * b4_) * b4_) * b4_);
    const float _e18 = weft_hair_sqr((((0.726 * b_2) + (0.812 * b2_)) + (3.7 * b20_)));
    return _e18;
}

float weft_hair_logistic_scale(float beta_n)
{
    float b_3 = clamp(beta_n, WEFT_HAIR_MIN_BETA_N, 1.0);
    float b2_1 = (b_3 * b_3);
    float b4_1 = (b2_1 * b2_1);
    float b22_ = (((((b4_1 * b4_1) * b4_1) * b4_1) * b4_1) * b2_1);
    return (0.62665707 * (((0.265 * b_3) + (1.194 * b2_1)) + (5.372 * b22_)));
}

float3 weft_hair_sigma_a_scaled(float3 c, float scale_1)
{
    float3 l = (log(clamp(c, (0.0001).xxx, (1.0).xxx)) * scale_1);
    return (l * l);
}

float weft_hair_sigma_a_scale(float beta_n_1)
{
    float b_4 = clamp(beta_n_1, WEFT_HAIR_MIN_BETA_N, 1.0);
    float d = (((((5.969 - (0.215 * b_4)) + ((2.532 * b_4) * b_4)) - (10.73 * pow(b_4, 3.0))) + (5.574 * pow(b_4, 4.0))) + (0.245 * pow(b_4, 5.0)));
    return (1.0 / d);
}

WeftHair weft_hair_params(float3 sigma_a, float eta_1, float beta_m_1, float beta_n_2, float alpha_deg)
{
    WeftHair hair = (WeftHair)0;

    hair.sigma_a = max(sigma_a, (0.0).xxx);
    hair.eta = max(eta_1, 1.0001);
    const float _e13 = weft_hair_variance(beta_m_1);
    hair.v = float4(_e13, (0.25 * _e13), (4.0 * _e13), (4.0 * _e13));
    const float _e23 = weft_hair_logistic_scale(beta_n_2);
    hair.s = _e23;
    float a_3 = radians(alpha_deg);
    float s0_ = sin(a_3);
    const float _e29 = weft_hair_safe_sqrt((1.0 - (s0_ * s0_)));
    float s1_ = ((2.0 * _e29) * s0_);
    float c1_ = ((_e29 * _e29) - (s0_ * s0_));
    float s2_ = ((2.0 * c1_) * s1_);
    float c2_ = ((c1_ * c1_) - (s1_ * s1_));
    hair.sin2k = float3(s0_, s1_, s2_);
    hair.cos2k = float3(_e29, c1_, c2_);
    hair.inv_v = (float3(1.0, 4.0, 0.25) / (_e13).xxx);
    float _e55 = hair.inv_v.x;
    float e_trt = exp((-0.5 * _e55));
    const float _e60 = weft_hair_sqr((e_trt * e_trt));
    float3 _e63 = hair.inv_v;
    const float _e67 = weft_hair_sqr((_e60 * _e60));
    hair.mp_norm = (_e63 / ((1.0).xxx - float3(_e60, _e67, e_trt)));
    float _e73 = hair.s;
    float d_1 = (0.8162094 * _e73);
    hair.blur = float2(sin(d_1), cos(d_1));
    float _e81 = hair.s;
    const float _e84 = weft_hair_sqr((0.4534 * _e81));
    hair.r_floor = _e84;
    float sh_1 = hair.s;
    hair.trt = float4((-9.2609 + (sh_1 * (65.993 - (107.38 * sh_1)))), (72.357 + (sh_1 * (-624.68 + (1069.8 * sh_1)))), (-153.75 + (sh_1 * (1704.7 - (3127.5 * sh_1)))), (-67.745 + (sh_1 * (-1105.8 + (2706.6 * sh_1)))));
    hair.trt4_ = (239.74 - (430.94 * sh_1));
    float _e124 = hair.eta;
    hair.inv_eta = (1.0 / _e124);
    WeftHair _e127 = hair;
    const WeftHair wefthair = _e127;
    return wefthair;
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

WeftHairAngles weft_hair_angles(float3 t, float3 o, float3 i)
{
    WeftHairAngles out_2 = (WeftHairAngles)0;

    float sin_o = clamp(dot(o, t), -1.0, 1.0);
    float sin_i = clamp(dot(i, t), -1.0, 1.0);
    const float _e16 = weft_hair_safe_sqrt((1.0 - (sin_o * sin_o)));
    const float _e20 = weft_hair_safe_sqrt((1.0 - (sin_i * sin_i)));
    out_2.theta = float4(sin_o, _e16, sin_i, _e20);
    float3 o_perp = (o - (sin_o * t));
    float3 i_perp = (i - (sin_i * t));
    float len2_2 = (dot(o_perp, o_perp) * dot(i_perp, i_perp));
    float cos_phi = ((len2_2 > 1e-12) ? (dot(o_perp, i_perp) * rsqrt(max(len2_2, 1e-30))) : 1.0);
    out_2.phi = acos(clamp(cos_phi, -1.0, 1.0));
    WeftHairAngles _e43 = out_2;
    const WeftHairAngles wefthairangles = _e43;
    return wefthairangles;
}

float3 weft_hair_fast_tt_density(float sin_half, float a)
{
    float rho2_ = ((1.0 - ((2.0 * a) * sin_half)) + (a * a));
    float inv_rho = rsqrt(max(rho2_, 1e-8));
    float cos_go = (max((sin_half - a), 0.0) * inv_rho);
    float cos_gt = ((1.0 - (a * sin_half)) * inv_rho);
    return float3(cos_go, cos_gt, (((0.25 * cos_go) * cos_gt) * inv_rho));
}

float3 weft_hair_fast_tt(float sin_plus, float sin_minus, float a_1, float cos_o, float eta_2, float3 sigma_a_1, float chord)
{
    const float3 _e7 = weft_hair_fast_tt_density(sin_plus, a_1);
    const float3 _e8 = weft_hair_fast_tt_density(sin_minus, a_1);
    const float _e11 = weft_f_dielectric((cos_o * _e7.x), eta_2);
    const float _e19 = weft_hair_sqr((1.0 - _e11));
    return (exp((-(sigma_a_1) * (chord * _e7.y))) * ((_e19 * 0.5) * (_e7.z + _e8.z)));
}

WeftHairLobes weft_hair_fast(WeftHair hair_1, float3 t_1, float3 o_1, float3 i_1)
{
    WeftHairLobes out_3 = (WeftHairLobes)0;

    float sin_o_1 = clamp(dot(o_1, t_1), -1.0, 1.0);
    float sin_i_1 = clamp(dot(i_1, t_1), -1.0, 1.0);
    const float _e15 = weft_hair_safe_sqrt((1.0 - (sin_o_1 * sin_o_1)));
    const float _e19 = weft_hair_safe_sqrt((1.0 - (sin_i_1 * sin_i_1)));
    float3 o_perp_1 = (o_1 - (sin_o_1 * t_1));
    float3 i_perp_1 = (i_1 - (sin_i_1 * t_1));
    float len2_3 = (dot(o_perp_1, o_perp_1) * dot(i_perp_1, i_perp_1));
    float cos_phi_1 = clamp(((len2_3 > 1e-12) ? (dot(o_perp_1, i_perp_1) * rsqrt(max(len2_3, 1e-30))) : 1.0), -1.0, 1.0);
    float cos_half = sqrt((0.5 + (0.5 * cos_phi_1)));
    float sin_half_1 = sqrt((0.5 - (0.5 * cos_phi_1)));
    float3 so = float3(((sin_o_1 * hair_1.cos2k.y) - (_e15 * hair_1.sin2k.y)), ((sin_o_1 * hair_1.cos2k.x) + (_e15 * hair_1.sin2k.x)), ((sin_o_1 * hair_1.cos2k.z) + (_e15 * hair_1.sin2k.z)));
    float3 co = abs(float3(((_e15 * hair_1.cos2k.y) + (sin_o_1 * hair_1.sin2k.y)), ((_e15 * hair_1.cos2k.x) - (sin_o_1 * hair_1.sin2k.x)), ((_e15 * hair_1.cos2k.z) - (sin_o_1 * hair_1.sin2k.z))));
    float3 inv_v_2 = hair_1.inv_v;
    float3 norm = hair_1.mp_norm;
    float3 x_6 = ((_e19 * co) * inv_v_2);
    float3 u = ((1.0).xxx / ((1.0).xxx + (0.7 * x_6)));
    float3 bessel = (((1.0).xxx + ((u * ((1.0).xxx - u)) * ((0.181903).xxx + (u * ((-0.401835).xxx + (u * 3.1851)))))) * rsqrt(((1.0).xxx + (6.2831855 * x_6))));
    float3 mp = ((exp(min(((((_e19 * co) - (sin_i_1 * so)) - (1.0).xxx) * inv_v_2), (0.0).xxx)) * bessel) * norm);
    float sin_t = (sin_o_1 * hair_1.inv_eta);
    float chord_1 = (2.0 * rsqrt(max((1.0 - (sin_t * sin_t)), 1e-8)));
    float a_4 = (_e15 * rsqrt(max(((hair_1.eta * hair_1.eta) - (sin_o_1 * sin_o_1)), 1e-8)));
    float sd = hair_1.blur.x;
    float cd = hair_1.blur.y;
    float c_r = sqrt(min(((0.5 + (0.5 * cos_phi_1)) + hair_1.r_floor), 1.0));
    const float _e179 = weft_f_dielectric((_e15 * c_r), hair_1.eta);
    float r = ((0.25 * c_r) * _e179);
    const float3 _e189 = weft_hair_fast_tt(((sin_half_1 * cd) + (cos_half * sd)), ((sin_half_1 * cd) - (cos_half * sd)), a_4, _e15, hair_1.eta, hair_1.sigma_a, chord_1);
    float h_f = (0.6243 + (0.1898 * _e15));
    const float _e197 = weft_hair_safe_sqrt((1.0 - (h_f * h_f)));
    const float _e200 = weft_f_dielectric((_e15 * _e197), hair_1.eta);
    float h2_ = (0.4824 + (0.2778 * _e15));
    const float _e208 = weft_hair_safe_sqrt((1.0 - (h2_ * h2_)));
    const float _e211 = weft_f_dielectric((_e15 * _e208), hair_1.eta);
    const float _e219 = weft_hair_safe_sqrt((1.0 - (((h2_ * h2_) * a_4) * a_4)));
    float3 t2_ = exp((-(hair_1.sigma_a) * (chord_1 * _e219)));
    const float _e225 = weft_hair_sqr((1.0 - _e211));
    float3 a2_ = (((_e225 * _e211) * t2_) * t2_);
    float3 ft = (_e200 * t2_);
    float3 a3_ = ((a2_ * ft) / ((1.0).xxx - ft));
    float s2_fit = (hair_1.trt.x + (a_4 * (hair_1.trt.y + (a_4 * (hair_1.trt.z + (a_4 * (hair_1.trt.w + (a_4 * hair_1.trt4_))))))));
    float s_trt = sqrt(max(exp(clamp(s2_fit, -9.0, 2.5)), (hair_1.s * hair_1.s)));
    const float _e262 = weft_hair_trimmed_logistic(acos(cos_phi_1), s_trt);
    out_3.s = ((((mp.x * r)).xxx + (mp.y * _e189)) + (mp.z * ((a2_ * _e262) + (a3_ * 0.15915494))));
    out_3.back = ((_e200).xxx + a2_);
    const float _e284 = weft_hair_sqr((1.0 - _e211));
    out_3.albedo = ((((_e200).xxx + (_e284 * t2_)) + a2_) + a3_);
    WeftHairLobes _e290 = out_3;
    const WeftHairLobes wefthairlobes = _e290;
    return wefthairlobes;
}

float hair_noise_period(float density)
{
    return max(round(density), 1.0);
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

WeftHair hair_from_varyings(HairVaryings in_4, float3 sigma_a_2)
{
    float v_1 = in_4.fibre.z;
    const WeftHair wefthair_1 = ConstructWeftHair(max(sigma_a_2, (0.0).xxx), in_4.fibre.x, float4(v_1, (0.25 * v_1), (4.0 * v_1), (4.0 * v_1)), in_4.fibre.y, in_4.sin2k.xyz, in_4.cos2k.xyz, in_4.inv_v.xyz, in_4.mp_norm.xyz, float2(in_4.cos2k.w, in_4.mp_norm.w), in_4.sin2k.w, float4(in_4.inv_v.w, in_4.trt.xyz), in_4.trt.w, in_4.jitter.z);
    return wefthair_1;
}

float3 hair_strand(float3x3 frame, float2 uv0_)
{
    float2 ts = (float2)0;

    uint _e10 = material.strand_along_tangent;
    ts = ((_e10 != 0u) ? float2(1.0, 0.0) : float2(0.0, 1.0));
    float _e17 = ts.x;
    float _e21 = ts.y;
    const float3 _e25 = weft_safe_normalize(((frame[0] * _e17) + (frame[1] * _e21)), frame[1]);
    return _e25;
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
    float c1_1 = (((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0));
    const float _e16 = hair_hash(naga_f2u32(c0_));
    const float _e18 = hair_hash(naga_f2u32(c1_1));
    return (lerp(_e16, _e18, ((f_1 * f_1) * (3.0 - (2.0 * f_1)))) - 0.5);
}

float hair_jitter(float2 uv0_1, float2 rotation, float noise_period)
{
    float4 _e5 = uv_rotate_mask.Sample(material_sampler, uv0_1);
    float mask = step(0.8, _e5.x);
    float c_2 = rotation.x;
    float s_4 = rotation.y;
    float2 rotated = float2(((c_2 * uv0_1.x) + (s_4 * uv0_1.y)), ((-(s_4) * uv0_1.x) + (c_2 * uv0_1.y)));
    float4 _e28 = material.jitter_map_st;
    const float2 _e29 = weft_transform_uv(((mask > 0.5) ? rotated : uv0_1), _e28);
    float4 _e32 = jitter_map.Sample(material_sampler, _e29);
    float j = _e32.x;
    uint _e38 = material.strand_along_tangent;
    float across = ((_e38 != 0u) ? _e29.y : _e29.x);
    float _e44 = material.strand_density;
    const float _e46 = hair_value_noise((across * _e44), noise_period);
    float _e49 = material.jitter_strength;
    float _e53 = material.strand_noise;
    return ((_e49 * j) + (_e53 * _e46));
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

VertexOutput_vs_hair vs_hair(WeftVertexInput in_1)
{
    WeftHair h = (WeftHair)0;
    float scale = 0.0;

    const WeftVaryings _e1 = weft_forward_vertex(in_1);
    float _e6 = material.ior;
    float _e9 = material.roughness;
    float _e12 = material.azimuthal_roughness;
    float _e15 = material.scale_angle;
    const WeftHair _e16 = weft_hair_params((0.0).xxx, _e6, _e9, _e12, _e15);
    h = _e16;
    {
        float _e22 = material.azimuthal_roughness;
        const float _e23 = weft_hair_sigma_a_scale(_e22);
        scale = _e23;
    }
    float _e26 = material.anisotropic_direction;
    float a_5 = radians(_e26);
    float _e34 = h.eta;
    float _e36 = h.s;
    float _e39 = h.v.x;
    float _e40 = scale;
    float3 _e43 = h.sin2k;
    float _e45 = h.r_floor;
    float3 _e48 = h.cos2k;
    float _e51 = h.blur.x;
    float3 _e54 = h.mp_norm;
    float _e57 = h.blur.y;
    float3 _e60 = h.inv_v;
    float _e63 = h.trt.x;
    float4 _e66 = h.trt;
    float _e69 = h.trt4_;
    float _e74 = h.inv_eta;
    float _e77 = material.strand_density;
    const float _e78 = hair_noise_period(_e77);
    const HairVaryings hairvaryings = ConstructHairVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, float4(_e34, _e36, _e39, _e40), float4(_e43, _e45), float4(_e48, _e51), float4(_e54, _e57), float4(_e60, _e63), float4(_e66.yzw, _e69), float4(cos(a_5), sin(a_5), _e74, _e78));
    const VertexOutput_vs_hair hairvaryings_1 = { hairvaryings.world_position, hairvaryings.world_normal, hairvaryings.world_tangent, hairvaryings.uv0_, hairvaryings.fibre, hairvaryings.sin2k, hairvaryings.cos2k, hairvaryings.mp_norm, hairvaryings.inv_v, hairvaryings.trt, hairvaryings.jitter, hairvaryings.clip_position };
    return hairvaryings_1;
}

float4 fs_main(FragmentInput_fs_main fragmentinput_fs_main) : SV_Target0
{
    HairVaryings in_2 = { fragmentinput_fs_main.clip_position_2, fragmentinput_fs_main.world_position_3, fragmentinput_fs_main.world_normal_2, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_3, fragmentinput_fs_main.fibre_1, fragmentinput_fs_main.sin2k_1, fragmentinput_fs_main.cos2k_1, fragmentinput_fs_main.mp_norm_1, fragmentinput_fs_main.inv_v_1, fragmentinput_fs_main.trt_1, fragmentinput_fs_main.jitter_1 };
    float3 color = (float3)0;
    WeftHairLobes lobes = (WeftHairLobes)0;

    float4 _e4 = material.base_map_st;
    const float2 _e5 = weft_transform_uv(in_2.uv0_, _e4);
    float4 _e8 = material.base_color;
    float4 _e11 = base_map.Sample(material_sampler, _e5);
    float4 base_rgba = (_e8 * _e11);
    float3 base = saturate(base_rgba.xyz);
    float alpha = saturate(base_rgba.w);
    const WeftSurface _e19 = weft_surface(in_2.world_position, in_2.world_normal);
    float3 v_2 = _e19.v;
    float3 n_3 = _e19.n;
    const float3x3 _e23 = weft_tangent_frame(n_3, in_2.world_tangent);
    const float3 _e25 = hair_strand(_e23, in_2.uv0_);
    const float _e31 = hair_jitter(in_2.uv0_, in_2.jitter.xy, in_2.jitter.w);
    const float3 _e32 = weft_main_light_direction();
    const float3 _e33 = weft_main_light_radiance();
    const float3 _e34 = weft_sh_irradiance(n_3);
    float n_dot_l = dot(n_3, _e32);
    {
        const float3 _e39 = weft_safe_normalize((_e25 + (_e31 * n_3)), _e25);
        const float3 _e42 = weft_hair_sigma_a_scaled(base, in_2.fibre.w);
        const WeftHair _e43 = hair_from_varyings(in_2, _e42);
        const WeftHairAngles _e44 = weft_hair_angles(_e39, v_2, _e32);
        {
            const WeftHairLobes _e46 = weft_hair_fast(_e43, _e39, v_2, _e32);
            lobes = _e46;
        }
        float body = smoothstep(-0.25, HAIR_TERMINATOR, n_dot_l);
        float3 _e53 = lobes.back;
        float3 multiple = (base * ((1.0).xxx - _e53));
        float3 _e57 = lobes.s;
        float3 direct = ((_e57 * body) + (multiple * (WEFT_INV_PI * saturate(n_dot_l))));
        float3 _e66 = lobes.back;
        color = ((direct * _e33) + (_e34 * (multiple + _e66)));
    }
    float3 _e70 = color;
    float3 radiance = clamp(_e70, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
