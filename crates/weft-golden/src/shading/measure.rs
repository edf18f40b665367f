//! One run: the materials selected, a job per tier (per half-precision
//! tier's f32 files too, and the cost floor), a probe frame to size each
//! job, the timed rounds over every job, then each tier's figures.

use super::spirv::spirv_counts_for;
use super::*;
use crate::error_grid::TierGridError;
use std::time::Instant;
use weft_meta::{F32FilesCost, MaterialMetadata, TierMeasurement};
use weft_render::{
    Background, EnvironmentMaps, HdrImage, Luts, Material, PreparedMaterial, PreviewOptions,
    RenderOptions, Renderer, Scene, TimingOptions,
};

struct Job {
    material: usize,
    tier: String,
    /// A half-precision variant timed from its portable f32 files (its
    /// `f16_files` job is the tier's own).
    f32_files: bool,
    variant: String,
    spirv: (u32, u32),
    prepared: PreparedMaterial,
    /// Timed frames planned after the probe.
    planned: u32,
    ms: Vec<f64>,
    image: Option<HdrImage>,
}

/// Measures every tier of the selected materials under `generated`.
pub fn run(
    generated: &Path,
    options: &ShadingOptions,
    log: &mut dyn FnMut(&str),
) -> Result<ShadingReport, String> {
    let started = Instant::now();
    let measured = measured_materials(generated, options)?;
    let Stage {
        mut renderer,
        adapter,
        scene,
        render_options,
    } = stage(generated, options, log)?;
    let mut jobs = tier_jobs(&mut renderer, &measured, options, &render_options)?;
    // The floor: an unlit fill drawn like every material, as one more job
    // (its material index is past `measured`).
    let floor_dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    if let Some(materials_dir) = &options.floor {
        jobs.push(floor_job(
            &mut renderer,
            materials_dir,
            floor_dir.path(),
            measured.len(),
            &render_options,
        )?);
    }
    let draw = Draw {
        scene: &scene,
        render_options: &render_options,
    };
    let timer = time_jobs(&mut renderer, &mut jobs, &measured, draw, options, log)?;
    let run = Run {
        measured: &measured,
        jobs: &jobs,
        options,
        adapter: &adapter,
        timer,
    };
    let materials = material_measurements(&mut renderer, &run, log)?;
    let floor_ms = jobs
        .iter()
        .find(|j| j.material == measured.len())
        .map(|j| round(quantile(&j.ms, 0.5), 4));
    Ok(ShadingReport {
        adapter,
        timer,
        options: options.clone(),
        materials,
        seconds: started.elapsed().as_secs_f64(),
        floor_ms,
    })
}

/// Whether `options` selects the material (no list: every material).
fn selected(options: &ShadingOptions, m: &MaterialMetadata) -> bool {
    options.materials.is_empty() || options.materials.contains(&m.name)
}

