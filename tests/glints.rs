//! Glint tests (issue 11, glitter): the four properties a glint model must
//! have, rendered on lavapipe from the committed `generated/glitter/` files.
//!
//! - Energy: over a large footprint (the whole sphere) the glints reflect
//!   what the smooth flake lobe does — the glint NDF's mean is the target
//!   NDF (`smooth` tier: E[D_glint] = GGX).
//! - No NaN, Inf or negative output at grazing view and light and at the
//!   extremes of density, size, twinkle and variation (f32 target).
//! - Temporal stability: a half-pixel camera shift of a static scene changes
//!   the picture by little (glints are anchored in uv, on cells at least
//!   half a pixel wide), measured as FLIP between the two frames.
//! - No aliasing at distance: a far sphere (a few uv cells per pixel) drawn
//!   at 1x matches the same view supersampled 4x4 and box-filtered.
//!
//! Each bound is stated with the reason for its number at its constant.

use std::path::{Path, PathBuf};
use weft_golden::shading::image_error;
use weft_render::{
    Background, ColorFormat, EnvironmentMaps, Gpu, HdrImage, Luts, Material, PreviewOptions,
    RenderOptions, Renderer, Scene, SceneKind, math,
};

fn generated() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated")
}

fn meta_path() -> PathBuf {
    generated().join("glitter/glitter.meta.json")
}

fn renderer() -> Renderer {
    let luts = Luts::load_dir(generated()).expect("generated/ LUTs");
    let gpu = Gpu::new().unwrap_or_else(|e| panic!("glint tests need a Vulkan adapter: {e}"));
    let env = EnvironmentMaps::sky(&PreviewOptions::default().sky_params());
    Renderer::new(gpu, &env, &luts).expect("renderer")
}

fn material(tier: &str, values: &[(&str, &str)]) -> Material {
    let mut m = Material::load(meta_path()).expect("glitter metadata");
    m.set_tier(tier).expect("tier");
    for (name, value) in values {
        m.set_from_str(name, value)
            .unwrap_or_else(|e| panic!("{name} = {value}: {e}"));
    }
    m
}

fn options(size: u32) -> RenderOptions {
    RenderOptions {
        width: size,
        height: size,
        format: ColorFormat::Rgba32Float,
        background: Background::Color([0.0; 4]),
        ..RenderOptions::default()
    }
}

fn render(r: &mut Renderer, m: &Material, scene: &Scene, size: u32) -> HdrImage {
    r.render(m, scene, &options(size)).expect("render")
}

/// Sum of r + g + b over the image (linear radiance).
fn energy(img: &HdrImage) -> f64 {
    img.pixels
        .iter()
        .map(|p| f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2]))
        .sum()
}

/// `camera` moved along its right axis by `pixels` pixels of a `size`-pixel
/// image, measured at the target's distance (eye and target translate
/// together: a pure sub-pixel pan of the static scene).
fn shift_camera(scene: &Scene, pixels: f32, size: u32) -> Scene {
    let mut s = scene.clone();
    let c = s.camera;
    let forward = math::sub(c.target, c.eye);
    let distance = math::length(forward);
    let right = math::normalize(math::cross(forward, c.up));
    let pixel = 2.0 * distance * (c.fov_y_degrees.to_radians() * 0.5).tan() / size as f32;
    let d = math::scale(right, pixels * pixel);
    s.camera.eye = math::add(c.eye, d);
    s.camera.target = math::add(c.target, d);
    s
}

/// `scene` seen from `factor` times as far (same target and field of view).
fn far(scene: &Scene, factor: f32) -> Scene {
    let mut s = scene.clone();
    let c = s.camera;
    s.camera.eye = math::add(c.target, math::scale(math::sub(c.eye, c.target), factor));
    s
}

/// Box filter of `k` x `k` pixel blocks (linear radiance).
fn downsample(img: &HdrImage, k: u32) -> HdrImage {
    let (w, h) = (img.width / k, img.height / k);
    let mut pixels = Vec::with_capacity((w * h) as usize);
    for y in 0..h {
        for x in 0..w {
            let mut acc = [0.0f64; 4];
            for j in 0..k {
                for i in 0..k {
                    let p = img.pixel(x * k + i, y * k + j);
                    for c in 0..4 {
                        acc[c] += f64::from(p[c]);
                    }
                }
            }
            let n = f64::from(k * k);
            pixels.push(acc.map(|a| (a / n) as f32));
        }
    }
    HdrImage {
        width: w,
        height: h,
        pixels,
    }
}

