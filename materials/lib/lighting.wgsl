// @include "lib/brdf.wgsl"
//
// weft lighting library: reads the group 0 frame bindings of the engine
// interface (weft_frame, weft_environment, weft_brdf_lut and their samplers).
// A binding is only kept in a variant whose code calls the function using it.

// ---------------------------------------------------------------- main light

// Unit direction from the surface towards the main light (world space).
fn weft_main_light_direction() -> vec3<f32> {
    return weft_safe_normalize(weft_frame.light_direction.xyz, vec3<f32>(0.0, 0.0, 1.0));
}

// Main light radiance (linear rgb); never negative.
// Zero in a scene without directional lights.
fn weft_main_light_radiance() -> vec3<f32> {
    if WEFT_DIRECTIONAL_LIGHTS == 0u {
        return vec3<f32>(0.0);
    }
    return max(weft_frame.light_color.rgb, vec3<f32>(0.0));
}

// Unit direction from `world_position` towards the camera; `fallback` when the
// camera sits on the point.
fn weft_view_direction(world_position: vec3<f32>, fallback: vec3<f32>) -> vec3<f32> {
    return weft_safe_normalize(weft_frame.camera_position.xyz - world_position, fallback);
}

// ---------------------------------------------------------------- ambient SH

// L2 spherical-harmonic irradiance (Ramamoorthi & Hanrahan 2001).
// weft_frame.sh holds c_i = A_l L_lm / pi (already cosine-convolved and
// divided by pi), in the order
//   0: Y00, 1: Y1-1 (y), 2: Y10 (z), 3: Y11 (x),
//   4: Y2-2 (xy), 5: Y2-1 (yz), 6: Y20 (3z^2 - 1), 7: Y21 (xz), 8: Y22 (x^2 - y^2)
// with the real orthonormal basis constants below. Returns E(n) / pi, i.e. the
// radiance leaving a white Lambertian surface: multiply by the diffuse albedo
// only, no further 1/pi. Clamped at 0 (ringing of L2 can go negative).
fn weft_sh_irradiance(n: vec3<f32>) -> vec3<f32> {
    if !WEFT_SH_AMBIENT {
        return vec3<f32>(0.0);
    }
    let sh = weft_frame.sh;
    var e = sh[0].xyz * 0.282095;
    e += sh[1].xyz * (0.488603 * n.y);
    e += sh[2].xyz * (0.488603 * n.z);
    e += sh[3].xyz * (0.488603 * n.x);
    e += sh[4].xyz * (1.092548 * n.x * n.y);
    e += sh[5].xyz * (1.092548 * n.y * n.z);
    e += sh[6].xyz * (0.315392 * (3.0 * n.z * n.z - 1.0));
    e += sh[7].xyz * (1.092548 * n.x * n.z);
    e += sh[8].xyz * (0.546274 * (n.x * n.x - n.y * n.y));
    return max(e, vec3<f32>(0.0));
}

// ---------------------------------------------------------------- specular IBL

// Mip of the prefiltered cube for perceptual roughness r (seed 004 sec. 2.3,
// Unity's perceptualRoughnessToMipmapLevel): r (1.7 - 0.7 r) * (mip_count - 1),
// mip_count = weft_frame.params.x (guarded against 0 mips).
fn weft_specular_mip(roughness: f32) -> f32 {
    let r = saturate(roughness);
    let max_mip = max(weft_frame.params.x - 1.0, 0.0);
    return r * (1.7 - 0.7 * r) * max_mip;
}

// Prefiltered (GGX) environment radiance along `dir` (world space, need not be
// unit but must be non-zero, e.g. reflect(-v, n) of unit vectors).
// Zero in a scene without an environment cube.
fn weft_prefiltered_radiance(dir: vec3<f32>, roughness: f32) -> vec3<f32> {
    if !WEFT_ENVIRONMENT {
        return vec3<f32>(0.0);
    }
    let c = textureSampleLevel(weft_environment, weft_environment_sampler, dir, weft_specular_mip(roughness));
    return max(c.rgb, vec3<f32>(0.0));
}

// Split-sum environment BRDF (scale, bias) from the toolchain-baked LUT
// (Karis 2013; u = n.v, v = perceptual roughness, texel centres). The LUT is
// tabulated at texel centres, so sampling at (n.v, r) interpolates correctly.
fn weft_env_brdf_lut(n_dot_v: f32, roughness: f32) -> vec2<f32> {
    let uv = vec2<f32>(saturate(n_dot_v), saturate(roughness));
    return textureSampleLevel(weft_brdf_lut, weft_lut_sampler, uv, 0.0).rg;
}

// (No nearest-texel read of this table: standard, silk and satin used one
// until 2026-11-28. It saves llvmpipe's software filter but costs ALU on a
// GPU, whose sampler filters for free: materials/standard/README.md.)

// ---------------------------------------------------------------- sphere map

// Lookup direction of a view-space sphere (cube) map (seed 004 sec. 6):
// reflect the view-space direction camera -> point about the view-space
// normal. weft_frame.view is rotation + translation, so its upper 3x3 also
// transforms normals. Returns a unit vector (fallbacks for a zero normal or a
// camera on the point).
fn weft_sphere_map_direction(world_normal: vec3<f32>, world_position: vec3<f32>) -> vec3<f32> {
    let view = weft_frame.view;
    let view3 = mat3x3<f32>(view[0].xyz, view[1].xyz, view[2].xyz);
    let n_vs = weft_safe_normalize(view3 * world_normal, vec3<f32>(0.0, 0.0, 1.0));
    let p_vs = (view * vec4<f32>(world_position, 1.0)).xyz;
    let d_vs = weft_safe_normalize(p_vs, vec3<f32>(0.0, 0.0, -1.0));
    return reflect(d_vs, n_vs);
}
