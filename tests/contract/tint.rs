//! Every generated WGSL module compiles in a real browser's WebGPU (Chromium's
//! Tint, on SwiftShader), and every pass of every canonical variant makes a
//! render pipeline there from the metadata alone (explicit bind group layouts
//! from `bindings[]`, colour targets, blend, primitive and depth state from
//! `passes[]`, vertex buffers from `vertex_inputs`, each value of each
//! pipeline constant), so Tint checks the metadata against the shader. The project is built as `cargo
//! xtask regenerate` builds it, so the shipped scenes' specialised shaders
//! are checked too, each with the passes (render state) of the instances
//! drawn with it and its own vertex inputs.
//!
//! One headless Chromium loads a page served on 127.0.0.1 by a tiny HTTP
//! responder in this process; the page compiles everything, writes the
//! results into the DOM as JSON, and `--dump-dom` hands the DOM back.
//! A missing browser or a missing WebGPU adapter fails the test; it never skips.

use serde_json::{Value, json};
use std::io::{Read, Write};
use std::net::{TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};
use weft_tests::{repo, shaders};

use shaders::ShaderRef;
use weft_compiler::{BuildOptions, BuildOutput, build_library};

/// The browser process is killed after this long.
const BROWSER_TIMEOUT: Duration = Duration::from_secs(120);
/// Virtual time the page gets before Chromium dumps the DOM. Virtual time
/// runs ahead while the page only waits on the GPU process, so the page also
/// holds a fetch open until it has finished (see [`HOLD_TIMEOUT`]).
const VIRTUAL_TIME_BUDGET_MS: u32 = 5_000;

fn build_dir(dir: &Path) -> BuildOutput {
    match build_library(dir, &BuildOptions::default(), &|_, _, _| {}) {
        Ok(out) => out,
        Err((db, diags)) => panic!(
            "{} does not build:\n{}",
            dir.display(),
            diags.render_plain(&db)
        ),
    }
}

// ---------------------------------------------------------------------------
// What the page is asked to compile

/// The whole project (materials and scenes) as `cargo xtask regenerate` builds it.
fn build_project() -> BuildOutput {
    match weft_golden::project::build_project(&repo(), &BuildOptions::default()) {
        Ok(out) => out,
        Err((db, diags)) => panic!("the project does not build:\n{}", diags.render_plain(&db)),
    }
}

/// One WGSL module, named `<material>/<file>` or `scenes/<scene>/<file>`.
struct Module {
    name: String,
    code: String,
}

/// Everything the page checks: modules, then pipelines (descriptors as
/// WebGPU JSON, with `module` an index into `modules`).
#[derive(Default)]
struct Job {
    modules: Vec<Module>,
    pipelines: Vec<Value>,
}

impl Job {
    fn payload(&self) -> Vec<u8> {
        let modules: Vec<Value> = self
            .modules
            .iter()
            .map(|m| json!({ "name": m.name, "code": m.code }))
            .collect();
        serde_json::to_vec(&json!({ "modules": modules, "pipelines": self.pipelines })).unwrap()
    }
}

/// Bytes of a WebGPU vertex format.
fn vertex_format_size(format: &str) -> u64 {
    let (base, n) = match format.split_once('x') {
        Some((b, n)) => (b, n.parse::<u64>().unwrap()),
        None => (format, 1),
    };
    let bits: u64 = base
        .trim_start_matches(|c: char| c.is_ascii_alphabetic())
        .parse()
        .unwrap_or_else(|_| panic!("unknown vertex format `{format}`"));
    bits / 8 * n
}

/// A metadata enum value as WebGPU spells it: metadata names are WebGPU's
/// in snake_case (`one_minus_src_alpha` -> `one-minus-src-alpha`).
fn webgpu<T: serde::Serialize>(v: &T) -> Value {
    match serde_json::to_value(v).unwrap() {
        Value::String(s) => json!(s.replace('_', "-")),
        other => panic!("not a unit enum: {other}"),
    }
}

