//! The vertex → fragment interface of each pass, checked on the composed
//! module: every `@location` the fragment entry point reads is written by
//! the vertex entry point with the same type and interpolation, and neither
//! side uses more inter-stage variables than WebGPU's
//! `maxInterStageShaderVariables` (or the material's `[limits]`). Errors
//! point at the pass in the TOML and at the structs in the WGSL.

use crate::compile::source_map::Composed;
use codespan_reporting::diagnostic::{Diagnostic, Label};
use naga::{Binding, BuiltIn, Interpolation, Module, Sampling, ShaderStage, TypeInner};
use weft_front::Diagnostics;
use weft_front::model::{Material, Pass};

/// One user-defined inter-stage variable of an entry point.
struct Io {
    location: u32,
    ty: naga::Handle<naga::Type>,
    interpolation: Interpolation,
    sampling: Sampling,
    /// The member or argument name, for messages.
    name: String,
    /// Where it is declared in the composed WGSL: the struct it is a
    /// member of, the entry point's argument, or (a bare vertex result) the
    /// entry point's `return`; labelled in the user's file.
    span: naga::Span,
}

/// An entry point's inter-stage variables: the vertex stage's outputs, the
/// fragment stage's inputs; and how many builtins count against the limit.
fn interface(module: &Module, ep: &naga::EntryPoint) -> (Vec<Io>, u32) {
    let mut out = Vec::new();
    let mut builtins = 0;
    let mut push = |binding: &Option<Binding>,
                    ty: naga::Handle<naga::Type>,
                    name: Option<&String>,
                    span: naga::Span| {
        match binding {
            Some(Binding::Location {
                location,
                interpolation,
                sampling,
                ..
            }) => {
                // WGSL's defaults: floats perspective/center, the rest flat/first.
                let interpolation = interpolation.unwrap_or(Interpolation::Flat);
                let sampling = sampling.unwrap_or(match interpolation {
                    Interpolation::Flat => Sampling::First,
                    _ => Sampling::Center,
                });
                out.push(Io {
                    location: *location,
                    ty,
                    interpolation,
                    sampling,
                    name: name.cloned().unwrap_or_default(),
                    span,
                });
            }
            // WebGPU counts these fragment inputs against the limit too.
            Some(Binding::BuiltIn(
                BuiltIn::FrontFacing | BuiltIn::SampleIndex | BuiltIn::SampleMask,
            )) if ep.stage == ShaderStage::Fragment => builtins += 1,
            _ => {}
        }
    };
    let mut visit = |binding: &Option<Binding>,
                     ty: naga::Handle<naga::Type>,
                     name: Option<&String>,
                     span: naga::Span| {
        match &module.types[ty].inner {
            TypeInner::Struct { members, .. } if binding.is_none() => {
                let declared = module.types.get_span(ty);
                for m in members {
                    push(&m.binding, m.ty, m.name.as_ref(), declared);
                }
            }
            _ => push(binding, ty, name, span),
        }
    };
    let f = &ep.function;
    match ep.stage {
        ShaderStage::Vertex => {
            if let Some(r) = &f.result {
                // A bare result has no declaration of its own: its `return`.
                let returned = f
                    .body
                    .span_iter()
                    .find(|(s, _)| matches!(s, naga::Statement::Return { .. }))
                    .map_or_else(naga::Span::default, |(_, span)| *span);
                visit(&r.binding, r.ty, None, returned);
            }
        }
        _ => {
            for (i, a) in f.arguments.iter().enumerate() {
                // The argument's declaration: its `FunctionArgument` expression.
                let declared = f
                    .expressions
                    .iter()
                    .find(|(_, e)| matches!(e, naga::Expression::FunctionArgument(n) if *n as usize == i))
                    .map_or_else(naga::Span::default, |(h, _)| f.expressions.get_span(h));
                visit(&a.binding, a.ty, a.name.as_ref(), declared);
            }
        }
    }
    out.sort_by_key(|io| io.location);
    (out, builtins)
}

fn type_text(module: &Module, ty: naga::Handle<naga::Type>) -> String {
    crate::compile::reflect::type_name(module, ty)
}

fn interpolation_text(io: &Io) -> String {
    let i = match io.interpolation {
        Interpolation::Perspective => "perspective",
        Interpolation::Linear => "linear",
        Interpolation::Flat => "flat",
        Interpolation::PerVertex => "per_vertex",
    };
    let s = match io.sampling {
        Sampling::Center => "center",
        Sampling::Centroid => "centroid",
        Sampling::Sample => "sample",
        Sampling::First => "first",
        Sampling::Either => "either",
    };
    format!("@interpolate({i}, {s})")
}

/// Where an inter-stage variable is declared in the user's WGSL (its struct,
/// argument or `return`), as a secondary label.
fn declaration_label(
    composed: &Composed,
    io: &Io,
    message: String,
) -> Option<Label<weft_front::FileId>> {
    let (file, range) = composed.map.map(io.span.to_range()?)?;
    Some(Label::secondary(file, range).with_message(message))
}

