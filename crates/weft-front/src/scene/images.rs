//! Scene images: a `texture2d` parameter of an instance set to an image
//! instead of a built-in texture (docs/scenes.md, "Images"):
//!
//! - `{ file = "maps/cloth_d.png" }`: a PNG or JPEG beside the manifest
//!   (relative to its folder, never outside it);
//! - `{ gltf = "x.glb", texture = 2 }`: a glTF texture's image (a file
//!   beside the glTF, a buffer view or a data URI);
//! - `{ gltf = "x.glb", metallic_roughness = 1, occlusion = 3 }`: glTF's
//!   metallic-roughness (G roughness, B metallic) and occlusion (R) textures
//!   repacked into standard's RMO layout (R roughness, G metallic, B
//!   occlusion); either may be left out (its channels then read 1).
//!
//! `scale = [u, v]` and `offset = [u, v]` set the parameter's tiling
//! (`<name>_st`: uv × scale + offset), what `KHR_texture_transform` gives.
//!
//! Images are decoded here, at load time, into the RGBA8 texels the scene
//! folder carries (`textures/<hash>.rgba8`), so a bad image is a diagnostic
//! at the value and no engine needs a decoder. Each distinct image is decoded
//! once per scene.

use crate::gltf::{GltfCache, GltfFile};
use crate::texture_files::{Image, MAX_TEXTURE_FILE_BYTES, decode_image};
use crate::toml_reader::{Cx, Table, Value};
use std::collections::BTreeMap;
use std::path::{Component, Path, PathBuf};
use std::sync::Arc;

/// Keys of an image value.
pub const IMAGE_KEYS: &[&str] = &[
    "file",
    "gltf",
    "texture",
    "metallic_roughness",
    "occlusion",
    "scale",
    "offset",
];

/// How an image value is written, in one line (diagnostics' notes).
pub const IMAGE_FORMS: &str = "an image is `{ file = \"maps/x.png\" }` (PNG or JPEG beside the \
     manifest), `{ gltf = \"x.glb\", texture = 0 }` or `{ gltf = \"x.glb\", metallic_roughness = \
     1, occlusion = 2 }` (repacked into R roughness, G metallic, B occlusion), with optional \
     `scale = [u, v]` and `offset = [u, v]`";

/// A texture parameter's image, decoded.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneImage {
    /// Texels as stored (the parameter's `srgb` says how to read them).
    pub image: Arc<Image>,
    /// Where the texels come from, for the metadata's `channels` text.
    pub source: String,
    /// `<name>_st`: uv scale (xy) and offset (zw).
    pub tiling: [f64; 4],
}

impl SceneImage {
    /// The file the scene folder carries: `textures/<first 16 hex of the
    /// texels' SHA-256>.rgba8` (one file per distinct image).
    pub fn file_name(&self) -> String {
        format!("textures/{}.rgba8", &self.image.sha256[..16])
    }
}

/// What the value asks for, before anything is read.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Source {
    File(String),
    GltfTexture(String, usize),
    GltfRmo {
        gltf: String,
        metallic_roughness: Option<usize>,
        occlusion: Option<usize>,
    },
}

/// Decodes the images of one scene, each once.
pub struct SceneImages {
    /// The manifest's folder: `file` and `gltf` paths are relative to it.
    dir: PathBuf,
    decoded: BTreeMap<Source, Result<Arc<Image>, String>>,
}

impl SceneImages {
    pub fn new(dir: &Path) -> SceneImages {
        SceneImages {
            dir: dir.to_path_buf(),
            decoded: BTreeMap::new(),
        }
    }

