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
struct GlintTetraFast {
    uint codes;
    vec4 w;
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
    float r = clamp(roughness_4, 0.0, 1.0);
    float _e5 = _group_0_binding_0_vs.params.x;
    float max_mip = max((_e5 - 1.0), 0.0);
    return ((r * (1.7 - (0.7 * r))) * max_mip);
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

vec2 weft_transform_uv(vec2 uv, vec4 st) {
    return ((uv * st.xy) + st.zw);
}

uvec3 glint_pcg3d(uvec3 v_in) {
    uvec3 v_2 = uvec3(0u);
    v_2 = ((v_in * 1664525u) + uvec3(1013904223u));
    uint _e8 = v_2.x;
    uint _e10 = v_2.y;
    uint _e12 = v_2.z;
    v_2.x = (_e8 + (_e10 * _e12));
    uint _e16 = v_2.y;
    uint _e18 = v_2.z;
    uint _e20 = v_2.x;
    v_2.y = (_e16 + (_e18 * _e20));
    uint _e24 = v_2.z;
    uint _e26 = v_2.x;
    uint _e28 = v_2.y;
    v_2.z = (_e24 + (_e26 * _e28));
    uvec3 _e31 = v_2;
    uvec3 _e32 = v_2;
    v_2 = (_e31 ^ (_e32 >> uvec3(16u)));
    uint _e38 = v_2.x;
    uint _e40 = v_2.y;
    uint _e42 = v_2.z;
    v_2.x = (_e38 + (_e40 * _e42));
    uint _e46 = v_2.y;
    uint _e48 = v_2.z;
    uint _e50 = v_2.x;
    v_2.y = (_e46 + (_e48 * _e50));
    uint _e54 = v_2.z;
    uint _e56 = v_2.x;
    uint _e58 = v_2.y;
    v_2.z = (_e54 + (_e56 * _e58));
    uvec3 _e61 = v_2;
    return _e61;
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

GlintSimplex glint_simplex(vec2 uv_1) {
    vec2 skewed = vec2((uv_1.x - (0.57735026 * uv_1.y)), (1.1547005 * uv_1.y));
    vec2 base = floor(skewed);
    vec2 f = (skewed - base);
    float fz = ((1.0 - f.x) - f.y);
    float s_2 = ((fz < 0.0) ? 1.0 : 0.0);
    float s2_ = ((2.0 * s_2) - 1.0);
    return GlintSimplex(ivec2(base), int(s_2), vec3((-(fz) * s2_), (s_2 - (f.y * s2_)), (s_2 - (f.x * s2_))));
}

GlintEllipse glint_ellipse(vec2 duv_dx, vec2 duv_dy) {
    GlintEllipse out_1 = GlintEllipse(vec2(0.0), 0.0, 0.0);
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
    out_1.major_dir = ((e_len2_ > 1e-37) ? (e_5 * inversesqrt(max(e_len2_, 1e-37))) : vec2(1.0, 0.0));
    out_1.major = max(sqrt(l1_), 1e-12);
    float _e68 = out_1.major;
    out_1.minor = max(sqrt(l2_), (_e68 / 64.0));
    GlintEllipse _e72 = out_1;
    return _e72;
}

vec2 glint_rotate(vec2 uv_2, float angle) {
    float c_4 = cos(angle);
    float s_3 = sin(angle);
    return vec2(((c_4 * uv_2.x) + (s_3 * uv_2.y)), ((c_4 * uv_2.y) - (s_3 * uv_2.x)));
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

vec4 glint_tetra_weights(vec3 p, vec3 a, vec3 b, vec3 c_1, vec3 d) {
    vec3 c1_ = (a - d);
    vec3 c2_ = (b - d);
    vec3 c3_ = (c_1 - d);
    vec3 q = (p - d);
    float det = dot(c1_, cross(c2_, c3_));
    float inv = (1.0 / det);
    float w1_ = (dot(q, cross(c2_, c3_)) * inv);
    float w2_ = (dot(c1_, cross(q, c3_)) * inv);
    float w3_ = (dot(c1_, cross(c2_, q)) * inv);
    return vec4(w1_, w2_, w3_, (((1.0 - w1_) - w2_) - w3_));
}

float glint_lod(GlintEllipse e_1, float screen_scale) {
    return clamp(log2(((e_1.minor * screen_scale) * 0.5)), GLINT_MIN_LOD, GLINT_MAX_LOD);
}

GlintFootprintCell glint_footprint_cell(GlintEllipse e_2, float screen_scale_1) {
    GlintFootprintCell out_2 = GlintFootprintCell(0.0, 0.0, 0.0, false, 0.0, 0.0, 0.0, 0.0, 0.0);
    float ratio_e = min((e_2.major / (e_2.minor + (1e-8 * e_2.major))), GLINT_MAX_RATIO);
    float _e11 = glint_lod(e_2, screen_scale_1);
    float lod0_ = floor(_e11);
    float lod_lerp = (_e11 - lod0_);
    float ratio0_ = max(exp2(floor(log2(max(ratio_e, 1.0)))), 1.0);
    float ratio1_ = (ratio0_ * 2.0);
    float ratio_lerp = clamp(((ratio_e - ratio0_) / (ratio1_ - ratio0_)), 0.0, 1.0);
    float q_1 = (0.7853982 / max(ratio0_, 2.0));
    float per_pi = (4.0 * max(ratio0_, 2.0));
    float theta_2 = atan(-(e_2.major_dir.x), e_2.major_dir.y);
    float theta_q = (theta_2 / q_1);
    float h0_ = floor(theta_q);
    float theta_lerp = clamp((theta_q - h0_), 0.0, 1.0);
    float i0_ = (h0_ - (per_pi * floor((h0_ / per_pi))));
    float i1_ = ((i0_ + 1.0) - (per_pi * floor(((i0_ + 1.0) / per_pi))));
    float theta_bin0_ = (i0_ * q_1);
    float theta_bin_h = ((i0_ + 0.5) * q_1);
    float theta_bin1_ = (i1_ * q_1);
    out_2.theta_lerp = theta_lerp;
    out_2.ratio_lerp = ratio_lerp;
    out_2.lod_lerp = lod_lerp;
    out_2.center = (ratio0_ == 1.0);
    out_2.bin0_ = theta_bin0_;
    out_2.bin_h = theta_bin_h;
    out_2.bin1_ = theta_bin1_;
    out_2.lod0_ = lod0_;
    out_2.ratio0_ = ratio0_;
    GlintFootprintCell _e74 = out_2;
    return _e74;
}

float glint_normal_fast(uint h_1) {
    float x_2 = fma(float(h_1), 4.656613e-10, -1.0);
    float x2_1 = (x_2 * x_2);
    return (x_2 * (1.2225 + (x2_1 * (0.75468 + (x2_1 * (-1.263127 + (x2_1 * 1.568366)))))));
}

float glint_corner_hits(uint ax, uint ay, float gate_a, float gate_b, float deviation, float mean1_) {
    uint x_1 = 0u;
    uint y = 0u;
    uint z = 0u;
    uint w = 0u;
    x_1 = (ax + (ay * 1860535849u));
    uint _e10 = x_1;
    y = (ay + (_e10 * 220351156u));
    uint _e16 = x_1;
    uint _e17 = y;
    z = (220351156u + (_e16 * _e17));
    uint _e22 = y;
    uint _e23 = z;
    w = (1860535849u + (_e22 * _e23));
    uint _e27 = x_1;
    uint _e28 = x_1;
    x_1 = (_e27 ^ (_e28 >> 16u));
    uint _e32 = y;
    uint _e33 = y;
    y = (_e32 ^ (_e33 >> 16u));
    uint _e37 = z;
    uint _e38 = z;
    z = (_e37 ^ (_e38 >> 16u));
    uint _e42 = w;
    uint _e43 = w;
    w = (_e42 ^ (_e43 >> 16u));
    uint _e47 = x_1;
    uint _e48 = y;
    uint _e49 = w;
    x_1 = (_e47 + (_e48 * _e49));
    uint _e52 = y;
    uint _e53 = z;
    uint _e54 = x_1;
    y = (_e52 + (_e53 * _e54));
    uint _e57 = x_1;
    float gate = clamp(fma(float(_e57), gate_a, gate_b), 0.0, 1.0);
    uint _e61 = y;
    float _e62 = glint_normal_fast(_e61);
    float count = max(floor(fma(_e62, deviation, mean1_)), 1.0);
    return (gate * count);
}

float glint_cell_fast(GlintParams params, GlintGrid grid, ivec2 c_2, vec2 s_slope, float p_1, float log2_q) {
    uvec3 _e16 = glint_pcg3d(uvec3((uint(c_2.x) + 2147483648u), (uint(c_2.y) + 2147483648u), grid.seed));
    float _e18 = glint_normal_fast(_e16.x);
    float log_density = clamp(((_e18 * params.density_randomization) + params.log_density), 0.0, 50.0);
    float count_1 = max(1e-8, (grid.cell_area * exp(log_density)));
    float blended = (count_1 * grid.weight);
    float miss = exp2((blended * log2_q));
    float one_hit = (1.0 - miss);
    float others = max((blended - 1.0), 0.0);
    float mean1_1 = ((others * p_1) + 1.0);
    float deviation_1 = sqrt((others * (p_1 * (1.0 - p_1))));
    float width = max(((0.1 * clamp((one_hit * 10.0), 0.0, 1.0)) * clamp((miss * 10.0), 0.0, 1.0)), 1e-30);
    float inv_1 = (0.5 / width);
    float gate_a_1 = (inv_1 * -2.3283064e-10);
    float gate_b_1 = fma(one_hit, inv_1, 0.5);
    vec2 s_4 = fma(vec2((_e16.yz >> uvec2(8u))), vec2(3.8146973e-6), s_slope);
    vec2 cell = floor(s_4);
    vec2 l = (s_4 - cell);
    uvec2 ci = uvec2(cell);
    uvec2 t0_ = (ci & uvec2(63u));
    uvec2 t1_ = ((ci + uvec2(1u)) & uvec2(63u));
    uvec2 ax_1 = ((uvec2(t0_.x, t1_.x) * 1664525u) + uvec2(1013904223u));
    uvec2 ay_1 = ((uvec2(t0_.y, t1_.y) * 1664525u) + uvec2(1013904223u));
    float _e104 = glint_corner_hits(ax_1.x, ay_1.x, gate_a_1, gate_b_1, deviation_1, mean1_1);
    float _e107 = glint_corner_hits(ax_1.x, ay_1.y, gate_a_1, gate_b_1, deviation_1, mean1_1);
    float _e110 = glint_corner_hits(ax_1.y, ay_1.x, gate_a_1, gate_b_1, deviation_1, mean1_1);
    float _e113 = glint_corner_hits(ax_1.y, ay_1.y, gate_a_1, gate_b_1, deviation_1, mean1_1);
    float x0_ = mix(_e104, _e110, l.x);
    float x1_ = mix(_e107, _e113, l.x);
    return (mix(x0_, x1_, l.y) / count_1);
}

float glint_sample_grid_fast(GlintParams params_1, GlintGrid grid_1, vec2 s_slope_1, float p_2, float log2_q_1) {
    float sum = 0.0;
    int k = 0;
    GlintSimplex _e6 = glint_simplex(grid_1.uv);
    ivec2 id = _e6.id;
    int si = _e6.si;
    vec3 bary = _e6.bary;
    bool loop_init = true;
    while(true) {
        if (!loop_init) {
            int _e47 = k;
            k = (_e47 + 1);
        }
        loop_init = false;
        int _e14 = k;
        if ((_e14 < 3)) {
        } else {
            break;
        }
        {
            int _e19 = k;
            int _e25 = k;
            ivec2 c_5 = (id + ivec2(((_e19 == 2) ? (1 - si) : si), ((_e25 == 1) ? (1 - si) : si)));
            int _e33 = k;
            int _e38 = k;
            float b_4 = ((_e38 == 0) ? bary.x : ((_e33 == 1) ? bary.y : bary.z));
            float _e42 = sum;
            float _e43 = glint_cell_fast(params_1, grid_1, c_5, s_slope_1, p_2, log2_q_1);
            sum = (_e42 + (b_4 * _e43));
        }
    }
    float _e49 = sum;
    return _e49;
}

vec3 glint_vertex_of_code(uint c_3) {
    uint rot = (c_3 & 3u);
    return vec3(((rot == 3u) ? 0.0 : (float(rot) * 0.5)), float(((c_3 >> 2u) & 1u)), float((c_3 >> 3u)));
}

GlintTetraFast glint_tetra_fast(GlintEllipse e_3, float screen_scale_2) {
    bool local_1 = false;
    GlintTetraFast out_3 = GlintTetraFast(0u, vec4(0.0), 0.0, 0.0, 0.0, 0.0, 0.0);
    GlintFootprintCell _e2 = glint_footprint_cell(e_3, screen_scale_2);
    float t_2 = _e2.theta_lerp;
    float r_1 = _e2.ratio_lerp;
    float l_1 = _e2.lod_lerp;
    bool upper = (l_1 > (1.0 - r_1));
    float upper_left = ((l_1 - (1.0 - r_1)) / max(r_1, 1e-8));
    float half_width = (0.5 * (1.0 - r_1));
    uint center_codes = (upper ? ((upper_left > t_2) ? GLINT_TET_CENTER_UP : GLINT_TET_CENTER_DOWN) : GLINT_TET_CENTER_LOW);
    uint a_codes = (upper ? ((upper_left > ((t_2 * 2.0) / max(r_1, 1e-8))) ? GLINT_TET_A_UP : GLINT_TET_A_DOWN) : GLINT_TET_A_LOW);
    uint b_codes = ((l_1 < (1.0 - r_1)) ? (((l_1 / max((1.0 - r_1), 1e-8)) > ((t_2 - (0.5 - half_width)) / max((2.0 * half_width), 1e-8))) ? GLINT_TET_B_UP : GLINT_TET_B_DOWN) : GLINT_TET_B_HIGH);
    uint c_codes = (upper ? ((upper_left > ((((t_2 - 0.5) * 2.0) - (1.0 - r_1)) / max(r_1, 1e-8))) ? GLINT_TET_C_UP : GLINT_TET_C_DOWN) : GLINT_TET_C_LOW);
    if ((t_2 < 0.5)) {
        local_1 = ((t_2 * 2.0) < r_1);
    } else {
        local_1 = false;
    }
    bool prism_a = local_1;
    bool prism_b = ((1.0 - ((t_2 - 0.5) * 2.0)) > r_1);
    uint codes = (_e2.center ? center_codes : (prism_a ? a_codes : (prism_b ? b_codes : c_codes)));
    vec3 point = vec3((_e2.center ? (t_2 * r_1) : t_2), r_1, l_1);
    out_3.codes = codes;
    vec3 _e103 = glint_vertex_of_code((codes & 15u));
    vec3 _e108 = glint_vertex_of_code(((codes >> 4u) & 15u));
    vec3 _e113 = glint_vertex_of_code(((codes >> 8u) & 15u));
    vec3 _e116 = glint_vertex_of_code((codes >> 12u));
    vec4 _e117 = glint_tetra_weights(point, _e103, _e108, _e113, _e116);
    out_3.w = _e117;
    out_3.bin0_ = _e2.bin0_;
    out_3.bin_h = _e2.bin_h;
    out_3.bin1_ = _e2.bin1_;
    out_3.lod0_ = _e2.lod0_;
    out_3.ratio0_ = _e2.ratio0_;
    GlintTetraFast _e128 = out_3;
    return _e128;
}

float glint_hits_fast(GlintParams params_2, vec2 uv_4, GlintEllipse e_4, float screen_scale_3, vec2 slope, float d_1, float d_max) {
    float sum_1 = 0.0;
    uint i = 0u;
    GlintTetraFast _e7 = glint_tetra_fast(e_4, screen_scale_3);
    uint codes_1 = _e7.codes;
    float p_4 = (params_2.micro_roughness * (d_1 / d_max));
    float log2_q_2 = log2((1.0 - p_4));
    vec2 s_slope_2 = ((abs(slope) / vec2(params_2.micro_roughness)) + vec2(1.9073486e-6));
    bool loop_init_1 = true;
    while(true) {
        if (!loop_init_1) {
            uint _e97 = i;
            i = (_e97 + 1u);
        }
        loop_init_1 = false;
        uint _e26 = i;
        if ((_e26 < 4u)) {
        } else {
            break;
        }
        {
            uint _e30 = i;
            uint c_6 = ((codes_1 >> (4u * _e30)) & 15u);
            uint rot_1 = (c_6 & 3u);
            float theta_3 = ((rot_1 == 0u) ? _e7.bin0_ : ((rot_1 == 1u) ? _e7.bin_h : ((rot_1 == 2u) ? _e7.bin1_ : 0.0)));
            float ratio_2 = (((c_6 & 4u) != 0u) ? (_e7.ratio0_ * 2.0) : _e7.ratio0_);
            float lod_2 = (_e7.lod0_ + float((c_6 >> 3u)));
            uint _e76 = i;
            uint _e82 = i;
            uint _e88 = i;
            float w_1 = ((_e88 == 0u) ? _e7.w.x : ((_e82 == 1u) ? _e7.w.y : ((_e76 == 2u) ? _e7.w.z : (((1.0 - _e7.w.x) - _e7.w.y) - _e7.w.z))));
            float _e92 = sum_1;
            GlintGrid _e93 = glint_make_grid(uv_4, lod_2, theta_3, ratio_2, w_1);
            float _e94 = glint_sample_grid_fast(params_2, _e93, s_slope_2, p_4, log2_q_2);
            sum_1 = (_e92 + _e94);
        }
    }
    float _e99 = sum_1;
    return _e99;
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

