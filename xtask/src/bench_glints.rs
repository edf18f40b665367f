//! `cargo xtask bench glints`: the glitter material's glint checks (weft_golden::glints).

use std::path::Path;
use std::process::ExitCode;

/// Measures the glitter glints (`weft_golden::glints`), prints the table and,
/// with `write`, rewrites generated/reports/glitter.glints.md and the table
/// between `<!-- weft:glints:… -->` in materials/glitter/README.md. Fails
/// when a bound is broken (after writing: the report says which).
pub(crate) fn bench_glints(root: &Path, write: bool, command: &str) -> ExitCode {
    use weft_golden::glints;
    let run = || -> Result<Vec<String>, String> {
        let report = glints::measure(&root.join("generated"), &mut |s| eprintln!("{s}"))?;
        print!("{}", glints::markdown_table(&report));
        if write {
            let path = root.join(format!("generated/reports/{}.glints.md", glints::MATERIAL));
            std::fs::write(&path, glints::markdown_report(&report, command))
                .map_err(|e| format!("{}: {e}", path.display()))?;
            println!("wrote {}", path.display());
            let readme = root.join(format!("materials/{}/README.md", glints::MATERIAL));
            let text = std::fs::read_to_string(&readme)
                .map_err(|e| format!("{}: {e}", readme.display()))?;
            let new = weft_golden::shading::replace_marked(
                &text,
                "glints",
                &glints::markdown_table(&report),
            )
            .ok_or_else(|| {
                format!(
                    "{}: no <!-- weft:glints:begin/end --> markers",
                    readme.display()
                )
            })?;
            if new != text {
                std::fs::write(&readme, new).map_err(|e| format!("{}: {e}", readme.display()))?;
                println!("updated the glint table in {}", readme.display());
            }
        }
        Ok(glints::failures(&report))
    };
    match run() {
        Ok(failures) if failures.is_empty() => ExitCode::SUCCESS,
        Ok(failures) => {
            for f in failures {
                eprintln!("error: glint bound broken: {f}");
            }
            ExitCode::FAILURE
        }
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
