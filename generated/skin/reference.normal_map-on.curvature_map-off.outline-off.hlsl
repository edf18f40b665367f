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
    float normal_strength;
    float roughness;
    float specular;
    float curvature_factor;
    float dark_bound;
    float bright_bound;
    float lobe_weight;
    int _pad9_0;
    float4 outline_color;
    float outline_width;
    float outline_max_distance;
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

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const float3 skin_lut_shape = float3(4.0, 10.0, 20.0);
static const float skin_lut_ring = 3.1415927;
static const float3 seed_lut_shape = float3(4.0, 10.0, 20.0);
static const float seed_lut_ring = 1.5707964;
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
Texture2D<float4> base_map : register(t3, space1);
Texture2D<float4> normal_map : register(t4, space1);
Texture2D<float4> curvature_map : register(t5, space1);
Texture2D<float4> specular_mask : register(t6, space1);

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

float3 weft_select3_f32bit(bool3 weft_sel_c, float3 weft_sel_a, float3 weft_sel_b)
{
    return float3((weft_sel_c.x ? weft_sel_a.x : weft_sel_b.x), (weft_sel_c.y ? weft_sel_a.y : weft_sel_b.y), (weft_sel_c.z ? weft_sel_a.z : weft_sel_b.z));
}

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
    float s = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return float3((1.0 + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
}

float weft_d_ggx_nh(float3 n_2, float3 h, float roughness_1)
{
    const float _e3 = weft_clamp_roughness(roughness_1);
    float a_1 = (_e3 * _e3);
    float a2_ = (a_1 * a_1);
    float noh = saturate(dot(n_2, h));
    float3 nxh = cross(n_2, h);
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

float3 weft_sh_irradiance(float3 n_3)
{
    float3 e = (float3)0;

    float4 sh[9] = weft_frame.sh;
    e = (sh[0].xyz * 0.282095);
    float3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_3.y)));
    float3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_3.z)));
    float3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_3.x)));
    float3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_3.x) * n_3.y)));
    float3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_3.y) * n_3.z)));
    float3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_3.z) * n_3.z) - 1.0))));
    float3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_3.x) * n_3.z)));
    float3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_3.x * n_3.x) - (n_3.y * n_3.y)))));
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

WeftLightGeometry weft_main_light_geometry(float3 n_4, float3 v_1)
{
    const float3 _e2 = weft_main_light_direction();
    const float3 _e4 = weft_safe_normalize((_e2 + v_1), n_4);
    const float _e6 = weft_clamp_cos(dot(n_4, v_1));
    const WeftLightGeometry weftlightgeometry = ConstructWeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_4, _e2)), saturate(dot(n_4, _e4)), saturate(dot(v_1, _e4)));
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

float3x3 weft_tangent_frame(float3 n_5, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_5 * dot(n_5, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_5);
    float3 t = (ok ? (t_proj * rsqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_5, t) * s_1);
    return float3x3(t, b_1, n_5);
}

float3 weft_unpack_normal(float3 texel, float strength)
{
    float3 v_2 = ((texel * 2.0) - (1.0).xxx);
    return float3((v_2.xy * strength), max(v_2.z, 0.001));
}

float3 weft_normal_from_tangent_space(float3x3 frame, float3 n_ts)
{
    const float3 _e4 = weft_safe_normalize(mul(n_ts, frame), frame[2]);
    return _e4;
}

float3 weft_mapped_normal(float3 n_6, float4 tangent_1, float3 texel_1, float strength_1)
{
    const float3x3 _e4 = weft_tangent_frame(n_6, tangent_1);
    const float3 _e5 = weft_unpack_normal(texel_1, strength_1);
    const float3 _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
}

float2 weft_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

float3 skin_preintegrated(float cos_theta, float curvature_1, float3 shape, float x_max)
{
    float3 num = (0.0).xxx;
    float3 den = (0.0).xxx;
    uint k = 0u;
    float g = (float)0;
    float dg = (float)0;

    float flat = max(cos_theta, 0.0);
    if ((curvature_1 <= 0.0)) {
        return (flat).xxx;
    }
    float r_1 = (1.0 / curvature_1);
    float theta = acos(clamp(cos_theta, -1.0, 1.0));
    float s_max = max(shape.x, max(shape.y, shape.z));
    float a_3 = min(log((1.0 + ((x_max * s_max) * r_1))), 40.0);
    float e_1 = (exp(a_3) - 1.0);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e100 = k;
            k = (_e100 + 1u);
        }
        loop_init = false;
        uint _e38 = k;
        if ((_e38 < 64u)) {
        } else {
            break;
        }
        {
            uint _e41 = k;
            float t_1 = ((float(_e41) + 0.5) / 64.0);
            g = t_1;
            dg = 1.0;
            if ((a_3 >= 0.0001)) {
                g = ((exp((a_3 * t_1)) - 1.0) / e_1);
                dg = ((a_3 * exp((a_3 * t_1))) / e_1);
            }
            float _e61 = g;
            float x_1 = (x_max * _e61);
            float _e63 = dg;
            float jac = (x_max * _e63);
            float d_1 = ((2.0 * r_1) * abs(sin((0.5 * x_1))));
            float light = (max(cos((theta + x_1)), 0.0) + max(cos((theta - x_1)), 0.0));
            float3 w_1 = ((exp((-(shape) * d_1)) + exp(((-(shape) * d_1) / (3.0).xxx))) * jac);
            float3 _e92 = num;
            num = (_e92 + (light * w_1));
            float3 _e95 = den;
            den = (_e95 + (2.0 * w_1));
        }
    }
    float3 _e103 = num;
    float3 _e104 = den;
    float3 _e109 = den;
    const float3 _e113 = weft_select3_f32bit((_e109 > (0.0).xxx), (_e103 / max(_e104, (1e-30).xxx)), (flat).xxx);
    return _e113;
}

