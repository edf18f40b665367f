//! `weft serve` in a real browser: headless Chromium (Debian's package,
//! WebGPU on SwiftShader, the flags `tint.rs` uses) driven over the DevTools
//! protocol by `headless_chrome`. The page is served by `weft_serve::Server`
//! in this process, exactly as `weft serve` serves it.
//!
//! - every shipped material's default render in the page matches `weft
//!   preview`'s (weft-render on lavapipe) within [`FLIP_BOUND`] (glints and
//!   fur, whose sparkles and strand edges move with the last bits of the
//!   maths, box-filtered: [`STOCHASTIC`]);
//! - moving a slider changes the picture (uniform rewritten, no pipeline
//!   swap), a keyword switches the variant (pipeline swapped), a preset
//!   applies, the Chinese switch changes labels;
//! - a TOML edit on disk reaches the page; a broken edit shows the CLI's
//!   diagnostic while the last good build stays; the fix clears it;
//! - the page's curve and gradient bakes equal `weft_meta::bake`'s bytes;
//! - moving the light moves the sky's sun too (the server's environment for
//!   that sun): the page matches `weft preview --light` within [`FLIP_BOUND`];
//! - a cube parameter takes an equirectangular panorama, converted to the
//!   engine's cube faces (`weft_render::cube_direction`) and bound.
//!
//! A missing browser or WebGPU adapter fails (never skips) with what to install.
//! Only the renders in this process (`preview`) take `weft_tests::gpu_serial`;
//! each page's Chromium runs beside the binary's other tests.

use base64::Engine;
use headless_chrome::{Browser, LaunchOptions, Tab};
use serde_json::{Value, json};
use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::{Duration, Instant};
use weft_render::{HdrImage, Tonemap};
use weft_serve::{ServeOptions, Server};
use weft_tests::{copy_dir, repo};

/// FLIP mean between the page's picture (Chromium's Tint on SwiftShader) and
/// `weft preview`'s (naga + lavapipe), 256×256 sphere, ACES, exposure 1.
/// Measured 0.0019 (velvet) to 0.0036 (gauze) on Chromium 156's SwiftShader
/// against Mesa's lavapipe; the bound is the goldens' threshold, about 3× that.
const FLIP_BOUND: f32 = 0.01;
const SIZE: u32 = 256;

/// Materials whose picture is a discontinuous function of float inputs:
/// glints gate each flake on a hashed cell and a random threshold, fur cuts
/// each strand out of each of its 20 blended shells with
/// `step(threshold, noise)`, so the last-bit differences between
/// SwiftShader's and llvmpipe's arithmetic and blending move single sparkles
/// and strand edges: full-resolution FLIP glitter 0.0147 (0.76 % of pixels
/// moved by more than 16/255), fur 0.0198 (0.25 %; 42 % of its pixels differ
/// by 1–4 levels through the layered blending). FLIP weighs such
/// pixel-sized changes heavily even after filtering (fur, 4×4: 0.0144), so
/// these are compared as the eye sees a sparkle or hair field: the images
/// box-filtered over [`STOCHASTIC_CELL`] pixels may differ by at most
/// [`STOCHASTIC_MEAN_LEVELS`] sRGB levels per channel on average (measured
/// 0.30 glitter, 0.34 fur), and at most [`STOCHASTIC_MOVED`] of the
/// full-resolution pixels may differ by more than 16 levels. A wrong
/// binding, uniform or lighting term shifts the filtered picture by many
/// levels and fails.
const STOCHASTIC: &[&str] = &["fur", "glitter"];
const STOCHASTIC_CELL: u32 = 4;
const STOCHASTIC_MEAN_LEVELS: f64 = 1.0;
const STOCHASTIC_MOVED: f64 = 0.01;

fn chromium() -> PathBuf {
    std::env::var_os("PATH")
        .and_then(|paths| {
            std::env::split_paths(&paths)
                .map(|p| p.join("chromium"))
                .find(|p| p.is_file())
        })
        .unwrap_or_else(|| {
            panic!(
                "`chromium` not found: the inspector tests need a real browser's WebGPU; \
                 install it with `apt-get install -y chromium` (see .ci/run)"
            )
        })
}

