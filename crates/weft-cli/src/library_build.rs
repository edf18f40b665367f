//! `weft build` (a library), `weft check` and `weft merge`: material files
//! found from the command line, built into a locked output folder (or only
//! checked), shard folders joined.

use crate::{Color, PRESERVED, lock_output, report};
use std::io::IsTerminal;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;
use weft_compiler::folder_build::{self, FolderBuildError};
use weft_compiler::ownership::{Input, check_apart};
use weft_compiler::{BuildOptions, BuildOutput};
use weft_front::{Diagnostics, SourceDb};

/// `weft build`'s arguments for a library (not `--scene`).
pub(crate) struct LibraryBuild {
    pub paths: Vec<PathBuf>,
    pub out: Option<PathBuf>,
    pub jobs: Option<usize>,
    pub force: bool,
    pub lock_timeout: Duration,
    pub shard: Option<weft_compiler::shard::Shard>,
    pub cache_dir: Option<PathBuf>,
    pub cache_verify: u8,
}

/// `weft build <materials> -o <out>`: the library built into `out`, which is
/// locked for the whole build and replaced atomically.
pub(crate) fn build_command(args: LibraryBuild, quiet: bool, color: Color) -> ExitCode {
    let LibraryBuild {
        paths,
        out,
        jobs,
        force,
        lock_timeout,
        shard,
        cache_dir,
        cache_verify,
    } = args;
    let out = out.unwrap_or_else(|| PathBuf::from("generated"));
    let started = std::time::Instant::now();
    let files = match material_files(&paths) {
        Ok(f) => f,
        Err((db, diags)) => {
            report(&db, &diags, color);
            return ExitCode::FAILURE;
        }
    };
    let options = BuildOptions {
        jobs,
        reuse_from: (!force).then(|| out.clone()),
        shard,
        cache_dir,
        cache_trust: weft_compiler::cache::CacheTrust {
            key: std::env::var_os("WEFT_CACHE_KEY")
                .filter(|k| !k.is_empty())
                .map(|k| k.as_encoded_bytes().to_vec()),
            verify_percent: cache_verify,
        },
        ..Default::default()
    };
    let root = files.root.as_deref();
    if let Err(e) = folder_build::check_inputs_apart(&files.paths, root, &out, &options) {
        eprintln!("error: {e}; nothing was written");
        return ExitCode::FAILURE;
    }
    // Locked for the whole build, so that no other build replaces the
    // folder while unchanged files are kept from it.
    let Some(lock) = lock_output(&out, lock_timeout, quiet) else {
        return ExitCode::FAILURE;
    };
    let progress = progress_printer(quiet);
    match folder_build::build_into(
        &files.paths,
        root,
        &lock,
        &options,
        &[],
        PRESERVED,
        &progress,
    ) {
        Ok(built) => {
            let result = &built.output;
            if let Some((db, warnings)) = &result.warnings {
                report(db, warnings, color);
            }
            if !quiet {
                println!(
                    "built {} material(s), {} variant(s), {} file(s) into {} in {:.2}s{}{}",
                    result.material_count(),
                    result.variant_count,
                    built.file_count,
                    out.display(),
                    started.elapsed().as_secs_f64(),
                    if result.reused.is_empty() {
                        String::new()
                    } else {
                        format!(" ({} unchanged)", result.reused.len())
                    },
                    if built.wrote {
                        ""
                    } else {
                        "; already up to date"
                    },
                );
                if options.cache_dir.is_some() {
                    println!(
                        "compile units: {} from the cache, {} compiled; {} compiled again \
                         to verify, {} refused (not signed with WEFT_CACHE_KEY)",
                        result.cache_hits,
                        result.cache_misses,
                        result.cache_verified,
                        result.cache_rejected
                    );
                }
            }
            ExitCode::SUCCESS
        }
        Err(FolderBuildError::Diagnostics(db, diags)) => {
            report(&db, &diags, color);
            ExitCode::FAILURE
        }
        Err(FolderBuildError::Io(e)) => {
            eprintln!(
                "error: cannot write `{}`: {e}; the old output is unchanged",
                out.display()
            );
            ExitCode::FAILURE
        }
    }
}

/// `weft check`: diagnostics only, nothing written.
pub(crate) fn check_command(paths: &[PathBuf], quiet: bool, color: Color) -> ExitCode {
    match build(paths, &BuildOptions::default(), quiet) {
        Ok(result) => {
            if let Some((db, warnings)) = &result.warnings {
                report(db, warnings, color);
            }
            if !quiet {
                println!(
                    "ok: {} material(s), {} variant(s)",
                    result.materials.len(),
                    result.variant_count
                );
            }
            ExitCode::SUCCESS
        }
        Err((db, diags)) => {
            report(&db, &diags, color);
            ExitCode::FAILURE
        }
    }
}

