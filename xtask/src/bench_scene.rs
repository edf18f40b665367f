//! `cargo xtask bench scene`: every shipped scene drawn with its specialised shaders against the generic variants (weft_golden::scene_bench).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

#[derive(clap::Args)]
pub(crate) struct SceneArgs {
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
    pub(crate) fn options(&self) -> weft_golden::scene_bench::SceneBenchOptions {
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
    pub(crate) fn command(&self) -> String {
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
pub(crate) fn bench_scene(root: &Path, args: &SceneArgs, write: bool) -> ExitCode {
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
