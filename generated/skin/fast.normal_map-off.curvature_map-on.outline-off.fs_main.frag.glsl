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
    float normal_strength;
    float roughness;
    float specular;
    float curvature_factor;
    float dark_bound;
    float bright_bound;
    float lobe_weight;
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
const vec3 skin_lut_shape = vec3(4.0, 10.0, 20.0);
const float skin_lut_ring = 3.1415927;
const vec3 seed_lut_shape = vec3(4.0, 10.0, 20.0);
const float seed_lut_ring = 1.5707964;
const uint TIER_FAST = 0u;
const uint TIER_REFERENCE = 1u;
const uint TIER_SEED = 2u;
const float WEFT_MIN_ROUGHNESS = 0.045;
const float WEFT_MIN_N_DOT = 0.0001;
const float WEFT_MAX_HALF = 65504.0;
const float WEFT_DIELECTRIC_F0_ = 0.04;

layout(std140, binding = 0) uniform WeftFrame_block_0Fragment { WeftFrame _group_0_binding_0_fs; };

layout(binding = 0) uniform samplerCube _group_0_binding_1_fs;

layout(binding = 1) uniform sampler2D _group_0_binding_3_fs;

layout(std140, binding = 1) uniform WeftMaterial_block_1Fragment { WeftMaterial _group_1_binding_0_fs; };

layout(binding = 2) uniform sampler2D _group_1_binding_3_fs;

layout(binding = 3) uniform sampler2D _group_1_binding_5_fs;

layout(binding = 4) uniform sampler2D _group_1_binding_6_fs;

layout(binding = 5) uniform sampler2D _group_1_binding_7_fs;

layout(location = 0) smooth in vec3 _vs2fs_location0;
layout(location = 1) smooth in vec3 _vs2fs_location1;
layout(location = 2) smooth in vec4 _vs2fs_location2;
layout(location = 3) smooth in vec2 _vs2fs_location3;
layout(location = 0) out vec4 _fs2p_location0;

vec4 table_skin_lut(vec2 uv) {
    vec2 size = vec2(64.0, 64.0);
    vec2 st_1 = (((clamp(uv, vec2(0.0), vec2(1.0)) * (size - vec2(1.0))) + vec2(0.5)) / size);
    vec4 _e20 = textureLod(_group_1_binding_7_fs, vec2(st_1), 0.0);
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

float weft_d_ggx_nh(vec3 n_1, vec3 h, float roughness_1) {
    float _e3 = weft_clamp_roughness(roughness_1);
    float a = (_e3 * _e3);
    float a2_ = (a * a);
    float noh = clamp(dot(n_1, h), 0.0, 1.0);
    vec3 nxh = cross(n_1, h);
    float d = (dot(nxh, nxh) + ((noh * noh) * a2_));
    return (a2_ / (WEFT_PI * max((d * d), 1e-30)));
}

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
}

