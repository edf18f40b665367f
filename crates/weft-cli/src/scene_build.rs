//! `weft build --scene`: one scene's shaders, specialised per instance, and
//! its `<scene>.scene.json`, written atomically (nothing on error).

use crate::{Color, lock_output, report};
use std::path::{Path, PathBuf};
use std::time::Duration;
use weft_compiler::SceneBuildOptions;
use weft_compiler::ownership::{Input, check_apart};

/// What `weft build --scene` was asked to do.
pub struct SceneBuild<'a> {
    pub scene: &'a Path,
    /// The folder that receives `<scene>/`.
    pub out: &'a Path,
    /// A glTF scene's materials root (`--materials`).
    pub gltf_materials: Option<&'a Path>,
    pub tier_costs: Option<&'a PathBuf>,
    pub lock_wait: Duration,
    /// Model the specialisation's GPU saving (`--gpu-model`).
    pub gpu_model: bool,
}

/// Builds the scene and writes it into `out` (which then holds `<scene>/`).
pub fn build_scene_command(args: &SceneBuild, quiet: bool, color: Color) -> bool {
    let SceneBuild {
        scene,
        out,
        gltf_materials,
        tier_costs,
        lock_wait,
        gpu_model,
    } = *args;
    let started = std::time::Instant::now();
    let chooser = match weft_auto::LavapipeTierChooser::new(tier_costs.map(PathBuf::as_path)) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: {e}");
            return false;
        }
    };
    let options = SceneBuildOptions {
        tier_chooser: Some(&chooser),
        gltf_materials,
    };
    let mut result = match weft_compiler::build_scene(scene, &options) {
        Ok(r) => r,
        Err((db, diags)) => {
            report(&db, &diags, color);
            return false;
        }
    };
    if let Some((db, warnings)) = &result.warnings {
        report(db, warnings, color);
    }
    // Only the scene's own folder is replaced: other scenes (and anything
    // else) in `out` stay.
    let prefix = format!("{}/", result.name);
    // Moved, not copied: a glTF scene's mesh files may be large.
    let mut files: std::collections::BTreeMap<String, Vec<u8>> = std::mem::take(&mut result.files)
        .into_iter()
        .filter_map(|(name, bytes)| Some((name.strip_prefix(&prefix)?.to_string(), bytes)))
        .collect();
    // Self-contained: the baked LUTs the shaders bind ride along at the
    // path their bindings name (`luts/…`), taken from ./generated when it
    // has them, else baked. Texture files are in `files` already.
    let mut library = std::collections::BTreeMap::new();
    let generated = Path::new("generated");
    weft_compiler::library::add_library_files(
        &mut library,
        generated.is_dir().then_some(generated),
    );
    files.extend(
        library
            .into_iter()
            .filter(|(path, _)| path.starts_with("luts/")),
    );
    // And the built-in meshes the instances draw, at the path their
    // `meshes` entries name (`meshes/<name>.mesh`): an engine reads a path
    // in the scene folder first (docs/scenes.md), and a scene built here has
    // no library above it. glTF meshes are in `files` already.
    match weft_render::builtin_mesh_files() {
        Ok(mut builtin) => files.extend(
            result
                .metadata
                .meshes
                .values()
                .filter_map(|m| m.path.as_ref())
                .filter_map(|p| Some((p.clone(), builtin.remove(p)?))),
        ),
        Err(e) => {
            eprintln!("error: the built-in meshes: {e}; nothing was written");
            return false;
        }
    }
    // Same machinery as a library build: `<out>/.<scene>.lock`, atomic swap.
    let dir = out.join(&result.name);
    let inputs = [
        Input {
            what: "scene file",
            path: scene,
        },
        Input {
            what: "materials root",
            path: &result.materials_root,
        },
    ];
    if let Err(e) = check_apart(&dir, &inputs) {
        eprintln!("error: {e}; nothing was written");
        return false;
    }
    // Modelled once the output is known to lie apart from the inputs (a
    // refused output costs no compile).
    if gpu_model {
        let families: Vec<String> = weft_gpu_stats::DEFAULT_FAMILIES
            .iter()
            .map(|f| f.to_string())
            .collect();
        match crate::scene_model::model_saving(
            &result.metadata,
            &files,
            &result.materials_root,
            &families,
        ) {
            Ok(modelled) => {
                if let Some(f) = &mut result.metadata.funnel {
                    f.modelled = modelled;
                }
                files.insert(
                    format!("{}.scene.json", result.name),
                    weft_compiler::scene::metadata_json(&result.metadata),
                );
            }
            Err(e) => {
                eprintln!("error: modelling the GPU cost (--gpu-model): {e}\nnothing was written");
                return false;
            }
        }
    }
    let Some(lock) = lock_output(&dir, lock_wait, quiet) else {
        return false;
    };
    if let Err(e) = lock.write(&files, &[]) {
        eprintln!(
            "error: cannot write `{}`: {e}; the old output is unchanged",
            dir.display()
        );
        return false;
    }
    if !quiet {
        for inst in &result.metadata.instances {
            if let Some(choice) = &inst.tier_choice {
                println!(
                    "{}",
                    weft_auto::describe_choice(&inst.name, &inst.tier, choice)
                );
            }
        }
        if let Some(f) = &result.metadata.funnel {
            println!("{}", describe_funnel(f));
        }
        if let Some(fixed) = &result.metadata.static_lighting {
            let what = if fixed.sh.is_some() {
                "light and SH"
            } else {
                "light"
            };
            println!(
                "static lighting: the scene's {what} folded into every shader (the frame's are not read)"
            );
        }
        println!(
            "built scene `{}`: {} instance(s), {} shader(s), {} file(s) into {} in {:.2}s",
            result.name,
            result.metadata.instances.len(),
            result.metadata.shaders.len(),
            files.len(),
            out.join(&result.name).display(),
            started.elapsed().as_secs_f64()
        );
    }
    true
}

/// The funnel in one line: `funnel: showroom.glb: 8 materials → 8 used → 14
/// instances → 9 generic variants → 7 shaders (1.2 MiB)`.
pub fn describe_funnel(f: &weft_meta::scene::SceneFunnel) -> String {
    let mut steps = Vec::new();
    if let (Some(file), Some(all), Some(used)) =
        (&f.gltf_file, f.gltf_materials, f.gltf_materials_used)
    {
        steps.push(format!("{file}: {all} material(s)"));
        steps.push(format!("{used} used by nodes"));
    }
    steps.push(format!("{} instance(s)", f.instances));
    steps.push(format!("{} generic variant(s)", f.generic_variants));
    steps.push(format!(
        "{} specialised shader(s) ({:.1} KiB of shader files)",
        f.shaders,
        f.shader_bytes as f64 / 1024.0
    ));
    if f.modelled.is_empty() {
        format!(
            "funnel: {} (the GPU cost saving: add --gpu-model)",
            steps.join(" → ")
        )
    } else {
        steps.push(crate::scene_model::describe(&f.modelled));
        format!("funnel: {}", steps.join(" → "))
    }
}
