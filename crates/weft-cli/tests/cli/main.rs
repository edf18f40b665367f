//! The `weft` binary as a user runs it: exit codes, output, nothing written
//! on error (this file), and by concern: scene builds and previews, the
//! shared cache, shards, hostile command lines, and builds killed midway.

mod build_scene;
mod cache;
mod hostile;
mod kill_safe;
mod preview_scene;
mod shard;

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

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

#[test]
fn check_accepts_the_shipped_library() {
    let o = weft(&["check", "materials"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stdout(&o).contains("12 variant(s)") || stdout(&o).contains("variant(s)"));
}

#[test]
fn check_rejects_a_bad_material_with_a_located_diagnostic() {
    let dir = tempfile::tempdir().unwrap();
    let toml = dir.path().join("bad.toml");
    std::fs::write(&toml, "[material]\nsource = \"bad.wgsl\"\n\n[params.x]\ntype = \"float\"\nrnage = [0, 1]\n\n[[tier]]\nname = \"fast\"\n").unwrap();
    std::fs::write(dir.path().join("bad.wgsl"), "").unwrap();
    let o = weft(&["check", "--color", "never", toml.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(err.contains("unknown key `rnage`"), "{err}");
    assert!(err.contains("did you mean `range`?"), "{err}");
    assert!(err.contains("bad.toml:6:1"), "file:line:column: {err}");
    assert!(
        err.contains("the `reference` tier is missing"),
        "several errors in one run: {err}"
    );
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn check_says_when_there_is_no_material() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("lib")).unwrap();
    let o = weft(&["check", "--color", "never", dir.path().to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let err = stderr(&o);
    assert!(err.contains("error[no-material]: no material in"), "{err}");
    let wgsl = dir.path().join("lib/shared.wgsl");
    std::fs::write(&wgsl, "fn f() {}\n").unwrap();
    let o = weft(&["check", "--color", "never", wgsl.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("is not a material"), "{}", stderr(&o));
    // `build` too: nothing is written.
    let out = dir.path().join("out");
    let o = weft(&[
        "build",
        dir.path().to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(o.status.code(), Some(1));
    assert!(!out.exists());
}

#[test]
fn build_writes_nothing_on_error() {
    let dir = tempfile::tempdir().unwrap();
    let toml = dir.path().join("bad.toml");
    std::fs::write(&toml, "[material]\nsource = \"missing.wgsl\"\n[[tier]]\nname = \"fast\"\n[[tier]]\nname = \"reference\"\n").unwrap();
    let out = dir.path().join("out");
    let o = weft(&["build", toml.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        stderr(&o).contains("cannot find WGSL source"),
        "{}",
        stderr(&o)
    );
    assert!(!out.exists(), "no output folder on error");
    // Nothing half-written beside it either.
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
}

#[test]
fn build_then_rebuild_reuses_unchanged_materials() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("gen");
    let o = weft(&["build", "materials", "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(out.join("standard/standard.meta.json").is_file());
    assert!(out.join("luts/split_sum_ggx_64x64_1024spp.rg16f").is_file());
    let o = weft(&["build", "materials", "-o", out.to_str().unwrap()]);
    assert!(stdout(&o).contains("unchanged"), "{}", stdout(&o));
}

#[test]
fn inspect_and_variants_print_tables() {
    let o = weft(&["inspect", "materials/standard/standard.toml"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    for needle in [
        "Parameters",
        "roughness",
        "[0, 1]",
        "SPHERE_MAP",
        "off | add | multiply",
        "Tiers (reference: reference)",
        "Presets",
        // The committed reports: measured, and the GPU model apart.
        "Measured cost and error",
        "GPU model (AMD's shader compiler",
        "navi21 x standard fast",
    ] {
        assert!(text.contains(needle), "missing {needle:?} in:\n{text}");
    }
    // standard `fast` is the model's baseline.
    let fast = text
        .lines()
        .skip_while(|l| !l.starts_with("GPU model"))
        .find(|l| l.starts_with("fast "))
        .unwrap_or_default();
    assert!(
        fast.split_whitespace().nth(1) == Some("1.00"),
        "{fast:?} in:\n{text}"
    );
    let o = weft(&["variants", "materials/standard/standard.toml"]);
    let text = stdout(&o);
    assert!(text.contains("standard: 24 variants"), "{text}");
    assert!(
        text.contains("reference.normal_map-on.sphere_map-multiply"),
        "{text}"
    );
}

#[test]
fn help_has_examples() {
    let o = weft(&["build", "--help"]);
    assert!(stdout(&o).contains("Examples:"));
}

/// `weft preview --texture NAME=PATH`: an artist's own map, from a PNG of
/// any colour type, reaches the picture; bad names and files get a clear
/// error and no output.
#[test]
fn preview_takes_a_texture_parameter_from_a_png() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, bytes: &[u8]| {
        let path = dir.path().join(name);
        std::fs::write(&path, bytes).unwrap();
        path.display().to_string()
    };
    // A red RGBA map, and a mid-grey one written as an 8-bit grey PNG.
    let red = write(
        "red.png",
        &weft_render::encode_png(2, 2, &[255, 0, 0, 255].repeat(4)).unwrap(),
    );
    let mut grey_png = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut grey_png, 2, 2);
        enc.set_color(png::ColorType::Grayscale);
        enc.set_depth(png::BitDepth::Eight);
        enc.write_header()
            .unwrap()
            .write_image_data(&[128; 4])
            .unwrap();
    }
    let grey = write("grey.png", &grey_png);
    let material = "generated/standard/standard.meta.json";
    let preview = |extra: &[&str], out: &str| {
        let out = dir.path().join(out);
        let mut args = vec![
            "preview",
            material,
            "-q",
            "--size",
            "32x32",
            "--set",
            "base_color=1,1,1",
            "-o",
            out.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        (weft(&args), out)
    };
    let centre = |path: &Path| {
        let img = weft_render::decode_png(&std::fs::read(path).unwrap(), "out").unwrap();
        let at = ((16 * 32 + 16) * 4) as usize;
        [img.2[at], img.2[at + 1], img.2[at + 2]]
    };
    let (o, red_out) = preview(&["--texture", &format!("base_map={red}")], "red_out.png");
    assert!(o.status.success(), "{}", stderr(&o));
    let [r, g, b] = centre(&red_out);
    assert!(
        r > 2 * g.max(b) && r > 60,
        "a red base map gives a red sphere: {r},{g},{b}"
    );
    let (o, grey_out) = preview(&["--texture", &format!("base_map={grey}")], "grey_out.png");
    assert!(o.status.success(), "{}", stderr(&o));
    let (o, white_out) = preview(&[], "white_out.png");
    assert!(o.status.success(), "{}", stderr(&o));
    // The default map is white: a mid-grey map (a grey PNG, replicated to
    // RGB) darkens every channel.
    let (grey, white) = (centre(&grey_out), centre(&white_out));
    for c in 0..3 {
        assert!(
            grey[c] + 20 < white[c],
            "grey {grey:?} against white {white:?}"
        );
    }

    // Errors: an unknown parameter, a file that is not a PNG, a 2D map for
    // a cube parameter. Nothing is written.
    let not_png = write("notes.png", b"not an image");
    for (arg, expected) in [
        (format!("base_mpa={red}"), "base_mpa"),
        (format!("base_map={not_png}"), "not a PNG"),
        (
            format!("base_map={}", dir.path().join("absent.png").display()),
            "absent.png",
        ),
        (format!("sphere_map={red}"), "sphere_map"),
    ] {
        let (o, out) = preview(
            &["--keyword", "SPHERE_MAP=add", "--texture", &arg],
            "bad.png",
        );
        assert!(!o.status.success(), "{arg}: accepted");
        assert!(stderr(&o).contains(expected), "{arg}: {}", stderr(&o));
        assert!(!out.exists(), "{arg}: wrote an image");
    }
}

#[test]
fn preview_draws_the_bust_with_the_maps_on_the_face() {
    // A map whose left half (u < 0.5) is red and right half blue: on the
    // bust's face UVs (u = 0.5 + φ/π) the character's right cheek, on the
    // image's left, is red and the left cheek blue.
    let dir = tempfile::tempdir().unwrap();
    let map = dir.path().join("halves.png");
    let mut texels = Vec::new();
    for _ in 0..8 {
        for x in 0..8 {
            texels.extend(if x < 4 {
                [255, 0, 0, 255]
            } else {
                [0, 0, 255, 255]
            });
        }
    }
    std::fs::write(&map, weft_render::encode_png(8, 8, &texels).unwrap()).unwrap();
    let out = dir.path().join("bust.png");
    let o = weft(&[
        "preview",
        "generated/standard/standard.meta.json",
        "-q",
        "--scene",
        "bust",
        "--size",
        "64x64",
        "--set",
        "base_color=1,1,1",
        "--texture",
        &format!("base_map={}", map.display()),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (w, _, img) = weft_render::decode_png(&std::fs::read(&out).unwrap(), "bust").unwrap();
    let at = |x: u32, y: u32| {
        let i = ((y * w + x) * 4) as usize;
        [img[i], img[i + 1], img[i + 2]]
    };
    // Cheeks, below the eyes and either side of the nose.
    let (left, right) = (at(26, 30), at(38, 30));
    assert!(
        left[0] > 2 * left[2].max(left[1]),
        "image-left cheek {left:?} is not red"
    );
    assert!(
        right[2] > 2 * right[0].max(right[1]),
        "image-right cheek {right:?} is not blue"
    );
}
