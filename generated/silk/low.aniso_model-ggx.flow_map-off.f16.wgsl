enable f16;

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
    smoothness: f32,
    metallic: f32,
    diffuse_uses_aniso_normal: u32,
    anisotropy: f32,
    aniso_normal_map_st: vec4<f32>,
    aniso_normal_strength: f32,
    tangent_shift: f32,
    aniso_gloss: f32,
    aniso_spec: f32,
    aniso_mask: f32,
    flow_strength: f32,
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

struct SilkLobe {
    value: f32,
    alpha: vec2<f32>,
    ibl_roughness: f32,
}

const WEFT_PI: f32 = 3.1415927f;
const WEFT_INV_PI: f32 = 0.31830987f;
const ANISO_MODEL_WARD: u32 = 0u;
const ANISO_MODEL_HAIR_SHIFTED: u32 = 1u;
const ANISO_MODEL_GGX: u32 = 2u;
const TIER_FAST: u32 = 0u;
const TIER_REFERENCE: u32 = 1u;
const TIER_SEED: u32 = 2u;
const TIER_LOW: u32 = 3u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_MIN_ANISO_ALPHA: f32 = 0.001f;
const SILK_MIN_ALPHA: f32 = 0.001f;
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
@group(1) @binding(4) 
var aniso_normal_map: texture_2d<f32>;

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

fn weft_specular_mip(roughness_1: f32) -> f32 {
    let r = saturate(roughness_1);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r * (1.7f - (0.7f * r))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_2: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_2);
    let c_1 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_1.xyz, vec3(0f));
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

fn weft_tangent_frame(n_3: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_3 * dot(n_3, t_in)));
    let len2_1 = dot(t_proj, t_proj);
    let ok = (len2_1 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_3);
    let t = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_3, t) * s_1);
    return mat3x3<f32>(t, b_1, n_3);
}

fn weft_unpack_normal(texel: vec3<f32>, strength: f32) -> vec3<f32> {
    let v_5 = ((texel * 2f) - vec3(1f));
    return vec3<f32>((v_5.xy * strength), max(v_5.z, 0.001f));
}

fn weft_normal_from_tangent_space(frame: mat3x3<f32>, n_ts: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_safe_normalize((frame * n_ts), frame[2]);
    return _e4;
}

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn weft_aniso_to_frame(frame_1: mat3x3<f32>, x: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(frame_1[0], x), dot(frame_1[1], x), dot(frame_1[2], x));
}

fn weft_aniso_alpha_burley(roughness_4: f32, anisotropy: f32) -> vec2<f32> {
    let _e2 = weft_clamp_roughness(roughness_4);
    let a_1 = (_e2 * _e2);
    let k = clamp(anisotropy, -1f, 1f);
    let aspect = sqrt((1f - (0.9f * abs(k))));
    let wide = (a_1 / aspect);
    let narrow = (a_1 * aspect);
    let ab = select(vec2<f32>(narrow, wide), vec2<f32>(wide, narrow), (k >= 0f));
    return max(ab, vec2(0.001f));
}

fn weft_aniso_bent_normal(frame_2: mat3x3<f32>, v_2: vec3<f32>, anisotropy_1: f32, roughness_5: f32) -> vec3<f32> {
    let k_1 = clamp(anisotropy_1, -1f, 1f);
    let n_4 = frame_2[2];
    let dir_1 = select(frame_2[0], frame_2[1], (k_1 >= 0f));
    let aniso_t = cross(dir_1, v_2);
    let aniso_n = cross(aniso_t, dir_1);
    let bend = (abs(k_1) * saturate((5f * saturate(roughness_5))));
    let _e22 = weft_safe_normalize(mix(n_4, aniso_n, bend), n_4);
    return _e22;
}

fn silk_lobe_anisotropy(alpha: vec2<f32>) -> f32 {
    let at = max(alpha.x, SILK_MIN_ALPHA);
    let ab_1 = max(alpha.y, SILK_MIN_ALPHA);
    return ((at - ab_1) / (at + ab_1));
}

fn weft_half_min_max(x_1: f16) -> f16 {
    return min(x_1, 65504h);
}

fn weft_half_pow5_(x_2: f16) -> f16 {
    let x2_ = (x_2 * x_2);
    return ((x2_ * x2_) * x_2);
}

fn weft_half_f_schlick(f0_: vec3<f16>, v_dot_h: f16) -> vec3<f16> {
    let _e7 = weft_half_pow5_((1h - v_dot_h));
    return (f0_ + ((vec3(1h) - f0_) * _e7));
}

fn weft_half_spec_ggx_aniso(v_3: vec3<f16>, l: vec3<f16>, h: vec3<f16>, alpha_1: vec2<f32>) -> f16 {
    let a_2 = max(alpha_1, vec2(0.007921f));
    let inv_a = vec2<f16>((vec2(1f) / a_2));
    let ah = vec2<f16>(a_2);
    let x_3 = (h.x * inv_a.x);
    let y = (h.y * inv_a.y);
    let q = max((((x_3 * x_3) + (y * y)) + (h.z * h.z)), 0.010002136h);
    let d = ((((inv_a.x * inv_a.y) / q) / q) * 0.31835938h);
    let nv = max(v_3.z, 0.0010004044h);
    let nl = saturate(l.z);
    let lv = (nl * length(vec3<f16>((ah.x * v_3.x), (ah.y * v_3.y), nv)));
    let ll = (nv * length(vec3<f16>((ah.x * l.x), (ah.y * l.y), nl)));
    let v_n_dot_l = ((0.5h * nl) / max((lv + ll), 0.000100016594h));
    let _e65 = weft_half_min_max((d * v_n_dot_l));
    return select(0h, _e65, (h.z > 0h));
}

