//! Deterministic test scenes generated in code: a UV sphere, a draped cloth
//! patch and a flat swatch, with a look-at camera and a directional light.
//!
//! World space is right-handed with +Y up; triangles are counter-clockwise
//! seen from their front side. Vertex streams follow the engine interface
//! (position 0, normal 1, tangent 2 with w = bitangent sign, uv0 3, uv1 4,
//! colour 5); the bitangent is `cross(normal, tangent.xyz) * tangent.w` and
//! points along increasing v.

use crate::bust::{BustPart, bust_parts};
use crate::math::{self, Mat4, Vec3};
use std::f32::consts::PI;

/// A triangle mesh with every engine-interface vertex stream.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub positions: Vec<[f32; 3]>,
    pub normals: Vec<[f32; 3]>,
    /// xyz: unit tangent along increasing u; w: bitangent sign (+1 or -1).
    pub tangents: Vec<[f32; 4]>,
    pub uv0: Vec<[f32; 2]>,
    /// Second UV set (defaults to uv0 when empty).
    pub uv1: Vec<[f32; 2]>,
    /// Vertex colours (default white when empty).
    pub colors: Vec<[f32; 4]>,
    pub indices: Vec<u32>,
}

impl Mesh {
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// A UV sphere of radius 1 centred on the origin, with analytic normals
    /// and tangents (u runs around +Y, v from the north pole down).
    pub fn uv_sphere(segments: u32, rings: u32) -> Mesh {
        let mut m = Mesh::default();
        for r in 0..=rings {
            let v = r as f32 / rings as f32;
            let theta = v * PI; // from +Y
            let (st, ct) = theta.sin_cos();
            for s in 0..=segments {
                let u = s as f32 / segments as f32;
                let phi = u * 2.0 * PI;
                let (sp, cp) = phi.sin_cos();
                // Counter-clockwise seen from outside with u increasing to the east.
                let n = [st * sp, ct, st * cp];
                m.positions.push(n);
                m.normals.push(n);
                // dP/du is along (cos phi, 0, -sin phi); dP/dv points down (south).
                let t = [cp, 0.0, -sp];
                let b = [ct * sp, -st, ct * cp]; // d n / d theta, along +v
                let w = if math::dot(math::cross(n, t), b) < 0.0 {
                    -1.0
                } else {
                    1.0
                };
                m.tangents.push([t[0], t[1], t[2], w]);
                m.uv0.push([u, v]);
            }
        }
        let stride = segments + 1;
        for r in 0..rings {
            for s in 0..segments {
                let a = r * stride + s;
                let b = a + stride;
                // a (north-west), a+1 (north-east), b (south-west), b+1 (south-east).
                if r != 0 {
                    m.indices.extend([a, b, a + 1]);
                }
                if r != rings - 1 {
                    m.indices.extend([a + 1, b, b + 1]);
                }
            }
        }
        m
    }

    /// A draped cloth patch: a `res` x `res` heightfield-like sheet over
    /// [-1, 1]^2 in x/z with folds, normals and tangents derived from the
    /// geometry and the UVs (uv0 tiles twice).
    pub fn cloth(res: u32) -> Mesh {
        let mut m = Mesh::default();
        let res = res.max(2);
        for j in 0..=res {
            for i in 0..=res {
                let u = i as f32 / res as f32;
                let v = j as f32 / res as f32;
                let x = u * 2.0 - 1.0;
                let z = v * 2.0 - 1.0;
                // Folds running mostly along z that fan out towards the
                // front, a cross ripple, and the sheet sagging off its centre.
                let fan = 2.6 + 1.2 * v;
                let fold = 0.13 * (fan * 3.0 * x + 0.9 * (2.3 * z).sin()).sin() * (0.55 + 0.45 * v);
                let ripple = 0.035 * (6.1 * z + 2.3 * x).sin();
                let sag = -0.45 * (x * x * 0.6 + z * z * 0.3);
                let y = fold + ripple + sag;
                m.positions.push([x, y, z]);
                m.uv0.push([u * 2.0, v * 2.0]);
            }
        }
        let stride = res + 1;
        for j in 0..res {
            for i in 0..res {
                let a = j * stride + i;
                let b = a + stride;
                // Seen from above (+Y): x right, z towards the viewer.
                m.indices.extend([a, b, a + 1, a + 1, b, b + 1]);
            }
        }
        m.compute_normals();
        m.compute_tangents();
        m
    }

