//! Numerical stability sweep (`weft stability` runs the same code; its own
//! test binary, see tests/Cargo.toml): every
//! shipped material, every canonical variant (and constant-keyword value),
//! a parameter grid derived from the metadata (each parameter at min / mid /
//! max with the others at their defaults, plus all-min and all-max corners),
//! crossed with the geometric extremes of `weft_render::probe` (N·V and N·L
//! at 1, 1e-4, 0 and negative, L = ±V, grazing, H parallel to the tangent,
//! degenerate tangents and normals). Outputs are read from an Rgba32Float
//! target on lavapipe; any NaN, Inf, negative or > 65504 channel fails.
//!
//! `a_nan_at_grazing_angles_is_found` proves the sweep can fail: it builds a
//! copy of the standard material with an unguarded N·V and expects the
//! failures exactly at the grazing and back-facing cases.
//!
//! The probe binds uniform blocks as storage buffers
//! (`RenderOptions::uniforms_as_storage`): Mesa 22.3's lavapipe otherwise
//! JIT-compiles and leaks a shader at every draw of a shader whose branch
//! reads a uniform, and this binary grew past 20 GiB.
//!
//! The tests run side by side (libtest's threads), unlike the other GPU
//! binaries' (`weft_tests::gpu_serial`): each draws on its calling thread
//! (`LP_NUM_THREADS=0`), so one at a time would leave a core idle.
//!
//! With no Vulkan adapter these tests fail with what to install; they never skip.

use std::path::{Path, PathBuf};
use std::time::Instant;
use weft_render::probe::{
    BadKind, Probe, SweepReport, failures_by_case, generated_materials, sweep_material,
    sweep_renderer,
};
use weft_render::{Light, Luts, Material, Renderer};
use weft_tests::{copy_dir, repo};

fn renderer(generated: &Path) -> Renderer {
    single_threaded_lavapipe();
    let luts = Luts::load_dir(generated).unwrap();
    sweep_renderer(&luts)
        .unwrap_or_else(|e| panic!("the stability sweep needs a Vulkan adapter: {e}"))
}

/// `LP_NUM_THREADS=0` for the whole binary (`weft stability` sets it too).
fn single_threaded_lavapipe() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    // SAFETY: every test here calls this before it creates a device, and
    // `call_once` holds the others until it returns, so no thread is inside
    // Mesa yet (the only reader of the environment through libc).
    ONCE.call_once(|| unsafe { weft_render::probe::draw_sweeps_on_the_calling_thread() });
}

fn probe() -> Probe {
    Probe::stability(Light::default().radiance)
}

fn sweep(renderer: &mut Renderer, probe: &Probe, metas: &[PathBuf]) -> SweepReport {
    let mut report = SweepReport::default();
    for meta in metas {
        let started = Instant::now();
        sweep_material(renderer, probe, meta, &mut report, &mut |_, _| {}).unwrap();
        let m = report.materials.last().unwrap();
        println!(
            "{}: {} variant(s) ({} aliases skipped), {} settings, {} draws, {} bad, {:.1}s",
            m.material,
            m.variants,
            m.aliases,
            m.renders,
            m.draws,
            m.bad,
            started.elapsed().as_secs_f64()
        );
    }
    report
}

