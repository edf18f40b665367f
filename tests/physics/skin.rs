//! The skin material's pre-integrated diffuse (issue 12, deliverable 1).
//!
//! - The tables the toolchain bakes (`generated/skin/*.rgba16f`, from
//!   `[tables]` in skin.toml by `weft_compiler::bake::skin`) match an
//!   independent evaluation of Penner & Borshukov's integral: adaptive
//!   Simpson straight on x in [−X, X], split at the kernel's peak and the
//!   cosine's kinks, with Burley's d R(d) written out in full (its constants
//!   cancel in the ratio, which this does not rely on).
//! - The reference tier's quadrature (64 warped points per pixel, the
//!   bake's own scheme) has converged: against 4096 points.
//! - The physics: more curvature wraps more light past the terminator, red
//!   (the smallest shape s) most.

use std::f64::consts::PI;
use weft_compiler::bake::skin::{SKIN_BAKE_POINTS, preintegrated};
use weft_front::model::TableRecipe;
use weft_tests::repo;

/// (name, size, shape, half ring) of each table skin.toml declares.
fn tables() -> Vec<(String, [u32; 2], [f64; 3], bool)> {
    let mut db = weft_front::SourceDb::default();
    let mut diags = weft_front::Diagnostics::default();
    let root = repo().join("materials");
    let m = weft_front::load_material(&root.join("skin/skin.toml"), &root, &mut db, &mut diags)
        .expect("skin.toml loads");
    m.tables
        .iter()
        .map(|t| match t.recipe {
            TableRecipe::PreintegratedSkin { shape, half_ring } => {
                (t.name.clone(), t.size, shape, half_ring)
            }
            TableRecipe::ThinFilmSensitivity { .. } => {
                panic!("skin declares a film table `{}`", t.name)
            }
        })
        .collect()
}

fn read_table(name: &str, size: [u32; 2]) -> Vec<[f32; 4]> {
    let path = repo().join(format!("generated/skin/{name}.rgba16f"));
    let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert_eq!(
        bytes.len(),
        (size[0] * size[1] * 8) as usize,
        "{name}: size"
    );
    bytes
        .chunks_exact(8)
        .map(|t| {
            std::array::from_fn(|c| half::f16::from_le_bytes([t[2 * c], t[2 * c + 1]]).to_f32())
        })
        .collect()
}

/// Burley's normalised diffusion profile times d (A = 1).
fn d_r(d: f64, s: f64) -> f64 {
    s * ((-s * d).exp() + (-s * d / 3.0).exp()) / (8.0 * PI)
}

/// One piece of the adaptive Simpson rule: its ends, the integrand at the
/// ends and the middle, and Simpson's estimate over it.
#[derive(Clone, Copy)]
struct Piece {
    a: f64,
    b: f64,
    fa: f64,
    fm: f64,
    fb: f64,
    whole: f64,
}

