//! The geometric cases (N, T, V, L) every material is evaluated at, and
//! the scene of each case's tile: a quad facing V, lit from L.

use crate::math::{self, Vec3};
use crate::scene::{Camera, Light, Mesh, Scene};

/// Distance of the probe camera along V.
const CAMERA_DISTANCE: f32 = 1.0e6;

/// One geometric configuration: world-space vectors as the shader receives them.
#[derive(Clone, Debug, PartialEq)]
pub struct GeometricCase {
    pub name: String,
    /// The vertex normal (not necessarily unit; may be zero).
    pub normal: Vec3,
    /// The vertex tangent, w = bitangent sign (not necessarily unit or orthogonal).
    pub tangent: [f32; 4],
    /// Unit direction towards the camera.
    pub view: Vec3,
    /// Unit direction towards the light.
    pub light: Vec3,
}

impl GeometricCase {
    /// N·V with the normal normalised (0 for a zero normal).
    pub fn n_dot_v(&self) -> f32 {
        math::dot(math::normalize_or(self.normal, [0.0; 3]), self.view)
    }

    /// N·L with the normal normalised (0 for a zero normal).
    pub fn n_dot_l(&self) -> f32 {
        math::dot(math::normalize_or(self.normal, [0.0; 3]), self.light)
    }
}

/// Unit vector at polar cosine `cos_theta` from +Z (may be negative: below
/// the horizon) and azimuth `phi` from +X.
fn polar(cos_theta: f32, phi: f32) -> Vec3 {
    let c = f64::from(cos_theta);
    let s = (1.0 - c * c).max(0.0).sqrt();
    let p = f64::from(phi);
    [(s * p.cos()) as f32, (s * p.sin()) as f32, c as f32]
}

pub(super) fn cos_label(c: f32) -> String {
    if c == 0.0 {
        "0".into()
    } else if c.abs() < 1e-3 {
        format!("{c:e}")
    } else {
        format!("{c}")
    }
}

/// The geometric extremes every material is evaluated at. The frame is
/// N = +Z, T = +X (w = +1) unless a case says otherwise.
///
/// - N·V × N·L over {1, 1e-4, 0, -0.5}², with L at the mirror azimuth
///   (φ_L = φ_V + π), at the same azimuth (L = V when the cosines agree) and
///   at a right angle (H off the incidence plane): 48 cases;
/// - L = V and L = −V at N·V = 1, 0.5, 1e-4, 0 (and −0.5 for L = −V, light
///   from above);
/// - grazing V along T and along B;
/// - H parallel to the tangent (V, L in the T–B plane; and N·V = −N·L = 0.8)
///   and to the bitangent;
/// - tangent: zero-length, parallel to N, 1e-4 from N, 45° to N, length 5,
///   w = 0, w = −1, each at a generic, a grazing and a normal-incidence
///   configuration;
/// - a zero-length normal and a non-unit normal.
pub fn geometric_cases() -> Vec<GeometricCase> {
    use std::f32::consts::{FRAC_PI_2, PI};
    let n = [0.0, 0.0, 1.0];
    let t = [1.0, 0.0, 0.0, 1.0];
    let case =
        |name: String, normal: Vec3, tangent: [f32; 4], view: Vec3, light: Vec3| GeometricCase {
            name,
            normal,
            tangent,
            view,
            light,
        };
    let cosines = [1.0f32, 1e-4, 0.0, -0.5];
    let mut out = Vec::new();
    for (az, dphi) in [
        ("mirror", PI),
        ("same-azimuth", 0.0),
        ("right-angle", FRAC_PI_2),
    ] {
        for &cv in &cosines {
            for &cl in &cosines {
                out.push(case(
                    format!("N.V={} N.L={} {az}", cos_label(cv), cos_label(cl)),
                    n,
                    t,
                    polar(cv, 0.0),
                    polar(cl, dphi),
                ));
            }
        }
    }
    for c in [0.5f32, 1e-4, 0.0] {
        let v = polar(c, 0.3);
        out.push(case(format!("L=V N.V={}", cos_label(c)), n, t, v, v));
    }
    for c in [1.0f32, 0.5, 1e-4, 0.0, -0.5] {
        let v = polar(c, 0.3);
        out.push(case(
            format!("L=-V N.V={}", cos_label(c)),
            n,
            t,
            v,
            math::scale(v, -1.0),
        ));
    }
    let generic_l = polar(0.7, 2.5);
    out.push(case(
        "grazing V along T".into(),
        n,
        t,
        [1.0, 0.0, 0.0],
        generic_l,
    ));
    out.push(case(
        "grazing V along B".into(),
        n,
        t,
        [0.0, 1.0, 0.0],
        generic_l,
    ));
    out.push(case(
        "H parallel to T, V and L in the T-B plane".into(),
        n,
        t,
        [0.6, 0.8, 0.0],
        [0.6, -0.8, 0.0],
    ));
    out.push(case(
        "H parallel to T, N.V=0.8 N.L=-0.8".into(),
        n,
        t,
        [0.6, 0.0, 0.8],
        [0.6, 0.0, -0.8],
    ));
    out.push(case(
        "H parallel to B, N.V=0.8 N.L=-0.8".into(),
        n,
        t,
        [0.0, 0.6, 0.8],
        [0.0, 0.6, -0.8],
    ));
    let s = std::f32::consts::FRAC_1_SQRT_2;
    let tangents: [(&str, [f32; 4]); 7] = [
        ("zero-length tangent", [0.0, 0.0, 0.0, 1.0]),
        ("tangent parallel to N", [0.0, 0.0, 1.0, 1.0]),
        ("tangent 1e-4 from N", [1e-4, 0.0, 1.0, 1.0]),
        ("tangent 45deg to N (non-orthogonal)", [s, 0.0, s, 1.0]),
        ("tangent of length 5", [5.0, 0.0, 0.0, 1.0]),
        ("tangent w=0", [1.0, 0.0, 0.0, 0.0]),
        ("tangent w=-1", [1.0, 0.0, 0.0, -1.0]),
    ];
    let configs: [(&str, Vec3, Vec3); 3] = [
        ("generic", polar(0.5, 0.4), generic_l),
        ("grazing N.V=1e-4", polar(1e-4, 0.4), generic_l),
        ("N=V=L", n, n),
    ];
    for (tname, tan) in tangents {
        for (cname, v, l) in configs {
            out.push(case(format!("{tname}, {cname}"), n, tan, v, l));
        }
    }
    out.push(case(
        "zero-length normal, generic".into(),
        [0.0; 3],
        t,
        polar(0.5, 0.4),
        generic_l,
    ));
    out.push(case(
        "normal of length 3, generic".into(),
        [0.0, 0.0, 3.0],
        t,
        polar(0.5, 0.4),
        generic_l,
    ));
    out
}

