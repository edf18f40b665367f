//! One child process per GPU family. The loader reads `VK_ICD_FILENAMES` and
//! RADV reads `RADV_FORCE_FAMILY` from the environment, so the parent sets
//! them on a child (setting them in a running, multi-threaded process is
//! unsound) that compiles the family's pipelines and prints them as JSON.

use crate::device::NullDevice;
use crate::error::{Error, Result};
use crate::family;
use crate::jobs::{Selection, library_jobs};
use crate::record::FamilyStats;
use serde::{Deserialize, Serialize};
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// What the parent asks a child: one family, one library.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Request {
    /// The `RADV_FORCE_FAMILY` value the child runs under.
    pub family: String,
    /// The generated library.
    pub generated: PathBuf,
    /// Which pipelines.
    pub selection: Selection,
    /// Capture each executable's ISA disassembly.
    pub disassembly: bool,
}

/// How to start a child that calls [`serve_stdio`]: a program and its arguments
/// (the crate's `weft-gpu-stats` binary, or a tool re-executing itself).
#[derive(Clone, Debug)]
pub struct WorkerCommand {
    /// The executable.
    pub program: PathBuf,
    /// Arguments that make it serve one request.
    pub args: Vec<String>,
}

/// Runs `request` in a child with RADV's manifest `icd` and the family set,
/// under each of the family's RADV spellings in turn until this Mesa knows
/// one ([`crate::family`]); the figures carry `request.family` either way.
pub fn run_child(worker: &WorkerCommand, icd: &Path, request: &Request) -> Result<FamilyStats> {
    let spellings = family::radv_spellings(&request.family);
    let mut unknown = Vec::new();
    for spelling in &spellings {
        match run_child_as(worker, icd, request, spelling)? {
            Attempt::Done(stats) => return Ok(stats),
            Attempt::UnknownFamily(stderr) => unknown.push(format!("`{spelling}`: {stderr}")),
        }
    }
    Err(Error::Worker(format!(
        "this Mesa's RADV knows the GPU family {} under none of its names ({}): {}. \
         Update `{}`, or ask for a family this Mesa has (weft's defaults: {})",
        request.family,
        spellings.join(", "),
        unknown.join("; "),
        crate::RADV_PACKAGE,
        crate::DEFAULT_FAMILIES.join(", "),
    )))
}

/// How one child run ended, when it did not fail outright.
enum Attempt {
    Done(FamilyStats),
    /// RADV rejected the `RADV_FORCE_FAMILY` value (its message).
    UnknownFamily(String),
}

fn run_child_as(
    worker: &WorkerCommand,
    icd: &Path,
    request: &Request,
    radv_family: &str,
) -> Result<Attempt> {
    let mut child = Command::new(&worker.program)
        .args(&worker.args)
        // The loader's old and new names for the driver list (the newer wins where known).
        .env("VK_ICD_FILENAMES", icd)
        .env("VK_DRIVER_FILES", icd)
        .env("RADV_FORCE_FAMILY", radv_family)
        // No on-disk cache: every figure comes from a fresh compile.
        .env("MESA_SHADER_CACHE_DISABLE", "true")
        .env("MESA_GLSL_CACHE_DISABLE", "true")
        // Mesa's device-select layer has nothing to select on a null device.
        .env("NODEVICE_SELECT", "1")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| {
            Error::Worker(format!(
                "starting the worker {}: {e}",
                worker.program.display()
            ))
        })?;
    let body = serde_json::to_vec(request).map_err(|e| Error::Worker(e.to_string()))?;
    if let Some(mut stdin) = child.stdin.take() {
        // A child that RADV aborts early may close its end first: its exit says why.
        let _ = stdin.write_all(&body);
    }
    let out = child
        .wait_with_output()
        .map_err(|e| Error::Worker(format!("waiting for the worker: {e}")))?;
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        if family::is_unknown_family(&stderr) {
            return Ok(Attempt::UnknownFamily(stderr.trim().to_string()));
        }
        return Err(Error::Worker(format!(
            "compiling for {} (RADV_FORCE_FAMILY={radv_family}) failed ({}): {}",
            request.family,
            out.status,
            stderr.trim()
        )));
    }
    serde_json::from_slice(&out.stdout)
        .map(Attempt::Done)
        .map_err(|e| {
            Error::Worker(format!(
                "the worker for {} printed no statistics ({e}); its messages: {}",
                request.family,
                stderr.trim()
            ))
        })
}

