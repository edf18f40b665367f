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

struct VertexOutput_vs_main {
    float3 world_position_1 : LOC0;
    float3 world_normal : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    float4 clip_position : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_2 : LOC0;
    float3 world_normal_1 : LOC1;
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

float3 weft_safe_normalize_k1_(float3 v_1)
{
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * rsqrt(max(len2_1, 1e-20))) : float3(0.0, 0.0, 1.0));
}

float3 weft_main_light_direction()
{
    float4 _e2 = weft_frame.light_direction;
    const float3 _e4 = weft_safe_normalize_k1_(_e2.xyz);
    return _e4;
}

float3 weft_main_light_radiance()
{
    float4 _e2 = weft_frame.light_color;
    return max(_e2.xyz, (0.0).xxx);
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

float weft_specular_mip(float roughness)
{
    float r = saturate(roughness);
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

float3 weft_prefiltered_radiance(float3 dir, float roughness_1)
{
    const float _e4 = weft_specular_mip(roughness_1);
    float4 c_1 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, (0.0).xxx);
}

float2 weft_env_brdf_lut(float n_dot_v, float roughness_2)
{
    float2 uv = float2(saturate(n_dot_v), saturate(roughness_2));
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv, 0.0);
    return _e8.xy;
}

float3x3 weft_tangent_frame(float3 n_2, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_2 = dot(t_proj, t_proj);
    bool ok = (len2_2 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_2);
    float3 t = (ok ? (t_proj * rsqrt(max(len2_2, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_2, t) * s_1);
    return float3x3(t, b_1, n_2);
}

float3 weft_aniso_to_frame(float3x3 frame, float3 x_1)
{
    return float3(dot(frame[0], x_1), dot(frame[1], x_1), dot(frame[2], x_1));
}

float3 weft_aniso_bent_normal(float3x3 frame_1, float3 v_2, float anisotropy, float roughness_3)
{
    float k = clamp(anisotropy, -1.0, 1.0);
    float3 n_3 = frame_1[2];
    float3 dir_1 = ((k >= 0.0) ? frame_1[1] : frame_1[0]);
    float3 aniso_t = cross(dir_1, v_2);
    float3 aniso_n = cross(aniso_t, dir_1);
    float bend = (abs(k) * saturate((5.0 * saturate(roughness_3))));
    const float3 _e22 = weft_safe_normalize(lerp(n_3, aniso_n, bend), n_3);
    return _e22;
}

float silk_lobe_anisotropy(float2 alpha)
{
    float at = max(alpha.x, SILK_MIN_ALPHA);
    float ab = max(alpha.y, SILK_MIN_ALPHA);
    return ((at - ab) / (at + ab));
}

float3 weft_safe_normalize_k2_(float3 v_3)
{
    float len2_3 = dot(v_3, v_3);
    return ((len2_3 > 1e-20) ? (v_3 * rsqrt(max(len2_3, 1e-20))) : (0.0).xxx);
}

float3 weft_view_direction_k4_(float3 world_position)
{
    float4 _e4 = weft_frame.camera_position;
    const float3 _e7 = weft_safe_normalize_k1_((_e4.xyz - world_position));
    return _e7;
}

float3 weft_f_schlick_k7_(float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (float3(0.14609632, 0.10047833, 0.11062463) + (float3(0.85390365, 0.89952165, 0.8893754) * _e5));
}

float3 weft_env_brdf_from_lut_k9_(float2 scale_bias_1)
{
    float2 sb = saturate(scale_bias_1);
    return ((float3(0.14609632, 0.10047833, 0.11062463) * sb.x) + (sb.y).xxx);
}

float3 weft_normal_from_tangent_space_k11_(float3x3 frame_2)
{
    const float3 _e4 = weft_safe_normalize(mul(float3(float2(0.002352977, 0.002352977), 1.0), frame_2), frame_2[2]);
    return _e4;
}

float silk_ward_bounded_k13_(float3 v_4, float3 l)
{
    bool local = (bool)0;

    float3 hv = (v_4 + l);
    float hn = max(hv.z, 0.0001);
    float hn2_ = (hn * hn);
    float x_2 = (hv.x / 0.20215853);
    float y = (hv.y / 0.047507256);
    float f = ((dot(hv, hv) / ((0.030171847 * hn2_) * hn2_)) * exp((-(((x_2 * x_2) + (y * y))) / hn2_)));
    if ((v_4.z > 0.0)) {
        local = (l.z > 0.0);
    } else {
        local = false;
    }
    bool _e35 = local;
    return (_e35 ? f : 0.0);
}

VertexOutput_vs_main vs_main(WeftVertexInput in_)
{
    WeftVaryings out_ = (WeftVaryings)0;

    float4x4 model = weft_object.model;
    float3x3 model3_ = float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    float4x4 nm = weft_object.normal_matrix;
    float3x3 normal3_ = float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    float4 world = mul(float4(in_.position, 1.0), model);
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    float4x4 _e43 = weft_frame.view_proj;
    out_.clip_position = mul(float4(world.xyz, 1.0), _e43);
    out_.world_position = world.xyz;
    const float3 _e53 = weft_safe_normalize_k2_(mul(in_.normal, normal3_));
    out_.world_normal = _e53;
    const float3 _e58 = weft_safe_normalize_k2_(mul(in_.tangent.xyz, model3_));
    out_.world_tangent = float4(_e58, bitangent_sign);
    out_.uv0_ = in_.uv0_;
    WeftVaryings _e62 = out_;
    const WeftVaryings weftvaryings = _e62;
    const VertexOutput_vs_main weftvaryings_1 = { weftvaryings.world_position, weftvaryings.world_normal, weftvaryings.world_tangent, weftvaryings.uv0_, weftvaryings.clip_position };
    return weftvaryings_1;
}

float4 fs_main(FragmentInput_fs_main fragmentinput_fs_main) : SV_Target0
{
    WeftVaryings in_1 = { fragmentinput_fs_main.clip_position_1, fragmentinput_fs_main.world_position_2, fragmentinput_fs_main.world_normal_1, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_1 };
    float3 fibre = (float3)0;
    SilkLobe lobe = (SilkLobe)0;
    float vis = (float)0;
    float3 env_brdf = (float3)0;
    float3 ambient_kd = (float3)0;
    float3 reflect_n = (float3)0;
    float2 scale_bias = (float2)0;

    const float3 _e10 = weft_view_direction_k4_(in_1.world_position);
    const float3 _e12 = weft_safe_normalize(in_1.world_normal, _e10);
    const float3x3 _e14 = weft_tangent_frame(_e12, in_1.world_tangent);
    const float3 _e16 = weft_normal_from_tangent_space_k11_(_e14);
    fibre = _e14[0];
    float3 _e19 = fibre;
    const float3x3 _e23 = weft_tangent_frame(_e16, float4(_e19, in_1.world_tangent.w));
    const float3 _e24 = weft_main_light_direction();
    const float3 _e26 = weft_safe_normalize((_e24 + _e10), _e16);
    const float _e28 = weft_clamp_cos(dot(_e16, _e10));
    float n_dot_l = saturate(dot(_e16, _e24));
    float n_dot_h = saturate(dot(_e16, _e26));
    float v_dot_h_1 = saturate(dot(_e10, _e26));
    const float3 _e35 = weft_aniso_to_frame(_e23, _e10);
    const float3 _e36 = weft_aniso_to_frame(_e23, _e24);
    {
        lobe.alpha = float2(0.20215853, 0.047507256);
        lobe.ibl_roughness = 0.3130495;
        {
            const float _e44 = silk_ward_bounded_k13_(_e35, _e36);
            lobe.value = (_e44 * n_dot_l);
        }
    }
    const float3 _e46 = weft_main_light_radiance();
    float n_dot_l_diffuse = saturate(dot(_e12, _e24));
    const float3 _e49 = weft_f_schlick_k7_(v_dot_h_1);
    float3 diffuse = ((((1.0).xxx - _e49) * float3(0.14527194, 0.08718932, 0.10010798)) * n_dot_l_diffuse);
    float _e56 = lobe.value;
    float3 direct = ((diffuse + (_e49 * _e56)) * _e46);
    reflect_n = _e16;
    {
        {
            float _e65 = lobe.ibl_roughness;
            const float2 _e66 = weft_env_brdf_lut(_e28, _e65);
            scale_bias = _e66;
        }
        float2 _e67 = scale_bias;
        const float3 _e68 = weft_env_brdf_from_lut_k9_(_e67);
        env_brdf = _e68;
        float3 _e70 = env_brdf;
        ambient_kd = max(((1.0).xxx - _e70), (0.0).xxx);
        float2 _e75 = lobe.alpha;
        const float _e76 = silk_lobe_anisotropy(_e75);
        float _e78 = lobe.ibl_roughness;
        const float3 _e79 = weft_aniso_bent_normal(_e23, _e10, _e76, _e78);
        reflect_n = _e79;
    }
    float3 _e81 = reflect_n;
    float _e84 = lobe.ibl_roughness;
    const float3 _e85 = weft_prefiltered_radiance(reflect(-(_e10), _e81), _e84);
    float3 _e86 = env_brdf;
    const float3 _e88 = weft_sh_irradiance(_e12);
    float3 _e89 = ambient_kd;
    float3 indirect = ((_e85 * _e86) + ((_e88 * _e89) * float3(0.45638528, 0.27391332, 0.3144985)));
    float3 radiance = clamp((direct + indirect), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
