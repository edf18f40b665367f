//! A second, independent consumer of the metadata contract
//! (docs/engine-interface.md): `support/engine/` builds bind group layouts,
//! pipeline layouts and pipelines for every pass of every canonical variant
//! of every material in `generated/` from the metadata alone — nothing from
//! `weft-render`, no WGSL read — and draws each with the declared defaults.
//! Its picture must match `weft-render`'s of the same variant on the same
//! mesh, camera, light and environment, and must not be black, NaN or empty.
//! Every shipped scene's shaders are bound, built and drawn the same way and
//! compared with `weft-render`'s scene render.
//!
//! With no Vulkan adapter these tests fail with what to install; they never skip.

use crate::{engine, harness};

use engine::library::{self, canonical_variants, scene_inputs};
use engine::{DrawItem, Engine, Image, Language, Library, ShaderRef, World};
use harness::{Stats, flip, stats};
use std::path::Path;
use weft_meta::MaterialMetadata;

/// FLIP mean (whole 128×128 picture, Reinhard then sRGB8) allowed between
/// the consumer's picture and weft-render's. Same mesh, data and shader
/// files: on lavapipe (Mesa 22.3 llvmpipe) the two pictures are bit-identical
/// (measured FLIP mean 0 and largest linear difference 0 for all 48
/// variants and both scenes); the allowance is for drivers whose shader
/// compilers differ between two devices.
const FLIP_MEAN_MAX: f32 = 1e-3;

/// Share of pixels an object must cover (alpha > 0.02; alpha is coverage
/// and the picture is cleared to alpha 0). The sphere covers 0.556 of the
/// picture in every variant, gauze's blended passes included.
const MIN_COVERAGE: f64 = 0.4;

/// Mean linear luminance the covered pixels must exceed. The darkest
/// variant is velvet's `fast` tier at 0.0122 (dark red, metallic 1); an
/// unlit picture measures 0 (`a_black_picture_fails`). 0.004 (sRGB ≈ 12/255)
/// is a third of the darkest.
const MIN_LUMINANCE: f64 = 0.004;

/// Draws one canonical variant with the consumer.
#[allow(clippy::too_many_arguments)]
fn consumer_variant(
    engine: &Engine,
    world: &mut World,
    lib: &Library,
    meta_path: &Path,
    meta: &MaterialMetadata,
    variant: &str,
    language: Language,
    mesh: &engine::Mesh,
) -> Result<Image, String> {
    engine.draw_variant(
        world,
        &lib.root,
        meta_path,
        meta,
        variant,
        language,
        mesh,
        (harness::SIZE, harness::SIZE),
        harness::CLEAR,
    )
}

/// The checks every variant passes: no NaN/Inf (nor a channel at the f16
/// maximum, which is what the materials' output clamp makes of an Inf or
/// NaN), something drawn, not black, and weft-render's picture. Returns
/// the FLIP mean, the consumer's stats and the failures.
fn check(label: &str, consumer: &Image, reference: &Image) -> (f32, Stats, Vec<String>) {
    let s = stats(consumer);
    let mut failures = Vec::new();
    if s.non_finite > 0 || s.at_f16_max > 0 {
        failures.push(format!(
            "{label}: {} NaN/Inf pixels, {} at the f16 maximum",
            s.non_finite, s.at_f16_max
        ));
    }
    if s.coverage < MIN_COVERAGE {
        failures.push(format!(
            "{label}: draws nothing (coverage {:.3} < {MIN_COVERAGE})",
            s.coverage
        ));
    }
    if s.mean_luminance.is_nan() || s.mean_luminance < MIN_LUMINANCE {
        failures.push(format!(
            "{label}: renders black (mean luminance {:.4} < {MIN_LUMINANCE})",
            s.mean_luminance
        ));
    }
    let f = flip(reference, consumer).mean;
    if f.is_nan() || f > FLIP_MEAN_MAX {
        failures.push(format!(
            "{label}: differs from weft-render's picture (FLIP mean {f:.5} > {FLIP_MEAN_MAX})"
        ));
    }
    (f, s, failures)
}

/// Extremes over the pictures checked, for the report.
#[derive(Default)]
struct Measured {
    max_flip: f32,
    max_difference: f32,
    min_coverage: Option<f64>,
    min_luminance: Option<f64>,
    max_channel: f32,
}

