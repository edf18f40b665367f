//! The committed scenes: the showroom, the cut-outs board and the bust.

use super::textures::{
    lace_base_color, wood_base_color, wood_metallic_roughness, wood_normals, wood_occlusion,
};
use super::{Packed, Prim, asset, block, glb, quat, rotation_to};
use serde_json::{Value, json};
use weft_render::{BustPart, Scene, SceneKind, bust_parts};

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