fn silk_low(frame_3: mat3x3<f32>, n_spec: vec3<f32>, n_diff: vec3<f32>, v_4: vec3<f32>, n_dot_v_1: f32, v_dot_h_1: f32, n_dot_l_diffuse: f32, f0_in: vec3<f32>, diffuse_albedo: vec3<f32>, lobe_1: SilkLobe, light: vec3<f32>) -> vec3<f32> {
    let f0_1 = vec3<f16>(f0_in);
    let _e13 = weft_half_f_schlick(f0_1, f16(v_dot_h_1));
    let kd = ((vec3(1h) - _e13) * (f16(n_dot_l_diffuse) * 0.31835938h));
    let direct = (((diffuse_albedo * vec3<f32>(kd)) + (vec3<f32>(_e13) * lobe_1.value)) * light);
    let _e29 = weft_env_brdf_lut(n_dot_v_1, lobe_1.ibl_roughness);
    let lut = saturate(_e29);
    let env_brdf_1 = ((f0_1 * f16(lut.x)) + vec3(f16(lut.y)));
    let ambient_kd_1 = max((vec3(1h) - env_brdf_1), vec3(0h));
    let _e45 = silk_lobe_anisotropy(lobe_1.alpha);
    let _e47 = weft_aniso_bent_normal(frame_3, v_4, _e45, lobe_1.ibl_roughness);
    let _e51 = weft_prefiltered_radiance(reflect(-(v_4), _e47), lobe_1.ibl_roughness);
    let _e54 = weft_sh_irradiance(n_diff);
    let indirect = ((_e51 * vec3<f32>(env_brdf_1)) + ((_e54 * vec3<f32>(ambient_kd_1)) * diffuse_albedo));
    return clamp((direct + indirect), vec3(0f), vec3(65504f));
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var fibre: vec3<f32>;
    var lobe: SilkLobe;
    var vis: f32;
    var env_brdf: vec3<f32>;
    var ambient_kd: vec3<f32>;
    var reflect_n: vec3<f32>;

    let _e4 = material.base_map_st;
    let _e5 = weft_transform_uv(in_1.uv0_, _e4);
    let _e8 = material.base_color;
    let _e11 = textureSample(base_map, material_sampler, _e5);
    let base_rgba = (_e8 * _e11);
    let base = saturate(base_rgba.xyz);
    let alpha_out = saturate(base_rgba.w);
    let _e19 = material.smoothness;
    let smoothness = saturate(_e19);
    let roughness_6 = (1f - smoothness);
    let _e25 = material.metallic;
    let metallic = saturate(_e25);
    let f0_2 = mix(vec3(0.04f), base, metallic);
    let diffuse_albedo_1 = (base * (1f - metallic));
    let _e35 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_6 = _e35.v;
    let n_geo = _e35.n;
    let _e39 = weft_tangent_frame(n_geo, in_1.world_tangent);
    let _e43 = material.aniso_normal_map_st;
    let _e44 = weft_transform_uv(in_1.uv0_, _e43);
    let _e47 = textureSample(aniso_normal_map, material_sampler, _e44);
    let texel_1 = _e47.xyz;
    let _e51 = material.aniso_normal_strength;
    let _e52 = weft_unpack_normal(texel_1, _e51);
    let _e53 = weft_normal_from_tangent_space(_e39, _e52);
    fibre = _e39[0];
    let _e56 = fibre;
    let _e60 = weft_tangent_frame(_e53, vec4<f32>(_e56, in_1.world_tangent.w));
    let _e63 = material.diffuse_uses_aniso_normal;
    let n_diff_1 = select(n_geo, _e53, (_e63 != 0u));
    let _e67 = weft_main_light_geometry(_e53, v_6);
    let _e68 = weft_aniso_to_frame(_e60, v_6);
    let _e70 = weft_aniso_to_frame(_e60, _e67.l);
    let _e72 = weft_aniso_to_frame(_e60, _e67.h);
    let k_2 = material.anisotropy;
    {
        {
            let _e77 = weft_aniso_alpha_burley(roughness_6, k_2);
            lobe.alpha = _e77;
            lobe.ibl_roughness = roughness_6;
            {
                let _e82 = weft_aniso_alpha_burley(max(roughness_6, WEFT_MIN_ROUGHNESS_HALF), k_2);
                let _e87 = weft_half_spec_ggx_aniso(vec3<f16>(_e68), vec3<f16>(_e70), vec3<f16>(_e72), _e82);
                lobe.value = f32(_e87);
            }
        }
    }
    let _e89 = weft_main_light_radiance();
    let n_dot_l_diffuse_1 = saturate(dot(n_diff_1, _e67.l));
    {
        let _e95 = lobe;
        let _e96 = silk_low(_e60, _e53, n_diff_1, v_6, _e67.n_dot_v, _e67.v_dot_h, n_dot_l_diffuse_1, f0_2, diffuse_albedo_1, _e95, _e89);
        return vec4<f32>(_e96, alpha_out);
    }
}
