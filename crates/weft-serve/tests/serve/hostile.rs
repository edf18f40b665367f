//! `weft serve` under hostile clients (loopback only): oversized request
//! lines and headers, half-open and slow connections, idle keep-alive
//! connections, bursts, ambiguous `Host` headers, malformed queries, the
//! connection cap, and SIGINT/SIGTERM removing the build cache folder.
//! Timeouts are shortened through [`Limits`] so each test ends in seconds;
//! reads carry generous timeouts so a server that never answers fails the
//! test instead of hanging it.

use std::io::{Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::time::Duration;
use weft_serve::{Limits, ServeOptions, Server};
use weft_tests::copy_dir;

/// How long a test waits for an answer the server owes (the server's own
/// timeouts in these tests are 1 s).
const PATIENCE: Duration = Duration::from_secs(15);

fn fixture() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/fixtures/materials");
    copy_dir(&root, dir.path());
    dir
}

/// Limits with 1 s header and idle timeouts.
fn quick() -> Limits {
    Limits {
        header_timeout: Duration::from_secs(1),
        idle_timeout: Duration::from_secs(1),
        ..Limits::default()
    }
}

fn start(limits: Limits) -> (tempfile::TempDir, Server) {
    let dir = fixture();
    let server = Server::start(ServeOptions {
        limits,
        ..ServeOptions::new(dir.path())
    })
    .unwrap();
    (dir, server)
}

fn connect(port: u16) -> TcpStream {
    let s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(PATIENCE)).unwrap();
    s
}

