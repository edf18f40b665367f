// @include "lib/forward.wgsl"
// @include "lib/half.wgsl"
//
// standard: metallic/roughness PBR (seed 004 sec. 2) with an optional
// view-space sphere map (seed 004 sec. 6). Returns linear HDR radiance.
//
// Tiers (WEFT_TIER):
//   reference = GGX D, Schlick F, height-correlated Smith visibility, the
//               toolchain-baked split-sum LUT, ambient kd = 1 - E_spec.
//   fast      = an approximation of the reference: the correlated visibility
//               without square roots (Hammon's linear form refined by one
//               Newton step, weft_v_smith_ggx_correlated_newton: within 6 %)
//               and GGX D from n.h (weft_d_ggx) in place of the |n x h|^2
//               form, the rest as the reference. 9 % cheaper than the
//               reference on AMD's compiler (README, "fast").
//   seed      = a look: the seed's form, GGX D, Schlick F, Schlick-GGX G with
//               k = (alpha + 1)^2 / 8, analytic split-sum fit (Unity's) for the
//               environment BRDF, roughness-aware Schlick for ambient kd. That
//               fit is far from the split-sum integral the reference bakes
//               (at roughness 0.35 and n.v = 1 it gives 0.89 F0 against
//               0.98 F0), hence a look rather than an approximation.
//   low       = an approximation of the reference in half precision: the
//               fast tier's visibility and the reference's D in weft_half
//               (f16 with shader-f16; the f32 fallback otherwise),
//               roughness floored at 0.089
//               (standard_low below, lib/half.wgsl).
// All: Lambert diffuse with 1/pi, L2 SH ambient, prefiltered environment cube,
// emission added after lighting (glTF emissive), back faces shaded with the
// flipped normal (a double-sided instance draws them: glTF doubleSided), and
// with ALPHA_TEST fragments below the alpha cutoff discarded (glTF MASK).
// The material uniform, textures and keyword overrides come from the
// generated prelude (standard.toml).

