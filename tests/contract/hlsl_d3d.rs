//! Every HLSL entry point of the committed `generated/` tree through the
//! D3D-side compilers that ship only as Windows DLLs, run under wine by
//! `tools/d3d-compile` (one process per mode for every entry point: wine
//! starts slowly), each entry point in four modes, one test each:
//!
//! - DXC 1.9 at its defaults (HLSL 2021) to DXIL, `vs_6_0`/`ps_6_0`: the
//!   DXIL must carry the validator's hash, and every resource
//!   `ID3D12ShaderReflection` (through `IDxcUtils::CreateReflection`) reports
//!   must be a binding the metadata states, at its `bindings[].hlsl` register
//!   and space, with the entry point's stage in its `stages`
//!   (`hlsl::check_registers`; the full set of declarations is Slang's check,
//!   since these compilers drop what an entry point does not use);
//! - DXC `-spirv`: the module's DescriptorSet/Binding decorations must be
//!   DXC's mapping of those registers (space = set, register number = binding);
//! - DXC `-HV 2016` to DXIL, registers as above;
//! - FXC (`d3dcompiler_47.dll`) `vs_5_1`/`ps_5_1` at its defaults, registers
//!   from `D3DReflect` (`ID3D12ShaderReflection`, which has register spaces).
//!
//! Negative controls run in the same process (`hlsl::controls`): naga's own
//! vector-condition `?:` must be rejected by DXC's HLSL 2021 (the class
//! weft's `hlsl_select.rs` rewrites; a compiler that silently accepted it
//! fails this test rather than passing it), and weft's HLSL for the same
//! shaders accepted in every mode. The other class, the sampler-heap
//! `static const`, only Slang rejects: `tests/contract/hlsl_compilers.rs`.
//!
//! Needs wine (Debian `wine64`), MinGW-w64 (`g++-mingw-w64-x86-64-win32`, to
//! build the driver from its source) and the DLLs that
//! `tools/d3d-compile/install.sh` fetches from PyPI into `target/tools/d3d/`
//! (.ci/run runs it); without them this test fails and says so.

use crate::hlsl;
use crate::hlsl::{Reflected, Scope};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;
use weft_meta::Stage;
use weft_tests::repo;

const INSTALL: &str = "apt-get install wine64 g++-mingw-w64-x86-64-win32 && \
    tools/d3d-compile/install.sh";

/// Where install.sh put the DLLs and the driver: `$WEFT_D3D_DIR` (relative to
/// the repository root), else `target/tools/d3d`.
fn tools_dir() -> PathBuf {
    match std::env::var_os("WEFT_D3D_DIR") {
        Some(p) => repo().join(p),
        None => repo().join("target/tools/d3d"),
    }
}

/// `$WEFT_WINE`, else `wine64` or `wine` on PATH, else Debian's
/// `/usr/lib/wine/wine64` (bookworm's `wine64` package puts it only there).
fn wine() -> PathBuf {
    if let Some(p) = std::env::var_os("WEFT_WINE") {
        let p = PathBuf::from(p);
        assert!(
            p.is_file(),
            "WEFT_WINE={} is not a file: install wine and the D3D compilers with `{INSTALL}`",
            p.display()
        );
        return p;
    }
    let on_path = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .flat_map(|p| [p.join("wine64"), p.join("wine")])
            .find(|p| p.is_file())
    });
    let debian = PathBuf::from("/usr/lib/wine/wine64");
    on_path
        .or(debian.is_file().then_some(debian))
        .unwrap_or_else(|| {
            panic!(
                "wine not found: install it and the D3D compilers with `{INSTALL}` (from the \
                 repository root; see .ci/run), or set WEFT_WINE to its path"
            )
        })
}

/// The driver, built from `tools/d3d-compile/d3d_compile.cpp` when missing or
/// older than its source.
fn driver(dir: &Path) -> PathBuf {
    let exe = dir.join("weft-d3d-compile.exe");
    let source = repo().join("tools/d3d-compile/d3d_compile.cpp");
    let modified = |p: &Path| std::fs::metadata(p).and_then(|m| m.modified()).ok();
    if modified(&exe).is_none() || modified(&exe) < modified(&source) {
        let status = Command::new("bash")
            .arg(repo().join("tools/d3d-compile/build.sh"))
            .arg(&exe)
            .status()
            .unwrap_or_else(|e| panic!("tools/d3d-compile/build.sh: {e}"));
        assert!(
            status.success(),
            "building the D3D driver failed (needs MinGW-w64: `{INSTALL}`)"
        );
    }
    exe
}

