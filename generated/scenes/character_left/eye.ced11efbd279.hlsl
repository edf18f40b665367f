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

struct WeftSurface {
    float3 v;
    int _pad1_0;
    float3 n;
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

struct EyeCornea {
    float z_iris;
    float centre_z;
    float radius;
};

struct EyeLookup {
    float2 iris;
    int _pad1_0;
    int _pad1_1;
    float3 normal;
    float through_cornea;
};

EyeCornea ConstructEyeCornea(float arg0, float arg1, float arg2) {
    EyeCornea ret = (EyeCornea)0;
    ret.z_iris = arg0;
    ret.centre_z = arg1;
    ret.radius = arg2;
    return ret;
}

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_SEED = 2u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;

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

float3 weft_safe_normalize(float3 v, float3 fallback)
{
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * rsqrt(max(len2_, 1e-20))) : fallback);
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

float3 weft_view_direction_k2_(float3 world_position)
{
    float4 _e4 = weft_frame.camera_position;
    const float3 _e7 = weft_safe_normalize_k1_((_e4.xyz - world_position));
    return _e7;
}

WeftSurface ConstructWeftSurface(float3 arg0, float3 arg1) {
    WeftSurface ret = (WeftSurface)0;
    ret.v = arg0;
    ret.n = arg1;
    return ret;
}

WeftSurface weft_surface(float3 world_position_1, float3 world_normal)
{
    const float3 _e2 = weft_view_direction_k2_(world_position_1);
    const float3 _e3 = weft_safe_normalize(world_normal, _e2);
    const WeftSurface weftsurface = ConstructWeftSurface(_e2, _e3);
    return weftsurface;
}

float3 weft_safe_normalize_k3_(float3 v_2)
{
    float len2_2 = dot(v_2, v_2);
    return ((len2_2 > 1e-20) ? (v_2 * rsqrt(max(len2_2, 1e-20))) : (0.0).xxx);
}

WeftVaryings weft_forward_vertex(WeftVertexInput in_2)
{
    WeftVaryings out_ = (WeftVaryings)0;

    float4x4 model = weft_object.model;
    float3x3 model3_ = float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    float4x4 nm = weft_object.normal_matrix;
    float3x3 normal3_1 = float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    float4 world = mul(float4(in_2.position, 1.0), model);
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    float4x4 _e43 = weft_frame.view_proj;
    out_.clip_position = mul(float4(world.xyz, 1.0), _e43);
    out_.world_position = world.xyz;
    const float3 _e53 = weft_safe_normalize_k3_(mul(in_2.normal, normal3_1));
    out_.world_normal = _e53;
    const float3 _e58 = weft_safe_normalize_k3_(mul(in_2.tangent.xyz, model3_));
    out_.world_tangent = float4(_e58, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e62 = out_;
    const WeftVaryings weftvaryings = _e62;
    return weftvaryings;
}

float3 eye_procedural_iris(float rho, float a)
{
    float3 c_1 = (float3)0;

    float t = saturate(((rho - 0.38) / 0.62));
    c_1 = lerp(float3(0.34239164, 0.147319, 0.021980947), float3(0.10653923, 0.033104766, 0.008540382), smoothstep(0.05, 0.5, t));
    float fibres = ((0.82 + (0.1 * sin(((a * 23.0) + (6.0 * t))))) + (0.08 * sin((((a * 41.0) - (9.0 * t)) + 1.3))));
    float3 _e35 = c_1;
    c_1 = (_e35 * fibres);
    float3 _e38 = c_1;
    c_1 = (_e38 * (1.0 - (0.8 * smoothstep(0.88, 1.0, rho))));
    float3 _e48 = c_1;
    return lerp((0.01).xxx, _e48, smoothstep(0.35999998, 0.4, rho));
}

float3 eye_albedo(float2 q, bool front)
{
    float3 iris = (float3)0;

    float rho_2 = (length(q) / 0.5);
    {
        float2 qa = ((dot(q, q) > 1e-12) ? q : float2(1.0, 0.0));
        const float3 _e14 = eye_procedural_iris(rho_2, atan2(qa.y, qa.x));
        iris = _e14;
    }
    float to_sclera = (front ? smoothstep(0.985, 1.015, rho_2) : 1.0);
    float3 _e21 = iris;
    return saturate(lerp(_e21, float3(0.71056646, 0.67385954, 0.6382832), to_sclera));
}

float3 weft_f_schlick_k20_(float v_dot_h)
{
    const float _e5 = weft_pow5_((1.0 - saturate(v_dot_h)));
    return ((0.025042804).xxx + (float3(0.97495717, 0.97495717, 0.97495717) * _e5));
}

float eye_fresnel_k8_(float cos_i)
{
    const float3 _e2 = weft_f_schlick_k20_(cos_i);
    return _e2.x;
}

float weft_d_ggx_k14_(float n_dot_h)
{
    float noh = saturate(n_dot_h);
    float one_minus_noh2_ = ((1.0 - noh) * (1.0 + noh));
    float d = (one_minus_noh2_ + ((noh * noh) * 1.2960001e-5));
    return (1.2960001e-5 / ((WEFT_PI * d) * d));
}

float weft_v_smith_ggx_correlated_newton_k15_(float n_dot_v, float n_dot_l)
{
    const float _e6 = weft_clamp_cos(n_dot_v);
    const float _e7 = weft_clamp_cos(n_dot_l);
    float gv = ((_e6 * 0.9964) + 0.0036000002);
    float gl = ((_e7 * 0.9964) + 0.0036000002);
    float pv = ((gv * _e6) + (1.2960001e-5 * (1.0 - _e6)));
    float pl = ((gl * _e7) + (1.2960001e-5 * (1.0 - _e7)));
    return (((0.5 * gv) * gl) / (((_e7 * gl) * pv) + ((_e6 * gv) * pl)));
}

float eye_ggx_k9_(float3 s, float3 h, float s_dot_v, float s_dot_l)
{
    const float _e7 = weft_d_ggx_k14_(saturate(dot(s, h)));
    const float _e8 = weft_v_smith_ggx_correlated_newton_k15_(s_dot_v, s_dot_l);
    return (_e7 * _e8);
}

float weft_specular_mip_k16_()
{
    float _e5 = weft_frame.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return (0.09948 * max_mip);
}

float3 weft_prefiltered_radiance_k11_(float3 dir)
{
    const float _e4 = weft_specular_mip_k16_();
    float4 c_2 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_2.xyz, (0.0).xxx);
}

