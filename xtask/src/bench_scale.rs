//! `cargo xtask bench scale`: builds synthetic libraries of growing size
//! (see `scale.rs`) with the release `weft` binary as a child process and
//! reports full build time, cost per variant, peak memory (the child's
//! maximum resident set, from `wait4`) and no-change rebuild time.

use crate::scale;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

#[derive(clap::Args)]
pub struct ScaleArgs {
    /// Synthetic library sizes, in materials (comma-separated). With the
    /// default 48 variants a material: ≈ 50, 500, 2 000 and 10 000 variants.
    #[arg(long, value_delimiter = ',', default_values_t = [1usize, 10, 42, 208])]
    materials: Vec<usize>,
    /// Target variants per synthetic material.
    #[arg(long, default_value_t = 48)]
    per_material: usize,
    /// Full builds per size (the median is reported).
    #[arg(long, default_value_t = 1)]
    full_runs: usize,
    /// No-change rebuilds per size (the median is reported).
    #[arg(long, default_value_t = 5)]
    runs: usize,
    /// Generator seed.
    #[arg(long, default_value_t = scale::DEFAULT_SEED)]
    seed: u64,
    /// `weft build --jobs` (default: all cores).
    #[arg(long)]
    jobs: Option<usize>,
    /// Keep the synthetic libraries' output folders (target/scale/*/out).
    #[arg(long)]
    keep: bool,
    /// Also write generated/reports/scale.md and scale.json.
    #[arg(long)]
    write: bool,
    /// Use this `weft` binary instead of building crates/weft-cli (release).
    #[arg(long)]
    weft: Option<PathBuf>,
    /// Skip the streamed library builds.
    #[arg(long)]
    no_streamed: bool,
}

impl ScaleArgs {
    fn command(&self) -> String {
        let mut c = "cargo run --release -p xtask -- bench scale".to_string();
        let sizes: Vec<String> = self.materials.iter().map(usize::to_string).collect();
        if self.materials != [1, 10, 42, 208] {
            c.push_str(&format!(" --materials {}", sizes.join(",")));
        }
        if self.per_material != 48 {
            c.push_str(&format!(" --per-material {}", self.per_material));
        }
        if self.full_runs != 1 {
            c.push_str(&format!(" --full-runs {}", self.full_runs));
        }
        if self.runs != 5 {
            c.push_str(&format!(" --runs {}", self.runs));
        }
        if self.seed != scale::DEFAULT_SEED {
            c.push_str(&format!(" --seed {}", self.seed));
        }
        if let Some(j) = self.jobs {
            c.push_str(&format!(" --jobs {j}"));
        }
        if self.no_streamed {
            c.push_str(" --no-streamed");
        }
        if let Some(w) = &self.weft {
            c.push_str(&format!(" --weft {}", w.display()));
        }
        c
    }
}

#[derive(clap::Args)]
pub struct StreamArgs {
    /// A materials folder.
    materials: PathBuf,
    /// Output folder (must not exist).
    out: PathBuf,
    #[arg(long)]
    jobs: Option<usize>,
}

/// `bench scale-stream-child`: builds `materials` with
/// `build_materials_streaming`, writing each file into `out` as it comes
/// (no atomic swap: this measures the library side of a streamed build),
/// then prints the same `built …` line as `weft build`.
pub fn stream_child(args: &StreamArgs) -> ExitCode {
    let started = Instant::now();
    if args.out.exists() {
        eprintln!("error: {} exists", args.out.display());
        return ExitCode::FAILURE;
    }
    let paths = match weft_compiler::library::discover(&args.materials) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("error: {}: {e}", args.materials.display());
            return ExitCode::FAILURE;
        }
    };
    let options = weft_compiler::BuildOptions {
        jobs: args.jobs,
        ..Default::default()
    };
    let mut files = 0usize;
    let mut write = |rel: String, bytes: Vec<u8>| -> std::io::Result<()> {
        let path = args.out.join(&rel);
        if let Some(p) = path.parent() {
            std::fs::create_dir_all(p)?;
        }
        files += 1;
        std::fs::write(path, bytes)
    };
    let built = weft_compiler::build_materials_streaming(
        &paths,
        Some(&args.materials),
        &options,
        &|_, _, _| {},
        &mut write,
    );
    match built {
        Ok(out) => {
            println!(
                "built {} material(s), {} variant(s), {files} file(s) into {} in {:.2}s",
                out.material_count(),
                out.variant_count,
                args.out.display(),
                started.elapsed().as_secs_f64()
            );
            ExitCode::SUCCESS
        }
        Err((db, diags)) => {
            eprint!("{}", diags.render_plain(&db));
            ExitCode::FAILURE
        }
    }
}

