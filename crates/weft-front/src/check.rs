//! Cross-reference checks over a parsed material: names that must exist,
//! names that must not collide, preset values, instance sources and the
//! variant budget.
//!
//! References written in the TOML (`show_if`, `default_when`, `group`,
//! `[variants].exclude`, preset values, `instances`) are checked by
//! [`check_references`], which the parser calls once the whole file is read,
//! with the [`Sites`] where each reference was written so errors point at it.
//! [`check`] covers the rest.

use crate::diag::{Diagnostics, Span, did_you_mean};
use crate::model::*;
use crate::variants;
use codespan_reporting::diagnostic::Label;
use std::collections::HashMap;
use weft_meta::{Condition, KeywordKind, ParamKind};

/// Where the references of a material file were written (byte spans in its
/// TOML). Anything missing falls back to the declaration's span.
#[derive(Clone, Debug, Default)]
pub struct Sites {
    /// Parameter name -> its `show_if` string.
    pub param_show_if: HashMap<String, Span>,
    /// Parameter name -> the `if` string of each entry of its `default_when`
    /// that was kept (parallel to `Param::default_when`).
    pub param_default_when: HashMap<String, Vec<Span>>,
    /// Keyword name -> its `show_if` string.
    pub keyword_show_if: HashMap<String, Span>,
    /// Parameter name -> its `group` string.
    pub param_group: HashMap<String, Span>,
    /// Keyword name -> its `group` string.
    pub keyword_group: HashMap<String, Span>,
    /// (preset, key) -> (span of the key, span of the value).
    pub preset_values: HashMap<(String, String), (Span, Span)>,
    /// One per entry of `Material::passes`: the `instances` value, if written.
    pub instances: Vec<Option<Span>>,
    /// Whether the material file itself has `[groups]` (a shared pass file's
    /// groups do not make the material's own group names need declaring).
    pub material_declares_groups: bool,
}

/// Checks after the includes are resolved: generated names and the budget.
pub fn check(m: &mut Material, diags: &mut Diagnostics) {
    check_names(m, diags);
    check_pass_names(m, diags);
    check_budget(m, diags);
}

/// Checks the references the TOML makes (see [`Sites`]); called by the parser.
pub fn check_references(m: &mut Material, sites: &Sites, diags: &mut Diagnostics) {
    check_groups(m, sites, diags);
    let at = |span: Option<&Span>, decl: &Loc| Loc {
        file: decl.file,
        span: span.cloned().unwrap_or(decl.span.clone()),
    };
    for p in &m.params {
        if let Some(c) = &p.show_if {
            check_condition(
                m,
                c,
                &at(sites.param_show_if.get(&p.name), &p.decl),
                "show_if",
                diags,
            );
        }
    }
    for p in &m.params {
        let spans = sites.param_default_when.get(&p.name);
        for (i, (c, _)) in p.default_when.iter().enumerate() {
            let loc = at(spans.and_then(|s| s.get(i)), &p.decl);
            check_condition(m, c, &loc, "default_when", diags);
        }
    }
    for k in &m.keywords {
        if let Some(c) = &k.show_if {
            check_condition(
                m,
                c,
                &at(sites.keyword_show_if.get(&k.name), &k.decl),
                "show_if",
                diags,
            );
        }
    }
    let decl = Loc {
        file: m.file,
        span: m.max_variants_span.clone().unwrap_or(m.decl.span.clone()),
    };
    for (i, e) in m.exclude.iter().enumerate() {
        let loc = at(m.exclude_spans.get(i), &decl);
        for c in e {
            check_condition(m, c, &loc, "exclude", diags);
        }
    }
    check_presets(m, sites, diags);
    check_instances(m, sites, diags);
    check_pass_conditions(m, diags);
}

/// A pass's `when` names static keywords or `tier` with their values, and
/// some pass exists in every variant (one without `when`).
fn check_pass_conditions(m: &Material, diags: &mut Diagnostics) {
    for pass in &m.passes {
        let loc = Loc {
            file: pass.decl.file,
            span: pass.when_span.clone().unwrap_or(pass.decl.span.clone()),
        };
        for c in &pass.when {
            check_condition(m, c, &loc, "when", diags);
        }
    }
    if !m.passes.is_empty() && m.passes.iter().all(|p| !p.when.is_empty()) {
        let first = &m.passes[0];
        let d = diags.error(
            "pass-condition",
            "every pass has a `when` condition",
            first.decl.file,
            first.when_span.clone().unwrap_or(first.decl.span.clone()),
            "conditional pass",
        );
        d.notes.push("a variant where no condition holds would draw nothing: give the material a pass without `when` (its main pass)".into());
    }
}

