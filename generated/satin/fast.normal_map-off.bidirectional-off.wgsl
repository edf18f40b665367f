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
    noise_map_st: vec4<f32>,
    specular_intensity: f32,
    specular_color: vec4<f32>,
    second_specular_color: vec4<f32>,
    second_layer_width: f32,
    anisotropy: f32,
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

struct SatinLayers {
    narrow: vec2<f32>,
    wide: vec2<f32>,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const TIER_LOW: u32 = 3u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_MIN_ANISO_ALPHA: f32 = 0.001f;
const WEFT_MIN_ROUGHNESS_HALF: f32 = 0.089f;
const WEFT_MIN_N_DOT_HALF: f32 = 0.001f;
const WEFT_MIN_ALPHA_HALF: f32 = 0.007921f;

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
@group(1) @binding(5) 
var rmo_map: texture_2d<f32>;
@group(1) @binding(6) 
var noise_map: texture_2d<f32>;

fn weft_pow5_(x: f32) -> f32 {
    let x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

fn weft_max3_(v: vec3<f32>) -> f32 {
    return max(v.x, max(v.y, v.z));
}

fn weft_clamp_cos(c: f32) -> f32 {
    return clamp(c, WEFT_MIN_N_DOT, 1f);
}

fn weft_clamp_roughness(roughness: f32) -> f32 {
    return clamp(roughness, WEFT_MIN_ROUGHNESS, 1f);
}

fn weft_safe_normalize(v_1: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v_1, v_1);
    return select(fallback, (v_1 * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
}

fn weft_any_perpendicular(n_1: vec3<f32>) -> vec3<f32> {
    let s_1 = select(-1f, 1f, (n_1.z >= 0f));
    let a_1 = (-1f / (s_1 + n_1.z));
    let b = ((n_1.x * n_1.y) * a_1);
    return vec3<f32>((1f + (((s_1 * n_1.x) * n_1.x) * a_1)), (s_1 * b), (-(s_1) * n_1.x));
}

fn weft_f_schlick(f0_: vec3<f32>, v_dot_h: f32) -> vec3<f32> {
    let _e5 = weft_pow5_((1f - saturate(v_dot_h)));
    return (f0_ + ((vec3(1f) - f0_) * _e5));
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

fn weft_specular_mip(roughness_1: f32) -> f32 {
    let r = saturate(roughness_1);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r * (1.7f - (0.7f * r))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_2: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_2);
    let c_2 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_2.xyz, vec3(0f));
}

fn weft_env_brdf_lut(n_dot_v: f32, roughness_3: f32) -> vec2<f32> {
    let uv_1 = vec2<f32>(saturate(n_dot_v), saturate(roughness_3));
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv_1, 0f);
    return _e8.xy;
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_main_light_geometry(n_3: vec3<f32>, v_2: vec3<f32>) -> WeftLightGeometry {
    let _e2 = weft_main_light_direction();
    let _e4 = weft_safe_normalize((_e2 + v_2), n_3);
    let _e6 = weft_clamp_cos(dot(n_3, v_2));
    return WeftLightGeometry(_e2, _e4, _e6, saturate(dot(n_3, _e2)), saturate(dot(n_3, _e4)), saturate(dot(v_2, _e4)));
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

fn weft_tangent_frame(n_4: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_4 * dot(n_4, t_in)));
    let len2_1 = dot(t_proj, t_proj);
    let ok = (len2_1 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_4);
    let t = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_2 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_4, t) * s_2);
    return mat3x3<f32>(t, b_1, n_4);
}

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn weft_aniso_to_frame(frame: mat3x3<f32>, x_1: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(frame[0], x_1), dot(frame[1], x_1), dot(frame[2], x_1));
}

fn weft_aniso_alpha_kulla(roughness_4: f32, anisotropy: f32) -> vec2<f32> {
    let _e2 = weft_clamp_roughness(roughness_4);
    let a_2 = (_e2 * _e2);
    let k_1 = clamp(anisotropy, -1f, 1f);
    return max(vec2<f32>((a_2 * (1f + k_1)), (a_2 * (1f - k_1))), vec2(0.001f));
}

