#version 450 core
struct WeftFrame {
    mat4x4 view_proj;
    mat4x4 view;
    vec4 camera_position;
    vec4 light_direction;
    vec4 light_color;
    vec4 sh[9];
    vec4 params;
    vec4 viewport;
};
struct WeftObject {
    mat4x4 model;
    mat4x4 normal_matrix;
};
struct WeftMaterial {
    float iris_radius;
    float pupil_size;
    vec4 iris_color;
    vec4 iris_inner_color;
    float limbus_width;
    vec4 sclera_color;
    float cornea_height;
    float cornea_ior;
    float cornea_smoothness;
    float specular_strength;
    float backlight_dimming;
    float parallax_height;
    float matcap_intensity;
};
struct WeftSurface {
    vec3 v;
    vec3 n;
};
struct WeftVertexInput {
    vec3 position;
    vec3 normal;
    vec4 tangent;
    vec2 uv0_;
};
struct WeftVaryings {
    vec4 clip_position;
    vec3 world_position;
    vec3 world_normal;
    vec4 world_tangent;
    vec2 uv0_;
};
struct EyeLookup {
    vec2 iris;
    vec3 normal;
    float through_cornea;
};
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(std140, binding = 2) uniform WeftObject_block_1Fragment { WeftObject _group_2_binding_0_fs; };

layout(std140, binding = 1) uniform WeftMaterial_block_2Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 0) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 1) uniform sampler2D _group_1_binding_4_fs;

layout(binding = 2) uniform sampler2D _group_1_binding_5_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_main_light_direction() {
    vec4 _e2 = _group_0_binding_0_fs.light_direction;
    vec3 _e8 = weft_safe_normalize(_e2.xyz, vec3(0.0, 0.0, 1.0));
    return _e8;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_fs.light_color;
    return max(_e2.xyz, vec3(0.0));
}

vec3 weft_view_direction(vec3 world_position, vec3 fallback_1) {
    vec4 _e4 = _group_0_binding_0_fs.camera_position;
    vec3 _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
}

vec3 weft_sh_irradiance(vec3 n) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_fs.sh;
    e = (sh[0].xyz * 0.282095);
    vec3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n.y)));
    vec3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n.z)));
    vec3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n.x)));
    vec3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n.x) * n.y)));
    vec3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n.y) * n.z)));
    vec3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n.z) * n.z) - 1.0))));
    vec3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n.x) * n.z)));
    vec3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n.x * n.x) - (n.y * n.y)))));
    vec3 _e91 = e;
    return max(_e91, vec3(0.0));
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e6 = weft_view_direction(world_position_1, vec3(0.0, 0.0, 1.0));
    vec3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

