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
};
struct WeftObject {
    metal::float4x4 model;
    metal::float4x4 normal_matrix;
};
struct WeftMaterial {
    metal::float4 thread1_color;
    float thread1_coverage;
    float thread1_ior;
    float thread1_gamma_s;
    float thread1_gamma_v;
    float thread1_isotropy;
    char _pad6[12];
    type_5 thread1_curve;
    metal::float4 thread1_offsets_a;
    metal::float4 thread1_offsets_b;
    int thread1_offset_count;
    char _pad10[12];
    metal::float4 thread2_color;
    float thread2_coverage;
    float thread2_ior;
    float thread2_gamma_s;
    float thread2_gamma_v;
    float thread2_isotropy;
    char _pad16[12];
    type_5 thread2_curve;
    metal::float4 thread2_offsets_a;
    metal::float4 thread2_offsets_b;
    int thread2_offset_count;
    float brightness;
    char _pad21[8];
    metal::float4 albedo_map_st;
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
struct McFastPre {
    metal::float3 wi;
    metal::packed_float3 wr;
    float inv_ri;
    float inv_rr;
    float u_psi;
    float ok;
    float f0_;
    float inv_gamma_s;
    float inv_gamma_v;
    float lo;
    float hi;
    float eta;
    char _pad12[12];
};
struct McFastNode {
    float x;
    float s;
    float v;
    float p;
};
struct type_12 {
    metal::float4 inner[2];
};
constant float WEFT_PI = 3.1415927;
constant float WEFT_INV_PI = 0.31830987;
constant uint TANGENT_OFFSETS_CURVE = 0u;
constant uint TANGENT_OFFSETS_LIST = 1u;
constant uint TIER_FAST = 0u;
constant uint TIER_REFERENCE = 1u;
constant float WEFT_MIN_ROUGHNESS = 0.045;
constant float WEFT_MIN_N_DOT = 0.0001;
constant float WEFT_MAX_HALF = 65504.0;
constant float WEFT_DIELECTRIC_F0_ = 0.04;
constant uint MC_CURVE_SAMPLES = 33u;
constant uint MC_CURVE_SEGMENTS = 32u;
constant uint MC_FAST_CHORDS = 4u;
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
constant float MC_FAST_MIN_DSLOPE = 0.001;
constant float MC_FAST_MIN_SPAN = 0.0001;
constant float MC_FAST_SPLIT_DEG = 60.0;

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
    float s_1 = (n.z >= 0.0) ? 1.0 : -1.0;
    float a = -1.0 / (s_1 + n.z);
    float b = (n.x * n.y) * a;
    return metal::float3(1.0 + (((s_1 * n.x) * n.x) * a), s_1 * b, -(s_1) * n.x);
}