impl Measured {
    fn add(&mut self, label: &str, flip: f32, st: &Stats, consumer: &Image, reference: &Image) {
        let d = harness::max_abs_difference(consumer, reference);
        println!(
            "{label:58} FLIP {flip:.5}  max |diff| {d:.2e}  coverage {:.3}  \
             luminance {:.4}  max {:.2}",
            st.coverage, st.mean_luminance, st.max_channel
        );
        self.max_flip = self.max_flip.max(flip);
        self.max_difference = self.max_difference.max(d);
        self.min_coverage = Some(
            self.min_coverage
                .map_or(st.coverage, |c| c.min(st.coverage)),
        );
        self.min_luminance = Some(
            self.min_luminance
                .map_or(st.mean_luminance, |c| c.min(st.mean_luminance)),
        );
        self.max_channel = self.max_channel.max(st.max_channel);
    }

    fn summary(&self) -> String {
        format!(
            "FLIP mean max {:.5}, largest linear difference {:.2e}, coverage min {:.3}, \
             luminance min {:.4}, largest channel {:.2}",
            self.max_flip,
            self.max_difference,
            self.min_coverage.unwrap_or(0.0),
            self.min_luminance.unwrap_or(0.0),
            self.max_channel
        )
    }
}

struct Setup {
    lib: Library,
    engine: Engine,
    world: World,
    mesh: engine::Mesh,
    reference: harness::Reference,
    scene: weft_render::Scene,
}

fn setup() -> Setup {
    let lib = Library::load(&harness::generated()).unwrap();
    let sky = harness::sky();
    let scene = harness::material_scene();
    Setup {
        engine: Engine::new(false),
        world: World::new(
            harness::environment(&sky),
            harness::frame(&scene.camera, &scene.light),
        ),
        mesh: harness::mesh(&scene.mesh),
        reference: harness::Reference::new(&sky),
        lib,
        scene,
    }
}

