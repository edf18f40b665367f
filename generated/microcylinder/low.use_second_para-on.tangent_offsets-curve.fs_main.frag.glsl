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
struct McFastPre {
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
    float eta;
};
struct McFastNode {
    float x;
    float s;
    float v;
    float p;
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
    float s_1 = ((n.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s_1 + n.z));
    float b = ((n.x * n.y) * a);
    return vec3((1.0 + (((s_1 * n.x) * n.x) * a)), (s_1 * b), (-(s_1) * n.x));
}

float weft_f0_from_ior(float ior) {
    float q_3 = ((ior - 1.0) / max((ior + 1.0), 0.0001));
    return (q_3 * q_3);
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
    float s_2 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_2, t_2) * s_2);
    return mat3x3(t_2, b_1, n_2);
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

float weft_half_f_dielectric(float cos_i, float eta) {
    float c = clamp(abs(cos_i), 0.001, 1.0);
    float g2_ = (((eta * eta) - 1.0) + (c * c));
    float g = sqrt(max(g2_, 0.0));
    float gmc = (g - c);
    float gpc = max((g + c), 0.001);
    float a_1 = (gmc / gpc);
    float b_2 = (((c * gpc) - 1.0) / max(((c * gmc) + 1.0), 0.001));
    float f = clamp((((0.5 * a_1) * a_1) * (1.0 + (b_2 * b_2))), 0.0, 1.0);
    return ((g2_ < 0.0) ? 1.0 : f);
}

vec2 weft_half_f_dielectric2_(vec2 cos_i_1, float eta_1) {
    vec2 c_1 = clamp(abs(cos_i_1), vec2(0.001), vec2(1.0));
    vec2 g2_1 = (vec2(((eta_1 * eta_1) - 1.0)) + (c_1 * c_1));
    vec2 g_1 = sqrt(max(g2_1, vec2(0.0)));
    vec2 gmc_1 = (g_1 - c_1);
    vec2 gpc_1 = max((g_1 + c_1), vec2(0.001));
    vec2 a_2 = (gmc_1 / gpc_1);
    vec2 b_3 = (((c_1 * gpc_1) - vec2(1.0)) / max(((c_1 * gmc_1) + vec2(1.0)), vec2(0.001)));
    vec2 f_1 = clamp((((0.5 * a_2) * a_2) * (vec2(1.0) + (b_3 * b_3))), vec2(0.0), vec2(1.0));
    return mix(f_1, vec2(1.0), lessThan(g2_1, vec2(0.0)));
}

float mc_acos_fast(float x) {
    float ax = min(abs(x), 1.0);
    float r_1 = (sqrt((1.0 - ax)) * (1.5707288 + (ax * (-0.2121144 + (ax * (0.074261 - (0.0187293 * ax)))))));
    return ((x < 0.0) ? (WEFT_PI - r_1) : r_1);
}

float mc_asin_fast(float x_1) {
    float _e2 = mc_acos_fast(x_1);
    return (1.5707964 - _e2);
}

