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
    metallic: f32,
    smoothness: f32,
    base_map_st: vec4<f32>,
    normal_strength: f32,
    occlusion_strength: f32,
    flake_color: vec4<f32>,
    flake_intensity: f32,
    flake_density: f32,
    flake_size: f32,
    flake_roughness: f32,
    twinkle: f32,
    density_variation: f32,
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
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SMOOTH: u32 = 2u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const GLINT_TAU: f32 = 6.2831855f;
const GLINT_HALF_PI: f32 = 1.5707964f;
const GLINT_TABLE_SIZE: f32 = 64f;
const GLINT_MIN_LOD: f32 = -20f;
const GLINT_MAX_LOD: f32 = 20f;
const GLINT_MAX_RATIO: f32 = 16f;
const GLINT_TET_A_UP: u32 = 36292u;
const GLINT_TET_A_DOWN: u32 = 36165u;
const GLINT_TET_A_LOW: u32 = 34112u;
const GLINT_TET_B_UP: u32 = 23168u;
const GLINT_TET_B_DOWN: u32 = 42242u;
const GLINT_TET_B_HIGH: u32 = 44421u;
const GLINT_TET_C_UP: u32 = 44517u;
const GLINT_TET_C_DOWN: u32 = 58790u;
const GLINT_TET_C_LOW: u32 = 42338u;
const GLINT_TET_CENTER_UP: u32 = 60596u;
const GLINT_TET_CENTER_DOWN: u32 = 18110u;
const GLINT_TET_CENTER_LOW: u32 = 46659u;

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
var base_map: texture_2d<f32>;
@group(1) @binding(4) 
var normal_map: texture_2d<f32>;
@group(1) @binding(5) 
var occlusion_map: texture_2d<f32>;

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

fn weft_d_ggx(n_dot_h: f32, roughness_1: f32) -> f32 {
    let _e2 = weft_clamp_roughness(roughness_1);
    let a_1 = (_e2 * _e2);
    let a2_ = (a_1 * a_1);
    let noh = saturate(n_dot_h);
    let one_minus_noh2_ = ((1f - noh) * (1f + noh));
    let d = (one_minus_noh2_ + ((noh * noh) * a2_));
    return (a2_ / ((WEFT_PI * d) * d));
}

fn weft_d_ggx_nh(n_2: vec3<f32>, h: vec3<f32>, roughness_2: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_2);
    let a_2 = (_e3 * _e3);
    let a2_1 = (a_2 * a_2);
    let noh_1 = saturate(dot(n_2, h));
    let nxh = cross(n_2, h);
    let d_1 = (dot(nxh, nxh) + ((noh_1 * noh_1) * a2_1));
    return (a2_1 / (WEFT_PI * max((d_1 * d_1), 0.000000000000000000000000000001f)));
}

fn weft_f_schlick(f0_: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (f0_ + ((vec3(1f) - f0_) * _e5));
}

fn weft_v_smith_ggx_correlated(n_dot_v: f32, n_dot_l: f32, roughness_3: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_3);
    let a_3 = (_e3 * _e3);
    let a2_2 = (a_3 * a_3);
    let _e6 = weft_clamp_cos(n_dot_v);
    let _e7 = weft_clamp_cos(n_dot_l);
    let lv = (_e7 * sqrt((((_e6 * _e6) * (1f - a2_2)) + a2_2)));
    let ll = (_e6 * sqrt((((_e7 * _e7) * (1f - a2_2)) + a2_2)));
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

fn weft_specular_mip(roughness_4: f32) -> f32 {
    let r = saturate(roughness_4);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r * (1.7f - (0.7f * r))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_5: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_5);
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
}

