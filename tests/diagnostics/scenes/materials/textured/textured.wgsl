// A vertex stage of its own and a fragment stage sampling every texture.

struct VertexInput {
    @location(0) position: vec3<f32>,
    @location(3) uv0: vec2<f32>,
}

struct Varyings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) uv0: vec2<f32>,
}

@vertex
fn vs_main(in: VertexInput) -> Varyings {
    var out: Varyings;
    out.clip_position = weft_frame.view_proj * weft_object.model * vec4<f32>(in.position, 1.0);
    out.uv0 = in.uv0;
    return out;
}

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
    c += textureSample(tint_map, material_sampler, in.uv0);
    c += textureSample(flake_map, material_sampler, in.uv0);
    c += textureSample(glint_map, material_sampler, in.uv0);
    return c;
}