/// Glints only: the render minus the same render with the flakes off (the
/// flakes are added on top of the base, so the difference is exact).
fn glint_energy(r: &mut Renderer, tier: &str, values: &[(&str, &str)], scene: &Scene) -> f64 {
    let with = render(r, &material(tier, values), scene, 256);
    let mut off: Vec<(&str, &str)> = values.to_vec();
    off.push(("flake_intensity", "0"));
    let without = render(r, &material(tier, &off), scene, 256);
    energy(&with) - energy(&without)
}

/// Energy of the glints over the object against the smooth lobe's, as a
/// relative difference. Bound: 10 %, and 1 % for dense flakes. The binomial count's expectation is
/// the target NDF exactly, but the paper's estimator floors the Gaussian
/// count (about -0.5 hit per reflecting cell, a bias that shrinks as the
/// count grows) and clamps a footprint at 20 D_max (rare bright cells); 10 %
/// is the visible-difference scale of a highlight's brightness and leaves
/// room over the measured figures (printed) without hiding a lost grid (a
/// missing quarter of the four grids' weight would be -25 %).
const MAX_ENERGY_ERROR: f64 = 0.10;
/// With dense flakes (density 0.9: ~10^7 flakes per cell on the sphere) the binomial
/// count is large, the floor's bias is relatively nil and no footprint
/// reaches the clamp: the glint NDF must then be the smooth one to 1 %
/// (measured: within 0.1 %).
const MAX_DENSE_ENERGY_ERROR: f64 = 0.01;

