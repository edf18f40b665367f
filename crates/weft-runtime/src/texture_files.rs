//! Texture parameters' images (`texture.file`: `<material>/<param>.rgba8`
//! beside the variants, RGBA8, rows top to bottom): read for the binding of
//! a texture left unset, in a material and in a scene.

use crate::error::{Error, Result, io_err};
use crate::values::TextureValue;
use std::path::{Path, PathBuf};
use weft_meta::ResourceFile;

/// The texels of `file` (its `path` relative to the library root), under the
/// first of `roots` that holds it; checked against its size and format.
pub fn read(roots: &[PathBuf], file: &ResourceFile) -> Result<TextureValue> {
    if !matches!(file.format.as_str(), "rgba8unorm" | "rgba8unorm_srgb") {
        return Err(Error::Metadata(format!(
            "texture file `{}` has format `{}`; weft-render reads rgba8unorm and rgba8unorm_srgb",
            file.path, file.format
        )));
    }
    let relative = Path::new(&file.path);
    if relative
        .components()
        .any(|c| !matches!(c, std::path::Component::Normal(_)))
    {
        return Err(Error::Metadata(format!(
            "texture file `{}`: a path inside the scene or library folder (no `..`, not absolute)",
            file.path
        )));
    }
    let path = roots
        .iter()
        .map(|r| r.join(relative))
        .find(|p| p.is_file())
        .unwrap_or_else(|| roots.first().map_or(PathBuf::new(), |r| r.join(&file.path)));
    let data = weft_meta::files::read_regular(&path, weft_meta::files::MAX_BINARY_BYTES)
        .map_err(io_err(&path))?;
    let expected = u64::from(file.width) * u64::from(file.height) * 4;
    if data.len() as u64 != expected || expected == 0 {
        return Err(Error::Metadata(format!(
            "texture file `{}` holds {} bytes, but the metadata describes {}x{} RGBA8 texels \
             ({expected} bytes); rebuild the library (`cargo xtask regenerate` or `weft build`)",
            path.display(),
            data.len(),
            file.width,
            file.height
        )));
    }
    Ok(TextureValue::Rgba8 {
        width: file.width,
        height: file.height,
        data,
    })
}

/// Where a material's files are looked for: the library root, the folder
/// above its metadata's.
pub fn material_roots(dir: &Path) -> Vec<PathBuf> {
    vec![dir.parent().unwrap_or(Path::new(".")).to_path_buf()]
}

/// Where a scene's files are looked for: the scene folder itself (a scene
/// build carries every file it binds, at the path the metadata names), then
/// — for folders built before it did — a project build's library root
/// (`generated/scenes/<scene>/` -> `generated/`) and the folder above the
/// scene's.
pub fn scene_roots(dir: &Path) -> Vec<PathBuf> {
    let up = dir.parent().unwrap_or(Path::new("."));
    vec![dir.to_path_buf(), up.join(".."), up.to_path_buf()]
}
