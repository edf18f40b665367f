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
    float4 scatter_color;
    float scatter_scale;
    int _pad8_0;
    int _pad8_1;
    int _pad8_2;
    float4 outline_color;
    float outline_width;
    float outline_max_distance;
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
static const uint TIER_SEED = 2u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float WEFT_SHEEN_MIN_ROUGHNESS = 0.07;

cbuffer weft_frame : register(b0) { WeftFrame weft_frame; }
TextureCube<float4> weft_environment : register(t1);
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup0SamplerIndexArray : register(t64, space0);
#define weft_environment_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[2]])
#define weft_lut_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[4]])
Texture2D<float4> weft_sheen_lut : register(t5);
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

float weft_max3_(float3 v)
{
    return max(v.x, max(v.y, v.z));
}

float weft_clamp_cos(float c)
{
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

float3 weft_safe_normalize(float3 v_1, float3 fallback)
{
    float len2_ = dot(v_1, v_1);
    return ((len2_ > 1e-20) ? (v_1 * rsqrt(max(len2_, 1e-20))) : fallback);
}

float3 weft_diffuse_lambert(float3 albedo)
{
    return (albedo * WEFT_INV_PI);
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
    float r_2 = saturate(roughness);
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r_2 * (1.7 - (0.7 * r_2))) * max_mip);
}

float3 weft_prefiltered_radiance(float3 dir, float roughness_1)
{
    const float _e4 = weft_specular_mip(roughness_1);
    float4 c_1 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, (0.0).xxx);
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

WeftLightGeometry weft_main_light_geometry(float3 n_2, float3 v_2)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_2), n_2);
    const float _e6 = weft_clamp_cos(dot(n_2, v_2));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_2, _e2)), saturate(dot(n_2, _e4)), saturate(dot(v_2, _e4)));
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

float weft_sheen_clamp_roughness(float sheen_roughness)
{
    return clamp(sheen_roughness, WEFT_SHEEN_MIN_ROUGHNESS, 1.0);
}

float weft_d_charlie(float n_dot_h, float sheen_roughness_1)
{
    const float _e2 = weft_sheen_clamp_roughness(sheen_roughness_1);
    float inv_r = (1.0 / _e2);
    float noh = saturate(n_dot_h);
    float sin2_ = max(((1.0 - noh) * (1.0 + noh)), 0.0);
    return (((2.0 + inv_r) * pow(sin2_, (0.5 * inv_r))) * 0.15915494);
}

float weft_sheen_l(float x, float r)
{
    float t = ((1.0 - r) * (1.0 - r));
    float a = lerp(21.5473, 25.3245, t);
    float b = lerp(3.82987, 3.32435, t);
    float c_2 = lerp(0.19823, 0.16801, t);
    float d = lerp(-1.9776, -1.27393, t);
    float e_1 = lerp(-4.32054, -4.85967, t);
    return (((a / (1.0 + (b * pow(max(x, 0.0), c_2)))) + (d * x)) + e_1);
}

float weft_sheen_lambda_one_exp(float cos_theta, float r_1)
{
    const float _e2 = weft_clamp_cos(cos_theta);
    bool low = (_e2 < 0.5);
    const float _e8 = weft_sheen_l((low ? _e2 : (1.0 - _e2)), r_1);
    const float _e10 = weft_sheen_l(0.5, r_1);
    return exp((low ? _e8 : ((2.0 * _e10) - _e8)));
}

float weft_v_charlie(float n_dot_v, float n_dot_l, float sheen_roughness_2)
{
    const float _e3 = weft_sheen_clamp_roughness(sheen_roughness_2);
    const float _e4 = weft_clamp_cos(n_dot_v);
    const float _e5 = weft_clamp_cos(n_dot_l);
    const float _e6 = weft_sheen_lambda_one_exp(_e4, _e3);
    const float _e9 = weft_sheen_lambda_one_exp(_e5, _e3);
    float g_inv = ((1.0 + _e6) + _e9);
    return (1.0 / (((g_inv * 4.0) * _e4) * _e5));
}

