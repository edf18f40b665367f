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
    float normal_strength;
    float specular_strength;
    int _pad6_0;
    int _pad6_1;
    int _pad6_2;
    float4 emissive;
    float emissive_strength;
    float alpha_cutoff;
    float sphere_strength;
    int _pad10_0;
    float4 base_map_st;
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
static const uint SPHERE_MAP_OFF = 0u;
static const uint SPHERE_MAP_ADD = 1u;
static const uint SPHERE_MAP_MULTIPLY = 2u;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SEED = 2u;
static const uint TIER_LOW = 3u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float WEFT_MIN_ROUGHNESS_HALF = 0.089;
static const float WEFT_MIN_N_DOT_HALF = 0.001;
static const float WEFT_MIN_ALPHA_HALF = 0.007921;
static const bool ALPHA_TEST = false;
static const bool EMISSION = false;

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
Texture2D<float4> emissive_map : register(t3, space1);
Texture2D<float4> base_map : register(t4, space1);
Texture2D<float4> normal_map : register(t5, space1);
Texture2D<float4> rmo_map : register(t6, space1);

struct VertexOutput_vs_main {
    float3 world_position_3 : LOC0;
    float3 world_normal_1 : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    float4 clip_position : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_4 : LOC0;
    float3 world_normal_2 : LOC1;
    float4 world_tangent_1 : LOC2;
    float2 uv0_1 : LOC3;
    float4 clip_position_1 : SV_Position;
    bool front_facing_2 : SV_IsFrontFace;
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
    float d_1 = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d_1 * d_1), 1e-30)));
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
    float2 uv_2 = float2(saturate(n_dot_v_1), saturate(roughness_5));
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv_2, 0.0);
    return _e8.xy;
}

WeftSurface ConstructWeftSurface(float3 arg0, float3 arg1) {
    WeftSurface ret = (WeftSurface)0;
    ret.v = arg0;
    ret.n = arg1;
    return ret;
}

