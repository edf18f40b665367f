//! The no-change fast path of a library build ([`crate::BuildOptions::keep_unchanged`]).
//!
//! A material whose inputs hash (its TOML, WGSL sources and includes, the
//! toolchain version) equals the one in the `.meta.json` of the previous
//! build is *kept*: its files stay on disk, unread, and its metadata is not
//! parsed beyond the hash and the file list (it is not in
//! `BuildOutput::materials`). [`BuildOutput::up_to_date`] then
//! says whether the output folder needs writing at all (it holds exactly the
//! build's files), and [`BuildOutput::load_kept`] reads the kept files (checking
//! each against the SHA-256 in the metadata) when it does.
//!
//! A no-change rebuild of a large library therefore costs one TOML/WGSL
//! load and hash per material, one metadata parse per material and one
//! directory listing, instead of reading, hashing and rewriting every file
//! (docs/performance.md, "Build scale").

use crate::BuildOptions;
use crate::library::BuildOutput;
use rayon::prelude::*;
use serde::Deserialize;
use std::collections::{BTreeMap, HashMap};
use std::io;
use std::path::{Path, PathBuf};

/// A material kept from a previous build: its variant count and its files
/// (relative to its folder) with their SHA-256 (None for the metadata file).
pub(crate) struct Kept {
    pub variants: usize,
    pub files: Vec<(String, Option<String>)>,
}

/// The part of a `.meta.json` the fast path reads; serde skips the rest
/// without building it (a 48-variant metadata file is over 1 MB).
#[derive(Deserialize)]
struct MetaFiles {
    inputs_hash: String,
    variants: Vec<VariantFiles>,
}

#[derive(Deserialize)]
struct VariantFiles {
    #[serde(default)]
    shader: Option<ShaderFiles>,
}

#[derive(Deserialize)]
struct ShaderFiles {
    files: BTreeMap<String, Vec<FileEntry>>,
}

#[derive(Deserialize)]
struct FileEntry {
    path: String,
    sha256: String,
}

/// The previous build's metadata (the hash and file list) of the materials
/// about to be built, read ahead in parallel: for a large unchanged library,
/// parsing the metadata is most of the work.
#[derive(Default)]
pub(crate) struct Previous(HashMap<String, MetaFiles>);

impl Previous {
    /// With `keep_unchanged`, reads `<reuse_from>/<stem>/<stem>.meta.json`
    /// for each material file `<stem>.toml` in `paths` (a material is named
    /// like its file, as discovered), on `pool`.
    pub fn read(paths: &[PathBuf], options: &BuildOptions, pool: &rayon::ThreadPool) -> Previous {
        let Some(dir) = options
            .reuse_from
            .as_deref()
            .filter(|_| options.keep_unchanged)
        else {
            return Previous::default();
        };
        if !dir.is_dir() {
            return Previous::default();
        }
        let read = || {
            paths
                .par_iter()
                .filter_map(|p| {
                    let name = p.file_stem()?.to_str()?;
                    Some((name.to_string(), read_meta(dir, name)?))
                })
                .collect()
        };
        Previous(pool.install(read))
    }

    /// The previous build of material `name` in `out_dir`, if its metadata
    /// records the inputs hash `hash`. Whether the files it lists are all
    /// there is left to [`BuildOutput::up_to_date`] (one listing of the whole
    /// folder) or [`BuildOutput::load_kept`].
    pub fn keep(&mut self, out_dir: &Path, name: &str, hash: &str) -> Option<Kept> {
        let meta = match self.0.remove(name) {
            Some(m) => m,
            None => read_meta(out_dir, name)?,
        };
        if meta.inputs_hash != hash {
            return None;
        }
        let mut files: Vec<(String, Option<String>)> = meta
            .variants
            .iter()
            .flat_map(|v| v.shader.iter().flat_map(|s| s.files.values().flatten()))
            .map(|f| (f.path.clone(), Some(f.sha256.clone())))
            .collect();
        files.push((format!("{name}.meta.json"), None));
        Some(Kept {
            variants: meta.variants.len(),
            files,
        })
    }
}

