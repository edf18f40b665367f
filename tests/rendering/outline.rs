//! The shared outline pass (`materials/lib/outline.pass.toml`, seed 004 §9),
//! as velvet includes it: the pass exists exactly in the `OUTLINE` variants,
//! and the rim it draws around the sphere is `outline_width` pixels wide at
//! any camera distance up to `outline_max_distance`, thinning beyond it.
//!
//! The width is measured on the picture: the sphere drawn with the outline
//! and without it differ only where the pushed-out back faces show, a ring
//! outside the silhouette; its width along the horizontal line through the
//! centre is counted in pixels on both sides.

use std::path::{Path, PathBuf};
use weft_render::{
    Background, ColorFormat, EnvironmentMaps, Gpu, HdrImage, Luts, Material, PreviewOptions,
    RenderOptions, Renderer, Scene,
};

fn generated() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated")
}

fn velvet() -> weft_meta::MaterialMetadata {
    let text = std::fs::read_to_string(generated().join("velvet/velvet.meta.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

#[test]
fn the_outline_pass_exists_exactly_where_its_keyword_is_on() {
    let meta = velvet();
    let outline = meta
        .passes
        .iter()
        .find(|p| p.name == "outline")
        .expect("velvet includes lib/outline.pass.toml");
    assert_eq!(outline.when.len(), 1, "{:?}", outline.when);
    assert_eq!(outline.when[0].subject, "OUTLINE");
    assert_eq!(outline.primitive.cull_mode, weft_meta::CullMode::Front);
    assert!(
        meta.keywords.iter().any(|k| k.name == "OUTLINE"),
        "keyword OUTLINE"
    );
    for p in ["outline_color", "outline_width", "outline_max_distance"] {
        assert!(meta.parameters.iter().any(|x| x.name == p), "parameter {p}");
    }
    let mut on = 0;
    for v in &meta.variants {
        let lit = v.keywords["OUTLINE"] == "on";
        let expected: Vec<&str> = if lit {
            vec!["forward", "outline"]
        } else {
            vec!["forward"]
        };
        assert_eq!(v.passes, expected, "{}", v.id);
        let target = match &v.alias_of {
            Some(t) => meta.variants.iter().find(|x| &x.id == t).unwrap(),
            None => v,
        };
        let shader = target.shader.as_ref().unwrap();
        let has_entry = shader.entry_points.iter().any(|e| e.name == "vs_outline");
        assert_eq!(has_entry, lit, "{}: vs_outline present = {has_entry}", v.id);
        on += lit as usize;
    }
    assert_eq!(
        on * 2,
        meta.variants.len(),
        "half the variants have OUTLINE on"
    );
}

const SIZE: u32 = 256;

struct Setup {
    renderer: Renderer,
}

impl Setup {
    fn new() -> Setup {
        let luts = Luts::load_dir(generated()).expect("generated/ LUTs");
        let gpu = Gpu::new().unwrap_or_else(|e| {
            panic!("outline tests need a Vulkan adapter (apt-get install mesa-vulkan-drivers): {e}")
        });
        let env = EnvironmentMaps::sky(&PreviewOptions::default().sky_params());
        Setup {
            renderer: Renderer::new(gpu, &env, &luts).expect("renderer"),
        }
    }

    fn render(&mut self, outline: bool, values: &[(&str, &str)], distance: f32) -> HdrImage {
        let mut m = Material::load(generated().join("velvet/velvet.meta.json")).unwrap();
        m.set_keyword("OUTLINE", if outline { "on" } else { "off" })
            .unwrap();
        for (name, value) in values {
            m.set_from_str(name, value).unwrap();
        }
        let mut scene = Scene::sphere();
        // Straight ahead, so the centre row crosses the silhouette square on.
        scene.camera.eye = [0.0, 0.0, distance];
        let options = RenderOptions {
            width: SIZE,
            height: SIZE,
            format: ColorFormat::Rgba32Float,
            background: Background::Color([0.5, 0.5, 0.5, 1.0]),
            ..RenderOptions::default()
        };
        self.renderer.render(&m, &scene, &options).expect("render")
    }

    /// Pixels of the outline ring along the centre row, (left, right): those
    /// that the outline changes (it is black on a grey background).
    fn ring_width(&mut self, values: &[(&str, &str)], distance: f32) -> (usize, usize) {
        let with = self.render(true, values, distance);
        let without = self.render(false, values, distance);
        let row = (SIZE / 2) as usize * SIZE as usize;
        let changed: Vec<bool> = (0..SIZE as usize)
            .map(|x| {
                let (a, b) = (with.pixels[row + x], without.pixels[row + x]);
                (0..3).any(|c| (a[c] - b[c]).abs() > 0.05)
            })
            .collect();
        let half = SIZE as usize / 2;
        let left = changed[..half].iter().filter(|&&c| c).count();
        let right = changed[half..].iter().filter(|&&c| c).count();
        (left, right)
    }
}

/// Rasterisation covers a pixel when its centre is inside: a ring of w pixels
/// covers w or w ± 1 of them on one row.
fn assert_width(what: &str, (left, right): (usize, usize), expected: f32) {
    for (side, n) in [("left", left), ("right", right)] {
        assert!(
            (n as f32 - expected).abs() <= 1.0,
            "{what}: {n} outline pixels on the {side}, expected {expected} ± 1"
        );
    }
}

#[test]
fn the_outline_is_as_wide_as_asked_in_pixels_at_any_distance_up_to_the_clamp() {
    let _gpu = weft_tests::gpu_serial();
    let mut s = Setup::new();
    for width in [2.0f32, 6.0] {
        let w = format!("{width}");
        for distance in [4.5f32, 9.0] {
            let ring = s.ring_width(&[("outline_width", &w)], distance);
            println!("width {width} px at distance {distance}: {ring:?}");
            assert_width(&format!("width {width} at {distance}"), ring, width);
        }
    }
    // Beyond the clamp distance the ring thins as clamp / depth: 8 px with
    // the clamp at 4.5 units, the silhouette at depth 9 − 1/9 (unit sphere
    // seen from 9), is 4.05 px.
    let ring = s.ring_width(
        &[("outline_width", "8"), ("outline_max_distance", "4.5")],
        9.0,
    );
    println!("width 8 px, clamp 4.5, at distance 9: {ring:?}");
    assert_width("beyond the clamp", ring, 4.0);
    // Width 0 draws nothing outside the sphere.
    let ring = s.ring_width(&[("outline_width", "0")], 4.5);
    assert_eq!(ring, (0, 0), "width 0");
}
