//! A glTF material's textures as weft image parameters: the texture
//! references (with `KHR_texture_transform`), their files, and what the
//! mapping loses (transforms weft cannot express, samplers, extension
//! textures it does not read).

// The parent's helpers (`num`, `float`, `round6`, `toml_string`) and types
// (`MaterialMapping`, `Literal`, `GltfFile`, `Value`).
use super::*;

/// A glTF `textureInfo` as weft reads it.
#[derive(Clone, Debug, PartialEq)]
struct TextureRef {
    /// `textures` index.
    index: usize,
    /// JSON pointer of the textureInfo (for losses).
    key: &'static str,
    /// `KHR_texture_transform`: scale (xy) and offset (zw) — weft's `_st`.
    tiling: [f64; 4],
    rotation: f64,
    tex_coord: u64,
}

/// The textureInfo at `key` (a `/`-separated path) of a material's JSON.
fn texture_ref(material: &Value, key: &'static str) -> Option<TextureRef> {
    let info = material.pointer(&format!("/{key}"))?;
    let index = usize::try_from(info.get("index")?.as_u64()?).ok()?;
    let t = info.pointer("/extensions/KHR_texture_transform");
    let pair = |k: &str, d: f64| -> [f64; 2] {
        let a = t.and_then(|t| t.get(k)).and_then(Value::as_array);
        [0, 1].map(|i| num(a.and_then(|a| a.get(i)), d))
    };
    let (scale, offset) = (pair("scale", 1.0), pair("offset", 0.0));
    let tex_coord = t
        .and_then(|t| t.get("texCoord"))
        .or_else(|| info.get("texCoord"))
        .and_then(Value::as_u64)
        .unwrap_or(0);
    Some(TextureRef {
        index,
        key,
        tiling: [scale[0], scale[1], offset[0], offset[1]],
        rotation: num(t.and_then(|t| t.get("rotation")), 0.0),
        tex_coord,
    })
}

/// `{ gltf = "…", texture = N }` with the base map's scale and offset.
fn image_value(gltf_ref: &str, fields: &str, tiling: Option<[f64; 4]>) -> Literal {
    let st = match tiling {
        Some([su, sv, ou, ov]) if [su, sv, ou, ov] != [1.0, 1.0, 0.0, 0.0] => format!(
            ", scale = [{}, {}], offset = [{}, {}]",
            float(su),
            float(sv),
            float(ou),
            float(ov)
        ),
        _ => String::new(),
    };
    format!("{{ gltf = {}, {fields}{st} }}", toml_string(gltf_ref))
}

