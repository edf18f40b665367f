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

struct McFastPre {
    float3 wi;
    int _pad1_0;
    float3 wr;
    float inv_ri;
    float inv_rr;
    float u_psi;
    float ok;
    float inv_gamma_s;
    float inv_gamma_v;
    float s_lo;
    float s_hi;
    float eta;
};

struct McFastNode {
    float x;
    float s;
    float v;
    float p;
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

float2 weft_select2_f32bit(bool2 weft_sel_c, float2 weft_sel_a, float2 weft_sel_b)
{
    return float2((weft_sel_c.x ? weft_sel_a.x : weft_sel_b.x), (weft_sel_c.y ? weft_sel_a.y : weft_sel_b.y));
}

int3 weft_select3_i32bit(bool3 weft_sel_c_1, int3 weft_sel_a_1, int3 weft_sel_b_1)
{
    return int3((weft_sel_c_1.x ? weft_sel_a_1.x : weft_sel_b_1.x), (weft_sel_c_1.y ? weft_sel_a_1.y : weft_sel_b_1.y), (weft_sel_c_1.z ? weft_sel_a_1.z : weft_sel_b_1.z));
}

float3 weft_select3_f32bit(bool3 weft_sel_c_2, float3 weft_sel_a_2, float3 weft_sel_b_2)
{
    return float3((weft_sel_c_2.x ? weft_sel_a_2.x : weft_sel_b_2.x), (weft_sel_c_2.y ? weft_sel_a_2.y : weft_sel_b_2.y), (weft_sel_c_2.z ? weft_sel_a_2.z : weft_sel_b_2.z));
}

int4 weft_select4_i32bit(bool4 weft_sel_c_3, int4 weft_sel_a_3, int4 weft_sel_b_3)
{
    return int4((weft_sel_c_3.x ? weft_sel_a_3.x : weft_sel_b_3.x), (weft_sel_c_3.y ? weft_sel_a_3.y : weft_sel_b_3.y), (weft_sel_c_3.z ? weft_sel_a_3.z : weft_sel_b_3.z), (weft_sel_c_3.w ? weft_sel_a_3.w : weft_sel_b_3.w));
}

float4 weft_select4_f32bit(bool4 weft_sel_c_4, float4 weft_sel_a_4, float4 weft_sel_b_4)
{
    return float4((weft_sel_c_4.x ? weft_sel_a_4.x : weft_sel_b_4.x), (weft_sel_c_4.y ? weft_sel_a_4.y : weft_sel_b_4.y), (weft_sel_c_4.z ? weft_sel_a_4.z : weft_sel_b_4.z), (weft_sel_c_4.w ? weft_sel_a_4.w : weft_sel_b_4.w));
}

float3 weft_safe_normalize(float3 v, float3 fallback)
{
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * rsqrt(max(len2_, 1e-20))) : fallback);
}

float3 weft_any_perpendicular(float3 n)
{
    float s = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a_1 = (-1.0 / (s + n.z));
    float b_1 = ((n.x * n.y) * a_1);
    return float3((1.0 + (((s * n.x) * n.x) * a_1)), (s * b_1), (-(s) * n.x));
}

float weft_f0_from_ior(float ior)
{
    float q_3 = ((ior - 1.0) / max((ior + 1.0), 0.0001));
    return (q_3 * q_3);
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
    float3 t_1 = (ok ? (t_proj * rsqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_2 = (cross(n_2, t_1) * s_1);
    return float3x3(t_1, b_2, n_2);
}

float2 weft_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

float weft_half_f_dielectric(float cos_i, float eta)
{
    float c = clamp(abs(cos_i), 0.001, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c * c));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c);
    float gpc = max((g + c), 0.001);
    float a_2 = (gmc / gpc);
    float b_3 = (((c * gpc) - 1.0) / max(((c * gmc) + 1.0), 0.001));
    float f = saturate((((0.5 * a_2) * a_2) * (1.0 + (b_3 * b_3))));
    return ((g2_ < 0.0) ? 1.0 : f);
}

