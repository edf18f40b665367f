//! `cargo xtask`: project automation (regenerate the committed `generated/`
//! tree, check it is current, benchmark the compiler).

use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};
use weft_compiler::{BuildOptions, build_library, output};

/// Paths under `generated/` that `regenerate` keeps: measured reports and
/// the gallery have their own commands (timings vary by machine).
const PRESERVED: &[&str] = &["reports", "gallery", "gallery.md"];

#[derive(Parser)]
#[command(name = "cargo xtask", about = "weft project tasks")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Rewrite generated/ from materials/ (atomically, removing stale files).
    Regenerate {
        /// Do not write: fail and list the stale files if generated/ is out of date.
        #[arg(long)]
        check: bool,
    },
    /// Benchmarks (reports, not tests).
    Bench {
        #[command(subcommand)]
        what: Bench,
    },
}

#[derive(Subcommand)]
enum Bench {
    /// Full-library build time, variants per second and no-change rebuild time.
    Compile {
        /// Timed repetitions (the median is reported).
        #[arg(long, default_value_t = 5)]
        runs: usize,
    },
}

fn workspace_root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask is in the workspace")
        .to_path_buf()
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let root = workspace_root();
    match cli.command {
        Command::Regenerate { check } => regenerate(&root, check),
        Command::Bench {
            what: Bench::Compile { runs },
        } => bench_compile(&root, runs.max(1)),
    }
}

fn build(root: &Path, options: &BuildOptions) -> Option<weft_compiler::BuildOutput> {
    match build_library(&root.join("materials"), options, &|_, _, _| {}) {
        Ok(out) => Some(out),
        Err((db, diags)) => {
            let mut stderr = codespan_reporting::term::termcolor::StandardStream::stderr(
                codespan_reporting::term::termcolor::ColorChoice::Auto,
            );
            diags.emit(&db, &mut stderr);
            eprintln!("error: materials do not compile; generated/ left untouched");
            None
        }
    }
}

fn regenerate(root: &Path, check: bool) -> ExitCode {
    let Some(out) = build(root, &BuildOptions::default()) else {
        return ExitCode::FAILURE;
    };
    let generated = root.join("generated");
    if check {
        return match output::check(&generated, &out.files, PRESERVED) {
            Ok(s) if s.is_clean() => {
                println!("generated/ is up to date ({} files)", out.files.len());
                ExitCode::SUCCESS
            }
            Ok(s) => {
                eprintln!("generated/ is stale; run `cargo xtask regenerate`:");
                for f in &s.changed {
                    eprintln!("  changed: generated/{f}");
                }
                for f in &s.missing {
                    eprintln!("  missing: generated/{f}");
                }
                for f in &s.extra {
                    eprintln!("  stale (would be removed): generated/{f}");
                }
                ExitCode::FAILURE
            }
            Err(e) => {
                eprintln!("error: cannot read generated/: {e}");
                ExitCode::FAILURE
            }
        };
    }
    match output::write_atomically(&generated, &out.files, PRESERVED) {
        Ok(()) => {
            println!(
                "regenerated generated/: {} materials, {} variants, {} files",
                out.materials.len(),
                out.variant_count,
                out.files.len()
            );
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: cannot write generated/: {e}");
            ExitCode::FAILURE
        }
    }
}

fn median(mut v: Vec<Duration>) -> Duration {
    v.sort();
    v[v.len() / 2]
}

fn bench_compile(root: &Path, runs: usize) -> ExitCode {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let profile = if cfg!(debug_assertions) {
        "debug"
    } else {
        "release"
    };
    // Warm-up (page cache, lazy statics).
    let Some(first) = build(root, &BuildOptions::default()) else {
        return ExitCode::FAILURE;
    };
    let canonical: usize = first
        .materials
        .iter()
        .map(|m| m.variants.iter().filter(|v| v.alias_of.is_none()).count())
        .sum();

    let mut full = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        build(root, &BuildOptions::default()).expect("built once already");
        full.push(t.elapsed());
    }
    let mut single = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        build(
            root,
            &BuildOptions {
                jobs: Some(1),
                ..Default::default()
            },
        )
        .expect("built once already");
        single.push(t.elapsed());
    }
    // No-change rebuild: inputs hashed, files reused from a previous output.
    let tmp = tempfile::tempdir().expect("temp dir");
    let out_dir = tmp.path().join("generated");
    output::write_atomically(&out_dir, &first.files, &[]).expect("write temp output");
    let mut unchanged = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        let out = build(
            root,
            &BuildOptions {
                reuse_from: Some(out_dir.clone()),
                ..Default::default()
            },
        )
        .expect("built");
        output::write_atomically(&out_dir, &out.files, &[]).expect("write");
        unchanged.push(t.elapsed());
        assert_eq!(
            out.reused.len(),
            out.materials.len(),
            "every material reused"
        );
    }
    let mut lut = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        let l = weft_compiler::bake::split_sum::split_sum_lut(
            weft_compiler::library::SPLIT_SUM_LUT_SIZE,
            weft_compiler::library::SPLIT_SUM_LUT_SAMPLES,
        );
        std::hint::black_box(l);
        lut.push(t.elapsed());
    }
    let (full, single, unchanged, lut) =
        (median(full), median(single), median(unchanged), median(lut));
    let vps = |d: Duration| first.variant_count as f64 / d.as_secs_f64();
    println!(
        "weft compile benchmark ({profile} build of xtask, {threads} threads available, median of {runs} runs)"
    );
    println!(
        "  materials: {}, variants: {} ({} distinct), files: {}",
        first.materials.len(),
        first.variant_count,
        canonical,
        first.files.len()
    );
    println!(
        "  full library build, all threads : {:>8.1} ms  ({:.0} variants/s)",
        full.as_secs_f64() * 1e3,
        vps(full)
    );
    println!(
        "  full library build, 1 thread    : {:>8.1} ms  ({:.0} variants/s)",
        single.as_secs_f64() * 1e3,
        vps(single)
    );
    println!(
        "  no-change rebuild (+ write)     : {:>8.1} ms",
        unchanged.as_secs_f64() * 1e3
    );
    println!(
        "  of which split-sum LUT bake     : {:>8.1} ms (reused on no-change rebuilds)",
        lut.as_secs_f64() * 1e3
    );
    ExitCode::SUCCESS
}
