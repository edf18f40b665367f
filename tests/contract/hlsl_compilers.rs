//! Every HLSL entry point of the committed `generated/` tree through Slang
//! (`slangc`, a D3D-side compiler no one here wrote), with its register
//! reflection checked against the metadata.
//!
//! Slang rejects the two classes of HLSL other D3D compilers disagree on
//! (negative controls below show it does, on HLSL as naga writes it):
//! a `static const SamplerState` initialised from naga's sampler heap (Slang:
//! "static const global initializer must be a compile-time constant"), and a
//! `?:` with a vector condition, which HLSL 2021 (DXC's default) rejects and
//! Slang deprecates (warning 30056, made an error here). DXC and FXC run
//! under wine in `tests/contract/hlsl_d3d.rs`.
//!
//! Files go through `slangc` eight to a run (each its own translation unit;
//! Slang's start-up is most of a one-file run), and a batch that fails in
//! any way is run again file by file, so every message names one file.
//!
//! `slangc` ships in PyPI's `slangtorch` Linux wheel (.ci/run installs it);
//! without it this test fails and says how to install it.

use crate::hlsl;
use crate::hlsl::{Job, Reflected, Scope};
use rayon::prelude::*;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;
use weft_meta::Stage;
use weft_tests::repo;

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

/// Files per `slangc` run. Slang spends ~0.4 s of every run loading its core
/// module and ~0.1 s per file compiling, so batches cut this test's time by
/// more than half.
const BATCH: usize = 8;

/// `jobs` in batches of at most `BATCH`, in order, no two files of a batch
/// with the same file name: Slang names a translation unit after its file,
/// and two of one name in a run abort it ("The key already exists in
/// Dictionary"; e.g. `gauze/fast.normal_map-off.hlsl` beside
/// `glitter/fast.normal_map-off.hlsl`).
fn batches(jobs: &[Job]) -> Vec<Vec<&Job>> {
    let mut batches: Vec<Vec<&Job>> = Vec::new();
    for job in jobs {
        let name = job.path.file_name();
        let open = (batches.iter_mut())
            .find(|b| b.len() < BATCH && b.iter().all(|other| other.path.file_name() != name));
        match open {
            Some(batch) => batch.push(job),
            None => batches.push(vec![job]),
        }
    }
    batches
}

/// Compiles every entry point of `jobs` (each file its own translation unit)
/// to HLSL (Slang's D3D target) in one run; the reflection (JSON) on
/// success, Slang's messages on failure.
fn compile(slangc: &Path, jobs: &[&Job], out: &Path) -> Result<Value, String> {
    let mut cmd = Command::new(slangc);
    for job in jobs {
        cmd.arg(&job.path);
        for (name, stage) in &job.entries {
            let stage = match stage {
                Stage::Vertex => "vertex",
                Stage::Fragment => "fragment",
                Stage::Compute => "compute",
            };
            cmd.args(["-entry", name, "-stage", stage]);
        }
    }
    // 30056: "non-short-circuiting `?:` is deprecated" (a vector condition).
    // The generated code goes to stdout, unread: the run must still lower
    // every entry point to HLSL, which is where Slang's legalisation fails.
    cmd.args([
        "-target",
        "hlsl",
        "-warnings-as-errors",
        "30056",
        "-reflection-json",
    ])
    .arg(out)
    .stdout(std::process::Stdio::null());
    let o = cmd
        .output()
        .map_err(|e| format!("{}: {e}", slangc.display()))?;
    let label = || {
        (jobs.iter().map(|j| j.label.as_str()))
            .collect::<Vec<_>>()
            .join(", ")
    };
    if !o.status.success() {
        let text = String::from_utf8_lossy(&o.stderr);
        let head: String = text.lines().take(12).collect::<Vec<_>>().join("\n");
        return Err(format!("Slang rejects {}:\n{head}", label()));
    }
    let text = std::fs::read_to_string(out).map_err(|e| format!("{}: {e}", label()))?;
    serde_json::from_str(&text).map_err(|e| format!("{}: reflection: {e}", label()))
}

/// One file alone through Slang: its register errors (none when it
/// passes), or Slang's rejection.
fn compile_and_check(slangc: &Path, job: &Job, out: &Path) -> Result<Vec<String>, String> {
    let reflection = compile(slangc, &[job], out)?;
    let params = reflection["parameters"]
        .as_array()
        .cloned()
        .unwrap_or_default();
    Ok(check(job, &params))
}

