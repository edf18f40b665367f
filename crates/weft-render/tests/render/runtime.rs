//! Render-runtime tests on the machine's Vulkan adapter (lavapipe without a
//! GPU). Without a Vulkan driver these tests FAIL with the install message;
//! they never skip.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use weft_render::weft_meta::{Keyframe, TextureDefault};
use weft_render::*;

use crate::support::ok;
use weft_tests::repo;

/// The materials roots this suite draws, built once per run.
fn built() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    crate::support::built(
        &DIR,
        "weft-render-tests",
        &[
            ("materials", "materials"),
            ("docs/example", "example"),
            ("tests/fixtures/materials", "fixtures"),
        ],
    )
}

fn meta(root: &str, material: &str) -> PathBuf {
    crate::support::meta_path(built(), root, material)
}

fn standard() -> (Material, PathBuf) {
    let p = meta("materials", "standard");
    (ok(Material::load(&p)), p)
}

fn env() -> &'static EnvironmentMaps {
    static ENV: OnceLock<EnvironmentMaps> = OnceLock::new();
    ENV.get_or_init(|| EnvironmentMaps::sky(&SkyParams::default()))
}

fn renderer(meta_path: &Path) -> Renderer {
    let gpu = ok(Gpu::new());
    let luts = ok(Luts::for_metadata(meta_path));
    ok(Renderer::new(gpu, env(), &luts))
}

fn small() -> RenderOptions {
    RenderOptions {
        width: 64,
        height: 64,
        ..RenderOptions::default()
    }
}

fn f32_at(bytes: &[u8], offset: u32) -> f32 {
    let o = offset as usize;
    f32::from_le_bytes(bytes[o..o + 4].try_into().unwrap())
}

fn offset(m: &Material, member: &str) -> u32 {
    let v = ok(m.current_variant());
    let layout = v.shader.material_uniform.as_ref().expect("uniform layout");
    layout
        .members
        .iter()
        .find(|x| x.name == member)
        .unwrap_or_else(|| panic!("no member {member}"))
        .offset
}

fn luminance(p: [f32; 4]) -> f32 {
    0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]
}

fn relative_rmse(a: &HdrImage, b: &HdrImage) -> f64 {
    let (mut num, mut den) = (0.0f64, 0.0f64);
    for (x, y) in a.pixels.iter().zip(&b.pixels) {
        for c in 0..3 {
            num += f64::from(x[c] - y[c]).powi(2);
            den += f64::from(x[c]).powi(2);
        }
    }
    (num / den.max(1e-30)).sqrt()
}

fn bits(img: &HdrImage) -> Vec<u32> {
    img.pixels.iter().flatten().map(|c| c.to_bits()).collect()
}

#[test]
fn missing_adapter_error_says_to_install_lavapipe() {
    let msg = Error::NoAdapter("no suitable adapter".into()).to_string();
    assert!(msg.contains("mesa-vulkan-drivers"), "{msg}");
    assert!(msg.contains("Vulkan"), "{msg}");
}

#[test]
fn adapter_is_vulkan() {
    let gpu = ok(Gpu::new());
    assert_eq!(
        gpu.adapter_info().backend,
        weft_render::wgpu::Backend::Vulkan
    );
    assert!(!gpu.describe().is_empty());
}