/// One compiler configuration every entry point goes through.
struct Mode {
    name: &'static str,
    tool: &'static str,
    shader_model: &'static str,
    args: &'static [&'static str],
}

const MODES: [Mode; 4] = [
    Mode {
        name: "DXC (HLSL 2021) -> DXIL",
        tool: "dxc",
        shader_model: "6_0",
        args: &[],
    },
    Mode {
        name: "DXC (HLSL 2021) -spirv",
        tool: "dxc",
        shader_model: "6_0",
        args: &["-spirv"],
    },
    Mode {
        name: "DXC -HV 2016 -> DXIL",
        tool: "dxc",
        shader_model: "6_0",
        args: &["-HV", "2016"],
    },
    Mode {
        name: "FXC SM 5.1",
        tool: "fxc",
        shader_model: "5_1",
        args: &[],
    },
];

fn profile(stage: Stage, shader_model: &str) -> String {
    let prefix = match stage {
        Stage::Vertex => "vs",
        Stage::Fragment => "ps",
        Stage::Compute => "cs",
    };
    format!("{prefix}_{shader_model}")
}

/// The driver's result for one job.
enum Outcome {
    Ok {
        resources: Vec<Reflected>,
        warnings: String,
    },
    Error(String),
}

fn unescape(s: &str) -> String {
    let mut out = String::new();
    let mut chars = s.chars();
    while let Some(c) = chars.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        match chars.next() {
            Some('n') => out.push('\n'),
            Some('t') => out.push('\t'),
            Some(other) => out.push(other),
            None => {}
        }
    }
    out
}

fn parse_resources(text: &str) -> Result<Vec<Reflected>, String> {
    if text == "?" {
        return Err("no reflection".into());
    }
    (text.split(';').filter(|s| !s.is_empty()))
        .map(|item| {
            let f: Vec<&str> = item.split(':').collect();
            match f[..] {
                [name, register, space, _count] => Ok(Reflected {
                    name: name.to_string(),
                    register: register.to_string(),
                    space: space.parse().map_err(|_| format!("bad space in {item}"))?,
                }),
                _ => Err(format!("bad resource `{item}`")),
            }
        })
        .collect()
}

// One test per mode, so that each stays short (all four in one took 126 s).
#[test]
fn every_hlsl_entry_point_compiles_with_dxc_to_dxil_and_its_registers_match() {
    compiles_in_mode(0);
}

#[test]
fn every_hlsl_entry_point_compiles_with_dxc_to_spirv_and_its_registers_match() {
    compiles_in_mode(1);
}

#[test]
fn every_hlsl_entry_point_compiles_with_dxc_hlsl_2016_and_its_registers_match() {
    compiles_in_mode(2);
}

#[test]
fn every_hlsl_entry_point_compiles_with_fxc_and_its_registers_match() {
    compiles_in_mode(3);
}

