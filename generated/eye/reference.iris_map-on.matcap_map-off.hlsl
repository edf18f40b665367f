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
    float iris_radius;
    float pupil_size;
    int _pad2_0;
    int _pad2_1;
    float4 iris_color;
    float4 iris_inner_color;
    float limbus_width;
    int _pad5_0;
    int _pad5_1;
    int _pad5_2;
    float4 sclera_color;
    float cornea_height;
    float cornea_ior;
    float cornea_smoothness;
    float specular_strength;
    float backlight_dimming;
    float parallax_height;
    float matcap_intensity;
    int _end_pad_0;
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
cbuffer material : register(b0, space1) { WeftMaterial material; }
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
#define material_clamp_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[2]])
Texture2D<float4> iris_map : register(t3, space1);
Texture2D<float4> sclera_map : register(t4, space1);

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

float weft_d_ggx_nh(float3 n, float3 h, float roughness_1)
{
    const float _e3 = weft_clamp_roughness(roughness_1);
    float a = (_e3 * _e3);
    float a2_ = (a * a);
    float noh = saturate(dot(n, h));
    float3 nxh = cross(n, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d * d), 1e-30)));
}

float weft_f_dielectric(float cos_i, float eta)
{
    float c_2 = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c_2 * c_2));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c_2);
    float gpc = max((g + c_2), 1e-7);
    float b_den = max(((c_2 * gmc) + 1.0), 1e-7);
    float b_num = ((c_2 * gpc) - 1.0);
    float inv = (1.0 / (gpc * b_den));
    float f = saturate(((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)));
    return ((g2_ < 0.0) ? 1.0 : f);
}

float weft_f0_from_ior(float ior)
{
    float q_1 = ((ior - 1.0) / max((ior + 1.0), 0.0001));
    return (q_1 * q_1);
}

float weft_v_smith_ggx_correlated(float n_dot_v, float n_dot_l, float roughness_2)
{
    const float _e3 = weft_clamp_roughness(roughness_2);
    float a_1 = (_e3 * _e3);
    float a2_1 = (a_1 * a_1);
    const float _e6 = weft_clamp_cos(n_dot_v);
    const float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * (1.0 - a2_1)) + a2_1)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * (1.0 - a2_1)) + a2_1)));
    return (0.5 / (lv + ll));
}

float3 weft_env_brdf_from_lut(float3 f0_, float2 scale_bias)
{
    float2 sb = saturate(scale_bias);
    return ((f0_ * sb.x) + (sb.y).xxx);
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
    float4 c_3 = weft_environment.SampleLevel(weft_environment_sampler, dir, _e4);
    return max(c_3.xyz, (0.0).xxx);
}

