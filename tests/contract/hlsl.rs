//! The HLSL files of the committed `generated/` tree with the entry points and
//! bindings their metadata states, and the check of a compiler's register
//! reflection against the metadata's `bindings[].hlsl`. Shared by
//! `hlsl_compilers` (Slang) and `hlsl_d3d` (DXC, FXC).

use std::path::PathBuf;
use weft_meta::scene::SceneMetadata;
use weft_meta::{Binding, BindingKind, MaterialMetadata, Stage};
use weft_tests::{repo, shaders};

/// One HLSL file with the entry points and bindings its metadata states.
pub struct Job {
    /// The file relative to `generated/`, for messages.
    pub label: String,
    pub path: PathBuf,
    pub entries: Vec<(String, Stage)>,
    pub bindings: Vec<Binding>,
}

/// Every HLSL file of every material variant and scene shader in `generated/`.
pub fn jobs() -> Vec<Job> {
    let generated = repo().join("generated");
    let mut materials = Vec::new();
    let mut scenes = Vec::new();
    for dir in std::fs::read_dir(&generated).unwrap().flatten() {
        let name = dir.file_name().to_string_lossy().into_owned();
        let meta = dir.path().join(format!("{name}.meta.json"));
        if meta.is_file() {
            let text = std::fs::read_to_string(&meta).unwrap();
            materials.push(MaterialMetadata::from_json(&text).unwrap());
        }
    }
    for dir in std::fs::read_dir(generated.join("scenes"))
        .unwrap()
        .flatten()
    {
        let name = dir.file_name().to_string_lossy().into_owned();
        let text = std::fs::read_to_string(dir.path().join(format!("{name}.scene.json"))).unwrap();
        scenes.push(SceneMetadata::from_json(&text).unwrap());
    }
    materials.sort_by(|a, b| a.name.cmp(&b.name));
    scenes.sort_by(|a, b| a.name.cmp(&b.name));
    let mut jobs = Vec::new();
    for s in shaders::shaders(&materials, &scenes) {
        for hlsl in &s.shader.files["hlsl"] {
            jobs.push(Job {
                label: s.file(&hlsl.path),
                path: generated.join(s.file(&hlsl.path)),
                entries: (s.shader.entry_points.iter())
                    .map(|e| (e.name.clone(), e.stage))
                    .collect(),
                bindings: s.shader.bindings.clone(),
            });
        }
    }
    jobs
}

/// The entry points of all jobs; with 400 or more and some scene shaders,
/// `jobs` saw every material variant and scene shader.
pub fn assert_complete(jobs: &[Job]) -> usize {
    let entries: usize = jobs.iter().map(|j| j.entries.len()).sum();
    assert!(
        jobs.iter().any(|j| j.label.starts_with("scenes/")) && entries >= 400,
        "expected every material variant's and scene shader's HLSL, got {entries} entry points"
    );
    entries
}

/// One resource binding as a compiler reflects it: the HLSL name, the
/// register (`b0`, `t64`, …) and the space.
#[derive(Clone, Debug, PartialEq)]
pub struct Reflected {
    pub name: String,
    pub register: String,
    pub space: u32,
}

/// The HLSL resource that carries a metadata binding: the binding's own name,
/// or for a sampler its group's sampler-index buffer (samplers live in naga's
/// heap).
pub fn resource_name(b: &Binding) -> String {
    if is_sampler(b) {
        format!("nagaGroup{}SamplerIndexArray", b.hlsl.space)
    } else {
        b.name.clone()
    }
}

fn is_sampler(b: &Binding) -> bool {
    matches!(
        b.kind,
        BindingKind::Sampler | BindingKind::ComparisonSampler
    )
}

