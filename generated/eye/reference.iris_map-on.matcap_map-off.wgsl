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
    iris_radius: f32,
    pupil_size: f32,
    iris_color: vec4<f32>,
    iris_inner_color: vec4<f32>,
    limbus_width: f32,
    sclera_color: vec4<f32>,
    cornea_height: f32,
    cornea_ior: f32,
    cornea_smoothness: f32,
    specular_strength: f32,
    backlight_dimming: f32,
    parallax_height: f32,
    matcap_intensity: f32,
}

struct WeftSurface {
    v: vec3<f32>,
    n: vec3<f32>,
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

struct EyeCornea {
    z_iris: f32,
    centre_z: f32,
    radius: f32,
}

struct EyeLookup {
    iris: vec2<f32>,
    normal: vec3<f32>,
    through_cornea: f32,
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
var iris_map: texture_2d<f32>;
@group(1) @binding(4) 
var sclera_map: texture_2d<f32>;

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

fn weft_d_ggx_nh(n: vec3<f32>, h: vec3<f32>, roughness_1: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_1);
    let a = (_e3 * _e3);
    let a2_ = (a * a);
    let noh = saturate(dot(n, h));
    let nxh = cross(n, h);
    let d = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d * d), 0.000000000000000000000000000001f)));
}

fn weft_f_dielectric(cos_i: f32, eta: f32) -> f32 {
    let c_2 = clamp(abs(cos_i), WEFT_MIN_N_DOT, 1f);
    let g2_ = (((eta * eta) - 1f) + (c_2 * c_2));
    let g = sqrt(max(g2_, 0f));
    let gmc = (g - c_2);
    let gpc = max((g + c_2), 0.0000001f);
    let b_den = max(((c_2 * gmc) + 1f), 0.0000001f);
    let b_num = ((c_2 * gpc) - 1f);
    let inv = (1f / (gpc * b_den));
    let f = saturate(((((0.5f * gmc) * gmc) * ((b_den * b_den) + (b_num * b_num))) * (inv * inv)));
    return select(f, 1f, (g2_ < 0f));
}

fn weft_f0_from_ior(ior: f32) -> f32 {
    let q_1 = ((ior - 1f) / max((ior + 1f), 0.0001f));
    return (q_1 * q_1);
}

fn weft_v_smith_ggx_correlated(n_dot_v: f32, n_dot_l: f32, roughness_2: f32) -> f32 {
    let _e3 = weft_clamp_roughness(roughness_2);
    let a_1 = (_e3 * _e3);
    let a2_1 = (a_1 * a_1);
    let _e6 = weft_clamp_cos(n_dot_v);
    let _e7 = weft_clamp_cos(n_dot_l);
    let lv = (_e7 * sqrt((((_e6 * _e6) * (1f - a2_1)) + a2_1)));
    let ll = (_e6 * sqrt((((_e7 * _e7) * (1f - a2_1)) + a2_1)));
    return (0.5f / (lv + ll));
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

fn weft_specular_mip(roughness_3: f32) -> f32 {
    let r = saturate(roughness_3);
    let _e5 = weft_frame.params.x;
    let max_mip = max((_e5 - 1f), 0f);
    return ((r * (1.7f - (0.7f * r))) * max_mip);
}

fn weft_prefiltered_radiance(dir: vec3<f32>, roughness_4: f32) -> vec3<f32> {
    let _e4 = weft_specular_mip(roughness_4);
    let c_3 = textureSampleLevel(weft_environment, weft_environment_sampler, dir, _e4);
    return max(c_3.xyz, vec3(0f));
}

fn weft_env_brdf_lut(n_dot_v_1: f32, roughness_5: f32) -> vec2<f32> {
    let uv = vec2<f32>(saturate(n_dot_v_1), saturate(roughness_5));
    let _e8 = textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv, 0f);
    return _e8.xy;
}

