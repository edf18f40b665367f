//! Scene drawing: uniform packing by layout, draw order, object matrices
//! (CPU), then whole scenes built by the compiler and drawn from their
//! `.scene.json` alone on the machine's Vulkan adapter (lavapipe without a
//! GPU): specialised and library shaders agree, no pipeline is built while
//! drawing, and bad metadata is an error that names the file and instance.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use weft_render::weft_meta::scene::{SceneInstance, SceneMetadata, SceneTransform, TierChoice};
use weft_render::weft_meta::{
    Binding, BindingKind, BlendMode, ColorChannel, ColorOutput, ColorTarget, CullMode,
    DepthStencilState, DepthTest, FrontFace, HlslBinding, InstanceCount, Pass, PrimitiveState,
    PrimitiveTopology, RenderState, Stage, StencilFaceState, StencilOperation, TextureBinding,
    TextureDefault, TextureSampleType, TextureViewDimension, UniformLayout, UniformMember,
};
use weft_render::*;

use crate::support::ok;
use weft_tests::repo;

fn member(name: &str, ty: &str, offset: u32, size: u32) -> UniformMember {
    UniformMember {
        name: name.into(),
        ty: ty.parse().unwrap(),
        offset,
        size,
        align: 16,
        parameter: None,
        encoding: None,
        description: None,
    }
}

fn layout() -> UniformLayout {
    UniformLayout {
        struct_name: "Material".into(),
        size: 144,
        align: 16,
        members: vec![
            member("tint", "vec4<f32>", 0, 16),
            member("offset", "vec3<f32>", 16, 12),
            member("roughness", "f32", 28, 4),
            member("scale", "vec2<f32>", 32, 8),
            member("layers", "i32", 40, 4),
            member("two_tone", "u32", 44, 4),
            member("falloff", "array<vec4<f32>, 3>", 48, 48),
            member("ramp", "array<vec4<f32>, 2>", 96, 32),
            member("flag", "u32", 128, 4),
        ],
    }
}

fn f32s(bytes: &[u8], offset: usize, n: usize) -> Vec<f32> {
    (0..n)
        .map(|i| {
            f32::from_le_bytes(
                bytes[offset + 4 * i..offset + 4 * i + 4]
                    .try_into()
                    .unwrap(),
            )
        })
        .collect()
}

fn u32_at(bytes: &[u8], offset: usize) -> u32 {
    u32::from_le_bytes(bytes[offset..offset + 4].try_into().unwrap())
}

fn values(json: serde_json::Value) -> BTreeMap<String, serde_json::Value> {
    serde_json::from_value(json).unwrap()
}

#[test]
fn uniform_values_are_packed_by_the_members_wgsl_types() {
    let v = values(serde_json::json!({
        "tint": [0.25, 0.5, 0.75, 1.0],
        "offset": [1.0, -2.0, 3.5],
        "roughness": 0.375,
        "scale": [2.0, 4.0],
        "layers": -7,
        "two_tone": 1,
        "falloff": [0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8],
        "ramp": [[1.0, 2.0, 3.0, 4.0], [5.0, 6.0, 7.0, 8.0]],
        "flag": true,
        "not_in_the_layout": 12.0
    }));
    let bytes = ok(pack_uniform_values(&layout(), &v));
    assert_eq!(bytes.len(), 144);
    assert_eq!(f32s(&bytes, 0, 4), [0.25, 0.5, 0.75, 1.0]);
    assert_eq!(f32s(&bytes, 16, 3), [1.0, -2.0, 3.5]);
    assert_eq!(f32s(&bytes, 28, 1), [0.375]);
    assert_eq!(f32s(&bytes, 32, 2), [2.0, 4.0]);
    assert_eq!(u32_at(&bytes, 40) as i32, -7);
    assert_eq!(u32_at(&bytes, 44), 1);
    // Curve samples 4 per vec4; the tail of the last vec4 stays zero.
    let falloff = f32s(&bytes, 48, 12);
    let expected = [
        0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8f32, 0.0, 0.0, 0.0,
    ];
    assert_eq!(falloff, expected);
    assert_eq!(
        f32s(&bytes, 96, 8),
        [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]
    );
    assert_eq!(u32_at(&bytes, 128), 1);
    assert!(bytes[132..].iter().all(|&b| b == 0));
}

