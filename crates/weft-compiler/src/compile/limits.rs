//! WebGPU device limits checked per variant, on what each specialised
//! variant actually binds: bind groups and binding numbers, uniform buffer
//! size, uniform buffers, sampled textures and samplers per shader stage,
//! vertex attributes. The limits in force are WebGPU's defaults, raised by
//! the material's `[limits]` table. A variant over a limit is a `gpu-limit`
//! error at the binding's declaration in the user's files (a parameter's in
//! the TOML, a binding's in the WGSL), naming the limit.

use crate::compile::source_map::Composed;
use crate::compile::variant::CompiledVariant;
use codespan_reporting::diagnostic::{Diagnostic, Label};
use std::collections::BTreeMap;
use weft_front::model::{Loc, Material};
use weft_front::variants::VariantKey;
use weft_front::{Diagnostics, FileId};
use weft_meta::limits::limit_spec;
use weft_meta::{Binding, BindingKind, Stage};

/// A per-stage limit: its key, what it counts (plural), and which bindings.
type PerStage = (&'static str, &'static str, fn(BindingKind) -> bool);

/// What a per-stage limit counts.
const PER_STAGE: [PerStage; 3] = [
    (
        "max_uniform_buffers_per_shader_stage",
        "uniform buffers",
        |k| k == BindingKind::UniformBuffer,
    ),
    (
        "max_sampled_textures_per_shader_stage",
        "sampled textures",
        |k| {
            matches!(
                k,
                BindingKind::Texture2d
                    | BindingKind::TextureCube
                    | BindingKind::Texture2dArray
                    | BindingKind::Texture3d
                    | BindingKind::DepthTexture2d
            )
        },
    ),
    ("max_samplers_per_shader_stage", "samplers", |k| {
        matches!(k, BindingKind::Sampler | BindingKind::ComparisonSampler)
    }),
];

/// One way a variant exceeds a limit, before it is reported.
struct Finding {
    limit: &'static str,
    /// What is over the limit (a binding, a stage): one report per limit and subject.
    subject: String,
    message: String,
    /// Where to point, and what to say there.
    at: Option<Loc>,
    label: String,
    /// Secondary labels.
    also: Vec<(Loc, String)>,
    notes: Vec<String>,
    /// How far over the limit (the worst variant is reported).
    amount: u64,
}

/// Where the module declares each binding, in the user's files: a
/// prelude-generated binding maps to its TOML declaration. None for the
/// engine interface's bindings, which the user did not write.
struct Sites<'a> {
    composed: &'a Composed,
    module: &'a naga::Module,
    engine: FileId,
}

impl Sites<'_> {
    fn of(&self, b: &Binding) -> Option<Loc> {
        let (handle, _) = self.module.global_variables.iter().find(|(_, v)| {
            v.binding
                .as_ref()
                .is_some_and(|r| r.group == b.group && r.binding == b.binding)
        })?;
        let span = self.module.global_variables.get_span(handle).to_range()?;
        let (file, span) = self.composed.map.map(span)?;
        (file != self.engine).then_some(Loc { file, span })
    }
}

fn stage_name(s: Stage) -> &'static str {
    match s {
        Stage::Vertex => "vertex",
        Stage::Fragment => "fragment",
        Stage::Compute => "compute",
    }
}

/// "1st", "2nd", "17th", …
fn ordinal(n: u64) -> String {
    let suffix = match (n % 10, n % 100) {
        (1, x) if x != 11 => "st",
        (2, x) if x != 12 => "nd",
        (3, x) if x != 13 => "rd",
        _ => "th",
    };
    format!("{n}{suffix}")
}

/// How to raise `key`: the hint every finding ends with.
fn raise_hint(m: &Material, key: &str, needed: u64, alternative: &str) -> String {
    let spec = limit_spec(key).expect("a checked limit");
    let current = m.limits.get(key);
    let from = if m.limits.declared(key).is_some() {
        format!("this material raises it to {current}")
    } else {
        format!("WebGPU's default is {current}")
    };
    format!(
        "{from}; {alternative}, or, if every device your engines target supports more, declare `{key} = {needed}` under `[limits]` (the metadata then tells engines to request {} = {needed})",
        spec.webgpu
    )
}

/// The findings of one variant.
fn variant_findings(m: &Material, v: &CompiledVariant, shown: &str, sites: &Sites) -> Vec<Finding> {
    let mut out = Vec::new();
    let bindings = &v.shader.bindings;
    for b in bindings {
        binding_findings(m, b, shown, sites, &mut out);
    }
    stage_findings(m, bindings, shown, sites, &mut out);
    out.extend(vertex_attribute_finding(m, v, shown));
    out
}

