//! The shell-count bench: for a material whose pass takes its instance count
//! from an `int` parameter (fur or fuzz shells), the error and cost of
//! drawing it with fewer instances than a reference count, at several
//! screen sizes.
//!
//! Each count in [`ShellOptions::counts`] is drawn at the material's default
//! tier and values and compared with [`ShellOptions::reference`] instances
//! (FLIP mean and 99th percentile over object pixels, as the shading bench);
//! each frame is timed like the shading bench. The recommended count for a
//! screen size is the smallest measured count whose FLIP mean is at most
//! [`ShellOptions::flip_bar`].
//!
//! On the sphere, each count's error is also split by the silhouette band
//! ([`crate::silhouette`]), and for fur, with [`ShellOptions::fins`], fins
//! are drawn with some counts and set against more shells at the same cost
//! ([`crate::fins`]).
//!
//! Written by `cargo xtask bench shading --write` and `cargo xtask
//! regenerate --reports` to `generated/reports/<name>.shells.md`, and into
//! the material README between `<!-- weft:shells:begin -->` and
//! `<!-- weft:shells:end -->` (the counts) and `<!-- weft:fins:begin -->`
//! and `<!-- weft:fins:end -->` (silhouette and fins).

use crate::fins::{FinOpacity, FinRule};
use crate::shading::{ImageError, image_error, quantile};
use crate::silhouette::{SilhouetteSplit, sphere_band, split};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use weft_meta::{InstanceCount, MaterialMetadata};
use weft_render::{
    Background, EnvironmentMaps, FrameTimes, Luts, Material, PreparedMaterial, PreviewOptions,
    RenderOptions, Renderer, Scene, SceneKind, TimingOptions,
};

/// What the shell bench draws.
#[derive(Clone, Debug, PartialEq)]
pub struct ShellOptions {
    /// Square image sizes in pixels (the sphere spans about 0.85 of it).
    pub sizes: Vec<u32>,
    /// Counts compared with the reference.
    pub counts: Vec<u32>,
    /// The reference count (clamped to the parameter's range).
    pub reference: u32,
    pub scene: SceneKind,
    /// Timed frames per count and size (the median is reported).
    pub frames: u32,
    /// Untimed frames before them.
    pub warmup: u32,
    pub force_cpu_timer: bool,
    /// The FLIP mean a recommended count must not exceed.
    pub flip_bar: f64,
    /// The FLIP 99th percentile a recommended count must not exceed (the
    /// worst pixels: gaps between shells at the rim).
    pub flip_p99_bar: f64,
    /// On the sphere, the silhouette band's bound on |N·V| for the error
    /// split ([`crate::silhouette`]) and the fins.
    pub silhouette_n_dot_v: f64,
    /// The fin experiment ([`crate::fins`], fur on the sphere only): the
    /// materials folder to build `fur_fins` from, and the shell counts to
    /// draw with fins, each with every fin opacity rule. None: not run.
    pub fins: Option<PathBuf>,
    pub fin_counts: Vec<u32>,
    pub fin_rules: Vec<FinRule>,
}

impl Default for ShellOptions {
    fn default() -> Self {
        ShellOptions {
            sizes: vec![64, 128, 256, 512],
            counts: vec![4, 8, 16, 32, 64],
            reference: 128,
            scene: SceneKind::Sphere,
            frames: 5,
            warmup: 1,
            force_cpu_timer: false,
            flip_bar: 0.03,
            flip_p99_bar: 0.1,
            silhouette_n_dot_v: 0.3,
            fins: None,
            fin_counts: vec![4, 8, 16],
            // Lengyel et al.'s scheme (shells fade out where fins fade in),
            // with a fin as opaque as one shell and as the strip it stands
            // for; fins over unfaded shells measured worse (README).
            fin_rules: [FinOpacity::Slabs(1.0), FinOpacity::Strip]
                .map(|opacity| FinRule {
                    opacity,
                    fade_shells: true,
                })
                .to_vec(),
        }
    }
}

