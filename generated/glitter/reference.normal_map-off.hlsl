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
    float metallic;
    float smoothness;
    int _pad3_0;
    int _pad3_1;
    float4 base_map_st;
    float normal_strength;
    float occlusion_strength;
    int _pad6_0;
    int _pad6_1;
    float4 flake_color;
    float flake_intensity;
    float flake_density;
    float flake_size;
    float flake_roughness;
    float twinkle;
    float density_variation;
    int _end_pad_0;
    int _end_pad_1;
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

struct GlintGrid {
    float2 uv;
    uint seed;
    float cell_area;
    float weight;
    int _end_pad_0;
};

struct GlintParams {
    float log_density;
    float micro_roughness;
    float density_randomization;
};

struct GlintSlopeRand {
    float4 gate_rand;
    float4 gaussian;
    float2 lerp_;
    int _end_pad_0;
    int _end_pad_1;
};

struct GlintSimplex {
    int2 id;
    int si;
    int _pad2_0;
    float3 bary;
    int _end_pad_0;
};

struct GlintEllipse {
    float2 major_dir;
    float major;
    float minor;
};

struct GlintGrids {
    GlintGrid g0_;
    GlintGrid g1_;
    GlintGrid g2_;
    GlintGrid g3_;
};

struct GlintTetra {
    float3 p0_;
    int _pad1_0;
    float3 p1_;
    int _pad2_0;
    float3 p2_;
    int _pad3_0;
    float3 p3_;
    int _pad4_0;
    float4 w;
    bool center_;
    float bin0_;
    float bin_h;
    float bin1_;
    float lod0_;
    float ratio0_;
    int _end_pad_0;
    int _end_pad_1;
};

struct GlintFootprintCell {
    float theta_lerp;
    float ratio_lerp;
    float lod_lerp;
    bool center_;
    float bin0_;
    float bin_h;
    float bin1_;
    float lod0_;
    float ratio0_;
};

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SMOOTH = 2u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float GLINT_TAU = 6.2831855;
static const float GLINT_HALF_PI = 1.5707964;
static const float GLINT_TABLE_SIZE = 64.0;
static const float GLINT_MIN_LOD = -20.0;
static const float GLINT_MAX_LOD = 20.0;
static const float GLINT_MAX_RATIO = 16.0;
static const uint GLINT_TET_A_UP = 36292u;
static const uint GLINT_TET_A_DOWN = 36165u;
static const uint GLINT_TET_A_LOW = 34112u;
static const uint GLINT_TET_B_UP = 23168u;
static const uint GLINT_TET_B_DOWN = 42242u;
static const uint GLINT_TET_B_HIGH = 44421u;
static const uint GLINT_TET_C_UP = 44517u;
static const uint GLINT_TET_C_DOWN = 58790u;
static const uint GLINT_TET_C_LOW = 42338u;
static const uint GLINT_TET_CENTER_UP = 60596u;
static const uint GLINT_TET_CENTER_DOWN = 18110u;
static const uint GLINT_TET_CENTER_LOW = 46659u;

cbuffer weft_frame : register(b0) { WeftFrame weft_frame; }
TextureCube<float4> weft_environment : register(t1);
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup0SamplerIndexArray : register(t64, space0);
#define weft_environment_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[2]])
Texture2D<float4> weft_brdf_lut : register(t3);
#define weft_lut_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[4]])
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }
cbuffer material : register(b0, space1) { WeftMaterial material; }
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
Texture2D<float4> base_map : register(t3, space1);
Texture2D<float4> occlusion_map : register(t5, space1);

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

float4 weft_select4_f32bit(bool4 weft_sel_c, float4 weft_sel_a, float4 weft_sel_b)
{
    return float4((weft_sel_c.x ? weft_sel_a.x : weft_sel_b.x), (weft_sel_c.y ? weft_sel_a.y : weft_sel_b.y), (weft_sel_c.z ? weft_sel_a.z : weft_sel_b.z), (weft_sel_c.w ? weft_sel_a.w : weft_sel_b.w));
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

float weft_clamp_roughness(float roughness)
{
    return clamp(roughness, WEFT_MIN_ROUGHNESS, 1.0);
}

float3 weft_safe_normalize(float3 v, float3 fallback)
{
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * rsqrt(max(len2_, 1e-20))) : fallback);
}

float3 weft_any_perpendicular(float3 n_1)
{
    float s = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a_1 = (-1.0 / (s + n_1.z));
    float b_1 = ((n_1.x * n_1.y) * a_1);
    return float3((1.0 + (((s * n_1.x) * n_1.x) * a_1)), (s * b_1), (-(s) * n_1.x));
}

float weft_d_ggx(float n_dot_h, float roughness_1)
{
    const float _e2 = weft_clamp_roughness(roughness_1);
    float a_2 = (_e2 * _e2);
    float a2_ = (a_2 * a_2);
    float noh = saturate(n_dot_h);
    float one_minus_noh2_ = ((1.0 - noh) * (1.0 + noh));
    float d_2 = (one_minus_noh2_ + ((noh * noh) * a2_));
    return (a2_ / ((WEFT_PI * d_2) * d_2));
}

float weft_d_ggx_nh(float3 n_2, float3 h, float roughness_2)
{
    const float _e3 = weft_clamp_roughness(roughness_2);
    float a_3 = (_e3 * _e3);
    float a2_1 = (a_3 * a_3);
    float noh_1 = saturate(dot(n_2, h));
    float3 nxh = cross(n_2, h);
    float d_3 = (dot(nxh, nxh) + ((noh_1 * noh_1) * a2_1));
    return (a2_1 / (WEFT_PI * max((d_3 * d_3), 1e-30)));
}

