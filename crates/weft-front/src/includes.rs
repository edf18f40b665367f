//! Resolves a material's WGSL sources: the `source` file and everything it
//! includes, transitively, in dependency order.
//!
//! An include is the comment directive `// @include "lib/brdf.wgsl"` (a WGSL
//! comment, so every file stays valid WGSL for editors and naga), or an entry
//! of `[material].includes`. Paths are relative to the materials root and may
//! not leave it. Each file is composed once; cycles are errors.

use crate::diag::{Diagnostics, FileId, SourceDb, Span};
use crate::model::SourceFile;
use codespan_reporting::diagnostic::{Diagnostic, Label};
use std::path::{Path, PathBuf};

/// One include directive found in a WGSL file.
pub struct Directive {
    pub path: String,
    /// Span of the quoted path.
    pub span: Span,
}

/// Finds `// @include "path"` directives.
pub fn directives(text: &str) -> Vec<Directive> {
    let mut out = Vec::new();
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        let trimmed = line.trim_start();
        if let Some(rest) = trimmed.strip_prefix("//") {
            let rest_trim = rest.trim_start();
            if let Some(arg) = rest_trim.strip_prefix("@include") {
                let start_in_line = line.len() - arg.len();
                let arg_trim = arg.trim();
                let lead = arg.len() - arg.trim_start().len();
                let path = arg_trim.trim_matches('"').to_string();
                let s = offset + start_in_line + lead;
                out.push(Directive {
                    path,
                    span: s..s + arg_trim.len(),
                });
            }
        }
        offset += line.len();
    }
    out
}

/// How diagnostics name a file named relative to the root.
struct Named {
    what: &'static str,
    verb: &'static str,
    fix: &'static str,
    missing_code: &'static str,
    outside_code: &'static str,
}

const INCLUDE: Named = Named {
    what: "include",
    verb: "included",
    fix: "move the file into its `lib/` folder",
    missing_code: "missing-include",
    outside_code: "include-outside-root",
};

const TEXTURE: Named = Named {
    what: "texture file",
    verb: "shipped with a material",
    fix: "move the PNG into the material's folder (e.g. `<material>/textures/`)",
    missing_code: "missing-texture-file",
    outside_code: "texture-file-outside-root",
};

/// Where a file was named from, for diagnostics.
#[derive(Clone)]
pub struct Origin {
    pub file: FileId,
    pub span: Span,
}

pub struct Resolver<'a> {
    pub db: &'a mut SourceDb,
    pub diags: &'a mut Diagnostics,
    pub root: PathBuf,
    /// Files fully resolved, in output order.
    done: Vec<SourceFile>,
    /// DFS stack for cycle reporting: (canonical path, file id, origin).
    stack: Vec<(PathBuf, Origin)>,
    /// Files come only from `db` (added beforehand), never the file system.
    in_memory: bool,
}

impl<'a> Resolver<'a> {
    pub fn new(db: &'a mut SourceDb, diags: &'a mut Diagnostics, root: &Path) -> Self {
        let root = root.canonicalize().unwrap_or_else(|_| root.to_path_buf());
        Self {
            db,
            diags,
            root,
            done: Vec::new(),
            stack: Vec::new(),
            in_memory: false,
        }
    }

    /// A resolver that reads nothing from disk: every file it may include
    /// must already be in `db`, under its path lexically normalised (see
    /// [`normalize`]); `root` is taken as written.
    pub fn in_memory(db: &'a mut SourceDb, diags: &'a mut Diagnostics, root: &Path) -> Self {
        Self {
            db,
            diags,
            root: normalize(root),
            done: Vec::new(),
            stack: Vec::new(),
            in_memory: true,
        }
    }

    /// The canonical path of an existing file: the file system's, or in
    /// memory the normalised path of a file in `db`.
    fn locate(&self, path: &Path) -> Option<PathBuf> {
        if self.in_memory {
            let p = normalize(path);
            self.db.find(&p).map(|_| p)
        } else {
            path.canonicalize().ok()
        }
    }

    /// Resolves an include path (relative to the root).
    pub fn include(&mut self, rel: &str, origin: Origin) {
        if let Some(canonical) = self.locate_include(rel, &origin) {
            self.visit(canonical, origin);
        }
    }

    /// Reads a file named relative to the root (a shared pass file) into
    /// `db` without composing it; the same checks as [`Resolver::include`].
    pub fn read(&mut self, rel: &str, origin: Origin) -> Option<FileId> {
        let path = self.locate_include(rel, &origin)?;
        if let Some(id) = self.db.find(&path) {
            return Some(id);
        }
        match weft_meta::files::read_regular_string(&path, weft_meta::files::MAX_TEXT_BYTES) {
            Ok(text) => Some(self.db.add(&path, display_path(&path), text)),
            Err(e) => {
                self.diags.error(
                    "io",
                    format!("cannot read `{}`: {e}", display_path(&path)),
                    origin.file,
                    origin.span,
                    "named here",
                );
                None
            }
        }
    }

