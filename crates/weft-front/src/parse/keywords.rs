//! `[keywords.<NAME>]` tables -> [`Keyword`] and the `[[tier]]` list ->
//! [`Tiers`]: the axes of the variant space.

use super::{KEYWORD_KEYS, TIER_KEYS, is_snake_ident, is_upper_ident, parse_show_if};
use crate::diag::Span;
use crate::model::humanize;
use crate::model::*;
use crate::toml_reader::{Cx, Table, Value, expect_array, type_error};
use toml::de::DeValue;
use weft_meta::{KeywordKind, KeywordMode};

pub(super) fn parse_keyword(
    name: &str,
    name_span: Span,
    v: &Value,
    cx: &mut Cx,
) -> Option<Keyword> {
    let t = Table::new(v, format!("keyword `{name}`"), cx)?;
    t.check_keys(KEYWORD_KEYS, cx);
    if !is_upper_ident(name) || name == "WEFT_TIER" || name.starts_with("TIER_") {
        cx.error_with_note(
            "bad-name",
            format!("keyword name `{name}` is not an UPPER_SNAKE identifier (or is reserved)"),
            name_span.clone(),
            "becomes a WGSL override",
            "use UPPER_SNAKE_CASE not ending in a digit; WEFT_TIER and TIER_* are reserved for tiers",
        );
    }
    let kind = parse_kind(&t, cx)?;
    let mode = parse_mode(&t, cx)?;
    let values = parse_values(&t, name, &name_span, kind, cx)?;
    let default = parse_default(&t, name, kind, &values, cx)?;
    let show_if = parse_show_if(&t, cx);
    Some(Keyword {
        name: name.to_string(),
        kind,
        mode,
        values,
        default,
        label: t
            .string("label", cx)
            .unwrap_or_else(|| humanize(&name.to_lowercase())),
        label_zh: t.string("label_zh", cx),
        tooltip: t.string("tooltip", cx),
        tooltip_zh: t.string("tooltip_zh", cx),
        group: t.string("group", cx).unwrap_or_else(|| "main".into()),
        show_if,
        decl: Loc {
            file: cx.file,
            span: name_span,
        },
    })
}

/// `type`: a toggle when not given.
fn parse_kind(t: &Table, cx: &mut Cx) -> Option<KeywordKind> {
    let kind_name = t
        .string("type", cx)
        .unwrap_or_else(|| KeywordKind::Toggle.name().into());
    let kind = KeywordKind::ALL.into_iter().find(|k| k.name() == kind_name);
    if kind.is_none() {
        let other = kind_name.as_str();
        let names = KeywordKind::ALL.map(KeywordKind::name);
        let hint = crate::diag::did_you_mean(other, names).map_or_else(
            || format!("use `{}`", names.join("` or `")),
            |s| format!("did you mean `{s}`?"),
        );
        cx.error_with_note(
            "unknown-value",
            format!("unknown keyword type `{other}`"),
            t.span_of("type"),
            "unknown",
            hint,
        );
    }
    kind
}

/// `mode`: static when not given.
fn parse_mode(t: &Table, cx: &mut Cx) -> Option<KeywordMode> {
    let Some(name) = t.string("mode", cx) else {
        return Some(KeywordMode::Static);
    };
    let mode = KeywordMode::ALL.into_iter().find(|m| m.name() == name);
    if mode.is_none() {
        cx.error_with_note(
            "unknown-value",
            format!("unknown keyword mode `{name}`"),
            t.span_of("mode"),
            "unknown",
            "use `static` (a variant per value) or `constant` (a pipeline constant)",
        );
    }
    mode
}

