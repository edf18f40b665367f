// @include "lib/common.wgsl"
// @include "lib/noise.wgsl"

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    return vec4<f32>(in.uv0, 0.0, 1.0);
}
