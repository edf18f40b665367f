// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

struct type_5 {
    metal::float4 inner[9];
};
struct WeftFrame {
    metal::float4x4 view_proj;
    metal::float4x4 view;
    metal::float4 camera_position;
    metal::float4 light_direction;
    metal::float4 light_color;
    type_5 sh;
    metal::float4 params;
    metal::float4 viewport;
};
struct WeftObject {
    metal::float4x4 model;
    metal::float4x4 normal_matrix;
};
struct WeftSurface {
    metal::float3 v;
    metal::float3 n;
};
struct WeftVertexInput {
    metal::float3 position;
    metal::float3 normal;
    metal::float4 tangent;
    metal::float2 uv0_;
    char _pad4[8];
};
struct WeftVaryings {
    metal::float4 clip_position;
    metal::float3 world_position;
    metal::float3 world_normal;
    metal::float4 world_tangent;
    metal::float2 uv0_;
    char _pad5[8];
};
struct McThread {
    metal::packed_float3 albedo;
    float eta;
    float kd;
    float gamma_s;
    float gamma_v;
    char _pad5[4];
};
struct McFrame {
    metal::float3 u;
    metal::float3 v;
    metal::float3 n;
};
struct McFastNode {
    float x;
    float s;
    float v;
    float p;
};
struct type_10 {
    metal::float4 inner[2];
};
struct McFastSet {
    metal::float3 wi;
    metal::packed_float3 wr;
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
    char _pad12[12];
};
struct McFastConst {
    metal::float4 shape;
    metal::float4 curve;
    metal::float2 steps;
    char _pad3[8];
};
struct MicrocylinderVaryings {
    metal::float4 clip_position;
    metal::float3 world_position;
    metal::float3 world_normal;
    metal::float4 world_tangent;
    metal::float2 uv0_;
    char _pad5[8];
    metal::float4 thread1_shape;
    metal::float4 thread1_curve;
    metal::float2 thread1_steps;
    char _pad8[8];
    metal::float4 thread2_shape;
    metal::float4 thread2_curve;
    metal::float2 thread2_steps;
    metal::float2 mean_fresnel;
};
struct WeftMaterial {
    type_5 thread1_curve;
    type_5 thread2_curve;
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint TANGENT_OFFSETS_CURVE = 0u;
constant uint TANGENT_OFFSETS_LIST = 1u;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant uint TIER_LOW = 2u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant float WEFT_MIN_ROUGHNESS_HALF = 0.089;
constant float WEFT_MIN_N_DOT_HALF = 0.001;
constant float WEFT_MIN_ALPHA_HALF = 0.007921;
constant uint MC_CURVE_SAMPLES = 33u;
constant uint MC_CURVE_SEGMENTS = 32u;
constant int MC_MAX_OFFSETS = 8;
constant float MC_REF_STEP_DEG = 1.0;
constant float MC_REF_MAX_SUBDIV = 64.0;
constant float MC_U_INV_TWO_SIGMA2_ = 4.1035185;
constant float MC_SQRT_TWO_PI = 2.5066283;
constant float MC_DEG = 0.017453292;
constant float MC_MIN_GAMMA = 0.0017453292;
constant float MC_MIN_PROJ2_ = 0.00000001;
constant float MC_MIN_COS2_THETA_D = 0.0001;
constant float MC_MIN_Q = 0.000001;
constant float MC_INV_SQRT_TWO_PI = 0.3989423;
constant float MC_FAST_MIN_DT = 0.1;
constant float MC_GL3_T = 0.11270166;
constant float MC_GL3_W0_ = 0.2777778;
constant float MC_GL3_W1_ = 0.44444445;
constant float MC_GL3_E0_ = -0.29099444;
constant float MC_GL3_E1_ = 0.42621785;
constant float MC_FAST_BIG = 1000000.0;
constant float MC_FAST_MIN_DSLOPE = 0.0001;
constant float MC_FAST_MIN_SPAN = 0.0001;
constant float MC_FAST_SPLIT_DEG = 60.0;
constant float MC_GL2_T = 0.21132487;
constant float MC_GJ2_T = 0.31101775;
constant float MC_GL2_E = 0.36602542;
constant float MC_GJ2_E = 0.8228757;
constant float MC_GJ2_W = 0.36296296;

metal::float3 weft_safe_normalize(
    metal::float3 v,
    metal::float3 fallback
) {
    float len2_ = metal::dot(v, v);
    return (len2_ > 0.00000000000000000001) ? (v * metal::rsqrt(metal::max(len2_, 0.00000000000000000001))) : fallback;
}

metal::float3 weft_any_perpendicular(
    metal::float3 n
) {
    float s = (n.z >= 0.0) ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = (n.x * n.y) * a;
    return metal::float3(1.0 + (((s * n.x) * n.x) * a), s * b, -(s) * n.x);
}

metal::float3 weft_sh_irradiance(
    metal::float3 n_1
) {
    metal::float3 e = {};
    e = metal::float3(0.27778354, 0.32136026, 0.4497644);
    e = metal::float3(0.27778354, 0.32136026, 0.4497644) + (metal::float3(0.2192843, 0.34164187, 0.663193) * (0.488603 * n_1.y));
    metal::float3 _e11 = e;
    e = _e11 + (metal::float3(0.1352113, 0.12394369, 0.10366199) * (0.488603 * n_1.z));
    metal::float3 _e18 = e;
    e = _e18 + (metal::float3(-0.14969625, -0.13722156, -0.11476713) * (0.488603 * n_1.x));
    metal::float3 _e25 = e;
    e = _e25 + (metal::float3(-0.064625785, -0.059240304, -0.049546435) * ((1.092548 * n_1.x) * n_1.y));
    metal::float3 _e34 = e;
    e = _e34 + (metal::float3(0.05837178, 0.053507466, 0.044751696) * ((1.092548 * n_1.y) * n_1.z));
    metal::float3 _e43 = e;
    e = _e43 + (metal::float3(0.025110306, 0.023586905, 0.01273896) * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0)));
    metal::float3 _e56 = e;
    e = _e56 + (metal::float3(-0.06322707, -0.057958152, -0.04847409) * ((1.092548 * n_1.x) * n_1.z));
    metal::float3 _e65 = e;
    e = _e65 + (metal::float3(0.056382716, 0.05266991, 0.031947177) * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y))));
    metal::float3 _e78 = e;
    return metal::max(_e78, metal::float3(0.0));
}