fn blend_component(c: &weft_meta::BlendComponent) -> Value {
    json!({
        "operation": webgpu(&c.operation),
        "srcFactor": webgpu(&c.src_factor),
        "dstFactor": webgpu(&c.dst_factor),
    })
}

/// The pass's colour targets, from the metadata alone.
fn color_targets(pass: &weft_meta::Pass) -> Vec<Value> {
    let mut targets = Vec::new();
    for t in &pass.color_targets {
        let mask: u32 = t
            .write_mask
            .iter()
            .map(|c| match c {
                weft_meta::ColorChannel::Red => 1,
                weft_meta::ColorChannel::Green => 2,
                weft_meta::ColorChannel::Blue => 4,
                weft_meta::ColorChannel::Alpha => 8,
            })
            .sum();
        let mut target = json!({ "format": t.format, "writeMask": mask });
        if let Some(b) = &t.blend {
            target["blend"] = json!({
                "color": blend_component(&b.color),
                "alpha": blend_component(&b.alpha),
            });
        }
        let i = t.location as usize;
        if targets.len() <= i {
            targets.resize(i + 1, Value::Null);
        }
        targets[i] = target;
    }
    targets
}

/// Explicit bind group layouts (one per group up to the highest used) from
/// the metadata's binding entries, so Tint checks them against the shader.
fn bind_group_layouts(shader: &weft_meta::VariantShader) -> Vec<Vec<Value>> {
    let groups = shader
        .bindings
        .iter()
        .map(|b| b.group + 1)
        .max()
        .unwrap_or(0);
    let mut layouts = vec![Vec::new(); groups as usize];
    for b in &shader.bindings {
        let visibility: u32 = b
            .stages
            .iter()
            .map(|s| match s {
                weft_meta::Stage::Vertex => 1,
                weft_meta::Stage::Fragment => 2,
                weft_meta::Stage::Compute => 4,
            })
            .sum();
        let mut entry = json!({ "binding": b.binding, "visibility": visibility });
        match (&b.buffer, &b.texture, &b.sampler) {
            (Some(buf), None, None) => {
                entry["buffer"] = json!({
                    "type": webgpu(&buf.ty),
                    "hasDynamicOffset": buf.has_dynamic_offset,
                    "minBindingSize": buf.min_binding_size,
                })
            }
            (None, Some(t), None) => {
                entry["texture"] = json!({
                    "sampleType": webgpu(&t.sample_type),
                    "viewDimension": webgpu(&t.view_dimension),
                    "multisampled": t.multisampled,
                })
            }
            (None, None, Some(smp)) => {
                entry["sampler"] = json!({ "type": webgpu(&smp.binding_type) })
            }
            _ => panic!(
                "binding {} must have exactly one of buffer/texture/sampler",
                b.name
            ),
        }
        layouts[b.group as usize].push(entry);
    }
    layouts
}

/// Every canonical WGSL module of a build and every scene shader in it, and
/// a pipeline per pass, shader and pipeline-constant value. Returns how many
/// scene shaders were added.
fn add_build(job: &mut Job, out: &BuildOutput) -> usize {
    let scenes = shaders::scenes(&out.files);
    let all = shaders::shaders(&out.materials, &scenes);
    for s in &all {
        add_shader(job, s, out);
    }
    all.iter().filter(|s| s.material.is_none()).count()
}

