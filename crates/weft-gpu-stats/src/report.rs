//! The markdown report of `cargo xtask bench gpu-model`: per family, each
//! material × tier (its default keyword values) × pass with the fragment
//! stage's figures and their ratio to `standard`'s `fast` tier; then each
//! scene shader against the generic library variant it specialises.

use crate::error::{Error, Result};
use crate::loop_report::{self, TierModel};
use crate::pairing::GenericVariants;
use crate::record::{FamilyStats, PipelineStats, StageStats};
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::Path;
use weft_meta::MaterialMetadata;

/// The driver's statistic names the report reads.
pub const INSTRUCTIONS: &str = "Instructions";
/// Vector registers per lane; fewer → more waves in flight.
pub const VGPRS: &str = "VGPRs";
/// RADV's waves per SIMD (occupancy) from the register and LDS use.
pub const WAVES: &str = "Subgroups per SIMD";
/// ACO's estimate of cycles per wave at full occupancy.
pub const INVERSE_THROUGHPUT: &str = "Inverse Throughput";

/// The baseline every ratio divides by.
const BASE: (&str, &str, &str) = ("standard", "fast", "forward");

type Key<'a> = (&'a str, &'a str, &'a str, &'a str); // material, variant, precision, pass

///
/// A variant with `constant`-mode keywords has a file set per value
/// combination; the first (its keywords' defaults, as the compiler orders
/// them) stands for the variant, as [`crate::summary`] takes it.
fn library_index(f: &FamilyStats) -> BTreeMap<Key<'_>, &PipelineStats> {
    let mut index = BTreeMap::new();
    for p in f.pipelines.iter().filter(|p| p.source.kind == "material") {
        let s = &p.source;
        index
            .entry((
                s.material.as_str(),
                s.variant.as_str(),
                s.precision.as_str(),
                p.pass.as_str(),
            ))
            .or_insert(p);
    }
    index
}

/// One row of the tier table: the default variant of a tier.
struct TierRow {
    material: String,
    tier: String,
    variant: String,
    passes: Vec<String>,
    /// Each pass's fragment entry point (the loop model reads its loops).
    fragment_entries: Vec<String>,
    has_f16: bool,
}

/// Each material's tiers in its order, each with the variant of the default keyword values.
fn tier_rows(generated: &Path, families: &[FamilyStats]) -> Result<Vec<TierRow>> {
    let mut materials: Vec<&str> = families
        .iter()
        .flat_map(|f| f.pipelines.iter())
        .filter(|p| p.source.kind == "material")
        .map(|p| p.source.material.as_str())
        .collect();
    materials.sort();
    materials.dedup();
    let mut rows = Vec::new();
    for name in materials {
        let path = generated.join(name).join(format!("{name}.meta.json"));
        let bytes =
            std::fs::read(&path).map_err(|e| Error::Input(format!("{}: {e}", path.display())))?;
        let meta: MaterialMetadata = serde_json::from_slice(&bytes)
            .map_err(|e| Error::Input(format!("{}: {e}", path.display())))?;
        for tier in &meta.tiers.values {
            let default = meta.variants.iter().find(|v| {
                &v.tier == tier
                    && v.keywords.iter().all(|(k, val)| {
                        meta.keywords
                            .iter()
                            .any(|kw| &kw.name == k && &kw.default == val)
                    })
            });
            let Some(v) = default.and_then(|v| meta.resolve_variant(&v.id)) else {
                continue;
            };
            rows.push(TierRow {
                material: name.into(),
                tier: tier.clone(),
                variant: v.id.clone(),
                passes: v.passes.clone(),
                fragment_entries: v
                    .passes
                    .iter()
                    .map(|name| {
                        meta.passes
                            .iter()
                            .find(|p| &p.name == name)
                            .map_or_else(String::new, |p| p.fragment_entry.clone())
                    })
                    .collect(),
                has_f16: v.shader.as_ref().is_some_and(|s| !s.f16_files.is_empty()),
            });
        }
    }
    Ok(rows)
}

fn fig(s: Option<&StageStats>, name: &str) -> Option<f64> {
    s.and_then(|s| s.get(name))
}

fn num(v: Option<f64>) -> String {
    v.map_or("–".into(), |v| format!("{v:.0}"))
}

