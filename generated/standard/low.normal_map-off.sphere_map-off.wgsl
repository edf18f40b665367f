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
    normal_strength: f32,
    specular_strength: f32,
    emissive: vec4<f32>,
    emissive_strength: f32,
    alpha_cutoff: f32,
    sphere_strength: f32,
    base_map_st: vec4<f32>,
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
const SPHERE_MAP_OFF: u32 = 0u;
const SPHERE_MAP_ADD: u32 = 1u;
const SPHERE_MAP_MULTIPLY: u32 = 2u;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const TIER_LOW: u32 = 3u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_MIN_ROUGHNESS_HALF: f32 = 0.089f;
const WEFT_MIN_N_DOT_HALF: f32 = 0.001f;
const WEFT_MIN_ALPHA_HALF: f32 = 0.007921f;

override ALPHA_TEST: bool = false;
override EMISSION: bool = false;

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
@group(1) @binding(3) 
var emissive_map: texture_2d<f32>;
@group(1) @binding(4) 
var base_map: texture_2d<f32>;
@group(1) @binding(6) 
var rmo_map: texture_2d<f32>;

fn weft_clamp_cos(c: f32) -> f32 {
    return clamp(c, WEFT_MIN_N_DOT, 1f);
}

fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v, v);
    return select(fallback, (v * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_env_brdf_from_lut(f0_: vec3<f32>, scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return ((f0_ * sb.x) + vec3(sb.y));
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

fn weft_specular_mip(roughness: f32) -> f32 {
    let r = saturate(roughness);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r * (1.7f - (0.7f * r))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_1: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_1);
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
}

fn weft_env_brdf_lut(n_dot_v: f32, roughness_2: f32) -> vec2<f32> {
    let uv_2 = vec2<f32>(saturate(n_dot_v), saturate(roughness_2));
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_2, 0f);
    return _e8.xy;
}

fn weft_surface_two_sided(world_position_1: vec3<f32>, world_normal: vec3<f32>, front_facing_1: bool) -> WeftSurface {
    let _e7 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let facing = select(-(world_normal), world_normal, front_facing_1);
    let _e10 = weft_safe_normalize(facing, _e7);
    return WeftSurface(_e7, _e10);
}

fn weft_main_light_geometry(n_2: vec3<f32>, v_1: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_1), n_2);
    let _e6 = weft_clamp_cos(dot(n_2, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_2, _e2)), saturate(dot(n_2, _e4)), saturate(dot(v_1, _e4)));
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

fn weft_half_min_max(x: f32) -> f32 {
    return min(x, 65504f);
}

fn weft_half_pow5_(x_1: f32) -> f32 {
    let x2_ = (x_1 * x_1);
    return ((x2_ * x2_) * x_1);
}

fn weft_half_d_ggx(one_minus_n_dot_h2_: f32, n_dot_h: f32, alpha: f32) -> f32 {
    let a = (n_dot_h * alpha);
    let k = (alpha / (one_minus_n_dot_h2_ + (a * a)));
    let _e10 = weft_half_min_max(((k * k) * 0.31830987f));
    return _e10;
}

fn weft_half_v_smith_ggx_correlated_newton_nl(n_dot_v_1: f32, n_dot_l: f32, alpha_1: f32) -> f32 {
    let x_2 = vec2<f32>(max(n_dot_v_1, 0.001f), n_dot_l);
    let alpha2_ = (alpha_1 * alpha_1);
    let g = mix(x_2, vec2(1f), alpha_1);
    let inv_gg = (1f / (g.x * g.y));
    let q = (x_2 + ((alpha2_ * (vec2(1f) - x_2)) * (g.yx * inv_gg)));
    let denominator = ((x_2.y * q.x) + (x_2.x * q.y));
    return ((0.5f * n_dot_l) / max(denominator, 0.0001f));
}

fn weft_half_f_schlick(f0_1: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let _e7 = weft_half_pow5_((1f - v_dot_h));
    return (f0_1 + ((vec3(1f) - f0_1) * _e7));
}

fn standard_emission(uv_1: vec2<f32>) -> vec3<f32> {
    if EMISSION {
        let _e4 = material.emissive_strength;
        let strength = max(_e4, 0f);
        let _e9 = material.emissive;
        let emissive = max(_e9.xyz, vec3(0f));
        let _e17 = textureSample(emissive_map, material_sampler, uv_1);
        return ((emissive * strength) * _e17.xyz);
    }
    return vec3(0f);
}

