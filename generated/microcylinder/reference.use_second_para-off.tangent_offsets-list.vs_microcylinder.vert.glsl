#version 450 core
struct WeftFrame {
    mat4x4 view_proj;
    mat4x4 view;
    vec4 camera_position;
    vec4 light_direction;
    vec4 light_color;
    vec4 sh[9];
    vec4 params;
    vec4 viewport;
};
struct WeftObject {
    mat4x4 model;
    mat4x4 normal_matrix;
};
struct WeftMaterial {
    vec4 thread1_color;
    float thread1_coverage;
    float thread1_ior;
    float thread1_gamma_s;
    float thread1_gamma_v;
    float thread1_isotropy;
    vec4 thread1_curve[9];
    vec4 thread1_offsets_a;
    vec4 thread1_offsets_b;
    int thread1_offset_count;
    vec4 thread2_color;
    float thread2_coverage;
    float thread2_ior;
    float thread2_gamma_s;
    float thread2_gamma_v;
    float thread2_isotropy;
    vec4 thread2_curve[9];
    vec4 thread2_offsets_a;
    vec4 thread2_offsets_b;
    int thread2_offset_count;
    float brightness;
    vec4 albedo_map_st;
};
struct WeftSurface {
    vec3 v;
    vec3 n;
};
struct WeftVertexInput {
    vec3 position;
    vec3 normal;
    vec4 tangent;
    vec2 uv0_;
};
struct WeftVaryings {
    vec4 clip_position;
    vec3 world_position;
    vec3 world_normal;
    vec4 world_tangent;
    vec2 uv0_;
};
struct McThread {
    vec3 albedo;
    float eta;
    float kd;
    float gamma_s;
    float gamma_v;
};
struct McFrame {
    vec3 u;
    vec3 v;
    vec3 n;
};
struct McPsi {
    vec3 pi;
    vec3 pr;
    float u;
    float ok;
};
struct McFastConst {
    vec4 shape;
    vec4 curve;
    vec2 steps;
};
struct MicrocylinderVaryings {
    vec4 clip_position;
    vec3 world_position;
    vec3 world_normal;
    vec4 world_tangent;
    vec2 uv0_;
    vec4 thread1_shape;
    vec4 thread1_curve;
    vec2 thread1_steps;
    vec4 thread2_shape;
    vec4 thread2_curve;
    vec2 thread2_steps;
    vec2 mean_fresnel;
};
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const uint TANGENT_OFFSETS_CURVE = 0u;
const uint TANGENT_OFFSETS_LIST = 1u;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_LOW = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_MIN_ROUGHNESS_HALF = 0.089;
const float WEFT_MIN_N_DOT_HALF = 0.001;
const float WEFT_MIN_ALPHA_HALF = 0.007921;
const uint MC_CURVE_SAMPLES = 33u;
const uint MC_CURVE_SEGMENTS = 32u;
const int MC_MAX_OFFSETS = 8;
const float MC_REF_STEP_DEG = 1.0;
const float MC_REF_MAX_SUBDIV = 64.0;
const float MC_U_INV_TWO_SIGMA2_ = 4.1035185;
const float MC_SQRT_TWO_PI = 2.5066283;
const float MC_DEG = 0.017453292;
const float MC_MIN_GAMMA = 0.0017453292;
const float MC_MIN_PROJ2_ = 1e-8;
const float MC_MIN_COS2_THETA_D = 0.0001;
const float MC_MIN_Q = 1e-6;
const float MC_INV_SQRT_TWO_PI = 0.3989423;
const float MC_FAST_MIN_DT = 0.1;
const float MC_GL3_T = 0.11270166;
const float MC_GL3_W0_ = 0.2777778;
const float MC_GL3_W1_ = 0.44444445;
const float MC_GL3_E0_ = -0.29099444;
const float MC_GL3_E1_ = 0.42621785;
const float MC_FAST_BIG = 1000000.0;
const float MC_FAST_MIN_DSLOPE = 0.0001;
const float MC_FAST_MIN_SPAN = 0.0001;
const float MC_FAST_SPLIT_DEG = 60.0;
const float MC_GL2_T = 0.21132487;
const float MC_GJ2_T = 0.31101775;
const float MC_GL2_E = 0.36602542;
const float MC_GJ2_E = 0.8228757;
const float MC_GJ2_W = 0.36296296;

