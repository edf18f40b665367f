//! The error of an image against a reference over object pixels (FLIP on
//! the tone-mapped image, relative RMSE on the linear one) and quantiles.

use weft_render::{HdrImage, Tonemap};

/// The tone mapping every comparison of HDR renders goes through (goldens,
/// benches, the `auto` chooser): ACES, exposure 1.
pub const TONEMAP: Tonemap = Tonemap::Aces;

/// An HDR render as the sRGB8 RGBA image FLIP compares.
pub fn to_ldr(image: &HdrImage) -> Vec<u8> {
    image.to_srgb8(TONEMAP, 1.0)
}

/// The q-quantile (nearest rank) of `values`; NaN when empty.
pub fn quantile(values: &[f64], q: f64) -> f64 {
    if values.is_empty() {
        return f64::NAN;
    }
    let mut v = values.to_vec();
    v.sort_by(f64::total_cmp);
    v[(q.clamp(0.0, 1.0) * (v.len() - 1) as f64).round() as usize]
}

/// Error of `test` against `reference` over object pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageError {
    /// Mean FLIP over object pixels (ACES tone mapping, sRGB8).
    pub flip_mean: f64,
    /// 99th percentile (nearest rank) of the per-pixel FLIP over object pixels.
    pub flip_p99: f64,
    /// sqrt(Σ(a−b)² / Σb²) over the RGB channels of object pixels, linear HDR.
    pub rel_rmse: f64,
    /// Number of object pixels.
    pub pixels: usize,
}

/// Per-pixel FLIP of `test` against `reference` (ACES tone mapping, sRGB8,
/// row-major) and the object mask: pixels not left at the transparent-black
/// clear colour in either image.
pub fn flip_map(reference: &HdrImage, test: &HdrImage) -> (Vec<f32>, Vec<bool>) {
    assert_eq!(
        (reference.width, reference.height),
        (test.width, test.height)
    );
    let (w, h) = (reference.width, reference.height);
    let mask: Vec<bool> = reference
        .pixels
        .iter()
        .zip(&test.pixels)
        .map(|(a, b)| *a != [0.0; 4] || *b != [0.0; 4])
        .collect();
    let rgb = |img: &HdrImage| -> Vec<u8> {
        to_ldr(img)
            .chunks_exact(4)
            .flat_map(|p| [p[0], p[1], p[2]])
            .collect()
    };
    let flip = nv_flip::flip(
        nv_flip::FlipImageRgb8::with_data(w, h, &rgb(reference)),
        nv_flip::FlipImageRgb8::with_data(w, h, &rgb(test)),
        nv_flip::DEFAULT_PIXELS_PER_DEGREE,
    )
    .to_vec();
    (flip, mask)
}

/// Object pixels: those not left at the transparent-black clear colour in
/// either image.
pub fn image_error(reference: &HdrImage, test: &HdrImage) -> ImageError {
    let (flip, mask) = flip_map(reference, test);
    let values: Vec<f64> = flip
        .iter()
        .zip(&mask)
        .filter(|(_, m)| **m)
        .map(|(v, _)| f64::from(*v))
        .collect();
    let (mut num, mut den) = (0.0f64, 0.0f64);
    for ((a, b), m) in test.pixels.iter().zip(&reference.pixels).zip(&mask) {
        if *m {
            for c in 0..3 {
                let (a, b) = (f64::from(a[c]), f64::from(b[c]));
                num += (a - b) * (a - b);
                den += b * b;
            }
        }
    }
    let n = values.len();
    ImageError {
        flip_mean: if n == 0 {
            0.0
        } else {
            values.iter().sum::<f64>() / n as f64
        },
        flip_p99: if n == 0 { 0.0 } else { quantile(&values, 0.99) },
        rel_rmse: if den > 0.0 {
            (num / den).sqrt()
        } else {
            num.sqrt()
        },
        pixels: n,
    }
}