fn ratio(v: Option<f64>, base: Option<f64>) -> String {
    match (v, base) {
        (Some(v), Some(b)) if b > 0.0 => format!("{:.2}×", v / b),
        _ => "–".into(),
    }
}

/// The report: `command` is the line that reproduces it.
pub fn markdown(generated: &Path, families: &[FamilyStats], command: &str) -> Result<String> {
    let rows = tier_rows(generated, families)?;
    let mut o = String::new();
    let _ = writeln!(
        o,
        "# GPU model: static figures from AMD's shader compiler\n"
    );
    let _ = writeln!(
        o,
        "Every pipeline built as its metadata describes it on Mesa RADV's null device (no GPU), \
         figures from `VK_KHR_pipeline_executable_properties` (ACO). Static: a loop body counts \
         once whatever its trip count (docs/performance.md). Reproduce with `{command}`.\n"
    );
    for f in families {
        let _ = writeln!(
            o,
            "- `{}`: {}, {}, {} pipelines",
            f.family,
            f.device_name,
            f.driver_info,
            f.pipelines.len()
        );
    }
    for f in families {
        tier_table(&mut o, f, &rows);
    }
    for f in families {
        loop_table(&mut o, generated, f, &rows);
    }
    for f in families {
        scene_table(&mut o, generated, f)?;
    }
    Ok(o)
}

fn tier_table(o: &mut String, f: &FamilyStats, rows: &[TierRow]) {
    let index = library_index(f);
    let base_row = rows
        .iter()
        .find(|r| r.material == BASE.0 && r.tier == BASE.1);
    let base = base_row
        .and_then(|r| index.get(&(BASE.0, r.variant.as_str(), "f32", BASE.2)))
        .and_then(|p| p.stage("fragment"));
    let _ = writeln!(
        o,
        "\n## {} ({}): fragment stage per material × tier\n\nThe variant of the material's \
         default keyword values; × standard fast: divided by `standard` `fast` `forward`.\n",
        f.family, f.device_name
    );
    let _ = writeln!(
        o,
        "| material | tier | pass | instructions | × standard fast | VGPRs | waves/SIMD | inverse throughput | × standard fast | VS instructions |"
    );
    let _ = writeln!(o, "|---|---|---|--:|--:|--:|--:|--:|--:|--:|");
    for r in rows {
        for precision in ["f32", "f16"] {
            if precision == "f16" && !r.has_f16 {
                continue;
            }
            for pass in &r.passes {
                let key = (
                    r.material.as_str(),
                    r.variant.as_str(),
                    precision,
                    pass.as_str(),
                );
                let Some(p) = index.get(&key) else { continue };
                let (fs, vs) = (p.stage("fragment"), p.stage("vertex"));
                let tier = if precision == "f16" {
                    format!("{} (f16)", r.tier)
                } else {
                    r.tier.clone()
                };
                let _ = writeln!(
                    o,
                    "| {} | {tier} | {pass} | {} | {} | {} | {} | {} | {} | {} |",
                    r.material,
                    num(fig(fs, INSTRUCTIONS)),
                    ratio(fig(fs, INSTRUCTIONS), fig(base, INSTRUCTIONS)),
                    num(fig(fs, VGPRS)),
                    num(fig(fs, WAVES)),
                    num(fig(fs, INVERSE_THROUGHPUT)),
                    ratio(fig(fs, INVERSE_THROUGHPUT), fig(base, INVERSE_THROUGHPUT)),
                    num(fig(vs, INSTRUCTIONS)),
                );
            }
        }
    }
}

/// Each material × tier's loop-aware model on one family (f32 files, fragment
/// stages summed over the variant's passes). Needs the disassembly.
pub fn tier_models(generated: &Path, f: &FamilyStats) -> Result<Vec<TierModel>> {
    let rows = tier_rows(generated, std::slice::from_ref(f))?;
    Ok(models_of(generated, f, &rows, "f32"))
}

