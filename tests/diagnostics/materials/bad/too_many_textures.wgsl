// @include "lib/common.wgsl"

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    var c = vec4<f32>(0.0);
    c += textureSample(albedo, material_sampler, in.uv0);
    c += textureSample(normal_map, material_sampler, in.uv0);
    c += textureSample(roughness_map, material_sampler, in.uv0);
    c += textureSample(metal_map, material_sampler, in.uv0);
    c += textureSample(ao_map, material_sampler, in.uv0);
    c += textureSample(height_map, material_sampler, in.uv0);
    c += textureSample(emission_map, material_sampler, in.uv0);
    c += textureSample(mask_a, material_sampler, in.uv0);
    c += textureSample(mask_b, material_sampler, in.uv0);
    c += textureSample(mask_c, material_sampler, in.uv0);
    c += textureSample(detail_albedo, material_sampler, in.uv0);
    c += textureSample(detail_normal, material_sampler, in.uv0);
    c += textureSample(sheen_map, material_sampler, in.uv0);
    c += textureSample(clearcoat_map, material_sampler, in.uv0);
    if DETAIL {
        c += textureSample(tint_map, material_sampler, in.uv0);
        c += textureSample(flake_map, material_sampler, in.uv0);
        c += textureSample(glint_map, material_sampler, in.uv0);
        c += textureSample(dust_map, material_sampler, in.uv0);
    }
    return c;
}
