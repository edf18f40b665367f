//! The face's SDF threshold map (seed 004 §4, the Genshin-style face
//! shadow), made the way artists' tools make it: binary shadow masks of a
//! stylised face for the light swinging from the front round the −X side to
//! the back, each turned into a signed distance field (`edt`), and each
//! texel's threshold interpolated between the two masks whose fields change
//! sign there.
//!
//! The shader (seed §4) reads `T = sdf.r` at uv for a light on the −X side
//! (at (1 − u, v) on the +X side) and lights a texel where
//! `T − FdotL > 0`, `FdotL = dot(forward, L_h) · −0.5 + 0.5` (0 with the
//! light in front, ½ at the side, 1 behind). So T is the FdotL at which the
//! texel goes dark, and the masks are taken at evenly spaced FdotL.
//!
//! The face is the bust's head (`head`) with stylised relief along its
//! normal where the bust's face is: a nose ridge from between the eyes to a
//! tip below them, cheekbones, and eye sockets around the eyes' positions.
//! A texel is lit when its relief normal faces the horizontal light and no
//! relief between it and the light (in its horizontal slice: a row of the
//! map, θ constant) rises above the light ray: the terminator bends round the
//! cheekbones and eye sockets, and the nose casts its shadow onto the far
//! cheek.

use super::head::{self, V3};
use super::{Channels, Texture, edt, quantise};
use weft_render::EYE_CENTRES;

/// Output size (square, covering the head's front half u, v ∈ [0, 1]).
pub const SIZE: usize = 256;
/// Columns generated beyond each side (to u = −3/16 and 1 + 3/16), so that
/// the first shadow and the last light, islands centred on the ears' line
/// (u = 1 and 0, about 35 texels wide each way), lie whole in the masks'
/// domain and their deepest texels are found.
const PAD: usize = 48;
const WIDTH: usize = SIZE + 2 * PAD;
/// Masks at FdotL = k / MASKS, k = 0..=MASKS.
pub const MASKS: usize = 32;

/// A C² bump of radius 1: (1 − r²)³ inside, 0 outside.
fn bump(r2: f64) -> f64 {
    if r2 >= 1.0 {
        0.0
    } else {
        let a = 1.0 - r2;
        a * a * a
    }
}

fn sq(x: f64) -> f64 {
    x * x
}

/// The face's features in head uv.
struct Face {
    eyes: [(f64, f64); 2],
}

impl Face {
    /// Places the features from the bust: each eye at the head texel nearest
    /// its eyeball's centre.
    fn new() -> Face {
        let nearest = |c: [f32; 3]| {
            let c: V3 = c.map(f64::from);
            let mut best = (f64::INFINITY, 0.0, 0.0);
            for j in 0..SIZE {
                for i in 0..SIZE {
                    let (u, v) = (
                        (i as f64 + 0.5) / SIZE as f64,
                        (j as f64 + 0.5) / SIZE as f64,
                    );
                    let (t, p) = head::angles(u, v);
                    let d = head::sub(head::point(t, p), c);
                    let d2 = head::dot(d, d);
                    if d2 < best.0 {
                        best = (d2, u, v);
                    }
                }
            }
            (best.1, best.2)
        };
        Face {
            eyes: [nearest(EYE_CENTRES[0]), nearest(EYE_CENTRES[1])],
        }
    }

    /// Relief height along the head's normal at (u, v), in head units.
    fn relief(&self, u: f64, v: f64) -> f64 {
        let (eu, ev) = self.eyes[0];
        let eye_gap = 0.5 - eu;
        // Nose: a ridge on u = 0.5 from eye level to the tip 0.085 below,
        // rising and widening towards the tip, ending just under it.
        let tip = ev + 0.085;
        let t = ((v - (ev - 0.01)) / (tip - (ev - 0.01))).clamp(0.0, 1.0);
        let width = 0.022 + 0.018 * t;
        let under = if v > tip {
            bump(sq((v - tip) / 0.022))
        } else {
            1.0
        };
        // The bridge starts between the eyes.
        let over = if v < ev {
            bump(sq((v - ev) / 0.03))
        } else {
            1.0
        };
        let nose = (0.012 + 0.06 * t * t) * under * over * bump(sq((u - 0.5) / width));
        // Cheekbones: under and outside the eyes.
        let mut cheeks = 0.0;
        let mut sockets = 0.0;
        for side in [-1.0, 1.0] {
            let cu = 0.5 + side * 1.3 * eye_gap;
            let cv = ev + 0.075;
            cheeks += 0.028 * bump(sq((u - cu) / 0.085) + sq((v - cv) / 0.06));
            let su = 0.5 + side * eye_gap;
            sockets += 0.022 * bump(sq((u - su) / 0.07) + sq((v - ev) / 0.05));
        }
        nose + cheeks - sockets
    }
}

/// u, v of column `i` (of the padded grid) and row `j`.
fn uv(i: isize, j: isize) -> (f64, f64) {
    (
        (i as f64 - PAD as f64 + 0.5) / SIZE as f64,
        (j as f64 + 0.5) / SIZE as f64,
    )
}

