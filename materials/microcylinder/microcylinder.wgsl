// @include "lib/forward.wgsl"
// @include "lib/microcylinder.wgsl"
// @include "lib/microcylinder_nodes.wgsl"
//
// microcylinder: woven cloth from two thread sets (seed 000; Sadeghi,
// Bisker, De Deken, Jensen 2013). Returns linear HDR radiance.
//
// Thread set 1 (warp) runs along the mesh tangent, thread set 2 (weft) along
// the bitangent; each is tilted about the other by its tangent offsets. The
// BSDF itself is the pure code of lib/microcylinder.wgsl (the model, the
// reference; see its header for the formulas) and lib/microcylinder_nodes.wgsl
// (the node rule of low and fast); this file reads the uniforms and sums over the main light:
//
// Tiers (WEFT_TIER):
//   fast      = the same offset distribution and lobe with a few nodes per
//               range of offsets, each range clipped to the offsets where
//               M P > 0: offset-list segments (halved beyond 60 deg) by a
//               3-point Gauss-Legendre rule; a curve by one range in t
//               (slope linear through t = 0, 1/2, 1, arc-length weighted)
//               and 2 nodes (Gauss-Legendre, or the 2-point Gauss-Jacobi
//               rule for the weight (t - t0)^2 (t1 - t)^2 where both ends
//               are support bounds and M P vanishes quadratically); the
//               surface Gaussian in theta_h averaged exactly (erf) over each
//               node's cell, the volume Gaussian (twice as wide) sampled at
//               the nodes; exact dielectric F_r in a one-division form,
//               Schlick's transmission in and out; transcendental-light
//               angle forms (one polynomial asin for theta_h, u() from a
//               series in cos); what depends on the uniforms alone from
//               the vertex stage (below). 3.72x standard fast on navi21
//               and gfx1100 (loop-aware model), worst FLIP 0.048 (README).
//   low       = an approximation of the reference: the 3-node rule (the
//               same clipped ranges, 3 nodes for lists and curves, erf-exact
//               cell means of both Gaussians: fast's rule before the cost
//               work)
//               with each node's slowly varying factors (masking and
//               reweighting blends, cos(phi_d/2), cos^2(theta_d), the three
//               exact Fresnel terms) in weft_half (f16 with shader-f16, the
//               f32 fallback otherwise); theta_h, the support and the
//               Gaussians in f32 (mc_thread_*_low, lib/microcylinder.wgsl).
//   reference = the whole tangent curve integrated (32 arc-length-weighted
//               segments, or the offset list interpolated in <= 1 deg
//               sub-steps); exact dielectric Fresnel reflection and
//               transmission in and out; atan2 angles.
// Keywords: USE_SECOND_PARA (second thread set; off = a2 = 0),
// TANGENT_OFFSETS = curve (the seed's curves) | list (Table II lists).
//
// Vertex stage (vs_microcylinder): lib/forward.wgsl's, plus what depends on
// the uniforms alone, flat: fast's McFastConst per thread set and the
// ambient's mean Fresnel per thread set. The same value at every vertex, so
// the fragment stage reads it instead of computing it per pixel (README,
// "Per-vertex constants").
//
// Ambient (all tiers, cheap and documented as an approximation): L2 SH
// irradiance E(n)/pi times the coverage-weighted (A_j + mean Fresnel of
// eta_j); no environment specular (README "Ambient" compares it with the
// model's own hemispherical response).

// Thread parameters from the uniforms, clamped to their physical domains so
// that out-of-range uniforms cannot produce negative or non-finite values.
fn microcylinder_thread(color: vec3<f32>, ior: f32, isotropy: f32, gamma_s_deg: f32, gamma_v_deg: f32, tint: vec3<f32>) -> McThread {
    return McThread(
        saturate(color * tint),
        clamp(ior, 1.0, 4.0),
        saturate(isotropy),
        max(gamma_s_deg, 0.0) * MC_DEG,
        max(gamma_v_deg, 0.0) * MC_DEG,
    );
}

// Cosine-weighted hemispherical mean of Schlick's Fresnel:
// 2 int_0^1 (f0 + (1 - f0)(1 - mu)^5) mu dmu = f0 + (1 - f0) / 21.
fn microcylinder_mean_fresnel(eta: f32) -> f32 {
    let f0 = weft_f0_from_ior(eta);
    return f0 + (1.0 - f0) / 21.0;
}

