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
    vec4 flake_color;
    float flake_intensity;
    float flake_density;
    float flake_size;
    float flake_roughness;
    float twinkle;
    float density_variation;
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
const uint TIER_SMOOTH = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float GLINT_TAU = 6.2831855;
const float GLINT_HALF_PI = 1.5707964;
const float GLINT_TABLE_SIZE = 64.0;
const float GLINT_MIN_LOD = -20.0;
const float GLINT_MAX_LOD = 20.0;
const float GLINT_MAX_RATIO = 16.0;
const uint GLINT_TET_A_UP = 36292u;
const uint GLINT_TET_A_DOWN = 36165u;
const uint GLINT_TET_A_LOW = 34112u;
const uint GLINT_TET_B_UP = 23168u;
const uint GLINT_TET_B_DOWN = 42242u;
const uint GLINT_TET_B_HIGH = 44421u;
const uint GLINT_TET_C_UP = 44517u;
const uint GLINT_TET_C_DOWN = 58790u;
const uint GLINT_TET_C_LOW = 42338u;
const uint GLINT_TET_CENTER_UP = 60596u;
const uint GLINT_TET_CENTER_DOWN = 18110u;
const uint GLINT_TET_CENTER_LOW = 46659u;

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_3_fs;

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 2) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 3) uniform sampler2D _group_1_binding_4_fs;

layout(binding = 4) uniform sampler2D _group_1_binding_5_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

float weft_pow5_(float x) {
    float x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

float weft_clamp_cos(float c) {
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

float weft_clamp_roughness(float roughness) {
    return clamp(roughness, WEFT_MIN_ROUGHNESS, 1.0);
}

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_any_perpendicular(vec3 n_1) {
    float s = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return vec3((1.0 + (((s * n_1.x) * n_1.x) * a)), (s * b), (-(s) * n_1.x));
}

float weft_d_ggx(float n_dot_h, float roughness_1) {
    float _e2 = weft_clamp_roughness(roughness_1);
    float a_1 = (_e2 * _e2);
    float a2_ = (a_1 * a_1);
    float noh = clamp(n_dot_h, 0.0, 1.0);
    float one_minus_noh2_ = ((1.0 - noh) * (1.0 + noh));
    float d = (one_minus_noh2_ + ((noh * noh) * a2_));
    return (a2_ / ((WEFT_PI * d) * d));
}

float weft_d_ggx_nh(vec3 n_2, vec3 h, float roughness_2) {
    float _e3 = weft_clamp_roughness(roughness_2);
    float a_2 = (_e3 * _e3);
    float a2_1 = (a_2 * a_2);
    float noh_1 = clamp(dot(n_2, h), 0.0, 1.0);
    vec3 nxh = cross(n_2, h);
    float d_1 = (dot(nxh, nxh) + ((noh_1 * noh_1) * a2_1));
    return (a2_1 / (WEFT_PI * max((d_1 * d_1), 1e-30)));
}

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
}

float weft_v_smith_ggx_correlated(float n_dot_v, float n_dot_l, float roughness_3) {
    float _e3 = weft_clamp_roughness(roughness_3);
    float a_3 = (_e3 * _e3);
    float a2_2 = (a_3 * a_3);
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * (1.0 - a2_2)) + a2_2)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * (1.0 - a2_2)) + a2_2)));
    return (0.5 / (lv + ll));
}

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
}

vec3 weft_env_brdf_from_lut(vec3 f0_1, vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((f0_1 * sb.x) + vec3(sb.y));
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

vec3 weft_sh_irradiance(vec3 n_3) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_fs.sh;
    e = (sh[0].xyz * 0.282095);
    vec3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_3.y)));
    vec3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_3.z)));
    vec3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_3.x)));
    vec3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_3.x) * n_3.y)));
    vec3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_3.y) * n_3.z)));
    vec3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_3.z) * n_3.z) - 1.0))));
    vec3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_3.x) * n_3.z)));
    vec3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_3.x * n_3.x) - (n_3.y * n_3.y)))));
    vec3 _e91 = e;
    return max(_e91, vec3(0.0));
}

float weft_specular_mip(float roughness_4) {
    float r = clamp(roughness_4, 0.0, 1.0);
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

vec3 weft_prefiltered_radiance(vec3 dir, float roughness_5) {
    float _e4 = weft_specular_mip(roughness_5);
    vec4 c_1 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_1.xyz, vec3(0.0));
}

vec2 weft_env_brdf_lut(float n_dot_v_1, float roughness_6) {
    vec2 uv_1 = vec2(clamp(n_dot_v_1, 0.0, 1.0), clamp(roughness_6, 0.0, 1.0));
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv_1), 0.0);
    return _e8.xy;
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e6 = weft_view_direction(world_position_1, vec3(0.0, 0.0, 1.0));
    vec3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

WeftLightGeometry weft_main_light_geometry(vec3 n_4, vec3 v_1) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_1), n_4);
    float _e6 = weft_clamp_cos(dot(n_4, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_4, _e2), 0.0, 1.0), clamp(dot(n_4, _e4), 0.0, 1.0), clamp(dot(v_1, _e4), 0.0, 1.0));
}

mat3x3 weft_tangent_frame(vec3 n_5, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_5 * dot(n_5, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_5);
    vec3 t = (ok ? (t_proj * inversesqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_5, t) * s_1);
    return mat3x3(t, b_1, n_5);
}

