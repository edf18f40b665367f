//! Half precision (`weft_half`, crate weft-compiler `half.rs`): a variant that
//! computes in f16 lists f16 WGSL/SPIR-V/MSL in its metadata's `f16_files`
//! (device feature `shader-f16`), while its `files` — every language — hold
//! the same code in f32, which every device and compiler accepts.

use std::path::{Path, PathBuf};
use weft_meta::{MaterialMetadata, VariantShader};

fn standard() -> (PathBuf, MaterialMetadata) {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated/standard");
    let text = std::fs::read_to_string(dir.join("standard.meta.json")).expect("generated/standard");
    (dir, serde_json::from_str(&text).expect("metadata"))
}

/// SPIR-V capability numbers (SPIR-V specification, "Capability").
const FLOAT16: u32 = 9;
const STORAGE_INPUT_OUTPUT16: u32 = 4436;

fn declares_float16(spirv: &[u8]) -> bool {
    declares_capability(spirv, FLOAT16)
}

/// `OpCapability <capability>` among the module's instructions.
fn declares_capability(spirv: &[u8], capability: u32) -> bool {
    let words: Vec<u32> = spirv
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    let mut at = 5;
    while at < words.len() {
        let (count, op) = ((words[at] >> 16) as usize, words[at] & 0xffff);
        if op == 17 && words.get(at + 1) == Some(&capability) {
            return true;
        }
        at += count.max(1);
    }
    false
}

/// An MSL/HLSL `half` type (`half`, `half2`..`half4`) as a whole word.
fn has_half_type(text: &str) -> bool {
    text.split(|c: char| !c.is_ascii_alphanumeric() && c != '_')
        .any(|w| matches!(w, "half" | "half2" | "half3" | "half4"))
}

fn read(dir: &Path, shader: &VariantShader, lang: &str, f16: bool) -> Vec<Vec<u8>> {
    let list = if f16 {
        &shader.f16_files
    } else {
        &shader.files
    };
    list.get(lang)
        .unwrap_or_else(|| panic!("no {lang} files (f16: {f16})"))
        .iter()
        .map(|f| {
            let bytes = std::fs::read(dir.join(&f.path)).expect("listed file");
            assert_eq!(
                weft_compiler::digest::sha256_hex(&bytes),
                f.sha256,
                "{}",
                f.path
            );
            bytes
        })
        .collect()
}

#[test]
fn half_precision_variants_add_f16_files_to_portable_f32_ones() {
    let (dir, meta) = standard();
    let mut half = 0;
    for v in &meta.variants {
        let Some(shader) = &v.shader else { continue };
        // `files`: f32 in every language, whatever the tier.
        for wgsl in read(&dir, shader, "wgsl", false) {
            assert!(
                !String::from_utf8(wgsl).unwrap().contains("f16"),
                "{}",
                v.id
            );
        }
        for spirv in read(&dir, shader, "spirv", false) {
            assert!(
                !declares_float16(&spirv),
                "{}: SPIR-V declares Float16",
                v.id
            );
        }
        for hlsl in read(&dir, shader, "hlsl", false) {
            let text = String::from_utf8(hlsl).unwrap();
            assert!(!has_half_type(&text), "{}: HLSL with a half type", v.id);
            assert!(
                !text.contains("float16_t") && !text.contains("min16float"),
                "{}",
                v.id
            );
        }
        for glsl in read(&dir, shader, "glsl", false) {
            assert!(
                !String::from_utf8(glsl).unwrap().contains("float16"),
                "{}",
                v.id
            );
        }
        for msl in read(&dir, shader, "msl", false) {
            let text = String::from_utf8(msl).unwrap();
            assert!(!has_half_type(&text), "{}: f32 MSL with a half type", v.id);
        }
        if v.tier != "low" {
            assert!(shader.f16_files.is_empty(), "{}", v.id);
            continue;
        }
        // `f16_files`: the languages that can carry f16.
        half += 1;
        let langs: Vec<&String> = shader.f16_files.keys().collect();
        assert_eq!(langs, ["msl", "spirv", "wgsl"], "{}", v.id);
        for wgsl in read(&dir, shader, "wgsl", true) {
            assert!(
                String::from_utf8(wgsl).unwrap().starts_with("enable f16;"),
                "{}",
                v.id
            );
        }
        for spirv in read(&dir, shader, "spirv", true) {
            assert!(
                declares_float16(&spirv),
                "{}: f16 SPIR-V without Float16",
                v.id
            );
            // f16 inputs and outputs need storageInputOutput16, which wgpu's
            // shader-f16 does not require and many desktop GPUs lack: the
            // interface stays f32.
            assert!(
                !declares_capability(&spirv, STORAGE_INPUT_OUTPUT16),
                "{}: f16 SPIR-V declares StorageInputOutput16",
                v.id
            );
        }
        for msl in read(&dir, shader, "msl", true) {
            assert!(has_half_type(&String::from_utf8(msl).unwrap()), "{}", v.id);
        }
    }
    assert!(half > 0, "standard has no half-precision variant");
}

/// The runtime draws the f16 files on a device with `shader-f16` and the f32
/// ones on request (and on devices without it): both render, and agree to
/// f16 precision.
#[test]
fn the_fallback_renders_like_the_half_precision_shader() {
    use weft_render::{
        EnvironmentMaps, Gpu, Luts, Material, PreviewOptions, RenderOptions, Renderer, Scene,
    };
    let (dir, meta) = standard();
    let generated = dir.parent().unwrap();
    let gpu = Gpu::new().unwrap_or_else(|e| panic!("{e}"));
    assert!(
        gpu.device.features().contains(wgpu::Features::SHADER_F16),
        "the Vulkan adapter ({}) has no shaderFloat16: lavapipe (mesa-vulkan-drivers) has it",
        gpu.describe()
    );
    let luts = Luts::load_dir(generated).expect("LUTs");
    let env = EnvironmentMaps::sky(&PreviewOptions::default().sky_params());
    let mut renderer = Renderer::new(gpu, &env, &luts).expect("renderer");
    let mut material = Material::load(dir.join("standard.meta.json")).expect("material");
    let id = &meta
        .variants
        .iter()
        .find(|v| v.tier == "low")
        .expect("low")
        .id;
    material.select_variant(id).expect("variant");
    let scene = Scene::sphere();
    let render = |renderer: &mut Renderer, f32_fallback: bool| {
        let options = RenderOptions {
            width: 64,
            height: 64,
            format: weft_render::ColorFormat::Rgba32Float,
            f32_fallback,
            ..RenderOptions::default()
        };
        renderer
            .render(&material, &scene, &options)
            .expect("render")
    };
    let half = render(&mut renderer, false);
    let full = render(&mut renderer, true);
    let mut worst = 0.0f32;
    for (a, b) in half.pixels.iter().zip(&full.pixels) {
        for c in 0..3 {
            worst = worst.max((a[c] - b[c]).abs() / b[c].abs().max(0.05));
        }
    }
    // f16 has an 11-bit significand: a few rounding steps through the BRDF.
    assert!(
        worst < 0.02,
        "half vs f32 fallback: worst relative difference {worst}"
    );
    assert!(
        worst > 0.0,
        "the half and f32 renders are identical: was f16 drawn at all?"
    );
}
