//! Reading a generated library: material metadata
//! (`<root>/<material>/<material>.meta.json`), scene metadata
//! (`<root>/scenes/<scene>/<scene>.scene.json`), and what each shader binds
//! with the declared defaults (library variants) or the instance's values
//! (scene shaders).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use weft_meta::scene::{SceneInstance, SceneMetadata};
use weft_meta::{
    BindingKind, InstanceCount, LanguageConventions, MaterialMetadata, ParamKind, Pass,
    TextureDefault, Variant, VariantShader,
};

/// A library folder: the one holding `metadata.schema.json` and `luts/`.
pub struct Library {
    pub root: PathBuf,
    /// (metadata file, metadata), sorted by material name.
    pub materials: Vec<(PathBuf, MaterialMetadata)>,
    /// (metadata file, metadata), sorted by scene name.
    pub scenes: Vec<(PathBuf, SceneMetadata)>,
}

fn read_material(path: &Path) -> Result<MaterialMetadata, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    serde_json::from_slice(&bytes).map_err(|e| format!("{}: {e}", path.display()))
}

fn read_scene(path: &Path) -> Result<SceneMetadata, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    serde_json::from_slice(&bytes).map_err(|e| format!("{}: {e}", path.display()))
}

fn sorted_dirs(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))? {
        let p = e.map_err(|e| e.to_string())?.path();
        if p.is_dir() {
            out.push(p);
        }
    }
    out.sort();
    Ok(out)
}

impl Library {
    pub fn load(root: &Path) -> Result<Library, String> {
        let mut materials = Vec::new();
        for dir in sorted_dirs(root)? {
            let name = dir.file_name().unwrap().to_string_lossy().to_string();
            let path = dir.join(format!("{name}.meta.json"));
            if path.is_file() {
                let meta = read_material(&path)?;
                materials.push((path, meta));
            }
        }
        let mut scenes = Vec::new();
        let scene_root = root.join("scenes");
        if scene_root.is_dir() {
            for dir in sorted_dirs(&scene_root)? {
                let name = dir.file_name().unwrap().to_string_lossy().to_string();
                let path = dir.join(format!("{name}.scene.json"));
                if path.is_file() {
                    let meta = read_scene(&path)?;
                    scenes.push((path, meta));
                }
            }
        }
        Ok(Library {
            root: root.to_path_buf(),
            materials,
            scenes,
        })
    }
}

/// The canonical variants of a material (aliases resolve to one of these
/// through `alias_of`), each with its shader.
/// The passes a variant draws: those of `passes[]` that its `passes` names
/// (docs/engine-interface.md: a pass with `when` exists only in some
/// variants), in declaration order.
pub fn variant_passes(meta: &MaterialMetadata, variant: &Variant) -> Vec<Pass> {
    meta.passes
        .iter()
        .filter(|p| variant.passes.contains(&p.name))
        .cloned()
        .collect()
}

pub fn canonical_variants(
    meta: &MaterialMetadata,
) -> Result<Vec<(&Variant, &VariantShader)>, String> {
    let mut out = Vec::new();
    for v in &meta.variants {
        match (&v.alias_of, &v.shader) {
            (None, Some(s)) => out.push((v, s)),
            (Some(target), None) => {
                let t = meta
                    .variants
                    .iter()
                    .find(|c| &c.id == target)
                    .ok_or_else(|| {
                        format!("{}: `{}` aliases unknown `{target}`", meta.name, v.id)
                    })?;
                if t.alias_of.is_some() || t.shader.is_none() {
                    return Err(format!(
                        "{}: `{}` aliases `{target}`, which is not canonical",
                        meta.name, v.id
                    ));
                }
            }
            _ => {
                return Err(format!(
                    "{}: variant `{}` must have exactly one of `shader` and `alias_of`",
                    meta.name, v.id
                ));
            }
        }
    }
    Ok(out)
}

/// One shader to bind and draw: its reflection, the folder its file paths
/// are relative to, the library root (for LUT files) and its passes.
#[derive(Clone)]
pub struct ShaderRef<'a> {
    pub label: String,
    pub dir: PathBuf,
    pub root: PathBuf,
    pub shader: &'a VariantShader,
    pub passes: &'a [Pass],
    /// `languages` of the material metadata (scene metadata has none).
    pub languages: Option<&'a BTreeMap<String, LanguageConventions>>,
}

