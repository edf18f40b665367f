//! `weft serve` without a browser: the HTTP surface (127.0.0.1, Host check,
//! 404s, garbage requests), the watcher's rebuilds, and a failed build
//! keeping the last good one.

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::time::{Duration, Instant};
use weft_serve::{ServeOptions, Server};
use weft_tests::copy_dir;

fn fixture() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/fixtures/materials");
    copy_dir(&root, dir.path());
    dir
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

/// The body of a 200 response (after the blank line).
fn body(response: &str) -> &str {
    response.split_once("\r\n\r\n").map_or("", |(_, b)| b)
}

#[test]
fn environment_follows_a_requested_sun_and_refuses_bad_directions() {
    let dir = fixture();
    let server = Server::start(ServeOptions::new(dir.path())).unwrap();
    let port = server.port();
    for bad in [
        "sun=",
        "sun=1,2",
        "sun=1,2,3,4",
        "sun=0,0,0",
        "sun=nan,1,0",
        "sun=inf,0,0",
        "sun=1e400,0,0",
        "sun=x,y,z",
        "sun=1,,2",
        "sun=%00%ff,1,1",
        "g=3&sun=0,-0,0",
    ] {
        let r = get(port, &format!("/api/environment.json?{bad}"));
        assert!(r.starts_with("HTTP/1.1 400"), "{bad}: {r}");
        assert!(
            r.contains("bad sun direction") || r.contains("malformed query"),
            "{bad}: {r}"
        );
        let r = get(port, &format!("/api/environment.bin?{bad}"));
        assert!(r.starts_with("HTTP/1.1 400"), "{bad}: {r}");
    }
    // The server still answers after every refusal.
    assert!(get(port, "/api/library.json").starts_with("HTTP/1.1 200"));

    let json = |query: &str| -> serde_json::Value {
        let r = get(port, &format!("/api/environment.json{query}"));
        assert!(r.starts_with("HTTP/1.1 200"), "{query}: {r}");
        serde_json::from_str(body(&r)).unwrap()
    };
    let default = json("");
    let start = Instant::now();
    // Unnormalised, commas URL-encoded, huge components: normalised.
    let moved = json("?g=1&sun=0%2C2000%2C0");
    let first = start.elapsed();
    let dir_of = |v: &serde_json::Value, key: &str| -> Vec<f64> {
        v[key]["sun_direction"]
            .as_array()
            .or_else(|| v["light"]["direction"].as_array())
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    assert_eq!(dir_of(&moved, "sky"), vec![0.0, 1.0, 0.0]);
    assert_eq!(
        moved["light"]["direction"],
        serde_json::json!([0.0, 1.0, 0.0])
    );
    assert_ne!(moved["sh"], default["sh"], "the SH follows the sun");
    assert_eq!(moved["mips"], default["mips"], "the same layout");
    let huge = json("?sun=0,1e300,0");
    assert_eq!(huge["sh"], moved["sh"]);
    // Cached: the second request for a direction is immediate.
    let start = Instant::now();
    let again = json("?sun=0,1,0");
    let cached = start.elapsed();
    assert_eq!(again["sh"], moved["sh"]);
    assert!(cached < first, "cached {cached:?} vs first {first:?}");
    let bytes = |path: &str| -> Vec<u8> {
        let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
        s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
        write!(
            s,
            "GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n"
        )
        .unwrap();
        let mut out = Vec::new();
        let _ = s.read_to_end(&mut out);
        assert!(out.starts_with(b"HTTP/1.1 200"), "{path}");
        let at = out.windows(4).position(|w| w == b"\r\n\r\n").unwrap();
        out.split_off(at + 4)
    };
    let bin = bytes("/api/environment.bin?sun=0,1,0");
    let default_bin = bytes("/api/environment.bin");
    assert_eq!(bin.len(), default_bin.len());
    assert_ne!(bin, default_bin);
    eprintln!("environment for a new sun: {first:?}; cached: {cached:?}");
}

/// The tier panel's figures: a material's served metadata carries its
/// measurements and, apart, the GPU model's tier costs per family from the
/// reports folder's `gpu-model.json`, with the inputs hash of the files the
/// model costed (the page flags a material changed since); a material the
/// model lacks gets no `gpu_model`.
#[test]
fn served_metadata_carries_the_gpu_models_tier_costs() {
    let dir = fixture();
    let reports = dir.path().join("out/reports");
    std::fs::create_dir_all(&reports).unwrap();
    std::fs::create_dir_all(dir.path().join("out/switches")).unwrap();
    std::fs::write(
        dir.path().join("out/switches/switches.meta.json"),
        r#"{"inputs_hash": "costed-hash"}"#,
    )
    .unwrap();
    let fragment = r#"{"instructions": 300, "vgprs": 40, "waves": 24, "static_cost": 400.0, "executed_cost": 400.0, "unknown_loops": 0}"#;
    let family = |name: &str, ratio: f64| {
        format!(
            r#"{{"family": "{name}", "device_name": "Null hardware (RADV {name})", "driver_info": "Mesa 22.3.6",
                "tiers": [{{"material": "switches", "tier": "fast", "variant": "fast", "fragment": {fragment}, "executed_ratio": {ratio}}}],
                "variants": [], "scene_shaders": []}}"#
        )
    };
    std::fs::write(
        reports.join("gpu-model.json"),
        format!(
            r#"{{"command": "test", "families": [{}, {}]}}"#,
            family("navi21", 1.25),
            family("gfx1100", 1.5)
        ),
    )
    .unwrap();
    let options = weft_serve::ServeOptions {
        reports: Some(reports),
        ..ServeOptions::new(dir.path())
    };
    let server = Server::start(options).unwrap();
    let port = server.port();
    let meta: serde_json::Value =
        serde_json::from_str(body(&get(port, "/api/materials/switches.json"))).unwrap();
    let model = &meta["gpu_model"];
    assert_eq!(model["inputs_hash"], "costed-hash");
    let families = model["families"].as_array().unwrap();
    assert_eq!(families.len(), 2);
    assert_eq!(families[0]["family"], "navi21");
    assert_eq!(families[0]["tiers"][0]["tier"], "fast");
    assert_eq!(families[0]["tiers"][0]["executed_ratio"], 1.25);
    assert_eq!(families[0]["tiers"][0]["vgprs"], 40);
    assert_eq!(families[1]["tiers"][0]["executed_ratio"], 1.5);
    // The metadata itself is unchanged besides: its name and tiers as built.
    assert_eq!(meta["name"], "switches");
    let other: serde_json::Value =
        serde_json::from_str(body(&get(port, "/api/materials/imaged.json"))).unwrap();
    assert!(other.get("gpu_model").is_none(), "{other}");
}
