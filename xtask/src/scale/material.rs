//! One synthetic material: a shipped base loaded, features picked to reach
//! the variant count, its defaults jittered and its TOML and WGSL written.

use super::Rng;
use super::features::{FEATURES, lit};
use super::wgsl::wrap_fragment;
use std::fmt::Write as _;
use std::path::Path;

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