/// Whether two folders hold the same files with the same bytes.
fn same_tree(a: &Path, b: &Path) -> Result<bool, String> {
    let list = |d: &Path| {
        weft_compiler::output::list_files(d).map_err(|e| format!("{}: {e}", d.display()))
    };
    let (fa, fb) = (list(a)?, list(b)?);
    if fa != fb {
        return Ok(false);
    }
    for f in &fa {
        if std::fs::read(a.join(f)).ok() != std::fs::read(b.join(f)).ok() {
            return Ok(false);
        }
    }
    Ok(true)
}

/// One child run: wall time, user + system CPU time, peak RSS (KiB; 0
/// where unknown), stdout.
struct Run {
    wall: Duration,
    /// User and system CPU time.
    cpu: (Duration, Duration),
    max_rss_kib: u64,
    stdout: String,
}

#[cfg(unix)]
fn run_child(cmd: &mut Command) -> Result<Run, String> {
    // Earlier runs' dirty pages are flushed first, not during this one.
    // SAFETY: sync(2) takes no arguments and cannot fail.
    unsafe { libc::sync() };
    let started = Instant::now();
    let mut child = cmd
        .stdout(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot start {cmd:?}: {e}"))?;
    let mut out = child.stdout.take().expect("piped");
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        let _ = std::io::Read::read_to_string(&mut out, &mut s);
        s
    });
    let mut status = 0;
    // SAFETY: plain syscall on our own child's pid; rusage is written by the kernel.
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    let pid = child.id() as libc::pid_t;
    let r = unsafe { libc::wait4(pid, &mut status, 0, &mut usage) };
    let wall = started.elapsed();
    let stdout = reader.join().unwrap_or_default();
    if r != pid {
        return Err(format!("wait4: {}", std::io::Error::last_os_error()));
    }
    if !(libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0) {
        return Err(format!("{cmd:?} failed (status {status:#x})"));
    }
    // Linux reports ru_maxrss in KiB, macOS in bytes.
    let rss = usage.ru_maxrss.max(0) as u64;
    let max_rss_kib = if cfg!(target_vendor = "apple") {
        rss / 1024
    } else {
        rss
    };
    let tv = |t: libc::timeval| Duration::new(t.tv_sec as u64, t.tv_usec as u32 * 1000);
    Ok(Run {
        wall,
        cpu: (tv(usage.ru_utime), tv(usage.ru_stime)),
        max_rss_kib,
        stdout,
    })
}

#[cfg(not(unix))]
fn run_child(cmd: &mut Command) -> Result<Run, String> {
    let started = Instant::now();
    let out = cmd
        .stderr(Stdio::inherit())
        .output()
        .map_err(|e| format!("cannot start {cmd:?}: {e}"))?;
    if !out.status.success() {
        return Err(format!("{cmd:?} failed ({})", out.status));
    }
    Ok(Run {
        wall: started.elapsed(),
        cpu: (Duration::ZERO, Duration::ZERO),
        max_rss_kib: 0,
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
    })
}

/// `built M material(s), V variant(s), F file(s) … (U unchanged)`.
fn parse_built(stdout: &str) -> Option<(usize, usize, usize, usize)> {
    let line = stdout.lines().find(|l| l.starts_with("built "))?;
    let num = |tag: &str| -> Option<usize> {
        let i = line.find(tag)?;
        line[..i]
            .split_whitespace()
            .last()?
            .trim_start_matches('(')
            .parse()
            .ok()
    };
    Some((
        num(" material(s)")?,
        num(" variant(s)")?,
        num(" file(s)")?,
        num(" unchanged)").unwrap_or(0),
    ))
}