/// One count at one size.
#[derive(Clone, Debug, PartialEq)]
pub struct ShellCell {
    pub size: u32,
    pub count: u32,
    /// Median frame time, ms.
    pub ms: f64,
    /// Error against the reference count at the same size.
    pub error: ImageError,
    /// That error split by the silhouette band (on the sphere).
    pub silhouette: Option<SilhouetteSplit>,
}

/// The bench of one material.
#[derive(Clone, Debug)]
pub struct ShellReport {
    pub material: String,
    pub inputs_hash: String,
    /// The int parameter that sets the instance count.
    pub parameter: String,
    pub tier: String,
    pub reference: u32,
    pub adapter: String,
    pub timer: String,
    pub options: ShellOptions,
    /// Per size: the reference's median frame time, ms.
    pub reference_ms: Vec<(u32, f64)>,
    pub cells: Vec<ShellCell>,
    /// The fin experiment, when run.
    pub fins: Vec<FinCell>,
}

/// N shells with fins against more shells at the same cost, at one size.
#[derive(Clone, Debug, PartialEq)]
pub struct FinCell {
    /// N shells without fins, timed in the same run, ms.
    pub plain_ms: f64,
    /// N shells plus fins (`ms`: both, in the shared mesh).
    pub with_fins: ShellCell,
    /// The fins' own time: `with_fins.ms` less the same draw with the fins
    /// hidden ([`FinOpacity::Hidden`]), ms.
    pub fin_ms: f64,
    /// How many fins were drawn.
    pub fins: usize,
    pub rule: FinRule,
    /// The shell count the fins' time would buy (N × (plain + fins' own
    /// time) / plain, rounded up), drawn without fins.
    pub same_cost: ShellCell,
}

/// The int parameter a pass of `meta` takes its instance count from.
pub fn instance_parameter(meta: &MaterialMetadata) -> Option<&str> {
    meta.passes.iter().find_map(|p| match &p.instances {
        InstanceCount::Parameter(name) => Some(name.as_str()),
        InstanceCount::Fixed(_) => None,
    })
}

/// Measures every material under `generated` that draws instances from a
/// parameter (only those in `names`, when not empty).
pub fn run(
    generated: &Path,
    names: &[String],
    options: &ShellOptions,
    log: &mut dyn FnMut(&str),
) -> Result<Vec<ShellReport>, String> {
    let selected: Vec<_> = crate::materials(generated)?
        .into_iter()
        .filter(|(_, m)| names.is_empty() || names.contains(&m.name))
        .filter(|(_, m)| instance_parameter(m).is_some())
        .collect();
    if selected.is_empty() {
        return Ok(Vec::new());
    }
    let e = |e: weft_render::Error| e.to_string();
    let gpu = weft_render::Gpu::new().map_err(e)?;
    let adapter = gpu.describe();
    let luts = Luts::load_dir(generated).map_err(e)?;
    let env = EnvironmentMaps::sky(&PreviewOptions::default().sky_params());
    let mut renderer = Renderer::new(gpu, &env, &luts).map_err(e)?;
    let mut reports = Vec::new();
    for (meta_path, meta) in &selected {
        let mut subject = Subject::load(meta_path, meta, options)?;
        let mut report = ShellReport {
            material: meta.name.clone(),
            inputs_hash: meta.inputs_hash.clone(),
            parameter: subject.parameter.clone(),
            tier: subject.material.tier().to_string(),
            reference: subject.reference,
            adapter: adapter.clone(),
            timer: String::new(),
            options: options.clone(),
            reference_ms: Vec::new(),
            cells: Vec::new(),
            fins: Vec::new(),
        };
        // The fin experiment's materials, one per opacity rule (fur on the
        // sphere only).
        let fins_dir = tempfile::tempdir().map_err(|e| e.to_string())?;
        subject.fins = fin_materials(options, meta, fins_dir.path())?;
        for &size in &options.sizes {
            measure_size(&mut renderer, &mut subject, size, options, &mut report, log)?;
        }
        reports.push(report);
    }
    Ok(reports)
}

