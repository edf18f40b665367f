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

float3 weft_f_schlick(float3 f0_, float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return (f0_ + (((1.0).xxx - f0_) * _e5));
}

float3 weft_diffuse_lambert(float3 albedo)
{
    return (albedo * WEFT_INV_PI);
}

float3 weft_env_brdf_from_lut(float3 f0_1, float2 scale_bias_1)
{
    float2 sb = saturate(scale_bias_1);
    return ((f0_1 * sb.x) + (sb.y).xxx);
}

float3 weft_main_light_direction()
{
    float4 _e2 = weft_frame.light_direction;
    const float3 _e5 = weft_safe_normalize(_e2.xyz, float3(0.0, 0.0, 1.0));
    return _e5;
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
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_2);
    float3 t = (ok ? (t_proj * rsqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_2, t) * s_1);
    return float3x3(t, b_1, n_2);
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

float3 weft_aniso_to_frame(float3x3 frame_1, float3 x_1)
{
    return float3(dot(frame_1[0], x_1), dot(frame_1[1], x_1), dot(frame_1[2], x_1));
}

float3 weft_aniso_bent_normal(float3x3 frame_2, float3 v_1, float anisotropy, float roughness_3)
{
    float k = clamp(anisotropy, -1.0, 1.0);
    float3 n_3 = frame_2[2];
    float3 dir_1 = ((k >= 0.0) ? frame_2[1] : frame_2[0]);
    float3 aniso_t = cross(dir_1, v_1);
    float3 aniso_n = cross(aniso_t, dir_1);
    float bend = (abs(k) * saturate((5.0 * saturate(roughness_3))));
    const float3 _e22 = weft_safe_normalize(lerp(n_3, aniso_n, bend), n_3);
    return _e22;
}

float silk_aspect(float anisotropy_1)
{
    return sqrt((1.0 - (0.9 * clamp(anisotropy_1, -1.0, 1.0))));
}

float2 silk_ward_alpha_seed(float smoothness, float anisotropy_2)
{
    float r_1 = (1.0 - saturate(smoothness));
    float a_1 = (r_1 * r_1);
    const float _e6 = silk_aspect(anisotropy_2);
    return (float2(max(SILK_MIN_ALPHA, (a_1 / _e6)), max(SILK_MIN_ALPHA, (a_1 * _e6))) * 5.0);
}

float silk_ward_bounded(float3 v_2, float3 l, float2 alpha)
{
    bool local = (bool)0;

    float ax = max(alpha.x, SILK_MIN_ALPHA);
    float ay = max(alpha.y, SILK_MIN_ALPHA);
    float3 hv = (v_2 + l);
    float hn = max(hv.z, 0.0001);
    float hn2_ = (hn * hn);
    float x_2 = (hv.x / ax);
    float y = (hv.y / ay);
    float f = ((dot(hv, hv) / ((((WEFT_PI * ax) * ay) * hn2_) * hn2_)) * exp((-(((x_2 * x_2) + (y * y))) / hn2_)));
    if ((v_2.z > 0.0)) {
        local = (l.z > 0.0);
    } else {
        local = false;
    }
    bool _e41 = local;
    return (_e41 ? f : 0.0);
}

float silk_lobe_anisotropy(float2 alpha_1)
{
    float at = max(alpha_1.x, SILK_MIN_ALPHA);
    float ab = max(alpha_1.y, SILK_MIN_ALPHA);
    return ((at - ab) / (at + ab));
}

