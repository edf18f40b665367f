//! Image tests for weft materials, in the style of wgpu's own: render a fixed
//! set of cases per material on lavapipe from the generated files alone, tone
//! map to sRGB8 and compare with committed goldens using FLIP (`nv-flip`).
//!
//! Shared by the render tests (`tests/rendering/render.rs`), `cargo xtask bless` (which
//! rewrites goldens) and `cargo xtask gallery` (contact sheet + gallery.md).

pub mod bindings;
pub mod cost_tables;
pub mod error_grid;
pub mod film;
pub mod fins;
pub mod floor;
pub mod glints;
pub mod gltf_samples;
pub mod pareto;
pub mod project;
pub mod scene_bench;
pub mod scenes;
pub mod shading;
pub mod shells;
pub mod silhouette;
pub mod textures;

use std::path::{Path, PathBuf};
use weft_meta::{KeywordMode, MaterialMetadata};
use weft_render::{
    EnvironmentMaps, HdrImage, Luts, Material, MaterialOptions, PreviewOptions, RenderOptions,
    Renderer, SceneKind, ShaderLanguage,
};

/// Goldens are small: enough to see every lobe, cheap on 2 cores.
pub const GOLDEN_SIZE: u32 = 96;
/// Tone mapping of goldens and gallery images, and the sRGB8 pixels a
/// golden holds: the `auto` chooser's, so goldens, benches and the chooser
/// compare alike.
pub use weft_auto::{TONEMAP, to_ldr};
/// A case passes when the FLIP mean against its golden is at most this.
/// lavapipe renders bit-identically run to run; the margin absorbs LLVM/CPU
/// differences between machines. The perturbation test shows a wrong sign,
/// a missing 1/pi or swapped channels all land far above it.
pub const FLIP_MEAN_THRESHOLD: f32 = 0.01;

/// One render of one material.
#[derive(Clone, Debug, PartialEq)]
pub struct Case {
    pub material: String,
    /// File stem of the golden, unique within the material.
    pub name: String,
    pub options: MaterialOptions,
    pub scene: SceneKind,
}

/// The cases of a material: its default variant on the sphere and the cloth
/// patch, every non-default tier, every non-default value of every keyword
/// (others at their defaults), and every preset.
pub fn cases(meta: &MaterialMetadata) -> Vec<Case> {
    let case = |name: String, options: MaterialOptions, scene: SceneKind| Case {
        material: meta.name.clone(),
        name,
        options,
        scene,
    };
    let mut out = vec![
        case(
            "default".into(),
            MaterialOptions::default(),
            SceneKind::Sphere,
        ),
        case(
            "default.cloth".into(),
            MaterialOptions::default(),
            SceneKind::Cloth,
        ),
    ];
    for tier in meta
        .tiers
        .values
        .iter()
        .filter(|t| **t != meta.tiers.default)
    {
        let options = MaterialOptions {
            tier: Some(tier.clone()),
            ..Default::default()
        };
        out.push(case(
            format!("tier-{tier}"),
            options.clone(),
            SceneKind::Sphere,
        ));
        out.push(case(
            format!("tier-{tier}.cloth"),
            options,
            SceneKind::Cloth,
        ));
    }
    for k in &meta.keywords {
        for v in k.values.iter().filter(|v| **v != k.default) {
            let options = MaterialOptions {
                keywords: vec![(k.name.clone(), v.clone())],
                tier: keyword_case_tier(meta, &k.name, v),
                ..Default::default()
            };
            let mode = if k.mode == KeywordMode::Constant {
                "const-"
            } else {
                ""
            };
            out.push(case(
                format!("{mode}{}-{v}", k.name.to_lowercase()),
                options,
                SceneKind::Sphere,
            ));
        }
    }
    for p in &meta.presets {
        let options = MaterialOptions {
            preset: Some(p.name.clone()),
            ..Default::default()
        };
        out.push(case(
            format!("preset-{}", p.name),
            options,
            SceneKind::Sphere,
        ));
    }
    out
}

/// The tier a keyword value's case is drawn at: the default tier (`None`)
/// unless the material's `exclude` removes that combination (eye's
/// `MATCAP_MAP` exists only in its `seed` tier), then the first tier in
/// declaration order that has it, the other keywords at their defaults.
fn keyword_case_tier(meta: &MaterialMetadata, keyword: &str, value: &str) -> Option<String> {
    let has = |tier: &str| {
        meta.variants.iter().any(|variant| {
            variant.tier == tier
                && meta.keywords.iter().all(|k| {
                    let want = if k.name == keyword {
                        value
                    } else {
                        k.default.as_str()
                    };
                    variant.keywords.get(&k.name).map(String::as_str) == Some(want)
                })
        })
    };
    if has(&meta.tiers.default) {
        return None;
    }
    meta.tiers.values.iter().find(|t| has(t)).cloned()
}

/// Every `<generated>/<name>/<name>.meta.json`, sorted by name.
pub fn materials(generated: &Path) -> Result<Vec<(PathBuf, MaterialMetadata)>, String> {
    let mut out = Vec::new();
    let entries = std::fs::read_dir(generated)
        .map_err(|e| format!("cannot read {}: {e}", generated.display()))?;
    for entry in entries {
        let dir = entry.map_err(|e| e.to_string())?.path();
        let Some(name) = dir.file_name().map(|n| n.to_string_lossy().into_owned()) else {
            continue;
        };
        let meta_path = dir.join(format!("{name}.meta.json"));
        if !meta_path.is_file() {
            continue;
        }
        let bytes =
            std::fs::read(&meta_path).map_err(|e| format!("{}: {e}", meta_path.display()))?;
        let meta: MaterialMetadata =
            serde_json::from_slice(&bytes).map_err(|e| format!("{}: {e}", meta_path.display()))?;
        out.push((meta_path, meta));
    }
    out.sort_by(|a, b| a.1.name.cmp(&b.1.name));
    Ok(out)
}

