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
struct WeftFilmStack {
    float n2_;
    float cos2_;
    vec2 r12_;
    vec3 r23_[2];
    bool total_internal_reflection;
};
struct WeftFilmSeries {
    vec3 dc;
    vec3 first;
    vec3 ratio;
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

layout(binding = 6) uniform sampler2D _group_1_binding_8_fs;

layout(binding = 7) uniform sampler2D _group_1_binding_9_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

vec4 table_film_sensitivity(vec2 uv) {
    vec2 size = vec2(2048.0, 2.0);
    vec2 st_1 = (((clamp(uv, vec2(0.0), vec2(1.0)) * (size - vec2(1.0))) + vec2(0.5)) / size);
    vec4 _e20 = textureLod(_group_1_binding_9_fs, vec2(st_1), 0.0);
    return _e20;
}

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
    float s_1 = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s_1 + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return vec3((1.0 + (((s_1 * n_1.x) * n_1.x) * a)), (s_1 * b), (-(s_1) * n_1.x));
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
    vec2 uv_2 = vec2(clamp(n_dot_v_1, 0.0, 1.0), clamp(roughness_5, 0.0, 1.0));
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv_2), 0.0);
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
    float s_2 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_5, t) * s_2);
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

vec2 weft_transform_uv(vec2 uv_1, vec4 st) {
    return ((uv_1 * st.xy) + st.zw);
}

vec3 weft_ior_from_f0_(vec3 f0_2) {
    vec3 s_3 = sqrt(clamp(f0_2, vec3(0.0), vec3(0.9999)));
    return ((vec3(1.0) + s_3) / (vec3(1.0) - s_3));
}

float weft_film_ior(float film_ior, float thickness_nm) {
    return mix(1.0, max(film_ior, 1.0), smoothstep(0.0, WEFT_FILM_FADE_NM, thickness_nm));
}

vec2 weft_fresnel_amplitudes(float n_i, float n_t, float cos_i, float cos_t) {
    float rs = (((n_i * cos_i) - (n_t * cos_t)) / max(((n_i * cos_i) + (n_t * cos_t)), 1e-12));
    float rp = (((n_t * cos_i) - (n_i * cos_t)) / max(((n_t * cos_i) + (n_i * cos_t)), 1e-12));
    return vec2(rs, rp);
}

vec3[2] weft_film_base_amplitudes(float n2_, float cos2_, vec3 n3_, float sin1_sq) {
    vec3 cos3_ = sqrt(max((vec3(1.0) - (vec3(sin1_sq) / (n3_ * n3_))), vec3(0.0)));
    vec3 s_4 = ((vec3((n2_ * cos2_)) - (n3_ * cos3_)) / max((vec3((n2_ * cos2_)) + (n3_ * cos3_)), vec3(1e-12)));
    vec3 p_1 = (((n3_ * cos2_) - (vec3(n2_) * cos3_)) / max(((n3_ * cos2_) + (vec3(n2_) * cos3_)), vec3(1e-12)));
    return vec3[2](s_4, p_1);
}

WeftFilmStack weft_film_stack(float cos_theta1_, float thickness_nm_1, float film_ior_1, vec3 base_f0_) {
    float cos1_ = clamp(cos_theta1_, 0.0, 1.0);
    float sin1_sq_1 = (1.0 - (cos1_ * cos1_));
    float _e10 = weft_film_ior(film_ior_1, thickness_nm_1);
    float cos2_sq = (1.0 - (sin1_sq_1 / (_e10 * _e10)));
    if ((cos2_sq <= 0.0)) {
        return WeftFilmStack(_e10, 0.0, vec2(1.0), vec3[2](vec3(1.0), vec3(1.0)), true);
    }
    float cos2_1 = sqrt(cos2_sq);
    vec2 _e29 = weft_fresnel_amplitudes(1.0, _e10, cos1_, cos2_1);
    vec3 _e30 = weft_ior_from_f0_(base_f0_);
    vec3 _e31[2] = weft_film_base_amplitudes(_e10, cos2_1, _e30, sin1_sq_1);
    return WeftFilmStack(_e10, cos2_1, _e29, _e31, false);
}

