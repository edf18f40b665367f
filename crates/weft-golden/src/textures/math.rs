//! sin and cos from fixed series, so that generated textures do not depend
//! on the platform's libm (whose last bits differ between systems).

use std::f64::consts::PI;

/// `x` reduced to [−π, π].
fn reduce(x: f64) -> f64 {
    let k = (x / (2.0 * PI)).round();
    x - k * 2.0 * PI
}

/// sin x: Taylor series to x^29 on [−π, π] (error below 1e−15).
pub fn sin(x: f64) -> f64 {
    let r = reduce(x);
    let r2 = r * r;
    // Horner over the odd terms, from the highest: x (1 − x²/(2·3) (1 − x²/(4·5) ...)).
    let mut acc = 1.0;
    let mut n = 29.0;
    while n > 1.0 {
        acc = 1.0 - r2 / (n * (n - 1.0)) * acc;
        n -= 2.0;
    }
    r * acc
}

/// cos x: Taylor series to x^30 on [−π, π].
pub fn cos(x: f64) -> f64 {
    let r = reduce(x);
    let r2 = r * r;
    let mut acc = 1.0;
    let mut n = 30.0;
    while n > 0.0 {
        acc = 1.0 - r2 / (n * (n - 1.0)) * acc;
        n -= 2.0;
    }
    acc
}

#[cfg(test)]
mod tests {
    #[test]
    fn series_match_libm() {
        for i in -400..=400 {
            let x = i as f64 * 0.0173;
            assert!((super::sin(x) - x.sin()).abs() < 1e-14, "sin {x}");
            assert!((super::cos(x) - x.cos()).abs() < 1e-14, "cos {x}");
        }
    }
}
