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
    float roughness;
    float metallic;
    float occlusion_strength;
    int _pad4_0;
    float4 base_map_st;
    float normal_strength;
    float saturation;
    float brightness;
    float span;
    float view_offset;
    int _pad10_0;
    int _pad10_1;
    int _pad10_2;
    float4 offset_map_st;
    uint sin_mapping;
    float color_direction;
    float film_strength;
    float film_ior;
    float thickness_min;
    float thickness_max;
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
cbuffer material : register(b0, space1) { WeftMaterial material; }
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
Texture2D<float4> base_map : register(t3, space1);
Texture2D<float4> normal_map : register(t4, space1);
Texture2D<float4> rmo_map : register(t5, space1);
Texture2D<float4> offset_map : register(t6, space1);
Texture2D<float4> direction_map : register(t8, space1);

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
    float a = (-1.0 / (s + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return float3((1.0 + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
}

float weft_d_ggx_nh(float3 n_2, float3 h, float roughness_1)
{
    const float _e3 = weft_clamp_roughness(roughness_1);
    float a_1 = (_e3 * _e3);
    float a2_ = (a_1 * a_1);
    float noh = saturate(dot(n_2, h));
    float3 nxh = cross(n_2, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d * d), 1e-30)));
}

float3 weft_f_schlick(float3 f0_, float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (f0_ + (((1.0).xxx - f0_) * _e5));
}

float weft_v_smith_ggx_correlated(float n_dot_v, float n_dot_l, float roughness_2)
{
    const float _e3 = weft_clamp_roughness(roughness_2);
    float a_2 = (_e3 * _e3);
    float a2_1 = (a_2 * a_2);
    const float _e6 = weft_clamp_cos(n_dot_v);
    const float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * (1.0 - a2_1)) + a2_1)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * (1.0 - a2_1)) + a2_1)));
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

float weft_specular_mip(float roughness_3)
{
    float r = saturate(roughness_3);
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

float3 weft_prefiltered_radiance(float3 dir, float roughness_4)
{
    const float _e4 = weft_specular_mip(roughness_4);
    float4 c_1 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, (0.0).xxx);
}

float2 weft_env_brdf_lut(float n_dot_v_1, float roughness_5)
{
    float2 uv_1 = float2(saturate(n_dot_v_1), saturate(roughness_5));
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv_1, 0.0);
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
    float3 b_1 = (cross(n_5, t) * s_1);
    return float3x3(t, b_1, n_5);
}

float3 weft_unpack_normal(float3 texel, float strength)
{
    float3 v_3 = ((texel * 2.0) - (1.0).xxx);
    return float3((v_3.xy * strength), max(v_3.z, 0.001));
}

float3 weft_normal_from_tangent_space(float3x3 frame, float3 n_ts)
{
    const float3 _e4 = weft_safe_normalize(mul(n_ts, frame), frame[2]);
    return _e4;
}

float3 weft_mapped_normal(float3 n_6, float4 tangent_1, float3 texel_1, float strength_1)
{
    const float3x3 _e4 = weft_tangent_frame(n_6, tangent_1);
    const float3 _e5 = weft_unpack_normal(texel_1, strength_1);
    const float3 _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
}

float2 weft_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

float3 weft_ior_from_f0_(float3 f0_2)
{
    float3 s_2 = sqrt(clamp(f0_2, (0.0).xxx, (0.9999).xxx));
    return (((1.0).xxx + s_2) / ((1.0).xxx - s_2));
}

float weft_film_ior(float film_ior, float thickness_nm)
{
    return lerp(1.0, max(film_ior, 1.0), smoothstep(0.0, WEFT_FILM_FADE_NM, thickness_nm));
}

float weft_cmf_lobe(float lambda, float mu, float sigma_left, float sigma_right)
{
    float t_1 = ((lambda - mu) / ((lambda < mu) ? sigma_left : sigma_right));
    return exp(((-0.5 * t_1) * t_1));
}

