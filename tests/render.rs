//! Render tests on lavapipe: every shipped material's cases (default variant
//! on sphere and cloth, every tier, every keyword value, every preset) drawn
//! from the committed `generated/` files and metadata alone, compared with
//! goldens under `tests/goldens/` by FLIP. `cargo xtask bless` rewrites them.
//!
//! With no Vulkan adapter these tests fail with what to install; they never skip.

use std::path::{Path, PathBuf};
use weft_golden::{
    Case, FLIP_MEAN_THRESHOLD, GOLDEN_SIZE, Harness, cases, flip, golden_path, materials, read_png,
    to_ldr, write_png,
};
use weft_render::ShaderLanguage;

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

fn harness(generated: &Path) -> Harness {
    Harness::new(generated).unwrap_or_else(|e| panic!("render tests need a Vulkan adapter: {e}"))
}

/// Compares one render with its golden; on failure writes `<golden>.actual.png`
/// and `<golden>.diff.png` (FLIP error map) next to it.
fn compare(goldens: &Path, case: &Case, ldr: &[u8], write_artifacts: bool) -> Result<f32, String> {
    let path = golden_path(goldens, case);
    let (w, h, golden) = read_png(&path).map_err(|e| {
        format!(
            "{}/{}: no golden ({e}); run `cargo xtask bless`",
            case.material, case.name
        )
    })?;
    if (w, h) != (GOLDEN_SIZE, GOLDEN_SIZE) {
        return Err(format!(
            "{}: golden is {w}x{h}, expected {GOLDEN_SIZE}; run `cargo xtask bless`",
            path.display()
        ));
    }
    let result = flip(&golden, ldr, w, h);
    println!(
        "{}/{}: FLIP mean {:.5}, p99 {:.4}",
        case.material, case.name, result.mean, result.p99
    );
    if result.mean <= FLIP_MEAN_THRESHOLD {
        return Ok(result.mean);
    }
    if write_artifacts {
        let actual = path.with_extension("actual.png");
        let diff = path.with_extension("diff.png");
        write_png(&actual, w, h, ldr).unwrap();
        let diff_rgba: Vec<u8> = result
            .error_map_rgb
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect();
        write_png(&diff, w, h, &diff_rgba).unwrap();
        return Err(format!(
            "{}/{}: FLIP mean {:.4} > {FLIP_MEAN_THRESHOLD} (p99 {:.3}); wrote {} and {}",
            case.material,
            case.name,
            result.mean,
            result.p99,
            actual.display(),
            diff.display()
        ));
    }
    Err(format!(
        "{}/{}: FLIP mean {:.4} > {FLIP_MEAN_THRESHOLD}",
        case.material, case.name, result.mean
    ))
}