    /// The canonical path of an include, reported when missing or outside
    /// the root.
    fn locate_include(&mut self, rel: &str, origin: &Origin) -> Option<PathBuf> {
        self.locate_under_root(rel, origin, &INCLUDE)
    }

    /// The canonical path of a texture parameter's `file` (a PNG named
    /// relative to the root), reported when missing or outside the root, as
    /// an include would be.
    pub fn locate_texture(&mut self, rel: &str, origin: &Origin) -> Option<PathBuf> {
        self.locate_under_root(rel, origin, &TEXTURE)
    }

    fn locate_under_root(&mut self, rel: &str, origin: &Origin, w: &Named) -> Option<PathBuf> {
        let candidate = self.root.join(rel);
        let Some(canonical) = self.locate(&candidate) else {
            let root = self.shown_root();
            let d = self.diags.error(
                w.missing_code,
                format!("cannot find {} `{rel}`", w.what),
                origin.file,
                origin.span.clone(),
                "no such file",
            );
            d.notes.push(format!(
                "{} paths are relative to the materials root `{}` (the nearest folder above the material that has a `lib/` folder)",
                w.what, root
            ));
            return None;
        };
        if !canonical.starts_with(&self.root) {
            let root = self.shown_root();
            let how = self.escape(rel, &candidate);
            let d = self.diags.error(
                w.outside_code,
                format!("{} `{rel}` is outside the materials root", w.what),
                origin.file,
                origin.span.clone(),
                "leaves the materials folder",
            );
            d.notes.extend(how);
            d.notes.push(format!(
                "only files under the materials root `{}` can be {}; {}",
                root, w.verb, w.fix
            ));
            return None;
        }
        Some(canonical)
    }

    /// How a path that resolved outside the root got there, when it is not
    /// plain `..`: an absolute path, or a symbolic link.
    fn escape(&self, written: &str, candidate: &Path) -> Option<String> {
        if Path::new(written).is_absolute() {
            Some(format!(
                "`{written}` is an absolute path; write it relative to the materials root"
            ))
        } else if normalize(candidate).starts_with(&self.root) {
            Some(format!(
                "`{written}` is inside the root as written, but a symbolic link on the way leads out of it"
            ))
        } else {
            None
        }
    }

    /// Resolves the material's own source: `written` (its `source`, relative
    /// to the TOML file) at `path`. Like includes, it must be under the root.
    pub fn source(&mut self, written: &str, path: &Path, origin: Origin) {
        match self.locate(path) {
            Some(c) if !c.starts_with(&self.root) => {
                let root = self.shown_root();
                let how = self.escape(written, path);
                let d = self.diags.error(
                    "source-outside-root",
                    format!("WGSL source `{written}` is outside the materials root"),
                    origin.file,
                    origin.span,
                    "leaves the materials folder",
                );
                d.notes.extend(how);
                d.notes.push(format!(
                    "a material's files must be under its materials root `{root}`; move the WGSL next to the TOML file"
                ));
            }
            Some(c) => self.visit(c, origin),
            None => {
                let d = self.diags.error(
                    "missing-source",
                    format!("cannot find WGSL source `{}`", display_path(path)),
                    origin.file,
                    origin.span,
                    "no such file",
                );
                d.notes
                    .push("`source` is relative to the material's TOML file".into());
            }
        }
    }

    fn visit(&mut self, path: PathBuf, origin: Origin) {
        if let Some(pos) = self.stack.iter().position(|(p, _)| *p == path) {
            let mut d = Diagnostic::error()
                .with_code("include-cycle")
                .with_message(format!("include cycle through `{}`", self.rel(&path)))
                .with_labels(vec![
                    Label::primary(origin.file, origin.span.clone())
                        .with_message("this include closes the cycle"),
                ]);
            let chain: Vec<String> = self.stack[pos..]
                .iter()
                .map(|(p, _)| self.rel(p))
                .chain(std::iter::once(self.rel(&path)))
                .collect();
            d.notes.push(format!("cycle: {}", chain.join(" -> ")));
            self.diags.push(d);
            return;
        }
        if self.done.iter().any(|f| self.db.path(f.file) == path) {
            return;
        }
        let id = match self.db.find(&path) {
            Some(id) => id,
            None => {
                match weft_meta::files::read_regular_string(&path, weft_meta::files::MAX_TEXT_BYTES)
                {
                    Ok(text) => {
                        let display = display_path(&path);
                        self.db.add(&path, display, text)
                    }
                    Err(e) => {
                        self.diags.error(
                            "io",
                            format!("cannot read `{}`: {e}", display_path(&path)),
                            origin.file,
                            origin.span,
                            "named here",
                        );
                        return;
                    }
                }
            }
        };
        self.stack.push((path.clone(), origin));
        for dir in directives(self.db.text(id)) {
            self.include(
                &dir.path,
                Origin {
                    file: id,
                    span: dir.span,
                },
            );
        }
        self.stack.pop();
        let rel_path = self.rel(&path);
        self.done.push(SourceFile { file: id, rel_path });
    }

