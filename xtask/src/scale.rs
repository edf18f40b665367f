//! Synthetic material libraries for `cargo xtask bench scale`.
//!
//! Each synthetic material is a copy of a shipped one (`materials/<base>/`,
//! taken round-robin in name order) under a new name, `<base>_<i:04>_syn`
//! (names may not end in a digit), with
//!
//! - its float parameters' defaults moved inside their ranges and
//! - static keywords added (toggles and three-value enums from a fixed pool,
//!   [`FEATURES`]), each with its own parameters and shading code (rim light,
//!   distance fog, detail map, glints, colour grading, wrap diffuse, tone
//!   shoulder), gated in the WGSL with plain `if`s.
//!
//! The keywords go into a new `@fragment` entry point that calls the shipped
//! one (renamed `weft_syn_base_<entry>`, its attributes dropped) and then
//! applies them, so the shipped shading code compiles unchanged in every
//! variant. Enough keywords are added to bring a material close to a target
//! variant count (48 by default: 4 × 12, 8 × 6, 12 × 4 for the shipped
//! bases). Everything is derived from a fixed seed: the same arguments write
//! the same bytes.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Default seed of `bench scale`.
pub const DEFAULT_SEED: u64 = 0x5eed_0013;

/// SplitMix64: small, deterministic, good enough to pick and jitter.
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi), rounded to 3 decimals (stable, short literals).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        ((lo + (hi - lo) * self.unit()) * 1000.0).round() / 1000.0
    }
}

/// A float literal valid in both TOML and WGSL (always with a decimal point).
fn lit(x: f64) -> String {
    let s = format!("{x}");
    if s.contains('.') || s.contains('e') {
        s
    } else {
        format!("{s}.0")
    }
}

fn colour(rng: &mut Rng, lo: f64, hi: f64) -> String {
    format!(
        "[{}, {}, {}, 1.0]",
        lit(rng.range(lo, hi)),
        lit(rng.range(lo, hi)),
        lit(rng.range(lo, hi))
    )
}

/// One synthetic keyword: its declaration, parameters and shading code.
pub struct Feature {
    /// Enum values; empty for a toggle.
    pub values: &'static [&'static str],
    /// `[params.*]` and `[keywords.*]` tables (TOML), given the material's rng.
    toml: fn(&mut Rng) -> String,
    /// Statements for the wrapper entry point, given the material's rng. In
    /// scope: `c` (var vec4, the shipped entry point's result), `vin`
    /// (WeftVaryings), `n`, `v`, `n_dot_v`, `l`.
    wgsl: fn(&mut Rng) -> String,
}

impl Feature {
    pub fn value_count(&self) -> usize {
        if self.values.is_empty() {
            2
        } else {
            self.values.len()
        }
    }
}

/// A `[params.<name>]` table; `labels` is the English and Chinese label.
fn param(
    name: &str,
    kind: &str,
    default: &str,
    extra: &str,
    (label, zh): (&str, &str),
    order: u32,
    show_if: &str,
) -> String {
    format!(
        "[params.{name}]\ntype = \"{kind}\"\ndefault = {default}\n{extra}label = \"{label}\"\nlabel_zh = \"{zh}\"\ngroup = \"synthetic\"\norder = {order}\nshow_if = \"{show_if}\"\n\n"
    )
}

fn toggle(name: &str, label: &str, zh: &str, tooltip: &str) -> String {
    format!(
        "[keywords.{name}]\ntype = \"toggle\"\ndefault = false\nlabel = \"{label}\"\nlabel_zh = \"{zh}\"\ntooltip = \"{tooltip}\"\ngroup = \"synthetic\"\n\n"
    )
}

fn enumeration(name: &str, values: &[&str], label: &str, zh: &str, tooltip: &str) -> String {
    let list = values
        .iter()
        .map(|v| format!("\"{v}\""))
        .collect::<Vec<_>>()
        .join(", ");
    format!(
        "[keywords.{name}]\ntype = \"enum\"\nvalues = [{list}]\ndefault = \"{}\"\nlabel = \"{label}\"\nlabel_zh = \"{zh}\"\ntooltip = \"{tooltip}\"\ngroup = \"synthetic\"\n\n",
        values[0]
    )
}

