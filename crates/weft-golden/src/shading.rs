//! The shading benchmark: for every material × tier, in one run on one
//! adapter, the GPU time of a frame (timestamp queries; CPU wall time when
//! the adapter has none), its ratio to `standard`'s `fast` tier, the SPIR-V
//! instruction count of the variant and its error against the material's
//! reference tier (FLIP on the ACES tone-mapped image, relative RMSE on the
//! linear HDR image, both over object pixels).
//!
//! Shared by `cargo xtask bench shading`, `cargo xtask regenerate --reports`
//! and `weft bench`. Reports go to `generated/reports/`: `shading.md`, and per
//! material `<name>.measurements.json` ([`weft_meta::Measurements`], which
//! inspectors attach to the metadata) and `<name>.pareto.svg`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;
use weft_meta::gpu_model::ModelSummary;
use weft_meta::{F32FilesCost, MaterialMetadata, Measurements, TierMeasurement};
use weft_render::{
    Background, EnvironmentMaps, FrameTimer, HdrImage, Luts, Material, PreparedMaterial,
    PreviewOptions, RenderOptions, Renderer, SceneKind, TimingOptions,
};

/// The cost every tier is compared with: `standard`'s `fast` tier.
pub const BASELINE_MATERIAL: &str = "standard";
pub const BASELINE_TIER: &str = "fast";

/// What the benchmark draws and how long it times.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadingOptions {
    /// Square image size in pixels.
    pub size: u32,
    pub scene: SceneKind,
    /// Untimed frames per tier before the first timed one.
    pub warmup: u32,
    /// Timed frames per tier (the median is reported).
    pub frames: u32,
    /// The timed frames are taken in this many rounds over all tiers, so
    /// that a change in machine load affects every tier alike.
    pub rounds: u32,
    /// Time with the CPU even when the adapter has timestamp queries.
    pub force_cpu_timer: bool,
    /// A tier whose `frames` would take longer than this (estimated from a
    /// probe frame) gets fewer, but at least `rounds` and at least 5.
    pub max_seconds_per_tier: f64,
    /// Materials to measure (empty: every material under the generated folder).
    pub materials: Vec<String>,
    /// Each tier's error over presets × scenes × lights
    /// ([`crate::error_grid`]); None measures only at the defaults.
    pub grid: Option<crate::error_grid::GridOptions>,
    /// Also time the cost floor, an unlit fill ([`crate::floor`]) built
    /// against this materials folder's `lib/`.
    pub floor: Option<PathBuf>,
}

impl Default for ShadingOptions {
    fn default() -> Self {
        ShadingOptions {
            size: 512,
            scene: SceneKind::Sphere,
            warmup: 5,
            frames: 50,
            rounds: 10,
            force_cpu_timer: false,
            max_seconds_per_tier: 20.0,
            materials: Vec::new(),
            grid: Some(crate::error_grid::GridOptions::default()),
            floor: None,
        }
    }
}

/// The result of [`run`].
#[derive(Clone, Debug)]
pub struct ShadingReport {
    pub adapter: String,
    pub timer: FrameTimer,
    pub options: ShadingOptions,
    /// One entry per measured material, sorted by name.
    pub materials: Vec<Measurements>,
    /// Wall time of the whole run, seconds.
    pub seconds: f64,
    /// Median frame time of the unlit fill ([`ShadingOptions::floor`]), ms.
    pub floor_ms: Option<f64>,
}

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

/// What every report says about the setup.
const SETUP: &str = "the material's default keyword and parameter values; no background (cleared to transparent black, so the pass holds the clear and the material's draws); Rgba16Float target; WGSL variants; errors over object pixels (those the material drew)";

