//! `weft preview`: render one material variant to a PNG.

use crate::{Color, build, report};
use clap::ValueEnum;
use std::path::PathBuf;
use weft_compiler::{BuildOptions, output};

pub(crate) const PREVIEW_EXAMPLES: &str = "Examples:
  weft preview materials/standard/standard.toml -o out.png
  weft preview materials/standard/standard.toml -o gold.png --preset gold --scene cloth
  weft preview generated/standard/standard.meta.json -o p.png --tier reference --keyword NORMAL_MAP=on
  weft preview generated/standard/standard.meta.json -o p.png --variant fast.normal_map-off.sphere_map-add
  weft preview materials/standard/standard.toml -o p.png --set base_color=0.9,0.2,0.1 --set roughness=0.2
  weft preview materials/standard/standard.toml -o p.png --size 512x384 --light-dir -1,1,0.5 --tonemap neutral --hdr-out p.pfm

The scene has a directional light (direction towards the light, also the sky's sun) and a procedural
sky: prefiltered cube, L2 SH irradiance and the baked split-sum LUT. Colours given with --set are
as edited (sRGB unless the parameter is an HDR colour). Needs a Vulkan driver: on Debian/Ubuntu
`apt-get install mesa-vulkan-drivers`.";

#[derive(clap::Args)]
pub(crate) struct PreviewArgs {
    /// A material .toml (built in memory into a temporary folder) or a generated .meta.json.
    path: PathBuf,
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
    /// Apply a preset first (then --variant/--tier/--keyword/--set).
    #[arg(long)]
    preset: Option<String>,
    /// Built-in scene.
    #[arg(long, value_enum, default_value_t = SceneArg::Sphere)]
    scene: SceneArg,
    /// Image size, WxH.
    #[arg(long, default_value = "256x256", value_name = "WxH")]
    size: String,
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
    /// Render into an Rgba32Float target instead of Rgba16Float.
    #[arg(long)]
    f32: bool,
    /// Print the Vulkan adapter's details (name, vendor/device ids, driver, type).
    #[arg(long)]
    adapter_info: bool,
}

#[derive(Clone, Copy, ValueEnum)]
enum SceneArg {
    Sphere,
    Cloth,
    Swatch,
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
    use weft_render::*;
    let started = std::time::Instant::now();
    let (w, h) = args
        .size
        .split_once(['x', 'X'])
        .and_then(|(w, h)| Some((w.trim().parse::<u32>().ok()?, h.trim().parse::<u32>().ok()?)))
        .filter(|&(w, h)| w > 0 && h > 0)
        .ok_or_else(|| format!("--size expects WxH, e.g. 256x256, got `{}`", args.size))?;
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

    // A .toml is compiled into a temporary folder; a .meta.json is used as is.
    let _tmp;
    let meta_path = if args.path.extension().is_some_and(|e| e == "toml") {
        let result = build(
            std::slice::from_ref(&args.path),
            &BuildOptions::default(),
            true,
        );
        let out = match result {
            Ok(out) => out,
            Err((db, diags)) => {
                report(&db, &diags, color);
                return Err(format!("`{}` does not compile", args.path.display()));
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
        args.path.clone()
    };
    let mut material = Material::load(&meta_path).map_err(|e| e.to_string())?;
    mopts.apply(&mut material).map_err(|e| e.to_string())?;
    let luts = Luts::for_metadata(&meta_path).map_err(|e| e.to_string())?;
    let options = PreviewOptions {
        scene: match args.scene {
            SceneArg::Sphere => SceneKind::Sphere,
            SceneArg::Cloth => SceneKind::Cloth,
            SceneArg::Swatch => SceneKind::Swatch,
        },
        width: w,
        height: h,
        light_direction,
        format: if args.f32 {
            ColorFormat::Rgba32Float
        } else {
            ColorFormat::Rgba16Float
        },
        language: match args.shader {
            ShaderArg::Wgsl => ShaderLanguage::Wgsl,
            ShaderArg::Spirv => ShaderLanguage::SpirV,
        },
        ..PreviewOptions::default()
    };
    if args.adapter_info {
        let gpu = Gpu::new().map_err(|e| e.to_string())?;
        let i = gpu.adapter_info();
        println!(
            "adapter: {}\n  vendor 0x{:04x}, device 0x{:04x}, type {:?}, backend {:?}\n  driver: {} {}",
            i.name, i.vendor, i.device, i.device_type, i.backend, i.driver, i.driver_info
        );
    }
    let (image, adapter) = render_preview(&material, &luts, &options).map_err(|e| e.to_string())?;
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
    if !quiet {
        let variant = material
            .current_variant()
            .map(|v| v.requested.id.clone())
            .unwrap_or_default();
        let bad = image.non_finite_count();
        println!(
            "rendered {} variant {variant} ({}, {w}x{h}) on {adapter} in {:.2}s -> {}{}",
            material.name(),
            options.scene.name(),
            started.elapsed().as_secs_f64(),
            args.out.display(),
            if bad > 0 {
                format!(" ({bad} non-finite pixels)")
            } else {
                String::new()
            }
        );
    }
    Ok(())
}
