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
    base_color: vec4<f32>,
    base_map_st: vec4<f32>,
    strand_along_tangent: u32,
    jitter_map_st: vec4<f32>,
    jitter_strength: f32,
    anisotropic_direction: f32,
    strand_noise: f32,
    strand_density: f32,
    primary_color: vec4<f32>,
    primary_exponent: f32,
    primary_intensity: f32,
    primary_shift: f32,
    secondary_color: vec4<f32>,
    secondary_exponent: f32,
    secondary_intensity: f32,
    secondary_shift: f32,
    roughness: f32,
    azimuthal_roughness: f32,
    scale_angle: f32,
    ior: f32,
    outline_color: vec4<f32>,
    outline_width: f32,
    outline_max_distance: f32,
    fringe_shadow_color: vec4<f32>,
    fringe_shadow_length: f32,
}

struct WeftFringeShadowVertex {
    @location(0) position: vec3<f32>,
}

struct WeftFringeShadowVaryings {
    @builtin(position) clip_position: vec4<f32>,
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

struct WeftHair {
    sigma_a: vec3<f32>,
    eta: f32,
    v: vec4<f32>,
    s: f32,
    sin2k: vec3<f32>,
    cos2k: vec3<f32>,
    inv_v: vec3<f32>,
    mp_norm: vec3<f32>,
    blur: vec2<f32>,
    r_floor: f32,
    trt: vec4<f32>,
    trt4_: f32,
    inv_eta: f32,
}

struct WeftHairLobes {
    s: vec3<f32>,
    albedo: vec3<f32>,
    back: vec3<f32>,
}

struct WeftHairAngles {
    theta: vec4<f32>,
    phi: f32,
}

struct HairVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) world_tangent: vec4<f32>,
    @location(3) uv0_: vec2<f32>,
    @location(4) @interpolate(flat) fibre: vec4<f32>,
    @location(5) @interpolate(flat) sin2k: vec4<f32>,
    @location(6) @interpolate(flat) cos2k: vec4<f32>,
    @location(7) @interpolate(flat) mp_norm: vec4<f32>,
    @location(8) @interpolate(flat) inv_v: vec4<f32>,
    @location(9) @interpolate(flat) trt: vec4<f32>,
    @location(10) @interpolate(flat) jitter: vec4<f32>,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_HAIR_MIN_BETA_M: f32 = 0.05f;
const WEFT_HAIR_MIN_BETA_N: f32 = 0.05f;
const HAIR_REFERENCE_CELLS: u32 = 64u;
const HAIR_TERMINATOR: f32 = 0.25f;

@group(0) @binding(0) 
var<uniform> weft_frame: WeftFrame;
@group(2) @binding(0) 
var<uniform> weft_object: WeftObject;
@group(1) @binding(0) 
var<uniform> material: WeftMaterial;
@group(1) @binding(1) 
var material_sampler: sampler;
@group(1) @binding(3) 
var base_map: texture_2d<f32>;
@group(1) @binding(4) 
var flow_map: texture_2d<f32>;
@group(1) @binding(5) 
var jitter_map: texture_2d<f32>;
@group(1) @binding(6) 
var uv_rotate_mask: texture_2d<f32>;

fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v, v);
    return select(fallback, (v * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_any_perpendicular(n: vec3<f32>) -> vec3<f32> {
    let s_2 = select(-1f, 1f, (n.z >= 0f));
    let a_2 = (-1f / (s_2 + n.z));
    let b = ((n.x * n.y) * a_2);
    return vec3<f32>((1f + (((s_2 * n.x) * n.x) * a_2)), (s_2 * b), (-(s_2) * n.x));
}

fn weft_f_dielectric(cos_i: f32, eta: f32) -> f32 {
    let c_1 = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1f);
    let g2_ = (((eta * eta) - 1f) + (c_1 * c_1));
    let g = sqrt(max(g2_, 0f));
    let gmc = (g - c_1);
    let gpc = max((g + c_1), 0.0000001f);
    let b_den = max(((c_1 * gmc) + 1f), 0.0000001f);
    let b_num = ((c_1 * gpc) - 1f);
    let inv = (1f / (gpc * b_den));
    let f = saturate(((((0.5f * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)));
    return select(f, 1f, (g2_ < 0f));
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

fn weft_forward_vertex(in_3: WeftVertexInput) -> WeftVaryings {
    var out_1: WeftVaryings;

    let model = weft_object.model;
    let model3_ = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm = weft_object.normal_matrix;
    let normal3_ = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = (model * vec4<f32>(in_3.position, 1f));
    let mirror = select(1f, -1f, (determinant(model3_) < 0f));
    let bitangent_sign = (select(1f, -1f, (in_3.tangent.w < 0f)) * mirror);
    let _e43 = weft_frame.view_proj;
    out_1.clip_position = (_e43 * vec4<f32>(world.xyz, 1f));
    out_1.world_position = world.xyz;
    let _e55 = weft_safe_normalize((normal3_ * in_3.normal), vec3(0f));
    out_1.world_normal = _e55;
    let _e62 = weft_safe_normalize((model3_ * in_3.tangent.xyz), vec3(0f));
    out_1.world_tangent = vec4<f32>(_e62, bitangent_sign);
    out_1.uv0_ = in_3.uv0_;
    let _e66 = out_1;
    return _e66;
}

fn weft_tangent_frame(n_2: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    let len2_1 = dot(t_proj, t_proj);
    let ok = (len2_1 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_2);
    let t_2 = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_3 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_2, t_2) * s_3);
    return mat3x3<f32>(t_2, b_1, n_2);
}

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn weft_hair_sqr(x: f32) -> f32 {
    return (x * x);
}

fn weft_hair_safe_sqrt(x_1: f32) -> f32 {
    return sqrt(max(x_1, 0f));
}

fn weft_hair_variance(beta_m: f32) -> f32 {
    let b_2 = clamp(beta_m, WEFT_HAIR_MIN_BETA_M, 1f);
    let b2_ = (b_2 * b_2);
    let b4_ = (b2_ * b2_);
    let b20_ = ((((b4_ * b4_) * b4_) * b4_) * b4_);
    let _e18 = weft_hair_sqr((((0.726f * b_2) + (0.812f * b2_)) + (3.7f * b20_)));
    return _e18;
}

fn weft_hair_logistic_scale(beta_n: f32) -> f32 {
    let b_3 = clamp(beta_n, WEFT_HAIR_MIN_BETA_N, 1f);
    let b2_1 = (b_3 * b_3);
    let b4_1 = (b2_1 * b2_1);
    let b22_ = (((((b4_1 * b4_1) * b4_1) * b4_1) * b4_1) * b2_1);
    return (0.62665707f * (((0.265f * b_3) + (1.194f * b2_1)) + (5.372f * b22_)));
}

fn weft_hair_sigma_a_scaled(c: vec3<f32>, scale_1: f32) -> vec3<f32> {
    let l = (log(clamp(c, vec3(0.0001f), vec3(1f))) * scale_1);
    return (l * l);
}

fn weft_hair_sigma_a_scale(beta_n_1: f32) -> f32 {
    let b_4 = clamp(beta_n_1, WEFT_HAIR_MIN_BETA_N, 1f);
    let d = (((((5.969f - (0.215f * b_4)) + ((2.532f * b_4) * b_4)) - (10.73f * pow(b_4, 3f))) + (5.574f * pow(b_4, 4f))) + (0.245f * pow(b_4, 5f)));
    return (1f / d);
}

fn weft_hair_params(sigma_a: vec3<f32>, eta_1: f32, beta_m_1: f32, beta_n_2: f32, alpha_deg: f32) -> WeftHair {
    var hair: WeftHair;

    hair.sigma_a = max(sigma_a, vec3(0f));
    hair.eta = max(eta_1, 1.0001f);
    let _e13 = weft_hair_variance(beta_m_1);
    hair.v = vec4<f32>(_e13, (0.25f * _e13), (4f * _e13), (4f * _e13));
    let _e23 = weft_hair_logistic_scale(beta_n_2);
    hair.s = _e23;
    let a_3 = radians(alpha_deg);
    let s0_ = sin(a_3);
    let _e29 = weft_hair_safe_sqrt((1f - (s0_ * s0_)));
    let s1_ = ((2f * _e29) * s0_);
    let c1_ = ((_e29 * _e29) - (s0_ * s0_));
    let s2_ = ((2f * c1_) * s1_);
    let c2_ = ((c1_ * c1_) - (s1_ * s1_));
    hair.sin2k = vec3<f32>(s0_, s1_, s2_);
    hair.cos2k = vec3<f32>(_e29, c1_, c2_);
    hair.inv_v = (vec3<f32>(1f, 4f, 0.25f) / vec3(_e13));
    let _e55 = hair.inv_v.x;
    let e_trt = exp((-0.5f * _e55));
    let _e60 = weft_hair_sqr((e_trt * e_trt));
    let _e63 = hair.inv_v;
    let _e67 = weft_hair_sqr((_e60 * _e60));
    hair.mp_norm = (_e63 / (vec3(1f) - vec3<f32>(_e60, _e67, e_trt)));
    let _e73 = hair.s;
    let d_1 = (0.8162094f * _e73);
    hair.blur = vec2<f32>(sin(d_1), cos(d_1));
    let _e81 = hair.s;
    let _e84 = weft_hair_sqr((0.4534f * _e81));
    hair.r_floor = _e84;
    let sh_1 = hair.s;
    hair.trt = vec4<f32>((-9.2609f + (sh_1 * (65.993f - (107.38f * sh_1)))), (72.357f + (sh_1 * (-624.68f + (1069.8f * sh_1)))), (-153.75f + (sh_1 * (1704.7f - (3127.5f * sh_1)))), (-67.745f + (sh_1 * (-1105.8f + (2706.6f * sh_1)))));
    hair.trt4_ = (239.74f - (430.94f * sh_1));
    let _e124 = hair.eta;
    hair.inv_eta = (1f / _e124);
    let _e127 = hair;
    return _e127;
}

fn weft_hair_logistic(x_2: f32, s: f32) -> f32 {
    let e_1 = exp((-(abs(x_2)) / s));
    let _e8 = weft_hair_sqr((1f + e_1));
    return (e_1 / (s * _e8));
}

fn weft_hair_trimmed_logistic(x_3: f32, s_1: f32) -> f32 {
    let e_2 = exp((-3.1415927f / s_1));
    let _e5 = weft_hair_logistic(x_3, s_1);
    return ((_e5 * (1f + e_2)) / (1f - e_2));
}

fn weft_hair_angles(t: vec3<f32>, o: vec3<f32>, i: vec3<f32>) -> WeftHairAngles {
    var out_2: WeftHairAngles;

    let sin_o = clamp(dot(o, t), -1f, 1f);
    let sin_i = clamp(dot(i, t), -1f, 1f);
    let _e16 = weft_hair_safe_sqrt((1f - (sin_o * sin_o)));
    let _e20 = weft_hair_safe_sqrt((1f - (sin_i * sin_i)));
    out_2.theta = vec4<f32>(sin_o, _e16, sin_i, _e20);
    let o_perp = (o - (sin_o * t));
    let i_perp = (i - (sin_i * t));
    let len2_2 = (dot(o_perp, o_perp) * dot(i_perp, i_perp));
    let cos_phi = select(1f, (dot(o_perp, i_perp) * inverseSqrt(max(len2_2, 0.000000000000000000000000000001f))), (len2_2 > 0.000000000001f));
    out_2.phi = acos(clamp(cos_phi, -1f, 1f));
    let _e43 = out_2;
    return _e43;
}

fn weft_hair_fast_tt_density(sin_half: f32, a: f32) -> vec3<f32> {
    let rho2_ = ((1f - ((2f * a) * sin_half)) + (a * a));
    let inv_rho = inverseSqrt(max(rho2_, 0.00000001f));
    let cos_go = (max((sin_half - a), 0f) * inv_rho);
    let cos_gt = ((1f - (a * sin_half)) * inv_rho);
    return vec3<f32>(cos_go, cos_gt, (((0.25f * cos_go) * cos_gt) * inv_rho));
}

fn weft_hair_fast_tt(sin_plus: f32, sin_minus: f32, a_1: f32, cos_o: f32, eta_2: f32, sigma_a_1: vec3<f32>, chord: f32) -> vec3<f32> {
    let _e7 = weft_hair_fast_tt_density(sin_plus, a_1);
    let _e8 = weft_hair_fast_tt_density(sin_minus, a_1);
    let _e11 = weft_f_dielectric((cos_o * _e7.x), eta_2);
    let _e19 = weft_hair_sqr((1f - _e11));
    return (exp((-(sigma_a_1) * (chord * _e7.y))) * ((_e19 * 0.5f) * (_e7.z + _e8.z)));
}

fn weft_hair_fast(hair_1: WeftHair, t_1: vec3<f32>, o_1: vec3<f32>, i_1: vec3<f32>) -> WeftHairLobes {
    var out_3: WeftHairLobes;

    let sin_o_1 = clamp(dot(o_1, t_1), -1f, 1f);
    let sin_i_1 = clamp(dot(i_1, t_1), -1f, 1f);
    let _e15 = weft_hair_safe_sqrt((1f - (sin_o_1 * sin_o_1)));
    let _e19 = weft_hair_safe_sqrt((1f - (sin_i_1 * sin_i_1)));
    let o_perp_1 = (o_1 - (sin_o_1 * t_1));
    let i_perp_1 = (i_1 - (sin_i_1 * t_1));
    let len2_3 = (dot(o_perp_1, o_perp_1) * dot(i_perp_1, i_perp_1));
    let cos_phi_1 = clamp(select(1f, (dot(o_perp_1, i_perp_1) * inverseSqrt(max(len2_3, 0.000000000000000000000000000001f))), (len2_3 > 0.000000000001f)), -1f, 1f);
    let cos_half = sqrt((0.5f + (0.5f * cos_phi_1)));
    let sin_half_1 = sqrt((0.5f - (0.5f * cos_phi_1)));
    let so = vec3<f32>(((sin_o_1 * hair_1.cos2k.y) - (_e15 * hair_1.sin2k.y)), ((sin_o_1 * hair_1.cos2k.x) + (_e15 * hair_1.sin2k.x)), ((sin_o_1 * hair_1.cos2k.z) + (_e15 * hair_1.sin2k.z)));
    let co = abs(vec3<f32>(((_e15 * hair_1.cos2k.y) + (sin_o_1 * hair_1.sin2k.y)), ((_e15 * hair_1.cos2k.x) - (sin_o_1 * hair_1.sin2k.x)), ((_e15 * hair_1.cos2k.z) - (sin_o_1 * hair_1.sin2k.z))));
    let inv_v = hair_1.inv_v;
    let norm = hair_1.mp_norm;
    let x_6 = ((_e19 * co) * inv_v);
    let u = (vec3(1f) / (vec3(1f) + (0.7f * x_6)));
    let bessel = ((vec3(1f) + ((u * (vec3(1f) - u)) * (vec3(0.181903f) + (u * (vec3(-0.401835f) + (u * 3.1851f)))))) * inverseSqrt((vec3(1f) + (6.2831855f * x_6))));
    let mp = ((exp(min(((((_e19 * co) - (sin_i_1 * so)) - vec3(1f)) * inv_v), vec3(0f))) * bessel) * norm);
    let sin_t = (sin_o_1 * hair_1.inv_eta);
    let chord_1 = (2f * inverseSqrt(max((1f - (sin_t * sin_t)), 0.00000001f)));
    let a_4 = (_e15 * inverseSqrt(max(((hair_1.eta * hair_1.eta) - (sin_o_1 * sin_o_1)), 0.00000001f)));
    let sd = hair_1.blur.x;
    let cd = hair_1.blur.y;
    let c_r = sqrt(min(((0.5f + (0.5f * cos_phi_1)) + hair_1.r_floor), 1f));
    let _e179 = weft_f_dielectric((_e15 * c_r), hair_1.eta);
    let r = ((0.25f * c_r) * _e179);
    let _e189 = weft_hair_fast_tt(((sin_half_1 * cd) + (cos_half * sd)), ((sin_half_1 * cd) - (cos_half * sd)), a_4, _e15, hair_1.eta, hair_1.sigma_a, chord_1);
    let h_f = (0.6243f + (0.1898f * _e15));
    let _e197 = weft_hair_safe_sqrt((1f - (h_f * h_f)));
    let _e200 = weft_f_dielectric((_e15 * _e197), hair_1.eta);
    let h2_ = (0.4824f + (0.2778f * _e15));
    let _e208 = weft_hair_safe_sqrt((1f - (h2_ * h2_)));
    let _e211 = weft_f_dielectric((_e15 * _e208), hair_1.eta);
    let _e219 = weft_hair_safe_sqrt((1f - (((h2_ * h2_) * a_4) * a_4)));
    let t2_ = exp((-(hair_1.sigma_a) * (chord_1 * _e219)));
    let _e225 = weft_hair_sqr((1f - _e211));
    let a2_ = (((_e225 * _e211) * t2_) * t2_);
    let ft = (_e200 * t2_);
    let a3_ = ((a2_ * ft) / (vec3(1f) - ft));
    let s2_fit = (hair_1.trt.x + (a_4 * (hair_1.trt.y + (a_4 * (hair_1.trt.z + (a_4 * (hair_1.trt.w + (a_4 * hair_1.trt4_))))))));
    let s_trt = sqrt(max(exp(clamp(s2_fit, -9f, 2.5f)), (hair_1.s * hair_1.s)));
    let _e262 = weft_hair_trimmed_logistic(acos(cos_phi_1), s_trt);
    out_3.s = ((vec3((mp.x * r)) + (mp.y * _e189)) + (mp.z * ((a2_ * _e262) + (a3_ * 0.15915494f))));
    out_3.back = (vec3(_e200) + a2_);
    let _e284 = weft_hair_sqr((1f - _e211));
    out_3.albedo = (((vec3(_e200) + (_e284 * t2_)) + a2_) + a3_);
    let _e290 = out_3;
    return _e290;
}

fn hair_noise_period(density: f32) -> f32 {
    return max(round(density), 1f);
}

fn hair_from_varyings(in_4: HairVaryings, sigma_a_2: vec3<f32>) -> WeftHair {
    let v_1 = in_4.fibre.z;
    return WeftHair(max(sigma_a_2, vec3(0f)), in_4.fibre.x, vec4<f32>(v_1, (0.25f * v_1), (4f * v_1), (4f * v_1)), in_4.fibre.y, in_4.sin2k.xyz, in_4.cos2k.xyz, in_4.inv_v.xyz, in_4.mp_norm.xyz, vec2<f32>(in_4.cos2k.w, in_4.mp_norm.w), in_4.sin2k.w, vec4<f32>(in_4.inv_v.w, in_4.trt.xyz), in_4.trt.w, in_4.jitter.z);
}

fn hair_strand(frame: mat3x3<f32>, uv0_: vec2<f32>) -> vec3<f32> {
    var ts: vec2<f32>;

    let _e10 = material.strand_along_tangent;
    ts = select(vec2<f32>(0f, 1f), vec2<f32>(1f, 0f), (_e10 != 0u));
    {
        let _e17 = textureSample(flow_map, material_sampler, uv0_);
        let f_1 = ((_e17.xy * 2f) - vec2(1f));
        let len2_4 = dot(f_1, f_1);
        let _e25 = ts;
        ts = select(_e25, (f_1 * inverseSqrt(max(len2_4, 0.000000000001f))), (len2_4 > 0.0001f));
    }
    let _e35 = ts.x;
    let _e39 = ts.y;
    let _e43 = weft_safe_normalize(((frame[0] * _e35) + (frame[1] * _e39)), frame[1]);
    return _e43;
}

fn hair_hash(x_4: u32) -> f32 {
    let state = ((x_4 * 747796405u) + 2891336453u);
    let word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (f32(((word >> 22u) ^ word)) * 0.00000000023283064f);
}

fn hair_value_noise(x_5: f32, p: f32) -> f32 {
    let cell = floor(x_5);
    let f_2 = (x_5 - cell);
    let c0_ = (cell - (p * floor((cell / p))));
    let c1_1 = select((c0_ + 1f), 0f, ((c0_ + 1f) >= p));
    let _e16 = hair_hash(u32(c0_));
    let _e18 = hair_hash(u32(c1_1));
    return (mix(_e16, _e18, ((f_2 * f_2) * (3f - (2f * f_2)))) - 0.5f);
}

fn hair_jitter(uv0_1: vec2<f32>, rotation: vec2<f32>, noise_period: f32) -> f32 {
    let _e5 = textureSample(uv_rotate_mask, material_sampler, uv0_1);
    let mask = step(0.8f, _e5.x);
    let c_2 = rotation.x;
    let s_4 = rotation.y;
    let rotated = vec2<f32>(((c_2 * uv0_1.x) + (s_4 * uv0_1.y)), ((-(s_4) * uv0_1.x) + (c_2 * uv0_1.y)));
    let _e28 = material.jitter_map_st;
    let _e29 = weft_transform_uv(select(uv0_1, rotated, (mask > 0.5f)), _e28);
    let _e32 = textureSample(jitter_map, material_sampler, _e29);
    let j = _e32.x;
    let _e38 = material.strand_along_tangent;
    let across = select(_e29.x, _e29.y, (_e38 != 0u));
    let _e44 = material.strand_density;
    let _e46 = hair_value_noise((across * _e44), noise_period);
    let _e49 = material.jitter_strength;
    let _e53 = material.strand_noise;
    return ((_e49 * j) + (_e53 * _e46));
}

@vertex 
fn vs_fringe_shadow(in: WeftFringeShadowVertex) -> WeftFringeShadowVaryings {
    var local: bool;
    var out: WeftFringeShadowVaryings;

    let _e3 = weft_object.model;
    let world_1 = (_e3 * vec4<f32>(in.position, 1f)).xyz;
    let _e11 = weft_frame.view_proj;
    let clip = (_e11 * vec4<f32>(world_1, 1f));
    let _e17 = weft_frame.light_direction;
    let l_1 = _e17.xyz;
    let l_len = length(l_1);
    let travel = select(vec3(0f), (-(l_1) / vec3(max(l_len, 0.000001f))), (l_len > 0.000001f));
    let _e32 = material.fringe_shadow_length;
    let length_world = max(_e32, 0f);
    let _e37 = weft_frame.view_proj;
    let pushed = (_e37 * vec4<f32>((world_1 + (travel * length_world)), 1f));
    if (clip.w > 0.000001f) {
        local = (pushed.w > 0.000001f);
    } else {
        local = false;
    }
    let usable = local;
    let offset_ndc = select(vec2(0f), ((pushed.xy / vec2(max(pushed.w, 0.000001f))) - (clip.xy / vec2(max(clip.w, 0.000001f)))), usable);
    out.clip_position = vec4<f32>((clip.xy + (offset_ndc * clip.w)), clip.zw);
    let _e77 = out;
    return _e77;
}

@fragment 
fn fs_fringe_shadow() -> @location(0) vec4<f32> {
    let _e2 = material.fringe_shadow_color;
    return vec4<f32>(max(_e2.xyz, vec3(0f)), 1f);
}

@vertex 
fn vs_hair(in_1: WeftVertexInput) -> HairVaryings {
    var h: WeftHair;
    var scale: f32 = 0f;

    let _e1 = weft_forward_vertex(in_1);
    let _e6 = material.ior;
    let _e9 = material.roughness;
    let _e12 = material.azimuthal_roughness;
    let _e15 = material.scale_angle;
    let _e16 = weft_hair_params(vec3(0f), _e6, _e9, _e12, _e15);
    h = _e16;
    {
        let _e22 = material.azimuthal_roughness;
        let _e23 = weft_hair_sigma_a_scale(_e22);
        scale = _e23;
    }
    let _e26 = material.anisotropic_direction;
    let a_5 = radians(_e26);
    let _e34 = h.eta;
    let _e36 = h.s;
    let _e39 = h.v.x;
    let _e40 = scale;
    let _e43 = h.sin2k;
    let _e45 = h.r_floor;
    let _e48 = h.cos2k;
    let _e51 = h.blur.x;
    let _e54 = h.mp_norm;
    let _e57 = h.blur.y;
    let _e60 = h.inv_v;
    let _e63 = h.trt.x;
    let _e66 = h.trt;
    let _e69 = h.trt4_;
    let _e74 = h.inv_eta;
    let _e77 = material.strand_density;
    let _e78 = hair_noise_period(_e77);
    return HairVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, vec4<f32>(_e34, _e36, _e39, _e40), vec4<f32>(_e43, _e45), vec4<f32>(_e48, _e51), vec4<f32>(_e54, _e57), vec4<f32>(_e60, _e63), vec4<f32>(_e66.yzw, _e69), vec4<f32>(cos(a_5), sin(a_5), _e74, _e78));
}

@fragment 
fn fs_main(in_2: HairVaryings) -> @location(0) vec4<f32> {
    var color: vec3<f32>;
    var lobes: WeftHairLobes;

    let _e4 = material.base_map_st;
    let _e5 = weft_transform_uv(in_2.uv0_, _e4);
    let _e8 = material.base_color;
    let _e11 = textureSample(base_map, material_sampler, _e5);
    let base_rgba = (_e8 * _e11);
    let base = saturate(base_rgba.xyz);
    let alpha = saturate(base_rgba.w);
    let _e19 = weft_surface(in_2.world_position, in_2.world_normal);
    let v_2 = _e19.v;
    let n_3 = _e19.n;
    let _e23 = weft_tangent_frame(n_3, in_2.world_tangent);
    let _e25 = hair_strand(_e23, in_2.uv0_);
    let _e31 = hair_jitter(in_2.uv0_, in_2.jitter.xy, in_2.jitter.w);
    let _e32 = weft_main_light_direction();
    let _e33 = weft_main_light_radiance();
    let _e34 = weft_sh_irradiance(n_3);
    let n_dot_l = dot(n_3, _e32);
    {
        let _e39 = weft_safe_normalize((_e25 + (_e31 * n_3)), _e25);
        let _e42 = weft_hair_sigma_a_scaled(base, in_2.fibre.w);
        let _e43 = hair_from_varyings(in_2, _e42);
        let _e44 = weft_hair_angles(_e39, v_2, _e32);
        {
            let _e46 = weft_hair_fast(_e43, _e39, v_2, _e32);
            lobes = _e46;
        }
        let body = smoothstep(-0.25f, HAIR_TERMINATOR, n_dot_l);
        let _e53 = lobes.back;
        let multiple = (base * (vec3(1f) - _e53));
        let _e57 = lobes.s;
        let direct = ((_e57 * body) + (multiple * (WEFT_INV_PI * saturate(n_dot_l))));
        let _e66 = lobes.back;
        color = ((direct * _e33) + (_e34 * (multiple + _e66)));
    }
    let _e70 = color;
    let radiance = clamp(_e70, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
