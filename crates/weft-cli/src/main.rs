//! `weft`: build, check and inspect weft materials from the command line.

use clap::{Parser, Subcommand, ValueEnum};
use codespan_reporting::term::termcolor::{ColorChoice, StandardStream};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use weft_compiler::{BuildOptions, BuildOutput, output};
use weft_front::{Diagnostics, SourceDb};
use weft_meta::MaterialMetadata;

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
enum Color {
    Auto,
    Always,
    Never,
}

#[derive(Subcommand)]
enum Command {
    /// Compile materials (folders or .toml files) into an output folder, atomically.
    #[command(
        after_help = "Examples:\n  weft build\n  weft build materials -o generated --jobs 2\n  weft build materials/standard/standard.toml -o /tmp/out --force"
    )]
    Build {
        /// A materials folder (with lib/ and one folder per material) or material .toml files.
        #[arg(default_value = "materials")]
        paths: Vec<PathBuf>,
        /// Output folder; replaced atomically (reports/ and the gallery are kept).
        #[arg(long, short, default_value = "generated")]
        out: PathBuf,
        /// Worker threads (default: all cores). Output bytes do not depend on it.
        #[arg(long, short)]
        jobs: Option<usize>,
        /// Recompile materials whose inputs are unchanged instead of reusing their files.
        #[arg(long)]
        force: bool,
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

const BENCH_EXAMPLES: &str = "Examples:
  weft bench
  weft bench generated --material microcylinder --size 256 --frames 20
  weft bench --write-reports          # generated/reports/: shading.md, <name>.measurements.json, <name>.pareto.svg

GPU time comes from timestamp queries around the render pass (clear + the material's draws, no
background); an adapter without them is timed on the CPU, and the `timer` line says so. Errors are
over object pixels, against the material's reference tier with the same keywords and parameters.";

#[derive(clap::Args)]
struct BenchArgs {
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

fn bench(args: &BenchArgs) -> Result<(), String> {
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
        let files = shading::write_reports(&dir, &report, "weft bench --write-reports")?;
        println!("wrote {} files in {}", files.len(), dir.display());
    }
    Ok(())
}

/// Prints measured per-tier figures attached from `<generated>/reports/`
/// (a .meta.json's folder, or `generated/` for a .toml).
fn print_measurements(m: &mut MaterialMetadata, path: &Path) {
    let meta_path = if path.extension().is_some_and(|e| e == "json") {
        path.to_path_buf()
    } else {
        Path::new("generated").join(&m.name).join("x.meta.json")
    };
    if let Err(e) = m.attach_measurements(&meta_path) {
        eprintln!("warning: ignoring measurements: {e}");
    }
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

const PREVIEW_EXAMPLES: &str = "Examples:
  weft preview materials/standard/standard.toml -o out.png
  weft preview materials/standard/standard.toml -o gold.png --preset gold --scene cloth
  weft preview generated/standard/standard.meta.json -o p.png --tier reference --keyword NORMAL_MAP=on
  weft preview generated/standard/standard.meta.json -o p.png --variant fast.normal_map-off.sphere_map-add
  weft preview materials/standard/standard.toml -o p.png --set base_color=0.9,0.2,0.1 --set roughness=0.2
  weft preview materials/standard/standard.toml -o p.png --size 512x384 --light-dir -1,1,0.5 --tonemap neutral --hdr-out p.pfm

The scene has a directional light (direction towards the light, also the sky's sun) and a procedural
sky: prefiltered cube, L2 SH irradiance and the baked split-sum LUT. Colours given with --set are
as edited (sRGB unless the parameter is an HDR colour). Needs a Vulkan driver: on Debian/Ubuntu
`apt-get install mesa-vulkan-drivers`.";

#[derive(clap::Args)]
struct PreviewArgs {
    /// A material .toml (built in memory into a temporary folder) or a generated .meta.json.
    path: PathBuf,
    /// Output PNG (tone-mapped sRGB8).
    #[arg(long, short, default_value = "preview.png")]
    out: PathBuf,
    /// A variant id (aliases allowed); sets the tier and the static keywords.
    #[arg(long, conflicts_with = "tier")]
    variant: Option<String>,
    /// Quality tier (default: the material's default tier).
    #[arg(long)]
    tier: Option<String>,
    /// Keyword value, NAME=VALUE (toggles: on/off); repeatable.
    #[arg(long = "keyword", value_name = "NAME=VALUE")]
    keywords: Vec<String>,
    /// Parameter value, NAME=VALUE (vectors and colours as comma lists); repeatable.
    #[arg(long = "set", value_name = "NAME=VALUE")]
    sets: Vec<String>,
    /// Apply a preset first (then --variant/--tier/--keyword/--set).
    #[arg(long)]
    preset: Option<String>,
    /// Built-in scene.
    #[arg(long, value_enum, default_value_t = SceneArg::Sphere)]
    scene: SceneArg,
    /// Image size, WxH.
    #[arg(long, default_value = "256x256", value_name = "WxH")]
    size: String,
    /// Direction towards the light, x,y,z (world +Y up, camera on +Z).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    light_dir: Option<String>,
    /// Tone-mapping operator.
    #[arg(long, value_enum, default_value_t = TonemapArg::Aces)]
    tonemap: TonemapArg,
    /// Exposure multiplier applied before tone mapping.
    #[arg(long, default_value_t = 1.0)]
    exposure: f32,
    /// Also write the linear HDR image as a PFM (RGB f32) file.
    #[arg(long, value_name = "FILE")]
    hdr_out: Option<PathBuf>,
    /// Draw from the WGSL or the SPIR-V file of the variant.
    #[arg(long, value_enum, default_value_t = ShaderArg::Wgsl)]
    shader: ShaderArg,
    /// Render into an Rgba32Float target instead of Rgba16Float.
    #[arg(long)]
    f32: bool,
    /// Print the Vulkan adapter's details (name, vendor/device ids, driver, type).
    #[arg(long)]
    adapter_info: bool,
}

#[derive(Clone, Copy, ValueEnum)]
enum SceneArg {
    Sphere,
    Cloth,
    Swatch,
}

#[derive(Clone, Copy, ValueEnum)]
enum TonemapArg {
    Aces,
    Neutral,
    Clamp,
}

#[derive(Clone, Copy, ValueEnum)]
enum ShaderArg {
    Wgsl,
    Spirv,
}

fn split_pair(s: &str, flag: &str) -> Result<(String, String), String> {
    match s.split_once('=') {
        Some((k, v)) if !k.trim().is_empty() => Ok((k.trim().to_string(), v.trim().to_string())),
        _ => Err(format!("{flag} expects NAME=VALUE, got `{s}`")),
    }
}

fn preview(args: &PreviewArgs, quiet: bool, color: Color) -> Result<(), String> {
    use weft_render::*;
    let started = std::time::Instant::now();
    let (w, h) = args
        .size
        .split_once(['x', 'X'])
        .and_then(|(w, h)| Some((w.trim().parse::<u32>().ok()?, h.trim().parse::<u32>().ok()?)))
        .filter(|&(w, h)| w > 0 && h > 0)
        .ok_or_else(|| format!("--size expects WxH, e.g. 256x256, got `{}`", args.size))?;
    let light_direction = match &args.light_dir {
        Some(s) => {
            let v: Vec<f32> = s
                .split(',')
                .map(|x| x.trim().parse::<f32>())
                .collect::<std::result::Result<_, _>>()
                .map_err(|_| format!("--light-dir expects x,y,z, got `{s}`"))?;
            match v[..] {
                [x, y, z] if x * x + y * y + z * z > 0.0 => Some([x, y, z]),
                _ => return Err(format!("--light-dir expects a non-zero x,y,z, got `{s}`")),
            }
        }
        None => None,
    };
    let mut mopts = MaterialOptions {
        preset: args.preset.clone(),
        variant: args.variant.clone(),
        tier: args.tier.clone(),
        ..MaterialOptions::default()
    };
    for k in &args.keywords {
        mopts.keywords.push(split_pair(k, "--keyword")?);
    }
    for s in &args.sets {
        mopts.sets.push(split_pair(s, "--set")?);
    }

    // A .toml is compiled into a temporary folder; a .meta.json is used as is.
    let _tmp;
    let meta_path = if args.path.extension().is_some_and(|e| e == "toml") {
        let result = build(
            std::slice::from_ref(&args.path),
            &BuildOptions::default(),
            true,
        );
        let out = match result {
            Ok(out) => out,
            Err((db, diags)) => {
                report(&db, &diags, color);
                return Err(format!("`{}` does not compile", args.path.display()));
            }
        };
        let tmp =
            tempfile::tempdir().map_err(|e| format!("cannot create a temporary folder: {e}"))?;
        let dir = tmp.path().join("generated");
        output::write_atomically(&dir, &out.files, &[])
            .map_err(|e| format!("cannot write `{}`: {e}", dir.display()))?;
        let name = &out.materials.first().ok_or("no material was built")?.name;
        let meta = dir.join(name).join(format!("{name}.meta.json"));
        _tmp = tmp;
        meta
    } else {
        args.path.clone()
    };
    let mut material = Material::load(&meta_path).map_err(|e| e.to_string())?;
    mopts.apply(&mut material).map_err(|e| e.to_string())?;
    let luts = Luts::for_metadata(&meta_path).map_err(|e| e.to_string())?;
    let options = PreviewOptions {
        scene: match args.scene {
            SceneArg::Sphere => SceneKind::Sphere,
            SceneArg::Cloth => SceneKind::Cloth,
            SceneArg::Swatch => SceneKind::Swatch,
        },
        width: w,
        height: h,
        light_direction,
        format: if args.f32 {
            ColorFormat::Rgba32Float
        } else {
            ColorFormat::Rgba16Float
        },
        language: match args.shader {
            ShaderArg::Wgsl => ShaderLanguage::Wgsl,
            ShaderArg::Spirv => ShaderLanguage::SpirV,
        },
        ..PreviewOptions::default()
    };
    if args.adapter_info {
        let gpu = Gpu::new().map_err(|e| e.to_string())?;
        let i = gpu.adapter_info();
        println!(
            "adapter: {}\n  vendor 0x{:04x}, device 0x{:04x}, type {:?}, backend {:?}\n  driver: {} {}",
            i.name, i.vendor, i.device, i.device_type, i.backend, i.driver, i.driver_info
        );
    }
    let (image, adapter) = render_preview(&material, &luts, &options).map_err(|e| e.to_string())?;
    let tonemap = match args.tonemap {
        TonemapArg::Aces => Tonemap::Aces,
        TonemapArg::Neutral => Tonemap::Neutral,
        TonemapArg::Clamp => Tonemap::Clamp,
    };
    image
        .save_png(&args.out, tonemap, args.exposure)
        .map_err(|e| e.to_string())?;
    if let Some(p) = &args.hdr_out {
        image.save_pfm(p).map_err(|e| e.to_string())?;
    }
    if !quiet {
        let variant = material
            .current_variant()
            .map(|v| v.requested.id.clone())
            .unwrap_or_default();
        let bad = image.non_finite_count();
        println!(
            "rendered {} variant {variant} ({}, {w}x{h}) on {adapter} in {:.2}s -> {}{}",
            material.name(),
            options.scene.name(),
            started.elapsed().as_secs_f64(),
            args.out.display(),
            if bad > 0 {
                format!(" ({bad} non-finite pixels)")
            } else {
                String::new()
            }
        );
    }
    Ok(())
}

const STABILITY_EXAMPLES: &str = "Examples:
  weft stability                                   compile materials/ and sweep every material
  weft stability generated
  weft stability materials/standard/standard.toml --show 100
  weft stability generated/standard/standard.meta.json

Every canonical variant (and constant-keyword value) is drawn with each parameter at its min, mid
and max (colours 0 and 1; textures black, white, flat normal; others at their defaults) plus the
all-min and all-max corners, at 84 geometric cases (N.V and N.L at 1, 1e-4, 0 and negative, L = V,
L = -V, grazing, H parallel to the tangent, degenerate tangents and normals) into an Rgba32Float
target. Any NaN, Inf, negative or > 65504 channel is printed with where it happened; exit status 1.";

#[derive(clap::Args)]
struct StabilityArgs {
    /// A materials folder or .toml (compiled into a temporary folder), a generated folder or a .meta.json.
    #[arg(default_value = "materials")]
    path: PathBuf,
    /// Only these materials (repeatable).
    #[arg(long = "material", value_name = "NAME")]
    materials: Vec<String>,
    /// Print at most this many failures (every failure is counted).
    #[arg(long, default_value_t = 50)]
    show: usize,
}

/// `weft stability`: Ok(true) when nothing bad was found.
fn stability(args: &StabilityArgs, quiet: bool, color: Color) -> Result<bool, String> {
    use weft_render::probe::{
        Probe, SweepReport, failures_by_case, generated_materials, sweep_material, sweep_renderer,
    };
    let started = std::time::Instant::now();
    let path = &args.path;
    let is_generated_dir = path.is_dir() && generated_materials(path).is_ok_and(|m| !m.is_empty());
    let _tmp;
    let (metas, generated) = if path.extension().is_some_and(|e| e == "json") {
        let dir = path
            .parent()
            .and_then(Path::parent)
            .unwrap_or(Path::new("."))
            .to_path_buf();
        (vec![path.clone()], dir)
    } else if is_generated_dir {
        (
            generated_materials(path).map_err(|e| e.to_string())?,
            path.clone(),
        )
    } else {
        let out = build(std::slice::from_ref(path), &BuildOptions::default(), true).map_err(
            |(db, diags)| {
                report(&db, &diags, color);
                format!("`{}` does not compile", path.display())
            },
        )?;
        let tmp =
            tempfile::tempdir().map_err(|e| format!("cannot create a temporary folder: {e}"))?;
        let dir = tmp.path().join("generated");
        output::write_atomically(&dir, &out.files, &[])
            .map_err(|e| format!("cannot write `{}`: {e}", dir.display()))?;
        _tmp = tmp;
        (generated_materials(&dir).map_err(|e| e.to_string())?, dir)
    };
    let metas: Vec<PathBuf> = metas
        .into_iter()
        .filter(|m| {
            args.materials.is_empty()
                || m.parent()
                    .and_then(Path::file_name)
                    .is_some_and(|n| args.materials.iter().any(|x| *x == *n.to_string_lossy()))
        })
        .collect();
    if metas.is_empty() {
        return Err(format!("no materials to sweep in `{}`", path.display()));
    }
    let luts = weft_render::Luts::load_dir(&generated).map_err(|e| e.to_string())?;
    let mut renderer = sweep_renderer(&luts).map_err(|e| e.to_string())?;
    let probe = Probe::stability(weft_render::Light::default().radiance);
    let mut sweep = SweepReport::default();
    let show_progress = !quiet && std::io::stderr().is_terminal();
    for meta in &metas {
        let t = std::time::Instant::now();
        let name = meta
            .file_stem()
            .map(|s| s.to_string_lossy().trim_end_matches(".meta").to_string())
            .unwrap_or_default();
        sweep_material(&mut renderer, &probe, meta, &mut sweep, &mut |i, n| {
            if show_progress {
                eprint!("\r\x1b[K[{i}/{n}] {name}");
            }
        })
        .map_err(|e| format!("{}: {e}", meta.display()))?;
        if show_progress {
            eprint!("\r\x1b[K");
        }
        let m = sweep.materials.last().expect("one per material");
        if !quiet {
            println!(
                "{}: {} variant(s), {} settings, {} draws, {} bad output(s) ({:.1}s)",
                m.material,
                m.variants,
                m.renders,
                m.draws,
                m.bad,
                t.elapsed().as_secs_f64()
            );
        }
    }
    let bad = sweep.bad();
    if bad > 0 {
        println!("\nfailing geometric cases ((variant, setting) pairs, kinds):");
        for (case, (n, kinds)) in failures_by_case(&sweep.failures) {
            let kinds: Vec<String> = kinds.iter().map(ToString::to_string).collect();
            println!("  {case}: {n} ({})", kinds.join(", "));
        }
        println!("\nfailures (material variant [parameter values] at `case`: value):");
        for f in sweep.failures.iter().take(args.show) {
            println!("  {f}");
        }
        if sweep.failures.len() > args.show {
            println!(
                "  ... and {} more (--show N)",
                sweep.failures.len() - args.show
            );
        }
    }
    if !quiet || bad > 0 {
        println!(
            "{} on {} in {:.1}s",
            sweep.summary(),
            renderer.gpu().describe(),
            started.elapsed().as_secs_f64()
        );
    }
    Ok(bad == 0)
}

fn color_choice(c: Color) -> ColorChoice {
    match c {
        Color::Always => ColorChoice::Always,
        Color::Never => ColorChoice::Never,
        Color::Auto if std::io::stderr().is_terminal() => ColorChoice::Auto,
        Color::Auto => ColorChoice::Never,
    }
}

fn report(db: &SourceDb, diags: &Diagnostics, color: Color) {
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
    if let [dir] = paths {
        if dir.is_dir() {
            return weft_compiler::build_library(dir, options, &progress);
        }
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
            paths,
            out,
            jobs,
            force,
        } => {
            let started = std::time::Instant::now();
            let options = BuildOptions {
                jobs,
                reuse_from: (!force).then(|| out.clone()),
            };
            match build(&paths, &options, cli.quiet) {
                Ok(result) => {
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
