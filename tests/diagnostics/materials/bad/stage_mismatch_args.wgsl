// @include "lib/common.wgsl"

@fragment
fn fs_args(
    @location(0) world_normal: vec2<f32>,
    @location(5) tint: vec4<f32>,
) -> @location(0) vec4<f32> {
    return vec4<f32>(world_normal, 0.0, 1.0) * tint;
}