vec3 weft_film_sensitivity(float opd_nm) {
    vec4 _e5 = table_film_sensitivity(vec2((opd_nm / film_sensitivity_opd_max), 0.0));
    return _e5.xyz;
}

vec3 weft_film_orders(float opd_nm_1, WeftFilmSeries s, WeftFilmSeries p) {
    vec3 k1_ = ((s.first * s.ratio) + (p.first * p.ratio));
    vec3 k2_ = (((s.first * s.ratio) * s.ratio) + ((p.first * p.ratio) * p.ratio));
    vec3 k3_ = ((((s.first * s.ratio) * s.ratio) * s.ratio) + (((p.first * p.ratio) * p.ratio) * p.ratio));
    vec3 k4_ = (((s.first * (s.ratio * s.ratio)) * (s.ratio * s.ratio)) + ((p.first * (p.ratio * p.ratio)) * (p.ratio * p.ratio)));
    vec3 _e55 = weft_film_sensitivity(opd_nm_1);
    vec3 _e59 = weft_film_sensitivity((2.0 * opd_nm_1));
    vec3 _e64 = weft_film_sensitivity((3.0 * opd_nm_1));
    vec3 _e69 = weft_film_sensitivity((4.0 * opd_nm_1));
    vec3 sum = ((((k1_ * _e55) + (k2_ * _e59)) + (k3_ * _e64)) + (k4_ * _e69));
    return (2.0 * sum);
}

WeftFilmSeries weft_film_series(float r12_, vec3 r23_) {
    float big_r12_ = (r12_ * r12_);
    float t121_ = (1.0 - big_r12_);
    vec3 big_r23_ = (r23_ * r23_);
    vec3 big_r123_ = min((big_r12_ * big_r23_), vec3(0.9999));
    vec3 rs_1 = (((t121_ * t121_) * big_r23_) / (vec3(1.0) - big_r123_));
    vec3 ratio = clamp((-(r12_) * r23_), vec3(-0.99995), vec3(0.99995));
    return WeftFilmSeries((vec3(big_r12_) + rs_1), (rs_1 - vec3(t121_)), ratio);
}

vec3 weft_film_fourier_layers(float cos_theta1_1, float d1_, float d2_, float film_ior_2, vec3 base_f0_1) {
    float d_mean = (0.5 * (max(d1_, 0.0) + max(d2_, 0.0)));
    WeftFilmStack _e12 = weft_film_stack(cos_theta1_1, d_mean, film_ior_2, base_f0_1);
    if (_e12.total_internal_reflection) {
        return vec3(1.0);
    }
    WeftFilmSeries _e20 = weft_film_series(_e12.r12_.x, _e12.r23_[0]);
    WeftFilmSeries _e25 = weft_film_series(_e12.r12_.y, _e12.r23_[1]);
    float path = ((2.0 * _e12.n2_) * _e12.cos2_);
    vec3 _e37 = weft_film_orders((path * max(d1_, 0.0)), _e20, _e25);
    vec3 r1_ = ((_e20.dc + _e25.dc) + _e37);
    vec3 _e45 = weft_film_orders((path * max(d2_, 0.0)), _e20, _e25);
    vec3 r2_ = ((_e20.dc + _e25.dc) + _e45);
    return clamp((0.25 * (r1_ + r2_)), vec3(0.0), vec3(1.0));
}

