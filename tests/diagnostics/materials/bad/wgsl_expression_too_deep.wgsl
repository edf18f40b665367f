// @include "lib/common.wgsl"

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    let u = in.uv0.x;
    let sum = u
        + u + u + u + u + u + u + u + u + u + u + u + u + u + u + u + u
        + u + u + u + u + u + u + u + u + u + u + u + u + u + u + u + u
        + u + u + u + u + u + u + u + u + u + u + u + u + u + u + u + u
        + u + u + u + u + u + u + u + u + u + u + u + u + u + u + u + u
        + u + u + u + u + u + u + u + u + u + u + u + u + u + u + u + u;
    return vec4<f32>(sum, 0.0, 0.0, 1.0);
}
