//! `cargo xtask bench gltf`: how fast a large glTF scene builds (issue 25's
//! target: 100 k triangles in 10 materials, no `auto` tier, ≤ 1 s on 2
//! cores in release, peak memory within 4× the file). The scene comes from
//! `weft_golden::gltf_samples::large`; each run is a fresh
//! `weft build --scene big.glb` process (wall time, peak RSS by `wait4`).

use crate::bench_scale::{run_child, weft_binary};
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode};

#[derive(clap::Args)]
pub(crate) struct GltfArgs {
    /// Triangles in the scene.
    #[arg(long, default_value_t = 100_000)]
    triangles: usize,
    /// Mesh objects (nodes) the triangles are split over.
    #[arg(long, default_value_t = 40)]
    objects: usize,
    /// glTF materials (half core PBR, half sheen).
    #[arg(long, default_value_t = 10)]
    materials: usize,
    /// Timed builds (each into a fresh folder).
    #[arg(long, default_value_t = 5)]
    runs: usize,
    /// A prebuilt release `weft` binary (default: build it).
    #[arg(long)]
    weft: Option<PathBuf>,
    /// Also write generated/reports/gltf.md.
    #[arg(long)]
    write: bool,
}

pub(crate) fn bench_gltf(root: &Path, args: &GltfArgs) -> ExitCode {
    match run(root, args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("bench gltf: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run(root: &Path, args: &GltfArgs) -> Result<(), String> {
    let weft = weft_binary(root, args.weft.as_ref())?;
    let tmp = tempfile::tempdir().map_err(|e| e.to_string())?;
    // The process's own footprint (binary, compiler, materials): a
    // one-triangle scene's peak, subtracted to see what the file costs.
    let tiny = tmp.path().join("tiny.glb");
    let baseline_of = |bytes: Vec<u8>, name: &str| -> Result<f64, String> {
        std::fs::write(&tiny, bytes).map_err(|e| e.to_string())?;
        Ok(run_child(
            Command::new(&weft)
                .current_dir(root)
                .args(["build", "--scene"])
                .arg(&tiny)
                .arg("-o")
                .arg(tmp.path().join(name))
                .args(["--materials", "materials"]),
        )?
        .max_rss_kib as f64
            / 1024.0)
    };
    let baseline = baseline_of(weft_golden::gltf_samples::large(2, 1, 1), "tiny_out")?;
    // The same objects and materials with two triangles each: the
    // compiler's footprint for this scene's shaders, so that what is left
    // is what the file's data costs.
    let structure = baseline_of(
        weft_golden::gltf_samples::large(2 * args.objects, args.objects, args.materials),
        "structure_out",
    )?;
    // Generated after the baseline and dropped before any run: a forked
    // child's peak RSS counts the parent's pages until it execs.
    let glb = tmp.path().join("big.glb");
    let file_len = {
        let bytes = weft_golden::gltf_samples::large(args.triangles, args.objects, args.materials);
        std::fs::write(&glb, &bytes).map_err(|e| e.to_string())?;
        bytes.len()
    };
    let mut walls = Vec::new();
    let mut rss = Vec::new();
    let mut summary = String::new();
    for i in 0..args.runs.max(1) {
        let out = tmp.path().join(format!("out{i}"));
        let r = run_child(
            Command::new(&weft)
                .current_dir(root)
                .args(["build", "--scene"])
                .arg(&glb)
                .arg("-o")
                .arg(&out)
                .args(["--materials", "materials"]),
        )?;
        walls.push(r.wall.as_secs_f64());
        rss.push(r.max_rss_kib);
        summary = r.stdout.lines().last().unwrap_or_default().to_string();
    }
    walls.sort_by(f64::total_cmp);
    rss.sort_unstable();
    let median = walls[walls.len() / 2];
    let file_mib = file_len as f64 / (1 << 20) as f64;
    let rss_mib = rss[rss.len() / 2] as f64 / 1024.0;
    let report = format!(
        "# glTF scene build speed\n\n\
         Written by `cargo xtask bench gltf --write` ({} runs; `weft build --scene`, release, one fresh process and output folder per run). \
         The scene: `weft_golden::gltf_samples::large({}, {}, {})` — {} draped cloths without tangents (MikkTSpace on each), \
         {} glTF materials (half core PBR → standard, half sheen → velvet), no `auto` tier.\n\n\
         | triangles | objects | materials | file MiB | build s (min / median / max) | peak RSS MiB (median) | one-triangle scene's peak RSS MiB | (RSS − that) ÷ file | same objects and materials, 2 triangles each: peak RSS MiB | (RSS − that) ÷ file |\n\
         | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: |\n\
         | {} | {} | {} | {:.1} | {:.2} / {:.2} / {:.2} | {:.0} | {:.0} | {:.1}× | {:.0} | {:.1}× |\n\n\
         Last run: {summary}\n\nMachine: {} logical CPUs.\n",
        args.runs,
        args.triangles,
        args.objects,
        args.materials,
        args.objects,
        args.materials,
        args.triangles,
        args.objects,
        args.materials,
        file_mib,
        walls[0],
        median,
        walls[walls.len() - 1],
        rss_mib,
        baseline,
        (rss_mib - baseline) / file_mib,
        structure,
        (rss_mib - structure) / file_mib,
        std::thread::available_parallelism().map_or(0, |n| n.get()),
    );
    print!("{report}");
    if args.write {
        let path = root.join("generated/reports/gltf.md");
        std::fs::write(&path, report).map_err(|e| format!("{}: {e}", path.display()))?;
        println!("wrote {}", path.display());
    }
    Ok(())
}