/// `weft merge`: the shards' folders joined into `out`, byte-identical to an
/// unsharded build.
pub(crate) fn merge_command(
    shards: &[PathBuf],
    out: Option<PathBuf>,
    lock_timeout: Duration,
    quiet: bool,
) -> ExitCode {
    let out = out.unwrap_or_else(|| PathBuf::from("generated"));
    let inputs: Vec<Input<'_>> = shards
        .iter()
        .map(|path| Input {
            what: "shard folder",
            path,
        })
        .collect();
    if let Err(e) = check_apart(&out, &inputs) {
        eprintln!("error: {e}; nothing was written");
        return ExitCode::FAILURE;
    }
    let files = match weft_compiler::shard::merge(shards) {
        Ok(f) => f,
        Err(e) => {
            eprintln!("error: {e}; nothing was written");
            return ExitCode::FAILURE;
        }
    };
    let Some(lock) = lock_output(&out, lock_timeout, quiet) else {
        return ExitCode::FAILURE;
    };
    let write = || -> std::io::Result<()> {
        let mut staging = lock.stage()?;
        for (rel, from) in &files {
            staging.link(rel, from)?;
        }
        staging.commit(PRESERVED)
    };
    if let Err(e) = write() {
        eprintln!(
            "error: cannot write `{}`: {e}; the old output is unchanged",
            out.display()
        );
        return ExitCode::FAILURE;
    }
    if !quiet {
        println!(
            "merged {} shard folder(s), {} file(s) into {}",
            shards.len(),
            files.len(),
            out.display()
        );
    }
    ExitCode::SUCCESS
}

/// The material files a build's paths name, and the materials root they
/// share (None: found per file).
struct MaterialFiles {
    paths: Vec<PathBuf>,
    root: Option<PathBuf>,
}

/// Resolves folders and files given on the command line to material files.
fn material_files(paths: &[PathBuf]) -> Result<MaterialFiles, (SourceDb, Diagnostics)> {
    if let Some(empty) = no_material(paths) {
        return Err(empty);
    }
    if let [dir] = paths
        && dir.is_dir()
    {
        return match weft_compiler::library::discover(dir) {
            Ok(found) => Ok(MaterialFiles {
                paths: found,
                root: Some(dir.clone()),
            }),
            Err(e) => {
                let mut diags = Diagnostics::new();
                diags.push(
                    codespan_reporting::diagnostic::Diagnostic::error()
                        .with_code("io")
                        .with_message(format!(
                            "cannot read materials folder `{}`: {e}",
                            dir.display()
                        )),
                );
                Err((SourceDb::new(), diags))
            }
        };
    }
    let mut files = Vec::new();
    for p in paths {
        if p.is_dir() {
            files.extend(weft_compiler::library::discover(p).unwrap_or_default());
        } else {
            files.push(p.clone());
        }
    }
    Ok(MaterialFiles {
        paths: files,
        root: None,
    })
}

/// Prints `[i/n] compiling <name>` on a terminal.
fn progress_printer(quiet: bool) -> impl Fn(usize, usize, &str) + Sync {
    let show = !quiet && std::io::stderr().is_terminal();
    move |i: usize, n: usize, name: &str| {
        if show {
            if name.is_empty() {
                eprint!("\r\x1b[K");
            } else {
                eprint!("\r\x1b[K[{}/{n}] compiling {name}", i + 1);
            }
        }
    }
}

/// Builds from folders and/or files, in memory (`weft check` and others).
pub(crate) fn build(
    paths: &[PathBuf],
    options: &BuildOptions,
    quiet: bool,
) -> Result<BuildOutput, (SourceDb, Diagnostics)> {
    let files = material_files(paths)?;
    let progress = progress_printer(quiet);
    weft_compiler::build_materials(&files.paths, files.root.as_deref(), options, &progress)
}

/// A `no-material` error for each folder that holds no material
/// (`<folder>/<name>/<name>.toml`); None when every path names some.
fn no_material(paths: &[PathBuf]) -> Option<(SourceDb, Diagnostics)> {
    let mut diags = Diagnostics::new();
    for p in paths.iter().filter(|p| p.is_file()) {
        let name = p
            .file_name()
            .map(|n| n.to_string_lossy())
            .unwrap_or_default();
        let hint = if name.ends_with(".scene.toml") {
            "this is a scene manifest: build it with `weft build --scene <file>`"
        } else if weft_front::gltf::is_gltf_path(p) {
            "this is a glTF file: build it as a scene with `weft build --scene <file>` (docs/gltf.md)"
        } else if !name.ends_with(".toml") {
            "a material is a .toml file (its WGSL is named by `source`)"
        } else {
            continue;
        };
        diags.push(
            codespan_reporting::diagnostic::Diagnostic::error()
                .with_code("no-material")
                .with_message(format!("`{}` is not a material", p.display()))
                .with_notes(vec![hint.into()]),
        );
    }
    for p in paths.iter().filter(|p| p.is_dir()) {
        // An unreadable folder is reported by the build itself.
        if weft_compiler::library::discover(p).is_ok_and(|found| found.is_empty()) {
            diags.push(
                codespan_reporting::diagnostic::Diagnostic::error()
                    .with_code("no-material")
                    .with_message(format!("no material in `{}`", p.display()))
                    .with_notes(vec![
                        "a materials folder holds one folder per material, `<name>/<name>.toml` (and `lib/` for shared WGSL); or name material .toml files".into(),
                    ]),
            );
        }
    }
    (!diags.is_empty()).then(|| (SourceDb::new(), diags))
}
