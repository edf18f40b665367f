//! A parsed scene checked against the materials it names. Each instance gets
//! its material (loaded once from the materials root), a value for every
//! parameter and keyword (default, then preset, then the instance's own),
//! its tier, its `dynamic` list, and a static variant the material builds.
//! Every mismatch is reported at the scene file's line, with the material's
//! declaration as a secondary label where that helps.

use super::model::*;
use super::parse::{AUTO_TIER, Parsed, WrittenParam};
use crate::diag::{Diagnostics, FileId, SourceDb, Span, suggestion, suggestion_listing};
use crate::model::{Material, ParamValue, PresetValue};
use crate::toml_reader::Cx;
use crate::values::{self, RangeReport, Site};
use crate::variants::{self, VariantKey};
use codespan_reporting::diagnostic::{Diagnostic, Label};
use std::path::Path;
use toml::de::DeValue;
use weft_meta::{KeywordMode, ParamKind};

mod library;
use library::Library;

/// Checks every instance against its material. The scene is complete only
/// when this added no error; the caller decides from the error count.
pub fn resolve(parsed: Parsed, db: &mut SourceDb, diags: &mut Diagnostics) -> ResolvedScene {
    resolve_with(parsed, crate::gltf::GltfCache::default(), db, diags)
}

/// [`resolve`] with glTF files already opened (a glTF scene's own file).
pub fn resolve_with(
    parsed: Parsed,
    mut gltf: crate::gltf::GltfCache,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> ResolvedScene {
    let Parsed { manifest, params } = parsed;
    let file = manifest.file;
    let mut library = Library::new(&manifest.materials_root);
    let manifest_dir = manifest
        .path
        .parent()
        .map(Path::to_path_buf)
        .unwrap_or_default();
    let mut images = super::images::SceneImages::new(&manifest_dir);
    let mut instances = Vec::new();
    for (decl, written) in manifest.instances.iter().zip(&params) {
        let Some(mesh) = instance_mesh(decl, &manifest_dir, &mut gltf, file, diags) else {
            continue;
        };
        let Some(index) = library.get(&decl.material, file, db, diags) else {
            continue;
        };
        let Some(material) = library.materials.get(index) else {
            continue;
        };
        let mut cx = Cx { file, diags };
        let at = Resolving {
            manifest: &manifest,
            decl,
            m: material,
            index,
        };
        let mut files = Files {
            images: &mut images,
            gltf: &mut gltf,
        };
        if let Some(instance) = at.instance(written, mesh, &mut files, &mut cx) {
            instances.push(instance);
        }
    }
    for w in std::mem::take(&mut gltf.warnings) {
        diags.push(Diagnostic::warning().with_code("gltf").with_message(w));
    }
    check_mesh_names(&instances, file, diags);
    check_variants(&manifest, diags);
    ResolvedScene {
        manifest,
        materials: library.materials,
        instances,
    }
}

/// The instance's mesh: built in, or read from its glTF file (errors at
/// the `mesh` key, naming the file's JSON pointer).
fn instance_mesh(
    decl: &InstanceDecl,
    manifest_dir: &Path,
    gltf: &mut crate::gltf::GltfCache,
    file: FileId,
    diags: &mut Diagnostics,
) -> Option<InstanceMesh> {
    match &decl.mesh.value {
        MeshSpec::Builtin(b) => Some(InstanceMesh::Builtin(*b)),
        MeshSpec::Gltf {
            file: path,
            mesh,
            primitive,
            uv_transform,
            node,
        } => match gltf.mesh(
            &manifest_dir.join(path),
            *mesh,
            *primitive,
            *uv_transform,
            *node,
        ) {
            Ok(m) => Some(InstanceMesh::File(m)),
            Err(e) => {
                diags.push(
                    Diagnostic::error()
                        .with_code("gltf")
                        .with_message(e.to_string())
                        .with_labels(vec![
                            Label::primary(file, decl.mesh.span.clone())
                                .with_message(format!("instance `{}`'s mesh", decl.name)),
                        ])
                        .with_notes(vec![e.hint.clone()]),
                );
                None
            }
        },
    }
}

/// A variant's instance replaces an instance of the scene that is not
/// itself a variant's.
fn check_variants(manifest: &SceneManifest, diags: &mut Diagnostics) {
    for decl in &manifest.instances {
        let Some(v) = &decl.variant else { continue };
        let target = manifest
            .instances
            .iter()
            .find(|i| i.name == v.value.replaces);
        let problem = match target {
            None => format!(
                "replaces `{}`, which the scene does not have",
                v.value.replaces
            ),
            Some(t) if t.variant.is_some() => {
                format!(
                    "replaces `{}`, which is itself a variant's instance",
                    v.value.replaces
                )
            }
            Some(_) => continue,
        };
        diags.push(
            Diagnostic::error()
                .with_code("unknown-instance")
                .with_message(format!("instance `{}` {problem}", decl.name))
                .with_labels(vec![Label::primary(manifest.file, v.span.clone())])
                .with_notes(vec![
                    "`replaces` names an ordinary instance of this scene".into(),
                ]),
        );
    }
}

/// Two glTF files with the same stem would give two meshes one name in
/// the scene metadata: refused.
fn check_mesh_names(instances: &[ResolvedInstance], file: FileId, diags: &mut Diagnostics) {
    let mut seen: Vec<&std::sync::Arc<crate::gltf::FileMesh>> = Vec::new();
    for inst in instances {
        let InstanceMesh::File(m) = &inst.mesh else {
            continue;
        };
        if let Some(other) = seen
            .iter()
            .find(|o| o.name == m.name && !std::sync::Arc::ptr_eq(o, m))
        {
            diags.push(
                Diagnostic::error()
                    .with_code("gltf")
                    .with_message(format!(
                        "two glTF meshes are both named `{}` in the scene metadata",
                        other.name
                    ))
                    .with_labels(vec![Label::primary(file, inst.span.clone())])
                    .with_notes(vec![
                        "glTF files of one scene need distinct file names".into(),
                    ]),
            );
            return;
        }
        seen.push(m);
    }
}

/// Where a keyword value or the tier came from, for the exclusion report.
#[derive(Clone, Debug)]
enum Source {
    Default,
    Preset(Span),
    Instance(Span),
}

/// One instance being checked against its material.
struct Resolving<'r> {
    manifest: &'r SceneManifest,
    decl: &'r InstanceDecl,
    m: &'r Material,
    /// Index of `m` in the scene's materials.
    index: usize,
}

