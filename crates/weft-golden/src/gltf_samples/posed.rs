//! Files whose meshes are posed in their default state (docs/gltf.md,
//! "Posed meshes"), made by the test that checks them against poses it
//! computes by hand (tests/rendering/gltf_scenes.rs):
//!
//! - a skinned strip after the Khronos SimpleSkin sample: ten vertices at
//!   x = ±0.5, y = 0, 0.5, …, 2, two joints (the root at the origin, its
//!   child at y = 1 turned 90° about +Z), weights from (1, 0) at the bottom
//!   to (0, 1) at the top; the skinned node stands at x = 5, which glTF
//!   ignores;
//! - a morphing triangle facing +z: two targets (the first also tilts the
//!   normals by (0.5, 0, 0)), mesh weights (0.5, 0.5), drawn by a node of
//!   its own and by a node whose weights are (1, 0).

use super::{Packed, asset, glb};
use serde_json::json;

fn packed() -> Packed {
    Packed {
        bin: Vec::new(),
        views: Vec::new(),
        accessors: Vec::new(),
    }
}

/// The strip's rows: y of each pair of vertices and the child joint's weight.
pub const STRIP_ROWS: [(f32, f32); 5] =
    [(0.0, 0.0), (0.5, 0.25), (1.0, 0.5), (1.5, 0.75), (2.0, 1.0)];

/// The skinned strip (see the module docs) as a GLB.
pub fn skinned_strip() -> Vec<u8> {
    let mut p = packed();
    let mut positions = Vec::new();
    let mut joints: Vec<[u16; 4]> = Vec::new();
    let mut weights: Vec<[f32; 4]> = Vec::new();
    for (y, w) in STRIP_ROWS {
        for x in [-0.5f32, 0.5] {
            positions.push([x, y, 0.0]);
            joints.push([0, 1, 0, 0]);
            weights.push([1.0 - w, w, 0.0, 0.0]);
        }
    }
    let n = positions.len();
    let normals = vec![[0.0f32, 0.0, 1.0]; n];
    let tangents = vec![[1.0f32, 0.0, 0.0, 1.0]; n];
    let mut indices: Vec<u16> = Vec::new();
    for row in 0..4u16 {
        let (a, b, c, d) = (2 * row, 2 * row + 1, 2 * row + 2, 2 * row + 3);
        indices.extend([a, b, d, a, d, c]);
    }
    let position = p.floats(&positions, "VEC3", true);
    let normal = p.floats(&normals, "VEC3", false);
    let tangent = p.floats(&tangents, "VEC4", false);
    let weight = p.floats(&weights, "VEC4", false);
    let joint_view = p.push(
        joints
            .iter()
            .flatten()
            .flat_map(|j| j.to_le_bytes())
            .collect(),
        34962,
    );
    let joint = p.accessor(joint_view, n, "VEC4", 5123, json!({}));
    let index_view = p.push(
        indices.iter().flat_map(|i| i.to_le_bytes()).collect(),
        34963,
    );
    let index = p.accessor(index_view, indices.len(), "SCALAR", 5123, json!({}));
    // Inverse bind matrices (column-major): the root's identity, the child's
    // translation by −1 in y.
    let ibm: Vec<[f32; 16]> = vec![
        [
            1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.,
        ],
        [
            1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 0., 0., -1., 0., 1.,
        ],
    ];
    let ibm_view = p.push(
        ibm.iter().flatten().flat_map(|x| x.to_le_bytes()).collect(),
        0,
    );
    p.views[ibm_view]
        .as_object_mut()
        .expect("view")
        .remove("target");
    let ibm_accessor = p.accessor(ibm_view, 2, "MAT4", 5126, json!({}));
    let half = std::f32::consts::FRAC_1_SQRT_2;
    let json = json!({
        "asset": asset(),
        "scene": 0,
        "scenes": [ { "nodes": [0, 1] } ],
        "nodes": [
            { "name": "strip", "mesh": 0, "skin": 0, "translation": [5.0, 0.0, 0.0] },
            { "name": "root", "children": [2] },
            { "name": "bend", "translation": [0.0, 1.0, 0.0], "rotation": [0.0, 0.0, half, half] },
        ],
        "meshes": [ { "name": "strip", "primitives": [ { "attributes": {
            "POSITION": position, "NORMAL": normal, "TANGENT": tangent,
            "JOINTS_0": joint, "WEIGHTS_0": weight }, "indices": index, "mode": 4 } ] } ],
        "skins": [ { "joints": [1, 2], "inverseBindMatrices": ibm_accessor } ],
        "buffers": [ { "byteLength": p.bin.len() } ],
        "bufferViews": p.views,
        "accessors": p.accessors,
    });
    glb(&json, &p.bin)
}

/// The morphing triangle's base positions and its two targets' displacements.
pub const MORPH_BASE: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 0.5, 0.0]];
pub const MORPH_TARGETS: [[[f32; 3]; 3]; 2] = [
    [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [-1.0, 1.0, 0.0]],
    [[0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [1.0, 1.0, 0.0]],
];

/// The first morph target's displacement of every normal.
pub const MORPH_NORMAL_DELTA: [f32; 3] = [0.5, 0.0, 0.0];

/// The morphing triangle (see the module docs) as a GLB.
pub fn morphing_triangle() -> Vec<u8> {
    let mut p = packed();
    let position = p.floats(&MORPH_BASE, "VEC3", true);
    let normal = p.floats(&[[0.0, 0.0, 1.0]; 3], "VEC3", false);
    let mut targets: Vec<_> = MORPH_TARGETS
        .iter()
        .map(|t| json!({ "POSITION": p.floats(t, "VEC3", true) }))
        .collect();
    targets[0]["NORMAL"] = json!(p.floats(&[MORPH_NORMAL_DELTA; 3], "VEC3", false));
    let json = json!({
        "asset": asset(),
        "scene": 0,
        "scenes": [ { "nodes": [0, 1] } ],
        "nodes": [
            { "name": "mesh_weights", "mesh": 0 },
            { "name": "node_weights", "mesh": 0, "weights": [1.0, 0.0], "translation": [2.0, 0.0, 0.0] },
        ],
        "meshes": [ { "name": "tri", "weights": [0.5, 0.5],
            "primitives": [ { "attributes": { "POSITION": position, "NORMAL": normal }, "targets": targets, "mode": 4 } ] } ],
        "buffers": [ { "byteLength": p.bin.len() } ],
        "bufferViews": p.views,
        "accessors": p.accessors,
    });
    glb(&json, &p.bin)
}
