//! Numbers that must fit the GPU type they become: `f32` for floats, vectors,
//! colours, curve keyframes, ranges and slider settings, `i32` for int
//! parameters, `u32` for instance counts. A value outside its type's range is
//! a `type-range` error at the value, naming the range.

use crate::diag::Span;
use crate::toml_reader::{Cx, F32_RANGE, Value};
use toml::de::DeValue;

/// The GPU scalar type a number is stored as.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GpuType {
    F32,
    I32,
    U32,
}

impl GpuType {
    pub fn name(self) -> &'static str {
        match self {
            GpuType::F32 => "f32",
            GpuType::I32 => "i32",
            GpuType::U32 => "u32",
        }
    }

    /// The type's range as shown in messages.
    pub fn range_text(self) -> &'static str {
        match self {
            GpuType::F32 => F32_RANGE,
            GpuType::I32 => "whole numbers from -2147483648 to 2147483647",
            GpuType::U32 => "whole numbers from 0 to 4294967295",
        }
    }

    /// The type's bounds, for labels.
    pub fn bounds(self) -> &'static str {
        match self {
            GpuType::F32 => "±3.4028235e38",
            GpuType::I32 => "[-2147483648, 2147483647]",
            GpuType::U32 => "[0, 4294967295]",
        }
    }

    /// Whether `x` is a value of the type (floats round to the nearest f32).
    pub fn fits(self, x: f64) -> bool {
        match self {
            GpuType::F32 => (x as f32).is_finite(),
            GpuType::I32 => {
                x.fract() == 0.0 && (f64::from(i32::MIN)..=f64::from(i32::MAX)).contains(&x)
            }
            GpuType::U32 => x.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&x),
        }
    }
}

/// A number as written in messages: exponent notation for huge or tiny magnitudes.
pub fn show(x: f64) -> String {
    let a = x.abs();
    if a != 0.0 && !(1e-6..1e16).contains(&a) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// Reports `x` (written at `span`) unless it fits `ty`; `what` names the
/// value ("`default` of parameter `roughness`"). True when it fits.
pub fn check(cx: &mut Cx, ty: GpuType, x: f64, span: Span, what: &str) -> bool {
    if ty.fits(x) {
        return true;
    }
    let name = ty.name();
    cx.error_with_note(
        "type-range",
        format!("{what} does not fit in an {name}"),
        span,
        format!("{} is outside {name}'s range {}", show(x), ty.bounds()),
        format!(
            "the GPU stores this value as an {name}: {}",
            ty.range_text()
        ),
    );
    false
}

/// [`check`] for every number of a TOML number or array of numbers (each
/// element at its own span); other values are left to the type checks.
pub fn check_value(cx: &mut Cx, ty: GpuType, v: &Value, what: &str) -> bool {
    let mut ok = true;
    match v.get_ref() {
        DeValue::Array(items) => {
            for item in items.iter() {
                ok &= check_value(cx, ty, item, what);
            }
        }
        _ => {
            if let Some(x) = number(v) {
                ok &= check(cx, ty, x, v.span(), what);
            }
        }
    }
    ok
}

/// A TOML integer or float as f64 (None for other values and for integers
/// beyond i64, which the type checks report).
fn number(v: &Value) -> Option<f64> {
    match v.get_ref() {
        DeValue::Integer(i) => i64::from_str_radix(i.as_str(), i.radix())
            .ok()
            .map(|n| n as f64),
        DeValue::Float(f) => f.as_str().parse::<f64>().ok().filter(|x| x.is_finite()),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges() {
        assert!(GpuType::F32.fits(3.4028235e38));
        assert!(GpuType::F32.fits(-3.4028235e38));
        assert!(!GpuType::F32.fits(3.5e38));
        assert!(!GpuType::F32.fits(-1e39));
        assert!(GpuType::F32.fits(1e-50), "underflows to 0, still an f32");
        assert!(GpuType::I32.fits(2147483647.0));
        assert!(!GpuType::I32.fits(2147483648.0));
        assert!(GpuType::I32.fits(-2147483648.0));
        assert!(!GpuType::I32.fits(-2147483649.0));
        assert!(GpuType::U32.fits(4294967295.0));
        assert!(!GpuType::U32.fits(-1.0));
        assert_eq!(show(1e39), "1e39");
        assert_eq!(show(0.5), "0.5");
        assert_eq!(show(3000000000.0), "3000000000");
    }
}
