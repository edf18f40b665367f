//! Automatic tier choice for scene instances (`tier = "auto"`): the
//! [`TierChooser`] the CLI and `cargo xtask regenerate` hand to the scene
//! build.
//!
//! For one instance, every tier of its material that has a variant with the
//! instance's keywords is rendered with the instance's values, on its mesh
//! with the framing of the material goldens, at `screen_size` x
//! `screen_size`, under the scene's engine features (a feature that is off is
//! drawn black/zero, as `weft_render::SceneLighting` does). Each tier's error
//! is the FLIP mean over object pixels against the reference tier
//! ([`crate::image_error::image_error`], as the bench measures it). Costs come
//! from the committed GPU model (`generated/reports/gpu-model.json`: AMD's
//! compiler on Mesa RADV's null device, the executed cost of the candidate's
//! variant on the scene's `gpu_family`, ÷ `standard` `fast`), so a choice
//! depends on no machine's load, or from a user file (`--tier-costs`). The
//! model is looked up by variant id, so after a WGSL change it describes the
//! old code until it is rewritten: `cargo xtask regenerate` rewrites it and
//! builds the scenes again when the library's figures moved. The choice
//! is the cheapest tier within the error budget; ties in cost go to the more
//! accurate tier. FLIP is rounded to 4 decimals and costs to 3 before they
//! are compared and recorded, so the decision and the record are byte-stable.
//!
//! Rendering goes through the runtime's scene path with the generic library
//! variants ([`SceneShaders::Library`]): the compiled material is written into
//! a temporary `generated/`-style folder (`<m>/<m>.meta.json` plus its files,
//! and `luts/`), and a one-instance scene is drawn from it. The wgpu device is
//! created on the first request only, so a scene without `auto` instances never
//! touches the GPU.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex, PoisonError};
use weft_compiler::scene::{AutoTierDecision, AutoTierRequest, TierChooser};
use weft_meta::gpu_model::ModelSummary;
use weft_meta::scene::{
    SCENE_SCHEMA_VERSION, SceneCamera, SceneFeatures, SceneInstance, SceneMetadata, SceneTransform,
    TierCandidate, TierChoice, TierGpuFigures,
};
use weft_meta::{MaterialMetadata, Variant};
use weft_render::{
    Background, EnvironmentMaps, HdrImage, Luts, PreviewOptions, RenderOptions, Renderer, Scene,
    SceneFile, SceneKind, SceneShaders,
};

/// Where the bench reports are looked up unless [`LavapipeTierChooser::with_reports_dir`] says otherwise.
pub const DEFAULT_REPORTS_DIR: &str = "generated/reports";
/// Decimals FLIP means are rounded to before comparing and recording.
pub const FLIP_DECIMALS: i32 = 4;
/// Decimals costs are rounded to before comparing and recording.
pub const COST_DECIMALS: i32 = 3;
/// Largest `screen_size` rendered (the scene format allows up to 4096).
const MAX_SCREEN_SIZE: u32 = 8192;

/// Where costs come from.
enum Costs {
    /// The GPU model, `<reports_dir>/gpu-model.json`: the executed cost of
    /// the variant each tier's candidate is, for the scene's GPU family.
    GpuModel,
    /// A `--tier-costs` file: material -> tier -> cost.
    File {
        path: PathBuf,
        costs: BTreeMap<String, BTreeMap<String, f64>>,
    },
}

/// The GPU side, created on the first request that needs a render.
struct GpuState {
    renderer: Renderer,
    /// Holds `luts/` and, per material build, `<material>-<hash>/<material>/…`.
    dir: tempfile::TempDir,
    /// Material folders already written into `dir`.
    written: HashSet<String>,
    /// Renders by (material, inputs hash, tier, keywords, values, mesh, size, features).
    images: HashMap<String, Arc<HdrImage>>,
}

/// Chooses `auto` tiers by rendering every tier on the local Vulkan adapter
/// (lavapipe in CI) and comparing it with the reference tier.
pub struct LavapipeTierChooser {
    costs: Costs,
    reports_dir: PathBuf,
    /// `gpu-model.json`, read on the first request that needs it.
    model: std::sync::OnceLock<Result<ModelSummary, String>>,
    gpu: Mutex<Option<GpuState>>,
}