/// One material under the bench.
struct Subject<'a> {
    meta: &'a MaterialMetadata,
    /// The int parameter that sets the instance count.
    parameter: String,
    /// The reference count and the counts compared with it (both clamped
    /// to the parameter's range; the counts below the reference).
    reference: u32,
    counts: Vec<u32>,
    material: Material,
    /// The fin experiment's materials: hidden fins first, then one per rule.
    fins: Vec<(FinRule, Material)>,
}

impl<'a> Subject<'a> {
    fn load(
        meta_path: &Path,
        meta: &'a MaterialMetadata,
        options: &ShellOptions,
    ) -> Result<Subject<'a>, String> {
        let parameter = instance_parameter(meta).expect("filtered").to_string();
        let what = |err: weft_render::Error| format!("{}: {err}", meta.name);
        let range = meta
            .parameters
            .iter()
            .find(|p| p.name == parameter)
            .and_then(|p| p.range)
            .unwrap_or([1.0, 4096.0]);
        let clamp = |n: u32| (f64::from(n)).clamp(range[0], range[1]) as u32;
        let reference = clamp(options.reference);
        let mut counts: Vec<u32> = options
            .counts
            .iter()
            .map(|&n| clamp(n))
            .filter(|&n| n < reference)
            .collect();
        counts.dedup();
        let material = Material::load(meta_path).map_err(what)?;
        Ok(Subject {
            meta,
            parameter,
            reference,
            counts,
            material,
            fins: Vec::new(),
        })
    }
}

/// The fin experiment's materials built into `dir` (fur on the sphere
/// only, with [`ShellOptions::fins`]): first the hidden fins, the cost of
/// the shared mesh alone, then one per rule.
fn fin_materials(
    options: &ShellOptions,
    meta: &MaterialMetadata,
    dir: &Path,
) -> Result<Vec<(FinRule, Material)>, String> {
    let e = |e: weft_render::Error| e.to_string();
    let mut fins_materials = Vec::new();
    if let Some(materials) = &options.fins
        && meta.name == "fur"
        && options.scene == SceneKind::Sphere
    {
        // First the hidden fins: the cost of the shared mesh alone.
        let hidden = FinRule {
            opacity: FinOpacity::Hidden,
            fade_shells: false,
        };
        let rules = std::iter::once(&hidden).chain(&options.fin_rules);
        for (i, &rule) in rules.enumerate() {
            let work = dir.join(i.to_string());
            let path = crate::fins::build(materials, &work, rule)?;
            fins_materials.push((rule, Material::load(path).map_err(e)?));
        }
    }
    Ok(fins_materials)
}

/// What every frame at one size is drawn with.
struct Frames<'a> {
    renderer: &'a mut Renderer,
    render_options: RenderOptions,
    timing: TimingOptions,
    parameter: &'a str,
    material_name: &'a str,
}

impl Frames<'_> {
    /// `n` instances of `material` drawn and timed.
    fn draw(
        &mut self,
        n: u32,
        material: &mut Material,
        prepared: &mut PreparedMaterial,
        scene: &Scene,
    ) -> Result<FrameTimes, String> {
        material
            .set(self.parameter, i64::from(n))
            .and_then(|()| self.renderer.update(prepared, material))
            .and_then(|()| {
                self.renderer
                    .time_frames(prepared, scene, &self.render_options, &self.timing)
            })
            .map_err(|err| format!("{}: {err}", self.material_name))
    }
}

/// The reference count's frame at one size, which every cell is held to.
struct Reference<'a> {
    size: u32,
    times: FrameTimes,
    band: Option<&'a [bool]>,
}

impl Reference<'_> {
    /// `count` instances drawn in `t`, against the reference.
    fn cell(&self, count: u32, t: &FrameTimes) -> ShellCell {
        ShellCell {
            size: self.size,
            count,
            ms: quantile(&t.ms, 0.5),
            error: image_error(&self.times.image, &t.image),
            silhouette: self.band.map(|b| split(&self.times.image, &t.image, b)),
        }
    }
}

