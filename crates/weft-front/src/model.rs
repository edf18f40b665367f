//! The checked material model: what the front end hands the compiler.
//!
//! Every value here has passed the checks in `check.rs`; spans are kept so the
//! compiler can still point back into the TOML (e.g. for a prelude error).

use crate::diag::{FileId, Span};
use std::collections::BTreeMap;
use std::path::PathBuf;
use weft_meta::{
    BlendMode, Condition, CullMode, DepthTest, GradientStop, Keyframe, KeywordKind, KeywordMode,
    ParamKind, StencilRenderState, TextureDefault,
};

/// Where something was declared: file and byte range.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Loc {
    pub file: FileId,
    pub span: Span,
}

#[derive(Clone, Debug)]
pub struct Material {
    pub name: String,
    pub label: String,
    pub label_zh: Option<String>,
    pub description: Option<String>,
    pub description_zh: Option<String>,
    /// The TOML file.
    pub file: FileId,
    pub path: PathBuf,
    /// The materials root (`materials/`), against which includes resolve.
    pub root: PathBuf,
    /// WGSL files in composition order: includes (dependencies first), then the material source.
    pub sources: Vec<SourceFile>,
    pub requires: Vec<VertexAttribute>,
    /// Where `requires` is written (or `[material]` when absent).
    pub requires_span: Span,
    pub groups: Vec<Group>,
    pub params: Vec<Param>,
    pub keywords: Vec<Keyword>,
    pub tiers: Tiers,
    /// `[material] stylised = true`: no physical ground truth (a stylised
    /// look such as an SDF face shadow); it may ship a single tier, which is
    /// then its reference (docs/material-format.md, `[[tier]]`).
    pub stylised: bool,
    pub max_variants: usize,
    /// Span of `max_variants` when set (budget errors point there).
    pub max_variants_span: Option<Span>,
    /// Excluded combinations: a variant matching every condition of one entry is dropped.
    pub exclude: Vec<Vec<Condition>>,
    /// Where each entry of `exclude` is written (the filter string), in `file`.
    pub exclude_spans: Vec<Span>,
    pub presets: Vec<Preset>,
    pub passes: Vec<Pass>,
    /// Shared pass files (`[[pass]] include = "lib/x.pass.toml"`) read for
    /// this material, in include order: their text is an input of the build.
    pub pass_files: Vec<SourceFile>,
    /// The WGSL `source` of each shared pass (relative to the root), where
    /// its file names it: composed like a `[material] includes` entry.
    pub pass_sources: Vec<(String, Loc)>,
    /// Lookup tables the toolchain bakes for this material (`[tables]`).
    pub tables: Vec<BakedTable>,
    /// WebGPU limits raised by `[limits]` (the rest are WebGPU's defaults).
    pub limits: weft_meta::DeviceLimits,
    /// Where each declared limit is written, in `file`.
    pub limit_spans: Vec<(&'static str, Span)>,
    pub decl: Loc,
}

#[derive(Clone, Debug)]
pub struct SourceFile {
    pub file: FileId,
    /// Path relative to the materials root, with `/` separators.
    pub rel_path: String,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum VertexAttribute {
    Position,
    Normal,
    Tangent,
    Uv0,
    Uv1,
    Color,
}

impl VertexAttribute {
    pub const ALL: [VertexAttribute; 6] = [
        VertexAttribute::Position,
        VertexAttribute::Normal,
        VertexAttribute::Tangent,
        VertexAttribute::Uv0,
        VertexAttribute::Uv1,
        VertexAttribute::Color,
    ];
    pub fn name(self) -> &'static str {
        match self {
            VertexAttribute::Position => "position",
            VertexAttribute::Normal => "normal",
            VertexAttribute::Tangent => "tangent",
            VertexAttribute::Uv0 => "uv0",
            VertexAttribute::Uv1 => "uv1",
            VertexAttribute::Color => "color",
        }
    }
    /// The engine interface's fixed shader location.
    pub fn location(self) -> u32 {
        self as u32
    }
    /// WebGPU vertex format.
    pub fn format(self) -> &'static str {
        match self {
            VertexAttribute::Position | VertexAttribute::Normal => "float32x3",
            VertexAttribute::Tangent | VertexAttribute::Color => "float32x4",
            VertexAttribute::Uv0 | VertexAttribute::Uv1 => "float32x2",
        }
    }
}