/// A unit vector perpendicular to the unit vector `v`.
fn perpendicular(v: Vec3) -> Vec3 {
    let a = if v[0].abs() < 0.6 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    math::normalize(math::cross(v, a))
}

/// The tile of one case: a quad facing V with the case's attributes, the
/// camera far along V, the light along L.
pub(super) fn case_scene(case: &GeometricCase, light_radiance: Vec3) -> Scene {
    let v = math::normalize(case.view);
    let up = perpendicular(v);
    let eye = math::scale(v, CAMERA_DISTANCE);
    // The camera's own right/up (as math::look_at computes them), so the
    // quad is counter-clockwise on screen.
    let f = math::scale(v, -1.0);
    let right = math::normalize(math::cross(f, up));
    let cam_up = math::cross(right, f);
    let corner = |a: f32, b: f32| math::add(math::scale(right, a), math::scale(cam_up, b));
    let mesh = Mesh {
        positions: vec![
            corner(-1.0, -1.0),
            corner(1.0, -1.0),
            corner(1.0, 1.0),
            corner(-1.0, 1.0),
        ],
        normals: vec![case.normal; 4],
        tangents: vec![case.tangent; 4],
        uv0: vec![[0.0, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]],
        uv1: Vec::new(),
        colors: Vec::new(),
        indices: vec![0, 1, 2, 0, 2, 3],
    };
    // The frustum's half-height at the quad is 0.5: the 2 x 2 quad
    // over-fills the viewport even if f32 rounding of the view matrix
    // shifts it by a few tenths.
    let half = 0.5 / CAMERA_DISTANCE;
    Scene {
        mesh,
        model: math::IDENTITY,
        camera: Camera {
            eye,
            target: [0.0; 3],
            up,
            fov_y_degrees: (2.0 * f64::from(half).atan()).to_degrees() as f32,
            near: CAMERA_DISTANCE * 0.5,
            far: CAMERA_DISTANCE * 2.0,
        },
        light: Light {
            direction: case.light,
            radiance: light_radiance,
        },
    }
}
