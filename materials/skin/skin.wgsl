// @include "lib/forward.wgsl"
// @include "lib/skin_specular.wgsl"
//
// skin: pre-integrated subsurface scattering (seed 004 sec. 3). Returns
// linear HDR radiance. See README.md for the derivations.
//
// Tiers (WEFT_TIER):
//   reference = the diffuse falloff D(theta, r) of Penner & Borshukov 2011,
//               the ring integral of the Burley profile, evaluated per pixel
//               (skin_preintegrated: 64 warped points, the bake's quadrature
//               with fewer points) with the same shape as the table;
//               normalised dual-lobe GGX specular (0.75x / 1.3x roughness,
//               weights 1 - w / w), split-sum environment specular, SH
//               diffuse ambient weighted by 1 - E(n.v).
//   fast      = an approximation of the reference: D read from the
//               toolchain-baked 64x64 table `skin_lut` ([tables] in
//               skin.toml), bilinear at texel centres; everything else the
//               reference's.
//   seed      = a look: the seed's own table (the profile over +-pi/2 of
//               the ring, `seed_lut`) and its dual-lobe specular term as
//               written (sec. 3.2), with its specular occlusion.

// D(theta, r) per channel: the ring integral of the Burley profile weighted
// by d R(d) (bake/skin.rs has the derivation); `curvature` = 1/r in [0, 1].
fn skin_preintegrated(cos_theta: f32, curvature: f32, shape: vec3<f32>, x_max: f32) -> vec3<f32> {
    let flat = max(cos_theta, 0.0);
    if curvature <= 0.0 {
        return vec3<f32>(flat);
    }
    let r = 1.0 / curvature;
    let theta = acos(clamp(cos_theta, -1.0, 1.0));
    let s_max = max(shape.x, max(shape.y, shape.z));
    // Points cluster where the sharpest channel's kernel is (bake/skin.rs).
    let a = min(log(1.0 + x_max * s_max * r), 40.0);
    let e = exp(a) - 1.0;
    var num = vec3<f32>(0.0);
    var den = vec3<f32>(0.0);
    for (var k = 0u; k < 64u; k++) {
        let t = (f32(k) + 0.5) / 64.0;
        var g = t;
        var dg = 1.0;
        if a >= 1e-4 {
            g = (exp(a * t) - 1.0) / e;
            dg = a * exp(a * t) / e;
        }
        let x = x_max * g;
        let jac = x_max * dg;
        let d = 2.0 * r * abs(sin(0.5 * x));
        let light = max(cos(theta + x), 0.0) + max(cos(theta - x), 0.0);
        let w = (exp(-shape * d) + exp(-shape * d / 3.0)) * jac;
        num += light * w;
        den += 2.0 * w;
    }
    return select(vec3<f32>(flat), num / max(den, vec3<f32>(1e-30)), den > vec3<f32>(0.0));
}

// Normalised dual-lobe GGX: (1 - w) lobe at 0.75 r plus w lobe at 1.3 r,
// each D V F with height-correlated Smith V (UE4's subsurface-profile
// multipliers), so the pair reflects no more than one lobe would.
fn skin_dual_ggx(n: vec3<f32>, h: vec3<f32>, n_dot_v: f32, n_dot_l: f32, v_dot_h: f32, roughness: f32, w: f32, f0: f32) -> f32 {
    let r0 = clamp(roughness * 0.75, 0.0, 1.0);
    let r1 = clamp(roughness * 1.3, 0.0, 1.0);
    let lobe0 = weft_d_ggx_nh(n, h, r0) * weft_v_smith_ggx_correlated(n_dot_v, n_dot_l, r0);
    let lobe1 = weft_d_ggx_nh(n, h, r1) * weft_v_smith_ggx_correlated(n_dot_v, n_dot_l, r1);
    let f = weft_f_schlick(vec3<f32>(f0), v_dot_h).x;
    return mix(lobe0, lobe1, saturate(w)) * f;
}

