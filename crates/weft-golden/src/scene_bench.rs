//! The scene benchmark: what drawing a scene with its scene-specialised
//! shaders (`generated/scenes/<scene>/`) saves against drawing the same
//! scene, instance values included, with the generic library variants
//! (`generated/<material>/`, [`SceneShaders::Library`]), measured in one run
//! on one adapter:
//!
//! - GPU time per frame (timestamp queries; CPU wall time when the adapter
//!   has none, said in `timer`), same camera, pixels and [`RenderOptions`],
//!   in interleaved rounds (generic, specialised, generic, …) so that machine
//!   drift hits both alike: the median of the per-round medians;
//! - the FLIP error between the two images over object pixels
//!   ([`crate::shading::image_error`]), so the saving is shown with the picture;
//! - per instance: the time of the instance drawn alone (and of an empty
//!   pass, the clear), SPIR-V instructions of the fragment entry point
//!   (generic variant vs specialised shader) and material uniform bytes;
//! - shader, file and byte counts of both ways of shipping the scene;
//! - build time: the scene's materials built generically
//!   (`weft_compiler::build_materials`) vs `weft_compiler::build_scene` with
//!   the lavapipe tier chooser (its renders included).
//!
//! Shared by `cargo xtask bench scene`; reports go to
//! `generated/reports/scenes.md` and `scenes.json`.

mod figures;
mod measure;
mod report;
mod static_figures;
#[cfg(test)]
mod tests;

pub use figures::{
    AbTiming, FileStats, InstanceBench, SceneBench, SceneBenchReport, SpirvCounts, Spread,
};
pub use measure::interleaved;
pub use report::{
    describe, json_report, markdown_report, scene_section, summary_table, write_reports,
};

use crate::scenes::SceneHarness;
use measure::Bench;
use std::path::{Path, PathBuf};
use std::time::Instant;
use weft_render::{Background, FrameTimer, RenderOptions};

/// The bound on the FLIP mean between the generic and the specialised image
/// (the scene tests' threshold).
pub const FLIP_BOUND: f64 = crate::scenes::FOLD_FLIP_MEAN_THRESHOLD;
/// The target: at least this much less GPU time than the generic draw.
pub const TARGET_SAVING: f64 = 0.30;

/// The variable that sets lavapipe's rasterizer threads. On a machine with
/// few cores its workers compete with the submitting thread and the frame
/// times of an A/B pair stop being comparable (on 2 cores, per-round savings
/// of one scene ranged over −15%…+47% with 2 workers and 30%…42% with 1), so
/// `cargo xtask bench scene` sets it to 1 unless it is set; the report
/// records it. Other adapters ignore it.
pub const LAVAPIPE_THREADS: &str = "LP_NUM_THREADS";

/// One scene to measure: its manifest and the material TOML files its
/// instances use (as the front end resolved them), for the generic build.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneInput {
    /// `scenes/<name>.scene.toml`.
    pub manifest: PathBuf,
    /// The materials root includes resolve against.
    pub materials_root: PathBuf,
    pub material_tomls: Vec<PathBuf>,
}

impl SceneInput {
    /// The scene's name: the file name before `.scene.toml`.
    pub fn name(&self) -> String {
        let file = self
            .manifest
            .file_name()
            .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
        file.strip_suffix(".scene.toml")
            .unwrap_or(&file)
            .to_string()
    }
}

/// What the benchmark draws and how long it times.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneBenchOptions {
    pub width: u32,
    pub height: u32,
    /// Rounds of (generic, specialised); also the rounds of every instance pair.
    pub rounds: u32,
    /// Timed frames per arm and round (their median is the round's figure).
    pub frames: u32,
    /// Untimed frames before each arm's first round.
    pub warmup: u32,
    /// Builds of each kind (interleaved; the median is reported).
    pub build_runs: u32,
    /// Time with the CPU even when the adapter has timestamp queries.
    pub force_cpu_timer: bool,
    /// Also time every instance drawn alone (and an empty pass).
    pub per_instance: bool,
}

impl Default for SceneBenchOptions {
    fn default() -> Self {
        SceneBenchOptions {
            width: 640,
            height: 400,
            rounds: 10,
            frames: 10,
            warmup: 3,
            build_runs: 5,
            force_cpu_timer: false,
            per_instance: true,
        }
    }
}

/// Measures every scene in `inputs` against the `generated` folder (the
/// library in `<material>/`, the scenes in `scenes/<scene>/`).
pub fn run(
    generated: &Path,
    inputs: &[SceneInput],
    options: &SceneBenchOptions,
    log: &mut dyn FnMut(&str),
) -> Result<SceneBenchReport, String> {
    let started = Instant::now();
    let mut harness = SceneHarness::new(generated).map_err(|e| e.to_string())?;
    let adapter = harness.adapter();
    log(&format!("adapter: {adapter}"));
    let renderer = harness.renderer();
    let render = render_options(options);
    let mut timer = if options.force_cpu_timer || !renderer.has_timestamp_queries() {
        FrameTimer::CpuWall
    } else {
        FrameTimer::GpuTimestamp
    };
    let mut scenes = Vec::new();
    for input in inputs {
        let name = input.name();
        let mut bench = Bench {
            renderer: &mut *renderer,
            generated,
            render: &render,
            options,
            timer: &mut timer,
        };
        let scene = bench
            .scene(input, log)
            .map_err(|err| format!("scene `{name}`: {err}"))?;
        scenes.push(scene);
    }
    Ok(SceneBenchReport {
        adapter,
        timer,
        options: options.clone(),
        profile: if cfg!(debug_assertions) {
            "debug"
        } else {
            "release"
        }
        .into(),
        lavapipe_threads: std::env::var(LAVAPIPE_THREADS).ok(),
        scenes,
        seconds: started.elapsed().as_secs_f64(),
    })
}

/// The options every frame is drawn with (those of the scene goldens, at
/// the bench's size, over transparent black).
pub fn render_options(options: &SceneBenchOptions) -> RenderOptions {
    crate::scenes::render_options(
        (options.width.max(1), options.height.max(1)),
        Background::Color([0.0; 4]),
    )
}
