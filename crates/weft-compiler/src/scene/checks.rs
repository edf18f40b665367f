//! The scene build's own checks, each a diagnostic at the scene file's
//! line: the number of distinct shaders, each instance's shader against its
//! mesh's vertex inputs and WebGPU's limits, `dynamic` parameters its shader
//! never reads (a warning), and the manifest's `max_shaders` budget.

use super::MAX_SCENE_SHADERS;
use crate::compile::variant::CompiledVariant;
use codespan_reporting::diagnostic::{Diagnostic, Label};
use weft_front::model::Material;
use weft_front::scene::model::{ResolvedInstance, ResolvedScene, SceneManifest};
use weft_front::variants::VariantKey;
use weft_front::{Diagnostics, FileId};
use weft_meta::VariantShader;

/// At most [`MAX_SCENE_SHADERS`] distinct specialisations (`unique` holds the
/// first instance of each).
pub(super) fn within_shader_limit(
    scene: &ResolvedScene,
    unique: &[usize],
    diags: &mut Diagnostics,
) -> bool {
    if unique.len() <= MAX_SCENE_SHADERS {
        return true;
    }
    let over = &scene.instances[unique[MAX_SCENE_SHADERS]];
    diags.push(
        Diagnostic::error()
            .with_code("too-many-shaders")
            .with_message(format!(
                "the scene needs {} distinct specialised shaders; at most {MAX_SCENE_SHADERS} are built",
                unique.len()
            ))
            .with_labels(vec![
                Label::primary(scene.manifest.file, over.span.clone()).with_message(format!(
                    "instance `{}` needs shader number {}",
                    over.name,
                    MAX_SCENE_SHADERS + 1
                )),
            ])
            .with_notes(vec![
                "instances share a shader when they have the same material, tier, keywords and constant values: make the differing parameters `dynamic`, or split the scene".into(),
            ]),
    );
    false
}

/// The mesh feeds every input the specialised shader reads.
pub(super) fn mesh_feeds_shader(
    manifest: &SceneManifest,
    inst: &ResolvedInstance,
    m: &Material,
    variant: &str,
    shader: &VariantShader,
    diags: &mut Diagnostics,
) -> bool {
    let missing: Vec<&str> = shader
        .vertex_inputs
        .iter()
        .filter(|vi| !inst.vertex_inputs.iter().any(|a| a.name() == vi.name))
        .map(|vi| vi.name.as_str())
        .collect();
    if missing.is_empty() {
        return true;
    }
    diags.push(
        Diagnostic::error()
            .with_code("missing-vertex-input")
            .with_message(format!(
                "instance `{}`: its shader ({} `{variant}`) reads vertex input{} {} that the mesh does not have",
                inst.name,
                m.name,
                if missing.len() > 1 { "s" } else { "" },
                missing.iter().map(|s| format!("`{s}`")).collect::<Vec<_>>().join(", ")
            ))
            .with_labels(vec![
                Label::primary(manifest.file, inst.vertex_inputs_span.clone())
                    .with_message("the mesh's vertex inputs"),
                Label::secondary(manifest.file, inst.span.clone())
                    .with_message("this instance"),
            ])
            .with_notes(vec![format!(
                "add {} to `vertex_inputs`, or choose keyword values whose variant does not read {}",
                missing.join(", "),
                if missing.len() > 1 { "them" } else { "it" }
            )]),
    );
    false
}

/// The material's module as the limit check needs it: composed text,
/// validated module, and the engine interface's file.
pub(super) struct LimitInputs<'a> {
    pub composed: &'a crate::compile::source_map::Composed,
    pub module: &'a naga::Module,
    pub engine: FileId,
}