/// Held while the driver is built and, when the wine prefix does not exist
/// yet, through the first run (which creates it): the tests above may run
/// at once.
static SETUP: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// Every entry point (and the negative controls) through `MODES[index]`.
fn compiles_in_mode(index: usize) {
    let mode = &MODES[index];
    let setup = SETUP.lock().unwrap_or_else(|e| e.into_inner());
    let dir = tools_dir();
    let dlls = dir.join("bin");
    for dll in ["dxcompiler.dll", "dxil.dll", "d3dcompiler_47.dll"] {
        assert!(
            dlls.join(dll).is_file(),
            "{} missing: install the D3D compilers with `{INSTALL}` (from the repository \
             root; see .ci/run), or set WEFT_D3D_DIR",
            dlls.join(dll).display()
        );
    }
    let wine = wine();
    let exe = driver(&dir);
    let prefix = dir.join("wineprefix");
    let _first_run = match prefix.is_dir() {
        true => {
            drop(setup);
            None
        }
        false => Some(setup),
    };
    let jobs = hlsl::jobs();
    let entries = hlsl::assert_complete(&jobs);

    // One line per (file, entry point); ids index `lines`.
    let tmp = tempfile::tempdir().unwrap();
    let mut list = String::new();
    let mut lines: Vec<(usize, String, Stage)> = Vec::new();
    for (j, job) in jobs.iter().enumerate() {
        for (entry, stage) in &job.entries {
            let mut fields = vec![
                lines.len().to_string(),
                mode.tool.to_string(),
                job.path.display().to_string(),
                entry.clone(),
                profile(*stage, mode.shader_model),
            ];
            fields.extend(mode.args.iter().map(|a| a.to_string()));
            list += &(fields.join("\t") + "\n");
            lines.push((j, entry.clone(), *stage));
        }
    }
    // The negative controls and weft's HLSL for them: naga's vector `?:` must
    // be rejected by DXC's HLSL 2021, weft's HLSL accepted by every mode.
    let mut controls: Vec<(usize, String, bool)> = Vec::new();
    for c in hlsl::controls() {
        for (kind, text) in [("raw", &c.raw), ("weft", &c.weft)] {
            let path = tmp.path().join(format!("{}.{kind}.hlsl", c.name));
            std::fs::write(&path, text).unwrap();
            // HLSL 2021: DXC's default, to DXIL and to SPIR-V.
            let hlsl_2021 = mode.tool == "dxc" && !mode.args.contains(&"-HV");
            let rejected = kind == "raw" && c.name == "vector_select" && hlsl_2021;
            if kind == "raw" && !rejected {
                continue;
            }
            let id = lines.len() + controls.len();
            let mut fields = vec![
                id.to_string(),
                mode.tool.to_string(),
                path.display().to_string(),
                "fs_main".to_string(),
                profile(Stage::Fragment, mode.shader_model),
            ];
            fields.extend(mode.args.iter().map(|a| a.to_string()));
            list += &(fields.join("\t") + "\n");
            let what = format!("{}: {} {kind}", mode.name, c.name);
            controls.push((id, what, !rejected));
        }
    }
    let list_path = tmp.path().join("jobs.txt");
    let results_path = tmp.path().join("results.txt");
    std::fs::write(&list_path, list).unwrap();

    // wine's output goes to a file, not a pipe: the first wine process
    // starts the prefix's wineserver, which inherits its output handles and
    // outlives it until every other wine process (the other modes) is done,
    // so reading a pipe to its end waited for them all.
    let log_path = tmp.path().join("wine.log");
    let log = std::fs::File::create(&log_path).unwrap();
    let start = Instant::now();
    let status = Command::new(&wine)
        .arg(&exe)
        .arg(&dlls)
        .arg(&list_path)
        .arg(&results_path)
        // One compiler thread: the modes run two at a time beside the
        // binary's other tests (the four alone: 71 s with one thread each,
        // 87 s with two).
        .arg("1")
        .env("WINEPREFIX", &prefix)
        .env("WINEDEBUG", "-all")
        // No Mono or Gecko installer prompts when the prefix is created.
        .env("WINEDLLOVERRIDES", "mscoree,mshtml=")
        .stdin(std::process::Stdio::null())
        .stdout(log.try_clone().unwrap())
        .stderr(log)
        .status()
        .unwrap_or_else(|e| panic!("{}: {e}", wine.display()));
    let seconds = start.elapsed().as_secs_f64();
    let text = std::fs::read_to_string(&results_path).unwrap_or_else(|e| {
        panic!(
            "the D3D driver wrote no results ({e}); wine exited with {status}:\n{}",
            std::fs::read_to_string(&log_path).unwrap_or_default()
        )
    });

    let mut results: BTreeMap<usize, Outcome> = BTreeMap::new();
    let mut header = "";
    for line in text.lines() {
        if let Some(h) = line.strip_prefix("# ") {
            header = h;
            continue;
        }
        let f: Vec<&str> = line.splitn(4, '\t').collect();
        let id: usize = f[0].parse().unwrap();
        let outcome = match f.get(1) {
            Some(&"ok") => match parse_resources(f.get(2).copied().unwrap_or("?")) {
                Ok(resources) => Outcome::Ok {
                    resources,
                    warnings: unescape(f.get(3).copied().unwrap_or("")),
                },
                Err(e) => Outcome::Error(e),
            },
            _ => Outcome::Error(unescape(&f[1..].join("\t"))),
        };
        results.insert(id, outcome);
    }
    assert!(
        header.starts_with("dxc 1.9 ") && header.ends_with("fxc loaded"),
        "the D3D driver found DXC and FXC as `{header}`, expected DXC 1.9 and FXC"
    );
    assert_eq!(
        results.len(),
        lines.len() + controls.len(),
        "the D3D driver answered {} of {} jobs",
        results.len(),
        lines.len() + controls.len()
    );

    for (id, what, accept) in &controls {
        match (&results[id], accept) {
            (Outcome::Ok { .. }, true) => {}
            (Outcome::Error(e), false) => assert!(
                e.contains("condition for short-circuiting ternary operator must be scalar"),
                "{what}: rejected, but not for its vector `?:`:\n{e}"
            ),
            (Outcome::Error(e), true) => panic!("{what}: rejected:\n{e}"),
            (Outcome::Ok { .. }, false) => panic!(
                "{what}: accepted, so this test could not catch the vector-condition `?:` \
                 weft's hlsl_select.rs rewrites"
            ),
        }
    }

    let mut passed = 0usize;
    // Per file, the resources some entry point reflects in some mode: a
    // metadata binding none does was dropped by every optimiser (reported,
    // not an error: its sample is dead in that variant).
    let mut seen: Vec<Vec<String>> = vec![Vec::new(); jobs.len()];
    let mut messages: Vec<String> = Vec::new();
    let mut warnings: BTreeMap<&str, usize> = BTreeMap::new();
    for (id, (j, entry, stage)) in lines.iter().enumerate() {
        let job = &jobs[*j];
        match &results[&id] {
            Outcome::Error(e) => {
                let head: String = e.lines().take(8).collect::<Vec<_>>().join("\n");
                messages.push(format!("{}: {} {entry}:\n{head}", mode.name, job.label));
            }
            Outcome::Ok {
                resources,
                warnings: w,
            } => {
                seen[*j].extend(resources.iter().map(|r| r.name.clone()));
                if !w.trim().is_empty() {
                    *warnings.entry(mode.name).or_default() += 1;
                }
                let scope = Scope::EntryPoint(*stage);
                let errors = if mode.args.contains(&"-spirv") {
                    // DXC's default HLSL → Vulkan mapping: set = space,
                    // binding = the register's number.
                    let vk = |r: &str| format!("vk{}", &r[1..]);
                    hlsl::check_registers(job, mode.name, resources, scope, vk)
                } else {
                    hlsl::check_registers(job, mode.name, resources, scope, str::to_string)
                };
                if errors.is_empty() {
                    passed += 1;
                }
                messages.extend(errors.into_iter().map(|e| format!("{e} ({entry})")));
            }
        }
    }
    let mut unused: Vec<String> = Vec::new();
    for (job, seen) in jobs.iter().zip(&seen) {
        for b in &job.bindings {
            if !seen.contains(&hlsl::resource_name(b)) {
                unused.push(format!("{}: {}", job.label, b.name));
            }
        }
    }
    let summary = format!("{}: {passed}/{entries}", mode.name);
    eprintln!(
        "{header}; {} files, {entries} entry points; {}; {seconds:.0} s under wine; \
         entry points with warnings: {warnings:?}; {} metadata bindings no compiler \
         keeps (dead in that variant){}",
        jobs.len(),
        summary,
        unused.len(),
        unused
            .first()
            .map(|u| format!(", e.g. {u}"))
            .unwrap_or_default()
    );
    assert!(
        messages.is_empty(),
        "{}; {} errors:\n{}",
        summary,
        messages.len(),
        messages[..messages.len().min(20)].join("\n")
    );
}

