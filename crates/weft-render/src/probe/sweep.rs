//! The sweep: every canonical variant × constant-keyword combination ×
//! parameter setting drawn at every case, bad outputs counted and recorded.

use super::cases::cos_label;
use super::{BadKind, Probe, classify, classify_half, parameter_settings};
use crate::environment::{EnvironmentMaps, Luts, SkyParams};
use crate::error::{Error, Result};
use crate::gpu::Gpu;
use crate::material::Material;
use crate::renderer::{RenderOptions, Renderer};
use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};
use weft_meta::{KeywordMode, MaterialMetadata};

/// Where a bad output happened.
#[derive(Clone, Debug, PartialEq)]
pub struct Failure {
    pub material: String,
    /// Variant id, plus `+KEYWORD=value` for constant-mode keywords.
    pub variant: String,
    /// The parameter setting's label.
    pub setting: String,
    /// The geometric case's name (with its N·V and N·L).
    pub case: String,
    pub n_dot_v: f32,
    pub n_dot_l: f32,
    /// The first bad pixel of the tile (RGBA) and its kind.
    pub value: [f32; 4],
    pub kind: BadKind,
    /// Bad channels in the tile.
    pub count: usize,
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} {} [{}] at `{}` (N.V={}, N.L={}): {} ({} channel{}), rgba = {:?}",
            self.material,
            self.variant,
            self.setting,
            self.case,
            cos_label(self.n_dot_v),
            cos_label(self.n_dot_l),
            self.kind,
            self.count,
            if self.count == 1 { "" } else { "s" },
            self.value
        )
    }
}

/// Counts of one material's sweep.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MaterialSweep {
    pub material: String,
    /// Canonical variants swept (times constant-keyword combinations).
    pub variants: usize,
    /// Variants skipped because they alias a swept one (identical WGSL).
    pub aliases: usize,
    /// Renders: (variant, parameter setting) pairs.
    pub renders: usize,
    /// Tiles drawn: renders x geometric cases.
    pub draws: usize,
    /// Channels checked.
    pub outputs: u64,
    /// Bad channels.
    pub bad: u64,
    /// Renders of half-precision variants compared with their f32 fallback.
    pub half_compared: usize,
    /// Renders of half-precision variants that could not be compared: the
    /// device has no `shader-f16`, so only the f32 files were drawn.
    pub half_unchecked: usize,
}

/// The result of a sweep over one or more materials.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SweepReport {
    pub cases: usize,
    pub materials: Vec<MaterialSweep>,
    /// One entry per (variant, setting, case) with bad outputs, at most
    /// [`SweepReport::MAX_RECORDED`].
    pub failures: Vec<Failure>,
}

impl SweepReport {
    pub const MAX_RECORDED: usize = 100_000;

    pub fn bad(&self) -> u64 {
        self.materials.iter().map(|m| m.bad).sum()
    }

    pub fn outputs(&self) -> u64 {
        self.materials.iter().map(|m| m.outputs).sum()
    }

    pub fn renders(&self) -> usize {
        self.materials.iter().map(|m| m.renders).sum()
    }

    pub fn draws(&self) -> usize {
        self.materials.iter().map(|m| m.draws).sum()
    }

    /// One line of totals.
    pub fn summary(&self) -> String {
        let compared: usize = self.materials.iter().map(|m| m.half_compared).sum();
        let unchecked: usize = self.materials.iter().map(|m| m.half_unchecked).sum();
        let half = match (compared, unchecked) {
            (0, 0) => String::new(),
            (c, 0) => format!("; {c} half-precision renders compared with their f32 fallback"),
            (c, u) => format!(
                "; {c} half-precision renders compared with their f32 fallback, {u} NOT compared (the device has no shader-f16)"
            ),
        };
        format!(
            "{} material(s), {} variant(s) ({} aliases skipped), {} parameter settings x {} geometric cases = {} draws, {} outputs checked: {} bad{half}",
            self.materials.len(),
            self.materials.iter().map(|m| m.variants).sum::<usize>(),
            self.materials.iter().map(|m| m.aliases).sum::<usize>(),
            self.renders(),
            self.cases,
            self.draws(),
            self.outputs(),
            self.bad()
        )
    }
}

/// Makes lavapipe draw on the calling thread (`LP_NUM_THREADS=0`) unless
/// the user set `LP_NUM_THREADS`; other drivers ignore it. A sweep draws
/// 2 x 2-pixel tiles, where llvmpipe's rasteriser threads spend more time at
/// their barriers than drawing: laser's sweep took 21.7 s with two threads
/// and 13.6 s with none (same pixels), the stability tests 374 s and 204 s.
///
/// # Safety
/// Sets an environment variable: call it before any Vulkan device exists
/// and while no other thread can be reading the environment (first in
/// `main`, or under a lock every other such thread waits on).
pub unsafe fn draw_sweeps_on_the_calling_thread() {
    if std::env::var_os("LP_NUM_THREADS").is_none() {
        // SAFETY: the caller's contract above.
        unsafe { std::env::set_var("LP_NUM_THREADS", "0") };
    }
}

/// A renderer for sweeps: a small procedural sky (16² faces; the sweep
/// checks finiteness, not appearance) and the LUTs of a generated folder.
pub fn sweep_renderer(luts: &Luts) -> Result<Renderer> {
    let sky = SkyParams {
        size: 16,
        samples: 16,
        ..SkyParams::default()
    };
    Renderer::new(Gpu::new()?, &EnvironmentMaps::sky(&sky), luts)
}

