// A small vertex stage and lighting helpers for the documentation examples
// (docs/material-format.md). Real materials include materials/lib/forward.wgsl.
//
// Reads position, normal and uv0: the default `requires` of a material.

struct SurfaceInput {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(3) uv0: vec2<f32>,
}

struct SurfaceVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) uv0: vec2<f32>,
}

// Object space -> varyings, with the vertex pushed `offset` along its normal.
fn surface_transform(in: SurfaceInput, offset: f32) -> SurfaceVaryings {
    let nm = weft_object.normal_matrix;
    let normal = normalize(mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz) * in.normal);
    let world = (weft_object.model * vec4<f32>(in.position, 1.0)).xyz + normal * offset;
    var out: SurfaceVaryings;
    out.clip_position = weft_frame.view_proj * vec4<f32>(world, 1.0);
    out.world_position = world;
    out.world_normal = normal;
    out.uv0 = in.uv0;
    return out;
}

@vertex
fn vs_main(in: SurfaceInput) -> SurfaceVaryings {
    return surface_transform(in, 0.0);
}

// Unit vector towards the main light.
fn surface_light_direction() -> vec3<f32> {
    return normalize(weft_frame.light_direction.xyz);
}

// Unit vector towards the camera.
fn surface_view_direction(world_position: vec3<f32>) -> vec3<f32> {
    return normalize(weft_frame.camera_position.xyz - world_position);
}

// Unity-style texture transform: xy tiling, zw offset (a texture's `<name>_st`).
fn surface_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return uv * st.xy + st.zw;
}
