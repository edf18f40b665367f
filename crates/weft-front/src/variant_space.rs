//! The size of a material's variant space, checked by counting before
//! anything enumerates it: a space too large to enumerate (static keywords
//! × tiers, or `constant` keyword combinations) and a space that
//! `[variants].exclude` empties are errors that name the counts.

use crate::diag::Diagnostics;
use crate::model::{Keyword, Material};
use crate::variants::{
    CONSTANT_COMBINATION_LIMIT, ENUMERATION_LIMIT, constant_combination_count, space_size,
};
use codespan_reporting::diagnostic::Label;
use weft_meta::KeywordMode;

/// At most this many keywords are listed one by one in a count's note.
const LISTED: usize = 8;

/// "tier: 2 values x A: 2 values x …", the last ones summarised.
fn factors(tiers: Option<usize>, keywords: &[&Keyword]) -> String {
    let mut parts: Vec<String> = tiers
        .map(|n| format!("tier: {n} values"))
        .into_iter()
        .collect();
    for k in keywords.iter().take(LISTED) {
        parts.push(format!("{}: {} values", k.name, k.values.len()));
    }
    if keywords.len() > LISTED {
        let more = keywords.len() - LISTED;
        parts.push(format!(
            "{more} more keyword{}",
            if more == 1 { "" } else { "s" }
        ));
    }
    parts.join(" x ")
}

fn count_text(n: Option<u128>) -> String {
    n.map_or_else(|| "more than 2^128".into(), |n| n.to_string())
}

/// The keyword at which the running product of `keywords`' value counts
/// (starting from `start`) first passes `limit`.
fn tipping<'m>(start: u128, keywords: &[&'m Keyword], limit: u128) -> Option<&'m Keyword> {
    let mut n = start;
    for k in keywords {
        n = n.saturating_mul(k.values.len() as u128);
        if n > limit {
            return Some(k);
        }
    }
    None
}

/// Reports a static space larger than [`ENUMERATION_LIMIT`] or more
/// constant combinations than [`CONSTANT_COMBINATION_LIMIT`]; true when
/// both are within their limits (the space may then be enumerated).
pub fn check_space(m: &Material, diags: &mut Diagnostics) -> bool {
    let mut ok = true;
    let statics: Vec<&Keyword> = m.static_keywords().collect();
    let size = space_size(m);
    if size.is_none_or(|n| n > ENUMERATION_LIMIT) {
        ok = false;
        let at = tipping(m.tiers.values.len() as u128, &statics, ENUMERATION_LIMIT)
            .map_or(m.decl.clone(), |k| k.decl.clone());
        let d = diags.error(
            "variant-space",
            format!(
                "the variant space has {} combinations, too many to enumerate",
                count_text(size)
            ),
            at.file,
            at.span,
            format!("passes {ENUMERATION_LIMIT} combinations with this keyword"),
        );
        d.notes.push(format!(
            "{} = {} combinations ({} static keywords)",
            factors(Some(m.tiers.values.len()), &statics),
            count_text(size),
            statics.len()
        ));
        d.notes.push(format!(
            "weft enumerates at most {ENUMERATION_LIMIT} combinations of tiers and static keyword values (before [variants].exclude); make keywords `mode = \"constant\"`, use bool parameters for run-time switches, or split the material"
        ));
    }
    let constants: Vec<&Keyword> = m
        .keywords
        .iter()
        .filter(|k| k.mode == KeywordMode::Constant)
        .collect();
    let combos = constant_combination_count(m);
    if combos.is_none_or(|n| n > CONSTANT_COMBINATION_LIMIT) {
        ok = false;
        let at = tipping(1, &constants, CONSTANT_COMBINATION_LIMIT)
            .map_or(m.decl.clone(), |k| k.decl.clone());
        let d = diags.error(
            "variant-space",
            format!(
                "`constant` keywords make {} value combinations per variant, more than {CONSTANT_COMBINATION_LIMIT}",
                count_text(combos)
            ),
            at.file,
            at.span,
            format!("passes {CONSTANT_COMBINATION_LIMIT} combinations with this keyword"),
        );
        d.notes.push(format!(
            "{} = {} combinations",
            factors(None, &constants),
            count_text(combos)
        ));
        d.notes.push(format!(
            "every combination is emitted as SPIR-V, HLSL, MSL and GLSL files of its own (WGSL keeps the overrides), so weft allows at most {CONSTANT_COMBINATION_LIMIT}; use bool or int parameters for run-time switches"
        ));
    }
    ok
}

