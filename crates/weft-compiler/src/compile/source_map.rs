//! The composed module's source map: which byte ranges of the one WGSL
//! module came from which user file (or TOML declaration), so that every
//! later stage (prelude, nesting, stage I/O, limits, naga's errors) can
//! point back into the user's files.

use std::ops::Range;
use weft_front::FileId;
use weft_front::model::Loc;

/// Where a range of composed text came from.
#[derive(Clone, Debug)]
pub enum Target {
    /// Copied from a file starting at this byte offset.
    File { file: FileId, offset: usize },
    /// Generated from a TOML declaration.
    Decl(Loc),
}

#[derive(Clone, Debug, Default)]
pub struct SourceMap {
    /// Composed byte ranges and where each came from, sorted by start
    /// (`compose.rs` fills them).
    pub(super) segments: Vec<(Range<usize>, Target)>,
}

impl SourceMap {
    /// Maps a composed span to a file span. A span inside generated text maps
    /// to the whole declaration it was generated from.
    pub fn map(&self, span: Range<usize>) -> Option<(FileId, Range<usize>)> {
        let (seg, target) = self
            .segments
            .iter()
            .find(|(r, _)| r.start <= span.start && span.start < r.end.max(r.start + 1))?;
        Some(match target {
            Target::File { file, offset } => {
                let start = span.start - seg.start + offset;
                let end = span.end.min(seg.end) - seg.start + offset;
                (*file, start..end.max(start))
            }
            Target::Decl(loc) => (loc.file, loc.span.clone()),
        })
    }
}

/// One composed WGSL module and its source map.
pub struct Composed {
    pub text: String,
    pub map: SourceMap,
}