/// The inspector served from `materials` and open in a fresh headless Chromium.
struct Page {
    tab: Arc<Tab>,
    _browser: Browser,
    _profile: tempfile::TempDir,
    /// None for a static export served by [`serve_static`].
    server: Option<Server>,
}

impl Page {
    fn open(materials: &Path) -> Page {
        let server = Server::start(ServeOptions {
            reports: Some(repo().join("generated/reports")),
            ..ServeOptions::new(materials)
        })
        .expect("weft serve starts");
        let url = server.url();
        Page::open_url(&url, Some(server))
    }

    fn open_url(url: &str, server: Option<Server>) -> Page {
        let profile = tempfile::tempdir().unwrap();
        let args: Vec<&OsStr> = [
            "--disable-gpu-sandbox",
            "--disable-quic",
            "--no-first-run",
            "--no-default-browser-check",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--enable-unsafe-webgpu",
            "--enable-features=Vulkan",
            "--use-webgpu-adapter=swiftshader",
        ]
        .iter()
        .map(OsStr::new)
        .collect();
        let options = LaunchOptions::default_builder()
            .path(Some(chromium()))
            .headless(true)
            .sandbox(false)
            // headless_chrome adds --disable-gpu otherwise, which takes WebGPU's device away.
            .enable_gpu(true)
            .ignore_default_args(vec![OsStr::new(
                "--enable-features=NetworkService,NetworkServiceInProcess",
            )])
            .window_size(Some((1400, 1000)))
            .user_data_dir(Some(profile.path().to_path_buf()))
            .idle_browser_timeout(Duration::from_secs(600))
            .args(args)
            .build()
            .unwrap();
        let browser = Browser::new(options).unwrap_or_else(|e| {
            panic!(
                "cannot start headless chromium ({}): {e}",
                chromium().display()
            )
        });
        let tab = browser.new_tab().expect("a tab");
        tab.set_default_timeout(Duration::from_secs(180));
        tab.navigate_to(url)
            .and_then(|t| t.wait_until_navigated())
            .expect("the inspector loads");
        let page = Page {
            tab,
            _browser: browser,
            _profile: profile,
            server,
        };
        page.eval("window.weftInspector.ready");
        let status = page.eval("window.weftInspector.state.status");
        match status.as_str() {
            Some("ready") => {}
            Some("no-webgpu") => panic!(
                "WebGPU is unavailable in headless Chromium: {}; install Debian's `chromium` \
                 (SwiftShader ships with it) and `mesa-vulkan-drivers` (see .ci/run)",
                page.eval("window.weftInspector.state.webgpuError")
            ),
            _ => panic!(
                "the inspector did not start ({status}): {}",
                page.eval("window.weftInspector.state.error")
            ),
        }
        page
    }

    /// Evaluates an expression (awaited if it is a promise) in the page; its
    /// value comes back through JSON.
    fn eval(&self, expr: &str) -> Value {
        let wrapped = format!(
            "(async () => {{ try {{ return JSON.stringify({{ ok: (await ({expr})) ?? null }}); }} \
             catch (e) {{ return JSON.stringify({{ error: String((e && e.stack) || e) }}); }} }})()"
        );
        let result = self
            .tab
            .evaluate(&wrapped, true)
            .unwrap_or_else(|e| panic!("evaluating `{expr}`: {e}"));
        let text = result
            .value
            .and_then(|v| v.as_str().map(String::from))
            .unwrap_or_else(|| panic!("`{expr}` returned no value"));
        let mut v: Value = serde_json::from_str(&text).unwrap();
        if let Some(e) = v.get("error") {
            panic!(
                "`{expr}` threw in the page: {}",
                e.as_str().unwrap_or_default()
            );
        }
        v["ok"].take()
    }

    fn idle(&self) {
        self.eval("window.weftInspector.idle()");
    }

    fn select(&self, name: &str) {
        self.eval(&format!(
            "document.querySelector('[data-material=\"{name}\"]').click(), window.weftInspector.idle()"
        ));
        // The click starts the swap; wait for it and everything queued after.
        self.wait_for(&format!(
            "window.weftInspector.state.name === '{name}' && !!window.weftInspector.variantId()"
        ));
        self.idle();
    }