/// Each candidate's cost (and GPU figures), the source, the family.
struct Costed {
    costs: Vec<(f64, Option<TierGpuFigures>)>,
    source: String,
    family: Option<String>,
}

impl LavapipeTierChooser {
    /// `tier_costs`: optional JSON file of user-measured costs `{ "<material>": { "<tier>": <cost>, ... }, ... }` (any unit, only ratios within a material matter).
    /// Without it, costs come from the committed GPU model `generated/reports/gpu-model.json` (AMD's shader compiler on Mesa RADV's null device, written by `cargo xtask bench gpu-model --write`): the executed cost of each candidate variant on the scene's `gpu_family`, as a ratio to `standard` `fast`; looked up in `reports_dir` (default: "generated/reports" relative to the current directory).
    pub fn new(tier_costs: Option<&Path>) -> Result<Self, String> {
        let costs = match tier_costs {
            None => Costs::GpuModel,
            Some(path) => Costs::File {
                path: path.to_path_buf(),
                costs: read_costs_file(path)?,
            },
        };
        Ok(LavapipeTierChooser {
            costs,
            reports_dir: PathBuf::from(DEFAULT_REPORTS_DIR),
            model: std::sync::OnceLock::new(),
            gpu: Mutex::new(None),
        })
    }

    /// Looks the bench reports up in `dir` instead of `generated/reports`.
    pub fn with_reports_dir(mut self, dir: PathBuf) -> Self {
        self.reports_dir = dir;
        self
    }

