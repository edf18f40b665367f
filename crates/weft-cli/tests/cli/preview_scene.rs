//! `weft preview --scene-file / --scene-dir`: whole scenes to a PNG, as a
//! user runs it (needs a Vulkan driver: lavapipe without a GPU).

use std::path::Path;
use std::process::{Command, Output};
use weft_tests::repo;

fn weft(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_weft"))
        .current_dir(repo())
        .args(args)
        .output()
        .unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Width and height from a PNG's IHDR chunk.
fn png_size(path: &Path) -> (u32, u32) {
    let bytes = std::fs::read(path).unwrap();
    assert_eq!(&bytes[1..4], b"PNG", "{} is not a PNG", path.display());
    let be = |o: usize| u32::from_be_bytes(bytes[o..o + 4].try_into().unwrap());
    (be(16), be(20))
}

#[test]
fn previews_a_scene_manifest_and_a_built_scene() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("book.png");
    let o = weft(&[
        "preview",
        "--scene-file",
        "scenes/swatch_book.scene.toml",
        "-o",
        png.to_str().unwrap(),
        "--width",
        "96",
        "--height",
        "64",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("rendered scene swatch_book"));
    assert_eq!(png_size(&png), (96, 64));

    // Built on its own (no LUTs beside it), previewed from its output folder
    // and from the scene folder, through the SPIR-V files.
    let out = dir.path().join("out");
    let o = weft(&[
        "build",
        "--scene",
        "scenes/swatch_book.scene.toml",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    for source in [out.clone(), out.join("swatch_book")] {
        let png = dir.path().join("built.png");
        let o = weft(&[
            "preview",
            "--scene-dir",
            source.to_str().unwrap(),
            "-o",
            png.to_str().unwrap(),
            "--size",
            "48x32",
            "--spirv",
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert_eq!(png_size(&png), (48, 32));
    }
}

#[test]
fn scene_preview_errors_are_reported_not_panics() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("x.png");
    let o = weft(&[
        "preview",
        "--scene-dir",
        dir.path().to_str().unwrap(),
        "-o",
        png.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("holds no built scene"),
        "{}",
        stderr(&o)
    );

    let manifest = dir.path().join("broken.scene.toml");
    std::fs::write(&manifest, "[scene]\nname = \"broken\"\n").unwrap();
    let o = weft(&[
        "preview",
        "--color",
        "never",
        "--scene-file",
        manifest.to_str().unwrap(),
        "-o",
        png.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("does not build"), "{}", stderr(&o));
    assert!(!stderr(&o).contains("panicked"), "{}", stderr(&o));
    assert!(!png.exists());

    // A scene is not drawn with material options.
    let o = weft(&[
        "preview",
        "--scene-file",
        "scenes/swatch_book.scene.toml",
        "--preset",
        "gold",
        "-o",
        png.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

/// A scene folder carries every file it binds (texture files, LUTs, glTF
/// meshes): built anywhere, moved elsewhere alone, it still previews — the
/// character scene binds the face's threshold maps, the glTF scene draws
/// its own meshes.
#[test]
fn a_built_scene_folder_is_self_contained() {
    for (source, name) in [
        ("scenes/character_left.scene.toml", "character_left"),
        ("scenes/gltf/showroom.glb", "showroom"),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        let o = weft(&[
            "build",
            "--scene",
            source,
            "-o",
            out.to_str().unwrap(),
            "-q",
        ]);
        assert!(o.status.success(), "{source}: {}", stderr(&o));
        // Only the scene's folder, somewhere else: no library above it.
        let moved = dir.path().join("elsewhere").join(name);
        std::fs::create_dir_all(moved.parent().unwrap()).unwrap();
        std::fs::rename(out.join(name), &moved).unwrap();
        assert!(moved.join("luts").is_dir(), "{source}: the LUTs ride along");
        // Every mesh the metadata names is in the folder: glTF meshes
        // (`file`) and built-in ones (`path`), these byte-equal to the
        // library's.
        let meta: weft_meta::scene::SceneMetadata = serde_json::from_slice(
            &std::fs::read(moved.join(format!("{name}.scene.json"))).unwrap(),
        )
        .unwrap();
        for (mesh, entry) in &meta.meshes {
            let rel = entry.file.as_ref().or(entry.path.as_ref()).unwrap();
            let carried = std::fs::read(moved.join(rel))
                .unwrap_or_else(|e| panic!("{source}: mesh `{mesh}` ({rel}): {e}"));
            if entry.path.is_some() {
                assert_eq!(
                    carried,
                    std::fs::read(repo().join("generated").join(rel)).unwrap(),
                    "{source}: {rel}"
                );
            }
        }
        let png = dir.path().join("scene.png");
        let o = weft(&[
            "preview",
            "--scene-dir",
            moved.to_str().unwrap(),
            "-o",
            png.to_str().unwrap(),
            "--width",
            "64",
            "--height",
            "48",
        ]);
        assert!(o.status.success(), "{source}: {}", stderr(&o));
        assert_eq!(png_size(&png), (64, 48));
    }
}

/// `weft preview <material> --mesh x.glb#M/P`: a material on the user's own
/// mesh; a bad reference fails with the JSON pointer.
#[test]
fn previews_a_material_on_a_gltf_mesh() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("on_mesh.png");
    let o = weft(&[
        "preview",
        "materials/velvet/velvet.toml",
        "--mesh",
        "scenes/gltf/showroom.glb#0/0",
        "-o",
        png.to_str().unwrap(),
        "--size",
        "48x48",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("showroom.glb#0/0"));
    assert_eq!(png_size(&png), (48, 48));
    let o = weft(&[
        "preview",
        "materials/velvet/velvet.toml",
        "--mesh",
        "scenes/gltf/showroom.glb#0/9",
        "-o",
        png.to_str().unwrap(),
    ]);
    assert!(!o.status.success());
    assert!(
        stderr(&o).contains("/meshes/0/primitives/9"),
        "{}",
        stderr(&o)
    );
}

/// `--material-variant`: the glTF showroom as its "linen cushions" variant
/// shows it — the two cushions drawn by their stand-ins (another material),
/// everything else as without it; an unknown variant is an error that
/// lists the scene's variants.
#[test]
fn previews_a_material_variant() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let o = weft(&[
        "build",
        "--scene",
        "scenes/showroom.scene.toml",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let draw = |variant: Option<&str>, png: &Path| {
        let mut args = vec![
            "preview",
            "--scene-dir",
            out.to_str().unwrap(),
            "-o",
            png.to_str().unwrap(),
            "--width",
            "160",
            "--height",
            "100",
        ];
        if let Some(v) = variant {
            args.extend(["--material-variant", v]);
        }
        weft(&args)
    };
    let (plain, linen) = (dir.path().join("plain.png"), dir.path().join("linen.png"));
    let o = draw(None, &plain);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = draw(Some("linen cushions"), &linen);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("as variant `linen cushions`"));
    // The pictures differ where the cushions are, and only a small part.
    let pixels = |p: &Path| {
        let mut d = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(p).unwrap()))
            .read_info()
            .unwrap();
        let mut buf = vec![0; d.output_buffer_size().unwrap()];
        d.next_frame(&mut buf).unwrap();
        buf
    };
    let (a, b) = (pixels(&plain), pixels(&linen));
    let changed = a
        .chunks(4)
        .zip(b.chunks(4))
        .filter(|(x, y)| x.iter().zip(*y).any(|(p, q)| p.abs_diff(*q) > 8))
        .count();
    let total = a.len() / 4;
    assert!(
        changed > 0 && changed < total / 10,
        "{changed} of {total} pixels changed"
    );
    let o = draw(Some("silk"), &dir.path().join("x.png"));
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("no material variant `silk`; its variants: linen cushions"),
        "{}",
        stderr(&o)
    );
}
