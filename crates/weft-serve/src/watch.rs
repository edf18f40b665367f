//! Change detection over the materials folder by polling.
//!
//! Why polling rather than OS notifications (the `notify` crate): a
//! materials library is tens of small files, so a stat of each every
//! quarter second costs microseconds; polling sees changes the same way on
//! every platform and file system (network mounts, containers, editors
//! that replace a file by renaming a new one over it), needs no extra
//! dependency tree, and cannot overflow an event queue. A change is acted
//! on once the folder has stopped changing for one more poll, so an editor
//! writing several files (or a file in several writes) causes one build.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, SystemTime};

/// How often the folder is scanned.
pub const POLL: Duration = Duration::from_millis(250);

/// What a scan sees of one file: modification time and length.
type Stamp = (Option<SystemTime>, u64);

/// Every `.toml`, `.wgsl` and `.png` (texture parameters' `file`) file under
/// `dir` (recursively, symbolic links not followed: the compiler refuses
/// them anyway) with its stamp.
pub fn scan(dir: &Path) -> BTreeMap<PathBuf, Stamp> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries.flatten() {
            let Ok(ft) = e.file_type() else { continue };
            let path = e.path();
            if ft.is_dir() {
                // Hidden folders (.git, editors' swap folders) are not material sources.
                if !e.file_name().to_string_lossy().starts_with('.') {
                    stack.push(path);
                }
            } else if ft.is_file()
                && path
                    .extension()
                    .is_some_and(|x| x == "toml" || x == "wgsl" || x == "png")
                && let Ok(md) = e.metadata()
            {
                out.insert(path, (md.modified().ok(), md.len()));
            }
        }
    }
    out
}

/// Remembers the last scan; [`Watcher::changed`] says whether the folder
/// changed since and has settled.
pub struct Watcher {
    dir: PathBuf,
    last: BTreeMap<PathBuf, Stamp>,
}

impl Watcher {
    pub fn new(dir: &Path) -> Watcher {
        Watcher {
            dir: dir.to_path_buf(),
            last: scan(dir),
        }
    }

    /// Blocks for at least one poll; true when a source was added, removed
    /// or modified (and the folder then stayed unchanged for one poll).
    /// False as soon as `stop` is set.
    pub fn changed(&mut self, stop: &AtomicBool) -> bool {
        std::thread::sleep(POLL);
        let now = scan(&self.dir);
        if now == self.last {
            return false;
        }
        let mut settled = now;
        loop {
            if stop.load(Ordering::SeqCst) {
                return false;
            }
            std::thread::sleep(POLL);
            let again = scan(&self.dir);
            if again == settled {
                break;
            }
            settled = again;
        }
        self.last = settled;
        true
    }
}
