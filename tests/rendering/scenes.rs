//! The shipped scenes (every `scenes/*.scene.toml`), as `cargo xtask
//! regenerate` builds them into `generated/scenes/<scene>/` (kept current by
//! `build_outputs`), drawn on lavapipe from their metadata and files alone:
//!
//! - folding keeps the picture: the scene-specialised shaders and the generic
//!   library variants (the instance's values set as parameters) draw the
//!   same image (FLIP mean over object pixels at most
//!   [`FOLD_FLIP_MEAN_THRESHOLD`]); a wrong folded constant or a wrong shader
//!   exceeds it, so the comparison can fail;
//! - each scene matches its golden `tests/goldens/scenes/<scene>.png` with
//!   the material goldens' threshold (`cargo xtask bless` writes them);
//! - drawing creates no pipeline, and every instance draws every pass;
//! - scene builds are byte-identical run to run and on 1 or 4 rayon threads.
//!
//! With no Vulkan adapter these tests fail with what to install; they never skip.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, OnceLock};
use weft_golden::scenes::{
    FOLD_FLIP_MEAN_THRESHOLD, SCENE_GOLDEN_SIZE, SceneHarness, built_scene_path, render_golden,
    scene_golden_path, shipped_scenes,
};
use weft_golden::shading::image_error;
use weft_golden::{FLIP_MEAN_THRESHOLD, flip, read_png, write_png};
use weft_meta::ParamKind;
use weft_render::{Background, HdrImage, SceneFile, SceneShaders, math};
use weft_tests::repo;

fn generated() -> PathBuf {
    repo().join("generated")
}

/// Every shipped scene's built metadata, by name.
fn scenes() -> Vec<(String, SceneFile)> {
    let names = shipped_scenes(&repo()).unwrap();
    assert!(!names.is_empty(), "no scenes/*.scene.toml");
    names
        .into_iter()
        .map(|name| {
            let path = built_scene_path(&generated(), &name);
            let scene = SceneFile::load(&path)
                .unwrap_or_else(|e| panic!("{name}: {e}; run `cargo xtask regenerate`"));
            (name, scene)
        })
        .collect()
}

/// One renderer for every test of this file (tests take turns).
fn harness() -> MutexGuard<'static, SceneHarness> {
    static CELL: OnceLock<Mutex<SceneHarness>> = OnceLock::new();
    CELL.get_or_init(|| {
        let h = SceneHarness::new(&generated())
            .unwrap_or_else(|e| panic!("scene tests need a Vulkan adapter: {e}"));
        println!("adapter: {}", h.adapter());
        Mutex::new(h)
    })
    .lock()
    .unwrap_or_else(|e| e.into_inner())
}

const BLACK: Background = Background::Color([0.0; 4]);

fn render(h: &mut SceneHarness, name: &str, scene: &SceneFile, shaders: &SceneShaders) -> HdrImage {
    let image = h
        .render(scene, shaders, SCENE_GOLDEN_SIZE, BLACK)
        .unwrap_or_else(|e| panic!("{name}: {e}"));
    assert_eq!(
        image.non_finite_count(),
        0,
        "{name}: NaN or Inf in the render"
    );
    image
}

fn library() -> SceneShaders {
    SceneShaders::Library(generated())
}

/// FLIP mean over object pixels (the background is transparent black).
fn fold_error(specialised: &HdrImage, other: &HdrImage) -> f64 {
    image_error(specialised, other).flip_mean
}

#[test]
fn folding_keeps_the_picture() {
    let _gpu = weft_tests::gpu_serial();
    let mut h = harness();
    for (name, scene) in scenes() {
        let specialised = render(&mut h, &name, &scene, &SceneShaders::Specialised);
        let generic = render(&mut h, &name, &scene, &library());
        let e = image_error(&specialised, &generic);
        println!(
            "{name}: specialised vs library FLIP mean {:.5} (p99 {:.4}) over {} object pixels",
            e.flip_mean, e.flip_p99, e.pixels
        );
        assert!(
            e.pixels > 1000,
            "{name}: only {} object pixels drawn",
            e.pixels
        );
        assert!(
            e.flip_mean <= FOLD_FLIP_MEAN_THRESHOLD,
            "{name}: the specialised shaders change the picture: FLIP mean {:.5} > {FOLD_FLIP_MEAN_THRESHOLD}",
            e.flip_mean
        );
    }
}

