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
use crate::build::library::BuildOutput;
use crate::build::output::is_preserved;
use crate::build::staging::Staging;
use crate::build::stamp::Stamp;
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
    /// Parameters, for their texture files (`texture.file`).
    #[serde(default)]
    parameters: Vec<ParameterFiles>,
}

#[derive(Deserialize)]
struct ParameterFiles {
    #[serde(default)]
    texture: Option<ResourceFiles>,
}

#[derive(Deserialize)]
struct VariantFiles {
    #[serde(default)]
    shader: Option<ShaderFiles>,
}

#[derive(Deserialize)]
struct ShaderFiles {
    files: BTreeMap<String, Vec<FileEntry>>,
    /// Bindings, for the baked tables' files (`resource.file`).
    #[serde(default)]
    bindings: Vec<BindingFiles>,
    /// Half-precision files beside the portable ones (absent when none).
    #[serde(default)]
    f16_files: BTreeMap<String, Vec<FileEntry>>,
}

impl ShaderFiles {
    /// Every file the variant lists, as `VariantShader::all_files` does.
    fn all_files(&self) -> impl Iterator<Item = &FileEntry> {
        self.files
            .values()
            .flatten()
            .chain(self.f16_files.values().flatten())
    }
}

#[derive(Deserialize)]
struct BindingFiles {
    #[serde(default)]
    resource: Option<ResourceFiles>,
}

#[derive(Deserialize)]
struct ResourceFiles {
    #[serde(default)]
    file: Option<TableFile>,
}

/// A `resource.file` (or `texture.file`) with a checksum: a baked table or a
/// texture parameter's image in the material's folder
/// (`<material>/<table>.rgba16f`, `<material>/<param>.rgba8`, relative to the
/// library root).
#[derive(Deserialize)]
struct TableFile {
    path: String,
    #[serde(default)]
    sha256: Option<String>,
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
        let files = listed_files(&meta, name);
        Some(Kept {
            variants: meta.variants.len(),
            files,
        })
    }
}

/// Files of a material's folder (relative to it) and the SHA-256 its
/// metadata records for each (None for the metadata file).
pub(crate) type ListedFiles = Vec<(String, Option<String>)>;

/// Every file of material `name`'s folder its metadata lists (relative to
/// that folder), with the SHA-256 recorded for it (None for the metadata
/// file itself): variant files, baked tables, texture files.
fn listed_files(meta: &MetaFiles, name: &str) -> ListedFiles {
    let mut files: Vec<(String, Option<String>)> = meta
        .variants
        .iter()
        .flat_map(|v| v.shader.iter().flat_map(|s| s.all_files()))
        .map(|f| (f.path.clone(), Some(f.sha256.clone())))
        .collect();
    // Baked tables: files of the material's folder that its bindings name.
    let prefix = format!("{name}/");
    for v in &meta.variants {
        let bindings = v.shader.iter().flat_map(|s| &s.bindings);
        for f in bindings.filter_map(|b| b.resource.as_ref()?.file.as_ref()) {
            if let (Some(rel), Some(sha)) = (f.path.strip_prefix(&prefix), &f.sha256)
                && !files.iter().any(|(p, _)| p == rel)
            {
                files.push((rel.to_string(), Some(sha.clone())));
            }
        }
    }
    // Texture parameters' images (`file`), named by the parameters.
    let images = meta.parameters.iter();
    for f in images.filter_map(|p| p.texture.as_ref()?.file.as_ref()) {
        if let (Some(rel), Some(sha)) = (f.path.strip_prefix(&prefix), &f.sha256)
            && !files.iter().any(|(p, _)| p == rel)
        {
            files.push((rel.to_string(), Some(sha.clone())));
        }
    }
    files.push((format!("{name}.meta.json"), None));
    files
}

/// The files of material `name` in the output folder `out_dir`, as its
/// metadata lists them (see [`listed_files`]), and its inputs hash; None
/// without readable metadata.
pub(crate) fn material_files(out_dir: &Path, name: &str) -> Option<(String, ListedFiles)> {
    let meta = read_meta(out_dir, name)?;
    let files = listed_files(&meta, name);
    Some((meta.inputs_hash, files))
}

