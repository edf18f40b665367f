struct WeftFrame {
    view_proj: mat4x4<f32>,
    view: mat4x4<f32>,
    camera_position: vec4<f32>,
    light_direction: vec4<f32>,
    light_color: vec4<f32>,
    sh: array<vec4<f32>, 9>,
    params: vec4<f32>,
    viewport: vec4<f32>,
}

struct WeftObject {
    model: mat4x4<f32>,
    normal_matrix: mat4x4<f32>,
}

struct WeftMaterial {
    thread1_color: vec4<f32>,
    thread1_coverage: f32,
    thread1_ior: f32,
    thread1_gamma_s: f32,
    thread1_gamma_v: f32,
    thread1_isotropy: f32,
    thread1_curve: array<vec4<f32>, 9>,
    thread1_offsets_a: vec4<f32>,
    thread1_offsets_b: vec4<f32>,
    thread1_offset_count: i32,
    thread2_color: vec4<f32>,
    thread2_coverage: f32,
    thread2_ior: f32,
    thread2_gamma_s: f32,
    thread2_gamma_v: f32,
    thread2_isotropy: f32,
    thread2_curve: array<vec4<f32>, 9>,
    thread2_offsets_a: vec4<f32>,
    thread2_offsets_b: vec4<f32>,
    thread2_offset_count: i32,
    brightness: f32,
    albedo_map_st: vec4<f32>,
}

struct WeftSurface {
    v: vec3<f32>,
    n: vec3<f32>,
}

struct WeftVertexInput {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) tangent: vec4<f32>,
    @location(3) uv0_: vec2<f32>,
}

struct WeftVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) world_tangent: vec4<f32>,
    @location(3) uv0_: vec2<f32>,
}

struct McThread {
    albedo: vec3<f32>,
    eta: f32,
    kd: f32,
    gamma_s: f32,
    gamma_v: f32,
}

struct McFrame {
    u: vec3<f32>,
    v: vec3<f32>,
    n: vec3<f32>,
}

struct McFastPre {
    wi: vec3<f32>,
    wr: vec3<f32>,
    inv_ri: f32,
    inv_rr: f32,
    u_psi: f32,
    ok: f32,
    inv_gamma_s: f32,
    inv_gamma_v: f32,
    s_lo: f32,
    s_hi: f32,
    eta: f32,
}

struct McFastNode {
    x: f32,
    s: f32,
    v: f32,
    p: f32,
}

struct McFastConst {
    shape: vec4<f32>,
    curve: vec4<f32>,
    steps: vec2<f32>,
}

struct MicrocylinderVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) world_tangent: vec4<f32>,
    @location(3) uv0_: vec2<f32>,
    @location(4) @interpolate(flat) thread1_shape: vec4<f32>,
    @location(5) @interpolate(flat) thread1_curve: vec4<f32>,
    @location(6) @interpolate(flat) thread1_steps: vec2<f32>,
    @location(7) @interpolate(flat) thread2_shape: vec4<f32>,
    @location(8) @interpolate(flat) thread2_curve: vec4<f32>,
    @location(9) @interpolate(flat) thread2_steps: vec2<f32>,
    @location(10) @interpolate(flat) mean_fresnel: vec2<f32>,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const TANGENT_OFFSETS_CURVE: u32 = 0u;
