//! Timing: generic and specialised draws in interleaved rounds (the whole
//! scene, then every instance alone and an empty pass), and the two builds.

use super::static_figures::{
    generic_file_stats, instance_figures, load_libraries, scene_file_stats,
};
use super::{AbTiming, InstanceBench, SceneBench, SceneBenchOptions, SceneInput};
use crate::shading::{image_error, quantile};
use std::collections::BTreeMap;
use std::path::Path;
use std::time::Instant;
use weft_render::{
    FrameTimer, HdrImage, RenderOptions, Renderer, SceneFile, SceneShaders, TimingOptions,
};

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

/// One run's renderer, folders and options: measures a scene at a time.
pub(super) struct Bench<'a> {
    pub(super) renderer: &'a mut Renderer,
    pub(super) generated: &'a Path,
    pub(super) render: &'a RenderOptions,
    pub(super) options: &'a SceneBenchOptions,
    pub(super) timer: &'a mut FrameTimer,
}

impl Bench<'_> {
    pub(super) fn scene(
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
            let chooser = weft_auto::LavapipeTierChooser::new(None)?
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

/// Whether `dir` holds exactly `files` (keyed `<scene>/<path>`, where a
/// path may name a subfolder: a ramp's `face/…`, a glTF scene's `meshes/…`).
pub(super) fn same_files(dir: &Path, files: &BTreeMap<String, Vec<u8>>) -> Result<bool, String> {
    if count_files(dir)? != files.len() {
        return Ok(false);
    }
    Ok(files.iter().all(|(name, bytes)| {
        let path = name.split_once('/').map_or(name.as_str(), |(_, p)| p);
        std::fs::read(dir.join(path)).is_ok_and(|b| &b == bytes)
    }))
}

/// The files under `dir`, its subfolders' included.
fn count_files(dir: &Path) -> Result<usize, String> {
    let mut n = 0;
    for entry in std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))? {
        let path = entry.map_err(|e| format!("{}: {e}", dir.display()))?.path();
        n += if path.is_dir() {
            count_files(&path)?
        } else {
            1
        };
    }
    Ok(n)
}
