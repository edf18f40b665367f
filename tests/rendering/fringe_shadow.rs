//! The fringe shadow pass (`materials/lib/fringe_shadow.pass.toml`, seed 004
//! §8) and the stencil state it needs, drawn as a scene: a stand-in face
//! (`tests/fixtures/materials/stencil_face`: unlit, its `mark` pass sets
//! stencil bit 0 on the upper half of a sphere) behind a small sphere drawn
//! with the hair material, built from a materials root made of the fixture,
//! `materials/hair` and `materials/lib`.
//!
//! The shadow is what changes between the hair with `FRINGE_SHADOW` on and
//! off: it must fall only where the bit is set (the lower half of the face
//! stays as it was though the pushed hair covers it too), on the side away
//! from the light, multiplied once by the tint where the pushed sphere's
//! front and back faces overlap (the pass draws both faces), and with the
//! keyword off the pass does not exist and nothing is drawn.

use std::path::Path;
use weft_golden::scenes::SceneHarness;
use weft_render::{Background, HdrImage, SceneFile, SceneShaders};
use weft_tests::{copy_dir, repo};

const SIZE: u32 = 128;
/// The fixture's unlit colours: the whole face, then the marked (stencil) half.
const FACE: f32 = 0.25;
const MARKED: f32 = 0.5;
/// The shadow tint, linear (written as sRGB 0.5 in the scene).
const TINT_SRGB: f64 = 0.5;
const BACKGROUND: [f32; 4] = [0.0, 0.0, 1.0, 1.0];

fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// Builds the face + hair scene with `FRINGE_SHADOW` `on`/`off` into a
/// temporary folder and loads it.
fn scene(fringe: bool, dir: &Path) -> SceneFile {
    let root = dir.join("materials");
    copy_dir(&repo().join("materials/lib"), &root.join("lib"));
    copy_dir(&repo().join("materials/hair"), &root.join("hair"));
    copy_dir(
        &repo().join("tests/fixtures/materials/stencil_face"),
        &root.join("stencil_face"),
    );
    let manifest = format!(
        r#"[scene]
name = "fringe"
materials = "materials"
environment = false
sh_ambient = false
directional_lights = 1
vertex_inputs = ["position", "normal", "tangent", "uv0"]

[camera]
position = [0.0, 0.0, 6.0]
target = [0.0, 0.0, 0.0]
fov_degrees = 30.0

[[instances]]
name = "face"
material = "stencil_face"
mesh = "sphere"

[[instances]]
name = "fringe"
material = "hair"
mesh = "sphere"
translation = [0.0, 0.0, 1.4]
scale = 0.3
keywords = {{ FRINGE_SHADOW = {fringe} }}
# The jitter map folded to black: this scene is built outside the library,
# and the shipped jitter file is not what the test is about.
params = {{ fringe_shadow_color = [{TINT_SRGB}, {TINT_SRGB}, {TINT_SRGB}], fringe_shadow_length = 0.4, jitter_map = "black" }}
"#
    );
    let path = dir.join("fringe.scene.toml");
    std::fs::write(&path, manifest).unwrap();
    let out = weft_compiler::build_scene(&path, &Default::default())
        .unwrap_or_else(|(db, d)| panic!("{}", d.render_plain(&db)));
    let built = dir.join("out");
    for (name, bytes) in &out.files {
        let p = built.join(name);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, bytes).unwrap();
    }
    SceneFile::load(built.join("fringe/fringe.scene.json")).unwrap()
}

/// Draws the scene lit from `light` (towards the light).
fn draw(h: &mut SceneHarness, scene: &SceneFile, light: [f32; 3]) -> HdrImage {
    let mut scene = scene.clone();
    scene.lighting.light.direction = light;
    h.render(
        &scene,
        &SceneShaders::Specialised,
        (SIZE, SIZE),
        Background::Color(BACKGROUND),
    )
    .expect("render")
}

fn is_grey(p: [f32; 4], v: f32) -> bool {
    (0..3).all(|c| (p[c] - v).abs() < 2e-3)
}

/// Pixels the shadow changed: (index, on / off ratio of the red channel).
fn shadowed(on: &HdrImage, off: &HdrImage) -> Vec<(usize, f32)> {
    on.pixels
        .iter()
        .zip(&off.pixels)
        .enumerate()
        .filter(|(_, (a, b))| (0..3).any(|c| (a[c] - b[c]).abs() > 1e-3))
        .map(|(i, (a, b))| (i, a[0] / b[0].max(1e-6)))
        .collect()
}

struct Pictures {
    off: HdrImage,
    on: HdrImage,
}