/// Identifiers the prelude generates must be unique.
fn check_names(m: &Material, diags: &mut Diagnostics) {
    let mut names: Vec<(String, &Loc)> = Vec::new();
    for p in &m.params {
        names.push((p.name.clone(), &p.decl));
        if p.tiling {
            names.push((format!("{}_st", p.name), &p.decl));
        }
    }
    for t in &m.tables {
        for n in [
            t.name.clone(),
            format!("table_{}", t.name),
            format!("{}_shape", t.name),
            format!("{}_ring", t.name),
        ] {
            names.push((n, &t.decl));
        }
    }
    for k in &m.keywords {
        names.push((k.name.clone(), &k.decl));
        if k.kind == KeywordKind::Enum {
            names.extend(
                k.values
                    .iter()
                    .map(|v| (format!("{}_{}", k.name, v.to_uppercase()), &k.decl)),
            );
        }
    }
    for (i, (name, loc)) in names.iter().enumerate() {
        if let Some((_, first)) = names[..i].iter().find(|(n, _)| n == name) {
            let d = diags.error(
                "duplicate",
                format!("`{name}` is declared twice"),
                loc.file,
                loc.span.clone(),
                "second declaration",
            );
            d.labels.push(
                Label::secondary(first.file, first.span.clone())
                    .with_message("first declared here"),
            );
            d.notes.push("parameter names, generated members (`<texture>_st`) and keyword constants share one WGSL namespace".into());
        }
    }
}

fn check_groups(m: &mut Material, sites: &Sites, diags: &mut Diagnostics) {
    let declared = sites.material_declares_groups;
    let mut used: Vec<(String, Loc)> = m
        .params
        .iter()
        .map(|p| {
            (
                p.group.clone(),
                Loc {
                    file: p.decl.file,
                    span: sites
                        .param_group
                        .get(&p.name)
                        .cloned()
                        .unwrap_or(p.decl.span.clone()),
                },
            )
        })
        .collect();
    used.extend(m.keywords.iter().map(|k| {
        (
            k.group.clone(),
            Loc {
                file: k.decl.file,
                span: sites
                    .keyword_group
                    .get(&k.name)
                    .cloned()
                    .unwrap_or(k.decl.span.clone()),
            },
        )
    }));
    for (g, loc) in used {
        if m.groups.iter().any(|x| x.name == g) {
            continue;
        }
        if declared && g != "main" {
            let names: Vec<&str> = m.groups.iter().map(|x| x.name.as_str()).collect();
            let hint = did_you_mean(&g, names.iter().copied()).map_or_else(
                || {
                    format!(
                        "declare `[groups.{g}]`, or use one of: {}",
                        names.join(", ")
                    )
                },
                |s| format!("did you mean `{s}`?"),
            );
            let d = diags.error(
                "unknown-group",
                format!("unknown group `{g}`"),
                loc.file,
                loc.span,
                "not declared under [groups]",
            );
            d.notes.push(hint);
        } else {
            m.groups.push(Group {
                label: humanize(&g),
                name: g,
                label_zh: None,
            });
        }
    }
}

/// What a per-variant condition decides, for notes.
fn per_variant_subject(what: &str) -> &'static str {
    if what == "when" {
        "whether a pass exists"
    } else {
        "a texture default"
    }
}

