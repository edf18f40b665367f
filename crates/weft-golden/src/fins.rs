//! The fin experiment of the shell bench (fur only, in the bench only):
//! Lengyel, Praun, Finkelstein & Hoppe 2001 add *fins* at the silhouette,
//! quads standing on the mesh edges and textured with hair seen from the
//! side, where shells are seen edge-on and gaps show. Whether they pay is
//! measured by drawing N shells plus fins against the reference shell count
//! and against simply drawing more shells at the same cost.
//!
//! weft's pass format draws every pass over the same mesh, so the
//! experiment builds, in a temporary folder, a copy of the fur material
//! (`fur_fins`) with a third pass, and a mesh holding the body and the fins
//! together: a vertex's tangent w tells them apart (±1 on the body, the
//! bitangent sign; 0 on a fin), the body's passes collapse fin vertices and
//! the fins pass collapses body vertices (the triangles fall outside the clip
//! volume and are never rasterised).
//!
//! Fins are built for the silhouette edges of the bench's fixed camera (the
//! CPU-side silhouette extraction of real-time fins; the camera does not
//! move, so once is enough): every mesh edge whose averaged normal has
//! |N·V| below the band bound. Each is a quad from the edge to the fur's tip
//! (the shells' offset 1), drawn like a shell slice: the same strand noise
//! (along the edge), cut-off, lighting and tier; its opacity is that of the
//! strip of fur it stands for (as deep as its edge is long, by the shells'
//! Beer–Lambert rule), faded by how edge-on the fin is seen and by how far
//! from the silhouette it stands.

use std::path::{Path, PathBuf};
use weft_render::{Scene, math};

/// The experiment material's name.
pub const FINS_MATERIAL: &str = "fur_fins";

/// The fins' entry points and the body passes' wrappers, appended to
/// fur.wgsl.
const FINS_WGSL: &str = r#"
// ---------------------------------------------------------------- fins
// (crates/weft-golden/src/fins.rs: the shell bench's fin experiment)

// Body and fins in one mesh: tangent.w is +-1 on the body, 0 on a fin.
// A fin vertex: uv0 at its edge end, uv1 = (the fin's width, 0 at the root
// or 1 at the tip), tangent.xyz the fin plane's unit normal.
struct FinInput {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) tangent: vec4<f32>,
    @location(3) uv0: vec2<f32>,
    @location(4) uv1: vec2<f32>,
}

// The silhouette band the fins stand in: |N.V| below this.
const FIN_BAND: f32 = 0.3;

fn fin_is_fin(in: FinInput) -> bool {
    return abs(in.tangent.w) < 0.5;
}

// Outside the clip volume: a triangle of such vertices is never drawn.
fn fin_collapsed() -> FurVaryings {
    var out: FurVaryings;
    out.clip_position = vec4<f32>(2.0, 2.0, 2.0, 1.0);
    return out;
}

fn fin_fur_input(in: FinInput) -> FurInput {
    return FurInput(in.position, in.normal, in.uv0);
}

// vs_skin and vs_shell (entry points cannot be called) over the body.
@vertex
fn vs_skin_body(in: FinInput) -> FurVaryings {
    if fin_is_fin(in) {
        return fin_collapsed();
    }
    return fur_vertex(fin_fur_input(in), 0.0);
}

// Lengyel et al. fade the shells out where the fins fade in: the shells'
// alpha x (1 - the band weight) when FIN_FADE_SHELLS.
@fragment
fn fs_shell_body(in: FurVaryings) -> @location(0) vec4<f32> {
    let shell = fur_shell(in);
    if !FIN_FADE_SHELLS {
        return shell;
    }
    let surface = weft_surface(in.world_position, in.world_normal);
    let band = saturate(1.0 - abs(dot(surface.n, surface.v)) / FIN_BAND);
    return vec4<f32>(shell.rgb, shell.a * (1.0 - band));
}

@vertex
fn vs_shell_body(in: FinInput, @builtin(instance_index) instance: u32) -> FurVaryings {
    if fin_is_fin(in) {
        return fin_collapsed();
    }
    let count = f32(max(material.shell_count, 1));
    return fur_vertex(fin_fur_input(in), (f32(instance) + 0.5) / count);
}