float2 weft_half_f_dielectric2_(float2 cos_i_1, float eta_1)
{
    float2 c_1 = clamp(abs(cos_i_1), (0.001).xx, (1.0).xx);
    float2 g2_1 = ((((eta_1 * eta_1) - 1.0)).xx + (c_1 * c_1));
    float2 g_1 = sqrt(max(g2_1, (0.0).xx));
    float2 gmc_1 = (g_1 - c_1);
    float2 gpc_1 = max((g_1 + c_1), (0.001).xx);
    float2 a_3 = (gmc_1 / gpc_1);
    float2 b_4 = (((c_1 * gpc_1) - (1.0).xx) / max(((c_1 * gmc_1) + (1.0).xx), (0.001).xx));
    float2 f_1 = saturate((((0.5 * a_3) * a_3) * ((1.0).xx + (b_4 * b_4))));
    const float2 _e50 = weft_select2_f32bit((g2_1 < (0.0).xx), (1.0).xx, f_1);
    return _e50;
}

float mc_acos_fast(float x)
{
    float ax = min(abs(x), 1.0);
    float r_1 = (sqrt((1.0 - ax)) * (1.5707288 + (ax * (-0.2121144 + (ax * (0.074261 - (0.0187293 * ax)))))));
    return ((x < 0.0) ? (WEFT_PI - r_1) : r_1);
}

float mc_asin_fast(float x_1)
{
    const float _e2 = mc_acos_fast(x_1);
    return (1.5707964 - _e2);
}

float mc_offset_at(float4 a, float4 b, int k)
{
    return ((k >= int(4)) ? b : a)[min(uint((k & int(3))), 3u)];
}

float3 mc_combine(float4 t1_, float4 t2_, float a1_, float a2_, float n_dot_wi, float n_dot_wr)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;

    float c1_ = saturate(a1_);
    float c2_ = saturate(a2_);
    float gap = max(((1.0 - c1_) - c2_), 0.0);
    float q_4 = (((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * max(n_dot_wi, 0.0)));
    float3 s_2 = max(((c1_ * t1_.xyz) + (c2_ * t2_.xyz)), (0.0).xxx);
    if ((n_dot_wi > 0.0)) {
        local = (n_dot_wr > 0.0);
    } else {
        local = false;
    }
    bool _e37 = local;
    if (_e37) {
        local_1 = (q_4 > MC_MIN_Q);
    } else {
        local_1 = false;
    }
    bool lit_ = local_1;
    return (lit_ ? (s_2 / (max(q_4, MC_MIN_Q)).xxx) : (0.0).xxx);
}

typedef float4 ret_Constructarray2_float4_[2];
ret_Constructarray2_float4_ Constructarray2_float4_(float4 arg0, float4 arg1) {
    float4 ret[2] = { arg0, arg1 };
    return ret;
}

typedef float4 ret_mc_normal4_[2];
ret_mc_normal4_ mc_normal4_(float4 t)
{
    float4 e_1 = exp(((-0.5 * t) * t));
    float4 z = (abs(t) * 0.70710677);
    float4 k_6 = ((1.0).xxxx / ((1.0).xxxx + (0.3275911 * z)));
    float4 poly = (k_6 * ((0.2548296).xxxx + (k_6 * ((-0.28449672).xxxx + (k_6 * ((1.4214138).xxxx + (k_6 * ((-1.4531521).xxxx + (k_6 * 1.0614054)))))))));
    float4 half_ = ((0.5).xxxx - ((0.5 * poly) * e_1));
    const float4 _e46 = weft_select4_f32bit((t >= (0.0).xxxx), half_, -(half_));
    return Constructarray2_float4_((e_1 * MC_INV_SQRT_TWO_PI), _e46);
}

float3 mc_cell_means(float4 xe, float inv_gamma)
{
    float4 t_2 = (xe * inv_gamma);
    const float4 _e3[2] = mc_normal4_(t_2);
    float3 dt = (t_2.yzw - t_2.xyz);
    bool3 wide = (abs(dt) >= (0.1).xxx);
    const float3 _e18 = weft_select3_f32bit(wide, dt, (1.0).xxx);
    float3 exact = ((_e3[1].yzw - _e3[1].xyz) / _e18);
    float3 trap = (0.5 * (_e3[0].xyz + _e3[0].yzw));
    const float3 _e27 = weft_select3_f32bit(wide, exact, trap);
    return (max(_e27, (0.0).xxx) * inv_gamma);
}

