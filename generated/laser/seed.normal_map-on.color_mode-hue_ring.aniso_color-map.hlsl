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

float laser_cos_in_plane(float3 n_7, float3 v_2, float3 direction)
{
    float3 p = cross(direction, n_7);
    float p_len = length(p);
    if ((p_len < 0.0001)) {
        const float _e8 = weft_clamp_cos(dot(n_7, v_2));
        return _e8;
    }
    float3 p_unit = (p / (p_len).xxx);
    float3 v_in_plane = (v_2 - (dot(v_2, p_unit) * p_unit));
    float len = length(v_in_plane);
    const float _e19 = weft_clamp_cos((dot(n_7, v_in_plane) / max(len, 0.0001)));
    return _e19;
}

float3 laser_hsv_to_rgb(float3 hsv)
{
    float3 k = float3(0.0, 0.6666667, 0.33333334);
    float3 p_1 = abs(((frac(((hsv.x).xxx + k)) * 6.0) - (3.0).xxx));
    float3 ring = saturate((p_1 - (1.0).xxx));
    return (hsv.z * lerp((1.0).xxx, ring, hsv.y));
}

float3 laser_seed_color(float cos_theta, float2 layer_offsets)
{
    float3 hsv_1 = (float3)0;

    float c_2 = saturate(cos_theta);
    uint _e13 = material.sin_mapping;
    float x_1 = ((_e13 != 0u) ? sqrt(max((1.0 - (c_2 * c_2)), 0.0)) : (1.0 - c_2));
    float _e19 = material.saturation;
    float saturation = saturate(_e19);
    float _e23 = material.brightness;
    float brightness = saturate(_e23);
    float _e27 = material.span;
    hsv_1 = float3((x_1 * _e27), saturation, brightness);
    float _e32 = hsv_1.x;
    float _e35 = material.view_offset;
    float hue = (_e32 + _e35);
    float _e41 = hsv_1.y;
    float _e43 = hsv_1.z;
    const float3 _e45 = laser_hsv_to_rgb(float3(frac((hue + layer_offsets.x)), _e41, _e43));
    float _e50 = hsv_1.y;
    float _e52 = hsv_1.z;
    const float3 _e54 = laser_hsv_to_rgb(float3(frac((hue + layer_offsets.y)), _e50, _e52));
    return (0.5 * (_e45 + _e54));
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
    {
        float _e103 = film_cos;
        const float3 _e104 = laser_seed_color(_e103, offsets);
        surface_base = (base * _e104);
    }
    float3 _e108 = surface_base;
    float3 f0_2 = lerp((0.04).xxx, _e108, metallic);
    float3 _e110 = surface_base;
    float3 diffuse_albedo = (_e110 * (1.0 - metallic));
    const float2 _e115 = weft_env_brdf_lut(_e66.n_dot_v, roughness_6);
    const float3 _e117 = weft_f_schlick(f0_2, _e66.v_dot_h);
    f_light = _e117;
    const float3 _e119 = weft_env_brdf_from_lut(f0_2, _e115);
    e_spec = _e119;
    float3 _e123 = e_spec;
    float3 kd = max(((1.0).xxx - _e123), (0.0).xxx);
    const float _e130 = weft_v_smith_ggx_correlated(_e66.n_dot_v, _e66.n_dot_l, roughness_6);
    float3 _e131 = n;
    const float _e133 = weft_d_ggx_nh(_e131, _e66.h, roughness_6);
    float3 _e135 = f_light;
    float3 specular = ((_e133 * _e130) * _e135);
    const float3 _e137 = weft_diffuse_lambert(diffuse_albedo);
    float3 diffuse = (kd * _e137);
    const float3 _e140 = weft_main_light_radiance();
    float3 direct = (((diffuse + specular) * _e140) * _e66.n_dot_l);
    float3 _e145 = n;
    const float3 _e147 = weft_prefiltered_radiance(reflect(-(v_4), _e145), roughness_6);
    float3 _e148 = e_spec;
    float3 indirect_specular = ((_e147 * _e148) * ao);
    float3 _e151 = n;
    const float3 _e152 = weft_sh_irradiance(_e151);
    float3 indirect_diffuse = (((_e152 * ao) * kd) * diffuse_albedo);
    float3 color = ((direct + indirect_specular) + indirect_diffuse);
    return float4(clamp(color, (0.0).xxx, (65504.0).xxx), alpha);
}