fn dir_bytes(dir: &Path) -> u64 {
    weft_compiler::output::list_files(dir)
        .unwrap_or_default()
        .iter()
        .filter_map(|f| std::fs::metadata(dir.join(f)).ok())
        .map(|m| m.len())
        .sum()
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

#[derive(Clone)]
struct Row {
    library: String,
    materials: usize,
    variants: usize,
    files: usize,
    bytes: u64,
    generate_s: f64,
    full_s: f64,
    /// User and system CPU seconds.
    full_cpu_s: (f64, f64),
    full_rss_kib: u64,
    no_change_ms: f64,
    no_change_cpu_ms: f64,
    no_change_rss_kib: u64,
    /// The streamed library build (`build_materials_streaming`): wall s, peak RSS KiB.
    streamed: Option<(f64, u64)>,
}

impl Row {
    fn per_variant_ms(&self) -> f64 {
        self.full_s * 1e3 / self.variants as f64
    }
}

fn weft_binary(root: &Path, args: &ScaleArgs) -> Result<PathBuf, String> {
    if let Some(w) = &args.weft {
        return Ok(w.clone());
    }
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
    eprintln!("building the release weft binary (cargo build --release -p weft-cli)…");
    let status = Command::new(cargo)
        .current_dir(root)
        .args(["build", "--release", "-p", "weft-cli", "--bin", "weft"])
        .status()
        .map_err(|e| format!("cannot run cargo: {e}"))?;
    if !status.success() {
        return Err("cargo build --release -p weft-cli failed".into());
    }
    let target =
        std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root.join("target"), PathBuf::from);
    Ok(target
        .join("release")
        .join(format!("weft{}", std::env::consts::EXE_SUFFIX)))
}

/// Full build into a fresh `out`, then `runs` no-change rebuilds.
fn measure(
    weft: &Path,
    library: &str,
    materials_dir: &Path,
    out: &Path,
    args: &ScaleArgs,
    generate_s: f64,
) -> Result<Row, String> {
    let build = || {
        let mut c = Command::new(weft);
        c.arg("build").arg(materials_dir).arg("-o").arg(out);
        if let Some(j) = args.jobs {
            c.arg("--jobs").arg(j.to_string());
        }
        c
    };
    let mut full = Vec::new();
    let mut full_cpu = Vec::new();
    let mut full_rss = 0;
    let mut counts = (0, 0, 0, 0);
    for _ in 0..args.full_runs.max(1) {
        remove_output(out)?;
        let r = run_child(&mut build())?;
        counts =
            parse_built(&r.stdout).ok_or_else(|| format!("unexpected output: {}", r.stdout))?;
        full.push(r.wall.as_secs_f64());
        full_cpu.push(r.cpu);
        full_rss = full_rss.max(r.max_rss_kib);
    }
    let (materials, variants, files, _) = counts;
    let bytes = dir_bytes(out);
    let mut no_change = Vec::new();
    let mut no_change_cpu = Vec::new();
    let mut no_change_rss = 0;
    for _ in 0..args.runs.max(1) {
        let r = run_child(&mut build())?;
        let (_, _, _, unchanged) =
            parse_built(&r.stdout).ok_or_else(|| format!("unexpected output: {}", r.stdout))?;
        if unchanged != materials {
            return Err(format!(
                "{library}: no-change rebuild reused {unchanged} of {materials} materials"
            ));
        }
        no_change.push(r.wall.as_secs_f64() * 1e3);
        no_change_cpu.push((r.cpu.0 + r.cpu.1).as_secs_f64() * 1e3);
        no_change_rss = no_change_rss.max(r.max_rss_kib);
    }
    let row = Row {
        library: library.into(),
        materials,
        variants,
        files,
        bytes,
        generate_s,
        full_s: median(full),
        full_cpu_s: {
            // The run with the median user time.
            full_cpu.sort();
            let (u, s) = full_cpu[full_cpu.len() / 2];
            (u.as_secs_f64(), s.as_secs_f64())
        },
        full_rss_kib: full_rss,
        no_change_ms: median(no_change),
        no_change_cpu_ms: median(no_change_cpu),
        no_change_rss_kib: no_change_rss,
        streamed: None,
    };
    eprintln!(
        "  {library}: {} materials, {} variants, {} files, {:.1} MiB; full build {:.2} s, {:.2} + {:.2} s user + system CPU ({:.2} ms/variant, peak RSS {:.0} MiB); no-change rebuild {:.1} ms (peak RSS {:.0} MiB)",
        row.materials,
        row.variants,
        row.files,
        row.bytes as f64 / 1048576.0,
        row.full_s,
        row.full_cpu_s.0,
        row.full_cpu_s.1,
        row.per_variant_ms(),
        row.full_rss_kib as f64 / 1024.0,
        row.no_change_ms,
        row.no_change_rss_kib as f64 / 1024.0
    );
    Ok(row)
}

