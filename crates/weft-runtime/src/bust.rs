//! The character bust (issue 12's test asset): a head with face UVs, two
//! eyes, a cap of hair cards and shoulders, generated procedurally and
//! deterministically. Each part is its own mesh (`bust_parts`), so a scene can
//! give each a material; `whole_bust` joins them for a one-material preview.
//!
//! Conventions, as in `scene.rs` (+Y up, the face looks along +Z, counter-
//! clockwise front faces). Every part is a surface over (θ from +Y, φ from
//! +Z towards +X), so rows run down and columns east like `mesh::uv_sphere`:
//! - head: u = 0.5 + φ/π, v = θ/π — the front half of the head spans u in
//!   [0, 1] from the right ear (the character's) to the left, v from the
//!   crown to the chin, so a face map (an SDF threshold map, a face texture)
//!   covers the face; the back half wraps to u outside [0, 1], continuous
//!   under repeat addressing;
//! - eyes: uv projected from the front over each eyeball's disc, the iris at
//!   (0.5, 0.5) and the disc's rim at the square's edges;
//! - hair: one card per strand bundle, u across the card, v from root (0) to
//!   tip (1); the strand direction is the bitangent (increasing v), the
//!   tangent runs across the card;
//! - shoulders: v = θ/π, u = φ/2π.

use crate::math;
use crate::mesh::{Mesh, compute_normals, compute_tangents, grid_indices};
use std::f32::consts::PI;

/// The bust's parts, in draw order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BustPart {
    Head,
    Eyes,
    Hair,
    Shoulders,
}

impl BustPart {
    pub const ALL: [BustPart; 4] = [
        BustPart::Head,
        BustPart::Eyes,
        BustPart::Hair,
        BustPart::Shoulders,
    ];

    pub fn name(self) -> &'static str {
        match self {
            BustPart::Head => "head",
            BustPart::Eyes => "eyes",
            BustPart::Hair => "hair",
            BustPart::Shoulders => "shoulders",
        }
    }

    /// The part's built-in mesh name in scenes and previews (`bust.head`).
    pub fn mesh_name(self) -> &'static str {
        match self {
            BustPart::Head => "bust.head",
            BustPart::Eyes => "bust.eyes",
            BustPart::Hair => "bust.hair",
            BustPart::Shoulders => "bust.shoulders",
        }
    }
}

// Public so that the texture generators (weft-golden's `textures`) place
// their features where the mesh has them.
/// Centre of the head and its radii (x across, y up, z forward).
pub const HEAD_CENTRE: [f32; 3] = [0.0, 0.55, 0.0];
pub const HEAD_RADII: [f32; 3] = [0.78, 1.0, 0.86];
/// How much the lower half narrows to a jaw (x, z): the radii times
/// 1 - k (-cos θ)² below the centre (`head_radii`).
pub const HEAD_JAW: [f32; 2] = [0.24, 0.08];
/// Eyeball radius and centres (right eye of the character at -x).
pub const EYE_RADIUS: f32 = 0.11;
pub const EYE_CENTRES: [[f32; 3]; 2] = [[-0.27, 0.62, 0.72], [0.27, 0.62, 0.72]];
/// Where the hair cards end, as fractions of π in θ: the fringe at
/// `HAIR_END[0]` in front, `HAIR_END[0] + HAIR_END[1]` at the nape, in
/// between as 0.5 - 0.5 cos φ.
pub const HAIR_END: [f32; 2] = [0.42, 0.36];
/// Hair cards around the head, and their rows from root to tip.
const HAIR_CARDS: u32 = 48;
const HAIR_ROWS: u32 = 12;

