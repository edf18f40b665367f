//! The server: `tiny_http` on 127.0.0.1 (one thread per request, no async
//! runtime), the build-and-watch thread, and the server-sent event stream
//! (`api/events`) that tells open pages about every build.

use crate::ServeOptions;
use crate::build::{BuildStatus, Builder};
use crate::routes::{self, Assets, RouteError};
use crate::watch::Watcher;
use std::io::Write;
use std::sync::mpsc::{Receiver, RecvTimeoutError, Sender, channel};
use std::sync::{Arc, Mutex, RwLock};
use std::time::Duration;

/// How often an idle event stream sends a comment, so a closed page is
/// noticed (the write fails) and proxies keep the connection.
const KEEPALIVE: Duration = Duration::from_secs(15);

struct Shared {
    status: RwLock<BuildStatus>,
    subscribers: Mutex<Vec<Sender<String>>>,
    assets: Assets,
    port: u16,
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

/// A running `weft serve`: the HTTP server and the watcher run on their
/// own threads for as long as the process lives.
pub struct Server {
    shared: Arc<Shared>,
    http: Arc<tiny_http::Server>,
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
        let http = tiny_http::Server::http(("127.0.0.1", options.port)).map_err(|e| {
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
        let port = http
            .server_addr()
            .to_ip()
            .map(|a| a.port())
            .ok_or("the server has no IP address")?;
        // Watch from before the first build, so no edit falls between them.
        let mut watcher = Watcher::new(&options.materials);
        let mut builder = Builder::new(options.clone());
        let first = builder.build(None);
        let shared = Arc::new(Shared {
            status: RwLock::new(first),
            subscribers: Mutex::new(Vec::new()),
            assets: Assets::default(),
            port,
        });
        let quiet = options.quiet;
        {
            let shared = shared.clone();
            std::thread::Builder::new()
                .name("weft-serve watch".into())
                .spawn(move || {
                    loop {
                        if !watcher.changed() {
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
                                Some(e) => eprintln!(
                                    "weft serve: the build failed; the page keeps the last good build\n{e}"
                                ),
                            }
                        }
                        shared.publish(status);
                    }
                })
                .map_err(|e| format!("cannot start the watcher thread: {e}"))?;
        }
        let http = Arc::new(http);
        {
            let shared = shared.clone();
            let http = http.clone();
            std::thread::Builder::new()
                .name("weft-serve http".into())
                .spawn(move || {
                    for request in http.incoming_requests() {
                        let shared = shared.clone();
                        let _ = std::thread::Builder::new()
                            .name("weft-serve request".into())
                            .spawn(move || handle(request, &shared));
                    }
                })
                .map_err(|e| format!("cannot start the server thread: {e}"))?;
        }
        {
            // The environment prefilter takes a moment: start it now.
            let shared = shared.clone();
            let _ = std::thread::Builder::new()
                .name("weft-serve environment".into())
                .spawn(move || {
                    shared.assets.environment();
                });
        }
        Ok(Server { shared, http })
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

    /// Blocks for as long as the process runs.
    pub fn wait(&self) {
        loop {
            std::thread::park();
        }
    }

    /// Stops accepting requests (open event streams end with the process).
    pub fn stop(&self) {
        self.http.unblock();
    }
}

/// The request's Host names this server on the loopback interface (a page
/// on another site reaching 127.0.0.1 through DNS rebinding does not).
fn host_allowed(request: &tiny_http::Request, port: u16) -> bool {
    let Some(host) = request
        .headers()
        .iter()
        .find(|h| h.field.equiv("Host"))
        .map(|h| h.value.as_str().to_ascii_lowercase())
    else {
        return true;
    };
    ["127.0.0.1", "localhost", "[::1]"]
        .iter()
        .any(|name| host == *name || host == format!("{name}:{port}"))
}

fn handle(request: tiny_http::Request, shared: &Shared) {
    use tiny_http::{Header, Method, Response};
    let header = |k: &str, v: &str| Header::from_bytes(k.as_bytes(), v.as_bytes()).ok();
    let text = |code: u16, msg: &str| {
        Response::from_string(msg)
            .with_status_code(code)
            .with_header(header("Content-Type", "text/plain; charset=utf-8").unwrap())
    };
    if !host_allowed(&request, shared.port) {
        let _ = request.respond(text(403, "weft serve answers requests for 127.0.0.1 only"));
        return;
    }
    if !matches!(request.method(), Method::Get | Method::Head) {
        let _ = request.respond(text(405, "weft serve only answers GET"));
        return;
    }
    let url = request.url().to_string();
    let url = url.split('#').next().unwrap_or("");
    let (path, query) = url.split_once('?').unwrap_or((url, ""));
    let path = path.trim_start_matches('/');
    if path == "api/events" {
        event_stream(request, shared);
        return;
    }
    let status = shared.status();
    match routes::route(path, query, &status, &shared.assets, true) {
        Ok(reply) => {
            let mut response = Response::from_data(reply.body.bytes().to_vec())
                .with_header(header("Content-Type", reply.content_type).unwrap())
                .with_header(header("Cache-Control", "no-store").unwrap());
            if let Some(h) = header("X-Weft-Generation", &status.generation.to_string()) {
                response = response.with_header(h);
            }
            let _ = request.respond(response);
        }
        Err(RouteError::BadRequest(why)) => {
            let _ = request.respond(text(400, &why));
        }
        Err(RouteError::NotFound) => {
            let _ = request.respond(text(404, &format!("not found: /{path}")));
        }
    }
}

/// `api/events`: `event: build` with the status of every build from now
/// on (the current one first), as server-sent events.
fn event_stream(request: tiny_http::Request, shared: &Shared) {
    let (tx, rx): (Sender<String>, Receiver<String>) = channel();
    let current = event_json(&shared.status());
    if let Ok(mut subs) = shared.subscribers.lock() {
        subs.push(tx);
    }
    let mut w = request.into_writer();
    let head = "HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\nCache-Control: no-store\r\nConnection: close\r\nX-Accel-Buffering: no\r\n\r\nretry: 1000\n\n";
    let send = |w: &mut Box<dyn Write + Send>, data: &str| -> std::io::Result<()> {
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
