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

struct GlintTetraFast {
    uint codes;
    int _pad1_0;
    int _pad1_1;
    int _pad1_2;
    float4 w;
    float bin0_;
    float bin_h;
    float bin1_;
    float lod0_;
    float ratio0_;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
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
    float r = saturate(roughness_4);
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

float3 weft_prefiltered_radiance(float3 dir, float roughness_5)
{
    const float _e4 = weft_specular_mip(roughness_5);
    float4 c_4 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_4.xyz, (0.0).xxx);
}

float2 weft_env_brdf_lut(float n_dot_v_1, float roughness_6)
{
    float2 uv_5 = float2(saturate(n_dot_v_1), saturate(roughness_6));
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv_5, 0.0);
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

uint3 glint_pcg3d(uint3 v_in)
{
    uint3 v_2 = (uint3)0;

    v_2 = ((v_in * 1664525u) + (1013904223u).xxx);
    uint _e8 = v_2.x;
    uint _e10 = v_2.y;
    uint _e12 = v_2.z;
    v_2.x = (_e8 + (_e10 * _e12));
    uint _e16 = v_2.y;
    uint _e18 = v_2.z;
    uint _e20 = v_2.x;
    v_2.y = (_e16 + (_e18 * _e20));
    uint _e24 = v_2.z;
    uint _e26 = v_2.x;
    uint _e28 = v_2.y;
    v_2.z = (_e24 + (_e26 * _e28));
    uint3 _e31 = v_2;
    uint3 _e32 = v_2;
    v_2 = (_e31 ^ (_e32 >> (16u).xxx));
    uint _e38 = v_2.x;
    uint _e40 = v_2.y;
    uint _e42 = v_2.z;
    v_2.x = (_e38 + (_e40 * _e42));
    uint _e46 = v_2.y;
    uint _e48 = v_2.z;
    uint _e50 = v_2.x;
    v_2.y = (_e46 + (_e48 * _e50));
    uint _e54 = v_2.z;
    uint _e56 = v_2.x;
    uint _e58 = v_2.y;
    v_2.z = (_e54 + (_e56 * _e58));
    uint3 _e61 = v_2;
    return _e61;
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
    float s_2 = ((fz < 0.0) ? 1.0 : 0.0);
    float s2_ = ((2.0 * s_2) - 1.0);
    const GlintSimplex glintsimplex = ConstructGlintSimplex(naga_f2i32(base), naga_f2i32(s_2), float3((-(fz) * s2_), (s_2 - (f.y * s2_)), (s_2 - (f.x * s2_))));
    return glintsimplex;
}

GlintEllipse glint_ellipse(float2 duv_dx, float2 duv_dy)
{
    GlintEllipse out_1 = (GlintEllipse)0;

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
    out_1.major_dir = ((e_len2_ > 1e-37) ? (e_5 * rsqrt(max(e_len2_, 1e-37))) : float2(1.0, 0.0));
    out_1.major = max(sqrt(l1_), 1e-12);
    float _e68 = out_1.major;
    out_1.minor = max(sqrt(l2_), (_e68 / 64.0));
    GlintEllipse _e72 = out_1;
    const GlintEllipse glintellipse = _e72;
    return glintellipse;
}

