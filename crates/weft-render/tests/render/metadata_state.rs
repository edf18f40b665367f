//! weft-render takes pipeline state, layouts, samplers, texture defaults,
//! LUT descriptions, engine uniform layouts and pipeline constants from the
//! metadata (schema 2), not from its own tables: editing a field changes
//! the draw, and a field weft-render cannot honour is an error naming it.
//! Runs on the machine's Vulkan adapter (lavapipe without a GPU).

use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use weft_render::weft_meta::{
    BlendComponent, BlendFactor, BlendOperation, BlendState, CullMode, MaterialMetadata,
    UniformMember,
};
use weft_render::*;

use crate::support::ok;

/// The materials roots this suite draws, built once per run.
fn built() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    crate::support::built(
        &DIR,
        "weft-render-metadata-state",
        &[
            ("materials", "materials"),
            ("tests/fixtures/materials", "fixtures"),
        ],
    )
}

fn meta_path(root: &str, material: &str) -> PathBuf {
    crate::support::meta_path(built(), root, material)
}

fn env() -> &'static EnvironmentMaps {
    static ENV: OnceLock<EnvironmentMaps> = OnceLock::new();
    ENV.get_or_init(|| EnvironmentMaps::sky(&SkyParams::default()))
}

fn renderer(path: &Path) -> Renderer {
    ok(Renderer::new(
        ok(Gpu::new()),
        env(),
        &ok(Luts::for_metadata(path)),
    ))
}

fn options() -> RenderOptions {
    RenderOptions {
        width: 48,
        height: 48,
        format: ColorFormat::Rgba32Float,
        background: Background::Color([0.25, 0.25, 0.25, 1.0]),
        ..RenderOptions::default()
    }
}

/// `standard` with its metadata edited by `edit` (files next to the original).
fn edited_standard(edit: impl FnOnce(&mut MaterialMetadata)) -> Material {
    let path = meta_path("materials", "standard");
    let mut meta: MaterialMetadata =
        serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
    edit(&mut meta);
    ok(Material::from_metadata(meta, path.parent().unwrap()))
}

/// Every variant's shader (edits apply to whichever one is drawn).
fn shaders(meta: &mut MaterialMetadata) -> impl Iterator<Item = &mut weft_meta::VariantShader> {
    meta.variants.iter_mut().filter_map(|v| v.shader.as_mut())
}