    /// The cost of every candidate variant (rounded), with the GPU model's
    /// figures when they are the source, where they came from and the family.
    fn costs(
        &self,
        meta: &MaterialMetadata,
        variants: &[&Variant],
        family: &str,
    ) -> Result<Costed, String> {
        let name = &meta.name;
        match &self.costs {
            Costs::File { path, costs } => {
                let shown = path.display();
                let per_tier = costs.get(name).ok_or_else(|| {
                    format!(
                        "the tier costs file {shown} has no entry for material `{name}`: add \
                         `\"{name}\": {{ {} }}` with costs measured on your target (only ratios \
                         within a material matter), or leave out --tier-costs to use the GPU \
                         model written by `cargo xtask bench gpu-model --write`",
                        variants
                            .iter()
                            .map(|v| format!("\"{}\": <cost>", v.tier))
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                })?;
                let mut out = Vec::new();
                for v in variants {
                    let tier = &v.tier;
                    let cost = *per_tier.get(tier).ok_or_else(|| {
                        format!(
                            "the tier costs file {shown} has no cost for tier `{tier}` of material \
                             `{name}` (it lists: {}): add `\"{tier}\": <cost>` to `\"{name}\"` in it",
                            join_or_none(per_tier.keys())
                        )
                    })?;
                    check_cost(cost, || format!("{shown}: `{name}`.`{tier}`"))?;
                    out.push((round(cost, COST_DECIMALS), None));
                }
                Ok(Costed {
                    costs: out,
                    source: format!("--tier-costs {shown}"),
                    family: None,
                })
            }
            Costs::GpuModel => {
                let shown = model_path_for_record(&self.reports_dir);
                let rerun = "run `cargo xtask bench gpu-model --write` to model it (needs \
                             `mesa-vulkan-drivers`, no GPU), or give measured costs with \
                             --tier-costs <file.json>";
                let model = self.model()?;
                let fam = model.family(family).ok_or_else(|| {
                    format!(
                        "the GPU model {shown} has no family `{family}` (it has: {}); {rerun}",
                        join_or_none(model.families.iter().map(|f| &f.family))
                    )
                })?;
                let mut out = Vec::new();
                for v in variants {
                    // An alias draws its target's shader.
                    let id = meta.resolve_variant(&v.id).map_or(&v.id, |c| &c.id);
                    let c = fam.variant(name, id).ok_or_else(|| {
                        format!(
                            "the GPU model {shown} has no figures for variant `{id}` (tier `{}`) of \
                             material `{name}` on `{family}`; {rerun}",
                            v.tier
                        )
                    })?;
                    check_cost(c.executed_ratio, || {
                        format!("{shown}: `{name}` variant `{id}` on `{family}`")
                    })?;
                    out.push((
                        round(c.executed_ratio, COST_DECIMALS),
                        Some(TierGpuFigures {
                            instructions: c.fragment.instructions,
                            vgprs: c.fragment.vgprs,
                            waves: c.fragment.waves,
                            executed_cost: c.fragment.executed_cost,
                        }),
                    ));
                }
                // A model written from an earlier version of the material is
                // still used (its variant ids must match): cost ratios move
                // little with an edit, and `bench gpu-model` is run apart from
                // builds.
                Ok(Costed {
                    costs: out,
                    source: format!(
                        "GPU model {shown}: {family} ({}, {}), executed cost ÷ standard fast",
                        fam.device_name, fam.driver_info
                    ),
                    family: Some(family.to_string()),
                })
            }
        }
    }

    /// The GPU model, read once.
    fn model(&self) -> Result<&ModelSummary, String> {
        self.model
            .get_or_init(|| ModelSummary::load(&self.reports_dir))
            .as_ref()
            .map_err(Clone::clone)
    }

    /// The image of `tier` for the request, rendered or from the cache.
    fn image(
        &self,
        state: &mut GpuState,
        request: &AutoTierRequest,
        variant: &Variant,
        kind: TierMesh,
    ) -> Result<Arc<HdrImage>, String> {
        let meta = &request.material.0;
        let f = &request.features;
        let key = format!(
            "{}|{}|{}|{}|{}|{}|{}|{}/{}/{}",
            meta.name,
            meta.inputs_hash,
            variant.tier,
            serde_json::to_string(&request.keywords).map_err(|e| e.to_string())?,
            serde_json::to_string(&request.values).map_err(|e| e.to_string())?,
            request.mesh,
            request.screen_size,
            f.environment,
            f.sh_ambient,
            f.directional_lights
        );
        if let Some(image) = state.images.get(&key) {
            return Ok(image.clone());
        }
        let generated = write_material(state, request.material)?;
        if let TierMesh::File(data) = kind {
            // The mesh beside the temporary scene file, as a scene build writes it.
            let path = state
                .dir
                .path()
                .join(weft_meta::mesh::mesh_path(request.mesh));
            std::fs::create_dir_all(path.parent().expect("meshes/"))
                .and_then(|()| std::fs::write(&path, data.to_bytes()))
                .map_err(|e| format!("cannot write {}: {e}", path.display()))?;
        }
        let scene = instance_scene(request, variant, kind)?;
        let file = SceneFile::from_metadata(scene, state.dir.path().join("auto_tier.scene.json"))
            .map_err(|e| e.to_string())?;
        let options = RenderOptions {
            width: request.screen_size,
            height: request.screen_size,
            // Object pixels are those not left at the clear colour (as the bench).
            background: Background::Color([0.0; 4]),
            ..PreviewOptions::default().render_options()
        };
        let what = |e: weft_render::Error| {
            // The scene file is a temporary: name the material and tier instead.
            let e = match e {
                weft_render::Error::Scene { source, .. } => *source,
                e => e,
            };
            format!(
                "rendering tier `{}` of `{}` ({} at {}x{}): {e}",
                variant.tier, meta.name, request.mesh, request.screen_size, request.screen_size
            )
        };
        let prepared = state
            .renderer
            .prepare_scene(&file, &SceneShaders::Library(generated), &options)
            .map_err(what)?;
        let image = Arc::new(
            state
                .renderer
                .render_scene(&prepared, &options)
                .map_err(what)?,
        );
        state.images.insert(key, image.clone());
        Ok(image)
    }
}

impl TierChooser for LavapipeTierChooser {
    fn choose(&self, request: &AutoTierRequest) -> Result<AutoTierDecision, String> {
        let meta = &request.material.0;
        let kind = match request.mesh_data {
            Some(data) => TierMesh::File(data),
            None => TierMesh::Builtin(SceneKind::from_name(request.mesh).ok_or_else(|| {
                format!(
                    "unknown mesh `{}` (valid: {})",
                    request.mesh,
                    SceneKind::ALL.map(SceneKind::name).join(", ")
                )
            })?),
        };
        if request.screen_size == 0 || request.screen_size > MAX_SCREEN_SIZE {
            return Err(format!(
                "screen_size {} is not a usable image size (1..={MAX_SCREEN_SIZE})",
                request.screen_size
            ));
        }
        if !request.error_budget.is_finite() {
            return Err(format!(
                "error budget {} is not a number",
                request.error_budget
            ));
        }
        // Tiers that have a variant with the instance's keywords (others are
        // excluded), looks excluded too: a different model is chosen by
        // name, never as an approximation within an error budget.
        let tiers: Vec<(usize, &Variant)> = meta
            .tiers
            .values
            .iter()
            .enumerate()
            .filter(|(_, t)| !meta.tiers.looks.contains(t))
            .filter_map(|(i, t)| variant_for(meta, t, &request.keywords).map(|v| (i, v)))
            .collect();
        let reference = &meta.tiers.reference;
        if !tiers.iter().any(|(_, v)| &v.tier == reference) {
            return Err(format!(
                "material `{}` builds no variant of its reference tier `{reference}` with the \
                 keywords {}: there is nothing to measure the other tiers against; choose a tier",
                meta.name,
                describe_keywords(&request.keywords)
            ));
        }
        // Costs first: a missing model fails before anything is rendered.
        let variants: Vec<&Variant> = tiers.iter().map(|(_, v)| *v).collect();
        let Costed {
            costs,
            source: cost_source,
            family: gpu_family,
        } = self.costs(meta, &variants, request.gpu_family)?;

        let mut guard = self.gpu.lock().unwrap_or_else(PoisonError::into_inner);
        if guard.is_none() {
            *guard = Some(GpuState::new(&self.reports_dir)?);
        }
        let state = guard.as_mut().expect("initialised above");
        let reference_variant = tiers
            .iter()
            .find(|(_, v)| &v.tier == reference)
            .map(|(_, v)| *v)
            .expect("checked above");
        let reference_image = self.image(state, request, reference_variant, kind)?;
        let mut ranked = Vec::new();
        for ((index, variant), (cost, gpu)) in tiers.iter().zip(costs) {
            let flip_mean = if &variant.tier == reference {
                0.0
            } else {
                let image = self.image(state, request, variant, kind)?;
                round(
                    crate::image_error::image_error(&reference_image, &image).flip_mean,
                    FLIP_DECIMALS,
                )
            };
            let within_budget = &variant.tier == reference || flip_mean <= request.error_budget;
            ranked.push((
                *index,
                TierCandidate {
                    tier: variant.tier.clone(),
                    cost,
                    gpu,
                    flip_mean,
                    within_budget,
                },
            ));
        }
        drop(guard);
        // Cheapest first; equal cost: the more accurate; then the reference
        // (a tier that computes what the reference does, as silk's `fast`,
        // ties it on both); then the material's tier order.
        ranked.sort_by(|(ia, a), (ib, b)| {
            a.cost
                .total_cmp(&b.cost)
                .then(a.flip_mean.total_cmp(&b.flip_mean))
                .then((&b.tier == reference).cmp(&(&a.tier == reference)))
                .then(ia.cmp(ib))
        });
        let candidates: Vec<TierCandidate> = ranked.into_iter().map(|(_, c)| c).collect();
        let tier = candidates
            .iter()
            .find(|c| c.within_budget)
            .map(|c| c.tier.clone())
            .expect("the reference tier is always within budget");
        Ok(AutoTierDecision {
            tier,
            record: TierChoice {
                error_budget: request.error_budget,
                screen_size: request.screen_size,
                cost_source,
                gpu_family,
                candidates,
            },
        })
    }
}

/// One line for the CLI: "scarf: auto tier -> fast (cost 0.92 of reference, FLIP 0.031 <= budget 0.05; candidates: fast 1.09/0.031, reference 1.18/0.000)".
pub fn describe_choice(instance: &str, tier: &str, choice: &TierChoice) -> String {
    let mut s = format!("{instance}: auto tier -> {tier} (");
    let chosen = choice.candidates.iter().find(|c| c.tier == tier);
    if let Some(c) = chosen {
        if let Some(r) = reference_candidate(choice)
            && r.cost > 0.0
        {
            let of = if r.tier == "reference" {
                "reference".to_string()
            } else {
                format!("reference `{}`", r.tier)
            };
            let _ = write!(s, "cost {:.2} of {of}, ", c.cost / r.cost);
        }
        let cmp = if c.flip_mean <= choice.error_budget {
            "<="
        } else {
            ">"
        };
        let _ = write!(
            s,
            "FLIP {:.3} {cmp} budget {}; ",
            c.flip_mean, choice.error_budget
        );
    }
    let _ = write!(
        s,
        "candidates: {})",
        choice
            .candidates
            .iter()
            .map(|c| format!("{} {:.2}/{:.3}", c.tier, c.cost, c.flip_mean))
            .collect::<Vec<_>>()
            .join(", ")
    );
    s
}

/// The reference tier of a record (not stored in it): the costliest
/// candidate without error, a tier named `reference` first among equals.
fn reference_candidate(choice: &TierChoice) -> Option<&TierCandidate> {
    choice
        .candidates
        .iter()
        .filter(|c| c.flip_mean == 0.0)
        .max_by(|a, b| {
            a.cost
                .total_cmp(&b.cost)
                .then((a.tier == "reference").cmp(&(b.tier == "reference")))
        })
}

impl GpuState {
    /// The device (failing with the lavapipe hint when there is none), the
    /// toolchain's LUTs and the golden sky.
    fn new(reports_dir: &Path) -> Result<GpuState, String> {
        let gpu = weft_render::Gpu::new().map_err(|e| format!("auto tier: {e}"))?;
        let dir = tempfile::Builder::new()
            .prefix("weft-auto-tier-")
            .tempdir()
            .map_err(|e| format!("cannot create a temporary folder: {e}"))?;
        // The LUT bytes a library build writes; an already-baked
        // `generated/luts/` next to the reports is reused (same name = same bake).
        let mut files = BTreeMap::new();
        let generated = reports_dir.parent().filter(|p| p.is_dir());
        weft_compiler::library::add_library_files(&mut files, generated);
        for (name, bytes) in files.iter().filter(|(n, _)| n.starts_with("luts/")) {
            write_file(&dir.path().join(name), bytes)?;
        }
        let luts = Luts::load_dir(dir.path()).map_err(|e| e.to_string())?;
        // The sky of the material goldens (`Harness`): its sun where the default light is.
        let env = EnvironmentMaps::sky(&PreviewOptions::default().sky_params());
        let renderer = Renderer::new(gpu, &env, &luts).map_err(|e| e.to_string())?;
        Ok(GpuState {
            renderer,
            dir,
            written: HashSet::new(),
            images: HashMap::new(),
        })
    }
}

/// Writes the material build into the temporary folder the way a library
/// build lays it out (`<m>/<m>.meta.json` and its files) once; returns the
/// `generated/`-style folder holding it.
fn write_material(
    state: &mut GpuState,
    (meta, files): &weft_compiler::library::CompiledMaterial,
) -> Result<PathBuf, String> {
    let hash: String = meta.inputs_hash.chars().take(16).collect();
    let tag = format!("{}-{hash}", meta.name);
    let generated = state.dir.path().join(&tag);
    if state.written.contains(&tag) {
        return Ok(generated);
    }
    let folder = generated.join(&meta.name);
    for (name, bytes) in files {
        write_file(&folder.join(name), bytes)?;
    }
    // A baked table's binding names its file by library path
    // (`<material>/<table>`), which the renderer reads under its LUT root:
    // the temporary folder. A table follows from the TOML alone, so every
    // build of the material writes the same bytes there.
    let table_extension = format!(".{}", weft_compiler::compile::tables::TABLE_EXTENSION);
    for (name, bytes) in files.iter().filter(|(n, _)| n.ends_with(&table_extension)) {
        write_file(&state.dir.path().join(&meta.name).join(name), bytes)?;
    }
    let mut json = serde_json::to_string_pretty(meta).map_err(|e| e.to_string())?;
    json.push('\n');
    write_file(
        &folder.join(format!("{}.meta.json", meta.name)),
        json.as_bytes(),
    )?;
    state.written.insert(tag);
    Ok(generated)
}

fn write_file(path: &Path, bytes: &[u8]) -> Result<(), String> {
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    }
    std::fs::write(path, bytes).map_err(|e| format!("{}: {e}", path.display()))
}