    /// The picture as weft-render would read it back: linear HDR, 256².
    fn capture(&self) -> HdrImage {
        let b64 = self.eval(&format!(
            "window.weftInspector.capture({SIZE}, {SIZE}, 'sphere')"
        ));
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(b64.as_str().unwrap())
            .unwrap();
        assert_eq!(bytes.len(), (SIZE * SIZE * 8) as usize);
        let pixels = bytes
            .chunks_exact(8)
            .map(|px| [0, 2, 4, 6].map(|i| half::f16::from_le_bytes([px[i], px[i + 1]]).to_f32()))
            .collect();
        HdrImage {
            width: SIZE,
            height: SIZE,
            pixels,
        }
    }

    /// Polls `condition` (a JS expression) until it is true.
    fn wait_for(&self, condition: &str) {
        let start = Instant::now();
        while start.elapsed() < Duration::from_secs(60) {
            if self.eval(condition) == json!(true) {
                return;
            }
            std::thread::sleep(Duration::from_millis(200));
        }
        panic!(
            "the page never satisfied `{condition}` within 60 s (status: {})",
            self.eval("{ error: window.weftInspector.state.error, preview: document.getElementById('preview-error').textContent }")
        );
    }
}

fn ldr(image: &HdrImage) -> Vec<u8> {
    image.to_srgb8(Tonemap::Aces, 1.0)
}

fn flip_mean(a: &HdrImage, b: &HdrImage) -> f32 {
    weft_golden::flip(&ldr(a), &ldr(b), a.width, a.height).mean
}

/// An sRGB8 image box-filtered over `cell` x `cell` pixels.
fn box_filtered(rgba: &[u8], width: u32, height: u32, cell: u32) -> Vec<u8> {
    let (w, h) = (width / cell, height / cell);
    let mut out = Vec::with_capacity((w * h * 4) as usize);
    for y in 0..h {
        for x in 0..w {
            let mut sum = [0u32; 4];
            for dy in 0..cell {
                for dx in 0..cell {
                    let i = (((y * cell + dy) * width + x * cell + dx) * 4) as usize;
                    for c in 0..4 {
                        sum[c] += u32::from(rgba[i + c]);
                    }
                }
            }
            out.extend(sum.map(|s| ((s + cell * cell / 2) / (cell * cell)) as u8));
        }
    }
    out
}

/// For a [`STOCHASTIC`] material: the mean absolute channel difference of
/// the box-filtered sRGB8 images (in levels) and the fraction of pixels that
/// moved visibly.
fn stochastic_difference(a: &HdrImage, b: &HdrImage) -> (f64, f64) {
    let (la, lb) = (ldr(a), ldr(b));
    let moved = la
        .chunks_exact(4)
        .zip(lb.chunks_exact(4))
        .filter(|(p, q)| (0..3).any(|c| p[c].abs_diff(q[c]) > 16))
        .count() as f64
        / f64::from(a.width * a.height);
    let cell = STOCHASTIC_CELL;
    let (fa, fb) = (
        box_filtered(&la, a.width, a.height, cell),
        box_filtered(&lb, b.width, b.height, cell),
    );
    let (sum, n) = fa
        .chunks_exact(4)
        .zip(fb.chunks_exact(4))
        .flat_map(|(p, q)| (0..3).map(move |c| f64::from(p[c].abs_diff(q[c]))))
        .fold((0.0, 0usize), |(s, n), d| (s + d, n + 1));
    (sum / n.max(1) as f64, moved)
}

/// `weft preview`'s image of `material`'s default variant (with `--light`
/// when `light` is given), drawn in this process: the only part of these
/// tests that needs the GPU lock (the page renders in Chromium's own
/// processes).
fn preview(material: &str, light: Option<[f32; 3]>) -> HdrImage {
    let _gpu = weft_tests::gpu_serial();
    let meta = repo().join(format!("generated/{material}/{material}.meta.json"));
    let m = weft_render::Material::load(&meta).unwrap();
    let luts = weft_render::Luts::for_metadata(&meta).unwrap();
    let options = weft_render::PreviewOptions {
        width: SIZE,
        height: SIZE,
        light_direction: light,
        ..Default::default()
    };
    weft_render::render_preview(&m, &luts, &options)
        .unwrap_or_else(|e| panic!("weft preview {material} (light {light:?}): {e}"))
        .0
}

fn save(image: &HdrImage, name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join("weft-inspector-test");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    image.save_png(&path, Tonemap::Aces, 1.0).unwrap();
    path
}

