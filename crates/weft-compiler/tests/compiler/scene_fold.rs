//! Folding scene constants into the shipped standard material: what must
//! disappear (uniform members, default textures, dead lobes) and what must stay.

use std::path::Path;
use weft_compiler::scene::fold::{FoldRequest, fold};
use weft_compiler::scene::instance::instance_values;
use weft_compiler::{backends, compose, prelude};
use weft_front::model::ParamValue;
use weft_front::scene::model::{
    BuiltinMesh, ResolvedInstance, SceneFeatures, TierChoice, Transform,
};
use weft_front::{Diagnostics, SourceDb};

fn load(name: &str) -> (weft_front::Material, naga::Module, prelude::Prelude) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../materials");
    let mut db = SourceDb::new();
    let mut diags = Diagnostics::new();
    let m = weft_front::load_material(
        &root.join(format!("{name}/{name}.toml")),
        &root,
        &mut db,
        &mut diags,
    )
    .unwrap_or_else(|| panic!("{}", diags.render_plain(&db)));
    let prelude = prelude::generate(&m);
    let composed = compose::compose(&m, &prelude, &mut db);
    let (module, _) = compose::parse_and_validate(&composed, &m, &mut diags).expect("valid");
    (m, module, prelude)
}

/// The f32 composition of a material with half-precision code (None without).
fn load_portable(name: &str) -> Option<naga::Module> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../materials");
    let mut db = SourceDb::new();
    let mut diags = Diagnostics::new();
    let toml = root.join(format!("{name}/{name}.toml"));
    let m = weft_front::load_material(&toml, &root, &mut db, &mut diags).expect("loads");
    let prelude = prelude::generate(&m);
    weft_compiler::half::fallback_module(&m, &prelude, &mut db, &mut diags)
        .expect("valid")
        .map(|(_, module)| module)
}

fn instance(m: &weft_front::Material, dynamic: &[&str]) -> ResolvedInstance {
    ResolvedInstance {
        images: Default::default(),
        overrides: Default::default(),
        name: "test".into(),
        material: 0,
        preset: None,
        tier: TierChoice::Fixed(m.tiers.default),
        keywords: m.keywords.iter().map(|k| k.default).collect(),
        values: m.params.iter().map(|p| p.default.clone()).collect(),
        set: vec![false; m.params.len()],
        dynamic: dynamic
            .iter()
            .map(|d| m.params.iter().position(|p| p.name == *d).expect("param"))
            .collect(),
        dynamic_spans: Vec::new(),
        mesh: weft_front::scene::model::InstanceMesh::Builtin(BuiltinMesh::Sphere),
        variant: None,
        vertex_inputs: Vec::new(),
        vertex_inputs_span: 0..0,
        transform: Transform::default(),
        span: 0..0,
        tier_span: 0..0,
    }
}

fn folded_wgsl(module: &naga::Module, request: &FoldRequest) -> (naga::Module, String) {
    let folded = fold(module, request).expect("folds").module;
    let info = compose::validator()
        .validate(&folded)
        .expect("folded module validates");
    let wgsl = backends::emit_wgsl(&folded, &info).expect("emits");
    (folded, wgsl)
}

#[test]
fn all_constant_standard_loses_its_uniform_and_default_textures() {
    let (m, module, _) = load("standard");
    let inst = instance(&m, &[]);
    let values = instance_values(&m, &inst, inst.keywords.len(), &SceneFeatures::default());
    let (folded, wgsl) = folded_wgsl(&module, &values.fold);
    let names: Vec<_> = folded
        .global_variables
        .iter()
        .filter_map(|(_, g)| g.name.clone())
        .collect();
    assert!(
        !names.contains(&"material".to_string()),
        "uniform still bound: {names:?}"
    );
    assert!(
        !names.contains(&"base_map".to_string()),
        "default base map still sampled"
    );
    assert!(
        !names.contains(&"rmo_map".to_string()),
        "default rmo map still sampled"
    );
    assert!(
        !wgsl.contains("override"),
        "scene shaders keep no overrides:\n{wgsl}"
    );
    // ao = saturate(mix(1, rmo.b, occlusion_strength)) with a white rmo map and
    // strength 1: `mix`, which naga's evaluator lacks, is folded too.
    assert!(!wgsl.contains("mix(1f, 1f, 1f)"), "{wgsl}");
    assert!(!wgsl.contains("let ao"), "{wgsl}");
    // The UV transform only fed the default textures: the call and the helper go.
    assert!(!wgsl.contains("weft_transform_uv"), "{wgsl}");
    // The environment is provided: its cube stays.
    assert!(names.contains(&"weft_environment".to_string()));
}

