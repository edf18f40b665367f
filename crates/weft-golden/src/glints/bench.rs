//! The checks drawn on lavapipe: energy, extremes, half-pixel pan,
//! distance and cost, each a method of [`GlintBench`]; [`measure`] runs them all.

use super::images::{downsample, energy, far, object_mean, options, redrawn, shift_camera};
use super::*;
use crate::shading::{image_error, quantile};
use std::path::{Path, PathBuf};
use weft_render::{
    Background, EnvironmentMaps, HdrImage, Luts, Material, PreviewOptions, RenderOptions, Renderer,
    Scene, SceneKind, TimingOptions, math,
};

/// A renderer on the glitter material of a generated/ folder.
pub struct GlintBench {
    renderer: Renderer,
    meta_path: PathBuf,
}

impl GlintBench {
    /// Fails when no Vulkan adapter exists or generated/ lacks glitter.
    pub fn new(generated: &Path) -> Result<GlintBench, String> {
        let meta_path = generated
            .join(MATERIAL)
            .join(format!("{MATERIAL}.meta.json"));
        if !meta_path.is_file() {
            return Err(format!("{}: no such file", meta_path.display()));
        }
        let e = |e: weft_render::Error| e.to_string();
        let luts = Luts::load_dir(generated).map_err(e)?;
        let gpu = weft_render::Gpu::new()
            .map_err(|e| format!("the glint checks need a Vulkan adapter: {e}"))?;
        let env = EnvironmentMaps::sky(&PreviewOptions::default().sky_params());
        Ok(GlintBench {
            renderer: Renderer::new(gpu, &env, &luts).map_err(e)?,
            meta_path,
        })
    }

    pub fn adapter(&self) -> String {
        self.renderer.gpu().describe()
    }

    fn material(&self, tier: &str, values: &[(&str, &str)]) -> Result<Material, String> {
        let mut m = Material::load(&self.meta_path).map_err(|e| e.to_string())?;
        m.set_tier(tier).map_err(|e| format!("tier {tier}: {e}"))?;
        for (name, value) in values {
            m.set_from_str(name, value)
                .map_err(|e| format!("{name} = {value}: {e}"))?;
        }
        Ok(m)
    }

    fn render(&mut self, m: &Material, scene: &Scene, size: u32) -> Result<HdrImage, String> {
        self.renderer
            .render(m, scene, &options(size))
            .map_err(|e| e.to_string())
    }

    /// Glints only: the render minus the same render with the flakes off
    /// (the flakes are added on top of the base, so the difference is exact).
    fn glint_energy(
        &mut self,
        tier: &str,
        values: &[(&str, &str)],
        scene: &Scene,
    ) -> Result<f64, String> {
        let with = self.render(&self.material(tier, values)?, scene, ENERGY_SIZE)?;
        let mut off: Vec<(&str, &str)> = values.to_vec();
        off.push(("flake_intensity", "0"));
        let without = self.render(&self.material(tier, &off)?, scene, ENERGY_SIZE)?;
        Ok(energy(&with) - energy(&without))
    }

    /// [`ENERGY_CASES`] on the sphere and the cloth, per sparkle tier.
    pub fn energy(&mut self) -> Result<Vec<EnergyRow>, String> {
        let mut rows = Vec::new();
        for kind in [SceneKind::Sphere, SceneKind::Cloth] {
            let scene = Scene::new(kind);
            for (case, extra) in ENERGY_CASES {
                let values: Vec<(&str, &str)> =
                    ENERGY_BASE.iter().chain(extra.iter()).copied().collect();
                let smooth = self.glint_energy(SMOOTH_TIER, &values, &scene)?;
                for tier in SPARKLE_TIERS {
                    rows.push(EnergyRow {
                        scene: kind,
                        case,
                        tier: tier.into(),
                        glints: self.glint_energy(tier, &values, &scene)?,
                        smooth,
                    });
                }
            }
        }
        Ok(rows)
    }

    /// [`EXTREMES`] × a swatch seen edge-on (about 1°) under a grazing
    /// light, the sphere (its silhouette is grazing), the sphere lit from
    /// behind and the cloth × every tier.
    pub fn extremes(&mut self) -> Result<Extremes, String> {
        let mut grazing = Scene::new(SceneKind::Swatch);
        grazing.camera.eye = [0.0, 3.4, 0.06];
        grazing.camera.up = [0.0, 0.0, -1.0];
        grazing.light.direction = math::normalize([0.3, 1.0, 0.01]);
        let mut from_behind = Scene::new(SceneKind::Sphere);
        from_behind.light.direction = math::normalize([0.0, 0.0, -1.0]);
        let scenes = [
            ("grazing swatch", grazing),
            ("sphere", Scene::new(SceneKind::Sphere)),
            ("sphere lit from behind", from_behind),
            ("cloth", Scene::new(SceneKind::Cloth)),
        ];
        let mut rows = Vec::new();
        for (scene_name, scene) in &scenes {
            for (extreme, values) in EXTREMES.iter().enumerate() {
                for tier in [SPARKLE_TIERS[0], SPARKLE_TIERS[1], SMOOTH_TIER] {
                    let img = self.render(&self.material(tier, values)?, scene, EXTREMES_SIZE)?;
                    let bad = img
                        .pixels
                        .iter()
                        .filter(|p| p.iter().any(|c| !c.is_finite() || *c < 0.0 || *c > 65504.0))
                        .count();
                    rows.push(ExtremeRow {
                        scene: scene_name,
                        extreme,
                        tier: tier.into(),
                        bad,
                    });
                }
            }
        }
        let lit = self.material(SPARKLE_TIERS[0], EXTREMES[1])?;
        let grazing_energy = energy(&self.render(&lit, &scenes[0].1, EXTREMES_SIZE)?);
        Ok(Extremes {
            rows,
            grazing_energy,
        })
    }