/// The pool of synthetic keywords: toggles first, then three-value enums.
pub const FEATURES: &[Feature] = &[
    Feature {
        values: &[],
        toml: |r| {
            toggle(
                "SYN_RIM",
                "Rim light",
                "边缘光",
                "Adds a Fresnel-like rim lit by the main light.",
            ) + &param(
                "syn_rim_color",
                "color",
                &colour(r, 0.5, 1.0),
                "",
                ("Rim colour", "边缘光颜色"),
                100,
                "SYN_RIM",
            ) + &param(
                "syn_rim_power",
                "float",
                &lit(r.range(1.5, 6.0)),
                "range = [0.5, 8.0]\nstep = 0.01\n",
                ("Rim power", "边缘光指数"),
                101,
                "SYN_RIM",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_RIM {{
        let rim = pow(1.0 - n_dot_v, max(material.syn_rim_power, 0.5)) * {};
        let lit_side = saturate(dot(n, l) * 0.5 + 0.5);
        c = vec4<f32>(c.rgb + rim * lit_side * material.syn_rim_color.rgb * weft_main_light_radiance() * c.a, c.a);
    }}
",
                lit(r.range(0.6, 1.0))
            )
        },
    },
    Feature {
        values: &[],
        toml: |r| {
            toggle(
                "SYN_FOG",
                "Distance fog",
                "距离雾",
                "Blends towards the fog colour with distance from the camera.",
            ) + &param(
                "syn_fog_color",
                "color",
                &colour(r, 0.4, 0.9),
                "",
                ("Fog colour", "雾颜色"),
                110,
                "SYN_FOG",
            ) + &param(
                "syn_fog_density",
                "float",
                &lit(r.range(0.01, 0.2)),
                "range = [0.0, 1.0]\nstep = 0.001\n",
                ("Fog density", "雾密度"),
                111,
                "SYN_FOG",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_FOG {{
        let d = length(weft_frame.camera_position.xyz - vin.world_position);
        let f = saturate(1.0 - exp(-max(material.syn_fog_density, 0.0) * d * {}));
        c = vec4<f32>(mix(c.rgb, material.syn_fog_color.rgb * c.a, f), c.a);
    }}
",
                lit(r.range(0.8, 1.2))
            )
        },
    },
    Feature {
        values: &[],
        toml: |r| {
            toggle(
                "SYN_DETAIL",
                "Detail map",
                "细节贴图",
                "Modulates the colour with a tiled grey detail texture (0.5 is neutral).",
            ) + &param(
                "syn_detail_map",
                "texture2d",
                "\"gray\"",
                "tiling = true\n",
                ("Detail map", "细节贴图"),
                120,
                "SYN_DETAIL",
            ) + &param(
                "syn_detail_strength",
                "float",
                &lit(r.range(0.2, 0.8)),
                "range = [0.0, 1.0]\nstep = 0.01\n",
                ("Detail strength", "细节强度"),
                121,
                "SYN_DETAIL",
            )
        },
        wgsl: |_| {
            "    if SYN_DETAIL {
        let duv = weft_transform_uv(vin.uv0, material.syn_detail_map_st);
        let detail = textureSample(syn_detail_map, material_sampler, duv).rgb;
        let k = mix(vec3<f32>(1.0), 2.0 * detail, saturate(material.syn_detail_strength));
        c = vec4<f32>(c.rgb * k, c.a);
    }
"
            .into()
        },
    },
    Feature {
        values: &[],
        toml: |r| {
            toggle(
                "SYN_GLINT",
                "Glints",
                "闪点",
                "Sparse sparkles: a hashed cell grid over uv0, lit along the mirror direction.",
            ) + &param(
                "syn_glint_density",
                "float",
                &lit(r.range(64.0, 512.0)),
                "range = [1.0, 2048.0]\nstep = 1.0\n",
                ("Glint density", "闪点密度"),
                130,
                "SYN_GLINT",
            ) + &param(
                "syn_glint_amount",
                "float",
                &lit(r.range(0.02, 0.2)),
                "range = [0.0, 1.0]\nstep = 0.001\n",
                ("Glint amount", "闪点比例"),
                131,
                "SYN_GLINT",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_GLINT {{
        let cell = floor(vin.uv0 * max(material.syn_glint_density, 1.0));
        let h = fract(sin(dot(cell, vec2<f32>({}, {}))) * 43758.5453);
        let lobe = pow(saturate(dot(reflect(-l, n), v)), {});
        let glint = select(0.0, 1.0, h > 1.0 - saturate(material.syn_glint_amount)) * lobe;
        c = vec4<f32>(c.rgb + glint * weft_main_light_radiance() * c.a, c.a);
    }}
",
                lit(r.range(10.0, 15.0)),
                lit(r.range(70.0, 90.0)),
                lit(r.range(32.0, 128.0).round())
            )
        },
    },
    Feature {
        values: &["neutral", "warm", "cool"],
        toml: |r| {
            enumeration(
                "SYN_GRADE",
                &["neutral", "warm", "cool"],
                "Colour grade",
                "调色",
                "Tints the result warm or cool.",
            ) + &param(
                "syn_grade_strength",
                "float",
                &lit(r.range(0.3, 1.0)),
                "range = [0.0, 1.0]\nstep = 0.01\n",
                ("Grade strength", "调色强度"),
                140,
                "SYN_GRADE != neutral",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_GRADE == SYN_GRADE_WARM {{
        c = vec4<f32>(c.rgb * mix(vec3<f32>(1.0), vec3<f32>({}, 1.0, {}), saturate(material.syn_grade_strength)), c.a);
    }}
    if SYN_GRADE == SYN_GRADE_COOL {{
        c = vec4<f32>(c.rgb * mix(vec3<f32>(1.0), vec3<f32>({}, {}, {}), saturate(material.syn_grade_strength)), c.a);
    }}
",
                lit(r.range(1.04, 1.12)),
                lit(r.range(0.85, 0.95)),
                lit(r.range(0.88, 0.95)),
                lit(r.range(0.97, 1.0)),
                lit(r.range(1.04, 1.12))
            )
        },
    },
    Feature {
        values: &["off", "soft", "deep"],
        toml: |r| {
            enumeration(
                "SYN_WRAP",
                &["off", "soft", "deep"],
                "Wrap lighting",
                "包裹光照",
                "Adds light that wraps past the terminator (soft) or scatters through (deep).",
            ) + &param(
                "syn_wrap_color",
                "color",
                &colour(r, 0.3, 0.9),
                "",
                ("Wrap colour", "包裹光颜色"),
                150,
                "SYN_WRAP != off",
            ) + &param(
                "syn_wrap_amount",
                "float",
                &lit(r.range(0.2, 0.7)),
                "range = [0.0, 1.0]\nstep = 0.01\n",
                ("Wrap amount", "包裹量"),
                151,
                "SYN_WRAP != off",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_WRAP == SYN_WRAP_SOFT {{
        let w = saturate(material.syn_wrap_amount);
        let wrap = saturate((dot(n, l) + w) / ((1.0 + w) * (1.0 + w))) - saturate(dot(n, l));
        c = vec4<f32>(c.rgb + max(wrap, 0.0) * WEFT_INV_PI * material.syn_wrap_color.rgb * weft_main_light_radiance() * c.a, c.a);
    }}
    if SYN_WRAP == SYN_WRAP_DEEP {{
        let back = pow(saturate(dot(v, -l)), {}) * saturate(material.syn_wrap_amount);
        let sh = weft_sh_irradiance(-n);
        c = vec4<f32>(c.rgb + (back * weft_main_light_radiance() + {} * sh) * material.syn_wrap_color.rgb * c.a, c.a);
    }}
",
                lit(r.range(2.0, 8.0).round()),
                lit(r.range(0.05, 0.2))
            )
        },
    },
    Feature {
        values: &["linear", "shoulder", "clip"],
        toml: |r| {
            enumeration(
                "SYN_TONE",
                &["linear", "shoulder", "clip"],
                "Highlight roll-off",
                "高光压缩",
                "Compresses highlights with a smooth shoulder, or clips them.",
            ) + &param(
                "syn_tone_white",
                "float",
                &lit(r.range(2.0, 16.0)),
                "range = [0.5, 64.0]\nstep = 0.1\n",
                ("White point", "白点"),
                160,
                "SYN_TONE != linear",
            )
        },
        wgsl: |r| {
            format!(
                "    if SYN_TONE == SYN_TONE_SHOULDER {{
        let w = max(material.syn_tone_white, 0.5);
        let x = c.rgb;
        c = vec4<f32>(x * (vec3<f32>(1.0) + x / (w * w)) / (vec3<f32>(1.0) + x * {}), c.a);
    }}
    if SYN_TONE == SYN_TONE_CLIP {{
        c = vec4<f32>(min(c.rgb, vec3<f32>(max(material.syn_tone_white, 0.5) * c.a)), c.a);
    }}
",
                lit(r.range(0.9, 1.1))
            )
        },
    },
];

