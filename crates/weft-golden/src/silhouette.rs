//! Where the shell bench's error lies: the silhouette band of the sphere
//! (pixels whose view ray grazes the surface, |N·V| below a bound, or misses
//! the body and sees only the fur around it) against the interior.
//!
//! Shell fur's known defect is the silhouette, where shells are seen edge-on
//! and gaps show (Lengyel et al. 2001 add fins there). The split says how
//! much of an N-shell image's error against the reference count a
//! silhouette-only remedy could remove at most: [`SilhouetteSplit::perfect`]
//! is the error left when the band is copied from the reference (a perfect
//! silhouette at no cost).

use crate::shading::{ImageError, flip_map, image_error};
use weft_render::{HdrImage, Scene, math};

/// The error of one image against its reference, split by the band.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SilhouetteSplit {
    /// Fraction of object pixels in the band.
    pub band_pixels: f64,
    /// FLIP mean over the band's object pixels.
    pub band_flip: f64,
    /// FLIP mean over the other object pixels.
    pub interior_flip: f64,
    /// The band's share of the summed FLIP over object pixels.
    pub band_share: f64,
    /// The whole image's error when the band is the reference's.
    pub perfect: ImageError,
}

/// The band of the unit sphere at the origin (`Scene::sphere`'s body) seen
/// by `scene`'s camera at `width`×`height`: true where the ray through the
/// pixel centre misses the sphere or meets it with |N·V| < `max_n_dot_v`.
/// Row-major, row 0 at the top (as rendered images).
pub fn sphere_band(scene: &Scene, width: u32, height: u32, max_n_dot_v: f64) -> Vec<bool> {
    let cam = &scene.camera;
    let f = math::normalize(math::sub(cam.target, cam.eye));
    let s = math::normalize(math::cross(f, cam.up));
    let u = math::cross(s, f);
    let tan = f64::from((0.5 * cam.fov_y_degrees.to_radians()).tan());
    let aspect = f64::from(width) / f64::from(height);
    let eye = cam.eye.map(f64::from);
    let mut band = Vec::with_capacity((width * height) as usize);
    for y in 0..height {
        let ny = 1.0 - 2.0 * (f64::from(y) + 0.5) / f64::from(height);
        for x in 0..width {
            let nx = 2.0 * (f64::from(x) + 0.5) / f64::from(width) - 1.0;
            let d: [f64; 3] = std::array::from_fn(|i| {
                f64::from(f[i]) + f64::from(s[i]) * nx * tan * aspect + f64::from(u[i]) * ny * tan
            });
            let len = d.iter().map(|c| c * c).sum::<f64>().sqrt();
            let d = d.map(|c| c / len);
            // |eye + t d|² = 1: t² + 2 b t + c = 0.
            let b: f64 = (0..3).map(|i| eye[i] * d[i]).sum();
            let c: f64 = eye.iter().map(|e| e * e).sum::<f64>() - 1.0;
            let disc = b * b - c;
            band.push(if disc < 0.0 {
                true
            } else {
                let t = -b - disc.sqrt();
                // The hit point is its own normal; V = -d.
                let n_dot_v: f64 = -(0..3).map(|i| (eye[i] + t * d[i]) * d[i]).sum::<f64>();
                n_dot_v.abs() < max_n_dot_v
            });
        }
    }
    band
}

/// Splits `test`'s error against `reference` by `band` (from
/// [`sphere_band`] at the images' size).
pub fn split(reference: &HdrImage, test: &HdrImage, band: &[bool]) -> SilhouetteSplit {
    let (flip, object) = flip_map(reference, test);
    assert_eq!(band.len(), flip.len());
    let (mut in_band, mut inside) = ((0.0f64, 0usize), (0.0f64, 0usize));
    for ((v, o), b) in flip.iter().zip(&object).zip(band) {
        if !*o {
            continue;
        }
        let acc = if *b { &mut in_band } else { &mut inside };
        acc.0 += f64::from(*v);
        acc.1 += 1;
    }
    let mean = |(sum, n): (f64, usize)| if n == 0 { 0.0 } else { sum / n as f64 };
    let total = in_band.0 + inside.0;
    let mut patched = test.clone();
    for ((p, r), b) in patched.pixels.iter_mut().zip(&reference.pixels).zip(band) {
        if *b {
            *p = *r;
        }
    }
    SilhouetteSplit {
        band_pixels: in_band.1 as f64 / (in_band.1 + inside.1).max(1) as f64,
        band_flip: mean(in_band),
        interior_flip: mean(inside),
        band_share: if total > 0.0 { in_band.0 / total } else { 0.0 },
        perfect: image_error(reference, &patched),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use weft_render::SceneKind;

    #[test]
    fn the_band_is_a_ring_around_the_sphere() {
        let scene = Scene::new(SceneKind::Sphere);
        let n = 64;
        let band = sphere_band(&scene, n, n, 0.3);
        let at = |x: u32, y: u32| band[(y * n + x) as usize];
        // The camera looks at the centre: the middle sees the sphere face
        // on, the corners miss it.
        assert!(!at(n / 2, n / 2));
        assert!(at(0, 0) && at(n - 1, n - 1));
        let ring = (0..n / 2).filter(|&x| at(x, n / 2)).count();
        let missed = (0..n / 2).take_while(|&x| at(x, n / 2)).count();
        assert!(ring > 0 && ring < (n / 2) as usize, "{ring}");
        assert_eq!(ring, missed, "the band is contiguous from the edge in");
        // Symmetric left and right (the camera has no roll).
        for y in 0..n {
            for x in 0..n {
                assert_eq!(at(x, y), at(n - 1 - x, y), "({x}, {y})");
            }
        }
    }

    #[test]
    fn an_error_only_in_the_band_is_all_the_bands() {
        let scene = Scene::new(SceneKind::Sphere);
        let n = 48;
        let band = sphere_band(&scene, n, n, 0.3);
        let grey = HdrImage {
            width: n,
            height: n,
            pixels: vec![[0.4, 0.3, 0.2, 1.0]; (n * n) as usize],
        };
        let mut test = grey.clone();
        for (p, b) in test.pixels.iter_mut().zip(&band) {
            if *b {
                *p = [0.9, 0.9, 0.9, 1.0];
            }
        }
        let s = split(&grey, &test, &band);
        assert!(s.band_flip > 0.1, "{s:?}");
        assert!(s.band_share > 0.8, "{s:?}");
        assert!(s.perfect.flip_mean < 1e-6, "{s:?}");
        assert!(s.band_pixels > 0.0 && s.band_pixels < 1.0);
    }
}