#[test]
fn parameter_writes_land_at_the_metadata_offsets() {
    let (mut m, path) = standard();
    ok(m.set("roughness", 0.3));
    ok(m.set("metallic", 0.75));
    ok(m.set("base_color", [0.5, 0.25, 1.0]));
    ok(m.set_tiling("base_map", [2.0, 3.0, 0.25, 0.5]));
    let mut r = renderer(&path);
    let mut prepared = ok(r.prepare(&m, &small()));
    let bytes = ok(r.read_uniform(&prepared)).expect("uniform buffer");
    assert_eq!(f32_at(&bytes, offset(&m, "roughness")), 0.3);
    assert_eq!(f32_at(&bytes, offset(&m, "metallic")), 0.75);
    let bc = offset(&m, "base_color");
    // sRGB as edited -> linear in the uniform.
    assert_eq!(f32_at(&bytes, bc), srgb_to_linear(0.5) as f32);
    assert_eq!(f32_at(&bytes, bc + 4), srgb_to_linear(0.25) as f32);
    assert_eq!(f32_at(&bytes, bc + 8), 1.0);
    assert_eq!(f32_at(&bytes, bc + 12), 1.0);
    let st = offset(&m, "base_map_st");
    let got: Vec<f32> = (0..4).map(|i| f32_at(&bytes, st + 4 * i)).collect();
    assert_eq!(got, [2.0, 3.0, 0.25, 0.5]);
    // Untouched parameters keep their metadata defaults.
    assert_eq!(f32_at(&bytes, offset(&m, "occlusion_strength")), 1.0);

    // update() rewrites the same buffer.
    ok(m.set("roughness", 0.9));
    ok(r.update(&mut prepared, &m));
    let bytes = ok(r.read_uniform(&prepared)).unwrap();
    assert_eq!(f32_at(&bytes, offset(&m, "roughness")), 0.9);
}

#[test]
fn every_parameter_kind_is_packed_as_the_layout_says() {
    let path = meta("example", "velvet_swatch");
    let mut m = ok(Material::load(&path));
    // Defaults first: exactly what the metadata says.
    let mut r = renderer(&path);
    let prepared = ok(r.prepare(&m, &small()));
    let bytes = ok(r.read_uniform(&prepared)).unwrap();
    let p = |name: &str| {
        m.metadata()
            .parameters
            .iter()
            .find(|p| p.name == name)
            .unwrap()
            .clone()
    };
    let curve = p("sheen_falloff").curve.unwrap();
    let off = offset(&m, "sheen_falloff");
    for (i, s) in curve.baked_default.iter().enumerate() {
        assert_eq!(
            f32_at(&bytes, off + 4 * i as u32),
            *s as f32,
            "curve sample {i}"
        );
    }
    let lin = p("base_color").color.unwrap().linear_default;
    for c in 0..4 {
        assert_eq!(
            f32_at(&bytes, offset(&m, "base_color") + 4 * c),
            lin[c as usize] as f32
        );
    }

    ok(m.set("two_tone", true));
    ok(m.set("fuzz_layers", 7));
    ok(m.set("weave_scale", [3.0, 4.0]));
    ok(m.set("scatter_tint", [0.1, 0.2, 0.3]));
    ok(m.set("sheen_color", [2.0, 1.0, 0.5, 1.0])); // HDR: linear as given
    let keys = vec![
        Keyframe {
            time: 0.0,
            value: 1.0,
            in_slope: 0.0,
            out_slope: 0.0,
        },
        Keyframe {
            time: 2.0,
            value: 0.0,
            in_slope: -1.0,
            out_slope: 0.0,
        },
    ];
    ok(m.set("sheen_falloff", CurveValue::Keyframes(keys.clone())));
    let prepared = ok(r.prepare(&m, &small()));
    let bytes = ok(r.read_uniform(&prepared)).unwrap();
    let u32_at = |o: u32| u32::from_le_bytes(bytes[o as usize..o as usize + 4].try_into().unwrap());
    assert_eq!(u32_at(offset(&m, "two_tone")), 1);
    assert_eq!(u32_at(offset(&m, "fuzz_layers")) as i32, 7);
    let ws = offset(&m, "weave_scale");
    assert_eq!([f32_at(&bytes, ws), f32_at(&bytes, ws + 4)], [3.0, 4.0]);
    let st = offset(&m, "scatter_tint");
    assert_eq!(
        [
            f32_at(&bytes, st),
            f32_at(&bytes, st + 4),
            f32_at(&bytes, st + 8)
        ],
        [0.1, 0.2, 0.3]
    );
    let sc = offset(&m, "sheen_color");
    assert_eq!([f32_at(&bytes, sc), f32_at(&bytes, sc + 8)], [2.0, 0.5]);
    let expected = weft_front::samples::sample_curve(&keys, curve.samples);
    for (i, s) in expected.iter().enumerate() {
        assert_eq!(
            f32_at(&bytes, off + 4 * i as u32),
            *s as f32,
            "keyframed sample {i}"
        );
    }
    // Baked samples, 4 per vec4.
    let samples: Vec<f64> = (0..curve.samples).map(|i| f64::from(i) / 20.0).collect();
    ok(m.set("sheen_falloff", CurveValue::Samples(samples.clone())));
    let prepared = ok(r.prepare(&m, &small()));
    let bytes = ok(r.read_uniform(&prepared)).unwrap();
    for (i, s) in samples.iter().enumerate() {
        assert_eq!(
            f32_at(&bytes, off + 16 * (i as u32 / 4) + 4 * (i as u32 % 4)),
            *s as f32
        );
    }
}