float3 weft_f_schlick(float3 f0_, float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (f0_ + (((1.0).xxx - f0_) * _e5));
}

float weft_v_smith_ggx_correlated(float n_dot_v, float n_dot_l, float roughness_3)
{
    const float _e3 = weft_clamp_roughness(roughness_3);
    float a_4 = (_e3 * _e3);
    float a2_2 = (a_4 * a_4);
    const float _e6 = weft_clamp_cos(n_dot_v);
    const float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * (1.0 - a2_2)) + a2_2)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * (1.0 - a2_2)) + a2_2)));
    return (0.5 / (lv + ll));
}

float3 weft_diffuse_lambert(float3 albedo)
{
    return (albedo * WEFT_INV_PI);
}

float3 weft_env_brdf_from_lut(float3 f0_1, float2 scale_bias)
{
    float2 sb = saturate(scale_bias);
    return ((f0_1 * sb.x) + (sb.y).xxx);
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

float3 weft_sh_irradiance(float3 n_3)
{
    float3 e = (float3)0;

    float4 sh[9] = weft_frame.sh;
    e = (sh[0].xyz * 0.282095);
    float3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_3.y)));
    float3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_3.z)));
    float3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_3.x)));
    float3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_3.x) * n_3.y)));
    float3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_3.y) * n_3.z)));
    float3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_3.z) * n_3.z) - 1.0))));
    float3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_3.x) * n_3.z)));
    float3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_3.x * n_3.x) - (n_3.y * n_3.y)))));
    float3 _e91 = e;
    return max(_e91, (0.0).xxx);
}

float weft_specular_mip(float roughness_4)
{
    float r_1 = saturate(roughness_4);
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r_1 * (1.7 - (0.7 * r_1))) * max_mip);
}

float3 weft_prefiltered_radiance(float3 dir, float roughness_5)
{
    const float _e4 = weft_specular_mip(roughness_5);
    float4 c_3 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_3.xyz, (0.0).xxx);
}

float2 weft_env_brdf_lut(float n_dot_v_1, float roughness_6)
{
    float2 uv_6 = float2(saturate(n_dot_v_1), saturate(roughness_6));
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv_6, 0.0);
    return _e8.xy;
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

WeftLightGeometry weft_main_light_geometry(float3 n_4, float3 v_1)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_1), n_4);
    const float _e6 = weft_clamp_cos(dot(n_4, v_1));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_4, _e2)), saturate(dot(n_4, _e4)), saturate(dot(v_1, _e4)));
    return weftlightgeometry;
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
    const float3 _e55 = weft_safe_normalize(mul(in_2.normal, normal3_), (0.0).xxx);
    out_.world_normal = _e55;
    const float3 _e62 = weft_safe_normalize(mul(in_2.tangent.xyz, model3_), (0.0).xxx);
    out_.world_tangent = float4(_e62, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out_;
    const WeftVaryings weftvaryings = _e66;
    return weftvaryings;
}

