// @include "lib/common.wgsl"

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    let t = in.uv0.x;
    let v = curve_falloff(t) + curve_profile(t) + curve_sheen(t) + curve_rim(t) + curve_scatter(t);
    return vec4<f32>(v, v, v, 1.0);
}