float3 weft_sheen_charlie(float3 sheen_color, float n_dot_h_1, float n_dot_v_1, float n_dot_l_1, float sheen_roughness_3)
{
    const float _e5 = weft_d_charlie(n_dot_h_1, sheen_roughness_3);
    const float _e6 = weft_v_charlie(n_dot_v_1, n_dot_l_1, sheen_roughness_3);
    float lobe = (_e5 * _e6);
    return (max(sheen_color, (0.0).xxx) * (lobe * saturate(n_dot_l_1)));
}

float weft_sheen_albedo_scaling(float3 sheen_color_1, float e_v, float e_l)
{
    const float _e3 = weft_max3_(sheen_color_1);
    float c_3 = saturate(_e3);
    return saturate(min((1.0 - (c_3 * saturate(e_v))), (1.0 - (c_3 * saturate(e_l)))));
}

float weft_sheen_albedo_scaling_view(float3 sheen_color_2, float e_v_1)
{
    const float _e2 = weft_max3_(sheen_color_2);
    return saturate((1.0 - (saturate(_e2) * saturate(e_v_1))));
}

float weft_sheen_albedo(float n_dot_x, float sheen_roughness_4)
{
    const float _e3 = weft_sheen_clamp_roughness(sheen_roughness_4);
    float2 uv_1 = float2(saturate(n_dot_x), _e3);
    float4 _e8 = weft_sheen_lut.SampleLevel(weft_lut_sampler, uv_1, 0.0);
    return saturate(_e8.x);
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
    float3 sheen = (float3)0;
    float scaling = (float)0;

    float4 _e4 = material.base_map_st;
    const float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    float4 _e8 = material.base_color;
    float4 _e11 = base_map.Sample(material_sampler, _e5);
    float4 base_rgba = (_e8 * _e11);
    float3 base = saturate(base_rgba.xyz);
    float alpha = saturate(base_rgba.w);
    float _e19 = material.metallic;
    float metallic = saturate(_e19);
    float _e23 = material.smoothness;
    float smoothness = saturate(_e23);
    float roughness_2 = (1.0 - smoothness);
    float4 _e29 = occlusion_map.Sample(material_sampler, _e5);
    float occlusion = _e29.x;
    float _e33 = material.occlusion_strength;
    float ao = saturate(lerp(1.0, occlusion, _e33));
    const WeftSurface _e39 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_3 = _e39.v;
    n = _e39.n;
    float3 _e43 = n;
    const WeftLightGeometry _e44 = weft_main_light_geometry(_e43, v_3);
    float l_dot_h = saturate(dot(_e44.l, _e44.h));
    float3 f0_ = lerp((0.04).xxx, base, metallic);
    float3 diffuse_albedo = (base * (1.0 - metallic));
    const float3 _e55 = weft_main_light_radiance();
    float3 _e56 = n;
    const float3 _e57 = weft_sh_irradiance(_e56);
    float3 ambient = (_e57 * ao);
    {
        float4 _e62 = material.scatter_color;
        float3 sheen_color_3 = saturate((f0_ + max(_e62.xyz, (0.0).xxx)));
        const float _e69 = weft_sheen_clamp_roughness(roughness_2);
        const float _e71 = weft_sheen_albedo(_e44.n_dot_v, _e69);
        const float _e72 = weft_sheen_albedo_scaling_view(sheen_color_3, _e71);
        {
            const float _e76 = weft_sheen_albedo(_e44.n_dot_l, _e69);
            const float3 _e80 = weft_sheen_charlie(sheen_color_3, _e44.n_dot_h, _e44.n_dot_v, _e44.n_dot_l, _e69);
            sheen = _e80;
            const float _e81 = weft_sheen_albedo_scaling(sheen_color_3, _e71, _e76);
            scaling = _e81;
        }
        const float3 _e82 = weft_diffuse_lambert(diffuse_albedo);
        float _e83 = scaling;
        float3 base_direct = (_e82 * (_e83 * _e44.n_dot_l));
        float3 _e87 = sheen;
        float3 direct = ((_e87 + base_direct) * _e55);
        float3 _e91 = n;
        const float3 _e93 = weft_prefiltered_radiance(reflect(-(v_3), _e91), _e69);
        float3 env_sheen = ((_e93 * sheen_color_3) * (_e71 * ao));
        color = ((direct + ((ambient * diffuse_albedo) * _e72)) + env_sheen);
    }
    float3 _e101 = color;
    float3 radiance = clamp(_e101, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