/// Everything the server sends until it closes; panics if it does not
/// close within [`PATIENCE`].
fn until_closed(s: &mut TcpStream) -> String {
    let mut out = Vec::new();
    let mut chunk = [0u8; 4096];
    loop {
        match s.read(&mut chunk) {
            Ok(0) => break,
            Ok(n) => out.extend_from_slice(&chunk[..n]),
            Err(e) if e.kind() == std::io::ErrorKind::ConnectionReset => break,
            Err(e) => panic!(
                "the server kept the connection open ({e}); received {:?}",
                String::from_utf8_lossy(&out)
            ),
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// One response on a kept-alive connection: its head and body (by
/// Content-Length).
fn response(s: &mut TcpStream) -> (String, Vec<u8>) {
    let mut buf = Vec::new();
    let mut byte = [0u8; 1];
    while !buf.ends_with(b"\r\n\r\n") {
        match s.read(&mut byte) {
            Ok(1) => buf.push(byte[0]),
            other => panic!(
                "no complete response head ({other:?}); received {:?}",
                String::from_utf8_lossy(&buf)
            ),
        }
    }
    let head = String::from_utf8_lossy(&buf).into_owned();
    let len: usize = head
        .lines()
        .find_map(|l| l.strip_prefix("Content-Length: "))
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or_else(|| panic!("no Content-Length: {head}"));
    let mut body = vec![0u8; len];
    s.read_exact(&mut body).unwrap();
    (head, body)
}

fn get(port: u16, path: &str) -> String {
    let mut s = connect(port);
    write!(
        s,
        "GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n"
    )
    .unwrap();
    until_closed(&mut s)
}

/// Sends `head` then `filler` bytes of `fill` then `tail` from another
/// thread (the server may stop reading and close: write errors are
/// expected), and returns what the server answered.
fn oversized(port: u16, head: &str, fill: u8, filler: usize, tail: &str) -> String {
    let mut s = connect(port);
    let mut w = s.try_clone().unwrap();
    let (head, tail) = (head.to_string(), tail.to_string());
    let writer = std::thread::spawn(move || {
        let chunk = vec![fill; 64 << 10];
        let _ = w.write_all(head.as_bytes());
        let mut left = filler;
        while left > 0 {
            let n = left.min(chunk.len());
            if w.write_all(&chunk[..n]).is_err() {
                return;
            }
            left -= n;
        }
        let _ = w.write_all(tail.as_bytes());
        let _ = w.shutdown(std::net::Shutdown::Write);
    });
    let answer = until_closed(&mut s);
    writer.join().unwrap();
    answer
}

#[test]
fn an_oversized_request_line_is_refused_with_414() {
    let (_dir, server) = start(Limits::default());
    let port = server.port();
    // A 32 MiB request line, and a 1 MB number in `?sun=`.
    for (head, filler) in [
        ("GET /", 32 << 20),
        ("GET /api/environment.json?sun=1", 1 << 20),
    ] {
        let answer = oversized(
            port,
            head,
            b'1',
            filler,
            ",0,0 HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n",
        );
        assert!(answer.starts_with("HTTP/1.1 414 "), "{head}: {answer:.200}");
        assert!(answer.contains("request line too long"), "{answer:.200}");
    }
    assert!(get(port, "/api/library.json").starts_with("HTTP/1.1 200"));
}

#[test]
fn oversized_header_fields_are_refused_with_431() {
    let (_dir, server) = start(Limits::default());
    let port = server.port();
    let line = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n";
    // One 64 MiB header.
    let answer = oversized(port, &format!("{line}X-Big: "), b'a', 64 << 20, "\r\n\r\n");
    assert!(answer.starts_with("HTTP/1.1 431 "), "{answer:.200}");
    // 3 MiB of small headers.
    let many =
        "X-Small: aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa\r\n".repeat((3 << 20) / 60);
    let answer = oversized(port, &format!("{line}{many}"), b'\n', 0, "\r\n");
    assert!(answer.starts_with("HTTP/1.1 431 "), "{answer:.200}");
    assert!(get(port, "/api/library.json").starts_with("HTTP/1.1 200"));
}

#[test]
fn half_open_connections_are_closed_and_do_not_starve_service() {
    let (_dir, server) = start(quick());
    let port = server.port();
    // 64 connections: half send nothing, half an unfinished head.
    let mut half_open: Vec<(bool, TcpStream)> = (0..64)
        .map(|i| {
            let mut s = connect(port);
            let partial = i % 2 == 1;
            if partial {
                s.write_all(b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n")
                    .unwrap();
            }
            (partial, s)
        })
        .collect();
    // Served meanwhile.
    assert!(get(port, "/api/library.json").starts_with("HTTP/1.1 200"));
    // Each is ended by the server: 408 for an unfinished head, a plain
    // close for silence.
    for (partial, s) in &mut half_open {
        let answer = until_closed(s);
        if *partial {
            assert!(answer.starts_with("HTTP/1.1 408 "), "{answer}");
        } else {
            assert_eq!(answer, "");
        }
    }
}

#[test]
fn a_slowloris_head_is_cut_off_at_the_header_deadline() {
    let (_dir, server) = start(quick());
    let port = server.port();
    let mut s = connect(port);
    let mut w = s.try_clone().unwrap();
    // One header line every 50 ms, for at most 10 s (the server's header
    // deadline is 1 s).
    let writer = std::thread::spawn(move || {
        let _ = w.write_all(b"GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n");
        for _ in 0..200 {
            if w.write_all(b"X-Slow: a\r\n").is_err() {
                return true;
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        false
    });
    let answer = until_closed(&mut s);
    assert!(answer.starts_with("HTTP/1.1 408 "), "{answer}");
    drop(s);
    assert!(writer.join().unwrap(), "the server still read after 10 s");
}

#[test]
fn an_idle_keep_alive_connection_is_closed() {
    let (_dir, server) = start(quick());
    let port = server.port();
    let mut s = connect(port);
    s.write_all(b"GET /api/library.json HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n")
        .unwrap();
    let (head, _) = response(&mut s);
    assert!(head.starts_with("HTTP/1.1 200 "), "{head}");
    assert!(!head.contains("Connection: close"), "{head}");
    // Nothing more is sent: the server closes after its idle timeout.
    assert_eq!(until_closed(&mut s), "");
}

#[test]
fn a_burst_of_keep_alive_requests_is_answered() {
    let (_dir, server) = start(Limits::default());
    let port = server.port();
    let request = format!("GET /api/library.json HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n\r\n");
    // 50 connections at once, two requests each (the second on the kept
    // connection), then two pipelined in one write.
    let mut conns: Vec<TcpStream> = (0..50).map(|_| connect(port)).collect();
    for round in 0..2 {
        for s in &mut conns {
            s.set_read_timeout(Some(Duration::from_secs(4))).unwrap();
            s.write_all(request.as_bytes()).unwrap();
        }
        for (i, s) in conns.iter_mut().enumerate() {
            let (head, body) = response(s);
            assert!(head.starts_with("HTTP/1.1 200 "), "{round}/{i}: {head}");
            assert!(String::from_utf8_lossy(&body).contains("\"switches\""));
        }
    }
    let s = &mut conns[0];
    s.write_all(format!("{request}{request}").as_bytes())
        .unwrap();
    for _ in 0..2 {
        assert!(response(s).0.starts_with("HTTP/1.1 200 "));
    }
}

#[test]
fn two_host_headers_are_refused() {
    let (_dir, server) = start(Limits::default());
    let port = server.port();
    for hosts in [
        "Host: 127.0.0.1\r\nHost: evil.example\r\n",
        "Host: evil.example\r\nHost: 127.0.0.1\r\n",
        "Host: 127.0.0.1\r\nhost: 127.0.0.1\r\n",
    ] {
        let mut s = connect(port);
        write!(s, "GET / HTTP/1.1\r\n{hosts}Connection: close\r\n\r\n").unwrap();
        let answer = until_closed(&mut s);
        assert!(
            answer.starts_with("HTTP/1.1 400 "),
            "{hosts}: {answer:.200}"
        );
        assert!(answer.ends_with("more than one Host header"), "{answer}");
    }
    // A single foreign Host stays a 403, a single own Host a 200.
    let mut s = connect(port);
    s.write_all(b"GET / HTTP/1.1\r\nHost: evil.example\r\nConnection: close\r\n\r\n")
        .unwrap();
    assert!(until_closed(&mut s).starts_with("HTTP/1.1 403 "));
    assert!(get(port, "/").starts_with("HTTP/1.1 200 "));
}

#[test]
fn malformed_queries_are_answered_with_400() {
    let (_dir, server) = start(Limits::default());
    let port = server.port();
    // A 7000-digit number (within the request-line cap: a 1 MB one is a
    // 414, see above) that would parse to a finite value.
    let long = format!("sun=0.{}1,1,0", "0".repeat(7000));
    for (query, why) in [
        ("sun=1,0,0&sun=0,1,0", "more than once"),
        (long.as_str(), "longer than 64 characters"),
        ("sun=NaN,0,1", "not finite"),
        ("sun=junk", "not three numbers"),
        ("sun=%zz,0,0", "two hex digits"),
        ("sun=%ff%fe,0,0", "not UTF-8"),
    ] {
        for path in ["/api/environment.json", "/api/environment.bin"] {
            let answer = get(port, &format!("{path}?{query}"));
            assert!(
                answer.starts_with("HTTP/1.1 400 "),
                "{query}: {answer:.300}"
            );
            let body = answer.split_once("\r\n\r\n").unwrap().1;
            assert!(body.contains(why), "{query}: {body}");
            assert!(body.len() < 300, "a short message: {body}");
        }
    }
    // A malformed query is refused on every path.
    assert!(get(port, "/api/library.json?g=%").starts_with("HTTP/1.1 400 "));
    assert!(get(port, "/api/library.json?g=3").starts_with("HTTP/1.1 200 "));
}

#[test]
fn connections_past_the_cap_get_503_and_service_resumes() {
    let (_dir, server) = start(Limits {
        max_connections: 4,
        ..quick()
    });
    let port = server.port();
    let idle: Vec<TcpStream> = (0..4).map(|_| connect(port)).collect();
    // A fifth connection, sending nothing (so the answer cannot be lost to
    // a reset for unread data), is answered 503 once the four are counted.
    let refused = (0..50).any(|_| {
        let answer = until_closed(&mut connect(port));
        answer.starts_with("HTTP/1.1 503 ") || {
            std::thread::sleep(Duration::from_millis(20));
            false
        }
    });
    assert!(refused, "a fifth connection is refused while four are open");
    drop(idle);
    // Closed by the clients: served again. Until the server has noticed
    // the closes it may still refuse (and close before the request is
    // written: a broken pipe here is a refusal, tried again).
    let try_get = || {
        let mut s = connect(port);
        let request =
            format!("GET / HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nConnection: close\r\n\r\n");
        s.write_all(request.as_bytes()).ok()?;
        Some(until_closed(&mut s))
    };
    let served = (0..200).any(|_| {
        try_get().is_some_and(|a| a.starts_with("HTTP/1.1 200 ")) || {
            std::thread::sleep(Duration::from_millis(50));
            false
        }
    });
    assert!(served);
}

/// Where the child `weft serve` of [`signals_stop_the_server_and_remove_its_cache`]
/// runs: the test binary itself, started with this variable.
const CHILD: &str = "WEFT_SERVE_SIGNAL_CHILD";

#[test]
#[ignore = "the child process of signals_stop_the_server_and_remove_its_cache"]
fn signal_child() {
    if let Some(dir) = std::env::var_os(CHILD) {
        let options = ServeOptions {
            quiet: false,
            ..ServeOptions::new(dir)
        };
        weft_serve::serve(&options).unwrap();
    }
}

#[cfg(unix)]
#[test]
fn signals_stop_the_server_and_remove_its_cache() {
    use std::io::BufRead;
    use std::process::{Command, Stdio};
    let dir = fixture();
    for signal in ["INT", "TERM"] {
        let tmp = tempfile::tempdir().unwrap();
        let mut child = Command::new(std::env::current_exe().unwrap())
            .args([
                "--exact",
                "hostile::signal_child",
                "--ignored",
                "--nocapture",
            ])
            .env(CHILD, dir.path())
            .env("TMPDIR", tmp.path())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // The port, from "inspector at http://127.0.0.1:<port>/".
        let stderr = std::io::BufReader::new(child.stderr.take().unwrap());
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            for line in stderr.lines().map_while(Result::ok) {
                if let Some(rest) = line.split_once("http://127.0.0.1:") {
                    let port: String = rest.1.chars().take_while(char::is_ascii_digit).collect();
                    let _ = tx.send(port.parse::<u16>().ok());
                }
            }
        });
        let port = rx.recv_timeout(Duration::from_secs(60)).ok().flatten();
        let Some(port) = port else {
            let _ = child.kill();
            panic!("the child server did not start");
        };
        assert!(get(port, "/").starts_with("HTTP/1.1 200 "));
        let cache: Vec<_> = std::fs::read_dir(tmp.path()).unwrap().flatten().collect();
        assert_eq!(
            cache.len(),
            1,
            "the build cache folder exists while serving"
        );
        let killed = Command::new("sh")
            .args(["-c", &format!("kill -{signal} {}", child.id())])
            .status()
            .unwrap();
        assert!(killed.success());
        let mut status = None;
        for _ in 0..300 {
            status = child.try_wait().unwrap();
            if status.is_some() {
                break;
            }
            std::thread::sleep(Duration::from_millis(100));
        }
        let Some(status) = status else {
            let _ = child.kill();
            panic!("SIG{signal}: the server did not stop within 30 s");
        };
        assert!(status.success(), "SIG{signal}: {status}");
        let left: Vec<_> = std::fs::read_dir(tmp.path()).unwrap().flatten().collect();
        assert!(left.is_empty(), "SIG{signal} left {left:?}");
    }
}
