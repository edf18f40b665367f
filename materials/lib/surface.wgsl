// @include "lib/lighting.wgsl"
//
// weft surface set-up: how every material's fragment stage opens. The view
// direction and the geometric normal with their fallbacks (weft_surface), and
// the main light's directions and cosines (weft_main_light_geometry), written
// once so that a fallback or a clamp means the same thing in every material.
// A material then adds its own twists (normal maps, microcylinder's horizon
// lift, hair's unclamped n.l) on top of these values.

// The shading point as the rasteriser hands it over.
struct WeftSurface {
    // Unit direction towards the camera; +z when the camera sits on the point.
    v: vec3<f32>,
    // Unit interpolated normal, facing the viewer's side on the back face of a
    // two-sided surface; v when the interpolated normal is degenerate (the
    // surface then faces the viewer).
    n: vec3<f32>,
}

// One-sided surface (back faces are culled, or shade as the front).
fn weft_surface(world_position: vec3<f32>, world_normal: vec3<f32>) -> WeftSurface {
    let v = weft_view_direction(world_position, vec3<f32>(0.0, 0.0, 1.0));
    return WeftSurface(v, weft_safe_normalize(world_normal, v));
}

// Two-sided surface (glTF doubleSided, gauze): a back face shades with the
// flipped normal, as glTF asks.
fn weft_surface_two_sided(world_position: vec3<f32>, world_normal: vec3<f32>, front_facing: bool) -> WeftSurface {
    let v = weft_view_direction(world_position, vec3<f32>(0.0, 0.0, 1.0));
    let facing = select(-world_normal, world_normal, front_facing);
    return WeftSurface(v, weft_safe_normalize(facing, v));
}

// The main light seen from a shading normal n, with the clamps every BRDF
// here assumes.
struct WeftLightGeometry {
    // Unit direction towards the main light.
    l: vec3<f32>,
    // Half vector; n when l = -v (a zero half vector: n.l <= 0 or grazing
    // there, so the direct term is multiplied by 0 anyway).
    h: vec3<f32>,
    // n.v floored at 1e-4: views below the shading normal (normal maps,
    // interpolated normals at silhouettes) count as grazing, not as black.
    n_dot_v: f32,
    // n.l, 0 for light below the horizon (it contributes nothing).
    n_dot_l: f32,
    n_dot_h: f32,
    v_dot_h: f32,
}

fn weft_main_light_geometry(n: vec3<f32>, v: vec3<f32>) -> WeftLightGeometry {
    let l = weft_main_light_direction();
    let h = weft_safe_normalize(l + v, n);
    return WeftLightGeometry(
        l,
        h,
        weft_clamp_cos(dot(n, v)),
        saturate(dot(n, l)),
        saturate(dot(n, h)),
        saturate(dot(v, h)),
    );
}
