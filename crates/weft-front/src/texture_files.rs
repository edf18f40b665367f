//! Texture parameters' `file`s: PNGs shipped with a material, bound while
//! the parameter is unset (docs/material-format.md, "Texture files"). Found
//! like includes (relative to the materials root, confined to it) and decoded
//! here, at load time, into the RGBA8 texels the toolchain writes beside the
//! variants, so that a bad file is a diagnostic on its `file` line and no
//! engine needs a PNG decoder.

use crate::diag::Diagnostics;
use crate::includes::{Origin, Resolver};
pub use crate::model::Image;
use crate::model::Material;
use std::sync::Arc;

/// Texels per axis a texture file may have: WebGPU's guaranteed 2-D texture
/// size is 8192, and a material's maps are small (the files ship in the
/// library, decoded).
pub const MAX_TEXTURE_FILE_SIZE: u32 = 4096;

/// Bytes a texture file may have on disk (a PNG of the largest size, barely
/// compressed, fits).
pub const MAX_TEXTURE_FILE_BYTES: u64 = 96 << 20;

/// Reads and decodes every texture parameter's `file` of `m` (the path as
/// written, under the materials root), reporting a missing, outside, unreadable
/// or undecodable file at its `file` value. In memory (`in_memory`) nothing is
/// read from disk, and a file cannot be given: an error.
pub fn load(m: &mut Material, resolver: &mut Resolver, in_memory: bool) {
    for p in &mut m.params {
        let Some(f) = &mut p.file else { continue };
        let origin = Origin {
            file: f.loc.file,
            span: f.loc.span.clone(),
        };
        if in_memory {
            resolver.diags.error(
                "unsupported-feature",
                format!("texture file `{}` cannot be read in memory", f.path),
                origin.file,
                origin.span,
                "a PNG on disk",
            );
            continue;
        }
        let Some(path) = resolver.locate_texture(&f.path, &origin) else {
            continue;
        };
        // A regular file of bounded size: a FIFO would block, a device never end.
        let bytes = weft_meta::files::read_regular(&path, MAX_TEXTURE_FILE_BYTES)
            .map_err(|e| format!("cannot read it: {e}"));
        match bytes.and_then(|b| decode_png(&b)) {
            Ok(image) => f.image = Arc::new(image),
            Err(why) => bad_file(resolver.diags, &origin, &f.path, why),
        }
    }
}

fn bad_file(diags: &mut Diagnostics, origin: &Origin, path: &str, why: String) {
    let d = diags.error(
        "bad-texture-file",
        format!("texture file `{path}` cannot be used: {why}"),
        origin.file,
        origin.span.clone(),
        "this file",
    );
    d.notes.push(format!(
        "a texture file is a PNG (any colour type and bit depth) of at most \
         {MAX_TEXTURE_FILE_SIZE}x{MAX_TEXTURE_FILE_SIZE} texels; re-export it"
    ));
}

/// A PNG's texels as [`Image`] holds them; `Err` says why not.
pub fn decode_png(bytes: &[u8]) -> Result<Image, String> {
    // Allocation capped at the largest accepted image (16-bit RGBA, plus
    // slack), so that a hostile header cannot reserve gigabytes.
    let limits = png::Limits {
        bytes: (MAX_TEXTURE_FILE_SIZE as usize).pow(2) * 8 + (1 << 20),
    };
    let mut decoder = png::Decoder::new_with_limits(std::io::Cursor::new(bytes), limits);
    // Compressed text and ICC profiles are not used, and would be inflated
    // (a small chunk can inflate to gigabytes): skipped unread.
    decoder.set_ignore_text_chunk(true);
    decoder.set_ignore_iccp_chunk(true);
    // Palettes to RGB(A), low bit depths to 8, tRNS to alpha; 16 bits kept,
    // to round them below.
    decoder.set_transformations(png::Transformations::EXPAND);
    let mut reader = decoder
        .read_info()
        .map_err(|e| format!("not a PNG this decoder reads ({e})"))?;
    let (width, height) = (reader.info().width, reader.info().height);
    if width > MAX_TEXTURE_FILE_SIZE || height > MAX_TEXTURE_FILE_SIZE {
        return Err(format!(
            "{width}x{height} is larger than {MAX_TEXTURE_FILE_SIZE}x{MAX_TEXTURE_FILE_SIZE}"
        ));
    }
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| "the image is too large".to_string())?;
    let mut buf = vec![0; size];
    let frame = reader
        .next_frame(&mut buf)
        .map_err(|e| format!("cannot decode it ({e})"))?;
    buf.truncate(frame.buffer_size());
    let samples: Vec<u8> = match frame.bit_depth {
        png::BitDepth::Sixteen => buf
            .chunks_exact(2)
            .map(|b| {
                let v = u32::from(u16::from_be_bytes([b[0], b[1]]));
                // Nearest 8-bit value: v * 255 / 65535, rounded.
                ((v * 255 + 32767) / 65535) as u8
            })
            .collect(),
        png::BitDepth::Eight => buf,
        other => return Err(format!("unexpected bit depth {other:?} after expansion")),
    };
    let rgba8: Vec<u8> = match frame.color_type {
        png::ColorType::Rgba => samples,
        png::ColorType::Rgb => samples
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect(),
        png::ColorType::GrayscaleAlpha => samples
            .chunks_exact(2)
            .flat_map(|p| [p[0], p[0], p[0], p[1]])
            .collect(),
        png::ColorType::Grayscale => samples.iter().flat_map(|&g| [g, g, g, 255]).collect(),
        png::ColorType::Indexed => return Err("a palette PNG that did not expand".into()),
    };
    Image::new(width, height, rgba8)
}

