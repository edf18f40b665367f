//! The server: a `std::net` listener on 127.0.0.1 with one thread per
//! connection (at most [`Limits::max_connections`]; each connection within
//! the head caps and timeouts of [`crate::conn`]), the build-and-watch
//! thread, and the server-sent event stream (`api/events`) that tells open
//! pages about every build.

use crate::ServeOptions;
use crate::build::{BuildStatus, Builder};
use crate::conn::{Conn, Head, Limits, Request};
use crate::routes::{self, Assets, RouteError};
use crate::watch::Watcher;
use std::io::Write;
use std::net::{SocketAddr, TcpListener, TcpStream};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{Receiver, RecvTimeoutError, Sender, channel};
use std::sync::{Arc, Mutex, RwLock};
use std::thread::JoinHandle;
use std::time::Duration;

/// How often an idle event stream sends a comment, so a closed page is
/// noticed (the write fails) and proxies keep the connection.
const KEEPALIVE: Duration = Duration::from_secs(15);

struct Shared {
    status: RwLock<BuildStatus>,
    subscribers: Mutex<Vec<Sender<String>>>,
    assets: Assets,
    port: u16,
    limits: Limits,
}

impl Shared {
    fn status(&self) -> BuildStatus {
        match self.status.read() {
            Ok(s) => s.clone(),
            Err(poisoned) => poisoned.into_inner().clone(),
        }
    }

    fn publish(&self, status: BuildStatus) {
        let event = event_json(&status);
        match self.status.write() {
            Ok(mut s) => *s = status,
            Err(poisoned) => *poisoned.into_inner() = status,
        }
        if let Ok(mut subs) = self.subscribers.lock() {
            subs.retain(|tx| tx.send(event.clone()).is_ok());
        }
    }
}

fn event_json(status: &BuildStatus) -> String {
    serde_json::json!({
        "generation": status.generation,
        "ok": status.error.is_none(),
        "error": status.error,
        "build_ms": status.build_ms,
    })
    .to_string()
}

/// A running `weft serve`: the listener and the watcher run on their own
/// threads until [`Server::stop`] (or the drop of the server).
pub struct Server {
    shared: Arc<Shared>,
    addr: SocketAddr,
    stop: Arc<AtomicBool>,
    /// The accept loop and the watcher (which owns the build cache folder).
    threads: Mutex<Vec<JoinHandle<()>>>,
}

/// Kept for API symmetry with [`Server::start`]; the same as [`Server`].
pub type ServerHandle = Server;

impl Server {
    /// Builds the materials once, binds 127.0.0.1:`options.port` and starts
    /// serving and watching. Errors: the port cannot be bound, the folder
    /// does not exist.
    pub fn start(options: ServeOptions) -> Result<Server, String> {
        if !options.materials.is_dir() {
            return Err(format!(
                "`{}` is not a folder: `weft serve` takes a materials folder (one folder per material, `lib/` for shared WGSL)",
                options.materials.display()
            ));
        }
        let listener = TcpListener::bind(("127.0.0.1", options.port)).map_err(|e| {
            format!(
                "cannot listen on 127.0.0.1:{}: {e}{}",
                options.port,
                if options.port != 0 {
                    " (another program uses the port? try --port 0)"
                } else {
                    ""
                }
            )
        })?;
        let addr = listener
            .local_addr()
            .map_err(|e| format!("the server has no address: {e}"))?;
        // Watch from before the first build, so no edit falls between them.
        let watcher = Watcher::new(&options.materials);
        let mut builder = Builder::new(options.clone());
        let first = builder.build(None);
        let shared = Arc::new(Shared {
            status: RwLock::new(first),
            subscribers: Mutex::new(Vec::new()),
            assets: Assets::default(),
            port: addr.port(),
            limits: options.limits.clone(),
        });
        let stop = Arc::new(AtomicBool::new(false));
        let spawn = |name: &str, f: Box<dyn FnOnce() + Send>| {
            std::thread::Builder::new()
                .name(name.into())
                .spawn(f)
                .map_err(|e| format!("cannot start the {name} thread: {e}"))
        };
        let (s, st, quiet) = (shared.clone(), stop.clone(), options.quiet);
        let watch = spawn(
            "weft-serve watch",
            Box::new(move || watch_loop(watcher, builder, &s, &st, quiet)),
        )?;
        let (s, st) = (shared.clone(), stop.clone());
        let server = Server {
            shared: shared.clone(),
            addr,
            stop: stop.clone(),
            threads: Mutex::new(vec![watch]),
        };
        let accept = spawn(
            "weft-serve http",
            Box::new(move || accept_loop(listener, s, &st)),
        )?;
        if let Ok(mut t) = server.threads.lock() {
            t.push(accept);
        }
        // The environment prefilter takes a moment: start it now.
        let _ = spawn(
            "weft-serve environment",
            Box::new(move || {
                shared.assets.environment();
            }),
        );
        Ok(server)
    }

