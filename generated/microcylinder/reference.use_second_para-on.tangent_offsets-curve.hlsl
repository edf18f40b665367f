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
    float4 thread1_color;
    float thread1_coverage;
    float thread1_ior;
    float thread1_gamma_s;
    float thread1_gamma_v;
    float thread1_isotropy;
    int _pad6_0;
    int _pad6_1;
    int _pad6_2;
    float4 thread1_curve[9];
    float4 thread1_offsets_a;
    float4 thread1_offsets_b;
    int thread1_offset_count;
    int _pad10_0;
    int _pad10_1;
    int _pad10_2;
    float4 thread2_color;
    float thread2_coverage;
    float thread2_ior;
    float thread2_gamma_s;
    float thread2_gamma_v;
    float thread2_isotropy;
    int _pad16_0;
    int _pad16_1;
    int _pad16_2;
    float4 thread2_curve[9];
    float4 thread2_offsets_a;
    float4 thread2_offsets_b;
    int thread2_offset_count;
    float brightness;
    int _pad21_0;
    int _pad21_1;
    float4 albedo_map_st;
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

struct McThread {
    float3 albedo;
    float eta;
    float kd;
    float gamma_s;
    float gamma_v;
    int _end_pad_0;
};

struct McFrame {
    float3 u;
    int _pad1_0;
    float3 v;
    int _pad2_0;
    float3 n;
    int _end_pad_0;
};

struct McPsi {
    float3 pi;
    int _pad1_0;
    float3 pr;
    float u;
    float ok;
    int _end_pad_0;
    int _end_pad_1;
    int _end_pad_2;
};

struct McFastConst {
    float4 shape;
    float4 curve;
    float2 steps;
    int _end_pad_0;
    int _end_pad_1;
};

struct MicrocylinderVaryings {
    float4 clip_position : SV_Position;
    float3 world_position : LOC0;
    float3 world_normal : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    nointerpolation float4 thread1_shape : LOC4;
    nointerpolation float4 thread1_curve : LOC5;
    nointerpolation float2 thread1_steps : LOC6;
    nointerpolation float4 thread2_shape : LOC7;
    nointerpolation float4 thread2_curve : LOC8;
    nointerpolation float2 thread2_steps : LOC9;
    nointerpolation float2 mean_fresnel : LOC10;
};

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const uint TANGENT_OFFSETS_CURVE = 0u;
static const uint TANGENT_OFFSETS_LIST = 1u;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const uint TIER_LOW = 2u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const float WEFT_MIN_ROUGHNESS_HALF = 0.089;
static const float WEFT_MIN_N_DOT_HALF = 0.001;
static const float WEFT_MIN_ALPHA_HALF = 0.007921;
static const uint MC_CURVE_SAMPLES = 33u;
static const uint MC_CURVE_SEGMENTS = 32u;
static const int MC_MAX_OFFSETS = int(8);
static const float MC_REF_STEP_DEG = 1.0;
static const float MC_REF_MAX_SUBDIV = 64.0;
static const float MC_U_INV_TWO_SIGMA2_ = 4.1035185;
static const float MC_SQRT_TWO_PI = 2.5066283;
static const float MC_DEG = 0.017453292;
static const float MC_MIN_GAMMA = 0.0017453292;
static const float MC_MIN_PROJ2_ = 1e-8;
static const float MC_MIN_COS2_THETA_D = 0.0001;
static const float MC_MIN_Q = 1e-6;
static const float MC_INV_SQRT_TWO_PI = 0.3989423;
static const float MC_FAST_MIN_DT = 0.1;
static const float MC_GL3_T = 0.11270166;
static const float MC_GL3_W0_ = 0.2777778;
static const float MC_GL3_W1_ = 0.44444445;
static const float MC_GL3_E0_ = -0.29099444;
static const float MC_GL3_E1_ = 0.42621785;
static const float MC_FAST_BIG = 1000000.0;
static const float MC_FAST_MIN_DSLOPE = 0.0001;
static const float MC_FAST_MIN_SPAN = 0.0001;
static const float MC_FAST_SPLIT_DEG = 60.0;
static const float MC_GL2_T = 0.21132487;
static const float MC_GJ2_T = 0.31101775;
static const float MC_GL2_E = 0.36602542;
static const float MC_GJ2_E = 0.8228757;
static const float MC_GJ2_W = 0.36296296;

