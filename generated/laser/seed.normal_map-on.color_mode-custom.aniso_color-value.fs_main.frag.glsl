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
    float roughness;
    float metallic;
    float occlusion_strength;
    vec4 base_map_st;
    float normal_strength;
    float saturation;
    float brightness;
    float span;
    float view_offset;
    vec4 offset_map_st;
    uint sin_mapping;
    float color_direction;
    float film_strength;
    float film_ior;
    float thickness_min;
    float thickness_max;
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
const float film_sensitivity_opd_max = 16000.0;
const uint COLOR_MODE_HUE_RING = 0u;
const uint COLOR_MODE_CUSTOM = 1u;
const uint ANISO_COLOR_OFF = 0u;
const uint ANISO_COLOR_VALUE = 1u;
const uint ANISO_COLOR_MAP = 2u;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_FILM_PI = 3.1415927;
const uint WEFT_FILM_SAMPLES = 101u;
const float WEFT_FILM_LAMBDA_MIN = 380.0;
const float WEFT_FILM_LAMBDA_MAX = 780.0;
const float WEFT_FILM_FADE_NM = 30.0;
const mat3x3 WEFT_XYZ_TO_REC709_ = mat3x3(vec3(3.2404542, -0.969266, 0.0556434), vec3(-1.5371385, 1.8760108, -0.2040259), vec3(-0.4985314, 0.041556, 1.0572252));

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_3_fs;

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 2) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 3) uniform sampler2D _group_1_binding_4_fs;

layout(binding = 4) uniform sampler2D _group_1_binding_5_fs;

layout(binding = 5) uniform sampler2D _group_1_binding_6_fs;

layout(binding = 6) uniform sampler2D _group_1_binding_7_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

vec4 gradient_color_ramp(float x) {
    vec4 _e9 = textureLod(_group_1_binding_7_fs, vec2(vec2(clamp(x, 0.0, 1.0), 0.5)), 0.0);
    return _e9;
}

float weft_pow5_(float x_1) {
    float x2_ = (x_1 * x_1);
    return ((x2_ * x2_) * x_1);
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

float weft_d_ggx_nh(vec3 n_2, vec3 h, float roughness_1) {
    float _e3 = weft_clamp_roughness(roughness_1);
    float a_1 = (_e3 * _e3);
    float a2_ = (a_1 * a_1);
    float noh = clamp(dot(n_2, h), 0.0, 1.0);
    vec3 nxh = cross(n_2, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d * d), 1e-30)));
}

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
}

