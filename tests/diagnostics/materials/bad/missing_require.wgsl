struct TangentInput {
    @location(0) position: vec3<f32>,
    @location(2) tangent: vec4<f32>,
}

struct TangentVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) tangent: vec3<f32>,
}

@vertex
fn vs_main(in: TangentInput) -> TangentVaryings {
    var out: TangentVaryings;
    out.clip_position = weft_frame.view_proj * (weft_object.model * vec4<f32>(in.position, 1.0));
    out.tangent = in.tangent.xyz;
    return out;
}

@fragment
fn fs_main(in: TangentVaryings) -> @location(0) vec4<f32> {
    return vec4<f32>(in.tangent * 0.5 + 0.5, 1.0);
}
