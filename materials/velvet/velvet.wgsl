// @include "lib/forward.wgsl"
// @include "lib/sheen_lighting.wgsl"
// @include "lib/half.wgsl"
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
//   low       = an approximation of the reference in half precision: the
//               fast tier's model with the Charlie D (its power
//               sin^(1/r) in f32), G2 / (4 n.v), the sheen colour and the
//               albedo scaling in weft_half (f16 with shader-f16, the f32 fallback
//               otherwise); the Lambdas in f32 (they reach ~8e8) with one
//               exp each instead of two (weft_sheen_lambda_one_exp: the
//               same value), and one albedo fetch, E(n.v), for direct
//               and ambient (velvet_low below; README).

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
    if WEFT_TIER == TIER_LOW {
        color = velvet_low(n, v, lit, f0, diffuse_albedo, roughness, ao, light, ambient);
    } else if WEFT_TIER == TIER_SEED {
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

// ---------------------------------------------------------------- low
// The fast tier's model (Charlie sheen, view-only albedo scaling) with its
// dimensionless terms in half precision (weft_half: f16 where the device has
// shader-f16, else the f32 fallback). Light, SH, the prefiltered environment,
// the Lambdas and sin^(1/r) stay f32. Every half intermediate is bounded:
// sin^(1/r) in [0, 1], 2 + 1/r <= 16.3, D <= 2.6, G2 in [0, 1], G2 / (4 n.v)
// <= 250 (n.v floored at 1e-3), D V n.l <= 650.
fn velvet_low(
    n: vec3<f32>, v: vec3<f32>, lit: WeftLightGeometry,
    f0: vec3<f32>, diffuse_albedo: vec3<f32>, roughness: f32, ao: f32,
    light: vec3<f32>, ambient: vec3<f32>,
) -> vec3<f32> {
    let sheen_r = weft_sheen_clamp_roughness(roughness);
    let n_dot_v = lit.n_dot_v;
    let n_dot_l = lit.n_dot_l;
    let sheen_color = vec3<weft_half>(saturate(f0 + max(material.scatter_color.rgb, vec3<f32>(0.0))));
    // One albedo fetch, filtered as fast's, for direct and ambient (the
    // nearest texel computed in ALU cost more on AMD's compiler: README).
    let e_v = weft_half(weft_sheen_albedo(n_dot_v, sheen_r));
    let scaling = saturate(weft_half(1.0) - max(sheen_color.x, max(sheen_color.y, sheen_color.z)) * e_v);
    // Charlie D = (2 + 1/r) sin^(1/r) / (2 pi), sin^2 = (1 - n.h)(1 + n.h).
    // The power is taken in f32 and its result in [0, 1] is half: near the
    // peak sin^2 (~1e-7 where n.h rounds to 0.99999994) is below f16's
    // normal range, and sin^(1/r) of it (3.5e-4 at r = 1) would be lost,
    // visibly under a bright light (`weft stability`).
    let inv_r = 1.0 / sheen_r;
    let noh = lit.n_dot_h;
    let sin_pow = weft_half(pow(max((1.0 - noh) * (1.0 + noh), 0.0), 0.5 * inv_r));
    let d = weft_half(2.0 + inv_r) * sin_pow * weft_half(0.5 * WEFT_INV_PI);
    // V n.l = G2 / (4 n.v) (n.l cancels; 0 below the horizon): G2 from the
    // f32 Lambdas, 1 / (1 + Lambda_v + Lambda_l) in [0, 1].
    let g2 = weft_half(1.0 / (1.0 + weft_sheen_lambda_one_exp(n_dot_v, sheen_r) + weft_sheen_lambda_one_exp(n_dot_l, sheen_r)));
    let nv = max(weft_half(n_dot_v), weft_half(WEFT_MIN_N_DOT_HALF));
    let v_n_dot_l = select(weft_half(0.0), g2 / (weft_half(4.0) * nv), n_dot_l > 0.0);
    let sheen = vec3<f32>(sheen_color * (d * v_n_dot_l));
    let base_direct = diffuse_albedo * f32(scaling * weft_half(n_dot_l) * weft_half(WEFT_INV_PI));
    let direct = (sheen + base_direct) * light;
    let env_sheen = weft_prefiltered_radiance(reflect(-v, n), sheen_r) * vec3<f32>(sheen_color * e_v) * ao;
    return direct + ambient * diffuse_albedo * f32(scaling) + env_sheen;
}
