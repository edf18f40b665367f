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
struct GlintGrid {
    vec2 uv;
    uint seed;
    float cell_area;
    float weight;
};
struct GlintParams {
    float log_density;
    float micro_roughness;
    float density_randomization;
};
struct GlintSlopeRand {
    vec4 gate_rand;
    vec4 gaussian;
    vec2 lerp;
};
struct GlintSimplex {
    ivec2 id;
    int si;
    vec3 bary;
};
struct GlintEllipse {
    vec2 major_dir;
    float major;
    float minor;
};
struct GlintGrids {
    GlintGrid g0_;
    GlintGrid g1_;
    GlintGrid g2_;
    GlintGrid g3_;
};
struct GlintTetra {
    vec3 p0_;
    vec3 p1_;
    vec3 p2_;
    vec3 p3_;
    vec4 w;
    bool center;
    float bin0_;
    float bin_h;
    float bin1_;
    float lod0_;
    float ratio0_;
};
struct GlintFootprintCell {
    float theta_lerp;
    float ratio_lerp;
    float lod_lerp;
    bool center;
    float bin0_;
    float bin_h;
    float bin1_;
    float lod0_;
    float ratio0_;
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

layout(std140, binding = 0) uniform WeftFrame_block_0Vertex { WeftFrame _group_0_binding_0_vs; };

layout(std140, binding = 2) uniform WeftObject_block_1Vertex { WeftObject _group_2_binding_0_vs; };

layout(location = 0) in vec3 _p2vs_location0;
layout(location = 1) in vec3 _p2vs_location1;
layout(location = 2) in vec4 _p2vs_location2;
layout(location = 3) in vec2 _p2vs_location3;
layout(location = 0) smooth out vec3 _vs2fs_location0;
layout(location = 1) smooth out vec3 _vs2fs_location1;
layout(location = 2) smooth out vec4 _vs2fs_location2;
layout(location = 3) smooth out vec2 _vs2fs_location3;

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
    float a_1 = (-1.0 / (s + n_1.z));
    float b_1 = ((n_1.x * n_1.y) * a_1);
    return vec3((1.0 + (((s * n_1.x) * n_1.x) * a_1)), (s * b_1), (-(s) * n_1.x));
}

float weft_d_ggx(float n_dot_h, float roughness_1) {
    float _e2 = weft_clamp_roughness(roughness_1);
    float a_2 = (_e2 * _e2);
    float a2_ = (a_2 * a_2);
    float noh = clamp(n_dot_h, 0.0, 1.0);
    float one_minus_noh2_ = ((1.0 - noh) * (1.0 + noh));
    float d_2 = (one_minus_noh2_ + ((noh * noh) * a2_));
    return (a2_ / ((WEFT_PI * d_2) * d_2));
}

float weft_d_ggx_nh(vec3 n_2, vec3 h, float roughness_2) {
    float _e3 = weft_clamp_roughness(roughness_2);
    float a_3 = (_e3 * _e3);
    float a2_1 = (a_3 * a_3);
    float noh_1 = clamp(dot(n_2, h), 0.0, 1.0);
    vec3 nxh = cross(n_2, h);
    float d_3 = (dot(nxh, nxh) + ((noh_1 * noh_1) * a2_1));
    return (a2_1 / (WEFT_PI * max((d_3 * d_3), 1e-30)));
}

vec3 weft_f_schlick(vec3 f0_, float v_dot_h) {
    float _e5 = weft_pow5_((1.0 - clamp(v_dot_h, 0.0, 1.0)));
    return (f0_ + ((vec3(1.0) - f0_) * _e5));
}

float weft_v_smith_ggx_correlated(float n_dot_v, float n_dot_l, float roughness_3) {
    float _e3 = weft_clamp_roughness(roughness_3);
    float a_4 = (_e3 * _e3);
    float a2_2 = (a_4 * a_4);
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
    vec4 _e2 = _group_0_binding_0_vs.light_direction;
    vec3 _e8 = weft_safe_normalize(_e2.xyz, vec3(0.0, 0.0, 1.0));
    return _e8;
}

vec3 weft_main_light_radiance() {
    vec4 _e2 = _group_0_binding_0_vs.light_color;
    return max(_e2.xyz, vec3(0.0));
}

vec3 weft_view_direction(vec3 world_position, vec3 fallback_1) {
    vec4 _e4 = _group_0_binding_0_vs.camera_position;
    vec3 _e7 = weft_safe_normalize((_e4.xyz - world_position), fallback_1);
    return _e7;
}

vec3 weft_sh_irradiance(vec3 n_3) {
    vec3 e = vec3(0.0);
    vec4 sh[9] = _group_0_binding_0_vs.sh;
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
    float r_1 = clamp(roughness_4, 0.0, 1.0);
    float _e5 = _group_0_binding_0_vs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r_1 * (1.7 - (0.7 * r_1))) * max_mip);
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