#[test]
fn default_render_matches_weft_preview_for_every_material() {
    let page = Page::open(&repo().join("materials"));
    let names: Vec<String> = page
        .server
        .as_ref()
        .unwrap()
        .status()
        .snapshot
        .unwrap()
        .materials
        .iter()
        .map(|m| m.metadata.name.clone())
        .collect();
    assert!(
        names.len() >= 6,
        "expected the shipped materials, got {names:?}"
    );
    let mut report = Vec::new();
    let mut failures = Vec::new();
    for name in &names {
        page.select(name);
        let variant = page.eval("window.weftInspector.variantId()");
        let browser = page.capture();
        let lavapipe = preview(name, None);
        let mean = flip_mean(&lavapipe, &browser);
        report.push(format!(
            "{name} ({}): FLIP mean {mean:.5}",
            variant.as_str().unwrap()
        ));
        if STOCHASTIC.contains(&name.as_str()) {
            let (levels, moved) = stochastic_difference(&lavapipe, &browser);
            report.push(format!(
                "  {name}: {STOCHASTIC_CELL}x{STOCHASTIC_CELL}-filtered mean difference {levels:.3} levels, {:.2} % of pixels moved",
                moved * 100.0
            ));
            if levels.is_nan() || levels > STOCHASTIC_MEAN_LEVELS || moved > STOCHASTIC_MOVED {
                failures.push(format!(
                    "{name}: filtered mean difference {levels:.3} levels (bound {STOCHASTIC_MEAN_LEVELS}), {:.2} % of pixels moved (bound {:.0} %) (page {}, weft preview {})",
                    moved * 100.0,
                    STOCHASTIC_MOVED * 100.0,
                    save(&browser, &format!("{name}.page.png")).display(),
                    save(&lavapipe, &format!("{name}.preview.png")).display()
                ));
            }
            continue;
        }
        if mean.is_nan() || mean > FLIP_BOUND {
            failures.push(format!(
                "{name}: FLIP mean {mean:.4} > {FLIP_BOUND} (page {}, weft preview {})",
                save(&browser, &format!("{name}.page.png")).display(),
                save(&lavapipe, &format!("{name}.preview.png")).display()
            ));
        }
    }
    eprintln!("page vs weft preview:\n  {}", report.join("\n  "));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

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

#[test]
fn export_is_deterministic_and_complete() {
    let a = tempfile::tempdir().unwrap();
    let b = tempfile::tempdir().unwrap();
    let options = ServeOptions {
        reports: Some(repo().join("generated/reports")),
        ..ServeOptions::new(repo().join("materials"))
    };
    let out_a = a.path().join("site");
    let out_b = b.path().join("site");
    let n = weft_serve::export(&options, &out_a).unwrap();
    weft_serve::export(&options, &out_b).unwrap();
    let list = |d: &Path| {
        let mut v = Vec::new();
        walk(d, d, &mut v);
        v.sort();
        v
    };
    let (fa, fb) = (list(&out_a), list(&out_b));
    // The exported files and the output marker every build folder carries.
    assert_eq!(fa.len(), n + 1);
    assert!(fa.iter().any(|(p, _)| p == ".weft-output"));
    assert_eq!(fa, fb, "two exports differ");
    for must in [
        "index.html",
        "app.js",
        "api/library.json",
        "api/environment.bin",
        "api/meshes/cloth.bin",
        "api/materials/standard.json",
        // standard's constant keywords (ALPHA_TEST, EMISSION) name each file set.
        "api/spirv/standard/fast.normal_map-off.sphere_map-off+alpha_test-off+emission-off.spv.txt",
    ] {
        assert!(
            fa.iter().any(|(p, _)| p == must),
            "{must} missing from the export"
        );
    }
    let lib: Value =
        serde_json::from_slice(&std::fs::read(out_a.join("api/library.json")).unwrap()).unwrap();
    assert_eq!(lib["live"], json!(false));
}

fn walk(root: &Path, dir: &Path, out: &mut Vec<(String, Vec<u8>)>) {
    for e in std::fs::read_dir(dir).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            walk(root, &p, out);
        } else {
            let rel = p
                .strip_prefix(root)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            out.push((rel, std::fs::read(&p).unwrap()));
        }
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

/// Serves the files under `root` on 127.0.0.1 (GET only), as any static
/// web server would; returns the port.
fn serve_static(root: PathBuf) -> u16 {
    use std::io::{BufRead, BufReader, Write};
    let listener = std::net::TcpListener::bind(("127.0.0.1", 0)).unwrap();
    let port = listener.local_addr().unwrap().port();
    std::thread::spawn(move || {
        for stream in listener.incoming().flatten() {
            let root = root.clone();
            std::thread::spawn(move || {
                let mut reader = BufReader::new(stream.try_clone().unwrap());
                let mut line = String::new();
                if reader.read_line(&mut line).is_err() {
                    return;
                }
                // Skip the headers.
                let mut h = String::new();
                while reader.read_line(&mut h).is_ok_and(|n| n > 2) {
                    h.clear();
                }
                let target = line.split_whitespace().nth(1).unwrap_or("/");
                let path = target
                    .split('?')
                    .next()
                    .unwrap_or("/")
                    .trim_start_matches('/');
                let path = if path.is_empty() || path.ends_with('/') {
                    format!("{path}index.html")
                } else {
                    path.to_string()
                };
                let file = root.join(&path);
                let (status, body) = match std::fs::read(&file) {
                    Ok(b) if !path.contains("..") => ("200 OK", b),
                    _ => ("404 Not Found", b"not found".to_vec()),
                };
                let ctype = match path.rsplit('.').next() {
                    Some("html") => "text/html; charset=utf-8",
                    Some("js") => "text/javascript",
                    Some("css") => "text/css",
                    Some("json") => "application/json",
                    _ => "application/octet-stream",
                };
                let mut s = stream;
                let _ = write!(
                    s,
                    "HTTP/1.1 {status}\r\nContent-Type: {ctype}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n",
                    body.len()
                );
                let _ = s.write_all(&body);
            });
        }
    });
    port
}

/// `weft serve --export`: the static files work without the server (no
/// event stream), under a sub-folder of a site.
#[test]
fn exported_inspector_works_from_a_static_server() {
    let site = tempfile::tempdir().unwrap();
    let options = ServeOptions {
        reports: Some(repo().join("generated/reports")),
        ..ServeOptions::new(repo().join("materials"))
    };
    weft_serve::export(&options, &site.path().join("docs/inspector")).unwrap();
    let port = serve_static(site.path().to_path_buf());
    let page = Page::open_url(&format!("http://127.0.0.1:{port}/docs/inspector/"), None);
    assert_eq!(
        page.eval("window.weftInspector.state.library.live"),
        json!(false)
    );
    page.select("velvet");
    let image = page.capture();
    // No server to compute another sky: the light moves alone, and the page says so.
    page.eval(
        "(() => { const f = document.querySelector('[data-light=\"azimuth\"] input[type=number]'); \
         f.value = '30'; f.dispatchEvent(new Event('change')); return window.weftInspector.idle(); })()",
    );
    assert_eq!(
        page.eval("document.getElementById('env-note').hidden"),
        json!(false)
    );
    assert_eq!(
        page.eval("document.getElementById('preview-error').hidden"),
        json!(true)
    );
    let lavapipe = preview("velvet", None);
    let mean = flip_mean(&lavapipe, &image);
    assert!(
        mean <= FLIP_BOUND,
        "exported page vs weft preview: FLIP mean {mean}"
    );
}

/// Moving the light moves the sky's sun too: the server computes the
/// environment (cube, SH) for the new sun and the page's picture matches
/// `weft preview --light` of the same direction.
#[test]
fn light_direction_moves_the_sun_and_matches_weft_preview() {
    let page = Page::open(&repo().join("materials"));
    page.select("standard");
    let default_light = page.capture();
    let set = |which: &str, degrees: i32| {
        page.eval(&format!(
            "(() => {{ const f = document.querySelector('[data-light=\"{which}\"] input[type=number]'); \
             f.value = '{degrees}'; f.dispatchEvent(new Event('change')); return window.weftInspector.idle(); }})()"
        ));
    };
    set("azimuth", 55);
    set("elevation", 40);
    page.idle();
    assert!(
        page.eval("window.weftInspector.state.envLoads").as_u64() >= Some(1),
        "the page did not fetch the environment for the new sun"
    );
    let light: Vec<f32> = page
        .eval("window.weftInspector.state.renderer.light.direction")
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap() as f32)
        .collect();
    let light: [f32; 3] = light.try_into().unwrap();
    let (a, e) = (55f32.to_radians(), 40f32.to_radians());
    let expected = [e.cos() * a.sin(), e.sin(), e.cos() * a.cos()];
    for i in 0..3 {
        assert!(
            (light[i] - expected[i]).abs() < 1e-5,
            "{light:?} vs {expected:?}"
        );
    }
    // The environment the page now binds has its sun there.
    let sun: Vec<f64> = page
        .eval("window.weftInspector.state.renderer.env.sky.sun_direction")
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    for i in 0..3 {
        assert!(
            (sun[i] - f64::from(expected[i])).abs() < 1e-5,
            "sky sun {sun:?}"
        );
    }
    let moved = page.capture();
    let lavapipe = preview("standard", Some(light));
    let lavapipe_default_sky = {
        // What the page drew before the sun followed the light: the light
        // moved, the sky's sun at the default (for the report only).
        let _gpu = weft_tests::gpu_serial();
        let meta = repo().join("generated/standard/standard.meta.json");
        let m = weft_render::Material::load(&meta).unwrap();
        let luts = weft_render::Luts::for_metadata(&meta).unwrap();
        let options = weft_render::PreviewOptions {
            width: SIZE,
            height: SIZE,
            light_direction: Some(light),
            ..Default::default()
        };
        let env =
            weft_render::EnvironmentMaps::sky(&weft_render::PreviewOptions::default().sky_params());
        let gpu = weft_render::Gpu::new().unwrap();
        let mut r = weft_render::Renderer::new(gpu, &env, &luts).unwrap();
        r.render(&m, &options.scene(), &options.render_options())
            .unwrap()
    };
    let mean = flip_mean(&lavapipe, &moved);
    let stale = flip_mean(&lavapipe, &lavapipe_default_sky);
    let change = flip_mean(&default_light, &moved);
    eprintln!(
        "standard, light {light:?}: page vs weft preview --light FLIP mean {mean:.5}; \
         default vs moved light in the page {change:.5}; \
         weft preview with the sky's sun left at the default vs moved {stale:.5}"
    );
    assert!(change > 0.01, "moving the light did not change the picture");

    // Dragging: many directions at once fetch one environment more (the
    // latest), which ends up bound.
    let loads = |p: &Page| {
        p.eval("window.weftInspector.state.envLoads")
            .as_u64()
            .unwrap()
    };
    let before = loads(&page);
    page.eval(
        "(() => { const s = document.querySelector('[data-light=\"azimuth\"] input[type=range]'); \
         for (const v of [300, 350, 400, 450, 500, 550, 600]) { s.value = v; s.dispatchEvent(new Event('input')); } \
         return window.weftInspector.idle(); })()",
    );
    let after = loads(&page);
    assert!(
        (before + 1..=before + 2).contains(&after),
        "seven light moves loaded {} environments",
        after - before
    );
    let agree = page.eval(
        "(() => { const r = window.weftInspector.state.renderer; const a = r.light.direction; \
         const n = Math.hypot(...a); const s = r.env.sky.sun_direction; \
         return Math.abs(a[0] / n - s[0]) + Math.abs(a[1] / n - s[1]) + Math.abs(a[2] / n - s[2]) < 1e-5; })()",
    );
    assert_eq!(
        agree,
        json!(true),
        "the bound sky's sun is the latest light direction"
    );
    assert!(
        mean <= FLIP_BOUND,
        "page vs weft preview --light {light:?}: FLIP mean {mean:.4} > {FLIP_BOUND} (page {}, weft preview {})",
        save(&moved, "standard.light.page.png").display(),
        save(&lavapipe, "standard.light.preview.png").display()
    );
}