#[test]
fn runtime_baking_matches_the_toolchain() {
    let keys = [
        Keyframe {
            time: -1.0,
            value: 0.2,
            in_slope: 0.0,
            out_slope: 3.0,
        },
        Keyframe {
            time: 0.5,
            value: 0.9,
            in_slope: -2.0,
            out_slope: 1.0,
        },
        Keyframe {
            time: 1.0,
            value: 0.1,
            in_slope: 0.0,
            out_slope: 0.0,
        },
    ];
    assert_eq!(
        sample_curve(&keys, 37),
        weft_front::samples::sample_curve(&keys, 37)
    );
    let stops = [
        weft_render::weft_meta::GradientStop {
            position: 0.1,
            color: [0.9, 0.1, 0.3, 1.0],
        },
        weft_render::weft_meta::GradientStop {
            position: 0.7,
            color: [0.0, 0.5, 1.0, 0.5],
        },
    ];
    assert_eq!(
        bake_gradient(&stops, 64),
        weft_front::samples::bake_gradient(&stops, 64)
    );
}

#[test]
fn unknown_and_invalid_values_are_errors() {
    let (mut m, _) = standard();
    let e = m.set("roughnes", 0.5).unwrap_err().to_string();
    assert!(e.contains("unknown parameter `roughnes`"), "{e}");
    for name in ["roughness", "metallic", "base_color", "base_map"] {
        assert!(e.contains(name), "{e}");
    }
    let e = m.set("roughness", 1.5).unwrap_err().to_string();
    assert!(e.contains("outside the range [0, 1]"), "{e}");
    let e = m.set("roughness", [0.5, 0.5]).unwrap_err().to_string();
    assert!(e.contains("float parameter"), "{e}");
    let e = m.set("base_color", [0.5, 0.5]).unwrap_err().to_string();
    assert!(e.contains("3 or 4 components"), "{e}");
    let e = m.set("base_map", 1.0).unwrap_err().to_string();
    assert!(e.contains("texture2d"), "{e}");
    assert!(m.set("base_map", TextureDefault::Black).is_ok());
    let e = m
        .set_from_str("base_map", "purple")
        .unwrap_err()
        .to_string();
    assert!(e.contains("white, black, gray, normal"), "{e}");
    let e = m
        .set_keyword("NORMAL_MAP", "maybe")
        .unwrap_err()
        .to_string();
    assert!(e.contains("off, on"), "{e}");
    let e = m.set_keyword("BLOOM", "on").unwrap_err().to_string();
    assert!(e.contains("NORMAL_MAP") && e.contains("SPHERE_MAP"), "{e}");
    let e = m.set_tier("ultra").unwrap_err().to_string();
    assert!(e.contains("fast, reference"), "{e}");
    let e = m.select_variant("fast.nope").unwrap_err().to_string();
    assert!(e.contains("fast.normal_map-off.sphere_map-off"), "{e}");
    let e = m.apply_preset("chrome").unwrap_err().to_string();
    assert!(e.contains("gold") && e.contains("plastic"), "{e}");
    // Nothing above changed the values.
    assert_eq!(m.get("roughness"), Some(&StoredValue::Numbers(vec![0.5])));
}