/// The shader's WGSL module(s), and a pipeline per pass and constant set.
fn add_shader(job: &mut Job, s: &ShaderRef, out: &BuildOutput) {
    let shader = s.shader;
    for file in &shader.files["wgsl"] {
        let name = s.file(&file.path);
        let code = String::from_utf8(
            out.files
                .get(&name)
                .unwrap_or_else(|| panic!("{name} is in the metadata but not in the build"))
                .clone(),
        )
        .unwrap();
        naga::front::wgsl::parse_str(&code)
            .unwrap_or_else(|e| panic!("naga cannot parse {name}: {}", e.emit_to_string(&code)));
        let index = job.modules.len();

        // Constant sets: all defaults, then each other value of each constant
        // (a library variant's keyword values; a scene draws its defaults).
        let mut constant_sets: Vec<(String, Value)> = vec![(String::new(), json!({}))];
        for c in &shader.pipeline_constants {
            let values: Vec<String> = match s
                .material
                .and_then(|m| m.keywords.iter().find(|k| k.name == c.name))
            {
                Some(k) => k.values.clone(),
                None if s.material.is_none() => continue,
                None if c.ty == "bool" => vec!["off".into(), "on".into()],
                None => panic!("{name}: pipeline constant {} names no keyword", c.name),
            };
            for (i, value) in values.iter().enumerate() {
                if *value == c.default {
                    continue;
                }
                // WebGPU constants are numbers: an enum's value index, a bool's 0/1.
                constant_sets.push((
                    format!(" {}={value}", c.name),
                    json!({ c.name.clone(): i as f64 }),
                ));
            }
        }

        let buffers: Vec<Value> = shader
            .vertex_inputs
            .iter()
            .map(|a| {
                json!({
                    "arrayStride": vertex_format_size(&a.format),
                    "attributes": [{ "shaderLocation": a.location, "offset": 0, "format": a.format }],
                })
            })
            .collect();
        let layouts = bind_group_layouts(shader);
        for pass in &s.passes {
            let targets = color_targets(pass);
            let primitive = json!({
                "topology": webgpu(&pass.primitive.topology),
                "frontFace": webgpu(&pass.primitive.front_face),
                "cullMode": webgpu(&pass.primitive.cull_mode),
            });
            let d = &pass.depth_stencil;
            let face = |f: &weft_meta::StencilFaceState| {
                json!({
                    "compare": webgpu(&f.compare),
                    "failOp": webgpu(&f.fail_op),
                    "depthFailOp": webgpu(&f.depth_fail_op),
                    "passOp": webgpu(&f.pass_op),
                })
            };
            let depth = json!({
                "format": webgpu(&d.format),
                "depthWriteEnabled": d.depth_write_enabled,
                "depthCompare": webgpu(&d.depth_compare),
                "stencilFront": face(&d.stencil_front),
                "stencilBack": face(&d.stencil_back),
                "stencilReadMask": d.stencil_read_mask,
                "stencilWriteMask": d.stencil_write_mask,
            });
            for (label, constants) in &constant_sets {
                job.pipelines.push(json!({
                    "name": format!("{name} pass `{}`{label}", pass.name),
                    "module": index,
                    "bindGroupLayouts": layouts,
                    "vertex": {
                        "entryPoint": pass.vertex_entry,
                        "buffers": buffers,
                        "constants": constants,
                    },
                    "fragment": {
                        "entryPoint": pass.fragment_entry,
                        "targets": targets,
                        "constants": constants,
                    },
                    "primitive": primitive,
                    "depthStencil": depth,
                }));
            }
        }
        job.modules.push(Module { name, code });
    }
}

// ---------------------------------------------------------------------------
// The page

const INDEX_HTML: &str = r#"<!doctype html>
<html><head><meta charset="utf-8"><title>weft tint check</title></head>
<body><pre id="weft-results">pending</pre><script src="/harness.js"></script></body></html>
"#;

