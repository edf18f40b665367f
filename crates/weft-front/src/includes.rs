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
        }
    }

    /// Resolves an include path (relative to the root).
    pub fn include(&mut self, rel: &str, origin: Origin) {
        let candidate = self.root.join(rel);
        let Ok(canonical) = candidate.canonicalize() else {
            let root = self.shown_root();
            let d = self.diags.error(
                "missing-include",
                format!("cannot find include `{rel}`"),
                origin.file,
                origin.span,
                "no such file",
            );
            d.notes.push(format!(
                "include paths are relative to the materials root `{}` (the nearest folder above the material that has a `lib/` folder)",
                root
            ));
            return;
        };
        if !canonical.starts_with(&self.root) {
            let root = self.shown_root();
            let d = self.diags.error(
                "include-outside-root",
                format!("include `{rel}` is outside the materials root"),
                origin.file,
                origin.span,
                "leaves the materials folder",
            );
            d.notes.push(format!(
                "only files under the materials root `{}` can be included; move the file into its `lib/` folder",
                root
            ));
            return;
        }
        self.visit(canonical, origin);
    }

    /// Resolves a file given by absolute path (the material's own source).
    pub fn source(&mut self, path: &Path, origin: Origin) {
        match path.canonicalize() {
            Ok(c) => self.visit(c, origin),
            Err(_) => {
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
            None => match std::fs::read_to_string(&path) {
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
            },
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
