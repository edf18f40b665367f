// weft glint library: a procedural glint NDF after Deliot & Belcour 2023,
// "Real-Time Rendering of Glinty Appearances using Distributed Binomial Laws
// on Anisotropic Grids" (CGF 42(8), HPG 2023). Pure functions, no bindings.
//
// A glinty surface is a field of flat microfacets ("flakes") whose normals
// follow a target NDF D. In a pixel footprint holding N flakes, the number of
// flakes that reflect the half vector h into the eye is binomial:
// B(N, p) with p = s D(h) / D_max, where s (the "microfacet roughness") is the
// angular size of one slope cell: the probability that a flake's normal
// falls in the cell around h. The glint NDF of the footprint is then
// D_glint(h) = (hits / N) D_max / s, whose expectation is D(h) exactly.
// The footprint is covered by simplex grids whose cells are about one pixel
// across (screen-space adaptive: level of detail from the pixel footprint's
// ellipse in uv), blended over a tetrahedron of (rotation, anisotropy,
// level) so no grid switches abruptly; each cell draws its own flake count
// and its own table of per-slope-cell random numbers.
//
// Differences from the published code (README, "reference"):
// - The 64 x 64 noise texture is replaced by a hash of the table
//   coordinate: pcg4d (Jarzynski & Olano 2020) of a lattice point gives its
//   uniform number (the gate) and one that becomes a standard normal number
//   by the inverse CDF sqrt(2) erfinv(2u - 1) (the count). The texture holds
//   independent uniform and standard normal numbers, so every corner value
//   has the same distribution; the table is still addressed as 64 x 64
//   points offset by each cell's random numbers, as the texture was.
// - The four corners of a slope cell are the lattice points around it,
//   shared with the neighbouring cells (the paper's texel holds its own four
//   corners, so the hit count jumps at every slope-cell border): the glint
//   NDF is continuous in h, which halves the sparkles' change under a
//   half-pixel camera pan on a curved surface (README, "Limits"). Each
//   corner keeps its distribution, so the expectation is unchanged.
// - Level of detail and rotation bins use floor, not truncation towards zero
//   ((int) in HLSL): with truncation a negative level (cells smaller than one
//   uv unit: every ordinary mapping) interpolates between the wrong two levels.
// - Rotation bins are indexed modulo pi (an ellipse's axis is defined up to
//   pi): the paper wraps only the first bin, so where the footprint's axis
//   is aligned with u or v the last bits of the derivatives chose between
//   two unrelated grids (glint_grids).
// - The fourth grid uses its own rotated uv (a known porting slip sets it from
//   the first grid's).
// - Uniform random numbers lie in the open interval (0, 1) (24-bit, +0.5):
//   erfinv(+-1) is infinite.
// - The binomial's mean and deviation use max(N - 1, 0): with fewer than one
//   flake in a blended cell the published sqrt takes a negative argument.
// - Barycentric weights in the tetrahedron by Cramer's rule.
// The fast tier (glint_hits_fast, end of file) evaluates the same grids,
// cells, table corners and hashes with the standard normal numbers from a
// polynomial (glint_normal_fast), without branches, one grid at a time.
// The guards of the paper are kept: log density clamped to [0, 50], flake
// count >= 1e-8, ellipse ratio over (minor + 1e-8), result <= 20 D_max.

const GLINT_TAU: f32 = 6.28318530717959;
const GLINT_HALF_PI: f32 = 1.5707963267949;
// The noise table's size (texels per side), as the published texture's.
const GLINT_TABLE_SIZE: f32 = 64.0;
// Levels of detail are clamped so grid coordinates stay well inside f32's
// integer range (uv / 2^lod with lod >= -20 and |uv| <= 64: < 2^27).
const GLINT_MIN_LOD: f32 = -20.0;
const GLINT_MAX_LOD: f32 = 20.0;
// Largest footprint anisotropy handled by a dedicated grid (2^4); a longer
// ellipse uses the 16:1 grids with a correspondingly larger cell count.
const GLINT_MAX_RATIO: f32 = 16.0;

// One grid of the four the footprint blends.
struct GlintGrid {
    uv: vec2<f32>,
    seed: u32,
    // Area of one grid cell in uv units (the flake count is area x density).
    cell_area: f32,
    weight: f32,
}

// Parameters of the glint NDF.
struct GlintParams {
    // ln(flakes per unit uv area).
    log_density: f32,
    // Angular size of a slope cell (the paper's microfacet roughness).
    micro_roughness: f32,
    // Standard deviation of the log density from cell to cell.
    density_randomization: f32,
}

// ---------------------------------------------------------------- random

// pcg4d (Jarzynski & Olano 2020, "Hash Functions for GPU Rendering").
fn glint_pcg4d(v_in: vec4<u32>) -> vec4<u32> {
    var v = v_in * 1664525u + vec4<u32>(1013904223u);
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    v = v ^ (v >> vec4<u32>(16u));
    v.x += v.y * v.w;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v.w += v.y * v.z;
    return v;
}

