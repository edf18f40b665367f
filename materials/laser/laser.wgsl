// @include "lib/forward.wgsl"
// @include "lib/thin_film.wgsl"
//
// laser: an iridescent film over the standard metallic/roughness surface
// (seed 001 sec. 5). Returns linear HDR radiance. See README.md.
//
// Tiers (WEFT_TIER):
//   reference = the film's spectral Airy reflectance (weft_film_spectral)
//               in place of the Fresnel term: at v.h for the light, at n.v
//               for the environment (E = F_film(n.v) (A + B) with the
//               split-sum scale/bias A, B); GGX D, height-correlated Smith,
//               the baked split-sum LUT, diffuse weighted by 1 - E.
//   fast      = an approximation of the reference: the film in Belcour &
//               Barla's Fourier form at the same angles, both layers from
//               one stack per angle (weft_film_fourier_layers), each Airy
//               order's spectral integral read from the baked table
//               `film_sensitivity` (laser.toml); the rest as the reference.
//   seed      = a look: the seed's hue ring (or custom ramp) multiplied into
//               the albedo, then the reference's lighting with a plain
//               Schlick Fresnel (no film).
// All tiers: two film layers (offset map R and G) averaged; the angle of the
// film is n.v, or - with anisotropic colour - the angle measured in the plane
// of a direction and the normal (seed 5.2.7).

@fragment
fn fs_main(in: WeftVaryings) -> @location(0) vec4<f32> {
    // ------------------------------------------------------------ surface
    let uv = weft_transform_uv(in.uv0, material.base_map_st);
    let base_rgba = material.base_color * textureSample(base_map, material_sampler, uv);
    let base = saturate(base_rgba.rgb);
    let alpha = saturate(base_rgba.a);
    let rmo = textureSample(rmo_map, material_sampler, uv).rgb;
    let roughness = saturate(material.roughness * rmo.r);
    let metallic = saturate(material.metallic * rmo.g);
    let ao = saturate(mix(1.0, rmo.b, material.occlusion_strength));
    let offsets = saturate(textureSample(offset_map, material_sampler, weft_transform_uv(in.uv0, material.offset_map_st)).rg);

    // ------------------------------------------------------------ geometry
    let surface = weft_surface(in.world_position, in.world_normal);
    let v = surface.v;
    let geometric_n = surface.n;
    var n = geometric_n;
    if NORMAL_MAP {
        let texel = textureSample(normal_map, material_sampler, uv).rgb;
        n = weft_mapped_normal(geometric_n, in.world_tangent, texel, material.normal_strength);
    }
    let lit = weft_main_light_geometry(n, v);

    // The angle the film colour follows (seed 5.2.7).
    var film_cos = lit.n_dot_v;
    if ANISO_COLOR != ANISO_COLOR_OFF {
        let frame = weft_tangent_frame(geometric_n, in.world_tangent);
        var direction_ts = vec2<f32>(1.0, 0.0);
        if ANISO_COLOR == ANISO_COLOR_VALUE {
            let angle = radians(material.color_direction);
            direction_ts = vec2<f32>(cos(angle), sin(angle));
        } else {
            // A flow map; grey (zero) keeps the mesh tangent.
            let flow = textureSample(direction_map, material_sampler, uv).rg * 2.0 - 1.0;
            direction_ts = select(vec2<f32>(1.0, 0.0), flow, dot(flow, flow) > 1e-6);
        }
        let direction = frame[0] * direction_ts.x + frame[1] * direction_ts.y;
        film_cos = laser_cos_in_plane(n, v, direction);
    }

    // ------------------------------------------------------------ film
    // f0 of the bare surface; the Fresnel terms of the light (at v.h) and of
    // the environment (at n.v), replaced by the film in the physical tiers.
    var surface_base = base;
    if WEFT_TIER == TIER_SEED {
        surface_base = base * laser_seed_color(film_cos, offsets);
    }
    let f0 = mix(vec3<f32>(WEFT_DIELECTRIC_F0), surface_base, metallic);
    let diffuse_albedo = surface_base * (1.0 - metallic);
    let split_sum = weft_env_brdf_lut(lit.n_dot_v, roughness);
    var f_light = weft_f_schlick(f0, lit.v_dot_h);
    // Directional albedo of the specular lobe: Schlick's split sum f0 A + B.
    var e_spec = weft_env_brdf_from_lut(f0, split_sum);
    if WEFT_TIER != TIER_SEED {
        let d1 = mix(material.thickness_min, material.thickness_max, offsets.r);
        let d2 = mix(material.thickness_min, material.thickness_max, offsets.g);
        let strength = saturate(material.film_strength);
        // The light's film angle is v.h; with anisotropic colour the film
        // follows the chosen angle for the light too.
        var light_cos = lit.v_dot_h;
        if ANISO_COLOR != ANISO_COLOR_OFF {
            light_cos = film_cos;
        }
        var film_view: vec3<f32>;
        var film_light: vec3<f32>;
        if WEFT_TIER == TIER_REFERENCE {
            film_view = laser_film_reference(film_cos, d1, d2, f0);
            film_light = laser_film_reference(light_cos, d1, d2, f0);
        } else {
            film_view = weft_film_fourier_layers(film_cos, d1, d2, material.film_ior, f0);
            film_light = weft_film_fourier_layers(light_cos, d1, d2, material.film_ior, f0);
        }
        f_light = mix(f_light, film_light, strength);
        // The film's reflectance times the lobe's albedo with F = 1 (A + B).
        e_spec = mix(e_spec, film_view * (split_sum.x + split_sum.y), strength);
    }

    // ------------------------------------------------------------ lighting
    let kd = max(vec3<f32>(1.0) - e_spec, vec3<f32>(0.0));
    let visibility = weft_v_smith_ggx_correlated(lit.n_dot_v, lit.n_dot_l, roughness);
    let specular = weft_d_ggx_nh(n, lit.h, roughness) * visibility * f_light;
    let diffuse = kd * weft_diffuse_lambert(diffuse_albedo);
    let direct = (diffuse + specular) * weft_main_light_radiance() * lit.n_dot_l;
    let indirect_specular = weft_prefiltered_radiance(reflect(-v, n), roughness) * e_spec * ao;
    let indirect_diffuse = weft_sh_irradiance(n) * ao * kd * diffuse_albedo;
    let color = direct + indirect_specular + indirect_diffuse;
    return vec4<f32>(clamp(color, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF)), alpha);
}