#[test]
fn bad_uniform_values_are_errors_naming_the_member() {
    let good = values(serde_json::json!({
        "tint": [0.25, 0.5, 0.75, 1.0], "offset": [1.0, 2.0, 3.0], "roughness": 0.5,
        "scale": [1.0, 1.0], "layers": 1, "two_tone": 0, "falloff": vec![0.5; 9],
        "ramp": [0.0, 1.0, 2.0, 3.0, 4.0], "flag": 0
    }));
    ok(pack_uniform_values(&layout(), &good));
    let cases: [(&str, serde_json::Value, &str); 7] = [
        ("tint", serde_json::json!([1.0, 2.0, 3.0]), "4 numbers"),
        ("roughness", serde_json::json!("rough"), "a number"),
        ("layers", serde_json::json!(1.5), "an i32"),
        ("two_tone", serde_json::json!(-1), "a u32"),
        ("falloff", serde_json::json!(vec![0.0; 13]), "at most 12"),
        (
            "ramp",
            serde_json::json!([[1.0, 2.0], [3.0, 4.0]]),
            "2 arrays of 4",
        ),
        ("flag", serde_json::json!([1]), "a u32"),
    ];
    for (name, bad, says) in cases {
        let mut v = good.clone();
        v.insert(name.into(), bad);
        let e = pack_uniform_values(&layout(), &v).unwrap_err().to_string();
        assert!(
            e.contains(&format!("`{name}`")) && e.contains(says),
            "{name}: {e}"
        );
    }
    let mut missing = good.clone();
    missing.remove("scale");
    let e = pack_uniform_values(&layout(), &missing)
        .unwrap_err()
        .to_string();
    assert!(e.contains("`scale`") && e.contains("no value"), "{e}");

    // Metadata that does not fit is an error, never a panic.
    let mut l = layout();
    l.members[0].offset = 140;
    let e = pack_uniform_values(&l, &good).unwrap_err().to_string();
    assert!(e.contains("`tint`") && e.contains("overruns"), "{e}");
    let mut l = layout();
    l.members[0].ty = "mat4x4<f32>".parse().unwrap();
    let e = pack_uniform_values(&l, &good).unwrap_err().to_string();
    assert!(e.contains("`tint`") && e.contains("16 numbers"), "{e}");
}

fn pass(name: &str, queue: i64, instances: InstanceCount) -> Pass {
    let no_stencil = StencilFaceState {
        compare: DepthTest::Always,
        fail_op: StencilOperation::Keep,
        depth_fail_op: StencilOperation::Keep,
        pass_op: StencilOperation::Keep,
    };
    Pass {
        name: name.into(),
        vertex_entry: "vs_main".into(),
        fragment_entry: "fs_main".into(),
        render_state: RenderState {
            blend: BlendMode::Opaque,
            cull: CullMode::Back,
            depth_write: true,
            depth_test: DepthTest::LessEqual,
            queue,
            stencil: None,
        },
        instances,
        when: Vec::new(),
        primitive: PrimitiveState {
            topology: PrimitiveTopology::TriangleList,
            front_face: FrontFace::Ccw,
            cull_mode: CullMode::Back,
        },
        color_targets: vec![ColorTarget {
            location: 0,
            format: "rgba16float".into(),
            output: ColorOutput::LinearRadiance,
            exposure_applied: false,
            tone_mapped: false,
            blend: None,
            write_mask: vec![
                ColorChannel::Red,
                ColorChannel::Green,
                ColorChannel::Blue,
                ColorChannel::Alpha,
            ],
        }],
        depth_stencil: DepthStencilState {
            format: weft_render::weft_meta::DEPTH_STENCIL_FORMAT.into(),
            depth_write_enabled: true,
            depth_compare: DepthTest::LessEqual,
            depth_clear_value: 1.0,
            stencil_front: no_stencil,
            stencil_back: no_stencil,
            stencil_read_mask: 0xff,
            stencil_write_mask: 0,
            stencil_reference: 0,
            stencil_clear_value: 0,
        },
    }
}

