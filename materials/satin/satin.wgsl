// @include "lib/forward.wgsl"
// @include "lib/anisotropic.wgsl"
// @include "lib/half.wgsl"
//
// satin: seed 001 sec. 7. The standard metallic/roughness surface (base, RMO
// and normal maps handled as materials/standard) whose direct specular is
// replaced by two anisotropic GGX layers: layer 1 narrow and bright (roughness
// r), layer 2 wide and dim (roughness min(1, r * second_layer_width)), both
// with ax = r^2 (1 + k), ay = r^2 (1 - k) (seed 7.2.1). Returns linear HDR
// radiance.
//
// Tiers (WEFT_TIER):
//   seed      = a look, the seed's form: per layer D = 1 / (pi q^2) (the seed's GGX
//               without 1/(ax ay)) times Schlick-GGX visibility (seed 004
//               form); colour c_i blended with the light (seed 7.2.3):
//                 gray = luminance(light), c_final = lerp(c * gray, light * max3(c), 0.5)
//               (max3(c) = 1 for any fully bright colour, where this is the
//               seed's formula exactly; it makes a black colour hide its layer,
//               as the seed promises); layer 2 dimmed by 1 / width;
//               specular = (layer 1 + layer 2) * mag * noise, noise = 0.5 + 0.5 n
//               (seed 7.2.2, 7.2.5); BIDIRECTIONAL sums D(ax, ay) + D(ay, ax)
//               (seed 7.2.4). Diffuse (1 - F) Lambert, analytic split-sum
//               environment (the standard material's seed tier).
//   reference = per layer the normalised anisotropic GGX D with the
//               height-correlated anisotropic Smith V (Heitz 2014) and Schlick
//               F(v.h) with the standard F0; each layer's single-scattering
//               albedo is <= 1. Layer tints t_i = lerp(c_i, max3(c_i), 0.5)
//               (the seed's blend for a white light; the light's own colour
//               then multiplies, as physics has it) are normalised so that
//               t_1 + t_2 <= 1 per channel: w_i = t_i / max(1, max3(t_1 + t_2)),
//               so the specular albedo is <= 1. BIDIRECTIONAL averages the two
//               directions. The intensity slider is not applied. Diffuse gets
//               (1 - w_sum F(n.v)) directly and 1 - sum w_i E_i (split-sum LUT per
//               layer) from the environment. Measured: directional albedo <= 1
//               (README, "Energy").
//   fast      = an approximation of the reference: the same lobes, weights
//               and split-sum albedos, one prefiltered environment lookup for
//               both layers (at the roughness of the layer that reflects
//               more) instead of one per layer (two per layer with
//               BIDIRECTIONAL).
//   low       = an approximation of the reference in half precision: the
//               fast tier's lobes, weights, Fresnel and diffuse weights in
//               weft_half (f16 with shader-f16, the f32 fallback
//               otherwise; both lobes at once in one vec2<weft_half>,
//               weft_half_spec_ggx_aniso2 in lib/half.wgsl),
//               roughness floored at 0.089 and each width at 0.089^2 for
//               the lobes; the split-sum table filtered, as fast;
//               one prefiltered lookup as fast, lighting in f32 (satin_low).
// All: Lambert 1/pi, L2 SH ambient, AO, prefiltered environment along the
// anisotropic bent reflection vector.

struct SatinLayers {
    narrow: vec2<f32>,
    wide: vec2<f32>,
}

// Seed 7.2.3 colour blend with the "black hides the layer" fix (see header).
fn satin_light_blend(c: vec3<f32>, light: vec3<f32>) -> vec3<f32> {
    let gray = weft_luminance(light);
    return mix(c * gray, light * weft_max3(c), 0.5);
}

// One layer of the seed's D (unnormalised), optionally both directions.
fn satin_d_seed(hf: vec3<f32>, a: vec2<f32>) -> f32 {
    var d = weft_d_ggx_aniso_unnormalized(hf.x, hf.y, hf.z, a.x, a.y);
    if BIDIRECTIONAL {
        d += weft_d_ggx_aniso_unnormalized(hf.x, hf.y, hf.z, a.y, a.x);
    }
    return d;
}

// One normalised layer, D V n.l; BIDIRECTIONAL averages the two directions
// (each has albedo <= 1, so does their mean).
fn satin_lobe_reference(vf: vec3<f32>, lf: vec3<f32>, a: vec2<f32>) -> f32 {
    var s = weft_spec_ggx_aniso(vf, lf, a.x, a.y);
    if BIDIRECTIONAL {
        s = 0.5 * (s + weft_spec_ggx_aniso(vf, lf, a.y, a.x));
    }
    return s;
}

