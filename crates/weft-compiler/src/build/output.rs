//! Writing a build's files: atomically, removing stale files, or checking
//! that a folder already holds exactly those bytes.
//!
//! # Kill-safe, concurrent-safe replacement of an output folder
//!
//! [`write_atomically`] (and [`OutputLock::write`]) write every file into a
//! temporary folder beside the target, `.<name>.tmp-XXXXXX`, then swap it in:
//!
//! - **Linux, Android, Apple**: one atomic exchange (`renameat2` with
//!   `RENAME_EXCHANGE`, `renamex_np` with `RENAME_SWAP`). At every instant
//!   `<name>` is either the complete old tree or the complete new one, even if
//!   the process is killed (`SIGKILL`) at any point; afterwards the old tree,
//!   now under the temporary name, is removed.
//! - **Elsewhere**, or on a file system without the exchange (e.g. NFS):
//!   two renames, `<name>` → `.<name>.old-XXXXXX` then the new tree →
//!   `<name>`. A kill between the two leaves no `<name>` until the next
//!   build into it, which first renames the `.old-` tree back.
//! - A first build into a missing `<name>` is a single rename.
//!
//! Leftover `.<name>.tmp-*` / `.<name>.old-*` folders of a killed build are
//! removed by the next build into `<name>`, under the lock below (so never
//! those of a live build). Files are not `fsync`ed: this protects against
//! killed processes, not against power loss.
//!
//! **Concurrency.** A build takes an exclusive advisory lock on
//! `.<name>.lock` beside the folder (`flock` on Unix, `LockFileEx` elsewhere;
//! released by the OS when the process dies, so it is never stale) for the
//! whole replacement. A second build into the same folder waits for it, up
//! to a bounded time ([`DEFAULT_LOCK_WAIT`] for [`write_atomically`]), then
//! fails with an error naming the folder and the holder (pid and command
//! line, which the holder writes into the lock file). The lock file stays.
//! `weft build` takes the lock before reading the old folder for reuse, so
//! the files it reuses cannot be swapped under it. A folder inside another
//! output folder (`generated/scenes/<scene>`) has its own lock, not
//! serialised with a build of the outer folder.
//!
//! **Errors.** An output folder without any write permission bit is refused
//! (it is not replaced), whoever runs the build. Errors creating the lock or
//! temporary folder, writing a file (full disk), or swapping name the path;
//! in every case the old folder is left as it was.
//!
//! Paths listed in `preserve` (e.g. measured reports, which only
//! `regenerate --reports` rewrites) are carried over untouched.

