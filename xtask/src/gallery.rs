//! `cargo xtask gallery`: generated/gallery/ and generated/gallery.md.

use crate::render_sets::png_bytes;
use crate::render_sets::render_cases;
use crate::render_sets::render_scenes;
use std::path::Path;
use std::process::ExitCode;
use weft_compiler::output;
use weft_meta::gpu_model::ModelSummary;

pub(crate) const GALLERY_SIZE: u32 = 160;

/// Size of a scene's image in the gallery.
pub(crate) const SCENE_GALLERY_SIZE: (u32, u32) = (480, 360);

pub(crate) fn gallery(root: &Path) -> ExitCode {
    let mut files = std::collections::BTreeMap::new();
    let mut tiles = Vec::new();
    let mut sections: Vec<(weft_meta::MaterialMetadata, Vec<String>)> = Vec::new();
    let result = render_cases(root, GALLERY_SIZE, |case, meta, ldr| {
        let rel = format!("{}/{}.png", case.material, case.name);
        files.insert(rel.clone(), png_bytes(GALLERY_SIZE, &ldr));
        if !case.name.ends_with(".cloth") || case.name == "default.cloth" {
            tiles.push(ldr);
        }
        match sections.last_mut() {
            Some((m, cases)) if m.name == meta.name => cases.push(case.name.clone()),
            _ => sections.push((meta.clone(), vec![case.name.clone()])),
        }
    });
    let adapter = match result {
        Ok(a) => a,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    let scenes = match render_scenes(root, SCENE_GALLERY_SIZE) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::FAILURE;
        }
    };
    for (name, _, ldr) in &scenes {
        let (w, h) = SCENE_GALLERY_SIZE;
        files.insert(
            format!("scenes/{name}.png"),
            weft_render::encode_png(w, h, ldr).expect("encode PNG"),
        );
    }
    let (w, h, sheet) = weft_golden::contact_sheet(&tiles, GALLERY_SIZE, 8);
    files.insert(
        "contact_sheet.png".into(),
        weft_render::encode_png(w, h, &sheet).expect("encode PNG"),
    );
    let generated = root.join("generated");
    // Measured tiers, when `cargo xtask regenerate --reports` left reports.
    for (m, _) in &mut sections {
        let meta_path = generated
            .join(&m.name)
            .join(format!("{}.meta.json", m.name));
        if let Err(e) = m.attach_measurements(&meta_path) {
            eprintln!("warning: ignoring measurements: {e}");
        }
    }
    // The GPU model's columns beside them (absent without gpu-model.json).
    let model = ModelSummary::load(&generated.join("reports")).ok();
    let mut md = gallery_markdown(&sections, &adapter, model.as_ref());
    md.push_str(&scenes_markdown(&scenes));
    let write = output::write_atomically(&generated.join("gallery"), &files, &[])
        .and_then(|()| std::fs::write(generated.join("gallery.md"), md));
    match write {
        Ok(()) => {
            println!(
                "gallery: {} images + contact sheet in generated/gallery/, generated/gallery.md",
                files.len() - 1
            );
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: cannot write the gallery: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The gallery's scene section: each shipped scene's image and its instances.
pub(crate) fn scenes_markdown(
    scenes: &[(String, weft_meta::scene::SceneMetadata, Vec<u8>)],
) -> String {
    use std::fmt::Write;
    let (w, h) = SCENE_GALLERY_SIZE;
    let mut md = String::new();
    let _ = writeln!(
        md,
        "## Scenes\n\nEvery scene under `scenes/` as `cargo xtask regenerate` builds it (`generated/scenes/<scene>/`): each instance drawn with its specialised shader, {w}x{h}, same sky, light and tone mapping.\n"
    );
    for (name, meta, _) in scenes {
        let _ = writeln!(md, "### {name}\n");
        if let Some(d) = &meta.description {
            let _ = writeln!(md, "{d}\n");
        }
        let _ = writeln!(
            md,
            "<img src=\"gallery/scenes/{name}.png\" width=\"{w}\" title=\"{name}\" alt=\"{name}\">\n"
        );
        let _ = writeln!(
            md,
            "{} instances, {} shaders.\n",
            meta.instances.len(),
            meta.shaders.len()
        );
        let _ = writeln!(
            md,
            "| instance | material | preset | tier | shader |\n|---|---|---|---|---|"
        );
        for i in &meta.instances {
            let tier = if i.tier_choice.is_some() {
                format!("auto → {}", i.tier)
            } else {
                i.tier.clone()
            };
            let _ = writeln!(
                md,
                "| {} | {} | {} | {tier} | `{}` |",
                i.name,
                i.material,
                i.preset.as_deref().unwrap_or("—"),
                i.shader
            );
        }
        let _ = writeln!(md);
    }
    md
}

pub(crate) fn gallery_markdown(
    sections: &[(weft_meta::MaterialMetadata, Vec<String>)],
    adapter: &str,
    model: Option<&ModelSummary>,
) -> String {
    use std::fmt::Write;
    let mut md = String::new();
    let _ = writeln!(md, "# weft material gallery\n");
    let _ = writeln!(
        md,
        "Generated by `cargo xtask gallery` (do not edit): every material's default variant on the sphere and the cloth patch, every tier, keyword value and preset, {GALLERY_SIZE}x{GALLERY_SIZE}, ACES tone mapping, rendered on {adapter}.\n"
    );
    let _ = writeln!(md, "![contact sheet](gallery/contact_sheet.png)\n");
    for (m, cases) in sections {
        let _ = writeln!(md, "## {} — {}\n", m.name, m.label.en);
        if let Some(d) = &m.description {
            let _ = writeln!(md, "{}\n", d.en);
        }
        for c in cases {
            let _ = write!(
                md,
                "<img src=\"gallery/{}/{c}.png\" width=\"{GALLERY_SIZE}\" title=\"{c}\" alt=\"{c}\"> ",
                m.name
            );
        }
        let _ = writeln!(md, "\n\n{}\n", cases.join(" · "));
        let _ = writeln!(
            md,
            "| group | parameter | type | default | range | label | 中文 |\n|---|---|---|---|---|---|---|"
        );
        for p in &m.parameters {
            let range = p
                .range
                .map(|r| format!("[{}, {}]", r[0], r[1]))
                .unwrap_or_default();
            let zh = p.label.zh.clone().unwrap_or_default();
            let default = p.default.to_string().replace('|', "\\|");
            let default = if default.len() > 40 {
                format!(
                    "{}…",
                    &default[..default
                        .char_indices()
                        .nth(37)
                        .map_or(default.len(), |(i, _)| i)]
                )
            } else {
                default
            };
            let _ = writeln!(
                md,
                "| {} | `{}` | {} | {} | {} | {} | {} |",
                p.group,
                p.name,
                p.kind.name(),
                default,
                range,
                p.label.en,
                zh
            );
        }
        let _ = writeln!(md);
        if !m.keywords.is_empty() {
            let _ = writeln!(
                md,
                "Keywords: {}\n",
                m.keywords
                    .iter()
                    .map(|k| format!("`{}` ({})", k.name, k.values.join(" / ")))
                    .collect::<Vec<_>>()
                    .join(", ")
            );
        }
        let _ = writeln!(md, "{}\n", tiers_line(m));
        if let Some(ms) = &m.measurements {
            // Marked, so that a new GPU model rewrites the table without
            // rendering again (bench_shading::rewrite_cost_tables).
            let _ = writeln!(
                md,
                "Cost and accuracy per tier (from `generated/reports/{}.measurements.json`):\n\n<!-- weft:{}:begin -->\n{}<!-- weft:{}:end -->\n\n![{} cost vs error](reports/{}.pareto.svg)\n",
                m.name,
                gallery_marker(&m.name),
                weft_golden::cost_tables::gallery_table(ms, &m.inputs_hash, model),
                gallery_marker(&m.name),
                m.name,
                m.name
            );
        }
    }
    md
}

/// The marker name around `material`'s tier table in gallery.md.
pub(crate) fn gallery_marker(material: &str) -> String {
    format!("tiers-{material}")
}

/// The material's tiers and what each computes, one line.
fn tiers_line(m: &weft_meta::MaterialMetadata) -> String {
    let tiers: Vec<String> = m
        .tiers
        .values
        .iter()
        .map(|t| {
            let description = m.tiers.descriptions.get(t).map_or("", |d| d.en.as_str());
            format!("**{t}** — {description}")
        })
        .collect();
    format!("Tiers: {}", tiers.join("; "))
}

#[cfg(test)]
mod tests {
    use super::{ModelSummary, tiers_line};

    /// The committed gallery.md says what the committed metadata and reports
    /// say: each material's description, tiers and measured tier table.
    /// (Its images are rendered, on llvmpipe, which differs between CPUs,
    /// so they are not checked here.)
    #[test]
    fn the_gallerys_text_is_current() {
        let generated = crate::workspace_root().join("generated");
        let md = std::fs::read_to_string(generated.join("gallery.md")).unwrap();
        let rerun = "generated/gallery.md is stale: run `cargo xtask gallery`";
        let model = ModelSummary::load(&generated.join("reports")).ok();
        for (_, mut m) in weft_golden::materials(&generated).unwrap() {
            let meta_path = generated
                .join(&m.name)
                .join(format!("{}.meta.json", m.name));
            m.attach_measurements(&meta_path).unwrap();
            if let Some(d) = &m.description {
                assert!(md.contains(&d.en), "{}: description; {rerun}", m.name);
            }
            assert!(md.contains(&tiers_line(&m)), "{}: tiers; {rerun}", m.name);
            if let Some(ms) = &m.measurements {
                let table =
                    weft_golden::cost_tables::gallery_table(ms, &m.inputs_hash, model.as_ref());
                assert!(md.contains(&table), "{}: measured tiers; {rerun}", m.name);
            }
        }
    }
}
