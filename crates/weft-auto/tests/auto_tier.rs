//! `tier = "auto"`: the lavapipe tier chooser, called directly with
//! hand-made requests for the silk material (built from materials/ here),
//! and once through a real scene build.
//!
//! These tests render on the local Vulkan adapter (lavapipe in CI). Without
//! one they fail with the message saying what to install; they never skip.

use serde_json::{Value, json};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use weft_auto::{LavapipeTierChooser, describe_choice};
use weft_compiler::library::CompiledMaterial;
use weft_compiler::scene::{AutoTierDecision, AutoTierRequest, TierChooser};
use weft_meta::gpu_model::ModelSummary;
use weft_meta::{MaterialMetadata, ParamKind};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn reports_dir() -> PathBuf {
    root().join("generated/reports")
}

/// The generic library build of a material, as the scene build hands it over.
fn build(name: &str) -> CompiledMaterial {
    let materials = root().join("materials");
    let path = materials.join(name).join(format!("{name}.toml"));
    let out = weft_compiler::build_materials(
        &[path],
        Some(&materials),
        &weft_compiler::BuildOptions::default(),
        &|_, _, _| {},
    )
    .unwrap_or_else(|_| panic!("material `{name}` compiles"));
    let meta = out.materials.into_iter().next().expect("one material");
    let prefix = format!("{name}/");
    let meta_file = format!("{name}.meta.json");
    let files = out
        .files
        .into_iter()
        .filter_map(|(path, bytes)| {
            let rel = path.strip_prefix(&prefix)?.to_string();
            (rel != meta_file).then_some((rel, bytes))
        })
        .collect();
    (meta, files)
}

fn silk() -> &'static CompiledMaterial {
    static SILK: OnceLock<CompiledMaterial> = OnceLock::new();
    SILK.get_or_init(|| build("silk"))
}

/// One chooser on the committed GPU model, shared so renders are cached across tests.
fn report_chooser() -> &'static LavapipeTierChooser {
    static CHOOSER: OnceLock<LavapipeTierChooser> = OnceLock::new();
    CHOOSER.get_or_init(|| {
        LavapipeTierChooser::new(None)
            .expect("no costs file to read")
            .with_reports_dir(reports_dir())
    })
}

/// Every parameter at its default, as a scene build uploads it: colours
/// linear, curves as baked samples, textures by built-in name, booleans as
/// 0/1, texture tilings under their uniform member.
fn default_values(meta: &MaterialMetadata) -> BTreeMap<String, Value> {
    let mut values = BTreeMap::new();
    for p in &meta.parameters {
        let v = match p.kind {
            ParamKind::Color => json!(p.color.as_ref().unwrap().linear_default),
            ParamKind::Curve => json!(p.curve.as_ref().unwrap().baked_default),
            ParamKind::Texture2d | ParamKind::Cube => {
                let t = p.texture.as_ref().unwrap();
                if let Some(member) = &t.tiling_member {
                    values.insert(
                        member.clone(),
                        json!(t.tiling_default.unwrap_or([1.0, 1.0, 0.0, 0.0])),
                    );
                }
                json!(t.default.name())
            }
            ParamKind::Bool => json!(u32::from(p.default.as_bool().unwrap())),
            // Gradients are not uniform values: a scene build does not send them.
            ParamKind::Gradient => continue,
            _ => p.default.clone(),
        };
        values.insert(p.name.clone(), v);
    }
    values
}

fn default_keywords(meta: &MaterialMetadata) -> BTreeMap<String, String> {
    meta.keywords
        .iter()
        .map(|k| (k.name.clone(), k.default.clone()))
        .collect()
}

fn request<'a>(
    material: &'a CompiledMaterial,
    mesh: &'a str,
    error_budget: f64,
    screen_size: u32,
) -> AutoTierRequest<'a> {
    AutoTierRequest {
        instance: "scarf",
        material,
        keywords: default_keywords(&material.0),
        values: default_values(&material.0),
        mesh,
        mesh_data: None,
        features: Default::default(),
        error_budget,
        screen_size,
        gpu_family: "navi21",
    }
}