/// Compiles the payload's modules and pipelines; writes
/// `{status, adapter, modules: [{name, messages}], pipelines: [{name, error}], uncaptured}`
/// into #weft-results. `status` is "done" only when everything was checked.
const HARNESS_JS: &str = r#"
(async () => {
  const out = document.getElementById('weft-results');
  const report = { status: 'started', adapter: null, modules: [], pipelines: [], uncaptured: [] };
  const write = () => { out.textContent = JSON.stringify(report); };
  // Keeps virtual time from running out while the GPU process works.
  fetch('/hold', { cache: 'no-store' }).catch(() => {});
  write();
  try {
    if (!navigator.gpu) throw { status: 'no-webgpu', detail: 'navigator.gpu is undefined (is the page a secure context, is --enable-unsafe-webgpu set?)' };
    const adapter = await navigator.gpu.requestAdapter();
    if (!adapter) throw { status: 'no-adapter', detail: 'navigator.gpu.requestAdapter() returned null' };
    const i = adapter.info || {};
    report.adapter = { vendor: i.vendor, architecture: i.architecture, device: i.device, description: i.description };
    const device = await adapter.requestDevice();
    device.addEventListener('uncapturederror', (e) => { report.uncaptured.push(String(e.error && e.error.message)); });
    const payload = await (await fetch('/payload.json', { cache: 'no-store' })).json();

    const modules = payload.modules.map((m) => device.createShaderModule({ code: m.code, label: m.name }));
    report.modules = await Promise.all(modules.map(async (mod, k) => {
      const info = await mod.getCompilationInfo();
      return {
        name: payload.modules[k].name,
        messages: info.messages.map((x) => ({ type: x.type, text: x.message, line: x.lineNum, column: x.linePos })),
      };
    }));

    report.pipelines = await Promise.all(payload.pipelines.map(async (p) => {
      const module = modules[p.module];
      // The pipeline layout comes from the metadata's binding entries alone.
      const layout = device.createPipelineLayout({
        bindGroupLayouts: p.bindGroupLayouts.map((entries) => device.createBindGroupLayout({ entries })),
      });
      const desc = {
        label: p.name,
        layout,
        vertex: Object.assign({}, p.vertex, { module }),
        fragment: Object.assign({}, p.fragment, { module }),
        primitive: p.primitive,
      };
      if (p.depthStencil) desc.depthStencil = p.depthStencil;
      try {
        await device.createRenderPipelineAsync(desc);
        return { name: p.name, error: null };
      } catch (e) {
        return { name: p.name, error: String((e && e.message) || e) };
      }
    }));
    report.status = 'done';
  } catch (e) {
    if (e && e.status) { report.status = e.status; report.detail = e.detail; }
    else { report.status = 'exception'; report.detail = String((e && e.stack) || e); }
  }
  write();
  fetch('/release', { cache: 'no-store' }).catch(() => {});
})();
"#;

// ---------------------------------------------------------------------------
// A tiny HTTP responder on 127.0.0.1

/// A request to `/hold` is answered when `/release` is requested (or after
/// [`HOLD_TIMEOUT`]): Chromium's virtual time does not advance while a fetch
/// is pending, so the page holds one open while it waits on the GPU process.
const HOLD_TIMEOUT: Duration = Duration::from_secs(90);

type Routes = Vec<(&'static str, &'static str, Vec<u8>)>;

struct Server {
    routes: Routes,
    released: Mutex<bool>,
    release: Condvar,
}

/// Serves `routes` (path, content type, body), `/hold` and `/release` on
/// 127.0.0.1 until the process exits; returns the port.
fn serve(routes: Routes) -> u16 {
    let listener = TcpListener::bind(("127.0.0.1", 0)).expect("bind 127.0.0.1:0");
    let port = listener.local_addr().unwrap().port();
    let server = Arc::new(Server {
        routes,
        released: Mutex::new(false),
        release: Condvar::new(),
    });
    std::thread::spawn(move || {
        for stream in listener.incoming() {
            let Ok(stream) = stream else { continue };
            let server = Arc::clone(&server);
            std::thread::spawn(move || {
                let _ = respond(stream, &server);
            });
        }
    });
    port
}

fn respond(mut stream: TcpStream, server: &Server) -> std::io::Result<()> {
    stream.set_read_timeout(Some(Duration::from_secs(30)))?;
    let mut head = Vec::new();
    let mut buf = [0u8; 4096];
    while !head.windows(4).any(|w| w == b"\r\n\r\n") {
        let n = stream.read(&mut buf)?;
        if n == 0 || head.len() > 64 * 1024 {
            return Ok(());
        }
        head.extend_from_slice(&buf[..n]);
    }
    let head = String::from_utf8_lossy(&head);
    let mut words = head.split_whitespace();
    let (method, target) = (words.next().unwrap_or(""), words.next().unwrap_or(""));
    let path = target.split('?').next().unwrap_or("");
    let (status, ctype, body): (&str, &str, &[u8]) = match path {
        "/hold" => {
            let released = server.released.lock().unwrap();
            let _ = server
                .release
                .wait_timeout_while(released, HOLD_TIMEOUT, |r| !*r)
                .unwrap();
            ("200 OK", "text/plain", b"released")
        }
        "/release" => {
            *server.released.lock().unwrap() = true;
            server.release.notify_all();
            ("200 OK", "text/plain", b"ok")
        }
        _ => match server.routes.iter().find(|(p, _, _)| *p == path) {
            Some((_, ctype, body)) if method == "GET" => ("200 OK", ctype, body),
            _ => ("404 Not Found", "text/plain", b"not found"),
        },
    };
    write!(
        stream,
        "HTTP/1.1 {status}\r\nContent-Type: {ctype}\r\nContent-Length: {}\r\nCache-Control: no-store\r\nConnection: close\r\n\r\n",
        body.len()
    )?;
    stream.write_all(body)?;
    stream.flush()
}

