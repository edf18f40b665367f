// @include "lib/common.wgsl"

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    let shade = 0.5 + 0.5 * normalize(in.world_normal).z
    return vec4<f32>(material.tint.rgb * shade, 1.0);
}
