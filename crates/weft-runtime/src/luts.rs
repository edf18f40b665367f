//! The lookup tables group 0 of the engine interface binds, baked by the
//! toolchain into `generated/luts/` and read here.
//!
//! What a variant binds is found from its metadata: a LUT binding's
//! `resource.file` names the file (relative to the library root), its
//! format and size ([`Luts::texels`]). The CPU-side tables ([`Luts::brdf`],
//! [`Luts::sheen`], for tests and measurements that evaluate them directly)
//! are read from the toolchain's file names below.

use crate::error::{Error, Result};
use std::borrow::Cow;
use std::path::{Path, PathBuf};
use weft_meta::ResourceFile;

/// Location of the split-sum LUT under a generated folder (weft-compiler's
/// `SPLIT_SUM_LUT_PATH`): where [`Luts::load_dir`] reads [`Luts::brdf`].
pub const SPLIT_SUM_LUT_FILE: &str = "luts/split_sum_ggx_64x64_1024spp.rg16f";
/// Location of the Charlie sheen albedo LUT under a generated folder
/// (weft-compiler's `SHEEN_LUT_PATH`): where [`Luts::load_dir`] reads [`Luts::sheen`].
pub const SHEEN_LUT_FILE: &str = "luts/charlie_albedo_32x32_8192spp.r16f";

/// The `resource.id`s of the baked tables.
pub const SPLIT_SUM_LUT_ID: &str = weft_meta::engine::SPLIT_SUM_LUT;
pub const SHEEN_LUT_ID: &str = weft_meta::engine::SHEEN_ALBEDO_LUT;

/// The generated folder of a material's metadata: `<meta dir>/..`.
fn generated_dir(meta_path: &Path) -> &Path {
    meta_path
        .parent()
        .and_then(Path::parent)
        .unwrap_or(Path::new("."))
}

fn read_lut(path: &Path) -> Result<Vec<u8>> {
    weft_meta::files::read_regular(path, weft_meta::files::MAX_BINARY_BYTES).map_err(|e| {
        let hint = if e.kind() == std::io::ErrorKind::NotFound {
            " (run `cargo xtask regenerate` or `weft build` to bake it)"
        } else {
            ""
        };
        Error::Io {
            path: path.to_path_buf(),
            source: std::io::Error::new(e.kind(), format!("{e}{hint}")),
        }
    })
}

fn square_size(len: usize, bytes_per_texel: usize) -> std::result::Result<u32, String> {
    let texels = len / bytes_per_texel;
    let size = (texels as f64).sqrt().round() as u32;
    if !len.is_multiple_of(bytes_per_texel) || (size * size) as usize != texels || size == 0 {
        return Err(format!(
            "{len} bytes is not a square table of {bytes_per_texel}-byte texels"
        ));
    }
    Ok(size)
}

fn half_at(bytes: &[u8], i: usize) -> f32 {
    half::f16::from_le_bytes([bytes[i], bytes[i + 1]]).to_f32()
}

/// The toolchain-baked split-sum LUT: `size * size` little-endian f16 (scale,
/// bias) pairs, row = roughness, column = N.V (an `Rg16Float` texture).
#[derive(Clone, Debug, PartialEq)]
pub struct BrdfLut {
    pub size: u32,
    pub bytes: Vec<u8>,
}

impl BrdfLut {
    pub fn load(path: impl AsRef<Path>) -> Result<BrdfLut> {
        let path = path.as_ref();
        BrdfLut::from_bytes(read_lut(path)?)
            .map_err(|m| Error::Metadata(format!("{}: {m}", path.display())))
    }

    pub fn from_bytes(bytes: Vec<u8>) -> std::result::Result<BrdfLut, String> {
        Ok(BrdfLut {
            size: square_size(bytes.len(), 4)?,
            bytes,
        })
    }

    /// The LUT next to a material's metadata: `<meta dir>/../luts/...`.
    pub fn for_metadata(meta_path: impl AsRef<Path>) -> Result<BrdfLut> {
        BrdfLut::load(generated_dir(meta_path.as_ref()).join(SPLIT_SUM_LUT_FILE))
    }

    /// (scale, bias) at texel (column = N.V index, row = roughness index).
    pub fn texel(&self, col: u32, row: u32) -> [f32; 2] {
        let i = ((row * self.size + col) * 4) as usize;
        [half_at(&self.bytes, i), half_at(&self.bytes, i + 2)]
    }
}

/// The toolchain-baked Charlie sheen albedo LUT: `size * size` little-endian
/// f16, row = sheen roughness, column = N.V (an `R16Float` texture).
#[derive(Clone, Debug, PartialEq)]
pub struct SheenLut {
    pub size: u32,
    pub bytes: Vec<u8>,
}

impl SheenLut {
    pub fn load(path: impl AsRef<Path>) -> Result<SheenLut> {
        let path = path.as_ref();
        let bytes = read_lut(path)?;
        let size = square_size(bytes.len(), 2)
            .map_err(|m| Error::Metadata(format!("{}: {m}", path.display())))?;
        Ok(SheenLut { size, bytes })
    }

