//! The environment from the page: the light moves the sky's sun, and a cube
//! parameter takes an equirectangular panorama.

use super::{FLIP_BOUND, Page, SIZE, flip_mean, preview, save};
use base64::Engine;
use serde_json::json;
use weft_render::HdrImage;
use weft_tests::repo;

/// Moving the light moves the sky's sun too: the server computes the
/// environment (cube, SH) for the new sun and the page's picture matches
/// `weft preview --light` of the same direction.
#[test]
fn light_direction_moves_the_sun_and_matches_weft_preview() {
    let page = Page::open(&repo().join("materials"));
    page.select("standard");
    let default_light = page.capture();
    let set = |which: &str, degrees: i32| {
        page.eval(&format!(
            "(() => {{ const f = document.querySelector('[data-light=\"{which}\"] input[type=number]'); \
             f.value = '{degrees}'; f.dispatchEvent(new Event('change')); return window.weftInspector.idle(); }})()"
        ));
    };
    set("azimuth", 55);
    set("elevation", 40);
    page.idle();
    assert!(
        page.eval("window.weftInspector.state.envLoads").as_u64() >= Some(1),
        "the page did not fetch the environment for the new sun"
    );
    let light: Vec<f32> = page
        .eval("window.weftInspector.state.renderer.light.direction")
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap() as f32)
        .collect();
    let light: [f32; 3] = light.try_into().unwrap();
    let (a, e) = (55f32.to_radians(), 40f32.to_radians());
    let expected = [e.cos() * a.sin(), e.sin(), e.cos() * a.cos()];
    for i in 0..3 {
        assert!(
            (light[i] - expected[i]).abs() < 1e-5,
            "{light:?} vs {expected:?}"
        );
    }
    // The environment the page now binds has its sun there.
    let sun: Vec<f64> = page
        .eval("window.weftInspector.state.renderer.env.sky.sun_direction")
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    for i in 0..3 {
        assert!(
            (sun[i] - f64::from(expected[i])).abs() < 1e-5,
            "sky sun {sun:?}"
        );
    }
    let moved = page.capture();
    let lavapipe = preview("standard", Some(light));
    let lavapipe_default_sky = {
        // What the page drew before the sun followed the light: the light
        // moved, the sky's sun at the default (for the report only).
        let _gpu = weft_tests::gpu_serial();
        let meta = repo().join("generated/standard/standard.meta.json");
        let m = weft_render::Material::load(&meta).unwrap();
        let luts = weft_render::Luts::for_metadata(&meta).unwrap();
        let options = weft_render::PreviewOptions {
            width: SIZE,
            height: SIZE,
            light_direction: Some(light),
            ..Default::default()
        };
        let env =
            weft_render::EnvironmentMaps::sky(&weft_render::PreviewOptions::default().sky_params());
        let gpu = weft_render::Gpu::new().unwrap();
        let mut r = weft_render::Renderer::new(gpu, &env, &luts).unwrap();
        r.render(&m, &options.scene(), &options.render_options())
            .unwrap()
    };
    let mean = flip_mean(&lavapipe, &moved);
    let stale = flip_mean(&lavapipe, &lavapipe_default_sky);
    let change = flip_mean(&default_light, &moved);
    eprintln!(
        "standard, light {light:?}: page vs weft preview --light FLIP mean {mean:.5}; \
         default vs moved light in the page {change:.5}; \
         weft preview with the sky's sun left at the default vs moved {stale:.5}"
    );
    assert!(change > 0.01, "moving the light did not change the picture");

    // Dragging: many directions at once fetch one environment more (the
    // latest), which ends up bound.
    let loads = |p: &Page| {
        p.eval("window.weftInspector.state.envLoads")
            .as_u64()
            .unwrap()
    };
    let before = loads(&page);
    page.eval(
        "(() => { const s = document.querySelector('[data-light=\"azimuth\"] input[type=range]'); \
         for (const v of [300, 350, 400, 450, 500, 550, 600]) { s.value = v; s.dispatchEvent(new Event('input')); } \
         return window.weftInspector.idle(); })()",
    );
    let after = loads(&page);
    assert!(
        (before + 1..=before + 2).contains(&after),
        "seven light moves loaded {} environments",
        after - before
    );
    let agree = page.eval(
        "(() => { const r = window.weftInspector.state.renderer; const a = r.light.direction; \
         const n = Math.hypot(...a); const s = r.env.sky.sun_direction; \
         return Math.abs(a[0] / n - s[0]) + Math.abs(a[1] / n - s[1]) + Math.abs(a[2] / n - s[2]) < 1e-5; })()",
    );
    assert_eq!(
        agree,
        json!(true),
        "the bound sky's sun is the latest light direction"
    );
    assert!(
        mean <= FLIP_BOUND,
        "page vs weft preview --light {light:?}: FLIP mean {mean:.4} > {FLIP_BOUND} (page {}, weft preview {})",
        save(&moved, "standard.light.page.png").display(),
        save(&lavapipe, "standard.light.preview.png").display()
    );
}

