//! glTF test content made in code (docs/gltf.md "Test content"): what a DCC
//! exports, built from weft's own deterministic meshes so that the files
//! are byte-identical on every machine.
//!
//! - `scenes/gltf/showroom.glb`: a draped garment (velvet sheen), a sofa of
//!   boxes (core PBR frame, sheen cushions, no normals: flat normals), an
//!   iridescent foil swatch, an anisotropic satin ball, a shot-silk swatch
//!   assigned through `extras.weft`, a camera, a directional and a point
//!   light; `KHR_materials_variants` switches the cushions' material.
//! - `tests/gltf/bust.gltf` (+ `.bin`): the character bust, each part's
//!   material from `extras.weft` (face, eye, hair, skin).
//! - `tests/gltf/cutouts.glb`: alpha MASK with doubleSided, emission, BLEND,
//!   a frame with all four core maps (PNG and JPEG, KHR_texture_transform),
//!   a glTF sampler and a rotated texture transform.
//! - [`quantized_sphere`]: one sphere with float attributes and under
//!   `KHR_mesh_quantization`, made by the test that compares them.
//! - [`skinned_strip`], [`morphing_triangle`]: meshes posed by a skin and by
//!   morph weights, made by the test that checks their poses.
//! - [`instanced_triangle`]: a mesh drawn three times by one node through
//!   `EXT_mesh_gpu_instancing`, made by the test that checks each copy.
//! - [`hostile`]: files weft must refuse, each with the JSON pointer the
//!   error names (tests/rendering/gltf_scenes.rs).
//!
//! `cargo xtask gltf-samples` writes the committed files; a test keeps
//! them equal to this generator.

mod hostile;
mod instanced;
mod posed;
mod quantized;
mod scenes;
mod textures;

pub use hostile::hostile;
pub use instanced::{INSTANCED_NODE_AT, INSTANCES, instanced_triangle};
pub use posed::{
    MORPH_BASE, MORPH_NORMAL_DELTA, MORPH_TARGETS, STRIP_ROWS, morphing_triangle, skinned_strip,
};
pub use quantized::{Encoding, SPHERE_AT, quantized_sphere};
pub use scenes::{bust, cutouts, showroom};
pub use textures::{png_rgba, wood_base_color, wood_metallic_roughness};

use serde_json::{Value, json};
use std::collections::BTreeMap;
use weft_render::Mesh;

/// Vertex streams of one primitive; absent streams are left out of the file.
struct Prim {
    positions: Vec<[f32; 3]>,
    normals: Option<Vec<[f32; 3]>>,
    tangents: Option<Vec<[f32; 4]>>,
    uv0: Option<Vec<[f32; 2]>>,
    indices: Vec<u32>,
    material: usize,
}

impl Prim {
    fn from_mesh(m: &Mesh, material: usize, tangents: bool) -> Prim {
        Prim {
            positions: m.positions.clone(),
            normals: Some(m.normals.clone()),
            tangents: (tangents && m.tangents.len() == m.positions.len())
                .then(|| m.tangents.clone()),
            uv0: (m.uv0.len() == m.positions.len()).then(|| m.uv0.clone()),
            indices: m.indices.clone(),
            material,
        }
    }
}

/// An axis-aligned box, 24 vertices with UVs and no normals (a DCC export
/// of a low-poly prop with "normals" unticked).
fn block(centre: [f32; 3], half: [f32; 3], material: usize) -> Prim {
    let mut p = Prim {
        positions: Vec::new(),
        normals: None,
        tangents: None,
        uv0: Some(Vec::new()),
        indices: Vec::new(),
        material,
    };
    // Each face: normal axis, sign; corners counter-clockwise seen from outside.
    for axis in 0..3 {
        for sign in [1.0f32, -1.0] {
            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
            let base = p.positions.len() as u32;
            for (a, b) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
                let mut q = centre;
                q[axis] += sign * half[axis];
                q[u] += a * half[u];
                q[v] += b * half[v] * sign;
                p.positions.push(q);
                p.uv0
                    .as_mut()
                    .unwrap()
                    .push([(a + 1.0) * 0.5, (1.0 - b) * 0.5]);
            }
            p.indices
                .extend([base, base + 1, base + 2, base, base + 2, base + 3]);
        }
    }
    p
}