impl Piece {
    fn new(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> Piece {
        let (fa, fm, fb) = (f(a), f(0.5 * (a + b)), f(b));
        Piece::with(a, b, fa, fm, fb)
    }

    fn with(a: f64, b: f64, fa: f64, fm: f64, fb: f64) -> Piece {
        let whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
        Piece {
            a,
            b,
            fa,
            fm,
            fb,
            whole,
        }
    }
}

fn simpson(f: &dyn Fn(f64) -> f64, p: Piece, tol: f64, depth: u32) -> f64 {
    let m = 0.5 * (p.a + p.b);
    let left = Piece::with(p.a, m, p.fa, f(0.5 * (p.a + m)), p.fm);
    let right = Piece::with(m, p.b, p.fm, f(0.5 * (m + p.b)), p.fb);
    let sum = left.whole + right.whole;
    if depth == 0 || (sum - p.whole).abs() <= 15.0 * tol {
        return sum + (sum - p.whole) / 15.0;
    }
    simpson(f, left, tol / 2.0, depth - 1) + simpson(f, right, tol / 2.0, depth - 1)
}

fn integrate(f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    simpson(f, Piece::new(f, a, b), 1e-10, 40)
}

/// D(θ, r) for one channel, independently: ∫ sat(cos(θ + x)) dR dx / ∫ dR dx
/// over [−X, X], split where the integrand has a peak or a kink.
fn exact(cos_theta: f64, curvature: f64, s: f64, x_max: f64) -> f64 {
    if curvature == 0.0 {
        return cos_theta.max(0.0);
    }
    let r = 1.0 / curvature;
    let theta = cos_theta.acos();
    let w = |x: f64| d_r(2.0 * r * (x / 2.0).sin().abs(), s);
    let lit = |x: f64| (theta + x).cos().max(0.0) * w(x);
    // The kernel peaks at 0 with a width of about 1/(s r): cut the range
    // geometrically towards 0 so that no piece hides it from Simpson's three
    // points, and at the cosine's kinks.
    let mut cuts = vec![-x_max, 0.0, x_max];
    for k in 1..48 {
        let c = x_max * 0.5f64.powi(k);
        cuts.extend([-c, c]);
    }
    for k in [-PI / 2.0 - theta, PI / 2.0 - theta] {
        if k > -x_max && k < x_max && k != 0.0 {
            cuts.push(k);
        }
    }
    cuts.sort_by(f64::total_cmp);
    let (mut num, mut den) = (0.0, 0.0);
    for pair in cuts.windows(2) {
        num += integrate(&lit, pair[0], pair[1]);
        den += integrate(&w, pair[0], pair[1]);
    }
    num / den
}

#[test]
fn the_baked_tables_match_an_independent_integral() {
    let tables = tables();
    assert_eq!(tables.len(), 2, "skin_lut and seed_lut");
    for (name, size, shape, half_ring) in tables {
        let texels = read_table(&name, size);
        let x_max = if half_ring { PI / 2.0 } else { PI };
        let mut worst = 0.0f64;
        // Every 3rd column and row, and the last ones.
        let pick = |n: u32| (0..n).filter(move |i| i % 3 == 0 || *i == n - 1);
        for j in pick(size[1]) {
            let v = f64::from(j) / f64::from(size[1] - 1);
            for i in pick(size[0]) {
                let u = f64::from(i) / f64::from(size[0] - 1);
                let texel = texels[(j * size[0] + i) as usize];
                for c in 0..3 {
                    let e = exact(2.0 * u - 1.0, v, shape[c], x_max);
                    let diff = (f64::from(texel[c]) - e).abs();
                    worst = worst.max(diff);
                    // f16 rounds values in [0.5, 1] to 2^-11 steps: 4.9e-4
                    // at most; the bake's quadrature adds well under that.
                    assert!(
                        diff <= 1e-3,
                        "{name} texel ({i}, {j}) channel {c}: baked {} vs integral {e:.6}",
                        texel[c]
                    );
                }
                assert_eq!(texel[3], 1.0, "{name}: alpha");
            }
        }
        println!("{name}: worst |baked − integral| {worst:.2e} over the sampled texels");
    }
}

#[test]
fn the_reference_quadrature_has_converged() {
    // The reference tier's per-pixel integral uses this scheme with 64
    // points (skin.wgsl, skin_preintegrated); the bake uses SKIN_BAKE_POINTS.
    let (_, _, shape, _) = tables().into_iter().find(|t| t.0 == "skin_lut").unwrap();
    let mut worst = 0.0f64;
    for j in 0..=16 {
        let v = f64::from(j) / 16.0;
        for i in 0..=32 {
            let cos_theta = f64::from(i) / 16.0 - 1.0;
            let coarse = preintegrated(cos_theta, v, shape, PI, 64);
            let fine = preintegrated(cos_theta, v, shape, PI, SKIN_BAKE_POINTS);
            for c in 0..3 {
                worst = worst.max((coarse[c] - fine[c]).abs());
            }
        }
    }
    println!("64 vs {SKIN_BAKE_POINTS} points: worst difference {worst:.2e}");
    // Below one 8-bit display step (1/255).
    assert!(worst < 1.0 / 255.0, "64 points: {worst}");
}

#[test]
fn curvature_wraps_light_past_the_terminator_red_most() {
    let (_, _, shape, _) = tables().into_iter().find(|t| t.0 == "skin_lut").unwrap();
    // Just beyond the terminator (N.L = −0.1): flat skin gets nothing.
    let mut last = [0.0; 3];
    for v in [0.0, 0.25, 0.5, 1.0] {
        let d = preintegrated(-0.1, v, shape, PI, SKIN_BAKE_POINTS);
        for c in 0..3 {
            assert!(d[c] >= last[c], "curvature {v}: {d:?} after {last:?}");
        }
        if v > 0.0 {
            assert!(d[0] > d[1] && d[1] > d[2], "red wraps most at {v}: {d:?}");
        }
        last = d;
    }
    assert!(
        last[0] > 0.02,
        "a curved surface lets red through: {last:?}"
    );
    // Fully lit and flat: the plain cosine.
    let d = preintegrated(0.8, 0.0, shape, PI, 64);
    assert_eq!(d, [0.8; 3]);
}
