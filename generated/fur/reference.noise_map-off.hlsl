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
Texture2D<float4> spot_map : register(t4, space1);
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

float weft_pow5_(float x)
{
    float x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

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

float3 weft_f_schlick(float3 f0_, float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (f0_ + (((1.0).xxx - f0_) * _e5));
}

float3 weft_diffuse_lambert(float3 albedo)
{
    return (albedo * WEFT_INV_PI);
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

float weft_sheen_l(float x_1, float r)
{
    float t_1 = ((1.0 - r) * (1.0 - r));
    float a = lerp(21.5473, 25.3245, t_1);
    float b = lerp(3.82987, 3.32435, t_1);
    float c_1 = lerp(0.19823, 0.16801, t_1);
    float d = lerp(-1.9776, -1.27393, t_1);
    float e_1 = lerp(-4.32054, -4.85967, t_1);
    return (((a / (1.0 + (b * pow(max(x_1, 0.0), c_1)))) + (d * x_1)) + e_1);
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
    float c_2 = saturate(_e3);
    return saturate(min((1.0 - (c_2 * saturate(e_v))), (1.0 - (c_2 * saturate(e_l)))));
}

float weft_sheen_albedo_scaling_view(float3 sheen_color_2, float e_v_1)
{
    const float _e2 = weft_max3_(sheen_color_2);
    return saturate((1.0 - (saturate(_e2) * saturate(e_v_1))));
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
    float4 c_3 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_3.xyz, (0.0).xxx);
}

float weft_sheen_albedo(float n_dot_x, float sheen_roughness_4)
{
    const float _e3 = weft_sheen_clamp_roughness(sheen_roughness_4);
    float2 uv_1 = float2(saturate(n_dot_x), _e3);
    float4 _e8 = weft_sheen_lut.SampleLevel(weft_lut_sampler, uv_1, 0.0);
    return saturate(_e8.x);
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

WeftLightGeometry weft_main_light_geometry(float3 n_1, float3 v_2)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_2), n_1);
    const float _e6 = weft_clamp_cos(dot(n_1, v_2));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_1, _e2)), saturate(dot(n_1, _e4)), saturate(dot(v_2, _e4)));
    return weftlightgeometry;
}

float2 fur_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

float fur_strand_exponent(float smoothness)
{
    return exp2((1.0 + (9.0 * saturate(smoothness))));
}

float fur_strand_norm(float p)
{
    return sqrt(((((2.0 * p) + 1.0) * 0.25) * WEFT_INV_PI));
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
    float3 dir_1 = lerp(_e24, target_dir, offset);
    float3 p_1 = (world + (dir_1 * (len * offset)));
    float4x4 _e88 = weft_frame.view_proj;
    out_.clip_position = mul(float4(p_1, 1.0), _e88);
    out_.world_position = p_1;
    out_.world_normal = _e24;
    out_.strand = (_e24 + ((2.0 * offset) * (target_dir - _e24)));
    out_.uv0_ = in_4.uv0_;
    out_.offset = offset;
    FurVaryings _e103 = out_;
    const FurVaryings furvaryings = _e103;
    return furvaryings;
}

