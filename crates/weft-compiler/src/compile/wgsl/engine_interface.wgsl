// weft engine interface, version 2 (v1 + `WeftFrame.viewport`).
//
// Composed ahead of every material by the toolchain (never edited per material).
// Group 0 is per frame, group 1 per material (generated from the material's
// parameter list), group 2 per object. Engines bind these; the inspector
// metadata lists exactly the bindings each variant still uses.

// Engine features. Library variants are built with every feature provided
// (these defaults); a scene build fixes them to what the scene provides, and
// code that tests them with an ordinary `if` is removed where a feature is
// absent (docs/scenes.md). Engine interface v1 has one directional light slot.
override WEFT_ENVIRONMENT: bool = true;
override WEFT_SH_AMBIENT: bool = true;
override WEFT_DIRECTIONAL_LIGHTS: u32 = 1u;

const WEFT_PI: f32 = 3.14159265358979;
const WEFT_INV_PI: f32 = 0.318309886183791;

struct WeftFrame {
    // World -> clip.
    view_proj: mat4x4<f32>,
    // World -> view (rotation + translation), for view-space effects (sphere maps).
    view: mat4x4<f32>,
    // xyz: camera position in world space; w: unused.
    camera_position: vec4<f32>,
    // xyz: unit direction from the surface towards the main light; w: unused.
    light_direction: vec4<f32>,
    // rgb: main light radiance (linear); a: unused.
    light_color: vec4<f32>,
    // L2 spherical-harmonic irradiance coefficients (rgb in xyz), already
    // convolved with the clamped cosine and divided by pi: E(n)/pi = sum c_i Y_i(n),
    // with the orthonormal real basis in the order
    // Y00, Y1-1 (y), Y10 (z), Y11 (x), Y2-2 (xy), Y2-1 (yz), Y20 (3z^2-1), Y21 (xz), Y22 (x^2-y^2).
    sh: array<vec4<f32>, 9>,
    // x: number of mip levels of the prefiltered environment cube;
    // y: exposure; z: time in seconds; w: unused.
    params: vec4<f32>,
    // xy: size of the colour target in pixels; zw: 1 / xy. For effects sized
    // in pixels (outlines); all zero when an engine does not know it, which
    // such code must survive (lib/outline.wgsl draws no outline then).
    viewport: vec4<f32>,
}

struct WeftObject {
    // Object -> world.
    model: mat4x4<f32>,
    // Inverse-transpose of the upper 3x3 of `model`, in a mat4 for alignment.
    normal_matrix: mat4x4<f32>,
}

@group(0) @binding(0) var<uniform> weft_frame: WeftFrame;
// Prefiltered (GGX) radiance cube. Mip m holds radiance prefiltered at the
// perceptual roughness r with r (1.7 - 0.7 r) (mip_count - 1) = m: the mapping
// of seed 004 sec. 2.3 that lib/lighting.wgsl (weft_specular_mip) samples with.
@group(0) @binding(1) var weft_environment: texture_cube<f32>;
@group(0) @binding(2) var weft_environment_sampler: sampler;
// Split-sum environment BRDF LUT baked by the toolchain (generated/luts/):
// u = N.V, v = perceptual roughness; rg = (scale, bias) applied to F0.
@group(0) @binding(3) var weft_brdf_lut: texture_2d<f32>;
@group(0) @binding(4) var weft_lut_sampler: sampler;
// Directional albedo E of the Charlie sheen BRDF (sheen colour 1), baked by the
// toolchain (generated/luts/charlie_albedo_*.r16f, R16Float): u = N.V, v = sheen
// roughness (Charlie r, clamped to >= 0.07 as in lib/sheen.wgsl), texel centres;
// r = E. Sample with weft_lut_sampler (linear, clamp to edge).
@group(0) @binding(5) var weft_sheen_lut: texture_2d<f32>;

@group(2) @binding(0) var<uniform> weft_object: WeftObject;