layout(std140, binding = 0) uniform WeftFrame_block_0Vertex { WeftFrame _group_0_binding_0_vs; };

layout(std140, binding = 2) uniform WeftObject_block_1Vertex { WeftObject _group_2_binding_0_vs; };

layout(std140, binding = 1) uniform WeftMaterial_block_2Vertex { WeftMaterial _group_1_binding_0_vs; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec4 _p2vs_location2;
layout(location = 3) in vec2 _p2vs_location3;
layout(location = 0) smooth out vec3 _vs2fs_location0;
layout(location = 1) smooth out vec3 _vs2fs_location1;
layout(location = 2) smooth out vec4 _vs2fs_location2;
layout(location = 3) smooth out vec2 _vs2fs_location3;
layout(location = 4) flat out vec4 _vs2fs_location4;
layout(location = 5) flat out vec4 _vs2fs_location5;
layout(location = 6) flat out vec2 _vs2fs_location6;
layout(location = 7) flat out vec4 _vs2fs_location7;
layout(location = 8) flat out vec4 _vs2fs_location8;
layout(location = 9) flat out vec2 _vs2fs_location9;
layout(location = 10) flat out vec2 _vs2fs_location10;

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_any_perpendicular(vec3 n) {
    float s = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a_1 = (-1.0 / (s + n.z));
    float b_1 = ((n.x * n.y) * a_1);
    return vec3((1.0 + (((s * n.x) * n.x) * a_1)), (s * b_1), (-(s) * n.x));
}

float weft_f_dielectric(float cos_i, float eta) {
    float c = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c * c));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c);
    float gpc = max((g + c), 1e-7);
    float b_den = max(((c * gmc) + 1.0), 1e-7);
    float b_num = ((c * gpc) - 1.0);
    float inv = (1.0 / (gpc * b_den));
    float f = clamp(((((0.5 * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)), 0.0, 1.0);
    return ((g2_ < 0.0) ? 1.0 : f);
}

float weft_f0_from_ior(float ior) {
    float q = ((ior - 1.0) / max((ior + 1.0), 0.0001));
    return (q * q);
}

vec3 weft_main_light_direction() {
    vec4 _e2 = _group_0_binding_0_vs.light_direction;
    vec3 _e8 = weft_safe_normalize(_e2.xyz, vec3(0.0, 0.0, 1.0));
    return _e8;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_vs.light_color;
    return max(_e2.xyz, vec3(0.0));
}

vec3 weft_view_direction(vec3 world_position, vec3 fallback_1) {
    vec4 _e4 = _group_0_binding_0_vs.camera_position;
    vec3 _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
}

vec3 weft_sh_irradiance(vec3 n_1) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_vs.sh;
    e = (sh[0].xyz * 0.282095);
    vec3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_1.y)));
    vec3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_1.z)));
    vec3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_1.x)));
    vec3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_1.x) * n_1.y)));
    vec3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_1.y) * n_1.z)));
    vec3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0))));
    vec3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_1.x) * n_1.z)));
    vec3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    vec3 _e91 = e;
    return max(_e91, vec3(0.0));
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e6 = weft_view_direction(world_position_1, vec3(0.0, 0.0, 1.0));
    vec3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