    /// The image `value` (an inline table) names, for parameter `what`;
    /// every problem is reported at the value and gives None. `tiling`:
    /// whether the parameter has a `_st` member to carry `scale`/`offset`.
    pub fn load(
        &mut self,
        value: &Value,
        what: &str,
        tiling: bool,
        gltf: &mut GltfCache,
        cx: &mut Cx,
    ) -> Option<SceneImage> {
        let table = Table::new(value, what, cx)?;
        let errors = cx.diags.error_count();
        table.check_keys(IMAGE_KEYS, cx);
        let source = source(&table, cx)?;
        let pair = |key: &str, default: f64, cx: &mut Cx| -> Option<[f64; 2]> {
            let Some(v) = table.numbers(key, cx) else {
                return table.get(key).is_none().then_some([default; 2]);
            };
            match v[..] {
                [u, v] if u.is_finite() && v.is_finite() && u.abs() < 1e6 && v.abs() < 1e6 => {
                    Some([u, v])
                }
                _ => {
                    cx.error(
                        "wrong-type",
                        format!("`{key}` of {what} must be two finite numbers [u, v]"),
                        table.span_of(key),
                        "not [u, v]",
                    );
                    None
                }
            }
        };
        let scale = pair("scale", 1.0, cx)?;
        let offset = pair("offset", 0.0, cx)?;
        let tiling_value = [scale[0], scale[1], offset[0], offset[1]];
        if !tiling && tiling_value != [1.0, 1.0, 0.0, 0.0] {
            cx.error_with_note(
                "unsupported-feature",
                format!("{what} has no tiling: `scale` and `offset` cannot apply"),
                table.span_of(if table.get("scale").is_some() {
                    "scale"
                } else {
                    "offset"
                }),
                "this transform",
                "only a parameter declared with `tiling = true` reads a uv scale and offset",
            );
            return None;
        }
        if cx.diags.error_count() > errors {
            return None;
        }
        let describe = describe(&source);
        let decoded = match self.decoded.get(&source) {
            Some(d) => d.clone(),
            None => {
                let d = self.decode(&source, gltf).map(Arc::new);
                self.decoded.insert(source.clone(), d.clone());
                d
            }
        };
        match decoded {
            Ok(image) => Some(SceneImage {
                image,
                source: describe,
                tiling: tiling_value,
            }),
            Err(why) => {
                cx.error_with_note(
                    "bad-texture-file",
                    format!("the image of {what} cannot be used: {why}"),
                    value.span(),
                    "this image",
                    format!(
                        "an image is a PNG or JPEG of at most {0}x{0} texels",
                        crate::texture_files::MAX_TEXTURE_FILE_SIZE
                    ),
                );
                None
            }
        }
    }

    fn decode(&self, source: &Source, gltf: &mut GltfCache) -> Result<Image, String> {
        match source {
            Source::File(path) => {
                let file = inside(&self.dir, path)?;
                let bytes = weft_meta::files::read_regular(&file, MAX_TEXTURE_FILE_BYTES)
                    .map_err(|e| format!("cannot read `{path}`: {e}"))?;
                decode_image(&bytes).map_err(|e| format!("`{path}`: {e}"))
            }
            Source::GltfTexture(path, texture) => {
                let file = gltf.file(&self.dir.join(path)).map_err(|e| e.to_string())?;
                gltf_texture(&file, *texture)
            }
            Source::GltfRmo {
                gltf: path,
                metallic_roughness,
                occlusion,
            } => {
                let file = gltf.file(&self.dir.join(path)).map_err(|e| e.to_string())?;
                let mr = metallic_roughness
                    .map(|t| gltf_texture(&file, t))
                    .transpose()?;
                let occ = occlusion.map(|t| gltf_texture(&file, t)).transpose()?;
                Ok(repack_rmo(mr.as_ref(), occ.as_ref()))
            }
        }
    }
}

fn source(table: &Table, cx: &mut Cx) -> Option<Source> {
    let index = |key: &str, cx: &mut Cx| -> Option<Option<usize>> {
        let Some(n) = table.integer(key, cx) else {
            return table.get(key).is_none().then_some(None);
        };
        match usize::try_from(n) {
            Ok(n) => Some(Some(n)),
            Err(_) => {
                cx.error(
                    "out-of-range",
                    format!("`{key}` of {} must be ≥ 0", table.what),
                    table.span_of(key),
                    "an index into the glTF file's `textures`",
                );
                None
            }
        }
    };
    let file = table.string("file", cx);
    let gltf = table.string("gltf", cx);
    let texture = index("texture", cx)?;
    let metallic_roughness = index("metallic_roughness", cx)?;
    let occlusion = index("occlusion", cx)?;
    let rmo = metallic_roughness.is_some() || occlusion.is_some();
    let wrong = |cx: &mut Cx, message: &str| {
        cx.error_with_note(
            "wrong-type",
            format!("{}: {message}", table.what),
            table.span.clone(),
            "this image",
            IMAGE_FORMS,
        );
        None
    };
    match (file, gltf) {
        (Some(f), None) if texture.is_none() && !rmo => Some(Source::File(f)),
        (Some(_), None) => wrong(
            cx,
            "`texture`, `metallic_roughness` and `occlusion` need `gltf`",
        ),
        (None, Some(g)) => match (texture, rmo) {
            (Some(t), false) => Some(Source::GltfTexture(g, t)),
            (None, true) => Some(Source::GltfRmo {
                gltf: g,
                metallic_roughness,
                occlusion,
            }),
            (Some(_), true) => wrong(
                cx,
                "`texture` and `metallic_roughness`/`occlusion` are two different images",
            ),
            (None, false) => wrong(
                cx,
                "a glTF image needs `texture` (or `metallic_roughness`/`occlusion`)",
            ),
        },
        (Some(_), Some(_)) => wrong(cx, "`file` and `gltf` are two different images"),
        (None, None) => wrong(cx, "no `file` or `gltf`"),
    }
}

