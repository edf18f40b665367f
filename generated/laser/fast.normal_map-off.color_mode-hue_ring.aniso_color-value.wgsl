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
    roughness: f32,
    metallic: f32,
    occlusion_strength: f32,
    base_map_st: vec4<f32>,
    normal_strength: f32,
    saturation: f32,
    brightness: f32,
    span: f32,
    view_offset: f32,
    offset_map_st: vec4<f32>,
    sin_mapping: u32,
    color_direction: f32,
    film_strength: f32,
    film_ior: f32,
    thickness_min: f32,
    thickness_max: f32,
}

struct WeftSurface {
    v: vec3<f32>,
    n: vec3<f32>,
}

struct WeftLightGeometry {
    l: vec3<f32>,
    h: vec3<f32>,
    n_dot_v: f32,
    n_dot_l: f32,
    n_dot_h: f32,
    v_dot_h: f32,
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

struct WeftFilmStack {
    n2_: f32,
    cos2_: f32,
    r12_: vec2<f32>,
    r23_: array<vec3<f32>, 2>,
    total_internal_reflection: bool,
}

struct WeftFilmSeries {
    dc: vec3<f32>,
    first: vec3<f32>,
    ratio: vec3<f32>,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const film_sensitivity_opd_max: f32 = 16000f;
const COLOR_MODE_HUE_RING: u32 = 0u;
const COLOR_MODE_CUSTOM: u32 = 1u;
const ANISO_COLOR_OFF: u32 = 0u;
const ANISO_COLOR_VALUE: u32 = 1u;
const ANISO_COLOR_MAP: u32 = 2u;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_FILM_PI: f32 = 3.1415927f;
const WEFT_FILM_SAMPLES: u32 = 101u;
const WEFT_FILM_LAMBDA_MIN: f32 = 380f;
const WEFT_FILM_LAMBDA_MAX: f32 = 780f;
const WEFT_FILM_FADE_NM: f32 = 30f;
const WEFT_XYZ_TO_REC709_: mat3x3<f32> = mat3x3<f32>(vec3<f32>(3.2404542f, -0.969266f, 0.0556434f), vec3<f32>(-1.5371385f, 1.8760108f, -0.2040259f), vec3<f32>(-0.4985314f, 0.041556f, 1.0572252f));

@group(0) @binding(0) 
var<uniform> weft_frame: WeftFrame;
@group(0) @binding(1) 
var weft_environment: texture_cube<f32>;
@group(0) @binding(2) 
var weft_environment_sampler: sampler;
@group(0) @binding(3) 
var weft_brdf_lut: texture_2d<f32>;
@group(0) @binding(4) 
var weft_lut_sampler: sampler;
@group(2) @binding(0) 
var<uniform> weft_object: WeftObject;
@group(1) @binding(0) 
var<uniform> material: WeftMaterial;
@group(1) @binding(1) 
var material_sampler: sampler;
@group(1) @binding(2) 
var material_clamp_sampler: sampler;
@group(1) @binding(3) 
var base_map: texture_2d<f32>;
@group(1) @binding(5) 
var rmo_map: texture_2d<f32>;
@group(1) @binding(6) 
var offset_map: texture_2d<f32>;
@group(1) @binding(9) 
var film_sensitivity: texture_2d<f32>;

fn table_film_sensitivity(uv: vec2<f32>) -> vec4<f32> {
    let size = vec2<f32>(2048f, 2f);
    let st_1 = (((clamp(uv, vec2(0f), vec2(1f)) * (size - vec2(1f))) + vec2(0.5f)) / size);
    let _e20 = textureSampleLevel(film_sensitivity, material_clamp_sampler, st_1, 0f);
    return _e20;
}

fn weft_pow5_(x: f32) -> f32 {
    let x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

fn weft_clamp_cos(c: f32) -> f32 {
    return clamp(c, WEFT_MIN_N_DOT, 1f);
}

fn weft_clamp_roughness(roughness: f32) -> f32 {
    return clamp(roughness, WEFT_MIN_ROUGHNESS, 1f);
}

fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v, v);
    return select(fallback, (v * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_any_perpendicular(n_1: vec3<f32>) -> vec3<f32> {
    let s_1 = select(-1f, 1f, (n_1.z >= 0f));
    let a = (-1f / (s_1 + n_1.z));
    let b = ((n_1.x * n_1.y) * a);
    return vec3<f32>((1f + (((s_1 * n_1.x) * n_1.x) * a)), (s_1 * b), (-(s_1) * n_1.x));
}

fn weft_d_ggx_nh(n_2: vec3<f32>, h: vec3<f32>, roughness_1: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_1);
    let a_1 = (_e3 * _e3);
    let a2_ = (a_1 * a_1);
    let noh = saturate(dot(n_2, h));
    let nxh = cross(n_2, h);
    let d = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d * d), 0.000000000000000000000000000001f)));
}