/// The materials under `generated` that `options` selects, and the
/// baseline's, which is measured even when `standard` is not selected.
/// A selected name that is not there is an error.
fn measured_materials(
    generated: &Path,
    options: &ShadingOptions,
) -> Result<Vec<(PathBuf, MaterialMetadata)>, String> {
    let all = crate::materials(generated)?;
    for name in &options.materials {
        if !all.iter().any(|(_, m)| &m.name == name) {
            return Err(format!(
                "no material `{name}` under {} (have: {})",
                generated.display(),
                all.iter()
                    .map(|(_, m)| m.name.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
    }
    let measured: Vec<(PathBuf, MaterialMetadata)> = all
        .into_iter()
        .filter(|(_, m)| selected(options, m) || m.name == BASELINE_MATERIAL)
        .collect();
    if measured.is_empty() {
        return Err(format!("no materials under {}", generated.display()));
    }
    Ok(measured)
}

/// The renderer on the adapter, the scene and the options every frame is
/// drawn with.
struct Stage {
    renderer: Renderer,
    adapter: String,
    scene: Scene,
    render_options: RenderOptions,
}

fn stage(
    generated: &Path,
    options: &ShadingOptions,
    log: &mut dyn FnMut(&str),
) -> Result<Stage, String> {
    let e = |e: weft_render::Error| e.to_string();
    let gpu = weft_render::Gpu::new().map_err(e)?;
    let adapter = gpu.describe();
    log(&format!("adapter: {adapter}"));
    let luts = Luts::load_dir(generated).map_err(e)?;
    let preview = PreviewOptions {
        scene: options.scene,
        width: options.size,
        height: options.size,
        ..PreviewOptions::default()
    };
    let env = EnvironmentMaps::sky(&preview.sky_params());
    let renderer = Renderer::new(gpu, &env, &luts).map_err(e)?;
    let scene = preview.scene();
    let render_options = RenderOptions {
        background: Background::Color([0.0; 4]),
        ..preview.render_options()
    };
    Ok(Stage {
        renderer,
        adapter,
        scene,
        render_options,
    })
}

impl Job {
    /// A job not yet timed.
    fn new(
        material: usize,
        tier: String,
        f32_files: bool,
        variant: String,
        spirv: (u32, u32),
        prepared: PreparedMaterial,
    ) -> Job {
        Job {
            material,
            tier,
            f32_files,
            variant,
            spirv,
            prepared,
            planned: 0,
            ms: Vec::new(),
            image: None,
        }
    }
}

/// A job per tier of every measured material (only the baseline tier of a
/// material measured for the baseline alone), and for a half-precision
/// tier on an adapter with `shader-f16` a second one from its f32 files.
fn tier_jobs(
    renderer: &mut Renderer,
    measured: &[(PathBuf, MaterialMetadata)],
    options: &ShadingOptions,
    render_options: &RenderOptions,
) -> Result<Vec<Job>, String> {
    let mut jobs = Vec::new();
    for (i, (meta_path, meta)) in measured.iter().enumerate() {
        let tiers: Vec<&String> = if selected(options, meta) {
            meta.tiers.values.iter().collect()
        } else {
            meta.tiers
                .values
                .iter()
                .filter(|t| *t == BASELINE_TIER)
                .collect()
        };
        for tier in tiers {
            let what = |err: weft_render::Error| format!("{}/{tier}: {err}", meta.name);
            let mut material = Material::load(meta_path).map_err(what)?;
            material.set_tier(tier).map_err(what)?;
            let prepared = renderer.prepare(&material, render_options).map_err(what)?;
            let spirv = spirv_counts_for(&material)?;
            let half = renderer.gpu().has_shader_f16()
                && material
                    .current_variant()
                    .is_ok_and(|v| !v.shader.f16_files.is_empty());
            let variant = prepared.variant_id().to_string();
            jobs.push(Job::new(
                i,
                tier.clone(),
                false,
                variant.clone(),
                spirv,
                prepared,
            ));
            if half {
                let f32_options = RenderOptions {
                    f32_fallback: true,
                    ..*render_options
                };
                let prepared = renderer.prepare(&material, &f32_options).map_err(what)?;
                jobs.push(Job::new(i, tier.clone(), true, variant, spirv, prepared));
            }
        }
    }
    Ok(jobs)
}

/// The cost floor's job: the unlit fill built from `materials_dir` into
/// `out_dir`, drawn at its only tier as material `index`.
fn floor_job(
    renderer: &mut Renderer,
    materials_dir: &Path,
    out_dir: &Path,
    index: usize,
    render_options: &RenderOptions,
) -> Result<Job, String> {
    let meta_path = crate::floor::build(materials_dir, out_dir)?;
    let what = |err: weft_render::Error| format!("{}: {err}", crate::floor::FLOOR_MATERIAL);
    let material = Material::load(&meta_path).map_err(what)?;
    let prepared = renderer.prepare(&material, render_options).map_err(what)?;
    Ok(Job::new(
        index,
        BASELINE_TIER.into(),
        false,
        prepared.variant_id().to_string(),
        spirv_counts_for(&material)?,
        prepared,
    ))
}

/// The material a job draws, by name (the floor past the measured ones).
fn job_name<'a>(measured: &'a [(PathBuf, MaterialMetadata)], job: &Job) -> &'a str {
    measured
        .get(job.material)
        .map_or(crate::floor::FLOOR_MATERIAL, |m| m.1.name.as_str())
}

/// What every job draws.
#[derive(Clone, Copy)]
struct Draw<'a> {
    scene: &'a Scene,
    render_options: &'a RenderOptions,
}

/// Probes every job (one untimed and one timed frame, to size the run),
/// then takes its planned frames in rounds over all jobs; returns the
/// timer the frames were timed with.
fn time_jobs(
    renderer: &mut Renderer,
    jobs: &mut [Job],
    measured: &[(PathBuf, MaterialMetadata)],
    draw: Draw<'_>,
    options: &ShadingOptions,
    log: &mut dyn FnMut(&str),
) -> Result<FrameTimer, String> {
    let what = |job: &Job, err: weft_render::Error| {
        format!("{}/{}: {err}", job_name(measured, job), job.tier)
    };
    let (scene, render_options) = (draw.scene, draw.render_options);
    // Probe: one untimed and one timed frame per tier, to size the run.
    let mut timer = FrameTimer::GpuTimestamp;
    let rounds = options.rounds.max(1);
    let frames = options.frames.max(1);
    let min_frames = 5.min(frames);
    for job in jobs.iter_mut() {
        let probe = TimingOptions {
            warmup: 1,
            frames: 1,
            force_cpu_timer: options.force_cpu_timer,
        };
        let t = renderer
            .time_frames(&job.prepared, scene, render_options, &probe)
            .map_err(|err| what(job, err))?;
        timer = t.timer;
        let affordable = (options.max_seconds_per_tier * 1e3 / t.ms[0].max(1e-3)).floor();
        job.planned = (affordable.min(f64::from(frames)) as u32).max(min_frames);
        job.ms = t.ms;
        job.image = Some(t.image);
    }
    log(&format!(
        "timing {} tiers: {} frames each (fewer for slow tiers) in {rounds} rounds",
        jobs.len(),
        frames
    ));
    for r in 0..rounds {
        for job in jobs.iter_mut() {
            // Spread what is left over the remaining rounds.
            let left = job.planned.saturating_sub(job.ms.len() as u32);
            let now = left.div_ceil(rounds - r);
            if now == 0 {
                continue;
            }
            let timing = TimingOptions {
                warmup: if r == 0 {
                    options.warmup.min(job.planned / 10)
                } else {
                    0
                },
                frames: now,
                force_cpu_timer: options.force_cpu_timer,
            };
            let t = renderer
                .time_frames(&job.prepared, scene, render_options, &timing)
                .map_err(|err| what(job, err))?;
            job.ms.extend(t.ms);
            job.image = Some(t.image);
        }
        log(&format!("round {}/{rounds} done", r + 1));
    }
    Ok(timer)
}

/// A timed run: what the figures are made from.
struct Run<'a> {
    measured: &'a [(PathBuf, MaterialMetadata)],
    jobs: &'a [Job],
    options: &'a ShadingOptions,
    adapter: &'a str,
    timer: FrameTimer,
}

