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
struct McPsi {
    metal::float3 pi;
    metal::packed_float3 pr;
    float u;
    float ok;
    char _pad4[12];
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

float weft_f_dielectric(
    float cos_i,
    float eta
) {
    float c = metal::clamp(metal::abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = ((eta * eta) - 1.0) + (c * c);
    float g = metal::sqrt(metal::max(g2_, 0.0));
    float gmc = g - c;
    float gpc = metal::max(g + c, 0.0000001);
    float b_den = metal::max((c * gmc) + 1.0, 0.0000001);
    float b_num = (c * gpc) - 1.0;
    float inv = 1.0 / (gpc * b_den);
    float f = metal::saturate((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv));
    return (g2_ < 0.0) ? 1.0 : f;
}

float weft_f0_from_ior(
    float ior
) {
    float q = (ior - 1.0) / metal::max(ior + 1.0, 0.0001);
    return q * q;
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
    metal::float3 t = ok ? (t_proj * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : _e13;
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_2 = metal::cross(n_2, t) * s_1;
    return metal::float3x3(t, b_2, n_2);
}

metal::float2 weft_transform_uv(
    metal::float2 uv,
    metal::float4 st
) {
    return (uv * st.xy) + st.zw;
}

float mc_gauss(
    float gamma,
    float x
) {
    float g_1 = metal::max(gamma, MC_MIN_GAMMA);
    return metal::exp((-(x) * x) / ((2.0 * g_1) * g_1)) / (MC_SQRT_TWO_PI * g_1);
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

McPsi mc_psi_reference(
    metal::float3 v_1,
    metal::float3 wi,
    metal::float3 wr
) {
    metal::float3 pi = wi - (v_1 * metal::dot(wi, v_1));
    metal::float3 pr = wr - (v_1 * metal::dot(wr, v_1));
    float li2_ = metal::dot(pi, pi);
    float lr2_ = metal::dot(pr, pr);
    bool ok_1 = metal::min(li2_, lr2_) >= MC_MIN_PROJ2_;
    metal::float3 hi = pi * metal::rsqrt(metal::max(li2_, MC_MIN_PROJ2_));
    metal::float3 hr = pr * metal::rsqrt(metal::max(lr2_, MC_MIN_PROJ2_));
    float psi_d = metal::atan2(metal::length(metal::cross(hi, hr)), metal::dot(hi, hr));
    float u_1 = metal::exp((-(psi_d) * psi_d) * MC_U_INV_TWO_SIGMA2_);
    return McPsi {hi, hr, u_1, ok_1 ? 1.0 : 0.0};
}

metal::float4 mc_lobe_reference(
    McFrame fr,
    McPsi psi,
    metal::float3 wi_1,
    metal::float3 wr_1,
    float ca,
    float sa,
    McThread th
) {
    bool local = {};
    metal::float3 u_2 = (fr.u * ca) + (fr.n * sa);
    metal::float3 np = (fr.n * ca) - (fr.u * sa);
    float si = metal::clamp(metal::dot(wi_1, u_2), -1.0, 1.0);
    float sr = metal::clamp(metal::dot(wr_1, u_2), -1.0, 1.0);
    metal::float3 pi_1 = wi_1 - (u_2 * si);
    metal::float3 pr_1 = wr_1 - (u_2 * sr);
    float ci2_ = metal::dot(pi_1, pi_1);
    float cr2_ = metal::dot(pr_1, pr_1);
    if (!((metal::min(ci2_, cr2_) < MC_MIN_PROJ2_))) {
        local = psi.ok == 0.0;
    } else {
        local = true;
    }
    bool _e41 = local;
    if (_e41) {
        return metal::float4(0.0);
    }
    float ci_1 = metal::sqrt(ci2_);
    float cr_1 = metal::sqrt(cr2_);
    metal::float3 hi_1 = pi_1 / metal::float3(ci_1);
    metal::float3 hr_1 = pr_1 / metal::float3(cr_1);
    float theta_i = metal::atan2(si, ci_1);
    float theta_r = metal::atan2(sr, cr_1);
    float theta_h = 0.5 * (theta_i + theta_r);
    float theta_d = 0.5 * (theta_i - theta_r);
    float phi_d = metal::atan2(metal::length(metal::cross(hi_1, hr_1)), metal::dot(hi_1, hr_1));
    float cos_half_phi = metal::cos(0.5 * phi_d);
    float u_phi = metal::exp((-(phi_d) * phi_d) * MC_U_INV_TWO_SIGMA2_);
    float _e72 = mc_correlate(metal::dot(np, hi_1), metal::dot(np, hr_1), u_phi);
    float _e78 = mc_correlate(metal::dot(np, psi.pi), metal::dot(np, psi.pr), psi.u);
    float cd = metal::cos(theta_d);
    float cd2_ = metal::max(cd * cd, MC_MIN_COS2_THETA_D);
    float _e85 = weft_f_dielectric(cd * cos_half_phi, th.eta);
    float _e88 = mc_gauss(th.gamma_s, theta_h);
    float surface = (_e85 * cos_half_phi) * _e88;
    float _e91 = weft_f_dielectric(ci_1, th.eta);
    float _e95 = weft_f_dielectric(cr_1, th.eta);
    float f_t = (1.0 - _e91) * (1.0 - _e95);
    float _e103 = mc_gauss(th.gamma_v, theta_h);
    float volume = (f_t * (((1.0 - th.kd) * _e103) + th.kd)) / (ci_1 + cr_1);
    metal::float3 fs = (metal::float3(surface) + (volume * th.albedo)) / metal::float3(cd2_);
    return metal::float4(fs * ((_e72 * _e78) * ci_1), _e78);
}

float mc_offset_at(
    metal::float4 a,
    metal::float4 b,
    int k
) {
    return ((k >= 4) ? b : a)[k & 3];
}

int naga_f2i32(float value) {
    return static_cast<int>(metal::clamp(value, -2147483600.0, 2147483500.0));
}

metal::float4 mc_thread_list_reference(
    McFrame fr_1,
    metal::float3 wi_2,
    metal::float3 wr_2,
    McThread th_1,
    metal::float4 offsets_a,
    metal::float4 offsets_b,
    int count
) {
    metal::float4 acc = metal::float4(0.0);
    int k_1 = 0;
    metal::float4 seg = {};
    int j = {};
    int n_3 = metal::clamp(count, 1, MC_MAX_OFFSETS);
    McPsi _e11 = mc_psi_reference(fr_1.v, wi_2, wr_2);
    if (n_3 == 1) {
        float a_2 = offsets_a.x * MC_DEG;
        metal::float4 _e19 = mc_lobe_reference(fr_1, _e11, wi_2, wr_2, metal::cos(a_2), metal::sin(a_2), th_1);
        return _e19;
    }
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            int _e75 = k_1;
            k_1 = as_type<int>(as_type<uint>(_e75) + as_type<uint>(1));
        }
        loop_init = false;
        int _e25 = k_1;
        if (_e25 < as_type<int>(as_type<uint>(n_3) - as_type<uint>(1))) {
        } else {
            break;
        }
        {
            int _e29 = k_1;
            float _e30 = mc_offset_at(offsets_a, offsets_b, _e29);
            int _e31 = k_1;
            float _e34 = mc_offset_at(offsets_a, offsets_b, as_type<int>(as_type<uint>(_e31) + as_type<uint>(1)));
            float m = metal::clamp(metal::ceil((metal::abs(_e34 - _e30) / MC_REF_STEP_DEG) - 0.001), 1.0, MC_REF_MAX_SUBDIV);
            int mi_1 = naga_f2i32(m);
            seg = metal::float4(0.0);
            j = 0;
            uint2 loop_bound_1 = uint2(4294967295u);
            bool loop_init_1 = true;
            while(true) {
                if (metal::all(loop_bound_1 == uint2(0u))) { break; }
                loop_bound_1 -= uint2(loop_bound_1.y == 0u, 1u);
                if (!loop_init_1) {
                    int _e67 = j;
                    j = as_type<int>(as_type<uint>(_e67) + as_type<uint>(1));
                }
                loop_init_1 = false;
                int _e51 = j;
                if (_e51 < mi_1) {
                } else {
                    break;
                }
                {
                    int _e53 = j;
                    float a_3 = metal::mix(_e30, _e34, (static_cast<float>(_e53) + 0.5) / m) * MC_DEG;
                    metal::float4 _e61 = seg;
                    metal::float4 _e64 = mc_lobe_reference(fr_1, _e11, wi_2, wr_2, metal::cos(a_3), metal::sin(a_3), th_1);
                    seg = _e61 + _e64;
                }
            }
            metal::float4 _e69 = acc;
            metal::float4 _e70 = seg;
            acc = _e69 + (_e70 / metal::float4(m));
        }
    }
    metal::float4 _e77 = acc;
    return _e77 / metal::float4(static_cast<float>(as_type<int>(as_type<uint>(n_3) - as_type<uint>(1))));
}

metal::float3 mc_combine(
    metal::float4 t1_,
    metal::float4 t2_,
    float a1_,
    float a2_,
    float n_dot_wi,
    float n_dot_wr
) {
    bool local_1 = {};
    bool local_2 = {};
    float c1_ = metal::saturate(a1_);
    float c2_ = metal::saturate(a2_);
    float gap = metal::max((1.0 - c1_) - c2_, 0.0);
    float q_1 = ((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * metal::max(n_dot_wi, 0.0));
    metal::float3 s_2 = metal::max((c1_ * t1_.xyz) + (c2_ * t2_.xyz), metal::float3(0.0));
    if (n_dot_wi > 0.0) {
        local_1 = n_dot_wr > 0.0;
    } else {
        local_1 = false;
    }
    bool _e37 = local_1;
    if (_e37) {
        local_2 = q_1 > MC_MIN_Q;
    } else {
        local_2 = false;
    }
    bool lit = local_2;
    return lit ? (s_2 / metal::float3(metal::max(q_1, MC_MIN_Q))) : metal::float3(0.0);
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

McFastConst microcylinder_fast_const(
    McThread th_2,
    type_5 heights
) {
    McFastConst k_2 = McFastConst {};
    McFastConst _e4 = k_2;
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
    {
        type_5 _e48 = material.thread2_curve;
        McFastConst _e49 = microcylinder_fast_const(_e39, _e48);
        k2_ = _e49;
    }
    metal::float4 _e59 = k2_.shape;
    metal::float4 _e61 = k2_.curve;
    metal::float2 _e63 = k2_.steps;
    float _e65 = microcylinder_mean_fresnel(_e20.eta);
    float _e67 = microcylinder_mean_fresnel(_e39.eta);
    const auto _tmp = MicrocylinderVaryings {_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, {}, _e43.shape, _e43.curve, _e43.steps, {}, _e59, _e61, _e63, metal::float2(_e65, _e67)};
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
    float a1_1 = metal::saturate(_e49);
    float _e53 = material.thread2_coverage;
    float a2_1 = true ? metal::saturate(_e53) : 0.0;
    float _e60 = material.brightness;
    float brightness = metal::max(_e60, 0.0);
    WeftSurface _e65 = weft_surface(in_1.world_position, in_1.world_normal, weft_frame);
    metal::float3 v_raw = _e65.v;
    metal::float3 n_4 = _e65.n;
    metal::float3x3 _e69 = weft_tangent_frame(n_4, in_1.world_tangent);
    metal::float3 t_1 = _e69[0];
    metal::float3 b_3 = _e69[1];
    metal::float3 _e79 = weft_safe_normalize(v_raw + (n_4 * metal::max(0.001 - metal::dot(n_4, v_raw), 0.0)), n_4);
    metal::float3 _e80 = weft_main_light_direction(weft_frame);
    McFrame warp = McFrame {t_1, b_3, n_4};
    McFrame weft = McFrame {b_3, t_1, n_4};
    {
        {
            metal::float4 _e91 = material.thread1_offsets_a;
            metal::float4 _e94 = material.thread1_offsets_b;
            int _e97 = material.thread1_offset_count;
            metal::float4 _e98 = mc_thread_list_reference(warp, _e80, _e79, _e29, _e91, _e94, _e97);
            s1_ = _e98;
            {
                metal::float4 _e101 = material.thread2_offsets_a;
                metal::float4 _e104 = material.thread2_offsets_b;
                int _e107 = material.thread2_offset_count;
                metal::float4 _e108 = mc_thread_list_reference(weft, _e80, _e79, _e46, _e101, _e104, _e107);
                s2_ = _e108;
            }
        }
    }
    metal::float4 _e109 = s1_;
    metal::float4 _e110 = s2_;
    metal::float3 _e113 = mc_combine(_e109, _e110, a1_1, a2_1, metal::dot(n_4, _e80), metal::dot(n_4, _e79));
    metal::float3 _e114 = weft_main_light_radiance(weft_frame);
    metal::float3 direct = _e113 * _e114;
    metal::float3 amb1_ = _e29.albedo + metal::float3(in_1.mean_fresnel.x);
    metal::float3 amb2_ = _e46.albedo + metal::float3(in_1.mean_fresnel.y);
    float cov = a1_1 + a2_1;
    metal::float3 ambient_albedo = (cov > 0.0001) ? (((a1_1 * amb1_) + (a2_1 * amb2_)) / metal::float3(metal::max(cov, 0.0001))) : amb1_;
    metal::float3 _e137 = weft_sh_irradiance(n_4, weft_frame);
    metal::float3 ambient = _e137 * ambient_albedo;
    metal::float3 radiance = metal::clamp((direct + ambient) * brightness, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
