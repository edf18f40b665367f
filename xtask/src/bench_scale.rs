//! `cargo xtask bench scale`: builds synthetic libraries of growing size
//! (see `scale.rs`) with the release `weft` binary as a child process and
//! reports full build time, cost per variant, peak memory (the child's
//! maximum resident set, from `wait4`), no-change and one-edit rebuild
//! times, and builds through a shared `--cache-dir` (cold, then warm into
//! a fresh folder, checked byte-identical).

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
    /// Skip the builds through a shared cache (`--cache-dir`).
    #[arg(long)]
    no_cache: bool,
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
        if self.no_cache {
            c.push_str(" --no-cache");
        }
        if let Some(w) = &self.weft {
            c.push_str(&format!(" --weft {}", w.display()));
        }
        c
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
pub(crate) struct Run {
    pub(crate) wall: Duration,
    /// User and system CPU time.
    pub(crate) cpu: (Duration, Duration),
    pub(crate) max_rss_kib: u64,
    pub(crate) stdout: String,
}

#[cfg(unix)]
pub(crate) fn run_child(cmd: &mut Command) -> Result<Run, String> {
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
pub(crate) fn run_child(cmd: &mut Command) -> Result<Run, String> {
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
    /// Rebuild after editing one material's TOML: wall s, peak RSS KiB.
    one_edit: (f64, u64),
    /// Through `--cache-dir`: cold cache (filled) wall s, then warm cache
    /// into a fresh folder wall s and peak RSS KiB.
    cache: Option<(f64, f64, u64)>,
}

impl Row {
    fn per_variant_ms(&self) -> f64 {
        self.full_s * 1e3 / self.variants as f64
    }
}

pub(crate) fn weft_binary(root: &Path, given: Option<&PathBuf>) -> Result<PathBuf, String> {
    if let Some(w) = given {
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
    let mut build = || {
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
    let one_edit = measure_one_edit(&mut build, materials_dir, library, materials)?;
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
        one_edit,
        cache: None,
    };
    eprintln!(
        "  {library}: {} materials, {} variants, {} files, {:.1} MiB; full build {:.2} s, {:.2} + {:.2} s user + system CPU ({:.2} ms/variant, peak RSS {:.0} MiB); no-change rebuild {:.1} ms (peak RSS {:.0} MiB); one edit {:.2} s (peak RSS {:.0} MiB)",
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
        row.no_change_rss_kib as f64 / 1024.0,
        row.one_edit.0,
        row.one_edit.1 as f64 / 1024.0
    );
    Ok(row)
}

/// Appends a comment to the first material's TOML (its inputs change, the
/// others' do not), rebuilds, and puts the file and the output back.
fn measure_one_edit(
    build: &mut dyn FnMut() -> Command,
    materials_dir: &Path,
    library: &str,
    materials: usize,
) -> Result<(f64, u64), String> {
    let first = weft_compiler::library::discover(materials_dir)
        .map_err(|e| format!("{}: {e}", materials_dir.display()))?
        .into_iter()
        .next()
        .ok_or_else(|| format!("{library}: no material"))?;
    let text = std::fs::read_to_string(&first).map_err(|e| format!("{}: {e}", first.display()))?;
    let write =
        |t: &str| std::fs::write(&first, t).map_err(|e| format!("{}: {e}", first.display()));
    write(&format!("{text}\n# edited by bench scale\n"))?;
    let r = run_child(&mut build());
    write(&text)?;
    let r = r?;
    // Back to the unedited build (not measured), for the comparisons after.
    run_child(&mut build())?;
    let (_, _, _, unchanged) =
        parse_built(&r.stdout).ok_or_else(|| format!("unexpected output: {}", r.stdout))?;
    if unchanged + 1 != materials {
        return Err(format!(
            "{library}: after one edit {unchanged} of {materials} materials were unchanged"
        ));
    }
    Ok((r.wall.as_secs_f64(), r.max_rss_kib))
}

/// Builds the library through a fresh `--cache-dir` into a fresh folder
/// (cold: every unit compiled and stored), then again into another fresh
/// folder (warm: every unit from the cache), which must come out
/// byte-identical to `out`.
fn measure_cache(
    weft: &Path,
    row: &mut Row,
    materials_dir: &Path,
    out: &Path,
    args: &ScaleArgs,
) -> Result<(), String> {
    let cache = out.with_file_name("cache");
    let _ = std::fs::remove_dir_all(&cache);
    let mut times = Vec::new();
    for name in ["out-cold", "out-warm"] {
        let dest = out.with_file_name(name);
        remove_output(&dest)?;
        let mut c = Command::new(weft);
        c.arg("build")
            .arg(materials_dir)
            .arg("-o")
            .arg(&dest)
            .arg("--cache-dir")
            .arg(&cache);
        if let Some(j) = args.jobs {
            c.arg("--jobs").arg(j.to_string());
        }
        let r = run_child(&mut c)?;
        let (hits, compiled) =
            parse_units(&r.stdout).ok_or_else(|| format!("unexpected output: {}", r.stdout))?;
        let expected = if name == "out-cold" {
            (0, row.variants)
        } else {
            (row.variants, 0)
        };
        // Aliased variants are compiled (then found identical), so every
        // variant is one unit.
        if (hits, compiled) != expected {
            return Err(format!(
                "{}: {name}: {hits} units from the cache, {compiled} compiled; expected {expected:?}",
                row.library
            ));
        }
        if !same_tree(out, &dest)? {
            return Err(format!(
                "{}: the build through the cache ({}) differs from `weft build`'s ({})",
                row.library,
                dest.display(),
                out.display()
            ));
        }
        remove_output(&dest)?;
        times.push(r);
    }
    let _ = std::fs::remove_dir_all(&cache);
    let (cold, warm) = (&times[0], &times[1]);
    row.cache = Some((
        cold.wall.as_secs_f64(),
        warm.wall.as_secs_f64(),
        warm.max_rss_kib,
    ));
    eprintln!(
        "  {}: through a fresh cache {:.2} s; warm cache into a fresh folder {:.2} s, peak RSS {:.0} MiB (byte-identical output)",
        row.library,
        cold.wall.as_secs_f64(),
        warm.wall.as_secs_f64(),
        warm.max_rss_kib as f64 / 1024.0
    );
    Ok(())
}

/// `compile units: H from the cache, C compiled`.
fn parse_units(stdout: &str) -> Option<(usize, usize)> {
    let line = stdout.lines().find(|l| l.starts_with("compile units: "))?;
    let mut nums = line
        .split(|c: char| !c.is_ascii_digit())
        .filter(|w| !w.is_empty())
        .map(|w| w.parse::<usize>());
    Some((nums.next()?.ok()?, nums.next()?.ok()?))
}

/// Removes an output folder and the lock file beside it.
fn remove_output(out: &Path) -> Result<(), String> {
    if out.exists() {
        std::fs::remove_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    }
    if let (Some(parent), Some(name)) = (out.parent(), out.file_name()) {
        for ext in ["lock", "stamp"] {
            let _ = std::fs::remove_file(parent.join(format!(".{}.{ext}", name.to_string_lossy())));
        }
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
         \"one edit\" rebuilds after a comment is appended to one material's TOML (that material recompiles, the others' files are hard-linked from the old folder). \
         \"cold cache\" builds into a fresh folder through a fresh `--cache-dir` (every unit compiled and stored); \"warm cache\" then builds into another fresh folder through it \
         (every unit from the cache); both are checked byte-identical to the full build.\n"
    );
    let _ = writeln!(
        md,
        "| library | materials | variants | files | output MiB | full build s | user + system CPU s | ms / variant | marginal ms / variant | user CPU ms / variant | peak RSS MiB | no-change ms (CPU ms) | no-change peak RSS MiB | one edit s | one edit peak RSS MiB | cold cache s | warm cache s | warm cache peak RSS MiB |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
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
            "| {} | {} | {} | {} | {:.1} | {:.2} | {:.2} + {:.2} | {:.2} | {marginal} | {:.2} | {:.0} | {:.1} ({:.1}) | {:.0} | {:.2} | {:.0} | {} | {} | {} |",
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
            r.one_edit.0,
            r.one_edit.1 as f64 / 1024.0,
            r.cache.map_or("—".into(), |(c, _, _)| format!("{c:.2}")),
            r.cache.map_or("—".into(), |(_, w, _)| format!("{w:.2}")),
            r.cache.map_or("—".into(), |(_, _, k)| format!(
                "{:.0}",
                k as f64 / 1024.0
            )),
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
                "one_edit_s": r.one_edit.0,
                "one_edit_peak_rss_kib": r.one_edit.1,
                "cold_cache_s": r.cache.map(|c| c.0),
                "warm_cache_s": r.cache.map(|c| c.1),
                "warm_cache_peak_rss_kib": r.cache.map(|c| c.2),
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
    let weft = weft_binary(root, args.weft.as_ref())?;
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let command = args.command();
    let work = root.join("target/scale");
    let mut rows = Vec::new();
    let load_before = load_average();
    eprintln!("bench scale: {}", weft.display());
    let shipped_out = work.join("shipped/out");
    // A copy: the one-edit rebuild edits a material.
    let shipped_materials = work.join("shipped/materials");
    let _ = std::fs::remove_dir_all(&shipped_materials);
    scale::copy_dir(&root.join("materials"), &shipped_materials)?;
    let mut shipped = measure(
        &weft,
        "shipped",
        &shipped_materials,
        &shipped_out,
        args,
        0.0,
    )?;
    if !args.no_cache {
        measure_cache(&weft, &mut shipped, &shipped_materials, &shipped_out, args)?;
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
        if !args.no_cache {
            measure_cache(&weft, &mut row, &lib.dir, &out, args)?;
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