fn choose(chooser: &LavapipeTierChooser, r: &AutoTierRequest) -> AutoTierDecision {
    chooser
        .choose(r)
        .unwrap_or_else(|e| panic!("choosing the tier of `{}`: {e}", r.instance))
}

/// Each tier's cost (not looks) by the committed GPU model on `family`, at
/// the material's default keywords (what `request` asks for), rounded as the
/// chooser rounds. Read here from the file, not through the chooser.
fn model_costs(material: &str, family: &str) -> BTreeMap<String, f64> {
    let model = ModelSummary::load(&reports_dir()).unwrap();
    let meta = &silk().0;
    assert_eq!(material, meta.name);
    model
        .family(family)
        .unwrap()
        .tiers
        .iter()
        .filter(|t| t.material == material && !meta.tiers.looks.contains(&t.tier))
        .map(|t| (t.tier.clone(), (t.executed_ratio * 1e3).round() / 1e3))
        .collect()
}

/// The tier a budget that admits every silk tier gets by the committed GPU
/// model: the cheapest, a tie going to the reference (the more accurate;
/// silk's other tiers differ from it at the defaults). Which of silk's close
/// tiers is cheapest is the model's to say, not this test's.
fn silk_cheapest_by_report() -> (String, BTreeMap<String, f64>) {
    let costs = model_costs("silk", "navi21");
    let tier = costs
        .iter()
        .min_by(|a, b| {
            a.1.total_cmp(b.1)
                .then((a.0 != "reference").cmp(&(b.0 != "reference")))
        })
        .map(|(t, _)| t.clone())
        .unwrap();
    (tier, costs)
}

/// A costs-file cost for silk's `low` tier above every other in these
/// tests, so the fast/reference cases below decide between those two.
const LOW_COST: f64 = 9.0;

/// Everything a decision must satisfy, checked against the record alone:
/// one candidate per tier, figures rounded, sorted cheapest first (ties: more
/// accurate first), `within_budget` right, and the choice the argmin of cost
/// (then error) over the candidates within budget.
fn check_decision(meta: &MaterialMetadata, r: &AutoTierRequest, d: &AutoTierDecision) {
    let rec = &d.record;
    assert_eq!(rec.error_budget, r.error_budget);
    assert_eq!(rec.screen_size, r.screen_size);
    let mut tiers: Vec<&str> = rec.candidates.iter().map(|c| c.tier.as_str()).collect();
    tiers.sort();
    let mut expected: Vec<&str> = meta
        .tiers
        .values
        .iter()
        .filter(|t| !meta.tiers.looks.contains(t))
        .map(String::as_str)
        .collect();
    expected.sort();
    assert_eq!(tiers, expected, "one candidate per tier that is not a look");
    for c in &rec.candidates {
        assert_eq!((c.flip_mean * 1e4).round() / 1e4, c.flip_mean, "{c:?}");
        assert_eq!((c.cost * 1e3).round() / 1e3, c.cost, "{c:?}");
        assert!(c.flip_mean >= 0.0 && c.flip_mean <= 1.0, "{c:?}");
        let reference = c.tier == meta.tiers.reference;
        if reference {
            assert_eq!(c.flip_mean, 0.0);
        }
        assert_eq!(
            c.within_budget,
            reference || c.flip_mean <= r.error_budget,
            "{c:?} at budget {}",
            r.error_budget
        );
    }
    for w in rec.candidates.windows(2) {
        assert!(
            w[0].cost < w[1].cost || (w[0].cost == w[1].cost && w[0].flip_mean <= w[1].flip_mean),
            "not cheapest first: {:?}",
            rec.candidates
        );
    }
    let best = rec
        .candidates
        .iter()
        .filter(|c| c.within_budget)
        .min_by(|a, b| {
            a.cost
                .total_cmp(&b.cost)
                .then(a.flip_mean.total_cmp(&b.flip_mean))
        })
        .expect("the reference is within budget");
    assert_eq!(d.tier, best.tier, "{rec:?}");
    // No candidate within budget is strictly cheaper, or as cheap and more accurate.
    for c in rec.candidates.iter().filter(|c| c.within_budget) {
        assert!(
            c.cost > best.cost || (c.cost == best.cost && c.flip_mean >= best.flip_mean),
            "{c:?} beats {best:?}"
        );
    }
}