/// An equirectangular panorama as the engine's cube faces, the page's
/// conversion restated: face texel (x, y) looks along
/// `weft_render::cube_direction`; the panorama's top row is +Y, its centre
/// column −Z, three quarters across +X; bilinear, wrapping in longitude.
fn equirect_to_cube(src: &[u8], w: usize, h: usize, size: usize, srgb: bool) -> Vec<u8> {
    let decode = |i: usize| {
        let c = f64::from(src[i]) / 255.0;
        if srgb && i % 4 != 3 {
            if c <= 0.04045 {
                c / 12.92
            } else {
                ((c + 0.055) / 1.055).powf(2.4)
            }
        } else {
            c
        }
    };
    let mut out = Vec::with_capacity(size * size * 24);
    for face in 0..6u32 {
        for y in 0..size {
            for x in 0..size {
                let u = (x as f64 + 0.5) / size as f64 * 2.0 - 1.0;
                let v = (y as f64 + 0.5) / size as f64 * 2.0 - 1.0;
                let d = weft_render::cube_direction(face, u, v);
                let eu = 0.5 + d[0].atan2(-d[2]) / (2.0 * std::f64::consts::PI);
                let ev = d[1].clamp(-1.0, 1.0).acos() / std::f64::consts::PI;
                let fx = eu * w as f64 - 0.5;
                let fy = (ev * h as f64 - 0.5).clamp(0.0, (h - 1) as f64);
                let (x0, y0) = (fx.floor(), fy.floor());
                let (tx, ty) = (fx - x0, fy - y0);
                let xa = (x0 as i64).rem_euclid(w as i64) as usize;
                let xb = (xa + 1) % w;
                let ya = y0 as usize;
                let yb = (ya + 1).min(h - 1);
                for c in 0..4 {
                    let at = |xx: usize, yy: usize| decode((yy * w + xx) * 4 + c);
                    let a = at(xa, ya) * (1.0 - tx) + at(xb, ya) * tx;
                    let b = at(xa, yb) * (1.0 - tx) + at(xb, yb) * tx;
                    let m = a * (1.0 - ty) + b * ty;
                    let e = if srgb && c != 3 {
                        if m <= 0.0031308 {
                            m * 12.92
                        } else {
                            1.055 * m.powf(1.0 / 2.4) - 0.055
                        }
                    } else {
                        m
                    };
                    out.push((e.clamp(0.0, 1.0) * 255.0).round() as u8);
                }
            }
        }
    }
    out
}

