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

use crate::scenes::SceneHarness;
use crate::shading::{ImageError, image_error, quantile, spirv_instruction_counts};
use serde_json::json;
use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;
use weft_meta::scene::{SceneInstance, SceneMetadata};
use weft_meta::{MaterialMetadata, ShaderFile, Variant, VariantShader};
use weft_render::{
    Background, FrameTimer, HdrImage, RenderOptions, Renderer, SceneFile, SceneShaders,
    TimingOptions,
};

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

/// A/B timing: the per-round medians of both arms, round by round.
#[derive(Clone, Debug, PartialEq)]
pub struct AbTiming {
    pub generic: Vec<f64>,
    pub specialised: Vec<f64>,
}

/// Statistics of a series of per-round figures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spread {
    pub median: f64,
    /// (p90 − p10) / median (nearest rank).
    pub spread: f64,
    pub min: f64,
    pub max: f64,
}

impl Spread {
    pub fn of(values: &[f64]) -> Spread {
        let median = quantile(values, 0.5);
        Spread {
            median,
            spread: (quantile(values, 0.9) - quantile(values, 0.1)) / median,
            min: quantile(values, 0.0),
            max: quantile(values, 1.0),
        }
    }
}

impl AbTiming {
    pub fn generic_stats(&self) -> Spread {
        Spread::of(&self.generic)
    }

    pub fn specialised_stats(&self) -> Spread {
        Spread::of(&self.specialised)
    }

    /// Specialised median over generic median.
    pub fn ratio(&self) -> f64 {
        self.specialised_stats().median / self.generic_stats().median
    }

    /// 1 − ratio, in percent (positive: the specialised draw is faster).
    pub fn saving_pct(&self) -> f64 {
        (1.0 - self.ratio()) * 100.0
    }

    /// The saving of each round, percent (specialised against the generic
    /// median of the same round, drawn just before it).
    pub fn round_savings_pct(&self) -> Vec<f64> {
        self.generic
            .iter()
            .zip(&self.specialised)
            .map(|(g, s)| (1.0 - s / g) * 100.0)
            .collect()
    }

    /// Rounds in which the specialised median was below the generic one.
    pub fn rounds_faster(&self) -> usize {
        self.generic
            .iter()
            .zip(&self.specialised)
            .filter(|(g, s)| s < g)
            .count()
    }

    fn json(&self) -> serde_json::Value {
        let (g, s) = (self.generic_stats(), self.specialised_stats());
        json!({
            "generic_ms": round(g.median, 4),
            "specialised_ms": round(s.median, 4),
            "ratio": round(self.ratio(), 4),
            "saving_pct": round(self.saving_pct(), 2),
            "generic_spread": round(g.spread, 4),
            "specialised_spread": round(s.spread, 4),
            "rounds_specialised_faster": self.rounds_faster(),
            "round_savings_pct": self.round_savings_pct().iter().map(|x| round(*x, 2)).collect::<Vec<_>>(),
            "round_saving_median_pct": round(quantile(&self.round_savings_pct(), 0.5), 2),
            "rounds": self.generic.len(),
            "generic_round_medians_ms": self.generic.iter().map(|x| round(*x, 4)).collect::<Vec<_>>(),
            "specialised_round_medians_ms": self.specialised.iter().map(|x| round(*x, 4)).collect::<Vec<_>>(),
        })
    }
}

/// Runs `rounds` rounds over `arms` arms (arm 0, 1, …, n−1, then again),
/// `time(arm, round)` returning that call's samples; returns, per arm, the
/// median of each round's samples.
pub fn interleaved(
    rounds: u32,
    arms: usize,
    mut time: impl FnMut(usize, u32) -> Result<Vec<f64>, String>,
) -> Result<Vec<Vec<f64>>, String> {
    let mut out = vec![Vec::with_capacity(rounds as usize); arms];
    for r in 0..rounds {
        for (arm, medians) in out.iter_mut().enumerate() {
            let samples = time(arm, r)?;
            if samples.is_empty() {
                return Err(format!("arm {arm} returned no samples in round {r}"));
            }
            medians.push(quantile(&samples, 0.5));
        }
    }
    Ok(out)
}

/// SPIR-V instruction counts: (module, fragment entry point's functions).
pub type SpirvCounts = (u32, u32);

