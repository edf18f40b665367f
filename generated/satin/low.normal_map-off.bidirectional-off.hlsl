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
    float a_1 = (_e2 * _e2);
    float k_1 = clamp(anisotropy, -1.0, 1.0);
    return max(float2((a_1 * (1.0 + k_1)), (a_1 * (1.0 - k_1))), (0.001).xx);
}

float3 weft_aniso_bent_normal(float3x3 frame_1, float3 v_2, float anisotropy_1, float roughness_5)
{
    float k_2 = clamp(anisotropy_1, -1.0, 1.0);
    float3 n_6 = frame_1[2];
    float3 dir_1 = ((k_2 >= 0.0) ? frame_1[1] : frame_1[0]);
    float3 aniso_t = cross(dir_1, v_2);
    float3 aniso_n = cross(aniso_t, dir_1);
    float bend = (abs(k_2) * saturate((5.0 * saturate(roughness_5))));
    const float3 _e22 = weft_safe_normalize(lerp(n_6, aniso_n, bend), n_6);
    return _e22;
}

float weft_half_pow5_(float x_2)
{
    float x2_1 = (x_2 * x_2);
    return ((x2_1 * x2_1) * x_2);
}

float3 weft_half_f_schlick(float3 f0_2, float v_dot_h_1)
{
    const float _e7 = weft_half_pow5_((1.0 - v_dot_h_1));
    return (f0_2 + (((1.0).xxx - f0_2) * _e7));
}

float2 weft_half_spec_ggx_aniso2_(float3 v_3, float3 l, float3 h, float2 alpha_t, float2 alpha_b)
{
    float2 at = max(alpha_t, (0.007921).xx);
    float2 ab = max(alpha_b, (0.007921).xx);
    float2 inv_at = float2(((1.0).xx / at));
    float2 inv_ab = float2(((1.0).xx / ab));
    float2 at_h = float2(at);
    float2 ab_h = float2(ab);
    float2 x_3 = (h.x * inv_at);
    float2 y = (h.y * inv_ab);
    float2 q = max((((x_3 * x_3) + (y * y)) + ((h.z * h.z)).xx), (0.01).xx);
    float2 d = ((((inv_at * inv_ab) / q) / q) * 0.31830987);
    float nv = max(v_3.z, 0.001);
    float nl = saturate(l.z);
    float2 vt = (at_h * v_3.x);
    float2 vb = (ab_h * v_3.y);
    float2 lt = (at_h * l.x);
    float2 lb = (ab_h * l.y);
    float2 lv = (nl * sqrt((((vt * vt) + (vb * vb)) + ((nv * nv)).xx)));
    float2 ll = (nv * sqrt((((lt * lt) + (lb * lb)) + ((nl * nl)).xx)));
    float2 v_n_dot_l = (((0.5 * nl)).xx / max((lv + ll), (0.0001).xx));
    return ((h.z > 0.0) ? min((d * v_n_dot_l), (65504.0).xx) : (0.0).xx);
}

float3 satin_env(float3x3 frame_2, float3 v_4, float k, float roughness_6)
{
    float3 bent_1 = (float3)0;
    float3 c_1 = (float3)0;

    const float3 _e4 = weft_aniso_bent_normal(frame_2, v_4, k, roughness_6);
    bent_1 = _e4;
    float3 _e7 = bent_1;
    const float3 _e9 = weft_prefiltered_radiance(reflect(-(v_4), _e7), roughness_6);
    c_1 = _e9;
    float3 _e11 = c_1;
    return _e11;
}

float2 satin_lobes_low(float3 vf, float3 lf, float3 hf, float2 a1_, float2 a2_)
{
    float2 s = (float2)0;

    float2 at_1 = float2(a1_.x, a2_.x);
    float2 ab_1 = float2(a1_.y, a2_.y);
    const float2 _e11 = weft_half_spec_ggx_aniso2_(vf, lf, hf, at_1, ab_1);
    s = _e11;
    float2 _e13 = s;
    return _e13;
}

