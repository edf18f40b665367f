//! How the toolchain bakes parameter values: curve samples, gradient ramps and
//! sRGB <-> linear colour. It lives here, in the crate engines link, so that an
//! engine letting users edit curves and gradients bakes them exactly as the
//! toolchain does (docs/material-format.md).

use crate::{GradientStop, Keyframe};

/// sRGB transfer function, encoded -> linear.
pub fn srgb_to_linear(c: f64) -> f64 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// sRGB transfer function, linear -> encoded.
pub fn linear_to_srgb(c: f64) -> f64 {
    if c <= 0.0031308 {
        c * 12.92
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

/// The number of mip levels of a full chain for a `width` × `height`
/// texture: floor(log2(max(width, height))) + 1 (1 for a 1×1 texture).
pub fn mip_level_count(width: u32, height: u32) -> u32 {
    32 - width.max(height).max(1).leading_zeros()
}

/// The full mip chain of an RGBA8 texture (rows top first, four bytes a
/// texel), level 0 first: what an engine binds for a texture parameter's
/// image (`texture.file`, whose `mip_chain` says so) and what weft's
/// renderer uploads. Level n + 1 is max(1, w / 2) × max(1, h / 2) (halves
/// rounded down); its texel (x, y) is the mean of level n's texels
/// (min(2x + i, w − 1), min(2y + j, h − 1)), i, j ∈ {0, 1}: a 2×2 box (a
/// side of 1 repeats its texel; an odd side's last row or column is left
/// out). With `srgb` (`rgba8unorm_srgb`) the RGB bytes are decoded to
/// linear light, averaged, encoded again and rounded to the nearest byte;
/// alpha, and every channel of an `rgba8unorm` texture, is the byte mean
/// rounded half up, (a + b + c + d + 2) / 4.
pub fn rgba8_mip_chain(width: u32, height: u32, level0: &[u8], srgb: bool) -> Vec<Vec<u8>> {
    assert_eq!(
        level0.len(),
        width as usize * height as usize * 4,
        "a {width}×{height} RGBA8 level"
    );
    let decode: Vec<f64> = (0..=255u8)
        .map(|b| srgb_to_linear(f64::from(b) / 255.0))
        .collect();
    let mut levels = vec![level0.to_vec()];
    let (mut w, mut h) = (width as usize, height as usize);
    for _ in 1..mip_level_count(width, height) {
        let src = levels.last().expect("level 0");
        let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
        let mut dst = Vec::with_capacity(nw * nh * 4);
        for y in 0..nh {
            for x in 0..nw {
                let texels = [(0, 0), (1, 0), (0, 1), (1, 1)]
                    .map(|(i, j)| ((2 * y + j).min(h - 1) * w + (2 * x + i).min(w - 1)) * 4);
                for c in 0..4 {
                    if srgb && c < 3 {
                        let mean = texels
                            .iter()
                            .map(|&t| decode[src[t + c] as usize])
                            .sum::<f64>()
                            / 4.0;
                        dst.push((linear_to_srgb(mean) * 255.0).round().clamp(0.0, 255.0) as u8);
                    } else {
                        let sum: u32 = texels.iter().map(|&t| u32::from(src[t + c])).sum();
                        dst.push(((sum + 2) / 4) as u8);
                    }
                }
            }
        }
        levels.push(dst);
        (w, h) = (nw, nh);
    }
    levels
}

/// Evaluates a keyframed curve (cubic Hermite, as Unity's AnimationCurve), clamped at the ends.
pub fn eval_curve(keys: &[Keyframe], t: f64) -> f64 {
    let (first, last) = (keys[0], keys[keys.len() - 1]);
    if t <= first.time {
        return first.value;
    }
    if t >= last.time {
        return last.value;
    }
    let i = keys
        .windows(2)
        .position(|w| t >= w[0].time && t <= w[1].time)
        .unwrap_or(0);
    let (k0, k1) = (keys[i], keys[i + 1]);
    let dt = k1.time - k0.time;
    let s = (t - k0.time) / dt;
    let (s2, s3) = (s * s, s * s * s);
    let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
    let h10 = s3 - 2.0 * s2 + s;
    let h01 = -2.0 * s3 + 3.0 * s2;
    let h11 = s3 - s2;
    h00 * k0.value + h10 * dt * k0.out_slope + h01 * k1.value + h11 * dt * k1.in_slope
}

/// The time span the baked samples cover.
pub fn curve_time_range(keys: &[Keyframe]) -> [f64; 2] {
    [keys[0].time, keys[keys.len() - 1].time]
}

/// `n` samples at evenly spaced times over the keyframes' span.
pub fn sample_curve(keys: &[Keyframe], n: u32) -> Vec<f64> {
    let [t0, t1] = curve_time_range(keys);
    (0..n)
        .map(|i| {
            let t = if n > 1 {
                t0 + (t1 - t0) * i as f64 / (n - 1) as f64
            } else {
                t0
            };
            eval_curve(keys, t)
        })
        .collect()
}

/// Bakes gradient stops into `width` sRGB8 RGBA texels: interpolated in linear
/// light between stops (texel centres), alpha linearly.
pub fn bake_gradient(stops: &[GradientStop], width: u32) -> Vec<u8> {
    let mut out = Vec::with_capacity(width as usize * 4);
    for i in 0..width {
        let x = (i as f64 + 0.5) / width as f64;
        let c = gradient_at(stops, x);
        for (ch, v) in c.iter().enumerate() {
            let enc = if ch < 3 { linear_to_srgb(*v) } else { *v };
            out.push((enc.clamp(0.0, 1.0) * 255.0).round() as u8);
        }
    }
    out
}

/// Linear-light colour of a gradient at `x`.
pub fn gradient_at(stops: &[GradientStop], x: f64) -> [f64; 4] {
    let lin = |s: &GradientStop| {
        [
            srgb_to_linear(s.color[0]),
            srgb_to_linear(s.color[1]),
            srgb_to_linear(s.color[2]),
            s.color[3],
        ]
    };
    let (first, last) = (&stops[0], &stops[stops.len() - 1]);
    if x <= first.position {
        return lin(first);
    }
    if x >= last.position {
        return lin(last);
    }
    let i = stops
        .windows(2)
        .position(|w| x >= w[0].position && x <= w[1].position)
        .unwrap_or(0);
    let (a, b) = (lin(&stops[i]), lin(&stops[i + 1]));
    let span = stops[i + 1].position - stops[i].position;
    let t = if span > 0.0 {
        (x - stops[i].position) / span
    } else {
        0.0
    };
    [0, 1, 2, 3].map(|c| a[c] + (b[c] - a[c]) * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn curve_hits_keys_and_slopes() {
        let keys = [
            Keyframe {
                time: 0.0,
                value: 0.0,
                in_slope: 1.0,
                out_slope: 1.0,
            },
            Keyframe {
                time: 1.0,
                value: 1.0,
                in_slope: 1.0,
                out_slope: 1.0,
            },
        ];
        // A Hermite with matching unit slopes is the straight line.
        for s in sample_curve(&keys, 5).iter().enumerate() {
            assert!((s.1 - s.0 as f64 / 4.0).abs() < 1e-12);
        }
    }

    #[test]
    fn srgb_round_trips() {
        for i in 0..=10 {
            let c = i as f64 / 10.0;
            assert!((linear_to_srgb(srgb_to_linear(c)) - c).abs() < 1e-12);
        }
    }

    #[test]
    fn gradient_ends() {
        let stops = [
            GradientStop {
                position: 0.0,
                color: [0.0, 0.0, 0.0, 1.0],
            },
            GradientStop {
                position: 1.0,
                color: [1.0, 1.0, 1.0, 1.0],
            },
        ];
        let ramp = bake_gradient(&stops, 4);
        assert_eq!(ramp.len(), 16);
        assert!(ramp[0] < ramp[12]);
        assert_eq!(ramp[3], 255);
    }

    #[test]
    fn mip_chains_box_filter_in_linear_light_for_srgb() {
        assert_eq!(mip_level_count(1, 1), 1);
        assert_eq!(mip_level_count(64, 256), 9);
        assert_eq!(mip_level_count(5, 3), 3);
        // 2×2 black/white checker: unorm 128 (127.5 rounded up); sRGB the
        // encoded linear mean, 188 (0.5 linear is 0.7354 encoded).
        let checker = [
            0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255,
        ];
        let unorm = rgba8_mip_chain(2, 2, &checker, false);
        assert_eq!(unorm.len(), 2);
        assert_eq!(unorm[1], [128, 128, 128, 255]);
        let srgb = rgba8_mip_chain(2, 2, &checker, true);
        assert_eq!(srgb[1], [188, 188, 188, 255]);
        // 4×1: the sides go 4×1, 2×1, 1×1; a side of 1 repeats its texel.
        let row = [0, 0, 0, 0, 100, 0, 0, 0, 200, 0, 0, 0, 255, 0, 0, 0];
        let c = rgba8_mip_chain(4, 1, &row, false);
        assert_eq!(c.iter().map(Vec::len).collect::<Vec<_>>(), [16, 8, 4]);
        assert_eq!(c[1], [50, 0, 0, 0, 228, 0, 0, 0]);
        assert_eq!(c[2], [139, 0, 0, 0]);
        // An odd side drops its last column: 3×1 -> 1×1 from texels 0 and 1.
        let c = rgba8_mip_chain(3, 1, &row[..12], false);
        assert_eq!(c[1], [50, 0, 0, 0]);
    }
}
