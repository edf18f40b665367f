// @include "lib/surface.wgsl"
//
// weft forward library: the standard vertex stage (vs_main) and the
// fragment-side helpers that go with its varyings.

struct WeftVertexInput {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    // xyz: object-space tangent; w: bitangent sign (+1 or -1).
    @location(2) tangent: vec4<f32>,
    @location(3) uv0: vec2<f32>,
}

struct WeftVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    // Unit at the vertices (zero if the mesh normal is degenerate); renormalise
    // after interpolation.
    @location(1) world_normal: vec3<f32>,
    // xyz: world tangent; w: bitangent sign (+1 or -1), already flipped for
    // mirroring model matrices.
    @location(2) world_tangent: vec4<f32>,
    @location(3) uv0: vec2<f32>,
}

@vertex
fn vs_main(in: WeftVertexInput) -> WeftVaryings {
    return weft_forward_vertex(in);
}

// The body of vs_main, for a material whose vertex stage adds varyings of its
// own (microcylinder's vs_microcylinder, hair's vs_hair: values of their
// uniforms alone, flat).
fn weft_forward_vertex(in: WeftVertexInput) -> WeftVaryings {
    let model = weft_object.model;
    let model3 = mat3x3<f32>(model[0].xyz, model[1].xyz, model[2].xyz);
    let nm = weft_object.normal_matrix;
    let normal3 = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = model * vec4<f32>(in.position, 1.0);

    // A model matrix with negative determinant mirrors the mesh: flip the
    // bitangent so the tangent frame keeps its handedness (Unity's
    // unity_WorldTransformParams.w). w = 0 counts as +1.
    let mirror = select(1.0, -1.0, determinant(model3) < 0.0);
    let bitangent_sign = select(1.0, -1.0, in.tangent.w < 0.0) * mirror;

    var out: WeftVaryings;
    out.clip_position = weft_frame.view_proj * vec4<f32>(world.xyz, 1.0);
    out.world_position = world.xyz;
    // Degenerate normals stay zero; the fragment stage falls back.
    out.world_normal = weft_safe_normalize(normal3 * in.normal, vec3<f32>(0.0));
    // Tangents are surface directions: they transform with the model matrix.
    out.world_tangent = vec4<f32>(weft_safe_normalize(model3 * in.tangent.xyz, vec3<f32>(0.0)), bitangent_sign);
    out.uv0 = in.uv0;
    return out;
}

// Orthonormal tangent frame, columns (T, B, N), from a unit normal `n` and the
// interpolated tangent (xyz, w = bitangent sign). Gram-Schmidt removes the
// normal component of the tangent; if what is left is (relatively) tiny, i.e.
// the tangent is zero-length or parallel to n, any perpendicular is used.
fn weft_tangent_frame(n: vec3<f32>, tangent: vec4<f32>) -> mat3x3<f32> {
    let t_in = tangent.xyz;
    let t_proj = t_in - n * dot(n, t_in);
    let len2 = dot(t_proj, t_proj);
    // Relative test (1e-6 = sin^2 of ~0.06 deg) plus an absolute floor for
    // zero-length tangents.
    let ok = len2 > max(1e-6 * dot(t_in, t_in), 1e-20);
    let t = select(weft_any_perpendicular(n), t_proj * inverseSqrt(max(len2, 1e-20)), ok);
    let s = select(1.0, -1.0, tangent.w < 0.0);
    let b = cross(n, t) * s;
    return mat3x3<f32>(t, b, n);
}

// Tangent-space normal from a linear normal-map texel (rgb in [0, 1]) scaled
// by `strength` (Unity UnpackNormalScale: xy scaled, z kept). z is floored at
// a small positive value so a broken texel cannot produce a zero or inward
// vector; the result is not normalised (weft_normal_from_tangent_space does).
fn weft_unpack_normal(texel: vec3<f32>, strength: f32) -> vec3<f32> {
    let v = texel * 2.0 - 1.0;
    return vec3<f32>(v.xy * strength, max(v.z, 1e-3));
}

// World-space unit normal from a tangent-space one; falls back to the frame's
// normal if the transformed vector vanishes.
fn weft_normal_from_tangent_space(frame: mat3x3<f32>, n_ts: vec3<f32>) -> vec3<f32> {
    return weft_safe_normalize(frame * n_ts, frame[2]);
}

// A normal map's normal: the texel (linear rgb in [0, 1], scaled by
// `strength`) in the tangent frame of the unit normal n and the interpolated
// tangent.
fn weft_mapped_normal(n: vec3<f32>, tangent: vec4<f32>, texel: vec3<f32>, strength: f32) -> vec3<f32> {
    return weft_normal_from_tangent_space(weft_tangent_frame(n, tangent), weft_unpack_normal(texel, strength));
}

// Unity-style texture transform: uv * tiling + offset (st = xy tiling, zw offset).
fn weft_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return uv * st.xy + st.zw;
}