// cos theta measured in the plane of `direction` and the normal: the view
// projected onto that plane (seed 5.2.7: p = cross(l', n), m = cross(p, v),
// v' = cross(m, p)), normalised so that it is a cosine. A direction along
// the normal has no such plane: n.v is kept.
fn laser_cos_in_plane(n: vec3<f32>, v: vec3<f32>, direction: vec3<f32>) -> f32 {
    let p = cross(direction, n);
    let p_len = length(p);
    if p_len < 1e-4 {
        return weft_clamp_cos(dot(n, v));
    }
    let p_unit = p / p_len;
    let v_in_plane = v - dot(v, p_unit) * p_unit;
    let len = length(v_in_plane);
    // A view along p sees the plane edge-on: grazing.
    return weft_clamp_cos(dot(n, v_in_plane) / max(len, 1e-4));
}

// The film's spectral sensitivity S(x) at a path difference in nm, which
// lib/thin_film.wgsl's fast form asks its includer for: the baked table
// (clamped past its end, where S has decayed to nothing).
fn weft_film_sensitivity(opd_nm: f32) -> vec3<f32> {
    return table_film_sensitivity(vec2<f32>(opd_nm / film_sensitivity_opd_max, 0.0)).rgb;
}

// The two film layers' reflectance, averaged; one evaluation when both
// layers have the same thickness (no offset map).
fn laser_film_reference(cos_theta: f32, d1: f32, d2: f32, f0: vec3<f32>) -> vec3<f32> {
    let first = weft_film_spectral(cos_theta, d1, material.film_ior, f0);
    if abs(d1 - d2) < 0.5 {
        return first;
    }
    return 0.5 * (first + weft_film_spectral(cos_theta, d2, material.film_ior, f0));
}

// ---------------------------------------------------------------- seed look

// The seed's colour, multiplied into the albedo: per layer (offset map R, G)
// hue = fract(x span + offset + layer offset) on the HSV ring, or the custom
// ramp at x with its hue turned by the same offsets, then S x saturation and
// V x brightness; the two layers averaged. x = 1 - cos theta, or sin theta
// (the seed's text prints sqrt(1 - cos) cos for it; sin theta is what it
// names and what its figures show).
fn laser_seed_color(cos_theta: f32, layer_offsets: vec2<f32>) -> vec3<f32> {
    let c = saturate(cos_theta);
    let x = select(1.0 - c, sqrt(max(1.0 - c * c, 0.0)), material.sin_mapping != 0u);
    let saturation = saturate(material.saturation);
    let brightness = saturate(material.brightness);
    var hsv = vec3<f32>(x * material.span, saturation, brightness);
    if COLOR_MODE == COLOR_MODE_CUSTOM {
        let ramp = laser_rgb_to_hsv(saturate(gradient_color_ramp(x).rgb));
        hsv = vec3<f32>(ramp.x, ramp.y * saturation, ramp.z * brightness);
    }
    let hue = hsv.x + material.view_offset;
    let first = laser_hsv_to_rgb(vec3<f32>(fract(hue + layer_offsets.x), hsv.y, hsv.z));
    let second = laser_hsv_to_rgb(vec3<f32>(fract(hue + layer_offsets.y), hsv.y, hsv.z));
    return 0.5 * (first + second);
}

// HSV (all in [0, 1]) to RGB: the piecewise-linear hue ring.
fn laser_hsv_to_rgb(hsv: vec3<f32>) -> vec3<f32> {
    let k = vec3<f32>(0.0, 2.0 / 3.0, 1.0 / 3.0);
    let p = abs(fract(vec3<f32>(hsv.x) + k) * 6.0 - vec3<f32>(3.0));
    let ring = saturate(p - vec3<f32>(1.0));
    return hsv.z * mix(vec3<f32>(1.0), ring, hsv.y);
}

// RGB to HSV; a grey has hue 0 and saturation 0 (no division by zero).
fn laser_rgb_to_hsv(rgb: vec3<f32>) -> vec3<f32> {
    let max_c = max(rgb.r, max(rgb.g, rgb.b));
    let min_c = min(rgb.r, min(rgb.g, rgb.b));
    let chroma = max_c - min_c;
    var hue = 0.0;
    if chroma > 1e-6 {
        if max_c == rgb.r {
            hue = (rgb.g - rgb.b) / chroma;
        } else if max_c == rgb.g {
            hue = (rgb.b - rgb.r) / chroma + 2.0;
        } else {
            hue = (rgb.r - rgb.g) / chroma + 4.0;
        }
        hue = fract(hue / 6.0 + 1.0);
    }
    let saturation = select(0.0, chroma / max_c, max_c > 1e-6);
    return vec3<f32>(hue, saturation, max_c);
}
