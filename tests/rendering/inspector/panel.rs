//! The panel on the shipped materials and the fixtures: sliders, keywords,
//! presets, the Chinese switch, edits on disk, and the curve, gradient and
//! texture controls.

use super::{Page, SIZE, flip_mean, save};
use serde_json::json;
use weft_tests::{copy_dir, repo};

#[test]
fn panel_controls_drive_the_preview() {
    let page = Page::open(&repo().join("materials"));
    page.select("standard");
    let before = page.capture();
    let swaps = |p: &Page| {
        p.eval("window.weftInspector.state.pipelineSwaps")
            .as_u64()
            .unwrap()
    };
    let writes = |p: &Page| {
        p.eval("window.weftInspector.state.uniformWrites")
            .as_u64()
            .unwrap()
    };

    // Slider: rewrites the uniform only.
    let (s0, w0) = (swaps(&page), writes(&page));
    page.eval(
        "(() => { const s = document.querySelector('[data-param=\"roughness\"] input[type=range]'); \
         s.value = 1000; s.dispatchEvent(new Event('input')); return window.weftInspector.idle(); })()",
    );
    let rough = page.capture();
    assert!(
        flip_mean(&before, &rough) > 0.01,
        "moving the roughness slider to 1 did not change the picture"
    );
    assert_eq!(swaps(&page), s0, "a slider must not swap the pipeline");
    assert!(writes(&page) > w0, "a slider must rewrite the uniform");
    let bytes = page.eval("window.weftInspector.materialBytes()");
    let meta: weft_meta::MaterialMetadata = serde_json::from_slice(
        &std::fs::read(repo().join("generated/standard/standard.meta.json")).unwrap(),
    )
    .unwrap();
    let layout = meta.variants[0]
        .shader
        .as_ref()
        .unwrap()
        .material_uniform
        .clone()
        .unwrap();
    let member = layout
        .members
        .iter()
        .find(|m| m.name == "roughness")
        .unwrap();
    let o = member.offset as usize;
    let b: Vec<u8> = bytes.as_array().unwrap()[o..o + 4]
        .iter()
        .map(|x| x.as_u64().unwrap() as u8)
        .collect();
    assert_eq!(
        f32::from_le_bytes(b.try_into().unwrap()),
        1.0,
        "roughness at its offset"
    );

    // Keyword: an enum value switches to that variant (pipeline swapped).
    assert_eq!(
        page.eval("window.weftInspector.variantId()"),
        json!("fast.normal_map-off.sphere_map-off")
    );
    page.eval(
        "(() => { const s = document.querySelector('[data-keyword=\"SPHERE_MAP\"] select'); \
         s.value = 'multiply'; s.dispatchEvent(new Event('change')); return window.weftInspector.idle(); })()",
    );
    assert_eq!(
        page.eval("window.weftInspector.variantId()"),
        json!("fast.normal_map-off.sphere_map-multiply")
    );
    assert!(swaps(&page) > s0, "a keyword must swap the pipeline");
    // Its show_if'd parameters appear.
    assert_eq!(
        page.eval("document.querySelector('[data-param=\"sphere_strength\"]') ? document.querySelector('[data-param=\"sphere_strength\"]').hidden : 'absent'"),
        json!(false)
    );

    // Tier: swaps the variant too.
    page.eval(
        "(() => { const s = document.querySelector('[data-tier]'); s.value = 'reference'; \
         s.dispatchEvent(new Event('change')); return window.weftInspector.idle(); })()",
    );
    assert_eq!(
        page.eval("window.weftInspector.variantId()"),
        json!("reference.normal_map-off.sphere_map-multiply")
    );
    // The tier table: measured time and, in columns of their own, the GPU
    // model's cost per AMD family (generated/reports/gpu-model.json), where
    // standard `fast` is the baseline, 1.00.
    assert_eq!(
        page.eval(
            "[...document.querySelectorAll('#tier-panel table.tiers th')].map((h) => h.textContent).slice(1, 6)"
        ),
        json!(["ms measured", "× measured", "navi21 ×", "gfx1100 ×", "VGPRs / waves"])
    );
    assert_eq!(
        page.eval(
            "[...document.querySelectorAll('#tier-panel table.tiers tr')].find((r) => r.cells[0].textContent === 'fast').cells[3].textContent"
        ),
        json!("1.00")
    );

    // Preset: values, keywords and the controls follow.
    let plain = page.capture();
    page.eval(
        "document.querySelector('[data-preset=\"gold\"]').click(), window.weftInspector.idle()",
    );
    page.idle();
    assert_eq!(
        page.eval("window.weftInspector.state.values.metallic")
            .as_f64(),
        Some(1.0)
    );
    assert_eq!(
        page.eval("document.querySelector('[data-param=\"metallic\"] input[type=number]').value"),
        json!("1")
    );
    assert!(
        flip_mean(&plain, &page.capture()) > 0.01,
        "the gold preset did not change the picture"
    );

    // Chinese switch: labels and tooltips come from the metadata's zh text.
    let en = page.eval("document.querySelector('[data-param=\"roughness\"] .label').textContent");
    page.eval(
        "document.querySelector('[data-lang-switch=\"zh\"]').click(), window.weftInspector.idle()",
    );
    let zh = page.eval("document.querySelector('[data-param=\"roughness\"] .label').textContent");
    assert_eq!(en, json!("Roughness"));
    let zh_label = meta
        .parameters
        .iter()
        .find(|p| p.name == "roughness")
        .unwrap()
        .label
        .zh
        .clone();
    assert_eq!(zh.as_str(), zh_label.as_deref(), "the Chinese label");
    assert_eq!(
        page.eval("document.querySelector('[data-material=\"standard\"] .mname').textContent"),
        json!(meta.label.zh.clone().unwrap())
    );
}

