//! What a build last wrote into an output folder: every file's size and
//! modification time, kept beside the folder as `.<name>.stamp` (outside
//! it, so the folder's bytes stay the build's alone).
//!
//! A no-change rebuild keeps unchanged materials' files unread
//! ([`crate::build::unchanged`]); the stamp is how it knows they are still the files
//! it wrote without reading them: a file edited, replaced or touched since
//! has another size or modification time. Without a stamp (a folder from a
//! checkout, or written by an older weft), or where one file differs, the
//! build reads and hashes the kept files against their metadata instead.
//! The stamp is written after each swap, under the folder's lock; a build
//! killed between the swap and the stamp leaves the old stamp, which the new
//! files do not match, so the slow path runs once.

use crate::build::output::{OutputLock, at};
use std::collections::HashMap;
use std::io::{self, Write};
use std::path::Path;
use std::time::UNIX_EPOCH;

/// First line of a stamp file.
const HEADER: &str = "weft output stamp v1";

/// Size and modification time (nanoseconds since the epoch) of each file,
/// by path relative to the output folder.
#[derive(Debug, Default)]
pub struct Stamp(HashMap<String, (u64, u128)>);

fn file_stamp(path: &Path) -> Option<(u64, u128)> {
    let m = std::fs::symlink_metadata(path).ok()?;
    if !m.is_file() {
        return None;
    }
    let mtime = m.modified().ok()?.duration_since(UNIX_EPOCH).ok()?;
    Some((m.len(), mtime.as_nanos()))
}

/// Whether `path` is a stamp file weft wrote (its first line is the header).
pub(crate) fn is_stamp_file(path: &Path) -> bool {
    use std::io::{BufRead, Read};
    // The type first: opening a FIFO would block.
    if !std::fs::metadata(path).is_ok_and(|m| m.is_file()) {
        return false;
    }
    let Ok(file) = std::fs::File::open(path) else {
        return false;
    };
    let mut first = String::new();
    let mut reader = std::io::BufReader::new(file.take(HEADER.len() as u64 + 1));
    reader.read_line(&mut first).is_ok() && first.trim_end() == HEADER
}

impl Stamp {
    /// The stamp of `lock`'s folder, if one was written and reads back whole.
    pub fn read(lock: &OutputLock) -> Option<Stamp> {
        let text = std::fs::read_to_string(lock.stamp_path()).ok()?;
        let mut lines = text.lines();
        if lines.next()? != HEADER {
            return None;
        }
        let mut files = HashMap::new();
        for line in lines {
            let mut parts = line.rsplitn(3, '\t');
            let mtime = parts.next()?.parse().ok()?;
            let size = parts.next()?.parse().ok()?;
            files.insert(parts.next()?.to_string(), (size, mtime));
        }
        Some(Stamp(files))
    }

    /// Whether `dir/rel` is still the file this stamp recorded.
    pub fn matches(&self, dir: &Path, rel: &str) -> bool {
        self.0
            .get(rel)
            .is_some_and(|s| file_stamp(&dir.join(rel)) == Some(*s))
    }

    /// Records the files now in `lock`'s folder (all but `preserve`d paths),
    /// replacing the stamp file atomically.
    pub fn record(lock: &OutputLock, preserve: &[&str]) -> io::Result<()> {
        let dir = lock.dir();
        let mut lines = Vec::new();
        crate::build::unchanged::walk(dir, String::new(), preserve, &mut |rel| {
            if let Some((size, mtime)) = file_stamp(&dir.join(rel)) {
                lines.push(format!("{rel}\t{size}\t{mtime}\n"));
            }
        })?;
        lines.sort();
        let path = lock.stamp_path();
        let parent = path.parent().unwrap_or(Path::new("."));
        let mut tmp = lock.temp_file().map_err(at(parent, "cannot write"))?;
        let mut text = format!("{HEADER}\n");
        text.extend(lines);
        tmp.write_all(text.as_bytes())
            .map_err(at(&path, "cannot write"))?;
        tmp.persist(&path)
            .map_err(|e| at(&path, "cannot write")(e.error))?;
        Ok(())
    }
}
