//! What makes an output value bad: NaN, Inf, negative, beyond f16, or a
//! half-precision value that differs visibly from its f32 fallback.

use std::fmt;

/// Largest finite f16: anything above it is "absurdly large" (it would be
/// Inf in an `Rgba16Float` target).
pub const MAX_HALF: f32 = 65504.0;

/// Why an output value is bad.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum BadKind {
    NaN,
    Inf,
    Negative,
    /// Finite but above [`MAX_HALF`].
    Huge,
    /// A half-precision variant saturates at the f16 maximum (or overflows to
    /// Inf) where its f32 fallback stays below it.
    HalfOverflow,
    /// A half-precision variant gives 0 where its f32 fallback is visible
    /// (at least [`VISIBLE`]): an f16 underflow that changes the picture.
    HalfUnderflow,
}

/// The smallest linear value an 8-bit sRGB display shows as non-black (1/255
/// after the sRGB curve): below it an underflow to 0 cannot be seen.
pub const VISIBLE: f32 = 1.0 / 255.0 / 12.92;

/// Compares a half-precision render's channel with its f32 fallback's.
pub fn classify_half(half: f32, full: f32) -> Option<BadKind> {
    if (half >= MAX_HALF || half.is_infinite()) && full < MAX_HALF {
        Some(BadKind::HalfOverflow)
    } else if half == 0.0 && full >= VISIBLE {
        Some(BadKind::HalfUnderflow)
    } else {
        None
    }
}

impl fmt::Display for BadKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            BadKind::NaN => "NaN",
            BadKind::Inf => "Inf",
            BadKind::Negative => "negative",
            BadKind::Huge => "> 65504",
            BadKind::HalfOverflow => "f16 overflow (the f32 fallback stays below 65504)",
            BadKind::HalfUnderflow => "f16 underflow to 0 (the f32 fallback is visible)",
        })
    }
}

/// NaN, ±Inf, negative (< 0; -0.0 is fine) or above 65504.
pub fn classify(x: f32) -> Option<BadKind> {
    if x.is_nan() {
        Some(BadKind::NaN)
    } else if x.is_infinite() {
        Some(BadKind::Inf)
    } else if x < 0.0 {
        Some(BadKind::Negative)
    } else if x > MAX_HALF {
        Some(BadKind::Huge)
    } else {
        None
    }
}
