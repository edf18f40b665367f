//! The bust's head surface in f64, from `weft_render`'s constants and the
//! same formulas as `bust.rs` (a test checks it against the mesh's vertices):
//! the point, its frame and curvature at (θ, φ) or at a head uv.

use super::math::{cos, sin};
use std::f64::consts::PI;
use weft_render::{HEAD_CENTRE, HEAD_JAW, HEAD_RADII};

pub type V3 = [f64; 3];

pub fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub fn add(a: V3, b: V3) -> V3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
pub fn scale(a: V3, s: f64) -> V3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
pub fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
pub fn normalize(a: V3) -> V3 {
    scale(a, 1.0 / dot(a, a).sqrt())
}

/// (θ, φ) of a head uv (u = 0.5 + φ/π, v = θ/π).
pub fn angles(u: f64, v: f64) -> (f64, f64) {
    (v * PI, (u - 0.5) * PI)
}

/// The head's point at (θ from +Y, φ from +Z towards +X), as `bust.rs`'s
/// `ellipsoid(HEAD_CENTRE, head_radii(θ), θ, φ)`.
pub fn point(theta: f64, phi: f64) -> V3 {
    let c = HEAD_CENTRE.map(f64::from);
    let below = (-cos(theta)).max(0.0);
    let r = [
        f64::from(HEAD_RADII[0]) * (1.0 - f64::from(HEAD_JAW[0]) * below * below),
        f64::from(HEAD_RADII[1]),
        f64::from(HEAD_RADII[2]) * (1.0 - f64::from(HEAD_JAW[1]) * below * below),
    ];
    let (st, ct) = (sin(theta), cos(theta));
    let (sp, cp) = (sin(phi), cos(phi));
    [
        c[0] + r[0] * st * sp,
        c[1] + r[1] * ct,
        c[2] + r[2] * st * cp,
    ]
}

/// Step of the central differences below (θ, φ in radians): small enough
/// for 1e−8 truncation, large enough that f64 round-off stays below 1e−7.
const H: f64 = 1e-4;

/// ∂P/∂θ and ∂P/∂φ by central differences.
pub fn tangents(theta: f64, phi: f64) -> (V3, V3) {
    let pt = scale(sub(point(theta + H, phi), point(theta - H, phi)), 0.5 / H);
    let pp = scale(sub(point(theta, phi + H), point(theta, phi - H)), 0.5 / H);
    (pt, pp)
}

/// The outward unit normal: ∂P/∂θ × ∂P/∂φ (θ runs down, φ east).
pub fn normal(theta: f64, phi: f64) -> V3 {
    let (pt, pp) = tangents(theta, phi);
    normalize(cross(pt, pp))
}

/// The principal curvatures (κ1 ≤ κ2, 1/units, positive where convex) from
/// the first and second fundamental forms, second derivatives by central
/// differences.
pub fn principal_curvatures(theta: f64, phi: f64) -> (f64, f64) {
    let (pt, pp) = tangents(theta, phi);
    let n = normalize(cross(pt, pp));
    let p0 = point(theta, phi);
    let second = |a: V3, b: V3| scale(add(sub(a, scale(p0, 2.0)), b), 1.0 / (H * H));
    let ptt = second(point(theta + H, phi), point(theta - H, phi));
    let ppp = second(point(theta, phi + H), point(theta, phi - H));
    let ptp = scale(
        sub(
            add(point(theta + H, phi + H), point(theta - H, phi - H)),
            add(point(theta + H, phi - H), point(theta - H, phi + H)),
        ),
        0.25 / (H * H),
    );
    let (e, f, g) = (dot(pt, pt), dot(pt, pp), dot(pp, pp));
    // Outward normal: a convex surface curves away from it, so the second
    // form's coefficients are negated to make convex curvature positive.
    let (l, m, nn) = (-dot(ptt, n), -dot(ptp, n), -dot(ppp, n));
    let det = e * g - f * f;
    let mean = (l * g - 2.0 * m * f + nn * e) / (2.0 * det);
    let gauss = (l * nn - m * m) / det;
    let d = (mean * mean - gauss).max(0.0).sqrt();
    (mean - d, mean + d)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The f64 surface is the mesh's: every head vertex within f32 precision.
    #[test]
    fn matches_the_bust_mesh() {
        let parts = weft_render::bust_parts();
        let head = &parts
            .iter()
            .find(|(p, _)| *p == weft_render::BustPart::Head)
            .unwrap()
            .1;
        for (p, uv) in head.positions.iter().zip(&head.uv0) {
            let (t, f) = angles(f64::from(uv[0]), f64::from(uv[1]));
            let q = point(t, f);
            for i in 0..3 {
                assert!((q[i] - f64::from(p[i])).abs() < 2e-5, "{p:?} vs {q:?}");
            }
        }
    }

    /// A sphere's curvature is 1/r in both directions (checks the signs and
    /// the fundamental forms on the jaw-free upper half, scaled).
    #[test]
    fn curvature_of_the_upper_front_is_the_ellipsoids() {
        // At the front pole (θ = π/2, φ = 0) of an ellipsoid with radii
        // (a, b, c): κ across = c/a², κ up = c/b².
        let (a, b, c) = (
            f64::from(HEAD_RADII[0]),
            f64::from(HEAD_RADII[1]),
            f64::from(HEAD_RADII[2]),
        );
        let (k1, k2) = principal_curvatures(PI / 2.0 - 1e-3, 0.0);
        assert!((k1 - c / (b * b)).abs() < 1e-3, "{k1}");
        assert!((k2 - c / (a * a)).abs() < 1e-3, "{k2}");
    }
}