use std::collections::BTreeMap;
use std::fs::File;
use std::io::{self, Seek, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

pub use crate::build::staging::Staging;

/// How long [`write_atomically`] waits for another build writing into the
/// same folder before giving up.
pub const DEFAULT_LOCK_WAIT: Duration = Duration::from_secs(120);

/// Random characters in the temporary folders' names.
const RAND_LEN: usize = 6;

/// What differs between a build and a folder on disk.
#[derive(Debug, Default, PartialEq)]
pub struct Staleness {
    pub changed: Vec<String>,
    pub missing: Vec<String>,
    /// Files on disk the build would remove.
    pub extra: Vec<String>,
}

impl Staleness {
    pub fn is_clean(&self) -> bool {
        self.changed.is_empty() && self.missing.is_empty() && self.extra.is_empty()
    }
}

pub(crate) fn is_preserved(rel: &str, preserve: &[&str]) -> bool {
    preserve
        .iter()
        .any(|p| rel == *p || rel.starts_with(&format!("{p}/")))
}

/// Whether `file_name` is one of the lock files or temporary folders that
/// writing an output folder creates beside it (`.<name>.lock`,
/// `.<name>.tmp-XXXXXX`, `.<name>.old-XXXXXX`), or the output marker
/// ([`crate::build::ownership::OUTPUT_MARKER`]) every build puts inside it. Those of a folder inside an
/// output folder (a scene's, the gallery's) live in it, so the staleness
/// check ignores them.
fn is_internal_name(file_name: &str) -> bool {
    if file_name == crate::build::ownership::OUTPUT_MARKER {
        return true;
    }
    let Some(rest) = file_name.strip_prefix('.') else {
        return false;
    };
    if [".lock", ".stamp"]
        .iter()
        .any(|ext| rest.len() > ext.len() && rest.ends_with(ext))
    {
        return true;
    }
    [".tmp-", ".old-"].iter().any(|tag| {
        rest.rfind(tag).is_some_and(|i| {
            let suffix = &rest[i + tag.len()..];
            i > 0 && is_random_suffix(suffix)
        })
    })
}

fn is_random_suffix(s: &str) -> bool {
    s.len() == RAND_LEN && s.bytes().all(|b| b.is_ascii_alphanumeric())
}

/// Every file under `dir`, relative, with `/` separators, sorted.
pub fn list_files(dir: &Path) -> io::Result<Vec<String>> {
    let mut out = Vec::new();
    if !dir.exists() {
        return Ok(out);
    }
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d)? {
            let e = e?;
            let p = e.path();
            // Not followed: a link to a folder is listed as itself.
            if e.file_type()?.is_dir() {
                stack.push(p);
            } else {
                let rel = p
                    .strip_prefix(dir)
                    .expect("under dir")
                    .to_string_lossy()
                    .replace('\\', "/");
                out.push(rel);
            }
        }
    }
    out.sort();
    Ok(out)
}

/// Compares `files` with `dir` (ignoring preserved paths, and the lock
/// files and temporary folders of builds into subfolders such as scenes).
pub fn check(
    dir: &Path,
    files: &BTreeMap<String, Vec<u8>>,
    preserve: &[&str],
) -> io::Result<Staleness> {
    let mut s = Staleness::default();
    for (rel, bytes) in files {
        match std::fs::read(dir.join(rel)) {
            Ok(disk) if disk == *bytes => {}
            Ok(_) => s.changed.push(rel.clone()),
            Err(_) => s.missing.push(rel.clone()),
        }
    }
    for rel in list_files(dir)? {
        if !files.contains_key(&rel)
            && !is_preserved(&rel, preserve)
            && !rel.split('/').any(is_internal_name)
        {
            s.extra.push(rel);
        }
    }
    Ok(s)
}

/// Replaces `dir` with exactly `files` (plus preserved paths from the old
/// `dir`): kill-safe and serialised with other builds into `dir`, waiting up
/// to [`DEFAULT_LOCK_WAIT`] for them (see the module documentation).
pub fn write_atomically(
    dir: &Path,
    files: &BTreeMap<String, Vec<u8>>,
    preserve: &[&str],
) -> io::Result<()> {
    OutputLock::acquire(dir, DEFAULT_LOCK_WAIT, &mut |_| {})?.write(files, preserve)
}

/// Adds the path an operation failed on to an I/O error.
pub(crate) fn at(path: &Path, what: &str) -> impl FnOnce(io::Error) -> io::Error {
    let msg = format!("{what} `{}`", path.display());
    move |e| io::Error::new(e.kind(), format!("{msg}: {e}"))
}

/// The exclusive right to replace one output folder, held until dropped.
///
/// Take it before reading the old folder (e.g. to reuse unchanged files) so
/// that no other build swaps it in between; [`OutputLock::write`] then
/// replaces the folder.
pub struct OutputLock {
    dir: PathBuf,
    parent: PathBuf,
    name: String,
    // Holds the lock; the OS releases it when the file is closed or the
    // process dies.
    _file: File,
}

