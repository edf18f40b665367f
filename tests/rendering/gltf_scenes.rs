//! glTF scenes (docs/gltf.md):
//!
//! - the committed glTF content is what its generator
//!   (`weft_golden::gltf_samples`) makes;
//! - every hostile file fails with an error naming its JSON pointer;
//! - the showroom's materials map as docs/gltf.md's table says, its nodes
//!   land where their world matrices put them, its mesh files hold the
//!   streams the glTF holds;
//! - tangents weft generates (MikkTSpace) follow the stated tangent frame.

use std::path::{Path, PathBuf};
use weft_compiler::{SceneBuildOptions, build_scene};
use weft_golden::gltf_samples;
use weft_meta::mesh::MeshData;
use weft_meta::scene::SceneMetadata;
use weft_tests::repo;

#[test]
fn committed_gltf_samples_are_what_the_generator_makes() {
    for (path, bytes) in gltf_samples::committed_files() {
        let on_disk = std::fs::read(repo().join(&path))
            .unwrap_or_else(|e| panic!("{path}: {e}; run `cargo xtask gltf-samples`"));
        assert!(
            on_disk == bytes,
            "{path} differs from its generator; run `cargo xtask gltf-samples`"
        );
    }
}

/// The build's error text for a scene that must fail.
fn build_error(path: &Path) -> String {
    match build_scene(path, &SceneBuildOptions::default()) {
        Ok(_) => panic!("{} built", path.display()),
        Err((db, diags)) => diags.render_plain(&db),
    }
}

#[test]
fn hostile_gltf_files_fail_at_their_json_pointer() {
    let cases = gltf_samples::hostile();
    assert!(cases.len() >= 12);
    for (name, _, pointer, phrase) in cases {
        let path = repo().join(format!("tests/gltf/bad/{name}.gltf"));
        let text = build_error(&path);
        assert!(
            text.contains(&format!("{name}.gltf at {pointer}:")),
            "{name}: the error does not name `{pointer}`:\n{text}"
        );
        assert!(text.contains(phrase), "{name}: no `{phrase}` in:\n{text}");
    }
}

/// `scenes/gltf/showroom.glb` built as it is (no `auto` tier in it).
fn showroom() -> (SceneMetadata, std::collections::BTreeMap<String, Vec<u8>>) {
    let out = build_scene(
        &repo().join("scenes/gltf/showroom.glb"),
        &SceneBuildOptions::default(),
    )
    .unwrap_or_else(|(db, diags)| panic!("{}", diags.render_plain(&db)));
    (out.metadata, out.files)
}

fn constant(meta: &SceneMetadata, instance: &str, name: &str) -> serde_json::Value {
    let inst = meta
        .instances
        .iter()
        .find(|i| i.name == instance)
        .unwrap_or_else(|| panic!("no instance `{instance}`"));
    inst.constants
        .get(name)
        .or_else(|| inst.uniform_values.get(name))
        .cloned()
        .unwrap_or_else(|| panic!("{instance}: no value `{name}`"))
}

fn number(v: serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("{v} is not a number"))
}

#[test]
fn gltf_materials_map_as_documented() {
    let (meta, _) = showroom();
    let by_name = |n: &str| meta.instances.iter().find(|i| i.name == n).unwrap();
    // KHR_materials_sheen → velvet reference; α = sheenRoughness² (the
    // Khronos sample renderer's), velvet's α = 1 − smoothness.
    let drape = by_name("drape");
    assert_eq!(
        (drape.material.as_str(), drape.tier.as_str()),
        ("velvet", "reference")
    );
    assert!((number(constant(&meta, "drape", "smoothness")) - (1.0 - 0.6 * 0.6)).abs() < 1e-6);
    // velvet's sheen colour is F0 (0.04) + scatter colour: scatter = sheen − 0.04,
    // uploaded linear.
    let scatter = constant(&meta, "drape", "scatter_color");
    for (c, want) in scatter.as_array().unwrap().iter().zip([0.51, 0.18, 0.26]) {
        assert!((c.as_f64().unwrap() - want).abs() < 1e-4, "{scatter}");
    }
    // Core metallic-roughness → standard; KHR_materials_specular's factor
    // scales F0 (standard's specular_strength).
    let frame = by_name("sofa_p0");
    assert_eq!(frame.material, "standard");
    assert!((number(constant(&meta, "sofa_p0", "specular_strength")) - 0.5).abs() < 1e-6);
    assert!((number(constant(&meta, "sofa_p0", "roughness")) - 0.45).abs() < 1e-6);
    let base = constant(&meta, "sofa_p0", "base_color");
    for (c, want) in base.as_array().unwrap().iter().zip([0.32, 0.2, 0.12, 1.0]) {
        // The factor is linear in glTF; weft uploads linear: the round trip
        // through the sRGB-edited parameter keeps it.
        assert!((c.as_f64().unwrap() - want).abs() < 1e-4, "{base}");
    }
    // KHR_materials_iridescence → laser fast, the film's parameters as written.
    let foil = by_name("foil_swatch");
    assert_eq!(
        (foil.material.as_str(), foil.tier.as_str()),
        ("laser", "fast")
    );
    for (name, want) in [
        ("film_strength", 1.0),
        ("film_ior", 1.8),
        ("thickness_min", 100.0),
        ("thickness_max", 420.0),
    ] {
        assert!(
            (number(constant(&meta, "foil_swatch", name)) - want).abs() < 1e-4,
            "{name}"
        );
    }
    // KHR_materials_anisotropy → silk's GGX lobe.
    let ball = by_name("satin_ball");
    assert_eq!(ball.material, "silk");
    assert_eq!(ball.keywords["ANISO_MODEL"], "ggx");
    // extras.weft → any weft material.
    let silk = by_name("shot_silk_swatch");
    assert_eq!(
        (
            silk.material.as_str(),
            silk.preset.as_deref(),
            silk.tier.as_str()
        ),
        ("microcylinder", Some("silk_shot"), "fast")
    );
    // Every mesh primitive a node draws is an instance: 1 + 6 + 1 + 1 + 1.
    assert_eq!(meta.instances.len(), 10);
    // Opaque, single-sided materials keep their own state.
    assert!(
        frame
            .passes
            .iter()
            .all(|p| p.render_state.cull == weft_meta::CullMode::Back
                && p.render_state.blend == weft_meta::BlendMode::Opaque)
    );
    // KHR_materials_variants: the linen variant's stand-ins for both
    // cushions, built (their shader listed), not drawn by default.
    let linen = &meta.variants["linen cushions"];
    assert_eq!(linen.keys().collect::<Vec<_>>(), ["sofa_p4", "sofa_p5"]);
    for (replaced, stand_in) in linen {
        assert_eq!(stand_in.material, "standard");
        assert!(meta.shaders.iter().any(|s| s.id == stand_in.shader));
        assert_eq!(stand_in.mesh, by_name(replaced).mesh, "the same primitive");
    }
    assert!(
        !meta.variants.contains_key("velvet cushions"),
        "the default material: no stand-in"
    );
    // The first directional light, towards it = the node's +Z.
    let light = meta.light.as_ref().unwrap();
    let d = [-0.62f64, 0.55, 0.56];
    let len = d.iter().map(|x| x * x).sum::<f64>().sqrt();
    for (a, b) in light.direction.iter().zip(d) {
        assert!((a - b / len).abs() < 1e-5, "{:?}", light.direction);
    }
    assert!(
        (light.color.unwrap()[0] - 3.0).abs() < 1e-6,
        "colour × intensity"
    );
    // The camera node: yfov 0.6 rad.
    assert!((meta.camera.fov_degrees - 0.6f64.to_degrees()).abs() < 1e-4);
    assert!((meta.camera.position[1] - 0.9).abs() < 1e-6);
}

