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
    vec4 base_map_st;
    float metallic;
    float smoothness;
    vec4 spot_color;
    vec4 noise_map_st;
    vec2 strand_density;
    float fur_length;
    float height_scale;
    float fur_occlusion;
    float cutoff_start;
    float cutoff_end;
    float edge_fade;
    uint tapered_tips;
    int shell_count;
    vec3 force_direction;
    float force_strength;
    float force_map_scale;
    vec4 sheen_color;
    float scatter_scale;
    vec4 strand_color;
    float strand_strength;
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
struct FurInput {
    vec3 position;
    vec3 normal;
    vec2 uv0_;
};
struct FurVaryings {
    vec4 clip_position;
    vec3 world_position;
    vec3 world_normal;
    vec3 strand;
    vec2 uv0_;
    float offset;
    vec4 light_diffuse;
    vec4 light_ambient;
    vec4 light_sheen;
    vec4 light_strand;
    float light_n_dot_v;
};
struct FurLight {
    vec4 diffuse;
    vec4 ambient;
    vec4 sheen;
    vec4 strand;
    float n_dot_v;
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
const float FUR_SEED_SHELLS = 20.0;

layout(std140, binding = 1) uniform WeftMaterial_block_0Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 2) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 3) uniform sampler2D _group_1_binding_4_fs;

layout(binding = 4) uniform sampler2D _group_1_binding_5_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec3 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 4) smooth in float _vs2fs_location4;
layout(location = 5) smooth in vec4 _vs2fs_location5;
layout(location = 6) smooth in vec4 _vs2fs_location6;
layout(location = 7) smooth in vec4 _vs2fs_location7;
layout(location = 8) smooth in vec4 _vs2fs_location8;
layout(location = 9) smooth in float _vs2fs_location9;
layout(location = 0) out vec4 _fs2p_location0;

float weft_pow5_(float x) {
    float x2_ = (x * x);
    return ((x2_ * x2_) * x);
}

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