float skin_dual_ggx(float3 n_7, float3 h_1, float n_dot_v_2, float n_dot_l_1, float v_dot_h_1, float roughness_6, float w, float f0_2)
{
    float r0_ = clamp((roughness_6 * 0.75), 0.0, 1.0);
    float r1_ = clamp((roughness_6 * 1.3), 0.0, 1.0);
    const float _e18 = weft_d_ggx_nh(n_7, h_1, r0_);
    const float _e19 = weft_v_smith_ggx_correlated(n_dot_v_2, n_dot_l_1, r0_);
    float lobe0_ = (_e18 * _e19);
    const float _e21 = weft_d_ggx_nh(n_7, h_1, r1_);
    const float _e22 = weft_v_smith_ggx_correlated(n_dot_v_2, n_dot_l_1, r1_);
    float lobe1_ = (_e21 * _e22);
    const float3 _e25 = weft_f_schlick((f0_2).xxx, v_dot_h_1);
    float f = _e25.x;
    return (lerp(lobe0_, lobe1_, saturate(w)) * f);
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
    float curvature = (float)0;
    float3 n = (float3)0;
    float3 falloff = (float3)0;
    float specular = (float)0;
    float3 kd = (float3)0;

    float4 _e4 = material.base_map_st;
    const float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    float4 _e8 = material.base_color;
    float4 _e11 = base_map.Sample(material_sampler, _e5);
    float4 base_rgba = (_e8 * _e11);
    float3 albedo_1 = saturate(base_rgba.xyz);
    float alpha = saturate(base_rgba.w);
    float _e19 = material.roughness;
    float roughness_7 = clamp(_e19, 0.05, 1.0);
    float _e25 = material.specular;
    float f0_3 = clamp(_e25, 0.0, 1.0);
    float4 _e31 = specular_mask.Sample(material_sampler, _e5);
    float mask = saturate(_e31.x);
    const WeftSurface _e36 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_3 = _e36.v;
    float3 n_geom = _e36.n;
    float3 _e39 = fwidth(n_geom);
    float dn = length(_e39);
    float3 _e42 = fwidth(in_1.world_position);
    float dp = length(_e42);
    float estimated = ((dp > 1e-12) ? (dn / dp) : 0.0);
    float4 _e51 = curvature_map.Sample(material_sampler, _e5);
    float mapped = _e51.x;
    float _e55 = material.curvature_factor;
    float factor = max(_e55, 0.0);
    curvature = saturate((factor * estimated));
    n = n_geom;
    {
        float4 _e64 = normal_map.Sample(material_sampler, _e5);
        float3 texel_2 = _e64.xyz;
        float3 _e66 = n;
        float _e70 = material.normal_strength;
        const float3 _e71 = weft_mapped_normal(_e66, in_1.world_tangent, texel_2, _e70);
        n = _e71;
    }
    float3 _e72 = n;
    const WeftLightGeometry _e73 = weft_main_light_geometry(_e72, v_3);
    float3 _e74 = n;
    float _e83 = material.dark_bound;
    float _e86 = material.bright_bound;
    float u = clamp(((dot(_e74, _e73.l) * 0.5) + 0.5), _e83, _e86);
    {
        float _e93 = curvature;
        const float3 _e96 = skin_preintegrated(((2.0 * u) - 1.0), _e93, skin_lut_shape, skin_lut_ring);
        falloff = _e96;
    }
    float3 _e97 = falloff;
    falloff = max(_e97, (0.0).xxx);
    const float2 _e103 = weft_env_brdf_lut(_e73.n_dot_v, roughness_7);
    const float3 _e104 = weft_env_brdf_from_lut((f0_3).xxx, _e103);
    {
        float3 _e107 = n;
        float _e114 = material.lobe_weight;
        const float _e115 = skin_dual_ggx(_e107, _e73.h, _e73.n_dot_v, _e73.n_dot_l, _e73.v_dot_h, roughness_7, _e114, f0_3);
        specular = ((_e115 * _e73.n_dot_l) * mask);
        kd = max(((1.0).xxx - _e104), (0.0).xxx);
    }
    const float3 _e125 = weft_main_light_radiance();
    float3 _e126 = kd;
    const float3 _e127 = weft_diffuse_lambert(albedo_1);
    float3 _e129 = falloff;
    float _e131 = specular;
    float3 direct = ((((_e126 * _e127) * _e129) + (_e131).xxx) * _e125);
    float3 _e135 = n;
    const float3 _e136 = weft_sh_irradiance(_e135);
    float3 _e137 = kd;
    float3 indirect_diffuse = ((_e136 * _e137) * albedo_1);
    float3 _e141 = n;
    const float3 _e143 = weft_prefiltered_radiance(reflect(-(v_3), _e141), roughness_7);
    float3 indirect_specular = ((_e143 * _e104) * mask);
    float3 color = ((direct + indirect_diffuse) + indirect_specular);
    float3 radiance = clamp(color, (0.0).xxx, (65504.0).xxx);
    return float4(radiance, alpha);
}