#[derive(Clone, Debug)]
pub struct Group {
    pub name: String,
    pub label: String,
    pub label_zh: Option<String>,
}

#[derive(Clone, Debug)]
pub struct Param {
    pub name: String,
    pub kind: ParamKind,
    pub label: String,
    pub label_zh: Option<String>,
    pub tooltip: Option<String>,
    pub tooltip_zh: Option<String>,
    pub group: String,
    pub order: i64,
    pub default: ParamValue,
    pub range: Option<[f64; 2]>,
    pub soft_range: Option<[f64; 2]>,
    pub step: Option<f64>,
    pub power: Option<f64>,
    pub show_if: Option<Condition>,
    /// Textures: keyword-dependent defaults, tried in order; the first whose
    /// condition (on a static keyword or `tier`) holds for a variant replaces
    /// `default` there. Empty when absent (and for other kinds).
    pub default_when: Vec<(Condition, TextureDefault)>,
    /// `texture2d`: the PNG shipped with the material that is bound while
    /// the parameter is unset (`file = "..."`); `default` remains the
    /// built-in texture for an engine that cannot load it.
    pub file: Option<TextureFile>,
    /// Colours: HDR (edited linear, may exceed 1).
    pub hdr: bool,
    /// Textures.
    pub srgb: bool,
    pub tiling: bool,
    /// Curves: samples baked into the uniform; gradients: ramp width.
    pub samples: u32,
    pub decl: Loc,
}

/// A texture parameter's `file`: where it was named and, once the material
/// is loaded, its texels.
#[derive(Clone, Debug)]
pub struct TextureFile {
    /// As written: relative to the materials root, `/`-separated.
    pub path: String,
    /// The `file` value in the TOML.
    pub loc: Loc,
    /// The decoded image (filled by [`crate::texture_files::load`]; empty
    /// before that and where the file could not be read).
    pub image: std::sync::Arc<Image>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ParamValue {
    Float(f64),
    Int(i64),
    Bool(bool),
    Vector(Vec<f64>),
    Texture(TextureDefault),
    Curve(Vec<Keyframe>),
    Gradient(Vec<GradientStop>),
}

#[derive(Clone, Debug)]
pub struct Keyword {
    pub name: String,
    pub kind: KeywordKind,
    pub mode: KeywordMode,
    pub values: Vec<String>,
    pub default: usize,
    pub label: String,
    pub label_zh: Option<String>,
    pub tooltip: Option<String>,
    pub tooltip_zh: Option<String>,
    pub group: String,
    pub show_if: Option<Condition>,
    pub decl: Loc,
}

#[derive(Clone, Debug)]
pub struct Tiers {
    pub values: Vec<String>,
    pub default: usize,
    pub reference: usize,
    /// (tier, English, Chinese) descriptions.
    pub descriptions: Vec<(String, String, Option<String>)>,
    /// Per tier (by index): the tier it approximates (its error is measured
    /// against that one). None for the reference and for looks.
    pub approximates: Vec<Option<usize>>,
    /// Per tier (by index): a different model (e.g. the seed's formula), not
    /// an approximation of anything (`look = true`).
    pub looks: Vec<bool>,
}

#[derive(Clone, Debug)]
pub struct Preset {
    pub name: String,
    pub label: String,
    pub label_zh: Option<String>,
    pub values: Vec<(String, PresetValue)>,
    pub decl: Loc,
}

#[derive(Clone, Debug, PartialEq)]
pub enum PresetValue {
    Param(ParamValue),
    Keyword(String),
}

#[derive(Clone, Debug)]
pub struct Pass {
    pub name: String,
    pub vertex: String,
    pub fragment: String,
    pub blend: BlendMode,
    pub cull: CullMode,
    pub depth_write: bool,
    pub depth_test: DepthTest,
    pub queue: i64,
    /// `stencil`: absent, the pass neither tests nor writes the stencil.
    pub stencil: Option<StencilRenderState>,
    pub instances: Instances,
    /// `when`: static keyword / tier conditions, all of which must hold for
    /// the pass to exist in a variant (empty: every variant).
    pub when: Vec<Condition>,
    /// Where `when` is written.
    pub when_span: Option<Span>,
    pub decl: Loc,
    /// Where `vertex` / `fragment` are written (the pass itself when absent).
    pub vertex_span: Span,
    pub fragment_span: Span,
}

/// A `[tables.<name>]` entry: a 2-D table the toolchain bakes at build time
/// (a texture file beside the variants, bound in group 1).
#[derive(Clone, Debug)]
pub struct BakedTable {
    pub name: String,
    pub recipe: TableRecipe,
    /// Texels along u and v.
    pub size: [u32; 2],
    pub decl: Loc,
}

/// What a baked table holds.
#[derive(Clone, Debug, PartialEq)]
pub enum TableRecipe {
    /// Pre-integrated skin diffuse (Penner & Borshukov 2011) over the Burley
    /// normalised diffusion profile with shape `shape` (s per RGB channel):
    /// u = N·L · 0.5 + 0.5, v = curvature 1/r. `half_ring`: the seed's
    /// integral over ±π/2 instead of the whole ring.
    PreintegratedSkin { shape: [f64; 3], half_ring: bool },
    /// The spectral sensitivity of thin-film interference (Belcour & Barla
    /// 2017): S(x) = ∫ CMF(λ) cos(2π x / λ) dλ over 380–780 nm, taken to
    /// linear Rec. 709 and divided per channel by its value at x = 0, for
    /// optical path differences x = u · `opd_max_nm` (v unused).
    ThinFilmSensitivity { opd_max_nm: f64 },
}

#[derive(Clone, Debug)]
pub enum Instances {
    Fixed(u32),
    Param(String),
}

impl Param {
    /// The built-in texture a texture parameter starts from in one variant:
    /// the first entry of `default_when` whose condition holds, else
    /// `default`. `value_of` gives the value a condition subject has there (a
    /// keyword's value name; the tier's name for `tier`), `None` when it has
    /// none (such a condition does not hold). `None` for parameters that are
    /// not textures.
    pub fn texture_default_where<'a>(
        &self,
        value_of: impl Fn(&str) -> Option<&'a str>,
    ) -> Option<TextureDefault> {
        let ParamValue::Texture(default) = self.default else {
            return None;
        };
        Some(
            self.default_when
                .iter()
                .find(|(c, _)| crate::condition::holds(c, value_of(&c.subject)))
                .map_or(default, |(_, d)| *d),
        )
    }
}