/// What a material texture binding samples.
#[derive(Clone, Debug, PartialEq)]
pub enum TextureData {
    /// A built-in 1×1 texture (six 1×1 faces for a cube): its RGBA8 texel,
    /// from the metadata's `conventions.builtin_textures`.
    Builtin([u8; 4]),
    /// A gradient ramp: RGBA8 texels as stored (sRGB-encoded), `len / 4` × 1.
    Ramp(Vec<u8>),
    /// A texture parameter's image (`texture.file`): RGBA8 texels read from
    /// the file, relative to the library root.
    File(weft_meta::ResourceFile),
}

/// The material side of one draw: group 1's uniform bytes and textures, and
/// the instances each pass draws.
#[derive(Clone, Debug, Default)]
pub struct MaterialInputs {
    /// The `material` uniform (None when the shader has no group-1 uniform).
    pub uniform: Option<Vec<u8>>,
    /// Group-1 texture bindings by binding number.
    pub textures: BTreeMap<u32, TextureData>,
    /// Per pass of the shader's `passes`, in that order.
    pub instances: Vec<u32>,
}

/// A built-in texture's RGBA8 texel as the metadata states it
/// (`conventions.builtin_textures`): this engine knows no value of its own.
fn builtin_texel(
    conventions: Option<&weft_meta::Conventions>,
    d: TextureDefault,
) -> Result<[u8; 4], String> {
    conventions
        .and_then(|c| c.builtin_textures.get(d.name()))
        .copied()
        .ok_or_else(|| {
            format!(
                "no `conventions.builtin_textures.{}` in the metadata",
                d.name()
            )
        })
}

/// A count from a JSON number: negative and non-finite counts draw nothing.
fn count_of(v: f64) -> u32 {
    if v.is_finite() && v > 0.0 {
        v.round().min(f64::from(u32::MAX)) as u32
    } else {
        0
    }
}

/// A library variant with every parameter at its declared default: the
/// material uniform from `parameters[]` (by each member's `parameter` and
/// `encoding`), textures from `bindings[].texture.file` (an image), else
/// `bindings[].texture.default` or the gradient's `baked_default`, instance counts (per pass of `passes`: the variant's,
/// [`variant_passes`]) fixed or the int parameter's default.
pub fn library_inputs(
    meta: &MaterialMetadata,
    passes: &[Pass],
    shader: &VariantShader,
) -> Result<MaterialInputs, String> {
    let uniform = match shader
        .bindings
        .iter()
        .find(|b| b.group == 1 && b.kind == BindingKind::UniformBuffer)
    {
        Some(b) => {
            let layout = &b
                .buffer
                .as_ref()
                .ok_or_else(|| format!("binding `{}` has no `buffer` entry", b.name))?
                .layout;
            Some(super::uniforms::material_defaults(meta, layout)?)
        }
        None => None,
    };
    let mut textures = BTreeMap::new();
    for b in &shader.bindings {
        let Some(t) = &b.texture else { continue };
        // A group-1 texture with a `resource` is baked data (a material's
        // table, docs/engine-interface.md): bound from its file.
        if b.group != 1 || b.resource.is_some() {
            continue;
        }
        let pname = b
            .parameter
            .as_ref()
            .ok_or_else(|| format!("material texture `{}` names no parameter", b.name))?;
        let p = meta
            .parameters
            .iter()
            .find(|p| &p.name == pname)
            .ok_or_else(|| format!("binding `{}`: no parameter `{pname}`", b.name))?;
        let data = match (p.kind, &p.gradient, t.default) {
            // Unset, a texture whose binding names an image binds the file.
            (ParamKind::Texture2d, _, _) if t.file.is_some() => {
                TextureData::File(t.file.clone().expect("checked"))
            }
            (ParamKind::Gradient, Some(g), _) => {
                if g.baked_default.len() != g.width as usize * 4 {
                    return Err(format!(
                        "gradient `{pname}`: {} baked bytes for width {}",
                        g.baked_default.len(),
                        g.width
                    ));
                }
                TextureData::Ramp(g.baked_default.clone())
            }
            (ParamKind::Texture2d | ParamKind::Cube, _, Some(d)) => {
                TextureData::Builtin(builtin_texel(meta.conventions.as_ref(), d)?)
            }
            (kind, _, d) => {
                return Err(format!(
                    "binding `{}` ({kind:?} parameter `{pname}`, default {d:?}): \
                     nothing says what to bind",
                    b.name
                ));
            }
        };
        textures.insert(b.binding, data);
    }
    let instances = passes
        .iter()
        .map(|pass| match &pass.instances {
            InstanceCount::Fixed(n) => Ok(*n),
            InstanceCount::Parameter(name) => {
                let p = meta
                    .parameters
                    .iter()
                    .find(|p| &p.name == name)
                    .ok_or_else(|| format!("pass `{}`: no parameter `{name}`", pass.name))?;
                match (p.kind, p.default.as_f64()) {
                    (ParamKind::Int, Some(v)) => Ok(count_of(v)),
                    _ => Err(format!(
                        "pass `{}`: instance count `{name}` is not an int parameter",
                        pass.name
                    )),
                }
            }
        })
        .collect::<Result<Vec<_>, String>>()?;
    Ok(MaterialInputs {
        uniform,
        textures,
        instances,
    })
}