fn instance(name: &str, passes: Vec<Pass>) -> SceneInstance {
    SceneInstance {
        name: name.into(),
        material: "m".into(),
        preset: None,
        tier: "fast".into(),
        keywords: BTreeMap::new(),
        variant: "fast".into(),
        shader: "m.0".into(),
        constants: BTreeMap::new(),
        dynamic: Vec::new(),
        uniform_values: BTreeMap::new(),
        textures: BTreeMap::new(),
        passes,
        mesh: "sphere".into(),
        transform: SceneTransform {
            translation: [0.0; 3],
            rotation_degrees: [0.0; 3],
            scale: [1.0; 3],
            model: [
                1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
            ],
        },
        tier_choice: None,
    }
}

#[test]
fn draws_go_by_queue_then_instance_then_pass() {
    let one = || InstanceCount::Fixed(1);
    let instances = vec![
        instance(
            "a",
            vec![pass("back", 3000, one()), pass("front", 3000, one())],
        ),
        instance(
            "b",
            vec![pass("forward", 2000, one()), pass("fuzz", 2450, one())],
        ),
        instance("c", vec![pass("forward", 2000, one())]),
        instance(
            "d",
            vec![pass("late", 2450, one()), pass("early", 1000, one())],
        ),
    ];
    let order: Vec<(&str, &str)> = scene_draw_order(&instances)
        .iter()
        .map(|d| {
            let i = &instances[d.instance];
            (i.name.as_str(), i.passes[d.pass].name.as_str())
        })
        .collect();
    assert_eq!(
        order,
        [
            ("d", "early"),
            ("b", "forward"),
            ("c", "forward"),
            ("b", "fuzz"),
            ("d", "late"),
            ("a", "back"),
            ("a", "front"),
        ]
    );
}

#[test]
fn pass_instance_counts_come_from_constants_or_uniform_values() {
    let mut inst = instance("shells", Vec::new());
    let fixed = pass("forward", 2000, InstanceCount::Fixed(3));
    let shells = pass("fuzz", 2450, InstanceCount::Parameter("fuzz_layers".into()));
    assert_eq!(ok(scene_instance_count(&inst, &fixed)), 3);
    let e = scene_instance_count(&inst, &shells)
        .unwrap_err()
        .to_string();
    assert!(e.contains("fuzz_layers") && e.contains("`fuzz`"), "{e}");
    inst.constants
        .insert("fuzz_layers".into(), serde_json::json!(6));
    assert_eq!(ok(scene_instance_count(&inst, &shells)), 6);
    inst.constants.clear();
    inst.uniform_values
        .insert("fuzz_layers".into(), serde_json::json!(9));
    assert_eq!(ok(scene_instance_count(&inst, &shells)), 9);
}

#[test]
fn object_uniform_holds_the_model_and_its_inverse_transpose() {
    // Rotated about X and Z, scaled non-uniformly, translated.
    let (s, c) = 0.5f32.sin_cos();
    let mut inst = instance("o", Vec::new());
    inst.transform.model = [
        2.0 * c,
        2.0 * s,
        0.0,
        0.0, //
        -0.5 * s,
        0.5 * c,
        0.0,
        0.0, //
        0.0,
        0.0,
        3.0,
        0.0, //
        1.0,
        -2.0,
        4.0,
        1.0,
    ];
    let model = instance_model(&inst);
    assert_eq!(model[1], [-0.5 * s, 0.5 * c, 0.0, 0.0], "columns");
    assert_eq!(model[3], [1.0, -2.0, 4.0, 1.0]);
    let o = object_uniform(&model);
    assert_eq!(o.len(), 32);
    assert_eq!(&o[..16], &inst.transform.model);
    // N = (M3^-1)^T  <=>  N^T M3 = I for the upper 3x3.
    let n: Vec<[f32; 4]> = o[16..].chunks(4).map(|c| c.try_into().unwrap()).collect();
    for (i, ni) in n.iter().take(3).enumerate() {
        for (j, mj) in model.iter().take(3).enumerate() {
            let dot: f32 = (0..3).map(|k| ni[k] * mj[k]).sum();
            let want = if i == j { 1.0 } else { 0.0 };
            assert!((dot - want).abs() < 1e-5, "N^T M [{i}][{j}] = {dot}");
        }
    }
    assert_eq!(n[3], [0.0, 0.0, 0.0, 1.0]);
}

