//! `cargo xtask`: project automation (regenerate the committed `generated/`
//! tree, check it is current, benchmark the compiler).

use clap::{Parser, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

// One module per task.
mod bench_compile;
mod bench_film;
mod bench_glints;
mod bench_gltf;
mod bench_gpu;
mod bench_gpu_model;
mod bench_scale;
mod bench_scene;
mod bench_shading;
mod bless;
mod gallery;
mod gltf_samples;
#[cfg(feature = "screenshots")]
mod inspector;
#[cfg(test)]
mod readme_materials;
mod regenerate;
mod render_sets;
mod scale;
#[cfg(test)]
mod tidy;

use bench_compile::bench_compile;
use bench_film::bench_film;
use bench_glints::bench_glints;
use bench_scene::SceneArgs;
use bench_scene::bench_scene;
use bench_shading::ShadingArgs;
use bench_shading::bench_shading;
use bless::bless;
use gallery::gallery;
use regenerate::regenerate;
use regenerate::textures;

#[derive(Parser)]
#[command(name = "cargo xtask", about = "weft project tasks")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Rewrite generated/ from materials/ (atomically, removing stale files),
    /// then the bindings table of each material's README (`<!-- weft:bindings:… -->`),
    /// then the GPU model (`bench gpu-model --write`; the scenes are built
    /// again when the library's modelled costs changed, since `auto` tiers
    /// read them).
    Regenerate {
        /// Do not write: fail and list the stale files if generated/ or a README's
        /// bindings table is out of date.
        #[arg(long, conflicts_with = "reports")]
        check: bool,
        /// Also run the GPU model (RADV's null device) and the shading, film
        /// and glint benchmarks and rewrite their reports in generated/reports/
        /// (machine-dependent timings: never done by default).
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
    /// Write the glTF test content (scenes/gltf/showroom.glb, tests/gltf/)
    /// from its generator, weft_golden::gltf_samples.
    GltfSamples {
        /// Do not write: fail and list the files that differ from a fresh generation.
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
    /// A large glTF scene (100 k triangles, 10 materials by default) built by
    /// the release `weft build --scene`: wall time and peak memory.
    Gltf(bench_gltf::GltfArgs),
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

/// `regenerate`, with the GPU model kept in step: the library is built,
/// AMD's compiler models it (`bench gpu-model --write`), and where the
/// library's figures changed the project is built again, so that
/// `tier = "auto"` choices - costed from generated/reports/gpu-model.json -
/// use the new library's costs, and the scene shaders that build makes are
/// modelled in turn. Scene figures do not feed back into choices, so two
/// rounds settle it. Without RADV the committed model stays, with a warning.
fn regenerate_modelled(root: &Path) -> ExitCode {
    let status = regenerate(root, false);
    if status != ExitCode::SUCCESS {
        return status;
    }
    let reports = root.join("generated/reports");
    let library_costs = || {
        weft_meta::gpu_model::ModelSummary::load(&reports)
            .ok()
            .map(|m| {
                m.families
                    .into_iter()
                    .map(|f| (f.family, f.variants))
                    .collect::<Vec<_>>()
            })
    };
    let before = library_costs();
    if let Err(e) = weft_gpu_stats::radv_available() {
        eprintln!(
            "warning: the GPU model was not refreshed ({e}); `tier = \"auto\"` was costed from \
             the committed generated/reports/gpu-model.json"
        );
        return ExitCode::SUCCESS;
    }
    let model = bench_gpu_model::GpuModelArgs::write_defaults();
    let modelled = bench_gpu_model::bench_gpu_model(root, &model);
    if modelled != ExitCode::SUCCESS || library_costs() == before {
        return modelled;
    }
    println!("the library's modelled costs changed: building the scenes' auto tiers on them");
    let status = regenerate(root, false);
    if status != ExitCode::SUCCESS {
        return status;
    }
    bench_gpu_model::bench_gpu_model(root, &model)
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

fn main() -> ExitCode {
    let cli = Cli::parse();
    let root = workspace_root();
    match cli.command {
        Command::Regenerate { check, reports } => {
            if check {
                return regenerate(&root, true);
            }
            let status = regenerate_modelled(&root);
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
            bench_glints(&root, true, "cargo xtask regenerate --reports")
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
        Command::GltfSamples { check } => gltf_samples::gltf_samples(&root, check),
        Command::Bench {
            what: Bench::Gltf(args),
        } => bench_gltf::bench_gltf(&root, &args),
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
