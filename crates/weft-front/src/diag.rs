//! Diagnostics: a file database and a list of codespan diagnostics.
//!
//! Every stage pushes into one [`Diagnostics`] and keeps going where it can, so
//! a run reports several errors at once. Spans are byte ranges into files held
//! by [`SourceDb`]; nothing points into generated text (the compiler maps its
//! composed WGSL back through a source map before reporting).

use codespan_reporting::diagnostic::{Diagnostic, Label, Severity};
use codespan_reporting::files::SimpleFiles;
use codespan_reporting::term::{self, termcolor::WriteColor};
use std::ops::Range;
use std::path::{Path, PathBuf};

pub type FileId = usize;
pub type Span = Range<usize>;

/// All source files a build has read, by id, for diagnostics.
#[derive(Default)]
pub struct SourceDb {
    files: SimpleFiles<String, String>,
    paths: Vec<PathBuf>,
}

impl SourceDb {
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds a file. `display` is how it is named in messages.
    pub fn add(&mut self, path: &Path, display: String, text: String) -> FileId {
        self.paths.push(path.to_path_buf());
        self.files.add(display, text)
    }

    /// The id of an already-loaded file, by its canonical path.
    pub fn find(&self, path: &Path) -> Option<FileId> {
        self.paths.iter().position(|p| p == path)
    }

    pub fn text(&self, id: FileId) -> &str {
        self.files.get(id).expect("file id").source()
    }

    pub fn name(&self, id: FileId) -> &str {
        self.files.get(id).expect("file id").name()
    }

    pub fn path(&self, id: FileId) -> &Path {
        &self.paths[id]
    }

    pub fn files(&self) -> &SimpleFiles<String, String> {
        &self.files
    }

    /// 1-based line and column of a byte offset.
    pub fn line_col(&self, id: FileId, offset: usize) -> (usize, usize) {
        let text = self.text(id);
        let offset = offset.min(text.len());
        let before = &text[..offset];
        let line = before.matches('\n').count() + 1;
        let col = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
        (line, col)
    }
}

/// An ordered list of diagnostics.
#[derive(Default, Debug)]
pub struct Diagnostics {
    list: Vec<Diagnostic<FileId>>,
}

impl Diagnostics {
    pub fn new() -> Self {
        Self::default()
    }

    pub fn push(&mut self, d: Diagnostic<FileId>) {
        self.list.push(d);
    }

    /// An error with a primary label at `span` in `file`.
    pub fn error(
        &mut self,
        code: &str,
        message: impl Into<String>,
        file: FileId,
        span: Span,
        label: impl Into<String>,
    ) -> &mut Diagnostic<FileId> {
        self.list.push(
            Diagnostic::error()
                .with_code(code)
                .with_message(message.into())
                .with_labels(vec![Label::primary(file, span).with_message(label.into())]),
        );
        self.list.last_mut().expect("just pushed")
    }

    pub fn extend(&mut self, other: Diagnostics) {
        self.list.extend(other.list);
    }

    pub fn has_errors(&self) -> bool {
        self.list
            .iter()
            .any(|d| matches!(d.severity, Severity::Error | Severity::Bug))
    }

    pub fn error_count(&self) -> usize {
        self.list
            .iter()
            .filter(|d| matches!(d.severity, Severity::Error | Severity::Bug))
            .count()
    }

    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    /// How many diagnostics there are: a mark for [`Diagnostics::since_mut`].
    pub fn len(&self) -> usize {
        self.list.len()
    }

    /// The diagnostics pushed since `mark`, to add context (labels, notes) to them.
    pub fn since_mut(&mut self, mark: usize) -> &mut [Diagnostic<FileId>] {
        self.list.get_mut(mark..).unwrap_or_default()
    }

    pub fn iter(&self) -> impl Iterator<Item = &Diagnostic<FileId>> {
        self.list.iter()
    }

    /// Writes every diagnostic in codespan's rich format.
    pub fn emit(&self, db: &SourceDb, out: &mut dyn WriteColor) {
        let config = term::Config::default();
        for d in &self.list {
            // Writing to a terminal or buffer only fails on I/O errors we cannot report anyway.
            let _ = term::emit_to_write_style(out, &config, db.files(), d);
        }
    }

    /// Renders every diagnostic without colour (for snapshots and logs).
    pub fn render_plain(&self, db: &SourceDb) -> String {
        let mut buf = codespan_reporting::term::termcolor::NoColor::new(Vec::new());
        self.emit(db, &mut buf);
        String::from_utf8_lossy(&buf.into_inner()).into_owned()
    }
}

/// Helper for "did you mean" hints.
pub fn did_you_mean<'a>(
    word: &str,
    candidates: impl IntoIterator<Item = &'a str>,
) -> Option<&'a str> {
    candidates
        .into_iter()
        .map(|c| (strsim::jaro_winkler(word, c), c))
        .filter(|(score, _)| *score > 0.8)
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, c)| c)
}

/// "did you mean `x`?" for the closest of `names`, else `"{list}: a, b, c"`.
pub fn suggestion(word: &str, names: &[&str], list: &str) -> String {
    match did_you_mean(word, names.iter().copied()) {
        Some(s) => format!("did you mean `{s}`?"),
        None if names.is_empty() => format!("{list}: none"),
        None => format!("{list}: {}", names.join(", ")),
    }
}

/// `"did you mean `x`? {list}: a, b, c"`: the closest of `names` (if any is
/// close), then all of them, for short lists (presets, tiers, values).
pub fn suggestion_listing(word: &str, names: &[&str], list: &str) -> String {
    let all = if names.is_empty() {
        format!("{list}: none")
    } else {
        format!("{list}: {}", names.join(", "))
    };
    match did_you_mean(word, names.iter().copied()) {
        Some(s) => format!("did you mean `{s}`? {all}"),
        None => all,
    }
}

/// Adds a note with a hint to the last diagnostic.
pub fn with_note(d: &mut Diagnostic<FileId>, note: impl Into<String>) {
    d.notes.push(note.into());
}