/// Measures every tier of the selected materials under `generated`.
pub fn run(
    generated: &Path,
    options: &ShadingOptions,
    log: &mut dyn FnMut(&str),
) -> Result<ShadingReport, String> {
    let started = Instant::now();
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
    let selected =
        |m: &MaterialMetadata| options.materials.is_empty() || options.materials.contains(&m.name);
    // The baseline is measured even when `standard` is not selected.
    let measured: Vec<(PathBuf, MaterialMetadata)> = all
        .into_iter()
        .filter(|(_, m)| selected(m) || m.name == BASELINE_MATERIAL)
        .collect();
    if measured.is_empty() {
        return Err(format!("no materials under {}", generated.display()));
    }

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
    let mut renderer = Renderer::new(gpu, &env, &luts).map_err(e)?;
    let scene = preview.scene();
    let render_options = RenderOptions {
        background: Background::Color([0.0; 4]),
        ..preview.render_options()
    };

    let mut jobs = Vec::new();
    for (i, (meta_path, meta)) in measured.iter().enumerate() {
        let tiers: Vec<&String> = if selected(meta) {
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
            let prepared = renderer.prepare(&material, &render_options).map_err(what)?;
            let spirv = spirv_counts_for(&material)?;
            let half = renderer.gpu().has_shader_f16()
                && material
                    .current_variant()
                    .is_ok_and(|v| !v.shader.f16_files.is_empty());
            let variant = prepared.variant_id().to_string();
            jobs.push(Job {
                material: i,
                tier: tier.clone(),
                f32_files: false,
                variant: variant.clone(),
                spirv,
                prepared,
                planned: 0,
                ms: Vec::new(),
                image: None,
            });
            if half {
                let f32_options = RenderOptions {
                    f32_fallback: true,
                    ..render_options
                };
                jobs.push(Job {
                    material: i,
                    tier: tier.clone(),
                    f32_files: true,
                    variant,
                    spirv,
                    prepared: renderer.prepare(&material, &f32_options).map_err(what)?,
                    planned: 0,
                    ms: Vec::new(),
                    image: None,
                });
            }
        }
    }

    // The floor: an unlit fill drawn like every material, as one more job
    // (its material index is past `measured`).
    let floor_dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    if let Some(materials_dir) = &options.floor {
        let meta_path = crate::floor::build(materials_dir, floor_dir.path())?;
        let what = |err: weft_render::Error| format!("{}: {err}", crate::floor::FLOOR_MATERIAL);
        let material = Material::load(&meta_path).map_err(what)?;
        let prepared = renderer.prepare(&material, &render_options).map_err(what)?;
        jobs.push(Job {
            material: measured.len(),
            tier: BASELINE_TIER.into(),
            f32_files: false,
            variant: prepared.variant_id().to_string(),
            spirv: spirv_counts_for(&material)?,
            prepared,
            planned: 0,
            ms: Vec::new(),
            image: None,
        });
    }
    let name_of = |job: &Job| {
        measured
            .get(job.material)
            .map_or(crate::floor::FLOOR_MATERIAL, |m| m.1.name.as_str())
    };
    let what = |job: &Job, err: weft_render::Error| format!("{}/{}: {err}", name_of(job), job.tier);
    // Probe: one untimed and one timed frame per tier, to size the run.
    let mut timer = FrameTimer::GpuTimestamp;
    let rounds = options.rounds.max(1);
    let frames = options.frames.max(1);
    let min_frames = 5.min(frames);
    for job in &mut jobs {
        let probe = TimingOptions {
            warmup: 1,
            frames: 1,
            force_cpu_timer: options.force_cpu_timer,
        };
        let t = renderer
            .time_frames(&job.prepared, &scene, &render_options, &probe)
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
        for job in &mut jobs {
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
                .time_frames(&job.prepared, &scene, &render_options, &timing)
                .map_err(|err| what(job, err))?;
            job.ms.extend(t.ms);
            job.image = Some(t.image);
        }
        log(&format!("round {}/{rounds} done", r + 1));
    }

    let baseline_ms = jobs
        .iter()
        .find(|j| name_of(j) == BASELINE_MATERIAL && j.tier == BASELINE_TIER && !j.f32_files)
        .map(|j| quantile(&j.ms, 0.5));
    let mut materials = Vec::new();
    for (i, (_, meta)) in measured.iter().enumerate() {
        if !selected(meta) {
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
                let meta_path = &measured[i].0;
                crate::error_grid::tier_errors(&mut renderer, meta_path, meta, g)?
            }
            None => Vec::new(),
        };
        let mut tiers = Vec::new();
        for job in jobs.iter().filter(|j| j.material == i && !j.f32_files) {
            let f32_files = jobs
                .iter()
                .find(|j| j.material == i && j.tier == job.tier && j.f32_files)
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
            tiers.push(TierMeasurement {
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
            });
        }
        materials.push(Measurements {
            material: meta.name.clone(),
            inputs_hash: meta.inputs_hash.clone(),
            adapter: adapter.clone(),
            timer: timer.name().into(),
            width: options.size,
            height: options.size,
            scene: options.scene.name().into(),
            setup: SETUP.into(),
            tiers,
        });
    }
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

