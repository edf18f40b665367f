// @include "lib/forward.wgsl"
// @include "lib/hair_bsdf.wgsl"
//
// hair: strand highlights for hair cards (seed 004 sec. 7). Returns linear
// HDR radiance. See README.md for the derivations and measurements.
//
// Every tier shades along the same strand tangent: the mesh's bitangent (or
// tangent), or the FLOW_MAP direction, tilted along the normal by the jitter
// map (its uv rotated where the UV-rotation mask says so) and a procedural
// per-strand noise.
//
// Tiers (WEFT_TIER):
//   reference = the energy-conserving fibre model of lib/hair_bsdf.wgsl
//               (d'Eon et al. 2011 M_p, Chiang et al. 2016 N_p and A_p: R,
//               TT, TRT and the residual), σ_a from the colour, averaged
//               over the fibre's width with HAIR_REFERENCE_CELLS cells
//               (N_p integrated per cell); multiple scattering between
//               fibres as a Lambert lobe carrying the colour's remainder.
//   fast      = an approximation of the reference (weft_hair_fast): the
//               same M_p (d'Eon's, with a closed-form e^(-x) I_0(x)) and
//               the h-average in closed form after Karis 2016: R and TT
//               at the offset whose exit azimuth is φ, weighted by the
//               smooth-limit density |dh/dφ| / 2 and blurred by the
//               logistic; TRT a logistic about φ = 0 of a fitted width;
//               ⟨A_0⟩, ⟨A_2⟩ at fitted offsets. No loop. README: its
//               error against the reference and its cost.
//   seed      = a look: the seed's Kajiya-Kay, smoothstep(-1, 0, t.h)
//               sin(t, h)^exponent intensity, plus Scheuermann's second
//               shifted highlight, over Lambert diffuse and SH ambient.

// Cells across the fibre in the reference's h average (equal cells in γ_o):
// converged (tests/physics/hair_furnace.rs: within 0.6 % of 2048
// intervals; 32 cells are 3.4 % off at β_n 0.15).
const HAIR_REFERENCE_CELLS: u32 = 64u;
// Body shadow: light more than this far below the surface (in n.l) is
// blocked by the head behind the hair; the band up to +this is the thin
// layer at the terminator where light still passes (README).
const HAIR_TERMINATOR: f32 = 0.25;

// lib/forward.wgsl's varyings (locations 0-3) and, flat, what the fragment
// stage takes from the uniforms alone (the physical tiers' weft_hair_params
// but σ_a, and every tier's jitter rotation and noise period; the same value
// at every vertex): RDNA has no scalar float ALU, so computed in the fragment
// stage it is per-pixel work (README, "Per-vertex constants").
struct HairVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) world_tangent: vec4<f32>,
    @location(3) uv0: vec2<f32>,
    // η, s, v (R), 1 / σ_a's polynomial in β_n (weft_hair_sigma_a_scale).
    @location(4) @interpolate(flat) fibre: vec4<f32>,
    // sin 2^k α, then R's floor; cos 2^k α, then sin(δ/2).
    @location(5) @interpolate(flat) sin2k: vec4<f32>,
    @location(6) @interpolate(flat) cos2k: vec4<f32>,
    // M_p's normalisation per lobe, then cos(δ/2); 1/v_p, then log s_TRT²'s
    // constant term; its a, a², a³, a⁴ coefficients.
    @location(7) @interpolate(flat) mp_norm: vec4<f32>,
    @location(8) @interpolate(flat) inv_v: vec4<f32>,
    @location(9) @interpolate(flat) trt: vec4<f32>,
    // cos and sin of the jitter's uv rotation, 1/η, the noise's period.
    @location(10) @interpolate(flat) jitter: vec4<f32>,
}

@vertex
fn vs_hair(in: WeftVertexInput) -> HairVaryings {
    let base = weft_forward_vertex(in);
    var h = weft_hair_params(vec3<f32>(0.0), material.ior, material.roughness, material.azimuthal_roughness, material.scale_angle);
    var scale = 0.0;
    if WEFT_TIER == TIER_SEED {
        h = WeftHair();
    } else {
        scale = weft_hair_sigma_a_scale(material.azimuthal_roughness);
    }
    let a = radians(material.anisotropic_direction);
    return HairVaryings(
        base.clip_position, base.world_position, base.world_normal, base.world_tangent, base.uv0,
        vec4<f32>(h.eta, h.s, h.v.x, scale),
        vec4<f32>(h.sin2k, h.r_floor), vec4<f32>(h.cos2k, h.blur.x),
        vec4<f32>(h.mp_norm, h.blur.y), vec4<f32>(h.inv_v, h.trt.x), vec4<f32>(h.trt.yzw, h.trt4),
        vec4<f32>(cos(a), sin(a), h.inv_eta, hair_noise_period(material.strand_density)),
    );
}

