//! One sphere written twice: with float attributes, and as gltfpack writes
//! it under `KHR_mesh_quantization` (positions as u16 with the
//! dequantisation in the node's scale and translation, normals and tangents
//! as normalised i8, texture coordinates as normalised u16). The two must
//! build into the same scene within the quantisation's step
//! (tests/rendering/gltf_scenes.rs).

use super::{Packed, asset, glb};
use serde_json::{Value, json};
use weft_render::{Scene, SceneKind};

/// The sphere's node translation in both files.
pub const SPHERE_AT: [f32; 3] = [0.3, 1.1, -0.4];

/// Each element's little-endian components, padded to a 4-byte stride as
/// glTF requires of vertex attributes (§ 3.6.2.4).
fn strided<const N: usize, T: Copy>(values: &[[T; N]], le: fn(T) -> Vec<u8>) -> (Vec<u8>, usize) {
    let size = values
        .first()
        .map_or(0, |v| v.iter().flat_map(|&c| le(c)).count());
    let stride = size.next_multiple_of(4);
    let mut out = Vec::with_capacity(values.len() * stride);
    for v in values {
        let start = out.len();
        out.extend(v.iter().flat_map(|&c| le(c)));
        out.resize(start + stride, 0);
    }
    (out, stride)
}

impl Packed {
    /// A vertex attribute's view (with its stride) and accessor.
    fn attribute(
        &mut self,
        (data, stride): (Vec<u8>, usize),
        count: usize,
        kind: &str,
        component: u32,
        extra: Value,
    ) -> usize {
        let view = self.push(data, 34962);
        self.views[view]["byteStride"] = json!(stride);
        self.accessor(view, count, kind, component, extra)
    }
}

/// How [`quantized_sphere`] stores the sphere's attributes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Encoding {
    Float,
    /// gltfpack's default: positions as plain u16 values, the node scaling
    /// them by the largest extent / 65535.
    Quantized,
    /// gltfpack's `-vpn`: positions as normalised u16, the node scaling them
    /// by the largest extent.
    QuantizedNormalized,
}

/// The sphere as a GLB, its attributes stored as `encoding` says.
pub fn quantized_sphere(encoding: Encoding) -> Vec<u8> {
    let quantize = encoding != Encoding::Float;
    let sphere = Scene::new(SceneKind::Sphere).mesh;
    let mut packed = Packed {
        bin: Vec::new(),
        views: Vec::new(),
        accessors: Vec::new(),
    };
    let count = sphere.positions.len();
    let lo: [f32; 3] = std::array::from_fn(|k| {
        sphere
            .positions
            .iter()
            .map(|p| p[k])
            .fold(f32::INFINITY, f32::min)
    });
    let hi: [f32; 3] = std::array::from_fn(|k| {
        sphere
            .positions
            .iter()
            .map(|p| p[k])
            .fold(f32::NEG_INFINITY, f32::max)
    });
    let f32_le = |x: f32| x.to_le_bytes().to_vec();
    let mut node = json!({ "name": "ball", "mesh": 0, "translation": SPHERE_AT });
    let attributes = if quantize {
        // gltfpack's position encoding: one scale for all axes (the largest
        // extent over 65535), the box's low corner as the offset.
        let scale = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f32::max) / 65535.0;
        let q: Vec<[u16; 3]> = sphere
            .positions
            .iter()
            .map(|p| std::array::from_fn(|k| ((p[k] - lo[k]) / scale).round() as u16))
            .collect();
        let qmin: [u16; 3] = std::array::from_fn(|k| q.iter().map(|v| v[k]).min().unwrap_or(0));
        let qmax: [u16; 3] = std::array::from_fn(|k| q.iter().map(|v| v[k]).max().unwrap_or(0));
        node["translation"] = json!(std::array::from_fn::<f32, 3, _>(|k| SPHERE_AT[k] + lo[k]));
        let normalized = encoding == Encoding::QuantizedNormalized;
        let node_scale = if normalized { scale * 65535.0 } else { scale };
        node["scale"] = json!([node_scale, node_scale, node_scale]);
        let snorm8 = |x: f32| {
            ((x.clamp(-1.0, 1.0) * 127.0).round() as i8)
                .to_le_bytes()
                .to_vec()
        };
        let normals: Vec<[f32; 3]> = sphere.normals.clone();
        let uv16 = |x: f32| {
            ((x.clamp(0.0, 1.0) * 65535.0).round() as u16)
                .to_le_bytes()
                .to_vec()
        };
        json!({
            "POSITION": packed.attribute(strided(&q, |x: u16| x.to_le_bytes().to_vec()), count, "VEC3", 5123,
                json!({ "min": qmin, "max": qmax, "normalized": normalized })),
            "NORMAL": packed.attribute(strided(&normals, snorm8), count, "VEC3", 5120, json!({ "normalized": true })),
            "TANGENT": packed.attribute(strided(&sphere.tangents, snorm8), count, "VEC4", 5120, json!({ "normalized": true })),
            "TEXCOORD_0": packed.attribute(strided(&sphere.uv0, uv16), count, "VEC2", 5123, json!({ "normalized": true })),
        })
    } else {
        json!({
            "POSITION": packed.attribute(strided(&sphere.positions, f32_le), count, "VEC3", 5126,
                json!({ "min": lo, "max": hi })),
            "NORMAL": packed.attribute(strided(&sphere.normals, f32_le), count, "VEC3", 5126, json!({})),
            "TANGENT": packed.attribute(strided(&sphere.tangents, f32_le), count, "VEC4", 5126, json!({})),
            "TEXCOORD_0": packed.attribute(strided(&sphere.uv0, f32_le), count, "VEC2", 5126, json!({})),
        })
    };
    let index_bytes: Vec<u8> = sphere
        .indices
        .iter()
        .flat_map(|i| i.to_le_bytes())
        .collect();
    let view = packed.push(index_bytes, 34963);
    let indices = packed.accessor(view, sphere.indices.len(), "SCALAR", 5125, json!({}));
    let mut json = json!({
        "asset": asset(),
        "scene": 0,
        "scenes": [ { "nodes": [0] } ],
        "nodes": [ node ],
        "meshes": [ { "name": "ball", "primitives": [ { "attributes": attributes, "indices": indices, "mode": 4 } ] } ],
        "buffers": [ { "byteLength": packed.bin.len() } ],
        "bufferViews": packed.views,
        "accessors": packed.accessors,
    });
    if quantize {
        json["extensionsUsed"] = json!(["KHR_mesh_quantization"]);
        json["extensionsRequired"] = json!(["KHR_mesh_quantization"]);
    }
    glb(&json, &packed.bin)
}