#[test]
fn edits_on_disk_reach_the_page_and_broken_edits_show_their_diagnostic() {
    let dir = tempfile::tempdir().unwrap();
    copy_dir(&repo().join("materials"), dir.path());
    let page = Page::open(dir.path());
    page.select("standard");
    let toml = dir.path().join("standard/standard.toml");
    let original = std::fs::read_to_string(&toml).unwrap();

    // A label edit reaches the page.
    assert!(original.contains("\"Roughness\""));
    std::fs::write(
        &toml,
        original.replacen("\"Roughness\"", "\"Roughness (edited)\"", 1),
    )
    .unwrap();
    page.wait_for(
        "document.querySelector('[data-param=\"roughness\"] .label').textContent === 'Roughness (edited)'",
    );

    // A broken edit: the CLI's diagnostic, the last good build still shown.
    let broken = original.replacen("\"Roughness\"", "\"Roughness (edited)\"", 1)
        + "\n[parameters.oops]\ntype = \"flaot\"\n";
    std::fs::write(&toml, &broken).unwrap();
    page.wait_for("!document.getElementById('diagnostics').hidden");
    let shown = page.eval("document.getElementById('diagnostics-text').textContent");
    let shown = shown.as_str().unwrap();
    let cli = match weft_compiler::build_library(dir.path(), &Default::default(), &|_, _, _| {}) {
        Ok(_) => panic!("the broken edit builds"),
        Err((db, diags)) => diags.render_plain(&db),
    };
    assert!(
        shown.starts_with(&cli),
        "the page must show the CLI's diagnostic text:\n--- page ---\n{shown}\n--- cli ---\n{cli}"
    );
    assert!(shown.contains("standard.toml:"), "file:line in {shown}");
    assert_eq!(
        page.eval("document.querySelector('[data-param=\"roughness\"] .label').textContent"),
        json!("Roughness (edited)"),
        "the last good build stays visible"
    );
    assert!(page.capture().pixels.iter().any(|p| p[0] > 0.0));

    // Fixed: the banner goes.
    std::fs::write(&toml, &original).unwrap();
    page.wait_for(
        "document.getElementById('diagnostics').hidden && document.querySelector('[data-param=\"roughness\"] .label').textContent === 'Roughness'",
    );
}

