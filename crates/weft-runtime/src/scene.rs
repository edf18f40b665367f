//! Deterministic test scenes generated in code: a mesh (`mesh.rs`: a UV
//! sphere, a draped cloth patch, a flat swatch; `bust.rs`: the character
//! bust) with a look-at camera and a directional light.
//!
//! World space is right-handed with +Y up; triangles are counter-clockwise
//! seen from their front side. Vertex streams follow the engine interface
//! (position 0, normal 1, tangent 2 with w = bitangent sign, uv0 3, uv1 4,
//! colour 5); the bitangent is `cross(normal, tangent.xyz) * tangent.w` and
//! points along increasing v.

use crate::bust::{BustPart, bust_parts, whole_bust};
use crate::math::{self, Mat4, Vec3};
use crate::mesh;
pub use crate::mesh::Mesh;

/// A look-at perspective camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    pub eye: Vec3,
    pub target: Vec3,
    pub up: Vec3,
    /// Vertical field of view in degrees.
    pub fov_y_degrees: f32,
    pub near: f32,
    pub far: f32,
}

impl Camera {
    pub fn view(&self) -> Mat4 {
        math::look_at(self.eye, self.target, self.up)
    }

    pub fn projection(&self, aspect: f32) -> Mat4 {
        math::perspective(self.fov_y_degrees.to_radians(), aspect, self.near, self.far)
    }

    pub fn view_proj(&self, aspect: f32) -> Mat4 {
        math::mul(&self.projection(aspect), &self.view())
    }
}

/// The main directional light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Direction from the surface towards the light (normalised on use).
    pub direction: Vec3,
    /// Linear radiance (irradiance at normal incidence).
    pub radiance: Vec3,
}

impl Default for Light {
    /// weft's default light, stated once in `weft-meta` (scene metadata
    /// writes it into `light` when a manifest has no `[light]`).
    fn default() -> Self {
        Light {
            direction: weft_meta::scene::DEFAULT_LIGHT_DIRECTION.map(|c| c as f32),
            radiance: weft_meta::scene::DEFAULT_LIGHT_COLOR.map(|c| c as f32),
        }
    }
}

/// Which built-in scene to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SceneKind {
    Sphere,
    Cloth,
    Swatch,
    /// The character bust (`bust.rs`): head, eyes, hair cards, shoulders.
    Bust,
    /// One part of the bust, framed as the whole bust is, so a scene can
    /// give each part its own material (`bust.head`, `bust.eyes`, …).
    BustPart(BustPart),
}

impl SceneKind {
    pub const ALL: [SceneKind; 8] = [
        SceneKind::Sphere,
        SceneKind::Cloth,
        SceneKind::Swatch,
        SceneKind::Bust,
        SceneKind::BustPart(BustPart::Head),
        SceneKind::BustPart(BustPart::Eyes),
        SceneKind::BustPart(BustPart::Hair),
        SceneKind::BustPart(BustPart::Shoulders),
    ];

    pub fn name(self) -> &'static str {
        match self {
            SceneKind::Sphere => "sphere",
            SceneKind::Cloth => "cloth",
            SceneKind::Swatch => "swatch",
            SceneKind::Bust => "bust",
            SceneKind::BustPart(part) => part.mesh_name(),
        }
    }

    pub fn from_name(s: &str) -> Option<SceneKind> {
        SceneKind::ALL.into_iter().find(|k| k.name() == s)
    }
}

/// A mesh, its model matrix, a camera and the main light.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    pub mesh: Mesh,
    pub model: Mat4,
    pub camera: Camera,
    pub light: Light,
}

