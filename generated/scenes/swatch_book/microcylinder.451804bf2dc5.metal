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

float weft_pow5_(
    float x
) {
    float x2_ = x * x;
    return (x2_ * x2_) * x;
}

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
    float q = (ior - 1.0) / metal::max(ior + 1.0, 0.0001);
    return q * q;
}

metal::float3 weft_main_light_direction(
    constant WeftFrame& weft_frame
) {
    metal::float4 _e2 = weft_frame.light_direction;
    metal::float3 _e5 = weft_safe_normalize(_e2.xyz, metal::float3(0.0, 0.0, 1.0));
    return _e5;
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
    metal::float3 t = ok ? (t_proj * metal::rsqrt(metal::max(len2_1, 0.00000000000000000001))) : _e13;
    float s_1 = (tangent.w < 0.0) ? -1.0 : 1.0;
    metal::float3 b_2 = metal::cross(n_2, t) * s_1;
    return metal::float3x3(t, b_2, n_2);
}

float mc_gauss(
    float gamma,
    float x_1
) {
    float g = metal::max(gamma, MC_MIN_GAMMA);
    return metal::exp((-(x_1) * x_1) / ((2.0 * g) * g)) / (MC_SQRT_TWO_PI * g);
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
    float x_2
) {
    float ax = metal::min(metal::abs(x_2), 1.0);
    float r = metal::sqrt(1.0 - ax) * (1.5707288 + (ax * (-0.2121144 + (ax * (0.074261 - (0.0187293 * ax))))));
    return (x_2 < 0.0) ? (WEFT_PI - r) : r;
}

float mc_asin_fast(
    float x_3
) {
    float _e2 = mc_acos_fast(x_3);
    return 1.5707964 - _e2;
}

McPsi mc_psi_fast(
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
    float _e23 = mc_acos_fast(metal::dot(hi, hr));
    float u_1 = metal::exp((-(_e23) * _e23) * MC_U_INV_TWO_SIGMA2_);
    return McPsi {hi, hr, u_1, ok_1 ? 1.0 : 0.0};
}

metal::float4 mc_lobe_fast(
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
    float inv_ci = metal::rsqrt(ci2_);
    float inv_cr = metal::rsqrt(cr2_);
    float ci_1 = ci2_ * inv_ci;
    float cr_1 = cr2_ * inv_cr;
    metal::float3 hi_1 = pi_1 * inv_ci;
    metal::float3 hr_1 = pr_1 * inv_cr;
    float cos_phi_d = metal::clamp(metal::dot(hi_1, hr_1), -1.0, 1.0);
    float cos_half_phi = metal::sqrt(metal::max(0.5 + (0.5 * cos_phi_d), 0.0));
    float _e60 = mc_acos_fast(cos_phi_d);
    float _e61 = mc_asin_fast(si);
    float _e62 = mc_asin_fast(sr);
    float theta_h = 0.5 * (_e61 + _e62);
    float cd2_ = metal::max(0.5 + (0.5 * ((ci_1 * cr_1) + (si * sr))), MC_MIN_COS2_THETA_D);
    float u_phi = metal::exp((-(_e60) * _e60) * MC_U_INV_TWO_SIGMA2_);
    float _e82 = mc_correlate(metal::dot(np, hi_1), metal::dot(np, hr_1), u_phi);
    float _e88 = mc_correlate(metal::dot(np, psi.pi), metal::dot(np, psi.pr), psi.u);
    float _e90 = weft_f0_from_ior(th.eta);
    float c_eff = metal::sqrt(cd2_) * cos_half_phi;
    float _e98 = weft_pow5_(1.0 - metal::saturate(c_eff));
    float f_r = _e90 + ((1.0 - _e90) * _e98);
    float f_t = (1.0 - f_r) * (1.0 - f_r);
    float _e108 = mc_gauss(th.gamma_s, theta_h);
    float surface = (f_r * cos_half_phi) * _e108;
    float _e114 = mc_gauss(th.gamma_v, theta_h);
    float volume = (f_t * (((1.0 - th.kd) * _e114) + th.kd)) / (ci_1 + cr_1);
    metal::float3 fs = (metal::float3(surface) + (volume * th.albedo)) / metal::float3(cd2_);
    return metal::float4(fs * ((_e82 * _e88) * ci_1), _e88);
}

float mc_offset_at(
    metal::float4 a,
    metal::float4 b,
    int k
) {
    return ((k >= 4) ? b : a)[k & 3];
}

