//! `weft`: build, check and inspect weft materials from the command line.

use clap::{Parser, Subcommand, ValueEnum};
use codespan_reporting::term::termcolor::{ColorChoice, StandardStream};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;
use weft_compiler::{BuildOptions, output};
use weft_front::{Diagnostics, SourceDb};
use weft_meta::MaterialMetadata;

mod bench;
mod library_build;
mod preview;
mod scene_build;
mod scene_model;
mod stability;

use bench::{BENCH_EXAMPLES, BenchArgs, bench, print_measurements};
use library_build::{LibraryBuild, build};
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
        /// Build exactly the shaders this scene needs, each specialised for its instance,
        /// into `<out>/<scene>/`: a manifest (`scenes/<name>.scene.toml`) or a glTF 2.0
        /// file (`.gltf`, `.glb`; docs/gltf.md).
        #[arg(long, conflicts_with = "paths")]
        scene: Option<PathBuf>,
        /// With a glTF --scene: the materials root its materials map into (default:
        /// ./materials, else a materials/ beside an ancestor folder of the file).
        #[arg(long, value_name = "DIR", requires = "scene")]
        materials: Option<PathBuf>,
        /// With --scene: per-tier costs measured on your own GPU (JSON, see docs/scenes.md)
        /// for `tier = "auto"` instead of the committed GPU model
        /// (generated/reports/gpu-model.json).
        #[arg(long, requires = "scene")]
        tier_costs: Option<PathBuf>,
        /// With --scene: model what specialising saves on AMD's shader compiler
        /// (Mesa RADV on its null device; no GPU needed, package mesa-vulkan-drivers),
        /// for RDNA2 (navi21) and RDNA3 (gfx1100): printed with the funnel and
        /// recorded in the scene metadata (`funnel.modelled`).
        #[arg(long, requires = "scene")]
        gpu_model: bool,
        /// Seconds to wait for another build writing into the same output folder
        /// (they are serialised by a lock file, `.<out>.lock`); 0 fails at once.
        #[arg(long, value_name = "SECONDS", default_value = "120", value_parser = parse_lock_timeout)]
        lock_timeout: Duration,
        /// Compile only the materials of shard K of N (by a hash of their names) into
        /// this output folder; join the N folders with `weft merge` (docs/scaling.md).
        #[arg(long, value_name = "K/N", conflicts_with = "scene")]
        shard: Option<weft_compiler::shard::Shard>,
        /// A shared cache of compiled units (material × variant), addressed by
        /// their inputs; any checkout or machine may share it (docs/scaling.md).
        /// Default: $WEFT_CACHE_DIR when set.
        #[arg(
            long,
            value_name = "DIR",
            env = "WEFT_CACHE_DIR",
            conflicts_with = "scene"
        )]
        cache_dir: Option<PathBuf>,
        /// Compile again this share (0 to 100) of the units served from the cache
        /// and fail if any differs from its compiled bytes. Units are signed and
        /// checked with $WEFT_CACHE_KEY when it is set (docs/scaling.md, "Trust").
        #[arg(long, value_name = "PERCENT", default_value_t = 0,
              value_parser = clap::value_parser!(u8).range(0..=100))]
        cache_verify: u8,
    },
    /// Join the output folders of `weft build --shard k/n` (all n of them) into one,
    /// byte-identical to an unsharded build; replaced atomically like `build`'s.
    #[command(
        after_help = "Examples:\n  weft build --shard 1/2 -o out-1 && weft build --shard 2/2 -o out-2\n  weft merge out-1 out-2 -o generated"
    )]
    Merge {
        /// The shards' output folders.
        #[arg(required = true)]
        shards: Vec<PathBuf>,
        /// Output folder (reports/ and the gallery are kept). Default: generated.
        #[arg(long, short)]
        out: Option<PathBuf>,
        /// Seconds to wait for another build writing into the same output folder.
        #[arg(long, value_name = "SECONDS", default_value = "120", value_parser = parse_lock_timeout)]
        lock_timeout: Duration,
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
    /// Live inspector: serve a browser material editor (panel from the metadata, WebGPU
    /// preview) on 127.0.0.1, rebuilt and pushed to the page on every change; or --export it.
    #[command(after_help = weft_serve::EXAMPLES)]
    Serve(weft_serve::ServeArgs),
    /// Internal: compiles one GPU family's pipelines for `build --scene --gpu-model`
    /// (a request on stdin, figures on stdout; weft_gpu_stats::worker).
    #[command(name = "gpu-stats-worker", hide = true)]
    GpuStatsWorker,
}