float2 glint_rotate(float2 uv_2, float angle)
{
    float c_5 = cos(angle);
    float s_3 = sin(angle);
    return float2(((c_5 * uv_2.x) + (s_3 * uv_2.y)), ((c_5 * uv_2.y) - (s_3 * uv_2.x)));
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

float4 glint_tetra_weights(float3 p, float3 a, float3 b, float3 c_1, float3 d)
{
    float3 c1_ = (a - d);
    float3 c2_ = (b - d);
    float3 c3_ = (c_1 - d);
    float3 q = (p - d);
    float det = dot(c1_, cross(c2_, c3_));
    float inv = (1.0 / det);
    float w1_ = (dot(q, cross(c2_, c3_)) * inv);
    float w2_ = (dot(c1_, cross(q, c3_)) * inv);
    float w3_ = (dot(c1_, cross(c2_, q)) * inv);
    return float4(w1_, w2_, w3_, (((1.0 - w1_) - w2_) - w3_));
}

float glint_lod(GlintEllipse e_1, float screen_scale)
{
    return clamp(log2(((e_1.minor * screen_scale) * 0.5)), GLINT_MIN_LOD, GLINT_MAX_LOD);
}

GlintFootprintCell glint_footprint_cell(GlintEllipse e_2, float screen_scale_1)
{
    GlintFootprintCell out_2 = (GlintFootprintCell)0;

    float ratio_e = min((e_2.major / (e_2.minor + (1e-8 * e_2.major))), GLINT_MAX_RATIO);
    const float _e11 = glint_lod(e_2, screen_scale_1);
    float lod0_ = floor(_e11);
    float lod_lerp = (_e11 - lod0_);
    float ratio0_ = max(exp2(floor(log2(max(ratio_e, 1.0)))), 1.0);
    float ratio1_ = (ratio0_ * 2.0);
    float ratio_lerp = saturate(((ratio_e - ratio0_) / (ratio1_ - ratio0_)));
    float q_1 = (0.7853982 / max(ratio0_, 2.0));
    float per_pi = (4.0 * max(ratio0_, 2.0));
    float theta_2 = atan2(-(e_2.major_dir.x), e_2.major_dir.y);
    float theta_q = (theta_2 / q_1);
    float h0_ = floor(theta_q);
    float theta_lerp = saturate((theta_q - h0_));
    float i0_ = (h0_ - (per_pi * floor((h0_ / per_pi))));
    float i1_ = ((i0_ + 1.0) - (per_pi * floor(((i0_ + 1.0) / per_pi))));
    float theta_bin0_ = (i0_ * q_1);
    float theta_bin_h = ((i0_ + 0.5) * q_1);
    float theta_bin1_ = (i1_ * q_1);
    out_2.theta_lerp = theta_lerp;
    out_2.ratio_lerp = ratio_lerp;
    out_2.lod_lerp = lod_lerp;
    out_2.center_ = (ratio0_ == 1.0);
    out_2.bin0_ = theta_bin0_;
    out_2.bin_h = theta_bin_h;
    out_2.bin1_ = theta_bin1_;
    out_2.lod0_ = lod0_;
    out_2.ratio0_ = ratio0_;
    GlintFootprintCell _e74 = out_2;
    const GlintFootprintCell glintfootprintcell = _e74;
    return glintfootprintcell;
}

float glint_normal_fast(uint h_1)
{
    float x_2 = mad(float(h_1), 4.656613e-10, -1.0);
    float x2_1 = (x_2 * x_2);
    return (x_2 * (1.2225 + (x2_1 * (0.75468 + (x2_1 * (-1.263127 + (x2_1 * 1.568366)))))));
}

float glint_corner_hits(uint ax, uint ay, float gate_a, float gate_b, float deviation, float mean1_)
{
    uint x_1 = (uint)0;
    uint y = (uint)0;
    uint z = (uint)0;
    uint w = (uint)0;

    x_1 = (ax + (ay * 1860535849u));
    uint _e10 = x_1;
    y = (ay + (_e10 * 220351156u));
    uint _e16 = x_1;
    uint _e17 = y;
    z = (220351156u + (_e16 * _e17));
    uint _e22 = y;
    uint _e23 = z;
    w = (1860535849u + (_e22 * _e23));
    uint _e27 = x_1;
    uint _e28 = x_1;
    x_1 = (_e27 ^ (_e28 >> 16u));
    uint _e32 = y;
    uint _e33 = y;
    y = (_e32 ^ (_e33 >> 16u));
    uint _e37 = z;
    uint _e38 = z;
    z = (_e37 ^ (_e38 >> 16u));
    uint _e42 = w;
    uint _e43 = w;
    w = (_e42 ^ (_e43 >> 16u));
    uint _e47 = x_1;
    uint _e48 = y;
    uint _e49 = w;
    x_1 = (_e47 + (_e48 * _e49));
    uint _e52 = y;
    uint _e53 = z;
    uint _e54 = x_1;
    y = (_e52 + (_e53 * _e54));
    uint _e57 = x_1;
    float gate = saturate(mad(float(_e57), gate_a, gate_b));
    uint _e61 = y;
    const float _e62 = glint_normal_fast(_e61);
    float count = max(floor(mad(_e62, deviation, mean1_)), 1.0);
    return (gate * count);
}

uint2 naga_f2u32(float2 value) {
    return uint2(clamp(value, 0.0, 4294967000.0));
}

float glint_cell_fast(GlintParams params, GlintGrid grid, int2 c_2, float2 s_slope, float p_1, float log2_q)
{
    const uint3 _e16 = glint_pcg3d(uint3((asuint(c_2.x) + 2147483648u), (asuint(c_2.y) + 2147483648u), grid.seed));
    const float _e18 = glint_normal_fast(_e16.x);
    float log_density = clamp(((_e18 * params.density_randomization) + params.log_density), 0.0, 50.0);
    float count_1 = max(1e-8, (grid.cell_area * exp(log_density)));
    float blended = (count_1 * grid.weight);
    float miss = exp2((blended * log2_q));
    float one_hit = (1.0 - miss);
    float others = max((blended - 1.0), 0.0);
    float mean1_1 = ((others * p_1) + 1.0);
    float deviation_1 = sqrt((others * (p_1 * (1.0 - p_1))));
    float width = max(((0.1 * saturate((one_hit * 10.0))) * saturate((miss * 10.0))), 1e-30);
    float inv_1 = (0.5 / width);
    float gate_a_1 = (inv_1 * -2.3283064e-10);
    float gate_b_1 = mad(one_hit, inv_1, 0.5);
    float2 s_4 = mad(float2((_e16.yz >> (8u).xx)), (3.8146973e-6).xx, s_slope);
    float2 cell = floor(s_4);
    float2 l = (s_4 - cell);
    uint2 ci = naga_f2u32(cell);
    uint2 t0_ = (ci & (63u).xx);
    uint2 t1_ = ((ci + (1u).xx) & (63u).xx);
    uint2 ax_1 = ((uint2(t0_.x, t1_.x) * 1664525u) + (1013904223u).xx);
    uint2 ay_1 = ((uint2(t0_.y, t1_.y) * 1664525u) + (1013904223u).xx);
    const float _e104 = glint_corner_hits(ax_1.x, ay_1.x, gate_a_1, gate_b_1, deviation_1, mean1_1);
    const float _e107 = glint_corner_hits(ax_1.x, ay_1.y, gate_a_1, gate_b_1, deviation_1, mean1_1);
    const float _e110 = glint_corner_hits(ax_1.y, ay_1.x, gate_a_1, gate_b_1, deviation_1, mean1_1);
    const float _e113 = glint_corner_hits(ax_1.y, ay_1.y, gate_a_1, gate_b_1, deviation_1, mean1_1);
    float x0_ = lerp(_e104, _e110, l.x);
    float x1_ = lerp(_e107, _e113, l.x);
    return (lerp(x0_, x1_, l.y) / count_1);
}

float glint_sample_grid_fast(GlintParams params_1, GlintGrid grid_1, float2 s_slope_1, float p_2, float log2_q_1)
{
    float sum = 0.0;
    int k = int(0);

    const GlintSimplex _e6 = glint_simplex(grid_1.uv);
    int2 id = _e6.id;
    int si = _e6.si;
    float3 bary = _e6.bary;
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            int _e47 = k;
            k = asint(asuint(_e47) + asuint(int(1)));
        }
        loop_init = false;
        int _e14 = k;
        if ((_e14 < int(3))) {
        } else {
            break;
        }
        {
            int _e19 = k;
            int _e25 = k;
            int2 c_6 = asint(asuint(id) + asuint(int2(((_e19 == int(2)) ? asint(asuint(int(1)) - asuint(si)) : si), ((_e25 == int(1)) ? asint(asuint(int(1)) - asuint(si)) : si))));
            int _e33 = k;
            int _e38 = k;
            float b_4 = ((_e38 == int(0)) ? bary.x : ((_e33 == int(1)) ? bary.y : bary.z));
            float _e42 = sum;
            const float _e43 = glint_cell_fast(params_1, grid_1, c_6, s_slope_1, p_2, log2_q_1);
            sum = (_e42 + (b_4 * _e43));
        }
    }
    float _e49 = sum;
    return _e49;
}

