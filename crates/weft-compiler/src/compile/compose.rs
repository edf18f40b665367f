//! Composition: the engine interface, the generated prelude, the included
//! library files and the material's source, concatenated into one WGSL module
//! with a source map from composed byte offsets back to the user's files.
//!
//! WGSL needs no declaration order at module scope, so plain concatenation is
//! enough; no identifier is mangled and the output stays readable.

use crate::compile::prelude::Prelude;
use codespan_reporting::diagnostic::{Diagnostic, Label};
use weft_front::model::{Loc, Material};
use weft_front::{Diagnostics, FileId, SourceDb};

use super::engine_binding::ENGINE_INTERFACE;
use super::source_map::{Composed, SourceMap, Target};

/// Registers the engine interface in the source database (once) so its lines can be shown.
pub fn engine_interface_file(db: &mut SourceDb) -> FileId {
    let path = std::path::Path::new("<weft>/engine_interface.wgsl");
    db.find(path).unwrap_or_else(|| {
        db.add(
            path,
            "<weft engine interface>".into(),
            ENGINE_INTERFACE.into(),
        )
    })
}

/// How `weft_half`, the type of half-precision code, is spelled in a composed
/// module (`half.rs`): `f16` in the module every language but HLSL and GLSL
/// is written from, `f32` in the fallback module they are written from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HalfAs {
    F16,
    F32,
}

/// The material composed with `weft_half = f16` (the module of record).
pub fn compose(m: &Material, prelude: &Prelude, db: &mut SourceDb) -> Composed {
    compose_with(m, prelude, db, HalfAs::F16)
}

pub fn compose_with(m: &Material, prelude: &Prelude, db: &mut SourceDb, half: HalfAs) -> Composed {
    let mut text = String::new();
    let mut map = SourceMap::default();
    // `enable` must precede every declaration; a variant that keeps no f16
    // value is written without it (naga writes it only when a type needs it).
    let preamble = match half {
        HalfAs::F16 => "enable f16;\nalias weft_half = f16;\n",
        HalfAs::F32 => "alias weft_half = f32;\n",
    };
    text.push_str(preamble);
    map.segments
        .push((0..preamble.len(), Target::Decl(m.decl.clone())));
    let mut push_file = |text: &mut String, file: FileId, src: &str| {
        let start = text.len();
        text.push_str(src);
        if !src.ends_with('\n') {
            text.push('\n');
        }
        map.segments
            .push((start..start + src.len(), Target::File { file, offset: 0 }));
    };
    let engine = engine_interface_file(db);
    push_file(&mut text, engine, ENGINE_INTERFACE);
    let mut prelude_segments = Vec::new();
    for (line, target) in &prelude.lines {
        let start = text.len();
        text.push_str(line);
        text.push('\n');
        prelude_segments.push((start..text.len(), target.clone()));
    }
    for src in &m.sources {
        let start = text.len();
        text.push_str(&format!("// ---- {} ----\n", src.rel_path));
        prelude_segments.push((start..text.len(), Target::Decl(m.decl.clone())));
        let body = db.text(src.file).to_string();
        push_file(&mut text, src.file, &body);
    }
    map.segments.extend(prelude_segments);
    map.segments.sort_by_key(|(r, _)| r.start);
    Composed { text, map }
}

/// Converts naga labels (composed spans) into a diagnostic in the user's files.
pub fn naga_diagnostic(
    code: &str,
    message: String,
    labels: impl IntoIterator<Item = (naga::Span, String)>,
    notes: Vec<String>,
    map: &SourceMap,
    fallback: &Loc,
) -> Diagnostic<FileId> {
    let mut out: Vec<Label<FileId>> = Vec::new();
    for (i, (span, msg)) in labels.into_iter().enumerate() {
        let Some(range) = span.to_range() else {
            continue;
        };
        if let Some((file, r)) = map.map(range) {
            let label = if i == 0 {
                Label::primary(file, r)
            } else {
                Label::secondary(file, r)
            };
            out.push(label.with_message(msg));
        }
    }
    if out.is_empty() {
        out.push(
            Label::primary(fallback.file, fallback.span.clone()).with_message("in this material"),
        );
    }
    Diagnostic::error()
        .with_code(code)
        .with_message(message)
        .with_labels(out)
        .with_notes(notes)
}