/// The longest `--lock-timeout`: a day. Longer waits are a mistake, and
/// much larger numbers do not fit a `Duration`.
const MAX_LOCK_TIMEOUT_SECS: f64 = 86_400.0;

/// `--lock-timeout`: seconds from 0 to [`MAX_LOCK_TIMEOUT_SECS`].
fn parse_lock_timeout(s: &str) -> Result<Duration, String> {
    let secs: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number of seconds"))?;
    if !(0.0..=MAX_LOCK_TIMEOUT_SECS).contains(&secs) {
        return Err(format!(
            "{s} s is out of range: give 0 to {MAX_LOCK_TIMEOUT_SECS:.0} seconds (a day)"
        ));
    }
    Duration::try_from_secs_f64(secs).map_err(|e| e.to_string())
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

/// Locks the output folder `dir` for this build (see `weft_compiler::output`),
/// waiting up to `wait` for another build writing into it; prints why not.
pub(crate) fn lock_output(dir: &Path, wait: Duration, quiet: bool) -> Option<output::OutputLock> {
    let on_wait = &mut |holder: &str| {
        if !quiet {
            eprintln!(
                "waiting up to {:.0} s (--lock-timeout) for another build writing into `{}` ({holder})",
                wait.as_secs_f64(),
                dir.display()
            );
        }
    };
    match output::OutputLock::acquire(dir, wait, on_wait) {
        Ok(lock) => Some(lock),
        Err(e) => {
            let hint = if e.kind() == std::io::ErrorKind::ResourceBusy {
                "; wait for it, or give a longer --lock-timeout"
            } else {
                ""
            };
            eprintln!("error: cannot write `{}`: {e}{hint}", dir.display());
            None
        }
    }
}

fn load_metadata(path: &Path, color: Color) -> Option<Vec<MaterialMetadata>> {
    if path.extension().is_some_and(|e| e == "json") {
        let bytes = match weft_meta::files::read_regular(path, weft_meta::files::MAX_TEXT_BYTES) {
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
    if matches!(cli.command, Command::Stability(_)) {
        // SAFETY: first in `main`, before any thread or device exists.
        unsafe { weft_render::probe::draw_sweeps_on_the_calling_thread() };
    }
    match cli.command {
        Command::Serve(args) => weft_serve::command(&args, cli.quiet),
        Command::GpuStatsWorker => match weft_gpu_stats::worker::serve_stdio() {
            0 => ExitCode::SUCCESS,
            _ => ExitCode::FAILURE,
        },
        Command::Build {
            scene: Some(scene),
            out,
            tier_costs,
            materials,
            lock_timeout,
            gpu_model,
            ..
        } => {
            let out = out.unwrap_or_else(|| PathBuf::from("generated/scenes"));
            if scene_build::build_scene_command(
                &scene_build::SceneBuild {
                    scene: &scene,
                    out: &out,
                    gltf_materials: materials.as_deref(),
                    tier_costs: tier_costs.as_ref(),
                    lock_wait: lock_timeout,
                    gpu_model,
                },
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
            lock_timeout,
            shard,
            cache_dir,
            cache_verify,
            ..
        } => library_build::build_command(
            LibraryBuild {
                paths,
                out,
                jobs,
                force,
                lock_timeout,
                shard,
                cache_dir,
                cache_verify,
            },
            cli.quiet,
            cli.color,
        ),
        Command::Check { paths } => library_build::check_command(&paths, cli.quiet, cli.color),
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
        Command::Merge {
            shards,
            out,
            lock_timeout,
        } => library_build::merge_command(&shards, out, lock_timeout, cli.quiet),
        Command::Bench(args) => match bench(&args) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                ExitCode::FAILURE
            }
        },
    }
}
