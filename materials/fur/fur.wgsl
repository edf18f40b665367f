// @include "lib/sheen_lighting.wgsl"
// @include "lib/surface.wgsl"
//
// fur: shell fur (seed 001 sec. 8, seed 003). Two passes: `skin` (opaque,
// vs_skin/fs_skin) is the surface itself, the roots of the fur; `shells`
// (alpha-blended, no depth write, one instanced draw of `shell_count`
// instances, vs_shell/fs_shell) extrudes shell i of n to offset
// (i + 1/2) / n of the fur length along the combed strand direction and cuts
// it from a strand noise. Returns linear HDR radiance. See README.md.
//
// Tiers (WEFT_TIER):
//   reference = Charlie sheen (Conty Estevez & Kulla 2017) with its Smith
//               visibility, sheen colour saturate(F0 + sheen colour), sheen
//               roughness 1 - smoothness, over a Lambert base scaled by
//               min(1 - max3(C) E(n.v), 1 - max3(C) E(n.l)) (the velvet
//               library); plus a Kajiya-Kay (1989) strand lobe along the
//               combed direction T in its exact cone form
//               (sin_l sin_v - cos_l cos_v)^p sin_l, the longitudinal
//               lobe normalised (sqrt((2p + 1) / 4pi)), with Schlick
//               Fresnel on F0; ambient diffuse (SH) scaled by the view-only
//               form, environment sheen C E(n.v) x prefiltered radiance.
//   fast      = an approximation of the reference: the same model, its
//               lighting evaluated per vertex (Gouraud) and interpolated
//               (fur_vertex_light): light, sheen lobe, albedo table, SH,
//               environment, Fresnel weight and the strand lobe's signed
//               angle from its cone; the fragment keeps the albedo and F0
//               (per pixel) and the strand's cos^p. The half-vector strand
//               form was measured and rejected (README).
//   seed      = a look: seed 003's lighting "put on the fur": BRDF1 with
//               FabricD in place of GGX (Schlick F, Schlick-GGX V), Lambert
//               diffuse, the fabric scatter rim added unlit, SH ambient, no
//               indirect specular, no strand highlight.
// Shell alpha (all tiers, seed 001 sec. 8.2.6 and seed 003):
//   a = step(mix(cut-off start, cut-off end, o or o^2), noise) x (1 - o)
//   x (1 - edge fade (1 - n.v)), the step antialiased over one pixel, as
//   the opacity of 1/20 of the fur (the seed's 20 shells): a shell of 1/n
//   blends with 1 - (1 - a)^(20/n).

// The seed's shell count (seed 001 sec. 8.2.5: "统一设置 20 层"): the
// shell opacity is defined per 1/20 of the fur.
const FUR_SEED_SHELLS: f32 = 20.0;

// Vertex inputs the material requires (position, normal, uv0).
struct FurInput {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(3) uv0: vec2<f32>,
}

struct FurVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    // Unit surface normal at the vertices (zero if degenerate).
    @location(1) world_normal: vec3<f32>,
    // Combed strand direction at this shell (not normalised).
    @location(2) strand: vec3<f32>,
    @location(3) uv0: vec2<f32>,
    // Shell offset: 0 on the skin, (i + 1/2) / n on shell i of n.
    @location(4) offset: f32,
    // `fast` only (zero in the other tiers): the lighting's angular terms,
    // evaluated per vertex (fur_vertex_light) and interpolated.
    @location(5) light_diffuse: vec4<f32>,
    @location(6) light_ambient: vec4<f32>,
    @location(7) light_sheen: vec4<f32>,
    @location(8) light_strand: vec4<f32>,
    @location(9) light_n_dot_v: f32,
}

fn fur_transform_uv(uv: vec2<f32>, st: vec4<f32>) -> vec2<f32> {
    return uv * st.xy + st.zw;
}

