//! Keeps ARCHITECTURE.md a true map: every path it names in backticks
//! exists, every bare file name it names (`fold.rs`) exists somewhere in the
//! code, and every crate, top folder and folder inside a crate's `src/` has
//! its entry. Keeps the materials' sources true too: a test, crate or doc
//! path named in a material's WGSL, TOML or README exists (files move; the
//! comments that cite them must follow). Run by the tests below (so by
//! `cargo test --workspace`); only tests use it.

use std::collections::BTreeSet;
use std::path::Path;

/// Top-level folders a named path may start with.
const TOP_FOLDERS: [&str; 11] = [
    "crates",
    "tests",
    "xtask",
    "fuzz",
    "docs",
    "materials",
    "generated",
    "schemas",
    "scenes",
    ".ci",
    "tools",
];

/// Folders whose file names a bare name (`fold.rs`) may refer to.
const CODE_FOLDERS: [&str; 5] = ["crates", "tests", "xtask", "fuzz", "materials"];

/// Extensions of the bare file names checked.
const EXTENSIONS: [&str; 7] = ["rs", "wgsl", "toml", "py", "js", "css", "html"];

/// What ARCHITECTURE.md names that is not there, and crates it does not name.
pub fn architecture_problems(root: &Path) -> Result<Vec<String>, String> {
    let path = root.join("ARCHITECTURE.md");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut names = BTreeSet::new();
    for folder in CODE_FOLDERS {
        collect_names(&root.join(folder), &mut names);
    }
    let mut problems = Vec::new();
    for token in backticked(&text) {
        // Placeholders, globs, code and prose are not paths.
        if token
            .chars()
            .any(|c| "<>*{} \"=…,()[]:".contains(c) || c.is_uppercase())
        {
            continue;
        }
        if let Some((first, _)) = token.split_once('/') {
            if TOP_FOLDERS.contains(&first) {
                if !root.join(token.trim_end_matches('/')).exists() {
                    problems.push(format!("`{token}` does not exist"));
                }
            } else if token.ends_with('/') && !token[..token.len() - 1].contains('/') {
                // A bare folder name (`bake/`).
                if !names.contains(token) {
                    problems.push(format!("no folder `{token}` in the code"));
                }
            }
        } else if let Some((stem, ext)) = token.rsplit_once('.')
            && !stem.is_empty()
            && EXTENSIONS.contains(&ext)
            && !names.contains(token)
        {
            problems.push(format!("no file `{token}` in the code"));
        }
    }
    let crates = root.join("crates");
    let entries = std::fs::read_dir(&crates).map_err(|e| format!("{}: {e}", crates.display()))?;
    let mut members: Vec<String> = entries
        .filter_map(|e| e.ok())
        .filter(|e| e.path().join("Cargo.toml").is_file())
        .filter_map(|e| e.file_name().into_string().ok())
        .map(|n| format!("crates/{n}"))
        .collect();
    // Every top folder (`.ci` too; build output and other hidden folders
    // are not the code's).
    for e in std::fs::read_dir(root).map_err(|e| format!("{}: {e}", root.display()))? {
        let e = e.map_err(|e| format!("{}: {e}", root.display()))?;
        let name = e.file_name().to_string_lossy().into_owned();
        let hidden = name.starts_with('.') && name != ".ci";
        if e.path().is_dir() && !hidden && name != "target" && name != "crates" {
            members.push(name);
        }
    }
    // Every folder inside a crate's or xtask's `src/`: the stages a crate is
    // split into are what the map is for.
    let src_dirs = members
        .iter()
        .filter(|m| m.starts_with("crates/") || *m == "xtask")
        .map(|m| format!("{m}/src"))
        .collect::<Vec<_>>();
    for src in src_dirs {
        let Ok(entries) = std::fs::read_dir(root.join(&src)) else {
            continue;
        };
        for e in entries.filter_map(|e| e.ok()) {
            if e.path().is_dir() {
                members.push(format!("{src}/{}", e.file_name().to_string_lossy()));
            }
        }
    }
    members.sort();
    members.dedup();
    for m in members {
        if !text.contains(&format!("`{m}`")) && !text.contains(&format!("`{m}/`")) {
            problems.push(format!("`{m}` has no entry"));
        }
    }
    Ok(problems)
}

/// Paths under `tests/`, `crates/`, `docs/` or `xtask/` that a file in
/// `materials/` names (in a comment, a tooltip or its README) and that do not
/// exist, as `file: path`.
pub fn material_source_problems(root: &Path) -> Result<Vec<String>, String> {
    let mut files = Vec::new();
    material_sources(&root.join("materials"), &mut files)?;
    files.sort();
    let mut problems = Vec::new();
    for file in files {
        let text =
            std::fs::read_to_string(&file).map_err(|e| format!("{}: {e}", file.display()))?;
        let shown = file
            .strip_prefix(root)
            .unwrap_or(&file)
            .display()
            .to_string();
        for path in named_paths(&text) {
            if !root.join(path).exists() {
                problems.push(format!("{shown}: `{path}` does not exist"));
            }
        }
    }
    Ok(problems)
}