/// A baseline or progressive JPEG's texels as [`Image`] holds them (alpha
/// 255); `Err` says why not. The decoder runs its portable code path (no
/// SIMD), so the texels are the same on every machine.
pub fn decode_jpeg(bytes: &[u8]) -> Result<Image, String> {
    use zune_jpeg::zune_core::{colorspace::ColorSpace, options::DecoderOptions};
    let max = MAX_TEXTURE_FILE_SIZE as usize;
    let options = DecoderOptions::default()
        .set_max_width(max)
        .set_max_height(max)
        .jpeg_set_out_colorspace(ColorSpace::RGBA);
    let mut decoder = zune_jpeg::JpegDecoder::new_with_options(
        zune_jpeg::zune_core::bytestream::ZCursor::new(bytes),
        options,
    );
    decoder
        .decode_headers()
        .map_err(|e| format!("not a JPEG this decoder reads ({e:?})"))?;
    let info = decoder
        .info()
        .ok_or_else(|| "a JPEG without a frame header".to_string())?;
    let (width, height) = (u32::from(info.width), u32::from(info.height));
    if width == 0 || height == 0 {
        return Err("a JPEG of no texels".into());
    }
    let rgba8 = decoder
        .decode()
        .map_err(|e| format!("cannot decode it ({e:?})"))?;
    Image::new(width, height, rgba8)
}

/// A PNG or a JPEG, told apart by their signatures; anything else is
/// refused by what it looks like (KTX2, WebP, …).
pub fn decode_image(bytes: &[u8]) -> Result<Image, String> {
    if bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
        decode_png(bytes)
    } else if bytes.starts_with(&[0xff, 0xd8, 0xff]) {
        decode_jpeg(bytes)
    } else {
        Err(format!(
            "{} (weft reads PNG and JPEG)",
            match bytes {
                [0xab, b'K', b'T', b'X', b' ', b'2', b'0', ..] => "a KTX2 image",
                [
                    b'R',
                    b'I',
                    b'F',
                    b'F',
                    _,
                    _,
                    _,
                    _,
                    b'W',
                    b'E',
                    b'B',
                    b'P',
                    ..,
                ] => "a WebP image",
                [b'D', b'D', b'S', b' ', ..] => "a DDS image",
                [b'G', b'I', b'F', b'8', ..] => "a GIF image",
                _ => "neither a PNG nor a JPEG",
            }
        ))
    }
}

impl Image {
    /// Texels as decoded, checked against the size, with their hash.
    pub fn new(width: u32, height: u32, rgba8: Vec<u8>) -> Result<Image, String> {
        if rgba8.len() as u64 != u64::from(width) * u64::from(height) * 4 {
            return Err("the decoded image has the wrong number of texels".into());
        }
        use sha2::Digest;
        let sha256 = sha2::Sha256::digest(&rgba8)
            .iter()
            .map(|b| format!("{b:02x}"))
            .collect();
        Ok(Image {
            width,
            height,
            rgba8,
            sha256,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn encode(color: png::ColorType, depth: png::BitDepth, w: u32, h: u32, data: &[u8]) -> Vec<u8> {
        let mut out = Vec::new();
        let mut e = png::Encoder::new(&mut out, w, h);
        e.set_color(color);
        e.set_depth(depth);
        let mut wr = e.write_header().unwrap();
        wr.write_image_data(data).unwrap();
        wr.finish().unwrap();
        out
    }

    #[test]
    fn grey_expands_and_sixteen_bits_round() {
        let g = decode_png(&encode(
            png::ColorType::Grayscale,
            png::BitDepth::Eight,
            2,
            1,
            &[10, 200],
        ))
        .unwrap();
        assert_eq!(g.rgba8, [10, 10, 10, 255, 200, 200, 200, 255]);
        // 0x00ff = 255 / 65535 * 255 = 0.99: rounds to 1 (taking the high byte gives 0).
        let w = decode_png(&encode(
            png::ColorType::GrayscaleAlpha,
            png::BitDepth::Sixteen,
            1,
            1,
            &[0x00, 0xff, 0xff, 0xff],
        ))
        .unwrap();
        assert_eq!(w.rgba8, [1, 1, 1, 255]);
        let two_bit = decode_png(&encode(
            png::ColorType::Grayscale,
            png::BitDepth::Two,
            4,
            1,
            &[0b00_01_10_11],
        ))
        .unwrap();
        assert_eq!(
            two_bit.rgba8,
            [
                0, 0, 0, 255, 85, 85, 85, 255, 170, 170, 170, 255, 255, 255, 255, 255
            ]
        );
    }

    #[test]
    fn rejects_garbage_and_oversize() {
        assert!(decode_png(b"not a png").is_err());
        let big = encode(
            png::ColorType::Grayscale,
            png::BitDepth::One,
            MAX_TEXTURE_FILE_SIZE + 1,
            1,
            &vec![0; (MAX_TEXTURE_FILE_SIZE as usize + 1).div_ceil(8)],
        );
        assert!(decode_png(&big).unwrap_err().contains("larger than"));
    }
}
