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

struct WeftOutlineVertex {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
}

struct WeftOutlineVaryings {
    @builtin(position) clip_position: vec4<f32>,
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
@group(1) @binding(1) 
var material_sampler: sampler;
@group(1) @binding(5) 
var jitter_map: texture_2d<f32>;

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

fn weft_safe_normalize_k1_(v_1: vec3<f32>) -> vec3<f32> {
    let len2_1 = dot(v_1, v_1);
    return select(vec3<f32>(0f, 0f, 1f), (v_1 * inverseSqrt(max(len2_1, 0.00000000000000000001f))), (len2_1 > 0.00000000000000000001f));
}

fn weft_main_light_direction() -> vec3<f32> {
    let _e2 = weft_frame.light_direction;
    let _e4 = weft_safe_normalize_k1_(_e2.xyz);
    return _e4;
}

fn weft_main_light_radiance() -> vec3<f32> {
    let _e2 = weft_frame.light_color;
    return max(_e2.xyz, vec3(0f));
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

fn weft_view_direction_k2_(world_position: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_frame.camera_position;
    let _e7 = weft_safe_normalize_k1_((_e4.xyz - world_position));
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

fn weft_forward_vertex(in_4: WeftVertexInput) -> WeftVaryings {
    var out_2: WeftVaryings;

    let model = weft_object.model;
    let model3_ = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm = weft_object.normal_matrix;
    let normal3_ = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = (model * vec4<f32>(in_4.position, 1f));
    let mirror = select(1f, -1f, (determinant(model3_) < 0f));
    let bitangent_sign = (select(1f, -1f, (in_4.tangent.w < 0f)) * mirror);
    let _e43 = weft_frame.view_proj;
    out_2.clip_position = (_e43 * vec4<f32>(world.xyz, 1f));
    out_2.world_position = world.xyz;
    let _e53 = weft_safe_normalize_k3_((normal3_ * in_4.normal));
    out_2.world_normal = _e53;
    let _e58 = weft_safe_normalize_k3_((model3_ * in_4.tangent.xyz));
    out_2.world_tangent = vec4<f32>(_e58, bitangent_sign);
    out_2.uv0_ = in_4.uv0_;
    let _e62 = out_2;
    return _e62;
}

fn weft_tangent_frame(n_2: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_2 * dot(n_2, t_in)));
    let len2_3 = dot(t_proj, t_proj);
    let ok = (len2_3 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_2);
    let t_1 = select(_e13, (t_proj * inverseSqrt(max(len2_3, 0.00000000000000000001f))), ok);
    let s_3 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_2, t_1) * s_3);
    return mat3x3<f32>(t_1, b_1, n_2);
}

fn weft_hair_sqr(x: f32) -> f32 {
    return (x * x);
}