WeftSurface weft_surface_two_sided(float3 world_position_1, float3 world_normal, bool front_facing_1)
{
    const float3 _e7 = weft_view_direction(world_position_1, float3(0.0, 0.0, 1.0));
    float3 facing = (front_facing_1 ? world_normal : -(world_normal));
    const float3 _e10 = weft_safe_normalize(facing, _e7);
    const WeftSurface weftsurface = ConstructWeftSurface(_e7, _e10);
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

float3 standard_emission(float2 uv_1)
{
    if (EMISSION) {
        float _e4 = material.emissive_strength;
        float strength_2 = max(_e4, 0.0);
        float4 _e9 = material.emissive;
        float3 emissive = max(_e9.xyz, (0.0).xxx);
        float4 _e17 = emissive_map.Sample(material_sampler, uv_1);
        return ((emissive * strength_2) * _e17.xyz);
    }
    return (0.0).xxx;
}

float3 standard_sphere_map(float3 color_in, float3 n_7, float3 world_position_2)
{
    float3 color = (float3)0;

    color = color_in;
    float3 _e4 = color;
    return _e4;
}

void standard_alpha_test(float alpha)
{
    if (ALPHA_TEST) {
        float _e4 = material.alpha_cutoff;
        if ((alpha < _e4)) {
            discard;
        } else {
            return;
        }
    } else {
        return;
    }
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
    WeftVaryings in_1 = { fragmentinput_fs_main.clip_position_1, fragmentinput_fs_main.world_position_4, fragmentinput_fs_main.world_normal_2, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_1 };
    bool front_facing = fragmentinput_fs_main.front_facing_2;
    float3 n = (float3)0;
    float visibility = (float)0;
    float3 env_brdf = (float3)0;
    float3 ambient_kd = (float3)0;
    float3 direct_kd = (float3)0;
    float3 specular = (0.0).xxx;
    float3 indirect_specular = (0.0).xxx;
    float d = (float)0;

    float4 _e5 = material.base_map_st;
    const float2 _e6 = weft_transform_uv(in_1.uv0_, _e5);
    float4 _e9 = material.base_color;
    float4 _e12 = base_map.Sample(material_sampler, _e6);
    float4 base_rgba = (_e9 * _e12);
    float3 base = saturate(base_rgba.xyz);
    float alpha_1 = saturate(base_rgba.w);
    float4 _e20 = rmo_map.Sample(material_sampler, _e6);
    float3 rmo = _e20.xyz;
    const float3 _e22 = standard_emission(_e6);
    float _e25 = material.roughness;
    float roughness_6 = saturate((_e25 * rmo.x));
    float _e31 = material.metallic;
    float metallic = saturate((_e31 * rmo.y));
    float _e38 = material.occlusion_strength;
    float ao = saturate(lerp(1.0, rmo.z, _e38));
    float _e44 = material.specular_strength;
    float specular_strength = max(_e44, 0.0);
    const WeftSurface _e49 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    float3 v_3 = _e49.v;
    n = _e49.n;
    {
        float4 _e55 = normal_map.Sample(material_sampler, _e6);
        float3 texel_2 = _e55.xyz;
        float3 _e57 = n;
        float _e61 = material.normal_strength;
        const float3 _e62 = weft_mapped_normal(_e57, in_1.world_tangent, texel_2, _e61);
        n = _e62;
    }
    float3 _e63 = n;
    const WeftLightGeometry _e64 = weft_main_light_geometry(_e63, v_3);
    float3 f0_2 = lerp((0.04).xxx, base, metallic);
    float3 diffuse_albedo = (base * (1.0 - metallic));
    {
        const float _e77 = weft_v_smith_ggx_correlated(_e64.n_dot_v, _e64.n_dot_l, roughness_6);
        visibility = _e77;
        const float2 _e79 = weft_env_brdf_lut(_e64.n_dot_v, roughness_6);
        const float3 _e80 = weft_env_brdf_from_lut(f0_2, _e79);
        env_brdf = _e80;
        float3 _e83 = env_brdf;
        ambient_kd = max(((1.0).xxx - _e83), (0.0).xxx);
        float3 _e88 = ambient_kd;
        direct_kd = _e88;
    }
    if ((specular_strength > 0.0)) {
        const float3 _e98 = weft_f_schlick(f0_2, _e64.v_dot_h);
        {
            float3 _e100 = n;
            const float _e102 = weft_d_ggx_nh(_e100, _e64.h, roughness_6);
            d = _e102;
        }
        float _e103 = d;
        float _e104 = visibility;
        specular = (((_e103 * _e104) * _e98) * specular_strength);
        float3 _e109 = n;
        const float3 _e111 = weft_prefiltered_radiance(reflect(-(v_3), _e109), roughness_6);
        float3 _e112 = env_brdf;
        indirect_specular = ((_e111 * _e112) * (ao * specular_strength));
    }
    float3 _e116 = direct_kd;
    const float3 _e117 = weft_diffuse_lambert(diffuse_albedo);
    float3 diffuse = (_e116 * _e117);
    float3 _e119 = specular;
    const float3 _e121 = weft_main_light_radiance();
    float3 direct = (((diffuse + _e119) * _e121) * _e64.n_dot_l);
    float3 _e125 = n;
    const float3 _e126 = weft_sh_irradiance(_e125);
    float3 _e128 = ambient_kd;
    float3 indirect_diffuse = (((_e126 * ao) * _e128) * diffuse_albedo);
    float3 _e131 = indirect_specular;
    float3 color_1 = ((direct + _e131) + indirect_diffuse);
    float3 _e134 = n;
    const float3 _e136 = standard_sphere_map(color_1, _e134, in_1.world_position);
    float3 radiance = clamp((_e136 + _e22), (0.0).xxx, (65504.0).xxx);
    standard_alpha_test(alpha_1);
    return float4(radiance, alpha_1);
}