/// One instance's figures.
#[derive(Clone, Debug, PartialEq)]
pub struct InstanceBench {
    pub name: String,
    pub material: String,
    pub tier: String,
    /// The generic library variant drawn (`alias_of` followed).
    pub generic_variant: String,
    /// The scene shader drawn.
    pub shader: String,
    pub spirv_generic: SpirvCounts,
    pub spirv_specialised: SpirvCounts,
    /// Material uniform bytes (0 when the shader reads none).
    pub uniform_generic: u32,
    pub uniform_specialised: u32,
    /// Drawn alone (same camera, options and transform).
    pub gpu: Option<AbTiming>,
    pub flip: Option<ImageError>,
}

impl InstanceBench {
    /// Fragment-instruction reduction, percent.
    pub fn spirv_reduction_pct(&self) -> f64 {
        reduction_pct(self.spirv_generic.1, self.spirv_specialised.1)
    }
}

fn reduction_pct(generic: u32, specialised: u32) -> f64 {
    if generic == 0 {
        return 0.0;
    }
    (1.0 - f64::from(specialised) / f64::from(generic)) * 100.0
}

/// Shaders and files of one way of shipping a scene.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FileStats {
    /// Distinct shaders (generic: canonical library variants; scene: scene shaders).
    pub shaders: usize,
    pub shader_files: usize,
    pub shader_bytes: u64,
    /// Metadata files (generic: each material's `.meta.json`; scene: `<scene>.scene.json`).
    pub metadata_files: usize,
    pub metadata_bytes: u64,
}

impl FileStats {
    pub fn files(&self) -> usize {
        self.shader_files + self.metadata_files
    }

    pub fn bytes(&self) -> u64 {
        self.shader_bytes + self.metadata_bytes
    }

    fn json(&self) -> serde_json::Value {
        json!({
            "shaders": self.shaders,
            "shader_files": self.shader_files,
            "shader_bytes": self.shader_bytes,
            "metadata_files": self.metadata_files,
            "metadata_bytes": self.metadata_bytes,
            "files": self.files(),
            "bytes": self.bytes(),
        })
    }
}

/// One scene's figures.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneBench {
    pub name: String,
    /// Of `generated/scenes/<scene>/<scene>.scene.json`, the files measured.
    pub inputs_hash: String,
    /// Whether a fresh `build_scene` produced exactly the files measured.
    pub current: bool,
    pub gpu: AbTiming,
    pub flip: ImageError,
    /// Per-round medians of an empty pass (the clear alone), with per-instance timing.
    pub empty_pass: Option<Vec<f64>>,
    pub instances: Vec<InstanceBench>,
    pub generic_files: FileStats,
    pub scene_files: FileStats,
    /// Build times, ms: generic materials and scene build, per run.
    pub build: AbTiming,
}

impl SceneBench {
    /// Mean over instances of the fragment-instruction reduction, percent.
    pub fn spirv_mean_reduction_pct(&self) -> f64 {
        if self.instances.is_empty() {
            return 0.0;
        }
        self.instances
            .iter()
            .map(InstanceBench::spirv_reduction_pct)
            .sum::<f64>()
            / self.instances.len() as f64
    }
}

/// The result of [`run`].
#[derive(Clone, Debug)]
pub struct SceneBenchReport {
    pub adapter: String,
    pub timer: FrameTimer,
    pub options: SceneBenchOptions,
    /// `debug` or `release`: the build times depend on it.
    pub profile: String,
    /// `LP_NUM_THREADS` (lavapipe's rasterizer threads) when set.
    pub lavapipe_threads: Option<String>,
    pub scenes: Vec<SceneBench>,
    /// Wall time of the whole run, seconds.
    pub seconds: f64,
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

struct Bench<'a> {
    renderer: &'a mut Renderer,
    generated: &'a Path,
    render: &'a RenderOptions,
    options: &'a SceneBenchOptions,
    timer: &'a mut FrameTimer,
}