/// The same library built by `bench scale-stream-child` (this binary) into
/// a fresh folder next to `out`, which must come out byte-identical.
fn measure_streamed(
    row: &mut Row,
    materials_dir: &Path,
    out: &Path,
    args: &ScaleArgs,
) -> Result<(), String> {
    let streamed = out.with_file_name("out-streamed");
    remove_output(&streamed)?;
    let exe = std::env::current_exe().map_err(|e| e.to_string())?;
    let mut c = Command::new(exe);
    c.args(["bench", "scale-stream-child"])
        .arg(materials_dir)
        .arg(&streamed);
    if let Some(j) = args.jobs {
        c.arg("--jobs").arg(j.to_string());
    }
    let r = run_child(&mut c)?;
    if !same_tree(out, &streamed)? {
        return Err(format!(
            "{}: the streamed build differs from `weft build`'s ({} vs {})",
            row.library,
            streamed.display(),
            out.display()
        ));
    }
    remove_output(&streamed)?;
    row.streamed = Some((r.wall.as_secs_f64(), r.max_rss_kib));
    eprintln!(
        "  {}: streamed library build {:.2} s, peak RSS {:.0} MiB (byte-identical output)",
        row.library,
        r.wall.as_secs_f64(),
        r.max_rss_kib as f64 / 1024.0
    );
    Ok(())
}

/// Removes an output folder and the lock file beside it.
fn remove_output(out: &Path) -> Result<(), String> {
    if out.exists() {
        std::fs::remove_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    }
    if let (Some(parent), Some(name)) = (out.parent(), out.file_name()) {
        let _ = std::fs::remove_file(parent.join(format!(".{}.lock", name.to_string_lossy())));
    }
    Ok(())
}