float weft_v_smith_ggx_correlated(float n_dot_v, float n_dot_l, float roughness_2) {
    float _e3 = weft_clamp_roughness(roughness_2);
    float a_1 = (_e3 * _e3);
    float a2_1 = (a_1 * a_1);
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

WeftLightGeometry weft_main_light_geometry(vec3 n_3, vec3 v_1) {
    vec3 _e2 = weft_main_light_direction();
    vec3 _e4 = weft_safe_normalize((_e2 + v_1), n_3);
    float _e6 = weft_clamp_cos(dot(n_3, v_1));
    return WeftLightGeometry(_e2, _e4, _e6, clamp(dot(n_3, _e2), 0.0, 1.0), clamp(dot(n_3, _e4), 0.0, 1.0), clamp(dot(v_1, _e4), 0.0, 1.0));
}

vec2 weft_transform_uv(vec2 uv_1, vec4 st) {
    return ((uv_1 * st.xy) + st.zw);
}

float skin_dual_ggx(vec3 n_4, vec3 h_1, float n_dot_v_2, float n_dot_l_1, float v_dot_h_1, float roughness_6, float w, float f0_2) {
    float r0_ = clamp((roughness_6 * 0.75), 0.0, 1.0);
    float r1_ = clamp((roughness_6 * 1.3), 0.0, 1.0);
    float _e18 = weft_d_ggx_nh(n_4, h_1, r0_);
    float _e19 = weft_v_smith_ggx_correlated(n_dot_v_2, n_dot_l_1, r0_);
    float lobe0_ = (_e18 * _e19);
    float _e21 = weft_d_ggx_nh(n_4, h_1, r1_);
    float _e22 = weft_v_smith_ggx_correlated(n_dot_v_2, n_dot_l_1, r1_);
    float lobe1_ = (_e21 * _e22);
    vec3 _e25 = weft_f_schlick(vec3(f0_2), v_dot_h_1);
    float f = _e25.x;
    return (mix(lobe0_, lobe1_, clamp(w, 0.0, 1.0)) * f);
}

void main() {
    WeftVaryings in_1 = WeftVaryings(gl_FragCoord, _vs2fs_location0, _vs2fs_location1, _vs2fs_location2, _vs2fs_location3);
    float curvature = 0.0;
    vec3 n = vec3(0.0);
    vec3 falloff = vec3(0.0);
    float specular = 0.0;
    vec3 kd = vec3(0.0);
    vec4 _e4 = _group_1_binding_0_fs.base_map_st;
    vec2 _e5 = weft_transform_uv(in_1.uv0_, _e4);
    vec4 _e8 = _group_1_binding_0_fs.base_color;
    vec4 _e11 = texture(_group_1_binding_3_fs, vec2(_e5));
    vec4 base_rgba = (_e8 * _e11);
    vec3 albedo_1 = clamp(base_rgba.xyz, vec3(0.0), vec3(1.0));
    float alpha = clamp(base_rgba.w, 0.0, 1.0);
    float _e19 = _group_1_binding_0_fs.roughness;
    float roughness_7 = clamp(_e19, 0.05, 1.0);
    float _e25 = _group_1_binding_0_fs.specular;
    float f0_3 = clamp(_e25, 0.0, 1.0);
    vec4 _e31 = texture(_group_1_binding_6_fs, vec2(_e5));
    float mask = clamp(_e31.x, 0.0, 1.0);
    WeftSurface _e36 = weft_surface(in_1.world_position, in_1.world_normal);
    vec3 v_2 = _e36.v;
    vec3 n_geom = _e36.n;
    vec3 _e39 = fwidth(n_geom);
    float dn = length(_e39);
    vec3 _e42 = fwidth(in_1.world_position);
    float dp = length(_e42);
    float estimated = ((dp > 1e-12) ? (dn / dp) : 0.0);
    vec4 _e51 = texture(_group_1_binding_5_fs, vec2(_e5));
    float mapped = _e51.x;
    float _e55 = _group_1_binding_0_fs.curvature_factor;
    float factor = max(_e55, 0.0);
    curvature = clamp((factor * estimated), 0.0, 1.0);
    {
        curvature = clamp((factor * mapped), 0.0, 1.0);
    }
    n = n_geom;
    vec3 _e64 = n;
    WeftLightGeometry _e65 = weft_main_light_geometry(_e64, v_2);
    vec3 _e66 = n;
    float _e75 = _group_1_binding_0_fs.dark_bound;
    float _e78 = _group_1_binding_0_fs.bright_bound;
    float u = clamp(((dot(_e66, _e65.l) * 0.5) + 0.5), _e75, _e78);
    {
        {
            float _e81 = curvature;
            vec4 _e83 = table_skin_lut(vec2(u, _e81));
            falloff = _e83.xyz;
        }
    }
    vec3 _e85 = falloff;
    falloff = max(_e85, vec3(0.0));
    vec2 _e91 = weft_env_brdf_lut(_e65.n_dot_v, roughness_7);
    vec3 _e92 = weft_env_brdf_from_lut(vec3(f0_3), _e91);
    {
        vec3 _e95 = n;
        float _e102 = _group_1_binding_0_fs.lobe_weight;
        float _e103 = skin_dual_ggx(_e95, _e65.h, _e65.n_dot_v, _e65.n_dot_l, _e65.v_dot_h, roughness_7, _e102, f0_3);
        specular = ((_e103 * _e65.n_dot_l) * mask);
        kd = max((vec3(1.0) - _e92), vec3(0.0));
    }
    vec3 _e113 = weft_main_light_radiance();
    vec3 _e114 = kd;
    vec3 _e115 = weft_diffuse_lambert(albedo_1);
    vec3 _e117 = falloff;
    float _e119 = specular;
    vec3 direct = ((((_e114 * _e115) * _e117) + vec3(_e119)) * _e113);
    vec3 _e123 = n;
    vec3 _e124 = weft_sh_irradiance(_e123);
    vec3 _e125 = kd;
    vec3 indirect_diffuse = ((_e124 * _e125) * albedo_1);
    vec3 _e129 = n;
    vec3 _e131 = weft_prefiltered_radiance(reflect(-(v_2), _e129), roughness_7);
    vec3 indirect_specular = ((_e131 * _e92) * mask);
    vec3 color = ((direct + indirect_diffuse) + indirect_specular);
    vec3 radiance = clamp(color, vec3(0.0), vec3(65504.0));
    _fs2p_location0 = vec4(radiance, alpha);
    return;
}