/// A shipped material a synthetic one is derived from.
pub struct Base {
    pub name: String,
    pub toml: String,
    /// WGSL file name (the TOML's `source`) and text.
    pub source: (String, String),
    /// Fragment entry points of its passes (distinct, in order).
    pub fragments: Vec<String>,
    /// Variants the shipped material has (after exclusions).
    pub variants: usize,
}

/// Loads the shipped materials of `materials_dir` (sorted by name) that can
/// be derived: every fragment entry point takes the engine interface's
/// `WeftVaryings`, which the synthetic features read (fur's shells carry
/// their own varyings and are left out).
pub fn load_bases(materials_dir: &Path) -> Result<Vec<Base>, String> {
    let paths = weft_compiler::library::discover(materials_dir)
        .map_err(|e| format!("cannot read {}: {e}", materials_dir.display()))?;
    let mut out = Vec::new();
    for path in paths {
        let (mut db, mut diags) = (weft_front::SourceDb::new(), weft_front::Diagnostics::new());
        let m = weft_front::load_material(&path, materials_dir, &mut db, &mut diags)
            .ok_or_else(|| format!("{} does not load", path.display()))?;
        let toml = std::fs::read_to_string(&path).map_err(|e| e.to_string())?;
        let table: toml::Table = toml
            .parse()
            .map_err(|e| format!("{}: {e}", path.display()))?;
        let source = table
            .get("material")
            .and_then(|t| t.get("source"))
            .and_then(|s| s.as_str())
            .ok_or_else(|| format!("{}: no [material].source", path.display()))?
            .to_string();
        let dir = path.parent().expect("material folder");
        let wgsl = std::fs::read_to_string(dir.join(&source)).map_err(|e| e.to_string())?;
        let mut fragments: Vec<String> = Vec::new();
        for p in &m.passes {
            if !fragments.contains(&p.fragment) {
                fragments.push(p.fragment.clone());
            }
        }
        if fragments
            .iter()
            .any(|entry| wrap_fragment(&wgsl, entry, "").is_err())
        {
            continue;
        }
        out.push(Base {
            name: m.name.clone(),
            toml,
            source: (source, wgsl),
            fragments,
            variants: weft_front::variants::variants(&m).len(),
        });
    }
    Ok(out)
}

