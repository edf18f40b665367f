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
    float normal_strength;
    float specular_strength;
    vec4 emissive;
    float emissive_strength;
    float alpha_cutoff;
    float sphere_strength;
    vec4 base_map_st;
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
const uint SPHERE_MAP_OFF = 0u;
const uint SPHERE_MAP_ADD = 1u;
const uint SPHERE_MAP_MULTIPLY = 2u;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const uint TIER_LOW = 3u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;
const float WEFT_MIN_ROUGHNESS_HALF = 0.089;
const float WEFT_MIN_N_DOT_HALF = 0.001;
const float WEFT_MIN_ALPHA_HALF = 0.007921;
const bool ALPHA_TEST = false;
const bool EMISSION = false;

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_3_fs;

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 2) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 3) uniform sampler2D _group_1_binding_4_fs;

layout(binding = 4) uniform sampler2D _group_1_binding_6_fs;

layout(binding = 5) uniform samplerCube _group_1_binding_7_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

float weft_clamp_cos(float c) {
    return clamp(c, WEFT_MIN_N_DOT, 1.0);
}

vec3 weft_safe_normalize(vec3 v, vec3 fallback) {
    float len2_ = dot(v, v);
    return ((len2_ > 1e-20) ? (v * inversesqrt(max(len2_, 1e-20))) : fallback);
}

vec3 weft_env_brdf_from_lut(vec3 f0_, vec2 scale_bias) {
    vec2 sb = clamp(scale_bias, vec2(0.0), vec2(1.0));
    return ((f0_ * sb.x) + vec3(sb.y));
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

vec3 weft_sh_irradiance(vec3 n_1) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_fs.sh;
    e = (sh[0].xyz * 0.282095);
    vec3 _e9 = e;
    e = (_e9 + (sh[1].xyz * (0.488603 * n_1.y)));
    vec3 _e17 = e;
    e = (_e17 + (sh[2].xyz * (0.488603 * n_1.z)));
    vec3 _e25 = e;
    e = (_e25 + (sh[3].xyz * (0.488603 * n_1.x)));
    vec3 _e33 = e;
    e = (_e33 + (sh[4].xyz * ((1.092548 * n_1.x) * n_1.y)));
    vec3 _e43 = e;
    e = (_e43 + (sh[5].xyz * ((1.092548 * n_1.y) * n_1.z)));
    vec3 _e53 = e;
    e = (_e53 + (sh[6].xyz * (0.315392 * (((3.0 * n_1.z) * n_1.z) - 1.0))));
    vec3 _e67 = e;
    e = (_e67 + (sh[7].xyz * ((1.092548 * n_1.x) * n_1.z)));
    vec3 _e77 = e;
    e = (_e77 + (sh[8].xyz * (0.546274 * ((n_1.x * n_1.x) - (n_1.y * n_1.y)))));
    vec3 _e91 = e;
    return max(_e91, vec3(0.0));
}

float weft_specular_mip(float roughness) {
    float r = clamp(roughness, 0.0, 1.0);
    float _e5 = _group_0_binding_0_fs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
}

vec3 weft_prefiltered_radiance(vec3 dir, float roughness_1) {
    float _e4 = weft_specular_mip(roughness_1);
    vec4 c_1 = textureLod(_group_0_binding_1_fs, vec3(dir), _e4);
    return max(c_1.xyz, vec3(0.0));
}

vec2 weft_env_brdf_lut(float n_dot_v, float roughness_2) {
    vec2 uv_2 = vec2(clamp(n_dot_v, 0.0, 1.0), clamp(roughness_2, 0.0, 1.0));
    vec4 _e8 = textureLod(_group_0_binding_3_fs, vec2(uv_2), 0.0);
    return _e8.xy;
}

vec3 weft_sphere_map_direction(vec3 world_normal, vec3 world_position_1) {
    mat4x4 view = _group_0_binding_0_fs.view;
    mat3x3 view3_ = mat3x3(view[0].xyz, view[1].xyz, view[2].xyz);
    vec3 _e17 = weft_safe_normalize((view3_ * world_normal), vec3(0.0, 0.0, 1.0));
    vec3 p_vs = (view * vec4(world_position_1, 1.0)).xyz;
    vec3 _e26 = weft_safe_normalize(p_vs, vec3(0.0, 0.0, -1.0));
    return reflect(_e26, _e17);
}

