//! The fur material's shells (issue 11, deliverable 3): one instanced draw
//! whose count is the `shell_count` parameter, transparent without depth
//! writes over an opaque skin pass, and a count that converges (the shell
//! bench, `weft_golden::shells`).

use std::path::{Path, PathBuf};
use weft_golden::shells::{ShellOptions, instance_parameter, run};
use weft_meta::{BlendMode, InstanceCount};
use weft_render::{
    EnvironmentMaps, Gpu, Luts, Material, PreviewOptions, RenderOptions, Renderer, SceneKind,
};

fn generated() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated")
}

fn meta_path() -> PathBuf {
    generated().join("fur/fur.meta.json")
}

#[test]
fn shells_are_one_instanced_transparent_pass_over_an_opaque_skin() {
    let _gpu = weft_tests::gpu_serial();
    let material = Material::load(meta_path()).expect("generated/fur");
    let meta = material.metadata();
    assert_eq!(instance_parameter(meta), Some("shell_count"));
    let [skin, shells] = meta.passes.as_slice() else {
        panic!("fur has two passes, got {:?}", meta.passes.len());
    };
    assert_eq!(skin.render_state.blend, BlendMode::Opaque);
    assert!(skin.render_state.depth_write);
    assert_eq!(skin.instances, InstanceCount::Fixed(1));
    assert_eq!(shells.render_state.blend, BlendMode::Alpha);
    assert!(!shells.render_state.depth_write);
    assert!(shells.render_state.queue > skin.render_state.queue);
    assert_eq!(
        shells.instances,
        InstanceCount::Parameter("shell_count".into())
    );
    // The pipeline state an engine sets: no depth write, depth tested.
    let depth = &shells.depth_stencil;
    assert!(!depth.depth_write_enabled);
    assert_ne!(
        depth.depth_compare,
        weft_meta::DepthTest::Always,
        "shells test depth"
    );

    // The runtime draws the skin once and the shells `shell_count` times,
    // and follows the parameter without re-preparing.
    let gpu = Gpu::new().unwrap_or_else(|e| panic!("needs a Vulkan adapter: {e}"));
    let luts = Luts::load_dir(generated()).expect("LUTs");
    let preview = PreviewOptions {
        scene: SceneKind::Sphere,
        width: 32,
        height: 32,
        ..PreviewOptions::default()
    };
    let env = EnvironmentMaps::sky(&preview.sky_params());
    let mut renderer = Renderer::new(gpu, &env, &luts).expect("renderer");
    let options: RenderOptions = preview.render_options();
    let mut material = material;
    let mut prepared = renderer.prepare(&material, &options).expect("prepare");
    assert_eq!(prepared.instances(), &[1, 20]);
    material.set("shell_count", 7i64).expect("set");
    renderer.update(&mut prepared, &material).expect("update");
    assert_eq!(prepared.instances(), &[1, 7]);
    assert!(material.set("shell_count", 129i64).is_err(), "out of range");
}

#[test]
fn more_shells_converge_to_the_reference_count() {
    let _gpu = weft_tests::gpu_serial();
    let options = ShellOptions {
        sizes: vec![96],
        counts: vec![4, 32],
        reference: 128,
        frames: 1,
        warmup: 0,
        ..ShellOptions::default()
    };
    let reports = run(&generated(), &["fur".into()], &options, &mut |_| {}).expect("bench");
    let [report] = reports.as_slice() else {
        panic!("one report for fur, got {}", reports.len());
    };
    let flip = |n: u32| {
        report
            .cells
            .iter()
            .find(|c| c.count == n)
            .unwrap_or_else(|| panic!("{n} shells measured"))
            .error
            .flip_mean
    };
    println!(
        "FLIP vs 128 shells: 4 -> {:.4}, 32 -> {:.4}",
        flip(4),
        flip(32)
    );
    // 4 shells visibly step the strands; 32 are close to 128.
    assert!(flip(4) > 2.0 * flip(32), "{} vs {}", flip(4), flip(32));
    assert!(flip(32) < 0.05, "32 shells: FLIP {}", flip(32));
}

/// The shell bench's fin experiment (`weft_golden::fins`) draws what it
/// claims: with the fins hidden, the body's passes over the shared mesh give
/// the fur's own image exactly; with fins, the image changes, and in the
/// silhouette band.
#[test]
fn the_fin_experiment_draws_fins_at_the_silhouette_only() {
    let _gpu = weft_tests::gpu_serial();
    use weft_golden::fins::{FinOpacity, FinRule, build, scene_with_fins};
    use weft_golden::silhouette::sphere_band;
    let repo = generated().parent().unwrap().to_path_buf();
    let work = tempfile::tempdir().expect("temp dir");
    let rule = |opacity| FinRule {
        opacity,
        fade_shells: false,
    };
    let hidden = build(
        &repo.join("materials"),
        &work.path().join("hidden"),
        rule(FinOpacity::Hidden),
    )
    .expect("fur_fins builds");
    let shown = build(
        &repo.join("materials"),
        &work.path().join("shown"),
        rule(FinOpacity::Slabs(1.0)),
    )
    .expect("fur_fins builds");

    let gpu = Gpu::new().unwrap_or_else(|e| panic!("needs a Vulkan adapter: {e}"));
    let luts = Luts::load_dir(generated()).expect("LUTs");
    let size = 96;
    let preview = PreviewOptions {
        scene: SceneKind::Sphere,
        width: size,
        height: size,
        ..PreviewOptions::default()
    };
    let env = EnvironmentMaps::sky(&preview.sky_params());
    let mut renderer = Renderer::new(gpu, &env, &luts).expect("renderer");
    let options = RenderOptions {
        background: weft_render::Background::Color([0.0; 4]),
        ..preview.render_options()
    };
    let scene = preview.scene();
    let (fin_scene, fins) = scene_with_fins(&scene, 0.3);
    assert!(fins > 0);
    let mut draw = |path: PathBuf, scene: &weft_render::Scene| {
        let mut m = Material::load(path).expect("load");
        m.set("shell_count", 8i64).expect("set");
        renderer.render(&m, scene, &options).expect("render")
    };
    let plain = draw(meta_path(), &scene);
    let without = draw(hidden, &fin_scene);
    assert!(
        plain.pixels == without.pixels,
        "hidden fins change the fur's image"
    );
    let with = draw(shown, &fin_scene);
    let band = sphere_band(&scene, size, size, 0.3);
    let (mut in_band, mut inside) = (0, 0);
    for ((a, b), in_b) in plain.pixels.iter().zip(&with.pixels).zip(&band) {
        // Visibly changed (fins fade to alpha 0 at the band's edge).
        if a.iter().zip(b).any(|(x, y)| (x - y).abs() > 1e-3) {
            if *in_b {
                in_band += 1;
            } else {
                inside += 1;
            }
        }
    }
    println!("pixels changed by fins: {in_band} in the band, {inside} inside");
    assert!(in_band > 50, "fins changed {in_band} band pixels");
    assert!(inside * 10 < in_band, "{inside} interior pixels changed");
}
