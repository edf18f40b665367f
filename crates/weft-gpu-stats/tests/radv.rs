//! RADV null-device statistics of the library under `generated/`: no GPU
//! needed, only Mesa's `mesa-vulkan-drivers` (which `.ci/run` installs).

use std::collections::BTreeSet;
use std::path::PathBuf;
use std::sync::OnceLock;
use weft_gpu_stats::{
    DEFAULT_FAMILIES, Error, FamilyStats, Options, PipelineStats, Selection, WorkerCommand,
};
use weft_meta::MaterialMetadata;

fn generated() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../../generated"))
}

fn options(selection: Selection) -> Options {
    Options {
        generated: generated(),
        selection,
        families: DEFAULT_FAMILIES.iter().map(|f| f.to_string()).collect(),
        disassembly: false,
        icd_dirs: None,
        worker: WorkerCommand {
            program: env!("CARGO_BIN_EXE_weft-gpu-stats").into(),
            args: vec![],
        },
    }
}

/// The whole library and every scene shader, for navi21 and gfx1100 (compiled once per run).
fn full() -> &'static [FamilyStats] {
    static FULL: OnceLock<Vec<FamilyStats>> = OnceLock::new();
    FULL.get_or_init(|| {
        let sel = Selection {
            scenes: true,
            ..Default::default()
        };
        weft_gpu_stats::collect(&options(sel)).unwrap_or_else(|e| panic!("{e}"))
    })
}

type Key = (String, String, String, String, Option<String>, String);

fn key(p: &PipelineStats) -> Key {
    let s = &p.source;
    (
        s.kind.clone(),
        s.material.clone(),
        s.variant.clone(),
        s.precision.clone(),
        s.scene.clone(),
        p.pass.clone(),
    )
}

/// (material, variant, precision, pass) of every canonical variant × pass, f16 files too, read
/// from the metadata independently of the crate's job list.
fn expected_library() -> BTreeSet<(String, String, String, String)> {
    let mut out = BTreeSet::new();
    for entry in std::fs::read_dir(generated()).unwrap() {
        let dir = entry.unwrap().path();
        let name = dir.file_name().unwrap().to_str().unwrap().to_string();
        let meta_path = dir.join(format!("{name}.meta.json"));
        if !meta_path.is_file() {
            continue;
        }
        let meta: MaterialMetadata =
            serde_json::from_slice(&std::fs::read(&meta_path).unwrap()).unwrap();
        for v in &meta.variants {
            let canonical = meta.resolve_variant(&v.id).unwrap();
            let shader = canonical.shader.as_ref().unwrap();
            let mut precisions = vec!["f32"];
            if !shader.f16_files.is_empty() {
                precisions.push("f16");
            }
            for precision in precisions {
                for pass in &v.passes {
                    out.insert((
                        name.clone(),
                        canonical.id.clone(),
                        precision.to_string(),
                        pass.clone(),
                    ));
                }
            }
        }
    }
    out
}

#[test]
fn every_variant_pass_and_scene_shader_has_figures_on_navi21_and_gfx1100() {
    let full = full();
    let expected = expected_library();
    assert!(
        expected.len() > 250,
        "library too small: {}",
        expected.len()
    );
    assert!(
        expected.iter().any(|k| k.2 == "f16"),
        "no f16 files in the library"
    );
    assert_eq!(full.len(), 2);
    for (f, family) in full.iter().zip(DEFAULT_FAMILIES) {
        assert_eq!(f.family, family);
        assert!(
            f.device_name
                .to_uppercase()
                .contains(&family.to_uppercase()),
            "{family} compiled on `{}`",
            f.device_name
        );
        let got: BTreeSet<_> = f
            .pipelines
            .iter()
            .filter(|p| p.source.kind == "material")
            .map(|p| {
                let s = &p.source;
                (
                    s.material.clone(),
                    s.variant.clone(),
                    s.precision.clone(),
                    p.pass.clone(),
                )
            })
            .collect();
        assert_eq!(got, expected, "{family}: library pipelines");
        let scenes = f
            .pipelines
            .iter()
            .filter(|p| p.source.kind == "scene")
            .count();
        assert!(scenes >= 20, "{family}: {scenes} scene pipelines");
        for p in &f.pipelines {
            for stage in ["vertex", "fragment"] {
                let s = p
                    .stage(stage)
                    .unwrap_or_else(|| panic!("{family} {:?}: no {stage} stage", key(p)));
                for name in [
                    "Instructions",
                    "VGPRs",
                    "SGPRs",
                    "Code size",
                    "Subgroups per SIMD",
                    "Inverse Throughput",
                    "Spilled VGPRs",
                ] {
                    assert!(
                        s.get(name).is_some(),
                        "{family} {:?} {stage}: no `{name}`",
                        key(p)
                    );
                }
                assert!(s.get("Instructions").unwrap() > 0.0 && s.get("VGPRs").unwrap() > 0.0);
            }
        }
    }
    // RDNA3 is not RDNA2 renamed: some fragment stage compiles differently.
    let differs = full[0]
        .pipelines
        .iter()
        .zip(&full[1].pipelines)
        .any(|(a, b)| {
            a.stage("fragment").unwrap().statistics != b.stage("fragment").unwrap().statistics
        });
    assert!(
        differs,
        "navi21 and gfx1100 gave identical figures everywhere"
    );
}

#[test]
fn the_same_spirv_compiled_again_gives_identical_figures() {
    // A second compile in new processes, of a subset in a different job list
    // (f32 and f16 files, several passes, scene shaders), against the full run.
    let sel = Selection {
        materials: Some(vec!["hair".into(), "satin".into(), "standard".into()]),
        tiers: None,
        scenes: true,
    };
    let again = weft_gpu_stats::collect(&options(sel)).unwrap_or_else(|e| panic!("{e}"));
    for (first, second) in full().iter().zip(&again) {
        assert_eq!(first.family, second.family);
        let mut compared = 0;
        for p in &second.pipelines {
            let q = first
                .pipelines
                .iter()
                .find(|q| key(q) == key(p) && q.source.spirv == p.source.spirv)
                .unwrap_or_else(|| panic!("{:?} missing from the full run", key(p)));
            assert_eq!(p, q, "{}: figures changed between compiles", first.family);
            compared += 1;
        }
        assert!(compared > 50, "only {compared} pipelines compared");
        assert!(second.pipelines.iter().any(|p| p.source.precision == "f16"));
    }
}

#[test]
fn missing_radv_names_the_package() {
    let empty = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("no-icd");
    std::fs::create_dir_all(&empty).unwrap();
    let mut opts = options(Selection::default());
    opts.icd_dirs = Some(vec![empty.clone()]);
    match weft_gpu_stats::collect(&opts) {
        Err(e @ Error::RadvMissing { .. }) => {
            let msg = e.to_string();
            assert!(msg.contains("mesa-vulkan-drivers"), "{msg}");
            assert!(msg.contains(&empty.display().to_string()), "{msg}");
        }
        other => panic!("expected RadvMissing, got {other:?}"),
    }
}

#[test]
fn unknown_family_is_a_clear_error() {
    let mut opts = options(Selection {
        materials: Some(vec!["standard".into()]),
        ..Default::default()
    });
    opts.families = vec!["navi99".into()];
    let e = weft_gpu_stats::collect(&opts).unwrap_err().to_string();
    assert!(e.contains("navi99"), "{e}");
}