// Prefiltered environment for one layer: the bent reflection of its own
// roughness; BIDIRECTIONAL averages the two bend directions.
fn satin_env(frame: mat3x3<f32>, v: vec3<f32>, k: f32, roughness: f32) -> vec3<f32> {
    var bent = weft_aniso_bent_normal(frame, v, k, roughness);
    var c = weft_prefiltered_radiance(reflect(-v, bent), roughness);
    if BIDIRECTIONAL {
        bent = weft_aniso_bent_normal(frame, v, -k, roughness);
        c = 0.5 * (c + weft_prefiltered_radiance(reflect(-v, bent), roughness));
    }
    return c;
}

@fragment
fn fs_main(in: WeftVaryings) -> @location(0) vec4<f32> {
    // ------------------------------------------------------------ surface (as standard)
    let uv = weft_transform_uv(in.uv0, material.base_map_st);
    let base_rgba = material.base_color * textureSample(base_map, material_sampler, uv);
    // Physical ranges: albedo > 1 would give F0 > 1 and a negative 1 - F.
    let base = saturate(base_rgba.rgb);
    let alpha = saturate(base_rgba.a);
    let rmo = textureSample(rmo_map, material_sampler, uv).rgb;
    let roughness = saturate(material.roughness * rmo.r);
    let metallic = saturate(material.metallic * rmo.g);
    let ao = saturate(mix(1.0, rmo.b, material.occlusion_strength));
    let anisotropy = clamp(material.anisotropy, -1.0, 1.0);
    let width = clamp(material.second_layer_width, 1.0, 4.0);
    let roughness2 = min(roughness * width, 1.0);
    // Seed 7.2.5: noise in [0, 1] mapped to [0.5, 1].
    let nuv = weft_transform_uv(in.uv0, material.noise_map_st);
    let noise = 0.5 + 0.5 * saturate(textureSample(noise_map, material_sampler, nuv).r);

    // ------------------------------------------------------------ geometry
    let surface = weft_surface(in.world_position, in.world_normal);
    let v = surface.v;
    var n = surface.n;
    if NORMAL_MAP {
        let texel = textureSample(normal_map, material_sampler, uv).rgb;
        n = weft_mapped_normal(n, in.world_tangent, texel, material.normal_strength);
    }
    // Frame of the shading normal (zero / parallel tangents fall back inside).
    let frame = weft_tangent_frame(n, in.world_tangent);
    let lit = weft_main_light_geometry(n, v);
    let light = weft_main_light_radiance();

    var layers: SatinLayers;
    layers.narrow = weft_aniso_alpha_kulla(roughness, anisotropy);
    layers.wide = weft_aniso_alpha_kulla(roughness2, anisotropy);

    let f0 = mix(vec3<f32>(WEFT_DIELECTRIC_F0), base, metallic);
    let diffuse_albedo = base * (1.0 - metallic);
    // Colours in their physical range (a negative colour would subtract light).
    let c1 = saturate(material.specular_color.rgb);
    let c2 = saturate(material.second_specular_color.rgb);
    let f = weft_f_schlick(f0, lit.v_dot_h);

    if WEFT_TIER == TIER_LOW {
        let color = satin_low(frame, n, v, lit, f0, diffuse_albedo, roughness, roughness2, anisotropy, c1, c2, noise, ao, light);
        return vec4<f32>(clamp(color, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF)), alpha);
    }

    var specular: vec3<f32>;
    var diffuse_kd: vec3<f32>;
    var indirect_specular: vec3<f32>;
    var ambient_kd: vec3<f32>;
    if WEFT_TIER != TIER_SEED {
        // Layer weights: the seed's blend for a white light, normalised so the
        // two sum to <= 1 per channel (max(1, .) never divides by < 1).
        let t1 = mix(c1, vec3<f32>(weft_max3(c1)), 0.5);
        let t2 = mix(c2, vec3<f32>(weft_max3(c2)), 0.5);
        let norm = 1.0 / max(1.0, weft_max3(t1 + t2));
        let w1 = t1 * norm;
        let w2 = t2 * norm;
        let vf = weft_aniso_to_frame(frame, v);
        let lf = weft_aniso_to_frame(frame, lit.l);
        let lobe1 = satin_lobe_reference(vf, lf, layers.narrow);
        let lobe2 = satin_lobe_reference(vf, lf, layers.wide);
        // The lobes already include n.l.
        specular = (w1 * lobe1 + w2 * lobe2) * f * noise * light;
        // Diffuse gets what the layers cannot reflect: 1 - w_sum F(n.v). The
        // (1 - F(v.h)) of the standard material lets the sum reach 1.8 at
        // grazing views with sharp lobes; with F(n.v) the measured maximum of
        // the total directional albedo is 1.0007 (README, "Energy").
        diffuse_kd = max(vec3<f32>(1.0) - (w1 + w2) * weft_f_schlick(f0, lit.n_dot_v), vec3<f32>(0.0));
        // Environment: each layer's split-sum albedo (isotropic LUT at its
        // roughness) times its own prefiltered lookup.
        let e1 = weft_env_brdf_from_lut(f0, weft_env_brdf_lut(lit.n_dot_v, roughness)) * w1;
        let e2 = weft_env_brdf_from_lut(f0, weft_env_brdf_lut(lit.n_dot_v, roughness2)) * w2;
        if WEFT_TIER == TIER_REFERENCE {
            indirect_specular = (satin_env(frame, v, anisotropy, roughness) * e1
                + satin_env(frame, v, anisotropy, roughness2) * e2) * noise;
        } else {
            // fast: one prefiltered lookup for both layers, at the roughness
            // of the layer that reflects more.
            let r_env = select(roughness2, roughness, weft_max3(e1) >= weft_max3(e2));
            indirect_specular = satin_env(frame, v, anisotropy, r_env) * (e1 + e2) * noise;
        }
        ambient_kd = max(vec3<f32>(1.0) - e1 - e2, vec3<f32>(0.0));
    } else {
        let hf = weft_aniso_to_frame(frame, lit.h);
        let d1 = satin_d_seed(hf, layers.narrow);
        let d2 = satin_d_seed(hf, layers.wide) / width;
        let vis1 = weft_v_schlick_ggx(lit.n_dot_v, lit.n_dot_l, roughness);
        let vis2 = weft_v_schlick_ggx(lit.n_dot_v, lit.n_dot_l, roughness2);
        // Seed 7.2.3: the colours already carry the light.
        let s1 = satin_light_blend(c1, light);
        let s2 = satin_light_blend(c2, light);
        let mag = max(material.specular_intensity, 0.0);
        specular = (d1 * vis1 * s1 + d2 * vis2 * s2) * (mag * noise * lit.n_dot_l);
        diffuse_kd = vec3<f32>(1.0) - f;
        // The standard seed tier's environment, along the bent reflection.
        var bent = weft_aniso_bent_normal(frame, v, anisotropy, roughness);
        if BIDIRECTIONAL {
            // Both directions at once: close to isotropic, use the normal.
            bent = n;
        }
        let env_brdf = weft_env_brdf_approx(f0, lit.n_dot_v, roughness);
        indirect_specular = weft_prefiltered_radiance(reflect(-v, bent), roughness) * env_brdf * noise;
        ambient_kd = vec3<f32>(1.0) - weft_f_schlick_roughness(f0, lit.n_dot_v, roughness);
    }

    // ------------------------------------------------------------ combine
    let direct = diffuse_kd * weft_diffuse_lambert(diffuse_albedo) * light * lit.n_dot_l + specular;
    let indirect = indirect_specular * ao + weft_sh_irradiance(n) * ao * ambient_kd * diffuse_albedo;
    // Never negative, at most the fp16 maximum (a sharp lobe at grazing under
    // a bright light can exceed it).
    let radiance = clamp(direct + indirect, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    return vec4<f32>(radiance, alpha);
}