float2 weft_env_brdf_lut_k12_(float n_dot_v_1)
{
    float2 uv = float2(saturate(n_dot_v_1), 0.060000002);
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv, 0.0);
    return _e8.xy;
}

float3 weft_env_brdf_from_lut_k19_(float2 scale_bias)
{
    float2 sb = saturate(scale_bias);
    return (((0.025042804).xxx * sb.x) + (sb.y).xxx);
}

float3 eye_physical_k7_(EyeLookup look_1, float3 n_1, float3 v_3, float3 l, float3x3 normal3_, float3 light)
{
    bool local = (bool)0;

    if (!((look_1.through_cornea > 0.0))) {
        local = (look_1.normal.z > 0.0);
    } else {
        local = true;
    }
    bool _e19 = local;
    const float3 _e20 = eye_albedo(look_1.iris, _e19);
    const float3 _e24 = weft_safe_normalize(mul(look_1.normal, normal3_), n_1);
    const float _e26 = weft_clamp_cos(dot(_e24, v_3));
    float s_dot_l_1 = saturate(dot(_e24, l));
    const float3 _e30 = weft_safe_normalize((l + v_3), _e24);
    const float _e32 = eye_fresnel_k8_(dot(v_3, _e30));
    const float _e33 = eye_ggx_k9_(_e24, _e30, _e26, s_dot_l_1);
    float direct_spec = ((_e33 * _e32) * s_dot_l_1);
    const float3 _e39 = weft_prefiltered_radiance_k11_(reflect(-(v_3), _e24));
    const float2 _e40 = weft_env_brdf_lut_k12_(_e26);
    const float3 _e41 = weft_env_brdf_from_lut_k19_(_e40);
    float3 env = (_e39 * _e41);
    float3 specular = ((light * direct_spec) + env);
    bool on_iris = (look_1.through_cornea > 0.0);
    const float3 _e50 = weft_safe_normalize(mul(float3(0.0, 0.0, 1.0), normal3_), n_1);
    float3 l_in = refract(-(l), _e24, 0.7267442);
    float iris_cos = ((s_dot_l_1 > 0.0) ? saturate(dot(_e50, -(l_in))) : 0.0);
    const float _e61 = eye_fresnel_k8_(_e26);
    float t_v = (1.0 - _e61);
    const float _e64 = eye_fresnel_k8_(s_dot_l_1);
    float t_l = (1.0 - _e64);
    float3 diffuse_n = (on_iris ? _e50 : n_1);
    float diffuse_cos = (on_iris ? (iris_cos * t_l) : saturate(dot(n_1, l)));
    float transmission = (on_iris ? t_v : 1.0);
    const float3 _e78 = weft_sh_irradiance(diffuse_n);
    float3 diffuse = ((_e20 * transmission) * ((light * (WEFT_INV_PI * diffuse_cos)) + _e78));
    return (diffuse + specular);
}

