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
struct McFastNode {
    float x;
    float s;
    float v;
    float p;
};
struct McFastSet {
    vec3 wi;
    vec3 wr;
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
struct WeftMaterial {
    vec4 thread1_curve[9];
    vec4 thread2_curve[9];
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

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 4) flat in vec4 _vs2fs_location4;
layout(location = 5) flat in vec4 _vs2fs_location5;
layout(location = 6) flat in vec2 _vs2fs_location6;
layout(location = 7) flat in vec4 _vs2fs_location7;
layout(location = 8) flat in vec4 _vs2fs_location8;
layout(location = 9) flat in vec2 _vs2fs_location9;
layout(location = 10) flat in vec2 _vs2fs_location10;
layout(location = 0) out vec4 _fs2p_location0;

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_any_perpendicular(vec3 n) {
    float s = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n.z));
    float b = ((n.x * n.y) * a);
    return vec3((1.0 + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
}

vec3 weft_sh_irradiance(vec3 n_1) {
    vec3 e = vec3(0.0);
    e = vec3(0.27778354, 0.32136026, 0.4497644);
    e = (vec3(0.27778354, 0.32136026, 0.4497644) + (vec3(0.2192843, 0.34164187, 0.663193) * (0.488603 * n_1.y)));
    vec3 _e11 = e;
    e = (_e11 + (vec3(0.1352113, 0.12394369, 0.10366199) * (0.488603 * n_1.z)));
    vec3 _e18 = e;
    e = (_e18 + (vec3(-0.14969625, -0.13722156, -0.11476713) * (0.488603 * n_1.x)));
    vec3 _e25 = e;
    e = (_e25 + (vec3(-0.064625785, -0.059240304, -0.049546435) * ((1.092548 * n_1.x) * n_1.y)));
    vec3 _e34 = e;
    e = (_e34 + (vec3(0.05837178, 0.053507466, 0.044751696) * ((1.092548 * n_1.y) * n_1.z)));
    vec3 _e43 = e;
    e = (_e43 + (vec3(0.025110306, 0.023586905, 0.01273896) * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0))));
    vec3 _e56 = e;
    e = (_e56 + (vec3(-0.06322707, -0.057958152, -0.04847409) * ((1.092548 * n_1.x) * n_1.z)));
    vec3 _e65 = e;
    e = (_e65 + (vec3(0.056382716, 0.05266991, 0.031947177) * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    vec3 _e78 = e;
    return max(_e78, vec3(0.0));
}

vec3 weft_safe_normalize_k12_(vec3 v_1) {
    float len2_1 = dot(v_1, v_1);
    return ((len2_1 > 1e-20) ? (v_1 * inversesqrt(max(len2_1, 1e-20))) : vec3(0.0, 0.0, 1.0));
}

vec3 weft_view_direction_k2_(vec3 world_position) {
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
    vec3 _e7 = weft_safe_normalize_k12_((_e4.xyz - world_position));
    return _e7;
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e2 = weft_view_direction_k2_(world_position_1);
    vec3 _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface(_e2, _e3);
}

vec3 weft_safe_normalize_k3_(vec3 v_2) {
    float len2_2 = dot(v_2, v_2);
    return ((len2_2 > 1e-20) ? (v_2 * inversesqrt(max(len2_2, 1e-20))) : vec3(0.0));
}

mat3x3 weft_tangent_frame(vec3 n_2, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_3 = dot(t_proj, t_proj);
    bool ok = (len2_3 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_2);
    vec3 t_1 = (ok ? (t_proj * inversesqrt(max(len2_3, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_2, t_1) * s_1);
    return mat3x3(t_1, b_1, n_2);
}

vec4[2] mc_normal4_(vec4 t) {
    vec4 e_1 = exp(((-0.5 * t) * t));
    vec4 z = (abs(t) * 0.70710677);
    vec4 k_8 = (vec4(1.0) / (vec4(1.0) + (0.3275911 * z)));
    vec4 poly = (k_8 * (vec4(0.2548296) + (k_8 * (vec4(-0.28449672) + (k_8 * (vec4(1.4214138) + (k_8 * (vec4(-1.4531521) + (k_8 * 1.0614054)))))))));
    vec4 half_ = (vec4(0.5) - ((0.5 * poly) * e_1));
    return vec4[2]((e_1 * MC_INV_SQRT_TWO_PI), mix(-(half_), half_, greaterThanEqual(t, vec4(0.0))));
}

vec3 mc_cell_means(vec4 xe, float inv_gamma) {
    vec4 t_2 = (xe * inv_gamma);
    vec4 _e3[2] = mc_normal4_(t_2);
    vec3 dt = (t_2.yzw - t_2.xyz);
    bvec3 wide = greaterThanEqual(abs(dt), vec3(0.1));
    vec3 exact = ((_e3[1].yzw - _e3[1].xyz) / mix(vec3(1.0), dt, wide));
    vec3 trap = (0.5 * (_e3[0].xyz + _e3[0].yzw));
    return (max(mix(trap, exact, wide), vec3(0.0)) * inv_gamma);
}

float mc_u_of_cos(float c) {
    float h_4 = (0.5 - (0.5 * clamp(c, -1.0, 1.0)));
    float x2_ = (h_4 * (1.0 + (0.33333334 * h_4)));
    return exp((-16.414074 * x2_));
}

float mc_fast_correlate(float ci, float cr, float u) {
    float mi = max(ci, 0.0);
    float mr = max(cr, 0.0);
    float prod = (mi * mr);
    return (prod + (u * (min(mi, mr) - prod)));
}

float mc_fast_asin(float x) {
    float ax = min(abs(x), 1.0);
    float r_1 = (1.5707964 - (sqrt((1.0 - ax)) * (1.5707288 + (ax * (-0.2121144 + (ax * (0.074261 - (0.0187293 * ax))))))));
    return ((x < 0.0) ? -(r_1) : r_1);
}

float mc_fresnel_exact(float c_in, float eta2_) {
    float c_2 = clamp(c_in, WEFT_MIN_N_DOT, 1.0);
    float g = sqrt(max(((eta2_ - 1.0) + (c_2 * c_2)), 0.0));
    float ec = (eta2_ * c_2);
    float a_1 = ((g - c_2) * (ec + g));
    float b_2 = ((ec - g) * (g + c_2));
    float d = ((g + c_2) * (ec + g));
    return clamp(((0.5 * ((a_1 * a_1) + (b_2 * b_2))) / (d * d)), 0.0, 1.0);
}

float mc_schlick_t(float c_1) {
    float x_2 = (1.0 - clamp(c_1, 0.0, 1.0));
    float x2_1 = (x_2 * x_2);
    return (1.0 - ((x2_1 * x2_1) * x_2));
}

McFastNode mc_fast_node(McFastSet q, float ca, float sa) {
    bool local = false;
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
    float inv_ci = inversesqrt(max(ci2_, MC_MIN_PROJ2_));
    float inv_cr = inversesqrt(max(cr2_, MC_MIN_PROJ2_));
    float ci_1 = (ci2_ * inv_ci);
    float cr_1 = (cr2_ * inv_cr);
    float cos_phi_d = ((((q.wi.y * q.wr.y) + (ni * nr)) * inv_ci) * inv_cr);
    float cos_half_phi = sqrt(clamp((0.5 + (0.5 * cos_phi_d)), 0.0, 1.0));
    float _e80 = mc_u_of_cos(cos_phi_d);
    float _e81 = mc_fast_correlate((ni * inv_ci), (nr * inv_cr), _e80);
    float _e87 = mc_fast_correlate((ni * q.inv_ri), (nr * q.inv_rr), q.u_psi);
    float cd2_ = max((0.5 + (0.5 * ((ci_1 * cr_1) + (si * sr)))), MC_MIN_COS2_THETA_D);
    float inv_cd = inversesqrt(cd2_);
    float _e105 = mc_fast_asin(clamp(((0.5 * (si + sr)) * inv_cd), -1.0, 1.0));
    float _e109 = mc_fresnel_exact(((cd2_ * inv_cd) * cos_half_phi), q.eta2_);
    float _e111 = mc_schlick_t(ci_1);
    float _e113 = mc_schlick_t(cr_1);
    float f_t = ((q.t02_ * _e111) * _e113);
    float base = (ok_1 ? ((((_e81 * _e87) * ci_1) * inv_cd) * inv_cd) : 0.0);
    return McFastNode(_e105, ((_e109 * cos_half_phi) * base), ((f_t * base) / max((ci_1 + cr_1), 0.0002)), (ok_1 ? _e87 : 0.0));
}

vec3 mc_fast_volume3_(vec3 x_1, float inv_gamma_1) {
    vec3 t_3 = (x_1 * inv_gamma_1);
    return (exp(((-0.5 * t_3) * t_3)) * (MC_INV_SQRT_TWO_PI * inv_gamma_1));
}

float mc_offset_at_k23_(int k) {
    return ((k >= 4) ? vec4(0.0, 0.0, 0.0, 0.0) : vec4(-25.0, -25.0, 25.0, 25.0))[(k & 3)];
}

int mc_fast_pieces_k24_(int k_1) {
    float _e5 = mc_offset_at_k23_((k_1 + 1));
    float _e6 = mc_offset_at_k23_(k_1);
    float span = abs((_e5 - _e6));
    return ((span > MC_FAST_SPLIT_DEG) ? 2 : 1);
}

vec3 mc_list_piece_k14_(int k_2, int h) {
    float _e5 = mc_offset_at_k23_(k_2);
    float d0_ = (_e5 * MC_DEG);
    float _e10 = mc_offset_at_k23_((k_2 + 1));
    float d1_ = (_e10 * MC_DEG);
    int _e13 = mc_fast_pieces_k24_(k_2);
    float fm = float(_e13);
    return vec3(mix(d0_, d1_, (float(h) / fm)), mix(d0_, d1_, (float((h + 1)) / fm)), (1.0 / fm));
}

ivec2 mc_list_next_k15_(int k_3, int h_1) {
    int _e5 = mc_fast_pieces_k24_(k_3);
    int next = (h_1 + 1);
    return ((next >= _e5) ? ivec2((k_3 + 1), 0) : ivec2(k_3, next));
}

vec3 mc_combine_k11_(vec4 t1_, vec4 t2_, float n_dot_wi, float n_dot_wr) {
    bool local_1 = false;
    bool local_2 = false;
    float q_6 = (((0.86 * t1_.w) + (0.14 * t2_.w)) + (0.0 * max(n_dot_wi, 0.0)));
    vec3 s_2 = max(((0.86 * t1_.xyz) + (0.14 * t2_.xyz)), vec3(0.0));
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
    bool lit = local_2;
    return (lit ? (s_2 / vec3(max(q_6, MC_MIN_Q))) : vec3(0.0));
}

McFastConst microcylinder_fast_const_k19_(vec4 heights[9]) {
    McFastConst k_4 = McFastConst(vec4(0.0), vec4(0.0), vec2(0.0));
    {
        {
            k_4.shape = vec4(14.323945, 7.1619725, 1.809025, 0.95717895);
        }
    }
    McFastConst _e6 = k_4;
    return _e6;
}

McFastConst microcylinder_fast_const_k20_(vec4 heights_1[9]) {
    McFastConst k_5 = McFastConst(vec4(0.0), vec4(0.0), vec2(0.0));
    {
        {
            k_5.shape = vec4(11.459156, 5.729578, 1.809025, 0.95717895);
        }
    }
    McFastConst _e6 = k_5;
    return _e6;
}

vec4 mc_fast_rule3_k35_(McFastSet q_1, McFastNode n0_, McFastNode n1_, McFastNode n2_, vec3 r) {
    vec4 xe_1 = vec4((n0_.x + (MC_GL3_E0_ * (n1_.x - n0_.x))), (n0_.x + (MC_GL3_E1_ * (n1_.x - n0_.x))), (n2_.x - (MC_GL3_E1_ * (n2_.x - n1_.x))), (n2_.x - (MC_GL3_E0_ * (n2_.x - n1_.x))));
    vec3 _e36 = mc_cell_means(xe_1, q_1.inv_gamma_s);
    vec3 _e42 = mc_fast_volume3_(vec3(n0_.x, n1_.x, n2_.x), q_1.inv_gamma_v);
    vec3 s_3 = (r * vec3(n0_.s, n1_.s, n2_.s));
    vec3 v_3 = (r * vec3(n0_.v, n1_.v, n2_.v));
    float surface = dot(_e36, s_3);
    float volume = ((0.9 * dot(_e42, v_3)) + (0.1 * ((v_3.x + v_3.y) + v_3.z)));
    return vec4((vec3(surface) + (volume * vec3(0.019999137, 0.2000007, 0.07999783))), dot(r, vec3(n0_.p, n1_.p, n2_.p)));
}

vec4 mc_fast_segment_k29_(McFastSet q_2, float a0_, float a1_, float lo_s, float hi_s) {
    float span_1 = abs((a1_ - a0_));
    bool flat_ = (span_1 < MC_FAST_MIN_SPAN);
    float lo = clamp(lo_s, min(a0_, a1_), max(a0_, a1_));
    float hi = clamp(hi_s, lo, max(a0_, a1_));
    float w = (hi - lo);
    vec3 al = vec3((lo + (MC_GL3_T * w)), (lo + (0.5 * w)), (hi - (MC_GL3_T * w)));
    vec3 ca_1 = cos(al);
    vec3 sa_1 = sin(al);
    McFastNode _e30 = mc_fast_node(q_2, ca_1.x, sa_1.x);
    McFastNode _e33 = mc_fast_node(q_2, ca_1.y, sa_1.y);
    McFastNode _e36 = mc_fast_node(q_2, ca_1.z, sa_1.z);
    vec3 r_2 = (vec3(0.2777778, 0.44444445, 0.2777778) * (flat_ ? 1.0 : (w / max(span_1, MC_FAST_MIN_SPAN))));
    vec4 _e44 = mc_fast_rule3_k35_(q_2, _e30, _e33, _e36, r_2);
    return _e44;
}

McFastSet mc_fast_setup_k37_(McFrame fr, vec3 wr, vec4 shape) {
    vec3 li = vec3(dot(vec3(-0.61984503, 0.54986256, 0.55986005), fr.u), dot(vec3(-0.61984503, 0.54986256, 0.55986005), fr.v), dot(vec3(-0.61984503, 0.54986256, 0.55986005), fr.n));
    vec3 lr = vec3(dot(wr, fr.u), dot(wr, fr.v), dot(wr, fr.n));
    float ri2_ = ((li.x * li.x) + (li.z * li.z));
    float rr2_ = ((lr.x * lr.x) + (lr.z * lr.z));
    bool ok_2 = (min(ri2_, rr2_) >= MC_MIN_PROJ2_);
    float inv_ri = inversesqrt(max(ri2_, MC_MIN_PROJ2_));
    float inv_rr = inversesqrt(max(rr2_, MC_MIN_PROJ2_));
    float _e50 = mc_u_of_cos(((((li.x * lr.x) + (li.z * lr.z)) * inv_ri) * inv_rr));
    float bi = (li.z / ((li.x < 0.0) ? min(li.x, -1e-12) : max(li.x, 1e-12)));
    float br = (lr.z / ((lr.x < 0.0) ? min(lr.x, -1e-12) : max(lr.x, 1e-12)));
    float s_lo = max(((li.x < 0.0) ? bi : -1000000.0), ((lr.x < 0.0) ? br : -1000000.0));
    float s_hi = min(((li.x > 0.0) ? bi : MC_FAST_BIG), ((lr.x > 0.0) ? br : MC_FAST_BIG));
    return McFastSet(li, lr, inv_ri, inv_rr, _e50, (ok_2 ? 1.0 : 0.0), shape.x, shape.y, clamp(s_lo, -1000000.0, MC_FAST_BIG), clamp(s_hi, -1000000.0, MC_FAST_BIG), shape.z, shape.w);
}

vec4 mc_thread_list_fast_with_k32_(McFrame fr_1, vec3 wr_1, vec4 shape_1) {
    vec4 acc = vec4(0.0);
    int k_6 = 0;
    int h_2 = 0;
    int i = 0;
    McFastSet _e9 = mc_fast_setup_k37_(fr_1, wr_1, shape_1);
    float lo_s_2 = atan(_e9.s_lo);
    float hi_s_2 = atan(_e9.s_hi);
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e42 = i;
            i = (_e42 + 1);
        }
        loop_init = false;
        int _e24 = i;
        if ((_e24 < 3)) {
        } else {
            break;
        }
        {
            int _e26 = k_6;
            int _e27 = h_2;
            vec3 _e28 = mc_list_piece_k14_(_e26, _e27);
            vec4 _e29 = acc;
            vec4 _e32 = mc_fast_segment_k29_(_e9, _e28.x, _e28.y, lo_s_2, hi_s_2);
            acc = (_e29 + (_e32 * _e28.z));
            int _e36 = k_6;
            int _e37 = h_2;
            ivec2 _e38 = mc_list_next_k15_(_e36, _e37);
            k_6 = _e38.x;
            h_2 = _e38.y;
        }
    }
    vec4 _e44 = acc;
    return (_e44 / vec4(3.0));
}

vec4 mc_fast_rule3_k44_(McFastSet q_3, McFastNode n0_1, McFastNode n1_1, McFastNode n2_1) {
    vec4 xe_2 = vec4((n0_1.x + (MC_GL3_E0_ * (n1_1.x - n0_1.x))), (n0_1.x + (MC_GL3_E1_ * (n1_1.x - n0_1.x))), (n2_1.x - (MC_GL3_E1_ * (n2_1.x - n1_1.x))), (n2_1.x - (MC_GL3_E0_ * (n2_1.x - n1_1.x))));
    vec3 _e36 = mc_cell_means(xe_2, q_3.inv_gamma_s);
    vec3 _e42 = mc_fast_volume3_(vec3(n0_1.x, n1_1.x, n2_1.x), q_3.inv_gamma_v);
    vec3 s_4 = (vec3(0.2777778, 0.44444445, 0.2777778) * vec3(n0_1.s, n1_1.s, n2_1.s));
    vec3 v_4 = (vec3(0.2777778, 0.44444445, 0.2777778) * vec3(n0_1.v, n1_1.v, n2_1.v));
    float surface_1 = dot(_e36, s_4);
    float volume_1 = ((0.9 * dot(_e42, v_4)) + (0.1 * ((v_4.x + v_4.y) + v_4.z)));
    return vec4((vec3(surface_1) + (volume_1 * vec3(0.60000384, 0.0, 0.060000107))), dot(vec3(0.2777778, 0.44444445, 0.2777778), vec3(n0_1.p, n1_1.p, n2_1.p)));
}

McFastNode mc_fast_node_k45_(McFastSet q_4) {
    bool local_3 = false;
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
    float inv_ci_1 = inversesqrt(max(ci2_1, MC_MIN_PROJ2_));
    float inv_cr_1 = inversesqrt(max(cr2_1, MC_MIN_PROJ2_));
    float ci_2 = (ci2_1 * inv_ci_1);
    float cr_2 = (cr2_1 * inv_cr_1);
    float cos_phi_d_1 = ((((q_4.wi.y * q_4.wr.y) + (ni_1 * nr_1)) * inv_ci_1) * inv_cr_1);
    float cos_half_phi_1 = sqrt(clamp((0.5 + (0.5 * cos_phi_d_1)), 0.0, 1.0));
    float _e76 = mc_u_of_cos(cos_phi_d_1);
    float _e77 = mc_fast_correlate((ni_1 * inv_ci_1), (nr_1 * inv_cr_1), _e76);
    float _e83 = mc_fast_correlate((ni_1 * q_4.inv_ri), (nr_1 * q_4.inv_rr), q_4.u_psi);
    float cd2_1 = max((0.5 + (0.5 * ((ci_2 * cr_2) + (si_1 * sr_1)))), MC_MIN_COS2_THETA_D);
    float inv_cd_1 = inversesqrt(cd2_1);
    float _e101 = mc_fast_asin(clamp(((0.5 * (si_1 + sr_1)) * inv_cd_1), -1.0, 1.0));
    float _e105 = mc_fresnel_exact(((cd2_1 * inv_cd_1) * cos_half_phi_1), q_4.eta2_);
    float _e107 = mc_schlick_t(ci_2);
    float _e109 = mc_schlick_t(cr_2);
    float f_t_1 = ((q_4.t02_ * _e107) * _e109);
    float base_1 = (ok_3 ? ((((_e77 * _e83) * ci_2) * inv_cd_1) * inv_cd_1) : 0.0);
    return McFastNode(_e101, ((_e105 * cos_half_phi_1) * base_1), ((f_t_1 * base_1) / max((ci_2 + cr_2), 0.0002)), (ok_3 ? _e83 : 0.0));
}

vec4 mc_fast_segment_k43_(McFastSet q_5, float lo_s_1, float hi_s_1) {
    McFastNode _e13 = mc_fast_node_k45_(q_5);
    McFastNode _e14 = mc_fast_node_k45_(q_5);
    McFastNode _e15 = mc_fast_node_k45_(q_5);
    vec4 _e16 = mc_fast_rule3_k44_(q_5, _e13, _e14, _e15);
    return _e16;
}

vec4 mc_thread_list_fast_with_k33_(McFrame fr_2, vec3 wr_2, vec4 shape_2) {
    vec4 acc_1 = vec4(0.0);
    int k_7 = 0;
    int h_3 = 0;
    int i_1 = 0;
    McFastSet _e9 = mc_fast_setup_k37_(fr_2, wr_2, shape_2);
    float lo_s_3 = atan(_e9.s_lo);
    float hi_s_3 = atan(_e9.s_hi);
    {
        {
            vec4 _e23 = mc_fast_segment_k43_(_e9, lo_s_3, hi_s_3);
            acc_1 = (vec4(0.0) + _e23);
        }
    }
    vec4 _e26 = acc_1;
    return _e26;
}

void main() {
    MicrocylinderVaryings in_1 = MicrocylinderVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3, _vs2fs_location4, _vs2fs_location5, _vs2fs_location6, _vs2fs_location7, _vs2fs_location8, _vs2fs_location9, _vs2fs_location10);
    vec4 s1_ = vec4(0.0);
    vec4 s2_ = vec4(0.0);
    WeftSurface _e9 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_raw = _e9.v;
    vec3 n_3 = _e9.n;
    mat3x3 _e13 = weft_tangent_frame(n_3, in_1.world_tangent);
    vec3 t_4 = _e13[0];
    vec3 b_3 = _e13[1];
    vec3 _e23 = weft_safe_normalize((v_raw + (n_3 * max((0.001 - dot(n_3, v_raw)), 0.0))), n_3);
    McFrame warp = McFrame(t_4, b_3, n_3);
    McFrame weft = McFrame(b_3, t_4, n_3);
    {
        {
            {
                vec4 _e32 = mc_thread_list_fast_with_k32_(warp, _e23, in_1.thread1_shape);
                s1_ = _e32;
                {
                    vec4 _e34 = mc_thread_list_fast_with_k33_(weft, _e23, in_1.thread2_shape);
                    s2_ = _e34;
                }
            }
        }
    }
    vec4 _e35 = s1_;
    vec4 _e36 = s2_;
    vec3 _e39 = mc_combine_k11_(_e35, _e36, dot(n_3, vec3(-0.61984503, 0.54986256, 0.55986005)), dot(n_3, _e23));
    vec3 direct = (_e39 * vec3(3.0, 2.8799999, 2.6999998));
    vec3 amb1_ = (vec3(0.019999137, 0.2000007, 0.07999783) + vec3(in_1.mean_fresnel.x));
    vec3 amb2_ = (vec3(0.60000384, 0.0, 0.060000107) + vec3(in_1.mean_fresnel.y));
    vec3 ambient_albedo = ((0.86 * amb1_) + (0.14 * amb2_));
    vec3 _e56 = weft_sh_irradiance(n_3);
    vec3 ambient = (_e56 * ambient_albedo);
    vec3 radiance = clamp((direct + ambient), vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, 1.0);
    return;
}