// Extrudes the vertex to `offset` of the fur length. Seed 003: the strand
// direction at offset o is mix(N, target, o), target = N (1 - s) + F s, the
// point is P + mix(N, target, o) L o, so the strand (the derivative in o) is
// N + 2 o (target - N). F = force direction + the force map's (rgb 2 - 1) x
// its scale (seed 001 sec. 8.2.8). L = fur length x (1 + height scale
// (h - 1)) (sec. 8.2.9).
fn fur_vertex(in: FurInput, offset: f32) -> FurVaryings {
    let model = weft_object.model;
    let nm = weft_object.normal_matrix;
    let normal3 = mat3x3<f32>(nm[0].xyz, nm[1].xyz, nm[2].xyz);
    let world = (model * vec4<f32>(in.position, 1.0)).xyz;
    let n = weft_safe_normalize(normal3 * in.normal, vec3<f32>(0.0));
    let uv = fur_transform_uv(in.uv0, material.base_map_st);

    let force_texel = textureSampleLevel(force_map, material_sampler, uv, 0.0).rgb;
    let force = material.force_direction + (force_texel * 2.0 - 1.0) * material.force_map_scale;
    let s = saturate(material.force_strength);
    let target_dir = n * (1.0 - s) + force * s;
    let height = textureSampleLevel(height_map, material_sampler, uv, 0.0).r;
    let hs = saturate(material.height_scale);
    let len = max(material.fur_length, 0.0) * max(1.0 + hs * (saturate(height) - 1.0), 0.0);
    let dir = mix(n, target_dir, offset);
    let p = world + dir * (len * offset);

    var out: FurVaryings;
    out.clip_position = weft_frame.view_proj * vec4<f32>(p, 1.0);
    out.world_position = p;
    out.world_normal = n;
    out.strand = n + 2.0 * offset * (target_dir - n);
    out.uv0 = in.uv0;
    out.offset = offset;
    if WEFT_TIER == TIER_FAST {
        let lit = fur_vertex_light(p, n, out.strand);
        out.light_diffuse = lit.diffuse;
        out.light_ambient = lit.ambient;
        out.light_sheen = lit.sheen;
        out.light_strand = lit.strand;
        out.light_n_dot_v = lit.n_dot_v;
    }
    return out;
}

@vertex
fn vs_skin(in: FurInput) -> FurVaryings {
    return fur_vertex(in, 0.0);
}

@vertex
fn vs_shell(in: FurInput, @builtin(instance_index) instance: u32) -> FurVaryings {
    let count = f32(max(material.shell_count, 1));
    return fur_vertex(in, (f32(instance) + 0.5) / count);
}

// ---------------------------------------------------------------- noise