/// Feature indices (into [`FEATURES`]) that multiply a base's variants by a
/// factor close to `factor`: as many three-value enums and toggles as fit.
fn pick_features(factor: f64, rng: &mut Rng) -> Vec<usize> {
    let toggles: Vec<usize> = (0..FEATURES.len())
        .filter(|&i| FEATURES[i].values.is_empty())
        .collect();
    let enums: Vec<usize> = (0..FEATURES.len())
        .filter(|&i| !FEATURES[i].values.is_empty())
        .collect();
    // The 2^a 3^b (within the pool) closest to `factor` in log terms.
    let mut best = (f64::INFINITY, 0, 0);
    for a in 0..=toggles.len() {
        for b in 0..=enums.len() {
            let f = 2f64.powi(a as i32) * 3f64.powi(b as i32);
            let d = (f.ln() - factor.max(1.0).ln()).abs();
            if d < best.0 - 1e-9 {
                best = (d, a, b);
            }
        }
    }
    let mut chosen = Vec::new();
    let mut pick = |pool: &[usize], k: usize, rng: &mut Rng| {
        let mut pool = pool.to_vec();
        for _ in 0..k {
            let i = (rng.next_u64() % pool.len() as u64) as usize;
            chosen.push(pool.remove(i));
        }
    };
    pick(&enums, best.2, rng);
    pick(&toggles, best.1, rng);
    chosen.sort();
    chosen
}

