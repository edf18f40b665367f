// @include "lib/common.wgsl"
// @include "lib/broken.wgsl"

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    return vec4<f32>(broken_helper(in.uv0), 0.0, 1.0);
}
