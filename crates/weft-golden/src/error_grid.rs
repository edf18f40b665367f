//! A tier's error over the space a user works in, not at one point: every
//! preset and the material's defaults × sphere and cloth × three light
//! directions (a key light, a side light and a grazing rim light from
//! behind), each cell rendered in the reference tier and in the tier under
//! test with the same keywords and values, compared by FLIP over object
//! pixels ([`weft_auto::image_error::image_error`]). A tier's figures are the worst
//! cell and the mean over cells.

use std::path::Path;
use weft_meta::MaterialMetadata;
use weft_render::{Background, HdrImage, Material, RenderOptions, Renderer, Scene, SceneKind};

/// A light direction of the grid (towards the light; the camera looks from +z).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GridLight {
    pub name: &'static str,
    pub direction: [f32; 3],
}

/// Key (the previews' light), side (90° from the view) and a grazing rim
/// light from behind the object, where sheen and retro-reflection differ most.
pub const LIGHTS: [GridLight; 3] = [
    GridLight {
        name: "key",
        direction: [-0.62, 0.55, 0.56],
    },
    GridLight {
        name: "side",
        direction: [1.0, 0.25, 0.0],
    },
    GridLight {
        name: "rim",
        direction: [0.3, 0.35, -0.89],
    },
];

/// What the grid covers.
#[derive(Clone, Debug, PartialEq)]
pub struct GridOptions {
    /// Square image size in pixels.
    pub size: u32,
    pub scenes: Vec<SceneKind>,
    pub lights: Vec<GridLight>,
    /// Include every preset (the defaults are always a row).
    pub presets: bool,
}

impl Default for GridOptions {
    fn default() -> Self {
        GridOptions {
            size: 160,
            scenes: vec![SceneKind::Sphere, SceneKind::Cloth],
            lights: LIGHTS.to_vec(),
            presets: true,
        }
    }
}

/// One tier's error over the grid.
#[derive(Clone, Debug, PartialEq)]
pub struct TierGridError {
    pub tier: String,
    /// FLIP mean of the worst cell.
    pub worst: f64,
    /// Mean over the cells.
    pub mean: f64,
    /// `preset/scene/light` of the worst cell (`defaults` for no preset).
    pub worst_cell: String,
    pub cells: u32,
    /// Every cell: `preset/scene/light` and its FLIP mean.
    pub per_cell: Vec<(String, f64)>,
}

/// Every non-reference tier of the material at `meta_path`, measured over
/// the grid. A cell whose keywords (from a preset) have no variant in some
/// tier is skipped for that tier.
pub fn tier_errors(
    renderer: &mut Renderer,
    meta_path: &Path,
    meta: &MaterialMetadata,
    options: &GridOptions,
) -> Result<Vec<TierGridError>, String> {
    let reference = &meta.tiers.reference;
    let tiers: Vec<&String> = meta
        .tiers
        .values
        .iter()
        .filter(|t| *t != reference)
        .collect();
    let mut presets: Vec<Option<&str>> = vec![None];
    if options.presets {
        presets.extend(meta.presets.iter().map(|p| Some(p.name.as_str())));
    }
    let render_options = RenderOptions {
        width: options.size,
        height: options.size,
        background: Background::Color([0.0; 4]),
        ..RenderOptions::default()
    };
    let what = |e: weft_render::Error| format!("{}: {e}", meta.name);
    let mut cells: Vec<Vec<(f64, String)>> = vec![Vec::new(); tiers.len()];
    for preset in &presets {
        let mut base = Material::load(meta_path).map_err(what)?;
        if let Some(p) = preset {
            base.apply_preset(p).map_err(what)?;
        }
        for &kind in &options.scenes {
            for light in &options.lights {
                let mut scene = Scene::new(kind);
                scene.light.direction = light.direction;
                let cell = format!(
                    "{}/{}/{}",
                    preset.unwrap_or("defaults"),
                    kind.name(),
                    light.name
                );
                let render =
                    |renderer: &mut Renderer, tier: &str| -> Option<Result<HdrImage, String>> {
                        let mut m = base.clone();
                        m.set_tier(tier).ok()?;
                        m.current_variant().ok()?;
                        Some(renderer.render(&m, &scene, &render_options).map_err(what))
                    };
                let Some(reference_image) = render(renderer, reference) else {
                    continue;
                };
                let reference_image = reference_image?;
                for (i, tier) in tiers.iter().enumerate() {
                    let Some(image) = render(renderer, tier) else {
                        continue;
                    };
                    let err = weft_auto::image_error::image_error(&reference_image, &image?);
                    cells[i].push((err.flip_mean, cell.clone()));
                }
            }
        }
    }
    Ok(tiers
        .iter()
        .zip(cells)
        .filter(|(_, c)| !c.is_empty())
        .map(|(tier, c)| {
            let (worst, worst_cell) = c
                .iter()
                .max_by(|a, b| a.0.total_cmp(&b.0))
                .cloned()
                .expect("non-empty");
            TierGridError {
                tier: (*tier).clone(),
                worst,
                mean: c.iter().map(|(v, _)| v).sum::<f64>() / c.len() as f64,
                worst_cell,
                cells: c.len() as u32,
                per_cell: c.iter().map(|(v, n)| (n.clone(), *v)).collect(),
            }
        })
        .collect())
}
