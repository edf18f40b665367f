//! The textures the samples embed, drawn in code: wood and lace.

/// A PNG of `w` × `h` RGB(A) texels from `f(x, y)`.
pub fn png_rgba(w: u32, h: u32, f: impl Fn(u32, u32) -> [u8; 4]) -> Vec<u8> {
    let data: Vec<u8> = (0..h)
        .flat_map(|y| (0..w).map(move |x| (x, y)))
        .flat_map(|(x, y)| f(x, y))
        .collect();
    let mut out = Vec::new();
    let mut e = png::Encoder::new(&mut out, w, h);
    e.set_color(png::ColorType::Rgba);
    e.set_depth(png::BitDepth::Eight);
    let mut writer = e.write_header().expect("png header");
    writer.write_image_data(&data).expect("png data");
    writer.finish().expect("png end");
    out
}

/// Wood grain: stripes along u with a slow wobble (sRGB).
fn wood_grain(x: u32, y: u32) -> f32 {
    let (u, v) = (x as f32 / 64.0, y as f32 / 64.0);
    let ring = (v * 9.0 + 0.6 * (u * std::f32::consts::TAU).sin()).fract();
    (ring * std::f32::consts::PI).sin().powi(4)
}

pub fn wood_base_color() -> Vec<u8> {
    png_rgba(64, 64, |x, y| {
        let g = wood_grain(x, y);
        let c = |lo: f32, hi: f32| (255.0 * (lo + (hi - lo) * g)).round() as u8;
        [c(0.62, 0.38), c(0.42, 0.22), c(0.26, 0.12), 255]
    })
}

/// Tangent-space normals of the grain's height (grooves where it is dark).
pub(super) fn wood_normals() -> Vec<u8> {
    png_rgba(64, 64, |x, y| {
        let dv = wood_grain(x, (y + 1) % 64) - wood_grain(x, (y + 63) % 64);
        let n = [0.0f32, -dv * 1.5, 1.0];
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        let e = |c: f32| (255.0 * (c / len * 0.5 + 0.5)).round() as u8;
        [e(n[0]), e(n[1]), e(n[2]), 255]
    })
}

/// glTF metallic-roughness (G roughness, B metallic) as a JPEG: rough in
/// the grain, a brass inlay band (metallic) across the middle.
pub fn wood_metallic_roughness() -> Vec<u8> {
    let (w, h) = (32u16, 32u16);
    let data: Vec<u8> = (0..u32::from(h))
        .flat_map(|y| {
            (0..u32::from(w)).flat_map(move |x| {
                let inlay = (14..18).contains(&y);
                let rough = if inlay {
                    0.3
                } else {
                    0.55 + 0.35 * wood_grain(x * 2, y * 2)
                };
                [0, (255.0 * rough) as u8, if inlay { 255 } else { 0 }]
            })
        })
        .collect();
    let mut out = Vec::new();
    jpeg_encoder::Encoder::new(&mut out, 95)
        .encode(&data, w, h, jpeg_encoder::ColorType::Rgb)
        .expect("jpeg");
    out
}

/// Lace: a white ground with round holes (alpha 0) on a 4 × 4 grid, for
/// `alphaMode: MASK` (32 × 32, sRGB with alpha).
pub(super) fn lace_base_color() -> Vec<u8> {
    png_rgba(32, 32, |x, y| {
        let (cx, cy) = ((x % 8) as f32 - 3.5, (y % 8) as f32 - 3.5);
        let hole = cx * cx + cy * cy < 6.0;
        [245, 240, 230, if hole { 0 } else { 255 }]
    })
}

/// Ambient occlusion, darker towards the edges of each face (R; 16 × 16).
pub(super) fn wood_occlusion() -> Vec<u8> {
    png_rgba(16, 16, |x, y| {
        let d = |t: u32| (t as f32 + 0.5) / 16.0 * (1.0 - (t as f32 + 0.5) / 16.0) * 4.0;
        let ao = (0.45 + 0.55 * (d(x) * d(y)).sqrt()).min(1.0);
        let a = (255.0 * ao).round() as u8;
        [a, a, a, 255]
    })
}
