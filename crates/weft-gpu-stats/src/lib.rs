//! Static GPU statistics of weft's pipelines from AMD's production shader
//! compiler: each pipeline is built exactly as the metadata describes it on
//! Mesa RADV's *null device* (no GPU needed; `RADV_FORCE_FAMILY` picks the
//! chip), and `VK_KHR_pipeline_executable_properties` returns ACO's figures
//! per stage: instructions, VGPRs, SGPRs, spills, code size, waves per SIMD,
//! inverse throughput, … (docs/performance.md says what each means).
//!
//! [`collect`] runs one child process per family (see [`worker`]).

mod compile;
mod device;
pub mod error;
pub mod family;
pub mod funnel;
pub mod icd;
pub mod isa;
pub mod jobs;
pub mod loop_report;
pub mod model;
pub mod pairing;
pub mod record;
pub mod report;
mod state;
pub mod summary;
pub mod trips;
pub mod worker;

pub use error::{Error, RADV_PACKAGE, Result};
pub use jobs::Selection;
pub use record::{FamilyStats, PipelineSource, PipelineStats, StageStats, StatValue, Statistic};
pub use summary::{
    FamilySummary, FragmentCost, ModelSummary, SceneShaderCost, TierCost, VariantCost, summarize,
};
pub use worker::WorkerCommand;

use std::path::PathBuf;

/// RDNA2 (Radeon RX 6800/6900) and RDNA3 (RX 7900: Mesa 22.3 calls it `gfx1100`, later
/// releases `navi31`; weft keeps the first name, [`family`]).
pub const DEFAULT_FAMILIES: [&str; 2] = ["navi21", "gfx1100"];

/// What to compile, for which families, with which driver.
#[derive(Clone, Debug)]
pub struct Options {
    /// The generated library (`generated/`).
    pub generated: PathBuf,
    /// Which pipelines.
    pub selection: Selection,
    /// Families (`RADV_FORCE_FAMILY` names; `navi31` is reported as `gfx1100`), in output order.
    pub families: Vec<String>,
    /// Capture each executable's ISA disassembly.
    pub disassembly: bool,
    /// Where to look for RADV's manifest; `None`: the loader's standard folders.
    pub icd_dirs: Option<Vec<PathBuf>>,
    /// The child process that compiles one family.
    pub worker: WorkerCommand,
}

/// Whether RADV's manifest is in the loader's standard folders: `Ok`, or the
/// error `collect` would fail with (it names the package to install).
pub fn radv_available() -> Result<()> {
    icd::find_radv_icd(&icd::standard_icd_dirs()).map(|_| ())
}

/// Compiles the selected pipelines for each family, one child process per
/// family, and returns the figures in family order. Fails naming the package
/// `mesa-vulkan-drivers` when RADV is not installed.
pub fn collect(options: &Options) -> Result<Vec<FamilyStats>> {
    let dirs = options
        .icd_dirs
        .clone()
        .unwrap_or_else(icd::standard_icd_dirs);
    let manifest = icd::find_radv_icd(&dirs)?;
    options
        .families
        .iter()
        .map(|family| {
            let request = worker::Request {
                family: family::weft_name(family).to_string(),
                generated: options.generated.clone(),
                selection: options.selection.clone(),
                disassembly: options.disassembly,
            };
            worker::run_child(&options.worker, &manifest, &request)
        })
        .collect()
}