float3 glint_vertex_of_code(uint c_3)
{
    uint rot = (c_3 & 3u);
    return float3(((rot == 3u) ? 0.0 : (float(rot) * 0.5)), float(((c_3 >> 2u) & 1u)), float((c_3 >> 3u)));
}

GlintTetraFast glint_tetra_fast(GlintEllipse e_3, float screen_scale_2)
{
    bool local_1 = (bool)0;
    GlintTetraFast out_3 = (GlintTetraFast)0;

    const GlintFootprintCell _e2 = glint_footprint_cell(e_3, screen_scale_2);
    float t_2 = _e2.theta_lerp;
    float r_1 = _e2.ratio_lerp;
    float l_1 = _e2.lod_lerp;
    bool upper = (l_1 > (1.0 - r_1));
    float upper_left = ((l_1 - (1.0 - r_1)) / max(r_1, 1e-8));
    float half_width = (0.5 * (1.0 - r_1));
    uint center_codes = (upper ? ((upper_left > t_2) ? GLINT_TET_CENTER_UP : GLINT_TET_CENTER_DOWN) : GLINT_TET_CENTER_LOW);
    uint a_codes = (upper ? ((upper_left > ((t_2 * 2.0) / max(r_1, 1e-8))) ? GLINT_TET_A_UP : GLINT_TET_A_DOWN) : GLINT_TET_A_LOW);
    uint b_codes = ((l_1 < (1.0 - r_1)) ? (((l_1 / max((1.0 - r_1), 1e-8)) > ((t_2 - (0.5 - half_width)) / max((2.0 * half_width), 1e-8))) ? GLINT_TET_B_UP : GLINT_TET_B_DOWN) : GLINT_TET_B_HIGH);
    uint c_codes = (upper ? ((upper_left > ((((t_2 - 0.5) * 2.0) - (1.0 - r_1)) / max(r_1, 1e-8))) ? GLINT_TET_C_UP : GLINT_TET_C_DOWN) : GLINT_TET_C_LOW);
    if ((t_2 < 0.5)) {
        local_1 = ((t_2 * 2.0) < r_1);
    } else {
        local_1 = false;
    }
    bool prism_a = local_1;
    bool prism_b = ((1.0 - ((t_2 - 0.5) * 2.0)) > r_1);
    uint codes = (_e2.center_ ? center_codes : (prism_a ? a_codes : (prism_b ? b_codes : c_codes)));
    float3 point_ = float3((_e2.center_ ? (t_2 * r_1) : t_2), r_1, l_1);
    out_3.codes = codes;
    const float3 _e103 = glint_vertex_of_code((codes & 15u));
    const float3 _e108 = glint_vertex_of_code(((codes >> 4u) & 15u));
    const float3 _e113 = glint_vertex_of_code(((codes >> 8u) & 15u));
    const float3 _e116 = glint_vertex_of_code((codes >> 12u));
    const float4 _e117 = glint_tetra_weights(point_, _e103, _e108, _e113, _e116);
    out_3.w = _e117;
    out_3.bin0_ = _e2.bin0_;
    out_3.bin_h = _e2.bin_h;
    out_3.bin1_ = _e2.bin1_;
    out_3.lod0_ = _e2.lod0_;
    out_3.ratio0_ = _e2.ratio0_;
    GlintTetraFast _e128 = out_3;
    const GlintTetraFast glinttetrafast = _e128;
    return glinttetrafast;
}