/// glTF's textures bound to the weft material's maps, as images the scene
/// folder carries (docs/gltf.md "Textures"): base colour → `base_map`,
/// normal → `normal_map` (with `NORMAL_MAP` and `normal_strength`),
/// metallic-roughness + occlusion → `rmo_map` repacked (standard, laser)
/// or occlusion → `occlusion_map` (velvet). One uv transform per material
/// (the base map's tiling). Whatever else the file asks is a loss.
pub(super) fn map_textures(
    file: &GltfFile,
    index: usize,
    gltf_ref: &str,
    out: &mut MaterialMapping,
) {
    let Ok(json) = serde_json::to_value(&file.document.as_json().materials[index]) else {
        return;
    };
    let material = out.material.clone();
    let has_normal = matches!(material.as_str(), "standard" | "laser" | "velvet");
    let has_rmo = matches!(material.as_str(), "standard" | "laser");
    let base = texture_ref(&json, "pbrMetallicRoughness/baseColorTexture");
    let normal = texture_ref(&json, "normalTexture");
    let mr = texture_ref(&json, "pbrMetallicRoughness/metallicRoughnessTexture");
    let occlusion = texture_ref(&json, "occlusionTexture");
    let tiling = base.as_ref().map(|b| b.tiling);
    let mut used: Vec<&TextureRef> = Vec::new();
    if let Some(b) = &base {
        out.params.push((
            "base_map".into(),
            image_value(gltf_ref, &format!("texture = {}", b.index), tiling),
        ));
        used.push(b);
    }
    match &normal {
        Some(n) if has_normal => {
            out.keywords.push(("NORMAL_MAP".into(), "true".into()));
            out.params.push((
                "normal_map".into(),
                image_value(gltf_ref, &format!("texture = {}", n.index), None),
            ));
            let scale = num(json.pointer("/normalTexture/scale"), 1.0);
            if !(0.0..=2.0).contains(&scale) {
                out.losses.push(format!(
                    "normalTexture.scale {scale} (normal_strength is in [0, 2]: clamped)"
                ));
            }
            out.params.push((
                "normal_strength".into(),
                float(round6(scale.clamp(0.0, 2.0))),
            ));
            used.push(n);
        }
        Some(_) => out
            .losses
            .push(format!("normalTexture ({material} has no normal map)")),
        None => {}
    }
    let strength = num(json.pointer("/occlusionTexture/strength"), 1.0).clamp(0.0, 1.0);
    if has_rmo && (mr.is_some() || occlusion.is_some()) {
        let mut fields = Vec::new();
        if let Some(t) = &mr {
            fields.push(format!("metallic_roughness = {}", t.index));
            used.push(t);
        }
        if let Some(t) = &occlusion {
            fields.push(format!("occlusion = {}", t.index));
            out.params
                .push(("occlusion_strength".into(), float(round6(strength))));
            used.push(t);
        }
        out.params.push((
            "rmo_map".into(),
            image_value(gltf_ref, &fields.join(", "), None),
        ));
    } else {
        if material == "velvet"
            && let Some(t) = &occlusion
        {
            out.params.push((
                "occlusion_map".into(),
                image_value(gltf_ref, &format!("texture = {}", t.index), None),
            ));
            out.params
                .push(("occlusion_strength".into(), float(round6(strength))));
            used.push(t);
        } else if occlusion.is_some() {
            out.losses.push(format!(
                "occlusionTexture ({material} has no occlusion map)"
            ));
        }
        if mr.is_some() {
            out.losses.push(format!(
                "metallicRoughnessTexture ({material} has no roughness/metallic map: the factors alone are used)"
            ));
        }
    }
    transform_losses(&used, tiling, &mut out.losses);
    let emissive = map_emissive_texture(&json, gltf_ref, tiling, out);
    used.extend(emissive.as_ref());
    map_sampler(file, &used, out);
    extension_texture_losses(&json, &mut out.losses);
}

/// What the maps' texture references lose: rotation, a transform other
/// than the base map's (every map is read with its tiling), another UV set.
fn transform_losses(used: &[&TextureRef], tiling: Option<[f64; 4]>, losses: &mut Vec<String>) {
    for t in used {
        if t.rotation != 0.0 {
            losses.push(format!(
                "{}'s KHR_texture_transform rotation {} rad (weft's tiling is scale and offset)",
                t.key, t.rotation
            ));
        }
        // Every map is read with the base map's tiling (identity without one).
        if t.tiling != tiling.unwrap_or([1.0, 1.0, 0.0, 0.0]) {
            losses.push(format!(
                "{}'s KHR_texture_transform (the material's maps share the base colour texture's)",
                t.key
            ));
        }
        if t.tex_coord != 0 {
            losses.push(format!(
                "{}'s texCoord {} (weft's materials read TEXCOORD_0)",
                t.key, t.tex_coord
            ));
        }
    }
}