#[test]
fn every_variant_draws_from_the_metadata_alone_like_weft_render() {
    let started = std::time::Instant::now();
    let mut s = setup();
    println!("consumer adapter: {}", s.engine.describe());
    let mut failures = Vec::new();
    let (mut count, mut expected) = (0, 0);
    let mut measured = Measured::default();
    for (meta_path, meta) in &s.lib.materials {
        let variants = canonical_variants(meta).unwrap();
        expected += variants.len();
        for (v, _) in variants {
            let label = format!("{}/{}", meta.name, v.id);
            let consumer = match consumer_variant(
                &s.engine,
                &mut s.world,
                &s.lib,
                meta_path,
                meta,
                &v.id,
                Language::Wgsl,
                &s.mesh,
            ) {
                Ok(i) => i,
                Err(e) => {
                    failures.push(format!("{label}: {e}"));
                    continue;
                }
            };
            if meta.name == "imaged" {
                failures.extend(image_quadrants(&label, &consumer));
            }
            let reference = s.reference.variant(meta_path, &v.id, &s.scene);
            let (f, st, mut fails) = check(&label, &consumer, &reference);
            measured.add(&label, f, &st, &consumer, &reference);
            failures.append(&mut fails);
            count += 1;
        }
    }
    println!(
        "{count} variants: {}; {:.1} s",
        measured.summary(),
        started.elapsed().as_secs_f64()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert_eq!(count, expected);
    assert!(count >= 48, "expected every shipped variant, drew {count}");
}

/// Every scene in `generated/scenes/`: each instance bound with its
/// specialised shader from the scene metadata alone (uniform by member
/// name, textures by binding name), every pass's pipeline built, the scene
/// drawn and compared with weft-render's.
#[test]
fn every_scene_draws_from_its_metadata_alone_like_weft_render() {
    let started = std::time::Instant::now();
    let mut s = setup();
    assert!(!s.lib.scenes.is_empty(), "no scene in generated/scenes/");
    let mut failures = Vec::new();
    let mut pipelines = 0;
    let mut measured = Measured::default();
    for (path, meta) in &s.lib.scenes {
        let camera = weft_render::scene_camera(meta);
        let light = weft_render::SceneLighting::from_metadata(meta).light;
        // No light of the engine's own: the metadata must state it.
        let no_light = weft_render::Light {
            direction: [0.0, 1.0, 0.0],
            radiance: [0.0; 3],
        };
        let (env, frame) =
            library::scene_world(meta, &s.world.env, &harness::frame(&camera, &no_light));
        assert_eq!(frame.light_color, light.radiance, "the same light");
        let d = light.direction;
        let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        for (a, b) in frame.light_direction.iter().zip(d) {
            assert!((a - b / len).abs() < 1e-6, "the same light direction");
        }
        let mut world = World::new(env, frame);
        let mut prepared = Vec::new();
        for inst in &meta.instances {
            let label = format!("scene {} instance {}", meta.name, inst.name);
            let shader = meta
                .shaders
                .iter()
                .find(|sh| sh.id == inst.shader)
                .unwrap_or_else(|| panic!("{label}: no shader `{}`", inst.shader));
            // The mesh from the file the metadata names (scene schema 3.3),
            // not from weft-render's generators.
            let mesh = library::scene_mesh(&s.lib.root, path.parent().unwrap(), meta, &inst.mesh)
                .unwrap_or_else(|e| panic!("{label}: {e}"));
            let sref = ShaderRef {
                label: label.clone(),
                dir: path.parent().unwrap().to_path_buf(),
                root: s.lib.root.clone(),
                shader: &shader.shader,
                passes: &inst.passes,
                languages: None,
            };
            let p = scene_inputs(meta, inst, &shader.shader, path.parent().unwrap()).and_then(
                |inputs| {
                    s.engine.prepare(
                        &mut world,
                        &sref,
                        Language::Wgsl,
                        &inputs,
                        &mesh,
                        &library::instance_model(inst),
                    )
                },
            );
            match p {
                Ok(p) => {
                    pipelines += p.pipelines.passes.len();
                    prepared.push(p);
                }
                Err(e) => failures.push(format!("{label}: {e}")),
            }
        }
        if prepared.len() != meta.instances.len() {
            continue;
        }
        let draws: Vec<DrawItem> = library::scene_order(meta)
            .into_iter()
            .map(|(i, pass)| DrawItem {
                prepared: &prepared[i],
                pass,
            })
            .collect();
        let consumer = s
            .engine
            .render(&draws, harness::SIZE, harness::SIZE, harness::CLEAR)
            .unwrap();
        let file = weft_render::SceneFile::load(path).unwrap();
        let r = &mut s.reference.renderer;
        let options = harness::options();
        let ps = r
            .prepare_scene(&file, &weft_render::SceneShaders::Specialised, &options)
            .unwrap();
        let reference = harness::image(&r.render_scene(&ps, &options).unwrap());
        let label = format!("scene {}", meta.name);
        let (f, st, mut fails) = check(&label, &consumer, &reference);
        measured.add(&label, f, &st, &consumer, &reference);
        failures.append(&mut fails);
    }
    println!(
        "{} scenes, {pipelines} pipelines: {}; {:.1} s",
        s.lib.scenes.len(),
        measured.summary(),
        started.elapsed().as_secs_f64()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Draws the default variant of `material` with the consumer after
/// `tamper` changed its metadata, the consumer's world after `world`
/// changed it, and returns the failures of [`check`] against weft-render's
/// untampered picture.
fn tampered(
    material: &str,
    tamper: impl FnOnce(&mut MaterialMetadata),
    world: impl FnOnce(&mut World),
) -> Vec<String> {
    let mut s = setup();
    let (meta_path, meta) = s
        .lib
        .materials
        .iter()
        .find(|(_, m)| m.name == material)
        .unwrap()
        .clone();
    let variant = canonical_variants(&meta).unwrap()[0].0.id.clone();
    let mut meta = meta;
    tamper(&mut meta);
    world(&mut s.world);
    let consumer = consumer_variant(
        &s.engine,
        &mut s.world,
        &s.lib,
        &meta_path,
        &meta,
        &variant,
        Language::Wgsl,
        &s.mesh,
    )
    .unwrap();
    let reference = s.reference.variant(&meta_path, &variant, &s.scene);
    let (f, st, failures) = check(material, &consumer, &reference);
    println!("tampered {material}: FLIP {f:.5}, {st:?}: {failures:?}");
    failures
}

fn assert_caught(failures: &[String], what: &str) {
    assert!(
        failures.iter().any(|f| f.contains(what)),
        "expected a failure mentioning `{what}`, got {failures:?}"
    );
}

/// An engine that uploads a colour as edited (sRGB) instead of
/// `color.linear_default` draws a different picture, and the comparison
/// says so.
#[test]
fn a_wrong_colour_encoding_fails_the_comparison() {
    let failures = tampered(
        "satin",
        |m| {
            for p in &mut m.parameters {
                if let (Some(c), Some(d)) = (&mut p.color, p.default.as_array()) {
                    c.linear_default = std::array::from_fn(|i| d[i].as_f64().unwrap());
                }
            }
        },
        |_| {},
    );
    assert_caught(&failures, "differs from weft-render's picture");
}

/// Without light (black environment, zero SH, no main light) a variant
/// renders black, and the luminance check says so.
#[test]
fn a_black_picture_fails() {
    let failures = tampered(
        "standard",
        |_| {},
        |w| {
            w.env = engine::Environment::black();
            w.frame.light_color = [0.0; 3];
        },
    );
    assert_caught(&failures, "renders black");
}

/// An infinite light makes infinite (and, times zero, NaN) radiance; the
/// materials clamp their output to the f16 maximum, and the check says so.
#[test]
fn a_nan_or_inf_picture_fails() {
    let failures = tampered(
        "satin",
        |_| {},
        |w| w.frame.light_color = [f32::INFINITY; 3],
    );
    assert_caught(&failures, "at the f16 maximum");
}

/// A pass that writes no channel draws nothing, and the coverage check
/// says so.
#[test]
fn an_empty_picture_fails() {
    let failures = tampered(
        "standard",
        |m| {
            for p in &mut m.passes {
                for t in &mut p.color_targets {
                    t.write_mask.clear();
                }
            }
        },
        |_| {},
    );
    assert_caught(&failures, "draws nothing");
}

/// The `imaged` fixture maps its shipped image (red top-left, green
/// top-right, blue bottom-left, white bottom-right) over the screen: the
/// engine, binding `texture.file` while the parameter is unset, must show it
/// so (not the built-in black default, not upside down).
fn image_quadrants(label: &str, img: &Image) -> Option<String> {
    let (a, b) = (img.width * 7 / 20, img.width * 13 / 20);
    let want = [
        ((a, a), [1.0, 0.0, 0.0]),
        ((b, a), [0.0, 1.0, 0.0]),
        ((a, b), [0.0, 0.0, 1.0]),
        ((b, b), [1.0, 1.0, 1.0]),
    ];
    let wrong: Vec<String> = want
        .iter()
        .filter_map(|&((x, y), w)| {
            let p = img.pixel(x, y);
            (0..3)
                .any(|i| (p[i] - w[i]).abs() > 0.02)
                .then(|| format!("({x}, {y}) is {p:?}, expected {w:?}"))
        })
        .collect();
    (!wrong.is_empty()).then(|| format!("{label}: the shipped image: {}", wrong.join("; ")))
}

/// The test fixtures exercise what the shipped materials do not: a
/// `constant`-mode keyword (a WGSL pipeline constant), a gradient ramp and
/// aliased variants. Every canonical variant draws like weft-render's.
#[test]
fn every_fixture_variant_draws_like_weft_render() {
    let (_tmp, root) = harness::fixture_library();
    let mut s = setup();
    s.lib = Library::load(&root).unwrap();
    assert!(!s.lib.materials.is_empty(), "no fixture material");
    let mut failures = Vec::new();
    let mut measured = Measured::default();
    let mut count = 0;
    let materials = std::mem::take(&mut s.lib.materials);
    for (meta_path, meta) in &materials {
        for (v, shader) in canonical_variants(meta).unwrap() {
            let label = format!("fixture {}/{}", meta.name, v.id);
            let consumer = consumer_variant(
                &s.engine,
                &mut s.world,
                &s.lib,
                meta_path,
                meta,
                &v.id,
                Language::Wgsl,
                &s.mesh,
            );
            let consumer = match consumer {
                Ok(i) => i,
                Err(e) => {
                    failures.push(format!("{label}: {e}"));
                    continue;
                }
            };
            let reference = s.reference.variant(meta_path, &v.id, &s.scene);
            let (f, st, mut fails) = check(&label, &consumer, &reference);
            measured.add(&label, f, &st, &consumer, &reference);
            failures.append(&mut fails);
            println!(
                "{label}: pipeline constants {:?}",
                shader
                    .pipeline_constants
                    .iter()
                    .map(|c| (&c.name, &c.default_value))
                    .collect::<Vec<_>>()
            );
            count += 1;
        }
    }
    println!("{count} fixture variants: {}", measured.summary());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(count >= 2);
}
