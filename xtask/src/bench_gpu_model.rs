//! `cargo xtask bench gpu-model`: every pipeline of the library and the
//! scenes compiled by Mesa RADV/ACO on its null device (no GPU) for each
//! family, figures per stage (weft_gpu_stats), written as
//! generated/reports/gpu-model.md and its compact form gpu-model.json
//! (weft_gpu_stats::summary; `--json FILE`: every statistic).

use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;
use weft_gpu_stats::{Options, Selection, WorkerCommand};

/// The hidden subcommand the per-family child processes run (this binary re-executed).
pub const WORKER_SUBCOMMAND: &str = "gpu-stats-worker";

#[derive(clap::Args)]
pub struct GpuModelArgs {
    /// `RADV_FORCE_FAMILY` values (repeatable; default navi21 and gfx1100).
    #[arg(long = "family", value_name = "FAMILY")]
    families: Vec<String>,
    /// Only these materials (repeatable; `standard` is always added, the
    /// baseline of every ratio) and no scenes: a quick look while editing a
    /// material's WGSL. Cannot be combined with --write.
    #[arg(long = "material", value_name = "NAME", conflicts_with = "write")]
    materials: Vec<String>,
    /// Also write generated/reports/gpu-model.md and gpu-model.json.
    #[arg(long)]
    write: bool,
    /// Write every statistic of every executable as JSON to this file
    /// (weft_gpu_stats::FamilyStats per family; about 1 MB, so not in reports/).
    #[arg(long, value_name = "FILE")]
    json: Option<std::path::PathBuf>,
    /// Write each executable's ISA disassembly under this folder
    /// (<family>/<spirv stem>.<pass>.<stage>.s), for reading loops.
    #[arg(long, value_name = "DIR")]
    disassembly: Option<std::path::PathBuf>,
    /// Print only what was written, not the report (regenerate's use).
    #[arg(skip)]
    quiet: bool,
}

impl GpuModelArgs {
    /// The default families, written, the report not printed (as `regenerate` runs it).
    pub fn write_defaults() -> GpuModelArgs {
        GpuModelArgs {
            families: Vec::new(),
            materials: Vec::new(),
            write: true,
            json: None,
            disassembly: None,
            quiet: true,
        }
    }
}

pub fn bench_gpu_model(root: &Path, args: &GpuModelArgs) -> ExitCode {
    match run(root, args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(root: &Path, args: &GpuModelArgs) -> Result<(), String> {
    let families: Vec<String> = if args.families.is_empty() {
        weft_gpu_stats::DEFAULT_FAMILIES
            .iter()
            .map(|f| f.to_string())
            .collect()
    } else {
        args.families.clone()
    };
    let exe = std::env::current_exe().map_err(|e| format!("locating xtask: {e}"))?;
    let options = Options {
        generated: root.join("generated"),
        selection: selection(&args.materials),
        families: families.clone(),
        // Always: the loop-aware model reads it (then it is dropped or written out).
        disassembly: true,
        icd_dirs: None,
        worker: WorkerCommand {
            program: exe,
            args: vec![WORKER_SUBCOMMAND.into()],
        },
    };
    let start = Instant::now();
    let mut stats = weft_gpu_stats::collect(&options).map_err(|e| e.to_string())?;
    let pipelines: usize = stats.iter().map(|f| f.pipelines.len()).sum();
    eprintln!(
        "compiled {pipelines} pipelines ({} families) in {:.1} s",
        stats.len(),
        start.elapsed().as_secs_f64()
    );
    let mut command = "cargo xtask bench gpu-model --write".to_string();
    if !args.families.is_empty() {
        for f in &families {
            command.push_str(&format!(" --family {f}"));
        }
    }
    let md = weft_gpu_stats::report::markdown(&root.join("generated"), &stats, &command)
        .map_err(|e| e.to_string())?;
    // Before the disassembly is dropped or moved out: the model reads it.
    let summary = weft_gpu_stats::summarize(&root.join("generated"), &stats, &command)
        .map_err(|e| e.to_string())?;
    match &args.disassembly {
        Some(dir) => write_disassembly(dir, &mut stats)?,
        None => stats
            .iter_mut()
            .flat_map(|f| f.pipelines.iter_mut())
            .flat_map(|p| p.stages.iter_mut())
            .for_each(|s| s.disassembly = None),
    }
    if !args.quiet {
        print!("{md}");
    }
    if args.write {
        let reports = root.join("generated/reports");
        std::fs::create_dir_all(&reports).map_err(|e| format!("{}: {e}", reports.display()))?;
        let md_path = reports.join("gpu-model.md");
        std::fs::write(&md_path, &md).map_err(|e| format!("{}: {e}", md_path.display()))?;
        println!("wrote {}", md_path.display());
        let json_path = reports.join(weft_gpu_stats::summary::FILE_NAME);
        std::fs::write(&json_path, summary.to_json())
            .map_err(|e| format!("{}: {e}", json_path.display()))?;
        println!("wrote {}", json_path.display());
        crate::bench_shading::rewrite_cost_tables(root)?;
    }
    if let Some(json_path) = &args.json {
        let mut json = serde_json::to_string(&stats).map_err(|e| e.to_string())?;
        json.push('\n');
        std::fs::write(json_path, json).map_err(|e| format!("{}: {e}", json_path.display()))?;
        println!("wrote {}", json_path.display());
    }
    Ok(())
}

/// Everything, or the named materials and the baseline without scenes.
fn selection(materials: &[String]) -> Selection {
    if materials.is_empty() {
        return Selection {
            scenes: true,
            ..Default::default()
        };
    }
    let mut only = materials.to_vec();
    if !only.iter().any(|m| m == "standard") {
        only.push("standard".into());
    }
    Selection {
        materials: Some(only),
        tiers: None,
        variants: None,
        scenes: false,
    }
}

/// Moves the disassembly out of the figures into one file per executable.
fn write_disassembly(dir: &Path, stats: &mut [weft_gpu_stats::FamilyStats]) -> Result<(), String> {
    let mut count = 0;
    for f in stats.iter_mut() {
        let fam_dir = dir.join(&f.family);
        for p in &mut f.pipelines {
            let stem = p.source.spirv.trim_end_matches(".spv").replace('/', ".");
            let sub = fam_dir.join(&p.source.kind);
            std::fs::create_dir_all(&sub).map_err(|e| format!("{}: {e}", sub.display()))?;
            for s in &mut p.stages {
                if let Some(text) = s.disassembly.take() {
                    let path = sub.join(format!("{stem}.{}.{}.s", p.pass, s.stage));
                    std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
                    count += 1;
                }
            }
        }
    }
    eprintln!("wrote {count} disassembly files under {}", dir.display());
    Ok(())
}