/// The values: off/on for a toggle, an enum's `values` (lower-case, no
/// repeats, at least two).
fn parse_values(
    t: &Table,
    name: &str,
    name_span: &Span,
    kind: KeywordKind,
    cx: &mut Cx,
) -> Option<Vec<String>> {
    Some(match kind {
        KeywordKind::Toggle => {
            if t.get("values").is_some() {
                cx.error(
                    "unknown-key",
                    "a toggle keyword has the fixed values off/on",
                    t.key_span("values").unwrap_or(t.span.clone()),
                    "remove `values`, or use type = \"enum\"",
                );
            }
            vec!["off".into(), "on".into()]
        }
        KeywordKind::Enum => {
            let Some(list) = t.strings("values", cx) else {
                cx.error(
                    "missing-key",
                    format!("enum keyword `{name}` needs `values`"),
                    name_span.clone(),
                    "declared here",
                );
                return None;
            };
            let mut out: Vec<String> = Vec::new();
            for (value, span) in list {
                if !is_snake_ident(&value) {
                    cx.error(
                        "bad-name",
                        format!("keyword value `{value}` is not a lower-case identifier"),
                        span,
                        "becomes a WGSL constant suffix",
                    );
                } else if out.contains(&value) {
                    cx.error(
                        "duplicate",
                        format!("keyword value `{value}` is listed twice"),
                        span,
                        "again here",
                    );
                } else {
                    out.push(value);
                }
            }
            if out.len() < 2 {
                cx.error(
                    "wrong-type",
                    format!("enum keyword `{name}` needs at least two values"),
                    t.span_of("values"),
                    "here",
                );
                return None;
            }
            out
        }
    })
}

/// The index of `default` in `values` (0 when not given or unknown).
fn parse_default(
    t: &Table,
    name: &str,
    kind: KeywordKind,
    values: &[String],
    cx: &mut Cx,
) -> Option<usize> {
    Some(match t.get("default") {
        None => 0,
        Some(dv) => {
            let value = match (kind, dv.get_ref()) {
                (KeywordKind::Toggle, DeValue::Boolean(b)) => {
                    if *b { "on" } else { "off" }.to_string()
                }
                (_, DeValue::String(s)) => s.to_string(),
                (_, other) => {
                    type_error(
                        cx,
                        &format!("`default` of keyword `{name}`"),
                        "a value name (or true/false for a toggle)",
                        other,
                        dv.span(),
                    );
                    return None;
                }
            };
            match values.iter().position(|v| *v == value) {
                Some(i) => i,
                None => {
                    let hint = match crate::diag::did_you_mean(
                        &value,
                        values.iter().map(String::as_str),
                    ) {
                        Some(s) => format!(
                            "did you mean `{s}`? values of `{name}`: {}",
                            values.join(", ")
                        ),
                        None => format!("values of `{name}`: {}", values.join(", ")),
                    };
                    cx.error_with_note(
                        "unknown-value",
                        format!("`{value}` is not a value of keyword `{name}`"),
                        dv.span(),
                        "unknown value",
                        hint,
                    );
                    0
                }
            }
        }
    })
}

/// Per tier as written: the `approximates` value with its span, and the
/// span of `look = true`.
type DeclaredRelation = (Option<(String, Span)>, Option<Span>);

