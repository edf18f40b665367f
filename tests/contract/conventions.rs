//! The per-language conventions of docs/engine-interface.md, checked with
//! the independent engine of `support/engine/` (metadata only):
//!
//! - SPIR-V: every canonical variant's SPIR-V file (the one whose baked
//!   constants are the keyword defaults), handed to the Vulkan driver
//!   untouched through wgpu's passthrough path, draws the WGSL picture when
//!   drawn as `languages.spirv` says for a layer with a negative viewport
//!   height (front face clockwise, rows read bottom to top); reversing the
//!   rows alone does not.
//! - GLSL: every GLSL file compiled by glslang (OpenGL semantics) has
//!   exactly the uniform-block binding points and texture units its
//!   `glsl` table states, the table names real bindings of the variant, and
//!   the stages of one variant agree.
//!
//! Needs a Vulkan adapter (lavapipe: `mesa-vulkan-drivers`) and
//! `glslangValidator` (`glslang-tools`); without them the tests fail with
//! what to install, never skip.

use crate::{engine, harness};

use engine::library::{canonical_variants, variant_passes};
use engine::{Engine, Image, Language, Library, World};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use weft_meta::scene::SceneMetadata;
use weft_meta::{
    BindingKind, BindingRef, CullMode, GlslReflection, MaterialMetadata, Stage, VariantShader,
};

// ------------------------------------------------------------------ SPIR-V

/// FLIP mean (128×128, Reinhard then sRGB8) allowed between a variant's
/// SPIR-V picture and its WGSL picture. Measured on lavapipe (Mesa 22.3
/// llvmpipe): at most 0.000013 over the 48 variants (largest linear
/// difference 2e-3, last-bit f16 differences between the two compiles);
/// reversing the rows alone measures 0.22 to 0.37 for the back-face-culled
/// materials, so 1e-3 separates the two by two orders of magnitude.
const SPIRV_FLIP_MAX: f32 = 1e-3;

struct Spirv {
    engine: Engine,
    world: World,
    mesh: engine::Mesh,
}

fn spirv_setup() -> Spirv {
    let sky = harness::sky();
    let scene = harness::material_scene();
    Spirv {
        engine: Engine::new(true),
        world: World::new(
            harness::environment(&sky),
            harness::frame(&scene.camera, &scene.light),
        ),
        mesh: harness::mesh(&scene.mesh),
    }
}

impl Spirv {
    /// A variant of the material at `meta_path`, whose library root (for
    /// LUT files) is the folder above the material's.
    fn draw(
        &mut self,
        meta_path: &Path,
        meta: &MaterialMetadata,
        variant: &str,
        language: Language,
    ) -> Result<Image, String> {
        let root = meta_path.parent().and_then(Path::parent).unwrap();
        self.engine.draw_variant(
            &mut self.world,
            root,
            meta_path,
            meta,
            variant,
            language,
            &self.mesh,
            (harness::SIZE, harness::SIZE),
            harness::CLEAR,
        )
    }
}

const SPIRV_AS_STATED: Language = Language::SpirvPassthrough {
    undo_layer_flip: true,
};
const ROWS_FLIPPED_ONLY: Language = Language::SpirvPassthrough {
    undo_layer_flip: false,
};