float3 weft_cie_xyz(float lambda_1)
{
    const float _e4 = weft_cmf_lobe(lambda_1, 599.8, 37.9, 31.0);
    const float _e10 = weft_cmf_lobe(lambda_1, 442.0, 16.0, 26.7);
    const float _e17 = weft_cmf_lobe(lambda_1, 501.1, 20.4, 26.2);
    float x_1 = (((1.056 * _e4) + (0.362 * _e10)) - (0.065 * _e17));
    const float _e24 = weft_cmf_lobe(lambda_1, 568.8, 46.9, 40.5);
    const float _e30 = weft_cmf_lobe(lambda_1, 530.9, 16.3, 31.1);
    float y = ((0.821 * _e24) + (0.286 * _e30));
    const float _e37 = weft_cmf_lobe(lambda_1, 437.0, 11.8, 36.0);
    const float _e43 = weft_cmf_lobe(lambda_1, 459.0, 26.0, 13.8);
    float z = ((1.217 * _e37) + (0.681 * _e43));
    return float3(x_1, y, z);
}

float2 weft_fresnel_amplitudes(float n_i, float n_t, float cos_i, float cos_t)
{
    float rs = (((n_i * cos_i) - (n_t * cos_t)) / max(((n_i * cos_i) + (n_t * cos_t)), 1e-12));
    float rp = (((n_t * cos_i) - (n_i * cos_t)) / max(((n_t * cos_i) + (n_i * cos_t)), 1e-12));
    return float2(rs, rp);
}

float3 weft_airy(float r12_, float3 r23_, float cos_delta)
{
    float3 cross_term = (((2.0 * r12_) * r23_) * cos_delta);
    float3 numerator = ((((r12_ * r12_)).xxx + (r23_ * r23_)) + cross_term);
    float3 denominator = (((1.0).xxx + (((r12_ * r12_) * r23_) * r23_)) + cross_term);
    return (numerator / max(denominator, (1e-12).xxx));
}

typedef float3 ret_Constructarray2_float3_[2];
ret_Constructarray2_float3_ Constructarray2_float3_(float3 arg0, float3 arg1) {
    float3 ret[2] = { arg0, arg1 };
    return ret;
}

typedef float3 ret_weft_film_base_amplitudes[2];
ret_weft_film_base_amplitudes weft_film_base_amplitudes(float n2_, float cos2_, float3 n3_, float sin1_sq)
{
    float3 cos3_ = sqrt(max(((1.0).xxx - ((sin1_sq).xxx / (n3_ * n3_))), (0.0).xxx));
    float3 s_3 = ((((n2_ * cos2_)).xxx - (n3_ * cos3_)) / max((((n2_ * cos2_)).xxx + (n3_ * cos3_)), (1e-12).xxx));
    float3 p = (((n3_ * cos2_) - ((n2_).xxx * cos3_)) / max(((n3_ * cos2_) + ((n2_).xxx * cos3_)), (1e-12).xxx));
    return Constructarray2_float3_(s_3, p);
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

WeftFilmStack weft_film_stack(float cos_theta1_, float thickness_nm_1, float film_ior_1, float3 base_f0_)
{
    float cos1_ = clamp(cos_theta1_, 0.0, 1.0);
    float sin1_sq_1 = (1.0 - (cos1_ * cos1_));
    const float _e10 = weft_film_ior(film_ior_1, thickness_nm_1);
    float cos2_sq = (1.0 - (sin1_sq_1 / (_e10 * _e10)));
    if ((cos2_sq <= 0.0)) {
        const WeftFilmStack weftfilmstack = ConstructWeftFilmStack(_e10, 0.0, (1.0).xx, Constructarray2_float3_((1.0).xxx, (1.0).xxx), true);
        return weftfilmstack;
    }
    float cos2_1 = sqrt(cos2_sq);
    const float2 _e29 = weft_fresnel_amplitudes(1.0, _e10, cos1_, cos2_1);
    const float3 _e30 = weft_ior_from_f0_(base_f0_);
    const float3 _e31[2] = weft_film_base_amplitudes(_e10, cos2_1, _e30, sin1_sq_1);
    const WeftFilmStack weftfilmstack_1 = ConstructWeftFilmStack(_e10, cos2_1, _e29, _e31, false);
    return weftfilmstack_1;
}

float3 weft_film_spectral(float cos_theta1_1, float thickness_nm_2, float film_ior_2, float3 base_f0_1)
{
    float3 xyz_r = (0.0).xxx;
    float3 xyz_g = (0.0).xxx;
    float3 xyz_b = (0.0).xxx;
    float3 white = (0.0).xxx;
    uint i = 0u;
    bool local = (bool)0;

    const WeftFilmStack _e4 = weft_film_stack(cos_theta1_1, thickness_nm_2, film_ior_2, base_f0_1);
    if (_e4.total_internal_reflection) {
        return (1.0).xxx;
    }
    float n2_1 = _e4.n2_;
    float cos2_2 = _e4.cos2_;
    float2 r12_1 = _e4.r12_;
    float3 r23_1[2] = _e4.r23_;
    float d_1 = max(thickness_nm_2, 0.0);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e83 = i;
            i = (_e83 + 1u);
        }
        loop_init = false;
        uint _e29 = i;
        if ((_e29 < WEFT_FILM_SAMPLES)) {
        } else {
            break;
        }
        {
            uint _e33 = i;
            float lambda_2 = (WEFT_FILM_LAMBDA_MIN + (4.0 * float(_e33)));
            uint _e37 = i;
            if (!((_e37 == 0u))) {
                uint _e43 = i;
                local = (_e43 == 100u);
            } else {
                local = true;
            }
            bool _e47 = local;
            float w = (_e47 ? 0.5 : 1.0);
            float cos_delta_1 = cos(((((12.566371 * n2_1) * d_1) * cos2_2) / lambda_2));
            const float3 _e59 = weft_airy(r12_1.x, r23_1[0], cos_delta_1);
            const float3 _e62 = weft_airy(r12_1.y, r23_1[1], cos_delta_1);
            float3 r_1 = (0.5 * (_e59 + _e62));
            const float3 _e66 = weft_cie_xyz(lambda_2);
            float3 cmf = (_e66 * w);
            float3 _e68 = xyz_r;
            xyz_r = (_e68 + (r_1.x * cmf));
            float3 _e72 = xyz_g;
            xyz_g = (_e72 + (r_1.y * cmf));
            float3 _e76 = xyz_b;
            xyz_b = (_e76 + (r_1.z * cmf));
            float3 _e80 = white;
            white = (_e80 + cmf);
        }
    }
    float3 _e86 = white;
    float3 rgb_white = mul(_e86, WEFT_XYZ_TO_REC709_);
    float3 _e89 = xyz_r;
    float3 _e93 = xyz_g;
    float3 _e97 = xyz_b;
    float3 rgb = float3(mul(_e89, WEFT_XYZ_TO_REC709_).x, mul(_e93, WEFT_XYZ_TO_REC709_).y, mul(_e97, WEFT_XYZ_TO_REC709_).z);
    return clamp((rgb / rgb_white), (0.0).xxx, (1.0).xxx);
}