impl Bench<'_> {
    fn scene(
        &mut self,
        input: &SceneInput,
        log: &mut dyn FnMut(&str),
    ) -> Result<SceneBench, String> {
        let name = input.name();
        let path = crate::scenes::built_scene_path(self.generated, &name);
        let file = SceneFile::load(&path).map_err(|e| e.to_string())?;
        let dir = file.dir.clone();
        let meta = &file.metadata;
        let libraries = load_libraries(self.generated, meta)?;
        let mut instances = Vec::new();
        for inst in &meta.instances {
            instances.push(instance_figures(self.generated, &file, inst, &libraries)?);
        }

        // Builds first: a scene that does not build fails before the long part.
        log(&format!("{name}: timing builds"));
        let (build, current) = time_builds(input, &dir, self.generated, self.options.build_runs)?;
        if !current {
            log(&format!(
                "warning: generated/scenes/{name}/ differs from a fresh build; run `cargo xtask regenerate`"
            ));
        }

        log(&format!("{name}: timing the whole scene"));
        let (gpu, images) = self.time_pair(&file)?;
        let flip = image_error(&images[0], &images[1]);
        let empty_pass = if self.options.per_instance {
            log(&format!("{name}: timing each instance alone"));
            Some(self.time_instances(&file, &mut instances)?)
        } else {
            None
        };
        Ok(SceneBench {
            name,
            inputs_hash: meta.inputs_hash.clone(),
            current,
            gpu,
            flip,
            empty_pass,
            instances,
            generic_files: generic_file_stats(self.generated, meta, &libraries)?,
            scene_files: scene_file_stats(&dir, meta)?,
            build,
        })
    }

    fn timing(&self, round: u32) -> TimingOptions {
        TimingOptions {
            warmup: if round == 0 { self.options.warmup } else { 0 },
            frames: self.options.frames.max(1),
            force_cpu_timer: self.options.force_cpu_timer,
        }
    }

    /// Generic and specialised draws of `scenes` (each one prepared both
    /// ways), interleaved; returns the per-round medians of every arm (scene
    /// i generic at 2i, specialised at 2i + 1) and the last image of each.
    fn time_arms(
        &mut self,
        scenes: &[SceneFile],
    ) -> Result<(Vec<Vec<f64>>, Vec<HdrImage>), String> {
        let library = SceneShaders::Library(self.generated.to_path_buf());
        let mut prepared = Vec::new();
        for scene in scenes {
            for shaders in [&library, &SceneShaders::Specialised] {
                prepared.push(
                    self.renderer
                        .prepare_scene(scene, shaders, self.render)
                        .map_err(|e| e.to_string())?,
                );
            }
        }
        let mut images: Vec<Option<HdrImage>> = vec![None; prepared.len()];
        let rounds = self.options.rounds.max(1);
        let medians = interleaved(rounds, prepared.len(), |arm, round| {
            let t = self
                .renderer
                .time_scene_frames(&prepared[arm], self.render, &self.timing(round))
                .map_err(|e| format!("{}: {e}", prepared[arm].name()))?;
            *self.timer = t.timer;
            images[arm] = Some(t.image);
            Ok(t.ms)
        })?;
        let images = images
            .into_iter()
            .map(|i| i.expect("every arm drew at least once"))
            .collect();
        Ok((medians, images))
    }

    fn time_pair(&mut self, scene: &SceneFile) -> Result<(AbTiming, Vec<HdrImage>), String> {
        let (mut medians, images) = self.time_arms(std::slice::from_ref(scene))?;
        let specialised = medians.pop().expect("two arms");
        let generic = medians.pop().expect("two arms");
        Ok((
            AbTiming {
                generic,
                specialised,
            },
            images,
        ))
    }

    /// Every instance drawn alone, both ways, and an empty pass (both
    /// arms of the empty scene draw nothing); returns the empty pass's
    /// per-round medians.
    fn time_instances(
        &mut self,
        file: &SceneFile,
        instances: &mut [InstanceBench],
    ) -> Result<Vec<f64>, String> {
        let alone = |keep: Option<usize>| {
            let mut f = file.clone();
            f.metadata.instances = keep
                .map(|i| vec![file.metadata.instances[i].clone()])
                .unwrap_or_default();
            f
        };
        let mut scenes = vec![alone(None)];
        scenes.extend((0..instances.len()).map(|i| alone(Some(i))));
        let (mut medians, images) = self.time_arms(&scenes)?;
        for (i, inst) in instances.iter_mut().enumerate() {
            let a = 2 * (i + 1);
            inst.gpu = Some(AbTiming {
                generic: std::mem::take(&mut medians[a]),
                specialised: std::mem::take(&mut medians[a + 1]),
            });
            inst.flip = Some(image_error(&images[a], &images[a + 1]));
        }
        // Both empty arms draw the same nothing: one series of 2 per round.
        Ok(medians[0]
            .iter()
            .zip(&medians[1])
            .map(|(a, b)| 0.5 * (a + b))
            .collect())
    }
}