float weft_f_dielectric(
    float cos_i,
    float eta
) {
    float c = metal::clamp(metal::abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = ((eta * eta) - 1.0) + (c * c);
    float g = metal::sqrt(metal::max(g2_, 0.0));
    float gmc = g - c;
    float gpc = metal::max(g + c, 0.0000001);
    float a_1 = gmc / gpc;
    float b_1 = ((c * gpc) - 1.0) / metal::max((c * gmc) + 1.0, 0.0000001);
    float f = metal::saturate(((0.5 * a_1) * a_1) * (1.0 + (b_1 * b_1)));
    return (g2_ < 0.0) ? 1.0 : f;
}

float weft_f0_from_ior(
    float ior
) {
    float q_4 = (ior - 1.0) / metal::max(ior + 1.0, 0.0001);
    return q_4 * q_4;
}

metal::float3 weft_main_light_direction(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_direction;
    metal::float3 _e8 = weft_safe_normalize(_e2.xyz, metal::float3(0.0, 0.0, 1.0));
    return _e8;
}

metal::float3 weft_main_light_radiance(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_color;
    return metal::max(_e2.xyz, metal::float3(0.0));
}

metal::float3 weft_view_direction(
    metal::float3 world_position,
    metal::float3 fallback_1,
    constant WeftFrame& weft_frame
) {
    metal::float4 _e4 = weft_frame.camera_position;
    metal::float3 _e7 = weft_safe_normalize(_e4.xyz - world_position, fallback_1);
    return _e7;
}

metal::float3 weft_sh_irradiance(
    metal::float3 n_1,
    constant WeftFrame& weft_frame
) {
    metal::float3 e = {};
    type_5 sh = weft_frame.sh;
    e = sh.inner[0].xyz * 0.282095;
    metal::float3 _e9 = e;
    e = _e9 + (sh.inner[1].xyz * (0.488603 * n_1.y));
    metal::float3 _e17 = e;
    e = _e17 + (sh.inner[2].xyz * (0.488603 * n_1.z));
    metal::float3 _e25 = e;
    e = _e25 + (sh.inner[3].xyz * (0.488603 * n_1.x));
    metal::float3 _e33 = e;
    e = _e33 + (sh.inner[4].xyz * ((1.092548 * n_1.x) * n_1.y));
    metal::float3 _e43 = e;
    e = _e43 + (sh.inner[5].xyz * ((1.092548 * n_1.y) * n_1.z));
    metal::float3 _e53 = e;
    e = _e53 + (sh.inner[6].xyz * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0)));
    metal::float3 _e67 = e;
    e = _e67 + (sh.inner[7].xyz * ((1.092548 * n_1.x) * n_1.z));
    metal::float3 _e77 = e;
    e = _e77 + (sh.inner[8].xyz * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y))));
    metal::float3 _e91 = e;
    return metal::max(_e91, metal::float3(0.0));
}

