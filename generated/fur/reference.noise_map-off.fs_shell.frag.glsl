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

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_5_fs;

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 2) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 3) uniform sampler2D _group_1_binding_4_fs;

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

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
}

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
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
    float t_1 = ((1.0 - r) * (1.0 - r));
    float a = mix(21.5473, 25.3245, t_1);
    float b = mix(3.82987, 3.32435, t_1);
    float c_1 = mix(0.19823, 0.16801, t_1);
    float d = mix(-1.9776, -1.27393, t_1);
    float e_1 = mix(-4.32054, -4.85967, t_1);
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

float weft_specular_mip(float roughness) {
    float r_2 = clamp(roughness, 0.0, 1.0);
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r_2 * (1.7 - (0.7 * r_2))) * max_mip);
}

vec3 weft_prefiltered_radiance(vec3 dir, float roughness_1) {
    float _e4 = weft_specular_mip(roughness_1);
    vec4 c_3 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_3.xyz, vec3(0.0));
}

float weft_sheen_albedo(float n_dot_x, float sheen_roughness_4) {
    float _e3 = weft_sheen_clamp_roughness(sheen_roughness_4);
    vec2 uv_1 = vec2(clamp(n_dot_x, 0.0, 1.0), _e3);
    vec4 _e8 = textureLod(_group_0_binding_5_fs, vec2(uv_1), 0.0);
    return clamp(_e8.x, 0.0, 1.0);
}

WeftSurface weft_surface(vec3 world_position_1, vec3 world_normal) {
    vec3 _e6 = weft_view_direction(world_position_1, vec3(0.0, 0.0, 1.0));
    vec3 _e7 = weft_safe_normalize(world_normal, _e6);
    return WeftSurface(_e6, _e7);
}

WeftLightGeometry weft_main_light_geometry(vec3 n_1, vec3 v_2) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_2), n_1);
    float _e6 = weft_clamp_cos(dot(n_1, v_2));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_1, _e2), 0.0, 1.0), clamp(dot(n_1, _e4), 0.0, 1.0), clamp(dot(v_2, _e4), 0.0, 1.0));
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

