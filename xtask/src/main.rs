//! `cargo xtask`: project automation (regenerate the committed `generated/`
//! tree, check it is current, benchmark the compiler).

use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};
use weft_compiler::{BuildOptions, output};

mod bench_gpu;
mod bench_gpu_model;
mod bench_scale;
#[cfg(feature = "screenshots")]
mod inspector;
mod scale;
#[cfg(test)]
mod tidy;

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
    /// Rewrite generated/ from materials/ (atomically, removing stale files),
    /// then the bindings table of each material's README (`<!-- weft:bindings:… -->`).
    Regenerate {
        /// Do not write: fail and list the stale files if generated/ or a README's
        /// bindings table is out of date.
        #[arg(long, conflicts_with = "reports")]
        check: bool,
        /// Also run the shading benchmark and rewrite its reports in
        /// generated/reports/ (machine-dependent timings: never done by default).
        #[arg(long)]
        reports: bool,
    },
    /// Re-render every golden under tests/goldens/ (materials' cases and
    /// shipped scenes, removing stale ones); a golden the new render matches
    /// within the tests' FLIP threshold is kept as it is.
    Bless {
        /// Rewrite every golden, even those the new render matches.
        #[arg(long)]
        force: bool,
    },
    /// Render every material, tier and preset: generated/gallery/ (a contact
    /// sheet and one image per case) and generated/gallery.md.
    Gallery,
    /// Generate the character textures (issue 12) into materials/<m>/textures/
    /// (face SDF threshold map and shadow mask, eye matcap, hair flow and
    /// jitter maps, skin curvature map): weft_golden::textures.
    Textures {
        /// Do not write: fail and list the textures that differ from a fresh generation.
        #[arg(long)]
        check: bool,
    },
    /// Screenshots of the live inspector (`weft serve`) in headless Chromium:
    /// docs/inspector/inspector-en.png and inspector-zh.png. Needs the
    /// `screenshots` feature: `cargo xtask-screenshots inspector`.
    Inspector,
    /// Benchmarks (reports, not tests).
    Bench {
        #[command(subcommand)]
        what: Bench,
    },
    /// The per-family child of `bench gpu-model` (not for direct use: it
    /// needs the environment the parent sets).
    #[command(name = "gpu-stats-worker", hide = true)]
    GpuStatsWorker,
}

#[derive(Subcommand)]
enum Bench {
    /// Full-library build time, variants per second and no-change rebuild time.
    Compile {
        /// Timed repetitions (the median is reported).
        #[arg(long, default_value_t = 5)]
        runs: usize,
    },
    /// Synthetic libraries of growing size (≈ 50 to 10 000 variants, derived
    /// from materials/): full build time, cost per variant, peak memory of the
    /// `weft build` process, no-change and one-edit rebuild times, and builds
    /// from a shared cache (release binary).
    Scale(bench_scale::ScaleArgs),
    /// Every pipeline (library variants x passes, f16 files, scene shaders)
    /// compiled by AMD's shader compiler (Mesa RADV/ACO on its null device,
    /// no GPU) for navi21 (RDNA2) and gfx1100 (RDNA3): instructions, VGPRs,
    /// waves per SIMD, inverse throughput per stage.
    GpuModel(bench_gpu_model::GpuModelArgs),
    /// On the first real GPU (WEFT_ADAPTER=hardware unless set): the shading
    /// and scene benches, each tier's GPU ratio beside llvmpipe's and the GPU
    /// model's, written as generated/reports/gpu-<adapter>.md and .json.
    Gpu(bench_gpu::GpuArgs),
    /// Every material x tier: GPU time per frame (timestamp queries), ratio to
    /// standard's fast tier, SPIR-V instructions, error against the reference tier.
    Shading {
        #[command(flatten)]
        args: ShadingArgs,
        /// Also write generated/reports/ (shading.md, <name>.measurements.json, <name>.pareto.svg).
        #[arg(long)]
        write: bool,
    },
    /// The laser film's fast form against its spectral reference over
    /// thickness x cos θ (CIELAB ΔE2000, chart FLIP), evaluated on the GPU.
    Film {
        /// Also write generated/reports/laser-film.md and the table in materials/laser/README.md.
        #[arg(long)]
        write: bool,
    },
    /// The glitter material's glint checks per tier (energy against the
    /// smooth lobe, extremes, half-pixel pan, distance), and each tier's cost.
    Glints {
        /// Also write generated/reports/glitter.glints.md and the table in materials/glitter/README.md.
        #[arg(long)]
        write: bool,
    },
    /// Every shipped scene, generic library variants vs scene-specialised
    /// shaders: GPU time per frame (interleaved rounds), FLIP between the
    /// images, SPIR-V instructions, shaders/files/bytes, build time.
    Scene {
        #[command(flatten)]
        args: SceneArgs,
        /// Also write generated/reports/scenes.md and scenes.json.
        #[arg(long)]
        write: bool,
    },
}