/// A colour far from `c` (linear RGB; alpha kept).
fn contrasting(c: &serde_json::Value) -> serde_json::Value {
    let v: Vec<f64> = c
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    let alpha = v.get(3).copied().unwrap_or(1.0);
    let magenta_ish = (v[0] + v[2]) / 2.0 > v[1] + 0.3;
    let rgb = if magenta_ish {
        [0.0, 1.0, 0.0]
    } else {
        [1.0, 0.0, 1.0]
    };
    serde_json::json!([rgb[0], rgb[1], rgb[2], alpha])
}

/// The comparison above can fail: (1) the metadata of one instance lies
/// about a folded colour (the library draw uses the lie, the specialised
/// shader what was folded); (2) one instance is drawn with another
/// instance's shader. Both change the picture beyond the threshold.
#[test]
fn a_wrong_folded_constant_or_shader_changes_the_picture() {
    let _gpu = weft_tests::gpu_serial();
    let mut h = harness();
    let materials: BTreeMap<String, weft_meta::MaterialMetadata> =
        weft_golden::materials(&generated())
            .unwrap()
            .into_iter()
            .map(|(_, m)| (m.name.clone(), m))
            .collect();
    for (name, scene) in scenes() {
        let specialised = render(&mut h, &name, &scene, &SceneShaders::Specialised);

        // (1) Every folded colour of one instance (one with a folded
        // `base_color` first) replaced in the metadata.
        let colours = |i: &weft_meta::scene::SceneInstance| -> Vec<String> {
            let m = &materials[&i.material];
            i.constants
                .keys()
                .filter(|k| {
                    m.parameters
                        .iter()
                        .any(|p| &p.name == *k && p.kind == ParamKind::Color)
                })
                .cloned()
                .collect()
        };
        let instances = &scene.metadata.instances;
        let target = instances
            .iter()
            .position(|i| colours(i).iter().any(|c| c == "base_color"))
            .or_else(|| instances.iter().position(|i| !colours(i).is_empty()))
            .unwrap_or_else(|| panic!("{name}: no instance has a folded colour to perturb"));
        let mut lying = scene.clone();
        let inst = &mut lying.metadata.instances[target];
        for c in colours(&instances[target]) {
            let v = contrasting(&inst.constants[&c]);
            inst.constants.insert(c, v);
        }
        let e = fold_error(&specialised, &render(&mut h, &name, &lying, &library()));
        println!(
            "{name}: instance `{}` with wrong folded colours in the metadata: FLIP mean {e:.5}",
            instances[target].name
        );
        assert!(
            e > FOLD_FLIP_MEAN_THRESHOLD,
            "{name}: a wrong folded colour of `{}` passes the fold comparison (FLIP mean {e:.5})",
            instances[target].name
        );

        // (2) The first instance drawn with the shader (and its values,
        // textures and passes) of the first instance whose shader differs.
        let Some(other) = instances
            .iter()
            .position(|i| i.shader != instances[0].shader)
        else {
            continue;
        };
        let mut swapped = scene.clone();
        let from = swapped.metadata.instances[other].clone();
        let inst = &mut swapped.metadata.instances[0];
        inst.shader = from.shader;
        inst.uniform_values = from.uniform_values;
        inst.textures = from.textures;
        inst.passes = from.passes;
        let generic = render(&mut h, &name, &scene, &library());
        let e = fold_error(
            &generic,
            &render(&mut h, &name, &swapped, &SceneShaders::Specialised),
        );
        println!(
            "{name}: `{}` drawn with the shader of `{}`: FLIP mean {e:.5}",
            instances[0].name, instances[other].name
        );
        assert!(
            e > FOLD_FLIP_MEAN_THRESHOLD,
            "{name}: drawing `{}` with the shader of `{}` passes the fold comparison (FLIP mean {e:.5})",
            instances[0].name,
            instances[other].name
        );
    }
}