#[test]
fn page_bakes_curves_and_gradients_byte_for_byte_like_weft_meta() {
    let page = Page::open(&repo().join("materials"));
    // A fixed pseudo-random set of curves and gradients, plus edge cases.
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for case in 0..40 {
        let n_keys = 1 + (rnd() * 5.0) as usize;
        let mut t = rnd() * 2.0 - 1.0;
        let keys: Vec<weft_meta::Keyframe> = (0..n_keys)
            .map(|_| {
                t += 0.01 + rnd();
                weft_meta::Keyframe {
                    time: t,
                    value: rnd() * 4.0 - 2.0,
                    in_slope: rnd() * 6.0 - 3.0,
                    out_slope: rnd() * 6.0 - 3.0,
                }
            })
            .collect();
        let samples = 1 + (rnd() * 64.0) as u32;
        let floats = samples.div_ceil(4) * 4;
        let rust: Vec<u8> = {
            let s = weft_meta::bake::sample_curve(&keys, samples);
            let mut out = vec![0u8; floats as usize * 4];
            for (i, v) in s.iter().enumerate() {
                out[i * 4..i * 4 + 4].copy_from_slice(&(*v as f32).to_le_bytes());
            }
            out
        };
        let js = page.eval(&format!(
            "window.weftInspector.bakeCurve({}, {samples}, {floats})",
            serde_json::to_string(&keys).unwrap()
        ));
        let js: Vec<u8> = js
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap() as u8)
            .collect();
        assert_eq!(js, rust, "curve case {case}: {keys:?}");

        let n_stops = 1 + (rnd() * 5.0) as usize;
        let mut stops: Vec<weft_meta::GradientStop> = (0..n_stops)
            .map(|_| weft_meta::GradientStop {
                position: if case % 7 == 0 { 0.5 } else { rnd() },
                color: [rnd(), rnd(), rnd(), rnd()],
            })
            .collect();
        stops.sort_by(|a, b| a.position.total_cmp(&b.position));
        let width = 1 + (rnd() * 300.0) as u32;
        let rust = weft_meta::bake::bake_gradient(&stops, width);
        let js = page.eval(&format!(
            "window.weftInspector.bakeGradient({}, {width})",
            serde_json::to_string(&stops).unwrap()
        ));
        let js: Vec<u8> = js
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap() as u8)
            .collect();
        assert_eq!(js, rust, "gradient case {case}: {stops:?} width {width}");
    }
}