/// The name of a `<name>/<name>.meta.json` path.
fn material_name(meta: &Path) -> String {
    meta.parent()
        .and_then(Path::file_name)
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// The sweep over one shipped material: every canonical variant (and
/// constant-keyword value) x the parameter grid x the geometric cases.
fn sweep_shipped_material(name: &str) {
    let started = Instant::now();
    let generated = repo().join("generated");
    let mut renderer = renderer(&generated);
    println!("adapter: {}", renderer.gpu().describe());
    let metas: Vec<PathBuf> = generated_materials(&generated)
        .unwrap()
        .into_iter()
        .filter(|m| material_name(m) == name)
        .collect();
    assert_eq!(
        metas.len(),
        1,
        "no material `{name}` in {}",
        generated.display()
    );
    let report = sweep(&mut renderer, &probe(), &metas);
    println!(
        "{name}: {} in {:.1}s",
        report.summary(),
        started.elapsed().as_secs_f64()
    );
    if report.bad() > 0 {
        let mut msg = String::new();
        for (case, (n, kinds)) in failures_by_case(&report.failures) {
            msg += &format!("  {case}: {n} (variant, setting) pair(s), {kinds:?}\n");
        }
        for f in report.failures.iter().take(40) {
            msg += &format!("  {f}\n");
        }
        panic!(
            "{}\nby case, then the first failures:\n{msg}",
            report.summary()
        );
    }
}

/// One test per shipped material (a failure names its material, and each
/// is a fraction of the whole sweep); `every_shipped_material_is_swept`
/// keeps the list whole.
macro_rules! sweep_each {
    ($($material:ident),* $(,)?) => {
        mod every_shipped_material_is_finite_non_negative_and_bounded {
            $(
                #[test]
                fn $material() {
                    super::sweep_shipped_material(stringify!($material));
                }
            )*
        }
        const SWEPT: &[&str] = &[$(stringify!($material)),*];
    };
}

sweep_each!(
    eye,
    face,
    fur,
    gauze,
    glitter,
    hair,
    laser,
    microcylinder,
    satin,
    silk,
    skin,
    standard,
    velvet,
);

/// A new material gets its own sweep test, or this fails.
#[test]
fn every_shipped_material_is_swept() {
    let mut shipped: Vec<String> = generated_materials(&repo().join("generated"))
        .unwrap()
        .iter()
        .map(|m| material_name(m))
        .collect();
    shipped.sort();
    assert_eq!(shipped, SWEPT, "add the new material to `sweep_each!`");
}

/// The probe really draws every tile: the standard material writes alpha =
/// base alpha = 1 on every pixel it shades (the background's alpha is 0),
/// and is lit wherever N·V and N·L are clearly positive.
#[test]
fn the_probe_covers_every_tile() {
    let generated = repo().join("generated");
    let mut renderer = renderer(&generated);
    let probe = probe();
    let material = Material::load(generated.join("standard/standard.meta.json")).unwrap();
    let prepared = renderer
        .prepare(&material, &probe.render_options())
        .unwrap();
    let tiles = probe.evaluate(&mut renderer, &prepared).unwrap();
    assert_eq!(tiles.len(), probe.cases.len());
    for (case, pixels) in probe.cases.iter().zip(&tiles) {
        assert_eq!(pixels.len(), (probe.cell * probe.cell) as usize);
        for px in pixels {
            assert_eq!(px[3], 1.0, "{}: pixel not drawn: {px:?}", case.name);
            if case.n_dot_v() > 0.1 && case.n_dot_l() > 0.1 {
                assert!(px[0] > 0.0 && px[1] > 0.0, "{}: unlit {px:?}", case.name);
            }
        }
    }
}

/// A deliberately broken copy of the standard material: the guarded n·v
/// (`weft_clamp_cos(dot(n, v))` in lib/surface.wgsl's
/// `weft_main_light_geometry`) becomes `dot(n, v)` and the returned alpha is
/// multiplied by `sqrt(n·v) / sqrt(n·v)` (1 for N·V > 0, NaN for
/// N·V <= 0: 0/0 at exactly 0, sqrt of a negative below). The sweep must
/// report NaN at every back-facing case, and (without a normal map, which
/// bends the normal) nowhere N·V >= 1e-4.
#[test]
fn a_nan_at_grazing_angles_is_found() {
    let tmp = tempfile::tempdir().unwrap();
    let materials = tmp.path().join("materials");
    copy_dir(&repo().join("materials/lib"), &materials.join("lib"));
    copy_dir(
        &repo().join("materials/standard"),
        &materials.join("standard"),
    );
    let break_in = |file: &str, from: &str, to: &str| {
        let path = materials.join(file);
        let source = std::fs::read_to_string(&path).unwrap();
        assert!(source.contains(from), "`{from}` not in {file}");
        std::fs::write(&path, source.replace(from, to)).unwrap();
    };
    break_in(
        "lib/surface.wgsl",
        "weft_clamp_cos(dot(n, v)),",
        "dot(n, v),",
    );
    break_in(
        "standard/standard.wgsl",
        "return vec4<f32>(radiance, alpha);",
        "return vec4<f32>(radiance, alpha * sqrt(lit.n_dot_v) / sqrt(lit.n_dot_v));",
    );
    let out = weft_compiler::build_library(
        &materials,
        &weft_compiler::BuildOptions::default(),
        &|_, _, _| {},
    )
    .unwrap_or_else(|_| panic!("the broken copy does not compile"));
    let generated = tmp.path().join("generated");
    weft_compiler::output::write_atomically(&generated, &out.files, &[]).unwrap();

    let mut renderer = renderer(&generated);
    let probe = probe();
    let report = sweep(
        &mut renderer,
        &probe,
        &[generated.join("standard/standard.meta.json")],
    );
    println!("{}", report.summary());
    assert!(report.bad() > 0, "the sweep found nothing");
    for f in &report.failures {
        assert_eq!(f.kind, BadKind::NaN, "{f}");
        // A normal map bends the shading normal away from the geometric
        // one, so only variants without it map failures to N.V exactly.
        if !f.variant.contains("normal_map-on") {
            assert!(f.n_dot_v <= 0.0, "failure where N.V > 0: {f}");
        }
    }
    let by_case = failures_by_case(&report.failures);
    for (case, (n, _)) in &by_case {
        println!("  {case}: {n}");
    }
    // Every case that looks from below the surface fails, in every variant
    // and setting that keeps the normal (normal maps bend it; all variants
    // without one must fail).
    for case in probe.cases.iter().filter(|c| c.n_dot_v() < -0.1) {
        let n = by_case.get(&case.name).map_or(0, |e| e.0);
        assert!(
            n > 0,
            "`{}` (N.V = {}) was not reported",
            case.name,
            case.n_dot_v()
        );
    }
    assert!(by_case.keys().any(|c| c.contains("N.V=0 ")));
}
