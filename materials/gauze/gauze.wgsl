// @include "lib/forward.wgsl"
// @include "lib/anisotropic.wgsl"
//
// gauze: sheer woven fabric (seed 001 sec. 4). Returns premultiplied linear
// HDR radiance: rgb = alpha * diffuse + coverage * specular, a = alpha
// (see the [[pass]] comment in gauze.toml for why premultiplied).
//
// Coverage (both tiers, seed 4.2.1):
//   s         = sin^d(theta), theta between view and the geometric normal
//   opacity_t = 1 - log(t) / log(1000)          thread transmittance t
//   alpha     = 1 - (1 - s)(1 - mesh * opacity_t)
//   coverage  = 1 - (1 - s)(1 - mesh)           where threads are (specular)
// Highlight (seed 4.2.2 - 4.2.6): anisotropic GGX with ax = r^2 (1 + k),
// ay = r^2 (1 - k) in a tangent frame rotated by `pattern_rotation` where the
// thread-pattern map exceeds the threshold, times the highlight noise.
// Tiers (WEFT_TIER):
//   seed      = a look, the seed's form: D = 1 / (pi q^2) (no 1/(ax ay)), Schlick-GGX
//               visibility (seed 004 form), times anisotropic intensity,
//               scatter colour and scatter intensity; hard threshold; analytic
//               split-sum fit for the environment.
//   reference = normalised anisotropic GGX D, height-correlated anisotropic
//               Smith V (Heitz 2014), Schlick F with F0 = 0.04, tinted by the
//               scatter colour clamped to <= 1 (albedo <= 1); the intensity
//               sliders are not applied; the rotation is anti-aliased (the two
//               lobes blended by the sub-pixel fraction above the threshold);
//               the toolchain's split-sum LUT, ambient kd = 1 - E_spec.
//   fast      = an approximation of the reference: one lobe instead of two,
//               in the frame turned by the blended angle rot * above_aa (the
//               reference's own frames wherever above_aa is 0 or 1, i.e.
//               outside the one-pixel anti-aliasing band of the threshold).
// All: Lambert diffuse (1/pi), L2 SH ambient, prefiltered environment
// sampled along the anisotropic bent reflection vector.

// ln(1000): thread transmittance 1..1000 maps to opacity 1..0 on a log scale.
const GAUZE_LN_MAX_TRANSMITTANCE: f32 = 6.907755279;

// Coverage of a procedural square-hole grid: 1 - open_x * open_y with holes of
// width `gap` (fraction of a cell) centred in each cell. Each axis is
// box-filtered over the pixel footprint w = fwidth(cell) (a linear ramp of
// width w), and fades to its mean `gap` once a cell is smaller than a pixel,
// so the grid neither aliases nor turns into the wrong average. gap = 0 gives
// coverage 1 exactly. fwidth is taken by the caller in uniform control flow.
fn gauze_grid_coverage(cell: vec2<f32>, w: vec2<f32>, gap: f32) -> f32 {
    let g = clamp(gap, 0.0, 1.0);
    let d = abs(fract(cell) - vec2<f32>(0.5));
    // w floored: a constant UV (zero derivative) must not divide by zero.
    let ww = max(w, vec2<f32>(1e-4));
    let ramp = saturate((vec2<f32>(0.5 * g) - d) / ww + vec2<f32>(0.5));
    let open = mix(ramp, vec2<f32>(g), saturate(ww * 2.0 - vec2<f32>(1.0)));
    let open_xy = select(0.0, open.x * open.y, g > 0.0);
    return 1.0 - open_xy;
}