#[derive(clap::Args)]
struct ShadingArgs {
    /// Only these materials (repeatable; standard's fast tier is always timed as the baseline).
    #[arg(long = "material", value_name = "NAME")]
    materials: Vec<String>,
    /// Square image size.
    #[arg(long, default_value_t = 512)]
    size: u32,
    /// Timed frames per tier (median reported).
    #[arg(long, default_value_t = 50)]
    frames: u32,
    /// Untimed frames per tier first.
    #[arg(long, default_value_t = 5)]
    warmup: u32,
    /// Rounds over all tiers the timed frames are split into.
    #[arg(long, default_value_t = 10)]
    rounds: u32,
    /// Time on the CPU (submit to completion) even with timestamp queries.
    #[arg(long)]
    cpu_timer: bool,
    /// A tier whose frames would take longer than this gets fewer (at least 5).
    #[arg(long, default_value_t = 20.0, value_name = "SECONDS")]
    max_seconds_per_tier: f64,
}

impl ShadingArgs {
    fn options(&self) -> weft_golden::shading::ShadingOptions {
        weft_golden::shading::ShadingOptions {
            size: self.size.max(1),
            frames: self.frames.max(1),
            warmup: self.warmup,
            rounds: self.rounds.max(1),
            force_cpu_timer: self.cpu_timer,
            max_seconds_per_tier: self.max_seconds_per_tier,
            materials: self.materials.clone(),
            ..Default::default()
        }
    }
}

#[derive(clap::Args)]
struct SceneArgs {
    /// Image width and height.
    #[arg(long, num_args = 2, value_names = ["W", "H"], default_values_t = [640, 400])]
    size: Vec<u32>,
    /// Rounds of (generic, specialised) draws.
    #[arg(long, default_value_t = 10)]
    rounds: u32,
    /// Timed frames per arm and round (the round's figure is their median).
    #[arg(long, default_value_t = 10)]
    frames: u32,
    /// Only these scenes (repeatable; default: every scenes/*.scene.toml).
    #[arg(long = "scene", value_name = "NAME")]
    scenes: Vec<String>,
    /// Time on the CPU (submit to completion) even with timestamp queries.
    #[arg(long)]
    cpu_timer: bool,
    /// Do not time each instance alone.
    #[arg(long)]
    no_per_instance: bool,
}

impl SceneArgs {
    fn options(&self) -> weft_golden::scene_bench::SceneBenchOptions {
        weft_golden::scene_bench::SceneBenchOptions {
            width: self.size[0].max(1),
            height: self.size[1].max(1),
            rounds: self.rounds.max(1),
            frames: self.frames.max(1),
            force_cpu_timer: self.cpu_timer,
            per_instance: !self.no_per_instance,
            ..Default::default()
        }
    }

    /// The command line that reproduces the run.
    fn command(&self) -> String {
        let o = self.options();
        let mut c = format!(
            "cargo xtask bench scene --write --size {} {} --rounds {} --frames {}",
            o.width, o.height, o.rounds, o.frames
        );
        for s in &self.scenes {
            c.push_str(&format!(" --scene {s}"));
        }
        for (on, flag) in [
            (self.cpu_timer, " --cpu-timer"),
            (self.no_per_instance, " --no-per-instance"),
        ] {
            if on {
                c.push_str(flag);
            }
        }
        c
    }
}

/// The checkout xtask works on: its own, or `WEFT_ROOT` when set (a prebuilt
/// xtask run against another worktree of the repository).
fn workspace_root() -> PathBuf {
    if let Some(root) = std::env::var_os("WEFT_ROOT") {
        return PathBuf::from(root);
    }
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("xtask is in the workspace")
        .to_path_buf()
}

