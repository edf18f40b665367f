//! Which library pipeline a scene pipeline specialises. Identical variants are
//! written once and the others carry `alias_of` (docs/material-format.md), so
//! a scene shader naming an alias is paired with the canonical variant's
//! pipeline: the report's table and the model's summary pair the same way.

use crate::error::{Error, Result};
use crate::record::{FamilyStats, PipelineStats};
use std::collections::BTreeMap;
use std::path::Path;
use weft_meta::MaterialMetadata;

/// Material metadata read once per material, for resolving variant ids.
pub struct GenericVariants<'g> {
    generated: &'g Path,
    metas: BTreeMap<String, MaterialMetadata>,
}

impl<'g> GenericVariants<'g> {
    pub fn new(generated: &'g Path) -> Self {
        Self {
            generated,
            metas: BTreeMap::new(),
        }
    }

    /// The f32 library pipeline, same pass, of the variant `scene` specialises
    /// (its `alias_of` resolved); `None` when the family has none.
    pub fn generic_of<'a>(
        &mut self,
        f: &'a FamilyStats,
        scene: &PipelineStats,
    ) -> Result<Option<&'a PipelineStats>> {
        let s = &scene.source;
        let meta = self.meta(&s.material)?;
        let canonical = meta
            .resolve_variant(&s.variant)
            .map_or(s.variant.as_str(), |v| v.id.as_str());
        Ok(material_pipeline(f, &s.material, canonical, &scene.pass))
    }

    /// The material's metadata, read on first use.
    fn meta(&mut self, material: &str) -> Result<&MaterialMetadata> {
        if !self.metas.contains_key(material) {
            let meta = read_meta(self.generated, material)?;
            self.metas.insert(material.to_string(), meta);
        }
        Ok(&self.metas[material])
    }
}

/// A library variant's f32 pipeline for one pass.
pub fn material_pipeline<'a>(
    f: &'a FamilyStats,
    material: &str,
    variant: &str,
    pass: &str,
) -> Option<&'a PipelineStats> {
    f.pipelines.iter().find(|p| {
        p.source.kind == "material"
            && p.source.material == material
            && p.source.variant == variant
            && p.source.precision == "f32"
            && p.pass == pass
    })
}

/// `generated/<material>/<material>.meta.json`.
pub fn read_meta(generated: &Path, material: &str) -> Result<MaterialMetadata> {
    let path = generated
        .join(material)
        .join(format!("{material}.meta.json"));
    let bytes =
        std::fs::read(&path).map_err(|e| Error::Input(format!("{}: {e}", path.display())))?;
    serde_json::from_slice(&bytes).map_err(|e| Error::Input(format!("{}: {e}", path.display())))
}
