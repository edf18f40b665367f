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
    return (float3(0.04, 0.04, 0.04) + (float3(0.96, 0.96, 0.96) * _e5));
}

float3 weft_env_brdf_from_lut_k9_(float2 scale_bias_1)
{
    float2 sb = saturate(scale_bias_1);
    return ((float3(0.04, 0.04, 0.04) * sb.x) + (sb.y).xxx);
}

float3 weft_normal_from_tangent_space_k11_(float3x3 frame_2)
{
    const float3 _e4 = weft_safe_normalize(mul(float3(float2(0.003921628, 0.003921628), 1.0), frame_2), frame_2[2]);
    return _e4;
}

float weft_v_smith_ggx_aniso_correlated_k12_(float3 v_4, float3 l)
{
    const float _e5 = weft_clamp_cos(v_4.z);
    const float _e7 = weft_clamp_cos(l.z);
    float lv = (_e7 * length(float3((0.23174134 * v_4.x), (0.06475432 * v_4.y), _e5)));
    float ll = (_e5 * length(float3((0.23174134 * l.x), (0.06475432 * l.y), _e7)));
    return (0.5 / (lv + ll));
}

float weft_aniso_ggx_q_k14_(float t_dot_h, float b_dot_h, float n_dot_h)
{
    float x_2 = (t_dot_h / 0.23174134);
    float y = (b_dot_h / 0.06475432);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 1e-6);
}

float weft_d_ggx_aniso_k13_(float t_dot_h_1, float b_dot_h_1, float n_dot_h_1)
{
    const float _e7 = weft_aniso_ggx_q_k14_(t_dot_h_1, b_dot_h_1, n_dot_h_1);
    float d = (1.0 / ((0.047143534 * _e7) * _e7));
    return ((n_dot_h_1 > 0.0) ? d : 0.0);
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
    float n_dot_h_2 = saturate(dot(_e16, _e26));
    float v_dot_h_1 = saturate(dot(_e10, _e26));
    const float3 _e35 = weft_aniso_to_frame(_e23, _e10);
    const float3 _e36 = weft_aniso_to_frame(_e23, _e24);
    const float3 _e37 = weft_aniso_to_frame(_e23, _e26);
    {
        {
            lobe.alpha = float2(0.23174134, 0.06475432);
            lobe.ibl_roughness = 0.35000002;
            {
                {
                    const float _e44 = weft_v_smith_ggx_aniso_correlated_k12_(_e35, _e36);
                    vis = _e44;
                }
                const float _e49 = weft_d_ggx_aniso_k13_(_e37.x, _e37.y, _e37.z);
                float _e50 = vis;
                lobe.value = ((_e49 * _e50) * n_dot_l);
            }
        }
    }
    const float3 _e53 = weft_main_light_radiance();
    float n_dot_l_diffuse = saturate(dot(_e12, _e24));
    const float3 _e56 = weft_f_schlick_k7_(v_dot_h_1);
    float3 diffuse = ((((1.0).xxx - _e56) * float3(0.222817, 0.14323957, 0.031830948)) * n_dot_l_diffuse);
    float _e63 = lobe.value;
    float3 direct = ((diffuse + (_e56 * _e63)) * _e53);
    reflect_n = _e16;
    {
        {
            float _e72 = lobe.ibl_roughness;
            const float2 _e73 = weft_env_brdf_lut(_e28, _e72);
            scale_bias = _e73;
        }
        float2 _e74 = scale_bias;
        const float3 _e75 = weft_env_brdf_from_lut_k9_(_e74);
        env_brdf = _e75;
        float3 _e77 = env_brdf;
        ambient_kd = max(((1.0).xxx - _e77), (0.0).xxx);
        float2 _e82 = lobe.alpha;
        const float _e83 = silk_lobe_anisotropy(_e82);
        float _e85 = lobe.ibl_roughness;
        const float3 _e86 = weft_aniso_bent_normal(_e23, _e10, _e83, _e85);
        reflect_n = _e86;
    }
    float3 _e88 = reflect_n;
    float _e91 = lobe.ibl_roughness;
    const float3 _e92 = weft_prefiltered_radiance(reflect(-(_e10), _e88), _e91);
    float3 _e93 = env_brdf;
    const float3 _e95 = weft_sh_irradiance(_e12);
    float3 _e96 = ambient_kd;
    float3 indirect = ((_e92 * _e93) + ((_e95 * _e96) * float3(0.7000003, 0.4500004, 0.099999875)));
    float3 radiance = clamp((direct + indirect), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