float3x3 weft_tangent_frame(float3 n_5, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_5 * dot(n_5, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_5);
    float3 t = (ok ? (t_proj * rsqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_2 = (cross(n_5, t) * s_1);
    return float3x3(t, b_2, n_5);
}

float2 weft_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

uint4 glint_pcg4d(uint4 v_in)
{
    uint4 v_2 = (uint4)0;

    v_2 = ((v_in * 1664525u) + (1013904223u).xxxx);
    uint _e8 = v_2.x;
    uint _e10 = v_2.y;
    uint _e12 = v_2.w;
    v_2.x = (_e8 + (_e10 * _e12));
    uint _e16 = v_2.y;
    uint _e18 = v_2.z;
    uint _e20 = v_2.x;
    v_2.y = (_e16 + (_e18 * _e20));
    uint _e24 = v_2.z;
    uint _e26 = v_2.x;
    uint _e28 = v_2.y;
    v_2.z = (_e24 + (_e26 * _e28));
    uint _e32 = v_2.w;
    uint _e34 = v_2.y;
    uint _e36 = v_2.z;
    v_2.w = (_e32 + (_e34 * _e36));
    uint4 _e39 = v_2;
    uint4 _e40 = v_2;
    v_2 = (_e39 ^ (_e40 >> (16u).xxxx));
    uint _e46 = v_2.x;
    uint _e48 = v_2.y;
    uint _e50 = v_2.w;
    v_2.x = (_e46 + (_e48 * _e50));
    uint _e54 = v_2.y;
    uint _e56 = v_2.z;
    uint _e58 = v_2.x;
    v_2.y = (_e54 + (_e56 * _e58));
    uint _e62 = v_2.z;
    uint _e64 = v_2.x;
    uint _e66 = v_2.y;
    v_2.z = (_e62 + (_e64 * _e66));
    uint _e70 = v_2.w;
    uint _e72 = v_2.y;
    uint _e74 = v_2.z;
    v_2.w = (_e70 + (_e72 * _e74));
    uint4 _e77 = v_2;
    return _e77;
}

uint3 glint_pcg3d(uint3 v_in_1)
{
    uint3 v_3 = (uint3)0;

    v_3 = ((v_in_1 * 1664525u) + (1013904223u).xxx);
    uint _e8 = v_3.x;
    uint _e10 = v_3.y;
    uint _e12 = v_3.z;
    v_3.x = (_e8 + (_e10 * _e12));
    uint _e16 = v_3.y;
    uint _e18 = v_3.z;
    uint _e20 = v_3.x;
    v_3.y = (_e16 + (_e18 * _e20));
    uint _e24 = v_3.z;
    uint _e26 = v_3.x;
    uint _e28 = v_3.y;
    v_3.z = (_e24 + (_e26 * _e28));
    uint3 _e31 = v_3;
    uint3 _e32 = v_3;
    v_3 = (_e31 ^ (_e32 >> (16u).xxx));
    uint _e38 = v_3.x;
    uint _e40 = v_3.y;
    uint _e42 = v_3.z;
    v_3.x = (_e38 + (_e40 * _e42));
    uint _e46 = v_3.y;
    uint _e48 = v_3.z;
    uint _e50 = v_3.x;
    v_3.y = (_e46 + (_e48 * _e50));
    uint _e54 = v_3.z;
    uint _e56 = v_3.x;
    uint _e58 = v_3.y;
    v_3.z = (_e54 + (_e56 * _e58));
    uint3 _e61 = v_3;
    return _e61;
}

float3 glint_unit3_(uint3 v_4)
{
    return ((float3((v_4 >> (8u).xxx)) + (0.5).xxx) * 5.9604645e-8);
}

float4 glint_unit4_(uint4 v_5)
{
    return ((float4((v_5 >> (8u).xxxx)) + (0.5).xxxx) * 5.9604645e-8);
}

float glint_hash13_(float3 p_in)
{
    float3 p3_ = (float3)0;

    p3_ = frac((p_in * 0.1031));
    float3 _e5 = p3_;
    float3 _e6 = p3_;
    float3 _e7 = p3_;
    p3_ = (_e5 + (dot(_e6, (_e7.yzx + (33.33).xxx))).xxx);
    float _e16 = p3_.x;
    float _e18 = p3_.y;
    float _e21 = p3_.z;
    return frac(((_e16 + _e18) * _e21));
}

float glint_erfinv(float x_1)
{
    float w = (float)0;
    float p = (float)0;

    w = -(log(max(((1.0 - x_1) * (1.0 + x_1)), 1e-30)));
    float _e12 = w;
    if ((_e12 < 5.0)) {
        float _e15 = w;
        w = (_e15 - 2.5);
        p = 2.8102264e-8;
        float _e19 = p;
        float _e20 = w;
        p = (3.4327394e-7 + (_e19 * _e20));
        float _e24 = p;
        float _e25 = w;
        p = (-3.5233877e-6 + (_e24 * _e25));
        float _e29 = p;
        float _e30 = w;
        p = (-4.3915065e-6 + (_e29 * _e30));
        float _e34 = p;
        float _e35 = w;
        p = (0.00021858087 + (_e34 * _e35));
        float _e39 = p;
        float _e40 = w;
        p = (-0.001253725 + (_e39 * _e40));
        float _e44 = p;
        float _e45 = w;
        p = (-0.0041776816 + (_e44 * _e45));
        float _e49 = p;
        float _e50 = w;
        p = (0.24664073 + (_e49 * _e50));
        float _e54 = p;
        float _e55 = w;
        p = (1.5014094 + (_e54 * _e55));
    } else {
        float _e59 = w;
        w = (sqrt(_e59) - 3.0);
        p = -0.00020021426;
        float _e64 = p;
        float _e65 = w;
        p = (0.00010095056 + (_e64 * _e65));
        float _e69 = p;
        float _e70 = w;
        p = (0.0013493432 + (_e69 * _e70));
        float _e74 = p;
        float _e75 = w;
        p = (-0.0036734284 + (_e74 * _e75));
        float _e79 = p;
        float _e80 = w;
        p = (0.0057395077 + (_e79 * _e80));
        float _e84 = p;
        float _e85 = w;
        p = (-0.0076224613 + (_e84 * _e85));
        float _e89 = p;
        float _e90 = w;
        p = (0.0094388705 + (_e89 * _e90));
        float _e94 = p;
        float _e95 = w;
        p = (1.001674 + (_e94 * _e95));
        float _e99 = p;
        float _e100 = w;
        p = (2.8329768 + (_e99 * _e100));
    }
    float _e104 = p;
    return (_e104 * x_1);
}

float glint_erfinv_poly(float x_in)
{
    float x_3 = clamp(x_in, -0.95, 0.95);
    float x2_1 = (x_3 * x_3);
    return (x_3 * (0.864441 + (x2_1 * (0.533641 + (x2_1 * (-0.893165 + (x2_1 * 1.108999)))))));
}

float glint_erfinv_by(float x_2, bool poly)
{
    if (poly) {
        const float _e2 = glint_erfinv_poly(x_2);
        return _e2;
    }
    const float _e3 = glint_erfinv(x_2);
    return _e3;
}

float3 glint_gaussian3_(float3 u, bool poly_normals)
{
    const float _e7 = glint_erfinv_by(((2.0 * u.x) - 1.0), poly_normals);
    const float _e13 = glint_erfinv_by(((2.0 * u.y) - 1.0), poly_normals);
    const float _e19 = glint_erfinv_by(((2.0 * u.z) - 1.0), poly_normals);
    return (1.4142135 * float3(_e7, _e13, _e19));
}

uint2 naga_f2u32(float2 value) {
    return uint2(clamp(value, 0.0, 4294967000.0));
}

float2 glint_corner(float2 c_1, bool poly_normals_1)
{
    uint2 texel = naga_f2u32((c_1 - (GLINT_TABLE_SIZE * floor((c_1 / (64.0).xx)))));
    const uint4 _e13 = glint_pcg4d(uint4(texel, 6777961u, 1953785202u));
    const float4 _e14 = glint_unit4_(_e13);
    const float _e21 = glint_erfinv_by(((2.0 * _e14.y) - 1.0), poly_normals_1);
    return float2(_e14.x, (1.4142135 * _e21));
}

GlintSlopeRand glint_slope_rand(float micro_roughness, float2 slope, float2 offset, bool poly_normals_2)
{
    GlintSlopeRand out_1 = (GlintSlopeRand)0;

    float2 s_2 = ((abs(slope) / (micro_roughness).xx) + (offset * GLINT_TABLE_SIZE));
    float2 cell = floor(s_2);
    const float2 _e11 = glint_corner(cell, poly_normals_2);
    const float2 _e16 = glint_corner((cell + float2(0.0, 1.0)), poly_normals_2);
    const float2 _e21 = glint_corner((cell + float2(1.0, 0.0)), poly_normals_2);
    const float2 _e26 = glint_corner((cell + float2(1.0, 1.0)), poly_normals_2);
    out_1.gate_rand = float4(_e11.x, _e16.x, _e21.x, _e26.x);
    out_1.gaussian = float4(_e11.y, _e16.y, _e21.y, _e26.y);
    out_1.lerp_ = (s_2 - cell);
    GlintSlopeRand _e42 = out_1;
    const GlintSlopeRand glintsloperand = _e42;
    return glintsloperand;
}

float glint_cell_hits(GlintSlopeRand r, float one_hit, float smooth_width, float mean, float deviation, float count)
{
    float4 gate = (float4)0;

    if ((smooth_width > 1e-7)) {
        gate = saturate(((r.gate_rand - ((one_hit + smooth_width)).xxxx) / ((-2.0 * smooth_width)).xxxx));
    } else {
        const float4 _e25 = weft_select4_f32bit((r.gate_rand < (one_hit).xxxx), (1.0).xxxx, (0.0).xxxx);
        gate = _e25;
    }
    float4 gauss = clamp(floor(((r.gaussian * deviation) + (mean).xxxx)), (0.0).xxxx, (count).xxxx);
    float4 _e35 = gate;
    float4 hits = (_e35 * ((1.0).xxxx + gauss));
    float x0_ = lerp(hits.x, hits.z, r.lerp_.x);
    float x1_ = lerp(hits.y, hits.w, r.lerp_.x);
    return lerp(x0_, x1_, r.lerp_.y);
}

GlintSimplex ConstructGlintSimplex(int2 arg0, int arg1, float3 arg2) {
    GlintSimplex ret = (GlintSimplex)0;
    ret.id = arg0;
    ret.si = arg1;
    ret.bary = arg2;
    return ret;
}

int2 naga_f2i32(float2 value) {
    return int2(clamp(value, -2147483600.0, 2147483500.0));
}

int naga_f2i32(float value) {
    return int(clamp(value, -2147483600.0, 2147483500.0));
}

GlintSimplex glint_simplex(float2 uv_1)
{
    float2 skewed = float2((uv_1.x - (0.57735026 * uv_1.y)), (1.1547005 * uv_1.y));
    float2 base = floor(skewed);
    float2 f = (skewed - base);
    float fz = ((1.0 - f.x) - f.y);
    float s_3 = ((fz < 0.0) ? 1.0 : 0.0);
    float s2_ = ((2.0 * s_3) - 1.0);
    const GlintSimplex glintsimplex = ConstructGlintSimplex(naga_f2i32(base), naga_f2i32(s_3), float3((-(fz) * s2_), (s_3 - (f.y * s2_)), (s_3 - (f.x * s2_))));
    return glintsimplex;
}

float glint_sample_grid(GlintParams params, GlintGrid grid, float2 slope_1, float target_ndf, bool poly_normals_3)
{
    const GlintSimplex _e6 = glint_simplex(grid.uv);
    int2 id = _e6.id;
    int si = _e6.si;
    int2 c0_ = asint(asuint(id) + asuint(int2(si, si)));
    int2 c1_ = asint(asuint(id) + asuint(int2(si, asint(asuint(int(1)) - asuint(si)))));
    int2 c2_ = asint(asuint(id) + asuint(int2(asint(asuint(int(1)) - asuint(si)), si)));
    float3 bary = _e6.bary;
    const uint3 _e29 = glint_pcg3d(uint3((asuint(c0_.x) + 2147483648u), (asuint(c0_.y) + 2147483648u), grid.seed));
    const float3 _e30 = glint_unit3_(_e29);
    const uint3 _e39 = glint_pcg3d(uint3((asuint(c1_.x) + 2147483648u), (asuint(c1_.y) + 2147483648u), grid.seed));
    const float3 _e40 = glint_unit3_(_e39);
    const uint3 _e49 = glint_pcg3d(uint3((asuint(c2_.x) + 2147483648u), (asuint(c2_.y) + 2147483648u), grid.seed));
    const float3 _e50 = glint_unit3_(_e49);
    const GlintSlopeRand _e53 = glint_slope_rand(params.micro_roughness, slope_1, _e30.yz, poly_normals_3);
    const GlintSlopeRand _e56 = glint_slope_rand(params.micro_roughness, slope_1, _e40.yz, poly_normals_3);
    const GlintSlopeRand _e59 = glint_slope_rand(params.micro_roughness, slope_1, _e50.yz, poly_normals_3);
    const float3 _e64 = glint_gaussian3_(float3(_e30.x, _e40.x, _e50.x), poly_normals_3);
    float3 log_density = clamp(((_e64 * params.density_randomization) + (params.log_density).xxx), (0.0).xxx, (50.0).xxx);
    float3 count_1 = max((1e-8).xxx, (grid.cell_area * exp(log_density)));
    float3 blended = (count_1 * grid.weight);
    float p_4 = (params.micro_roughness * target_ndf);
    float3 one_hit_1 = ((1.0).xxx - pow(((1.0 - p_4)).xxx, blended));
    float3 others = max((blended - (1.0).xxx), (0.0).xxx);
    float3 mean_1 = (others * p_4);
    float3 deviation_1 = sqrt((others * (p_4 * (1.0 - p_4))));
    float3 smooth_width_1 = ((0.1 * saturate((one_hit_1 * 10.0))) * saturate((((1.0).xxx - one_hit_1) * 10.0)));
    const float _e121 = glint_cell_hits(_e53, one_hit_1.x, smooth_width_1.x, mean_1.x, deviation_1.x, blended.x);
    const float _e127 = glint_cell_hits(_e56, one_hit_1.y, smooth_width_1.y, mean_1.y, deviation_1.y, blended.y);
    const float _e133 = glint_cell_hits(_e59, one_hit_1.z, smooth_width_1.z, mean_1.z, deviation_1.z, blended.z);
    return dot((float3(_e121, _e127, _e133) / count_1), bary);
}

GlintEllipse glint_ellipse(float2 duv_dx, float2 duv_dy)
{
    GlintEllipse out_2 = (GlintEllipse)0;

    float a_5 = ((duv_dx.x * duv_dx.x) + (duv_dy.x * duv_dy.x));
    float b_3 = ((duv_dx.x * duv_dx.y) + (duv_dy.x * duv_dy.y));
    float d_4 = ((duv_dx.y * duv_dx.y) + (duv_dy.y * duv_dy.y));
    float half_trace = (0.5 * (a_5 + d_4));
    float disc = sqrt(max((((0.25 * (a_5 - d_4)) * (a_5 - d_4)) + (b_3 * b_3)), 0.0));
    float l1_ = (half_trace + disc);
    float l2_ = max((half_trace - disc), 0.0);
    float2 e_a = float2(b_3, (l1_ - a_5));
    float2 e_b = float2((l1_ - d_4), b_3);
    float2 e_5 = ((dot(e_a, e_a) > dot(e_b, e_b)) ? e_a : e_b);
    float e_len2_ = dot(e_5, e_5);
    out_2.major_dir = ((e_len2_ > 1e-37) ? (e_5 * rsqrt(max(e_len2_, 1e-37))) : float2(1.0, 0.0));
    out_2.major = max(sqrt(l1_), 1e-12);
    float _e68 = out_2.major;
    out_2.minor = max(sqrt(l2_), (_e68 / 64.0));
    GlintEllipse _e72 = out_2;
    const GlintEllipse glintellipse = _e72;
    return glintellipse;
}

float2 glint_rotate(float2 uv_2, float angle)
{
    float c_4 = cos(angle);
    float s_4 = sin(angle);
    return float2(((c_4 * uv_2.x) + (s_4 * uv_2.y)), ((c_4 * uv_2.y) - (s_4 * uv_2.x)));
}

uint naga_f2u32(float value) {
    return uint(clamp(value, 0.0, 4294967000.0));
}

uint glint_grid_seed(float lod, float theta, float ratio)
{
    float t_1 = (theta - (GLINT_TAU * trunc((theta / GLINT_TAU))));
    const float _e10 = glint_hash13_(float3(lod, t_1, ratio));
    return naga_f2u32(min((_e10 * 4294967300.0), 4294967000.0));
}

GlintGrid glint_make_grid(float2 uv_3, float lod_1, float theta_1, float ratio_1, float weight)
{
    GlintGrid g = (GlintGrid)0;

    const float2 _e7 = glint_rotate(uv_3, theta_1);
    g.uv = ((_e7 * exp2(-(lod_1))) / float2(1.0, ratio_1));
    const uint _e15 = glint_grid_seed(lod_1, theta_1, ratio_1);
    g.seed = _e15;
    g.cell_area = (ratio_1 * exp2((2.0 * lod_1)));
    g.weight = weight;
    GlintGrid _e22 = g;
    const GlintGrid glintgrid = _e22;
    return glintgrid;
}

float4 glint_tetra_weights(float3 p_1, float3 a, float3 b, float3 c_2, float3 d)
{
    float3 c1_1 = (a - d);
    float3 c2_1 = (b - d);
    float3 c3_ = (c_2 - d);
    float3 q = (p_1 - d);
    float det = dot(c1_1, cross(c2_1, c3_));
    float inv = (1.0 / det);
    float w1_ = (dot(q, cross(c2_1, c3_)) * inv);
    float w2_ = (dot(c1_1, cross(q, c3_)) * inv);
    float w3_ = (dot(c1_1, cross(c2_1, q)) * inv);
    return float4(w1_, w2_, w3_, (((1.0 - w1_) - w2_) - w3_));
}

float glint_lod(GlintEllipse e_1, float screen_scale)
{
    return clamp(log2(((e_1.minor * screen_scale) * 0.5)), GLINT_MIN_LOD, GLINT_MAX_LOD);
}

GlintFootprintCell glint_footprint_cell(GlintEllipse e_2, float screen_scale_1)
{
    GlintFootprintCell out_3 = (GlintFootprintCell)0;

    float ratio_e = min((e_2.major / (e_2.minor + (1e-8 * e_2.major))), GLINT_MAX_RATIO);
    const float _e11 = glint_lod(e_2, screen_scale_1);
    float lod0_1 = floor(_e11);
    float lod_lerp = (_e11 - lod0_1);
    float ratio0_1 = max(exp2(floor(log2(max(ratio_e, 1.0)))), 1.0);
    float ratio1_ = (ratio0_1 * 2.0);
    float ratio_lerp = saturate(((ratio_e - ratio0_1) / (ratio1_ - ratio0_1)));
    float q_1 = (0.7853982 / max(ratio0_1, 2.0));
    float per_pi = (4.0 * max(ratio0_1, 2.0));
    float theta_3 = atan2(-(e_2.major_dir.x), e_2.major_dir.y);
    float theta_q = (theta_3 / q_1);
    float h0_ = floor(theta_q);
    float theta_lerp_1 = saturate((theta_q - h0_));
    float i0_ = (h0_ - (per_pi * floor((h0_ / per_pi))));
    float i1_ = ((i0_ + 1.0) - (per_pi * floor(((i0_ + 1.0) / per_pi))));
    float theta_bin0_ = (i0_ * q_1);
    float theta_bin_h = ((i0_ + 0.5) * q_1);
    float theta_bin1_ = (i1_ * q_1);
    out_3.theta_lerp = theta_lerp_1;
    out_3.ratio_lerp = ratio_lerp;
    out_3.lod_lerp = lod_lerp;
    out_3.center_ = (ratio0_1 == 1.0);
    out_3.bin0_ = theta_bin0_;
    out_3.bin_h = theta_bin_h;
    out_3.bin1_ = theta_bin1_;
    out_3.lod0_ = lod0_1;
    out_3.ratio0_ = ratio0_1;
    GlintFootprintCell _e74 = out_3;
    const GlintFootprintCell glintfootprintcell = _e74;
    return glintfootprintcell;
}

GlintTetra glint_tetra(GlintEllipse e_3, float screen_scale_2)
{
    float theta_lerp = (float)0;
    float3 p0_ = (float3)0;
    float3 p1_ = (float3)0;
    float3 p2_ = (float3)0;
    float3 p3_1 = (float3)0;
    bool local_1 = (bool)0;
    GlintTetra out_4 = (GlintTetra)0;

    const GlintFootprintCell _e2 = glint_footprint_cell(e_3, screen_scale_2);
    theta_lerp = _e2.theta_lerp;
    float ratio_lerp_1 = _e2.ratio_lerp;
    float lod_lerp_1 = _e2.lod_lerp;
    bool center_1 = _e2.center_;
    if (center_1) {
        float3 a_6 = float3(0.0, 1.0, 0.0);
        float3 b_4 = float3(0.0, 0.0, 0.0);
        float3 c_5 = float3(1.0, 1.0, 0.0);
        float3 d_5 = float3(0.0, 1.0, 1.0);
        float3 ee = float3(0.0, 0.0, 1.0);
        float3 f_1 = float3(1.0, 1.0, 1.0);
        if ((lod_lerp_1 > (1.0 - ratio_lerp_1))) {
            float _e45 = theta_lerp;
            if ((((lod_lerp_1 - (1.0 - ratio_lerp_1)) / max(ratio_lerp_1, 1e-8)) > _e45)) {
                p0_ = a_6;
                p1_ = ee;
                p2_ = d_5;
                p3_1 = f_1;
            } else {
                p0_ = f_1;
                p1_ = ee;
                p2_ = c_5;
                p3_1 = a_6;
            }
        } else {
            p0_ = b_4;
            p1_ = a_6;
            p2_ = c_5;
            p3_1 = ee;
        }
        float _e47 = theta_lerp;
        theta_lerp = (_e47 * ratio_lerp_1);
    } else {
        float3 a_7 = float3(0.0, 1.0, 0.0);
        float3 b_5 = float3(0.0, 0.0, 0.0);
        float3 c_6 = float3(0.5, 1.0, 0.0);
        float3 d_6 = float3(1.0, 0.0, 0.0);
        float3 ee_1 = float3(1.0, 1.0, 0.0);
        float3 f_2 = float3(0.0, 1.0, 1.0);
        float3 g_1 = float3(0.0, 0.0, 1.0);
        float3 h_1 = float3(0.5, 1.0, 1.0);
        float3 i = float3(1.0, 0.0, 1.0);
        float3 j = float3(1.0, 1.0, 1.0);
        float _e89 = theta_lerp;
        if ((_e89 < 0.5)) {
            float _e94 = theta_lerp;
            local_1 = ((_e94 * 2.0) < ratio_lerp_1);
        } else {
            local_1 = false;
        }
        bool _e99 = local_1;
        if (_e99) {
            if ((lod_lerp_1 > (1.0 - ratio_lerp_1))) {
                float _e109 = theta_lerp;
                if ((((lod_lerp_1 - (1.0 - ratio_lerp_1)) / max(ratio_lerp_1, 1e-8)) > ((_e109 * 2.0) / max(ratio_lerp_1, 1e-8)))) {
                    p0_ = a_7;
                    p1_ = f_2;
                    p2_ = h_1;
                    p3_1 = g_1;
                } else {
                    p0_ = c_6;
                    p1_ = a_7;
                    p2_ = h_1;
                    p3_1 = g_1;
                }
            } else {
                p0_ = b_5;
                p1_ = a_7;
                p2_ = c_6;
                p3_1 = g_1;
            }
        } else {
            float _e116 = theta_lerp;
            if (((1.0 - ((_e116 - 0.5) * 2.0)) > ratio_lerp_1)) {
                if ((lod_lerp_1 < (1.0 - ratio_lerp_1))) {
                    float half_width = (0.5 * (1.0 - ratio_lerp_1));
                    float _e136 = theta_lerp;
                    if (((lod_lerp_1 / max((1.0 - ratio_lerp_1), 1e-8)) > ((_e136 - (0.5 - half_width)) / max((2.0 * half_width), 1e-8)))) {
                        p0_ = b_5;
                        p1_ = g_1;
                        p2_ = i;
                        p3_1 = c_6;
                    } else {
                        p0_ = d_6;
                        p1_ = b_5;
                        p2_ = c_6;
                        p3_1 = i;
                    }
                } else {
                    p0_ = c_6;
                    p1_ = g_1;
                    p2_ = h_1;
                    p3_1 = i;
                }
            } else {
                if ((lod_lerp_1 > (1.0 - ratio_lerp_1))) {
                    float _e155 = theta_lerp;
                    if ((((lod_lerp_1 - (1.0 - ratio_lerp_1)) / max(ratio_lerp_1, 1e-8)) > ((((_e155 - 0.5) * 2.0) - (1.0 - ratio_lerp_1)) / max(ratio_lerp_1, 1e-8)))) {
                        p0_ = c_6;
                        p1_ = j;
                        p2_ = h_1;
                        p3_1 = i;
                    } else {
                        p0_ = ee_1;
                        p1_ = i;
                        p2_ = c_6;
                        p3_1 = j;
                    }
                } else {
                    p0_ = d_6;
                    p1_ = ee_1;
                    p2_ = c_6;
                    p3_1 = i;
                }
            }
        }
    }
    float3 _e169 = p0_;
    out_4.p0_ = _e169;
    float3 _e171 = p1_;
    out_4.p1_ = _e171;
    float3 _e173 = p2_;
    out_4.p2_ = _e173;
    float3 _e175 = p3_1;
    out_4.p3_ = _e175;
    float _e177 = theta_lerp;
    float3 _e179 = p0_;
    float3 _e180 = p1_;
    float3 _e181 = p2_;
    float3 _e182 = p3_1;
    const float4 _e183 = glint_tetra_weights(float3(_e177, ratio_lerp_1, lod_lerp_1), _e179, _e180, _e181, _e182);
    out_4.w = _e183;
    out_4.center_ = center_1;
    out_4.bin0_ = _e2.bin0_;
    out_4.bin_h = _e2.bin_h;
    out_4.bin1_ = _e2.bin1_;
    out_4.lod0_ = _e2.lod0_;
    out_4.ratio0_ = _e2.ratio0_;
    GlintTetra _e195 = out_4;
    const GlintTetra glinttetra = _e195;
    return glinttetra;
}

GlintGrid glint_vertex_grid(float2 uv_4, float3 p_2, float weight_1, bool center_, float bin0_, float bin_h, float bin1_, float lod0_, float ratio0_)
{
    float theta_2 = (float)0;
    bool local_2 = (bool)0;

    float rot_index = (p_2.x * 2.0);
    theta_2 = ((rot_index < 0.5) ? bin0_ : ((rot_index < 1.5) ? bin_h : bin1_));
    if (center_) {
        local_2 = (p_2.y == 0.0);
    } else {
        local_2 = false;
    }
    bool _e25 = local_2;
    if (_e25) {
        theta_2 = 0.0;
    }
    float ratio_2 = ((p_2.y > 0.5) ? (ratio0_ * 2.0) : ratio0_);
    float lod_2 = (lod0_ + p_2.z);
    float _e35 = theta_2;
    const GlintGrid _e36 = glint_make_grid(uv_4, lod_2, _e35, ratio_2, weight_1);
    const GlintGrid glintgrid_1 = _e36;
    return glintgrid_1;
}

GlintGrids glint_grids(float2 uv_5, GlintEllipse e_4, float screen_scale_3)
{
    GlintGrids out_5 = (GlintGrids)0;

    const GlintTetra _e3 = glint_tetra(e_4, screen_scale_3);
    const GlintGrid _e15 = glint_vertex_grid(uv_5, _e3.p0_, _e3.w.x, _e3.center_, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g0_ = _e15;
    const GlintGrid _e26 = glint_vertex_grid(uv_5, _e3.p1_, _e3.w.y, _e3.center_, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g1_ = _e26;
    const GlintGrid _e37 = glint_vertex_grid(uv_5, _e3.p2_, _e3.w.z, _e3.center_, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g2_ = _e37;
    const GlintGrid _e48 = glint_vertex_grid(uv_5, _e3.p3_, _e3.w.w, _e3.center_, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g3_ = _e48;
    GlintGrids _e49 = out_5;
    const GlintGrids glintgrids = _e49;
    return glintgrids;
}

float glint_ndf(GlintParams params_1, GlintGrids grids, float2 slope_2, float d_1, float d_max, bool poly_normals_4)
{
    float target_ndf_1 = (d_1 / d_max);
    const float _e8 = glint_sample_grid(params_1, grids.g0_, slope_2, target_ndf_1, poly_normals_4);
    const float _e10 = glint_sample_grid(params_1, grids.g1_, slope_2, target_ndf_1, poly_normals_4);
    const float _e13 = glint_sample_grid(params_1, grids.g2_, slope_2, target_ndf_1, poly_normals_4);
    const float _e16 = glint_sample_grid(params_1, grids.g3_, slope_2, target_ndf_1, poly_normals_4);
    float sum = (((_e8 + _e10) + _e13) + _e16);
    return (min((sum / params_1.micro_roughness), 20.0) * d_max);
}

GlintParams glitter_params()
{
    GlintParams p_3 = (GlintParams)0;

    float _e4 = material.flake_density;
    p_3.log_density = (4.0 + (28.0 * saturate(_e4)));
    float _e13 = material.twinkle;
    p_3.micro_roughness = exp2(lerp(-4.321928, -8.965784, saturate(_e13)));
    float _e22 = material.density_variation;
    p_3.density_randomization = clamp(_e22, 0.0, 4.0);
    GlintParams _e26 = p_3;
    const GlintParams glintparams = _e26;
    return glintparams;
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
    bool local = (bool)0;
    float d_flakes = (float)0;

    float4 _e4 = material.base_map_st;
    const float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    float2 duv_dx_1 = ddx(_e5);
    float2 duv_dy_1 = ddy(_e5);
    float4 _e10 = material.base_color;
    float4 _e13 = base_map.Sample(material_sampler, _e5);
    float4 base_rgba = (_e10 * _e13);
    float3 base_1 = saturate(base_rgba.xyz);
    float alpha = saturate(base_rgba.w);
    float _e21 = material.metallic;
    float metallic = saturate(_e21);
    float _e25 = material.smoothness;
    float roughness_7 = (1.0 - saturate(_e25));
    float4 _e31 = occlusion_map.Sample(material_sampler, _e5);
    float occlusion = _e31.x;
    float _e35 = material.occlusion_strength;
    float ao = saturate(lerp(1.0, occlusion, _e35));
    const WeftSurface _e41 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_6 = _e41.v;
    n = _e41.n;
    float3 _e45 = n;
    const float3x3 _e47 = weft_tangent_frame(_e45, in_1.world_tangent);
    float3 _e48 = n;
    const WeftLightGeometry _e49 = weft_main_light_geometry(_e48, v_6);
    const float3 _e50 = weft_main_light_radiance();
    float3 f0_2 = lerp((0.04).xxx, base_1, metallic);
    float3 diffuse_albedo = (base_1 * (1.0 - metallic));
    const float _e59 = weft_v_smith_ggx_correlated(_e49.n_dot_v, _e49.n_dot_l, roughness_7);
    const float2 _e61 = weft_env_brdf_lut(_e49.n_dot_v, roughness_7);
    const float3 _e62 = weft_env_brdf_from_lut(f0_2, _e61);
    float3 kd = max(((1.0).xxx - _e62), (0.0).xxx);
    float3 _e69 = n;
    const float _e71 = weft_d_ggx_nh(_e69, _e49.h, roughness_7);
    const float3 _e74 = weft_f_schlick(f0_2, _e49.v_dot_h);
    float3 specular = ((_e71 * _e59) * _e74);
    const float3 _e76 = weft_diffuse_lambert(diffuse_albedo);
    float3 direct = ((((kd * _e76) + specular) * _e50) * _e49.n_dot_l);
    float3 _e83 = n;
    const float3 _e85 = weft_prefiltered_radiance(reflect(-(v_6), _e83), roughness_7);
    float3 _e88 = n;
    const float3 _e89 = weft_sh_irradiance(_e88);
    float3 indirect = (((_e85 * _e62) * ao) + (((_e89 * ao) * kd) * diffuse_albedo));
    color = (direct + indirect);
    float _e98 = material.flake_intensity;
    float intensity = max(_e98, 0.0);
    if ((intensity > 0.0)) {
        local = (_e49.n_dot_l > 0.0);
    } else {
        local = false;
    }
    bool _e109 = local;
    if (_e109) {
        float _e112 = material.flake_roughness;
        float r_f = clamp(_e112, 0.05, 1.0);
        float3 _e116 = n;
        const float _e118 = weft_d_ggx_nh(_e116, _e49.h, r_f);
        const float _e120 = weft_d_ggx(1.0, r_f);
        float4 _e123 = material.flake_color;
        float3 flake_f0_ = saturate(_e123.xyz);
        const float _e128 = weft_v_smith_ggx_correlated(_e49.n_dot_v, _e49.n_dot_l, r_f);
        {
            {
                float2 slope_3 = float2(dot(_e47[0], _e49.h), dot(_e47[1], _e49.h));
                const GlintParams _e137 = glitter_params();
                const GlintEllipse _e138 = glint_ellipse(duv_dx_1, duv_dy_1);
                float _e141 = material.flake_size;
                float screen_scale_4 = clamp(_e141, 1.0, 8.0);
                const GlintGrids _e145 = glint_grids(_e5, _e138, screen_scale_4);
                const float _e147 = glint_ndf(_e137, _e145, slope_3, _e118, _e120, false);
                d_flakes = _e147;
            }
            float3 _e148 = color;
            float _e149 = d_flakes;
            const float3 _e153 = weft_f_schlick(flake_f0_, _e49.v_dot_h);
            color = (_e148 + (((((intensity * _e149) * _e128) * _e153) * _e50) * _e49.n_dot_l));
        }
    }
    float3 _e159 = color;
    float3 radiance = clamp(_e159, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