vec3 weft_unpack_normal(vec3 texel, float strength) {
    vec3 v_2 = ((texel * 2.0) - vec3(1.0));
    return vec3((v_2.xy * strength), max(v_2.z, 0.001));
}

vec3 weft_normal_from_tangent_space(mat3x3 frame, vec3 n_ts) {
    vec3 _e4 = weft_safe_normalize((frame * n_ts), frame[2]);
    return _e4;
}

vec3 weft_mapped_normal(vec3 n_6, vec4 tangent_1, vec3 texel_1, float strength_1) {
    mat3x3 _e4 = weft_tangent_frame(n_6, tangent_1);
    vec3 _e5 = weft_unpack_normal(texel_1, strength_1);
    vec3 _e6 = weft_normal_from_tangent_space(_e4, _e5);
    return _e6;
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 n = vec3(0.0);
    vec3 color = vec3(0.0);
    bool local = false;
    float d_flakes = 0.0;
    vec4 _e4 = _group_1_binding_0_fs.base_map_st;
    vec2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    vec2 duv_dx = dFdx(_e5);
    vec2 duv_dy = dFdy(_e5);
    vec4 _e10 = _group_1_binding_0_fs.base_color;
    vec4 _e13 = texture(_group_1_binding_3_fs, vec2(_e5));
    vec4 base_rgba = (_e10 * _e13);
    vec3 base = clamp(base_rgba.xyz, vec3(0.0), vec3(1.0));
    float alpha = clamp(base_rgba.w, 0.0, 1.0);
    float _e21 = _group_1_binding_0_fs.metallic;
    float metallic = clamp(_e21, 0.0, 1.0);
    float _e25 = _group_1_binding_0_fs.smoothness;
    float roughness_7 = (1.0 - clamp(_e25, 0.0, 1.0));
    vec4 _e31 = texture(_group_1_binding_5_fs, vec2(_e5));
    float occlusion = _e31.x;
    float _e35 = _group_1_binding_0_fs.occlusion_strength;
    float ao = clamp(mix(1.0, occlusion, _e35), 0.0, 1.0);
    WeftSurface _e41 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_3 = _e41.v;
    n = _e41.n;
    {
        vec4 _e47 = texture(_group_1_binding_4_fs, vec2(_e5));
        vec3 texel_2 = _e47.xyz;
        vec3 _e49 = n;
        float _e53 = _group_1_binding_0_fs.normal_strength;
        vec3 _e54 = weft_mapped_normal(_e49, in_1.world_tangent, texel_2, _e53);
        n = _e54;
    }
    vec3 _e55 = n;
    mat3x3 _e57 = weft_tangent_frame(_e55, in_1.world_tangent);
    vec3 _e58 = n;
    WeftLightGeometry _e59 = weft_main_light_geometry(_e58, v_3);
    vec3 _e60 = weft_main_light_radiance();
    vec3 f0_2 = mix(vec3(0.04), base, metallic);
    vec3 diffuse_albedo = (base * (1.0 - metallic));
    float _e69 = weft_v_smith_ggx_correlated(_e59.n_dot_v, _e59.n_dot_l, roughness_7);
    vec2 _e71 = weft_env_brdf_lut(_e59.n_dot_v, roughness_7);
    vec3 _e72 = weft_env_brdf_from_lut(f0_2, _e71);
    vec3 kd = max((vec3(1.0) - _e72), vec3(0.0));
    vec3 _e79 = n;
    float _e81 = weft_d_ggx_nh(_e79, _e59.h, roughness_7);
    vec3 _e84 = weft_f_schlick(f0_2, _e59.v_dot_h);
    vec3 specular = ((_e81 * _e69) * _e84);
    vec3 _e86 = weft_diffuse_lambert(diffuse_albedo);
    vec3 direct = ((((kd * _e86) + specular) * _e60) * _e59.n_dot_l);
    vec3 _e93 = n;
    vec3 _e95 = weft_prefiltered_radiance(reflect(-(v_3), _e93), roughness_7);
    vec3 _e98 = n;
    vec3 _e99 = weft_sh_irradiance(_e98);
    vec3 indirect = (((_e95 * _e72) * ao) + (((_e99 * ao) * kd) * diffuse_albedo));
    color = (direct + indirect);
    float _e108 = _group_1_binding_0_fs.flake_intensity;
    float intensity = max(_e108, 0.0);
    if ((intensity > 0.0)) {
        local = (_e59.n_dot_l > 0.0);
    } else {
        local = false;
    }
    bool _e119 = local;
    if (_e119) {
        float _e122 = _group_1_binding_0_fs.flake_roughness;
        float r_f = clamp(_e122, 0.05, 1.0);
        vec3 _e126 = n;
        float _e128 = weft_d_ggx_nh(_e126, _e59.h, r_f);
        float _e130 = weft_d_ggx(1.0, r_f);
        vec4 _e133 = _group_1_binding_0_fs.flake_color;
        vec3 flake_f0_ = clamp(_e133.xyz, vec3(0.0), vec3(1.0));
        float _e138 = weft_v_smith_ggx_correlated(_e59.n_dot_v, _e59.n_dot_l, r_f);
        {
            {
                d_flakes = _e128;
            }
            vec3 _e140 = color;
            float _e141 = d_flakes;
            vec3 _e145 = weft_f_schlick(flake_f0_, _e59.v_dot_h);
            color = (_e140 + (((((intensity * _e141) * _e138) * _e145) * _e60) * _e59.n_dot_l));
        }
    }
    vec3 _e151 = color;
    vec3 radiance = clamp(_e151, vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, alpha);
    return;
}