/// The model of each row's `precision` files (`f32`, or `f16` for the rows
/// that have them); a row whose pipelines lack figures is left out.
fn models_of(
    generated: &Path,
    f: &FamilyStats,
    rows: &[TierRow],
    precision: &str,
) -> Vec<TierModel> {
    let index = library_index(f);
    let mut out = Vec::new();
    for r in rows.iter().filter(|r| precision == "f32" || r.has_f16) {
        let mut t = TierModel {
            material: r.material.clone(),
            tier: r.tier.clone(),
            variant: r.variant.clone(),
            static_cost: 0.0,
            executed_cost: 0.0,
            loops: 0,
            unknown: 0,
        };
        let mut complete = true;
        for (pass, entry) in r.passes.iter().zip(&r.fragment_entries) {
            let key = (
                r.material.as_str(),
                r.variant.as_str(),
                precision,
                pass.as_str(),
            );
            let m = index
                .get(&key)
                .and_then(|p| loop_report::fragment_model(generated, p, entry));
            let Some(m) = m else {
                complete = false;
                break;
            };
            t.static_cost += m.static_cost;
            t.executed_cost += m.executed_cost;
            t.loops += m.loops.len();
            t.unknown += m.unknown_loops();
        }
        if complete {
            out.push(t);
        }
    }
    out
}

/// One row of the loop-aware table: a tier's model for one kind of files,
/// beside the timings of the same files.
struct CostedRow {
    label: String,
    model: TierModel,
    /// Picks the timing of these files from a tier's ratios.
    files: fn(&loop_report::TierRatio) -> Option<f64>,
}

fn loop_table(o: &mut String, generated: &Path, f: &FamilyStats, rows: &[TierRow]) {
    let models = models_of(generated, f, rows, "f32");
    let Some(base) = models
        .iter()
        .find(|m| m.material == BASE.0 && m.tier == BASE.1)
        .cloned()
    else {
        return; // no disassembly captured
    };
    // Each tier's f32 files, and after a half-precision tier its f16 files
    // (what a device with `shader-f16` runs).
    let f16 = models_of(generated, f, rows, "f16");
    let mut costed = Vec::new();
    for m in models {
        let half = f16
            .iter()
            .find(|h| h.material == m.material && h.tier == m.tier)
            .cloned();
        let label = m.tier.clone();
        costed.push(CostedRow {
            label,
            model: m,
            files: |r| Some(r.f32_files()),
        });
        if let Some(h) = half {
            costed.push(CostedRow {
                label: format!("{} (f16)", h.tier),
                model: h,
                files: |r| r.f16_files(),
            });
        }
    }
    let _ = writeln!(
        o,
        "\n## {}: loop-aware model per material × tier\n\nWeighted ISA cost (VALU 1, \
         transcendental 4, vector memory 8, scalar memory 2, waits 0) of the fragment stages of the \
         variant's passes: static (each block once) and executed (each block × the trip counts of \
         the loops around it, from the specialised WGSL; docs/performance.md). × standard fast: \
         divided by `standard` `fast`. A half-precision tier has a row for its f32 files and one \
         for its f16 files (`(f16)`, what a device with `shader-f16` runs). llvmpipe: \
         `ratio_to_standard_fast` of `generated/reports/<material>.measurements.json` for the same \
         files (a half-precision tier's f32 row: its `f32_files` ratio).\n",
        f.family
    );
    let _ = writeln!(
        o,
        "| material | tier | static cost | executed cost | static × standard fast | executed × standard fast | loops (unknown trip count) | llvmpipe × standard fast |"
    );
    let _ = writeln!(o, "|---|---|--:|--:|--:|--:|--:|--:|");
    let llvmpipe_of = |c: &CostedRow| {
        loop_report::llvmpipe_ratio(generated, &c.model.material, &c.model.tier)
            .and_then(|r| (c.files)(&r))
    };
    let mut pairs = Vec::new();
    let mut statics = Vec::new();
    let mut unknown = Vec::new();
    for c in &costed {
        let m = &c.model;
        let executed = m.executed_cost / base.executed_cost;
        let llvmpipe = llvmpipe_of(c);
        if let Some(l) = llvmpipe {
            pairs.push((executed, l));
            statics.push((m.static_cost, l));
        }
        if m.unknown > 0 {
            unknown.push(format!("{} {} ({})", m.material, c.label, m.unknown));
        }
        let _ = writeln!(
            o,
            "| {} | {} | {:.0} | {:.0} | {:.2}× | {executed:.2}× | {} ({}) | {} |",
            m.material,
            c.label,
            m.static_cost,
            m.executed_cost,
            m.static_cost / base.static_cost,
            m.loops,
            m.unknown,
            llvmpipe.map_or("–".into(), |l| format!("{l:.2}×")),
        );
    }
    let rho =
        |p: &[(f64, f64)]| loop_report::spearman(p).map_or("–".into(), |r| format!("{r:.3}"));
    let gpus: Vec<String> = loop_report::committed_gpu_timings(generated)
        .iter()
        .map(|g| {
            // Only timings of today's files rank today's costs.
            let current = g.current_ratios(generated);
            let timed: Vec<(&CostedRow, f64)> = costed
                .iter()
                .filter_map(|c| {
                    let key = (c.model.material.clone(), c.model.tier.clone());
                    Some((c, (c.files)(current.get(&key)?)?))
                })
                .collect();
            let earlier = g.tiers.len() - current.len();
            let pairs: Vec<(f64, f64)> = timed
                .iter()
                .map(|(c, gpu)| (c.model.executed_cost / base.executed_cost, *gpu))
                .collect();
            let statics: Vec<(f64, f64)> = timed
                .iter()
                .map(|(c, gpu)| (c.model.static_cost, *gpu))
                .collect();
            let then = g
                .recorded_rho(&f.family)
                .map_or("–".into(), |r| format!("{r:.3}"));
            // A tier counts as timed on today's files when its material's
            // `inputs_hash` is the one the report recorded (reports before
            // 2026-11-29 recorded none).
            if pairs.is_empty() {
                return format!(
                    "{} (`generated/reports/{}`): none of its {} tiers was timed on today's files \
                     (the material's `inputs_hash`, recorded since 2026-11-29); the run's own ρ \
                     against the model of the library it timed: {then}",
                    g.adapter,
                    g.file,
                    g.tiers.len()
                );
            }
            let mut line = format!(
                "{} (`generated/reports/{}`, {} pairs timed on today's files): executed cost ρ = \
                 {}, static cost ρ = {}",
                g.adapter,
                g.file,
                pairs.len(),
                rho(&pairs),
                rho(&statics)
            );
            if earlier > 0 {
                let _ = write!(
                    line,
                    " ({earlier} of its {} tiers, timed on an earlier version of their material, \
                     left out; the run's own ρ against the model of then: {then})",
                    g.tiers.len()
                );
            }
            line
        })
        .collect();
    let _ = writeln!(
        o,
        "\nSpearman rank correlation with llvmpipe over the {} material × tier pairs with both \
         (each half-precision tier's f32 and f16 files apart): executed cost ρ = {}, static cost \
         ρ = {}. With real GPUs' ratios (`cargo xtask bench gpu`): {}. Loops with an unknown trip \
         count (counted once): {}.",
        pairs.len(),
        rho(&pairs),
        rho(&statics),
        if gpus.is_empty() {
            "none committed".into()
        } else {
            gpus.join("; ")
        },
        if unknown.is_empty() {
            "none".into()
        } else {
            unknown.join(", ")
        }
    );
}

