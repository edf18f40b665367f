//! Linear HDR images read back from the GPU, CPU tone mapping to sRGB8, PNG
//! and PFM output.

use crate::error::{Error, Result, io_err};
use std::path::Path;

/// Linear scene-referred RGBA, f32 per channel, row-major with row 0 at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct HdrImage {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<[f32; 4]>,
}

/// Tone-mapping operator applied before sRGB encoding.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Tonemap {
    /// Narkowicz's fit of the ACES filmic curve (2015).
    #[default]
    Aces,
    /// Khronos PBR Neutral (2024): colour-preserving, identity below ~0.8.
    Neutral,
    /// Clamp only.
    Clamp,
}

impl Tonemap {
    pub const ALL: [Tonemap; 3] = [Tonemap::Aces, Tonemap::Neutral, Tonemap::Clamp];

    pub fn name(self) -> &'static str {
        match self {
            Tonemap::Aces => "aces",
            Tonemap::Neutral => "neutral",
            Tonemap::Clamp => "clamp",
        }
    }

    pub fn from_name(s: &str) -> Option<Tonemap> {
        Tonemap::ALL.into_iter().find(|t| t.name() == s)
    }

    /// Maps linear RGB to display-linear RGB in [0, 1].
    pub fn apply(self, c: [f32; 3]) -> [f32; 3] {
        let c = c.map(|x| if x.is_finite() { x.max(0.0) } else { 0.0 });
        match self {
            Tonemap::Aces => c.map(|x| {
                let (a, b, cc, d, e) = (2.51, 0.03, 2.43, 0.59, 0.14);
                ((x * (a * x + b)) / (x * (cc * x + d) + e)).clamp(0.0, 1.0)
            }),
            Tonemap::Neutral => pbr_neutral(c),
            Tonemap::Clamp => c.map(|x| x.clamp(0.0, 1.0)),
        }
    }
}

/// Khronos PBR Neutral tone mapper (reference implementation, KhronosGroup/ToneMapping).
fn pbr_neutral(mut c: [f32; 3]) -> [f32; 3] {
    const START_COMPRESSION: f32 = 0.8 - 0.04;
    const DESATURATION: f32 = 0.15;
    let x = c[0].min(c[1]).min(c[2]);
    let offset = if x < 0.08 { x - 6.25 * x * x } else { 0.04 };
    for v in &mut c {
        *v -= offset;
    }
    let peak = c[0].max(c[1]).max(c[2]);
    if peak < START_COMPRESSION {
        return c.map(|v| v.clamp(0.0, 1.0));
    }
    let d = 1.0 - START_COMPRESSION;
    let new_peak = 1.0 - d * d / (peak + d - START_COMPRESSION);
    for v in &mut c {
        *v *= new_peak / peak;
    }
    let g = 1.0 - 1.0 / (DESATURATION * (peak - new_peak) + 1.0);
    c.map(|v| (v * (1.0 - g) + new_peak * g).clamp(0.0, 1.0))
}

