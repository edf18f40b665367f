//! glTF materials as weft instances: which weft material, preset, tier,
//! keywords and parameter values each glTF material becomes, and what the
//! mapping loses (docs/gltf.md has the table and the measured differences).
//!
//! - `extras.weft = { material, preset, tier, params, keywords, dynamic }`
//!   (a DCC's custom properties) assigns any weft material as written.
//! - `KHR_materials_sheen` → velvet `reference` (Charlie sheen with albedo
//!   scaling). The Khronos sample renderer squares `sheenRoughnessFactor`
//!   into Charlie's α; velvet's α is `1 - smoothness`, so the mapping writes
//!   `smoothness = 1 - sheenRoughness²`: the same lobe.
//! - `KHR_materials_iridescence` → laser `fast` (Belcour–Barla film).
//! - `KHR_materials_anisotropy` → silk with the GGX anisotropic lobe.
//! - everything else → standard (core metallic-roughness).
//!
//! Colours: glTF factors are linear; weft's plain `color` parameters are
//! edited in sRGB, so factors are sRGB-encoded on the way in (the shader
//! decodes them back: the same linear value).

use super::GltfError;
use super::document::GltfFile;
use serde_json::Value;

mod textures;
use textures::map_textures;

/// The keys of weft's choices for one glTF material: `extras.weft` in the
/// file, `[gltf.materials.<name>]` in a scene manifest.
pub const WEFT_KEYS: &[&str] = &[
    "material",
    "preset",
    "tier",
    "error_budget",
    "screen_size",
    "params",
    "keywords",
    "dynamic",
];

/// A parameter or keyword value, as TOML text for the generated manifest.
pub type Literal = String;

/// One glTF material as a weft instance's settings.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MaterialMapping {
    /// The glTF material's name, or `material_<index>` (`default` for
    /// primitives without a material).
    pub gltf_name: String,
    pub material: String,
    pub preset: Option<String>,
    /// A tier name, or `auto` with its budget.
    pub tier: Option<String>,
    pub error_budget: Option<f64>,
    pub screen_size: Option<u32>,
    pub keywords: Vec<(String, Literal)>,
    pub params: Vec<(String, Literal)>,
    pub dynamic: Vec<String>,
    /// What the file asks that the mapping drops, said in the build output.
    pub losses: Vec<String>,
    /// Which rule mapped it: `core`, `KHR_materials_sheen`, …, `extras.weft`.
    pub rule: &'static str,
    /// glTF `doubleSided`: the instance draws back faces (`double_sided`).
    pub double_sided: bool,
    /// glTF `alphaMode: BLEND`: the instance's passes blend (`blend = "alpha"`).
    pub blend: bool,
    /// The glTF samplers of the maps bound, as the instance's `sampler = { … }`
    /// (None: the material's trilinear repeat).
    pub sampler: Option<Literal>,
    /// The maps' KHR_texture_transform when it rotates, baked into the
    /// primitive's uv0 (`mesh = { …, uv_transform }`; the maps then have no
    /// tiling of their own).
    pub uv_transform: Option<[f64; 6]>,
}

/// Linear → sRGB-encoded (IEC 61966-2-1), for weft's sRGB-edited colours.
pub fn linear_to_srgb(x: f64) -> f64 {
    let x = x.clamp(0.0, 1.0);
    if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}

/// A number as TOML (always with a decimal point or exponent: a float).
pub fn float(x: f64) -> Literal {
    let s = format!("{x:?}");
    if s.contains('.') || s.contains('e') || s.contains("inf") || s.contains("NaN") {
        s
    } else {
        format!("{s}.0")
    }
}

fn color(rgb: [f32; 3], alpha: f32) -> Literal {
    let c: Vec<String> = rgb
        .iter()
        .map(|&x| float(round6(linear_to_srgb(x as f64))))
        .chain([float(round6(alpha.clamp(0.0, 1.0) as f64))])
        .collect();
    format!("[{}]", c.join(", "))
}

/// An f32 of the file as the decimal it was written as (its shortest
/// round-tripping form): 0.45f32 is 0.45, not 0.449999988.
fn decimal(x: f32) -> f64 {
    format!("{x}").parse().unwrap_or(f64::from(x))
}

