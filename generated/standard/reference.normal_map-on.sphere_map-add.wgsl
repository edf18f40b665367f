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
@group(1) @binding(2) 
var material_clamp_sampler: sampler;
@group(1) @binding(3) 
var emissive_map: texture_2d<f32>;
@group(1) @binding(4) 
var base_map: texture_2d<f32>;
@group(1) @binding(5) 
var normal_map: texture_2d<f32>;
@group(1) @binding(6) 
var rmo_map: texture_2d<f32>;
@group(1) @binding(7) 
var sphere_map: texture_cube<f32>;

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
    let s = select(-1f, 1f, (n_1.z >= 0f));
    let a = (-1f / (s + n_1.z));
    let b = ((n_1.x * n_1.y) * a);
    return vec3<f32>((1f + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
}

fn weft_d_ggx_nh(n_2: vec3<f32>, h: vec3<f32>, roughness_1: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_1);
    let a_1 = (_e3 * _e3);
    let a2_ = (a_1 * a_1);
    let noh = saturate(dot(n_2, h));
    let nxh = cross(n_2, h);
    let d_1 = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d_1 * d_1), 0.000000000000000000000000000001f)));
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

fn weft_sphere_map_direction(world_normal: vec3<f32>, world_position_1: vec3<f32>) -> vec3<f32> {
    let view = weft_frame.view;
    let view3_ = mat3x3<f32>(view[0].xyz, view[1].xyz, view[2].xyz);
    let _e17 = weft_safe_normalize((view3_ * world_normal), vec3<f32>(0f, 0f, 1f));
    let p_vs = (view * vec4<f32>(world_position_1, 1f)).xyz;
    let _e26 = weft_safe_normalize(p_vs, vec3<f32>(0f, 0f, -1f));
    return reflect(_e26, _e17);
}

fn weft_surface_two_sided(world_position_2: vec3<f32>, world_normal_1: vec3<f32>, front_facing_1: bool) -> WeftSurface {
    let _e7 = weft_view_direction(world_position_2, vec3<f32>(0f, 0f, 1f));
    let facing = select(-(world_normal_1), world_normal_1, front_facing_1);
    let _e10 = weft_safe_normalize(facing, _e7);
    return WeftSurface(_e7, _e10);
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
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_5, t) * s_1);
    return mat3x3<f32>(t, b_1, n_5);
}

fn weft_unpack_normal(texel: vec3<f32>, strength: f32) -> vec3<f32> {
    let v_2 = ((texel * 2f) - vec3(1f));
    return vec3<f32>((v_2.xy * strength), max(v_2.z, 0.001f));
}

fn weft_normal_from_tangent_space(frame: mat3x3<f32>, n_ts: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_safe_normalize((frame * n_ts), frame[2]);
    return _e4;
}

fn weft_mapped_normal(n_6: vec3<f32>, tangent_1: vec4<f32>, texel_1: vec3<f32>, strength_1: f32) -> vec3<f32> {
    let _e4 = weft_tangent_frame(n_6, tangent_1);
    let _e5 = weft_unpack_normal(texel_1, strength_1);
    let _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
}

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn standard_emission(uv_1: vec2<f32>) -> vec3<f32> {
    if EMISSION {
        let _e4 = material.emissive_strength;
        let strength_2 = max(_e4, 0f);
        let _e9 = material.emissive;
        let emissive = max(_e9.xyz, vec3(0f));
        let _e17 = textureSample(emissive_map, material_sampler, uv_1);
        return ((emissive * strength_2) * _e17.xyz);
    }
    return vec3(0f);
}

fn standard_sphere_map(color_in: vec3<f32>, n_7: vec3<f32>, world_position_3: vec3<f32>) -> vec3<f32> {
    var color: vec3<f32>;

    color = color_in;
    {
        let _e4 = weft_sphere_map_direction(n_7, world_position_3);
        let _e7 = textureSample(sphere_map, material_clamp_sampler, _e4);
        let sph = max(_e7.xyz, vec3(0f));
        let _e12 = color;
        let _e15 = material.sphere_strength;
        color = (_e12 + (sph * _e15));
    }
    let _e18 = color;
    return _e18;
}

fn standard_alpha_test(alpha: f32) {
    if ALPHA_TEST {
        let _e4 = material.alpha_cutoff;
        if (alpha < _e4) {
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
    let alpha_1 = saturate(base_rgba.w);
    let _e20 = textureSample(rmo_map, material_sampler, _e6);
    let rmo = _e20.xyz;
    let _e22 = standard_emission(_e6);
    let _e25 = material.roughness;
    let roughness_6 = saturate((_e25 * rmo.x));
    let _e31 = material.metallic;
    let metallic = saturate((_e31 * rmo.y));
    let _e38 = material.occlusion_strength;
    let ao = saturate(mix(1f, rmo.z, _e38));
    let _e44 = material.specular_strength;
    let specular_strength = max(_e44, 0f);
    let _e49 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    let v_3 = _e49.v;
    n = _e49.n;
    {
        let _e55 = textureSample(normal_map, material_sampler, _e6);
        let texel_2 = _e55.xyz;
        let _e57 = n;
        let _e61 = material.normal_strength;
        let _e62 = weft_mapped_normal(_e57, in_1.world_tangent, texel_2, _e61);
        n = _e62;
    }
    let _e63 = n;
    let _e64 = weft_main_light_geometry(_e63, v_3);
    let f0_2 = mix(vec3(0.04f), base, metallic);
    let diffuse_albedo = (base * (1f - metallic));
    {
        let _e77 = weft_v_smith_ggx_correlated(_e64.n_dot_v, _e64.n_dot_l, roughness_6);
        visibility = _e77;
        let _e79 = weft_env_brdf_lut(_e64.n_dot_v, roughness_6);
        let _e80 = weft_env_brdf_from_lut(f0_2, _e79);
        env_brdf = _e80;
        let _e83 = env_brdf;
        ambient_kd = max((vec3(1f) - _e83), vec3(0f));
        let _e88 = ambient_kd;
        direct_kd = _e88;
    }
    if (specular_strength > 0f) {
        let _e98 = weft_f_schlick(f0_2, _e64.v_dot_h);
        {
            let _e100 = n;
            let _e102 = weft_d_ggx_nh(_e100, _e64.h, roughness_6);
            d = _e102;
        }
        let _e103 = d;
        let _e104 = visibility;
        specular = (((_e103 * _e104) * _e98) * specular_strength);
        let _e109 = n;
        let _e111 = weft_prefiltered_radiance(reflect(-(v_3), _e109), roughness_6);
        let _e112 = env_brdf;
        indirect_specular = ((_e111 * _e112) * (ao * specular_strength));
    }
    let _e116 = direct_kd;
    let _e117 = weft_diffuse_lambert(diffuse_albedo);
    let diffuse = (_e116 * _e117);
    let _e119 = specular;
    let _e121 = weft_main_light_radiance();
    let direct = (((diffuse + _e119) * _e121) * _e64.n_dot_l);
    let _e125 = n;
    let _e126 = weft_sh_irradiance(_e125);
    let _e128 = ambient_kd;
    let indirect_diffuse = (((_e126 * ao) * _e128) * diffuse_albedo);
    let _e131 = indirect_specular;
    let color_1 = ((direct + _e131) + indirect_diffuse);
    let _e134 = n;
    let _e136 = standard_sphere_map(color_1, _e134, in_1.world_position);
    let radiance = clamp((_e136 + _e22), vec3(0f), vec3(65504f));
    standard_alpha_test(alpha_1);
    return vec4<f32>(radiance, alpha_1);
}