/// The threshold each texel of the padded grid would have with infinitely
/// many masks: the FdotL at which its relief normal turns from the light or
/// the relief towards the light first blocks it (row-major, WIDTH × SIZE).
pub fn direct_thresholds_padded() -> Vec<f64> {
    let face = Face::new();
    // Relief points with a one-texel border, for central differences.
    let (bw, bh) = (WIDTH + 2, SIZE + 2);
    let mut pts = Vec::with_capacity(bw * bh);
    for j in -1..=SIZE as isize {
        for i in -1..=WIDTH as isize {
            let (u, v) = uv(i, j);
            let (t, p) = head::angles(u, v);
            let base = head::point(t, p);
            let n = head::normal(t, p);
            pts.push(head::add(base, head::scale(n, face.relief(u, v))));
        }
    }
    let at = |i: usize, j: usize| pts[(j + 1) * bw + (i + 1)];
    let mut out = vec![0.0; WIDTH * SIZE];
    for j in 0..SIZE {
        for i in 0..WIDTH {
            // Outward normal: down (θ) × east (φ).
            let down = head::sub(pts[(j + 2) * bw + i + 1], pts[j * bw + i + 1]);
            let east = head::sub(pts[(j + 1) * bw + i + 2], pts[(j + 1) * bw + i]);
            let n = head::cross(down, east);
            // Light L(α) = (−sin α, 0, cos α): lit while cos α > c. The
            // normal faces it while cos α > n_x / |n_h|; a relief point Q
            // towards −X blocks it once cos α ≤ d_z / |d| (d = Q − P in xz).
            let mut c = n[0] / (n[0] * n[0] + n[2] * n[2]).sqrt();
            let p = at(i, j);
            for q in 0..i {
                let d = head::sub(at(q, j), p);
                if d[0] < 0.0 {
                    c = c.max(d[2] / (d[0] * d[0] + d[2] * d[2]).sqrt());
                }
            }
            out[j * WIDTH + i] = (1.0 - c) / 2.0;
        }
    }
    out
}

/// The shadow masks (lit = true) at FdotL = k / MASKS, k = 0..=MASKS, over
/// the padded grid. Nested by construction (each texel's light arc is one
/// interval from the front).
pub fn masks() -> Vec<Vec<bool>> {
    let direct = direct_thresholds_padded();
    (0..=MASKS)
        .map(|k| {
            let f = k as f64 / MASKS as f64;
            direct.iter().map(|&t| t > f).collect()
        })
        .collect()
}

/// The threshold map from nested masks (`masks[k]` lit at FdotL = k / n, n =
/// masks.len() − 1, `width` × `height`): a texel lit in mask k and dark in
/// mask k + 1 gets (k + a / (a + b)) / n, a its distance to mask k's shadow
/// and b to mask k + 1's light (texel centres to the boundary between
/// texels: distances − ½). Where mask k + 1 has no light left, the last
/// island of light shrinks to its deepest texel (b = max a − a); where mask
/// k has no shadow yet, the first one grows from its deepest texel
/// (a = max b − b).
pub fn thresholds_from_masks(masks: &[Vec<bool>], width: usize, height: usize) -> Vec<f64> {
    let n = masks.len() - 1;
    let mut out = vec![0.0; width * height];
    for k in 0..n {
        let lit = &masks[k];
        let next = &masks[k + 1];
        let band: Vec<usize> = (0..width * height)
            .filter(|&t| lit[t] && !next[t])
            .collect();
        let dark: Vec<bool> = lit.iter().map(|l| !l).collect();
        let to_dark = edt::distance_to(&dark, width, height);
        let to_light = edt::distance_to(next, width, height);
        let a_of = |t: usize| to_dark.as_ref().map(|d| d[t] - 0.5);
        let b_of = |t: usize| to_light.as_ref().map(|d| d[t] - 0.5);
        let a_max = band.iter().filter_map(|&t| a_of(t)).fold(0.0, f64::max);
        let b_max = band.iter().filter_map(|&t| b_of(t)).fold(0.0, f64::max);
        for &t in &band {
            let (a, b) = match (a_of(t), b_of(t)) {
                (Some(a), Some(b)) => (a, b),
                // The first shadow grows from its island's deepest texel.
                (None, Some(b)) => (b_max - b, b),
                // The last light shrinks to its island's deepest texel.
                (Some(a), None) => (a, a_max - a),
                (None, None) => (1.0, 1.0),
            };
            let frac = if a + b > 0.0 { a / (a + b) } else { 0.5 };
            out[t] = (k as f64 + frac) / n as f64;
        }
    }
    // Texels lit in every mask but the last are in the last band; texels
    // dark in mask 0 keep 0.
    out
}

/// The threshold map, unquantised (row-major, SIZE × SIZE, u ∈ [0, 1]).
pub fn thresholds() -> Vec<f64> {
    let padded = thresholds_from_masks(&masks(), WIDTH, SIZE);
    crop(&padded)
}

/// The central SIZE columns of a padded grid.
pub fn crop(padded: &[f64]) -> Vec<f64> {
    (0..SIZE)
        .flat_map(|j| {
            padded[j * WIDTH + PAD..j * WIDTH + PAD + SIZE]
                .iter()
                .copied()
        })
        .collect()
}

pub fn texture() -> Texture {
    Texture {
        path: "materials/face/textures/face_sdf.png",
        width: SIZE as u32,
        height: SIZE as u32,
        channels: Channels::Grey,
        srgb: false,
        data: thresholds().into_iter().map(quantise).collect(),
    }
}