WeftSurface weft_surface_two_sided(vec3 world_position_2, vec3 world_normal_1, bool front_facing_1) {
    vec3 _e7 = weft_view_direction(world_position_2, vec3(0.0, 0.0, 1.0));
    vec3 facing = (front_facing_1 ? world_normal_1 : -(world_normal_1));
    vec3 _e10 = weft_safe_normalize(facing, _e7);
    return WeftSurface(_e7, _e10);
}

WeftLightGeometry weft_main_light_geometry(vec3 n_2, vec3 v_1) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_1), n_2);
    float _e6 = weft_clamp_cos(dot(n_2, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_2, _e2), 0.0, 1.0), clamp(dot(n_2, _e4), 0.0, 1.0), clamp(dot(v_1, _e4), 0.0, 1.0));
}

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

float weft_half_min_max(float x) {
    return min(x, 65504.0);
}

float weft_half_pow5_(float x_1) {
    float x2_ = (x_1 * x_1);
    return ((x2_ * x2_) * x_1);
}

float weft_half_d_ggx(float one_minus_n_dot_h2_, float n_dot_h, float alpha) {
    float a = (n_dot_h * alpha);
    float k = (alpha / (one_minus_n_dot_h2_ + (a * a)));
    float _e10 = weft_half_min_max(((k * k) * 0.31830987));
    return _e10;
}

float weft_half_v_smith_ggx_correlated_newton_nl(float n_dot_v_1, float n_dot_l, float alpha_1) {
    vec2 x_2 = vec2(max(n_dot_v_1, 0.001), n_dot_l);
    float alpha2_ = (alpha_1 * alpha_1);
    vec2 g = mix(x_2, vec2(1.0), alpha_1);
    float inv_gg = (1.0 / (g.x * g.y));
    vec2 q = (x_2 + ((alpha2_ * (vec2(1.0) - x_2)) * (g.yx * inv_gg)));
    float denominator = ((x_2.y * q.x) + (x_2.x * q.y));
    return ((0.5 * n_dot_l) / max(denominator, 0.0001));
}

vec3 weft_half_f_schlick(vec3 f0_1, float v_dot_h) {
    float _e7 = weft_half_pow5_((1.0 - v_dot_h));
    return (f0_1 + ((vec3(1.0) - f0_1) * _e7));
}

vec3 standard_emission(vec2 uv_1) {
    if (EMISSION) {
        float _e4 = _group_1_binding_0_fs.emissive_strength;
        float strength = max(_e4, 0.0);
        vec4 _e9 = _group_1_binding_0_fs.emissive;
        vec3 emissive = max(_e9.xyz, vec3(0.0));
        vec4 _e17 = texture(_group_1_binding_3_fs, vec2(uv_1));
        return ((emissive * strength) * _e17.xyz);
    }
    return vec3(0.0);
}

vec3 standard_low(vec3 n_3, vec3 v_2, WeftLightGeometry lit, vec3 f0_in, vec3 diffuse_albedo, float roughness_in, float ao, float specular_strength) {
    vec3 direct_n_dot_l = vec3(0.0);
    vec3 indirect_specular_1 = vec3(0.0);
    float n_dot_v_2 = float(lit.n_dot_v);
    float n_dot_l_1 = float(lit.n_dot_l);
    float n_dot_h_1 = float(lit.n_dot_h);
    float v_dot_h_1 = float(lit.v_dot_h);
    float one_minus_n_dot_h2_1 = float(((1.0 - lit.n_dot_h) * (1.0 + lit.n_dot_h)));
    float roughness_3 = float(max(roughness_in, WEFT_MIN_ROUGHNESS_HALF));
    float alpha_3 = (roughness_3 * roughness_3);
    vec3 f0_2 = vec3(f0_in);
    vec2 _e30 = weft_env_brdf_lut(lit.n_dot_v, roughness_in);
    vec3 _e31 = weft_env_brdf_from_lut(f0_in, _e30);
    vec3 env_brdf_1 = vec3(_e31);
    vec3 kd = max((vec3(1.0) - env_brdf_1), vec3(0.0));
    direct_n_dot_l = (vec3((kd * (n_dot_l_1 * 0.31830987))) * diffuse_albedo);
    if ((specular_strength > 0.0)) {
        float _e50 = weft_half_d_ggx(one_minus_n_dot_h2_1, n_dot_h_1, alpha_3);
        float _e51 = weft_half_v_smith_ggx_correlated_newton_nl(n_dot_v_2, n_dot_l_1, alpha_3);
        vec3 _e52 = weft_half_f_schlick(f0_2, v_dot_h_1);
        float _e54 = weft_half_min_max((_e50 * _e51));
        vec3 _e55 = direct_n_dot_l;
        direct_n_dot_l = (_e55 + (vec3((_e52 * _e54)) * specular_strength));
        vec3 _e62 = weft_prefiltered_radiance(reflect(-(v_2), n_3), roughness_in);
        indirect_specular_1 = ((_e62 * vec3(env_brdf_1)) * (ao * specular_strength));
    }
    vec3 _e67 = direct_n_dot_l;
    vec3 _e68 = weft_main_light_radiance();
    vec3 direct = (_e67 * _e68);
    vec3 _e70 = weft_sh_irradiance(n_3);
    vec3 indirect_diffuse = (((_e70 * ao) * vec3(kd)) * diffuse_albedo);
    vec3 _e75 = indirect_specular_1;
    return ((direct + _e75) + indirect_diffuse);
}

