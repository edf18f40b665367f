//! Every compiled shader of a build: the canonical variants of its materials
//! and the specialised shaders of its scenes (`scenes/<scene>/<scene>.scene.json`
//! among the files of a project build), each with the folder its files are
//! listed relative to and the passes drawn with it. Shared by the test
//! binaries through `weft_tests::shaders`.

use std::collections::BTreeMap;
use weft_meta::scene::SceneMetadata;
use weft_meta::{MaterialMetadata, Pass, VariantShader};

/// One compiled shader of a build.
pub struct ShaderRef<'a> {
    /// The folder of its metadata in the build's files: `<material>` or `scenes/<scene>`.
    pub dir: String,
    /// `<material> variant <id>` or `scene <scene> shader <id>`, for messages.
    pub label: String,
    pub shader: &'a VariantShader,
    /// The passes drawn with it; for a scene shader, those of the instances
    /// that use it, each distinct pass once.
    pub passes: Vec<&'a Pass>,
    /// The material of a library variant (its keywords give the values of
    /// its pipeline constants); None for a scene shader.
    pub material: Option<&'a MaterialMetadata>,
}

impl ShaderRef<'_> {
    /// A file of this shader, as the build's files name it.
    pub fn file(&self, path: &str) -> String {
        format!("{}/{path}", self.dir)
    }
}

/// The scene metadata among a build's files, sorted by scene name.
pub fn scenes(files: &BTreeMap<String, Vec<u8>>) -> Vec<SceneMetadata> {
    files
        .iter()
        .filter(|(name, _)| name.starts_with("scenes/") && name.ends_with(".scene.json"))
        .map(|(name, bytes)| {
            serde_json::from_slice(bytes)
                .unwrap_or_else(|e| panic!("{name} is not scene metadata: {e}"))
        })
        .collect()
}

/// Every canonical variant of `materials`, then every shader of `scenes`.
pub fn shaders<'a>(
    materials: &'a [MaterialMetadata],
    scenes: &'a [SceneMetadata],
) -> Vec<ShaderRef<'a>> {
    let mut out = Vec::new();
    for m in materials {
        for v in &m.variants {
            let Some(shader) = &v.shader else { continue };
            out.push(ShaderRef {
                dir: m.name.clone(),
                label: format!("{} variant {}", m.name, v.id),
                shader,
                // The variant's own passes (`Variant::passes`).
                passes: m
                    .passes
                    .iter()
                    .filter(|p| v.passes.contains(&p.name))
                    .collect(),
                material: Some(m),
            });
        }
    }
    for s in scenes {
        for entry in &s.shaders {
            let mut passes: Vec<&Pass> = Vec::new();
            for inst in s.built_instances().filter(|i| i.shader == entry.id) {
                for p in &inst.passes {
                    if !passes.contains(&p) {
                        passes.push(p);
                    }
                }
            }
            assert!(
                !passes.is_empty(),
                "scene {}: no instance draws shader {}",
                s.name,
                entry.id
            );
            out.push(ShaderRef {
                dir: format!("scenes/{}", s.name),
                label: format!("scene {} shader {}", s.name, entry.id),
                shader: &entry.shader,
                passes,
                material: None,
            });
        }
    }
    out
}