impl Scene {
    /// `mesh` at the origin (identity model), seen from +Z by a 35° camera
    /// that frames its bounds, under the default light: a preview of a
    /// mesh of the user's.
    pub fn framing(mesh: Mesh) -> Scene {
        let mut lo = [f32::INFINITY; 3];
        let mut hi = [f32::NEG_INFINITY; 3];
        for p in &mesh.positions {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let centre: Vec3 = std::array::from_fn(|k| 0.5 * (lo[k] + hi[k]));
        let radius = (0..3)
            .map(|k| (hi[k] - lo[k]).powi(2))
            .sum::<f32>()
            .sqrt()
            .max(1e-3)
            * 0.5;
        let fov = 35.0f32;
        let distance = radius / (0.5 * fov.to_radians()).sin() / 0.95;
        let mut scene = Scene::new(SceneKind::Sphere);
        scene.mesh = mesh;
        scene.model = math::IDENTITY;
        scene.camera = Camera {
            eye: [centre[0], centre[1], centre[2] + distance],
            target: centre,
            up: [0.0, 1.0, 0.0],
            fov_y_degrees: fov,
            near: (distance - radius).max(distance * 1e-3) * 0.5,
            far: (distance + radius) * 2.0,
        };
        scene
    }

    pub fn new(kind: SceneKind) -> Scene {
        match kind {
            SceneKind::Sphere => Scene::sphere(),
            SceneKind::Cloth => Scene::cloth(),
            SceneKind::Swatch => Scene::swatch(),
            SceneKind::Bust => Scene::bust(),
            SceneKind::BustPart(part) => Scene::bust_part(part),
        }
    }

    /// The unit sphere filling most of the frame; corners show the sky.
    pub fn sphere() -> Scene {
        Scene {
            mesh: mesh::uv_sphere(96, 48),
            model: math::IDENTITY,
            camera: Camera {
                eye: [0.0, 0.55, 3.75],
                target: [0.0, 0.0, 0.0],
                up: [0.0, 1.0, 0.0],
                fov_y_degrees: 36.0,
                near: 0.1,
                far: 100.0,
            },
            light: Light::default(),
        }
    }

    /// The draped cloth seen from above at an angle.
    pub fn cloth() -> Scene {
        Scene {
            mesh: mesh::cloth(96),
            model: math::IDENTITY,
            camera: Camera {
                eye: [0.0, 1.55, 2.55],
                target: [0.0, -0.2, 0.05],
                up: [0.0, 1.0, 0.0],
                fov_y_degrees: 40.0,
                near: 0.1,
                far: 100.0,
            },
            light: Light::default(),
        }
    }

    /// The flat swatch facing the camera, filling the frame's centre.
    pub fn swatch() -> Scene {
        Scene {
            mesh: mesh::swatch(),
            model: math::IDENTITY,
            camera: Camera {
                eye: [0.0, 0.0, 3.4],
                target: [0.0, 0.0, 0.0],
                up: [0.0, 1.0, 0.0],
                fov_y_degrees: 40.0,
                near: 0.1,
                far: 100.0,
            },
            light: Light::default(),
        }
    }
}

impl Scene {
    /// One part of the bust, in the bust's frame and camera.
    pub fn bust_part(part: BustPart) -> Scene {
        let mesh = bust_parts()
            .into_iter()
            .find(|(p, _)| *p == part)
            .map(|(_, m)| m)
            .expect("bust_parts has every part");
        Scene {
            mesh,
            ..Scene::bust()
        }
    }