/// A scene instance as built: the uniform from `uniform_values` (by member
/// name), textures from `textures` (by binding name; an image's file read
/// from the scene folder `scene_dir` first, as docs/scenes.md says, else
/// the library root), instance counts fixed or the folded/uploaded int value.
pub fn scene_inputs(
    meta: &SceneMetadata,
    inst: &SceneInstance,
    shader: &VariantShader,
    scene_dir: &Path,
) -> Result<MaterialInputs, String> {
    let uniform = match shader
        .bindings
        .iter()
        .find(|b| b.group == 1 && b.kind == BindingKind::UniformBuffer)
    {
        Some(b) => {
            let layout = &b
                .buffer
                .as_ref()
                .ok_or_else(|| format!("binding `{}` has no `buffer` entry", b.name))?
                .layout;
            Some(super::uniforms::by_member_values(
                &inst.uniform_values,
                layout,
            )?)
        }
        None => None,
    };
    let mut textures = BTreeMap::new();
    for b in &shader.bindings {
        if b.group != 1 || b.texture.is_none() || b.resource.is_some() {
            continue;
        }
        let t = inst.textures.get(&b.name).ok_or_else(|| {
            format!(
                "instance `{}`: no texture for binding `{}`",
                inst.name, b.name
            )
        })?;
        let data = match (&t.builtin, &t.ramp_rgba8) {
            // Left at its image: the file (`builtin` is a fallback).
            _ if t.file.is_some() => {
                let mut f = t.file.clone().expect("checked");
                let in_scene = scene_dir.join(&f.path);
                if in_scene.is_file() {
                    // Absolute: joined to the library root it stays itself.
                    f.path = in_scene.to_string_lossy().into_owned();
                }
                TextureData::File(f)
            }
            (Some(d), None) => TextureData::Builtin(builtin_texel(meta.conventions.as_ref(), *d)?),
            (None, Some(r)) => TextureData::Ramp(r.clone()),
            _ => {
                return Err(format!(
                    "instance `{}`: texture `{}` needs exactly one of builtin and ramp_rgba8",
                    inst.name, b.name
                ));
            }
        };
        textures.insert(b.binding, data);
    }
    let instances = inst
        .passes
        .iter()
        .map(|pass| match &pass.instances {
            InstanceCount::Fixed(n) => Ok(*n),
            InstanceCount::Parameter(name) => inst
                .constants
                .get(name)
                .or_else(|| inst.uniform_values.get(name))
                .and_then(serde_json::Value::as_f64)
                .map(count_of)
                .ok_or_else(|| {
                    format!(
                        "instance `{}` pass `{}`: no value for instance count `{name}`",
                        inst.name, pass.name
                    )
                }),
        })
        .collect::<Result<Vec<_>, String>>()?;
    Ok(MaterialInputs {
        uniform,
        textures,
        instances,
    })
}