float silk_ibl_roughness(float2 alpha_2)
{
    return saturate(sqrt(sqrt(max((alpha_2.x * alpha_2.y), 0.0))));
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
    const float3 _e54 = weft_safe_normalize(mul(in_.normal, normal3_), (0.0).xxx);
    out_.world_normal = _e54;
    const float3 _e60 = weft_safe_normalize(mul(in_.tangent.xyz, model3_), (0.0).xxx);
    out_.world_tangent = float4(_e60, bitangent_sign);
    out_.uv0_ = in_.uv0_;
    WeftVaryings _e64 = out_;
    const WeftVaryings weftvaryings = _e64;
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

    const float3 _e11 = weft_view_direction(in_1.world_position, float3(0.0, 0.0, 1.0));
    const float3 _e13 = weft_safe_normalize(in_1.world_normal, _e11);
    const float3x3 _e15 = weft_tangent_frame(_e13, in_1.world_tangent);
    const float3 _e18 = weft_unpack_normal(float3(0.5019608, 0.5019608, 1.0), 0.6);
    const float3 _e19 = weft_normal_from_tangent_space(_e15, _e18);
    fibre = _e15[0];
    float3 _e22 = fibre;
    const float3x3 _e26 = weft_tangent_frame(_e19, float4(_e22, in_1.world_tangent.w));
    float3 n_diff = (false ? _e19 : _e13);
    const float3 _e29 = weft_main_light_direction();
    const float3 _e31 = weft_safe_normalize((_e29 + _e11), _e19);
    const float _e33 = weft_clamp_cos(dot(_e19, _e11));
    float n_dot_l = saturate(dot(_e19, _e29));
    float n_dot_h = saturate(dot(_e19, _e31));
    float v_dot_h_1 = saturate(dot(_e11, _e31));
    const float3 _e40 = weft_aniso_to_frame(_e26, _e11);
    const float3 _e41 = weft_aniso_to_frame(_e26, _e29);
    {
        const float2 _e44 = silk_ward_alpha_seed(0.86, 0.85);
        lobe.alpha = _e44;
        const float _e47 = silk_ibl_roughness(_e44);
        lobe.ibl_roughness = _e47;
        {
            const float _e49 = silk_ward_bounded(_e40, _e41, _e44);
            lobe.value = (_e49 * n_dot_l);
        }
    }
    const float3 _e51 = weft_main_light_radiance();
    float n_dot_l_diffuse = saturate(dot(n_diff, _e29));
    const float3 _e54 = weft_f_schlick(float3(0.14609632, 0.10047833, 0.11062463), v_dot_h_1);
    const float3 _e57 = weft_diffuse_lambert(float3(0.45638528, 0.27391332, 0.3144985));
    float3 diffuse = ((((1.0).xxx - _e54) * _e57) * n_dot_l_diffuse);
    float _e61 = lobe.value;
    float3 direct = ((diffuse + (_e54 * _e61)) * _e51);
    reflect_n = _e19;
    {
        {
            float _e70 = lobe.ibl_roughness;
            const float2 _e71 = weft_env_brdf_lut(_e33, _e70);
            scale_bias = _e71;
        }
        float2 _e72 = scale_bias;
        const float3 _e73 = weft_env_brdf_from_lut(float3(0.14609632, 0.10047833, 0.11062463), _e72);
        env_brdf = _e73;
        float3 _e75 = env_brdf;
        ambient_kd = max(((1.0).xxx - _e75), (0.0).xxx);
        float2 _e80 = lobe.alpha;
        const float _e81 = silk_lobe_anisotropy(_e80);
        float _e83 = lobe.ibl_roughness;
        const float3 _e84 = weft_aniso_bent_normal(_e26, _e11, _e81, _e83);
        reflect_n = _e84;
    }
    float3 _e86 = reflect_n;
    float _e89 = lobe.ibl_roughness;
    const float3 _e90 = weft_prefiltered_radiance(reflect(-(_e11), _e86), _e89);
    float3 _e91 = env_brdf;
    const float3 _e93 = weft_sh_irradiance(n_diff);
    float3 _e94 = ambient_kd;
    float3 indirect = ((_e90 * _e91) + ((_e93 * _e94) * float3(0.45638528, 0.27391332, 0.3144985)));
    float3 radiance = clamp((direct + indirect), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
