// @include "lib/surface.wgsl"
//
// velvet_swatch: see velvet_swatch.toml. Everything named `material.*`,
// the textures, `curve_*`, `gradient_*`, the keyword overrides and the tier
// constants come from the prelude weft generates from the TOML.

// Woven thread coverage in [0, 1] for the WEAVE pattern (a pipeline constant).
fn weave_mask(uv: vec2<f32>) -> f32 {
    let cell = uv * material.weave_scale;
    let f = fract(cell);
    let warp = step(abs(f.x - 0.5), material.weave_shape.x * 0.5);
    let weft = step(abs(f.y - 0.5), material.weave_shape.y * 0.5);
    var over = 0.5;
    if WEAVE == WEAVE_TWILL {
        over = step(0.5, fract((floor(cell.x) + floor(cell.y)) * 0.25));
    } else if WEAVE == WEAVE_SATIN {
        over = step(0.75, fract((floor(cell.x) * 2.0 + floor(cell.y)) * 0.2));
    }
    return max(warp * over, weft * (1.0 - over));
}

// Charlie sheen distribution (Estevez & Kulla 2017).
fn sheen_charlie(n_dot_h: f32, roughness: f32) -> f32 {
    let inv_r = 1.0 / roughness;
    let sin2 = max(1.0 - n_dot_h * n_dot_h, 0.0078125);
    return (2.0 + inv_r) * pow(sin2, inv_r * 0.5) / (2.0 * WEFT_PI);
}

// Neubelt & Pettineo visibility for cloth.
fn sheen_visibility(n_dot_l: f32, n_dot_v: f32) -> f32 {
    return 1.0 / (4.0 * (n_dot_l + n_dot_v - n_dot_l * n_dot_v) + 1e-4);
}

fn shade(in: SurfaceVaryings, layer: f32) -> vec3<f32> {
    let n = normalize(in.world_normal);
    let v = surface_view_direction(in.world_position);
    let l = surface_light_direction();
    let uv = surface_transform_uv(in.uv0, material.base_map_st);

    var base = material.base_color.rgb * textureSample(base_map, material_sampler, uv).rgb;
    let threads = weave_mask(in.uv0) * textureSample(thread_mask, material_sampler, uv).r;
    base *= mix(1.0, threads, material.weave_shape.z);
    if material.two_tone != 0u {
        base = mix(base, base * material.sheen_color.rgb, threads);
    }

    // Wrapped diffuse through the tone ramp, tinted where light scatters.
    let wrap = dot(n, l) * 0.5 + 0.5;
    let ramp = gradient_tone_ramp(wrap).rgb;
    let scatter = mix(material.scatter_tint, vec3<f32>(1.0), saturate(dot(n, l)));
    var color = base * ramp * scatter * weft_frame.light_color.rgb;

    if SHEEN {
        let n_dot_v = saturate(dot(n, v));
        let falloff = curve_sheen_falloff(1.0 - n_dot_v);
        var lobe: f32;
        if WEFT_TIER == TIER_REFERENCE {
            let h = normalize(l + v);
            let n_dot_l = saturate(dot(n, l));
            lobe = sheen_charlie(saturate(dot(n, h)), material.sheen_roughness)
                * sheen_visibility(n_dot_l, n_dot_v) * n_dot_l;
        } else {
            lobe = exp(-n_dot_v * n_dot_v / (material.sheen_roughness * material.sheen_roughness));
        }
        let env = textureSample(sheen_env, material_clamp_sampler, reflect(-v, n)).rgb;
        color += material.sheen_color.rgb * (lobe * weft_frame.light_color.rgb + env) * falloff * (1.0 + layer);
    }
    return color;
}

@fragment
fn fs_main(in: SurfaceVaryings) -> @location(0) vec4<f32> {
    return vec4<f32>(shade(in, 0.0), 1.0);
}

// ------------------------------------------------------------------ fuzz pass
// Drawn `fuzz_layers` times (the pass's `instances`): shell i sits i + 1
// steps of fuzz_length / fuzz_layers above the surface.

struct FuzzVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) uv0: vec2<f32>,
    @location(3) layer: f32,
}

@vertex
fn vs_fuzz(in: SurfaceInput, @builtin(instance_index) instance: u32) -> FuzzVaryings {
    let layers = f32(max(material.fuzz_layers, 1));
    let layer = (f32(instance) + 1.0) / layers;
    let s = surface_transform(in, material.fuzz_length * layer);
    return FuzzVaryings(s.clip_position, s.world_position, s.world_normal, s.uv0, layer);
}

@fragment
fn fs_fuzz(in: FuzzVaryings) -> @location(0) vec4<f32> {
    let surface = SurfaceVaryings(in.clip_position, in.world_position, in.world_normal, in.uv0);
    let strands = weave_mask(in.uv0 * 3.0);
    let alpha = strands * (1.0 - in.layer) * 0.5;
    return vec4<f32>(shade(surface, in.layer), alpha);
}
