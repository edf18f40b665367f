//! Cross-reference checks over a parsed material: names that must exist,
//! names that must not collide, preset values, instance sources and the
//! variant budget.

use crate::diag::{Diagnostics, did_you_mean};
use crate::model::*;
use crate::variants;
use codespan_reporting::diagnostic::Label;
use weft_meta::{Condition, KeywordKind, ParamKind};

pub fn check(m: &mut Material, diags: &mut Diagnostics) {
    check_names(m, diags);
    check_groups(m, diags);
    for p in &m.params {
        if let Some(c) = &p.show_if {
            check_condition(m, c, &p.decl, "show_if", diags);
        }
    }
    for k in &m.keywords {
        if let Some(c) = &k.show_if {
            check_condition(m, c, &k.decl, "show_if", diags);
        }
    }
    let decl = Loc { file: m.file, span: m.max_variants_span.clone().unwrap_or(m.decl.span.clone()) };
    for e in &m.exclude {
        for c in e {
            check_condition(m, c, &decl, "exclude", diags);
        }
    }
    check_presets(m, diags);
    check_passes(m, diags);
    check_budget(m, diags);
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
    for k in &m.keywords {
        names.push((k.name.clone(), &k.decl));
        if k.kind == KeywordKind::Enum {
            names.extend(k.values.iter().map(|v| (format!("{}_{}", k.name, v.to_uppercase()), &k.decl)));
        }
    }
    for (i, (name, loc)) in names.iter().enumerate() {
        if let Some((_, first)) = names[..i].iter().find(|(n, _)| n == name) {
            let d = diags.error("duplicate", format!("`{name}` is declared twice"), loc.file, loc.span.clone(), "second declaration");
            d.labels.push(Label::secondary(first.file, first.span.clone()).with_message("first declared here"));
            d.notes.push("parameter names, generated members (`<texture>_st`) and keyword constants share one WGSL namespace".into());
        }
    }
}

fn check_groups(m: &mut Material, diags: &mut Diagnostics) {
    let declared = !m.groups.is_empty();
    let mut used: Vec<(String, Loc)> = m.params.iter().map(|p| (p.group.clone(), p.decl.clone())).collect();
    used.extend(m.keywords.iter().map(|k| (k.group.clone(), k.decl.clone())));
    for (g, loc) in used {
        if m.groups.iter().any(|x| x.name == g) {
            continue;
        }
        if declared && g != "main" {
            let hint = did_you_mean(&g, m.groups.iter().map(|x| x.name.as_str()))
                .map_or_else(|| "declare it under [groups]".to_string(), |s| format!("did you mean `{s}`?"));
            let d = diags.error("unknown-group", format!("unknown group `{g}`"), loc.file, loc.span, "uses an undeclared group");
            d.notes.push(hint);
        } else {
            m.groups.push(Group { label: crate::parse::humanize(&g), name: g, label_zh: None });
        }
    }
}

fn check_condition(m: &Material, c: &Condition, loc: &Loc, what: &str, diags: &mut Diagnostics) {
    let values: Option<Vec<String>> = if c.subject == "tier" {
        Some(m.tiers.values.clone())
    } else if let Some(k) = m.keyword(&c.subject) {
        Some(k.values.clone())
    } else if m.param(&c.subject).is_some_and(|p| p.kind == ParamKind::Bool) {
        if what == "exclude" {
            let d = diags.error("bad-condition", format!("`exclude` can only name keywords and `tier`, not parameter `{}`", c.subject), loc.file, loc.span.clone(), "in this filter");
            d.notes.push("parameters do not create variants".into());
            return;
        }
        Some(vec!["off".into(), "on".into()])
    } else {
        None
    };
    let Some(values) = values else {
        let mut names: Vec<&str> = m.keywords.iter().map(|k| k.name.as_str()).collect();
        names.push("tier");
        names.extend(m.params.iter().filter(|p| p.kind == ParamKind::Bool).map(|p| p.name.as_str()));
        let d = diags.error("unknown-keyword", format!("unknown keyword `{}` in {what}", c.subject), loc.file, loc.span.clone(), format!("{what} names `{}`", c.subject));
        d.notes.push(match did_you_mean(&c.subject, names.iter().copied()) {
            Some(s) => format!("did you mean `{s}`?"),
            None => format!("known names: {}", names.join(", ")),
        });
        return;
    };
    if !values.contains(&c.value) {
        let d = diags.error("unknown-value", format!("`{}` is not a value of `{}` in {what}", c.value, c.subject), loc.file, loc.span.clone(), "here");
        d.notes.push(format!("values: {}", values.join(", ")));
    }
}

