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
    float metallic;
    float smoothness;
    int _pad4_0;
    int _pad4_1;
    float4 spot_color;
    float4 noise_map_st;
    float2 strand_density;
    float fur_length;
    float height_scale;
    float fur_occlusion;
    float cutoff_start;
    float cutoff_end;
    float edge_fade;
    uint tapered_tips;
    int shell_count;
    int _pad15_0;
    int _pad15_1;
    float3 force_direction;
    float force_strength;
    float force_map_scale;
    int _pad18_0;
    int _pad18_1;
    int _pad18_2;
    float4 sheen_color;
    float scatter_scale;
    int _pad20_0;
    int _pad20_1;
    int _pad20_2;
    float4 strand_color;
    float strand_strength;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
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

struct FurInput {
    float3 position : LOC0;
    float3 normal : LOC1;
    float2 uv0_ : LOC3;
};

struct FurVaryings {
    float4 clip_position : SV_Position;
    float3 world_position : LOC0;
    float3 world_normal : LOC1;
    float3 strand : LOC2;
    float2 uv0_ : LOC3;
    float offset : LOC4;
    float4 light_diffuse : LOC5;
    float4 light_ambient : LOC6;
    float4 light_sheen : LOC7;
    float4 light_strand : LOC8;
    float light_n_dot_v : LOC9;
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
static const float FUR_SEED_SHELLS = 20.0;

cbuffer weft_frame : register(b0) { WeftFrame weft_frame; }
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }
cbuffer material : register(b0, space1) { WeftMaterial material; }
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
Texture2D<float4> base_map : register(t3, space1);
Texture2D<float4> spot_map : register(t4, space1);
Texture2D<float4> noise_map : register(t5, space1);
Texture2D<float4> height_map : register(t6, space1);
Texture2D<float4> force_map : register(t7, space1);

struct VertexOutput_vs_skin {
    float3 world_position_2 : LOC0;
    float3 world_normal_1 : LOC1;
    float3 strand : LOC2;
    float2 uv0_1 : LOC3;
    float offset_1 : LOC4;
    float4 light_diffuse : LOC5;
    float4 light_ambient : LOC6;
    float4 light_sheen : LOC7;
    float4 light_strand : LOC8;
    float light_n_dot_v : LOC9;
    float4 clip_position : SV_Position;
};

struct VertexOutput_vs_shell {
    float3 world_position_3 : LOC0;
    float3 world_normal_2 : LOC1;
    float3 strand_1 : LOC2;
    float2 uv0_2 : LOC3;
    float offset_2 : LOC4;
    float4 light_diffuse_1 : LOC5;
    float4 light_ambient_1 : LOC6;
    float4 light_sheen_1 : LOC7;
    float4 light_strand_1 : LOC8;
    float light_n_dot_v_1 : LOC9;
    float4 clip_position_1 : SV_Position;
};

struct FragmentInput_fs_skin {
    float3 world_position_4 : LOC0;
    float3 world_normal_3 : LOC1;
    float3 strand_2 : LOC2;
    float2 uv0_3 : LOC3;
    float offset_3 : LOC4;
    float4 light_diffuse_2 : LOC5;
    float4 light_ambient_2 : LOC6;
    float4 light_sheen_2 : LOC7;
    float4 light_strand_2 : LOC8;
    float light_n_dot_v_2 : LOC9;
    float4 clip_position_2 : SV_Position;
};

struct FragmentInput_fs_shell {
    float3 world_position_5 : LOC0;
    float3 world_normal_4 : LOC1;
    float3 strand_3 : LOC2;
    float2 uv0_4 : LOC3;
    float offset_4 : LOC4;
    float4 light_diffuse_3 : LOC5;
    float4 light_ambient_3 : LOC6;
    float4 light_sheen_3 : LOC7;
    float4 light_strand_3 : LOC8;
    float light_n_dot_v_3 : LOC9;
    float4 clip_position_3 : SV_Position;
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

float3 weft_f_schlick(float3 f0_, float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (f0_ + (((1.0).xxx - f0_) * _e5));
}

float weft_v_schlick_ggx(float n_dot_v, float n_dot_l, float roughness_1)
{
    const float _e3 = weft_clamp_roughness(roughness_1);
    float a = (_e3 * _e3);
    float k = (((a + 1.0) * (a + 1.0)) * 0.125);
    float gv = ((saturate(n_dot_v) * (1.0 - k)) + k);
    float gl = ((saturate(n_dot_l) * (1.0 - k)) + k);
    return (0.25 / (gv * gl));
}

float3 weft_diffuse_lambert(float3 albedo)
{
    return (albedo * WEFT_INV_PI);
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

float3 weft_sh_irradiance(float3 n)
{
    float3 e = (float3)0;

    float4 sh[9] = weft_frame.sh;
    e = (sh[0].xyz * 0.282095);
    float3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n.y)));
    float3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n.z)));
    float3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n.x)));
    float3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n.x) * n.y)));
    float3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n.y) * n.z)));
    float3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n.z) * n.z) - 1.0))));
    float3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n.x) * n.z)));
    float3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n.x * n.x) - (n.y * n.y)))));
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