float laser_cos_in_plane(vec3 n_7, vec3 v_2, vec3 direction) {
    vec3 p_2 = cross(direction, n_7);
    float p_len = length(p_2);
    if ((p_len < 0.0001)) {
        float _e8 = weft_clamp_cos(dot(n_7, v_2));
        return _e8;
    }
    vec3 p_unit = (p_2 / vec3(p_len));
    vec3 v_in_plane = (v_2 - (dot(v_2, p_unit) * p_unit));
    float len = length(v_in_plane);
    float _e19 = weft_clamp_cos((dot(n_7, v_in_plane) / max(len, 0.0001)));
    return _e19;
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
            vec4 _e77 = texture(_group_1_binding_8_fs, vec2(_e5));
            vec2 flow = ((_e77.xy * 2.0) - vec2(1.0));
            direction_ts = ((dot(flow, flow) > 1e-6) ? flow : vec2(1.0, 0.0));
        }
        float _e93 = direction_ts.x;
        float _e97 = direction_ts.y;
        vec3 direction_1 = ((_e70[0] * _e93) + (_e70[1] * _e97));
        vec3 _e100 = n;
        float _e101 = laser_cos_in_plane(_e100, v_4, direction_1);
        film_cos = _e101;
    }
    surface_base = base;
    vec3 _e105 = surface_base;
    vec3 f0_3 = mix(vec3(0.04), _e105, metallic);
    vec3 _e107 = surface_base;
    vec3 diffuse_albedo = (_e107 * (1.0 - metallic));
    vec2 _e112 = weft_env_brdf_lut(_e66.n_dot_v, roughness_6);
    vec3 _e114 = weft_f_schlick(f0_3, _e66.v_dot_h);
    f_light = _e114;
    vec3 _e116 = weft_env_brdf_from_lut(f0_3, _e112);
    e_spec = _e116;
    {
        float _e120 = _group_1_binding_0_fs.thickness_min;
        float _e123 = _group_1_binding_0_fs.thickness_max;
        float d1_1 = mix(_e120, _e123, offsets.x);
        float _e128 = _group_1_binding_0_fs.thickness_min;
        float _e131 = _group_1_binding_0_fs.thickness_max;
        float d2_1 = mix(_e128, _e131, offsets.y);
        float _e136 = _group_1_binding_0_fs.film_strength;
        float strength_2 = clamp(_e136, 0.0, 1.0);
        light_cos = _e66.v_dot_h;
        {
            float _e140 = film_cos;
            light_cos = _e140;
        }
        {
            float _e143 = film_cos;
            float _e146 = _group_1_binding_0_fs.film_ior;
            vec3 _e147 = weft_film_fourier_layers(_e143, d1_1, d2_1, _e146, f0_3);
            film_view = _e147;
            float _e148 = light_cos;
            float _e151 = _group_1_binding_0_fs.film_ior;
            vec3 _e152 = weft_film_fourier_layers(_e148, d1_1, d2_1, _e151, f0_3);
            film_light = _e152;
        }
        vec3 _e153 = f_light;
        vec3 _e154 = film_light;
        f_light = mix(_e153, _e154, strength_2);
        vec3 _e156 = e_spec;
        vec3 _e157 = film_view;
        e_spec = mix(_e156, (_e157 * (_e112.x + _e112.y)), strength_2);
    }
    vec3 _e165 = e_spec;
    vec3 kd = max((vec3(1.0) - _e165), vec3(0.0));
    float _e172 = weft_v_smith_ggx_correlated(_e66.n_dot_v, _e66.n_dot_l, roughness_6);
    vec3 _e173 = n;
    float _e175 = weft_d_ggx_nh(_e173, _e66.h, roughness_6);
    vec3 _e177 = f_light;
    vec3 specular = ((_e175 * _e172) * _e177);
    vec3 _e179 = weft_diffuse_lambert(diffuse_albedo);
    vec3 diffuse = (kd * _e179);
    vec3 _e182 = weft_main_light_radiance();
    vec3 direct = (((diffuse + specular) * _e182) * _e66.n_dot_l);
    vec3 _e187 = n;
    vec3 _e189 = weft_prefiltered_radiance(reflect(-(v_4), _e187), roughness_6);
    vec3 _e190 = e_spec;
    vec3 indirect_specular = ((_e189 * _e190) * ao);
    vec3 _e193 = n;
    vec3 _e194 = weft_sh_irradiance(_e193);
    vec3 indirect_diffuse = (((_e194 * ao) * kd) * diffuse_albedo);
    vec3 color = ((direct + indirect_specular) + indirect_diffuse);
    _fs2p_location0 = vec4(clamp(color, vec3(0.0), vec3(65504.0)), alpha);
    return;
}