metal::float4 mc_thread_list_fast(
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
    int n_3 = metal::clamp(count, 1, MC_MAX_OFFSETS);
    McPsi _e11 = mc_psi_fast(fr_1.v, wi_2, wr_2);
    uint2 loop_bound = uint2(4294967295u);
    bool loop_init = true;
    while(true) {
        if (metal::all(loop_bound == uint2(0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            int _e28 = k_1;
            k_1 = as_type<int>(as_type<uint>(_e28) + as_type<uint>(1));
        }
        loop_init = false;
        int _e16 = k_1;
        if (_e16 < n_3) {
        } else {
            break;
        }
        {
            int _e18 = k_1;
            float _e19 = mc_offset_at(offsets_a, offsets_b, _e18);
            float a_2 = _e19 * MC_DEG;
            metal::float4 _e22 = acc;
            metal::float4 _e25 = mc_lobe_fast(fr_1, _e11, wi_2, wr_2, metal::cos(a_2), metal::sin(a_2), th_1);
            acc = _e22 + _e25;
        }
    }
    metal::float4 _e30 = acc;
    return _e30 / metal::float4(static_cast<float>(n_3));
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
    bool _e36 = local_1;
    if (_e36) {
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
    float eta
) {
    float _e1 = weft_f0_from_ior(eta);
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
, constant WeftObject& weft_object [[buffer(1)]]
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
    metal::float3 _e54 = weft_safe_normalize(normal3_ * in.normal, metal::float3(0.0));
    out.world_normal = _e54;
    metal::float3 _e60 = weft_safe_normalize(model3_ * in.tangent.xyz, metal::float3(0.0));
    out.world_tangent = metal::float4(_e60, bitangent_sign);
    out.uv0_ = in.uv0_;
    WeftVaryings _e64 = out;
    const auto _tmp = _e64;
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
) {
    const WeftVaryings in_1 = { clip_position, varyings_1.world_position_1, varyings_1.world_normal, varyings_1.world_tangent, varyings_1.uv0_ };
    metal::float4 s1_ = metal::float4(0.0);
    metal::float4 s2_ = metal::float4(0.0);
    McThread _e7 = microcylinder_thread(metal::float3(0.119998775, 0.11399968, 0.0059994496), 1.345, 0.2, 5.0, 10.0, metal::float3(1.0, 1.0, 1.0));
    McThread _e13 = microcylinder_thread(metal::float3(0.16000229, 0.15199894, 0.007999428), 1.345, 0.3, 18.0, 32.0, metal::float3(1.0, 1.0, 1.0));
    metal::float3 _e19 = weft_view_direction(in_1.world_position, metal::float3(0.0, 0.0, 1.0), weft_frame);
    metal::float3 _e21 = weft_safe_normalize(in_1.world_normal, _e19);
    metal::float3x3 _e23 = weft_tangent_frame(_e21, in_1.world_tangent);
    metal::float3 t_1 = _e23[0];
    metal::float3 b_3 = _e23[1];
    metal::float3 _e33 = weft_safe_normalize(_e19 + (_e21 * metal::max(0.001 - metal::dot(_e21, _e19), 0.0)), _e21);
    metal::float3 _e34 = weft_main_light_direction(weft_frame);
    McFrame warp = McFrame {t_1, b_3, _e21};
    McFrame weft = McFrame {b_3, t_1, _e21};
    {
        {
            metal::float4 _e44 = mc_thread_list_fast(warp, _e34, _e33, _e7, metal::float4(-35.0, -35.0, 35.0, 35.0), metal::float4(0.0, 0.0, 0.0, 0.0), 4);
            s1_ = _e44;
            {
                metal::float4 _e48 = mc_thread_list_fast(weft, _e34, _e33, _e13, metal::float4(0.0, 0.0, 0.0, 0.0), metal::float4(0.0, 0.0, 0.0, 0.0), 1);
                s2_ = _e48;
            }
        }
    }
    metal::float4 _e49 = s1_;
    metal::float4 _e50 = s2_;
    metal::float3 _e53 = mc_combine(_e49, _e50, 0.75, 0.25, metal::dot(_e21, _e34), metal::dot(_e21, _e33));
    metal::float3 _e54 = weft_main_light_radiance(weft_frame);
    metal::float3 direct = _e53 * _e54;
    float _e58 = microcylinder_mean_fresnel(_e7.eta);
    metal::float3 amb1_ = _e7.albedo + metal::float3(_e58);
    float _e63 = microcylinder_mean_fresnel(_e13.eta);
    metal::float3 amb2_ = _e13.albedo + metal::float3(_e63);
    metal::float3 ambient_albedo = true ? (((0.75 * amb1_) + (0.25 * amb2_)) / metal::float3(1.0)) : amb1_;
    metal::float3 _e74 = weft_sh_irradiance(_e21, weft_frame);
    metal::float3 ambient = _e74 * ambient_albedo;
    metal::float3 radiance = metal::clamp((direct + ambient) * 1.0, metal::float3(0.0), metal::float3(65504.0));
    return fs_mainOutput { metal::float4(radiance, 1.0) };
}
