//! The reports: the header, the tables of every material × tier,
//! `shading.md`, each material's `<name>.measurements.json` and the
//! marked sections other files take the tables into.

use super::*;
use std::fmt::Write as _;
use weft_meta::TierMeasurement;
use weft_meta::gpu_model::ModelSummary;

/// The header lines of a report: what was measured, where, how.
pub fn describe(report: &ShadingReport) -> String {
    let o = &report.options;
    let timer = match report.timer {
        FrameTimer::GpuTimestamp => {
            "GPU timestamp queries at the beginning and end of the render pass".to_string()
        }
        FrameTimer::CpuWall => {
            "CPU wall time from submit to completion (the adapter has no timestamp queries, or --cpu-timer was given): includes submission overhead".to_string()
        }
    };
    format!(
        "Adapter: {}. Timer: {timer}. Scene: {}x{} {}, {SETUP}. Time: median of {} frames per tier (fewer, at least {}, for a tier that would take over {} s; column `frames`), after 1 + up to {} warm-up frames, taken in {} rounds over all tiers so that changing machine load affects all alike; spread = (p90 − p10) / median. Cost ratio: against `{BASELINE_MATERIAL}` tier `{BASELINE_TIER}` in the same run; a half-precision tier is drawn from its f16 files where the adapter has shader-f16, and its portable f32 files' ratio follows in brackets. SPIR-V: instructions in the module (in the fragment entry point's functions). Error against the material's reference tier: FLIP mean and 99th percentile on the ACES tone-mapped sRGB8 image, relative RMSE sqrt(Σ(a−b)²/Σb²) on the linear HDR image.",
        report.adapter,
        o.size,
        o.size,
        o.scene.name(),
        o.frames.max(1),
        5.min(o.frames.max(1)),
        o.max_seconds_per_tier,
        o.warmup,
        o.rounds.max(1),
    )
}

/// The tables of every material × tier, Markdown: the reference and its
/// approximations (whose difference from the reference is their error),
/// then the looks (different models, whose difference is not an error).
pub fn markdown_table(materials: &[Measurements]) -> String {
    let mut md = String::new();
    let header = "| material | tier | GPU ms (median) | min | spread | frames | × standard fast | SPIR-V instr. (fragment) | FLIP mean | FLIP p99 | rel. RMSE | FLIP worst (grid) | FLIP grid mean | worst cell |\n| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
    let is_look = |t: &TierMeasurement| t.kind.as_deref() == Some("look");
    let row = |md: &mut String, m: &Measurements, t: &TierMeasurement| {
        let opt = |v: Option<f64>| v.map_or("—".to_string(), |v| format!("{v:.4}"));
        let _ = writeln!(
            md,
            "| {} | {} | {:.3} | {:.3} | {:.1}% | {} | {} | {} ({}) | {:.4} | {:.4} | {:.4} | {} | {} | {} |",
            m.material,
            t.tier,
            t.gpu_ms,
            t.gpu_ms_min,
            t.gpu_ms_spread * 100.0,
            t.frames,
            cost_cell(t),
            t.spirv_instructions,
            t.spirv_fragment_instructions,
            t.flip_mean,
            t.flip_p99,
            t.rel_rmse,
            opt(t.flip_worst),
            opt(t.flip_grid_mean),
            t.flip_worst_cell.as_deref().unwrap_or("—"),
        );
    };
    md.push_str("Reference tiers and their approximations (FLIP against the reference is the approximation's error):\n\n");
    md.push_str(header);
    for m in materials {
        for t in m.tiers.iter().filter(|t| !is_look(t)) {
            row(&mut md, m, t);
        }
    }
    if materials.iter().any(|m| m.tiers.iter().any(is_look)) {
        md.push_str("\nLooks: different models kept for their look (a source document's formula), not approximations; the FLIP columns say how far the look is from the reference, not an error:\n\n");
        md.push_str(header);
        for m in materials {
            for t in m.tiers.iter().filter(|t| is_look(t)) {
                row(&mut md, m, t);
            }
        }
    }
    md
}