/// Every selected material's figures (its error grid drawn here), in
/// `measured`'s order.
fn material_measurements(
    renderer: &mut Renderer,
    run: &Run<'_>,
    log: &mut dyn FnMut(&str),
) -> Result<Vec<Measurements>, String> {
    let (jobs, options) = (run.jobs, run.options);
    let baseline_ms = jobs
        .iter()
        .find(|j| {
            job_name(run.measured, j) == BASELINE_MATERIAL
                && j.tier == BASELINE_TIER
                && !j.f32_files
        })
        .map(|j| quantile(&j.ms, 0.5));
    let mut materials = Vec::new();
    for (i, (meta_path, meta)) in run.measured.iter().enumerate() {
        if !selected(options, meta) {
            continue;
        }
        let reference = jobs
            .iter()
            .find(|j| j.material == i && j.tier == meta.tiers.reference && !j.f32_files)
            .and_then(|j| j.image.as_ref())
            .ok_or_else(|| format!("{}: reference tier was not rendered", meta.name))?;
        let grid = match &options.grid {
            Some(g) => {
                log(&format!("{}: error grid", meta.name));
                crate::error_grid::tier_errors(renderer, meta_path, meta, g)?
            }
            None => Vec::new(),
        };
        let tiers = jobs
            .iter()
            .filter(|j| j.material == i && !j.f32_files)
            .map(|job| tier_measurement(job, jobs, meta, reference, &grid, baseline_ms))
            .collect();
        materials.push(Measurements {
            material: meta.name.clone(),
            inputs_hash: meta.inputs_hash.clone(),
            adapter: run.adapter.to_string(),
            timer: run.timer.name().into(),
            width: options.size,
            height: options.size,
            scene: options.scene.name().into(),
            setup: SETUP.into(),
            tiers,
        });
    }
    Ok(materials)
}

/// One tier's figures: its time (and its f32 files' where it has them)
/// against the baseline, its SPIR-V counts, its error against the
/// `reference` image and its error grid's cell.
fn tier_measurement(
    job: &Job,
    jobs: &[Job],
    meta: &MaterialMetadata,
    reference: &HdrImage,
    grid: &[TierGridError],
    baseline_ms: Option<f64>,
) -> TierMeasurement {
    let f32_files = jobs
        .iter()
        .find(|j| j.material == job.material && j.tier == job.tier && j.f32_files)
        .map(|j| {
            let median = quantile(&j.ms, 0.5);
            F32FilesCost {
                gpu_ms: round(median, 4),
                ratio_to_standard_fast: baseline_ms.map(|b| round(median / b, 3)),
            }
        });
    let cell = grid.iter().find(|g| g.tier == job.tier);
    let kind = if job.tier == meta.tiers.reference {
        "reference"
    } else if meta.tiers.looks.contains(&job.tier) {
        "look"
    } else {
        "approximation"
    };
    let image = job.image.as_ref().expect("every job rendered");
    let err = image_error(reference, image);
    let median = quantile(&job.ms, 0.5);
    let spread = (quantile(&job.ms, 0.9) - quantile(&job.ms, 0.1)) / median;
    TierMeasurement {
        tier: job.tier.clone(),
        variant: job.variant.clone(),
        frames: job.ms.len() as u32,
        gpu_ms: round(median, 4),
        gpu_ms_min: round(quantile(&job.ms, 0.0), 4),
        gpu_ms_spread: round(spread, 3),
        ratio_to_standard_fast: baseline_ms.map(|b| round(median / b, 3)),
        spirv_instructions: job.spirv.0,
        spirv_fragment_instructions: job.spirv.1,
        flip_mean: round(err.flip_mean, 5),
        flip_p99: round(err.flip_p99, 5),
        rel_rmse: round(err.rel_rmse, 5),
        kind: Some(kind.into()),
        flip_worst: cell.map(|c| round(c.worst, 5)),
        flip_grid_mean: cell.map(|c| round(c.mean, 5)),
        flip_worst_cell: cell.map(|c| c.worst_cell.clone()),
        grid_cells: cell.map(|c| c.cells),
        f32_files,
    }
}

fn round(x: f64, digits: i32) -> f64 {
    let s = 10f64.powi(digits);
    (x * s).round() / s
}
