//! Compiling a material held in memory, reading nothing from disk: the front
//! end's [`weft_front::load_material_in_memory`] (parse, includes, checks),
//! then what [`crate::build::library::compile_material`] does per material —
//! prelude, compose, naga parse + validate once, the pass interface check,
//! and per variant specialise, validate, emit every language and reflect —
//! on the calling thread, for a few variants only if asked. The
//! material-level metadata is assembled too. For the fuzz targets (`fuzz/`)
//! and tools that keep sources in memory; builds use `library`.

use crate::compile::variant::{self, CompiledVariant};
use crate::compile::{compose, metadata, prelude};
use codespan_reporting::diagnostic::{Diagnostic, Label};
use std::path::Path;
use weft_front::model::Material;
use weft_front::{Diagnostics, SourceDb, variants};

/// What [`compile_in_memory`] produced: the checked material and the
/// variants compiled, in variant order.
pub struct InMemoryBuild {
    pub material: Material,
    pub variants: Vec<CompiledVariant>,
}

/// Loads a material from `toml_text` and `files` (WGSL text by path, paths
/// relative to `root`, as for [`weft_front::load_material_in_memory`]) and
/// compiles at most `max_variants` of its variants, spread evenly over the
/// variant list (the first always among them). `None` on the first
/// error, with the reasons in `diags` (the same diagnostics a build gives).
pub fn compile_in_memory(
    toml_path: &str,
    toml_text: &str,
    files: &[(String, String)],
    root: &Path,
    max_variants: usize,
    db: &mut SourceDb,
    diags: &mut Diagnostics,
) -> Option<InMemoryBuild> {
    let m = weft_front::load_material_in_memory(toml_path, toml_text, files, root, db, diags)?;
    let prelude = prelude::generate(&m);
    let composed = compose::compose(&m, &prelude, db);
    let (module, _info) = compose::parse_and_validate(&composed, &m, diags)?;
    if !crate::compile::material::check_interface(&m, &module, diags) {
        return None;
    }
    let fallback = crate::compile::half::fallback_module(&m, &prelude, db, diags)?;
    let fallback = fallback.as_ref().map(|(_, f)| f);
    // The material-level metadata (what `compile_material` records).
    let _ = (
        metadata::groups(&m),
        metadata::parameters(&m, &prelude),
        metadata::keywords(&m),
        metadata::tiers(&m),
        metadata::presets(&m),
        metadata::passes(&m),
        metadata::vertex_inputs(&m),
    );
    let keys = variants::variants(&m);
    let mut compiled = Vec::new();
    for key in spread(&keys, max_variants) {
        match variant::compile_variant(&m, &module, fallback, key, &prelude) {
            Ok(v) => compiled.push(v),
            Err(msg) => {
                diags.push(
                    Diagnostic::error()
                        .with_code("variant")
                        .with_message(msg)
                        .with_labels(vec![
                            Label::primary(m.decl.file, m.decl.span.clone())
                                .with_message("in this material"),
                        ]),
                );
                return None;
            }
        }
    }
    Some(InMemoryBuild {
        material: m,
        variants: compiled,
    })
}

/// At most `n` of `items`, evenly spaced, the first included.
fn spread<T>(items: &[T], n: usize) -> impl Iterator<Item = &T> {
    let len = items.len();
    let n = n.min(len);
    (0..n).map(move |i| &items[i * len / n])
}
