//! The compiled shader library and the shipped scenes' shaders, checked by
//! consumers no one here wrote: naga (re-parse + validate), `spirv-val`,
//! glslang's HLSL front end; plus metadata-vs-module agreement, determinism,
//! aliasing and staleness of the committed `generated/` tree.
//!
//! The project is built the way `cargo xtask regenerate` builds it
//! (`weft_golden::project::build_project`: materials, then every scene under
//! `scenes/`), so every check covers scene shaders too.

use shaders::ShaderRef;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;
use weft_compiler::{BuildOptions, BuildOutput, build_library, output};
use weft_meta::scene::SceneMetadata;
use weft_meta::{Pass, Stage, VariantShader};
use weft_tests::{repo, shaders};

fn build_dir(dir: &Path, jobs: Option<usize>) -> BuildOutput {
    match build_library(
        dir,
        &BuildOptions {
            jobs,
            ..Default::default()
        },
        &|_, _, _| {},
    ) {
        Ok(out) => out,
        Err((db, diags)) => panic!(
            "{} does not build:\n{}",
            dir.display(),
            diags.render_plain(&db)
        ),
    }
}

/// The whole project (materials and scenes) as `cargo xtask regenerate` builds it.
fn build_project(jobs: Option<usize>) -> BuildOutput {
    let options = BuildOptions {
        jobs,
        ..Default::default()
    };
    match weft_golden::project::build_project(&repo(), &options) {
        Ok(out) => out,
        Err((db, diags)) => panic!("the project does not build:\n{}", diags.render_plain(&db)),
    }
}

/// The shipped project (materials and scenes) and the test fixtures, built
/// once per test binary.
fn builds() -> &'static [BuildOutput] {
    static CELL: OnceLock<Vec<BuildOutput>> = OnceLock::new();
    CELL.get_or_init(|| {
        vec![
            build_project(None),
            build_dir(&repo().join("tests/fixtures/materials"), None),
        ]
    })
}

fn all_files() -> impl Iterator<Item = (&'static String, &'static Vec<u8>)> {
    builds().iter().flat_map(|b| b.files.iter())
}

/// The scene metadata of each build (the fixtures have none).
fn scenes() -> &'static [Vec<SceneMetadata>] {
    static CELL: OnceLock<Vec<Vec<SceneMetadata>>> = OnceLock::new();
    CELL.get_or_init(|| builds().iter().map(|b| shaders::scenes(&b.files)).collect())
}

/// Every canonical material variant and every scene shader of every build.
fn all_shaders() -> Vec<ShaderRef<'static>> {
    builds()
        .iter()
        .zip(scenes())
        .flat_map(|(b, s)| shaders::shaders(&b.materials, s))
        .collect()
}

fn file(name: &str) -> &'static [u8] {
    all_files()
        .find(|(n, _)| *n == name)
        .unwrap_or_else(|| panic!("{name} is in the metadata but not in the build"))
        .1
}

/// An external validator, or a failure saying what to install.
fn tool(name: &str, package: &str) -> PathBuf {
    let found = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|p| p.join(name))
            .find(|p| p.is_file())
    });
    found.unwrap_or_else(|| {
        panic!("`{name}` not found: install it with `apt-get install -y {package}` (see .ci/run)")
    })
}

/// Every manifest in `scenes/` is built into the project's files (and the
/// checks below see its shaders).
#[test]
fn every_shipped_scene_is_in_the_project_build() {
    let names: Vec<&str> = scenes()[0].iter().map(|s| s.name.as_str()).collect();
    let shipped = weft_golden::scenes::shipped_scenes(&repo()).unwrap();
    assert!(!shipped.is_empty(), "no scenes/*.scene.toml");
    assert_eq!(names, shipped);
    for s in &scenes()[0] {
        assert!(!s.shaders.is_empty(), "scene {} has no shader", s.name);
        for entry in &s.shaders {
            for f in entry.shader.all_files() {
                file(&format!("scenes/{}/{}", s.name, f.path));
            }
        }
    }
}

