//! `cargo xtask bench shading`: every material × tier timed (weft_golden::shading), its reports, and the docs' tier tables, which put that timing beside the GPU model's cost (weft_golden::cost_tables).

use std::path::Path;
use std::process::ExitCode;

#[derive(clap::Args)]
pub(crate) struct ShadingArgs {
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
    pub(crate) fn options(&self) -> weft_golden::shading::ShadingOptions {
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

/// Runs the shading benchmark on generated/, prints the table and, with
/// `write`, rewrites its files in generated/reports/.
pub(crate) fn bench_shading(
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

/// Rewrites each measured material README's shell table
/// (`<!-- weft:shells:… -->`).
pub(crate) fn write_shell_tables(
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
pub(crate) fn write_tier_tables(
    root: &Path,
    materials: &[weft_meta::Measurements],
) -> Result<(), String> {
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
pub(crate) fn update_marked(path: &Path, name: &str, content: &str) -> Result<(), String> {
    update_all_marked(path, &[(name.to_owned(), content.to_owned())])
}

/// [`update_marked`] for several marked tables of one file: read once,
/// written once (if anything changed).
fn update_all_marked(path: &Path, tables: &[(String, String)]) -> Result<(), String> {
    let Ok(text) = std::fs::read_to_string(path) else {
        return Ok(());
    };
    let mut new = text.clone();
    let mut updated = Vec::new();
    for (name, content) in tables {
        if let Some(replaced) = weft_golden::shading::replace_marked(&new, name, content)
            && replaced != new
        {
            new = replaced;
            updated.push(name.as_str());
        }
    }
    if new != text {
        std::fs::write(path, new).map_err(|e| format!("{}: {e}", path.display()))?;
        for name in updated {
            println!("updated the `{name}` table in {}", path.display());
        }
    }
    Ok(())
}

/// After `bench gpu-model --write`: the docs' cost tables and plots from the
/// committed measurements and the new model, without timing anything again
/// (the tier tables, each material's Pareto plot and gallery table,
/// shading.md's model section).
pub(crate) fn rewrite_cost_tables(root: &Path) -> Result<(), String> {
    let reports = root.join("generated/reports");
    let model = weft_meta::gpu_model::ModelSummary::load(&reports)?;
    let mut materials = Vec::new();
    let mut gallery_tables = Vec::new();
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
        gallery_tables.push((
            crate::gallery::gallery_marker(&m.material),
            weft_golden::cost_tables::gallery_table(&m, &meta.inputs_hash, Some(&model)),
        ));
        materials.push(m);
    }
    update_all_marked(&root.join("generated/gallery.md"), &gallery_tables)?;
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
