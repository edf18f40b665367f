//! Files weft must refuse, each with the JSON pointer its error names.

use super::bytes;
use super::textures::png_rgba;
use serde_json::{Value, json};

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
        "attribute_not_a_semantic",
        &|v| {
            v["meshes"][0]["primitives"][0]["attributes"]["UVS"] = json!(0);
        },
        "/meshes/0/primitives/0/attributes",
        "not a glTF 2.0 semantic",
    );
    case(
        "positions_all_zero",
        &|v| {
            v["accessors"][0]
                .as_object_mut()
                .expect("accessor")
                .remove("bufferView");
        },
        "/accessors/0",
        "every element as zero",
    );
    case(
        "morph_weights_count",
        &|v| {
            v["meshes"][0]["primitives"][0]["targets"] =
                json!([ { "POSITION": 0 }, { "POSITION": 0 } ]);
            v["meshes"][0]["weights"] = json!([0.5]);
        },
        "/meshes/0/weights",
        "morph weights for the 2 targets",
    );
    case(
        "normal_not_finite",
        &|v| {
            // The positions' bytes again, as normals, with one NaN:
            // f32 0x7fc00000 in the second buffer.
            let mut normals: Vec<u8> = [[0.0f32, 0.0, 1.0]; 3]
                .iter()
                .flatten()
                .flat_map(|x| x.to_le_bytes())
                .collect();
            normals[8..12].copy_from_slice(&f32::NAN.to_le_bytes());
            v["buffers"]
                .as_array_mut()
                .expect("buffers")
                .push(json!({ "byteLength": 36, "uri": format!("data:application/octet-stream;base64,{}", b64(&normals)) }));
            v["bufferViews"]
                .as_array_mut()
                .expect("views")
                .push(json!({ "buffer": 1, "byteLength": 36 }));
            v["accessors"].as_array_mut().expect("accessors").push(
                json!({ "bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC3" }),
            );
            v["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = json!(2);
        },
        "/accessors/2",
        "not finite",
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
        "instance_counts_differ",
        &|v| {
            v["extensionsUsed"] = json!(["EXT_mesh_gpu_instancing"]);
            // Two scales for three translations (the positions' accessor).
            v["accessors"].as_array_mut().expect("accessors").push(
                json!({ "bufferView": 0, "componentType": 5126, "count": 2, "type": "VEC3" }),
            );
            v["nodes"][0]["extensions"] = json!({ "EXT_mesh_gpu_instancing": {
                "attributes": { "TRANSLATION": 0, "SCALE": 2 } } });
        },
        "/nodes/0/extensions/EXT_mesh_gpu_instancing/attributes/SCALE",
        "where the other attributes have 3",
    );
    case(
        "instances_past_the_scene_limit",
        &|v| {
            v["extensionsUsed"] = json!(["EXT_mesh_gpu_instancing"]);
            // Refused by its count alone, before any byte is read.
            v["accessors"].as_array_mut().expect("accessors").push(
                json!({ "bufferView": 0, "componentType": 5126, "count": 100000, "type": "VEC3" }),
            );
            v["nodes"][0]["extensions"] =
                json!({ "EXT_mesh_gpu_instancing": { "attributes": { "TRANSLATION": 2 } } });
        },
        "/nodes/0/extensions/EXT_mesh_gpu_instancing",
        "100000 instances",
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
