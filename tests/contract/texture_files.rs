//! Texture parameters that ship an image (`file = "..."`): the fixture
//! `imaged` (tests/fixtures/materials/imaged: an 8×8 checker, red top-left,
//! green top-right, blue bottom-left, white bottom-right, mapped over the
//! screen) built, described in its metadata, kept by no-change rebuilds,
//! bound by weft-render the right way up and overridden by a set value, and
//! left bound (not folded) by a scene.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use weft_render::weft_meta::TextureDefault;
use weft_render::*;
use weft_tests::repo;

fn fixtures() -> PathBuf {
    repo().join("tests/fixtures/materials")
}

fn build(options: &weft_compiler::BuildOptions) -> weft_compiler::BuildOutput {
    weft_compiler::build_library(&fixtures(), options, &|_, _, _| {})
        .unwrap_or_else(|(db, d)| panic!("fixtures do not build:\n{}", d.render_plain(&db)))
}

fn sha256_hex(bytes: &[u8]) -> String {
    use sha2::Digest;
    sha2::Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The checker's texels, decoded by weft-render's own PNG reader (the one
/// `weft preview --texture` uses), independent of the toolchain's.
fn checker_rgba8() -> (u32, u32, Vec<u8>) {
    let png = std::fs::read(fixtures().join("imaged/textures/checker.png")).unwrap();
    decode_png(&png, "checker").unwrap()
}

#[test]
fn metadata_states_the_file_and_the_file_holds_the_png_texels() {
    let out = build(&Default::default());
    let meta = out.materials.iter().find(|m| m.name == "imaged").unwrap();
    let p = meta.parameters.iter().find(|p| p.name == "image").unwrap();
    let t = p.texture.as_ref().unwrap();
    assert_eq!(
        t.default,
        TextureDefault::Black,
        "the built-in fallback stays"
    );
    let f = t.file.as_ref().expect("parameter texture.file");
    assert_eq!(f.path, "imaged/image.rgba8");
    assert_eq!(f.format, "rgba8unorm_srgb");
    let (w, h, texels) = checker_rgba8();
    assert_eq!((f.width, f.height), (w, h));
    let bytes = &out.files[&f.path];
    assert!(*bytes == texels, "the written texels are not the PNG's");
    assert_eq!(f.sha256.as_deref(), Some(sha256_hex(bytes).as_str()));
    // Top-left texel red, bottom-right white: rows top to bottom.
    assert_eq!(bytes[..4], [255, 0, 0, 255]);
    assert_eq!(bytes[bytes.len() - 4..], [255, 255, 255, 255]);
    // Every variant's binding states the same file next to its default.
    let mut bound = 0;
    for v in &meta.variants {
        for b in v.shader.iter().flat_map(|s| &s.bindings) {
            if b.parameter.as_deref() == Some("image") {
                let bt = b.texture.as_ref().unwrap();
                assert_eq!(bt.file.as_ref(), Some(f), "variant {}", v.id);
                assert_eq!(bt.default, Some(TextureDefault::Black));
                bound += 1;
            }
        }
    }
    assert!(bound > 0, "no variant binds the image");
}

#[test]
fn builds_are_deterministic_and_reuse_keeps_the_file() {
    let one = build(&Default::default());
    let two = build(&Default::default());
    assert!(one.files == two.files, "two builds differ");
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("generated");
    weft_compiler::output::write_atomically(&out, &one.files, &[]).unwrap();
    let again = build(&weft_compiler::BuildOptions {
        reuse_from: Some(out.clone()),
        ..Default::default()
    });
    assert!(
        again.reused.iter().any(|m| m == "imaged"),
        "{:?}",
        again.reused
    );
    assert!(again.files == one.files, "a reusing build differs");
    let kept = build(&weft_compiler::BuildOptions {
        reuse_from: Some(out.clone()),
        keep_unchanged: true,
        ..Default::default()
    });
    let k = kept.kept.as_ref().expect("kept files");
    let f = &k.files.get("imaged/image.rgba8");
    assert!(
        matches!(f, Some(Some(sha)) if *sha == sha256_hex(&one.files["imaged/image.rgba8"])),
        "a no-change rebuild does not keep the image: {:?}",
        k.files.keys().collect::<Vec<_>>()
    );
}

fn render(m: &Material, meta_path: &Path) -> HdrImage {
    let gpu = Gpu::new().unwrap();
    let env = EnvironmentMaps::sky(&SkyParams::default());
    let luts = Luts::for_metadata(meta_path).unwrap();
    let mut r = Renderer::new(gpu, &env, &luts).unwrap();
    let options = RenderOptions {
        width: 64,
        height: 64,
        ..RenderOptions::default()
    };
    r.render(m, &Scene::swatch(), &options).unwrap()
}

/// The colour at the centre of each quadrant of the picture: top-left,
/// top-right, bottom-left, bottom-right.
fn quadrants(img: &HdrImage) -> [[f32; 3]; 4] {
    [(20, 20), (44, 20), (20, 44), (44, 44)].map(|(x, y)| {
        let p = img.pixel(x, y);
        [p[0], p[1], p[2]]
    })
}

fn assert_near(got: [[f32; 3]; 4], want: [[f32; 3]; 4], what: &str) {
    for (g, w) in got.iter().zip(&want) {
        assert!(
            g.iter().zip(w).all(|(a, b)| (a - b).abs() < 0.02),
            "{what}: quadrants {got:?}, expected {want:?}"
        );
    }
}

#[test]
fn weft_render_binds_the_image_the_right_way_up_and_a_set_value_overrides_it() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("generated");
    weft_compiler::output::write_atomically(&out, &build(&Default::default()).files, &[]).unwrap();
    let meta_path = out.join("imaged/imaged.meta.json");
    let mut m = Material::load(&meta_path).unwrap();
    const R: [f32; 3] = [1.0, 0.0, 0.0];
    const G: [f32; 3] = [0.0, 1.0, 0.0];
    const B: [f32; 3] = [0.0, 0.0, 1.0];
    const W: [f32; 3] = [1.0, 1.0, 1.0];
    assert_near(quadrants(&render(&m, &meta_path)), [R, G, B, W], "unset");

    // A set value (what `weft preview --texture` does) replaces the image.
    m.set("image", TextureDefault::White).unwrap();
    assert_near(quadrants(&render(&m, &meta_path)), [W; 4], "set to white");
    let (w, h, mut texels) = checker_rgba8();
    // Upside down and mirrored: texels in reverse order.
    texels.reverse();
    for t in texels.chunks_exact_mut(4) {
        t.reverse();
    }
    m.set(
        "image",
        TextureValue::Rgba8 {
            width: w,
            height: h,
            data: texels,
        },
    )
    .unwrap();
    assert_near(
        quadrants(&render(&m, &meta_path)),
        [W, B, G, R],
        "a user image",
    );
    // Reset: unset again, the file is bound again.
    m.reset().unwrap();
    assert_near(quadrants(&render(&m, &meta_path)), [R, G, B, W], "reset");

    // A missing file is an error naming it, not a silent default.
    std::fs::remove_file(out.join("imaged/image.rgba8")).unwrap();
    let e = Material::load(&meta_path).unwrap_err().to_string();
    assert!(e.contains("image.rgba8"), "{e}");
}

/// A scene instance left at the image keeps the texture bound (its file in
/// the scene metadata); one given a built-in folds it.
#[test]
fn scenes_keep_an_unset_image_bound_and_fold_a_set_texture() {
    let tmp = tempfile::tempdir().unwrap();
    let scene = tmp.path().join("imaged.scene.toml");
    std::fs::write(
        &scene,
        format!(
            "[scene]\nname = \"imaged\"\nmaterials = {:?}\nvertex_inputs = [\"position\", \"uv0\"]\n\n\
             [[instances]]\nname = \"shipped\"\nmaterial = \"imaged\"\nmesh = \"swatch\"\n\n\
             [[instances]]\nname = \"white\"\nmaterial = \"imaged\"\nmesh = \"swatch\"\nparams = {{ image = \"white\" }}\n",
            fixtures().display().to_string()
        ),
    )
    .unwrap();
    let out = weft_compiler::build_scene(&scene, &Default::default())
        .unwrap_or_else(|(db, d)| panic!("{}", d.render_plain(&db)));
    let by_name: BTreeMap<&str, _> = out
        .metadata
        .instances
        .iter()
        .map(|i| (i.name.as_str(), i))
        .collect();
    let shipped = by_name["shipped"];
    assert!(
        !shipped.constants.contains_key("image"),
        "the image was folded"
    );
    let t = shipped.textures.values().find(|t| t.parameter == "image");
    let f = t
        .and_then(|t| t.file.as_ref())
        .expect("the image stays bound");
    assert_eq!(f.path, "imaged/image.rgba8");
    assert_eq!((f.width, f.height), (8, 8));
    let white = by_name["white"];
    assert_eq!(
        white.constants.get("image"),
        Some(&serde_json::json!("white"))
    );
    assert!(
        white.textures.values().all(|t| t.parameter != "image"),
        "a folded texture is still bound"
    );
}