/// The shader fits WebGPU's limits (or the material's `[limits]`); the
/// diagnostics the check gives also point at the instance.
pub(super) fn shader_fits_limits(
    manifest: &SceneManifest,
    inst: &ResolvedInstance,
    m: &Material,
    static_key: &VariantKey,
    compiled: &CompiledVariant,
    inputs: LimitInputs,
    diags: &mut Diagnostics,
) -> bool {
    let mark = diags.len();
    let fits = crate::compile::limits::check_variants(
        m,
        &[format!("the shader of instance `{}`", inst.name)],
        inputs.composed,
        inputs.module,
        inputs.engine,
        std::slice::from_ref(static_key),
        std::slice::from_ref(compiled),
        diags,
    );
    if !fits {
        for d in diags.since_mut(mark) {
            d.labels.push(
                Label::secondary(manifest.file, inst.span.clone())
                    .with_message(format!("instance `{}`", inst.name)),
            );
        }
    }
    fits
}

/// A `dynamic` parameter the shader does not read does nothing at run time:
/// a warning at its name.
pub(super) fn warn_unread_dynamic(
    manifest: &SceneManifest,
    inst: &ResolvedInstance,
    m: &Material,
    variant: &str,
    shader: &VariantShader,
    diags: &mut Diagnostics,
) {
    for (k, &pi) in inst.dynamic.iter().enumerate() {
        let name = &m.params[pi].name;
        if shader.reads.contains(name) {
            continue;
        }
        let span = inst
            .dynamic_spans
            .get(k)
            .cloned()
            .unwrap_or(inst.span.clone());
        diags.push(
            Diagnostic::warning()
                .with_code("unread-dynamic")
                .with_message(format!(
                    "instance `{}`: dynamic parameter `{name}` is not read by its shader ({} `{variant}`)",
                    inst.name, m.name
                ))
                .with_labels(vec![Label::primary(manifest.file, span)
                    .with_message("changing this at run time changes nothing")])
                .with_notes(vec![format!(
                    "`{name}` only matters with other keyword values or tiers; remove it from `dynamic`"
                )]),
        );
    }
}

/// The binding of `material_sampler`, through which a material reads its maps.
pub(super) fn is_material_sampler(b: &weft_meta::Binding) -> bool {
    b.group == weft_meta::engine::MATERIAL_GROUP
        && b.binding == weft_meta::engine::MATERIAL_SAMPLER_BINDING
}

/// An instance `sampler` whose shader reads no map through
/// `material_sampler` (none bound, or every one folded away) sets nothing.
pub(super) fn warn_unused_sampler(
    manifest: &SceneManifest,
    inst: &ResolvedInstance,
    shader: &VariantShader,
    diags: &mut Diagnostics,
) {
    let reads_maps = shader.bindings.iter().any(is_material_sampler);
    if inst.overrides.sampler.is_none() || reads_maps {
        return;
    }
    diags.push(
        Diagnostic::warning()
            .with_code("unused-sampler")
            .with_message(format!(
                "instance `{}` sets `sampler`, but its shader reads no map through `material_sampler`",
                inst.name
            ))
            .with_labels(vec![
                Label::primary(manifest.file, inst.span.clone())
                    .with_message("this instance's `sampler` changes nothing"),
            ])
            .with_notes(vec![
                "give the instance a texture parameter (a map), or remove `sampler`".into(),
            ]),
    );
}

/// The manifest's `max_shaders`, if it has one, against the shaders built.
pub(super) fn within_shader_budget(
    manifest: &SceneManifest,
    shaders: usize,
    diags: &mut Diagnostics,
) {
    if let Some(budget) = &manifest.max_shaders
        && shaders > budget.value
    {
        diags.push(
            Diagnostic::error()
                .with_code("shader-budget")
                .with_message(format!(
                    "the scene needs {} distinct shaders; `max_shaders` allows {}",
                    shaders,
                    budget.value
                ))
                .with_labels(vec![Label::primary(manifest.file, budget.span.clone())])
                .with_notes(vec![
                    "raise `max_shaders`, or make instances share a shader: same material, tier, keywords and constant values (or make the differing parameters `dynamic`)".into(),
                ]),
        );
    }
}