/// One size: the reference count, every smaller count, and the fin
/// experiment (N shells with fins against the shell count of the same
/// cost) when its materials were built.
fn measure_size(
    renderer: &mut Renderer,
    subject: &mut Subject<'_>,
    size: u32,
    options: &ShellOptions,
    report: &mut ShellReport,
    log: &mut dyn FnMut(&str),
) -> Result<(), String> {
    let meta = subject.meta;
    let e = |e: weft_render::Error| e.to_string();
    let what = |err: weft_render::Error| format!("{}: {err}", meta.name);
    let preview = PreviewOptions {
        scene: options.scene,
        width: size,
        height: size,
        ..PreviewOptions::default()
    };
    let scene = preview.scene();
    let band = (options.scene == SceneKind::Sphere)
        .then(|| sphere_band(&scene, size, size, options.silhouette_n_dot_v));
    let render_options = RenderOptions {
        background: Background::Color([0.0; 4]),
        ..preview.render_options()
    };
    let mut prepared = renderer
        .prepare(&subject.material, &render_options)
        .map_err(what)?;
    let mut fins_prepared = subject
        .fins
        .iter()
        .map(|(_, m)| renderer.prepare(m, &render_options).map_err(e))
        .collect::<Result<Vec<_>, _>>()?;
    let (fin_scene, fins) = crate::fins::scene_with_fins(&scene, options.silhouette_n_dot_v as f32);
    let timing = TimingOptions {
        warmup: options.warmup,
        frames: options.frames.max(1),
        force_cpu_timer: options.force_cpu_timer,
    };
    let mut frames = Frames {
        renderer,
        render_options,
        timing,
        parameter: &subject.parameter,
        material_name: &meta.name,
    };
    let material = &mut subject.material;
    let reference = subject.reference;
    let r = frames.draw(reference, material, &mut prepared, &scene)?;
    report.timer = r.timer.name().into();
    report.reference_ms.push((size, quantile(&r.ms, 0.5)));
    log(&format!(
        "{} {size}px: {reference} shells {:.2} ms",
        meta.name,
        quantile(&r.ms, 0.5)
    ));
    let measure = Reference {
        size,
        times: r,
        band: band.as_deref(),
    };
    for &count in &subject.counts {
        let cell = measure.cell(count, &frames.draw(count, material, &mut prepared, &scene)?);
        log(&format!(
            "{} {size}px: {count} shells {:.2} ms, FLIP mean {:.4}",
            meta.name, cell.ms, cell.error.flip_mean
        ));
        report.cells.push(cell);
    }
    if let (Some(((_, hidden), others)), Some((hidden_prepared, others_prepared))) = (
        subject.fins.split_first_mut(),
        fins_prepared.split_first_mut(),
    ) {
        for &count in options.fin_counts.iter().filter(|&&n| n < reference) {
            let plain = measure.cell(count, &frames.draw(count, material, &mut prepared, &scene)?);
            let shared = frames.draw(count, hidden, hidden_prepared, &fin_scene)?;
            let shared_ms = quantile(&shared.ms, 0.5);
            for ((rule, fins_material), fins_prepared) in
                others.iter_mut().zip(others_prepared.iter_mut())
            {
                let t = frames.draw(count, fins_material, fins_prepared, &fin_scene)?;
                let with_fins = measure.cell(count, &t);
                // The fins' own time: without the shared mesh's
                // overhead (body passes skipping fin vertices), an
                // engine with a fin mesh of its own would not pay.
                let fin_ms = (with_fins.ms - shared_ms).max(0.0);
                let same =
                    (f64::from(count) * (plain.ms + fin_ms) / plain.ms.max(1e-6)).ceil() as u32;
                let same = same.clamp(count + 1, reference - 1);
                let same_cost =
                    measure.cell(same, &frames.draw(same, material, &mut prepared, &scene)?);
                log(&format!(
                    "{} {size}px: {count} shells + {fins} fins ({}) {:.2} ms (fins {fin_ms:.2}), FLIP mean {:.4}; {same} shells {:.2} ms, FLIP mean {:.4}",
                    meta.name,
                    rule.describe(),
                    with_fins.ms,
                    with_fins.error.flip_mean,
                    same_cost.ms,
                    same_cost.error.flip_mean
                ));
                report.fins.push(FinCell {
                    plain_ms: plain.ms,
                    with_fins,
                    fin_ms,
                    fins,
                    rule: *rule,
                    same_cost,
                });
            }
        }
        for (_, m) in subject.fins.iter_mut() {
            m.reset().map_err(e)?;
        }
    }
    material.reset().map_err(what)?;
    Ok(())
}