/// Every `<dir>/<name>/<name>.meta.json` of a generated folder, sorted.
pub fn generated_materials(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    let entries = std::fs::read_dir(dir).map_err(|e| Error::Io {
        path: dir.to_path_buf(),
        source: e,
    })?;
    for entry in entries.flatten() {
        let path = entry.path();
        let Some(name) = path.file_name().map(|n| n.to_string_lossy().into_owned()) else {
            continue;
        };
        let meta = path.join(format!("{name}.meta.json"));
        if meta.is_file() {
            out.push(meta);
        }
    }
    out.sort();
    Ok(out)
}

/// Every combination of the constant-mode keywords' values.
fn constant_combinations(meta: &MaterialMetadata) -> Vec<Vec<(String, String)>> {
    let mut combos: Vec<Vec<(String, String)>> = vec![Vec::new()];
    for k in meta
        .keywords
        .iter()
        .filter(|k| k.mode == KeywordMode::Constant)
    {
        combos = combos
            .into_iter()
            .flat_map(|c| {
                k.values.iter().map(move |v| {
                    let mut c = c.clone();
                    c.push((k.name.clone(), v.clone()));
                    c
                })
            })
            .collect();
    }
    combos
}

/// Sweeps one material (`<name>.meta.json`): every canonical variant x every
/// constant-keyword combination x [`parameter_settings`], each rendered at
/// every case of `probe`. `progress(done, total)` is called after each render.
pub fn sweep_material(
    renderer: &mut Renderer,
    probe: &Probe,
    meta_path: &Path,
    report: &mut SweepReport,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<()> {
    let mut material = Material::load(meta_path)?;
    let meta = material.metadata().clone();
    let options = probe.render_options();
    report.cases = probe.cases.len();
    let mut summary = MaterialSweep {
        material: meta.name.clone(),
        ..MaterialSweep::default()
    };
    let mut jobs = Vec::new();
    for v in &meta.variants {
        if v.alias_of.is_some() {
            summary.aliases += 1;
            continue;
        }
        let Some(shader) = &v.shader else { continue };
        let settings = parameter_settings(&meta, shader);
        let half = !shader.f16_files.is_empty();
        for combo in constant_combinations(&meta) {
            jobs.push((v.id.clone(), combo, settings.clone(), half));
        }
    }
    summary.variants = jobs.len();
    let total: usize = jobs.iter().map(|j| j.2.len()).sum();
    let has_f16 = renderer
        .gpu()
        .device
        .features()
        .contains(wgpu::Features::SHADER_F16);
    for (id, combo, settings, half) in jobs {
        let variant_label = std::iter::once(id.clone())
            .chain(combo.iter().map(|(k, v)| format!("+{k}={v}")))
            .collect::<String>();
        for setting in settings {
            material.reset()?;
            material.select_variant(&id)?;
            for (k, v) in &combo {
                material.set_keyword(k, v)?;
            }
            for (name, value) in &setting.values {
                material
                    .set(name, value.clone())
                    .map_err(|e| Error::InvalidValue {
                        name: name.clone(),
                        message: format!("probe setting `{}`: {e}", setting.label),
                    })?;
            }
            let prepared = renderer.prepare(&material, &options)?;
            let tiles = probe.evaluate(renderer, &prepared)?;
            // A half-precision variant is also drawn in f32 (its fallback):
            // where they disagree by an overflow or a visible underflow, f16
            // changed the picture.
            let fallback_tiles = match half && has_f16 {
                true => {
                    let options = RenderOptions {
                        f32_fallback: true,
                        ..options
                    };
                    let prepared = renderer.prepare(&material, &options)?;
                    summary.half_compared += 1;
                    Some(probe.evaluate(renderer, &prepared)?)
                }
                false => {
                    summary.half_unchecked += half as usize;
                    None
                }
            };
            summary.renders += 1;
            summary.draws += tiles.len();
            for (i, (case, pixels)) in probe.cases.iter().zip(&tiles).enumerate() {
                let mut first: Option<([f32; 4], BadKind)> = None;
                let mut count = 0;
                let full = fallback_tiles.as_ref().map(|t| &t[i]);
                for (j, px) in pixels.iter().enumerate() {
                    summary.outputs += 4;
                    for (c, &x) in px.iter().enumerate() {
                        let kind =
                            classify(x).or_else(|| full.and_then(|f| classify_half(x, f[j][c])));
                        if let Some(kind) = kind {
                            count += 1;
                            first.get_or_insert((*px, kind));
                        }
                    }
                }
                if let Some((value, kind)) = first {
                    summary.bad += count as u64;
                    if report.failures.len() < SweepReport::MAX_RECORDED {
                        report.failures.push(Failure {
                            material: meta.name.clone(),
                            variant: variant_label.clone(),
                            setting: setting.label.clone(),
                            case: case.name.clone(),
                            n_dot_v: case.n_dot_v(),
                            n_dot_l: case.n_dot_l(),
                            value,
                            kind,
                            count,
                        });
                    }
                }
            }
            progress(summary.renders, total);
        }
        // This job's pipelines are not drawn again: keep memory flat.
        renderer.release_pipelines();
    }
    report.materials.push(summary);
    Ok(())
}

/// Failures grouped by geometric case: case -> (count of (variant, setting)
/// pairs, kinds seen).
pub fn failures_by_case(failures: &[Failure]) -> BTreeMap<String, (usize, Vec<BadKind>)> {
    let mut out: BTreeMap<String, (usize, Vec<BadKind>)> = BTreeMap::new();
    for f in failures {
        let e = out.entry(f.case.clone()).or_default();
        e.0 += 1;
        if !e.1.contains(&f.kind) {
            e.1.push(f.kind);
        }
    }
    out
}