// lib/forward.wgsl's varyings (locations 0-3) and the flat values of the
// uniforms alone (both thread sets'; zero for a thread set or tier that does
// not read them).
struct MicrocylinderVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) world_tangent: vec4<f32>,
    @location(3) uv0: vec2<f32>,
    @location(4) @interpolate(flat) thread1_shape: vec4<f32>,
    @location(5) @interpolate(flat) thread1_curve: vec4<f32>,
    @location(6) @interpolate(flat) thread1_steps: vec2<f32>,
    @location(7) @interpolate(flat) thread2_shape: vec4<f32>,
    @location(8) @interpolate(flat) thread2_curve: vec4<f32>,
    @location(9) @interpolate(flat) thread2_steps: vec2<f32>,
    // The ambient's mean Fresnel of thread sets 1 and 2.
    @location(10) @interpolate(flat) mean_fresnel: vec2<f32>,
}

// The thread set's McFastConst where fast reads it (a list reads only its
// shape), else zero.
fn microcylinder_fast_const(th: McThread, heights: array<vec4<f32>, 9>) -> McFastConst {
    var k = McFastConst();
    if WEFT_TIER == TIER_FAST {
        if TANGENT_OFFSETS == TANGENT_OFFSETS_LIST {
            k.shape = mc_fast_shape(th);
        } else {
            k = mc_fast_const(th, heights);
        }
    }
    return k;
}

@vertex
fn vs_microcylinder(in: WeftVertexInput) -> MicrocylinderVaryings {
    let base = weft_forward_vertex(in);
    // The colour and its texture tint do not enter what is computed here.
    let th1 = microcylinder_thread(material.thread1_color.rgb, material.thread1_ior, material.thread1_isotropy,
                                   material.thread1_gamma_s, material.thread1_gamma_v, vec3<f32>(1.0));
    let th2 = microcylinder_thread(material.thread2_color.rgb, material.thread2_ior, material.thread2_isotropy,
                                   material.thread2_gamma_s, material.thread2_gamma_v, vec3<f32>(1.0));
    let k1 = microcylinder_fast_const(th1, material.thread1_curve);
    var k2 = McFastConst();
    if USE_SECOND_PARA {
        k2 = microcylinder_fast_const(th2, material.thread2_curve);
    }
    return MicrocylinderVaryings(
        base.clip_position, base.world_position, base.world_normal, base.world_tangent, base.uv0,
        k1.shape, k1.curve, k1.steps, k2.shape, k2.curve, k2.steps,
        vec2<f32>(microcylinder_mean_fresnel(th1.eta), microcylinder_mean_fresnel(th2.eta)),
    );
}

