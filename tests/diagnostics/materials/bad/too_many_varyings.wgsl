// A vertex stage of its own: 17 varyings.

struct VertexInput {
    @location(0) position: vec3<f32>,
    @location(3) uv0: vec2<f32>,
}

struct Varyings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) v0: vec4<f32>,
    @location(1) v1: vec4<f32>,
    @location(2) v2: vec4<f32>,
    @location(3) v3: vec4<f32>,
    @location(4) v4: vec4<f32>,
    @location(5) v5: vec4<f32>,
    @location(6) v6: vec4<f32>,
    @location(7) v7: vec4<f32>,
    @location(8) v8: vec4<f32>,
    @location(9) v9: vec4<f32>,
    @location(10) v10: vec4<f32>,
    @location(11) v11: vec4<f32>,
    @location(12) v12: vec4<f32>,
    @location(13) v13: vec4<f32>,
    @location(14) v14: vec4<f32>,
    @location(15) v15: vec4<f32>,
    @location(16) v16: vec4<f32>,
}

@vertex
fn vs_main(in: VertexInput) -> Varyings {
    var out: Varyings;
    out.clip_position = weft_frame.view_proj * weft_object.model * vec4<f32>(in.position, 1.0);
    out.v0 = vec4<f32>(in.uv0, 0.0, 1.0);
    out.v1 = vec4<f32>(in.uv0, 1.0, 1.0);
    out.v2 = vec4<f32>(in.uv0, 2.0, 1.0);
    out.v3 = vec4<f32>(in.uv0, 3.0, 1.0);
    out.v4 = vec4<f32>(in.uv0, 4.0, 1.0);
    out.v5 = vec4<f32>(in.uv0, 5.0, 1.0);
    out.v6 = vec4<f32>(in.uv0, 6.0, 1.0);
    out.v7 = vec4<f32>(in.uv0, 7.0, 1.0);
    out.v8 = vec4<f32>(in.uv0, 8.0, 1.0);
    out.v9 = vec4<f32>(in.uv0, 9.0, 1.0);
    out.v10 = vec4<f32>(in.uv0, 10.0, 1.0);
    out.v11 = vec4<f32>(in.uv0, 11.0, 1.0);
    out.v12 = vec4<f32>(in.uv0, 12.0, 1.0);
    out.v13 = vec4<f32>(in.uv0, 13.0, 1.0);
    out.v14 = vec4<f32>(in.uv0, 14.0, 1.0);
    out.v15 = vec4<f32>(in.uv0, 15.0, 1.0);
    out.v16 = vec4<f32>(in.uv0, 16.0, 1.0);
    return out;
}

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    return in.v0 + in.v16;
}