/// A `w`×`h` equirectangular panorama: black, white within `radius_deg`
/// of `towards` (the same mapping as [`equirect_to_cube`]).
fn spot_panorama(w: usize, h: usize, towards: [f64; 3], radius_deg: f64) -> Vec<u8> {
    let mut out = Vec::with_capacity(w * h * 4);
    for y in 0..h {
        for x in 0..w {
            let lon = ((x as f64 + 0.5) / w as f64 - 0.5) * 2.0 * std::f64::consts::PI;
            let colat = (y as f64 + 0.5) / h as f64 * std::f64::consts::PI;
            let d = [
                colat.sin() * lon.sin(),
                colat.cos(),
                -colat.sin() * lon.cos(),
            ];
            let c = d[0] * towards[0] + d[1] * towards[1] + d[2] * towards[2];
            let on = c >= radius_deg.to_radians().cos();
            out.extend_from_slice(&if on {
                [255, 255, 255, 255]
            } else {
                [0, 0, 0, 255]
            });
        }
    }
    out
}

/// Sums of the luminance change (b − a) over the left, right, top and
/// bottom halves of the picture.
fn halves(a: &HdrImage, b: &HdrImage) -> [f64; 4] {
    let mut s = [0f64; 4];
    let n = a.width as usize;
    for (i, (p, q)) in a.pixels.iter().zip(&b.pixels).enumerate() {
        let l = |c: &[f32; 4]| 0.2126 * c[0] as f64 + 0.7152 * c[1] as f64 + 0.0722 * c[2] as f64;
        let d = (l(q) - l(p)).max(0.0);
        let (x, y) = (i % n, i / n);
        s[if x < n / 2 { 0 } else { 1 }] += d;
        s[if y < n / 2 { 2 } else { 3 }] += d;
    }
    s
}