#[test]
fn presets_keywords_and_tiers_pick_the_variant() {
    let (mut m, _) = standard();
    assert_eq!(
        ok(m.current_variant()).canonical.id,
        "fast.normal_map-off.sphere_map-off"
    );
    ok(m.apply_preset("armour_sheen"));
    assert_eq!(
        ok(m.current_variant()).canonical.id,
        "fast.normal_map-off.sphere_map-add"
    );
    ok(m.set_tier("reference"));
    ok(m.set_keyword("NORMAL_MAP", "true"));
    assert_eq!(
        ok(m.current_variant()).canonical.id,
        "reference.normal_map-on.sphere_map-add"
    );
    ok(m.select_variant("fast.normal_map-on.sphere_map-multiply"));
    assert_eq!(m.tier(), "fast");
    assert_eq!(m.keyword("SPHERE_MAP"), Some("multiply"));
    // Aliases resolve to their canonical variant.
    let fx = ok(Material::load(meta("fixtures", "switches")));
    for v in &fx.metadata().variants {
        let r = ok(fx.variant_by_id(&v.id));
        assert!(r.canonical.alias_of.is_none());
        if let Some(target) = &v.alias_of {
            assert_eq!(&r.canonical.id, target);
        }
    }
    assert!(fx.metadata().variants.iter().any(|v| v.alias_of.is_some()));
}

#[test]
fn standard_sphere_is_lit_in_the_centre_with_sky_in_the_corners() {
    let (mut m, path) = standard();
    let mut r = renderer(&path);
    let opts = RenderOptions::default();
    let sky_only = {
        let mut s = Scene::sphere();
        s.mesh.indices.clear();
        ok(r.render(&m, &s, &opts))
    };
    for preset in [None, Some("gold"), Some("plastic")] {
        if let Some(p) = preset {
            ok(m.apply_preset(p));
        }
        let img = ok(r.render(&m, &Scene::sphere(), &opts));
        assert_eq!(img.non_finite_count(), 0);
        let (w, h) = (img.width, img.height);
        let centre = img.pixel(w / 2, h / 2);
        assert!(luminance(centre) > 0.1, "{preset:?}: centre {centre:?}");
        assert_ne!(centre, sky_only.pixel(w / 2, h / 2));
        // The lit side (towards the light, upper left) is brighter than the far side.
        let lit = luminance(img.pixel(w * 3 / 8, h * 3 / 8));
        let dark = luminance(img.pixel(w * 5 / 8 + 10, h * 5 / 8 + 10));
        assert!(lit > 1.5 * dark, "{preset:?}: lit {lit} vs dark {dark}");
        for (x, y) in [(0, 0), (w - 1, 0), (0, h - 1), (w - 1, h - 1)] {
            assert_eq!(
                img.pixel(x, y),
                sky_only.pixel(x, y),
                "{preset:?}: corner ({x}, {y})"
            );
        }
        // Sky above, ground below.
        assert!(img.pixel(0, 0)[2] > img.pixel(0, h - 1)[2]);
        // No black pixels on the sphere.
        for y in h / 4..h * 3 / 4 {
            for x in w / 4..w * 3 / 4 {
                assert!(
                    luminance(img.pixel(x, y)) > 0.005,
                    "{preset:?}: black at ({x}, {y})"
                );
            }
        }
    }
}

#[test]
fn renders_are_byte_identical() {
    let (mut m, path) = standard();
    ok(m.apply_preset("gold"));
    let render = || {
        // A fresh renderer and environment each time: nothing cached.
        let lut = ok(Luts::for_metadata(&path));
        let env = EnvironmentMaps::sky(&SkyParams::default());
        let mut r = ok(Renderer::new(ok(Gpu::new()), &env, &lut));
        ok(r.render(&m, &Scene::cloth(), &RenderOptions::default()))
    };
    let (a, b) = (render(), render());
    assert_eq!(bits(&a), bits(&b));
    let (pa, pb) = (
        ok(encode_png(
            a.width,
            a.height,
            &a.to_srgb8(Tonemap::Aces, 1.0),
        )),
        ok(encode_png(
            b.width,
            b.height,
            &b.to_srgb8(Tonemap::Aces, 1.0),
        )),
    );
    assert_eq!(pa, pb);
    assert_eq!(a.to_pfm(), b.to_pfm());
}

