//! `weft stability`: sweep parameters and degenerate geometry for NaN/Inf/negative output.

use crate::library_build::build;
use crate::{Color, report};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use weft_compiler::{BuildOptions, output};

pub(crate) const STABILITY_EXAMPLES: &str = "Examples:
  weft stability                                   compile materials/ and sweep every material
  weft stability generated
  weft stability materials/standard/standard.toml --show 100
  weft stability generated/standard/standard.meta.json

Every canonical variant (and constant-keyword value) is drawn with each parameter at its min, mid
and max (colours 0 and 1; textures black, white, flat normal; others at their defaults) plus the
all-min and all-max corners, at 84 geometric cases (N.V and N.L at 1, 1e-4, 0 and negative, L = V,
L = -V, grazing, H parallel to the tangent, degenerate tangents and normals) into an Rgba32Float
target. Any NaN, Inf, negative or > 65504 channel is printed with where it happened; exit status 1.
On lavapipe the tiles are drawn on one thread (LP_NUM_THREADS=0, faster for tiles this small)
unless LP_NUM_THREADS is set.";

#[derive(clap::Args)]
pub(crate) struct StabilityArgs {
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
pub(crate) fn stability(args: &StabilityArgs, quiet: bool, color: Color) -> Result<bool, String> {
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