struct FinVaryings {
    @builtin(position) clip_position: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) world_normal: vec3<f32>,
    @location(2) strand: vec3<f32>,
    @location(3) uv0: vec2<f32>,
    @location(4) offset: f32,
    @location(5) light_diffuse: vec4<f32>,
    @location(6) light_ambient: vec4<f32>,
    @location(7) light_sheen: vec4<f32>,
    @location(8) light_strand: vec4<f32>,
    @location(9) light_n_dot_v: f32,
    // The fin's fade (edge-on and band) and its width (world units).
    @location(10) fin: vec2<f32>,
}

@vertex
fn vs_fin(in: FinInput) -> FinVaryings {
    var out: FinVaryings;
    if !fin_is_fin(in) || FIN_HIDDEN {
        out.clip_position = vec4<f32>(2.0, 2.0, 2.0, 1.0);
        return out;
    }
    // The root on the surface, the tip where the shells' offset 1 would be.
    let f = fur_vertex(fin_fur_input(in), in.uv1.y);
    let v = weft_view_direction(f.world_position, vec3<f32>(0.0, 0.0, 1.0));
    let face_on = abs(dot(in.tangent.xyz, v));
    let band = saturate(1.0 - abs(dot(f.world_normal, v)) / FIN_BAND);
    out.clip_position = f.clip_position;
    out.world_position = f.world_position;
    out.world_normal = f.world_normal;
    out.strand = f.strand;
    out.uv0 = f.uv0;
    out.offset = f.offset;
    out.light_diffuse = f.light_diffuse;
    out.light_ambient = f.light_ambient;
    out.light_sheen = f.light_sheen;
    out.light_strand = f.light_strand;
    out.light_n_dot_v = f.light_n_dot_v;
    out.fin = vec2<f32>(face_on * band, in.uv1.x);
    return out;
}

@fragment
fn fs_fin(in: FinVaryings) -> @location(0) vec4<f32> {
    let fur = FurVaryings(in.clip_position, in.world_position, in.world_normal, in.strand, in.uv0, in.offset,
        in.light_diffuse, in.light_ambient, in.light_sheen, in.light_strand, in.light_n_dot_v);
    // The strands the edge crosses, seen from the side: the shells' noise
    // along the edge, cut at each height as the shell there would be.
    let noise = fur_noise(in.uv0);
    let o = saturate(in.offset);
    let shape = select(o, o * o, material.tapered_tips != 0u);
    let threshold = mix(saturate(material.cutoff_start), saturate(material.cutoff_end), shape);
    let width = max(fwidth(noise), 1e-3);
    let coverage = saturate((noise - threshold) / width + 0.5) * step(1e-6, noise);
    let shaded = fur_shade(fur);
    // A shell's alpha is the opacity of a slab 1/20 of the fur length
    // thick; the fin has FIN_SLABS of them, or (FIN_SLABS <= 0) stands for
    // a strip as deep as it is wide.
    let a = saturate(coverage * (1.0 - o) * shaded.a);
    let strip = in.fin.y / max(material.fur_length / FUR_SEED_SHELLS, 1e-6);
    let slabs = select(FIN_SLABS, strip, FIN_SLABS <= 0.0);
    let keep = 1.0 - a;
    let alpha = (1.0 - select(pow(keep, slabs), 0.0, keep <= 0.0)) * saturate(in.fin.x);
    return vec4<f32>(shaded.rgb, alpha);
}
"#;

/// The passes of the experiment material: fur's skin and shells over the
/// body only, then the fins (after the skin, before the shells, as
/// Lengyel et al. draw them).
const FINS_PASSES: &str = r#"
[[pass]]
name = "skin"
vertex = "vs_skin_body"
fragment = "fs_skin"
blend = "opaque"
cull = "back"
depth_write = true
queue = 2000

[[pass]]
name = "fins"
vertex = "vs_fin"
fragment = "fs_fin"
blend = "alpha"
cull = "none"
depth_write = false
depth_test = "less_equal"
queue = 2500

[[pass]]
name = "shells"
vertex = "vs_shell_body"
fragment = "fs_shell_body"
blend = "alpha"
cull = "back"
depth_write = false
depth_test = "less_equal"
queue = 3000
instances = "shell_count"
"#;

