//! What each check measures, one row per scene and tier, each with the
//! bound it is held to; [`GlintReport`] gathers them with the cost.

use super::{MAX_DENSE_ENERGY_ERROR, MAX_DISTANT_FLIP, MAX_DISTANT_RATIO, MAX_ENERGY_ERROR};
use weft_render::SceneKind;

/// One energy measurement: glint energy of a tier against the smooth lobe's.
#[derive(Clone, Debug, PartialEq)]
pub struct EnergyRow {
    pub scene: SceneKind,
    pub case: &'static str,
    pub tier: String,
    /// Σ r + g + b of the glints alone (render minus render at intensity 0).
    pub glints: f64,
    pub smooth: f64,
}

impl EnergyRow {
    /// glints / smooth − 1.
    pub fn relative(&self) -> f64 {
        self.glints / self.smooth - 1.0
    }

    pub fn bound(&self) -> f64 {
        if self.case == "dense" {
            MAX_DENSE_ENERGY_ERROR
        } else {
            MAX_ENERGY_ERROR
        }
    }

    pub fn within_bound(&self) -> bool {
        self.smooth > 0.0 && self.relative().abs() <= self.bound()
    }
}

/// One extreme setting drawn in one scene and tier.
#[derive(Clone, Debug, PartialEq)]
pub struct ExtremeRow {
    pub scene: &'static str,
    /// Index into [`EXTREMES`].
    pub extreme: usize,
    pub tier: String,
    /// Pixels that are NaN, Inf, negative or above the f16 maximum.
    pub bad: usize,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Extremes {
    pub rows: Vec<ExtremeRow>,
    /// Energy of the grazing swatch at the lit extreme (reference): the
    /// check looks at something when it is > 0.
    pub grazing_energy: f64,
}

/// The half-pixel pan of one scene and tier at the defaults.
#[derive(Clone, Debug, PartialEq)]
pub struct PanRow {
    pub scene: SceneKind,
    pub tier: String,
    /// FLIP between the frame and the panned frame.
    pub flip: f64,
    /// Relative change of the object's mean radiance.
    pub mean_change: f64,
    /// FLIP of the frame against a fully redrawn pattern (sparkle tiers).
    pub redrawn: Option<f64>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Pan {
    pub rows: Vec<PanRow>,
    /// Steady flakes (twinkle 0, size 8) on the sphere, reference: the
    /// pan's FLIP and a redrawn pattern's.
    pub steady_pan: f64,
    pub steady_redrawn: f64,
}

impl Pan {
    pub fn steady_ratio(&self) -> f64 {
        self.steady_pan / self.steady_redrawn
    }
}

/// The distance check of one scene and tier.
#[derive(Clone, Debug, PartialEq)]
pub struct DistantRow {
    pub scene: SceneKind,
    pub tier: String,
    /// FLIP of the 1x render against the 4x4 supersampled one.
    pub flip: f64,
    /// The same for the reference at sparkle size 1 (the aliasing end).
    pub aliasing_end: f64,
}

impl DistantRow {
    pub fn within_bound(&self) -> bool {
        self.flip <= MAX_DISTANT_FLIP && self.flip <= MAX_DISTANT_RATIO * self.aliasing_end
    }
}

/// Every check, per tier, and each tier's frame time.
#[derive(Clone, Debug)]
pub struct GlintReport {
    pub adapter: String,
    pub inputs_hash: String,
    pub energy: Vec<EnergyRow>,
    pub extremes: Extremes,
    pub pan: Pan,
    pub distant: Vec<DistantRow>,
    /// (tier, median GPU ms per frame) on a 256² sphere at the defaults.
    pub cost: Vec<(String, f64)>,
    /// The timer of the cost figures (`gpu-timestamp` or `cpu-wall`).
    pub timer: String,
}
