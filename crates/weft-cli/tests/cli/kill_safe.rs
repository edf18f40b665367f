//! `weft build` replacing an existing output folder is kill-safe and
//! concurrent-safe: SIGKILL at any point leaves the complete old or the
//! complete new output, two builds into one folder never interleave, and a
//! folder that cannot be written (read-only, full) gives a clear error and
//! keeps the old output. See `weft_compiler::output`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};
use weft_compiler::output::{self, OutputLock};
use weft_tests::{copy_dir, repo};

type Tree = BTreeMap<String, Vec<u8>>;

/// The tests of this file run one at a time: the kill test measures how long
/// a build takes, which other builds running beside it would change.
static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn serial() -> std::sync::MutexGuard<'static, ()> {
    SERIAL.lock().unwrap_or_else(|e| e.into_inner())
}

fn weft() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_weft"));
    c.arg("--color").arg("never");
    c
}

fn build(inputs: &Path, out: &Path, extra: &[&str]) -> Command {
    let mut c = weft();
    c.arg("build").arg(inputs).arg("-o").arg(out).args(extra);
    c
}

fn run(mut c: Command) -> Output {
    c.output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Every file under `dir` with its bytes (empty if `dir` is missing).
fn tree(dir: &Path) -> Tree {
    output::list_files(dir)
        .unwrap()
        .into_iter()
        .map(|rel| {
            let bytes = std::fs::read(dir.join(&rel)).unwrap();
            (rel, bytes)
        })
        .collect()
}

/// Replaces `dir` by `files`, the way a user might have left it.
fn put(dir: &Path, files: &Tree) {
    if dir.exists() {
        std::fs::remove_dir_all(dir).unwrap();
    }
    for (rel, bytes) in files {
        let p = dir.join(rel);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, bytes).unwrap();
    }
}

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// Two input libraries whose outputs differ (three shipped materials, and the
/// same with one default changed), and their complete outputs: A (built
/// from scratch) and B (built over A, the way an incremental rebuild does;
/// byte-identical to B built from scratch, which the fixture checks).
struct Fixture {
    root: tempfile::TempDir,
    a_in: PathBuf,
    b_in: PathBuf,
    a: Tree,
    b: Tree,
}

