//! One child process per GPU family. The loader reads `VK_ICD_FILENAMES` and
//! RADV reads `RADV_FORCE_FAMILY` from the environment, so the parent sets
//! them on a child (setting them in a running, multi-threaded process is
//! unsound) that compiles the family's pipelines and prints them as JSON.

use crate::device::NullDevice;
use crate::error::{Error, Result};
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

/// Runs `request` in a child with RADV's manifest `icd` and the family set.
pub fn run_child(worker: &WorkerCommand, icd: &Path, request: &Request) -> Result<FamilyStats> {
    let mut child = Command::new(&worker.program)
        .args(&worker.args)
        // The loader's old and new names for the driver list (the newer wins where known).
        .env("VK_ICD_FILENAMES", icd)
        .env("VK_DRIVER_FILES", icd)
        .env("RADV_FORCE_FAMILY", &request.family)
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
        stdin
            .write_all(&body)
            .map_err(|e| Error::Worker(format!("writing the request to the worker: {e}")))?;
    }
    let out = child
        .wait_with_output()
        .map_err(|e| Error::Worker(format!("waiting for the worker: {e}")))?;
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        return Err(Error::Worker(format!(
            "compiling for {} failed ({}): {}",
            request.family,
            out.status,
            stderr.trim()
        )));
    }
    serde_json::from_slice(&out.stdout).map_err(|e| {
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
    if env_family != request.family {
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
