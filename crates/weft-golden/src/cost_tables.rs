//! The tier tables the docs carry, timed cost beside the GPU model: the
//! README's "Choosing a tier", each material README's ladder, the gallery's
//! per-material table and the GPU model section of
//! `generated/reports/shading.md`.
//!
//! Two sources, never mixed in one column: the shading bench's timed ratio
//! (`<material>.measurements.json`, llvmpipe on the development machine) and
//! the committed GPU model (`gpu-model.json`: AMD's compiler on Mesa RADV's
//! null device, the loop-aware executed cost, per family). Both are ratios to
//! `standard` `fast` within their own source.

use crate::shading::cost_cell;
use std::fmt::Write as _;
use std::path::Path;
use weft_meta::Measurements;
use weft_meta::gpu_model::{FragmentCost, ModelSummary, TierCost};
use weft_meta::scene::SceneMetadata;

/// The timed columns' name: the adapter's short name (`llvmpipe`) or `timed`.
fn timed_label(materials: &[Measurements]) -> &'static str {
    if materials
        .iter()
        .all(|m| m.adapter.contains("llvmpipe") || m.tiers.is_empty())
    {
        "llvmpipe"
    } else {
        "timed"
    }
}

/// The model's figures of `material` `tier` on each family, in the model's order.
fn model_costs<'a>(
    model: Option<&'a ModelSummary>,
    material: &str,
    tier: &str,
) -> Vec<Option<&'a TierCost>> {
    model.map_or_else(Vec::new, |m| {
        m.families.iter().map(|f| f.tier(material, tier)).collect()
    })
}

fn families(model: Option<&ModelSummary>) -> Vec<&str> {
    model.map_or_else(Vec::new, |m| {
        m.families.iter().map(|f| f.family.as_str()).collect()
    })
}

fn ratio(c: Option<&TierCost>) -> String {
    c.map_or("—".into(), |c| format!("{:.2}", c.executed_ratio))
}

fn regs(c: Option<&TierCost>) -> String {
    c.map_or("—".into(), |c| {
        format!("{} / {}", c.fragment.vgprs, c.fragment.waves)
    })
}

/// The model's header cells: per family its ratio, then VGPRs / waves of the
/// first family (nothing without a model).
fn model_header(head: &mut String, rule: &mut String, model: Option<&ModelSummary>) {
    let fams = families(model);
    for f in &fams {
        let _ = write!(head, " {f} model × |");
        rule.push_str(" ---: |");
    }
    if let Some(first) = fams.first() {
        let _ = write!(head, " VGPRs / waves ({first}) |");
        rule.push_str(" ---: |");
    }
}

/// A row's model cells, matching [`model_header`].
fn model_cells(row: &mut String, model: Option<&ModelSummary>, material: &str, tier: &str) {
    let costs = model_costs(model, material, tier);
    for c in &costs {
        let _ = write!(row, " {} |", ratio(*c));
    }
    if let Some(first) = costs.first() {
        let _ = write!(row, " {} |", regs(*first));
    }
}

/// The compact header: tier columns, the timed ones, then per family the
/// model's ratio, and VGPRs / waves of the first family.
fn compact_header(
    materials: &[Measurements],
    model: Option<&ModelSummary>,
    with_material: bool,
) -> String {
    let timed = timed_label(materials);
    let mut head = String::from("|");
    let mut rule = String::from("|");
    if with_material {
        head.push_str(" material |");
        rule.push_str(" --- |");
    }
    let _ = write!(
        head,
        " tier | kind | {timed} ms | {timed} × standard fast |"
    );
    rule.push_str(" --- | --- | ---: | ---: |");
    model_header(&mut head, &mut rule, model);
    head.push_str(" FLIP at defaults | worst FLIP over the grid | worst cell |");
    rule.push_str(" ---: | ---: | --- |");
    format!("{head}\n{rule}\n")
}

/// Rows of the compact tier tables: approximations (and references) or looks.
fn compact_rows(
    md: &mut String,
    materials: &[Measurements],
    model: Option<&ModelSummary>,
    looks: bool,
    with_material: bool,
) {
    let opt = |v: Option<f64>| match v {
        None => "—".to_string(),
        Some(0.0) => "0".to_string(),
        Some(v) => format!("{v:.3}"),
    };
    for m in materials {
        for t in &m.tiers {
            if (t.kind.as_deref() == Some("look")) != looks {
                continue;
            }
            let mut row = String::from("|");
            if with_material {
                let _ = write!(row, " {} |", m.material);
            }
            let _ = write!(
                row,
                " {} | {} | {:.1} | {} |",
                t.tier,
                t.kind.as_deref().unwrap_or("—"),
                t.gpu_ms,
                cost_cell(t)
            );
            model_cells(&mut row, model, &m.material, &t.tier);
            let _ = writeln!(
                row,
                " {} | {} | {} |",
                opt(Some(t.flip_mean)),
                opt(t.flip_worst),
                t.flip_worst_cell.as_deref().unwrap_or("—"),
            );
            md.push_str(&row);
        }
    }
}

