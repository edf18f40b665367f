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