/// The child's side: reads a [`Request`] from stdin, compiles, prints
/// [`FamilyStats`] as JSON on stdout. Returns the process exit code (errors go to stderr).
pub fn serve_stdio() -> i32 {
    let mut input = Vec::new();
    let result = std::io::stdin()
        .read_to_end(&mut input)
        .map_err(|e| Error::Worker(format!("reading the request: {e}")))
        .and_then(|_| {
            serde_json::from_slice::<Request>(&input)
                .map_err(|e| Error::Worker(format!("not a request: {e}")))
        })
        .and_then(|r| serve(&r));
    match result {
        Ok(stats) => match serde_json::to_writer(std::io::stdout().lock(), &stats) {
            Ok(()) => 0,
            Err(e) => {
                eprintln!("weft-gpu-stats: writing the statistics: {e}");
                1
            }
        },
        Err(e) => {
            eprintln!("weft-gpu-stats: {e}");
            1
        }
    }
}

/// Compiles every selected pipeline for the family this process's environment holds.
pub fn serve(request: &Request) -> Result<FamilyStats> {
    // The family comes from the environment; refuse a request for another one
    // rather than label one family's figures with another's name.
    let env_family = std::env::var("RADV_FORCE_FAMILY").unwrap_or_default();
    if !family::radv_spellings(&request.family).contains(&env_family.as_str()) {
        return Err(Error::Worker(format!(
            "asked for {} but RADV_FORCE_FAMILY is `{env_family}`: start the worker through \
             weft_gpu_stats::collect",
            request.family
        )));
    }
    let jobs = library_jobs(&request.generated, &request.selection)?;
    let dev = NullDevice::open()?;
    let mut pipelines = Vec::with_capacity(jobs.len());
    for job in &jobs {
        pipelines.push(crate::compile::compile(
            &dev,
            &request.family,
            job,
            request.disassembly,
        )?);
    }
    Ok(FamilyStats {
        family: request.family.clone(),
        device_name: dev.device_name.clone(),
        driver_info: dev.driver_info.clone(),
        pipelines,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::jobs::Selection;

    /// A stand-in worker: a shell script that behaves as RADV does on a Mesa
    /// that knows RDNA3 only as `known` (aborting with "radv: Unknown family"
    /// otherwise) and prints empty statistics with the family it was asked for.
    fn fake_worker(dir: &Path, known: &str) -> WorkerCommand {
        let script = dir.join(format!("worker-{known}.sh"));
        std::fs::write(
            &script,
            format!(
                "cat > /dev/null\n\
                 if [ \"$RADV_FORCE_FAMILY\" != {known} ]; then\n\
                 echo \"radv: Unknown family: $RADV_FORCE_FAMILY\" >&2; kill -ABRT $$\n\
                 fi\n\
                 printf '{{\"family\":\"gfx1100\",\"device_name\":\"Null hardware (RADV %s)\",\
                 \"driver_info\":\"Mesa\",\"pipelines\":[]}}' \"$RADV_FORCE_FAMILY\"\n"
            ),
        )
        .unwrap();
        WorkerCommand {
            program: "sh".into(),
            args: vec![script.display().to_string()],
        }
    }

    #[test]
    fn rdna3_compiles_under_whichever_name_this_mesa_knows() {
        let dir = std::env::temp_dir().join(format!("weft-gpu-family-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let request = Request {
            family: "gfx1100".into(),
            generated: dir.clone(),
            selection: Selection::default(),
            disassembly: false,
        };
        let icd = dir.join("radeon_icd.json");
        for known in ["gfx1100", "navi31"] {
            let stats = run_child(&fake_worker(&dir, known), &icd, &request).unwrap();
            assert_eq!(stats.family, "gfx1100", "weft's name whatever RADV's");
            assert_eq!(stats.device_name, format!("Null hardware (RADV {known})"));
        }
        let e = run_child(&fake_worker(&dir, "navi99"), &icd, &request)
            .expect_err("no name known")
            .to_string();
        for needed in [
            "gfx1100, navi31",
            "Unknown family: navi31",
            crate::RADV_PACKAGE,
        ] {
            assert!(e.contains(needed), "{needed} in: {e}");
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