#[test]
fn a_huge_budget_picks_the_cheapest_tier() {
    let silk = silk();
    let r = request(silk, "sphere", 1.0, 64);
    let d = choose(report_chooser(), &r);
    check_decision(&silk.0, &r, &d);
    let (cheapest, costs) = silk_cheapest_by_report();
    assert_eq!(d.tier, cheapest);
    assert_eq!(d.record.candidates[0].tier, cheapest);
    for c in &d.record.candidates {
        assert_eq!(c.cost, costs[&c.tier], "costs come from the GPU model");
        assert!(c.within_budget);
        let gpu = c.gpu.as_ref().expect("the model's figures are recorded");
        assert!(
            gpu.instructions > 0 && gpu.vgprs > 0 && gpu.waves > 0,
            "{c:?}"
        );
        assert!(gpu.executed_cost > 0.0, "{c:?}");
    }
    assert!(
        d.record.cost_source.starts_with(
            "GPU model generated/reports/gpu-model.json: navi21 (Null hardware (RADV NAVI21), Mesa "
        ),
        "{}",
        d.record.cost_source
    );
    assert_eq!(d.record.gpu_family.as_deref(), Some("navi21"));
    // The scene's family picks the figures.
    let mut rdna3 = clone(&r);
    rdna3.gpu_family = "gfx1100";
    let d3 = choose(report_chooser(), &rdna3);
    let costs3 = model_costs("silk", "gfx1100");
    for c in &d3.record.candidates {
        assert_eq!(c.cost, costs3[&c.tier], "{c:?}");
    }
    assert_eq!(d3.record.gpu_family.as_deref(), Some("gfx1100"));
    let mut unknown = clone(&r);
    unknown.gpu_family = "navi99";
    let e = report_chooser()
        .choose(&unknown)
        .err()
        .expect("no such family");
    assert!(
        e.contains("no family `navi99`") && e.contains("navi21"),
        "{e}"
    );
    // silk's `low` (half precision) differs from the reference a little;
    // its `fast` is the reference's code (materials/silk/README.md).
    let low = d
        .record
        .candidates
        .iter()
        .find(|c| c.tier == "low")
        .unwrap();
    assert!(
        low.flip_mean > 0.0 && low.flip_mean < 0.5,
        "the low tier differs from the reference, a little: {low:?}"
    );
    // Byte-stable: a fresh chooser renders again and records the same figures.
    let fresh = LavapipeTierChooser::new(None)
        .unwrap()
        .with_reports_dir(reports_dir());
    let again = choose(&fresh, &r);
    assert_eq!(again.tier, d.tier);
    assert_eq!(
        serde_json::to_string(&again.record).unwrap(),
        serde_json::to_string(&d.record).unwrap()
    );
    let line = describe_choice("scarf", &d.tier, &d.record);
    assert!(
        line.starts_with(&format!("scarf: auto tier -> {cheapest} (cost ")),
        "{line}"
    );
    assert!(
        line.contains(&format!("; candidates: {cheapest} ")),
        "{line}"
    );
}

#[test]
fn a_zero_budget_picks_the_reference() {
    let silk = silk();
    for mesh in ["sphere", "cloth"] {
        let r = request(silk, mesh, 0.0, 64);
        let d = choose(report_chooser(), &r);
        check_decision(&silk.0, &r, &d);
        assert_eq!(d.tier, silk.0.tiers.reference, "{mesh}: {:?}", d.record);
        let others: Vec<_> = d
            .record
            .candidates
            .iter()
            .filter(|c| c.tier != silk.0.tiers.reference)
            .collect();
        // A zero budget admits only a tier that draws the reference's image
        // (silk's `fast` is the reference's code; the tie goes to the
        // reference); `low` differs.
        assert!(
            others
                .iter()
                .all(|c| c.within_budget == (c.flip_mean == 0.0)),
            "{mesh}: {others:?}"
        );
        assert!(
            others.iter().any(|c| c.flip_mean > 0.0),
            "{mesh}: {others:?}"
        );
    }
}

