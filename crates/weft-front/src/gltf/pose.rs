//! A primitive as the file shows it when nothing is animated: its morph
//! targets blended by the default weights, and its vertices skinned by the
//! skin's joints where they stand (glTF 2.0 § 3.7.2.2 and § 3.7.3). weft
//! draws static scenes, so a character exported mid-pose or with a blend
//! shape dialled in draws as every glTF viewer shows it, not as its
//! unposed bind mesh.
//!
//! - Morph targets: position += Σ wₖ Δpositionₖ, and the same for normals
//!   and tangents (xyz), with the node's `weights`, else the mesh's.
//! - Skin: each vertex by Σ wᵢ · world(jointᵢ) · inverseBind(jointᵢ) over its
//!   JOINTS_n/WEIGHTS_n sets (weights divided by their sum); normals by the
//!   cofactor of that matrix, tangents by its 3×3; the result is in world
//!   space, so the instance that draws it has the identity matrix (glTF
//!   ignores a skinned node's own transform).
//!
//! Every accessor is checked as the primitive's own are ([`check_accessor`]).

use super::GltfError;
use super::accessors::{self, Allowed, Norm, Vector, check_accessor, read_finite};
use super::document::GltfFile;
use super::transform::{
    Mat4, mul, normal_matrix, normalize, transform_point, transform_vector, unit_or,
};
use gltf::accessor::{DataType, Dimensions};
use weft_meta::mesh::MeshData;

/// The most vertex × morph target displacements one primitive may blend
/// (2²⁸: ARKit's 52 blend shapes on a 5-million-vertex mesh), and the most
/// JOINTS_n/WEIGHTS_n sets (32 influences) and joints per skin: a hostile
/// file whose targets or sets all name the same accessor would otherwise
/// cost time and memory its bytes do not bound.
pub const MAX_MORPH_ELEMENTS: usize = 1 << 28;
pub const MAX_SKIN_SETS: u32 = 8;
pub const MAX_JOINTS: usize = 1 << 16;

/// Whether drawing `node`'s mesh differs from the mesh's own default
/// state: the node has a skin, or morph weights of its own.
pub fn node_poses(node: &gltf::Node) -> bool {
    node.skin().is_some() || (node.weights().is_some() && node.mesh().is_some())
}

/// The morph weights a primitive is drawn with: the node's, else the
/// mesh's; all zero when neither has any.
fn default_weights<'a>(mesh: &gltf::Mesh<'a>, node: Option<&gltf::Node<'a>>) -> Option<&'a [f32]> {
    node.and_then(gltf::Node::weights)
        .or_else(|| mesh.weights())
}