    pub fn port(&self) -> u16 {
        self.shared.port
    }

    /// `http://127.0.0.1:<port>/`
    pub fn url(&self) -> String {
        format!("http://127.0.0.1:{}/", self.shared.port)
    }

    /// The latest build's status.
    pub fn status(&self) -> BuildStatus {
        self.shared.status()
    }

    /// Stops: no new connection is accepted (the port is released), the
    /// watcher ends (a build in progress finishes first) and with it the
    /// build cache folder is removed, open event streams end. Connections
    /// being served finish within their timeouts. Returns once done; a
    /// second call does nothing.
    pub fn stop(&self) {
        if self.stop.swap(true, Ordering::SeqCst) {
            return;
        }
        // Wake the accept loop, blocked in accept().
        let _ = TcpStream::connect_timeout(&self.addr, Duration::from_secs(1));
        let threads = match self.threads.lock() {
            Ok(mut t) => std::mem::take(&mut *t),
            Err(poisoned) => std::mem::take(&mut *poisoned.into_inner()),
        };
        for t in threads {
            let _ = t.join();
        }
        if let Ok(mut subs) = self.shared.subscribers.lock() {
            subs.clear();
        }
    }
}

impl Drop for Server {
    fn drop(&mut self) {
        self.stop();
    }
}

/// Rebuilds on every change until `stop`; the builder (and its cache
/// folder) is dropped when it returns.
fn watch_loop(
    mut watcher: Watcher,
    mut builder: Builder,
    shared: &Shared,
    stop: &AtomicBool,
    quiet: bool,
) {
    while !stop.load(Ordering::SeqCst) {
        if !watcher.changed(stop) {
            continue;
        }
        let previous = shared.status();
        let status = builder.build(Some(&previous));
        if !quiet {
            match &status.error {
                None => eprintln!(
                    "weft serve: rebuilt in {} ms (generation {})",
                    status.build_ms, status.generation
                ),
                Some(e) => {
                    eprintln!(
                        "weft serve: the build failed; the page keeps the last good build\n{e}"
                    )
                }
            }
        }
        shared.publish(status);
    }
}

/// Counts a connection thread for as long as it lives.
struct Active(Arc<AtomicUsize>);

impl Drop for Active {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::SeqCst);
    }
}

/// Accepts until `stop`: a thread per connection while fewer than
/// `max_connections` are open, else an immediate 503.
fn accept_loop(listener: TcpListener, shared: Arc<Shared>, stop: &AtomicBool) {
    let active = Arc::new(AtomicUsize::new(0));
    for stream in listener.incoming() {
        if stop.load(Ordering::SeqCst) {
            return;
        }
        let Ok(stream) = stream else {
            // Out of file descriptors, say: let connections close first.
            std::thread::sleep(Duration::from_millis(20));
            continue;
        };
        let conn = Conn::new(stream, shared.limits.clone());
        if active.load(Ordering::SeqCst) >= shared.limits.max_connections {
            // Answered here without waiting on the client (no thread left).
            conn.refuse_at_once(503, "weft serve: too many open connections");
            continue;
        }
        active.fetch_add(1, Ordering::SeqCst);
        let guard = Active(active.clone());
        let shared = shared.clone();
        // A failed spawn drops the closure: the guard and the connection.
        let _ = std::thread::Builder::new()
            .name("weft-serve connection".into())
            .spawn(move || {
                let _guard = guard;
                serve_connection(conn, &shared);
            });
    }
}

/// Requests on one connection, until the client closes, stays idle past
/// the idle timeout, or a request ends the connection.
fn serve_connection(mut conn: Conn, shared: &Shared) {
    let mut first = true;
    loop {
        let request = match conn.next_request(first) {
            Head::Request(r) => r,
            Head::Closed => return,
            Head::Refuse(code, why) => {
                conn.respond_text(code, why, false, true);
                conn.linger_close();
                return;
            }
        };
        first = false;
        if path_and_query(&request.target).0 == "api/events" && request.method == "GET" {
            if check(&mut conn, &request, shared) {
                event_stream(conn, shared);
            }
            return;
        }
        if check(&mut conn, &request, shared) {
            answer(&mut conn, &request, shared);
        }
        if request.has_body {
            // Its body was not read: the connection cannot go on.
            conn.linger_close();
            return;
        }
        if !request.keep_alive {
            return;
        }
    }
}