fn fixture() -> Fixture {
    let root = tempfile::tempdir().unwrap();
    let a_in = root.path().join("in_a");
    let b_in = root.path().join("in_b");
    // Three materials (about 670 files), not the whole library: the swap
    // is the same, and each of the tests' ~45 builds takes a tenth as long.
    for input in [&a_in, &b_in] {
        for part in ["lib", "standard", "satin"] {
            copy_dir(&repo().join("materials").join(part), &input.join(part));
        }
    }
    let toml = b_in.join("satin/satin.toml");
    let text = std::fs::read_to_string(&toml).unwrap();
    assert!(text.contains("default = 0.45"));
    std::fs::write(&toml, text.replacen("default = 0.45", "default = 0.5", 1)).unwrap();
    let scratch = root.path().join("scratch");
    let o = run(build(&a_in, &scratch.join("out"), &["-q"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let a = tree(&scratch.join("out"));
    let o = run(build(&b_in, &scratch.join("out"), &["-q"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let b = tree(&scratch.join("out"));
    let o = run(build(&b_in, &scratch.join("out"), &["-q", "--force"]));
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        tree(&scratch.join("out")) == b,
        "an incremental build is byte-identical to a build from scratch"
    );
    std::fs::remove_dir_all(&scratch).unwrap();
    assert!(a.len() > 100, "a build with many files: {}", a.len());
    assert_ne!(a, b, "the changed input changes the output");
    Fixture {
        root,
        a_in,
        b_in,
        a,
        b,
    }
}

/// What a folder holds: A, B, or (a failure) something else.
fn which(f: &Fixture, dir: &Path) -> &'static str {
    let t = tree(dir);
    if t == f.a {
        "A"
    } else if t == f.b {
        "B"
    } else {
        let (a, b) = (&f.a, &f.b);
        let differ = |x: &Tree| {
            t.keys()
                .chain(x.keys())
                .filter(|k| t.get(*k) != x.get(*k))
                .take(5)
                .cloned()
                .collect::<Vec<_>>()
        };
        panic!(
            "`{}` is neither the old nor the new output ({} files; differs from A at {:?}, from B at {:?})",
            dir.display(),
            t.len(),
            differ(a),
            differ(b)
        );
    }
}

// Elsewhere the swap is two renames, with a documented window.
#[cfg(any(target_os = "linux", target_os = "android", target_vendor = "apple"))]
#[test]
fn sigkill_at_any_point_leaves_the_old_or_the_new_output() {
    let _serial = serial();
    let f = fixture();
    let parent = f.root.path().join("kill");
    let out = parent.join("out");
    std::fs::create_dir_all(&parent).unwrap();
    // The time an incremental build of B over A takes, start to exit.
    let mut times = Vec::new();
    for _ in 0..3 {
        put(&out, &f.a);
        let started = Instant::now();
        let o = run(build(&f.b_in, &out, &["-q"]));
        times.push(started.elapsed());
        assert!(o.status.success(), "{}", stderr(&o));
        assert_eq!(which(&f, &out), "B");
    }
    times.sort();
    let t = times[1];
    // Kills spread over 0..1.4 t: while compiling, while writing the new
    // tree, around the swap and after the build (build times vary).
    const KILLS: u32 = 30;
    let mut seen = BTreeMap::<&str, u32>::new();
    let mut finished_first = 0;
    let started = Instant::now();
    for i in 0..KILLS {
        if which(&f, &out) != "A" {
            put(&out, &f.a);
        }
        let delay = t.mul_f64(1.4 * f64::from(i) / f64::from(KILLS - 1));
        let mut child = build(&f.b_in, &out, &["-q"])
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .unwrap();
        std::thread::sleep(delay);
        if child.try_wait().unwrap().is_some() {
            finished_first += 1;
        }
        child.kill().unwrap(); // SIGKILL
        child.wait().unwrap();
        *seen.entry(which(&f, &out)).or_default() += 1;
        // Beside the folder: only the lock file, the stamp of what is in it
        // (crates/weft-compiler/src/build/stamp.rs) and what the next build removes.
        for name in names(&parent) {
            assert!(
                name == "out"
                    || name == ".out.lock"
                    || name == ".out.stamp"
                    || name.starts_with(".out.tmp-"),
                "unexpected `{name}` beside the output"
            );
        }
    }
    eprintln!(
        "build time {t:?}; {KILLS} kills in {:?}: {seen:?} ({finished_first} after the build had exited)",
        started.elapsed()
    );
    assert!(finished_first < KILLS, "no kill landed during a build");
    // A following build cleans up what the killed ones left.
    put(&out, &f.a);
    let o = run(build(&f.b_in, &out, &["-q"]));
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(which(&f, &out), "B");
    assert_eq!(names(&parent), [".out.lock", ".out.stamp", "out"]);
}

#[test]
fn concurrent_builds_into_one_folder_do_not_interleave() {
    let _serial = serial();
    let f = fixture();
    let out = f.root.path().join("conc/out");
    for round in 0..2 {
        // Fresh builds of different inputs, started together.
        let spawn = |inputs: &Path| {
            build(inputs, &out, &["--force"])
                .stdout(Stdio::null())
                .stderr(Stdio::piped())
                .spawn()
                .unwrap()
        };
        let (x, y) = (spawn(&f.a_in), spawn(&f.b_in));
        let (x, y) = (x.wait_with_output().unwrap(), y.wait_with_output().unwrap());
        // Both wait their turn (the default --lock-timeout is long), so both
        // succeed and the folder holds one complete output.
        assert!(x.status.success(), "{}", stderr(&x));
        assert!(y.status.success(), "{}", stderr(&y));
        let now = which(&f, &out);
        eprintln!(
            "round {round}: ends as {now}; builds that waited: {}",
            [&x, &y]
                .iter()
                .filter(|o| stderr(o).contains("waiting up to"))
                .count()
        );
    }
    assert_eq!(
        names(out.parent().unwrap()),
        [".out.lock", ".out.stamp", "out"]
    );

    // Another build holding the lock: with --lock-timeout 0 a build fails at
    // once, naming the folder and the holder, and the folder is untouched.
    let before = which(&f, &out);
    let held = OutputLock::acquire(&out, Duration::ZERO, &mut |_| {}).unwrap();
    let o = run(build(&f.a_in, &out, &["--lock-timeout", "0"]));
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains(&format!(
            "another build is writing into `{}`",
            out.display()
        )),
        "{err}"
    );
    assert!(
        err.contains(&format!("pid {}", std::process::id())),
        "{err}"
    );
    assert!(err.contains("--lock-timeout"), "{err}");
    assert_eq!(which(&f, &out), before);

    // With a timeout, it waits for the holder, then builds.
    let other = if before == "A" { &f.b_in } else { &f.a_in };
    let other_out = if before == "A" { "B" } else { "A" };
    let release = std::thread::spawn(move || {
        std::thread::sleep(Duration::from_millis(500));
        drop(held);
    });
    let started = Instant::now();
    let o = run(build(other, &out, &["--lock-timeout", "30", "--force"]));
    release.join().unwrap();
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("waiting up to 30 s"), "{}", stderr(&o));
    assert!(started.elapsed() >= Duration::from_millis(500));
    assert_eq!(which(&f, &out), other_out);
}

#[cfg(unix)]
fn chmod(p: &Path, mode: u32) {
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(p, std::fs::Permissions::from_mode(mode)).unwrap();
}

/// Whether this process ignores permission bits (root).
#[cfg(unix)]
fn permissions_ignored(scratch: &Path) -> bool {
    let probe = scratch.join("probe");
    std::fs::create_dir_all(&probe).unwrap();
    chmod(&probe, 0o555);
    let ignored = std::fs::write(probe.join("x"), "").is_ok();
    chmod(&probe, 0o755);
    std::fs::remove_dir_all(&probe).unwrap();
    ignored
}

#[cfg(unix)]
#[test]
fn an_unwritable_or_full_output_gives_a_clear_error_and_keeps_the_old_output() {
    let _serial = serial();
    use std::os::unix::process::CommandExt;
    let f = fixture();
    let parent = f.root.path().join("ro");
    let out = parent.join("out");
    let o = run(build(&f.a_in, &out, &["-q"]));
    assert!(o.status.success(), "{}", stderr(&o));
    let intact = |o: &Output, needle: &str| {
        let err = stderr(o);
        assert_eq!(o.status.code(), Some(1), "{err}");
        assert!(err.contains(needle), "expected `{needle}` in: {err}");
        assert!(
            err.contains("the old output is unchanged") || err.contains("lock"),
            "{err}"
        );
        assert_eq!(which(&f, &out), "A");
        assert_eq!(names(&parent), [".out.lock", ".out.stamp", "out"]);
    };

    // A read-only output folder is refused (whoever runs the build).
    chmod(&out, 0o555);
    let o = run(build(&f.b_in, &out, &[]));
    intact(&o, &format!("`{}` is read-only", out.display()));
    chmod(&out, 0o755);

    // A read-only parent: no temporary folder can be made beside the output.
    // Root ignores permission bits, so as root the build runs as `nobody`.
    let as_root = permissions_ignored(f.root.path());
    chmod(f.root.path(), 0o755);
    chmod(&parent.join(".out.lock"), 0o666);
    chmod(&parent, 0o555);
    let mut c = build(&f.b_in, &out, &[]);
    if as_root {
        c.uid(65534).gid(65534);
    }
    match c.output() {
        Ok(o) if o.status.code() == Some(1) || !as_root => {
            intact(
                &o,
                &format!("cannot create a temporary folder in `{}`", parent.display()),
            );
            // Without a lock file, it cannot be created either.
            chmod(&parent, 0o755);
            std::fs::remove_file(parent.join(".out.lock")).unwrap();
            chmod(&parent, 0o555);
            let mut c = build(&f.b_in, &out, &[]);
            if as_root {
                c.uid(65534).gid(65534);
            }
            let o = c.output().unwrap();
            chmod(&parent, 0o755);
            let err = stderr(&o);
            assert_eq!(o.status.code(), Some(1), "{err}");
            assert!(
                err.contains(&format!(
                    "cannot open lock file `{}`",
                    parent.join(".out.lock").display()
                )),
                "{err}"
            );
            assert_eq!(which(&f, &out), "A");
            assert_eq!(names(&parent), [".out.stamp", "out"]);
            eprintln!(
                "read-only parent checked{}",
                if as_root {
                    " (root: the build ran as uid 65534)"
                } else {
                    ""
                }
            );
        }
        other => {
            // Could not run as another user (e.g. no such uid in a user
            // namespace): what is left to check is the read-only folder above.
            chmod(&parent, 0o755);
            eprintln!("read-only parent not checked: running as root and {other:?}");
        }
    }

    // A full disk, simulated by a file size limit: writes past 4 KiB fail
    // (EFBIG) in the middle of writing the new tree.
    let mut c = Command::new("sh");
    c.arg("-c")
        .arg("trap '' XFSZ; ulimit -f 8 && exec \"$@\"")
        .arg("sh")
        .arg(env!("CARGO_BIN_EXE_weft"))
        .args(["--color", "never", "build"])
        .arg(&f.b_in)
        .arg("-o")
        .arg(&out);
    let o = run(c);
    let err = stderr(&o);
    assert!(
        err.contains("cannot write `") && err.contains(".out.tmp-"),
        "{err}"
    );
    intact(&o, "File too large");

    // And a real full file system where one can be mounted (root with
    // CAP_SYS_ADMIN): a tmpfs with room for A but not for A and all of B.
    let mnt = f.root.path().join("tmpfs");
    std::fs::create_dir_all(&mnt).unwrap();
    let a_size: usize = f.a.values().map(|b| b.len().div_ceil(4096) * 4096).sum();
    let size = a_size * 3 / 2;
    let mounted = Command::new("mount")
        .args(["-t", "tmpfs", "-o", &format!("size={size}"), "weft-full"])
        .arg(&mnt)
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    if !mounted {
        eprintln!("tmpfs not mounted: full file system checked by the size limit only");
        return;
    }
    struct Unmount(PathBuf);
    impl Drop for Unmount {
        fn drop(&mut self) {
            let _ = Command::new("umount").arg(&self.0).status();
        }
    }
    let _unmount = Unmount(mnt.clone());
    let out = mnt.join("out");
    let o = run(build(&f.a_in, &out, &["-q"]));
    assert!(o.status.success(), "{}", stderr(&o));
    // --force: every file written anew, which does not fit.
    let o = run(build(&f.b_in, &out, &["--force"]));
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("No space left on device"), "{err}");
    assert!(err.contains("the old output is unchanged"), "{err}");
    assert_eq!(which(&f, &out), "A");
    assert_eq!(names(&mnt), [".out.lock", ".out.stamp", "out"]);
    // Without it, the unchanged materials' files are hard-linked into the
    // new tree, so only satin's new files need room: it fits.
    let o = run(build(&f.b_in, &out, &["-q"]));
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(which(&f, &out), "B");
    eprintln!("full tmpfs checked");
}