/// Blends `prim`'s morph targets into `data` (positions, and normals and
/// tangents where `data` has them) with the default weights.
pub fn morph(
    file: &GltfFile,
    mesh: &gltf::Mesh,
    prim: &gltf::Primitive,
    node: Option<&gltf::Node>,
    data: &mut MeshData,
    pointer: &str,
) -> Result<(), GltfError> {
    let targets: Vec<gltf::mesh::MorphTarget> = prim.morph_targets().collect();
    let Some(weights) = default_weights(mesh, node) else {
        return Ok(());
    };
    if targets.is_empty() {
        return Ok(());
    }
    if weights.len() != targets.len() {
        let at = match node.filter(|n| n.weights().is_some()) {
            Some(n) => format!("/nodes/{}/weights", n.index()),
            None => format!("/meshes/{}/weights", mesh.index()),
        };
        return Err(file.error(
            &at,
            format!(
                "{} morph weights for the {} targets of {pointer}",
                weights.len(),
                targets.len()
            ),
            "glTF gives one default weight per morph target; re-export the file",
        ));
    }
    let quantized = accessors::quantized(file);
    let count = data.positions.len();
    let blended = weights.iter().filter(|w| **w != 0.0).count();
    if blended.saturating_mul(count) > MAX_MORPH_ELEMENTS {
        return Err(file.error(
            pointer,
            format!("{blended} morph targets with a weight × {count} vertices to blend"),
            "weft blends at most 2^28 displacements per primitive; bake the default pose in your DCC",
        ));
    }
    let (mut moved_normals, mut moved_tangents) = (false, false);
    for (k, (target, &w)) in targets.iter().zip(weights).enumerate() {
        if w == 0.0 {
            continue;
        }
        if !w.is_finite() {
            return Err(file.error(
                &format!("/meshes/{}/weights/{k}", mesh.index()),
                "a morph weight is not finite".into(),
                "re-export the file",
            ));
        }
        // A stream's displacements, where the target has them and the
        // primitive has the stream.
        let deltas = |accessor: Option<gltf::Accessor>, has: bool, position: bool, stream: &str| {
            match accessor.filter(|_| has) {
                None => Ok(None),
                Some(a) => {
                    let what = format!("{pointer} target {k} {stream}");
                    let types = delta_types(quantized, position);
                    read_checked::<[f32; 3]>(file, &a, &types, count, &what).map(Some)
                }
            }
        };
        if let Some(d) = deltas(target.positions(), true, true, "POSITION")? {
            add(data.positions.iter_mut().map(|p| &mut p[..]), &d, w);
        }
        if let Some(d) = deltas(target.normals(), !data.normals.is_empty(), false, "NORMAL")? {
            add(data.normals.iter_mut().map(|n| &mut n[..]), &d, w);
            moved_normals = true;
        }
        if let Some(d) = deltas(
            target.tangents(),
            !data.tangents.is_empty(),
            false,
            "TANGENT",
        )? {
            add(data.tangents.iter_mut().map(|t| &mut t[..3]), &d, w);
            moved_tangents = true;
        }
    }
    // Displaced normals and tangents are directions again.
    if moved_normals {
        for n in &mut data.normals {
            *n = unit_or(*n, [0.0, 0.0, 1.0]);
        }
    }
    if moved_tangents {
        for t in &mut data.tangents {
            let [x, y, z] = unit_or([t[0], t[1], t[2]], [1.0, 0.0, 0.0]);
            *t = [x, y, z, t[3]];
        }
    }
    finite_positions(file, data, pointer)
}

/// The accessor types a morph target's displacements may have: float, and
/// with KHR_mesh_quantization i8/i16 (plain or normalised for positions,
/// normalised for normals and tangents).
fn delta_types(quantized: bool, position: bool) -> Vec<Allowed> {
    let mut types = vec![(DataType::F32, Dimensions::Vec3, Norm::Either)];
    if quantized {
        let norm = if position { Norm::Either } else { Norm::Yes };
        types.extend([DataType::I8, DataType::I16].map(|t| (t, Dimensions::Vec3, norm)));
    }
    types
}

/// Each value's first three components plus `w` times its displacement.
fn add<'v>(values: impl Iterator<Item = &'v mut [f32]>, deltas: &[[f32; 3]], w: f32) {
    for (v, d) in values.zip(deltas) {
        for (x, dx) in v.iter_mut().zip(d) {
            *x += w * dx;
        }
    }
}

/// An accessor checked (type, byte ranges, one element per vertex) and read.
fn read_checked<V: Vector>(
    file: &GltfFile,
    accessor: &gltf::Accessor,
    allowed: &[Allowed],
    count: usize,
    what: &str,
) -> Result<Vec<V>, GltfError> {
    check_accessor(file, accessor, allowed, what)?;
    if accessor.count() != count {
        return Err(file.error(
            &format!("/accessors/{}", accessor.index()),
            format!("{what} has {} elements, POSITION {count}", accessor.count()),
            "every attribute of a primitive has one element per vertex",
        ));
    }
    read_finite(file, accessor, what)
}

/// One JOINTS_n/WEIGHTS_n pair: per vertex its four joints and weights.
type InfluenceSet = (Vec<[f32; 4]>, Vec<[f32; 4]>);