#[test]
fn dynamic_parameters_stay_in_a_shrunk_uniform() {
    let (m, module, _) = load("standard");
    let inst = instance(&m, &["roughness", "base_color"]);
    let values = instance_values(&m, &inst, m.tiers.default, &SceneFeatures::default());
    let (folded, _) = folded_wgsl(&module, &values.fold);
    let layout = weft_compiler::reflect::material_uniform(
        &folded,
        &weft_compiler::reflect::member_params(&m),
    )
    .expect("uniform kept");
    let members: Vec<_> = layout.members.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(members, ["base_color", "roughness"]);
    assert_eq!(layout.members[0].offset, 0);
    assert_eq!(layout.members[1].offset, 16);
    assert_eq!(layout.size, 32);
}

#[test]
fn absent_engine_features_remove_their_bindings() {
    let (m, module, _) = load("standard");
    let inst = instance(&m, &[]);
    let features = SceneFeatures {
        environment: false,
        sh_ambient: true,
        directional_lights: 1,
    };
    let values = instance_values(&m, &inst, m.tiers.default, &features);
    let (folded, _) = folded_wgsl(&module, &values.fold);
    let names: Vec<_> = folded
        .global_variables
        .iter()
        .filter_map(|(_, g)| g.name.clone())
        .collect();
    assert!(
        !names.contains(&"weft_environment".to_string()),
        "{names:?}"
    );
}

#[test]
fn a_non_default_texture_value_folds_to_its_texel() {
    let (m, _, _) = load("standard");
    let mut inst = instance(&m, &[]);
    let i = m
        .params
        .iter()
        .position(|p| p.name == "base_map")
        .expect("base_map");
    inst.values[i] = ParamValue::Texture(weft_meta::TextureDefault::Gray);
    inst.set[i] = true;
    let values = instance_values(&m, &inst, m.tiers.default, &SceneFeatures::default());
    let texel = values.fold.textures["base_map"];
    // sRGB-decoded 128/255.
    assert!((texel[0] - 0.2158605).abs() < 1e-5, "{texel:?}");
    assert_eq!(texel[3], 1.0);
}

#[test]
fn an_unset_texture_folds_to_its_keyword_dependent_default() {
    let (m, _, _) = load("standard");
    let mut inst = instance(&m, &[]);
    let k = m
        .keywords
        .iter()
        .position(|k| k.name == "SPHERE_MAP")
        .expect("SPHERE_MAP");
    let value = |name: &str| m.keywords[k].values.iter().position(|v| v == name).unwrap();
    let sphere = |inst: &ResolvedInstance| {
        instance_values(&m, inst, m.tiers.default, &SceneFeatures::default())
            .fold
            .textures["sphere_map"]
    };
    inst.keywords[k] = value("add");
    assert_eq!(sphere(&inst), [0.0, 0.0, 0.0, 1.0], "black under ADD");
    inst.keywords[k] = value("multiply");
    assert_eq!(sphere(&inst), [1.0, 1.0, 1.0, 1.0], "white under MULTIPLY");
    // A value the instance wrote is kept whatever the keywords.
    let i = m
        .params
        .iter()
        .position(|p| p.name == "sphere_map")
        .unwrap();
    inst.set[i] = true;
    assert_eq!(sphere(&inst), [0.0, 0.0, 0.0, 1.0], "written black kept");
}

