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
    float smoothness;
    float metallic;
    uint diffuse_uses_aniso_normal;
    float anisotropy;
    float4 aniso_normal_map_st;
    float aniso_normal_strength;
    float tangent_shift;
    float aniso_gloss;
    float aniso_spec;
    float aniso_mask;
    float flow_strength;
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

struct SilkLobe {
    float value;
    int _pad1_0;
    float2 alpha;
    float ibl_roughness;
    int _end_pad_0;
};

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const uint ANISO_MODEL_WARD = 0u;
static const uint ANISO_MODEL_HAIR_SHIFTED = 1u;
static const uint ANISO_MODEL_GGX = 2u;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SEED = 2u;
static const uint TIER_LOW = 3u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float WEFT_MIN_ANISO_ALPHA = 0.001;
static const float SILK_MIN_ALPHA = 0.001;
static const float WEFT_MIN_ROUGHNESS_HALF = 0.089;
static const float WEFT_MIN_N_DOT_HALF = 0.001;
static const float WEFT_MIN_ALPHA_HALF = 0.007921;

cbuffer weft_frame : register(b0) { WeftFrame weft_frame; }
TextureCube<float4> weft_environment : register(t1);
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup0SamplerIndexArray : register(t64, space0);
#define weft_environment_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[2]])
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }
cbuffer material : register(b0, space1) { WeftMaterial material; }
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
Texture2D<float4> base_map : register(t3, space1);
Texture2D<float4> aniso_normal_map : register(t4, space1);

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

float3 weft_any_perpendicular(float3 n)
{
    float s = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n.z));
    float b = ((n.x * n.y) * a);
    return float3((1.0 + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
}

float3 weft_f_schlick(float3 f0_, float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (f0_ + (((1.0).xxx - f0_) * _e5));
}

float3 weft_f_schlick_roughness(float3 f0_1, float n_dot_v, float roughness_1)
{
    const float _e6 = weft_pow5_((1.0 - saturate(n_dot_v)));
    float3 f90_ = max(((1.0 - saturate(roughness_1))).xxx, f0_1);
    return (f0_1 + ((f90_ - f0_1) * _e6));
}

float weft_v_schlick_ggx(float n_dot_v_1, float n_dot_l, float roughness_2)
{
    const float _e3 = weft_clamp_roughness(roughness_2);
    float a_1 = (_e3 * _e3);
    float k = (((a_1 + 1.0) * (a_1 + 1.0)) * 0.125);
    float gv = ((saturate(n_dot_v_1) * (1.0 - k)) + k);
    float gl = ((saturate(n_dot_l) * (1.0 - k)) + k);
    return (0.25 / (gv * gl));
}

float3 weft_diffuse_lambert(float3 albedo)
{
    return (albedo * WEFT_INV_PI);
}

float3 weft_env_brdf_approx(float3 f0_2, float n_dot_v_2, float roughness_3)
{
    float r = saturate(roughness_3);
    float surface_reduction = (1.0 / ((r * r) + 1.0));
    const float _e9 = weft_max3_(f0_2);
    float grazing = saturate((_e9 + (1.0 - r)));
    const float _e17 = weft_pow4_((1.0 - saturate(n_dot_v_2)));
    return (lerp(f0_2, (grazing).xxx, _e17) * surface_reduction);
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

float weft_specular_mip(float roughness_4)
{
    float r_1 = saturate(roughness_4);
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r_1 * (1.7 - (0.7 * r_1))) * max_mip);
}