/// `cargo xtask textures [--check]`.
fn textures(root: &Path, check: bool) -> ExitCode {
    use weft_golden::textures;
    if check {
        let stale = textures::stale(root);
        if stale.is_empty() {
            println!("textures are current");
            return ExitCode::SUCCESS;
        }
        for path in stale {
            eprintln!("stale: {path}");
        }
        eprintln!("run `cargo xtask textures` and commit the PNGs");
        return ExitCode::FAILURE;
    }
    match textures::write(root) {
        Ok(written) => {
            for path in &written {
                println!("wrote {}", path.display());
            }
            if written.is_empty() {
                println!("textures are current");
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("cannot write the textures: {e}");
            ExitCode::FAILURE
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let root = workspace_root();
    match cli.command {
        Command::Regenerate { check, reports } => {
            let status = regenerate(&root, check);
            if !reports || status != ExitCode::SUCCESS {
                return status;
            }
            let measured = bench_shading(
                &root,
                &Default::default(),
                true,
                "cargo xtask regenerate --reports",
            );
            if measured != ExitCode::SUCCESS {
                return measured;
            }
            let film = bench_film(&root, true, "cargo xtask regenerate --reports");
            if film != ExitCode::SUCCESS {
                return film;
            }
            let glints = bench_glints(&root, true, "cargo xtask regenerate --reports");
            if glints != ExitCode::SUCCESS {
                return glints;
            }
            // Scene builds read the reports (`tier = "auto"` costs): build
            // again on the new ones so generated/ is current.
            regenerate(&root, false)
        }
        Command::Bless { force } => bless(&root, force),
        Command::Gallery => gallery(&root),
        #[cfg(feature = "screenshots")]
        Command::Inspector => inspector::inspector(&root),
        #[cfg(not(feature = "screenshots"))]
        Command::Inspector => {
            eprintln!(
                "error: screenshots need the `screenshots` feature (headless Chromium's driver): \
                 run `cargo xtask-screenshots inspector`"
            );
            ExitCode::FAILURE
        }
        Command::Textures { check } => textures(&root, check),
        Command::Bench {
            what: Bench::Compile { runs },
        } => bench_compile(&root, runs.max(1)),
        Command::Bench {
            what: Bench::Scale(args),
        } => bench_scale::bench_scale(&root, &args),
        Command::Bench {
            what: Bench::GpuModel(args),
        } => bench_gpu_model::bench_gpu_model(&root, &args),
        Command::Bench {
            what: Bench::Gpu(args),
        } => bench_gpu::bench_gpu(&root, &args),
        Command::GpuStatsWorker => match weft_gpu_stats::worker::serve_stdio() {
            0 => ExitCode::SUCCESS,
            _ => ExitCode::FAILURE,
        },
        Command::Bench {
            what: Bench::Film { write },
        } => bench_film(&root, write, "cargo xtask bench film --write"),
        Command::Bench {
            what: Bench::Glints { write },
        } => bench_glints(&root, write, "cargo xtask bench glints --write"),
        Command::Bench {
            what: Bench::Shading { args, write },
        } => bench_shading(
            &root,
            &args.options(),
            write,
            "cargo xtask bench shading --write",
        ),
        Command::Bench {
            what: Bench::Scene { args, write },
        } => bench_scene(&root, &args, write),
    }
}

/// The whole project: every material, then every scene under `scenes/`
/// (files under `scenes/<scene>/`), `auto` tiers measured on lavapipe.
fn build(root: &Path, options: &BuildOptions) -> Option<weft_compiler::BuildOutput> {
    match weft_golden::project::build_project(root, options) {
        Ok(out) => Some(out),
        Err((db, diags)) => {
            let mut stderr = codespan_reporting::term::termcolor::StandardStream::stderr(
                codespan_reporting::term::termcolor::ColorChoice::Auto,
            );
            diags.emit(&db, &mut stderr);
            eprintln!("error: materials or scenes do not compile; generated/ left untouched");
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
        match readme_binding_tables(root, &out.files, true) {
            Ok(stale) if stale.is_empty() => {}
            Ok(stale) => {
                eprintln!(
                    "bindings tables in material READMEs are stale; run `cargo xtask regenerate`:"
                );
                for p in &stale {
                    eprintln!("  {}", p.strip_prefix(root).unwrap_or(p).display());
                }
                return ExitCode::FAILURE;
            }
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::FAILURE;
            }
        }
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
            match readme_binding_tables(root, &out.files, false) {
                Ok(updated) => {
                    for p in updated {
                        println!("updated the bindings table in {}", p.display());
                    }
                    ExitCode::SUCCESS
                }
                Err(e) => {
                    eprintln!("error: {e}");
                    ExitCode::FAILURE
                }
            }
        }
        Err(e) => {
            eprintln!("error: cannot write generated/: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The bindings table of each material's README (`<!-- weft:bindings:… -->`,
/// `weft_golden::bindings`), from the metadata just built: rewritten, or with
/// `check` only compared. Returns the READMEs whose table changed (or would).
/// A README without the markers is left alone (tests/metadata_contract.rs
/// requires them in every material's README).
fn readme_binding_tables(
    root: &Path,
    files: &std::collections::BTreeMap<String, Vec<u8>>,
    check: bool,
) -> Result<Vec<PathBuf>, String> {
    use weft_golden::{bindings, shading::replace_marked};
    let mut changed = Vec::new();
    for (rel, bytes) in files {
        let mut parts = rel.split('/');
        let (Some(dir), Some(file), None) = (parts.next(), parts.next(), parts.next()) else {
            continue;
        };
        if file != format!("{dir}.meta.json") {
            continue;
        }
        let meta: weft_meta::MaterialMetadata =
            serde_json::from_slice(bytes).map_err(|e| format!("generated/{rel}: {e}"))?;
        let readme = root.join("materials").join(&meta.name).join("README.md");
        let Ok(text) = std::fs::read_to_string(&readme) else {
            continue;
        };
        let Some(new) = replace_marked(&text, bindings::MARKER, &bindings::readme_table(&meta))
        else {
            continue;
        };
        if new != text {
            if !check {
                std::fs::write(&readme, new).map_err(|e| format!("{}: {e}", readme.display()))?;
            }
            changed.push(readme);
        }
    }
    Ok(changed)
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
    // No-change rebuild of the library, as `weft build` does it: inputs
    // loaded and hashed, unchanged materials kept on disk unread, nothing
    // written when the folder already holds the build (scenes are not reused
    // and not included here).
    let tmp = tempfile::tempdir().expect("temp dir");
    let out_dir = tmp.path().join("generated");
    let materials = root.join("materials");
    let library = weft_compiler::build_library(&materials, &BuildOptions::default(), &|_, _, _| {})
        .unwrap_or_else(|_| panic!("materials/ built once already"));
    output::write_atomically(&out_dir, &library.files, &[]).expect("write temp output");
    drop(library);
    let lock = output::OutputLock::acquire(&out_dir, output::DEFAULT_LOCK_WAIT, &mut |_| {})
        .expect("lock temp output");
    let paths = weft_compiler::library::discover(&materials).expect("materials/");
    let mut unchanged = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        let options = BuildOptions {
            reuse_from: Some(out_dir.clone()),
            ..Default::default()
        };
        let built = weft_compiler::folder_build::build_into(
            &paths,
            Some(&materials),
            &lock,
            &options,
            &[],
            &[],
            &|_, _, _| {},
        )
        .unwrap_or_else(|_| panic!("materials/ built once already"));
        unchanged.push(t.elapsed());
        assert!(!built.wrote, "nothing to write");
        assert_eq!(
            built.output.reused.len(),
            built.output.material_count(),
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
        "  no-change library rebuild       : {:>8.1} ms (as `weft build`: nothing rewritten)",
        unchanged.as_secs_f64() * 1e3
    );
    println!(
        "  of which split-sum LUT bake     : {:>8.1} ms (reused on no-change rebuilds)",
        lut.as_secs_f64() * 1e3
    );
    ExitCode::SUCCESS
}

/// Runs the shading benchmark on generated/, prints the table and, with
/// `write`, rewrites its files in generated/reports/.
fn bench_shading(
    root: &Path,
    options: &weft_golden::shading::ShadingOptions,
    write: bool,
    command: &str,
) -> ExitCode {
    use weft_golden::shading;
    let generated = root.join("generated");
    // The cost floor (an unlit fill) is timed in the same run.
    let options = &shading::ShadingOptions {
        floor: Some(root.join("materials")),
        ..options.clone()
    };
    let report = match shading::run(&generated, options, &mut |s| eprintln!("{s}")) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    println!("{}\n", shading::describe(&report));
    print!("{}", shading::markdown_table(&report.materials));
    print!("{}", shading::floor_line(&report));
    println!("\nbench shading: {:.1} s", report.seconds);
    // Materials drawing instances from a parameter (shells): the count
    // against cost and error (weft_golden::shells).
    let shell_options = weft_golden::shells::ShellOptions {
        force_cpu_timer: options.force_cpu_timer,
        fins: Some(root.join("materials")),
        ..Default::default()
    };
    let shells =
        match weft_golden::shells::run(&generated, &options.materials, &shell_options, &mut |s| {
            eprintln!("{s}")
        }) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("error: shell bench: {e}");
                return ExitCode::FAILURE;
            }
        };
    for r in &shells {
        println!(
            "\n{} shells:\n{}{}",
            r.material,
            weft_golden::shells::markdown_table(r),
            weft_golden::shells::silhouette_section(r)
        );
    }
    if write {
        let model = weft_meta::gpu_model::ModelSummary::load(&generated.join("reports")).ok();
        match shading::write_reports(&generated.join("reports"), &report, command, model.as_ref()) {
            Ok(files) => println!("wrote {} files in generated/reports/", files.len()),
            Err(e) => {
                eprintln!("error: cannot write reports: {e}");
                return ExitCode::FAILURE;
            }
        }
        match weft_golden::shells::write_reports(&generated.join("reports"), &shells, command) {
            Ok(files) => println!("wrote {} shell reports in generated/reports/", files.len()),
            Err(e) => {
                eprintln!("error: cannot write the shell reports: {e}");
                return ExitCode::FAILURE;
            }
        }
        if let Err(e) = write_shell_tables(root, &shells) {
            eprintln!("error: cannot update the shell tables: {e}");
            return ExitCode::FAILURE;
        }
        if let Err(e) = write_tier_tables(root, &report.materials) {
            eprintln!("error: cannot update the tier tables: {e}");
            return ExitCode::FAILURE;
        }
    }
    ExitCode::SUCCESS
}

/// Measures the laser film (`weft_golden::film`), prints the table and, with
/// `write`, rewrites generated/reports/laser-film.md and the table between
/// `<!-- weft:film:… -->` in materials/laser/README.md.
fn bench_film(root: &Path, write: bool, command: &str) -> ExitCode {
    use weft_golden::film;
    let run = || -> Result<(), String> {
        let lib = root.join("materials/lib/thin_film.wgsl");
        let source =
            std::fs::read_to_string(&lib).map_err(|e| format!("{}: {e}", lib.display()))?;
        let gpu = weft_render::Gpu::new().map_err(|e| e.to_string())?;
        let measurements = film::CASES
            .iter()
            .map(|case| film::measure(&gpu, &source, case))
            .collect::<Result<Vec<_>, _>>()?;
        print!("{}", film::markdown_table(&measurements));
        if write {
            let report = root.join("generated/reports/laser-film.md");
            let text = film::markdown_report(&measurements, &gpu.describe(), command);
            std::fs::write(&report, text).map_err(|e| format!("{}: {e}", report.display()))?;
            println!("wrote {}", report.display());
            let readme = root.join("materials/laser/README.md");
            let text = std::fs::read_to_string(&readme)
                .map_err(|e| format!("{}: {e}", readme.display()))?;
            let new = weft_golden::shading::replace_marked(
                &text,
                "film",
                &film::markdown_table(&measurements),
            )
            .ok_or_else(|| {
                format!(
                    "{}: no <!-- weft:film:begin/end --> markers",
                    readme.display()
                )
            })?;
            if new != text {
                std::fs::write(&readme, new).map_err(|e| format!("{}: {e}", readme.display()))?;
                println!("updated the film table in {}", readme.display());
            }
        }
        Ok(())
    };
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Measures the glitter glints (`weft_golden::glints`), prints the table and,
/// with `write`, rewrites generated/reports/glitter.glints.md and the table
/// between `<!-- weft:glints:… -->` in materials/glitter/README.md. Fails
/// when a bound is broken (after writing: the report says which).
fn bench_glints(root: &Path, write: bool, command: &str) -> ExitCode {
    use weft_golden::glints;
    let run = || -> Result<Vec<String>, String> {
        let report = glints::measure(&root.join("generated"), &mut |s| eprintln!("{s}"))?;
        print!("{}", glints::markdown_table(&report));
        if write {
            let path = root.join(format!("generated/reports/{}.glints.md", glints::MATERIAL));
            std::fs::write(&path, glints::markdown_report(&report, command))
                .map_err(|e| format!("{}: {e}", path.display()))?;
            println!("wrote {}", path.display());
            let readme = root.join(format!("materials/{}/README.md", glints::MATERIAL));
            let text = std::fs::read_to_string(&readme)
                .map_err(|e| format!("{}: {e}", readme.display()))?;
            let new = weft_golden::shading::replace_marked(
                &text,
                "glints",
                &glints::markdown_table(&report),
            )
            .ok_or_else(|| {
                format!(
                    "{}: no <!-- weft:glints:begin/end --> markers",
                    readme.display()
                )
            })?;
            if new != text {
                std::fs::write(&readme, new).map_err(|e| format!("{}: {e}", readme.display()))?;
                println!("updated the glint table in {}", readme.display());
            }
        }
        Ok(glints::failures(&report))
    };
    match run() {
        Ok(failures) if failures.is_empty() => ExitCode::SUCCESS,
        Ok(failures) => {
            for f in failures {
                eprintln!("error: glint bound broken: {f}");
            }
            ExitCode::FAILURE
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Rewrites each measured material README's shell table
/// (`<!-- weft:shells:… -->`).
fn write_shell_tables(
    root: &Path,
    reports: &[weft_golden::shells::ShellReport],
) -> Result<(), String> {
    for r in reports {
        let path = root.join("materials").join(&r.material).join("README.md");
        let Ok(text) = std::fs::read_to_string(&path) else {
            continue;
        };
        let mut new = text.clone();
        for (marker, table) in [
            ("shells", weft_golden::shells::markdown_table(r)),
            (
                "fins",
                weft_golden::shells::silhouette_table(r) + &weft_golden::shells::fins_table(r),
            ),
        ] {
            if let Some(replaced) = weft_golden::shading::replace_marked(&new, marker, &table) {
                new = replaced;
            }
        }
        if new != text {
            std::fs::write(&path, new).map_err(|e| format!("{}: {e}", path.display()))?;
            println!("updated the shell tables in {}", path.display());
        }
    }
    Ok(())
}

/// Rewrites the measured tier tables between their markers: the README's
/// "Choosing a tier" (`<!-- weft:tiers:… -->`, every material, when all were
/// measured) and each measured material's README (`<!-- weft:ladder:… -->`),
/// timed costs beside the committed GPU model's (when there is one).
fn write_tier_tables(root: &Path, materials: &[weft_meta::Measurements]) -> Result<(), String> {
    use weft_golden::cost_tables::{choosing_tables, ladder_table};
    let model = weft_meta::gpu_model::ModelSummary::load(&root.join("generated/reports")).ok();
    let model = model.as_ref();
    let all = weft_golden::materials(&root.join("generated"))?;
    if all
        .iter()
        .all(|(_, m)| materials.iter().any(|x| x.material == m.name))
    {
        update_marked(
            &root.join("README.md"),
            "tiers",
            &choosing_tables(materials, model),
        )?;
    }
    for m in materials {
        let readme = root.join("materials").join(&m.material).join("README.md");
        update_marked(&readme, "ladder", &ladder_table(m, model))?;
    }
    Ok(())
}

/// Replaces the text between `<!-- weft:<name>:… -->` in `path` (a file
/// without the markers, or missing, is left alone).
fn update_marked(path: &Path, name: &str, content: &str) -> Result<(), String> {
    let Ok(text) = std::fs::read_to_string(path) else {
        return Ok(());
    };
    if let Some(new) = weft_golden::shading::replace_marked(&text, name, content)
        && new != text
    {
        std::fs::write(path, new).map_err(|e| format!("{}: {e}", path.display()))?;
        println!("updated the `{name}` table in {}", path.display());
    }
    Ok(())
}

/// After `bench gpu-model --write`: the docs' cost tables and plots from the
/// committed measurements and the new model, without timing anything again
/// (the tier tables, each material's Pareto plot, shading.md's model section).
pub(crate) fn rewrite_cost_tables(root: &Path) -> Result<(), String> {
    let reports = root.join("generated/reports");
    let model = weft_meta::gpu_model::ModelSummary::load(&reports)?;
    let mut materials = Vec::new();
    for (_, meta) in weft_golden::materials(&root.join("generated"))? {
        let path = reports.join(format!("{}.measurements.json", meta.name));
        let Ok(bytes) = std::fs::read(&path) else {
            continue;
        };
        let m: weft_meta::Measurements =
            serde_json::from_slice(&bytes).map_err(|e| format!("{}: {e}", path.display()))?;
        let svg = reports.join(format!("{}.pareto.svg", m.material));
        std::fs::write(&svg, weft_golden::pareto::pareto_svg(&m, Some(&model)))
            .map_err(|e| format!("{}: {e}", svg.display()))?;
        materials.push(m);
    }
    write_tier_tables(root, &materials)?;
    update_marked(
        &reports.join("shading.md"),
        "gpu-model",
        &weft_golden::cost_tables::model_section(&materials, Some(&model)),
    )?;
    update_marked(
        &reports.join("scenes.md"),
        "gpu-model",
        &weft_golden::cost_tables::scene_model_section(&root.join("generated"), Some(&model))?,
    )?;
    println!(
        "rewrote {} Pareto plots and the model columns from the committed measurements",
        materials.len()
    );
    Ok(())
}

/// The scene manifests under scenes/ (only `names` when given), resolved
/// by the front end for the materials they use.
pub(crate) fn scene_inputs(
    root: &Path,
    names: &[String],
) -> Result<Vec<weft_golden::scene_bench::SceneInput>, String> {
    let dir = root.join("scenes");
    let paths = weft_compiler::scene::discover_scenes(&dir)
        .map_err(|e| format!("cannot read {}: {e}", dir.display()))?;
    let mut inputs = Vec::new();
    for manifest in paths {
        let input = weft_golden::scene_bench::SceneInput {
            manifest,
            materials_root: PathBuf::new(),
            material_tomls: Vec::new(),
        };
        if !names.is_empty() && !names.contains(&input.name()) {
            continue;
        }
        let (mut db, mut diags) = (weft_front::SourceDb::new(), weft_front::Diagnostics::new());
        let Some(scene) = weft_front::scene::load_scene(&input.manifest, &mut db, &mut diags)
        else {
            return Err(diags.render_plain(&db));
        };
        inputs.push(weft_golden::scene_bench::SceneInput {
            materials_root: scene.manifest.materials_root.clone(),
            material_tomls: scene.materials.iter().map(|m| m.path.clone()).collect(),
            ..input
        });
    }
    if let Some(missing) = names
        .iter()
        .find(|n| !inputs.iter().any(|i| &i.name() == *n))
    {
        return Err(format!("no scene `{missing}` in {}", dir.display()));
    }
    Ok(inputs)
}

/// Runs the scene benchmark on generated/, prints the tables and, with
/// `write`, rewrites generated/reports/scenes.md and scenes.json.
fn bench_scene(root: &Path, args: &SceneArgs, write: bool) -> ExitCode {
    use weft_golden::scene_bench;
    if std::env::var_os(scene_bench::LAVAPIPE_THREADS).is_none() {
        // SAFETY: no other thread runs yet (nothing has touched the GPU,
        // rayon or the compiler); lavapipe reads it when the device is made.
        unsafe { std::env::set_var(scene_bench::LAVAPIPE_THREADS, "1") };
    }
    let generated = root.join("generated");
    let command = args.command();
    let result = scene_inputs(root, &args.scenes)
        .and_then(|inputs| {
            scene_bench::run(&generated, &inputs, &args.options(), &mut |s| {
                eprintln!("{s}")
            })
        })
        .and_then(|report| {
            let model = weft_meta::gpu_model::ModelSummary::load(&generated.join("reports")).ok();
            let section =
                weft_golden::cost_tables::scene_model_section(&generated, model.as_ref())?;
            print!(
                "{}",
                scene_bench::markdown_report(&report, &command, &section)
            );
            if write {
                let files = scene_bench::write_reports(
                    &generated.join("reports"),
                    &report,
                    &command,
                    &section,
                )?;
                println!("wrote {} files in generated/reports/", files.len());
            }
            Ok(())
        });
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// Renders every case of every generated material with `render`.
fn render_cases(
    root: &Path,
    size: u32,
    mut each: impl FnMut(&weft_golden::Case, &weft_meta::MaterialMetadata, Vec<u8>),
) -> Result<String, String> {
    let generated = root.join("generated");
    let mut h = weft_golden::Harness::new(&generated).map_err(|e| e.to_string())?;
    for (meta_path, meta) in weft_golden::materials(&generated)? {
        for case in weft_golden::cases(&meta) {
            let image = h
                .render(&meta_path, &case, size, weft_render::ShaderLanguage::Wgsl)
                .map_err(|e| format!("{}/{}: {e}", case.material, case.name))?;
            each(&case, &meta, weft_golden::to_ldr(&image));
        }
    }
    Ok(h.adapter())
}

fn png_bytes(size: u32, rgba: &[u8]) -> Vec<u8> {
    weft_render::encode_png(size, size, rgba).expect("encode PNG")
}

/// Every shipped scene as built into generated/scenes/, drawn whole with its
/// specialised shaders over the sky at `size`: (metadata, sRGB8 RGBA) by name.
#[allow(clippy::type_complexity)]
fn render_scenes(
    root: &Path,
    size: (u32, u32),
) -> Result<Vec<(String, weft_meta::scene::SceneMetadata, Vec<u8>)>, String> {
    use weft_golden::scenes;
    let generated = root.join("generated");
    let mut h = scenes::SceneHarness::new(&generated).map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    for name in scenes::shipped_scenes(root)? {
        let path = scenes::built_scene_path(&generated, &name);
        let scene = weft_render::SceneFile::load(&path)
            .map_err(|e| format!("{name}: {e} (run `cargo xtask regenerate`)"))?;
        let image = h
            .render(
                &scene,
                &weft_render::SceneShaders::Specialised,
                size,
                weft_render::Background::Sky { mip: 0.0 },
            )
            .map_err(|e| format!("scene {name}: {e}"))?;
        out.push((name, scene.metadata, weft_golden::to_ldr(&image)));
    }
    Ok(out)
}

fn bless(root: &Path, force: bool) -> ExitCode {
    let goldens = root.join("tests/goldens");
    let mut files = std::collections::BTreeMap::new();
    // (kept, largest FLIP mean among them)
    let mut kept = (0usize, 0.0f32);
    // A golden the new render matches within the tests' threshold keeps its
    // bytes (re-blessing on another machine does not churn every PNG).
    let mut add = |rel: String, (w, h): (u32, u32), ldr: &[u8]| {
        let old = goldens.join(&rel);
        if !force
            && let Ok((ow, oh, rgba)) = weft_golden::read_png(&old)
            && (ow, oh) == (w, h)
            && let mean = weft_golden::flip(&rgba, ldr, w, h).mean
            && mean <= weft_golden::FLIP_MEAN_THRESHOLD
            && let Ok(bytes) = std::fs::read(&old)
        {
            kept = (kept.0 + 1, kept.1.max(mean));
            files.insert(rel, bytes);
            return;
        }
        files.insert(rel, weft_render::encode_png(w, h, ldr).expect("encode PNG"));
    };
    let size = weft_golden::GOLDEN_SIZE;
    let result = render_cases(root, size, |case, _, ldr| {
        let rel = weft_golden::golden_path(Path::new(""), case);
        add(rel.to_string_lossy().replace('\\', "/"), (size, size), &ldr);
    })
    .and_then(|adapter| {
        let size = weft_golden::scenes::SCENE_GOLDEN_SIZE;
        for (name, _, ldr) in render_scenes(root, size)? {
            let rel = weft_golden::scenes::scene_golden_path(Path::new(""), &name);
            add(rel.to_string_lossy().replace('\\', "/"), size, &ldr);
        }
        Ok(adapter)
    });
    match result.and_then(|adapter| {
        output::write_atomically(&goldens, &files, &[]).map_err(|e| e.to_string())?;
        Ok(adapter)
    }) {
        Ok(adapter) => {
            println!(
                "blessed {} goldens in tests/goldens/ on {adapter}",
                files.len()
            );
            if kept.0 > 0 {
                println!(
                    "kept {} of them unchanged: their new renders match within FLIP mean {} (largest {:.5}); `--force` rewrites them",
                    kept.0,
                    weft_golden::FLIP_MEAN_THRESHOLD,
                    kept.1
                );
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

const GALLERY_SIZE: u32 = 160;
/// Size of a scene's image in the gallery.
const SCENE_GALLERY_SIZE: (u32, u32) = (480, 360);

fn gallery(root: &Path) -> ExitCode {
    let mut files = std::collections::BTreeMap::new();
    let mut tiles = Vec::new();
    let mut sections: Vec<(weft_meta::MaterialMetadata, Vec<String>)> = Vec::new();
    let result = render_cases(root, GALLERY_SIZE, |case, meta, ldr| {
        let rel = format!("{}/{}.png", case.material, case.name);
        files.insert(rel.clone(), png_bytes(GALLERY_SIZE, &ldr));
        if !case.name.ends_with(".cloth") || case.name == "default.cloth" {
            tiles.push(ldr);
        }
        match sections.last_mut() {
            Some((m, cases)) if m.name == meta.name => cases.push(case.name.clone()),
            _ => sections.push((meta.clone(), vec![case.name.clone()])),
        }
    });
    let adapter = match result {
        Ok(a) => a,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let scenes = match render_scenes(root, SCENE_GALLERY_SIZE) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    for (name, _, ldr) in &scenes {
        let (w, h) = SCENE_GALLERY_SIZE;
        files.insert(
            format!("scenes/{name}.png"),
            weft_render::encode_png(w, h, ldr).expect("encode PNG"),
        );
    }
    let (w, h, sheet) = weft_golden::contact_sheet(&tiles, GALLERY_SIZE, 8);
    files.insert(
        "contact_sheet.png".into(),
        weft_render::encode_png(w, h, &sheet).expect("encode PNG"),
    );
    let generated = root.join("generated");
    // Measured tiers, when `cargo xtask regenerate --reports` left reports.
    for (m, _) in &mut sections {
        let meta_path = generated
            .join(&m.name)
            .join(format!("{}.meta.json", m.name));
        if let Err(e) = m.attach_measurements(&meta_path) {
            eprintln!("warning: ignoring measurements: {e}");
        }
    }
    let mut md = gallery_markdown(&sections, &adapter);
    md.push_str(&scenes_markdown(&scenes));
    let write = output::write_atomically(&generated.join("gallery"), &files, &[])
        .and_then(|()| std::fs::write(generated.join("gallery.md"), md));
    match write {
        Ok(()) => {
            println!(
                "gallery: {} images + contact sheet in generated/gallery/, generated/gallery.md",
                files.len() - 1
            );
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: cannot write the gallery: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The gallery's scene section: each shipped scene's image and its instances.
fn scenes_markdown(scenes: &[(String, weft_meta::scene::SceneMetadata, Vec<u8>)]) -> String {
    use std::fmt::Write;
    let (w, h) = SCENE_GALLERY_SIZE;
    let mut md = String::new();
    let _ = writeln!(
        md,
        "## Scenes\n\nEvery scene under `scenes/` as `cargo xtask regenerate` builds it (`generated/scenes/<scene>/`): each instance drawn with its specialised shader, {w}x{h}, same sky, light and tone mapping.\n"
    );
    for (name, meta, _) in scenes {
        let _ = writeln!(md, "### {name}\n");
        if let Some(d) = &meta.description {
            let _ = writeln!(md, "{d}\n");
        }
        let _ = writeln!(
            md,
            "<img src=\"gallery/scenes/{name}.png\" width=\"{w}\" title=\"{name}\" alt=\"{name}\">\n"
        );
        let _ = writeln!(
            md,
            "{} instances, {} shaders.\n",
            meta.instances.len(),
            meta.shaders.len()
        );
        let _ = writeln!(
            md,
            "| instance | material | preset | tier | shader |\n|---|---|---|---|---|"
        );
        for i in &meta.instances {
            let tier = if i.tier_choice.is_some() {
                format!("auto → {}", i.tier)
            } else {
                i.tier.clone()
            };
            let _ = writeln!(
                md,
                "| {} | {} | {} | {tier} | `{}` |",
                i.name,
                i.material,
                i.preset.as_deref().unwrap_or("—"),
                i.shader
            );
        }
        let _ = writeln!(md);
    }
    md
}

fn gallery_markdown(
    sections: &[(weft_meta::MaterialMetadata, Vec<String>)],
    adapter: &str,
) -> String {
    use std::fmt::Write;
    let mut md = String::new();
    let _ = writeln!(md, "# weft material gallery\n");
    let _ = writeln!(
        md,
        "Generated by `cargo xtask gallery` (do not edit): every material's default variant on the sphere and the cloth patch, every tier, keyword value and preset, {GALLERY_SIZE}x{GALLERY_SIZE}, ACES tone mapping, rendered on {adapter}.\n"
    );
    let _ = writeln!(md, "![contact sheet](gallery/contact_sheet.png)\n");
    for (m, cases) in sections {
        let _ = writeln!(md, "## {} — {}\n", m.name, m.label.en);
        if let Some(d) = &m.description {
            let _ = writeln!(md, "{}\n", d.en);
        }
        for c in cases {
            let _ = write!(
                md,
                "<img src=\"gallery/{}/{c}.png\" width=\"{GALLERY_SIZE}\" title=\"{c}\" alt=\"{c}\"> ",
                m.name
            );
        }
        let _ = writeln!(md, "\n\n{}\n", cases.join(" · "));
        let _ = writeln!(
            md,
            "| group | parameter | type | default | range | label | 中文 |\n|---|---|---|---|---|---|---|"
        );
        for p in &m.parameters {
            let range = p
                .range
                .map(|r| format!("[{}, {}]", r[0], r[1]))
                .unwrap_or_default();
            let zh = p.label.zh.clone().unwrap_or_default();
            let default = p.default.to_string().replace('|', "\\|");
            let default = if default.len() > 40 {
                format!(
                    "{}…",
                    &default[..default
                        .char_indices()
                        .nth(37)
                        .map_or(default.len(), |(i, _)| i)]
                )
            } else {
                default
            };
            let _ = writeln!(
                md,
                "| {} | `{}` | {} | {} | {} | {} | {} |",
                p.group,
                p.name,
                p.kind.name(),
                default,
                range,
                p.label.en,
                zh
            );
        }
        let _ = writeln!(md);
        if !m.keywords.is_empty() {
            let _ = writeln!(
                md,
                "Keywords: {}\n",
                m.keywords
                    .iter()
                    .map(|k| format!("`{}` ({})", k.name, k.values.join(" / ")))
                    .collect::<Vec<_>>()
                    .join(", ")
            );
        }
        let _ = writeln!(
            md,
            "Tiers: {}\n",
            m.tiers
                .values
                .iter()
                .map(|t| format!(
                    "**{t}** — {}",
                    m.tiers
                        .descriptions
                        .get(t)
                        .map(|d| d.en.as_str())
                        .unwrap_or("")
                ))
                .collect::<Vec<_>>()
                .join("; ")
        );
        if let Some(ms) = &m.measurements {
            let _ = writeln!(
                md,
                "Cost and accuracy per tier (from `generated/reports/{}.measurements.json`):\n\n{}\n![{} cost vs error](reports/{}.pareto.svg)\n",
                m.name,
                weft_golden::shading::tier_table(ms, &m.inputs_hash),
                m.name,
                m.name
            );
        }
    }
    md
}
