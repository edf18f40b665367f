// Minimal vertex stage for the diagnostics corpus: position, normal and uv0
// (the default `requires`), transformed by the engine interface's matrices.

struct VertexInput {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(3) uv0: vec2<f32>,
}

struct Varyings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_normal: vec3<f32>,
    @location(1) uv0: vec2<f32>,
}

@vertex
fn vs_main(in: VertexInput) -> Varyings {
    let world = weft_object.model * vec4<f32>(in.position, 1.0);
    let nm = weft_object.normal_matrix;
    var out: Varyings;
    out.clip_position = weft_frame.view_proj * world;
    out.world_normal = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz) * in.normal;
    out.uv0 = in.uv0;
    return out;
}