    /// The character bust, three-quarter height, face towards the camera.
    pub fn bust() -> Scene {
        Scene {
            mesh: whole_bust(),
            model: math::IDENTITY,
            camera: Camera {
                eye: [0.0, 0.55, 4.4],
                target: [0.0, 0.3, 0.0],
                up: [0.0, 1.0, 0.0],
                fov_y_degrees: 40.0,
                near: 0.1,
                far: 100.0,
            },
            light: Light::default(),
        }
    }
}

/// `scene` with its light turned towards `direction` (None: the scene's
/// own), and `sky` with its sun where that light is: what `weft preview
/// --light` draws under and the inspector bakes for the browser, computed
/// in one place so the two agree.
pub fn lit(
    mut scene: Scene,
    direction: Option<Vec3>,
    mut sky: crate::environment::SkyParams,
) -> (Scene, crate::environment::SkyParams) {
    if let Some(d) = direction {
        scene.light.direction = math::normalize(d);
    }
    sky.sun_direction = scene.light.direction;
    (scene, sky)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_tangents_match_uv_derived_ones() {
        let analytic = mesh::uv_sphere(32, 16);
        let mut derived = analytic.clone();
        mesh::compute_tangents(&mut derived);
        let mut checked = 0;
        for (i, (a, d)) in analytic.tangents.iter().zip(&derived.tangents).enumerate() {
            let y = analytic.positions[i][1];
            // Skip the poles and the seam column (different triangles on each side).
            if y.abs() > 0.9 {
                continue;
            }
            let u = analytic.uv0[i][0];
            if u == 0.0 || u == 1.0 {
                continue;
            }
            let c = a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
            assert!(c > 0.99, "vertex {i}: {a:?} vs {d:?}");
            assert_eq!(a[3], d[3], "vertex {i}: handedness");
            checked += 1;
        }
        assert!(checked > 300);
    }

    #[test]
    fn triangles_face_outwards() {
        let s = mesh::uv_sphere(16, 8);
        for t in s.indices.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| s.positions[i as usize]);
            let n = math::cross(math::sub(b, a), math::sub(c, a));
            let centre = math::scale(math::add(math::add(a, b), c), 1.0 / 3.0);
            assert!(math::dot(n, centre) > 0.0);
        }
        let c = mesh::cloth(8);
        for t in c.indices.chunks_exact(3) {
            let [a, b, cc] = [t[0], t[1], t[2]].map(|i| c.positions[i as usize]);
            assert!(math::cross(math::sub(b, a), math::sub(cc, a))[1] > 0.0);
        }
        let q = mesh::swatch();
        assert_eq!(q.tangents[0], [1.0, 0.0, 0.0, -1.0]);
    }

    /// Every built-in mesh follows the tangent-frame convention the
    /// metadata states (`weft_meta::conventions::TangentFrame`): the tangent
    /// along +u and w·cross(N, T) along +v, per triangle from its positions
    /// and uvs (seams and poles, where a vertex's frame belongs to other
    /// triangles, aside: nearly every corner agrees).
    #[test]
    fn built_in_meshes_follow_the_stated_tangent_frame() {
        let frame = weft_meta::conventions::TangentFrame::current();
        assert_eq!(
            (
                frame.tangent_follows.as_str(),
                frame.bitangent_follows.as_str()
            ),
            ("+u", "+v")
        );
        for kind in SceneKind::ALL {
            let m = Scene::new(kind).mesh;
            let (mut agree, mut total) = (0usize, 0usize);
            for t in m.indices.chunks_exact(3) {
                let [i0, i1, i2] = [t[0], t[1], t[2]].map(|i| i as usize);
                let (p0, p1, p2) = (m.positions[i0], m.positions[i1], m.positions[i2]);
                let (w0, w1, w2) = (m.uv0[i0], m.uv0[i1], m.uv0[i2]);
                let (e1, e2) = (math::sub(p1, p0), math::sub(p2, p0));
                let (du1, dv1) = (w1[0] - w0[0], w1[1] - w0[1]);
                let (du2, dv2) = (w2[0] - w0[0], w2[1] - w0[1]);
                let det = du1 * dv2 - du2 * dv1;
                if det.abs() < 1e-9 {
                    continue;
                }
                let dp_du = math::scale(
                    math::sub(math::scale(e1, dv2), math::scale(e2, dv1)),
                    1.0 / det,
                );
                let dp_dv = math::scale(
                    math::sub(math::scale(e2, du1), math::scale(e1, du2)),
                    1.0 / det,
                );
                for i in [i0, i1, i2] {
                    let [tx, ty, tz, w] = m.tangents[i];
                    let tangent = [tx, ty, tz];
                    let w = if w < 0.0 { -1.0 } else { 1.0 };
                    let bitangent = math::scale(math::cross(m.normals[i], tangent), w);
                    total += 1;
                    if math::dot(tangent, dp_du) > 0.0 && math::dot(bitangent, dp_dv) > 0.0 {
                        agree += 1;
                    }
                }
            }
            let share = agree as f64 / total as f64;
            assert!(
                total > 0 && share > 0.97,
                "{}: {agree} of {total} corners",
                kind.name()
            );
        }
    }
}
