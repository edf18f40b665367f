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

struct WeftOutlineVertex {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
}

struct WeftOutlineVaryings {
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
    let s = select(-1f, 1f, (n.z >= 0f));
    let a = (-1f / (s + n.z));
    let b = ((n.x * n.y) * a);
    return vec3<f32>((1f + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
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
    let t_1 = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_2, t_1) * s_1);
    return mat3x3<f32>(t_1, b_1, n_2);
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

fn weft_hair_params(sigma_a: vec3<f32>, eta: f32, beta_m_1: f32, beta_n_1: f32, alpha_deg: f32) -> WeftHair {
    var hair: WeftHair;

    hair.sigma_a = max(sigma_a, vec3(0f));
    hair.eta = max(eta, 1.0001f);
    let _e13 = weft_hair_variance(beta_m_1);
    hair.v = vec4<f32>(_e13, (0.25f * _e13), (4f * _e13), (4f * _e13));
    let _e23 = weft_hair_logistic_scale(beta_n_1);
    hair.s = _e23;
    let a_1 = radians(alpha_deg);
    let s0_ = sin(a_1);
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
    let d = (0.8162094f * _e73);
    hair.blur = vec2<f32>(sin(d), cos(d));
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

fn hair_noise_period(density: f32) -> f32 {
    return max(round(density), 1f);
}

fn hair_strand(frame: mat3x3<f32>, uv0_: vec2<f32>) -> vec3<f32> {
    var ts: vec2<f32>;

    let _e10 = material.strand_along_tangent;
    ts = select(vec2<f32>(0f, 1f), vec2<f32>(1f, 0f), (_e10 != 0u));
    {
        let _e17 = textureSample(flow_map, material_sampler, uv0_);
        let f = ((_e17.xy * 2f) - vec2(1f));
        let len2_2 = dot(f, f);
        let _e25 = ts;
        ts = select(_e25, (f * inverseSqrt(max(len2_2, 0.000000000001f))), (len2_2 > 0.0001f));
    }
    let _e35 = ts.x;
    let _e39 = ts.y;
    let _e43 = weft_safe_normalize(((frame[0] * _e35) + (frame[1] * _e39)), frame[1]);
    return _e43;
}

fn hair_hash(x_2: u32) -> f32 {
    let state = ((x_2 * 747796405u) + 2891336453u);
    let word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return (f32(((word >> 22u) ^ word)) * 0.00000000023283064f);
}

fn hair_value_noise(x_3: f32, p: f32) -> f32 {
    let cell = floor(x_3);
    let f_1 = (x_3 - cell);
    let c0_ = (cell - (p * floor((cell / p))));
    let c1_1 = select((c0_ + 1f), 0f, ((c0_ + 1f) >= p));
    let _e16 = hair_hash(u32(c0_));
    let _e18 = hair_hash(u32(c1_1));
    return (mix(_e16, _e18, ((f_1 * f_1) * (3f - (2f * f_1)))) - 0.5f);
}

fn hair_jitter(uv0_1: vec2<f32>, rotation: vec2<f32>, noise_period: f32) -> f32 {
    let _e5 = textureSample(uv_rotate_mask, material_sampler, uv0_1);
    let mask = step(0.8f, _e5.x);
    let c = rotation.x;
    let s_2 = rotation.y;
    let rotated = vec2<f32>(((c * uv0_1.x) + (s_2 * uv0_1.y)), ((-(s_2) * uv0_1.x) + (c * uv0_1.y)));
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

fn hair_kajiya_kay(t: vec3<f32>, h_1: vec3<f32>, exponent: f32) -> f32 {
    let t_dot_h = clamp(dot(t, h_1), -1f, 1f);
    let sin_th = sqrt(max((1f - (t_dot_h * t_dot_h)), 0f));
    let dir_atten = smoothstep(-1f, 0f, t_dot_h);
    return (dir_atten * pow(sin_th, max(exponent, 1f)));
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
    let _e68 = material.outline_width;
    let width_px = max(_e68, 0f);
    let _e74 = material.outline_max_distance;
    let distance_ = min(clip.w, max(_e74, 0f));
    let _e83 = weft_frame.viewport;
    let offset = ((((direction * width_px) * 2f) * _e83.zw) * distance_);
    out.clip_position = vec4<f32>((clip.xy + offset), clip.zw);
    let _e93 = out;
    return _e93;
}

@fragment 
fn fs_outline() -> @location(0) vec4<f32> {
    let _e2 = material.outline_color;
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
        h = WeftHair();
    }
    let _e23 = material.anisotropic_direction;
    let a_2 = radians(_e23);
    let _e31 = h.eta;
    let _e33 = h.s;
    let _e36 = h.v.x;
    let _e37 = scale;
    let _e40 = h.sin2k;
    let _e42 = h.r_floor;
    let _e45 = h.cos2k;
    let _e48 = h.blur.x;
    let _e51 = h.mp_norm;
    let _e54 = h.blur.y;
    let _e57 = h.inv_v;
    let _e60 = h.trt.x;
    let _e63 = h.trt;
    let _e66 = h.trt4_;
    let _e71 = h.inv_eta;
    let _e74 = material.strand_density;
    let _e75 = hair_noise_period(_e74);
    return HairVaryings(_e1.clip_position, _e1.world_position, _e1.world_normal, _e1.world_tangent, _e1.uv0_, vec4<f32>(_e31, _e33, _e36, _e37), vec4<f32>(_e40, _e42), vec4<f32>(_e45, _e48), vec4<f32>(_e51, _e54), vec4<f32>(_e57, _e60), vec4<f32>(_e63.yzw, _e66), vec4<f32>(cos(a_2), sin(a_2), _e71, _e75));
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
    let v_1 = _e19.v;
    let n_3 = _e19.n;
    let _e23 = weft_tangent_frame(n_3, in_2.world_tangent);
    let _e25 = hair_strand(_e23, in_2.uv0_);
    let _e31 = hair_jitter(in_2.uv0_, in_2.jitter.xy, in_2.jitter.w);
    let _e32 = weft_main_light_direction();
    let _e33 = weft_main_light_radiance();
    let _e34 = weft_sh_irradiance(n_3);
    let n_dot_l = dot(n_3, _e32);
    {
        let _e38 = weft_safe_normalize((_e32 + v_1), n_3);
        let _e41 = material.primary_shift;
        let _e45 = weft_safe_normalize((_e25 + ((_e41 + _e31) * n_3)), _e25);
        let _e48 = material.secondary_shift;
        let _e52 = weft_safe_normalize((_e25 + ((_e48 + _e31) * n_3)), _e25);
        let _e55 = material.primary_color;
        let _e59 = material.primary_intensity;
        let _e62 = material.primary_exponent;
        let _e63 = hair_kajiya_kay(_e45, _e38, _e62);
        let primary = (_e55.xyz * (_e59 * _e63));
        let _e68 = material.secondary_color;
        let _e72 = material.secondary_intensity;
        let _e75 = material.secondary_exponent;
        let _e76 = hair_kajiya_kay(_e52, _e38, _e75);
        let secondary = (_e68.xyz * (_e72 * _e76));
        let direct = (((((base + primary) + secondary) * WEFT_INV_PI) * _e33) * saturate(n_dot_l));
        color = (direct + (_e34 * base));
    }
    let _e88 = color;
    let radiance = clamp(_e88, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
