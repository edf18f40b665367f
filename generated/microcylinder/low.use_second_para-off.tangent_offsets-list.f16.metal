// language: metal2.1
#include <metal_stdlib>
#include <simd/simd.h>

using metal::uint;

typedef half weft_half;
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
struct McFastPre {
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
    float eta;
};
struct McFastNode {
    float x;
    float s;
    float v;
    float p;
};
struct type_13 {
    metal::float4 inner[2];
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
    float a_1 = -1.0 / (s + n.z);
    float b_1 = (n.x * n.y) * a_1;
    return metal::float3(1.0 + (((s * n.x) * n.x) * a_1), s * b_1, -(s) * n.x);
}

float weft_f0_from_ior(
    float ior
) {
    float q_3 = (ior - 1.0) / metal::max(ior + 1.0, 0.0001);
    return q_3 * q_3;
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

WeftSurface weft_surface(
    metal::float3 world_position_1,
    metal::float3 world_normal,
    constant WeftFrame& weft_frame
) {
    metal::float3 _e6 = weft_view_direction(world_position_1, metal::float3(0.0, 0.0, 1.0), weft_frame);
    metal::float3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface {_e6, _e7};
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
    metal::float3 _e55 = weft_safe_normalize(normal3_ * in_2.normal, metal::float3(0.0));
    out.world_normal = _e55;
    metal::float3 _e62 = weft_safe_normalize(model3_ * in_2.tangent.xyz, metal::float3(0.0));
    out.world_tangent = metal::float4(_e62, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out;
    return _e66;
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
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_2 = metal::cross(n_2, t_1) * s_1;
    return metal::float3x3(t_1, b_2, n_2);
}

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

weft_half weft_half_f_dielectric(
    weft_half cos_i,
    weft_half eta
) {
    half c = metal::clamp(metal::abs(cos_i), 0.0010004044h, 1.0h);
    weft_half g2_ = ((eta * eta) - 1.0h) + (c * c);
    half g = metal::sqrt(metal::max(g2_, 0.0h));
    half gmc = g - c;
    half gpc = metal::max(g + c, 0.0010004044h);
    half a_2 = gmc / gpc;
    half b_3 = ((c * gpc) - 1.0h) / metal::max((c * gmc) + 1.0h, 0.0010004044h);
    half f = metal::saturate(((0.5h * a_2) * a_2) * (1.0h + (b_3 * b_3)));
    return (g2_ < 0.0h) ? 1.0h : f;
}

metal::half2 weft_half_f_dielectric2_(
    metal::half2 cos_i_1,
    weft_half eta_1
) {
    metal::half2 c_1 = metal::clamp(metal::abs(cos_i_1), metal::half2(0.0010004044h), metal::half2(1.0h));
    metal::half2 g2_1 = metal::half2((eta_1 * eta_1) - 1.0h) + (c_1 * c_1);
    metal::half2 g_1 = metal::sqrt(metal::max(g2_1, metal::half2(0.0h)));
    metal::half2 gmc_1 = g_1 - c_1;
    metal::half2 gpc_1 = metal::max(g_1 + c_1, metal::half2(0.0010004044h));
    metal::half2 a_3 = gmc_1 / gpc_1;
    metal::half2 b_4 = ((c_1 * gpc_1) - metal::half2(1.0h)) / metal::max((c_1 * gmc_1) + metal::half2(1.0h), metal::half2(0.0010004044h));
    metal::half2 f_1 = metal::saturate(((0.5h * a_3) * a_3) * (metal::half2(1.0h) + (b_4 * b_4)));
    return metal::select(f_1, metal::half2(1.0h), g2_1 < metal::half2(0.0h));
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

float mc_offset_at(
    metal::float4 a,
    metal::float4 b,
    int k
) {
    return ((k >= 4) ? b : a)[k & 3];
}

metal::float3 mc_combine(
    metal::float4 t1_,
    metal::float4 t2_,
    float a1_,
    float a2_,
    float n_dot_wi,
    float n_dot_wr
) {
    bool local = {};
    bool local_1 = {};
    float c1_ = metal::saturate(a1_);
    float c2_ = metal::saturate(a2_);
    float gap = metal::max((1.0 - c1_) - c2_, 0.0);
    float q_4 = ((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * metal::max(n_dot_wi, 0.0));
    metal::float3 s_2 = metal::max((c1_ * t1_.xyz) + (c2_ * t2_.xyz), metal::float3(0.0));
    if (n_dot_wi > 0.0) {
        local = n_dot_wr > 0.0;
    } else {
        local = false;
    }
    bool _e37 = local;
    if (_e37) {
        local_1 = q_4 > MC_MIN_Q;
    } else {
        local_1 = false;
    }
    bool lit = local_1;
    return lit ? (s_2 / metal::float3(metal::max(q_4, MC_MIN_Q))) : metal::float3(0.0);
}

type_13 mc_normal4_(
    metal::float4 t
) {
    metal::float4 e_1 = metal::exp((-0.5 * t) * t);
    metal::float4 z = metal::abs(t) * 0.70710677;
    metal::float4 k_6 = metal::float4(1.0) / (metal::float4(1.0) + (0.3275911 * z));
    metal::float4 poly = k_6 * (metal::float4(0.2548296) + (k_6 * (metal::float4(-0.28449672) + (k_6 * (metal::float4(1.4214138) + (k_6 * (metal::float4(-1.4531521) + (k_6 * 1.0614054))))))));
    metal::float4 half_ = metal::float4(0.5) - ((0.5 * poly) * e_1);
    return type_13 {{e_1 * MC_INV_SQRT_TWO_PI, metal::select(-(half_), half_, t >= metal::float4(0.0))}};
}

metal::float3 mc_cell_means(
    metal::float4 xe,
    float inv_gamma
) {
    metal::float4 t_2 = xe * inv_gamma;
    type_13 _e3 = mc_normal4_(t_2);
    metal::float3 dt = t_2.yzw - t_2.xyz;
    metal::bool3 wide = metal::abs(dt) >= metal::float3(0.1);
    metal::float3 exact = (_e3.inner[1].yzw - _e3.inner[1].xyz) / metal::select(metal::float3(1.0), dt, wide);
    metal::float3 trap = 0.5 * (_e3.inner[0].xyz + _e3.inner[0].yzw);
    return metal::max(metal::select(trap, exact, wide), metal::float3(0.0)) * inv_gamma;
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
    float bi = li.z / ((li.x < 0.0) ? metal::min(li.x, -0.000000000001) : metal::max(li.x, 0.000000000001));
    float br = lr.z / ((lr.x < 0.0) ? metal::min(lr.x, -0.000000000001) : metal::max(lr.x, 0.000000000001));
    float s_lo = metal::max((li.x < 0.0) ? bi : -1000000.0, (lr.x < 0.0) ? br : -1000000.0);
    float s_hi = metal::min((li.x > 0.0) ? bi : MC_FAST_BIG, (lr.x > 0.0) ? br : MC_FAST_BIG);
    return McFastPre {li, lr, inv_ri, inv_rr, u_psi, ok_1 ? 1.0 : 0.0, 1.0 / metal::max(th.gamma_s, MC_MIN_GAMMA), 1.0 / metal::max(th.gamma_v, MC_MIN_GAMMA), metal::clamp(s_lo, -1000000.0, MC_FAST_BIG), metal::clamp(s_hi, -1000000.0, MC_FAST_BIG), th.eta};
}

metal::float4 mc_fast_gl3_(
    McFastPre q,
    McThread th_1,
    McFastNode n0_,
    McFastNode n1_,
    McFastNode n2_,
    metal::float3 r
) {
    metal::float4 xe_1 = metal::float4(n0_.x + (MC_GL3_E0_ * (n1_.x - n0_.x)), n0_.x + (MC_GL3_E1_ * (n1_.x - n0_.x)), n2_.x - (MC_GL3_E1_ * (n2_.x - n1_.x)), n2_.x - (MC_GL3_E0_ * (n2_.x - n1_.x)));
    metal::float3 _e36 = mc_cell_means(xe_1, q.inv_gamma_s);
    metal::float3 _e38 = mc_cell_means(xe_1, q.inv_gamma_v);
    metal::float3 s_3 = r * metal::float3(n0_.s, n1_.s, n2_.s);
    metal::float3 v_1 = r * metal::float3(n0_.v, n1_.v, n2_.v);
    float surface = metal::dot(_e36, s_3);
    float volume = ((1.0 - th_1.kd) * metal::dot(_e38, v_1)) + (th_1.kd * ((v_1.x + v_1.y) + v_1.z));
    return metal::float4(metal::float3(surface) + (volume * th_1.albedo), metal::dot(r, metal::float3(n0_.p, n1_.p, n2_.p)));
}

McFastNode mc_low_node(
    McFastPre q_1,
    float ca,
    float sa
) {
    bool local_2 = {};
    float si = metal::clamp((q_1.wi.x * ca) + (q_1.wi.z * sa), -1.0, 1.0);
    float sr = metal::clamp((q_1.wr[0] * ca) + (q_1.wr[2] * sa), -1.0, 1.0);
    float ni = (q_1.wi.z * ca) - (q_1.wi.x * sa);
    float nr = (q_1.wr[2] * ca) - (q_1.wr[0] * sa);
    float ci2_ = (q_1.wi.y * q_1.wi.y) + (ni * ni);
    float cr2_ = (q_1.wr[1] * q_1.wr[1]) + (nr * nr);
    if (metal::min(ci2_, cr2_) >= MC_MIN_PROJ2_) {
        local_2 = q_1.ok != 0.0;
    } else {
        local_2 = false;
    }
    bool ok_2 = local_2;
    float inv_ci = metal::rsqrt(metal::max(ci2_, MC_MIN_PROJ2_));
    float inv_cr = metal::rsqrt(metal::max(cr2_, MC_MIN_PROJ2_));
    float ci_f = ci2_ * inv_ci;
    float cr_f = cr2_ * inv_cr;
    float cos_phi_d = metal::clamp((((q_1.wi.y * q_1.wr[1]) + (ni * nr)) * inv_ci) * inv_cr, -1.0, 1.0);
    float _e81 = mc_acos_fast(cos_phi_d);
    float u_phi = metal::exp((-(_e81) * _e81) * MC_U_INV_TWO_SIGMA2_);
    float _e87 = mc_asin_fast(si);
    float _e88 = mc_asin_fast(sr);
    float x_2 = 0.5 * (_e87 + _e88);
    half ci = static_cast<half>(ci_f);
    half cr = static_cast<half>(cr_f);
    half eta_3 = static_cast<half>(q_1.eta);
    half cos_half_phi = metal::sqrt(0.5h + (0.5h * static_cast<half>(cos_phi_d)));
    metal::half2 at_i = metal::max(static_cast<metal::half2>(metal::float2(ni * inv_ci, ni * q_1.inv_ri)), metal::half2(0.0h));
    metal::half2 at_r = metal::max(static_cast<metal::half2>(metal::float2(nr * inv_cr, nr * q_1.inv_rr)), metal::half2(0.0h));
    metal::half2 blend = static_cast<metal::half2>(metal::float2(u_phi, q_1.u_psi));
    metal::half2 mask = (((metal::half2(1.0h) - blend) * at_i) * at_r) + (blend * metal::min(at_i, at_r));
    half m = mask.x;
    half p = mask.y;
    half cd2_ = metal::max(0.5h + (0.5h * static_cast<half>((ci_f * cr_f) + (si * sr))), 0.000100016594h);
    weft_half _e143 = weft_half_f_dielectric(metal::sqrt(cd2_) * cos_half_phi, eta_3);
    metal::half2 _e145 = weft_half_f_dielectric2_(metal::half2(ci, cr), eta_3);
    half f_t = (1.0h - _e145.x) * (1.0h - _e145.y);
    half mp = (m * p) / cd2_;
    half s_4 = ((_e143 * cos_half_phi) * mp) * ci;
    half v_2 = (f_t * mp) * (ci / metal::max(ci + cr, 0.00020003319h));
    return McFastNode {x_2, ok_2 ? static_cast<float>(s_4) : 0.0, ok_2 ? static_cast<float>(v_2) : 0.0, ok_2 ? static_cast<float>(p) : 0.0};
}

metal::float4 mc_low_segment(
    McFastPre q_2,
    McThread th_2,
    float a0_,
    float a1_1,
    float lo_s,
    float hi_s
) {
    float span = metal::abs(a1_1 - a0_);
    bool flat = span < MC_FAST_MIN_SPAN;
    float lo = metal::clamp(lo_s, metal::min(a0_, a1_1), metal::max(a0_, a1_1));
    float hi = metal::clamp(hi_s, lo, metal::max(a0_, a1_1));
    float w = hi - lo;
    metal::float3 al = metal::float3(lo + (MC_GL3_T * w), lo + (0.5 * w), hi - (MC_GL3_T * w));
    metal::float3 ca_1 = metal::cos(al);
    metal::float3 sa_1 = metal::sin(al);
    McFastNode _e30 = mc_low_node(q_2, ca_1.x, sa_1.x);
    McFastNode _e33 = mc_low_node(q_2, ca_1.y, sa_1.y);
    McFastNode _e36 = mc_low_node(q_2, ca_1.z, sa_1.z);
    metal::float3 r_2 = metal::float3(0.2777778, 0.44444445, 0.2777778) * (flat ? 1.0 : (w / metal::max(span, MC_FAST_MIN_SPAN)));
    metal::float4 _e47 = mc_fast_gl3_(q_2, th_2, _e30, _e33, _e36, r_2);
    return _e47;
}

int mc_list_piece_count(
    metal::float4 offsets_a,
    metal::float4 offsets_b,
    int n_3
) {
    metal::float4 spans = metal::abs(metal::float4(offsets_a.yzw, offsets_b.x) - offsets_a);
    metal::float3 spans_b = metal::abs(offsets_b.yzw - offsets_b.xyz);
    metal::bool4 live = metal::int4(0, 1, 2, 3) < metal::int4(as_type<int>(as_type<uint>(n_3) - as_type<uint>(1)));
    metal::bool3 live_b = metal::int3(4, 5, 6) < metal::int3(as_type<int>(as_type<uint>(n_3) - as_type<uint>(1)));
    metal::int4 per = metal::select(metal::int4(0), metal::select(metal::int4(1), metal::int4(2), spans > metal::float4(60.0)), live);
    metal::int3 per_b = metal::select(metal::int3(0), metal::select(metal::int3(1), metal::int3(2), spans_b > metal::float3(60.0)), live_b);
    return metal::max(as_type<int>(as_type<uint>(as_type<int>(as_type<uint>(as_type<int>(as_type<uint>(as_type<int>(as_type<uint>(as_type<int>(as_type<uint>(as_type<int>(as_type<uint>(per.x) + as_type<uint>(per.y))) + as_type<uint>(per.z))) + as_type<uint>(per.w))) + as_type<uint>(per_b.x))) + as_type<uint>(per_b.y))) + as_type<uint>(per_b.z)), 1);
}

int mc_fast_pieces(
    metal::float4 offsets_a_1,
    metal::float4 offsets_b_1,
    int k_1
) {
    float _e5 = mc_offset_at(offsets_a_1, offsets_b_1, as_type<int>(as_type<uint>(k_1) + as_type<uint>(1)));
    float _e6 = mc_offset_at(offsets_a_1, offsets_b_1, k_1);
    float span_1 = metal::abs(_e5 - _e6);
    return (span_1 > MC_FAST_SPLIT_DEG) ? 2 : 1;
}

metal::float3 mc_list_piece(
    metal::float4 offsets_a_2,
    metal::float4 offsets_b_2,
    int n_4,
    int k_2,
    int h
) {
    float _e5 = mc_offset_at(offsets_a_2, offsets_b_2, k_2);
    float d0_ = _e5 * MC_DEG;
    float _e10 = mc_offset_at(offsets_a_2, offsets_b_2, as_type<int>(as_type<uint>(k_2) + as_type<uint>(1)));
    float d1_ = (n_4 > 1) ? (_e10 * MC_DEG) : d0_;
    int _e16 = mc_fast_pieces(offsets_a_2, offsets_b_2, k_2);
    float fm = static_cast<float>((n_4 > 1) ? _e16 : 1);
    return metal::float3(metal::mix(d0_, d1_, static_cast<float>(h) / fm), metal::mix(d0_, d1_, static_cast<float>(as_type<int>(as_type<uint>(h) + as_type<uint>(1))) / fm), 1.0 / fm);
}

metal::int2 mc_list_next(
    metal::float4 offsets_a_3,
    metal::float4 offsets_b_3,
    int n_5,
    int k_3,
    int h_1
) {
    int _e5 = mc_fast_pieces(offsets_a_3, offsets_b_3, k_3);
    int m_1 = (n_5 > 1) ? _e5 : 1;
    int next = as_type<int>(as_type<uint>(h_1) + as_type<uint>(1));
    return (next >= m_1) ? metal::int2(as_type<int>(as_type<uint>(k_3) + as_type<uint>(1)), 0) : metal::int2(k_3, next);
}

metal::float4 mc_thread_list_low(
    McFrame fr_1,
    metal::float3 wi_1,
    metal::float3 wr_1,
    McThread th_3,
    metal::float4 offsets_a_4,
    metal::float4 offsets_b_4,
    int count
) {
    metal::float4 acc = metal::float4(0.0);
    int k_4 = 0;
    int h_2 = 0;
    int i = 0;
    int n_6 = metal::clamp(count, 1, MC_MAX_OFFSETS);
    McFastPre _e10 = mc_fast_pre(fr_1, wi_1, wr_1, th_3);
    float lo_s_1 = metal::atan(_e10.s_lo);
    float hi_s_1 = metal::atan(_e10.s_hi);
    int segments = metal::max(as_type<int>(as_type<uint>(n_6) - as_type<uint>(1)), 1);
    int _e19 = mc_list_piece_count(offsets_a_4, offsets_b_4, n_6);
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            int _e47 = i;
            i = as_type<int>(as_type<uint>(_e47) + as_type<uint>(1));
        }
        loop_init = false;
        int _e29 = i;
        if (_e29 < _e19) {
        } else {
            break;
        }
        {
            int _e31 = k_4;
            int _e32 = h_2;
            metal::float3 _e33 = mc_list_piece(offsets_a_4, offsets_b_4, n_6, _e31, _e32);
            metal::float4 _e34 = acc;
            metal::float4 _e37 = mc_low_segment(_e10, th_3, _e33.x, _e33.y, lo_s_1, hi_s_1);
            acc = _e34 + (_e37 * _e33.z);
            int _e41 = k_4;
            int _e42 = h_2;
            metal::int2 _e43 = mc_list_next(offsets_a_4, offsets_b_4, n_6, _e41, _e42);
            k_4 = _e43.x;
            h_2 = _e43.y;
        }
    }
    metal::float4 _e49 = acc;
    return _e49 / metal::float4(static_cast<float>(segments));
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
    float eta_2
) {
    float _e1 = weft_f0_from_ior(eta_2);
    return _e1 + ((1.0 - _e1) / 21.0);
}

McFastConst microcylinder_fast_const(
    McThread th_4,
    type_5 heights
) {
    McFastConst k_5 = McFastConst {};
    McFastConst _e4 = k_5;
    return _e4;
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
    metal::float4 _e4 = material.thread1_color;
    float _e8 = material.thread1_ior;
    float _e11 = material.thread1_isotropy;
    float _e14 = material.thread1_gamma_s;
    float _e17 = material.thread1_gamma_v;
    McThread _e20 = microcylinder_thread(_e4.xyz, _e8, _e11, _e14, _e17, metal::float3(1.0));
    metal::float4 _e23 = material.thread2_color;
    float _e27 = material.thread2_ior;
    float _e30 = material.thread2_isotropy;
    float _e33 = material.thread2_gamma_s;
    float _e36 = material.thread2_gamma_v;
    McThread _e39 = microcylinder_thread(_e23.xyz, _e27, _e30, _e33, _e36, metal::float3(1.0));
    type_5 _e42 = material.thread1_curve;
    McFastConst _e43 = microcylinder_fast_const(_e20, _e42);
    metal::float4 _e55 = k2_.shape;
    metal::float4 _e57 = k2_.curve;
    metal::float2 _e59 = k2_.steps;
    float _e61 = microcylinder_mean_fresnel(_e20.eta);
    float _e63 = microcylinder_mean_fresnel(_e39.eta);
    const auto _tmp = MicrocylinderVaryings {_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, {}, _e43.shape, _e43.curve, _e43.steps, {}, _e55, _e57, _e59, metal::float2(_e61, _e63)};
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
, constant WeftMaterial& material [[buffer(1)]]
, metal::sampler material_sampler [[sampler(0)]]
, metal::texture2d<float, metal::access::sample> albedo_map [[texture(0)]]
) {
    const MicrocylinderVaryings in_1 = { clip_position, varyings_1.world_position_2, varyings_1.world_normal_1, varyings_1.world_tangent, varyings_1.uv0_, {}, varyings_1.thread1_shape, varyings_1.thread1_curve, varyings_1.thread1_steps, {}, varyings_1.thread2_shape, varyings_1.thread2_curve, varyings_1.thread2_steps, varyings_1.mean_fresnel };
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
    WeftSurface _e65 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_raw = _e65.v;
    metal::float3 n_7 = _e65.n;
    metal::float3x3 _e69 = weft_tangent_frame(n_7, in_1.world_tangent);
    metal::float3 t_3 = _e69[0];
    metal::float3 b_5 = _e69[1];
    metal::float3 _e79 = weft_safe_normalize(v_raw + (n_7 * metal::max(0.001 - metal::dot(n_7, v_raw), 0.0)), n_7);
    metal::float3 _e80 = weft_main_light_direction(weft_frame);
    McFrame warp = McFrame {t_3, b_5, n_7};
    McFrame weft = McFrame {b_5, t_3, n_7};
    {
        {
            {
                metal::float4 _e91 = material.thread1_offsets_a;
                metal::float4 _e94 = material.thread1_offsets_b;
                int _e97 = material.thread1_offset_count;
                metal::float4 _e98 = mc_thread_list_low(warp, _e80, _e79, _e29, _e91, _e94, _e97);
                s1_ = _e98;
            }
        }
    }
    metal::float4 _e99 = s1_;
    metal::float4 _e100 = s2_;
    metal::float3 _e103 = mc_combine(_e99, _e100, a1_2, a2_1, metal::dot(n_7, _e80), metal::dot(n_7, _e79));
    metal::float3 _e104 = weft_main_light_radiance(weft_frame);
    metal::float3 direct = _e103 * _e104;
    metal::float3 amb1_ = _e29.albedo + metal::float3(in_1.mean_fresnel.x);
    metal::float3 amb2_ = _e46.albedo + metal::float3(in_1.mean_fresnel.y);
    float cov = a1_2 + a2_1;
    metal::float3 ambient_albedo = (cov > 0.0001) ? (((a1_2 * amb1_) + (a2_1 * amb2_)) / metal::float3(metal::max(cov, 0.0001))) : amb1_;
    metal::float3 _e127 = weft_sh_irradiance(n_7, weft_frame);
    metal::float3 ambient = _e127 * ambient_albedo;
    metal::float3 radiance = metal::clamp((direct + ambient) * brightness, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
