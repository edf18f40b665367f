//! `cargo xtask regenerate [--check]` and `textures [--check]`: the shader library (generated/), its README binding tables and the character textures, written or checked.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use weft_compiler::{BuildOptions, output};

/// Paths under `generated/` that `regenerate` keeps: measured reports and
/// the gallery have their own commands (timings vary by machine).
pub(crate) const PRESERVED: &[&str] = &["reports", "gallery", "gallery.md"];

/// The whole project: every material, then every scene under `scenes/`
/// (files under `scenes/<scene>/`), `auto` tiers measured on lavapipe.
pub(crate) fn build(root: &Path, options: &BuildOptions) -> Option<weft_compiler::BuildOutput> {
    match weft_golden::project::build_project(root, options) {
        Ok(out) => Some(out),
        Err((db, diags)) => {
            let mut stderr = codespan_reporting::term::termcolor::StandardStream::stderr(
                codespan_reporting::term::termcolor::ColorChoice::Auto,
            );
            diags.emit(&db, &mut stderr);
            eprintln!("error: materials or scenes do not compile; generated/ left untouched");
            None
        }
    }
}

pub(crate) fn regenerate(root: &Path, check: bool) -> ExitCode {
    let Some(out) = build(root, &BuildOptions::default()) else {
        return ExitCode::FAILURE;
    };
    let generated = root.join("generated");
    if check {
        match readme_binding_tables(root, &out.files, true) {
            Ok(stale) if stale.is_empty() => {}
            Ok(stale) => {
                eprintln!(
                    "bindings tables in material READMEs are stale; run `cargo xtask regenerate`:"
                );
                for p in &stale {
                    eprintln!("  {}", p.strip_prefix(root).unwrap_or(p).display());
                }
                return ExitCode::FAILURE;
            }
            Err(e) => {
                eprintln!("error: {e}");
                return ExitCode::FAILURE;
            }
        }
        return match output::check(&generated, &out.files, PRESERVED) {
            Ok(s) if s.is_clean() => {
                println!("generated/ is up to date ({} files)", out.files.len());
                ExitCode::SUCCESS
            }
            Ok(s) => {
                eprintln!("generated/ is stale; run `cargo xtask regenerate`:");
                for f in &s.changed {
                    eprintln!("  changed: generated/{f}");
                }
                for f in &s.missing {
                    eprintln!("  missing: generated/{f}");
                }
                for f in &s.extra {
                    eprintln!("  stale (would be removed): generated/{f}");
                }
                ExitCode::FAILURE
            }
            Err(e) => {
                eprintln!("error: cannot read generated/: {e}");
                ExitCode::FAILURE
            }
        };
    }
    match output::write_atomically(&generated, &out.files, PRESERVED) {
        Ok(()) => {
            println!(
                "regenerated generated/: {} materials, {} variants, {} files",
                out.materials.len(),
                out.variant_count,
                out.files.len()
            );
            match readme_binding_tables(root, &out.files, false) {
                Ok(updated) => {
                    for p in updated {
                        println!("updated the bindings table in {}", p.display());
                    }
                    ExitCode::SUCCESS
                }
                Err(e) => {
                    eprintln!("error: {e}");
                    ExitCode::FAILURE
                }
            }
        }
        Err(e) => {
            eprintln!("error: cannot write generated/: {e}");
            ExitCode::FAILURE
        }
    }
}

/// The bindings table of each material's README (`<!-- weft:bindings:… -->`,
/// `weft_golden::bindings`), from the metadata just built: rewritten, or with
/// `check` only compared. Returns the READMEs whose table changed (or would).
/// A README without the markers is left alone (tests/contract/metadata_contract.rs
/// requires them in every material's README).
pub(crate) fn readme_binding_tables(
    root: &Path,
    files: &std::collections::BTreeMap<String, Vec<u8>>,
    check: bool,
) -> Result<Vec<PathBuf>, String> {
    use weft_golden::{bindings, shading::replace_marked};
    let mut changed = Vec::new();
    for (rel, bytes) in files {
        let mut parts = rel.split('/');
        let (Some(dir), Some(file), None) = (parts.next(), parts.next(), parts.next()) else {
            continue;
        };
        if file != format!("{dir}.meta.json") {
            continue;
        }
        let meta: weft_meta::MaterialMetadata =
            serde_json::from_slice(bytes).map_err(|e| format!("generated/{rel}: {e}"))?;
        let readme = root.join("materials").join(&meta.name).join("README.md");
        let Ok(text) = std::fs::read_to_string(&readme) else {
            continue;
        };
        let Some(new) = replace_marked(&text, bindings::MARKER, &bindings::readme_table(&meta))
        else {
            continue;
        };
        if new != text {
            if !check {
                std::fs::write(&readme, new).map_err(|e| format!("{}: {e}", readme.display()))?;
            }
            changed.push(readme);
        }
    }
    Ok(changed)
}

/// `cargo xtask textures [--check]`.
pub(crate) fn textures(root: &Path, check: bool) -> ExitCode {
    use weft_golden::textures;
    if check {
        let stale = textures::stale(root);
        if stale.is_empty() {
            println!("textures are current");
            return ExitCode::SUCCESS;
        }
        for path in stale {
            eprintln!("stale: {path}");
        }
        eprintln!("run `cargo xtask textures` and commit the PNGs");
        return ExitCode::FAILURE;
    }
    match textures::write(root) {
        Ok(written) => {
            for path in &written {
                println!("wrote {}", path.display());
            }
            if written.is_empty() {
                println!("textures are current");
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("cannot write the textures: {e}");
            ExitCode::FAILURE
        }
    }
}