/// An equirectangular panorama as the engine's cube faces, the page's
/// conversion restated: face texel (x, y) looks along
/// `weft_render::cube_direction`; the panorama's top row is +Y, its centre
/// column −Z, three quarters across +X; bilinear, wrapping in longitude.
fn equirect_to_cube(src: &[u8], w: usize, h: usize, size: usize, srgb: bool) -> Vec<u8> {
    let decode = |i: usize| {
        let c = f64::from(src[i]) / 255.0;
        if srgb && i % 4 != 3 {
            if c <= 0.04045 {
                c / 12.92
            } else {
                ((c + 0.055) / 1.055).powf(2.4)
            }
        } else {
            c
        }
    };
    let mut out = Vec::with_capacity(size * size * 24);
    for face in 0..6u32 {
        for y in 0..size {
            for x in 0..size {
                let u = (x as f64 + 0.5) / size as f64 * 2.0 - 1.0;
                let v = (y as f64 + 0.5) / size as f64 * 2.0 - 1.0;
                let d = weft_render::cube_direction(face, u, v);
                let eu = 0.5 + d[0].atan2(-d[2]) / (2.0 * std::f64::consts::PI);
                let ev = d[1].clamp(-1.0, 1.0).acos() / std::f64::consts::PI;
                let fx = eu * w as f64 - 0.5;
                let fy = (ev * h as f64 - 0.5).clamp(0.0, (h - 1) as f64);
                let (x0, y0) = (fx.floor(), fy.floor());
                let (tx, ty) = (fx - x0, fy - y0);
                let xa = (x0 as i64).rem_euclid(w as i64) as usize;
                let xb = (xa + 1) % w;
                let ya = y0 as usize;
                let yb = (ya + 1).min(h - 1);
                for c in 0..4 {
                    let at = |xx: usize, yy: usize| decode((yy * w + xx) * 4 + c);
                    let a = at(xa, ya) * (1.0 - tx) + at(xb, ya) * tx;
                    let b = at(xa, yb) * (1.0 - tx) + at(xb, yb) * tx;
                    let m = a * (1.0 - ty) + b * ty;
                    let e = if srgb && c != 3 {
                        if m <= 0.0031308 {
                            m * 12.92
                        } else {
                            1.055 * m.powf(1.0 / 2.4) - 0.055
                        }
                    } else {
                        m
                    };
                    out.push((e.clamp(0.0, 1.0) * 255.0).round() as u8);
                }
            }
        }
    }
    out
}

/// A `w`×`h` equirectangular panorama: black, white within `radius_deg`
/// of `towards` (the same mapping as [`equirect_to_cube`]).
fn spot_panorama(w: usize, h: usize, towards: [f64; 3], radius_deg: f64) -> Vec<u8> {
    let mut out = Vec::with_capacity(w * h * 4);
    for y in 0..h {
        for x in 0..w {
            let lon = ((x as f64 + 0.5) / w as f64 - 0.5) * 2.0 * std::f64::consts::PI;
            let colat = (y as f64 + 0.5) / h as f64 * std::f64::consts::PI;
            let d = [
                colat.sin() * lon.sin(),
                colat.cos(),
                -colat.sin() * lon.cos(),
            ];
            let c = d[0] * towards[0] + d[1] * towards[1] + d[2] * towards[2];
            let on = c >= radius_deg.to_radians().cos();
            out.extend_from_slice(&if on {
                [255, 255, 255, 255]
            } else {
                [0, 0, 0, 255]
            });
        }
    }
    out
}

/// Sums of the luminance change (b − a) over the left, right, top and
/// bottom halves of the picture.
fn halves(a: &HdrImage, b: &HdrImage) -> [f64; 4] {
    let mut s = [0f64; 4];
    let n = a.width as usize;
    for (i, (p, q)) in a.pixels.iter().zip(&b.pixels).enumerate() {
        let l = |c: &[f32; 4]| 0.2126 * c[0] as f64 + 0.7152 * c[1] as f64 + 0.0722 * c[2] as f64;
        let d = (l(q) - l(p)).max(0.0);
        let (x, y) = (i % n, i / n);
        s[if x < n / 2 { 0 } else { 1 }] += d;
        s[if y < n / 2 { 2 } else { 3 }] += d;
    }
    s
}