/// The register check itself, without wine: the metadata's own registers
/// pass, and a moved register, a resource the metadata does not state and a
/// resource in a stage its `stages` leave out are each reported.
#[test]
fn the_register_check_reports_moved_unknown_and_wrong_stage_resources() {
    let jobs = hlsl::jobs();
    let job = (jobs.iter())
        .find(|j| {
            j.bindings.iter().any(|b| b.stages == [Stage::Fragment])
                && j.entries.iter().any(|(_, s)| *s == Stage::Vertex)
        })
        .expect("a file with a fragment-only binding and a vertex entry point");
    let truth: Vec<Reflected> = (job.bindings.iter())
        .map(|b| Reflected {
            name: hlsl::resource_name(b),
            register: b.hlsl.register.clone(),
            space: b.hlsl.space,
        })
        .collect();
    let check = |r: &[Reflected], stage| {
        hlsl::check_registers(job, "test", r, Scope::EntryPoint(stage), str::to_string)
    };
    let fragment: Vec<Reflected> = (job.bindings.iter().zip(&truth))
        .filter(|(b, _)| b.stages.contains(&Stage::Fragment))
        .map(|(_, r)| r.clone())
        .collect();
    assert_eq!(check(&fragment, Stage::Fragment), Vec::<String>::new());

    let mut moved = fragment.clone();
    moved[0].register = format!("{}9", &moved[0].register[..1]);
    assert!(check(&moved, Stage::Fragment)[0].contains("metadata says"));

    let mut unknown = fragment.clone();
    unknown.push(Reflected {
        name: "not_in_metadata".into(),
        register: "t9".into(),
        space: 1,
    });
    assert!(check(&unknown, Stage::Fragment)[0].contains("does not state"));

    let b = (job.bindings.iter())
        .position(|b| b.stages == [Stage::Fragment])
        .unwrap();
    let errors = check(&truth[b..=b], Stage::Vertex);
    assert!(
        errors.iter().any(|e| e.contains("leave it out")),
        "{errors:?}"
    );
}