@fragment
fn fs_main(in: MicrocylinderVaryings) -> @location(0) vec4<f32> {
    // ------------------------------------------------------------ inputs
    let uv = weft_transform_uv(in.uv0, material.albedo_map_st);
    let tint = max(textureSample(albedo_map, material_sampler, uv).rgb, vec3<f32>(0.0));
    let th1 = microcylinder_thread(material.thread1_color.rgb, material.thread1_ior, material.thread1_isotropy,
                                   material.thread1_gamma_s, material.thread1_gamma_v, tint);
    let th2 = microcylinder_thread(material.thread2_color.rgb, material.thread2_ior, material.thread2_isotropy,
                                   material.thread2_gamma_s, material.thread2_gamma_v, tint);
    let a1 = saturate(material.thread1_coverage);
    let a2 = select(0.0, saturate(material.thread2_coverage), USE_SECOND_PARA);
    let brightness = max(material.brightness, 0.0);

    // ------------------------------------------------------------ geometry
    // Fallbacks: lib/surface.wgsl. weft_tangent_frame handles zero-length
    // and non-orthogonal tangents (any perpendicular is used).
    let surface = weft_surface(in.world_position, in.world_normal);
    let v_raw = surface.v;
    let n = surface.n;
    let frame = weft_tangent_frame(n, in.world_tangent);
    let t = frame[0];
    let b = frame[1];
    // Interpolated normals can face slightly away from the camera near
    // silhouettes: lift v to 1e-3 above the horizon instead of going black
    // (v = -n lifts to n).
    let v = weft_safe_normalize(v_raw + n * max(1e-3 - dot(n, v_raw), 0.0), n);
    let l = weft_main_light_direction();

    let warp = McFrame(t, b, n);
    let weft = McFrame(b, t, n);

    // ------------------------------------------------------------ direct
    // Each tier/keyword branch calls only its own functions so the others
    // vanish from the variant.
    var s1 = vec4<f32>(0.0);
    var s2 = vec4<f32>(0.0);
    if WEFT_TIER == TIER_REFERENCE {
        if TANGENT_OFFSETS == TANGENT_OFFSETS_LIST {
            s1 = mc_thread_list_reference(warp, l, v, th1, material.thread1_offsets_a, material.thread1_offsets_b, material.thread1_offset_count);
            if USE_SECOND_PARA {
                s2 = mc_thread_list_reference(weft, l, v, th2, material.thread2_offsets_a, material.thread2_offsets_b, material.thread2_offset_count);
            }
        } else {
            s1 = mc_thread_curve_reference(warp, l, v, th1, material.thread1_curve);
            if USE_SECOND_PARA {
                s2 = mc_thread_curve_reference(weft, l, v, th2, material.thread2_curve);
            }
        }
    } else if WEFT_TIER == TIER_LOW {
        if TANGENT_OFFSETS == TANGENT_OFFSETS_LIST {
            s1 = mc_thread_list_low(warp, l, v, th1, material.thread1_offsets_a, material.thread1_offsets_b, material.thread1_offset_count);
            if USE_SECOND_PARA {
                s2 = mc_thread_list_low(weft, l, v, th2, material.thread2_offsets_a, material.thread2_offsets_b, material.thread2_offset_count);
            }
        } else {
            s1 = mc_thread_curve_low(warp, l, v, th1, material.thread1_curve);
            if USE_SECOND_PARA {
                s2 = mc_thread_curve_low(weft, l, v, th2, material.thread2_curve);
            }
        }
    } else {
        if TANGENT_OFFSETS == TANGENT_OFFSETS_LIST {
            s1 = mc_thread_list_fast_with(warp, l, v, th1, in.thread1_shape, material.thread1_offsets_a, material.thread1_offsets_b, material.thread1_offset_count);
            if USE_SECOND_PARA {
                s2 = mc_thread_list_fast_with(weft, l, v, th2, in.thread2_shape, material.thread2_offsets_a, material.thread2_offsets_b, material.thread2_offset_count);
            }
        } else {
            s1 = mc_thread_curve_fast_with(warp, l, v, th1, McFastConst(in.thread1_shape, in.thread1_curve, in.thread1_steps));
            if USE_SECOND_PARA {
                s2 = mc_thread_curve_fast_with(weft, l, v, th2, McFastConst(in.thread2_shape, in.thread2_curve, in.thread2_steps));
            }
        }
    }
    // L_r / L_i (= BRDF x n.l), zero below either horizon.
    let direct = mc_combine(s1, s2, a1, a2, dot(n, l), dot(n, v)) * weft_main_light_radiance();

    // ------------------------------------------------------------ ambient
    // Cheap, documented approximation (README "Ambient"): SH irradiance
    // E(n)/pi times a per-thread "albedo + mean surface reflectance"
    // A_j + F_avg(eta_j), F_avg = f0 + (1 - f0)/21 (the cosine-weighted
    // hemispherical mean of Schlick), coverage-weighted. No environment
    // specular. With no coverage at all, thread set 1's.
    let amb1 = th1.albedo + vec3<f32>(in.mean_fresnel.x);
    let amb2 = th2.albedo + vec3<f32>(in.mean_fresnel.y);
    let cov = a1 + a2;
    let ambient_albedo = select(amb1, (a1 * amb1 + a2 * amb2) / max(cov, 1e-4), cov > 1e-4);
    let ambient = weft_sh_irradiance(n) * ambient_albedo;

    // Never negative; at most the fp16 maximum (a sharp lobe under a bright
    // light can exceed it; NaN cannot reach here: every division is guarded).
    let radiance = clamp((direct + ambient) * brightness, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    return vec4<f32>(radiance, 1.0);
}
