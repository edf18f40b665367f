// @include "lib/common.wgsl"

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    let shade = f16(0.5) + f16(0.5) * f16(normalize(in.world_normal).z);
    return vec4<f32>(material.tint.rgb * f32(shade), 1.0);
}