fn round(x: f64, digits: i32) -> f64 {
    let s = 10f64.powi(digits);
    (x * s).round() / s
}

/// The q-quantile (nearest rank) of `values`; NaN when empty.
pub fn quantile(values: &[f64], q: f64) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    v[(q.clamp(0.0, 1.0) * (v.len() - 1) as f64).round() as usize]
}

/// Error of `test` against `reference` over object pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageError {
    /// Mean FLIP over object pixels (ACES tone mapping, sRGB8).
    pub flip_mean: f64,
    /// 99th percentile (nearest rank) of the per-pixel FLIP over object pixels.
    pub flip_p99: f64,
    /// sqrt(Σ(a−b)² / Σb²) over the RGB channels of object pixels, linear HDR.
    pub rel_rmse: f64,
    /// Number of object pixels.
    pub pixels: usize,
}

/// Per-pixel FLIP of `test` against `reference` (ACES tone mapping, sRGB8,
/// row-major) and the object mask: pixels not left at the transparent-black
/// clear colour in either image.
pub fn flip_map(reference: &HdrImage, test: &HdrImage) -> (Vec<f32>, Vec<bool>) {
    assert_eq!(
        (reference.width, reference.height),
        (test.width, test.height)
    );
    let (w, h) = (reference.width, reference.height);
    let mask: Vec<bool> = reference
        .pixels
        .iter()
        .zip(&test.pixels)
        .map(|(a, b)| *a != [0.0; 4] || *b != [0.0; 4])
        .collect();
    let rgb = |img: &HdrImage| -> Vec<u8> {
        crate::to_ldr(img)
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect()
    };
    let flip = nv_flip::flip(
        nv_flip::FlipImageRgb8::with_data(w, h, &rgb(reference)),
        nv_flip::FlipImageRgb8::with_data(w, h, &rgb(test)),
        nv_flip::DEFAULT_PIXELS_PER_DEGREE,
    )
    .to_vec();
    (flip, mask)
}

/// Object pixels: those not left at the transparent-black clear colour in
/// either image.
pub fn image_error(reference: &HdrImage, test: &HdrImage) -> ImageError {
    let (flip, mask) = flip_map(reference, test);
    let values: Vec<f64> = flip
        .iter()
        .zip(&mask)
        .filter(|(_, m)| **m)
        .map(|(v, _)| f64::from(*v))
        .collect();
    let (mut num, mut den) = (0.0f64, 0.0f64);
    for ((a, b), m) in test.pixels.iter().zip(&reference.pixels).zip(&mask) {
        if *m {
            for c in 0..3 {
                let (a, b) = (f64::from(a[c]), f64::from(b[c]));
                num += (a - b) * (a - b);
                den += b * b;
            }
        }
    }
    let n = values.len();
    ImageError {
        flip_mean: if n == 0 {
            0.0
        } else {
            values.iter().sum::<f64>() / n as f64
        },
        flip_p99: if n == 0 { 0.0 } else { quantile(&values, 0.99) },
        rel_rmse: if den > 0.0 {
            (num / den).sqrt()
        } else {
            num.sqrt()
        },
        pixels: n,
    }
}