pub(super) fn parse_tiers(top: &Table, material: &mut Material, cx: &mut Cx) {
    let Some(v) = top.get("tier") else {
        cx.error_with_note(
            "missing-key",
            "no quality tiers declared",
            material.decl.span.clone(),
            "material declared here",
            "add [[tier]] tables named `fast` and `reference` (the reference is what other tiers are measured against)",
        );
        return;
    };
    let Some(items) = expect_array(v, "`tier`", cx) else {
        return;
    };
    let mut default = None;
    let mut declared: Vec<DeclaredRelation> = Vec::new();
    for item in items {
        let Some(t) = Table::new(item, "a [[tier]]", cx) else {
            continue;
        };
        t.check_keys(TIER_KEYS, cx);
        let Some(name) = t.string("name", cx) else {
            cx.error(
                "missing-key",
                "a [[tier]] needs a `name`",
                item.span(),
                "here",
            );
            continue;
        };
        if !is_snake_ident(&name) {
            cx.error(
                "bad-name",
                format!("tier name `{name}` is not a lower-case identifier"),
                t.span_of("name"),
                "becomes TIER_<NAME> in WGSL",
            );
            continue;
        }
        if material.tiers.values.contains(&name) {
            cx.error(
                "duplicate",
                format!("tier `{name}` is declared twice"),
                t.span_of("name"),
                "again here",
            );
            continue;
        }
        if t.boolean("default", cx) == Some(true) {
            if default.is_some() {
                cx.error(
                    "duplicate",
                    "more than one tier is marked `default = true`",
                    t.span_of("default"),
                    "second default",
                );
            }
            default = Some(material.tiers.values.len());
        }
        material.tiers.descriptions.push((
            name.clone(),
            t.string("description", cx).unwrap_or_default(),
            t.string("description_zh", cx),
        ));
        let approximates = t
            .string("approximates", cx)
            .map(|a| (a, t.span_of("approximates")));
        let look = (t.boolean("look", cx) == Some(true)).then(|| t.span_of("look"));
        declared.push((approximates, look));
        material.tiers.values.push(name);
    }
    // A stylised material may ship one tier of any name: it is the
    // reference (nothing is measured against it).
    let single_stylised = material.stylised && material.tiers.values.len() == 1;
    for required in ["fast", "reference"] {
        if single_stylised {
            break;
        }
        if !material.tiers.values.iter().any(|t| t == required) {
            cx.error_with_note(
                "missing-tier",
                format!("the `{required}` tier is missing"),
                v.span(),
                "tiers declared here",
                if material.stylised {
                    "a stylised material declares one tier, or at least `fast` and `reference`"
                } else {
                    "every material has at least `fast` and `reference` tiers; one with no physical ground truth may declare `stylised = true` in [material] and ship a single tier"
                },
            );
        }
    }
    material.tiers.reference = material
        .tiers
        .values
        .iter()
        .position(|t| t == "reference")
        .unwrap_or(0);
    material.tiers.default = default
        .or_else(|| material.tiers.values.iter().position(|t| t == "fast"))
        .unwrap_or(0);
    tier_relations(material, &declared, cx);
}

/// What each tier approximates, and which are looks: a look approximates
/// nothing and nothing approximates it; the reference approximates nothing;
/// every other tier approximates the reference unless it names another
/// tier, and following `approximates` always reaches the reference.
fn tier_relations(material: &mut Material, declared: &[DeclaredRelation], cx: &mut Cx) {
    let tiers = &material.tiers;
    let n = tiers.values.len();
    let looks: Vec<bool> = declared.iter().map(|(_, l)| l.is_some()).collect();
    let mut approximates = vec![None; n];
    for (i, (target, look)) in declared.iter().enumerate() {
        let name = &tiers.values[i];
        // A stylised material's only tier stands as its reference.
        if name == "reference" || (material.stylised && n == 1) {
            let what = if name == "reference" {
                "the `reference` tier".to_string()
            } else {
                format!("tier `{name}`, a stylised material's only tier, is its reference: it")
            };
            if let Some((_, span)) = target {
                cx.error(
                    "tier-relation",
                    format!(
                        "{what} approximates nothing: it is what the others are measured against"
                    ),
                    span.clone(),
                    "remove this",
                );
            }
            if let Some(span) = look {
                cx.error(
                    "tier-relation",
                    format!("{what} cannot be a look: it is the most accurate model"),
                    span.clone(),
                    "remove this",
                );
            }
            continue;
        }
        if look.is_some() {
            if let Some((_, span)) = target {
                cx.error_with_note(
                    "tier-relation",
                    format!("tier `{name}` is a look and cannot approximate another tier"),
                    span.clone(),
                    "a look is a different model",
                    "keep `look = true` for a different model (its difference is reported apart), or `approximates` for an approximation (its error is measured)",
                );
            }
            continue;
        }
        let Some((target, span)) = target else {
            approximates[i] = Some(tiers.reference);
            continue;
        };
        let Some(j) = tiers.values.iter().position(|t| t == target) else {
            let mut note = format!("tiers: {}", tiers.values.join(", "));
            if let Some(s) =
                crate::diag::did_you_mean(target, tiers.values.iter().map(String::as_str))
            {
                note = format!("did you mean `{s}`? {note}");
            }
            cx.error_with_note(
                "tier-relation",
                format!(
                    "tier `{name}` approximates `{target}`, which is not a tier of this material"
                ),
                span.clone(),
                "unknown tier",
                note,
            );
            continue;
        };
        if j == i || looks[j] {
            cx.error_with_note(
                "tier-relation",
                format!(
                    "tier `{name}` cannot approximate {}",
                    if j == i {
                        "itself".to_string()
                    } else {
                        format!("`{target}`, a look")
                    }
                ),
                span.clone(),
                "here",
                "an approximation is measured against a more accurate tier: usually `reference`",
            );
            continue;
        }
        approximates[i] = Some(j);
    }
    // Chains end at the reference (no cycles).
    for (i, (target, _)) in declared.iter().enumerate() {
        let mut at = i;
        let mut steps = 0;
        while let Some(next) = approximates[at] {
            at = next;
            steps += 1;
            if steps > n {
                break;
            }
        }
        if steps > n
            && let Some((_, span)) = target
        {
            cx.error(
                "tier-relation",
                format!(
                    "tier `{}` approximates in a cycle that never reaches the reference",
                    tiers.values[i]
                ),
                span.clone(),
                "part of the cycle",
            );
            approximates[i] = None;
        }
    }
    material.tiers.approximates = approximates;
    material.tiers.looks = looks;
}