/// glTF's emissive texture → standard's `emissive_map` (glTF multiplies the
/// texture by emissiveFactor, default black: a texture without a factor
/// emits nothing). Returns the texture when it is bound.
fn map_emissive_texture(
    json: &Value,
    gltf_ref: &str,
    tiling: Option<[f64; 4]>,
    out: &mut MaterialMapping,
) -> Option<TextureRef> {
    let material = out.material.clone();
    let emits = json
        .get("emissiveFactor")
        .and_then(Value::as_array)
        .is_some_and(|f| f.iter().any(|x| x.as_f64().unwrap_or(0.0) > 0.0));
    // glTF multiplies the texture by emissiveFactor (default black): a
    // texture without a factor emits nothing.
    let t = texture_ref(json, "emissiveTexture").filter(|_| emits)?;
    if material != "standard" {
        out.losses.push(format!(
            "emissiveTexture ({material} does not emit; standard does)"
        ));
        return None;
    }
    out.params.push((
        "emissive_map".into(),
        image_value(gltf_ref, &format!("texture = {}", t.index), None),
    ));
    if t.tiling != tiling.unwrap_or([1.0, 1.0, 0.0, 0.0]) {
        out.losses.push(
            "emissiveTexture's KHR_texture_transform (the material's maps share the base colour texture's)"
                .into(),
        );
    }
    Some(t)
}

/// Textures of extensions whose factors are mapped (or not at all): named as
/// losses, since only the factors are carried.
fn extension_texture_losses(json: &Value, losses: &mut Vec<String>) {
    for (has, name) in [
        (
            json.pointer("/extensions/KHR_materials_specular/specularTexture")
                .is_some(),
            "KHR_materials_specular.specularTexture",
        ),
        (
            json.pointer("/extensions/KHR_materials_specular/specularColorTexture")
                .is_some(),
            "KHR_materials_specular.specularColorTexture",
        ),
    ] {
        if has {
            losses.push(format!("{name} (not carried: the factor alone is used)"));
        }
    }
    if let Some(Value::Object(exts)) = json.get("extensions") {
        for (ext, v) in exts
            .iter()
            .filter(|(e, _)| e.as_str() != "KHR_materials_specular")
        {
            if let Value::Object(fields) = v {
                for k in fields.keys().filter(|k| k.ends_with("Texture")) {
                    losses.push(format!("{ext}.{k} (not carried)"));
                }
            }
        }
    }
}

/// The glTF samplers of the maps bound → the instance's `sampler` (the state
/// of `material_sampler`, through which a weft material reads every map).
/// Maps that ask for different samplers get the first one's (the base
/// colour texture's when there is one): a loss, named.
fn map_sampler(file: &GltfFile, used: &[&TextureRef], out: &mut MaterialMapping) {
    let asked: Vec<(&TextureRef, Option<usize>, Option<Literal>)> = used
        .iter()
        .map(|t| {
            let sampler = file
                .document
                .textures()
                .nth(t.index)
                .map(|texture| texture.sampler());
            let index = sampler.as_ref().and_then(|s| s.index());
            (*t, index, sampler.as_ref().and_then(sampler_literal))
        })
        .collect();
    let Some((_, _, first)) = asked.first() else {
        return;
    };
    out.sampler = first.clone();
    let differing: Vec<String> = asked
        .iter()
        .filter(|(_, _, l)| l != first)
        .map(|(t, i, _)| match i {
            Some(i) => format!("{} (sampler {i})", t.key),
            None => format!("{} (the default sampler)", t.key),
        })
        .collect();
    if !differing.is_empty() {
        out.losses.push(format!(
            "{}'s sampler differs from {}'s (weft reads a material's maps through one sampler: {}'s)",
            differing.join(", "),
            asked[0].0.key,
            asked[0].0.key
        ));
    }
}

