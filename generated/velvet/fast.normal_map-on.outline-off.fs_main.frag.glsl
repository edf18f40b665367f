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
    vec4 base_color;
    float metallic;
    float smoothness;
    vec4 base_map_st;
    float normal_strength;
    float occlusion_strength;
    vec4 scatter_color;
    float scatter_scale;
    vec4 outline_color;
    float outline_width;
    float outline_max_distance;
};
struct WeftSurface {
    vec3 v;
    vec3 n;
};
struct WeftLightGeometry {
    vec3 l;
    vec3 h;
    float n_dot_v;
    float n_dot_l;
    float n_dot_h;
    float v_dot_h;
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
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_SHEEN_MIN_ROUGHNESS = 0.07;

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_5_fs;

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 2) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 3) uniform sampler2D _group_1_binding_4_fs;

layout(binding = 4) uniform sampler2D _group_1_binding_5_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

float weft_max3_(vec3 v) {
    return max(v.x, max(v.y, v.z));
}

float weft_clamp_cos(float c) {
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

vec3 weft_safe_normalize(vec3 v_1, vec3 fallback) {
    float len2_ = dot(v_1, v_1);
    return ((len2_ > 1e-20) ? (v_1 * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_any_perpendicular(vec3 n_1) {
    float s = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return vec3((1.0 + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
}

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
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

vec3 weft_sh_irradiance(vec3 n_2) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_fs.sh;
    e = (sh[0].xyz * 0.282095);
    vec3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_2.y)));
    vec3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_2.z)));
    vec3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_2.x)));
    vec3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_2.x) * n_2.y)));
    vec3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_2.y) * n_2.z)));
    vec3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_2.z) * n_2.z) - 1.0))));
    vec3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_2.x) * n_2.z)));
    vec3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_2.x * n_2.x) - (n_2.y * n_2.y)))));
    vec3 _e91 = e;
    return max(_e91, vec3(0.0));
}

float weft_specular_mip(float roughness) {
    float r_2 = clamp(roughness, 0.0, 1.0);
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r_2 * (1.7 - (0.7 * r_2))) * max_mip);
}

vec3 weft_prefiltered_radiance(vec3 dir, float roughness_1) {
    float _e4 = weft_specular_mip(roughness_1);
    vec4 c_1 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_1.xyz, vec3(0.0));
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e6 = weft_view_direction(world_position_1, vec3(0.0, 0.0, 1.0));
    vec3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

WeftLightGeometry weft_main_light_geometry(vec3 n_3, vec3 v_2) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_2), n_3);
    float _e6 = weft_clamp_cos(dot(n_3, v_2));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_3, _e2), 0.0, 1.0), clamp(dot(n_3, _e4), 0.0, 1.0), clamp(dot(v_2, _e4), 0.0, 1.0));
}

mat3x3 weft_tangent_frame(vec3 n_4, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_4 * dot(n_4, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_4);
    vec3 t = (ok ? (t_proj * inversesqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_4, t) * s_1);
    return mat3x3(t, b_1, n_4);
}

vec3 weft_unpack_normal(vec3 texel, float strength) {
    vec3 v_3 = ((texel * 2.0) - vec3(1.0));
    return vec3((v_3.xy * strength), max(v_3.z, 0.001));
}

vec3 weft_normal_from_tangent_space(mat3x3 frame, vec3 n_ts) {
    vec3 _e4 = weft_safe_normalize((frame * n_ts), frame[2]);
    return _e4;
}