/// The smallest measured count at `size` whose FLIP mean and 99th
/// percentile are within their bars; None when none is.
pub fn recommended(report: &ShellReport, size: u32) -> Option<u32> {
    report
        .cells
        .iter()
        .filter(|c| {
            c.size == size
                && c.error.flip_mean <= report.options.flip_bar
                && c.error.flip_p99 <= report.options.flip_p99_bar
        })
        .map(|c| c.count)
        .min()
}

/// The measured table (markdown): one row per size, FLIP mean and cost per
/// count, the recommended count.
pub fn markdown_table(report: &ShellReport) -> String {
    let mut counts: Vec<u32> = report.cells.iter().map(|c| c.count).collect();
    counts.sort_unstable();
    counts.dedup();
    let mut md = String::new();
    let _ = write!(md, "| image (sphere ≈ 0.85 of it) |");
    for n in &counts {
        let _ = write!(md, " {n} shells |");
    }
    let _ = writeln!(md, " {} (reference) | recommended |", report.reference);
    let _ = write!(md, "|---|");
    for _ in &counts {
        let _ = write!(md, "---|");
    }
    let _ = writeln!(md, "---|---|");
    for &size in &report.options.sizes {
        let _ = write!(md, "| {size}² px |");
        for n in &counts {
            match report
                .cells
                .iter()
                .find(|c| c.size == size && c.count == *n)
            {
                Some(c) => {
                    let _ = write!(
                        md,
                        " FLIP {:.4} (p99 {:.3}), {:.2} ms |",
                        c.error.flip_mean, c.error.flip_p99, c.ms
                    );
                }
                None => {
                    let _ = write!(md, " – |");
                }
            }
        }
        let ms = report
            .reference_ms
            .iter()
            .find(|(s, _)| *s == size)
            .map_or(f64::NAN, |(_, ms)| *ms);
        let rec = recommended(report, size).map_or_else(
            || format!("> {}", counts.last().copied().unwrap_or(0)),
            |n| n.to_string(),
        );
        let _ = writeln!(md, " {ms:.2} ms | {rec} |");
    }
    let _ = writeln!(
        md,
        "\nMeasured on {} ({}): `{}` at its defaults, tier `{}`, `{}` set to each count, on the {}; FLIP mean (and 99th percentile) over object pixels against {} shells at the same size; median frame time of {} frames. Recommended: the fewest shells with FLIP mean ≤ {} and FLIP p99 ≤ {}. Inputs hash {}.",
        report.adapter,
        report.timer,
        report.material,
        report.tier,
        report.parameter,
        report.options.scene.name(),
        report.reference,
        report.options.frames.max(1),
        report.options.flip_bar,
        report.options.flip_p99_bar,
        report.inputs_hash
    );
    md
}