impl OutputLock {
    /// Locks `dir` (creating its parent folders and `.<name>.lock` beside
    /// it), waiting up to `wait` for another build holding it; `on_wait` is
    /// called once, with a description of the holder, if it has to wait.
    /// Then recovers or removes what a killed earlier build left beside it.
    pub fn acquire(
        dir: &Path,
        wait: Duration,
        on_wait: &mut dyn FnMut(&str),
    ) -> io::Result<OutputLock> {
        let name = match dir.file_name() {
            Some(n) => n.to_string_lossy().into_owned(),
            None => {
                return Err(io::Error::new(
                    io::ErrorKind::InvalidInput,
                    format!(
                        "`{}` does not name a folder that can be replaced; give its name (e.g. `out`)",
                        dir.display()
                    ),
                ));
            }
        };
        let parent = dir
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .unwrap_or(Path::new("."))
            .to_path_buf();
        // Refused before the lock file is made: a folder weft may not
        // replace gets nothing written beside it. Checked again under the
        // lock before the swap.
        if std::fs::metadata(dir).is_ok_and(|m| m.is_dir()) {
            let stamp = parent.join(format!(".{name}.stamp"));
            crate::build::ownership::check_replaceable(dir, &stamp)?;
        }
        std::fs::create_dir_all(&parent).map_err(at(&parent, "cannot create folder"))?;
        let lock_path = parent.join(format!(".{name}.lock"));
        let (mut file, writable) = open_lock_file(&lock_path)?;
        let started = Instant::now();
        let mut waited = false;
        loop {
            if try_lock(&file).map_err(at(&lock_path, "cannot lock"))? {
                if still_linked(&file, &lock_path) {
                    break;
                }
                // The holder we waited for removed the file (its build into
                // a missing folder failed): lock the file now at that path.
                drop(file);
                file = open_lock_file(&lock_path)?.0;
                continue;
            }
            let holder = std::fs::read_to_string(&lock_path)
                .ok()
                .map(|s| s.trim().to_string())
                .filter(|s| !s.is_empty())
                .unwrap_or_else(|| "another process".into());
            if started.elapsed() >= wait {
                return Err(io::Error::new(
                    io::ErrorKind::ResourceBusy,
                    format!(
                        "another build is writing into `{}` ({holder}; lock file `{}`); \
                         gave up after waiting {:.0} s",
                        dir.display(),
                        lock_path.display(),
                        wait.as_secs_f64()
                    ),
                ));
            }
            if !waited {
                waited = true;
                on_wait(&holder);
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        // Who holds it, for the message of a build that has to wait.
        let args: Vec<String> = std::env::args().collect();
        let holder = format!("pid {}: {}", std::process::id(), args.join(" "));
        if writable {
            let _ = file
                .set_len(0)
                .and_then(|()| file.rewind())
                .and_then(|()| file.write_all(holder.as_bytes()));
        }
        let lock = OutputLock {
            dir: dir.to_path_buf(),
            parent,
            name,
            _file: file,
        };
        lock.recover();
        Ok(lock)
    }

    /// The folder this lock is for.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Leftovers of a killed build into this folder: if the folder is
    /// missing (killed between the two renames of the fallback), the newest
    /// `.old-` tree is renamed back; every other `.tmp-`/`.old-` folder is
    /// removed. Only called with the lock held, so none belongs to a live
    /// build. Best effort: what cannot be removed now is retried next time.
    fn recover(&self) {
        let Ok(entries) = std::fs::read_dir(&self.parent) else {
            return;
        };
        let tmp = format!(".{}.tmp-", self.name);
        let old = format!(".{}.old-", self.name);
        let mut stale = Vec::new();
        let mut olds = Vec::new();
        for e in entries.flatten() {
            let file_name = e.file_name().to_string_lossy().into_owned();
            let path = e.path();
            if file_name.strip_prefix(&old).is_some_and(is_random_suffix) {
                let mtime = e.metadata().and_then(|m| m.modified()).ok();
                olds.push((mtime, path));
            } else if file_name.strip_prefix(&tmp).is_some_and(is_random_suffix) {
                stale.push(path);
            }
        }
        olds.sort();
        if std::fs::symlink_metadata(&self.dir).is_err()
            && let Some((_, newest)) = olds.pop()
        {
            let _ = std::fs::rename(&newest, &self.dir);
        }
        for path in stale.into_iter().chain(olds.into_iter().map(|(_, p)| p)) {
            // A stamp's temporary file, or a tree.
            if path.is_file() {
                let _ = std::fs::remove_file(path);
            } else {
                let _ = std::fs::remove_dir_all(path);
            }
        }
    }

    /// Replaces the folder with exactly `files` (plus preserved paths from
    /// the old folder). On any error the old folder is left as it was.
    pub fn write(&self, files: &BTreeMap<String, Vec<u8>>, preserve: &[&str]) -> io::Result<()> {
        let mut staging = self.stage()?;
        for (rel, bytes) in files {
            staging.put_ref(rel, bytes)?;
        }
        staging.commit(preserve)
    }

    /// Starts a new tree for this folder that files are added to one at a
    /// time ([`Staging::put`], [`Staging::link`]) and that replaces the
    /// folder on [`Staging::commit`]; dropped uncommitted, it vanishes.
    pub fn stage(&self) -> io::Result<Staging<'_>> {
        Staging::new(self)
    }

    /// Where the folder exists, whether it may be replaced.
    pub(crate) fn existing(&self) -> io::Result<bool> {
        let dir = &self.dir;
        match std::fs::metadata(dir) {
            Ok(m) if !m.is_dir() => Err(io::Error::new(
                io::ErrorKind::AlreadyExists,
                format!("`{}` exists and is not a folder", dir.display()),
            )),
            Ok(m) if m.permissions().readonly() => Err(io::Error::new(
                io::ErrorKind::PermissionDenied,
                format!(
                    "`{}` is read-only (no write permission); not replacing it",
                    dir.display()
                ),
            )),
            Ok(_) => {
                crate::build::ownership::check_replaceable(dir, &self.stamp_path())?;
                Ok(true)
            }
            Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(false),
            Err(e) => Err(at(dir, "cannot read")(e)),
        }
    }

    /// A temporary folder beside the output folder, for a new tree.
    pub(crate) fn temp_dir(&self) -> io::Result<tempfile::TempDir> {
        tempfile::Builder::new()
            .prefix(&format!(".{}.tmp-", self.name))
            .rand_bytes(RAND_LEN)
            .tempdir_in(&self.parent)
            .map_err(at(&self.parent, "cannot create a temporary folder in"))
    }

    /// A temporary file beside the output folder, named like its temporary
    /// folders (so a killed build's is removed by the next).
    pub(crate) fn temp_file(&self) -> io::Result<tempfile::NamedTempFile> {
        tempfile::Builder::new()
            .prefix(&format!(".{}.tmp-", self.name))
            .rand_bytes(RAND_LEN)
            .tempfile_in(&self.parent)
    }

    /// Puts the complete tree `tmp` in place of the folder (see the module
    /// documentation); on error the old folder is left as it was.
    pub(crate) fn swap_in(&self, tmp: tempfile::TempDir, existed: bool) -> io::Result<()> {
        let dir = &self.dir;
        if !existed {
            // Dropping `tmp` on error removes the new tree.
            std::fs::rename(tmp.path(), dir).map_err(at(dir, "cannot replace"))?;
            let _ = tmp.keep();
            return Ok(());
        }
        if exchange(tmp.path(), dir).map_err(at(dir, "cannot replace"))? {
            // `tmp` now holds the old tree; dropping it removes it (if that
            // fails, the next build into `dir` retries).
            drop(tmp);
            return Ok(());
        }
        self.replace_by_renames(tmp)
    }

    /// `.<name>.stamp` beside the folder (see [`crate::build::stamp`]).
    pub(crate) fn stamp_path(&self) -> PathBuf {
        self.parent.join(format!(".{}.stamp", self.name))
    }

    /// The fallback swap: two renames, between which `dir` does not exist
    /// (see the module documentation for how the next build recovers).
    fn replace_by_renames(&self, tmp: tempfile::TempDir) -> io::Result<()> {
        let dir = &self.dir;
        let tmp_name = tmp.path().file_name().unwrap_or_default().to_string_lossy();
        let suffix = tmp_name
            .strip_prefix(&format!(".{}.tmp-", self.name))
            .unwrap_or("000000");
        let old = self.parent.join(format!(".{}.old-{suffix}", self.name));
        std::fs::rename(dir, &old).map_err(at(dir, "cannot replace"))?;
        if let Err(e) = std::fs::rename(tmp.path(), dir) {
            // Put the old tree back rather than leave nothing.
            let _ = std::fs::rename(&old, dir);
            return Err(at(dir, "cannot replace")(e));
        }
        let _ = tmp.keep();
        let _ = std::fs::remove_dir_all(&old);
        Ok(())
    }
}

impl Drop for OutputLock {
    /// A build into a missing folder that failed leaves nothing beside it:
    /// the lock file is removed while still held. Builds waiting on it notice
    /// (see [`still_linked`]) and lock a new one.
    fn drop(&mut self) {
        if cfg!(unix) && std::fs::symlink_metadata(&self.dir).is_err() {
            let _ = std::fs::remove_file(self.parent.join(format!(".{}.lock", self.name)));
        }
    }
}

/// Opens (creating) a lock file; read-only where it is someone else's
/// (locking works on it, only the holder's description is not written).
fn open_lock_file(lock_path: &Path) -> io::Result<(File, bool)> {
    match std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(lock_path)
    {
        Ok(f) => Ok((f, true)),
        Err(e) => match File::open(lock_path) {
            Ok(f) => Ok((f, false)),
            Err(_) => Err(at(lock_path, "cannot open lock file")(e)),
        },
    }
}

/// Whether the locked `file` is still the one at `path` (not removed by
/// the holder before us).
#[cfg(unix)]
fn still_linked(file: &File, path: &Path) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (file.metadata(), std::fs::metadata(path)) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

#[cfg(not(unix))]
fn still_linked(_: &File, _: &Path) -> bool {
    // Lock files are never removed there (see `Drop for OutputLock`).
    true
}

/// Takes an exclusive lock on `file` if nobody holds one; `Ok(false)` if
/// someone does.
#[cfg(unix)]
fn try_lock(file: &File) -> io::Result<bool> {
    use rustix::fs::{FlockOperation, flock};
    match flock(file, FlockOperation::NonBlockingLockExclusive) {
        Ok(()) => Ok(true),
        Err(e) if e == rustix::io::Errno::WOULDBLOCK => Ok(false),
        Err(e) => Err(e.into()),
    }
}

#[cfg(not(unix))]
#[allow(clippy::incompatible_msrv)] // std's file locks: Rust 1.89
fn try_lock(file: &File) -> io::Result<bool> {
    match file.try_lock() {
        Ok(()) => Ok(true),
        Err(std::fs::TryLockError::WouldBlock) => Ok(false),
        Err(std::fs::TryLockError::Error(e)) => Err(e),
    }
}

/// Atomically exchanges the two existing paths; `Ok(false)` where the
/// platform or file system cannot.
#[cfg(any(target_os = "linux", target_os = "android", target_vendor = "apple"))]
fn exchange(a: &Path, b: &Path) -> io::Result<bool> {
    use rustix::fs::{CWD, RenameFlags, renameat_with};
    use rustix::io::Errno;
    match renameat_with(CWD, a, CWD, b, RenameFlags::EXCHANGE) {
        Ok(()) => Ok(true),
        Err(e) if e == Errno::INVAL || e == Errno::NOSYS || e == Errno::NOTSUP => Ok(false),
        Err(e) => Err(e.into()),
    }
}

#[cfg(not(any(target_os = "linux", target_os = "android", target_vendor = "apple")))]
fn exchange(_: &Path, _: &Path) -> io::Result<bool> {
    Ok(false)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entries(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn writes_checks_and_preserves() {
        let root = tempfile::tempdir().unwrap();
        let dir = root.path().join("generated");
        let mut files = BTreeMap::new();
        files.insert("a/x.txt".to_string(), b"one".to_vec());
        write_atomically(&dir, &files, &["reports"]).unwrap();
        std::fs::create_dir_all(dir.join("reports")).unwrap();
        std::fs::write(dir.join("reports/r.md"), "kept").unwrap();
        std::fs::write(dir.join("a/stale.txt"), "old").unwrap();
        let s = check(&dir, &files, &["reports"]).unwrap();
        assert_eq!(s.extra, vec!["a/stale.txt".to_string()]);
        files.insert("b.txt".into(), b"two".to_vec());
        write_atomically(&dir, &files, &["reports"]).unwrap();
        assert!(check(&dir, &files, &["reports"]).unwrap().is_clean());
        assert_eq!(
            std::fs::read_to_string(dir.join("reports/r.md")).unwrap(),
            "kept"
        );
        assert!(!dir.join("a/stale.txt").exists());
        // No temporary folders left behind, only the lock file.
        assert_eq!(
            entries(root.path()),
            [".generated.lock", ".generated.stamp", "generated"]
        );
    }

    #[test]
    fn a_folder_weft_did_not_write_is_never_replaced() {
        let root = tempfile::tempdir().unwrap();
        let project = root.path().join("project");
        let source = project.join("materials/velvet/velvet.toml");
        std::fs::create_dir_all(source.parent().unwrap()).unwrap();
        std::fs::write(&source, "[material]").unwrap();
        let mut files = BTreeMap::new();
        files.insert("x.txt".to_string(), b"new".to_vec());
        let e = write_atomically(&project, &files, &[]).unwrap_err();
        assert!(e.to_string().contains("not a folder weft built"), "{e}");
        assert_eq!(std::fs::read_to_string(&source).unwrap(), "[material]");
        assert!(!project.join("x.txt").exists());
        // An empty folder is taken, marked, and replaced by the next build.
        let empty = root.path().join("empty");
        std::fs::create_dir(&empty).unwrap();
        write_atomically(&empty, &files, &[]).unwrap();
        assert!(empty.join(crate::build::ownership::OUTPUT_MARKER).is_file());
        files.insert("y.txt".to_string(), b"more".to_vec());
        write_atomically(&empty, &files, &[]).unwrap();
        assert!(check(&empty, &files, &[]).unwrap().is_clean());
    }

    #[test]
    fn leftovers_of_a_killed_build_are_recovered_or_removed() {
        let root = tempfile::tempdir().unwrap();
        let dir = root.path().join("out");
        let mut files = BTreeMap::new();
        files.insert("x.txt".to_string(), b"new".to_vec());
        // Killed between the two renames of the fallback: no `out`, the old
        // tree under `.out.old-`, a half-written `.out.tmp-`.
        std::fs::create_dir_all(root.path().join(".out.old-AbC123")).unwrap();
        std::fs::write(root.path().join(".out.old-AbC123/x.txt"), "old").unwrap();
        let marker = crate::build::ownership::OUTPUT_MARKER;
        std::fs::write(root.path().join(".out.old-AbC123").join(marker), "").unwrap();
        std::fs::create_dir_all(root.path().join(".out.tmp-zzz999/sub")).unwrap();
        // Not ours: other names, wrong suffixes.
        std::fs::create_dir_all(root.path().join(".other.tmp-abc123")).unwrap();
        std::fs::create_dir_all(root.path().join(".out.tmp-toolong1")).unwrap();
        let lock = OutputLock::acquire(&dir, Duration::ZERO, &mut |_| {}).unwrap();
        assert_eq!(std::fs::read_to_string(dir.join("x.txt")).unwrap(), "old");
        lock.write(&files, &[]).unwrap();
        drop(lock);
        assert_eq!(std::fs::read_to_string(dir.join("x.txt")).unwrap(), "new");
        assert_eq!(
            entries(root.path()),
            [
                ".other.tmp-abc123",
                ".out.lock",
                ".out.stamp",
                ".out.tmp-toolong1",
                "out"
            ]
        );
    }

    #[test]
    fn a_second_build_waits_then_fails_naming_the_folder_and_holder() {
        let root = tempfile::tempdir().unwrap();
        let dir = root.path().join("out");
        let held = OutputLock::acquire(&dir, Duration::ZERO, &mut |_| {}).unwrap();
        let mut told = None;
        let started = Instant::now();
        let err = OutputLock::acquire(&dir, Duration::from_millis(200), &mut |h| {
            told = Some(h.to_string())
        })
        .err()
        .expect("locked");
        assert!(started.elapsed() >= Duration::from_millis(200));
        let msg = err.to_string();
        let pid = format!("pid {}", std::process::id());
        assert!(msg.contains(&format!("`{}`", dir.display())), "{msg}");
        assert!(msg.contains(&pid), "{msg}");
        assert!(told.unwrap().contains(&pid));
        drop(held);
        OutputLock::acquire(&dir, Duration::ZERO, &mut |_| {}).unwrap();
    }

    #[test]
    fn errors_leave_the_old_folder() {
        let root = tempfile::tempdir().unwrap();
        let dir = root.path().join("out");
        let mut old = BTreeMap::new();
        old.insert("x.txt".to_string(), b"old".to_vec());
        write_atomically(&dir, &old, &[]).unwrap();
        // A file path that cannot be written (a file where a folder must be).
        let mut bad = BTreeMap::new();
        bad.insert("x.txt".to_string(), b"new".to_vec());
        bad.insert("x.txt/y".to_string(), b"new".to_vec());
        let msg = write_atomically(&dir, &bad, &[]).unwrap_err().to_string();
        assert!(msg.contains("cannot write") && msg.contains("y`"), "{msg}");
        assert!(check(&dir, &old, &[]).unwrap().is_clean());
        // A read-only output folder is refused, even for root.
        let mut perms = std::fs::metadata(&dir).unwrap().permissions();
        perms.set_readonly(true);
        std::fs::set_permissions(&dir, perms.clone()).unwrap();
        let msg = write_atomically(&dir, &old, &[]).unwrap_err().to_string();
        assert!(msg.contains("read-only") && msg.contains("out`"), "{msg}");
        #[allow(clippy::permissions_set_readonly_false)]
        perms.set_readonly(false);
        std::fs::set_permissions(&dir, perms).unwrap();
        assert!(check(&dir, &old, &[]).unwrap().is_clean());
        assert_eq!(entries(root.path()), [".out.lock", ".out.stamp", "out"]);
    }

    #[test]
    fn the_two_rename_fallback_replaces_the_folder() {
        let root = tempfile::tempdir().unwrap();
        let dir = root.path().join("out");
        let mut old = BTreeMap::new();
        old.insert("x.txt".to_string(), b"old".to_vec());
        write_atomically(&dir, &old, &[]).unwrap();
        let lock = OutputLock::acquire(&dir, Duration::ZERO, &mut |_| {}).unwrap();
        let tmp = tempfile::Builder::new()
            .prefix(".out.tmp-")
            .rand_bytes(RAND_LEN)
            .tempdir_in(root.path())
            .unwrap();
        std::fs::write(tmp.path().join("y.txt"), "new").unwrap();
        lock.replace_by_renames(tmp).unwrap();
        assert_eq!(list_files(&dir).unwrap(), ["y.txt"]);
        assert_eq!(entries(root.path()), [".out.lock", ".out.stamp", "out"]);
    }

    #[test]
    fn internal_names() {
        assert!(is_internal_name(".fitting_room.lock"));
        assert!(is_internal_name(".generated.tmp-a1B2c3"));
        assert!(is_internal_name(".a.b.old-a1B2c3"));
        assert!(!is_internal_name(".lock"));
        assert!(!is_internal_name("x.lock"));
        assert!(!is_internal_name(".x.tmp-short"));
    }
}
