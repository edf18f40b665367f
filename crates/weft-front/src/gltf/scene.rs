//! A glTF scene as a weft scene manifest: every mesh primitive a node of
//! the scene draws is an instance (its world matrix, its material mapped by
//! `materials`), the first camera frames it (else a framing of its bounds),
//! the first directional `KHR_lights_punctual` light lights it.
//!
//! The result is manifest text that the ordinary scene front end then
//! parses and resolves, so a glTF scene is checked exactly as a written one;
//! `weft build --scene x.glb --print-manifest` shows it.

use super::document::GltfFile;
use super::instancing::instance_transforms;
use super::materials::{MaterialMapping, float, map_material, toml_string};
use super::transform::{IDENTITY, Mat4, mul, normalize, transform_point};
use super::{GltfError, Warnings};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;
use weft_meta::scene::MAX_INSTANCES;

/// A lower_snake_case name from any glTF name (instance names).
pub fn snake_name(raw: &str, fallback: &str) -> String {
    let mut out = String::new();
    for c in raw.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.ends_with('_') && !out.is_empty() {
            out.push('_');
        }
    }
    let out = out.trim_end_matches('_').to_string();
    match out.chars().next() {
        Some(c) if c.is_ascii_lowercase() => out,
        Some(_) => format!("n_{out}"),
        None => fallback.to_string(),
    }
}

/// One drawn primitive: which node, which mesh primitive, its world matrix.
#[derive(Clone)]
struct Draw {
    name: String,
    mesh: usize,
    primitive: usize,
    material: Option<usize>,
    world: Mat4,
    /// The node that draws it, when its skin or morph weights pose the
    /// mesh (`pose::node_poses`): the instance's mesh names it.
    posing_node: Option<usize>,
    /// A skinned draw: its vertices come out in world space (glTF ignores
    /// the node's own transform), so the instance's matrix is the identity.
    skinned: bool,
    /// For a `KHR_materials_variants` stand-in: (variant name, the
    /// instance it replaces is `name` without the suffix).
    variant: Option<String>,
}

/// Per `KHR_materials_variants` variant the primitive maps to another
/// material: a stand-in draw each, after the ordinary ones. Indices are
/// checked (gltf 1.4 does not).
fn variant_draws(file: &GltfFile, draws: &[Draw]) -> Result<Vec<Draw>, GltfError> {
    let names: Vec<String> = file
        .document
        .variants()
        .map(|v| v.map(|v| v.name().to_string()).collect())
        .unwrap_or_default();
    let materials = file.document.materials().count();
    let mut out = Vec::new();
    for (vi, vname) in names.iter().enumerate() {
        for d in draws {
            let json = &file.document.as_json().meshes[d.mesh].primitives[d.primitive];
            let Some(mappings) = json
                .extensions
                .as_ref()
                .and_then(|e| e.khr_materials_variants.as_ref())
            else {
                continue;
            };
            for (k, mapping) in mappings.mappings.iter().enumerate() {
                let pointer = format!(
                    "/meshes/{}/primitives/{}/extensions/KHR_materials_variants/mappings/{k}",
                    d.mesh, d.primitive
                );
                if mapping.material as usize >= materials
                    || mapping.variants.iter().any(|&v| v as usize >= names.len())
                {
                    return Err(file.error(
                        &pointer,
                        format!("a mapping names material {} or a variant the file does not have", mapping.material),
                        "KHR_materials_variants: `material` indexes materials, `variants` the root's variants",
                    ));
                }
                if mapping.variants.contains(&(vi as u32))
                    && Some(mapping.material as usize) != d.material
                {
                    out.push(Draw {
                        name: format!("{}__{}", d.name, snake_name(vname, &format!("variant{vi}"))),
                        material: Some(mapping.material as usize),
                        variant: Some(vname.clone()),
                        ..d.clone()
                    });
                }
            }
        }
    }
    Ok(out)
}