/// A one-instance scene: the instance as the library variant of `variant`
/// draws it, on `kind` at the origin, seen by the golden camera of that mesh.
/// The mesh tiers are measured on: built in, or the instance's own (glTF).
#[derive(Clone, Copy)]
enum TierMesh<'a> {
    Builtin(SceneKind),
    File(&'a weft_meta::mesh::MeshData),
}

/// The camera `weft preview --mesh` frames a mesh with (`Scene::framing`),
/// as scene metadata states it.
fn framing_camera(data: &weft_meta::mesh::MeshData) -> SceneCamera {
    let camera = Scene::framing(data.clone()).camera;
    SceneCamera {
        position: camera.eye.map(f64::from),
        target: camera.target.map(f64::from),
        fov_degrees: f64::from(camera.fov_y_degrees),
    }
}

fn instance_scene(
    request: &AutoTierRequest,
    variant: &Variant,
    kind: TierMesh,
) -> Result<SceneMetadata, String> {
    let meta = &request.material.0;
    // Parameters by name (colours linear, curves baked, textures by built-in
    // name); other names are uniform members, i.e. `<texture>_st` tilings.
    let mut constants = BTreeMap::new();
    let mut uniform_values = BTreeMap::new();
    for (name, value) in &request.values {
        if meta.parameters.iter().any(|p| &p.name == name) {
            constants.insert(name.clone(), value.clone());
        } else if meta.parameters.iter().any(|p| {
            p.texture.as_ref().and_then(|t| t.tiling_member.as_deref()) == Some(name.as_str())
        }) {
            uniform_values.insert(name.clone(), value.clone());
        } else {
            return Err(format!(
                "value `{name}` is neither a parameter nor a texture tiling of material `{}`",
                meta.name
            ));
        }
    }
    let identity: [f32; 16] = std::array::from_fn(|i| if i % 5 == 0 { 1.0 } else { 0.0 });
    let (camera, meshes, model) = match kind {
        TierMesh::Builtin(kind) => {
            let golden = Scene::new(kind);
            let model = std::array::from_fn(|i| golden.model[i / 4][i % 4]);
            let camera = golden.camera;
            let camera = SceneCamera {
                position: camera.eye.map(f64::from),
                target: camera.target.map(f64::from),
                fov_degrees: f64::from(camera.fov_y_degrees),
            };
            (camera, BTreeMap::new(), model)
        }
        TierMesh::File(data) => {
            let entry = weft_meta::scene::SceneMesh {
                path: None,
                file: Some(weft_meta::mesh::mesh_path(request.mesh)),
                radius: Some(data.radius()),
                format: weft_meta::mesh::MESH_FORMAT.into(),
            };
            (
                framing_camera(data),
                BTreeMap::from([(request.mesh.to_string(), entry)]),
                identity,
            )
        }
    };
    let mut passes = meta.passes.clone();
    passes.sort_by_key(|p| p.render_state.queue);
    let f = &request.features;
    Ok(SceneMetadata {
        schema_version: SCENE_SCHEMA_VERSION,
        schema_minor: weft_meta::scene::SCENE_SCHEMA_MINOR,
        engine_interface_version: weft_meta::ENGINE_INTERFACE_VERSION,
        name: "auto_tier".into(),
        description: None,
        inputs_hash: String::new(),
        features: SceneFeatures {
            environment: f.environment,
            sh_ambient: f.sh_ambient,
            directional_lights: f.directional_lights,
        },
        camera,
        light: None,
        static_lighting: None,
        shaders: Vec::new(),
        languages: meta.languages.clone(),
        conventions: meta.conventions.clone(),
        meshes,
        variants: BTreeMap::new(),
        funnel: None,
        limits: meta.limits.clone(),
        instances: vec![SceneInstance {
            name: request.instance.to_string(),
            material: meta.name.clone(),
            preset: None,
            tier: variant.tier.clone(),
            keywords: request.keywords.clone(),
            variant: variant.id.clone(),
            shader: String::new(),
            constants,
            dynamic: Vec::new(),
            uniform_values,
            textures: BTreeMap::new(),
            passes,
            mesh: request.mesh.into(),
            transform: SceneTransform {
                translation: [0.0; 3],
                rotation_degrees: [0.0; 3],
                scale: [1.0; 3],
                model,
            },
            tier_choice: None,
        }],
    })
}