float glint_hits_fast(GlintParams params_2, float2 uv_4, GlintEllipse e_4, float screen_scale_3, float2 slope, float d_1, float d_max)
{
    float sum_1 = 0.0;
    uint i = 0u;

    const GlintTetraFast _e7 = glint_tetra_fast(e_4, screen_scale_3);
    uint codes_1 = _e7.codes;
    float p_4 = (params_2.micro_roughness * (d_1 / d_max));
    float log2_q_2 = log2((1.0 - p_4));
    float2 s_slope_2 = ((abs(slope) / (params_2.micro_roughness).xx) + (1.9073486e-6).xx);
    uint2 loop_bound_1 = uint2(4294967295u, 4294967295u);
    bool loop_init_1 = true;
    while(true) {
        if (all(loop_bound_1 == uint2(0u, 0u))) { break; }
        loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
        if (!loop_init_1) {
            uint _e97 = i;
            i = (_e97 + 1u);
        }
        loop_init_1 = false;
        uint _e26 = i;
        if ((_e26 < 4u)) {
        } else {
            break;
        }
        {
            uint _e30 = i;
            uint c_7 = ((codes_1 >> (4u * _e30)) & 15u);
            uint rot_1 = (c_7 & 3u);
            float theta_3 = ((rot_1 == 0u) ? _e7.bin0_ : ((rot_1 == 1u) ? _e7.bin_h : ((rot_1 == 2u) ? _e7.bin1_ : 0.0)));
            float ratio_2 = (((c_7 & 4u) != 0u) ? (_e7.ratio0_ * 2.0) : _e7.ratio0_);
            float lod_2 = (_e7.lod0_ + float((c_7 >> 3u)));
            uint _e76 = i;
            uint _e82 = i;
            uint _e88 = i;
            float w_1 = ((_e88 == 0u) ? _e7.w.x : ((_e82 == 1u) ? _e7.w.y : ((_e76 == 2u) ? _e7.w.z : (((1.0 - _e7.w.x) - _e7.w.y) - _e7.w.z))));
            float _e92 = sum_1;
            const GlintGrid _e93 = glint_make_grid(uv_4, lod_2, theta_3, ratio_2, w_1);
            const float _e94 = glint_sample_grid_fast(params_2, _e93, s_slope_2, p_4, log2_q_2);
            sum_1 = (_e92 + _e94);
        }
    }
    float _e99 = sum_1;
    return _e99;
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
    float3 v_3 = _e41.v;
    n = _e41.n;
    float3 _e45 = n;
    const float3x3 _e47 = weft_tangent_frame(_e45, in_1.world_tangent);
    float3 _e48 = n;
    const WeftLightGeometry _e49 = weft_main_light_geometry(_e48, v_3);
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
    const float3 _e85 = weft_prefiltered_radiance(reflect(-(v_3), _e83), roughness_7);
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
            const GlintParams _e129 = glitter_params();
            const float3 _e132 = weft_f_schlick(flake_f0_, _e49.v_dot_h);
            float3 lobe = (((((intensity * _e128) * _e132) * _e50) * _e49.n_dot_l) * (_e120 / _e129.micro_roughness));
            float2 slope_1 = float2(dot(_e47[0], _e49.h), dot(_e47[1], _e49.h));
            const GlintEllipse _e147 = glint_ellipse(duv_dx_1, duv_dy_1);
            float _e150 = material.flake_size;
            float screen_scale_4 = clamp(_e150, 1.0, 8.0);
            const float _e154 = glint_hits_fast(_e129, _e5, _e147, screen_scale_4, slope_1, _e118, _e120);
            float3 _e155 = color;
            color = (_e155 + (min(_e154, (20.0 * _e129.micro_roughness)) * lobe));
        }
    }
    float3 _e162 = color;
    float3 radiance = clamp(_e162, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
