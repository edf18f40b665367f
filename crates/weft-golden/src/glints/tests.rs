//! The image helpers and the energy bound of the dense case.

use super::images::{downsample, shift_camera};
use super::*;
use weft_render::{HdrImage, Scene, SceneKind, math};

#[test]
fn downsampling_averages_blocks() {
    let img = HdrImage {
        width: 2,
        height: 2,
        pixels: vec![
            [1.0, 0.0, 0.0, 1.0],
            [3.0, 0.0, 0.0, 1.0],
            [0.0, 4.0, 0.0, 1.0],
            [0.0, 0.0, 8.0, 1.0],
        ],
    };
    let d = downsample(&img, 2);
    assert_eq!((d.width, d.height), (1, 1));
    assert_eq!(d.pixels[0], [1.0, 1.0, 2.0, 1.0]);
}

#[test]
fn a_half_pixel_pan_moves_eye_and_target_together() {
    let scene = Scene::new(SceneKind::Sphere);
    let s = shift_camera(&scene, 0.5, 256);
    let d_eye = math::sub(s.camera.eye, scene.camera.eye);
    let d_target = math::sub(s.camera.target, scene.camera.target);
    assert_eq!(d_eye, d_target);
    let c = scene.camera;
    let pixel =
        2.0 * math::length(math::sub(c.target, c.eye)) * (c.fov_y_degrees.to_radians() * 0.5).tan()
            / 256.0;
    assert!((math::length(d_eye) - 0.5 * pixel).abs() < 1e-6 * pixel.max(1.0));
}

#[test]
fn the_dense_case_has_the_tight_bound() {
    let row = |case: &'static str, glints: f64| EnergyRow {
        scene: SceneKind::Sphere,
        case,
        tier: "reference".into(),
        glints,
        smooth: 100.0,
    };
    assert!(row("defaults", 105.0).within_bound());
    assert!(!row("dense", 105.0).within_bound());
    assert!(row("dense", 100.5).within_bound());
    assert!(!row("defaults", 75.0).within_bound(), "a lost grid");
}
