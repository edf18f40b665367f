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
    int _pad6_0;
    int _pad6_1;
    int _pad6_2;
    float4 noise_map_st;
    float specular_intensity;
    int _pad8_0;
    int _pad8_1;
    int _pad8_2;
    float4 specular_color;
    float4 second_specular_color;
    float second_layer_width;
    float anisotropy;
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

struct SatinLayers {
    float2 narrow;
    float2 wide;
};

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SEED = 2u;
static const uint TIER_LOW = 3u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float WEFT_MIN_ANISO_ALPHA = 0.001;
static const float WEFT_MIN_ROUGHNESS_HALF = 0.089;
static const float WEFT_MIN_N_DOT_HALF = 0.001;
static const float WEFT_MIN_ALPHA_HALF = 0.007921;

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
Texture2D<float4> rmo_map : register(t5, space1);
Texture2D<float4> noise_map : register(t6, space1);

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

float weft_max3_(float3 v)
{
    return max(v.x, max(v.y, v.z));
}

float weft_clamp_cos(float c)
{
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

float weft_clamp_roughness(float roughness)
{
    return clamp(roughness, WEFT_MIN_ROUGHNESS, 1.0);
}

float3 weft_safe_normalize(float3 v_1, float3 fallback)
{
    float len2_ = dot(v_1, v_1);
    return ((len2_ > 1e-20) ? (v_1 * rsqrt(max(len2_, 1e-20))) : fallback);
}

float3 weft_any_perpendicular(float3 n_1)
{
    float s_1 = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a_1 = (-1.0 / (s_1 + n_1.z));
    float b = ((n_1.x * n_1.y) * a_1);
    return float3((1.0 + (((s_1 * n_1.x) * n_1.x) * a_1)), (s_1 * b), (-(s_1) * n_1.x));
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

float weft_specular_mip(float roughness_1)
{
    float r = saturate(roughness_1);
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

float3 weft_prefiltered_radiance(float3 dir, float roughness_2)
{
    const float _e4 = weft_specular_mip(roughness_2);
    float4 c_2 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_2.xyz, (0.0).xxx);
}

float2 weft_env_brdf_lut(float n_dot_v, float roughness_3)
{
    float2 uv_1 = float2(saturate(n_dot_v), saturate(roughness_3));
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

WeftLightGeometry weft_main_light_geometry(float3 n_3, float3 v_2)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_2), n_3);
    const float _e6 = weft_clamp_cos(dot(n_3, v_2));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_3, _e2)), saturate(dot(n_3, _e4)), saturate(dot(v_2, _e4)));
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
    float s_2 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_4, t) * s_2);
    return float3x3(t, b_1, n_4);
}

float2 weft_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

float3 weft_aniso_to_frame(float3x3 frame, float3 x_1)
{
    return float3(dot(frame[0], x_1), dot(frame[1], x_1), dot(frame[2], x_1));
}

float2 weft_aniso_alpha_kulla(float roughness_4, float anisotropy)
{
    const float _e2 = weft_clamp_roughness(roughness_4);
    float a_2 = (_e2 * _e2);
    float k_1 = clamp(anisotropy, -1.0, 1.0);
    return max(float2((a_2 * (1.0 + k_1)), (a_2 * (1.0 - k_1))), (0.001).xx);
}

float weft_aniso_ggx_q(float t_dot_h, float b_dot_h, float n_dot_h, float alpha_t, float alpha_b)
{
    float at = max(alpha_t, WEFT_MIN_ANISO_ALPHA);
    float ab = max(alpha_b, WEFT_MIN_ANISO_ALPHA);
    float x_2 = (t_dot_h / at);
    float y = (b_dot_h / ab);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 1e-6);
}

float weft_d_ggx_aniso(float t_dot_h_1, float b_dot_h_1, float n_dot_h_1, float alpha_t_1, float alpha_b_1)
{
    float at_1 = max(alpha_t_1, WEFT_MIN_ANISO_ALPHA);
    float ab_1 = max(alpha_b_1, WEFT_MIN_ANISO_ALPHA);
    const float _e9 = weft_aniso_ggx_q(t_dot_h_1, b_dot_h_1, n_dot_h_1, at_1, ab_1);
    float d = (1.0 / ((((WEFT_PI * at_1) * ab_1) * _e9) * _e9));
    return ((n_dot_h_1 > 0.0) ? d : 0.0);
}