float laser_cos_in_plane(float3 n_7, float3 v_2, float3 direction)
{
    float3 p_1 = cross(direction, n_7);
    float p_len = length(p_1);
    if ((p_len < 0.0001)) {
        const float _e8 = weft_clamp_cos(dot(n_7, v_2));
        return _e8;
    }
    float3 p_unit = (p_1 / (p_len).xxx);
    float3 v_in_plane = (v_2 - (dot(v_2, p_unit) * p_unit));
    float len = length(v_in_plane);
    const float _e19 = weft_clamp_cos((dot(n_7, v_in_plane) / max(len, 0.0001)));
    return _e19;
}

float3 laser_film_reference(float cos_theta, float d1_, float d2_, float3 f0_3)
{
    float _e6 = material.film_ior;
    const float3 _e7 = weft_film_spectral(cos_theta, d1_, _e6, f0_3);
    if ((abs((d1_ - d2_)) < 0.5)) {
        return _e7;
    }
    float _e14 = material.film_ior;
    const float3 _e15 = weft_film_spectral(cos_theta, d2_, _e14, f0_3);
    return (0.5 * (_e7 + _e15));
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

    float4 _e4 = material.base_map_st;
    const float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    float4 _e8 = material.base_color;
    float4 _e11 = base_map.Sample(material_sampler, _e5);
    float4 base_rgba = (_e8 * _e11);
    float3 base = saturate(base_rgba.xyz);
    float alpha = saturate(base_rgba.w);
    float4 _e19 = rmo_map.Sample(material_sampler, _e5);
    float3 rmo = _e19.xyz;
    float _e23 = material.roughness;
    float roughness_6 = saturate((_e23 * rmo.x));
    float _e29 = material.metallic;
    float metallic = saturate((_e29 * rmo.y));
    float _e36 = material.occlusion_strength;
    float ao = saturate(lerp(1.0, rmo.z, _e36));
    float4 _e45 = material.offset_map_st;
    const float2 _e46 = weft_transform_uv(in_1.uv0_, _e45);
    float4 _e47 = offset_map.Sample(material_sampler, _e46);
    float2 offsets = saturate(_e47.xy);
    const WeftSurface _e52 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_4 = _e52.v;
    float3 geometric_n = _e52.n;
    n = geometric_n;
    {
        float4 _e58 = normal_map.Sample(material_sampler, _e5);
        float3 texel_2 = _e58.xyz;
        float _e63 = material.normal_strength;
        const float3 _e64 = weft_mapped_normal(geometric_n, in_1.world_tangent, texel_2, _e63);
        n = _e64;
    }
    float3 _e65 = n;
    const WeftLightGeometry _e66 = weft_main_light_geometry(_e65, v_4);
    film_cos = _e66.n_dot_v;
    {
        const float3x3 _e70 = weft_tangent_frame(geometric_n, in_1.world_tangent);
        {
            float4 _e77 = direction_map.Sample(material_sampler, _e5);
            float2 flow = ((_e77.xy * 2.0) - (1.0).xx);
            direction_ts = ((dot(flow, flow) > 1e-6) ? flow : float2(1.0, 0.0));
        }
        float _e93 = direction_ts.x;
        float _e97 = direction_ts.y;
        float3 direction_1 = ((_e70[0] * _e93) + (_e70[1] * _e97));
        float3 _e100 = n;
        const float _e101 = laser_cos_in_plane(_e100, v_4, direction_1);
        film_cos = _e101;
    }
    surface_base = base;
    float3 _e105 = surface_base;
    float3 f0_4 = lerp((0.04).xxx, _e105, metallic);
    float3 _e107 = surface_base;
    float3 diffuse_albedo = (_e107 * (1.0 - metallic));
    const float2 _e112 = weft_env_brdf_lut(_e66.n_dot_v, roughness_6);
    const float3 _e114 = weft_f_schlick(f0_4, _e66.v_dot_h);
    f_light = _e114;
    const float3 _e116 = weft_env_brdf_from_lut(f0_4, _e112);
    e_spec = _e116;
    {
        float _e120 = material.thickness_min;
        float _e123 = material.thickness_max;
        float d1_1 = lerp(_e120, _e123, offsets.x);
        float _e128 = material.thickness_min;
        float _e131 = material.thickness_max;
        float d2_1 = lerp(_e128, _e131, offsets.y);
        float _e136 = material.film_strength;
        float strength_2 = saturate(_e136);
        light_cos = _e66.v_dot_h;
        {
            float _e140 = film_cos;
            light_cos = _e140;
        }
        {
            float _e143 = film_cos;
            const float3 _e144 = laser_film_reference(_e143, d1_1, d2_1, f0_4);
            film_view = _e144;
            float _e145 = light_cos;
            const float3 _e146 = laser_film_reference(_e145, d1_1, d2_1, f0_4);
            film_light = _e146;
        }
        float3 _e147 = f_light;
        float3 _e148 = film_light;
        f_light = lerp(_e147, _e148, strength_2);
        float3 _e150 = e_spec;
        float3 _e151 = film_view;
        e_spec = lerp(_e150, (_e151 * (_e112.x + _e112.y)), strength_2);
    }
    float3 _e159 = e_spec;
    float3 kd = max(((1.0).xxx - _e159), (0.0).xxx);
    const float _e166 = weft_v_smith_ggx_correlated(_e66.n_dot_v, _e66.n_dot_l, roughness_6);
    float3 _e167 = n;
    const float _e169 = weft_d_ggx_nh(_e167, _e66.h, roughness_6);
    float3 _e171 = f_light;
    float3 specular = ((_e169 * _e166) * _e171);
    const float3 _e173 = weft_diffuse_lambert(diffuse_albedo);
    float3 diffuse = (kd * _e173);
    const float3 _e176 = weft_main_light_radiance();
    float3 direct = (((diffuse + specular) * _e176) * _e66.n_dot_l);
    float3 _e181 = n;
    const float3 _e183 = weft_prefiltered_radiance(reflect(-(v_4), _e181), roughness_6);
    float3 _e184 = e_spec;
    float3 indirect_specular = ((_e183 * _e184) * ao);
    float3 _e187 = n;
    const float3 _e188 = weft_sh_irradiance(_e187);
    float3 indirect_diffuse = (((_e188 * ao) * kd) * diffuse_albedo);
    float3 color = ((direct + indirect_specular) + indirect_diffuse);
    return float4(clamp(color, (0.0).xxx, (65504.0).xxx), alpha);
}