/// The byte range of the parenthesised list starting at `open` (`(`).
fn matching_paren(s: &str, open: usize) -> Option<usize> {
    let mut depth = 0i32;
    for (i, ch) in s[open..].char_indices() {
        match ch {
            '(' => depth += 1,
            ')' => {
                depth -= 1;
                if depth == 0 {
                    return Some(open + i);
                }
            }
            _ => {}
        }
    }
    None
}

/// Splits a parameter list at top-level commas.
fn split_params(list: &str) -> Vec<String> {
    let (mut out, mut cur, mut depth) = (Vec::new(), String::new(), 0i32);
    for ch in list.chars() {
        match ch {
            '(' | '<' => depth += 1,
            ')' | '>' => depth -= 1,
            ',' if depth == 0 => {
                out.push(std::mem::take(&mut cur));
                continue;
            }
            _ => {}
        }
        cur.push(ch);
    }
    out.push(cur);
    out.into_iter()
        .map(|p| p.trim().to_string())
        .filter(|p| !p.is_empty())
        .collect()
}

/// A parameter without its attributes (`@builtin(x) name: T` -> `name: T`).
fn strip_attributes(p: &str) -> String {
    let mut s = p.trim_start();
    while let Some(rest) = s.strip_prefix('@') {
        let end = rest
            .find(|c: char| !(c.is_alphanumeric() || c == '_'))
            .unwrap_or(rest.len());
        let mut after = rest[end..].trim_start();
        if after.starts_with('(') {
            let close = matching_paren(after, 0).unwrap_or(after.len() - 1);
            after = &after[close + 1..];
        }
        s = after.trim_start();
    }
    s.to_string()
}

