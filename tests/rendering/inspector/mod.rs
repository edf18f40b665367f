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

mod environment;
mod export;
mod panel;

use base64::Engine;
use headless_chrome::{Browser, LaunchOptions, Tab};
use serde_json::{Value, json};
use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::{Duration, Instant};
use weft_render::{HdrImage, Tonemap};
use weft_serve::{ServeOptions, Server};
use weft_tests::repo;

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
