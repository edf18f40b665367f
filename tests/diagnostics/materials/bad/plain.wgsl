// Shared WGSL for the corpus materials whose error is in their TOML: valid on
// its own, so each TOML fails only for the reason its file name gives.
// @include "lib/common.wgsl"

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    return vec4<f32>(in.uv0, 0.0, 1.0);
}