#[test]
fn wgsl_and_spirv_render_the_same() {
    let (mut m, path) = standard();
    let mut r = renderer(&path);
    ok(m.apply_preset("plastic"));
    for id in [
        "fast.normal_map-off.sphere_map-off",
        "reference.normal_map-on.sphere_map-add",
    ] {
        ok(m.select_variant(id));
        let mut opts = small();
        opts.format = ColorFormat::Rgba32Float;
        let wgsl = ok(r.render(&m, &Scene::sphere(), &opts));
        opts.language = ShaderLanguage::SpirV;
        let spirv = ok(r.render(&m, &Scene::sphere(), &opts));
        let e = relative_rmse(&wgsl, &spirv);
        assert!(e < 1e-4, "{id}: relative RMSE {e}");
    }
    // A constant-mode keyword: a pipeline constant in WGSL, a separate SPIR-V file.
    let path = meta("fixtures", "switches");
    let mut fx = ok(Material::load(&path));
    let mut r = renderer(&path);
    let mut images = Vec::new();
    for style in ["flat", "ramp"] {
        ok(fx.set_keyword("STYLE", style));
        let mut opts = small();
        let wgsl = ok(r.render(&fx, &Scene::swatch(), &opts));
        opts.language = ShaderLanguage::SpirV;
        let spirv = ok(r.render(&fx, &Scene::swatch(), &opts));
        assert!(relative_rmse(&wgsl, &spirv) < 1e-4, "STYLE={style}");
        images.push(wgsl);
    }
    assert!(
        relative_rmse(&images[0], &images[1]) > 0.05,
        "STYLE had no effect"
    );
}

#[test]
fn every_standard_variant_renders_finite() {
    let (mut m, path) = standard();
    let mut r = renderer(&path);
    let ids: Vec<String> = m.metadata().variants.iter().map(|v| v.id.clone()).collect();
    assert_eq!(ids.len(), 24);
    let cube = env().sky_cube_rgba();
    for id in ids {
        ok(m.select_variant(&id));
        if m.keyword("SPHERE_MAP") != Some("off") {
            ok(m.set(
                "sphere_map",
                TextureValue::CubeRgbaF32 {
                    size: cube.0,
                    data: cube.1.clone(),
                },
            ));
        }
        let mut opts = small();
        opts.format = ColorFormat::Rgba32Float;
        let img = ok(r.render(&m, &Scene::cloth(), &opts));
        assert_eq!(img.non_finite_count(), 0, "{id}");
        assert!(luminance(img.pixel(32, 32)) > 0.01, "{id}");
    }
}

#[test]
fn textures_and_normal_maps_bind_from_parameters() {
    let (mut m, path) = standard();
    let mut r = renderer(&path);
    // A 2x2 black/white checker on the swatch: quadrants differ.
    let checker = vec![
        255, 255, 255, 255, 0, 0, 0, 255, //
        0, 0, 0, 255, 255, 255, 255, 255,
    ];
    ok(m.set(
        "base_map",
        TextureValue::Rgba8 {
            width: 2,
            height: 2,
            data: checker,
        },
    ));
    let img = ok(r.render(&m, &Scene::swatch(), &small()));
    let (a, b) = (luminance(img.pixel(20, 20)), luminance(img.pixel(44, 20)));
    assert!(a > 3.0 * b, "white quadrant {a} vs black quadrant {b}");

    // A tilted normal map changes the shading only with NORMAL_MAP on.
    ok(m.set("base_map", TextureDefault::White));
    let flat_off = ok(r.render(&m, &Scene::cloth(), &small()));
    let tilted = TextureValue::Rgba8 {
        width: 1,
        height: 1,
        data: vec![230, 128, 200, 255],
    };
    ok(m.set("normal_map", tilted));
    let tilted_off = ok(r.render(&m, &Scene::cloth(), &small()));
    assert_eq!(bits(&flat_off), bits(&tilted_off));
    ok(m.set_keyword("NORMAL_MAP", "on"));
    let tilted_on = ok(r.render(&m, &Scene::cloth(), &small()));
    assert!(relative_rmse(&flat_off, &tilted_on) > 0.02);
    ok(m.set("normal_map", TextureDefault::Normal));
    let flat_on = ok(r.render(&m, &Scene::cloth(), &small()));
    // The flat normal map reproduces the vertex normals.
    assert!(relative_rmse(&flat_off, &flat_on) < 0.01);
}