/// How the fins are drawn: their opacity, and whether the shells fade out
/// where the fins fade in (Lengyel et al.) or are drawn as without fins.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FinRule {
    pub opacity: FinOpacity,
    pub fade_shells: bool,
}

impl FinRule {
    pub fn describe(&self) -> String {
        let fade = if self.fade_shells {
            ", shells faded"
        } else {
            ""
        };
        format!("{}{fade}", self.opacity.describe())
    }
}

/// How opaque a fin is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FinOpacity {
    /// As this many of the seed's shells (each the opacity of 1/20 of the
    /// fur, Beer–Lambert): what a fin texture drawn like a shell gives.
    Slabs(f32),
    /// As the strip of fur it stands for, as deep as the fin is wide, by the
    /// same rule (width / (fur length / 20) slabs).
    Strip,
    /// No fins drawn (the fins pass collapses every vertex): the cost of
    /// the body and fins in one mesh without the fins' own.
    Hidden,
}

impl FinOpacity {
    pub fn describe(&self) -> String {
        match self {
            FinOpacity::Slabs(k) => format!("opacity of {k} shell slab(s)"),
            FinOpacity::Strip => "opacity of the strip it stands for".into(),
            FinOpacity::Hidden => "hidden".into(),
        }
    }
}

/// Builds `fur_fins` from `materials_dir`'s fur and lib into
/// `work/generated`; returns its metadata path.
pub fn build(materials_dir: &Path, work: &Path, rule: FinRule) -> Result<PathBuf, String> {
    let opacity = rule.opacity;
    let io = |p: &Path, e: std::io::Error| format!("{}: {e}", p.display());
    let read = |p: &Path| std::fs::read_to_string(p).map_err(|e| io(p, e));
    let fur = materials_dir.join("fur");
    let toml = read(&fur.join("fur.toml"))?;
    let wgsl = read(&fur.join("fur.wgsl"))?;
    // fur.toml up to its passes, renamed, with the streams the fins need.
    let head = toml
        .find("[[pass]]")
        .map(|i| &toml[..i])
        .ok_or("fur.toml has no [[pass]]")?;
    let replace = |text: &str, from: &str, to: &str| -> Result<String, String> {
        text.contains(from)
            .then(|| text.replacen(from, to, 1))
            .ok_or_else(|| format!("fur.toml: no `{from}`"))
    };
    let head = replace(
        head,
        "name = \"fur\"",
        &format!("name = \"{FINS_MATERIAL}\""),
    )?;
    let head = replace(
        &head,
        "source = \"fur.wgsl\"",
        &format!("source = \"{FINS_MATERIAL}.wgsl\""),
    )?;
    let head = replace(
        &head,
        "requires = [\"position\", \"normal\", \"uv0\"]",
        "requires = [\"position\", \"normal\", \"tangent\", \"uv0\", \"uv1\"]",
    )?;
    let src = work.join("materials");
    let dir = src.join(FINS_MATERIAL);
    std::fs::create_dir_all(&dir).map_err(|e| io(&dir, e))?;
    crate::floor::copy_dir(&materials_dir.join("lib"), &src.join("lib"))?;
    for (name, text) in [
        (format!("{FINS_MATERIAL}.toml"), head + FINS_PASSES),
        (
            format!("{FINS_MATERIAL}.wgsl"),
            format!(
                "{wgsl}{FINS_WGSL}\nconst FIN_SLABS: f32 = {:?};\nconst FIN_HIDDEN: bool = {};\nconst FIN_FADE_SHELLS: bool = {};\n",
                match opacity {
                    FinOpacity::Slabs(k) => k,
                    FinOpacity::Strip | FinOpacity::Hidden => 0.0,
                },
                opacity == FinOpacity::Hidden,
                rule.fade_shells
            ),
        ),
    ] {
        let p = dir.join(name);
        std::fs::write(&p, text).map_err(|e| io(&p, e))?;
    }
    let built = weft_compiler::build_library(&src, &Default::default(), &|_, _, _| {})
        .map_err(|(db, d)| format!("{FINS_MATERIAL} does not build:\n{}", d.render_plain(&db)))?;
    let out = work.join("generated");
    weft_compiler::output::write_atomically(&out, &built.files, &[]).map_err(|e| io(&out, e))?;
    Ok(out
        .join(FINS_MATERIAL)
        .join(format!("{FINS_MATERIAL}.meta.json")))
}