fn weft_f_schlick(f0_: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (f0_ + ((vec3(1f) - f0_) * _e5));
}

fn weft_v_smith_ggx_correlated(n_dot_v: f32, n_dot_l: f32, roughness_2: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_2);
    let a_2 = (_e3 * _e3);
    let a2_1 = (a_2 * a_2);
    let _e6 = weft_clamp_cos(n_dot_v);
    let _e7 = weft_clamp_cos(n_dot_l);
    let lv = (_e7 * sqrt((((_e6 * _e6) * (1f - a2_1)) + a2_1)));
    let ll = (_e6 * sqrt((((_e7 * _e7) * (1f - a2_1)) + a2_1)));
    return (0.5f / (lv + ll));
}

fn weft_diffuse_lambert(albedo: vec3<f32>) -> vec3<f32> {
    return (albedo * WEFT_INV_PI);
}

fn weft_env_brdf_from_lut(f0_1: vec3<f32>, scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return ((f0_1 * sb.x) + vec3(sb.y));
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

fn weft_sh_irradiance(n_3: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    let sh = weft_frame.sh;
    e = (sh[0].xyz * 0.282095f);
    let _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603f * n_3.y)));
    let _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603f * n_3.z)));
    let _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603f * n_3.x)));
    let _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548f * n_3.x) * n_3.y)));
    let _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548f * n_3.y) * n_3.z)));
    let _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392f * (((3f * n_3.z) * n_3.z) - 1f))));
    let _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548f * n_3.x) * n_3.z)));
    let _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274f * ((n_3.x * n_3.x) - (n_3.y * n_3.y)))));
    let _e91 = e;
    return max(_e91, vec3(0f));
}

fn weft_specular_mip(roughness_3: f32) -> f32 {
    let r = saturate(roughness_3);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r * (1.7f - (0.7f * r))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_4: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_4);
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
}

fn weft_env_brdf_lut(n_dot_v_1: f32, roughness_5: f32) -> vec2<f32> {
    let uv_2 = vec2<f32>(saturate(n_dot_v_1), saturate(roughness_5));
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_2, 0f);
    return _e8.xy;
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_main_light_geometry(n_4: vec3<f32>, v_1: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_1), n_4);
    let _e6 = weft_clamp_cos(dot(n_4, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_4, _e2)), saturate(dot(n_4, _e4)), saturate(dot(v_1, _e4)));
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

fn weft_tangent_frame(n_5: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_5 * dot(n_5, t_in)));
    let len2_1 = dot(t_proj, t_proj);
    let ok = (len2_1 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_5);
    let t = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_2 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_5, t) * s_2);
    return mat3x3<f32>(t, b_1, n_5);
}

fn weft_transform_uv(uv_1: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv_1 * st.xy) + st.zw);
}

fn weft_ior_from_f0_(f0_2: vec3<f32>) -> vec3<f32> {
    let s_3 = sqrt(clamp(f0_2, vec3(0f), vec3(0.9999f)));
    return ((vec3(1f) + s_3) / (vec3(1f) - s_3));
}