float eye_cornea_height_k17_(float rho_1)
{
    float z = (0.5380625 + sqrt(max((0.35755965 - (rho_1 * rho_1)), 0.0)));
    return max((z - 0.8660254), 0.0);
}

float3 eye_cornea_normal_k18_(float2 xy)
{
    float z_1 = sqrt(max((0.35755965 - dot(xy, xy)), 0.0));
    return (float3(xy, z_1) / (0.5979629).xxx);
}

EyeLookup ConstructEyeLookup(float2 arg0, float3 arg1, float arg2) {
    EyeLookup ret = (EyeLookup)0;
    ret.iris = arg0;
    ret.normal = arg1;
    ret.through_cornea = arg2;
    return ret;
}

EyeLookup eye_parallax_k13_(float3 p, float3 v_4)
{
    bool local_1 = (bool)0;

    float rho_3 = length(p.xy);
    if (!((p.z <= 0.0))) {
        local_1 = (rho_3 >= 0.5);
    } else {
        local_1 = true;
    }
    bool _e15 = local_1;
    if (_e15) {
        const EyeLookup eyelookup = ConstructEyeLookup(p.xy, p, 0.0);
        return eyelookup;
    }
    const float _e21 = eye_cornea_height_k17_(rho_3);
    float d_1 = ((0.8660254 + _e21) - p.z);
    float2 e_raw = (p.xy + (d_1 * v_4.xy));
    float2 e_1 = (e_raw * min(1.0, (0.5 / max(length(e_raw), 1e-6))));
    const float _e37 = eye_cornea_height_k17_(length(e_1));
    const float3 _e38 = eye_cornea_normal_k18_(e_1);
    float2 iris_1 = (e_1 - (_e37 * ((v_4.xy * 0.7267442) + (_e38.xy * 0.27325583))));
    const EyeLookup eyelookup_1 = ConstructEyeLookup(iris_1, _e38, 1.0);
    return eyelookup_1;
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
    float3 color = (float3)0;
    EyeLookup look = (EyeLookup)0;

    float4x4 model_1 = weft_object.model;
    float3x3 model3_1 = float3x3(model_1[0].xyz, model_1[1].xyz, model_1[2].xyz);
    float4x4 nm_1 = weft_object.normal_matrix;
    float3x3 normal3_2 = float3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    const WeftSurface _e23 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_5 = _e23.v;
    float3 n_2 = _e23.n;
    const float3 _e26 = weft_main_light_direction();
    const float3 _e29 = weft_safe_normalize_k1_(mul(n_2, transpose(model3_1)));
    const float3 _e32 = weft_safe_normalize_k1_(mul(v_5, transpose(normal3_2)));
    const float3 _e35 = weft_safe_normalize(mul(float3(0.0, 0.0, 1.0), model3_1), n_2);
    float dimming = (1.0 - (0.5 * saturate(-(dot(_e35, _e26)))));
    const float3 _e43 = weft_main_light_radiance();
    {
        {
            const EyeLookup _e48 = eye_parallax_k13_(_e29, _e32);
            look = _e48;
        }
        EyeLookup _e49 = look;
        const float3 _e50 = eye_physical_k7_(_e49, n_2, v_5, _e26, normal3_2, _e43);
        color = _e50;
    }
    float3 _e51 = color;
    float3 radiance = clamp((_e51 * dimming), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