fn read_meta(out_dir: &Path, name: &str) -> Option<MetaFiles> {
    let path = out_dir.join(name).join(format!("{name}.meta.json"));
    let bytes = weft_meta::files::read_regular(&path, weft_meta::files::MAX_TEXT_BYTES).ok()?;
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
        self.materials.len()
            + self.dropped_metadata
            + self.kept.as_ref().map_or(0, |k| k.materials.len())
    }

    /// Files the build produced: those in `files` and those kept on disk.
    pub fn file_count(&self) -> usize {
        self.files.len() + self.kept.as_ref().map_or(0, |k| k.files.len())
    }

    /// Whether `dir` already holds exactly this build's files (apart from
    /// `preserve`d paths), so that nothing needs writing: `files` (what the
    /// build handed over: LUTs, schemas, recompiled materials) have the same
    /// bytes there, every kept file is still the one `stamp` recorded when
    /// it was written (same size and modification time), and `dir` holds no
    /// other file. Without a stamp, kept files cannot be vouched for unread:
    /// not up to date.
    pub fn up_to_date(
        &self,
        files: &BTreeMap<String, Vec<u8>>,
        dir: &Path,
        preserve: &[&str],
        stamp: Option<&Stamp>,
    ) -> io::Result<bool> {
        let kept = match (&self.kept, stamp) {
            (Some(k), Some(stamp)) if k.dir == dir => {
                // One `stat` per kept file, spread over the cores.
                if !k.files.par_iter().all(|(rel, _)| stamp.matches(dir, rel)) {
                    return Ok(false);
                }
                &k.files
            }
            (Some(_), _) => return Ok(false),
            (None, _) if dir.exists() => &BTreeMap::new(),
            (None, _) => return Ok(false),
        };
        for (rel, bytes) in files {
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
            if files.contains_key(rel) || kept.contains_key(rel) {
                found += 1;
            } else {
                extra = true;
            }
        })?;
        Ok(!extra && found == files.len() + kept.len())
    }

    /// Adds the kept files to `staging` without copying their bytes (hard
    /// links into the new tree). Each must still be the file its material's
    /// metadata lists: the one `stamp` recorded, or else one whose SHA-256
    /// matches (read and hashed; a metadata file, which has no recorded
    /// hash, must match the stamp). Fails if one is missing (`NotFound`) or
    /// changed (`InvalidData`): build again without `keep_unchanged` to
    /// recompile its material.
    pub fn link_kept(&self, staging: &mut Staging, stamp: Option<&Stamp>) -> io::Result<()> {
        let Some(kept) = &self.kept else {
            return Ok(());
        };
        for (rel, sha) in &kept.files {
            let path = kept.dir.join(rel);
            if !stamp.is_some_and(|s| s.matches(&kept.dir, rel)) {
                // A metadata file has no recorded hash to check it against.
                let Some(sha) = sha else {
                    return Err(changed(&path));
                };
                let bytes = std::fs::read(&path)
                    .map_err(|e| io::Error::new(e.kind(), format!("`{}`: {e}", path.display())))?;
                if crate::compile::digest::sha256_hex(&bytes) != *sha {
                    return Err(changed(&path));
                }
            }
            staging.link(rel, &path)?;
        }
        Ok(())
    }

    /// Reads the kept files into `files` (for a caller that holds the whole
    /// build in memory). Fails as [`BuildOutput::link_kept`] does; every
    /// file with a recorded SHA-256 is read and checked.
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
                && crate::compile::digest::sha256_hex(&bytes) != *sha
            {
                return Err(changed(&path));
            }
            loaded.push((rel.clone(), bytes));
        }
        // Now in `files`; the kept materials stay listed.
        kept.files.clear();
        self.files.extend(loaded);
        Ok(())
    }
}

fn changed(path: &Path) -> io::Error {
    io::Error::new(
        io::ErrorKind::InvalidData,
        format!(
            "`{}` is not the file its metadata lists (changed since it was built)",
            path.display()
        ),
    )
}

/// Calls `each` with every file under `dir` (relative, `/`-separated),
/// not descending into preserved paths. Uses the directory entries' types,
/// so one `getdents` per folder and no `stat` per file on most systems.
pub(crate) fn walk(
    dir: &Path,
    prefix: String,
    preserve: &[&str],
    each: &mut dyn FnMut(&str),
) -> io::Result<()> {
    for e in std::fs::read_dir(dir)? {
        let e = e?;
        let name = e.file_name();
        let rel = format!("{prefix}{}", name.to_string_lossy());
        // The output marker is the folder's, not the build's.
        if is_preserved(&rel, preserve) || name == crate::build::ownership::OUTPUT_MARKER {
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