/// Every canonical variant's SPIR-V, drawn through Vulkan with the stated
/// conventions, matches its WGSL picture.
#[test]
fn spirv_through_vulkan_matches_wgsl() {
    let started = std::time::Instant::now();
    let mut s = spirv_setup();
    // The shipped materials, then the fixtures (a `constant`-mode keyword:
    // one SPIR-V file per value, the default's drawn).
    let (_tmp, fixtures) = harness::fixture_library();
    let libraries = [
        Library::load(&harness::generated()).unwrap(),
        Library::load(&fixtures).unwrap(),
    ];
    let (mut count, mut max_flip) = (0, 0.0f32);
    let mut failures = Vec::new();
    for (meta_path, meta) in libraries.iter().flat_map(|l| &l.materials) {
        for (v, _) in canonical_variants(meta).unwrap() {
            let label = format!("{}/{}", meta.name, v.id);
            let pictures = s
                .draw(meta_path, meta, &v.id, Language::Wgsl)
                .and_then(|w| {
                    s.draw(meta_path, meta, &v.id, SPIRV_AS_STATED)
                        .map(|spv| (w, spv))
                });
            let (wgsl, spirv) = match pictures {
                Ok(p) => p,
                Err(e) => {
                    failures.push(format!("{label}: {e}"));
                    continue;
                }
            };
            let f = harness::flip(&wgsl, &spirv).mean;
            let st = harness::stats(&spirv);
            println!(
                "{label:58} SPIR-V vs WGSL: FLIP {f:.6}, max |diff| {:.2e}, coverage {:.3}",
                harness::max_abs_difference(&wgsl, &spirv),
                st.coverage
            );
            max_flip = max_flip.max(f);
            if f.is_nan() || f > SPIRV_FLIP_MAX || st.non_finite > 0 || st.coverage < 0.4 {
                failures.push(format!(
                    "{label}: SPIR-V picture differs from WGSL (FLIP {f:.5} > {SPIRV_FLIP_MAX}, \
                     {} NaN/Inf, coverage {:.3})",
                    st.non_finite, st.coverage
                ));
            }
            count += 1;
        }
    }
    println!(
        "{count} variants: SPIR-V vs WGSL FLIP mean max {max_flip:.6}; {:.1} s",
        started.elapsed().as_secs_f64()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    let shipped: usize = libraries[0]
        .materials
        .iter()
        .map(|(_, m)| canonical_variants(m).unwrap().len())
        .sum();
    assert!(
        shipped >= 48,
        "expected the shipped variants, found {shipped}"
    );
    assert!(
        count > shipped,
        "expected every shipped and fixture variant, drew {count}"
    );
}

/// The winding statement: with the metadata's WGSL front face (ccw) and the
/// rows merely reversed, a back-face-culled material shows its back faces
/// (the inside of the sphere) instead of the front — the picture differs.
#[test]
fn reversing_the_rows_alone_does_not_match() {
    let mut s = spirv_setup();
    let materials = Library::load(&harness::generated()).unwrap().materials;
    let mut culled = 0;
    let mut failures = Vec::new();
    for (meta_path, meta) in &materials {
        let (first, _) = canonical_variants(meta).unwrap()[0];
        if !variant_passes(meta, first)
            .iter()
            .all(|p| p.primitive.cull_mode == CullMode::Back)
        {
            continue;
        }
        let variant = first.id.clone();
        let wgsl = s.draw(meta_path, meta, &variant, Language::Wgsl).unwrap();
        let flipped = s
            .draw(meta_path, meta, &variant, ROWS_FLIPPED_ONLY)
            .unwrap();
        let f = harness::flip(&wgsl, &flipped).mean;
        println!("{}/{variant}: rows reversed alone: FLIP {f:.5}", meta.name);
        if f <= SPIRV_FLIP_MAX {
            failures.push(format!(
                "{}/{variant}: the rows reversed alone match the WGSL picture (FLIP {f:.5})",
                meta.name
            ));
        }
        culled += 1;
    }
    assert!(culled >= 1, "no back-face-culled material to check");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

// -------------------------------------------------------------------- GLSL

fn glslang() -> PathBuf {
    std::env::var_os("PATH")
        .and_then(|paths| {
            std::env::split_paths(&paths)
                .map(|p| p.join("glslangValidator"))
                .find(|p| p.is_file())
        })
        .unwrap_or_else(|| {
            panic!(
                "`glslangValidator` not found: install it with \
                 `apt-get install -y glslang-tools` (see .ci/run)"
            )
        })
}

/// What glslang's reflection (`-q`) says one compiled GLSL file binds:
/// uniform blocks and opaque (sampler) uniforms by name, with the binding
/// written in the file (-1: none).
#[derive(Clone, Debug, Default)]
struct Compiled {
    blocks: BTreeMap<String, i64>,
    samplers: BTreeMap<String, i64>,
    /// The file's text.
    source: String,
}

/// Whether `source` uses the sampler uniform `name` only where no sampler
/// state applies: its declaration, `texelFetch` and `textureSize` (from
/// WGSL's textureLoad and textureDimensions).
fn fetched_only(source: &str, name: &str) -> bool {
    let is_ident = |c: char| c.is_ascii_alphanumeric() || c == '_';
    source.match_indices(name).all(|(at, _)| {
        let after = source[at + name.len()..].chars().next();
        let before = source[..at].chars().next_back();
        if after.is_some_and(is_ident) || before.is_some_and(is_ident) {
            return true; // part of another identifier
        }
        let head = source[..at].trim_end();
        head.ends_with("texelFetch(")
            || head.ends_with("textureSize(")
            || head.ends_with("sampler2D")
            || head.ends_with("samplerCube")
    })
}

/// Compiles `path` as a `stage` shader with OpenGL semantics (`-G`, as a GL
/// driver would) and reads its reflection.
fn compile(glslang: &Path, path: &Path, stage: Stage, out_dir: &Path) -> Result<Compiled, String> {
    let out = Command::new(glslang)
        .args(["-G", "-q", "-S", glslang_stage(stage)])
        .arg(path)
        .arg("-o")
        .arg(out_dir.join("out.spv"))
        .output()
        .map_err(|e| format!("glslangValidator: {e}"))?;
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    if !out.status.success() {
        return Err(format!("glslang rejects {}:\n{text}", path.display()));
    }
    let mut compiled = Compiled {
        source: std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?,
        ..Compiled::default()
    };
    let mut section = "";
    for line in text.lines() {
        if line.ends_with("reflection:") {
            section = line;
            continue;
        }
        let Some((name, fields)) = line.split_once(": ") else {
            continue;
        };
        let binding = fields
            .split(", ")
            .find_map(|f| f.strip_prefix("binding "))
            .and_then(|b| b.trim().parse::<i64>().ok())
            .ok_or_else(|| format!("{}: no binding in `{line}`", path.display()))?;
        match section {
            "Uniform block reflection:" => {
                compiled.blocks.insert(name.to_string(), binding);
            }
            // Block members are `instance.member`; the rest of the
            // default uniform block are opaque uniforms (samplers).
            "Uniform reflection:" if !name.contains('.') => {
                compiled.samplers.insert(name.to_string(), binding);
            }
            "Buffer block reflection:" => {
                return Err(format!(
                    "{}: unexpected buffer block `{name}`",
                    path.display()
                ));
            }
            _ => {}
        }
    }
    Ok(compiled)
}

/// Checks one file's compiled bindings against its table, and the table's
/// references against the variant's bindings. The failures.
fn check_file(
    label: &str,
    table: &GlslReflection,
    compiled: &Compiled,
    shader: &VariantShader,
    stage: Stage,
) -> Vec<String> {
    let mut failures = Vec::new();
    // Every compiled block and sampler has exactly the table's binding…
    for (name, &binding) in &compiled.blocks {
        match table.uniform_blocks.iter().find(|b| &b.block == name) {
            Some(b) if i64::from(b.binding) == binding => {}
            Some(b) => failures.push(format!(
                "{label}: block `{name}` is bound to {binding}, the table says {}",
                b.binding
            )),
            None => failures.push(format!("{label}: block `{name}` has no table entry")),
        }
    }
    for (name, &unit) in &compiled.samplers {
        match table.samplers.iter().find(|s| &s.name == name) {
            Some(s) if i64::from(s.unit) == unit => {}
            Some(s) => failures.push(format!(
                "{label}: sampler `{name}` is on unit {unit}, the table says {}",
                s.unit
            )),
            None => failures.push(format!("{label}: sampler `{name}` has no table entry")),
        }
    }
    // … and every table entry is in the file.
    for b in &table.uniform_blocks {
        if !compiled.blocks.contains_key(&b.block) {
            failures.push(format!(
                "{label}: table block `{}` is not in the file",
                b.block
            ));
        }
    }
    for s in &table.samplers {
        if !compiled.samplers.contains_key(&s.name) {
            failures.push(format!(
                "{label}: table sampler `{}` is not in the file",
                s.name
            ));
        }
    }
    // The table's references name bindings of the variant, of the right
    // kind, visible to this stage.
    let refers = |what: &str, r: &BindingRef, ok: &dyn Fn(BindingKind) -> bool| -> Option<String> {
        match shader
            .bindings
            .iter()
            .find(|b| b.group == r.group && b.binding == r.binding)
        {
            Some(b) if ok(b.kind) && b.stages.contains(&stage) => None,
            Some(b) => Some(format!(
                "{label}: {what} names group {} binding {} (`{}`, {:?}, stages {:?})",
                r.group, r.binding, b.name, b.kind, b.stages
            )),
            None => Some(format!(
                "{label}: {what} names group {} binding {}, which the variant does not have",
                r.group, r.binding
            )),
        }
    };
    for b in &table.uniform_blocks {
        failures.extend(refers(&format!("block `{}`", b.block), &b.source, &|k| {
            matches!(k, BindingKind::UniformBuffer)
        }));
    }
    for s in &table.samplers {
        failures.extend(refers(
            &format!("sampler `{}` texture", s.name),
            &s.texture,
            &|k| {
                matches!(
                    k,
                    BindingKind::Texture2d
                        | BindingKind::TextureCube
                        | BindingKind::Texture2dArray
                        | BindingKind::Texture3d
                        | BindingKind::DepthTexture2d
                )
            },
        ));
        match &s.sampler {
            Some(r) => failures.extend(refers(&format!("sampler `{}` sampler", s.name), r, &|k| {
                matches!(k, BindingKind::Sampler | BindingKind::ComparisonSampler)
            })),
            // A texture read only by texel fetches needs no sampler state.
            None if fetched_only(&compiled.source, &s.name) => {}
            None => failures.push(format!(
                "{label}: sampler `{}` names no sampler but is sampled",
                s.name
            )),
        }
    }
    failures
}

type Key = (u32, u32);
fn key(r: &BindingRef) -> Key {
    (r.group, r.binding)
}

/// The stages of one variant agree (a WGSL binding has one binding point
/// or unit in every file, and no two share one), and the numbers are the
/// stated ones: blocks 0, 1, … in (group, binding) order, units likewise
/// in their own namespace.
fn check_variant(label: &str, tables: &[(String, &GlslReflection)]) -> Vec<String> {
    let mut failures = Vec::new();
    let mut blocks: BTreeMap<Key, (u32, &str)> = BTreeMap::new();
    let mut units: BTreeMap<(Key, Option<Key>), (u32, &str)> = BTreeMap::new();
    for (file, t) in tables {
        for b in &t.uniform_blocks {
            let seen = blocks.entry(key(&b.source)).or_insert((b.binding, file));
            if seen.0 != b.binding {
                failures.push(format!(
                    "{label}: group {} binding {} is block binding {} in {} but {} in {file}",
                    b.source.group, b.source.binding, seen.0, seen.1, b.binding
                ));
            }
        }
        for s in &t.samplers {
            let k = (key(&s.texture), s.sampler.as_ref().map(key));
            let seen = units.entry(k).or_insert((s.unit, file));
            if seen.0 != s.unit {
                failures.push(format!(
                    "{label}: texture {:?} is unit {} in {} but {} in {file}",
                    k, seen.0, seen.1, s.unit
                ));
            }
        }
    }
    let numbered = |what: &str, got: Vec<u32>, failures: &mut Vec<String>| {
        let want: Vec<u32> = (0..got.len() as u32).collect();
        if got != want {
            failures.push(format!(
                "{label}: {what} in (group, binding) order are {got:?}, the docs say {want:?}"
            ));
        }
    };
    numbered(
        "uniform-block bindings",
        blocks.values().map(|v| v.0).collect(),
        &mut failures,
    );
    numbered(
        "texture units",
        units.values().map(|v| v.0).collect(),
        &mut failures,
    );
    failures
}

/// glslangValidator's name for a stage (`-S`).
fn glslang_stage(stage: Stage) -> &'static str {
    match stage {
        Stage::Vertex => "vert",
        Stage::Fragment => "frag",
        Stage::Compute => "comp",
    }
}

/// `compile` once per distinct (text, stage): variants share many files
/// (a vertex stage is often the same for every fragment keyword, a scene
/// shader can equal its library variant): 553 distinct texts of 721 files.
struct GlslCompiles<'a> {
    glslang: &'a Path,
    out_dir: &'a Path,
    done: std::collections::HashMap<(String, &'static str), Result<Compiled, String>>,
}

impl GlslCompiles<'_> {
    fn compile(&mut self, path: &Path, stage: Stage) -> Result<Compiled, String> {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
        let (glslang, out_dir) = (self.glslang, self.out_dir);
        self.done
            .entry((text, glslang_stage(stage)))
            .or_insert_with(|| compile(glslang, path, stage, out_dir))
            .clone()
    }
}

