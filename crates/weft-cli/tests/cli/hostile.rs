//! What a careless or hostile user can point `weft` at: folders it must not
//! replace, special files it must not block on or read for ever, shard
//! folders and caches it must not trust blindly, numbers that do not fit.
//! Each case must fail with a clear error, a non-zero exit and nothing
//! written, in bounded time.

use super::{repo, stderr, stdout};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};
use weft_tests::copy_dir;

/// A scratch project: `materials/` with the shared library and `standard`.
fn project() -> tempfile::TempDir {
    let tmp = tempfile::tempdir().unwrap();
    for part in ["lib", "standard"] {
        copy_dir(
            &repo().join("materials").join(part),
            &tmp.path().join("materials").join(part),
        );
    }
    tmp
}

/// Runs `weft` in `dir`, killed (and the test failed) if it has not ended
/// within a minute: a blocking read must not hang the process.
fn weft_in(dir: &Path, args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_weft"))
        .current_dir(dir)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let started = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if started.elapsed() > Duration::from_secs(60) {
            child.kill().unwrap();
            panic!("`weft {args:?}` hung (killed after 60 s)");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

/// Every file under `dir` with its bytes (symbolic links not followed).
fn snapshot(dir: &Path) -> Vec<(PathBuf, Vec<u8>)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let e = e.unwrap();
            let kind = e.file_type().unwrap();
            if kind.is_dir() {
                stack.push(e.path());
            } else if kind.is_file() {
                out.push((e.path(), std::fs::read(e.path()).unwrap()));
            } else {
                out.push((e.path(), Vec::new()));
            }
        }
    }
    out.sort();
    out
}

fn assert_refused(o: &Output, what: &str) {
    assert_eq!(o.status.code(), Some(1), "{what}: {}", stderr(o));
    assert!(!stderr(o).contains("panicked"), "{what}: {}", stderr(o));
}