#[test]
fn the_choice_is_the_argmin_of_cost_within_budget() {
    let silk = silk();
    let meta = &silk.0;
    let mut configs = Vec::new();
    configs.push(request(silk, "sphere", 0.0, 64));
    let mut ggx = request(silk, "cloth", 0.0, 96);
    ggx.keywords.insert("ANISO_MODEL".into(), "ggx".into());
    configs.push(ggx);
    let mut hair = request(silk, "swatch", 0.0, 64);
    hair.keywords
        .insert("ANISO_MODEL".into(), "hair_shifted".into());
    hair.values.insert("smoothness".into(), json!(0.55));
    hair.values
        .insert("base_color".into(), json!([0.2, 0.05, 0.08, 1.0]));
    configs.push(hair);
    let mut unlit_sky = request(silk, "sphere", 0.0, 64);
    unlit_sky.features.environment = false;
    configs.push(unlit_sky);

    // Costs from the report, and from files that reverse or tie them.
    let dir = tempfile::tempdir().unwrap();
    let mut choosers = vec![("report".to_string(), None)];
    for (i, (fast, reference)) in [(3.0, 1.0), (1.0, 1.0), (0.25, 4.0)]
        .into_iter()
        .enumerate()
    {
        let path = dir.path().join(format!("costs{i}.json"));
        std::fs::write(
            &path,
            json!({ "silk": { "fast": fast, "reference": reference, "low": LOW_COST } })
                .to_string(),
        )
        .unwrap();
        choosers.push((
            format!("fast {fast} / reference {reference}"),
            Some(LavapipeTierChooser::new(Some(&path)).unwrap()),
        ));
    }
    let mut decisions = 0;
    for base in &configs {
        // The candidates' errors at this configuration, then budgets around each.
        let probe = choose(
            report_chooser(),
            &AutoTierRequest {
                error_budget: 1.0,
                ..clone(base)
            },
        );
        let mut budgets = vec![0.0, 1e-4, 0.001, 0.01, 0.02, 0.05, 0.1, 0.3, 1.0];
        for c in &probe.record.candidates {
            budgets.extend([c.flip_mean, c.flip_mean - 1e-4, c.flip_mean + 1e-4]);
        }
        for budget in budgets.into_iter().filter(|b| *b >= 0.0) {
            let r = AutoTierRequest {
                error_budget: budget,
                ..clone(base)
            };
            for (what, chooser) in &choosers {
                let chooser = chooser.as_ref().unwrap_or(report_chooser());
                let d = choose(chooser, &r);
                check_decision(meta, &r, &d);
                // Same instance, same figures, whichever costs.
                for c in &d.record.candidates {
                    let p = probe
                        .record
                        .candidates
                        .iter()
                        .find(|p| p.tier == c.tier)
                        .unwrap();
                    assert_eq!(c.flip_mean, p.flip_mean, "{what}: {c:?}");
                }
                decisions += 1;
            }
        }
    }
    assert!(decisions > 100, "{decisions}");
}

/// Requests borrow; `..` needs an owned base.
fn clone<'a>(r: &AutoTierRequest<'a>) -> AutoTierRequest<'a> {
    AutoTierRequest {
        instance: r.instance,
        material: r.material,
        keywords: r.keywords.clone(),
        values: r.values.clone(),
        mesh: r.mesh,
        mesh_data: r.mesh_data,
        features: r.features,
        error_budget: r.error_budget,
        screen_size: r.screen_size,
        gpu_family: r.gpu_family,
    }
}

