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
@group(1) @binding(7) 
var color_ramp: texture_2d<f32>;

fn gradient_color_ramp(x: f32) -> vec4<f32> {
    let _e9 = textureSampleLevel(color_ramp, material_clamp_sampler, vec2<f32>(clamp(x, 0f, 1f), 0.5f), 0f);
    return _e9;
}

fn weft_pow5_(x_1: f32) -> f32 {
    let x2_ = (x_1 * x_1);
    return ((x2_ * x2_) * x_1);
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

fn weft_d_ggx_nh(n_1: vec3<f32>, h: vec3<f32>, roughness_1: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_1);
    let a = (_e3 * _e3);
    let a2_ = (a * a);
    let noh = saturate(dot(n_1, h));
    let nxh = cross(n_1, h);
    let d = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d * d), 0.000000000000000000000000000001f)));
}

fn weft_f_schlick(f0_: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (f0_ + ((vec3(1f) - f0_) * _e5));
}

fn weft_v_smith_ggx_correlated(n_dot_v: f32, n_dot_l: f32, roughness_2: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_2);
    let a_1 = (_e3 * _e3);
    let a2_1 = (a_1 * a_1);
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

fn weft_sh_irradiance(n_2: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    let sh = weft_frame.sh;
    e = (sh[0].xyz * 0.282095f);
    let _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603f * n_2.y)));
    let _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603f * n_2.z)));
    let _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603f * n_2.x)));
    let _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548f * n_2.x) * n_2.y)));
    let _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548f * n_2.y) * n_2.z)));
    let _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392f * (((3f * n_2.z) * n_2.z) - 1f))));
    let _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548f * n_2.x) * n_2.z)));
    let _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274f * ((n_2.x * n_2.x) - (n_2.y * n_2.y)))));
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
    let uv_1 = vec2<f32>(saturate(n_dot_v_1), saturate(roughness_5));
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_1, 0f);
    return _e8.xy;
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_main_light_geometry(n_3: vec3<f32>, v_1: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_1), n_3);
    let _e6 = weft_clamp_cos(dot(n_3, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_3, _e2)), saturate(dot(n_3, _e4)), saturate(dot(v_1, _e4)));
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

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn laser_rgb_to_hsv(rgb: vec3<f32>) -> vec3<f32> {
    var hue: f32 = 0f;

    let max_c = max(rgb.x, max(rgb.y, rgb.z));
    let min_c = min(rgb.x, min(rgb.y, rgb.z));
    let chroma = (max_c - min_c);
    if (chroma > 0.000001f) {
        if (max_c == rgb.x) {
            hue = ((rgb.y - rgb.z) / chroma);
        } else {
            if (max_c == rgb.y) {
                hue = (((rgb.z - rgb.x) / chroma) + 2f);
            } else {
                hue = (((rgb.x - rgb.y) / chroma) + 4f);
            }
        }
        let _e36 = hue;
        hue = fract(((_e36 / 6f) + 1f));
    }
    let saturation = select(0f, (chroma / max_c), (max_c > 0.000001f));
    let _e47 = hue;
    return vec3<f32>(_e47, saturation, max_c);
}

fn laser_hsv_to_rgb(hsv: vec3<f32>) -> vec3<f32> {
    let k = vec3<f32>(0f, 0.6666667f, 0.33333334f);
    let p = abs(((fract((vec3(hsv.x) + k)) * 6f) - vec3(3f)));
    let ring = saturate((p - vec3(1f)));
    return (hsv.z * mix(vec3(1f), ring, hsv.y));
}

fn laser_seed_color(cos_theta: f32, layer_offsets: vec2<f32>) -> vec3<f32> {
    var hsv_1: vec3<f32>;

    let c_2 = saturate(cos_theta);
    let _e13 = material.sin_mapping;
    let x_2 = select((1f - c_2), sqrt(max((1f - (c_2 * c_2)), 0f)), (_e13 != 0u));
    let _e19 = material.saturation;
    let saturation_1 = saturate(_e19);
    let _e23 = material.brightness;
    let brightness = saturate(_e23);
    let _e27 = material.span;
    hsv_1 = vec3<f32>((x_2 * _e27), saturation_1, brightness);
    {
        let _e31 = gradient_color_ramp(x_2);
        let _e34 = laser_rgb_to_hsv(saturate(_e31.xyz));
        hsv_1 = vec3<f32>(_e34.x, (_e34.y * saturation_1), (_e34.z * brightness));
    }
    let _e42 = hsv_1.x;
    let _e45 = material.view_offset;
    let hue_1 = (_e42 + _e45);
    let _e51 = hsv_1.y;
    let _e53 = hsv_1.z;
    let _e55 = laser_hsv_to_rgb(vec3<f32>(fract((hue_1 + layer_offsets.x)), _e51, _e53));
    let _e60 = hsv_1.y;
    let _e62 = hsv_1.z;
    let _e64 = laser_hsv_to_rgb(vec3<f32>(fract((hue_1 + layer_offsets.y)), _e60, _e62));
    return (0.5f * (_e55 + _e64));
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
    let v_2 = _e52.v;
    let geometric_n = _e52.n;
    n = geometric_n;
    let _e56 = n;
    let _e57 = weft_main_light_geometry(_e56, v_2);
    film_cos = _e57.n_dot_v;
    surface_base = base;
    {
        let _e64 = film_cos;
        let _e65 = laser_seed_color(_e64, offsets);
        surface_base = (base * _e65);
    }
    let _e69 = surface_base;
    let f0_2 = mix(vec3(0.04f), _e69, metallic);
    let _e71 = surface_base;
    let diffuse_albedo = (_e71 * (1f - metallic));
    let _e76 = weft_env_brdf_lut(_e57.n_dot_v, roughness_6);
    let _e78 = weft_f_schlick(f0_2, _e57.v_dot_h);
    f_light = _e78;
    let _e80 = weft_env_brdf_from_lut(f0_2, _e76);
    e_spec = _e80;
    let _e84 = e_spec;
    let kd = max((vec3(1f) - _e84), vec3(0f));
    let _e91 = weft_v_smith_ggx_correlated(_e57.n_dot_v, _e57.n_dot_l, roughness_6);
    let _e92 = n;
    let _e94 = weft_d_ggx_nh(_e92, _e57.h, roughness_6);
    let _e96 = f_light;
    let specular = ((_e94 * _e91) * _e96);
    let _e98 = weft_diffuse_lambert(diffuse_albedo);
    let diffuse = (kd * _e98);
    let _e101 = weft_main_light_radiance();
    let direct = (((diffuse + specular) * _e101) * _e57.n_dot_l);
    let _e106 = n;
    let _e108 = weft_prefiltered_radiance(reflect(-(v_2), _e106), roughness_6);
    let _e109 = e_spec;
    let indirect_specular = ((_e108 * _e109) * ao);
    let _e112 = n;
    let _e113 = weft_sh_irradiance(_e112);
    let indirect_diffuse = (((_e113 * ao) * kd) * diffuse_albedo);
    let color = ((direct + indirect_specular) + indirect_diffuse);
    return vec4<f32>(clamp(color, vec3(0f), vec3(65504f)), alpha);
}