// pcg3d (same source), as the paper seeds its surface cells.
fn glint_pcg3d(v_in: vec3<u32>) -> vec3<u32> {
    var v = v_in * 1664525u + vec3<u32>(1013904223u);
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v = v ^ (v >> vec3<u32>(16u));
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// Uniform numbers in the open interval (0, 1) from the top 24 bits.
fn glint_unit3(v: vec3<u32>) -> vec3<f32> {
    return (vec3<f32>(v >> vec3<u32>(8u)) + 0.5) * (1.0 / 16777216.0);
}

fn glint_unit4(v: vec4<u32>) -> vec4<f32> {
    return (vec4<f32>(v >> vec4<u32>(8u)) + 0.5) * (1.0 / 16777216.0);
}

// Dave Hoskins' "hash without sine" (float3 -> float), as the paper seeds
// its grids.
fn glint_hash13(p_in: vec3<f32>) -> f32 {
    var p3 = fract(p_in * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

// erfinv for x in (-1, 1) (Giles 2010, "Approximating the erfinv function",
// single precision).
fn glint_erfinv(x: f32) -> f32 {
    var w = -log(max((1.0 - x) * (1.0 + x), 1e-30));
    var p: f32;
    if w < 5.0 {
        w = w - 2.5;
        p = 2.81022636e-08;
        p = 3.43273939e-07 + p * w;
        p = -3.5233877e-06 + p * w;
        p = -4.39150654e-06 + p * w;
        p = 0.00021858087 + p * w;
        p = -0.00125372503 + p * w;
        p = -0.00417768164 + p * w;
        p = 0.246640727 + p * w;
        p = 1.50140941 + p * w;
    } else {
        w = sqrt(w) - 3.0;
        p = -0.000200214257;
        p = 0.000100950558 + p * w;
        p = 0.00134934322 + p * w;
        p = -0.00367342844 + p * w;
        p = 0.00573950773 + p * w;
        p = -0.0076224613 + p * w;
        p = 0.00943887047 + p * w;
        p = 1.00167406 + p * w;
        p = 2.83297682 + p * w;
    }
    return p * x;
}

// A polynomial erfinv: a degree-7 odd polynomial, least-squares fit of
// Giles' erfinv over |x| <= 0.95 (standard normal numbers within +-1.96,
// error <= 0.033 there), x clamped to that range: the 5 % of draws further
// out get +-1.96. The previous fast tier's (glint_ndf with poly_normals);
// the fast tier now uses glint_normal_fast (the same fit, unclamped).
fn glint_erfinv_poly(x_in: f32) -> f32 {
    let x = clamp(x_in, -0.95, 0.95);
    let x2 = x * x;
    return x * (0.864441 + x2 * (0.533641 + x2 * (-0.893165 + x2 * 1.108999)));
}

// erfinv by tier: `poly` (fast) or Giles' (reference).
fn glint_erfinv_by(x: f32, poly: bool) -> f32 {
    if poly {
        return glint_erfinv_poly(x);
    }
    return glint_erfinv(x);
}

// Standard normal numbers from uniform ones in (0, 1) (inverse CDF; the
// polynomial one for the fast tier).
fn glint_gaussian3(u: vec3<f32>, poly_normals: bool) -> vec3<f32> {
    return 1.41421356 * vec3<f32>(glint_erfinv_by(2.0 * u.x - 1.0, poly_normals), glint_erfinv_by(2.0 * u.y - 1.0, poly_normals), glint_erfinv_by(2.0 * u.z - 1.0, poly_normals));
}

fn glint_gaussian4(u: vec4<f32>) -> vec4<f32> {
    return 1.41421356 * vec4<f32>(
        glint_erfinv(2.0 * u.x - 1.0), glint_erfinv(2.0 * u.y - 1.0),
        glint_erfinv(2.0 * u.z - 1.0), glint_erfinv(2.0 * u.w - 1.0),
    );
}

// ---------------------------------------------------------------- slope table

// The paper's noise texture read: the slope cell around `slope` (cells of
// width micro_roughness in |h.xy|), offset into the 64 x 64 table by the
// surface cell's two random numbers. Returns the uniform numbers (gates) and
// standard normal numbers (counts) of its 4 corners (00, 01, 10, 11: lattice
// points shared with the neighbouring cells) and the position inside it.
struct GlintSlopeRand {
    gate_rand: vec4<f32>,
    gaussian: vec4<f32>,
    lerp: vec2<f32>,
}

// (gate, count) random numbers of one lattice point of the table.
fn glint_corner(c: vec2<f32>, poly_normals: bool) -> vec2<f32> {
    let texel = vec2<u32>(c - GLINT_TABLE_SIZE * floor(c / GLINT_TABLE_SIZE));
    let u = glint_unit4(glint_pcg4d(vec4<u32>(texel, 0x676c69u, 0x74746572u)));
    return vec2<f32>(u.x, 1.41421356 * glint_erfinv_by(2.0 * u.y - 1.0, poly_normals));
}

fn glint_slope_rand(micro_roughness: f32, slope: vec2<f32>, offset: vec2<f32>, poly_normals: bool) -> GlintSlopeRand {
    let s = abs(slope) / micro_roughness + offset * GLINT_TABLE_SIZE;
    let cell = floor(s);
    let c00 = glint_corner(cell, poly_normals);
    let c01 = glint_corner(cell + vec2<f32>(0.0, 1.0), poly_normals);
    let c10 = glint_corner(cell + vec2<f32>(1.0, 0.0), poly_normals);
    let c11 = glint_corner(cell + vec2<f32>(1.0, 1.0), poly_normals);
    var out: GlintSlopeRand;
    out.gate_rand = vec4<f32>(c00.x, c01.x, c10.x, c11.x);
    out.gaussian = vec4<f32>(c00.y, c01.y, c10.y, c11.y);
    out.lerp = s - cell;
    return out;
}

// ---------------------------------------------------------------- binomial

// The number of hits in one surface cell at the four corners of the slope
// cell, bilinearly blended: a cell reflects at least one flake with
// probability P1 = 1 - (1 - p)^N (smoothed gate of width 0.1 near 0 and 1),
// then 1 + the count of the N - 1 others, a Gaussian of mean (N - 1) p and
// deviation sqrt((N - 1) p (1 - p)), floored and clamped to [0, N].
fn glint_cell_hits(r: GlintSlopeRand, one_hit: f32, smooth_width: f32, mean: f32, deviation: f32, count: f32) -> f32 {
    var gate: vec4<f32>;
    if smooth_width > 1e-7 {
        gate = saturate((r.gate_rand - (one_hit + smooth_width)) / (-2.0 * smooth_width));
    } else {
        gate = select(vec4<f32>(0.0), vec4<f32>(1.0), r.gate_rand < vec4<f32>(one_hit));
    }
    let gauss = clamp(floor(r.gaussian * deviation + mean), vec4<f32>(0.0), vec4<f32>(count));
    let hits = gate * (1.0 + gauss);
    // Corners (00, 01, 10, 11).
    let x0 = mix(hits.x, hits.z, r.lerp.x);
    let x1 = mix(hits.y, hits.w, r.lerp.x);
    return mix(x0, x1, r.lerp.y);
}

// The simplex cell of a point of a grid (skewed: equilateral triangles of
// unit side): the cell's integer corner, whether it is the upper triangle
// (si = 1), and the point's barycentric weights on its three vertices.
struct GlintSimplex {
    id: vec2<i32>,
    si: i32,
    bary: vec3<f32>,
}

fn glint_simplex(uv: vec2<f32>) -> GlintSimplex {
    let skewed = vec2<f32>(uv.x - 0.57735027 * uv.y, 1.15470054 * uv.y);
    let base = floor(skewed);
    let f = skewed - base;
    let fz = 1.0 - f.x - f.y;
    let s = select(0.0, 1.0, fz < 0.0);
    let s2 = 2.0 * s - 1.0;
    return GlintSimplex(vec2<i32>(base), i32(s), vec3<f32>(-fz * s2, s - f.y * s2, s - f.x * s2));
}

// One grid: the three simplex cells around the point, each with its own
// flake count (log-normal around the density) and slope table offset; the
// cells' hit fractions blended by the point's barycentric coordinates.
// `target_ndf` = D(h) / D_max. Returns sum of weight x hits / N (its
// expectation is weight x p).
fn glint_sample_grid(params: GlintParams, grid: GlintGrid, slope: vec2<f32>, target_ndf: f32, poly_normals: bool) -> f32 {
    let cell = glint_simplex(grid.uv);
    let id = cell.id;
    let si = cell.si;
    let c0 = id + vec2<i32>(si, si);
    let c1 = id + vec2<i32>(si, 1 - si);
    let c2 = id + vec2<i32>(1 - si, si);
    let bary = cell.bary;

    let bias = 2147483648u;
    let r0 = glint_unit3(glint_pcg3d(vec3<u32>(bitcast<u32>(c0.x) + bias, bitcast<u32>(c0.y) + bias, grid.seed)));
    let r1 = glint_unit3(glint_pcg3d(vec3<u32>(bitcast<u32>(c1.x) + bias, bitcast<u32>(c1.y) + bias, grid.seed)));
    let r2 = glint_unit3(glint_pcg3d(vec3<u32>(bitcast<u32>(c2.x) + bias, bitcast<u32>(c2.y) + bias, grid.seed)));
    let t0 = glint_slope_rand(params.micro_roughness, slope, r0.yz, poly_normals);
    let t1 = glint_slope_rand(params.micro_roughness, slope, r1.yz, poly_normals);
    let t2 = glint_slope_rand(params.micro_roughness, slope, r2.yz, poly_normals);

    // Flake counts: log-normal around the density, clamped as the paper.
    let log_density = clamp(
        glint_gaussian3(vec3<f32>(r0.x, r1.x, r2.x), poly_normals) * params.density_randomization + params.log_density,
        vec3<f32>(0.0), vec3<f32>(50.0));
    let count = max(vec3<f32>(1e-8), grid.cell_area * exp(log_density));
    let blended = count * grid.weight;

    // Binomial law of the hits.
    let p = params.micro_roughness * target_ndf;
    let one_hit = vec3<f32>(1.0) - pow(vec3<f32>(1.0 - p), blended);
    let others = max(blended - 1.0, vec3<f32>(0.0));
    let mean = others * p;
    let deviation = sqrt(others * (p * (1.0 - p)));
    let smooth_width = 0.1 * saturate(one_hit * 10.0) * saturate((1.0 - one_hit) * 10.0);

    let h0 = glint_cell_hits(t0, one_hit.x, smooth_width.x, mean.x, deviation.x, blended.x);
    let h1 = glint_cell_hits(t1, one_hit.y, smooth_width.y, mean.y, deviation.y, blended.y);
    let h2 = glint_cell_hits(t2, one_hit.z, smooth_width.z, mean.z, deviation.z, blended.z);
    return dot(vec3<f32>(h0, h1, h2) / count, bary);
}

// ---------------------------------------------------------------- footprint

// The pixel footprint's ellipse in uv: the eigen-decomposition of the
// covariance S = du du^T + dv dv^T of the screen derivatives (the paper's
// inverse-Jacobian construction gives the same axes without the inverse,
// which a degenerate mapping makes singular). Returns (major axis, minor
// length) with the minor length floored relative to the major one and
// absolutely (a constant uv has a zero footprint).
struct GlintEllipse {
    major_dir: vec2<f32>,
    major: f32,
    minor: f32,
}

fn glint_ellipse(duv_dx: vec2<f32>, duv_dy: vec2<f32>) -> GlintEllipse {
    let a = duv_dx.x * duv_dx.x + duv_dy.x * duv_dy.x;
    let b = duv_dx.x * duv_dx.y + duv_dy.x * duv_dy.y;
    let d = duv_dx.y * duv_dx.y + duv_dy.y * duv_dy.y;
    let half_trace = 0.5 * (a + d);
    let disc = sqrt(max(0.25 * (a - d) * (a - d) + b * b, 0.0));
    let l1 = half_trace + disc;
    let l2 = max(half_trace - disc, 0.0);
    // Eigenvector of l1: (b, l1 - a) or (l1 - d, b), whichever is longer.
    let e_a = vec2<f32>(b, l1 - a);
    let e_b = vec2<f32>(l1 - d, b);
    let e = select(e_b, e_a, dot(e_a, e_a) > dot(e_b, e_b));
    let e_len2 = dot(e, e);
    var out: GlintEllipse;
    out.major_dir = select(vec2<f32>(1.0, 0.0), e * inverseSqrt(max(e_len2, 1e-37)), e_len2 > 1e-37);
    out.major = max(sqrt(l1), 1e-12);
    out.minor = max(sqrt(l2), out.major / (GLINT_MAX_RATIO * 4.0));
    return out;
}

fn glint_rotate(uv: vec2<f32>, angle: f32) -> vec2<f32> {
    let c = cos(angle);
    let s = sin(angle);
    return vec2<f32>(c * uv.x + s * uv.y, c * uv.y - s * uv.x);
}

// Seed of the grid at (level, rotation, anisotropy), as the paper's.
fn glint_grid_seed(lod: f32, theta: f32, ratio: f32) -> u32 {
    // HLSL fmod (sign of the dividend).
    let t = theta - GLINT_TAU * trunc(theta / GLINT_TAU);
    return u32(min(glint_hash13(vec3<f32>(lod, t, ratio)) * 4294967296.0, 4294967040.0));
}

fn glint_make_grid(uv: vec2<f32>, lod: f32, theta: f32, ratio: f32, weight: f32) -> GlintGrid {
    var g: GlintGrid;
    g.uv = glint_rotate(uv, theta) * exp2(-lod) / vec2<f32>(1.0, ratio);
    g.seed = glint_grid_seed(lod, theta, ratio);
    g.cell_area = ratio * exp2(2.0 * lod);
    g.weight = weight;
    return g;
}

// Barycentric weights of p in the tetrahedron (a, b, c, d) (Cramer's rule).
fn glint_tetra_weights(p: vec3<f32>, a: vec3<f32>, b: vec3<f32>, c: vec3<f32>, d: vec3<f32>) -> vec4<f32> {
    let c1 = a - d;
    let c2 = b - d;
    let c3 = c - d;
    let q = p - d;
    let det = dot(c1, cross(c2, c3));
    let inv = 1.0 / det;
    let w1 = dot(q, cross(c2, c3)) * inv;
    let w2 = dot(c1, cross(q, c3)) * inv;
    let w3 = dot(c1, cross(c2, q)) * inv;
    return vec4<f32>(w1, w2, w3, 1.0 - w1 - w2 - w3);
}

// The level of detail of the footprint's minor axis at `screen_scale`
// pixels per cell.
fn glint_lod(e: GlintEllipse, screen_scale: f32) -> f32 {
    return clamp(log2(e.minor * screen_scale * 0.5), GLINT_MIN_LOD, GLINT_MAX_LOD);
}

// The four grids of the paper's tetrahedralised (rotation bin, anisotropy
// ratio, level) space, with their weights (summing to 1).
struct GlintGrids {
    g0: GlintGrid,
    g1: GlintGrid,
    g2: GlintGrid,
    g3: GlintGrid,
}

// The tetrahedron of the footprint's (rotation, anisotropy, level) point:
// its vertices (rotation index / 2, ratio index, level index), their
// barycentric weights and the bins the indices select.
struct GlintTetra {
    p0: vec3<f32>,
    p1: vec3<f32>,
    p2: vec3<f32>,
    p3: vec3<f32>,
    w: vec4<f32>,
    center: bool,
    bin0: f32,
    bin_h: f32,
    bin1: f32,
    lod0: f32,
    ratio0: f32,
}

fn glint_grids(uv: vec2<f32>, e: GlintEllipse, screen_scale: f32) -> GlintGrids {
    let t = glint_tetra(e, screen_scale);
    // Rotation index 0, 1, 2 = bin0, binH, bin1 (x * 2); the centre's
    // isotropic vertices (ratio index 0) are not rotated.
    var out: GlintGrids;
    out.g0 = glint_vertex_grid(uv, t.p0, t.w.x, t.center, t.bin0, t.bin_h, t.bin1, t.lod0, t.ratio0);
    out.g1 = glint_vertex_grid(uv, t.p1, t.w.y, t.center, t.bin0, t.bin_h, t.bin1, t.lod0, t.ratio0);
    out.g2 = glint_vertex_grid(uv, t.p2, t.w.z, t.center, t.bin0, t.bin_h, t.bin1, t.lod0, t.ratio0);
    out.g3 = glint_vertex_grid(uv, t.p3, t.w.w, t.center, t.bin0, t.bin_h, t.bin1, t.lod0, t.ratio0);
    return out;
}

// The footprint's point in the (rotation, anisotropy, level) space: the
// cell's origin (bins, lod0, ratio0) and the point's position in it.
struct GlintFootprintCell {
    theta_lerp: f32,
    ratio_lerp: f32,
    lod_lerp: f32,
    center: bool,
    bin0: f32,
    bin_h: f32,
    bin1: f32,
    lod0: f32,
    ratio0: f32,
}

fn glint_footprint_cell(e: GlintEllipse, screen_scale: f32) -> GlintFootprintCell {
    let ratio_e = min(e.major / (e.minor + 1e-8 * e.major), GLINT_MAX_RATIO);
    // Level of detail.
    let lod = glint_lod(e, screen_scale);
    let lod0 = floor(lod);
    let lod_lerp = lod - lod0;
    // Anisotropy ratio.
    let ratio0 = max(exp2(floor(log2(max(ratio_e, 1.0)))), 1.0);
    let ratio1 = ratio0 * 2.0;
    let ratio_lerp = saturate((ratio_e - ratio0) / (ratio1 - ratio0));
    // Rotation of the major axis from +v, in bins of pi/2 / max(ratio0, 2),
    // split in halves: the point lies between the half-bin angles bin0 and
    // bin1 = bin0 + q (binH between them). An ellipse's axis is defined up
    // to pi, and its eigenvector's sign flips with the sign of S's
    // off-diagonal term, so the bins are indexed modulo pi (pi / q = 4
    // max(ratio0, 2) half-bins, exact): theta and theta + pi select the
    // same grids. The paper wraps bin0 alone at 0, which leaves a seam of
    // different grids wherever the axis is aligned with u or v (and lets
    // the last bits of the derivatives pick the side).
    let q = 0.5 * GLINT_HALF_PI / max(ratio0, 2.0);
    let per_pi = 4.0 * max(ratio0, 2.0);
    let theta = atan2(-e.major_dir.x, e.major_dir.y);
    let theta_q = theta / q;
    let h0 = floor(theta_q);
    let theta_lerp = saturate(theta_q - h0);
    let i0 = h0 - per_pi * floor(h0 / per_pi);
    let i1 = (i0 + 1.0) - per_pi * floor((i0 + 1.0) / per_pi);
    let theta_bin0 = i0 * q;
    let theta_bin_h = (i0 + 0.5) * q;
    let theta_bin1 = i1 * q;
    var out: GlintFootprintCell;
    out.theta_lerp = theta_lerp;
    out.ratio_lerp = ratio_lerp;
    out.lod_lerp = lod_lerp;
    out.center = ratio0 == 1.0;
    out.bin0 = theta_bin0;
    out.bin_h = theta_bin_h;
    out.bin1 = theta_bin1;
    out.lod0 = lod0;
    out.ratio0 = ratio0;
    return out;
}

fn glint_tetra(e: GlintEllipse, screen_scale: f32) -> GlintTetra {
    let k = glint_footprint_cell(e, screen_scale);
    var theta_lerp = k.theta_lerp;
    let ratio_lerp = k.ratio_lerp;
    let lod_lerp = k.lod_lerp;
    // Tetrahedron of the (rotation, ratio, level) cell holding the point.
    let center = k.center;
    var p0: vec3<f32>;
    var p1: vec3<f32>;
    var p2: vec3<f32>;
    var p3: vec3<f32>;
    if center {
        // No anisotropy: the centre of the pattern, another triangulation.
        let a = vec3<f32>(0.0, 1.0, 0.0);
        let b = vec3<f32>(0.0, 0.0, 0.0);
        let c = vec3<f32>(1.0, 1.0, 0.0);
        let d = vec3<f32>(0.0, 1.0, 1.0);
        let ee = vec3<f32>(0.0, 0.0, 1.0);
        let f = vec3<f32>(1.0, 1.0, 1.0);
        if lod_lerp > 1.0 - ratio_lerp {
            if (lod_lerp - (1.0 - ratio_lerp)) / max(ratio_lerp, 1e-8) > theta_lerp {
                p0 = a; p1 = ee; p2 = d; p3 = f;
            } else {
                p0 = f; p1 = ee; p2 = c; p3 = a;
            }
        } else {
            p0 = b; p1 = a; p2 = c; p3 = ee;
        }
        theta_lerp = theta_lerp * ratio_lerp;
    } else {
        let a = vec3<f32>(0.0, 1.0, 0.0);
        let b = vec3<f32>(0.0, 0.0, 0.0);
        let c = vec3<f32>(0.5, 1.0, 0.0);
        let d = vec3<f32>(1.0, 0.0, 0.0);
        let ee = vec3<f32>(1.0, 1.0, 0.0);
        let f = vec3<f32>(0.0, 1.0, 1.0);
        let g = vec3<f32>(0.0, 0.0, 1.0);
        let h = vec3<f32>(0.5, 1.0, 1.0);
        let i = vec3<f32>(1.0, 0.0, 1.0);
        let j = vec3<f32>(1.0, 1.0, 1.0);
        if theta_lerp < 0.5 && theta_lerp * 2.0 < ratio_lerp {
            // Prism A.
            if lod_lerp > 1.0 - ratio_lerp {
                if (lod_lerp - (1.0 - ratio_lerp)) / max(ratio_lerp, 1e-8) > theta_lerp * 2.0 / max(ratio_lerp, 1e-8) {
                    p0 = a; p1 = f; p2 = h; p3 = g;
                } else {
                    p0 = c; p1 = a; p2 = h; p3 = g;
                }
            } else {
                p0 = b; p1 = a; p2 = c; p3 = g;
            }
        } else if 1.0 - (theta_lerp - 0.5) * 2.0 > ratio_lerp {
            // Prism B.
            if lod_lerp < 1.0 - ratio_lerp {
                let half_width = 0.5 * (1.0 - ratio_lerp);
                if lod_lerp / max(1.0 - ratio_lerp, 1e-8) > (theta_lerp - (0.5 - half_width)) / max(2.0 * half_width, 1e-8) {
                    p0 = b; p1 = g; p2 = i; p3 = c;
                } else {
                    p0 = d; p1 = b; p2 = c; p3 = i;
                }
            } else {
                p0 = c; p1 = g; p2 = h; p3 = i;
            }
        } else {
            // Prism C.
            if lod_lerp > 1.0 - ratio_lerp {
                if (lod_lerp - (1.0 - ratio_lerp)) / max(ratio_lerp, 1e-8) > ((theta_lerp - 0.5) * 2.0 - (1.0 - ratio_lerp)) / max(ratio_lerp, 1e-8) {
                    p0 = c; p1 = j; p2 = h; p3 = i;
                } else {
                    p0 = ee; p1 = i; p2 = c; p3 = j;
                }
            } else {
                p0 = d; p1 = ee; p2 = c; p3 = i;
            }
        }
    }
    var out: GlintTetra;
    out.p0 = p0;
    out.p1 = p1;
    out.p2 = p2;
    out.p3 = p3;
    out.w = glint_tetra_weights(vec3<f32>(theta_lerp, ratio_lerp, lod_lerp), p0, p1, p2, p3);
    out.center = center;
    out.bin0 = k.bin0;
    out.bin_h = k.bin_h;
    out.bin1 = k.bin1;
    out.lod0 = k.lod0;
    out.ratio0 = k.ratio0;
    return out;
}

fn glint_vertex_grid(
    uv: vec2<f32>, p: vec3<f32>, weight: f32, center: bool,
    bin0: f32, bin_h: f32, bin1: f32, lod0: f32, ratio0: f32,
) -> GlintGrid {
    let rot_index = p.x * 2.0;
    var theta = select(select(bin1, bin_h, rot_index < 1.5), bin0, rot_index < 0.5);
    if center && p.y == 0.0 {
        theta = 0.0;
    }
    let ratio = select(ratio0, ratio0 * 2.0, p.y > 0.5);
    let lod = lod0 + p.z;
    return glint_make_grid(uv, lod, theta, ratio, weight);
}

// ---------------------------------------------------------------- NDF

// The glint NDF at the tangent-space half vector's slope h.xy, for a target
// NDF value d (D(h)) and its maximum d_max: sum of the grids' hit fractions
// / s x D_max, at most 20 D_max (the paper's guard at grazing footprints).
// `poly_normals`: the standard normal numbers from glint_erfinv_poly (the
// previous fast tier; the reference passes false); the gates' uniform
// numbers, grids and cells are the same, so the same flakes sparkle.
fn glint_ndf(params: GlintParams, grids: GlintGrids, slope: vec2<f32>, d: f32, d_max: f32, poly_normals: bool) -> f32 {
    let target_ndf = d / d_max;
    let sum = glint_sample_grid(params, grids.g0, slope, target_ndf, poly_normals)
        + glint_sample_grid(params, grids.g1, slope, target_ndf, poly_normals)
        + glint_sample_grid(params, grids.g2, slope, target_ndf, poly_normals)
        + glint_sample_grid(params, grids.g3, slope, target_ndf, poly_normals);
    return min(sum / params.micro_roughness, 20.0) * d_max;
}

// ---------------------------------------------------------------- fast
//
// The fast tier (glint_hits_fast): the reference's glint NDF on the same
// four grids, twelve cells and 48 table corners with the same hashes (the
// same gates: the same flakes sparkle), written for the GPU:
// - table addressing in integers (lattice point & 63, as the reference's
//   c - 64 floor(c / 64)), pcg4d's constant inputs folded by the compiler,
//   only the two words used (gate, count);
// - uniform numbers straight from the hash words (f32(h) / 2^32: the same
//   number to 2^-24), the smoothed gate as one clamped multiply-add;
// - every standard normal number (cell log-density, corner counts) from a
//   degree-7 odd polynomial of x = 2u - 1 (glint_normal_fast), no log;
// - the reference's tetrahedron decision tree without branches
//   (glint_tetra_fast: the same tests, the vertices as packed codes, the
//   same barycentric weights);
// - the grids one at a time in a loop and the cells one after the other,
//   so that 64 VGPRs suffice (60 on gfx1100).

// Standard normal number from a 32-bit hash h (u = h / 2^32, x = 2u - 1):
// sqrt(2) erfinv(x) by a degree-7 odd polynomial, least-squares fit over
// |x| <= 0.95 (error <= 0.034 there), unclamped: out to |x| = 1 it rises to
// 2.28 where the true tails reach 2.6 to 5.3 (rms error 0.078 over u,
// against 0.120 with the 1.96 clamp of glint_erfinv_poly).
fn glint_normal_fast(h: u32) -> f32 {
    let x = fma(f32(h), 1.0 / 2147483648.0, -1.0);
    let x2 = x * x;
    return x * (1.22250 + x2 * (0.754680 + x2 * (-1.263127 + x2 * 1.568366)));
}

// Hits at the table's lattice point (x, y): pcg4d(x, y, 0x676c69,
// 0x74746572) of the reference's glint_corner with its first multiply-adds
// done per coordinate (ax = x a + c, ay = y a + c) and the constant lanes
// folded (Z = 0x676c69 a + c, W = 0x74746572 a + c); the gate from word x,
// 1 + the count of the others from word y (max(., 1) = 1 + the reference's
// clamp at 0; its clamp at N never binds: p <= 0.05 and |z| <= 2.3).
fn glint_corner_hits(ax: u32, ay: u32, gate_a: f32, gate_b: f32, deviation: f32, mean1: f32) -> f32 {
    var x = ax + ay * 0x6ee58629u;
    var y = ay + x * 0xd224ab4u;
    var z = 0xd224ab4u + x * y;
    var w = 0x6ee58629u + y * z;
    x ^= x >> 16u;
    y ^= y >> 16u;
    z ^= z >> 16u;
    w ^= w >> 16u;
    x += y * w;
    y += z * x;
    let gate = saturate(fma(f32(x), gate_a, gate_b));
    let count = max(floor(fma(glint_normal_fast(y), deviation, mean1)), 1.0);
    return gate * count;
}

// One simplex cell of a grid: its random numbers (pcg3d of its id and the
// grid's seed: log-density deviate, table offset), its flake count and
// binomial law, and the hits at the four table corners around the slope,
// bilinearly blended; returns hits / flake count.
fn glint_cell_fast(params: GlintParams, grid: GlintGrid, c: vec2<i32>, s_slope: vec2<f32>, p: f32, log2_q: f32) -> f32 {
    let h = glint_pcg3d(vec3<u32>(bitcast<u32>(c.x) + 2147483648u, bitcast<u32>(c.y) + 2147483648u, grid.seed));
    // Log-normal flake count around the density (the reference's clamp).
    let log_density = clamp(glint_normal_fast(h.x) * params.density_randomization + params.log_density, 0.0, 50.0);
    let count = max(1e-8, grid.cell_area * exp(log_density));
    let blended = count * grid.weight;
    // Binomial law: P(at least one hit) with its smoothed gate, mean and
    // deviation of the others (+ 1: the count of a gated corner).
    let miss = exp2(blended * log2_q);
    let one_hit = 1.0 - miss;
    let others = max(blended - 1.0, 0.0);
    let mean1 = others * p + 1.0;
    let deviation = sqrt(others * (p * (1.0 - p)));
    let width = max(0.1 * saturate(one_hit * 10.0) * saturate(miss * 10.0), 1e-30);
    let inv = 0.5 / width;
    let gate_a = inv * (-1.0 / 4294967296.0);
    let gate_b = fma(one_hit, inv, 0.5);
    // Slope table position: the reference's (h >> 8 + 0.5) / 2^24 x 64.
    let s = fma(vec2<f32>(h.yz >> vec2<u32>(8u)), vec2<f32>(GLINT_TABLE_SIZE / 16777216.0), s_slope);
    let cell = floor(s);
    let l = s - cell;
    let ci = vec2<u32>(cell);
    let t0 = ci & vec2<u32>(63u);
    let t1 = (ci + vec2<u32>(1u)) & vec2<u32>(63u);
    let ax = vec2<u32>(t0.x, t1.x) * 1664525u + vec2<u32>(1013904223u);
    let ay = vec2<u32>(t0.y, t1.y) * 1664525u + vec2<u32>(1013904223u);
    let h00 = glint_corner_hits(ax.x, ay.x, gate_a, gate_b, deviation, mean1);
    let h01 = glint_corner_hits(ax.x, ay.y, gate_a, gate_b, deviation, mean1);
    let h10 = glint_corner_hits(ax.y, ay.x, gate_a, gate_b, deviation, mean1);
    let h11 = glint_corner_hits(ax.y, ay.y, gate_a, gate_b, deviation, mean1);
    let x0 = mix(h00, h10, l.x);
    let x1 = mix(h01, h11, l.x);
    return mix(x0, x1, l.y) / count;
}

// One grid (glint_sample_grid): its three simplex cells blended by the
// point's barycentric coordinates.
fn glint_sample_grid_fast(params: GlintParams, grid: GlintGrid, s_slope: vec2<f32>, p: f32, log2_q: f32) -> f32 {
    let cell = glint_simplex(grid.uv);
    let id = cell.id;
    let si = cell.si;
    let bary = cell.bary;
    var sum = 0.0;
    for (var k = 0; k < 3; k++) {
        let c = id + vec2<i32>(select(si, 1 - si, k == 2), select(si, 1 - si, k == 1));
        let b = select(select(bary.z, bary.y, k == 1), bary.x, k == 0);
        sum += b * glint_cell_fast(params, grid, c, s_slope, p, log2_q);
    }
    return sum;
}

// A vertex of the tetrahedron as 4 bits (exact: its coordinates are 0,
// 0.5 or 1): rotation index (0, 1, 2 = bin0, binH, bin1; 3 = unrotated, the
// centre's isotropic vertices), ratio index << 2, level index << 3.
// glint_tetra's tetrahedra as codes, four to a constant (p0 | p1 << 4 |
// p2 << 8 | p3 << 12), in the reference's order. Non-centre vertices a..j:
// a 4, b 0, c 5, d 2, e 6, f 12, g 8, h 13, i 10, j 14; centre vertices:
// a 4, b 3, c 6, d 12, e 11, f 14.
const GLINT_TET_A_UP: u32 = 4u | (12u << 4u) | (13u << 8u) | (8u << 12u);    // a f h g
const GLINT_TET_A_DOWN: u32 = 5u | (4u << 4u) | (13u << 8u) | (8u << 12u);  // c a h g
const GLINT_TET_A_LOW: u32 = 0u | (4u << 4u) | (5u << 8u) | (8u << 12u);    // b a c g
const GLINT_TET_B_UP: u32 = 0u | (8u << 4u) | (10u << 8u) | (5u << 12u);    // b g i c
const GLINT_TET_B_DOWN: u32 = 2u | (0u << 4u) | (5u << 8u) | (10u << 12u);  // d b c i
const GLINT_TET_B_HIGH: u32 = 5u | (8u << 4u) | (13u << 8u) | (10u << 12u); // c g h i
const GLINT_TET_C_UP: u32 = 5u | (14u << 4u) | (13u << 8u) | (10u << 12u);  // c j h i
const GLINT_TET_C_DOWN: u32 = 6u | (10u << 4u) | (5u << 8u) | (14u << 12u); // e i c j
const GLINT_TET_C_LOW: u32 = 2u | (6u << 4u) | (5u << 8u) | (10u << 12u);   // d e c i
const GLINT_TET_CENTER_UP: u32 = 4u | (11u << 4u) | (12u << 8u) | (14u << 12u);   // a e d f
const GLINT_TET_CENTER_DOWN: u32 = 14u | (11u << 4u) | (6u << 8u) | (4u << 12u);  // f e c a
const GLINT_TET_CENTER_LOW: u32 = 3u | (4u << 4u) | (6u << 8u) | (11u << 12u);    // b a c e

// A vertex's coordinates from its code (exact).
fn glint_vertex_of_code(c: u32) -> vec3<f32> {
    let rot = c & 3u;
    return vec3<f32>(select(f32(rot) * 0.5, 0.0, rot == 3u), f32((c >> 2u) & 1u), f32(c >> 3u));
}

// glint_tetra without branches: every test of the reference's decision
// tree evaluated (the same expressions), the tetrahedron picked by selects
// as packed codes; the same vertices and weights.
struct GlintTetraFast {
    codes: u32,
    w: vec4<f32>,
    bin0: f32,
    bin_h: f32,
    bin1: f32,
    lod0: f32,
    ratio0: f32,
}

fn glint_tetra_fast(e: GlintEllipse, screen_scale: f32) -> GlintTetraFast {
    let k = glint_footprint_cell(e, screen_scale);
    let t = k.theta_lerp;
    let r = k.ratio_lerp;
    let l = k.lod_lerp;
    let upper = l > 1.0 - r;
    let upper_left = (l - (1.0 - r)) / max(r, 1e-8);
    let half_width = 0.5 * (1.0 - r);
    let center_codes = select(GLINT_TET_CENTER_LOW, select(GLINT_TET_CENTER_DOWN, GLINT_TET_CENTER_UP, upper_left > t), upper);
    let a_codes = select(GLINT_TET_A_LOW, select(GLINT_TET_A_DOWN, GLINT_TET_A_UP, upper_left > t * 2.0 / max(r, 1e-8)), upper);
    let b_codes = select(GLINT_TET_B_HIGH, select(GLINT_TET_B_DOWN, GLINT_TET_B_UP,
        l / max(1.0 - r, 1e-8) > (t - (0.5 - half_width)) / max(2.0 * half_width, 1e-8)), l < 1.0 - r);
    let c_codes = select(GLINT_TET_C_LOW, select(GLINT_TET_C_DOWN, GLINT_TET_C_UP,
        upper_left > ((t - 0.5) * 2.0 - (1.0 - r)) / max(r, 1e-8)), upper);
    let prism_a = t < 0.5 && t * 2.0 < r;
    let prism_b = 1.0 - (t - 0.5) * 2.0 > r;
    let codes = select(select(select(c_codes, b_codes, prism_b), a_codes, prism_a), center_codes, k.center);
    let point = vec3<f32>(select(t, t * r, k.center), r, l);
    var out: GlintTetraFast;
    out.codes = codes;
    out.w = glint_tetra_weights(point, glint_vertex_of_code(codes & 15u), glint_vertex_of_code((codes >> 4u) & 15u),
        glint_vertex_of_code((codes >> 8u) & 15u), glint_vertex_of_code(codes >> 12u));
    out.bin0 = k.bin0;
    out.bin_h = k.bin_h;
    out.bin1 = k.bin1;
    out.lod0 = k.lod0;
    out.ratio0 = k.ratio0;
    return out;
}

// The fast tier's sum over the four grids of weight x hits / N (the
// reference's, before / s x D_max): the grids one at a time in a loop, the
// tetrahedron's vertices packed into 16 bits, so that little stays live.
fn glint_hits_fast(params: GlintParams, uv: vec2<f32>, e: GlintEllipse, screen_scale: f32, slope: vec2<f32>, d: f32, d_max: f32) -> f32 {
    let t = glint_tetra_fast(e, screen_scale);
    let codes = t.codes;
    let p = params.micro_roughness * (d / d_max);
    let log2_q = log2(1.0 - p);
    // The slope in table cells, with the offset's + 0.5 / 2^24 x 64.
    let s_slope = abs(slope) / params.micro_roughness + GLINT_TABLE_SIZE * 0.5 / 16777216.0;
    var sum = 0.0;
    for (var i = 0u; i < 4u; i++) {
        let c = (codes >> (4u * i)) & 15u;
        let rot = c & 3u;
        let theta = select(select(select(0.0, t.bin1, rot == 2u), t.bin_h, rot == 1u), t.bin0, rot == 0u);
        let ratio = select(t.ratio0, t.ratio0 * 2.0, (c & 4u) != 0u);
        let lod = t.lod0 + f32(c >> 3u);
        let w = select(select(select(1.0 - t.w.x - t.w.y - t.w.z, t.w.z, i == 2u), t.w.y, i == 1u), t.w.x, i == 0u);
        sum += glint_sample_grid_fast(params, glint_make_grid(uv, lod, theta, ratio, w), s_slope, p, log2_q);
    }
    return sum;
}

// The fast tier's glint NDF (as glint_ndf: at most 20 D_max).
fn glint_ndf_fast(params: GlintParams, uv: vec2<f32>, e: GlintEllipse, screen_scale: f32, slope: vec2<f32>, d: f32, d_max: f32) -> f32 {
    return min(glint_hits_fast(params, uv, e, screen_scale, slope, d, d_max) / params.micro_roughness, 20.0) * d_max;
}
