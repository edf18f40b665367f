//! `weft preview`: render one material variant, or a whole scene, to a PNG.

use crate::library_build::build;
use crate::{Color, report};
use clap::ValueEnum;
use std::path::{Path, PathBuf};
use weft_compiler::{BuildOptions, output};

pub(crate) const PREVIEW_EXAMPLES: &str = "Examples:
  weft preview materials/standard/standard.toml -o out.png
  weft preview materials/standard/standard.toml -o gold.png --preset gold --scene cloth
  weft preview generated/standard/standard.meta.json -o p.png --tier reference --keyword NORMAL_MAP=on
  weft preview generated/standard/standard.meta.json -o p.png --variant fast.normal_map-off.sphere_map-add
  weft preview materials/standard/standard.toml -o p.png --set base_color=0.9,0.2,0.1 --set roughness=0.2
  weft preview materials/standard/standard.toml -o p.png --texture base_map=my_albedo.png --keyword NORMAL_MAP=on --texture normal_map=my_normal.png
  weft preview materials/standard/standard.toml -o p.png --size 512x384 --light-dir -1,1,0.5 --tonemap neutral --hdr-out p.pfm
  weft preview --scene-file scenes/fitting_room.scene.toml -o room.png --width 640 --height 400
  weft preview --scene-dir generated/scenes/swatch_book -o book.png --spirv
  weft preview --scene-dir generated/scenes/swatch_book -o generic.png --library generated