float weft_sheen_l(float x_1, float r) {
    float t = ((1.0 - r) * (1.0 - r));
    float a = mix(21.5473, 25.3245, t);
    float b = mix(3.82987, 3.32435, t);
    float c_1 = mix(0.19823, 0.16801, t);
    float d = mix(-1.9776, -1.27393, t);
    float e_1 = mix(-4.32054, -4.85967, t);
    return (((a / (1.0 + (b * pow(max(x_1, 0.0), c_1)))) + (d * x_1)) + e_1);
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

float weft_sheen_albedo_scaling(vec3 sheen_color_1, float e_v, float e_l) {
    float _e3 = weft_max3_(sheen_color_1);
    float c_2 = clamp(_e3, 0.0, 1.0);
    return clamp(min((1.0 - (c_2 * clamp(e_v, 0.0, 1.0))), (1.0 - (c_2 * clamp(e_l, 0.0, 1.0)))), 0.0, 1.0);
}

float weft_sheen_albedo_scaling_view(vec3 sheen_color_2, float e_v_1) {
    float _e2 = weft_max3_(sheen_color_2);
    return clamp((1.0 - (clamp(_e2, 0.0, 1.0) * clamp(e_v_1, 0.0, 1.0))), 0.0, 1.0);
}

vec2 fur_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

float fur_strand_exponent(float smoothness) {
    return exp2((1.0 + (9.0 * clamp(smoothness, 0.0, 1.0))));
}

float fur_strand_norm(float p) {
    return sqrt(((((2.0 * p) + 1.0) * 0.25) * WEFT_INV_PI));
}

float fur_noise(vec2 uv0_) {
    vec4 _e3 = _group_1_binding_0_fs.noise_map_st;
    vec2 _e4 = fur_transform_uv(uv0_, _e3);
    {
        vec4 _e7 = texture(_group_1_binding_5_fs, vec2(_e4));
        return clamp(_e7.x, 0.0, 1.0);
    }
}

vec3 fur_shade_fast(FurVaryings in_5, vec3 base) {
    float _e4 = _group_1_binding_0_fs.metallic;
    float metallic = clamp(_e4, 0.0, 1.0);
    vec3 f0_ = mix(vec3(0.04), base, metallic);
    vec3 diffuse_albedo = (base * (1.0 - metallic));
    vec4 _e14 = _group_1_binding_0_fs.sheen_color;
    vec3 sheen_color_3 = clamp((f0_ + max(_e14.xyz, vec3(0.0))), vec3(0.0), vec3(1.0));
    float _e25 = weft_sheen_albedo_scaling(sheen_color_3, in_5.light_diffuse.w, in_5.light_ambient.w);
    float _e28 = weft_sheen_albedo_scaling_view(sheen_color_3, in_5.light_diffuse.w);
    vec3 fresnel = (f0_ + ((vec3(1.0) - f0_) * in_5.light_sheen.w));
    vec4 _e38 = _group_1_binding_0_fs.strand_color;
    vec3 strand_color = (max(_e38.xyz, vec3(0.0)) * fresnel);
    float _e51 = _group_1_binding_0_fs.smoothness;
    float _e52 = fur_strand_exponent(_e51);
    float cone_p = pow(max(cos(in_5.light_strand.w), 0.0), _e52);
    return (((diffuse_albedo * ((in_5.light_diffuse.xyz * _e25) + (in_5.light_ambient.xyz * _e28))) + (sheen_color_3 * in_5.light_sheen.xyz)) + (strand_color * (in_5.light_strand.xyz * cone_p)));
}

vec4 fur_shade(FurVaryings in_6) {
    vec3 color = vec3(0.0);
    vec4 _e4 = _group_1_binding_0_fs.base_map_st;
    vec2 _e5 = fur_transform_uv(in_6.uv0_, _e4);
    vec4 _e8 = _group_1_binding_0_fs.base_color;
    vec4 _e11 = texture(_group_1_binding_3_fs, vec2(_e5));
    vec4 base_rgba = (_e8 * _e11);
    vec4 _e15 = texture(_group_1_binding_4_fs, vec2(_e5));
    float spot = clamp(_e15.x, 0.0, 1.0);
    vec4 _e22 = _group_1_binding_0_fs.spot_color;
    vec3 base_1 = mix(clamp(base_rgba.xyz, vec3(0.0), vec3(1.0)), clamp(_e22.xyz, vec3(0.0), vec3(1.0)), spot);
    float alpha = clamp(base_rgba.w, 0.0, 1.0);
    {
        vec3 _e29 = fur_shade_fast(in_6, base_1);
        color = _e29;
    }
    float _e32 = _group_1_binding_0_fs.fur_occlusion;
    float occlusion = (1.0 - (clamp(_e32, 0.0, 1.0) * (1.0 - in_6.offset)));
    vec3 _e40 = color;
    vec3 radiance = clamp((_e40 * occlusion), vec3(0.0), vec3(65504.0));
    return vec4(radiance, alpha);
}

float fur_fade_n_dot_v(FurVaryings in_7) {
    {
        return in_7.light_n_dot_v;
    }
}

vec4 fur_shell(FurVaryings in_8) {
    float _e2 = fur_noise(in_8.uv0_);
    float o = clamp(in_8.offset, 0.0, 1.0);
    uint _e8 = _group_1_binding_0_fs.tapered_tips;
    float shape = ((_e8 != 0u) ? (o * o) : o);
    float _e14 = _group_1_binding_0_fs.cutoff_start;
    float _e18 = _group_1_binding_0_fs.cutoff_end;
    float threshold = mix(clamp(_e14, 0.0, 1.0), clamp(_e18, 0.0, 1.0), shape);
    float _e21 = fwidth(_e2);
    float width = max(_e21, 0.001);
    float coverage = (clamp((((_e2 - threshold) / width) + 0.5), 0.0, 1.0) * step(1e-6, _e2));
    vec4 _e32 = fur_shade(in_8);
    float _e35 = _group_1_binding_0_fs.edge_fade;
    float _e37 = fur_fade_n_dot_v(in_8);
    float fade = (1.0 - (clamp(_e35, 0.0, 1.0) * (1.0 - _e37)));
    float a_1 = clamp((((coverage * (1.0 - o)) * fade) * _e32.w), 0.0, 1.0);
    int _e53 = _group_1_binding_0_fs.shell_count;
    float slab = (FUR_SEED_SHELLS / float(max(_e53, 1)));
    float keep = (1.0 - a_1);
    float alpha_1 = (1.0 - ((keep <= 0.0) ? 0.0 : pow(keep, slab)));
    return vec4(_e32.xyz, alpha_1);
}

void main() {
    FurVaryings in_3 = FurVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3, _vs2fs_location4, _vs2fs_location5, _vs2fs_location6, _vs2fs_location7, _vs2fs_location8, _vs2fs_location9);
    vec4 _e1 = fur_shell(in_3);
    _fs2p_location0 = _e1;
    return;
}