#[test]
fn generated_tree_is_current() {
    let s = output::check(
        &repo().join("generated"),
        &builds()[0].files,
        &["reports", "gallery", "gallery.md"],
    )
    .unwrap();
    assert!(
        s.is_clean(),
        "generated/ is stale, run `cargo xtask regenerate`: {s:?}"
    );
}

#[test]
fn every_spirv_passes_spirv_val() {
    let spirv_val = tool("spirv-val", "spirv-tools");
    let dir = tempfile::tempdir().unwrap();
    let mut count = 0;
    for (name, bytes) in all_files().filter(|(n, _)| n.ends_with(".spv")) {
        let path = dir.path().join(name.replace('/', "__"));
        std::fs::write(&path, bytes).unwrap();
        let out = Command::new(&spirv_val)
            .args(["--target-env", "vulkan1.0"])
            .arg(&path)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "spirv-val rejects {name}:\n{}",
            String::from_utf8_lossy(&out.stderr)
        );
        count += 1;
    }
    assert!(
        count >= 12,
        "expected SPIR-V for every variant, found {count}"
    );
}

#[test]
fn every_hlsl_compiles_with_glslang_for_each_stage() {
    use rayon::prelude::*;
    let glslang = tool("glslangValidator", "glslang-tools");
    let dir = tempfile::tempdir().unwrap();
    // (file, entry point, stage, is a scene shader), one glslang run each.
    let mut runs = Vec::new();
    for s in all_shaders() {
        for hlsl in &s.shader.files["hlsl"] {
            let name = s.file(&hlsl.path);
            let path = dir.path().join(name.replace('/', "__"));
            std::fs::write(&path, file(&name)).unwrap();
            for ep in &s.shader.entry_points {
                let stage = match ep.stage {
                    Stage::Vertex => "vert",
                    Stage::Fragment => "frag",
                    Stage::Compute => "comp",
                };
                runs.push((
                    name.clone(),
                    path.clone(),
                    ep.name.clone(),
                    stage,
                    s.material.is_none(),
                ));
            }
        }
    }
    runs.par_iter()
        .enumerate()
        .for_each(|(i, (name, path, entry, stage, _))| {
            let out = Command::new(&glslang)
                .args(["-D", "-V", "-S", stage, "-e", entry])
                .arg(path)
                .arg("-o")
                .arg(dir.path().join(format!("{i}.spv")))
                .output()
                .unwrap();
            assert!(
                out.status.success(),
                "glslang rejects {name} ({stage} {entry}):\n{}",
                String::from_utf8_lossy(&out.stdout)
            );
        });
    let count = runs.len();
    let scene_count = runs.iter().filter(|r| r.4).count();
    assert!(
        count >= 24,
        "expected every HLSL entry point checked, got {count}"
    );
    assert!(
        scene_count >= 2,
        "expected the scene shaders' HLSL checked, got {scene_count}"
    );
}

/// Every MSL file declares each resource its entry points use at the
/// argument slot the metadata's `bindings[].msl` states (no Metal compiler
/// runs here, so this is the check that a Metal engine can bind the file:
/// naga's unbindable `[[user(fake…)]]` placeholder never appears).
#[test]
fn every_msl_resource_sits_at_its_metadata_slot() {
    let mut checked = 0;
    for s in all_shaders() {
        for f in &s.shader.files["msl"] {
            let name = s.file(&f.path);
            let text = std::str::from_utf8(file(&name)).unwrap();
            assert!(
                !text.contains("[[user(fake"),
                "{name}: a resource without a slot"
            );
            for b in &s.shader.bindings {
                let slot = b
                    .msl
                    .unwrap_or_else(|| panic!("{name}: binding {} has no msl slot", b.name));
                let attr = match slot.kind {
                    weft_meta::MslSlotKind::Buffer => format!("[[buffer({})]]", slot.index),
                    weft_meta::MslSlotKind::Texture => format!("[[texture({})]]", slot.index),
                    weft_meta::MslSlotKind::Sampler => format!("[[sampler({})]]", slot.index),
                };
                // Entry-point arguments read `<type> <name> [[<table>(<n>)]]`.
                let declared = text
                    .lines()
                    .filter(|l| l.contains(&format!(" {} [[", b.name)))
                    .collect::<Vec<_>>();
                assert!(
                    !declared.is_empty(),
                    "{name}: `{}` is not an argument",
                    b.name
                );
                for l in declared {
                    assert!(l.ends_with(&attr), "{name}: `{l}` is not at {attr}");
                }
                checked += 1;
            }
        }
    }
    assert!(checked > 400, "{checked}");
}

