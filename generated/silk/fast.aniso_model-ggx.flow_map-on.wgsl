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
@group(1) @binding(5) 
var flow_map: texture_2d<f32>;

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

fn weft_any_perpendicular(n: vec3<f32>) -> vec3<f32> {
    let s = select(-1f, 1f, (n.z >= 0f));
    let a = (-1f / (s + n.z));
    let b = ((n.x * n.y) * a);
    return vec3<f32>((1f + (((s * n.x) * n.x) * a)), (s * b), (-(s) * n.x));
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
    let v_4 = ((texel * 2f) - vec3(1f));
    return vec3<f32>((v_4.xy * strength), max(v_4.z, 0.001f));
}

fn weft_normal_from_tangent_space(frame: mat3x3<f32>, n_ts: vec3<f32>) -> vec3<f32> {
    let _e4 = weft_safe_normalize((frame * n_ts), frame[2]);
    return _e4;
}

fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return ((uv * st.xy) + st.zw);
}

fn weft_aniso_to_frame(frame_1: mat3x3<f32>, x_1: vec3<f32>) -> vec3<f32> {
    return vec3<f32>(dot(frame_1[0], x_1), dot(frame_1[1], x_1), dot(frame_1[2], x_1));
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

fn weft_aniso_ggx_q(t_dot_h: f32, b_dot_h: f32, n_dot_h: f32, alpha_t: f32, alpha_b: f32) -> f32 {
    let at = max(alpha_t, WEFT_MIN_ANISO_ALPHA);
    let ab_1 = max(alpha_b, WEFT_MIN_ANISO_ALPHA);
    let x_2 = (t_dot_h / at);
    let y = (b_dot_h / ab_1);
    return max((((x_2 * x_2) + (y * y)) + (n_dot_h * n_dot_h)), 0.000001f);
}

fn weft_d_ggx_aniso(t_dot_h_1: f32, b_dot_h_1: f32, n_dot_h_1: f32, alpha_t_1: f32, alpha_b_1: f32) -> f32 {
    let at_1 = max(alpha_t_1, WEFT_MIN_ANISO_ALPHA);
    let ab_2 = max(alpha_b_1, WEFT_MIN_ANISO_ALPHA);
    let _e9 = weft_aniso_ggx_q(t_dot_h_1, b_dot_h_1, n_dot_h_1, at_1, ab_2);
    let d = (1f / ((((WEFT_PI * at_1) * ab_2) * _e9) * _e9));
    return select(0f, d, (n_dot_h_1 > 0f));
}

fn weft_v_smith_ggx_aniso_correlated(v_2: vec3<f32>, l: vec3<f32>, alpha_t_2: f32, alpha_b_2: f32) -> f32 {
    let _e5 = weft_clamp_cos(v_2.z);
    let _e7 = weft_clamp_cos(l.z);
    let lv = (_e7 * length(vec3<f32>((alpha_t_2 * v_2.x), (alpha_b_2 * v_2.y), _e5)));
    let ll = (_e5 * length(vec3<f32>((alpha_t_2 * l.x), (alpha_b_2 * l.y), _e7)));
    return (0.5f / (lv + ll));
}

fn weft_aniso_bent_normal(frame_2: mat3x3<f32>, v_3: vec3<f32>, anisotropy_1: f32, roughness_5: f32) -> vec3<f32> {
    let k_1 = clamp(anisotropy_1, -1f, 1f);
    let n_4 = frame_2[2];
    let dir_1 = select(frame_2[0], frame_2[1], (k_1 >= 0f));
    let aniso_t = cross(dir_1, v_3);
    let aniso_n = cross(aniso_t, dir_1);
    let bend = (abs(k_1) * saturate((5f * saturate(roughness_5))));
    let _e22 = weft_safe_normalize(mix(n_4, aniso_n, bend), n_4);
    return _e22;
}

fn silk_lobe_anisotropy(alpha: vec2<f32>) -> f32 {
    let at_2 = max(alpha.x, SILK_MIN_ALPHA);
    let ab_3 = max(alpha.y, SILK_MIN_ALPHA);
    return ((at_2 - ab_3) / (at_2 + ab_3));
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
    let diffuse_albedo = (base * (1f - metallic));
    let _e35 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_5 = _e35.v;
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
    {
        let _e58 = textureSample(flow_map, material_sampler, _e5);
        let flow = ((_e58.xy * 2f) - vec2(1f));
        let dir_2 = ((_e39[0] * flow.x) + (_e39[1] * flow.y));
        let _e75 = material.flow_strength;
        let _e79 = weft_safe_normalize(mix(_e39[0], dir_2, saturate(_e75)), _e39[0]);
        fibre = _e79;
    }
    let _e80 = fibre;
    let _e84 = weft_tangent_frame(_e53, vec4<f32>(_e80, in_1.world_tangent.w));
    let _e87 = material.diffuse_uses_aniso_normal;
    let n_diff = select(n_geo, _e53, (_e87 != 0u));
    let _e91 = weft_main_light_geometry(_e53, v_5);
    let _e92 = weft_aniso_to_frame(_e84, v_5);
    let _e94 = weft_aniso_to_frame(_e84, _e91.l);
    let _e96 = weft_aniso_to_frame(_e84, _e91.h);
    let k_2 = material.anisotropy;
    {
        {
            let _e101 = weft_aniso_alpha_burley(roughness_6, k_2);
            lobe.alpha = _e101;
            lobe.ibl_roughness = roughness_6;
            {
                {
                    let _e107 = weft_v_smith_ggx_aniso_correlated(_e92, _e94, _e101.x, _e101.y);
                    vis = _e107;
                }
                let _e114 = weft_d_ggx_aniso(_e96.x, _e96.y, _e96.z, _e101.x, _e101.y);
                let _e115 = vis;
                lobe.value = ((_e114 * _e115) * _e91.n_dot_l);
            }
        }
    }
    let _e119 = weft_main_light_radiance();
    let n_dot_l_diffuse = saturate(dot(n_diff, _e91.l));
    let _e124 = weft_f_schlick(f0_2, _e91.v_dot_h);
    let _e128 = weft_diffuse_lambert(diffuse_albedo);
    let diffuse = (((vec3(1f) - _e124) * _e128) * n_dot_l_diffuse);
    let _e132 = lobe.value;
    let direct = ((diffuse + (_e124 * _e132)) * _e119);
    reflect_n = _e53;
    {
        let _e141 = lobe.ibl_roughness;
        let _e142 = weft_env_brdf_lut(_e91.n_dot_v, _e141);
        let _e143 = weft_env_brdf_from_lut(f0_2, _e142);
        env_brdf = _e143;
        let _e146 = env_brdf;
        ambient_kd = max((vec3(1f) - _e146), vec3(0f));
        let _e152 = lobe.alpha;
        let _e153 = silk_lobe_anisotropy(_e152);
        let _e155 = lobe.ibl_roughness;
        let _e156 = weft_aniso_bent_normal(_e84, v_5, _e153, _e155);
        reflect_n = _e156;
    }
    let _e158 = reflect_n;
    let _e161 = lobe.ibl_roughness;
    let _e162 = weft_prefiltered_radiance(reflect(-(v_5), _e158), _e161);
    let _e163 = env_brdf;
    let _e165 = weft_sh_irradiance(n_diff);
    let _e166 = ambient_kd;
    let indirect = ((_e162 * _e163) + ((_e165 * _e166) * diffuse_albedo));
    let radiance = clamp((direct + indirect), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha_out);
}