fn standard_low(n_3: vec3<f32>, v_2: vec3<f32>, lit: WeftLightGeometry, f0_in: vec3<f32>, diffuse_albedo: vec3<f32>, roughness_in: f32, ao: f32, specular_strength: f32) -> vec3<f32> {
    var direct_n_dot_l: vec3<f32>;
    var indirect_specular_1: vec3<f32> = vec3(0f);

    let n_dot_v_2 = f32(lit.n_dot_v);
    let n_dot_l_1 = f32(lit.n_dot_l);
    let n_dot_h_1 = f32(lit.n_dot_h);
    let v_dot_h_1 = f32(lit.v_dot_h);
    let one_minus_n_dot_h2_1 = f32(((1f - lit.n_dot_h) * (1f + lit.n_dot_h)));
    let roughness_3 = f32(max(roughness_in, WEFT_MIN_ROUGHNESS_HALF));
    let alpha_3 = (roughness_3 * roughness_3);
    let f0_2 = vec3<f32>(f0_in);
    let _e30 = weft_env_brdf_lut(lit.n_dot_v, roughness_in);
    let _e31 = weft_env_brdf_from_lut(f0_in, _e30);
    let env_brdf_1 = vec3<f32>(_e31);
    let kd = max((vec3(1f) - env_brdf_1), vec3(0f));
    direct_n_dot_l = (vec3<f32>((kd * (n_dot_l_1 * 0.31830987f))) * diffuse_albedo);
    if (specular_strength > 0f) {
        let _e50 = weft_half_d_ggx(one_minus_n_dot_h2_1, n_dot_h_1, alpha_3);
        let _e51 = weft_half_v_smith_ggx_correlated_newton_nl(n_dot_v_2, n_dot_l_1, alpha_3);
        let _e52 = weft_half_f_schlick(f0_2, v_dot_h_1);
        let _e54 = weft_half_min_max((_e50 * _e51));
        let _e55 = direct_n_dot_l;
        direct_n_dot_l = (_e55 + (vec3<f32>((_e52 * _e54)) * specular_strength));
        let _e62 = weft_prefiltered_radiance(reflect(-(v_2), n_3), roughness_in);
        indirect_specular_1 = ((_e62 * vec3<f32>(env_brdf_1)) * (ao * specular_strength));
    }
    let _e67 = direct_n_dot_l;
    let _e68 = weft_main_light_radiance();
    let direct = (_e67 * _e68);
    let _e70 = weft_sh_irradiance(n_3);
    let indirect_diffuse = (((_e70 * ao) * vec3<f32>(kd)) * diffuse_albedo);
    let _e75 = indirect_specular_1;
    return ((direct + _e75) + indirect_diffuse);
}

fn standard_sphere_map(color_in: vec3<f32>, n_4: vec3<f32>, world_position_2: vec3<f32>) -> vec3<f32> {
    var color: vec3<f32>;

    color = color_in;
    let _e4 = color;
    return _e4;
}

fn standard_alpha_test(alpha_2: f32) {
    if ALPHA_TEST {
        let _e4 = material.alpha_cutoff;
        if (alpha_2 < _e4) {
            discard;
        } else {
            return;
        }
    } else {
        return;
    }
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var visibility: f32;
    var env_brdf: vec3<f32>;
    var ambient_kd: vec3<f32>;
    var direct_kd: vec3<f32>;
    var specular: vec3<f32> = vec3(0f);
    var indirect_specular: vec3<f32> = vec3(0f);
    var d: f32;

    let _e5 = material.base_map_st;
    let _e6 = weft_transform_uv(in_1.uv0_, _e5);
    let _e9 = material.base_color;
    let _e12 = textureSample(base_map, material_sampler, _e6);
    let base_rgba = (_e9 * _e12);
    let base = saturate(base_rgba.xyz);
    let alpha_4 = saturate(base_rgba.w);
    let _e20 = textureSample(rmo_map, material_sampler, _e6);
    let rmo = _e20.xyz;
    let _e22 = standard_emission(_e6);
    let _e25 = material.roughness;
    let roughness_4 = saturate((_e25 * rmo.x));
    let _e31 = material.metallic;
    let metallic = saturate((_e31 * rmo.y));
    let _e38 = material.occlusion_strength;
    let ao_1 = saturate(mix(1f, rmo.z, _e38));
    let _e44 = material.specular_strength;
    let specular_strength_1 = max(_e44, 0f);
    let _e49 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    let v_3 = _e49.v;
    n = _e49.n;
    let _e53 = n;
    let _e54 = weft_main_light_geometry(_e53, v_3);
    let f0_3 = mix(vec3(0.04f), base, metallic);
    let diffuse_albedo_1 = (base * (1f - metallic));
    {
        let _e61 = n;
        let _e62 = standard_low(_e61, v_3, _e54, f0_3, diffuse_albedo_1, roughness_4, ao_1, specular_strength_1);
        let _e63 = n;
        let _e65 = standard_sphere_map(_e62, _e63, in_1.world_position);
        let radiance = clamp((_e65 + _e22), vec3(0f), vec3(65504f));
        standard_alpha_test(alpha_4);
        return vec4<f32>(radiance, alpha_4);
    }
}