/// Six decimals: what an artist types, and stable across platforms' `powf`.
fn round6(x: f64) -> f64 {
    (x * 1e6).round() / 1e6
}

fn num(v: Option<&Value>, default: f64) -> f64 {
    v.and_then(Value::as_f64).unwrap_or(default)
}

fn rgb(v: Option<&Value>, default: [f32; 3]) -> [f32; 3] {
    match v.and_then(Value::as_array) {
        Some(a) if a.len() == 3 => {
            std::array::from_fn(|i| a[i].as_f64().unwrap_or(default[i] as f64) as f32)
        }
        _ => default,
    }
}

/// A JSON value written as a TOML value (for `extras.weft.params`).
fn toml_literal(v: &Value) -> Option<Literal> {
    Some(match v {
        Value::Bool(b) => b.to_string(),
        Value::Number(n) if n.is_i64() => n.to_string(),
        Value::Number(n) => float(n.as_f64()?),
        Value::String(s) => toml_string(s),
        Value::Array(items) => format!(
            "[{}]",
            items
                .iter()
                .map(toml_literal)
                .collect::<Option<Vec<_>>>()?
                .join(", ")
        ),
        Value::Object(map) => format!(
            "{{ {} }}",
            map.iter()
                .map(|(k, v)| Some(format!("{} = {}", toml_string(k), toml_literal(v)?)))
                .collect::<Option<Vec<_>>>()?
                .join(", ")
        ),
        Value::Null => return None,
    })
}

