struct WeftFrame {
    row_major float4x4 view_proj;
    row_major float4x4 view;
    float4 camera_position;
    float4 light_direction;
    float4 light_color;
    float4 sh[9];
    float4 params;
};

struct WeftObject {
    row_major float4x4 model;
    row_major float4x4 normal_matrix;
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

static const float WEFT_PI = 3.1415927;
static const float WEFT_INV_PI = 0.31830987;
static const uint TANGENT_OFFSETS_CURVE = 0u;
static const uint TANGENT_OFFSETS_LIST = 1u;
static const uint TIER_FAST = 0u;
static const uint TIER_REFERENCE = 1u;
static const float WEFT_MIN_ROUGHNESS = 0.045;
static const float WEFT_MIN_N_DOT = 0.0001;
static const float WEFT_MAX_HALF = 65504.0;
static const float WEFT_DIELECTRIC_F0_ = 0.04;
static const uint MC_CURVE_SAMPLES = 33u;
static const uint MC_CURVE_SEGMENTS = 32u;
static const uint MC_FAST_CHORDS = 4u;
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

cbuffer weft_frame : register(b0) { WeftFrame weft_frame; }
cbuffer weft_object : register(b0, space2) { WeftObject weft_object; }

struct VertexOutput_vs_main {
    float3 world_position_1 : LOC0;
    float3 world_normal : LOC1;
    float4 world_tangent : LOC2;
    float2 uv0_ : LOC3;
    float4 clip_position : SV_Position;
};

struct FragmentInput_fs_main {
    float3 world_position_2 : LOC0;
    float3 world_normal_1 : LOC1;
    float4 world_tangent_1 : LOC2;
    float2 uv0_1 : LOC3;
    float4 clip_position_1 : SV_Position;
};

float weft_pow5_(float x)
{
    float x2_ = (x * x);
    return ((x2_ * x2_) * x);
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
    float q = ((ior - 1.0) / max((ior + 1.0), 0.0001));
    return (q * q);
}

float3 weft_main_light_direction()
{
    float4 _e2 = weft_frame.light_direction;
    const float3 _e5 = weft_safe_normalize(_e2.xyz, float3(0.0, 0.0, 1.0));
    return _e5;
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

float3x3 weft_tangent_frame(float3 n_2, float4 tangent)
{
    float3 t_in = tangent.xyz;
    float3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    const float3 _e13 = weft_any_perpendicular(n_2);
    float3 t = (ok ? (t_proj * rsqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    float3 b_2 = (cross(n_2, t) * s_1);
    return float3x3(t, b_2, n_2);
}

float mc_gauss(float gamma, float x_1)
{
    float g = max(gamma, MC_MIN_GAMMA);
    return (exp(((-(x_1) * x_1) / ((2.0 * g) * g))) / (MC_SQRT_TWO_PI * g));
}

float mc_correlate(float ci, float cr, float u)
{
    float mi = max(ci, 0.0);
    float mr = max(cr, 0.0);
    return ((((1.0 - u) * mi) * mr) + (u * min(mi, mr)));
}

float mc_acos_fast(float x_2)
{
    float ax = min(abs(x_2), 1.0);
    float r = (sqrt((1.0 - ax)) * (1.5707288 + (ax * (-0.2121144 + (ax * (0.074261 - (0.0187293 * ax)))))));
    return ((x_2 < 0.0) ? (WEFT_PI - r) : r);
}

float mc_asin_fast(float x_3)
{
    const float _e2 = mc_acos_fast(x_3);
    return (1.5707964 - _e2);
}

McPsi ConstructMcPsi(float3 arg0, float3 arg1, float arg2, float arg3) {
    McPsi ret = (McPsi)0;
    ret.pi = arg0;
    ret.pr = arg1;
    ret.u = arg2;
    ret.ok = arg3;
    return ret;
}

McPsi mc_psi_fast(float3 v_1, float3 wi, float3 wr)
{
    float3 pi = (wi - (v_1 * dot(wi, v_1)));
    float3 pr = (wr - (v_1 * dot(wr, v_1)));
    float li2_ = dot(pi, pi);
    float lr2_ = dot(pr, pr);
    bool ok_1 = (min(li2_, lr2_) >= MC_MIN_PROJ2_);
    float3 hi = (pi * rsqrt(max(li2_, MC_MIN_PROJ2_)));
    float3 hr = (pr * rsqrt(max(lr2_, MC_MIN_PROJ2_)));
    const float _e23 = mc_acos_fast(dot(hi, hr));
    float u_1 = exp(((-(_e23) * _e23) * MC_U_INV_TWO_SIGMA2_));
    const McPsi mcpsi = ConstructMcPsi(hi, hr, u_1, (ok_1 ? 1.0 : 0.0));
    return mcpsi;
}

float4 mc_lobe_fast(McFrame fr, McPsi psi, float3 wi_1, float3 wr_1, float ca, float sa, McThread th)
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
    float inv_ci = rsqrt(ci2_);
    float inv_cr = rsqrt(cr2_);
    float ci_1 = (ci2_ * inv_ci);
    float cr_1 = (cr2_ * inv_cr);
    float3 hi_1 = (pi_1 * inv_ci);
    float3 hr_1 = (pr_1 * inv_cr);
    float cos_phi_d = clamp(dot(hi_1, hr_1), -1.0, 1.0);
    float cos_half_phi = sqrt(max((0.5 + (0.5 * cos_phi_d)), 0.0));
    const float _e60 = mc_acos_fast(cos_phi_d);
    const float _e61 = mc_asin_fast(si);
    const float _e62 = mc_asin_fast(sr);
    float theta_h = (0.5 * (_e61 + _e62));
    float cd2_ = max((0.5 + (0.5 * ((ci_1 * cr_1) + (si * sr)))), MC_MIN_COS2_THETA_D);
    float u_phi = exp(((-(_e60) * _e60) * MC_U_INV_TWO_SIGMA2_));
    const float _e82 = mc_correlate(dot(np, hi_1), dot(np, hr_1), u_phi);
    const float _e88 = mc_correlate(dot(np, psi.pi), dot(np, psi.pr), psi.u);
    const float _e90 = weft_f0_from_ior(th.eta);
    float c_eff = (sqrt(cd2_) * cos_half_phi);
    const float _e98 = weft_pow5_((1.0 - saturate(c_eff)));
    float f_r = (_e90 + ((1.0 - _e90) * _e98));
    float f_t = ((1.0 - f_r) * (1.0 - f_r));
    const float _e108 = mc_gauss(th.gamma_s, theta_h);
    float surface = ((f_r * cos_half_phi) * _e108);
    const float _e114 = mc_gauss(th.gamma_v, theta_h);
    float volume = ((f_t * (((1.0 - th.kd) * _e114) + th.kd)) / (ci_1 + cr_1));
    float3 fs = (((surface).xxx + (volume * th.albedo)) / (cd2_).xxx);
    return float4((fs * ((_e82 * _e88) * ci_1)), _e88);
}

float mc_offset_at(float4 a, float4 b, int k)
{
    return ((k >= int(4)) ? b : a)[min(uint((k & int(3))), 3u)];
}

float4 mc_thread_list_fast(McFrame fr_1, float3 wi_2, float3 wr_2, McThread th_1, float4 offsets_a, float4 offsets_b, int count)
{
    float4 acc = (0.0).xxxx;
    int k_1 = int(0);

    int n_3 = clamp(count, int(1), MC_MAX_OFFSETS);
    const McPsi _e11 = mc_psi_fast(fr_1.v, wi_2, wr_2);
    uint2 loop_bound = uint2(4294967295u, 4294967295u);
    bool loop_init = true;
    while(true) {
        if (all(loop_bound == uint2(0u, 0u))) { break; }
        loop_bound -= uint2(loop_bound.y == 0u, 1u);
        if (!loop_init) {
            int _e28 = k_1;
            k_1 = asint(asuint(_e28) + asuint(int(1)));
        }
        loop_init = false;
        int _e16 = k_1;
        if ((_e16 < n_3)) {
        } else {
            break;
        }
        {
            int _e18 = k_1;
            const float _e19 = mc_offset_at(offsets_a, offsets_b, _e18);
            float a_2 = (_e19 * MC_DEG);
            float4 _e22 = acc;
            const float4 _e25 = mc_lobe_fast(fr_1, _e11, wi_2, wr_2, cos(a_2), sin(a_2), th_1);
            acc = (_e22 + _e25);
        }
    }
    float4 _e30 = acc;
    return (_e30 / (float(n_3)).xxxx);
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
    bool _e36 = local_1;
    if (_e36) {
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

float microcylinder_mean_fresnel(float eta)
{
    const float _e1 = weft_f0_from_ior(eta);
    return (_e1 + ((1.0 - _e1) / 21.0));
}

VertexOutput_vs_main vs_main(WeftVertexInput in_)
{
    WeftVaryings out_ = (WeftVaryings)0;

    float4x4 model = weft_object.model;
    float3x3 model3_ = float3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    float4x4 nm = weft_object.normal_matrix;
    float3x3 normal3_ = float3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    float4 world = mul(float4(in_.position, 1.0), model);
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    float4x4 _e43 = weft_frame.view_proj;
    out_.clip_position = mul(float4(world.xyz, 1.0), _e43);
    out_.world_position = world.xyz;
    const float3 _e54 = weft_safe_normalize(mul(in_.normal, normal3_), (0.0).xxx);
    out_.world_normal = _e54;
    const float3 _e60 = weft_safe_normalize(mul(in_.tangent.xyz, model3_), (0.0).xxx);
    out_.world_tangent = float4(_e60, bitangent_sign);
    out_.uv0_ = in_.uv0_;
    WeftVaryings _e64 = out_;
    const WeftVaryings weftvaryings = _e64;
    const VertexOutput_vs_main weftvaryings_1 = { weftvaryings.world_position, weftvaryings.world_normal, weftvaryings.world_tangent, weftvaryings.uv0_, weftvaryings.clip_position };
    return weftvaryings_1;
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
    WeftVaryings in_1 = { fragmentinput_fs_main.clip_position_1, fragmentinput_fs_main.world_position_2, fragmentinput_fs_main.world_normal_1, fragmentinput_fs_main.world_tangent_1, fragmentinput_fs_main.uv0_1 };
    float4 s1_ = (0.0).xxxx;
    float4 s2_ = (0.0).xxxx;

    const McThread _e7 = microcylinder_thread(float3(0.034998663, 0.012949297, 0.010499509), 1.539, 0.1, 2.5, 5.0, float3(1.0, 1.0, 1.0));
    const McThread _e13 = microcylinder_thread(float3(0.019999137, 0.0073994505, 0.0059994496), 1.539, 0.7, 30.0, 60.0, float3(1.0, 1.0, 1.0));
    const float3 _e19 = weft_view_direction(in_1.world_position, float3(0.0, 0.0, 1.0));
    const float3 _e21 = weft_safe_normalize(in_1.world_normal, _e19);
    const float3x3 _e23 = weft_tangent_frame(_e21, in_1.world_tangent);
    float3 t_1 = _e23[0];
    float3 b_3 = _e23[1];
    const float3 _e33 = weft_safe_normalize((_e19 + (_e21 * max((0.001 - dot(_e21, _e19)), 0.0))), _e21);
    const float3 _e34 = weft_main_light_direction();
    McFrame warp = ConstructMcFrame(t_1, b_3, _e21);
    McFrame weft = ConstructMcFrame(b_3, t_1, _e21);
    {
        {
            const float4 _e44 = mc_thread_list_fast(warp, _e34, _e33, _e7, float4(-30.0, -30.0, 30.0, 30.0), float4(-5.0, -5.0, 5.0, 5.0), int(8));
            s1_ = _e44;
            {
                const float4 _e48 = mc_thread_list_fast(weft, _e34, _e33, _e13, float4(0.0, 0.0, 0.0, 0.0), float4(0.0, 0.0, 0.0, 0.0), int(1));
                s2_ = _e48;
            }
        }
    }
    float4 _e49 = s1_;
    float4 _e50 = s2_;
    const float3 _e53 = mc_combine(_e49, _e50, 0.67, 0.33, dot(_e21, _e34), dot(_e21, _e33));
    const float3 _e54 = weft_main_light_radiance();
    float3 direct = (_e53 * _e54);
    const float _e58 = microcylinder_mean_fresnel(_e7.eta);
    float3 amb1_ = (_e7.albedo + (_e58).xxx);
    const float _e63 = microcylinder_mean_fresnel(_e13.eta);
    float3 amb2_ = (_e13.albedo + (_e63).xxx);
    float3 ambient_albedo = (true ? (((0.67 * amb1_) + (0.33 * amb2_)) / (1.0).xxx) : amb1_);
    const float3 _e74 = weft_sh_irradiance(_e21);
    float3 ambient = (_e74 * ambient_albedo);
    float3 radiance = clamp(((direct + ambient) * 1.0), (0.0).xxx, (65504.0).xxx);
    return float4(radiance, 1.0);
}