fn pictures(light: [f32; 3]) -> (Pictures, SceneFile, SceneFile) {
    let dir_on = tempfile::tempdir().unwrap();
    let dir_off = tempfile::tempdir().unwrap();
    let on_scene = scene(true, dir_on.path());
    let off_scene = scene(false, dir_off.path());
    let mut h = SceneHarness::new(&repo().join("generated")).expect("a Vulkan adapter");
    let p = Pictures {
        off: draw(&mut h, &off_scene, light),
        on: draw(&mut h, &on_scene, light),
    };
    (p, on_scene, off_scene)
}

/// Light from the viewer's left (towards the light: -x, a little towards the camera).
const FROM_LEFT: [f32; 3] = [-1.0, 0.0, 0.4];
const FROM_RIGHT: [f32; 3] = [1.0, 0.0, 0.4];

#[test]
fn the_shadow_falls_only_on_the_stencil_bit_darkens_once_and_moves_with_the_light() {
    let _gpu = weft_tests::gpu_serial();
    let (left, on_scene, off_scene) = pictures(FROM_LEFT);
    let (right, _, _) = pictures(FROM_RIGHT);

    let tint = srgb_to_linear(TINT_SRGB) as f32;
    let mut centroids = Vec::new();
    for (what, p) in [
        ("light from the left", &left),
        ("light from the right", &right),
    ] {
        // With the keyword off nothing is drawn: the marked half keeps the
        // fixture's colour wherever the hair does not cover it.
        let marked: Vec<usize> = (0..p.off.pixels.len())
            .filter(|&i| is_grey(p.off.pixels[i], MARKED))
            .collect();
        let unmarked: Vec<usize> = (0..p.off.pixels.len())
            .filter(|&i| is_grey(p.off.pixels[i], FACE))
            .collect();
        assert!(
            marked.len() > 1000 && unmarked.len() > 1000,
            "{what}: {} marked and {} unmarked face pixels",
            marked.len(),
            unmarked.len()
        );
        // Outside the hair's disc (radius ~16 px at the centre) the off
        // picture is the fixture's colours or the background, nothing else.
        let c = f64::from(SIZE) / 2.0;
        let stray = (0..p.off.pixels.len())
            .filter(|&i| {
                let (x, y) = (
                    (i % SIZE as usize) as f64 + 0.5,
                    (i / SIZE as usize) as f64 + 0.5,
                );
                let px = p.off.pixels[i];
                (x - c).hypot(y - c) > 20.0
                    && !(is_grey(px, FACE) || is_grey(px, MARKED) || px == BACKGROUND)
            })
            .count();
        assert_eq!(stray, 0, "{what}: FRINGE_SHADOW off changed {stray} pixels");
        let shadow = shadowed(&p.on, &p.off);
        assert!(
            shadow.len() > 40,
            "{what}: only {} shadowed pixels",
            shadow.len()
        );
        // Only where the stencil bit is set: the pushed hair covers the
        // lower (unmarked) half as much as the upper.
        let outside = shadow
            .iter()
            .filter(|(i, _)| !is_grey(p.off.pixels[*i], MARKED))
            .count();
        assert_eq!(
            outside, 0,
            "{what}: {outside} shadowed pixels outside the face's stencil bit"
        );
        // Once: the pushed sphere's front and back faces both cover each
        // shadowed pixel, and the tint is applied a single time.
        let worst = shadow
            .iter()
            .map(|(_, r)| (r - tint).abs())
            .fold(0.0f32, f32::max);
        assert!(
            worst < 5e-3,
            "{what}: shadowed / unshadowed deviates from the tint {tint} by up to {worst} (tint² = {})",
            tint * tint
        );
        let mean_x = shadow
            .iter()
            .map(|(i, _)| (i % SIZE as usize) as f64)
            .sum::<f64>()
            / shadow.len() as f64;
        centroids.push(mean_x);
    }
    // Away from the light: right of the hair (the image centre) when lit
    // from the left, left of it when lit from the right.
    let centre = f64::from(SIZE) / 2.0;
    assert!(
        centroids[0] > centre + 4.0 && centroids[1] < centre - 4.0,
        "shadow centroids (x): light from the left {:.1}, from the right {:.1}, hair at {centre}",
        centroids[0],
        centroids[1]
    );
    // The pass exists exactly with the keyword on, after the face and
    // before the hair's own pass.
    let passes = |s: &SceneFile| -> Vec<(String, i64)> {
        s.metadata.instances[1]
            .passes
            .iter()
            .map(|p| (p.name.clone(), p.render_state.queue))
            .collect()
    };
    let on_passes = passes(&on_scene);
    assert!(
        on_passes.contains(&("fringe_shadow".into(), 2005)),
        "{on_passes:?}"
    );
    assert!(
        !passes(&off_scene).iter().any(|(n, _)| n == "fringe_shadow"),
        "{:?}",
        passes(&off_scene)
    );
    let face_queue = off_scene.metadata.instances[0].passes[1].render_state.queue;
    let hair_queue = on_passes.iter().find(|(n, _)| n == "forward").unwrap().1;
    assert!(face_queue < 2005 && 2005 < hair_queue);
}