WeftVaryings weft_forward_vertex(WeftVertexInput in_2) {
    WeftVaryings out_ = WeftVaryings(vec4(0.0), vec3(0.0), vec3(0.0), vec4(0.0), vec2(0.0));
    mat4x4 model = _group_2_binding_0_fs.model;
    mat3x3 model3_ = mat3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    mat4x4 nm = _group_2_binding_0_fs.normal_matrix;
    mat3x3 normal3_ = mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    vec4 world = (model * vec4(in_2.position, 1.0));
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    mat4x4 _e43 = _group_0_binding_0_fs.view_proj;
    out_.clip_position = (_e43 * vec4(world.xyz, 1.0));
    out_.world_position = world.xyz;
    vec3 _e55 = weft_safe_normalize((normal3_ * in_2.normal), vec3(0.0));
    out_.world_normal = _e55;
    vec3 _e62 = weft_safe_normalize((model3_ * in_2.tangent.xyz), vec3(0.0));
    out_.world_tangent = vec4(_e62, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out_;
    return _e66;
}

vec2 eye_seed_uv(vec2 uv, vec3 v_1, float height) {
    return (uv + (height * vec2(v_1.x, -(v_1.y))));
}

vec2 eye_uv_from_xy(vec2 xy) {
    return vec2((0.5 + (0.5 * xy.x)), (0.5 - (0.5 * xy.y)));
}

vec2 eye_xy_from_uv(vec2 uv_1) {
    return vec2(((2.0 * uv_1.x) - 1.0), (1.0 - (2.0 * uv_1.y)));
}

vec3 eye_albedo(vec2 q, bool front) {
    vec3 iris = vec3(0.0);
    float _e4 = _group_1_binding_0_fs.iris_radius;
    float r = clamp(_e4, 0.05, 0.95);
    float rho = (length(q) / r);
    {
        vec2 iris_uv = (vec2(0.5, 0.5) + (vec2(q.x, -(q.y)) * (0.5 / r)));
        vec4 _e24 = _group_1_binding_0_fs.iris_color;
        vec4 _e28 = texture(_group_1_binding_3_fs, vec2(iris_uv));
        iris = (_e24.xyz * _e28.xyz);
    }
    vec4 _e33 = _group_1_binding_0_fs.sclera_color;
    vec2 _e37 = eye_uv_from_xy(q);
    vec4 _e38 = texture(_group_1_binding_4_fs, vec2(_e37));
    vec3 sclera = (_e33.xyz * _e38.xyz);
    float to_sclera = (front ? smoothstep(0.985, 1.015, rho) : 1.0);
    vec3 _e46 = iris;
    return clamp(mix(_e46, sclera, to_sclera), vec3(0.0), vec3(1.0));
}

vec3 eye_seed(vec3 p, vec3 v_eye, vec3 n_1, vec3 world_position_2, vec3 light) {
    vec3 matcap = vec3(0.0);
    vec2 _e6 = eye_uv_from_xy(p.xy);
    float _e9 = _group_1_binding_0_fs.parallax_height;
    vec2 _e10 = eye_seed_uv(_e6, v_eye, _e9);
    vec2 _e11 = eye_xy_from_uv(_e10);
    vec3 _e15 = eye_albedo(_e11, (p.z > 0.0));
    mat4x4 view = _group_0_binding_0_fs.view;
    mat3x3 view3_ = mat3x3(view[0].xyz, view[1].xyz, view[2].xyz);
    vec3 _e31 = weft_safe_normalize((view3_ * n_1), vec3(0.0, 0.0, 1.0));
    vec3 _e40 = weft_safe_normalize((view * vec4(world_position_2, 1.0)).xyz, vec3(0.0, 0.0, -1.0));
    vec3 vxn = cross(_e40, _e31);
    vec2 matcap_uv = vec2((0.5 - (0.5 * vxn.y)), (0.5 - (0.5 * vxn.x)));
    {
        vec4 _e56 = texture(_group_1_binding_5_fs, vec2(matcap_uv));
        matcap = _e56.xyz;
    }
    vec3 _e58 = matcap;
    float _e61 = _group_1_binding_0_fs.matcap_intensity;
    vec3 base = (_e15 + (_e58 * max(_e61, 0.0)));
    vec3 _e68 = weft_sh_irradiance(n_1);
    return (base * ((light * WEFT_INV_PI) + _e68));
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 color = vec3(0.0);
    EyeLookup look = EyeLookup(vec2(0.0), vec3(0.0), 0.0);
    mat4x4 model_1 = _group_2_binding_0_fs.model;
    mat3x3 model3_1 = mat3x3(model_1[0].xyz, model_1[1].xyz, model_1[2].xyz);
    mat4x4 nm_1 = _group_2_binding_0_fs.normal_matrix;
    mat3x3 normal3_1 = mat3x3(nm_1[0].xyz, nm_1[1].xyz, nm_1[2].xyz);
    WeftSurface _e23 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_2 = _e23.v;
    vec3 n_2 = _e23.n;
    vec3 _e26 = weft_main_light_direction();
    vec3 _e33 = weft_safe_normalize((transpose(model3_1) * n_2), vec3(0.0, 0.0, 1.0));
    vec3 _e40 = weft_safe_normalize((transpose(normal3_1) * v_2), vec3(0.0, 0.0, 1.0));
    vec3 _e46 = weft_safe_normalize((model3_1 * vec3(0.0, 0.0, 1.0)), n_2);
    float _e49 = _group_1_binding_0_fs.backlight_dimming;
    float dimming = (1.0 - (clamp(_e49, 0.0, 1.0) * clamp(-(dot(_e46, _e26)), 0.0, 1.0)));
    vec3 _e57 = weft_main_light_radiance();
    {
        vec3 _e60 = eye_seed(_e33, _e40, n_2, in_1.world_position, _e57);
        color = _e60;
    }
    vec3 _e61 = color;
    vec3 radiance = clamp((_e61 * dimming), vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, 1.0);
    return;
}

