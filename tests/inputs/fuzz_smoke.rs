//! The fuzz smoke run (docs/fuzzing.md): the fuzz targets' bodies
//! (`fuzz/src/lib.rs`) on the committed fuzz corpus (`fuzz/corpus/`), then
//! a bounded random-mutation loop with a fixed seed through the same
//! functions. Stable Rust, no libFuzzer, about a minute on two cores; the
//! long coverage-guided run is `fuzz/run.sh`.
//!
//! An input that panics or takes longer than [`HANG`] fails the test; it is
//! written to `$CARGO_TARGET_TMPDIR/fuzz-smoke/` and its path printed, to
//! replay with `cargo run --example show` in `fuzz/` and then to turn into a
//! corpus file with a snapshot (tests/diagnostics/).

#[path = "../../fuzz/src/lib.rs"]
mod harness;

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// Longest one input may take here. The long run bounds it at 1 s in an
/// optimised build; the test suite's weft crates are unoptimised.
const HANG: Duration = Duration::from_secs(5);
/// Wall-clock cap on one target's mutation loop (it stops early, and says so).
const LOOP_CAP: Duration = Duration::from_secs(75);

struct Target {
    name: &'static str,
    dict: &'static str,
    run: fn(&[u8]) -> String,
    /// Mutated inputs per run.
    mutations: usize,
}

const FRONT: Target = Target {
    name: "material_front",
    dict: "material",
    run: harness::material_front,
    mutations: 500_000,
};
const COMPILE: Target = Target {
    name: "material_compile",
    dict: "material_compile",
    run: harness::material_compile,
    mutations: 60_000,
};
const SCENE: Target = Target {
    name: "scene",
    dict: "scene",
    run: harness::scene,
    mutations: 400_000,
};

const GLTF: Target = Target {
    name: "gltf",
    dict: "gltf",
    run: harness::gltf,
    mutations: 60_000,
};

fn fuzz_dir() -> PathBuf {
    harness::repo().join("fuzz")
}

/// The committed corpus of a target, sorted by name.
fn corpus(target: &Target) -> Vec<(String, Vec<u8>)> {
    let dir = fuzz_dir().join("corpus").join(target.name);
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("corpus entry").path())
        .map(|p| {
            let name = p.file_name().expect("name").to_string_lossy().into_owned();
            (name, std::fs::read(&p).expect("corpus file"))
        })
        .collect();
    files.sort();
    assert!(!files.is_empty(), "{}: empty corpus", dir.display());
    files
}