// ---------------------------------------------------------------- low
// The fast tier with every dimensionless term in half precision (weft_half:
// f16 where the device has shader-f16, else the f32 fallback): the two
// lobes' D V n.l (weft_half_spec_ggx_aniso2: lane 0 the narrow lobe, lane 1
// the wide one, so that AMD's compiler packs both lobes' f16 arithmetic
// into one v_pk_* instruction each; README, "On AMD's compiler"), Schlick
// F, the layer weights, the split-sum albedos and the diffuse weights.
// Light radiance, SH, the prefiltered environment and the table fetch stay
// f32; the noise factor is applied in f32. The lobes' roughness is floored
// at 0.089 (f16's GGX peak limit) and each width at 0.089^2; the table and
// the environment keep the material's roughness. The table is read
// filtered, as fast (a nearest-texel read costs more on a GPU).
fn satin_lobes_low(vf: vec3<weft_half>, lf: vec3<weft_half>, hf: vec3<weft_half>, a1: vec2<f32>, a2: vec2<f32>) -> vec2<weft_half> {
    let at = vec2<f32>(a1.x, a2.x);
    let ab = vec2<f32>(a1.y, a2.y);
    var s = weft_half_spec_ggx_aniso2(vf, lf, hf, at, ab);
    if BIDIRECTIONAL {
        s = weft_half(0.5) * (s + weft_half_spec_ggx_aniso2(vf, lf, hf, ab, at));
    }
    return s;
}