/// Where the model columns come from, one line (empty without a model).
fn model_note(model: Option<&ModelSummary>) -> String {
    let Some(m) = model else {
        return String::new();
    };
    let fams: Vec<String> = m
        .families
        .iter()
        .map(|f| format!("`{}` ({}, {})", f.family, f.device_name, f.driver_info))
        .collect();
    format!(
        " Model columns: the loop-aware executed cost of the tier's default variant from AMD's \
         shader compiler on Mesa RADV's null device, ÷ `standard` `fast`'s, for {} \
         (`generated/reports/gpu-model.json`, `cargo xtask bench gpu-model --write`; \
         docs/performance.md); VGPRs / waves: registers per lane and waves per SIMD they allow.",
        fams.join(" and ")
    )
}

/// The README's "Choosing a tier" tables, from the measurements and the
/// model: the references and their approximations, then the looks.
pub fn choosing_tables(materials: &[Measurements], model: Option<&ModelSummary>) -> String {
    let header = compact_header(materials, model, true);
    let mut md =
        String::from("Approximations (their difference from the reference is their error):\n\n");
    md.push_str(&header);
    compact_rows(&mut md, materials, model, false, true);
    md.push_str(
        "\nLooks (different models; the FLIP says how far the look is from the reference):\n\n",
    );
    md.push_str(&header);
    compact_rows(&mut md, materials, model, true, true);
    let note = model_note(model);
    if !note.is_empty() {
        let _ = writeln!(md, "\n{}", note.trim_start());
    }
    md
}

/// One material's tier ladder (for its README), from its measurements and the model.
pub fn ladder_table(m: &Measurements, model: Option<&ModelSummary>) -> String {
    let one = std::slice::from_ref(m);
    let mut md = compact_header(one, model, false);
    compact_rows(&mut md, one, model, false, false);
    compact_rows(&mut md, one, model, true, false);
    let _ = write!(
        md,
        "\nTimed by `cargo xtask regenerate --reports` on {} ({}): cost on a {}x{} {} at the defaults; error against the reference, FLIP mean over object pixels, at the defaults and over the error grid (every preset and the defaults × sphere and cloth × key, side and rim light).{}\n",
        m.adapter,
        m.timer,
        m.width,
        m.height,
        m.scene,
        model_note(model)
    );
    md
}

/// One material's tiers for the gallery: the timed figures in full (time,
/// SPIR-V size, FLIP mean and p99, relative RMSE, worst FLIP over the
/// grid), then the model's columns, with where and how each was measured.
pub fn gallery_table(
    m: &Measurements,
    current_inputs_hash: &str,
    model: Option<&ModelSummary>,
) -> String {
    let timed = timed_label(std::slice::from_ref(m));
    let mut md = format!("| tier | kind | {timed} ms | {timed} × standard fast | SPIR-V instr. |");
    let mut rule = String::from("| --- | --- | ---: | ---: | ---: |");
    model_header(&mut md, &mut rule, model);
    let _ = writeln!(
        md,
        " FLIP mean | FLIP p99 | rel. RMSE | FLIP worst (grid) |\n{rule} ---: | ---: | ---: | ---: |"
    );
    for t in &m.tiers {
        let _ = write!(
            md,
            "| {} | {} | {:.3} | {} | {} |",
            t.tier,
            t.kind.as_deref().unwrap_or("—"),
            t.gpu_ms,
            cost_cell(t),
            t.spirv_instructions,
        );
        model_cells(&mut md, model, &m.material, &t.tier);
        let _ = writeln!(
            md,
            " {:.4} | {:.4} | {:.4} | {} |",
            t.flip_mean,
            t.flip_p99,
            t.rel_rmse,
            t.flip_worst.map_or("—".to_string(), |v| format!("{v:.4}")),
        );
    }
    let stale = if m.inputs_hash != current_inputs_hash {
        " **Measured on an earlier version of the material: rerun `cargo xtask regenerate --reports`.**"
    } else {
        ""
    };
    let _ = writeln!(
        md,
        "\nMeasured on {} ({}), {}x{} {}, median over frames; error against the reference tier over object pixels.{stale}{}",
        m.adapter,
        m.timer,
        m.width,
        m.height,
        m.scene,
        model_note(model)
    );
    md
}

