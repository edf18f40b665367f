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
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }
cbuffer material : register(b0, space1) { WeftMaterial material; }
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
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

float weft_pow4_(float x)
{
    float x2_ = (x * x);
    return (x2_ * x2_);
}

float weft_pow5_(float x_1)
{
    float x2_1 = (x_1 * x_1);
    return ((x2_1 * x2_1) * x_1);
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

float3 weft_f_schlick(float3 f0_, float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (f0_ + (((1.0).xxx - f0_) * _e5));
}

float weft_v_schlick_ggx(float n_dot_v, float n_dot_l, float roughness_1)
{
    const float _e3 = weft_clamp_roughness(roughness_1);
    float a_1 = (_e3 * _e3);
    float k = (((a_1 + 1.0) * (a_1 + 1.0)) * 0.125);
    float gv = ((saturate(n_dot_v) * (1.0 - k)) + k);
    float gl = ((saturate(n_dot_l) * (1.0 - k)) + k);
    return (0.25 / (gv * gl));
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

WeftLightGeometry weft_main_light_geometry(float3 n_3, float3 v_1)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_1), n_3);
    const float _e6 = weft_clamp_cos(dot(n_3, v_1));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_3, _e2)), saturate(dot(n_3, _e4)), saturate(dot(v_1, _e4)));
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
    float3 v_2 = ((texel * 2.0) - (1.0).xxx);
    return float3((v_2.xy * strength), max(v_2.z, 0.001));
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

float weft_fabric_d(float n_dot_h)
{
    float x_2 = (1.0 - saturate(n_dot_h));
    return (((0.96 * x_2) * x_2) + 0.057);
}

float weft_fabric_scatter_fresnel_lerp(float n_dot_v_1, float scale)
{
    float x_3 = (1.0 - saturate(n_dot_v_1));
    const float _e5 = weft_pow4_(x_3);
    return lerp(_e5, (0.4 * x_3), saturate(scale));
}

float3 weft_fabric_scatter(float3 scatter_color, float n_dot_l_1, float n_dot_v_2, float scale_1)
{
    float wrap = ((saturate(n_dot_l_1) * 0.5) + 0.5);
    const float _e12 = weft_fabric_scatter_fresnel_lerp(n_dot_v_2, scale_1);
    return (max(scatter_color, (0.0).xxx) * (wrap * _e12));
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
    {
        float4 _e45 = normal_map.Sample(material_sampler, _e5);
        float3 texel_2 = _e45.xyz;
        float3 _e47 = n;
        float _e51 = material.normal_strength;
        const float3 _e52 = weft_mapped_normal(_e47, in_1.world_tangent, texel_2, _e51);
        n = _e52;
    }
    float3 _e53 = n;
    const WeftLightGeometry _e54 = weft_main_light_geometry(_e53, v_3);
    float l_dot_h = saturate(dot(_e54.l, _e54.h));
    float3 f0_1 = lerp((0.04).xxx, base, metallic);
    float3 diffuse_albedo = (base * (1.0 - metallic));
    const float3 _e65 = weft_main_light_radiance();
    float3 _e66 = n;
    const float3 _e67 = weft_sh_irradiance(_e66);
    float3 ambient = (_e67 * ao);
    {
        const float _e72 = weft_v_schlick_ggx(_e54.n_dot_v, _e54.n_dot_l, roughness_2);
        const float3 _e73 = weft_f_schlick(f0_1, l_dot_h);
        const float _e75 = weft_fabric_d(_e54.n_dot_h);
        float3 specular = ((_e75 * _e72) * _e73);
        const float3 _e78 = weft_diffuse_lambert(diffuse_albedo);
        float3 direct = (((_e78 + specular) * _e65) * _e54.n_dot_l);
        float4 _e85 = material.scatter_color;
        float _e91 = material.scatter_scale;
        const float3 _e92 = weft_fabric_scatter(_e85.xyz, _e54.n_dot_l, _e54.n_dot_v, _e91);
        color = ((direct + (ambient * diffuse_albedo)) + _e92);
    }
    float3 _e96 = color;
    float3 radiance = clamp(_e96, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