WeftLightGeometry weft_main_light_geometry(float3 n_1, float3 v_1)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_1), n_1);
    const float _e6 = weft_clamp_cos(dot(n_1, v_1));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_1, _e2)), saturate(dot(n_1, _e4)), saturate(dot(v_1, _e4)));
    return weftlightgeometry;
}

float2 fur_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

FurVaryings fur_vertex(FurInput in_4, float offset)
{
    FurVaryings out_ = (FurVaryings)0;

    float4x4 model = weft_object.model;
    float4x4 nm = weft_object.normal_matrix;
    float3x3 normal3_ = float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    float3 world = mul(float4(in_4.position, 1.0), model).xyz;
    const float3 _e24 = weft_safe_normalize(mul(in_4.normal, normal3_), (0.0).xxx);
    float4 _e28 = material.base_map_st;
    const float2 _e29 = fur_transform_uv(in_4.uv0_, _e28);
    float4 _e33 = force_map.SampleLevel(material_sampler, _e29, 0.0);
    float3 force_texel = _e33.xyz;
    float3 _e37 = material.force_direction;
    float _e45 = material.force_map_scale;
    float3 force = (_e37 + (((force_texel * 2.0) - (1.0).xxx) * _e45));
    float _e50 = material.force_strength;
    float s = saturate(_e50);
    float3 target_dir = ((_e24 * (1.0 - s)) + (force * s));
    float4 _e60 = height_map.SampleLevel(material_sampler, _e29, 0.0);
    float height = _e60.x;
    float _e64 = material.height_scale;
    float hs = saturate(_e64);
    float _e68 = material.fur_length;
    float len = (max(_e68, 0.0) * max((1.0 + (hs * (saturate(height) - 1.0))), 0.0));
    float3 dir = lerp(_e24, target_dir, offset);
    float3 p = (world + (dir * (len * offset)));
    float4x4 _e88 = weft_frame.view_proj;
    out_.clip_position = mul(float4(p, 1.0), _e88);
    out_.world_position = p;
    out_.world_normal = _e24;
    out_.strand = (_e24 + ((2.0 * offset) * (target_dir - _e24)));
    out_.uv0_ = in_4.uv0_;
    out_.offset = offset;
    FurVaryings _e103 = out_;
    const FurVaryings furvaryings = _e103;
    return furvaryings;
}

float fur_noise(float2 uv0_)
{
    float4 _e3 = material.noise_map_st;
    const float2 _e4 = fur_transform_uv(uv0_, _e3);
    {
        float4 _e7 = noise_map.Sample(material_sampler, _e4);
        return saturate(_e7.x);
    }
}