/// What the glTF scene becomes, and what the build reports about it.
pub struct GltfScene {
    /// `[scene]` (name, description, materials root, vertex inputs).
    pub scene: String,
    /// `[camera]`: the file's camera or a framing of its bounds.
    pub camera: String,
    /// `[light]`, empty when the file has no directional light.
    pub light: String,
    /// Every `[[instances]]` table.
    pub instances: String,
    /// Materials in the file → used by the drawn nodes (variants included).
    pub materials_in_file: usize,
    pub materials_used: usize,
    /// Per used glTF material: its mapping (losses included).
    pub mappings: Vec<MaterialMapping>,
}

impl GltfScene {
    /// The whole manifest of a glTF file built as it is.
    pub fn manifest(&self) -> String {
        [&self.scene, &self.camera, &self.light, &self.instances]
            .iter()
            .filter(|s| !s.is_empty())
            .map(|s| s.as_str())
            .collect::<Vec<_>>()
            .join("\n")
    }
}

/// Per glTF material (by name, or `#<index>`): the scene TOML's `[gltf]`
/// overrides layered on the mapping.
pub type Overrides = BTreeMap<String, MaterialMapping>;

/// The glTF's drawn primitives, in scene order (depth first, children in
/// file order), with their world matrices. Cycles and shared nodes fail.
/// Every node visited, with its world matrix (camera and light search).
type Placed = Vec<(usize, Mat4)>;

fn drawn_primitives(file: &GltfFile) -> Result<(Vec<Draw>, Placed), GltfError> {
    let doc = &file.document;
    let scene = doc
        .default_scene()
        .or_else(|| doc.scenes().next())
        .ok_or_else(|| {
            file.error(
                "/scenes",
                "the file has no scene".into(),
                "export with at least one scene",
            )
        })?;
    let nodes = doc.nodes().count();
    let mut draws = Vec::new();
    let mut placed = Vec::new(); // (node, world) of every visited node
    let mut stack: Vec<(gltf::Node, Mat4, usize)> =
        scene.nodes().map(|n| (n, IDENTITY, usize::MAX)).collect();
    stack.reverse();
    let mut visited = vec![false; nodes];
    while let Some((node, parent, parent_index)) = stack.pop() {
        let i = node.index();
        if visited[i] {
            let pointer = if parent_index == usize::MAX {
                format!("/scenes/{}/nodes", scene.index())
            } else {
                format!("/nodes/{parent_index}/children")
            };
            return Err(file.error(
                &pointer,
                format!("node {i} is reached twice: the node graph has a cycle or a shared node"),
                "glTF nodes form disjoint trees: every node has at most one parent",
            ));
        }
        visited[i] = true;
        let local = node.transform().matrix().map(|c| c.map(f64::from));
        let world = mul(&parent, &local);
        if world.iter().flatten().any(|x| !x.is_finite()) {
            return Err(file.error(
                &format!("/nodes/{i}"),
                "the node's world transform is not finite".into(),
                "re-export the file",
            ));
        }
        placed.push((i, world));
        // EXT_mesh_gpu_instancing: a copy per instance, each placed by the
        // node's world transform after its own (an error on a node it does
        // not fit, drawn or not).
        let primitives = node.mesh().map_or(1, |m| m.primitives().count());
        let room = MAX_INSTANCES.saturating_sub(draws.len()) / primitives.max(1);
        let copies = instance_transforms(file, &node, room)?;
        if let Some(mesh) = node.mesh() {
            let base = snake_name(
                node.name().or(mesh.name()).unwrap_or(""),
                &format!("node{i}"),
            );
            let copies = match copies {
                Some(copies) => copies
                    .iter()
                    .enumerate()
                    .map(|(k, m)| (format!("_i{k}"), mul(&world, m)))
                    .collect(),
                None => vec![(String::new(), world)],
            };
            for (suffix, world) in copies {
                for prim in mesh.primitives() {
                    let name = if primitives > 1 {
                        format!("{base}_p{}{suffix}", prim.index())
                    } else {
                        format!("{base}{suffix}")
                    };
                    let skinned = node.skin().is_some();
                    draws.push(Draw {
                        name,
                        mesh: mesh.index(),
                        primitive: prim.index(),
                        material: prim.material().index(),
                        world: if skinned { IDENTITY } else { world },
                        posing_node: super::pose::node_poses(&node).then_some(i),
                        skinned,
                        variant: None,
                    });
                }
            }
        }
        let children: Vec<_> = node.children().collect();
        for child in children.into_iter().rev() {
            stack.push((child, world, i));
        }
    }
    Ok((draws, placed))
}

