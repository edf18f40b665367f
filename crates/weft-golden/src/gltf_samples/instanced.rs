//! A file whose node draws its mesh several times through
//! `EXT_mesh_gpu_instancing` (docs/gltf.md, "Instanced meshes"), made by the
//! test that checks each copy's matrix (tests/rendering/gltf_scenes.rs):
//! a triangle drawn by a node at (0, 0, −1) with three instances and once
//! by a plain node. The rotations are normalised i16 quaternions, as
//! gltfpack writes them, and an application-specific `_ID` attribute rides
//! along (weft ignores it, as the extension allows).

use super::{Packed, asset, glb};
use serde_json::json;

/// Per instance: translation, rotation (x, y, z, w as stored i16) and scale.
pub const INSTANCES: [([f32; 3], [i16; 4], [f32; 3]); 3] = [
    ([0.0, 0.0, 0.0], [0, 0, 0, 32767], [1.0, 1.0, 1.0]),
    ([2.0, 0.0, 0.0], [0, 0, 0, 32767], [1.0, 1.0, 1.0]),
    // 90° about +Z (z = w = √½ as i16), scaled by 2.
    ([0.0, 3.0, 0.0], [0, 0, 23170, 23170], [2.0, 2.0, 2.0]),
];

/// The instancing node's own translation.
pub const INSTANCED_NODE_AT: [f32; 3] = [0.0, 0.0, -1.0];

/// The instanced triangle (see the module docs) as a GLB.
pub fn instanced_triangle() -> Vec<u8> {
    let mut p = Packed {
        bin: Vec::new(),
        views: Vec::new(),
        accessors: Vec::new(),
    };
    let position = p.floats(
        &[[0.0f32, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
        "VEC3",
        true,
    );
    let normal = p.floats(&[[0.0f32, 0.0, 1.0]; 3], "VEC3", false);
    let translation = p.floats(&INSTANCES.map(|i| i.0), "VEC3", false);
    let scale = p.floats(&INSTANCES.map(|i| i.2), "VEC3", false);
    let rotation_view = p.push(
        INSTANCES
            .iter()
            .flat_map(|i| i.1)
            .flat_map(i16::to_le_bytes)
            .collect(),
        0,
    );
    let ids_view = p.push(
        [0u16, 1, 2, 0]
            .iter()
            .flat_map(|i| i.to_le_bytes())
            .collect(),
        0,
    );
    for view in [rotation_view, ids_view] {
        p.views[view]
            .as_object_mut()
            .expect("view")
            .remove("target");
    }
    let rotation = p.accessor(
        rotation_view,
        3,
        "VEC4",
        5122,
        json!({ "normalized": true }),
    );
    let ids = p.accessor(ids_view, 3, "SCALAR", 5123, json!({}));
    let json = json!({
        "asset": asset(),
        "extensionsUsed": ["EXT_mesh_gpu_instancing"],
        "scene": 0,
        "scenes": [ { "nodes": [0, 1] } ],
        "nodes": [
            { "name": "copies", "mesh": 0, "translation": INSTANCED_NODE_AT,
              "extensions": { "EXT_mesh_gpu_instancing": { "attributes": {
                  "TRANSLATION": translation, "ROTATION": rotation, "SCALE": scale, "_ID": ids } } } },
            { "name": "single", "mesh": 0, "translation": [-3.0, 0.0, 0.0] },
        ],
        "meshes": [ { "name": "tri", "primitives": [ { "attributes": { "POSITION": position, "NORMAL": normal }, "mode": 4 } ] } ],
        "buffers": [ { "byteLength": p.bin.len() } ],
        "bufferViews": p.views,
        "accessors": p.accessors,
    });
    glb(&json, &p.bin)
}