/// Skins `data` by `node`'s skin at the joints' default transforms, into
/// world space. `worlds` holds every node's world matrix.
pub fn skin(
    file: &GltfFile,
    prim: &gltf::Primitive,
    node: &gltf::Node,
    worlds: &[Option<Mat4>],
    data: &mut MeshData,
    pointer: &str,
) -> Result<(), GltfError> {
    let Some(skin) = node.skin() else {
        return Ok(());
    };
    let matrices = joint_matrices(file, &skin, worlds)?;
    let count = data.positions.len();
    // Each JOINTS_n/WEIGHTS_n set, read whole.
    let mut sets: Vec<InfluenceSet> = Vec::new();
    for set in 0u32.. {
        if set == MAX_SKIN_SETS {
            if prim.get(&gltf::Semantic::Joints(set)).is_some() {
                return Err(file.error(
                    &format!("{pointer}/attributes/JOINTS_{set}"),
                    format!("more than {MAX_SKIN_SETS} JOINTS_n sets"),
                    "weft skins with at most 32 influences per vertex; re-export with fewer",
                ));
            }
            break;
        }
        let (Some(joints), Some(weights)) = (
            prim.get(&gltf::Semantic::Joints(set)),
            prim.get(&gltf::Semantic::Weights(set)),
        ) else {
            break;
        };
        let joint_types =
            [DataType::U8, DataType::U16].map(|t| (t, Dimensions::Vec4, Norm::Either));
        let weight_types = [
            (DataType::F32, Dimensions::Vec4, Norm::Either),
            (DataType::U8, Dimensions::Vec4, Norm::Yes),
            (DataType::U16, Dimensions::Vec4, Norm::Yes),
        ];
        let j: Vec<[f32; 4]> = read_checked(
            file,
            &joints,
            &joint_types,
            count,
            &format!("{pointer} JOINTS_{set}"),
        )?;
        let w: Vec<[f32; 4]> = read_checked(
            file,
            &weights,
            &weight_types,
            count,
            &format!("{pointer} WEIGHTS_{set}"),
        )?;
        for (v, (j, w)) in j.iter().zip(&w).enumerate() {
            for (&joint, &weight) in j.iter().zip(w) {
                if weight == 0.0 {
                    continue;
                }
                let joint = joint as usize;
                if joint >= matrices.len() || !weight.is_finite() || weight < 0.0 {
                    return Err(file.error(
                        &format!("/accessors/{}", joints.index()),
                        format!(
                            "vertex {v} of {pointer}: joint {joint} with weight {weight}; the skin has {} joints",
                            matrices.len()
                        ),
                        "joint indices point into the skin's `joints`, weights are finite and ≥ 0; re-export the file",
                    ));
                }
            }
        }
        sets.push((j, w));
    }
    if sets.is_empty() {
        return Err(file.error(
            &format!("{pointer}/attributes"),
            format!(
                "node {} has a skin but the primitive has no JOINTS_0 and WEIGHTS_0",
                node.index()
            ),
            "a skinned primitive names its joints and weights; re-export the file",
        ));
    }
    for v in 0..count {
        // (joint, weight) of every influence on vertex v.
        let influences = || {
            sets.iter()
                .flat_map(move |(j, w)| j[v].iter().zip(&w[v]))
                .filter(|(_, w)| **w != 0.0)
                .map(|(&j, &w)| (j as usize, w))
        };
        let total: f32 = influences().map(|(_, w)| w).sum();
        // No weight at all: the vertex stays where the bind pose puts it.
        if total <= 0.0 {
            continue;
        }
        let mut m = [[0.0f64; 4]; 4];
        for (joint, weight) in influences() {
            let share = f64::from(weight / total);
            for (col, joint_col) in m.iter_mut().zip(&matrices[joint]) {
                for (x, y) in col.iter_mut().zip(joint_col) {
                    *x += share * y;
                }
            }
        }
        let p = data.positions[v].map(f64::from);
        data.positions[v] = transform_point(&m, p).map(|x| x as f32);
        let (cofactor, det) = normal_matrix(&m);
        if let Some(n) = data.normals.get_mut(v) {
            let moved: [f64; 3] =
                std::array::from_fn(|r| (0..3).map(|c| cofactor[c][r] * f64::from(n[c])).sum());
            *n = normalize(moved)
                .unwrap_or([0.0, 0.0, 1.0])
                .map(|x| x as f32);
        }
        if let Some(t) = data.tangents.get_mut(v) {
            let moved = transform_vector(&m, [t[0], t[1], t[2]].map(f64::from));
            let [x, y, z] = normalize(moved)
                .unwrap_or([1.0, 0.0, 0.0])
                .map(|x| x as f32);
            let w = if det < 0.0 { -t[3] } else { t[3] };
            *t = [x, y, z, w];
        }
    }
    finite_positions(file, data, pointer)
}