/// The world-space bounds of every drawn primitive (from accessor min/max).
fn bounds(file: &GltfFile, draws: &[Draw]) -> Option<([f64; 3], f64)> {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    let worlds = file.node_worlds();
    for d in draws {
        // A skinned primitive's box through each joint's matrix: a bound of
        // where skinning can put it (the mesh itself is posed later).
        let frames = match d.posing_node.filter(|_| d.skinned) {
            Some(n) => super::pose::joint_frames(file, n, worlds),
            None => vec![d.world],
        };
        let prim = file
            .document
            .meshes()
            .nth(d.mesh)?
            .primitives()
            .nth(d.primitive)?;
        let (min, max) = super::accessors::position_bounds(&prim)?;
        for corner in 0..8 {
            let p = std::array::from_fn(|k| {
                if corner >> k & 1 == 0 {
                    min[k] as f64
                } else {
                    max[k] as f64
                }
            });
            for frame in &frames {
                let w = transform_point(frame, p);
                for k in 0..3 {
                    lo[k] = lo[k].min(w[k]);
                    hi[k] = hi[k].max(w[k]);
                }
            }
        }
    }
    let centre: [f64; 3] = std::array::from_fn(|k| 0.5 * (lo[k] + hi[k]));
    let radius = (0..3).map(|k| (hi[k] - lo[k]).powi(2)).sum::<f64>().sqrt() * 0.5;
    (radius.is_finite() && centre.iter().all(|x| x.is_finite()))
        .then_some((centre, radius.max(1e-3)))
}

fn vec3(v: [f64; 3]) -> String {
    format!("[{}, {}, {}]", float(v[0]), float(v[1]), float(v[2]))
}

fn round(x: f64) -> f64 {
    // Nine significant figures: f32-exact for the renderer, stable in text.
    if x == 0.0 {
        0.0
    } else {
        format!("{x:.9e}").parse().unwrap_or(x)
    }
}

/// The viewport height `auto` tiers' `screen_size` is derived for when a
/// glTF material leaves it out: a 1080-pixel-high frame.
pub const VIEWPORT_HEIGHT: f64 = 1080.0;

/// Where the scene's camera stands (for `screen_size`).
#[derive(Clone, Copy, Debug)]
struct View {
    eye: [f64; 3],
    fov_degrees: f64,
}

/// The size on screen, in pixels of a [`VIEWPORT_HEIGHT`]-high frame, of a
/// sphere of `radius` at `centre` seen from `view`: its diameter over the
/// frustum's height at its distance, clamped to what `screen_size` takes.
fn screen_size(view: &View, centre: [f64; 3], radius: f64) -> u32 {
    let distance = (0..3)
        .map(|k| (centre[k] - view.eye[k]).powi(2))
        .sum::<f64>()
        .sqrt()
        .max(radius.max(1e-6));
    let half_height = distance * (view.fov_degrees.to_radians() * 0.5).tan();
    (radius / half_height * VIEWPORT_HEIGHT * 0.5)
        .round()
        .clamp(16.0, 4096.0) as u32
}

