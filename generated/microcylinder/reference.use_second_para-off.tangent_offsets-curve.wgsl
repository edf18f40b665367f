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

struct McPsi {
    pi: vec3<f32>,
    pr: vec3<f32>,
    u: f32,
    ok: f32,
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
    let a = (-1f / (s + n.z));
    let b = ((n.x * n.y) * a);
    return vec3<f32>((1f + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
}

fn weft_f_dielectric(cos_i: f32, eta: f32) -> f32 {
    let c = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1f);
    let g2_ = (((eta * eta) - 1f) + (c * c));
    let g = sqrt(max(g2_, 0f));
    let gmc = (g - c);
    let gpc = max((g + c), 0.0000001f);
    let b_den = max(((c * gmc) + 1f), 0.0000001f);
    let b_num = ((c * gpc) - 1f);
    let inv = (1f / (gpc * b_den));
    let f = saturate(((((0.5f * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)));
    return select(f, 1f, (g2_ < 0f));
}

fn weft_f0_from_ior(ior: f32) -> f32 {
    let q = ((ior - 1f) / max((ior + 1f), 0.0001f));
    return (q * q);
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
    let t = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_2, t) * s_1);
    return mat3x3<f32>(t, b_1, n_2);
}

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn mc_gauss(gamma: f32, x: f32) -> f32 {
    let g_1 = max(gamma, MC_MIN_GAMMA);
    return (exp(((-(x) * x) / ((2f * g_1) * g_1))) / (MC_SQRT_TWO_PI * g_1));
}

fn mc_correlate(ci: f32, cr: f32, u: f32) -> f32 {
    let mi = max(ci, 0f);
    let mr = max(cr, 0f);
    return ((((1f - u) * mi) * mr) + (u * min(mi, mr)));
}

fn mc_psi_reference(v_1: vec3<f32>, wi: vec3<f32>, wr: vec3<f32>) -> McPsi {
    let pi = (wi - (v_1 * dot(wi, v_1)));
    let pr = (wr - (v_1 * dot(wr, v_1)));
    let li2_ = dot(pi, pi);
    let lr2_ = dot(pr, pr);
    let ok_1 = (min(li2_, lr2_) >= MC_MIN_PROJ2_);
    let hi = (pi * inverseSqrt(max(li2_, MC_MIN_PROJ2_)));
    let hr = (pr * inverseSqrt(max(lr2_, MC_MIN_PROJ2_)));
    let psi_d = atan2(length(cross(hi, hr)), dot(hi, hr));
    let u_1 = exp(((-(psi_d) * psi_d) * MC_U_INV_TWO_SIGMA2_));
    return McPsi(hi, hr, u_1, select(0f, 1f, ok_1));
}

fn mc_lobe_reference(fr: McFrame, psi: McPsi, wi_1: vec3<f32>, wr_1: vec3<f32>, ca: f32, sa: f32, th: McThread) -> vec4<f32> {
    var local: bool;

    let u_2 = ((fr.u * ca) + (fr.n * sa));
    let np = ((fr.n * ca) - (fr.u * sa));
    let si = clamp(dot(wi_1, u_2), -1f, 1f);
    let sr = clamp(dot(wr_1, u_2), -1f, 1f);
    let pi_1 = (wi_1 - (u_2 * si));
    let pr_1 = (wr_1 - (u_2 * sr));
    let ci2_ = dot(pi_1, pi_1);
    let cr2_ = dot(pr_1, pr_1);
    if !((min(ci2_, cr2_) < MC_MIN_PROJ2_)) {
        local = (psi.ok == 0f);
    } else {
        local = true;
    }
    let _e41 = local;
    if _e41 {
        return vec4(0f);
    }
    let ci_1 = sqrt(ci2_);
    let cr_1 = sqrt(cr2_);
    let hi_1 = (pi_1 / vec3(ci_1));
    let hr_1 = (pr_1 / vec3(cr_1));
    let theta_i = atan2(si, ci_1);
    let theta_r = atan2(sr, cr_1);
    let theta_h = (0.5f * (theta_i + theta_r));
    let theta_d = (0.5f * (theta_i - theta_r));
    let phi_d = atan2(length(cross(hi_1, hr_1)), dot(hi_1, hr_1));
    let cos_half_phi = cos((0.5f * phi_d));
    let u_phi = exp(((-(phi_d) * phi_d) * MC_U_INV_TWO_SIGMA2_));
    let _e72 = mc_correlate(dot(np, hi_1), dot(np, hr_1), u_phi);
    let _e78 = mc_correlate(dot(np, psi.pi), dot(np, psi.pr), psi.u);
    let cd = cos(theta_d);
    let cd2_ = max((cd * cd), MC_MIN_COS2_THETA_D);
    let _e85 = weft_f_dielectric((cd * cos_half_phi), th.eta);
    let _e88 = mc_gauss(th.gamma_s, theta_h);
    let surface = ((_e85 * cos_half_phi) * _e88);
    let _e91 = weft_f_dielectric(ci_1, th.eta);
    let _e95 = weft_f_dielectric(cr_1, th.eta);
    let f_t = ((1f - _e91) * (1f - _e95));
    let _e103 = mc_gauss(th.gamma_v, theta_h);
    let volume = ((f_t * (((1f - th.kd) * _e103) + th.kd)) / (ci_1 + cr_1));
    let fs = ((vec3(surface) + (volume * th.albedo)) / vec3(cd2_));
    return vec4<f32>((fs * ((_e72 * _e78) * ci_1)), _e78);
}

fn mc_curve_at(h: array<vec4<f32>, 9>, i: u32) -> f32 {
    return h[(i / 4u)][(i % 4u)];
}

fn mc_thread_curve_reference(fr_1: McFrame, wi_2: vec3<f32>, wr_2: vec3<f32>, th_1: McThread, heights: array<vec4<f32>, 9>) -> vec4<f32> {
    var acc: vec4<f32> = vec4(0f);
    var wsum: f32 = 0f;
    var k: u32 = 0u;

    let _e6 = mc_psi_reference(fr_1.v, wi_2, wr_2);
    loop {
        let _e15 = k;
        if (_e15 < MC_CURVE_SEGMENTS) {
        } else {
            break;
        }
        {
            let _e18 = k;
            let _e21 = mc_curve_at(heights, (_e18 + 1u));
            let _e22 = k;
            let _e23 = mc_curve_at(heights, _e22);
            let dh = (_e21 - _e23);
            let len = sqrt(((0.03125f * 0.03125f) + (dh * dh)));
            let _e29 = acc;
            let _e32 = mc_lobe_reference(fr_1, _e6, wi_2, wr_2, (0.03125f / len), (dh / len), th_1);
            acc = (_e29 + (len * _e32));
            let _e35 = wsum;
            wsum = (_e35 + len);
        }
        continuing {
            let _e38 = k;
            k = (_e38 + 1u);
        }
    }
    let _e40 = acc;
    let _e41 = wsum;
    return (_e40 / vec4(_e41));
}

fn mc_combine(t1_: vec4<f32>, t2_: vec4<f32>, a1_: f32, a2_: f32, n_dot_wi: f32, n_dot_wr: f32) -> vec3<f32> {
    var local_1: bool;
    var local_2: bool;

    let c1_ = saturate(a1_);
    let c2_ = saturate(a2_);
    let gap = max(((1f - c1_) - c2_), 0f);
    let q_1 = (((c1_ * t1_.w) + (c2_ * t2_.w)) + (gap * max(n_dot_wi, 0f)));
    let s_2 = max(((c1_ * t1_.xyz) + (c2_ * t2_.xyz)), vec3(0f));
    if (n_dot_wi > 0f) {
        local_1 = (n_dot_wr > 0f);
    } else {
        local_1 = false;
    }
    let _e37 = local_1;
    if _e37 {
        local_2 = (q_1 > MC_MIN_Q);
    } else {
        local_2 = false;
    }
    let lit = local_2;
    return select(vec3(0f), (s_2 / vec3(max(q_1, MC_MIN_Q))), lit);
}

fn microcylinder_thread(color: vec3<f32>, ior_1: f32, isotropy: f32, gamma_s_deg: f32, gamma_v_deg: f32, tint: vec3<f32>) -> McThread {
    return McThread(saturate((color * tint)), clamp(ior_1, 1f, 4f), saturate(isotropy), (max(gamma_s_deg, 0f) * MC_DEG), (max(gamma_v_deg, 0f) * MC_DEG));
}

fn microcylinder_mean_fresnel(eta_1: f32) -> f32 {
    let _e1 = weft_f0_from_ior(eta_1);
    return (_e1 + ((1f - _e1) / 21f));
}

fn microcylinder_fast_const(th_2: McThread, heights_1: array<vec4<f32>, 9>) -> McFastConst {
    var k_1: McFastConst = McFastConst();

    let _e4 = k_1;
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
    let a1_1 = saturate(_e49);
    let _e53 = material.thread2_coverage;
    let a2_1 = select(0f, saturate(_e53), false);
    let _e60 = material.brightness;
    let brightness = max(_e60, 0f);
    let _e65 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_raw = _e65.v;
    let n_3 = _e65.n;
    let _e69 = weft_tangent_frame(n_3, in_1.world_tangent);
    let t_1 = _e69[0];
    let b_2 = _e69[1];
    let _e79 = weft_safe_normalize((v_raw + (n_3 * max((0.001f - dot(n_3, v_raw)), 0f))), n_3);
    let _e80 = weft_main_light_direction();
    let warp = McFrame(t_1, b_2, n_3);
    let weft = McFrame(b_2, t_1, n_3);
    {
        {
            let _e91 = material.thread1_curve;
            let _e92 = mc_thread_curve_reference(warp, _e80, _e79, _e29, _e91);
            s1_ = _e92;
        }
    }
    let _e93 = s1_;
    let _e94 = s2_;
    let _e97 = mc_combine(_e93, _e94, a1_1, a2_1, dot(n_3, _e80), dot(n_3, _e79));
    let _e98 = weft_main_light_radiance();
    let direct = (_e97 * _e98);
    let amb1_ = (_e29.albedo + vec3(in_1.mean_fresnel.x));
    let amb2_ = (_e46.albedo + vec3(in_1.mean_fresnel.y));
    let cov = (a1_1 + a2_1);
    let ambient_albedo = select(amb1_, (((a1_1 * amb1_) + (a2_1 * amb2_)) / vec3(max(cov, 0.0001f))), (cov > 0.0001f));
    let _e121 = weft_sh_irradiance(n_3);
    let ambient = (_e121 * ambient_albedo);
    let radiance = clamp(((direct + ambient) * brightness), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