    /// E at texel (column = N.V index, row = roughness index).
    pub fn texel(&self, col: u32, row: u32) -> f32 {
        half_at(&self.bytes, ((row * self.size + col) * 2) as usize)
    }
}

/// The lookup tables group 0 of the engine interface binds.
#[derive(Clone, Debug, PartialEq)]
pub struct Luts {
    /// `weft_brdf_lut` (required).
    pub brdf: BrdfLut,
    /// `weft_sheen_lut`; only variants that bind it need it.
    pub sheen: Option<SheenLut>,
    /// The library root the tables were read from (the folder holding
    /// `luts/`). With a root, a variant's LUT is read from the file its
    /// metadata names; without one (tables built in memory) the table of
    /// the binding's `resource.id` is bound.
    pub root: Option<PathBuf>,
}

impl Luts {
    /// The tables of a generated folder (`generated/luts/...`); the sheen
    /// table is optional (toolchains before it did not bake one).
    pub fn load_dir(generated: impl AsRef<Path>) -> Result<Luts> {
        let dir = generated.as_ref();
        let brdf = BrdfLut::load(dir.join(SPLIT_SUM_LUT_FILE))?;
        let sheen_path = dir.join(SHEEN_LUT_FILE);
        let sheen = if sheen_path.exists() {
            Some(SheenLut::load(sheen_path)?)
        } else {
            None
        };
        Ok(Luts {
            brdf,
            sheen,
            root: Some(dir.to_path_buf()),
        })
    }

    /// The texels of the LUT a binding names (`resource.id`, `resource.file`):
    /// the file at `file.path` under [`Luts::root`], else the in-memory
    /// table for `id`; checked against the metadata's format, width and height.
    pub fn texels(&self, id: &str, file: &ResourceFile) -> Result<Cow<'_, [u8]>> {
        let bytes: Cow<[u8]> = match &self.root {
            Some(root) => Cow::Owned(read_lut(&root.join(&file.path))?),
            None => match id {
                SPLIT_SUM_LUT_ID => Cow::Borrowed(&self.brdf.bytes),
                SHEEN_LUT_ID => match &self.sheen {
                    Some(s) => Cow::Borrowed(&s.bytes),
                    None => {
                        return Err(Error::Metadata(format!(
                            "the variant binds LUT `{id}` (`{}`), which was not loaded",
                            file.path
                        )));
                    }
                },
                other => {
                    return Err(Error::Metadata(format!(
                        "LUT `{other}` (`{}`) is none that weft-render holds in memory \
                         (`{SPLIT_SUM_LUT_ID}`, `{SHEEN_LUT_ID}`); load the tables from a folder",
                        file.path
                    )));
                }
            },
        };
        let texel = texel_bytes(&file.format).ok_or_else(|| {
            Error::Metadata(format!(
                "LUT `{}` has format `{}`; weft-render reads rgba16float, rg16float and r16float tables",
                file.path, file.format
            ))
        })?;
        let expected = u64::from(file.width) * u64::from(file.height) * texel;
        if bytes.len() as u64 != expected || file.width == 0 || file.height == 0 {
            return Err(Error::Metadata(format!(
                "LUT `{}` holds {} bytes, but the metadata describes a {}x{} `{}` table \
                 ({expected} bytes); rebuild the library (`cargo xtask regenerate` or `weft build`)",
                file.path,
                bytes.len(),
                file.width,
                file.height,
                file.format
            )));
        }
        Ok(bytes)
    }

    /// The tables next to a material's metadata (`<meta dir>/../luts/`).
    pub fn for_metadata(meta_path: impl AsRef<Path>) -> Result<Luts> {
        Luts::load_dir(generated_dir(meta_path.as_ref()))
    }

    /// The tables of a built scene (`<out>/<scene>/<scene>.scene.json`):
    /// the scene folder's own `luts/` (a self-contained scene, `weft build
    /// --scene`), else `<out>/luts/`, else, for a project build's
    /// `generated/scenes/<scene>/`, `generated/luts/`.
    pub fn for_scene(scene_json: impl AsRef<Path>) -> Result<Luts> {
        let scene_dir = scene_json.as_ref().parent().unwrap_or(Path::new("."));
        let out = generated_dir(scene_json.as_ref());
        let candidates = [scene_dir.to_path_buf(), out.to_path_buf(), out.join("..")];
        match candidates
            .iter()
            .find(|dir| dir.join(SPLIT_SUM_LUT_FILE).is_file())
        {
            Some(dir) => Luts::load_dir(dir),
            None => Luts::load_dir(out),
        }
    }
}

impl From<BrdfLut> for Luts {
    fn from(brdf: BrdfLut) -> Luts {
        Luts {
            brdf,
            sheen: None,
            root: None,
        }
    }
}

/// Bytes per texel of the LUT formats weft bakes.
fn texel_bytes(format: &str) -> Option<u64> {
    match format {
        "rgba16float" => Some(8),
        "rg16float" => Some(4),
        "r16float" => Some(2),
        _ => None,
    }
}
