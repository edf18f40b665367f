//! The reports: `scenes.md` (description, summary table, a section per
//! scene) and `scenes.json` (every figure), written side by side.

use super::figures::round;
use super::{
    AbTiming, FLIP_BOUND, LAVAPIPE_THREADS, SceneBench, SceneBenchReport, Spread, TARGET_SAVING,
};
use crate::shading::{ImageError, quantile};
use serde_json::json;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use weft_render::FrameTimer;

fn timer_text(timer: FrameTimer) -> &'static str {
    match timer {
        FrameTimer::GpuTimestamp => {
            "GPU timestamp queries at the beginning and end of the render pass"
        }
        FrameTimer::CpuWall => {
            "CPU wall time from submit to completion (the adapter has no timestamp queries, or --cpu-timer was given): includes submission overhead"
        }
    }
}

/// The header: what was measured, where, how.
pub fn describe(report: &SceneBenchReport) -> String {
    let o = &report.options;
    format!(
        "Adapter: {}{}. Timer: {}. Image: {}x{} Rgba16Float, WGSL shaders, cleared to transparent black (no sky: object pixels are those drawn), the scene's camera and lighting (sky environment cube and SH, one sun, as its features say). \
         Generic: the library variants in `generated/<material>/` drawn with every instance's values (`SceneShaders::Library`); specialised: `generated/scenes/<scene>/`. \
         GPU time: {} rounds, each drawing generic then specialised for {} timed frames (after {} warm-up frames in the first round); reported: the median of the per-round medians; spread = (p90 − p10) / median of the per-round medians; `rounds faster` = rounds whose specialised median is below the generic median of the same round; per-round saving = 1 − specialised / generic within a round (median, lowest…highest), a paired figure that drift between rounds cannot bias. \
         FLIP: mean over object pixels of the specialised image against the generic one (ACES tone-mapped sRGB8; bound {FLIP_BOUND}). \
         SPIR-V: instructions in the fragment entry point's functions (module total in parentheses), generic variant file vs scene shader file. \
         Build: median of {} interleaved runs ({} profile), the scene's materials with `build_materials` vs `build_scene` with a fresh `LavapipeTierChooser` per run (device creation and the `auto` tier renders on the adapter included).",
        report.adapter,
        report
            .lavapipe_threads
            .as_ref()
            .map_or(String::new(), |n| format!(", {LAVAPIPE_THREADS}={n}")),
        timer_text(report.timer),
        o.width.max(1),
        o.height.max(1),
        o.rounds.max(1),
        o.frames.max(1),
        o.warmup,
        o.build_runs.max(1),
        report.profile,
    )
}

fn pct(x: f64) -> String {
    format!("{x:.1}%")
}

/// "k/n, median m% (lowest…highest)": rounds faster, and the per-round savings.
fn rounds_text(t: &AbTiming) -> String {
    let savings = t.round_savings_pct();
    format!(
        "{}/{}, median {} ({:.1}…{})",
        t.rounds_faster(),
        t.generic.len(),
        pct(quantile(&savings, 0.5)),
        quantile(&savings, 0.0),
        pct(quantile(&savings, 1.0))
    )
}

/// The summary table: one row per scene.
pub fn summary_table(scenes: &[SceneBench]) -> String {
    let mut md = String::from(
        "| scene | GPU ms generic | GPU ms specialised | ratio | saving | spread (gen. / spec.) | rounds faster, per-round saving | FLIP mean | within bound | SPIR-V fragment instr. (mean reduction) | shaders | files | bytes | build ms generic | build ms scene |\n\
         | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n",
    );
    for s in scenes {
        let (g, sp) = (s.gpu.generic_stats(), s.gpu.specialised_stats());
        let (gf, sf) = (&s.generic_files, &s.scene_files);
        let _ = writeln!(
            md,
            "| {} | {:.3} | {:.3} | {:.3} | {} | {} / {} | {} | {:.6} | {} | {} | {} → {} | {} → {} | {} → {} | {:.0} | {:.0} |",
            s.name,
            g.median,
            sp.median,
            s.gpu.ratio(),
            pct(s.gpu.saving_pct()),
            pct(g.spread * 100.0),
            pct(sp.spread * 100.0),
            rounds_text(&s.gpu),
            s.flip.flip_mean,
            if s.flip.flip_mean <= FLIP_BOUND {
                "yes"
            } else {
                "**no**"
            },
            pct(s.spirv_mean_reduction_pct()),
            gf.shaders,
            sf.shaders,
            gf.files(),
            sf.files(),
            gf.bytes(),
            sf.bytes(),
            s.build.generic_stats().median,
            s.build.specialised_stats().median,
        );
    }
    md
}

