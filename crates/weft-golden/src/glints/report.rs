//! The report: the bounds a run breaks, the README's table and
//! `glitter.glints.md` with every figure.

use super::*;
use std::fmt::Write as _;
use weft_render::SceneKind;

/// Every bound the report's figures break, one line each (empty: all hold).
pub fn failures(report: &GlintReport) -> Vec<String> {
    let mut out = Vec::new();
    for r in &report.energy {
        if !r.within_bound() {
            out.push(format!(
                "energy {}/{}/{}: {:+.2} % (bound ±{} %)",
                r.scene.name(),
                r.case,
                r.tier,
                r.relative() * 100.0,
                r.bound() * 100.0
            ));
        }
    }
    for r in report.extremes.rows.iter().filter(|r| r.bad > 0) {
        out.push(format!(
            "extremes {}/{}/{}: {} bad pixels",
            r.scene, r.extreme, r.tier, r.bad
        ));
    }
    if report.extremes.grazing_energy <= 0.0 {
        out.push("extremes: the grazing swatch drew nothing".into());
    }
    for r in &report.pan.rows {
        if r.flip > MAX_SHIFT_FLIP || r.mean_change.abs() > MAX_SHIFT_MEAN_CHANGE {
            out.push(format!(
                "pan {}/{}: FLIP {:.4}, mean {:+.3} %",
                r.scene.name(),
                r.tier,
                r.flip,
                r.mean_change * 100.0
            ));
        }
    }
    if report.pan.steady_ratio() > MAX_ANCHORED_RATIO {
        out.push(format!(
            "pan, steady flakes: {:.4} vs redrawn {:.4}",
            report.pan.steady_pan, report.pan.steady_redrawn
        ));
    }
    for r in report
        .distant
        .iter()
        .filter(|r| r.tier != SMOOTH_TIER && !r.within_bound())
    {
        out.push(format!(
            "distant {}/{}: {:.4} (aliasing end {:.4})",
            r.scene.name(),
            r.tier,
            r.flip,
            r.aliasing_end
        ));
    }
    out
}

/// The report's table (also written into materials/glitter/README.md).
pub fn markdown_table(report: &GlintReport) -> String {
    let pct = |x: f64| format!("{:+.1}", x * 100.0);
    let per_scene = |tier: &str, rows: &[(SceneKind, &str, f64)], digits: usize| -> String {
        [SceneKind::Sphere, SceneKind::Cloth]
            .iter()
            .map(|k| {
                rows.iter()
                    .find(|(s, t, _)| s == k && *t == tier)
                    .map_or("—".into(), |(_, _, v)| format!("{v:.digits$}"))
            })
            .collect::<Vec<_>>()
            .join(" / ")
    };
    let pan: Vec<(SceneKind, &str, f64)> = report
        .pan
        .rows
        .iter()
        .map(|r| (r.scene, r.tier.as_str(), r.flip))
        .collect();
    let distant: Vec<(SceneKind, &str, f64)> = report
        .distant
        .iter()
        .map(|r| (r.scene, r.tier.as_str(), r.flip))
        .collect();
    let mut md = String::from(
        "| tier | energy vs smooth, % (sphere, cloth × 3 settings) | dense, % | bad pixels at the extremes | half-pixel pan FLIP, sphere / cloth | pan: object mean change, % | distant 1x vs 4×4 FLIP, sphere / cloth | GPU ms, 256² sphere |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n",
    );
    for tier in [SPARKLE_TIERS[0], SPARKLE_TIERS[1], SMOOTH_TIER] {
        let energy: Vec<f64> = report
            .energy
            .iter()
            .filter(|r| r.tier == tier && r.case != "dense")
            .map(EnergyRow::relative)
            .collect();
        let dense: Vec<f64> = report
            .energy
            .iter()
            .filter(|r| r.tier == tier && r.case == "dense")
            .map(EnergyRow::relative)
            .collect();
        let range = |v: &[f64]| -> String {
            if v.is_empty() {
                "— (the mean)".into()
            } else {
                let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
                let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
                format!("{} … {}", pct(lo), pct(hi))
            }
        };
        let dense = if dense.is_empty() {
            "—".into()
        } else {
            let worst = dense.iter().copied().fold(0.0f64, |a, b| a.max(b.abs()));
            format!("within {:.2}", worst * 100.0)
        };
        let (bad, draws) = report
            .extremes
            .rows
            .iter()
            .filter(|r| r.tier == tier)
            .fold((0, 0), |(b, n), r| (b + r.bad, n + 1));
        let mean_change = report
            .pan
            .rows
            .iter()
            .filter(|r| r.tier == tier)
            .map(|r| r.mean_change.abs())
            .fold(0.0f64, f64::max);
        let ms = report
            .cost
            .iter()
            .find(|(t, _)| t == tier)
            .map_or("—".into(), |(_, ms)| format!("{ms:.1}"));
        let _ = writeln!(
            md,
            "| {tier} | {} | {dense} | {bad} of {draws} draws | {} | within {:.2} | {} | {ms} |",
            range(&energy),
            per_scene(tier, &pan, 3),
            mean_change * 100.0,
            per_scene(tier, &distant, 3),
        );
    }
    let _ = writeln!(
        md,
        "| bound | ±{:.0} | ±{:.0} | 0 | ≤ {:.2} (sparkle tiers) | ±{:.0} | ≤ {:.2} and ≤ {:.2} × the aliasing end (sparkle tiers) | |",
        MAX_ENERGY_ERROR * 100.0,
        MAX_DENSE_ENERGY_ERROR * 100.0,
        MAX_SHIFT_FLIP,
        MAX_SHIFT_MEAN_CHANGE * 100.0,
        MAX_DISTANT_FLIP,
        MAX_DISTANT_RATIO,
    );
    let redrawn: Vec<String> = report
        .pan
        .rows
        .iter()
        .filter_map(|r| {
            r.redrawn
                .map(|u| format!("{} {} {:.2}", r.tier, r.scene.name(), r.flip / u))
        })
        .collect();
    let aliasing: Vec<String> = [SceneKind::Sphere, SceneKind::Cloth]
        .iter()
        .filter_map(|k| {
            report
                .distant
                .iter()
                .find(|r| r.scene == *k)
                .map(|r| format!("{:.3} ({})", r.aliasing_end, k.name()))
        })
        .collect();
    let _ = writeln!(
        md,
        "\nPan against a fully redrawn pattern (FLIP ratio, 1 = every sparkle redrawn): {}; steady flakes (twinkle 0, size 8, reference, sphere): {:.2} (bound ≤ {MAX_ANCHORED_RATIO}). Aliasing end of the distance check (reference at sparkle size 1): {}. Failures: {}.",
        redrawn.join(", "),
        report.pan.steady_ratio(),
        aliasing.join(", "),
        match failures(report).len() {
            0 => "none".to_string(),
            n => format!("{n} (see the report)"),
        }
    );
    let _ = writeln!(
        md,
        "\nMeasured on {} ({} for the cost, median of 10 frames) by `crates/weft-golden/src/glints.rs` (bounds and their reasons there; asserted by `tests/physics/glints.rs`). Energy: Σ over the object of render − render at flake intensity 0 (black metal base) against the smooth tier's, 256², sphere and cloth × defaults and two spreads of size and twinkle (range), and dense flakes (density 0.9); extremes: 4 settings × grazing swatch, sphere, sphere lit from behind, cloth, 128², Rgba32Float, a pixel is bad when NaN, Inf, negative or > 65504; pan: the camera moved by half a pixel (eye and target), 256², FLIP over object pixels; distance: the object at {DISTANCE_FACTOR}× the distance at 128² against 512² box-filtered 4×4. Inputs hash {}.",
        report.adapter, report.timer, report.inputs_hash
    );
    md
}