#[test]
fn a_tier_costs_file_overrides_the_report_and_can_flip_the_choice() {
    let silk = silk();
    let dir = tempfile::tempdir().unwrap();
    let r = request(silk, "sphere", 1.0, 64);
    // Without a costs file, the report decides.
    assert_eq!(
        choose(report_chooser(), &r).tier,
        silk_cheapest_by_report().0
    );
    let cases = [
        // Reference cheaper: chosen even though fast is within budget.
        ((2.0, 1.0), "reference"),
        // A tie in cost goes to the more accurate tier.
        ((1.5, 1.5), "reference"),
        ((0.5, 1.0), "fast"),
        // Costs are rounded to 3 decimals before comparing: this is a tie.
        ((1.0004, 1.0), "reference"),
    ];
    for ((fast, reference), expected) in cases {
        let path = dir.path().join("costs.json");
        std::fs::write(
            &path,
            serde_json::to_string_pretty(&json!({
                "standard": { "fast": 1.0 },
                "silk": { "fast": fast, "reference": reference, "low": LOW_COST }
            }))
            .unwrap(),
        )
        .unwrap();
        let chooser = LavapipeTierChooser::new(Some(&path)).unwrap();
        let d = choose(&chooser, &r);
        check_decision(&silk.0, &r, &d);
        assert_eq!(
            d.tier, expected,
            "fast {fast}, reference {reference}: {:?}",
            d.record
        );
        assert_eq!(
            d.record.cost_source,
            format!("--tier-costs {}", path.display())
        );
        let cost = |t: &str| {
            d.record
                .candidates
                .iter()
                .find(|c| c.tier == t)
                .unwrap()
                .cost
        };
        assert_eq!(cost("fast"), (fast * 1e3f64).round() / 1e3);
        assert_eq!(cost("reference"), reference);
    }
}