float weft_v_smith_ggx_aniso_correlated(float3 v_3, float3 l, float alpha_t_2, float alpha_b_2)
{
    const float _e5 = weft_clamp_cos(v_3.z);
    const float _e7 = weft_clamp_cos(l.z);
    float lv = (_e7 * length(float3((alpha_t_2 * v_3.x), (alpha_b_2 * v_3.y), _e5)));
    float ll = (_e5 * length(float3((alpha_t_2 * l.x), (alpha_b_2 * l.y), _e7)));
    return (0.5 / (lv + ll));
}

float weft_spec_ggx_aniso(float3 v_4, float3 l_1, float alpha_t_3, float alpha_b_3)
{
    const float3 _e9 = weft_safe_normalize((v_4 + l_1), float3(0.0, 0.0, 1.0));
    const float _e13 = weft_d_ggx_aniso(_e9.x, _e9.y, _e9.z, alpha_t_3, alpha_b_3);
    const float _e14 = weft_v_smith_ggx_aniso_correlated(v_4, l_1, alpha_t_3, alpha_b_3);
    return ((_e13 * _e14) * saturate(l_1.z));
}

float3 weft_aniso_bent_normal(float3x3 frame_1, float3 v_5, float anisotropy_1, float roughness_5)
{
    float k_2 = clamp(anisotropy_1, -1.0, 1.0);
    float3 n_5 = frame_1[2];
    float3 dir_1 = ((k_2 >= 0.0) ? frame_1[1] : frame_1[0]);
    float3 aniso_t = cross(dir_1, v_5);
    float3 aniso_n = cross(aniso_t, dir_1);
    float bend = (abs(k_2) * saturate((5.0 * saturate(roughness_5))));
    const float3 _e22 = weft_safe_normalize(lerp(n_5, aniso_n, bend), n_5);
    return _e22;
}

float satin_lobe_reference(float3 vf, float3 lf, float2 a)
{
    float s = (float)0;

    const float _e5 = weft_spec_ggx_aniso(vf, lf, a.x, a.y);
    s = _e5;
    {
        float _e7 = s;
        const float _e10 = weft_spec_ggx_aniso(vf, lf, a.y, a.x);
        s = (0.5 * (_e7 + _e10));
    }
    float _e14 = s;
    return _e14;
}