// ---- Scenes built by the compiler, drawn on the GPU ----

/// Picks the reference tier for `tier = "auto"` (the test does not measure).
struct ReferenceTier;

impl weft_compiler::scene::TierChooser for ReferenceTier {
    fn choose(
        &self,
        request: &weft_compiler::scene::AutoTierRequest,
    ) -> std::result::Result<weft_compiler::scene::AutoTierDecision, String> {
        let tier = request.material.0.tiers.reference.clone();
        Ok(weft_compiler::scene::AutoTierDecision {
            tier,
            record: TierChoice {
                error_budget: request.error_budget,
                screen_size: request.screen_size,
                cost_source: "test: reference tier".into(),
                gpu_family: None,
                candidates: Vec::new(),
            },
        })
    }
}

fn tmp() -> PathBuf {
    Path::new(env!("CARGO_TARGET_TMPDIR")).join("weft-render-scenes")
}

/// The library (`generated/`), built once per run from materials/.
fn generated() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let out = tmp().join("generated");
        let built = weft_compiler::build_library(
            &repo().join("materials"),
            &weft_compiler::BuildOptions::default(),
            &|_, _, _| {},
        )
        .unwrap_or_else(|_| panic!("materials do not build"));
        weft_compiler::output::write_atomically(&out, &built.files, &[]).expect("write");
        out
    })
}

/// Builds a scene manifest into `generated/scenes/<name>/` (where a project
/// build puts it) and returns the path of its `.scene.json`.
fn build_scene(manifest: &Path) -> PathBuf {
    let options = weft_compiler::SceneBuildOptions {
        tier_chooser: Some(&ReferenceTier),
        ..Default::default()
    };
    let out = weft_compiler::build_scene(manifest, &options)
        .unwrap_or_else(|(db, d)| panic!("{}", d.render_plain(&db)));
    let dir = generated().join("scenes");
    std::fs::create_dir_all(&dir).unwrap();
    weft_compiler::output::write_atomically(
        &dir.join(&out.name),
        &strip(&out.files, &out.name),
        &[],
    )
    .expect("write the scene");
    dir.join(&out.name).join(format!("{}.scene.json", out.name))
}

/// Files relative to `<scene>/` (the build's paths start with it).
fn strip(files: &BTreeMap<String, Vec<u8>>, name: &str) -> BTreeMap<String, Vec<u8>> {
    files
        .iter()
        .map(|(k, v)| {
            let rel = k.strip_prefix(&format!("{name}/")).unwrap_or(k);
            (rel.to_string(), v.clone())
        })
        .collect()
}

fn shipped(name: &str) -> &'static Path {
    static SCENES: OnceLock<std::sync::Mutex<BTreeMap<String, &'static Path>>> = OnceLock::new();
    let map = SCENES.get_or_init(Default::default);
    let mut map = map.lock().unwrap_or_else(|e| e.into_inner());
    map.entry(name.to_string()).or_insert_with(|| {
        let p = build_scene(&repo().join(format!("scenes/{name}.scene.toml")));
        Box::leak(p.into_boxed_path())
    })
}

fn renderer_for(scene_json: &Path) -> Renderer {
    let luts = ok(Luts::for_scene(scene_json));
    let env = EnvironmentMaps::sky(&SkyParams::default());
    ok(Renderer::new(ok(Gpu::new()), &env, &luts))
}

fn opts(w: u32, h: u32) -> RenderOptions {
    RenderOptions {
        width: w,
        height: h,
        ..RenderOptions::default()
    }
}

fn relative_rmse(a: &HdrImage, b: &HdrImage) -> f64 {
    let (mut num, mut den) = (0.0f64, 0.0f64);
    for (x, y) in a.pixels.iter().zip(&b.pixels) {
        for c in 0..3 {
            num += f64::from(x[c] - y[c]).powi(2);
            den += f64::from(y[c]).powi(2);
        }
    }
    (num / den.max(1e-30)).sqrt()
}