#[test]
fn passes_draw_in_queue_order_with_parameter_instances() {
    let path = meta("example", "velvet_swatch");
    let mut m = ok(Material::load(&path));
    let mut r = renderer(&path);
    let mut opts = small();
    opts.format = ColorFormat::Rgba32Float;
    ok(m.set("fuzz_layers", 8));
    ok(m.set("fuzz_length", 0.05));
    let prepared = ok(r.prepare(&m, &opts));
    assert_eq!(prepared.pass_names(), ["forward", "fuzz"]);
    assert_eq!(prepared.instances(), [1, 8]);
    let eight = ok(r.render_prepared(&prepared, &Scene::sphere(), &opts));
    ok(m.set("fuzz_layers", 1));
    let one = ok(r.render(&m, &Scene::sphere(), &opts));
    assert_eq!(eight.non_finite_count(), 0);
    assert!(
        relative_rmse(&eight, &one) > 1e-3,
        "instances had no effect"
    );
    // The constant-mode WEAVE keyword reaches the WGSL pipeline.
    ok(m.set_keyword("WEAVE", "plain"));
    let plain = ok(r.render(&m, &Scene::sphere(), &opts));
    assert!(relative_rmse(&plain, &one) > 1e-3, "WEAVE had no effect");
}

#[test]
fn half_and_full_float_targets_agree() {
    let (m, path) = standard();
    let mut r = renderer(&path);
    let half = ok(r.render(&m, &Scene::sphere(), &small()));
    let mut opts = small();
    opts.format = ColorFormat::Rgba32Float;
    let full = ok(r.render(&m, &Scene::sphere(), &opts));
    let e = relative_rmse(&full, &half);
    assert!(e < 2e-3, "relative RMSE {e}");
}

#[test]
fn shipped_generated_tree_renders() {
    // The committed output (cargo xtask regenerate), read like an engine would.
    let path = repo().join("generated/standard/standard.meta.json");
    let mut m = ok(Material::load(&path));
    ok(m.apply_preset("gold"));
    let mut r = renderer(&path);
    let img = ok(r.render(&m, &Scene::sphere(), &small()));
    assert_eq!(img.non_finite_count(), 0);
    assert!(luminance(img.pixel(32, 32)) > 0.1);
}

#[test]
fn preview_options_apply_in_order() {
    let (mut m, _) = standard();
    let opts = MaterialOptions {
        preset: Some("gold".into()),
        tier: Some("reference".into()),
        keywords: vec![("SPHERE_MAP".into(), "multiply".into())],
        sets: vec![
            ("roughness".into(), "0.125".into()),
            ("base_color".into(), "1,0,0".into()),
        ],
        ..MaterialOptions::default()
    };
    ok(opts.apply(&mut m));
    assert_eq!(
        ok(m.current_variant()).canonical.id,
        "reference.normal_map-off.sphere_map-multiply"
    );
    assert_eq!(m.get("roughness"), Some(&StoredValue::Numbers(vec![0.125])));
    assert_eq!(m.get("metallic"), Some(&StoredValue::Numbers(vec![1.0])));
    let bad = MaterialOptions {
        sets: vec![("shininess".into(), "1".into())],
        ..MaterialOptions::default()
    };
    let e = bad.apply(&mut m).unwrap_err().to_string();
    assert!(e.contains("valid parameters: base_color, roughness"), "{e}");
}