#[cfg(test)]
mod tests {
    use crate::{Diagnostics, SourceDb, load_material_in_memory};
    use std::path::Path;

    /// Loads `[material]` + `tiers` (TOML text) and returns the material and
    /// the plain-text diagnostics.
    fn load(material_keys: &str, tiers: &str) -> (Option<crate::model::Material>, String) {
        let toml =
            format!("[material]\nname = \"m\"\nsource = \"m.wgsl\"\n{material_keys}\n{tiers}");
        let wgsl = "@fragment fn fs_main() -> @location(0) vec4<f32> { return vec4<f32>(1.0); }\n";
        let (mut db, mut diags) = (SourceDb::new(), Diagnostics::new());
        let m = load_material_in_memory(
            "m/m.toml",
            &toml,
            &[("m/m.wgsl".into(), wgsl.into())],
            Path::new("/materials"),
            &mut db,
            &mut diags,
        );
        (m, diags.render_plain(&db))
    }

    #[test]
    fn a_stylised_material_may_ship_one_tier_which_is_its_reference() {
        let (m, text) = load("stylised = true", "[[tier]]\nname = \"toon\"\n");
        let m = m.unwrap_or_else(|| panic!("{text}"));
        assert!(m.stylised);
        assert_eq!(m.tiers.values, ["toon"]);
        assert_eq!((m.tiers.reference, m.tiers.default), (0, 0));
        assert_eq!(m.tiers.approximates, [None]);
    }

    #[test]
    fn one_tier_without_stylised_is_an_error_that_names_the_key() {
        let (m, text) = load("", "[[tier]]\nname = \"toon\"\n");
        assert!(m.is_none());
        assert!(
            text.contains("missing-tier") && text.contains("stylised = true"),
            "{text}"
        );
    }

    #[test]
    fn a_stylised_materials_only_tier_cannot_be_a_look_or_approximate() {
        let (m, text) = load(
            "stylised = true",
            "[[tier]]\nname = \"seed\"\nlook = true\n",
        );
        assert!(m.is_none());
        assert!(
            text.contains("stylised material's only tier") && text.contains("look"),
            "{text}"
        );
        let (m, text) = load(
            "stylised = true",
            "[[tier]]\nname = \"seed\"\napproximates = \"seed\"\n",
        );
        assert!(m.is_none());
        assert!(text.contains("approximates nothing"), "{text}");
    }

    #[test]
    fn a_stylised_material_with_several_tiers_keeps_the_usual_rule() {
        let (m, text) = load(
            "stylised = true",
            "[[tier]]\nname = \"fast\"\n[[tier]]\nname = \"seed\"\nlook = true\n",
        );
        assert!(m.is_none());
        assert!(text.contains("the `reference` tier is missing"), "{text}");
        let (m, text) = load(
            "stylised = true",
            "[[tier]]\nname = \"fast\"\n[[tier]]\nname = \"reference\"\n",
        );
        assert!(m.is_some(), "{text}");
    }
}
