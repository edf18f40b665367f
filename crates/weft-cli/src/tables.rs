//! Plain-text tables for `weft inspect` and `weft variants`.

use std::fmt::Write;
use weft_meta::{Condition, ConditionOp, MaterialMetadata};

/// Renders rows as left-aligned columns separated by two spaces.
pub fn table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut widths: Vec<usize> = header.iter().map(|h| h.chars().count()).collect();
    for r in rows {
        for (i, c) in r.iter().enumerate() {
            widths[i] = widths[i].max(c.chars().count());
        }
    }
    let mut out = String::new();
    let line = |out: &mut String, cells: Vec<&str>| {
        let mut s = String::new();
        for (i, c) in cells.iter().enumerate() {
            let pad = widths[i] - c.chars().count();
            s.push_str(c);
            if i + 1 < cells.len() {
                s.push_str(&" ".repeat(pad + 2));
            }
        }
        let _ = writeln!(out, "{}", s.trim_end());
    };
    line(&mut out, header.to_vec());
    line(
        &mut out,
        widths
            .iter()
            .map(|w| "-".repeat(*w))
            .collect::<Vec<_>>()
            .iter()
            .map(|s| s.as_str())
            .collect(),
    );
    for r in rows {
        line(&mut out, r.iter().map(|s| s.as_str()).collect());
    }
    out
}

fn cond(c: &Option<Condition>) -> String {
    match c {
        None => String::new(),
        Some(c) => format!(
            "{} {} {}",
            c.subject,
            if c.op == ConditionOp::Equal {
                "=="
            } else {
                "!="
            },
            c.value
        ),
    }
}

fn num(x: f64) -> String {
    format!("{x}")
}

pub fn inspect(m: &MaterialMetadata) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{} — {}", m.name, m.label.en);
    if let Some(d) = &m.description {
        let _ = writeln!(out, "{}", d.en);
    }
    let _ = writeln!(out, "\nParameters");
    let mut params: Vec<_> = m.parameters.iter().collect();
    let group_pos = |g: &str| {
        m.groups
            .iter()
            .position(|x| x.name == g)
            .unwrap_or(usize::MAX)
    };
    params.sort_by_key(|p| (group_pos(&p.group), p.order));
    let rows: Vec<Vec<String>> = params
        .iter()
        .map(|p| {
            vec![
                p.group.clone(),
                p.name.clone(),
                p.kind.name().to_string(),
                p.default.to_string(),
                p.range
                    .map(|r| format!("[{}, {}]", num(r[0]), num(r[1])))
                    .unwrap_or_default(),
                p.label.en.clone(),
                cond(&p.show_if),
            ]
        })
        .collect();
    out.push_str(&table(
        &[
            "group", "name", "type", "default", "range", "label", "show if",
        ],
        &rows,
    ));
    let _ = writeln!(out, "\nKeywords");
    let rows: Vec<Vec<String>> = m
        .keywords
        .iter()
        .map(|k| {
            vec![
                k.name.clone(),
                format!("{:?}", k.kind).to_lowercase(),
                format!("{:?}", k.mode).to_lowercase(),
                k.values.join(" | "),
                k.default.clone(),
            ]
        })
        .collect();
    out.push_str(&table(
        &["name", "kind", "mode", "values", "default"],
        &rows,
    ));
    let _ = writeln!(out, "\nTiers (reference: {})", m.tiers.reference);
    let rows: Vec<Vec<String>> = m
        .tiers
        .values
        .iter()
        .map(|t| {
            vec![
                t.clone(),
                m.tiers
                    .descriptions
                    .get(t)
                    .map(|d| d.en.clone())
                    .unwrap_or_default(),
            ]
        })
        .collect();
    out.push_str(&table(&["tier", "what it computes"], &rows));
    if !m.presets.is_empty() {
        let _ = writeln!(out, "\nPresets");
        let rows: Vec<Vec<String>> = m
            .presets
            .iter()
            .map(|p| {
                vec![
                    p.name.clone(),
                    p.label.en.clone(),
                    p.values
                        .iter()
                        .map(|(k, v)| format!("{k}={v}"))
                        .collect::<Vec<_>>()
                        .join(" "),
                ]
            })
            .collect();
        out.push_str(&table(&["name", "label", "values"], &rows));
    }
    let _ = writeln!(out, "\nPasses");
    let rows: Vec<Vec<String>> = m
        .passes
        .iter()
        .map(|p| {
            let rs = &p.render_state;
            vec![
                p.name.clone(),
                format!("{} / {}", p.vertex_entry, p.fragment_entry),
                format!("{:?}", rs.blend).to_lowercase(),
                format!("{:?}", rs.cull).to_lowercase(),
                format!("write={} test={:?}", rs.depth_write, rs.depth_test).to_lowercase(),
                rs.stencil.map_or_else(
                    || "-".to_string(),
                    |s| {
                        format!(
                            "ref={} {:?} read={:#04x} write={:#04x} pass={:?}",
                            s.reference, s.compare, s.read_mask, s.write_mask, s.pass_op
                        )
                        .to_lowercase()
                    },
                ),
                rs.queue.to_string(),
            ]
        })
        .collect();
    out.push_str(&table(
        &[
            "pass",
            "entry points",
            "blend",
            "cull",
            "depth",
            "stencil",
            "queue",
        ],
        &rows,
    ));
    let canonical = m.variants.iter().filter(|v| v.alias_of.is_none()).count();
    let _ = writeln!(
        out,
        "\nVariants: {} ({} distinct, {} aliases) — `weft variants` lists them\n",
        m.variants.len(),
        canonical,
        m.variants.len() - canonical
    );
    out
}

pub fn variants(m: &MaterialMetadata) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{}: {} variants", m.name, m.variants.len());
    let rows: Vec<Vec<String>> = m
        .variants
        .iter()
        .map(|v| match (&v.alias_of, &v.shader) {
            (Some(a), _) => vec![v.id.clone(), format!("= {a}"), String::new(), String::new()],
            (None, Some(s)) => {
                let textures = s
                    .bindings
                    .iter()
                    .filter(|b| {
                        b.group == weft_meta::engine::MATERIAL_GROUP && b.parameter.is_some()
                    })
                    .count();
                let files: usize = s.all_files().count();
                let ubo = s
                    .material_uniform
                    .as_ref()
                    .map_or("-".into(), |u| format!("{} B", u.size));
                vec![
                    v.id.clone(),
                    format!("{} bindings ({textures} textures)", s.bindings.len()),
                    ubo,
                    format!("{files} files"),
                ]
            }
            _ => vec![v.id.clone(), String::new(), String::new(), String::new()],
        })
        .collect();
    out.push_str(&table(&["variant", "bindings", "uniform", "files"], &rows));
    out
}