float3 weft_prefiltered_radiance(float3 dir, float roughness_5)
{
    const float _e4 = weft_specular_mip(roughness_5);
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

float3x3 weft_tangent_frame(float3 n_3, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_3 * dot(n_3, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_3);
    float3 t = (ok ? (t_proj * rsqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_3, t) * s_1);
    return float3x3(t, b_1, n_3);
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

float2 weft_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

float3 weft_aniso_to_frame(float3x3 frame_1, float3 x_2)
{
    return float3(dot(frame_1[0], x_2), dot(frame_1[1], x_2), dot(frame_1[2], x_2));
}

float2 weft_aniso_alpha_burley(float roughness_6, float anisotropy)
{
    const float _e2 = weft_clamp_roughness(roughness_6);
    float a_2 = (_e2 * _e2);
    float k_1 = clamp(anisotropy, -1.0, 1.0);
    float aspect = sqrt((1.0 - (0.9 * abs(k_1))));
    float wide = (a_2 / aspect);
    float narrow = (a_2 * aspect);
    float2 ab = ((k_1 >= 0.0) ? float2(wide, narrow) : float2(narrow, wide));
    return max(ab, (0.001).xx);
}

float weft_aniso_ggx_q(float t_dot_h, float b_dot_h, float n_dot_h, float alpha_t, float alpha_b)
{
    float at = max(alpha_t, WEFT_MIN_ANISO_ALPHA);
    float ab_1 = max(alpha_b, WEFT_MIN_ANISO_ALPHA);
    float x_3 = (t_dot_h / at);
    float y = (b_dot_h / ab_1);
    return max((((x_3 * x_3) + (y * y)) + (n_dot_h * n_dot_h)), 1e-6);
}

float weft_d_ggx_aniso(float t_dot_h_1, float b_dot_h_1, float n_dot_h_1, float alpha_t_1, float alpha_b_1)
{
    float at_1 = max(alpha_t_1, WEFT_MIN_ANISO_ALPHA);
    float ab_2 = max(alpha_b_1, WEFT_MIN_ANISO_ALPHA);
    const float _e9 = weft_aniso_ggx_q(t_dot_h_1, b_dot_h_1, n_dot_h_1, at_1, ab_2);
    float d = (1.0 / ((((WEFT_PI * at_1) * ab_2) * _e9) * _e9));
    return ((n_dot_h_1 > 0.0) ? d : 0.0);
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
    float3 fibre = (float3)0;
    SilkLobe lobe = (SilkLobe)0;
    float vis = (float)0;
    float3 env_brdf = (float3)0;
    float3 ambient_kd = (float3)0;
    float3 reflect_n = (float3)0;

    float4 _e4 = material.base_map_st;
    const float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    float4 _e8 = material.base_color;
    float4 _e11 = base_map.Sample(material_sampler, _e5);
    float4 base_rgba = (_e8 * _e11);
    float3 base = saturate(base_rgba.xyz);
    float alpha_out = saturate(base_rgba.w);
    float _e19 = material.smoothness;
    float smoothness = saturate(_e19);
    float roughness_7 = (1.0 - smoothness);
    float _e25 = material.metallic;
    float metallic = saturate(_e25);
    float3 f0_3 = lerp((0.04).xxx, base, metallic);
    float3 diffuse_albedo = (base * (1.0 - metallic));
    const WeftSurface _e35 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_4 = _e35.v;
    float3 n_geo = _e35.n;
    const float3x3 _e39 = weft_tangent_frame(n_geo, in_1.world_tangent);
    float4 _e43 = material.aniso_normal_map_st;
    const float2 _e44 = weft_transform_uv(in_1.uv0_, _e43);
    float4 _e47 = aniso_normal_map.Sample(material_sampler, _e44);
    float3 texel_1 = _e47.xyz;
    float _e51 = material.aniso_normal_strength;
    const float3 _e52 = weft_unpack_normal(texel_1, _e51);
    const float3 _e53 = weft_normal_from_tangent_space(_e39, _e52);
    fibre = _e39[0];
    float3 _e56 = fibre;
    const float3x3 _e60 = weft_tangent_frame(_e53, float4(_e56, in_1.world_tangent.w));
    uint _e63 = material.diffuse_uses_aniso_normal;
    float3 n_diff = ((_e63 != 0u) ? _e53 : n_geo);
    const WeftLightGeometry _e67 = weft_main_light_geometry(_e53, v_4);
    const float3 _e68 = weft_aniso_to_frame(_e60, v_4);
    const float3 _e70 = weft_aniso_to_frame(_e60, _e67.l);
    const float3 _e72 = weft_aniso_to_frame(_e60, _e67.h);
    float k_2 = material.anisotropy;
    {
        {
            const float2 _e77 = weft_aniso_alpha_burley(roughness_7, k_2);
            lobe.alpha = _e77;
            lobe.ibl_roughness = roughness_7;
            {
                {
                    const float _e83 = weft_v_schlick_ggx(_e67.n_dot_v, _e67.n_dot_l, roughness_7);
                    vis = _e83;
                }
                const float _e90 = weft_d_ggx_aniso(_e72.x, _e72.y, _e72.z, _e77.x, _e77.y);
                float _e91 = vis;
                lobe.value = ((_e90 * _e91) * _e67.n_dot_l);
            }
        }
    }
    const float3 _e95 = weft_main_light_radiance();
    float n_dot_l_diffuse = saturate(dot(n_diff, _e67.l));
    const float3 _e100 = weft_f_schlick(f0_3, _e67.v_dot_h);
    const float3 _e104 = weft_diffuse_lambert(diffuse_albedo);
    float3 diffuse = ((((1.0).xxx - _e100) * _e104) * n_dot_l_diffuse);
    float _e108 = lobe.value;
    float3 direct = ((diffuse + (_e100 * _e108)) * _e95);
    reflect_n = _e53;
    {
        float _e117 = lobe.ibl_roughness;
        const float3 _e118 = weft_env_brdf_approx(f0_3, _e67.n_dot_v, _e117);
        env_brdf = _e118;
        float _e123 = lobe.ibl_roughness;
        const float3 _e124 = weft_f_schlick_roughness(f0_3, _e67.n_dot_v, _e123);
        ambient_kd = ((1.0).xxx - _e124);
    }
    float3 _e127 = reflect_n;
    float _e130 = lobe.ibl_roughness;
    const float3 _e131 = weft_prefiltered_radiance(reflect(-(v_4), _e127), _e130);
    float3 _e132 = env_brdf;
    const float3 _e134 = weft_sh_irradiance(n_diff);
    float3 _e135 = ambient_kd;
    float3 indirect = ((_e131 * _e132) + ((_e134 * _e135) * diffuse_albedo));
    float3 radiance = clamp((direct + indirect), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha_out);
}
