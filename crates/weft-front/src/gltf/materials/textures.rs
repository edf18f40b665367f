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
    transform_losses(file, &used, tiling, &mut out.losses);
    map_emissive_texture(file, &json, gltf_ref, tiling, out);
    extension_texture_losses(&json, &mut out.losses);
}

/// What the maps' texture references lose: rotation, a transform other
/// than the base map's (every map is read with its tiling), another UV set,
/// a sampler other than trilinear repeat.
fn transform_losses(
    file: &GltfFile,
    used: &[&TextureRef],
    tiling: Option<[f64; 4]>,
    losses: &mut Vec<String>,
) {
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
        sampler_losses(file, t, losses);
    }
}

/// glTF's emissive texture → standard's `emissive_map` (glTF multiplies the
/// texture by emissiveFactor, default black: a texture without a factor
/// emits nothing).
fn map_emissive_texture(
    file: &GltfFile,
    json: &Value,
    gltf_ref: &str,
    tiling: Option<[f64; 4]>,
    out: &mut MaterialMapping,
) {
    let material = out.material.clone();
    let emits = json
        .get("emissiveFactor")
        .and_then(Value::as_array)
        .is_some_and(|f| f.iter().any(|x| x.as_f64().unwrap_or(0.0) > 0.0));
    // glTF multiplies the texture by emissiveFactor (default black): a
    // texture without a factor emits nothing.
    if let Some(t) = texture_ref(json, "emissiveTexture").filter(|_| emits) {
        if material == "standard" {
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
            sampler_losses(file, &t, &mut out.losses);
        } else {
            out.losses.push(format!(
                "emissiveTexture ({material} does not emit; standard does)"
            ));
        }
    }
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

/// weft's material sampler is trilinear and repeats: a glTF sampler that
/// asks otherwise is a loss.
fn sampler_losses(file: &GltfFile, t: &TextureRef, losses: &mut Vec<String>) {
    use gltf::texture::{MagFilter, MinFilter, WrappingMode};
    let Some(texture) = file.document.textures().nth(t.index) else {
        return;
    };
    let sampler = texture.sampler();
    let Some(i) = sampler.index() else { return };
    let mut asks = Vec::new();
    for (axis, mode) in [("wrapS", sampler.wrap_s()), ("wrapT", sampler.wrap_t())] {
        if mode != WrappingMode::Repeat {
            asks.push(format!("{axis} {mode:?}"));
        }
    }
    if sampler.mag_filter() == Some(MagFilter::Nearest) {
        asks.push("magFilter NEAREST".into());
    }
    if let Some(min) = sampler.min_filter()
        && min != MinFilter::LinearMipmapLinear
    {
        asks.push(format!("minFilter {min:?}"));
    }
    let loss = format!(
        "sampler {i}'s {} (weft's material sampler is trilinear and repeats)",
        asks.join(", ")
    );
    if !asks.is_empty() && !losses.contains(&loss) {
        losses.push(loss);
    }
}
