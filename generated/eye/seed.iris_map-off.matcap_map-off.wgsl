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
@group(2) @binding(0) 
var<uniform> weft_object: WeftObject;
@group(1) @binding(0) 
var<uniform> material: WeftMaterial;
@group(1) @binding(1) 
var material_sampler: sampler;
@group(1) @binding(4) 
var sclera_map: texture_2d<f32>;

fn weft_safe_normalize(v: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    let len2_ = dot(v, v);
    return select(fallback, (v * inverseSqrt(max(len2_, 0.00000000000000000001f))), (len2_ > 0.00000000000000000001f));
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

fn eye_seed_uv(uv: vec2<f32>, v_1: vec3<f32>, height: f32) -> vec2<f32> {
    return (uv + (height * vec2<f32>(v_1.x, -(v_1.y))));
}

fn eye_uv_from_xy(xy: vec2<f32>) -> vec2<f32> {
    return vec2<f32>((0.5f + (0.5f * xy.x)), (0.5f - (0.5f * xy.y)));
}

fn eye_xy_from_uv(uv_1: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(((2f * uv_1.x) - 1f), (1f - (2f * uv_1.y)));
}

fn eye_procedural_iris(rho: f32, a: f32) -> vec3<f32> {
    var c: vec3<f32>;

    let _e4 = material.pupil_size;
    let pupil = clamp(_e4, 0f, 0.95f);
    let t = saturate(((rho - pupil) / (1f - pupil)));
    let _e15 = material.iris_inner_color;
    let _e19 = material.iris_color;
    c = mix(_e15.xyz, _e19.xyz, smoothstep(0.05f, 0.5f, t));
    let fibres = ((0.82f + (0.1f * sin(((a * 23f) + (6f * t))))) + (0.08f * sin((((a * 41f) - (9f * t)) + 1.3f))));
    let _e47 = c;
    c = (_e47 * fibres);
    let _e51 = material.limbus_width;
    let w = saturate(_e51);
    let _e53 = c;
    c = (_e53 * (1f - (0.8f * smoothstep((1f - w), 1f, rho))));
    let _e65 = c;
    return mix(vec3(0.01f), _e65, smoothstep((pupil - 0.02f), (pupil + 0.02f), rho));
}

fn eye_albedo(q: vec2<f32>, front: bool) -> vec3<f32> {
    var iris: vec3<f32>;

    let _e4 = material.iris_radius;
    let r = clamp(_e4, 0.05f, 0.95f);
    let rho_1 = (length(q) / r);
    {
        let qa = select(vec2<f32>(1f, 0f), q, (dot(q, q) > 0.000000000001f));
        let _e21 = eye_procedural_iris(rho_1, atan2(qa.y, qa.x));
        iris = _e21;
    }
    let _e24 = material.sclera_color;
    let _e28 = eye_uv_from_xy(q);
    let _e29 = textureSample(sclera_map, material_sampler, _e28);
    let sclera = (_e24.xyz * _e29.xyz);
    let to_sclera = select(1f, smoothstep(0.985f, 1.015f, rho_1), front);
    let _e37 = iris;
    return saturate(mix(_e37, sclera, to_sclera));
}

fn eye_procedural_matcap(uv_2: vec2<f32>) -> vec3<f32> {
    let key = (1f - smoothstep(0.03f, 0.08f, length((uv_2 - vec2<f32>(0.36f, 0.3f)))));
    let bounce = (1f - smoothstep(0.02f, 0.09f, length((uv_2 - vec2<f32>(0.66f, 0.72f)))));
    return vec3((key + (0.25f * bounce)));
}

fn eye_seed(p: vec3<f32>, v_eye: vec3<f32>, n_1: vec3<f32>, world_position_2: vec3<f32>, light: vec3<f32>) -> vec3<f32> {
    var matcap: vec3<f32>;

    let _e6 = eye_uv_from_xy(p.xy);
    let _e9 = material.parallax_height;
    let _e10 = eye_seed_uv(_e6, v_eye, _e9);
    let _e11 = eye_xy_from_uv(_e10);
    let _e15 = eye_albedo(_e11, (p.z > 0f));
    let view = weft_frame.view;
    let view3_ = mat3x3<f32>(view[0].xyz, view[1].xyz, view[2].xyz);
    let _e31 = weft_safe_normalize((view3_ * n_1), vec3<f32>(0f, 0f, 1f));
    let _e40 = weft_safe_normalize((view * vec4<f32>(world_position_2, 1f)).xyz, vec3<f32>(0f, 0f, -1f));
    let vxn = cross(_e40, _e31);
    let matcap_uv = vec2<f32>((0.5f - (0.5f * vxn.y)), (0.5f - (0.5f * vxn.x)));
    {
        let _e54 = eye_procedural_matcap(matcap_uv);
        matcap = _e54;
    }
    let _e55 = matcap;
    let _e58 = material.matcap_intensity;
    let base = (_e15 + (_e55 * max(_e58, 0f)));
    let _e65 = weft_sh_irradiance(n_1);
    return (base * ((light * WEFT_INV_PI) + _e65));
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
    let normal3_1 = mat3x3<f32>(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    let _e23 = weft_surface(in_1.world_position, in_1.world_normal);
    let v_2 = _e23.v;
    let n_2 = _e23.n;
    let _e26 = weft_main_light_direction();
    let _e33 = weft_safe_normalize((transpose(model3_1) * n_2), vec3<f32>(0f, 0f, 1f));
    let _e40 = weft_safe_normalize((transpose(normal3_1) * v_2), vec3<f32>(0f, 0f, 1f));
    let _e46 = weft_safe_normalize((model3_1 * vec3<f32>(0f, 0f, 1f)), n_2);
    let _e49 = material.backlight_dimming;
    let dimming = (1f - (saturate(_e49) * saturate(-(dot(_e46, _e26)))));
    let _e57 = weft_main_light_radiance();
    {
        let _e60 = eye_seed(_e33, _e40, n_2, in_1.world_position, _e57);
        color = _e60;
    }
    let _e61 = color;
    let radiance = clamp((_e61 * dimming), vec3(0f), vec3(65504f));
    return vec4<f32>(radiance, 1f);
}