// PCG hash (Jarzynski & Olano 2020): integer only, identical on every backend.
fn fur_pcg(x: u32) -> u32 {
    let state = x * 747796405u + 2891336453u;
    let word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// One strand per cell of `x`: its centre jittered by up to 0.15 of the
// cell, a cone of radius 0.35 (so it never crosses into a neighbour cell),
// peak 0.7..1. `salt` decorrelates layers. In [0, 1].
fn fur_strand_cell(x: vec2<f32>, salt: u32) -> f32 {
    let cell = floor(x);
    // Cells wrap at 2^16 so the hash input stays exact for any tiling.
    let c = vec2<u32>(vec2<i32>(cell - 65536.0 * floor(cell / 65536.0)));
    let h0 = fur_pcg(c.x + fur_pcg(c.y + salt));
    let h1 = fur_pcg(h0);
    let h2 = fur_pcg(h1);
    let jitter = (vec2<f32>(f32(h0 & 0xffffu), f32(h1 & 0xffffu)) / 65535.0 - 0.5) * 0.3;
    let peak = 0.7 + 0.3 * f32(h2 & 0xffffu) / 65535.0;
    let r = length(fract(x) - (vec2<f32>(0.5) + jitter));
    return saturate(1.0 - r / 0.35) * peak;
}

// Procedural strand noise: two jittered strand grids, the second rotated by
// about 37 degrees, 1.31x denser and offset, so no lattice shows; the
// brighter wins (strands overlap as in a pelt). In [0, 1].
fn fur_procedural_noise(x: vec2<f32>) -> f32 {
    let rotated = vec2<f32>(0.8 * x.x - 0.6 * x.y, 0.6 * x.x + 0.8 * x.y) * 1.31 + vec2<f32>(17.3, 5.9);
    return max(fur_strand_cell(x, 0u), fur_strand_cell(rotated, 0x9e3779b9u));
}

fn fur_noise(uv0: vec2<f32>) -> f32 {
    let x = fur_transform_uv(uv0, material.noise_map_st);
    if NOISE_MAP {
        return saturate(textureSample(noise_map, material_sampler, x).r);
    }
    return fur_procedural_noise(uv0 * material.noise_map_st.xy * material.strand_density + material.noise_map_st.zw);
}

// ---------------------------------------------------------------- shading

// Strand highlight exponent from smoothness: 2^(1 + 9 s), 2..1024.
fn fur_strand_exponent(smoothness: f32) -> f32 {
    return exp2(1.0 + 9.0 * saturate(smoothness));
}

// Kajiya-Kay (1989) in its exact cone form: (cone, sin_l), cone the cos of
// the angle between v and the mirror cone of l around the unit strand t,
// = sin_l sin_v - cos_l cos_v; the lobe is cone^p sin_l (sin_l: the
// fibre's projected width towards the light). The half-vector form
// sin(T, H)^(4p) sin_l (one square root less) was measured against it and
// rejected (worst FLIP 0.144 over the error grid; README).
fn fur_kajiya_kay_cone(t: vec3<f32>, l: vec3<f32>, v: vec3<f32>) -> vec2<f32> {
    let t_dot_l = clamp(dot(t, l), -1.0, 1.0);
    let t_dot_v = clamp(dot(t, v), -1.0, 1.0);
    let sin_l = sqrt(max(1.0 - t_dot_l * t_dot_l, 0.0));
    let sin_v = sqrt(max(1.0 - t_dot_v * t_dot_v, 0.0));
    return vec2<f32>(max(sin_l * sin_v - t_dot_l * t_dot_v, 0.0), sin_l);
}

// The longitudinal lobe cos^p normalised to unit integral over the angle
// from the cone, 1 / int cos^p = Gamma(p/2 + 1) / (sqrt(pi) Gamma(p/2 +
// 1/2)) ~ sqrt((2p + 1) / 4pi) (within 2% for p >= 2).
fn fur_strand_norm(p: f32) -> f32 {
    return sqrt((2.0 * p + 1.0) * 0.25 * WEFT_INV_PI);
}

// The reference's lighting with everything that does not depend on the
// albedo (light, sheen lobe, strand lobe, Fresnel weight, sheen albedo
// table, SH, environment), for `fast` to evaluate per vertex. What the
// albedo multiplies is kept apart, so textured albedo stays per pixel.
struct FurLight {
    // Main light x n.l / pi (Lambert); w = E(n.v).
    diffuse: vec4<f32>,
    // SH irradiance; w = E(n.l).
    ambient: vec4<f32>,
    // Sheen with colour 1: Charlie lobe x light + environment x E(n.v);
    // w = Schlick's weight (1 - l.h)^5.
    sheen: vec4<f32>,
    // Strand lobe x light with Fresnel 1 and strand colour 1, but for its
    // cone^p; w = the signed angle from the cone, a + b - pi (a, b: the
    // angles of l and v from t), cone = cos(a + b - pi). The angle is
    // smooth across the peak and interpolates well; the cone^p (p up to
    // 1024) is not, nor is the cone (flat at its peak), so the fragment
    // takes cos and pow.
    strand: vec4<f32>,
    // n.v for the edge fade.
    n_dot_v: f32,
}

fn fur_vertex_light(p: vec3<f32>, normal: vec3<f32>, strand: vec3<f32>) -> FurLight {
    let smoothness = saturate(material.smoothness);
    let surface = weft_surface(p, normal);
    let v = surface.v;
    let n = surface.n;
    let t = weft_safe_normalize(strand, n);
    let lit = weft_main_light_geometry(n, v);
    let light = weft_main_light_radiance();
    let sheen_r = weft_sheen_clamp_roughness(1.0 - smoothness);
    let e_v = weft_sheen_albedo(lit.n_dot_v, sheen_r);
    let e_l = weft_sheen_albedo(lit.n_dot_l, sheen_r);
    let sheen = weft_sheen_charlie(vec3<f32>(1.0), lit.n_dot_h, lit.n_dot_v, lit.n_dot_l, sheen_r) * light
        + weft_prefiltered_radiance(reflect(-v, n), sheen_r) * e_v;
    let p_exp = fur_strand_exponent(smoothness);
    let t_dot_l = clamp(dot(t, lit.l), -1.0, 1.0);
    let sin_l = sqrt(max(1.0 - t_dot_l * t_dot_l, 0.0));
    let cone_angle = acos(t_dot_l) + acos(clamp(dot(t, v), -1.0, 1.0)) - WEFT_PI;
    let lobe = max(material.strand_strength, 0.0) * fur_strand_norm(p_exp) * sin_l * lit.n_dot_l;
    var out: FurLight;
    out.diffuse = vec4<f32>(light * (WEFT_INV_PI * lit.n_dot_l), e_v);
    out.ambient = vec4<f32>(weft_sh_irradiance(n), e_l);
    out.sheen = vec4<f32>(sheen, weft_pow5(1.0 - saturate(dot(lit.l, lit.h))));
    out.strand = vec4<f32>(light * lobe, cone_angle);
    out.n_dot_v = saturate(dot(n, v));
    return out;
}

// `fast`: the reference's terms from the interpolated per-vertex light,
// times this pixel's albedo and F0 (the algebra of the reference's sum:
// Schlick's F0 + (1 - F0) w and the sheen colour are linear in F0, the
// albedo scaling takes the pixel's sheen colour).
fn fur_shade_fast(in: FurVaryings, base: vec3<f32>) -> vec3<f32> {
    let metallic = saturate(material.metallic);
    let f0 = mix(vec3<f32>(WEFT_DIELECTRIC_F0), base, metallic);
    let diffuse_albedo = base * (1.0 - metallic);
    let sheen_color = saturate(f0 + max(material.sheen_color.rgb, vec3<f32>(0.0)));
    let direct_scaling = weft_sheen_albedo_scaling(sheen_color, in.light_diffuse.w, in.light_ambient.w);
    let ambient_scaling = weft_sheen_albedo_scaling_view(sheen_color, in.light_diffuse.w);
    let fresnel = f0 + (vec3<f32>(1.0) - f0) * in.light_sheen.w;
    let strand_color = max(material.strand_color.rgb, vec3<f32>(0.0)) * fresnel;
    let cone_p = pow(max(cos(in.light_strand.w), 0.0), fur_strand_exponent(material.smoothness));
    return diffuse_albedo * (in.light_diffuse.rgb * direct_scaling + in.light_ambient.rgb * ambient_scaling)
        + sheen_color * in.light_sheen.rgb + strand_color * (in.light_strand.rgb * cone_p);
}

// Radiance of one fur fragment at shell offset `offset` (0: skin).
fn fur_shade(in: FurVaryings) -> vec4<f32> {
    let uv = fur_transform_uv(in.uv0, material.base_map_st);
    let base_rgba = material.base_color * textureSample(base_map, material_sampler, uv);
    let spot = saturate(textureSample(spot_map, material_sampler, uv).r);
    let base = mix(saturate(base_rgba.rgb), saturate(material.spot_color.rgb), spot);
    let alpha = saturate(base_rgba.a);

    var color: vec3<f32>;
    if WEFT_TIER == TIER_FAST {
        color = fur_shade_fast(in, base);
    } else {
        let metallic = saturate(material.metallic);
        let smoothness = saturate(material.smoothness);
        let roughness = 1.0 - smoothness;

        let surface = weft_surface(in.world_position, in.world_normal);
        let v = surface.v;
        let n = surface.n;
        let t = weft_safe_normalize(in.strand, n);
        let lit = weft_main_light_geometry(n, v);
        let l_dot_h = saturate(dot(lit.l, lit.h));

        let f0 = mix(vec3<f32>(WEFT_DIELECTRIC_F0), base, metallic);
        let diffuse_albedo = base * (1.0 - metallic);
        let light = weft_main_light_radiance();
        let ambient = weft_sh_irradiance(n);

        if WEFT_TIER == TIER_SEED {
            // Seed 003: velvet's look on the shells (materials/velvet seed tier).
            let visibility = weft_v_schlick_ggx(lit.n_dot_v, lit.n_dot_l, roughness);
            let f = weft_f_schlick(f0, l_dot_h);
            let specular = weft_fabric_d(lit.n_dot_h) * visibility * f;
            let diffuse = weft_diffuse_lambert(diffuse_albedo);
            let scatter = weft_fabric_scatter(material.sheen_color.rgb, lit.n_dot_l, lit.n_dot_v, material.scatter_scale);
            color = (diffuse + specular) * light * lit.n_dot_l + ambient * diffuse_albedo + scatter;
        } else {
            let sheen_color = saturate(f0 + max(material.sheen_color.rgb, vec3<f32>(0.0)));
            let sheen_r = weft_sheen_clamp_roughness(roughness);
            let e_v = weft_sheen_albedo(lit.n_dot_v, sheen_r);
            let e_l = weft_sheen_albedo(lit.n_dot_l, sheen_r);
            let ambient_scaling = weft_sheen_albedo_scaling_view(sheen_color, e_v);
            let scaling = weft_sheen_albedo_scaling(sheen_color, e_v, e_l);
            let sheen = weft_sheen_charlie(sheen_color, lit.n_dot_h, lit.n_dot_v, lit.n_dot_l, sheen_r);
            let p = fur_strand_exponent(smoothness);
            let kk = fur_kajiya_kay_cone(t, lit.l, v);
            let strand = pow(kk.x, p) * kk.y;
            // The fibre's surface reflection (the R lobe of hair models):
            // Schlick Fresnel on the metallic-workflow F0, so dielectric
            // fibres reflect ~4% at normal incidence; strand colour and
            // strength scale it. The body shadows the fibres where the
            // light is below the skin's horizon (n.l).
            let fresnel = weft_f_schlick(f0, l_dot_h);
            let strand_color = max(material.strand_color.rgb, vec3<f32>(0.0)) * fresnel;
            let strand_lobe = strand_color * (max(material.strand_strength, 0.0) * fur_strand_norm(p) * strand * lit.n_dot_l);
            let base_direct = weft_diffuse_lambert(diffuse_albedo) * (scaling * lit.n_dot_l);
            let direct = (sheen + base_direct + strand_lobe) * light;
            let env_sheen = weft_prefiltered_radiance(reflect(-v, n), sheen_r) * sheen_color * e_v;
            color = direct + ambient * diffuse_albedo * ambient_scaling + env_sheen;
        }
    }

    // Fur occlusion (seed 001 sec. 8.2.5): darker towards the roots.
    let occlusion = 1.0 - saturate(material.fur_occlusion) * (1.0 - in.offset);
    let radiance = clamp(color * occlusion, vec3<f32>(0.0), vec3<f32>(WEFT_MAX_HALF));
    return vec4<f32>(radiance, alpha);
}

// n.v for the edge fade: per pixel, or `fast`'s per-vertex value.
fn fur_fade_n_dot_v(in: FurVaryings) -> f32 {
    if WEFT_TIER == TIER_FAST {
        return in.light_n_dot_v;
    }
    let surface = weft_surface(in.world_position, in.world_normal);
    return saturate(dot(surface.n, surface.v));
}

@fragment
fn fs_skin(in: FurVaryings) -> @location(0) vec4<f32> {
    return vec4<f32>(fur_shade(in).rgb, 1.0);
}

@fragment
fn fs_shell(in: FurVaryings) -> @location(0) vec4<f32> {
    return fur_shell(in);
}

// One shell fragment: radiance and blend alpha (the shell bench's fin
// experiment fades it at the silhouette).
fn fur_shell(in: FurVaryings) -> vec4<f32> {
    // Coverage first, in uniform control flow (fwidth).
    let noise = fur_noise(in.uv0);
    let o = saturate(in.offset);
    let shape = select(o, o * o, material.tapered_tips != 0u);
    let threshold = mix(saturate(material.cutoff_start), saturate(material.cutoff_end), shape);
    // step(threshold, noise) antialiased over about one pixel of the noise.
    let width = max(fwidth(noise), 1e-3);
    let coverage = saturate((noise - threshold) / width + 0.5) * step(1e-6, noise);

    let shaded = fur_shade(in);
    let fade = 1.0 - saturate(material.edge_fade) * (1.0 - fur_fade_n_dot_v(in));
    // The seed's alpha is the opacity of one of its 20 shells, a slab of
    // 1/20 of the fur; a shell of 1/n of it keeps 1 - (1 - a)^(20/n)
    // (Beer-Lambert), so the look at 20 shells is the seed's and more shells
    // converge to the same fur instead of piling up opacity.
    let a = saturate(coverage * (1.0 - o) * fade * shaded.a);
    let slab = FUR_SEED_SHELLS / f32(max(material.shell_count, 1));
    let keep = 1.0 - a;
    let alpha = 1.0 - select(pow(keep, slab), 0.0, keep <= 0.0);
    return vec4<f32>(shaded.rgb, alpha);
}
