//! A library build into an output folder, as `weft build` runs it: files
//! stream to disk as each material is compiled ([`crate::build::staging`]),
//! unchanged materials' files are kept from the previous build without
//! being read ([`crate::build::unchanged`], vouched for by [`crate::build::stamp`]), and
//! the folder is replaced whole, or not at all when it already holds
//! exactly this build ([`crate::build::output`]).

use crate::build::library::{BuildOptions, BuildOutput, build_materials_streaming};
use crate::build::output::OutputLock;
use crate::build::ownership::{Input, check_apart};
use crate::build::stamp::Stamp;
use std::io;
use std::path::{Path, PathBuf};
use weft_front::{Diagnostics, SourceDb};

/// What [`build_into`] did.
pub struct FolderBuild {
    /// The build (its `files` and `materials` are empty: they went to the folder).
    pub output: BuildOutput,
    /// Files the folder holds for this build (written, linked or unchanged).
    pub file_count: usize,
    /// False when the folder already held exactly this build.
    pub wrote: bool,
}

/// Why [`build_into`] failed; the folder is unchanged either way.
pub enum FolderBuildError {
    /// The materials do not build.
    Diagnostics(SourceDb, Diagnostics),
    /// The folder could not be written.
    Io(io::Error),
}

/// Builds `paths` (material files; `root` as for
/// [`crate::build_materials`]) into the folder `lock` holds, plus `extra`
/// files (e.g. a shard's marker), keeping `preserve`d paths of the old
/// folder. `options.reuse_from` should be the folder itself (None
/// recompiles everything); `options.keep_unchanged` is decided here: kept
/// files are only trusted unread where a stamp vouches for them.
pub fn build_into(
    paths: &[PathBuf],
    root: Option<&Path>,
    lock: &OutputLock,
    options: &BuildOptions,
    extra: &[(String, Vec<u8>)],
    preserve: &[&str],
    progress: &(dyn Fn(usize, usize, &str) + Sync),
) -> Result<FolderBuild, FolderBuildError> {
    check_inputs_apart(paths, root, lock.dir(), options).map_err(FolderBuildError::Io)?;
    let stamp = Stamp::read(lock);
    let mut keep = options.reuse_from.is_some() && stamp.is_some();
    loop {
        let options = BuildOptions {
            keep_unchanged: keep,
            // The metadata goes to the folder with the rest.
            drop_metadata: true,
            ..options.clone()
        };
        let mut staging = lock.stage().map_err(FolderBuildError::Io)?;
        let mut sink_error = None;
        let built =
            build_materials_streaming(paths, root, &options, progress, &mut |rel, bytes| {
                staging.put(rel, bytes).inspect_err(|e| {
                    sink_error.get_or_insert_with(|| io::Error::new(e.kind(), e.to_string()));
                })
            });
        let output = match built {
            Ok(o) => o,
            // A write error is reported as an I/O error, not as a diagnostic.
            Err(_) if sink_error.is_some() => {
                return Err(FolderBuildError::Io(sink_error.expect("checked")));
            }
            Err((db, diags)) => return Err(FolderBuildError::Diagnostics(db, diags)),
        };
        for (rel, bytes) in extra {
            staging.put_ref(rel, bytes).map_err(FolderBuildError::Io)?;
        }
        // A shard's folder says which shard it is and what it was built
        // from, for `weft merge`.
        if let Some(shard) = options.shard {
            let marker = shard.marker(&output.library_inputs);
            staging
                .put(crate::build::shard::SHARD_MARKER.to_string(), marker)
                .map_err(FolderBuildError::Io)?;
        }
        let kept_count = output.kept.as_ref().map_or(0, |k| k.files.len());
        let file_count = staging.len() + kept_count;
        if let Some(files) = staging.in_memory()
            && output
                .up_to_date(files, lock.dir(), preserve, stamp.as_ref())
                .unwrap_or(false)
        {
            if !keep {
                // Every file was just compared by content: vouch for them
                // (best effort) so the next build need not read them.
                let _ = Stamp::record(lock, preserve);
            }
            return Ok(FolderBuild {
                output,
                file_count,
                wrote: false,
            });
        }
        match output.link_kept(&mut staging, stamp.as_ref()) {
            Ok(()) => {}
            // A kept file changed or vanished since it was built: build
            // again, reading (and checking) what is reused.
            Err(e)
                if keep
                    && matches!(
                        e.kind(),
                        io::ErrorKind::InvalidData | io::ErrorKind::NotFound
                    ) =>
            {
                keep = false;
                continue;
            }
            Err(e) => return Err(FolderBuildError::Io(e)),
        }
        staging.commit(preserve).map_err(FolderBuildError::Io)?;
        return Ok(FolderBuild {
            output,
            file_count,
            wrote: true,
        });
    }
}