fn weft_env_brdf_lut(n_dot_v_1: f32, roughness_6: f32) -> vec2<f32> {
    let uv_1 = vec2<f32>(saturate(n_dot_v_1), saturate(roughness_6));
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_1, 0f);
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

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var color: vec3<f32>;
    var local: bool;
    var d_flakes: f32;

    let _e4 = material.base_map_st;
    let _e5 = weft_transform_uv(in_1.uv0_, _e4);
    let duv_dx = dpdx(_e5);
    let duv_dy = dpdy(_e5);
    let _e10 = material.base_color;
    let _e13 = textureSample(base_map, material_sampler, _e5);
    let base_rgba = (_e10 * _e13);
    let base = saturate(base_rgba.xyz);
    let alpha = saturate(base_rgba.w);
    let _e21 = material.metallic;
    let metallic = saturate(_e21);
    let _e25 = material.smoothness;
    let roughness_7 = (1f - saturate(_e25));
    let _e31 = textureSample(occlusion_map, material_sampler, _e5);
    let occlusion = _e31.x;
    let _e35 = material.occlusion_strength;
    let ao = saturate(mix(1f, occlusion, _e35));
    let _e41 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_3 = _e41.v;
    n = _e41.n;
    {
        let _e47 = textureSample(normal_map, material_sampler, _e5);
        let texel_2 = _e47.xyz;
        let _e49 = n;
        let _e53 = material.normal_strength;
        let _e54 = weft_mapped_normal(_e49, in_1.world_tangent, texel_2, _e53);
        n = _e54;
    }
    let _e55 = n;
    let _e57 = weft_tangent_frame(_e55, in_1.world_tangent);
    let _e58 = n;
    let _e59 = weft_main_light_geometry(_e58, v_3);
    let _e60 = weft_main_light_radiance();
    let f0_2 = mix(vec3(0.04f), base, metallic);
    let diffuse_albedo = (base * (1f - metallic));
    let _e69 = weft_v_smith_ggx_correlated(_e59.n_dot_v, _e59.n_dot_l, roughness_7);
    let _e71 = weft_env_brdf_lut(_e59.n_dot_v, roughness_7);
    let _e72 = weft_env_brdf_from_lut(f0_2, _e71);
    let kd = max((vec3(1f) - _e72), vec3(0f));
    let _e79 = n;
    let _e81 = weft_d_ggx_nh(_e79, _e59.h, roughness_7);
    let _e84 = weft_f_schlick(f0_2, _e59.v_dot_h);
    let specular = ((_e81 * _e69) * _e84);
    let _e86 = weft_diffuse_lambert(diffuse_albedo);
    let direct = ((((kd * _e86) + specular) * _e60) * _e59.n_dot_l);
    let _e93 = n;
    let _e95 = weft_prefiltered_radiance(reflect(-(v_3), _e93), roughness_7);
    let _e98 = n;
    let _e99 = weft_sh_irradiance(_e98);
    let indirect = (((_e95 * _e72) * ao) + (((_e99 * ao) * kd) * diffuse_albedo));
    color = (direct + indirect);
    let _e108 = material.flake_intensity;
    let intensity = max(_e108, 0f);
    if (intensity > 0f) {
        local = (_e59.n_dot_l > 0f);
    } else {
        local = false;
    }
    let _e119 = local;
    if _e119 {
        let _e122 = material.flake_roughness;
        let r_f = clamp(_e122, 0.05f, 1f);
        let _e126 = n;
        let _e128 = weft_d_ggx_nh(_e126, _e59.h, r_f);
        let _e130 = weft_d_ggx(1f, r_f);
        let _e133 = material.flake_color;
        let flake_f0_ = saturate(_e133.xyz);
        let _e138 = weft_v_smith_ggx_correlated(_e59.n_dot_v, _e59.n_dot_l, r_f);
        {
            {
                d_flakes = _e128;
            }
            let _e140 = color;
            let _e141 = d_flakes;
            let _e145 = weft_f_schlick(flake_f0_, _e59.v_dot_h);
            color = (_e140 + (((((intensity * _e141) * _e138) * _e145) * _e60) * _e59.n_dot_l));
        }
    }
    let _e151 = color;
    let radiance = clamp(_e151, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
