//! The bindings table of a material's README (between
//! `<!-- weft:bindings:begin -->` and `<!-- weft:bindings:end -->`): which
//! bindings each tier's variants use, read from the material's metadata
//! (`variants[].shader.bindings`). `cargo xtask regenerate` writes it after
//! building; `tests/contract/metadata_contract.rs` checks every README's table is the
//! one its committed metadata gives, so what a README says a tier binds
//! cannot drift from what the tier binds.

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write;
use weft_meta::{Binding, BindingKind, KeywordKind, MaterialMetadata, Variant};

/// The marker name: `<!-- weft:bindings:… -->`.
pub const MARKER: &str = "bindings";

/// What a binding carries, for the table's third column.
fn carries(b: &Binding) -> String {
    if let Some(r) = &b.resource {
        let what = if b.group == weft_meta::engine::MATERIAL_GROUP {
            "baked table"
        } else {
            "engine"
        };
        let file = r
            .file
            .as_ref()
            .map_or(String::new(), |f| format!(", file `{}`", f.path));
        return format!("{what} `{}`{file}", r.id);
    }
    if let Some(p) = &b.parameter {
        return format!("parameter `{p}`");
    }
    match b.kind {
        BindingKind::UniformBuffer => "material uniform".into(),
        BindingKind::Sampler | BindingKind::ComparisonSampler => "sampler".into(),
        other => format!("{other:?}"),
    }
}

/// One condition on a variant's static keywords, as the material format
/// writes conditions.
struct Atom {
    text: String,
    holds: BTreeSet<String>,
}

/// `K`, `!K` (toggles), `K == v` and `K != v` (enums) over `variants`.
fn atoms(meta: &MaterialMetadata, variants: &[&Variant]) -> Vec<Atom> {
    let mut out = Vec::new();
    for k in &meta.keywords {
        if !variants.iter().all(|v| v.keywords.contains_key(&k.name)) {
            continue; // not a static keyword
        }
        for value in &k.values {
            let with = |equal: bool| -> BTreeSet<String> {
                variants
                    .iter()
                    .filter(|v| (v.keywords[&k.name] == *value) == equal)
                    .map(|v| v.id.clone())
                    .collect()
            };
            let (is, is_not) = match k.kind {
                KeywordKind::Toggle if value == "on" => (k.name.clone(), format!("!{}", k.name)),
                KeywordKind::Toggle => continue, // `off` reads as `!K` above
                KeywordKind::Enum => (
                    format!("{} == {value}", k.name),
                    format!("{} != {value}", k.name),
                ),
            };
            out.push(Atom {
                text: format!("`{is}`"),
                holds: with(true),
            });
            out.push(Atom {
                text: format!("`{is_not}`"),
                holds: with(false),
            });
        }
    }
    out
}

/// The variants of one tier that use a binding (`some`, a strict non-empty
/// subset of `variants`), said as simply as their keywords allow: one
/// condition, two joined by "or" or "and", else the variant ids.
fn describe(meta: &MaterialMetadata, variants: &[&Variant], some: &BTreeSet<String>) -> String {
    let atoms = atoms(meta, variants);
    if let Some(a) = atoms.iter().find(|a| &a.holds == some) {
        return a.text.clone();
    }
    for (i, a) in atoms.iter().enumerate() {
        for b in &atoms[i + 1..] {
            if &a.holds.union(&b.holds).cloned().collect::<BTreeSet<_>>() == some {
                return format!("{} or {}", a.text, b.text);
            }
        }
    }
    for (i, a) in atoms.iter().enumerate() {
        for b in &atoms[i + 1..] {
            if &a
                .holds
                .intersection(&b.holds)
                .cloned()
                .collect::<BTreeSet<_>>()
                == some
            {
                return format!("{} and {}", a.text, b.text);
            }
        }
    }
    let ids: Vec<String> = some.iter().map(|id| format!("`{id}`")).collect();
    ids.join(", ")
}

/// The Markdown between the README's bindings markers: a sentence saying
/// what the table is, then one row per binding any variant uses, sorted by
/// (group, binding), and one column per tier.
pub fn readme_table(meta: &MaterialMetadata) -> String {
    // (group, binding, name) -> (what it carries, tier -> variant ids using it)
    type Uses = BTreeMap<String, BTreeSet<String>>;
    let mut rows: BTreeMap<(u32, u32, String), (String, Uses)> = BTreeMap::new();
    for v in &meta.variants {
        let Some(shader) = meta.resolve_variant(&v.id).and_then(|c| c.shader.as_ref()) else {
            continue;
        };
        for b in &shader.bindings {
            let row = rows
                .entry((b.group, b.binding, b.name.clone()))
                .or_insert_with(|| (carries(b), BTreeMap::new()));
            row.1
                .entry(v.tier.clone())
                .or_default()
                .insert(v.id.clone());
        }
    }
    let tiers = &meta.tiers.values;
    let by_tier: BTreeMap<&String, Vec<&Variant>> = tiers
        .iter()
        .map(|t| (t, meta.variants.iter().filter(|v| &v.tier == t).collect()))
        .collect();

    let mut md = format!(
        "Bindings each tier uses, from `variants[].shader.bindings` in \
         `generated/{0}/{0}.meta.json` (written by `cargo xtask regenerate`; a test checks it \
         against the metadata): ✓ every variant of the tier, — none, otherwise the variants \
         whose static keywords satisfy the condition.\n\n",
        meta.name
    );
    md.push_str("| binding | group/binding | carries |");
    for t in tiers {
        let _ = write!(md, " `{t}` |");
    }
    md.push_str("\n|---|---|---|");
    md.push_str(&"---|".repeat(tiers.len()));
    md.push('\n');
    for ((group, binding, name), (what, uses)) in &rows {
        let _ = write!(md, "| `{name}` | {group}/{binding} | {what} |");
        for t in tiers {
            let all = &by_tier[t];
            let cell = match uses.get(t) {
                None => "—".to_string(),
                Some(some) if some.len() == all.len() => "✓".to_string(),
                Some(some) => describe(meta, all, some),
            };
            let _ = write!(md, " {cell} |");
        }
        md.push('\n');
    }
    md
}