/// One renderer (one device, one environment) reused for every case.
pub struct Harness {
    renderer: Renderer,
}

impl Harness {
    /// Fails (never skips) when no Vulkan adapter exists: the error says to
    /// install lavapipe (`mesa-vulkan-drivers`).
    pub fn new(generated: &Path) -> weft_render::Result<Harness> {
        let gpu = weft_render::Gpu::new()?;
        let luts = Luts::load_dir(generated)?;
        let env = EnvironmentMaps::sky(&PreviewOptions::default().sky_params());
        Ok(Harness {
            renderer: Renderer::new(gpu, &env, &luts)?,
        })
    }

    pub fn adapter(&self) -> String {
        self.renderer.gpu().describe()
    }

    /// Renders a case from `<meta dir>` at `size`x`size` in `language`.
    pub fn render(
        &mut self,
        meta_path: &Path,
        case: &Case,
        size: u32,
        language: ShaderLanguage,
    ) -> weft_render::Result<HdrImage> {
        self.render_edited(meta_path, case, size, language, |_, _| Ok(()))
    }

    /// [`Harness::render`] with the case's material and scene changed by
    /// `edit` first (another mesh or tangents, a texture the case leaves
    /// unset).
    pub fn render_edited(
        &mut self,
        meta_path: &Path,
        case: &Case,
        size: u32,
        language: ShaderLanguage,
        edit: impl FnOnce(&mut Material, &mut weft_render::Scene) -> weft_render::Result<()>,
    ) -> weft_render::Result<HdrImage> {
        let mut material = Material::load(meta_path)?;
        case.options.apply(&mut material)?;
        let preview = PreviewOptions {
            scene: case.scene,
            ..Default::default()
        };
        let options = RenderOptions {
            width: size,
            height: size,
            language,
            ..preview.render_options()
        };
        let mut scene = preview.scene();
        edit(&mut material, &mut scene)?;
        self.renderer.render(&material, &scene, &options)
    }
}

/// Where a case's golden lives: `<goldens>/<material>/<case>.png`.
pub fn golden_path(goldens: &Path, case: &Case) -> PathBuf {
    goldens
        .join(&case.material)
        .join(format!("{}.png", case.name))
}

/// FLIP between two sRGB8 RGBA images of the same size.
pub struct FlipResult {
    pub mean: f32,
    pub p99: f32,
    /// The error map coloured with FLIP's magma LUT, RGB8.
    pub error_map_rgb: Vec<u8>,
}

fn rgb(rgba: &[u8]) -> Vec<u8> {
    rgba.chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect()
}

pub fn flip(reference_rgba: &[u8], test_rgba: &[u8], width: u32, height: u32) -> FlipResult {
    let reference = nv_flip::FlipImageRgb8::with_data(width, height, &rgb(reference_rgba));
    let test = nv_flip::FlipImageRgb8::with_data(width, height, &rgb(test_rgba));
    let error = nv_flip::flip(reference, test, nv_flip::DEFAULT_PIXELS_PER_DEGREE);
    let mut pool = nv_flip::FlipPool::from_image(&error);
    let mean = pool.mean();
    let p99 = pool.get_percentile(0.99, true);
    let error_map_rgb = error.apply_color_lut(&nv_flip::magma_lut()).to_vec();
    FlipResult {
        mean,
        p99,
        error_map_rgb,
    }
}

/// Decodes a PNG (as written by `weft_render::encode_png`) into RGBA8.
pub fn read_png(path: &Path) -> Result<(u32, u32, Vec<u8>), String> {
    let bytes = std::fs::read(path).map_err(|e| format!("{}: {e}", path.display()))?;
    weft_render::decode_png(&bytes, &path.display().to_string()).map_err(|e| e.to_string())
}

pub fn write_png(path: &Path, width: u32, height: u32, rgba: &[u8]) -> Result<(), String> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| e.to_string())?;
    }
    let bytes = weft_render::encode_png(width, height, rgba).map_err(|e| e.to_string())?;
    std::fs::write(path, bytes).map_err(|e| format!("{}: {e}", path.display()))
}

/// Tiles equally sized RGBA images into a sheet `columns` wide, with a gap.
pub fn contact_sheet(tiles: &[Vec<u8>], tile: u32, columns: u32) -> (u32, u32, Vec<u8>) {
    let gap = 4;
    let rows = (tiles.len() as u32).div_ceil(columns.max(1));
    let (w, h) = (columns * (tile + gap) + gap, rows * (tile + gap) + gap);
    let mut sheet = vec![0u8; (w * h * 4) as usize];
    for px in sheet.chunks_exact_mut(4) {
        px.copy_from_slice(&[24, 24, 28, 255]);
    }
    for (i, t) in tiles.iter().enumerate() {
        let (cx, cy) = (i as u32 % columns, i as u32 / columns);
        let (x0, y0) = (gap + cx * (tile + gap), gap + cy * (tile + gap));
        for y in 0..tile {
            let src = (y * tile * 4) as usize;
            let dst = (((y0 + y) * w + x0) * 4) as usize;
            sheet[dst..dst + (tile * 4) as usize]
                .copy_from_slice(&t[src..src + (tile * 4) as usize]);
        }
    }
    (w, h, sheet)
}
