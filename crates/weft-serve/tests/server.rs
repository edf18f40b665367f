//! `weft serve` without a browser: the HTTP surface (127.0.0.1, Host check,
//! 404s, garbage requests), the watcher's rebuilds, and a failed build
//! keeping the last good one.

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::time::{Duration, Instant};
use weft_serve::{ServeOptions, Server};

fn fixture() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/fixtures/materials");
    copy_dir(&root, dir.path());
    dir
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap().flatten() {
        let p = e.path();
        if p.is_dir() {
            copy_dir(&p, &to.join(e.file_name()));
        } else {
            std::fs::copy(&p, to.join(e.file_name())).unwrap();
        }
    }
}

/// The raw response to `request` (sent as is).
fn raw(port: u16, request: &[u8]) -> String {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(20))).unwrap();
    s.write_all(request).unwrap();
    // The request ends here (a truncated one too).
    let _ = s.shutdown(std::net::Shutdown::Write);
    let mut out = Vec::new();
    let _ = s.read_to_end(&mut out);
    String::from_utf8_lossy(&out).into_owned()
}

fn get(port: u16, path: &str) -> String {
    raw(
        port,
        format!("GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n")
            .as_bytes(),
    )
}

#[test]
fn serves_the_page_and_refuses_what_it_should() {
    let dir = fixture();
    let server = Server::start(ServeOptions::new(dir.path())).unwrap();
    let port = server.port();
    assert!(get(port, "/").contains("<title>weft inspector</title>"));
    assert!(get(port, "/api/library.json").contains("\"switches\""));
    assert!(get(port, "/api/materials/switches.json").starts_with("HTTP/1.1 200"));
    for missing in [
        "/api/materials/nope.json",
        "/api/files/../../etc/passwd",
        "/api/files/%2e%2e/x",
        "/api/spirv/switches/x.wgsl.txt",
        "/api/meshes/teapot.bin",
    ] {
        assert!(get(port, missing).starts_with("HTTP/1.1 404"), "{missing}");
    }
    // Another site's page reaching 127.0.0.1 (DNS rebinding) is refused.
    let foreign = raw(
        port,
        b"GET / HTTP/1.1\r\nHost: evil.example:80\r\nConnection: close\r\n\r\n",
    );
    assert!(foreign.starts_with("HTTP/1.1 403"), "{foreign}");
    assert!(
        raw(
            port,
            b"POST / HTTP/1.1\r\nHost: localhost\r\nContent-Length: 0\r\n\r\n"
        )
        .starts_with("HTTP/1.1 405")
    );
    // Garbage does not take the server down.
    let _ = raw(port, b"\x00\xff\r\n\r\nnot http at all\r\n\r\n");
    let _ = raw(port, b"GET");
    assert!(get(port, "/api/library.json").starts_with("HTTP/1.1 200"));
}

#[test]
fn rebuilds_on_change_and_keeps_the_last_good_build() {
    let dir = fixture();
    let server = Server::start(ServeOptions::new(dir.path())).unwrap();
    let first = server.status();
    assert!(first.error.is_none(), "{:?}", first.error);
    let toml = dir.path().join("switches/switches.toml");
    let good = std::fs::read_to_string(&toml).unwrap();
    let wait = |pred: &dyn Fn(&weft_serve::BuildStatus) -> bool| {
        let start = Instant::now();
        while start.elapsed() < Duration::from_secs(60) {
            let s = server.status();
            if pred(&s) {
                return s;
            }
            std::thread::sleep(Duration::from_millis(100));
        }
        panic!("no rebuild within 60 s");
    };
    std::fs::write(
        &toml,
        format!("{good}\n[parameters.oops]\ntype = \"flaot\"\n"),
    )
    .unwrap();
    let broken = wait(&|s| s.generation > first.generation);
    let error = broken.error.expect("the broken edit fails");
    assert!(error.contains("switches.toml:"), "{error}");
    assert!(
        error.contains("error: 1 error found; nothing was written"),
        "{error}"
    );
    let kept = broken.snapshot.expect("the last good build is kept");
    assert!(kept.material("switches").is_some());
    std::fs::write(&toml, &good).unwrap();
    let fixed = wait(&|s| s.generation > broken.generation);
    assert!(fixed.error.is_none());
}