/// The controls the shipped materials do not exercise, on the `switches`
/// fixture: a constant-mode keyword (same variant, pipeline constants
/// swapped), the gradient editor (ramp re-baked and re-uploaded), the curve
/// editor (uniform samples equal to the Rust bake) and a texture's
/// tiling/offset member.
#[test]
fn fixture_controls_constant_keyword_gradient_curve_and_tiling() {
    let page = Page::open(&repo().join("tests/fixtures/materials"));
    page.select("switches");
    let flat = page.capture();
    let variant = page.eval("window.weftInspector.variantId()");
    let swaps = |p: &Page| {
        p.eval("window.weftInspector.state.pipelineSwaps")
            .as_u64()
            .unwrap()
    };
    let s0 = swaps(&page);

    // Constant keyword: the same variant, new pipeline constants.
    page.eval(
        "(() => { const s = document.querySelector('[data-keyword=\"STYLE\"] select'); \
         s.value = 'ramp'; s.dispatchEvent(new Event('change')); return window.weftInspector.idle(); })()",
    );
    assert_eq!(page.eval("window.weftInspector.variantId()"), variant);
    assert!(
        swaps(&page) > s0,
        "a constant keyword must swap the pipeline"
    );
    let ramp = page.capture();
    assert!(
        flip_mean(&flat, &ramp) > 0.01,
        "STYLE = ramp did not change the picture"
    );

    // Gradient: the first stop turned green re-bakes the ramp.
    page.eval(
        "(() => { const c = document.querySelector('[data-param=\"ramp\"] .stop input[type=color]'); \
         c.value = '#00ff00'; c.dispatchEvent(new Event('input')); return window.weftInspector.idle(); })()",
    );
    assert!(
        flip_mean(&ramp, &page.capture()) > 0.01,
        "editing a gradient stop did not change the picture"
    );

    // Curve: the uniform holds the Rust bake of the edited keys.
    page.eval(
        "(() => { \
         const rows = document.querySelectorAll('[data-param=\"falloff\"] .keyrow'); \
         const v = rows[0].querySelectorAll('input')[1]; v.value = '0.5'; v.dispatchEvent(new Event('change')); \
         return window.weftInspector.idle(); })()",
    );
    let status = page.server.as_ref().unwrap().status();
    let snapshot = status.snapshot.unwrap();
    let meta = &snapshot.material("switches").unwrap().metadata;
    let p = meta
        .parameters
        .iter()
        .find(|p| p.name == "falloff")
        .unwrap();
    let curve = p.curve.as_ref().unwrap();
    let mut keys = curve.keyframes.clone();
    keys[0].value = 0.5;
    let samples = weft_meta::bake::sample_curve(&keys, curve.samples);
    let layout = meta
        .resolve_variant(variant.as_str().unwrap())
        .unwrap()
        .shader
        .as_ref()
        .unwrap()
        .material_uniform
        .clone()
        .unwrap();
    let bytes: Vec<u8> = page
        .eval("window.weftInspector.materialBytes()")
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_u64().unwrap() as u8)
        .collect();
    let m = layout.members.iter().find(|m| m.name == "falloff").unwrap();
    for (i, s) in samples.iter().enumerate() {
        let o = m.offset as usize + i * 4;
        assert_eq!(
            bytes[o..o + 4],
            (*s as f32).to_le_bytes(),
            "curve sample {i} in the uniform"
        );
    }

    // Tiling/offset of a texture slot: its member in the uniform.
    page.eval(
        "(() => { const f = document.querySelectorAll('[data-param=\"mask\"] .vector input')[0]; \
         f.value = '3'; f.dispatchEvent(new Event('change')); return window.weftInspector.idle(); })()",
    );
    let bytes: Vec<u8> = page
        .eval("window.weftInspector.materialBytes()")
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_u64().unwrap() as u8)
        .collect();
    let st = layout.members.iter().find(|m| m.name == "mask_st").unwrap();
    let o = st.offset as usize;
    assert_eq!(bytes[o..o + 4], 3.0f32.to_le_bytes(), "mask tiling x");

    // The file picker: the user's own image replaces the built-in default.
    let before = page.capture();
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("black.png");
    std::fs::write(
        &png,
        weft_render::encode_png(4, 4, &[0, 0, 0, 255].repeat(16)).unwrap(),
    )
    .unwrap();
    page.tab
        .find_element("[data-param=\"mask\"] input[type=file]")
        .and_then(|e| e.set_input_files(&[png.to_str().unwrap()]).map(|_| ()))
        .expect("the mask's file picker takes a file");
    page.wait_for(
        "document.querySelector('[data-param=\"mask\"] .texname').textContent === 'black.png'",
    );
    page.idle();
    assert!(
        flip_mean(&before, &page.capture()) > 0.01,
        "a black mask image did not change the picture"
    );
}

/// The `imaged` fixture ships an image (`texture.file`: red top-left, green
/// top-right, blue bottom-left, white bottom-right) mapped over the screen:
/// the page fetches the file and binds it while the parameter is unset, the
/// right way up, not the built-in black default.
#[test]
fn fixture_texture_file_is_fetched_and_bound_the_right_way_up() {
    let page = Page::open(&repo().join("tests/fixtures/materials"));
    page.select("imaged");
    let img = page.capture();
    let (a, b) = (SIZE * 7 / 20, SIZE * 13 / 20);
    let want = [
        ((a, a), [1.0, 0.0, 0.0]),
        ((b, a), [0.0, 1.0, 0.0]),
        ((a, b), [0.0, 0.0, 1.0]),
        ((b, b), [1.0, 1.0, 1.0]),
    ];
    for ((x, y), w) in want {
        let p = img.pixel(x, y);
        assert!(
            (0..3).all(|i| (p[i] - w[i]).abs() < 0.02),
            "({x}, {y}) is {p:?}, expected {w:?} (page {})",
            save(&img, "imaged.page.png").display()
        );
    }
}