#[test]
fn gltf_meshes_ship_in_the_scene_folder_as_the_file_holds_them() {
    let (meta, files) = showroom();
    let mesh = |name: &str| {
        let entry = &meta.meshes[name];
        assert!(
            entry.path.is_none(),
            "{name}: a scene-folder mesh has no library path"
        );
        let file = entry.file.as_ref().unwrap();
        let bytes = &files[&format!("showroom/{file}")];
        (MeshData::from_bytes(bytes).unwrap(), entry.radius.unwrap())
    };
    // The sphere went in with its own tangents: read back exactly.
    let sphere = weft_render::Scene::new(weft_render::SceneKind::Sphere).mesh;
    let (ball, radius) = mesh(
        &meta
            .instances
            .iter()
            .find(|i| i.name == "satin_ball")
            .unwrap()
            .mesh,
    );
    assert!(ball.positions == sphere.positions, "positions as written");
    assert!(ball.normals == sphere.normals, "normals as written");
    assert!(ball.tangents == sphere.tangents, "tangents as written");
    assert!(ball.indices == sphere.indices, "indices as written");
    assert!((radius - 1.0).abs() < 1e-5, "{radius}");
    // The sofa's boxes have no normals: flat normals, one vertex per corner.
    let (block, _) = mesh(
        &meta
            .instances
            .iter()
            .find(|i| i.name == "sofa_p0")
            .unwrap()
            .mesh,
    );
    assert_eq!(block.positions.len(), 36, "12 triangles, unwelded");
    for t in block.indices.chunks_exact(3) {
        let [a, b, c] = [0, 1, 2].map(|k| block.positions[t[k] as usize]);
        let n = block.normals[t[0] as usize];
        let e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let cross = [
            e1[1] * e2[2] - e1[2] * e2[1],
            e1[2] * e2[0] - e1[0] * e2[2],
            e1[0] * e2[1] - e1[1] * e2[0],
        ];
        let dot: f32 = cross.iter().zip(n).map(|(x, y)| x * y).sum();
        assert!(
            dot > 0.0,
            "the flat normal faces the triangle's front (CCW)"
        );
    }
}

/// The draped cloth went in without tangents: MikkTSpace's, as glTF asks.
/// They must follow weft's tangent frame (T along +u, B = w·(N × T) along
/// +v): checked against the UV gradient of each triangle, computed here.
#[test]
fn generated_tangents_follow_the_tangent_frame() {
    let (meta, files) = showroom();
    let name = &meta
        .instances
        .iter()
        .find(|i| i.name == "drape")
        .unwrap()
        .mesh;
    let file = meta.meshes[name].file.clone().unwrap();
    let m = MeshData::from_bytes(&files[&format!("showroom/{file}")]).unwrap();
    let (mut agree_t, mut agree_b, mut n) = (0, 0, 0);
    for t in m.indices.chunks_exact(3) {
        let [i0, i1, i2] = [0, 1, 2].map(|k| t[k] as usize);
        let (p0, p1, p2) = (m.positions[i0], m.positions[i1], m.positions[i2]);
        let (u0, u1, u2) = (m.uv0[i0], m.uv0[i1], m.uv0[i2]);
        let e1 = [p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]];
        let e2 = [p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]];
        let (du1, dv1, du2, dv2) = (u1[0] - u0[0], u1[1] - u0[1], u2[0] - u0[0], u2[1] - u0[1]);
        let det = du1 * dv2 - du2 * dv1;
        if det.abs() < 1e-12 {
            continue;
        }
        // dP/du and dP/dv of the triangle.
        let dpdu: Vec<f32> = (0..3).map(|k| (e1[k] * dv2 - e2[k] * dv1) / det).collect();
        let dpdv: Vec<f32> = (0..3).map(|k| (e2[k] * du1 - e1[k] * du2) / det).collect();
        let tan = m.tangents[i0];
        let nrm = m.normals[i0];
        let b = [
            tan[3] * (nrm[1] * tan[2] - nrm[2] * tan[1]),
            tan[3] * (nrm[2] * tan[0] - nrm[0] * tan[2]),
            tan[3] * (nrm[0] * tan[1] - nrm[1] * tan[0]),
        ];
        let dot = |a: &[f32], b: &[f32]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f32>();
        agree_t += usize::from(dot(&dpdu, &tan[..3]) > 0.0);
        agree_b += usize::from(dot(&dpdv, &b) > 0.0);
        n += 1;
    }
    assert!(n > 1000);
    assert!(
        agree_t * 100 >= n * 99,
        "T along +u on {agree_t} of {n} triangles"
    );
    assert!(
        agree_b * 100 >= n * 99,
        "B along +v on {agree_b} of {n} triangles"
    );
}