#[cfg(unix)]
#[test]
fn build_never_replaces_its_inputs_or_a_folder_it_did_not_write() {
    let tmp = project();
    let root = tmp.path();
    std::fs::create_dir(root.join("notes")).unwrap();
    std::fs::write(root.join("notes/todo.txt"), "mine").unwrap();
    std::os::unix::fs::symlink(root.join("materials"), root.join("link")).unwrap();
    let abs = root.canonicalize().unwrap();
    let before = snapshot(root);
    let spellings = [
        "materials".to_string(),
        "materials/".to_string(),
        "materials/standard".to_string(),
        "./materials/standard/".to_string(),
        "notes/../materials".to_string(),
        "link/standard".to_string(),
        "link".to_string(),
        abs.display().to_string(),
        format!("{}/", abs.display()),
        abs.join("materials/standard").display().to_string(),
        format!(
            "{}/../{}",
            abs.display(),
            abs.file_name().unwrap().to_string_lossy()
        ),
        ".".to_string(),
        "notes".to_string(),
    ];
    for out in &spellings {
        let o = weft_in(root, &["build", "materials", "-o", out]);
        assert_refused(&o, out);
        let e = stderr(&o);
        assert!(
            e.contains("nothing was written")
                || e.contains("not a folder weft built")
                || e.contains("does not name a folder"),
            "-o {out}: {e}"
        );
        assert_eq!(snapshot(root), before, "-o {out} changed the project");
    }
    // The inspector's export obeys the same rules.
    let o = weft_in(root, &["serve", "materials", "--export", "materials"]);
    assert_ne!(o.status.code(), Some(0), "{}", stderr(&o));
    assert_eq!(snapshot(root), before, "serve --export changed the project");
    // A new folder is built, marked, and rebuilt.
    let o = weft_in(root, &["build", "materials", "-o", "out"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(root.join("out/.weft-output").is_file());
    let o = weft_in(root, &["build", "materials", "-o", "out", "--force"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[cfg(unix)]
fn mkfifo(path: &Path) {
    let _ = std::fs::remove_file(path);
    let s = Command::new("mkfifo").arg(path).status().unwrap();
    assert!(s.success());
}

#[cfg(unix)]
#[test]
fn special_files_are_refused_not_read() {
    let tmp = project();
    let root = tmp.path();
    // A material TOML inside the root, an include, a scene file, a texture.
    let toml = root.join("materials/fifo/fifo.toml");
    std::fs::create_dir_all(toml.parent().unwrap()).unwrap();
    mkfifo(&toml);
    let o = weft_in(root, &["check", "materials/fifo/fifo.toml"]);
    assert_refused(&o, "material FIFO");
    assert!(stderr(&o).contains("FIFO"), "{}", stderr(&o));
    let o = weft_in(root, &["build", "materials", "-o", "out"]);
    assert_refused(&o, "build with a FIFO material");
    assert!(!root.join("out").exists());
    std::fs::remove_file(&toml).unwrap();

    let include = root.join("materials/lib/forward.wgsl");
    mkfifo(&include);
    let o = weft_in(root, &["check", "materials/standard/standard.toml"]);
    assert_refused(&o, "include FIFO");
    assert!(stderr(&o).contains("FIFO"), "{}", stderr(&o));
    // Copying onto a FIFO would block: remove it first.
    std::fs::remove_file(&include).unwrap();
    std::fs::copy(repo().join("materials/lib/forward.wgsl"), &include).unwrap();

    let scene = root.join("x.scene.toml");
    mkfifo(&scene);
    let o = weft_in(root, &["build", "--scene", "x.scene.toml", "-o", "out"]);
    assert_refused(&o, "scene FIFO");
    assert!(stderr(&o).contains("FIFO"), "{}", stderr(&o));

    let png = root.join("map.png");
    mkfifo(&png);
    for texture in ["base_map=map.png", "base_map=/dev/zero"] {
        let args = [
            "preview",
            "materials/standard/standard.toml",
            "-o",
            "p.png",
            "--texture",
            texture,
        ];
        let o = weft_in(root, &args);
        assert_refused(&o, texture);
        let e = stderr(&o);
        assert!(
            e.contains("FIFO") || e.contains("a device"),
            "{texture}: {e}"
        );
        assert!(!root.join("p.png").exists());
    }
}

#[cfg(unix)]
#[test]
fn a_texture_file_that_is_a_fifo_is_a_diagnostic() {
    let tmp = project();
    let root = tmp.path();
    copy_dir(&repo().join("materials/eye"), &root.join("materials/eye"));
    let texture = root.join("materials/eye/textures/matcap.png");
    assert!(texture.is_file(), "the eye ships its matcap");
    mkfifo(&texture);
    let o = weft_in(root, &["check", "materials/eye/eye.toml"]);
    assert_refused(&o, "texture FIFO");
    let e = stderr(&o);
    assert!(e.contains("FIFO") && e.contains("eye.toml"), "{e}");
}

#[test]
fn an_absurd_lock_timeout_is_a_usage_error() {
    for value in ["1e300", "inf", "NaN", "-1", "86401"] {
        let arg = format!("--lock-timeout={value}");
        let o = weft_in(&repo(), &["build", &arg, "-o", "/nonexistent/x"]);
        assert_eq!(o.status.code(), Some(2), "{value}: {}", stderr(&o));
        assert!(!stderr(&o).contains("panicked"), "{value}: {}", stderr(&o));
        assert!(stderr(&o).contains("--lock-timeout"), "{}", stderr(&o));
    }
    let o = weft_in(
        &repo(),
        &["build", "--shard", "1/99999999999", "-o", "/nonexistent/x"],
    );
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("at most 4096 shards"), "{}", stderr(&o));
}

#[cfg(unix)]
#[test]
fn merge_takes_only_files_the_shards_wrote_from_one_set_of_inputs() {
    let tmp = project();
    let root = tmp.path();
    for k in ["1/2", "2/2"] {
        let out = format!("s{}", &k[..1]);
        let o = weft_in(root, &["build", "materials", "--shard", k, "-o", &out]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let merge = |dir: &Path| weft_in(dir, &["merge", "s1", "s2", "-o", "merged"]);
    let o = merge(root);
    assert!(o.status.success(), "{}", stderr(&o));
    std::fs::remove_dir_all(root.join("merged")).unwrap();
    // The shard holding `standard`.
    let shard = ["s1", "s2"]
        .into_iter()
        .find(|s| root.join(s).join("standard").is_dir())
        .unwrap();
    for planted in ["passwd", "standard/passwd"] {
        let link = root.join(shard).join(planted);
        std::os::unix::fs::symlink("/etc/passwd", &link).unwrap();
        let o = merge(root);
        assert_refused(&o, planted);
        assert!(stderr(&o).contains("not a regular file"), "{}", stderr(&o));
        assert!(!root.join("merged").exists());
        std::fs::remove_file(&link).unwrap();
    }
    std::fs::write(root.join(shard).join("standard/extra.txt"), "x").unwrap();
    let o = merge(root);
    assert_refused(&o, "unlisted file");
    assert!(stderr(&o).contains("metadata lists"), "{}", stderr(&o));
    std::fs::remove_file(root.join(shard).join("standard/extra.txt")).unwrap();
    // The other shard rebuilt from changed sources.
    let other = if shard == "s1" { "s2" } else { "s1" };
    let wgsl = root.join("materials/standard/standard.wgsl");
    let text = std::fs::read_to_string(&wgsl).unwrap();
    std::fs::write(&wgsl, format!("{text}\n// changed\n")).unwrap();
    let k = if other == "s1" { "1/2" } else { "2/2" };
    let o = weft_in(root, &["build", "materials", "--shard", k, "-o", other]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = merge(root);
    assert_refused(&o, "different inputs");
    assert!(stderr(&o).contains("different inputs"), "{}", stderr(&o));
    assert!(!root.join("merged").exists());
}

/// Replaces one unit's WGSL blob and the SHA-256 its unit records,
/// consistently: what a hostile writer of a shared cache can do.
fn forge_one_unit(cache: &Path) {
    let mut units = Vec::new();
    let mut stack = vec![cache.join("v1/units")];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                units.push(p);
            }
        }
    }
    units.sort();
    let unit = &units[0];
    let mut json: serde_json::Value =
        serde_json::from_slice(&std::fs::read(unit).unwrap()).unwrap();
    let files = json["files"].as_array_mut().unwrap();
    let entry = files
        .iter_mut()
        .find(|f| f[0].as_str().unwrap().ends_with(".wgsl"))
        .unwrap();
    let evil = b"// forged\n".to_vec();
    let sha: String = {
        use sha2::Digest;
        sha2::Sha256::digest(&evil)
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect()
    };
    let blob = cache.join("v1/blobs").join(&sha[..2]).join(&sha);
    std::fs::create_dir_all(blob.parent().unwrap()).unwrap();
    std::fs::write(&blob, &evil).unwrap();
    entry[1] = serde_json::Value::String(sha);
    std::fs::write(unit, serde_json::to_vec(&json).unwrap()).unwrap();
}

fn build_with_cache(root: &Path, out: &str, key: Option<&str>, extra: &[&str]) -> Output {
    let mut args = vec!["build", "materials", "-o", out, "--cache-dir", "cache"];
    args.extend(extra);
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_weft"));
    cmd.current_dir(root)
        .args(&args)
        .env_remove("WEFT_CACHE_KEY");
    if let Some(k) = key {
        cmd.env("WEFT_CACHE_KEY", k);
    }
    cmd.output().unwrap()
}

#[test]
fn a_forged_cache_unit_is_caught_by_verification_or_refused_with_a_key() {
    let tmp = project();
    let root = tmp.path();
    let o = build_with_cache(root, "honest", None, &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    forge_one_unit(&root.join("cache"));
    let o = build_with_cache(root, "checked", None, &["--cache-verify", "100"]);
    assert_refused(&o, "verify");
    assert!(stderr(&o).contains("tampered"), "{}", stderr(&o));
    assert!(!root.join("checked").exists());

    // Signed units: a forgery without the key is refused and compiled again.
    std::fs::remove_dir_all(root.join("cache")).unwrap();
    let o = build_with_cache(root, "signed", Some("team secret"), &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    forge_one_unit(&root.join("cache"));
    let o = build_with_cache(root, "again", Some("team secret"), &[]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("1 refused"), "{}", stdout(&o));
    assert_eq!(
        snapshot(&root.join("again"))
            .into_iter()
            .map(|(p, b)| (p.strip_prefix(root.join("again")).unwrap().to_owned(), b))
            .collect::<Vec<_>>(),
        snapshot(&root.join("honest"))
            .into_iter()
            .map(|(p, b)| (p.strip_prefix(root.join("honest")).unwrap().to_owned(), b))
            .collect::<Vec<_>>()
    );
}
