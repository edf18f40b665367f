//! `cargo xtask-screenshots inspector` (xtask's `screenshots` feature): screenshots of the live inspector (`weft serve`)
//! for the README — one material in English, one in Chinese — taken in
//! headless Chromium (WebGPU on SwiftShader, as tests/rendering/inspector/ runs it)
//! and written to docs/inspector/.

use headless_chrome::protocol::cdp::Page::CaptureScreenshotFormatOption;
use headless_chrome::{Browser, LaunchOptions, Tab};
use std::ffi::OsStr;
use std::path::Path;
use std::process::ExitCode;
use std::time::Duration;

/// (file, material, language, preset or "")
const SHOTS: &[(&str, &str, &str, &str)] = &[
    ("inspector-en.png", "standard", "en", "gold"),
    ("inspector-zh.png", "microcylinder", "zh", ""),
];

pub fn inspector(root: &Path) -> ExitCode {
    match run(root) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn eval(tab: &Tab, expr: &str) -> Result<serde_json::Value, String> {
    let wrapped = format!(
        "(async () => {{ try {{ return JSON.stringify({{ ok: (await ({expr})) ?? null }}); }} catch (e) {{ return JSON.stringify({{ error: String(e) }}); }} }})()"
    );
    let v = tab
        .evaluate(&wrapped, true)
        .map_err(|e| format!("`{expr}`: {e}"))?
        .value
        .and_then(|v| v.as_str().map(String::from))
        .ok_or_else(|| format!("`{expr}` returned nothing"))?;
    let mut v: serde_json::Value = serde_json::from_str(&v).map_err(|e| e.to_string())?;
    if let Some(e) = v.get("error") {
        return Err(format!("`{expr}` threw: {e}"));
    }
    Ok(v["ok"].take())
}

fn run(root: &Path) -> Result<(), String> {
    let chromium = which("chromium").ok_or(
        "`chromium` not found: install it with `apt-get install -y chromium` (see .ci/run)",
    )?;
    // Without a CJK font the Chinese screenshot is boxes; refuse rather
    // than commit it.
    let cjk = std::process::Command::new("fc-list")
        .arg(":lang=zh")
        .output()
        .map_err(|e| format!("`fc-list` (fontconfig): {e}"))?;
    if cjk.stdout.is_empty() {
        return Err(
            "no font covers Chinese: install one with `apt-get install -y fonts-noto-cjk`".into(),
        );
    }
    let server = weft_serve::Server::start(weft_serve::ServeOptions {
        reports: Some(root.join("generated/reports")),
        ..weft_serve::ServeOptions::new(root.join("materials"))
    })?;
    let profile = tempfile::tempdir().map_err(|e| e.to_string())?;
    let args: Vec<&OsStr> = [
        "--disable-gpu-sandbox",
        "--disable-quic",
        "--no-default-browser-check",
        "--enable-unsafe-webgpu",
        "--enable-features=Vulkan",
        "--use-webgpu-adapter=swiftshader",
        "--hide-scrollbars",
    ]
    .iter()
    .map(OsStr::new)
    .collect();
    let options = LaunchOptions::default_builder()
        .path(Some(chromium))
        .headless(true)
        .sandbox(false)
        .enable_gpu(true)
        .ignore_default_args(vec![OsStr::new(
            "--enable-features=NetworkService,NetworkServiceInProcess",
        )])
        .window_size(Some((1400, 1000)))
        .user_data_dir(Some(profile.path().to_path_buf()))
        .idle_browser_timeout(Duration::from_secs(300))
        .args(args)
        .build()
        .map_err(|e| e.to_string())?;
    let browser = Browser::new(options).map_err(|e| format!("cannot start chromium: {e}"))?;
    let tab = browser.new_tab().map_err(|e| e.to_string())?;
    tab.set_default_timeout(Duration::from_secs(180));
    tab.navigate_to(&server.url())
        .and_then(|t| t.wait_until_navigated())
        .map_err(|e| e.to_string())?;
    eval(&tab, "window.weftInspector.ready")?;
    let status = eval(&tab, "window.weftInspector.state.status")?;
    if status != "ready" {
        return Err(format!(
            "the inspector is not ready ({status}): {}",
            eval(
                &tab,
                "window.weftInspector.state.webgpuError || window.weftInspector.state.error"
            )?
        ));
    }
    let dir = root.join("docs/inspector");
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for (file, material, lang, preset) in SHOTS {
        eval(&tab, &format!("window.weftInspector.select('{material}')"))?;
        eval(&tab, &format!("window.weftInspector.setLanguage('{lang}')"))?;
        if !preset.is_empty() {
            eval(
                &tab,
                &format!("window.weftInspector.applyPreset('{preset}')"),
            )?;
        }
        eval(&tab, "window.weftInspector.idle()")?;
        let png = tab
            .capture_screenshot(CaptureScreenshotFormatOption::Png, None, None, true)
            .map_err(|e| e.to_string())?;
        let path = dir.join(file);
        std::fs::write(&path, png).map_err(|e| format!("{}: {e}", path.display()))?;
        eprintln!("inspector: wrote {}", path.display());
    }
    Ok(())
}

fn which(name: &str) -> Option<std::path::PathBuf> {
    std::env::split_paths(&std::env::var_os("PATH")?)
        .map(|p| p.join(name))
        .find(|p| p.is_file())
}