cbuffer weft_frame : register(b0) { WeftFrame weft_frame; }
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }
cbuffer material : register(b0, space1) { WeftMaterial material; }
SamplerState nagaSamplerHeap[2048]: register(s0, space8);
SamplerComparisonState nagaComparisonSamplerHeap[2048]: register(s0, space9);
StructuredBuffer<uint> nagaGroup1SamplerIndexArray : register(t64, space1);
#define material_sampler (nagaSamplerHeap[nagaGroup1SamplerIndexArray[1]])
Texture2D<float4> albedo_map : register(t3, space1);

struct VertexOutput_vs_microcylinder {
    float3 world_position_2 : LOC0;
    float3 world_normal_1 : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    nointerpolation float4 thread1_shape : LOC4;
    nointerpolation float4 thread1_curve : LOC5;
    nointerpolation float2 thread1_steps : LOC6;
    nointerpolation float4 thread2_shape : LOC7;
    nointerpolation float4 thread2_curve : LOC8;
    nointerpolation float2 thread2_steps : LOC9;
    nointerpolation float2 mean_fresnel : LOC10;
    float4 clip_position : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_3 : LOC0;
    float3 world_normal_2 : LOC1;
    float4 world_tangent_1 : LOC2;
    float2 uv0_1 : LOC3;
    nointerpolation float4 thread1_shape_1 : LOC4;
    nointerpolation float4 thread1_curve_1 : LOC5;
    nointerpolation float2 thread1_steps_1 : LOC6;
    nointerpolation float4 thread2_shape_1 : LOC7;
    nointerpolation float4 thread2_curve_1 : LOC8;
    nointerpolation float2 thread2_steps_1 : LOC9;
    nointerpolation float2 mean_fresnel_1 : LOC10;
    float4 clip_position_1 : SV_Position;
};

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

float weft_f_dielectric(float cos_i, float eta)
{
    float c = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c * c));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c);
    float gpc = max((g + c), 1e-7);
    float b_den = max(((c * gmc) + 1.0), 1e-7);
    float b_num = ((c * gpc) - 1.0);
    float inv = (1.0 / (gpc * b_den));
    float f = saturate(((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)));
    return ((g2_ < 0.0) ? 1.0 : f);
}

