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

float3 weft_select3_f32bit(bool3 weft_sel_c, float3 weft_sel_a, float3 weft_sel_b)
{
    return float3((weft_sel_c.x ? weft_sel_a.x : weft_sel_b.x), (weft_sel_c.y ? weft_sel_a.y : weft_sel_b.y), (weft_sel_c.z ? weft_sel_a.z : weft_sel_b.z));
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

float weft_f0_from_ior(float ior)
{
    float q_2 = ((ior - 1.0) / max((ior + 1.0), 0.0001));
    return (q_2 * q_2);
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
    float3 t_2 = (ok ? (t_proj * rsqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_1 = (cross(n_2, t_2) * s_1);
    return float3x3(t_2, b_1, n_2);
}

float2 weft_transform_uv(float2 uv, float4 st)
{
    return ((uv * st.xy) + st.zw);
}

float3 mc_combine(float4 t1_, float4 t2_, float a1_, float a2_, float n_dot_wi, float n_dot_wr)
{
    bool local = (bool)0;
    bool local_1 = (bool)0;

    float c1_ = saturate(a1_);
    float c2_ = saturate(a2_);
    float gap = max(((1.0 - c1_) - c2_), 0.0);
    float q_3 = (((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * max(n_dot_wi, 0.0)));
    float3 s_2 = max(((c1_ * t1_.xyz) + (c2_ * t2_.xyz)), (0.0).xxx);
    if ((n_dot_wi > 0.0)) {
        local = (n_dot_wr > 0.0);
    } else {
        local = false;
    }
    bool _e37 = local;
    if (_e37) {
        local_1 = (q_3 > MC_MIN_Q);
    } else {
        local_1 = false;
    }
    bool lit_ = local_1;
    return (lit_ ? (s_2 / (max(q_3, MC_MIN_Q)).xxx) : (0.0).xxx);
}

float mc_fast_slope(float s0_, float s1_1, float s2_1, float t)
{
    return ((t < 0.5) ? (s0_ + ((s1_1 - s0_) * (2.0 * t))) : (s1_1 + ((s2_1 - s1_1) * ((2.0 * t) - 1.0))));
}

float mc_u_of_cos(float c)
{
    float h = (0.5 - (0.5 * clamp(c, -1.0, 1.0)));
    float x2_ = (h * (1.0 + (0.33333334 * h)));
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

float4 mc_fast_shape(McThread th)
{
    const float _e2 = weft_f0_from_ior(th.eta);
    return float4((1.0 / max(th.gamma_s, MC_MIN_GAMMA)), (1.0 / max(th.gamma_v, MC_MIN_GAMMA)), (th.eta * th.eta), ((1.0 - _e2) * (1.0 - _e2)));
}

float mc_fast_half_len(float sa, float sb)
{
    float2 s_3 = float2(lerp(sa, sb, MC_GL2_T), lerp(sa, sb, 0.7886751));
    float2 l = sqrt(((1.0).xx + (s_3 * s_3)));
    return (0.25 * (l.x + l.y));
}

float mc_fast_clip_step(float sa_1, float sb_1)
{
    float ds = (sb_1 - sa_1);
    return (1.0 / ((abs(ds) < MC_FAST_MIN_DSLOPE) ? ((ds >= 0.0) ? MC_FAST_MIN_DSLOPE : -0.0001) : ds));
}

McFastConst ConstructMcFastConst(float4 arg0, float4 arg1, float2 arg2) {
    McFastConst ret = (McFastConst)0;
    ret.shape = arg0;
    ret.curve = arg1;
    ret.steps = arg2;
    return ret;
}

McFastConst mc_fast_const(McThread th_1, float4 heights[9])
{
    float s0_1 = (32.0 * (((-1.5 * heights[0].x) + (2.0 * heights[0].y)) - (0.5 * heights[0].z)));
    float s1_2 = ((0.5 * 32.0) * (heights[4].y - heights[3].w));
    float s2_2 = (32.0 * (((1.5 * heights[8].x) - (2.0 * heights[7].w)) + (0.5 * heights[7].z)));
    const float _e41 = mc_fast_half_len(s0_1, s1_2);
    const float _e42 = mc_fast_half_len(s1_2, s2_2);
    float total = (_e41 + _e42);
    const float4 _e44 = mc_fast_shape(th_1);
    const float _e50 = mc_fast_clip_step(s0_1, s1_2);
    const float _e51 = mc_fast_clip_step(s1_2, s2_2);
    const McFastConst mcfastconst = ConstructMcFastConst(_e44, float4(s0_1, s1_2, s2_2, (1.0 / max(total, 1e-6))), float2(_e50, _e51));
    return mcfastconst;
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

McFastSet mc_fast_setup(McFrame fr, float3 wi, float3 wr, float4 shape)
{
    float3 li = float3(dot(wi, fr.u), dot(wi, fr.v), dot(wi, fr.n));
    float3 lr = float3(dot(wr, fr.u), dot(wr, fr.v), dot(wr, fr.n));
    float ri2_ = ((li.x * li.x) + (li.z * li.z));
    float rr2_ = ((lr.x * lr.x) + (lr.z * lr.z));
    bool ok_1 = (min(ri2_, rr2_) >= MC_MIN_PROJ2_);
    float inv_ri = rsqrt(max(ri2_, MC_MIN_PROJ2_));
    float inv_rr = rsqrt(max(rr2_, MC_MIN_PROJ2_));
    const float _e50 = mc_u_of_cos(((((li.x * lr.x) + (li.z * lr.z)) * inv_ri) * inv_rr));
    float bi = (li.z / ((li.x < 0.0) ? min(li.x, -1e-12) : max(li.x, 1e-12)));
    float br = (lr.z / ((lr.x < 0.0) ? min(lr.x, -1e-12) : max(lr.x, 1e-12)));
    float s_lo_1 = max(((li.x < 0.0) ? bi : -1000000.0), ((lr.x < 0.0) ? br : -1000000.0));
    float s_hi_1 = min(((li.x > 0.0) ? bi : MC_FAST_BIG), ((lr.x > 0.0) ? br : MC_FAST_BIG));
    const McFastSet mcfastset = ConstructMcFastSet(li, lr, inv_ri, inv_rr, _e50, (ok_1 ? 1.0 : 0.0), shape.x, shape.y, clamp(s_lo_1, -1000000.0, MC_FAST_BIG), clamp(s_hi_1, -1000000.0, MC_FAST_BIG), shape.z, shape.w);
    return mcfastset;
}

McFastNode ConstructMcFastNode(float arg0, float arg1, float arg2, float arg3) {
    McFastNode ret = (McFastNode)0;
    ret.x = arg0;
    ret.s = arg1;
    ret.v = arg2;
    ret.p = arg3;
    return ret;
}

McFastNode mc_fast_node(McFastSet q, float ca, float sa_2)
{
    bool local_2 = (bool)0;

    float si = ((q.wi.x * ca) + (q.wi.z * sa_2));
    float sr = ((q.wr.x * ca) + (q.wr.z * sa_2));
    float ni = ((q.wi.z * ca) - (q.wi.x * sa_2));
    float nr = ((q.wr.z * ca) - (q.wr.x * sa_2));
    float ci2_ = ((q.wi.y * q.wi.y) + (ni * ni));
    float cr2_ = ((q.wr.y * q.wr.y) + (nr * nr));
    if ((min(ci2_, cr2_) >= MC_MIN_PROJ2_)) {
        local_2 = (q.ok != 0.0);
    } else {
        local_2 = false;
    }
    bool ok_2 = local_2;
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
    float base = (ok_2 ? ((((_e81 * _e87) * ci_1) * inv_cd) * inv_cd) : 0.0);
    const McFastNode mcfastnode = ConstructMcFastNode(_e105, ((_e109 * cos_half_phi) * base), ((f_t * base) / max((ci_1 + cr_1), 0.0002)), (ok_2 ? _e87 : 0.0));
    return mcfastnode;
}

float2 mc_fast_volume2_(float2 x_1, float inv_gamma)
{
    float2 t_3 = (x_1 * inv_gamma);
    return (exp(((-0.5 * t_3) * t_3)) * (MC_INV_SQRT_TWO_PI * inv_gamma));
}

float2 mc_fast_clip(float s_lo, float s_hi, float sa_3, float inv, float ta)
{
    float u0_ = ((s_lo - sa_3) * inv);
    float u1_ = ((s_hi - sa_3) * inv);
    float2 u_1 = saturate(float2(min(u0_, u1_), max(u0_, u1_)));
    return ((u_1.x < u_1.y) ? ((ta).xx + (0.5 * u_1)) : float2(2.0, -1.0));
}

typedef float3 ret_Constructarray2_float3_[2];
ret_Constructarray2_float3_ Constructarray2_float3_(float3 arg0, float3 arg1) {
    float3 ret[2] = { arg0, arg1 };
    return ret;
}

typedef float3 ret_mc_normal3_[2];
ret_mc_normal3_ mc_normal3_(float3 t_1)
{
    float3 e_1 = exp(((-0.5 * t_1) * t_1));
    float3 z = (abs(t_1) * 0.70710677);
    float3 k_2 = ((1.0).xxx / ((1.0).xxx + (0.3275911 * z)));
    float3 poly = (k_2 * ((0.2548296).xxx + (k_2 * ((-0.28449672).xxx + (k_2 * ((1.4214138).xxx + (k_2 * ((-1.4531521).xxx + (k_2 * 1.0614054)))))))));
    float3 half_ = ((0.5).xxx - ((0.5 * poly) * e_1));
    const float3 _e46 = weft_select3_f32bit((t_1 >= (0.0).xxx), half_, -(half_));
    return Constructarray2_float3_((e_1 * MC_INV_SQRT_TWO_PI), _e46);
}

float4 mc_fast_rule2_(McFastSet q_1, McThread th_2, McFastNode n0_, McFastNode n1_, float2 r, bool jacobi)
{
    float e_2 = (jacobi ? MC_GJ2_E : MC_GL2_E);
    float d_1 = (n1_.x - n0_.x);
    float3 xe = float3((n0_.x - (e_2 * d_1)), (0.5 * (n0_.x + n1_.x)), (n1_.x + (e_2 * d_1)));
    float dx = ((jacobi ? 1.3228757 : 0.86602545) * d_1);
    const float3 _e30[2] = mc_normal3_((xe * q_1.inv_gamma_s));
    bool wide = ((abs(dx) * q_1.inv_gamma_s) >= MC_FAST_MIN_DT);
    float2 exact = ((_e30[1].yz - _e30[1].xy) / ((wide ? dx : 1.0)).xx);
    float2 trap = ((0.5 * q_1.inv_gamma_s) * (_e30[0].xy + _e30[0].yz));
    float2 gs = max((wide ? exact : trap), (0.0).xx);
    const float2 _e62 = mc_fast_volume2_(float2(n0_.x, n1_.x), q_1.inv_gamma_v);
    float2 s_4 = (r * float2(n0_.s, n1_.s));
    float2 v_1 = (r * float2(n0_.v, n1_.v));
    float surface = dot(gs, s_4);
    float volume = (((1.0 - th_2.kd) * dot(_e62, v_1)) + (th_2.kd * (v_1.x + v_1.y)));
    return float4(((surface).xxx + (volume * th_2.albedo)), dot(r, float2(n0_.p, n1_.p)));
}

float4 mc_thread_curve_fast_with(McFrame fr_1, float3 wi_1, float3 wr_1, McThread th_3, McFastConst k)
{
    bool local_3 = (bool)0;

    const McFastSet _e6 = mc_fast_setup(fr_1, wi_1, wr_1, k.shape);
    float s0_2 = k.curve.x;
    float s1_3 = k.curve.y;
    float s2_3 = k.curve.z;
    const float2 _e18 = mc_fast_clip(_e6.s_lo, _e6.s_hi, s0_2, k.steps.x, 0.0);
    const float2 _e24 = mc_fast_clip(_e6.s_lo, _e6.s_hi, s1_3, k.steps.y, 0.5);
    float t0_ = min(_e18.x, _e24.x);
    float t1_1 = max(max(_e18.y, _e24.y), t0_);
    float w = (t1_1 - t0_);
    if ((t0_ > 0.0001)) {
        local_3 = (t1_1 < 0.9999);
    } else {
        local_3 = false;
    }
    bool bump = local_3;
    float tn = (bump ? MC_GJ2_T : MC_GL2_T);
    float2 t_4 = float2((t0_ + (tn * w)), (t1_1 - (tn * w)));
    const float _e50 = mc_fast_slope(s0_2, s1_3, s2_3, t_4.x);
    const float _e52 = mc_fast_slope(s0_2, s1_3, s2_3, t_4.y);
    float2 sl = float2(_e50, _e52);
    float2 l2_ = ((1.0).xx + (sl * sl));
    float2 inv_len = rsqrt(l2_);
    const McFastNode _e63 = mc_fast_node(_e6, inv_len.x, (sl.x * inv_len.x));
    const McFastNode _e68 = mc_fast_node(_e6, inv_len.y, (sl.y * inv_len.y));
    float2 r_2 = (((bump ? MC_GJ2_W : 0.5) * w) * (l2_ * inv_len));
    const float4 _e75 = mc_fast_rule2_(_e6, th_3, _e63, _e68, r_2, bump);
    return (_e75 * k.curve.w);
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

float microcylinder_mean_fresnel(float eta)
{
    const float _e1 = weft_f0_from_ior(eta);
    return (_e1 + ((1.0 - _e1) / 21.0));
}

McFastConst ZeroValueMcFastConst() {
    return (McFastConst)0;
}

McFastConst microcylinder_fast_const(McThread th_4, float4 heights_1[9])
{
    McFastConst k_1 = ZeroValueMcFastConst();

    {
        {
            const McFastConst _e4 = mc_fast_const(th_4, heights_1);
            k_1 = _e4;
        }
    }
    McFastConst _e5 = k_1;
    const McFastConst mcfastconst_1 = _e5;
    return mcfastconst_1;
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
    float4 _e55 = k2_.shape;
    float4 _e57 = k2_.curve;
    float2 _e59 = k2_.steps;
    const float _e61 = microcylinder_mean_fresnel(_e20.eta);
    const float _e63 = microcylinder_mean_fresnel(_e39.eta);
    const MicrocylinderVaryings microcylindervaryings = ConstructMicrocylinderVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, _e43.shape, _e43.curve, _e43.steps, _e55, _e57, _e59, float2(_e61, _e63));
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
    float a2_1 = (false ? saturate(_e53) : 0.0);
    float _e60 = material.brightness;
    float brightness = max(_e60, 0.0);
    const WeftSurface _e65 = weft_surface(in_1.world_position, in_1.world_normal);
    float3 v_raw = _e65.v;
    float3 n_3 = _e65.n;
    const float3x3 _e69 = weft_tangent_frame(n_3, in_1.world_tangent);
    float3 t_5 = _e69[0];
    float3 b_3 = _e69[1];
    const float3 _e79 = weft_safe_normalize((v_raw + (n_3 * max((0.001 - dot(n_3, v_raw)), 0.0))), n_3);
    const float3 _e80 = weft_main_light_direction();
    McFrame warp = ConstructMcFrame(t_5, b_3, n_3);
    McFrame weft = ConstructMcFrame(b_3, t_5, n_3);
    {
        {
            {
                const float4 _e93 = mc_thread_curve_fast_with(warp, _e80, _e79, _e29, ConstructMcFastConst(in_1.thread1_shape, in_1.thread1_curve, in_1.thread1_steps));
                s1_ = _e93;
            }
        }
    }
    float4 _e94 = s1_;
    float4 _e95 = s2_;
    const float3 _e98 = mc_combine(_e94, _e95, a1_1, a2_1, dot(n_3, _e80), dot(n_3, _e79));
    const float3 _e99 = weft_main_light_radiance();
    float3 direct = (_e98 * _e99);
    float3 amb1_ = (_e29.albedo + (in_1.mean_fresnel.x).xxx);
    float3 amb2_ = (_e46.albedo + (in_1.mean_fresnel.y).xxx);
    float cov = (a1_1 + a2_1);
    float3 ambient_albedo = ((cov > 0.0001) ? (((a1_1 * amb1_) + (a2_1 * amb2_)) / (max(cov, 0.0001)).xxx) : amb1_);
    const float3 _e122 = weft_sh_irradiance(n_3);
    float3 ambient = (_e122 * ambient_albedo);
    float3 radiance = clamp(((direct + ambient) * brightness), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
