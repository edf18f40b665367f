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
    int _pad2_0;
    int _pad2_1;
    int _pad2_2;
    float4 base_map_st;
    float4 normal_map_st;
    float normal_strength;
    float thread_density;
    float thread_transmittance;
    float mesh_gap;
    float anisotropy;
    float anisotropic_intensity;
    int _pad10_0;
    int _pad10_1;
    float4 scatter_color;
    float scatter_intensity;
    float pattern_threshold;
    float pattern_rotation;
    float sampling_density;
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
static const float WEFT_MIN_ANISO_ALPHA = 0.001;
static const float GAUZE_LN_MAX_TRANSMITTANCE = 6.9077554;

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
Texture2D<float4> mesh_map : register(t5, space1);
Texture2D<float4> noise_map : register(t6, space1);
Texture2D<float4> pattern_map : register(t7, space1);

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
    bool front_facing_2 : SV_IsFrontFace;
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
    float s_1 = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s_1 + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return float3((1.0 + (((s_1 * n_1.x) * n_1.x) * a)), (s_1 * b), (-(s_1) * n_1.x));
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
    float s_2 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_4, t) * s_2);
    return float3x3(t, b_1, n_4);
}

float3 weft_unpack_normal(float3 texel, float strength)
{
    float3 v_5 = ((texel * 2.0) - (1.0).xxx);
    return float3((v_5.xy * strength), max(v_5.z, 0.001));
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

float3 weft_aniso_to_frame(float3x3 frame_1, float3 x_1)
{
    return float3(dot(frame_1[0], x_1), dot(frame_1[1], x_1), dot(frame_1[2], x_1));
}

float3x3 weft_rotate_tangent_frame_cs(float3x3 frame_2, float c_1, float s)
{
    float len2_2 = ((c_1 * c_1) + (s * s));
    float inv = rsqrt(max(len2_2, 1e-20));
    float cc = ((len2_2 > 1e-20) ? (c_1 * inv) : 1.0);
    float ss = ((len2_2 > 1e-20) ? (s * inv) : 0.0);
    float3 t_1 = ((frame_2[0] * cc) + (frame_2[1] * ss));
    float3 b_2 = ((frame_2[1] * cc) - (frame_2[0] * ss));
    return float3x3(t_1, b_2, frame_2[2]);
}

float3x3 weft_rotate_tangent_frame(float3x3 frame_3, float angle)
{
    const float3x3 _e4 = weft_rotate_tangent_frame_cs(frame_3, cos(angle), sin(angle));
    return _e4;
}

float2 weft_aniso_alpha_kulla(float roughness_4, float anisotropy)
{
    const float _e2 = weft_clamp_roughness(roughness_4);
    float a_1 = (_e2 * _e2);
    float k = clamp(anisotropy, -1.0, 1.0);
    return max(float2((a_1 * (1.0 + k)), (a_1 * (1.0 - k))), (0.001).xx);
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

float weft_v_smith_ggx_aniso_correlated(float3 v_2, float3 l, float alpha_t_2, float alpha_b_2)
{
    const float _e5 = weft_clamp_cos(v_2.z);
    const float _e7 = weft_clamp_cos(l.z);
    float lv = (_e7 * length(float3((alpha_t_2 * v_2.x), (alpha_b_2 * v_2.y), _e5)));
    float ll = (_e5 * length(float3((alpha_t_2 * l.x), (alpha_b_2 * l.y), _e7)));
    return (0.5 / (lv + ll));
}

float weft_spec_ggx_aniso(float3 v_3, float3 l_1, float alpha_t_3, float alpha_b_3)
{
    const float3 _e9 = weft_safe_normalize((v_3 + l_1), float3(0.0, 0.0, 1.0));
    const float _e13 = weft_d_ggx_aniso(_e9.x, _e9.y, _e9.z, alpha_t_3, alpha_b_3);
    const float _e14 = weft_v_smith_ggx_aniso_correlated(v_3, l_1, alpha_t_3, alpha_b_3);
    return ((_e13 * _e14) * saturate(l_1.z));
}

float3 weft_aniso_bent_normal(float3x3 frame_4, float3 v_4, float anisotropy_1, float roughness_5)
{
    float k_1 = clamp(anisotropy_1, -1.0, 1.0);
    float3 n_6 = frame_4[2];
    float3 dir_1 = ((k_1 >= 0.0) ? frame_4[1] : frame_4[0]);
    float3 aniso_t = cross(dir_1, v_4);
    float3 aniso_n = cross(aniso_t, dir_1);
    float bend = (abs(k_1) * saturate((5.0 * saturate(roughness_5))));
    const float3 _e22 = weft_safe_normalize(lerp(n_6, aniso_n, bend), n_6);
    return _e22;
}

float gauze_grid_coverage(float2 cell, float2 w, float gap)
{
    float g = clamp(gap, 0.0, 1.0);
    float2 d_1 = abs((frac(cell) - (0.5).xx));
    float2 ww = max(w, (0.0001).xx);
    float2 ramp = saturate((((((0.5 * g)).xx - d_1) / ww) + (0.5).xx));
    float2 open = lerp(ramp, (g).xx, saturate(((ww * 2.0) - (1.0).xx)));
    float open_xy = ((g > 0.0) ? (open.x * open.y) : 0.0);
    return (1.0 - open_xy);
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
    bool front_facing = fragmentinput_fs_main.front_facing_2;
    float3 n = (float3)0;
    float3 spec_direct = (float3)0;
    float3 env_brdf = (float3)0;
    float3 diffuse_kd = (float3)0;
    float3 ambient_kd = (float3)0;
    float lobe = (float)0;

    float4 _e5 = material.base_map_st;
    const float2 _e6 = weft_transform_uv(in_1.uv0_, _e5);
    float4 _e9 = material.base_color;
    float4 _e12 = base_map.Sample(material_sampler, _e6);
    float4 base_rgba = (_e9 * _e12);
    float3 base = saturate(base_rgba.xyz);
    float base_alpha = saturate(base_rgba.w);
    float _e20 = material.roughness;
    float roughness_6 = saturate(_e20);
    float _e24 = material.anisotropy;
    float anisotropy_2 = clamp(_e24, -1.0, 1.0);
    float _e31 = material.sampling_density;
    float2 uv_s = (in_1.uv0_ * _e31);
    float4 _e35 = mesh_map.Sample(material_sampler, uv_s);
    float mesh_tex = saturate(_e35.x);
    float4 _e40 = noise_map.Sample(material_sampler, uv_s);
    float noise_ = saturate(_e40.x);
    float4 _e45 = pattern_map.Sample(material_sampler, uv_s);
    float pattern = _e45.x;
    float2 grid_w = fwidth(uv_s);
    float pattern_w = fwidth(pattern);
    float _e51 = material.mesh_gap;
    const float _e52 = gauze_grid_coverage(uv_s, grid_w, _e51);
    float mesh = (mesh_tex * _e52);
    const WeftSurface _e56 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    float3 v_6 = _e56.v;
    float3 n_geom = _e56.n;
    n = n_geom;
    {
        float4 _e63 = material.normal_map_st;
        const float2 _e64 = weft_transform_uv(in_1.uv0_, _e63);
        float4 _e67 = normal_map.Sample(material_sampler, _e64);
        float3 texel_2 = _e67.xyz;
        float _e72 = material.normal_strength;
        const float3 _e73 = weft_mapped_normal(n_geom, in_1.world_tangent, texel_2, _e72);
        n = _e73;
    }
    float3 _e74 = n;
    const float3x3 _e76 = weft_tangent_frame(_e74, in_1.world_tangent);
    float cos_v = min(abs(dot(n_geom, v_6)), 1.0);
    float sin_v = sqrt(max((1.0 - (cos_v * cos_v)), 0.0));
    float _e89 = material.thread_density;
    float density = clamp(_e89, 0.0, 200.0);
    float s_3 = pow(max(sin_v, 1e-8), density);
    float _e98 = material.thread_transmittance;
    float transmittance = clamp(_e98, 1.0, 1000.0);
    float thread_opacity = saturate((1.0 - (log(transmittance) / GAUZE_LN_MAX_TRANSMITTANCE)));
    float alpha = saturate(((1.0 - ((1.0 - s_3) * (1.0 - (mesh * thread_opacity)))) * base_alpha));
    float coverage = saturate(((1.0 - ((1.0 - s_3) * (1.0 - mesh))) * base_alpha));
    float _e129 = material.pattern_rotation;
    float rot = radians(_e129);
    const float3x3 _e131 = weft_rotate_tangent_frame(_e76, rot);
    float _e134 = material.pattern_threshold;
    float above_hard = ((pattern > _e134) ? 1.0 : 0.0);
    float _e141 = material.pattern_threshold;
    float above_aa = saturate((((pattern - _e141) / max(pattern_w, 0.0001)) + 0.5));
    float3 _e149 = n;
    const WeftLightGeometry _e150 = weft_main_light_geometry(_e149, v_6);
    const float2 _e151 = weft_aniso_alpha_kulla(roughness_6, anisotropy_2);
    const float3 _e152 = weft_main_light_radiance();
    float4 _e155 = material.scatter_color;
    float3 scatter = max(_e155.xyz, (0.0).xxx);
    float3 tint = saturate(scatter);
    float3 f0_2 = (0.04).xxx;
    {
        {
            const float3x3 _e169 = weft_rotate_tangent_frame(_e76, (rot * above_aa));
            const float3 _e170 = weft_aniso_to_frame(_e169, v_6);
            const float3 _e172 = weft_aniso_to_frame(_e169, _e150.l);
            const float _e175 = weft_spec_ggx_aniso(_e170, _e172, _e151.x, _e151.y);
            lobe = _e175;
        }
        const float3 _e177 = weft_f_schlick(f0_2, _e150.v_dot_h);
        float _e178 = lobe;
        spec_direct = ((((_e178 * _e177) * tint) * noise_) * _e152);
        const float3 _e186 = weft_f_schlick(f0_2, _e150.n_dot_v);
        diffuse_kd = ((1.0).xxx - (tint * _e186));
        const float2 _e190 = weft_env_brdf_lut(_e150.n_dot_v, roughness_6);
        const float3 _e191 = weft_env_brdf_from_lut(f0_2, _e190);
        env_brdf = (_e191 * tint);
        float3 _e195 = env_brdf;
        ambient_kd = max(((1.0).xxx - _e195), (0.0).xxx);
    }
    float3 _e200 = diffuse_kd;
    const float3 _e201 = weft_diffuse_lambert(base);
    float3 diffuse_direct = (((_e200 * _e201) * _e152) * _e150.n_dot_l);
    float3 _e206 = n;
    const float3 _e207 = weft_sh_irradiance(_e206);
    float3 _e208 = ambient_kd;
    float3 diffuse_indirect = ((_e207 * _e208) * base);
    const float3 _e211 = weft_aniso_bent_normal(_e76, v_6, anisotropy_2, roughness_6);
    const float3 _e214 = weft_prefiltered_radiance(reflect(-(v_6), _e211), roughness_6);
    float3 _e215 = env_brdf;
    float3 spec_indirect = ((_e214 * _e215) * noise_);
    float3 _e220 = spec_direct;
    float3 color = ((alpha * (diffuse_direct + diffuse_indirect)) + (coverage * (_e220 + spec_indirect)));
    float3 radiance = clamp(color, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