    /// The root as shown in messages (relative to the working directory when inside it).
    fn shown_root(&self) -> String {
        match display_path(&self.root) {
            s if s.is_empty() => ".".into(),
            s => s,
        }
    }

    fn rel(&self, p: &Path) -> String {
        p.strip_prefix(&self.root)
            .unwrap_or(p)
            .to_string_lossy()
            .replace('\\', "/")
    }

    pub fn finish(self) -> Vec<SourceFile> {
        self.done
    }
}

/// Whether a material's TOML file (canonical path `abs`) lies under the
/// materials `root`; reports it when not (a material folder that is a
/// symbolic link out of the root, for one).
pub fn material_inside_root(
    abs: &Path,
    root: &Path,
    file: FileId,
    diags: &mut Diagnostics,
) -> bool {
    let root = root.canonicalize().unwrap_or_else(|_| root.to_path_buf());
    if abs.starts_with(&root) {
        return true;
    }
    let shown = match display_path(&root) {
        s if s.is_empty() => ".".into(),
        s => s,
    };
    let d = diags.error(
        "material-outside-root",
        format!(
            "material `{}` is outside the materials root",
            display_path(abs)
        ),
        file,
        0..0,
        "this file",
    );
    d.notes.push(format!(
        "a material is `<root>/<name>/<name>.toml` under the materials root `{shown}`; its folder (or a symbolic link on the way) leads out of the root"
    ));
    false
}

/// `path` with `.` and `..` components resolved lexically (no file system
/// access, links not followed): how in-memory files are named.
pub fn normalize(path: &Path) -> PathBuf {
    use std::path::Component;
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// A path as shown in diagnostics: relative to the working directory when inside it.
pub fn display_path(path: &Path) -> String {
    let cwd = std::env::current_dir()
        .ok()
        .and_then(|c| c.canonicalize().ok());
    match cwd.and_then(|c| path.strip_prefix(&c).ok().map(Path::to_path_buf)) {
        Some(rel) => rel.to_string_lossy().replace('\\', "/"),
        None => path.to_string_lossy().replace('\\', "/"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The codes a material `<root>/m/m.toml` whose source is written
    /// `source` gets, and whether the source was resolved.
    fn resolve_source(root: &Path, source: &str) -> (Vec<String>, usize) {
        let mut db = SourceDb::new();
        let mut diags = Diagnostics::new();
        let toml = db.add(&root.join("m/m.toml"), "m.toml".into(), String::new());
        let mut r = Resolver::new(&mut db, &mut diags, root);
        r.source(
            source,
            &root.join("m").join(source),
            Origin {
                file: toml,
                span: 0..0,
            },
        );
        let n = r.finish().len();
        (diags.iter().filter_map(|d| d.code.clone()).collect(), n)
    }

    #[test]
    fn sources_stay_under_the_root() {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path().join("materials");
        std::fs::create_dir_all(root.join("m")).unwrap();
        std::fs::write(root.join("m/m.wgsl"), "").unwrap();
        std::fs::write(tmp.path().join("outside.wgsl"), "").unwrap();
        assert_eq!(resolve_source(&root, "m.wgsl"), (vec![], 1));
        let out = || (vec!["source-outside-root".to_string()], 0);
        assert_eq!(resolve_source(&root, "../../outside.wgsl"), out());
        let abs = tmp.path().join("outside.wgsl");
        assert_eq!(resolve_source(&root, abs.to_str().unwrap()), out());
        #[cfg(unix)]
        {
            std::os::unix::fs::symlink(tmp.path().join("outside.wgsl"), root.join("m/link.wgsl"))
                .unwrap();
            assert_eq!(resolve_source(&root, "link.wgsl"), out());
            // A link that stays inside the root is fine.
            std::os::unix::fs::symlink(root.join("m/m.wgsl"), root.join("m/inside.wgsl")).unwrap();
            assert_eq!(resolve_source(&root, "inside.wgsl"), (vec![], 1));
        }
    }
    #[test]
    fn finds_directives() {
        let text = "// @include \"lib/a.wgsl\"\nfn f() {}\n  //@include \"b.wgsl\"\n";
        let d = directives(text);
        assert_eq!(d.len(), 2);
        assert_eq!(d[0].path, "lib/a.wgsl");
        assert_eq!(&text[d[0].span.clone()], "\"lib/a.wgsl\"");
        assert_eq!(d[1].path, "b.wgsl");
        assert_eq!(&text[d[1].span.clone()], "\"b.wgsl\"");
    }
}