/// One scene's section: instances, files, build.
pub fn scene_section(s: &SceneBench) -> String {
    let mut md = String::new();
    let _ = writeln!(md, "## {}\n", s.name);
    let _ = writeln!(
        md,
        "Scene metadata `inputs_hash` {}{}.\n",
        s.inputs_hash,
        if s.current {
            " (generated/ matches a fresh build)"
        } else {
            " — **generated/ differs from a fresh build of the sources: rerun `cargo xtask regenerate`**"
        }
    );
    if let Some(empty) = &s.empty_pass {
        let _ = writeln!(
            md,
            "Each instance drawn alone (same camera, options and transform). An empty pass (the clear alone) takes {:.3} ms; `shading` is the instance's time minus that.\n",
            Spread::of(empty).median
        );
    }
    md.push_str("| instance | material | tier | generic variant → scene shader | GPU ms alone, generic | specialised | saving | shading ms (gen. → spec.) | rounds faster, per-round saving | FLIP mean | SPIR-V fragment instr. | reduction | uniform bytes |\n");
    md.push_str("| --- | --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    let empty = s.empty_pass.as_deref().map(|e| Spread::of(e).median);
    for i in &s.instances {
        let timing = match &i.gpu {
            Some(t) => {
                let (g, sp) = (t.generic_stats().median, t.specialised_stats().median);
                let shading =
                    empty.map_or("—".into(), |e| format!("{:.3} → {:.3}", g - e, sp - e));
                format!(
                    "{g:.3} | {sp:.3} | {} | {shading} | {}",
                    pct(t.saving_pct()),
                    rounds_text(t)
                )
            }
            None => "— | — | — | — | —".into(),
        };
        let _ = writeln!(
            md,
            "| {} | {} | {} | `{}` → `{}` | {timing} | {} | {} → {} ({} → {}) | {} | {} → {} |",
            i.name,
            i.material,
            i.tier,
            i.generic_variant,
            i.shader,
            i.flip.map_or("—".into(), |f| format!("{:.6}", f.flip_mean)),
            i.spirv_generic.1,
            i.spirv_specialised.1,
            i.spirv_generic.0,
            i.spirv_specialised.0,
            pct(i.spirv_reduction_pct()),
            i.uniform_generic,
            i.uniform_specialised,
        );
    }
    let _ = writeln!(
        md,
        "\nMean SPIR-V fragment-instruction reduction: {}.\n",
        pct(s.spirv_mean_reduction_pct())
    );
    md.push_str("| shipped as | shaders | shader files | shader bytes | metadata files | metadata bytes | files | bytes |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n");
    for (what, f) in [
        (
            "generic (library variants used, every language, + materials' `.meta.json`)",
            &s.generic_files,
        ),
        (
            "scene build (`generated/scenes/` folder, everything)",
            &s.scene_files,
        ),
    ] {
        let _ = writeln!(
            md,
            "| {what} | {} | {} | {} | {} | {} | {} | {} |",
            f.shaders,
            f.shader_files,
            f.shader_bytes,
            f.metadata_files,
            f.metadata_bytes,
            f.files(),
            f.bytes()
        );
    }
    let (bg, bs) = (s.build.generic_stats(), s.build.specialised_stats());
    let _ = writeln!(
        md,
        "\nBuild: generic {:.0} ms (min {:.0}, max {:.0}), scene {:.0} ms (min {:.0}, max {:.0}; `auto` tier renders included).\n",
        bg.median, bg.min, bg.max, bs.median, bs.min, bs.max
    );
    md
}

/// `scenes.md`: the description, the command, the summary and every scene's
/// section, then the GPU model's per-instance section between
/// `<!-- weft:gpu-model:… -->` (`model`: that section's text, which
/// `cargo xtask bench gpu-model --write` rewrites on its own).
pub fn markdown_report(report: &SceneBenchReport, command: &str, model: &str) -> String {
    let mut md = format!(
        "# Scene-specialised vs generic shaders\n\nGenerated by `{command}` (timings vary by machine; do not edit). {}\n\n{}\nTarget: at least {:.0}% less GPU time than the generic draw with FLIP mean ≤ {FLIP_BOUND}.\n\n",
        describe(report),
        summary_table(&report.scenes),
        TARGET_SAVING * 100.0
    );
    for s in &report.scenes {
        md.push_str(&scene_section(s));
    }
    let _ = writeln!(
        md,
        "<!-- weft:gpu-model:begin -->\n{model}<!-- weft:gpu-model:end -->\n"
    );
    let _ = writeln!(md, "Total run time: {:.1} s.", report.seconds);
    md
}

fn flip_json(f: &ImageError) -> serde_json::Value {
    json!({
        "flip_mean": round(f.flip_mean, 6),
        "flip_p99": round(f.flip_p99, 6),
        "rel_rmse": round(f.rel_rmse, 6),
        "pixels": f.pixels,
    })
}

/// `scenes.json`: every figure, machine-readable.
pub fn json_report(report: &SceneBenchReport, command: &str) -> serde_json::Value {
    let o = &report.options;
    let scenes: Vec<serde_json::Value> = report
        .scenes
        .iter()
        .map(|s| {
            let instances: Vec<serde_json::Value> = s
                .instances
                .iter()
                .map(|i| {
                    json!({
                        "name": i.name,
                        "material": i.material,
                        "tier": i.tier,
                        "generic_variant": i.generic_variant,
                        "shader": i.shader,
                        "spirv": {
                            "generic_instructions": i.spirv_generic.0,
                            "generic_fragment_instructions": i.spirv_generic.1,
                            "specialised_instructions": i.spirv_specialised.0,
                            "specialised_fragment_instructions": i.spirv_specialised.1,
                            "fragment_reduction_pct": round(i.spirv_reduction_pct(), 2),
                        },
                        "uniform_bytes": { "generic": i.uniform_generic, "specialised": i.uniform_specialised },
                        "gpu_alone": i.gpu.as_ref().map(AbTiming::json),
                        "flip_alone": i.flip.as_ref().map(flip_json),
                    })
                })
                .collect();
            json!({
                "scene": s.name,
                "inputs_hash": s.inputs_hash,
                "generated_current": s.current,
                "gpu": s.gpu.json(),
                "flip": flip_json(&s.flip),
                "flip_within_bound": s.flip.flip_mean <= FLIP_BOUND,
                "empty_pass_ms": s.empty_pass.as_deref().map(|e| round(Spread::of(e).median, 4)),
                "spirv_fragment_mean_reduction_pct": round(s.spirv_mean_reduction_pct(), 2),
                "files": { "generic": s.generic_files.json(), "scene": s.scene_files.json() },
                "build_ms": {
                    "generic": round(s.build.generic_stats().median, 1),
                    "scene": round(s.build.specialised_stats().median, 1),
                    "generic_runs": s.build.generic.iter().map(|x| round(*x, 1)).collect::<Vec<_>>(),
                    "scene_runs": s.build.specialised.iter().map(|x| round(*x, 1)).collect::<Vec<_>>(),
                    "scene_includes": "LavapipeTierChooser (device creation and auto tier renders)",
                },
                "instances": instances,
            })
        })
        .collect();
    json!({
        "command": command,
        "adapter": report.adapter,
        "timer": report.timer.name(),
        "profile": report.profile,
        "lavapipe_threads": report.lavapipe_threads,
        "options": {
            "width": o.width.max(1),
            "height": o.height.max(1),
            "format": "Rgba16Float",
            "language": "wgsl",
            "background": "transparent black",
            "rounds": o.rounds.max(1),
            "frames_per_round": o.frames.max(1),
            "warmup": o.warmup,
            "build_runs": o.build_runs.max(1),
            "per_instance": o.per_instance,
        },
        "flip_bound": FLIP_BOUND,
        "target_saving": TARGET_SAVING,
        "scenes": scenes,
        "seconds": round(report.seconds, 1),
    })
}

/// Writes `scenes.md` and `scenes.json` into `dir` (other files there are
/// left alone). Returns the paths written.
pub fn write_reports(
    dir: &Path,
    report: &SceneBenchReport,
    command: &str,
    model_section: &str,
) -> Result<Vec<PathBuf>, String> {
    let json = serde_json::to_string_pretty(&json_report(report, command))
        .map_err(|e| e.to_string())?
        + "\n";
    let files = [
        (
            dir.join("scenes.md"),
            markdown_report(report, command, model_section),
        ),
        (dir.join("scenes.json"), json),
    ];
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    files
        .into_iter()
        .map(|(path, text)| replace_file(&path, &text).map(|()| path))
        .collect()
}

/// Writes `text` next to `path` and renames it over `path`.
fn replace_file(path: &Path, text: &str) -> Result<(), String> {
    let tmp = path.with_extension("tmp");
    std::fs::write(&tmp, text)
        .and_then(|()| std::fs::rename(&tmp, path))
        .map_err(|e| format!("{}: {e}", path.display()))
}