/// Compares a scene render with its golden; on failure writes
/// `<golden>.actual.png` and `<golden>.diff.png` (FLIP error map) beside it.
fn compare_golden(name: &str, ldr: &[u8]) -> Result<f32, String> {
    let path = scene_golden_path(&repo().join("tests/goldens"), name);
    let (w, h) = SCENE_GOLDEN_SIZE;
    let (gw, gh, golden) =
        read_png(&path).map_err(|e| format!("{name}: no golden ({e}); run `cargo xtask bless`"))?;
    if (gw, gh) != (w, h) {
        return Err(format!(
            "{}: golden is {gw}x{gh}, expected {w}x{h}; run `cargo xtask bless`",
            path.display()
        ));
    }
    let result = flip(&golden, ldr, w, h);
    println!(
        "{name}: FLIP mean {:.5}, p99 {:.4} against its golden",
        result.mean, result.p99
    );
    if result.mean <= FLIP_MEAN_THRESHOLD {
        return Ok(result.mean);
    }
    let actual = path.with_extension("actual.png");
    let diff = path.with_extension("diff.png");
    write_png(&actual, w, h, ldr).unwrap();
    let diff_rgba: Vec<u8> = result
        .error_map_rgb
        .chunks_exact(3)
        .flat_map(|p| [p[0], p[1], p[2], 255])
        .collect();
    write_png(&diff, w, h, &diff_rgba).unwrap();
    Err(format!(
        "{name}: FLIP mean {:.4} > {FLIP_MEAN_THRESHOLD} (p99 {:.3}); wrote {} and {}",
        result.mean,
        result.p99,
        actual.display(),
        diff.display()
    ))
}

#[test]
fn every_scene_matches_its_golden() {
    let _gpu = weft_tests::gpu_serial();
    let mut h = harness();
    let scenes = scenes();
    let mut failures = Vec::new();
    for (name, scene) in &scenes {
        let ldr = render_golden(&mut h, scene).unwrap_or_else(|e| panic!("{name}: {e}"));
        if let Err(e) = compare_golden(name, &ldr) {
            failures.push(e);
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} scenes differ from their goldens:\n{}",
        failures.len(),
        scenes.len(),
        failures.join("\n")
    );
    // No golden of a scene that is gone (`cargo xtask bless` removes them).
    let mut goldens: Vec<String> = std::fs::read_dir(repo().join("tests/goldens/scenes"))
        .unwrap()
        .filter_map(|e| {
            let file = e.unwrap().file_name().into_string().ok()?;
            let stem = file.strip_suffix(".png")?;
            (!stem.ends_with(".actual") && !stem.ends_with(".diff")).then(|| stem.to_string())
        })
        .collect();
    goldens.sort();
    let names: Vec<String> = scenes.into_iter().map(|(n, _)| n).collect();
    assert_eq!(goldens, names, "tests/goldens/scenes/ and scenes/ differ");
}

/// Pixel of a world point seen by the camera.
fn project(camera: &weft_render::Camera, p: [f32; 3], (w, h): (u32, u32)) -> (u32, u32) {
    let clip = math::transform_point(&camera.view_proj(w as f32 / h as f32), p);
    let (x, y) = (clip[0] / clip[3], clip[1] / clip[3]);
    (
        ((x * 0.5 + 0.5) * w as f32) as u32,
        ((0.5 - y * 0.5) * h as f32) as u32,
    )
}