/// Every GLSL file of `shader` (in `dir`): compiled, checked against its
/// table and the variant's bindings, the stages checked together.
fn check_glsl_shader(
    compiles: &mut GlslCompiles,
    label: &str,
    dir: &Path,
    shader: &VariantShader,
) -> (usize, usize, Vec<String>) {
    let mut failures = Vec::new();
    let mut compared = 0;
    let files = shader.files.get("glsl").map(Vec::as_slice).unwrap_or(&[]);
    if files.is_empty() {
        failures.push(format!("{label}: no GLSL file"));
    }
    let mut tables = Vec::new();
    for f in files {
        let file_label = format!("{label} {}", f.path);
        let Some(table) = &f.glsl else {
            failures.push(format!("{file_label}: no `glsl` table"));
            continue;
        };
        let stage = f
            .entry_point
            .as_ref()
            .and_then(|ep| shader.entry_points.iter().find(|e| &e.name == ep))
            .map(|e| e.stage);
        let Some(stage) = stage else {
            failures.push(format!("{file_label}: names no entry point of the variant"));
            continue;
        };
        match compiles.compile(&dir.join(&f.path), stage) {
            Ok(c) => {
                compared += c.blocks.len() + c.samplers.len();
                failures.extend(check_file(&file_label, table, &c, shader, stage));
            }
            Err(e) => failures.push(format!("{file_label}: {e}")),
        }
        tables.push((f.path.clone(), table));
    }
    failures.extend(check_variant(label, &tables));
    (files.len(), compared, failures)
}