/// Pixel of a world point seen by the scene's camera.
fn project(camera: &Camera, p: [f32; 3], w: u32, h: u32) -> (u32, u32) {
    let clip = math::transform_point(&camera.view_proj(w as f32 / h as f32), p);
    let (x, y) = (clip[0] / clip[3], clip[1] / clip[3]);
    (
        ((x * 0.5 + 0.5) * w as f32) as u32,
        ((0.5 - y * 0.5) * h as f32) as u32,
    )
}

#[test]
fn shipped_scenes_draw_the_same_with_specialised_and_library_shaders() {
    for name in ["swatch_book", "fitting_room"] {
        let path = shipped(name);
        let scene = ok(SceneFile::load(path));
        let mut r = renderer_for(path);
        let (w, h) = (160, 120);
        let o = opts(w, h);
        let prepared = ok(r.prepare_scene(&scene, &SceneShaders::Specialised, &o));
        let created = r.pipelines_created();
        let specialised = ok(r.render_scene(&prepared, &o));
        let again = ok(r.render_scene(&prepared, &o));
        assert_eq!(
            r.pipelines_created(),
            created,
            "{name}: a draw built a pipeline"
        );
        assert_eq!(
            specialised.pixels, again.pixels,
            "{name}: draws are deterministic"
        );
        assert_eq!(specialised.non_finite_count(), 0, "{name}");

        let library = SceneShaders::Library(generated().to_path_buf());
        let generic = ok(r.prepare_scene(&scene, &library, &o));
        let generic = ok(r.render_scene(&generic, &o));
        let e = relative_rmse(&specialised, &generic);
        assert!(e < 1e-3, "{name}: specialised vs library relative RMSE {e}");

        let mut spirv = o;
        spirv.language = ShaderLanguage::SpirV;
        let p = ok(r.prepare_scene(&scene, &SceneShaders::Specialised, &spirv));
        let s = ok(r.render_scene(&p, &spirv));
        let e = relative_rmse(&specialised, &s);
        assert!(e < 1e-3, "{name}: WGSL vs SPIR-V relative RMSE {e}");

        // Every instance covers the pixel its origin projects to.
        let mut black = o;
        black.background = Background::Color([0.0; 4]);
        let img = ok(r.render_scene(&prepared, &black));
        for inst in &scene.metadata.instances {
            let t = inst.transform.translation.map(|x| x as f32);
            let (x, y) = project(prepared.camera(), t, w, h);
            assert!(
                img.pixel(x, y)[3] > 0.0,
                "{name}: instance `{}` not drawn at ({x}, {y})",
                inst.name
            );
        }
    }
}

#[test]
fn draws_follow_the_scene_order_and_instance_counts() {
    let path = shipped("fitting_room");
    let scene = ok(SceneFile::load(path));
    let mut r = renderer_for(path);
    let prepared = ok(r.prepare_scene(&scene, &SceneShaders::Specialised, &opts(32, 32)));
    let meta = &scene.metadata;
    let expected: Vec<(String, String, u32)> = scene_draw_order(&meta.instances)
        .iter()
        .map(|d| {
            let i = &meta.instances[d.instance];
            let p = &i.passes[d.pass];
            (
                i.name.clone(),
                p.name.clone(),
                ok(scene_instance_count(i, p)),
            )
        })
        .collect();
    let got: Vec<(String, String, u32)> = prepared
        .draws()
        .into_iter()
        .map(|(i, p, n)| (i.to_string(), p.to_string(), n))
        .collect();
    assert_eq!(got, expected);
    // The transparent veil (queue 3000) is drawn last.
    assert_eq!(got.last().map(|d| d.0.as_str()), Some("veil"));
    // Preparing the same scene again reuses every pipeline.
    let created = r.pipelines_created();
    ok(r.prepare_scene(&scene, &SceneShaders::Specialised, &opts(32, 32)));
    assert_eq!(r.pipelines_created(), created);

    // What was uploaded is the instance's uniform_values at the layout's offsets.
    let mut checked = 0;
    for (i, inst) in meta.instances.iter().enumerate() {
        let shader = meta.shaders.iter().find(|s| s.id == inst.shader).unwrap();
        let Some(layout) = &shader.shader.material_uniform else {
            assert!(prepared.uniform_buffer(i).is_none());
            continue;
        };
        let buffer = prepared.uniform_buffer(i).expect("uniform buffer");
        let uploaded = ok(r.gpu().read_buffer(buffer));
        assert_eq!(
            uploaded,
            ok(pack_uniform_values(layout, &inst.uniform_values))
        );
        checked += 1;
    }
    assert!(checked > 0);

    // The bench times whole scenes like materials.
    let timing = TimingOptions {
        warmup: 1,
        frames: 2,
        force_cpu_timer: true,
    };
    let times = ok(r.time_scene_frames(&prepared, &opts(32, 32), &timing));
    assert_eq!(times.ms.len(), 2);
    assert_eq!(r.pipelines_created(), created);
}