/// The joint matrices of node `node`'s skin for framing the scene; empty
/// when it has none or they cannot be read (the mesh's own read reports it).
pub fn joint_frames(file: &GltfFile, node: usize, worlds: &[Option<Mat4>]) -> Vec<Mat4> {
    file.document
        .nodes()
        .nth(node)
        .and_then(|n| n.skin())
        .and_then(|skin| joint_matrices(file, &skin, worlds).ok())
        .unwrap_or_default()
}

/// world(joint) · inverseBind(joint) for each of the skin's joints.
fn joint_matrices(
    file: &GltfFile,
    skin: &gltf::Skin,
    worlds: &[Option<Mat4>],
) -> Result<Vec<Mat4>, GltfError> {
    let at = format!("/skins/{}", skin.index());
    if skin.joints().len() > MAX_JOINTS {
        return Err(file.error(
            &format!("{at}/joints"),
            format!("{} joints", skin.joints().len()),
            "JOINTS_n index at most 65536 joints; re-export the file",
        ));
    }
    let joints: Vec<gltf::Node> = skin.joints().collect();
    let inverse_binds: Vec<Mat4> = match skin.inverse_bind_matrices() {
        None => vec![super::transform::IDENTITY; joints.len()],
        Some(a) => {
            let allowed = [(DataType::F32, Dimensions::Mat4, Norm::Either)];
            check_accessor(file, &a, &allowed, &format!("{at} inverseBindMatrices"))?;
            if a.count() < joints.len() {
                return Err(file.error(
                    &format!("{at}/inverseBindMatrices"),
                    format!(
                        "{} inverse bind matrices for {} joints",
                        a.count(),
                        joints.len()
                    ),
                    "one matrix per joint; re-export the file",
                ));
            }
            let get = |b: gltf::Buffer| file.buffers.get(b.index()).map(Vec::as_slice);
            skin.reader(get)
                .read_inverse_bind_matrices()
                .ok_or_else(|| {
                    file.error(
                        &format!("{at}/inverseBindMatrices"),
                        "could not be read".into(),
                        "re-export the file",
                    )
                })?
                .map(|m| m.map(|c| c.map(f64::from)))
                .collect()
        }
    };
    joints
        .iter()
        .zip(&inverse_binds)
        .enumerate()
        .map(|(k, (joint, ibm))| {
            let world = worlds
                .get(joint.index())
                .copied()
                .flatten()
                .ok_or_else(|| {
                    file.error(
                        &format!("{at}/joints/{k}"),
                        format!(
                            "joint node {} has no world transform (its parents form a cycle)",
                            joint.index()
                        ),
                        "glTF nodes form disjoint trees",
                    )
                })?;
            Ok(mul(&world, ibm))
        })
        .collect()
}

fn finite_positions(file: &GltfFile, data: &MeshData, pointer: &str) -> Result<(), GltfError> {
    if data.positions.iter().flatten().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(file.error(
            pointer,
            "a posed position is not finite".into(),
            "check the morph weights, the joints' transforms and the inverse bind matrices",
        ))
    }
}