/// `[camera]`: the first perspective camera in the scene, else a framing of
/// the bounds from +Z (a three-quarter view is not assumed: glTF is +Y up,
/// front facing +Z).
fn camera(
    file: &GltfFile,
    placed: &[(usize, Mat4)],
    draws: &[Draw],
    warnings: &mut Warnings,
) -> (String, View) {
    let doc = &file.document;
    let framing = bounds(file, draws);
    for (i, world) in placed {
        let Some(cam) = doc.nodes().nth(*i).and_then(|n| n.camera()) else {
            continue;
        };
        match cam.projection() {
            gltf::camera::Projection::Perspective(p) => {
                let eye = [world[3][0], world[3][1], world[3][2]];
                let Some(forward) = normalize([-world[2][0], -world[2][1], -world[2][2]]) else { continue };
                let distance = framing.map_or(1.0, |(c, _)| {
                    let d: f64 = (0..3).map(|k| (c[k] - eye[k]) * forward[k]).sum();
                    d.max(1e-3)
                });
                let target = std::array::from_fn(|k| round(eye[k] + forward[k] * distance));
                let fov = (p.yfov() as f64).to_degrees().clamp(1.0, 179.0);
                let text = format!(
                    "[camera]\n# node {i}'s camera (`/cameras/{}`)\nposition = {}\ntarget = {}\nfov_degrees = {}\n",
                    cam.index(),
                    vec3(eye.map(round)),
                    vec3(target),
                    float(round(fov))
                );
                return (text, View { eye, fov_degrees: fov });
            }
            gltf::camera::Projection::Orthographic(_) => warnings.push(format!(
                "{}: /cameras/{}: an orthographic camera; weft's scene camera is perspective: the scene is framed instead",
                super::shown(&file.path),
                cam.index()
            )),
        }
    }
    let (centre, radius) = framing.unwrap_or(([0.0; 3], 1.0));
    let fov: f64 = 35.0;
    let distance = radius / (fov.to_radians() * 0.5).sin() * 1.1;
    let eye = [centre[0], centre[1], centre[2] + distance].map(round);
    let text = format!(
        "[camera]\n# no camera in the file: its bounds framed from +Z\nposition = {}\ntarget = {}\nfov_degrees = {}\n",
        vec3(eye),
        vec3(centre.map(round)),
        float(fov)
    );
    (
        text,
        View {
            eye,
            fov_degrees: fov,
        },
    )
}

/// `[light]`: the first directional light a node of the scene carries.
fn light(file: &GltfFile, placed: &[(usize, Mat4)], warnings: &mut Warnings) -> String {
    let doc = &file.document;
    let mut chosen = None;
    for (i, world) in placed {
        let Some(light) = doc.nodes().nth(*i).and_then(|n| n.light()) else {
            continue;
        };
        let pointer = format!("/extensions/KHR_lights_punctual/lights/{}", light.index());
        match light.kind() {
            gltf::khr_lights_punctual::Kind::Directional if chosen.is_none() => {
                // The light shines along the node's −Z: towards it is +Z.
                let Some(dir) = normalize([world[2][0], world[2][1], world[2][2]]) else { continue };
                let intensity = light.intensity() as f64;
                let color = light.color().map(|c| round(c as f64 * intensity));
                chosen = Some(format!(
                    "[light]\n# node {i}'s directional light (`{pointer}`): colour × intensity\ndirection = {}\ncolor = {}\n",
                    vec3(dir.map(round)),
                    vec3(color)
                ));
            }
            gltf::khr_lights_punctual::Kind::Directional => warnings.push(format!(
                "{}: {pointer}: a second directional light; engine interface v1 has one light slot: dropped",
                super::shown(&file.path)
            )),
            kind => warnings.push(format!(
                "{}: {pointer}: a {} light; weft's scenes have one directional light: dropped",
                super::shown(&file.path),
                match kind {
                    gltf::khr_lights_punctual::Kind::Point => "point",
                    _ => "spot",
                }
            )),
        }
    }
    chosen.unwrap_or_default()
}