float3 satin_low(float3x3 frame_3, float3 n_5, float3 v_5, WeftLightGeometry lit_, float3 f0_in, float3 diffuse_albedo, float roughness_7, float roughness2_, float anisotropy_2, float3 c1_in, float3 c2_in, float noise_, float ao, float3 light)
{
    float n_dot_v_1 = lit_.n_dot_v;
    float n_dot_l = float(lit_.n_dot_l);
    float v_dot_h_2 = float(lit_.v_dot_h);
    float3 f0_3 = float3(f0_in);
    float3 c1_ = float3(c1_in);
    float3 c2_ = float3(c2_in);
    float3 t1_ = lerp(c1_, (max(c1_.x, max(c1_.y, c1_.z))).xxx, 0.5);
    float3 t2_ = lerp(c2_, (max(c2_.x, max(c2_.y, c2_.z))).xxx, 0.5);
    float3 t_1 = (t1_ + t2_);
    float norm = (1.0 / max(1.0, max(t_1.x, max(t_1.y, t_1.z))));
    float3 w1_ = (t1_ * norm);
    float3 w2_ = (t2_ * norm);
    float r_low = max(roughness_7, WEFT_MIN_ROUGHNESS_HALF);
    float r2_low = max(roughness2_, WEFT_MIN_ROUGHNESS_HALF);
    const float3 _e54 = weft_aniso_to_frame(frame_3, v_5);
    float3 vf_1 = float3(_e54);
    const float3 _e57 = weft_aniso_to_frame(frame_3, lit_.l);
    float3 lf_1 = float3(_e57);
    const float3 _e60 = weft_aniso_to_frame(frame_3, lit_.h);
    float3 hf_1 = float3(_e60);
    const float2 _e62 = weft_aniso_alpha_kulla(r_low, anisotropy_2);
    const float2 _e63 = weft_aniso_alpha_kulla(r2_low, anisotropy_2);
    const float2 _e64 = satin_lobes_low(vf_1, lf_1, hf_1, _e62, _e63);
    float lobe1_ = _e64.x;
    float lobe2_ = _e64.y;
    const float3 _e67 = weft_half_f_schlick(f0_3, v_dot_h_2);
    float3 specular_1 = (((float3((w1_ * _e67)) * float(lobe1_)) + (float3((w2_ * _e67)) * float(lobe2_))) * (noise_ * light));
    const float3 _e83 = weft_half_f_schlick(f0_3, float(n_dot_v_1));
    float3 diffuse_kd_1 = max(((1.0).xxx - ((w1_ + w2_) * _e83)), (0.0).xxx);
    const float2 _e89 = weft_env_brdf_lut(n_dot_v_1, roughness_7);
    const float3 _e90 = weft_env_brdf_from_lut(f0_in, _e89);
    float3 e1_ = (float3(_e90) * w1_);
    const float2 _e93 = weft_env_brdf_lut(n_dot_v_1, roughness2_);
    const float3 _e94 = weft_env_brdf_from_lut(f0_in, _e93);
    float3 e2_ = (float3(_e94) * w2_);
    float r_env = ((max(e1_.x, max(e1_.y, e1_.z)) >= max(e2_.x, max(e2_.y, e2_.z))) ? roughness_7 : roughness2_);
    const float3 _e109 = satin_env(frame_3, v_5, anisotropy_2, r_env);
    float3 indirect_specular_1 = ((_e109 * float3((e1_ + e2_))) * noise_);
    float3 ambient_kd_1 = max((((1.0).xxx - e1_) - e2_), (0.0).xxx);
    float3 direct = (((diffuse_albedo * float3((diffuse_kd_1 * (n_dot_l * 0.31830987)))) * light) + specular_1);
    const float3 _e129 = weft_sh_irradiance(n_5);
    float3 indirect = ((indirect_specular_1 * ao) + (((_e129 * ao) * float3(ambient_kd_1)) * diffuse_albedo));
    return (direct + indirect);
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
    float roughness_8 = saturate((_e23 * rmo.x));
    float _e29 = material.metallic;
    float metallic = saturate((_e29 * rmo.y));
    float _e36 = material.occlusion_strength;
    float ao_1 = saturate(lerp(1.0, rmo.z, _e36));
    float _e42 = material.anisotropy;
    float anisotropy_3 = clamp(_e42, -1.0, 1.0);
    float _e48 = material.second_layer_width;
    float width = clamp(_e48, 1.0, 4.0);
    float roughness2_1 = min((roughness_8 * width), 1.0);
    float4 _e58 = material.noise_map_st;
    const float2 _e59 = weft_transform_uv(in_1.uv0_, _e58);
    float4 _e62 = noise_map.Sample(material_sampler, _e59);
    float noise_1 = (0.5 + (0.5 * saturate(_e62.x)));
    const WeftSurface _e71 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_6 = _e71.v;
    n = _e71.n;
    float3 _e75 = n;
    const float3x3 _e77 = weft_tangent_frame(_e75, in_1.world_tangent);
    float3 _e78 = n;
    const WeftLightGeometry _e79 = weft_main_light_geometry(_e78, v_6);
    const float3 _e80 = weft_main_light_radiance();
    const float2 _e83 = weft_aniso_alpha_kulla(roughness_8, anisotropy_3);
    layers.narrow = _e83;
    const float2 _e85 = weft_aniso_alpha_kulla(roughness2_1, anisotropy_3);
    layers.wide = _e85;
    float3 f0_4 = lerp((0.04).xxx, base, metallic);
    float3 diffuse_albedo_1 = (base * (1.0 - metallic));
    float4 _e94 = material.specular_color;
    float3 c1_1 = saturate(_e94.xyz);
    float4 _e99 = material.second_specular_color;
    float3 c2_1 = saturate(_e99.xyz);
    const float3 _e103 = weft_f_schlick(f0_4, _e79.v_dot_h);
    {
        float3 _e104 = n;
        const float3 _e105 = satin_low(_e77, _e104, v_6, _e79, f0_4, diffuse_albedo_1, roughness_8, roughness2_1, anisotropy_3, c1_1, c2_1, noise_1, ao_1, _e80);
        return float4(clamp(_e105, (0.0).xxx, (65504.0).xxx), alpha);
    }
}
