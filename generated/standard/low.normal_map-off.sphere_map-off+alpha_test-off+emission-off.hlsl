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

float weft_clamp_cos(float c)
{
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

float3 weft_safe_normalize(float3 v, float3 fallback)
{
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * rsqrt(max(len2_, 1e-20))) : fallback);
}

float3 weft_env_brdf_from_lut(float3 f0_, float2 scale_bias)
{
    float2 sb = saturate(scale_bias);
    return ((f0_ * sb.x) + (sb.y).xxx);
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

float weft_specular_mip(float roughness)
{
    float r = saturate(roughness);
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

float3 weft_prefiltered_radiance(float3 dir, float roughness_1)
{
    const float _e4 = weft_specular_mip(roughness_1);
    float4 c_1 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, (0.0).xxx);
}

float2 weft_env_brdf_lut(float n_dot_v, float roughness_2)
{
    float2 uv_2 = float2(saturate(n_dot_v), saturate(roughness_2));
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

WeftLightGeometry weft_main_light_geometry(float3 n_2, float3 v_1)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_1), n_2);
    const float _e6 = weft_clamp_cos(dot(n_2, v_1));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_2, _e2)), saturate(dot(n_2, _e4)), saturate(dot(v_1, _e4)));
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

float2 weft_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

float weft_half_min_max(float x)
{
    return min(x, 65504.0);
}

float weft_half_pow5_(float x_1)
{
    float x2_ = (x_1 * x_1);
    return ((x2_ * x2_) * x_1);
}

float weft_half_d_ggx(float one_minus_n_dot_h2_, float n_dot_h, float alpha)
{
    float a = (n_dot_h * alpha);
    float k = (alpha / (one_minus_n_dot_h2_ + (a * a)));
    const float _e10 = weft_half_min_max(((k * k) * 0.31830987));
    return _e10;
}

float weft_half_v_smith_ggx_correlated_newton_nl(float n_dot_v_1, float n_dot_l, float alpha_1)
{
    float2 x_2 = float2(max(n_dot_v_1, 0.001), n_dot_l);
    float alpha2_ = (alpha_1 * alpha_1);
    float2 g = lerp(x_2, (1.0).xx, alpha_1);
    float inv_gg = (1.0 / (g.x * g.y));
    float2 q = (x_2 + ((alpha2_ * ((1.0).xx - x_2)) * (g.yx * inv_gg)));
    float denominator = ((x_2.y * q.x) + (x_2.x * q.y));
    return ((0.5 * n_dot_l) / max(denominator, 0.0001));
}

float3 weft_half_f_schlick(float3 f0_1, float v_dot_h)
{
    const float _e7 = weft_half_pow5_((1.0 - v_dot_h));
    return (f0_1 + (((1.0).xxx - f0_1) * _e7));
}

float3 standard_emission(float2 uv_1)
{
    if (EMISSION) {
        float _e4 = material.emissive_strength;
        float strength = max(_e4, 0.0);
        float4 _e9 = material.emissive;
        float3 emissive = max(_e9.xyz, (0.0).xxx);
        float4 _e17 = emissive_map.Sample(material_sampler, uv_1);
        return ((emissive * strength) * _e17.xyz);
    }
    return (0.0).xxx;
}