/// Every material the scene uses, from `<generated>/<material>/<material>.meta.json`.
fn load_libraries(
    generated: &Path,
    meta: &SceneMetadata,
) -> Result<BTreeMap<String, MaterialMetadata>, String> {
    let mut out = BTreeMap::new();
    for inst in &meta.instances {
        if out.contains_key(&inst.material) {
            continue;
        }
        let path = library_meta_path(generated, &inst.material);
        let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let m: MaterialMetadata =
            serde_json::from_slice(&bytes).map_err(|e| format!("{}: {e}", path.display()))?;
        out.insert(inst.material.clone(), m);
    }
    Ok(out)
}

fn library_meta_path(generated: &Path, material: &str) -> PathBuf {
    generated
        .join(material)
        .join(format!("{material}.meta.json"))
}

/// The canonical library variant an instance's generic draw uses.
fn canonical_variant<'a>(
    m: &'a MaterialMetadata,
    id: &str,
) -> Result<(&'a Variant, &'a VariantShader), String> {
    let find = |id: &str| m.variants.iter().find(|v| v.id == id);
    let v = find(id).ok_or_else(|| format!("material `{}` has no variant `{id}`", m.name))?;
    let canonical = match &v.alias_of {
        Some(target) => find(target).ok_or_else(|| {
            format!(
                "variant `{id}` of `{}` aliases `{target}`, which is missing",
                m.name
            )
        })?,
        None => v,
    };
    let shader = canonical.shader.as_ref().ok_or_else(|| {
        format!(
            "variant `{}` of `{}` has no shader files",
            canonical.id, m.name
        )
    })?;
    Ok((canonical, shader))
}

/// The SPIR-V file of `shader` whose baked constant-mode keywords have the
/// instance's values, counted.
fn spirv_counts(
    dir: &Path,
    shader: &VariantShader,
    keywords: &BTreeMap<String, String>,
) -> Result<SpirvCounts, String> {
    let matches = |f: &&ShaderFile| f.constants.iter().all(|(k, v)| keywords.get(k) == Some(v));
    let file = shader
        .files
        .get("spirv")
        .and_then(|files| files.iter().find(matches))
        .ok_or_else(|| {
            format!(
                "no SPIR-V file for keywords {keywords:?} in {}",
                dir.display()
            )
        })?;
    let path = dir.join(&file.path);
    let bytes = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    spirv_instruction_counts(&bytes).map_err(|e| format!("{}: {e}", path.display()))
}

/// The static figures of an instance (timing is added later).
fn instance_figures(
    generated: &Path,
    file: &SceneFile,
    inst: &SceneInstance,
    libraries: &BTreeMap<String, MaterialMetadata>,
) -> Result<InstanceBench, String> {
    let m = &libraries[&inst.material];
    let (variant, generic) = canonical_variant(m, &inst.variant)?;
    let scene_shader = file
        .metadata
        .shaders
        .iter()
        .find(|s| s.id == inst.shader)
        .ok_or_else(|| format!("instance `{}` names no shader of the scene", inst.name))?;
    let uniform = |s: &VariantShader| s.material_uniform.as_ref().map_or(0, |u| u.size);
    Ok(InstanceBench {
        name: inst.name.clone(),
        material: inst.material.clone(),
        tier: inst.tier.clone(),
        generic_variant: variant.id.clone(),
        shader: inst.shader.clone(),
        spirv_generic: spirv_counts(&generated.join(&inst.material), generic, &inst.keywords)?,
        spirv_specialised: spirv_counts(&file.dir, &scene_shader.shader, &inst.keywords)?,
        uniform_generic: uniform(generic),
        uniform_specialised: uniform(&scene_shader.shader),
        gpu: None,
        flip: None,
    })
}

fn file_len(path: &Path) -> Result<u64, String> {
    std::fs::metadata(path)
        .map(|m| m.len())
        .map_err(|e| format!("{}: {e}", path.display()))
}