/// sRGB encode of a display-linear value in [0, 1].
pub fn encode_srgb(x: f32) -> f32 {
    if x <= 0.003_130_8 {
        x * 12.92
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}

impl HdrImage {
    pub fn pixel(&self, x: u32, y: u32) -> [f32; 4] {
        self.pixels[(y * self.width + x) as usize]
    }

    /// Pixels with a NaN or infinite channel.
    pub fn non_finite_count(&self) -> usize {
        self.pixels
            .iter()
            .filter(|p| p.iter().any(|c| !c.is_finite()))
            .count()
    }

    /// Tone-mapped sRGB8 RGBA (alpha 255), row-major. `exposure` scales
    /// linear radiance first.
    pub fn to_srgb8(&self, tonemap: Tonemap, exposure: f32) -> Vec<u8> {
        let mut out = Vec::with_capacity(self.pixels.len() * 4);
        for p in &self.pixels {
            let c = tonemap.apply([p[0] * exposure, p[1] * exposure, p[2] * exposure]);
            for v in c {
                out.push((encode_srgb(v) * 255.0 + 0.5).floor().clamp(0.0, 255.0) as u8);
            }
            out.push(255);
        }
        out
    }

    /// Writes a tone-mapped sRGB8 PNG.
    pub fn save_png(&self, path: impl AsRef<Path>, tonemap: Tonemap, exposure: f32) -> Result<()> {
        let bytes = encode_png(self.width, self.height, &self.to_srgb8(tonemap, exposure))?;
        let path = path.as_ref();
        std::fs::write(path, bytes).map_err(io_err(path))
    }

    /// The linear image as a PFM (Portable Float Map: RGB f32 little-endian,
    /// rows bottom to top as the format requires).
    pub fn to_pfm(&self) -> Vec<u8> {
        let mut out = format!("PF\n{} {}\n-1.0\n", self.width, self.height).into_bytes();
        for y in (0..self.height).rev() {
            for x in 0..self.width {
                let p = self.pixel(x, y);
                for c in &p[..3] {
                    out.extend_from_slice(&c.to_le_bytes());
                }
            }
        }
        out
    }

    pub fn save_pfm(&self, path: impl AsRef<Path>) -> Result<()> {
        let path = path.as_ref();
        std::fs::write(path, self.to_pfm()).map_err(io_err(path))
    }

    /// Reads a PFM written by [`HdrImage::to_pfm`] (alpha = 1).
    pub fn from_pfm(bytes: &[u8]) -> Result<HdrImage> {
        let bad = |m: &str| Error::Metadata(format!("not a PFM file: {m}"));
        let mut fields = Vec::new();
        let mut pos = 0;
        while fields.len() < 4 {
            while pos < bytes.len() && bytes[pos].is_ascii_whitespace() {
                pos += 1;
            }
            let start = pos;
            while pos < bytes.len() && !bytes[pos].is_ascii_whitespace() {
                pos += 1;
            }
            if start == pos {
                return Err(bad("truncated header"));
            }
            fields.push(String::from_utf8_lossy(&bytes[start..pos]).to_string());
        }
        pos += 1; // the single whitespace after the scale
        if fields[0] != "PF" {
            return Err(bad("only colour (PF) maps are supported"));
        }
        let w: u32 = fields[1].parse().map_err(|_| bad("width"))?;
        let h: u32 = fields[2].parse().map_err(|_| bad("height"))?;
        let scale: f32 = fields[3].parse().map_err(|_| bad("scale"))?;
        let data = &bytes[pos.min(bytes.len())..];
        if data.len() < (w * h * 12) as usize {
            return Err(bad("truncated data"));
        }
        let mut pixels = vec![[0.0f32; 4]; (w * h) as usize];
        for y in 0..h {
            for x in 0..w {
                let i = ((y * w + x) * 12) as usize;
                let f = |o: usize| {
                    let b = [
                        data[i + o],
                        data[i + o + 1],
                        data[i + o + 2],
                        data[i + o + 3],
                    ];
                    if scale < 0.0 {
                        f32::from_le_bytes(b)
                    } else {
                        f32::from_be_bytes(b)
                    }
                };
                pixels[((h - 1 - y) * w + x) as usize] = [f(0), f(4), f(8), 1.0];
            }
        }
        Ok(HdrImage {
            width: w,
            height: h,
            pixels,
        })
    }
}

/// Encodes RGBA8 as a PNG with fixed settings (same bytes for the same pixels).
pub fn encode_png(width: u32, height: u32, rgba: &[u8]) -> Result<Vec<u8>> {
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, width, height);
        enc.set_color(png::ColorType::Rgba);
        enc.set_depth(png::BitDepth::Eight);
        enc.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
        let mut w = enc
            .write_header()
            .map_err(|e| Error::Gpu(format!("png: {e}")))?;
        w.write_image_data(rgba)
            .map_err(|e| Error::Gpu(format!("png: {e}")))?;
    }
    Ok(out)
}

/// Largest width or height [`decode_png`] accepts: wgpu's default
/// `max_texture_dimension_2d`, the size every device can sample.
pub const MAX_TEXTURE_SIZE: u32 = 8192;