fn render(m: &Material) -> Result<HdrImage> {
    renderer(&meta_path("materials", "standard")).render(m, &Scene::sphere(), &options())
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

fn err(r: Result<HdrImage>) -> String {
    match r {
        Ok(_) => panic!("expected an error"),
        Err(e) => e.to_string(),
    }
}

#[test]
fn an_unset_texture_binds_the_default_its_variant_names() {
    let path = meta_path("materials", "standard");
    let mut r = renderer(&path);
    let mut m = ok(Material::load(&path));
    ok(m.set("sphere_strength", 1.0));
    let plain = ok(r.render(&m, &Scene::sphere(), &options()));
    // Unset, the sphere map is neutral in both modes: black for ADD, white
    // for MULTIPLY (the parameter's declared default is black).
    for mode in ["add", "multiply"] {
        ok(m.set_keyword("SPHERE_MAP", mode));
        let img = ok(r.render(&m, &Scene::sphere(), &options()));
        let e = relative_rmse(&plain, &img);
        assert!(e < 1e-5, "SPHERE_MAP={mode} unset: relative RMSE {e}");
    }
    // Set explicitly, the value is bound whatever the variant's default.
    ok(m.set_from_str("sphere_map", "black"));
    assert!(m.texture_is_set("sphere_map"));
    let black = ok(r.render(&m, &Scene::sphere(), &options()));
    assert!(relative_rmse(&plain, &black) > 0.5, "black did not darken");
    ok(m.reset());
    assert!(!m.texture_is_set("sphere_map"));
}

#[test]
fn blend_and_cull_come_from_the_pass_metadata() {
    let plain = ok(render(&edited_standard(|_| {})));
    // Additive colour blend over the 0.25 background: every covered pixel
    // gains exactly the background.
    let one = BlendComponent {
        src_factor: BlendFactor::One,
        dst_factor: BlendFactor::One,
        operation: BlendOperation::Add,
    };
    let added = ok(render(&edited_standard(|m| {
        m.passes[0].color_targets[0].blend = Some(BlendState {
            color: one,
            alpha: one,
        });
    })));
    let centre = 24 * 48 + 24;
    for c in 0..3 {
        let d = added.pixels[centre][c] - plain.pixels[centre][c];
        assert!(
            (d - 0.25).abs() < 1e-4,
            "channel {c}: blended {d} over 0.25"
        );
    }
    // Culling the front faces shows the inside of the sphere instead.
    let front = ok(render(&edited_standard(|m| {
        m.passes[0].primitive.cull_mode = CullMode::Front;
    })));
    assert!(relative_rmse(&plain, &front) > 0.05, "cull_mode ignored");
    // A write mask without colour channels leaves the background.
    let masked = ok(render(&edited_standard(|m| {
        m.passes[0].color_targets[0].write_mask.clear();
    })));
    assert_eq!(masked.pixels[centre], [0.25, 0.25, 0.25, 1.0]);
}

#[test]
fn samplers_are_made_from_their_binding_description() {
    let plain = ok(render(&edited_standard(|_| {})));
    // The environment sampler clamped to mip 0: a rough sphere reflects the sharp sky.
    let sharp = ok(render(&edited_standard(|m| {
        for s in shaders(m) {
            for b in &mut s.bindings {
                if b.name == "weft_environment_sampler" {
                    b.sampler.as_mut().unwrap().lod_max_clamp = 0.0;
                }
            }
        }
    })));
    assert!(relative_rmse(&plain, &sharp) > 1e-3, "lod clamp ignored");
}

#[test]
fn pipeline_state_weft_render_cannot_honour_is_an_error() {
    let e = err(render(&edited_standard(|m| {
        m.passes[0].depth_stencil.format = "depth32float".into();
    })));
    assert!(
        e.contains("depth32float") && e.contains("depth24plus_stencil8"),
        "{e}"
    );
    let e = err(render(&edited_standard(|m| {
        m.passes[0].color_targets[0].format = "rgba8unorm".into();
    })));
    assert!(e.contains("rgba8unorm") && e.contains("float"), "{e}");
    // A pass without depth still draws (always passes, never writes).
    let no_depth = ok(render(&edited_standard(|m| {
        let d = &mut m.passes[0].depth_stencil;
        d.depth_write_enabled = false;
        d.depth_compare = weft_render::weft_meta::DepthTest::Always;
    })));
    assert!(
        no_depth
            .pixels
            .iter()
            .all(|p| p.iter().all(|c| c.is_finite()))
    );
}

#[test]
fn engine_uniforms_are_written_by_member_name() {
    let plain = ok(render(&edited_standard(|_| {})));
    // The light's direction and colour written at each other's offsets:
    // the shader still reads them where it was compiled to, so the
    // picture changes only because the bytes follow the layout.
    let swapped = ok(render(&edited_standard(|m| {
        for s in shaders(m) {
            for b in &mut s.bindings {
                if b.name != "weft_frame" {
                    continue;
                }
                let members = &mut b.buffer.as_mut().unwrap().layout.members;
                let at = |name: &str| members.iter().position(|x| x.name == name).unwrap();
                let (d, c) = (at("light_direction"), at("light_color"));
                let (od, oc) = (members[d].offset, members[c].offset);
                members[d].offset = oc;
                members[c].offset = od;
            }
        }
    })));
    assert!(relative_rmse(&plain, &swapped) > 1e-2, "offsets ignored");
    let e = err(render(&edited_standard(|m| {
        for s in shaders(m) {
            for b in &mut s.bindings {
                if b.name == "weft_frame" {
                    let buf = b.buffer.as_mut().unwrap();
                    let size = buf.layout.size;
                    buf.layout.members.push(UniformMember {
                        name: "wind".into(),
                        ty: weft_render::weft_meta::UniformType::vec_f32(4),
                        offset: size,
                        size: 16,
                        align: 16,
                        parameter: None,
                        encoding: None,
                        description: None,
                    });
                    buf.layout.size += 16;
                    buf.min_binding_size += 16;
                }
            }
        }
    })));
    assert!(e.contains("wind") && e.contains("weft_frame"), "{e}");
}

/// `standard` edited, at its reference tier (which binds the split-sum LUT).
fn edited_reference(edit: impl FnOnce(&mut MaterialMetadata)) -> Material {
    let mut m = edited_standard(edit);
    ok(m.set_tier("reference"));
    m
}

/// Edits every LUT file description of every variant.
fn edit_lut_files(m: &mut MaterialMetadata, edit: impl Fn(&mut weft_meta::ResourceFile)) {
    for s in shaders(m) {
        for b in &mut s.bindings {
            if let Some(f) = b.resource.as_mut().and_then(|r| r.file.as_mut()) {
                edit(f);
            }
        }
    }
}

#[test]
fn lut_files_are_checked_against_their_description() {
    ok(render(&edited_reference(|_| {})));
    let e = err(render(&edited_reference(|m| {
        edit_lut_files(m, |f| f.width = 32)
    })));
    assert!(
        e.contains("split_sum_ggx") && e.contains("32x64") && e.contains("bytes"),
        "{e}"
    );
    let e = err(render(&edited_reference(|m| {
        edit_lut_files(m, |f| f.path = "luts/elsewhere.rg16f".into())
    })));
    assert!(e.contains("elsewhere.rg16f"), "{e}");
}

#[test]
fn pipeline_constants_follow_their_values_list() {
    let path = meta_path("fixtures", "switches");
    let mut meta: MaterialMetadata =
        serde_json::from_slice(&std::fs::read(&path).unwrap()).unwrap();
    let style = |m: &Material| {
        let shader = ok(m.current_variant()).shader;
        ok(m.pipeline_constants(shader))
            .into_iter()
            .find(|(n, _)| n == "STYLE")
            .expect("STYLE is a pipeline constant")
            .1
    };
    let m = ok(Material::from_metadata(
        meta.clone(),
        path.parent().unwrap(),
    ));
    assert_eq!(style(&m), 0.0); // flat
    // The same keyword value at another index of `values`.
    for s in shaders(&mut meta) {
        for c in &mut s.pipeline_constants {
            c.values.reverse();
        }
    }
    let m = ok(Material::from_metadata(meta, path.parent().unwrap()));
    assert_eq!(style(&m), 1.0);
}