fn weft_film_ior(film_ior: f32, thickness_nm: f32) -> f32 {
    return mix(1f, max(film_ior, 1f), smoothstep(0f, WEFT_FILM_FADE_NM, thickness_nm));
}

fn weft_fresnel_amplitudes(n_i: f32, n_t: f32, cos_i: f32, cos_t: f32) -> vec2<f32> {
    let rs = (((n_i * cos_i) - (n_t * cos_t)) / max(((n_i * cos_i) + (n_t * cos_t)), 0.000000000001f));
    let rp = (((n_t * cos_i) - (n_i * cos_t)) / max(((n_t * cos_i) + (n_i * cos_t)), 0.000000000001f));
    return vec2<f32>(rs, rp);
}

fn weft_film_base_amplitudes(n2_: f32, cos2_: f32, n3_: vec3<f32>, sin1_sq: f32) -> array<vec3<f32>, 2> {
    let cos3_ = sqrt(max((vec3(1f) - (vec3(sin1_sq) / (n3_ * n3_))), vec3(0f)));
    let s_4 = ((vec3((n2_ * cos2_)) - (n3_ * cos3_)) / max((vec3((n2_ * cos2_)) + (n3_ * cos3_)), vec3(0.000000000001f)));
    let p_1 = (((n3_ * cos2_) - (vec3(n2_) * cos3_)) / max(((n3_ * cos2_) + (vec3(n2_) * cos3_)), vec3(0.000000000001f)));
    return array<vec3<f32>, 2>(s_4, p_1);
}

fn weft_film_stack(cos_theta1_: f32, thickness_nm_1: f32, film_ior_1: f32, base_f0_: vec3<f32>) -> WeftFilmStack {
    let cos1_ = clamp(cos_theta1_, 0f, 1f);
    let sin1_sq_1 = (1f - (cos1_ * cos1_));
    let _e10 = weft_film_ior(film_ior_1, thickness_nm_1);
    let cos2_sq = (1f - (sin1_sq_1 / (_e10 * _e10)));
    if (cos2_sq <= 0f) {
        return WeftFilmStack(_e10, 0f, vec2(1f), array<vec3<f32>, 2>(vec3(1f), vec3(1f)), true);
    }
    let cos2_1 = sqrt(cos2_sq);
    let _e29 = weft_fresnel_amplitudes(1f, _e10, cos1_, cos2_1);
    let _e30 = weft_ior_from_f0_(base_f0_);
    let _e31 = weft_film_base_amplitudes(_e10, cos2_1, _e30, sin1_sq_1);
    return WeftFilmStack(_e10, cos2_1, _e29, _e31, false);
}

fn weft_film_sensitivity(opd_nm: f32) -> vec3<f32> {
    let _e5 = table_film_sensitivity(vec2<f32>((opd_nm / film_sensitivity_opd_max), 0f));
    return _e5.xyz;
}

fn weft_film_orders(opd_nm_1: f32, s: WeftFilmSeries, p: WeftFilmSeries) -> vec3<f32> {
    let k1_ = ((s.first * s.ratio) + (p.first * p.ratio));
    let k2_ = (((s.first * s.ratio) * s.ratio) + ((p.first * p.ratio) * p.ratio));
    let k3_ = ((((s.first * s.ratio) * s.ratio) * s.ratio) + (((p.first * p.ratio) * p.ratio) * p.ratio));
    let k4_ = (((s.first * (s.ratio * s.ratio)) * (s.ratio * s.ratio)) + ((p.first * (p.ratio * p.ratio)) * (p.ratio * p.ratio)));
    let _e55 = weft_film_sensitivity(opd_nm_1);
    let _e59 = weft_film_sensitivity((2f * opd_nm_1));
    let _e64 = weft_film_sensitivity((3f * opd_nm_1));
    let _e69 = weft_film_sensitivity((4f * opd_nm_1));
    let sum = ((((k1_ * _e55) + (k2_ * _e59)) + (k3_ * _e64)) + (k4_ * _e69));
    return (2f * sum);
}