/// The WGSL, TOML and Markdown files under `dir`.
fn material_sources(dir: &Path, out: &mut Vec<std::path::PathBuf>) -> Result<(), String> {
    for e in std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))? {
        let path = e.map_err(|e| format!("{}: {e}", dir.display()))?.path();
        if path.is_dir() {
            material_sources(&path, out)?;
        } else if matches!(
            path.extension().and_then(|x| x.to_str()),
            Some("wgsl" | "toml" | "md")
        ) {
            out.push(path);
        }
    }
    Ok(())
}

/// Repository paths with a file extension that start at one of the code or
/// docs folders (`tests/physics/eye.rs`), not preceded by a path character
/// (so `../lib/x.wgsl` and `generated/docs/x.md` are not taken).
fn named_paths(text: &str) -> Vec<&str> {
    let is_path_char = |c: char| c.is_ascii_alphanumeric() || "_-./".contains(c);
    let mut paths = Vec::new();
    for prefix in ["tests/", "crates/", "docs/", "xtask/"] {
        for (at, _) in text.match_indices(prefix) {
            if text[..at].chars().next_back().is_some_and(is_path_char) {
                continue;
            }
            let len = text[at..]
                .find(|c: char| !is_path_char(c))
                .unwrap_or(text.len() - at);
            let path = text[at..at + len].trim_end_matches('.');
            let file = path.rsplit('/').next().unwrap_or("");
            if file.rsplit_once('.').is_some_and(|(stem, ext)| {
                !stem.is_empty() && (EXTENSIONS.contains(&ext) || ext == "md")
            }) {
                paths.push(path);
            }
        }
    }
    paths
}

/// The text between each pair of backticks (code spans; fenced blocks' lines too).
fn backticked(text: &str) -> Vec<&str> {
    text.split('`')
        .enumerate()
        .filter(|(i, s)| i % 2 == 1 && !s.is_empty() && !s.contains('\n'))
        .map(|(_, s)| s)
        .collect()
}

/// File names and `folder/` names under `dir`, build output excluded.
fn collect_names(dir: &Path, out: &mut BTreeSet<String>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.filter_map(|e| e.ok()) {
        let name = e.file_name().to_string_lossy().into_owned();
        if name == "target" || name.starts_with('.') {
            continue;
        }
        if e.path().is_dir() {
            out.insert(format!("{name}/"));
            collect_names(&e.path(), out);
        } else {
            out.insert(name);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn architecture_md_names_only_what_exists_and_every_crate() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        let problems = architecture_problems(root).unwrap();
        assert!(
            problems.is_empty(),
            "ARCHITECTURE.md is out of date:\n{}",
            problems.join("\n")
        );
    }

    #[test]
    fn paths_the_materials_cite_exist() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        let problems = material_source_problems(root).unwrap();
        assert!(
            problems.is_empty(),
            "a material cites a file that is not there (moved? update the comment):\n{}",
            problems.join("\n")
        );
    }

    #[test]
    fn named_paths_take_repository_paths_only() {
        let text = "// measured by tests/physics/eye.rs, see docs/energy.md.\n\
                    // ../lib/x.wgsl and generated/docs/y.md and tests/ alone are not taken;\n\
                    // (crates/weft-meta/src/uniform.rs: the encoder)";
        assert_eq!(
            named_paths(text),
            [
                "tests/physics/eye.rs",
                "crates/weft-meta/src/uniform.rs",
                "docs/energy.md"
            ]
        );
    }

    #[test]
    fn a_missing_file_or_crate_is_reported() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        std::fs::create_dir_all(root.join("crates/a/src")).unwrap();
        std::fs::write(root.join("crates/a/Cargo.toml"), "").unwrap();
        std::fs::write(root.join("crates/a/src/fold.rs"), "").unwrap();
        std::fs::create_dir_all(root.join("crates/b")).unwrap();
        std::fs::create_dir_all(root.join("fuzz")).unwrap();
        std::fs::create_dir_all(root.join("xtask")).unwrap();
        std::fs::create_dir_all(root.join("tests")).unwrap();
        std::fs::create_dir_all(root.join("crates/a/src/stages")).unwrap();
        std::fs::create_dir_all(root.join("docs")).unwrap();
        std::fs::create_dir_all(root.join("target")).unwrap();
        std::fs::create_dir_all(root.join(".git")).unwrap();
        std::fs::write(root.join("crates/b/Cargo.toml"), "").unwrap();
        std::fs::write(
            root.join("ARCHITECTURE.md"),
            "- `crates/a`: `fold.rs`, `gone.rs`, `crates/a/src/missing.rs`, `<name>.rs`\n- `xtask`, `tests`, `fuzz/`\n",
        )
        .unwrap();
        let problems = architecture_problems(root).unwrap();
        assert_eq!(
            problems,
            [
                "no file `gone.rs` in the code",
                "`crates/a/src/missing.rs` does not exist",
                "`crates/a/src/stages` has no entry",
                "`crates/b` has no entry",
                "`docs` has no entry",
            ]
        );
    }
}