fn read_meta(out_dir: &Path, name: &str) -> Option<MetaFiles> {
    let bytes = std::fs::read(out_dir.join(name).join(format!("{name}.meta.json"))).ok()?;
    serde_json::from_slice(&bytes).ok()
}

/// Files kept on disk by a build (relative to the output folder), with the
/// SHA-256 their material's metadata records (None for metadata files).
#[derive(Clone, Debug, Default)]
pub struct KeptFiles {
    /// The folder they are in (the build's `reuse_from`).
    pub dir: PathBuf,
    /// The kept materials, by name.
    pub materials: Vec<String>,
    pub files: BTreeMap<String, Option<String>>,
}

impl BuildOutput {
    /// Materials the build produced: those in `materials` and those kept on disk.
    pub fn material_count(&self) -> usize {
        self.materials.len() + self.kept.as_ref().map_or(0, |k| k.materials.len())
    }

    /// Files the build produced: those in `files` and those kept on disk.
    pub fn file_count(&self) -> usize {
        self.files.len() + self.kept.as_ref().map_or(0, |k| k.files.len())
    }

    /// Whether `dir` already holds exactly this build's files (apart from
    /// `preserve`d paths), so that nothing needs writing: every material was
    /// kept from `dir`, every other file (LUTs, schemas, recompiled
    /// materials) has the same bytes there, and `dir` holds no other file.
    /// Kept files are judged by name (see the module documentation).
    pub fn up_to_date(&self, dir: &Path, preserve: &[&str]) -> io::Result<bool> {
        let kept = match &self.kept {
            Some(k) if k.dir == dir => &k.files,
            Some(_) => return Ok(false),
            None if dir.exists() => &BTreeMap::new(),
            None => return Ok(false),
        };
        for (rel, bytes) in &self.files {
            match std::fs::read(dir.join(rel)) {
                Ok(disk) if disk == *bytes => {}
                Ok(_) => return Ok(false),
                Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(false),
                Err(e) => return Err(e),
            }
        }
        let mut found = 0usize;
        let mut extra = false;
        walk(dir, String::new(), preserve, &mut |rel| {
            if self.files.contains_key(rel) || kept.contains_key(rel) {
                found += 1;
            } else {
                extra = true;
            }
        })?;
        Ok(!extra && found == self.files.len() + kept.len())
    }

    /// Reads the kept files into `files` (for a build that must rewrite the
    /// output folder). Fails if one is missing, or (`InvalidData`) no longer
    /// has the SHA-256 its metadata records: build again without
    /// `keep_unchanged` to recompile its material.
    pub fn load_kept(&mut self) -> io::Result<()> {
        let Some(kept) = self.kept.as_mut() else {
            return Ok(());
        };
        let mut loaded = Vec::with_capacity(kept.files.len());
        for (rel, sha) in &kept.files {
            let path = kept.dir.join(rel);
            let bytes = std::fs::read(&path)
                .map_err(|e| io::Error::new(e.kind(), format!("`{}`: {e}", path.display())))?;
            if let Some(sha) = sha
                && crate::variant::sha256_hex(&bytes) != *sha
            {
                return Err(io::Error::new(
                    io::ErrorKind::InvalidData,
                    format!(
                        "`{}` is not the file its metadata lists (changed since it was built)",
                        path.display()
                    ),
                ));
            }
            loaded.push((rel.clone(), bytes));
        }
        // Now in `files`; the kept materials stay listed.
        kept.files.clear();
        self.files.extend(loaded);
        Ok(())
    }
}

fn is_preserved(rel: &str, preserve: &[&str]) -> bool {
    preserve.iter().any(|p| {
        rel == *p
            || rel
                .strip_prefix(p)
                .is_some_and(|rest| rest.starts_with('/'))
    })
}

