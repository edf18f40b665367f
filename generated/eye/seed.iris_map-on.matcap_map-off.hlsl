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
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }
cbuffer material : register(b0, space1) { WeftMaterial material; }
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
#define material_clamp_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[2]])
Texture2D<float4> iris_map : register(t3, space1);
Texture2D<float4> sclera_map : register(t4, space1);

struct VertexOutput_vs_main {
    float3 world_position_3 : LOC0;
    float3 world_normal_1 : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    float4 clip_position : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_4 : LOC0;
    float3 world_normal_2 : LOC1;
    float4 world_tangent_1 : LOC2;
    float2 uv0_1 : LOC3;
    float4 clip_position_1 : SV_Position;
};

float3 weft_safe_normalize(float3 v, float3 fallback)
{
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * rsqrt(max(len2_, 1e-20))) : fallback);
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

float2 eye_seed_uv(float2 uv, float3 v_1, float height)
{
    return (uv + (height * float2(v_1.x, -(v_1.y))));
}

float2 eye_uv_from_xy(float2 xy)
{
    return float2((0.5 + (0.5 * xy.x)), (0.5 - (0.5 * xy.y)));
}

float2 eye_xy_from_uv(float2 uv_1)
{
    return float2(((2.0 * uv_1.x) - 1.0), (1.0 - (2.0 * uv_1.y)));
}

float3 eye_albedo(float2 q, bool front)
{
    float3 iris = (float3)0;

    float _e4 = material.iris_radius;
    float r = clamp(_e4, 0.05, 0.95);
    float rho = (length(q) / r);
    {
        float2 iris_uv = (float2(0.5, 0.5) + (float2(q.x, -(q.y)) * (0.5 / r)));
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

float3 eye_procedural_matcap(float2 uv_2)
{
    float key = (1.0 - smoothstep(0.03, 0.08, length((uv_2 - float2(0.36, 0.3)))));
    float bounce = (1.0 - smoothstep(0.02, 0.09, length((uv_2 - float2(0.66, 0.72)))));
    return ((key + (0.25 * bounce))).xxx;
}

float3 eye_seed(float3 p, float3 v_eye, float3 n_1, float3 world_position_2, float3 light)
{
    float3 matcap = (float3)0;

    const float2 _e6 = eye_uv_from_xy(p.xy);
    float _e9 = material.parallax_height;
    const float2 _e10 = eye_seed_uv(_e6, v_eye, _e9);
    const float2 _e11 = eye_xy_from_uv(_e10);
    const float3 _e15 = eye_albedo(_e11, (p.z > 0.0));
    float4x4 view = weft_frame.view;
    float3x3 view3_ = float3x3(view[0].xyz, view[1].xyz, view[2].xyz);
    const float3 _e31 = weft_safe_normalize(mul(n_1, view3_), float3(0.0, 0.0, 1.0));
    const float3 _e40 = weft_safe_normalize(mul(float4(world_position_2, 1.0), view).xyz, float3(0.0, 0.0, -1.0));
    float3 vxn = cross(_e40, _e31);
    float2 matcap_uv = float2((0.5 - (0.5 * vxn.y)), (0.5 - (0.5 * vxn.x)));
    {
        const float3 _e54 = eye_procedural_matcap(matcap_uv);
        matcap = _e54;
    }
    float3 _e55 = matcap;
    float _e58 = material.matcap_intensity;
    float3 base = (_e15 + (_e55 * max(_e58, 0.0)));
    const float3 _e65 = weft_sh_irradiance(n_1);
    return (base * ((light * WEFT_INV_PI) + _e65));
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
    WeftVaryings in_1 = { fragmentinput_fs_main.clip_position_1, fragmentinput_fs_main.world_position_4, fragmentinput_fs_main.world_normal_2, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_1 };
    float3 color = (float3)0;
    EyeLookup look = (EyeLookup)0;

    float4x4 model_1 = weft_object.model;
    float3x3 model3_1 = float3x3(model_1[0].xyz, model_1[1].xyz, model_1[2].xyz);
    float4x4 nm_1 = weft_object.normal_matrix;
    float3x3 normal3_1 = float3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    const WeftSurface _e23 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_2 = _e23.v;
    float3 n_2 = _e23.n;
    const float3 _e26 = weft_main_light_direction();
    const float3 _e33 = weft_safe_normalize(mul(n_2, transpose(model3_1)), float3(0.0, 0.0, 1.0));
    const float3 _e40 = weft_safe_normalize(mul(v_2, transpose(normal3_1)), float3(0.0, 0.0, 1.0));
    const float3 _e46 = weft_safe_normalize(mul(float3(0.0, 0.0, 1.0), model3_1), n_2);
    float _e49 = material.backlight_dimming;
    float dimming = (1.0 - (saturate(_e49) * saturate(-(dot(_e46, _e26)))));
    const float3 _e57 = weft_main_light_radiance();
    {
        const float3 _e60 = eye_seed(_e33, _e40, n_2, in_1.world_position, _e57);
        color = _e60;
    }
    float3 _e61 = color;
    float3 radiance = clamp((_e61 * dimming), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