metal::float3 weft_safe_normalize_k9_(
    metal::float3 v_1
) {
    float len2_1 = metal::dot(v_1, v_1);
    return (len2_1 > 0.00000000000000000001) ? (v_1 * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : metal::float3(0.0, 0.0, 1.0);
}

metal::float3 weft_view_direction_k2_(
    metal::float3 world_position,
    constant WeftFrame& weft_frame
) {
    metal::float4 _e4 = weft_frame.camera_position;
    metal::float3 _e7 = weft_safe_normalize_k9_(_e4.xyz - world_position);
    return _e7;
}

WeftSurface weft_surface(
    metal::float3 world_position_1,
    metal::float3 world_normal,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e2 = weft_view_direction_k2_(world_position_1, weft_frame);
    metal::float3 _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface {_e2, _e3};
}

metal::float3 weft_safe_normalize_k3_(
    metal::float3 v_2
) {
    float len2_2 = metal::dot(v_2, v_2);
    return (len2_2 > 0.00000000000000000001) ? (v_2 * metal::rsqrt(metal::max(len2_2, 0.00000000000000000001))) : metal::float3(0.0);
}

WeftVaryings weft_forward_vertex(
    WeftVertexInput in_2,
    constant WeftFrame& weft_frame,
    constant WeftObject& weft_object
) {
    WeftVaryings out = {};
    metal::float4x4 model = weft_object.model;
    metal::float3x3 model3_ = metal::float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    metal::float4x4 nm = weft_object.normal_matrix;
    metal::float3x3 normal3_ = metal::float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    metal::float4 world = model * metal::float4(in_2.position, 1.0);
    float mirror = (metal::determinant(model3_) < 0.0) ? -1.0 : 1.0;
    float bitangent_sign = ((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror;
    metal::float4x4 _e43 = weft_frame.view_proj;
    out.clip_position = _e43 * metal::float4(world.xyz, 1.0);
    out.world_position = world.xyz;
    metal::float3 _e53 = weft_safe_normalize_k3_(normal3_ * in_2.normal);
    out.world_normal = _e53;
    metal::float3 _e58 = weft_safe_normalize_k3_(model3_ * in_2.tangent.xyz);
    out.world_tangent = metal::float4(_e58, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    WeftVaryings _e62 = out;
    return _e62;
}

metal::float3x3 weft_tangent_frame(
    metal::float3 n_2,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_2 * metal::dot(n_2, t_in));
    float len2_3 = metal::dot(t_proj, t_proj);
    bool ok = len2_3 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_2);
    metal::float3 t_1 = ok ? (t_proj * metal::rsqrt(metal::max(len2_3, 0.00000000000000000001))) : _e13;
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_1 = metal::cross(n_2, t_1) * s_1;
    return metal::float3x3(t_1, b_1, n_2);
}

type_10 mc_normal4_(
    metal::float4 t
) {
    metal::float4 e_1 = metal::exp((-0.5 * t) * t);
    metal::float4 z = metal::abs(t) * 0.70710677;
    metal::float4 k_2 = metal::float4(1.0) / (metal::float4(1.0) + (0.3275911 * z));
    metal::float4 poly = k_2 * (metal::float4(0.2548296) + (k_2 * (metal::float4(-0.28449672) + (k_2 * (metal::float4(1.4214138) + (k_2 * (metal::float4(-1.4531521) + (k_2 * 1.0614054))))))));
    metal::float4 half_ = metal::float4(0.5) - ((0.5 * poly) * e_1);
    return type_10 {{e_1 * MC_INV_SQRT_TWO_PI, metal::select(-(half_), half_, t >= metal::float4(0.0))}};
}

metal::float3 mc_cell_means(
    metal::float4 xe,
    float inv_gamma
) {
    metal::float4 t_2 = xe * inv_gamma;
    type_10 _e3 = mc_normal4_(t_2);
    metal::float3 dt = t_2.yzw - t_2.xyz;
    metal::bool3 wide = metal::abs(dt) >= metal::float3(0.1);
    metal::float3 exact = (_e3.inner[1].yzw - _e3.inner[1].xyz) / metal::select(metal::float3(1.0), dt, wide);
    metal::float3 trap = 0.5 * (_e3.inner[0].xyz + _e3.inner[0].yzw);
    return metal::max(metal::select(trap, exact, wide), metal::float3(0.0)) * inv_gamma;
}

float mc_u_of_cos(
    float c
) {
    float h_1 = 0.5 - (0.5 * metal::clamp(c, -1.0, 1.0));
    float x2_ = h_1 * (1.0 + (0.33333334 * h_1));
    return metal::exp(-16.414074 * x2_);
}

float mc_fast_correlate(
    float ci,
    float cr,
    float u
) {
    float mi = metal::max(ci, 0.0);
    float mr = metal::max(cr, 0.0);
    float prod = mi * mr;
    return prod + (u * (metal::min(mi, mr) - prod));
}

float mc_fast_asin(
    float x
) {
    float ax = metal::min(metal::abs(x), 1.0);
    float r_1 = 1.5707964 - (metal::sqrt(1.0 - ax) * (1.5707288 + (ax * (-0.2121144 + (ax * (0.074261 - (0.0187293 * ax)))))));
    return (x < 0.0) ? -(r_1) : r_1;
}

float mc_fresnel_exact(
    float c_in,
    float eta2_
) {
    float c_2 = metal::clamp(c_in, WEFT_MIN_N_DOT, 1.0);
    float g = metal::sqrt(metal::max((eta2_ - 1.0) + (c_2 * c_2), 0.0));
    float ec = eta2_ * c_2;
    float a_1 = (g - c_2) * (ec + g);
    float b_2 = (ec - g) * (g + c_2);
    float d = (g + c_2) * (ec + g);
    return metal::saturate((0.5 * ((a_1 * a_1) + (b_2 * b_2))) / (d * d));
}

float mc_schlick_t(
    float c_1
) {
    float x_2 = 1.0 - metal::saturate(c_1);
    float x2_1 = x_2 * x_2;
    return 1.0 - ((x2_1 * x2_1) * x_2);
}

McFastNode mc_fast_node(
    McFastSet q,
    float ca,
    float sa
) {
    bool local = {};
    float si = (q.wi.x * ca) + (q.wi.z * sa);
    float sr = (q.wr[0] * ca) + (q.wr[2] * sa);
    float ni = (q.wi.z * ca) - (q.wi.x * sa);
    float nr = (q.wr[2] * ca) - (q.wr[0] * sa);
    float ci2_ = (q.wi.y * q.wi.y) + (ni * ni);
    float cr2_ = (q.wr[1] * q.wr[1]) + (nr * nr);
    if (metal::min(ci2_, cr2_) >= MC_MIN_PROJ2_) {
        local = q.ok != 0.0;
    } else {
        local = false;
    }
    bool ok_1 = local;
    float inv_ci = metal::rsqrt(metal::max(ci2_, MC_MIN_PROJ2_));
    float inv_cr = metal::rsqrt(metal::max(cr2_, MC_MIN_PROJ2_));
    float ci_1 = ci2_ * inv_ci;
    float cr_1 = cr2_ * inv_cr;
    float cos_phi_d = (((q.wi.y * q.wr[1]) + (ni * nr)) * inv_ci) * inv_cr;
    float cos_half_phi = metal::sqrt(metal::saturate(0.5 + (0.5 * cos_phi_d)));
    float _e80 = mc_u_of_cos(cos_phi_d);
    float _e81 = mc_fast_correlate(ni * inv_ci, nr * inv_cr, _e80);
    float _e87 = mc_fast_correlate(ni * q.inv_ri, nr * q.inv_rr, q.u_psi);
    float cd2_ = metal::max(0.5 + (0.5 * ((ci_1 * cr_1) + (si * sr))), MC_MIN_COS2_THETA_D);
    float inv_cd = metal::rsqrt(cd2_);
    float _e105 = mc_fast_asin(metal::clamp((0.5 * (si + sr)) * inv_cd, -1.0, 1.0));
    float _e109 = mc_fresnel_exact((cd2_ * inv_cd) * cos_half_phi, q.eta2_);
    float _e111 = mc_schlick_t(ci_1);
    float _e113 = mc_schlick_t(cr_1);
    float f_t = (q.t02_ * _e111) * _e113;
    float base = ok_1 ? ((((_e81 * _e87) * ci_1) * inv_cd) * inv_cd) : 0.0;
    return McFastNode {_e105, (_e109 * cos_half_phi) * base, (f_t * base) / metal::max(ci_1 + cr_1, 0.0002), ok_1 ? _e87 : 0.0};
}

metal::float3 mc_fast_volume3_(
    metal::float3 x_1,
    float inv_gamma_1
) {
    metal::float3 t_3 = x_1 * inv_gamma_1;
    return metal::exp((-0.5 * t_3) * t_3) * (MC_INV_SQRT_TWO_PI * inv_gamma_1);
}

metal::float3 mc_combine_k8_(
    metal::float4 t1_,
    metal::float4 t2_,
    float n_dot_wi,
    float n_dot_wr
) {
    bool local_1 = {};
    bool local_2 = {};
    float q_3 = ((0.33 * t1_.w) + (0.33 * t2_.w)) + (0.33999994 * metal::max(n_dot_wi, 0.0));
    metal::float3 s_2 = metal::max((0.33 * t1_.xyz) + (0.33 * t2_.xyz), metal::float3(0.0));
    if (n_dot_wi > 0.0) {
        local_1 = n_dot_wr > 0.0;
    } else {
        local_1 = false;
    }
    bool _e32 = local_1;
    if (_e32) {
        local_2 = q_3 > MC_MIN_Q;
    } else {
        local_2 = false;
    }
    bool lit = local_2;
    return lit ? (s_2 / metal::float3(metal::max(q_3, MC_MIN_Q))) : metal::float3(0.0);
}

McFastConst microcylinder_fast_const_k13_(
    type_5 heights
) {
    McFastConst k = McFastConst {};
    {
        {
            k.shape = metal::float4(4.774648, 2.387324, 2.1316001, 0.9312906);
        }
    }
    McFastConst _e6 = k;
    return _e6;
}

metal::float4 mc_fast_rule3_k22_(
    McFastSet q_1,
    McFastNode n0_,
    McFastNode n1_,
    McFastNode n2_,
    metal::float3 r
) {
    metal::float4 xe_1 = metal::float4(n0_.x + (MC_GL3_E0_ * (n1_.x - n0_.x)), n0_.x + (MC_GL3_E1_ * (n1_.x - n0_.x)), n2_.x - (MC_GL3_E1_ * (n2_.x - n1_.x)), n2_.x - (MC_GL3_E0_ * (n2_.x - n1_.x)));
    metal::float3 _e36 = mc_cell_means(xe_1, q_1.inv_gamma_s);
    metal::float3 _e42 = mc_fast_volume3_(metal::float3(n0_.x, n1_.x, n2_.x), q_1.inv_gamma_v);
    metal::float3 s_3 = r * metal::float3(n0_.s, n1_.s, n2_.s);
    metal::float3 v_3 = r * metal::float3(n0_.v, n1_.v, n2_.v);
    float surface = metal::dot(_e36, s_3);
    float volume = (0.7 * metal::dot(_e42, v_3)) + (0.3 * ((v_3.x + v_3.y) + v_3.z));
    return metal::float4(metal::float3(surface) + (volume * metal::float3(0.060000107, 0.23999724, 0.2999983)), metal::dot(r, metal::float3(n0_.p, n1_.p, n2_.p)));
}

McFastSet mc_fast_setup_k23_(
    McFrame fr,
    metal::float3 wr,
    metal::float4 shape
) {
    metal::float3 li = metal::float3(metal::dot(metal::float3(-0.61984503, 0.54986256, 0.55986005), fr.u), metal::dot(metal::float3(-0.61984503, 0.54986256, 0.55986005), fr.v), metal::dot(metal::float3(-0.61984503, 0.54986256, 0.55986005), fr.n));
    metal::float3 lr = metal::float3(metal::dot(wr, fr.u), metal::dot(wr, fr.v), metal::dot(wr, fr.n));
    float ri2_ = (li.x * li.x) + (li.z * li.z);
    float rr2_ = (lr.x * lr.x) + (lr.z * lr.z);
    bool ok_2 = metal::min(ri2_, rr2_) >= MC_MIN_PROJ2_;
    float inv_ri = metal::rsqrt(metal::max(ri2_, MC_MIN_PROJ2_));
    float inv_rr = metal::rsqrt(metal::max(rr2_, MC_MIN_PROJ2_));
    float _e50 = mc_u_of_cos((((li.x * lr.x) + (li.z * lr.z)) * inv_ri) * inv_rr);
    float bi = li.z / ((li.x < 0.0) ? metal::min(li.x, -0.000000000001) : metal::max(li.x, 0.000000000001));
    float br = lr.z / ((lr.x < 0.0) ? metal::min(lr.x, -0.000000000001) : metal::max(lr.x, 0.000000000001));
    float s_lo = metal::max((li.x < 0.0) ? bi : -1000000.0, (lr.x < 0.0) ? br : -1000000.0);
    float s_hi = metal::min((li.x > 0.0) ? bi : MC_FAST_BIG, (lr.x > 0.0) ? br : MC_FAST_BIG);
    return McFastSet {li, lr, inv_ri, inv_rr, _e50, ok_2 ? 1.0 : 0.0, shape.x, shape.y, metal::clamp(s_lo, -1000000.0, MC_FAST_BIG), metal::clamp(s_hi, -1000000.0, MC_FAST_BIG), shape.z, shape.w};
}

metal::float4 mc_fast_segment_k29_(
    McFastSet q_2,
    float lo_s,
    float hi_s
) {
    float lo = metal::clamp(lo_s, -0.43633232, 0.43633232);
    float hi = metal::clamp(hi_s, lo, 0.43633232);
    float w = hi - lo;
    metal::float3 al = metal::float3(lo + (MC_GL3_T * w), lo + (0.5 * w), hi - (MC_GL3_T * w));
    metal::float3 ca_1 = metal::cos(al);
    metal::float3 sa_1 = metal::sin(al);
    McFastNode _e28 = mc_fast_node(q_2, ca_1.x, sa_1.x);
    McFastNode _e31 = mc_fast_node(q_2, ca_1.y, sa_1.y);
    McFastNode _e34 = mc_fast_node(q_2, ca_1.z, sa_1.z);
    metal::float3 r_2 = metal::float3(0.2777778, 0.44444445, 0.2777778) * (w / 0.87266463);
    metal::float4 _e39 = mc_fast_rule3_k22_(q_2, _e28, _e31, _e34, r_2);
    return _e39;
}

metal::float4 mc_thread_list_fast_with_k20_(
    McFrame fr_1,
    metal::float3 wr_1,
    metal::float4 shape_1
) {
    metal::float4 acc = metal::float4(0.0);
    int k_1 = 0;
    int h = 0;
    int i = 0;
    McFastSet _e9 = mc_fast_setup_k23_(fr_1, wr_1, shape_1);
    float lo_s_1 = metal::atan(_e9.s_lo);
    float hi_s_1 = metal::atan(_e9.s_hi);
    {
        {
            metal::float4 _e23 = mc_fast_segment_k29_(_e9, lo_s_1, hi_s_1);
            acc = metal::float4(0.0) + _e23;
        }
    }
    metal::float4 _e26 = acc;
    return _e26;
}

struct vs_microcylinderInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float4 tangent_1 [[attribute(2)]];
    metal::float2 uv0_ [[attribute(3)]];
};
struct vs_microcylinderOutput {
    metal::float4 clip_position [[position]];
    metal::float3 world_position [[user(loc0), center_perspective]];
    metal::float3 world_normal [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
    metal::float4 thread1_shape [[user(loc4), flat]];
    metal::float4 thread1_curve [[user(loc5), flat]];
    metal::float2 thread1_steps [[user(loc6), flat]];
    metal::float4 thread2_shape [[user(loc7), flat]];
    metal::float4 thread2_curve [[user(loc8), flat]];
    metal::float2 thread2_steps [[user(loc9), flat]];
    metal::float2 mean_fresnel [[user(loc10), flat]];
};
vertex vs_microcylinderOutput vs_microcylinder(
  vs_microcylinderInput varyings [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
, constant WeftMaterial& material [[buffer(1)]]
) {
    const WeftVertexInput in = { varyings.position, varyings.normal, varyings.tangent_1, varyings.uv0_ };
    McFastConst k2_ = McFastConst {};
    WeftVaryings _e1 = weft_forward_vertex(in, weft_frame, weft_object);
    type_5 _e6 = material.thread1_curve;
    McFastConst _e7 = microcylinder_fast_const_k13_(_e6);
    {
        type_5 _e12 = material.thread2_curve;
        McFastConst _e13 = microcylinder_fast_const_k13_(_e12);
        k2_ = _e13;
    }
    metal::float4 _e23 = k2_.shape;
    metal::float4 _e25 = k2_.curve;
    metal::float2 _e27 = k2_.steps;
    const auto _tmp = MicrocylinderVaryings {_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, {}, _e7.shape, _e7.curve, _e7.steps, {}, _e23, _e25, _e27, metal::float2(0.080919966, 0.080919966)};
    return vs_microcylinderOutput { _tmp.clip_position, _tmp.world_position, _tmp.world_normal, _tmp.world_tangent, _tmp.uv0_, _tmp.thread1_shape, _tmp.thread1_curve, _tmp.thread1_steps, _tmp.thread2_shape, _tmp.thread2_curve, _tmp.thread2_steps, _tmp.mean_fresnel };
}


struct fs_mainInput {
    metal::float3 world_position_2 [[user(loc0), center_perspective]];
    metal::float3 world_normal_1 [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
    metal::float4 thread1_shape [[user(loc4), flat]];
    metal::float4 thread1_curve [[user(loc5), flat]];
    metal::float2 thread1_steps [[user(loc6), flat]];
    metal::float4 thread2_shape [[user(loc7), flat]];
    metal::float4 thread2_curve [[user(loc8), flat]];
    metal::float2 thread2_steps [[user(loc9), flat]];
    metal::float2 mean_fresnel [[user(loc10), flat]];
};
struct fs_mainOutput {
    metal::float4 member_1 [[color(0)]];
};
fragment fs_mainOutput fs_main(
  fs_mainInput varyings_1 [[stage_in]]
, metal::float4 clip_position [[position]]
, constant WeftFrame& weft_frame [[buffer(0)]]
) {
    const MicrocylinderVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_, {}, varyings_1.thread1_shape, varyings_1.thread1_curve, varyings_1.thread1_steps, {}, varyings_1.thread2_shape, varyings_1.thread2_curve, varyings_1.thread2_steps, varyings_1.mean_fresnel };
    metal::float4 s1_ = metal::float4(0.0);
    metal::float4 s2_ = metal::float4(0.0);
    WeftSurface _e9 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_raw = _e9.v;
    metal::float3 n_3 = _e9.n;
    metal::float3x3 _e13 = weft_tangent_frame(n_3, in_1.world_tangent);
    metal::float3 t_4 = _e13[0];
    metal::float3 b_3 = _e13[1];
    metal::float3 _e23 = weft_safe_normalize(v_raw + (n_3 * metal::max(0.001 - metal::dot(n_3, v_raw), 0.0)), n_3);
    McFrame warp = McFrame {t_4, b_3, n_3};
    McFrame weft = McFrame {b_3, t_4, n_3};
    {
        {
            {
                metal::float4 _e32 = mc_thread_list_fast_with_k20_(warp, _e23, in_1.thread1_shape);
                s1_ = _e32;
                {
                    metal::float4 _e34 = mc_thread_list_fast_with_k20_(weft, _e23, in_1.thread2_shape);
                    s2_ = _e34;
                }
            }
        }
    }
    metal::float4 _e35 = s1_;
    metal::float4 _e36 = s2_;
    metal::float3 _e39 = mc_combine_k8_(_e35, _e36, metal::dot(n_3, metal::float3(-0.61984503, 0.54986256, 0.55986005)), metal::dot(n_3, _e23));
    metal::float3 direct = _e39 * metal::float3(3.2, 3.05, 2.8);
    metal::float3 amb1_ = metal::float3(0.060000107, 0.23999724, 0.2999983) + metal::float3(in_1.mean_fresnel.x);
    metal::float3 amb2_ = metal::float3(0.060000107, 0.23999724, 0.2999983) + metal::float3(in_1.mean_fresnel.y);
    metal::float3 ambient_albedo = ((0.33 * amb1_) + (0.33 * amb2_)) / metal::float3(0.66);
    metal::float3 _e58 = weft_sh_irradiance(n_3);
    metal::float3 ambient = _e58 * ambient_albedo;
    metal::float3 radiance = metal::clamp(direct + ambient, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
