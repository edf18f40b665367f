//! The renderer's pipeline cache: each variant's pipelines built once per
//! colour format and language (`pipelines.rs` builds them), and the sky's.

use super::Renderer;
use crate::error::Result;
use crate::pipelines::{ShaderInput, VariantPipelines, build_pipelines, build_sky_pipeline};
use crate::targets::ColorFormat;
use std::sync::Arc;
use weft_meta::Pass;

impl Renderer {
    /// The pipelines of `input` for `passes` (in that order), from the cache
    /// or built now (counted in [`Renderer::pipelines_created`]).
    pub(crate) fn variant_pipelines(
        &mut self,
        input: &ShaderInput,
        passes: &[Pass],
        format: ColorFormat,
    ) -> Result<Arc<VariantPipelines>> {
        let states: Vec<_> = passes
            .iter()
            .map(|p| {
                (
                    &p.name,
                    &p.vertex_entry,
                    &p.fragment_entry,
                    &p.primitive,
                    &p.color_targets,
                    &p.depth_stencil,
                )
            })
            .collect();
        let key = format!(
            "{}|{:?}|{}|{}|{:?}|{:?}|{:?}|{:?}",
            input.cache_id,
            input.language(),
            input.f32_fallback,
            input.uniforms_as_storage,
            format,
            input.constants,
            input.spirv_file,
            states
        );
        if let Some(p) = self.cache.get(&key) {
            return Ok(p.clone());
        }
        let p = Arc::new(build_pipelines(&self.gpu, input, passes, format)?);
        self.pipelines_created += p.passes.len() as u64;
        self.cache.insert(key, p.clone());
        Ok(p)
    }

    /// Builds the sky pipeline for `format` unless it exists.
    pub(crate) fn ensure_sky_pipeline(&mut self, format: ColorFormat) -> Result<()> {
        if !self.sky_pipelines.contains_key(&format) {
            let p = build_sky_pipeline(&self.gpu, &self.sky_layout, &self.sky_module, format)?;
            self.pipelines_created += 1;
            self.sky_pipelines.insert(format, p);
        }
        Ok(())
    }
}
