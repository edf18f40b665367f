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
    vec4 noise_map_st;
    float specular_intensity;
    vec4 specular_color;
    vec4 second_specular_color;
    float second_layer_width;
    float anisotropy;
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
struct SatinLayers {
    vec2 narrow;
    vec2 wide;
};
const float WEFT_PI = 3.1415927;
const float WEFT_INV_PI = 0.31830987;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const uint TIER_LOW = 3u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_MIN_ANISO_ALPHA = 0.001;
const float WEFT_MIN_ROUGHNESS_HALF = 0.089;
const float WEFT_MIN_N_DOT_HALF = 0.001;
const float WEFT_MIN_ALPHA_HALF = 0.007921;

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_3_fs;

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 2) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 3) uniform sampler2D _group_1_binding_4_fs;

layout(binding = 4) uniform sampler2D _group_1_binding_5_fs;

layout(binding = 5) uniform sampler2D _group_1_binding_6_fs;

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
    float s_1 = ((n_1.z >= 0.0) ? 1.0 : -1.0);
    float a = (-1.0 / (s_1 + n_1.z));
    float b = ((n_1.x * n_1.y) * a);
    return vec3((1.0 + (((s_1 * n_1.x) * n_1.x) * a)), (s_1 * b), (-(s_1) * n_1.x));
}

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
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

float weft_specular_mip(float roughness_1) {
    float r = clamp(roughness_1, 0.0, 1.0);
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

vec3 weft_prefiltered_radiance(vec3 dir, float roughness_2) {
    float _e4 = weft_specular_mip(roughness_2);
    vec4 c_2 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_2.xyz, vec3(0.0));
}

vec2 weft_env_brdf_lut(float n_dot_v, float roughness_3) {
    vec2 uv_1 = vec2(clamp(n_dot_v, 0.0, 1.0), clamp(roughness_3, 0.0, 1.0));
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv_1), 0.0);
    return _e8.xy;
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e6 = weft_view_direction(world_position_1, vec3(0.0, 0.0, 1.0));
    vec3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

WeftLightGeometry weft_main_light_geometry(vec3 n_3, vec3 v_1) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_1), n_3);
    float _e6 = weft_clamp_cos(dot(n_3, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_3, _e2), 0.0, 1.0), clamp(dot(n_3, _e4), 0.0, 1.0), clamp(dot(v_1, _e4), 0.0, 1.0));
}

mat3x3 weft_tangent_frame(vec3 n_4, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_4 * dot(n_4, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_4);
    vec3 t = (ok ? (t_proj * inversesqrt(max(len2_1, 1e-20))) : _e13);
    float s_2 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_1 = (cross(n_4, t) * s_2);
    return mat3x3(t, b_1, n_4);
}