/// A surface over (θ, φ) on a `rows` x `columns` grid (θ may be any
/// parameter that runs down the rows): `at(θ, φ)` gives the
/// position and uv0. θ runs down the rows, φ east along the columns, which
/// winds the triangles counter-clockwise seen from outside. Normals from the
/// triangles, tangents from the uvs.
fn surface(
    rows: u32,
    columns: u32,
    theta: (f32, f32),
    phi: (f32, f32),
    at: impl Fn(f32, f32) -> ([f32; 3], [f32; 2]),
) -> Mesh {
    let mut m = Mesh::default();
    for r in 0..=rows {
        let t = theta.0 + (theta.1 - theta.0) * r as f32 / rows as f32;
        for c in 0..=columns {
            let p = phi.0 + (phi.1 - phi.0) * c as f32 / columns as f32;
            let (position, uv) = at(t, p);
            m.positions.push(position);
            m.uv0.push(uv);
        }
    }
    m.indices = grid_indices(rows, columns);
    // Triangles collapsed at a pole have no area; drop them so that they
    // neither weigh on the normals nor reach the rasteriser.
    let positions = m.positions.clone();
    let indices: Vec<u32> = m
        .indices
        .chunks_exact(3)
        .filter(|t| {
            let [a, b, c] = [t[0], t[1], t[2]].map(|i| positions[i as usize]);
            math::dot(
                math::cross(math::sub(b, a), math::sub(c, a)),
                math::cross(math::sub(b, a), math::sub(c, a)),
            ) > 1e-14
        })
        .flatten()
        .copied()
        .collect();
    m.indices = indices;
    compute_normals(&mut m);
    compute_tangents(&mut m);
    m
}

/// The point of an ellipsoid at (θ, φ).
fn ellipsoid(centre: [f32; 3], radii: [f32; 3], theta: f32, phi: f32) -> [f32; 3] {
    let (st, ct) = theta.sin_cos();
    let (sp, cp) = phi.sin_cos();
    [
        centre[0] + radii[0] * st * sp,
        centre[1] + radii[1] * ct,
        centre[2] + radii[2] * st * cp,
    ]
}

/// The head's radii at polar angle θ: the lower half narrows to a jaw.
fn head_radii(theta: f32) -> [f32; 3] {
    let below = (-theta.cos()).max(0.0);
    [
        HEAD_RADII[0] * (1.0 - HEAD_JAW[0] * below * below),
        HEAD_RADII[1],
        HEAD_RADII[2] * (1.0 - HEAD_JAW[1] * below * below),
    ]
}

fn head() -> Mesh {
    surface(64, 96, (0.0, PI), (-PI, PI), |theta, phi| {
        let p = ellipsoid(HEAD_CENTRE, head_radii(theta), theta, phi);
        (p, [0.5 + phi / PI, theta / PI])
    })
}

fn eye(centre: [f32; 3]) -> Mesh {
    surface(24, 32, (0.0, PI), (-PI, PI), |theta, phi| {
        let p = ellipsoid(centre, [EYE_RADIUS; 3], theta, phi);
        // Projected from the front onto the eyeball's disc.
        let u = 0.5 + (p[0] - centre[0]) / (2.0 * EYE_RADIUS);
        let v = 0.5 - (p[1] - centre[1]) / (2.0 * EYE_RADIUS);
        (p, [u, v])
    })
}

/// One hair card: a ribbon from the crown down the head, over the head's
/// surface at `lift` times its radii, ending at the fringe over the forehead
/// and lower at the back.
fn hair_card(k: u32) -> Mesh {
    let centre_phi = 2.0 * PI * k as f32 / HAIR_CARDS as f32;
    // 30 % overlap with the neighbours, so no scalp shows between cards.
    let half_width = 1.3 * PI / HAIR_CARDS as f32;
    // Alternate cards sit on two layers, so overlaps do not z-fight.
    let lift = if k.is_multiple_of(2) { 1.05 } else { 1.075 };
    // The fringe ends at the brow (θ ≈ 0.42π) at the front, the back hair at
    // the nape (θ ≈ 0.78π).
    let end = HAIR_END[0] * PI + HAIR_END[1] * PI * (0.5 - 0.5 * centre_phi.cos());
    let start = 0.03;
    let mut m = surface(
        HAIR_ROWS,
        2,
        (start, end),
        (centre_phi - half_width, centre_phi + half_width),
        |theta, phi| {
            let along = (theta - start) / (end - start);
            // Tips flare out a little.
            let r = head_radii(theta).map(|x| x * (lift + 0.05 * along * along));
            let p = ellipsoid(HEAD_CENTRE, r, theta, phi);
            let u = (phi - centre_phi + half_width) / (2.0 * half_width);
            (p, [u, along])
        },
    );
    m.uv1 = m.uv0.clone();
    m
}