/// A TOML basic string.
pub fn toml_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            c if c.is_control() => out.push_str(&format!("\\u{:04X}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// The mapping of glTF material `index` (None: the default material).
/// `gltf_ref` is the file as the generated manifest names it (relative to
/// the manifest's folder), for the images its textures become.
pub fn map_material(
    file: &GltfFile,
    index: Option<usize>,
    gltf_ref: &str,
) -> Result<MaterialMapping, GltfError> {
    let Some(index) = index else {
        return Ok(MaterialMapping {
            gltf_name: "default".into(),
            material: "standard".into(),
            params: vec![
                ("base_color".into(), color([1.0; 3], 1.0)),
                ("roughness".into(), float(1.0)),
                ("metallic".into(), float(1.0)),
            ],
            rule: "core",
            ..MaterialMapping::default()
        });
    };
    let m = file
        .document
        .materials()
        .nth(index)
        .expect("validated index");
    let pointer = format!("/materials/{index}");
    let gltf_name = m
        .name()
        .map_or_else(|| format!("material_{index}"), str::to_string);
    let exts: serde_json::Map<String, Value> = m.extensions().cloned().unwrap_or_default();
    let extras: Option<Value> = m
        .extras()
        .as_ref()
        .and_then(|raw| serde_json::from_str(raw.get()).ok());
    if let Some(weft) = extras.as_ref().and_then(|e| e.get("weft")) {
        // The render state stays the glTF material's own.
        return map_extras(file, &pointer, gltf_name, weft).map(|mut o| {
            o.double_sided = m.double_sided();
            o.blend = m.alpha_mode() == gltf::material::AlphaMode::Blend;
            o
        });
    }
    let pbr = m.pbr_metallic_roughness();
    let [r, g, b, a] = pbr.base_color_factor();
    let base = color([r, g, b], a);
    let metallic = decimal(pbr.metallic_factor());
    let roughness = decimal(pbr.roughness_factor());
    let mut out = MaterialMapping {
        gltf_name,
        double_sided: m.double_sided(),
        blend: m.alpha_mode() == gltf::material::AlphaMode::Blend,
        ..MaterialMapping::default()
    };
    let factors = Factors {
        base,
        roughness,
        metallic,
    };
    out.losses = if let Some(sheen) = exts.get("KHR_materials_sheen") {
        map_sheen(sheen, factors, &mut out)
    } else if let Some(film) = exts.get("KHR_materials_iridescence") {
        map_iridescence(film, factors, &mut out)
    } else if let Some(aniso) = exts.get("KHR_materials_anisotropy") {
        map_anisotropy(aniso, factors, &mut out)
    } else {
        map_core(&m, factors, &mut out)
    };
    map_textures(file, index, gltf_ref, &mut out);
    map_emission_and_alpha(&m, &mut out);
    Ok(out)
}

/// The core factors every rule starts from: base colour (as a TOML value),
/// roughness, metallic.
struct Factors {
    base: String,
    roughness: f64,
    metallic: f64,
}

/// `KHR_materials_sheen` → velvet's reference (Charlie sheen, albedo
/// scaling). Returns what the mapping loses.
fn map_sheen(sheen: &Value, factors: Factors, out: &mut MaterialMapping) -> Vec<String> {
    let Factors { base, metallic, .. } = factors;
    let mut losses = Vec::new();
    let sheen_color = rgb(sheen.get("sheenColorFactor"), [0.0; 3]);
    let sheen_roughness = num(sheen.get("sheenRoughnessFactor"), 0.0).clamp(0.0, 1.0);
    // velvet's sheen colour is saturate(F0 + scatter colour) with F0 =
    // 0.04 for a dielectric base: scatter = sheenColor − 0.04.
    let scatter = sheen_color.map(|c| (c - 0.04).max(0.0));
    if sheen_color.iter().any(|&c| c < 0.04) {
        losses.push(
            "sheenColorFactor below 0.04 (velvet's sheen colour includes the base's F0 0.04)"
                .into(),
        );
    }
    losses.push(
        "the base layer's GGX specular lobe (velvet has only the sheen over a Lambert base)".into(),
    );
    if metallic > 0.0 {
        losses.push(format!(
            "metallicFactor {metallic} (velvet's base is drawn dielectric under the sheen)"
        ));
    }
    out.material = "velvet".into();
    out.tier = Some("reference".into());
    out.params = vec![
        ("base_color".into(), base),
        ("metallic".into(), float(0.0)),
        (
            "smoothness".into(),
            float(round6(1.0 - sheen_roughness * sheen_roughness)),
        ),
        ("scatter_color".into(), color(scatter, 1.0)),
    ];
    out.rule = "KHR_materials_sheen";
    losses
}

/// `KHR_materials_iridescence` → laser's fast tier (Belcour & Barla's film).
fn map_iridescence(film: &Value, factors: Factors, out: &mut MaterialMapping) -> Vec<String> {
    let Factors {
        base,
        roughness,
        metallic,
    } = factors;
    let mut losses = Vec::new();
    out.material = "laser".into();
    out.tier = Some("fast".into());
    let ior = num(film.get("iridescenceIor"), 1.3);
    if !(1.0..=2.0).contains(&ior) {
        losses.push(format!(
            "iridescenceIor {ior} (laser's film_ior is in [1, 2]: clamped)"
        ));
    }
    let tmin = num(film.get("iridescenceThicknessMinimum"), 100.0);
    let tmax = num(film.get("iridescenceThicknessMaximum"), 400.0);
    // Without a thickness texture glTF takes the maximum everywhere, as
    // laser does without its offset map.
    for (t, name) in [
        (tmin, "iridescenceThicknessMinimum"),
        (tmax, "iridescenceThicknessMaximum"),
    ] {
        if !(0.0..=1000.0).contains(&t) {
            losses.push(format!(
                "{name} {t} nm (laser's range is 0–1000 nm: clamped)"
            ));
        }
    }
    out.params = vec![
        ("base_color".into(), base),
        ("roughness".into(), float(roughness)),
        ("metallic".into(), float(metallic)),
        (
            "film_strength".into(),
            float(num(film.get("iridescenceFactor"), 0.0).clamp(0.0, 1.0)),
        ),
        ("film_ior".into(), float(ior.clamp(1.0, 2.0))),
        ("thickness_min".into(), float(tmin.clamp(0.0, 1000.0))),
        ("thickness_max".into(), float(tmax.clamp(0.0, 1000.0))),
    ];
    out.rule = "KHR_materials_iridescence";
    losses
}

/// `KHR_materials_anisotropy` → silk's anisotropic GGX, the stretch matched.
fn map_anisotropy(aniso: &Value, factors: Factors, out: &mut MaterialMapping) -> Vec<String> {
    let Factors {
        base,
        roughness,
        metallic,
    } = factors;
    let mut losses = Vec::new();
    let strength = num(aniso.get("anisotropyStrength"), 0.0).clamp(0.0, 1.0);
    let rotation = num(aniso.get("anisotropyRotation"), 0.0);
    if rotation != 0.0 {
        losses.push(format!(
            "anisotropyRotation {rotation} rad (silk's fibres run along the mesh tangent)"
        ));
    }
    // glTF: α_t = mix(α, 1, s²), α_b = α. silk's GGX (Disney):
    // α_t / α_b = 1 / (1 − 0.9 k). Match the ratio at the material's α.
    let alpha = (roughness * roughness).max(1e-4);
    let ratio = (alpha + (1.0 - alpha) * strength * strength) / alpha;
    let k = ((1.0 - 1.0 / ratio) / 0.9).clamp(0.0, 1.0);
    if k >= 1.0 && ratio > 10.0 {
        losses.push(format!(
            "anisotropy ratio {ratio:.1} (silk's GGX stretches at most 10:1)"
        ));
    }
    out.material = "silk".into();
    out.keywords = vec![("ANISO_MODEL".into(), toml_string("ggx"))];
    out.params = vec![
        ("base_color".into(), base),
        ("smoothness".into(), float(round6(1.0 - roughness))),
        ("metallic".into(), float(metallic)),
        ("anisotropy".into(), float(round6(k))),
    ];
    out.rule = "KHR_materials_anisotropy";
    losses
}

/// Core metallic-roughness (and `KHR_materials_specular`) → standard.
fn map_core(m: &gltf::Material, factors: Factors, out: &mut MaterialMapping) -> Vec<String> {
    let Factors {
        base,
        roughness,
        metallic,
    } = factors;
    let mut losses = Vec::new();
    out.material = "standard".into();
    out.params = vec![
        ("base_color".into(), base),
        ("roughness".into(), float(roughness)),
        ("metallic".into(), float(metallic)),
    ];
    if let Some(spec) = m.specular() {
        // standard's specular_strength scales F0 (0.04 dielectric): glTF's
        // specularFactor × specularColorFactor's max does the same.
        let f = decimal(spec.specular_factor());
        let c = spec.specular_color_factor();
        let strength = f * decimal(c.iter().fold(0.0f32, |a, &x| a.max(x)));
        out.params.push((
            "specular_strength".into(),
            float(round6(strength.clamp(0.0, 4.0))),
        ));
        if c[0] != c[1] || c[1] != c[2] {
            losses.push(
                "specularColorFactor's hue (standard scales F0 by one number: its maximum)".into(),
            );
        }
    }
    out.rule = "core";
    losses
}

/// Emission, `alphaMode` `MASK` and `doubleSided`: standard carries all
/// three (`emissive`, `emissive_strength`, `ALPHA_TEST` with `alpha_cutoff`,
/// back faces shaded with the flipped normal); another material loses what
/// it cannot draw. `BLEND` and `doubleSided` are the instance's render
/// state (`blend`, `double_sided`), whatever the material.
fn map_emission_and_alpha(m: &gltf::Material, out: &mut MaterialMapping) {
    let standard = out.material == "standard";
    let emissive = m.emissive_factor();
    let strength = f64::from(m.emissive_strength().unwrap_or(1.0));
    if emissive != [0.0; 3] && strength > 0.0 {
        if standard {
            out.keywords.push(("EMISSION".into(), "true".into()));
            out.params.push(("emissive".into(), color(emissive, 1.0)));
            if strength != 1.0 {
                out.params.push((
                    "emissive_strength".into(),
                    float(round6(strength.clamp(0.0, 1000.0))),
                ));
            }
        } else {
            out.losses.push(format!(
                "emissiveFactor × strength {strength} ({} does not emit; standard does)",
                out.material
            ));
        }
    }
    if m.alpha_mode() == gltf::material::AlphaMode::Mask {
        if standard {
            out.keywords.push(("ALPHA_TEST".into(), "true".into()));
            out.params.push((
                "alpha_cutoff".into(),
                float(round6(
                    f64::from(m.alpha_cutoff().unwrap_or(0.5)).clamp(0.0, 1.0),
                )),
            ));
        } else {
            out.losses.push(format!(
                "alphaMode MASK ({} has no alpha test; standard has)",
                out.material
            ));
        }
    }
    if m.double_sided() && !matches!(out.material.as_str(), "standard" | "gauze") {
        out.losses.push(format!(
            "doubleSided's flipped back-face normal ({} shades back faces with the front normal)",
            out.material
        ));
    }
}

/// `extras.weft`: a weft material as the DCC's custom properties name it.
fn map_extras(
    file: &GltfFile,
    pointer: &str,
    gltf_name: String,
    weft: &Value,
) -> Result<MaterialMapping, GltfError> {
    let at = format!("{pointer}/extras/weft");
    let err = |key: &str, message: String| {
        file.error(
            &format!("{at}{key}"),
            message,
            "extras.weft is { material = \"<weft material>\", preset?, tier?, error_budget?, screen_size?, params?, keywords?, dynamic? }",
        )
    };
    let Value::Object(map) = weft else {
        return Err(err("", "extras.weft is not an object".into()));
    };
    if let Some(k) = map.keys().find(|k| !WEFT_KEYS.contains(&k.as_str())) {
        return Err(err(&format!("/{k}"), format!("unknown key `{k}`")));
    }
    let string = |key: &str| -> Result<Option<String>, GltfError> {
        match map.get(key) {
            None => Ok(None),
            Some(Value::String(s)) => Ok(Some(s.clone())),
            Some(_) => Err(err(&format!("/{key}"), format!("`{key}` is not a string"))),
        }
    };
    let material =
        string("material")?.ok_or_else(|| err("", "extras.weft has no `material`".into()))?;
    let table = |key: &str| -> Result<Vec<(String, Literal)>, GltfError> {
        match map.get(key) {
            None => Ok(Vec::new()),
            Some(Value::Object(m)) => m
                .iter()
                .map(|(k, v)| {
                    toml_literal(v)
                        .map(|l| (k.clone(), l))
                        .ok_or_else(|| err(&format!("/{key}/{k}"), format!("`{k}` is null")))
                })
                .collect(),
            Some(_) => Err(err(&format!("/{key}"), format!("`{key}` is not an object"))),
        }
    };
    let dynamic = match map.get("dynamic") {
        None => Vec::new(),
        Some(Value::Array(items)) => items
            .iter()
            .enumerate()
            .map(|(i, v)| {
                v.as_str()
                    .map(str::to_string)
                    .ok_or_else(|| err(&format!("/dynamic/{i}"), "not a string".into()))
            })
            .collect::<Result<_, _>>()?,
        Some(_) => return Err(err("/dynamic", "`dynamic` is not an array".into())),
    };
    let number = |key: &str| {
        map.get(key)
            .map(|v| {
                v.as_f64()
                    .ok_or_else(|| err(&format!("/{key}"), format!("`{key}` is not a number")))
            })
            .transpose()
    };
    Ok(MaterialMapping {
        gltf_name,
        material,
        preset: string("preset")?,
        tier: string("tier")?,
        error_budget: number("error_budget")?,
        screen_size: number("screen_size")?.map(|x| x.clamp(1.0, 65536.0) as u32),
        keywords: table("keywords")?,
        params: table("params")?,
        dynamic,
        losses: Vec::new(),
        rule: "extras.weft",
        double_sided: false,
        blend: false,
        sampler: None,
        uv_transform: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_encoding_matches_the_standard() {
        assert_eq!(linear_to_srgb(0.0), 0.0);
        assert!((linear_to_srgb(1.0) - 1.0).abs() < 1e-12);
        // 0.5 linear is 0.7354 sRGB (IEC 61966-2-1).
        assert!((linear_to_srgb(0.5) - 0.735_356_983).abs() < 1e-6);
    }

    #[test]
    fn toml_literals() {
        assert_eq!(float(1.0), "1.0");
        assert_eq!(toml_string("a\"b"), "\"a\\\"b\"");
        let v: Value = serde_json::json!([1, 0.5, true, "x"]);
        assert_eq!(toml_literal(&v).unwrap(), "[1, 0.5, true, \"x\"]");
    }
}
