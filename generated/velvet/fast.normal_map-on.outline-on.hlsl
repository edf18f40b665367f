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
Texture2D<float4> normal_map : register(t4, space1);
Texture2D<float4> occlusion_map : register(t5, space1);

struct VertexOutput_vs_outline {
    float4 clip_position : SV_Position;
};

struct VertexOutput_vs_main {
    float3 world_position_2 : LOC0;
    float3 world_normal_1 : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    float4 clip_position_1 : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_3 : LOC0;
    float3 world_normal_2 : LOC1;
    float4 world_tangent_1 : LOC2;
    float2 uv0_1 : LOC3;
    float4 clip_position_2 : SV_Position;
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

float3 weft_any_perpendicular(float3 n_1)
{
    float s = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return float3((1.0 + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
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

float3 weft_sh_irradiance(float3 n_2)
{
    float3 e = (float3)0;

    float4 sh[9] = weft_frame.sh;
    e = (sh[0].xyz * 0.282095);
    float3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_2.y)));
    float3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_2.z)));
    float3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_2.x)));
    float3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_2.x) * n_2.y)));
    float3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_2.y) * n_2.z)));
    float3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_2.z) * n_2.z) - 1.0))));
    float3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_2.x) * n_2.z)));
    float3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_2.x * n_2.x) - (n_2.y * n_2.y)))));
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

WeftLightGeometry weft_main_light_geometry(float3 n_3, float3 v_2)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_2), n_3);
    const float _e6 = weft_clamp_cos(dot(n_3, v_2));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_3, _e2)), saturate(dot(n_3, _e4)), saturate(dot(v_2, _e4)));
    return weftlightgeometry;
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

float3x3 weft_tangent_frame(float3 n_4, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_4 * dot(n_4, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_4);
    float3 t = (ok ? (t_proj * rsqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_4, t) * s_1);
    return float3x3(t, b_1, n_4);
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

float3 weft_mapped_normal(float3 n_5, float4 tangent_1, float3 texel_1, float strength_1)
{
    const float3x3 _e4 = weft_tangent_frame(n_5, tangent_1);
    const float3 _e5 = weft_unpack_normal(texel_1, strength_1);
    const float3 _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
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
    float t_1 = ((1.0 - r) * (1.0 - r));
    float a_1 = lerp(21.5473, 25.3245, t_1);
    float b_2 = lerp(3.82987, 3.32435, t_1);
    float c_2 = lerp(0.19823, 0.16801, t_1);
    float d = lerp(-1.9776, -1.27393, t_1);
    float e_1 = lerp(-4.32054, -4.85967, t_1);
    return (((a_1 / (1.0 + (b_2 * pow(max(x, 0.0), c_2)))) + (d * x)) + e_1);
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

float weft_sheen_albedo_scaling_view(float3 sheen_color_1, float e_v)
{
    const float _e2 = weft_max3_(sheen_color_1);
    return saturate((1.0 - (saturate(_e2) * saturate(e_v))));
}

float weft_sheen_albedo(float n_dot_x, float sheen_roughness_4)
{
    const float _e3 = weft_sheen_clamp_roughness(sheen_roughness_4);
    float2 uv_1 = float2(saturate(n_dot_x), _e3);
    float4 _e8 = weft_sheen_lut.SampleLevel(weft_lut_sampler, uv_1, 0.0);
    return saturate(_e8.x);
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

VertexOutput_vs_main vs_main(WeftVertexInput in_1)
{
    const WeftVaryings _e1 = weft_forward_vertex(in_1);
    const WeftVaryings weftvaryings_1 = _e1;
    const VertexOutput_vs_main weftvaryings_1_ = { weftvaryings_1.world_position, weftvaryings_1.world_normal, weftvaryings_1.world_tangent, weftvaryings_1.uv0_, weftvaryings_1.clip_position };
    return weftvaryings_1_;
}

float4 fs_main(FragmentInput_fs_main fragmentinput_fs_main) : SV_Target0
{
    WeftVaryings in_2 = { fragmentinput_fs_main.clip_position_2, fragmentinput_fs_main.world_position_3, fragmentinput_fs_main.world_normal_2, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_1 };
    float3 n = (float3)0;
    float3 color = (float3)0;
    float3 sheen = (float3)0;
    float scaling = (float)0;

    float4 _e4 = material.base_map_st;
    const float2 _e5 = weft_transform_uv(in_2.uv0_, _e4);
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
    const WeftSurface _e39 = weft_surface(in_2.world_position, in_2.world_normal);
    float3 v_4 = _e39.v;
    n = _e39.n;
    {
        float4 _e45 = normal_map.Sample(material_sampler, _e5);
        float3 texel_2 = _e45.xyz;
        float3 _e47 = n;
        float _e51 = material.normal_strength;
        const float3 _e52 = weft_mapped_normal(_e47, in_2.world_tangent, texel_2, _e51);
        n = _e52;
    }
    float3 _e53 = n;
    const WeftLightGeometry _e54 = weft_main_light_geometry(_e53, v_4);
    float l_dot_h = saturate(dot(_e54.l, _e54.h));
    float3 f0_ = lerp((0.04).xxx, base, metallic);
    float3 diffuse_albedo = (base * (1.0 - metallic));
    const float3 _e65 = weft_main_light_radiance();
    float3 _e66 = n;
    const float3 _e67 = weft_sh_irradiance(_e66);
    float3 ambient = (_e67 * ao);
    {
        float4 _e72 = material.scatter_color;
        float3 sheen_color_2 = saturate((f0_ + max(_e72.xyz, (0.0).xxx)));
        const float _e79 = weft_sheen_clamp_roughness(roughness_2);
        const float _e81 = weft_sheen_albedo(_e54.n_dot_v, _e79);
        const float _e82 = weft_sheen_albedo_scaling_view(sheen_color_2, _e81);
        {
            const float3 _e88 = weft_sheen_charlie(sheen_color_2, _e54.n_dot_h, _e54.n_dot_v, _e54.n_dot_l, _e79);
            sheen = _e88;
            scaling = _e82;
        }
        const float3 _e89 = weft_diffuse_lambert(diffuse_albedo);
        float _e90 = scaling;
        float3 base_direct = (_e89 * (_e90 * _e54.n_dot_l));
        float3 _e94 = sheen;
        float3 direct = ((_e94 + base_direct) * _e65);
        float3 _e98 = n;
        const float3 _e100 = weft_prefiltered_radiance(reflect(-(v_4), _e98), _e79);
        float3 env_sheen = ((_e100 * sheen_color_2) * (_e81 * ao));
        color = ((direct + ((ambient * diffuse_albedo) * _e82)) + env_sheen);
    }
    float3 _e108 = color;
    float3 radiance = clamp(_e108, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
