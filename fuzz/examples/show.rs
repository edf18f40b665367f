//! Runs one fuzz target's body on files and prints the diagnostics, without
//! libFuzzer: `cargo run --example show -- <target> <file>...` (from fuzz/).
//! Use it to see what an input (a seed, a crash artifact) does; a crash
//! shows as a panic with its backtrace (`RUST_BACKTRACE=1`).

fn main() {
    let mut args = std::env::args().skip(1);
    let target = args.next().unwrap_or_default();
    let run: fn(&[u8]) -> String = match target.as_str() {
        "material_front" => weft_fuzz::material_front,
        "material_compile" => weft_fuzz::material_compile,
        "scene" => weft_fuzz::scene,
        _ => {
            eprintln!("usage: show <material_front|material_compile|scene> <file>...");
            std::process::exit(2);
        }
    };
    for path in args {
        let data = std::fs::read(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        let start = std::time::Instant::now();
        let diags = run(&data);
        let time = start.elapsed();
        let verdict = if diags.is_empty() {
            "clean"
        } else {
            "diagnostics"
        };
        println!("== {path}: {verdict} in {time:.1?}");
        print!("{diags}");
    }
}
