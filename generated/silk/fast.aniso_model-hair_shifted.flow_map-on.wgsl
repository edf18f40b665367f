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

fn weft_d_ggx_nh(n_1: vec3<f32>, h: vec3<f32>, roughness_1: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_1);
    let a_1 = (_e3 * _e3);
    let a2_ = (a_1 * a_1);
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

fn weft_tangent_frame(n_4: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = (t_in - (n_4 * dot(n_4, t_in)));
    let len2_1 = dot(t_proj, t_proj);
    let ok = (len2_1 > max((0.000001f * dot(t_in, t_in)), 0.00000000000000000001f));
    let _e13 = weft_any_perpendicular(n_4);
    let t = select(_e13, (t_proj * inverseSqrt(max(len2_1, 0.00000000000000000001f))), ok);
    let s_1 = select(1f, -1f, (tangent.w < 0f));
    let b_1 = (cross(n_4, t) * s_1);
    return mat3x3<f32>(t, b_1, n_4);
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
    let d_1 = (1f / ((((WEFT_PI * at_1) * ab_1) * _e9) * _e9));
    return select(0f, d_1, (n_dot_h_1 > 0f));
}

fn weft_v_smith_ggx_aniso_correlated(v_2: vec3<f32>, l: vec3<f32>, alpha_t_2: f32, alpha_b_2: f32) -> f32 {
    let _e5 = weft_clamp_cos(v_2.z);
    let _e7 = weft_clamp_cos(l.z);
    let lv_1 = (_e7 * length(vec3<f32>((alpha_t_2 * v_2.x), (alpha_b_2 * v_2.y), _e5)));
    let ll_1 = (_e5 * length(vec3<f32>((alpha_t_2 * l.x), (alpha_b_2 * l.y), _e7)));
    return (0.5f / (lv_1 + ll_1));
}

fn weft_aniso_bent_normal(frame_2: mat3x3<f32>, v_3: vec3<f32>, anisotropy: f32, roughness_6: f32) -> vec3<f32> {
    let k = clamp(anisotropy, -1f, 1f);
    let n_5 = frame_2[2];
    let dir_1 = select(frame_2[0], frame_2[1], (k >= 0f));
    let aniso_t = cross(dir_1, v_3);
    let aniso_n = cross(aniso_t, dir_1);
    let bend = (abs(k) * saturate((5f * saturate(roughness_6))));
    let _e22 = weft_safe_normalize(mix(n_5, aniso_n, bend), n_5);
    return _e22;
}

fn silk_hair_mx_seed(smoothness: f32, gloss: f32) -> f32 {
    let p = (1f - saturate((smoothness * gloss)));
    let rx = (p * p);
    let rx_safe = select(rx, 0.0001f, (rx == 0f));
    return (rx_safe * rx_safe);
}

fn silk_tilt_frame(frame_3: mat3x3<f32>, shift: f32) -> mat3x3<f32> {
    let s_2 = clamp(shift, -1f, 1f);
    let _e10 = weft_safe_normalize((frame_3[0] + (s_2 * frame_3[2])), frame_3[0]);
    let _e16 = weft_safe_normalize((frame_3[2] - (s_2 * frame_3[0])), frame_3[2]);
    return mat3x3<f32>(_e10, frame_3[1], _e16);
}

fn silk_lobe_anisotropy(alpha: vec2<f32>) -> f32 {
    let at_2 = max(alpha.x, SILK_MIN_ALPHA);
    let ab_2 = max(alpha.y, SILK_MIN_ALPHA);
    return ((at_2 - ab_2) / (at_2 + ab_2));
}

fn silk_ibl_roughness(alpha_1: vec2<f32>) -> f32 {
    return saturate(sqrt(sqrt(max((alpha_1.x * alpha_1.y), 0f))));
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
    let smoothness_1 = saturate(_e19);
    let roughness_7 = (1f - smoothness_1);
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
    let k_1 = material.anisotropy;
    {
        {
            let _e103 = material.aniso_gloss;
            let _e104 = silk_hair_mx_seed(smoothness_1, _e103);
            let _e107 = material.aniso_mask;
            let mask = saturate(_e107);
            let _e111 = material.aniso_spec;
            let spec_scale = mix(max(_e111, 0f), 1f, mask);
            let a_hair = vec2<f32>(max(_e104, SILK_MIN_ALPHA), 1f);
            let _e120 = weft_clamp_roughness(roughness_7);
            let _e121 = weft_clamp_roughness(roughness_7);
            let a_iso = (_e120 * _e121);
            lobe.alpha = mix(a_hair, vec2(a_iso), mask);
            let _e127 = silk_ibl_roughness(a_hair);
            lobe.ibl_roughness = mix(_e127, roughness_7, mask);
            {
                {
                    let _e131 = material.tangent_shift;
                    let _e132 = silk_tilt_frame(_e84, _e131);
                    let _e133 = weft_aniso_to_frame(_e132, v_5);
                    let _e135 = weft_aniso_to_frame(_e132, _e91.l);
                    let _e137 = weft_aniso_to_frame(_e132, _e91.h);
                    let _e143 = weft_d_ggx_aniso(_e137.x, _e137.y, _e137.z, a_hair.x, a_hair.y);
                    let _e146 = weft_v_smith_ggx_aniso_correlated(_e133, _e135, a_hair.x, a_hair.y);
                    let aniso = ((_e143 * _e146) * saturate(_e135.z));
                    let _e152 = weft_d_ggx_nh(_e53, _e91.h, roughness_7);
                    let _e155 = weft_v_smith_ggx_correlated(_e91.n_dot_v, _e91.n_dot_l, roughness_7);
                    let iso = ((_e152 * _e155) * _e91.n_dot_l);
                    lobe.value = (mix(aniso, iso, mask) * spec_scale);
                }
            }
        }
    }
    let _e162 = weft_main_light_radiance();
    let n_dot_l_diffuse = saturate(dot(n_diff, _e91.l));
    let _e167 = weft_f_schlick(f0_2, _e91.v_dot_h);
    let _e171 = weft_diffuse_lambert(diffuse_albedo);
    let diffuse = (((vec3(1f) - _e167) * _e171) * n_dot_l_diffuse);
    let _e175 = lobe.value;
    let direct = ((diffuse + (_e167 * _e175)) * _e162);
    reflect_n = _e53;
    {
        let _e184 = lobe.ibl_roughness;
        let _e185 = weft_env_brdf_lut(_e91.n_dot_v, _e184);
        let _e186 = weft_env_brdf_from_lut(f0_2, _e185);
        env_brdf = _e186;
        let _e189 = env_brdf;
        ambient_kd = max((vec3(1f) - _e189), vec3(0f));
        let _e195 = lobe.alpha;
        let _e196 = silk_lobe_anisotropy(_e195);
        let _e198 = lobe.ibl_roughness;
        let _e199 = weft_aniso_bent_normal(_e84, v_5, _e196, _e198);
        reflect_n = _e199;
    }
    let _e201 = reflect_n;
    let _e204 = lobe.ibl_roughness;
    let _e205 = weft_prefiltered_radiance(reflect(-(v_5), _e201), _e204);
    let _e206 = env_brdf;
    let _e208 = weft_sh_irradiance(n_diff);
    let _e209 = ambient_kd;
    let indirect = ((_e205 * _e206) + ((_e208 * _e209) * diffuse_albedo));
    let radiance = clamp((direct + indirect), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha_out);
}