/// Every pipeline is built when a scene is prepared: drawing (twice) builds
/// none, with specialised or library shaders. Every instance draws each of
/// its passes at least once and covers the pixel its origin projects to.
#[test]
fn drawing_builds_no_pipeline_and_every_instance_draws() {
    let _gpu = weft_tests::gpu_serial();
    let mut h = harness();
    let size = (128, 96);
    let options = weft_golden::scenes::render_options(size, BLACK);
    for (name, scene) in scenes() {
        for shaders in [SceneShaders::Specialised, library()] {
            let r = h.renderer();
            let prepared = r
                .prepare_scene(&scene, &shaders, &options)
                .unwrap_or_else(|e| panic!("{name}: {e}"));
            let created = r.pipelines_created();
            let first = r.render_scene(&prepared, &options).unwrap();
            let second = r.render_scene(&prepared, &options).unwrap();
            assert_eq!(
                r.pipelines_created(),
                created,
                "{name} ({shaders:?}): a draw built a pipeline"
            );
            assert_eq!(
                first.pixels, second.pixels,
                "{name}: draws are deterministic"
            );

            let draws = prepared.draws();
            for inst in &scene.metadata.instances {
                for pass in &inst.passes {
                    assert!(
                        draws
                            .iter()
                            .any(|(i, p, n)| *i == inst.name && *p == pass.name && *n >= 1),
                        "{name} ({shaders:?}): instance `{}` pass `{}` is not drawn: {draws:?}",
                        inst.name,
                        pass.name
                    );
                }
                let t = inst.transform.translation.map(|x| x as f32);
                let (x, y) = project(prepared.camera(), t, size);
                assert!(
                    first.pixel(x, y)[3] > 0.0,
                    "{name} ({shaders:?}): instance `{}` not drawn at ({x}, {y})",
                    inst.name
                );
            }
        }
    }
}

/// Two builds of each shipped scene, on rayon pools of 1 and 4 threads (the
/// scene build has no `jobs` option: it runs on the pool it is called in),
/// give the same files byte for byte. The `auto` tiers are measured once
/// (the chooser caches its renders), so this compares the compiler's output.
#[test]
fn scene_builds_are_byte_deterministic() {
    let _gpu = weft_tests::gpu_serial();
    let chooser = weft_auto::LavapipeTierChooser::new(None)
        .unwrap()
        .with_reports_dir(generated().join("reports"));
    let options = weft_compiler::SceneBuildOptions {
        tier_chooser: Some(&chooser),
        ..Default::default()
    };
    let build = |path: &Path, threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| weft_compiler::build_scene(path, &options))
            .unwrap_or_else(|(db, d)| panic!("{}:\n{}", path.display(), d.render_plain(&db)))
    };
    let paths = weft_compiler::scene::discover_scenes(&repo().join("scenes")).unwrap();
    assert!(!paths.is_empty());
    for path in paths {
        let one = build(&path, 1);
        let four = build(&path, 4);
        let keys = |o: &weft_compiler::SceneOutput| o.files.keys().cloned().collect::<Vec<_>>();
        assert_eq!(keys(&one), keys(&four), "{}: file lists", one.name);
        for (k, v) in &one.files {
            assert!(four.files[k] == *v, "{k} differs between 1 and 4 threads");
        }
        assert_eq!(one.metadata, four.metadata);
    }
}

/// Every scene's metadata states the light weft draws it with (scene schema
/// 3.3): the manifest's `[light]`, else `weft_meta`'s default light, which
/// is the renderer's `Light::default()`; and the renderer draws with it.
#[test]
fn every_scene_states_the_light_it_is_drawn_with() {
    let _gpu = weft_tests::gpu_serial();
    use weft_meta::scene::{DEFAULT_LIGHT_COLOR, DEFAULT_LIGHT_DIRECTION};
    let default = weft_render::Light::default();
    assert_eq!(default.direction, DEFAULT_LIGHT_DIRECTION.map(|c| c as f32));
    assert_eq!(default.radiance, DEFAULT_LIGHT_COLOR.map(|c| c as f32));
    let mut defaulted = 0;
    for (name, scene) in scenes() {
        let meta = &scene.metadata;
        let light = meta
            .light
            .as_ref()
            .unwrap_or_else(|| panic!("{name}: no `light`"));
        let color = light
            .color
            .unwrap_or_else(|| panic!("{name}: no `light.color`"));
        let manifest =
            std::fs::read_to_string(repo().join(format!("scenes/{name}.scene.toml"))).unwrap();
        // Without `[light]` the default light — unless a `[gltf]` file
        // gives its own (docs/gltf.md).
        let own_light = |l: &str| l.trim() == "[light]" || l.trim() == "[gltf]";
        if !manifest.lines().any(own_light) {
            defaulted += 1;
            assert_eq!(light.direction, DEFAULT_LIGHT_DIRECTION, "{name}");
            assert_eq!(color, DEFAULT_LIGHT_COLOR, "{name}");
        }
        let drawn = scene.lighting.light;
        assert_eq!(drawn.direction, light.direction.map(|c| c as f32), "{name}");
        if meta.features.directional_lights > 0 {
            assert_eq!(drawn.radiance, color.map(|c| c as f32), "{name}");
        }
    }
    assert!(
        defaulted > 0,
        "no shipped scene exercises the default light"
    );
}