#[test]
fn every_glsl_binding_resolves_by_its_table() {
    let started = std::time::Instant::now();
    let glslang = glslang();
    let tmp = tempfile::tempdir().unwrap();
    let mut compiles = GlslCompiles {
        glslang: &glslang,
        out_dir: tmp.path(),
        done: Default::default(),
    };
    let lib = Library::load(&harness::generated()).unwrap();
    // The fixtures add a `constant`-mode keyword: one file per value and stage.
    let (_fixtures_dir, fixtures) = harness::fixture_library();
    let fixtures = Library::load(&fixtures).unwrap();
    let (mut files, mut variants, mut scene_shaders, mut bindings) = (0, 0, 0, 0);
    let mut failures = Vec::new();
    for (path, meta) in lib.materials.iter().chain(&fixtures.materials) {
        for (v, shader) in canonical_variants(meta).unwrap() {
            let label = format!("{}/{}", meta.name, v.id);
            let (n, b, f) =
                check_glsl_shader(&mut compiles, &label, path.parent().unwrap(), shader);
            files += n;
            bindings += b;
            variants += 1;
            failures.extend(f);
        }
    }
    for (path, meta) in &lib.scenes {
        let meta: &SceneMetadata = meta;
        for sh in &meta.shaders {
            let label = format!("scene {} shader {}", meta.name, sh.id);
            let (n, b, f) =
                check_glsl_shader(&mut compiles, &label, path.parent().unwrap(), &sh.shader);
            files += n;
            bindings += b;
            scene_shaders += 1;
            failures.extend(f);
        }
    }
    println!(
        "{files} GLSL files of {variants} variants and {scene_shaders} scene shaders, \
         {bindings} compiled bindings compared; {:.1} s",
        started.elapsed().as_secs_f64()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(variants >= 48 && scene_shaders >= 2 && files >= 2 * (variants + scene_shaders));
    assert!(
        bindings >= 2 * files,
        "{bindings} bindings in {files} files: the reflection was not read"
    );
}

/// The default variant of `material`: its folder, shader and GLSL files
/// (vertex, fragment) with their stages.
fn glsl_case(material: &str) -> (PathBuf, VariantShader) {
    let lib = Library::load(&harness::generated()).unwrap();
    let (path, meta) = lib
        .materials
        .iter()
        .find(|(_, m)| m.name == material)
        .unwrap();
    let shader = canonical_variants(meta).unwrap()[0].1.clone();
    (path.parent().unwrap().to_path_buf(), shader)
}

/// (file, table, stage) of the shader's file for `stage`.
fn glsl_file(shader: &VariantShader, stage: Stage) -> (weft_meta::ShaderFile, GlslReflection) {
    let f = shader.files["glsl"]
        .iter()
        .find(|f| {
            shader
                .entry_points
                .iter()
                .any(|e| Some(&e.name) == f.entry_point.as_ref() && e.stage == stage)
        })
        .unwrap()
        .clone();
    let t = f.glsl.clone().unwrap();
    (f, t)
}

fn assert_caught(failures: &[String], what: &str) {
    println!("{failures:#?}");
    assert!(
        failures.iter().any(|f| f.contains(what)),
        "expected a failure mentioning `{what}`, got {failures:?}"
    );
}

/// The untampered files pass; each tampering below fails.
fn compiled_fragment(dir: &Path, shader: &VariantShader, tmp: &Path) -> Compiled {
    let (f, _) = glsl_file(shader, Stage::Fragment);
    compile(&glslang(), &dir.join(&f.path), Stage::Fragment, tmp).unwrap()
}

#[test]
fn a_table_entry_with_another_binding_is_caught() {
    let tmp = tempfile::tempdir().unwrap();
    let (dir, shader) = glsl_case("standard");
    let compiled = compiled_fragment(&dir, &shader, tmp.path());
    let (_, table) = glsl_file(&shader, Stage::Fragment);
    assert!(check_file("untampered", &table, &compiled, &shader, Stage::Fragment).is_empty());
    let mut blocks = table.clone();
    blocks.uniform_blocks[0].binding += 5;
    assert_caught(
        &check_file("tampered", &blocks, &compiled, &shader, Stage::Fragment),
        "the table says",
    );
    let mut units = table.clone();
    units.samplers[0].unit += 5;
    assert_caught(
        &check_file("tampered", &units, &compiled, &shader, Stage::Fragment),
        "the table says",
    );
}

#[test]
fn a_missing_or_extra_table_entry_is_caught() {
    let tmp = tempfile::tempdir().unwrap();
    let (dir, shader) = glsl_case("standard");
    let compiled = compiled_fragment(&dir, &shader, tmp.path());
    let (_, table) = glsl_file(&shader, Stage::Fragment);
    let mut missing = table.clone();
    missing.samplers.remove(0);
    assert_caught(
        &check_file("tampered", &missing, &compiled, &shader, Stage::Fragment),
        "has no table entry",
    );
    let mut extra = table.clone();
    let mut ghost = extra.uniform_blocks[0].clone();
    ghost.block = "Ghost_block".into();
    extra.uniform_blocks.push(ghost);
    assert_caught(
        &check_file("tampered", &extra, &compiled, &shader, Stage::Fragment),
        "is not in the file",
    );
}

/// A file whose `layout(binding = N)` is not the table's fails once compiled.
#[test]
fn a_file_with_another_binding_is_caught() {
    let tmp = tempfile::tempdir().unwrap();
    let (dir, shader) = glsl_case("standard");
    let (f, table) = glsl_file(&shader, Stage::Fragment);
    let text = std::fs::read_to_string(dir.join(&f.path)).unwrap();
    let block = &table.uniform_blocks[0];
    let from = format!("binding = {}) uniform {}", block.binding, block.block);
    assert!(text.contains(&from), "`{from}` not in {}", f.path);
    let to = format!("binding = {}) uniform {}", block.binding + 7, block.block);
    let path = tmp.path().join("tampered.frag.glsl");
    std::fs::write(&path, text.replacen(&from, &to, 1)).unwrap();
    let compiled = compile(&glslang(), &path, Stage::Fragment, tmp.path()).unwrap();
    assert_caught(
        &check_file("tampered", &table, &compiled, &shader, Stage::Fragment),
        "the table says",
    );
}

#[test]
fn a_table_naming_no_binding_of_the_variant_is_caught() {
    let tmp = tempfile::tempdir().unwrap();
    let (dir, shader) = glsl_case("standard");
    let compiled = compiled_fragment(&dir, &shader, tmp.path());
    let (_, table) = glsl_file(&shader, Stage::Fragment);
    let mut texture = table.clone();
    texture.samplers[0].texture.binding = 99;
    assert_caught(
        &check_file("tampered", &texture, &compiled, &shader, Stage::Fragment),
        "which the variant does not have",
    );
    let mut sampler = table.clone();
    sampler.samplers[0].sampler = Some(sampler.samplers[0].texture);
    assert_caught(
        &check_file("tampered", &sampler, &compiled, &shader, Stage::Fragment),
        "sampler names group",
    );
    let mut block = table.clone();
    block.uniform_blocks[0].source = BindingRef {
        group: 1,
        binding: 1,
    };
    assert_caught(
        &check_file("tampered", &block, &compiled, &shader, Stage::Fragment),
        "names group 1 binding 1",
    );
}

#[test]
fn stages_that_disagree_are_caught() {
    let (_, shader) = glsl_case("standard");
    let (vf, vertex) = glsl_file(&shader, Stage::Vertex);
    let (ff, fragment) = glsl_file(&shader, Stage::Fragment);
    assert!(
        check_variant(
            "untampered",
            &[(vf.path.clone(), &vertex), (ff.path.clone(), &fragment)]
        )
        .is_empty()
    );
    // Both files bind weft_frame (group 0, binding 0): give it another
    // binding point in the vertex file.
    let mut v = vertex.clone();
    let frame = v
        .uniform_blocks
        .iter_mut()
        .find(|b| (b.source.group, b.source.binding) == (0, 0))
        .unwrap();
    frame.binding = 7;
    assert_caught(
        &check_variant("tampered", &[(vf.path.clone(), &v), (ff.path, &fragment)]),
        "is block binding",
    );
    // Numbering other than 0, 1, … in (group, binding) order.
    let mut v = vertex.clone();
    for b in &mut v.uniform_blocks {
        b.binding += 1;
    }
    assert_caught(&check_variant("tampered", &[(vf.path, &v)]), "the docs say");
}
