// The outline pass (seed 004 sec. 9, "描边": the normal-extrusion outline of
// toon rendering), shared by every material that includes
// lib/outline.pass.toml (docs/material-format.md, "Shared passes").
//
// The mesh is drawn a second time with front faces culled, each vertex pushed
// out along its normal as seen on screen, so the back faces show as a rim
// around the silhouette and at creases. The push is `outline_width` pixels
// wide whatever the distance (the offset is applied in clip space and
// multiplied by clip w, which the perspective divide removes), until the
// vertex is farther than `outline_max_distance` from the camera: from there
// the width shrinks as 1 / distance like the object does, so a far character
// is not drawn as a black blob. Unlit: the colour is written as it is
// (the seed's official footage uses black outlines).

// The outline reads only position and normal: any mesh that has them.
struct WeftOutlineVertex {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
}

struct WeftOutlineVaryings {
    @builtin(position) clip_position: vec4<f32>,
}

@vertex
fn vs_outline(in: WeftOutlineVertex) -> WeftOutlineVaryings {
    let world = weft_object.model * vec4<f32>(in.position, 1.0);
    let nm = weft_object.normal_matrix;
    let normal = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz) * in.normal;
    let clip = weft_frame.view_proj * vec4<f32>(world.xyz, 1.0);
    // The normal's direction on screen. Clip-space xy of a direction, scaled
    // by the aspect so that a pixel is square: viewport.zw is 1 / size.
    let size = weft_frame.viewport.xy;
    let screen_normal = (weft_frame.view_proj * vec4<f32>(normal, 0.0)).xy * size;
    let len = length(screen_normal);
    // Degenerate normals (zero, or pointing at the camera) and an engine that
    // does not fill `viewport` (all zero) get no push: the back faces stay
    // behind the front ones, so no outline rather than a wrong one.
    let usable = len > 1e-6 && weft_frame.viewport.x > 0.0 && clip.w > 0.0;
    let direction = select(vec2<f32>(0.0), screen_normal / max(len, 1e-6), usable);
    // Pixels to clip units: 2 / size per pixel, times w (undone by the
    // divide) up to the clamp distance, so the width is constant on screen.
    let width_px = max(material.outline_width, 0.0);
    let distance = min(clip.w, max(material.outline_max_distance, 0.0));
    let offset = direction * width_px * 2.0 * weft_frame.viewport.zw * distance;
    var out: WeftOutlineVaryings;
    out.clip_position = vec4<f32>(clip.xy + offset, clip.zw);
    return out;
}

@fragment
fn fs_outline() -> @location(0) vec4<f32> {
    return vec4<f32>(max(material.outline_color.rgb, vec3<f32>(0.0)), 1.0);
}