#[test]
fn missing_costs_are_clear_errors() {
    let silk = silk();
    let r = request(silk, "sphere", 0.05, 64);
    let dir = tempfile::tempdir().unwrap();

    // No GPU model.
    let empty = dir.path().join("reports");
    std::fs::create_dir_all(&empty).unwrap();
    let e = LavapipeTierChooser::new(None)
        .unwrap()
        .with_reports_dir(empty.clone())
        .choose(&r)
        .err()
        .expect("no model, no choice");
    assert!(
        e.contains(&empty.join("gpu-model.json").display().to_string()),
        "{e}"
    );
    assert!(e.contains("cargo xtask bench gpu-model --write"), "{e}");

    // A model without the variant one tier's candidate is.
    let mut model = ModelSummary::load(&reports_dir()).unwrap();
    for f in &mut model.families {
        f.variants
            .retain(|v| !(v.material == "silk" && v.tier == "fast"));
    }
    std::fs::write(empty.join("gpu-model.json"), model.to_json()).unwrap();
    let e = LavapipeTierChooser::new(None)
        .unwrap()
        .with_reports_dir(empty.clone())
        .choose(&r)
        .err()
        .expect("variant missing from the model");
    assert!(e.contains("no figures for variant `fast."), "{e}");
    assert!(
        e.contains("(tier `fast`) of material `silk` on `navi21`"),
        "{e}"
    );
    assert!(e.contains("cargo xtask bench gpu-model --write"), "{e}");
    assert!(e.contains("--tier-costs"), "{e}");

    // A costs file without the material, or without one of its tiers.
    let costs = dir.path().join("costs.json");
    std::fs::write(&costs, r#"{ "standard": { "fast": 1, "reference": 2 } }"#).unwrap();
    let e = LavapipeTierChooser::new(Some(&costs))
        .unwrap()
        .choose(&r)
        .err()
        .expect("material missing from the costs file");
    assert!(e.contains(&costs.display().to_string()), "{e}");
    assert!(e.contains("no entry for material `silk`"), "{e}");
    assert!(e.contains("cargo xtask bench gpu-model"), "{e}");
    std::fs::write(&costs, r#"{ "silk": { "fast": 1 } }"#).unwrap();
    let e = LavapipeTierChooser::new(Some(&costs))
        .unwrap()
        .choose(&r)
        .err()
        .expect("tier missing from the costs file");
    assert!(e.contains(&costs.display().to_string()), "{e}");
    assert!(e.contains("no cost for tier `reference`"), "{e}");
    assert!(e.contains("add `\"reference\": <cost>`"), "{e}");

    // A costs file that cannot be used at all fails when the chooser is made.
    std::fs::write(&costs, r#"{ "silk": { "fast": "cheap" } }"#).unwrap();
    let e = LavapipeTierChooser::new(Some(&costs))
        .err()
        .expect("not numbers");
    assert!(e.contains(&costs.display().to_string()), "{e}");
    let e = LavapipeTierChooser::new(Some(&dir.path().join("absent.json")))
        .err()
        .expect("no file");
    assert!(e.contains("absent.json"), "{e}");
    std::fs::write(&costs, r#"{ "silk": { "fast": 0, "reference": 1 } }"#).unwrap();
    let e = LavapipeTierChooser::new(Some(&costs))
        .unwrap()
        .choose(&r)
        .err()
        .expect("zero cost");
    assert!(e.contains("not a positive number"), "{e}");
}

#[test]
fn scene_features_reach_the_renderer() {
    let silk = silk();
    let lit = choose(report_chooser(), &request(silk, "sphere", 1.0, 64));
    let mut r = request(silk, "sphere", 1.0, 64);
    r.features.environment = false;
    r.features.sh_ambient = false;
    r.features.directional_lights = 0;
    let dark = choose(report_chooser(), &r);
    check_decision(&silk.0, &r, &dark);
    let flip = |d: &AutoTierDecision| {
        d.record
            .candidates
            .iter()
            .find(|c| c.tier == "low")
            .unwrap()
            .flip_mean
    };
    // With no light at all both tiers draw black: no error.
    assert_eq!(flip(&dark), 0.0, "{:?}", dark.record);
    assert!(flip(&lit) > 0.0, "{:?}", lit.record);
}

#[test]
fn a_scene_build_decides_auto_tiers() {
    let dir = tempfile::tempdir().unwrap();
    let materials = root().join("materials").canonicalize().unwrap();
    let scene = dir.path().join("auto_probe.scene.toml");
    let instance = |name: &str, budget: f64| {
        format!(
            r#"
[[instances]]
name = "{name}"
material = "silk"
tier = "auto"
error_budget = {budget}
screen_size = 64
mesh = "cloth"
params = {{ smoothness = 0.6, base_color = [0.5, 0.2, 0.3] }}
"#
        )
    };
    std::fs::write(
        &scene,
        format!(
            r#"[scene]
name = "auto_probe"
materials = "{}"
environment = true
sh_ambient = true
directional_lights = 1
vertex_inputs = ["position", "normal", "tangent", "uv0"]

[camera]
position = [0.0, 0.0, 3.0]
target = [0.0, 0.0, 0.0]
fov_degrees = 40.0
{}{}"#,
            materials.display().to_string().replace('\\', "/"),
            instance("loose", 1.0),
            instance("strict", 0.0001),
        ),
    )
    .unwrap();
    let chooser = LavapipeTierChooser::new(None)
        .unwrap()
        .with_reports_dir(reports_dir());
    let options = weft_compiler::SceneBuildOptions {
        tier_chooser: Some(&chooser),
        ..Default::default()
    };
    let out = match weft_compiler::build_scene(&scene, &options) {
        Ok(out) => out,
        Err((db, diags)) => panic!("{}", diags.render_plain(&db)),
    };
    let by_name = |n: &str| out.metadata.instances.iter().find(|i| i.name == n).unwrap();
    let loose = by_name("loose");
    let strict = by_name("strict");
    let (cheapest, costs) = silk_cheapest_by_report();
    assert_eq!(loose.tier, cheapest);
    assert_eq!(strict.tier, "reference");
    let choice = loose.tier_choice.as_ref().expect("recorded");
    assert_eq!(choice.error_budget, 1.0);
    assert_eq!(choice.screen_size, 64);
    // One candidate per tier that is not a look.
    let silk_meta = &silk().0;
    assert_eq!(
        choice.candidates.len(),
        silk_meta.tiers.values.len() - silk_meta.tiers.looks.len()
    );
    // Both instances have the same values: the same figures.
    assert_eq!(
        choice.candidates,
        strict
            .tier_choice
            .as_ref()
            .unwrap()
            .candidates
            .iter()
            .map(|c| weft_meta::scene::TierCandidate {
                within_budget: true,
                ..c.clone()
            })
            .collect::<Vec<_>>()
    );
    let line = describe_choice(&loose.name, &loose.tier, choice);
    let of_reference = costs[&cheapest] / costs["reference"];
    assert!(
        line.starts_with(&format!(
            "loose: auto tier -> {cheapest} (cost {of_reference:.2} of reference, FLIP "
        )),
        "{line}"
    );
}