float weft_f0_from_ior(float ior)
{
    float q = ((ior - 1.0) / max((ior + 1.0), 0.0001));
    return (q * q);
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

float2 weft_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

float mc_gauss(float gamma, float x)
{
    float g_1 = max(gamma, MC_MIN_GAMMA);
    return (exp(((-(x) * x) / ((2.0 * g_1) * g_1))) / (MC_SQRT_TWO_PI * g_1));
}

float mc_correlate(float ci, float cr, float u)
{
    float mi = max(ci, 0.0);
    float mr = max(cr, 0.0);
    return ((((1.0 - u) * mi) * mr) + (u * min(mi, mr)));
}

McPsi ConstructMcPsi(float3 arg0, float3 arg1, float arg2, float arg3) {
    McPsi ret = (McPsi)0;
    ret.pi = arg0;
    ret.pr = arg1;
    ret.u = arg2;
    ret.ok = arg3;
    return ret;
}

McPsi mc_psi_reference(float3 v_1, float3 wi, float3 wr)
{
    float3 pi = (wi - (v_1 * dot(wi, v_1)));
    float3 pr = (wr - (v_1 * dot(wr, v_1)));
    float li2_ = dot(pi, pi);
    float lr2_ = dot(pr, pr);
    bool ok_1 = (min(li2_, lr2_) >= MC_MIN_PROJ2_);
    float3 hi = (pi * rsqrt(max(li2_, MC_MIN_PROJ2_)));
    float3 hr = (pr * rsqrt(max(lr2_, MC_MIN_PROJ2_)));
    float psi_d = atan2(length(cross(hi, hr)), dot(hi, hr));
    float u_1 = exp(((-(psi_d) * psi_d) * MC_U_INV_TWO_SIGMA2_));
    const McPsi mcpsi = ConstructMcPsi(hi, hr, u_1, (ok_1 ? 1.0 : 0.0));
    return mcpsi;
}

float4 mc_lobe_reference(McFrame fr, McPsi psi, float3 wi_1, float3 wr_1, float ca, float sa, McThread th)
{
    bool local = (bool)0;

    float3 u_2 = ((fr.u * ca) + (fr.n * sa));
    float3 np = ((fr.n * ca) - (fr.u * sa));
    float si = clamp(dot(wi_1, u_2), -1.0, 1.0);
    float sr = clamp(dot(wr_1, u_2), -1.0, 1.0);
    float3 pi_1 = (wi_1 - (u_2 * si));
    float3 pr_1 = (wr_1 - (u_2 * sr));
    float ci2_ = dot(pi_1, pi_1);
    float cr2_ = dot(pr_1, pr_1);
    if (!((min(ci2_, cr2_) < MC_MIN_PROJ2_))) {
        local = (psi.ok == 0.0);
    } else {
        local = true;
    }
    bool _e41 = local;
    if (_e41) {
        return (0.0).xxxx;
    }
    float ci_1 = sqrt(ci2_);
    float cr_1 = sqrt(cr2_);
    float3 hi_1 = (pi_1 / (ci_1).xxx);
    float3 hr_1 = (pr_1 / (cr_1).xxx);
    float theta_i = atan2(si, ci_1);
    float theta_r = atan2(sr, cr_1);
    float theta_h = (0.5 * (theta_i + theta_r));
    float theta_d = (0.5 * (theta_i - theta_r));
    float phi_d = atan2(length(cross(hi_1, hr_1)), dot(hi_1, hr_1));
    float cos_half_phi = cos((0.5 * phi_d));
    float u_phi = exp(((-(phi_d) * phi_d) * MC_U_INV_TWO_SIGMA2_));
    const float _e72 = mc_correlate(dot(np, hi_1), dot(np, hr_1), u_phi);
    const float _e78 = mc_correlate(dot(np, psi.pi), dot(np, psi.pr), psi.u);
    float cd = cos(theta_d);
    float cd2_ = max((cd * cd), MC_MIN_COS2_THETA_D);
    const float _e85 = weft_f_dielectric((cd * cos_half_phi), th.eta);
    const float _e88 = mc_gauss(th.gamma_s, theta_h);
    float surface = ((_e85 * cos_half_phi) * _e88);
    const float _e91 = weft_f_dielectric(ci_1, th.eta);
    const float _e95 = weft_f_dielectric(cr_1, th.eta);
    float f_t = ((1.0 - _e91) * (1.0 - _e95));
    const float _e103 = mc_gauss(th.gamma_v, theta_h);
    float volume = ((f_t * (((1.0 - th.kd) * _e103) + th.kd)) / (ci_1 + cr_1));
    float3 fs = (((surface).xxx + (volume * th.albedo)) / (cd2_).xxx);
    return float4((fs * ((_e72 * _e78) * ci_1)), _e78);
}

uint naga_div(uint lhs, uint rhs) {
    return lhs / (rhs == 0u ? 1u : rhs);
}

uint naga_mod(uint lhs, uint rhs) {
    return lhs % (rhs == 0u ? 1u : rhs);
}

float mc_curve_at(float4 h[9], uint i)
{
    return h[min(uint(naga_div(i, 4u)), 8u)][min(uint(naga_mod(i, 4u)), 3u)];
}

float4 mc_thread_curve_reference(McFrame fr_1, float3 wi_2, float3 wr_2, McThread th_1, float4 heights[9])
{
    float4 acc = (0.0).xxxx;
    float wsum = 0.0;
    uint k = 0u;

    const McPsi _e6 = mc_psi_reference(fr_1.v, wi_2, wr_2);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            uint _e38 = k;
            k = (_e38 + 1u);
        }
        loop_init = false;
        uint _e15 = k;
        if ((_e15 < MC_CURVE_SEGMENTS)) {
        } else {
            break;
        }
        {
            uint _e18 = k;
            const float _e21 = mc_curve_at(heights, (_e18 + 1u));
            uint _e22 = k;
            const float _e23 = mc_curve_at(heights, _e22);
            float dh = (_e21 - _e23);
            float len = sqrt(((0.03125 * 0.03125) + (dh * dh)));
            float4 _e29 = acc;
            const float4 _e32 = mc_lobe_reference(fr_1, _e6, wi_2, wr_2, (0.03125 / len), (dh / len), th_1);
            acc = (_e29 + (len * _e32));
            float _e35 = wsum;
            wsum = (_e35 + len);
        }
    }
    float4 _e40 = acc;
    float _e41 = wsum;
    return (_e40 / (_e41).xxxx);
}