impl Material {
    /// The entry points variant `key`'s passes name (vertex and fragment):
    /// the compiler keeps these and removes every other the WGSL defines
    /// (passes the variant does not have; a library's entry point no pass
    /// uses, such as lib/forward.wgsl's `vs_main` beside a material's own
    /// vertex stage) with the code only they reach.
    pub fn kept_entry_points(&self, key: &VariantKey) -> Vec<String> {
        let mut kept: Vec<String> = Vec::new();
        for p in self.passes_of(key) {
            for name in [&p.vertex, &p.fragment] {
                if !kept.contains(name) {
                    kept.push(name.clone());
                }
            }
        }
        kept
    }

    /// The passes variant `key` has: those whose `when` holds there, in
    /// declaration order.
    pub fn passes_of<'a>(&'a self, key: &'a VariantKey) -> impl Iterator<Item = &'a Pass> {
        self.passes.iter().filter(|p| key.matches(self, &p.when))
    }

    /// [`Param::texture_default_where`] for the variant with static keyword
    /// values `keywords` (keyword name -> value name; a keyword missing from
    /// the map has its default value) and tier `tier` (a tier name).
    pub fn texture_default_for(
        &self,
        param: &Param,
        keywords: &BTreeMap<String, String>,
        tier: &str,
    ) -> Option<TextureDefault> {
        param.texture_default_where(|subject| {
            if subject == "tier" {
                return Some(tier);
            }
            keywords.get(subject).map(String::as_str).or_else(|| {
                self.keyword(subject)
                    .and_then(|k| k.values.get(k.default))
                    .map(String::as_str)
            })
        })
    }

    /// [`Param::texture_default_where`] for one point of the variant space.
    pub fn texture_default_in(
        &self,
        param: &Param,
        variant: &VariantKey,
    ) -> Option<TextureDefault> {
        param.texture_default_where(|subject| variant.value_of(self, subject))
    }

