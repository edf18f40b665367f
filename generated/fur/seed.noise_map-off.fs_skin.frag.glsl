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

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 0) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 1) uniform sampler2D _group_1_binding_4_fs;

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

float weft_pow4_(float x) {
    float x2_ = (x * x);
    return (x2_ * x2_);
}

float weft_pow5_(float x_1) {
    float x2_1 = (x_1 * x_1);
    return ((x2_1 * x2_1) * x_1);
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

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
}

float weft_v_schlick_ggx(float n_dot_v, float n_dot_l, float roughness_1) {
    float _e3 = weft_clamp_roughness(roughness_1);
    float a = (_e3 * _e3);
    float k = (((a + 1.0) * (a + 1.0)) * 0.125);
    float gv = ((clamp(n_dot_v, 0.0, 1.0) * (1.0 - k)) + k);
    float gl = ((clamp(n_dot_l, 0.0, 1.0) * (1.0 - k)) + k);
    return (0.25 / (gv * gl));
}

vec3 weft_diffuse_lambert(vec3 albedo) {
    return (albedo * WEFT_INV_PI);
}

float weft_fabric_d(float n_dot_h) {
    float x_5 = (1.0 - clamp(n_dot_h, 0.0, 1.0));
    return (((0.96 * x_5) * x_5) + 0.057);
}

float weft_fabric_scatter_fresnel_lerp(float n_dot_v_1, float scale) {
    float x_6 = (1.0 - clamp(n_dot_v_1, 0.0, 1.0));
    float _e5 = weft_pow4_(x_6);
    return mix(_e5, (0.4 * x_6), clamp(scale, 0.0, 1.0));
}

vec3 weft_fabric_scatter(vec3 scatter_color, float n_dot_l_1, float n_dot_v_2, float scale_1) {
    float wrap = ((clamp(n_dot_l_1, 0.0, 1.0) * 0.5) + 0.5);
    float _e12 = weft_fabric_scatter_fresnel_lerp(n_dot_v_2, scale_1);
    return (max(scatter_color, vec3(0.0)) * (wrap * _e12));
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

WeftLightGeometry weft_main_light_geometry(vec3 n_1, vec3 v_1) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_1), n_1);
    float _e6 = weft_clamp_cos(dot(n_1, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_1, _e2), 0.0, 1.0), clamp(dot(n_1, _e4), 0.0, 1.0), clamp(dot(v_1, _e4), 0.0, 1.0));
}

vec2 fur_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

uint fur_pcg(uint x_2) {
    uint state = ((x_2 * 747796405u) + 2891336453u);
    uint word = (((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u);
    return ((word >> 22u) ^ word);
}

float fur_strand_cell(vec2 x_3, uint salt) {
    vec2 cell = floor(x_3);
    uvec2 c_1 = uvec2(ivec2((cell - (65536.0 * floor((cell / vec2(65536.0)))))));
    uint _e15 = fur_pcg((c_1.y + salt));
    uint _e17 = fur_pcg((c_1.x + _e15));
    uint _e18 = fur_pcg(_e17);
    uint _e19 = fur_pcg(_e18);
    vec2 jitter = (((vec2(float((_e17 & 65535u)), float((_e18 & 65535u))) / vec2(65535.0)) - vec2(0.5)) * 0.3);
    float peak = (0.7 + ((0.3 * float((_e19 & 65535u))) / 65535.0));
    float r = length((fract(x_3) - (vec2(0.5) + jitter)));
    return (clamp((1.0 - (r / 0.35)), 0.0, 1.0) * peak);
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
        float smoothness = clamp(_e35, 0.0, 1.0);
        float roughness_2 = (1.0 - smoothness);
        WeftSurface _e41 = weft_surface(in_5.world_position, in_5.world_normal);
        vec3 v_2 = _e41.v;
        vec3 n_2 = _e41.n;
        vec3 _e45 = weft_safe_normalize(in_5.strand, n_2);
        WeftLightGeometry _e46 = weft_main_light_geometry(n_2, v_2);
        float l_dot_h = clamp(dot(_e46.l, _e46.h), 0.0, 1.0);
        vec3 f0_1 = mix(vec3(0.04), base, metallic);
        vec3 diffuse_albedo = (base * (1.0 - metallic));
        vec3 _e57 = weft_main_light_radiance();
        vec3 _e58 = weft_sh_irradiance(n_2);
        {
            float _e61 = weft_v_schlick_ggx(_e46.n_dot_v, _e46.n_dot_l, roughness_2);
            vec3 _e62 = weft_f_schlick(f0_1, l_dot_h);
            float _e64 = weft_fabric_d(_e46.n_dot_h);
            vec3 specular = ((_e64 * _e61) * _e62);
            vec3 _e67 = weft_diffuse_lambert(diffuse_albedo);
            vec4 _e70 = _group_1_binding_0_fs.sheen_color;
            float _e76 = _group_1_binding_0_fs.scatter_scale;
            vec3 _e77 = weft_fabric_scatter(_e70.xyz, _e46.n_dot_l, _e46.n_dot_v, _e76);
            color = (((((_e67 + specular) * _e57) * _e46.n_dot_l) + (_e58 * diffuse_albedo)) + _e77);
        }
    }
    float _e87 = _group_1_binding_0_fs.fur_occlusion;
    float occlusion = (1.0 - (clamp(_e87, 0.0, 1.0) * (1.0 - in_5.offset)));
    vec3 _e95 = color;
    vec3 radiance = clamp((_e95 * occlusion), vec3(0.0), vec3(65504.0));
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
    FurVaryings in_2 = FurVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3, _vs2fs_location4, _vs2fs_location5, _vs2fs_location6, _vs2fs_location7, _vs2fs_location8, _vs2fs_location9);
    vec4 _e1 = fur_shade(in_2);
    _fs2p_location0 = vec4(_e1.xyz, 1.0);
    return;
}