float3 mc_combine(float4 t1_, float4 t2_, float a1_, float a2_, float n_dot_wi, float n_dot_wr)
{
    bool local_1 = (bool)0;
    bool local_2 = (bool)0;

    float c1_ = saturate(a1_);
    float c2_ = saturate(a2_);
    float gap = max(((1.0 - c1_) - c2_), 0.0);
    float q_1 = (((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * max(n_dot_wi, 0.0)));
    float3 s_2 = max(((c1_ * t1_.xyz) + (c2_ * t2_.xyz)), (0.0).xxx);
    if ((n_dot_wi > 0.0)) {
        local_1 = (n_dot_wr > 0.0);
    } else {
        local_1 = false;
    }
    bool _e37 = local_1;
    if (_e37) {
        local_2 = (q_1 > MC_MIN_Q);
    } else {
        local_2 = false;
    }
    bool lit_ = local_2;
    return (lit_ ? (s_2 / (max(q_1, MC_MIN_Q)).xxx) : (0.0).xxx);
}

McThread ConstructMcThread(float3 arg0, float arg1, float arg2, float arg3, float arg4) {
    McThread ret = (McThread)0;
    ret.albedo = arg0;
    ret.eta = arg1;
    ret.kd = arg2;
    ret.gamma_s = arg3;
    ret.gamma_v = arg4;
    return ret;
}

McThread microcylinder_thread(float3 color, float ior_1, float isotropy, float gamma_s_deg, float gamma_v_deg, float3 tint)
{
    const McThread mcthread = ConstructMcThread(saturate((color * tint)), clamp(ior_1, 1.0, 4.0), saturate(isotropy), (max(gamma_s_deg, 0.0) * MC_DEG), (max(gamma_v_deg, 0.0) * MC_DEG));
    return mcthread;
}

float microcylinder_mean_fresnel(float eta_1)
{
    const float _e1 = weft_f0_from_ior(eta_1);
    return (_e1 + ((1.0 - _e1) / 21.0));
}

McFastConst ZeroValueMcFastConst() {
    return (McFastConst)0;
}

McFastConst microcylinder_fast_const(McThread th_2, float4 heights_1[9])
{
    McFastConst k_1 = ZeroValueMcFastConst();

    McFastConst _e4 = k_1;
    const McFastConst mcfastconst = _e4;
    return mcfastconst;
}

MicrocylinderVaryings ConstructMicrocylinderVaryings(float4 arg0, float3 arg1, float3 arg2, float4 arg3, float2 arg4, float4 arg5, float4 arg6, float2 arg7, float4 arg8, float4 arg9, float2 arg10, float2 arg11) {
    MicrocylinderVaryings ret = (MicrocylinderVaryings)0;
    ret.clip_position = arg0;
    ret.world_position = arg1;
    ret.world_normal = arg2;
    ret.world_tangent = arg3;
    ret.uv0_ = arg4;
    ret.thread1_shape = arg5;
    ret.thread1_curve = arg6;
    ret.thread1_steps = arg7;
    ret.thread2_shape = arg8;
    ret.thread2_curve = arg9;
    ret.thread2_steps = arg10;
    ret.mean_fresnel = arg11;
    return ret;
}

VertexOutput_vs_microcylinder vs_microcylinder(WeftVertexInput in_)
{
    McFastConst k2_ = ZeroValueMcFastConst();

    const WeftVaryings _e1 = weft_forward_vertex(in_);
    float4 _e4 = material.thread1_color;
    float _e8 = material.thread1_ior;
    float _e11 = material.thread1_isotropy;
    float _e14 = material.thread1_gamma_s;
    float _e17 = material.thread1_gamma_v;
    const McThread _e20 = microcylinder_thread(_e4.xyz, _e8, _e11, _e14, _e17, (1.0).xxx);
    float4 _e23 = material.thread2_color;
    float _e27 = material.thread2_ior;
    float _e30 = material.thread2_isotropy;
    float _e33 = material.thread2_gamma_s;
    float _e36 = material.thread2_gamma_v;
    const McThread _e39 = microcylinder_thread(_e23.xyz, _e27, _e30, _e33, _e36, (1.0).xxx);
    float4 _e42[9] = material.thread1_curve;
    const McFastConst _e43 = microcylinder_fast_const(_e20, _e42);
    {
        float4 _e48[9] = material.thread2_curve;
        const McFastConst _e49 = microcylinder_fast_const(_e39, _e48);
        k2_ = _e49;
    }
    float4 _e59 = k2_.shape;
    float4 _e61 = k2_.curve;
    float2 _e63 = k2_.steps;
    const float _e65 = microcylinder_mean_fresnel(_e20.eta);
    const float _e67 = microcylinder_mean_fresnel(_e39.eta);
    const MicrocylinderVaryings microcylindervaryings = ConstructMicrocylinderVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, _e43.shape, _e43.curve, _e43.steps, _e59, _e61, _e63, float2(_e65, _e67));
    const VertexOutput_vs_microcylinder microcylindervaryings_1 = { microcylindervaryings.world_position, microcylindervaryings.world_normal, microcylindervaryings.world_tangent, microcylindervaryings.uv0_, microcylindervaryings.thread1_shape, microcylindervaryings.thread1_curve, microcylindervaryings.thread1_steps, microcylindervaryings.thread2_shape, microcylindervaryings.thread2_curve, microcylindervaryings.thread2_steps, microcylindervaryings.mean_fresnel, microcylindervaryings.clip_position };
    return microcylindervaryings_1;
}

