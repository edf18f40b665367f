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
    float s = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n.z));
    float b = ((n.x * n.y) * a);
    return float3((1.0 + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
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
    float3 t_1 = (ok ? (t_proj * rsqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_2, t_1) * s_1);
    return float3x3(t_1, b_1, n_2);
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

WeftHair weft_hair_params(float3 sigma_a, float eta, float beta_m_1, float beta_n_1, float alpha_deg)
{
    WeftHair hair = (WeftHair)0;

    hair.sigma_a = max(sigma_a, (0.0).xxx);
    hair.eta = max(eta, 1.0001);
    const float _e13 = weft_hair_variance(beta_m_1);
    hair.v = float4(_e13, (0.25 * _e13), (4.0 * _e13), (4.0 * _e13));
    const float _e23 = weft_hair_logistic_scale(beta_n_1);
    hair.s = _e23;
    float a_1 = radians(alpha_deg);
    float s0_ = sin(a_1);
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
    float d = (0.8162094 * _e73);
    hair.blur = float2(sin(d), cos(d));
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

float hair_noise_period(float density)
{
    return max(round(density), 1.0);
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

float hair_hash(uint x_2)
{
    uint state = ((x_2 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (float(((word >> 22u) ^ word)) * 2.3283064e-10);
}

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

float hair_value_noise(float x_3, float p)
{
    float cell = floor(x_3);
    float f = (x_3 - cell);
    float c0_ = (cell - (p * floor((cell / p))));
    float c1_1 = (((c0_ + 1.0) >= p) ? 0.0 : (c0_ + 1.0));
    const float _e16 = hair_hash(naga_f2u32(c0_));
    const float _e18 = hair_hash(naga_f2u32(c1_1));
    return (lerp(_e16, _e18, ((f * f) * (3.0 - (2.0 * f)))) - 0.5);
}

float hair_jitter(float2 uv0_1, float2 rotation, float noise_period)
{
    float4 _e5 = uv_rotate_mask.Sample(material_sampler, uv0_1);
    float mask = step(0.8, _e5.x);
    float c = rotation.x;
    float s_2 = rotation.y;
    float2 rotated = float2(((c * uv0_1.x) + (s_2 * uv0_1.y)), ((-(s_2) * uv0_1.x) + (c * uv0_1.y)));
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

float hair_kajiya_kay(float3 t, float3 h_1, float exponent)
{
    float t_dot_h = clamp(dot(t, h_1), -1.0, 1.0);
    float sin_th = sqrt(max((1.0 - (t_dot_h * t_dot_h)), 0.0));
    float dir_atten = smoothstep(-1.0, 0.0, t_dot_h);
    return (dir_atten * pow(sin_th, max(exponent, 1.0)));
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

WeftHair ZeroValueWeftHair() {
    return (WeftHair)0;
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
        h = ZeroValueWeftHair();
    }
    float _e23 = material.anisotropic_direction;
    float a_2 = radians(_e23);
    float _e31 = h.eta;
    float _e33 = h.s;
    float _e36 = h.v.x;
    float _e37 = scale;
    float3 _e40 = h.sin2k;
    float _e42 = h.r_floor;
    float3 _e45 = h.cos2k;
    float _e48 = h.blur.x;
    float3 _e51 = h.mp_norm;
    float _e54 = h.blur.y;
    float3 _e57 = h.inv_v;
    float _e60 = h.trt.x;
    float4 _e63 = h.trt;
    float _e66 = h.trt4_;
    float _e71 = h.inv_eta;
    float _e74 = material.strand_density;
    const float _e75 = hair_noise_period(_e74);
    const HairVaryings hairvaryings = ConstructHairVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, float4(_e31, _e33, _e36, _e37), float4(_e40, _e42), float4(_e45, _e48), float4(_e51, _e54), float4(_e57, _e60), float4(_e63.yzw, _e66), float4(cos(a_2), sin(a_2), _e71, _e75));
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
    float3 v_1 = _e19.v;
    float3 n_3 = _e19.n;
    const float3x3 _e23 = weft_tangent_frame(n_3, in_2.world_tangent);
    const float3 _e25 = hair_strand(_e23, in_2.uv0_);
    const float _e31 = hair_jitter(in_2.uv0_, in_2.jitter.xy, in_2.jitter.w);
    const float3 _e32 = weft_main_light_direction();
    const float3 _e33 = weft_main_light_radiance();
    const float3 _e34 = weft_sh_irradiance(n_3);
    float n_dot_l = dot(n_3, _e32);
    {
        const float3 _e38 = weft_safe_normalize((_e32 + v_1), n_3);
        float _e41 = material.primary_shift;
        const float3 _e45 = weft_safe_normalize((_e25 + ((_e41 + _e31) * n_3)), _e25);
        float _e48 = material.secondary_shift;
        const float3 _e52 = weft_safe_normalize((_e25 + ((_e48 + _e31) * n_3)), _e25);
        float4 _e55 = material.primary_color;
        float _e59 = material.primary_intensity;
        float _e62 = material.primary_exponent;
        const float _e63 = hair_kajiya_kay(_e45, _e38, _e62);
        float3 primary = (_e55.xyz * (_e59 * _e63));
        float4 _e68 = material.secondary_color;
        float _e72 = material.secondary_intensity;
        float _e75 = material.secondary_exponent;
        const float _e76 = hair_kajiya_kay(_e52, _e38, _e75);
        float3 secondary = (_e68.xyz * (_e72 * _e76));
        float3 direct = (((((base + primary) + secondary) * WEFT_INV_PI) * _e33) * saturate(n_dot_l));
        color = (direct + (_e34 * base));
    }
    float3 _e88 = color;
    float3 radiance = clamp(_e88, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