float2 weft_env_brdf_lut(float n_dot_v_1, float roughness_5)
{
    float2 uv = float2(saturate(n_dot_v_1), saturate(roughness_5));
    float4 _e8 = weft_brdf_lut.SampleLevel(weft_lut_sampler, uv, 0.0);
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
    const float3 _e55 = weft_safe_normalize(mul(in_2.normal, normal3_1), (0.0).xxx);
    out_.world_normal = _e55;
    const float3 _e62 = weft_safe_normalize(mul(in_2.tangent.xyz, model3_), (0.0).xxx);
    out_.world_tangent = float4(_e62, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out_;
    const WeftVaryings weftvaryings = _e66;
    return weftvaryings;
}

EyeCornea ConstructEyeCornea(float arg0, float arg1, float arg2) {
    EyeCornea ret = (EyeCornea)0;
    ret.z_iris = arg0;
    ret.centre_z = arg1;
    ret.radius = arg2;
    return ret;
}

EyeCornea eye_cornea(float iris_radius, float height)
{
    float r_1 = clamp(iris_radius, 0.05, 0.95);
    float h_2 = max(height, 0.01);
    float z_iris_1 = sqrt((1.0 - (r_1 * r_1)));
    float radius = (((r_1 * r_1) + (h_2 * h_2)) / (2.0 * h_2));
    const EyeCornea eyecornea = ConstructEyeCornea(z_iris_1, ((z_iris_1 + h_2) - radius), radius);
    return eyecornea;
}

float2 eye_to_iris_plane(float3 start, float3 t, float z_iris)
{
    float down = max(-(t.z), 0.0001);
    return (start.xy + (t.xy * ((start.z - z_iris) / down)));
}

EyeLookup ConstructEyeLookup(float2 arg0, float3 arg1, float arg2) {
    EyeLookup ret = (EyeLookup)0;
    ret.iris = arg0;
    ret.normal = arg1;
    ret.through_cornea = arg2;
    return ret;
}

EyeLookup eye_refracted(float3 p, float3 v_1, EyeCornea c_1, float ior_1)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;

    float3 centre = float3(0.0, 0.0, c_1.centre_z);
    float3 o = (p - centre);
    float b = dot(o, v_1);
    float disc = ((b * b) - (dot(o, o) - (c_1.radius * c_1.radius)));
    float s_1 = (-(b) + sqrt(max(disc, 0.0)));
    float3 hit = (p + (s_1 * v_1));
    if (!((p.z <= 0.0))) {
        local = (disc <= 0.0);
    } else {
        local = true;
    }
    bool _e33 = local;
    if (!(_e33)) {
        local_1 = (hit.z < c_1.z_iris);
    } else {
        local_1 = true;
    }
    bool _e41 = local_1;
    if (_e41) {
        const EyeLookup eyelookup = ConstructEyeLookup(p.xy, p, 0.0);
        return eyelookup;
    }
    float3 n_3 = ((hit - centre) / (c_1.radius).xxx);
    float3 t_1 = refract(-(v_1), n_3, (1.0 / max(ior_1, 1.0)));
    const float2 _e56 = eye_to_iris_plane(hit, t_1, c_1.z_iris);
    const EyeLookup eyelookup_1 = ConstructEyeLookup(_e56, n_3, 1.0);
    return eyelookup_1;
}

float2 eye_uv_from_xy(float2 xy)
{
    return float2((0.5 + (0.5 * xy.x)), (0.5 - (0.5 * xy.y)));
}

float3 eye_albedo(float2 q, bool front)
{
    float3 iris = (float3)0;

    float _e4 = material.iris_radius;
    float r_2 = clamp(_e4, 0.05, 0.95);
    float rho = (length(q) / r_2);
    {
        float2 iris_uv = (float2(0.5, 0.5) + (float2(q.x, -(q.y)) * (0.5 / r_2)));
        float4 _e24 = material.iris_color;
        float4 _e28 = iris_map.Sample(material_clamp_sampler, iris_uv);
        iris = (_e24.xyz * _e28.xyz);
    }
    float4 _e33 = material.sclera_color;
    const float2 _e37 = eye_uv_from_xy(q);
    float4 _e38 = sclera_map.Sample(material_sampler, _e37);
    float3 sclera = (_e33.xyz * _e38.xyz);
    float to_sclera = (front ? smoothstep(0.985, 1.015, rho) : 1.0);
    float3 _e46 = iris;
    return saturate(lerp(_e46, sclera, to_sclera));
}

float eye_fresnel(float cos_i_1, float ior_2)
{
    {
        const float _e2 = weft_f_dielectric(cos_i_1, ior_2);
        return _e2;
    }
}

float eye_ggx(float3 s, float3 h_1, float s_dot_v, float s_dot_l, float roughness_6)
{
    {
        const float _e5 = weft_d_ggx_nh(s, h_1, roughness_6);
        const float _e6 = weft_v_smith_ggx_correlated(s_dot_v, s_dot_l, roughness_6);
        return (_e5 * _e6);
    }
}

