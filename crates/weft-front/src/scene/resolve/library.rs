//! The materials under a scene's materials root, each loaded the first
//! time an instance names it, and confined to the root.

use crate::diag::{Diagnostics, FileId, SourceDb, suggestion_listing};
use crate::model::Material;
use crate::scene::model::Spanned;
use codespan_reporting::diagnostic::{Diagnostic, Label};
use std::path::{Path, PathBuf};

/// The materials under a scene's root, loaded on first use.
pub(super) struct Library {
    root: PathBuf,
    /// Material folders found under the root (`<name>/<name>.toml`), sorted.
    found: Vec<String>,
    /// Materials loaded so far: name -> index into `materials`, `None` if it failed.
    loaded: Vec<(String, Option<usize>)>,
    pub materials: Vec<Material>,
}

impl Library {
    pub fn new(root: &Path) -> Self {
        let mut found: Vec<String> = std::fs::read_dir(root)
            .into_iter()
            .flatten()
            .flatten()
            .filter_map(|entry| {
                let name = entry.file_name().to_str()?.to_string();
                entry
                    .path()
                    .join(format!("{name}.toml"))
                    .is_file()
                    .then_some(name)
            })
            .collect();
        found.sort();
        Library {
            root: root.to_path_buf(),
            found,
            loaded: Vec::new(),
            materials: Vec::new(),
        }
    }

    /// The material an instance names, loading it the first time. Unknown
    /// names are reported at the instance; a material that fails to load
    /// reports its own errors (in its files) and a note at the instance.
    pub fn get(
        &mut self,
        name: &Spanned<String>,
        file: FileId,
        db: &mut SourceDb,
        diags: &mut Diagnostics,
    ) -> Option<usize> {
        if !self.root.is_dir() {
            // Reported by `parse` as `missing-root`.
            return None;
        }
        if !self.found.contains(&name.value) {
            let names: Vec<&str> = self.found.iter().map(String::as_str).collect();
            let shown = crate::includes::display_path(&self.root);
            let d = diags.error(
                "unknown-material",
                format!("unknown material `{}`", name.value),
                file,
                name.span.clone(),
                format!("no `{0}/{0}.toml` under the materials root", name.value),
            );
            d.notes.push(suggestion_listing(
                &name.value,
                &names,
                &format!("materials under `{shown}`"),
            ));
            return None;
        }
        let loaded = match self.loaded.iter().find(|(n, _)| *n == name.value) {
            Some((_, loaded)) => *loaded,
            None => {
                let path = self
                    .root
                    .join(&name.value)
                    .join(format!("{}.toml", name.value));
                if !self.inside_root(&path, name, file, diags) {
                    self.loaded.push((name.value.clone(), None));
                    return None;
                }
                let loaded = crate::load_material(&path, &self.root, db, diags).map(|m| {
                    self.materials.push(m);
                    self.materials.len() - 1
                });
                self.loaded.push((name.value.clone(), loaded));
                loaded
            }
        };
        if loaded.is_none() {
            diags.push(
                Diagnostic::note()
                    .with_code("material-error")
                    .with_message(format!(
                        "material `{}` has errors (reported above), so this instance cannot be checked",
                        name.value
                    ))
                    .with_labels(vec![
                        Label::primary(file, name.span.clone()).with_message("used here"),
                    ]),
            );
        }
        loaded
    }

    /// Whether the material file `path` an instance names really lies under
    /// the root (its folder may be a symbolic link out of it); reported at
    /// the instance's `material` when not.
    fn inside_root(
        &self,
        path: &Path,
        name: &Spanned<String>,
        file: FileId,
        diags: &mut Diagnostics,
    ) -> bool {
        let canonical = path.canonicalize().unwrap_or_else(|_| path.to_path_buf());
        if canonical.starts_with(&self.root) {
            return true;
        }
        let shown = crate::includes::display_path(&self.root);
        let d = diags.error(
            "material-outside-root",
            format!("material `{}` is outside the materials root", name.value),
            file,
            name.span.clone(),
            format!(
                "`{0}/{0}.toml` leads to `{1}`",
                name.value,
                crate::includes::display_path(&canonical)
            ),
        );
        d.notes.push(format!(
            "a scene's materials must lie under its materials root `{shown}`; the folder `{}` (or a symbolic link on the way) leads out of it: copy the material into the root",
            name.value
        ));
        false
    }
}