uint fur_pcg(uint x_2) {
    uint state = ((x_2 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return ((word >> 22u) ^ word);
}

float fur_strand_cell(vec2 x_3, uint salt) {
    vec2 cell = floor(x_3);
    uvec2 c_4 = uvec2(ivec2((cell - (65536.0 * floor((cell / vec2(65536.0)))))));
    uint _e15 = fur_pcg((c_4.y + salt));
    uint _e17 = fur_pcg((c_4.x + _e15));
    uint _e18 = fur_pcg(_e17);
    uint _e19 = fur_pcg(_e18);
    vec2 jitter = (((vec2(float((_e17 & 65535u)), float((_e18 & 65535u))) / vec2(65535.0)) - vec2(0.5)) * 0.3);
    float peak = (0.7 + ((0.3 * float((_e19 & 65535u))) / 65535.0));
    float r_3 = length((fract(x_3) - (vec2(0.5) + jitter)));
    return (clamp((1.0 - (r_3 / 0.35)), 0.0, 1.0) * peak);
}

float fur_procedural_noise(vec2 x_4) {
    vec2 rotated = ((vec2(((0.8 * x_4.x) - (0.6 * x_4.y)), ((0.6 * x_4.x) + (0.8 * x_4.y))) * 1.31) + vec2(17.3, 5.9));
    float _e23 = fur_strand_cell(x_4, 0u);
    float _e25 = fur_strand_cell(rotated, 2654435769u);
    return max(_e23, _e25);
}

float fur_noise(vec2 uv0_) {
    vec4 _e3 = _group_1_binding_0_fs.noise_map_st;
    vec2 _e4 = fur_transform_uv(uv0_, _e3);
    vec4 _e7 = _group_1_binding_0_fs.noise_map_st;
    vec2 _e12 = _group_1_binding_0_fs.strand_density;
    vec4 _e16 = _group_1_binding_0_fs.noise_map_st;
    float _e19 = fur_procedural_noise((((uv0_ * _e7.xy) * _e12) + _e16.zw));
    return _e19;
}

vec2 fur_kajiya_kay_cone(vec3 t, vec3 l, vec3 v_3) {
    float t_dot_l = clamp(dot(t, l), -1.0, 1.0);
    float t_dot_v = clamp(dot(t, v_3), -1.0, 1.0);
    float sin_l = sqrt(max((1.0 - (t_dot_l * t_dot_l)), 0.0));
    float sin_v = sqrt(max((1.0 - (t_dot_v * t_dot_v)), 0.0));
    return vec2(max(((sin_l * sin_v) - (t_dot_l * t_dot_v)), 0.0), sin_l);
}

vec4 fur_shade(FurVaryings in_5) {
    vec3 color = vec3(0.0);
    vec4 _e4 = _group_1_binding_0_fs.base_map_st;
    vec2 _e5 = fur_transform_uv(in_5.uv0_, _e4);
    vec4 _e8 = _group_1_binding_0_fs.base_color;
    vec4 _e11 = texture(_group_1_binding_3_fs, vec2(_e5));
    vec4 base_rgba = (_e8 * _e11);
    vec4 _e15 = texture(_group_1_binding_4_fs, vec2(_e5));
    float spot = clamp(_e15.x, 0.0, 1.0);
    vec4 _e22 = _group_1_binding_0_fs.spot_color;
    vec3 base = mix(clamp(base_rgba.xyz, vec3(0.0), vec3(1.0)), clamp(_e22.xyz, vec3(0.0), vec3(1.0)), spot);
    float alpha = clamp(base_rgba.w, 0.0, 1.0);
    {
        float _e31 = _group_1_binding_0_fs.metallic;
        float metallic = clamp(_e31, 0.0, 1.0);
        float _e35 = _group_1_binding_0_fs.smoothness;
        float smoothness_1 = clamp(_e35, 0.0, 1.0);
        float roughness_2 = (1.0 - smoothness_1);
        WeftSurface _e41 = weft_surface(in_5.world_position, in_5.world_normal);
        vec3 v_4 = _e41.v;
        vec3 n_2 = _e41.n;
        vec3 _e45 = weft_safe_normalize(in_5.strand, n_2);
        WeftLightGeometry _e46 = weft_main_light_geometry(n_2, v_4);
        float l_dot_h = clamp(dot(_e46.l, _e46.h), 0.0, 1.0);
        vec3 f0_1 = mix(vec3(0.04), base, metallic);
        vec3 diffuse_albedo = (base * (1.0 - metallic));
        vec3 _e57 = weft_main_light_radiance();
        vec3 _e58 = weft_sh_irradiance(n_2);
        {
            vec4 _e61 = _group_1_binding_0_fs.sheen_color;
            vec3 sheen_color_3 = clamp((f0_1 + max(_e61.xyz, vec3(0.0))), vec3(0.0), vec3(1.0));
            float _e68 = weft_sheen_clamp_roughness(roughness_2);
            float _e70 = weft_sheen_albedo(_e46.n_dot_v, _e68);
            float _e72 = weft_sheen_albedo(_e46.n_dot_l, _e68);
            float _e73 = weft_sheen_albedo_scaling_view(sheen_color_3, _e70);
            float _e74 = weft_sheen_albedo_scaling(sheen_color_3, _e70, _e72);
            vec3 _e78 = weft_sheen_charlie(sheen_color_3, _e46.n_dot_h, _e46.n_dot_v, _e46.n_dot_l, _e68);
            float _e79 = fur_strand_exponent(smoothness_1);
            vec2 _e81 = fur_kajiya_kay_cone(_e45, _e46.l, v_4);
            float strand = (pow(_e81.x, _e79) * _e81.y);
            vec3 _e86 = weft_f_schlick(f0_1, l_dot_h);
            vec4 _e89 = _group_1_binding_0_fs.strand_color;
            vec3 strand_color = (max(_e89.xyz, vec3(0.0)) * _e86);
            float _e97 = _group_1_binding_0_fs.strand_strength;
            float _e100 = fur_strand_norm(_e79);
            vec3 strand_lobe = (strand_color * (((max(_e97, 0.0) * _e100) * strand) * _e46.n_dot_l));
            vec3 _e106 = weft_diffuse_lambert(diffuse_albedo);
            vec3 base_direct = (_e106 * (_e74 * _e46.n_dot_l));
            vec3 direct = (((_e78 + base_direct) + strand_lobe) * _e57);
            vec3 _e115 = weft_prefiltered_radiance(reflect(-(v_4), n_2), _e68);
            vec3 env_sheen = ((_e115 * sheen_color_3) * _e70);
            color = ((direct + ((_e58 * diffuse_albedo) * _e73)) + env_sheen);
        }
    }
    float _e124 = _group_1_binding_0_fs.fur_occlusion;
    float occlusion = (1.0 - (clamp(_e124, 0.0, 1.0) * (1.0 - in_5.offset)));
    vec3 _e132 = color;
    vec3 radiance = clamp((_e132 * occlusion), vec3(0.0), vec3(65504.0));
    return vec4(radiance, alpha);
}

float fur_fade_n_dot_v(FurVaryings in_6) {
    WeftSurface _e3 = weft_surface(in_6.world_position, in_6.world_normal);
    return clamp(dot(_e3.n, _e3.v), 0.0, 1.0);
}

vec4 fur_shell(FurVaryings in_7) {
    float _e2 = fur_noise(in_7.uv0_);
    float o = clamp(in_7.offset, 0.0, 1.0);
    uint _e8 = _group_1_binding_0_fs.tapered_tips;
    float shape = ((_e8 != 0u) ? (o * o) : o);
    float _e14 = _group_1_binding_0_fs.cutoff_start;
    float _e18 = _group_1_binding_0_fs.cutoff_end;
    float threshold = mix(clamp(_e14, 0.0, 1.0), clamp(_e18, 0.0, 1.0), shape);
    float _e21 = fwidth(_e2);
    float width = max(_e21, 0.001);
    float coverage = (clamp((((_e2 - threshold) / width) + 0.5), 0.0, 1.0) * step(1e-6, _e2));
    vec4 _e32 = fur_shade(in_7);
    float _e35 = _group_1_binding_0_fs.edge_fade;
    float _e37 = fur_fade_n_dot_v(in_7);
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