/// Where the error lies (markdown; empty when the split was not measured):
/// per size and count, the silhouette band's share of the summed FLIP, the
/// band's and the interior's FLIP mean, and the FLIP mean left with a
/// perfect silhouette (the band copied from the reference).
pub fn silhouette_table(report: &ShellReport) -> String {
    if report.cells.iter().all(|c| c.silhouette.is_none()) {
        return String::new();
    }
    let mut counts: Vec<u32> = report.cells.iter().map(|c| c.count).collect();
    counts.sort_unstable();
    counts.dedup();
    let mut md = String::new();
    let _ = write!(md, "| image | band pixels |");
    for n in &counts {
        let _ = write!(md, " {n} shells |");
    }
    let _ = write!(md, "\n|---|---|");
    for _ in &counts {
        let _ = write!(md, "---|");
    }
    md.push('\n');
    for &size in &report.options.sizes {
        let row: Vec<_> = counts
            .iter()
            .map(|n| {
                report
                    .cells
                    .iter()
                    .find(|c| c.size == size && c.count == *n)
                    .and_then(|c| c.silhouette.map(|s| (c, s)))
            })
            .collect();
        let band_pixels = row.iter().flatten().map(|(_, s)| s.band_pixels).next();
        let _ = write!(
            md,
            "| {size}² px | {} |",
            band_pixels.map_or("–".into(), |b| format!("{:.0} %", 100.0 * b))
        );
        for cell in &row {
            match cell {
                Some((c, s)) => {
                    let _ = write!(
                        md,
                        " {:.0} % of the error (band {:.3}, interior {:.3}); perfect silhouette {:.4} (of {:.4}) |",
                        100.0 * s.band_share,
                        s.band_flip,
                        s.interior_flip,
                        s.perfect.flip_mean,
                        c.error.flip_mean
                    );
                }
                None => {
                    let _ = write!(md, " – |");
                }
            }
        }
        md.push('\n');
    }
    let _ = writeln!(
        md,
        "\nThe silhouette band: object pixels whose view ray meets the sphere with |N·V| < {} or misses it (the fur beyond the body). Per count: the band's share of the summed per-pixel FLIP against {} shells, the FLIP mean over the band and over the interior, and the image's FLIP mean when its band is copied from the reference (the most any silhouette remedy, fins included, could remove, at no cost), of the image's FLIP mean as drawn.",
        report.options.silhouette_n_dot_v, report.reference
    );
    md
}

/// The fin experiment (markdown; empty when not run): per size and shell
/// count N, N shells with fins against the shell count the fins' time buys
/// without them.
pub fn fins_table(report: &ShellReport) -> String {
    if report.fins.is_empty() {
        return String::new();
    }
    let mut md = String::from(
        "\n| image | fins | fin rule | N shells | N + fins | shells at the same cost | pays |\n|---|---|---|---|---|---|---|\n",
    );
    for f in &report.fins {
        let c = &f.with_fins;
        let plain = report
            .cells
            .iter()
            .find(|p| p.size == c.size && p.count == c.count);
        let band = |s: &ShellCell| {
            s.silhouette
                .map_or(String::new(), |b| format!(", band {:.3}", b.band_flip))
        };
        let _ = writeln!(
            md,
            "| {}² px | {} | {} | {} | FLIP {:.4}{}, fins {:.2} ms | {}: FLIP {:.4}{}, {:.2} ms | {} |",
            c.size,
            f.fins,
            f.rule.describe(),
            plain.map_or(format!("{}", c.count), |p| format!(
                "{}: FLIP {:.4}{}, {:.2} ms",
                p.count,
                p.error.flip_mean,
                band(p),
                f.plain_ms
            )),
            c.error.flip_mean,
            band(c),
            f.fin_ms,
            f.same_cost.count,
            f.same_cost.error.flip_mean,
            band(&f.same_cost),
            f.same_cost.ms,
            if c.error.flip_mean < f.same_cost.error.flip_mean {
                "yes"
            } else {
                "no"
            }
        );
    }
    let _ = writeln!(
        md,
        "\nFins (`crates/weft-golden/src/fins.rs`): a quad on every mesh edge of the silhouette band (averaged normal |N·V| < {}, from the fixed camera), from the edge to the fur's tip, cut from the strand noise along the edge and lit as the shells, faded by how edge-on it is seen and by |N·V|; its opacity by the rule in the column, where \"shells faded\" also fades the shells by the same |N·V| weight (Lengyel et al.: fins fade in where shells fade out). FLIP mean (and over the band) against {} shells without fins. The time of N shells is the median frame, the fins' is their own: the frame with fins less the same frame with the fins pass hidden (body and fins share one mesh in the experiment, and the body's passes skip the fin vertices at a cost an engine with a fin mesh of its own would not pay). \"Shells at the same cost\": N × (N shells' time + the fins') / N shells' time, rounded up, drawn without fins in the same run. Pays: a lower FLIP mean than that.",
        report.options.silhouette_n_dot_v, report.reference
    );
    md
}