fn weft_film_series(r12_: f32, r23_: vec3<f32>) -> WeftFilmSeries {
    let big_r12_ = (r12_ * r12_);
    let t121_ = (1f - big_r12_);
    let big_r23_ = (r23_ * r23_);
    let big_r123_ = min((big_r12_ * big_r23_), vec3(0.9999f));
    let rs_1 = (((t121_ * t121_) * big_r23_) / (vec3(1f) - big_r123_));
    let ratio = clamp((-(r12_) * r23_), vec3(-0.99995f), vec3(0.99995f));
    return WeftFilmSeries((vec3(big_r12_) + rs_1), (rs_1 - vec3(t121_)), ratio);
}

fn weft_film_fourier_layers(cos_theta1_1: f32, d1_: f32, d2_: f32, film_ior_2: f32, base_f0_1: vec3<f32>) -> vec3<f32> {
    let d_mean = (0.5f * (max(d1_, 0f) + max(d2_, 0f)));
    let _e12 = weft_film_stack(cos_theta1_1, d_mean, film_ior_2, base_f0_1);
    if _e12.total_internal_reflection {
        return vec3(1f);
    }
    let _e20 = weft_film_series(_e12.r12_.x, _e12.r23_[0]);
    let _e25 = weft_film_series(_e12.r12_.y, _e12.r23_[1]);
    let path = ((2f * _e12.n2_) * _e12.cos2_);
    let _e37 = weft_film_orders((path * max(d1_, 0f)), _e20, _e25);
    let r1_ = ((_e20.dc + _e25.dc) + _e37);
    let _e45 = weft_film_orders((path * max(d2_, 0f)), _e20, _e25);
    let r2_ = ((_e20.dc + _e25.dc) + _e45);
    return clamp((0.25f * (r1_ + r2_)), vec3(0f), vec3(1f));
}

