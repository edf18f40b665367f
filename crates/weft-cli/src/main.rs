//! `weft`: build, check and inspect weft materials from the command line.

use clap::{Parser, Subcommand, ValueEnum};
use codespan_reporting::term::termcolor::{ColorChoice, StandardStream};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use weft_compiler::{BuildOptions, BuildOutput, output};
use weft_front::{Diagnostics, SourceDb};
use weft_meta::MaterialMetadata;

mod bench;
mod preview;
mod scene_build;
mod stability;

use bench::{BENCH_EXAMPLES, BenchArgs, bench, print_measurements};
use preview::{PREVIEW_EXAMPLES, PreviewArgs, preview};
use stability::{STABILITY_EXAMPLES, StabilityArgs, stability};

/// Paths under an output folder that `weft build` never removes: measured
/// reports and the gallery are written by their own commands.
pub const PRESERVED: &[&str] = &["reports", "gallery", "gallery.md"];

#[derive(Parser)]
#[command(
    name = "weft",
    version,
    about = "Compile weft materials (TOML + WGSL) into validated WGSL, SPIR-V and HLSL variants with inspector metadata",
    after_help = "Examples:\n  weft build                                   build every material under materials/ into generated/\n  weft build materials/standard/standard.toml -o out\n  weft check tests/diagnostics/materials/bad/unknown_key.toml\n  weft inspect materials/standard/standard.toml\n  weft variants materials/standard/standard.toml\n  weft preview materials/standard/standard.toml -o out.png --preset gold"
)]
struct Cli {
    /// Print nothing but errors.
    #[arg(long, short, global = true)]
    quiet: bool,
    /// When to colour diagnostics.
    #[arg(long, global = true, value_enum, default_value_t = Color::Auto)]
    color: Color,
    #[command(subcommand)]
    command: Command,
}

#[derive(Clone, Copy, ValueEnum)]
pub(crate) enum Color {
    Auto,
    Always,
    Never,
}

#[derive(Subcommand)]
enum Command {
    /// Compile materials (folders or .toml files) into an output folder, atomically.
    #[command(
        after_help = "Examples:\n  weft build\n  weft build materials -o generated --jobs 2\n  weft build materials/standard/standard.toml -o /tmp/out --force\n  weft build --scene scenes/fitting_room.scene.toml -o out"
    )]
    Build {
        /// A materials folder (with lib/ and one folder per material) or material .toml files.
        #[arg(default_value = "materials")]
        paths: Vec<PathBuf>,
        /// Output folder; replaced atomically (reports/ and the gallery are kept).
        /// Default: generated. With --scene, only `<out>/<scene>/` is replaced
        /// (default out: generated/scenes), its siblings are left alone.
        #[arg(long, short)]
        out: Option<PathBuf>,
        /// Worker threads (default: all cores). Output bytes do not depend on it.
        #[arg(long, short)]
        jobs: Option<usize>,
        /// Recompile materials whose inputs are unchanged instead of reusing their files.
        #[arg(long)]
        force: bool,
        /// Build exactly the shaders this scene manifest needs (`scenes/<name>.scene.toml`),
        /// each specialised for its instance, into `<out>/<scene>/`.
        #[arg(long, conflicts_with = "paths")]
        scene: Option<PathBuf>,
        /// With --scene: per-tier costs measured on your own GPU (JSON, see docs/scenes.md)
        /// for `tier = "auto"` instead of the committed lavapipe bench figures.
        #[arg(long, requires = "scene")]
        tier_costs: Option<PathBuf>,
    },
    /// Report diagnostics only; writes nothing. Exit status 1 on any error.
    #[command(
        after_help = "Examples:\n  weft check\n  weft check materials/standard/standard.toml"
    )]
    Check {
        #[arg(default_value = "materials")]
        paths: Vec<PathBuf>,
    },
    /// Show a material's parameters, keywords, tiers and variants as tables.
    #[command(
        after_help = "Examples:\n  weft inspect materials/standard/standard.toml\n  weft inspect generated/standard/standard.meta.json"
    )]
    Inspect {
        /// A material .toml file or a generated .meta.json file.
        path: PathBuf,
    },
    /// List a material's variants, their aliases and files.
    #[command(after_help = "Examples:\n  weft variants materials/standard/standard.toml")]
    Variants { path: PathBuf },
    /// Render a material with the wgpu runtime (Vulkan; lavapipe without a GPU) to a PNG.
    #[command(after_help = PREVIEW_EXAMPLES)]
    Preview(PreviewArgs),
    /// Sweep materials for NaN, Inf, negative and > 65504 outputs over their parameter grid and
    /// geometric extremes (Vulkan; lavapipe without a GPU). Exit status 1 on any.
    #[command(after_help = STABILITY_EXAMPLES)]
    Stability(StabilityArgs),
    /// Measure every material x tier of a generated folder: GPU time per frame, ratio to
    /// standard's fast tier, SPIR-V instructions and error against the reference tier.
    #[command(after_help = BENCH_EXAMPLES)]
    Bench(BenchArgs),
}

fn color_choice(c: Color) -> ColorChoice {
    match c {
        Color::Always => ColorChoice::Always,
        Color::Never => ColorChoice::Never,
        Color::Auto if std::io::stderr().is_terminal() => ColorChoice::Auto,
        Color::Auto => ColorChoice::Never,
    }
}