fn hair() -> Mesh {
    let mut m = Mesh::default();
    for k in 0..HAIR_CARDS {
        append(&mut m, &hair_card(k));
    }
    m
}

fn shoulders() -> Mesh {
    // The upper half of a wide, flat ellipsoid below the neck, and the neck.
    let mut m = surface(24, 96, (0.0, 0.62 * PI), (-PI, PI), |theta, phi| {
        let p = ellipsoid([0.0, -0.95, -0.05], [1.45, 0.55, 0.62], theta, phi);
        (p, [0.5 + phi / (2.0 * PI), theta / PI])
    });
    let neck = cylinder([0.0, -0.75, -0.02], 0.34, 0.85);
    append(&mut m, &neck);
    m
}

/// An open cylinder along +Y from `base`, `height` tall (rows run down, as
/// on the other parts).
fn cylinder(base: [f32; 3], radius: f32, height: f32) -> Mesh {
    surface(8, 48, (0.0, 1.0), (-PI, PI), |v, phi| {
        let (sp, cp) = phi.sin_cos();
        let p = [
            base[0] + radius * sp,
            base[1] + height * (1.0 - v),
            base[2] + radius * cp,
        ];
        (p, [0.5 + phi / (2.0 * PI), v])
    })
}

/// Appends `other` to `m` (every stream; empty optional streams stay empty
/// only if both are).
fn append(m: &mut Mesh, other: &Mesh) {
    let offset = m.positions.len() as u32;
    let fill_uv1 = |mesh: &Mesh| {
        if mesh.uv1.is_empty() {
            mesh.uv0.clone()
        } else {
            mesh.uv1.clone()
        }
    };
    let fill_colors = |mesh: &Mesh| {
        if mesh.colors.is_empty() {
            vec![[1.0; 4]; mesh.positions.len()]
        } else {
            mesh.colors.clone()
        }
    };
    let keep_uv1 = !m.uv1.is_empty() || !other.uv1.is_empty();
    let keep_colors = !m.colors.is_empty() || !other.colors.is_empty();
    if keep_uv1 {
        m.uv1 = fill_uv1(m);
        m.uv1.extend(fill_uv1(other));
    }
    if keep_colors {
        m.colors = fill_colors(m);
        m.colors.extend(fill_colors(other));
    }
    m.positions.extend(&other.positions);
    m.normals.extend(&other.normals);
    m.tangents.extend(&other.tangents);
    m.uv0.extend(&other.uv0);
    m.indices.extend(other.indices.iter().map(|i| i + offset));
}

/// The bust's parts, each its own mesh.
pub fn bust_parts() -> Vec<(BustPart, Mesh)> {
    let mut eyes = eye(EYE_CENTRES[0]);
    append(&mut eyes, &eye(EYE_CENTRES[1]));
    vec![
        (BustPart::Head, head()),
        (BustPart::Eyes, eyes),
        (BustPart::Hair, hair()),
        (BustPart::Shoulders, shoulders()),
    ]
}

/// The whole bust as one mesh (every part), for a one-material preview.
pub fn whole_bust() -> Mesh {
    let mut m = Mesh::default();
    for (_, part) in bust_parts() {
        append(&mut m, &part);
    }
    m
}

#[cfg(test)]
mod tests {
    use super::*;

    fn centroid(t: &[u32], m: &Mesh) -> [f32; 3] {
        let [a, b, c] = [t[0], t[1], t[2]].map(|i| m.positions[i as usize]);
        math::scale(math::add(math::add(a, b), c), 1.0 / 3.0)
    }