The scene has a directional light (direction towards the light, also the sky's sun) and a procedural
sky: prefiltered cube, L2 SH irradiance and the baked split-sum LUT. Colours given with --set are
as edited (sRGB unless the parameter is an HDR colour). A scene is drawn whole from its built
`.scene.json` (--scene-file builds the manifest into a temporary folder first), every instance with its
specialised shader, or with the library's generic variants (--library). Needs a Vulkan driver: on
Debian/Ubuntu `apt-get install mesa-vulkan-drivers`.";

/// What a scene preview does not take: a material and its options.
const NOT_WITH_A_SCENE: [&str; 9] = [
    "path", "variant", "tier", "keywords", "sets", "textures", "preset", "scene", "mesh",
];

#[derive(clap::Args)]
pub(crate) struct PreviewArgs {
    /// A material .toml (built in memory into a temporary folder) or a generated .meta.json.
    #[arg(required_unless_present_any = ["scene_file", "scene_dir"])]
    path: Option<PathBuf>,
    // Boxed: keeps `Command` (main.rs) small.
    #[command(flatten)]
    scene_mode: Box<SceneArgs>,
    /// Output PNG (tone-mapped sRGB8).
    #[arg(long, short, default_value = "preview.png")]
    out: PathBuf,
    /// A variant id (aliases allowed); sets the tier and the static keywords.
    #[arg(long, conflicts_with = "tier")]
    variant: Option<String>,
    /// Quality tier (default: the material's default tier).
    #[arg(long)]
    tier: Option<String>,
    /// Keyword value, NAME=VALUE (toggles: on/off); repeatable.
    #[arg(long = "keyword", value_name = "NAME=VALUE")]
    keywords: Vec<String>,
    /// Parameter value, NAME=VALUE (vectors and colours as comma lists); repeatable.
    #[arg(long = "set", value_name = "NAME=VALUE")]
    sets: Vec<String>,
    /// A texture parameter from a PNG file, NAME=PATH (any colour type; texels
    /// as stored: sRGB when the parameter declares `srgb`; up to 8192x8192;
    /// a 1-pixel-high PNG for a gradient); repeatable.
    #[arg(long = "texture", value_name = "NAME=PATH")]
    textures: Vec<String>,
    /// Apply a preset first (then --variant/--tier/--keyword/--set).
    #[arg(long)]
    preset: Option<String>,
    /// Built-in scene.
    #[arg(long, value_enum, default_value_t = SceneArg::Sphere, conflicts_with = "mesh")]
    scene: SceneArg,
    /// Draw on a mesh of a glTF file instead: `my.glb` (its first mesh's first
    /// primitive) or `my.glb#M/P` (mesh M, primitive P), framed whole;
    /// normals and MikkTSpace tangents generated where the file has none.
    #[arg(long, value_name = "FILE[#M/P]")]
    mesh: Option<String>,
    /// Image size, WxH.
    #[arg(long, default_value = "256x256", value_name = "WxH")]
    size: String,
    /// Image width (with --height; instead of --size).
    #[arg(long, requires = "height", conflicts_with = "size")]
    width: Option<u32>,
    /// Image height (with --width).
    #[arg(long, requires = "width", conflicts_with = "size")]
    height: Option<u32>,
    /// Direction towards the light, x,y,z (world +Y up, camera on +Z).
    #[arg(long, value_name = "X,Y,Z", allow_hyphen_values = true)]
    light_dir: Option<String>,
    /// Tone-mapping operator.
    #[arg(long, value_enum, default_value_t = TonemapArg::Aces)]
    tonemap: TonemapArg,
    /// Exposure multiplier applied before tone mapping.
    #[arg(long, default_value_t = 1.0)]
    exposure: f32,
    /// Also write the linear HDR image as a PFM (RGB f32) file.
    #[arg(long, value_name = "FILE")]
    hdr_out: Option<PathBuf>,
    /// Draw from the WGSL or the SPIR-V file of the variant.
    #[arg(long, value_enum, default_value_t = ShaderArg::Wgsl)]
    shader: ShaderArg,
    /// Draw from the SPIR-V files (same as --shader spirv).
    #[arg(long, conflicts_with = "shader")]
    spirv: bool,
    /// Render into an Rgba32Float target instead of Rgba16Float.
    #[arg(long)]
    f32: bool,
    /// Print the Vulkan adapter's details (name, vendor/device ids, driver, type).
    #[arg(long)]
    adapter_info: bool,
}

/// The scene mode of `weft preview`.
#[derive(clap::Args)]
#[command(group = clap::ArgGroup::new("scene_source").args(["scene_file", "scene_dir"]))]
struct SceneArgs {
    /// A scene manifest (`scenes/<name>.scene.toml`) or a glTF 2.0 file (`.gltf`, `.glb`):
    /// built into a temporary folder and drawn whole.
    #[arg(long, value_name = "FILE", conflicts_with = "scene_dir", conflicts_with_all = NOT_WITH_A_SCENE)]
    scene_file: Option<PathBuf>,
    /// An already built scene: the folder holding `<scene>.scene.json`, that file, or the output
    /// folder of `weft build --scene` (holding one `<scene>/`).
    #[arg(long, value_name = "DIR", conflicts_with_all = NOT_WITH_A_SCENE)]
    scene_dir: Option<PathBuf>,
    /// With a scene: draw every instance with the generic library variant from this generated
    /// folder (its values set as parameters) instead of the specialised shaders.
    #[arg(long, value_name = "GENERATED", requires = "scene_source")]
    library: Option<PathBuf>,
    /// With a scene: draw it as material variant NAME shows it (glTF
    /// KHR_materials_variants): each instance the variant replaces drawn by its stand-in.
    #[arg(long, value_name = "NAME", requires = "scene_source")]
    material_variant: Option<String>,
}

#[derive(Clone, Copy, ValueEnum)]
enum SceneArg {
    Sphere,
    Cloth,
    Swatch,
    /// The character bust: head (face UVs), eyes, hair cards, shoulders.
    Bust,
}

#[derive(Clone, Copy, ValueEnum)]
enum TonemapArg {
    Aces,
    Neutral,
    Clamp,
}

#[derive(Clone, Copy, ValueEnum)]
enum ShaderArg {
    Wgsl,
    Spirv,
}

fn split_pair(s: &str, flag: &str) -> Result<(String, String), String> {
    match s.split_once('=') {
        Some((k, v)) if !k.trim().is_empty() => Ok((k.trim().to_string(), v.trim().to_string())),
        _ => Err(format!("{flag} expects NAME=VALUE, got `{s}`")),
    }
}

pub(crate) fn preview(args: &PreviewArgs, quiet: bool, color: Color) -> Result<(), String> {
    if args.scene_mode.scene_file.is_some() || args.scene_mode.scene_dir.is_some() {
        return preview_scene(args, quiet, color);
    }
    use weft_render::*;
    let started = std::time::Instant::now();
    let path = args
        .path
        .as_ref()
        .ok_or("give a material, --scene-file or --scene-dir")?;
    let options = preview_options(args)?;
    let mut mopts = MaterialOptions {
        preset: args.preset.clone(),
        variant: args.variant.clone(),
        tier: args.tier.clone(),
        ..MaterialOptions::default()
    };
    for k in &args.keywords {
        mopts.keywords.push(split_pair(k, "--keyword")?);
    }
    for s in &args.sets {
        mopts.sets.push(split_pair(s, "--set")?);
    }
    for t in &args.textures {
        let (name, path) = split_pair(t, "--texture")?;
        mopts.textures.push((name, PathBuf::from(path)));
    }

    // A .toml is compiled into a temporary folder; a .meta.json is used as is.
    let _tmp;
    let meta_path = if path.extension().is_some_and(|e| e == "toml") {
        let result = build(std::slice::from_ref(path), &BuildOptions::default(), true);
        let out = match result {
            Ok(out) => out,
            Err((db, diags)) => {
                report(&db, &diags, color);
                return Err(format!("`{}` does not compile", path.display()));
            }
        };
        let tmp =
            tempfile::tempdir().map_err(|e| format!("cannot create a temporary folder: {e}"))?;
        let dir = tmp.path().join("generated");
        output::write_atomically(&dir, &out.files, &[])
            .map_err(|e| format!("cannot write `{}`: {e}", dir.display()))?;
        let name = &out.materials.first().ok_or("no material was built")?.name;
        let meta = dir.join(name).join(format!("{name}.meta.json"));
        _tmp = tmp;
        meta
    } else {
        path.clone()
    };
    let mut material = Material::load(&meta_path).map_err(|e| e.to_string())?;
    mopts.apply(&mut material).map_err(|e| e.to_string())?;
    let luts = Luts::for_metadata(&meta_path).map_err(|e| e.to_string())?;
    print_adapter_info(args)?;
    let (image, adapter) = render_preview(&material, &luts, &options).map_err(|e| e.to_string())?;
    save(args, &image)?;
    if !quiet {
        let variant = material
            .current_variant()
            .map(|v| v.requested.id.clone())
            .unwrap_or_default();
        println!(
            "rendered {} variant {variant} ({}, {}x{}) on {adapter} in {:.2}s -> {}{}",
            material.name(),
            args.mesh.as_deref().unwrap_or(options.scene.name()),
            options.width,
            options.height,
            started.elapsed().as_secs_f64(),
            args.out.display(),
            non_finite_note(&image)
        );
    }
    Ok(())
}

/// `--mesh FILE[#M/P]`: the glTF primitive as a mesh to draw.
fn gltf_mesh(spec: &str) -> Result<weft_render::Mesh, String> {
    let (file, at) = spec.split_once('#').unwrap_or((spec, "0/0"));
    let (m, p) = at.split_once('/').unwrap_or((at, "0"));
    let index = |s: &str| {
        s.trim().parse::<usize>().map_err(|_| {
            format!("--mesh expects FILE or FILE#M/P (mesh and primitive indices), got `{spec}`")
        })
    };
    let mut cache = weft_front::gltf::GltfCache::default();
    let mesh = cache
        .mesh(std::path::Path::new(file), index(m)?, index(p)?, None, None)
        .map_err(|e| format!("{e}\n  = {}", e.hint))?;
    for w in &cache.warnings {
        eprintln!("warning: {w}");
    }
    for g in &mesh.generated {
        eprintln!("note: {}: weft generated {g}", file);
    }
    Ok(mesh.data())
}

/// Size, light, format and language from the arguments (both modes).
fn preview_options(args: &PreviewArgs) -> Result<weft_render::PreviewOptions, String> {
    use weft_render::*;
    let (width, height) = match (args.width, args.height) {
        (Some(w), Some(h)) if w > 0 && h > 0 => (w, h),
        (Some(_), Some(_)) => return Err("--width and --height must be positive".into()),
        _ => args
            .size
            .split_once(['x', 'X'])
            .and_then(|(w, h)| Some((w.trim().parse::<u32>().ok()?, h.trim().parse::<u32>().ok()?)))
            .filter(|&(w, h)| w > 0 && h > 0)
            .ok_or_else(|| format!("--size expects WxH, e.g. 256x256, got `{}`", args.size))?,
    };
    let light_direction = match &args.light_dir {
        Some(s) => {
            let v: Vec<f32> = s
                .split(',')
                .map(|x| x.trim().parse::<f32>())
                .collect::<std::result::Result<_, _>>()
                .map_err(|_| format!("--light-dir expects x,y,z, got `{s}`"))?;
            match v[..] {
                [x, y, z] if x * x + y * y + z * z > 0.0 => Some([x, y, z]),
                _ => return Err(format!("--light-dir expects a non-zero x,y,z, got `{s}`")),
            }
        }
        None => None,
    };
    let mesh = match &args.mesh {
        Some(spec) => Some(std::sync::Arc::new(gltf_mesh(spec)?)),
        None => None,
    };
    Ok(PreviewOptions {
        mesh,
        scene: match args.scene {
            SceneArg::Sphere => SceneKind::Sphere,
            SceneArg::Cloth => SceneKind::Cloth,
            SceneArg::Swatch => SceneKind::Swatch,
            SceneArg::Bust => SceneKind::Bust,
        },
        width,
        height,
        light_direction,
        format: if args.f32 {
            ColorFormat::Rgba32Float
        } else {
            ColorFormat::Rgba16Float
        },
        language: match (args.spirv, args.shader) {
            (true, _) | (_, ShaderArg::Spirv) => ShaderLanguage::SpirV,
            _ => ShaderLanguage::Wgsl,
        },
        ..PreviewOptions::default()
    })
}

fn print_adapter_info(args: &PreviewArgs) -> Result<(), String> {
    if args.adapter_info {
        let gpu = weft_render::Gpu::new().map_err(|e| e.to_string())?;
        let i = gpu.adapter_info();
        println!(
            "adapter: {}\n  vendor 0x{:04x}, device 0x{:04x}, type {:?}, backend {:?}\n  driver: {} {}",
            i.name, i.vendor, i.device, i.device_type, i.backend, i.driver, i.driver_info
        );
    }
    Ok(())
}

/// Writes the tone-mapped PNG and, when asked, the linear PFM.
fn save(args: &PreviewArgs, image: &weft_render::HdrImage) -> Result<(), String> {
    use weft_render::Tonemap;
    let tonemap = match args.tonemap {
        TonemapArg::Aces => Tonemap::Aces,
        TonemapArg::Neutral => Tonemap::Neutral,
        TonemapArg::Clamp => Tonemap::Clamp,
    };
    image
        .save_png(&args.out, tonemap, args.exposure)
        .map_err(|e| e.to_string())?;
    if let Some(p) = &args.hdr_out {
        image.save_pfm(p).map_err(|e| e.to_string())?;
    }
    Ok(())
}

fn non_finite_note(image: &weft_render::HdrImage) -> String {
    match image.non_finite_count() {
        0 => String::new(),
        bad => format!(" ({bad} non-finite pixels)"),
    }
}

/// `--scene-file` / `--scene-dir`: the whole scene, from its `.scene.json`.
fn preview_scene(args: &PreviewArgs, quiet: bool, color: Color) -> Result<(), String> {
    use weft_render::*;
    let started = std::time::Instant::now();
    let options = preview_options(args)?;
    // A manifest is built into a temporary folder with the LUTs beside it,
    // as `weft build` lays a project out; a built scene is read in place.
    let tmp = tempfile::tempdir().map_err(|e| format!("cannot create a temporary folder: {e}"))?;
    let scene_json = match (&args.scene_mode.scene_file, &args.scene_mode.scene_dir) {
        (Some(manifest), _) => build_scene_into(manifest, tmp.path(), color)?,
        (None, Some(dir)) => find_scene_json(dir)?,
        (None, None) => return Err("give --scene-file or --scene-dir".into()),
    };
    let luts = match Luts::for_scene(&scene_json) {
        Ok(l) => l,
        // A scene built on its own (`weft build --scene -o out`) has no LUTs: bake them.
        Err(_) => {
            let dir = tmp.path().join("baked");
            let mut files = std::collections::BTreeMap::new();
            weft_compiler::library::add_library_files(&mut files, None);
            output::write_atomically(&dir, &files, &[])
                .map_err(|e| format!("cannot write `{}`: {e}", dir.display()))?;
            Luts::load_dir(&dir).map_err(|e| e.to_string())?
        }
    };
    let mut scene = SceneFile::load(&scene_json).map_err(|e| e.to_string())?;
    if let Some(variant) = &args.scene_mode.material_variant {
        scene.metadata = scene.metadata.showing_variant(variant)?;
    }
    let shaders = match &args.scene_mode.library {
        Some(generated) => SceneShaders::Library(generated.clone()),
        None => SceneShaders::Specialised,
    };
    print_adapter_info(args)?;
    let (image, adapter) =
        render_scene_preview(&scene, &shaders, &luts, &options).map_err(|e| e.to_string())?;
    save(args, &image)?;
    if !quiet {
        let meta = &scene.metadata;
        println!(
            "rendered scene {}{} ({} instance(s), {} {} shader(s), {:?}, {}x{}) on {adapter} in {:.2}s -> {}{}",
            meta.name,
            args.scene_mode
                .material_variant
                .as_ref()
                .map_or_else(String::new, |v| format!(" as variant `{v}` shows it")),
            meta.instances.len(),
            meta.shaders.len(),
            if args.scene_mode.library.is_some() {
                "library"
            } else {
                "specialised"
            },
            options.language,
            options.width,
            options.height,
            started.elapsed().as_secs_f64(),
            args.out.display(),
            non_finite_note(&image)
        );
    }
    Ok(())
}

/// Builds the manifest into `out` (scene files under `<scene>/`, LUTs under
/// `luts/`, reused from the project's `generated/` when it has them) and
/// returns the `.scene.json`.
fn build_scene_into(manifest: &Path, out: &Path, color: Color) -> Result<PathBuf, String> {
    let chooser = weft_auto::LavapipeTierChooser::new(None)?;
    let options = weft_compiler::SceneBuildOptions {
        tier_chooser: Some(&chooser),
        ..Default::default()
    };
    let built = match weft_compiler::build_scene(manifest, &options) {
        Ok(b) => b,
        Err((db, diags)) => {
            report(&db, &diags, color);
            return Err(format!("`{}` does not build", manifest.display()));
        }
    };
    if let Some((db, warnings)) = &built.warnings {
        report(db, warnings, color);
    }
    let mut files = built.files.clone();
    let project = manifest
        .parent()
        .map(|d| d.join("../generated"))
        .filter(|d| d.is_dir());
    weft_compiler::library::add_library_files(&mut files, project.as_deref());
    let dir = out.join("scenes");
    output::write_atomically(&dir, &files, &[])
        .map_err(|e| format!("cannot write `{}`: {e}", dir.display()))?;
    Ok(dir
        .join(&built.name)
        .join(format!("{}.scene.json", built.name)))
}

/// The `.scene.json` of a built scene: the file itself, the scene's folder,
/// or an output folder holding exactly one scene folder (`<out>/<scene>/`).
fn find_scene_json(path: &Path) -> Result<PathBuf, String> {
    if path.is_file() {
        return Ok(path.to_path_buf());
    }
    let listed = |dir: &Path| -> Result<Vec<PathBuf>, String> {
        let entries = std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        let mut paths: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        paths.sort();
        Ok(paths)
    };
    let is_scene = |p: &Path| p.is_file() && p.to_string_lossy().ends_with(".scene.json");
    let entries = listed(path)?;
    let mut found: Vec<PathBuf> = entries.iter().filter(|p| is_scene(p)).cloned().collect();
    if found.is_empty() {
        for dir in entries.iter().filter(|p| p.is_dir()) {
            let name = dir.file_name().unwrap_or_default().to_string_lossy();
            let json = dir.join(format!("{name}.scene.json"));
            if is_scene(&json) {
                found.push(json);
            }
        }
    }
    match found.len() {
        1 => Ok(found.remove(0)),
        0 => Err(format!(
            "`{}` holds no built scene (`<scene>.scene.json`); build one with `weft build --scene`",
            path.display()
        )),
        _ => Err(format!(
            "`{}` holds several scenes ({}); name one",
            path.display(),
            found
                .iter()
                .map(|p| p.display().to_string())
                .collect::<Vec<_>>()
                .join(", ")
        )),
    }
}
