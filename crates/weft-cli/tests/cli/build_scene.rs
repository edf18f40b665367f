//! `weft build --scene` as a user runs it: a scene that only the compiler can
//! reject (its front end accepts it) exits 1 with the diagnostic and writes nothing.

use std::process::Command;
use weft_tests::repo;

#[test]
fn build_scene_writes_nothing_when_the_compiler_rejects_the_scene() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_weft"))
        .current_dir(repo())
        .args([
            "build",
            "--color",
            "never",
            "--scene",
            "tests/diagnostics/scenes/bad/shader_budget.scene.toml",
            "-o",
        ])
        .arg(&out)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("error[shader-budget]"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!out.exists(), "no output folder on error");
    // Nothing half-written beside it either.
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn build_scene_replaces_only_its_own_folder() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir_all(out.join("other_scene")).unwrap();
    std::fs::write(out.join("other_scene/keep.txt"), "kept").unwrap();
    std::fs::create_dir_all(out.join("swatch_book")).unwrap();
    std::fs::write(out.join("swatch_book/stale.wgsl"), "old").unwrap();
    let build = || {
        Command::new(env!("CARGO_BIN_EXE_weft"))
            .current_dir(repo())
            .args(["build", "--scene", "scenes/swatch_book.scene.toml", "-o"])
            .arg(&out)
            .output()
            .unwrap()
    };
    // Not marked as weft's output: refused, left as it was.
    let o = build();
    assert_eq!(o.status.code(), Some(1));
    assert_eq!(
        std::fs::read_to_string(out.join("swatch_book/stale.wgsl")).unwrap(),
        "old"
    );
    // An earlier build's folder (marked) is replaced.
    std::fs::write(out.join("swatch_book/.weft-output"), "").unwrap();
    let o = build();
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{stderr}");
    assert_eq!(
        std::fs::read_to_string(out.join("other_scene/keep.txt")).unwrap(),
        "kept"
    );
    assert!(
        !out.join("swatch_book/stale.wgsl").exists(),
        "the scene folder is replaced whole"
    );
    // Byte-identical to the committed build.
    let built = std::fs::read(out.join("swatch_book/swatch_book.scene.json")).unwrap();
    let committed =
        std::fs::read(repo().join("generated/scenes/swatch_book/swatch_book.scene.json")).unwrap();
    assert_eq!(built, committed);
}

/// `--gpu-model`: the funnel's cost saving per family, recorded in the scene
/// metadata and printed, for every shipped scene (the showroom's satin ball
/// draws a variant that is an alias of another: its generic files are the
/// other's). The figures are the ones `cargo xtask bench gpu-model`
/// committed for the same scene (generated/reports/gpu-model.json, the
/// shipped library's generic variants), summed over the instances and their
/// passes: two routes to one number. Deterministic (a second build is
/// byte-identical), and nothing is written without RADV.
#[test]
fn gpu_model_records_what_specialising_saves() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let build = |scene: &str, extra_env: &[(&str, &str)]| {
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_weft"));
        cmd.current_dir(repo())
            .args([
                "build",
                "--scene",
                &format!("scenes/{scene}.scene.toml"),
                "--gpu-model",
                "-o",
            ])
            .arg(&out);
        for (k, v) in extra_env {
            cmd.env(k, v);
        }
        cmd.output().unwrap()
    };
    let committed: weft_meta::gpu_model::ModelSummary = serde_json::from_slice(
        &std::fs::read(repo().join("generated/reports/gpu-model.json")).unwrap(),
    )
    .unwrap();
    let mut scenes: Vec<String> = std::fs::read_dir(repo().join("scenes"))
        .unwrap()
        .filter_map(|e| {
            let name = e.unwrap().file_name().into_string().unwrap();
            name.strip_suffix(".scene.toml").map(str::to_string)
        })
        .collect();
    scenes.sort();
    assert!(scenes.len() >= 5, "{scenes:?}");
    for scene in &scenes {
        let o = build(scene, &[]);
        let stdout = String::from_utf8_lossy(&o.stdout);
        assert!(
            o.status.success(),
            "{scene}: {stdout}{}",
            String::from_utf8_lossy(&o.stderr)
        );
        assert!(
            stdout.contains("modelled fragment cost") && stdout.contains("on navi21"),
            "{scene}: {stdout}"
        );
        let path = out.join(format!("{scene}/{scene}.scene.json"));
        let bytes = std::fs::read(&path).unwrap();
        let meta: weft_meta::scene::SceneMetadata = serde_json::from_slice(&bytes).unwrap();
        let modelled = &meta.funnel.as_ref().unwrap().modelled;
        assert_eq!(
            modelled
                .iter()
                .map(|m| m.family.as_str())
                .collect::<Vec<_>>(),
            ["navi21", "gfx1100"]
        );
        for m in modelled {
            let family = committed
                .families
                .iter()
                .find(|f| f.family == m.family)
                .unwrap();
            // Another compiler gives other figures: say so rather than differ below.
            assert_eq!(
                m.driver, family.driver_info,
                "the committed model (generated/reports/gpu-model.json) is {}'s and this \
                 machine's RADV is {}: run with Debian 12's mesa-vulkan-drivers, as .ci/run \
                 installs (docs/performance.md, \"On another Mesa\")",
                family.driver_info, m.driver
            );
            let (mut generic, mut specialised) = (0.0, 0.0);
            let (mut generic_i, mut specialised_i) = (0, 0);
            for inst in meta.built_instances() {
                for pass in &inst.passes {
                    let c = family
                        .scene_shaders
                        .iter()
                        .find(|c| {
                            c.scene == *scene && c.shader == inst.shader && c.pass == pass.name
                        })
                        .unwrap_or_else(|| {
                            panic!(
                                "{scene} {} {}: not in the committed model",
                                inst.name, pass.name
                            )
                        });
                    generic += c.generic.executed_cost;
                    specialised += c.specialised.executed_cost;
                    generic_i += c.generic.instructions;
                    specialised_i += c.specialised.instructions;
                }
            }
            assert!(
                (m.generic_cost - generic).abs() < 0.1
                    && (m.specialised_cost - specialised).abs() < 0.1
                    && m.generic_instructions == generic_i
                    && m.specialised_instructions == specialised_i,
                "{scene}: {m:?} against the committed model's {generic} → {specialised}, \
                 {generic_i} → {specialised_i} instructions"
            );
            assert!(m.specialised_cost < m.generic_cost, "{scene}: {m:?}");
            let saving = 100.0 * (1.0 - m.specialised_cost / m.generic_cost);
            assert!(
                (m.cost_saving_percent - saving).abs() < 0.1,
                "{scene}: {m:?}"
            );
        }
    }
    // The same build again: byte-identical.
    let path = out.join("character_left/character_left.scene.json");
    let bytes = std::fs::read(&path).unwrap();
    let o = build("character_left", &[]);
    assert!(o.status.success());
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
    // Without RADV (the loader's folders hold no radeon manifest): an error
    // naming the package, and the previous build left as it was.
    let empty = dir.path().join("no-icd");
    std::fs::create_dir_all(&empty).unwrap();
    let empty = empty.to_str().unwrap();
    let o = build(
        "character_left",
        &[
            ("XDG_CONFIG_HOME", empty),
            ("XDG_CONFIG_DIRS", empty),
            ("XDG_DATA_HOME", empty),
            ("XDG_DATA_DIRS", empty),
        ],
    );
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("mesa-vulkan-drivers"), "{stderr}");
    assert_eq!(std::fs::read(&path).unwrap(), bytes);
}
