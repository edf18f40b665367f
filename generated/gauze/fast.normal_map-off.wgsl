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
    base_map_st: vec4<f32>,
    normal_map_st: vec4<f32>,
    normal_strength: f32,
    thread_density: f32,
    thread_transmittance: f32,
    mesh_gap: f32,
    anisotropy: f32,
    anisotropic_intensity: f32,
    scatter_color: vec4<f32>,
    scatter_intensity: f32,
    pattern_threshold: f32,
    pattern_rotation: f32,
    sampling_density: f32,
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
const TIER_SEED: u32 = 2u;
const WEFT_MIN_ROUGHNESS: f32 = 0.045f;
const WEFT_MIN_N_DOT: f32 = 0.0001f;
const WEFT_MAX_HALF: f32 = 65504f;
const WEFT_DIELECTRIC_F0_: f32 = 0.04f;
const WEFT_MIN_ANISO_ALPHA: f32 = 0.001f;
const GAUZE_LN_MAX_TRANSMITTANCE: f32 = 6.9077554f;

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
var mesh_map: texture_2d<f32>;
@group(1) @binding(6) 
var noise_map: texture_2d<f32>;
@group(1) @binding(7) 
var pattern_map: texture_2d<f32>;

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
    let s_1 = select(-1f, 1f, (n_1.z >= 0f));
    let a = (-1f / (s_1 + n_1.z));
    let b = ((n_1.x * n_1.y) * a);
    return vec3<f32>((1f + (((s_1 * n_1.x) * n_1.x) * a)), (s_1 * b), (-(s_1) * n_1.x));
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