fn weft_aniso_ggx_q(t_dot_h: f32, b_dot_h: f32, n_dot_h: f32, alpha_t: f32, alpha_b: f32) -> f32 {
    let at = max(alpha_t, WEFT_MIN_ANISO_ALPHA);
    let ab = max(alpha_b, WEFT_MIN_ANISO_ALPHA);
    let x_2 = (t_dot_h / at);
    let y = (b_dot_h / ab);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 0.000001f);
}

fn weft_d_ggx_aniso(t_dot_h_1: f32, b_dot_h_1: f32, n_dot_h_1: f32, alpha_t_1: f32, alpha_b_1: f32) -> f32 {
    let at_1 = max(alpha_t_1, WEFT_MIN_ANISO_ALPHA);
    let ab_1 = max(alpha_b_1, WEFT_MIN_ANISO_ALPHA);
    let _e9 = weft_aniso_ggx_q(t_dot_h_1, b_dot_h_1, n_dot_h_1, at_1, ab_1);
    let d = (1f / ((((WEFT_PI * at_1) * ab_1) * _e9) * _e9));
    return select(0f, d, (n_dot_h_1 > 0f));
}

fn weft_v_smith_ggx_aniso_correlated(v_3: vec3<f32>, l: vec3<f32>, alpha_t_2: f32, alpha_b_2: f32) -> f32 {
    let _e5 = weft_clamp_cos(v_3.z);
    let _e7 = weft_clamp_cos(l.z);
    let lv = (_e7 * length(vec3<f32>((alpha_t_2 * v_3.x), (alpha_b_2 * v_3.y), _e5)));
    let ll = (_e5 * length(vec3<f32>((alpha_t_2 * l.x), (alpha_b_2 * l.y), _e7)));
    return (0.5f / (lv + ll));
}

fn weft_spec_ggx_aniso(v_4: vec3<f32>, l_1: vec3<f32>, alpha_t_3: f32, alpha_b_3: f32) -> f32 {
    let _e9 = weft_safe_normalize((v_4 + l_1), vec3<f32>(0f, 0f, 1f));
    let _e13 = weft_d_ggx_aniso(_e9.x, _e9.y, _e9.z, alpha_t_3, alpha_b_3);
    let _e14 = weft_v_smith_ggx_aniso_correlated(v_4, l_1, alpha_t_3, alpha_b_3);
    return ((_e13 * _e14) * saturate(l_1.z));
}

fn weft_aniso_bent_normal(frame_1: mat3x3<f32>, v_5: vec3<f32>, anisotropy_1: f32, roughness_5: f32) -> vec3<f32> {
    let k_2 = clamp(anisotropy_1, -1f, 1f);
    let n_5 = frame_1[2];
    let dir_1 = select(frame_1[0], frame_1[1], (k_2 >= 0f));
    let aniso_t = cross(dir_1, v_5);
    let aniso_n = cross(aniso_t, dir_1);
    let bend = (abs(k_2) * saturate((5f * saturate(roughness_5))));
    let _e22 = weft_safe_normalize(mix(n_5, aniso_n, bend), n_5);
    return _e22;
}

fn satin_lobe_reference(vf: vec3<f32>, lf: vec3<f32>, a: vec2<f32>) -> f32 {
    var s: f32;

    let _e5 = weft_spec_ggx_aniso(vf, lf, a.x, a.y);
    s = _e5;
    let _e7 = s;
    return _e7;
}

