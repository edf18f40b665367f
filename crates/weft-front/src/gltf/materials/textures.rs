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
    // The gltf crate hands a textureInfo's transform to us at f32 precision
    // and a normalTexture's at f64 (0.1 vs 0.10000000149…): both are read
    // at f32, written shortest, so equal transforms compare equal.
    let f32_value = |x: f64| (x as f32).to_string().parse().unwrap_or(x);
    let pair = |k: &str, d: f64| -> [f64; 2] {
        let a = t.and_then(|t| t.get(k)).and_then(Value::as_array);
        [0, 1].map(|i| f32_value(num(a.and_then(|a| a.get(i)), d)))
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
        rotation: f32_value(num(t.and_then(|t| t.get("rotation")), 0.0)),
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
    let emissive =
        texture_ref(&json, "emissiveTexture").filter(|_| material == "standard" && emits(&json));
    // The maps this material binds, and whether their one transform has a
    // rotation: weft's tiling is scale and offset, so such a transform is
    // baked into the primitive's uv0 instead (the maps then read it as is).
    let bound: Vec<&TextureRef> = [
        base.as_ref(),
        normal.as_ref().filter(|_| has_normal),
        mr.as_ref().filter(|_| has_rmo),
        occlusion
            .as_ref()
            .filter(|_| has_rmo || material == "velvet"),
        emissive.as_ref(),
    ]
    .into_iter()
    .flatten()
    .collect();
    let baked = bound.iter().any(|t| t.rotation != 0.0)
        && bound.iter().all(|t| {
            t.tiling == bound[0].tiling && t.rotation == bound[0].rotation && t.tex_coord == 0
        });
    if baked {
        out.uv_transform = Some(uv_matrix(bound[0]));
    }
    // What the maps are read with: the base map's tiling, or none when baked.
    let tiling = base.as_ref().map(|b| b.tiling).filter(|_| !baked);
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
    if !baked {
        transform_losses(&used, tiling, &mut out.losses);
    }
    if map_emissive_texture(&json, emissive.as_ref(), gltf_ref, tiling, baked, out) {
        used.extend(emissive.as_ref());
    }
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
/// emits nothing). `emissive` is the texture when standard binds it (it
/// emits); true when it is bound.
fn map_emissive_texture(
    json: &Value,
    emissive: Option<&TextureRef>,
    gltf_ref: &str,
    tiling: Option<[f64; 4]>,
    baked: bool,
    out: &mut MaterialMapping,
) -> bool {
    let Some(t) = emissive else {
        if texture_ref(json, "emissiveTexture").is_some() && emits(json) {
            out.losses.push(format!(
                "emissiveTexture ({} does not emit; standard does)",
                out.material
            ));
        }
        return false;
    };
    out.params.push((
        "emissive_map".into(),
        image_value(gltf_ref, &format!("texture = {}", t.index), None),
    ));
    if !baked && t.tiling != tiling.unwrap_or([1.0, 1.0, 0.0, 0.0]) {
        out.losses.push(
            "emissiveTexture's KHR_texture_transform (the material's maps share the base colour texture's)"
                .into(),
        );
    }
    true
}

/// Whether the material emits (glTF's emissiveFactor, default black).
fn emits(json: &Value) -> bool {
    json.get("emissiveFactor")
        .and_then(Value::as_array)
        .is_some_and(|f| f.iter().any(|x| x.as_f64().unwrap_or(0.0) > 0.0))
}

/// KHR_texture_transform as the affine map of uv0 it stands for,
/// translation · rotation · scale (the extension's matrix), in
/// `uv_transform`'s order [a, b, c, d, e, f]: (a u + b v + c, d u + e v + f).
fn uv_matrix(t: &TextureRef) -> [f64; 6] {
    let [sx, sy, ox, oy] = t.tiling;
    let (sin, cos) = t.rotation.sin_cos();
    [sx * cos, sy * sin, ox, -sx * sin, sy * cos, oy]
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

    /// Material 0 of a glTF (JSON) mapped.
    fn map(json: &Value) -> MaterialMapping {
        let mut warnings = Vec::new();
        let file = GltfFile::from_bytes(
            std::path::Path::new("t.gltf"),
            None,
            serde_json::to_vec(json).unwrap(),
            &mut warnings,
        )
        .unwrap();
        super::super::map_material(&file, Some(0), "t.gltf").unwrap()
    }

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
        map(&json)
    }

    /// Material 0 with a base colour and a normal texture, each with the
    /// KHR_texture_transform given, mapped.
    fn transformed(base: Value, normal: Value) -> MaterialMapping {
        let info = |index: u64, t: Value| serde_json::json!({ "index": index, "extensions": { "KHR_texture_transform": t } });
        let json = serde_json::json!({
            "asset": { "version": "2.0" },
            "extensionsUsed": ["KHR_texture_transform"],
            "images": [ { "uri": "a.png" } ],
            "textures": [ { "source": 0 }, { "source": 0 } ],
            "materials": [ {
                "pbrMetallicRoughness": { "baseColorTexture": info(0, base) },
                "normalTexture": info(1, normal) } ]
        });
        map(&json)
    }

    #[test]
    fn a_rotated_transform_shared_by_the_maps_is_baked_into_uv0() {
        let t = serde_json::json!({ "offset": [0.1, 0.2], "rotation": 0.5, "scale": [3.0, 2.0] });
        let m = transformed(t.clone(), t);
        let [a, b, c, d, e, f] = m.uv_transform.unwrap_or_else(|| panic!("{m:?}"));
        // The extension's matrix, translation · rotation · scale.
        let (sin, cos) = 0.5f64.sin_cos();
        for (got, want) in
            [a, b, c, d, e, f]
                .iter()
                .zip([3.0 * cos, 2.0 * sin, 0.1, -3.0 * sin, 2.0 * cos, 0.2])
        {
            assert!((got - want).abs() < 1e-12, "{:?}", m.uv_transform);
        }
        // The maps read the baked uv0 as is: no tiling, nothing lost.
        let base = &m.params.iter().find(|(k, _)| k == "base_map").unwrap().1;
        assert!(
            !base.contains("scale") && !base.contains("offset"),
            "{base}"
        );
        assert!(m.losses.is_empty(), "{:?}", m.losses);
    }

    #[test]
    fn maps_rotated_differently_keep_the_loss() {
        let m = transformed(
            serde_json::json!({ "rotation": 0.5 }),
            serde_json::json!({ "rotation": 0.25 }),
        );
        assert_eq!(m.uv_transform, None);
        assert!(
            m.losses.iter().any(|l| l.contains("rotation 0.5 rad")),
            "{:?}",
            m.losses
        );
        // Scale and offset alone stay the base map's tiling, as before.
        let m = transformed(
            serde_json::json!({ "scale": [2.0, 1.0] }),
            serde_json::json!({ "scale": [2.0, 1.0] }),
        );
        assert_eq!(m.uv_transform, None);
        assert!(m.losses.is_empty(), "{:?}", m.losses);
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