    /// The half-pixel pan at the defaults on the sphere and the cloth, every
    /// tier, and the anchoring of steady flakes on the sphere.
    pub fn pan(&mut self) -> Result<Pan, String> {
        let mut rows = Vec::new();
        for kind in [SceneKind::Sphere, SceneKind::Cloth] {
            let scene = Scene::new(kind);
            let shifted = shift_camera(&scene, 0.5, PAN_SIZE);
            for tier in [SPARKLE_TIERS[0], SPARKLE_TIERS[1], SMOOTH_TIER] {
                let m = self.material(tier, &[])?;
                let a = self.render(&m, &scene, PAN_SIZE)?;
                let b = self.render(&m, &shifted, PAN_SIZE)?;
                let redrawn = if tier == SMOOTH_TIER {
                    None
                } else {
                    let other = self.render(&redrawn(&m)?, &scene, PAN_SIZE)?;
                    Some(image_error(&a, &other).flip_mean)
                };
                rows.push(PanRow {
                    scene: kind,
                    tier: tier.into(),
                    flip: image_error(&a, &b).flip_mean,
                    mean_change: object_mean(&b) / object_mean(&a) - 1.0,
                    redrawn,
                });
            }
        }
        let scene = Scene::new(SceneKind::Sphere);
        let shifted = shift_camera(&scene, 0.5, PAN_SIZE);
        let steady = self.material(SPARKLE_TIERS[0], &[("twinkle", "0"), ("flake_size", "8")])?;
        let a = self.render(&steady, &scene, PAN_SIZE)?;
        let panned = self.render(&steady, &shifted, PAN_SIZE)?;
        let other = self.render(&redrawn(&steady)?, &scene, PAN_SIZE)?;
        Ok(Pan {
            rows,
            steady_pan: image_error(&a, &panned).flip_mean,
            steady_redrawn: image_error(&a, &other).flip_mean,
        })
    }

    /// The far sphere and cloth, 1x against 4x4 supersampled, every tier
    /// (the smooth tier's figure is the edges' and shading's aliasing alone).
    pub fn distant(&mut self) -> Result<Vec<DistantRow>, String> {
        let mut rows = Vec::new();
        for kind in [SceneKind::Sphere, SceneKind::Cloth] {
            let scene = far(&Scene::new(kind), DISTANCE_FACTOR);
            let aliasing_end = self.distant_flip(
                &self.material(SPARKLE_TIERS[0], &[("flake_size", "1")])?,
                &scene,
            )?;
            for tier in [SPARKLE_TIERS[0], SPARKLE_TIERS[1], SMOOTH_TIER] {
                rows.push(DistantRow {
                    scene: kind,
                    tier: tier.into(),
                    flip: self.distant_flip(&self.material(tier, &[])?, &scene)?,
                    aliasing_end,
                });
            }
        }
        Ok(rows)
    }

    fn distant_flip(&mut self, m: &Material, scene: &Scene) -> Result<f64, String> {
        let direct = self.render(m, scene, DISTANT_SIZE)?;
        let supersampled = downsample(
            &self.render(m, scene, DISTANT_SIZE * SUPERSAMPLING)?,
            SUPERSAMPLING,
        );
        Ok(image_error(&supersampled, &direct).flip_mean)
    }

    /// Median frame time of each tier on a 256² sphere at the defaults;
    /// returns the figures and the timer's name.
    pub fn cost(&mut self, timing: &TimingOptions) -> Result<(Vec<(String, f64)>, String), String> {
        let preview = PreviewOptions {
            scene: SceneKind::Sphere,
            width: PAN_SIZE,
            height: PAN_SIZE,
            ..PreviewOptions::default()
        };
        let scene = preview.scene();
        let render_options = RenderOptions {
            background: Background::Color([0.0; 4]),
            ..preview.render_options()
        };
        let (mut out, mut timer) = (Vec::new(), String::new());
        for tier in [SPARKLE_TIERS[0], SPARKLE_TIERS[1], SMOOTH_TIER] {
            let m = self.material(tier, &[])?;
            let e = |e: weft_render::Error| format!("{tier}: {e}");
            let prepared = self.renderer.prepare(&m, &render_options).map_err(e)?;
            let t = self
                .renderer
                .time_frames(&prepared, &scene, &render_options, timing)
                .map_err(e)?;
            timer = t.timer.name().into();
            out.push((tier.to_string(), quantile(&t.ms, 0.5)));
        }
        Ok((out, timer))
    }

    fn inputs_hash(&self) -> Result<String, String> {
        Ok(Material::load(&self.meta_path)
            .map_err(|e| e.to_string())?
            .metadata()
            .inputs_hash
            .clone())
    }
}

/// Runs every check and times every tier.
pub fn measure(generated: &Path, log: &mut dyn FnMut(&str)) -> Result<GlintReport, String> {
    let mut bench = GlintBench::new(generated)?;
    log("glints: energy");
    let energy = bench.energy()?;
    log("glints: extremes");
    let extremes = bench.extremes()?;
    log("glints: half-pixel pan");
    let pan = bench.pan()?;
    log("glints: distance");
    let distant = bench.distant()?;
    log("glints: cost");
    let timing = TimingOptions {
        warmup: 2,
        frames: 10,
        force_cpu_timer: false,
    };
    let (cost, timer) = bench.cost(&timing)?;
    Ok(GlintReport {
        adapter: bench.adapter(),
        inputs_hash: bench.inputs_hash()?,
        energy,
        extremes,
        pan,
        distant,
        cost,
        timer,
    })
}