/// The distinct canonical library variants the instances use, all their
/// files (every language), and the materials' metadata.
fn generic_file_stats(
    generated: &Path,
    meta: &SceneMetadata,
    libraries: &BTreeMap<String, MaterialMetadata>,
) -> Result<FileStats, String> {
    let mut variants = BTreeSet::new();
    let mut stats = FileStats::default();
    for inst in &meta.instances {
        let (v, shader) = canonical_variant(&libraries[&inst.material], &inst.variant)?;
        if !variants.insert((inst.material.clone(), v.id.clone())) {
            continue;
        }
        for f in shader.all_files() {
            stats.shader_files += 1;
            stats.shader_bytes += file_len(&generated.join(&inst.material).join(&f.path))?;
        }
    }
    stats.shaders = variants.len();
    for material in libraries.keys() {
        stats.metadata_files += 1;
        stats.metadata_bytes += file_len(&library_meta_path(generated, material))?;
    }
    Ok(stats)
}

/// Every file of the built scene's folder.
fn scene_file_stats(dir: &Path, meta: &SceneMetadata) -> Result<FileStats, String> {
    let mut stats = FileStats {
        shaders: meta.shaders.len(),
        ..FileStats::default()
    };
    let entries = std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for entry in entries {
        let path = entry.map_err(|e| format!("{}: {e}", dir.display()))?.path();
        let len = file_len(&path)?;
        if path.to_string_lossy().ends_with(".scene.json") {
            stats.metadata_files += 1;
            stats.metadata_bytes += len;
        } else {
            stats.shader_files += 1;
            stats.shader_bytes += len;
        }
    }
    Ok(stats)
}

/// Interleaved build times (ms): `build_materials` over the scene's
/// materials vs `build_scene` with a fresh lavapipe tier chooser per run
/// (device creation and `auto` renders included). Also says whether the
/// built scene is byte-identical to `dir`.
fn time_builds(
    input: &SceneInput,
    dir: &Path,
    generated: &Path,
    runs: u32,
) -> Result<(AbTiming, bool), String> {
    let mut current = None;
    let mut medians = interleaved(runs.max(1), 2, |arm, _| {
        let t = Instant::now();
        if arm == 0 {
            weft_compiler::build_materials(
                &input.material_tomls,
                Some(&input.materials_root),
                &weft_compiler::BuildOptions::default(),
                &|_, _, _| {},
            )
            .map_err(|(db, d)| d.render_plain(&db))?;
        } else {
            let chooser = crate::auto_tier::LavapipeTierChooser::new(None)?
                .with_reports_dir(generated.join("reports"));
            let options = weft_compiler::SceneBuildOptions {
                tier_chooser: Some(&chooser),
                ..Default::default()
            };
            let out = weft_compiler::build_scene(&input.manifest, &options)
                .map_err(|(db, d)| d.render_plain(&db))?;
            if current.is_none() {
                current = Some(same_files(dir, &out.files)?);
            }
        }
        Ok(vec![t.elapsed().as_secs_f64() * 1e3])
    })?;
    let scene = medians.pop().expect("two arms");
    let generic = medians.pop().expect("two arms");
    Ok((
        AbTiming {
            generic,
            specialised: scene,
        },
        current.unwrap_or(false),
    ))
}

/// Whether `dir` holds exactly `files` (keyed `<scene>/<file>`).
fn same_files(dir: &Path, files: &BTreeMap<String, Vec<u8>>) -> Result<bool, String> {
    let on_disk = std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .count();
    if on_disk != files.len() {
        return Ok(false);
    }
    Ok(files.iter().all(|(name, bytes)| {
        let file = name.rsplit('/').next().unwrap_or(name);
        std::fs::read(dir.join(file)).is_ok_and(|b| &b == bytes)
    }))
}

fn round(x: f64, digits: i32) -> f64 {
    let s = 10f64.powi(digits);
    (x * s).round() / s
}

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

#[cfg(test)]
mod tests {
    use super::*;

    fn ab(generic: &[f64], specialised: &[f64]) -> AbTiming {
        AbTiming {
            generic: generic.to_vec(),
            specialised: specialised.to_vec(),
        }
    }

    fn no_error() -> ImageError {
        ImageError {
            flip_mean: 0.0012,
            flip_p99: 0.01,
            rel_rmse: 0.0001,
            pixels: 1000,
        }
    }