float weft_v_smith_ggx_correlated(float n_dot_v, float n_dot_l, float roughness_2) {
    float _e3 = weft_clamp_roughness(roughness_2);
    float a_2 = (_e3 * _e3);
    float a2_1 = (a_2 * a_2);
    float _e6 = weft_clamp_cos(n_dot_v);
    float _e7 = weft_clamp_cos(n_dot_l);
    float lv = (_e7 * sqrt((((_e6 * _e6) * (1.0 - a2_1)) + a2_1)));
    float ll = (_e6 * sqrt((((_e7 * _e7) * (1.0 - a2_1)) + a2_1)));
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

float weft_specular_mip(float roughness_3) {
    float r = clamp(roughness_3, 0.0, 1.0);
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

vec3 weft_prefiltered_radiance(vec3 dir, float roughness_4) {
    float _e4 = weft_specular_mip(roughness_4);
    vec4 c_1 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_1.xyz, vec3(0.0));
}

vec2 weft_env_brdf_lut(float n_dot_v_1, float roughness_5) {
    vec2 uv_1 = vec2(clamp(n_dot_v_1, 0.0, 1.0), clamp(roughness_5, 0.0, 1.0));
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
    vec3 v_3 = ((texel * 2.0) - vec3(1.0));
    return vec3((v_3.xy * strength), max(v_3.z, 0.001));
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

float laser_cos_in_plane(vec3 n_7, vec3 v_2, vec3 direction) {
    vec3 p = cross(direction, n_7);
    float p_len = length(p);
    if ((p_len < 0.0001)) {
        float _e8 = weft_clamp_cos(dot(n_7, v_2));
        return _e8;
    }
    vec3 p_unit = (p / vec3(p_len));
    vec3 v_in_plane = (v_2 - (dot(v_2, p_unit) * p_unit));
    float len = length(v_in_plane);
    float _e19 = weft_clamp_cos((dot(n_7, v_in_plane) / max(len, 0.0001)));
    return _e19;
}

vec3 laser_rgb_to_hsv(vec3 rgb) {
    float hue = 0.0;
    float max_c = max(rgb.x, max(rgb.y, rgb.z));
    float min_c = min(rgb.x, min(rgb.y, rgb.z));
    float chroma = (max_c - min_c);
    if ((chroma > 1e-6)) {
        if ((max_c == rgb.x)) {
            hue = ((rgb.y - rgb.z) / chroma);
        } else {
            if ((max_c == rgb.y)) {
                hue = (((rgb.z - rgb.x) / chroma) + 2.0);
            } else {
                hue = (((rgb.x - rgb.y) / chroma) + 4.0);
            }
        }
        float _e36 = hue;
        hue = fract(((_e36 / 6.0) + 1.0));
    }
    float saturation = ((max_c > 1e-6) ? (chroma / max_c) : 0.0);
    float _e47 = hue;
    return vec3(_e47, saturation, max_c);
}

vec3 laser_hsv_to_rgb(vec3 hsv) {
    vec3 k = vec3(0.0, 0.6666667, 0.33333334);
    vec3 p_1 = abs(((fract((vec3(hsv.x) + k)) * 6.0) - vec3(3.0)));
    vec3 ring = clamp((p_1 - vec3(1.0)), vec3(0.0), vec3(1.0));
    return (hsv.z * mix(vec3(1.0), ring, hsv.y));
}

vec3 laser_seed_color(float cos_theta, vec2 layer_offsets) {
    vec3 hsv_1 = vec3(0.0);
    float c_2 = clamp(cos_theta, 0.0, 1.0);
    uint _e13 = _group_1_binding_0_fs.sin_mapping;
    float x_2 = ((_e13 != 0u) ? sqrt(max((1.0 - (c_2 * c_2)), 0.0)) : (1.0 - c_2));
    float _e19 = _group_1_binding_0_fs.saturation;
    float saturation_1 = clamp(_e19, 0.0, 1.0);
    float _e23 = _group_1_binding_0_fs.brightness;
    float brightness = clamp(_e23, 0.0, 1.0);
    float _e27 = _group_1_binding_0_fs.span;
    hsv_1 = vec3((x_2 * _e27), saturation_1, brightness);
    {
        vec4 _e31 = gradient_color_ramp(x_2);
        vec3 _e34 = laser_rgb_to_hsv(clamp(_e31.xyz, vec3(0.0), vec3(1.0)));
        hsv_1 = vec3(_e34.x, (_e34.y * saturation_1), (_e34.z * brightness));
    }
    float _e42 = hsv_1.x;
    float _e45 = _group_1_binding_0_fs.view_offset;
    float hue_1 = (_e42 + _e45);
    float _e51 = hsv_1.y;
    float _e53 = hsv_1.z;
    vec3 _e55 = laser_hsv_to_rgb(vec3(fract((hue_1 + layer_offsets.x)), _e51, _e53));
    float _e60 = hsv_1.y;
    float _e62 = hsv_1.z;
    vec3 _e64 = laser_hsv_to_rgb(vec3(fract((hue_1 + layer_offsets.y)), _e60, _e62));
    return (0.5 * (_e55 + _e64));
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 n = vec3(0.0);
    float film_cos = 0.0;
    vec2 direction_ts = vec2(1.0, 0.0);
    vec3 surface_base = vec3(0.0);
    vec3 f_light = vec3(0.0);
    vec3 e_spec = vec3(0.0);
    float light_cos = 0.0;
    vec3 film_view = vec3(0.0);
    vec3 film_light = vec3(0.0);
    vec4 _e4 = _group_1_binding_0_fs.base_map_st;
    vec2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    vec4 _e8 = _group_1_binding_0_fs.base_color;
    vec4 _e11 = texture(_group_1_binding_3_fs, vec2(_e5));
    vec4 base_rgba = (_e8 * _e11);
    vec3 base = clamp(base_rgba.xyz, vec3(0.0), vec3(1.0));
    float alpha = clamp(base_rgba.w, 0.0, 1.0);
    vec4 _e19 = texture(_group_1_binding_5_fs, vec2(_e5));
    vec3 rmo = _e19.xyz;
    float _e23 = _group_1_binding_0_fs.roughness;
    float roughness_6 = clamp((_e23 * rmo.x), 0.0, 1.0);
    float _e29 = _group_1_binding_0_fs.metallic;
    float metallic = clamp((_e29 * rmo.y), 0.0, 1.0);
    float _e36 = _group_1_binding_0_fs.occlusion_strength;
    float ao = clamp(mix(1.0, rmo.z, _e36), 0.0, 1.0);
    vec4 _e45 = _group_1_binding_0_fs.offset_map_st;
    vec2 _e46 = weft_transform_uv(in_1.uv0_, _e45);
    vec4 _e47 = texture(_group_1_binding_6_fs, vec2(_e46));
    vec2 offsets = clamp(_e47.xy, vec2(0.0), vec2(1.0));
    WeftSurface _e52 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_4 = _e52.v;
    vec3 geometric_n = _e52.n;
    n = geometric_n;
    {
        vec4 _e58 = texture(_group_1_binding_4_fs, vec2(_e5));
        vec3 texel_2 = _e58.xyz;
        float _e63 = _group_1_binding_0_fs.normal_strength;
        vec3 _e64 = weft_mapped_normal(geometric_n, in_1.world_tangent, texel_2, _e63);
        n = _e64;
    }
    vec3 _e65 = n;
    WeftLightGeometry _e66 = weft_main_light_geometry(_e65, v_4);
    film_cos = _e66.n_dot_v;
    {
        mat3x3 _e70 = weft_tangent_frame(geometric_n, in_1.world_tangent);
        {
            float _e77 = _group_1_binding_0_fs.color_direction;
            float angle = radians(_e77);
            direction_ts = vec2(cos(angle), sin(angle));
        }
        float _e84 = direction_ts.x;
        float _e88 = direction_ts.y;
        vec3 direction_1 = ((_e70[0] * _e84) + (_e70[1] * _e88));
        vec3 _e91 = n;
        float _e92 = laser_cos_in_plane(_e91, v_4, direction_1);
        film_cos = _e92;
    }
    surface_base = base;
    {
        float _e94 = film_cos;
        vec3 _e95 = laser_seed_color(_e94, offsets);
        surface_base = (base * _e95);
    }
    vec3 _e99 = surface_base;
    vec3 f0_2 = mix(vec3(0.04), _e99, metallic);
    vec3 _e101 = surface_base;
    vec3 diffuse_albedo = (_e101 * (1.0 - metallic));
    vec2 _e106 = weft_env_brdf_lut(_e66.n_dot_v, roughness_6);
    vec3 _e108 = weft_f_schlick(f0_2, _e66.v_dot_h);
    f_light = _e108;
    vec3 _e110 = weft_env_brdf_from_lut(f0_2, _e106);
    e_spec = _e110;
    vec3 _e114 = e_spec;
    vec3 kd = max((vec3(1.0) - _e114), vec3(0.0));
    float _e121 = weft_v_smith_ggx_correlated(_e66.n_dot_v, _e66.n_dot_l, roughness_6);
    vec3 _e122 = n;
    float _e124 = weft_d_ggx_nh(_e122, _e66.h, roughness_6);
    vec3 _e126 = f_light;
    vec3 specular = ((_e124 * _e121) * _e126);
    vec3 _e128 = weft_diffuse_lambert(diffuse_albedo);
    vec3 diffuse = (kd * _e128);
    vec3 _e131 = weft_main_light_radiance();
    vec3 direct = (((diffuse + specular) * _e131) * _e66.n_dot_l);
    vec3 _e136 = n;
    vec3 _e138 = weft_prefiltered_radiance(reflect(-(v_4), _e136), roughness_6);
    vec3 _e139 = e_spec;
    vec3 indirect_specular = ((_e138 * _e139) * ao);
    vec3 _e142 = n;
    vec3 _e143 = weft_sh_irradiance(_e142);
    vec3 indirect_diffuse = (((_e143 * ao) * kd) * diffuse_albedo);
    vec3 color = ((direct + indirect_specular) + indirect_diffuse);
    _fs2p_location0 = vec4(clamp(color, vec3(0.0), vec3(65504.0)), alpha);
    return;
}