fn weft_hair_safe_sqrt(x_1: f32) -> f32 {
    return sqrt(max(x_1, 0f));
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

fn weft_hair_fast_tt_density(sin_half: f32, a: f32) -> vec3<f32> {
    let rho2_ = ((1f - ((2f * a) * sin_half)) + (a * a));
    let inv_rho = inverseSqrt(max(rho2_, 0.00000001f));
    let cos_go = (max((sin_half - a), 0f) * inv_rho);
    let cos_gt = ((1f - (a * sin_half)) * inv_rho);
    return vec3<f32>(cos_go, cos_gt, (((0.25f * cos_go) * cos_gt) * inv_rho));
}

fn weft_hair_fast_tt(sin_plus: f32, sin_minus: f32, a_1: f32, cos_o: f32, eta_1: f32, sigma_a: vec3<f32>, chord: f32) -> vec3<f32> {
    let _e7 = weft_hair_fast_tt_density(sin_plus, a_1);
    let _e8 = weft_hair_fast_tt_density(sin_minus, a_1);
    let _e11 = weft_f_dielectric((cos_o * _e7.x), eta_1);
    let _e19 = weft_hair_sqr((1f - _e11));
    return (exp((-(sigma_a) * (chord * _e7.y))) * ((_e19 * 0.5f) * (_e7.z + _e8.z)));
}

fn weft_hair_fast(hair: WeftHair, t: vec3<f32>, o: vec3<f32>, i: vec3<f32>) -> WeftHairLobes {
    var out_3: WeftHairLobes;

    let sin_o = clamp(dot(o, t), -1f, 1f);
    let sin_i = clamp(dot(i, t), -1f, 1f);
    let _e15 = weft_hair_safe_sqrt((1f - (sin_o * sin_o)));
    let _e19 = weft_hair_safe_sqrt((1f - (sin_i * sin_i)));
    let o_perp = (o - (sin_o * t));
    let i_perp = (i - (sin_i * t));
    let len2_4 = (dot(o_perp, o_perp) * dot(i_perp, i_perp));
    let cos_phi = clamp(select(1f, (dot(o_perp, i_perp) * inverseSqrt(max(len2_4, 0.000000000000000000000000000001f))), (len2_4 > 0.000000000001f)), -1f, 1f);
    let cos_half = sqrt((0.5f + (0.5f * cos_phi)));
    let sin_half_1 = sqrt((0.5f - (0.5f * cos_phi)));
    let so = vec3<f32>(((sin_o * hair.cos2k.y) - (_e15 * hair.sin2k.y)), ((sin_o * hair.cos2k.x) + (_e15 * hair.sin2k.x)), ((sin_o * hair.cos2k.z) + (_e15 * hair.sin2k.z)));
    let co = abs(vec3<f32>(((_e15 * hair.cos2k.y) + (sin_o * hair.sin2k.y)), ((_e15 * hair.cos2k.x) - (sin_o * hair.sin2k.x)), ((_e15 * hair.cos2k.z) - (sin_o * hair.sin2k.z))));
    let inv_v = hair.inv_v;
    let norm = hair.mp_norm;
    let x_6 = ((_e19 * co) * inv_v);
    let u = (vec3(1f) / (vec3(1f) + (0.7f * x_6)));
    let bessel = ((vec3(1f) + ((u * (vec3(1f) - u)) * (vec3(0.181903f) + (u * (vec3(-0.401835f) + (u * 3.1851f)))))) * inverseSqrt((vec3(1f) + (6.2831855f * x_6))));
    let mp = ((exp(min(((((_e19 * co) - (sin_i * so)) - vec3(1f)) * inv_v), vec3(0f))) * bessel) * norm);
    let sin_t = (sin_o * hair.inv_eta);
    let chord_1 = (2f * inverseSqrt(max((1f - (sin_t * sin_t)), 0.00000001f)));
    let a_3 = (_e15 * inverseSqrt(max(((hair.eta * hair.eta) - (sin_o * sin_o)), 0.00000001f)));
    let sd = hair.blur.x;
    let cd = hair.blur.y;
    let c_r = sqrt(min(((0.5f + (0.5f * cos_phi)) + hair.r_floor), 1f));
    let _e170 = weft_f_dielectric((_e15 * c_r), hair.eta);
    let r = ((0.25f * c_r) * _e170);
    let _e180 = weft_hair_fast_tt(((sin_half_1 * cd) + (cos_half * sd)), ((sin_half_1 * cd) - (cos_half * sd)), a_3, _e15, hair.eta, hair.sigma_a, chord_1);
    let h_f = (0.6243f + (0.1898f * _e15));
    let _e188 = weft_hair_safe_sqrt((1f - (h_f * h_f)));
    let _e191 = weft_f_dielectric((_e15 * _e188), hair.eta);
    let h2_ = (0.4824f + (0.2778f * _e15));
    let _e199 = weft_hair_safe_sqrt((1f - (h2_ * h2_)));
    let _e202 = weft_f_dielectric((_e15 * _e199), hair.eta);
    let _e210 = weft_hair_safe_sqrt((1f - (((h2_ * h2_) * a_3) * a_3)));
    let t2_ = exp((-(hair.sigma_a) * (chord_1 * _e210)));
    let _e216 = weft_hair_sqr((1f - _e202));
    let a2_ = (((_e216 * _e202) * t2_) * t2_);
    let ft = (_e191 * t2_);
    let a3_ = ((a2_ * ft) / (vec3(1f) - ft));
    let s2_fit = (hair.trt.x + (a_3 * (hair.trt.y + (a_3 * (hair.trt.z + (a_3 * (hair.trt.w + (a_3 * hair.trt4_))))))));
    let s_trt = sqrt(max(exp(clamp(s2_fit, -9f, 2.5f)), (hair.s * hair.s)));
    let _e252 = weft_hair_trimmed_logistic(acos(cos_phi), s_trt);
    out_3.s = ((vec3((mp.x * r)) + (mp.y * _e180)) + (mp.z * ((a2_ * _e252) + (a3_ * 0.15915494f))));
    out_3.back = (vec3(_e191) + a2_);
    let _e274 = weft_hair_sqr((1f - _e202));
    out_3.albedo = (((vec3(_e191) + (_e274 * t2_)) + a2_) + a3_);
    let _e280 = out_3;
    return _e280;
}

fn hair_from_varyings(in_5: HairVaryings, sigma_a_1: vec3<f32>) -> WeftHair {
    let v_3 = in_5.fibre.z;
    return WeftHair(max(sigma_a_1, vec3(0f)), in_5.fibre.x, vec4<f32>(v_3, (0.25f * v_3), (4f * v_3), (4f * v_3)), in_5.fibre.y, in_5.sin2k.xyz, in_5.cos2k.xyz, in_5.inv_v.xyz, in_5.mp_norm.xyz, vec2<f32>(in_5.cos2k.w, in_5.mp_norm.w), in_5.sin2k.w, vec4<f32>(in_5.inv_v.w, in_5.trt.xyz), in_5.trt.w, in_5.jitter.z);
}

fn hair_strand(frame: mat3x3<f32>, uv0_: vec2<f32>) -> vec3<f32> {
    var ts: vec2<f32>;

    ts = vec2<f32>(0f, 1f);
    let _e6 = ts.x;
    let _e10 = ts.y;
    let _e14 = weft_safe_normalize(((frame[0] * _e6) + (frame[1] * _e10)), frame[1]);
    return _e14;
}

fn hair_hash(x_4: u32) -> f32 {
    let state = ((x_4 * 747796405u) + 2891336453u);
    let word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (f32(((word >> 22u) ^ word)) * 0.00000000023283064f);
}

fn hair_value_noise(x_5: f32, p: f32) -> f32 {
    let cell = floor(x_5);
    let f_1 = (x_5 - cell);
    let c0_ = (cell - (p * floor((cell / p))));
    let c1_ = select((c0_ + 1f), 0f, ((c0_ + 1f) >= p));
    let _e16 = hair_hash(u32(c0_));
    let _e18 = hair_hash(u32(c1_));
    return (mix(_e16, _e18, ((f_1 * f_1) * (3f - (2f * f_1)))) - 0.5f);
}

fn weft_transform_uv_k4_(uv: vec2<f32>) -> vec2<f32> {
    return (uv + vec2<f32>(0f, 0f));
}

fn hair_jitter(uv0_1: vec2<f32>, rotation: vec2<f32>, noise_period: f32) -> f32 {
    let c_1 = rotation.x;
    let s_4 = rotation.y;
    let rotated = vec2<f32>(((c_1 * uv0_1.x) + (s_4 * uv0_1.y)), ((-(s_4) * uv0_1.x) + (c_1 * uv0_1.y)));
    let _e18 = weft_transform_uv_k4_(uv0_1);
    let _e21 = textureSample(jitter_map, material_sampler, _e18);
    let j = _e21.x;
    let across = _e18.x;
    let _e26 = hair_value_noise((across * 128f), noise_period);
    return (j + (0.2f * _e26));
}

fn weft_hair_params_k5_() -> WeftHair {
    var hair_1: WeftHair;

    hair_1.sigma_a = vec3<f32>(0f, 0f, 0f);
    hair_1.eta = 1.55f;
    hair_1.v = vec4<f32>(0.03157018f, 0.007892545f, 0.12628073f, 0.12628073f);
    hair_1.s = 0.11715981f;
    hair_1.sin2k = vec3<f32>(0.034899496f, 0.06975647f, 0.1391731f);
    hair_1.cos2k = vec3<f32>(0.99939084f, 0.9975641f, 0.9902682f);
    hair_1.inv_v = vec3<f32>(31.675459f, 126.701836f, 7.9188647f);
    let _e30 = hair_1.inv_v.x;
    let e_trt = exp((-0.5f * _e30));
    let _e35 = weft_hair_sqr((e_trt * e_trt));
    let _e38 = hair_1.inv_v;
    let _e41 = weft_hair_sqr((_e35 * _e35));
    hair_1.mp_norm = (_e38 / (vec3(1f) - vec3<f32>(_e35, _e41, e_trt)));
    let _e47 = hair_1.s;
    let d = (0.8162094f * _e47);
    hair_1.blur = vec2<f32>(sin(d), cos(d));
    let _e55 = hair_1.s;
    let _e58 = weft_hair_sqr((0.4534f * _e55));
    hair_1.r_floor = _e58;
    let sh_1 = hair_1.s;
    hair_1.trt = vec4<f32>((-9.2609f + (sh_1 * (65.993f - (107.38f * sh_1)))), (72.357f + (sh_1 * (-624.68f + (1069.8f * sh_1)))), (-153.75f + (sh_1 * (1704.7f - (3127.5f * sh_1)))), (-67.745f + (sh_1 * (-1105.8f + (2706.6f * sh_1)))));
    hair_1.trt4_ = (239.74f - (430.94f * sh_1));
    let _e98 = hair_1.eta;
    hair_1.inv_eta = (1f / _e98);
    let _e101 = hair_1;
    return _e101;
}

fn weft_hair_sigma_a_scaled_k8_(scale_1: f32) -> vec3<f32> {
    let l = (vec3<f32>(-2.6140277f, -3.9318867f, -5.1191573f) * scale_1);
    return (l * l);
}

@vertex 
fn vs_outline(in: WeftOutlineVertex) -> WeftOutlineVaryings {
    var local: bool;
    var local_1: bool;
    var out: WeftOutlineVaryings;

    let _e3 = weft_object.model;
    let world_1 = (_e3 * vec4<f32>(in.position, 1f));
    let nm_1 = weft_object.normal_matrix;
    let normal = (mat3x3<f32>(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz) * in.normal);
    let _e22 = weft_frame.view_proj;
    let clip = (_e22 * vec4<f32>(world_1.xyz, 1f));
    let _e29 = weft_frame.viewport;
    let size = _e29.xy;
    let _e33 = weft_frame.view_proj;
    let screen_normal = ((_e33 * vec4<f32>(normal, 0f)).xy * size);
    let len = length(screen_normal);
    if (len > 0.000001f) {
        let _e47 = weft_frame.viewport.x;
        local = (_e47 > 0f);
    } else {
        local = false;
    }
    let _e51 = local;
    if _e51 {
        local_1 = (clip.w > 0f);
    } else {
        local_1 = false;
    }
    let usable = local_1;
    let direction = select(vec2(0f), (screen_normal / vec2(max(len, 0.000001f))), usable);
    let distance_ = min(clip.w, 10f);
    let _e74 = weft_frame.viewport;
    let offset = ((((direction * 1.5f) * 2f) * _e74.zw) * distance_);
    out.clip_position = vec4<f32>((clip.xy + offset), clip.zw);
    let _e84 = out;
    return _e84;
}

@fragment 
fn fs_outline() -> @location(0) vec4<f32> {
    return vec4<f32>(vec3<f32>(0f, 0f, 0f), 1f);
}

@vertex 
fn vs_fringe_shadow(in_1: WeftFringeShadowVertex) -> WeftFringeShadowVaryings {
    var local_2: bool;
    var out_1: WeftFringeShadowVaryings;

    let _e3 = weft_object.model;
    let world_2 = (_e3 * vec4<f32>(in_1.position, 1f)).xyz;
    let _e11 = weft_frame.view_proj;
    let clip_1 = (_e11 * vec4<f32>(world_2, 1f));
    let _e17 = weft_frame.light_direction;
    let l_1 = _e17.xyz;
    let l_len = length(l_1);
    let travel = select(vec3(0f), (-(l_1) / vec3(max(l_len, 0.000001f))), (l_len > 0.000001f));
    let _e32 = weft_frame.view_proj;
    let pushed = (_e32 * vec4<f32>((world_2 + (travel * 0.16f)), 1f));
    if (clip_1.w > 0.000001f) {
        local_2 = (pushed.w > 0.000001f);
    } else {
        local_2 = false;
    }
    let usable_1 = local_2;
    let offset_ndc = select(vec2(0f), ((pushed.xy / vec2(max(pushed.w, 0.000001f))) - (clip_1.xy / vec2(max(clip_1.w, 0.000001f)))), usable_1);
    out_1.clip_position = vec4<f32>((clip_1.xy + (offset_ndc * clip_1.w)), clip_1.zw);
    let _e71 = out_1;
    return _e71;
}

@fragment 
fn fs_fringe_shadow() -> @location(0) vec4<f32> {
    return vec4<f32>(vec3<f32>(0.5704816f, 0.34239164f, 0.34239164f), 1f);
}

@vertex 
fn vs_hair(in_2: WeftVertexInput) -> HairVaryings {
    var h: WeftHair;
    var scale: f32 = 0f;

    let _e1 = weft_forward_vertex(in_2);
    let _e2 = weft_hair_params_k5_();
    h = _e2;
    {
    }
    let _e12 = h.eta;
    let _e14 = h.s;
    let _e17 = h.v.x;
    let _e21 = h.sin2k;
    let _e23 = h.r_floor;
    let _e26 = h.cos2k;
    let _e29 = h.blur.x;
    let _e32 = h.mp_norm;
    let _e35 = h.blur.y;
    let _e38 = h.inv_v;
    let _e41 = h.trt.x;
    let _e44 = h.trt;
    let _e47 = h.trt4_;
    let _e52 = h.inv_eta;
    return HairVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, vec4<f32>(_e12, _e14, _e17, 0.16982499f), vec4<f32>(_e21, _e23), vec4<f32>(_e26, _e29), vec4<f32>(_e32, _e35), vec4<f32>(_e38, _e41), vec4<f32>(_e44.yzw, _e47), vec4<f32>(-0.00000004371139f, 1f, _e52, 128f));
}