    fn instance(name: &str, gpu: Option<AbTiming>) -> InstanceBench {
        InstanceBench {
            name: name.into(),
            material: "satin".into(),
            tier: "reference".into(),
            generic_variant: "reference.normal_map-off".into(),
            shader: "satin.0123456789ab".into(),
            spirv_generic: (1000, 800),
            spirv_specialised: (900, 600),
            uniform_generic: 144,
            uniform_specialised: 16,
            flip: gpu.as_ref().map(|_| no_error()),
            gpu,
        }
    }

    fn report() -> SceneBenchReport {
        let files = |shaders, files| FileStats {
            shaders,
            shader_files: files,
            shader_bytes: 1000 * files as u64,
            metadata_files: 1,
            metadata_bytes: 500,
        };
        SceneBenchReport {
            adapter: "llvmpipe (test)".into(),
            timer: FrameTimer::GpuTimestamp,
            options: SceneBenchOptions::default(),
            profile: "debug".into(),
            lavapipe_threads: Some("1".into()),
            scenes: vec![SceneBench {
                name: "fitting_room".into(),
                inputs_hash: "abc123".into(),
                current: true,
                gpu: ab(&[10.0, 12.0, 11.0], &[6.0, 7.0, 6.5]),
                flip: no_error(),
                empty_pass: Some(vec![0.25, 0.25, 0.25]),
                instances: vec![
                    instance("dress", Some(ab(&[4.0, 4.0], &[3.0, 3.0]))),
                    instance("skin", None),
                ],
                generic_files: files(2, 12),
                scene_files: files(2, 12),
                build: ab(&[300.0, 310.0, 290.0], &[200.0, 220.0, 210.0]),
            }],
            seconds: 12.3,
        }
    }

    #[test]
    fn rounds_alternate_the_arms_and_keep_each_rounds_median() {
        let mut calls = Vec::new();
        let medians = interleaved(3, 2, |arm, round| {
            calls.push((round, arm));
            let base = if arm == 0 { 10.0 } else { 6.0 };
            // An outlier in every call does not move the round's median.
            Ok(vec![
                base + f64::from(round),
                1000.0,
                base + f64::from(round),
            ])
        })
        .unwrap();
        assert_eq!(calls, [(0, 0), (0, 1), (1, 0), (1, 1), (2, 0), (2, 1)]);
        assert_eq!(medians, [vec![10.0, 11.0, 12.0], vec![6.0, 7.0, 8.0]]);
    }

    #[test]
    fn an_arm_without_samples_is_an_error() {
        let e = interleaved(1, 2, |arm, _| Ok(if arm == 1 { vec![] } else { vec![1.0] }));
        assert!(e.unwrap_err().contains("arm 1"));
        let e = interleaved(2, 1, |_, round| {
            if round == 1 {
                Err("lost the device".to_string())
            } else {
                Ok(vec![1.0])
            }
        });
        assert_eq!(e.unwrap_err(), "lost the device");
    }

    #[test]
    fn ab_figures_are_medians_of_round_medians() {
        let t = ab(&[10.0, 12.0, 11.0, 30.0, 9.0], &[6.0, 7.0, 6.5, 20.0, 9.5]);
        let (g, s) = (t.generic_stats(), t.specialised_stats());
        assert_eq!((g.median, s.median), (11.0, 7.0));
        assert_eq!((g.min, g.max), (9.0, 30.0));
        // (p90 − p10) / median, nearest rank over 5 values: indices 4 and 0.
        assert!((g.spread - (30.0 - 9.0) / 11.0).abs() < 1e-12);
        assert!((t.ratio() - 7.0 / 11.0).abs() < 1e-12);
        assert!((t.saving_pct() - (1.0 - 7.0 / 11.0) * 100.0).abs() < 1e-9);
        // The last round was slower specialised.
        assert_eq!(t.rounds_faster(), 4);
        let savings = t.round_savings_pct();
        assert_eq!(savings.len(), 5);
        assert!((savings[0] - 40.0).abs() < 1e-9 && savings[4] < 0.0);
    }

    #[test]
    fn spirv_reduction_is_per_fragment_instruction() {
        let i = instance("dress", None);
        assert!((i.spirv_reduction_pct() - 25.0).abs() < 1e-12);
        assert_eq!(reduction_pct(0, 10), 0.0);
        let r = report();
        assert!((r.scenes[0].spirv_mean_reduction_pct() - 25.0).abs() < 1e-12);
    }