#[test]
fn a_character_from_gltf_extras_builds_with_its_weft_materials() {
    let out = build_scene(
        &repo().join("tests/gltf/bust.gltf"),
        &SceneBuildOptions::default(),
    )
    .unwrap_or_else(|(db, diags)| panic!("{}", diags.render_plain(&db)));
    let materials: Vec<&str> = out
        .metadata
        .instances
        .iter()
        .map(|i| i.material.as_str())
        .collect();
    assert_eq!(materials, ["face", "eye", "hair", "skin"]);
    // The outline keyword from extras.weft: the outline pass is drawn.
    let face = &out.metadata.instances[0];
    assert!(
        face.passes.iter().any(|p| p.name == "outline"),
        "{:?}",
        face.passes
    );
}

/// An instance's bound texture file and its texels from the scene's files.
fn bound_image<'a>(
    meta: &'a SceneMetadata,
    files: &'a std::collections::BTreeMap<String, Vec<u8>>,
    instance: &str,
    param: &str,
) -> (&'a weft_meta::ResourceFile, &'a [u8]) {
    let inst = meta.instances.iter().find(|i| i.name == instance).unwrap();
    let t = inst
        .textures
        .values()
        .find(|t| t.parameter == param)
        .unwrap_or_else(|| panic!("{instance}: `{param}` is not bound"));
    let file = t.file.as_ref().expect("an image file");
    let bytes = files
        .get(&format!("{}/{}", meta.name, file.path))
        .unwrap_or_else(|| panic!("the scene folder has no {}", file.path));
    (file, bytes)
}

/// `tests/gltf/cutouts.glb` built as it is.
fn cutouts() -> (SceneMetadata, std::collections::BTreeMap<String, Vec<u8>>) {
    let out = build_scene(
        &repo().join("tests/gltf/cutouts.glb"),
        &SceneBuildOptions {
            gltf_materials: Some(&repo().join("materials")),
            ..SceneBuildOptions::default()
        },
    )
    .unwrap_or_else(|(db, diags)| panic!("{}", diags.render_plain(&db)));
    (out.metadata, out.files)
}

#[test]
fn gltf_textures_become_the_scene_folders_images() {
    let (meta, files) = cutouts();
    let frame = meta
        .instances
        .iter()
        .find(|i| i.name == "textured_frame")
        .unwrap();
    assert_eq!(
        frame.keywords["NORMAL_MAP"], "on",
        "normalTexture turns the normal map on"
    );
    assert!((number(constant(&meta, "textured_frame", "normal_strength")) - 0.8).abs() < 1e-6);
    assert!((number(constant(&meta, "textured_frame", "occlusion_strength")) - 0.7).abs() < 1e-6);
    // KHR_texture_transform's scale and offset: the base map's tiling.
    let st = constant(&meta, "textured_frame", "base_map_st");
    let st: Vec<f64> = st
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert_eq!(st, [2.0, 1.0, 0.25, 0.0]);
    // An image is no constant: the maps stay bound.
    for p in ["base_map", "normal_map", "rmo_map"] {
        assert!(!frame.constants.contains_key(p), "{p} folded");
    }
    // Base colour: sRGB texels of the 64 × 64 PNG, exactly.
    let (base, texels) = bound_image(&meta, &files, "textured_frame", "base_map");
    assert_eq!(
        (base.width, base.height, base.format.as_str()),
        (64, 64, "rgba8unorm_srgb")
    );
    assert!(base.path.starts_with("textures/"), "{}", base.path);
    let mut png = png::Decoder::new(std::io::Cursor::new(gltf_samples::wood_base_color()))
        .read_info()
        .unwrap();
    let mut want = vec![0; png.output_buffer_size().unwrap()];
    png.next_frame(&mut want).unwrap();
    assert_eq!(texels, &want[..], "the PNG's texels as stored");
    // Normal map: linear.
    let (normal, _) = bound_image(&meta, &files, "textured_frame", "normal_map");
    assert_eq!(normal.format, "rgba8unorm");
    // RMO repacked from the JPEG's G (roughness) and B (metallic) and the
    // 16 × 16 occlusion PNG's R, at the metallic-roughness map's 32 × 32.
    let (rmo, texels) = bound_image(&meta, &files, "textured_frame", "rmo_map");
    assert_eq!(
        (rmo.width, rmo.height, rmo.format.as_str()),
        (32, 32, "rgba8unorm")
    );
    let at = |x: usize, y: usize| &texels[(y * 32 + x) * 4..(y * 32 + x) * 4 + 4];
    // The brass inlay (rows 14–17): metallic, roughness 0.3 (JPEG's error aside).
    let inlay = at(10, 15);
    assert!(
        inlay[1] > 240 && (inlay[0] as i32 - 76).abs() < 12,
        "{inlay:?}"
    );
    let wood = at(10, 4);
    assert!(wood[1] < 15 && wood[0] > 130, "{wood:?}");
    // Occlusion: the 16 × 16 map at its nearest texel, darker at the corner.
    assert!(
        at(0, 0)[2] < at(16, 16)[2],
        "{:?} {:?}",
        at(0, 0),
        at(16, 16)
    );
    assert_eq!(at(16, 16)[3], 255);
    assert!(
        texels.len() == 32 * 32 * 4
            && files.keys().filter(|k| k.contains("/textures/")).count() == 4
    );
}

