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
Texture2D<float4> weft_brdf_lut : register(t3);
#define weft_lut_sampler (nagaSamplerHeap[nagaGroup0SamplerIndexArray[4]])
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }
cbuffer material : register(b0, space1) { WeftMaterial material; }
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
Texture2D<float4> base_map : register(t3, space1);
Texture2D<float4> aniso_normal_map : register(t4, space1);
Texture2D<float4> flow_map : register(t5, space1);

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

float3 weft_any_perpendicular(float3 n)
{
    float s = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n.z));
    float b = ((n.x * n.y) * a);
    return float3((1.0 + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
}

float weft_d_ggx_nh(float3 n_1, float3 h, float roughness_1)
{
    const float _e3 = weft_clamp_roughness(roughness_1);
    float a_1 = (_e3 * _e3);
    float a2_ = (a_1 * a_1);
    float noh = saturate(dot(n_1, h));
    float3 nxh = cross(n_1, h);
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
    float3 v_4 = ((texel * 2.0) - (1.0).xxx);
    return float3((v_4.xy * strength), max(v_4.z, 0.001));
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

float3 weft_aniso_to_frame(float3x3 frame_1, float3 x_1)
{
    return float3(dot(frame_1[0], x_1), dot(frame_1[1], x_1), dot(frame_1[2], x_1));
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
    float d_1 = (1.0 / ((((WEFT_PI * at_1) * ab_1) * _e9) * _e9));
    return ((n_dot_h_1 > 0.0) ? d_1 : 0.0);
}

float weft_v_smith_ggx_aniso_correlated(float3 v_2, float3 l, float alpha_t_2, float alpha_b_2)
{
    const float _e5 = weft_clamp_cos(v_2.z);
    const float _e7 = weft_clamp_cos(l.z);
    float lv_1 = (_e7 * length(float3((alpha_t_2 * v_2.x), (alpha_b_2 * v_2.y), _e5)));
    float ll_1 = (_e5 * length(float3((alpha_t_2 * l.x), (alpha_b_2 * l.y), _e7)));
    return (0.5 / (lv_1 + ll_1));
}

float3 weft_aniso_bent_normal(float3x3 frame_2, float3 v_3, float anisotropy, float roughness_6)
{
    float k = clamp(anisotropy, -1.0, 1.0);
    float3 n_5 = frame_2[2];
    float3 dir_1 = ((k >= 0.0) ? frame_2[1] : frame_2[0]);
    float3 aniso_t = cross(dir_1, v_3);
    float3 aniso_n = cross(aniso_t, dir_1);
    float bend = (abs(k) * saturate((5.0 * saturate(roughness_6))));
    const float3 _e22 = weft_safe_normalize(lerp(n_5, aniso_n, bend), n_5);
    return _e22;
}

float silk_hair_mx_seed(float smoothness, float gloss)
{
    float p = (1.0 - saturate((smoothness * gloss)));
    float rx = (p * p);
    float rx_safe = ((rx == 0.0) ? 0.0001 : rx);
    return (rx_safe * rx_safe);
}

float3x3 silk_tilt_frame(float3x3 frame_3, float shift)
{
    float s_2 = clamp(shift, -1.0, 1.0);
    const float3 _e10 = weft_safe_normalize((frame_3[0] + (s_2 * frame_3[2])), frame_3[0]);
    const float3 _e16 = weft_safe_normalize((frame_3[2] - (s_2 * frame_3[0])), frame_3[2]);
    return float3x3(_e10, frame_3[1], _e16);
}

float silk_lobe_anisotropy(float2 alpha)
{
    float at_2 = max(alpha.x, SILK_MIN_ALPHA);
    float ab_2 = max(alpha.y, SILK_MIN_ALPHA);
    return ((at_2 - ab_2) / (at_2 + ab_2));
}

float silk_ibl_roughness(float2 alpha_1)
{
    return saturate(sqrt(sqrt(max((alpha_1.x * alpha_1.y), 0.0))));
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
    float smoothness_1 = saturate(_e19);
    float roughness_7 = (1.0 - smoothness_1);
    float _e25 = material.metallic;
    float metallic = saturate(_e25);
    float3 f0_2 = lerp((0.04).xxx, base, metallic);
    float3 diffuse_albedo = (base * (1.0 - metallic));
    const WeftSurface _e35 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_5 = _e35.v;
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
    {
        float4 _e58 = flow_map.Sample(material_sampler, _e5);
        float2 flow = ((_e58.xy * 2.0) - (1.0).xx);
        float3 dir_2 = ((_e39[0] * flow.x) + (_e39[1] * flow.y));
        float _e75 = material.flow_strength;
        const float3 _e79 = weft_safe_normalize(lerp(_e39[0], dir_2, saturate(_e75)), _e39[0]);
        fibre = _e79;
    }
    float3 _e80 = fibre;
    const float3x3 _e84 = weft_tangent_frame(_e53, float4(_e80, in_1.world_tangent.w));
    uint _e87 = material.diffuse_uses_aniso_normal;
    float3 n_diff = ((_e87 != 0u) ? _e53 : n_geo);
    const WeftLightGeometry _e91 = weft_main_light_geometry(_e53, v_5);
    const float3 _e92 = weft_aniso_to_frame(_e84, v_5);
    const float3 _e94 = weft_aniso_to_frame(_e84, _e91.l);
    const float3 _e96 = weft_aniso_to_frame(_e84, _e91.h);
    float k_1 = material.anisotropy;
    {
        {
            float _e103 = material.aniso_gloss;
            const float _e104 = silk_hair_mx_seed(smoothness_1, _e103);
            float _e107 = material.aniso_mask;
            float mask = saturate(_e107);
            float _e111 = material.aniso_spec;
            float spec_scale = lerp(max(_e111, 0.0), 1.0, mask);
            float2 a_hair = float2(max(_e104, SILK_MIN_ALPHA), 1.0);
            const float _e120 = weft_clamp_roughness(roughness_7);
            const float _e121 = weft_clamp_roughness(roughness_7);
            float a_iso = (_e120 * _e121);
            lobe.alpha = lerp(a_hair, (a_iso).xx, mask);
            const float _e127 = silk_ibl_roughness(a_hair);
            lobe.ibl_roughness = lerp(_e127, roughness_7, mask);
            {
                {
                    float _e131 = material.tangent_shift;
                    const float3x3 _e132 = silk_tilt_frame(_e84, _e131);
                    const float3 _e133 = weft_aniso_to_frame(_e132, v_5);
                    const float3 _e135 = weft_aniso_to_frame(_e132, _e91.l);
                    const float3 _e137 = weft_aniso_to_frame(_e132, _e91.h);
                    const float _e143 = weft_d_ggx_aniso(_e137.x, _e137.y, _e137.z, a_hair.x, a_hair.y);
                    const float _e146 = weft_v_smith_ggx_aniso_correlated(_e133, _e135, a_hair.x, a_hair.y);
                    float aniso = ((_e143 * _e146) * saturate(_e135.z));
                    const float _e152 = weft_d_ggx_nh(_e53, _e91.h, roughness_7);
                    const float _e155 = weft_v_smith_ggx_correlated(_e91.n_dot_v, _e91.n_dot_l, roughness_7);
                    float iso = ((_e152 * _e155) * _e91.n_dot_l);
                    lobe.value = (lerp(aniso, iso, mask) * spec_scale);
                }
            }
        }
    }
    const float3 _e162 = weft_main_light_radiance();
    float n_dot_l_diffuse = saturate(dot(n_diff, _e91.l));
    const float3 _e167 = weft_f_schlick(f0_2, _e91.v_dot_h);
    const float3 _e171 = weft_diffuse_lambert(diffuse_albedo);
    float3 diffuse = ((((1.0).xxx - _e167) * _e171) * n_dot_l_diffuse);
    float _e175 = lobe.value;
    float3 direct = ((diffuse + (_e167 * _e175)) * _e162);
    reflect_n = _e53;
    {
        float _e184 = lobe.ibl_roughness;
        const float2 _e185 = weft_env_brdf_lut(_e91.n_dot_v, _e184);
        const float3 _e186 = weft_env_brdf_from_lut(f0_2, _e185);
        env_brdf = _e186;
        float3 _e189 = env_brdf;
        ambient_kd = max(((1.0).xxx - _e189), (0.0).xxx);
        float2 _e195 = lobe.alpha;
        const float _e196 = silk_lobe_anisotropy(_e195);
        float _e198 = lobe.ibl_roughness;
        const float3 _e199 = weft_aniso_bent_normal(_e84, v_5, _e196, _e198);
        reflect_n = _e199;
    }
    float3 _e201 = reflect_n;
    float _e204 = lobe.ibl_roughness;
    const float3 _e205 = weft_prefiltered_radiance(reflect(-(v_5), _e201), _e204);
    float3 _e206 = env_brdf;
    const float3 _e208 = weft_sh_irradiance(n_diff);
    float3 _e209 = ambient_kd;
    float3 indirect = ((_e205 * _e206) + ((_e208 * _e209) * diffuse_albedo));
    float3 radiance = clamp((direct + indirect), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha_out);
}