// ---------------------------------------------------------------------------
// The browser

fn chromium() -> PathBuf {
    let found = std::env::var_os("PATH").and_then(|paths| {
        std::env::split_paths(&paths)
            .map(|p| p.join("chromium"))
            .find(|p| p.is_file())
    });
    found.unwrap_or_else(|| {
        panic!(
            "`chromium` not found: the Tint check needs a real browser's WebGPU; \
             install it with `apt-get install -y chromium` (see .ci/run)"
        )
    })
}

/// Runs one headless Chromium on the page; returns the dumped DOM.
fn dump_dom(url: &str) -> String {
    let browser = chromium();
    let profile = tempfile::tempdir().unwrap();
    let mut child = Command::new(&browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu-sandbox",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--disable-quic",
            "--no-first-run",
            "--no-default-browser-check",
            "--enable-unsafe-webgpu",
            "--enable-features=Vulkan",
            "--use-webgpu-adapter=swiftshader",
        ])
        .arg(format!("--user-data-dir={}", profile.path().display()))
        .arg(format!("--virtual-time-budget={VIRTUAL_TIME_BUDGET_MS}"))
        .arg("--dump-dom")
        .arg(url)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start {}: {e}", browser.display()));
    let mut stdout = child.stdout.take().unwrap();
    let mut stderr = child.stderr.take().unwrap();
    let out = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stdout.read_to_string(&mut s);
        s
    });
    let err = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = stderr.read_to_string(&mut s);
        s
    });
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break Some(status);
        }
        if start.elapsed() > BROWSER_TIMEOUT {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let (stdout, stderr) = (out.join().unwrap(), err.join().unwrap());
    let tail = |s: &str| {
        let lines: Vec<&str> = s.lines().collect();
        lines[lines.len().saturating_sub(30)..].join("\n")
    };
    match status {
        None => panic!(
            "chromium did not finish within {BROWSER_TIMEOUT:?}; its stderr ends:\n{}",
            tail(&stderr)
        ),
        Some(s) if !s.success() => panic!(
            "chromium exited with {s}; its stderr ends:\n{}",
            tail(&stderr)
        ),
        Some(_) => {}
    }
    if stdout.trim().is_empty() {
        panic!(
            "chromium dumped no DOM; its stderr ends:\n{}",
            tail(&stderr)
        );
    }
    stdout
}

/// The page's report, from the dumped DOM.
fn report_from_dom(dom: &str) -> Value {
    const OPEN: &str = r#"<pre id="weft-results">"#;
    let start = dom
        .find(OPEN)
        .unwrap_or_else(|| panic!("no #weft-results in the dumped DOM:\n{dom}"))
        + OPEN.len();
    let len = dom[start..]
        .find("</pre>")
        .expect("unterminated #weft-results");
    // Text content as serialised HTML: only &, <, > and U+00A0 are escaped.
    let text = dom[start..start + len]
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&nbsp;", "\u{a0}")
        .replace("&amp;", "&");
    if text == "pending" {
        panic!("the page's script did not run (the DOM still says `pending`)");
    }
    let report: Value = serde_json::from_str(&text)
        .unwrap_or_else(|e| panic!("#weft-results is not JSON ({e}):\n{text}"));
    match report["status"].as_str() {
        Some("done") => report,
        Some("no-webgpu" | "no-adapter") => panic!(
            "WebGPU is unavailable in headless Chromium ({}): {}; the Tint check cannot run",
            report["status"], report["detail"]
        ),
        Some("started") => panic!(
            "the page did not finish (virtual time budget {VIRTUAL_TIME_BUDGET_MS} ms, hold {HOLD_TIMEOUT:?}): {report}"
        ),
        _ => panic!("the page failed: {}", report["detail"]),
    }
}

