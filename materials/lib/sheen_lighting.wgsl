// @include "lib/sheen.wgsl"
// @include "lib/lighting.wgsl"
//
// weft sheen lighting: the one function of the sheen library that reads a
// group 0 binding of the engine interface (weft_sheen_lut, the toolchain-baked
// Charlie albedo table). Only variants that call it bind the table.

// Directional albedo E(n.v, r) of the Charlie sheen BRDF with sheen colour 1
// (crates/weft-compiler/src/bake/sheen.rs: u = N.V, v = sheen roughness,
// texel centres, rows below r = 0.07 hold the clamped value). In [0, 1].
fn weft_sheen_albedo(n_dot_x: f32, sheen_roughness: f32) -> f32 {
    let uv = vec2<f32>(saturate(n_dot_x), weft_sheen_clamp_roughness(sheen_roughness));
    return saturate(textureSampleLevel(weft_sheen_lut, weft_lut_sampler, uv, 0.0).r);
}

// No nearest-texel read of the table: it saved llvmpipe's software filter,
// but on a GPU the sampler filters for free and rounding the coordinate in
// ALU costs more (docs/performance.md, issue 24).