const TANGENT_OFFSETS_LIST: u32 = 1u;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_LOW: u32 = 2u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_MIN_ROUGHNESS_HALF: f32 = 0.089f;
const WEFT_MIN_N_DOT_HALF: f32 = 0.001f;
const WEFT_MIN_ALPHA_HALF: f32 = 0.007921f;
const MC_CURVE_SAMPLES: u32 = 33u;
const MC_CURVE_SEGMENTS: u32 = 32u;
const MC_MAX_OFFSETS: i32 = 8i;
const MC_REF_STEP_DEG: f32 = 1f;
const MC_REF_MAX_SUBDIV: f32 = 64f;
const MC_U_INV_TWO_SIGMA2_: f32 = 4.1035185f;
const MC_SQRT_TWO_PI: f32 = 2.5066283f;
const MC_DEG: f32 = 0.017453292f;
const MC_MIN_GAMMA: f32 = 0.0017453292f;
const MC_MIN_PROJ2_: f32 = 0.00000001f;
const MC_MIN_COS2_THETA_D: f32 = 0.0001f;
const MC_MIN_Q: f32 = 0.000001f;
const MC_INV_SQRT_TWO_PI: f32 = 0.3989423f;
const MC_FAST_MIN_DT: f32 = 0.1f;
const MC_GL3_T: f32 = 0.11270166f;
const MC_GL3_W0_: f32 = 0.2777778f;
const MC_GL3_W1_: f32 = 0.44444445f;
const MC_GL3_E0_: f32 = -0.29099444f;
const MC_GL3_E1_: f32 = 0.42621785f;
const MC_FAST_BIG: f32 = 1000000f;
const MC_FAST_MIN_DSLOPE: f32 = 0.0001f;
const MC_FAST_MIN_SPAN: f32 = 0.0001f;
const MC_FAST_SPLIT_DEG: f32 = 60f;
const MC_GL2_T: f32 = 0.21132487f;
const MC_GJ2_T: f32 = 0.31101775f;
const MC_GL2_E: f32 = 0.36602542f;
const MC_GJ2_E: f32 = 0.8228757f;
const MC_GJ2_W: f32 = 0.36296296f;

@group(0) @binding(0) 
var<uniform> weft_frame: WeftFrame;
@group(2) @binding(0) 
var<uniform> weft_object: WeftObject;
@group(1) @binding(0) 
var<uniform> material: WeftMaterial;
@group(1) @binding(1) 
var material_sampler: sampler;
@group(1) @binding(3) 
var albedo_map: texture_2d<f32>;

fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v, v);
    return select(fallback, (v * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_any_perpendicular(n: vec3<f32>) -> vec3<f32> {
    let s = select(-1f, 1f, (n.z >= 0f));
    let a_1 = (-1f / (s + n.z));
    let b_1 = ((n.x * n.y) * a_1);
    return vec3<f32>((1f + (((s * n.x) * n.x) * a_1)), (s * b_1), (-(s) * n.x));
}

fn weft_f0_from_ior(ior: f32) -> f32 {
    let q_3 = ((ior - 1f) / max((ior + 1f), 0.0001f));
    return (q_3 * q_3);
}

fn weft_main_light_direction() -> vec3<f32> {
    let _e2 = weft_frame.light_direction;
    let _e8 = weft_safe_normalize(_e2.xyz, vec3<f32>(0f, 0f, 1f));
    return _e8;
}

fn weft_main_light_radiance() -> vec3<f32> {
    let _e2 = weft_frame.light_color;
    return max(_e2.xyz, vec3(0f));
}

fn weft_view_direction(world_position: vec3<f32>, fallback_1: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_frame.camera_position;
    let _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
}

fn weft_sh_irradiance(n_1: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    let sh = weft_frame.sh;
    e = (sh[0].xyz * 0.282095f);
    let _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603f * n_1.y)));
    let _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603f * n_1.z)));
    let _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603f * n_1.x)));
    let _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548f * n_1.x) * n_1.y)));
    let _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548f * n_1.y) * n_1.z)));
    let _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392f * (((3f * n_1.z) * n_1.z) - 1f))));
    let _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548f * n_1.x) * n_1.z)));
    let _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274f * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    let _e91 = e;
    return max(_e91, vec3(0f));
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_forward_vertex(in_2: WeftVertexInput) -> WeftVaryings {
    var out: WeftVaryings;

    let model = weft_object.model;
    let model3_ = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm = weft_object.normal_matrix;
    let normal3_ = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = (model * vec4<f32>(in_2.position, 1f));
    let mirror = select(1f, -1f, (determinant(model3_) < 0f));
    let bitangent_sign = (select(1f, -1f, (in_2.tangent.w < 0f)) * mirror);
    let _e43 = weft_frame.view_proj;
    out.clip_position = (_e43 * vec4<f32>(world.xyz, 1f));
    out.world_position = world.xyz;
    let _e55 = weft_safe_normalize((normal3_ * in_2.normal), vec3(0f));
    out.world_normal = _e55;
    let _e62 = weft_safe_normalize((model3_ * in_2.tangent.xyz), vec3(0f));
    out.world_tangent = vec4<f32>(_e62, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    let _e66 = out;
    return _e66;
}

fn weft_tangent_frame(n_2: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    let len2_1 = dot(t_proj, t_proj);
    let ok = (len2_1 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_2);
    let t_1 = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_2 = (cross(n_2, t_1) * s_1);
    return mat3x3<f32>(t_1, b_2, n_2);
}

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn weft_half_f_dielectric(cos_i: f32, eta: f32) -> f32 {
    let c = clamp(abs(cos_i), 0.001f, 1f);
    let g2_ = (((eta * eta) - 1f) + (c * c));
    let g = sqrt(max(g2_, 0f));
    let gmc = (g - c);
    let gpc = max((g + c), 0.001f);
    let a_2 = (gmc / gpc);
    let b_3 = (((c * gpc) - 1f) / max(((c * gmc) + 1f), 0.001f));
    let f = saturate((((0.5f * a_2) * a_2) * (1f + (b_3 * b_3))));
    return select(f, 1f, (g2_ < 0f));
}

fn weft_half_f_dielectric2_(cos_i_1: vec2<f32>, eta_1: f32) -> vec2<f32> {
    let c_1 = clamp(abs(cos_i_1), vec2(0.001f), vec2(1f));
    let g2_1 = (vec2(((eta_1 * eta_1) - 1f)) + (c_1 * c_1));
    let g_1 = sqrt(max(g2_1, vec2(0f)));
    let gmc_1 = (g_1 - c_1);
    let gpc_1 = max((g_1 + c_1), vec2(0.001f));
    let a_3 = (gmc_1 / gpc_1);
    let b_4 = (((c_1 * gpc_1) - vec2(1f)) / max(((c_1 * gmc_1) + vec2(1f)), vec2(0.001f)));
    let f_1 = saturate((((0.5f * a_3) * a_3) * (vec2(1f) + (b_4 * b_4))));
    return select(f_1, vec2(1f), (g2_1 < vec2(0f)));
}

fn mc_acos_fast(x: f32) -> f32 {
    let ax = min(abs(x), 1f);
    let r_1 = (sqrt((1f - ax)) * (1.5707288f + (ax * (-0.2121144f + (ax * (0.074261f - (0.0187293f * ax)))))));
    return select(r_1, (WEFT_PI - r_1), (x < 0f));
}

fn mc_asin_fast(x_1: f32) -> f32 {
    let _e2 = mc_acos_fast(x_1);
    return (1.5707964f - _e2);
}

fn mc_offset_at(a: vec4<f32>, b: vec4<f32>, k: i32) -> f32 {
    return select(a, b, (k >= 4i))[(k & 3i)];
}

fn mc_combine(t1_: vec4<f32>, t2_: vec4<f32>, a1_: f32, a2_: f32, n_dot_wi: f32, n_dot_wr: f32) -> vec3<f32> {
    var local: bool;
    var local_1: bool;

    let c1_ = saturate(a1_);
    let c2_ = saturate(a2_);
    let gap = max(((1f - c1_) - c2_), 0f);
    let q_4 = (((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * max(n_dot_wi, 0f)));
    let s_2 = max(((c1_ * t1_.xyz) + (c2_ * t2_.xyz)), vec3(0f));
    if (n_dot_wi > 0f) {
        local = (n_dot_wr > 0f);
    } else {
        local = false;
    }
    let _e37 = local;
    if _e37 {
        local_1 = (q_4 > MC_MIN_Q);
    } else {
        local_1 = false;
    }
    let lit = local_1;
    return select(vec3(0f), (s_2 / vec3(max(q_4, MC_MIN_Q))), lit);
}

fn mc_normal4_(t: vec4<f32>) -> array<vec4<f32>, 2> {
    let e_1 = exp(((-0.5f * t) * t));
    let z = (abs(t) * 0.70710677f);
    let k_6 = (vec4(1f) / (vec4(1f) + (0.3275911f * z)));
    let poly = (k_6 * (vec4(0.2548296f) + (k_6 * (vec4(-0.28449672f) + (k_6 * (vec4(1.4214138f) + (k_6 * (vec4(-1.4531521f) + (k_6 * 1.0614054f)))))))));
    let half = (vec4(0.5f) - ((0.5f * poly) * e_1));
    return array<vec4<f32>, 2>((e_1 * MC_INV_SQRT_TWO_PI), select(-(half), half, (t >= vec4(0f))));
}

fn mc_cell_means(xe: vec4<f32>, inv_gamma: f32) -> vec3<f32> {
    let t_2 = (xe * inv_gamma);
    let _e3 = mc_normal4_(t_2);
    let dt = (t_2.yzw - t_2.xyz);
    let wide = (abs(dt) >= vec3(0.1f));
    let exact = ((_e3[1].yzw - _e3[1].xyz) / select(vec3(1f), dt, wide));
    let trap = (0.5f * (_e3[0].xyz + _e3[0].yzw));
    return (max(select(trap, exact, wide), vec3(0f)) * inv_gamma);
}

fn mc_fast_pre(fr: McFrame, wi: vec3<f32>, wr: vec3<f32>, th: McThread) -> McFastPre {
    let li = vec3<f32>(dot(wi, fr.u), dot(wi, fr.v), dot(wi, fr.n));
    let lr = vec3<f32>(dot(wr, fr.u), dot(wr, fr.v), dot(wr, fr.n));
    let ri2_ = ((li.x * li.x) + (li.z * li.z));
    let rr2_ = ((lr.x * lr.x) + (lr.z * lr.z));
    let ok_1 = (min(ri2_, rr2_) >= MC_MIN_PROJ2_);
    let inv_ri = inverseSqrt(max(ri2_, MC_MIN_PROJ2_));
    let inv_rr = inverseSqrt(max(rr2_, MC_MIN_PROJ2_));
    let cos_psi_d = ((((li.x * lr.x) + (li.z * lr.z)) * inv_ri) * inv_rr);
    let _e50 = mc_acos_fast(cos_psi_d);
    let u_psi = exp(((-(_e50) * _e50) * MC_U_INV_TWO_SIGMA2_));
    let bi = (li.z / select(max(li.x, 0.000000000001f), min(li.x, -0.000000000001f), (li.x < 0f)));
    let br = (lr.z / select(max(lr.x, 0.000000000001f), min(lr.x, -0.000000000001f), (lr.x < 0f)));
    let s_lo = max(select(-1000000f, bi, (li.x < 0f)), select(-1000000f, br, (lr.x < 0f)));
    let s_hi = min(select(MC_FAST_BIG, bi, (li.x > 0f)), select(MC_FAST_BIG, br, (lr.x > 0f)));
    return McFastPre(li, lr, inv_ri, inv_rr, u_psi, select(0f, 1f, ok_1), (1f / max(th.gamma_s, MC_MIN_GAMMA)), (1f / max(th.gamma_v, MC_MIN_GAMMA)), clamp(s_lo, -1000000f, MC_FAST_BIG), clamp(s_hi, -1000000f, MC_FAST_BIG), th.eta);
}

fn mc_fast_gl3_(q: McFastPre, th_1: McThread, n0_: McFastNode, n1_: McFastNode, n2_: McFastNode, r: vec3<f32>) -> vec4<f32> {
    let xe_1 = vec4<f32>((n0_.x + (MC_GL3_E0_ * (n1_.x - n0_.x))), (n0_.x + (MC_GL3_E1_ * (n1_.x - n0_.x))), (n2_.x - (MC_GL3_E1_ * (n2_.x - n1_.x))), (n2_.x - (MC_GL3_E0_ * (n2_.x - n1_.x))));
    let _e36 = mc_cell_means(xe_1, q.inv_gamma_s);
    let _e38 = mc_cell_means(xe_1, q.inv_gamma_v);
    let s_3 = (r * vec3<f32>(n0_.s, n1_.s, n2_.s));
    let v_1 = (r * vec3<f32>(n0_.v, n1_.v, n2_.v));
    let surface = dot(_e36, s_3);
    let volume = (((1f - th_1.kd) * dot(_e38, v_1)) + (th_1.kd * ((v_1.x + v_1.y) + v_1.z)));
    return vec4<f32>((vec3(surface) + (volume * th_1.albedo)), dot(r, vec3<f32>(n0_.p, n1_.p, n2_.p)));
}

fn mc_low_node(q_1: McFastPre, ca: f32, sa: f32) -> McFastNode {
    var local_2: bool;

    let si = clamp(((q_1.wi.x * ca) + (q_1.wi.z * sa)), -1f, 1f);
    let sr = clamp(((q_1.wr.x * ca) + (q_1.wr.z * sa)), -1f, 1f);
    let ni = ((q_1.wi.z * ca) - (q_1.wi.x * sa));
    let nr = ((q_1.wr.z * ca) - (q_1.wr.x * sa));
    let ci2_ = ((q_1.wi.y * q_1.wi.y) + (ni * ni));
    let cr2_ = ((q_1.wr.y * q_1.wr.y) + (nr * nr));
    if (min(ci2_, cr2_) >= MC_MIN_PROJ2_) {
        local_2 = (q_1.ok != 0f);
    } else {
        local_2 = false;
    }
    let ok_2 = local_2;
    let inv_ci = inverseSqrt(max(ci2_, MC_MIN_PROJ2_));
    let inv_cr = inverseSqrt(max(cr2_, MC_MIN_PROJ2_));
    let ci_f = (ci2_ * inv_ci);
    let cr_f = (cr2_ * inv_cr);
    let cos_phi_d = clamp(((((q_1.wi.y * q_1.wr.y) + (ni * nr)) * inv_ci) * inv_cr), -1f, 1f);
    let _e81 = mc_acos_fast(cos_phi_d);
    let u_phi = exp(((-(_e81) * _e81) * MC_U_INV_TWO_SIGMA2_));
    let _e87 = mc_asin_fast(si);
    let _e88 = mc_asin_fast(sr);
    let x_2 = (0.5f * (_e87 + _e88));
    let ci = f32(ci_f);
    let cr = f32(cr_f);
    let eta_3 = f32(q_1.eta);
    let cos_half_phi = sqrt((0.5f + (0.5f * f32(cos_phi_d))));
    let at_i = max(vec2<f32>(vec2<f32>((ni * inv_ci), (ni * q_1.inv_ri))), vec2(0f));
    let at_r = max(vec2<f32>(vec2<f32>((nr * inv_cr), (nr * q_1.inv_rr))), vec2(0f));
    let blend = vec2<f32>(vec2<f32>(u_phi, q_1.u_psi));
    let mask = ((((vec2(1f) - blend) * at_i) * at_r) + (blend * min(at_i, at_r)));
    let m = mask.x;
    let p = mask.y;
    let cd2_ = max((0.5f + (0.5f * f32(((ci_f * cr_f) + (si * sr))))), 0.0001f);
    let _e143 = weft_half_f_dielectric((sqrt(cd2_) * cos_half_phi), eta_3);
    let _e145 = weft_half_f_dielectric2_(vec2<f32>(ci, cr), eta_3);
    let f_t = ((1f - _e145.x) * (1f - _e145.y));
    let mp = ((m * p) / cd2_);
    let s_4 = (((_e143 * cos_half_phi) * mp) * ci);
    let v_2 = ((f_t * mp) * (ci / max((ci + cr), 0.0002f)));
    return McFastNode(x_2, select(0f, f32(s_4), ok_2), select(0f, f32(v_2), ok_2), select(0f, f32(p), ok_2));
}

fn mc_low_segment(q_2: McFastPre, th_2: McThread, a0_: f32, a1_1: f32, lo_s: f32, hi_s: f32) -> vec4<f32> {
    let span = abs((a1_1 - a0_));
    let flat = (span < MC_FAST_MIN_SPAN);
    let lo = clamp(lo_s, min(a0_, a1_1), max(a0_, a1_1));
    let hi = clamp(hi_s, lo, max(a0_, a1_1));
    let w = (hi - lo);
    let al = vec3<f32>((lo + (MC_GL3_T * w)), (lo + (0.5f * w)), (hi - (MC_GL3_T * w)));
    let ca_1 = cos(al);
    let sa_1 = sin(al);
    let _e30 = mc_low_node(q_2, ca_1.x, sa_1.x);
    let _e33 = mc_low_node(q_2, ca_1.y, sa_1.y);
    let _e36 = mc_low_node(q_2, ca_1.z, sa_1.z);
    let r_2 = (vec3<f32>(0.2777778f, 0.44444445f, 0.2777778f) * select((w / max(span, MC_FAST_MIN_SPAN)), 1f, flat));
    let _e47 = mc_fast_gl3_(q_2, th_2, _e30, _e33, _e36, r_2);
    return _e47;
}

fn mc_list_piece_count(offsets_a: vec4<f32>, offsets_b: vec4<f32>, n_3: i32) -> i32 {
    let spans = abs((vec4<f32>(offsets_a.yzw, offsets_b.x) - offsets_a));
    let spans_b = abs((offsets_b.yzw - offsets_b.xyz));
    let live = (vec4<i32>(0i, 1i, 2i, 3i) < vec4((n_3 - 1i)));
    let live_b = (vec3<i32>(4i, 5i, 6i) < vec3((n_3 - 1i)));
    let per = select(vec4(0i), select(vec4(1i), vec4(2i), (spans > vec4(60f))), live);
    let per_b = select(vec3(0i), select(vec3(1i), vec3(2i), (spans_b > vec3(60f))), live_b);
    return max(((((((per.x + per.y) + per.z) + per.w) + per_b.x) + per_b.y) + per_b.z), 1i);
}

fn mc_fast_pieces(offsets_a_1: vec4<f32>, offsets_b_1: vec4<f32>, k_1: i32) -> i32 {
    let _e5 = mc_offset_at(offsets_a_1, offsets_b_1, (k_1 + 1i));
    let _e6 = mc_offset_at(offsets_a_1, offsets_b_1, k_1);
    let span_1 = abs((_e5 - _e6));
    return select(1i, 2i, (span_1 > MC_FAST_SPLIT_DEG));
}

fn mc_list_piece(offsets_a_2: vec4<f32>, offsets_b_2: vec4<f32>, n_4: i32, k_2: i32, h: i32) -> vec3<f32> {
    let _e5 = mc_offset_at(offsets_a_2, offsets_b_2, k_2);
    let d0_ = (_e5 * MC_DEG);
    let _e10 = mc_offset_at(offsets_a_2, offsets_b_2, (k_2 + 1i));
    let d1_ = select(d0_, (_e10 * MC_DEG), (n_4 > 1i));
    let _e16 = mc_fast_pieces(offsets_a_2, offsets_b_2, k_2);
    let fm = f32(select(1i, _e16, (n_4 > 1i)));
    return vec3<f32>(mix(d0_, d1_, (f32(h) / fm)), mix(d0_, d1_, (f32((h + 1i)) / fm)), (1f / fm));
}

fn mc_list_next(offsets_a_3: vec4<f32>, offsets_b_3: vec4<f32>, n_5: i32, k_3: i32, h_1: i32) -> vec2<i32> {
    let _e5 = mc_fast_pieces(offsets_a_3, offsets_b_3, k_3);
    let m_1 = select(1i, _e5, (n_5 > 1i));
    let next = (h_1 + 1i);
    return select(vec2<i32>(k_3, next), vec2<i32>((k_3 + 1i), 0i), (next >= m_1));
}

fn mc_thread_list_low(fr_1: McFrame, wi_1: vec3<f32>, wr_1: vec3<f32>, th_3: McThread, offsets_a_4: vec4<f32>, offsets_b_4: vec4<f32>, count: i32) -> vec4<f32> {
    var acc: vec4<f32> = vec4(0f);
    var k_4: i32 = 0i;
    var h_2: i32 = 0i;
    var i: i32 = 0i;

    let n_6 = clamp(count, 1i, MC_MAX_OFFSETS);
    let _e10 = mc_fast_pre(fr_1, wi_1, wr_1, th_3);
    let lo_s_1 = atan(_e10.s_lo);
    let hi_s_1 = atan(_e10.s_hi);
    let segments = max((n_6 - 1i), 1i);
    let _e19 = mc_list_piece_count(offsets_a_4, offsets_b_4, n_6);
    loop {
        let _e29 = i;
        if (_e29 < _e19) {
        } else {
            break;
        }
        {
            let _e31 = k_4;
            let _e32 = h_2;
            let _e33 = mc_list_piece(offsets_a_4, offsets_b_4, n_6, _e31, _e32);
            let _e34 = acc;
            let _e37 = mc_low_segment(_e10, th_3, _e33.x, _e33.y, lo_s_1, hi_s_1);
            acc = (_e34 + (_e37 * _e33.z));
            let _e41 = k_4;
            let _e42 = h_2;
            let _e43 = mc_list_next(offsets_a_4, offsets_b_4, n_6, _e41, _e42);
            k_4 = _e43.x;
            h_2 = _e43.y;
        }
        continuing {
            let _e47 = i;
            i = (_e47 + 1i);
        }
    }
    let _e49 = acc;
    return (_e49 / vec4(f32(segments)));
}

fn microcylinder_thread(color: vec3<f32>, ior_1: f32, isotropy: f32, gamma_s_deg: f32, gamma_v_deg: f32, tint: vec3<f32>) -> McThread {
    return McThread(saturate((color * tint)), clamp(ior_1, 1f, 4f), saturate(isotropy), (max(gamma_s_deg, 0f) * MC_DEG), (max(gamma_v_deg, 0f) * MC_DEG));
}

fn microcylinder_mean_fresnel(eta_2: f32) -> f32 {
    let _e1 = weft_f0_from_ior(eta_2);
    return (_e1 + ((1f - _e1) / 21f));
}

fn microcylinder_fast_const(th_4: McThread, heights: array<vec4<f32>, 9>) -> McFastConst {
    var k_5: McFastConst = McFastConst();

    let _e4 = k_5;
    return _e4;
}

@vertex 
fn vs_microcylinder(in: WeftVertexInput) -> MicrocylinderVaryings {
    var k2_: McFastConst = McFastConst();

    let _e1 = weft_forward_vertex(in);
    let _e4 = material.thread1_color;
    let _e8 = material.thread1_ior;
    let _e11 = material.thread1_isotropy;
    let _e14 = material.thread1_gamma_s;
    let _e17 = material.thread1_gamma_v;
    let _e20 = microcylinder_thread(_e4.xyz, _e8, _e11, _e14, _e17, vec3(1f));
    let _e23 = material.thread2_color;
    let _e27 = material.thread2_ior;
    let _e30 = material.thread2_isotropy;
    let _e33 = material.thread2_gamma_s;
    let _e36 = material.thread2_gamma_v;
    let _e39 = microcylinder_thread(_e23.xyz, _e27, _e30, _e33, _e36, vec3(1f));
    let _e42 = material.thread1_curve;
    let _e43 = microcylinder_fast_const(_e20, _e42);
    let _e55 = k2_.shape;
    let _e57 = k2_.curve;
    let _e59 = k2_.steps;
    let _e61 = microcylinder_mean_fresnel(_e20.eta);
    let _e63 = microcylinder_mean_fresnel(_e39.eta);
    return MicrocylinderVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, _e43.shape, _e43.curve, _e43.steps, _e55, _e57, _e59, vec2<f32>(_e61, _e63));
}

@fragment 
fn fs_main(in_1: MicrocylinderVaryings) -> @location(0) vec4<f32> {
    var s1_: vec4<f32> = vec4(0f);
    var s2_: vec4<f32> = vec4(0f);

    let _e4 = material.albedo_map_st;
    let _e5 = weft_transform_uv(in_1.uv0_, _e4);
    let _e8 = textureSample(albedo_map, material_sampler, _e5);
    let tint_1 = max(_e8.xyz, vec3(0f));
    let _e15 = material.thread1_color;
    let _e19 = material.thread1_ior;
    let _e22 = material.thread1_isotropy;
    let _e25 = material.thread1_gamma_s;
    let _e28 = material.thread1_gamma_v;
    let _e29 = microcylinder_thread(_e15.xyz, _e19, _e22, _e25, _e28, tint_1);
    let _e32 = material.thread2_color;
    let _e36 = material.thread2_ior;
    let _e39 = material.thread2_isotropy;
    let _e42 = material.thread2_gamma_s;
    let _e45 = material.thread2_gamma_v;
    let _e46 = microcylinder_thread(_e32.xyz, _e36, _e39, _e42, _e45, tint_1);
    let _e49 = material.thread1_coverage;
    let a1_2 = saturate(_e49);
    let _e53 = material.thread2_coverage;
    let a2_1 = select(0f, saturate(_e53), false);
    let _e60 = material.brightness;
    let brightness = max(_e60, 0f);
    let _e65 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_raw = _e65.v;
    let n_7 = _e65.n;
    let _e69 = weft_tangent_frame(n_7, in_1.world_tangent);
    let t_3 = _e69[0];
    let b_5 = _e69[1];
    let _e79 = weft_safe_normalize((v_raw + (n_7 * max((0.001f - dot(n_7, v_raw)), 0f))), n_7);
    let _e80 = weft_main_light_direction();
    let warp = McFrame(t_3, b_5, n_7);
    let weft = McFrame(b_5, t_3, n_7);
    {
        {
            {
                let _e91 = material.thread1_offsets_a;
                let _e94 = material.thread1_offsets_b;
                let _e97 = material.thread1_offset_count;
                let _e98 = mc_thread_list_low(warp, _e80, _e79, _e29, _e91, _e94, _e97);
                s1_ = _e98;
            }
        }
    }
    let _e99 = s1_;
    let _e100 = s2_;
    let _e103 = mc_combine(_e99, _e100, a1_2, a2_1, dot(n_7, _e80), dot(n_7, _e79));
    let _e104 = weft_main_light_radiance();
    let direct = (_e103 * _e104);
    let amb1_ = (_e29.albedo + vec3(in_1.mean_fresnel.x));
    let amb2_ = (_e46.albedo + vec3(in_1.mean_fresnel.y));
    let cov = (a1_2 + a2_1);
    let ambient_albedo = select(amb1_, (((a1_2 * amb1_) + (a2_1 * amb2_)) / vec3(max(cov, 0.0001f))), (cov > 0.0001f));
    let _e127 = weft_sh_irradiance(n_7);
    let ambient = (_e127 * ambient_albedo);
    let radiance = clamp(((direct + ambient) * brightness), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