/// Instruction counts of a SPIR-V module: all instructions, and those in
/// the functions a fragment entry point reaches (its function and callees,
/// `OpFunction` to `OpFunctionEnd`; module-level types, constants and
/// decorations are not included).
pub fn spirv_instruction_counts(bytes: &[u8]) -> Result<(u32, u32), String> {
    if !bytes.len().is_multiple_of(4) || bytes.len() < 20 {
        return Err("not a SPIR-V module (length)".into());
    }
    let words: Vec<u32> = bytes
        .chunks_exact(4)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect();
    if words[0] != 0x0723_0203 {
        return Err("not a little-endian SPIR-V module (magic)".into());
    }
    const OP_ENTRY_POINT: u32 = 15;
    const OP_FUNCTION: u32 = 54;
    const OP_FUNCTION_END: u32 = 56;
    const OP_FUNCTION_CALL: u32 = 57;
    const FRAGMENT: u32 = 4;
    let mut total = 0u32;
    let mut fragment_roots = Vec::new();
    // Per function id: instruction count and callees.
    let mut functions: std::collections::HashMap<u32, (u32, Vec<u32>)> = Default::default();
    let mut current: Option<u32> = None;
    let mut i = 5;
    while i < words.len() {
        let count = (words[i] >> 16) as usize;
        let op = words[i] & 0xffff;
        if count == 0 || i + count > words.len() {
            return Err(format!("malformed instruction at word {i}"));
        }
        let w = &words[i..i + count];
        total += 1;
        match op {
            OP_ENTRY_POINT if count > 2 && w[1] == FRAGMENT => fragment_roots.push(w[2]),
            OP_FUNCTION if count > 2 => {
                current = Some(w[2]);
                functions.entry(w[2]).or_default();
            }
            _ => {}
        }
        if let Some(f) = current {
            let entry = functions.entry(f).or_default();
            entry.0 += 1;
            if op == OP_FUNCTION_CALL && count > 3 {
                entry.1.push(w[3]);
            }
        }
        if op == OP_FUNCTION_END {
            current = None;
        }
        i += count;
    }
    let mut seen = std::collections::HashSet::new();
    let mut stack = fragment_roots;
    let mut fragment = 0;
    while let Some(f) = stack.pop() {
        if !seen.insert(f) {
            continue;
        }
        if let Some((n, callees)) = functions.get(&f) {
            fragment += n;
            stack.extend(callees);
        }
    }
    Ok((total, fragment))
}

/// The SPIR-V file of the material's current variant (the one whose baked
/// constant-mode keyword values match the material's) and its counts.
fn spirv_counts_for(material: &Material) -> Result<(u32, u32), String> {
    let name = material.name().to_string();
    let v = material
        .current_variant()
        .map_err(|e| format!("{name}: {e}"))?;
    let file = v
        .shader
        .files
        .get("spirv")
        .and_then(|files| {
            files.iter().find(|f| {
                f.constants
                    .iter()
                    .all(|(k, val)| material.keyword(k) == Some(val.as_str()))
            })
        })
        .ok_or_else(|| format!("{name}: variant `{}` has no SPIR-V file", v.canonical.id))?;
    let path = material.dir().join(&file.path);
    let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    spirv_instruction_counts(&bytes).map_err(|e| format!("{}: {e}", path.display()))
}

/// The header lines of a report: what was measured, where, how.
pub fn describe(report: &ShadingReport) -> String {
    let o = &report.options;
    let timer = match report.timer {
        FrameTimer::GpuTimestamp => {
            "GPU timestamp queries at the beginning and end of the render pass".to_string()
        }
        FrameTimer::CpuWall => {
            "CPU wall time from submit to completion (the adapter has no timestamp queries, or --cpu-timer was given): includes submission overhead".to_string()
        }
    };
    format!(
        "Adapter: {}. Timer: {timer}. Scene: {}x{} {}, {SETUP}. Time: median of {} frames per tier (fewer, at least {}, for a tier that would take over {} s; column `frames`), after 1 + up to {} warm-up frames, taken in {} rounds over all tiers so that changing machine load affects all alike; spread = (p90 − p10) / median. Cost ratio: against `{BASELINE_MATERIAL}` tier `{BASELINE_TIER}` in the same run; a half-precision tier is drawn from its f16 files where the adapter has shader-f16, and its portable f32 files' ratio follows in brackets. SPIR-V: instructions in the module (in the fragment entry point's functions). Error against the material's reference tier: FLIP mean and 99th percentile on the ACES tone-mapped sRGB8 image, relative RMSE sqrt(Σ(a−b)²/Σb²) on the linear HDR image.",
        report.adapter,
        o.size,
        o.size,
        o.scene.name(),
        o.frames.max(1),
        5.min(o.frames.max(1)),
        o.max_seconds_per_tier,
        o.warmup,
        o.rounds.max(1),
    )
}

