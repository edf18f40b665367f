//! The triangle mesh every draw takes (the engine interface's six vertex
//! streams) and the meshes generated in code: a UV sphere, a draped cloth
//! patch, a flat swatch. Conventions as `scene.rs` states them: right-handed,
//! +Y up, counter-clockwise fronts, bitangent = cross(normal, tangent.xyz) ×
//! tangent.w along increasing v.

use crate::math::{self, Vec3};
use std::f32::consts::PI;

/// A triangle mesh with every engine-interface vertex stream: the type a
/// mesh file holds (`weft_meta::mesh`), so that what is drawn, written and
/// read back is one value. Drawn, `uv1` may be empty (uv0 is read) and so
/// may `colors` (white); a file holds every stream
/// (`weft_render::mesh_data` fills them as the renderer uploads them).
pub use weft_meta::mesh::MeshData as Mesh;

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
    // Seen from above (+Y): x right, z towards the viewer.
    m.indices = grid_indices(res, res);
    compute_normals(&mut m);
    compute_tangents(&mut m);
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
    compute_tangents(&mut m);
    m
}

/// The triangles of a grid of `rows` x `columns` quads whose vertices run
/// row by row (`columns + 1` to a row): quad (r, c) with a = its top-left
/// vertex and b the one below is a, b, a+1 and a+1, b, b+1.
pub(crate) fn grid_indices(rows: u32, columns: u32) -> Vec<u32> {
    let stride = columns + 1;
    let mut indices = Vec::with_capacity(rows as usize * columns as usize * 6);
    for r in 0..rows {
        for c in 0..columns {
            let a = r * stride + c;
            let b = a + stride;
            indices.extend([a, b, a + 1, a + 1, b, b + 1]);
        }
    }
    indices
}

/// Area-weighted vertex normals from the triangles.
pub fn compute_normals(m: &mut Mesh) {
    let mut acc = vec![[0.0f32; 3]; m.positions.len()];
    for t in m.indices.chunks_exact(3) {
        let [a, b, c] = [t[0], t[1], t[2]].map(|i| m.positions[i as usize]);
        let n = math::cross(math::sub(b, a), math::sub(c, a));
        for &i in t {
            acc[i as usize] = math::add(acc[i as usize], n);
        }
    }
    m.normals = acc
        .into_iter()
        .map(|n| math::normalize_or(n, [0.0, 1.0, 0.0]))
        .collect();
}

/// Per-vertex tangents from positions and uv0 (Lengyel 2001): the
/// per-triangle dP/du and dP/dv are accumulated, the tangent is
/// Gram-Schmidt orthogonalised against the normal and w is the sign of
/// `dot(cross(n, t), dP/dv)`.
pub fn compute_tangents(m: &mut Mesh) {
    let n = m.positions.len();
    let mut tan = vec![[0.0f32; 3]; n];
    let mut bit = vec![[0.0f32; 3]; n];
    for t in m.indices.chunks_exact(3) {
        let [i0, i1, i2] = [t[0], t[1], t[2]].map(|i| i as usize);
        let (p0, p1, p2) = (m.positions[i0], m.positions[i1], m.positions[i2]);
        let (w0, w1, w2) = (m.uv0[i0], m.uv0[i1], m.uv0[i2]);
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
    m.tangents = (0..n)
        .map(|i| {
            let nrm = m.normals[i];
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

fn any_perpendicular(n: Vec3) -> Vec3 {
    let a = if n[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    math::normalize(math::cross(n, a))
}