metal::float3x3 weft_tangent_frame(
    metal::float3 n_2,
    metal::float4 tangent
) {
    metal::float3 t_in = tangent.xyz;
    metal::float3 t_proj = t_in - (n_2 * metal::dot(n_2, t_in));
    float len2_1 = metal::dot(t_proj, t_proj);
    bool ok = len2_1 > metal::max(0.000001 * metal::dot(t_in, t_in), 0.00000000000000000001);
    metal::float3 _e13 = weft_any_perpendicular(n_2);
    metal::float3 t_1 = ok ? (t_proj * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : _e13;
    float s_2 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_2 = metal::cross(n_2, t_1) * s_2;
    return metal::float3x3(t_1, b_2, n_2);
}

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

float mc_correlate(
    float ci,
    float cr,
    float u
) {
    float mi = metal::max(ci, 0.0);
    float mr = metal::max(cr, 0.0);
    return (((1.0 - u) * mi) * mr) + (u * metal::min(mi, mr));
}

float mc_acos_fast(
    float x
) {
    float ax = metal::min(metal::abs(x), 1.0);
    float r_1 = metal::sqrt(1.0 - ax) * (1.5707288 + (ax * (-0.2121144 + (ax * (0.074261 - (0.0187293 * ax))))));
    return (x < 0.0) ? (WEFT_PI - r_1) : r_1;
}

float mc_asin_fast(
    float x_1
) {
    float _e2 = mc_acos_fast(x_1);
    return 1.5707964 - _e2;
}

type_12 mc_normal4_(
    metal::float4 t
) {
    metal::float4 e_1 = metal::exp((-0.5 * t) * t);
    metal::float4 z = metal::abs(t) * 0.70710677;
    metal::float4 k = metal::float4(1.0) / (metal::float4(1.0) + (0.3275911 * z));
    metal::float4 poly = k * (metal::float4(0.2548296) + (k * (metal::float4(-0.28449672) + (k * (metal::float4(1.4214138) + (k * (metal::float4(-1.4531521) + (k * 1.0614054))))))));
    metal::float4 half_ = metal::float4(0.5) - ((0.5 * poly) * e_1);
    return type_12 {{e_1 * MC_INV_SQRT_TWO_PI, metal::select(-(half_), half_, t >= metal::float4(0.0))}};
}

metal::float3 mc_cell_means(
    metal::float4 xe,
    float inv_gamma
) {
    metal::float4 t_2 = xe * inv_gamma;
    type_12 _e3 = mc_normal4_(t_2);
    metal::float3 dt = t_2.yzw - t_2.xyz;
    metal::bool3 wide = metal::abs(dt) >= metal::float3(0.1);
    metal::float3 exact = (_e3.inner[1].yzw - _e3.inner[1].xyz) / metal::select(metal::float3(1.0), dt, wide);
    metal::float3 trap = 0.5 * (_e3.inner[0].xyz + _e3.inner[0].yzw);
    return metal::max(metal::select(trap, exact, wide), metal::float3(0.0)) * inv_gamma;
}

float mc_atan_fast(
    float y,
    float x_2
) {
    float ax_1 = metal::max(metal::abs(x_2), 0.00000000000000000001);
    float ay = metal::abs(y);
    float r_2 = metal::min(ax_1, ay) / metal::max(ax_1, ay);
    float r2_ = r_2 * r_2;
    float a_2 = r_2 * (0.99997723 + (r2_ * (-0.33262348 + (r2_ * (0.19354346 + (r2_ * (-0.11643287 + (r2_ * (0.05265332 - (0.0117212 * r2_))))))))));
    float b_3 = (ay > ax_1) ? (1.5707964 - a_2) : a_2;
    float c_1 = (x_2 < 0.0) ? (WEFT_PI - b_3) : b_3;
    return (y < 0.0) ? -(c_1) : c_1;
}

McFastPre mc_fast_pre(
    McFrame fr,
    metal::float3 wi,
    metal::float3 wr,
    McThread th
) {
    metal::float3 li = metal::float3(metal::dot(wi, fr.u), metal::dot(wi, fr.v), metal::dot(wi, fr.n));
    metal::float3 lr = metal::float3(metal::dot(wr, fr.u), metal::dot(wr, fr.v), metal::dot(wr, fr.n));
    float ri2_ = (li.x * li.x) + (li.z * li.z);
    float rr2_ = (lr.x * lr.x) + (lr.z * lr.z);
    bool ok_1 = metal::min(ri2_, rr2_) >= MC_MIN_PROJ2_;
    float inv_ri = metal::rsqrt(metal::max(ri2_, MC_MIN_PROJ2_));
    float inv_rr = metal::rsqrt(metal::max(rr2_, MC_MIN_PROJ2_));
    float cos_psi_d = (((li.x * lr.x) + (li.z * lr.z)) * inv_ri) * inv_rr;
    float _e50 = mc_acos_fast(cos_psi_d);
    float u_psi = metal::exp((-(_e50) * _e50) * MC_U_INV_TWO_SIGMA2_);
    float _e58 = mc_atan_fast(li.x, li.z);
    float _e61 = mc_atan_fast(lr.x, lr.z);
    float _e66 = weft_f0_from_ior(th.eta);
    return McFastPre {li, lr, inv_ri, inv_rr, u_psi, ok_1 ? 1.0 : 0.0, _e66, 1.0 / metal::max(th.gamma_s, MC_MIN_GAMMA), 1.0 / metal::max(th.gamma_v, MC_MIN_GAMMA), -1.5707964 - metal::min(_e58, _e61), 1.5707964 - metal::max(_e58, _e61), th.eta};
}

McFastNode mc_fast_node(
    McFastPre q,
    float alpha
) {
    bool local = {};
    float ca = metal::cos(alpha);
    float sa_1 = metal::sin(alpha);
    float si = metal::clamp((q.wi.x * ca) + (q.wi.z * sa_1), -1.0, 1.0);
    float sr = metal::clamp((q.wr[0] * ca) + (q.wr[2] * sa_1), -1.0, 1.0);
    float ni = (q.wi.z * ca) - (q.wi.x * sa_1);
    float nr = (q.wr[2] * ca) - (q.wr[0] * sa_1);
    float ci2_ = (q.wi.y * q.wi.y) + (ni * ni);
    float cr2_ = (q.wr[1] * q.wr[1]) + (nr * nr);
    if (metal::min(ci2_, cr2_) >= MC_MIN_PROJ2_) {
        local = q.ok != 0.0;
    } else {
        local = false;
    }
    bool ok_2 = local;
    float inv_ci = metal::rsqrt(metal::max(ci2_, MC_MIN_PROJ2_));
    float inv_cr = metal::rsqrt(metal::max(cr2_, MC_MIN_PROJ2_));
    float ci_1 = ci2_ * inv_ci;
    float cr_1 = cr2_ * inv_cr;
    float cos_phi_d = metal::clamp((((q.wi.y * q.wr[1]) + (ni * nr)) * inv_ci) * inv_cr, -1.0, 1.0);
    float cos_half_phi = metal::sqrt(0.5 + (0.5 * cos_phi_d));
    float _e87 = mc_acos_fast(cos_phi_d);
    float u_phi = metal::exp((-(_e87) * _e87) * MC_U_INV_TWO_SIGMA2_);
    float _e95 = mc_correlate(ni * inv_ci, nr * inv_cr, u_phi);
    float _e101 = mc_correlate(ni * q.inv_ri, nr * q.inv_rr, q.u_psi);
    float _e102 = mc_asin_fast(si);
    float _e103 = mc_asin_fast(sr);
    float x_3 = 0.5 * (_e102 + _e103);
    float cd2_ = metal::max(0.5 + (0.5 * ((ci_1 * cr_1) + (si * sr))), MC_MIN_COS2_THETA_D);
    float _e119 = weft_f_dielectric(metal::sqrt(cd2_) * cos_half_phi, q.eta);
    float _e121 = weft_f_dielectric(ci_1, q.eta);
    float _e125 = weft_f_dielectric(cr_1, q.eta);
    float f_t = (1.0 - _e121) * (1.0 - _e125);
    float base = ok_2 ? (((_e95 * _e101) * ci_1) / cd2_) : 0.0;
    return McFastNode {x_3, (_e119 * cos_half_phi) * base, (f_t * base) / (ci_1 + cr_1), ok_2 ? _e101 : 0.0};
}

metal::float4 mc_fast_point(
    McFastPre q_1,
    McThread th_1,
    float alpha_1
) {
    McFastNode _e3 = mc_fast_node(q_1, alpha_1);
    float ts = _e3.x * q_1.inv_gamma_s;
    float tv = _e3.x * q_1.inv_gamma_v;
    float gs = (metal::exp((-0.5 * ts) * ts) * MC_INV_SQRT_TWO_PI) * q_1.inv_gamma_s;
    float gv = (metal::exp((-0.5 * tv) * tv) * MC_INV_SQRT_TWO_PI) * q_1.inv_gamma_v;
    return metal::float4(metal::float3(gs * _e3.s) + (((((1.0 - th_1.kd) * gv) + th_1.kd) * _e3.v) * th_1.albedo), _e3.p);
}

metal::float4 mc_fast_range(
    McFastPre q_2,
    McThread th_2,
    float a0_,
    float a1_,
    bool arc,
    float split,
    float rate_lo,
    float rate_hi
) {
    metal::float3 r = {};
    float lo = metal::clamp(q_2.lo, metal::min(a0_, a1_), metal::max(a0_, a1_));
    float hi = metal::clamp(q_2.hi, lo, metal::max(a0_, a1_));
    float w = hi - lo;
    metal::float3 al = metal::float3(lo + (MC_GL3_T * w), lo + (0.5 * w), hi - (MC_GL3_T * w));
    McFastNode _e27 = mc_fast_node(q_2, al.x);
    McFastNode _e29 = mc_fast_node(q_2, al.y);
    McFastNode _e31 = mc_fast_node(q_2, al.z);
    r = metal::float3(0.2777778, 0.44444445, 0.2777778) * w;
    if (arc) {
        metal::float3 c_2 = metal::cos(al);
        metal::float3 _e39 = r;
        r = _e39 * (metal::select(metal::float3(rate_hi), metal::float3(rate_lo), al < metal::float3(split)) / ((c_2 * c_2) * c_2));
    }
    metal::float4 xe_1 = metal::float4(_e27.x + (MC_GL3_E0_ * (_e29.x - _e27.x)), _e27.x + (MC_GL3_E1_ * (_e29.x - _e27.x)), _e31.x - (MC_GL3_E1_ * (_e31.x - _e29.x)), _e31.x - (MC_GL3_E0_ * (_e31.x - _e29.x)));
    metal::float3 _e79 = mc_cell_means(xe_1, q_2.inv_gamma_s);
    metal::float3 _e81 = mc_cell_means(xe_1, q_2.inv_gamma_v);
    metal::float3 _e82 = r;
    metal::float3 s_3 = _e82 * metal::float3(_e27.s, _e29.s, _e31.s);
    metal::float3 _e88 = r;
    metal::float3 v_1 = _e88 * metal::float3(_e27.v, _e29.v, _e31.v);
    float surface = metal::dot(_e79, s_3);
    float volume = ((1.0 - th_2.kd) * metal::dot(_e81, v_1)) + (th_2.kd * ((v_1.x + v_1.y) + v_1.z));
    metal::float3 _e112 = r;
    return metal::float4(metal::float3(surface) + (volume * th_2.albedo), metal::dot(_e112, metal::float3(_e27.p, _e29.p, _e31.p)));
}

float mc_arc_primitive(
    float s
) {
    float h = metal::sqrt(1.0 + (s * s));
    return 0.5 * ((s * h) + (metal::log(metal::abs(s) + h) * metal::sign(s)));
}

metal::float4 mc_fast_half(
    McFastPre q_3,
    McThread th_3,
    float sa,
    float sb
) {
    float ds = sb - sa;
    if (metal::abs(ds) < MC_FAST_MIN_DSLOPE) {
        float s_4 = 0.5 * (sa + sb);
        metal::float4 _e12 = mc_fast_point(q_3, th_3, metal::atan(s_4));
        return _e12 * (0.5 * metal::sqrt(1.0 + (s_4 * s_4)));
    }
    float rate = 0.5 / metal::abs(ds);
    metal::float4 _e27 = mc_fast_range(q_3, th_3, metal::atan(sa), metal::atan(sb), true, 0.0, rate, rate);
    return _e27;
}

metal::float4 mc_thread_curve_fast(
    McFrame fr_1,
    metal::float3 wi_1,
    metal::float3 wr_1,
    McThread th_4,
    type_5 heights
) {
    metal::float4 acc = metal::float4(0.0);
    bool local_1 = {};
    McFastPre _e5 = mc_fast_pre(fr_1, wi_1, wr_1, th_4);
    float s0_ = 32.0 * (((-1.5 * heights.inner[0].x) + (2.0 * heights.inner[0].y)) - (0.5 * heights.inner[0].z));
    float s1_1 = (0.5 * 32.0) * (heights.inner[4].y - heights.inner[3].w);
    float s2_1 = 32.0 * (((1.5 * heights.inner[8].x) - (2.0 * heights.inner[7].w)) + (0.5 * heights.inner[7].z));
    float d01_ = s1_1 - s0_;
    float d12_ = s2_1 - s1_1;
    float _e53 = mc_arc_primitive(s1_1);
    float _e54 = mc_arc_primitive(s0_);
    float len01_ = (metal::abs(d01_) >= MC_FAST_MIN_DSLOPE) ? ((0.5 * (_e53 - _e54)) / d01_) : (0.5 * metal::sqrt(1.0 + (s0_ * s0_)));
    float _e69 = mc_arc_primitive(s2_1);
    float _e70 = mc_arc_primitive(s1_1);
    float len12_ = (metal::abs(d12_) >= MC_FAST_MIN_DSLOPE) ? ((0.5 * (_e69 - _e70)) / d12_) : (0.5 * metal::sqrt(1.0 + (s2_1 * s2_1)));
    if ((d01_ * d12_) > 0.0) {
        local_1 = metal::min(metal::abs(d01_), metal::abs(d12_)) >= MC_FAST_MIN_DSLOPE;
    } else {
        local_1 = false;
    }
    bool _e93 = local_1;
    if (_e93) {
        float r01_ = 0.5 / metal::abs(d01_);
        float r12_ = 0.5 / metal::abs(d12_);
        bool rise = d01_ > 0.0;
        metal::float4 _e108 = mc_fast_range(_e5, th_4, metal::atan(s0_), metal::atan(s2_1), true, metal::atan(s1_1), rise ? r01_ : r12_, rise ? r12_ : r01_);
        acc = _e108;
    } else {
        metal::float4 _e109 = mc_fast_half(_e5, th_4, s0_, s1_1);
        metal::float4 _e110 = mc_fast_half(_e5, th_4, s1_1, s2_1);
        acc = _e109 + _e110;
    }
    metal::float4 _e112 = acc;
    return _e112 / metal::float4(metal::max(len01_ + len12_, 0.000001));
}

metal::float3 mc_combine(
    metal::float4 t1_,
    metal::float4 t2_,
    float a1_1,
    float a2_,
    float n_dot_wi,
    float n_dot_wr
) {
    bool local_2 = {};
    bool local_3 = {};
    float c1_ = metal::saturate(a1_1);
    float c2_ = metal::saturate(a2_);
    float gap = metal::max((1.0 - c1_) - c2_, 0.0);
    float q_5 = ((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * metal::max(n_dot_wi, 0.0));
    metal::float3 s_5 = metal::max((c1_ * t1_.xyz) + (c2_ * t2_.xyz), metal::float3(0.0));
    if (n_dot_wi > 0.0) {
        local_2 = n_dot_wr > 0.0;
    } else {
        local_2 = false;
    }
    bool _e37 = local_2;
    if (_e37) {
        local_3 = q_5 > MC_MIN_Q;
    } else {
        local_3 = false;
    }
    bool lit = local_3;
    return lit ? (s_5 / metal::float3(metal::max(q_5, MC_MIN_Q))) : metal::float3(0.0);
}

McThread microcylinder_thread(
    metal::float3 color,
    float ior_1,
    float isotropy,
    float gamma_s_deg,
    float gamma_v_deg,
    metal::float3 tint
) {
    return McThread {metal::saturate(color * tint), metal::clamp(ior_1, 1.0, 4.0), metal::saturate(isotropy), metal::max(gamma_s_deg, 0.0) * MC_DEG, metal::max(gamma_v_deg, 0.0) * MC_DEG};
}

float microcylinder_mean_fresnel(
    float eta_1
) {
    float _e1 = weft_f0_from_ior(eta_1);
    return _e1 + ((1.0 - _e1) / 21.0);
}

struct vs_mainInput {
    metal::float3 position [[attribute(0)]];
    metal::float3 normal [[attribute(1)]];
    metal::float4 tangent_1 [[attribute(2)]];
    metal::float2 uv0_ [[attribute(3)]];
};
struct vs_mainOutput {
    metal::float4 clip_position [[position]];
    metal::float3 world_position [[user(loc0), center_perspective]];
    metal::float3 world_normal [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
};
vertex vs_mainOutput vs_main(
  vs_mainInput varyings [[stage_in]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftObject& weft_object [[buffer(2)]]
) {
    const WeftVertexInput in = { varyings.position, varyings.normal, varyings.tangent_1, varyings.uv0_ };
    WeftVaryings out = {};
    metal::float4x4 model = weft_object.model;
    metal::float3x3 model3_ = metal::float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    metal::float4x4 nm = weft_object.normal_matrix;
    metal::float3x3 normal3_ = metal::float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    metal::float4 world = model * metal::float4(in.position, 1.0);
    float mirror = (metal::determinant(model3_) < 0.0) ? -1.0 : 1.0;
    float bitangent_sign = ((in.tangent.w < 0.0) ? -1.0 : 1.0) * mirror;
    metal::float4x4 _e43 = weft_frame.view_proj;
    out.clip_position = _e43 * metal::float4(world.xyz, 1.0);
    out.world_position = world.xyz;
    metal::float3 _e55 = weft_safe_normalize(normal3_ * in.normal, metal::float3(0.0));
    out.world_normal = _e55;
    metal::float3 _e62 = weft_safe_normalize(model3_ * in.tangent.xyz, metal::float3(0.0));
    out.world_tangent = metal::float4(_e62, bitangent_sign);
    out.uv0_ = in.uv0_;
    WeftVaryings _e66 = out;
    const auto _tmp = _e66;
    return vs_mainOutput { _tmp.clip_position, _tmp.world_position, _tmp.world_normal, _tmp.world_tangent, _tmp.uv0_ };
}


struct fs_mainInput {
    metal::float3 world_position_1 [[user(loc0), center_perspective]];
    metal::float3 world_normal [[user(loc1), center_perspective]];
    metal::float4 world_tangent [[user(loc2), center_perspective]];
    metal::float2 uv0_ [[user(loc3), center_perspective]];
};
struct fs_mainOutput {
    metal::float4 member_1 [[color(0)]];
};
fragment fs_mainOutput fs_main(
  fs_mainInput varyings_1 [[stage_in]]
, metal::float4 clip_position [[position]]
, constant WeftFrame& weft_frame [[buffer(0)]]
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> albedo_map [[texture(0)]]
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_1, varyings_1.world_normal, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float4 s1_ = metal::float4(0.0);
    metal::float4 s2_ = metal::float4(0.0);
    metal::float4 _e4 = material.albedo_map_st;
    metal::float2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    metal::float4 _e8 = albedo_map.sample(material_sampler, _e5);
    metal::float3 tint_1 = metal::max(_e8.xyz, metal::float3(0.0));
    metal::float4 _e15 = material.thread1_color;
    float _e19 = material.thread1_ior;
    float _e22 = material.thread1_isotropy;
    float _e25 = material.thread1_gamma_s;
    float _e28 = material.thread1_gamma_v;
    McThread _e29 = microcylinder_thread(_e15.xyz, _e19, _e22, _e25, _e28, tint_1);
    metal::float4 _e32 = material.thread2_color;
    float _e36 = material.thread2_ior;
    float _e39 = material.thread2_isotropy;
    float _e42 = material.thread2_gamma_s;
    float _e45 = material.thread2_gamma_v;
    McThread _e46 = microcylinder_thread(_e32.xyz, _e36, _e39, _e42, _e45, tint_1);
    float _e49 = material.thread1_coverage;
    float a1_2 = metal::saturate(_e49);
    float _e53 = material.thread2_coverage;
    float a2_1 = false ? metal::saturate(_e53) : 0.0;
    float _e60 = material.brightness;
    float brightness = metal::max(_e60, 0.0);
    metal::float3 _e68 = weft_view_direction(in_1.world_position, metal::float3(0.0, 0.0, 1.0), weft_frame);
    metal::float3 _e70 = weft_safe_normalize(in_1.world_normal, _e68);
    metal::float3x3 _e72 = weft_tangent_frame(_e70, in_1.world_tangent);
    metal::float3 t_3 = _e72[0];
    metal::float3 b_4 = _e72[1];
    metal::float3 _e82 = weft_safe_normalize(_e68 + (_e70 * metal::max(0.001 - metal::dot(_e70, _e68), 0.0)), _e70);
    metal::float3 _e83 = weft_main_light_direction(weft_frame);
    McFrame warp = McFrame {t_3, b_4, _e70};
    McFrame weft = McFrame {b_4, t_3, _e70};
    {
        {
            type_5 _e94 = material.thread1_curve;
            metal::float4 _e95 = mc_thread_curve_fast(warp, _e83, _e82, _e29, _e94);
            s1_ = _e95;
        }
    }
    metal::float4 _e96 = s1_;
    metal::float4 _e97 = s2_;
    metal::float3 _e100 = mc_combine(_e96, _e97, a1_2, a2_1, metal::dot(_e70, _e83), metal::dot(_e70, _e82));
    metal::float3 _e101 = weft_main_light_radiance(weft_frame);
    metal::float3 direct = _e100 * _e101;
    float _e105 = microcylinder_mean_fresnel(_e29.eta);
    metal::float3 amb1_ = _e29.albedo + metal::float3(_e105);
    float _e110 = microcylinder_mean_fresnel(_e46.eta);
    metal::float3 amb2_ = _e46.albedo + metal::float3(_e110);
    float cov = a1_2 + a2_1;
    metal::float3 ambient_albedo = (cov > 0.0001) ? (((a1_2 * amb1_) + (a2_1 * amb2_)) / metal::float3(metal::max(cov, 0.0001))) : amb1_;
    metal::float3 _e124 = weft_sh_irradiance(_e70, weft_frame);
    metal::float3 ambient = _e124 * ambient_albedo;
    metal::float3 radiance = metal::clamp((direct + ambient) * brightness, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
