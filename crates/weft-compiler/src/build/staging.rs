//! A new tree for an output folder, built up one file at a time and swapped
//! in whole ([`crate::build::output`] has the swap and the lock).
//!
//! A library build streams its files here as each material is compiled, so
//! the process holds one material's files at a time, not the library's
//! (docs/performance.md, "Build scale"). Files stay in memory while they are
//! few and small — a no-change rebuild hands over only the library-wide
//! files, which are then compared with the folder and nothing is written —
//! and go to a temporary folder beside the output folder once they pass
//! [`SPILL_BYTES`]. Files of materials kept from the previous build are
//! hard-linked from it (copied where the file system cannot link): the
//! old tree keeps its own name for each until the swap removes it.

use crate::build::output::{OutputLock, at, is_preserved, list_files};
use std::collections::BTreeMap;
use std::io;
use std::path::Path;

/// Bytes held in memory before the tree goes to disk: above the shipped
/// library (34 MiB with thirteen materials, standard's `constant` keywords'
/// file sets included), so that a build of it is compared with the folder
/// by content when the folder has no stamp.
pub const SPILL_BYTES: usize = 64 << 20;

/// See the module documentation. Dropped without [`Staging::commit`], the
/// temporary folder is removed and the output folder is untouched.
pub struct Staging<'l> {
    lock: &'l OutputLock,
    /// Files not yet on disk.
    pending: BTreeMap<String, Vec<u8>>,
    pending_bytes: usize,
    /// The temporary folder, once anything went to disk.
    tmp: Option<tempfile::TempDir>,
    /// Files on disk in `tmp` (written or linked).
    on_disk: usize,
}

impl<'l> Staging<'l> {
    pub(crate) fn new(lock: &'l OutputLock) -> io::Result<Staging<'l>> {
        // Refuse a read-only or non-folder output before any work.
        lock.existing()?;
        Ok(Staging {
            lock,
            pending: BTreeMap::new(),
            pending_bytes: 0,
            tmp: None,
            on_disk: 0,
        })
    }

    /// Adds a file (path relative to the output folder, `/`-separated).
    pub fn put(&mut self, rel: String, bytes: Vec<u8>) -> io::Result<()> {
        if self.tmp.is_some() {
            return self.write_file(&rel, &bytes);
        }
        self.pending_bytes += bytes.len();
        if let Some(old) = self.pending.insert(rel, bytes) {
            self.pending_bytes -= old.len();
        }
        if self.pending_bytes > SPILL_BYTES {
            self.spill()?;
        }
        Ok(())
    }

    /// As [`Staging::put`], for bytes the caller keeps.
    pub fn put_ref(&mut self, rel: &str, bytes: &[u8]) -> io::Result<()> {
        if self.tmp.is_some() {
            return self.write_file(rel, bytes);
        }
        self.put(rel.to_string(), bytes.to_vec())
    }

    /// Adds the file `from` (e.g. in the folder being replaced) as `rel`,
    /// without reading it: a hard link, or a copy where linking fails.
    pub fn link(&mut self, rel: &str, from: &Path) -> io::Result<()> {
        self.spill()?;
        let to = self.tmp_path()?.join(rel);
        if let Some(p) = to.parent() {
            std::fs::create_dir_all(p).map_err(at(&to, "cannot write"))?;
        }
        if std::fs::hard_link(from, &to).is_err() {
            std::fs::copy(from, &to).map_err(at(&to, "cannot write"))?;
        }
        self.on_disk += 1;
        Ok(())
    }

    /// The staged files, while all are still in memory (None once any went
    /// to disk).
    pub fn in_memory(&self) -> Option<&BTreeMap<String, Vec<u8>>> {
        self.tmp.is_none().then_some(&self.pending)
    }

    /// How many files are staged.
    pub fn len(&self) -> usize {
        self.pending.len() + self.on_disk
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Copies the preserved paths of the old folder that the new tree does
    /// not have, then swaps the new tree in. On any error the old folder is
    /// left as it was.
    pub fn commit(mut self, preserve: &[&str]) -> io::Result<()> {
        self.spill()?;
        let existed = self.lock.existing()?;
        let dir = self.lock.dir().to_path_buf();
        let tmp = self.tmp.take().expect("spilled");
        // Marks the new tree as weft's, so that the next build may replace it.
        let marker = tmp.path().join(crate::build::ownership::OUTPUT_MARKER);
        std::fs::write(&marker, crate::build::ownership::OUTPUT_MARKER_TEXT)
            .map_err(at(&marker, "cannot write"))?;
        if existed {
            for rel in list_files(&dir).map_err(at(&dir, "cannot read"))? {
                let to = tmp.path().join(&rel);
                if is_preserved(&rel, preserve) && !to.exists() {
                    if let Some(p) = to.parent() {
                        std::fs::create_dir_all(p).map_err(at(&to, "cannot write"))?;
                    }
                    std::fs::copy(dir.join(&rel), &to).map_err(at(&to, "cannot write"))?;
                }
            }
        }
        self.lock.swap_in(tmp, existed)?;
        // Best effort: without a stamp the next build reads the files instead.
        if crate::build::stamp::Stamp::record(self.lock, preserve).is_err() {
            let _ = std::fs::remove_file(self.lock.stamp_path());
        }
        Ok(())
    }

    /// Moves the pending files to the temporary folder (creating it).
    fn spill(&mut self) -> io::Result<()> {
        if self.tmp.is_none() {
            self.tmp = Some(self.lock.temp_dir()?);
        }
        for (rel, bytes) in std::mem::take(&mut self.pending) {
            self.write_file(&rel, &bytes)?;
        }
        self.pending_bytes = 0;
        Ok(())
    }

    fn tmp_path(&self) -> io::Result<&Path> {
        Ok(self.tmp.as_ref().expect("spilled").path())
    }

    fn write_file(&mut self, rel: &str, bytes: &[u8]) -> io::Result<()> {
        let path = self.tmp_path()?.join(rel);
        if let Some(p) = path.parent() {
            std::fs::create_dir_all(p).map_err(at(&path, "cannot write"))?;
        }
        std::fs::write(&path, bytes).map_err(at(&path, "cannot write"))?;
        self.on_disk += 1;
        Ok(())
    }
}