/// `glitter.glints.md`: the command, the table and every figure.
pub fn markdown_report(report: &GlintReport, command: &str) -> String {
    let mut md = format!(
        "# glitter: glint checks\n\nGenerated by `{command}` on {} (timings vary by machine; do not edit).\n\n{}",
        report.adapter,
        markdown_table(report)
    );
    let _ = writeln!(
        md,
        "\n## Energy (glints / smooth − 1)\n\n| scene | setting | tier | % | bound % |\n| --- | --- | --- | ---: | ---: |"
    );
    for r in &report.energy {
        let _ = writeln!(
            md,
            "| {} | {} | {} | {:+.2} | ±{:.0} |",
            r.scene.name(),
            r.case,
            r.tier,
            r.relative() * 100.0,
            r.bound() * 100.0
        );
    }
    let _ = writeln!(
        md,
        "\n## Half-pixel pan\n\n| scene | tier | FLIP | mean change % | redrawn pattern FLIP | pan / redrawn |\n| --- | --- | ---: | ---: | ---: | ---: |"
    );
    for r in &report.pan.rows {
        let (u, ratio) = r.redrawn.map_or(("—".into(), "—".into()), |u| {
            (format!("{u:.4}"), format!("{:.2}", r.flip / u))
        });
        let _ = writeln!(
            md,
            "| {} | {} | {:.4} | {:+.3} | {u} | {ratio} |",
            r.scene.name(),
            r.tier,
            r.flip,
            r.mean_change * 100.0
        );
    }
    let _ = writeln!(
        md,
        "\nSteady flakes (sphere, reference, twinkle 0, size 8): pan FLIP {:.4}, redrawn {:.4}, ratio {:.2}.",
        report.pan.steady_pan,
        report.pan.steady_redrawn,
        report.pan.steady_ratio()
    );
    let _ = writeln!(
        md,
        "\n## Distance\n\n| scene | tier | FLIP 1x vs 4×4 | aliasing end | ratio |\n| --- | --- | ---: | ---: | ---: |"
    );
    for r in &report.distant {
        let _ = writeln!(
            md,
            "| {} | {} | {:.4} | {:.4} | {:.2} |",
            r.scene.name(),
            r.tier,
            r.flip,
            r.aliasing_end,
            r.flip / r.aliasing_end
        );
    }
    let fails = failures(report);
    let _ = writeln!(
        md,
        "\n## Failures\n\n{}",
        if fails.is_empty() {
            "None.".to_string()
        } else {
            fails.join("\n")
        }
    );
    md
}