/// One binding against the bind group count, the binding numbers per group
/// and (a uniform buffer) the uniform buffer size.
fn binding_findings(m: &Material, b: &Binding, shown: &str, sites: &Sites, out: &mut Vec<Finding>) {
    let groups = m.limits.get("max_bind_groups");
    if u64::from(b.group) >= groups {
        out.push(Finding {
            limit: "max_bind_groups",
            subject: format!("{}:{}", b.group, b.binding),
            message: format!(
                "{shown} binds `{}` in @group({}), but maxBindGroups is {groups}",
                b.name, b.group
            ),
            at: sites.of(b),
            label: format!("@group({}) needs {} bind groups", b.group, b.group + 1),
            also: Vec::new(),
            notes: vec![raise_hint(
                m,
                "max_bind_groups",
                u64::from(b.group) + 1,
                "use groups 0 to 2 (the engine interface's and the material's)",
            )],
            amount: u64::from(b.group) + 1 - groups,
        });
    }
    let per_group = m.limits.get("max_bindings_per_bind_group");
    if u64::from(b.binding) >= per_group {
        out.push(Finding {
            limit: "max_bindings_per_bind_group",
            subject: format!("{}:{}", b.group, b.binding),
            message: format!(
                "{shown} binds `{}` at @binding({}), but maxBindingsPerBindGroup is {per_group}",
                b.name, b.binding
            ),
            at: sites.of(b),
            label: format!("binding number {} is too large", b.binding),
            also: Vec::new(),
            notes: vec![raise_hint(
                m,
                "max_bindings_per_bind_group",
                u64::from(b.binding) + 1,
                "use smaller binding numbers",
            )],
            amount: u64::from(b.binding) + 1 - per_group,
        });
    }
    let size_limit = m.limits.get("max_uniform_buffer_binding_size");
    if b.kind == BindingKind::UniformBuffer
        && let Some(buffer) = &b.buffer
        && buffer.min_binding_size > size_limit
    {
        let size = buffer.min_binding_size;
        let mut members: Vec<&weft_meta::UniformMember> = buffer.layout.members.iter().collect();
        members.sort_by_key(|mem| std::cmp::Reverse(mem.size));
        let largest: Vec<String> = members
            .iter()
            .take(3)
            .map(|mem| format!("`{}` ({} bytes)", mem.name, mem.size))
            .collect();
        out.push(Finding {
            limit: "max_uniform_buffer_binding_size",
            subject: format!("{}:{}", b.group, b.binding),
            message: format!(
                "the uniform buffer `{}` of {shown} is {size} bytes, more than maxUniformBufferBindingSize ({size_limit})",
                b.name
            ),
            at: sites.of(b),
            label: format!("`{}` is {size} bytes", buffer.layout.struct_name),
            also: members
                .iter()
                .take(3)
                .filter_map(|mem| {
                    let p = m.param(mem.parameter.as_deref()?)?;
                    Some((p.decl.clone(), format!("{} bytes", mem.size)))
                })
                .collect(),
            notes: vec![
                format!("its largest members: {}", largest.join(", ")),
                raise_hint(
                    m,
                    "max_uniform_buffer_binding_size",
                    size,
                    "use fewer or smaller uniform members (curve `samples`, for one)",
                ),
            ],
            amount: size - size_limit,
        });
    }
}

/// The sampled textures, samplers and uniform buffers of each stage against
/// their per-stage limits.
fn stage_findings(
    m: &Material,
    bindings: &[Binding],
    shown: &str,
    sites: &Sites,
    out: &mut Vec<Finding>,
) {
    for stage in [Stage::Vertex, Stage::Fragment] {
        for (key, what, counts) in PER_STAGE {
            let limit = m.limits.get(key);
            let used: Vec<&Binding> = bindings
                .iter()
                .filter(|b| counts(b.kind) && b.stages.contains(&stage))
                .collect();
            let n = used.len() as u64;
            if n <= limit {
                continue;
            }
            // Point at the one that tips the count over, else the last one the user wrote.
            let stage = stage_name(stage);
            let tipping = used.get(limit as usize).and_then(|b| sites.of(b));
            let label = match tipping {
                Some(_) => format!(
                    "the {} of {n} {what} in the {stage} stage",
                    ordinal(limit + 1)
                ),
                None => format!("one of {n} {what} in the {stage} stage"),
            };
            let at = tipping.or_else(|| used.iter().rev().find_map(|b| sites.of(b)));
            let (engine, material): (Vec<&&Binding>, Vec<&&Binding>) =
                used.iter().partition(|b| sites.of(b).is_none());
            let names = |bs: &[&&Binding]| {
                bs.iter()
                    .map(|b| b.parameter.clone().unwrap_or_else(|| b.name.clone()))
                    .collect::<Vec<_>>()
                    .join(", ")
            };
            let mut counted = Vec::new();
            if !engine.is_empty() {
                counted.push(format!(
                    "{} of the engine interface ({})",
                    engine.len(),
                    names(&engine)
                ));
            }
            if !material.is_empty() {
                counted.push(format!(
                    "{} of this material ({})",
                    material.len(),
                    names(&material)
                ));
            }
            let spec = limit_spec(key).expect("a checked limit");
            out.push(Finding {
                limit: key,
                subject: stage.into(),
                message: format!(
                    "{shown} uses {n} {what} in the {stage} stage, more than {} ({limit})",
                    spec.webgpu
                ),
                at,
                label,
                also: Vec::new(),
                notes: vec![
                    format!("counted: {}", counted.join(", ")),
                    raise_hint(
                        m,
                        key,
                        n,
                        &format!("use fewer {what} in this variant (branches a keyword or tier removes do not count)"),
                    ),
                ],
                amount: n - limit,
            });
        }
    }
}