fn describe(source: &Source) -> String {
    match source {
        Source::File(path) => format!("`{path}`"),
        Source::GltfTexture(path, t) => format!("texture {t} of `{path}`"),
        Source::GltfRmo {
            gltf,
            metallic_roughness,
            occlusion,
        } => {
            let mut parts = Vec::new();
            if let Some(t) = metallic_roughness {
                parts.push(format!(
                    "roughness (G) and metallic (B) of texture {t} into R and G"
                ));
            }
            if let Some(t) = occlusion {
                parts.push(format!("occlusion (R) of texture {t} into B"));
            }
            format!(
                "repacked from `{gltf}`: {} (a channel without a texture reads 255)",
                parts.join(", ")
            )
        }
    }
}

/// `path` under `dir`, also through symbolic links.
fn inside(dir: &Path, path: &str) -> Result<PathBuf, String> {
    let relative = Path::new(path);
    if relative
        .components()
        .any(|c| !matches!(c, Component::Normal(_) | Component::CurDir))
    {
        return Err(format!(
            "`{path}` leaves the manifest's folder (`..` or an absolute path)"
        ));
    }
    let root = dir.canonicalize().unwrap_or_else(|_| dir.to_path_buf());
    let real = dir
        .join(relative)
        .canonicalize()
        .map_err(|e| format!("cannot open `{path}`: {e}"))?;
    if !real.starts_with(&root) {
        return Err(format!(
            "`{path}` lies outside the manifest's folder (a symbolic link)"
        ));
    }
    Ok(real)
}

/// The texels of glTF texture `index`: its `source` image, from a file
/// beside the glTF, a buffer view or a data URI; PNG and JPEG only. Errors
/// name the file and the JSON pointer, as every glTF error does.
pub fn gltf_texture(file: &GltfFile, index: usize) -> Result<Image, String> {
    const HINT: &str =
        "weft reads PNG and JPEG images, from a file beside the glTF, a buffer view or a data URI";
    let fail = |pointer: String, message: String| file.error(&pointer, message, HINT).to_string();
    file.document.textures().nth(index).ok_or_else(|| {
        fail(
            "/textures".into(),
            format!("the file has no texture {index}"),
        )
    })?;
    // A texture without an image (a KTX2 or WebP one with no fallback)
    // has no `source`: refused here, before the crate's lookup.
    let source = file.document.as_json().textures[index].source.value();
    if source >= file.document.images().count() {
        return Err(fail(
            format!("/textures/{index}"),
            "the texture has no PNG or JPEG `source` (weft reads no KTX2 or WebP)".into(),
        ));
    }
    // The image read from the JSON itself: the crate's accessor unwraps a
    // missing `mimeType` or `uri`, which a hostile file may leave out.
    let image_index = source;
    let image = &file.document.as_json().images[image_index];
    let at = format!("/images/{image_index}");
    let bytes: Vec<u8> = match (&image.buffer_view, &image.uri) {
        (Some(view), _) => {
            let view = file
                .document
                .views()
                .nth(view.value())
                .ok_or_else(|| fail(at.clone(), "its buffer view does not exist".into()))?;
            let buffer = file
                .buffers
                .get(view.buffer().index())
                .ok_or_else(|| fail(at.clone(), "its buffer view's buffer is missing".into()))?;
            let (start, len) = (view.offset(), view.length());
            buffer
                .get(start..start.saturating_add(len))
                .ok_or_else(|| fail(at.clone(), "its buffer view runs past its buffer".into()))?
                .to_vec()
        }
        (None, Some(uri)) => {
            if uri.starts_with("data:") {
                // The buffers' reader of data URIs (document.rs), for images.
                let (media, payload) = crate::gltf::document::data_uri(uri)
                    .ok_or_else(|| fail(at.clone(), "a data URI that is not base64".into()))?;
                if media != "image/png" && media != "image/jpeg" {
                    return Err(fail(
                        at,
                        format!(
                            "an image data URI of type `{media}` (weft reads image/png and image/jpeg)"
                        ),
                    ));
                }
                if payload.len() as u64 / 4 * 3 > MAX_TEXTURE_FILE_BYTES {
                    return Err(fail(
                        at,
                        "the data URI is larger than an image may be".into(),
                    ));
                }
                use base64::Engine;
                base64::engine::general_purpose::STANDARD
                    .decode(payload)
                    .map_err(|e| fail(at.clone(), format!("bad base64 in the data URI: {e}")))?
            } else {
                let path = crate::gltf::document::resolve_relative_uri(&file.dir, uri)
                    .map_err(|e| fail(at.clone(), format!("image `{uri}`: {e}")))?;
                weft_meta::files::read_regular(&path, MAX_TEXTURE_FILE_BYTES)
                    .map_err(|e| fail(at.clone(), format!("cannot read image `{uri}`: {e}")))?
            }
        }
        (None, None) => {
            return Err(fail(
                at,
                "the image has neither `bufferView` nor `uri`".into(),
            ));
        }
    };
    decode_image(&bytes).map_err(|e| fail(at, e))
}