@fragment
fn fs_main(in: WeftVaryings, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    // ------------------------------------------------------------ surface
    // One UV transform for all main maps (Unity's _MainTex_ST convention).
    let uv = weft_transform_uv(in.uv0, material.base_map_st);
    let base_rgba = material.base_color * textureSample(base_map, material_sampler, uv);
    // Colours and factors are clamped to their physical ranges so that
    // out-of-range uniforms or texels cannot make radiance negative (an
    // albedo > 1 would give F0 > 1 and a negative 1 - F).
    let base = saturate(base_rgba.rgb);
    let alpha = saturate(base_rgba.a);
    let rmo = textureSample(rmo_map, material_sampler, uv).rgb;
    // Sampled here, beside the other maps, so that uv is not kept alive to the end.
    let emitted = standard_emission(uv);
    let roughness = saturate(material.roughness * rmo.r);
    let metallic = saturate(material.metallic * rmo.g);
    let ao = saturate(mix(1.0, rmo.b, material.occlusion_strength));
    let specular_strength = max(material.specular_strength, 0.0);

    // ------------------------------------------------------------ geometry
    // Back faces are drawn only when an instance turns culling off (glTF
    // doubleSided); they shade with the flipped normal (lib/surface.wgsl).
    let surface = weft_surface_two_sided(in.world_position, in.world_normal, front_facing);
    let v = surface.v;
    var n = surface.n;
    if NORMAL_MAP {
        let texel = textureSample(normal_map, material_sampler, uv).rgb;
        n = weft_mapped_normal(n, in.world_tangent, texel, material.normal_strength);
    }
    let lit = weft_main_light_geometry(n, v);

    let f0 = mix(vec3<f32>(WEFT_DIELECTRIC_F0), base, metallic);
    let diffuse_albedo = base * (1.0 - metallic);

    if WEFT_TIER == TIER_LOW {
        let color = standard_low(n, v, lit, f0, diffuse_albedo, roughness, ao, specular_strength);
        let radiance = clamp(standard_sphere_map(color, n, in.world_position) + emitted, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
        standard_alpha_test(alpha);
        return vec4<f32>(radiance, alpha);
    }

    // ------------------------------------------------------------ tier terms
    var visibility: f32;
    var env_brdf: vec3<f32>;
    var ambient_kd: vec3<f32>;
    // Weight of the direct diffuse lobe.
    var direct_kd: vec3<f32>;
    if WEFT_TIER == TIER_REFERENCE {
        visibility = weft_v_smith_ggx_correlated(lit.n_dot_v, lit.n_dot_l, roughness);
        env_brdf = weft_env_brdf_from_lut(f0, weft_env_brdf_lut(lit.n_dot_v, roughness));
        // Diffuse ambient gets the energy the specular lobe did not reflect
        // (Filament: Fd * (1 - E)); E <= 1, the max() is for interpolation.
        ambient_kd = max(vec3<f32>(1.0) - env_brdf, vec3<f32>(0.0));
        // Direct diffuse gets the same 1 - E(n.v): with 1 - F(v.h) per light
        // a white dielectric reflected up to 1.86x the incident light at
        // grazing view (docs/energy.md); with 1 - E the directional albedo is
        // E + (1 - E) rho <= 1.
        direct_kd = ambient_kd;
    } else if WEFT_TIER == TIER_SEED {
        visibility = weft_v_schlick_ggx(lit.n_dot_v, lit.n_dot_l, roughness);
        env_brdf = weft_env_brdf_approx(f0, lit.n_dot_v, roughness);
        ambient_kd = vec3<f32>(1.0) - weft_f_schlick_roughness(f0, lit.n_dot_v, roughness);
        direct_kd = vec3<f32>(1.0) - weft_f_schlick(f0, lit.v_dot_h);
    } else {
        // The reference without its square roots: Hammon's linear form of
        // the correlated visibility refined by one Newton step (Hammon's
        // alone is up to 29 % low at grazing light); the same split-sum table,
        // filtered (free in a GPU's sampler; the nearest texel computed in ALU
        // cost more on AMD's compiler), and 1 - E diffuse weighting.
        visibility = weft_v_smith_ggx_correlated_newton(lit.n_dot_v, lit.n_dot_l, roughness);
        env_brdf = weft_env_brdf_from_lut(f0, weft_env_brdf_lut(lit.n_dot_v, roughness));
        ambient_kd = max(vec3<f32>(1.0) - env_brdf, vec3<f32>(0.0));
        direct_kd = ambient_kd;
    }

    // ------------------------------------------------------------ direct
    // Cook-Torrance D * V * F with V = G / (4 n.v n.l) (finite for all
    // cosines, see brdf.wgsl); kd = (1 - F)(1 - metallic), Lambert 1/pi.
    // Indirect specular: split sum, prefiltered radiance along reflect(-v, n)
    // times the environment BRDF; AO applied as in the seed.
    // Both specular terms are skipped at zero strength: a uniform branch in a
    // library variant, decided at build time in a scene that fixes the
    // strength (docs/scenes.md, "Writing foldable materials").
    var specular = vec3<f32>(0.0);
    var indirect_specular = vec3<f32>(0.0);
    if specular_strength > 0.0 {
        let f = weft_f_schlick(f0, lit.v_dot_h);
        // fast: D from n.h, 12 fewer instructions than the reference's
        // |n x h|^2 form, which keeps the peak exact only near the roughness
        // floor (README, "fast").
        var d: f32;
        if WEFT_TIER == TIER_FAST {
            d = weft_d_ggx(lit.n_dot_h, roughness);
        } else {
            d = weft_d_ggx_nh(n, lit.h, roughness);
        }
        specular = d * visibility * f * specular_strength;
        let prefiltered = weft_prefiltered_radiance(reflect(-v, n), roughness);
        indirect_specular = prefiltered * env_brdf * (ao * specular_strength);
    }
    let diffuse = direct_kd * weft_diffuse_lambert(diffuse_albedo);
    let direct = (diffuse + specular) * weft_main_light_radiance() * lit.n_dot_l;

    // ------------------------------------------------------------ indirect
    // SH already returns E / pi.
    let indirect_diffuse = weft_sh_irradiance(n) * ao * ambient_kd * diffuse_albedo;

    let color = direct + indirect_specular + indirect_diffuse;

    // Never negative (e.g. a negative ADD strength); at most the fp16 maximum
    // so an Rgba16Float target never stores Inf (a sharp lobe at grazing under
    // a bright light can exceed it).
    let radiance = clamp(standard_sphere_map(color, n, in.world_position) + emitted, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    standard_alpha_test(alpha);
    return vec4<f32>(radiance, alpha);
}

// ---------------------------------------------------------------- emission
// Emitted radiance: colour (linear) x strength x emissive map (glTF's
// emissive x KHR_materials_emissive_strength x emissiveTexture), with
// EMISSION on. A constant keyword: without it the code and the map are gone
// (measured: the uniform-branch form cost every variant 8 VGPRs on RDNA2).
fn standard_emission(uv: vec2<f32>) -> vec3<f32> {
    if EMISSION {
        let strength = max(material.emissive_strength, 0.0);
        let emissive = max(material.emissive.rgb, vec3<f32>(0.0));
        return emissive * strength * textureSample(emissive_map, material_sampler, uv).rgb;
    }
    return vec3<f32>(0.0);
}

// ---------------------------------------------------------------- alpha test
// glTF alphaMode MASK: a fragment below the cutoff is discarded. Called last,
// after every texture sample (derivatives stay defined); without ALPHA_TEST
// the variant has no discard at all, so early depth testing stays on.
fn standard_alpha_test(alpha: f32) {
    if ALPHA_TEST {
        if alpha < material.alpha_cutoff {
            discard;
        }
    }
}

// ---------------------------------------------------------------- sphere map
// Each branch samples sphere_map itself so the texture vanishes from the
// OFF variant once the toolchain drops dead branches.
fn standard_sphere_map(color_in: vec3<f32>, n: vec3<f32>, world_position: vec3<f32>) -> vec3<f32> {
    var color = color_in;
    if SPHERE_MAP == SPHERE_MAP_ADD {
        let dir = weft_sphere_map_direction(n, world_position);
        let sph = max(textureSample(sphere_map, material_clamp_sampler, dir).rgb, vec3<f32>(0.0));
        color += sph * material.sphere_strength;
    }
    if SPHERE_MAP == SPHERE_MAP_MULTIPLY {
        let dir = weft_sphere_map_direction(n, world_position);
        let sph = max(textureSample(sphere_map, material_clamp_sampler, dir).rgb, vec3<f32>(0.0));
        // mix() extrapolates for strength > 1 and could turn negative.
        color *= max(mix(vec3<f32>(1.0), sph, material.sphere_strength), vec3<f32>(0.0));
    }
    return color;
}

// ---------------------------------------------------------------- low
// The reference's model with fast's visibility (Hammon's chord refined by
// one Newton step; the chord alone was 0.063 worst FLIP) and every BRDF
// term in half precision (weft_half: f16 where the device has shader-f16,
// else the f32 fallback). Lighting (light radiance, SH, prefiltered
// environment) and the table fetch stay f32; the half terms are
// dimensionless and bounded (lib/half.wgsl), so a bright light cannot
// overflow them. Roughness is floored at 0.089 (f16's GGX peak limit).
fn standard_low(
    n: vec3<f32>, v: vec3<f32>, lit: WeftLightGeometry,
    f0_in: vec3<f32>, diffuse_albedo: vec3<f32>,
    roughness_in: f32, ao: f32, specular_strength: f32,
) -> vec3<f32> {
    let n_dot_v = weft_half(lit.n_dot_v);
    let n_dot_l = weft_half(lit.n_dot_l);
    let n_dot_h = weft_half(lit.n_dot_h);
    let v_dot_h = weft_half(lit.v_dot_h);
    // 1 - n.h^2 formed in f32 from n.h, as fast does: at low's roughness
    // floor (alpha^2 = 6.3e-5) the f32 rounding of n.h (~1e-7) is 0.2 % of
    // D's denominator at the peak, so |n x h|^2 (6 more instructions) buys
    // nothing here; only the f16 n.h would cancel.
    let one_minus_n_dot_h2 = weft_half((1.0 - lit.n_dot_h) * (1.0 + lit.n_dot_h));
    let roughness = weft_half(max(roughness_in, WEFT_MIN_ROUGHNESS_HALF));
    let alpha = roughness * roughness;
    let f0 = vec3<weft_half>(f0_in);
    // The split-sum table, filtered as fast reads it (f32 fetch, a
    // dimensionless pair): Karis's analytic fit in its place was measured
    // at worst FLIP 0.25 (README).
    let lut = weft_env_brdf_lut(lit.n_dot_v, roughness_in);
    let env_brdf = vec3<weft_half>(weft_env_brdf_from_lut(f0_in, lut));
    let kd = max(vec3<weft_half>(1.0) - env_brdf, vec3<weft_half>(0.0));
    // Direct diffuse BRDF times n.l: kd / pi n.l (half), times the albedo.
    var direct_n_dot_l = vec3<f32>(kd * (n_dot_l * weft_half(WEFT_INV_PI))) * diffuse_albedo;
    var indirect_specular = vec3<f32>(0.0);
    if specular_strength > 0.0 {
        let d = weft_half_d_ggx(one_minus_n_dot_h2, n_dot_h, alpha);
        let v_n_dot_l = weft_half_v_smith_ggx_correlated_newton_nl(n_dot_v, n_dot_l, alpha);
        let f = weft_half_f_schlick(f0, v_dot_h);
        // D (V n.l) can exceed the f16 range at a sharp grazing peak:
        // clamped before F (the final radiance is clamped there anyway).
        let lobe = weft_half_min_max(d * v_n_dot_l);
        // The strength is a user factor: applied in f32, never in f16.
        direct_n_dot_l += vec3<f32>(f * lobe) * specular_strength;
        let prefiltered = weft_prefiltered_radiance(reflect(-v, n), roughness_in);
        indirect_specular = prefiltered * vec3<f32>(env_brdf) * (ao * specular_strength);
    }
    let direct = direct_n_dot_l * weft_main_light_radiance();
    let indirect_diffuse = weft_sh_irradiance(n) * ao * vec3<f32>(kd) * diffuse_albedo;
    return direct + indirect_specular + indirect_diffuse;
}
