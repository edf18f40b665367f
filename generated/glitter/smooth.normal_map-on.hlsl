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
Texture2D<float4> normal_map : register(t4, space1);
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
    float a = (-1.0 / (s + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return float3((1.0 + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
}

float weft_d_ggx(float n_dot_h, float roughness_1)
{
    const float _e2 = weft_clamp_roughness(roughness_1);
    float a_1 = (_e2 * _e2);
    float a2_ = (a_1 * a_1);
    float noh = saturate(n_dot_h);
    float one_minus_noh2_ = ((1.0 - noh) * (1.0 + noh));
    float d = (one_minus_noh2_ + ((noh * noh) * a2_));
    return (a2_ / ((WEFT_PI * d) * d));
}

float weft_d_ggx_nh(float3 n_2, float3 h, float roughness_2)
{
    const float _e3 = weft_clamp_roughness(roughness_2);
    float a_2 = (_e3 * _e3);
    float a2_1 = (a_2 * a_2);
    float noh_1 = saturate(dot(n_2, h));
    float3 nxh = cross(n_2, h);
    float d_1 = (dot(nxh, nxh) + ((noh_1 * noh_1) * a2_1));
    return (a2_1 / (WEFT_PI * max((d_1 * d_1), 1e-30)));
}

float3 weft_f_schlick(float3 f0_, float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (f0_ + (((1.0).xxx - f0_) * _e5));
}

float weft_v_smith_ggx_correlated(float n_dot_v, float n_dot_l, float roughness_3)
{
    const float _e3 = weft_clamp_roughness(roughness_3);
    float a_3 = (_e3 * _e3);
    float a2_2 = (a_3 * a_3);
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
    float4 c_1 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, (0.0).xxx);
}

float2 weft_env_brdf_lut(float n_dot_v_1, float roughness_6)
{
    float2 uv_1 = float2(saturate(n_dot_v_1), saturate(roughness_6));
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
    float3 v_2 = ((texel * 2.0) - (1.0).xxx);
    return float3((v_2.xy * strength), max(v_2.z, 0.001));
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
    float2 duv_dx = ddx(_e5);
    float2 duv_dy = ddy(_e5);
    float4 _e10 = material.base_color;
    float4 _e13 = base_map.Sample(material_sampler, _e5);
    float4 base_rgba = (_e10 * _e13);
    float3 base = saturate(base_rgba.xyz);
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
    {
        float4 _e47 = normal_map.Sample(material_sampler, _e5);
        float3 texel_2 = _e47.xyz;
        float3 _e49 = n;
        float _e53 = material.normal_strength;
        const float3 _e54 = weft_mapped_normal(_e49, in_1.world_tangent, texel_2, _e53);
        n = _e54;
    }
    float3 _e55 = n;
    const float3x3 _e57 = weft_tangent_frame(_e55, in_1.world_tangent);
    float3 _e58 = n;
    const WeftLightGeometry _e59 = weft_main_light_geometry(_e58, v_3);
    const float3 _e60 = weft_main_light_radiance();
    float3 f0_2 = lerp((0.04).xxx, base, metallic);
    float3 diffuse_albedo = (base * (1.0 - metallic));
    const float _e69 = weft_v_smith_ggx_correlated(_e59.n_dot_v, _e59.n_dot_l, roughness_7);
    const float2 _e71 = weft_env_brdf_lut(_e59.n_dot_v, roughness_7);
    const float3 _e72 = weft_env_brdf_from_lut(f0_2, _e71);
    float3 kd = max(((1.0).xxx - _e72), (0.0).xxx);
    float3 _e79 = n;
    const float _e81 = weft_d_ggx_nh(_e79, _e59.h, roughness_7);
    const float3 _e84 = weft_f_schlick(f0_2, _e59.v_dot_h);
    float3 specular = ((_e81 * _e69) * _e84);
    const float3 _e86 = weft_diffuse_lambert(diffuse_albedo);
    float3 direct = ((((kd * _e86) + specular) * _e60) * _e59.n_dot_l);
    float3 _e93 = n;
    const float3 _e95 = weft_prefiltered_radiance(reflect(-(v_3), _e93), roughness_7);
    float3 _e98 = n;
    const float3 _e99 = weft_sh_irradiance(_e98);
    float3 indirect = (((_e95 * _e72) * ao) + (((_e99 * ao) * kd) * diffuse_albedo));
    color = (direct + indirect);
    float _e108 = material.flake_intensity;
    float intensity = max(_e108, 0.0);
    if ((intensity > 0.0)) {
        local = (_e59.n_dot_l > 0.0);
    } else {
        local = false;
    }
    bool _e119 = local;
    if (_e119) {
        float _e122 = material.flake_roughness;
        float r_f = clamp(_e122, 0.05, 1.0);
        float3 _e126 = n;
        const float _e128 = weft_d_ggx_nh(_e126, _e59.h, r_f);
        const float _e130 = weft_d_ggx(1.0, r_f);
        float4 _e133 = material.flake_color;
        float3 flake_f0_ = saturate(_e133.xyz);
        const float _e138 = weft_v_smith_ggx_correlated(_e59.n_dot_v, _e59.n_dot_l, r_f);
        {
            {
                d_flakes = _e128;
            }
            float3 _e140 = color;
            float _e141 = d_flakes;
            const float3 _e145 = weft_f_schlick(flake_f0_, _e59.v_dot_h);
            color = (_e140 + (((((intensity * _e141) * _e138) * _e145) * _e60) * _e59.n_dot_l));
        }
    }
    float3 _e151 = color;
    float3 radiance = clamp(_e151, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