McFastPre ConstructMcFastPre(float3 arg0, float3 arg1, float arg2, float arg3, float arg4, float arg5, float arg6, float arg7, float arg8, float arg9, float arg10) {
    McFastPre ret = (McFastPre)0;
    ret.wi = arg0;
    ret.wr = arg1;
    ret.inv_ri = arg2;
    ret.inv_rr = arg3;
    ret.u_psi = arg4;
    ret.ok = arg5;
    ret.inv_gamma_s = arg6;
    ret.inv_gamma_v = arg7;
    ret.s_lo = arg8;
    ret.s_hi = arg9;
    ret.eta = arg10;
    return ret;
}

McFastPre mc_fast_pre(McFrame fr, float3 wi, float3 wr, McThread th)
{
    float3 li = float3(dot(wi, fr.u), dot(wi, fr.v), dot(wi, fr.n));
    float3 lr = float3(dot(wr, fr.u), dot(wr, fr.v), dot(wr, fr.n));
    float ri2_ = ((li.x * li.x) + (li.z * li.z));
    float rr2_ = ((lr.x * lr.x) + (lr.z * lr.z));
    bool ok_1 = (min(ri2_, rr2_) >= MC_MIN_PROJ2_);
    float inv_ri = rsqrt(max(ri2_, MC_MIN_PROJ2_));
    float inv_rr = rsqrt(max(rr2_, MC_MIN_PROJ2_));
    float cos_psi_d = ((((li.x * lr.x) + (li.z * lr.z)) * inv_ri) * inv_rr);
    const float _e50 = mc_acos_fast(cos_psi_d);
    float u_psi = exp(((-(_e50) * _e50) * MC_U_INV_TWO_SIGMA2_));
    float bi = (li.z / ((li.x < 0.0) ? min(li.x, -1e-12) : max(li.x, 1e-12)));
    float br = (lr.z / ((lr.x < 0.0) ? min(lr.x, -1e-12) : max(lr.x, 1e-12)));
    float s_lo = max(((li.x < 0.0) ? bi : -1000000.0), ((lr.x < 0.0) ? br : -1000000.0));
    float s_hi = min(((li.x > 0.0) ? bi : MC_FAST_BIG), ((lr.x > 0.0) ? br : MC_FAST_BIG));
    const McFastPre mcfastpre = ConstructMcFastPre(li, lr, inv_ri, inv_rr, u_psi, (ok_1 ? 1.0 : 0.0), (1.0 / max(th.gamma_s, MC_MIN_GAMMA)), (1.0 / max(th.gamma_v, MC_MIN_GAMMA)), clamp(s_lo, -1000000.0, MC_FAST_BIG), clamp(s_hi, -1000000.0, MC_FAST_BIG), th.eta);
    return mcfastpre;
}

float4 mc_fast_gl3_(McFastPre q, McThread th_1, McFastNode n0_, McFastNode n1_, McFastNode n2_, float3 r)
{
    float4 xe_1 = float4((n0_.x + (MC_GL3_E0_ * (n1_.x - n0_.x))), (n0_.x + (MC_GL3_E1_ * (n1_.x - n0_.x))), (n2_.x - (MC_GL3_E1_ * (n2_.x - n1_.x))), (n2_.x - (MC_GL3_E0_ * (n2_.x - n1_.x))));
    const float3 _e36 = mc_cell_means(xe_1, q.inv_gamma_s);
    const float3 _e38 = mc_cell_means(xe_1, q.inv_gamma_v);
    float3 s_3 = (r * float3(n0_.s, n1_.s, n2_.s));
    float3 v_1 = (r * float3(n0_.v, n1_.v, n2_.v));
    float surface = dot(_e36, s_3);
    float volume = (((1.0 - th_1.kd) * dot(_e38, v_1)) + (th_1.kd * ((v_1.x + v_1.y) + v_1.z)));
    return float4(((surface).xxx + (volume * th_1.albedo)), dot(r, float3(n0_.p, n1_.p, n2_.p)));
}

McFastNode ConstructMcFastNode(float arg0, float arg1, float arg2, float arg3) {
    McFastNode ret = (McFastNode)0;
    ret.x = arg0;
    ret.s = arg1;
    ret.v = arg2;
    ret.p = arg3;
    return ret;
}

