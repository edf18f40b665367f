//! `cargo xtask bench gpu`: the shading and scene benchmarks on the first
//! real GPU adapter (never a CPU rasteriser unless `WEFT_ADAPTER` names
//! one), written as `generated/reports/gpu-<adapter>.md` and `.json`: per
//! tier the GPU time and its ratio to `standard` `fast`, beside the
//! committed llvmpipe ratio and the GPU model's prediction
//! (`generated/reports/gpu-model.json`, RADV/ACO on the null device), with
//! Spearman's rank correlation of each against the GPU; per scene the
//! generic vs specialised frame time beside the model's predicted saving.
//!
//! Sized to finish within 8 minutes on a lent GPU machine; nothing else in
//! the project reads its output except the GPU-model report, which quotes
//! the committed correlations.

use serde::Serialize;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;
use weft_golden::scene_bench::{self, SceneBenchOptions, SceneBenchReport};
use weft_golden::shading::{self, ShadingOptions, ShadingReport};
use weft_gpu_stats::ModelSummary;
use weft_gpu_stats::loop_report::{llvmpipe_ratio, spearman};

#[derive(clap::Args)]
pub struct GpuArgs {
    /// Square image of the shading bench, pixels (a sphere filling most of it).
    #[arg(long, default_value_t = 2048)]
    size: u32,
    /// Timed frames per tier (the median is reported).
    #[arg(long, default_value_t = 40)]
    frames: u32,
    /// Rounds over all tiers the frames are spread across.
    #[arg(long, default_value_t = 5)]
    rounds: u32,
    /// Scene bench frame size, WIDTHxHEIGHT.
    #[arg(long, default_value = "1920x1080", value_parser = parse_size)]
    scene_size: (u32, u32),
    /// Skip the scene bench.
    #[arg(long)]
    no_scenes: bool,
    /// Write the report into this folder instead of generated/reports/.
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s
        .split_once('x')
        .ok_or_else(|| format!("`{s}`: expected WIDTHxHEIGHT, e.g. 1920x1080"))?;
    let n = |v: &str| {
        v.parse::<u32>()
            .ok()
            .filter(|n| (16..=8192).contains(n))
            .ok_or_else(|| format!("`{s}`: each side must be 16…8192 pixels"))
    };
    Ok((n(w)?, n(h)?))
}