fn reparse(name: &str, bytes: &[u8]) -> (naga::Module, naga::valid::ModuleInfo) {
    let text = std::str::from_utf8(bytes).unwrap();
    let module = naga::front::wgsl::parse_str(text)
        .unwrap_or_else(|e| panic!("{name} does not re-parse:\n{}", e.emit_to_string(text)));
    let info = naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::all(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{name} does not validate:\n{}", e.emit_to_string(text)));
    (module, info)
}

#[test]
fn every_wgsl_reparses_and_validates_in_naga() {
    let mut count = 0;
    for (name, bytes) in all_files().filter(|(n, _)| n.ends_with(".wgsl")) {
        reparse(name, bytes);
        count += 1;
    }
    assert!(count >= 12);
    // A scene shader of a `low` tier also has its `.f16.wgsl` file.
    let scene_wgsl = all_files()
        .filter(|(n, _)| {
            n.starts_with("scenes/") && n.ends_with(".wgsl") && !n.ends_with(".f16.wgsl")
        })
        .count();
    let scene_shaders: usize = scenes()[0].iter().map(|s| s.shaders.len()).sum();
    assert_eq!(
        scene_wgsl, scene_shaders,
        "one WGSL module per scene shader"
    );
}

/// WebGPU vertex format of a vertex input's WGSL type.
fn vertex_format(module: &naga::Module, ty: naga::Handle<naga::Type>) -> String {
    let (scalar, n) = match module.types[ty].inner {
        naga::TypeInner::Scalar(s) => (s, 1),
        naga::TypeInner::Vector { size, scalar } => (scalar, size as u32),
        ref other => panic!("vertex input of type {other:?}"),
    };
    let base = match scalar.kind {
        naga::ScalarKind::Float => "float",
        naga::ScalarKind::Sint => "sint",
        naga::ScalarKind::Uint => "uint",
        other => panic!("vertex input of kind {other:?}"),
    };
    let bits = u32::from(scalar.width) * 8;
    if n == 1 {
        format!("{base}{bits}")
    } else {
        format!("{base}{bits}x{n}")
    }
}

/// (location, format) of every `@location` input of the vertex entry points.
fn module_vertex_inputs(module: &naga::Module) -> Vec<(u32, String)> {
    let mut out = Vec::new();
    for ep in module
        .entry_points
        .iter()
        .filter(|e| e.stage == naga::ShaderStage::Vertex)
    {
        for arg in &ep.function.arguments {
            let mut inputs = vec![(arg.binding.clone(), arg.ty)];
            if let naga::TypeInner::Struct { members, .. } = &module.types[arg.ty].inner {
                inputs.extend(members.iter().map(|m| (m.binding.clone(), m.ty)));
            }
            for (binding, ty) in inputs {
                if let Some(naga::Binding::Location { location, .. }) = binding {
                    let input = (location, vertex_format(module, ty));
                    if !out.contains(&input) {
                        out.push(input);
                    }
                }
            }
        }
    }
    out.sort();
    out
}

/// The metadata of one compiled shader (`name` is its WGSL file) agrees with
/// what naga finds in the emitted module: hash, material uniform layout,
/// bindings, entry points (exactly those its passes name) and vertex inputs
/// (locations, formats and the engine interface's names for them).
fn assert_metadata_matches_module(name: &str, shader: &VariantShader, passes: &[&Pass]) {
    let wgsl = &shader.files["wgsl"][0];
    let bytes = file(name);
    assert_eq!(
        weft_compiler::digest::sha256_hex(bytes),
        wgsl.sha256,
        "{name}: hash"
    );
    let (module, _) = reparse(name, bytes);

    let mut layouter = naga::proc::Layouter::default();
    layouter.update(module.to_ctx()).unwrap();
    let ubo = module.global_variables.iter().find(|(_, g)| {
        g.binding
            .as_ref()
            .is_some_and(|b| b.group == 1 && b.binding == 0)
    });
    match (&shader.material_uniform, ubo) {
        (Some(meta), Some((_, g))) => {
            let naga::TypeInner::Struct { members, span } = &module.types[g.ty].inner else {
                panic!("{name}: uniform is not a struct")
            };
            assert_eq!(meta.size, *span, "{name}: uniform size");
            assert_eq!(meta.members.len(), members.len(), "{name}: member count");
            for (mm, nm) in meta.members.iter().zip(members) {
                assert_eq!(Some(&mm.name), nm.name.as_ref(), "{name}: member order");
                assert_eq!(mm.offset, nm.offset, "{name}: offset of {}", mm.name);
                assert_eq!(mm.size, layouter[nm.ty].size, "{name}: size of {}", mm.name);
            }
        }
        (None, None) => {}
        (meta, naga) => panic!(
            "{name}: metadata uniform {:?} vs module uniform {:?}",
            meta.is_some(),
            naga.is_some()
        ),
    }

    let mut found: Vec<(u32, u32, String)> = module
        .global_variables
        .iter()
        .filter_map(|(_, g)| {
            g.binding
                .as_ref()
                .map(|b| (b.group, b.binding, g.name.clone().unwrap_or_default()))
        })
        .collect();
    found.sort();
    let listed: Vec<(u32, u32, String)> = shader
        .bindings
        .iter()
        .map(|b| (b.group, b.binding, b.name.clone()))
        .collect();
    assert_eq!(found, listed, "{name}: bindings");

    let eps: Vec<&str> = module
        .entry_points
        .iter()
        .map(|e| e.name.as_str())
        .collect();
    let listed: Vec<&str> = shader
        .entry_points
        .iter()
        .map(|e| e.name.as_str())
        .collect();
    assert_eq!(eps, listed, "{name}: entry points");
    for pass in passes {
        assert!(
            eps.contains(&pass.vertex_entry.as_str())
                && eps.contains(&pass.fragment_entry.as_str()),
            "{name}: pass {}",
            pass.name
        );
    }
    // And no other: a library's entry point that no pass of the variant
    // names (lib/forward.wgsl's `vs_main` beside microcylinder's and hair's
    // own vertex stages) is not in its outputs.
    for ep in &eps {
        assert!(
            passes
                .iter()
                .any(|p| p.vertex_entry == *ep || p.fragment_entry == *ep),
            "{name}: entry point `{ep}` is named by no pass"
        );
    }

    let listed: Vec<(u32, String)> = shader
        .vertex_inputs
        .iter()
        .map(|v| (v.location, v.format.clone()))
        .collect();
    assert_eq!(
        module_vertex_inputs(&module),
        listed,
        "{name}: vertex inputs"
    );
    for v in &shader.vertex_inputs {
        let attribute = weft_front::model::VertexAttribute::ALL
            .into_iter()
            .find(|a| a.location() == v.location)
            .unwrap_or_else(|| panic!("{name}: no vertex attribute at location {}", v.location));
        assert_eq!(
            v.name,
            attribute.name(),
            "{name}: the input at location {}",
            v.location
        );
    }
}

/// Offsets, bindings, entry points and vertex inputs in the metadata equal
/// what naga finds in the emitted WGSL, computed independently of the
/// compiler's reflection: every material variant and every scene shader.
#[test]
fn metadata_matches_the_emitted_modules() {
    let (mut materials, mut scene_shaders) = (0, 0);
    for s in all_shaders() {
        let name = s.file(&s.shader.files["wgsl"][0].path);
        assert_metadata_matches_module(&name, s.shader, &s.passes);
        match s.material {
            Some(_) => materials += 1,
            None => scene_shaders += 1,
        }
    }
    assert!(materials >= 12, "checked {materials} material variants");
    let expected: usize = scenes().iter().flatten().map(|s| s.shaders.len()).sum();
    assert!(expected >= 2, "the shipped scenes have {expected} shaders");
    assert_eq!(scene_shaders, expected, "every scene shader checked");
}

/// A glTF primitive's `COLOR_0` is dropped with a warning that says weft's
/// materials read no vertex colours (`gltf::scene::vertex_colour_warnings`):
/// true while no library variant takes the `color` stream.
#[test]
fn no_library_material_reads_vertex_colours() {
    for s in all_shaders().iter().filter(|s| s.material.is_some()) {
        assert!(
            s.shader.vertex_inputs.iter().all(|v| v.name != "color"),
            "{} reads vertex colours: glTF's COLOR_0 can now reach it, so \
             `vertex_colour_warnings` in crates/weft-front/src/gltf/scene.rs must \
             stop dropping it for this material",
            s.file(&s.shader.files["wgsl"][0].path)
        );
    }
}

/// Materials and scenes (scenes on a rayon pool of the same size).
#[test]
fn output_is_identical_across_runs_and_thread_counts() {
    let a = build_project(Some(1));
    let b = build_project(Some(4));
    assert!(
        a.files.keys().any(|k| k.starts_with("scenes/")),
        "the scenes are part of the comparison"
    );
    let keys_a: Vec<&String> = a.files.keys().collect();
    let keys_b: Vec<&String> = b.files.keys().collect();
    assert_eq!(keys_a, keys_b);
    for (k, v) in &a.files {
        assert!(b.files[k] == *v, "{k} differs between 1 and 4 threads");
    }
    assert!(builds()[0].files == a.files, "a third build differs");
}

#[test]
fn dead_branches_and_their_bindings_are_removed() {
    let m = &builds()[0]
        .materials
        .iter()
        .find(|m| m.name == "standard")
        .unwrap();
    let params = |id: &str| -> Vec<String> {
        let v = m.resolve_variant(id).unwrap();
        v.shader
            .as_ref()
            .unwrap()
            .bindings
            .iter()
            .filter_map(|b| b.parameter.clone())
            .collect()
    };
    let plain = params("fast.normal_map-off.sphere_map-off");
    assert!(
        !plain.contains(&"normal_map".to_string()) && !plain.contains(&"sphere_map".to_string()),
        "{plain:?}"
    );
    assert!(params("fast.normal_map-on.sphere_map-off").contains(&"normal_map".to_string()));
    assert!(params("reference.normal_map-off.sphere_map-add").contains(&"sphere_map".to_string()));
    // Static keywords never survive into variants as overrides: only
    // `constant`-mode ones (standard's ALPHA_TEST and EMISSION) stay.
    let constant: Vec<&str> = builds()[0]
        .materials
        .iter()
        .flat_map(|m| &m.keywords)
        .filter(|k| k.mode == weft_meta::KeywordMode::Constant)
        .map(|k| k.name.as_str())
        .collect();
    assert!(constant.contains(&"EMISSION"), "{constant:?}");
    for (name, bytes) in builds()[0]
        .files
        .iter()
        .filter(|(n, _)| n.ends_with(".wgsl"))
    {
        let text = std::str::from_utf8(bytes).unwrap();
        for line in text.lines().filter(|l| l.starts_with("override ")) {
            assert!(
                constant
                    .iter()
                    .any(|k| line.starts_with(&format!("override {k}:"))),
                "{name} keeps a static keyword's override: {line}"
            );
        }
    }
}

#[test]
fn identical_variants_are_aliased_and_constant_keywords_stay_overrides() {
    let m = builds()[1]
        .materials
        .iter()
        .find(|m| m.name == "switches")
        .unwrap();
    let v = m
        .variants
        .iter()
        .find(|v| v.id == "fast.unused-on.use_mask-on")
        .unwrap();
    assert_eq!(v.alias_of.as_deref(), Some("fast.unused-off.use_mask-on"));
    assert!(v.shader.is_none());
    let files: BTreeMap<&String, &Vec<u8>> = builds()[1].files.iter().collect();
    assert!(
        !files.keys().any(|k| k.contains("unused-on")),
        "aliased variants emit no files"
    );

    let canonical = m
        .resolve_variant("fast.unused-off.use_mask-on")
        .unwrap()
        .shader
        .as_ref()
        .unwrap();
    assert_eq!(canonical.pipeline_constants.len(), 1);
    assert_eq!(canonical.pipeline_constants[0].name, "STYLE");
    let wgsl = std::str::from_utf8(files[&"switches/fast.unused-off.use_mask-on.wgsl".to_string()])
        .unwrap();
    assert!(
        wgsl.contains("override STYLE"),
        "constant-mode keyword kept as a pipeline constant"
    );
    // One SPIR-V per value of the constant keyword, each labelled.
    let spirv = &canonical.files["spirv"];
    assert_eq!(spirv.len(), 2);
    assert_eq!(
        spirv[1].constants.get("STYLE").map(String::as_str),
        Some("ramp")
    );
    // The gradient ramp's binding is only used when STYLE may be `ramp`: it is, so it is listed.
    assert!(
        canonical
            .bindings
            .iter()
            .any(|b| b.parameter.as_deref() == Some("ramp"))
    );
}

#[test]
fn baked_curves_and_gradients_reach_the_metadata() {
    let m = builds()[1]
        .materials
        .iter()
        .find(|m| m.name == "switches")
        .unwrap();
    let curve = m
        .parameters
        .iter()
        .find(|p| p.name == "falloff")
        .unwrap()
        .curve
        .as_ref()
        .unwrap();
    assert_eq!(curve.baked_default.len(), 8);
    assert_eq!(curve.baked_default[0], 0.0);
    assert!((curve.baked_default[7] - 1.0).abs() < 1e-12);
    let ramp = m
        .parameters
        .iter()
        .find(|p| p.name == "ramp")
        .unwrap()
        .gradient
        .as_ref()
        .unwrap();
    assert_eq!(ramp.baked_default.len(), 16 * 4);
    // First texel centre x = 1/32: linear-light mix (31/32 red, 1/32 blue), sRGB-encoded.
    assert_eq!(&ramp.baked_default[0..4], &[251, 0, 49, 255]);
    assert_eq!(&ramp.baked_default[60..64], &[49, 0, 251, 255]);
    let tint = m
        .parameters
        .iter()
        .find(|p| p.name == "tint")
        .unwrap()
        .color
        .as_ref()
        .unwrap();
    assert!(
        (tint.linear_default[0] - 0.214).abs() < 1e-3,
        "sRGB 0.5 -> linear 0.214"
    );
}

#[test]
fn generated_code_snapshots() {
    let files = &builds()[0].files;
    let text = |k: &str| String::from_utf8(files[k].clone()).unwrap();
    insta::assert_snapshot!(
        "standard_default_wgsl",
        text("standard/fast.normal_map-off.sphere_map-off.wgsl")
    );
    insta::assert_snapshot!(
        "standard_reference_normal_add_hlsl",
        text("standard/reference.normal_map-on.sphere_map-add+alpha_test-off+emission-off.hlsl")
    );
    let fixtures = &builds()[1].files;
    insta::assert_snapshot!(
        "switches_constant_mode_wgsl",
        String::from_utf8(fixtures["switches/fast.unused-off.use_mask-on.wgsl"].clone()).unwrap()
    );
}

#[test]
fn generated_prelude_snapshot() {
    let mut db = weft_front::SourceDb::new();
    let mut diags = weft_front::Diagnostics::new();
    let root = repo().join("tests/fixtures/materials");
    let m = weft_front::load_material(
        &root.join("switches/switches.toml"),
        &root,
        &mut db,
        &mut diags,
    )
    .unwrap();
    let prelude = weft_compiler::prelude::generate(&m);
    let text: Vec<&str> = prelude.lines.iter().map(|(l, _)| l.as_str()).collect();
    insta::assert_snapshot!("switches_prelude", text.join("\n"));
}