/// The vertex attributes the variant reads against `max_vertex_attributes`.
fn vertex_attribute_finding(m: &Material, v: &CompiledVariant, shown: &str) -> Option<Finding> {
    let attributes = m.limits.get("max_vertex_attributes");
    let inputs = &v.shader.vertex_inputs;
    let highest = inputs
        .iter()
        .map(|i| u64::from(i.location) + 1)
        .max()
        .unwrap_or(0);
    let needed = highest.max(inputs.len() as u64);
    if needed <= attributes {
        return None;
    }
    Some(Finding {
        limit: "max_vertex_attributes",
        subject: String::new(),
        message: format!(
            "{shown} reads {} vertex attributes (up to @location({})), more than maxVertexAttributes ({attributes})",
            inputs.len(),
            highest.saturating_sub(1)
        ),
        at: Some(Loc {
            file: m.file,
            span: m.requires_span.clone(),
        }),
        label: "the vertex inputs this material requires".into(),
        also: Vec::new(),
        notes: vec![raise_hint(
            m,
            "max_vertex_attributes",
            needed,
            "read fewer vertex inputs",
        )],
        amount: needed - attributes,
    })
}

/// Checks every compiled variant against the limits in force; reports one
/// diagnostic per limit (and binding or stage), for the variant furthest over
/// it, noting which other variants exceed it too. `shown` names each
/// compiled variant in messages ("variant `fast`", "the shader of instance
/// `dress`"). True when all fit.
#[allow(clippy::too_many_arguments)]
pub fn check_variants(
    m: &Material,
    shown: &[String],
    composed: &Composed,
    module: &naga::Module,
    engine: FileId,
    keys: &[VariantKey],
    compiled: &[CompiledVariant],
    diags: &mut Diagnostics,
) -> bool {
    let sites = Sites {
        composed,
        module,
        engine,
    };
    // (limit, message shape) -> (worst finding, variants that exceed it).
    let mut found: BTreeMap<(&'static str, String), (Finding, Vec<String>)> = BTreeMap::new();
    for ((_, v), name) in keys.iter().zip(compiled).zip(shown) {
        for f in variant_findings(m, v, name, &sites) {
            let key = (f.limit, f.subject.clone());
            match found.get_mut(&key) {
                Some((worst, ids)) => {
                    ids.push(name.clone());
                    if f.amount > worst.amount {
                        *worst = f;
                    }
                }
                None => {
                    found.insert(key, (f, vec![name.clone()]));
                }
            }
        }
    }
    let ok = found.is_empty();
    for (_, (f, ids)) in found {
        let at = f.at.unwrap_or(m.decl.clone());
        let mut labels = vec![Label::primary(at.file, at.span).with_message(f.label)];
        labels.extend(
            f.also
                .into_iter()
                .map(|(loc, msg)| Label::secondary(loc.file, loc.span).with_message(msg)),
        );
        if let Some((_, span)) = m.limit_spans.iter().find(|(k, _)| *k == f.limit) {
            labels.push(
                Label::secondary(m.file, span.clone())
                    .with_message(format!("raised to {} here", m.limits.get(f.limit))),
            );
        }
        let mut notes = f.notes;
        if ids.len() > 1 {
            let listed: Vec<&str> = ids.iter().take(4).map(String::as_str).collect();
            notes.push(format!(
                "over the limit ({}): {}{}",
                ids.len(),
                listed.join(", "),
                if ids.len() > listed.len() {
                    ", …"
                } else {
                    ""
                }
            ));
        }
        diags.push(
            Diagnostic::error()
                .with_code("gpu-limit")
                .with_message(f.message)
                .with_labels(labels)
                .with_notes(notes),
        );
    }
    ok
}