/// The manifest for `file`'s default scene. `manifest_dir` is the folder the
/// manifest's paths are relative to; `name` the scene's name.
pub fn scene_manifest(
    file: &GltfFile,
    name: &str,
    manifest_dir: &Path,
    materials_root: Option<&Path>,
    overrides: &Overrides,
    warnings: &mut Warnings,
) -> Result<GltfScene, GltfError> {
    let (mut draws, placed) = drawn_primitives(file)?;
    let ordinary = draws.len();
    draws.extend(variant_draws(file, &draws)?);
    if draws.is_empty() {
        return Err(file.error(
            "/nodes",
            "the scene draws no mesh".into(),
            "export at least one node with a mesh",
        ));
    }
    if draws.len() > MAX_INSTANCES {
        return Err(file.error(
            "/nodes",
            format!("the scene draws {} mesh primitives; a weft scene has at most {MAX_INSTANCES} instances", draws.len()),
            "merge meshes that share a material, or split the scene",
        ));
    }
    let relative = pathdiff(&file.path, manifest_dir);
    let (used, mappings) = mapped_materials(file, &draws, &relative, overrides)?;
    let header = scene_header(file, name, manifest_dir, materials_root, &relative);
    let (camera, view) = camera(file, &placed, &draws, warnings);
    let light = light(file, &placed, warnings);
    let mut instances = String::new();
    let mut taken = std::collections::BTreeSet::new();
    let mut final_names: Vec<String> = Vec::new();
    for d in &draws {
        let name = (1..)
            .map(|n| {
                if n == 1 {
                    d.name.clone()
                } else {
                    format!("{}_{n}", d.name)
                }
            })
            .find(|candidate| !taken.contains(candidate))
            .expect("a free name");
        taken.insert(name.clone());
        final_names.push(name.clone());
        let mapping = &mappings[used.iter().position(|m| *m == d.material).unwrap_or(0)];
        // A variant's draw replaces the ordinary draw of the same primitive.
        let replaced = d.variant.as_ref().map(|_| {
            draws[..ordinary]
                .iter()
                .position(|o| o.mesh == d.mesh && o.primitive == d.primitive && o.world == d.world)
                .map_or_else(String::new, |o| final_names[o].clone())
        });
        let instance = Instance {
            draw: d,
            name: &name,
            mapping,
            replaced: replaced.as_deref(),
        };
        instance_table(&mut instances, file, &instance, &view, &relative);
    }
    vertex_colour_warnings(file, &draws, warnings);
    Ok(GltfScene {
        scene: header,
        camera,
        light,
        instances,
        materials_in_file: file.document.materials().count(),
        materials_used: used.len(),
        mappings,
    })
}

/// glTF multiplies `COLOR_0` into the base colour, and no material of
/// weft's library reads the vertex colour stream (the test
/// `no_library_material_reads_vertex_colours` holds this): each drawn
/// primitive that has one is said to draw without it, once.
fn vertex_colour_warnings(file: &GltfFile, draws: &[Draw], warnings: &mut Warnings) {
    let mut seen = std::collections::BTreeSet::new();
    for d in draws {
        let has_colours = file
            .document
            .meshes()
            .nth(d.mesh)
            .and_then(|m| m.primitives().nth(d.primitive))
            .is_some_and(|p| p.get(&gltf::Semantic::Colors(0)).is_some());
        if has_colours && seen.insert((d.mesh, d.primitive)) {
            warnings.push(format!(
                "{}: /meshes/{}/primitives/{}: drops COLOR_0 (vertex colours, which glTF multiplies into the base colour; weft's materials read none): bake them into baseColorTexture",
                super::shown(&file.path),
                d.mesh,
                d.primitive
            ));
        }
    }
}

/// Each material the draws use once, in first-use order, mapped (docs/gltf.md)
/// with the manifest's overrides layered on by name or `#index`.
fn mapped_materials(
    file: &GltfFile,
    draws: &[Draw],
    relative: &str,
    overrides: &Overrides,
) -> Result<(Vec<Option<usize>>, Vec<MaterialMapping>), GltfError> {
    let mut used: Vec<Option<usize>> = Vec::new();
    for d in draws {
        if !used.contains(&d.material) {
            used.push(d.material);
        }
    }
    let mut mappings = Vec::new();
    for m in &used {
        let mut mapping = map_material(file, *m, relative)?;
        let key_name = mapping.gltf_name.clone();
        let key_index = m.map_or("#default".to_string(), |i| format!("#{i}"));
        if let Some(o) = overrides
            .get(&key_name)
            .or_else(|| overrides.get(&key_index))
        {
            mapping = layer(mapping, o);
        }
        mappings.push(mapping);
    }
    Ok((used, mappings))
}