    #[test]
    fn the_markdown_report_shows_every_figure() {
        let md = markdown_report(&report(), "cargo xtask bench scene --write", "");
        assert!(md.starts_with("# Scene-specialised vs generic shaders\n"));
        assert!(md.contains("Generated by `cargo xtask bench scene --write`"));
        assert!(md.contains("Adapter: llvmpipe (test), LP_NUM_THREADS=1."));
        assert!(md.contains(
            "| fitting_room | 11.000 | 6.500 | 0.591 | 40.9% | 18.2% / 15.4% | 3/3, median 40.9% (40.0…41.7%) | 0.001200 | yes | 25.0% | 2 → 2 | 13 → 13 | 12500 → 12500 | 300 | 210 |"
        ), "{md}");
        assert!(md.contains("inputs_hash` abc123 (generated/ matches a fresh build)"));
        assert!(md.contains("An empty pass (the clear alone) takes 0.250 ms"));
        assert!(md.contains(
            "| dress | satin | reference | `reference.normal_map-off` → `satin.0123456789ab` | 4.000 | 3.000 | 25.0% | 3.750 → 2.750 | 2/2, median 25.0% (25.0…25.0%) | 0.001200 | 800 → 600 (1000 → 900) | 25.0% | 144 → 16 |"
        ), "{md}");
        assert!(md.contains("| skin | satin | reference |"));
        assert!(md.contains("| — | — | — | — | — | — |"));
        assert!(md.contains("Build: generic 300 ms (min 290, max 310), scene 210 ms"));
        assert!(md.ends_with("Total run time: 12.3 s.\n"));
    }

    #[test]
    fn a_stale_scene_and_a_picture_change_are_flagged() {
        let mut r = report();
        r.scenes[0].current = false;
        r.scenes[0].flip.flip_mean = 0.02;
        let md = markdown_report(&r, "c", "");
        assert!(md.contains("rerun `cargo xtask regenerate`"));
        assert!(md.contains("| 0.020000 | **no** |"));
        let json = json_report(&r, "c");
        assert_eq!(json["scenes"][0]["flip_within_bound"], false);
        assert_eq!(json["scenes"][0]["generated_current"], false);
    }

    #[test]
    fn the_json_report_is_machine_readable() {
        let j = json_report(&report(), "cargo xtask bench scene --write");
        assert_eq!(j["command"], "cargo xtask bench scene --write");
        assert_eq!(j["timer"], "gpu-timestamp");
        assert_eq!(j["lavapipe_threads"], "1");
        assert_eq!(j["options"]["width"], 640);
        assert_eq!(j["options"]["format"], "Rgba16Float");
        let s = &j["scenes"][0];
        assert_eq!(s["inputs_hash"], "abc123");
        assert_eq!(s["gpu"]["generic_ms"], 11.0);
        assert_eq!(s["gpu"]["specialised_ms"], 6.5);
        assert_eq!(s["gpu"]["saving_pct"], 40.91);
        assert_eq!(s["gpu"]["rounds_specialised_faster"], 3);
        assert_eq!(s["empty_pass_ms"], 0.25);
        assert_eq!(s["files"]["generic"]["bytes"], 12500);
        assert_eq!(s["build_ms"]["scene"], 210.0);
        let dress = &s["instances"][0];
        assert_eq!(dress["spirv"]["specialised_fragment_instructions"], 600);
        assert_eq!(dress["uniform_bytes"]["generic"], 144);
        assert_eq!(dress["gpu_alone"]["saving_pct"], 25.0);
        assert!(s["instances"][1]["gpu_alone"].is_null());
    }

    #[test]
    fn reports_are_written_side_by_side() {
        let dir = tempfile::tempdir().unwrap();
        let written = write_reports(dir.path(), &report(), "c", "").unwrap();
        assert_eq!(
            written,
            [dir.path().join("scenes.md"), dir.path().join("scenes.json")]
        );
        let json: serde_json::Value =
            serde_json::from_slice(&std::fs::read(&written[1]).unwrap()).unwrap();
        assert_eq!(json["scenes"][0]["scene"], "fitting_room");
    }

    #[test]
    fn a_scene_input_is_named_after_its_manifest() {
        let input = SceneInput {
            manifest: PathBuf::from("scenes/fitting_room.scene.toml"),
            materials_root: PathBuf::from("materials"),
            material_tomls: Vec::new(),
        };
        assert_eq!(input.name(), "fitting_room");
    }
}
