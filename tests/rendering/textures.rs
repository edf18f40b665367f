//! The character textures (issue 12, `weft_golden::textures`): the committed
//! PNGs are exactly what the generators make now (`cargo xtask textures`
//! rewrites them), and the maps mean what their shaders read.

use std::path::Path;
use weft_golden::textures::{self, face_sdf, flow};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap()
}

/// Every texture regenerated in memory equals the committed bytes, is a
/// small PNG, and decodes back to the generated texels.
#[test]
fn committed_pngs_are_reproduced_byte_for_byte() {
    for t in textures::all() {
        let committed = std::fs::read(root().join(t.path))
            .unwrap_or_else(|e| panic!("{}: {e} (run `cargo xtask textures`)", t.path));
        let fresh = t.encode();
        assert!(
            committed == fresh,
            "{} differs from a fresh generation (run `cargo xtask textures`)",
            t.path
        );
        assert!(t.width <= 256 && t.height <= 256, "{}", t.path);
        assert!(fresh.len() < 48 * 1024, "{}: {} bytes", t.path, fresh.len());
        let (w, h, rgba) = weft_render::decode_png(&fresh, t.path).unwrap();
        assert_eq!((w, h), (t.width, t.height), "{}", t.path);
        // decode_png expands to RGBA (grey replicated); R is the first stored channel.
        for (k, px) in rgba.chunks_exact(4).enumerate() {
            let (x, y) = (k % t.width as usize, k / t.width as usize);
            assert_eq!(px[0], t.at(x, y, 0), "{} texel ({x}, {y})", t.path);
        }
    }
}

/// The face's texels: u < 0.5 is the −X half (the character's right).
struct Sdf {
    t: Vec<f64>,
    n: usize,
}

impl Sdf {
    fn new() -> Sdf {
        let tex = face_sdf::texture();
        let n = tex.width as usize;
        Sdf {
            t: tex.data.iter().map(|&b| f64::from(b) / 255.0).collect(),
            n,
        }
    }
    fn at(&self, i: usize, j: usize) -> f64 {
        self.t[j * self.n + i]
    }
    /// Rows of the face (between the hairline and the chin).
    fn face_rows(&self) -> std::ops::Range<usize> {
        self.n * 42 / 100..self.n * 78 / 100
    }
    /// Whether texel (i, j) is lit, as the seed decides it, for a horizontal
    /// light at `deg` degrees from the front towards −X.
    fn lit(&self, i: usize, j: usize, deg: f64) -> bool {
        let fdotl = (1.0 - deg.to_radians().cos()) / 2.0;
        self.at(i, j) - fdotl > 0.0
    }
}

/// The generator's masks are nested (lit at one angle ⇒ lit at every
/// smaller one) and the threshold map reproduces every one of them: a texel
/// is lit in mask k exactly when its threshold exceeds k / MASKS (up to
/// 8-bit rounding, ± 1/255).
#[test]
fn face_sdf_reproduces_its_nested_masks() {
    let masks = face_sdf::masks();
    assert_eq!(masks.len(), face_sdf::MASKS + 1);
    for k in 1..masks.len() {
        for (t, (&now, &before)) in masks[k].iter().zip(&masks[k - 1]).enumerate() {
            assert!(
                !now || before,
                "mask {k}: texel {t} lit but dark in mask {}",
                k - 1
            );
        }
    }
    let sdf = Sdf::new();
    let mut wrong = 0;
    for (k, mask) in masks.iter().enumerate() {
        let cropped = face_sdf::crop(
            &mask
                .iter()
                .map(|&l| f64::from(u8::from(l)))
                .collect::<Vec<_>>(),
        );
        let f = k as f64 / face_sdf::MASKS as f64;
        for (t, &lit) in cropped.iter().enumerate() {
            let v = sdf.t[t];
            let agrees = if lit == 1.0 {
                v > f - 1.0 / 255.0
            } else {
                v < f + 1.0 / 255.0
            };
            wrong += usize::from(!agrees);
        }
    }
    assert_eq!(wrong, 0, "texels whose threshold disagrees with their mask");
}

/// Smooth: the map uses nearly every 8-bit level over the face (33 masks
/// without interpolation would give 33), no level holds more than 3 % of the
/// face, and neighbouring texels differ by little except along the nose's
/// cast shadow.
#[test]
fn face_sdf_is_smooth() {
    let sdf = Sdf::new();
    let mut counts = [0usize; 256];
    let mut total = 0;
    let mut jumps = 0;
    let mut worst = 0.0f64;
    for j in sdf.face_rows() {
        for i in 0..sdf.n {
            counts[(sdf.at(i, j) * 255.0).round() as usize] += 1;
            total += 1;
            if i + 1 < sdf.n {
                let d = (sdf.at(i + 1, j) - sdf.at(i, j)).abs();
                worst = worst.max(d);
                jumps += usize::from(d > 8.0 / 255.0);
            }
        }
    }
    let levels = counts.iter().filter(|&&c| c > 0).count();
    let most = *counts.iter().max().unwrap();
    eprintln!(
        "levels {levels}, fullest level {most} of {total}, steps > 8/255: {jumps}, worst {worst:.3}"
    );
    assert!(levels >= 200, "{levels} levels");
    assert!(
        (most as f64) < 0.03 * total as f64,
        "{most} of {total} at one level"
    );
    assert!(
        (jumps as f64) < 0.005 * total as f64,
        "{jumps} steps over 8/255"
    );
}

