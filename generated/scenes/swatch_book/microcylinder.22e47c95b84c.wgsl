struct WeftFrame {
    view_proj: mat4x4<f32>,
    view: mat4x4<f32>,
    camera_position: vec4<f32>,
    light_direction: vec4<f32>,
    light_color: vec4<f32>,
    sh: array<vec4<f32>, 9>,
    params: vec4<f32>,
}

struct WeftObject {
    model: mat4x4<f32>,
    normal_matrix: mat4x4<f32>,
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

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const TANGENT_OFFSETS_CURVE: u32 = 0u;
const TANGENT_OFFSETS_LIST: u32 = 1u;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const MC_CURVE_SAMPLES: u32 = 33u;
const MC_CURVE_SEGMENTS: u32 = 32u;
const MC_FAST_CHORDS: u32 = 4u;
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

@group(0) @binding(0) 
var<uniform> weft_frame: WeftFrame;
@group(2) @binding(0) 
var<uniform> weft_object: WeftObject;

fn weft_pow5_(x: f32) -> f32 {
    let x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

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
    let q = ((ior - 1f) / max((ior + 1f), 0.0001f));
    return (q * q);
}

fn weft_main_light_direction() -> vec3<f32> {
    let _e2 = weft_frame.light_direction;
    let _e5 = weft_safe_normalize(_e2.xyz, vec3<f32>(0f, 0f, 1f));
    return _e5;
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

fn weft_tangent_frame(n_2: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    let len2_1 = dot(t_proj, t_proj);
    let ok = (len2_1 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_2);
    let t = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_2 = (cross(n_2, t) * s_1);
    return mat3x3<f32>(t, b_2, n_2);
}

fn mc_gauss(gamma: f32, x_1: f32) -> f32 {
    let g = max(gamma, MC_MIN_GAMMA);
    return (exp(((-(x_1) * x_1) / ((2f * g) * g))) / (MC_SQRT_TWO_PI * g));
}

fn mc_correlate(ci: f32, cr: f32, u: f32) -> f32 {
    let mi = max(ci, 0f);
    let mr = max(cr, 0f);
    return ((((1f - u) * mi) * mr) + (u * min(mi, mr)));
}

fn mc_acos_fast(x_2: f32) -> f32 {
    let ax = min(abs(x_2), 1f);
    let r = (sqrt((1f - ax)) * (1.5707288f + (ax * (-0.2121144f + (ax * (0.074261f - (0.0187293f * ax)))))));
    return select(r, (WEFT_PI - r), (x_2 < 0f));
}

fn mc_asin_fast(x_3: f32) -> f32 {
    let _e2 = mc_acos_fast(x_3);
    return (1.5707964f - _e2);
}

fn mc_psi_fast(v_1: vec3<f32>, wi: vec3<f32>, wr: vec3<f32>) -> McPsi {
    let pi = (wi - (v_1 * dot(wi, v_1)));
    let pr = (wr - (v_1 * dot(wr, v_1)));
    let li2_ = dot(pi, pi);
    let lr2_ = dot(pr, pr);
    let ok_1 = (min(li2_, lr2_) >= MC_MIN_PROJ2_);
    let hi = (pi * inverseSqrt(max(li2_, MC_MIN_PROJ2_)));
    let hr = (pr * inverseSqrt(max(lr2_, MC_MIN_PROJ2_)));
    let _e23 = mc_acos_fast(dot(hi, hr));
    let u_1 = exp(((-(_e23) * _e23) * MC_U_INV_TWO_SIGMA2_));
    return McPsi(hi, hr, u_1, select(0f, 1f, ok_1));
}

fn mc_lobe_fast(fr: McFrame, psi: McPsi, wi_1: vec3<f32>, wr_1: vec3<f32>, ca: f32, sa: f32, th: McThread) -> vec4<f32> {
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
    let inv_ci = inverseSqrt(ci2_);
    let inv_cr = inverseSqrt(cr2_);
    let ci_1 = (ci2_ * inv_ci);
    let cr_1 = (cr2_ * inv_cr);
    let hi_1 = (pi_1 * inv_ci);
    let hr_1 = (pr_1 * inv_cr);
    let cos_phi_d = clamp(dot(hi_1, hr_1), -1f, 1f);
    let cos_half_phi = sqrt(max((0.5f + (0.5f * cos_phi_d)), 0f));
    let _e60 = mc_acos_fast(cos_phi_d);
    let _e61 = mc_asin_fast(si);
    let _e62 = mc_asin_fast(sr);
    let theta_h = (0.5f * (_e61 + _e62));
    let cd2_ = max((0.5f + (0.5f * ((ci_1 * cr_1) + (si * sr)))), MC_MIN_COS2_THETA_D);
    let u_phi = exp(((-(_e60) * _e60) * MC_U_INV_TWO_SIGMA2_));
    let _e82 = mc_correlate(dot(np, hi_1), dot(np, hr_1), u_phi);
    let _e88 = mc_correlate(dot(np, psi.pi), dot(np, psi.pr), psi.u);
    let _e90 = weft_f0_from_ior(th.eta);
    let c_eff = (sqrt(cd2_) * cos_half_phi);
    let _e98 = weft_pow5_((1f - saturate(c_eff)));
    let f_r = (_e90 + ((1f - _e90) * _e98));
    let f_t = ((1f - f_r) * (1f - f_r));
    let _e108 = mc_gauss(th.gamma_s, theta_h);
    let surface = ((f_r * cos_half_phi) * _e108);
    let _e114 = mc_gauss(th.gamma_v, theta_h);
    let volume = ((f_t * (((1f - th.kd) * _e114) + th.kd)) / (ci_1 + cr_1));
    let fs = ((vec3(surface) + (volume * th.albedo)) / vec3(cd2_));
    return vec4<f32>((fs * ((_e82 * _e88) * ci_1)), _e88);
}

fn mc_offset_at(a: vec4<f32>, b: vec4<f32>, k: i32) -> f32 {
    return select(a, b, (k >= 4i))[(k & 3i)];
}

fn mc_thread_list_fast(fr_1: McFrame, wi_2: vec3<f32>, wr_2: vec3<f32>, th_1: McThread, offsets_a: vec4<f32>, offsets_b: vec4<f32>, count: i32) -> vec4<f32> {
    var acc: vec4<f32> = vec4(0f);
    var k_1: i32 = 0i;

    let n_3 = clamp(count, 1i, MC_MAX_OFFSETS);
    let _e11 = mc_psi_fast(fr_1.v, wi_2, wr_2);
    loop {
        let _e16 = k_1;
        if (_e16 < n_3) {
        } else {
            break;
        }
        {
            let _e18 = k_1;
            let _e19 = mc_offset_at(offsets_a, offsets_b, _e18);
            let a_2 = (_e19 * MC_DEG);
            let _e22 = acc;
            let _e25 = mc_lobe_fast(fr_1, _e11, wi_2, wr_2, cos(a_2), sin(a_2), th_1);
            acc = (_e22 + _e25);
        }
        continuing {
            let _e28 = k_1;
            k_1 = (_e28 + 1i);
        }
    }
    let _e30 = acc;
    return (_e30 / vec4(f32(n_3)));
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
    let _e36 = local_1;
    if _e36 {
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

fn microcylinder_mean_fresnel(eta: f32) -> f32 {
    let _e1 = weft_f0_from_ior(eta);
    return (_e1 + ((1f - _e1) / 21f));
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    var out: WeftVaryings;

    let model = weft_object.model;
    let model3_ = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm = weft_object.normal_matrix;
    let normal3_ = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = (model * vec4<f32>(in.position, 1f));
    let mirror = select(1f, -1f, (determinant(model3_) < 0f));
    let bitangent_sign = (select(1f, -1f, (in.tangent.w < 0f)) * mirror);
    let _e43 = weft_frame.view_proj;
    out.clip_position = (_e43 * vec4<f32>(world.xyz, 1f));
    out.world_position = world.xyz;
    let _e54 = weft_safe_normalize((normal3_ * in.normal), vec3(0f));
    out.world_normal = _e54;
    let _e60 = weft_safe_normalize((model3_ * in.tangent.xyz), vec3(0f));
    out.world_tangent = vec4<f32>(_e60, bitangent_sign);
    out.uv0_ = in.uv0_;
    let _e64 = out;
    return _e64;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var s1_: vec4<f32> = vec4(0f);
    var s2_: vec4<f32> = vec4(0f);

    let _e7 = microcylinder_thread(vec3<f32>(0.060000107f, 0.23999724f, 0.2999983f), 1.46f, 0.3f, 12f, 24f, vec3<f32>(1f, 1f, 1f));
    let _e13 = microcylinder_thread(vec3<f32>(0.060000107f, 0.23999724f, 0.2999983f), 1.46f, 0.3f, 12f, 24f, vec3<f32>(1f, 1f, 1f));
    let _e19 = weft_view_direction(in_1.world_position, vec3<f32>(0f, 0f, 1f));
    let _e21 = weft_safe_normalize(in_1.world_normal, _e19);
    let _e23 = weft_tangent_frame(_e21, in_1.world_tangent);
    let t_1 = _e23[0];
    let b_3 = _e23[1];
    let _e33 = weft_safe_normalize((_e19 + (_e21 * max((0.001f - dot(_e21, _e19)), 0f))), _e21);
    let _e34 = weft_main_light_direction();
    let warp = McFrame(t_1, b_3, _e21);
    let weft = McFrame(b_3, t_1, _e21);
    {
        {
            let _e44 = mc_thread_list_fast(warp, _e34, _e33, _e7, vec4<f32>(-25f, 25f, 0f, 0f), vec4<f32>(0f, 0f, 0f, 0f), 2i);
            s1_ = _e44;
            {
                let _e48 = mc_thread_list_fast(weft, _e34, _e33, _e13, vec4<f32>(-25f, 25f, 0f, 0f), vec4<f32>(0f, 0f, 0f, 0f), 2i);
                s2_ = _e48;
            }
        }
    }
    let _e49 = s1_;
    let _e50 = s2_;
    let _e53 = mc_combine(_e49, _e50, 0.33f, 0.33f, dot(_e21, _e34), dot(_e21, _e33));
    let _e54 = weft_main_light_radiance();
    let direct = (_e53 * _e54);
    let _e58 = microcylinder_mean_fresnel(_e7.eta);
    let amb1_ = (_e7.albedo + vec3(_e58));
    let _e63 = microcylinder_mean_fresnel(_e13.eta);
    let amb2_ = (_e13.albedo + vec3(_e63));
    let ambient_albedo = select(amb1_, (((0.33f * amb1_) + (0.33f * amb2_)) / vec3(0.66f)), true);
    let _e74 = weft_sh_irradiance(_e21);
    let ambient = (_e74 * ambient_albedo);
    let radiance = clamp(((direct + ambient) * 1f), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