#[test]
fn glint_energy_converges_to_the_smooth_lobe() {
    let mut r = renderer();
    let mut failures = Vec::new();
    // Black metal base (F0 = 0): the flakes alone; defaults, dense flakes,
    // and the presets' spread of sizes and twinkle.
    let base = [("base_color", "0,0,0,1"), ("metallic", "1")];
    let cases: [(&str, &[(&str, &str)]); 4] = [
        ("defaults", &[]),
        ("dense", &[("flake_density", "0.9")]),
        (
            "large steady flakes",
            &[
                ("flake_size", "8"),
                ("twinkle", "0.2"),
                ("flake_density", "0.6"),
            ],
        ),
        (
            "small twinkling flakes",
            &[
                ("flake_size", "1.5"),
                ("twinkle", "0.8"),
                ("flake_density", "0.7"),
            ],
        ),
    ];
    for kind in [SceneKind::Sphere, SceneKind::Cloth] {
        let scene = Scene::new(kind);
        for (name, extra) in cases {
            let values: Vec<(&str, &str)> = base.iter().chain(extra.iter()).copied().collect();
            let smooth = glint_energy(&mut r, "smooth", &values, &scene);
            assert!(smooth > 0.0, "{name}: the smooth lobe reflects nothing");
            for tier in ["reference", "fast"] {
                let glints = glint_energy(&mut r, tier, &values, &scene);
                let rel = glints / smooth - 1.0;
                println!(
                    "{}/{name}/{tier}: glint energy {glints:.1} vs smooth {smooth:.1}: {:+.2} %",
                    kind.name(),
                    rel * 100.0
                );
                let bound = if name == "dense" {
                    MAX_DENSE_ENERGY_ERROR
                } else {
                    MAX_ENERGY_ERROR
                };
                if rel.abs() > bound {
                    failures.push(format!(
                        "{}/{name}/{tier}: {:+.2} %",
                        kind.name(),
                        rel * 100.0
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "energy beyond its bound: {failures:?}");
}

#[test]
fn no_nan_at_grazing_and_density_extremes() {
    let mut r = renderer();
    // A swatch seen edge-on (about 1 degree) under a grazing light, the
    // sphere (its silhouette is grazing) and the cloth.
    let mut grazing = Scene::new(SceneKind::Swatch);
    grazing.camera.eye = [0.0, 3.4, 0.06];
    grazing.camera.up = [0.0, 0.0, -1.0];
    grazing.light.direction = math::normalize([0.3, 1.0, 0.01]);
    let mut grazing_light = Scene::new(SceneKind::Sphere);
    grazing_light.light.direction = math::normalize([0.0, 0.0, -1.0]);
    let scenes = [
        ("grazing swatch", grazing),
        ("sphere", Scene::new(SceneKind::Sphere)),
        ("sphere lit from behind", grazing_light),
        ("cloth", Scene::new(SceneKind::Cloth)),
    ];
    let extremes: [&[(&str, &str)]; 4] = [
        &[
            ("flake_density", "0"),
            ("density_variation", "0"),
            ("twinkle", "0"),
            ("flake_size", "1"),
            ("flake_roughness", "0.05"),
        ],
        &[
            ("flake_density", "1"),
            ("density_variation", "4"),
            ("twinkle", "1"),
            ("flake_size", "8"),
            ("flake_roughness", "1"),
        ],
        &[
            ("flake_density", "0"),
            ("density_variation", "4"),
            ("twinkle", "1"),
            ("flake_size", "1"),
            ("flake_intensity", "10"),
        ],
        &[
            ("flake_density", "1"),
            ("density_variation", "0"),
            ("twinkle", "0"),
            ("flake_size", "8"),
            ("flake_roughness", "0.05"),
            ("flake_intensity", "10"),
        ],
    ];
    let mut checked = 0;
    for (scene_name, scene) in &scenes {
        for (i, values) in extremes.iter().enumerate() {
            for tier in ["reference", "fast", "smooth"] {
                let img = render(&mut r, &material(tier, values), scene, 128);
                let bad = img
                    .pixels
                    .iter()
                    .filter(|p| p.iter().any(|c| !c.is_finite() || *c < 0.0 || *c > 65504.0))
                    .count();
                assert_eq!(
                    bad, 0,
                    "{scene_name}, extreme {i}, {tier}: {bad} bad pixels"
                );
                checked += 1;
            }
        }
    }
    // The grazing swatch must actually show glints (the test looks at
    // something): some pixel of the lit extremes is non-zero.
    let img = render(
        &mut r,
        &material("reference", extremes[1]),
        &scenes[0].1,
        128,
    );
    assert!(energy(&img) > 0.0, "the grazing swatch drew nothing");
    println!("{checked} renders, every pixel finite, non-negative and <= 65504");
}

/// The half-pixel pan, three checks on the object's pixels:
///
/// 1. The whole surface does not flicker: its mean radiance changes by at
///    most 1 % between the frames (measured within 0.35 %; a level-of-detail
///    pop across the surface would shift it).
/// 2. Frame-to-frame FLIP at the defaults <= 0.20 (measured 0.127 sphere,
///    0.100 cloth; the `smooth` tier, i.e. the half-pixel resampling of
///    edges and shading alone, measures 0.033 and 0.053).
/// 3. Sparkles are anchored to the surface: with steady flakes (twinkle 0,
///    sparkle size 8) the pan's FLIP is at most 0.6 x that of the same frame
///    against a fully redrawn pattern (every uv cell moved by an offset of
///    the uv transform: same statistics, other flakes); measured 0.37 on
///    the sphere. A pattern hashed from screen position would score ~1.
///
/// What is not claimed: at the default twinkle the individual sparkles are
/// largely redrawn by a half-pixel pan (0.56 x a redrawn pattern on the
/// sphere, 0.88 x on the cloth, printed; README "Limits"): the slope cells
/// are a few thousandths of a radian wide and the normal a pixel sees turns
/// by that much across half a pixel of a curved surface, so each sparkle is
/// about a pixel across on screen and point sampling resamples it.
const MAX_SHIFT_MEAN_CHANGE: f64 = 0.01;
const MAX_SHIFT_FLIP: f64 = 0.20;
const MAX_ANCHORED_RATIO: f64 = 0.6;

/// Mean of r + g + b over the pixels the object covers (non-zero alpha or
/// colour; the background is cleared to zero).
fn object_mean(img: &HdrImage) -> f64 {
    let covered: Vec<&[f32; 4]> = img.pixels.iter().filter(|p| **p != [0.0; 4]).collect();
    covered
        .iter()
        .map(|p| f64::from(p[0]) + f64::from(p[1]) + f64::from(p[2]))
        .sum::<f64>()
        / covered.len().max(1) as f64
}

#[test]
fn a_half_pixel_camera_shift_does_not_make_the_surface_flicker() {
    let mut r = renderer();
    let size = 256;
    let mut failures = Vec::new();
    for kind in [SceneKind::Sphere, SceneKind::Cloth] {
        let scene = Scene::new(kind);
        let shifted = shift_camera(&scene, 0.5, size);
        for tier in ["reference", "fast", "smooth"] {
            let m = material(tier, &[]);
            let a = render(&mut r, &m, &scene, size);
            let b = render(&mut r, &m, &shifted, size);
            let e = image_error(&a, &b).flip_mean;
            let change = object_mean(&b) / object_mean(&a) - 1.0;
            println!(
                "{}/{tier}: half-pixel shift FLIP {e:.4}, mean radiance {:+.3} %",
                kind.name(),
                change * 100.0
            );
            if e > MAX_SHIFT_FLIP {
                failures.push(format!("{}/{tier}: FLIP {e:.4}", kind.name()));
            }
            if change.abs() > MAX_SHIFT_MEAN_CHANGE {
                failures.push(format!(
                    "{}/{tier}: mean {:+.3} %",
                    kind.name(),
                    change * 100.0
                ));
            }
            if tier == "reference" {
                // For the record (README, "Limits"): the pan against a fully
                // redrawn pattern at the defaults.
                let mut redrawn = m.clone();
                redrawn
                    .set_tiling("base_map", [1.0, 1.0, 0.37, 0.21])
                    .expect("uv offset");
                let u = image_error(&a, &render(&mut r, &redrawn, &scene, size)).flip_mean;
                println!(
                    "{}/{tier}: redrawn pattern FLIP {u:.4}, pan / redrawn {:.2}",
                    kind.name(),
                    e / u
                );
            }
        }
    }
    // Anchoring, with steady flakes on the sphere.
    let scene = Scene::new(SceneKind::Sphere);
    let shifted = shift_camera(&scene, 0.5, size);
    let steady = material("reference", &[("twinkle", "0"), ("flake_size", "8")]);
    let mut redrawn = steady.clone();
    redrawn
        .set_tiling("base_map", [1.0, 1.0, 0.37, 0.21])
        .expect("uv offset");
    let a = render(&mut r, &steady, &scene, size);
    let pan = image_error(&a, &render(&mut r, &steady, &shifted, size)).flip_mean;
    let unrelated = image_error(&a, &render(&mut r, &redrawn, &scene, size)).flip_mean;
    println!(
        "sphere, steady flakes: pan FLIP {pan:.4}, redrawn pattern {unrelated:.4}, ratio {:.2}",
        pan / unrelated
    );
    if pan > MAX_ANCHORED_RATIO * unrelated {
        failures.push(format!(
            "steady flakes: pan {pan:.4} vs redrawn {unrelated:.4}"
        ));
    }
    assert!(failures.is_empty(), "flicker: {failures:?}");
}

/// FLIP between a far object (3x the distance) drawn at 1x and the same
/// view drawn at 4x4 the resolution and box-filtered, over the object's
/// pixels. The supersampled render averages 16 footprints a quarter the
/// size: the per-pixel integral of the glint NDF that an anti-aliased 1x
/// render estimates; residual differences are the 1x render's own sparkles
/// (a sample of the binomial law, not its mean). Bounds: FLIP <= 0.12
/// (measured 0.092 sphere, 0.054 cloth), and at most 0.75 x the figure of
/// the aliasing end of the panel (sparkle size 1: cells half a pixel wide,
/// point-sampled; measured 0.172 sphere, 0.097 cloth), so the test fails
/// if the footprint-adapted grids stop filtering.
const MAX_DISTANT_FLIP: f64 = 0.12;
const MAX_DISTANT_RATIO: f64 = 0.75;

#[test]
fn distant_glitter_does_not_alias_into_noise() {
    let mut r = renderer();
    let size = 128;
    let k = 4;
    let mut failures = Vec::new();
    for kind in [SceneKind::Sphere, SceneKind::Cloth] {
        let scene = far(&Scene::new(kind), 3.0);
        let mut distant = |m: &Material| {
            let direct = render(&mut r, m, &scene, size);
            let supersampled = downsample(&render(&mut r, m, &scene, size * k), k);
            image_error(&supersampled, &direct).flip_mean
        };
        let aliasing = distant(&material("reference", &[("flake_size", "1")]));
        println!(
            "{}: sparkle size 1 (aliasing end) FLIP {aliasing:.4}",
            kind.name()
        );
        for tier in ["reference", "fast"] {
            let e = distant(&material(tier, &[]));
            println!(
                "{}/{tier}: distant 1x vs 4x4 supersampled FLIP {e:.4}",
                kind.name()
            );
            if e > MAX_DISTANT_FLIP || e > MAX_DISTANT_RATIO * aliasing {
                failures.push(format!(
                    "{}/{tier}: {e:.4} (aliasing end {aliasing:.4})",
                    kind.name()
                ));
            }
        }
    }
    assert!(failures.is_empty(), "distant glitter: {failures:?}");
}