/// The 1-minute load average (Linux), to judge how busy the machine was.
fn load_average() -> Option<f64> {
    std::fs::read_to_string("/proc/loadavg")
        .ok()?
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

fn markdown(rows: &[Row], command: &str, threads: usize, load: &str) -> String {
    use std::fmt::Write;
    let mut md = String::new();
    let _ = writeln!(md, "# Build scale\n");
    let _ = writeln!(
        md,
        "Generated by `{command}` ({threads} hardware threads, 1-minute load average {load}): the release `weft build` binary as a child process; \
         peak RSS is the child's maximum resident set (`wait4`); every run starts after a `sync`. \"full\" builds into a missing output folder; \
         \"no-change\" rebuilds the same inputs into it again (median of the runs). The synthetic libraries are \
         derived from materials/ by `xtask/src/scale.rs` (deterministic). \
         \"streamed\" is the same library built in a child of xtask with `weft_compiler::build_materials_streaming`, \
         each file written to disk as its material finishes (no atomic swap); its output is checked byte-identical to `weft build`'s.\n"
    );
    let _ = writeln!(
        md,
        "| library | materials | variants | files | output MiB | full build s | user + system CPU s | ms / variant | marginal ms / variant | user CPU ms / variant | peak RSS MiB | no-change ms (CPU ms) | no-change peak RSS MiB | streamed build s | streamed peak RSS MiB |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    );
    let mut prev: Option<&Row> = None;
    for r in rows {
        let marginal = match prev {
            Some(p)
                if r.library != "shipped" && p.library != "shipped" && r.variants > p.variants =>
            {
                format!(
                    "{:.2}",
                    (r.full_s - p.full_s) * 1e3 / (r.variants - p.variants) as f64
                )
            }
            _ => "—".into(),
        };
        let _ = writeln!(
            md,
            "| {} | {} | {} | {} | {:.1} | {:.2} | {:.2} + {:.2} | {:.2} | {marginal} | {:.2} | {:.0} | {:.1} ({:.1}) | {:.0} | {} | {} |",
            r.library,
            r.materials,
            r.variants,
            r.files,
            r.bytes as f64 / 1048576.0,
            r.full_s,
            r.full_cpu_s.0,
            r.full_cpu_s.1,
            r.per_variant_ms(),
            r.full_cpu_s.0 * 1e3 / r.variants as f64,
            r.full_rss_kib as f64 / 1024.0,
            r.no_change_ms,
            r.no_change_cpu_ms,
            r.no_change_rss_kib as f64 / 1024.0,
            r.streamed.map_or("—".into(), |(t, _)| format!("{t:.2}")),
            r.streamed
                .map_or("—".into(), |(_, k)| format!("{:.0}", k as f64 / 1024.0)),
        );
        if r.library != "shipped" {
            prev = Some(r);
        }
    }
    md
}

fn json(rows: &[Row], command: &str, threads: usize, load: &str) -> String {
    let rows: Vec<serde_json::Value> = rows
        .iter()
        .map(|r| {
            serde_json::json!({
                "library": r.library,
                "materials": r.materials,
                "variants": r.variants,
                "files": r.files,
                "output_bytes": r.bytes,
                "generate_s": r.generate_s,
                "full_build_s": r.full_s,
                "full_build_user_cpu_s": r.full_cpu_s.0,
                "full_build_system_cpu_s": r.full_cpu_s.1,
                "ms_per_variant": r.per_variant_ms(),
                "full_build_peak_rss_kib": r.full_rss_kib,
                "no_change_ms": r.no_change_ms,
                "no_change_cpu_ms": r.no_change_cpu_ms,
                "no_change_peak_rss_kib": r.no_change_rss_kib,
                "streamed_build_s": r.streamed.map(|s| s.0),
                "streamed_peak_rss_kib": r.streamed.map(|s| s.1),
            })
        })
        .collect();
    let mut s = serde_json::to_string_pretty(&serde_json::json!({
        "command": command,
        "hardware_threads": threads,
        "load_average_1min": load,
        "rows": rows,
    }))
    .expect("serialises");
    s.push('\n');
    s
}

pub fn bench_scale(root: &Path, args: &ScaleArgs) -> ExitCode {
    match run(root, args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(root: &Path, args: &ScaleArgs) -> Result<(), String> {
    let weft = weft_binary(root, args)?;
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let command = args.command();
    let work = root.join("target/scale");
    let mut rows = Vec::new();
    let load_before = load_average();
    eprintln!("bench scale: {}", weft.display());
    let shipped_out = work.join("shipped/out");
    let mut shipped = measure(
        &weft,
        "shipped",
        &root.join("materials"),
        &shipped_out,
        args,
        0.0,
    )?;
    if !args.no_streamed {
        measure_streamed(&mut shipped, &root.join("materials"), &shipped_out, args)?;
    }
    rows.push(shipped);
    if !args.keep {
        remove_output(&shipped_out)?;
    }
    for &count in &args.materials {
        let label = format!("synthetic-{count}");
        let dir = work.join(&label);
        let t = Instant::now();
        let lib = scale::generate(
            &root.join("materials"),
            &dir.join("materials"),
            count,
            args.per_material,
            args.seed,
        )?;
        let generate_s = t.elapsed().as_secs_f64();
        let out = dir.join("out");
        let mut row = measure(&weft, &label, &lib.dir, &out, args, generate_s)?;
        if !args.no_streamed {
            measure_streamed(&mut row, &lib.dir, &out, args)?;
        }
        if row.variants != lib.variants {
            return Err(format!(
                "{label}: built {} variants, the generator promised {}",
                row.variants, lib.variants
            ));
        }
        rows.push(row);
        if !args.keep {
            remove_output(&out)?;
        }
    }
    let fmt = |l: Option<f64>| l.map_or("?".to_string(), |l| format!("{l:.1}"));
    let load = format!("{} before, {} after", fmt(load_before), fmt(load_average()));
    let md = markdown(&rows, &command, threads, &load);
    let js = json(&rows, &command, threads, &load);
    print!("\n{md}");
    std::fs::create_dir_all(&work).map_err(|e| e.to_string())?;
    std::fs::write(work.join("scale.md"), &md)
        .and_then(|()| std::fs::write(work.join("scale.json"), &js))
        .map_err(|e| format!("cannot write target/scale/: {e}"))?;
    println!("\nwrote target/scale/scale.md and scale.json");
    if args.write {
        let reports = root.join("generated/reports");
        std::fs::create_dir_all(&reports).map_err(|e| e.to_string())?;
        std::fs::write(reports.join("scale.md"), &md)
            .and_then(|()| std::fs::write(reports.join("scale.json"), &js))
            .map_err(|e| format!("cannot write generated/reports/: {e}"))?;
        println!("wrote generated/reports/scale.md and scale.json");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    #[test]
    fn parses_the_build_line() {
        assert_eq!(
            super::parse_built(
                "built 6 material(s), 48 variant(s), 298 file(s) into out in 0.03s (6 unchanged)\n"
            ),
            Some((6, 48, 298, 6))
        );
        assert_eq!(
            super::parse_built("built 1 material(s), 48 variant(s), 99 file(s) into o in 1.2s\n"),
            Some((1, 48, 99, 0))
        );
    }
}
