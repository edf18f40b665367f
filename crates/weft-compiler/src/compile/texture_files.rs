//! Texture parameters' `file`s (decoded by weft-front's `texture_files`):
//! the RGBA8 file written beside the material's variants, and the
//! `ResourceFile` the metadata states it with, so that an engine binds the
//! image without a PNG decoder.

use weft_front::model::{Material, Param};
use weft_front::scene::images::SceneImage;
use weft_front::texture_files::Image;
use weft_meta::ResourceFile;

/// The file's name in the material's folder: `<parameter>.rgba8`.
pub fn file_name(p: &Param) -> String {
    format!("{}.rgba8", p.name)
}

/// The texture files of `m` (name in its folder, bytes), in parameter order.
pub fn files(m: &Material) -> Vec<(String, Vec<u8>)> {
    m.params
        .iter()
        .filter_map(|p| Some((file_name(p), p.file.as_ref()?.image.rgba8.clone())))
        .collect()
}

/// What the metadata says about parameter `p`'s file (None without one):
/// its path relative to the library root, format, size, layout and hash.
pub fn resource_file(m: &Material, p: &Param) -> Option<ResourceFile> {
    let f = p.file.as_ref()?;
    Some(rgba8_file(
        format!("{}/{}", m.name, file_name(p)),
        &f.image,
        p.srgb,
        &format!("`{}`", f.path),
        "PNG",
    ))
}

/// What the scene metadata says about a scene image (docs/scenes.md
/// "Images"): `textures/<hash>.rgba8`, relative to the scene folder.
pub fn scene_image_file(image: &SceneImage, srgb: bool) -> ResourceFile {
    rgba8_file(
        image.file_name(),
        &image.image,
        srgb,
        &image.source,
        "image",
    )
}

/// `kind`: what the source is (`PNG`, `image`), as the channels text names it.
fn rgba8_file(path: String, image: &Image, srgb: bool, source: &str, kind: &str) -> ResourceFile {
    ResourceFile {
        path,
        format: if srgb {
            "rgba8unorm_srgb"
        } else {
            "rgba8unorm"
        }
        .into(),
        width: image.width,
        height: image.height,
        layout: "width × height texels, rows in order (row 0 first: the top row of the \
                 image), texels in a row left to right; each texel four bytes (r, g, b, a); no \
                 header, no padding"
            .into(),
        u: "0 at the left edge of the image, 1 at the right".into(),
        v: "0 at the top edge of the image (row 0), 1 at the bottom".into(),
        channels: format!(
            "rgba of {source} as stored{}: grey expanded to rgb, alpha 255 where the {kind} has \
             none, 16-bit samples rounded to 8 bits",
            if srgb {
                " (sRGB-encoded: sample through an sRGB view)"
            } else {
                " (linear data)"
            }
        ),
        sha256: Some(image.sha256.clone()),
        mip_chain: Some(weft_meta::MipChain::for_texture(
            image.width,
            image.height,
            srgb,
        )),
    }
}
