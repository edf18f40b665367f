//! Keeps README.md's material table true to the metadata: every material
//! of the library has a row, each row's picture exists, and its tier texts
//! name exactly the material's tiers, each marked as the metadata says
//! ("approximates reference" for an approximation, "look" for a look).
//! Run by the test below (so by `cargo test --workspace`); only tests use it.

use std::collections::BTreeMap;
use std::path::Path;

/// One row of the table: picture, tier name → its text.
struct Row {
    picture: String,
    tiers: BTreeMap<String, String>,
}

/// The rows of README.md's "## The materials" table, by material name.
fn rows(readme: &str) -> Result<BTreeMap<String, Row>, String> {
    let section = readme
        .split("\n## The materials\n")
        .nth(1)
        .and_then(|s| s.split("\n## ").next())
        .ok_or("README.md has no `## The materials` section")?;
    let mut out = BTreeMap::new();
    for line in section.lines().filter(|l| l.starts_with("| <img")) {
        let cells: Vec<&str> = line.split(" | ").collect();
        let picture = cells[0]
            .split("src=\"")
            .nth(1)
            .and_then(|s| s.split('"').next())
            .ok_or_else(|| format!("a row without a picture: {line}"))?;
        let name = cells
            .get(1)
            .and_then(|c| c.strip_prefix('['))
            .and_then(|c| c.split(']').next())
            .ok_or_else(|| format!("a row without a [material](…) link: {line}"))?;
        let tiers = cells
            .get(3)
            .map(|c| c.trim_end_matches(" |"))
            .ok_or_else(|| format!("{name}: no tiers cell"))?
            .split(" · ")
            .filter_map(|t| {
                let (tier, text) = t.split_once(": ")?;
                Some((tier.trim().to_string(), text.to_string()))
            })
            .collect();
        out.insert(
            name.to_string(),
            Row {
                picture: picture.to_string(),
                tiers,
            },
        );
    }
    Ok(out)
}

/// What README.md's material table says that the metadata does not.
pub fn readme_material_problems(root: &Path) -> Result<Vec<String>, String> {
    let readme = std::fs::read_to_string(root.join("README.md")).map_err(|e| e.to_string())?;
    let rows = rows(&readme)?;
    let mut problems = Vec::new();
    let generated = root.join("generated");
    let mut materials = Vec::new();
    for entry in std::fs::read_dir(&generated).map_err(|e| e.to_string())? {
        let name = entry.map_err(|e| e.to_string())?.file_name();
        let name = name.to_string_lossy().into_owned();
        let meta = generated.join(&name).join(format!("{name}.meta.json"));
        if meta.is_file() {
            materials.push((name, meta));
        }
    }
    materials.sort();
    for (name, meta) in &materials {
        let Some(row) = rows.get(name) else {
            problems.push(format!("{name}: no row in README.md's material table"));
            continue;
        };
        if !root.join(&row.picture).is_file() {
            problems.push(format!(
                "{name}: the picture {} does not exist (`cargo xtask gallery`)",
                row.picture
            ));
        }
        let text = std::fs::read_to_string(meta).map_err(|e| e.to_string())?;
        let json: serde_json::Value = serde_json::from_str(&text).map_err(|e| e.to_string())?;
        let tiers = &json["tiers"];
        let names: Vec<String> = tiers["values"]
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(|v| v.as_str().map(str::to_string))
            .collect();
        let written: Vec<&String> = row.tiers.keys().collect();
        let mut sorted = names.clone();
        sorted.sort();
        if written != sorted.iter().collect::<Vec<_>>() {
            problems.push(format!(
                "{name}: README.md lists tiers {written:?}; the metadata has {names:?}"
            ));
        }
        for (tier, text) in &row.tiers {
            let approximates = tiers["approximates"].get(tier).and_then(|v| v.as_str());
            let look = tiers["looks"]
                .as_array()
                .is_some_and(|l| l.iter().any(|v| v == tier.as_str()));
            let says_approx = text.contains("approximates ");
            let says_look = text.contains("(look)");
            match approximates {
                Some(r) if !text.contains(&format!("approximates {r}")) => problems.push(format!(
                    "{name} {tier}: README.md does not say it approximates {r}"
                )),
                None if says_approx => problems.push(format!(
                    "{name} {tier}: README.md says it approximates; the metadata does not"
                )),
                _ => {}
            }
            if look != says_look {
                problems.push(format!(
                    "{name} {tier}: README.md {} it a look; the metadata {}",
                    if says_look { "calls" } else { "does not call" },
                    if look { "does" } else { "does not" }
                ));
            }
        }
    }
    for name in rows.keys() {
        if !materials.iter().any(|(m, _)| m == name) {
            problems.push(format!(
                "{name}: a README.md row for no material of the library"
            ));
        }
    }
    Ok(problems)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn readme_material_table_matches_the_metadata() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        let problems = readme_material_problems(root).unwrap();
        assert!(
            problems.is_empty(),
            "README.md's material table is out of date:\n{}",
            problems.join("\n")
        );
    }

    #[test]
    fn rows_read_tiers_and_pictures() {
        let readme = "x\n## The materials\n\n| | material | from | tiers |\n| --- |\n| <img src=\"a.png\" width=\"9\"> | [m](materials/m/) — text | src | fast: quick (approximates reference) · reference: full |\n\n## Next\n";
        let rows = rows(readme).unwrap();
        let m = &rows["m"];
        assert_eq!(m.picture, "a.png");
        assert_eq!(m.tiers.keys().collect::<Vec<_>>(), ["fast", "reference"]);
        assert!(m.tiers["fast"].contains("approximates reference"));
    }
}