/// A glTF sampler as the fields of weft's `sampler = { … }` it changes
/// (None: trilinear and repeating, the material's own).
fn sampler_literal(sampler: &gltf::texture::Sampler) -> Option<Literal> {
    use gltf::texture::{MagFilter, MinFilter, WrappingMode};
    let mut fields = Vec::new();
    for (key, mode) in [
        ("address_mode_u", sampler.wrap_s()),
        ("address_mode_v", sampler.wrap_t()),
    ] {
        let name = match mode {
            WrappingMode::Repeat => continue,
            WrappingMode::ClampToEdge => "clamp_to_edge",
            WrappingMode::MirroredRepeat => "mirror_repeat",
        };
        fields.push(format!("{key} = \"{name}\""));
    }
    if sampler.mag_filter() == Some(MagFilter::Nearest) {
        fields.push("mag_filter = \"nearest\"".into());
    }
    // glTF's minFilter: the texel filter, the filter between mip levels,
    // and whether mip levels are read at all.
    let (min_nearest, mip_nearest, mipmaps) = match sampler.min_filter() {
        None | Some(MinFilter::LinearMipmapLinear) => (false, false, true),
        Some(MinFilter::Nearest) => (true, false, false),
        Some(MinFilter::Linear) => (false, false, false),
        Some(MinFilter::NearestMipmapNearest) => (true, true, true),
        Some(MinFilter::LinearMipmapNearest) => (false, true, true),
        Some(MinFilter::NearestMipmapLinear) => (true, false, true),
    };
    if min_nearest {
        fields.push("min_filter = \"nearest\"".into());
    }
    if mip_nearest {
        fields.push("mipmap_filter = \"nearest\"".into());
    }
    if !mipmaps {
        fields.push("mipmaps = false".into());
    }
    (!fields.is_empty()).then(|| format!("{{ {} }}", fields.join(", ")))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Material 0 of a glTF whose textures 0 and 1 use `samplers`' entries
    /// as `texture_samplers` says, mapped.
    fn mapped(samplers: Value, texture_samplers: [Option<u64>; 2]) -> MaterialMapping {
        let textures: Vec<Value> = texture_samplers
            .iter()
            .map(|s| match s {
                Some(i) => serde_json::json!({ "source": 0, "sampler": i }),
                None => serde_json::json!({ "source": 0 }),
            })
            .collect();
        let json = serde_json::json!({
            "asset": { "version": "2.0" },
            "images": [ { "uri": "a.png" } ],
            "samplers": samplers,
            "textures": textures,
            "materials": [ {
                "pbrMetallicRoughness": { "baseColorTexture": { "index": 0 },
                    "metallicRoughnessTexture": { "index": 1 } } } ]
        });
        let mut warnings = Vec::new();
        let file = GltfFile::from_bytes(
            std::path::Path::new("t.gltf"),
            None,
            serde_json::to_vec(&json).unwrap(),
            &mut warnings,
        )
        .unwrap();
        super::super::map_material(&file, Some(0), "t.gltf").unwrap()
    }

    #[test]
    fn a_gltf_sampler_becomes_the_instances_sampler() {
        // CLAMP_TO_EDGE, MIRRORED_REPEAT, NEAREST, LINEAR (no mip levels).
        let samplers = serde_json::json!([
            { "wrapS": 33071, "wrapT": 33648, "magFilter": 9728, "minFilter": 9729 }
        ]);
        let m = mapped(samplers, [Some(0), Some(0)]);
        assert_eq!(
            m.sampler.as_deref(),
            Some(
                "{ address_mode_u = \"clamp_to_edge\", address_mode_v = \"mirror_repeat\", \
                 mag_filter = \"nearest\", mipmaps = false }"
            )
        );
        assert!(m.losses.is_empty(), "{:?}", m.losses);
        // Trilinear repeat, stated or left out, is the material's own.
        let trilinear = serde_json::json!([
            { "wrapS": 10497, "wrapT": 10497, "magFilter": 9729, "minFilter": 9987 }
        ]);
        let m = mapped(trilinear, [Some(0), None]);
        assert_eq!(m.sampler, None);
        assert!(m.losses.is_empty(), "{:?}", m.losses);
    }

    #[test]
    fn maps_with_different_samplers_take_the_base_colours_and_say_so() {
        let samplers = serde_json::json!([
            { "minFilter": 9984 },
            { "wrapS": 33071 }
        ]);
        let m = mapped(samplers, [Some(0), Some(1)]);
        assert_eq!(
            m.sampler.as_deref(),
            Some("{ min_filter = \"nearest\", mipmap_filter = \"nearest\" }")
        );
        assert_eq!(
            m.losses,
            [
                "pbrMetallicRoughness/metallicRoughnessTexture (sampler 1)'s sampler differs from \
              pbrMetallicRoughness/baseColorTexture's (weft reads a material's maps through one \
              sampler: pbrMetallicRoughness/baseColorTexture's)"
            ]
        );
    }
}