/// `shading.md`'s GPU model section: per material × tier and family, the
/// model's instructions, VGPRs, waves and executed cost × standard fast,
/// beside the timed ratio of the same report.
pub fn model_section(materials: &[Measurements], model: Option<&ModelSummary>) -> String {
    let Some(model) = model else {
        return "GPU model: no `generated/reports/gpu-model.json` (run `cargo xtask bench gpu-model --write`).\n".into();
    };
    let timed = timed_label(materials);
    let mut md = String::from("## GPU model per tier\n\n");
    let _ = writeln!(md, "{}\n", model_note(Some(model)).trim_start());
    let mut head = format!("| material | tier | {timed} × standard fast |");
    let mut rule = String::from("| --- | --- | ---: |");
    for f in &model.families {
        let _ = write!(
            head,
            " {0} instructions | {0} VGPRs / waves | {0} executed × standard fast |",
            f.family
        );
        rule.push_str(" ---: | ---: | ---: |");
    }
    let _ = writeln!(md, "{head}\n{rule}");
    for m in materials {
        for t in &m.tiers {
            let _ = write!(md, "| {} | {} | {} |", m.material, t.tier, cost_cell(t));
            for c in model_costs(Some(model), &m.material, &t.tier) {
                let _ = write!(
                    md,
                    " {} | {} | {} |",
                    c.map_or("—".into(), |c| c.fragment.instructions.to_string()),
                    regs(c),
                    ratio(c)
                );
            }
            md.push('\n');
        }
    }
    md
}

/// `scenes.md`'s GPU model section: per scene instance, its specialised
/// shader against the generic variant it specialises (fragment stages of the
/// passes it draws), per family, from the committed model and the built
/// scene metadata under `generated/scenes/`.
pub fn scene_model_section(
    generated: &Path,
    model: Option<&ModelSummary>,
) -> Result<String, String> {
    let Some(model) = model else {
        return Ok("GPU model: no `generated/reports/gpu-model.json` (run `cargo xtask bench gpu-model --write`).\n".into());
    };
    let dir = generated.join("scenes");
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(|e| e.ok())
        .filter(|e| e.path().is_dir())
        .filter_map(|e| e.file_name().into_string().ok())
        .collect();
    names.sort();
    let mut md = String::from("## GPU model per instance\n\n");
    let _ = writeln!(
        md,
        "Each instance's scene shader against the generic library variant it specialises: ISA \
         instructions, VGPRs and waves per SIMD (the fragment stages of the passes it draws: \
         instructions and cost summed, registers the worst pass) and the loop-aware executed \
         cost, from AMD's compiler on Mesa RADV's null device (`generated/reports/gpu-model.json`, \
         `cargo xtask bench gpu-model --write`).\n"
    );
    let mut head = String::from("| scene | instance | material | tier | shader |");
    let mut rule = String::from("| --- | --- | --- | --- | --- |");
    for f in &model.families {
        let _ = write!(
            head,
            " {0} instructions | {0} VGPRs | {0} waves | {0} executed cost | {0} saving |",
            f.family
        );
        rule.push_str(" ---: | ---: | ---: | ---: | ---: |");
    }
    let _ = writeln!(md, "{head}\n{rule}");
    let mut reductions: Vec<Vec<f64>> = vec![Vec::new(); model.families.len()];
    for name in &names {
        let path = dir.join(name).join(format!("{name}.scene.json"));
        let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let meta: SceneMetadata =
            serde_json::from_slice(&bytes).map_err(|e| format!("{}: {e}", path.display()))?;
        for inst in &meta.instances {
            let _ = write!(
                md,
                "| {name} | {} | {} | {} | `{}` |",
                inst.name, inst.material, inst.tier, inst.shader
            );
            for (k, f) in model.families.iter().enumerate() {
                let costs: Vec<(FragmentCost, FragmentCost)> = f
                    .scene_shaders
                    .iter()
                    .filter(|c| &c.scene == name && c.shader == inst.shader)
                    .filter(|c| inst.passes.iter().any(|p| p.name == c.pass))
                    .map(|c| (c.specialised, c.generic))
                    .collect();
                if costs.is_empty() {
                    md.push_str(" — | — | — | — | — |");
                    continue;
                }
                let sum = |pick: fn(&(FragmentCost, FragmentCost)) -> FragmentCost| {
                    FragmentCost::combined(costs.iter().map(pick)).expect("not empty")
                };
                let (s, g) = (sum(|c| c.0), sum(|c| c.1));
                let saving = 100.0 * (1.0 - s.executed_cost / g.executed_cost.max(1e-9));
                reductions[k]
                    .push(100.0 * (1.0 - s.instructions as f64 / g.instructions.max(1) as f64));
                let _ = write!(
                    md,
                    " {} → {} | {} → {} | {} → {} | {:.0} → {:.0} | {saving:.1}% |",
                    g.instructions,
                    s.instructions,
                    g.vgprs,
                    s.vgprs,
                    g.waves,
                    s.waves,
                    g.executed_cost,
                    s.executed_cost
                );
            }
            md.push('\n');
        }
    }
    let medians: Vec<String> = model
        .families
        .iter()
        .zip(&mut reductions)
        .map(|(f, r)| {
            r.sort_by(f64::total_cmp);
            let median = if r.is_empty() { 0.0 } else { r[r.len() / 2] };
            format!("{} {median:.1}% over {} instances", f.family, r.len())
        })
        .collect();
    let _ = writeln!(
        md,
        "\nMedian instruction reduction (generic → scene): {}.",
        medians.join(", ")
    );
    Ok(md)
}