/// `[static_lighting]` (docs/scenes.md): a scene that states it holds its
/// light and SH in every shader. The shipped ones state the SH of the sky
/// the renderer binds, bit for bit, and the renderer uploads those; their
/// shaders read neither the frame's light nor its SH (drawn with another
/// light and black SH, the picture does not move by one bit), while the
/// generic variants, which still read the frame, do change; and a scene
/// without it still reads both.
#[test]
fn static_lighting_is_folded_into_the_shaders() {
    let _gpu = weft_tests::gpu_serial();
    let sky = weft_render::EnvironmentMaps::sky(&weft_render::SkyParams::default()).sh;
    let frame_reads = |scene: &SceneFile| -> Vec<String> {
        let mut reads = Vec::new();
        for shader in &scene.metadata.shaders {
            let wgsl = std::fs::read_to_string(scene.dir.join(format!("{}.wgsl", shader.id)))
                .unwrap_or_else(|e| panic!("{}: {e}", shader.id));
            for member in ["light_direction", "light_color", "sh"] {
                if wgsl.contains(&format!("weft_frame.{member};"))
                    || wgsl.contains(&format!("weft_frame.{member}."))
                    || wgsl.contains(&format!("weft_frame.{member}["))
                {
                    reads.push(format!("{} reads weft_frame.{member}", shader.id));
                }
            }
        }
        reads
    };
    let mut h = harness();
    let (mut fixed, mut dynamic) = (0, 0);
    for (name, scene) in scenes() {
        let Some(lighting) = &scene.metadata.static_lighting else {
            dynamic += 1;
            assert!(
                !frame_reads(&scene).is_empty(),
                "{name}: lit at run time, yet no shader reads the frame's light or SH"
            );
            continue;
        };
        fixed += 1;
        let sh = lighting.sh.unwrap_or_else(|| panic!("{name}: no `sh`"));
        assert_eq!(
            sh.map(|rgb| rgb.map(|c| c as f32)),
            sky,
            "{name}: `[static_lighting] sh` is not the default sky's SH"
        );
        assert_eq!(scene.lighting.static_sh, Some(sky), "{name}");
        assert_eq!(frame_reads(&scene), Vec::<String>::new(), "{name}");

        let mut moved = scene.clone();
        moved.lighting.light.direction = [0.3, -0.8, 0.5];
        moved.lighting.light.radiance = [0.5, 2.0, 9.0];
        moved.lighting.static_sh = Some([[0.0; 3]; 9]);
        let folded = render(&mut h, &name, &scene, &SceneShaders::Specialised);
        let folded_moved = render(&mut h, &name, &moved, &SceneShaders::Specialised);
        assert!(
            folded.pixels == folded_moved.pixels,
            "{name}: the specialised shaders still read the frame's light or SH"
        );
        let generic = render(&mut h, &name, &scene, &library());
        let generic_moved = render(&mut h, &name, &moved, &library());
        assert!(
            fold_error(&generic, &generic_moved) > 0.05,
            "{name}: the generic variants ignore the moved light and SH"
        );
    }
    assert!(
        fixed > 0 && dynamic > 0,
        "{fixed} static, {dynamic} dynamic"
    );
}
