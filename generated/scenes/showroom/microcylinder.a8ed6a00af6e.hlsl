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

struct McFastNode {
    float x;
    float s;
    float v;
    float p;
};

struct McFastSet {
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
    float eta2_;
    float t02_;
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

struct WeftMaterial {
    float4 thread1_curve[9];
    float4 thread2_curve[9];
};

typedef float4 ret_Constructarray9_float4_[9];
ret_Constructarray9_float4_ Constructarray9_float4_(float4 arg0, float4 arg1, float4 arg2, float4 arg3, float4 arg4, float4 arg5, float4 arg6, float4 arg7, float4 arg8) {
    float4 ret[9] = { arg0, arg1, arg2, arg3, arg4, arg5, arg6, arg7, arg8 };
    return ret;
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

float3 weft_select3_f32bit(bool3 weft_sel_c, float3 weft_sel_a, float3 weft_sel_b)
{
    return float3((weft_sel_c.x ? weft_sel_a.x : weft_sel_b.x), (weft_sel_c.y ? weft_sel_a.y : weft_sel_b.y), (weft_sel_c.z ? weft_sel_a.z : weft_sel_b.z));
}

float4 weft_select4_f32bit(bool4 weft_sel_c_1, float4 weft_sel_a_1, float4 weft_sel_b_1)
{
    return float4((weft_sel_c_1.x ? weft_sel_a_1.x : weft_sel_b_1.x), (weft_sel_c_1.y ? weft_sel_a_1.y : weft_sel_b_1.y), (weft_sel_c_1.z ? weft_sel_a_1.z : weft_sel_b_1.z), (weft_sel_c_1.w ? weft_sel_a_1.w : weft_sel_b_1.w));
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

float3 weft_sh_irradiance(float3 n_1)
{
    float3 e = (float3)0;

    e = float3(0.27778354, 0.32136026, 0.4497644);
    e = (float3(0.27778354, 0.32136026, 0.4497644) + (float3(0.2192843, 0.34164187, 0.663193) * (0.488603 * n_1.y)));
    float3 _e11 = e;
    e = (_e11 + (float3(0.1352113, 0.12394369, 0.10366199) * (0.488603 * n_1.z)));
    float3 _e18 = e;
    e = (_e18 + (float3(-0.14969625, -0.13722156, -0.11476713) * (0.488603 * n_1.x)));
    float3 _e25 = e;
    e = (_e25 + (float3(-0.064625785, -0.059240304, -0.049546435) * ((1.092548 * n_1.x) * n_1.y)));
    float3 _e34 = e;
    e = (_e34 + (float3(0.05837178, 0.053507466, 0.044751696) * ((1.092548 * n_1.y) * n_1.z)));
    float3 _e43 = e;
    e = (_e43 + (float3(0.025110306, 0.023586905, 0.01273896) * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0))));
    float3 _e56 = e;
    e = (_e56 + (float3(-0.06322707, -0.057958152, -0.04847409) * ((1.092548 * n_1.x) * n_1.z)));
    float3 _e65 = e;
    e = (_e65 + (float3(0.056382716, 0.05266991, 0.031947177) * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    float3 _e78 = e;
    return max(_e78, (0.0).xxx);
}

float3 weft_safe_normalize_k12_(float3 v_1)
{
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * rsqrt(max(len2_1, 1e-20))) : float3(0.0, 0.0, 1.0));
}

float3 weft_view_direction_k2_(float3 world_position)
{
    float4 _e4 = weft_frame.camera_position;
    const float3 _e7 = weft_safe_normalize_k12_((_e4.xyz - world_position));
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
    float3x3 normal3_ = float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    float4 world = mul(float4(in_2.position, 1.0), model);
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    float4x4 _e43 = weft_frame.view_proj;
    out_.clip_position = mul(float4(world.xyz, 1.0), _e43);
    out_.world_position = world.xyz;
    const float3 _e53 = weft_safe_normalize_k3_(mul(in_2.normal, normal3_));
    out_.world_normal = _e53;
    const float3 _e58 = weft_safe_normalize_k3_(mul(in_2.tangent.xyz, model3_));
    out_.world_tangent = float4(_e58, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e62 = out_;
    const WeftVaryings weftvaryings = _e62;
    return weftvaryings;
}

float3x3 weft_tangent_frame(float3 n_2, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_3 = dot(t_proj, t_proj);
    bool ok = (len2_3 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_2);
    float3 t_1 = (ok ? (t_proj * rsqrt(max(len2_3, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_2, t_1) * s_1);
    return float3x3(t_1, b_1, n_2);
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
    float4 k_8 = ((1.0).xxxx / ((1.0).xxxx + (0.3275911 * z)));
    float4 poly = (k_8 * ((0.2548296).xxxx + (k_8 * ((-0.28449672).xxxx + (k_8 * ((1.4214138).xxxx + (k_8 * ((-1.4531521).xxxx + (k_8 * 1.0614054)))))))));
    float4 half_ = ((0.5).xxxx - ((0.5 * poly) * e_1));
    const float4 _e38 = weft_select4_f32bit((t >= (0.0).xxxx), half_, -(half_));
    return Constructarray2_float4_((e_1 * MC_INV_SQRT_TWO_PI), _e38);
}

float3 mc_cell_means(float4 xe, float inv_gamma)
{
    float4 t_2 = (xe * inv_gamma);
    const float4 _e3[2] = mc_normal4_(t_2);
    float3 dt = (t_2.yzw - t_2.xyz);
    bool3 wide = (abs(dt) >= (0.1).xxx);
    const float3 _e16 = weft_select3_f32bit(wide, dt, (1.0).xxx);
    float3 exact = ((_e3[1].yzw - _e3[1].xyz) / _e16);
    float3 trap = (0.5 * (_e3[0].xyz + _e3[0].yzw));
    const float3 _e25 = weft_select3_f32bit(wide, exact, trap);
    return (max(_e25, (0.0).xxx) * inv_gamma);
}

float mc_u_of_cos(float c)
{
    float h_4 = (0.5 - (0.5 * clamp(c, -1.0, 1.0)));
    float x2_ = (h_4 * (1.0 + (0.33333334 * h_4)));
    return exp((-16.414074 * x2_));
}

float mc_fast_correlate(float ci, float cr, float u)
{
    float mi = max(ci, 0.0);
    float mr = max(cr, 0.0);
    float prod = (mi * mr);
    return (prod + (u * (min(mi, mr) - prod)));
}

float mc_fast_asin(float x)
{
    float ax = min(abs(x), 1.0);
    float r_1 = (1.5707964 - (sqrt((1.0 - ax)) * (1.5707288 + (ax * (-0.2121144 + (ax * (0.074261 - (0.0187293 * ax))))))));
    return ((x < 0.0) ? -(r_1) : r_1);
}

float mc_fresnel_exact(float c_in, float eta2_)
{
    float c_2 = clamp(c_in, WEFT_MIN_N_DOT, 1.0);
    float g = sqrt(max(((eta2_ - 1.0) + (c_2 * c_2)), 0.0));
    float ec = (eta2_ * c_2);
    float a_1 = ((g - c_2) * (ec + g));
    float b_2 = ((ec - g) * (g + c_2));
    float d = ((g + c_2) * (ec + g));
    return saturate(((0.5 * ((a_1 * a_1) + (b_2 * b_2))) / (d * d)));
}

float mc_schlick_t(float c_1)
{
    float x_2 = (1.0 - saturate(c_1));
    float x2_1 = (x_2 * x_2);
    return (1.0 - ((x2_1 * x2_1) * x_2));
}

McFastNode ConstructMcFastNode(float arg0, float arg1, float arg2, float arg3) {
    McFastNode ret = (McFastNode)0;
    ret.x = arg0;
    ret.s = arg1;
    ret.v = arg2;
    ret.p = arg3;
    return ret;
}

McFastNode mc_fast_node(McFastSet q, float ca, float sa)
{
    bool local = (bool)0;

    float si = ((q.wi.x * ca) + (q.wi.z * sa));
    float sr = ((q.wr.x * ca) + (q.wr.z * sa));
    float ni = ((q.wi.z * ca) - (q.wi.x * sa));
    float nr = ((q.wr.z * ca) - (q.wr.x * sa));
    float ci2_ = ((q.wi.y * q.wi.y) + (ni * ni));
    float cr2_ = ((q.wr.y * q.wr.y) + (nr * nr));
    if ((min(ci2_, cr2_) >= MC_MIN_PROJ2_)) {
        local = (q.ok != 0.0);
    } else {
        local = false;
    }
    bool ok_1 = local;
    float inv_ci = rsqrt(max(ci2_, MC_MIN_PROJ2_));
    float inv_cr = rsqrt(max(cr2_, MC_MIN_PROJ2_));
    float ci_1 = (ci2_ * inv_ci);
    float cr_1 = (cr2_ * inv_cr);
    float cos_phi_d = ((((q.wi.y * q.wr.y) + (ni * nr)) * inv_ci) * inv_cr);
    float cos_half_phi = sqrt(saturate((0.5 + (0.5 * cos_phi_d))));
    const float _e80 = mc_u_of_cos(cos_phi_d);
    const float _e81 = mc_fast_correlate((ni * inv_ci), (nr * inv_cr), _e80);
    const float _e87 = mc_fast_correlate((ni * q.inv_ri), (nr * q.inv_rr), q.u_psi);
    float cd2_ = max((0.5 + (0.5 * ((ci_1 * cr_1) + (si * sr)))), MC_MIN_COS2_THETA_D);
    float inv_cd = rsqrt(cd2_);
    const float _e105 = mc_fast_asin(clamp(((0.5 * (si + sr)) * inv_cd), -1.0, 1.0));
    const float _e109 = mc_fresnel_exact(((cd2_ * inv_cd) * cos_half_phi), q.eta2_);
    const float _e111 = mc_schlick_t(ci_1);
    const float _e113 = mc_schlick_t(cr_1);
    float f_t = ((q.t02_ * _e111) * _e113);
    float base = (ok_1 ? ((((_e81 * _e87) * ci_1) * inv_cd) * inv_cd) : 0.0);
    const McFastNode mcfastnode = ConstructMcFastNode(_e105, ((_e109 * cos_half_phi) * base), ((f_t * base) / max((ci_1 + cr_1), 0.0002)), (ok_1 ? _e87 : 0.0));
    return mcfastnode;
}

float3 mc_fast_volume3_(float3 x_1, float inv_gamma_1)
{
    float3 t_3 = (x_1 * inv_gamma_1);
    return (exp(((-0.5 * t_3) * t_3)) * (MC_INV_SQRT_TWO_PI * inv_gamma_1));
}

float mc_offset_at_k23_(int k)
{
    return ((k >= int(4)) ? float4(0.0, 0.0, 0.0, 0.0) : float4(-25.0, -25.0, 25.0, 25.0))[min(uint((k & int(3))), 3u)];
}

int mc_fast_pieces_k24_(int k_1)
{
    const float _e5 = mc_offset_at_k23_(asint(asuint(k_1) + asuint(int(1))));
    const float _e6 = mc_offset_at_k23_(k_1);
    float span = abs((_e5 - _e6));
    return ((span > MC_FAST_SPLIT_DEG) ? int(2) : int(1));
}

float3 mc_list_piece_k14_(int k_2, int h)
{
    const float _e5 = mc_offset_at_k23_(k_2);
    float d0_ = (_e5 * MC_DEG);
    const float _e10 = mc_offset_at_k23_(asint(asuint(k_2) + asuint(int(1))));
    float d1_ = (_e10 * MC_DEG);
    const int _e13 = mc_fast_pieces_k24_(k_2);
    float fm = float(_e13);
    return float3(lerp(d0_, d1_, (float(h) / fm)), lerp(d0_, d1_, (float(asint(asuint(h) + asuint(int(1)))) / fm)), (1.0 / fm));
}

int2 mc_list_next_k15_(int k_3, int h_1)
{
    const int _e5 = mc_fast_pieces_k24_(k_3);
    int next = asint(asuint(h_1) + asuint(int(1)));
    return ((next >= _e5) ? int2(asint(asuint(k_3) + asuint(int(1))), int(0)) : int2(k_3, next));
}

float3 mc_combine_k11_(float4 t1_, float4 t2_, float n_dot_wi, float n_dot_wr)
{
    bool local_1 = (bool)0;
    bool local_2 = (bool)0;

    float q_6 = (((0.86 * t1_.w) + (0.14 * t2_.w)) + (0.0 * max(n_dot_wi, 0.0)));
    float3 s_2 = max(((0.86 * t1_.xyz) + (0.14 * t2_.xyz)), (0.0).xxx);
    if ((n_dot_wi > 0.0)) {
        local_1 = (n_dot_wr > 0.0);
    } else {
        local_1 = false;
    }
    bool _e32 = local_1;
    if (_e32) {
        local_2 = (q_6 > MC_MIN_Q);
    } else {
        local_2 = false;
    }
    bool lit_ = local_2;
    return (lit_ ? (s_2 / (max(q_6, MC_MIN_Q)).xxx) : (0.0).xxx);
}

McFastConst ZeroValueMcFastConst() {
    return (McFastConst)0;
}

McFastConst microcylinder_fast_const_k19_(float4 heights[9])
{
    McFastConst k_4 = ZeroValueMcFastConst();

    {
        {
            k_4.shape = float4(14.323945, 7.1619725, 1.809025, 0.95717895);
        }
    }
    McFastConst _e6 = k_4;
    const McFastConst mcfastconst = _e6;
    return mcfastconst;
}

McFastConst microcylinder_fast_const_k20_(float4 heights_1[9])
{
    McFastConst k_5 = ZeroValueMcFastConst();

    {
        {
            k_5.shape = float4(11.459156, 5.729578, 1.809025, 0.95717895);
        }
    }
    McFastConst _e6 = k_5;
    const McFastConst mcfastconst_1 = _e6;
    return mcfastconst_1;
}

float4 mc_fast_rule3_k35_(McFastSet q_1, McFastNode n0_, McFastNode n1_, McFastNode n2_, float3 r)
{
    float4 xe_1 = float4((n0_.x + (MC_GL3_E0_ * (n1_.x - n0_.x))), (n0_.x + (MC_GL3_E1_ * (n1_.x - n0_.x))), (n2_.x - (MC_GL3_E1_ * (n2_.x - n1_.x))), (n2_.x - (MC_GL3_E0_ * (n2_.x - n1_.x))));
    const float3 _e36 = mc_cell_means(xe_1, q_1.inv_gamma_s);
    const float3 _e42 = mc_fast_volume3_(float3(n0_.x, n1_.x, n2_.x), q_1.inv_gamma_v);
    float3 s_3 = (r * float3(n0_.s, n1_.s, n2_.s));
    float3 v_3 = (r * float3(n0_.v, n1_.v, n2_.v));
    float surface = dot(_e36, s_3);
    float volume = ((0.9 * dot(_e42, v_3)) + (0.1 * ((v_3.x + v_3.y) + v_3.z)));
    return float4(((surface).xxx + (volume * float3(0.019999137, 0.2000007, 0.07999783))), dot(r, float3(n0_.p, n1_.p, n2_.p)));
}

float4 mc_fast_segment_k29_(McFastSet q_2, float a0_, float a1_, float lo_s, float hi_s)
{
    float span_1 = abs((a1_ - a0_));
    bool flat = (span_1 < MC_FAST_MIN_SPAN);
    float lo = clamp(lo_s, min(a0_, a1_), max(a0_, a1_));
    float hi = clamp(hi_s, lo, max(a0_, a1_));
    float w = (hi - lo);
    float3 al = float3((lo + (MC_GL3_T * w)), (lo + (0.5 * w)), (hi - (MC_GL3_T * w)));
    float3 ca_1 = cos(al);
    float3 sa_1 = sin(al);
    const McFastNode _e30 = mc_fast_node(q_2, ca_1.x, sa_1.x);
    const McFastNode _e33 = mc_fast_node(q_2, ca_1.y, sa_1.y);
    const McFastNode _e36 = mc_fast_node(q_2, ca_1.z, sa_1.z);
    float3 r_2 = (float3(0.2777778, 0.44444445, 0.2777778) * (flat ? 1.0 : (w / max(span_1, MC_FAST_MIN_SPAN))));
    const float4 _e44 = mc_fast_rule3_k35_(q_2, _e30, _e33, _e36, r_2);
    return _e44;
}

McFastSet ConstructMcFastSet(float3 arg0, float3 arg1, float arg2, float arg3, float arg4, float arg5, float arg6, float arg7, float arg8, float arg9, float arg10, float arg11) {
    McFastSet ret = (McFastSet)0;
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
    ret.eta2_ = arg10;
    ret.t02_ = arg11;
    return ret;
}

McFastSet mc_fast_setup_k37_(McFrame fr, float3 wr, float4 shape)
{
    float3 li = float3(dot(float3(-0.61984503, 0.54986256, 0.55986005), fr.u), dot(float3(-0.61984503, 0.54986256, 0.55986005), fr.v), dot(float3(-0.61984503, 0.54986256, 0.55986005), fr.n));
    float3 lr = float3(dot(wr, fr.u), dot(wr, fr.v), dot(wr, fr.n));
    float ri2_ = ((li.x * li.x) + (li.z * li.z));
    float rr2_ = ((lr.x * lr.x) + (lr.z * lr.z));
    bool ok_2 = (min(ri2_, rr2_) >= MC_MIN_PROJ2_);
    float inv_ri = rsqrt(max(ri2_, MC_MIN_PROJ2_));
    float inv_rr = rsqrt(max(rr2_, MC_MIN_PROJ2_));
    const float _e50 = mc_u_of_cos(((((li.x * lr.x) + (li.z * lr.z)) * inv_ri) * inv_rr));
    float bi = (li.z / ((li.x < 0.0) ? min(li.x, -1e-12) : max(li.x, 1e-12)));
    float br = (lr.z / ((lr.x < 0.0) ? min(lr.x, -1e-12) : max(lr.x, 1e-12)));
    float s_lo = max(((li.x < 0.0) ? bi : -1000000.0), ((lr.x < 0.0) ? br : -1000000.0));
    float s_hi = min(((li.x > 0.0) ? bi : MC_FAST_BIG), ((lr.x > 0.0) ? br : MC_FAST_BIG));
    const McFastSet mcfastset = ConstructMcFastSet(li, lr, inv_ri, inv_rr, _e50, (ok_2 ? 1.0 : 0.0), shape.x, shape.y, clamp(s_lo, -1000000.0, MC_FAST_BIG), clamp(s_hi, -1000000.0, MC_FAST_BIG), shape.z, shape.w);
    return mcfastset;
}

float4 mc_thread_list_fast_with_k32_(McFrame fr_1, float3 wr_1, float4 shape_1)
{
    float4 acc = (0.0).xxxx;
    int k_6 = int(0);
    int h_2 = int(0);
    int i = int(0);

    const McFastSet _e9 = mc_fast_setup_k37_(fr_1, wr_1, shape_1);
    float lo_s_2 = atan(_e9.s_lo);
    float hi_s_2 = atan(_e9.s_hi);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            int _e42 = i;
            i = asint(asuint(_e42) + asuint(int(1)));
        }
        loop_init = false;
        int _e24 = i;
        if ((_e24 < int(3))) {
        } else {
            break;
        }
        {
            int _e26 = k_6;
            int _e27 = h_2;
            const float3 _e28 = mc_list_piece_k14_(_e26, _e27);
            float4 _e29 = acc;
            const float4 _e32 = mc_fast_segment_k29_(_e9, _e28.x, _e28.y, lo_s_2, hi_s_2);
            acc = (_e29 + (_e32 * _e28.z));
            int _e36 = k_6;
            int _e37 = h_2;
            const int2 _e38 = mc_list_next_k15_(_e36, _e37);
            k_6 = _e38.x;
            h_2 = _e38.y;
        }
    }
    float4 _e44 = acc;
    return (_e44 / (3.0).xxxx);
}

float4 mc_fast_rule3_k44_(McFastSet q_3, McFastNode n0_1, McFastNode n1_1, McFastNode n2_1)
{
    float4 xe_2 = float4((n0_1.x + (MC_GL3_E0_ * (n1_1.x - n0_1.x))), (n0_1.x + (MC_GL3_E1_ * (n1_1.x - n0_1.x))), (n2_1.x - (MC_GL3_E1_ * (n2_1.x - n1_1.x))), (n2_1.x - (MC_GL3_E0_ * (n2_1.x - n1_1.x))));
    const float3 _e36 = mc_cell_means(xe_2, q_3.inv_gamma_s);
    const float3 _e42 = mc_fast_volume3_(float3(n0_1.x, n1_1.x, n2_1.x), q_3.inv_gamma_v);
    float3 s_4 = (float3(0.2777778, 0.44444445, 0.2777778) * float3(n0_1.s, n1_1.s, n2_1.s));
    float3 v_4 = (float3(0.2777778, 0.44444445, 0.2777778) * float3(n0_1.v, n1_1.v, n2_1.v));
    float surface_1 = dot(_e36, s_4);
    float volume_1 = ((0.9 * dot(_e42, v_4)) + (0.1 * ((v_4.x + v_4.y) + v_4.z)));
    return float4(((surface_1).xxx + (volume_1 * float3(0.60000384, 0.0, 0.060000107))), dot(float3(0.2777778, 0.44444445, 0.2777778), float3(n0_1.p, n1_1.p, n2_1.p)));
}

McFastNode mc_fast_node_k45_(McFastSet q_4)
{
    bool local_3 = (bool)0;

    float si_1 = (q_4.wi.x + (q_4.wi.z * 0.0));
    float sr_1 = (q_4.wr.x + (q_4.wr.z * 0.0));
    float ni_1 = (q_4.wi.z - (q_4.wi.x * 0.0));
    float nr_1 = (q_4.wr.z - (q_4.wr.x * 0.0));
    float ci2_1 = ((q_4.wi.y * q_4.wi.y) + (ni_1 * ni_1));
    float cr2_1 = ((q_4.wr.y * q_4.wr.y) + (nr_1 * nr_1));
    if ((min(ci2_1, cr2_1) >= MC_MIN_PROJ2_)) {
        local_3 = (q_4.ok != 0.0);
    } else {
        local_3 = false;
    }
    bool ok_3 = local_3;
    float inv_ci_1 = rsqrt(max(ci2_1, MC_MIN_PROJ2_));
    float inv_cr_1 = rsqrt(max(cr2_1, MC_MIN_PROJ2_));
    float ci_2 = (ci2_1 * inv_ci_1);
    float cr_2 = (cr2_1 * inv_cr_1);
    float cos_phi_d_1 = ((((q_4.wi.y * q_4.wr.y) + (ni_1 * nr_1)) * inv_ci_1) * inv_cr_1);
    float cos_half_phi_1 = sqrt(saturate((0.5 + (0.5 * cos_phi_d_1))));
    const float _e76 = mc_u_of_cos(cos_phi_d_1);
    const float _e77 = mc_fast_correlate((ni_1 * inv_ci_1), (nr_1 * inv_cr_1), _e76);
    const float _e83 = mc_fast_correlate((ni_1 * q_4.inv_ri), (nr_1 * q_4.inv_rr), q_4.u_psi);
    float cd2_1 = max((0.5 + (0.5 * ((ci_2 * cr_2) + (si_1 * sr_1)))), MC_MIN_COS2_THETA_D);
    float inv_cd_1 = rsqrt(cd2_1);
    const float _e101 = mc_fast_asin(clamp(((0.5 * (si_1 + sr_1)) * inv_cd_1), -1.0, 1.0));
    const float _e105 = mc_fresnel_exact(((cd2_1 * inv_cd_1) * cos_half_phi_1), q_4.eta2_);
    const float _e107 = mc_schlick_t(ci_2);
    const float _e109 = mc_schlick_t(cr_2);
    float f_t_1 = ((q_4.t02_ * _e107) * _e109);
    float base_1 = (ok_3 ? ((((_e77 * _e83) * ci_2) * inv_cd_1) * inv_cd_1) : 0.0);
    const McFastNode mcfastnode_1 = ConstructMcFastNode(_e101, ((_e105 * cos_half_phi_1) * base_1), ((f_t_1 * base_1) / max((ci_2 + cr_2), 0.0002)), (ok_3 ? _e83 : 0.0));
    return mcfastnode_1;
}

float4 mc_fast_segment_k43_(McFastSet q_5, float lo_s_1, float hi_s_1)
{
    const McFastNode _e13 = mc_fast_node_k45_(q_5);
    const McFastNode _e14 = mc_fast_node_k45_(q_5);
    const McFastNode _e15 = mc_fast_node_k45_(q_5);
    const float4 _e16 = mc_fast_rule3_k44_(q_5, _e13, _e14, _e15);
    return _e16;
}

float4 mc_thread_list_fast_with_k33_(McFrame fr_2, float3 wr_2, float4 shape_2)
{
    float4 acc_1 = (0.0).xxxx;
    int k_7 = int(0);
    int h_3 = int(0);
    int i_1 = int(0);

    const McFastSet _e9 = mc_fast_setup_k37_(fr_2, wr_2, shape_2);
    float lo_s_3 = atan(_e9.s_lo);
    float hi_s_3 = atan(_e9.s_hi);
    {
        {
            const float4 _e23 = mc_fast_segment_k43_(_e9, lo_s_3, hi_s_3);
            acc_1 = ((0.0).xxxx + _e23);
        }
    }
    float4 _e26 = acc_1;
    return _e26;
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
    float4 _e6[9] = material.thread1_curve;
    const McFastConst _e7 = microcylinder_fast_const_k19_(_e6);
    {
        float4 _e12[9] = material.thread2_curve;
        const McFastConst _e13 = microcylinder_fast_const_k20_(_e12);
        k2_ = _e13;
    }
    float4 _e23 = k2_.shape;
    float4 _e25 = k2_.curve;
    float2 _e27 = k2_.steps;
    const MicrocylinderVaryings microcylindervaryings = ConstructMicrocylinderVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, _e7.shape, _e7.curve, _e7.steps, _e23, _e25, _e27, float2(0.068233095, 0.068233095));
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

    const WeftSurface _e9 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_raw = _e9.v;
    float3 n_3 = _e9.n;
    const float3x3 _e13 = weft_tangent_frame(n_3, in_1.world_tangent);
    float3 t_4 = _e13[0];
    float3 b_3 = _e13[1];
    const float3 _e23 = weft_safe_normalize((v_raw + (n_3 * max((0.001 - dot(n_3, v_raw)), 0.0))), n_3);
    McFrame warp = ConstructMcFrame(t_4, b_3, n_3);
    McFrame weft = ConstructMcFrame(b_3, t_4, n_3);
    {
        {
            {
                const float4 _e32 = mc_thread_list_fast_with_k32_(warp, _e23, in_1.thread1_shape);
                s1_ = _e32;
                {
                    const float4 _e34 = mc_thread_list_fast_with_k33_(weft, _e23, in_1.thread2_shape);
                    s2_ = _e34;
                }
            }
        }
    }
    float4 _e35 = s1_;
    float4 _e36 = s2_;
    const float3 _e39 = mc_combine_k11_(_e35, _e36, dot(n_3, float3(-0.61984503, 0.54986256, 0.55986005)), dot(n_3, _e23));
    float3 direct = (_e39 * float3(3.0, 2.8799999, 2.6999998));
    float3 amb1_ = (float3(0.019999137, 0.2000007, 0.07999783) + (in_1.mean_fresnel.x).xxx);
    float3 amb2_ = (float3(0.60000384, 0.0, 0.060000107) + (in_1.mean_fresnel.y).xxx);
    float3 ambient_albedo = ((0.86 * amb1_) + (0.14 * amb2_));
    const float3 _e56 = weft_sh_irradiance(n_3);
    float3 ambient = (_e56 * ambient_albedo);
    float3 radiance = clamp((direct + ambient), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