fn write_manifest(name: &str, features: &str, instance: &str) -> PathBuf {
    let dir = tmp().join("manifests");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(format!("{name}.scene.toml"));
    let text = format!(
        "[scene]\nname = \"{name}\"\nmaterials = \"{}\"\n{features}\n\
         vertex_inputs = [\"position\", \"normal\", \"tangent\", \"uv0\"]\n\n\
         [camera]\nposition = [0.0, 0.0, 4.0]\ntarget = [0.0, 0.0, 0.0]\nfov_degrees = 35.0\n\n\
         [[instances]]\n{instance}\n",
        repo().join("materials").display()
    );
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn engine_features_that_are_off_are_black_for_both_shaders() {
    let sphere = "name = \"ball\"\nmaterial = \"standard\"\nmesh = \"sphere\"\n\
                  params = { roughness = 0.4 }";
    let cases = [
        (
            "lit",
            "environment = true\nsh_ambient = true\ndirectional_lights = 1",
        ),
        (
            "sh_only",
            "environment = false\nsh_ambient = true\ndirectional_lights = 0",
        ),
        (
            "sun_only",
            "environment = false\nsh_ambient = false\ndirectional_lights = 1",
        ),
        (
            "dark",
            "environment = false\nsh_ambient = false\ndirectional_lights = 0",
        ),
    ];
    let (w, h) = (64, 64);
    let o = RenderOptions {
        background: Background::Color([0.0; 4]),
        ..opts(w, h)
    };
    let mut centre = BTreeMap::new();
    for (name, features) in cases {
        let path = build_scene(&write_manifest(name, features, sphere));
        let scene = ok(SceneFile::load(&path));
        let mut r = renderer_for(&path);
        let p = ok(r.prepare_scene(&scene, &SceneShaders::Specialised, &o));
        let specialised = ok(r.render_scene(&p, &o));
        let library = SceneShaders::Library(generated().to_path_buf());
        let p = ok(r.prepare_scene(&scene, &library, &o));
        let generic = ok(r.render_scene(&p, &o));
        let e = relative_rmse(&specialised, &generic);
        assert!(e < 1e-3, "{name}: specialised vs library relative RMSE {e}");
        let px = specialised.pixel(w / 2, h / 2);
        centre.insert(name, px[0] + px[1] + px[2]);
    }
    assert!(centre["dark"] < 1e-4, "{centre:?}");
    for lit in ["sh_only", "sun_only", "lit"] {
        assert!(centre[lit] > 0.01, "{lit}: {centre:?}");
    }
    assert!(centre["lit"] > centre["sh_only"] && centre["lit"] > centre["sun_only"]);
}

fn scene_error(scene: &SceneFile) -> String {
    let mut r = renderer_for(&scene.path);
    match r.prepare_scene(scene, &SceneShaders::Specialised, &opts(32, 32)) {
        Ok(_) => panic!("the broken scene prepared"),
        Err(e) => {
            assert!(matches!(e, Error::Scene { .. }), "{e:?}");
            e.to_string()
        }
    }
}

fn edited(path: &Path, edit: impl FnOnce(&mut SceneMetadata)) -> SceneFile {
    let mut scene = ok(SceneFile::load(path));
    edit(&mut scene.metadata);
    scene
}

#[test]
fn bad_scene_metadata_is_an_error_naming_the_file_and_instance() {
    let path = shipped("swatch_book");
    let json = path.display().to_string();
    let first = ok(SceneFile::load(path)).metadata.instances[0].name.clone();

    // A shader file that is missing.
    let copy = generated().join("scenes/broken_swatch_book");
    let _ = std::fs::remove_dir_all(&copy);
    std::fs::create_dir_all(&copy).unwrap();
    for entry in std::fs::read_dir(path.parent().unwrap()).unwrap() {
        let p = entry.unwrap().path();
        std::fs::copy(&p, copy.join(p.file_name().unwrap())).unwrap();
    }
    let copy_json = copy.join("swatch_book.scene.json");
    let scene = ok(SceneFile::load(&copy_json));
    let wgsl = &scene.metadata.shaders[0].shader.files["wgsl"][0].path;
    std::fs::remove_file(copy.join(wgsl)).unwrap();
    let e = scene_error(&scene);
    assert!(
        e.contains(&copy_json.display().to_string())
            && e.contains(&format!("instance `{first}`"))
            && e.contains(wgsl.as_str()),
        "{e}"
    );

    // A binding the engine interface has no resource for.
    let e = scene_error(&edited(path, |m| {
        m.shaders[0].shader.bindings.push(Binding {
            group: 3,
            binding: 0,
            name: "mystery".into(),
            kind: BindingKind::UniformBuffer,
            parameter: None,
            stages: vec![Stage::Fragment],
            hlsl: HlslBinding {
                register: "b0".into(),
                space: 3,
                sampler_index_slot: None,
            },
            msl: None,
            buffer: None,
            texture: None,
            sampler: None,
            resource: None,
        });
    }));
    assert!(
        e.contains(&json) && e.contains(&format!("instance `{first}`")) && e.contains("mystery"),
        "{e}"
    );

    // A material texture the instance gives nothing for.
    let e = scene_error(&edited(path, |m| {
        m.shaders[0].shader.bindings.push(Binding {
            group: 1,
            binding: 9,
            name: "detail_map".into(),
            kind: BindingKind::Texture2d,
            parameter: Some("detail_map".into()),
            stages: vec![Stage::Fragment],
            hlsl: HlslBinding {
                register: "t9".into(),
                space: 1,
                sampler_index_slot: None,
            },
            msl: None,
            buffer: None,
            texture: Some(TextureBinding {
                sample_type: TextureSampleType::Float,
                view_dimension: TextureViewDimension::D2,
                multisampled: false,
                format: "rgba8unorm".into(),
                default: Some(TextureDefault::White),
                file: None,
            }),
            sampler: None,
            resource: None,
        });
    }));
    assert!(e.contains("detail_map") && e.contains("textures"), "{e}");

    // An unknown shader id, an unknown mesh, a missing uniform value.
    let e = scene_error(&edited(path, |m| m.instances[1].shader = "nope.000".into()));
    let second = ok(SceneFile::load(path)).metadata.instances[1].name.clone();
    assert!(
        e.contains(&format!("instance `{second}`")) && e.contains("nope.000"),
        "{e}"
    );
    let e = scene_error(&edited(path, |m| m.instances[0].mesh = "teapot".into()));
    assert!(
        e.contains("teapot") && e.contains("sphere, cloth, swatch"),
        "{e}"
    );
    let room = shipped("fitting_room");
    let e = scene_error(&edited(room, |m| {
        let (inst, member) = m
            .instances
            .iter_mut()
            .find_map(|inst| {
                let shader = m.shaders.iter().find(|s| s.id == inst.shader)?;
                let name = shader
                    .shader
                    .material_uniform
                    .as_ref()?
                    .members
                    .first()?
                    .name
                    .clone();
                Some((inst, name))
            })
            .expect("an instance with a material uniform");
        inst.uniform_values.remove(&member);
    }));
    assert!(e.contains("uniform_values"), "{e}");

    // Metadata of another version.
    let mut meta = ok(SceneFile::load(path)).metadata;
    meta.schema_version += 1;
    let e = SceneFile::from_metadata(meta, path)
        .unwrap_err()
        .to_string();
    assert!(
        e.contains(&json) && e.contains("scene schema version"),
        "{e}"
    );
    // Not scene metadata at all.
    let not_json = tmp().join("not.scene.json");
    std::fs::write(&not_json, "{}").unwrap();
    let e = SceneFile::load(&not_json).unwrap_err().to_string();
    assert!(e.contains("not weft scene metadata"), "{e}");
}