fn laser_cos_in_plane(n_6: vec3<f32>, v_2: vec3<f32>, direction: vec3<f32>) -> f32 {
    let p_2 = cross(direction, n_6);
    let p_len = length(p_2);
    if (p_len < 0.0001f) {
        let _e8 = weft_clamp_cos(dot(n_6, v_2));
        return _e8;
    }
    let p_unit = (p_2 / vec3(p_len));
    let v_in_plane = (v_2 - (dot(v_2, p_unit) * p_unit));
    let len = length(v_in_plane);
    let _e19 = weft_clamp_cos((dot(n_6, v_in_plane) / max(len, 0.0001f)));
    return _e19;
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var film_cos: f32;
    var direction_ts: vec2<f32> = vec2<f32>(1f, 0f);
    var surface_base: vec3<f32>;
    var f_light: vec3<f32>;
    var e_spec: vec3<f32>;
    var light_cos: f32;
    var film_view: vec3<f32>;
    var film_light: vec3<f32>;

    let _e4 = material.base_map_st;
    let _e5 = weft_transform_uv(in_1.uv0_, _e4);
    let _e8 = material.base_color;
    let _e11 = textureSample(base_map, material_sampler, _e5);
    let base_rgba = (_e8 * _e11);
    let base = saturate(base_rgba.xyz);
    let alpha = saturate(base_rgba.w);
    let _e19 = textureSample(rmo_map, material_sampler, _e5);
    let rmo = _e19.xyz;
    let _e23 = material.roughness;
    let roughness_6 = saturate((_e23 * rmo.x));
    let _e29 = material.metallic;
    let metallic = saturate((_e29 * rmo.y));
    let _e36 = material.occlusion_strength;
    let ao = saturate(mix(1f, rmo.z, _e36));
    let _e45 = material.offset_map_st;
    let _e46 = weft_transform_uv(in_1.uv0_, _e45);
    let _e47 = textureSample(offset_map, material_sampler, _e46);
    let offsets = saturate(_e47.xy);
    let _e52 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_3 = _e52.v;
    let geometric_n = _e52.n;
    n = geometric_n;
    let _e56 = n;
    let _e57 = weft_main_light_geometry(_e56, v_3);
    film_cos = _e57.n_dot_v;
    {
        let _e61 = weft_tangent_frame(geometric_n, in_1.world_tangent);
        {
            let _e68 = material.color_direction;
            let angle = radians(_e68);
            direction_ts = vec2<f32>(cos(angle), sin(angle));
        }
        let _e75 = direction_ts.x;
        let _e79 = direction_ts.y;
        let direction_1 = ((_e61[0] * _e75) + (_e61[1] * _e79));
        let _e82 = n;
        let _e83 = laser_cos_in_plane(_e82, v_3, direction_1);
        film_cos = _e83;
    }
    surface_base = base;
    let _e87 = surface_base;
    let f0_3 = mix(vec3(0.04f), _e87, metallic);
    let _e89 = surface_base;
    let diffuse_albedo = (_e89 * (1f - metallic));
    let _e94 = weft_env_brdf_lut(_e57.n_dot_v, roughness_6);
    let _e96 = weft_f_schlick(f0_3, _e57.v_dot_h);
    f_light = _e96;
    let _e98 = weft_env_brdf_from_lut(f0_3, _e94);
    e_spec = _e98;
    {
        let _e102 = material.thickness_min;
        let _e105 = material.thickness_max;
        let d1_1 = mix(_e102, _e105, offsets.x);
        let _e110 = material.thickness_min;
        let _e113 = material.thickness_max;
        let d2_1 = mix(_e110, _e113, offsets.y);
        let _e118 = material.film_strength;
        let strength = saturate(_e118);
        light_cos = _e57.v_dot_h;
        {
            let _e122 = film_cos;
            light_cos = _e122;
        }
        {
            let _e125 = film_cos;
            let _e128 = material.film_ior;
            let _e129 = weft_film_fourier_layers(_e125, d1_1, d2_1, _e128, f0_3);
            film_view = _e129;
            let _e130 = light_cos;
            let _e133 = material.film_ior;
            let _e134 = weft_film_fourier_layers(_e130, d1_1, d2_1, _e133, f0_3);
            film_light = _e134;
        }
        let _e135 = f_light;
        let _e136 = film_light;
        f_light = mix(_e135, _e136, strength);
        let _e138 = e_spec;
        let _e139 = film_view;
        e_spec = mix(_e138, (_e139 * (_e94.x + _e94.y)), strength);
    }
    let _e147 = e_spec;
    let kd = max((vec3(1f) - _e147), vec3(0f));
    let _e154 = weft_v_smith_ggx_correlated(_e57.n_dot_v, _e57.n_dot_l, roughness_6);
    let _e155 = n;
    let _e157 = weft_d_ggx_nh(_e155, _e57.h, roughness_6);
    let _e159 = f_light;
    let specular = ((_e157 * _e154) * _e159);
    let _e161 = weft_diffuse_lambert(diffuse_albedo);
    let diffuse = (kd * _e161);
    let _e164 = weft_main_light_radiance();
    let direct = (((diffuse + specular) * _e164) * _e57.n_dot_l);
    let _e169 = n;
    let _e171 = weft_prefiltered_radiance(reflect(-(v_3), _e169), roughness_6);
    let _e172 = e_spec;
    let indirect_specular = ((_e171 * _e172) * ao);
    let _e175 = n;
    let _e176 = weft_sh_irradiance(_e175);
    let indirect_diffuse = (((_e176 * ao) * kd) * diffuse_albedo);
    let color = ((direct + indirect_specular) + indirect_diffuse);
    return vec4<f32>(clamp(color, vec3(0f), vec3(65504f)), alpha);
}
