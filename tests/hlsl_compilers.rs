//! Every HLSL entry point of the committed `generated/` tree through Slang
//! (`slangc`, a D3D-side compiler no one here wrote), with its register
//! reflection checked against the metadata.
//!
//! Slang rejects the two classes of HLSL other D3D compilers disagree on:
//! a `static const SamplerState` initialised from naga's sampler heap (Slang:
//! "static const global initializer must be a compile-time constant"), and a
//! `?:` with a vector condition, which HLSL 2021 (DXC's default) rejects and
//! Slang deprecates (warning 30056, made an error here). DXC and FXC are
//! Windows programs: docs/engine-interface.md says how to run them.
//!
//! `slangc` ships in PyPI's `slangtorch` Linux wheel (.ci/run installs it);
//! without it this test fails and says how to install it.

#[path = "support/shaders.rs"]
mod shaders;

use rayon::prelude::*;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;
use weft_meta::scene::SceneMetadata;
use weft_meta::{Binding, BindingKind, MaterialMetadata, Stage};

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

const INSTALL: &str = "python3 -m venv target/tools/slang && \
    target/tools/slang/bin/pip install --no-deps slangtorch==1.3.22";

/// `$WEFT_SLANGC` (relative to the repository root), else `slangc` on PATH,
/// else where .ci/run installs it.
fn slangc() -> PathBuf {
    if let Some(p) = std::env::var_os("WEFT_SLANGC") {
        // A relative path is taken from the repository root, where it was
        // typed (the test itself runs in its package folder).
        return repo().join(p);
    }
    let on_path = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|p| p.join("slangc"))
            .find(|p| p.is_file())
    });
    let venv_lib = repo().join("target/tools/slang/lib");
    let in_venv = std::fs::read_dir(&venv_lib).ok().and_then(|d| {
        d.flatten()
            .map(|py| py.path().join("site-packages/slangtorch/bin/slangc"))
            .find(|p| p.is_file())
    });
    on_path.or(in_venv).unwrap_or_else(|| {
        panic!(
            "`slangc` not found: install it with `{INSTALL}` (from the repository root; see \
             .ci/run), put it on PATH, or set WEFT_SLANGC to its path"
        )
    })
}

/// One HLSL file with the entry points and bindings its metadata states.
struct Job {
    label: String,
    path: PathBuf,
    entries: Vec<(String, Stage)>,
    bindings: Vec<Binding>,
}

fn jobs() -> Vec<Job> {
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

/// Compiles every entry point of one file to HLSL (Slang's D3D target); the
/// reflection (JSON) on success, Slang's messages on failure.
fn compile(slangc: &Path, job: &Job, out: &Path) -> Result<Value, String> {
    let mut cmd = Command::new(slangc);
    cmd.arg(&job.path).args(["-target", "hlsl"]);
    for (name, stage) in &job.entries {
        let stage = match stage {
            Stage::Vertex => "vertex",
            Stage::Fragment => "fragment",
            Stage::Compute => "compute",
        };
        cmd.args(["-entry", name, "-stage", stage]);
    }
    // 30056: "non-short-circuiting `?:` is deprecated" (a vector condition).
    cmd.args(["-warnings-as-errors", "30056", "-reflection-json"])
        .arg(out);
    let o = cmd
        .output()
        .map_err(|e| format!("{}: {e}", slangc.display()))?;
    if !o.status.success() {
        let text = String::from_utf8_lossy(&o.stderr);
        let head: String = text.lines().take(12).collect::<Vec<_>>().join("\n");
        return Err(format!("Slang rejects {}:\n{head}", job.label));
    }
    let text = std::fs::read_to_string(out).map_err(|e| format!("{}: {e}", job.label))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: reflection: {e}", job.label))
}

/// The metadata's `hlsl` register of every binding against Slang's reflection.
/// Samplers live in naga's heap: their register is the group's sampler-index
/// buffer, and the HLSL must alias heap element `index[sampler_index_slot]`.
fn check_registers(job: &Job, reflection: &Value) -> Vec<String> {
    let hlsl = std::fs::read_to_string(&job.path).unwrap();
    let params = reflection["parameters"]
        .as_array()
        .cloned()
        .unwrap_or_default();
    let find = |name: &str| params.iter().find(|p| p["name"] == name);
    let mut errors = Vec::new();
    for b in &job.bindings {
        let h = &b.hlsl;
        let sampler = matches!(
            b.kind,
            BindingKind::Sampler | BindingKind::ComparisonSampler
        );
        let name = if sampler {
            format!("nagaGroup{}SamplerIndexArray", h.space)
        } else {
            b.name.clone()
        };
        let Some(p) = find(&name) else {
            errors.push(format!(
                "{}: `{name}` ({}) not in Slang's reflection",
                job.label, b.name
            ));
            continue;
        };
        let binding = &p["binding"];
        let letter = match binding["kind"].as_str() {
            Some("constantBuffer") => "b",
            Some("shaderResource") => "t",
            Some("unorderedAccess") => "u",
            Some("samplerState") => "s",
            other => {
                errors.push(format!(
                    "{}: `{name}` has binding kind {other:?}",
                    job.label
                ));
                continue;
            }
        };
        let register = format!("{letter}{}", binding["index"]);
        let space = binding["space"].as_u64().unwrap_or(0);
        if register != h.register || space != u64::from(h.space) {
            errors.push(format!(
                "{}: `{}`: metadata says {} space {}, Slang reflects {register} space {space}",
                job.label, b.name, h.register, h.space
            ));
        }
        if sampler {
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
    let heaps = [
        (
            "nagaSamplerHeap",
            weft_compiler::backends::HLSL_SAMPLER_HEAP_SPACE,
        ),
        (
            "nagaComparisonSamplerHeap",
            weft_compiler::backends::HLSL_COMPARISON_SAMPLER_HEAP_SPACE,
        ),
    ];
    for (heap, space) in heaps {
        if let Some(p) = find(heap) {
            let b = &p["binding"];
            if b["kind"] != "samplerState" || b["index"] != 0 || b["space"] != u64::from(space) {
                errors.push(format!(
                    "{}: `{heap}` is at {b}, not s0 space{space}",
                    job.label
                ));
            }
        }
    }
    errors
}

#[test]
fn every_hlsl_entry_point_compiles_with_slang_and_its_registers_match() {
    let slangc = slangc();
    let jobs = jobs();
    let tmp = tempfile::tempdir().unwrap();
    let results: Vec<Result<Vec<String>, String>> = jobs
        .par_iter()
        .enumerate()
        .map(|(i, job)| {
            let out = tmp.path().join(format!("{i}.json"));
            compile(&slangc, job, &out).map(|r| check_registers(job, &r))
        })
        .collect();
    let entries: usize = jobs.iter().map(|j| j.entries.len()).sum();
    let rejected: usize = (jobs.iter().zip(&results))
        .filter(|(_, r)| r.is_err())
        .map(|(j, _)| j.entries.len())
        .sum();
    let mut messages: Vec<String> = Vec::new();
    for r in results {
        match r {
            Ok(errors) => messages.extend(errors),
            Err(e) => messages.push(e),
        }
    }
    assert!(
        messages.is_empty(),
        "Slang rejects {rejected} of {entries} HLSL entry points ({} files); register or \
         compile errors:\n{}",
        jobs.len(),
        messages[..messages.len().min(20)].join("\n")
    );
    assert!(
        jobs.iter().any(|j| j.label.starts_with("scenes/")) && entries >= 400,
        "expected every material variant's and scene shader's HLSL, got {entries} entry points"
    );
}
