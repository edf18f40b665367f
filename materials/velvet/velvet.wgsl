// @include "lib/forward.wgsl"
// @include "lib/sheen_lighting.wgsl"
//
// velvet: fabric PBR (seed 003, the PBR extension of a Unity shell-fur
// article; the same lighting is meant for shell fur). Returns linear HDR
// radiance. See README.md for the derivations and deviations.
//
// Tiers (WEFT_TIER):
//   reference = Charlie sheen (Conty Estevez & Kulla 2017): D_Charlie with
//               its fitted Smith visibility (KHR_materials_sheen), sheen
//               colour C = saturate(F0 + scatter colour), sheen roughness
//               1 - smoothness; the Lambert base scaled by
//               min(1 - max3(C) E(n.v), 1 - max3(C) E(n.l)) with E from the
//               toolchain-baked table (weft_sheen_lut); ambient: diffuse
//               scaled by 1 - max3(C) E(n.v), plus environment sheen
//               C E(n.v) x prefiltered radiance.
//   fast      = an approximation of the reference: the same sheen lobe,
//               colour and ambient, with the view-only albedo scaling
//               1 - max3(C) E(n.v) for the direct light too (one table
//               fetch instead of two). Neubelt & Pettineo's visibility in
//               place of the fitted Smith one was measured and rejected
//               (worst FLIP 0.147 over the error grid; README).
//   seed      = a look, not an approximation: the seed's BRDF1 extension,
//               specular D = FabricD (0.96 (1 - n.h)^2 + 0.057) in place of
//               GGX, with Schlick F on the metallic-workflow specular colour
//               and the Schlick-GGX visibility of lib/brdf.wgsl; Lambert
//               diffuse; the fabric scatter term lerp(pow4(1 - n.v),
//               0.4 (1 - n.v), scale) x scatter colour x (n.l 0.5 + 0.5),
//               added unlit as the seed does; SH ambient diffuse; no
//               indirect specular (seed).
// No `low` tier since 2026-11-29: its half precision gained nothing on a
// GPU compiler (README, "Tiers").

@fragment
fn fs_main(in: WeftVaryings) -> @location(0) vec4<f32> {
    // ------------------------------------------------------------ surface
    let uv = weft_transform_uv(in.uv0, material.base_map_st);
    let base_rgba = material.base_color * textureSample(base_map, material_sampler, uv);
    // Clamped to physical ranges: an albedo > 1 would make F0 > 1 and the
    // albedo scaling negative.
    let base = saturate(base_rgba.rgb);
    let alpha = saturate(base_rgba.a);
    let metallic = saturate(material.metallic);
    let smoothness = saturate(material.smoothness);
    let roughness = 1.0 - smoothness;
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
    let lit = weft_main_light_geometry(n, v);
    let l_dot_h = saturate(dot(lit.l, lit.h));

    // Metallic workflow as in Unity's BRDF1: specular colour and diffuse colour.
    let f0 = mix(vec3<f32>(WEFT_DIELECTRIC_F0), base, metallic);
    let diffuse_albedo = base * (1.0 - metallic);
    let light = weft_main_light_radiance();
    let ambient = weft_sh_irradiance(n) * ao;

    var color: vec3<f32>;
    if WEFT_TIER == TIER_SEED {
        // -------------------------------------------------------- seed (look)
        // BRDF1 with GGXTerm -> FabricD. In weft's units (Lambert with 1/pi)
        // Unity's specularTerm = V D pi becomes D V; FabricD is used as the
        // seed writes it (no 1/pi), so lobe and diffuse keep the seed's ratio.
        let visibility = weft_v_schlick_ggx(lit.n_dot_v, lit.n_dot_l, roughness);
        let f = weft_f_schlick(f0, l_dot_h);
        let specular = weft_fabric_d(lit.n_dot_h) * visibility * f;
        let diffuse = weft_diffuse_lambert(diffuse_albedo);
        let direct = (diffuse + specular) * light * lit.n_dot_l;
        // Fabric scatter, exactly as the seed adds it (not multiplied by the
        // light colour). No indirect specular (seed: "去掉标准PBR的间接光反射").
        let scatter = weft_fabric_scatter(material.scatter_color.rgb, lit.n_dot_l, lit.n_dot_v, material.scatter_scale);
        color = direct + ambient * diffuse_albedo + scatter;
    } else {
        // Sheen colour: the seed's two fibre tints (F0 on the FabricD lobe and
        // the scatter colour on the rim) become one lobe; saturate keeps
        // max3(C) <= 1 so the albedo scaling stays in [0, 1].
        let sheen_color = saturate(f0 + max(material.scatter_color.rgb, vec3<f32>(0.0)));
        let sheen_r = weft_sheen_clamp_roughness(roughness);
        let e_v = weft_sheen_albedo(lit.n_dot_v, sheen_r);
        let ambient_scaling = weft_sheen_albedo_scaling_view(sheen_color, e_v);
        var sheen: vec3<f32>;
        var scaling: f32;
        if WEFT_TIER == TIER_REFERENCE {
            // ---------------------------------------------------- reference
            let e_l = weft_sheen_albedo(lit.n_dot_l, sheen_r);
            sheen = weft_sheen_charlie(sheen_color, lit.n_dot_h, lit.n_dot_v, lit.n_dot_l, sheen_r);
            scaling = weft_sheen_albedo_scaling(sheen_color, e_v, e_l);
        } else {
            // ---------------------------------------------------- fast
            sheen = weft_sheen_charlie(sheen_color, lit.n_dot_h, lit.n_dot_v, lit.n_dot_l, sheen_r);
            scaling = ambient_scaling;
        }
        let base_direct = weft_diffuse_lambert(diffuse_albedo) * (scaling * lit.n_dot_l);
        let direct = (sheen + base_direct) * light;

        // Ambient: the base gets the energy the sheen did not reflect
        // (view-only scaling); the sheen reflects C E(n.v) of the incident
        // radiance, approximated by the prefiltered environment along the
        // mirror direction at the sheen roughness (the engine has no
        // Charlie-prefiltered cube; see README).
        let env_sheen = weft_prefiltered_radiance(reflect(-v, n), sheen_r) * sheen_color * (e_v * ao);
        color = direct + ambient * diffuse_albedo * ambient_scaling + env_sheen;
    }

    // Never negative, at most the fp16 maximum (Rgba16Float targets).
    let radiance = clamp(color, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    return vec4<f32>(radiance, alpha);
}