/// A batch of files through one Slang run, each checked against its own
/// slice of the reflection; a batch that fails in any way is retried file
/// by file, so every message names one file and a batch-only failure (a
/// Slang quirk across translation units) never fails the test.
///
/// Slang lists the global parameters of each translation unit in
/// command-line order, so the reflection is cut at each file's count of
/// `register(` declarations. A wrong cut cannot pass: each slice is checked
/// against its file's metadata, and every name in it must be declared in
/// that file's text.
fn compile_batch(slangc: &Path, jobs: &[&Job], out: &Path) -> Vec<Result<Vec<String>, String>> {
    let batch_passes = || -> Option<()> {
        let reflection = compile(slangc, jobs, out).ok()?;
        let params = reflection["parameters"].as_array()?;
        let mut rest = params.as_slice();
        for job in jobs {
            let text = std::fs::read_to_string(&job.path).ok()?;
            let declared = text.lines().filter(|l| l.contains("register(")).count();
            let (mine, others) = rest.split_at_checked(declared)?;
            rest = others;
            let declares = |p: &Value| {
                let name = p["name"].as_str().unwrap_or_default();
                text.lines()
                    .any(|l| l.contains("register(") && l.contains(name))
            };
            if !mine.iter().all(declares) || !check(job, mine).is_empty() {
                return None;
            }
        }
        rest.is_empty().then_some(())
    };
    if jobs.len() > 1 && batch_passes().is_some() {
        return vec![Ok(Vec::new()); jobs.len()];
    }
    (jobs.iter())
        .map(|job| compile_and_check(slangc, job, out))
        .collect()
}

/// Slang's reflection (JSON `parameters`, every declared resource) as
/// bindings; the metadata is checked against it with `hlsl::check_registers`,
/// every binding required.
fn reflected(job: &Job, params: &[Value]) -> Result<Vec<Reflected>, String> {
    let mut out = Vec::new();
    for p in params {
        let name = p["name"].as_str().unwrap_or_default().to_string();
        let binding = &p["binding"];
        let letter = match binding["kind"].as_str() {
            Some("constantBuffer") => "b",
            Some("shaderResource") => "t",
            Some("unorderedAccess") => "u",
            Some("samplerState") => "s",
            other => {
                return Err(format!(
                    "{}: `{name}` has binding kind {other:?}",
                    job.label
                ));
            }
        };
        out.push(Reflected {
            name,
            register: format!("{letter}{}", binding["index"]),
            space: binding["space"].as_u64().unwrap_or(0) as u32,
        });
    }
    Ok(out)
}

fn check(job: &Job, params: &[Value]) -> Vec<String> {
    match reflected(job, params) {
        Ok(r) => hlsl::check_registers(job, "Slang", &r, Scope::File, str::to_string),
        Err(e) => vec![e],
    }
}

#[test]
fn every_hlsl_entry_point_compiles_with_slang_and_its_registers_match() {
    let slangc = slangc();
    let jobs = hlsl::jobs();
    let tmp = tempfile::tempdir().unwrap();
    let batches = batches(&jobs);
    let results: Vec<(&Job, Result<Vec<String>, String>)> = batches
        .par_iter()
        .enumerate()
        .flat_map_iter(|(i, batch)| {
            let out = tmp.path().join(format!("{i}.json"));
            batch
                .iter()
                .copied()
                .zip(compile_batch(&slangc, batch, &out))
        })
        .collect();
    let entries = hlsl::assert_complete(&jobs);
    let rejected: usize = (results.iter())
        .filter(|(_, r)| r.is_err())
        .map(|(j, _)| j.entries.len())
        .sum();
    let mut messages: Vec<String> = Vec::new();
    for (_, r) in results {
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
}

/// Both classes this test exists for, as naga writes them (`hlsl::controls`):
/// Slang must reject each, and accept weft's HLSL for the same shader.
#[test]
fn slang_rejects_naga_vector_ternaries_and_sampler_heap_constants() {
    let slangc = slangc();
    let tmp = tempfile::tempdir().unwrap();
    for c in hlsl::controls() {
        for (kind, text) in [("raw", &c.raw), ("weft", &c.weft)] {
            let path = tmp.path().join(format!("{}.{kind}.hlsl", c.name));
            std::fs::write(&path, text).unwrap();
            let job = Job {
                label: format!("{} ({kind})", c.name),
                path,
                entries: vec![("fs_main".to_string(), Stage::Fragment)],
                bindings: Vec::new(),
            };
            let out = tmp.path().join(format!("{}.{kind}.json", c.name));
            let result = compile(&slangc, &[&job], &out);
            match (kind, result) {
                ("weft", Err(e)) => panic!("{e}"),
                ("raw", Ok(_)) => panic!(
                    "Slang accepts naga's {} HLSL: this test could not catch that class",
                    c.name
                ),
                ("raw", Err(e)) => {
                    let code = match c.name {
                        "vector_select" => "30056",
                        _ => "31226",
                    };
                    assert!(
                        e.contains(code),
                        "Slang rejects {}, but not with {code}:\n{e}",
                        c.name
                    );
                }
                _ => {}
            }
        }
    }
}
