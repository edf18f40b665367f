//! The character set's texture assets (issue 12): generated here, committed
//! as small PNGs under `materials/<material>/textures/`, and checked to be
//! current by `cargo xtask textures --check` and `tests/rendering/textures.rs`.
//!
//! Every generator is deterministic: f64 arithmetic with only +, −, ×, ÷ and
//! √ (IEEE-exact everywhere), sin/cos from fixed series (`math`, not the
//! platform's libm), integer hashes for noise, and PNGs written with fixed
//! encoder settings, so the bytes are the same on every machine.

use std::path::{Path, PathBuf};

pub mod curvature;
pub mod edt;
pub mod face_mask;
pub mod face_sdf;
pub mod flow;
pub mod head;
pub mod jitter;
pub mod matcap;
pub mod math;

/// How a texture's bytes are laid out (8 bits per channel).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Channels {
    Grey,
    Rgb,
}

impl Channels {
    pub fn count(self) -> usize {
        match self {
            Channels::Grey => 1,
            Channels::Rgb => 3,
        }
    }
}

/// One generated texture: where it lives and its texels (rows top to bottom,
/// v = 0 first, as wgpu and the bust's uvs read them).
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    /// Path relative to the repository root.
    pub path: &'static str,
    pub width: u32,
    pub height: u32,
    pub channels: Channels,
    /// sRGB-encoded colour (the PNG gets an sRGB chunk) or linear data.
    pub srgb: bool,
    pub data: Vec<u8>,
}

impl Texture {
    /// The PNG bytes, with fixed settings (same bytes for the same texels).
    pub fn encode(&self) -> Vec<u8> {
        let mut out = Vec::new();
        let mut enc = png::Encoder::new(&mut out, self.width, self.height);
        enc.set_color(match self.channels {
            Channels::Grey => png::ColorType::Grayscale,
            Channels::Rgb => png::ColorType::Rgb,
        });
        enc.set_depth(png::BitDepth::Eight);
        enc.set_compression(png::Compression::High);
        enc.set_filter(png::Filter::Adaptive);
        if self.srgb {
            enc.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
        }
        let mut w = enc.write_header().expect("png header to a Vec");
        w.write_image_data(&self.data).expect("png data to a Vec");
        w.finish().expect("png end to a Vec");
        out
    }

    /// The texel at column `x`, row `y`, channel `c`, as 0..=255.
    pub fn at(&self, x: usize, y: usize, c: usize) -> u8 {
        let n = self.channels.count();
        self.data[(y * self.width as usize + x) * n + c]
    }
}

/// Every texture, in a fixed order.
pub fn all() -> Vec<Texture> {
    vec![
        face_sdf::texture(),
        face_mask::texture(),
        matcap::texture(),
        flow::texture(),
        jitter::texture(),
        curvature::texture(),
    ]
}

/// Writes every texture under `root` (the repository), returning the paths
/// written (only those whose bytes changed).
pub fn write(root: &Path) -> std::io::Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    for t in all() {
        let path = root.join(t.path);
        let bytes = t.encode();
        if std::fs::read(&path).ok().as_deref() == Some(&bytes[..]) {
            continue;
        }
        if let Some(dir) = path.parent() {
            std::fs::create_dir_all(dir)?;
        }
        std::fs::write(&path, &bytes)?;
        written.push(path);
    }
    Ok(written)
}

/// The textures under `root` that are missing or differ from a fresh
/// generation (relative paths).
pub fn stale(root: &Path) -> Vec<&'static str> {
    all()
        .into_iter()
        .filter(|t| std::fs::read(root.join(t.path)).ok() != Some(t.encode()))
        .map(|t| t.path)
        .collect()
}

/// A value in [0, 1] as 0..=255 (round half up; inputs clamped).
pub fn quantise(x: f64) -> u8 {
    (x.clamp(0.0, 1.0) * 255.0 + 0.5).floor() as u8
}

/// Hermite smoothstep, as WGSL's.
pub fn smoothstep(e0: f64, e1: f64, x: f64) -> f64 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}