/// What an instance's values may read: images, through glTF files opened once per scene.
struct Files<'f> {
    images: &'f mut super::images::SceneImages,
    gltf: &'f mut crate::gltf::GltfCache,
}

/// Values and keywords as they resolve, with where each keyword and the tier came from.
struct State {
    values: Vec<ParamValue>,
    images: std::collections::BTreeMap<usize, super::images::SceneImage>,
    /// Which values the preset or the instance wrote.
    set: Vec<bool>,
    keywords: Vec<usize>,
    keyword_from: Vec<Source>,
    tier: usize,
    tier_from: Source,
}

impl Resolving<'_> {
    fn instance(
        &self,
        written: &[WrittenParam],
        mesh: InstanceMesh,
        files: &mut Files,
        cx: &mut Cx,
    ) -> Option<ResolvedInstance> {
        let (decl, m) = (self.decl, self.m);
        let mut state = State {
            values: m.params.iter().map(|p| p.default.clone()).collect(),
            images: Default::default(),
            set: vec![false; m.params.len()],
            keywords: m.keywords.iter().map(|k| k.default).collect(),
            keyword_from: vec![Source::Default; m.keywords.len()],
            tier: m.tiers.default,
            tier_from: Source::Default,
        };
        let before = cx.diags.error_count();
        self.apply_preset(&mut state, cx);
        self.apply_keywords(&mut state, cx);
        let tier = self.tier(&mut state, cx);
        if let Some(tier) = &tier
            && cx.diags.error_count() == before
        {
            self.check_excluded(tier, &state, cx);
        }
        self.apply_params(&mut state, written, files, cx);
        let (dynamic, dynamic_spans) = self.dynamic(cx);
        let (vertex_inputs, vertex_inputs_span) = match &decl.vertex_inputs {
            Some(v) => (v.value.clone(), v.span.clone()),
            None => (
                self.manifest.vertex_inputs.value.clone(),
                self.manifest.vertex_inputs.span.clone(),
            ),
        };
        Some(ResolvedInstance {
            name: decl.name.clone(),
            material: self.index,
            preset: decl.preset.as_ref().map(|p| p.value.clone()),
            tier: tier?,
            keywords: state.keywords,
            values: state.values,
            set: state.set,
            dynamic,
            dynamic_spans,
            images: state.images,
            mesh,
            variant: decl.variant.as_ref().map(|v| v.value.clone()),
            overrides: decl.overrides,
            vertex_inputs,
            vertex_inputs_span,
            transform: decl.transform.clone(),
            span: decl.span.clone(),
            tier_span: decl.tier.span.clone(),
        })
    }

    fn what(&self) -> String {
        format!("instance `{}`", self.decl.name)
    }

    /// The preset's parameter values, keyword values and tier.
    fn apply_preset(&self, state: &mut State, cx: &mut Cx) {
        let (decl, m) = (self.decl, self.m);
        let Some(written) = &decl.preset else {
            return;
        };
        let Some(preset) = m.presets.iter().find(|p| p.name == written.value) else {
            let names: Vec<&str> = m.presets.iter().map(|p| p.name.as_str()).collect();
            cx.error_with_note(
                "unknown-preset",
                format!("material `{}` has no preset `{}`", m.name, written.value),
                written.span.clone(),
                "unknown preset",
                suggestion_listing(&written.value, &names, &format!("presets of `{}`", m.name)),
            );
            return;
        };
        let from = Source::Preset(written.span.clone());
        for (key, value) in &preset.values {
            match value {
                PresetValue::Param(v) => {
                    for ((p, slot), set) in m
                        .params
                        .iter()
                        .zip(state.values.iter_mut())
                        .zip(state.set.iter_mut())
                    {
                        if p.name == *key {
                            *slot = values::conform(p.kind, v);
                            *set = true;
                        }
                    }
                }
                PresetValue::Keyword(v) if m.keyword(key).is_none() => {
                    // `tier` (the material's checks admit no other non-keyword).
                    if let Some(t) = m.tiers.values.iter().position(|t| t == v) {
                        state.tier = t;
                        state.tier_from = from.clone();
                    }
                }
                PresetValue::Keyword(v) => {
                    for (k, kw) in m.keywords.iter().enumerate() {
                        if kw.name == *key
                            && let Some(vi) = kw.values.iter().position(|x| x == v)
                            && let (Some(slot), Some(src)) =
                                (state.keywords.get_mut(k), state.keyword_from.get_mut(k))
                        {
                            *slot = vi;
                            *src = from.clone();
                        }
                    }
                }
            }
        }
    }

    /// The instance's `keywords`.
    fn apply_keywords(&self, state: &mut State, cx: &mut Cx) {
        let m = self.m;
        for (name, value) in &self.decl.keywords {
            let Some(k) = m.keywords.iter().position(|k| k.name == name.value) else {
                let names: Vec<&str> = m.keywords.iter().map(|k| k.name.as_str()).collect();
                let note = if m.param(&name.value).is_some() {
                    format!("`{}` is a parameter: set it under `params`", name.value)
                } else if name.value == "tier" {
                    "`tier` is set on the instance itself, not under `keywords`".to_string()
                } else {
                    suggestion(&name.value, &names, &format!("keywords of `{}`", m.name))
                };
                cx.error_with_note(
                    "unknown-keyword",
                    format!("material `{}` has no keyword `{}`", m.name, name.value),
                    name.span.clone(),
                    "unknown keyword",
                    note,
                );
                continue;
            };
            let Some(kw) = m.keywords.get(k) else {
                continue;
            };
            match kw.values.iter().position(|v| *v == value.value) {
                Some(vi) => {
                    if let (Some(slot), Some(src)) =
                        (state.keywords.get_mut(k), state.keyword_from.get_mut(k))
                    {
                        *slot = vi;
                        *src = Source::Instance(value.span.clone());
                    }
                }
                None => {
                    let names: Vec<&str> = kw.values.iter().map(String::as_str).collect();
                    let note = suggestion_listing(
                        &value.value,
                        &names,
                        &format!("values of `{}`", kw.name),
                    );
                    let d = cx.diags.error(
                        "unknown-value",
                        format!("`{}` is not a value of keyword `{}`", value.value, kw.name),
                        cx.file,
                        value.span.clone(),
                        "unknown value",
                    );
                    d.labels.push(
                        Label::secondary(kw.decl.file, kw.decl.span.clone())
                            .with_message(format!("`{}` declared here", kw.name)),
                    );
                    d.notes.push(note);
                }
            }
        }
    }

    /// The tier: the instance's, else the preset's, else the material's default.
    fn tier(&self, state: &mut State, cx: &mut Cx) -> Option<TierChoice> {
        let (decl, m) = (self.decl, self.m);
        match &decl.tier.value {
            TierRequest::Default => Some(TierChoice::Fixed(state.tier)),
            TierRequest::Auto {
                error_budget,
                screen_size,
            } => Some(TierChoice::Auto {
                error_budget: *error_budget,
                screen_size: *screen_size,
            }),
            TierRequest::Named(name) => match m.tiers.values.iter().position(|t| t == name) {
                Some(t) => {
                    state.tier = t;
                    state.tier_from = Source::Instance(decl.tier.span.clone());
                    Some(TierChoice::Fixed(t))
                }
                None => {
                    let mut names: Vec<&str> = m.tiers.values.iter().map(String::as_str).collect();
                    names.push(AUTO_TIER);
                    let note = suggestion_listing(name, &names, &format!("tiers of `{}`", m.name));
                    cx.error_with_note(
                        "unknown-tier",
                        format!("material `{}` has no tier `{name}`", m.name),
                        decl.tier.span.clone(),
                        "unknown tier",
                        note,
                    );
                    None
                }
            },
        }
    }

    /// The instance's `params`, typed against the material's declarations.
    fn apply_params(
        &self,
        state: &mut State,
        written: &[WrittenParam],
        files: &mut Files,
        cx: &mut Cx,
    ) {
        let m = self.m;
        for w in written {
            let Some(i) = m.params.iter().position(|p| p.name == w.name) else {
                let names: Vec<&str> = m.params.iter().map(|p| p.name.as_str()).collect();
                let note = if m.keyword(w.name).is_some() {
                    format!("`{}` is a keyword: set it under `keywords`", w.name)
                } else if w.name == "tier" {
                    "`tier` is set on the instance itself, not under `params`".to_string()
                } else {
                    suggestion(w.name, &names, &format!("parameters of `{}`", m.name))
                };
                cx.error_with_note(
                    "unknown-param",
                    format!("material `{}` has no parameter `{}`", m.name, w.name),
                    w.name_span.clone(),
                    "unknown parameter",
                    note,
                );
                continue;
            };
            let (Some(p), Some(slot)) = (m.params.get(i), state.values.get_mut(i)) else {
                continue;
            };
            state.set[i] = true;
            let range = p
                .range
                .map_or_else(String::new, |r| format!(" [{}, {}]", r[0], r[1]));
            let site = Site {
                what: format!("`{}` of {}", w.name, self.what()),
                texture: "built-in texture",
                range: RangeReport {
                    code: "out-of-range",
                    message: format!(
                        "`{}` of {} is outside its range{range}",
                        w.name,
                        self.what()
                    ),
                    declared: None,
                    note: None,
                },
            };
            let mark = cx.diags.len();
            state.images.remove(&i);
            if p.kind == ParamKind::Texture2d && matches!(w.value.get_ref(), DeValue::Table(_)) {
                // An image: the value stays the default, the binding the image's.
                let what = format!("`{}` of {}", w.name, self.what());
                if let Some(image) = files.images.load(w.value, &what, p.tiling, files.gltf, cx) {
                    state.images.insert(i, image);
                }
            } else if let Some(v) = values::parse_value(w.value, p.kind, p.range, &site, cx) {
                *slot = v;
            }
            // Point every problem with the value at the declaration too.
            let declared = match p.range {
                Some(_) => format!("declared here as {} in{range}", p.kind.name()),
                None => format!("declared here as {}", p.kind.name()),
            };
            for d in cx.diags.since_mut(mark) {
                d.labels.push(
                    Label::secondary(p.decl.file, p.decl.span.clone())
                        .with_message(declared.clone()),
                );
                if d.code.as_deref() == Some("wrong-type") {
                    d.notes.push(values::how_to_write(p.kind).into());
                }
            }
        }
    }

    /// `dynamic`: parameter indices and where each is written.
    fn dynamic(&self, cx: &mut Cx) -> (Vec<usize>, Vec<Span>) {
        let m = self.m;
        let mut out = (Vec::new(), Vec::new());
        for d in &self.decl.dynamic {
            match m.params.iter().position(|p| p.name == d.value) {
                Some(i) => {
                    out.0.push(i);
                    out.1.push(d.span.clone());
                }
                None => {
                    let names: Vec<&str> = m.params.iter().map(|p| p.name.as_str()).collect();
                    let note = if m.keyword(&d.value).is_some() {
                        format!(
                            "`{}` is a keyword: keywords are fixed per instance, only parameters can be dynamic",
                            d.value
                        )
                    } else {
                        suggestion(&d.value, &names, &format!("parameters of `{}`", m.name))
                    };
                    cx.error_with_note(
                        "unknown-param",
                        format!(
                            "`dynamic` names `{}`, which is not a parameter of `{}`",
                            d.value, m.name
                        ),
                        d.span.clone(),
                        "unknown parameter",
                        note,
                    );
                }
            }
        }
        out
    }

    /// The variant the instance needs (its tier and static keyword values)
    /// must be one the material builds; with `auto`, at least one tier must be.
    fn check_excluded(&self, tier: &TierChoice, state: &State, cx: &mut Cx) {
        let m = self.m;
        let statics: Vec<(usize, usize)> = m
            .keywords
            .iter()
            .zip(&state.keywords)
            .enumerate()
            .filter(|(_, (k, _))| k.mode == KeywordMode::Static)
            .map(|(i, (_, v))| (i, *v))
            .collect();
        let key = |tier: usize| VariantKey {
            tier,
            keywords: statics.clone(),
        };
        let excluded = |key: VariantKey| {
            m.exclude
                .iter()
                .position(|e| key.matches(m, e))
                .map(|entry| (key, entry))
        };
        let hits: Vec<(VariantKey, usize)> = match tier {
            TierChoice::Fixed(t) => excluded(key(*t)).into_iter().collect(),
            TierChoice::Auto { .. } => {
                let all: Vec<_> = (0..m.tiers.values.len())
                    .filter_map(|t| excluded(key(t)))
                    .collect();
                if all.len() == m.tiers.values.len() {
                    all
                } else {
                    Vec::new()
                }
            }
        };
        if !hits.is_empty() {
            self.report_excluded(tier, &hits, state, cx);
        }
    }

    fn report_excluded(
        &self,
        tier: &TierChoice,
        hits: &[(VariantKey, usize)],
        state: &State,
        cx: &mut Cx,
    ) {
        let (decl, m) = (self.decl, self.m);
        let Some((first, _)) = hits.first() else {
            return;
        };
        // What the excluding entries test, and where each tested value came from.
        let mut parts: Vec<(String, Source)> = Vec::new();
        for (_, entry) in hits {
            for c in m.exclude.get(*entry).into_iter().flatten() {
                let part = if c.subject == "tier" {
                    if matches!(tier, TierChoice::Auto { .. }) {
                        continue;
                    }
                    let name = m.tiers.values.get(state.tier).cloned().unwrap_or_default();
                    (format!("tier = {name}"), state.tier_from.clone())
                } else {
                    let Some(k) = m.keywords.iter().position(|k| k.name == c.subject) else {
                        continue;
                    };
                    let value = first.value_of(m, &c.subject).unwrap_or_default();
                    let from = state
                        .keyword_from
                        .get(k)
                        .cloned()
                        .unwrap_or(Source::Default);
                    (format!("{} = {value}", c.subject), from)
                };
                if !parts.iter().any(|(p, _)| *p == part.0) {
                    parts.push(part);
                }
            }
        }
        let message = match tier {
            TierChoice::Fixed(_) => format!(
                "instance `{}` needs variant `{}` of `{}`, which `[variants].exclude` removes",
                decl.name,
                first.id(m),
                m.name
            ),
            TierChoice::Auto { .. } => format!(
                "instance `{}` leaves `{AUTO_TIER}` no tier: `[variants].exclude` removes every tier of `{}` with these keywords",
                decl.name, m.name
            ),
        };
        let mut labels = Vec::new();
        for (text, from) in &parts {
            match from {
                Source::Instance(span) => labels.push((span.clone(), format!("`{text}`"))),
                Source::Preset(span) => {
                    labels.push((span.clone(), format!("the preset sets `{text}`")))
                }
                Source::Default => {}
            }
        }
        labels.sort_by_key(|(span, _)| span.start);
        labels.dedup_by(|a, b| a.0 == b.0);
        if labels.is_empty() {
            labels.push((
                decl.material.span.clone(),
                format!("`{}`'s default values", m.name),
            ));
        }
        let mut list = labels.into_iter();
        let Some((span, label)) = list.next() else {
            return;
        };
        let d = cx
            .diags
            .error("excluded-variant", message, cx.file, span, label);
        for (span, label) in list {
            d.labels
                .push(Label::secondary(cx.file, span).with_message(label));
        }
        let mut entries: Vec<usize> = hits.iter().map(|(_, e)| *e).collect();
        entries.dedup();
        for e in entries {
            if let Some(span) = m.exclude_spans.get(e) {
                d.labels.push(
                    Label::secondary(m.file, span.clone())
                        .with_message("this `exclude` entry removes it"),
                );
            }
        }
        let combination: Vec<&str> = parts.iter().map(|(p, _)| p.as_str()).collect();
        d.notes
            .push(format!("the combination: {}", combination.join(", ")));
        let built: Vec<String> = variants::variants(m).iter().map(|v| v.id(m)).collect();
        let shown = built.iter().take(8).cloned().collect::<Vec<_>>().join(", ");
        let more = if built.len() > 8 { ", …" } else { "" };
        d.notes.push(format!(
            "variants `{}` builds: {shown}{more}; choose another tier or keyword value",
            m.name
        ));
    }
}