/// Parses and validates the composed module once, reporting naga's errors in the user's files.
pub fn parse_and_validate(
    composed: &Composed,
    m: &Material,
    diags: &mut Diagnostics,
) -> Option<(naga::Module, naga::valid::ModuleInfo)> {
    let module = match naga::front::wgsl::parse_str(&composed.text) {
        Ok(module) => module,
        Err(e) => {
            let labels: Vec<(naga::Span, String)> =
                e.labels().map(|(s, m)| (s, m.to_string())).collect();
            let notes: Vec<String> = e.notes().map(|n| n.to_string()).collect();
            let d = match labels.is_empty() {
                // naga's recursion limit says nothing about where: find the deepest nesting.
                true => parse_limit_diagnostic(composed, e.message(), &notes),
                false => None,
            };
            diags.push(d.unwrap_or_else(|| {
                naga_diagnostic(
                    "wgsl-parse",
                    e.message().to_string(),
                    labels,
                    notes,
                    &composed.map,
                    &m.decl,
                )
            }));
            return None;
        }
    };
    if let Some((depth, span)) = crate::compile::nesting::too_deep(&module) {
        let limit = crate::compile::nesting::MAX_EXPRESSION_DEPTH;
        diags.push(naga_diagnostic(
            "wgsl-nesting",
            format!("an expression is nested {depth} levels deep, more than weft's limit of {limit}"),
            [(span, format!("{depth} levels of operations"))],
            vec![
                "naga's shader writers recurse once per level of an expression, so weft bounds the depth (long chains such as `a + b + c + …` count one level per operator)".into(),
                "split the expression with `let` bindings: each named value starts again at one level".into(),
            ],
            &composed.map,
            &m.decl,
        ));
        return None;
    }
    let info = match validator().validate(&module) {
        Ok(info) => info,
        Err(e) => {
            diags.push(validation_diagnostic(&e, composed, m));
            return None;
        }
    };
    if !crate::compile::stage_io::check_passes(m, &module, composed, diags) {
        return None;
    }
    Some((module, info))
}

/// naga's WGSL parser gives up at its recursion limit without a location;
/// the most deeply nested bracket of the user's WGSL is shown instead.
fn parse_limit_diagnostic(
    composed: &Composed,
    message: &str,
    notes: &[String],
) -> Option<Diagnostic<FileId>> {
    if !notes.iter().any(|n| n.contains("recursion limit")) && !message.contains("recursion limit")
    {
        return None;
    }
    let (file, range, depth) = crate::compile::nesting::deepest_bracket(composed)?;
    let limit = crate::compile::nesting::NAGA_PARSER_RECURSION_LIMIT;
    Some(
        Diagnostic::error()
            .with_code("wgsl-parse")
            .with_message(format!(
                "the WGSL nests too deeply for naga's parser (its recursion limit is {limit})"
            ))
            .with_labels(vec![
                Label::primary(file, range).with_message(format!("{depth} brackets deep here")),
            ])
            .with_notes(vec![
                "each nested parenthesis, call, block or statement counts towards naga's limit"
                    .into(),
                "flatten the expression with `let` bindings, or move nested code into functions"
                    .into(),
            ]),
    )
}

pub fn validator() -> naga::valid::Validator {
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
}

pub fn validation_diagnostic(
    e: &naga::WithSpan<naga::valid::ValidationError>,
    composed: &Composed,
    m: &Material,
) -> Diagnostic<FileId> {
    let labels: Vec<(naga::Span, String)> = e.spans().map(|(s, l)| (*s, l.clone())).collect();
    // naga nests errors (function -> expression -> cause); the innermost one
    // says what is wrong, the outer ones say where.
    let mut chain = vec![e.as_inner().to_string()];
    let mut source: Option<&dyn std::error::Error> = std::error::Error::source(e.as_inner());
    while let Some(s) = source {
        chain.push(s.to_string());
        source = s.source();
    }
    let message = chain.last().cloned().unwrap_or_default();
    let notes = chain[..chain.len() - 1]
        .iter()
        .map(|c| format!("in: {c}"))
        .collect();
    naga_diagnostic(
        "wgsl-validation",
        message,
        labels,
        notes,
        &composed.map,
        &m.decl,
    )
}
