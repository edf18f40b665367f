//! `weft bench`: per-tier GPU cost and error against the reference tier.

use std::path::{Path, PathBuf};
use weft_meta::MaterialMetadata;
use weft_meta::gpu_model::{ModelSummary, generated_inputs_hash};

pub(crate) const BENCH_EXAMPLES: &str = "Examples:
  weft bench
  weft bench generated --material microcylinder --size 256 --frames 20
  weft bench --write-reports          # generated/reports/: shading.md, <name>.measurements.json, <name>.pareto.svg

GPU time comes from timestamp queries around the render pass (clear + the material's draws, no
background); an adapter without them is timed on the CPU, and the `timer` line says so. Errors are
over object pixels, against the material's reference tier with the same keywords and parameters.";

#[derive(clap::Args)]
pub(crate) struct BenchArgs {
    /// A generated folder (`weft build` output).
    #[arg(default_value = "generated")]
    generated: PathBuf,
    /// Only these materials (repeatable); standard's fast tier is still timed as the baseline.
    #[arg(long = "material", value_name = "NAME")]
    materials: Vec<String>,
    /// Square image size in pixels.
    #[arg(long, default_value_t = 512)]
    size: u32,
    /// Timed frames per tier (the median is reported).
    #[arg(long, default_value_t = 50)]
    frames: u32,
    /// Untimed warm-up frames per tier.
    #[arg(long, default_value_t = 5)]
    warmup: u32,
    /// Rounds over all tiers the timed frames are split into.
    #[arg(long, default_value_t = 10)]
    rounds: u32,
    /// Time on the CPU (submit to completion) even when timestamp queries exist.
    #[arg(long)]
    cpu_timer: bool,
    /// A tier whose frames would take longer than this gets fewer (at least 5).
    #[arg(long, default_value_t = 20.0, value_name = "SECONDS")]
    max_seconds_per_tier: f64,
    /// Write <generated>/reports/ (read by `weft inspect` and the gallery).
    #[arg(long)]
    write_reports: bool,
}

pub(crate) fn bench(args: &BenchArgs) -> Result<(), String> {
    use weft_golden::shading;
    let options = shading::ShadingOptions {
        size: args.size.max(1),
        frames: args.frames.max(1),
        warmup: args.warmup,
        rounds: args.rounds.max(1),
        force_cpu_timer: args.cpu_timer,
        max_seconds_per_tier: args.max_seconds_per_tier,
        materials: args.materials.clone(),
        ..Default::default()
    };
    let report = shading::run(&args.generated, &options, &mut |s| eprintln!("{s}"))?;
    println!("{}\n", shading::describe(&report));
    print!("{}", shading::markdown_table(&report.materials));
    println!(
        "\ntimer: {}; total {:.1} s",
        report.timer.name(),
        report.seconds
    );
    if args.write_reports {
        let dir = args.generated.join("reports");
        // The GPU model's columns, when the folder has the committed model.
        let model = weft_meta::gpu_model::ModelSummary::load(&dir).ok();
        let files =
            shading::write_reports(&dir, &report, "weft bench --write-reports", model.as_ref())?;
        println!("wrote {} files in {}", files.len(), dir.display());
    }
    Ok(())
}

/// Prints measured per-tier figures attached from `<generated>/reports/`
/// (a .meta.json's folder, or `generated/` for a .toml).
pub(crate) fn print_measurements(m: &mut MaterialMetadata, path: &Path) {
    let meta_path = if path.extension().is_some_and(|e| e == "json") {
        path.to_path_buf()
    } else {
        Path::new("generated").join(&m.name).join("x.meta.json")
    };
    if let Err(e) = m.attach_measurements(&meta_path) {
        eprintln!("warning: ignoring measurements: {e}");
    }
    print_measured(m);
    print_gpu_model(m, &meta_path);
}

/// The measured table (a rasteriser's timings and the errors).
fn print_measured(m: &MaterialMetadata) {
    let Some(ms) = &m.measurements else { return };
    let stale = if ms.inputs_hash == m.inputs_hash {
        ""
    } else {
        " — measured on an earlier version of the material"
    };
    println!(
        "\nMeasured cost and error ({}x{} {}, {}, {}{stale})",
        ms.width, ms.height, ms.scene, ms.adapter, ms.timer
    );
    let rows: Vec<Vec<String>> = ms
        .tiers
        .iter()
        .map(|t| {
            vec![
                t.tier.clone(),
                format!("{:.3}", t.gpu_ms),
                t.ratio_to_standard_fast
                    .map_or("-".into(), |r| format!("{r:.2}")),
                t.spirv_instructions.to_string(),
                format!("{:.4}", t.flip_mean),
                format!("{:.4}", t.flip_p99),
                format!("{:.4}", t.rel_rmse),
            ]
        })
        .collect();
    print!(
        "{}",
        weft_cli::tables::table(
            &[
                "tier",
                "GPU ms",
                "x standard fast",
                "SPIR-V instr.",
                "FLIP mean",
                "FLIP p99",
                "rel. RMSE"
            ],
            &rows
        )
    );
}

/// The GPU model's table, apart from the measured one: per AMD family the
/// tier's loop-aware executed cost ÷ standard fast and its VGPRs / waves,
/// from `<generated>/reports/gpu-model.json` beside the measurements
/// (nothing when it is absent).
fn print_gpu_model(m: &MaterialMetadata, meta_path: &Path) {
    let generated = meta_path
        .parent()
        .and_then(|d| d.parent())
        .unwrap_or(Path::new("."));
    let Ok(model) = ModelSummary::load(&generated.join("reports")) else {
        return;
    };
    let families: Vec<_> = model
        .families
        .iter()
        .filter(|f| f.tiers.iter().any(|t| t.material == m.name))
        .collect();
    if families.is_empty() {
        return;
    }
    // The model costed the generated files: flag a material changed since.
    let costed_hash = generated_inputs_hash(generated, &m.name);
    let stale = if costed_hash.as_deref() == Some(m.inputs_hash.as_str()) {
        ""
    } else {
        " — modelled on an earlier version of the material"
    };
    let devices: Vec<String> = families
        .iter()
        .map(|f| format!("{}: {}, {}", f.family, f.device_name, f.driver_info))
        .collect();
    println!(
        "\nGPU model (AMD's shader compiler, loop-aware executed cost of the fragment stage ÷ standard fast; {}{stale})",
        devices.join("; ")
    );
    let mut header = vec!["tier".to_string()];
    for f in &families {
        header.push(format!("{} x standard fast", f.family));
        header.push(format!("{} VGPRs / waves", f.family));
    }
    let rows: Vec<Vec<String>> = m
        .tiers
        .values
        .iter()
        .map(|tier| {
            let mut row = vec![tier.clone()];
            for f in &families {
                match f.tier(&m.name, tier) {
                    Some(c) => {
                        row.push(format!("{:.2}", c.executed_ratio));
                        row.push(format!("{} / {}", c.fragment.vgprs, c.fragment.waves));
                    }
                    None => row.extend(["-".to_string(), "-".to_string()]),
                }
            }
            row
        })
        .collect();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    print!("{}", weft_cli::tables::table(&header, &rows));
}