McFrame ConstructMcFrame(float3 arg0, float3 arg1, float3 arg2) {
    McFrame ret = (McFrame)0;
    ret.u = arg0;
    ret.v = arg1;
    ret.n = arg2;
    return ret;
}

float4 fs_main(FragmentInput_fs_main fragmentinput_fs_main) : SV_Target0
{
    MicrocylinderVaryings in_1 = { fragmentinput_fs_main.clip_position_1, fragmentinput_fs_main.world_position_3, fragmentinput_fs_main.world_normal_2, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_1, fragmentinput_fs_main.thread1_shape_1, fragmentinput_fs_main.thread1_curve_1, fragmentinput_fs_main.thread1_steps_1, fragmentinput_fs_main.thread2_shape_1, fragmentinput_fs_main.thread2_curve_1, fragmentinput_fs_main.thread2_steps_1, fragmentinput_fs_main.mean_fresnel_1 };
    float4 s1_ = (0.0).xxxx;
    float4 s2_ = (0.0).xxxx;

    float4 _e4 = material.albedo_map_st;
    const float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    float4 _e8 = albedo_map.Sample(material_sampler, _e5);
    float3 tint_1 = max(_e8.xyz, (0.0).xxx);
    float4 _e15 = material.thread1_color;
    float _e19 = material.thread1_ior;
    float _e22 = material.thread1_isotropy;
    float _e25 = material.thread1_gamma_s;
    float _e28 = material.thread1_gamma_v;
    const McThread _e29 = microcylinder_thread(_e15.xyz, _e19, _e22, _e25, _e28, tint_1);
    float4 _e32 = material.thread2_color;
    float _e36 = material.thread2_ior;
    float _e39 = material.thread2_isotropy;
    float _e42 = material.thread2_gamma_s;
    float _e45 = material.thread2_gamma_v;
    const McThread _e46 = microcylinder_thread(_e32.xyz, _e36, _e39, _e42, _e45, tint_1);
    float _e49 = material.thread1_coverage;
    float a1_1 = saturate(_e49);
    float _e53 = material.thread2_coverage;
    float a2_1 = (true ? saturate(_e53) : 0.0);
    float _e60 = material.brightness;
    float brightness = max(_e60, 0.0);
    const WeftSurface _e65 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_raw = _e65.v;
    float3 n_3 = _e65.n;
    const float3x3 _e69 = weft_tangent_frame(n_3, in_1.world_tangent);
    float3 t_1 = _e69[0];
    float3 b_2 = _e69[1];
    const float3 _e79 = weft_safe_normalize((v_raw + (n_3 * max((0.001 - dot(n_3, v_raw)), 0.0))), n_3);
    const float3 _e80 = weft_main_light_direction();
    McFrame warp = ConstructMcFrame(t_1, b_2, n_3);
    McFrame weft = ConstructMcFrame(b_2, t_1, n_3);
    {
        {
            float4 _e91[9] = material.thread1_curve;
            const float4 _e92 = mc_thread_curve_reference(warp, _e80, _e79, _e29, _e91);
            s1_ = _e92;
            {
                float4 _e95[9] = material.thread2_curve;
                const float4 _e96 = mc_thread_curve_reference(weft, _e80, _e79, _e46, _e95);
                s2_ = _e96;
            }
        }
    }
    float4 _e97 = s1_;
    float4 _e98 = s2_;
    const float3 _e101 = mc_combine(_e97, _e98, a1_1, a2_1, dot(n_3, _e80), dot(n_3, _e79));
    const float3 _e102 = weft_main_light_radiance();
    float3 direct = (_e101 * _e102);
    float3 amb1_ = (_e29.albedo + (in_1.mean_fresnel.x).xxx);
    float3 amb2_ = (_e46.albedo + (in_1.mean_fresnel.y).xxx);
    float cov = (a1_1 + a2_1);
    float3 ambient_albedo = ((cov > 0.0001) ? (((a1_1 * amb1_) + (a2_1 * amb2_)) / (max(cov, 0.0001)).xxx) : amb1_);
    const float3 _e125 = weft_sh_irradiance(n_3);
    float3 ambient = (_e125 * ambient_albedo);
    float3 radiance = clamp(((direct + ambient) * brightness), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