fn satin_low(
    frame: mat3x3<f32>, n: vec3<f32>, v: vec3<f32>, lit: WeftLightGeometry,
    f0_in: vec3<f32>, diffuse_albedo: vec3<f32>, roughness: f32, roughness2: f32,
    anisotropy: f32, c1_in: vec3<f32>, c2_in: vec3<f32>, noise: f32, ao: f32, light: vec3<f32>,
) -> vec3<f32> {
    let n_dot_v = lit.n_dot_v;
    let n_dot_l = weft_half(lit.n_dot_l);
    let v_dot_h = weft_half(lit.v_dot_h);
    let f0 = vec3<weft_half>(f0_in);
    let c1 = vec3<weft_half>(c1_in);
    let c2 = vec3<weft_half>(c2_in);
    let t1 = mix(c1, vec3<weft_half>(max(c1.x, max(c1.y, c1.z))), weft_half(0.5));
    let t2 = mix(c2, vec3<weft_half>(max(c2.x, max(c2.y, c2.z))), weft_half(0.5));
    let t = t1 + t2;
    let norm = weft_half(1.0) / max(weft_half(1.0), max(t.x, max(t.y, t.z)));
    let w1 = t1 * norm;
    let w2 = t2 * norm;
    let r_low = max(roughness, WEFT_MIN_ROUGHNESS_HALF);
    let r2_low = max(roughness2, WEFT_MIN_ROUGHNESS_HALF);
    let vf = vec3<weft_half>(weft_aniso_to_frame(frame, v));
    let lf = vec3<weft_half>(weft_aniso_to_frame(frame, lit.l));
    let hf = vec3<weft_half>(weft_aniso_to_frame(frame, lit.h));
    let lobes = satin_lobes_low(vf, lf, hf, weft_aniso_alpha_kulla(r_low, anisotropy), weft_aniso_alpha_kulla(r2_low, anisotropy));
    let lobe1 = lobes.x;
    let lobe2 = lobes.y;
    let f = weft_half_f_schlick(f0, v_dot_h);
    // The lobes include n.l. Each weighted lobe is <= 65504; their sum could
    // round past it, so it is formed in f32, with the noise (a texel).
    let specular = (vec3<f32>(w1 * f) * f32(lobe1) + vec3<f32>(w2 * f) * f32(lobe2)) * (noise * light);
    let diffuse_kd = max(vec3<weft_half>(1.0) - (w1 + w2) * weft_half_f_schlick(f0, weft_half(n_dot_v)), vec3<weft_half>(0.0));
    let e1 = vec3<weft_half>(weft_env_brdf_from_lut(f0_in, weft_env_brdf_lut(n_dot_v, roughness))) * w1;
    let e2 = vec3<weft_half>(weft_env_brdf_from_lut(f0_in, weft_env_brdf_lut(n_dot_v, roughness2))) * w2;
    let r_env = select(roughness2, roughness, max(e1.x, max(e1.y, e1.z)) >= max(e2.x, max(e2.y, e2.z)));
    let indirect_specular = satin_env(frame, v, anisotropy, r_env) * vec3<f32>(e1 + e2) * noise;
    let ambient_kd = max(vec3<weft_half>(1.0) - e1 - e2, vec3<weft_half>(0.0));
    let direct = diffuse_albedo * vec3<f32>(diffuse_kd * (n_dot_l * weft_half(WEFT_INV_PI))) * light + specular;
    let indirect = indirect_specular * ao + weft_sh_irradiance(n) * ao * vec3<f32>(ambient_kd) * diffuse_albedo;
    return direct + indirect;
}