fn check_presets(m: &Material, diags: &mut Diagnostics) {
    for preset in &m.presets {
        for (key, value) in &preset.values {
            let loc = &preset.decl;
            match (m.param(key), m.keyword(key), value) {
                (Some(p), _, PresetValue::Param(v)) => {
                    let nums: Vec<f64> = match v {
                        ParamValue::Float(x) => vec![*x],
                        ParamValue::Vector(xs) => xs.clone(),
                        _ => vec![],
                    };
                    let ok_type = match (p.kind, v) {
                        (ParamKind::Float | ParamKind::Int, ParamValue::Float(_)) => true,
                        (ParamKind::Bool, ParamValue::Bool(_)) => true,
                        (ParamKind::Vec2 | ParamKind::Vec3 | ParamKind::Vec4 | ParamKind::Color, ParamValue::Vector(xs)) => {
                            xs.len() == p.kind.components().unwrap_or(0) || (p.kind == ParamKind::Color && xs.len() == 3)
                        }
                        (ParamKind::Texture2d | ParamKind::Cube, ParamValue::Texture(_)) => true,
                        _ => false,
                    };
                    if !ok_type {
                        diags.error("wrong-type", format!("preset `{}` gives `{key}` a value of the wrong type", preset.name), loc.file, loc.span.clone(), format!("`{key}` is a {}", p.kind.name()));
                    } else if let Some(r) = p.range {
                        if nums.iter().any(|x| *x < r[0] || *x > r[1]) {
                            diags.error("out-of-range", format!("preset `{}` sets `{key}` outside its range [{}, {}]", preset.name, r[0], r[1]), loc.file, loc.span.clone(), "in this preset");
                        }
                    }
                }
                (_, Some(k), PresetValue::Keyword(v)) => {
                    if !k.values.contains(v) {
                        diags.error("unknown-value", format!("preset `{}`: `{v}` is not a value of keyword `{key}`", preset.name), loc.file, loc.span.clone(), "in this preset");
                    }
                }
                (None, None, PresetValue::Keyword(v)) if key == "tier" => {
                    if !m.tiers.values.contains(v) {
                        diags.error("unknown-value", format!("preset `{}`: unknown tier `{v}`", preset.name), loc.file, loc.span.clone(), "in this preset");
                    }
                }
                _ => {
                    let names = m.params.iter().map(|p| p.name.as_str()).chain(m.keywords.iter().map(|k| k.name.as_str()));
                    let d = diags.error("unknown-key", format!("preset `{}` sets unknown `{key}`", preset.name), loc.file, loc.span.clone(), "in this preset");
                    if let Some(s) = did_you_mean(key, names) {
                        d.notes.push(format!("did you mean `{s}`?"));
                    }
                }
            }
        }
    }
}

fn check_passes(m: &Material, diags: &mut Diagnostics) {
    for (i, pass) in m.passes.iter().enumerate() {
        if m.passes[..i].iter().any(|p| p.name == pass.name) {
            diags.error("duplicate", format!("pass `{}` is declared twice", pass.name), pass.decl.file, pass.decl.span.clone(), "second pass with this name");
        }
        if let Instances::Param(name) = &pass.instances {
            match m.param(name) {
                Some(p) if p.kind == ParamKind::Int => {}
                _ => {
                    let d = diags.error("unknown-param", format!("pass `{}` takes its instance count from `{name}`, which is not an int parameter", pass.name), pass.decl.file, pass.decl.span.clone(), "in this pass");
                    d.notes.push("declare an int parameter (e.g. a shell count) and name it in `instances`".into());
                }
            }
        }
    }
}

fn check_budget(m: &Material, diags: &mut Diagnostics) {
    if m.tiers.values.is_empty() {
        return;
    }
    let all = variants::all_variants(m).len();
    let kept = variants::variants(m).len();
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
        d.notes.push(format!("{} = {all} combinations, {} excluded by [variants].exclude", parts.join(" x "), all - kept));
        d.notes.push("raise `max_variants`, exclude combinations, or make a keyword `mode = \"constant\"`".into());
    }
}
