//! `weft serve`: the live inspector.
//!
//! A local HTTP server (127.0.0.1 only) that builds a materials folder in
//! memory, serves a single-page inspector whose panel and WebGPU preview are
//! driven by the inspector metadata alone, watches the folder and pushes
//! every rebuild to open pages over server-sent events. A build that fails
//! keeps the last good build served and sends the diagnostics, rendered as
//! `weft build` prints them. `weft serve --export <dir>` writes the same
//! page and data as static files.
//!
//! - `build.rs`: the in-memory build and the snapshot the routes read;
//! - `assets.rs`: the engine data the page binds (environment cube and SH
//!   from `weft-render`, the built-in meshes and cameras);
//! - `routes.rs`: every path the page reads (shared by the server and
//!   the exporter, so both serve the same bytes);
//! - `watch.rs`: change detection over the materials folder;
//! - `http.rs`: the server (connection threads, Host and method checks)
//!   and the event stream;
//! - `conn.rs`: HTTP/1.1 on one connection, within the [`Limits`];
//! - `query.rs`: query strings, every malformed one refused;
//! - `signals.rs`: Ctrl-C and SIGTERM stop the server cleanly;
//! - `page/`: the page (HTML, CSS, ES modules), embedded at compile time.

mod assets;
mod build;
mod conn;
mod http;
mod query;
mod routes;
mod signals;
mod tier_costs;
mod watch;

pub use build::{BuildStatus, Snapshot};
pub use conn::Limits;
pub use http::{Server, ServerHandle};

use std::path::{Path, PathBuf};

/// What `weft serve` serves.
#[derive(Clone, Debug)]
pub struct ServeOptions {
    /// The materials folder (one folder per material, `lib/` for shared WGSL).
    pub materials: PathBuf,
    /// Where `<name>.measurements.json` reports and `gpu-model.json` are
    /// read from (tier costs and errors in the tier selector). None:
    /// `<materials>/../generated/reports`.
    pub reports: Option<PathBuf>,
    /// Port on 127.0.0.1; 0 picks a free one.
    pub port: u16,
    /// Print nothing but errors.
    pub quiet: bool,
    /// What one client may cost the server (head sizes, timeouts, open
    /// connections).
    pub limits: Limits,
}

impl ServeOptions {
    pub fn new(materials: impl Into<PathBuf>) -> ServeOptions {
        ServeOptions {
            materials: materials.into(),
            reports: None,
            port: 0,
            quiet: true,
            limits: Limits::default(),
        }
    }

    pub(crate) fn reports_dir(&self) -> PathBuf {
        self.reports.clone().unwrap_or_else(|| {
            let parent = self
                .materials
                .canonicalize()
                .ok()
                .and_then(|p| p.parent().map(Path::to_path_buf))
                .unwrap_or_else(|| PathBuf::from("."));
            parent.join("generated/reports")
        })
    }
}

/// Writes the inspector for `options.materials` as static files into `dir`
/// (replaced atomically, as `weft build` replaces its output). The bytes
/// depend only on the materials and reports. Returns how many files, or the
/// build's diagnostics as `weft build` prints them.
pub fn export(options: &ServeOptions, dir: &Path) -> Result<usize, String> {
    // Apart from the materials, like `weft build`'s output: checked before
    // the build, so a refused export writes nothing.
    let materials = weft_compiler::ownership::Input {
        what: "materials root",
        path: &options.materials,
    };
    weft_compiler::ownership::check_apart(dir, &[materials])
        .map_err(|e| format!("{e}; nothing was written"))?;
    let status = build::build_once(options);
    let snapshot = match (&status.error, &status.snapshot) {
        (None, Some(s)) => s.clone(),
        (Some(e), _) => return Err(e.clone()),
        (None, None) => return Err("the build produced nothing".into()),
    };
    let files = routes::export_files(&snapshot, &status);
    let n = files.len();
    weft_compiler::output::write_atomically(dir, &files, &[])
        .map_err(|e| format!("cannot write `{}`: {e}", dir.display()))?;
    Ok(n)
}

/// Runs `weft serve` until Ctrl-C or SIGTERM: builds, serves, watches;
/// then stops the server (the build cache folder is removed). A second
/// signal while stopping ends the process at once.
pub fn serve(options: &ServeOptions) -> Result<(), String> {
    // Before the first build, so a signal during it is not lost.
    let stop = signals::stop_flag()?;
    let server = Server::start(options.clone())?;
    if !options.quiet {
        eprintln!(
            "weft serve: inspector at {} (watching `{}`; Ctrl-C stops)",
            server.url(),
            options.materials.display()
        );
        if let Some(e) = server.status().error {
            eprintln!("{e}");
        }
    }
    while !stop.load(std::sync::atomic::Ordering::SeqCst) {
        std::thread::sleep(std::time::Duration::from_millis(100));
    }
    if !options.quiet {
        eprintln!("weft serve: stopping");
    }
    server.stop();
    Ok(())
}

/// `weft serve`'s examples (its `--help`).
pub const EXAMPLES: &str = "Examples:\n  weft serve                          inspector for materials/ at http://127.0.0.1:7878/\n  weft serve materials --port 0       any free port (printed)\n  weft serve --export site/inspector  the same page as static files (no live rebuilds)";

/// `weft serve`'s arguments.
#[derive(clap::Args, Clone, Debug)]
pub struct ServeArgs {
    /// The materials folder to build, serve and watch.
    #[arg(default_value = "materials")]
    pub materials: PathBuf,
    /// Port on 127.0.0.1 (0: any free port).
    #[arg(long, default_value_t = 7878)]
    pub port: u16,
    /// Write the inspector as static files into this folder (replaced atomically) and exit.
    #[arg(long, value_name = "DIR")]
    pub export: Option<PathBuf>,
    /// Folder of `<name>.measurements.json` reports and `gpu-model.json`
    /// for the tier selector (default: generated/reports beside the
    /// materials folder).
    #[arg(long, value_name = "DIR")]
    pub reports: Option<PathBuf>,
}

/// Runs `weft serve` as the CLI does.
pub fn command(args: &ServeArgs, quiet: bool) -> std::process::ExitCode {
    use std::process::ExitCode;
    let options = ServeOptions {
        materials: args.materials.clone(),
        reports: args.reports.clone(),
        port: args.port,
        quiet,
        limits: Limits::default(),
    };
    let result = match &args.export {
        Some(dir) => export(&options, dir).map(|n| {
            if !quiet {
                eprintln!(
                    "weft serve: wrote the inspector ({n} files) into `{}`; open index.html through any static web server",
                    dir.display()
                );
            }
        }),
        None => serve(&options),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{}", e.trim_end());
            if !e.starts_with("error") {
                eprintln!("error: weft serve stopped");
            }
            ExitCode::FAILURE
        }
    }
}
