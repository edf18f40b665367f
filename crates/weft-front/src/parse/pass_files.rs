//! Shared passes: `[[pass]] include = "lib/outline.pass.toml"` takes a pass
//! from a file any material can include, with the groups, parameters and
//! keywords it needs and the WGSL `source` that defines its entry points, so
//! a pass such as an outline is written once (docs/material-format.md,
//! "Shared passes").
//!
//! The files are read by `lib.rs` before parsing (root confinement as for
//! WGSL includes); this module parses them into the material: declarations
//! first, so the material's presets may set them, the pass later in its
//! place among the material's `[[pass]]` tables.

use super::{PASS_FILE_PASS_KEYS, PASS_FILE_TOP_KEYS, parse_declarations, passes, value_of};
use crate::check::Sites;
use crate::diag::{FileId, Span};
use crate::model::*;
use crate::toml_reader::{Cx, Table, expect_array, expect_string};
use std::collections::HashMap;
use toml::de::{DeTable, DeValue};

/// The pass (and the span of its `instances`) of every `[[pass]]` item that
/// includes a shared pass file read without errors, by item index.
pub(super) type IncludedPasses = HashMap<usize, (Pass, Option<Span>)>;

/// Parses the shared pass files that `top`'s `[[pass]]` items include into
/// `material` (declarations, `pass_files`, `pass_sources`).
pub(super) fn parse_included(
    top: &Table,
    files: &[(String, FileId, String)],
    material: &mut Material,
    sites: &mut Sites,
    cx: &mut Cx,
) -> IncludedPasses {
    let mut out = IncludedPasses::new();
    let Some(items) = top.get("pass").and_then(|v| match v.get_ref() {
        DeValue::Array(_) => expect_array(v, "`pass`", cx),
        _ => None,
    }) else {
        return out;
    };
    for (i, item) in items.iter().enumerate() {
        let Some(include) = value_of(item, "include") else {
            continue;
        };
        if let DeValue::Table(t) = item.get_ref() {
            for (key, _) in t.iter().filter(|(k, _)| k.get_ref() != "include") {
                cx.error_with_note(
                    "pass-include",
                    format!(
                        "a [[pass]] that includes a shared pass cannot also set `{}`",
                        key.get_ref()
                    ),
                    key.span(),
                    "set in the shared pass file",
                    "a shared pass is taken whole; copy it into the material as a [[pass]] to change it",
                );
            }
        }
        let Some(written) = expect_string(include, "`include`", cx) else {
            continue;
        };
        // Not in `files`: the loader reported why (missing, outside the root).
        let Some((_, file, text)) = files.iter().find(|(w, _, _)| *w == written) else {
            continue;
        };
        let mut fcx = Cx {
            file: *file,
            diags: cx.diags,
        };
        if let Some((pass, instances)) = parse_file(text, material, sites, &mut fcx) {
            out.insert(i, (pass, instances));
        }
        material.pass_files.push(SourceFile {
            file: *file,
            rel_path: written.clone(),
        });
    }
    out
}

/// One shared pass file (`cx.file`): its declarations into `material`, its
/// `source` into `material.pass_sources`, and its pass.
fn parse_file(
    text: &str,
    material: &mut Material,
    sites: &mut Sites,
    cx: &mut Cx,
) -> Option<(Pass, Option<Span>)> {
    let doc = match DeTable::parse(text) {
        Ok(doc) => doc,
        Err(e) => {
            cx.error_with_note(
                "toml-syntax",
                format!("invalid TOML: {}", e.message().trim()),
                e.span().unwrap_or(0..0),
                "here",
                "see docs/material-format.md, \"Shared passes\", for the file format",
            );
            return None;
        }
    };
    let top = Table {
        map: doc.get_ref(),
        span: 0..0,
        what: "the shared pass file".into(),
    };
    top.check_keys(PASS_FILE_TOP_KEYS, cx);
    parse_declarations(&top, material, sites, cx);
    let Some(pass_v) = top.get("pass") else {
        cx.error_with_note(
            "missing-key",
            "a shared pass file needs a [pass] table",
            0..0,
            "the file starts here",
            "add [pass] with `name`, `vertex`, `fragment` and the WGSL `source` that defines them",
        );
        return None;
    };
    let pass = passes::parse_pass(pass_v, PASS_FILE_PASS_KEYS, "the shared [pass]", cx)?;
    match value_of(pass_v, "source") {
        Some(source) => {
            if let Some(rel) = expect_string(source, "`source`", cx) {
                material.pass_sources.push((
                    rel,
                    Loc {
                        file: cx.file,
                        span: source.span(),
                    },
                ));
            }
        }
        None => cx.error_with_note(
            "missing-key",
            "the shared pass has no `source`",
            pass_v.span(),
            "in this [pass]",
            "add `source = \"lib/<name>.wgsl\"` (relative to the materials root): the WGSL with the pass's entry points",
        ),
    }
    let instances = value_of(pass_v, "instances").map(|v| v.span());
    Some((pass, instances))
}