    /// A flat 2 x 2 quad in the xy plane facing +Z, uv (0, 0) at the top left.
    pub fn swatch() -> Mesh {
        let mut m = Mesh {
            positions: vec![
                [-1.0, 1.0, 0.0],
                [1.0, 1.0, 0.0],
                [-1.0, -1.0, 0.0],
                [1.0, -1.0, 0.0],
            ],
            normals: vec![[0.0, 0.0, 1.0]; 4],
            uv0: vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]],
            indices: vec![0, 2, 1, 1, 2, 3],
            ..Mesh::default()
        };
        m.compute_tangents();
        m
    }

    /// Area-weighted vertex normals from the triangles.
    pub fn compute_normals(&mut self) {
        let mut acc = vec![[0.0f32; 3]; self.positions.len()];
        for t in self.indices.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| self.positions[i as usize]);
            let n = math::cross(math::sub(b, a), math::sub(c, a));
            for &i in t {
                acc[i as usize] = math::add(acc[i as usize], n);
            }
        }
        self.normals = acc
            .into_iter()
            .map(|n| math::normalize_or(n, [0.0, 1.0, 0.0]))
            .collect();
    }

    /// Per-vertex tangents from positions and uv0 (Lengyel 2001): the
    /// per-triangle dP/du and dP/dv are accumulated, the tangent is
    /// Gram-Schmidt orthogonalised against the normal and w is the sign of
    /// `dot(cross(n, t), dP/dv)`.
    pub fn compute_tangents(&mut self) {
        let n = self.positions.len();
        let mut tan = vec![[0.0f32; 3]; n];
        let mut bit = vec![[0.0f32; 3]; n];
        for t in self.indices.chunks_exact(3) {
            let [i0, i1, i2] = [t[0], t[1], t[2]].map(|i| i as usize);
            let (p0, p1, p2) = (self.positions[i0], self.positions[i1], self.positions[i2]);
            let (w0, w1, w2) = (self.uv0[i0], self.uv0[i1], self.uv0[i2]);
            let e1 = math::sub(p1, p0);
            let e2 = math::sub(p2, p0);
            let (du1, dv1) = (w1[0] - w0[0], w1[1] - w0[1]);
            let (du2, dv2) = (w2[0] - w0[0], w2[1] - w0[1]);
            let det = du1 * dv2 - du2 * dv1;
            if det.abs() < 1e-12 {
                continue;
            }
            let r = 1.0 / det;
            let sdir = math::scale(math::sub(math::scale(e1, dv2), math::scale(e2, dv1)), r);
            let tdir = math::scale(math::sub(math::scale(e2, du1), math::scale(e1, du2)), r);
            // Weight by triangle area so that small slivers do not dominate.
            let area = 0.5 * math::length(math::cross(e1, e2));
            let sdir = math::scale(math::normalize_or(sdir, [0.0; 3]), area);
            let tdir = math::scale(math::normalize_or(tdir, [0.0; 3]), area);
            for i in [i0, i1, i2] {
                tan[i] = math::add(tan[i], sdir);
                bit[i] = math::add(bit[i], tdir);
            }
        }
        self.tangents = (0..n)
            .map(|i| {
                let nrm = self.normals[i];
                let t = math::sub(tan[i], math::scale(nrm, math::dot(nrm, tan[i])));
                let t = math::normalize_or(t, any_perpendicular(nrm));
                let w = if math::dot(math::cross(nrm, t), bit[i]) < 0.0 {
                    -1.0
                } else {
                    1.0
                };
                [t[0], t[1], t[2], w]
            })
            .collect();
    }
}

fn any_perpendicular(n: Vec3) -> Vec3 {
    let a = if n[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    math::normalize(math::cross(n, a))
}

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
            mesh: Mesh::uv_sphere(96, 48),
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
            mesh: Mesh::cloth(96),
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
            mesh: Mesh::swatch(),
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
            mesh: Mesh::bust(),
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
        let analytic = Mesh::uv_sphere(32, 16);
        let mut derived = analytic.clone();
        derived.compute_tangents();
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
        let s = Mesh::uv_sphere(16, 8);
        for t in s.indices.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| s.positions[i as usize]);
            let n = math::cross(math::sub(b, a), math::sub(c, a));
            let centre = math::scale(math::add(math::add(a, b), c), 1.0 / 3.0);
            assert!(math::dot(n, centre) > 0.0);
        }
        let c = Mesh::cloth(8);
        for t in c.indices.chunks_exact(3) {
            let [a, b, cc] = [t[0], t[1], t[2]].map(|i| c.positions[i as usize]);
            assert!(math::cross(math::sub(b, a), math::sub(cc, a))[1] > 0.0);
        }
        let q = Mesh::swatch();
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
