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

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 0) uniform sampler2D _group_1_binding_3_fs;

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

float weft_f0_from_ior(float ior) {
    float q_2 = ((ior - 1.0) / max((ior + 1.0), 0.0001));
    return (q_2 * q_2);
}

vec3 weft_main_light_direction() {
    vec4 _e2 = _group_0_binding_0_fs.light_direction;
    vec3 _e8 = weft_safe_normalize(_e2.xyz, vec3(0.0, 0.0, 1.0));
    return _e8;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_fs.light_color;
    return max(_e2.xyz, vec3(0.0));
}

vec3 weft_view_direction(vec3 world_position, vec3 fallback_1) {
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
    vec3 _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
}

vec3 weft_sh_irradiance(vec3 n_1) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_fs.sh;
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

mat3x3 weft_tangent_frame(vec3 n_2, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_2);
    vec3 t_2 = (ok ? (t_proj * inversesqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_2, t_2) * s_1);
    return mat3x3(t_2, b_1, n_2);
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

vec3 mc_combine(vec4 t1_, vec4 t2_, float a1_, float a2_, float n_dot_wi, float n_dot_wr) {
    bool local = false;
    bool local_1 = false;
    float c1_ = clamp(a1_, 0.0, 1.0);
    float c2_ = clamp(a2_, 0.0, 1.0);
    float gap = max(((1.0 - c1_) - c2_), 0.0);
    float q_3 = (((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * max(n_dot_wi, 0.0)));
    vec3 s_2 = max(((c1_ * t1_.xyz) + (c2_ * t2_.xyz)), vec3(0.0));
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
    bool lit = local_1;
    return (lit ? (s_2 / vec3(max(q_3, MC_MIN_Q))) : vec3(0.0));
}

float mc_fast_slope(float s0_, float s1_1, float s2_1, float t) {
    return ((t < 0.5) ? (s0_ + ((s1_1 - s0_) * (2.0 * t))) : (s1_1 + ((s2_1 - s1_1) * ((2.0 * t) - 1.0))));
}

float mc_u_of_cos(float c) {
    float h = (0.5 - (0.5 * clamp(c, -1.0, 1.0)));
    float x2_ = (h * (1.0 + (0.33333334 * h)));
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

vec4 mc_fast_shape(McThread th) {
    float _e2 = weft_f0_from_ior(th.eta);
    return vec4((1.0 / max(th.gamma_s, MC_MIN_GAMMA)), (1.0 / max(th.gamma_v, MC_MIN_GAMMA)), (th.eta * th.eta), ((1.0 - _e2) * (1.0 - _e2)));
}

float mc_fast_half_len(float sa, float sb) {
    vec2 s_3 = vec2(mix(sa, sb, MC_GL2_T), mix(sa, sb, 0.7886751));
    vec2 l = sqrt((vec2(1.0) + (s_3 * s_3)));
    return (0.25 * (l.x + l.y));
}

float mc_fast_clip_step(float sa_1, float sb_1) {
    float ds = (sb_1 - sa_1);
    return (1.0 / ((abs(ds) < MC_FAST_MIN_DSLOPE) ? ((ds >= 0.0) ? MC_FAST_MIN_DSLOPE : -0.0001) : ds));
}

McFastConst mc_fast_const(McThread th_1, vec4 heights[9]) {
    float s0_1 = (32.0 * (((-1.5 * heights[0].x) + (2.0 * heights[0].y)) - (0.5 * heights[0].z)));
    float s1_2 = ((0.5 * 32.0) * (heights[4].y - heights[3].w));
    float s2_2 = (32.0 * (((1.5 * heights[8].x) - (2.0 * heights[7].w)) + (0.5 * heights[7].z)));
    float _e41 = mc_fast_half_len(s0_1, s1_2);
    float _e42 = mc_fast_half_len(s1_2, s2_2);
    float total = (_e41 + _e42);
    vec4 _e44 = mc_fast_shape(th_1);
    float _e50 = mc_fast_clip_step(s0_1, s1_2);
    float _e51 = mc_fast_clip_step(s1_2, s2_2);
    return McFastConst(_e44, vec4(s0_1, s1_2, s2_2, (1.0 / max(total, 1e-6))), vec2(_e50, _e51));
}

McFastSet mc_fast_setup(McFrame fr, vec3 wi, vec3 wr, vec4 shape) {
    vec3 li = vec3(dot(wi, fr.u), dot(wi, fr.v), dot(wi, fr.n));
    vec3 lr = vec3(dot(wr, fr.u), dot(wr, fr.v), dot(wr, fr.n));
    float ri2_ = ((li.x * li.x) + (li.z * li.z));
    float rr2_ = ((lr.x * lr.x) + (lr.z * lr.z));
    bool ok_1 = (min(ri2_, rr2_) >= MC_MIN_PROJ2_);
    float inv_ri = inversesqrt(max(ri2_, MC_MIN_PROJ2_));
    float inv_rr = inversesqrt(max(rr2_, MC_MIN_PROJ2_));
    float _e50 = mc_u_of_cos(((((li.x * lr.x) + (li.z * lr.z)) * inv_ri) * inv_rr));
    float bi = (li.z / ((li.x < 0.0) ? min(li.x, -1e-12) : max(li.x, 1e-12)));
    float br = (lr.z / ((lr.x < 0.0) ? min(lr.x, -1e-12) : max(lr.x, 1e-12)));
    float s_lo_1 = max(((li.x < 0.0) ? bi : -1000000.0), ((lr.x < 0.0) ? br : -1000000.0));
    float s_hi_1 = min(((li.x > 0.0) ? bi : MC_FAST_BIG), ((lr.x > 0.0) ? br : MC_FAST_BIG));
    return McFastSet(li, lr, inv_ri, inv_rr, _e50, (ok_1 ? 1.0 : 0.0), shape.x, shape.y, clamp(s_lo_1, -1000000.0, MC_FAST_BIG), clamp(s_hi_1, -1000000.0, MC_FAST_BIG), shape.z, shape.w);
}

McFastNode mc_fast_node(McFastSet q, float ca, float sa_2) {
    bool local_2 = false;
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
    float base = (ok_2 ? ((((_e81 * _e87) * ci_1) * inv_cd) * inv_cd) : 0.0);
    return McFastNode(_e105, ((_e109 * cos_half_phi) * base), ((f_t * base) / max((ci_1 + cr_1), 0.0002)), (ok_2 ? _e87 : 0.0));
}

vec2 mc_fast_volume2_(vec2 x_1, float inv_gamma) {
    vec2 t_3 = (x_1 * inv_gamma);
    return (exp(((-0.5 * t_3) * t_3)) * (MC_INV_SQRT_TWO_PI * inv_gamma));
}

vec2 mc_fast_clip(float s_lo, float s_hi, float sa_3, float inv, float ta) {
    float u0_ = ((s_lo - sa_3) * inv);
    float u1_ = ((s_hi - sa_3) * inv);
    vec2 u_1 = clamp(vec2(min(u0_, u1_), max(u0_, u1_)), vec2(0.0), vec2(1.0));
    return ((u_1.x < u_1.y) ? (vec2(ta) + (0.5 * u_1)) : vec2(2.0, -1.0));
}

vec3[2] mc_normal3_(vec3 t_1) {
    vec3 e_1 = exp(((-0.5 * t_1) * t_1));
    vec3 z = (abs(t_1) * 0.70710677);
    vec3 k_2 = (vec3(1.0) / (vec3(1.0) + (0.3275911 * z)));
    vec3 poly = (k_2 * (vec3(0.2548296) + (k_2 * (vec3(-0.28449672) + (k_2 * (vec3(1.4214138) + (k_2 * (vec3(-1.4531521) + (k_2 * 1.0614054)))))))));
    vec3 half_ = (vec3(0.5) - ((0.5 * poly) * e_1));
    return vec3[2]((e_1 * MC_INV_SQRT_TWO_PI), mix(-(half_), half_, greaterThanEqual(t_1, vec3(0.0))));
}

vec4 mc_fast_rule2_(McFastSet q_1, McThread th_2, McFastNode n0_, McFastNode n1_, vec2 r, bool jacobi) {
    float e_2 = (jacobi ? MC_GJ2_E : MC_GL2_E);
    float d_1 = (n1_.x - n0_.x);
    vec3 xe = vec3((n0_.x - (e_2 * d_1)), (0.5 * (n0_.x + n1_.x)), (n1_.x + (e_2 * d_1)));
    float dx = ((jacobi ? 1.3228757 : 0.86602545) * d_1);
    vec3 _e30[2] = mc_normal3_((xe * q_1.inv_gamma_s));
    bool wide = ((abs(dx) * q_1.inv_gamma_s) >= MC_FAST_MIN_DT);
    vec2 exact = ((_e30[1].yz - _e30[1].xy) / vec2((wide ? dx : 1.0)));
    vec2 trap = ((0.5 * q_1.inv_gamma_s) * (_e30[0].xy + _e30[0].yz));
    vec2 gs = max((wide ? exact : trap), vec2(0.0));
    vec2 _e62 = mc_fast_volume2_(vec2(n0_.x, n1_.x), q_1.inv_gamma_v);
    vec2 s_4 = (r * vec2(n0_.s, n1_.s));
    vec2 v_1 = (r * vec2(n0_.v, n1_.v));
    float surface = dot(gs, s_4);
    float volume = (((1.0 - th_2.kd) * dot(_e62, v_1)) + (th_2.kd * (v_1.x + v_1.y)));
    return vec4((vec3(surface) + (volume * th_2.albedo)), dot(r, vec2(n0_.p, n1_.p)));
}

vec4 mc_thread_curve_fast_with(McFrame fr_1, vec3 wi_1, vec3 wr_1, McThread th_3, McFastConst k) {
    bool local_3 = false;
    McFastSet _e6 = mc_fast_setup(fr_1, wi_1, wr_1, k.shape);
    float s0_2 = k.curve.x;
    float s1_3 = k.curve.y;
    float s2_3 = k.curve.z;
    vec2 _e18 = mc_fast_clip(_e6.s_lo, _e6.s_hi, s0_2, k.steps.x, 0.0);
    vec2 _e24 = mc_fast_clip(_e6.s_lo, _e6.s_hi, s1_3, k.steps.y, 0.5);
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
    vec2 t_4 = vec2((t0_ + (tn * w)), (t1_1 - (tn * w)));
    float _e50 = mc_fast_slope(s0_2, s1_3, s2_3, t_4.x);
    float _e52 = mc_fast_slope(s0_2, s1_3, s2_3, t_4.y);
    vec2 sl = vec2(_e50, _e52);
    vec2 l2_ = (vec2(1.0) + (sl * sl));
    vec2 inv_len = inversesqrt(l2_);
    McFastNode _e63 = mc_fast_node(_e6, inv_len.x, (sl.x * inv_len.x));
    McFastNode _e68 = mc_fast_node(_e6, inv_len.y, (sl.y * inv_len.y));
    vec2 r_2 = (((bump ? MC_GJ2_W : 0.5) * w) * (l2_ * inv_len));
    vec4 _e75 = mc_fast_rule2_(_e6, th_3, _e63, _e68, r_2, bump);
    return (_e75 * k.curve.w);
}

McThread microcylinder_thread(vec3 color, float ior_1, float isotropy, float gamma_s_deg, float gamma_v_deg, vec3 tint) {
    return McThread(clamp((color * tint), vec3(0.0), vec3(1.0)), clamp(ior_1, 1.0, 4.0), clamp(isotropy, 0.0, 1.0), (max(gamma_s_deg, 0.0) * MC_DEG), (max(gamma_v_deg, 0.0) * MC_DEG));
}

float microcylinder_mean_fresnel(float eta) {
    float _e1 = weft_f0_from_ior(eta);
    return (_e1 + ((1.0 - _e1) / 21.0));
}

McFastConst microcylinder_fast_const(McThread th_4, vec4 heights_1[9]) {
    McFastConst k_1 = McFastConst(vec4(0.0), vec4(0.0), vec2(0.0));
    {
        {
            McFastConst _e4 = mc_fast_const(th_4, heights_1);
            k_1 = _e4;
        }
    }
    McFastConst _e5 = k_1;
    return _e5;
}

void main() {
    MicrocylinderVaryings in_1 = MicrocylinderVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3, _vs2fs_location4, _vs2fs_location5, _vs2fs_location6, _vs2fs_location7, _vs2fs_location8, _vs2fs_location9, _vs2fs_location10);
    vec4 s1_ = vec4(0.0);
    vec4 s2_ = vec4(0.0);
    vec4 _e4 = _group_1_binding_0_fs.albedo_map_st;
    vec2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    vec4 _e8 = texture(_group_1_binding_3_fs, vec2(_e5));
    vec3 tint_1 = max(_e8.xyz, vec3(0.0));
    vec4 _e15 = _group_1_binding_0_fs.thread1_color;
    float _e19 = _group_1_binding_0_fs.thread1_ior;
    float _e22 = _group_1_binding_0_fs.thread1_isotropy;
    float _e25 = _group_1_binding_0_fs.thread1_gamma_s;
    float _e28 = _group_1_binding_0_fs.thread1_gamma_v;
    McThread _e29 = microcylinder_thread(_e15.xyz, _e19, _e22, _e25, _e28, tint_1);
    vec4 _e32 = _group_1_binding_0_fs.thread2_color;
    float _e36 = _group_1_binding_0_fs.thread2_ior;
    float _e39 = _group_1_binding_0_fs.thread2_isotropy;
    float _e42 = _group_1_binding_0_fs.thread2_gamma_s;
    float _e45 = _group_1_binding_0_fs.thread2_gamma_v;
    McThread _e46 = microcylinder_thread(_e32.xyz, _e36, _e39, _e42, _e45, tint_1);
    float _e49 = _group_1_binding_0_fs.thread1_coverage;
    float a1_1 = clamp(_e49, 0.0, 1.0);
    float _e53 = _group_1_binding_0_fs.thread2_coverage;
    float a2_1 = (false ? clamp(_e53, 0.0, 1.0) : 0.0);
    float _e60 = _group_1_binding_0_fs.brightness;
    float brightness = max(_e60, 0.0);
    WeftSurface _e65 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_raw = _e65.v;
    vec3 n_3 = _e65.n;
    mat3x3 _e69 = weft_tangent_frame(n_3, in_1.world_tangent);
    vec3 t_5 = _e69[0];
    vec3 b_3 = _e69[1];
    vec3 _e79 = weft_safe_normalize((v_raw + (n_3 * max((0.001 - dot(n_3, v_raw)), 0.0))), n_3);
    vec3 _e80 = weft_main_light_direction();
    McFrame warp = McFrame(t_5, b_3, n_3);
    McFrame weft = McFrame(b_3, t_5, n_3);
    {
        {
            {
                vec4 _e93 = mc_thread_curve_fast_with(warp, _e80, _e79, _e29, McFastConst(in_1.thread1_shape, in_1.thread1_curve, in_1.thread1_steps));
                s1_ = _e93;
            }
        }
    }
    vec4 _e94 = s1_;
    vec4 _e95 = s2_;
    vec3 _e98 = mc_combine(_e94, _e95, a1_1, a2_1, dot(n_3, _e80), dot(n_3, _e79));
    vec3 _e99 = weft_main_light_radiance();
    vec3 direct = (_e98 * _e99);
    vec3 amb1_ = (_e29.albedo + vec3(in_1.mean_fresnel.x));
    vec3 amb2_ = (_e46.albedo + vec3(in_1.mean_fresnel.y));
    float cov = (a1_1 + a2_1);
    vec3 ambient_albedo = ((cov > 0.0001) ? (((a1_1 * amb1_) + (a2_1 * amb2_)) / vec3(max(cov, 0.0001))) : amb1_);
    vec3 _e122 = weft_sh_irradiance(n_3);
    vec3 ambient = (_e122 * ambient_albedo);
    vec3 radiance = clamp(((direct + ambient) * brightness), vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, 1.0);
    return;
}