/// A libFuzzer dictionary's entries (`"token"` or `name="token"` per line, `\xNN` escapes).
fn dictionary(name: &str) -> Vec<Vec<u8>> {
    let path = fuzz_dir().join("dict").join(format!("{name}.dict"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.lines()
        .filter_map(|line| {
            let line = line.trim();
            if line.starts_with('#') {
                return None;
            }
            let quoted = &line[line.find('"')? + 1..line.rfind('"')?];
            let mut out = Vec::new();
            let mut bytes = quoted.bytes();
            while let Some(b) = bytes.next() {
                match (b, bytes.clone().next()) {
                    (b'\\', Some(b'x')) => {
                        bytes.next();
                        let hex: String = bytes.by_ref().take(2).map(char::from).collect();
                        out.push(u8::from_str_radix(&hex, 16).expect("\\xNN escape"));
                    }
                    (b'\\', Some(c)) => {
                        bytes.next();
                        out.push(c);
                    }
                    _ => out.push(b),
                }
            }
            Some(out)
        })
        .collect()
}

/// xorshift64*: a fixed-seed generator, so every run mutates the same way.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// Bytes that matter to TOML and WGSL, inserted one at a time.
const PUNCTUATION: &[u8] = b" \n=\"'[]{}(),.:;<>0123456789-_#@";

/// One to four of libFuzzer's kinds of mutation: bytes changed, inserted,
/// erased or copied; dictionary words inserted; a part of another input
/// spliced in.
fn mutate(input: &mut Vec<u8>, rng: &mut Rng, dict: &[Vec<u8>], others: &[(String, Vec<u8>)]) {
    for _ in 0..1 + rng.below(4) {
        let len = input.len();
        let at = rng.below(len + 1);
        match rng.below(8) {
            0 if len > 0 => input[at.min(len - 1)] ^= 1 << rng.below(8),
            1 if len > 0 => input[at.min(len - 1)] = rng.next() as u8,
            2 => input.insert(at, PUNCTUATION[rng.below(PUNCTUATION.len())]),
            3 if len > 0 => {
                let end = (at + 1 + rng.below(64)).min(len);
                input.drain(at.min(len - 1)..end);
            }
            4 if len > 0 => {
                let start = rng.below(len);
                let end = (start + 1 + rng.below(256)).min(len);
                let part = input[start..end].to_vec();
                input.splice(at..at, part);
            }
            5 | 6 if !dict.is_empty() => {
                let word = &dict[rng.below(dict.len())];
                input.splice(at..at, word.iter().copied());
            }
            _ => {
                let other = &others[rng.below(others.len())].1;
                if !other.is_empty() {
                    let start = rng.below(other.len());
                    let end = (start + 1 + rng.below(512)).min(other.len());
                    input.splice(at..at, other[start..end].iter().copied());
                }
            }
        }
    }
}

/// Runs one input; the failure (panic or hang) as a message, the input saved.
fn check_one(target: &Target, label: &str, data: &[u8]) -> Result<(), String> {
    let start = Instant::now();
    let outcome = catch_unwind(AssertUnwindSafe(|| (target.run)(data)));
    let took = start.elapsed();
    let problem = match outcome {
        Err(payload) => {
            let msg = payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default();
            format!("panicked: {msg}")
        }
        Ok(_) if took > HANG => format!("took {took:.1?} (limit {HANG:?})"),
        Ok(_) => return Ok(()),
    };
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("fuzz-smoke");
    std::fs::create_dir_all(&dir).expect("failure folder");
    let saved = dir.join(format!("{}-{label}", target.name));
    std::fs::write(&saved, data).expect("save failing input");
    Err(format!(
        "{} on {label} {problem}; input saved to {} (replay: cd fuzz && cargo run --example show -- {} <file>)",
        target.name,
        saved.display(),
        target.name
    ))
}

/// The corpus replayed, then the mutation loop.
fn smoke(target: &Target, seed: u64) {
    let start = Instant::now();
    let corpus = corpus(target);
    let dict = dictionary(target.dict);
    let mut failures = Vec::new();
    for (name, data) in &corpus {
        if let Err(e) = check_one(target, name, data) {
            failures.push(e);
        }
    }
    let replayed = start.elapsed();
    let mut rng = Rng(seed);
    let mut done = 0;
    while done < target.mutations && start.elapsed() - replayed < LOOP_CAP {
        let (_, base) = &corpus[rng.below(corpus.len())];
        let mut input = base.clone();
        mutate(&mut input, &mut rng, &dict, &corpus);
        if let Err(e) = check_one(target, &format!("mutation-{done}"), &input) {
            failures.push(e);
        }
        done += 1;
    }
    eprintln!(
        "{}: {} corpus inputs in {replayed:.1?}, {done} of {} mutations in {:.1?}{}",
        target.name,
        corpus.len(),
        target.mutations,
        start.elapsed() - replayed,
        if done < target.mutations {
            " (stopped at the time cap)"
        } else {
            ""
        }
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn material_front_smoke() {
    smoke(&FRONT, 0x5eed_0001);
}

#[test]
fn material_compile_smoke() {
    smoke(&COMPILE, 0x5eed_0002);
}

#[test]
fn scene_smoke() {
    smoke(&SCENE, 0x5eed_0003);
}

#[test]
fn gltf_smoke() {
    smoke(&GLTF, 0x5eed_0004);
}

/// The in-memory compile path is the build's: each shipped material,
/// given as a `material_compile` input, compiles without a diagnostic (so
/// the corpus' seeds reach every stage).
#[test]
fn shipped_materials_compile_in_memory() {
    let materials = harness::repo().join("materials");
    let mut names: Vec<String> = std::fs::read_dir(&materials)
        .expect("materials folder")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .filter(|n| n != "lib" && materials.join(n).join(format!("{n}.toml")).is_file())
        .collect();
    names.sort();
    assert!(names.len() >= 6, "{names:?}");
    for name in names {
        let dir = materials.join(&name);
        let toml = std::fs::read_to_string(dir.join(format!("{name}.toml"))).expect("toml");
        // An in-memory load reads no files: the shipped texture files (`file =`)
        // go, leaving each parameter's built-in `default`.
        let toml: String = toml
            .lines()
            .filter(|l| !l.starts_with("file = "))
            .map(|l| format!("{l}\n"))
            .collect();
        let wgsl = std::fs::read_to_string(dir.join(format!("{name}.wgsl"))).expect("wgsl");
        let input = format!("{toml}{}m/{name}.wgsl\n{wgsl}", harness::FILE_MARK);
        let diags = harness::material_compile(input.as_bytes());
        assert!(diags.is_empty(), "{name}:\n{diags}");
    }
}