fn weft_surface_two_sided(world_position_1: vec3<f32>, world_normal: vec3<f32>, front_facing_1: bool) -> WeftSurface {
    let _e7 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let facing = select(-(world_normal), world_normal, front_facing_1);
    let _e10 = weft_safe_normalize(facing, _e7);
    return WeftSurface(_e7, _e10);
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

fn weft_rotate_tangent_frame_cs(frame_1: mat3x3<f32>, c_1: f32, s: f32) -> mat3x3<f32> {
    let len2_2 = ((c_1 * c_1) + (s * s));
    let inv = inverseSqrt(max(len2_2, 0.00000000000000000001f));
    let cc = select(1f, (c_1 * inv), (len2_2 > 0.00000000000000000001f));
    let ss = select(0f, (s * inv), (len2_2 > 0.00000000000000000001f));
    let t_1 = ((frame_1[0] * cc) + (frame_1[1] * ss));
    let b_2 = ((frame_1[1] * cc) - (frame_1[0] * ss));
    return mat3x3<f32>(t_1, b_2, frame_1[2]);
}

fn weft_rotate_tangent_frame(frame_2: mat3x3<f32>, angle: f32) -> mat3x3<f32> {
    let _e4 = weft_rotate_tangent_frame_cs(frame_2, cos(angle), sin(angle));
    return _e4;
}

fn weft_aniso_alpha_kulla(roughness_4: f32, anisotropy: f32) -> vec2<f32> {
    let _e2 = weft_clamp_roughness(roughness_4);
    let a_1 = (_e2 * _e2);
    let k = clamp(anisotropy, -1f, 1f);
    return max(vec2<f32>((a_1 * (1f + k)), (a_1 * (1f - k))), vec2(0.001f));
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

fn weft_v_smith_ggx_aniso_correlated(v_2: vec3<f32>, l: vec3<f32>, alpha_t_2: f32, alpha_b_2: f32) -> f32 {
    let _e5 = weft_clamp_cos(v_2.z);
    let _e7 = weft_clamp_cos(l.z);
    let lv = (_e7 * length(vec3<f32>((alpha_t_2 * v_2.x), (alpha_b_2 * v_2.y), _e5)));
    let ll = (_e5 * length(vec3<f32>((alpha_t_2 * l.x), (alpha_b_2 * l.y), _e7)));
    return (0.5f / (lv + ll));
}

fn weft_spec_ggx_aniso(v_3: vec3<f32>, l_1: vec3<f32>, alpha_t_3: f32, alpha_b_3: f32) -> f32 {
    let _e9 = weft_safe_normalize((v_3 + l_1), vec3<f32>(0f, 0f, 1f));
    let _e13 = weft_d_ggx_aniso(_e9.x, _e9.y, _e9.z, alpha_t_3, alpha_b_3);
    let _e14 = weft_v_smith_ggx_aniso_correlated(v_3, l_1, alpha_t_3, alpha_b_3);
    return ((_e13 * _e14) * saturate(l_1.z));
}

fn weft_aniso_bent_normal(frame_3: mat3x3<f32>, v_4: vec3<f32>, anisotropy_1: f32, roughness_5: f32) -> vec3<f32> {
    let k_1 = clamp(anisotropy_1, -1f, 1f);
    let n_5 = frame_3[2];
    let dir_1 = select(frame_3[0], frame_3[1], (k_1 >= 0f));
    let aniso_t = cross(dir_1, v_4);
    let aniso_n = cross(aniso_t, dir_1);
    let bend = (abs(k_1) * saturate((5f * saturate(roughness_5))));
    let _e22 = weft_safe_normalize(mix(n_5, aniso_n, bend), n_5);
    return _e22;
}

fn gauze_grid_coverage(cell: vec2<f32>, w: vec2<f32>, gap: f32) -> f32 {
    let g = clamp(gap, 0f, 1f);
    let d_1 = abs((fract(cell) - vec2(0.5f)));
    let ww = max(w, vec2(0.0001f));
    let ramp = saturate((((vec2((0.5f * g)) - d_1) / ww) + vec2(0.5f)));
    let open = mix(ramp, vec2(g), saturate(((ww * 2f) - vec2(1f))));
    let open_xy = select(0f, (open.x * open.y), (g > 0f));
    return (1f - open_xy);
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    var n: vec3<f32>;
    var spec_direct: vec3<f32>;
    var env_brdf: vec3<f32>;
    var diffuse_kd: vec3<f32>;
    var ambient_kd: vec3<f32>;
    var lobe: f32;

    let _e5 = material.base_map_st;
    let _e6 = weft_transform_uv(in_1.uv0_, _e5);
    let _e9 = material.base_color;
    let _e12 = textureSample(base_map, material_sampler, _e6);
    let base_rgba = (_e9 * _e12);
    let base = saturate(base_rgba.xyz);
    let base_alpha = saturate(base_rgba.w);
    let _e20 = material.roughness;
    let roughness_6 = saturate(_e20);
    let _e24 = material.anisotropy;
    let anisotropy_2 = clamp(_e24, -1f, 1f);
    let _e31 = material.sampling_density;
    let uv_s = (in_1.uv0_ * _e31);
    let _e35 = textureSample(mesh_map, material_sampler, uv_s);
    let mesh_tex = saturate(_e35.x);
    let _e40 = textureSample(noise_map, material_sampler, uv_s);
    let noise = saturate(_e40.x);
    let _e45 = textureSample(pattern_map, material_sampler, uv_s);
    let pattern = _e45.x;
    let grid_w = fwidth(uv_s);
    let pattern_w = fwidth(pattern);
    let _e51 = material.mesh_gap;
    let _e52 = gauze_grid_coverage(uv_s, grid_w, _e51);
    let mesh = (mesh_tex * _e52);
    let _e56 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    let v_5 = _e56.v;
    let n_geom = _e56.n;
    n = n_geom;
    let _e60 = n;
    let _e62 = weft_tangent_frame(_e60, in_1.world_tangent);
    let cos_v = min(abs(dot(n_geom, v_5)), 1f);
    let sin_v = sqrt(max((1f - (cos_v * cos_v)), 0f));
    let _e75 = material.thread_density;
    let density = clamp(_e75, 0f, 200f);
    let s_3 = pow(max(sin_v, 0.00000001f), density);
    let _e84 = material.thread_transmittance;
    let transmittance = clamp(_e84, 1f, 1000f);
    let thread_opacity = saturate((1f - (log(transmittance) / GAUZE_LN_MAX_TRANSMITTANCE)));
    let alpha = saturate(((1f - ((1f - s_3) * (1f - (mesh * thread_opacity)))) * base_alpha));
    let coverage = saturate(((1f - ((1f - s_3) * (1f - mesh))) * base_alpha));
    let _e115 = material.pattern_rotation;
    let rot = radians(_e115);
    let _e117 = weft_rotate_tangent_frame(_e62, rot);
    let _e120 = material.pattern_threshold;
    let above_hard = select(0f, 1f, (pattern > _e120));
    let _e127 = material.pattern_threshold;
    let above_aa = saturate((((pattern - _e127) / max(pattern_w, 0.0001f)) + 0.5f));
    let _e135 = n;
    let _e136 = weft_main_light_geometry(_e135, v_5);
    let _e137 = weft_aniso_alpha_kulla(roughness_6, anisotropy_2);
    let _e138 = weft_main_light_radiance();
    let _e141 = material.scatter_color;
    let scatter = max(_e141.xyz, vec3(0f));
    let tint = saturate(scatter);
    let f0_2 = vec3(0.04f);
    {
        {
            let _e155 = weft_rotate_tangent_frame(_e62, (rot * above_aa));
            let _e156 = weft_aniso_to_frame(_e155, v_5);
            let _e158 = weft_aniso_to_frame(_e155, _e136.l);
            let _e161 = weft_spec_ggx_aniso(_e156, _e158, _e137.x, _e137.y);
            lobe = _e161;
        }
        let _e163 = weft_f_schlick(f0_2, _e136.v_dot_h);
        let _e164 = lobe;
        spec_direct = ((((_e164 * _e163) * tint) * noise) * _e138);
        let _e172 = weft_f_schlick(f0_2, _e136.n_dot_v);
        diffuse_kd = (vec3(1f) - (tint * _e172));
        let _e176 = weft_env_brdf_lut(_e136.n_dot_v, roughness_6);
        let _e177 = weft_env_brdf_from_lut(f0_2, _e176);
        env_brdf = (_e177 * tint);
        let _e181 = env_brdf;
        ambient_kd = max((vec3(1f) - _e181), vec3(0f));
    }
    let _e186 = diffuse_kd;
    let _e187 = weft_diffuse_lambert(base);
    let diffuse_direct = (((_e186 * _e187) * _e138) * _e136.n_dot_l);
    let _e192 = n;
    let _e193 = weft_sh_irradiance(_e192);
    let _e194 = ambient_kd;
    let diffuse_indirect = ((_e193 * _e194) * base);
    let _e197 = weft_aniso_bent_normal(_e62, v_5, anisotropy_2, roughness_6);
    let _e200 = weft_prefiltered_radiance(reflect(-(v_5), _e197), roughness_6);
    let _e201 = env_brdf;
    let spec_indirect = ((_e200 * _e201) * noise);
    let _e206 = spec_direct;
    let color = ((alpha * (diffuse_direct + diffuse_indirect)) + (coverage * (_e206 + spec_indirect)));
    let radiance = clamp(color, vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, alpha);
}