/// A light on the −X side lights the −X half (u < 0.5) first, the lit part
/// of the face grows as the light comes round to the front (by at least
/// ½ % of it every 10°), and at the side (90°) about half the face is lit, nearly all of it
/// on the −X half.
#[test]
fn face_sdf_lights_the_near_half_and_grows_towards_the_front() {
    let sdf = Sdf::new();
    let fraction = |deg: f64| {
        let (mut lit, mut all) = (0usize, 0usize);
        for j in sdf.face_rows() {
            for i in 0..sdf.n {
                lit += usize::from(sdf.lit(i, j, deg));
                all += 1;
            }
        }
        lit as f64 / all as f64
    };
    let mut previous = 0.0;
    for deg in (0..=18).rev().map(|k| f64::from(k) * 10.0) {
        let f = fraction(deg);
        eprintln!("{deg}°: lit {f:.3}");
        if deg < 180.0 {
            assert!(
                f > previous + 0.005,
                "{deg}°: lit {f:.3}, at {}°: {previous:.3}",
                deg + 10.0
            );
        }
        previous = f;
    }
    let side = fraction(90.0);
    assert!((side - 0.5).abs() < 0.06, "lit at 90°: {side:.3}");
    let (mut near, mut far) = (0usize, 0usize);
    for j in sdf.face_rows() {
        for i in 0..sdf.n {
            if sdf.lit(i, j, 90.0) {
                if i < sdf.n / 2 { near += 1 } else { far += 1 }
            }
        }
    }
    assert!(
        far * 20 < near,
        "lit at 90°: {near} texels on −X, {far} on +X"
    );
}

/// The mirror matters: the map is not symmetric (T(u) ≠ T(1 − u)), the −X
/// half holds the higher thresholds, and the nose breaks the antisymmetry
/// T(u) + T(1 − u) = 1 of a bare head (its shadow falls on the far cheek).
#[test]
fn face_sdf_mirrored_texels_differ() {
    let sdf = Sdf::new();
    let (mut diff, mut higher, mut count) = (0.0, 0usize, 0usize);
    let mut asym = 0.0f64;
    for j in sdf.face_rows() {
        for i in 0..sdf.n / 2 {
            let (a, b) = (sdf.at(i, j), sdf.at(sdf.n - 1 - i, j));
            diff += (a - b).abs();
            higher += usize::from(a > b);
            count += 1;
            asym = asym.max((a + b - 1.0).abs());
        }
    }
    let mean = diff / count as f64;
    assert!(mean > 0.2, "mean |T(u) − T(1 − u)| = {mean:.3}");
    assert!(
        higher as f64 > 0.95 * count as f64,
        "{higher} of {count} higher on −X"
    );
    assert!(
        asym > 0.15,
        "nose shadow: max |T(u) + T(1 − u) − 1| = {asym:.3}"
    );
    eprintln!(
        "mean |T(u) − T(1 − u)| {mean:.3}, −X higher {higher}/{count}, max |T(u) + T(1 − u) − 1| {asym:.3}"
    );
}

/// The flow map: unit directions in the tangent plane (no component along
/// the normal), pointing root to tip (+v) and within 30° of the card's
/// strand, and not the constant "keep the mesh's direction" texel.
#[test]
fn flow_map_is_unit_tangent_plane_directions() {
    let t = flow::texture();
    let mut off_axis = 0usize;
    for y in 0..t.height as usize {
        for x in 0..t.width as usize {
            let d = |c| f64::from(t.at(x, y, c)) / 255.0 * 2.0 - 1.0;
            let (fx, fy, fz) = (d(0), d(1), d(2));
            let len = (fx * fx + fy * fy).sqrt();
            assert!((len - 1.0).abs() < 0.01, "({x}, {y}): |xy| = {len}");
            assert!(fz.abs() <= 1.0 / 255.0, "({x}, {y}): normal component {fz}");
            assert!(
                fy > 30f64.to_radians().cos() - 0.01,
                "({x}, {y}): ({fx}, {fy})"
            );
            off_axis += usize::from(fx.abs() > 0.05);
        }
    }
    assert!(
        off_axis > (t.width * t.height / 4) as usize,
        "{off_axis} texels bend"
    );
}
