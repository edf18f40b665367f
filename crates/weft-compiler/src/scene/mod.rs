//! Scene builds: compile exactly the shaders a scene manifest needs, each
//! specialised for its instance.
//!
//! `weft_front::scene` resolves the manifest against its materials (every
//! diagnostic about what a scene asks is raised there); [`build`] folds each
//! instance ([`fold`], values from [`instance`]), checks what only the
//! specialised shader can tell (vertex inputs, the shader budget) and
//! assembles `<scene>.scene.json`; [`tiers`] is the interface for `auto` tiers.

pub mod build;
pub mod fold;
pub mod instance;
pub mod tiers;

pub use build::{SceneBuildOptions, SceneOutput, build_resolved_scene};
pub use tiers::{AutoTierDecision, AutoTierRequest, TierChooser};