/// The "× standard fast" cell: a half-precision tier's f32 files beside it.
pub(crate) fn cost_cell(t: &TierMeasurement) -> String {
    let ratio = |r: Option<f64>| r.map_or("—".to_string(), |r| format!("{r:.2}"));
    match &t.f32_files {
        Some(f) => format!(
            "{} (f32 files: {})",
            ratio(t.ratio_to_standard_fast),
            ratio(f.ratio_to_standard_fast)
        ),
        None => ratio(t.ratio_to_standard_fast),
    }
}

/// Replaces the text between `<!-- weft:<name>:begin -->` and
/// `<!-- weft:<name>:end -->` in `text` with `content`; None when the
/// markers are absent.
pub fn replace_marked(text: &str, name: &str, content: &str) -> Option<String> {
    let begin = format!("<!-- weft:{name}:begin -->");
    let end = format!("<!-- weft:{name}:end -->");
    let a = text.find(&begin)? + begin.len();
    let b = a + text[a..].find(&end)?;
    Some(format!("{}\n{}{}", &text[..a], content, &text[b..]))
}

/// `shading.md`: the description, the command, the timed table and the GPU
/// model's table (between `<!-- weft:gpu-model:… -->`, which
/// `cargo xtask bench gpu-model --write` rewrites on its own).
pub fn markdown_report(
    report: &ShadingReport,
    command: &str,
    model: Option<&ModelSummary>,
) -> String {
    format!(
        "# Shading cost and accuracy\n\nGenerated by `{command}` (timings vary by machine; do not edit). {}\n\n{}{}\n<!-- weft:gpu-model:begin -->\n{}<!-- weft:gpu-model:end -->\n\nTotal run time: {:.1} s.\n",
        describe(report),
        markdown_table(&report.materials),
        floor_line(report),
        crate::cost_tables::model_section(&report.materials, model),
        report.seconds
    )
}

/// The cost floor and `standard` `fast` against it, when both were timed.
pub fn floor_line(report: &ShadingReport) -> String {
    let standard = report
        .materials
        .iter()
        .find(|m| m.material == BASELINE_MATERIAL)
        .and_then(|m| m.tiers.iter().find(|t| t.tier == BASELINE_TIER));
    match (report.floor_ms, standard) {
        (Some(floor), Some(t)) => format!(
            "\nFloor: an unlit fill (the same geometry and vertex stage, a flat colour; `crates/weft-golden/src/floor.rs`) takes {floor:.3} ms in the same run: `{BASELINE_MATERIAL}` `{BASELINE_TIER}` costs {:.2}× the floor.\n",
            t.gpu_ms / floor
        ),
        _ => String::new(),
    }
}

/// Writes `shading.md` and, per material, `<name>.measurements.json` and
/// `<name>.pareto.svg` into `dir` (other files there are left alone).
/// Returns the paths written.
pub fn write_reports(
    dir: &Path,
    report: &ShadingReport,
    command: &str,
    model: Option<&ModelSummary>,
) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut files: Vec<(PathBuf, String)> = vec![(
        dir.join("shading.md"),
        markdown_report(report, command, model),
    )];
    for m in &report.materials {
        let mut json = serde_json::to_string_pretty(m).map_err(|e| e.to_string())?;
        json.push('\n');
        files.push((dir.join(format!("{}.measurements.json", m.material)), json));
        files.push((
            dir.join(format!("{}.pareto.svg", m.material)),
            crate::pareto::pareto_svg(m, model),
        ));
    }
    let mut written = Vec::new();
    for (path, text) in files {
        let tmp = path.with_extension("tmp");
        std::fs::write(&tmp, text)
            .and_then(|()| std::fs::rename(&tmp, &path))
            .map_err(|e| format!("{}: {e}", path.display()))?;
        written.push(path);
    }
    Ok(written)
}