// WeftHair from the flat varyings and the pixel's σ_a (v_TT, v_TRT and the
// residual's as weft_hair_params forms them).
fn hair_from_varyings(in: HairVaryings, sigma_a: vec3<f32>) -> WeftHair {
    let v = in.fibre.z;
    return WeftHair(max(sigma_a, vec3<f32>(0.0)), in.fibre.x, vec4<f32>(v, 0.25 * v, 4.0 * v, 4.0 * v), in.fibre.y,
                    in.sin2k.xyz, in.cos2k.xyz, in.inv_v.xyz, in.mp_norm.xyz, vec2<f32>(in.cos2k.w, in.mp_norm.w),
                    in.sin2k.w, vec4<f32>(in.inv_v.w, in.trt.xyz), in.trt.w, in.jitter.z);
}

@fragment
fn fs_main(in: HairVaryings) -> @location(0) vec4<f32> {
    // ------------------------------------------------------------ surface
    let uv = weft_transform_uv(in.uv0, material.base_map_st);
    let base_rgba = material.base_color * textureSample(base_map, material_sampler, uv);
    let base = saturate(base_rgba.rgb);
    let alpha = saturate(base_rgba.a);

    // ------------------------------------------------------------ geometry
    let surface = weft_surface(in.world_position, in.world_normal);
    let v = surface.v;
    let n = surface.n;
    let frame = weft_tangent_frame(n, in.world_tangent);
    let strand = hair_strand(frame, in.uv0);
    let shift = hair_jitter(in.uv0, in.jitter.xy, in.jitter.w);
    let l = weft_main_light_direction();
    let light = weft_main_light_radiance();
    let ambient = weft_sh_irradiance(n);
    let n_dot_l = dot(n, l);

    var color: vec3<f32>;
    if WEFT_TIER == TIER_SEED {
        // -------------------------------------------------------- seed (look)
        // Unity's diffuse has no 1/π and the seed's specular is added to it:
        // both are divided by π here (weft's Lambert), keeping their ratio.
        let h = weft_safe_normalize(l + v, n);
        let t1 = weft_safe_normalize(strand + (material.primary_shift + shift) * n, strand);
        let t2 = weft_safe_normalize(strand + (material.secondary_shift + shift) * n, strand);
        let primary = material.primary_color.rgb * (material.primary_intensity * hair_kajiya_kay(t1, h, material.primary_exponent));
        let secondary = material.secondary_color.rgb * (material.secondary_intensity * hair_kajiya_kay(t2, h, material.secondary_exponent));
        let direct = (base + primary + secondary) * WEFT_INV_PI * light * saturate(n_dot_l);
        color = direct + ambient * base;
    } else {
        let t = weft_safe_normalize(strand + shift * n, strand);
        let hair = hair_from_varyings(in, weft_hair_sigma_a_scaled(base, in.fibre.w));
        let angles = weft_hair_angles(t, v, l);
        var lobes: WeftHairLobes;
        if WEFT_TIER == TIER_REFERENCE {
            lobes = weft_hair_mean(hair, angles, HAIR_REFERENCE_CELLS);
        } else {
            lobes = weft_hair_fast(hair, t, v, l);
        }
        let body = smoothstep(-HAIR_TERMINATOR, HAIR_TERMINATOR, n_dot_l);
        // Multiple scattering between fibres (README, "Colour"): the fibres
        // in front send back ⟨A_R + A_TRT⟩ themselves; of the rest, which
        // enters the lock, the fraction `base` leaves it again (Chiang et
        // al. fit σ_a so that a lock shows that colour), diffusely: a
        // Lambert lobe for the light, the SH irradiance for the ambient.
        let multiple = base * (vec3<f32>(1.0) - lobes.back);
        let direct = lobes.s * body + multiple * (WEFT_INV_PI * saturate(n_dot_l));
        color = direct * light + ambient * (multiple + lobes.back);
    }

    // Never negative, at most the fp16 maximum (Rgba16Float targets).
    let radiance = clamp(color, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    return vec4<f32>(radiance, alpha);
}

// The seed's Kajiya-Kay highlight: smoothstep(-1, 0, t.h) sin(t, h)^exponent.
// sin is formed from the clamped cosine (t.h can leave [-1, 1] by rounding).
fn hair_kajiya_kay(t: vec3<f32>, h: vec3<f32>, exponent: f32) -> f32 {
    let t_dot_h = clamp(dot(t, h), -1.0, 1.0);
    let sin_th = sqrt(max(1.0 - t_dot_h * t_dot_h, 0.0));
    let dir_atten = smoothstep(-1.0, 0.0, t_dot_h);
    return dir_atten * pow(sin_th, max(exponent, 1.0));
}

// The strand direction (world, unit, in the tangent plane): the mesh's
// bitangent (hair cards run root to tip along v) or tangent, or with
// FLOW_MAP the map's tangent-space direction (rgb * 2 - 1, as the seed
// decodes it). The map's component along the normal is dropped (the jitter
// supplies the tilt), and a texel with no direction in the plane (the
// default `normal` texel, (0, 0, 1)) keeps the mesh's.
fn hair_strand(frame: mat3x3<f32>, uv0: vec2<f32>) -> vec3<f32> {
    var ts = select(vec2<f32>(0.0, 1.0), vec2<f32>(1.0, 0.0), material.strand_along_tangent != 0u);
    if FLOW_MAP {
        let f = textureSample(flow_map, material_sampler, uv0).xy * 2.0 - 1.0;
        let len2 = dot(f, f);
        ts = select(ts, f * inverseSqrt(max(len2, 1e-12)), len2 > 1e-4);
    }
    return weft_safe_normalize(frame[0] * ts.x + frame[1] * ts.y, frame[1]);
}

// The tilt of the strand along the normal: the seed's jitter map (its red
// channel, with its own tiling; in the masked region of the UV-rotation mask,
// step(0.8, mask), the uv is first rotated by the direction angle, as the
// seed does for cards unwrapped across the strands) times its strength, plus
// a procedural per-strand noise across the strands. `rotation`: cos and sin
// of the direction angle; `noise_period`: hair_noise_period of the density
// (both from the vertex stage's flat `jitter` varying).
fn hair_jitter(uv0: vec2<f32>, rotation: vec2<f32>, noise_period: f32) -> f32 {
    let mask = step(0.8, textureSample(uv_rotate_mask, material_sampler, uv0).r);
    let c = rotation.x;
    let s = rotation.y;
    // HLSL mul(float2x2(c, s, -s, c), uv): rows (c, s) and (-s, c).
    let rotated = vec2<f32>(c * uv0.x + s * uv0.y, -s * uv0.x + c * uv0.y);
    let uv_j = weft_transform_uv(select(uv0, rotated, mask > 0.5), material.jitter_map_st);
    let j = textureSample(jitter_map, material_sampler, uv_j).r;
    // Across the strands: u when they run along v, and v otherwise.
    let across = select(uv_j.x, uv_j.y, material.strand_along_tangent != 0u);
    let noise = hair_value_noise(across * material.strand_density, noise_period);
    return material.jitter_strength * j + material.strand_noise * noise;
}

// The noise's period in cells: the strand density, rounded, at least 1.
fn hair_noise_period(density: f32) -> f32 {
    return max(round(density), 1.0);
}

// 1-D value noise in [-0.5, 0.5]: a hash per integer cell (PCG, Jarzynski &
// Olano 2020), smoothstep-interpolated; deterministic on every GPU. The cells
// repeat every `p` (hair_noise_period), so the noise wraps across a uv seam
// (u = 0 and 1 on the sphere) when the density and the tiling are integers.
fn hair_value_noise(x: f32, p: f32) -> f32 {
    let cell = floor(x);
    let f = x - cell;
    let c0 = cell - p * floor(cell / p);
    let c1 = select(c0 + 1.0, 0.0, c0 + 1.0 >= p);
    let a = hair_hash(u32(c0));
    let b = hair_hash(u32(c1));
    return mix(a, b, f * f * (3.0 - 2.0 * f)) - 0.5;
}

fn hair_hash(x: u32) -> f32 {
    let state = x * 747796405u + 2891336453u;
    let word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return f32((word >> 22u) ^ word) * (1.0 / 4294967296.0);
}
