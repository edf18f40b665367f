//! `cargo xtask bench film`: the laser film's fast form against its spectral reference (weft_golden::film).

use std::path::Path;
use std::process::ExitCode;

/// Measures the laser film (`weft_golden::film`), prints the table and, with
/// `write`, rewrites generated/reports/laser-film.md and the table between
/// `<!-- weft:film:… -->` in materials/laser/README.md.
pub(crate) fn bench_film(root: &Path, write: bool, command: &str) -> ExitCode {
    use weft_golden::film;
    let run = || -> Result<(), String> {
        let code = film::FilmCode::load(&root.join("materials"))?;
        let gpu = weft_render::Gpu::new().map_err(|e| e.to_string())?;
        let measurements = film::CASES
            .iter()
            .map(|case| film::measure(&gpu, &code, case))
            .collect::<Result<Vec<_>, _>>()?;
        print!("{}", film::markdown_table(&measurements));
        if write {
            let report = root.join("generated/reports/laser-film.md");
            let text = film::markdown_report(&measurements, &gpu.describe(), command);
            std::fs::write(&report, text).map_err(|e| format!("{}: {e}", report.display()))?;
            println!("wrote {}", report.display());
            let readme = root.join("materials/laser/README.md");
            let text = std::fs::read_to_string(&readme)
                .map_err(|e| format!("{}: {e}", readme.display()))?;
            let new = weft_golden::shading::replace_marked(
                &text,
                "film",
                &film::markdown_table(&measurements),
            )
            .ok_or_else(|| {
                format!(
                    "{}: no <!-- weft:film:begin/end --> markers",
                    readme.display()
                )
            })?;
            if new != text {
                std::fs::write(&readme, new).map_err(|e| format!("{}: {e}", readme.display()))?;
                println!("updated the film table in {}", readme.display());
            }
        }
        Ok(())
    };
    match run() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