/// A manifest in a temporary folder with `images` written beside it.
fn image_scene(params: &str, images: &[(&str, Vec<u8>)]) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    for (name, bytes) in images {
        let path = dir.path().join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, bytes).unwrap();
    }
    let manifest = dir.path().join("img.scene.toml");
    std::fs::write(
        &manifest,
        format!(
            "[scene]\nname = \"img\"\nmaterials = {:?}\nvertex_inputs = [\"position\", \"normal\", \"tangent\", \"uv0\"]\n\n[[instances]]\nname = \"ball\"\nmaterial = \"standard\"\nmesh = \"sphere\"\nparams = {{ {params} }}\n",
            repo().join("materials").display().to_string()
        ),
    )
    .unwrap();
    (dir, manifest)
}

#[test]
fn a_scene_binds_png_and_jpeg_images_written_beside_it() {
    let png = gltf_samples::png_rgba(4, 2, |x, y| [x as u8 * 60, y as u8 * 200, 7, 255]);
    let jpeg = gltf_samples::wood_metallic_roughness();
    let (_dir, manifest) = image_scene(
        "base_map = { file = \"maps/albedo.png\", scale = [3.0, 2.0], offset = [0.5, 0.0] }, rmo_map = { file = \"maps/rmo.jpg\" }",
        &[("maps/albedo.png", png), ("maps/rmo.jpg", jpeg)],
    );
    let out = build_scene(&manifest, &SceneBuildOptions::default())
        .unwrap_or_else(|(db, diags)| panic!("{}", diags.render_plain(&db)));
    let (base, texels) = bound_image(&out.metadata, &out.files, "ball", "base_map");
    assert_eq!((base.width, base.height), (4, 2));
    assert_eq!(&texels[4..8], &[60, 0, 7, 255]);
    assert_eq!(&texels[16..20], &[0, 200, 7, 255]);
    let (rmo, _) = bound_image(&out.metadata, &out.files, "ball", "rmo_map");
    assert_eq!((rmo.width, rmo.height), (32, 32), "the JPEG decoded");
    let st = constant(&out.metadata, "ball", "base_map_st");
    assert_eq!(st, serde_json::json!([3.0, 2.0, 0.5, 0.0]));
}

#[test]
fn bad_scene_images_are_errors_at_the_value() {
    let png = gltf_samples::png_rgba(2, 2, |_, _| [1, 2, 3, 255]);
    for (params, phrase) in [
        (
            "base_map = { file = \"../outside.png\" }",
            "leaves the manifest's folder",
        ),
        ("base_map = { file = \"missing.png\" }", "cannot open"),
        (
            "base_map = { file = \"a.png\", texture = 0 }",
            "need `gltf`",
        ),
        ("base_map = { gltf = \"x.glb\" }", "needs `texture`"),
        (
            "rmo_map = { file = \"a.png\", scale = [2.0, 2.0] }",
            "has no tiling",
        ),
        ("base_map = { file = \"a.png\", scale = [1.0] }", "[u, v]"),
        (
            "base_map = { file = \"a.png\", colour = 1 }",
            "unknown key `colour`",
        ),
        (
            "base_map = { file = \"not_png.png\" }",
            "a GIF image (weft reads PNG and JPEG)",
        ),
    ] {
        let (_dir, manifest) = image_scene(
            params,
            &[
                ("a.png", png.clone()),
                ("not_png.png", b"GIF89a....".to_vec()),
            ],
        );
        let text = build_error(&manifest);
        assert!(text.contains(phrase), "{params}: no `{phrase}` in:\n{text}");
        assert!(
            text.contains("img.scene.toml:"),
            "{params}: no line in:\n{text}"
        );
    }
}

#[test]
fn an_auto_tier_left_without_screen_size_takes_the_cameras_view() {
    // The shipped showroom leaves the satin ball's `screen_size` out: the
    // build derives it from the file's camera (docs/gltf.md "Camera").
    let path = repo().join("generated/scenes/showroom/showroom.scene.json");
    let meta = SceneMetadata::from_json(&std::fs::read_to_string(&path).unwrap()).unwrap();
    let ball = meta
        .instances
        .iter()
        .find(|i| i.name == "satin_ball")
        .unwrap();
    let choice = ball.tier_choice.as_ref().expect("an auto tier");
    // The sphere's bounding box (half-diagonal √3 · scale 0.35) at the
    // node's translation, seen by the camera in a 1080-pixel-high frame.
    let radius = 3f64.sqrt() * 0.35;
    let centre = [-0.5, 0.35, 0.9];
    let d = (0..3)
        .map(|k| (centre[k] - meta.camera.position[k]).powi(2))
        .sum::<f64>()
        .sqrt();
    let half_height = d * (meta.camera.fov_degrees.to_radians() / 2.0).tan();
    let want = (radius / half_height * 540.0).round() as u32;
    assert_eq!(choice.screen_size, want);
}

