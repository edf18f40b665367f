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
//! - [`hostile`]: files weft must refuse, each with the JSON pointer the
//!   error names (tests/rendering/gltf_scenes.rs).
//!
//! `cargo xtask gltf-samples` writes the committed files; a test keeps
//! them equal to this generator.

use serde_json::{Value, json};
use std::collections::BTreeMap;
use weft_render::{BustPart, Mesh, Scene, SceneKind, bust_parts};

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

/// The showroom GLB (see the module docs).
pub fn showroom() -> Vec<u8> {
    let materials = json!([
        { "name": "Velvet drape",
          "pbrMetallicRoughness": { "baseColorFactor": [0.18, 0.02, 0.05, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.8 },
          "extensions": { "KHR_materials_sheen": { "sheenColorFactor": [0.55, 0.22, 0.3], "sheenRoughnessFactor": 0.6 } } },
        { "name": "Sofa frame",
          "pbrMetallicRoughness": { "baseColorFactor": [0.32, 0.2, 0.12, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.45 },
          "extensions": { "KHR_materials_specular": { "specularFactor": 0.5 } } },
        { "name": "Cushion",
          "pbrMetallicRoughness": { "baseColorFactor": [0.05, 0.12, 0.3, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.9 },
          "extensions": { "KHR_materials_sheen": { "sheenColorFactor": [0.3, 0.4, 0.7], "sheenRoughnessFactor": 0.35 } } },
        { "name": "Cushion linen",
          "pbrMetallicRoughness": { "baseColorFactor": [0.6, 0.55, 0.45, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.85 } },
        { "name": "Holographic foil",
          "pbrMetallicRoughness": { "baseColorFactor": [0.9, 0.9, 0.9, 1.0], "metallicFactor": 1.0, "roughnessFactor": 0.2 },
          "extensions": { "KHR_materials_iridescence": { "iridescenceFactor": 1.0, "iridescenceIor": 1.8,
              "iridescenceThicknessMinimum": 100.0, "iridescenceThicknessMaximum": 420.0 } } },
        { "name": "Satin ball",
          "pbrMetallicRoughness": { "baseColorFactor": [0.7, 0.45, 0.1, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.35 },
          "extensions": { "KHR_materials_anisotropy": { "anisotropyStrength": 0.6 } } },
        { "name": "Shot silk",
          "pbrMetallicRoughness": { "baseColorFactor": [0.5, 0.2, 0.5, 1.0] },
          "extras": { "weft": { "material": "microcylinder", "preset": "silk_shot", "tier": "fast" } } },
    ]);
    let mut packed = Packed {
        bin: Vec::new(),
        views: Vec::new(),
        accessors: Vec::new(),
    };
    let cloth = Scene::new(SceneKind::Cloth).mesh;
    let sphere = Scene::new(SceneKind::Sphere).mesh;
    let swatch = Scene::new(SceneKind::Swatch).mesh;
    // Cloth without tangents (MikkTSpace), sphere with its own.
    let drape = packed.primitive(&Prim::from_mesh(&cloth, 0, false), None);
    let ball = packed.primitive(&Prim::from_mesh(&sphere, 5, true), None);
    let foil = packed.primitive(&Prim::from_mesh(&swatch, 4, false), None);
    let silk = packed.primitive(&Prim::from_mesh(&swatch, 6, false), None);
    let frame: Vec<Value> = [
        block([0.0, 0.2, 0.0], [0.9, 0.2, 0.4], 1),
        block([0.0, 0.55, -0.32], [0.9, 0.35, 0.08], 1),
        block([-0.82, 0.45, 0.0], [0.08, 0.25, 0.4], 1),
        block([0.82, 0.45, 0.0], [0.08, 0.25, 0.4], 1),
    ]
    .iter()
    .map(|b| packed.primitive(b, None))
    .collect();
    let cushion_variants = json!({ "mappings": [ { "material": 3, "variants": [1] } ] });
    let cushions: Vec<Value> = [
        block([-0.4, 0.47, 0.02], [0.36, 0.07, 0.34], 2),
        block([0.4, 0.47, 0.02], [0.36, 0.07, 0.34], 2),
    ]
    .iter()
    .map(|b| packed.primitive(b, Some(cushion_variants.clone())))
    .collect();
    let mut sofa = frame;
    sofa.extend(cushions);
    let json = json!({
        "asset": asset(),
        "extensionsUsed": ["KHR_materials_sheen", "KHR_materials_specular", "KHR_materials_iridescence",
                           "KHR_materials_anisotropy", "KHR_lights_punctual", "KHR_materials_variants"],
        "scene": 0,
        "scenes": [ { "name": "Showroom", "nodes": [0, 1, 2, 3, 4, 5, 6, 7] } ],
        "nodes": [
            { "name": "Drape", "mesh": 0, "translation": [-1.2, 0.9, 0.0], "rotation": quat([1.0, 0.0, 0.0], 70.0), "scale": [0.6, 0.6, 0.6] },
            { "name": "Sofa", "mesh": 1, "translation": [0.4, 0.0, -0.4], "rotation": quat([0.0, 1.0, 0.0], -15.0) },
            { "name": "Foil swatch", "mesh": 2, "translation": [1.25, 0.75, 0.2], "scale": [0.35, 0.35, 0.35] },
            { "name": "Satin ball", "mesh": 3, "translation": [-0.5, 0.35, 0.9], "scale": [0.35, 0.35, 0.35] },
            { "name": "Shot silk swatch", "mesh": 4, "translation": [1.25, 0.1, 0.2], "scale": [0.35, 0.35, 0.35] },
            { "name": "Camera", "camera": 0, "translation": [0.05, 0.9, 3.6], "rotation": quat([1.0, 0.0, 0.0], -8.0) },
            { "name": "Sun", "rotation": rotation_to([-0.62, 0.55, 0.56]),
              "extensions": { "KHR_lights_punctual": { "light": 0 } } },
            { "name": "Lamp", "translation": [1.0, 2.0, 1.0], "extensions": { "KHR_lights_punctual": { "light": 1 } } },
        ],
        "meshes": [
            { "name": "drape", "primitives": [drape] },
            { "name": "sofa", "primitives": sofa },
            { "name": "foil", "primitives": [foil] },
            { "name": "ball", "primitives": [ball] },
            { "name": "silk swatch", "primitives": [silk] },
        ],
        "materials": materials,
        "cameras": [ { "type": "perspective", "perspective": { "yfov": 0.6, "znear": 0.1, "aspectRatio": 1.6 } } ],
        "extensions": {
            "KHR_lights_punctual": { "lights": [
                { "type": "directional", "color": [1.0, 0.96, 0.9], "intensity": 3.0 },
                { "type": "point", "color": [1.0, 0.8, 0.6], "intensity": 20.0 } ] },
            "KHR_materials_variants": { "variants": [ { "name": "velvet cushions" }, { "name": "linen cushions" } ] }
        },
        "buffers": [ { "byteLength": packed.bin.len() } ],
        "bufferViews": packed.views,
        "accessors": packed.accessors,
    });
    glb(&json, &packed.bin)
}

/// `tests/gltf/cutouts.glb`: glTF's alpha modes, sides and emission on core
/// materials — a lace panel (MASK, doubleSided, turned so that its back
/// face shows, its texture read through its own sampler), a glowing bulb
/// (emissive × KHR_materials_emissive_strength), a glass block (BLEND), a
/// frame with the four core maps and a tile whose maps share a rotated
/// KHR_texture_transform — framed by weft (no camera).
pub fn cutouts() -> Vec<u8> {
    let materials = json!([
        { "name": "Lace",
          "pbrMetallicRoughness": { "baseColorFactor": [0.95, 0.92, 0.88, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.7,
              "baseColorTexture": { "index": 0 } },
          "alphaMode": "MASK", "alphaCutoff": 0.4, "doubleSided": true },
        { "name": "Glow bulb",
          "pbrMetallicRoughness": { "baseColorFactor": [0.9, 0.85, 0.8, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.4 },
          "emissiveFactor": [1.0, 0.6, 0.3],
          "extensions": { "KHR_materials_emissive_strength": { "emissiveStrength": 2.5 } } },
        { "name": "Tinted glass",
          "pbrMetallicRoughness": { "baseColorFactor": [0.6, 0.8, 0.9, 0.35], "metallicFactor": 0.0, "roughnessFactor": 0.1 },
          "alphaMode": "BLEND" },
        { "name": "Textured frame",
          "pbrMetallicRoughness": { "baseColorFactor": [0.8, 0.62, 0.45, 1.0], "metallicFactor": 1.0, "roughnessFactor": 1.0,
              "baseColorTexture": { "index": 1,
                  "extensions": { "KHR_texture_transform": { "scale": [2.0, 1.0], "offset": [0.25, 0.0] } } },
              "metallicRoughnessTexture": { "index": 3,
                  "extensions": { "KHR_texture_transform": { "scale": [2.0, 1.0], "offset": [0.25, 0.0] } } } },
          "normalTexture": { "index": 2, "scale": 0.8,
              "extensions": { "KHR_texture_transform": { "scale": [2.0, 1.0], "offset": [0.25, 0.0] } } },
          "occlusionTexture": { "index": 4, "strength": 0.7,
              "extensions": { "KHR_texture_transform": { "scale": [2.0, 1.0], "offset": [0.25, 0.0] } } },
          "extensions": { "KHR_materials_specular": { "specularFactor": 0.5 } } },
        // One rotated KHR_texture_transform on both maps: baked into the
        // primitive's uv0 (weft's tiling is scale and offset).
        { "name": "Rotated tiles",
          "pbrMetallicRoughness": { "baseColorFactor": [1.0, 1.0, 1.0, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.6,
              "baseColorTexture": { "index": 1,
                  "extensions": { "KHR_texture_transform": { "offset": [0.1, 0.2], "rotation": 0.5, "scale": [3.0, 2.0] } } } },
          "normalTexture": { "index": 2,
              "extensions": { "KHR_texture_transform": { "offset": [0.1, 0.2], "rotation": 0.5, "scale": [3.0, 2.0] } } } },
    ]);
    let mut packed = Packed {
        bin: Vec::new(),
        views: Vec::new(),
        accessors: Vec::new(),
    };
    let sphere = Scene::new(SceneKind::Sphere).mesh;
    let swatch = Scene::new(SceneKind::Swatch).mesh;
    let lace = packed.primitive(&Prim::from_mesh(&swatch, 0, false), None);
    let bulb = packed.primitive(&Prim::from_mesh(&sphere, 1, true), None);
    let glass = packed.primitive(&block([0.0; 3], [0.3, 0.3, 0.3], 2), None);
    let frame = packed.primitive(&block([0.0; 3], [0.5, 0.25, 0.2], 3), None);
    let tiles = packed.primitive(&block([0.0; 3], [0.5, 0.25, 0.2], 4), None);
    // The images, stored in the BIN chunk: the lace's alpha PNG, then the
    // frame's maps as PNG and JPEG of three sizes (the occlusion map is
    // resampled into the RMO map's size).
    let images: Vec<Value> = [
        (lace_base_color(), "image/png"),
        (wood_base_color(), "image/png"),
        (wood_normals(), "image/png"),
        (wood_metallic_roughness(), "image/jpeg"),
        (wood_occlusion(), "image/png"),
    ]
    .into_iter()
    .map(|(data, mime)| {
        let view = packed.push(data, 0);
        packed.views[view]
            .as_object_mut()
            .expect("view")
            .remove("target");
        json!({ "bufferView": view, "mimeType": mime })
    })
    .collect();
    let json = json!({
        "asset": asset(),
        "extensionsUsed": ["KHR_materials_emissive_strength", "KHR_materials_specular", "KHR_texture_transform"],
        "scene": 0,
        "scenes": [ { "name": "Cutouts", "nodes": [0, 1, 2, 3, 4] } ],
        "nodes": [
            { "name": "Lace panel", "mesh": 0, "translation": [-1.0, 0.0, 0.0], "rotation": quat([0.0, 1.0, 0.0], 160.0), "scale": [0.6, 0.6, 0.6] },
            { "name": "Glow bulb", "mesh": 1, "translation": [0.2, 0.0, 0.0], "scale": [0.3, 0.3, 0.3] },
            { "name": "Glass block", "mesh": 2, "translation": [1.1, 0.0, 0.2] },
            { "name": "Textured frame", "mesh": 3, "translation": [0.0, -0.8, 0.0] },
            { "name": "Rotated tiles", "mesh": 4, "translation": [1.2, -0.8, 0.0] },
        ],
        "meshes": [
            { "name": "lace", "primitives": [lace] },
            { "name": "bulb", "primitives": [bulb] },
            { "name": "glass", "primitives": [glass] },
            { "name": "frame", "primitives": [frame] },
            { "name": "tiles", "primitives": [tiles] },
        ],
        "materials": materials,
        // The frame's maps: trilinear repeat, stated (sampler 0) or left
        // out; the lace's: clamped across, mirrored along, nearest texels
        // when magnified, no mip levels (sampler 1).
        "textures": [ { "source": 0, "sampler": 1 }, { "source": 1, "sampler": 0 }, { "source": 2, "sampler": 0 }, { "source": 3, "sampler": 0 }, { "source": 4 } ],
        "samplers": [ { "magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497 },
                      { "magFilter": 9728, "minFilter": 9729, "wrapS": 33071, "wrapT": 33648 } ],
        "images": images,
        "buffers": [ { "byteLength": packed.bin.len() } ],
        "bufferViews": packed.views,
        "accessors": packed.accessors,
    });
    glb(&json, &packed.bin)
}

/// A PNG of `w` × `h` RGB(A) texels from `f(x, y)`.
pub fn png_rgba(w: u32, h: u32, f: impl Fn(u32, u32) -> [u8; 4]) -> Vec<u8> {
    let data: Vec<u8> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .flat_map(|(x, y)| f(x, y))
        .collect();
    let mut out = Vec::new();
    let mut e = png::Encoder::new(&mut out, w, h);
    e.set_color(png::ColorType::Rgba);
    e.set_depth(png::BitDepth::Eight);
    let mut writer = e.write_header().expect("png header");
    writer.write_image_data(&data).expect("png data");
    writer.finish().expect("png end");
    out
}

/// Wood grain: stripes along u with a slow wobble (sRGB).
fn wood_grain(x: u32, y: u32) -> f32 {
    let (u, v) = (x as f32 / 64.0, y as f32 / 64.0);
    let ring = (v * 9.0 + 0.6 * (u * std::f32::consts::TAU).sin()).fract();
    (ring * std::f32::consts::PI).sin().powi(4)
}

pub fn wood_base_color() -> Vec<u8> {
    png_rgba(64, 64, |x, y| {
        let g = wood_grain(x, y);
        let c = |lo: f32, hi: f32| (255.0 * (lo + (hi - lo) * g)).round() as u8;
        [c(0.62, 0.38), c(0.42, 0.22), c(0.26, 0.12), 255]
    })
}

/// Tangent-space normals of the grain's height (grooves where it is dark).
fn wood_normals() -> Vec<u8> {
    png_rgba(64, 64, |x, y| {
        let dv = wood_grain(x, (y + 1) % 64) - wood_grain(x, (y + 63) % 64);
        let n = [0.0f32, -dv * 1.5, 1.0];
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        let e = |c: f32| (255.0 * (c / len * 0.5 + 0.5)).round() as u8;
        [e(n[0]), e(n[1]), e(n[2]), 255]
    })
}

/// glTF metallic-roughness (G roughness, B metallic) as a JPEG: rough in
/// the grain, a brass inlay band (metallic) across the middle.
pub fn wood_metallic_roughness() -> Vec<u8> {
    let (w, h) = (32u16, 32u16);
    let data: Vec<u8> = (0..u32::from(h))
        .flat_map(|y| {
            (0..u32::from(w)).flat_map(move |x| {
                let inlay = (14..18).contains(&y);
                let rough = if inlay {
                    0.3
                } else {
                    0.55 + 0.35 * wood_grain(x * 2, y * 2)
                };
                [0, (255.0 * rough) as u8, if inlay { 255 } else { 0 }]
            })
        })
        .collect();
    let mut out = Vec::new();
    jpeg_encoder::Encoder::new(&mut out, 95)
        .encode(&data, w, h, jpeg_encoder::ColorType::Rgb)
        .expect("jpeg");
    out
}

/// Lace: a white ground with round holes (alpha 0) on a 4 × 4 grid, for
/// `alphaMode: MASK` (32 × 32, sRGB with alpha).
fn lace_base_color() -> Vec<u8> {
    png_rgba(32, 32, |x, y| {
        let (cx, cy) = ((x % 8) as f32 - 3.5, (y % 8) as f32 - 3.5);
        let hole = cx * cx + cy * cy < 6.0;
        [245, 240, 230, if hole { 0 } else { 255 }]
    })
}

/// Ambient occlusion, darker towards the edges of each face (R; 16 × 16).
fn wood_occlusion() -> Vec<u8> {
    png_rgba(16, 16, |x, y| {
        let d = |t: u32| (t as f32 + 0.5) / 16.0 * (1.0 - (t as f32 + 0.5) / 16.0) * 4.0;
        let ao = (0.45 + 0.55 * (d(x) * d(y)).sqrt()).min(1.0);
        let a = (255.0 * ao).round() as u8;
        [a, a, a, 255]
    })
}

/// The bust as `.gltf` JSON and its `.bin`: each part's weft material from
/// `extras.weft`, as a DCC's custom properties would carry it.
pub fn bust() -> (Vec<u8>, Vec<u8>) {
    let weft = |material: &str, tier: Option<&str>, keywords: Value| {
        let mut w = json!({ "material": material, "keywords": keywords });
        if let Some(t) = tier {
            w["tier"] = json!(t);
        }
        json!({ "weft": w })
    };
    let materials = json!([
        { "name": "Face", "extras": weft("face", None, json!({ "OUTLINE": true })) },
        { "name": "Eyes", "extras": weft("eye", Some("fast"), json!({})) },
        { "name": "Hair", "extras": weft("hair", Some("fast"), json!({ "OUTLINE": true })) },
        { "name": "Skin", "extras": weft("skin", Some("fast"), json!({ "OUTLINE": true })) },
    ]);
    let mut packed = Packed {
        bin: Vec::new(),
        views: Vec::new(),
        accessors: Vec::new(),
    };
    let mut meshes = Vec::new();
    for (part, mesh) in bust_parts() {
        let material = BustPart::ALL.iter().position(|p| *p == part).unwrap_or(0);
        let prim = packed.primitive(&Prim::from_mesh(&mesh, material, true), None);
        meshes.push(json!({ "name": part.name(), "primitives": [prim] }));
    }
    let nodes: Vec<Value> = (0..meshes.len())
        .map(|i| json!({ "name": BustPart::ALL[i].name(), "mesh": i }))
        .collect();
    let json = json!({
        "asset": asset(),
        "scene": 0,
        "scenes": [ { "nodes": [0, 1, 2, 3] } ],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "buffers": [ { "uri": "bust.bin", "byteLength": packed.bin.len() } ],
        "bufferViews": packed.views,
        "accessors": packed.accessors,
    });
    let mut text = serde_json::to_vec_pretty(&json).expect("json");
    text.push(b'\n');
    (text, packed.bin)
}

/// A small valid triangle file (base for the hostile cases).
fn triangle() -> Value {
    let positions: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let data: Vec<u8> = bytes(&positions)
        .into_iter()
        .chain([0u16, 1, 2, 0].iter().flat_map(|i| i.to_le_bytes()))
        .collect();
    use base64::Engine as _;
    let uri = format!(
        "data:application/octet-stream;base64,{}",
        base64::engine::general_purpose::STANDARD.encode(&data)
    );
    json!({
        "asset": { "version": "2.0" },
        "scene": 0,
        "scenes": [ { "nodes": [0] } ],
        "nodes": [ { "mesh": 0 } ],
        "meshes": [ { "primitives": [ { "attributes": { "POSITION": 0 }, "indices": 1, "material": 0 } ] } ],
        "materials": [ { "name": "plain" } ],
        "buffers": [ { "byteLength": 44, "uri": uri } ],
        "bufferViews": [ { "buffer": 0, "byteOffset": 0, "byteLength": 36 }, { "buffer": 0, "byteOffset": 36, "byteLength": 6 } ],
        "accessors": [
            { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0] },
            { "bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR" }
        ]
    })
}

/// Files weft must refuse: (name, `.gltf` JSON, the JSON pointer the error
/// names, a phrase the message contains).
pub fn hostile() -> Vec<(&'static str, Vec<u8>, &'static str, &'static str)> {
    let mut out = Vec::new();
    let mut case = |name: &'static str,
                    edit: &dyn Fn(&mut Value),
                    pointer: &'static str,
                    phrase: &'static str| {
        let mut v = triangle();
        edit(&mut v);
        out.push((
            name,
            serde_json::to_vec_pretty(&v).expect("json"),
            pointer,
            phrase,
        ));
    };
    // Images are read when an instance binds them: each case's material
    // has a base colour texture.
    let textured = |v: &mut Value, image: Value, texture: Value| {
        v["materials"][0]["pbrMetallicRoughness"] = json!({ "baseColorTexture": { "index": 0 } });
        v["textures"] = json!([texture]);
        v["images"] = json!([image]);
    };
    let b64 = |bytes: &[u8]| {
        use base64::Engine as _;
        base64::engine::general_purpose::STANDARD.encode(bytes)
    };
    case(
        "image_outside_folder",
        &|v| {
            textured(
                v,
                json!({ "uri": "../../secret.png" }),
                json!({ "source": 0 }),
            )
        },
        "/images/0",
        "leaves the file's folder",
    );
    case(
        "image_webp_data_uri",
        &|v| {
            let uri = format!("data:image/webp;base64,{}", b64(b"RIFF\0\0\0\0WEBPVP8 "));
            textured(v, json!({ "uri": uri }), json!({ "source": 0 }))
        },
        "/images/0",
        "image/webp",
    );
    case(
        "image_not_an_image",
        &|v| {
            let uri = format!("data:image/png;base64,{}", b64(b"not a picture at all"));
            textured(v, json!({ "uri": uri }), json!({ "source": 0 }))
        },
        "/images/0",
        "neither a PNG nor a JPEG",
    );
    case(
        "image_truncated_png",
        &|v| {
            let mut png = png_rgba(8, 8, |x, y| [x as u8 * 30, y as u8 * 30, 0, 255]);
            png.truncate(png.len() / 2);
            let uri = format!("data:image/png;base64,{}", b64(&png));
            textured(v, json!({ "uri": uri }), json!({ "source": 0 }))
        },
        "/images/0",
        "cannot decode",
    );
    case(
        "required_clearcoat",
        &|v| {
            v["extensionsUsed"] = json!(["KHR_materials_clearcoat"]);
            v["extensionsRequired"] = json!(["KHR_materials_clearcoat"]);
            v["materials"][0]["extensions"] =
                json!({ "KHR_materials_clearcoat": { "clearcoatFactor": 1.0 } });
        },
        "/materials/0/extensions/KHR_materials_clearcoat",
        "cannot honour",
    );
    case(
        "required_draco",
        &|v| {
            v["extensionsUsed"] = json!(["KHR_draco_mesh_compression"]);
            v["extensionsRequired"] = json!(["KHR_draco_mesh_compression"]);
            v["meshes"][0]["primitives"][0]["extensions"] = json!({ "KHR_draco_mesh_compression": { "bufferView": 0, "attributes": { "POSITION": 0 } } });
        },
        "/meshes/0/primitives/0/extensions/KHR_draco_mesh_compression",
        "cannot honour",
    );
    case(
        "required_basisu",
        &|v| {
            v["extensionsUsed"] = json!(["KHR_texture_basisu"]);
            v["extensionsRequired"] = json!(["KHR_texture_basisu"]);
        },
        "/extensionsRequired/0",
        "cannot honour",
    );
    case(
        "truncated_buffer",
        &|v| {
            v["buffers"][0]["byteLength"] = json!(4000);
        },
        "/buffers/0",
        "truncated",
    );
    case(
        "index_out_of_range",
        &|v| {
            use base64::Engine as _;
            let positions: [[f32; 3]; 3] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
            let data: Vec<u8> = bytes(&positions)
                .into_iter()
                .chain([0u16, 1, 7, 0].iter().flat_map(|i| i.to_le_bytes()))
                .collect();
            v["buffers"][0]["uri"] = json!(format!(
                "data:application/octet-stream;base64,{}",
                base64::engine::general_purpose::STANDARD.encode(&data)
            ));
        },
        "/meshes/0/primitives/0/indices",
        "out of range",
    );
    case(
        "accessor_past_view",
        &|v| {
            v["accessors"][0]["count"] = json!(4);
        },
        "/accessors/0",
        "run past",
    );
    case(
        "billion_elements",
        &|v| {
            v["accessors"][0]["count"] = json!(1_000_000_000u64);
        },
        "/accessors/0",
        "elements",
    );
    case(
        "uri_escapes",
        &|v| {
            v["buffers"][0]["uri"] = json!("../../etc/passwd");
        },
        "/buffers/0",
        "leaves the file's folder",
    );
    case(
        "data_uri_wrong_type",
        &|v| {
            v["buffers"][0]["uri"] = json!("data:image/png;base64,AAAA");
        },
        "/buffers/0",
        "image/png",
    );
    case(
        "node_cycle",
        &|v| {
            v["nodes"] = json!([ { "mesh": 0, "children": [1] }, { "children": [0] } ]);
        },
        "/nodes/1/children",
        "cycle",
    );
    case(
        "bad_accessor_index",
        &|v| {
            v["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = json!(9);
        },
        "/meshes/0/primitives/0/attributes/POSITION",
        "invalid glTF",
    );
    case(
        "positions_as_bytes",
        &|v| {
            v["accessors"][0]["componentType"] = json!(5121);
        },
        "/accessors/0",
        "does not allow",
    );
    case(
        "variant_mapping_out_of_range",
        &|v| {
            v["extensionsUsed"] = json!(["KHR_materials_variants"]);
            v["extensions"] =
                json!({ "KHR_materials_variants": { "variants": [ { "name": "a" } ] } });
            v["meshes"][0]["primitives"][0]["extensions"] = json!({
                "KHR_materials_variants": { "mappings": [ { "material": 5, "variants": [0] } ] }
            });
        },
        "/meshes/0/primitives/0/extensions/KHR_materials_variants/mappings/0",
        "does not have",
    );
    case(
        "extras_weft_unknown_key",
        &|v| {
            v["materials"][0]["extras"] =
                json!({ "weft": { "material": "standard", "colour": 1 } });
        },
        "/materials/0/extras/weft/colour",
        "unknown key",
    );
    out
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
    let cloth = Mesh::cloth(res);
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
    for (name, bytes, _, _) in hostile() {
        out.insert(format!("tests/gltf/bad/{name}.gltf"), bytes);
    }
    out
}