McFastNode mc_low_node(McFastPre q_1, float ca, float sa)
{
    bool local_2 = (bool)0;

    float si = clamp(((q_1.wi.x * ca) + (q_1.wi.z * sa)), -1.0, 1.0);
    float sr = clamp(((q_1.wr.x * ca) + (q_1.wr.z * sa)), -1.0, 1.0);
    float ni = ((q_1.wi.z * ca) - (q_1.wi.x * sa));
    float nr = ((q_1.wr.z * ca) - (q_1.wr.x * sa));
    float ci2_ = ((q_1.wi.y * q_1.wi.y) + (ni * ni));
    float cr2_ = ((q_1.wr.y * q_1.wr.y) + (nr * nr));
    if ((min(ci2_, cr2_) >= MC_MIN_PROJ2_)) {
        local_2 = (q_1.ok != 0.0);
    } else {
        local_2 = false;
    }
    bool ok_2 = local_2;
    float inv_ci = rsqrt(max(ci2_, MC_MIN_PROJ2_));
    float inv_cr = rsqrt(max(cr2_, MC_MIN_PROJ2_));
    float ci_f = (ci2_ * inv_ci);
    float cr_f = (cr2_ * inv_cr);
    float cos_phi_d = clamp(((((q_1.wi.y * q_1.wr.y) + (ni * nr)) * inv_ci) * inv_cr), -1.0, 1.0);
    const float _e81 = mc_acos_fast(cos_phi_d);
    float u_phi = exp(((-(_e81) * _e81) * MC_U_INV_TWO_SIGMA2_));
    const float _e87 = mc_asin_fast(si);
    const float _e88 = mc_asin_fast(sr);
    float x_2 = (0.5 * (_e87 + _e88));
    float ci = float(ci_f);
    float cr = float(cr_f);
    float eta_3 = float(q_1.eta);
    float cos_half_phi = sqrt((0.5 + (0.5 * float(cos_phi_d))));
    float2 at_i = max(float2(float2((ni * inv_ci), (ni * q_1.inv_ri))), (0.0).xx);
    float2 at_r = max(float2(float2((nr * inv_cr), (nr * q_1.inv_rr))), (0.0).xx);
    float2 blend = float2(float2(u_phi, q_1.u_psi));
    float2 mask = (((((1.0).xx - blend) * at_i) * at_r) + (blend * min(at_i, at_r)));
    float m = mask.x;
    float p = mask.y;
    float cd2_ = max((0.5 + (0.5 * float(((ci_f * cr_f) + (si * sr))))), 0.0001);
    const float _e143 = weft_half_f_dielectric((sqrt(cd2_) * cos_half_phi), eta_3);
    const float2 _e145 = weft_half_f_dielectric2_(float2(ci, cr), eta_3);
    float f_t = ((1.0 - _e145.x) * (1.0 - _e145.y));
    float mp = ((m * p) / cd2_);
    float s_4 = (((_e143 * cos_half_phi) * mp) * ci);
    float v_2 = ((f_t * mp) * (ci / max((ci + cr), 0.0002)));
    const McFastNode mcfastnode = ConstructMcFastNode(x_2, (ok_2 ? float(s_4) : 0.0), (ok_2 ? float(v_2) : 0.0), (ok_2 ? float(p) : 0.0));
    return mcfastnode;
}

float4 mc_low_segment(McFastPre q_2, McThread th_2, float a0_, float a1_1, float lo_s, float hi_s)
{
    float span = abs((a1_1 - a0_));
    bool flat = (span < MC_FAST_MIN_SPAN);
    float lo = clamp(lo_s, min(a0_, a1_1), max(a0_, a1_1));
    float hi = clamp(hi_s, lo, max(a0_, a1_1));
    float w = (hi - lo);
    float3 al = float3((lo + (MC_GL3_T * w)), (lo + (0.5 * w)), (hi - (MC_GL3_T * w)));
    float3 ca_1 = cos(al);
    float3 sa_1 = sin(al);
    const McFastNode _e30 = mc_low_node(q_2, ca_1.x, sa_1.x);
    const McFastNode _e33 = mc_low_node(q_2, ca_1.y, sa_1.y);
    const McFastNode _e36 = mc_low_node(q_2, ca_1.z, sa_1.z);
    float3 r_2 = (float3(0.2777778, 0.44444445, 0.2777778) * (flat ? 1.0 : (w / max(span, MC_FAST_MIN_SPAN))));
    const float4 _e47 = mc_fast_gl3_(q_2, th_2, _e30, _e33, _e36, r_2);
    return _e47;
}

