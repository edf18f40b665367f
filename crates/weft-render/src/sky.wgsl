// weft-render background: the environment cube seen from the camera.

struct SkyUniform {
    inv_view_proj: mat4x4<f32>,
    // xyz: camera position.
    camera: vec4<f32>,
    // x: mip level to show.
    params: vec4<f32>,
}

@group(0) @binding(0) var<uniform> sky: SkyUniform;
@group(0) @binding(1) var sky_environment: texture_cube<f32>;
@group(0) @binding(2) var sky_sampler: sampler;

struct SkyVaryings {
    @builtin(position) position: vec4<f32>,
    @location(0) ndc: vec2<f32>,
}

@vertex
fn vs_sky(@builtin(vertex_index) i: u32) -> SkyVaryings {
    let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    let ndc = uv * 2.0 - 1.0;
    var out: SkyVaryings;
    out.position = vec4<f32>(ndc, 1.0, 1.0);
    out.ndc = ndc;
    return out;
}

@fragment
fn fs_sky(in: SkyVaryings) -> @location(0) vec4<f32> {
    let p = sky.inv_view_proj * vec4<f32>(in.ndc, 1.0, 1.0);
    let dir = p.xyz / p.w - sky.camera.xyz;
    let c = textureSampleLevel(sky_environment, sky_sampler, dir, sky.params.x);
    return vec4<f32>(max(c.rgb, vec3<f32>(0.0)), 1.0);
}