float3 satin_env(float3x3 frame_2, float3 v_6, float k, float roughness_6)
{
    float3 bent_1 = (float3)0;
    float3 c_1 = (float3)0;

    const float3 _e4 = weft_aniso_bent_normal(frame_2, v_6, k, roughness_6);
    bent_1 = _e4;
    float3 _e7 = bent_1;
    const float3 _e9 = weft_prefiltered_radiance(reflect(-(v_6), _e7), roughness_6);
    c_1 = _e9;
    {
        const float3 _e12 = weft_aniso_bent_normal(frame_2, v_6, -(k), roughness_6);
        bent_1 = _e12;
        float3 _e13 = c_1;
        float3 _e15 = bent_1;
        const float3 _e17 = weft_prefiltered_radiance(reflect(-(v_6), _e15), roughness_6);
        c_1 = (0.5 * (_e13 + _e17));
    }
    float3 _e21 = c_1;
    return _e21;
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
    SatinLayers layers = (SatinLayers)0;
    float3 specular = (float3)0;
    float3 diffuse_kd = (float3)0;
    float3 indirect_specular = (float3)0;
    float3 ambient_kd = (float3)0;
    float3 bent = (float3)0;

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
    float roughness_7 = saturate((_e23 * rmo.x));
    float _e29 = material.metallic;
    float metallic = saturate((_e29 * rmo.y));
    float _e36 = material.occlusion_strength;
    float ao = saturate(lerp(1.0, rmo.z, _e36));
    float _e42 = material.anisotropy;
    float anisotropy_2 = clamp(_e42, -1.0, 1.0);
    float _e48 = material.second_layer_width;
    float width = clamp(_e48, 1.0, 4.0);
    float roughness2_ = min((roughness_7 * width), 1.0);
    float4 _e58 = material.noise_map_st;
    const float2 _e59 = weft_transform_uv(in_1.uv0_, _e58);
    float4 _e62 = noise_map.Sample(material_sampler, _e59);
    float noise_ = (0.5 + (0.5 * saturate(_e62.x)));
    const WeftSurface _e71 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_7 = _e71.v;
    n = _e71.n;
    float3 _e75 = n;
    const float3x3 _e77 = weft_tangent_frame(_e75, in_1.world_tangent);
    float3 _e78 = n;
    const WeftLightGeometry _e79 = weft_main_light_geometry(_e78, v_7);
    const float3 _e80 = weft_main_light_radiance();
    const float2 _e83 = weft_aniso_alpha_kulla(roughness_7, anisotropy_2);
    layers.narrow = _e83;
    const float2 _e85 = weft_aniso_alpha_kulla(roughness2_, anisotropy_2);
    layers.wide = _e85;
    float3 f0_2 = lerp((0.04).xxx, base, metallic);
    float3 diffuse_albedo = (base * (1.0 - metallic));
    float4 _e94 = material.specular_color;
    float3 c1_ = saturate(_e94.xyz);
    float4 _e99 = material.second_specular_color;
    float3 c2_ = saturate(_e99.xyz);
    const float3 _e103 = weft_f_schlick(f0_2, _e79.v_dot_h);
    {
        const float _e108 = weft_max3_(c1_);
        float3 t1_ = lerp(c1_, (_e108).xxx, 0.5);
        const float _e112 = weft_max3_(c2_);
        float3 t2_ = lerp(c2_, (_e112).xxx, 0.5);
        const float _e117 = weft_max3_((t1_ + t2_));
        float norm = (1.0 / max(1.0, _e117));
        float3 w1_ = (t1_ * norm);
        float3 w2_ = (t2_ * norm);
        const float3 _e124 = weft_aniso_to_frame(_e77, v_7);
        const float3 _e126 = weft_aniso_to_frame(_e77, _e79.l);
        float2 _e128 = layers.narrow;
        const float _e129 = satin_lobe_reference(_e124, _e126, _e128);
        float2 _e131 = layers.wide;
        const float _e132 = satin_lobe_reference(_e124, _e126, _e131);
        specular = (((((w1_ * _e129) + (w2_ * _e132)) * _e103) * noise_) * _e80);
        const float3 _e143 = weft_f_schlick(f0_2, _e79.n_dot_v);
        diffuse_kd = max(((1.0).xxx - ((w1_ + w2_) * _e143)), (0.0).xxx);
        const float2 _e150 = weft_env_brdf_lut(_e79.n_dot_v, roughness_7);
        const float3 _e151 = weft_env_brdf_from_lut(f0_2, _e150);
        float3 e1_ = (_e151 * w1_);
        const float2 _e154 = weft_env_brdf_lut(_e79.n_dot_v, roughness2_);
        const float3 _e155 = weft_env_brdf_from_lut(f0_2, _e154);
        float3 e2_ = (_e155 * w2_);
        {
            const float3 _e157 = satin_env(_e77, v_7, anisotropy_2, roughness_7);
            const float3 _e159 = satin_env(_e77, v_7, anisotropy_2, roughness2_);
            indirect_specular = (((_e157 * e1_) + (_e159 * e2_)) * noise_);
        }
        ambient_kd = max((((1.0).xxx - e1_) - e2_), (0.0).xxx);
    }
    float3 _e170 = diffuse_kd;
    const float3 _e171 = weft_diffuse_lambert(diffuse_albedo);
    float3 _e176 = specular;
    float3 direct = ((((_e170 * _e171) * _e80) * _e79.n_dot_l) + _e176);
    float3 _e178 = indirect_specular;
    float3 _e180 = n;
    const float3 _e181 = weft_sh_irradiance(_e180);
    float3 _e183 = ambient_kd;
    float3 indirect = ((_e178 * ao) + (((_e181 * ao) * _e183) * diffuse_albedo));
    float3 radiance = clamp((direct + indirect), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
