// @include "lib/common.wgsl"
// @include "lib/cycle_a.wgsl"

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    return vec4<f32>(in.uv0, cycle_a(), 1.0);
}