/// The manifest's `[scene]` table. Paths are relative to the manifest: the
/// text (hashed into the metadata) must not depend on where the checkout lies.
fn scene_header(
    file: &GltfFile,
    name: &str,
    manifest_dir: &Path,
    materials_root: Option<&Path>,
    relative: &str,
) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# Generated by weft from `{relative}` (glTF 2.0): docs/gltf.md."
    );
    out.push_str("[scene]\n");
    let _ = writeln!(out, "name = {}", toml_string(name));
    let _ = writeln!(
        out,
        "description = {}",
        toml_string(&format!(
            "Built from {} (glTF).",
            file.path
                .file_name()
                .map_or(String::new(), |f| f.to_string_lossy().into_owned())
        ))
    );
    if let Some(root) = materials_root {
        let _ = writeln!(
            out,
            "materials = {}",
            toml_string(&pathdiff(root, manifest_dir))
        );
    }
    out.push_str("vertex_inputs = [\"position\", \"normal\", \"tangent\", \"uv0\"]\n");
    out
}

/// One drawn primitive as the manifest's instance.
struct Instance<'a> {
    draw: &'a Draw,
    name: &'a str,
    mapping: &'a MaterialMapping,
    /// For a material variant's draw: the instance it replaces.
    replaced: Option<&'a str>,
}

/// Writes one `[[instances]]` table: material, tier and values from the
/// mapping, the mesh, the vertex inputs the primitive has, render-state
/// overrides, the variant it belongs to, and its world matrix.
fn instance_table(
    out: &mut String,
    file: &GltfFile,
    instance: &Instance,
    view: &View,
    relative: &str,
) {
    let Instance {
        draw: d,
        name,
        mapping,
        replaced,
    } = *instance;
    let prim = file
        .document
        .meshes()
        .nth(d.mesh)
        .and_then(|m| m.primitives().nth(d.primitive));
    let mut inputs = vec!["\"position\"", "\"normal\"", "\"tangent\"", "\"uv0\""];
    if prim
        .as_ref()
        .is_some_and(|p| p.get(&gltf::Semantic::TexCoords(1)).is_some())
    {
        inputs.push("\"uv1\"");
    }
    if prim
        .as_ref()
        .is_some_and(|p| p.get(&gltf::Semantic::Colors(0)).is_some())
    {
        inputs.push("\"color\"");
    }
    out.push_str("\n[[instances]]\n");
    let _ = writeln!(out, "name = {}", toml_string(name));
    let _ = writeln!(
        out,
        "# glTF material `{}` ({})",
        mapping.gltf_name.replace('\n', " "),
        mapping.rule
    );
    let _ = writeln!(out, "material = {}", toml_string(&mapping.material));
    if let Some(p) = &mapping.preset {
        let _ = writeln!(out, "preset = {}", toml_string(p));
    }
    if let Some(t) = &mapping.tier {
        let _ = writeln!(out, "tier = {}", toml_string(t));
    }
    if let Some(b) = mapping.error_budget {
        let _ = writeln!(out, "error_budget = {}", float(b));
    }
    if let Some(s) = mapping.screen_size {
        let _ = writeln!(out, "screen_size = {s}");
    } else if mapping.tier.as_deref() == Some("auto")
        && let Some((centre, radius)) = bounds(file, std::slice::from_ref(d))
    {
        // Left out: what the scene's camera gives the primitive.
        let _ = writeln!(
            out,
            "screen_size = {}  # the camera's view of it in a {VIEWPORT_HEIGHT}-pixel-high frame",
            screen_size(view, centre, radius)
        );
    }
    if !mapping.keywords.is_empty() {
        let kw: Vec<String> = mapping
            .keywords
            .iter()
            .map(|(k, v)| format!("{k} = {v}"))
            .collect();
        let _ = writeln!(out, "keywords = {{ {} }}", kw.join(", "));
    }
    if !mapping.params.is_empty() {
        let ps: Vec<String> = mapping
            .params
            .iter()
            .map(|(k, v)| format!("{k} = {v}"))
            .collect();
        let _ = writeln!(out, "params = {{ {} }}", ps.join(", "));
    }
    if !mapping.dynamic.is_empty() {
        let ds: Vec<String> = mapping.dynamic.iter().map(|d| toml_string(d)).collect();
        let _ = writeln!(out, "dynamic = [{}]", ds.join(", "));
    }
    let uv_transform = mapping.uv_transform.map_or_else(String::new, |t| {
        let t: Vec<String> = t.iter().map(|&x| float(round(x))).collect();
        format!(", uv_transform = [{}]", t.join(", "))
    });
    let node = d
        .posing_node
        .map_or_else(String::new, |n| format!(", node = {n}"));
    let _ = writeln!(
        out,
        "mesh = {{ gltf = {}, mesh = {}, primitive = {}{uv_transform}{node} }}",
        toml_string(relative),
        d.mesh,
        d.primitive
    );
    if inputs.len() > 4 {
        let _ = writeln!(out, "vertex_inputs = [{}]", inputs.join(", "));
    }
    if mapping.double_sided {
        let _ = writeln!(out, "double_sided = true");
    }
    if mapping.blend {
        let _ = writeln!(out, "blend = \"alpha\"");
    }
    if let Some(sampler) = &mapping.sampler {
        let _ = writeln!(out, "sampler = {sampler}");
    }
    if let (Some(v), Some(replaced)) = (&d.variant, replaced) {
        let _ = writeln!(
            out,
            "variant = {{ name = {}, replaces = {} }}",
            toml_string(v),
            toml_string(replaced)
        );
    }
    let m: Vec<String> = d.world.iter().flatten().map(|&x| float(round(x))).collect();
    let _ = writeln!(out, "matrix = [{}]", m.join(", "));
}