/// The tables of every material × tier, Markdown: the reference and its
/// approximations (whose difference from the reference is their error),
/// then the looks (different models, whose difference is not an error).
pub fn markdown_table(materials: &[Measurements]) -> String {
    let mut md = String::new();
    let header = "| material | tier | GPU ms (median) | min | spread | frames | × standard fast | SPIR-V instr. (fragment) | FLIP mean | FLIP p99 | rel. RMSE | FLIP worst (grid) | FLIP grid mean | worst cell |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
    let is_look = |t: &TierMeasurement| t.kind.as_deref() == Some("look");
    let row = |md: &mut String, m: &Measurements, t: &TierMeasurement| {
        let opt = |v: Option<f64>| v.map_or("—".to_string(), |v| format!("{v:.4}"));
        let _ = writeln!(
            md,
            "| {} | {} | {:.3} | {:.3} | {:.1}% | {} | {} | {} ({}) | {:.4} | {:.4} | {:.4} | {} | {} | {} |",
            m.material,
            t.tier,
            t.gpu_ms,
            t.gpu_ms_min,
            t.gpu_ms_spread * 100.0,
            t.frames,
            cost_cell(t),
            t.spirv_instructions,
            t.spirv_fragment_instructions,
            t.flip_mean,
            t.flip_p99,
            t.rel_rmse,
            opt(t.flip_worst),
            opt(t.flip_grid_mean),
            t.flip_worst_cell.as_deref().unwrap_or("—"),
        );
    };
    md.push_str("Reference tiers and their approximations (FLIP against the reference is the approximation's error):\n\n");
    md.push_str(header);
    for m in materials {
        for t in m.tiers.iter().filter(|t| !is_look(t)) {
            row(&mut md, m, t);
        }
    }
    if materials.iter().any(|m| m.tiers.iter().any(is_look)) {
        md.push_str("\nLooks: different models kept for their look (a source document's formula), not approximations; the FLIP columns say how far the look is from the reference, not an error:\n\n");
        md.push_str(header);
        for m in materials {
            for t in m.tiers.iter().filter(|t| is_look(t)) {
                row(&mut md, m, t);
            }
        }
    }
    md
}

/// The "× standard fast" cell: a half-precision tier's f32 files beside it.
pub(crate) fn cost_cell(t: &TierMeasurement) -> String {
    let ratio = |r: Option<f64>| r.map_or("—".to_string(), |r| format!("{r:.2}"));
    match &t.f32_files {
        Some(f) => format!(
            "{} (f32 files: {})",
            ratio(t.ratio_to_standard_fast),
            ratio(f.ratio_to_standard_fast)
        ),
        None => ratio(t.ratio_to_standard_fast),
    }
}

/// Replaces the text between `<!-- weft:<name>:begin -->` and
/// `<!-- weft:<name>:end -->` in `text` with `content`; None when the
/// markers are absent.
pub fn replace_marked(text: &str, name: &str, content: &str) -> Option<String> {
    let begin = format!("<!-- weft:{name}:begin -->");
    let end = format!("<!-- weft:{name}:end -->");
    let a = text.find(&begin)? + begin.len();
    let b = a + text[a..].find(&end)?;
    Some(format!("{}\n{}{}", &text[..a], content, &text[b..]))
}

/// `shading.md`: the description, the command, the timed table and the GPU
/// model's table (between `<!-- weft:gpu-model:… -->`, which
/// `cargo xtask bench gpu-model --write` rewrites on its own).
pub fn markdown_report(
    report: &ShadingReport,
    command: &str,
    model: Option<&ModelSummary>,
) -> String {
    format!(
        "# Shading cost and accuracy\n\nGenerated by `{command}` (timings vary by machine; do not edit). {}\n\n{}{}\n<!-- weft:gpu-model:begin -->\n{}<!-- weft:gpu-model:end -->\n\nTotal run time: {:.1} s.\n",
        describe(report),
        markdown_table(&report.materials),
        floor_line(report),
        crate::cost_tables::model_section(&report.materials, model),
        report.seconds
    )
}

/// The cost floor and `standard` `fast` against it, when both were timed.
pub fn floor_line(report: &ShadingReport) -> String {
    let standard = report
        .materials
        .iter()
        .find(|m| m.material == BASELINE_MATERIAL)
        .and_then(|m| m.tiers.iter().find(|t| t.tier == BASELINE_TIER));
    match (report.floor_ms, standard) {
        (Some(floor), Some(t)) => format!(
            "\nFloor: an unlit fill (the same geometry and vertex stage, a flat colour; `crates/weft-golden/src/floor.rs`) takes {floor:.3} ms in the same run: `{BASELINE_MATERIAL}` `{BASELINE_TIER}` costs {:.2}× the floor.\n",
            t.gpu_ms / floor
        ),
        _ => String::new(),
    }
}

