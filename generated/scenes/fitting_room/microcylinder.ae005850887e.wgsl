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

struct McFastNode {
    x: f32,
    s: f32,
    v: f32,
    p: f32,
}

struct McFastSet {
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
    eta2_: f32,
    t02_: f32,
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

struct WeftMaterial {
    thread1_curve: array<vec4<f32>, 9>,
    thread2_curve: array<vec4<f32>, 9>,
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

fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v, v);
    return select(fallback, (v * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_any_perpendicular(n: vec3<f32>) -> vec3<f32> {
    let s = select(-1f, 1f, (n.z >= 0f));
    let a = (-1f / (s + n.z));
    let b = ((n.x * n.y) * a);
    return vec3<f32>((1f + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
}

fn weft_sh_irradiance(n_1: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    e = vec3<f32>(0.27778354f, 0.32136026f, 0.4497644f);
    e = (vec3<f32>(0.27778354f, 0.32136026f, 0.4497644f) + (vec3<f32>(0.2192843f, 0.34164187f, 0.663193f) * (0.488603f * n_1.y)));
    let _e11 = e;
    e = (_e11 + (vec3<f32>(0.1352113f, 0.12394369f, 0.10366199f) * (0.488603f * n_1.z)));
    let _e18 = e;
    e = (_e18 + (vec3<f32>(-0.14969625f, -0.13722156f, -0.11476713f) * (0.488603f * n_1.x)));
    let _e25 = e;
    e = (_e25 + (vec3<f32>(-0.064625785f, -0.059240304f, -0.049546435f) * ((1.092548f * n_1.x) * n_1.y)));
    let _e34 = e;
    e = (_e34 + (vec3<f32>(0.05837178f, 0.053507466f, 0.044751696f) * ((1.092548f * n_1.y) * n_1.z)));
    let _e43 = e;
    e = (_e43 + (vec3<f32>(0.025110306f, 0.023586905f, 0.01273896f) * (0.315392f * (((3f * n_1.z) * n_1.z) - 1f))));
    let _e56 = e;
    e = (_e56 + (vec3<f32>(-0.06322707f, -0.057958152f, -0.04847409f) * ((1.092548f * n_1.x) * n_1.z)));
    let _e65 = e;
    e = (_e65 + (vec3<f32>(0.056382716f, 0.05266991f, 0.031947177f) * (0.546274f * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    let _e78 = e;
    return max(_e78, vec3(0f));
}

fn weft_safe_normalize_k9_(v_1: vec3<f32>) -> vec3<f32> {
    let len2_1 = dot(v_1, v_1);
    return select(vec3<f32>(0f, 0f, 1f), (v_1 * inverseSqrt(max(len2_1, 0.00000000000000000001f))), (len2_1 > 0.00000000000000000001f));
}

fn weft_view_direction_k2_(world_position: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_frame.camera_position;
    let _e7 = weft_safe_normalize_k9_((_e4.xyz - world_position));
    return _e7;
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e2 = weft_view_direction_k2_(world_position_1);
    let _e3 = weft_safe_normalize(world_normal, _e2);
    return WeftSurface(_e2, _e3);
}

fn weft_safe_normalize_k3_(v_2: vec3<f32>) -> vec3<f32> {
    let len2_2 = dot(v_2, v_2);
    return select(vec3(0f), (v_2 * inverseSqrt(max(len2_2, 0.00000000000000000001f))), (len2_2 > 0.00000000000000000001f));
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
    let _e53 = weft_safe_normalize_k3_((normal3_ * in_2.normal));
    out.world_normal = _e53;
    let _e58 = weft_safe_normalize_k3_((model3_ * in_2.tangent.xyz));
    out.world_tangent = vec4<f32>(_e58, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    let _e62 = out;
    return _e62;
}

fn weft_tangent_frame(n_2: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    let len2_3 = dot(t_proj, t_proj);
    let ok = (len2_3 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_2);
    let t_1 = select(_e13, (t_proj * inverseSqrt(max(len2_3, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_2, t_1) * s_1);
    return mat3x3<f32>(t_1, b_1, n_2);
}

fn mc_normal4_(t: vec4<f32>) -> array<vec4<f32>, 2> {
    let e_1 = exp(((-0.5f * t) * t));
    let z = (abs(t) * 0.70710677f);
    let k_2 = (vec4(1f) / (vec4(1f) + (0.3275911f * z)));
    let poly = (k_2 * (vec4(0.2548296f) + (k_2 * (vec4(-0.28449672f) + (k_2 * (vec4(1.4214138f) + (k_2 * (vec4(-1.4531521f) + (k_2 * 1.0614054f)))))))));
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

fn mc_u_of_cos(c: f32) -> f32 {
    let h_1 = (0.5f - (0.5f * clamp(c, -1f, 1f)));
    let x2_ = (h_1 * (1f + (0.33333334f * h_1)));
    return exp((-16.414074f * x2_));
}

fn mc_fast_correlate(ci: f32, cr: f32, u: f32) -> f32 {
    let mi = max(ci, 0f);
    let mr = max(cr, 0f);
    let prod = (mi * mr);
    return (prod + (u * (min(mi, mr) - prod)));
}

fn mc_fast_asin(x: f32) -> f32 {
    let ax = min(abs(x), 1f);
    let r_1 = (1.5707964f - (sqrt((1f - ax)) * (1.5707288f + (ax * (-0.2121144f + (ax * (0.074261f - (0.0187293f * ax))))))));
    return select(r_1, -(r_1), (x < 0f));
}

fn mc_fresnel_exact(c_in: f32, eta2_: f32) -> f32 {
    let c_2 = clamp(c_in, WEFT_MIN_N_DOT, 1f);
    let g = sqrt(max(((eta2_ - 1f) + (c_2 * c_2)), 0f));
    let ec = (eta2_ * c_2);
    let a_1 = ((g - c_2) * (ec + g));
    let b_2 = ((ec - g) * (g + c_2));
    let d = ((g + c_2) * (ec + g));
    return saturate(((0.5f * ((a_1 * a_1) + (b_2 * b_2))) / (d * d)));
}

fn mc_schlick_t(c_1: f32) -> f32 {
    let x_2 = (1f - saturate(c_1));
    let x2_1 = (x_2 * x_2);
    return (1f - ((x2_1 * x2_1) * x_2));
}

fn mc_fast_node(q: McFastSet, ca: f32, sa: f32) -> McFastNode {
    var local: bool;

    let si = ((q.wi.x * ca) + (q.wi.z * sa));
    let sr = ((q.wr.x * ca) + (q.wr.z * sa));
    let ni = ((q.wi.z * ca) - (q.wi.x * sa));
    let nr = ((q.wr.z * ca) - (q.wr.x * sa));
    let ci2_ = ((q.wi.y * q.wi.y) + (ni * ni));
    let cr2_ = ((q.wr.y * q.wr.y) + (nr * nr));
    if (min(ci2_, cr2_) >= MC_MIN_PROJ2_) {
        local = (q.ok != 0f);
    } else {
        local = false;
    }
    let ok_1 = local;
    let inv_ci = inverseSqrt(max(ci2_, MC_MIN_PROJ2_));
    let inv_cr = inverseSqrt(max(cr2_, MC_MIN_PROJ2_));
    let ci_1 = (ci2_ * inv_ci);
    let cr_1 = (cr2_ * inv_cr);
    let cos_phi_d = ((((q.wi.y * q.wr.y) + (ni * nr)) * inv_ci) * inv_cr);
    let cos_half_phi = sqrt(saturate((0.5f + (0.5f * cos_phi_d))));
    let _e80 = mc_u_of_cos(cos_phi_d);
    let _e81 = mc_fast_correlate((ni * inv_ci), (nr * inv_cr), _e80);
    let _e87 = mc_fast_correlate((ni * q.inv_ri), (nr * q.inv_rr), q.u_psi);
    let cd2_ = max((0.5f + (0.5f * ((ci_1 * cr_1) + (si * sr)))), MC_MIN_COS2_THETA_D);
    let inv_cd = inverseSqrt(cd2_);
    let _e105 = mc_fast_asin(clamp(((0.5f * (si + sr)) * inv_cd), -1f, 1f));
    let _e109 = mc_fresnel_exact(((cd2_ * inv_cd) * cos_half_phi), q.eta2_);
    let _e111 = mc_schlick_t(ci_1);
    let _e113 = mc_schlick_t(cr_1);
    let f_t = ((q.t02_ * _e111) * _e113);
    let base = select(0f, ((((_e81 * _e87) * ci_1) * inv_cd) * inv_cd), ok_1);
    return McFastNode(_e105, ((_e109 * cos_half_phi) * base), ((f_t * base) / max((ci_1 + cr_1), 0.0002f)), select(0f, _e87, ok_1));
}

fn mc_fast_volume3_(x_1: vec3<f32>, inv_gamma_1: f32) -> vec3<f32> {
    let t_3 = (x_1 * inv_gamma_1);
    return (exp(((-0.5f * t_3) * t_3)) * (MC_INV_SQRT_TWO_PI * inv_gamma_1));
}

fn mc_combine_k8_(t1_: vec4<f32>, t2_: vec4<f32>, n_dot_wi: f32, n_dot_wr: f32) -> vec3<f32> {
    var local_1: bool;
    var local_2: bool;

    let q_3 = (((0.33f * t1_.w) + (0.33f * t2_.w)) + (0.33999994f * max(n_dot_wi, 0f)));
    let s_2 = max(((0.33f * t1_.xyz) + (0.33f * t2_.xyz)), vec3(0f));
    if (n_dot_wi > 0f) {
        local_1 = (n_dot_wr > 0f);
    } else {
        local_1 = false;
    }
    let _e32 = local_1;
    if _e32 {
        local_2 = (q_3 > MC_MIN_Q);
    } else {
        local_2 = false;
    }
    let lit = local_2;
    return select(vec3(0f), (s_2 / vec3(max(q_3, MC_MIN_Q))), lit);
}

fn microcylinder_fast_const_k13_(heights: array<vec4<f32>, 9>) -> McFastConst {
    var k: McFastConst = McFastConst();

    {
        {
            k.shape = vec4<f32>(4.774648f, 2.387324f, 2.1316001f, 0.9312906f);
        }
    }
    let _e6 = k;
    return _e6;
}

fn mc_fast_rule3_k22_(q_1: McFastSet, n0_: McFastNode, n1_: McFastNode, n2_: McFastNode, r: vec3<f32>) -> vec4<f32> {
    let xe_1 = vec4<f32>((n0_.x + (MC_GL3_E0_ * (n1_.x - n0_.x))), (n0_.x + (MC_GL3_E1_ * (n1_.x - n0_.x))), (n2_.x - (MC_GL3_E1_ * (n2_.x - n1_.x))), (n2_.x - (MC_GL3_E0_ * (n2_.x - n1_.x))));
    let _e36 = mc_cell_means(xe_1, q_1.inv_gamma_s);
    let _e42 = mc_fast_volume3_(vec3<f32>(n0_.x, n1_.x, n2_.x), q_1.inv_gamma_v);
    let s_3 = (r * vec3<f32>(n0_.s, n1_.s, n2_.s));
    let v_3 = (r * vec3<f32>(n0_.v, n1_.v, n2_.v));
    let surface = dot(_e36, s_3);
    let volume = ((0.7f * dot(_e42, v_3)) + (0.3f * ((v_3.x + v_3.y) + v_3.z)));
    return vec4<f32>((vec3(surface) + (volume * vec3<f32>(0.060000107f, 0.23999724f, 0.2999983f))), dot(r, vec3<f32>(n0_.p, n1_.p, n2_.p)));
}

fn mc_fast_setup_k23_(fr: McFrame, wr: vec3<f32>, shape: vec4<f32>) -> McFastSet {
    let li = vec3<f32>(dot(vec3<f32>(-0.61984503f, 0.54986256f, 0.55986005f), fr.u), dot(vec3<f32>(-0.61984503f, 0.54986256f, 0.55986005f), fr.v), dot(vec3<f32>(-0.61984503f, 0.54986256f, 0.55986005f), fr.n));
    let lr = vec3<f32>(dot(wr, fr.u), dot(wr, fr.v), dot(wr, fr.n));
    let ri2_ = ((li.x * li.x) + (li.z * li.z));
    let rr2_ = ((lr.x * lr.x) + (lr.z * lr.z));
    let ok_2 = (min(ri2_, rr2_) >= MC_MIN_PROJ2_);
    let inv_ri = inverseSqrt(max(ri2_, MC_MIN_PROJ2_));
    let inv_rr = inverseSqrt(max(rr2_, MC_MIN_PROJ2_));
    let _e50 = mc_u_of_cos(((((li.x * lr.x) + (li.z * lr.z)) * inv_ri) * inv_rr));
    let bi = (li.z / select(max(li.x, 0.000000000001f), min(li.x, -0.000000000001f), (li.x < 0f)));
    let br = (lr.z / select(max(lr.x, 0.000000000001f), min(lr.x, -0.000000000001f), (lr.x < 0f)));
    let s_lo = max(select(-1000000f, bi, (li.x < 0f)), select(-1000000f, br, (lr.x < 0f)));
    let s_hi = min(select(MC_FAST_BIG, bi, (li.x > 0f)), select(MC_FAST_BIG, br, (lr.x > 0f)));
    return McFastSet(li, lr, inv_ri, inv_rr, _e50, select(0f, 1f, ok_2), shape.x, shape.y, clamp(s_lo, -1000000f, MC_FAST_BIG), clamp(s_hi, -1000000f, MC_FAST_BIG), shape.z, shape.w);
}

fn mc_fast_segment_k29_(q_2: McFastSet, lo_s: f32, hi_s: f32) -> vec4<f32> {
    let lo = clamp(lo_s, -0.43633232f, 0.43633232f);
    let hi = clamp(hi_s, lo, 0.43633232f);
    let w = (hi - lo);
    let al = vec3<f32>((lo + (MC_GL3_T * w)), (lo + (0.5f * w)), (hi - (MC_GL3_T * w)));
    let ca_1 = cos(al);
    let sa_1 = sin(al);
    let _e28 = mc_fast_node(q_2, ca_1.x, sa_1.x);
    let _e31 = mc_fast_node(q_2, ca_1.y, sa_1.y);
    let _e34 = mc_fast_node(q_2, ca_1.z, sa_1.z);
    let r_2 = (vec3<f32>(0.2777778f, 0.44444445f, 0.2777778f) * (w / 0.87266463f));
    let _e39 = mc_fast_rule3_k22_(q_2, _e28, _e31, _e34, r_2);
    return _e39;
}

fn mc_thread_list_fast_with_k20_(fr_1: McFrame, wr_1: vec3<f32>, shape_1: vec4<f32>) -> vec4<f32> {
    var acc: vec4<f32> = vec4(0f);
    var k_1: i32 = 0i;
    var h: i32 = 0i;
    var i: i32 = 0i;

    let _e9 = mc_fast_setup_k23_(fr_1, wr_1, shape_1);
    let lo_s_1 = atan(_e9.s_lo);
    let hi_s_1 = atan(_e9.s_hi);
    {
        {
            let _e23 = mc_fast_segment_k29_(_e9, lo_s_1, hi_s_1);
            acc = (vec4(0f) + _e23);
        }
    }
    let _e26 = acc;
    return _e26;
}

@vertex 
fn vs_microcylinder(in: WeftVertexInput) -> MicrocylinderVaryings {
    var k2_: McFastConst = McFastConst();

    let _e1 = weft_forward_vertex(in);
    let _e6 = material.thread1_curve;
    let _e7 = microcylinder_fast_const_k13_(_e6);
    {
        let _e12 = material.thread2_curve;
        let _e13 = microcylinder_fast_const_k13_(_e12);
        k2_ = _e13;
    }
    let _e23 = k2_.shape;
    let _e25 = k2_.curve;
    let _e27 = k2_.steps;
    return MicrocylinderVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, _e7.shape, _e7.curve, _e7.steps, _e23, _e25, _e27, vec2<f32>(0.080919966f, 0.080919966f));
}

@fragment 
fn fs_main(in_1: MicrocylinderVaryings) -> @location(0) vec4<f32> {
    var s1_: vec4<f32> = vec4(0f);
    var s2_: vec4<f32> = vec4(0f);

    let _e9 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_raw = _e9.v;
    let n_3 = _e9.n;
    let _e13 = weft_tangent_frame(n_3, in_1.world_tangent);
    let t_4 = _e13[0];
    let b_3 = _e13[1];
    let _e23 = weft_safe_normalize((v_raw + (n_3 * max((0.001f - dot(n_3, v_raw)), 0f))), n_3);
    let warp = McFrame(t_4, b_3, n_3);
    let weft = McFrame(b_3, t_4, n_3);
    {
        {
            {
                let _e32 = mc_thread_list_fast_with_k20_(warp, _e23, in_1.thread1_shape);
                s1_ = _e32;
                {
                    let _e34 = mc_thread_list_fast_with_k20_(weft, _e23, in_1.thread2_shape);
                    s2_ = _e34;
                }
            }
        }
    }
    let _e35 = s1_;
    let _e36 = s2_;
    let _e39 = mc_combine_k8_(_e35, _e36, dot(n_3, vec3<f32>(-0.61984503f, 0.54986256f, 0.55986005f)), dot(n_3, _e23));
    let direct = (_e39 * vec3<f32>(3.2f, 3.05f, 2.8f));
    let amb1_ = (vec3<f32>(0.060000107f, 0.23999724f, 0.2999983f) + vec3(in_1.mean_fresnel.x));
    let amb2_ = (vec3<f32>(0.060000107f, 0.23999724f, 0.2999983f) + vec3(in_1.mean_fresnel.y));
    let ambient_albedo = (((0.33f * amb1_) + (0.33f * amb2_)) / vec3(0.66f));
    let _e58 = weft_sh_irradiance(n_3);
    let ambient = (_e58 * ambient_albedo);
    let radiance = clamp((direct + ambient), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
