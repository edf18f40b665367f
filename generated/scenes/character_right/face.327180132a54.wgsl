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
@group(1) @binding(1) 
var material_sampler: sampler;
@group(1) @binding(2) 
var material_clamp_sampler: sampler;
@group(1) @binding(4) 
var face_sdf_map: texture_2d<f32>;
@group(1) @binding(5) 
var shadow_mask_map: texture_2d<f32>;
@group(1) @binding(7) 
var skin_lut: texture_2d<f32>;

fn table_skin_lut(uv: vec2<f32>) -> vec4<f32> {
    let st = (((clamp(uv, vec2(0f), vec2(1f)) * vec2<f32>(63f, 63f)) + vec2(0.5f)) / vec2<f32>(64f, 64f));
    let _e13 = textureSampleLevel(skin_lut, material_clamp_sampler, st, 0f);
    return _e13;
}

fn weft_clamp_cos(c: f32) -> f32 {
    return clamp(c, WEFT_MIN_N_DOT, 1f);
}

fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v, v);
    return select(fallback, (v * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
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

fn weft_main_light_geometry(n_1: vec3<f32>, v_2: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_2), n_1);
    let _e6 = weft_clamp_cos(dot(n_1, v_2));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_1, _e2)), saturate(dot(n_1, _e4)), saturate(dot(v_2, _e4)));
}

fn weft_safe_normalize_k3_(v_3: vec3<f32>) -> vec3<f32> {
    let len2_2 = dot(v_3, v_3);
    return select(vec3(0f), (v_3 * inverseSqrt(max(len2_2, 0.00000000000000000001f))), (len2_2 > 0.00000000000000000001f));
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
    let _e53 = weft_safe_normalize_k3_((normal3_ * in_3.normal));
    out_1.world_normal = _e53;
    let _e58 = weft_safe_normalize_k3_((model3_ * in_3.tangent.xyz));
    out_1.world_tangent = vec4<f32>(_e58, bitangent_sign);
    out_1.uv0_ = in_3.uv0_;
    let _e62 = out_1;
    return _e62;
}

fn weft_safe_normalize_k4_(v_4: vec3<f32>) -> vec3<f32> {
    let len2_3 = dot(v_4, v_4);
    return select(vec3<f32>(1f, 0f, 0f), (v_4 * inverseSqrt(max(len2_3, 0.00000000000000000001f))), (len2_3 > 0.00000000000000000001f));
}

fn face_light(l: vec3<f32>) -> FaceLight {
    var out_2: FaceLight;

    let model_1 = weft_object.model;
    let _e6 = weft_safe_normalize_k1_(model_1[2].xyz);
    let _e9 = weft_safe_normalize_k4_(model_1[0].xyz);
    let _e14 = weft_safe_normalize(vec3<f32>(l.x, 0f, l.z), _e6);
    out_2.f_dot_l = ((dot(_e6, _e14) * -0.5f) + 0.5f);
    out_2.from_right = (dot(_e9, _e14) >= 0f);
    let _e26 = out_2;
    return _e26;
}

fn weft_transform_uv_k5_(uv_1: vec2<f32>) -> vec2<f32> {
    return (uv_1 + vec2<f32>(0f, 0f));
}

fn face_sdf_shadow_k6_(uv_2: vec2<f32>, light: FaceLight) -> f32 {
    let _e5 = textureSample(face_sdf_map, material_sampler, uv_2);
    let sdf_l = _e5.x;
    let _e14 = textureSample(face_sdf_map, material_sampler, vec2<f32>((1f - uv_2.x), uv_2.y));
    let sdf_r = _e14.x;
    let sdf = select(sdf_l, sdf_r, light.from_right);
    return smoothstep(-0.05f, 0.05f, (sdf - light.f_dot_l));
}

fn skin_seed_specular_k7_(n_2: vec3<f32>, l_1: vec3<f32>, h: vec3<f32>) -> f32 {
    let n_dot_h = saturate(dot(n_2, h));
    let l_dot_h = saturate(dot(l_1, h));
    let d = (((n_dot_h * n_dot_h) * -0.8704f) + 1.00001f);
    let nl = saturate(dot(n_2, l_1));
    let s_ao = mix(0.100112915f, 1f, saturate((-0.3f + (nl * nl))));
    let denom = (((d * d) * max(0.1f, (l_dot_h * l_dot_h))) * 3.44f);
    let ggx = (0.1296f / denom);
    let second = ((0.2592f / denom) * 0.15f);
    return ((((ggx / 2f) + second) * s_ao) / WEFT_PI);
}

fn weft_env_brdf_lut_k9_(n_dot_v: f32) -> vec2<f32> {
    let uv_3 = vec2<f32>(saturate(n_dot_v), 0.6f);
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_3, 0f);
    return _e8.xy;
}

fn weft_env_brdf_from_lut_k10_(scale_bias: vec2<f32>) -> vec3<f32> {
    let sb = saturate(scale_bias);
    return ((vec3(0.028f) * sb.x) + vec3(sb.y));
}

fn weft_specular_mip_k12_() -> f32 {
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return (0.768f * max_mip);
}

fn weft_prefiltered_radiance_k11_(dir: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_specular_mip_k12_();
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
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
fn vs_main(in_1: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in_1);
    return _e1;
}

@fragment 
fn fs_main(in_2: WeftVaryings) -> @location(0) vec4<f32> {
    var bias: f32;

    let _e2 = weft_transform_uv_k5_(in_2.uv0_);
    let _e11 = textureSample(shadow_mask_map, material_sampler, _e2);
    let shadow_mask = saturate(_e11.x);
    let _e16 = weft_surface(in_2.world_position, in_2.world_normal);
    let v_5 = _e16.v;
    let n_3 = _e16.n;
    let _e19 = fwidth(n_3);
    let dn = length(_e19);
    let _e22 = fwidth(in_2.world_position);
    let dp = length(_e22);
    let estimated = select(0f, (dn / dp), (dp > 0.000000000001f));
    let curvature = clamp((0.6f * estimated), 0.01f, 0.99f);
    let _e34 = weft_main_light_geometry(n_3, v_5);
    let _e36 = face_light(_e34.l);
    let _e37 = face_sdf_shadow_k6_(_e2, _e36);
    bias = (_e37 * shadow_mask);
    let _e40 = bias;
    bias = clamp(_e40, 0f, 1f);
    let _e44 = bias;
    let _e46 = table_skin_lut(vec2<f32>(_e44, curvature));
    let falloff = max(_e46.xyz, vec3(0f));
    let _e52 = skin_seed_specular_k7_(n_3, _e34.l, _e34.h);
    let specular = ((_e52 * 0.028f) * _e34.n_dot_l);
    let _e57 = weft_main_light_radiance();
    let direct = (((vec3<f32>(0.2560481f, 0.15688866f, 0.1216312f) * falloff) + vec3(specular)) * _e57);
    let _e64 = weft_env_brdf_lut_k9_(_e34.n_dot_v);
    let _e65 = weft_env_brdf_from_lut_k10_(_e64);
    let _e66 = weft_sh_irradiance(n_3);
    let indirect_diffuse = ((_e66 * vec3(0.972f)) * vec3<f32>(0.82757086f, 0.5070785f, 0.39312312f));
    let _e71 = weft_prefiltered_radiance_k11_(reflect(-(v_5), n_3));
    let indirect_specular = (_e71 * _e65);
    let color = ((direct + indirect_diffuse) + indirect_specular);
    let radiance = clamp(color, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