uint fur_pcg(uint x_2)
{
    uint state = ((x_2 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return ((word >> 22u) ^ word);
}

int2 naga_f2i32(float2 value) {
    return int2(clamp(value, -2147483600.0, 2147483500.0));
}

float fur_strand_cell(float2 x_3, uint salt)
{
    float2 cell = floor(x_3);
    uint2 c_4 = uint2(naga_f2i32((cell - (65536.0 * floor((cell / (65536.0).xx))))));
    const uint _e15 = fur_pcg((c_4.y + salt));
    const uint _e17 = fur_pcg((c_4.x + _e15));
    const uint _e18 = fur_pcg(_e17);
    const uint _e19 = fur_pcg(_e18);
    float2 jitter = (((float2(float((_e17 & 65535u)), float((_e18 & 65535u))) / (65535.0).xx) - (0.5).xx) * 0.3);
    float peak = (0.7 + ((0.3 * float((_e19 & 65535u))) / 65535.0));
    float r_3 = length((frac(x_3) - ((0.5).xx + jitter)));
    return (saturate((1.0 - (r_3 / 0.35))) * peak);
}

float fur_procedural_noise(float2 x_4)
{
    float2 rotated = ((float2(((0.8 * x_4.x) - (0.6 * x_4.y)), ((0.6 * x_4.x) + (0.8 * x_4.y))) * 1.31) + float2(17.3, 5.9));
    const float _e23 = fur_strand_cell(x_4, 0u);
    const float _e25 = fur_strand_cell(rotated, 2654435769u);
    return max(_e23, _e25);
}

float fur_noise(float2 uv0_)
{
    float4 _e3 = material.noise_map_st;
    const float2 _e4 = fur_transform_uv(uv0_, _e3);
    float4 _e7 = material.noise_map_st;
    float2 _e12 = material.strand_density;
    float4 _e16 = material.noise_map_st;
    const float _e19 = fur_procedural_noise((((uv0_ * _e7.xy) * _e12) + _e16.zw));
    return _e19;
}

float2 fur_kajiya_kay_cone(float3 t, float3 l, float3 v_3)
{
    float t_dot_l = clamp(dot(t, l), -1.0, 1.0);
    float t_dot_v = clamp(dot(t, v_3), -1.0, 1.0);
    float sin_l = sqrt(max((1.0 - (t_dot_l * t_dot_l)), 0.0));
    float sin_v = sqrt(max((1.0 - (t_dot_v * t_dot_v)), 0.0));
    return float2(max(((sin_l * sin_v) - (t_dot_l * t_dot_v)), 0.0), sin_l);
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
        float smoothness_1 = saturate(_e35);
        float roughness_2 = (1.0 - smoothness_1);
        const WeftSurface _e41 = weft_surface(in_5.world_position, in_5.world_normal);
        float3 v_4 = _e41.v;
        float3 n_2 = _e41.n;
        const float3 _e45 = weft_safe_normalize(in_5.strand, n_2);
        const WeftLightGeometry _e46 = weft_main_light_geometry(n_2, v_4);
        float l_dot_h = saturate(dot(_e46.l, _e46.h));
        float3 f0_1 = lerp((0.04).xxx, base, metallic);
        float3 diffuse_albedo = (base * (1.0 - metallic));
        const float3 _e57 = weft_main_light_radiance();
        const float3 _e58 = weft_sh_irradiance(n_2);
        {
            float4 _e61 = material.sheen_color;
            float3 sheen_color_3 = saturate((f0_1 + max(_e61.xyz, (0.0).xxx)));
            const float _e68 = weft_sheen_clamp_roughness(roughness_2);
            const float _e70 = weft_sheen_albedo(_e46.n_dot_v, _e68);
            const float _e72 = weft_sheen_albedo(_e46.n_dot_l, _e68);
            const float _e73 = weft_sheen_albedo_scaling_view(sheen_color_3, _e70);
            const float _e74 = weft_sheen_albedo_scaling(sheen_color_3, _e70, _e72);
            const float3 _e78 = weft_sheen_charlie(sheen_color_3, _e46.n_dot_h, _e46.n_dot_v, _e46.n_dot_l, _e68);
            const float _e79 = fur_strand_exponent(smoothness_1);
            const float2 _e81 = fur_kajiya_kay_cone(_e45, _e46.l, v_4);
            float strand_4 = (pow(_e81.x, _e79) * _e81.y);
            const float3 _e86 = weft_f_schlick(f0_1, l_dot_h);
            float4 _e89 = material.strand_color;
            float3 strand_color = (max(_e89.xyz, (0.0).xxx) * _e86);
            float _e97 = material.strand_strength;
            const float _e100 = fur_strand_norm(_e79);
            float3 strand_lobe = (strand_color * (((max(_e97, 0.0) * _e100) * strand_4) * _e46.n_dot_l));
            const float3 _e106 = weft_diffuse_lambert(diffuse_albedo);
            float3 base_direct = (_e106 * (_e74 * _e46.n_dot_l));
            float3 direct = (((_e78 + base_direct) + strand_lobe) * _e57);
            const float3 _e115 = weft_prefiltered_radiance(reflect(-(v_4), n_2), _e68);
            float3 env_sheen = ((_e115 * sheen_color_3) * _e70);
            color = ((direct + ((_e58 * diffuse_albedo) * _e73)) + env_sheen);
        }
    }
    float _e124 = material.fur_occlusion;
    float occlusion = (1.0 - (saturate(_e124) * (1.0 - in_5.offset)));
    float3 _e132 = color;
    float3 radiance = clamp((_e132 * occlusion), (0.0).xxx, (65504.0).xxx);
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