/// A cube parameter takes an equirectangular panorama: the page converts it
/// to the engine's six faces (checked texel for texel against
/// `weft_render::cube_direction`), binds it, and the picture changes where
/// the panorama's bright spot is reflected.
#[test]
fn cube_parameter_takes_an_equirectangular_panorama() {
    let page = Page::open(&repo().join("materials"));
    page.select("standard");
    page.eval(
        "(() => { const s = document.querySelector('[data-keyword=\"SPHERE_MAP\"] select'); \
         s.value = 'add'; s.dispatchEvent(new Event('change')); return window.weftInspector.idle(); })()",
    );
    assert_eq!(
        page.eval("window.weftInspector.variantId()"),
        json!("fast.normal_map-off.sphere_map-add")
    );
    let base = page.capture();
    let dir = tempfile::tempdir().unwrap();
    let (w, h) = (128usize, 64usize);
    let load = |name: &str, towards: [f64; 3]| -> Vec<u8> {
        let rgba = spot_panorama(w, h, towards, 25.0);
        let png = dir.path().join(name);
        std::fs::write(
            &png,
            weft_render::encode_png(w as u32, h as u32, &rgba).unwrap(),
        )
        .unwrap();
        page.tab
            .find_element("[data-param=\"sphere_map\"] input[type=file]")
            .and_then(|e| e.set_input_files(&[png.to_str().unwrap()]).map(|_| ()))
            .expect("the sphere map's file picker takes a file");
        page.wait_for(&format!(
            "document.querySelector('[data-param=\"sphere_map\"] .texname').textContent === '{name}' \
             && !!window.weftInspector.cubeFaces('sphere_map')"
        ));
        page.idle();
        rgba
    };
    let faces = |rgba: &[u8]| {
        let got = page.eval("window.weftInspector.cubeFaces('sphere_map')");
        let size = got["size"].as_u64().unwrap() as usize;
        assert_eq!(size, 32, "a 128-wide panorama gives 32² faces");
        assert_eq!(got["srgb"], json!(false), "sphere_map is linear data");
        let bytes = base64::engine::general_purpose::STANDARD
            .decode(got["faces"].as_str().unwrap())
            .unwrap();
        let want = equirect_to_cube(rgba, w, h, size, false);
        assert_eq!(bytes.len(), want.len());
        let worst = bytes
            .iter()
            .zip(&want)
            .map(|(a, b)| a.abs_diff(*b))
            .max()
            .unwrap();
        assert!(
            worst <= 1,
            "the page's faces differ from the engine's by {worst}"
        );
    };

    // A bright spot towards +X: the sphere map is sampled by the view-space
    // reflection, so it shows on the right of the sphere.
    let spot_x = load("spot_x.png", [1.0, 0.0, 0.0]);
    faces(&spot_x);
    let right = page.capture();
    let [l, r, t, b] = halves(&base, &right);
    eprintln!("+X spot: brightening left {l:.2}, right {r:.2}, top {t:.2}, bottom {b:.2}");
    assert!(r > 20.0 && r > 20.0 * l, "+X spot: left {l}, right {r}");
    assert!(t < 2.0 * b && b < 2.0 * t, "+X spot: top {t}, bottom {b}");

    // A second panorama, the spot towards +Y: the top of the sphere instead.
    let spot_y = load("spot_y.png", [0.0, 1.0, 0.0]);
    faces(&spot_y);
    let top = page.capture();
    let [l, r, t, b] = halves(&base, &top);
    eprintln!("+Y spot: brightening left {l:.2}, right {r:.2}, top {t:.2}, bottom {b:.2}");
    assert!(t > 20.0 && t > 20.0 * b, "+Y spot: top {t}, bottom {b}");
    assert!(r < 2.0 * l && l < 2.0 * r, "+Y spot: left {l}, right {r}");
    assert!(
        flip_mean(&right, &top) > 0.01,
        "the second image did not change the picture"
    );

    // The sRGB path (a colour cube, rgba8unorm_srgb): filtered in linear.
    let ramp: Vec<u8> = (0..16 * 8)
        .flat_map(|i| [(i % 16 * 17) as u8, (i / 16 * 36) as u8, 200, 255])
        .collect();
    for srgb in [false, true] {
        let js: Vec<u8> = page
            .eval(&format!(
                "window.weftInspector.equirectToCube({}, 16, 8, 8, {srgb})",
                serde_json::to_string(&ramp).unwrap()
            ))
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap() as u8)
            .collect();
        let want = equirect_to_cube(&ramp, 16, 8, 8, srgb);
        let worst = js
            .iter()
            .zip(&want)
            .map(|(a, b)| a.abs_diff(*b))
            .max()
            .unwrap();
        assert!(
            worst <= 1,
            "srgb {srgb}: the page's faces differ by {worst}"
        );
    }
}