#[test]
fn every_material_matches_its_goldens() {
    let generated = repo().join("generated");
    let goldens = repo().join("tests/goldens");
    let mut h = harness(&generated);
    println!("adapter: {}", h.adapter());
    let mut failures = Vec::new();
    let mut count = 0;
    for (meta_path, meta) in materials(&generated).unwrap() {
        for case in cases(&meta) {
            let image = h
                .render(&meta_path, &case, GOLDEN_SIZE, ShaderLanguage::Wgsl)
                .unwrap();
            assert_eq!(
                image.non_finite_count(),
                0,
                "{}/{}: NaN or Inf in the render",
                case.material,
                case.name
            );
            if let Err(e) = compare(&goldens, &case, &to_ldr(&image), true) {
                failures.push(e);
            }
            count += 1;
        }
    }
    assert!(
        count >= 9,
        "expected a case per tier, keyword value and preset, rendered {count}"
    );
    assert!(
        failures.is_empty(),
        "{} of {count} render cases differ from their goldens:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The WGSL and the SPIR-V of the same variant render the same image.
#[test]
fn wgsl_and_spirv_render_the_same_images() {
    let generated = repo().join("generated");
    let mut h = harness(&generated);
    for (meta_path, meta) in materials(&generated).unwrap() {
        for case in cases(&meta) {
            let a = to_ldr(
                &h.render(&meta_path, &case, GOLDEN_SIZE, ShaderLanguage::Wgsl)
                    .unwrap(),
            );
            let b = to_ldr(
                &h.render(&meta_path, &case, GOLDEN_SIZE, ShaderLanguage::SpirV)
                    .unwrap(),
            );
            let r = flip(&a, &b, GOLDEN_SIZE, GOLDEN_SIZE);
            assert!(
                r.mean <= 1e-3,
                "{}/{}: WGSL vs SPIR-V FLIP mean {:.5}",
                case.material,
                case.name,
                r.mean
            );
        }
    }
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let p = e.unwrap().path();
        let target = to.join(p.file_name().unwrap());
        if p.is_dir() {
            copy_dir(&p, &target);
        } else {
            std::fs::copy(&p, &target).unwrap();
        }
    }
}

/// The thresholds are tight enough to catch real shading bugs: each
/// perturbation, compiled and rendered like the real material, must fail
/// its golden, while the unperturbed copy passes.
#[test]
fn perturbed_shaders_fail_their_goldens() {
    let goldens = repo().join("tests/goldens");
    // (what, file, original text, replacement, case name)
    let perturbations = [
        ("unperturbed", "standard/standard.wgsl", "", "", "default"),
        (
            "missing 1/pi in Lambert",
            "lib/brdf.wgsl",
            "albedo * WEFT_INV_PI",
            "albedo",
            "default",
        ),
        (
            "wrong sign of N.L",
            "standard/standard.wgsl",
            "saturate(dot(n, l))",
            "saturate(dot(n, -l))",
            "default",
        ),
        (
            "swapped colour channels",
            "standard/standard.wgsl",
            // fs_main's last return (the low tier returns early with the
            // same expression, indented).
            "vec4<f32>(radiance, alpha);\n}",
            "vec4<f32>(radiance.bgr, alpha);\n}",
            "preset-plastic",
        ),
    ];
    let mut h: Option<Harness> = None;
    for (what, file, from, to, case_name) in perturbations {
        let tmp = tempfile::tempdir().unwrap();
        let root = tmp.path().join("materials");
        copy_dir(&repo().join("materials"), &root);
        if !from.is_empty() {
            let path = root.join(file);
            let text = std::fs::read_to_string(&path).unwrap();
            assert!(
                text.contains(from),
                "perturbation `{what}`: `{from}` not found in {file}"
            );
            // Every occurrence: a tier branch may repeat the line.
            std::fs::write(&path, text.replace(from, to)).unwrap();
        }
        let out = weft_compiler::build_library(&root, &Default::default(), &|_, _, _| {})
            .unwrap_or_else(|(db, d)| panic!("{what}: does not compile:\n{}", d.render_plain(&db)));
        let generated = tmp.path().join("generated");
        weft_compiler::output::write_atomically(&generated, &out.files, &[]).unwrap();
        let h = h.get_or_insert_with(|| harness(&generated));
        let meta_path = generated.join("standard/standard.meta.json");
        let meta = materials(&generated)
            .unwrap()
            .into_iter()
            .find(|(_, m)| m.name == "standard")
            .unwrap()
            .1;
        let case = cases(&meta)
            .into_iter()
            .find(|c| c.name == case_name)
            .unwrap();
        let image = h
            .render(&meta_path, &case, GOLDEN_SIZE, ShaderLanguage::Wgsl)
            .unwrap();
        let result = compare(&goldens, &case, &to_ldr(&image), false);
        match (what, result) {
            ("unperturbed", Ok(_)) => {}
            ("unperturbed", Err(e)) => panic!("the unperturbed copy must pass: {e}"),
            (_, Ok(mean)) => {
                panic!("perturbation `{what}` passed its golden (FLIP mean {mean:.5})")
            }
            (_, Err(e)) => println!("perturbation `{what}` fails as it must: {e}"),
        }
    }
}