/// The variant of `tier` whose static keywords have the instance's values.
fn variant_for<'a>(
    meta: &'a MaterialMetadata,
    tier: &str,
    keywords: &BTreeMap<String, String>,
) -> Option<&'a Variant> {
    meta.variants.iter().find(|v| {
        v.tier == tier
            && v.keywords
                .iter()
                .all(|(k, value)| keywords.get(k) == Some(value))
    })
}

fn describe_keywords(keywords: &BTreeMap<String, String>) -> String {
    if keywords.is_empty() {
        return "(none)".into();
    }
    keywords
        .iter()
        .map(|(k, v)| format!("{k} = {v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn join_or_none<'a>(names: impl Iterator<Item = &'a String>) -> String {
    let v: Vec<&str> = names.map(String::as_str).collect();
    if v.is_empty() {
        "nothing".into()
    } else {
        v.join(", ")
    }
}

fn check_cost(cost: f64, what: impl FnOnce() -> String) -> Result<(), String> {
    if cost.is_finite() && cost > 0.0 {
        Ok(())
    } else {
        Err(format!("{}: cost {cost} is not a positive number", what()))
    }
}

/// The model's path as recorded: `generated/reports/gpu-model.json`
/// when the folder is a project's `generated/reports` (wherever the project
/// is), else relative to the current directory when under it.
fn model_path_for_record(reports_dir: &Path) -> String {
    let file = weft_meta::gpu_model::FILE_NAME;
    if reports_dir.ends_with(DEFAULT_REPORTS_DIR) {
        return format!("{DEFAULT_REPORTS_DIR}/{file}");
    }
    let path = reports_dir.join(file);
    let relative = std::env::current_dir()
        .ok()
        .and_then(|cwd| path.strip_prefix(cwd).ok().map(Path::to_path_buf));
    relative.unwrap_or(path).display().to_string()
}

/// `{ "<material>": { "<tier>": <cost>, ... }, ... }`.
fn read_costs_file(path: &Path) -> Result<BTreeMap<String, BTreeMap<String, f64>>, String> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read the tier costs file {}: {e}", path.display()))?;
    serde_json::from_str(&text).map_err(|e| {
        format!(
            "the tier costs file {} is not `{{ \"<material>\": {{ \"<tier>\": <cost>, ... }}, ... }}`: {e}",
            path.display()
        )
    })
}

fn round(x: f64, decimals: i32) -> f64 {
    let s = 10f64.powi(decimals);
    (x * s).round() / s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn candidate(tier: &str, cost: f64, flip_mean: f64) -> TierCandidate {
        TierCandidate {
            tier: tier.into(),
            cost,
            gpu: None,
            flip_mean,
            within_budget: flip_mean <= 0.05,
        }
    }

    #[test]
    fn describe_choice_matches_the_cli_line() {
        let choice = TierChoice {
            error_budget: 0.05,
            screen_size: 128,
            cost_source: "--tier-costs costs.json".into(),
            gpu_family: None,
            candidates: vec![
                candidate("fast", 1.086, 0.0312),
                candidate("reference", 1.178, 0.0),
            ],
        };
        assert_eq!(
            describe_choice("scarf", "fast", &choice),
            "scarf: auto tier -> fast (cost 0.92 of reference, FLIP 0.031 <= budget 0.05; candidates: fast 1.09/0.031, reference 1.18/0.000)"
        );
        assert_eq!(
            describe_choice("scarf", "reference", &choice),
            "scarf: auto tier -> reference (cost 1.00 of reference, FLIP 0.000 <= budget 0.05; candidates: fast 1.09/0.031, reference 1.18/0.000)"
        );
    }

    #[test]
    fn rounding_is_to_the_stated_decimals() {
        assert_eq!(round(0.031_249_9, FLIP_DECIMALS), 0.0312);
        assert_eq!(round(1.0855, COST_DECIMALS), 1.086);
    }

    #[test]
    fn a_project_model_is_recorded_without_its_location() {
        assert_eq!(
            model_path_for_record(Path::new("/somewhere/else/generated/reports")),
            "generated/reports/gpu-model.json"
        );
        assert_eq!(
            model_path_for_record(Path::new("generated/reports")),
            "generated/reports/gpu-model.json"
        );
    }
}
