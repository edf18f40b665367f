// @include "lib/surface.wgsl"

@fragment
fn fs_main(in: SurfaceVaryings) -> @location(0) vec4<f32> {
    let uv = surface_transform_uv(in.uv0, material.albedo_st);
    var color = textureSample(albedo, material_sampler, uv).rgb * material.tint.rgb;
    if CHANNEL == CHANNEL_LUMA {
        color = vec3<f32>(dot(color, vec3<f32>(0.2126, 0.7152, 0.0722)));
    }
    if INVERT {
        color = vec3<f32>(1.0) - saturate(color);
    }
    return vec4<f32>(color * material.strength, 1.0);
}