vec3 mc_combine(vec4 t1_, vec4 t2_, float a1_, float a2_, float n_dot_wi, float n_dot_wr) {
    bool local = false;
    bool local_1 = false;
    float c1_ = clamp(a1_, 0.0, 1.0);
    float c2_ = clamp(a2_, 0.0, 1.0);
    float gap = max(((1.0 - c1_) - c2_), 0.0);
    float q_4 = (((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * max(n_dot_wi, 0.0)));
    vec3 s_3 = max(((c1_ * t1_.xyz) + (c2_ * t2_.xyz)), vec3(0.0));
    if ((n_dot_wi > 0.0)) {
        local = (n_dot_wr > 0.0);
    } else {
        local = false;
    }
    bool _e37 = local;
    if (_e37) {
        local_1 = (q_4 > MC_MIN_Q);
    } else {
        local_1 = false;
    }
    bool lit = local_1;
    return (lit ? (s_3 / vec3(max(q_4, MC_MIN_Q))) : vec3(0.0));
}

vec4[2] mc_normal4_(vec4 t) {
    vec4 e_1 = exp(((-0.5 * t) * t));
    vec4 z = (abs(t) * 0.70710677);
    vec4 k_1 = (vec4(1.0) / (vec4(1.0) + (0.3275911 * z)));
    vec4 poly = (k_1 * (vec4(0.2548296) + (k_1 * (vec4(-0.28449672) + (k_1 * (vec4(1.4214138) + (k_1 * (vec4(-1.4531521) + (k_1 * 1.0614054)))))))));
    vec4 half_ = (vec4(0.5) - ((0.5 * poly) * e_1));
    return vec4[2]((e_1 * MC_INV_SQRT_TWO_PI), mix(-(half_), half_, greaterThanEqual(t, vec4(0.0))));
}

vec3 mc_cell_means(vec4 xe, float inv_gamma) {
    vec4 t_3 = (xe * inv_gamma);
    vec4 _e3[2] = mc_normal4_(t_3);
    vec3 dt = (t_3.yzw - t_3.xyz);
    bvec3 wide = greaterThanEqual(abs(dt), vec3(0.1));
    vec3 exact = ((_e3[1].yzw - _e3[1].xyz) / mix(vec3(1.0), dt, wide));
    vec3 trap = (0.5 * (_e3[0].xyz + _e3[0].yzw));
    return (max(mix(trap, exact, wide), vec3(0.0)) * inv_gamma);
}

McFastPre mc_fast_pre(McFrame fr, vec3 wi, vec3 wr, McThread th) {
    vec3 li = vec3(dot(wi, fr.u), dot(wi, fr.v), dot(wi, fr.n));
    vec3 lr = vec3(dot(wr, fr.u), dot(wr, fr.v), dot(wr, fr.n));
    float ri2_ = ((li.x * li.x) + (li.z * li.z));
    float rr2_ = ((lr.x * lr.x) + (lr.z * lr.z));
    bool ok_1 = (min(ri2_, rr2_) >= MC_MIN_PROJ2_);
    float inv_ri = inversesqrt(max(ri2_, MC_MIN_PROJ2_));
    float inv_rr = inversesqrt(max(rr2_, MC_MIN_PROJ2_));
    float cos_psi_d = ((((li.x * lr.x) + (li.z * lr.z)) * inv_ri) * inv_rr);
    float _e50 = mc_acos_fast(cos_psi_d);
    float u_psi = exp(((-(_e50) * _e50) * MC_U_INV_TWO_SIGMA2_));
    float bi = (li.z / ((li.x < 0.0) ? min(li.x, -1e-12) : max(li.x, 1e-12)));
    float br = (lr.z / ((lr.x < 0.0) ? min(lr.x, -1e-12) : max(lr.x, 1e-12)));
    float s_lo = max(((li.x < 0.0) ? bi : -1000000.0), ((lr.x < 0.0) ? br : -1000000.0));
    float s_hi = min(((li.x > 0.0) ? bi : MC_FAST_BIG), ((lr.x > 0.0) ? br : MC_FAST_BIG));
    return McFastPre(li, lr, inv_ri, inv_rr, u_psi, (ok_1 ? 1.0 : 0.0), (1.0 / max(th.gamma_s, MC_MIN_GAMMA)), (1.0 / max(th.gamma_v, MC_MIN_GAMMA)), clamp(s_lo, -1000000.0, MC_FAST_BIG), clamp(s_hi, -1000000.0, MC_FAST_BIG), th.eta);
}

vec4 mc_fast_gl3_(McFastPre q, McThread th_1, McFastNode n0_, McFastNode n1_, McFastNode n2_, vec3 r) {
    vec4 xe_1 = vec4((n0_.x + (MC_GL3_E0_ * (n1_.x - n0_.x))), (n0_.x + (MC_GL3_E1_ * (n1_.x - n0_.x))), (n2_.x - (MC_GL3_E1_ * (n2_.x - n1_.x))), (n2_.x - (MC_GL3_E0_ * (n2_.x - n1_.x))));
    vec3 _e36 = mc_cell_means(xe_1, q.inv_gamma_s);
    vec3 _e38 = mc_cell_means(xe_1, q.inv_gamma_v);
    vec3 s_4 = (r * vec3(n0_.s, n1_.s, n2_.s));
    vec3 v_1 = (r * vec3(n0_.v, n1_.v, n2_.v));
    float surface = dot(_e36, s_4);
    float volume = (((1.0 - th_1.kd) * dot(_e38, v_1)) + (th_1.kd * ((v_1.x + v_1.y) + v_1.z)));
    return vec4((vec3(surface) + (volume * th_1.albedo)), dot(r, vec3(n0_.p, n1_.p, n2_.p)));
}

vec2 mc_fast_half_clip(McFastPre q_1, float sa, float sb, float ta) {
    bool local_2 = false;
    float ds = (sb - sa);
    bool flat_ = (abs(ds) < MC_FAST_MIN_DSLOPE);
    float inv = (1.0 / (flat_ ? 1.0 : ds));
    float u0_ = ((q_1.s_lo - sa) * inv);
    float u1_ = ((q_1.s_hi - sa) * inv);
    if ((sa > q_1.s_lo)) {
        local_2 = (sa < q_1.s_hi);
    } else {
        local_2 = false;
    }
    bool _e31 = local_2;
    vec2 uf = (_e31 ? vec2(0.0, 1.0) : vec2(1.0, 0.0));
    vec2 u = (flat_ ? uf : vec2(max(min(u0_, u1_), 0.0), min(max(u0_, u1_), 1.0)));
    return ((u.x < u.y) ? (vec2(ta) + (0.5 * u)) : vec2(2.0, -1.0));
}

float mc_fast_slope(float s0_, float s1_1, float s2_1, float t_1) {
    return ((t_1 < 0.5) ? (s0_ + ((s1_1 - s0_) * (2.0 * t_1))) : (s1_1 + ((s2_1 - s1_1) * ((2.0 * t_1) - 1.0))));
}

float mc_arc_primitive(float s) {
    float h = sqrt((1.0 + (s * s)));
    return (0.5 * ((s * h) + (sign(s) * log((abs(s) + h)))));
}

float mc_fast_half_length(float sa_1, float sb_1) {
    float ds_1 = (sb_1 - sa_1);
    float sm = (0.5 * (sa_1 + sb_1));
    float _e6 = mc_arc_primitive(sb_1);
    float _e7 = mc_arc_primitive(sa_1);
    return ((abs(ds_1) < MC_FAST_MIN_DSLOPE) ? (0.5 * sqrt((1.0 + (sm * sm)))) : ((0.5 * (_e6 - _e7)) / ds_1));
}

McFastNode mc_low_node(McFastPre q_2, float ca, float sa_2) {
    bool local_3 = false;
    float si = clamp(((q_2.wi.x * ca) + (q_2.wi.z * sa_2)), -1.0, 1.0);
    float sr = clamp(((q_2.wr.x * ca) + (q_2.wr.z * sa_2)), -1.0, 1.0);
    float ni = ((q_2.wi.z * ca) - (q_2.wi.x * sa_2));
    float nr = ((q_2.wr.z * ca) - (q_2.wr.x * sa_2));
    float ci2_ = ((q_2.wi.y * q_2.wi.y) + (ni * ni));
    float cr2_ = ((q_2.wr.y * q_2.wr.y) + (nr * nr));
    if ((min(ci2_, cr2_) >= MC_MIN_PROJ2_)) {
        local_3 = (q_2.ok != 0.0);
    } else {
        local_3 = false;
    }
    bool ok_2 = local_3;
    float inv_ci = inversesqrt(max(ci2_, MC_MIN_PROJ2_));
    float inv_cr = inversesqrt(max(cr2_, MC_MIN_PROJ2_));
    float ci_f = (ci2_ * inv_ci);
    float cr_f = (cr2_ * inv_cr);
    float cos_phi_d = clamp(((((q_2.wi.y * q_2.wr.y) + (ni * nr)) * inv_ci) * inv_cr), -1.0, 1.0);
    float _e81 = mc_acos_fast(cos_phi_d);
    float u_phi = exp(((-(_e81) * _e81) * MC_U_INV_TWO_SIGMA2_));
    float _e87 = mc_asin_fast(si);
    float _e88 = mc_asin_fast(sr);
    float x_2 = (0.5 * (_e87 + _e88));
    float ci = float(ci_f);
    float cr = float(cr_f);
    float eta_3 = float(q_2.eta);
    float cos_half_phi = sqrt((0.5 + (0.5 * float(cos_phi_d))));
    vec2 at_i = max(vec2(vec2((ni * inv_ci), (ni * q_2.inv_ri))), vec2(0.0));
    vec2 at_r = max(vec2(vec2((nr * inv_cr), (nr * q_2.inv_rr))), vec2(0.0));
    vec2 blend = vec2(vec2(u_phi, q_2.u_psi));
    vec2 mask = ((((vec2(1.0) - blend) * at_i) * at_r) + (blend * min(at_i, at_r)));
    float m = mask.x;
    float p = mask.y;
    float cd2_ = max((0.5 + (0.5 * float(((ci_f * cr_f) + (si * sr))))), 0.0001);
    float _e143 = weft_half_f_dielectric((sqrt(cd2_) * cos_half_phi), eta_3);
    vec2 _e145 = weft_half_f_dielectric2_(vec2(ci, cr), eta_3);
    float f_t = ((1.0 - _e145.x) * (1.0 - _e145.y));
    float mp = ((m * p) / cd2_);
    float s_5 = (((_e143 * cos_half_phi) * mp) * ci);
    float v_2 = ((f_t * mp) * (ci / max((ci + cr), 0.0002)));
    return McFastNode(x_2, (ok_2 ? float(s_5) : 0.0), (ok_2 ? float(v_2) : 0.0), (ok_2 ? float(p) : 0.0));
}

vec4 mc_thread_curve_low(McFrame fr_1, vec3 wi_1, vec3 wr_1, McThread th_2, vec4 heights[9]) {
    McFastPre _e5 = mc_fast_pre(fr_1, wi_1, wr_1, th_2);
    float s0_1 = (32.0 * (((-1.5 * heights[0].x) + (2.0 * heights[0].y)) - (0.5 * heights[0].z)));
    float s1_2 = ((0.5 * 32.0) * (heights[4].y - heights[3].w));
    float s2_2 = (32.0 * (((1.5 * heights[8].x) - (2.0 * heights[7].w)) + (0.5 * heights[7].z)));
    vec2 _e46 = mc_fast_half_clip(_e5, s0_1, s1_2, 0.0);
    vec2 _e48 = mc_fast_half_clip(_e5, s1_2, s2_2, 0.5);
    float t0_ = min(_e46.x, _e48.x);
    float t1_1 = max(max(_e46.y, _e48.y), t0_);
    float w = (t1_1 - t0_);
    vec3 t_4 = vec3((t0_ + (MC_GL3_T * w)), (t0_ + (0.5 * w)), (t1_1 - (MC_GL3_T * w)));
    float _e68 = mc_fast_slope(s0_1, s1_2, s2_2, t_4.x);
    float _e70 = mc_fast_slope(s0_1, s1_2, s2_2, t_4.y);
    float _e72 = mc_fast_slope(s0_1, s1_2, s2_2, t_4.z);
    vec3 sl = vec3(_e68, _e70, _e72);
    vec3 inv_len = inversesqrt((vec3(1.0) + (sl * sl)));
    McFastNode _e83 = mc_low_node(_e5, inv_len.x, (sl.x * inv_len.x));
    McFastNode _e88 = mc_low_node(_e5, inv_len.y, (sl.y * inv_len.y));
    McFastNode _e93 = mc_low_node(_e5, inv_len.z, (sl.z * inv_len.z));
    vec3 r_2 = ((vec3(0.2777778, 0.44444445, 0.2777778) * w) / inv_len);
    float _e100 = mc_fast_half_length(s0_1, s1_2);
    float _e101 = mc_fast_half_length(s1_2, s2_2);
    float total = (_e100 + _e101);
    vec4 _e103 = mc_fast_gl3_(_e5, th_2, _e83, _e88, _e93, r_2);
    return (_e103 / vec4(max(total, 1e-6)));
}

McThread microcylinder_thread(vec3 color, float ior_1, float isotropy, float gamma_s_deg, float gamma_v_deg, vec3 tint) {
    return McThread(clamp((color * tint), vec3(0.0), vec3(1.0)), clamp(ior_1, 1.0, 4.0), clamp(isotropy, 0.0, 1.0), (max(gamma_s_deg, 0.0) * MC_DEG), (max(gamma_v_deg, 0.0) * MC_DEG));
}

float microcylinder_mean_fresnel(float eta_2) {
    float _e1 = weft_f0_from_ior(eta_2);
    return (_e1 + ((1.0 - _e1) / 21.0));
}

McFastConst microcylinder_fast_const(McThread th_3, vec4 heights_1[9]) {
    McFastConst k = McFastConst(vec4(0.0), vec4(0.0), vec2(0.0));
    McFastConst _e4 = k;
    return _e4;
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
    float a2_1 = (true ? clamp(_e53, 0.0, 1.0) : 0.0);
    float _e60 = _group_1_binding_0_fs.brightness;
    float brightness = max(_e60, 0.0);
    WeftSurface _e65 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_raw = _e65.v;
    vec3 n_3 = _e65.n;
    mat3x3 _e69 = weft_tangent_frame(n_3, in_1.world_tangent);
    vec3 t_5 = _e69[0];
    vec3 b_4 = _e69[1];
    vec3 _e79 = weft_safe_normalize((v_raw + (n_3 * max((0.001 - dot(n_3, v_raw)), 0.0))), n_3);
    vec3 _e80 = weft_main_light_direction();
    McFrame warp = McFrame(t_5, b_4, n_3);
    McFrame weft = McFrame(b_4, t_5, n_3);
    {
        {
            {
                vec4 _e91[9] = _group_1_binding_0_fs.thread1_curve;
                vec4 _e92 = mc_thread_curve_low(warp, _e80, _e79, _e29, _e91);
                s1_ = _e92;
                {
                    vec4 _e95[9] = _group_1_binding_0_fs.thread2_curve;
                    vec4 _e96 = mc_thread_curve_low(weft, _e80, _e79, _e46, _e95);
                    s2_ = _e96;
                }
            }
        }
    }
    vec4 _e97 = s1_;
    vec4 _e98 = s2_;
    vec3 _e101 = mc_combine(_e97, _e98, a1_1, a2_1, dot(n_3, _e80), dot(n_3, _e79));
    vec3 _e102 = weft_main_light_radiance();
    vec3 direct = (_e101 * _e102);
    vec3 amb1_ = (_e29.albedo + vec3(in_1.mean_fresnel.x));
    vec3 amb2_ = (_e46.albedo + vec3(in_1.mean_fresnel.y));
    float cov = (a1_1 + a2_1);
    vec3 ambient_albedo = ((cov > 0.0001) ? (((a1_1 * amb1_) + (a2_1 * amb2_)) / vec3(max(cov, 0.0001))) : amb1_);
    vec3 _e125 = weft_sh_irradiance(n_3);
    vec3 ambient = (_e125 * ambient_albedo);
    vec3 radiance = clamp(((direct + ambient) * brightness), vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, 1.0);
    return;
}

