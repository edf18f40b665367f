//! Which folders a build may replace. weft replaces its output folder
//! whole (crate::build::output), so it must never be pointed at something that is
//! not its own: a build never deletes a file it did not write.
//!
//! Two rules, checked before anything is written:
//!
//! - **Ownership.** An existing output folder is replaced only if it is
//!   empty, or holds [`OUTPUT_MARKER`] (written into every output folder by
//!   every build) or lies inside a folder that does, or has a
//!   `.<name>.stamp` beside it (written by weft builds before the marker
//!   existed). Anything else — a project folder, a
//!   material's folder, a user's folder — is refused with an error that
//!   says so.
//! - **Apart from the inputs.** An output folder that is, contains or lies
//!   inside one of the build's inputs (the materials root, a scene file, the
//!   shard folders being merged, the cache) is refused, however it is
//!   spelled: relative, absolute, through `..` or a symbolic link, with a
//!   trailing slash. Paths are compared after resolving every existing
//!   prefix, so two spellings of one folder compare equal.

use std::io;
use std::path::{Component, Path, PathBuf};

/// The file inside every folder a build writes, marking it as weft's
/// output (and so as replaceable by the next build).
pub const OUTPUT_MARKER: &str = ".weft-output";

/// [`OUTPUT_MARKER`]'s contents.
pub const OUTPUT_MARKER_TEXT: &str = "This folder is build output of weft: the next build replaces it whole.\n\
Do not keep files of your own here.\n";

/// Whether the existing folder `dir` may be replaced by a build (see the
/// module documentation); an error explaining why not otherwise.
pub(crate) fn check_replaceable(dir: &Path, stamp: &Path) -> io::Result<()> {
    // Marked itself, or inside a marked folder (a scene's folder in
    // `generated/scenes/`, the gallery): weft's output either way.
    let resolved = resolve(dir)?;
    if resolved
        .ancestors()
        .any(|d| std::fs::symlink_metadata(d.join(OUTPUT_MARKER)).is_ok_and(|m| m.is_file()))
    {
        return Ok(());
    }
    if crate::build::stamp::is_stamp_file(stamp) {
        return Ok(());
    }
    let mut entries =
        std::fs::read_dir(dir).map_err(crate::build::output::at(dir, "cannot read"))?;
    if entries.next().is_none() {
        return Ok(());
    }
    Err(io::Error::new(
        io::ErrorKind::PermissionDenied,
        format!(
            "`{}` is not empty and is not a folder weft built (it has no `{OUTPUT_MARKER}` file); \
             a build replaces its output folder whole, so weft will not write into it. \
             Give a new or empty folder with -o, or move this one away yourself",
            dir.display()
        ),
    ))
}

/// An input of a build, for [`check_apart`]: what it is (e.g. "materials
/// root") and where.
pub struct Input<'a> {
    pub what: &'a str,
    pub path: &'a Path,
}

/// Refuses an output folder `out` that is, contains or lies inside one of
/// `inputs` (see the module documentation).
pub fn check_apart(out: &Path, inputs: &[Input<'_>]) -> io::Result<()> {
    let out_resolved = resolve(out)?;
    for input in inputs {
        let Ok(inp) = resolve(input.path) else {
            continue;
        };
        let relation = if out_resolved == inp {
            "is"
        } else if out_resolved.starts_with(&inp) {
            "lies inside"
        } else if inp.starts_with(&out_resolved) {
            "contains"
        } else {
            continue;
        };
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            format!(
                "the output folder `{}` {relation} the {} `{}`; a build replaces its output \
                 folder whole, so it must lie apart from its inputs. Choose another -o (e.g. `generated`)",
                out.display(),
                input.what,
                input.path.display()
            ),
        ));
    }
    Ok(())
}

/// `path` made absolute with every existing prefix resolved (symbolic
/// links, `..` after a link) and the rest taken as written.
pub fn resolve(path: &Path) -> io::Result<PathBuf> {
    let abs = std::path::absolute(path)?;
    let mut out = PathBuf::new();
    for c in abs.components() {
        match c {
            Component::Prefix(_) | Component::RootDir => out.push(c.as_os_str()),
            Component::CurDir => {}
            Component::ParentDir => {
                out = canonical_or_same(out);
                out.pop();
            }
            Component::Normal(name) => {
                out.push(name);
                out = canonical_or_same(out);
            }
        }
    }
    Ok(out)
}

fn canonical_or_same(p: PathBuf) -> PathBuf {
    std::fs::canonicalize(&p).unwrap_or(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(path: &Path) -> [Input<'_>; 1] {
        [Input {
            what: "materials root",
            path,
        }]
    }

    #[test]
    fn every_spelling_of_an_input_is_refused() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path().join("project");
        let materials = root.join("materials");
        std::fs::create_dir_all(materials.join("velvet")).unwrap();
        std::fs::create_dir_all(root.join("other")).unwrap();
        let link = tmp.path().join("link");
        #[cfg(unix)]
        std::os::unix::fs::symlink(&materials, &link).unwrap();
        let mut spellings = vec![
            (materials.clone(), "is"),
            (materials.join("velvet"), "lies inside"),
            (root.clone(), "contains"),
            (PathBuf::from(format!("{}/", materials.display())), "is"),
            (root.join("other/../materials"), "is"),
            (root.join("other/../materials/velvet/new"), "lies inside"),
            (root.join("./materials/."), "is"),
        ];
        #[cfg(unix)]
        spellings.push((link.join("velvet"), "lies inside"));
        for (out, relation) in spellings {
            let e = check_apart(&out, &input(&materials))
                .unwrap_err()
                .to_string();
            assert!(e.contains(relation), "{}: {e}", out.display());
        }
        check_apart(&root.join("generated"), &input(&materials)).unwrap();
        check_apart(&root.join("other"), &input(&materials)).unwrap();
    }

    #[test]
    fn relative_spellings_resolve_like_absolute_ones() {
        let here = std::env::current_dir().unwrap();
        assert_eq!(resolve(Path::new(".")).unwrap(), resolve(&here).unwrap());
        let e = check_apart(Path::new("."), &input(&here)).unwrap_err();
        assert!(e.to_string().contains("is the materials root"), "{e}");
    }

    #[test]
    fn only_empty_or_marked_folders_are_replaceable() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path().join("out");
        let stamp = tmp.path().join(".out.stamp");
        std::fs::create_dir(&dir).unwrap();
        check_replaceable(&dir, &stamp).unwrap();
        std::fs::write(dir.join("notes.txt"), "mine").unwrap();
        let e = check_replaceable(&dir, &stamp).unwrap_err().to_string();
        assert!(e.contains("not a folder weft built"), "{e}");
        std::fs::write(dir.join(OUTPUT_MARKER), OUTPUT_MARKER_TEXT).unwrap();
        check_replaceable(&dir, &stamp).unwrap();
        // A folder inside weft's output is weft's too (generated/scenes/x).
        let inner = dir.join("scenes/x");
        std::fs::create_dir_all(&inner).unwrap();
        std::fs::write(inner.join("x.json"), "{}").unwrap();
        check_replaceable(&inner, &tmp.path().join(".x.stamp")).unwrap();
    }
}