/// Indices into `passes` in draw order: by `render_state.queue`, ties in
/// the given order.
pub fn queue_order(passes: &[Pass]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..passes.len()).collect();
    order.sort_by_key(|&i| passes[i].render_state.queue);
    order
}

/// What group 0 carries for a scene: its shaders were specialised for
/// `features`, and a feature that is off is bound black (cube), zero (SH)
/// or dark (light); the scene's own `light`, when it names one, replaces
/// the frame's (its direction normalised, as the engine interface wants),
/// and so does its `static_lighting.sh`.
pub fn scene_world(
    meta: &SceneMetadata,
    env: &super::data::Environment,
    frame: &super::data::FrameInputs,
) -> (super::data::Environment, super::data::FrameInputs) {
    let features = &meta.features;
    let black = super::data::Environment::black();
    let mut e = if features.environment {
        env.clone()
    } else {
        black.clone()
    };
    // A scene with static lighting (scene schema 3.7) holds its SH as
    // constants: the frame carries the same (docs/engine-interface.md).
    let stated_sh = meta.static_lighting.as_ref().and_then(|s| s.sh);
    e.sh = match (features.sh_ambient, stated_sh) {
        (true, Some(sh)) => sh.map(|rgb| rgb.map(|c| c as f32)),
        (true, None) => env.sh,
        (false, _) => black.sh,
    };
    let mut f = frame.clone();
    // Scene schema 3.3 states the light weft draws with, defaults included:
    // this engine knows no default light of its own.
    let light = meta
        .light
        .as_ref()
        .unwrap_or_else(|| panic!("scene {}: no `light` in the metadata", meta.name));
    let d = light.direction;
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    f.light_direction = d.map(|c| (c / len) as f32);
    let c = light
        .color
        .unwrap_or_else(|| panic!("scene {}: no `light.color` in the metadata", meta.name));
    f.light_color = c.map(|c| c as f32);
    if features.directional_lights == 0 {
        f.light_color = [0.0; 3];
    }
    (e, f)
}

/// A mesh of a scene, read from the file its `meshes` entry names: `path`
/// relative to the scene's folder `scene_dir` first, else to the library
/// root `root`; `file` relative to the scene's folder
/// (docs/engine-interface.md).
pub fn scene_mesh(
    root: &Path,
    scene_dir: &Path,
    meta: &SceneMetadata,
    name: &str,
) -> Result<super::data::Mesh, String> {
    let entry = meta
        .meshes
        .get(name)
        .ok_or_else(|| format!("no `meshes.{name}` in scene {}", meta.name))?;
    if entry.format != "weft_mesh_v1" {
        return Err(format!("mesh `{name}`: unknown format `{}`", entry.format));
    }
    let path = match (&entry.path, &entry.file) {
        (Some(p), None) if scene_dir.join(p).is_file() => scene_dir.join(p),
        (Some(p), None) => root.join(p),
        (None, Some(f)) => scene_dir.join(f),
        _ => {
            return Err(format!(
                "mesh `{name}`: not exactly one of `path` and `file`"
            ));
        }
    };
    let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let m = weft_meta::mesh::MeshData::from_bytes(&bytes)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(super::data::Mesh {
        positions: m.positions,
        normals: m.normals,
        tangents: m.tangents,
        uv0: m.uv0,
        uv1: m.uv1,
        colors: m.colors,
        indices: m.indices,
    })
}

/// An instance's `transform.model` as columns.
pub fn instance_model(inst: &SceneInstance) -> super::data::Mat4 {
    let m = &inst.transform.model;
    std::array::from_fn(|c| std::array::from_fn(|r| m[4 * c + r]))
}

/// (instance, pass) pairs in a scene's draw order: by pass queue, then
/// instance order, then the instance's pass order.
pub fn scene_order(meta: &SceneMetadata) -> Vec<(usize, usize)> {
    let mut order: Vec<(i64, usize, usize)> = meta
        .instances
        .iter()
        .enumerate()
        .flat_map(|(i, inst)| {
            inst.passes
                .iter()
                .enumerate()
                .map(move |(p, pass)| (pass.render_state.queue, i, p))
        })
        .collect();
    order.sort_by_key(|&(q, i, p)| (q, i, p));
    order.into_iter().map(|(_, i, p)| (i, p)).collect()
}
