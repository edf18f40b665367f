//! The pipelines to compile, read from a generated library: every canonical
//! variant × pass of every material (its `f16_files` too), then every
//! scene's specialised shaders × the passes their instances draw. The order
//! is stable: materials and scenes by name, then metadata order.

use crate::error::{Error, Result};
use crate::record::PipelineSource;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use weft_meta::scene::SceneMetadata;
use weft_meta::{MaterialMetadata, Pass, VariantShader};

/// Which pipelines of the library to compile.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Selection {
    /// Only these materials' variants (none: every material).
    #[serde(default)]
    pub materials: Option<Vec<String>>,
    /// Only variants of these tiers (none: every tier).
    #[serde(default)]
    pub tiers: Option<Vec<String>>,
    /// Only these variants, as (material, variant id) (none: every variant):
    /// a scene's generic variants, when only its saving is modelled.
    #[serde(default)]
    pub variants: Option<Vec<(String, String)>>,
    /// Also the scene shaders in `scenes/*/*.scene.json`.
    pub scenes: bool,
}

/// One pipeline to build: a SPIR-V file, the reflection that lays out its
/// bindings and vertex inputs, and the pass that gives its state.
#[derive(Clone, Debug)]
pub struct Job {
    /// Where the shader comes from.
    pub source: PipelineSource,
    /// The pass.
    pub pass: Pass,
    /// Bindings, vertex inputs and entry points.
    pub shader: VariantShader,
    /// The SPIR-V file.
    pub spirv_path: PathBuf,
}

/// The jobs of the library under `generated` (the folder `weft build` writes).
pub fn library_jobs(generated: &Path, sel: &Selection) -> Result<Vec<Job>> {
    let mut jobs = Vec::new();
    for name in sorted_dirs(generated)? {
        let meta_path = generated.join(&name).join(format!("{name}.meta.json"));
        if !meta_path.is_file() {
            continue; // scenes/, reports/, luts/ …
        }
        if sel.materials.as_ref().is_some_and(|m| !m.contains(&name)) {
            continue;
        }
        let meta: MaterialMetadata = read_json(&meta_path)?;
        material_jobs(generated, &name, &meta, sel, &mut jobs)?;
    }
    if let Some(m) = &sel.materials {
        for wanted in m {
            if !jobs.iter().any(|j| &j.source.material == wanted) {
                return Err(Error::Input(format!(
                    "no material `{wanted}` with variants in {} (run `weft build` first?)",
                    generated.display()
                )));
            }
        }
    }
    if sel.scenes {
        let scenes = generated.join("scenes");
        if scenes.is_dir() {
            for name in sorted_dirs(&scenes)? {
                let path = scenes.join(&name).join(format!("{name}.scene.json"));
                if path.is_file() {
                    scene_jobs(generated, &name, &read_json(&path)?, &mut jobs)?;
                }
            }
        }
    }
    Ok(jobs)
}

fn material_jobs(
    generated: &Path,
    name: &str,
    meta: &MaterialMetadata,
    sel: &Selection,
    jobs: &mut Vec<Job>,
) -> Result<()> {
    // A selected alias (a scene's generic variant may be one) selects the
    // variant whose files it shares, which `pairing` pairs it with.
    let selected: Option<Vec<&str>> = sel.variants.as_ref().map(|v| {
        v.iter()
            .filter(|(m, _)| m == name)
            .map(|(_, id)| {
                meta.resolve_variant(id)
                    .map_or(id.as_str(), |c| c.id.as_str())
            })
            .collect()
    });
    for variant in &meta.variants {
        // An alias shares its target's files: compiling it again would repeat a row.
        let Some(shader) = variant
            .shader
            .as_ref()
            .filter(|_| variant.alias_of.is_none())
        else {
            continue;
        };
        if sel
            .tiers
            .as_ref()
            .is_some_and(|t| !t.contains(&variant.tier))
            || selected
                .as_ref()
                .is_some_and(|ids| !ids.contains(&variant.id.as_str()))
        {
            continue;
        }
        for (precision, files) in [("f32", &shader.files), ("f16", &shader.f16_files)] {
            for file in files.get("spirv").into_iter().flatten() {
                for pass in meta.variant_passes(variant) {
                    jobs.push(Job {
                        source: PipelineSource {
                            kind: "material".into(),
                            material: name.into(),
                            variant: variant.id.clone(),
                            tier: variant.tier.clone(),
                            precision: precision.into(),
                            scene: None,
                            shader: None,
                            spirv: format!("{name}/{}", file.path),
                        },
                        pass: pass.clone(),
                        shader: shader.clone(),
                        spirv_path: generated.join(name).join(&file.path),
                    });
                }
            }
        }
    }
    Ok(())
}

fn scene_jobs(
    generated: &Path,
    scene_name: &str,
    scene: &SceneMetadata,
    jobs: &mut Vec<Job>,
) -> Result<()> {
    for s in &scene.shaders {
        // Instances that share a shader share its static keywords, hence its passes.
        let instance = scene
            .built_instances()
            .find(|i| i.shader == s.id)
            .ok_or_else(|| {
                Error::Input(format!(
                    "scene `{scene_name}`: no instance draws shader `{}`",
                    s.id
                ))
            })?;
        for file in s.shader.files.get("spirv").into_iter().flatten() {
            for pass in &instance.passes {
                jobs.push(Job {
                    source: PipelineSource {
                        kind: "scene".into(),
                        material: s.material.clone(),
                        variant: s.variant.clone(),
                        tier: instance.tier.clone(),
                        precision: "f32".into(),
                        scene: Some(scene_name.into()),
                        shader: Some(s.id.clone()),
                        spirv: format!("scenes/{scene_name}/{}", file.path),
                    },
                    pass: pass.clone(),
                    shader: s.shader.clone(),
                    spirv_path: generated.join("scenes").join(scene_name).join(&file.path),
                });
            }
        }
    }
    Ok(())
}

fn sorted_dirs(dir: &Path) -> Result<Vec<String>> {
    let entries = std::fs::read_dir(dir)
        .map_err(|e| Error::Input(format!("{}: {e} (run `weft build` first?)", dir.display())))?;
    let mut names: Vec<String> = entries
        .filter_map(|e| e.ok())
        .filter(|e| e.path().is_dir())
        .filter_map(|e| e.file_name().into_string().ok())
        .collect();
    names.sort();
    Ok(names)
}

fn read_json<T: serde::de::DeserializeOwned>(path: &Path) -> Result<T> {
    let bytes =
        std::fs::read(path).map_err(|e| Error::Input(format!("{}: {e}", path.display())))?;
    serde_json::from_slice(&bytes).map_err(|e| Error::Input(format!("{}: {e}", path.display())))
}

/// Reads a SPIR-V file as words, checking its size and magic number.
pub fn read_spirv(path: &Path) -> Result<Vec<u32>> {
    let bytes =
        std::fs::read(path).map_err(|e| Error::Input(format!("{}: {e}", path.display())))?;
    if bytes.len() % 4 != 0 || bytes.len() < 20 {
        return Err(Error::Input(format!(
            "{}: not SPIR-V ({} bytes)",
            path.display(),
            bytes.len()
        )));
    }
    let words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    if words[0] != 0x0723_0203 {
        return Err(Error::Input(format!(
            "{}: not SPIR-V (magic {:#010x})",
            path.display(),
            words[0]
        )));
    }
    Ok(words)
}
