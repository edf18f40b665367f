// @include "lib/common.wgsl"

struct ShadeIn {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) @interpolate(linear) world_normal: vec3<f32>,
    @location(1) uv0: vec3<f32>,
    @location(2) tint: vec4<f32>,
}

@fragment
fn fs_shade(in: ShadeIn) -> @location(0) vec4<f32> {
    return vec4<f32>(in.world_normal + in.uv0, 1.0) * in.tint;
}