/// A cube parameter takes an equirectangular panorama: the page converts it
/// to the engine's six faces (checked texel for texel against
/// `weft_render::cube_direction`), binds it, and the picture changes where
/// the panorama's bright spot is reflected.
#[test]
fn cube_parameter_takes_an_equirectangular_panorama() {
    let page = Page::open(&repo().join("materials"));
    page.select("standard");
    page.eval(
        "(() => { const s = document.querySelector('[data-keyword=\"SPHERE_MAP\"] select'); \
         s.value = 'add'; s.dispatchEvent(new Event('change')); return window.weftInspector.idle(); })()",
    );
    assert_eq!(
        page.eval("window.weftInspector.variantId()"),
        json!("fast.normal_map-off.sphere_map-add")
    );
    let base = page.capture();
    let dir = tempfile::tempdir().unwrap();
    let (w, h) = (128usize, 64usize);
    let load = |name: &str, towards: [f64; 3]| -> Vec<u8> {
        let rgba = spot_panorama(w, h, towards, 25.0);
        let png = dir.path().join(name);
        std::fs::write(
            &png,
            weft_render::encode_png(w as u32, h as u32, &rgba).unwrap(),
        )
        .unwrap();
        page.tab
            .find_element("[data-param=\"sphere_map\"] input[type=file]")
            .and_then(|e| e.set_input_files(&[png.to_str().unwrap()]).map(|_| ()))
            .expect("the sphere map's file picker takes a file");
        page.wait_for(&format!(
            "document.querySelector('[data-param=\"sphere_map\"] .texname').textContent === '{name}' \
             && !!window.weftInspector.cubeFaces('sphere_map')"
        ));
        page.idle();
        rgba
    };
    let faces = |rgba: &[u8]| {
        let got = page.eval("window.weftInspector.cubeFaces('sphere_map')");
        let size = got["size"].as_u64().unwrap() as usize;
        assert_eq!(size, 32, "a 128-wide panorama gives 32² faces");
        assert_eq!(got["srgb"], json!(false), "sphere_map is linear data");
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(got["faces"].as_str().unwrap())
            .unwrap();
        let want = equirect_to_cube(rgba, w, h, size, false);
        assert_eq!(bytes.len(), want.len());
        let worst = bytes
            .iter()
            .zip(&want)
            .map(|(a, b)| a.abs_diff(*b))
            .max()
            .unwrap();
        assert!(
            worst <= 1,
            "the page's faces differ from the engine's by {worst}"
        );
    };

    // A bright spot towards +X: the sphere map is sampled by the view-space
    // reflection, so it shows on the right of the sphere.
    let spot_x = load("spot_x.png", [1.0, 0.0, 0.0]);
    faces(&spot_x);
    let right = page.capture();
    let [l, r, t, b] = halves(&base, &right);
    eprintln!("+X spot: brightening left {l:.2}, right {r:.2}, top {t:.2}, bottom {b:.2}");
    assert!(r > 20.0 && r > 20.0 * l, "+X spot: left {l}, right {r}");
    assert!(t < 2.0 * b && b < 2.0 * t, "+X spot: top {t}, bottom {b}");

    // A second panorama, the spot towards +Y: the top of the sphere instead.
    let spot_y = load("spot_y.png", [0.0, 1.0, 0.0]);
    faces(&spot_y);
    let top = page.capture();
    let [l, r, t, b] = halves(&base, &top);
    eprintln!("+Y spot: brightening left {l:.2}, right {r:.2}, top {t:.2}, bottom {b:.2}");
    assert!(t > 20.0 && t > 20.0 * b, "+Y spot: top {t}, bottom {b}");
    assert!(r < 2.0 * l && l < 2.0 * r, "+Y spot: left {l}, right {r}");
    assert!(
        flip_mean(&right, &top) > 0.01,
        "the second image did not change the picture"
    );

    // The sRGB path (a colour cube, rgba8unorm_srgb): filtered in linear.
    let ramp: Vec<u8> = (0..16 * 8)
        .flat_map(|i| [(i % 16 * 17) as u8, (i / 16 * 36) as u8, 200, 255])
        .collect();
    for srgb in [false, true] {
        let js: Vec<u8> = page
            .eval(&format!(
                "window.weftInspector.equirectToCube({}, 16, 8, 8, {srgb})",
                serde_json::to_string(&ramp).unwrap()
            ))
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap() as u8)
            .collect();
        let want = equirect_to_cube(&ramp, 16, 8, 8, srgb);
        let worst = js
            .iter()
            .zip(&want)
            .map(|(a, b)| a.abs_diff(*b))
            .max()
            .unwrap();
        assert!(
            worst <= 1,
            "srgb {srgb}: the page's faces differ by {worst}"
        );
    }
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