/// Renames the `@fragment fn <entry>` of `wgsl` to `weft_syn_base_<entry>`
/// (a plain function) and appends a new `@fragment fn <entry>` with the same
/// signature that calls it and then runs `body`.
fn wrap_fragment(wgsl: &str, entry: &str, body: &str) -> Result<String, String> {
    let needle = format!("fn {entry}(");
    let at = wgsl
        .match_indices(&needle)
        .map(|(i, _)| i)
        .find(|&i| wgsl[..i].trim_end().ends_with("@fragment"))
        .ok_or_else(|| format!("no `@fragment fn {entry}(`"))?;
    let attr = wgsl[..at].trim_end().len() - "@fragment".len();
    let open = at + needle.len() - 1;
    let close = matching_paren(wgsl, open).ok_or("unbalanced parameter list")?;
    let params = split_params(&wgsl[open + 1..close]);
    let brace = close + wgsl[close..].find('{').ok_or("no function body")?;
    let ret = wgsl[close + 1..brace].trim();
    if ret != "-> @location(0) vec4<f32>" {
        return Err(format!(
            "`{entry}` returns `{ret}`, not `@location(0) vec4<f32>`"
        ));
    }
    let stripped: Vec<String> = params.iter().map(|p| strip_attributes(p)).collect();
    let names: Vec<&str> = stripped
        .iter()
        .map(|p| p.split(':').next().unwrap_or("").trim())
        .collect();
    let varyings = stripped
        .iter()
        .zip(&names)
        .find(|(p, _)| p.split(':').nth(1).map(str::trim) == Some("WeftVaryings"))
        .map(|(_, n)| *n)
        .ok_or_else(|| format!("`{entry}` takes no WeftVaryings"))?;
    let base = format!("weft_syn_base_{entry}");
    let mut out = String::with_capacity(wgsl.len() + body.len() + 1024);
    out.push_str(&wgsl[..attr]);
    let _ = write!(out, "fn {base}({}) -> vec4<f32> ", stripped.join(", "));
    out.push_str(&wgsl[brace..]);
    if !out.ends_with('\n') {
        out.push('\n');
    }
    let _ = write!(
        out,
        "
// ---- synthetic keywords (cargo xtask bench scale) ----
@fragment
fn {entry}({}) -> @location(0) vec4<f32> {{
    var c = {base}({});
    let vin = {varyings};
    let v = weft_view_direction(vin.world_position, vec3<f32>(0.0, 0.0, 1.0));
    let n = weft_safe_normalize(vin.world_normal, v);
    let n_dot_v = weft_clamp_cos(dot(n, v));
    let l = weft_main_light_direction();
{body}    return c;
}}
",
        params.join(", "),
        names.join(", ")
    );
    Ok(out)
}

/// Moves float parameters' defaults (those with a `range` and no
/// `default_when`) to a seeded point inside the middle of their range.
fn jitter_defaults(toml_text: &str, rng: &mut Rng) -> Result<String, String> {
    let table: toml::Table = toml_text.parse().map_err(|e| format!("{e}"))?;
    let params = table.get("params").and_then(|p| p.as_table());
    let mut out = String::with_capacity(toml_text.len());
    let mut section = String::new();
    for line in toml_text.split_inclusive('\n') {
        let t = line.trim();
        if t.starts_with('[') {
            section = t.trim_matches(|c| c == '[' || c == ']').trim().to_string();
        }
        let param = section
            .strip_prefix("params.")
            .and_then(|n| params.and_then(|p| p.get(n)))
            .and_then(|p| p.as_table());
        if let Some(p) = param
            && t.starts_with("default =")
            && p.get("type").and_then(|v| v.as_str()) == Some("float")
            && p.get("default_when").is_none()
            && p.get("default").is_some_and(|d| d.is_float())
            && let Some([lo, hi]) = p.get("range").and_then(|r| r.as_array()).and_then(|r| {
                let v: Vec<f64> = r.iter().filter_map(|x| x.as_float()).collect();
                <[f64; 2]>::try_from(v).ok()
            })
        {
            let x = rng.range(lo + 0.2 * (hi - lo), lo + 0.8 * (hi - lo));
            let _ = writeln!(out, "default = {}", lit(x.clamp(lo, hi)));
            continue;
        }
        out.push_str(line);
    }
    Ok(out)
}

/// Replaces the value of `key = …` lines in `[section]` (the first one).
fn set_key(toml_text: &str, section: &str, key: &str, value: &str) -> Result<String, String> {
    let mut out = String::with_capacity(toml_text.len());
    let (mut current, mut done) = (String::new(), false);
    for line in toml_text.split_inclusive('\n') {
        let t = line.trim();
        if t.starts_with('[') {
            current = t.trim_matches(|c| c == '[' || c == ']').trim().to_string();
        }
        if !done
            && current == section
            && t.split('=').next().map(str::trim) == Some(key)
            && t.contains('=')
        {
            let _ = writeln!(out, "{key} = {value}");
            done = true;
            continue;
        }
        out.push_str(line);
    }
    if !done {
        return Err(format!("no `{key}` in [{section}]"));
    }
    Ok(out)
}