fn weft_surface(world_position_1: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let _e6 = weft_view_direction(world_position_1, vec3<f32>(0f, 0f, 1f));
    let _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

fn weft_forward_vertex(in_2: WeftVertexInput) -> WeftVaryings {
    var out: WeftVaryings;

    let model = weft_object.model;
    let model3_ = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm = weft_object.normal_matrix;
    let normal3_1 = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = (model * vec4<f32>(in_2.position, 1f));
    let mirror = select(1f, -1f, (determinant(model3_) < 0f));
    let bitangent_sign = (select(1f, -1f, (in_2.tangent.w < 0f)) * mirror);
    let _e43 = weft_frame.view_proj;
    out.clip_position = (_e43 * vec4<f32>(world.xyz, 1f));
    out.world_position = world.xyz;
    let _e55 = weft_safe_normalize((normal3_1 * in_2.normal), vec3(0f));
    out.world_normal = _e55;
    let _e62 = weft_safe_normalize((model3_ * in_2.tangent.xyz), vec3(0f));
    out.world_tangent = vec4<f32>(_e62, bitangent_sign);
    out.uv0_ = in_2.uv0_;
    let _e66 = out;
    return _e66;
}

fn eye_cornea(iris_radius: f32, height: f32) -> EyeCornea {
    let r_1 = clamp(iris_radius, 0.05f, 0.95f);
    let h_2 = max(height, 0.01f);
    let z_iris_1 = sqrt((1f - (r_1 * r_1)));
    let radius = (((r_1 * r_1) + (h_2 * h_2)) / (2f * h_2));
    return EyeCornea(z_iris_1, ((z_iris_1 + h_2) - radius), radius);
}

fn eye_to_iris_plane(start: vec3<f32>, t: vec3<f32>, z_iris: f32) -> vec2<f32> {
    let down = max(-(t.z), 0.0001f);
    return (start.xy + (t.xy * ((start.z - z_iris) / down)));
}

fn eye_refracted(p: vec3<f32>, v_1: vec3<f32>, c_1: EyeCornea, ior_1: f32) -> EyeLookup {
    var local: bool;
    var local_1: bool;

    let centre = vec3<f32>(0f, 0f, c_1.centre_z);
    let o = (p - centre);
    let b = dot(o, v_1);
    let disc = ((b * b) - (dot(o, o) - (c_1.radius * c_1.radius)));
    let s_1 = (-(b) + sqrt(max(disc, 0f)));
    let hit = (p + (s_1 * v_1));
    if !((p.z <= 0f)) {
        local = (disc <= 0f);
    } else {
        local = true;
    }
    let _e33 = local;
    if !(_e33) {
        local_1 = (hit.z < c_1.z_iris);
    } else {
        local_1 = true;
    }
    let _e41 = local_1;
    if _e41 {
        return EyeLookup(p.xy, p, 0f);
    }
    let n_3 = ((hit - centre) / vec3(c_1.radius));
    let t_1 = refract(-(v_1), n_3, (1f / max(ior_1, 1f)));
    let _e56 = eye_to_iris_plane(hit, t_1, c_1.z_iris);
    return EyeLookup(_e56, n_3, 1f);
}

fn eye_uv_from_xy(xy: vec2<f32>) -> vec2<f32> {
    return vec2<f32>((0.5f + (0.5f * xy.x)), (0.5f - (0.5f * xy.y)));
}

fn eye_albedo(q: vec2<f32>, front: bool) -> vec3<f32> {
    var iris: vec3<f32>;

    let _e4 = material.iris_radius;
    let r_2 = clamp(_e4, 0.05f, 0.95f);
    let rho = (length(q) / r_2);
    {
        let iris_uv = (vec2<f32>(0.5f, 0.5f) + (vec2<f32>(q.x, -(q.y)) * (0.5f / r_2)));
        let _e24 = material.iris_color;
        let _e28 = textureSample(iris_map, material_clamp_sampler, iris_uv);
        iris = (_e24.xyz * _e28.xyz);
    }
    let _e33 = material.sclera_color;
    let _e37 = eye_uv_from_xy(q);
    let _e38 = textureSample(sclera_map, material_sampler, _e37);
    let sclera = (_e33.xyz * _e38.xyz);
    let to_sclera = select(1f, smoothstep(0.985f, 1.015f, rho), front);
    let _e46 = iris;
    return saturate(mix(_e46, sclera, to_sclera));
}

fn eye_fresnel(cos_i_1: f32, ior_2: f32) -> f32 {
    {
        let _e2 = weft_f_dielectric(cos_i_1, ior_2);
        return _e2;
    }
}

fn eye_ggx(s: vec3<f32>, h_1: vec3<f32>, s_dot_v: f32, s_dot_l: f32, roughness_6: f32) -> f32 {
    {
        let _e5 = weft_d_ggx_nh(s, h_1, roughness_6);
        let _e6 = weft_v_smith_ggx_correlated(s_dot_v, s_dot_l, roughness_6);
        return (_e5 * _e6);
    }
}

fn eye_physical(look_1: EyeLookup, n_2: vec3<f32>, v_2: vec3<f32>, l: vec3<f32>, normal3_: mat3x3<f32>, ior_3: f32, light: vec3<f32>) -> vec3<f32> {
    var local_2: bool;

    if !((look_1.through_cornea > 0f)) {
        local_2 = (look_1.normal.z > 0f);
    } else {
        local_2 = true;
    }
    let _e19 = local_2;
    let _e20 = eye_albedo(look_1.iris, _e19);
    let _e23 = material.cornea_smoothness;
    let _e27 = weft_clamp_roughness((1f - saturate(_e23)));
    let _e30 = weft_safe_normalize((normal3_ * look_1.normal), n_2);
    let _e32 = weft_clamp_cos(dot(_e30, v_2));
    let s_dot_l_1 = saturate(dot(_e30, l));
    let _e36 = weft_safe_normalize((l + v_2), _e30);
    let _e38 = eye_fresnel(dot(v_2, _e36), ior_3);
    let _e39 = eye_ggx(_e30, _e36, _e32, s_dot_l_1, _e27);
    let direct_spec = ((_e39 * _e38) * s_dot_l_1);
    let _e42 = weft_f0_from_ior(ior_3);
    let f0_1 = vec3(_e42);
    let _e46 = weft_prefiltered_radiance(reflect(-(v_2), _e30), _e27);
    let _e47 = weft_env_brdf_lut(_e32, _e27);
    let _e48 = weft_env_brdf_from_lut(f0_1, _e47);
    let env = (_e46 * _e48);
    let _e54 = material.specular_strength;
    let specular = (((light * direct_spec) + env) * max(_e54, 0f));
    let on_iris = (look_1.through_cornea > 0f);
    let _e66 = weft_safe_normalize((normal3_ * vec3<f32>(0f, 0f, 1f)), n_2);
    let l_in = refract(-(l), _e30, (1f / ior_3));
    let iris_cos = select(0f, saturate(dot(_e66, -(l_in))), (s_dot_l_1 > 0f));
    let _e78 = eye_fresnel(_e32, ior_3);
    let t_v = (1f - _e78);
    let _e81 = eye_fresnel(s_dot_l_1, ior_3);
    let t_l = (1f - _e81);
    let diffuse_n = select(n_2, _e66, on_iris);
    let diffuse_cos = select(saturate(dot(n_2, l)), (iris_cos * t_l), on_iris);
    let transmission = select(1f, t_v, on_iris);
    let _e95 = weft_sh_irradiance(diffuse_n);
    let diffuse = ((_e20 * transmission) * ((light * (WEFT_INV_PI * diffuse_cos)) + _e95));
    return (diffuse + specular);
}

@vertex 
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    let _e1 = weft_forward_vertex(in);
    return _e1;
}