@fragment
fn fs_main(in: WeftVaryings, @builtin(front_facing) front_facing: bool) -> @location(0) vec4<f32> {
    // ------------------------------------------------------------ inputs
    let uv = weft_transform_uv(in.uv0, material.base_map_st);
    let base_rgba = material.base_color * textureSample(base_map, material_sampler, uv);
    // Clamped to the physical range: an albedo > 1 would make 1 - F tricks and
    // energy bounds meaningless, a negative one negative radiance.
    let base = saturate(base_rgba.rgb);
    let base_alpha = saturate(base_rgba.a);
    let roughness = saturate(material.roughness);
    let anisotropy = clamp(material.anisotropy, -1.0, 1.0);

    // Seed 4.2.7: one sampling density scales the UVs of the pattern, noise and
    // mesh maps.
    let uv_s = in.uv0 * material.sampling_density;
    let mesh_tex = saturate(textureSample(mesh_map, material_sampler, uv_s).r);
    let noise = saturate(textureSample(noise_map, material_sampler, uv_s).r);
    let pattern = textureSample(pattern_map, material_sampler, uv_s).r;
    // Derivatives in uniform control flow (before any branch).
    let grid_w = fwidth(uv_s);
    let pattern_w = fwidth(pattern);
    let mesh = mesh_tex * gauze_grid_coverage(uv_s, grid_w, material.mesh_gap);

    // ------------------------------------------------------------ geometry
    // Double-sided: back faces shade with the flipped normal (lib/surface.wgsl).
    let surface = weft_surface_two_sided(in.world_position, in.world_normal, front_facing);
    let v = surface.v;
    let n_geom = surface.n;
    var n = n_geom;
    if NORMAL_MAP {
        let nuv = weft_transform_uv(in.uv0, material.normal_map_st);
        let texel = textureSample(normal_map, material_sampler, nuv).rgb;
        n = weft_mapped_normal(n_geom, in.world_tangent, texel, material.normal_strength);
    }
    // Tangent frame of the (mapped) shading normal; a zero or normal-parallel
    // tangent falls back to an arbitrary perpendicular inside weft_tangent_frame.
    let frame = weft_tangent_frame(n, in.world_tangent);

    // ------------------------------------------------------------ coverage
    // theta from the geometric normal (the weave's projection, not the
    // normal-mapped bumps). |cos| so either side works; sin via sqrt of a
    // clamped difference (never negative). pow(0, d) is undefined in some
    // backends: the base is floored at 1e-8 (1e-8^1 is already invisible).
    let cos_v = min(abs(dot(n_geom, v)), 1.0);
    let sin_v = sqrt(max(1.0 - cos_v * cos_v, 0.0));
    let density = clamp(material.thread_density, 0.0, 200.0);
    let s = pow(max(sin_v, 1e-8), density);
    // log of a value >= 1: thread_transmittance is clamped into its range.
    let transmittance = clamp(material.thread_transmittance, 1.0, 1000.0);
    let thread_opacity = saturate(1.0 - log(transmittance) / GAUZE_LN_MAX_TRANSMITTANCE);
    let alpha = saturate((1.0 - (1.0 - s) * (1.0 - mesh * thread_opacity)) * base_alpha);
    let coverage = saturate((1.0 - (1.0 - s) * (1.0 - mesh)) * base_alpha);

    // ------------------------------------------------------------ highlight frame
    // Seed 4.2.6: above the threshold the highlight turns by pattern_rotation.
    let rot = radians(material.pattern_rotation);
    let frame_rot = weft_rotate_tangent_frame(frame, rot);
    // seed: a hard threshold (the seed). fast, reference: the fraction of the pixel
    // footprint above the threshold (linear ramp over fwidth), so the two lobes
    // blend instead of aliasing. fwidth floored against division by zero.
    let above_hard = select(0.0, 1.0, pattern > material.pattern_threshold);
    let above_aa = saturate((pattern - material.pattern_threshold) / max(pattern_w, 1e-4) + 0.5);

    let lit = weft_main_light_geometry(n, v);
    let alphas = weft_aniso_alpha_kulla(roughness, anisotropy);
    let light = weft_main_light_radiance();

    // Highlight colour: the scatter colour only tints the highlight (seed 4.2.4).
    let scatter = max(material.scatter_color.rgb, vec3<f32>(0.0));
    let tint = saturate(scatter);
    let f0 = vec3<f32>(WEFT_DIELECTRIC_F0);

    var spec_direct: vec3<f32>;
    var env_brdf: vec3<f32>;
    var diffuse_kd: vec3<f32>;
    var ambient_kd: vec3<f32>;
    if WEFT_TIER != TIER_SEED {
        var lobe: f32;
        if WEFT_TIER == TIER_REFERENCE {
            let vf = weft_aniso_to_frame(frame, v);
            let lf = weft_aniso_to_frame(frame, lit.l);
            let vr = weft_aniso_to_frame(frame_rot, v);
            let lr = weft_aniso_to_frame(frame_rot, lit.l);
            // D V n.l of each frame (finite; 0 below the horizon).
            let lobe0 = weft_spec_ggx_aniso(vf, lf, alphas.x, alphas.y);
            let lobe1 = weft_spec_ggx_aniso(vr, lr, alphas.x, alphas.y);
            lobe = mix(lobe0, lobe1, above_aa);
        } else {
            // fast: one lobe, in the frame turned by the blended angle (the
            // same as the reference away from the threshold's AA band).
            let fb = weft_rotate_tangent_frame(frame, rot * above_aa);
            lobe = weft_spec_ggx_aniso(weft_aniso_to_frame(fb, v), weft_aniso_to_frame(fb, lit.l), alphas.x, alphas.y);
        }
        let f = weft_f_schlick(f0, lit.v_dot_h);
        // Tint <= 1 and F <= 1: directional albedo <= 1 (lib/anisotropic.wgsl).
        spec_direct = lobe * f * tint * noise * light;
        // Diffuse gets what the tinted lobe cannot reflect, 1 - tint F(n.v)
        // (not 1 - F(v.h): that lets the total albedo reach 1.8 at grazing
        // views with sharp lobes; this one measures <= 1.0007, see README).
        diffuse_kd = vec3<f32>(1.0) - tint * weft_f_schlick(f0, lit.n_dot_v);
        env_brdf = weft_env_brdf_from_lut(f0, weft_env_brdf_lut(lit.n_dot_v, roughness)) * tint;
        ambient_kd = max(vec3<f32>(1.0) - env_brdf, vec3<f32>(0.0));
    } else {
        // The seed's D; the frame is chosen by the hard threshold.
        let fr = weft_rotate_tangent_frame(frame, rot * above_hard);
        let hf = weft_aniso_to_frame(fr, lit.h);
        let d = weft_d_ggx_aniso_unnormalized(hf.x, hf.y, hf.z, alphas.x, alphas.y);
        let vis = weft_v_schlick_ggx(lit.n_dot_v, lit.n_dot_l, roughness);
        let gain = max(material.anisotropic_intensity, 0.0) * max(material.scatter_intensity, 0.0);
        spec_direct = (d * vis * lit.n_dot_l * gain * noise) * scatter * light;
        diffuse_kd = vec3<f32>(1.0);
        env_brdf = weft_env_brdf_approx(f0, lit.n_dot_v, roughness);
        ambient_kd = vec3<f32>(1.0) - weft_f_schlick_roughness(f0, lit.n_dot_v, roughness);
    }

    // ------------------------------------------------------------ diffuse
    let diffuse_direct = diffuse_kd * weft_diffuse_lambert(base) * light * lit.n_dot_l;
    let diffuse_indirect = weft_sh_irradiance(n) * ambient_kd * base;

    // ------------------------------------------------------------ environment specular
    // Anisotropic lobe approximated by a bent reflection vector into the
    // isotropic prefiltered cube (Filament); the bent normal is unit.
    let bent = weft_aniso_bent_normal(frame, v, anisotropy, roughness);
    let prefiltered = weft_prefiltered_radiance(reflect(-v, bent), roughness);
    let spec_indirect = prefiltered * env_brdf * noise;

    // ------------------------------------------------------------ output
    // Premultiplied: the diffuse radiance of the threads scaled by what they
    // cover, the highlight by where threads are (it is reflected at the
    // thread surface whatever their transmittance). Never negative, at most the
    // fp16 maximum (a sharp lobe under a bright light can exceed it).
    let color = alpha * (diffuse_direct + diffuse_indirect) + coverage * (spec_direct + spec_indirect);
    let radiance = clamp(color, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    return vec4<f32>(radiance, alpha);
}