#[test]
fn the_funnel_counts_what_the_scene_keeps() {
    let (meta, files) = showroom();
    let f = meta.funnel.as_ref().expect("a funnel");
    assert_eq!(
        (
            f.gltf_file.as_deref(),
            f.gltf_materials,
            f.gltf_materials_used
        ),
        (Some("showroom.glb"), Some(7), Some(7))
    );
    let stand_ins: usize = meta.variants.values().map(|v| v.len()).sum();
    assert_eq!(f.instances, meta.instances.len() + stand_ins);
    assert_eq!(f.shaders, meta.shaders.len());
    let distinct: std::collections::BTreeSet<&str> = meta
        .instances
        .iter()
        .chain(meta.variants.values().flat_map(|v| v.values()))
        .map(|i| i.variant.as_str())
        .collect();
    assert_eq!(f.generic_variants, distinct.len());
    let bytes: usize = files
        .iter()
        .filter(|(k, _)| {
            [".wgsl", ".spv", ".hlsl", ".metal", ".glsl"]
                .iter()
                .any(|e| k.ends_with(e))
        })
        .map(|(_, b)| b.len())
        .sum();
    assert_eq!(f.shader_bytes, bytes as u64);
}

#[test]
fn an_instance_overrides_its_passes_render_state() {
    let (_dir, manifest) = image_scene("base_color = [1.0, 1.0, 1.0, 0.5]", &[]);
    let text = std::fs::read_to_string(&manifest).unwrap();
    std::fs::write(
        &manifest,
        format!("{text}double_sided = true\nblend = \"alpha\"\n"),
    )
    .unwrap();
    let out = build_scene(&manifest, &SceneBuildOptions::default())
        .unwrap_or_else(|(db, diags)| panic!("{}", diags.render_plain(&db)));
    let p = &out.metadata.instances[0].passes[0];
    assert_eq!(p.render_state.cull, weft_meta::CullMode::None);
    assert_eq!(p.primitive.cull_mode, weft_meta::CullMode::None);
    assert_eq!(p.render_state.blend, weft_meta::BlendMode::Alpha);
    assert!(!p.depth_stencil.depth_write_enabled && p.render_state.queue == 3000);
    // `opaque` is no override; a typo is named.
    for (value, phrase) in [
        ("\"opaque\"", "not a blend mode an instance may set"),
        ("\"alpah\"", "alpha"),
    ] {
        std::fs::write(&manifest, format!("{text}blend = {value}\n")).unwrap();
        let error = build_error(&manifest);
        assert!(
            error.contains(phrase) && error.contains("img.scene.toml:"),
            "{error}"
        );
    }
}

#[test]
fn alpha_modes_sides_and_emission_map_onto_standard_and_the_render_state() {
    let (meta, _) = cutouts();
    let meta = &meta;
    let by_name = |n: &str| meta.instances.iter().find(|i| i.name == n).unwrap();
    // alphaMode MASK → standard's alpha test at alphaCutoff; doubleSided →
    // the passes draw both faces.
    let lace = by_name("lace_panel");
    assert_eq!(lace.keywords["ALPHA_TEST"], "on");
    assert!((number(constant(meta, "lace_panel", "alpha_cutoff")) - 0.4).abs() < 1e-6);
    assert!(
        lace.passes
            .iter()
            .all(|p| p.render_state.cull == weft_meta::CullMode::None
                && p.primitive.cull_mode == weft_meta::CullMode::None)
    );
    // Emission: emissiveFactor (linear, as uploaded) × emissive_strength.
    assert_eq!(by_name("glow_bulb").keywords["EMISSION"], "on");
    let glow = constant(meta, "glow_bulb", "emissive");
    for (c, want) in glow.as_array().unwrap().iter().zip([1.0, 0.6, 0.3]) {
        assert!((c.as_f64().unwrap() - want).abs() < 1e-4, "{glow}");
    }
    assert!((number(constant(meta, "glow_bulb", "emissive_strength")) - 2.5).abs() < 1e-6);
    // alphaMode BLEND → the passes blend, write no depth, draw after opaque.
    let glass = by_name("glass_block");
    for p in &glass.passes {
        assert_eq!(p.render_state.blend, weft_meta::BlendMode::Alpha);
        assert!(!p.render_state.depth_write && !p.depth_stencil.depth_write_enabled);
        assert!(p.render_state.queue >= 3000);
        assert!(p.color_targets[0].blend.is_some());
    }
}

/// glTF samplers reach the engine as the instance shader's
/// `bindings[].sampler` (the state every engine creates its samplers from):
/// the lace's sampler 1 (CLAMP_TO_EDGE × MIRRORED_REPEAT, magFilter NEAREST,
/// minFilter LINEAR: no mip levels) on `material_sampler`; the frame, whose
/// maps ask for trilinear repeat (stated or left out), keeps the material's.
#[test]
fn gltf_samplers_set_the_instance_shaders_sampler_state() {
    use weft_meta::engine::{MATERIAL_GROUP, MATERIAL_SAMPLER_BINDING};
    use weft_meta::{AddressMode, FilterMode};
    let (meta, _) = cutouts();
    let material_sampler = |instance: &str| {
        let inst = meta.instances.iter().find(|i| i.name == instance).unwrap();
        let shader = meta.shaders.iter().find(|s| s.id == inst.shader).unwrap();
        shader
            .shader
            .bindings
            .iter()
            .find(|b| b.group == MATERIAL_GROUP && b.binding == MATERIAL_SAMPLER_BINDING)
            .and_then(|b| b.sampler.clone())
            .unwrap_or_else(|| panic!("{instance}: no material sampler"))
    };
    let lace = material_sampler("lace_panel");
    assert_eq!(
        (
            lace.address_mode_u,
            lace.address_mode_v,
            lace.mag_filter,
            lace.min_filter,
            lace.lod_max_clamp
        ),
        (
            AddressMode::ClampToEdge,
            AddressMode::MirrorRepeat,
            FilterMode::Nearest,
            FilterMode::Linear,
            0.0
        )
    );
    let frame = material_sampler("textured_frame");
    assert_eq!(
        (
            frame.address_mode_u,
            frame.address_mode_v,
            frame.mag_filter,
            frame.min_filter,
            frame.mipmap_filter
        ),
        (
            AddressMode::Repeat,
            AddressMode::Repeat,
            FilterMode::Linear,
            FilterMode::Linear,
            FilterMode::Linear
        )
    );
    assert!(frame.lod_max_clamp >= 32.0);
}