/// Serves the job's page, runs Chromium once, and returns its report.
fn check_in_browser(job: &Job) -> Value {
    let port = serve(vec![
        (
            "/",
            "text/html; charset=utf-8",
            INDEX_HTML.as_bytes().to_vec(),
        ),
        (
            "/harness.js",
            "text/javascript; charset=utf-8",
            HARNESS_JS.as_bytes().to_vec(),
        ),
        ("/payload.json", "application/json", job.payload()),
    ]);
    let report = report_from_dom(&dump_dom(&format!("http://127.0.0.1:{port}/")));
    let modules = report["modules"].as_array().unwrap();
    assert_eq!(
        modules.len(),
        job.modules.len(),
        "the page reported on {} of {} modules",
        modules.len(),
        job.modules.len()
    );
    assert_eq!(
        report["pipelines"].as_array().unwrap().len(),
        job.pipelines.len(),
        "the page reported on some pipelines only"
    );
    report
}

/// A message, with the source line it points at.
fn describe(job: &Job, module: &Value, msg: &Value) -> String {
    let name = module["name"].as_str().unwrap();
    let line = msg["line"].as_u64().unwrap_or(0);
    let source = job
        .modules
        .iter()
        .find(|m| m.name == name)
        .and_then(|m| m.code.lines().nth((line as usize).wrapping_sub(1)))
        .unwrap_or("");
    format!(
        "{name}:{line}:{}: {}: {}\n    | {}",
        msg["column"],
        msg["type"].as_str().unwrap_or("?"),
        msg["text"].as_str().unwrap_or("?"),
        source.trim()
    )
}

/// (errors, warnings) of every module and pipeline, and uncaptured device errors.
fn findings(job: &Job, report: &Value) -> (Vec<String>, Vec<String>) {
    let (mut errors, mut warnings) = (Vec::new(), Vec::new());
    for module in report["modules"].as_array().unwrap() {
        // Tint's notes ("info") explain the error or warning before them.
        let mut last_was_error = true;
        for msg in module["messages"].as_array().unwrap() {
            let text = describe(job, module, msg);
            match msg["type"].as_str() {
                Some("error") => {
                    errors.push(text);
                    last_was_error = true;
                }
                Some("warning") => {
                    warnings.push(text);
                    last_was_error = false;
                }
                _ => {
                    let list = if last_was_error {
                        &mut errors
                    } else {
                        &mut warnings
                    };
                    match list.last_mut() {
                        Some(prev) => prev.push_str(&format!("\n  {text}")),
                        None => list.push(text),
                    }
                }
            }
        }
    }
    for p in report["pipelines"].as_array().unwrap() {
        if let Some(e) = p["error"].as_str() {
            errors.push(format!("pipeline {}: {e}", p["name"].as_str().unwrap()));
        }
    }
    for e in report["uncaptured"].as_array().unwrap() {
        // Shader errors are already reported through getCompilationInfo.
        if !e
            .as_str()
            .unwrap_or("")
            .contains("Error while parsing WGSL")
        {
            errors.push(format!("uncaptured device error: {e}"));
        }
    }
    (errors, warnings)
}

// ---------------------------------------------------------------------------