/// Little-endian bytes of a stream, padded to 4.
fn bytes<const N: usize>(values: &[[f32; N]]) -> Vec<u8> {
    values
        .iter()
        .flatten()
        .flat_map(|x| x.to_le_bytes())
        .collect()
}

/// Buffer, views and accessors of every primitive in one binary buffer.
struct Packed {
    bin: Vec<u8>,
    views: Vec<Value>,
    accessors: Vec<Value>,
}

impl Packed {
    fn push(&mut self, data: Vec<u8>, target: u32) -> usize {
        while !self.bin.len().is_multiple_of(4) {
            self.bin.push(0);
        }
        self.views.push(json!({
            "buffer": 0, "byteOffset": self.bin.len(), "byteLength": data.len(), "target": target
        }));
        self.bin.extend(data);
        self.views.len() - 1
    }

    fn accessor(
        &mut self,
        view: usize,
        count: usize,
        kind: &str,
        component: u32,
        extra: Value,
    ) -> usize {
        let mut a =
            json!({ "bufferView": view, "componentType": component, "count": count, "type": kind });
        if let (Value::Object(a), Value::Object(e)) = (&mut a, extra) {
            a.extend(e);
        }
        self.accessors.push(a);
        self.accessors.len() - 1
    }

    fn floats<const N: usize>(&mut self, values: &[[f32; N]], kind: &str, bounds: bool) -> usize {
        let view = self.push(bytes(values), 34962);
        let extra = if bounds {
            let min: Vec<f32> = (0..N)
                .map(|k| values.iter().map(|v| v[k]).fold(f32::INFINITY, f32::min))
                .collect();
            let max: Vec<f32> = (0..N)
                .map(|k| {
                    values
                        .iter()
                        .map(|v| v[k])
                        .fold(f32::NEG_INFINITY, f32::max)
                })
                .collect();
            json!({ "min": min, "max": max })
        } else {
            json!({})
        };
        self.accessor(view, values.len(), kind, 5126, extra)
    }

    /// A primitive's JSON, its streams packed.
    fn primitive(&mut self, p: &Prim, variants: Option<Value>) -> Value {
        let mut attributes = serde_json::Map::new();
        attributes.insert(
            "POSITION".into(),
            json!(self.floats(&p.positions, "VEC3", true)),
        );
        if let Some(n) = &p.normals {
            attributes.insert("NORMAL".into(), json!(self.floats(n, "VEC3", false)));
        }
        if let Some(t) = &p.tangents {
            attributes.insert("TANGENT".into(), json!(self.floats(t, "VEC4", false)));
        }
        if let Some(uv) = &p.uv0 {
            attributes.insert("TEXCOORD_0".into(), json!(self.floats(uv, "VEC2", false)));
        }
        let index_bytes: Vec<u8> = p.indices.iter().flat_map(|i| i.to_le_bytes()).collect();
        let view = self.push(index_bytes, 34963);
        let indices = self.accessor(view, p.indices.len(), "SCALAR", 5125, json!({}));
        let mut prim = json!({ "attributes": attributes, "indices": indices, "material": p.material, "mode": 4 });
        if let Some(v) = variants {
            prim["extensions"] = json!({ "KHR_materials_variants": v });
        }
        prim
    }
}

/// A GLB container: header, JSON chunk (space-padded), BIN chunk (zero-padded).
pub fn glb(json: &Value, bin: &[u8]) -> Vec<u8> {
    let mut text = serde_json::to_vec(json).expect("json");
    while !text.len().is_multiple_of(4) {
        text.push(b' ');
    }
    let mut bin = bin.to_vec();
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let total = 12 + 8 + text.len() + 8 + bin.len();
    let mut out = Vec::with_capacity(total);
    out.extend(b"glTF");
    out.extend(2u32.to_le_bytes());
    out.extend((total as u32).to_le_bytes());
    out.extend((text.len() as u32).to_le_bytes());
    out.extend(b"JSON");
    out.extend(text);
    out.extend((bin.len() as u32).to_le_bytes());
    out.extend(b"BIN\0");
    out.extend(bin);
    out
}

fn asset() -> Value {
    json!({ "version": "2.0", "generator": "weft gltf_samples (crates/weft-golden/src/gltf_samples.rs)" })
}