    pub fn param(&self, name: &str) -> Option<&Param> {
        self.params.iter().find(|p| p.name == name)
    }
    pub fn keyword(&self, name: &str) -> Option<&Keyword> {
        self.keywords.iter().find(|k| k.name == name)
    }
    /// Keywords that multiply the static variant count.
    pub fn static_keywords(&self) -> impl Iterator<Item = &Keyword> {
        self.keywords
            .iter()
            .filter(|k| k.mode == KeywordMode::Static)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::{Diagnostics, SourceDb};
    use crate::toml_reader::Cx;
    use std::path::Path;

    const MATERIAL: &str = r#"
[material]
name = "m"

[params.sphere_map]
type = "cube"
default = "black"
default_when = [
    { if = "SPHERE_MAP == multiply", default = "white" },
    { if = "tier == reference", default = "gray" },
]

[params.mask]
type = "texture2d"
default = "gray"

[params.amount]
type = "float"

[keywords.SPHERE_MAP]
type = "enum"
values = ["off", "add", "multiply"]
default = "multiply"

[keywords.WEAVE]
type = "enum"
values = ["plain", "twill"]
mode = "constant"

[[tier]]
name = "fast"

[[tier]]
name = "reference"
"#;

    fn material() -> Material {
        let mut db = SourceDb::new();
        let mut diags = Diagnostics::new();
        let file = db.add(Path::new("m.toml"), "m.toml".into(), MATERIAL.into());
        let m = crate::parse::parse_material(
            MATERIAL,
            Path::new("m.toml"),
            Path::new("."),
            &[],
            &mut Cx {
                file,
                diags: &mut diags,
            },
        );
        assert!(diags.is_empty(), "{}", diags.render_plain(&db));
        m.expect("parses")
    }

    fn kw(pairs: &[(&str, &str)]) -> BTreeMap<String, String> {
        pairs
            .iter()
            .map(|(k, v)| (k.to_string(), v.to_string()))
            .collect()
    }

    #[test]
    fn default_when_is_read_in_order() {
        let m = material();
        let p = m.param("sphere_map").unwrap();
        assert_eq!(p.default, ParamValue::Texture(TextureDefault::Black));
        let got: Vec<(String, TextureDefault)> = p
            .default_when
            .iter()
            .map(|(c, d)| (format!("{} {:?} {}", c.subject, c.op, c.value), *d))
            .collect();
        assert_eq!(
            got,
            [
                ("SPHERE_MAP Equal multiply".into(), TextureDefault::White),
                ("tier Equal reference".into(), TextureDefault::Gray),
            ]
        );
        assert!(m.param("mask").unwrap().default_when.is_empty());
    }

    #[test]
    fn first_holding_entry_wins_else_default() {
        let m = material();
        let p = m.param("sphere_map").unwrap();
        let at = |sphere: &str, tier: &str| {
            m.texture_default_for(p, &kw(&[("SPHERE_MAP", sphere)]), tier)
        };
        assert_eq!(at("add", "fast"), Some(TextureDefault::Black));
        assert_eq!(at("off", "fast"), Some(TextureDefault::Black));
        assert_eq!(at("multiply", "fast"), Some(TextureDefault::White));
        assert_eq!(at("add", "reference"), Some(TextureDefault::Gray));
        // Both hold: the first entry wins.
        assert_eq!(at("multiply", "reference"), Some(TextureDefault::White));
        // A keyword left out of the map has its default value (multiply).
        assert_eq!(
            m.texture_default_for(p, &BTreeMap::new(), "fast"),
            Some(TextureDefault::White)
        );
        // Unconditional textures, and parameters that are not textures.
        let mask = m.param("mask").unwrap();
        assert_eq!(
            m.texture_default_for(mask, &kw(&[("SPHERE_MAP", "multiply")]), "reference"),
            Some(TextureDefault::Gray)
        );
        let amount = m.param("amount").unwrap();
        assert_eq!(
            m.texture_default_for(amount, &BTreeMap::new(), "fast"),
            None
        );
    }

    #[test]
    fn resolves_per_variant_key() {
        let m = material();
        let p = m.param("sphere_map").unwrap();
        let mut seen = Vec::new();
        for v in crate::variants::variants(&m) {
            let by_key = m.texture_default_in(p, &v);
            let names: BTreeMap<String, String> = v
                .keywords
                .iter()
                .map(|&(k, i)| (m.keywords[k].name.clone(), m.keywords[k].values[i].clone()))
                .collect();
            let tier = &m.tiers.values[v.tier];
            assert_eq!(
                by_key,
                m.texture_default_for(p, &names, tier),
                "{}",
                v.id(&m)
            );
            seen.push((v.id(&m), by_key.unwrap().name()));
        }
        assert_eq!(
            seen,
            [
                ("fast.sphere_map-off".to_string(), "black"),
                ("fast.sphere_map-add".into(), "black"),
                ("fast.sphere_map-multiply".into(), "white"),
                ("reference.sphere_map-off".into(), "gray"),
                ("reference.sphere_map-add".into(), "gray"),
                ("reference.sphere_map-multiply".into(), "white"),
            ]
        );
    }

    #[test]
    fn not_equal_conditions() {
        let mut m = material();
        let (c, _) = &mut m.params[0].default_when[0];
        c.op = weft_meta::ConditionOp::NotEqual;
        let p = m.params[0].clone();
        let at = |sphere: &str| m.texture_default_for(&p, &kw(&[("SPHERE_MAP", sphere)]), "fast");
        assert_eq!(at("multiply"), Some(TextureDefault::Black));
        assert_eq!(at("add"), Some(TextureDefault::White));
        // A subject with no value in the variant never holds, even with `!=`.
        assert_eq!(
            p.texture_default_where(|s| (s == "tier").then_some("fast")),
            Some(TextureDefault::Black)
        );
    }
}

/// The label of a name the TOML gives none for: "base_color" -> "Base color".
pub fn humanize(name: &str) -> String {
    let s = name.replace('_', " ");
    let mut c = s.chars();
    match c.next() {
        Some(f) => f.to_uppercase().chain(c).collect(),
        None => s,
    }
}

/// One point of the variant space.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct VariantKey {
    pub tier: usize,
    /// (keyword index in `Material::keywords`, value index), static keywords only, in declaration order.
    pub keywords: Vec<(usize, usize)>,
}