/// One condition of `what` (`show_if`, `exclude` or `default_when`): its
/// subject exists and may be named there, and its value is one of the
/// subject's. `exclude` and `default_when` select variants, so they may only
/// name `tier` and `static` keywords.
fn check_condition(m: &Material, c: &Condition, loc: &Loc, what: &str, diags: &mut Diagnostics) {
    // `default_when` and a pass's `when` are decided per compiled variant.
    let per_variant = what == "default_when" || what == "when";
    let values: Option<Vec<String>> = if c.subject == "tier" {
        Some(m.tiers.values.clone())
    } else if let Some(k) = m.keyword(&c.subject) {
        if per_variant && k.mode == weft_meta::KeywordMode::Constant {
            let d = diags.error(
                "bad-condition",
                format!("`{what}` names `{}`, a `constant` keyword", c.subject),
                loc.file,
                loc.span.clone(),
                "in this condition",
            );
            d.labels.push(
                Label::secondary(k.decl.file, k.decl.span.clone())
                    .with_message("declared with mode = \"constant\""),
            );
            d.notes.push(format!("{} is fixed per compiled variant, and one variant serves every value of a constant keyword; make it `mode = \"static\"` or test a static keyword or `tier`", per_variant_subject(what)));
            return;
        }
        if what == "exclude" && k.mode == weft_meta::KeywordMode::Constant {
            let d = diags.error(
                "bad-condition",
                format!("`exclude` names `{}`, a `constant` keyword", c.subject),
                loc.file,
                loc.span.clone(),
                "in this filter",
            );
            d.labels.push(
                Label::secondary(k.decl.file, k.decl.span.clone())
                    .with_message("declared with mode = \"constant\""),
            );
            d.notes.push("a constant keyword does not create variants (one variant serves all its values), so there is nothing to exclude; make it `mode = \"static\"` or drop it from the filter".into());
            return;
        }
        Some(k.values.clone())
    } else if m
        .param(&c.subject)
        .is_some_and(|p| p.kind == ParamKind::Bool)
    {
        if what == "exclude" {
            let d = diags.error(
                "bad-condition",
                format!(
                    "`exclude` can only name keywords and `tier`, not parameter `{}`",
                    c.subject
                ),
                loc.file,
                loc.span.clone(),
                "in this filter",
            );
            d.notes.push("parameters do not create variants".into());
            return;
        }
        if per_variant {
            let d = diags.error(
                "bad-condition",
                format!(
                    "`{what}` can only name static keywords and `tier`, not parameter `{}`",
                    c.subject
                ),
                loc.file,
                loc.span.clone(),
                "in this condition",
            );
            d.notes.push(format!("{} is fixed per compiled variant, and parameters change at run time; use a static keyword", per_variant_subject(what)));
            return;
        }
        Some(vec!["off".into(), "on".into()])
    } else {
        None
    };
    let Some(values) = values else {
        // `default_when` can name only static keywords and `tier`: suggest only those.
        let (names, is_not): (Vec<&str>, &str) = if per_variant {
            let names = m.static_keywords().map(|k| k.name.as_str());
            (
                names.chain(["tier"]).collect(),
                "a static keyword or `tier`",
            )
        } else {
            let names = m.keywords.iter().map(|k| k.name.as_str()).chain(["tier"]);
            let bools = m.params.iter().filter(|p| p.kind == ParamKind::Bool);
            (
                names.chain(bools.map(|p| p.name.as_str())).collect(),
                "a keyword, `tier` or a bool parameter",
            )
        };
        let d = diags.error(
            "unknown-keyword",
            format!(
                "unknown keyword `{}` in {}",
                c.subject,
                if what == "when" {
                    "a pass's `when`"
                } else {
                    what
                }
            ),
            loc.file,
            loc.span.clone(),
            format!("`{}` is not {is_not}", c.subject),
        );
        d.notes
            .push(match did_you_mean(&c.subject, names.iter().copied()) {
                Some(s) => format!("did you mean `{s}`?"),
                None => format!("known names: {}", names.join(", ")),
            });
        return;
    };
    if !values.contains(&c.value) {
        let d = diags.error(
            "unknown-value",
            format!("`{}` is not a value of `{}` in {what}", c.value, c.subject),
            loc.file,
            loc.span.clone(),
            format!("`{}` has no value `{}`", c.subject, c.value),
        );
        d.notes.push(
            match did_you_mean(&c.value, values.iter().map(String::as_str)) {
                Some(s) => format!(
                    "did you mean `{s}`? values of `{}`: {}",
                    c.subject,
                    values.join(", ")
                ),
                None => format!("values of `{}`: {}", c.subject, values.join(", ")),
            },
        );
    }
}