/// A KHR_texture_transform with a rotation, shared by a material's maps, is
/// baked into the primitive's uv0 (weft's tiling is scale and offset): the
/// tile's mesh file holds the file's uv0 taken through translation ·
/// rotation · scale, its tangents are the ones generated from the file's own
/// uv0 (as a glTF viewer generates them), and the maps read it untiled.
#[test]
fn a_rotated_texture_transform_is_baked_into_the_meshes_uv0() {
    let (meta, files) = cutouts();
    let tiles = meta
        .instances
        .iter()
        .find(|i| i.name == "rotated_tiles")
        .unwrap();
    let plain_frame = meta
        .instances
        .iter()
        .find(|i| i.name == "textured_frame")
        .unwrap();
    assert!(
        tiles.mesh.contains(".uv"),
        "{}: a transformed copy of the primitive",
        tiles.mesh
    );
    let st = constant(&meta, "rotated_tiles", "base_map_st");
    assert_eq!(
        st,
        serde_json::json!([1.0, 1.0, 0.0, 0.0]),
        "no tiling left"
    );
    let read = |name: &str| {
        let file = meta.meshes[name].file.as_ref().unwrap();
        MeshData::from_bytes(&files[&format!("{}/{file}", meta.name)]).unwrap()
    };
    let baked = read(&tiles.mesh);
    // The same box as the frame's, its own (untransformed) uv0 equal.
    let frame = read(&plain_frame.mesh);
    assert_eq!(baked.positions.len(), frame.positions.len());
    let (sin, cos) = 0.5f64.sin_cos();
    for (got, uv) in baked.uv0.iter().zip(&frame.uv0) {
        let (u, v) = (f64::from(uv[0]), f64::from(uv[1]));
        let want = [
            3.0 * cos * u + 2.0 * sin * v + 0.1,
            -3.0 * sin * u + 2.0 * cos * v + 0.2,
        ];
        for k in 0..2 {
            assert!(
                (f64::from(got[k]) - want[k]).abs() < 1e-5,
                "{got:?} from {uv:?}, want {want:?}"
            );
        }
    }
    assert_eq!(
        baked.tangents, frame.tangents,
        "tangents from the file's uv0"
    );
}

/// A manifest's `sampler` on an instance: applied where the shader reads a
/// map through `material_sampler`; on an instance whose shader reads none
/// (every map a built-in default, folded away), a warning that it changes
/// nothing.
#[test]
fn an_instance_sampler_applies_where_a_map_is_read_and_warns_elsewhere() {
    use weft_meta::engine::{MATERIAL_GROUP, MATERIAL_SAMPLER_BINDING};
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("albedo.png"),
        gltf_samples::png_rgba(2, 2, |x, _| [x as u8 * 200, 9, 9, 255]),
    )
    .unwrap();
    let manifest = dir.path().join("s.scene.toml");
    std::fs::write(
        &manifest,
        format!(
            "[scene]\nname = \"s\"\nmaterials = {:?}\nvertex_inputs = [\"position\", \"normal\", \"tangent\", \"uv0\"]\n\n\
             [[instances]]\nname = \"mapped\"\nmaterial = \"standard\"\nmesh = \"sphere\"\n\
             params = {{ base_map = {{ file = \"albedo.png\" }} }}\n\
             sampler = {{ address_mode_u = \"clamp_to_edge\", mag_filter = \"nearest\" }}\n\n\
             [[instances]]\nname = \"plain\"\nmaterial = \"standard\"\nmesh = \"sphere\"\ntranslation = [2.0, 0.0, 0.0]\n\
             sampler = {{ mag_filter = \"nearest\" }}\n",
            repo().join("materials").display().to_string()
        ),
    )
    .unwrap();
    let out = build_scene(&manifest, &SceneBuildOptions::default())
        .unwrap_or_else(|(db, diags)| panic!("{}", diags.render_plain(&db)));
    let meta = &out.metadata;
    let inst = meta.instances.iter().find(|i| i.name == "mapped").unwrap();
    let shader = meta.shaders.iter().find(|s| s.id == inst.shader).unwrap();
    let sampler = shader
        .shader
        .bindings
        .iter()
        .find(|b| b.group == MATERIAL_GROUP && b.binding == MATERIAL_SAMPLER_BINDING)
        .and_then(|b| b.sampler.clone())
        .expect("the map is read through material_sampler");
    assert_eq!(
        (
            sampler.address_mode_u,
            sampler.address_mode_v,
            sampler.mag_filter
        ),
        (
            weft_meta::AddressMode::ClampToEdge,
            weft_meta::AddressMode::Repeat,
            weft_meta::FilterMode::Nearest
        )
    );
    let (db, warnings) = out.warnings.as_ref().expect("a warning");
    let text = warnings.render_plain(db);
    assert!(
        text.contains("warning[unused-sampler]") && text.contains("instance `plain`"),
        "{text}"
    );
    assert!(!text.contains("instance `mapped`"), "{text}");
}

