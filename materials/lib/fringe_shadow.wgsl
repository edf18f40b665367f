// The fringe shadow pass (seed 004 sec. 8, "刘海投影", after 流朔's method),
// shared by every material that includes lib/fringe_shadow.pass.toml
// (docs/material-format.md, "Shared passes").
//
// The hair is drawn a second time, each vertex moved on screen by where the
// light would carry it: the point `fringe_shadow_length` scene units along
// the light's direction of travel is projected, and the vertex is moved by
// the screen offset between the two, keeping its own depth. Keeping the depth
// (rather than moving the vertex in 3-D) is what makes this a screen-space
// shadow as in the seed: light from the front would push the hair into the
// face, where the depth test would hide it. The pass's stencil state limits it
// to the face (stencil bit 0), and its multiply blend tints what is there.

// Only the position is read: any mesh has it.
struct WeftFringeShadowVertex {
    @location(0) position: vec3<f32>,
}

struct WeftFringeShadowVaryings {
    @builtin(position) clip_position: vec4<f32>,
}

@vertex
fn vs_fringe_shadow(in: WeftFringeShadowVertex) -> WeftFringeShadowVaryings {
    let world = (weft_object.model * vec4<f32>(in.position, 1.0)).xyz;
    let clip = weft_frame.view_proj * vec4<f32>(world, 1.0);
    // `light_direction` points towards the light; the shadow lies the other way.
    let l = weft_frame.light_direction.xyz;
    let l_len = length(l);
    let travel = select(vec3<f32>(0.0), -l / max(l_len, 1e-6), l_len > 1e-6);
    let length_world = max(material.fringe_shadow_length, 0.0);
    let pushed = weft_frame.view_proj * vec4<f32>(world + travel * length_world, 1.0);
    // A vertex or pushed point behind the camera gets no offset rather than
    // a mirrored one.
    let usable = clip.w > 1e-6 && pushed.w > 1e-6;
    let offset_ndc = select(
        vec2<f32>(0.0),
        pushed.xy / max(pushed.w, 1e-6) - clip.xy / max(clip.w, 1e-6),
        usable,
    );
    var out: WeftFringeShadowVaryings;
    // Back to clip units (the divide by w undoes the multiply), depth kept.
    out.clip_position = vec4<f32>(clip.xy + offset_ndc * clip.w, clip.zw);
    return out;
}

@fragment
fn fs_fringe_shadow() -> @location(0) vec4<f32> {
    // Multiplied onto the target (`multiply` blend); alpha is left as it was.
    return vec4<f32>(max(material.fringe_shadow_color.rgb, vec3<f32>(0.0)), 1.0);
}