/// glTF's metallic-roughness (G, B) and occlusion (R) textures as standard's
/// RMO map. The output has the metallic-roughness texture's size (else the
/// occlusion's); the other is read at its nearest texel.
fn repack_rmo(mr: Option<&Image>, occlusion: Option<&Image>) -> Image {
    let (w, h) = mr.or(occlusion).map_or((1, 1), |i| (i.width, i.height));
    let texel = |img: Option<&Image>, x: u32, y: u32, channel: usize| -> u8 {
        img.map_or(255, |i| {
            // Nearest texel centre of the same uv.
            let sx = ((u64::from(x) * 2 + 1) * u64::from(i.width) / (2 * u64::from(w))) as usize;
            let sy = ((u64::from(y) * 2 + 1) * u64::from(i.height) / (2 * u64::from(h))) as usize;
            i.rgba8[(sy * i.width as usize + sx) * 4 + channel]
        })
    };
    let mut rgba8 = Vec::with_capacity(w as usize * h as usize * 4);
    for y in 0..h {
        for x in 0..w {
            rgba8.extend([
                texel(mr, x, y, 1),
                texel(mr, x, y, 2),
                texel(occlusion, x, y, 0),
                255,
            ]);
        }
    }
    Image::new(w, h, rgba8).expect("w × h texels")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(w: u32, h: u32, f: impl Fn(u32, u32) -> [u8; 4]) -> Image {
        let rgba8 = (0..h)
            .flat_map(|y| (0..w).map(move |x| (x, y)))
            .flat_map(|(x, y)| f(x, y))
            .collect();
        Image::new(w, h, rgba8).unwrap()
    }

    #[test]
    fn rmo_takes_roughness_metallic_and_occlusion_from_their_gltf_channels() {
        let mr = image(2, 2, |x, y| [9, 10 * x as u8, 100 + y as u8, 7]);
        let occ = image(1, 1, |_, _| [42, 0, 0, 0]);
        let rmo = repack_rmo(Some(&mr), Some(&occ));
        assert_eq!((rmo.width, rmo.height), (2, 2));
        assert_eq!(&rmo.rgba8[..8], &[0, 100, 42, 255, 10, 100, 42, 255]);
        assert_eq!(&rmo.rgba8[8..], &[0, 101, 42, 255, 10, 101, 42, 255]);
        // Without a metallic-roughness texture: roughness and metallic read 1.
        let only_occ = repack_rmo(None, Some(&occ));
        assert_eq!(only_occ.rgba8, [255, 255, 42, 255]);
    }

    #[test]
    fn a_path_may_not_leave_the_manifests_folder() {
        let dir = std::env::temp_dir();
        assert!(inside(&dir, "../x.png").unwrap_err().contains("leaves"));
        assert!(inside(&dir, "/etc/passwd").unwrap_err().contains("leaves"));
    }
}