@fragment
fn fs_main(in: WeftVaryings) -> @location(0) vec4<f32> {
    // ------------------------------------------------------------ surface
    let uv = weft_transform_uv(in.uv0, material.base_map_st);
    let base_rgba = material.base_color * textureSample(base_map, material_sampler, uv);
    let albedo = saturate(base_rgba.rgb);
    let alpha = saturate(base_rgba.a);
    let roughness = clamp(material.roughness, 0.05, 1.0);
    let f0 = clamp(material.specular, 0.0, 1.0);
    let mask = saturate(textureSample(specular_mask, material_sampler, uv).r);

    // ------------------------------------------------------------ geometry
    let surface = weft_surface(in.world_position, in.world_normal);
    let v = surface.v;
    let n_geom = surface.n;
    // Curvature 1/r before any branch (derivatives need uniform control
    // flow): the seed's |fwidth(N)| / |fwidth(P)| x factor, or the map.
    let dn = length(fwidth(n_geom));
    let dp = length(fwidth(in.world_position));
    let estimated = select(0.0, dn / dp, dp > 1e-12);
    let mapped = textureSample(curvature_map, material_sampler, uv).r;
    let factor = max(material.curvature_factor, 0.0);
    var curvature = saturate(factor * estimated);
    if CURVATURE_MAP {
        curvature = saturate(factor * mapped);
    }
    var n = n_geom;
    if NORMAL_MAP {
        let texel = textureSample(normal_map, material_sampler, uv).rgb;
        n = weft_mapped_normal(n, in.world_tangent, texel, material.normal_strength);
    }
    let lit = weft_main_light_geometry(n, v);
    // The table's u: signed N.L mapped to [0, 1], clamped to the artist's
    // bounds (the seed's _SkinSSSDarkBound / _SkinSSSBrightBound).
    let u = clamp(dot(n, lit.l) * 0.5 + 0.5, material.dark_bound, material.bright_bound);

    // ------------------------------------------------------------ diffuse falloff
    var falloff: vec3<f32>;
    if WEFT_TIER == TIER_REFERENCE {
        falloff = skin_preintegrated(2.0 * u - 1.0, curvature, skin_lut_shape, skin_lut_ring);
    } else if WEFT_TIER == TIER_SEED {
        falloff = table_seed_lut(vec2<f32>(u, curvature)).rgb;
    } else {
        falloff = table_skin_lut(vec2<f32>(u, curvature)).rgb;
    }
    falloff = max(falloff, vec3<f32>(0.0));

    // ------------------------------------------------------------ specular
    let env_brdf = weft_env_brdf_from_lut(vec3<f32>(f0), weft_env_brdf_lut(lit.n_dot_v, roughness));
    var specular: f32;
    var kd: vec3<f32>;
    if WEFT_TIER == TIER_SEED {
        let linear_roughness = roughness * roughness;
        specular = skin_seed_specular(n, lit.l, lit.h, linear_roughness, mask, material.lobe_weight) * f0 * lit.n_dot_l;
        kd = vec3<f32>(1.0 - f0);
    } else {
        specular = skin_dual_ggx(n, lit.h, lit.n_dot_v, lit.n_dot_l, lit.v_dot_h, roughness, material.lobe_weight, f0) * lit.n_dot_l * mask;
        // Diffuse gets what the specular layer did not reflect (1 - E).
        kd = max(vec3<f32>(1.0) - env_brdf, vec3<f32>(0.0));
    }
    let light = weft_main_light_radiance();
    // The pre-integrated falloff replaces n.l for the diffuse term only.
    let direct = (kd * weft_diffuse_lambert(albedo) * falloff + vec3<f32>(specular)) * light;

    // ------------------------------------------------------------ indirect
    let indirect_diffuse = weft_sh_irradiance(n) * kd * albedo;
    let indirect_specular = weft_prefiltered_radiance(reflect(-v, n), roughness) * env_brdf * mask;
    let color = direct + indirect_diffuse + indirect_specular;
    let radiance = clamp(color, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    return vec4<f32>(radiance, alpha);
}