fn check_presets(m: &Material, sites: &Sites, diags: &mut Diagnostics) {
    for preset in &m.presets {
        for (key, value) in &preset.values {
            let file = preset.decl.file;
            let (key_span, value_span) = sites
                .preset_values
                .get(&(preset.name.clone(), key.clone()))
                .cloned()
                .unwrap_or((preset.decl.span.clone(), preset.decl.span.clone()));
            match (m.param(key), m.keyword(key), value) {
                (Some(p), _, PresetValue::Param(v)) => {
                    let nums: Vec<f64> = match v {
                        ParamValue::Float(x) => vec![*x],
                        ParamValue::Vector(xs) => xs.clone(),
                        _ => vec![],
                    };
                    let ok_type = match (p.kind, v) {
                        (ParamKind::Float, ParamValue::Float(_)) => true,
                        (ParamKind::Int, ParamValue::Float(x)) => x.fract() == 0.0,
                        (ParamKind::Bool, ParamValue::Bool(_)) => true,
                        (
                            ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 | ParamKind::Color,
                            ParamValue::Vector(xs),
                        ) => {
                            xs.len() == p.kind.components().unwrap_or(0)
                                || (p.kind == ParamKind::Color && xs.len() == 3)
                        }
                        (ParamKind::Texture2d | ParamKind::Cube, ParamValue::Texture(_)) => true,
                        (ParamKind::Curve, ParamValue::Curve(_)) => true,
                        (ParamKind::Gradient, ParamValue::Gradient(_)) => true,
                        _ => false,
                    };
                    if !ok_type {
                        let d = diags.error(
                            "wrong-type",
                            format!(
                                "preset `{}` gives `{key}` a value of the wrong type",
                                preset.name
                            ),
                            file,
                            value_span,
                            format!("not a {} value", p.kind.name()),
                        );
                        d.labels.push(
                            Label::secondary(p.decl.file, p.decl.span.clone())
                                .with_message(format!("`{key}` is a {}", p.kind.name())),
                        );
                        d.notes.push(crate::values::how_to_write(p.kind).into());
                    } else if let Some(r) = p.range
                        && nums.iter().any(|x| *x < r[0] || *x > r[1])
                    {
                        let d = diags.error(
                            "out-of-range",
                            format!(
                                "preset `{}` sets `{key}` outside its range [{}, {}]",
                                preset.name, r[0], r[1]
                            ),
                            file,
                            value_span,
                            format!("not in [{}, {}]", r[0], r[1]),
                        );
                        d.labels.push(
                            Label::secondary(p.decl.file, p.decl.span.clone())
                                .with_message(format!("`{key}` declared here")),
                        );
                    }
                }
                (_, Some(k), PresetValue::Keyword(v)) => {
                    if !k.values.contains(v) {
                        let d = diags.error(
                            "unknown-value",
                            format!(
                                "preset `{}`: `{v}` is not a value of keyword `{key}`",
                                preset.name
                            ),
                            file,
                            value_span,
                            "unknown value",
                        );
                        d.notes
                            .push(match did_you_mean(v, k.values.iter().map(String::as_str)) {
                                Some(s) => format!(
                                    "did you mean `{s}`? values of `{key}`: {}",
                                    k.values.join(", ")
                                ),
                                None => format!("values of `{key}`: {}", k.values.join(", ")),
                            });
                    }
                }
                (None, None, PresetValue::Keyword(v)) if key == "tier" => {
                    if !m.tiers.values.contains(v) {
                        let d = diags.error(
                            "unknown-value",
                            format!("preset `{}`: unknown tier `{v}`", preset.name),
                            file,
                            value_span,
                            "unknown tier",
                        );
                        d.notes
                            .push(format!("tiers: {}", m.tiers.values.join(", ")));
                    }
                }
                (None, Some(k), PresetValue::Param(_)) => {
                    let d = diags.error(
                        "wrong-type",
                        format!(
                            "preset `{}` gives keyword `{key}` a value of the wrong type",
                            preset.name
                        ),
                        file,
                        value_span,
                        "expected a value name",
                    );
                    d.notes.push(format!(
                        "write one of: {}",
                        k.values
                            .iter()
                            .map(|v| format!("\"{v}\""))
                            .collect::<Vec<_>>()
                            .join(", ")
                    ));
                }
                _ => {
                    let names = m
                        .params
                        .iter()
                        .map(|p| p.name.as_str())
                        .chain(m.keywords.iter().map(|k| k.name.as_str()));
                    let d = diags.error(
                        "unknown-key",
                        format!("preset `{}` sets unknown `{key}`", preset.name),
                        file,
                        key_span,
                        "not a parameter, keyword or `tier`",
                    );
                    if let Some(s) = did_you_mean(key, names) {
                        d.notes.push(format!("did you mean `{s}`?"));
                    }
                }
            }
        }
    }
}