/// One material's tiers as a Markdown table (for the gallery), with where
/// and how they were measured.
pub fn tier_table(m: &Measurements, current_inputs_hash: &str) -> String {
    let mut md = String::new();
    let _ = writeln!(
        md,
        "| tier | kind | GPU ms | × standard fast | SPIR-V instr. | FLIP mean | FLIP p99 | rel. RMSE | FLIP worst (grid) |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    );
    for t in &m.tiers {
        let _ = writeln!(
            md,
            "| {} | {} | {:.3} | {} | {} | {:.4} | {:.4} | {:.4} | {} |",
            t.tier,
            t.kind.as_deref().unwrap_or("—"),
            t.gpu_ms,
            cost_cell(t),
            t.spirv_instructions,
            t.flip_mean,
            t.flip_p99,
            t.rel_rmse,
            t.flip_worst.map_or("—".to_string(), |v| format!("{v:.4}")),
        );
    }
    let stale = if m.inputs_hash != current_inputs_hash {
        " **Measured on an earlier version of the material: rerun `cargo xtask regenerate --reports`.**"
    } else {
        ""
    };
    let _ = writeln!(
        md,
        "\nMeasured on {} ({}), {}x{} {}, median over frames; error against the reference tier over object pixels.{stale}",
        m.adapter, m.timer, m.width, m.height, m.scene
    );
    md
}

/// Writes `shading.md` and, per material, `<name>.measurements.json` and
/// `<name>.pareto.svg` into `dir` (other files there are left alone).
/// Returns the paths written.
pub fn write_reports(
    dir: &Path,
    report: &ShadingReport,
    command: &str,
    model: Option<&ModelSummary>,
) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut files: Vec<(PathBuf, String)> = vec![(
        dir.join("shading.md"),
        markdown_report(report, command, model),
    )];
    for m in &report.materials {
        let mut json = serde_json::to_string_pretty(m).map_err(|e| e.to_string())?;
        json.push('\n');
        files.push((dir.join(format!("{}.measurements.json", m.material)), json));
        files.push((
            dir.join(format!("{}.pareto.svg", m.material)),
            crate::pareto::pareto_svg(m, model),
        ));
    }
    let mut written = Vec::new();
    for (path, text) in files {
        let tmp = path.with_extension("tmp");
        std::fs::write(&tmp, text)
            .and_then(|()| std::fs::rename(&tmp, &path))
            .map_err(|e| format!("{}: {e}", path.display()))?;
        written.push(path);
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spirv_counts_follow_calls_from_the_fragment_entry() {
        // Header, OpEntryPoint Fragment %10, two functions: %10 calls %11.
        let mut w: Vec<u32> = vec![0x0723_0203, 0x0001_0000, 0, 20, 0];
        w.extend([(4 << 16) | 15, 4, 10, 0]); // OpEntryPoint Fragment %10 ""
        w.extend([(2 << 16) | 19, 1]); // OpTypeVoid %1
        w.extend([(5 << 16) | 54, 1, 11, 0, 2]); // OpFunction %11
        w.extend([(1 << 16) | 56]); // OpFunctionEnd
        w.extend([(5 << 16) | 54, 1, 10, 0, 2]); // OpFunction %10
        w.extend([(4 << 16) | 57, 1, 12, 11]); // OpFunctionCall %11
        w.extend([(1 << 16) | 56]); // OpFunctionEnd
        w.extend([(5 << 16) | 54, 1, 13, 0, 2]); // OpFunction %13 (unreached)
        w.extend([(1 << 16) | 56]);
        let bytes: Vec<u8> = w.iter().flat_map(|x| x.to_le_bytes()).collect();
        assert_eq!(spirv_instruction_counts(&bytes).unwrap(), (9, 5));
    }

    #[test]
    fn an_image_has_no_error_against_itself() {
        let img = HdrImage {
            width: 4,
            height: 4,
            pixels: (0..16)
                .map(|i| {
                    if i % 3 == 0 {
                        [0.0; 4]
                    } else {
                        [i as f32 * 0.1, 0.5, 0.2, 1.0]
                    }
                })
                .collect(),
        };
        let e = image_error(&img, &img);
        assert_eq!((e.flip_mean, e.flip_p99, e.rel_rmse), (0.0, 0.0, 0.0));
        assert_eq!(e.pixels, 10);
    }
}