WeftVaryings weft_forward_vertex(WeftVertexInput in_2) {
    WeftVaryings out_ = WeftVaryings(vec4(0.0), vec3(0.0), vec3(0.0), vec4(0.0), vec2(0.0));
    mat4x4 model = _group_2_binding_0_vs.model;
    mat3x3 model3_ = mat3x3(model[0].xyz, model[1].xyz, model[2].xyz);
    mat4x4 nm = _group_2_binding_0_vs.normal_matrix;
    mat3x3 normal3_ = mat3x3(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    vec4 world = (model * vec4(in_2.position, 1.0));
    float mirror = ((determinant(model3_) < 0.0) ? -1.0 : 1.0);
    float bitangent_sign = (((in_2.tangent.w < 0.0) ? -1.0 : 1.0) * mirror);
    mat4x4 _e43 = _group_0_binding_0_vs.view_proj;
    out_.clip_position = (_e43 * vec4(world.xyz, 1.0));
    out_.world_position = world.xyz;
    vec3 _e55 = weft_safe_normalize((normal3_ * in_2.normal), vec3(0.0));
    out_.world_normal = _e55;
    vec3 _e62 = weft_safe_normalize((model3_ * in_2.tangent.xyz), vec3(0.0));
    out_.world_tangent = vec4(_e62, bitangent_sign);
    out_.uv0_ = in_2.uv0_;
    WeftVaryings _e66 = out_;
    return _e66;
}

mat3x3 weft_tangent_frame(vec3 n_5, vec4 tangent) {
    vec3 t_in = tangent.xyz;
    vec3 t_proj = (t_in - (n_5 * dot(n_5, t_in)));
    float len2_1 = dot(t_proj, t_proj);
    bool ok = (len2_1 > max((1e-6 * dot(t_in, t_in)), 1e-20));
    vec3 _e13 = weft_any_perpendicular(n_5);
    vec3 t = (ok ? (t_proj * inversesqrt(max(len2_1, 1e-20))) : _e13);
    float s_1 = ((tangent.w < 0.0) ? -1.0 : 1.0);
    vec3 b_2 = (cross(n_5, t) * s_1);
    return mat3x3(t, b_2, n_5);
}

vec3 weft_unpack_normal(vec3 texel, float strength) {
    vec3 v_6 = ((texel * 2.0) - vec3(1.0));
    return vec3((v_6.xy * strength), max(v_6.z, 0.001));
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

uvec4 glint_pcg4d(uvec4 v_in) {
    uvec4 v_2 = uvec4(0u);
    v_2 = ((v_in * 1664525u) + uvec4(1013904223u));
    uint _e8 = v_2.x;
    uint _e10 = v_2.y;
    uint _e12 = v_2.w;
    v_2.x = (_e8 + (_e10 * _e12));
    uint _e16 = v_2.y;
    uint _e18 = v_2.z;
    uint _e20 = v_2.x;
    v_2.y = (_e16 + (_e18 * _e20));
    uint _e24 = v_2.z;
    uint _e26 = v_2.x;
    uint _e28 = v_2.y;
    v_2.z = (_e24 + (_e26 * _e28));
    uint _e32 = v_2.w;
    uint _e34 = v_2.y;
    uint _e36 = v_2.z;
    v_2.w = (_e32 + (_e34 * _e36));
    uvec4 _e39 = v_2;
    uvec4 _e40 = v_2;
    v_2 = (_e39 ^ (_e40 >> uvec4(16u)));
    uint _e46 = v_2.x;
    uint _e48 = v_2.y;
    uint _e50 = v_2.w;
    v_2.x = (_e46 + (_e48 * _e50));
    uint _e54 = v_2.y;
    uint _e56 = v_2.z;
    uint _e58 = v_2.x;
    v_2.y = (_e54 + (_e56 * _e58));
    uint _e62 = v_2.z;
    uint _e64 = v_2.x;
    uint _e66 = v_2.y;
    v_2.z = (_e62 + (_e64 * _e66));
    uint _e70 = v_2.w;
    uint _e72 = v_2.y;
    uint _e74 = v_2.z;
    v_2.w = (_e70 + (_e72 * _e74));
    uvec4 _e77 = v_2;
    return _e77;
}

uvec3 glint_pcg3d(uvec3 v_in_1) {
    uvec3 v_3 = uvec3(0u);
    v_3 = ((v_in_1 * 1664525u) + uvec3(1013904223u));
    uint _e8 = v_3.x;
    uint _e10 = v_3.y;
    uint _e12 = v_3.z;
    v_3.x = (_e8 + (_e10 * _e12));
    uint _e16 = v_3.y;
    uint _e18 = v_3.z;
    uint _e20 = v_3.x;
    v_3.y = (_e16 + (_e18 * _e20));
    uint _e24 = v_3.z;
    uint _e26 = v_3.x;
    uint _e28 = v_3.y;
    v_3.z = (_e24 + (_e26 * _e28));
    uvec3 _e31 = v_3;
    uvec3 _e32 = v_3;
    v_3 = (_e31 ^ (_e32 >> uvec3(16u)));
    uint _e38 = v_3.x;
    uint _e40 = v_3.y;
    uint _e42 = v_3.z;
    v_3.x = (_e38 + (_e40 * _e42));
    uint _e46 = v_3.y;
    uint _e48 = v_3.z;
    uint _e50 = v_3.x;
    v_3.y = (_e46 + (_e48 * _e50));
    uint _e54 = v_3.z;
    uint _e56 = v_3.x;
    uint _e58 = v_3.y;
    v_3.z = (_e54 + (_e56 * _e58));
    uvec3 _e61 = v_3;
    return _e61;
}

vec3 glint_unit3_(uvec3 v_4) {
    return ((vec3((v_4 >> uvec3(8u))) + vec3(0.5)) * 5.9604645e-8);
}

vec4 glint_unit4_(uvec4 v_5) {
    return ((vec4((v_5 >> uvec4(8u))) + vec4(0.5)) * 5.9604645e-8);
}

float glint_hash13_(vec3 p_in) {
    vec3 p3_ = vec3(0.0);
    p3_ = fract((p_in * 0.1031));
    vec3 _e5 = p3_;
    vec3 _e6 = p3_;
    vec3 _e7 = p3_;
    p3_ = (_e5 + vec3(dot(_e6, (_e7.yzx + vec3(33.33)))));
    float _e16 = p3_.x;
    float _e18 = p3_.y;
    float _e21 = p3_.z;
    return fract(((_e16 + _e18) * _e21));
}

float glint_erfinv(float x_1) {
    float w = 0.0;
    float p = 0.0;
    w = -(log(max(((1.0 - x_1) * (1.0 + x_1)), 1e-30)));
    float _e12 = w;
    if ((_e12 < 5.0)) {
        float _e15 = w;
        w = (_e15 - 2.5);
        p = 2.8102264e-8;
        float _e19 = p;
        float _e20 = w;
        p = (3.4327394e-7 + (_e19 * _e20));
        float _e24 = p;
        float _e25 = w;
        p = (-3.5233877e-6 + (_e24 * _e25));
        float _e29 = p;
        float _e30 = w;
        p = (-4.3915065e-6 + (_e29 * _e30));
        float _e34 = p;
        float _e35 = w;
        p = (0.00021858087 + (_e34 * _e35));
        float _e39 = p;
        float _e40 = w;
        p = (-0.001253725 + (_e39 * _e40));
        float _e44 = p;
        float _e45 = w;
        p = (-0.0041776816 + (_e44 * _e45));
        float _e49 = p;
        float _e50 = w;
        p = (0.24664073 + (_e49 * _e50));
        float _e54 = p;
        float _e55 = w;
        p = (1.5014094 + (_e54 * _e55));
    } else {
        float _e59 = w;
        w = (sqrt(_e59) - 3.0);
        p = -0.00020021426;
        float _e64 = p;
        float _e65 = w;
        p = (0.00010095056 + (_e64 * _e65));
        float _e69 = p;
        float _e70 = w;
        p = (0.0013493432 + (_e69 * _e70));
        float _e74 = p;
        float _e75 = w;
        p = (-0.0036734284 + (_e74 * _e75));
        float _e79 = p;
        float _e80 = w;
        p = (0.0057395077 + (_e79 * _e80));
        float _e84 = p;
        float _e85 = w;
        p = (-0.0076224613 + (_e84 * _e85));
        float _e89 = p;
        float _e90 = w;
        p = (0.0094388705 + (_e89 * _e90));
        float _e94 = p;
        float _e95 = w;
        p = (1.001674 + (_e94 * _e95));
        float _e99 = p;
        float _e100 = w;
        p = (2.8329768 + (_e99 * _e100));
    }
    float _e104 = p;
    return (_e104 * x_1);
}

float glint_erfinv_poly(float x_in) {
    float x_3 = clamp(x_in, -0.95, 0.95);
    float x2_1 = (x_3 * x_3);
    return (x_3 * (0.864441 + (x2_1 * (0.533641 + (x2_1 * (-0.893165 + (x2_1 * 1.108999)))))));
}

float glint_erfinv_by(float x_2, bool poly) {
    if (poly) {
        float _e2 = glint_erfinv_poly(x_2);
        return _e2;
    }
    float _e3 = glint_erfinv(x_2);
    return _e3;
}

vec3 glint_gaussian3_(vec3 u, bool poly_normals) {
    float _e7 = glint_erfinv_by(((2.0 * u.x) - 1.0), poly_normals);
    float _e13 = glint_erfinv_by(((2.0 * u.y) - 1.0), poly_normals);
    float _e19 = glint_erfinv_by(((2.0 * u.z) - 1.0), poly_normals);
    return (1.4142135 * vec3(_e7, _e13, _e19));
}

vec2 glint_corner(vec2 c_1, bool poly_normals_1) {
    uvec2 texel_2 = uvec2((c_1 - (GLINT_TABLE_SIZE * floor((c_1 / vec2(64.0))))));
    uvec4 _e13 = glint_pcg4d(uvec4(texel_2, 6777961u, 1953785202u));
    vec4 _e14 = glint_unit4_(_e13);
    float _e21 = glint_erfinv_by(((2.0 * _e14.y) - 1.0), poly_normals_1);
    return vec2(_e14.x, (1.4142135 * _e21));
}

GlintSlopeRand glint_slope_rand(float micro_roughness, vec2 slope, vec2 offset, bool poly_normals_2) {
    GlintSlopeRand out_1 = GlintSlopeRand(vec4(0.0), vec4(0.0), vec2(0.0));
    vec2 s_2 = ((abs(slope) / vec2(micro_roughness)) + (offset * GLINT_TABLE_SIZE));
    vec2 cell = floor(s_2);
    vec2 _e11 = glint_corner(cell, poly_normals_2);
    vec2 _e16 = glint_corner((cell + vec2(0.0, 1.0)), poly_normals_2);
    vec2 _e21 = glint_corner((cell + vec2(1.0, 0.0)), poly_normals_2);
    vec2 _e26 = glint_corner((cell + vec2(1.0, 1.0)), poly_normals_2);
    out_1.gate_rand = vec4(_e11.x, _e16.x, _e21.x, _e26.x);
    out_1.gaussian = vec4(_e11.y, _e16.y, _e21.y, _e26.y);
    out_1.lerp = (s_2 - cell);
    GlintSlopeRand _e42 = out_1;
    return _e42;
}

float glint_cell_hits(GlintSlopeRand r, float one_hit, float smooth_width, float mean, float deviation, float count) {
    vec4 gate = vec4(0.0);
    if ((smooth_width > 1e-7)) {
        gate = clamp(((r.gate_rand - vec4((one_hit + smooth_width))) / vec4((-2.0 * smooth_width))), vec4(0.0), vec4(1.0));
    } else {
        gate = mix(vec4(0.0), vec4(1.0), lessThan(r.gate_rand, vec4(one_hit)));
    }
    vec4 gauss = clamp(floor(((r.gaussian * deviation) + vec4(mean))), vec4(0.0), vec4(count));
    vec4 _e35 = gate;
    vec4 hits = (_e35 * (vec4(1.0) + gauss));
    float x0_ = mix(hits.x, hits.z, r.lerp.x);
    float x1_ = mix(hits.y, hits.w, r.lerp.x);
    return mix(x0_, x1_, r.lerp.y);
}

GlintSimplex glint_simplex(vec2 uv_1) {
    vec2 skewed = vec2((uv_1.x - (0.57735026 * uv_1.y)), (1.1547005 * uv_1.y));
    vec2 base = floor(skewed);
    vec2 f = (skewed - base);
    float fz = ((1.0 - f.x) - f.y);
    float s_3 = ((fz < 0.0) ? 1.0 : 0.0);
    float s2_ = ((2.0 * s_3) - 1.0);
    return GlintSimplex(ivec2(base), int(s_3), vec3((-(fz) * s2_), (s_3 - (f.y * s2_)), (s_3 - (f.x * s2_))));
}

float glint_sample_grid(GlintParams params, GlintGrid grid, vec2 slope_1, float target_ndf, bool poly_normals_3) {
    GlintSimplex _e6 = glint_simplex(grid.uv);
    ivec2 id = _e6.id;
    int si = _e6.si;
    ivec2 c0_ = (id + ivec2(si, si));
    ivec2 c1_ = (id + ivec2(si, (1 - si)));
    ivec2 c2_ = (id + ivec2((1 - si), si));
    vec3 bary = _e6.bary;
    uvec3 _e29 = glint_pcg3d(uvec3((uint(c0_.x) + 2147483648u), (uint(c0_.y) + 2147483648u), grid.seed));
    vec3 _e30 = glint_unit3_(_e29);
    uvec3 _e39 = glint_pcg3d(uvec3((uint(c1_.x) + 2147483648u), (uint(c1_.y) + 2147483648u), grid.seed));
    vec3 _e40 = glint_unit3_(_e39);
    uvec3 _e49 = glint_pcg3d(uvec3((uint(c2_.x) + 2147483648u), (uint(c2_.y) + 2147483648u), grid.seed));
    vec3 _e50 = glint_unit3_(_e49);
    GlintSlopeRand _e53 = glint_slope_rand(params.micro_roughness, slope_1, _e30.yz, poly_normals_3);
    GlintSlopeRand _e56 = glint_slope_rand(params.micro_roughness, slope_1, _e40.yz, poly_normals_3);
    GlintSlopeRand _e59 = glint_slope_rand(params.micro_roughness, slope_1, _e50.yz, poly_normals_3);
    vec3 _e64 = glint_gaussian3_(vec3(_e30.x, _e40.x, _e50.x), poly_normals_3);
    vec3 log_density = clamp(((_e64 * params.density_randomization) + vec3(params.log_density)), vec3(0.0), vec3(50.0));
    vec3 count_1 = max(vec3(1e-8), (grid.cell_area * exp(log_density)));
    vec3 blended = (count_1 * grid.weight);
    float p_4 = (params.micro_roughness * target_ndf);
    vec3 one_hit_1 = (vec3(1.0) - pow(vec3((1.0 - p_4)), blended));
    vec3 others = max((blended - vec3(1.0)), vec3(0.0));
    vec3 mean_1 = (others * p_4);
    vec3 deviation_1 = sqrt((others * (p_4 * (1.0 - p_4))));
    vec3 smooth_width_1 = ((0.1 * clamp((one_hit_1 * 10.0), vec3(0.0), vec3(1.0))) * clamp(((vec3(1.0) - one_hit_1) * 10.0), vec3(0.0), vec3(1.0)));
    float _e121 = glint_cell_hits(_e53, one_hit_1.x, smooth_width_1.x, mean_1.x, deviation_1.x, blended.x);
    float _e127 = glint_cell_hits(_e56, one_hit_1.y, smooth_width_1.y, mean_1.y, deviation_1.y, blended.y);
    float _e133 = glint_cell_hits(_e59, one_hit_1.z, smooth_width_1.z, mean_1.z, deviation_1.z, blended.z);
    return dot((vec3(_e121, _e127, _e133) / count_1), bary);
}

GlintEllipse glint_ellipse(vec2 duv_dx, vec2 duv_dy) {
    GlintEllipse out_2 = GlintEllipse(vec2(0.0), 0.0, 0.0);
    float a_5 = ((duv_dx.x * duv_dx.x) + (duv_dy.x * duv_dy.x));
    float b_3 = ((duv_dx.x * duv_dx.y) + (duv_dy.x * duv_dy.y));
    float d_4 = ((duv_dx.y * duv_dx.y) + (duv_dy.y * duv_dy.y));
    float half_trace = (0.5 * (a_5 + d_4));
    float disc = sqrt(max((((0.25 * (a_5 - d_4)) * (a_5 - d_4)) + (b_3 * b_3)), 0.0));
    float l1_ = (half_trace + disc);
    float l2_ = max((half_trace - disc), 0.0);
    vec2 e_a = vec2(b_3, (l1_ - a_5));
    vec2 e_b = vec2((l1_ - d_4), b_3);
    vec2 e_5 = ((dot(e_a, e_a) > dot(e_b, e_b)) ? e_a : e_b);
    float e_len2_ = dot(e_5, e_5);
    out_2.major_dir = ((e_len2_ > 1e-37) ? (e_5 * inversesqrt(max(e_len2_, 1e-37))) : vec2(1.0, 0.0));
    out_2.major = max(sqrt(l1_), 1e-12);
    float _e68 = out_2.major;
    out_2.minor = max(sqrt(l2_), (_e68 / 64.0));
    GlintEllipse _e72 = out_2;
    return _e72;
}

vec2 glint_rotate(vec2 uv_2, float angle) {
    float c_3 = cos(angle);
    float s_4 = sin(angle);
    return vec2(((c_3 * uv_2.x) + (s_4 * uv_2.y)), ((c_3 * uv_2.y) - (s_4 * uv_2.x)));
}

uint glint_grid_seed(float lod, float theta, float ratio) {
    float t_1 = (theta - (GLINT_TAU * trunc((theta / GLINT_TAU))));
    float _e10 = glint_hash13_(vec3(lod, t_1, ratio));
    return uint(min((_e10 * 4294967300.0), 4294967000.0));
}

GlintGrid glint_make_grid(vec2 uv_3, float lod_1, float theta_1, float ratio_1, float weight) {
    GlintGrid g = GlintGrid(vec2(0.0), 0u, 0.0, 0.0);
    vec2 _e7 = glint_rotate(uv_3, theta_1);
    g.uv = ((_e7 * exp2(-(lod_1))) / vec2(1.0, ratio_1));
    uint _e15 = glint_grid_seed(lod_1, theta_1, ratio_1);
    g.seed = _e15;
    g.cell_area = (ratio_1 * exp2((2.0 * lod_1)));
    g.weight = weight;
    GlintGrid _e22 = g;
    return _e22;
}

vec4 glint_tetra_weights(vec3 p_1, vec3 a, vec3 b, vec3 c_2, vec3 d) {
    vec3 c1_1 = (a - d);
    vec3 c2_1 = (b - d);
    vec3 c3_ = (c_2 - d);
    vec3 q = (p_1 - d);
    float det = dot(c1_1, cross(c2_1, c3_));
    float inv = (1.0 / det);
    float w1_ = (dot(q, cross(c2_1, c3_)) * inv);
    float w2_ = (dot(c1_1, cross(q, c3_)) * inv);
    float w3_ = (dot(c1_1, cross(c2_1, q)) * inv);
    return vec4(w1_, w2_, w3_, (((1.0 - w1_) - w2_) - w3_));
}

float glint_lod(GlintEllipse e_1, float screen_scale) {
    return clamp(log2(((e_1.minor * screen_scale) * 0.5)), GLINT_MIN_LOD, GLINT_MAX_LOD);
}

GlintFootprintCell glint_footprint_cell(GlintEllipse e_2, float screen_scale_1) {
    GlintFootprintCell out_3 = GlintFootprintCell(0.0, 0.0, 0.0, false, 0.0, 0.0, 0.0, 0.0, 0.0);
    float ratio_e = min((e_2.major / (e_2.minor + (1e-8 * e_2.major))), GLINT_MAX_RATIO);
    float _e11 = glint_lod(e_2, screen_scale_1);
    float lod0_1 = floor(_e11);
    float lod_lerp = (_e11 - lod0_1);
    float ratio0_1 = max(exp2(floor(log2(max(ratio_e, 1.0)))), 1.0);
    float ratio1_ = (ratio0_1 * 2.0);
    float ratio_lerp = clamp(((ratio_e - ratio0_1) / (ratio1_ - ratio0_1)), 0.0, 1.0);
    float q_1 = (0.7853982 / max(ratio0_1, 2.0));
    float per_pi = (4.0 * max(ratio0_1, 2.0));
    float theta_3 = atan(-(e_2.major_dir.x), e_2.major_dir.y);
    float theta_q = (theta_3 / q_1);
    float h0_ = floor(theta_q);
    float theta_lerp_1 = clamp((theta_q - h0_), 0.0, 1.0);
    float i0_ = (h0_ - (per_pi * floor((h0_ / per_pi))));
    float i1_ = ((i0_ + 1.0) - (per_pi * floor(((i0_ + 1.0) / per_pi))));
    float theta_bin0_ = (i0_ * q_1);
    float theta_bin_h = ((i0_ + 0.5) * q_1);
    float theta_bin1_ = (i1_ * q_1);
    out_3.theta_lerp = theta_lerp_1;
    out_3.ratio_lerp = ratio_lerp;
    out_3.lod_lerp = lod_lerp;
    out_3.center = (ratio0_1 == 1.0);
    out_3.bin0_ = theta_bin0_;
    out_3.bin_h = theta_bin_h;
    out_3.bin1_ = theta_bin1_;
    out_3.lod0_ = lod0_1;
    out_3.ratio0_ = ratio0_1;
    GlintFootprintCell _e74 = out_3;
    return _e74;
}

GlintTetra glint_tetra(GlintEllipse e_3, float screen_scale_2) {
    float theta_lerp = 0.0;
    vec3 p0_ = vec3(0.0);
    vec3 p1_ = vec3(0.0);
    vec3 p2_ = vec3(0.0);
    vec3 p3_1 = vec3(0.0);
    bool local_1 = false;
    GlintTetra out_4 = GlintTetra(vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0), vec4(0.0), false, 0.0, 0.0, 0.0, 0.0, 0.0);
    GlintFootprintCell _e2 = glint_footprint_cell(e_3, screen_scale_2);
    theta_lerp = _e2.theta_lerp;
    float ratio_lerp_1 = _e2.ratio_lerp;
    float lod_lerp_1 = _e2.lod_lerp;
    bool center_1 = _e2.center;
    if (center_1) {
        vec3 a_6 = vec3(0.0, 1.0, 0.0);
        vec3 b_4 = vec3(0.0, 0.0, 0.0);
        vec3 c_4 = vec3(1.0, 1.0, 0.0);
        vec3 d_5 = vec3(0.0, 1.0, 1.0);
        vec3 ee = vec3(0.0, 0.0, 1.0);
        vec3 f_1 = vec3(1.0, 1.0, 1.0);
        if ((lod_lerp_1 > (1.0 - ratio_lerp_1))) {
            float _e45 = theta_lerp;
            if ((((lod_lerp_1 - (1.0 - ratio_lerp_1)) / max(ratio_lerp_1, 1e-8)) > _e45)) {
                p0_ = a_6;
                p1_ = ee;
                p2_ = d_5;
                p3_1 = f_1;
            } else {
                p0_ = f_1;
                p1_ = ee;
                p2_ = c_4;
                p3_1 = a_6;
            }
        } else {
            p0_ = b_4;
            p1_ = a_6;
            p2_ = c_4;
            p3_1 = ee;
        }
        float _e47 = theta_lerp;
        theta_lerp = (_e47 * ratio_lerp_1);
    } else {
        vec3 a_7 = vec3(0.0, 1.0, 0.0);
        vec3 b_5 = vec3(0.0, 0.0, 0.0);
        vec3 c_5 = vec3(0.5, 1.0, 0.0);
        vec3 d_6 = vec3(1.0, 0.0, 0.0);
        vec3 ee_1 = vec3(1.0, 1.0, 0.0);
        vec3 f_2 = vec3(0.0, 1.0, 1.0);
        vec3 g_1 = vec3(0.0, 0.0, 1.0);
        vec3 h_1 = vec3(0.5, 1.0, 1.0);
        vec3 i = vec3(1.0, 0.0, 1.0);
        vec3 j = vec3(1.0, 1.0, 1.0);
        float _e89 = theta_lerp;
        if ((_e89 < 0.5)) {
            float _e94 = theta_lerp;
            local_1 = ((_e94 * 2.0) < ratio_lerp_1);
        } else {
            local_1 = false;
        }
        bool _e99 = local_1;
        if (_e99) {
            if ((lod_lerp_1 > (1.0 - ratio_lerp_1))) {
                float _e109 = theta_lerp;
                if ((((lod_lerp_1 - (1.0 - ratio_lerp_1)) / max(ratio_lerp_1, 1e-8)) > ((_e109 * 2.0) / max(ratio_lerp_1, 1e-8)))) {
                    p0_ = a_7;
                    p1_ = f_2;
                    p2_ = h_1;
                    p3_1 = g_1;
                } else {
                    p0_ = c_5;
                    p1_ = a_7;
                    p2_ = h_1;
                    p3_1 = g_1;
                }
            } else {
                p0_ = b_5;
                p1_ = a_7;
                p2_ = c_5;
                p3_1 = g_1;
            }
        } else {
            float _e116 = theta_lerp;
            if (((1.0 - ((_e116 - 0.5) * 2.0)) > ratio_lerp_1)) {
                if ((lod_lerp_1 < (1.0 - ratio_lerp_1))) {
                    float half_width = (0.5 * (1.0 - ratio_lerp_1));
                    float _e136 = theta_lerp;
                    if (((lod_lerp_1 / max((1.0 - ratio_lerp_1), 1e-8)) > ((_e136 - (0.5 - half_width)) / max((2.0 * half_width), 1e-8)))) {
                        p0_ = b_5;
                        p1_ = g_1;
                        p2_ = i;
                        p3_1 = c_5;
                    } else {
                        p0_ = d_6;
                        p1_ = b_5;
                        p2_ = c_5;
                        p3_1 = i;
                    }
                } else {
                    p0_ = c_5;
                    p1_ = g_1;
                    p2_ = h_1;
                    p3_1 = i;
                }
            } else {
                if ((lod_lerp_1 > (1.0 - ratio_lerp_1))) {
                    float _e155 = theta_lerp;
                    if ((((lod_lerp_1 - (1.0 - ratio_lerp_1)) / max(ratio_lerp_1, 1e-8)) > ((((_e155 - 0.5) * 2.0) - (1.0 - ratio_lerp_1)) / max(ratio_lerp_1, 1e-8)))) {
                        p0_ = c_5;
                        p1_ = j;
                        p2_ = h_1;
                        p3_1 = i;
                    } else {
                        p0_ = ee_1;
                        p1_ = i;
                        p2_ = c_5;
                        p3_1 = j;
                    }
                } else {
                    p0_ = d_6;
                    p1_ = ee_1;
                    p2_ = c_5;
                    p3_1 = i;
                }
            }
        }
    }
    vec3 _e169 = p0_;
    out_4.p0_ = _e169;
    vec3 _e171 = p1_;
    out_4.p1_ = _e171;
    vec3 _e173 = p2_;
    out_4.p2_ = _e173;
    vec3 _e175 = p3_1;
    out_4.p3_ = _e175;
    float _e177 = theta_lerp;
    vec3 _e179 = p0_;
    vec3 _e180 = p1_;
    vec3 _e181 = p2_;
    vec3 _e182 = p3_1;
    vec4 _e183 = glint_tetra_weights(vec3(_e177, ratio_lerp_1, lod_lerp_1), _e179, _e180, _e181, _e182);
    out_4.w = _e183;
    out_4.center = center_1;
    out_4.bin0_ = _e2.bin0_;
    out_4.bin_h = _e2.bin_h;
    out_4.bin1_ = _e2.bin1_;
    out_4.lod0_ = _e2.lod0_;
    out_4.ratio0_ = _e2.ratio0_;
    GlintTetra _e195 = out_4;
    return _e195;
}

GlintGrid glint_vertex_grid(vec2 uv_4, vec3 p_2, float weight_1, bool center, float bin0_, float bin_h, float bin1_, float lod0_, float ratio0_) {
    float theta_2 = 0.0;
    bool local_2 = false;
    float rot_index = (p_2.x * 2.0);
    theta_2 = ((rot_index < 0.5) ? bin0_ : ((rot_index < 1.5) ? bin_h : bin1_));
    if (center) {
        local_2 = (p_2.y == 0.0);
    } else {
        local_2 = false;
    }
    bool _e25 = local_2;
    if (_e25) {
        theta_2 = 0.0;
    }
    float ratio_2 = ((p_2.y > 0.5) ? (ratio0_ * 2.0) : ratio0_);
    float lod_2 = (lod0_ + p_2.z);
    float _e35 = theta_2;
    GlintGrid _e36 = glint_make_grid(uv_4, lod_2, _e35, ratio_2, weight_1);
    return _e36;
}

GlintGrids glint_grids(vec2 uv_5, GlintEllipse e_4, float screen_scale_3) {
    GlintGrids out_5 = GlintGrids(GlintGrid(vec2(0.0), 0u, 0.0, 0.0), GlintGrid(vec2(0.0), 0u, 0.0, 0.0), GlintGrid(vec2(0.0), 0u, 0.0, 0.0), GlintGrid(vec2(0.0), 0u, 0.0, 0.0));
    GlintTetra _e3 = glint_tetra(e_4, screen_scale_3);
    GlintGrid _e15 = glint_vertex_grid(uv_5, _e3.p0_, _e3.w.x, _e3.center, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g0_ = _e15;
    GlintGrid _e26 = glint_vertex_grid(uv_5, _e3.p1_, _e3.w.y, _e3.center, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g1_ = _e26;
    GlintGrid _e37 = glint_vertex_grid(uv_5, _e3.p2_, _e3.w.z, _e3.center, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g2_ = _e37;
    GlintGrid _e48 = glint_vertex_grid(uv_5, _e3.p3_, _e3.w.w, _e3.center, _e3.bin0_, _e3.bin_h, _e3.bin1_, _e3.lod0_, _e3.ratio0_);
    out_5.g3_ = _e48;
    GlintGrids _e49 = out_5;
    return _e49;
}

float glint_ndf(GlintParams params_1, GlintGrids grids, vec2 slope_2, float d_1, float d_max, bool poly_normals_4) {
    float target_ndf_1 = (d_1 / d_max);
    float _e8 = glint_sample_grid(params_1, grids.g0_, slope_2, target_ndf_1, poly_normals_4);
    float _e10 = glint_sample_grid(params_1, grids.g1_, slope_2, target_ndf_1, poly_normals_4);
    float _e13 = glint_sample_grid(params_1, grids.g2_, slope_2, target_ndf_1, poly_normals_4);
    float _e16 = glint_sample_grid(params_1, grids.g3_, slope_2, target_ndf_1, poly_normals_4);
    float sum = (((_e8 + _e10) + _e13) + _e16);
    return (min((sum / params_1.micro_roughness), 20.0) * d_max);
}

void main() {
    WeftVertexInput in_ = WeftVertexInput(_p2vs_location0, _p2vs_location1, _p2vs_location2, _p2vs_location3);
    WeftVaryings _e1 = weft_forward_vertex(in_);
    gl_Position = _e1.clip_position;
    _vs2fs_location0 = _e1.world_position;
    _vs2fs_location1 = _e1.world_normal;
    _vs2fs_location2 = _e1.world_tangent;
    _vs2fs_location3 = _e1.uv0_;
    gl_Position.yz = vec2(-gl_Position.y, gl_Position.z * 2.0 - gl_Position.w);
    return;
}