#[test]
fn every_generated_wgsl_compiles_in_chromium_tint() {
    let mut job = Job::default();
    let scene_shaders = add_build(&mut job, &build_project());
    add_build(
        &mut job,
        &build_dir(&repo().join("tests/fixtures/materials")),
    );
    assert!(
        job.modules.len() >= 12,
        "expected a WGSL module per canonical variant, found {}",
        job.modules.len()
    );
    assert!(
        scene_shaders >= 2,
        "expected the shipped scenes' shaders, found {scene_shaders}"
    );
    let report = check_in_browser(&job);
    let (errors, warnings) = findings(&job, &report);
    assert!(
        errors.is_empty(),
        "Tint (Chromium WebGPU on {}) rejects generated WGSL:\n\n{}\n\nwarnings:\n{}",
        report["adapter"],
        errors.join("\n\n"),
        if warnings.is_empty() {
            "none".to_string()
        } else {
            warnings.join("\n\n")
        }
    );
    if !warnings.is_empty() {
        eprintln!("Tint warnings (allowed):\n{}", warnings.join("\n\n"));
    }
    eprintln!(
        "Tint accepted {} modules ({scene_shaders} of them scene shaders) and {} pipelines (adapter {})",
        job.modules.len(),
        job.pipelines.len(),
        report["adapter"]
    );
}

/// The harness reports what Tint rejects: a module whose function returns
/// the wrong type fails while a correct one beside it passes, and a pipeline
/// missing a vertex buffer the shader reads fails while the complete one passes.
#[test]
fn the_tint_harness_reports_broken_modules_and_pipelines() {
    const STAGES: &str = "@group(0) @binding(0) var<uniform> tint: vec4<f32>;\n@vertex fn vs(@location(0) p: vec3<f32>) -> @builtin(position) vec4<f32> {\n    return vec4<f32>(p, 1.0);\n}\n@fragment fn fs() -> @location(0) vec4<f32> {\n    return tint;\n}\n";
    let uniform_layout = |min_binding_size: u64| json!([[{ "binding": 0, "visibility": 2, "buffer": { "type": "uniform", "hasDynamicOffset": false, "minBindingSize": min_binding_size } }]]);
    let pipeline = |name: &str, buffers: Value, layouts: Value| {
        json!({
            "name": name,
            "module": 2,
            "bindGroupLayouts": layouts,
            "vertex": { "entryPoint": "vs", "buffers": buffers, "constants": {} },
            "fragment": { "entryPoint": "fs", "targets": [{ "format": "rgba16float" }], "constants": {} },
            "primitive": { "topology": "triangle-list", "cullMode": "back" },
            "depthStencil": { "format": "depth24plus-stencil8", "depthWriteEnabled": true, "depthCompare": "less-equal" },
        })
    };
    let job = Job {
        modules: vec![
            Module {
                name: "broken.wgsl".into(),
                code: "fn half(x: f32) -> f32 {\n    return vec2<f32>(x, x);\n}\n".into(),
            },
            Module {
                name: "fine.wgsl".into(),
                code: "fn half(x: f32) -> f32 {\n    return x * 0.5;\n}\n".into(),
            },
            Module {
                name: "stages.wgsl".into(),
                code: STAGES.into(),
            },
        ],
        pipelines: vec![
            pipeline(
                "complete",
                json!([{ "arrayStride": 12, "attributes": [{ "shaderLocation": 0, "offset": 0, "format": "float32x3" }] }]),
                uniform_layout(16),
            ),
            pipeline("no vertex buffer", json!([]), uniform_layout(16)),
            // A layout entry smaller than the shader's uniform: metadata that
            // disagrees with the shader is caught.
            pipeline(
                "layout too small",
                json!([{ "arrayStride": 12, "attributes": [{ "shaderLocation": 0, "offset": 0, "format": "float32x3" }] }]),
                uniform_layout(4),
            ),
        ],
    };
    let report = check_in_browser(&job);
    let (errors, _) = findings(&job, &report);
    assert_eq!(errors.len(), 3, "expected three errors, got {errors:#?}");
    assert!(
        errors[0].starts_with("broken.wgsl:2:")
            && errors[0].contains("return statement type must match its function return type"),
        "unexpected module error: {}",
        errors[0]
    );
    assert!(
        errors[1].starts_with("pipeline no vertex buffer:"),
        "unexpected pipeline error: {}",
        errors[1]
    );
    assert!(
        errors[2].starts_with("pipeline layout too small:"),
        "unexpected pipeline error: {}",
        errors[2]
    );
}
