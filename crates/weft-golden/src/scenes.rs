//! Scene goldens and previews: every shipped scene (`scenes/*.scene.toml`),
//! as a project build writes it (`generated/scenes/<scene>/<scene>.scene.json`),
//! drawn whole from its metadata and files alone under the sky of the
//! material goldens.
//!
//! Shared by the scene tests (`tests/rendering/scenes.rs`), `cargo xtask bless` (which
//! writes `tests/goldens/scenes/<scene>.png`) and `cargo xtask gallery`.

use std::path::{Path, PathBuf};
use weft_render::{
    Background, EnvironmentMaps, HdrImage, Luts, PreviewOptions, RenderOptions, Renderer,
    SceneFile, SceneShaders,
};

/// Size of a scene golden: the shipped scenes are laid out wider than tall.
pub const SCENE_GOLDEN_SIZE: (u32, u32) = (256, 192);
/// Largest FLIP mean (over object pixels, [`crate::shading::image_error`])
/// between a scene drawn with its specialised shaders and with the generic
/// library variants: folding must not change the picture.
pub const FOLD_FLIP_MEAN_THRESHOLD: f64 = 0.005;

/// The names of the scene manifests in `<root>/scenes`, sorted.
pub fn shipped_scenes(root: &Path) -> Result<Vec<String>, String> {
    let dir = root.join("scenes");
    let paths = weft_compiler::scene::discover_scenes(&dir)
        .map_err(|e| format!("cannot read {}: {e}", dir.display()))?;
    Ok(paths
        .iter()
        .filter_map(|p| {
            let file = p.file_name()?.to_str()?;
            file.strip_suffix(".scene.toml").map(str::to_string)
        })
        .collect())
}

/// Where a project build puts a scene's metadata: `<generated>/scenes/<name>/<name>.scene.json`.
pub fn built_scene_path(generated: &Path, name: &str) -> PathBuf {
    generated
        .join(weft_compiler::scene::SCENES_OUTPUT_DIR)
        .join(name)
        .join(format!("{name}.scene.json"))
}

/// Where a scene's golden lives: `<goldens>/scenes/<name>.png`.
pub fn scene_golden_path(goldens: &Path, name: &str) -> PathBuf {
    goldens.join("scenes").join(format!("{name}.png"))
}

/// One renderer (one device, the golden sky) reused for every scene draw.
pub struct SceneHarness {
    renderer: Renderer,
}

impl SceneHarness {
    /// The LUTs of `generated/` and the sky of the material goldens (its sun
    /// where a scene's light is). Fails (never skips) without a Vulkan adapter.
    pub fn new(generated: &Path) -> weft_render::Result<SceneHarness> {
        let gpu = weft_render::Gpu::new()?;
        let luts = Luts::load_dir(generated)?;
        let env = EnvironmentMaps::sky(&PreviewOptions::default().sky_params());
        Ok(SceneHarness {
            renderer: Renderer::new(gpu, &env, &luts)?,
        })
    }

    pub fn adapter(&self) -> String {
        self.renderer.gpu().describe()
    }

    /// The renderer, for checks on what it creates.
    pub fn renderer(&mut self) -> &mut Renderer {
        &mut self.renderer
    }

    /// Prepares and draws `scene` with `shaders` at `width`x`height` (WGSL,
    /// linear HDR).
    pub fn render(
        &mut self,
        scene: &SceneFile,
        shaders: &SceneShaders,
        (width, height): (u32, u32),
        background: Background,
    ) -> weft_render::Result<HdrImage> {
        let options = render_options((width, height), background);
        let prepared = self.renderer.prepare_scene(scene, shaders, &options)?;
        self.renderer.render_scene(&prepared, &options)
    }
}

/// The options scene goldens are drawn with: `render_scene_preview`'s, at this size.
pub fn render_options((width, height): (u32, u32), background: Background) -> RenderOptions {
    RenderOptions {
        width,
        height,
        background,
        ..PreviewOptions::default().render_options()
    }
}

/// A scene's golden image: its specialised shaders over the sky, tone mapped
/// like the material goldens (sRGB8 RGBA, [`SCENE_GOLDEN_SIZE`]).
pub fn render_golden(h: &mut SceneHarness, scene: &SceneFile) -> weft_render::Result<Vec<u8>> {
    let image = h.render(
        scene,
        &SceneShaders::Specialised,
        SCENE_GOLDEN_SIZE,
        Background::Sky { mip: 0.0 },
    )?;
    Ok(crate::to_ldr(&image))
}