fn check_pass_names(m: &Material, diags: &mut Diagnostics) {
    for (i, pass) in m.passes.iter().enumerate() {
        if let Some(first) = m.passes[..i].iter().find(|p| p.name == pass.name) {
            let d = diags.error(
                "duplicate",
                format!("pass `{}` is declared twice", pass.name),
                pass.decl.file,
                pass.decl.span.clone(),
                "second pass with this name",
            );
            d.labels.push(
                Label::secondary(first.decl.file, first.decl.span.clone())
                    .with_message("first pass with this name"),
            );
            d.notes.push("give each [[pass]] a distinct `name`".into());
        }
    }
}

fn check_instances(m: &Material, sites: &Sites, diags: &mut Diagnostics) {
    for (i, pass) in m.passes.iter().enumerate() {
        let Instances::Param(name) = &pass.instances else {
            continue;
        };
        let span = sites
            .instances
            .get(i)
            .cloned()
            .flatten()
            .unwrap_or(pass.decl.span.clone());
        match m.param(name) {
            Some(p) if p.kind == ParamKind::Int => {
                let lowest = match (&p.default, p.range) {
                    (ParamValue::Int(d), Some(r)) => r[0].min(*d as f64),
                    (ParamValue::Int(d), None) => *d as f64,
                    _ => 0.0,
                };
                if lowest < 0.0 {
                    let d = diags.error(
                        "type-range",
                        format!(
                            "pass `{}` draws `{name}` instances, which can be {} and does not fit in a u32",
                            pass.name,
                            crate::gpu_numbers::show(lowest)
                        ),
                        p.decl.file,
                        p.decl.span.clone(),
                        format!("`{name}` can be negative"),
                    );
                    d.labels.push(
                        Label::secondary(pass.decl.file, span)
                            .with_message("used as the instance count here"),
                    );
                    d.notes.push(format!(
                        "an instance count is a u32 ({}); give `{name}` a default and a `range` of 0 or more",
                        crate::gpu_numbers::GpuType::U32.range_text()
                    ));
                }
            }
            Some(p) => {
                let d = diags.error(
                    "unknown-param",
                    format!("pass `{}` takes its instance count from `{name}`, which is not an int parameter", pass.name),
                    pass.decl.file,
                    span,
                    "instance count named here",
                );
                d.labels.push(
                    Label::secondary(p.decl.file, p.decl.span.clone())
                        .with_message(format!("`{name}` is a {} parameter", p.kind.name())),
                );
                d.notes.push(format!(
                    "make `{name}` `type = \"int\"`, or give `instances` a fixed count"
                ));
            }
            None => {
                let ints: Vec<&str> = m
                    .params
                    .iter()
                    .filter(|p| p.kind == ParamKind::Int)
                    .map(|p| p.name.as_str())
                    .collect();
                let d = diags.error(
                    "unknown-param",
                    format!("pass `{}` takes its instance count from `{name}`, which is not a parameter", pass.name),
                    pass.decl.file,
                    span,
                    "no such parameter",
                );
                d.notes
                    .push(match did_you_mean(name, ints.iter().copied()) {
                    Some(s) => format!("did you mean `{s}`?"),
                    None => {
                        "declare an int parameter (e.g. a shell count) and name it in `instances`"
                            .into()
                    }
                });
            }
        }
    }
}

fn check_budget(m: &Material, diags: &mut Diagnostics) {
    if m.tiers.values.is_empty() {
        return;
    }
    // Counted first, so a space too large to enumerate fails at once.
    if !crate::variant_space::check_space(m, diags) {
        return;
    }
    let all = variants::all_variants(m).len();
    let kept = variants::variants(m).len();
    if kept == 0 {
        crate::variant_space::report_all_excluded(m, diags);
        return;
    }
    if kept > m.max_variants {
        let span = m.max_variants_span.clone().unwrap_or(m.decl.span.clone());
        let d = diags.error(
            "variant-budget",
            format!("{kept} variants exceed the budget of {}", m.max_variants),
            m.file,
            span,
            format!("budget {}", m.max_variants),
        );
        let mut parts = vec![format!("tier: {} values", m.tiers.values.len())];
        for k in m.static_keywords() {
            parts.push(format!("{}: {} values", k.name, k.values.len()));
        }
        d.notes.push(format!(
            "{} = {all} combinations, {} excluded by [variants].exclude",
            parts.join(" x "),
            all - kept
        ));
        d.notes.push(
            "raise `max_variants`, exclude combinations, or make a keyword `mode = \"constant\"`"
                .into(),
        );
    }
}