/// `[variants].exclude` removed every one of the (enumerable) space's
/// variants: each filter is labelled with how many it matches.
pub fn report_all_excluded(m: &Material, diags: &mut Diagnostics) {
    let all = crate::variants::all_variants(m);
    let matched = |i: usize| all.iter().filter(|v| v.matches(m, &m.exclude[i])).count();
    let mut labels = m.exclude_spans.iter().enumerate().map(|(i, span)| {
        (
            span.clone(),
            format!("matches {} of the {}", matched(i), all.len()),
        )
    });
    let (file, (span, label)) = match labels.next() {
        Some(first) => (m.file, first),
        None => (
            m.decl.file,
            (m.decl.span.clone(), "in this material".into()),
        ),
    };
    let d = diags.error(
        "no-variants",
        format!(
            "[variants].exclude removes all {} variants of `{}`",
            all.len(),
            m.name
        ),
        file,
        span,
        label,
    );
    for (span, label) in labels {
        d.labels
            .push(Label::secondary(m.file, span).with_message(label));
    }
    d.notes.push(
        "a material must compile at least one variant; remove or narrow an `exclude` entry".into(),
    );
}

#[cfg(test)]
mod tests {
    use crate::diag::{Diagnostics, SourceDb};
    use crate::toml_reader::Cx;
    use std::path::Path;
    use std::time::{Duration, Instant};

    /// The codes `check` reports for a material with `body` after [material].
    fn codes(body: &str) -> Vec<String> {
        let text = format!(
            "[material]\nname = \"m\"\n{body}\n[[tier]]\nname = \"fast\"\n[[tier]]\nname = \"reference\"\n"
        );
        let mut db = SourceDb::new();
        let mut diags = Diagnostics::new();
        let file = db.add(Path::new("m.toml"), "m.toml".into(), text.clone());
        let mut m = crate::parse::parse_material(
            &text,
            Path::new("m.toml"),
            Path::new("."),
            &[],
            &mut Cx {
                file,
                diags: &mut diags,
            },
        )
        .unwrap_or_else(|| panic!("{}", diags.render_plain(&db)));
        crate::check::check(&mut m, &mut diags);
        diags.iter().filter_map(|d| d.code.clone()).collect()
    }

    fn toggles(n: usize, mode: &str) -> String {
        (0..n)
            .map(|i| {
                format!(
                    "[keywords.{}_{i}X]\ntype = \"toggle\"\nmode = \"{mode}\"\n",
                    mode.to_uppercase()
                )
            })
            .collect()
    }

    #[test]
    fn huge_spaces_fail_fast_by_counting() {
        for n in [17, 40, 200] {
            let start = Instant::now();
            assert_eq!(
                codes(&toggles(n, "static")),
                ["variant-space"],
                "{n} toggles"
            );
            assert!(
                start.elapsed() < Duration::from_secs(2),
                "{n} toggles took {:?}",
                start.elapsed()
            );
        }
        // 2 tiers x 2^15 = 65536: enumerable, so only the budget applies.
        assert_eq!(codes(&toggles(15, "static")), ["variant-budget"]);
        assert_eq!(codes(&toggles(9, "constant")), ["variant-space"]);
        assert!(codes(&toggles(8, "constant")).is_empty());
        assert_eq!(
            codes(&format!(
                "{}{}",
                toggles(200, "constant"),
                toggles(200, "static")
            )),
            ["variant-space", "variant-space"]
        );
    }

    #[test]
    fn exclude_that_removes_everything() {
        let body = "[keywords.A]\ntype = \"toggle\"\n[variants]\nexclude = [\"A\", \"!A\"]\n";
        assert_eq!(codes(body), ["no-variants"]);
        let body = "[variants]\nexclude = [\"tier == fast\", \"tier == reference\"]\n";
        assert_eq!(codes(body), ["no-variants"]);
        let body = "[variants]\nexclude = [\"tier == fast\"]\n";
        assert!(codes(body).is_empty());
    }
}