#[test]
fn lut_location_matches_the_toolchain() {
    assert_eq!(
        SPLIT_SUM_LUT_FILE,
        weft_compiler::library::SPLIT_SUM_LUT_PATH
    );
    let lut = ok(BrdfLut::for_metadata(meta("materials", "standard")));
    assert_eq!(lut.size, weft_compiler::library::SPLIT_SUM_LUT_SIZE);
    // Row = roughness, column = N.V. On the smooth row, head-on (last column)
    // reflects everything with no Fresnel bias; at grazing (first column) the
    // bias dominates. Swapped axes would read the rough grazing texel instead.
    let [s, b] = lut.texel(lut.size - 1, 0);
    assert!(s + b > 0.95 && b < 0.01, "{s} {b}");
    let [_, b] = lut.texel(0, 0);
    assert!(b > 0.5, "{b}");
}

#[test]
fn sheen_lut_is_bound_when_the_engine_interface_declares_it() {
    if !weft_compiler::engine_binding::ENGINE_INTERFACE.contains("weft_sheen_lut") {
        return; // engine interface without a sheen table: nothing to bind
    }
    // A probe material that shows the table's value at (N.V, r) = (0.5, 0.5).
    let root = Path::new(env!("CARGO_TARGET_TMPDIR")).join("weft-render-sheen-probe");
    std::fs::create_dir_all(root.join("lib")).unwrap();
    std::fs::create_dir_all(root.join("probe")).unwrap();
    std::fs::write(
        root.join("probe/probe.toml"),
        "[material]\nname = \"probe\"\nsource = \"probe.wgsl\"\nrequires = [\"position\"]\n\n\
         [[tier]]\nname = \"fast\"\n\n[[tier]]\nname = \"reference\"\n",
    )
    .unwrap();
    std::fs::write(
        root.join("probe/probe.wgsl"),
        "@vertex\nfn vs_main(@location(0) p: vec3<f32>) -> @builtin(position) vec4<f32> {\n\
         \x20   return weft_frame.view_proj * weft_object.model * vec4<f32>(p, 1.0);\n}\n\
         @fragment\nfn fs_main() -> @location(0) vec4<f32> {\n\
         \x20   let e = textureSampleLevel(weft_sheen_lut, weft_lut_sampler, vec2<f32>(0.5), 0.0).r;\n\
         \x20   return vec4<f32>(e, e, e, 1.0);\n}\n",
    )
    .unwrap();
    let built = weft_compiler::build_library(&root, &Default::default(), &|_, _, _| {})
        .unwrap_or_else(|_| panic!("the probe does not build"));
    let out = root.join("generated");
    weft_compiler::output::write_atomically(&out, &built.files, &[]).unwrap();
    let path = out.join("probe/probe.meta.json");
    let m = ok(Material::load(&path));
    let luts = ok(Luts::for_metadata(&path));
    let sheen = luts.sheen.clone().expect("the build bakes a sheen LUT");
    let mut r = ok(Renderer::new(ok(Gpu::new()), env(), &luts));
    let mut opts = small();
    opts.format = ColorFormat::Rgba32Float;
    let img = ok(r.render(&m, &Scene::swatch(), &opts));
    let h = sheen.size / 2;
    let expected = (sheen.texel(h - 1, h - 1)
        + sheen.texel(h, h - 1)
        + sheen.texel(h - 1, h)
        + sheen.texel(h, h))
        / 4.0;
    let got = img.pixel(32, 32)[0];
    assert!(
        (got - expected).abs() < 2e-3,
        "sampled {got}, table {expected}"
    );
    // Without the table the same variant is an error that names the file.
    let mut r = ok(Renderer::new(
        ok(Gpu::new()),
        env(),
        &Luts::from(luts.brdf.clone()),
    ));
    let e = r
        .render(&m, &Scene::swatch(), &opts)
        .unwrap_err()
        .to_string();
    assert!(e.contains(SHEEN_LUT_FILE), "{e}");
}