/// A primitive with vertex colours: glTF multiplies them into the base
/// colour, weft's materials read none, so the build says it drops them
/// (once per primitive, however many nodes draw it) and still builds.
#[test]
fn vertex_colours_are_dropped_with_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    // Three positions, then three RGB colours, as little-endian f32.
    let floats: [f32; 18] = [
        0., 0., 0., 1., 0., 0., 0., 1., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1.,
    ];
    let data: Vec<u8> = floats.iter().flat_map(|f| f.to_le_bytes()).collect();
    use base64::Engine as _;
    let uri = format!(
        "data:application/octet-stream;base64,{}",
        base64::engine::general_purpose::STANDARD.encode(&data)
    );
    let gltf = serde_json::json!({
        "asset": { "version": "2.0" },
        "scene": 0, "scenes": [ { "nodes": [0, 1] } ],
        "nodes": [ { "mesh": 0 }, { "mesh": 0, "translation": [2, 0, 0] } ],
        "meshes": [ { "primitives": [ { "attributes": { "POSITION": 0, "COLOR_0": 1 } } ] } ],
        "buffers": [ { "byteLength": 72, "uri": uri } ],
        "bufferViews": [ { "buffer": 0, "byteLength": 72 } ],
        "accessors": [
            { "bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
              "min": [0, 0, 0], "max": [1, 1, 0] },
            { "bufferView": 0, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC3" }
        ]
    });
    let path = dir.path().join("coloured.gltf");
    std::fs::write(&path, serde_json::to_vec(&gltf).unwrap()).unwrap();
    let out = build_with_library(&path);
    assert_eq!(out.metadata.instances.len(), 2);
    let (db, warnings) = out.warnings.as_ref().expect("a warning");
    let text = warnings.render_plain(db);
    assert_eq!(
        text.matches("/meshes/0/primitives/0: drops COLOR_0")
            .count(),
        1,
        "{text}"
    );
}

/// A sphere written with float attributes and under KHR_mesh_quantization
/// (gltfpack's encoding: u16 positions dequantised by the node, i8 normals
/// and tangents, u16 texture coordinates) builds into the same scene within
/// the quantisation's step: the same world positions, normals, tangents,
/// texture coordinates and camera.
#[test]
fn quantized_meshes_build_as_their_float_originals() {
    let dir = tempfile::tempdir().unwrap();
    let build = |name: &str, encoding: gltf_samples::Encoding| {
        let (meta, meshes) = build_glb(dir.path(), name, gltf_samples::quantized_sphere(encoding));
        let mesh = meshes["ball"].clone();
        let m = meta.instances[0].transform.model;
        let world: Vec<[f32; 3]> = mesh
            .positions
            .iter()
            .map(|p| {
                std::array::from_fn(|r| m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r])
            })
            .collect();
        (meta.camera.clone(), mesh, world)
    };
    let (camera, float, float_world) = build("float", gltf_samples::Encoding::Float);
    for encoding in [
        gltf_samples::Encoding::Quantized,
        gltf_samples::Encoding::QuantizedNormalized,
    ] {
        let (q_camera, quantized, q_world) =
            build(&format!("{encoding:?}").to_lowercase(), encoding);
        assert_same_sphere(
            (&camera, &float, &float_world),
            (&q_camera, &quantized, &q_world),
        );
    }
}

fn assert_same_sphere(
    (camera, float, float_world): (&weft_meta::scene::SceneCamera, &MeshData, &[[f32; 3]]),
    (q_camera, quantized, q_world): (&weft_meta::scene::SceneCamera, &MeshData, &[[f32; 3]]),
) {
    assert_eq!(float.indices, quantized.indices);
    // The sphere has radius 1: a u16 step of its 2-unit extent is 3.1e-5
    // (and f32 rounding of the normalised form's scale on top).
    let step = 2.0 / 65535.0 + 2e-6;
    let max_diff = |a: &[f32], b: &[f32]| {
        a.iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f32::max)
    };
    for (a, b) in float_world.iter().zip(q_world) {
        assert!(max_diff(a, b) <= step, "{a:?} vs {b:?}");
    }
    assert!(
        (float_world[0][1] - q_world[0][1]).abs() <= step
            && float_world
                .iter()
                .any(|p| (p[1] - gltf_samples::SPHERE_AT[1]).abs() > 0.5),
        "both at the node's translation"
    );
    // i8 normals and tangents: within one step of 1/127 per component
    // (normals are made unit length when read).
    for (a, b) in float.normals.iter().zip(&quantized.normals) {
        assert!(max_diff(a, b) <= 1.5 / 127.0, "{a:?} vs {b:?}");
    }
    for (a, b) in float.tangents.iter().zip(&quantized.tangents) {
        assert!(max_diff(&a[..3], &b[..3]) <= 1.5 / 127.0, "{a:?} vs {b:?}");
        assert_eq!(a[3], b[3], "bitangent sign");
    }
    for (a, b) in float.uv0.iter().zip(&quantized.uv0) {
        assert!(max_diff(a, b) <= 0.5 / 65535.0 + 1e-7, "{a:?} vs {b:?}");
    }
    // The camera frames the same bounds (the quantised min/max are raw u16
    // values; scaled by the node they are the float ones).
    for k in 0..3 {
        assert!(
            (camera.position[k] - q_camera.position[k]).abs() < 1e-3
                && (camera.target[k] - q_camera.target[k]).abs() < 1e-3,
            "{camera:?} vs {q_camera:?}"
        );
    }
}

/// Builds the glTF file at `path` (outside the repository) with the
/// repository's materials.
fn build_with_library(path: &Path) -> weft_compiler::SceneOutput {
    let materials = repo().join("materials");
    let options = SceneBuildOptions {
        gltf_materials: Some(&materials),
        ..SceneBuildOptions::default()
    };
    build_scene(path, &options).unwrap_or_else(|(db, diags)| panic!("{}", diags.render_plain(&db)))
}

/// Builds `bytes` as `<name>.glb` in `dir`: its metadata and each
/// instance's mesh by instance name.
fn build_glb(
    dir: &Path,
    name: &str,
    bytes: Vec<u8>,
) -> (SceneMetadata, std::collections::BTreeMap<String, MeshData>) {
    let path = dir.join(format!("{name}.glb"));
    std::fs::write(&path, bytes).unwrap();
    let out = build_with_library(&path);
    let meshes = out
        .metadata
        .instances
        .iter()
        .map(|i| {
            let file = out.metadata.meshes[&i.mesh].file.clone().unwrap();
            let bytes = &out.files[&format!("{name}/{file}")];
            (i.name.clone(), MeshData::from_bytes(bytes).unwrap())
        })
        .collect();
    (out.metadata, meshes)
}