pub(crate) fn report(db: &SourceDb, diags: &Diagnostics, color: Color) {
    let mut stderr = StandardStream::stderr(color_choice(color));
    diags.emit(db, &mut stderr);
    let n = diags.error_count();
    if n > 0 {
        eprintln!(
            "error: {n} error{} found; nothing was written",
            if n == 1 { "" } else { "s" }
        );
    }
}

/// Builds from folders and/or files.
fn build(
    paths: &[PathBuf],
    options: &BuildOptions,
    quiet: bool,
) -> Result<BuildOutput, (SourceDb, Diagnostics)> {
    let show = !quiet && std::io::stderr().is_terminal();
    let progress = move |i: usize, n: usize, name: &str| {
        if show {
            if name.is_empty() {
                eprint!("\r\x1b[K");
            } else {
                eprint!("\r\x1b[K[{}/{n}] compiling {name}", i + 1);
            }
        }
    };
    if let [dir] = paths
        && dir.is_dir()
    {
        return weft_compiler::build_library(dir, options, &progress);
    }
    let mut files = Vec::new();
    for p in paths {
        if p.is_dir() {
            files.extend(weft_compiler::library::discover(p).unwrap_or_default());
        } else {
            files.push(p.clone());
        }
    }
    weft_compiler::build_materials(&files, None, options, &progress)
}

fn load_metadata(path: &Path, color: Color) -> Option<Vec<MaterialMetadata>> {
    if path.extension().is_some_and(|e| e == "json") {
        let bytes = match std::fs::read(path) {
            Ok(b) => b,
            Err(e) => {
                eprintln!("error: cannot read `{}`: {e}", path.display());
                return None;
            }
        };
        return match serde_json::from_slice(&bytes) {
            Ok(m) => Some(vec![m]),
            Err(e) => {
                eprintln!("error: `{}` is not weft metadata: {e}", path.display());
                None
            }
        };
    }
    match build(&[path.to_path_buf()], &BuildOptions::default(), true) {
        Ok(out) => Some(out.materials),
        Err((db, diags)) => {
            report(&db, &diags, color);
            None
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Build {
            scene: Some(scene),
            out,
            tier_costs,
            ..
        } => {
            let out = out.unwrap_or_else(|| PathBuf::from("generated/scenes"));
            if scene_build::build_scene_command(
                &scene,
                &out,
                tier_costs.as_ref(),
                cli.quiet,
                cli.color,
            ) {
                ExitCode::SUCCESS
            } else {
                ExitCode::FAILURE
            }
        }
        Command::Build {
            paths,
            out,
            jobs,
            force,
            ..
        } => {
            let out = out.unwrap_or_else(|| PathBuf::from("generated"));
            let started = std::time::Instant::now();
            let options = BuildOptions {
                jobs,
                reuse_from: (!force).then(|| out.clone()),
            };
            match build(&paths, &options, cli.quiet) {
                Ok(result) => {
                    if let Some((db, warnings)) = &result.warnings {
                        report(db, warnings, cli.color);
                    }
                    if let Err(e) = output::write_atomically(&out, &result.files, PRESERVED) {
                        eprintln!("error: cannot write `{}`: {e}", out.display());
                        return ExitCode::FAILURE;
                    }
                    if !cli.quiet {
                        println!(
                            "built {} material(s), {} variant(s), {} file(s) into {} in {:.2}s{}",
                            result.materials.len(),
                            result.variant_count,
                            result.files.len(),
                            out.display(),
                            started.elapsed().as_secs_f64(),
                            if result.reused.is_empty() {
                                String::new()
                            } else {
                                format!(" ({} unchanged)", result.reused.len())
                            }
                        );
                    }
                    ExitCode::SUCCESS
                }
                Err((db, diags)) => {
                    report(&db, &diags, cli.color);
                    ExitCode::FAILURE
                }
            }
        }
        Command::Check { paths } => match build(&paths, &BuildOptions::default(), cli.quiet) {
            Ok(result) => {
                if let Some((db, warnings)) = &result.warnings {
                    report(db, warnings, cli.color);
                }
                if !cli.quiet {
                    println!(
                        "ok: {} material(s), {} variant(s)",
                        result.materials.len(),
                        result.variant_count
                    );
                }
                ExitCode::SUCCESS
            }
            Err((db, diags)) => {
                report(&db, &diags, cli.color);
                ExitCode::FAILURE
            }
        },
        Command::Inspect { path } => match load_metadata(&path, cli.color) {
            Some(mut ms) => {
                for m in &mut ms {
                    print!("{}", weft_cli::tables::inspect(m));
                    print_measurements(m, &path);
                }
                ExitCode::SUCCESS
            }
            None => ExitCode::FAILURE,
        },
        Command::Variants { path } => match load_metadata(&path, cli.color) {
            Some(ms) => {
                for m in &ms {
                    print!("{}", weft_cli::tables::variants(m));
                }
                ExitCode::SUCCESS
            }
            None => ExitCode::FAILURE,
        },
        Command::Stability(args) => match stability(&args, cli.quiet, cli.color) {
            Ok(true) => ExitCode::SUCCESS,
            Ok(false) => ExitCode::FAILURE,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::FAILURE
            }
        },
        Command::Preview(args) => match preview(&args, cli.quiet, cli.color) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::FAILURE
            }
        },
        Command::Bench(args) => match bench(&args) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::FAILURE
            }
        },
    }
}
