//! The exact Euclidean distance transform of Felzenszwalb & Huttenlocher
//! ("Distance Transforms of Sampled Functions", 2012): squared distances by
//! the lower envelope of parabolas, one 1-D pass per column then per row.

/// Stands for "no site": larger than any squared distance on a texture, and
/// small enough that differences of it stay exact in f64.
const FAR: f64 = 1e20;

/// The 1-D transform of `f` (squared distances) into `d`, using `v` and `z`
/// as scratch (lengths n and n + 1).
fn transform_1d(f: &[f64], d: &mut [f64], v: &mut [usize], z: &mut [f64]) {
    let n = f.len();
    let mut k = 0usize;
    v[0] = 0;
    z[0] = f64::NEG_INFINITY;
    z[1] = f64::INFINITY;
    let sq = |q: usize| (q * q) as f64;
    for q in 1..n {
        // Where the parabola from q meets the rightmost one of the envelope;
        // parabolas it hides are dropped (z[0] = −∞ stops the loop).
        let meet = |p: usize| ((f[q] + sq(q)) - (f[p] + sq(p))) / (2.0 * (q as f64 - p as f64));
        let mut s = meet(v[k]);
        while s <= z[k] {
            k -= 1;
            s = meet(v[k]);
        }
        k += 1;
        v[k] = q;
        z[k] = s;
        z[k + 1] = f64::INFINITY;
    }
    let mut k = 0usize;
    for (q, dq) in d.iter_mut().enumerate() {
        while z[k + 1] < q as f64 {
            k += 1;
        }
        let p = v[k];
        let dx = q as f64 - p as f64;
        *dq = dx * dx + f[p];
    }
}

/// For each texel of a `width` × `height` grid, the Euclidean distance (in
/// texels, centre to centre) to the nearest texel where `site` is true;
/// `None` where there is no site at all.
pub fn distance_to(site: &[bool], width: usize, height: usize) -> Option<Vec<f64>> {
    if !site.iter().any(|&s| s) {
        return None;
    }
    let mut g: Vec<f64> = site.iter().map(|&s| if s { 0.0 } else { FAR }).collect();
    let n = width.max(height);
    let (mut f, mut d) = (vec![0.0; n], vec![0.0; n]);
    let (mut v, mut z) = (vec![0usize; n], vec![0.0; n + 1]);
    for x in 0..width {
        for y in 0..height {
            f[y] = g[y * width + x];
        }
        transform_1d(&f[..height], &mut d[..height], &mut v, &mut z);
        for y in 0..height {
            g[y * width + x] = d[y];
        }
    }
    for y in 0..height {
        let row = &mut g[y * width..(y + 1) * width];
        f[..width].copy_from_slice(row);
        transform_1d(&f[..width], &mut d[..width], &mut v, &mut z);
        row.copy_from_slice(&d[..width]);
    }
    Some(g.into_iter().map(f64::sqrt).collect())
}

#[cfg(test)]
mod tests {
    /// Against brute force on an irregular pattern.
    #[test]
    fn exact_against_brute_force() {
        let (w, h) = (23, 17);
        let site: Vec<bool> = (0..w * h)
            .map(|i| (i * 7919 + i / 5 * 31) % 37 == 0)
            .collect();
        let d = super::distance_to(&site, w, h).unwrap();
        for y in 0..h {
            for x in 0..w {
                let mut best = f64::INFINITY;
                for (j, _) in site.iter().enumerate().filter(|(_, s)| **s) {
                    let (dx, dy) = ((j % w) as f64 - x as f64, (j / w) as f64 - y as f64);
                    best = best.min((dx * dx + dy * dy).sqrt());
                }
                assert_eq!(d[y * w + x], best, "({x}, {y})");
            }
        }
        assert!(super::distance_to(&[false; 6], 3, 2).is_none());
    }
}
