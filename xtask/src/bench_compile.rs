//! `cargo xtask bench compile`: full-library build time, variants per second and no-change rebuild time.

use crate::regenerate::build;
use std::path::Path;
use std::process::ExitCode;
use std::time::{Duration, Instant};
use weft_compiler::{BuildOptions, output};

pub(crate) fn median(mut v: Vec<Duration>) -> Duration {
    v.sort();
    v[v.len() / 2]
}

pub(crate) fn bench_compile(root: &Path, runs: usize) -> ExitCode {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let profile = if cfg!(debug_assertions) {
        "debug"
    } else {
        "release"
    };
    // Warm-up (page cache, lazy statics).
    let Some(first) = build(root, &BuildOptions::default()) else {
        return ExitCode::FAILURE;
    };
    let canonical: usize = first
        .materials
        .iter()
        .map(|m| m.variants.iter().filter(|v| v.alias_of.is_none()).count())
        .sum();

    let mut full = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        build(root, &BuildOptions::default()).expect("built once already");
        full.push(t.elapsed());
    }
    let mut single = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        build(
            root,
            &BuildOptions {
                jobs: Some(1),
                ..Default::default()
            },
        )
        .expect("built once already");
        single.push(t.elapsed());
    }
    // No-change rebuild of the library, as `weft build` does it: inputs
    // loaded and hashed, unchanged materials kept on disk unread, nothing
    // written when the folder already holds the build (scenes are not reused
    // and not included here).
    let tmp = tempfile::tempdir().expect("temp dir");
    let out_dir = tmp.path().join("generated");
    let materials = root.join("materials");
    let library = weft_compiler::build_library(&materials, &BuildOptions::default(), &|_, _, _| {})
        .unwrap_or_else(|_| panic!("materials/ built once already"));
    output::write_atomically(&out_dir, &library.files, &[]).expect("write temp output");
    drop(library);
    let lock = output::OutputLock::acquire(&out_dir, output::DEFAULT_LOCK_WAIT, &mut |_| {})
        .expect("lock temp output");
    let paths = weft_compiler::library::discover(&materials).expect("materials/");
    let mut unchanged = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        let options = BuildOptions {
            reuse_from: Some(out_dir.clone()),
            ..Default::default()
        };
        let built = weft_compiler::folder_build::build_into(
            &paths,
            Some(&materials),
            &lock,
            &options,
            &[],
            &[],
            &|_, _, _| {},
        )
        .unwrap_or_else(|_| panic!("materials/ built once already"));
        unchanged.push(t.elapsed());
        assert!(!built.wrote, "nothing to write");
        assert_eq!(
            built.output.reused.len(),
            built.output.material_count(),
            "every material reused"
        );
    }
    let mut lut = Vec::new();
    for _ in 0..runs {
        let t = Instant::now();
        let l = weft_compiler::bake::split_sum::split_sum_lut(
            weft_compiler::library::SPLIT_SUM_LUT_SIZE,
            weft_compiler::library::SPLIT_SUM_LUT_SAMPLES,
        );
        std::hint::black_box(l);
        lut.push(t.elapsed());
    }
    let (full, single, unchanged, lut) =
        (median(full), median(single), median(unchanged), median(lut));
    let vps = |d: Duration| first.variant_count as f64 / d.as_secs_f64();
    println!(
        "weft compile benchmark ({profile} build of xtask, {threads} threads available, median of {runs} runs)"
    );
    println!(
        "  materials: {}, variants: {} ({} distinct), files: {}",
        first.materials.len(),
        first.variant_count,
        canonical,
        first.files.len()
    );
    println!(
        "  full library build, all threads : {:>8.1} ms  ({:.0} variants/s)",
        full.as_secs_f64() * 1e3,
        vps(full)
    );
    println!(
        "  full library build, 1 thread    : {:>8.1} ms  ({:.0} variants/s)",
        single.as_secs_f64() * 1e3,
        vps(single)
    );
    println!(
        "  no-change library rebuild       : {:>8.1} ms (as `weft build`: nothing rewritten)",
        unchanged.as_secs_f64() * 1e3
    );
    println!(
        "  of which split-sum LUT bake     : {:>8.1} ms (reused on no-change rebuilds)",
        lut.as_secs_f64() * 1e3
    );
    ExitCode::SUCCESS
}