fn satin_env(frame_2: mat3x3<f32>, v_6: vec3<f32>, k: f32, roughness_6: f32) -> vec3<f32> {
    var bent_1: vec3<f32>;
    var c_1: vec3<f32>;

    let _e4 = weft_aniso_bent_normal(frame_2, v_6, k, roughness_6);
    bent_1 = _e4;
    let _e7 = bent_1;
    let _e9 = weft_prefiltered_radiance(reflect(-(v_6), _e7), roughness_6);
    c_1 = _e9;
    let _e11 = c_1;
    return _e11;
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var layers: SatinLayers;
    var specular: vec3<f32>;
    var diffuse_kd: vec3<f32>;
    var indirect_specular: vec3<f32>;
    var ambient_kd: vec3<f32>;
    var bent: vec3<f32>;

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
    let roughness_7 = saturate((_e23 * rmo.x));
    let _e29 = material.metallic;
    let metallic = saturate((_e29 * rmo.y));
    let _e36 = material.occlusion_strength;
    let ao = saturate(mix(1f, rmo.z, _e36));
    let _e42 = material.anisotropy;
    let anisotropy_2 = clamp(_e42, -1f, 1f);
    let _e48 = material.second_layer_width;
    let width = clamp(_e48, 1f, 4f);
    let roughness2_ = min((roughness_7 * width), 1f);
    let _e58 = material.noise_map_st;
    let _e59 = weft_transform_uv(in_1.uv0_, _e58);
    let _e62 = textureSample(noise_map, material_sampler, _e59);
    let noise = (0.5f + (0.5f * saturate(_e62.x)));
    let _e71 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_7 = _e71.v;
    n = _e71.n;
    let _e75 = n;
    let _e77 = weft_tangent_frame(_e75, in_1.world_tangent);
    let _e78 = n;
    let _e79 = weft_main_light_geometry(_e78, v_7);
    let _e80 = weft_main_light_radiance();
    let _e83 = weft_aniso_alpha_kulla(roughness_7, anisotropy_2);
    layers.narrow = _e83;
    let _e85 = weft_aniso_alpha_kulla(roughness2_, anisotropy_2);
    layers.wide = _e85;
    let f0_2 = mix(vec3(0.04f), base, metallic);
    let diffuse_albedo = (base * (1f - metallic));
    let _e94 = material.specular_color;
    let c1_ = saturate(_e94.xyz);
    let _e99 = material.second_specular_color;
    let c2_ = saturate(_e99.xyz);
    let _e103 = weft_f_schlick(f0_2, _e79.v_dot_h);
    {
        let _e108 = weft_max3_(c1_);
        let t1_ = mix(c1_, vec3(_e108), 0.5f);
        let _e112 = weft_max3_(c2_);
        let t2_ = mix(c2_, vec3(_e112), 0.5f);
        let _e117 = weft_max3_((t1_ + t2_));
        let norm = (1f / max(1f, _e117));
        let w1_ = (t1_ * norm);
        let w2_ = (t2_ * norm);
        let _e124 = weft_aniso_to_frame(_e77, v_7);
        let _e126 = weft_aniso_to_frame(_e77, _e79.l);
        let _e128 = layers.narrow;
        let _e129 = satin_lobe_reference(_e124, _e126, _e128);
        let _e131 = layers.wide;
        let _e132 = satin_lobe_reference(_e124, _e126, _e131);
        specular = (((((w1_ * _e129) + (w2_ * _e132)) * _e103) * noise) * _e80);
        let _e143 = weft_f_schlick(f0_2, _e79.n_dot_v);
        diffuse_kd = max((vec3(1f) - ((w1_ + w2_) * _e143)), vec3(0f));
        let _e150 = weft_env_brdf_lut(_e79.n_dot_v, roughness_7);
        let _e151 = weft_env_brdf_from_lut(f0_2, _e150);
        let e1_ = (_e151 * w1_);
        let _e154 = weft_env_brdf_lut(_e79.n_dot_v, roughness2_);
        let _e155 = weft_env_brdf_from_lut(f0_2, _e154);
        let e2_ = (_e155 * w2_);
        {
            let _e157 = weft_max3_(e1_);
            let _e158 = weft_max3_(e2_);
            let r_env = select(roughness2_, roughness_7, (_e157 >= _e158));
            let _e161 = satin_env(_e77, v_7, anisotropy_2, r_env);
            indirect_specular = ((_e161 * (e1_ + e2_)) * noise);
        }
        ambient_kd = max(((vec3(1f) - e1_) - e2_), vec3(0f));
    }
    let _e172 = diffuse_kd;
    let _e173 = weft_diffuse_lambert(diffuse_albedo);
    let _e178 = specular;
    let direct = ((((_e172 * _e173) * _e80) * _e79.n_dot_l) + _e178);
    let _e180 = indirect_specular;
    let _e182 = n;
    let _e183 = weft_sh_irradiance(_e182);
    let _e185 = ambient_kd;
    let indirect = ((_e180 * ao) + (((_e183 * ao) * _e185) * diffuse_albedo));
    let radiance = clamp((direct + indirect), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