#[test]
fn a_zero_specular_strength_removes_the_specular_code() {
    let (m, module, _) = load("standard");
    let mut inst = instance(&m, &[]);
    let i = m
        .params
        .iter()
        .position(|p| p.name == "specular_strength")
        .expect("param");
    let lit = instance_values(&m, &inst, m.tiers.default, &SceneFeatures::default());
    let (_, lit_wgsl) = folded_wgsl(&module, &lit.fold);
    assert!(
        // (as the helper or a clone of it bound to the scene's constants;
        // fast takes D from n.h: weft_d_ggx)
        lit_wgsl.contains("fn weft_d_ggx"),
        "the lobe is there at strength 1"
    );
    inst.values[i] = ParamValue::Float(0.0);
    let values = instance_values(&m, &inst, m.tiers.default, &SceneFeatures::default());
    let (folded, wgsl) = folded_wgsl(&module, &values.fold);
    assert!(
        !wgsl.contains("weft_d_ggx"),
        "GGX D still evaluated:\n{wgsl}"
    );
    assert!(!wgsl.contains("weft_prefiltered_radiance"), "{wgsl}");
    // Nothing else samples the environment cube in standard's fast tier.
    let names: Vec<_> = folded
        .global_variables
        .iter()
        .filter_map(|(_, g)| g.name.clone())
        .collect();
    assert!(
        !names.contains(&"weft_environment".to_string()),
        "{names:?}"
    );
}

/// Every parameter at its range's low or high end (`at_max`), or its default.
fn values_at(m: &weft_front::Material, bound: Option<bool>) -> Vec<ParamValue> {
    m.params
        .iter()
        .map(|p| {
            let (Some(at_max), Some([lo, hi])) = (bound, p.range) else {
                return p.default.clone();
            };
            let x = if at_max { hi } else { lo };
            match &p.default {
                ParamValue::Float(_) => ParamValue::Float(x),
                ParamValue::Int(_) => ParamValue::Int(x as i64),
                ParamValue::Vector(v) => {
                    let mut v2 = vec![x; v.len()];
                    if p.kind == weft_meta::ParamKind::Color && v.len() == 4 {
                        v2[3] = x.clamp(0.0, 1.0);
                    }
                    ParamValue::Vector(v2)
                }
                ParamValue::Bool(_) => ParamValue::Bool(at_max),
                other => other.clone(),
            }
        })
        .collect()
}

#[test]
fn every_variant_folds_at_every_range_end_and_emits_every_language() {
    use rayon::prelude::*;
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../materials");
    let mut folded = 0;
    for toml in weft_compiler::library::discover(&root).unwrap() {
        let name = toml.file_stem().unwrap().to_string_lossy().into_owned();
        let (m, module, prelude) = load(&name);
        let portable = load_portable(&name);
        let cases: Vec<_> = (weft_front::variants::variants(&m).into_iter())
            .flat_map(|key| [None, Some(false), Some(true)].map(|bound| (key.clone(), bound)))
            .collect();
        // Each case is independent: spread them over the cores.
        cases.par_iter().for_each(|(key, bound)| {
            let mut inst = instance(&m, &[]);
            inst.values = values_at(&m, *bound);
            for &(k, v) in &key.keywords {
                inst.keywords[k] = v;
            }
            let values = instance_values(&m, &inst, key.tier, &SceneFeatures::default());
            let (f, _) = folded_wgsl(&module, &values.fold);
            let info = compose::validator().validate(&f).unwrap();
            let portable = portable.as_ref().map(|p| {
                let (p, _) = folded_wgsl(p, &values.fold);
                let info = compose::validator().validate(&p).unwrap();
                (p, info)
            });
            weft_compiler::variant::emit_shader(
                &m,
                (&f, &info),
                portable.as_ref().map(|(p, i)| (p, i)),
                format!("{name}.test"),
                &prelude,
                &weft_compiler::variant::material_textures(
                    &m,
                    &prelude,
                    &m.tiers.values[key.tier],
                    |_| None,
                ),
                &[Vec::new()],
            )
            .unwrap_or_else(|e| panic!("{name} {} at {bound:?}: {e}", key.id(&m)));
        });
        folded += cases.len();
    }
    assert!(folded >= 48 * 3, "{folded}");
}