@fragment 
fn fs_main(in_3: HairVaryings) -> @location(0) vec4<f32> {
    var color: vec3<f32>;
    var lobes: WeftHairLobes;

    let _e6 = weft_surface(in_3.world_position, in_3.world_normal);
    let v_4 = _e6.v;
    let n_3 = _e6.n;
    let _e10 = weft_tangent_frame(n_3, in_3.world_tangent);
    let _e12 = hair_strand(_e10, in_3.uv0_);
    let _e18 = hair_jitter(in_3.uv0_, in_3.jitter.xy, in_3.jitter.w);
    let _e19 = weft_main_light_direction();
    let _e20 = weft_main_light_radiance();
    let _e21 = weft_sh_irradiance(n_3);
    let n_dot_l = dot(n_3, _e19);
    {
        let _e26 = weft_safe_normalize((_e12 + (_e18 * n_3)), _e12);
        let _e29 = weft_hair_sigma_a_scaled_k8_(in_3.fibre.w);
        let _e30 = hair_from_varyings(in_3, _e29);
        {
            let _e32 = weft_hair_fast(_e30, _e26, v_4, _e19);
            lobes = _e32;
        }
        let body = smoothstep(-0.25f, HAIR_TERMINATOR, n_dot_l);
        let _e38 = lobes.back;
        let multiple = (vec3<f32>(0.073238954f, 0.019606648f, 0.0059810597f) * (vec3(1f) - _e38));
        let _e42 = lobes.s;
        let direct = ((_e42 * body) + (multiple * (WEFT_INV_PI * saturate(n_dot_l))));
        let _e51 = lobes.back;
        color = ((direct * _e20) + (_e21 * (multiple + _e51)));
    }
    let _e55 = color;
    let radiance = clamp(_e55, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