/// `path` relative to the folder `dir` (`..` where it lies outside), `/`
/// separated; absolute only when the two share no root.
fn pathdiff(path: &Path, dir: &Path) -> String {
    let abs = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
    let dir = dir.canonicalize().unwrap_or_else(|_| dir.to_path_buf());
    let a: Vec<_> = abs.components().collect();
    let d: Vec<_> = dir.components().collect();
    let common = a.iter().zip(&d).take_while(|(x, y)| x == y).count();
    if common == 0 {
        return abs.to_string_lossy().replace('\\', "/");
    }
    let mut parts: Vec<String> = vec!["..".into(); d.len() - common];
    parts.extend(
        a[common..]
            .iter()
            .map(|c| c.as_os_str().to_string_lossy().into_owned()),
    );
    if parts.is_empty() {
        ".".into()
    } else {
        parts.join("/")
    }
}

/// The mapping with a scene's overrides on top: the override's material
/// replaces the mapping (its params then start from the material's
/// defaults); otherwise its params, keywords and tier are layered.
fn layer(mut base: MaterialMapping, o: &MaterialMapping) -> MaterialMapping {
    if !o.material.is_empty() && o.material != base.material {
        let mut out = o.clone();
        out.gltf_name = base.gltf_name;
        // The render state is the glTF material's, whatever weft draws; its
        // maps (and their sampler) are the override's.
        out.double_sided = base.double_sided;
        out.blend = base.blend;
        out.sampler = None;
        out.uv_transform = None;
        out.rule = "[gltf.materials]";
        return out;
    }
    for (k, v) in &o.params {
        base.params.retain(|(key, _)| key != k);
        base.params.push((k.clone(), v.clone()));
    }
    for (k, v) in &o.keywords {
        base.keywords.retain(|(key, _)| key != k);
        base.keywords.push((k.clone(), v.clone()));
    }
    if o.preset.is_some() {
        base.preset = o.preset.clone();
    }
    if o.tier.is_some() {
        base.tier = o.tier.clone();
        base.error_budget = o.error_budget;
        base.screen_size = o.screen_size;
    }
    if !o.dynamic.is_empty() {
        base.dynamic = o.dynamic.clone();
    }
    base.rule = "[gltf.materials]";
    base
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn screen_size_is_the_spheres_share_of_the_frame_height() {
        let view = View {
            eye: [0.0; 3],
            fov_degrees: 60.0,
        };
        // r / (d tan 30°) of half the frame: 1 / (10 · 0.57735) · 540 = 93.5.
        assert_eq!(screen_size(&view, [0.0, 0.0, -10.0], 1.0), 94);
        // Clamped to what `screen_size` takes.
        assert_eq!(screen_size(&view, [0.0, 0.0, -1e6], 1.0), 16);
        let narrow = View {
            eye: [0.0; 3],
            fov_degrees: 5.0,
        };
        assert_eq!(screen_size(&narrow, [0.0, 0.0, -1.0], 1.0), 4096);
    }
}