int mc_list_piece_count(float4 offsets_a, float4 offsets_b, int n_3)
{
    float4 spans = abs((float4(offsets_a.yzw, offsets_b.x) - offsets_a));
    float3 spans_b = abs((offsets_b.yzw - offsets_b.xyz));
    bool4 live = (int4(int(0), int(1), int(2), int(3)) < (asint(asuint(n_3) - asuint(int(1)))).xxxx);
    bool3 live_b = (int3(int(4), int(5), int(6)) < (asint(asuint(n_3) - asuint(int(1)))).xxx);
    const int4 _e38 = weft_select4_i32bit((spans > (60.0).xxxx), (int(2)).xxxx, (int(1)).xxxx);
    const int4 _e39 = weft_select4_i32bit(live, _e38, (int(0)).xxxx);
    const int3 _e49 = weft_select3_i32bit((spans_b > (60.0).xxx), (int(2)).xxx, (int(1)).xxx);
    const int3 _e50 = weft_select3_i32bit(live_b, _e49, (int(0)).xxx);
    return max(asint(asuint(asint(asuint(asint(asuint(asint(asuint(asint(asuint(asint(asuint(_e39.x) + asuint(_e39.y))) + asuint(_e39.z))) + asuint(_e39.w))) + asuint(_e50.x))) + asuint(_e50.y))) + asuint(_e50.z)), int(1));
}

int mc_fast_pieces(float4 offsets_a_1, float4 offsets_b_1, int k_1)
{
    const float _e5 = mc_offset_at(offsets_a_1, offsets_b_1, asint(asuint(k_1) + asuint(int(1))));
    const float _e6 = mc_offset_at(offsets_a_1, offsets_b_1, k_1);
    float span_1 = abs((_e5 - _e6));
    return ((span_1 > MC_FAST_SPLIT_DEG) ? int(2) : int(1));
}

float3 mc_list_piece(float4 offsets_a_2, float4 offsets_b_2, int n_4, int k_2, int h)
{
    const float _e5 = mc_offset_at(offsets_a_2, offsets_b_2, k_2);
    float d0_ = (_e5 * MC_DEG);
    const float _e10 = mc_offset_at(offsets_a_2, offsets_b_2, asint(asuint(k_2) + asuint(int(1))));
    float d1_ = ((n_4 > int(1)) ? (_e10 * MC_DEG) : d0_);
    const int _e16 = mc_fast_pieces(offsets_a_2, offsets_b_2, k_2);
    float fm = float(((n_4 > int(1)) ? _e16 : int(1)));
    return float3(lerp(d0_, d1_, (float(h) / fm)), lerp(d0_, d1_, (float(asint(asuint(h) + asuint(int(1)))) / fm)), (1.0 / fm));
}

int2 mc_list_next(float4 offsets_a_3, float4 offsets_b_3, int n_5, int k_3, int h_1)
{
    const int _e5 = mc_fast_pieces(offsets_a_3, offsets_b_3, k_3);
    int m_1 = ((n_5 > int(1)) ? _e5 : int(1));
    int next = asint(asuint(h_1) + asuint(int(1)));
    return ((next >= m_1) ? int2(asint(asuint(k_3) + asuint(int(1))), int(0)) : int2(k_3, next));
}