/// Checks every pass whose entry points both exist (missing ones are
/// reported by the interface check). True when all match and fit.
pub fn check_passes(
    m: &Material,
    module: &Module,
    composed: &Composed,
    diags: &mut Diagnostics,
) -> bool {
    let before = diags.error_count();
    let limit = m.limits.get("max_inter_stage_shader_variables");
    let find = |name: &str, stage| {
        module
            .entry_points
            .iter()
            .find(|ep| ep.name == name && ep.stage == stage)
    };
    for pass in &m.passes {
        let (Some(vs), Some(fs)) = (
            find(&pass.vertex, ShaderStage::Vertex),
            find(&pass.fragment, ShaderStage::Fragment),
        ) else {
            continue;
        };
        let (outputs, _) = interface(module, vs);
        let (inputs, builtins) = interface(module, fs);
        let vertex_ok = check_count(m, pass, composed, &outputs, 0, "vertex", limit, diags);
        // Inputs the vertex stage writes, and no counted builtin: reported above if over.
        let covered = builtins == 0
            && inputs
                .iter()
                .all(|i| outputs.iter().any(|o| o.location == i.location));
        if vertex_ok || !covered {
            check_count(
                m, pass, composed, &inputs, builtins, "fragment", limit, diags,
            );
        }
        for input in &inputs {
            let output = outputs.iter().find(|o| o.location == input.location);
            let problem = match output {
                None => Some((
                    format!(
                        "pass `{}`: fragment `{}` reads @location({}), which vertex `{}` does not write",
                        pass.name, pass.fragment, input.location, pass.vertex
                    ),
                    format!(
                        "vertex `{}` writes {}",
                        pass.vertex,
                        if outputs.is_empty() {
                            "no @location".to_string()
                        } else {
                            outputs
                                .iter()
                                .map(|o| format!("@location({})", o.location))
                                .collect::<Vec<_>>()
                                .join(", ")
                        }
                    ),
                )),
                Some(o) if module.types[o.ty].inner != module.types[input.ty].inner => Some((
                    format!(
                        "pass `{}`: @location({}) is {} out of vertex `{}` but {} into fragment `{}`",
                        pass.name,
                        input.location,
                        type_text(module, o.ty),
                        pass.vertex,
                        type_text(module, input.ty),
                        pass.fragment
                    ),
                    "the two stages must agree on each location's type".to_string(),
                )),
                Some(o)
                    if (o.interpolation, o.sampling) != (input.interpolation, input.sampling) =>
                {
                    Some((
                        format!(
                            "pass `{}`: @location({}) is {} out of vertex `{}` but {} into fragment `{}`",
                            pass.name,
                            input.location,
                            interpolation_text(o),
                            pass.vertex,
                            interpolation_text(input),
                            pass.fragment
                        ),
                        "the two stages must agree on each location's interpolation and sampling"
                            .to_string(),
                    ))
                }
                Some(_) => None,
            };
            let Some((message, note)) = problem else {
                continue;
            };
            let mut labels = vec![
                Label::primary(pass.decl.file, pass.fragment_span.clone()).with_message(format!(
                    "fragment `{}` reads @location({})",
                    pass.fragment, input.location
                )),
            ];
            if pass.vertex_span != pass.fragment_span {
                labels.push(
                    Label::secondary(pass.decl.file, pass.vertex_span.clone())
                        .with_message(format!("vertex `{}`", pass.vertex)),
                );
            }
            labels.extend(declaration_label(
                composed,
                input,
                format!("`{}` is @location({})", input.name, input.location),
            ));
            if let Some(o) = output {
                labels.extend(declaration_label(
                    composed,
                    o,
                    format!("`{}` is @location({})", o.name, o.location),
                ));
            }
            diags.push(
                Diagnostic::error()
                    .with_code("stage-mismatch")
                    .with_message(message)
                    .with_labels(labels)
                    .with_notes(vec![note]),
            );
        }
    }
    diags.error_count() == before
}

/// The inter-stage variables of one side of a pass fit the limit: their
/// number (plus counted builtins) and their highest location. False (and
/// reported) when they do not.
#[allow(clippy::too_many_arguments)]
fn check_count(
    m: &Material,
    pass: &Pass,
    composed: &Composed,
    io: &[Io],
    builtins: u32,
    stage: &str,
    limit: u64,
    diags: &mut Diagnostics,
) -> bool {
    let count = io.len() as u64 + u64::from(builtins);
    let highest = io
        .iter()
        .map(|v| u64::from(v.location) + 1)
        .max()
        .unwrap_or(0);
    if count <= limit && highest <= limit {
        return true;
    }
    let entry = if stage == "vertex" {
        &pass.vertex
    } else {
        &pass.fragment
    };
    let span = if stage == "vertex" {
        &pass.vertex_span
    } else {
        &pass.fragment_span
    };
    let needed = count.max(highest);
    let message = if count > limit {
        format!(
            "pass `{}`: {stage} `{entry}` uses {count} inter-stage variables, more than maxInterStageShaderVariables ({limit})",
            pass.name
        )
    } else {
        format!(
            "pass `{}`: {stage} `{entry}` uses @location({}), but maxInterStageShaderVariables is {limit}",
            pass.name,
            highest - 1
        )
    };
    let mut labels = vec![
        Label::primary(pass.decl.file, span.clone()).with_message(format!("{stage} `{entry}`")),
    ];
    if let Some(last) = io.last() {
        labels.extend(declaration_label(
            composed,
            last,
            format!("up to @location({})", highest - 1),
        ));
    }
    if let Some((_, s)) = m
        .limit_spans
        .iter()
        .find(|(k, _)| *k == "max_inter_stage_shader_variables")
    {
        labels.push(
            Label::secondary(m.file, s.clone()).with_message(format!("raised to {limit} here")),
        );
    }
    let mut notes = Vec::new();
    if builtins > 0 {
        notes.push(format!(
            "{} @location inputs and {builtins} of front_facing, sample_index, sample_mask (WebGPU counts those too)",
            io.len()
        ));
    }
    notes.push(format!(
        "each @location passed between the stages is one variable, and every location must be below the limit; pack values into fewer vec4s, or, if every device your engines target supports more, declare `max_inter_stage_shader_variables = {needed}` under `[limits]`"
    ));
    diags.push(
        Diagnostic::error()
            .with_code("gpu-limit")
            .with_message(message)
            .with_labels(labels)
            .with_notes(notes),
    );
    false
}