vec3 weft_unpack_normal(vec3 texel, float strength) {
    vec3 v_6 = ((texel * 2.0) - vec3(1.0));
    return vec3((v_6.xy * strength), max(v_6.z, 0.001));
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

vec3 weft_aniso_to_frame(mat3x3 frame_1, vec3 x_1) {
    return vec3(dot(frame_1[0], x_1), dot(frame_1[1], x_1), dot(frame_1[2], x_1));
}

vec2 weft_aniso_alpha_kulla(float roughness_4, float anisotropy) {
    float _e2 = weft_clamp_roughness(roughness_4);
    float a_1 = (_e2 * _e2);
    float k_1 = clamp(anisotropy, -1.0, 1.0);
    return max(vec2((a_1 * (1.0 + k_1)), (a_1 * (1.0 - k_1))), vec2(0.001));
}

vec3 weft_aniso_bent_normal(mat3x3 frame_2, vec3 v_2, float anisotropy_1, float roughness_5) {
    float k_2 = clamp(anisotropy_1, -1.0, 1.0);
    vec3 n_7 = frame_2[2];
    vec3 dir_1 = ((k_2 >= 0.0) ? frame_2[1] : frame_2[0]);
    vec3 aniso_t = cross(dir_1, v_2);
    vec3 aniso_n = cross(aniso_t, dir_1);
    float bend = (abs(k_2) * clamp((5.0 * clamp(roughness_5, 0.0, 1.0)), 0.0, 1.0));
    vec3 _e22 = weft_safe_normalize(mix(n_7, aniso_n, bend), n_7);
    return _e22;
}

float weft_half_pow5_(float x_2) {
    float x2_1 = (x_2 * x_2);
    return ((x2_1 * x2_1) * x_2);
}

vec3 weft_half_f_schlick(vec3 f0_2, float v_dot_h_1) {
    float _e7 = weft_half_pow5_((1.0 - v_dot_h_1));
    return (f0_2 + ((vec3(1.0) - f0_2) * _e7));
}

vec2 weft_half_spec_ggx_aniso2_(vec3 v_3, vec3 l, vec3 h, vec2 alpha_t, vec2 alpha_b) {
    vec2 at = max(alpha_t, vec2(0.007921));
    vec2 ab = max(alpha_b, vec2(0.007921));
    vec2 inv_at = vec2((vec2(1.0) / at));
    vec2 inv_ab = vec2((vec2(1.0) / ab));
    vec2 at_h = vec2(at);
    vec2 ab_h = vec2(ab);
    vec2 x_3 = (h.x * inv_at);
    vec2 y = (h.y * inv_ab);
    vec2 q = max((((x_3 * x_3) + (y * y)) + vec2((h.z * h.z))), vec2(0.01));
    vec2 d = ((((inv_at * inv_ab) / q) / q) * 0.31830987);
    float nv = max(v_3.z, 0.001);
    float nl = clamp(l.z, 0.0, 1.0);
    vec2 vt = (at_h * v_3.x);
    vec2 vb = (ab_h * v_3.y);
    vec2 lt = (at_h * l.x);
    vec2 lb = (ab_h * l.y);
    vec2 lv = (nl * sqrt((((vt * vt) + (vb * vb)) + vec2((nv * nv)))));
    vec2 ll = (nv * sqrt((((lt * lt) + (lb * lb)) + vec2((nl * nl)))));
    vec2 v_n_dot_l = (vec2((0.5 * nl)) / max((lv + ll), vec2(0.0001)));
    return ((h.z > 0.0) ? min((d * v_n_dot_l), vec2(65504.0)) : vec2(0.0));
}

vec3 satin_env(mat3x3 frame_3, vec3 v_4, float k, float roughness_6) {
    vec3 bent_1 = vec3(0.0);
    vec3 c_1 = vec3(0.0);
    vec3 _e4 = weft_aniso_bent_normal(frame_3, v_4, k, roughness_6);
    bent_1 = _e4;
    vec3 _e7 = bent_1;
    vec3 _e9 = weft_prefiltered_radiance(reflect(-(v_4), _e7), roughness_6);
    c_1 = _e9;
    vec3 _e11 = c_1;
    return _e11;
}

vec2 satin_lobes_low(vec3 vf, vec3 lf, vec3 hf, vec2 a1_, vec2 a2_) {
    vec2 s = vec2(0.0);
    vec2 at_1 = vec2(a1_.x, a2_.x);
    vec2 ab_1 = vec2(a1_.y, a2_.y);
    vec2 _e11 = weft_half_spec_ggx_aniso2_(vf, lf, hf, at_1, ab_1);
    s = _e11;
    vec2 _e13 = s;
    return _e13;
}

vec3 satin_low(mat3x3 frame_4, vec3 n_6, vec3 v_5, WeftLightGeometry lit, vec3 f0_in, vec3 diffuse_albedo, float roughness_7, float roughness2_, float anisotropy_2, vec3 c1_in, vec3 c2_in, float noise, float ao, vec3 light) {
    float n_dot_v_1 = lit.n_dot_v;
    float n_dot_l = float(lit.n_dot_l);
    float v_dot_h_2 = float(lit.v_dot_h);
    vec3 f0_3 = vec3(f0_in);
    vec3 c1_ = vec3(c1_in);
    vec3 c2_ = vec3(c2_in);
    vec3 t1_ = mix(c1_, vec3(max(c1_.x, max(c1_.y, c1_.z))), 0.5);
    vec3 t2_ = mix(c2_, vec3(max(c2_.x, max(c2_.y, c2_.z))), 0.5);
    vec3 t_1 = (t1_ + t2_);
    float norm = (1.0 / max(1.0, max(t_1.x, max(t_1.y, t_1.z))));
    vec3 w1_ = (t1_ * norm);
    vec3 w2_ = (t2_ * norm);
    float r_low = max(roughness_7, WEFT_MIN_ROUGHNESS_HALF);
    float r2_low = max(roughness2_, WEFT_MIN_ROUGHNESS_HALF);
    vec3 _e54 = weft_aniso_to_frame(frame_4, v_5);
    vec3 vf_1 = vec3(_e54);
    vec3 _e57 = weft_aniso_to_frame(frame_4, lit.l);
    vec3 lf_1 = vec3(_e57);
    vec3 _e60 = weft_aniso_to_frame(frame_4, lit.h);
    vec3 hf_1 = vec3(_e60);
    vec2 _e62 = weft_aniso_alpha_kulla(r_low, anisotropy_2);
    vec2 _e63 = weft_aniso_alpha_kulla(r2_low, anisotropy_2);
    vec2 _e64 = satin_lobes_low(vf_1, lf_1, hf_1, _e62, _e63);
    float lobe1_ = _e64.x;
    float lobe2_ = _e64.y;
    vec3 _e67 = weft_half_f_schlick(f0_3, v_dot_h_2);
    vec3 specular_1 = (((vec3((w1_ * _e67)) * float(lobe1_)) + (vec3((w2_ * _e67)) * float(lobe2_))) * (noise * light));
    vec3 _e83 = weft_half_f_schlick(f0_3, float(n_dot_v_1));
    vec3 diffuse_kd_1 = max((vec3(1.0) - ((w1_ + w2_) * _e83)), vec3(0.0));
    vec2 _e89 = weft_env_brdf_lut(n_dot_v_1, roughness_7);
    vec3 _e90 = weft_env_brdf_from_lut(f0_in, _e89);
    vec3 e1_ = (vec3(_e90) * w1_);
    vec2 _e93 = weft_env_brdf_lut(n_dot_v_1, roughness2_);
    vec3 _e94 = weft_env_brdf_from_lut(f0_in, _e93);
    vec3 e2_ = (vec3(_e94) * w2_);
    float r_env = ((max(e1_.x, max(e1_.y, e1_.z)) >= max(e2_.x, max(e2_.y, e2_.z))) ? roughness_7 : roughness2_);
    vec3 _e109 = satin_env(frame_4, v_5, anisotropy_2, r_env);
    vec3 indirect_specular_1 = ((_e109 * vec3((e1_ + e2_))) * noise);
    vec3 ambient_kd_1 = max(((vec3(1.0) - e1_) - e2_), vec3(0.0));
    vec3 direct = (((diffuse_albedo * vec3((diffuse_kd_1 * (n_dot_l * 0.31830987)))) * light) + specular_1);
    vec3 _e129 = weft_sh_irradiance(n_6);
    vec3 indirect = ((indirect_specular_1 * ao) + (((_e129 * ao) * vec3(ambient_kd_1)) * diffuse_albedo));
    return (direct + indirect);
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    vec3 n = vec3(0.0);
    SatinLayers layers = SatinLayers(vec2(0.0), vec2(0.0));
    vec3 specular = vec3(0.0);
    vec3 diffuse_kd = vec3(0.0);
    vec3 indirect_specular = vec3(0.0);
    vec3 ambient_kd = vec3(0.0);
    vec3 bent = vec3(0.0);
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
    float roughness_8 = clamp((_e23 * rmo.x), 0.0, 1.0);
    float _e29 = _group_1_binding_0_fs.metallic;
    float metallic = clamp((_e29 * rmo.y), 0.0, 1.0);
    float _e36 = _group_1_binding_0_fs.occlusion_strength;
    float ao_1 = clamp(mix(1.0, rmo.z, _e36), 0.0, 1.0);
    float _e42 = _group_1_binding_0_fs.anisotropy;
    float anisotropy_3 = clamp(_e42, -1.0, 1.0);
    float _e48 = _group_1_binding_0_fs.second_layer_width;
    float width = clamp(_e48, 1.0, 4.0);
    float roughness2_1 = min((roughness_8 * width), 1.0);
    vec4 _e58 = _group_1_binding_0_fs.noise_map_st;
    vec2 _e59 = weft_transform_uv(in_1.uv0_, _e58);
    vec4 _e62 = texture(_group_1_binding_6_fs, vec2(_e59));
    float noise_1 = (0.5 + (0.5 * clamp(_e62.x, 0.0, 1.0)));
    WeftSurface _e71 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_7 = _e71.v;
    n = _e71.n;
    {
        vec4 _e77 = texture(_group_1_binding_4_fs, vec2(_e5));
        vec3 texel_2 = _e77.xyz;
        vec3 _e79 = n;
        float _e83 = _group_1_binding_0_fs.normal_strength;
        vec3 _e84 = weft_mapped_normal(_e79, in_1.world_tangent, texel_2, _e83);
        n = _e84;
    }
    vec3 _e85 = n;
    mat3x3 _e87 = weft_tangent_frame(_e85, in_1.world_tangent);
    vec3 _e88 = n;
    WeftLightGeometry _e89 = weft_main_light_geometry(_e88, v_7);
    vec3 _e90 = weft_main_light_radiance();
    vec2 _e93 = weft_aniso_alpha_kulla(roughness_8, anisotropy_3);
    layers.narrow = _e93;
    vec2 _e95 = weft_aniso_alpha_kulla(roughness2_1, anisotropy_3);
    layers.wide = _e95;
    vec3 f0_4 = mix(vec3(0.04), base, metallic);
    vec3 diffuse_albedo_1 = (base * (1.0 - metallic));
    vec4 _e104 = _group_1_binding_0_fs.specular_color;
    vec3 c1_1 = clamp(_e104.xyz, vec3(0.0), vec3(1.0));
    vec4 _e109 = _group_1_binding_0_fs.second_specular_color;
    vec3 c2_1 = clamp(_e109.xyz, vec3(0.0), vec3(1.0));
    vec3 _e113 = weft_f_schlick(f0_4, _e89.v_dot_h);
    {
        vec3 _e114 = n;
        vec3 _e115 = satin_low(_e87, _e114, v_7, _e89, f0_4, diffuse_albedo_1, roughness_8, roughness2_1, anisotropy_3, c1_1, c2_1, noise_1, ao_1, _e90);
        _fs2p_location0 = vec4(clamp(_e115, vec3(0.0), vec3(65504.0)), alpha);
        return;
    }
}

