// @include "lib/forward.wgsl"
// @include "lib/glints.wgsl"
//
// glitter: sparkling flakes over weft's standard surface (seed 001 sec. 6,
// left "to be completed" by its authors; the design is README.md's).
// Returns linear HDR radiance.
//
// Base (every tier): the standard material's reference model, Unity's
// metallic/smoothness workflow: GGX D, Schlick F, height-correlated Smith
// visibility, Lambert diffuse weighted by 1 - E(n.v), the toolchain-baked
// split-sum table for the environment, L2 SH ambient, occlusion on ambient.
//
// Flakes (added on top, main light only): a Cook-Torrance lobe whose NDF is
// the flakes' glint NDF,
//   f_flakes = intensity D_flakes(h) V(n.v, n.l; r_f) F_schlick(flake colour, v.h),
// with V the height-correlated Smith visibility of the flake roughness r_f,
// and D_flakes by tier (WEFT_TIER):
//   reference = Deliot & Belcour 2023's glint NDF (lib/glints.wgsl): four
//               grids chosen by the pixel footprint's ellipse (level,
//               anisotropy, rotation) blended over a tetrahedron, binomial
//               flake counts per simplex cell; target NDF = GGX(r_f).
//   fast      = an approximation of the reference (glint_hits_fast): the
//               same four grids, twelve cells, 48 table corners and hashes,
//               so the same gates (the same flakes sparkle); every standard
//               normal number (cell log-density, corner counts) from a
//               degree-7 polynomial of the hash instead of Giles' erfinv (no
//               log, no branch); the tetrahedron without branches; the grids
//               one at a time (64 VGPRs, 60 on gfx1100, instead of 96).
//               Modelled cost 0.60 x the reference's (9.2 x standard fast
//               on navi21; README, "fast": 4 x needs fewer than the 48
//               corner hashes, which the per-pixel FLIP does not allow).
//   smooth    = the glints' expectation, E[D_flakes] = GGX(r_f): the flakes
//               averaged into a smooth lobe (no sparkle).

