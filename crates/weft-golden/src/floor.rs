//! The cost floor of the shading benchmark: an unlit fill, a material that
//! draws the same geometry through the same vertex stage (lib/forward.wgsl)
//! and returns a flat colour, so its frame time is what any material pays
//! before shading (rasterisation, the vertex stage, blending into the
//! target). "standard fast within 2× of an unlit fill" is measured against
//! it in the same run.

use std::path::{Path, PathBuf};

/// Its name in the reports.
pub const FLOOR_MATERIAL: &str = "unlit_fill";

const TOML: &str = r#"[material]
name = "unlit_fill"
label = "Unlit fill"
label_zh = "无光照填充"
description = "The benchmark's cost floor: the standard vertex stage and a flat colour."
source = "unlit_fill.wgsl"
requires = ["position", "normal", "tangent", "uv0"]

[params.color]
type = "color"
default = [0.5, 0.5, 0.5, 1.0]
label = "Colour"

[[tier]]
name = "fast"

[[tier]]
name = "reference"

[[pass]]
name = "forward"
vertex = "vs_main"
fragment = "fs_main"
"#;

const WGSL: &str = r#"// @include "lib/forward.wgsl"

@fragment
fn fs_main(in: WeftVaryings) -> @location(0) vec4<f32> {
    return vec4<f32>(material.color.rgb, 1.0);
}
"#;

/// Builds the unlit fill against `materials_dir`'s `lib/` into
/// `work/generated`; returns its metadata path.
pub fn build(materials_dir: &Path, work: &Path) -> Result<PathBuf, String> {
    let src = work.join("materials");
    let dir = src.join(FLOOR_MATERIAL);
    let io = |p: &Path, e: std::io::Error| format!("{}: {e}", p.display());
    std::fs::create_dir_all(&dir).map_err(|e| io(&dir, e))?;
    copy_dir(&materials_dir.join("lib"), &src.join("lib"))?;
    for (name, text) in [("unlit_fill.toml", TOML), ("unlit_fill.wgsl", WGSL)] {
        let p = dir.join(name);
        std::fs::write(&p, text).map_err(|e| io(&p, e))?;
    }
    let built = weft_compiler::build_library(&src, &Default::default(), &|_, _, _| {})
        .map_err(|(db, d)| format!("the unlit fill does not build:\n{}", d.render_plain(&db)))?;
    let out = work.join("generated");
    weft_compiler::output::write_atomically(&out, &built.files, &[]).map_err(|e| io(&out, e))?;
    Ok(out
        .join(FLOOR_MATERIAL)
        .join(format!("{FLOOR_MATERIAL}.meta.json")))
}

pub(crate) fn copy_dir(from: &Path, to: &Path) -> Result<(), String> {
    std::fs::create_dir_all(to).map_err(|e| format!("{}: {e}", to.display()))?;
    let entries = std::fs::read_dir(from).map_err(|e| format!("{}: {e}", from.display()))?;
    for e in entries {
        let p = e.map_err(|e| e.to_string())?.path();
        let t = to.join(p.file_name().unwrap_or_default());
        if p.is_dir() {
            copy_dir(&p, &t)?;
        } else {
            std::fs::copy(&p, &t).map_err(|e| format!("{}: {e}", p.display()))?;
        }
    }
    Ok(())
}