/// Refuses (and returns false for) a request with no single Host naming
/// this server, a method other than GET and HEAD, a target not a path.
fn check(conn: &mut Conn, request: &Request, shared: &Shared) -> bool {
    let head_only = request.method == "HEAD";
    let close = !request.keep_alive;
    let refusal = if request.hosts.len() > 1 {
        // Proxies and servers disagree on which one counts.
        Some((400, "more than one Host header"))
    } else if !host_allowed(request.hosts.first(), shared.port) {
        Some((403, "weft serve answers requests for 127.0.0.1 only"))
    } else if !matches!(request.method.as_str(), "GET" | "HEAD") {
        let body = b"weft serve only answers GET and HEAD";
        let headers = [
            ("Content-Type", "text/plain; charset=utf-8"),
            ("Allow", "GET, HEAD"),
        ];
        let _ = conn.respond(405, &headers, body, head_only, close);
        return false;
    } else if !request.target.starts_with('/') {
        Some((400, "the request target must be a path (/…)"))
    } else {
        None
    };
    match refusal {
        Some((code, why)) => {
            conn.respond_text(code, why, head_only, close);
            false
        }
        None => true,
    }
}

/// The request's Host names this server on the loopback interface (a page
/// on another site reaching 127.0.0.1 through DNS rebinding does not).
/// Without a Host (HTTP/1.0 clients), allowed: browsers always send one.
fn host_allowed(host: Option<&String>, port: u16) -> bool {
    let Some(host) = host.map(|h| h.to_ascii_lowercase()) else {
        return true;
    };
    ["127.0.0.1", "localhost", "[::1]"]
        .iter()
        .any(|name| host == *name || host == format!("{name}:{port}"))
}

/// The target's path (no leading slash) and query (empty when none).
fn path_and_query(target: &str) -> (&str, &str) {
    let target = target.split('#').next().unwrap_or("");
    let (path, query) = target.split_once('?').unwrap_or((target, ""));
    (path.trim_start_matches('/'), query)
}

/// Answers a checked GET or HEAD from the routes.
fn answer(conn: &mut Conn, request: &Request, shared: &Shared) {
    let head_only = request.method == "HEAD";
    let close = !request.keep_alive;
    let (path, query) = path_and_query(&request.target);
    let status = shared.status();
    match routes::route(path, query, &status, &shared.assets, true) {
        Ok(reply) => {
            let generation = status.generation.to_string();
            let headers = [
                ("Content-Type", reply.content_type),
                ("Cache-Control", "no-store"),
                ("X-Weft-Generation", generation.as_str()),
            ];
            let _ = conn.respond(200, &headers, reply.body.bytes(), head_only, close);
        }
        Err(RouteError::BadRequest(why)) => conn.respond_text(400, &why, head_only, close),
        Err(RouteError::NotFound) => {
            conn.respond_text(404, &format!("not found: /{path}"), head_only, close)
        }
    }
}

/// `api/events`: `event: build` with the status of every build from now
/// on (the current one first), as server-sent events, until the page
/// closes or the server stops.
fn event_stream(conn: Conn, shared: &Shared) {
    let (tx, rx): (Sender<String>, Receiver<String>) = channel();
    let current = event_json(&shared.status());
    if let Ok(mut subs) = shared.subscribers.lock() {
        subs.push(tx);
    }
    let mut w = conn.stream;
    let head = "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\nConnection: close\r\nX-Accel-Buffering: no\r\n\r\nretry: 1000\n\n";
    let send = |w: &mut TcpStream, data: &str| -> std::io::Result<()> {
        w.write_all(format!("event: build\ndata: {data}\n\n").as_bytes())?;
        w.flush()
    };
    if w.write_all(head.as_bytes()).is_err() || send(&mut w, &current).is_err() {
        return;
    }
    loop {
        match rx.recv_timeout(KEEPALIVE) {
            Ok(event) => {
                if send(&mut w, &event).is_err() {
                    return;
                }
            }
            Err(RecvTimeoutError::Timeout) => {
                if w.write_all(b": keepalive\n\n")
                    .and_then(|_| w.flush())
                    .is_err()
                {
                    return;
                }
            }
            Err(RecvTimeoutError::Disconnected) => return,
        }
    }
}