/// One synthetic material's files.
pub struct Synthetic {
    pub name: String,
    pub toml: String,
    pub wgsl_name: String,
    pub wgsl: String,
    pub variants: usize,
}

/// Derives synthetic material number `index` from `base`.
pub fn synthesise(
    base: &Base,
    index: usize,
    per_material: usize,
    seed: u64,
) -> Result<Synthetic, String> {
    let mut rng = Rng::new(seed ^ (index as u64).wrapping_mul(0x2545_f491_4f6c_dd1d));
    let name = format!("{}_{index:04}_syn", base.name);
    let factor = per_material as f64 / base.variants.max(1) as f64;
    let features = pick_features(factor, &mut rng);
    let multiplier: usize = features
        .iter()
        .map(|&i| FEATURES[i].value_count())
        .product();
    let variants = base.variants * multiplier;
    let wgsl_name = format!("{name}.wgsl");
    let label = format!("\"{} (synthetic {index})\"", base.name);
    let mut toml = jitter_defaults(&base.toml, &mut rng)?;
    toml = set_key(&toml, "material", "name", &format!("\"{name}\""))?;
    toml = set_key(&toml, "material", "label", &label)?;
    toml = set_key(&toml, "material", "source", &format!("\"{wgsl_name}\""))?;
    toml = set_key(&toml, "variants", "max_variants", &variants.to_string())?;
    toml.push_str(&format!(
        "\n# ---- synthetic (cargo xtask bench scale, seed {seed:#x}) ----\n\n[groups.synthetic]\nlabel = \"Synthetic\"\nlabel_zh = \"合成\"\n\n"
    ));
    let mut body = String::new();
    for &i in &features {
        toml.push_str(&(FEATURES[i].toml)(&mut rng));
        body.push_str(&(FEATURES[i].wgsl)(&mut rng));
    }
    let mut wgsl = base.source.1.clone();
    for entry in &base.fragments {
        wgsl = wrap_fragment(&wgsl, entry, &body).map_err(|e| format!("{}: {e}", base.name))?;
    }
    Ok(Synthetic {
        name,
        toml: toml.trim_end().to_string() + "\n",
        wgsl_name,
        wgsl,
        variants,
    })
}

/// A generated library.
pub struct Library {
    /// The materials folder (with `lib/`).
    pub dir: PathBuf,
    /// Variants the front end will enumerate (tiers × static keyword values).
    pub variants: usize,
}

/// Writes `count` synthetic materials derived from `shipped` (a materials
/// folder) into `dest` (replaced), with `shipped/lib` and the shipped
/// materials' `textures/` folders copied beside them.
pub fn generate(
    shipped: &Path,
    dest: &Path,
    count: usize,
    per_material: usize,
    seed: u64,
) -> Result<Library, String> {
    let bases = load_bases(shipped)?;
    if bases.is_empty() {
        return Err(format!("no materials under {}", shipped.display()));
    }
    if dest.exists() {
        std::fs::remove_dir_all(dest).map_err(|e| format!("{}: {e}", dest.display()))?;
    }
    copy_dir(&shipped.join("lib"), &dest.join("lib"))?;
    // The shipped texture files (`file = "<base>/textures/x.png"`): a copy
    // keeps naming its base's path under the materials root.
    for entry in std::fs::read_dir(shipped).map_err(|e| format!("{}: {e}", shipped.display()))? {
        let base = entry.map_err(|e| e.to_string())?.path();
        let textures = base.join("textures");
        if textures.is_dir() {
            let name = base.file_name().expect("a folder entry has a name");
            copy_dir(&textures, &dest.join(name).join("textures"))?;
        }
    }
    let mut variants = 0;
    for i in 0..count {
        let s = synthesise(&bases[i % bases.len()], i, per_material, seed)?;
        let dir = dest.join(&s.name);
        std::fs::create_dir_all(&dir).map_err(|e| e.to_string())?;
        std::fs::write(dir.join(format!("{}.toml", s.name)), &s.toml)
            .and_then(|()| std::fs::write(dir.join(&s.wgsl_name), &s.wgsl))
            .map_err(|e| format!("{}: {e}", dir.display()))?;
        variants += s.variants;
    }
    Ok(Library {
        dir: dest.to_path_buf(),
        variants,
    })
}