vec3 standard_sphere_map(vec3 color_in, vec3 n_4, vec3 world_position_3) {
    vec3 color = vec3(0.0);
    color = color_in;
    {
        vec3 _e4 = weft_sphere_map_direction(n_4, world_position_3);
        vec4 _e7 = texture(_group_1_binding_7_fs, vec3(_e4));
        vec3 sph = max(_e7.xyz, vec3(0.0));
        vec3 _e12 = color;
        float _e15 = _group_1_binding_0_fs.sphere_strength;
        color = (_e12 + (sph * _e15));
    }
    vec3 _e18 = color;
    return _e18;
}

void standard_alpha_test(float alpha_2) {
    if (ALPHA_TEST) {
        float _e4 = _group_1_binding_0_fs.alpha_cutoff;
        if ((alpha_2 < _e4)) {
            discard;
        } else {
            return;
        }
    } else {
        return;
    }
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    bool front_facing = gl_FrontFacing;
    vec3 n = vec3(0.0);
    float visibility = 0.0;
    vec3 env_brdf = vec3(0.0);
    vec3 ambient_kd = vec3(0.0);
    vec3 direct_kd = vec3(0.0);
    vec3 specular = vec3(0.0);
    vec3 indirect_specular = vec3(0.0);
    float d = 0.0;
    vec4 _e5 = _group_1_binding_0_fs.base_map_st;
    vec2 _e6 = weft_transform_uv(in_1.uv0_, _e5);
    vec4 _e9 = _group_1_binding_0_fs.base_color;
    vec4 _e12 = texture(_group_1_binding_4_fs, vec2(_e6));
    vec4 base_rgba = (_e9 * _e12);
    vec3 base = clamp(base_rgba.xyz, vec3(0.0), vec3(1.0));
    float alpha_4 = clamp(base_rgba.w, 0.0, 1.0);
    vec4 _e20 = texture(_group_1_binding_6_fs, vec2(_e6));
    vec3 rmo = _e20.xyz;
    vec3 _e22 = standard_emission(_e6);
    float _e25 = _group_1_binding_0_fs.roughness;
    float roughness_4 = clamp((_e25 * rmo.x), 0.0, 1.0);
    float _e31 = _group_1_binding_0_fs.metallic;
    float metallic = clamp((_e31 * rmo.y), 0.0, 1.0);
    float _e38 = _group_1_binding_0_fs.occlusion_strength;
    float ao_1 = clamp(mix(1.0, rmo.z, _e38), 0.0, 1.0);
    float _e44 = _group_1_binding_0_fs.specular_strength;
    float specular_strength_1 = max(_e44, 0.0);
    WeftSurface _e49 = weft_surface_two_sided(in_1.world_position, in_1.world_normal, front_facing);
    vec3 v_3 = _e49.v;
    n = _e49.n;
    vec3 _e53 = n;
    WeftLightGeometry _e54 = weft_main_light_geometry(_e53, v_3);
    vec3 f0_3 = mix(vec3(0.04), base, metallic);
    vec3 diffuse_albedo_1 = (base * (1.0 - metallic));
    {
        vec3 _e61 = n;
        vec3 _e62 = standard_low(_e61, v_3, _e54, f0_3, diffuse_albedo_1, roughness_4, ao_1, specular_strength_1);
        vec3 _e63 = n;
        vec3 _e65 = standard_sphere_map(_e62, _e63, in_1.world_position);
        vec3 radiance = clamp((_e65 + _e22), vec3(0.0), vec3(65504.0));
        standard_alpha_test(alpha_4);
        _fs2p_location0 = vec4(radiance, alpha_4);
        return;
    }
}