@fragment
fn fs_main(in: WeftVaryings) -> @location(0) vec4<f32> {
    // ------------------------------------------------------------ surface
    let uv = weft_transform_uv(in.uv0, material.base_map_st);
    // Screen derivatives of uv: the pixel footprint the glints integrate
    // over (taken here, in uniform control flow).
    let duv_dx = dpdx(uv);
    let duv_dy = dpdy(uv);
    let base_rgba = material.base_color * textureSample(base_map, material_sampler, uv);
    // Clamped to physical ranges (an albedo > 1 gives F0 > 1 and 1 - E < 0).
    let base = saturate(base_rgba.rgb);
    let alpha = saturate(base_rgba.a);
    let metallic = saturate(material.metallic);
    let roughness = 1.0 - saturate(material.smoothness);
    let occlusion = textureSample(occlusion_map, material_sampler, uv).r;
    let ao = saturate(mix(1.0, occlusion, material.occlusion_strength));

    // ------------------------------------------------------------ geometry
    // Fallbacks and clamps: lib/surface.wgsl.
    let surface = weft_surface(in.world_position, in.world_normal);
    let v = surface.v;
    var n = surface.n;
    if NORMAL_MAP {
        let texel = textureSample(normal_map, material_sampler, uv).rgb;
        n = weft_mapped_normal(n, in.world_tangent, texel, material.normal_strength);
    }
    // The flakes' tangent frame around the shading normal.
    let frame = weft_tangent_frame(n, in.world_tangent);
    let lit = weft_main_light_geometry(n, v);
    let light = weft_main_light_radiance();

    // ------------------------------------------------------------ base
    let f0 = mix(vec3<f32>(WEFT_DIELECTRIC_F0), base, metallic);
    let diffuse_albedo = base * (1.0 - metallic);
    let visibility = weft_v_smith_ggx_correlated(lit.n_dot_v, lit.n_dot_l, roughness);
    let env_brdf = weft_env_brdf_from_lut(f0, weft_env_brdf_lut(lit.n_dot_v, roughness));
    let kd = max(vec3<f32>(1.0) - env_brdf, vec3<f32>(0.0));
    let specular = weft_d_ggx_nh(n, lit.h, roughness) * visibility * weft_f_schlick(f0, lit.v_dot_h);
    let direct = (kd * weft_diffuse_lambert(diffuse_albedo) + specular) * light * lit.n_dot_l;
    let indirect = weft_prefiltered_radiance(reflect(-v, n), roughness) * env_brdf * ao
        + weft_sh_irradiance(n) * ao * kd * diffuse_albedo;
    var color = direct + indirect;

    // ------------------------------------------------------------ flakes
    // Skipped at zero intensity or with the light below the horizon (a
    // uniform branch for the intensity; n.l per pixel).
    let intensity = max(material.flake_intensity, 0.0);
    if intensity > 0.0 && lit.n_dot_l > 0.0 {
        let r_f = clamp(material.flake_roughness, 0.05, 1.0);
        let d = weft_d_ggx_nh(n, lit.h, r_f);
        let d_max = weft_d_ggx(1.0, r_f);
        let flake_f0 = saturate(material.flake_color.rgb);
        let v_f = weft_v_smith_ggx_correlated(lit.n_dot_v, lit.n_dot_l, r_f);
        if WEFT_TIER == TIER_FAST {
            // The lobe's factors other than D first: three numbers live
            // across the glint loop instead of the inputs of V and F.
            let params = glitter_params();
            let lobe = intensity * v_f * weft_f_schlick(flake_f0, lit.v_dot_h) * light * lit.n_dot_l
                * (d_max / params.micro_roughness);
            // Tangent-space half vector: its slope h.xy addresses the
            // flakes' slope cells.
            let slope = vec2<f32>(dot(frame[0], lit.h), dot(frame[1], lit.h));
            let ellipse = glint_ellipse(duv_dx, duv_dy);
            let screen_scale = clamp(material.flake_size, 1.0, 8.0);
            // D_flakes = min(hits / s, 20) D_max (glint_ndf_fast), D_max / s
            // folded into the lobe.
            let hits = glint_hits_fast(params, uv, ellipse, screen_scale, slope, d, d_max);
            color += min(hits, 20.0 * params.micro_roughness) * lobe;
        } else {
            var d_flakes: f32;
            if WEFT_TIER == TIER_SMOOTH {
                d_flakes = d;
            } else {
                let slope = vec2<f32>(dot(frame[0], lit.h), dot(frame[1], lit.h));
                let params = glitter_params();
                let ellipse = glint_ellipse(duv_dx, duv_dy);
                let screen_scale = clamp(material.flake_size, 1.0, 8.0);
                let grids = glint_grids(uv, ellipse, screen_scale);
                d_flakes = glint_ndf(params, grids, slope, d, d_max, false);
            }
            color += intensity * d_flakes * v_f * weft_f_schlick(flake_f0, lit.v_dot_h) * light * lit.n_dot_l;
        }
    }

    // Never negative, at most the fp16 maximum (Rgba16Float targets).
    let radiance = clamp(color, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    return vec4<f32>(radiance, alpha);
}

// The glint NDF's parameters from the panel: ln density = 4 + 28 density
// (e^4 ~ 55 to e^32 ~ 8e13 flakes per unit uv area), slope-cell size
// s = 0.05^(1 - twinkle) 0.002^twinkle, log-density deviation.
fn glitter_params() -> GlintParams {
    var p: GlintParams;
    p.log_density = 4.0 + 28.0 * saturate(material.flake_density);
    p.micro_roughness = exp2(mix(log2(0.05), log2(0.002), saturate(material.twinkle)));
    p.density_randomization = clamp(material.density_variation, 0.0, 4.0);
    return p;
}