/// `<name>.shells.md`.
pub fn markdown_report(report: &ShellReport, command: &str) -> String {
    format!(
        "# {}: shell count against cost and error\n\nGenerated by `{command}` (timings vary by machine; do not edit).\n\n{}",
        report.material,
        markdown_table(report)
    ) + &silhouette_section(report)
}

/// The report's silhouette section (and the README's between
/// `<!-- weft:fins:begin -->` and `<!-- weft:fins:end -->`): the error split
/// by the silhouette band. Empty when not measured.
pub fn silhouette_section(report: &ShellReport) -> String {
    let table = silhouette_table(report);
    if table.is_empty() {
        return table;
    }
    format!("\n## Silhouette and fins\n\n{table}{}", fins_table(report))
}

/// Writes `<name>.shells.md` per report into `dir`; returns the paths.
pub fn write_reports(
    dir: &Path,
    reports: &[ShellReport],
    command: &str,
) -> Result<Vec<std::path::PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut written = Vec::new();
    for r in reports {
        let path = dir.join(format!("{}.shells.md", r.material));
        std::fs::write(&path, markdown_report(r, command))
            .map_err(|e| format!("{}: {e}", path.display()))?;
        written.push(path);
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cell(size: u32, count: u32, flip: f64) -> ShellCell {
        ShellCell {
            size,
            count,
            ms: 1.0,
            error: ImageError {
                flip_mean: flip,
                flip_p99: flip,
                rel_rmse: flip,
                pixels: 1,
            },
            silhouette: None,
        }
    }

    #[test]
    fn the_recommendation_is_the_fewest_shells_within_the_bar() {
        let report = ShellReport {
            material: "m".into(),
            inputs_hash: String::new(),
            parameter: "n".into(),
            tier: "fast".into(),
            reference: 128,
            adapter: String::new(),
            timer: String::new(),
            options: ShellOptions::default(),
            reference_ms: vec![(128, 2.0)],
            cells: vec![
                cell(128, 4, 0.2),
                cell(128, 8, 0.03),
                cell(128, 16, 0.02),
                cell(256, 4, 0.3),
                cell(256, 8, 0.06),
                cell(256, 16, 0.04),
            ],
            fins: Vec::new(),
        };
        assert_eq!(recommended(&report, 128), Some(8));
        assert_eq!(recommended(&report, 256), None);
        let md = markdown_table(&report);
        assert!(md.contains("| 256² px |"), "{md}");
        assert!(md.contains("| > 16 |"), "{md}");
        assert!(fins_table(&report).is_empty());
        assert!(silhouette_table(&report).is_empty());
    }

    #[test]
    fn fins_pay_only_below_the_error_of_the_shells_at_their_cost() {
        let fin = |with: f64, same: f64| FinCell {
            plain_ms: 1.0,
            with_fins: cell(128, 8, with),
            fin_ms: 0.5,
            fins: 10,
            rule: FinRule {
                opacity: FinOpacity::Slabs(1.0),
                fade_shells: true,
            },
            same_cost: cell(128, 12, same),
        };
        let report = ShellReport {
            material: "m".into(),
            inputs_hash: String::new(),
            parameter: "n".into(),
            tier: "fast".into(),
            reference: 128,
            adapter: String::new(),
            timer: String::new(),
            options: ShellOptions::default(),
            reference_ms: vec![(128, 2.0)],
            cells: vec![cell(128, 8, 0.03)],
            fins: vec![fin(0.02, 0.025), fin(0.03, 0.025)],
        };
        let md = fins_table(&report);
        let rows: Vec<&str> = md.lines().filter(|l| l.starts_with("| 128² px")).collect();
        assert_eq!(rows.len(), 2, "{md}");
        assert!(rows[0].ends_with("| yes |"), "{md}");
        assert!(rows[1].ends_with("| no |"), "{md}");
    }
}