float3 standard_low(float3 n_3, float3 v_2, WeftLightGeometry lit_, float3 f0_in, float3 diffuse_albedo, float roughness_in, float ao, float specular_strength)
{
    float3 direct_n_dot_l = (float3)0;
    float3 indirect_specular_1 = (0.0).xxx;

    float n_dot_v_2 = float(lit_.n_dot_v);
    float n_dot_l_1 = float(lit_.n_dot_l);
    float n_dot_h_1 = float(lit_.n_dot_h);
    float v_dot_h_1 = float(lit_.v_dot_h);
    float one_minus_n_dot_h2_1 = float(((1.0 - lit_.n_dot_h) * (1.0 + lit_.n_dot_h)));
    float roughness_3 = float(max(roughness_in, WEFT_MIN_ROUGHNESS_HALF));
    float alpha_3 = (roughness_3 * roughness_3);
    float3 f0_2 = float3(f0_in);
    const float2 _e30 = weft_env_brdf_lut(lit_.n_dot_v, roughness_in);
    const float3 _e31 = weft_env_brdf_from_lut(f0_in, _e30);
    float3 env_brdf_1 = float3(_e31);
    float3 kd = max(((1.0).xxx - env_brdf_1), (0.0).xxx);
    direct_n_dot_l = (float3((kd * (n_dot_l_1 * 0.31830987))) * diffuse_albedo);
    if ((specular_strength > 0.0)) {
        const float _e50 = weft_half_d_ggx(one_minus_n_dot_h2_1, n_dot_h_1, alpha_3);
        const float _e51 = weft_half_v_smith_ggx_correlated_newton_nl(n_dot_v_2, n_dot_l_1, alpha_3);
        const float3 _e52 = weft_half_f_schlick(f0_2, v_dot_h_1);
        const float _e54 = weft_half_min_max((_e50 * _e51));
        float3 _e55 = direct_n_dot_l;
        direct_n_dot_l = (_e55 + (float3((_e52 * _e54)) * specular_strength));
        const float3 _e62 = weft_prefiltered_radiance(reflect(-(v_2), n_3), roughness_in);
        indirect_specular_1 = ((_e62 * float3(env_brdf_1)) * (ao * specular_strength));
    }
    float3 _e67 = direct_n_dot_l;
    const float3 _e68 = weft_main_light_radiance();
    float3 direct = (_e67 * _e68);
    const float3 _e70 = weft_sh_irradiance(n_3);
    float3 indirect_diffuse = (((_e70 * ao) * float3(kd)) * diffuse_albedo);
    float3 _e75 = indirect_specular_1;
    return ((direct + _e75) + indirect_diffuse);
}

float3 standard_sphere_map(float3 color_in, float3 n_4, float3 world_position_2)
{
    float3 color = (float3)0;

    color = color_in;
    float3 _e4 = color;
    return _e4;
}

void standard_alpha_test(float alpha_2)
{
    if (ALPHA_TEST) {
        float _e4 = material.alpha_cutoff;
        if ((alpha_2 < _e4)) {
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
    float alpha_4 = saturate(base_rgba.w);
    float4 _e20 = rmo_map.Sample(material_sampler, _e6);
    float3 rmo = _e20.xyz;
    const float3 _e22 = standard_emission(_e6);
    float _e25 = material.roughness;
    float roughness_4 = saturate((_e25 * rmo.x));
    float _e31 = material.metallic;
    float metallic = saturate((_e31 * rmo.y));
    float _e38 = material.occlusion_strength;
    float ao_1 = saturate(lerp(1.0, rmo.z, _e38));
    float _e44 = material.specular_strength;
    float specular_strength_1 = max(_e44, 0.0);
    const WeftSurface _e49 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    float3 v_3 = _e49.v;
    n = _e49.n;
    float3 _e53 = n;
    const WeftLightGeometry _e54 = weft_main_light_geometry(_e53, v_3);
    float3 f0_3 = lerp((0.04).xxx, base, metallic);
    float3 diffuse_albedo_1 = (base * (1.0 - metallic));
    {
        float3 _e61 = n;
        const float3 _e62 = standard_low(_e61, v_3, _e54, f0_3, diffuse_albedo_1, roughness_4, ao_1, specular_strength_1);
        float3 _e63 = n;
        const float3 _e65 = standard_sphere_map(_e62, _e63, in_1.world_position);
        float3 radiance = clamp((_e65 + _e22), (0.0).xxx, (65504.0).xxx);
        standard_alpha_test(alpha_4);
        return float4(radiance, alpha_4);
    }
}