/// Decodes a PNG of any colour type and bit depth into RGBA8 texels as
/// stored (no colour conversion: an sRGB parameter reads them as sRGB).
/// Grey is replicated to RGB, a missing alpha is 255, 16-bit channels keep
/// their high byte. `what` names the source in errors.
pub fn decode_png(bytes: &[u8], what: &str) -> Result<(u32, u32, Vec<u8>)> {
    let bad = |message: String| Error::InvalidValue {
        name: what.to_string(),
        message,
    };
    // Allocation capped at the largest texture accepted (plus slack), so a
    // hostile header cannot make the decoder reserve gigabytes.
    let limits = png::Limits {
        bytes: (MAX_TEXTURE_SIZE as usize).pow(2) * 8 + (1 << 20),
    };
    let mut decoder = png::Decoder::new_with_limits(std::io::Cursor::new(bytes), limits);
    // Compressed text and ICC profiles are not used, and would be inflated
    // (a small chunk can inflate to gigabytes): skipped unread.
    decoder.set_ignore_text_chunk(true);
    decoder.set_ignore_iccp_chunk(true);
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder
        .read_info()
        .map_err(|e| bad(format!("not a PNG this decoder reads: {e}")))?;
    let (width, height) = {
        let info = reader.info();
        (info.width, info.height)
    };
    if width > MAX_TEXTURE_SIZE || height > MAX_TEXTURE_SIZE {
        return Err(bad(format!(
            "{width}x{height} is larger than {MAX_TEXTURE_SIZE}x{MAX_TEXTURE_SIZE}, the largest texture every device can sample: scale it down"
        )));
    }
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| bad("image too large".into()))?;
    let mut buf = vec![0; size];
    let frame = reader
        .next_frame(&mut buf)
        .map_err(|e| bad(format!("cannot decode: {e}")))?;
    buf.truncate(frame.buffer_size());
    let rgba = match frame.color_type {
        png::ColorType::Rgba => buf,
        png::ColorType::Rgb => buf
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect(),
        png::ColorType::GrayscaleAlpha => buf
            .chunks_exact(2)
            .flat_map(|p| [p[0], p[0], p[0], p[1]])
            .collect(),
        png::ColorType::Grayscale => buf.iter().flat_map(|&g| [g, g, g, 255]).collect(),
        png::ColorType::Indexed => {
            return Err(bad("indexed PNG left unexpanded".into()));
        }
    };
    Ok((width, height, rgba))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn png_of(
        width: u32,
        height: u32,
        color: png::ColorType,
        depth: png::BitDepth,
        data: &[u8],
    ) -> Vec<u8> {
        let mut out = Vec::new();
        let mut enc = png::Encoder::new(&mut out, width, height);
        enc.set_color(color);
        enc.set_depth(depth);
        enc.write_header().unwrap().write_image_data(data).unwrap();
        out
    }

    #[test]
    fn any_png_decodes_to_rgba8_as_stored() {
        use png::{BitDepth, ColorType};
        let rgb16 = png_of(
            1,
            1,
            ColorType::Rgb,
            BitDepth::Sixteen,
            &[0x12, 0x34, 0xab, 0xcd, 0xff, 0x00],
        );
        assert_eq!(
            decode_png(&rgb16, "t").unwrap(),
            (1, 1, vec![0x12, 0xab, 0xff, 255])
        );
        let grey_alpha = png_of(1, 1, ColorType::GrayscaleAlpha, BitDepth::Eight, &[7, 9]);
        assert_eq!(
            decode_png(&grey_alpha, "t").unwrap(),
            (1, 1, vec![7, 7, 7, 9])
        );
        // A texture no device must sample: refused with the limit named.
        let wide = png_of(
            MAX_TEXTURE_SIZE + 1,
            1,
            ColorType::Grayscale,
            BitDepth::Eight,
            &vec![0; MAX_TEXTURE_SIZE as usize + 1],
        );
        let e = decode_png(&wide, "wide").unwrap_err().to_string();
        assert!(e.contains("wide") && e.contains("8192"), "{e}");
        let e = decode_png(b"\x89PNG but not", "junk")
            .unwrap_err()
            .to_string();
        assert!(e.contains("junk"), "{e}");
    }

    #[test]
    fn tonemaps_are_monotonic_and_bounded() {
        for t in Tonemap::ALL {
            let mut prev = -1.0;
            for i in 0..200 {
                let x = i as f32 * 0.1;
                let y = t.apply([x, x, x])[0];
                assert!((0.0..=1.0).contains(&y));
                assert!(y >= prev, "{t:?} at {x}");
                prev = y;
            }
        }
        // Neutral: a 0.04 toe offset, then identity up to the compression start.
        assert!((Tonemap::Neutral.apply([0.5, 0.5, 0.5])[0] - 0.46).abs() < 1e-6);
        assert_eq!(Tonemap::Aces.apply([f32::NAN, 0.0, 0.0])[0], 0.0);
    }

    #[test]
    fn pfm_round_trips() {
        let img = HdrImage {
            width: 3,
            height: 2,
            pixels: (0..6).map(|i| [i as f32, 0.5, -1.0, 1.0]).collect(),
        };
        let back = HdrImage::from_pfm(&img.to_pfm()).unwrap();
        assert_eq!(back, img);
    }
}
