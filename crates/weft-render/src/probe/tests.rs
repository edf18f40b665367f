//! Half-precision classification, the cases' cosines and the quads'
//! winding.

use super::cases::case_scene;
use super::*;
use crate::math;

#[test]
fn half_precision_outputs_are_held_against_their_f32_fallback() {
    use super::{BadKind, VISIBLE, classify_half};
    assert_eq!(classify_half(65504.0, 7e4), None); // both saturate
    assert_eq!(classify_half(65504.0, 1.2e3), Some(BadKind::HalfOverflow));
    assert_eq!(
        classify_half(f32::INFINITY, 10.0),
        Some(BadKind::HalfOverflow)
    );
    assert_eq!(classify_half(0.0, VISIBLE), Some(BadKind::HalfUnderflow));
    assert_eq!(classify_half(0.0, VISIBLE * 0.5), None); // invisible either way
    assert_eq!(classify_half(0.2, 0.2001), None); // rounding is not a failure
}

#[test]
fn cases_have_the_cosines_they_are_named_after() {
    let cases = geometric_cases();
    let find = |name: &str| cases.iter().find(|c| c.name == name).unwrap();
    let c = find("N.V=1e-4 N.L=-0.5 mirror");
    assert!((c.n_dot_v() - 1e-4).abs() < 1e-7);
    assert!((c.n_dot_l() + 0.5).abs() < 1e-6);
    let c = find("L=-V N.V=0");
    assert_eq!(math::add(c.view, c.light), [0.0; 3]);
    let c = find("H parallel to T, V and L in the T-B plane");
    let h = math::normalize(math::add(c.view, c.light));
    assert_eq!(h, [1.0, 0.0, 0.0]);
    for c in &cases {
        assert!((math::length(c.view) - 1.0).abs() < 1e-6, "{}", c.name);
        assert!((math::length(c.light) - 1.0).abs() < 1e-6, "{}", c.name);
    }
}

#[test]
fn quads_face_the_camera_counter_clockwise() {
    for c in geometric_cases() {
        let s = case_scene(&c, [1.0; 3]);
        let vp = s.camera.view_proj(1.0);
        let ndc: Vec<[f32; 2]> = s.mesh.positions[..3]
            .iter()
            .map(|p| {
                let q = math::transform_point(&vp, *p);
                [q[0] / q[3], q[1] / q[3]]
            })
            .collect();
        let (a, b, d) = (ndc[0], ndc[1], ndc[2]);
        let area = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
        assert!(area > 0.0, "{}: clockwise", c.name);
        // The quad over-fills the viewport ([-1, 1]) on every side.
        assert!(
            a[0] < -1.2 && a[1] < -1.2 && d[0] > 1.2 && d[1] > 1.2,
            "{}: {ndc:?}",
            c.name
        );
    }
}