/// The sampler heaps weft places (docs/hlsl-registers.md): name and space,
/// always register `s0`.
pub fn heaps() -> [(&'static str, u32); 2] {
    [
        (
            "nagaSamplerHeap",
            u32::from(weft_compiler::engine_binding::HLSL_SAMPLER_HEAP_SPACE),
        ),
        (
            "nagaComparisonSamplerHeap",
            u32::from(weft_compiler::engine_binding::HLSL_COMPARISON_SAMPLER_HEAP_SPACE),
        ),
    ]
}

/// What a compiler's reflection covers: every declaration of the file
/// (Slang), or what one entry point of `stage` uses after optimisation (DXC,
/// FXC: an optimiser drops a texture whose sample is dead in a variant, e.g.
/// skin's `curvature_map` with `curvature_map = off`, though the metadata
/// lists it).
#[derive(Clone, Copy)]
pub enum Scope {
    File,
    EntryPoint(Stage),
}

/// A compiler's reflection against the metadata, for the file of `job`
/// compiled by `who` (for messages):
///
/// - every reflected resource is one the metadata states (a binding, a
///   group's sampler-index buffer, a sampler heap), at the register and space
///   the metadata (or docs/hlsl-registers.md, for the heaps) gives;
/// - `Scope::File`: every binding of the metadata is reflected;
///   `Scope::EntryPoint(stage)`: every reflected binding lists `stage` in
///   its metadata `stages` (the visibility an engine gives it);
/// - every sampler global is the macro naming its heap element
///   (`#define s (nagaSamplerHeap[nagaGroup<g>SamplerIndexArray[slot]])`).
///
/// `map_register` turns a metadata register into the one the compiler
/// reports (identity for D3D; DXC's SPIR-V reflects `b3`/`t3` as binding 3).
pub fn check_registers(
    job: &Job,
    who: &str,
    reflected: &[Reflected],
    scope: Scope,
    map_register: impl Fn(&str) -> String,
) -> Vec<String> {
    let hlsl = std::fs::read_to_string(&job.path).unwrap();
    let mut errors = Vec::new();
    let find = |name: &str| reflected.iter().find(|r| r.name == name);
    for b in &job.bindings {
        let name = resource_name(b);
        let h = &b.hlsl;
        match find(&name) {
            Some(r) => {
                let register = map_register(&h.register);
                if r.register != register || r.space != h.space {
                    errors.push(format!(
                        "{}: `{}`: metadata says {} space {}, {who} reflects {} space {}",
                        job.label, b.name, h.register, h.space, r.register, r.space
                    ));
                }
            }
            None if matches!(scope, Scope::File) => errors.push(format!(
                "{}: `{name}` ({}) not in {who}'s reflection",
                job.label, b.name
            )),
            None => {}
        }
        if is_sampler(b) {
            let heap = match b.kind {
                BindingKind::ComparisonSampler => "nagaComparisonSamplerHeap",
                _ => "nagaSamplerHeap",
            };
            let slot = h.sampler_index_slot.unwrap_or(u32::MAX);
            let alias = format!("#define {} ({heap}[{name}[{slot}]])", b.name);
            if !hlsl.lines().any(|l| l == alias) {
                errors.push(format!("{}: no `{alias}`", job.label));
            }
        }
    }
    for r in reflected {
        if let Some((heap, space)) = heaps().into_iter().find(|(h, _)| r.name == *h) {
            let register = map_register("s0");
            if r.register != register || r.space != space {
                errors.push(format!(
                    "{}: {who} reflects `{heap}` at {} space {}, not {register} space {space}",
                    job.label, r.register, r.space
                ));
            }
            continue;
        }
        let carriers: Vec<&Binding> = (job.bindings.iter())
            .filter(|b| resource_name(b) == r.name)
            .collect();
        if carriers.is_empty() {
            errors.push(format!(
                "{}: {who} reflects `{}` ({} space {}), which the metadata does not state",
                job.label, r.name, r.register, r.space
            ));
        } else if let Scope::EntryPoint(stage) = scope
            && !carriers.iter().any(|b| b.stages.contains(&stage))
        {
            errors.push(format!(
                "{}: {who} reflects `{}` in a {stage:?} entry point, but the metadata's \
                 `stages` of {} leave it out",
                job.label,
                r.name,
                (carriers.iter().map(|b| b.name.as_str()))
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
    }
    errors
}

/// A negative control: WGSL whose HLSL, as naga writes it with weft's options
/// but without weft's rewrites (`raw`), holds one construct a D3D-side
/// compiler rejects; `weft` is what weft emits for it
/// (`backends::emit_hlsl`). A compiler check that accepted a `raw` file
/// could not catch that class in `generated/`.
pub struct Control {
    pub name: &'static str,
    pub raw: String,
    pub weft: String,
}

/// A fragment shader `fs_main` per class: a `select` with a `vec4<bool>`
/// condition (naga writes `c ? a : b`, which HLSL 2021 rejects and Slang
/// deprecates: hlsl_select.rs), and a sampler (naga writes
/// `static const SamplerState s = nagaSamplerHeap[…]`, which Slang rejects:
/// hlsl_samplers.rs).
pub fn controls() -> Vec<Control> {
    const VECTOR_SELECT: &str = "
@fragment fn fs_main(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
    return select(vec4(0.0, 0.0, 0.0, 1.0), p, p > vec4(0.5));
}";
    const SAMPLER_HEAP: &str = "
@group(1) @binding(0) var t: texture_2d<f32>;
@group(1) @binding(1) var s: sampler;
@fragment fn fs_main(@builtin(position) p: vec4<f32>) -> @location(0) vec4<f32> {
    return textureSample(t, s, p.xy);
}";
    [
        ("vector_select", VECTOR_SELECT, "? p :"),
        (
            "sampler_heap",
            SAMPLER_HEAP,
            "static const SamplerState s = ",
        ),
    ]
    .into_iter()
    .map(|(name, wgsl, construct)| {
        let module = naga::front::wgsl::parse_str(wgsl).unwrap();
        let info = weft_compiler::compose::validator()
            .validate(&module)
            .unwrap();
        let options = weft_compiler::engine_binding::hlsl_options(&module);
        let pipeline = naga::back::hlsl::PipelineOptions { entry_point: None };
        let mut raw = String::new();
        naga::back::hlsl::Writer::new(&mut raw, &options, &pipeline)
            .write(&module, &info, None)
            .unwrap();
        assert!(
            raw.contains(construct),
            "naga no longer writes `{construct}` for the {name} control:\n{raw}"
        );
        let weft = weft_compiler::backends::emit_hlsl(&module, &info).unwrap();
        assert!(!weft.contains(construct), "weft's HLSL for {name}:\n{weft}");
        Control { name, raw, weft }
    })
    .collect()
}
