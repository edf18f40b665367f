//! One-call previews: configure a material from textual options (as the
//! `weft preview` command and a gallery take them) and render a built-in
//! scene, or render a whole built scene.

use crate::environment::{EnvironmentMaps, SkyParams};
use crate::error::{Error, Result};
use crate::gpu::Gpu;
use crate::image::HdrImage;
use crate::luts::Luts;
use crate::material::Material;
use crate::math::{self, Vec3};
use crate::renderer::{Background, ColorFormat, RenderOptions, Renderer, ShaderLanguage};
use crate::scene::{Scene, SceneKind};
use crate::scene_draw::{SceneFile, SceneShaders};

/// Material selection and values, applied in this order: preset, variant,
/// tier, keywords, parameter values.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MaterialOptions {
    pub preset: Option<String>,
    pub variant: Option<String>,
    pub tier: Option<String>,
    /// `(keyword, value)` pairs.
    pub keywords: Vec<(String, String)>,
    /// `(parameter, text)` pairs, parsed per the parameter's kind.
    pub sets: Vec<(String, String)>,
    /// `(texture parameter, PNG file)` pairs: the user's own maps, texels
    /// as stored (sRGB when the parameter declares `srgb`).
    pub textures: Vec<(String, std::path::PathBuf)>,
}

impl MaterialOptions {
    pub fn apply(&self, material: &mut Material) -> Result<()> {
        if let Some(p) = &self.preset {
            material.apply_preset(p)?;
        }
        if let Some(v) = &self.variant {
            material.select_variant(v)?;
        }
        if let Some(t) = &self.tier {
            material.set_tier(t)?;
        }
        for (k, v) in &self.keywords {
            material.set_keyword(k, v)?;
        }
        for (name, text) in &self.sets {
            material.set_from_str(name, text)?;
        }
        for (name, path) in &self.textures {
            // The name first: a typo is reported before the file is read.
            material.parameter(name)?;
            let bytes = weft_meta::files::read_regular(path, weft_meta::files::MAX_BINARY_BYTES)
                .map_err(|source| Error::Io {
                    path: path.clone(),
                    source,
                })?;
            let (width, height, data) =
                crate::image::decode_png(&bytes, &format!("{name} ({})", path.display()))?;
            material.set(
                name,
                crate::values::TextureValue::Rgba8 {
                    width,
                    height,
                    data,
                },
            )?;
        }
        // Fail early on a combination that has no compiled variant.
        material.current_variant()?;
        Ok(())
    }
}

/// Scene, light, image size and formats of a preview.
#[derive(Clone, Debug, PartialEq)]
pub struct PreviewOptions {
    pub scene: SceneKind,
    /// A mesh of the user's (glTF) drawn in place of the built-in scene's,
    /// framed whole (`Scene::framing`).
    pub mesh: Option<std::sync::Arc<crate::scene::Mesh>>,
    pub width: u32,
    pub height: u32,
    /// Direction towards the light (and the sky's sun); None: the default.
    pub light_direction: Option<Vec3>,
    pub format: ColorFormat,
    pub language: ShaderLanguage,
    pub sky: SkyParams,
}

impl Default for PreviewOptions {
    fn default() -> Self {
        PreviewOptions {
            scene: SceneKind::Sphere,
            mesh: None,
            width: 256,
            height: 256,
            light_direction: None,
            format: ColorFormat::Rgba16Float,
            language: ShaderLanguage::Wgsl,
            sky: SkyParams::default(),
        }
    }
}

impl PreviewOptions {
    /// The scene with the requested light direction.
    pub fn scene(&self) -> Scene {
        self.lit().0
    }

    /// The sky with its sun where the light is.
    pub fn sky_params(&self) -> SkyParams {
        self.lit().1
    }

    fn lit(&self) -> (Scene, SkyParams) {
        let scene = match &self.mesh {
            Some(mesh) => Scene::framing((**mesh).clone()),
            None => Scene::new(self.scene),
        };
        weft_runtime::lit(scene, self.light_direction, self.sky)
    }

    pub fn render_options(&self) -> RenderOptions {
        RenderOptions {
            width: self.width,
            height: self.height,
            format: self.format,
            language: self.language,
            background: Background::Sky { mip: 0.0 },
            ..RenderOptions::default()
        }
    }
}

/// Renders `material` (already configured) in a fresh renderer with the
/// engine LUTs `luts`. Returns the linear image and the adapter description.
pub fn render_preview(
    material: &Material,
    luts: &Luts,
    options: &PreviewOptions,
) -> Result<(HdrImage, String)> {
    let (mut renderer, adapter) = preview_renderer(luts, options, &options.sky_params())?;
    let image = renderer.render(material, &options.scene(), &options.render_options())?;
    Ok((image, adapter))
}

/// Renders a whole built scene (every instance, `shaders` choosing the
/// specialised or the library shaders) in a fresh renderer, under the sky
/// with its sun where the scene's light is (`options.light_direction`
/// overrides it; `options.scene` is not used). Returns the linear image and
/// the adapter description.
pub fn render_scene_preview(
    scene: &SceneFile,
    shaders: &SceneShaders,
    luts: &Luts,
    options: &PreviewOptions,
) -> Result<(HdrImage, String)> {
    let mut scene = scene.clone();
    if let Some(d) = options.light_direction {
        scene.lighting.light.direction = math::normalize(d);
    }
    let mut sky = options.sky;
    sky.sun_direction = scene.lighting.light.direction;
    let (mut renderer, adapter) = preview_renderer(luts, options, &sky)?;
    let render = options.render_options();
    let prepared = renderer.prepare_scene(&scene, shaders, &render)?;
    let image = renderer.render_scene(&prepared, &render)?;
    Ok((image, adapter))
}

fn preview_renderer(
    luts: &Luts,
    options: &PreviewOptions,
    sky: &SkyParams,
) -> Result<(Renderer, String)> {
    if options.width == 0 || options.height == 0 || options.width > 8192 || options.height > 8192 {
        return Err(Error::InvalidValue {
            name: "size".into(),
            message: format!(
                "{}x{} is not a usable image size",
                options.width, options.height
            ),
        });
    }
    let gpu = Gpu::new()?;
    let adapter = gpu.describe();
    let env = EnvironmentMaps::sky(sky);
    Ok((Renderer::new(gpu, &env, luts)?, adapter))
}
