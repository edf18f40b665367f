// @include "lib/common.wgsl"
// @include "../outside.wgsl"

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    return vec4<f32>(in.uv0, outside(), 1.0);
}
