//! The render sets `bless` and `gallery` share: every material case and every shipped scene, rendered on the local adapter.

use std::path::Path;

/// Renders every case of every generated material with `render`.
pub(crate) fn render_cases(
    root: &Path,
    size: u32,
    mut each: impl FnMut(&weft_golden::Case, &weft_meta::MaterialMetadata, Vec<u8>),
) -> Result<String, String> {
    let generated = root.join("generated");
    let mut h = weft_golden::Harness::new(&generated).map_err(|e| e.to_string())?;
    for (meta_path, meta) in weft_golden::materials(&generated)? {
        for case in weft_golden::cases(&meta) {
            let image = h
                .render(&meta_path, &case, size, weft_render::ShaderLanguage::Wgsl)
                .map_err(|e| format!("{}/{}: {e}", case.material, case.name))?;
            each(&case, &meta, weft_golden::to_ldr(&image));
        }
    }
    Ok(h.adapter())
}

pub(crate) fn png_bytes(size: u32, rgba: &[u8]) -> Vec<u8> {
    weft_render::encode_png(size, size, rgba).expect("encode PNG")
}

/// Every shipped scene as built into generated/scenes/, drawn whole with its
/// specialised shaders over the sky at `size`: (metadata, sRGB8 RGBA) by name.
#[allow(clippy::type_complexity)]
pub(crate) fn render_scenes(
    root: &Path,
    size: (u32, u32),
) -> Result<Vec<(String, weft_meta::scene::SceneMetadata, Vec<u8>)>, String> {
    use weft_golden::scenes;
    let generated = root.join("generated");
    let mut h = scenes::SceneHarness::new(&generated).map_err(|e| e.to_string())?;
    let mut out = Vec::new();
    for name in scenes::shipped_scenes(root)? {
        let path = scenes::built_scene_path(&generated, &name);
        let scene = weft_render::SceneFile::load(&path)
            .map_err(|e| format!("{name}: {e} (run `cargo xtask regenerate`)"))?;
        let image = h
            .render(
                &scene,
                &weft_render::SceneShaders::Specialised,
                size,
                weft_render::Background::Sky { mip: 0.0 },
            )
            .map_err(|e| format!("scene {name}: {e}"))?;
        out.push((name, scene.metadata, weft_golden::to_ldr(&image)));
    }
    Ok(out)
}