WeftVaryings weft_forward_vertex(WeftVertexInput in_2) {
    WeftVaryings out_ = WeftVaryings(vec4(0.0), vec3(0.0), vec3(0.0), vec4(0.0), vec2(0.0));
    mat4x4 model = _group_2_binding_0_vs.model;
    mat3x3 model3_ = mat3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    mat4x4 nm = _group_2_binding_0_vs.normal_matrix;
    mat3x3 normal3_ = mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    vec4 world = (model * vec4(in_2.position, 1.0));
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    mat4x4 _e43 = _group_0_binding_0_vs.view_proj;
    out_.clip_position = (_e43 * vec4(world.xyz, 1.0));
    out_.world_position = world.xyz;
    vec3 _e55 = weft_safe_normalize((normal3_ * in_2.normal), vec3(0.0));
    out_.world_normal = _e55;
    vec3 _e62 = weft_safe_normalize((model3_ * in_2.tangent.xyz), vec3(0.0));
    out_.world_tangent = vec4(_e62, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out_;
    return _e66;
}

mat3x3 weft_tangent_frame(vec3 n_2, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_2);
    vec3 t = (ok ? (t_proj * inversesqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_2 = (cross(n_2, t) * s_1);
    return mat3x3(t, b_2, n_2);
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

float mc_gauss(float gamma, float x) {
    float g_1 = max(gamma, MC_MIN_GAMMA);
    return (exp(((-(x) * x) / ((2.0 * g_1) * g_1))) / (MC_SQRT_TWO_PI * g_1));
}

float mc_correlate(float ci, float cr, float u) {
    float mi = max(ci, 0.0);
    float mr = max(cr, 0.0);
    return ((((1.0 - u) * mi) * mr) + (u * min(mi, mr)));
}

McPsi mc_psi_reference(vec3 v_1, vec3 wi, vec3 wr) {
    vec3 pi = (wi - (v_1 * dot(wi, v_1)));
    vec3 pr = (wr - (v_1 * dot(wr, v_1)));
    float li2_ = dot(pi, pi);
    float lr2_ = dot(pr, pr);
    bool ok_1 = (min(li2_, lr2_) >= MC_MIN_PROJ2_);
    vec3 hi = (pi * inversesqrt(max(li2_, MC_MIN_PROJ2_)));
    vec3 hr = (pr * inversesqrt(max(lr2_, MC_MIN_PROJ2_)));
    float psi_d = atan(length(cross(hi, hr)), dot(hi, hr));
    float u_1 = exp(((-(psi_d) * psi_d) * MC_U_INV_TWO_SIGMA2_));
    return McPsi(hi, hr, u_1, (ok_1 ? 1.0 : 0.0));
}

vec4 mc_lobe_reference(McFrame fr, McPsi psi, vec3 wi_1, vec3 wr_1, float ca, float sa, McThread th) {
    bool local = false;
    vec3 u_2 = ((fr.u * ca) + (fr.n * sa));
    vec3 np = ((fr.n * ca) - (fr.u * sa));
    float si = clamp(dot(wi_1, u_2), -1.0, 1.0);
    float sr = clamp(dot(wr_1, u_2), -1.0, 1.0);
    vec3 pi_1 = (wi_1 - (u_2 * si));
    vec3 pr_1 = (wr_1 - (u_2 * sr));
    float ci2_ = dot(pi_1, pi_1);
    float cr2_ = dot(pr_1, pr_1);
    if (!((min(ci2_, cr2_) < MC_MIN_PROJ2_))) {
        local = (psi.ok == 0.0);
    } else {
        local = true;
    }
    bool _e41 = local;
    if (_e41) {
        return vec4(0.0);
    }
    float ci_1 = sqrt(ci2_);
    float cr_1 = sqrt(cr2_);
    vec3 hi_1 = (pi_1 / vec3(ci_1));
    vec3 hr_1 = (pr_1 / vec3(cr_1));
    float theta_i = atan(si, ci_1);
    float theta_r = atan(sr, cr_1);
    float theta_h = (0.5 * (theta_i + theta_r));
    float theta_d = (0.5 * (theta_i - theta_r));
    float phi_d = atan(length(cross(hi_1, hr_1)), dot(hi_1, hr_1));
    float cos_half_phi = cos((0.5 * phi_d));
    float u_phi = exp(((-(phi_d) * phi_d) * MC_U_INV_TWO_SIGMA2_));
    float _e72 = mc_correlate(dot(np, hi_1), dot(np, hr_1), u_phi);
    float _e78 = mc_correlate(dot(np, psi.pi), dot(np, psi.pr), psi.u);
    float cd = cos(theta_d);
    float cd2_ = max((cd * cd), MC_MIN_COS2_THETA_D);
    float _e85 = weft_f_dielectric((cd * cos_half_phi), th.eta);
    float _e88 = mc_gauss(th.gamma_s, theta_h);
    float surface = ((_e85 * cos_half_phi) * _e88);
    float _e91 = weft_f_dielectric(ci_1, th.eta);
    float _e95 = weft_f_dielectric(cr_1, th.eta);
    float f_t = ((1.0 - _e91) * (1.0 - _e95));
    float _e103 = mc_gauss(th.gamma_v, theta_h);
    float volume = ((f_t * (((1.0 - th.kd) * _e103) + th.kd)) / (ci_1 + cr_1));
    vec3 fs = ((vec3(surface) + (volume * th.albedo)) / vec3(cd2_));
    return vec4((fs * ((_e72 * _e78) * ci_1)), _e78);
}

float mc_offset_at(vec4 a, vec4 b, int k) {
    return ((k >= 4) ? b : a)[(k & 3)];
}

vec4 mc_thread_list_reference(McFrame fr_1, vec3 wi_2, vec3 wr_2, McThread th_1, vec4 offsets_a, vec4 offsets_b, int count) {
    vec4 acc = vec4(0.0);
    int k_1 = 0;
    vec4 seg = vec4(0.0);
    int j = 0;
    int n_3 = min(max(count, 1), MC_MAX_OFFSETS);
    McPsi _e11 = mc_psi_reference(fr_1.v, wi_2, wr_2);
    if ((n_3 == 1)) {
        float a_2 = (offsets_a.x * MC_DEG);
        vec4 _e19 = mc_lobe_reference(fr_1, _e11, wi_2, wr_2, cos(a_2), sin(a_2), th_1);
        return _e19;
    }
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e75 = k_1;
            k_1 = (_e75 + 1);
        }
        loop_init = false;
        int _e25 = k_1;
        if ((_e25 < (n_3 - 1))) {
        } else {
            break;
        }
        {
            int _e29 = k_1;
            float _e30 = mc_offset_at(offsets_a, offsets_b, _e29);
            int _e31 = k_1;
            float _e34 = mc_offset_at(offsets_a, offsets_b, (_e31 + 1));
            float m = clamp(ceil(((abs((_e34 - _e30)) / MC_REF_STEP_DEG) - 0.001)), 1.0, MC_REF_MAX_SUBDIV);
            int mi_1 = int(m);
            seg = vec4(0.0);
            j = 0;
            bool loop_init_1 = true;
            while(true) {
                if (!loop_init_1) {
                    int _e67 = j;
                    j = (_e67 + 1);
                }
                loop_init_1 = false;
                int _e51 = j;
                if ((_e51 < mi_1)) {
                } else {
                    break;
                }
                {
                    int _e53 = j;
                    float a_3 = (mix(_e30, _e34, ((float(_e53) + 0.5) / m)) * MC_DEG);
                    vec4 _e61 = seg;
                    vec4 _e64 = mc_lobe_reference(fr_1, _e11, wi_2, wr_2, cos(a_3), sin(a_3), th_1);
                    seg = (_e61 + _e64);
                }
            }
            vec4 _e69 = acc;
            vec4 _e70 = seg;
            acc = (_e69 + (_e70 / vec4(m)));
        }
    }
    vec4 _e77 = acc;
    return (_e77 / vec4(float((n_3 - 1))));
}

vec3 mc_combine(vec4 t1_, vec4 t2_, float a1_, float a2_, float n_dot_wi, float n_dot_wr) {
    bool local_1 = false;
    bool local_2 = false;
    float c1_ = clamp(a1_, 0.0, 1.0);
    float c2_ = clamp(a2_, 0.0, 1.0);
    float gap = max(((1.0 - c1_) - c2_), 0.0);
    float q_1 = (((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * max(n_dot_wi, 0.0)));
    vec3 s_2 = max(((c1_ * t1_.xyz) + (c2_ * t2_.xyz)), vec3(0.0));
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
    bool lit = local_2;
    return (lit ? (s_2 / vec3(max(q_1, MC_MIN_Q))) : vec3(0.0));
}

McThread microcylinder_thread(vec3 color, float ior_1, float isotropy, float gamma_s_deg, float gamma_v_deg, vec3 tint) {
    return McThread(clamp((color * tint), vec3(0.0), vec3(1.0)), clamp(ior_1, 1.0, 4.0), clamp(isotropy, 0.0, 1.0), (max(gamma_s_deg, 0.0) * MC_DEG), (max(gamma_v_deg, 0.0) * MC_DEG));
}

float microcylinder_mean_fresnel(float eta_1) {
    float _e1 = weft_f0_from_ior(eta_1);
    return (_e1 + ((1.0 - _e1) / 21.0));
}

McFastConst microcylinder_fast_const(McThread th_2, vec4 heights[9]) {
    McFastConst k_2 = McFastConst(vec4(0.0), vec4(0.0), vec2(0.0));
    McFastConst _e4 = k_2;
    return _e4;
}

void main() {
    WeftVertexInput in_ = WeftVertexInput(_p2vs_location0, _p2vs_location1, _p2vs_location2, _p2vs_location3);
    McFastConst k2_ = McFastConst(vec4(0.0), vec4(0.0), vec2(0.0));
    WeftVaryings _e1 = weft_forward_vertex(in_);
    vec4 _e4 = _group_1_binding_0_vs.thread1_color;
    float _e8 = _group_1_binding_0_vs.thread1_ior;
    float _e11 = _group_1_binding_0_vs.thread1_isotropy;
    float _e14 = _group_1_binding_0_vs.thread1_gamma_s;
    float _e17 = _group_1_binding_0_vs.thread1_gamma_v;
    McThread _e20 = microcylinder_thread(_e4.xyz, _e8, _e11, _e14, _e17, vec3(1.0));
    vec4 _e23 = _group_1_binding_0_vs.thread2_color;
    float _e27 = _group_1_binding_0_vs.thread2_ior;
    float _e30 = _group_1_binding_0_vs.thread2_isotropy;
    float _e33 = _group_1_binding_0_vs.thread2_gamma_s;
    float _e36 = _group_1_binding_0_vs.thread2_gamma_v;
    McThread _e39 = microcylinder_thread(_e23.xyz, _e27, _e30, _e33, _e36, vec3(1.0));
    vec4 _e42[9] = _group_1_binding_0_vs.thread1_curve;
    McFastConst _e43 = microcylinder_fast_const(_e20, _e42);
    vec4 _e55 = k2_.shape;
    vec4 _e57 = k2_.curve;
    vec2 _e59 = k2_.steps;
    float _e61 = microcylinder_mean_fresnel(_e20.eta);
    float _e63 = microcylinder_mean_fresnel(_e39.eta);
    MicrocylinderVaryings _tmp_return = MicrocylinderVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, _e43.shape, _e43.curve, _e43.steps, _e55, _e57, _e59, vec2(_e61, _e63));
    gl_Position = _tmp_return.clip_position;
    _vs2fs_location0 = _tmp_return.world_position;
    _vs2fs_location1 = _tmp_return.world_normal;
    _vs2fs_location2 = _tmp_return.world_tangent;
    _vs2fs_location3 = _tmp_return.uv0_;
    _vs2fs_location4 = _tmp_return.thread1_shape;
    _vs2fs_location5 = _tmp_return.thread1_curve;
    _vs2fs_location6 = _tmp_return.thread1_steps;
    _vs2fs_location7 = _tmp_return.thread2_shape;
    _vs2fs_location8 = _tmp_return.thread2_curve;
    _vs2fs_location9 = _tmp_return.thread2_steps;
    _vs2fs_location10 = _tmp_return.mean_fresnel;
    gl_Position.yz = vec2(-gl_Position.y, gl_Position.z * 2.0 - gl_Position.w);
    return;
}