/// The quaternion turning +Z onto the direction `d` (a directional light
/// shines along its −Z: `d` is then the direction towards the light).
fn rotation_to(d: [f32; 3]) -> [f32; 4] {
    let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let d = d.map(|x| x / len);
    // axis = z × d, cos θ = d.z; half-angle form.
    let axis = [-d[1], d[0], 0.0];
    let w = 1.0 + d[2];
    let n = (axis[0] * axis[0] + axis[1] * axis[1] + w * w).sqrt();
    [axis[0] / n, axis[1] / n, 0.0, w / n]
}

/// Quaternion (x, y, z, w) of a rotation by `degrees` about a unit axis.
fn quat(axis: [f32; 3], degrees: f32) -> [f32; 4] {
    let (s, c) = (degrees.to_radians() * 0.5).sin_cos();
    [axis[0] * s, axis[1] * s, axis[2] * s, c]
}

/// A large scene for the build-speed bench (`cargo xtask bench gltf`): a
/// grid of `objects` draped cloths of about `triangles / objects`
/// triangles each, without tangents (MikkTSpace runs on every one), their
/// materials cycling through `materials` core-PBR and sheen materials.
pub fn large(triangles: usize, objects: usize, materials: usize) -> Vec<u8> {
    let objects = objects.max(1);
    let per = triangles / objects;
    // cloth(res) has 2 res² triangles.
    let res = ((per as f64 / 2.0).sqrt().round() as u32).max(2);
    let cloth = weft_render::mesh::cloth(res);
    let mut packed = Packed {
        bin: Vec::new(),
        views: Vec::new(),
        accessors: Vec::new(),
    };
    let mut meshes = Vec::new();
    let mut nodes = Vec::new();
    for i in 0..objects {
        let prim = packed.primitive(&Prim::from_mesh(&cloth, i % materials.max(1), false), None);
        meshes.push(json!({ "name": format!("cloth {i}"), "primitives": [prim] }));
        let (x, z) = ((i % 8) as f32 * 2.5, (i / 8) as f32 * 2.5);
        nodes.push(json!({ "name": format!("cloth {i}"), "mesh": i, "translation": [x, 0.0, -z] }));
    }
    let materials: Vec<Value> = (0..materials.max(1))
        .map(|k| {
            let t = k as f32 / materials.max(1) as f32;
            let mut m = json!({ "name": format!("fabric {k}"),
                "pbrMetallicRoughness": { "baseColorFactor": [0.2 + 0.6 * t, 0.3, 0.8 - 0.6 * t, 1.0],
                                          "metallicFactor": 0.0, "roughnessFactor": 0.3 + 0.5 * t } });
            if k % 2 == 1 {
                m["extensions"] = json!({ "KHR_materials_sheen": { "sheenColorFactor": [0.5, 0.4, 0.6], "sheenRoughnessFactor": 0.2 + 0.6 * t } });
            }
            m
        })
        .collect();
    let json = json!({
        "asset": asset(),
        "extensionsUsed": ["KHR_materials_sheen"],
        "scene": 0,
        "scenes": [ { "nodes": (0..objects).collect::<Vec<_>>() } ],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "buffers": [ { "byteLength": packed.bin.len() } ],
        "bufferViews": packed.views,
        "accessors": packed.accessors,
    });
    glb(&json, &packed.bin)
}

/// Every committed file this generator makes, by path from the repository root.
pub fn committed_files() -> BTreeMap<String, Vec<u8>> {
    let mut out = BTreeMap::new();
    out.insert("scenes/gltf/showroom.glb".to_string(), showroom());
    let (gltf, bin) = bust();
    out.insert("tests/gltf/bust.gltf".to_string(), gltf);
    out.insert("tests/gltf/bust.bin".to_string(), bin);
    out.insert("tests/gltf/cutouts.glb".to_string(), cutouts());
    // Seeds of the fuzz smoke run's glTF target (docs/fuzzing.md).
    for (name, bytes) in [
        ("skinned_strip", skinned_strip()),
        ("morphing_triangle", morphing_triangle()),
        ("instanced_triangle", instanced_triangle()),
    ] {
        out.insert(format!("fuzz/corpus/gltf/{name}.glb"), bytes);
    }
    for (name, bytes, _, _) in hostile() {
        out.insert(format!("tests/gltf/bad/{name}.gltf"), bytes);
    }
    out
}