vec3 weft_mapped_normal(vec3 n_5, vec4 tangent_1, vec3 texel_1, float strength_1) {
    mat3x3 _e4 = weft_tangent_frame(n_5, tangent_1);
    vec3 _e5 = weft_unpack_normal(texel_1, strength_1);
    vec3 _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

float weft_sheen_clamp_roughness(float sheen_roughness) {
    return clamp(sheen_roughness, WEFT_SHEEN_MIN_ROUGHNESS, 1.0);
}

float weft_d_charlie(float n_dot_h, float sheen_roughness_1) {
    float _e2 = weft_sheen_clamp_roughness(sheen_roughness_1);
    float inv_r = (1.0 / _e2);
    float noh = clamp(n_dot_h, 0.0, 1.0);
    float sin2_ = max(((1.0 - noh) * (1.0 + noh)), 0.0);
    return (((2.0 + inv_r) * pow(sin2_, (0.5 * inv_r))) * 0.15915494);
}

float weft_sheen_l(float x, float r) {
    float t_1 = ((1.0 - r) * (1.0 - r));
    float a_1 = mix(21.5473, 25.3245, t_1);
    float b_2 = mix(3.82987, 3.32435, t_1);
    float c_2 = mix(0.19823, 0.16801, t_1);
    float d = mix(-1.9776, -1.27393, t_1);
    float e_1 = mix(-4.32054, -4.85967, t_1);
    return (((a_1 / (1.0 + (b_2 * pow(max(x, 0.0), c_2)))) + (d * x)) + e_1);
}

float weft_sheen_lambda_one_exp(float cos_theta, float r_1) {
    float _e2 = weft_clamp_cos(cos_theta);
    bool low = (_e2 < 0.5);
    float _e8 = weft_sheen_l((low ? _e2 : (1.0 - _e2)), r_1);
    float _e10 = weft_sheen_l(0.5, r_1);
    return exp((low ? _e8 : ((2.0 * _e10) - _e8)));
}

float weft_v_charlie(float n_dot_v, float n_dot_l, float sheen_roughness_2) {
    float _e3 = weft_sheen_clamp_roughness(sheen_roughness_2);
    float _e4 = weft_clamp_cos(n_dot_v);
    float _e5 = weft_clamp_cos(n_dot_l);
    float _e6 = weft_sheen_lambda_one_exp(_e4, _e3);
    float _e9 = weft_sheen_lambda_one_exp(_e5, _e3);
    float g_inv = ((1.0 + _e6) + _e9);
    return (1.0 / (((g_inv * 4.0) * _e4) * _e5));
}

vec3 weft_sheen_charlie(vec3 sheen_color, float n_dot_h_1, float n_dot_v_1, float n_dot_l_1, float sheen_roughness_3) {
    float _e5 = weft_d_charlie(n_dot_h_1, sheen_roughness_3);
    float _e6 = weft_v_charlie(n_dot_v_1, n_dot_l_1, sheen_roughness_3);
    float lobe = (_e5 * _e6);
    return (max(sheen_color, vec3(0.0)) * (lobe * clamp(n_dot_l_1, 0.0, 1.0)));
}

float weft_sheen_albedo_scaling_view(vec3 sheen_color_1, float e_v) {
    float _e2 = weft_max3_(sheen_color_1);
    return clamp((1.0 - (clamp(_e2, 0.0, 1.0) * clamp(e_v, 0.0, 1.0))), 0.0, 1.0);
}

float weft_sheen_albedo(float n_dot_x, float sheen_roughness_4) {
    float _e3 = weft_sheen_clamp_roughness(sheen_roughness_4);
    vec2 uv_1 = vec2(clamp(n_dot_x, 0.0, 1.0), _e3);
    vec4 _e8 = textureLod(_group_0_binding_5_fs, vec2(uv_1), 0.0);
    return clamp(_e8.x, 0.0, 1.0);
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 n = vec3(0.0);
    vec3 color = vec3(0.0);
    vec3 sheen = vec3(0.0);
    float scaling = 0.0;
    vec4 _e4 = _group_1_binding_0_fs.base_map_st;
    vec2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    vec4 _e8 = _group_1_binding_0_fs.base_color;
    vec4 _e11 = texture(_group_1_binding_3_fs, vec2(_e5));
    vec4 base_rgba = (_e8 * _e11);
    vec3 base = clamp(base_rgba.xyz, vec3(0.0), vec3(1.0));
    float alpha = clamp(base_rgba.w, 0.0, 1.0);
    float _e19 = _group_1_binding_0_fs.metallic;
    float metallic = clamp(_e19, 0.0, 1.0);
    float _e23 = _group_1_binding_0_fs.smoothness;
    float smoothness = clamp(_e23, 0.0, 1.0);
    float roughness_2 = (1.0 - smoothness);
    vec4 _e29 = texture(_group_1_binding_5_fs, vec2(_e5));
    float occlusion = _e29.x;
    float _e33 = _group_1_binding_0_fs.occlusion_strength;
    float ao = clamp(mix(1.0, occlusion, _e33), 0.0, 1.0);
    WeftSurface _e39 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_4 = _e39.v;
    n = _e39.n;
    {
        vec4 _e45 = texture(_group_1_binding_4_fs, vec2(_e5));
        vec3 texel_2 = _e45.xyz;
        vec3 _e47 = n;
        float _e51 = _group_1_binding_0_fs.normal_strength;
        vec3 _e52 = weft_mapped_normal(_e47, in_1.world_tangent, texel_2, _e51);
        n = _e52;
    }
    vec3 _e53 = n;
    WeftLightGeometry _e54 = weft_main_light_geometry(_e53, v_4);
    float l_dot_h = clamp(dot(_e54.l, _e54.h), 0.0, 1.0);
    vec3 f0_ = mix(vec3(0.04), base, metallic);
    vec3 diffuse_albedo = (base * (1.0 - metallic));
    vec3 _e65 = weft_main_light_radiance();
    vec3 _e66 = n;
    vec3 _e67 = weft_sh_irradiance(_e66);
    vec3 ambient = (_e67 * ao);
    {
        vec4 _e72 = _group_1_binding_0_fs.scatter_color;
        vec3 sheen_color_2 = clamp((f0_ + max(_e72.xyz, vec3(0.0))), vec3(0.0), vec3(1.0));
        float _e79 = weft_sheen_clamp_roughness(roughness_2);
        float _e81 = weft_sheen_albedo(_e54.n_dot_v, _e79);
        float _e82 = weft_sheen_albedo_scaling_view(sheen_color_2, _e81);
        {
            vec3 _e88 = weft_sheen_charlie(sheen_color_2, _e54.n_dot_h, _e54.n_dot_v, _e54.n_dot_l, _e79);
            sheen = _e88;
            scaling = _e82;
        }
        vec3 _e89 = weft_diffuse_lambert(diffuse_albedo);
        float _e90 = scaling;
        vec3 base_direct = (_e89 * (_e90 * _e54.n_dot_l));
        vec3 _e94 = sheen;
        vec3 direct = ((_e94 + base_direct) * _e65);
        vec3 _e98 = n;
        vec3 _e100 = weft_prefiltered_radiance(reflect(-(v_4), _e98), _e79);
        vec3 env_sheen = ((_e100 * sheen_color_2) * (_e81 * ao));
        color = ((direct + ((ambient * diffuse_albedo) * _e82)) + env_sheen);
    }
    vec3 _e108 = color;
    vec3 radiance = clamp(_e108, vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, alpha);
    return;
}