/// Refuses an output folder that is, holds or lies inside the materials
/// root (when given), holds a material file, or is or holds the compile cache. [`build_into`]
/// checks it; callers check it before taking the folder's lock, so that a
/// refused build leaves no lock file either.
pub fn check_inputs_apart(
    paths: &[PathBuf],
    root: Option<&Path>,
    out: &Path,
    options: &BuildOptions,
) -> io::Result<()> {
    // The root when one was given (a materials folder); material files
    // named one by one are inputs themselves (their guessed root may be far
    // above them, even `/`).
    let mut inputs: Vec<Input<'_>> = root
        .iter()
        .map(|path| Input {
            what: "materials root",
            path,
        })
        .collect();
    inputs.extend(paths.iter().map(|path| Input {
        what: "material file",
        path,
    }));
    if let Some(path) = &options.cache_dir {
        inputs.push(Input {
            what: "compile cache",
            path,
        });
    }
    check_apart(out, &inputs)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build::output::DEFAULT_LOCK_WAIT;

    fn materials() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../materials")
    }

    /// The shipped library, built in memory: the bytes every folder build must hold.
    fn reference() -> std::collections::BTreeMap<String, Vec<u8>> {
        match crate::build_library(&materials(), &BuildOptions::default(), &|_, _, _| {}) {
            Ok(b) => b.files,
            Err((db, d)) => panic!("{}", d.render_plain(&db)),
        }
    }

    fn build(out: &Path, options: &BuildOptions) -> FolderBuild {
        let lock = OutputLock::acquire(out, DEFAULT_LOCK_WAIT, &mut |_| {}).unwrap();
        let paths = crate::build::library::discover(&materials()).unwrap();
        let options = BuildOptions {
            reuse_from: Some(out.to_path_buf()),
            ..options.clone()
        };
        let preserve = ["reports"];
        match build_into(
            &paths,
            Some(&materials()),
            &lock,
            &options,
            &[],
            &preserve,
            &|_, _, _| {},
        ) {
            Ok(b) => b,
            Err(FolderBuildError::Diagnostics(db, d)) => panic!("{}", d.render_plain(&db)),
            Err(FolderBuildError::Io(e)) => panic!("{e}"),
        }
    }

    fn assert_holds(out: &Path, files: &std::collections::BTreeMap<String, Vec<u8>>) {
        let s = crate::build::output::check(out, files, &["reports"]).unwrap();
        assert!(s.is_clean(), "{}: {s:?}", out.display());
    }

    #[test]
    fn unchanged_is_not_rewritten_and_changed_outputs_are_healed() {
        let full = reference();
        let tmp = tempfile::tempdir().unwrap();
        let out = tmp.path().join("out");
        let first = build(&out, &BuildOptions::default());
        assert!(first.wrote && first.output.reused.is_empty());
        assert_eq!(first.file_count, full.len());
        assert!(
            first.output.materials.is_empty(),
            "metadata went to the folder"
        );
        assert_holds(&out, &full);

        // No change: kept unread, nothing written.
        std::fs::create_dir_all(out.join("reports")).unwrap();
        std::fs::write(out.join("reports/r.md"), "kept").unwrap();
        let again = build(&out, &BuildOptions::default());
        assert!(!again.wrote);
        assert_eq!(again.output.reused.len(), again.output.material_count());
        assert_eq!(again.file_count, full.len());

        // A stray file is removed; preserved paths stay.
        std::fs::write(out.join("standard/stray.txt"), "x").unwrap();
        assert!(build(&out, &BuildOptions::default()).wrote);
        assert_holds(&out, &full);
        assert_eq!(
            std::fs::read_to_string(out.join("reports/r.md")).unwrap(),
            "kept"
        );

        // A kept shader file or metadata file edited by hand, or removed:
        // noticed without --force, its material recompiled.
        let shader = full
            .keys()
            .find(|k| k.starts_with("standard/") && k.ends_with(".wgsl"))
            .unwrap()
            .clone();
        for victim in [shader.as_str(), "velvet/velvet.meta.json"] {
            let path = out.join(victim);
            let mut bytes = std::fs::read(&path).unwrap();
            bytes.extend_from_slice(b"\n");
            std::fs::write(&path, bytes).unwrap();
            assert!(build(&out, &BuildOptions::default()).wrote, "{victim}");
            assert_holds(&out, &full);
            std::fs::remove_file(&path).unwrap();
            assert!(build(&out, &BuildOptions::default()).wrote, "{victim}");
            assert_holds(&out, &full);
            assert!(!build(&out, &BuildOptions::default()).wrote);
        }

        // Without its stamp, a folder is compared by content (here: equal,
        // nothing written) and stamped, so the next build keeps it unread.
        let stamp = tmp.path().join(".out.stamp");
        std::fs::remove_file(&stamp).unwrap();
        let unstamped = build(&out, &BuildOptions::default());
        assert!(
            !unstamped.wrote && unstamped.output.kept.is_none(),
            "wrote {}, kept {:?}",
            unstamped.wrote,
            unstamped.output.kept.is_some()
        );
        assert!(stamp.exists());
        let stamped = build(&out, &BuildOptions::default());
        assert!(!stamped.wrote && stamped.output.kept.is_some());

        // An edit to one material's inputs recompiles only it; the others'
        // files are linked, not copied.
        let before = std::fs::metadata(out.join(&shader)).unwrap();
        let kept_velvet = full
            .keys()
            .find(|k| k.starts_with("velvet/"))
            .unwrap()
            .clone();
        let velvet_before = file_id(&out.join(&kept_velvet));
        let src = tmp.path().join("materials");
        copy(&materials(), &src);
        let standard = src.join("standard/standard.toml");
        let text = std::fs::read_to_string(&standard).unwrap();
        std::fs::write(&standard, format!("{text}\n# edited\n")).unwrap();
        let lock = OutputLock::acquire(&out, DEFAULT_LOCK_WAIT, &mut |_| {}).unwrap();
        let options = BuildOptions {
            reuse_from: Some(out.clone()),
            ..Default::default()
        };
        let paths = crate::build::library::discover(&src).unwrap();
        let Ok(edited) = build_into(&paths, Some(&src), &lock, &options, &[], &[], &|_, _, _| {})
        else {
            panic!("builds");
        };
        drop(lock);
        assert!(edited.wrote);
        assert_eq!(
            edited.output.reused.len(),
            edited.output.material_count() - 1
        );
        assert!(
            std::fs::metadata(out.join(&shader))
                .unwrap()
                .modified()
                .unwrap()
                >= before.modified().unwrap()
        );
        #[cfg(unix)]
        assert_eq!(
            file_id(&out.join(&kept_velvet)),
            velvet_before,
            "hard-linked"
        );
        let _ = velvet_before;
    }

    #[cfg(unix)]
    fn file_id(p: &Path) -> u64 {
        use std::os::unix::fs::MetadataExt;
        std::fs::metadata(p).unwrap().ino()
    }

    #[cfg(not(unix))]
    fn file_id(_: &Path) -> u64 {
        0
    }

    fn copy(from: &Path, to: &Path) {
        std::fs::create_dir_all(to).unwrap();
        for e in std::fs::read_dir(from).unwrap() {
            let p = e.unwrap().path();
            let t = to.join(p.file_name().unwrap());
            if p.is_dir() {
                copy(&p, &t);
            } else {
                std::fs::copy(&p, &t).unwrap();
            }
        }
    }

    #[test]
    fn a_shared_cache_serves_every_unit_with_identical_bytes() {
        let full = reference();
        let tmp = tempfile::tempdir().unwrap();
        let cache = tmp.path().join("cache");
        let options = BuildOptions {
            cache_dir: Some(cache.clone()),
            ..Default::default()
        };
        let cold = build(&tmp.path().join("a"), &options);
        let units = cold.output.variant_count;
        assert_eq!(
            (cold.output.cache_hits, cold.output.cache_misses),
            (0, units)
        );
        assert_holds(&tmp.path().join("a"), &full);
        // Another checkout's first build: every unit from the cache.
        let warm = build(&tmp.path().join("b"), &options);
        assert_eq!(
            (warm.output.cache_hits, warm.output.cache_misses),
            (units, 0)
        );
        assert_holds(&tmp.path().join("b"), &full);

        // A damaged blob is a miss: that unit is compiled again (and stored).
        let blobs = cache.join("v1/blobs");
        let dir = std::fs::read_dir(&blobs)
            .unwrap()
            .next()
            .unwrap()
            .unwrap()
            .path();
        let blob = std::fs::read_dir(&dir)
            .unwrap()
            .next()
            .unwrap()
            .unwrap()
            .path();
        std::fs::write(&blob, b"damaged").unwrap();
        let healed = build(&tmp.path().join("c"), &options);
        assert!(healed.output.cache_misses >= 1);
        assert_eq!(healed.output.cache_hits + healed.output.cache_misses, units);
        assert_holds(&tmp.path().join("c"), &full);

        // A hostile unit naming a file outside its folder is not used.
        let units_dir = cache.join("v1/units");
        let sub = std::fs::read_dir(&units_dir)
            .unwrap()
            .next()
            .unwrap()
            .unwrap()
            .path();
        let unit = std::fs::read_dir(&sub)
            .unwrap()
            .next()
            .unwrap()
            .unwrap()
            .path();
        let text = std::fs::read_to_string(&unit).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        let first = v["files"][0][0].as_str().unwrap().to_string();
        std::fs::write(
            &unit,
            text.replacen(&format!("\"{first}\""), "\"../../escaped.wgsl\"", 1),
        )
        .unwrap();
        let guarded = build(&tmp.path().join("d"), &options);
        assert!(guarded.output.cache_misses >= 1);
        assert_holds(&tmp.path().join("d"), &full);
        assert!(!tmp.path().join("escaped.wgsl").exists());
    }
}
