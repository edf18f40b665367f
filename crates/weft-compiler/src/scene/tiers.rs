//! Automatic tier choice (`tier = "auto"`): the compiler states the question,
//! a [`TierChooser`] answers it. Measuring needs a GPU runtime, which the
//! compiler must not depend on: `weft-golden` implements the chooser that
//! renders on lavapipe, and the CLI wires it in.

use crate::compile::material::CompiledMaterial;
use std::collections::BTreeMap;
use weft_front::scene::model::SceneFeatures;

/// Everything needed to measure an instance's tiers.
pub struct AutoTierRequest<'a> {
    pub instance: &'a str,
    /// The material's generic (library) build: metadata and files.
    pub material: &'a CompiledMaterial,
    /// Every keyword's value name.
    pub keywords: BTreeMap<String, String>,
    /// Every parameter's value as uploaded (colours linear, curves baked,
    /// textures by built-in name), by parameter or uniform-member name.
    pub values: BTreeMap<String, serde_json::Value>,
    pub mesh: &'a str,
    /// The mesh's vertex data when it is not built in (read from glTF): the
    /// tiers are measured on it.
    pub mesh_data: Option<&'a weft_meta::mesh::MeshData>,
    pub features: SceneFeatures,
    pub error_budget: f64,
    pub screen_size: u32,
    /// The GPU family whose modelled cost ranks the tiers (`[scene] gpu_family`).
    pub gpu_family: &'a str,
}

/// The chosen tier and the figures it was chosen from (recorded in the scene metadata).
pub struct AutoTierDecision {
    pub tier: String,
    pub record: weft_meta::scene::TierChoice,
}

pub trait TierChooser: Sync {
    fn choose(&self, request: &AutoTierRequest) -> Result<AutoTierDecision, String>;
}