#[cfg(test)]
mod tests {
    use super::*;
    use weft_meta::gpu_model::FamilySummary;

    fn measurements() -> Measurements {
        serde_json::from_str(
            r#"{"material":"silk","inputs_hash":"h","adapter":"llvmpipe (LLVM 15)","timer":"gpu-timestamp",
            "width":512,"height":512,"scene":"sphere","setup":"s","tiers":[
            {"tier":"fast","variant":"v","frames":50,"gpu_ms":7.4,"gpu_ms_min":7.0,"gpu_ms_spread":0.1,
             "ratio_to_standard_fast":0.96,"spirv_instructions":995,"spirv_fragment_instructions":671,
             "flip_mean":0.0017,"flip_p99":0.01,"rel_rmse":0.001,"kind":"approximation"}]}"#,
        )
        .unwrap()
    }

    fn model() -> ModelSummary {
        let cost = FragmentCost {
            instructions: 535,
            vgprs: 48,
            waves: 20,
            static_cost: 636.0,
            executed_cost: 636.0,
            unknown_loops: 0,
        };
        let family = |name: &str, ratio: f64| FamilySummary {
            family: name.into(),
            device_name: format!("Null hardware ({name})"),
            driver_info: "Mesa 22.3.6".into(),
            tiers: vec![TierCost {
                material: "silk".into(),
                tier: "fast".into(),
                variant: "v".into(),
                fragment: cost,
                executed_ratio: ratio,
            }],
            variants: Vec::new(),
            scene_shaders: Vec::new(),
        };
        ModelSummary {
            command: "c".into(),
            families: vec![family("navi21", 1.525), family("gfx1100", 1.5)],
        }
    }

    #[test]
    fn timed_and_modelled_costs_sit_in_their_own_columns() {
        let m = measurements();
        let md = ladder_table(&m, Some(&model()));
        let mut lines = md.lines();
        assert_eq!(
            lines.next().unwrap(),
            "| tier | kind | llvmpipe ms | llvmpipe × standard fast | navi21 model × | gfx1100 model × | VGPRs / waves (navi21) | FLIP at defaults | worst FLIP over the grid | worst cell |"
        );
        lines.next();
        assert_eq!(
            lines.next().unwrap(),
            "| fast | approximation | 7.4 | 0.96 | 1.52 | 1.50 | 48 / 20 | 0.002 | — | — |"
        );
        assert!(
            md.contains("`navi21` (Null hardware (navi21), Mesa 22.3.6)"),
            "{md}"
        );
        // Without a model the table keeps only the timed columns.
        let plain = ladder_table(&m, None);
        assert!(plain.starts_with(
            "| tier | kind | llvmpipe ms | llvmpipe × standard fast | FLIP at defaults |"
        ));
        let section = model_section(&[m], Some(&model()));
        assert!(
            section
                .contains("| silk | fast | 0.96 | 535 | 48 / 20 | 1.52 | 535 | 48 / 20 | 1.50 |"),
            "{section}"
        );
    }

    /// The gallery's table: the timed figures in full, then the model's own
    /// columns; a stale measurement says so.
    #[test]
    fn the_gallery_table_keeps_the_two_sources_apart() {
        let m = measurements();
        let md = gallery_table(&m, &m.inputs_hash, Some(&model()));
        let mut lines = md.lines();
        assert_eq!(
            lines.next().unwrap(),
            "| tier | kind | llvmpipe ms | llvmpipe × standard fast | SPIR-V instr. | navi21 model × | gfx1100 model × | VGPRs / waves (navi21) | FLIP mean | FLIP p99 | rel. RMSE | FLIP worst (grid) |"
        );
        lines.next();
        assert!(
            lines
                .next()
                .unwrap()
                .starts_with("| fast | approximation | 7.400 | 0.96 | "),
            "{md}"
        );
        assert!(md.contains("| 1.52 | 1.50 | 48 / 20 |"), "{md}");
        assert!(!md.contains("earlier version"), "{md}");
        let stale = gallery_table(&m, "another hash", None);
        assert!(stale.contains("Measured on an earlier version"), "{stale}");
        assert!(!stale.contains("model ×"), "{stale}");
    }
}