float4 mc_thread_list_low(McFrame fr_1, float3 wi_1, float3 wr_1, McThread th_3, float4 offsets_a_4, float4 offsets_b_4, int count)
{
    float4 acc = (0.0).xxxx;
    int k_4 = int(0);
    int h_2 = int(0);
    int i = int(0);

    int n_6 = clamp(count, int(1), MC_MAX_OFFSETS);
    const McFastPre _e10 = mc_fast_pre(fr_1, wi_1, wr_1, th_3);
    float lo_s_1 = atan(_e10.s_lo);
    float hi_s_1 = atan(_e10.s_hi);
    int segments = max(asint(asuint(n_6) - asuint(int(1))), int(1));
    const int _e19 = mc_list_piece_count(offsets_a_4, offsets_b_4, n_6);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            int _e47 = i;
            i = asint(asuint(_e47) + asuint(int(1)));
        }
        loop_init = false;
        int _e29 = i;
        if ((_e29 < _e19)) {
        } else {
            break;
        }
        {
            int _e31 = k_4;
            int _e32 = h_2;
            const float3 _e33 = mc_list_piece(offsets_a_4, offsets_b_4, n_6, _e31, _e32);
            float4 _e34 = acc;
            const float4 _e37 = mc_low_segment(_e10, th_3, _e33.x, _e33.y, lo_s_1, hi_s_1);
            acc = (_e34 + (_e37 * _e33.z));
            int _e41 = k_4;
            int _e42 = h_2;
            const int2 _e43 = mc_list_next(offsets_a_4, offsets_b_4, n_6, _e41, _e42);
            k_4 = _e43.x;
            h_2 = _e43.y;
        }
    }
    float4 _e49 = acc;
    return (_e49 / (float(segments)).xxxx);
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

float microcylinder_mean_fresnel(float eta_2)
{
    const float _e1 = weft_f0_from_ior(eta_2);
    return (_e1 + ((1.0 - _e1) / 21.0));
}

McFastConst ZeroValueMcFastConst() {
    return (McFastConst)0;
}

McFastConst microcylinder_fast_const(McThread th_4, float4 heights[9])
{
    McFastConst k_5 = ZeroValueMcFastConst();

    McFastConst _e4 = k_5;
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
    float a1_2 = saturate(_e49);
    float _e53 = material.thread2_coverage;
    float a2_1 = (true ? saturate(_e53) : 0.0);
    float _e60 = material.brightness;
    float brightness = max(_e60, 0.0);
    const WeftSurface _e65 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_raw = _e65.v;
    float3 n_7 = _e65.n;
    const float3x3 _e69 = weft_tangent_frame(n_7, in_1.world_tangent);
    float3 t_3 = _e69[0];
    float3 b_5 = _e69[1];
    const float3 _e79 = weft_safe_normalize((v_raw + (n_7 * max((0.001 - dot(n_7, v_raw)), 0.0))), n_7);
    const float3 _e80 = weft_main_light_direction();
    McFrame warp = ConstructMcFrame(t_3, b_5, n_7);
    McFrame weft = ConstructMcFrame(b_5, t_3, n_7);
    {
        {
            {
                float4 _e91 = material.thread1_offsets_a;
                float4 _e94 = material.thread1_offsets_b;
                int _e97 = material.thread1_offset_count;
                const float4 _e98 = mc_thread_list_low(warp, _e80, _e79, _e29, _e91, _e94, _e97);
                s1_ = _e98;
                {
                    float4 _e101 = material.thread2_offsets_a;
                    float4 _e104 = material.thread2_offsets_b;
                    int _e107 = material.thread2_offset_count;
                    const float4 _e108 = mc_thread_list_low(weft, _e80, _e79, _e46, _e101, _e104, _e107);
                    s2_ = _e108;
                }
            }
        }
    }
    float4 _e109 = s1_;
    float4 _e110 = s2_;
    const float3 _e113 = mc_combine(_e109, _e110, a1_2, a2_1, dot(n_7, _e80), dot(n_7, _e79));
    const float3 _e114 = weft_main_light_radiance();
    float3 direct = (_e113 * _e114);
    float3 amb1_ = (_e29.albedo + (in_1.mean_fresnel.x).xxx);
    float3 amb2_ = (_e46.albedo + (in_1.mean_fresnel.y).xxx);
    float cov = (a1_2 + a2_1);
    float3 ambient_albedo = ((cov > 0.0001) ? (((a1_2 * amb1_) + (a2_1 * amb2_)) / (max(cov, 0.0001)).xxx) : amb1_);
    const float3 _e137 = weft_sh_irradiance(n_7);
    float3 ambient = (_e137 * ambient_albedo);
    float3 radiance = clamp(((direct + ambient) * brightness), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