/// Calls `each` with every file under `dir` (relative, `/`-separated),
/// not descending into preserved paths. Uses the directory entries' types,
/// so one `getdents` per folder and no `stat` per file on most systems.
fn walk(
    dir: &Path,
    prefix: String,
    preserve: &[&str],
    each: &mut dyn FnMut(&str),
) -> io::Result<()> {
    for e in std::fs::read_dir(dir)? {
        let e = e?;
        let name = e.file_name();
        let rel = format!("{prefix}{}", name.to_string_lossy());
        if is_preserved(&rel, preserve) {
            continue;
        }
        if e.file_type()?.is_dir() {
            walk(&e.path(), format!("{rel}/"), preserve, each)?;
        } else {
            each(&rel);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build_library;

    fn materials() -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../materials")
    }

    fn build(out: &Path, keep: bool) -> BuildOutput {
        let options = BuildOptions {
            reuse_from: Some(out.to_path_buf()),
            keep_unchanged: keep,
            ..Default::default()
        };
        match build_library(&materials(), &options, &|_, _, _| {}) {
            Ok(b) => b,
            Err((db, d)) => panic!("{}", d.render_plain(&db)),
        }
    }

    #[test]
    fn an_unchanged_tree_is_up_to_date_and_a_touched_one_is_not() {
        let tmp = tempfile::tempdir().unwrap();
        let out = tmp.path().join("out");
        let full = build(&out, true);
        assert!(full.kept.is_none() && full.reused.is_empty());
        assert!(!full.up_to_date(&out, &[]).unwrap(), "nothing written yet");
        crate::output::write_atomically(&out, &full.files, &["reports"]).unwrap();

        let again = build(&out, true);
        assert_eq!(again.reused.len(), full.materials.len());
        assert_eq!(again.material_count(), full.materials.len());
        assert!(again.materials.is_empty());
        assert_eq!(again.file_count(), full.files.len());
        assert_eq!(again.variant_count, full.variant_count);
        assert!(again.up_to_date(&out, &["reports"]).unwrap());

        // Preserved paths are ignored; any other extra file is not.
        std::fs::create_dir_all(out.join("reports")).unwrap();
        std::fs::write(out.join("reports/x.md"), "kept").unwrap();
        assert!(again.up_to_date(&out, &["reports"]).unwrap());
        std::fs::write(out.join("standard/stray.txt"), "x").unwrap();
        assert!(!again.up_to_date(&out, &["reports"]).unwrap());
        std::fs::remove_file(out.join("standard/stray.txt")).unwrap();

        // The kept files read back are the full build's bytes.
        let mut loaded = again.clone_kept_for_test();
        loaded.load_kept().unwrap();
        assert_eq!(loaded.files, full.files);

        // A changed output file: still kept by name, but caught when read.
        let victim = full
            .files
            .keys()
            .find(|k| k.starts_with("standard/") && k.ends_with(".wgsl"))
            .unwrap()
            .clone();
        std::fs::write(out.join(&victim), "// edited\n").unwrap();
        let mut tampered = build(&out, true);
        let err = tampered.load_kept().unwrap_err();
        assert_eq!(err.kind(), io::ErrorKind::InvalidData);
        // Without keep_unchanged the material is recompiled.
        let healed = build(&out, false);
        assert!(!healed.reused.contains(&"standard".to_string()));
        assert_eq!(healed.files, full.files);

        // A missing output file: not up to date, and caught when read.
        std::fs::remove_file(out.join(&victim)).unwrap();
        let mut missing = build(&out, true);
        assert!(!missing.up_to_date(&out, &["reports"]).unwrap());
        let err = missing.load_kept().unwrap_err();
        assert_eq!(err.kind(), io::ErrorKind::NotFound);
        let rebuilt = build(&out, false);
        assert!(!rebuilt.reused.contains(&"standard".to_string()));
        assert_eq!(rebuilt.files, full.files);
    }

    impl BuildOutput {
        fn clone_kept_for_test(&self) -> BuildOutput {
            BuildOutput {
                files: self.files.clone(),
                kept: self.kept.clone(),
                ..Default::default()
            }
        }
    }
}