float3 eye_physical(EyeLookup look_1, float3 n_2, float3 v_2, float3 l, float3x3 normal3_, float ior_3, float3 light)
{
    bool local_2 = (bool)0;

    if (!((look_1.through_cornea > 0.0))) {
        local_2 = (look_1.normal.z > 0.0);
    } else {
        local_2 = true;
    }
    bool _e19 = local_2;
    const float3 _e20 = eye_albedo(look_1.iris, _e19);
    float _e23 = material.cornea_smoothness;
    const float _e27 = weft_clamp_roughness((1.0 - saturate(_e23)));
    const float3 _e30 = weft_safe_normalize(mul(look_1.normal, normal3_), n_2);
    const float _e32 = weft_clamp_cos(dot(_e30, v_2));
    float s_dot_l_1 = saturate(dot(_e30, l));
    const float3 _e36 = weft_safe_normalize((l + v_2), _e30);
    const float _e38 = eye_fresnel(dot(v_2, _e36), ior_3);
    const float _e39 = eye_ggx(_e30, _e36, _e32, s_dot_l_1, _e27);
    float direct_spec = ((_e39 * _e38) * s_dot_l_1);
    const float _e42 = weft_f0_from_ior(ior_3);
    float3 f0_1 = (_e42).xxx;
    const float3 _e46 = weft_prefiltered_radiance(reflect(-(v_2), _e30), _e27);
    const float2 _e47 = weft_env_brdf_lut(_e32, _e27);
    const float3 _e48 = weft_env_brdf_from_lut(f0_1, _e47);
    float3 env = (_e46 * _e48);
    float _e54 = material.specular_strength;
    float3 specular = (((light * direct_spec) + env) * max(_e54, 0.0));
    bool on_iris = (look_1.through_cornea > 0.0);
    const float3 _e66 = weft_safe_normalize(mul(float3(0.0, 0.0, 1.0), normal3_), n_2);
    float3 l_in = refract(-(l), _e30, (1.0 / ior_3));
    float iris_cos = ((s_dot_l_1 > 0.0) ? saturate(dot(_e66, -(l_in))) : 0.0);
    const float _e78 = eye_fresnel(_e32, ior_3);
    float t_v = (1.0 - _e78);
    const float _e81 = eye_fresnel(s_dot_l_1, ior_3);
    float t_l = (1.0 - _e81);
    float3 diffuse_n = (on_iris ? _e66 : n_2);
    float diffuse_cos = (on_iris ? (iris_cos * t_l) : saturate(dot(n_2, l)));
    float transmission = (on_iris ? t_v : 1.0);
    const float3 _e95 = weft_sh_irradiance(diffuse_n);
    float3 diffuse = ((_e20 * transmission) * ((light * (WEFT_INV_PI * diffuse_cos)) + _e95));
    return (diffuse + specular);
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
    float3 v_3 = _e23.v;
    float3 n_4 = _e23.n;
    const float3 _e26 = weft_main_light_direction();
    const float3 _e33 = weft_safe_normalize(mul(n_4, transpose(model3_1)), float3(0.0, 0.0, 1.0));
    const float3 _e40 = weft_safe_normalize(mul(v_3, transpose(normal3_2)), float3(0.0, 0.0, 1.0));
    const float3 _e46 = weft_safe_normalize(mul(float3(0.0, 0.0, 1.0), model3_1), n_4);
    float _e49 = material.backlight_dimming;
    float dimming = (1.0 - (saturate(_e49) * saturate(-(dot(_e46, _e26)))));
    const float3 _e57 = weft_main_light_radiance();
    {
        float _e61 = material.iris_radius;
        float _e64 = material.cornea_height;
        const EyeCornea _e65 = eye_cornea(_e61, _e64);
        float _e68 = material.cornea_ior;
        float ior_4 = max(_e68, 1.0);
        {
            const EyeLookup _e72 = eye_refracted(_e33, _e40, _e65, ior_4);
            look = _e72;
        }
        EyeLookup _e73 = look;
        const float3 _e74 = eye_physical(_e73, n_4, v_3, _e26, normal3_2, ior_4, _e57);
        color = _e74;
    }
    float3 _e75 = color;
    float3 radiance = clamp((_e75 * dimming), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