/// `scene` with its mesh replaced by the body and the fins of its
/// silhouette edges (averaged normal with |N·V| < `max_n_dot_v` seen from
/// the camera); also returns the number of fins.
pub fn scene_with_fins(scene: &Scene, max_n_dot_v: f32) -> (Scene, usize) {
    let body = &scene.mesh;
    let mut mesh = body.clone();
    mesh.uv1 = if body.uv1.is_empty() {
        body.uv0.clone()
    } else {
        body.uv1.clone()
    };
    let eye = scene.camera.eye;
    // Each edge once, also across seams (vertices repeated at one position).
    let key = |p: [f32; 3]| p.map(|c| (c * 1e4).round() as i64);
    let mut seen = std::collections::HashSet::new();
    let mut fins = 0;
    for tri in body.indices.chunks_exact(3) {
        for (a, b) in [(tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])] {
            let (a, b) = (a as usize, b as usize);
            let (pa, pb) = (body.positions[a], body.positions[b]);
            let edge = math::sub(pb, pa);
            if math::dot(edge, edge) < 1e-12 {
                continue;
            }
            let (ka, kb) = (key(pa), key(pb));
            if !seen.insert(if ka < kb { (ka, kb) } else { (kb, ka) }) {
                continue;
            }
            let n = math::normalize(math::add(body.normals[a], body.normals[b]));
            let mid = math::scale(math::add(pa, pb), 0.5);
            let v = math::normalize(math::sub(eye, mid));
            if math::dot(n, v).abs() >= max_n_dot_v {
                continue;
            }
            let plane = math::normalize(math::cross(edge, n));
            let width = math::dot(edge, edge).sqrt();
            let base = mesh.positions.len() as u32;
            // root a, root b, tip b, tip a
            for (i, h) in [(a, 0.0), (b, 0.0), (b, 1.0), (a, 1.0)] {
                mesh.positions.push(body.positions[i]);
                mesh.normals.push(body.normals[i]);
                mesh.tangents.push([plane[0], plane[1], plane[2], 0.0]);
                mesh.uv0.push(body.uv0[i]);
                mesh.uv1.push([width, h]);
                if !body.colors.is_empty() {
                    mesh.colors.push([1.0; 4]);
                }
            }
            mesh.indices
                .extend([base, base + 1, base + 2, base, base + 2, base + 3]);
            fins += 1;
        }
    }
    (
        Scene {
            mesh,
            ..scene.clone()
        },
        fins,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use weft_render::SceneKind;

    #[test]
    fn fins_stand_on_the_silhouette_edges_only() {
        let scene = Scene::new(SceneKind::Sphere);
        let (with, fins) = scene_with_fins(&scene, 0.3);
        let body = scene.mesh.positions.len();
        assert_eq!(with.mesh.positions.len(), body + 4 * fins);
        assert_eq!(with.mesh.uv1.len(), with.mesh.positions.len());
        // The body keeps its vertices, tangent w ±1; fins have w 0.
        assert!(with.mesh.tangents[..body].iter().all(|t| t[3].abs() == 1.0));
        assert!(with.mesh.tangents[body..].iter().all(|t| t[3] == 0.0));
        // N·V is uniform over a sphere's area (seen from afar), so the band
        // |N·V| < 0.3 holds about 0.3 of the surface, front and back, and of
        // its edges (about 1.5 per triangle).
        let all = scene.mesh.indices.len() / 2;
        let share = fins as f64 / all as f64;
        assert!(share > 0.25 && share < 0.45, "{fins} of about {all}");
        // Every fin root lies in the band.
        let eye = scene.camera.eye;
        for q in with.mesh.positions[body..].chunks_exact(4) {
            let mid = math::scale(math::add(q[0], q[1]), 0.5);
            let v = math::normalize(math::sub(eye, mid));
            assert!(math::dot(math::normalize(mid), v).abs() < 0.32);
        }
    }
}