    /// Every triangle faces away from its part's inside: the head's and the
    /// hair's centre, each eye's centre, the shoulders' and neck's axis.
    #[test]
    fn triangles_face_outwards() {
        for (part, m) in bust_parts() {
            assert!(!m.indices.is_empty(), "{}", part.name());
            for t in m.indices.chunks_exact(3) {
                let [a, b, c] = [t[0], t[1], t[2]].map(|i| m.positions[i as usize]);
                let n = math::cross(math::sub(b, a), math::sub(c, a));
                let p = centroid(t, &m);
                let inside = match part {
                    BustPart::Head | BustPart::Hair => HEAD_CENTRE,
                    BustPart::Eyes => EYE_CENTRES[usize::from(p[0] > 0.0)],
                    // Below the neck's top: the axis at the triangle's height.
                    BustPart::Shoulders => [0.0, p[1].min(-0.95), -0.03],
                };
                assert!(
                    math::dot(n, math::sub(p, inside)) > 0.0,
                    "{}: triangle {t:?} faces in",
                    part.name()
                );
            }
        }
    }

    #[test]
    fn streams_are_complete_finite_and_unit() {
        let m = whole_bust();
        let n = m.vertex_count();
        assert!(n > 10_000);
        assert_eq!(
            (m.normals.len(), m.tangents.len(), m.uv0.len(), m.uv1.len()),
            (n, n, n, n)
        );
        assert!(m.indices.iter().all(|&i| (i as usize) < n));
        for (i, (nrm, t)) in m.normals.iter().zip(&m.tangents).enumerate() {
            let ln = math::dot(*nrm, *nrm).sqrt();
            let lt = math::dot([t[0], t[1], t[2]], [t[0], t[1], t[2]]).sqrt();
            assert!(
                (ln - 1.0).abs() < 1e-3 && (lt - 1.0).abs() < 1e-3,
                "vertex {i}: {nrm:?} {t:?}"
            );
            assert!(t[3] == 1.0 || t[3] == -1.0);
        }
        assert!(m.uv0.iter().flatten().all(|x| x.is_finite()));
        // Deterministic: the same bytes every time.
        assert_eq!(whole_bust(), m);
    }

    #[test]
    fn the_face_spans_the_unit_square_and_the_iris_is_centred() {
        let head = head();
        // The front of the head (z > 0) maps into [0, 1]^2: a face texture covers it.
        for (p, uv) in head.positions.iter().zip(&head.uv0) {
            if p[2] > 1e-4 {
                assert!(
                    (0.0..=1.0).contains(&uv[0]) && (0.0..=1.0).contains(&uv[1]),
                    "{p:?} -> {uv:?}"
                );
            }
        }
        // The nose tip (front pole at the centre's height) is the face's centre.
        let front = head
            .positions
            .iter()
            .zip(&head.uv0)
            .max_by(|a, b| a.0[2].total_cmp(&b.0[2]))
            .unwrap();
        assert!(
            (front.1[0] - 0.5).abs() < 0.02 && (front.1[1] - 0.5).abs() < 0.02,
            "{front:?}"
        );
        for centre in EYE_CENTRES {
            let e = eye(centre);
            let (_, uv) = e
                .positions
                .iter()
                .zip(&e.uv0)
                .max_by(|a, b| a.0[2].total_cmp(&b.0[2]))
                .unwrap();
            assert!(
                (uv[0] - 0.5).abs() < 1e-3 && (uv[1] - 0.5).abs() < 1e-3,
                "{uv:?}"
            );
        }
    }

    #[test]
    fn hair_strands_run_from_root_to_tip_along_the_bitangent() {
        let h = hair();
        for i in 0..h.vertex_count() {
            let [t0, t1, t2, w] = h.tangents[i];
            let bitangent = math::scale(math::cross(h.normals[i], [t0, t1, t2]), w);
            // Down the head from the crown: the bitangent's y falls except at
            // the very crown, where the cards start almost flat.
            if h.uv0[i][1] > 0.2 {
                assert!(bitangent[1] < 0.0, "vertex {i}: strand {bitangent:?}");
            }
        }
    }
}