impl VariantKey {
    /// The static part of a full assignment of keyword values (value index
    /// per keyword of `m`, static and constant alike) at tier `tier`.
    pub fn of_values(m: &Material, tier: usize, keyword_values: &[usize]) -> VariantKey {
        VariantKey {
            tier,
            keywords: m
                .keywords
                .iter()
                .enumerate()
                .filter(|(_, k)| k.mode == weft_meta::KeywordMode::Static)
                .map(|(i, _)| (i, keyword_values[i]))
                .collect(),
        }
    }

    /// File stem and id: `<tier>.<keyword>-<value>…`, lower case.
    pub fn id(&self, m: &Material) -> String {
        let mut id = m.tiers.values[self.tier].clone();
        for &(k, v) in &self.keywords {
            let kw = &m.keywords[k];
            id.push('.');
            id.push_str(&kw.name.to_lowercase());
            id.push('-');
            id.push_str(&kw.values[v]);
        }
        id
    }

    /// The value a condition subject has in this variant (None: not a keyword/tier).
    pub fn value_of<'m>(&self, m: &'m Material, subject: &str) -> Option<&'m str> {
        if subject == "tier" {
            return Some(&m.tiers.values[self.tier]);
        }
        self.keywords
            .iter()
            .find(|(k, _)| m.keywords[*k].name == subject)
            .map(|&(k, v)| m.keywords[k].values[v].as_str())
    }

    pub fn matches(&self, m: &Material, conds: &[Condition]) -> bool {
        conds
            .iter()
            .all(|c| crate::condition::holds(c, self.value_of(m, &c.subject)))
    }
}

/// A decoded texture file: RGBA8, rows top to bottom (the PNG's first row
/// first), texels left to right; grey expanded to rgb, alpha 255 where the
/// PNG has none, 16-bit samples rounded to 8 bits. Bytes as stored: the
/// parameter's `srgb` says whether they are sRGB-encoded.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub rgba8: Vec<u8>,
    /// SHA-256 of `rgba8`, hex: every variant's metadata states it.
    pub sha256: String,
}