/// A skinned mesh draws as glTF poses it: every vertex by its joints'
/// matrices at the file's default transforms, in world space (the node's
/// own translation ignored, the instance's matrix the identity). The pose
/// is computed here from the sample's construction: the child joint turns
/// 90° about +Z around (0, 1, 0).
#[test]
fn skinned_meshes_draw_in_the_files_default_pose() {
    let dir = tempfile::tempdir().unwrap();
    let (meta, meshes) = build_glb(dir.path(), "strip", gltf_samples::skinned_strip());
    let strip = &meshes["strip"];
    let model = meta.instances[0].transform.model;
    let identity = [
        1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    assert_eq!(
        model, identity,
        "a skinned instance is already in world space"
    );
    // Child joint: p ↦ R(p − (0, 1, 0)) + (0, 1, 0), R(x, y) = (−y, x).
    let bent = |[x, y, z]: [f32; 3]| [-(y - 1.0), x + 1.0, z];
    let mut v = 0;
    for (y, w) in gltf_samples::STRIP_ROWS {
        for x in [-0.5f32, 0.5] {
            let b = bent([x, y, 0.0]);
            let want = [(1.0 - w) * x + w * b[0], (1.0 - w) * y + w * b[1], 0.0];
            let got = strip.positions[v];
            assert!(
                (0..3).all(|k| (got[k] - want[k]).abs() < 1e-5),
                "vertex {v}: {got:?}, want {want:?}"
            );
            // The tangent (1, 0, 0) turns by the blend of I and R: along
            // (1 − w, w, 0); the normal (0, 0, 1) stays.
            let t = strip.tangents[v];
            let len = ((1.0 - w).powi(2) + w * w).sqrt();
            let want_t = [(1.0 - w) / len, w / len, 0.0];
            assert!(
                (0..3).all(|k| (t[k] - want_t[k]).abs() < 1e-5) && t[3] == 1.0,
                "tangent {v}: {t:?}, want {want_t:?}"
            );
            assert!((strip.normals[v][2] - 1.0).abs() < 1e-6, "normal {v}");
            v += 1;
        }
    }
}

/// Morph targets blend with the node's weights, else the mesh's: one mesh
/// drawn by two nodes is two posed meshes.
#[test]
fn morph_targets_blend_with_the_default_weights() {
    let dir = tempfile::tempdir().unwrap();
    let (_, meshes) = build_glb(dir.path(), "tri", gltf_samples::morphing_triangle());
    let blend = |weights: [f32; 2]| -> Vec<[f32; 3]> {
        (0..3)
            .map(|v| {
                std::array::from_fn(|k| {
                    gltf_samples::MORPH_BASE[v][k]
                        + weights[0] * gltf_samples::MORPH_TARGETS[0][v][k]
                        + weights[1] * gltf_samples::MORPH_TARGETS[1][v][k]
                })
            })
            .collect()
    };
    for (instance, weights) in [("mesh_weights", [0.5, 0.5]), ("node_weights", [1.0, 0.0])] {
        let mesh = &meshes[instance];
        assert_eq!(mesh.positions, blend(weights), "{instance}");
        // The normal (0, 0, 1) displaced by w₀ (0.5, 0, 0), at unit length.
        let d = weights[0] * gltf_samples::MORPH_NORMAL_DELTA[0];
        let len = (d * d + 1.0).sqrt();
        for n in &mesh.normals {
            assert!(
                (n[0] - d / len).abs() < 1e-6 && n[1] == 0.0 && (n[2] - 1.0 / len).abs() < 1e-6,
                "{instance}: {n:?}"
            );
        }
    }
}

/// `EXT_mesh_gpu_instancing`: each copy is an instance of the scene whose
/// matrix is the node's world transform after the copy's own translation ·
/// rotation · scale, all copies drawing the one mesh; a plain node still
/// draws once. The matrices are written out by hand from the sample's
/// numbers (column-major).
#[test]
fn gpu_instances_become_scene_instances() {
    let dir = tempfile::tempdir().unwrap();
    let (meta, _) = build_glb(dir.path(), "copies", gltf_samples::instanced_triangle());
    let names: Vec<&str> = meta.instances.iter().map(|i| i.name.as_str()).collect();
    assert_eq!(names, ["copies_i0", "copies_i1", "copies_i2", "single"]);
    let [x, y, z] = gltf_samples::INSTANCED_NODE_AT;
    let want: [[f32; 16]; 3] = [
        [1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 0., x, y, z, 1.],
        [
            1.,
            0.,
            0.,
            0.,
            0.,
            1.,
            0.,
            0.,
            0.,
            0.,
            1.,
            0.,
            x + 2.,
            y,
            z,
            1.,
        ],
        // 90° about +Z, then × 2: x → 2y, y → −2x.
        [
            0.,
            2.,
            0.,
            0.,
            -2.,
            0.,
            0.,
            0.,
            0.,
            0.,
            2.,
            0.,
            x,
            y + 3.,
            z,
            1.,
        ],
    ];
    for (k, want) in want.iter().enumerate() {
        let got = meta.instances[k].transform.model;
        assert!(
            got.iter().zip(want).all(|(g, w)| (g - w).abs() < 1e-5),
            "instance {k}: {got:?}, want {want:?}"
        );
        assert_eq!(meta.instances[k].mesh, meta.instances[3].mesh, "one mesh");
    }
    assert_eq!(meta.instances[3].transform.model[12], -3.0);
}
