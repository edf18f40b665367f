//! What the generated files say without drawing: the library variant each
//! instance's generic draw uses, SPIR-V instruction counts, uniform bytes,
//! and the shaders and files of both ways of shipping the scene.

use super::{FileStats, InstanceBench, SpirvCounts};
use crate::shading::spirv_instruction_counts;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use weft_meta::scene::{SceneInstance, SceneMetadata};
use weft_meta::{MaterialMetadata, ShaderFile, Variant, VariantShader};
use weft_render::SceneFile;

/// Every material the scene uses, from `<generated>/<material>/<material>.meta.json`.
pub(super) fn load_libraries(
    generated: &Path,
    meta: &SceneMetadata,
) -> Result<BTreeMap<String, MaterialMetadata>, String> {
    let mut out = BTreeMap::new();
    for inst in &meta.instances {
        if out.contains_key(&inst.material) {
            continue;
        }
        let path = library_meta_path(generated, &inst.material);
        let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let m: MaterialMetadata =
            serde_json::from_slice(&bytes).map_err(|e| format!("{}: {e}", path.display()))?;
        out.insert(inst.material.clone(), m);
    }
    Ok(out)
}

fn library_meta_path(generated: &Path, material: &str) -> PathBuf {
    generated
        .join(material)
        .join(format!("{material}.meta.json"))
}

/// The canonical library variant an instance's generic draw uses.
fn canonical_variant<'a>(
    m: &'a MaterialMetadata,
    id: &str,
) -> Result<(&'a Variant, &'a VariantShader), String> {
    let find = |id: &str| m.variants.iter().find(|v| v.id == id);
    let v = find(id).ok_or_else(|| format!("material `{}` has no variant `{id}`", m.name))?;
    let canonical = match &v.alias_of {
        Some(target) => find(target).ok_or_else(|| {
            format!(
                "variant `{id}` of `{}` aliases `{target}`, which is missing",
                m.name
            )
        })?,
        None => v,
    };
    let shader = canonical.shader.as_ref().ok_or_else(|| {
        format!(
            "variant `{}` of `{}` has no shader files",
            canonical.id, m.name
        )
    })?;
    Ok((canonical, shader))
}

/// The SPIR-V file of `shader` whose baked constant-mode keywords have the
/// instance's values, counted.
fn spirv_counts(
    dir: &Path,
    shader: &VariantShader,
    keywords: &BTreeMap<String, String>,
) -> Result<SpirvCounts, String> {
    let matches = |f: &&ShaderFile| f.constants.iter().all(|(k, v)| keywords.get(k) == Some(v));
    let file = shader
        .files
        .get("spirv")
        .and_then(|files| files.iter().find(matches))
        .ok_or_else(|| {
            format!(
                "no SPIR-V file for keywords {keywords:?} in {}",
                dir.display()
            )
        })?;
    let path = dir.join(&file.path);
    let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    spirv_instruction_counts(&bytes).map_err(|e| format!("{}: {e}", path.display()))
}

/// The static figures of an instance (timing is added later).
pub(super) fn instance_figures(
    generated: &Path,
    file: &SceneFile,
    inst: &SceneInstance,
    libraries: &BTreeMap<String, MaterialMetadata>,
) -> Result<InstanceBench, String> {
    let m = &libraries[&inst.material];
    let (variant, generic) = canonical_variant(m, &inst.variant)?;
    let scene_shader = file
        .metadata
        .shaders
        .iter()
        .find(|s| s.id == inst.shader)
        .ok_or_else(|| format!("instance `{}` names no shader of the scene", inst.name))?;
    let uniform = |s: &VariantShader| s.material_uniform.as_ref().map_or(0, |u| u.size);
    Ok(InstanceBench {
        name: inst.name.clone(),
        material: inst.material.clone(),
        tier: inst.tier.clone(),
        generic_variant: variant.id.clone(),
        shader: inst.shader.clone(),
        spirv_generic: spirv_counts(&generated.join(&inst.material), generic, &inst.keywords)?,
        spirv_specialised: spirv_counts(&file.dir, &scene_shader.shader, &inst.keywords)?,
        uniform_generic: uniform(generic),
        uniform_specialised: uniform(&scene_shader.shader),
        gpu: None,
        flip: None,
    })
}

fn file_len(path: &Path) -> Result<u64, String> {
    std::fs::metadata(path)
        .map(|m| m.len())
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// The distinct canonical library variants the instances use, all their
/// files (every language), and the materials' metadata.
pub(super) fn generic_file_stats(
    generated: &Path,
    meta: &SceneMetadata,
    libraries: &BTreeMap<String, MaterialMetadata>,
) -> Result<FileStats, String> {
    let mut variants = BTreeSet::new();
    let mut stats = FileStats::default();
    for inst in &meta.instances {
        let (v, shader) = canonical_variant(&libraries[&inst.material], &inst.variant)?;
        if !variants.insert((inst.material.clone(), v.id.clone())) {
            continue;
        }
        for f in shader.all_files() {
            stats.shader_files += 1;
            stats.shader_bytes += file_len(&generated.join(&inst.material).join(&f.path))?;
        }
    }
    stats.shaders = variants.len();
    for material in libraries.keys() {
        stats.metadata_files += 1;
        stats.metadata_bytes += file_len(&library_meta_path(generated, material))?;
    }
    Ok(stats)
}

/// Every file of the built scene's folder.
pub(super) fn scene_file_stats(dir: &Path, meta: &SceneMetadata) -> Result<FileStats, String> {
    let mut stats = FileStats {
        shaders: meta.shaders.len(),
        ..FileStats::default()
    };
    let entries = std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for entry in entries {
        let path = entry.map_err(|e| format!("{}: {e}", dir.display()))?.path();
        let len = file_len(&path)?;
        if path.to_string_lossy().ends_with(".scene.json") {
            stats.metadata_files += 1;
            stats.metadata_bytes += len;
        } else {
            stats.shader_files += 1;
            stats.shader_bytes += len;
        }
    }
    Ok(stats)
}
