//! `weft serve --export`: the static site, deterministic and complete, and
//! working from any static web server.

use super::{FLIP_BOUND, Page, flip_mean, preview};
use serde_json::{Value, json};
use std::path::{Path, PathBuf};
use weft_serve::ServeOptions;
use weft_tests::repo;

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