fn scene_table(o: &mut String, generated: &Path, f: &FamilyStats) -> Result<()> {
    let mut generics = GenericVariants::new(generated);
    let scenes: Vec<&PipelineStats> = f
        .pipelines
        .iter()
        .filter(|p| p.source.kind == "scene")
        .collect();
    if scenes.is_empty() {
        return Ok(());
    }
    let _ = writeln!(
        o,
        "\n## {}: scene shaders against their generic variants (fragment stage)\n",
        f.family
    );
    let _ = writeln!(
        o,
        "| scene | shader | variant | pass | instructions (scene / generic) | VGPRs (scene / generic) | inverse throughput (scene / generic) |"
    );
    let _ = writeln!(o, "|---|---|---|---|--:|--:|--:|");
    for p in scenes {
        let s = &p.source;
        let generic = generics.generic_of(f, p)?.and_then(|g| g.stage("fragment"));
        let fs = p.stage("fragment");
        let pair = |name: &str| format!("{} / {}", num(fig(fs, name)), num(fig(generic, name)));
        let _ = writeln!(
            o,
            "| {} | {} | {} | {} | {} | {} | {} |",
            s.scene.as_deref().unwrap_or(""),
            s.shader.as_deref().unwrap_or(""),
            s.variant,
            p.pass,
            pair(INSTRUCTIONS),
            pair(VGPRS),
            pair(INVERSE_THROUGHPUT),
        );
    }
    Ok(())
}