pub fn bench_gpu(root: &Path, args: &GpuArgs) -> ExitCode {
    match run(root, args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The command line that reproduces a report made with `args`.
fn command(args: &GpuArgs) -> String {
    let mut c = "cargo xtask bench gpu".to_string();
    if args.size != 2048 {
        let _ = write!(c, " --size {}", args.size);
    }
    if args.frames != 40 {
        let _ = write!(c, " --frames {}", args.frames);
    }
    if args.rounds != 5 {
        let _ = write!(c, " --rounds {}", args.rounds);
    }
    if args.scene_size != (1920, 1080) {
        let _ = write!(
            c,
            " --scene-size {}x{}",
            args.scene_size.0, args.scene_size.1
        );
    }
    if args.no_scenes {
        c.push_str(" --no-scenes");
    }
    c
}

fn run(root: &Path, args: &GpuArgs) -> Result<(), String> {
    let var = weft_render::ADAPTER_VARIABLE;
    if std::env::var_os(var).is_none_or(|v| v.is_empty()) {
        // SAFETY: set before any thread starts (nothing has touched the
        // GPU, rayon or the compiler yet).
        unsafe { std::env::set_var(var, "hardware") };
    }
    let generated = root.join("generated");
    let model = ModelSummary::load(&generated.join("reports"))?;
    let started = Instant::now();
    let options = ShadingOptions {
        size: args.size,
        frames: args.frames,
        rounds: args.rounds,
        // A GPU frame is short: the per-tier cap only guards a slow adapter.
        max_seconds_per_tier: 10.0,
        // The error grid measures accuracy, which does not depend on the adapter.
        grid: None,
        ..ShadingOptions::default()
    };
    let shading = shading::run(&generated, &options, &mut |s| eprintln!("{s}")).map_err(|e| {
        format!("{e}\n(hint: `{var}` picks the adapter; this bench wants a real GPU, `{var}=llvmpipe` rehearses it on lavapipe)")
    })?;
    eprintln!("shading bench: {:.1} s", shading.seconds);
    let dir = args
        .out
        .clone()
        .unwrap_or_else(|| generated.join("reports"));
    let command = command(args);
    // The shading half is written at once, so a run stopped during the
    // scenes (a lent machine's time limit) still leaves it.
    let report = GpuReport::new(&generated, &shading, None, &model);
    write_report(&dir, &report, &command, started.elapsed().as_secs_f64())?;
    if args.no_scenes {
        return Ok(());
    }
    let inputs = crate::bench_scene::scene_inputs(root, &[])?;
    let options = SceneBenchOptions {
        width: args.scene_size.0,
        height: args.scene_size.1,
        rounds: 5,
        frames: 10,
        warmup: 3,
        build_runs: 1,
        force_cpu_timer: false,
        per_instance: false,
    };
    let scenes = scene_bench::run(&generated, &inputs, &options, &mut |s| eprintln!("{s}"))?;
    eprintln!("scene bench: {:.1} s", scenes.seconds);
    let report = GpuReport::new(&generated, &shading, Some(&scenes), &model);
    let md = write_report(&dir, &report, &command, started.elapsed().as_secs_f64())?;
    print!("{md}");
    Ok(())
}

/// Writes `<dir>/gpu-<adapter>.md` and `.json`; returns the markdown.
fn write_report(
    dir: &Path,
    report: &GpuReport,
    command: &str,
    seconds: f64,
) -> Result<String, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let md = report.markdown(command, seconds);
    let stem = format!("gpu-{}", slug(&report.adapter_name));
    let md_path = dir.join(format!("{stem}.md"));
    std::fs::write(&md_path, &md).map_err(|e| format!("{}: {e}", md_path.display()))?;
    let json_path = dir.join(format!("{stem}.json"));
    let mut json = serde_json::to_string_pretty(report).map_err(|e| e.to_string())?;
    json.push('\n');
    std::fs::write(&json_path, json).map_err(|e| format!("{}: {e}", json_path.display()))?;
    eprintln!("wrote {} and {}", md_path.display(), json_path.display());
    Ok(md)
}

/// `NVIDIA H100 80GB HBM3` → `nvidia-h100-80gb-hbm3`.
pub fn slug(name: &str) -> String {
    let mut out = String::new();
    for c in name.chars() {
        if c.is_ascii_alphanumeric() {
            out.push(c.to_ascii_lowercase());
        } else if !out.ends_with('-') && !out.is_empty() {
            out.push('-');
        }
    }
    let out = out.trim_end_matches('-').to_string();
    if out.is_empty() {
        "adapter".into()
    } else {
        out
    }
}

/// One tier on the GPU beside the other cost sources.
#[derive(Clone, Debug, Serialize)]
struct TierRow {
    material: String,
    tier: String,
    gpu_ms: f64,
    spread: f64,
    frames: u32,
    /// GPU ms ÷ `standard` `fast`'s.
    gpu_ratio: Option<f64>,
    /// A half-precision tier's f32 files on this GPU.
    f32_files_ratio: Option<f64>,
    /// Committed llvmpipe ratio (`<material>.measurements.json`).
    llvmpipe_ratio: Option<f64>,
    /// The model's executed cost ratio per family, in the summary's order.
    model_ratios: Vec<Option<f64>>,
    flip_mean: f64,
    /// The material's `inputs_hash` when timed: the GPU model's report
    /// ranks its costs only against timings of the same files.
    inputs_hash: String,
}

/// One scene: generic vs specialised.
#[derive(Clone, Debug, Serialize)]
struct SceneRow {
    scene: String,
    generic_ms: f64,
    specialised_ms: f64,
    saving_pct: f64,
    /// Per family: 1 − Σ specialised executed cost ÷ Σ generic (the scene's shader passes).
    model_saving_pct: Vec<Option<f64>>,
    flip_mean: f64,
}

#[derive(Clone, Debug, Serialize)]
struct GpuReport {
    adapter_name: String,
    adapter: String,
    timer: String,
    size: u32,
    families: Vec<String>,
    tiers: Vec<TierRow>,
    /// ρ(GPU ratio of the f32 files, model ratio) per family over tiers with
    /// both: the model costs a tier's f32 files.
    spearman_model: Vec<Option<f64>>,
    /// ρ(GPU ratio, llvmpipe ratio), each as drawn.
    spearman_llvmpipe: Option<f64>,
    scene_adapter: Option<String>,
    scene_size: Option<(u32, u32)>,
    scenes: Vec<SceneRow>,
}

impl GpuReport {
    fn new(
        generated: &Path,
        shading: &ShadingReport,
        scenes: Option<&SceneBenchReport>,
        model: &ModelSummary,
    ) -> GpuReport {
        let families: Vec<String> = model.families.iter().map(|f| f.family.clone()).collect();
        let mut tiers = Vec::new();
        for m in &shading.materials {
            for t in &m.tiers {
                let model_ratios = model
                    .families
                    .iter()
                    .map(|f| f.tier(&m.material, &t.tier).map(|c| c.executed_ratio))
                    .collect();
                tiers.push(TierRow {
                    material: m.material.clone(),
                    tier: t.tier.clone(),
                    gpu_ms: t.gpu_ms,
                    spread: t.gpu_ms_spread,
                    frames: t.frames,
                    gpu_ratio: t.ratio_to_standard_fast,
                    f32_files_ratio: t.f32_files.as_ref().and_then(|f| f.ratio_to_standard_fast),
                    // As drawn, like `gpu_ratio` (f16 files where both adapters have them).
                    llvmpipe_ratio: llvmpipe_ratio(generated, &m.material, &t.tier)
                        .map(|r| r.drawn),
                    model_ratios,
                    flip_mean: t.flip_mean,
                    inputs_hash: m.inputs_hash.clone(),
                });
            }
        }
        let rho = |gpu: &dyn Fn(&TierRow) -> Option<f64>,
                   pick: &dyn Fn(&TierRow) -> Option<f64>| {
            let pairs: Vec<(f64, f64)> = tiers
                .iter()
                .filter_map(|t| Some((gpu(t)?, pick(t)?)))
                .collect();
            spearman(&pairs)
        };
        // The model costs a tier's f32 files: paired with their timing (a
        // half-precision tier drawn from f16 files was timed in f32 too).
        let f32_files = |t: &TierRow| t.f32_files_ratio.or(t.gpu_ratio);
        let spearman_model = (0..families.len())
            .map(|i| rho(&f32_files, &|t: &TierRow| t.model_ratios[i]))
            .collect();
        let spearman_llvmpipe = rho(&|t: &TierRow| t.gpu_ratio, &|t: &TierRow| t.llvmpipe_ratio);
        let scene_rows = scenes.map_or_else(Vec::new, |r| {
            r.scenes
                .iter()
                .map(|s| SceneRow {
                    scene: s.name.clone(),
                    generic_ms: s.gpu.generic_stats().median,
                    specialised_ms: s.gpu.specialised_stats().median,
                    saving_pct: s.gpu.saving_pct(),
                    model_saving_pct: model
                        .families
                        .iter()
                        .map(|f| {
                            let shaders = f.scene_shaders.iter().filter(|c| c.scene == s.name);
                            let (spec, generic) = shaders.fold((0.0, 0.0), |(a, b), c| {
                                (a + c.specialised.executed_cost, b + c.generic.executed_cost)
                            });
                            (generic > 0.0).then(|| 100.0 * (1.0 - spec / generic))
                        })
                        .collect(),
                    flip_mean: s.flip.flip_mean,
                })
                .collect()
        });
        GpuReport {
            adapter_name: shading
                .adapter
                .split(" (")
                .next()
                .unwrap_or(&shading.adapter)
                .to_string(),
            adapter: shading.adapter.clone(),
            timer: shading.timer.name().into(),
            size: shading.options.size,
            families,
            tiers,
            spearman_model,
            spearman_llvmpipe,
            scene_adapter: scenes.map(|r| r.adapter.clone()),
            scene_size: scenes.map(|r| (r.options.width, r.options.height)),
            scenes: scene_rows,
        }
    }

    fn markdown(&self, command: &str, seconds: f64) -> String {
        let x = |v: Option<f64>| v.map_or("–".into(), |v| format!("{v:.2}×"));
        let r = |v: Option<f64>| v.map_or("–".into(), |v| format!("{v:.3}"));
        let mut o = String::new();
        let _ = writeln!(o, "# Shading cost on a GPU: {}\n", self.adapter_name);
        let _ = writeln!(
            o,
            "Measured by `{command}` ({seconds:.0} s) on {}. Timer: {}. Shading: {s}×{s} sphere, \
             each material's default keyword and parameter values, WGSL variants, the median of \
             the timed frames per tier. Beside each GPU ratio: llvmpipe's committed ratio \
             (`generated/reports/<material>.measurements.json`) and the GPU model's executed-cost \
             ratio (`generated/reports/gpu-model.json`: Mesa RADV/ACO on its null device, loops \
             counted by their trip counts; docs/performance.md). All ratios divide by `standard` \
             `fast` in the same source. FLIP: against the material's reference tier, at the \
             defaults, on this adapter.\n",
            self.adapter,
            self.timer,
            s = self.size
        );
        let fam_heads: String = self
            .families
            .iter()
            .map(|f| format!(" model {f} × |"))
            .collect();
        let _ = writeln!(
            o,
            "| material | tier | GPU ms | spread | frames | GPU × standard fast | llvmpipe × |{fam_heads} FLIP mean |"
        );
        let _ = writeln!(
            o,
            "|---|---|--:|--:|--:|--:|--:|{}--:|",
            "--:|".repeat(self.families.len())
        );
        for t in &self.tiers {
            let gpu = match t.f32_files_ratio {
                Some(f) => format!("{} (f32 files: {f:.2}×)", x(t.gpu_ratio)),
                None => x(t.gpu_ratio),
            };
            let models: String = t
                .model_ratios
                .iter()
                .map(|m| format!(" {} |", x(*m)))
                .collect();
            let _ = writeln!(
                o,
                "| {} | {} | {:.4} | {:.1}% | {} | {gpu} | {} |{models} {:.4} |",
                t.material,
                t.tier,
                t.gpu_ms,
                t.spread * 100.0,
                t.frames,
                x(t.llvmpipe_ratio),
                t.flip_mean
            );
        }
        let model_rhos: Vec<String> = self
            .families
            .iter()
            .zip(&self.spearman_model)
            .map(|(f, v)| format!("model {f} ρ = {}", r(*v)))
            .collect();
        let _ = writeln!(
            o,
            "\nSpearman rank correlation with this GPU's ratios over the {} tiers (the model \
             against the f32 files' ratios, the files it costs): {}; llvmpipe ρ = {}.",
            self.tiers.len(),
            model_rhos.join(", "),
            r(self.spearman_llvmpipe)
        );
        if let (Some(adapter), Some((w, h))) = (&self.scene_adapter, self.scene_size) {
            let _ = writeln!(
                o,
                "\n## Scenes: generic library variants vs scene-specialised shaders\n\n{w}×{h}, \
                 {adapter}; the median of 5 interleaved rounds of 10 frames. Model: 1 − Σ \
                 specialised ÷ Σ generic executed cost over the scene's shader passes.\n"
            );
            let fam_heads: String = self
                .families
                .iter()
                .map(|f| format!(" model {f} saving |"))
                .collect();
            let _ = writeln!(
                o,
                "| scene | generic ms | specialised ms | GPU saving |{fam_heads} FLIP mean |"
            );
            let _ = writeln!(
                o,
                "|---|--:|--:|--:|{}--:|",
                "--:|".repeat(self.families.len())
            );
            for s in &self.scenes {
                let models: String = s
                    .model_saving_pct
                    .iter()
                    .map(|m| m.map_or(" – |".into(), |m| format!(" {m:.1}% |")))
                    .collect();
                let _ = writeln!(
                    o,
                    "| {} | {:.4} | {:.4} | {:.1}% |{models} {:.4} |",
                    s.scene, s.generic_ms, s.specialised_ms, s.saving_pct, s.flip_mean
                );
            }
        }
        o
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adapter_names_make_file_names() {
        assert_eq!(slug("NVIDIA H100 80GB HBM3"), "nvidia-h100-80gb-hbm3");
        assert_eq!(
            slug("llvmpipe (LLVM 15.0.6, 256 bits)"),
            "llvmpipe-llvm-15-0-6-256-bits"
        );
        assert_eq!(slug("  ??  "), "adapter");
    }

    #[test]
    fn scene_sizes_parse_within_bounds() {
        assert_eq!(parse_size("1920x1080"), Ok((1920, 1080)));
        assert!(parse_size("1920").is_err());
        assert!(parse_size("8x8").is_err());
        assert!(parse_size("99999x10").is_err());
    }
}