pub fn copy_dir(from: &Path, to: &Path) -> Result<(), String> {
    std::fs::create_dir_all(to).map_err(|e| format!("{}: {e}", to.display()))?;
    let mut entries: Vec<_> = std::fs::read_dir(from)
        .map_err(|e| format!("{}: {e}", from.display()))?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .collect();
    entries.sort();
    for p in entries {
        let target = to.join(p.file_name().expect("entry name"));
        if p.is_dir() {
            copy_dir(&p, &target)?;
        } else {
            std::fs::copy(&p, &target).map_err(|e| format!("{}: {e}", p.display()))?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shipped() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../materials")
    }

    #[test]
    fn attributes_are_stripped_and_the_entry_wrapped() {
        assert_eq!(
            strip_attributes("@builtin(front_facing) ff: bool"),
            "ff: bool"
        );
        let src = "@fragment\nfn fs(in: WeftVaryings, @builtin(front_facing) ff: bool) -> @location(0) vec4<f32> {\n    return vec4<f32>(1.0);\n}\n";
        let out = wrap_fragment(src, "fs", "").unwrap();
        assert!(
            out.starts_with("fn weft_syn_base_fs(in: WeftVaryings, ff: bool) -> vec4<f32> {"),
            "{out}"
        );
        assert!(out.contains("var c = weft_syn_base_fs(in, ff);"), "{out}");
        assert!(out.contains(
            "@fragment\nfn fs(in: WeftVaryings, @builtin(front_facing) ff: bool) -> @location(0) vec4<f32> {"
        ));
    }

    /// One synthetic material per shipped base compiles without warnings,
    /// with the variant count the generator promised; generation is
    /// deterministic.
    #[test]
    fn every_base_yields_a_compiling_material() {
        let tmp = tempfile::tempdir().unwrap();
        let dest = tmp.path().join("materials");
        let bases = load_bases(&shipped()).unwrap();
        let lib = generate(&shipped(), &dest, bases.len(), 48, DEFAULT_SEED).unwrap();
        let again = tmp.path().join("again");
        generate(&shipped(), &again, bases.len(), 48, DEFAULT_SEED).unwrap();
        for name in weft_compiler::output::list_files(&dest).unwrap() {
            assert_eq!(
                std::fs::read(dest.join(&name)).unwrap(),
                std::fs::read(again.join(&name)).unwrap(),
                "{name} differs between two runs"
            );
        }
        let out = match weft_compiler::build_library(&dest, &Default::default(), &|_, _, _| {}) {
            Ok(out) => out,
            Err((db, diags)) => {
                let mut s = codespan_reporting::term::termcolor::Buffer::no_color();
                diags.emit(&db, &mut s);
                panic!("{}", String::from_utf8_lossy(s.as_slice()));
            }
        };
        if let Some((db, diags)) = &out.warnings {
            let mut s = codespan_reporting::term::termcolor::Buffer::no_color();
            diags.emit(db, &mut s);
            panic!("warnings: {}", String::from_utf8_lossy(s.as_slice()));
        }
        assert_eq!(out.materials.len(), bases.len());
        assert_eq!(out.variant_count, lib.variants);
        // Each material lands within a factor sqrt(3) of the target (the
        // keywords multiply the base's count by a 2^a 3^b).
        let target = 48.0 * bases.len() as f64;
        let ratio = lib.variants as f64 / target;
        assert!(
            (0.577..=1.733).contains(&ratio),
            "{} variants for a target of {target}",
            lib.variants
        );
    }
}
