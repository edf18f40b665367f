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
    normal_strength: f32,
    roughness: f32,
    specular: f32,
    curvature_factor: f32,
    dark_bound: f32,
    bright_bound: f32,
    lobe_weight: f32,
    outline_color: vec4<f32>,
    outline_width: f32,
    outline_max_distance: f32,
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
const skin_lut_shape: vec3<f32> = vec3<f32>(4f, 10f, 20f);
const skin_lut_ring: f32 = 3.1415927f;
const seed_lut_shape: vec3<f32> = vec3<f32>(4f, 10f, 20f);
const seed_lut_ring: f32 = 1.5707964f;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;

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
var curvature_map: texture_2d<f32>;
@group(1) @binding(6) 
var specular_mask: texture_2d<f32>;
@group(1) @binding(8) 
var seed_lut: texture_2d<f32>;

fn table_seed_lut(uv: vec2<f32>) -> vec4<f32> {
    let size = vec2<f32>(64f, 64f);
    let st_1 = (((clamp(uv, vec2(0f), vec2(1f)) * (size - vec2(1f))) + vec2(0.5f)) / size);
    let _e20 = textureSampleLevel(seed_lut, material_clamp_sampler, st_1, 0f);
    return _e20;
}

fn weft_clamp_cos(c: f32) -> f32 {
    return clamp(c, WEFT_MIN_N_DOT, 1f);
}

fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v, v);
    return select(fallback, (v * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_diffuse_lambert(albedo: vec3<f32>) -> vec3<f32> {
    return (albedo * WEFT_INV_PI);
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

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
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

fn weft_transform_uv(uv_1: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv_1 * st.xy) + st.zw);
}

fn skin_seed_specular(n_3: vec3<f32>, l: vec3<f32>, h: vec3<f32>, roughness_3: f32, mask: f32, lobe_weight: f32) -> f32 {
    let n_dot_h = saturate(dot(n_3, h));
    let l_dot_h = saturate(dot(l, h));
    let r2_ = (roughness_3 * roughness_3);
    let normalization = ((roughness_3 * 4f) + 2f);
    let d = (((n_dot_h * n_dot_h) * (r2_ - 1f)) + 1.00001f);
    let nl = saturate(dot(n_3, l));
    let s_ao = mix(0.100112915f, 1f, saturate((-0.3f + (nl * nl))));
    let denom = (((d * d) * max(0.1f, (l_dot_h * l_dot_h))) * normalization);
    let ggx = (r2_ / denom);
    let second = ((((2f * r2_) / denom) * lobe_weight) * mask);
    return ((((ggx / 2f) + second) * s_ao) / WEFT_PI);
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var curvature: f32;
    var n: vec3<f32>;
    var falloff: vec3<f32>;
    var specular: f32;
    var kd: vec3<f32>;

    let _e4 = material.base_map_st;
    let _e5 = weft_transform_uv(in_1.uv0_, _e4);
    let _e8 = material.base_color;
    let _e11 = textureSample(base_map, material_sampler, _e5);
    let base_rgba = (_e8 * _e11);
    let albedo_1 = saturate(base_rgba.xyz);
    let alpha = saturate(base_rgba.w);
    let _e19 = material.roughness;
    let roughness_4 = clamp(_e19, 0.05f, 1f);
    let _e25 = material.specular;
    let f0_1 = clamp(_e25, 0f, 1f);
    let _e31 = textureSample(specular_mask, material_sampler, _e5);
    let mask_1 = saturate(_e31.x);
    let _e36 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_2 = _e36.v;
    let n_geom = _e36.n;
    let _e39 = fwidth(n_geom);
    let dn = length(_e39);
    let _e42 = fwidth(in_1.world_position);
    let dp = length(_e42);
    let estimated = select(0f, (dn / dp), (dp > 0.000000000001f));
    let _e51 = textureSample(curvature_map, material_sampler, _e5);
    let mapped = _e51.x;
    let _e55 = material.curvature_factor;
    let factor = max(_e55, 0f);
    curvature = saturate((factor * estimated));
    {
        curvature = saturate((factor * mapped));
    }
    n = n_geom;
    let _e64 = n;
    let _e65 = weft_main_light_geometry(_e64, v_2);
    let _e66 = n;
    let _e75 = material.dark_bound;
    let _e78 = material.bright_bound;
    let u = clamp(((dot(_e66, _e65.l) * 0.5f) + 0.5f), _e75, _e78);
    {
        {
            let _e81 = curvature;
            let _e83 = table_seed_lut(vec2<f32>(u, _e81));
            falloff = _e83.xyz;
        }
    }
    let _e85 = falloff;
    falloff = max(_e85, vec3(0f));
    let _e91 = weft_env_brdf_lut(_e65.n_dot_v, roughness_4);
    let _e92 = weft_env_brdf_from_lut(vec3(f0_1), _e91);
    {
        let linear_roughness = (roughness_4 * roughness_4);
        let _e96 = n;
        let _e101 = material.lobe_weight;
        let _e102 = skin_seed_specular(_e96, _e65.l, _e65.h, linear_roughness, mask_1, _e101);
        specular = ((_e102 * f0_1) * _e65.n_dot_l);
        kd = vec3((1f - f0_1));
    }
    let _e109 = weft_main_light_radiance();
    let _e110 = kd;
    let _e111 = weft_diffuse_lambert(albedo_1);
    let _e113 = falloff;
    let _e115 = specular;
    let direct = ((((_e110 * _e111) * _e113) + vec3(_e115)) * _e109);
    let _e119 = n;
    let _e120 = weft_sh_irradiance(_e119);
    let _e121 = kd;
    let indirect_diffuse = ((_e120 * _e121) * albedo_1);
    let _e125 = n;
    let _e127 = weft_prefiltered_radiance(reflect(-(v_2), _e125), roughness_4);
    let indirect_specular = ((_e127 * _e92) * mask_1);
    let color = ((direct + indirect_diffuse) + indirect_specular);
    let radiance = clamp(color, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
