//! The figures: one [`PipelineStats`] per (family, pipeline), one
//! [`StageStats`] per executable the driver reports, each statistic as the
//! driver names it. Serialised in a stable order (the jobs' order, then the
//! driver's order of executables and statistics, which is fixed per Mesa version).

use serde::{Deserialize, Serialize};

/// Where a pipeline's shader comes from.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub struct PipelineSource {
    /// `material` (a library variant) or `scene` (a scene's specialised shader).
    pub kind: String,
    /// The material.
    pub material: String,
    /// The library variant id (for a scene shader: the variant it specialises).
    pub variant: String,
    /// The variant's tier.
    pub tier: String,
    /// `f32` (`files`) or `f16` (`f16_files`).
    pub precision: String,
    /// Scene shaders: the scene's name.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub scene: Option<String>,
    /// Scene shaders: the shader id (`<material>.<hash>`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shader: Option<String>,
    /// The SPIR-V file, relative to the generated folder.
    pub spirv: String,
}

/// One statistic's value in the type the driver gives it.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum StatValue {
    /// `VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR`.
    Bool(bool),
    /// `..._UINT64_KHR` (RADV's every statistic).
    Uint(u64),
    /// `..._INT64_KHR`.
    Int(i64),
    /// `..._FLOAT64_KHR`.
    Float(f64),
}

impl StatValue {
    /// The value as a number (booleans 0/1).
    pub fn as_f64(self) -> f64 {
        match self {
            StatValue::Bool(b) => f64::from(u8::from(b)),
            StatValue::Uint(u) => u as f64,
            StatValue::Int(i) => i as f64,
            StatValue::Float(f) => f,
        }
    }
}

/// One statistic as the driver names it (e.g. `VGPRs`, `Inverse Throughput`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Statistic {
    /// The driver's name.
    pub name: String,
    /// The value.
    pub value: StatValue,
}

/// One executable of a pipeline (RADV: one per hardware shader stage).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StageStats {
    /// `vertex` or `fragment` (`vertex+…` when the driver merges stages).
    pub stage: String,
    /// The driver's name for the executable (e.g. `Vertex Shader`).
    pub executable: String,
    /// Threads per wave the executable runs with (32 or 64 on RDNA).
    pub subgroup_size: u32,
    /// The statistics in the driver's order.
    pub statistics: Vec<Statistic>,
    /// The final ISA disassembly (RADV's `Assembly` representation), when asked for.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub disassembly: Option<String>,
}

impl StageStats {
    /// The statistic named `name`, as a number.
    pub fn get(&self, name: &str) -> Option<f64> {
        self.statistics
            .iter()
            .find(|s| s.name == name)
            .map(|s| s.value.as_f64())
    }
}

/// A pipeline's figures on one family.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PipelineStats {
    /// weft's name of the family (`navi21`, `gfx1100`, …: [`crate::family`]).
    pub family: String,
    /// The shader.
    pub source: PipelineSource,
    /// The pass (pipeline state and entry points).
    pub pass: String,
    /// One entry per executable, in the driver's order.
    pub stages: Vec<StageStats>,
}

impl PipelineStats {
    /// The executable that runs `stage` (`vertex` or `fragment`).
    pub fn stage(&self, stage: &str) -> Option<&StageStats> {
        self.stages
            .iter()
            .find(|s| s.stage.split('+').any(|p| p == stage))
    }
}

/// Every pipeline's figures on one family, with the driver that produced them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FamilyStats {
    /// weft's name of the family, whichever `RADV_FORCE_FAMILY` spelling this Mesa took.
    pub family: String,
    /// The Vulkan device name the driver reports.
    pub device_name: String,
    /// The driver's version string (e.g. `Mesa 22.3.6`).
    pub driver_info: String,
    /// The pipelines in job order.
    pub pipelines: Vec<PipelineStats>,
}