float4 fur_shade(FurVaryings in_5)
{
    float3 color = (float3)0;

    float4 _e4 = material.base_map_st;
    const float2 _e5 = fur_transform_uv(in_5.uv0_, _e4);
    float4 _e8 = material.base_color;
    float4 _e11 = base_map.Sample(material_sampler, _e5);
    float4 base_rgba = (_e8 * _e11);
    float4 _e15 = spot_map.Sample(material_sampler, _e5);
    float spot = saturate(_e15.x);
    float4 _e22 = material.spot_color;
    float3 base = lerp(saturate(base_rgba.xyz), saturate(_e22.xyz), spot);
    float alpha = saturate(base_rgba.w);
    {
        float _e31 = material.metallic;
        float metallic = saturate(_e31);
        float _e35 = material.smoothness;
        float smoothness = saturate(_e35);
        float roughness_2 = (1.0 - smoothness);
        const WeftSurface _e41 = weft_surface(in_5.world_position, in_5.world_normal);
        float3 v_2 = _e41.v;
        float3 n_2 = _e41.n;
        const float3 _e45 = weft_safe_normalize(in_5.strand, n_2);
        const WeftLightGeometry _e46 = weft_main_light_geometry(n_2, v_2);
        float l_dot_h = saturate(dot(_e46.l, _e46.h));
        float3 f0_1 = lerp((0.04).xxx, base, metallic);
        float3 diffuse_albedo = (base * (1.0 - metallic));
        const float3 _e57 = weft_main_light_radiance();
        const float3 _e58 = weft_sh_irradiance(n_2);
        {
            const float _e61 = weft_v_schlick_ggx(_e46.n_dot_v, _e46.n_dot_l, roughness_2);
            const float3 _e62 = weft_f_schlick(f0_1, l_dot_h);
            const float _e64 = weft_fabric_d(_e46.n_dot_h);
            float3 specular = ((_e64 * _e61) * _e62);
            const float3 _e67 = weft_diffuse_lambert(diffuse_albedo);
            float4 _e70 = material.sheen_color;
            float _e76 = material.scatter_scale;
            const float3 _e77 = weft_fabric_scatter(_e70.xyz, _e46.n_dot_l, _e46.n_dot_v, _e76);
            color = (((((_e67 + specular) * _e57) * _e46.n_dot_l) + (_e58 * diffuse_albedo)) + _e77);
        }
    }
    float _e87 = material.fur_occlusion;
    float occlusion = (1.0 - (saturate(_e87) * (1.0 - in_5.offset)));
    float3 _e95 = color;
    float3 radiance = clamp((_e95 * occlusion), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}

float fur_fade_n_dot_v(FurVaryings in_6)
{
    const WeftSurface _e3 = weft_surface(in_6.world_position, in_6.world_normal);
    return saturate(dot(_e3.n, _e3.v));
}

float4 fur_shell(FurVaryings in_7)
{
    const float _e2 = fur_noise(in_7.uv0_);
    float o = saturate(in_7.offset);
    uint _e8 = material.tapered_tips;
    float shape = ((_e8 != 0u) ? (o * o) : o);
    float _e14 = material.cutoff_start;
    float _e18 = material.cutoff_end;
    float threshold = lerp(saturate(_e14), saturate(_e18), shape);
    float _e21 = fwidth(_e2);
    float width = max(_e21, 0.001);
    float coverage = (saturate((((_e2 - threshold) / width) + 0.5)) * step(1e-6, _e2));
    const float4 _e32 = fur_shade(in_7);
    float _e35 = material.edge_fade;
    const float _e37 = fur_fade_n_dot_v(in_7);
    float fade = (1.0 - (saturate(_e35) * (1.0 - _e37)));
    float a_1 = saturate((((coverage * (1.0 - o)) * fade) * _e32.w));
    int _e53 = material.shell_count;
    float slab = (FUR_SEED_SHELLS / float(max(_e53, int(1))));
    float keep = (1.0 - a_1);
    float alpha_1 = (1.0 - ((keep <= 0.0) ? 0.0 : pow(keep, slab)));
    return float4(_e32.xyz, alpha_1);
}

VertexOutput_vs_skin vs_skin(FurInput in_)
{
    const FurVaryings _e2 = fur_vertex(in_, 0.0);
    const FurVaryings furvaryings_1 = _e2;
    const VertexOutput_vs_skin furvaryings_1_ = { furvaryings_1.world_position, furvaryings_1.world_normal, furvaryings_1.strand, furvaryings_1.uv0_, furvaryings_1.offset, furvaryings_1.light_diffuse, furvaryings_1.light_ambient, furvaryings_1.light_sheen, furvaryings_1.light_strand, furvaryings_1.light_n_dot_v, furvaryings_1.clip_position };
    return furvaryings_1_;
}

VertexOutput_vs_shell vs_shell(FurInput in_1, uint instance : SV_InstanceID)
{
    int _e4 = material.shell_count;
    float count = float(max(_e4, int(1)));
    const FurVaryings _e12 = fur_vertex(in_1, ((float(instance) + 0.5) / count));
    const FurVaryings furvaryings_2 = _e12;
    const VertexOutput_vs_shell furvaryings_2_ = { furvaryings_2.world_position, furvaryings_2.world_normal, furvaryings_2.strand, furvaryings_2.uv0_, furvaryings_2.offset, furvaryings_2.light_diffuse, furvaryings_2.light_ambient, furvaryings_2.light_sheen, furvaryings_2.light_strand, furvaryings_2.light_n_dot_v, furvaryings_2.clip_position };
    return furvaryings_2_;
}

float4 fs_skin(FragmentInput_fs_skin fragmentinput_fs_skin) : SV_Target0
{
    FurVaryings in_2 = { fragmentinput_fs_skin.clip_position_2, fragmentinput_fs_skin.world_position_4, fragmentinput_fs_skin.world_normal_3, fragmentinput_fs_skin.strand_2, fragmentinput_fs_skin.uv0_3, fragmentinput_fs_skin.offset_3, fragmentinput_fs_skin.light_diffuse_2, fragmentinput_fs_skin.light_ambient_2, fragmentinput_fs_skin.light_sheen_2, fragmentinput_fs_skin.light_strand_2, fragmentinput_fs_skin.light_n_dot_v_2 };
    const float4 _e1 = fur_shade(in_2);
    return float4(_e1.xyz, 1.0);
}

float4 fs_shell(FragmentInput_fs_shell fragmentinput_fs_shell) : SV_Target0
{
    FurVaryings in_3 = { fragmentinput_fs_shell.clip_position_3, fragmentinput_fs_shell.world_position_5, fragmentinput_fs_shell.world_normal_4, fragmentinput_fs_shell.strand_3, fragmentinput_fs_shell.uv0_4, fragmentinput_fs_shell.offset_4, fragmentinput_fs_shell.light_diffuse_3, fragmentinput_fs_shell.light_ambient_3, fragmentinput_fs_shell.light_sheen_3, fragmentinput_fs_shell.light_strand_3, fragmentinput_fs_shell.light_n_dot_v_3 };
    const float4 _e1 = fur_shell(in_3);
    return _e1;
}
