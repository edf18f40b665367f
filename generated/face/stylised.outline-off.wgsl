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
    face_soft_shadow: f32,
    curvature_factor: f32,
    dark_bound: f32,
    bright_bound: f32,
    roughness: f32,
    specular: f32,
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

struct FaceLight {
    f_dot_l: f32,
    from_right: bool,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const skin_lut_shape: vec3<f32> = vec3<f32>(4f, 10f, 20f);
const skin_lut_ring: f32 = 3.1415927f;
const TIER_STYLISED: u32 = 0u;
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
@group(1) @binding(4) 
var face_sdf_map: texture_2d<f32>;
@group(1) @binding(5) 
var shadow_mask_map: texture_2d<f32>;
@group(1) @binding(6) 
var specular_mask: texture_2d<f32>;
@group(1) @binding(7) 
var skin_lut: texture_2d<f32>;

fn table_skin_lut(uv: vec2<f32>) -> vec4<f32> {
    let size = vec2<f32>(64f, 64f);
    let st_1 = (((clamp(uv, vec2(0f), vec2(1f)) * (size - vec2(1f))) + vec2(0.5f)) / size);
    let _e20 = textureSampleLevel(skin_lut, material_clamp_sampler, st_1, 0f);
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

fn weft_sh_irradiance(n: vec3<f32>) -> vec3<f32> {
    var e: vec3<f32>;

    let sh = weft_frame.sh;
    e = (sh[0].xyz * 0.282095f);
    let _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603f * n.y)));
    let _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603f * n.z)));
    let _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603f * n.x)));
    let _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548f * n.x) * n.y)));
    let _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548f * n.y) * n.z)));
    let _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392f * (((3f * n.z) * n.z) - 1f))));
    let _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548f * n.x) * n.z)));
    let _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274f * ((n.x * n.x) - (n.y * n.y)))));
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
    let uv_3 = vec2<f32>(saturate(n_dot_v), saturate(roughness_2));
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_3, 0f);
    return _e8.xy;
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_main_light_geometry(n_1: vec3<f32>, v_1: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_1), n_1);
    let _e6 = weft_clamp_cos(dot(n_1, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_1, _e2)), saturate(dot(n_1, _e4)), saturate(dot(v_1, _e4)));
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

fn skin_seed_specular(n_2: vec3<f32>, l: vec3<f32>, h: vec3<f32>, roughness_3: f32, mask: f32, lobe_weight: f32) -> f32 {
    let n_dot_h = saturate(dot(n_2, h));
    let l_dot_h = saturate(dot(l, h));
    let r2_ = (roughness_3 * roughness_3);
    let normalization = ((roughness_3 * 4f) + 2f);
    let d = (((n_dot_h * n_dot_h) * (r2_ - 1f)) + 1.00001f);
    let nl = saturate(dot(n_2, l));
    let s_ao = mix(0.100112915f, 1f, saturate((-0.3f + (nl * nl))));
    let denom = (((d * d) * max(0.1f, (l_dot_h * l_dot_h))) * normalization);
    let ggx = (r2_ / denom);
    let second = ((((2f * r2_) / denom) * lobe_weight) * mask);
    return ((((ggx / 2f) + second) * s_ao) / WEFT_PI);
}

fn face_light(l_1: vec3<f32>) -> FaceLight {
    var out_1: FaceLight;

    let model_1 = weft_object.model;
    let _e10 = weft_safe_normalize(model_1[2].xyz, vec3<f32>(0f, 0f, 1f));
    let _e17 = weft_safe_normalize(model_1[0].xyz, vec3<f32>(1f, 0f, 0f));
    let _e22 = weft_safe_normalize(vec3<f32>(l_1.x, 0f, l_1.z), _e10);
    out_1.f_dot_l = ((dot(_e10, _e22) * -0.5f) + 0.5f);
    out_1.from_right = (dot(_e17, _e22) >= 0f);
    let _e34 = out_1;
    return _e34;
}

fn face_sdf_shadow(uv_2: vec2<f32>, light: FaceLight, soft: f32) -> f32 {
    let _e5 = textureSample(face_sdf_map, material_sampler, uv_2);
    let sdf_l = _e5.x;
    let _e14 = textureSample(face_sdf_map, material_sampler, vec2<f32>((1f - uv_2.x), uv_2.y));
    let sdf_r = _e14.x;
    let sdf = select(sdf_l, sdf_r, light.from_right);
    let w = max(soft, 0.0001f);
    return smoothstep(-(w), w, (sdf - light.f_dot_l));
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var bias: f32;

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
    let _e36 = textureSample(shadow_mask_map, material_sampler, _e5);
    let shadow_mask = saturate(_e36.x);
    let _e41 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_2 = _e41.v;
    let n_3 = _e41.n;
    let _e44 = fwidth(n_3);
    let dn = length(_e44);
    let _e47 = fwidth(in_1.world_position);
    let dp = length(_e47);
    let estimated = select(0f, (dn / dp), (dp > 0.000000000001f));
    let _e56 = material.curvature_factor;
    let curvature = clamp((max(_e56, 0f) * estimated), 0.01f, 0.99f);
    let _e63 = weft_main_light_geometry(n_3, v_2);
    let _e65 = face_light(_e63.l);
    let _e68 = material.face_soft_shadow;
    let _e69 = face_sdf_shadow(_e5, _e65, _e68);
    bias = (_e69 * shadow_mask);
    let _e72 = bias;
    let _e75 = material.dark_bound;
    let _e78 = material.bright_bound;
    bias = clamp(_e72, _e75, _e78);
    let _e80 = bias;
    let _e82 = table_skin_lut(vec2<f32>(_e80, curvature));
    let falloff = max(_e82.xyz, vec3(0f));
    let _e92 = material.lobe_weight;
    let _e93 = skin_seed_specular(n_3, _e63.l, _e63.h, (roughness_4 * roughness_4), mask_1, _e92);
    let specular = ((_e93 * f0_1) * _e63.n_dot_l);
    let kd = vec3((1f - f0_1));
    let _e100 = weft_main_light_radiance();
    let _e101 = weft_diffuse_lambert(albedo_1);
    let direct = ((((kd * _e101) * falloff) + vec3(specular)) * _e100);
    let _e109 = weft_env_brdf_lut(_e63.n_dot_v, roughness_4);
    let _e110 = weft_env_brdf_from_lut(vec3(f0_1), _e109);
    let _e111 = weft_sh_irradiance(n_3);
    let indirect_diffuse = ((_e111 * kd) * albedo_1);
    let _e116 = weft_prefiltered_radiance(reflect(-(v_2), n_3), roughness_4);
    let indirect_specular = ((_e116 * _e110) * mask_1);
    let color = ((direct + indirect_diffuse) + indirect_specular);
    let radiance = clamp(color, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