@fragment 
fn fs_main(in_1: WeftVaryings) -> @location(0) vec4<f32> {
    var color: vec3<f32>;
    var look: EyeLookup;

    let model_1 = weft_object.model;
    let model3_1 = mat3x3<f32>(model_1[0].xyz, model_1[1].xyz, model_1[2].xyz);
    let nm_1 = weft_object.normal_matrix;
    let normal3_2 = mat3x3<f32>(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    let _e23 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_3 = _e23.v;
    let n_4 = _e23.n;
    let _e26 = weft_main_light_direction();
    let _e33 = weft_safe_normalize((transpose(model3_1) * n_4), vec3<f32>(0f, 0f, 1f));
    let _e40 = weft_safe_normalize((transpose(normal3_2) * v_3), vec3<f32>(0f, 0f, 1f));
    let _e46 = weft_safe_normalize((model3_1 * vec3<f32>(0f, 0f, 1f)), n_4);
    let _e49 = material.backlight_dimming;
    let dimming = (1f - (saturate(_e49) * saturate(-(dot(_e46, _e26)))));
    let _e57 = weft_main_light_radiance();
    {
        let _e61 = material.iris_radius;
        let _e64 = material.cornea_height;
        let _e65 = eye_cornea(_e61, _e64);
        let _e68 = material.cornea_ior;
        let ior_4 = max(_e68, 1f);
        {
            let _e72 = eye_refracted(_e33, _e40, _e65, ior_4);
            look = _e72;
        }
        let _e73 = look;
        let _e74 = eye_physical(_e73, n_4, v_3, _e26, normal3_2, ior_4, _e57);
        color = _e74;
    }
    let _e75 = color;
    let radiance = clamp((_e75 * dimming), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
